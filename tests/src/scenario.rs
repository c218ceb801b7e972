//! Rule scenarios as data (`tests/data/scenarios.toml`): the model of the file, the walls it
//! describes and action names, shared by the scenario runner (tests/scenarios.rs) and the tests
//! that replay a scenario's prepared round through other paths (tests/tenhou_roundtrip.rs).

use std::collections::BTreeSet;

use rinshan_engine::notation::parse_tile;
use rinshan_engine::{Tile, TileType, Variant};
use serde::Deserialize;

use crate::test_data;

/// The whole file: `[[scenario]]` tables.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct File {
    pub scenario: Vec<Scenario>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    pub name: String,
    pub rule: String,
    pub variant: String,
    #[serde(default = "default_mode")]
    pub mode: String,
    #[serde(default)]
    pub dealer: u32,
    /// One per seat (absolute seats, not dealing order: four, or three in sanma), 13 tiles each.
    pub hands: Vec<String>,
    /// Live wall from `wall[52]` on ("x": filler).
    #[serde(default)]
    pub draws: Vec<String>,
    /// Per seat: the tiles of its k-th live draw, assuming no calls or kans (52 + its turn offset + 4k).
    #[serde(default)]
    pub seat_draws: Vec<Vec<String>>,
    /// Single wall positions: index (as a string) -> tile.
    #[serde(default)]
    pub wall_at: std::collections::BTreeMap<String, String>,
    pub dora: Vec<String>,
    #[serde(default)]
    pub ura: Vec<String>,
    #[serde(default)]
    pub rinshan: Vec<String>,
    /// Uma in points; zero unless given, so that single-hand rewards show the hand alone.
    pub uma: Option<[i32; 4]>,
    pub penalty: Option<f32>,
    pub seed: Option<[u32; 2]>,
    pub start: Option<Start>,
    pub steps: Vec<Step>,
    pub expect: Expect,
}

fn default_mode() -> String {
    "single".to_string()
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Start {
    pub round: Option<u32>,
    pub scores: Option<[i32; 4]>,
    pub honba: Option<u32>,
    pub sticks: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    pub seat: Option<u32>,
    pub action: Option<String>,
    /// `auto = "tsumogiri"`: whoever is to act plays tsumogiri (pass in a claim window) until the
    /// live wall has `until_wall_left` tiles left and a seat is to act on its draw, or without
    /// `until_wall_left` until the round ends.
    pub auto: Option<String>,
    pub until_wall_left: Option<u32>,
    /// The action is expected to be illegal (it is played anyway).
    #[serde(default)]
    pub illegal: bool,
    pub expect_legal: Option<Vec<String>>,
    #[serde(default)]
    pub legal_includes: Vec<String>,
    #[serde(default)]
    pub legal_excludes: Vec<String>,
    pub expect_rewards: Option<[f64; 4]>,
    pub expect_events: Option<Vec<String>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    pub rewards_total: Option<[f64; 4]>,
    pub scores: Option<[i32; 4]>,
    pub terminated: Option<bool>,
    /// Exact set of EVENT bits of the last step.
    pub events: Option<Vec<String>>,
    pub winners: Option<Vec<u32>>,
    /// Seat that dealt in on the last step (none: -1).
    pub deal_in: Option<i32>,
    /// Yaku the last step's winning hands must (not) have.
    #[serde(default)]
    pub yaku: Vec<String>,
    #[serde(default)]
    pub no_yaku: Vec<String>,
    pub round: Option<u32>,
    pub dealer: Option<u32>,
    pub honba: Option<u32>,
    pub sticks: Option<u32>,
    pub current_player: Option<u32>,
    pub illegal: Option<bool>,
}

/// A tile type index as written, e.g. `5m`.
pub fn type_name(t: u32) -> String {
    let kind = u8::try_from(t).ok().and_then(TileType::new);
    kind.map_or_else(|| format!("type {t}"), TileType::name)
}

/// Tile value as the kernel writes it: 0..33, or 34..36 for the red fives.
pub fn tile_value(text: &str, red_variant: bool) -> Result<u32, String> {
    let t = parse_tile(text).map_err(|e| e.to_string())?;
    if t.is_red() && !red_variant {
        return Err(format!("`{text}`: no red fives in this variant"));
    }
    Ok(u32::from(t.value()))
}

/// A kernel tile value as written, e.g. `0p` for a red five.
pub fn value_name(v: u32) -> String {
    let tile = u8::try_from(v).ok().and_then(Tile::from_value);
    tile.map_or_else(|| format!("value {v}"), Tile::name)
}

/// The variant's action layout, for names <-> ids.
pub struct Actions {
    pub blocks: Vec<(&'static str, u32, u32)>,
    pub red: bool,
}

impl Actions {
    pub fn block(&self, kind: &str) -> Option<(u32, u32)> {
        self.blocks.iter().find(|b| b.0 == kind).map(|b| (b.1, b.2))
    }

    pub fn id(&self, action: &str) -> Result<u32, String> {
        let words: Vec<&str> = action.split_whitespace().collect();
        match words.as_slice() {
            ["discard", tile] => {
                let v = tile_value(tile, self.red)?;
                let (first, _) = self.block("discard").ok_or("no discard block")?;
                Ok(first + v)
            }
            ["kan", tile] => {
                let t = parse_tile(tile).map_err(|e| e.to_string())?;
                let (first, _) = self.block("self_kan").ok_or("no self_kan block")?;
                Ok(first + u32::from(t.kind()))
            }
            [kind] => match self.block(kind) {
                Some((first, 1)) => Ok(first),
                _ => Err(format!("unknown action `{action}` in this variant")),
            },
            _ => Err(format!("cannot read action `{action}`")),
        }
    }

    pub fn name(&self, id: u32) -> String {
        for &(kind, first, count) in &self.blocks {
            if id >= first && id < first + count {
                return match kind {
                    "discard" => format!("discard {}", value_name(id - first)),
                    "self_kan" => format!("kan {}", type_name(id - first)),
                    _ => kind.to_string(),
                };
            }
        }
        format!("#{id}")
    }

    pub fn names(&self, ids: &[u32]) -> BTreeSet<String> {
        ids.iter().map(|&a| self.name(a)).collect()
    }
}

/// The variant's tile values in dealing order (136, or 108 for three players), from the
/// scenario's hands, draws and dead wall; the rest is filled with the unused tiles in value order.
pub fn build_wall(sc: &Scenario, variant: Variant) -> Result<[u32; 136], String> {
    let red = variant.red_fives();
    let seats = variant.seats();
    let layout = variant.wall();
    let in_play = |t: usize| variant.tile_in_play(t as u32);
    let mut left = [0u32; 37];
    for (t, n) in left.iter_mut().enumerate().take(34) {
        *n = match (in_play(t), red && t < 27 && t % 9 == 4) {
            (false, _) => 0,
            (true, true) => 3,
            (true, false) => 4,
        };
    }
    if red {
        for suit in 0..3 {
            left[34 + suit] = u32::from(in_play(suit * 9 + 4));
        }
    }
    let mut wall: [Option<u32>; 136] = [None; 136];
    let mut place = |i: usize, text: &str, what: &str, wall: &mut [Option<u32>; 136]| -> Result<(), String> {
        if text == "x" {
            return Ok(());
        }
        let v = tile_value(text, red).map_err(|e| format!("{what}: {e}"))?;
        if let Some(old) = wall[i] {
            return Err(format!(
                "{what}: wall[{i}] is already {} (two sources place a tile there)",
                value_name(old)
            ));
        }
        if left[v as usize] == 0 {
            return Err(format!(
                "{what}: no copy of {} left (every type in play has 4 copies, a red five replacing one five)",
                value_name(v)
            ));
        }
        left[v as usize] -= 1;
        wall[i] = Some(v);
        Ok(())
    };
    if sc.dealer >= seats {
        return Err(format!("dealer must be 0..{}", seats - 1));
    }
    if sc.hands.len() != seats as usize {
        return Err(format!("{} hands for {seats} seats", sc.hands.len()));
    }
    for (seat, hand) in sc.hands.iter().enumerate() {
        let tiles = rinshan_engine::notation::parse_tiles(hand).map_err(|e| format!("hand of seat {seat}: {e}"))?;
        if tiles.tiles.len() != 13 {
            return Err(format!("hand of seat {seat} has {} tiles, not 13", tiles.tiles.len()));
        }
        let offset = ((seat as u32 + seats - sc.dealer) % seats * 13) as usize;
        for (k, t) in tiles.tiles.iter().enumerate() {
            place(offset + k, &t.name(), &format!("hand of seat {seat}"), &mut wall)?;
        }
    }
    let at = |i: u32| i as usize;
    let lists: [(&[String], usize, usize, &str); 3] = [
        (
            &sc.draws,
            at(layout.live_start),
            at(layout.live_end - layout.live_start),
            "draws",
        ),
        (&sc.dora, at(layout.dora), at(layout.ura - layout.dora), "dora"),
        (&sc.ura, at(layout.ura), at(layout.rinshan - layout.ura), "ura"),
    ];
    for (list, start, max, what) in lists {
        if list.len() > max {
            return Err(format!("{what}: at most {max} tiles"));
        }
        for (k, text) in list.iter().enumerate() {
            place(start + k, text, what, &mut wall)?;
        }
    }
    // Replacement tiles, in the order drawn (three players' past the fourth come from the live
    // wall's end).
    if sc.rinshan.len() > 8 || (seats == 4 && sc.rinshan.len() > 4) {
        return Err(format!("rinshan: at most {} tiles", if seats == 4 { 4 } else { 8 }));
    }
    for (k, text) in sc.rinshan.iter().enumerate() {
        place(at(variant.replacement_index(k as u32)), text, "rinshan", &mut wall)?;
    }
    if sc.seat_draws.len() > seats as usize {
        return Err("seat_draws: one list per seat".into());
    }
    for (seat, list) in sc.seat_draws.iter().enumerate() {
        for (k, text) in list.iter().enumerate() {
            let i = layout.live_start + (seat as u32 + seats - sc.dealer) % seats + seats * k as u32;
            if i >= layout.live_end {
                return Err(format!("seat_draws of seat {seat}: draw {k} is past the live wall"));
            }
            place(i as usize, text, &format!("seat_draws of seat {seat}"), &mut wall)?;
        }
    }
    for (index, text) in &sc.wall_at {
        let i: usize = index.parse().map_err(|_| format!("wall_at: bad index `{index}`"))?;
        if i >= at(layout.tiles) {
            return Err(format!("wall_at: index {i} is past the wall"));
        }
        place(i, text, &format!("wall_at {i}"), &mut wall)?;
    }
    let mut pool = (0..34u32).flat_map(|t| {
        let red_copy = if red && t < 27 && t % 9 == 4 {
            Some(34 + t / 9)
        } else {
            None
        };
        std::iter::repeat_n(t, left[t as usize] as usize).chain(red_copy.filter(|&r| left[r as usize] == 1))
    });
    let mut out = [0u32; 136];
    for i in 0..at(layout.tiles) {
        out[i] = match wall[i] {
            Some(v) => v,
            None => pool.next().ok_or("ran out of filler tiles")?,
        };
    }
    Ok(out)
}

/// Every scenario of tests/data/scenarios.toml.
pub fn load() -> Vec<Scenario> {
    let path = test_data().join("scenarios.toml");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let file: File = toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    file.scenario
}
