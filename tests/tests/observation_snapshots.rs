//! Golden observations at chosen positions of the real Tenhou logs (tests/data/tenhou): both
//! forms, as `rinshan observe` prints them, pinned by insta. Each position is the first of its
//! kind in the logs (files in name order): a riichi declaration's discard, a chi and a pon prompt
//! and the turn after the call, a chankan prompt, each kan kind and the moment its dora appears,
//! and a red five among the dora indicators.

use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::generated::red as k;
use rinshan_engine::observe::{describe, Form};
use rinshan_logs::tenhou::log::{collect_files, read_game, Game};
use rinshan_logs::tenhou::position::{round_positions, Position};

fn games() -> Vec<Game> {
    let files = collect_files(&[rinshan_tests::test_data().join("tenhou")]).expect("logs");
    let mut games: Vec<Game> = files.iter().map(|f| read_game(f).expect("log")).collect();
    games.sort_by(|a, b| a.path.cmp(&b.path));
    games
}

/// Every round's positions, in file and round order.
fn all_positions(games: &[Game]) -> Vec<(String, usize, Vec<Position>)> {
    let mut out = Vec::new();
    for g in games {
        for r in 0..g.rounds.len() {
            let positions = round_positions(g, r).expect("round replays");
            let name = std::path::Path::new(&g.path)
                .file_name()
                .map(|n| n.to_string_lossy().to_string())
                .unwrap_or_default();
            out.push((name, r, positions));
        }
    }
    out
}

fn render(file: &str, round: usize, p: &Position, seat: u32, why: &str) -> String {
    let planes = k::observe_planes(p.state, seat);
    let tokens = k::observe_tokens(p.state, seat);
    format!(
        "{why}\n{file}, round {round}, step {}: seat {} decides ({}); seen by seat {seat}\n\n== tokens ==\n{}\n== planes ==\n{}",
        p.step,
        p.seat,
        p.what,
        describe(Form::Tokens, bytemuck::bytes_of(&tokens)),
        describe(Form::Planes, bytemuck::bytes_of(&planes)),
    )
}

fn is_call(a: u32, first: u32, last: u32) -> bool {
    (first..=last).contains(&a)
}

fn indicators(s: &GameState) -> Vec<u32> {
    (0..s.dora_revealed)
        .map(|i| kernel::wall_tile(&mut { *s }, rinshan_engine::Variant::Red.wall().dora + i))
        .collect()
}

#[test]
fn observations_at_chosen_log_positions() {
    let games = games();
    let rounds = all_positions(&games);
    type Pick = Box<dyn Fn(&[Position], usize) -> Option<(u32, &'static str)>>;
    let cases: Vec<(&str, Pick)> = vec![
        (
            "riichi_discard",
            Box::new(|ps, i| {
                (i > 0 && ps[i - 1].action == k::ACTION_RIICHI)
                    .then_some((ps[i].seat, "the discard that declares riichi"))
            }),
        ),
        (
            "chi_prompt",
            Box::new(|ps, i| {
                is_call(ps[i].action, k::ACTION_CHI_LEFT, k::ACTION_CHI_RIGHT_RED)
                    .then_some((ps[i].seat, "a chi prompt the log takes"))
            }),
        ),
        (
            "after_chi",
            Box::new(|ps, i| {
                (i > 0 && is_call(ps[i - 1].action, k::ACTION_CHI_LEFT, k::ACTION_CHI_RIGHT_RED))
                    .then_some((ps[i].seat, "the caller's turn after a chi (kuikae applies)"))
            }),
        ),
        (
            "pon_prompt",
            Box::new(|ps, i| {
                is_call(ps[i].action, k::ACTION_PON, k::ACTION_PON_RED)
                    .then_some((ps[i].seat, "a pon prompt the log takes"))
            }),
        ),
        (
            "pon_prompt_other_seat",
            Box::new(|ps, i| {
                is_call(ps[i].action, k::ACTION_PON, k::ACTION_PON_RED).then_some((
                    (ps[i].seat + 2) % 4,
                    "the same kind of prompt seen by a seat not asked (no sign of it)",
                ))
            }),
        ),
        (
            "chankan_prompt",
            Box::new(|ps, i| {
                (ps[i].state.phase == kernel::PHASE_CLAIM && ps[i].state.claim_kan == 1)
                    .then_some((ps[i].seat, "a chankan prompt: a claim on an added kan"))
            }),
        ),
        (
            "closed_kan_dora",
            Box::new(|ps, i| {
                (i > 0
                    && ps[i - 1].state.kans < ps[i].state.kans
                    && ps[i]
                        .state
                        .melds
                        .iter()
                        .any(|&m| kernel::meld_kind(m) == kernel::MELD_CLOSED_KAN)
                    && ps[i].state.dora_revealed == ps[i].state.kans + 1
                    && ps[i - 1].action >= k::ACTION_SELF_KAN
                    && ps[i - 1].action < k::ACTION_SELF_KAN + 34)
                    .then_some((ps[i].seat, "the turn after a closed kan: its dora is already shown"))
            }),
        ),
        (
            "open_kan_dora_pending",
            Box::new(|ps, i| {
                (i > 0 && ps[i - 1].action == k::ACTION_OPEN_KAN).then_some((
                    ps[i].seat,
                    "the turn after an open kan: its dora shows only after this discard",
                ))
            }),
        ),
        (
            "added_kan_dora_pending",
            Box::new(|ps, i| {
                (i > 0
                    && ps[i - 1].action >= k::ACTION_SELF_KAN
                    && ps[i - 1].action < k::ACTION_SELF_KAN + 34
                    && ps[i].state.dora_pending > 0
                    && ps[i].state.phase != 2)
                    .then_some((
                        ps[i].seat,
                        "the turn after an added kan: its dora shows only after this discard",
                    ))
            }),
        ),
        (
            "red_indicator",
            Box::new(|ps, i| {
                indicators(&ps[i].state)
                    .iter()
                    .any(|&v| v >= 34)
                    .then_some((ps[i].seat, "a red five among the dora indicators"))
            }),
        ),
    ];
    for (name, pick) in &cases {
        let found = rounds.iter().find_map(|(file, round, ps)| {
            (0..ps.len()).find_map(|i| pick(ps, i).map(|(seat, why)| render(file, *round, &ps[i], seat, why)))
        });
        let Some(text) = found else {
            panic!("no position for `{name}` in the logs");
        };
        insta::assert_snapshot!(*name, text);
    }
}
