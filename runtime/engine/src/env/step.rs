//! The outcome of a reset or a step as flat batch arrays, and the names of its ids.

use crate::generated::kernel;
use crate::tile::Tile;
use crate::Variant;

/// The outcome of a reset or a step, as flat batch arrays (index = env).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Step {
    /// The seat to act next (0..3).
    pub current_player: Vec<u32>,
    /// Legal actions of `current_player`, a bitset over the variant's action ids (bit `a % 32` of
    /// word `a / 32`).
    pub legal_action_mask: Vec<[u32; 3]>,
    /// This step's score change per seat in units of 100 points (uma in a game's last step), or
    /// the penalty for the seat that played an illegal action.
    pub rewards: Vec<[f32; 4]>,
    /// The game ended in this step (with auto-reset, a new one has already started).
    pub terminated: Vec<bool>,
    /// The game was cut short rather than ended by the rules. The rules end every game, so this
    /// stays false; it completes the usual RL step tuple.
    pub truncated: Vec<bool>,
    /// This step's action was illegal (the game ended with the penalty).
    pub illegal: Vec<bool>,
    /// What the step settled: the kernel's `EVENT_*` bits (see [`events`]).
    pub events: Vec<u32>,
    /// Seats that won in this step, one bit per seat.
    pub winners: Vec<u32>,
    /// The seat that dealt in + 1 (0 = none).
    pub deal_in: Vec<u32>,
    /// Yaku of the winning hands: bit `y` of word `y / 32` for yaku id `y` (`host::YAKU_NAMES`).
    pub yaku: Vec<[u32; 2]>,
    /// Rounds played in the (finished) game so far.
    pub rounds: Vec<u32>,
    /// In the step that ends a game by the rules: each seat's final place (0 = first; ties go to
    /// the seat nearer the game's first dealer), as uma paid it. Zeros elsewhere: other steps,
    /// later steps of a finished game, and a game ended by an illegal action (it has no final
    /// standings).
    pub ranks: Vec<[u8; 4]>,
}

/// The `events` bits of a [`Step`]: the kernel's `EVENT_*`.
pub mod events {
    use crate::generated::kernel as k;
    /// A round ended by ron (one or more winners).
    pub const RON: u32 = k::EVENT_RON;
    /// A round ended by tsumo.
    pub const TSUMO: u32 = k::EVENT_TSUMO;
    /// The wall ran out.
    pub const EXHAUSTIVE_DRAW: u32 = k::EVENT_EXHAUSTIVE_DRAW;
    /// An abortive draw (kyuushu kyuuhai, four riichi, triple ron, four kans, four winds).
    pub const ABORTIVE_DRAW: u32 = k::EVENT_ABORTIVE_DRAW;
    /// The game ended.
    pub const GAME_OVER: u32 = k::EVENT_GAME_OVER;
    /// Nagashi mangan was paid at an exhaustive draw.
    pub const NAGASHI: u32 = k::EVENT_NAGASHI;
    /// Any of the bits of a step that ends a round.
    pub const ROUND_OVER: u32 = k::EVENT_ROUND_OVER;
}

impl Step {
    pub(super) fn with_batch(b: usize) -> Step {
        Step {
            current_player: vec![0; b],
            legal_action_mask: vec![[0; 3]; b],
            rewards: vec![[0.0; 4]; b],
            terminated: vec![false; b],
            truncated: vec![false; b],
            illegal: vec![false; b],
            events: vec![0; b],
            winners: vec![0; b],
            deal_in: vec![0; b],
            yaku: vec![[0; 2]; b],
            rounds: vec![0; b],
            ranks: vec![[0; 4]; b],
        }
    }

    /// Legal action ids of env `i`, in increasing order.
    pub fn legal_actions(&self, i: usize) -> impl Iterator<Item = u32> + '_ {
        let mask = self.legal_action_mask[i];
        (0..96u32).filter(move |a| mask[(a / 32) as usize] >> (a % 32) & 1 == 1)
    }

    /// Fills the arrays from kernel `StepView` words (one record per env).
    pub(crate) fn fill(&mut self, view_words: &[u32]) {
        {
            let views: &[kernel::StepView] = bytemuck::cast_slice(view_words);
            for (i, w) in views.iter().enumerate() {
                self.current_player[i] = w.current_player;
                self.legal_action_mask[i] = w.mask;
                self.rewards[i] = w.rewards;
                self.terminated[i] = w.terminated != 0;
                self.truncated[i] = w.truncated != 0;
                self.illegal[i] = w.illegal != 0;
                self.events[i] = w.events;
                self.winners[i] = w.winners;
                self.deal_in[i] = w.deal_in;
                self.yaku[i] = w.yaku;
                self.rounds[i] = w.rounds;
                self.ranks[i] = std::array::from_fn(|p| (w.ranks >> (p as u32 * kernel::RANK_SHIFT)) as u8);
            }
        }
    }
}

/// The yaku names of `variant`, indexed by yaku id (the bits of [`Step::yaku`]).
pub fn yaku_names(variant: Variant) -> &'static [&'static str] {
    with_variant!(variant, v => &v::host::YAKU_NAMES)
}

/// The action ids of `variant` by name, from its `[actions]` layout: `discard_<tile>` (a red five
/// is `discard_0m`), `self_kan_<tile type>`, then one id per other kind (`tsumogiri`, `riichi`,
/// `pon_red`, `pass` ...).
pub fn action_names(variant: Variant) -> Vec<String> {
    let blocks: &[(&str, u32, u32)] = with_variant!(variant, v => &v::host::ACTION_BLOCKS);
    let mut names = Vec::new();
    for &(kind, _, count) in blocks {
        if count == 1 {
            names.push(kind.to_string());
            continue;
        }
        for i in 0..count {
            let tile = u8::try_from(i).ok().and_then(Tile::from_value);
            names.push(match tile {
                Some(t) => format!("{kind}_{t}"),
                None => format!("{kind}_{i}"),
            });
        }
    }
    names
}
