//! Lines from an MJAI host as `rinshan mjai-bot` and Python's `rinshan.mjai.Bot` read them: the
//! first byte picks the dialect and the seat, then each line is answered by the built-in
//! `defensive` agent. Whatever the lines say (malformed JSON, unknown events, wrong actors,
//! impossible tiles, more draws than a wall holds), the player answers or stays silent as its
//! dialect asks, and never panics; every reply is an MJAI event.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rinshan_engine::agents::Agent;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::Dialect;
use rinshan_logs::mjai::player::Player;
use rinshan_logs::mjai::Event;

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let dialect = if first & 1 == 0 { Dialect::App } else { Dialect::Stdio };
    let seat = (first >> 1) % 5;
    let mut player = Player::new((seat < 4).then_some(seat));
    let mut decide = |s: &GameState| Ok(Agent::Defensive.act(Variant::Red, s));
    for line in String::from_utf8_lossy(rest).lines().take(400) {
        let reply = player.respond(line, dialect, &mut decide, &mut |_| {});
        if let Some(reply) = reply {
            serde_json::from_str::<Event>(&reply).expect("a reply is an MJAI event");
        } else {
            assert_eq!(dialect, Dialect::Stdio, "the app dialect answers every line");
        }
    }
});
