//! An independent brute-force oracle for hand scoring, checked against `rinshan_engine::hand::score` on
//! random winning hands.
//!
//! The oracle shares nothing with the scoring kernel but the rule files: it splits the concealed
//! tiles into sets and a pair by plain recursion over tile counts (no suit tables), places the
//! winning tile in every set that can hold it, computes every `Features` field of each reading from
//! the doc comments of `rules/kernel/features.rs`, evaluates the yaku conditions of
//! `rules/yaku.toml` with the codegen's interpreter, and counts fu, points and payments by Tenhou's
//! rules (the variant's `[scoring]` options read from the spec).
#![allow(clippy::needless_range_loop)] // index loops mirror the rules text in this oracle

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use rinshan_codegen::expr::{eval, Value};
use rinshan_codegen::Spec;
use rinshan_engine::hand::{score, Payment, Score, ScoreError, Win, WinContext};
use rinshan_engine::notation::{parse_meld, parse_tile, parse_tiles, MeldKind};
use rinshan_engine::random::{random_win, Rng};
use rinshan_engine::{TileType, Variant};

/// The oracle's own tile: a type index 0..33, counted with plain arithmetic.
type Tile = u8;

fn tile_name(t: Tile) -> String {
    TileType::new(t).map_or_else(|| format!("#{t}"), TileType::name)
}

const WHITE: Tile = 31;
const GREEN: Tile = 32;
const RED: Tile = 33;

fn is_honor(t: Tile) -> bool {
    t >= 27
}

fn is_terminal_or_honor(t: Tile) -> bool {
    is_honor(t) || t.is_multiple_of(9) || t % 9 == 8
}

fn is_dragon(t: Tile) -> bool {
    (WHITE..=RED).contains(&t)
}

fn is_wind(t: Tile) -> bool {
    (27..31).contains(&t)
}

fn is_green(t: Tile) -> bool {
    // 2s 3s 4s 6s 8s and the green dragon.
    [19, 20, 21, 23, 25, GREEN].contains(&t)
}

/// The tile an indicator points at.
fn dora_of(indicator: Tile) -> Tile {
    match indicator {
        0..=26 => indicator / 9 * 9 + (indicator % 9 + 1) % 9,
        27..=30 => 27 + (indicator - 27 + 1) % 4,
        _ => 31 + (indicator - 31 + 1) % 3,
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Run,
    Triplet,
    Quad,
}

/// One set of a reading: from the concealed tiles (`called = None`) or a meld.
#[derive(Clone, Copy, Debug)]
struct Set {
    shape: Shape,
    /// The set's tile (the lowest one of a run).
    tile: Tile,
    called: Option<MeldKind>,
}

impl Set {
    fn tiles(&self) -> Vec<Tile> {
        match self.shape {
            Shape::Run => vec![self.tile, self.tile + 1, self.tile + 2],
            Shape::Triplet => vec![self.tile; 3],
            Shape::Quad => vec![self.tile; 4],
        }
    }

    fn has_terminal_or_honor(&self) -> bool {
        self.tiles().into_iter().any(is_terminal_or_honor)
    }
}

/// Where the winning tile sits in a standard reading.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slot {
    Pair,
    Triplet,
    /// The run starting at this tile.
    Run(Tile),
}

/// Every `Features` field, filled by the oracle.
#[derive(Clone, Copy, Debug, Default)]
struct Features {
    concealed: bool,
    tsumo: bool,
    riichi: bool,
    double_riichi: bool,
    ippatsu: bool,
    haitei: bool,
    houtei: bool,
    rinshan: bool,
    chankan: bool,
    tenhou: bool,
    chiihou: bool,
    dealer: bool,
    standard: bool,
    seven_pairs: bool,
    thirteen_orphans: bool,
    thirteen_wait: bool,
    all_simples: bool,
    no_simples: bool,
    honors_only: bool,
    green_only: bool,
    has_honors: bool,
    suits: u32,
    outside: bool,
    runs: u32,
    triplets: u32,
    concealed_triplets: u32,
    kans: u32,
    identical_runs: u32,
    two_sided_wait: bool,
    pair_wait: bool,
    pair_is_value: bool,
    seat_wind_set: bool,
    round_wind_set: bool,
    white_set: bool,
    green_set: bool,
    red_set: bool,
    dragon_sets: u32,
    wind_sets: u32,
    dragon_pair: bool,
    wind_pair: bool,
    straight: bool,
    three_colour_runs: bool,
    three_colour_triplets: bool,
    nine_gates: bool,
    nine_gates_nine_wait: bool,
}

impl Features {
    fn get(&self, name: &str) -> Option<Value> {
        let b = |x: bool| Some(Value::Bool(x));
        let n = |x: u32| Some(Value::Int(i64::from(x)));
        match name {
            "concealed" => b(self.concealed),
            "tsumo" => b(self.tsumo),
            "riichi" => b(self.riichi),
            "double_riichi" => b(self.double_riichi),
            "ippatsu" => b(self.ippatsu),
            "haitei" => b(self.haitei),
            "houtei" => b(self.houtei),
            "rinshan" => b(self.rinshan),
            "chankan" => b(self.chankan),
            "tenhou" => b(self.tenhou),
            "chiihou" => b(self.chiihou),
            "dealer" => b(self.dealer),
            "standard" => b(self.standard),
            "seven_pairs" => b(self.seven_pairs),
            "thirteen_orphans" => b(self.thirteen_orphans),
            "thirteen_wait" => b(self.thirteen_wait),
            "all_simples" => b(self.all_simples),
            "no_simples" => b(self.no_simples),
            "honors_only" => b(self.honors_only),
            "green_only" => b(self.green_only),
            "has_honors" => b(self.has_honors),
            "suits" => n(self.suits),
            "outside" => b(self.outside),
            "runs" => n(self.runs),
            "triplets" => n(self.triplets),
            "concealed_triplets" => n(self.concealed_triplets),
            "kans" => n(self.kans),
            "identical_runs" => n(self.identical_runs),
            "two_sided_wait" => b(self.two_sided_wait),
            "pair_wait" => b(self.pair_wait),
            "pair_is_value" => b(self.pair_is_value),
            "seat_wind_set" => b(self.seat_wind_set),
            "round_wind_set" => b(self.round_wind_set),
            "white_set" => b(self.white_set),
            "green_set" => b(self.green_set),
            "red_set" => b(self.red_set),
            "dragon_sets" => n(self.dragon_sets),
            "wind_sets" => n(self.wind_sets),
            "dragon_pair" => b(self.dragon_pair),
            "wind_pair" => b(self.wind_pair),
            "straight" => b(self.straight),
            "three_colour_runs" => b(self.three_colour_runs),
            "three_colour_triplets" => b(self.three_colour_triplets),
            "nine_gates" => b(self.nine_gates),
            "nine_gates_nine_wait" => b(self.nine_gates_nine_wait),
            _ => None,
        }
    }
}

/// Every way to split `counts` into sets (runs and triplets), by taking the lowest remaining tile.
fn split_into_sets(counts: &mut [u8; 34], acc: &mut Vec<Set>, out: &mut Vec<Vec<Set>>) {
    let Some(t) = (0..34).find(|&t| counts[t] > 0) else {
        out.push(acc.clone());
        return;
    };
    let tile = t as Tile;
    if counts[t] >= 3 {
        counts[t] -= 3;
        acc.push(Set {
            shape: Shape::Triplet,
            tile,
            called: None,
        });
        split_into_sets(counts, acc, out);
        acc.pop();
        counts[t] += 3;
    }
    if !is_honor(tile) && t % 9 <= 6 && counts[t + 1] > 0 && counts[t + 2] > 0 {
        for k in t..t + 3 {
            counts[k] -= 1;
        }
        acc.push(Set {
            shape: Shape::Run,
            tile,
            called: None,
        });
        split_into_sets(counts, acc, out);
        acc.pop();
        for k in t..t + 3 {
            counts[k] += 1;
        }
    }
}

/// Every decomposition of the concealed tiles into a pair and sets: (pair tile, concealed sets).
fn decompositions(hand: &[u8; 34]) -> Vec<(Tile, Vec<Set>)> {
    let mut result = Vec::new();
    for p in 0..34 {
        if hand[p] < 2 {
            continue;
        }
        let mut rest = *hand;
        rest[p] -= 2;
        let mut splits = Vec::new();
        split_into_sets(&mut rest, &mut Vec::new(), &mut splits);
        result.extend(splits.into_iter().map(|sets| (p as Tile, sets)));
    }
    result
}

fn meld_set(kind: MeldKind, tile: Tile) -> Set {
    let shape = match kind {
        MeldKind::Chi => Shape::Run,
        MeldKind::Pon => Shape::Triplet,
        MeldKind::Kan | MeldKind::Ankan | MeldKind::Kakan => Shape::Quad,
    };
    Set {
        shape,
        tile,
        called: Some(kind),
    }
}

/// What the oracle makes of a hand.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Judged {
    han: u32,
    fu: u32,
    yakuman: u32,
    base: u32,
    /// Yaku names with han (yakuman: weight), plus dora / aka / ura when non-zero.
    yaku: BTreeMap<String, u32>,
}

struct Oracle {
    spec: Spec,
    /// For each yaku, every yaku it removes (followed transitively here).
    removes: Vec<Vec<bool>>,
}

impl Oracle {
    fn new(variant: &str) -> Oracle {
        let rules = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../rules");
        let spec = rinshan_codegen::load(&rules, variant).unwrap_or_else(|d| panic!("loading the spec: {d:?}"));
        let n = spec.yaku.len();
        let mut removes = vec![vec![false; n]; n];
        for (i, y) in spec.yaku.iter().enumerate() {
            for &j in &y.supersedes {
                removes[i][j] = true;
            }
        }
        // Transitive closure (Floyd-Warshall style).
        for k in 0..n {
            for i in 0..n {
                if removes[i][k] {
                    for j in 0..n {
                        if removes[k][j] {
                            removes[i][j] = true;
                        }
                    }
                }
            }
        }
        let oracle = Oracle { spec, removes };
        // The oracle must know every feature the spec knows (a new field would otherwise go unseen).
        let f = Features::default();
        for feature in &oracle.spec.features {
            assert!(
                f.get(&feature.name).is_some(),
                "the oracle does not compute feature `{}`",
                feature.name
            );
        }
        oracle
    }

    fn lookup(&self, f: &Features, name: &str) -> Value {
        f.get(name)
            .or_else(|| self.spec.option(name).map(Value::Bool))
            .unwrap_or_else(|| panic!("unknown name `{name}` in a yaku condition"))
    }

    /// Applies the yaku table to one reading. `fu` is the reading's fu before the tsumo bonus,
    /// the open-20 rule and rounding; `flat_fu` replaces it for seven pairs.
    fn judge(&self, win: &Win, all: &[u8; 34], f: &Features, fu: u32, flat_fu: Option<u32>) -> Option<Judged> {
        let v = &self.spec.variant;
        let n = self.spec.yaku.len();
        let held: Vec<bool> = self
            .spec
            .yaku
            .iter()
            .map(|y| {
                eval(&y.condition, &|name| self.lookup(f, name)).as_bool()
                    && (f.concealed || y.han_open > 0 || y.yakuman > 0)
            })
            .collect();
        let mut kept = held.clone();
        for i in 0..n {
            if held[i] {
                for j in 0..n {
                    if self.removes[i][j] {
                        kept[j] = false;
                    }
                }
            }
        }
        let yakuman_weight = |i: usize| {
            if v.bool_option("double_yakuman").expect("double_yakuman") {
                self.spec.yaku[i].yakuman
            } else {
                1
            }
        };
        let yakuman_held: Vec<usize> = (0..n).filter(|&i| kept[i] && self.spec.yaku[i].yakuman > 0).collect();
        let mut yaku = BTreeMap::new();
        if !yakuman_held.is_empty() {
            let mut total = 0;
            for &i in &yakuman_held {
                yaku.insert(self.spec.yaku[i].name.clone(), yakuman_weight(i));
                total += yakuman_weight(i);
            }
            if !v.bool_option("multiple_yakuman").expect("multiple_yakuman") {
                total = total.min(1);
            }
            return Some(Judged {
                han: 0,
                fu: 0,
                yakuman: total,
                base: 8000 * total,
                yaku,
            });
        }
        let mut han = 0;
        for i in (0..n).filter(|&i| kept[i]) {
            let y = &self.spec.yaku[i];
            let h = if f.concealed { y.han_closed } else { y.han_open };
            yaku.insert(y.name.clone(), h);
            han += h;
        }
        if han == 0 {
            return None;
        }
        let count = |indicators: &[TileType]| {
            indicators
                .iter()
                .map(|&i| u32::from(all[dora_of(u8::from(i)) as usize]))
                .sum::<u32>()
        };
        let dora = count(&win.context.dora);
        let ura = if f.riichi { count(&win.context.ura) } else { 0 };
        let aka = if v.red_fives { u32::from(win.aka) } else { 0 };
        for (name, k) in [("dora", dora), ("ura", ura), ("aka", aka)] {
            if k > 0 {
                yaku.insert(name.to_string(), k);
            }
        }
        han += dora + ura + aka;
        let fu = match flat_fu {
            Some(x) => x,
            None => {
                let mut fu = fu;
                if f.tsumo && !yaku.contains_key("pinfu") {
                    fu += 2;
                }
                if !f.concealed && fu == 20 {
                    fu = 30;
                }
                fu.div_ceil(10) * 10
            }
        };
        let base = if han >= 13 && v.bool_option("kazoe_yakuman").expect("kazoe_yakuman") {
            8000
        } else if han >= 11 {
            6000
        } else if han >= 8 {
            4000
        } else if han >= 6 {
            3000
        } else if han >= 5 {
            2000
        } else {
            let raw = fu << (han + 2);
            if raw >= 2000 || (v.bool_option("kiriage_mangan").expect("kiriage_mangan") && raw == 1920) {
                2000
            } else {
                raw
            }
        };
        Some(Judged {
            han,
            fu,
            yakuman: 0,
            base,
            yaku,
        })
    }

    /// Scores `win`: the best readings (all of those tied for best) and the number of readings, or
    /// the error kind.
    fn score(&self, win: &Win) -> (Result<Vec<Judged>, ScoreError>, usize) {
        let c = &win.context;
        let hand = &win.hand;
        let w = u8::from(win.win);
        let melds: Vec<Set> = win.melds.iter().map(|m| meld_set(m.kind, u8::from(m.tile))).collect();
        let mut all = *hand;
        for m in &melds {
            for t in m.tiles() {
                all[t as usize] += 1;
            }
        }
        // What holds for every reading.
        let mut common = Features {
            concealed: win.melds.iter().all(|m| m.kind == MeldKind::Ankan),
            tsumo: c.tsumo,
            riichi: c.riichi || c.double_riichi,
            double_riichi: c.double_riichi,
            ippatsu: c.ippatsu,
            haitei: c.haitei,
            houtei: c.houtei,
            rinshan: c.rinshan,
            chankan: c.chankan,
            tenhou: c.tenhou,
            chiihou: c.chiihou,
            dealer: c.dealer,
            ..Features::default()
        };
        let tiles: Vec<Tile> = (0..34u8).filter(|&t| all[t as usize] > 0).collect();
        common.all_simples = tiles.iter().all(|&t| !is_terminal_or_honor(t));
        common.no_simples = tiles.iter().all(|&t| is_terminal_or_honor(t));
        common.honors_only = tiles.iter().all(|&t| is_honor(t));
        common.green_only = tiles.iter().all(|&t| is_green(t));
        common.has_honors = tiles.iter().any(|&t| is_honor(t));
        common.suits = (0..3)
            .filter(|&s| tiles.iter().any(|&t| !is_honor(t) && t / 9 == s))
            .count() as u32;
        if win.melds.is_empty() && common.suits == 1 && !common.has_honors {
            let s = (tiles[0] / 9 * 9) as usize;
            let need = [3, 1, 1, 1, 1, 1, 1, 1, 3];
            common.nine_gates = (0..9).all(|i| hand[s + i] >= need[i]);
            let mut before = *hand;
            before[w as usize] -= 1;
            common.nine_gates_nine_wait = common.nine_gates && (0..9).all(|i| before[s + i] == need[i]);
        }

        let mut readings = 0;
        let mut best: Vec<Judged> = Vec::new();
        let mut complete = false;
        let mut consider = |j: Option<Judged>| {
            let Some(j) = j else { return };
            let key = |x: &Judged| (x.base, x.han, x.fu);
            match best.first().map(key) {
                Some(k) if k > key(&j) => {}
                Some(k) if k == key(&j) => best.push(j),
                _ => best = vec![j],
            }
        };

        // Four sets and a pair.
        if melds.len() <= 4 {
            for (pair, concealed_sets) in decompositions(hand) {
                let mut slots = Vec::new();
                if pair == w {
                    slots.push(Slot::Pair);
                }
                if concealed_sets.iter().any(|s| s.shape == Shape::Triplet && s.tile == w) {
                    slots.push(Slot::Triplet);
                }
                for s in &concealed_sets {
                    let run_here = s.shape == Shape::Run && s.tile <= w && w <= s.tile + 2;
                    if run_here && !slots.contains(&Slot::Run(s.tile)) {
                        slots.push(Slot::Run(s.tile));
                    }
                }
                let sets: Vec<Set> = melds.iter().chain(concealed_sets.iter()).copied().collect();
                for slot in slots {
                    readings += 1;
                    complete = true;
                    let double_wind = self
                        .spec
                        .variant
                        .u32_option("double_wind_pair_fu")
                        .expect("double_wind_pair_fu");
                    let (f, fu) = standard_reading(win, &common, pair, &sets, slot, double_wind);
                    consider(self.judge(win, &all, &f, fu, None));
                }
            }
        }
        // Seven distinct pairs.
        if melds.is_empty() && (0..34).filter(|&t| hand[t] == 2).count() == 7 {
            readings += 1;
            complete = true;
            let f = Features {
                standard: false,
                seven_pairs: true,
                pair_wait: true,
                ..common
            };
            consider(self.judge(win, &all, &f, 0, Some(25)));
        }
        // Thirteen orphans.
        let orphans: Vec<Tile> = (0..34u8).filter(|&t| is_terminal_or_honor(t)).collect();
        let only_orphans = (0..34u8).all(|t| is_terminal_or_honor(t) || hand[t as usize] == 0);
        if melds.is_empty() && only_orphans && orphans.iter().all(|&t| hand[t as usize] >= 1) {
            readings += 1;
            complete = true;
            let mut before = *hand;
            before[w as usize] -= 1;
            let thirteen_wait = orphans.iter().all(|&t| before[t as usize] == 1);
            let f = Features {
                thirteen_orphans: true,
                thirteen_wait,
                pair_wait: thirteen_wait,
                ..common
            };
            consider(self.judge(win, &all, &f, 0, Some(0)));
        }
        let result = if !best.is_empty() {
            Ok(best)
        } else if complete {
            Err(ScoreError::NoYaku)
        } else {
            Err(ScoreError::NotComplete)
        };
        (result, readings)
    }
}

/// The features and fu (before the tsumo bonus and rounding) of one standard reading.
/// `double_wind_pair_fu`: the fu of a pair of the wind that is both round and seat wind (the
/// spec's option; either wind alone is 2).
fn standard_reading(
    win: &Win,
    common: &Features,
    pair: Tile,
    sets: &[Set],
    slot: Slot,
    double_wind_pair_fu: u32,
) -> (Features, u32) {
    let c = &win.context;
    let w = u8::from(win.win);
    let ron = !c.tsumo;
    let mut f = Features {
        standard: true,
        ..*common
    };
    let seat = 27 + c.seat_wind;
    let round = 27 + c.round_wind;
    let mut fu = 20;
    if f.concealed && ron {
        fu += 10;
    }
    // A set counts as concealed unless it was called, or is the triplet that a ron completed.
    let ron_triplet =
        |s: &Set| ron && slot == Slot::Triplet && s.called.is_none() && s.shape == Shape::Triplet && s.tile == w;
    let is_concealed = |s: &Set| match s.called {
        None => !ron_triplet(s),
        Some(kind) => kind == MeldKind::Ankan,
    };
    let mut run_counts: BTreeMap<Tile, u32> = BTreeMap::new();
    let mut runs_of_suit = [[false; 9]; 3];
    let mut triplets_of_suit = [[false; 9]; 3];
    for s in sets {
        match s.shape {
            Shape::Run => {
                f.runs += 1;
                runs_of_suit[(s.tile / 9) as usize][(s.tile % 9) as usize] = true;
                if s.called.is_none() {
                    *run_counts.entry(s.tile).or_default() += 1;
                }
            }
            Shape::Triplet | Shape::Quad => {
                f.triplets += 1;
                let concealed = is_concealed(s);
                if concealed {
                    f.concealed_triplets += 1;
                }
                let mut set_fu = match (s.shape, concealed) {
                    (Shape::Triplet, false) => 2,
                    (Shape::Triplet, true) => 4,
                    (_, false) => 8,
                    (_, true) => 16,
                };
                if is_terminal_or_honor(s.tile) {
                    set_fu *= 2;
                }
                fu += set_fu;
                if s.shape == Shape::Quad {
                    f.kans += 1;
                }
                if is_honor(s.tile) {
                    f.seat_wind_set |= s.tile == seat;
                    f.round_wind_set |= s.tile == round;
                    f.white_set |= s.tile == WHITE;
                    f.green_set |= s.tile == GREEN;
                    f.red_set |= s.tile == RED;
                    f.dragon_sets += u32::from(is_dragon(s.tile));
                    f.wind_sets += u32::from(is_wind(s.tile));
                } else {
                    triplets_of_suit[(s.tile / 9) as usize][(s.tile % 9) as usize] = true;
                }
            }
        }
    }
    f.identical_runs = run_counts.values().map(|&m| m / 2).sum();
    f.outside = is_terminal_or_honor(pair) && sets.iter().all(Set::has_terminal_or_honor);
    f.straight = runs_of_suit.iter().any(|r| r[0] && r[3] && r[6]);
    f.three_colour_runs = (0..7).any(|i| (0..3).all(|s| runs_of_suit[s][i]));
    f.three_colour_triplets = (0..9).any(|i| (0..3).all(|s| triplets_of_suit[s][i]));
    f.dragon_pair = is_dragon(pair);
    f.wind_pair = is_wind(pair);
    f.pair_is_value = is_dragon(pair) || pair == seat || pair == round;
    if is_dragon(pair) {
        fu += 2;
    }
    if pair == seat && pair == round {
        fu += double_wind_pair_fu;
    } else if pair == seat || pair == round {
        fu += 2;
    }
    match slot {
        Slot::Pair => {
            f.pair_wait = true;
            fu += 2; // tanki
        }
        Slot::Triplet => {}
        Slot::Run(start) => {
            let at = w - start;
            let penchan = (at == 2 && start % 9 == 0) || (at == 0 && start % 9 == 6);
            if at == 1 || penchan {
                fu += 2; // kanchan or penchan
            } else {
                f.two_sided_wait = true;
            }
        }
    }
    (f, fu)
}

fn ceil100(x: u32) -> u32 {
    x.div_ceil(100) * 100
}

fn payment(spec: &Spec, win: &Win, base: u32) -> (Payment, u32) {
    let c = &win.context;
    let v = &spec.variant;
    let sticks = c.sticks * v.u32_option("riichi_stick_points").expect("riichi_stick_points");
    if c.tsumo {
        let honba = c.honba * v.u32_option("honba_tsumo_points").expect("honba_tsumo_points");
        if c.dealer {
            let each = ceil100(2 * base) + honba;
            (
                Payment::Tsumo {
                    dealer: None,
                    others: each,
                },
                3 * each + sticks,
            )
        } else {
            let dealer = ceil100(2 * base) + honba;
            let others = ceil100(base) + honba;
            (
                Payment::Tsumo {
                    dealer: Some(dealer),
                    others,
                },
                dealer + 2 * others + sticks,
            )
        }
    } else {
        let ron = ceil100(base * if c.dealer { 6 } else { 4 })
            + c.honba * v.u32_option("honba_ron_points").expect("honba_ron_points");
        (Payment::Ron { discarder: ron }, ron + sticks)
    }
}

fn notation(counts: &[u8; 34]) -> String {
    let mut out = String::new();
    for (suit, letter) in [(0, 'm'), (1, 'p'), (2, 's'), (3, 'z')] {
        let digits: String = (0..34u8)
            .filter(|&t| t / 9 == suit)
            .flat_map(|t| std::iter::repeat_n(tile_name(t).chars().next().unwrap(), counts[t as usize] as usize))
            .collect();
        if !digits.is_empty() {
            out += &digits;
            out.push(letter);
        }
    }
    out
}

fn describe(win: &Win) -> String {
    let c = &win.context;
    let mut s = notation(&win.hand);
    for m in &win.melds {
        let kind = match m.kind {
            MeldKind::Chi => "chi",
            MeldKind::Pon => "pon",
            MeldKind::Kan => "kan",
            MeldKind::Ankan => "ankan",
            MeldKind::Kakan => "kakan",
        };
        let mut counts = [0u8; 34];
        for t in m.tiles() {
            counts[t.index()] += 1;
        }
        write!(s, " {kind}:{}", notation(&counts)).unwrap();
    }
    write!(s, " win {} {}", win.win.name(), if c.tsumo { "tsumo" } else { "ron" }).unwrap();
    let winds = ["E", "S", "W", "N"];
    write!(
        s,
        " round {} seat {}",
        winds[c.round_wind as usize], winds[c.seat_wind as usize]
    )
    .unwrap();
    for (flag, name) in [
        (c.riichi, "riichi"),
        (c.double_riichi, "double_riichi"),
        (c.ippatsu, "ippatsu"),
        (c.haitei, "haitei"),
        (c.houtei, "houtei"),
        (c.rinshan, "rinshan"),
        (c.chankan, "chankan"),
        (c.tenhou, "tenhou"),
        (c.chiihou, "chiihou"),
    ] {
        if flag {
            write!(s, " {name}").unwrap();
        }
    }
    let names = |ts: &[TileType]| ts.iter().map(|t| t.name()).collect::<Vec<_>>().join(",");
    write!(
        s,
        " dora [{}] ura [{}] aka {} honba {} sticks {}",
        names(&c.dora),
        names(&c.ura),
        win.aka,
        c.honba,
        c.sticks
    )
    .unwrap();
    s
}

fn kind(r: &Result<impl Sized, ScoreError>) -> &'static str {
    match r {
        Ok(_) => "Ok",
        Err(ScoreError::NotComplete) => "NotComplete",
        Err(ScoreError::NoYaku) => "NoYaku",
        Err(ScoreError::BadInput(_)) => "BadInput",
    }
}

/// Why the kernel's score differs from the oracle's, as (kind of difference, details), or `None`
/// when they agree. Among readings tied for best (same base, han and fu) any yaku list is accepted.
fn compare(
    oracle: &Oracle,
    win: &Win,
    expected: &Result<Vec<Judged>, ScoreError>,
    got: &Result<Score, ScoreError>,
) -> Option<(String, String)> {
    let (best, s) = match (expected, got) {
        (Ok(best), Ok(s)) => (best, s),
        _ if kind(expected) == kind(got) => return None,
        _ => {
            let what = format!("oracle {} / rinshan {}", kind(expected), kind(got));
            return Some((what, format!("oracle {expected:?}\n    rinshan {got:?}")));
        }
    };
    let yaku: BTreeMap<String, u32> = s.yaku.iter().map(|y| (y.name.to_string(), y.han.number())).collect();
    let j = &best[0];
    let (pay, gain) = payment(&oracle.spec, win, j.base);
    let same = (s.han, s.fu, s.yakuman, s.base, s.payment, s.gain) == (j.han, j.fu, j.yakuman, j.base, pay, gain)
        && best.iter().any(|b| b.yaku == yaku)
        && s.yaku.len() == yaku.len();
    if same {
        return None;
    }
    let tied = if best.len() > 1 {
        format!(
            " (or, tied: {:?})",
            best[1..].iter().map(|b| &b.yaku).collect::<Vec<_>>()
        )
    } else {
        String::new()
    };
    Some((
        "different score".to_string(),
        format!(
            "oracle han {} fu {} yakuman {} base {} {pay:?} gain {gain} yaku {:?}{tied}\n    \
             rinshan han {} fu {} yakuman {} base {} {:?} gain {} yaku {:?}",
            j.han, j.fu, j.yakuman, j.base, j.yaku, s.han, s.fu, s.yakuman, s.base, s.payment, s.gain, yaku
        ),
    ))
}

#[derive(Default, Debug)]
struct Stats {
    wins: usize,
    no_yaku: usize,
    not_complete: usize,
    yakuman: usize,
    multi_reading_wins: usize,
    ties: usize,
    seen_yaku: BTreeMap<String, usize>,
}

fn check_random_wins(variant_name: &str, seeds: std::ops::Range<u64>) -> Stats {
    let oracle = Oracle::new(variant_name);
    let variant = Variant::from_name(variant_name).expect("variant");
    let mut stats = Stats::default();
    // Kind of difference -> (number of hands, the first few of them).
    let mut mismatches: BTreeMap<String, (usize, Vec<String>)> = BTreeMap::new();
    for seed in seeds {
        let win = random_win(&mut Rng::new(seed));
        let (expected, readings) = oracle.score(&win);
        let got = score(variant, &win);
        match &expected {
            Ok(best) => {
                stats.wins += 1;
                stats.yakuman += usize::from(best[0].yakuman > 0);
                stats.multi_reading_wins += usize::from(readings >= 2);
                stats.ties += usize::from(best.len() > 1);
                for name in best[0].yaku.keys() {
                    *stats.seen_yaku.entry(name.clone()).or_default() += 1;
                }
            }
            Err(ScoreError::NoYaku) => stats.no_yaku += 1,
            Err(_) => stats.not_complete += 1,
        }
        if let Some((what, why)) = compare(&oracle, &win, &expected, &got) {
            let entry = mismatches.entry(what).or_default();
            entry.0 += 1;
            if entry.1.len() < 5 {
                entry.1.push(format!("seed {seed}: {}\n    {why}", describe(&win)));
            }
        }
    }
    let unseen: Vec<&str> = oracle
        .spec
        .yaku
        .iter()
        .map(|y| y.name.as_str())
        .filter(|n| !stats.seen_yaku.contains_key(*n))
        .collect();
    eprintln!(
        "{variant_name}: {} wins ({} yakuman, {} with several readings, {} with tied best readings), {} without yaku, {} not complete; yaku never seen: {unseen:?}",
        stats.wins, stats.yakuman, stats.multi_reading_wins, stats.ties, stats.no_yaku, stats.not_complete
    );
    let report: Vec<String> = mismatches
        .iter()
        .map(|(what, (n, first))| format!("{n} hands: {what}; the first ones:\n{}", first.join("\n")))
        .collect();
    assert!(
        mismatches.is_empty(),
        "rinshan and the brute-force oracle disagree ({variant_name}):\n{}",
        report.join("\n")
    );
    stats
}

#[test]
fn brute_force_agrees_on_100000_random_wins() {
    let stats = check_random_wins("red", 0..100_000);
    assert!(
        stats.multi_reading_wins > 1000,
        "too few wins with several readings: {stats:?}"
    );
    assert!(
        stats.wins > 50_000 && stats.no_yaku > 1000 && stats.yakuman > 100,
        "{stats:?}"
    );
    assert!(stats.seen_yaku.contains_key("aka"), "{stats:?}");
}

#[test]
fn brute_force_agrees_on_20000_random_no_red_wins() {
    let stats = check_random_wins("no_red", 1 << 40..(1 << 40) + 20_000);
    assert!(
        stats.multi_reading_wins > 200,
        "too few wins with several readings: {stats:?}"
    );
    assert!(!stats.seen_yaku.contains_key("aka"), "{stats:?}");
}

// The other rule sets score the same hands by their `[scoring]` options (double and several
// yakuman, kazoe yakuman, kiriage mangan), which the oracle reads from their specs too.
#[test]
fn brute_force_agrees_on_20000_random_mjsoul_wins() {
    let stats = check_random_wins("mjsoul", 2 << 40..(2 << 40) + 20_000);
    assert!(stats.multi_reading_wins > 200 && stats.yakuman > 20, "{stats:?}");
    assert!(stats.seen_yaku.contains_key("aka"), "{stats:?}");
}

#[test]
fn brute_force_agrees_on_20000_random_mleague_wins() {
    let stats = check_random_wins("mleague", 3 << 40..(3 << 40) + 20_000);
    assert!(stats.multi_reading_wins > 200 && stats.yakuman > 20, "{stats:?}");
    assert!(stats.seen_yaku.contains_key("aka"), "{stats:?}");
}

#[test]
fn brute_force_agrees_on_20000_random_wrc_wins() {
    let stats = check_random_wins("wrc", 4 << 40..(4 << 40) + 20_000);
    assert!(stats.multi_reading_wins > 200 && stats.yakuman > 20, "{stats:?}");
    assert!(!stats.seen_yaku.contains_key("aka"), "{stats:?}");
}

/// A hand picked by hand: (concealed tiles with the winning one, winning tile, melds, tsumo, riichi,
/// round wind, seat wind), and what the rules make of it: Ok((han, fu, yakuman)) or the error.
type Picked = (
    &'static str,
    &'static str,
    &'static [&'static str],
    bool,
    bool,
    u8,
    u8,
    Result<(u32, u32, u32), ScoreError>,
);

/// Worked out by hand from the rules, and reaching the yakuman random hands rarely make.
const PICKED: [Picked; 11] = [
    // menzen tsumo + pinfu: 20 fu flat.
    ("123456m234p678s55p", "4m", &[], true, false, 0, 1, Ok((2, 20, 0))),
    // chiitoitsu: 25 fu.
    ("1133m5577p22s66s77z", "2s", &[], false, false, 0, 1, Ok((2, 25, 0))),
    // riichi, dealer, double-East pair 4 + closed ron 10 + kanchan 2 = 36 -> 40 fu.
    ("123m456p789s345s11z", "8s", &[], false, true, 0, 0, Ok((1, 40, 0))),
    // tanyao; the triplet completed by ron counts open: 20 + 10 + 4 + 4 + 2 = 40 fu, no sanankou.
    ("222m444p666s345m88m", "6s", &[], false, false, 0, 1, Ok((1, 40, 0))),
    // junsei chuuren: a single yakuman under Tenhou's rules (the red spec).
    ("11123455678999m", "5m", &[], false, false, 0, 1, Ok((0, 0, 1))),
    // chuuren: before the win 1112345778999m, not the nine-sided wait.
    ("11123456778999m", "6m", &[], false, false, 0, 1, Ok((0, 0, 1))),
    // daisuushi + suuankou tanki: two yakuman add up, each single under Tenhou's rules.
    ("111222333444z55m", "5m", &[], true, false, 0, 1, Ok((0, 0, 2))),
    // shousuushi.
    ("11122233344z123m", "3m", &[], false, false, 0, 1, Ok((0, 0, 1))),
    // chinroutou (the ron on 999s leaves three concealed triplets: no suuankou).
    ("111999m111p99911s", "9s", &[], false, false, 0, 1, Ok((0, 0, 1))),
    // kokushi with the thirteen-sided wait: single under Tenhou's rules.
    ("19m19p19s12345677z", "7z", &[], false, false, 0, 1, Ok((0, 0, 1))),
    // open, complete, no yaku.
    (
        "456p789s234s55p",
        "2s",
        &["chi:123m"],
        false,
        false,
        0,
        1,
        Err(ScoreError::NoYaku),
    ),
];

fn picked_win(p: &Picked) -> Win {
    let (hand, win, melds, tsumo, riichi, round_wind, seat_wind, _) = *p;
    let tiles = parse_tiles(hand).unwrap();
    let melds: Vec<_> = melds.iter().map(|m| parse_meld(m).unwrap()).collect();
    let context = WinContext {
        tsumo,
        riichi,
        dealer: seat_wind == 0,
        round_wind,
        seat_wind,
        ..WinContext::default()
    };
    Win {
        hand: tiles.counts(),
        win: parse_tile(win).unwrap().kind(),
        melds,
        aka: 0,
        context,
    }
}

#[test]
fn oracle_matches_hand_worked_values() {
    let oracle = Oracle::new("red");
    for p in &PICKED {
        let win = picked_win(p);
        let got = oracle
            .score(&win)
            .0
            .map(|best| (best[0].han, best[0].fu, best[0].yakuman));
        assert_eq!(got, p.7, "oracle on {}", describe(&win));
    }
}

#[test]
fn brute_force_agrees_on_hand_picked_wins() {
    let oracle = Oracle::new("red");
    let variant = Variant::from_name("red").unwrap();
    let mut mismatches = Vec::new();
    for p in &PICKED {
        let win = picked_win(p);
        let expected = oracle.score(&win).0;
        if let Some((what, why)) = compare(&oracle, &win, &expected, &score(variant, &win)) {
            mismatches.push(format!("{}: {what}\n    {why}", describe(&win)));
        }
    }
    assert!(
        mismatches.is_empty(),
        "rinshan and the brute-force oracle disagree:\n{}",
        mismatches.join("\n")
    );
}
