//! The wall a logged round was dealt from, as the engine reads it.

use crate::tenhou::log::Round;
use rinshan_engine::generated::red as four_seats;
use rinshan_engine::tile::Tile;

/// Where the engine deals a four-player game from (rules/kernel/game_round.rs: `WALL_*`, the same
/// for every four-player variant). Tenhou logs here are four-player games.
pub(crate) const LIVE_START: usize = four_seats::WALL_LIVE_START as usize;
pub(crate) const LIVE_END: usize = four_seats::WALL_LIVE_END as usize;
pub(crate) const DORA: usize = four_seats::WALL_DORA as usize;
pub(crate) const URA: usize = four_seats::WALL_URA as usize;
pub(crate) const RINSHAN: usize = four_seats::WALL_RINSHAN as usize;

/// Copies of each tile value in the red rules' set: four of each type, one of them red for the
/// fives of the three suits.
pub(crate) fn tile_set() -> [u8; 37] {
    let mut left = [4u8; 37];
    for suit in 0..3 {
        left[suit * 9 + 4] = 3;
        left[34 + suit] = 1;
    }
    left
}

/// Places the logged tiles where the engine reads them and fills the rest with the unused tiles.
pub(super) fn build_wall(round: &Round, live: &[Tile], rinshan: &[Tile]) -> Result<[Tile; 136], String> {
    if rinshan.len() > 4 || round.dora.len() > 5 || round.ura.len() > 5 {
        return Err(format!(
            "{} replacement draws, {} dora and {} ura indicators: at most 4, 5 and 5 fit the dead wall",
            rinshan.len(),
            round.dora.len(),
            round.ura.len()
        ));
    }
    if LIVE_START + live.len() > LIVE_END - rinshan.len() {
        return Err(format!(
            "{} live draws with {} kans: the live wall holds {}",
            live.len(),
            rinshan.len(),
            LIVE_END - LIVE_START - rinshan.len()
        ));
    }
    let mut slots: [Option<Tile>; 136] = [None; 136];
    let dealer = round.dealer();
    for j in 0..4 {
        let hand = &round.hands[(dealer + j) % 4];
        for (i, t) in hand.iter().enumerate().take(13) {
            slots[j * 13 + i] = Some(*t);
        }
    }
    let placed = [
        (LIVE_START, live),
        (DORA, round.dora.as_slice()),
        (URA, round.ura.as_slice()),
        (RINSHAN, rinshan),
    ];
    for (start, tiles) in placed {
        for (i, t) in tiles.iter().enumerate() {
            slots[start + i] = Some(*t);
        }
    }
    let mut left = tile_set();
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
        .map(|slot| match slot {
            Some(t) => Ok(*t),
            None => spare.next().ok_or("more tiles placed than the wall holds"),
        })
        .collect::<Result<Vec<Tile>, _>>()?;
    <[Tile; 136]>::try_from(wall).map_err(|_| "the wall is not 136 tiles".to_string())
}
