//! tenhou.net/6 JSON as converters of Mahjong Soul games write it: the round wind's yakuhai as
//! `役牌:場風牌`, and at three players the North dora as their own `抜きドラ`.

use super::*;
use rinshan_engine::hand::{Yaku, YakuHan};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data");

/// The real three-player game (an mjlog) as tenhou.net/6 text.
fn sanma_text() -> String {
    let path = Path::new(DATA).join("mjlog/2014091101gm-00b9-0000-5ca6b487.xml");
    let game = crate::file::read_log(&path).unwrap_or_else(|e| panic!("{e}"));
    crate::tenhou::write::game_text(&game)
}

fn wins(game: &Game) -> Vec<&LoggedWin> {
    game.rounds
        .iter()
        .flat_map(|r| match &r.outcome {
            Outcome::Wins(w) => w.iter().collect(),
            Outcome::Draw { .. } => Vec::new(),
        })
        .collect()
}

#[test]
fn north_dora_count_with_the_dora_at_three_players() {
    let text = sanma_text();
    let game = parse_game("s.json", &text).unwrap_or_else(|e| panic!("{e}"));
    // The first win's two dora, one of them written as a North's; and a win whose only dora is one.
    let split = text.replacen(r#""ドラ(2飜)""#, r#""ドラ(1飜)","抜きドラ(1飜)""#, 1);
    let north_only = split.replacen(r#""ドラ(1飜)"]"#, r#""抜きドラ(1飜)"]"#, 1);
    assert!(split != text && north_only != split);
    let read = parse_game("s.json", &north_only).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(read.rounds, game.rounds);
    let dora = |g: &Game| -> Vec<Option<Yaku>> {
        wins(g)
            .iter()
            .map(|w| w.yaku.iter().find(|y| y.name == "dora").copied())
            .collect()
    };
    assert_eq!(dora(&read)[0].map(|y| y.han), Some(YakuHan::Han(2)));
    // Four players keep North.
    let four =
        std::fs::read_to_string(Path::new(DATA).join("tenhou/2010081709gm-00a9-0000-fe3371ad.json")).expect("reads");
    let north = four.replacen(r#""ドラ(1飜)""#, r#""抜きドラ(1飜)""#, 1);
    assert_ne!(north, four);
    let message = parse_game("f.json", &north).expect_err("refused").to_string();
    assert!(
        message.contains("抜きドラ (the dora of Norths set aside) at four players"),
        "{message}"
    );
}

#[test]
fn mahjong_souls_wind_yakuhai_read_as_tenhous() {
    let path = Path::new(DATA).join("tenhou/2010081709gm-00a9-0000-fe3371ad.json");
    let text = std::fs::read_to_string(path).expect("reads");
    let game = parse_game("t.json", &text).unwrap_or_else(|e| panic!("{e}"));
    let renamed = text
        .replace(r#""場風 東(1飜)""#, r#""役牌:場風牌(1飜)""#)
        .replace(r#""場風 南(1飜)""#, r#""役牌:場風牌(1飜)""#)
        .replace(r#""自風 南(1飜)""#, r#""役牌:自風牌(1飜)""#);
    assert!(renamed.contains("役牌:場風牌") && renamed.contains("役牌:自風牌"));
    let read = parse_game("t.json", &renamed).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(read, game);
    // Written back, they are Tenhou's names again.
    assert_eq!(
        crate::tenhou::write::game_text(&read),
        crate::tenhou::write::game_text(&game)
    );
}
