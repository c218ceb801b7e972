//! The wall a logged round was dealt from, as the engine reads it.

use crate::tenhou::log::Round;
use rinshan_engine::generated::red as four_seats;
use rinshan_engine::tile::Tile;
use rinshan_engine::Variant;

/// Where the engine deals a four-player game from (rules/kernel/game_round.rs: `WALL_*`, the same
/// for every four-player variant); the MJAI reader's four-player walls are placed by these.
pub(crate) const LIVE_START: usize = four_seats::WALL_LIVE_START as usize;
pub(crate) const LIVE_END: usize = four_seats::WALL_LIVE_END as usize;
pub(crate) const DORA: usize = four_seats::WALL_DORA as usize;
pub(crate) const RINSHAN: usize = four_seats::WALL_RINSHAN as usize;

/// The rules whose wall a table of `seats` is dealt from: the wall's layout and its tiles follow
/// from the seat count alone (`WALL_*` derive from `SEATS`; three players drop 2m-8m).
pub(crate) fn table_of(seats: usize) -> Variant {
    let same = Variant::ALL.iter().copied().find(|v| v.seats() as usize == seats);
    same.unwrap_or(Variant::Red)
}

/// Copies of each tile value in the red rules' set: four of each type, one of them red for the
/// fives of the three suits.
pub(crate) fn tile_set() -> [u8; 37] {
    tile_set_of(4)
}

/// As [`tile_set`], for a table of `seats` (three players have no 2m-8m, so no red 5m).
pub(crate) fn tile_set_of(seats: usize) -> [u8; 37] {
    let table = table_of(seats);
    let mut left = [0u8; 37];
    for t in 0..34u8 {
        if table.tile_in_play(u32::from(t)) {
            left[usize::from(t)] = 4;
        }
    }
    for suit in 0..3 {
        if left[suit * 9 + 4] == 4 {
            left[suit * 9 + 4] = 3;
            left[34 + suit] = 1;
        }
    }
    left
}

/// Places the logged tiles where the engine reads them and fills the rest with the unused tiles.
/// Replacement draws (after kans, and three players' kita) take the dead wall's four and then
/// the live wall's end; `rinshan` are they in the order drawn.
pub(super) fn build_wall(round: &Round, live: &[Tile], rinshan: &[Tile]) -> Result<[Tile; 136], String> {
    let seats = round.seats;
    let table = table_of(seats);
    let w = table.wall();
    let at = |i: u32| i as usize;
    // Four kans end the round; kita adds a North each, four at most.
    let most_replacements = if seats == 3 { 8 } else { 4 };
    if rinshan.len() > most_replacements || round.dora.len() > 5 || round.ura.len() > 5 {
        return Err(format!(
            "{} replacement draws, {} dora and {} ura indicators: at most {most_replacements}, 5 and 5 fit the dead wall",
            rinshan.len(),
            round.dora.len(),
            round.ura.len()
        ));
    }
    if at(w.live_start) + live.len() > at(w.live_end) - rinshan.len() {
        return Err(format!(
            "{} live draws with {} replacement draws: the live wall holds {}",
            live.len(),
            rinshan.len(),
            at(w.live_end - w.live_start) - rinshan.len()
        ));
    }
    let mut slots: [Option<Tile>; 136] = [None; 136];
    let dealer = round.dealer();
    for j in 0..seats {
        let hand = &round.hands[(dealer + j) % seats];
        for (i, t) in hand.iter().enumerate().take(13) {
            slots[j * 13 + i] = Some(*t);
        }
    }
    let placed = [
        (at(w.live_start), live),
        (at(w.dora), round.dora.as_slice()),
        (at(w.ura), round.ura.as_slice()),
    ];
    for (start, tiles) in placed {
        for (i, t) in tiles.iter().enumerate() {
            slots[start + i] = Some(*t);
        }
    }
    for (k, t) in rinshan.iter().enumerate() {
        slots[at(table.replacement_index(k as u32))] = Some(*t);
    }
    let mut left = tile_set_of(seats);
    for t in slots.iter().flatten() {
        let v = usize::from(t.value());
        // A game without red fives plays four black ones: the fourth takes the red copy's place.
        let v = match Tile::red(t.kind()) {
            Some(red) if left[v] == 0 && !t.is_red() => usize::from(red.value()),
            _ => v,
        };
        left[v] = left[v].checked_sub(1).ok_or_else(|| {
            format!(
                "tile {} appears more often than the set holds (hands, draws and indicators together)",
                t.name()
            )
        })?;
    }
    let mut spare = (0..37u8)
        .flat_map(|v| std::iter::repeat_n(v, usize::from(left[usize::from(v)])))
        .filter_map(Tile::from_value);
    let wall = slots
        .iter()
        .take(at(w.tiles))
        .map(|slot| match slot {
            Some(t) => Ok(*t),
            None => spare.next().ok_or("more tiles placed than the wall holds"),
        })
        .collect::<Result<Vec<Tile>, _>>()?;
    let mut full = [Tile::plain(rinshan_engine::tile::TileType::NORTH); 136];
    // Past a three-player wall's 108 tiles the engine reads nothing.
    full[..wall.len()].copy_from_slice(&wall);
    Ok(full)
}
