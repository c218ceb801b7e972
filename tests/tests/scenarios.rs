//! Rule scenarios as data (tests/data/scenarios.toml): a prepared wall, a script of actions and the
//! outcome the rules call for, played on the native game kernel of the scenario's variant.
//!
//! Every scripted step checks that its seat is `current_player` and that its action is legal
//! (failing with the scenario name, the step and the legal set in readable names); the expectations
//! are checked after the steps. Expected values were worked out from the rules (Tenhou for the red
//! variant), not from running the engine; scenarios where the engine is believed to be wrong are
//! listed in `KNOWN_FAILING` and reported instead of failing the test.

use std::collections::BTreeSet;

use rinshan_engine::env::{Deal, Mode};
use rinshan_engine::{Tile, Variant};
use rinshan_tests::scenario::{build_wall, load, Actions, Expect, Scenario};

/// What the native run of a scenario dealt, played and saw, to play it again on the [`Env`] of
/// each backend (`rule_scenarios_on_both_backends`).
///
/// [`Env`]: rinshan_engine::env::Env
struct Trace {
    deal: Deal,
    mode: Mode,
    uma: [i32; 4],
    penalty: f32,
    actions: Vec<u32>,
    /// The view after each action.
    seen: Vec<Seen>,
    /// Round, dealer, honba, sticks and scores after the last action.
    table: (u32, u32, u32, u32, [i32; 4]),
}

/// The parts of a step's view that both the kernel's `StepView` and the env's `Step` carry.
#[derive(Debug, Clone, PartialEq)]
struct Seen {
    current_player: u32,
    mask: [u32; 3],
    rewards: [f32; 4],
    terminated: bool,
    illegal: bool,
    events: u32,
    winners: u32,
    deal_in: u32,
    yaku: [u32; 2],
}

impl Seen {
    fn of(v: &rinshan_engine::generated::kernel::StepView) -> Seen {
        Seen {
            current_player: v.current_player,
            mask: v.mask,
            rewards: v.rewards,
            terminated: v.terminated != 0,
            illegal: v.illegal != 0,
            events: v.events,
            winners: v.winners,
            deal_in: v.deal_in,
            yaku: v.yaku,
        }
    }

    fn of_env(step: &rinshan_engine::env::Step, i: usize) -> Seen {
        Seen {
            current_player: step.current_player[i],
            mask: step.legal_action_mask[i],
            rewards: step.rewards[i],
            terminated: step.terminated[i],
            illegal: step.illegal[i],
            events: step.events[i],
            winners: step.winners[i],
            deal_in: step.deal_in[i],
            yaku: step.yaku[i],
        }
    }
}

/// The `events` bits of a step that ends a round.
const ROUND_OVER: u32 = rinshan_engine::env::events::ROUND_OVER;

/// A scenario's wall as tiles (the places past a three-player wall's 108 are not read).
fn tiles_of(wall: &[u32; 136]) -> Result<[Tile; 136], String> {
    let mut out = [Tile::from_value(0).ok_or("no tile of value 0")?; 136];
    for (o, &v) in out.iter_mut().zip(wall) {
        *o = u8::try_from(v)
            .ok()
            .and_then(Tile::from_value)
            .ok_or(format!("no tile of value {v}"))?;
    }
    Ok(out)
}

/// Scenarios where the engine disagrees with the rules (see the comment of each entry). They are
/// run and reported, but do not fail the test.
const KNOWN_FAILING: &[(&str, &str)] = &[];

const EVENTS: [(&str, u32); 6] = [
    ("ron", 1),
    ("tsumo", 2),
    ("exhaustive_draw", 4),
    ("abortive_draw", 8),
    ("game_over", 16),
    ("nagashi", 32),
];

fn event_names(bits: u32) -> Vec<String> {
    EVENTS
        .iter()
        .filter(|(_, b)| bits & b != 0)
        .map(|(n, _)| n.to_string())
        .collect()
}

fn event_bits(names: &[String]) -> Result<u32, String> {
    names.iter().try_fold(0, |acc, n| {
        EVENTS
            .iter()
            .find(|(name, _)| name == n)
            .map(|(_, b)| acc | b)
            .ok_or_else(|| format!("unknown event `{n}` (known: {EVENTS:?})"))
    })
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

macro_rules! runner {
    ($fn_name:ident, $v:ident, $variant:ident) => {
        fn $fn_name(sc: &Scenario) -> Result<Trace, String> {
            use rinshan_engine::generated::$v as k;
            let acts = Actions {
                blocks: k::host::ACTION_BLOCKS.to_vec(),
                red: k::host::ACTION_BLOCKS.iter().any(|b| b.0 == "pon_red"),
            };
            let mode = match sc.mode.as_str() {
                "single" => 0,
                "east" => 1,
                "half" => 2,
                m => return Err(format!("unknown mode `{m}` (single, east, half)")),
            };
            let wall = build_wall(sc, Variant::$variant)?;
            let mut s = k::game_new(rinshan_engine::generated::kernel::ResetInput {
                seed: sc.seed.unwrap_or([7, 11]),
                mode,
                dealer: sc.dealer,
                use_wall: 1,
                wall,
                uma: sc.uma.unwrap_or([0; 4]),
                penalty: sc.penalty.unwrap_or(-1.0),
                auto_reset: 0,
            });
            if let Some(st) = &sc.start {
                if let Some(r) = st.round {
                    s.round = r;
                }
                if let Some(x) = st.scores {
                    s.scores = x;
                }
                if let Some(h) = st.honba {
                    s.honba = h;
                }
                if let Some(x) = st.sticks {
                    s.sticks = x;
                }
            }
            let mut trace = Trace {
                deal: Deal {
                    round: s.round,
                    dealer: s.dealer,
                    honba: s.honba,
                    sticks: s.sticks,
                    scores: s.scores,
                    wall: tiles_of(&wall)?,
                },
                mode: [Mode::Single, Mode::East, Mode::Half][mode as usize],
                uma: sc.uma.unwrap_or([0; 4]),
                penalty: sc.penalty.unwrap_or(-1.0),
                actions: Vec::new(),
                seen: Vec::new(),
                table: (0, 0, 0, 0, [0; 4]),
            };
            let legal_of = |view: &rinshan_engine::generated::kernel::StepView| -> Vec<u32> {
                (0..k::NUM_ACTIONS)
                    .filter(|a| view.mask[(a / 32) as usize] >> (a % 32) & 1 == 1)
                    .collect()
            };
            let mut total = [0f64; 4];
            let mut last = k::game_view(s);
            for (i, step) in sc.steps.iter().enumerate() {
                let at = format!("step {i}");
                if let Some(auto) = &step.auto {
                    if auto != "tsumogiri" {
                        return Err(format!("{at}: unknown auto `{auto}` (tsumogiri)"));
                    }
                    let rounds = s.rounds;
                    let tsumogiri = acts.id("tsumogiri")?;
                    let pass = acts.id("pass")?;
                    let mut n = 0;
                    loop {
                        let view = k::game_view(s);
                        match step.until_wall_left {
                            Some(_) if view.terminated != 0 || s.rounds != rounds => {
                                return Err(format!("{at} (auto): the round ended after {n} auto steps"));
                            }
                            Some(until) if s.phase == 0 && s.live_end - s.next_draw <= until => break,
                            None if view.terminated != 0 || s.rounds != rounds => break,
                            _ => {}
                        }
                        let legal = legal_of(&view);
                        let a = if legal.contains(&tsumogiri) {
                            tsumogiri
                        } else if legal.contains(&pass) {
                            pass
                        } else {
                            return Err(format!(
                                "{at} (auto, {n} steps in): seat {} can neither tsumogiri nor pass; legal: {:?}",
                                view.current_player,
                                acts.names(&legal)
                            ));
                        };
                        k::game_step(&mut s, a);
                        last = k::game_view(s);
                        trace.actions.push(a);
                        trace.seen.push(Seen::of(&last));
                        for p in 0..4 {
                            total[p] += f64::from(last.rewards[p]);
                        }
                        n += 1;
                        if n > 2000 {
                            return Err(format!("{at} (auto): does not stop"));
                        }
                    }
                    continue;
                }
                let action = step.action.as_deref().ok_or(format!("{at}: no action"))?;
                let at = format!("{at} (`{action}`)");
                let view = k::game_view(s);
                if view.terminated != 0 {
                    return Err(format!("{at}: the game has already ended"));
                }
                let legal = legal_of(&view);
                let legal_names = acts.names(&legal);
                let seat = step.seat.ok_or(format!("{at}: no seat"))?;
                if view.current_player != seat {
                    return Err(format!(
                        "{at}: seat {} is to act, not seat {seat}; its legal actions: {legal_names:?}",
                        view.current_player
                    ));
                }
                if let Some(want) = &step.expect_legal {
                    let want: BTreeSet<String> = want.iter().cloned().collect();
                    if want != legal_names {
                        return Err(format!(
                            "{at}: legal actions are {legal_names:?}, expected {want:?}"
                        ));
                    }
                }
                for n in &step.legal_includes {
                    if !legal_names.contains(n) {
                        return Err(format!("{at}: `{n}` should be legal; legal: {legal_names:?}"));
                    }
                }
                for n in &step.legal_excludes {
                    if legal_names.contains(n) {
                        return Err(format!("{at}: `{n}` should not be legal; legal: {legal_names:?}"));
                    }
                }
                let id = acts.id(action).map_err(|e| format!("{at}: {e}"))?;
                if legal.contains(&id) == step.illegal {
                    return Err(format!(
                        "{at}: seat {seat}'s action is {} but expected {}; legal: {legal_names:?}",
                        if step.illegal { "legal" } else { "illegal" },
                        if step.illegal { "illegal" } else { "legal" },
                    ));
                }
                k::game_step(&mut s, id);
                last = k::game_view(s);
                trace.actions.push(id);
                trace.seen.push(Seen::of(&last));
                if (last.illegal != 0) != step.illegal {
                    return Err(format!("{at}: the kernel's illegal flag is {}", last.illegal));
                }
                let r: Vec<f64> = last.rewards.iter().map(|&x| f64::from(x)).collect();
                for p in 0..4 {
                    total[p] += r[p];
                }
                if let Some(want) = step.expect_rewards {
                    if !(0..4).all(|p| close(r[p], want[p])) {
                        return Err(format!("{at}: rewards {r:?}, expected {want:?}"));
                    }
                }
                if let Some(want) = &step.expect_events {
                    let want = event_bits(want)?;
                    if last.events != want {
                        return Err(format!(
                            "{at}: events {:?}, expected {:?}",
                            event_names(last.events),
                            event_names(want)
                        ));
                    }
                }
            }
            let e = &sc.expect;
            let mut errors = Vec::new();
            if let Some(want) = e.rewards_total {
                if !(0..4).all(|p| close(total[p], want[p])) {
                    errors.push(format!("rewards_total {total:?}, expected {want:?}"));
                }
            }
            if let Some(want) = e.scores {
                if s.scores != want {
                    errors.push(format!("scores {:?}, expected {want:?}", s.scores));
                }
            }
            if let Some(want) = e.terminated {
                if (last.terminated != 0) != want {
                    errors.push(format!("terminated {}, expected {want}", last.terminated));
                }
            }
            if let Some(want) = &e.events {
                let want = event_bits(want)?;
                if last.events != want {
                    errors.push(format!(
                        "events {:?}, expected {:?}",
                        event_names(last.events),
                        event_names(want)
                    ));
                }
            }
            if let Some(want) = &e.winners {
                let bits = want.iter().fold(0, |acc, &p| acc | 1 << p);
                if last.winners != bits {
                    errors.push(format!(
                        "winners bits {:#06b}, expected seats {want:?}",
                        last.winners
                    ));
                }
            }
            if let Some(want) = e.deal_in {
                let got = last.deal_in as i32 - 1;
                if got != want {
                    errors.push(format!("deal_in seat {got}, expected {want}"));
                }
            }
            let has_yaku = |name: &str| -> Result<bool, String> {
                let i = k::host::YAKU_NAMES
                    .iter()
                    .position(|&n| n == name)
                    .ok_or(format!("unknown yaku `{name}`"))?;
                Ok(last.yaku[i / 32] >> (i % 32) & 1 == 1)
            };
            let got_yaku: Vec<&str> = k::host::YAKU_NAMES
                .iter()
                .copied()
                .filter(|n| has_yaku(n).unwrap_or(false))
                .collect();
            for y in &e.yaku {
                if !has_yaku(y)? {
                    errors.push(format!("yaku `{y}` missing; the winners had {got_yaku:?}"));
                }
            }
            for y in &e.no_yaku {
                if has_yaku(y)? {
                    errors.push(format!(
                        "yaku `{y}` should not count; the winners had {got_yaku:?}"
                    ));
                }
            }
            let fields = [
                ("round", e.round, s.round),
                ("dealer", e.dealer, s.dealer),
                ("honba", e.honba, s.honba),
                ("sticks", e.sticks, s.sticks),
                ("current_player", e.current_player, last.current_player),
            ];
            for (what, want, got) in fields {
                if let Some(want) = want {
                    if got != want {
                        errors.push(format!("{what} {got}, expected {want}"));
                    }
                }
            }
            if let Some(want) = e.illegal {
                if (last.illegal != 0) != want {
                    errors.push(format!("illegal {}, expected {want}", last.illegal));
                }
            }
            trace.table = (s.round, s.dealer, s.honba, s.sticks, s.scores);
            if errors.is_empty() {
                Ok(trace)
            } else {
                Err(format!("after the last step: {}", errors.join("; ")))
            }
        }
    };
}

runner!(run_red, red, Red);
runner!(run_no_red, no_red, NoRed);
runner!(run_mjsoul, mjsoul, Mjsoul);
runner!(run_mleague, mleague, Mleague);
runner!(run_wrc, wrc, Wrc);
runner!(run_sanma, sanma, Sanma);
runner!(run_mjsoul_sanma, mjsoul_sanma, MjsoulSanma);

fn run(sc: &Scenario) -> Result<Trace, String> {
    match sc.variant.as_str() {
        "red" => run_red(sc),
        "no_red" => run_no_red(sc),
        "mjsoul" => run_mjsoul(sc),
        "mleague" => run_mleague(sc),
        "wrc" => run_wrc(sc),
        "sanma" => run_sanma(sc),
        "mjsoul_sanma" => run_mjsoul_sanma(sc),
        v => Err(format!(
            "unknown variant `{v}` (red, no_red, mjsoul, mleague, wrc, sanma, mjsoul_sanma)"
        )),
    }
}

#[test]
fn rule_scenarios() {
    let scenarios = load();
    let mut names = BTreeSet::new();
    for sc in &scenarios {
        assert!(
            names.insert(sc.name.clone()),
            "scenario name `{}` is used twice",
            sc.name
        );
        assert!(!sc.rule.trim().is_empty(), "scenario `{}` has no rule", sc.name);
    }
    for (name, _) in KNOWN_FAILING {
        assert!(
            names.contains(*name),
            "KNOWN_FAILING names `{name}`, which is not a scenario"
        );
    }
    let mut failures = Vec::new();
    let mut passed = 0;
    for sc in &scenarios {
        let known = KNOWN_FAILING.iter().find(|(n, _)| *n == sc.name);
        match (run(sc), known) {
            (Ok(_), None) => passed += 1,
            (Ok(_), Some(_)) => {
                passed += 1;
                eprintln!(
                    "NOTE: `{}` is in KNOWN_FAILING but passes now: take it off the list",
                    sc.name
                );
            }
            (Err(e), Some((_, why))) => {
                eprintln!("KNOWN FAILING `{}` ({}): {e}\n  why: {why}", sc.name, sc.rule);
            }
            (Err(e), None) => failures.push(format!("`{}` ({}): {e}", sc.name, sc.rule)),
        }
    }
    eprintln!("{passed} of {} scenarios pass", scenarios.len());
    assert!(
        failures.is_empty(),
        "{} scenario(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Every scenario of `variant` again on the `Env` of both backends, on the GPU device of that
/// variant's parity test (`env_parity`), whose step and reset pipelines are compiled already: the
/// rounds dealt from the scenarios' walls and tables (`Env::deal`), the actions the native run
/// played, the scenarios of each mode and uma stepped as one batch. The CPU env must see what the
/// native run saw after every action (and its table at the end), and the GPU env the same steps as
/// the CPU env and the same states at the end, so each scenario's expectations, checked on the
/// native run, hold on the GPU too. Envs whose script has ended are given action 0 on both
/// backends alike.
pub(crate) fn on_both_backends(variant: Variant, mut gpu: rinshan_engine::gpu::Gpu) {
    type Group = Vec<(String, Trace)>;
    let mut groups: std::collections::BTreeMap<(usize, [i32; 4], u32), Group> = Default::default();
    for sc in load() {
        let known = KNOWN_FAILING.iter().any(|(n, _)| *n == sc.name);
        if known || sc.variant.parse::<Variant>().ok() != Some(variant) {
            continue;
        }
        let trace = run(&sc).unwrap_or_else(|e| panic!("`{}`: {e}", sc.name));
        let key = (trace.mode as usize, trace.uma, trace.penalty.to_bits());
        groups.entry(key).or_default().push((sc.name.clone(), trace));
    }
    let mut checked = 0;
    for traces in groups.into_values() {
        let first = &traces[0].1;
        let config = rinshan_engine::env::Config {
            mode: first.mode,
            uma: Some(first.uma),
            penalty: Some(first.penalty),
            threads: Some(1),
            ..rinshan_engine::env::Config::new(variant, traces.len())
        };
        let mut cpu = rinshan_engine::env::Env::new(config.clone()).expect("cpu env");
        let mut on_gpu = rinshan_engine::env::Env::with_gpu(config, gpu).expect("gpu env");
        cpu.reset().expect("cpu reset");
        on_gpu.reset().expect("gpu reset");
        let deals: Vec<Option<Deal>> = traces.iter().map(|(_, t)| Some(t.deal.clone())).collect();
        let c = cpu.deal(&deals).expect("cpu deal").clone();
        let g = on_gpu.deal(&deals).expect("gpu deal").clone();
        assert_eq!(c, g, "{variant}: the deals differ between the backends");
        let longest = traces.iter().map(|(_, t)| t.actions.len()).max().unwrap_or(0);
        for k in 0..longest {
            let actions: Vec<u32> = traces
                .iter()
                .map(|(_, t)| t.actions.get(k).copied().unwrap_or(0))
                .collect();
            let c = cpu.step(&actions).expect("cpu step").clone();
            let g = on_gpu.step(&actions).expect("gpu step").clone();
            assert_eq!(c, g, "{variant}: step {k} differs between the backends");
            for (i, (name, t)) in traces.iter().enumerate() {
                // The next round's wall comes from each game's seed, which the env's and the native
                // run's differ in: the native run is followed up to the first round that ends with
                // the game going on, but for the new hand's legal actions.
                let before = &t.seen[..k.min(t.seen.len())];
                if before.iter().any(|v| v.events & ROUND_OVER != 0 && !v.terminated) {
                    continue;
                }
                if let Some(seen) = t.seen.get(k) {
                    let mut got = Seen::of_env(&c, i);
                    if seen.events & ROUND_OVER != 0 && !seen.terminated {
                        got.mask = seen.mask;
                    }
                    assert_eq!(&got, seen, "`{name}`: step {k}: the env differs from the kernel");
                }
                if k + 1 == t.actions.len() {
                    let table = &cpu.tables().expect("tables")[i];
                    let got = (table.round, table.dealer, table.honba, table.sticks, table.scores);
                    assert_eq!(got, t.table, "`{name}`: the table after the last step");
                    checked += 1;
                }
            }
        }
        assert!(
            cpu.states_words().expect("cpu states") == on_gpu.states_words().expect("gpu states"),
            "{variant}: the states differ between the backends at the end"
        );
        gpu = on_gpu.into_gpu().expect("a GPU env gives its device back");
    }
    assert!(checked > 0, "{variant}: no scenario");
    eprintln!("{variant}: {checked} scenarios played alike on the kernel, the CPU env and the GPU env");
}

fn tiny(hands: [&str; 4]) -> Scenario {
    Scenario {
        name: "tiny".into(),
        rule: "harness self-test".into(),
        variant: "red".into(),
        mode: "single".into(),
        dealer: 1,
        hands: hands.map(String::from).to_vec(),
        draws: vec!["1z".into()],
        seat_draws: vec![],
        wall_at: Default::default(),
        dora: vec!["2z".into()],
        ura: vec![],
        rinshan: vec![],
        uma: None,
        penalty: None,
        seed: None,
        start: None,
        steps: vec![],
        expect: Expect::default(),
    }
}

#[test]
fn harness_builds_walls_and_rejects_overused_tiles() {
    let sc = tiny(["123456789m1234z"; 4]);
    let err = build_wall(&sc, Variant::Red).unwrap_err();
    assert!(err.contains("no copy of"), "{err}");
    let sc = tiny([
        "123456789m1234z",
        "123456789p1234z",
        "123456789s1234z",
        "1111222333444z",
    ]);
    let err = build_wall(&sc, Variant::Red).unwrap_err();
    assert!(err.contains("no copy of 1z"), "{err}");
    let sc = tiny([
        "123406789m1234z",
        "123456789p1567z",
        "123456789s2567z",
        "1188m99p1199s567z",
    ]);
    let wall = build_wall(&sc, Variant::Red).expect("wall");
    // Dealer is seat 1: its hand comes first; seat 0 deals last.
    assert_eq!(wall[0], 9);
    assert_eq!(wall[39], 0);
    assert_eq!(wall[43], 34);
    assert_eq!(wall[52], 27);
    assert_eq!(wall[122], 28);
    let mut counts = [0u32; 37];
    wall.iter().for_each(|&v| counts[v as usize] += 1);
    assert_eq!(counts[4], 3);
    assert_eq!(counts[34], 1);
    assert!(counts[..34].iter().all(|&n| n == 4 || n == 3));
}
