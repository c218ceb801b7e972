//! The rule variants as users name them (`red`, `no-red`, ...), and what the host reads of their spec.

use crate::generated::Variant;
use crate::names::UnknownName;

impl Variant {
    /// Parses a variant name as users write it: `red`, `no-red` or `no_red`.
    pub fn from_name(name: &str) -> Option<Variant> {
        let wanted = name.replace('-', "_");
        Variant::ALL.iter().copied().find(|v| v.name() == wanted)
    }

    /// The spec's one-line summary of its rules (`[variant] description`).
    pub fn description(self) -> &'static str {
        with_variant!(self, v => v::host::VARIANT_DESCRIPTION)
    }

    /// The spec's plain options as (section, name, value), in file order.
    pub fn options(self) -> &'static [(&'static str, &'static str, &'static str)] {
        with_variant!(self, v => &v::host::OPTIONS)
    }

    /// The value of the plain option `name` (`"true"`, `"1000"`), if the spec has it.
    pub fn option(self, name: &str) -> Option<&'static str> {
        self.options().iter().find(|o| o.1 == name).map(|o| o.2)
    }

    /// The uma each seat was paid in a game's last step, from the scores `after` it, the final
    /// places `ranks` and the uma by place: the kernel's `uma_shares`, which ties read from the
    /// scores before the uma. Ties hold consecutive places, so each of the 8 ways to group the
    /// places is tried and the one whose shares, taken off `after`, give back the same shares is
    /// kept (the uma by place where none does).
    pub fn uma_paid(self, after: [i32; 4], ranks: [u8; 4], uma: [i32; 4]) -> [i32; 4] {
        let ranks = ranks.map(u32::from);
        with_variant!(self, v => {
            for cuts in 0u32..8 {
                let mut group = [0i32; 4];
                for place in 1..4 {
                    group[place] = group[place - 1] + (cuts >> (place - 1) & 1) as i32;
                }
                let grouped: [i32; 4] = std::array::from_fn(|p| -group[ranks[p].min(3) as usize]);
                let shares = v::uma_shares(grouped, ranks, uma);
                let before: [i32; 4] = std::array::from_fn(|p| after[p] - shares[p]);
                if v::uma_shares(before, ranks, uma) == shares {
                    return shares;
                }
            }
            std::array::from_fn(|p| uma[ranks[p].min(3) as usize])
        })
    }

    /// A game of these rules dealt from `seed` (its two words: low, high), `mode` long, with the
    /// spec's penalty for an illegal action: the single game the arena and the tests step seat by
    /// seat.
    pub fn new_game(self, seed: u64, mode: crate::env::Mode) -> crate::generated::kernel::GameState {
        with_variant!(self, v => {
            v::game_new(crate::generated::kernel::ResetInput {
                seed: [seed as u32, (seed >> 32) as u32],
                mode: mode.kernel(),
                dealer: 4,
                use_wall: 0,
                wall: [0; 136],
                uma: [0; 4],
                penalty: v::host::ILLEGAL_ACTION_PENALTY,
                auto_reset: 0,
            })
        })
    }

    /// Whether one copy of each five is red (`[tiles] red_fives`).
    pub fn red_fives(self) -> bool {
        with_variant!(self, v => v::RED_FIVES)
    }

    /// Each player's points at the start of a game (`[game] starting_points` of the spec).
    pub fn starting_points(self) -> u32 {
        with_variant!(self, v => v::STARTING_POINTS)
    }

    /// Players at the table (`[game] seats`): 4, or 3 for the three-player game. The state keeps
    /// four seats' arrays; seats from this number on take no part.
    pub fn seats(self) -> u32 {
        with_variant!(self, v => v::SEATS)
    }

    /// Where the parts of the wall lie in a state's `wall` (the kernel's `WALL_*` constants).
    pub fn wall(self) -> WallLayout {
        with_variant!(self, v => WallLayout {
            tiles: v::WALL_TILES,
            live_start: v::WALL_LIVE_START,
            live_end: v::WALL_LIVE_END,
            dora: v::WALL_DORA,
            ura: v::WALL_URA,
            rinshan: v::WALL_RINSHAN,
        })
    }

    /// The wall index of the round's `k`-th replacement tile (kans and kita together).
    pub fn replacement_index(self, k: u32) -> u32 {
        with_variant!(self, v => v::replacement_index(k))
    }

    /// The wall indices of the replacement tiles `state` has drawn this round, in order.
    pub fn drawn_replacements(self, state: &crate::generated::kernel::GameState) -> Vec<u32> {
        let n = with_variant!(self, v => v::replacements_drawn(&mut state.clone()));
        (0..n).map(|k| self.replacement_index(k)).collect()
    }

    /// The actions that discard a tile (`discard_<tile>` and `tsumogiri`), one bit per action id
    /// as the legal masks hold them.
    pub fn discard_actions(self) -> [u32; 3] {
        let (first, count, tsumogiri) =
            with_variant!(self, v => (v::ACTION_DISCARD, v::ACTION_DISCARD_COUNT, v::ACTION_TSUMOGIRI));
        let mut mask = [0u32; 3];
        for a in (first..first + count).chain([tsumogiri]) {
            mask[a as usize / 32] |= 1 << (a % 32);
        }
        mask
    }

    /// Whether tile type `t` (0..33) is in the set: three players have no 2m-8m.
    pub fn tile_in_play(self, t: u32) -> bool {
        with_variant!(self, v => v::tile_in_play(t))
    }
}

/// Where the parts of a variant's wall lie, as indices into the dealing order: 13 tiles per seat
/// from 0, the live wall from `live_start` to `live_end`, then five dora indicators, five ura
/// indicators and four replacement tiles, `tiles` in all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WallLayout {
    /// Tiles in the wall: 136, or 108 for three players.
    pub tiles: u32,
    /// The first live draw (the dealer's): 13 per seat dealt before it.
    pub live_start: u32,
    /// The end of the live wall before any kan or kita.
    pub live_end: u32,
    /// The first dora indicator; kan dora follow it.
    pub dora: u32,
    /// The first ura indicator.
    pub ura: u32,
    /// The first replacement tile; see [`Variant::replacement_index`] for the rest.
    pub rinshan: u32,
}

impl std::fmt::Display for Variant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name().replace('_', "-"))
    }
}

impl std::str::FromStr for Variant {
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Variant, UnknownName> {
        Variant::from_name(name).ok_or_else(|| UnknownName::new("variant", name, Variant::ALL))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_discard_actions_are_those_the_layout_names_so() {
        for &v in Variant::ALL {
            let names = crate::env::action_names(v);
            let mask = v.discard_actions();
            for (a, name) in names.iter().enumerate() {
                let named = name.starts_with("discard_") || name == "tsumogiri";
                assert_eq!(mask[a / 32] >> (a % 32) & 1 == 1, named, "{v}: {name}");
            }
        }
    }
}
