//! What a host can read and force about the table of each game beyond a step's flat outputs: the
//! round, dealer, honba, sticks and scores, what the last settlement scored (han, fu, yaku, dora)
//! and how the last drawn round ended; and a forced deal of the next round (log replay).

use super::config::EnvError;
use super::cpu::CpuEnv;
use super::games::{check_wall, Backing, Env, DEAL_WORDS};
use super::step::Step;
use crate::generated::kernel;
use crate::tile::Tile;
use crate::Variant;

/// The table of one game, read from its state.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Table {
    /// 0 = East 1, 4 = South 1, 8 = West 1.
    pub round: u32,
    /// The dealer's seat.
    pub dealer: u32,
    /// Repeat counters.
    pub honba: u32,
    /// Riichi sticks on the table.
    pub sticks: u32,
    /// Each seat's points.
    pub scores: [i32; 4],
    /// Rounds finished in this game.
    pub rounds: u32,
    /// The game has ended (its last step reported `terminated`; with auto-reset, the step that
    /// ended it).
    pub over: bool,
    /// What each seat's last winning hand scored. Only the seats of the step's `winners` are
    /// fresh: a record stays until that seat wins again.
    pub wins: [WinRecord; 4],
    /// How the last round without a win ended; fresh when the step's events say a draw.
    pub draw: DrawRecord,
}

/// A scored winning hand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WinRecord {
    /// Yaku bits (ids as in [`super::yaku_names`]).
    pub yaku: [u32; 2],
    /// Han of yaku and dora (0 for a yakuman hand).
    pub han: u32,
    /// Fu of the hand.
    pub fu: u32,
    /// Yakuman weight (0 = none, 2 = double ...).
    pub yakuman: u32,
    /// No meld was called (closed kans allowed): each yaku counts its closed han.
    pub concealed: bool,
    /// Han from dora.
    pub dora: u32,
    /// Han from red fives.
    pub aka: u32,
    /// Han from ura-dora.
    pub ura: u32,
}

impl WinRecord {
    /// Seat `p`'s record in a state's `win_yaku` and `win_score` words (two per seat).
    pub fn decode(yaku: &[u32; 8], score: &[u32; 8], p: usize) -> WinRecord {
        let (points, extra) = (score[2 * p], score[2 * p + 1]);
        let field = |word: u32, shift: u32| word >> shift & kernel::WIN_FIELD_MASK;
        WinRecord {
            yaku: [yaku[2 * p], yaku[2 * p + 1]],
            han: field(points, 0),
            fu: field(points, kernel::WIN_FU_SHIFT),
            yakuman: field(points, kernel::WIN_YAKUMAN_SHIFT),
            concealed: field(points, kernel::WIN_CONCEALED_SHIFT) == 1,
            dora: field(extra, 0),
            aka: field(extra, kernel::WIN_AKA_SHIFT),
            ura: field(extra, kernel::WIN_URA_SHIFT),
        }
    }

    /// Yaku ids of the hand, in increasing order.
    pub fn yaku_ids(&self) -> impl Iterator<Item = u32> + '_ {
        (0..64u32).filter(move |i| self.yaku[(i / 32) as usize] >> (i % 32) & 1 == 1)
    }
}

/// How a round ended without a win.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DrawKind {
    /// The wall ran out (ryuukyoku).
    Exhaustive,
    /// The wall ran out and nagashi mangan was paid.
    Nagashi,
    /// Nine terminals and honors declared (kyuushu kyuuhai).
    Kyuushu,
    /// All four seats declared riichi.
    FourRiichi,
    /// Three seats called ron on one discard.
    TripleRon,
    /// Four kans by more than one seat.
    FourKans,
    /// All four first discards were the same wind.
    FourWinds,
}

/// The last drawn round of a game.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct DrawRecord {
    /// `None` before any round of the game ended in a draw.
    pub kind: Option<DrawKind>,
    /// Seats tenpai at an exhaustive draw.
    pub tenpai: [bool; 4],
    /// Seats paid nagashi mangan.
    pub nagashi: [bool; 4],
}

impl DrawRecord {
    /// A state's `draw_kind` word.
    pub fn decode(word: u32) -> DrawRecord {
        use crate::generated::kernel as k;
        let kind = match word & k::DRAW_KIND_MASK {
            k::DRAW_EXHAUSTIVE => Some(DrawKind::Exhaustive),
            k::DRAW_NAGASHI => Some(DrawKind::Nagashi),
            k::DRAW_KYUUSHU => Some(DrawKind::Kyuushu),
            k::DRAW_FOUR_RIICHI => Some(DrawKind::FourRiichi),
            k::DRAW_TRIPLE_RON => Some(DrawKind::TripleRon),
            k::DRAW_FOUR_KANS => Some(DrawKind::FourKans),
            k::DRAW_FOUR_WINDS => Some(DrawKind::FourWinds),
            _ => None,
        };
        DrawRecord {
            kind,
            tenpai: std::array::from_fn(|p| word >> (k::DRAW_TENPAI_SHIFT + p as u32) & 1 == 1),
            nagashi: std::array::from_fn(|p| word >> (k::DRAW_NAGASHI_SHIFT + p as u32) & 1 == 1),
        }
    }
}

/// The table and wall a forced deal starts a round from (see [`Env::deal`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Deal {
    /// 0 = East 1, 4 = South 1, 8 = West 1.
    pub round: u32,
    /// The dealer's seat.
    pub dealer: u32,
    /// Repeat counters.
    pub honba: u32,
    /// Riichi sticks on the table.
    pub sticks: u32,
    /// Each seat's points.
    pub scores: [i32; 4],
    /// The tiles in dealing order, as for [`Env::reset_with_walls`].
    pub wall: [Tile; 136],
}

/// The most points (or debt) a seat may hold when a round is dealt: the kernel adds payments to
/// scores in `i32`, and no table comes near it.
pub const MAX_SCORE: i32 = 100_000_000;

/// Whether a round can be dealt from this table: a round of East 1 to North 4 (0-15), at most
/// [`MAX_STICKS`](crate::hand::MAX_STICKS) honba and as many riichi sticks, and scores within
/// [`MAX_SCORE`] either way, so that no payment of the round can overflow.
pub fn check_table(round: u32, honba: u32, sticks: u32, scores: &[i32; 4]) -> Result<(), String> {
    if round >= 16 {
        return Err(format!("round {round} is not 0-15 (East 1 to North 4)"));
    }
    crate::hand::check_sticks(honba, sticks)?;
    if let Some(s) = scores.iter().find(|s| s.unsigned_abs() > MAX_SCORE.unsigned_abs()) {
        return Err(format!("a score of {s}: at most {MAX_SCORE} either way"));
    }
    Ok(())
}

impl CpuEnv {
    fn deal(&mut self, variant: Variant, inputs: &[u32]) {
        with_variant!(variant, v => {
            let ins: &[kernel::DealInput] = bytemuck::cast_slice(inputs);
            let sts: &mut [kernel::GameState] = bytemuck::cast_slice_mut(&mut self.states);
            let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(&mut self.views);
            for ((s, w), i) in sts.iter_mut().zip(vws.iter_mut()).zip(ins) {
                if i.deal != 0 {
                    v::game_deal(s, *i);
                    *w = v::game_view(*s);
                }
            }
        })
    }
}

impl Env {
    /// Starts the next round of the envs given a `Some` from that table and wall instead of the
    /// one each game reached by itself (log replay deals every logged round from its own wall).
    /// A finished game is left as it is. Returns the views after the deal. A wall that is not
    /// this variant's tiles, a dealer who is not a seat of the table or a table that fails [`check_table`] is an
    /// error, and nothing is dealt.
    pub fn deal(&mut self, deals: &[Option<Deal>]) -> Result<&Step, EnvError> {
        self.check_len("deals", deals.len())?;
        let variant = self.variant();
        for (env, d) in deals.iter().enumerate() {
            let Some(d) = d else { continue };
            check_wall(variant, &d.wall).map_err(|reason| EnvError::BadWall { env, reason })?;
            if d.dealer >= variant.seats() {
                return Err(EnvError::BadDealer {
                    env,
                    dealer: d.dealer,
                    seats: variant.seats(),
                });
            }
            check_table(d.round, d.honba, d.sticks, &d.scores).map_err(|reason| EnvError::BadDeal { env, reason })?;
        }
        let mut words = vec![0u32; deals.len() * DEAL_WORDS];
        {
            let ins: &mut [kernel::DealInput] = bytemuck::cast_slice_mut(&mut words);
            for (inp, d) in ins.iter_mut().zip(deals) {
                if let Some(d) = d {
                    *inp = kernel::DealInput {
                        deal: 1,
                        round: d.round,
                        dealer: d.dealer,
                        honba: d.honba,
                        sticks: d.sticks,
                        scores: d.scores,
                        wall: d.wall.map(|t| u32::from(t.value())),
                    };
                }
            }
        };
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                cpu.deal(variant, &words);
                self.step.fill(&cpu.views);
            }
            Backing::Gpu(gpu) => {
                let views = gpu.deal(&words)?;
                self.step.fill(views);
            }
        }
        self.write_observations()?;
        Ok(&self.step)
    }

    /// The table of every env (read back from the device on the GPU backend).
    pub fn tables(&self) -> Result<Vec<Table>, EnvError> {
        let words = self.states_words()?;
        let states: &[kernel::GameState] = bytemuck::cast_slice(&words);
        Ok(states
            .iter()
            .map(|s| Table {
                round: s.round,
                dealer: s.dealer,
                honba: s.honba,
                sticks: s.sticks,
                scores: s.scores,
                rounds: s.rounds,
                over: s.terminated != 0,
                wins: std::array::from_fn(|p| WinRecord::decode(&s.win_yaku, &s.win_score, p)),
                draw: DrawRecord::decode(s.draw_kind),
            })
            .collect())
    }
}
