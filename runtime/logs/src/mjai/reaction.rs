//! A bot's MJAI reaction as the engine's action id (Tenhou's rules, four or three players),
//! checked against the legal actions of the state that asked for it.

use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::generated::red as k;
use rinshan_engine::tile::Tile;
use rinshan_engine::{with_variant, Variant};

use super::event::Event;
use super::tile::Pai;
use crate::tenhou::plan::{MoveIds, KITA};

fn tile(p: &Pai, what: &str) -> Result<Tile, String> {
    p.0.ok_or_else(|| format!("the {what} tile is `?`"))
}

/// Action `a` is legal in `s`.
pub(super) fn legal(s: &GameState, a: u32) -> bool {
    s.mask.get((a / 32) as usize).is_some_and(|w| w >> (a % 32) & 1 == 1)
}

/// The action id of `reaction`, the reply of the bot in MJAI seat `seat` to state `s` of a game
/// of `variant` (whose current player it is); `Err` says why it is not a legal action there.
///
/// A discard's `tsumogiri` flag is taken as a hint: a discard of the drawn tile's kind with the
/// flag wrong (libriichi accepts that too) plays the discard the engine allows.
pub fn action_of(reaction: &Event, seat: u8, s: &GameState, variant: Variant) -> Result<u32, String> {
    let actor = match reaction {
        Event::None {} => None,
        Event::Dahai { actor, .. }
        | Event::Chi { actor, .. }
        | Event::Pon { actor, .. }
        | Event::Daiminkan { actor, .. }
        | Event::Kakan { actor, .. }
        | Event::Ankan { actor, .. }
        | Event::Reach { actor }
        | Event::Kita { actor, .. }
        | Event::Hora { actor, .. } => Some(*actor),
        Event::Ryukyoku { .. } => None,
        other => {
            let kind = serde_json::to_value(other)
                .ok()
                .and_then(|v| v["type"].as_str().map(String::from))
                .unwrap_or_default();
            return Err(format!("`{kind}` is an event, not a reaction"));
        }
    };
    if let Some(a) = actor.filter(|&a| a != seat) {
        return Err(format!("the reaction is for actor {a}, but the bot plays seat {seat}"));
    }
    let kind_of = |p: &Pai, what: &str| tile(p, what).map(|t| u32::from(t.kind()));
    // The reaction in red's layout (and kita), then in the variant's.
    let ids = MoveIds::new(variant);
    let plan = match reaction {
        Event::None {} => k::ACTION_PASS,
        Event::Dahai { pai, tsumogiri, .. } => {
            let v = u32::from(tile(pai, "discarded")?.value());
            let from_hand = k::ACTION_DISCARD + v;
            let drawn = s.drawn == v;
            let allowed = |a: u32| ids.get(a).is_some_and(|a| legal(s, a));
            let (stated, other) = if *tsumogiri {
                (drawn.then_some(k::ACTION_TSUMOGIRI), Some(from_hand))
            } else {
                (Some(from_hand), drawn.then_some(k::ACTION_TSUMOGIRI))
            };
            match (stated, other) {
                (Some(a), _) if allowed(a) => a,
                (_, Some(a)) if allowed(a) => a,
                (Some(a), _) => a,
                (None, _) => return Err(format!("tsumogiri of {pai}, but the drawn tile is another")),
            }
        }
        Event::Reach { .. } => k::ACTION_RIICHI,
        Event::Kita { .. } => KITA,
        Event::Hora { target, .. } if *target == seat => k::ACTION_TSUMO,
        Event::Hora { .. } => k::ACTION_RON,
        Event::Ryukyoku { .. } => k::ACTION_KYUUSHU,
        Event::Pon { consumed, .. } => {
            let red = consumed.iter().any(|p| p.0.is_some_and(|t| t.is_red()));
            if red {
                k::ACTION_PON_RED
            } else {
                k::ACTION_PON
            }
        }
        Event::Daiminkan { .. } => k::ACTION_OPEN_KAN,
        Event::Chi { pai, consumed, .. } => {
            let t = kind_of(pai, "called")?;
            let low = consumed
                .iter()
                .map(|c| kind_of(c, "consumed"))
                .collect::<Result<Vec<_>, _>>()?
                .into_iter()
                .fold(t, u32::min);
            let red = consumed.iter().any(|p| p.0.is_some_and(|t| t.is_red()));
            match (t - low, red) {
                (0, false) => k::ACTION_CHI_LEFT,
                (0, true) => k::ACTION_CHI_LEFT_RED,
                (1, false) => k::ACTION_CHI_MIDDLE,
                (1, true) => k::ACTION_CHI_MIDDLE_RED,
                (2, false) => k::ACTION_CHI_RIGHT,
                (2, true) => k::ACTION_CHI_RIGHT_RED,
                _ => {
                    return Err(format!(
                        "chi of {pai} with {} and {} is not a sequence",
                        consumed[0], consumed[1]
                    ))
                }
            }
        }
        Event::Kakan { pai, .. } => k::ACTION_SELF_KAN + kind_of(pai, "added")?,
        Event::Ankan { consumed, .. } => k::ACTION_SELF_KAN + kind_of(&consumed[0], "kan")?,
        _ => unreachable!("every other event was refused above"),
    };
    let Some(action) = ids.get(plan) else {
        let kind = serde_json::to_value(reaction)
            .ok()
            .and_then(|v| v["type"].as_str().map(String::from))
            .unwrap_or_default();
        return Err(format!("`{kind}` is not a move of {variant}"));
    };
    if !legal(s, action) {
        let names = rinshan_engine::env::action_names(variant);
        let actions = with_variant!(variant, v => v::NUM_ACTIONS);
        let allowed: Vec<&str> = (0..actions)
            .filter(|&a| legal(s, a))
            .filter_map(|a| names.get(a as usize).map(String::as_str))
            .collect();
        let name = names.get(action as usize).map_or("?", String::as_str);
        return Err(format!(
            "`{name}` is not legal here (MJAI seat {seat}, {}; legal: {})",
            match s.phase {
                kernel::PHASE_CLAIM => "a claim on a discard",
                kernel::PHASE_RIICHI_DISCARD => "the riichi discard",
                _ => "its turn",
            },
            allowed.join(", ")
        ));
    }
    Ok(action)
}
