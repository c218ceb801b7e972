//! A hand in notation as a user types it (`rinshan shanten`, `rinshan score`, Python's
//! `rinshan.hands`): the concealed tiles, the winning tile, melds, indicators, winds and flags.
//! A clear error, never a panic.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use rinshan_engine::win_input::WinInput;
use rinshan_engine::Variant;

#[derive(Debug, Arbitrary)]
struct Input {
    red: bool,
    hand: String,
    win: String,
    melds: Vec<String>,
    round_wind: String,
    seat_wind: Option<String>,
    dora: Option<String>,
    ura: Option<String>,
    honba: u32,
    sticks: u32,
    flags: u16,
}

fuzz_target!(|input: Input| {
    let _ = rinshan_engine::hand::shanten_of_notation(&input.hand);
    let f = |bit: u16| input.flags & (1 << bit) != 0;
    let win_input = WinInput {
        hand: input.hand,
        win: input.win,
        melds: input.melds,
        round_wind: input.round_wind,
        seat_wind: input.seat_wind,
        dora: input.dora,
        ura: input.ura,
        honba: input.honba,
        sticks: input.sticks,
        tsumo: f(0),
        riichi: f(1),
        double_riichi: f(2),
        ippatsu: f(3),
        haitei: f(4),
        houtei: f(5),
        rinshan: f(6),
        chankan: f(7),
        tenhou: f(8),
        chiihou: f(9),
        dealer: f(10),
    };
    let variant = if input.red { Variant::Red } else { Variant::NoRed };
    if let Ok(win) = win_input.win() {
        let _ = rinshan_engine::hand::score(variant, &win);
    }
});
