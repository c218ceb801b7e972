//! One game in two files: the same Tenhou game as mjlog XML and as tenhou.net/6 JSON, or one log
//! copied into two folders, would give the same rows twice (18.5% of a dataset's rows were such
//! duplicates). A game is recognised by what was played, not by its file's name, format or bytes.

use std::fmt::Write as _;
use std::hash::Hasher as _;

use rinshan_logs::tenhou::log::Game;
use siphasher::sip128::{Hasher128 as _, SipHasher13};

/// What a game played, in 128 bits: two different games share a key with odds of about 2^-64 in
/// a dataset of four billion games.
pub type GameKey = [u8; 16];

/// Feeds formatted text to the hasher without building the string.
struct Feed(SipHasher13);

impl std::fmt::Write for Feed {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.0.write(s.as_bytes());
        Ok(())
    }
}

/// The key of `game`: per round its table (round, honba, sticks, scores), dora indicators,
/// starting hands, draws and discards, which the seed's wall and the players' choices make.
/// Left out, as they do not make another game: the file's path and line numbers, the players'
/// names (one source may anonymise them), the rule's display name, and how each result is written
/// (formats name yaku differently; the result follows from the play).
pub fn game_key(game: &Game) -> GameKey {
    // Fixed keys: the same game gets the same key in every run, so a resumed build agrees.
    let mut feed = Feed(SipHasher13::new_with_keys(0x7269_6e73_6861_6e00, 0x6761_6d65_6b65_7900));
    for r in &game.rounds {
        // Debug formatting of the engine's plain tile and move types is their content; a round's
        // fields are listed one by one so that a field added to `Round` is not silently keyed.
        let _ = write!(
            feed,
            "{}|{}|{}|{}|{:?}|{:?}|{:?}|{:?}|{:?};",
            r.seats, r.kyoku, r.honba, r.sticks, r.scores, r.dora, r.hands, r.draws, r.discards
        );
    }
    feed.0.finish128().as_bytes()
}
