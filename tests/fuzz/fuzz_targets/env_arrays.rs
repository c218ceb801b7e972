//! The arrays a user hands the environment (from Rust, and from Python through the extension):
//! actions of any value, walls and dealers, forced deals, saved states. Bad ones are an error or,
//! for an action, a recorded illegal move; nothing panics.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use rinshan_engine::env::{Config, Deal, Env, Mode};
use rinshan_engine::{Tile, Variant};

#[derive(Debug, Arbitrary)]
enum Call {
    Step(Vec<u32>),
    Walls(Vec<u8>, Vec<u32>),
    Deal {
        round: u32,
        dealer: u32,
        honba: u32,
        sticks: u32,
        scores: [i32; 4],
        wall: Vec<u8>,
    },
    Load(Vec<u32>),
    Observe(Vec<u32>),
}

#[derive(Debug, Arbitrary)]
struct Input {
    red: bool,
    single: bool,
    calls: Vec<Call>,
}

fn wall(bytes: &[u8]) -> [Tile; 136] {
    std::array::from_fn(|i| {
        Tile::from_value(bytes.get(i).copied().unwrap_or(0) % 37)
            .unwrap_or_else(|| Tile::from_value(0).expect("a tile"))
    })
}

fuzz_target!(|input: Input| {
    const B: usize = 2;
    let variant = if input.red { Variant::Red } else { Variant::NoRed };
    let mut config = Config::new(variant, B);
    config.mode = if input.single { Mode::Single } else { Mode::East };
    config.threads = Some(1);
    let Ok(mut env) = Env::new(config) else { return };
    if env.reset().is_err() {
        return;
    }
    for call in input.calls.iter().take(64) {
        match call {
            Call::Step(actions) => {
                let _ = env.step(actions);
            }
            Call::Walls(bytes, dealers) => {
                let walls = [wall(bytes), wall(bytes.get(136..).unwrap_or(&[]))];
                let _ = env.reset_with_walls(&walls[..dealers.len().min(B)], dealers);
            }
            Call::Deal {
                round,
                dealer,
                honba,
                sticks,
                scores,
                wall: w,
            } => {
                let deal = Deal {
                    round: *round,
                    dealer: *dealer,
                    honba: *honba,
                    sticks: *sticks,
                    scores: *scores,
                    wall: wall(w),
                };
                let _ = env.deal(&[Some(deal), None]);
            }
            Call::Load(words) => {
                let _ = env.load_states(words);
            }
            Call::Observe(seats) => {
                let _ = env.observe(
                    rinshan_engine::observe::Form::Planes,
                    rinshan_engine::env::Observer::Seats(seats),
                );
            }
        }
    }
});
