//! The engine's state of the present, rebuilt from what one seat has seen of the round: the
//! events since `start_kyoku`, others' hands and draws hidden.
//!
//! A wall consistent with the view is dealt and the round's decisions are played on it. Every
//! tile the seat saw is put where it came from: its own hand and draws, the dora indicators, and
//! each tile another seat gave up (a discard, a call's tiles, a kan) into a slot of that seat's
//! hidden hand (its draw, for a tsumogiri). A seat in riichi gets a tenpai hand from the tiles
//! nobody has seen, the engine's condition for the declaration; the rest of the wall is filled with
//! the other unseen tiles. The seat's observation does not depend on that fill (the engine's leak
//! tests hold it to that), so neither does an agent's decision on it.

use rinshan_engine::generated::kernel::{self, DealInput, GameState, ResetInput, PHASE_CLAIM};
use rinshan_engine::generated::red as v;
use rinshan_engine::tile::{Tile, TileType};

use super::event::Event;
use super::reaction::{action_of, legal};
use crate::tenhou::plan::wall::{tile_set, DORA, LIVE_END, LIVE_START, RINSHAN};

struct Wall {
    slots: [Option<Tile>; 136],
    /// Each seat's hidden hand as wall positions, in the order they came.
    hands: [Vec<usize>; 4],
    last_draw: [Option<usize>; 4],
    /// Each riichi seat's hand after its riichi discard.
    riichi_hands: Vec<Vec<usize>>,
}

impl Wall {
    fn set(&mut self, pos: usize, t: Tile) -> Result<(), String> {
        match self.slots[pos] {
            Some(u) if u != t => Err(format!("wall position {pos} is both {u} and {t}")),
            _ => {
                self.slots[pos] = Some(t);
                Ok(())
            }
        }
    }

    /// Seat `q` gives up tile `t` from its hand: the slot holding it, else a hidden slot
    /// (`drawn`: the slot of its last draw, a tsumogiri; otherwise another one if it has any).
    fn take(&mut self, q: usize, t: Tile, drawn: bool) -> Result<(), String> {
        let hand = &self.hands[q];
        let last = self.last_draw[q];
        let pick = if drawn {
            last.filter(|p| hand.contains(p) && self.slots[*p].is_none_or(|u| u == t))
        } else {
            hand.iter()
                .copied()
                .find(|&p| self.slots[p] == Some(t))
                .or_else(|| {
                    hand.iter()
                        .copied()
                        .find(|&p| self.slots[p].is_none() && Some(p) != last)
                })
                .or_else(|| last.filter(|p| hand.contains(p) && self.slots[*p].is_none()))
        };
        let pos = pick.ok_or_else(|| format!("seat {q} gives up {t}, which its hand cannot hold"))?;
        self.set(pos, t)?;
        self.hands[q].retain(|&p| p != pos);
        Ok(())
    }
}

/// A complete hand of `sets` sets and a pair from the kinds `pool`, kinds at or after `from`,
/// with exactly one tile not from the pool (the wait); the pool tiles used go to `out`.
#[allow(clippy::too_many_arguments)]
fn complete(
    pool: &mut [u8; 34],
    avoid: &[bool; 34],
    from: usize,
    sets: usize,
    pair: bool,
    joker: bool,
    out: &mut Vec<u8>,
    budget: &mut u32,
) -> bool {
    // The search is depth first over few sets; a pool with no shape could make it long, so it
    // gives up after a fixed number of steps (the seat's state is then not rebuilt).
    *budget = match budget.checked_sub(1) {
        Some(b) => b,
        None => return false,
    };
    if sets == 0 && !pair {
        // The wait (the joker, marked by 100 + its kind) must not be a fifth copy of a kind the
        // hand holds four of: the engine does not count that as tenpai.
        let wait = out.iter().find(|&&x| x >= 100).map(|&x| x - 100);
        return !joker && wait.is_some_and(|w| out.iter().filter(|&&x| x == w).count() < 4);
    }
    for k in from..34 {
        let mut shapes: Vec<(bool, [Option<usize>; 3])> = Vec::new();
        if sets > 0 {
            shapes.push((false, [Some(k); 3]));
            if k < 27 && k % 9 < 7 {
                shapes.push((false, [Some(k), Some(k + 1), Some(k + 2)]));
            }
        }
        if pair {
            shapes.push((true, [Some(k), Some(k), None]));
        }
        for (is_pair, tiles) in shapes {
            let tiles: Vec<usize> = tiles.into_iter().flatten().collect();
            if tiles.iter().any(|&t| avoid[t]) {
                continue;
            }
            // Each tile of the shape from the pool, or (once) the joker in its place.
            for joker_at in std::iter::once(None).chain((0..tiles.len()).map(Some)) {
                if joker_at.is_some() && !joker {
                    continue;
                }
                let used: Vec<usize> = (0..tiles.len())
                    .filter(|&i| Some(i) != joker_at)
                    .map(|i| tiles[i])
                    .collect();
                let mut ok = true;
                for (n, &t) in used.iter().enumerate() {
                    if pool[t] == 0 {
                        for &u in &used[..n] {
                            pool[u] += 1;
                        }
                        ok = false;
                        break;
                    }
                    pool[t] -= 1;
                }
                if !ok {
                    continue;
                }
                let mark = out.len();
                out.extend(used.iter().map(|&t| t as u8));
                out.extend(joker_at.map(|i| 100 + tiles[i] as u8));
                let (s, p) = if is_pair { (sets, false) } else { (sets - 1, pair) };
                if complete(pool, avoid, k, s, p, joker && joker_at.is_none(), out, budget) {
                    return true;
                }
                out.truncate(mark);
                for &t in &used {
                    pool[t] += 1;
                }
            }
        }
    }
    false
}

/// Takes from the unseen tiles `left` a tenpai hand of `n` tiles (`n = 13 - 3 x melds`), or
/// one discard away from it (`n` one more), beside the hand's `known` tiles (a later closed
/// kan's): nothing within two of them, so a kan of theirs leaves the wait as it is.
fn tenpai_shape(n: usize, known: &[Tile], left: &mut [u8; 37]) -> Option<Vec<Tile>> {
    let wait_n = if n % 3 == 2 { n - 1 } else { n };
    if n == 0 || wait_n % 3 != 1 {
        return (n == 0).then(Vec::new);
    }
    let mut avoid = [false; 34];
    for t in known {
        let k = t.kind().index();
        let near = match t.kind().suit() {
            Some(_) => (k - k % 9 + (k % 9).saturating_sub(2))..=(k - k % 9 + (k % 9 + 2).min(8)),
            None => k..=k,
        };
        for j in near {
            avoid[j] = true;
        }
    }
    let mut pool = [0u8; 34];
    for (v, &c) in left.iter().enumerate() {
        if let Some(t) = Tile::from_value(v as u8) {
            pool[t.kind().index()] += c;
        }
    }
    let mut kinds = Vec::new();
    let found = complete(&mut pool, &avoid, 0, wait_n / 3, true, true, &mut kinds, &mut 100_000)
        // Seven pairs, one of them waited on.
        || (wait_n == 13 && {
            kinds.clear();
            let pairs: Vec<usize> = (0..34).filter(|&k| pool[k] >= 2 && !avoid[k]).take(6).collect();
            let single = (0..34).find(|k| !pairs.contains(k) && pool[*k] > 0 && !avoid[*k]);
            match (pairs.len(), single) {
                (6, Some(x)) => {
                    kinds.extend(pairs.iter().flat_map(|&k| [k as u8, k as u8]));
                    kinds.push(x as u8);
                    true
                }
                _ => false,
            }
        });
    if !found {
        return None;
    }
    kinds.retain(|&k| k < 100);
    if n != wait_n {
        kinds.push(
            (0..34u8)
                .find(|&k| pool[usize::from(k)] > 0 && !kinds.contains(&k))
                .or_else(|| (0..34u8).find(|&k| pool[usize::from(k)] > 0))?,
        );
    }
    // Kinds to tiles: black copies first, then the red five.
    kinds
        .into_iter()
        .map(|k| {
            let kind = TileType::try_from(k).ok()?;
            let black = usize::from(Tile::plain(kind).value());
            if left[black] > 0 {
                left[black] -= 1;
                return Tile::from_value(black as u8);
            }
            let red = Tile::red(kind)?;
            let r = usize::from(red.value());
            left[r] = left[r].checked_sub(1)?;
            Some(red)
        })
        .collect()
}

fn known(p: &super::tile::Pai, what: &str) -> Result<Tile, String> {
    p.0.ok_or_else(|| format!("{what} is `?`"))
}

/// The state of the round `round` (its events from `start_kyoku` on, as seat `seat` saw them)
/// in a game of kernel mode `mode`, after its last event; `None` when the round is over.
pub fn rebuild(seat: u8, mode: u32, round: &[Event]) -> Result<Option<GameState>, String> {
    let Some(Event::StartKyoku {
        bakaze,
        dora_marker,
        kyoku,
        honba,
        kyotaku,
        oya,
        scores,
        tehais,
    }) = round.first()
    else {
        return Err("no start_kyoku yet".into());
    };
    let me = usize::from(seat);
    let dealer = usize::from(*oya);
    let wind = bakaze.0.map(|t| u32::from(t.kind())).filter(|k| (27..31).contains(k));
    let wind = wind.ok_or("bakaze is not a wind")? - 27;
    if !(1..=4).contains(kyoku) || dealer > 3 || me > 3 {
        return Err(format!("kyoku {kyoku}, oya {oya}, seat {seat}: out of range"));
    }
    let mut w = Wall {
        slots: [None; 136],
        hands: Default::default(),
        last_draw: [None; 4],
        riichi_hands: Vec::new(),
    };
    for j in 0..4 {
        let q = (dealer + j) % 4;
        if tehais[q].len() != 13 {
            return Err(format!("seat {q}'s starting hand has {} tiles", tehais[q].len()));
        }
        for (i, tile) in tehais[q].iter().enumerate() {
            w.hands[q].push(j * 13 + i);
            if q == me {
                w.set(j * 13 + i, known(tile, "the seat's own starting tile")?)?;
            }
        }
    }
    w.set(DORA, known(dora_marker, "the dora indicator")?)?;
    let (mut live, mut rinshan, mut doras) = (0, 0, 1);
    let mut replacement = false;
    let mut declared = [false; 4];
    let mut riichi = [false; 4];
    for e in &round[1..] {
        match e {
            Event::Tsumo { actor, pai } => {
                let q = usize::from(*actor) % 4;
                let pos = if std::mem::take(&mut replacement) {
                    rinshan += 1;
                    RINSHAN + rinshan - 1
                } else {
                    live += 1;
                    LIVE_START + live - 1
                };
                if rinshan > 4 || LIVE_START + live > LIVE_END - rinshan {
                    return Err(format!(
                        "{live} draws and {rinshan} replacement draws: more than the wall holds"
                    ));
                }
                if let Some(t) = pai.0 {
                    w.set(pos, t)?;
                } else if q == me {
                    return Err("the seat's own draw is `?`".into());
                }
                w.hands[q].push(pos);
                w.last_draw[q] = Some(pos);
            }
            Event::Dahai { actor, pai, tsumogiri } => {
                let q = usize::from(*actor) % 4;
                w.take(q, known(pai, "a discard")?, *tsumogiri)?;
                if std::mem::take(&mut declared[q]) {
                    riichi[q] = true;
                    w.riichi_hands.push(w.hands[q].clone());
                }
            }
            Event::Chi { actor, consumed, .. } | Event::Pon { actor, consumed, .. } => {
                for c in consumed {
                    w.take(usize::from(*actor) % 4, known(c, "a call's tile")?, false)?;
                }
            }
            Event::Daiminkan { actor, consumed, .. } => {
                for c in consumed {
                    w.take(usize::from(*actor) % 4, known(c, "a kan's tile")?, false)?;
                }
                replacement = true;
            }
            Event::Kakan { actor, pai, .. } => {
                w.take(usize::from(*actor) % 4, known(pai, "an added kan's tile")?, false)?;
                replacement = true;
            }
            Event::Ankan { actor, consumed } => {
                let q = usize::from(*actor) % 4;
                let mut tiles = consumed
                    .iter()
                    .map(|c| known(c, "a kan's tile"))
                    .collect::<Result<Vec<_>, _>>()?;
                if riichi[q] {
                    // A seat in riichi may only kan with its draw.
                    let drawn = w.last_draw[q].and_then(|p| w.slots[p]);
                    let i = tiles.iter().position(|&t| drawn.is_none_or(|d| d == t)).unwrap_or(0);
                    w.take(q, tiles.remove(i), true)?;
                }
                for t in tiles {
                    w.take(q, t, false)?;
                }
                replacement = true;
            }
            Event::Dora { dora_marker } => {
                if doras < 5 {
                    w.set(DORA + doras, known(dora_marker, "a dora indicator")?)?;
                }
                doras += 1;
            }
            Event::Reach { actor } => declared[usize::from(*actor) % 4] = true,
            _ => {}
        }
    }
    // A riichi declared and not yet discarded: a hand one discard away from tenpai.
    for q in (0..4).filter(|&q| declared[q]) {
        w.riichi_hands.push(w.hands[q].clone());
    }
    let mut left = tile_set();
    for t in w.slots.iter().flatten() {
        let v = usize::from(t.value());
        left[v] = left[v]
            .checked_sub(1)
            .ok_or_else(|| format!("more copies of {t} were seen than the set holds"))?;
    }
    for hand in std::mem::take(&mut w.riichi_hands) {
        let open: Vec<usize> = hand.iter().copied().filter(|&p| w.slots[p].is_none()).collect();
        let known: Vec<Tile> = hand.iter().filter_map(|&p| w.slots[p]).collect();
        let shape = tenpai_shape(open.len(), &known, &mut left)
            .ok_or_else(|| format!("no tenpai hand of {} fits the unseen tiles {left:?}", open.len()))?;
        for (p, t) in open.into_iter().zip(shape) {
            w.slots[p] = Some(t);
        }
    }
    let mut spare = (0..37u8).flat_map(|v| std::iter::repeat_n(v, usize::from(left[usize::from(v)])));
    let mut wall = [0u32; 136];
    for (x, slot) in wall.iter_mut().zip(&w.slots) {
        *x = match slot {
            Some(t) => u32::from(t.value()),
            None => u32::from(spare.next().ok_or("the wall has more slots than tiles")?),
        };
    }
    play(
        seat,
        mode,
        round,
        wind * 4 + u32::from(*kyoku) - 1,
        dealer as u32,
        (*honba, *kyotaku),
        *scores,
        wall,
    )
}

/// Deals `wall` and plays the round's decisions on it.
#[allow(clippy::too_many_arguments)]
fn play(
    seat: u8,
    mode: u32,
    round: &[Event],
    round_no: u32,
    dealer: u32,
    (honba, sticks): (u32, u32),
    scores: [i32; 4],
    wall: [u32; 136],
) -> Result<Option<GameState>, String> {
    let mut s: GameState = v::game_new(ResetInput {
        seed: [round_no, honba],
        mode,
        dealer,
        use_wall: 0,
        wall: [0; 136],
        uma: [0; 4],
        penalty: v::host::ILLEGAL_ACTION_PENALTY,
        auto_reset: 0,
    });
    v::game_deal(
        &mut s,
        DealInput {
            deal: 1,
            round: round_no,
            dealer,
            honba,
            sticks,
            scores,
            wall,
        },
    );
    for (i, e) in round.iter().enumerate().skip(1) {
        let at = |what: String| format!("event {} of the round ({}): {what}", i + 1, e.kind());
        let actor = match e {
            Event::Tsumo { actor, .. } => {
                pass_claims(&mut s, None).map_err(at)?;
                if s.current != u32::from(*actor) {
                    return Err(at(format!("the engine has seat {} to draw", s.current)));
                }
                continue;
            }
            Event::Dahai { actor, .. }
            | Event::Reach { actor }
            | Event::Chi { actor, .. }
            | Event::Pon { actor, .. }
            | Event::Daiminkan { actor, .. }
            | Event::Kakan { actor, .. }
            | Event::Ankan { actor, .. } => *actor,
            Event::Hora { .. } | Event::Ryukyoku { .. } | Event::EndKyoku {} => return Ok(None),
            _ => continue,
        };
        pass_claims(&mut s, Some(actor)).map_err(at)?;
        let a = action_of(e, actor, &s, rinshan_engine::Variant::Red).map_err(at)?;
        v::game_step(&mut s, a);
        if matches!(e, Event::Chi { .. } | Event::Pon { .. } | Event::Daiminkan { .. }) {
            // The call is on the table: whoever the engine asks after the caller passed.
            pass_claims(&mut s, None).map_err(at)?;
        }
    }
    // Others asked before the seat pass; when the window closes without asking it, the seat has
    // nothing to decide (what comes next is the next event's).
    let claim = s.phase == PHASE_CLAIM;
    pass_claims(&mut s, Some(seat))?;
    Ok((!claim || s.phase == PHASE_CLAIM).then_some(s))
}

/// In a claim window, every seat asked before `until` passes (the next event says they did).
fn pass_claims(s: &mut GameState, until: Option<u8>) -> Result<(), String> {
    while s.phase == PHASE_CLAIM && until.map(u32::from) != Some(s.current) && s.terminated == 0 {
        if !legal(s, v::ACTION_PASS) {
            return Err(format!("seat {} cannot pass here", s.current));
        }
        v::game_step(s, v::ACTION_PASS);
    }
    if s.illegal != 0 || s.phase == kernel::PHASE_OVER {
        return Err("the round ended while replaying it".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(tiles: &[Tile]) -> Vec<usize> {
        let mut k: Vec<usize> = tiles.iter().map(|t| t.kind().index()).collect();
        k.sort();
        k
    }

    #[test]
    fn a_tenpai_shape_is_tenpai_and_leaves_the_kan_alone() {
        let mut left = tile_set();
        let kan = Tile::plain(TileType::try_from(4).unwrap()); // 5m
        let shape = tenpai_shape(10, &[kan, kan, kan], &mut left).expect("a shape");
        assert_eq!(shape.len(), 10);
        // Nothing within two of the kan's 5m: 3m..7m.
        assert!(kinds(&shape).iter().all(|&k| !(2..=6).contains(&k)), "{shape:?}");
        let hand: Vec<u8> = shape
            .iter()
            .chain([kan; 3].iter())
            .map(|t| t.kind().index() as u8)
            .collect();
        let mut counts = [0u8; 34];
        for k in hand {
            counts[usize::from(k)] += 1;
        }
        assert_eq!(rinshan_engine::hand::shanten(&counts).shanten, 0, "tenpai: {shape:?}");
        // The tiles came out of the unseen ones.
        assert_eq!(left.iter().map(|&c| u32::from(c)).sum::<u32>(), 136 - 10);
    }

    #[test]
    fn no_shape_in_a_pool_without_one_is_refused_quickly() {
        // 13 tiles, no two of a kind and none within two of another of its suit: no tenpai hand.
        let mut left = [0u8; 37];
        for v in [0, 3, 6, 9, 12, 15, 18, 21, 24, 27, 28, 29, 30] {
            left[v] = 1;
        }
        let started = std::time::Instant::now();
        assert_eq!(tenpai_shape(13, &[], &mut left), None);
        assert!(started.elapsed() < std::time::Duration::from_secs(5));
    }
}
