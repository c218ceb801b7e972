//! Shanten and hand scoring on the CPU: the generated kernels, one hand at a time or a batch in
//! parallel. Batches are kept as raw kernel words so the GPU backend takes exactly the same input.

use rayon::prelude::*;

use crate::generated::kernel;
use crate::notation::{Meld, MeldKind};
use crate::tile::TileType;
use crate::Variant;

/// Shanten of a concealed hand: the number of tiles away from tenpai (`-1` = complete).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shanten {
    /// The best of the three shapes below.
    pub shanten: i32,
    /// Towards four sets and a pair.
    pub normal: i32,
    /// Towards seven pairs; `None` when the hand has too few tiles for them (it has called melds).
    pub chiitoitsu: Option<i32>,
    /// Towards thirteen orphans; `None` as for `chiitoitsu`.
    pub kokushi: Option<i32>,
}

/// Words of one shanten kernel input (the size of the kernel's `ShantenInput`).
pub const SHANTEN_IN_WORDS: usize = words::<kernel::ShantenInput>();
/// Words of one shanten kernel output (`ShantenOutput`).
pub const SHANTEN_OUT_WORDS: usize = words::<kernel::ShantenOutput>();
/// Words of one scoring kernel input (`ScoreInput`).
pub const SCORE_IN_WORDS: usize = words::<kernel::ScoreInput>();
/// Words of one scoring kernel output (`ScoreOutput`).
pub const SCORE_OUT_WORDS: usize = words::<kernel::ScoreOutput>();
/// The most honba, and the most riichi sticks, a hand to score may carry.
pub const MAX_STICKS: u32 = 10_000;

/// 32-bit words of a kernel record.
pub(crate) const fn words<T>() -> usize {
    std::mem::size_of::<T>() / 4
}

/// Shanten input words for a concealed hand given as counts.
pub fn shanten_input(counts: &[u8; 34]) -> [u32; SHANTEN_IN_WORDS] {
    counts.map(u32::from)
}

/// Decodes one shanten output (SHANTEN_OUT_WORDS words).
pub fn decode_shanten(words: &[u32]) -> Shanten {
    let o: kernel::ShantenOutput = bytemuck::pod_read_unaligned(bytemuck::cast_slice(&words[..SHANTEN_OUT_WORDS]));
    let opt = |x: i32| (x != kernel::SHANTEN_NOT_APPLICABLE).then_some(x);
    Shanten {
        shanten: o.shanten,
        normal: o.normal,
        chiitoitsu: opt(o.chiitoitsu),
        kokushi: opt(o.kokushi),
    }
}

/// Shanten of one hand of 1 to 14 concealed tiles (counts per type, each at most 4).
pub fn shanten(counts: &[u8; 34]) -> Shanten {
    let mut out = [0u32; SHANTEN_OUT_WORDS];
    shanten_batch(&shanten_input(counts), &mut out);
    decode_shanten(&out)
}

/// The shanten of a concealed hand in notation (`123m456p789s1122z`, 0 = red five): 1 to 14
/// tiles, 3k+1 or 3k+2 of them, at most 4 of a kind; otherwise what is wrong with it.
pub fn shanten_of_notation(hand: &str) -> Result<Shanten, String> {
    let tiles = crate::notation::parse_tiles(hand).map_err(|e| e.to_string())?;
    let counts = tiles.counts();
    if let Some((t, n)) = TileType::all().zip(counts).find(|&(_, n)| n > 4) {
        return Err(format!("{n} copies of {t}: there are only 4"));
    }
    let n = tiles.tiles.len();
    if n > 14 || n % 3 == 0 {
        return Err(format!(
            "{n} tiles: a hand to measure has 3k+1 or 3k+2 tiles (13 or 14 without melds)"
        ));
    }
    Ok(shanten(&counts))
}

/// Runs the shanten kernel over `inputs` (SHANTEN_IN_WORDS each) into `outputs`, on the calling thread.
pub fn shanten_batch(inputs: &[u32], outputs: &mut [u32]) {
    {
        let ins: &[kernel::ShantenInput] = bytemuck::cast_slice(inputs);
        let outs: &mut [kernel::ShantenOutput] = bytemuck::cast_slice_mut(outputs);
        for (i, o) in ins.iter().zip(outs.iter_mut()) {
            *o = kernel::shanten(*i);
        }
    }
}

/// As [`shanten_batch`], split over the current rayon pool.
pub fn shanten_batch_par(inputs: &[u32], outputs: &mut [u32]) {
    {
        let ins: &[kernel::ShantenInput] = bytemuck::cast_slice(inputs);
        let outs: &mut [kernel::ShantenOutput] = bytemuck::cast_slice_mut(outputs);
        ins.par_iter()
            .zip(outs.par_iter_mut())
            .with_min_len(256)
            .for_each(|(i, o)| *o = kernel::shanten(*i));
    }
}

/// The circumstances of a win.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct WinContext {
    /// Won on one's own draw (else by ron).
    pub tsumo: bool,
    /// The winner declared riichi.
    pub riichi: bool,
    /// The riichi was a double riichi (`riichi` is set too).
    pub double_riichi: bool,
    /// Won within one uninterrupted go-around after riichi.
    pub ippatsu: bool,
    /// Tsumo on the last tile of the wall.
    pub haitei: bool,
    /// Ron on the last discard.
    pub houtei: bool,
    /// Tsumo on a kan's replacement tile.
    pub rinshan: bool,
    /// Ron on a tile added to a pon.
    pub chankan: bool,
    /// The dealer's win on the first draw.
    pub tenhou: bool,
    /// A non-dealer's win on the first uninterrupted draw.
    pub chiihou: bool,
    /// The winner is the dealer.
    pub dealer: bool,
    /// 0..3 = E S W N.
    pub round_wind: u8,
    /// The winner's wind, 0..3 = E S W N (East for the dealer).
    pub seat_wind: u8,
    /// Dora indicators (at most 5).
    pub dora: Vec<TileType>,
    /// Ura-dora indicators (at most 5), counted only with riichi.
    pub ura: Vec<TileType>,
    /// Repeat counters on the table.
    pub honba: u32,
    /// Riichi sticks on the table, collected by the winner.
    pub sticks: u32,
}

/// A winning hand to score.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Win {
    /// Concealed tiles, the winning tile included.
    pub hand: [u8; 34],
    /// The winning tile.
    pub win: TileType,
    /// Called and declared sets, in any order.
    pub melds: Vec<Meld>,
    /// Red fives among all the winner's tiles, melds included.
    pub aka: u8,
    /// How and where it was won.
    pub context: WinContext,
}

/// Why a hand could not be scored.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ScoreError {
    /// The input itself is inconsistent (tile counts, too many melds or indicators...).
    BadInput(String),
    /// The tiles do not form a winning hand.
    NotComplete,
    /// A complete hand without any yaku (dora are not yaku).
    NoYaku,
}

impl std::fmt::Display for ScoreError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ScoreError::BadInput(m) => write!(f, "invalid hand: {m}"),
            ScoreError::NotComplete => f.write_str(
                "not a winning hand: the tiles do not form four sets and a pair, seven pairs or thirteen orphans",
            ),
            ScoreError::NoYaku => f.write_str("the hand is complete but has no yaku (dora alone do not count)"),
        }
    }
}

impl std::error::Error for ScoreError {}

/// What a yaku is worth in a hand: han, or a number of yakuman.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum YakuHan {
    /// An ordinary yaku's han (dora count here too).
    Han(u32),
    /// A yakuman's weight (2 = double where the variant counts double yakuman).
    Yakuman(u32),
}

impl YakuHan {
    /// The number alone: the han, or the yakuman weight.
    pub fn number(self) -> u32 {
        match self {
            YakuHan::Han(n) | YakuHan::Yakuman(n) => n,
        }
    }
}

/// One yaku of a win and what it is worth; the dora of a hand are listed as `dora`, `aka` (red
/// fives) and `ura`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Yaku {
    /// The spec's name (`rules/yaku.toml`), or `dora`, `aka`, `ura`.
    pub name: &'static str,
    /// What it is worth.
    pub han: YakuHan,
}

/// What each payer pays for a win, riichi sticks excluded. In a [`Score`] honba are included;
/// `tenhou::write`'s points texts show it before honba.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Payment {
    /// A win on a discard: the discarder pays it all.
    Ron {
        /// What the discarder pays.
        discarder: u32,
    },
    /// A win on one's own draw: every other seat pays a share.
    Tsumo {
        /// The dealer's share; `None` when the dealer is the winner (then all three pay `others`).
        dealer: Option<u32>,
        /// Each non-dealer's share.
        others: u32,
    },
}

/// What a winning hand scores.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Score {
    /// Han of yaku and dora (0 for a yakuman hand).
    pub han: u32,
    /// Fu, rounded as the rules count them.
    pub fu: u32,
    /// Total yakuman weight (0 for an ordinary hand; kazoe yakuman is han >= 13 with 0 here).
    pub yakuman: u32,
    /// The yaku of the best-paying reading, then dora, red fives and ura.
    pub yaku: Vec<Yaku>,
    /// Base points: fu x 2^(han+2) up to the limits.
    pub base: u32,
    /// Who pays what.
    pub payment: Payment,
    /// The winner's total gain, riichi sticks included.
    pub gain: u32,
}

/// At most [`MAX_STICKS`] honba and as many riichi sticks: the kernel pays in u32 points, and far
/// more sticks than any table holds would wrap around.
pub(crate) fn check_sticks(honba: u32, sticks: u32) -> Result<(), String> {
    if honba > MAX_STICKS || sticks > MAX_STICKS {
        return Err(format!(
            "{honba} honba and {sticks} riichi sticks: at most {MAX_STICKS} of each"
        ));
    }
    Ok(())
}

fn bad(message: impl Into<String>) -> ScoreError {
    ScoreError::BadInput(message.into())
}

fn meld_word(m: &Meld) -> u32 {
    let kind = match m.kind {
        MeldKind::Chi => kernel::MELD_CHI,
        MeldKind::Pon => kernel::MELD_PON,
        MeldKind::Kan => kernel::MELD_OPEN_KAN,
        MeldKind::Ankan => kernel::MELD_CLOSED_KAN,
        MeldKind::Kakan => kernel::MELD_ADDED_KAN,
    };
    kernel::meld_word(kind, u32::from(m.tile))
}

/// Checks a win for consistency and packs it into kernel input words.
pub fn score_input(win: &Win) -> Result<[u32; SCORE_IN_WORDS], ScoreError> {
    let c = &win.context;
    if win.melds.len() > 4 {
        return Err(bad(format!("{} melds: a hand has at most 4", win.melds.len())));
    }
    if c.dora.len() > 5 || c.ura.len() > 5 {
        return Err(bad("at most 5 dora and 5 ura indicators"));
    }
    if c.round_wind > 3 || c.seat_wind > 3 {
        return Err(bad("winds are 0..3 (E S W N)"));
    }
    if c.dealer != (c.seat_wind == 0) {
        return Err(bad("the dealer's seat wind is East, and only the dealer's"));
    }
    check_sticks(c.honba, c.sticks).map_err(bad)?;
    if win.hand[win.win.index()] == 0 {
        return Err(bad("the winning tile must be among the concealed tiles"));
    }
    if let Some(m) = win
        .melds
        .iter()
        .find(|m| m.kind == MeldKind::Chi && m.tile.up(2).is_none())
    {
        return Err(bad(format!("a chi from {} is not a run of one suit", m.tile)));
    }
    let mut all = win.hand;
    for m in &win.melds {
        for t in m.tiles() {
            all[t.index()] += 1;
        }
    }
    if let Some((t, &n)) = TileType::all().zip(&all).find(|&(_, &n)| n > 4) {
        return Err(bad(format!("{n} copies of {t}: there are only 4")));
    }
    let concealed: usize = win.hand.iter().map(|&n| n as usize).sum();
    if concealed + 3 * win.melds.len() != 14 {
        return Err(bad(format!(
            "{concealed} concealed tiles and {} melds: a winning hand has 14 - 3 x melds concealed tiles",
            win.melds.len()
        )));
    }
    let fives = all[4] + all[13] + all[22];
    if win.aka > fives.min(3) {
        return Err(bad(format!("{} red fives but only {fives} fives", win.aka)));
    }
    let flags = [
        (c.tsumo, kernel::FLAG_TSUMO),
        (c.riichi, kernel::FLAG_RIICHI),
        (c.double_riichi, kernel::FLAG_DOUBLE_RIICHI),
        (c.ippatsu, kernel::FLAG_IPPATSU),
        (c.haitei, kernel::FLAG_HAITEI),
        (c.houtei, kernel::FLAG_HOUTEI),
        (c.rinshan, kernel::FLAG_RINSHAN),
        (c.chankan, kernel::FLAG_CHANKAN),
        (c.tenhou, kernel::FLAG_TENHOU),
        (c.chiihou, kernel::FLAG_CHIIHOU),
        (c.dealer, kernel::FLAG_DEALER),
    ];
    let up_to_five = |tiles: &[TileType]| std::array::from_fn(|i| tiles.get(i).map_or(0, |&t| u32::from(t)));
    let mut melds = [0u32; 4];
    for (word, m) in melds.iter_mut().zip(&win.melds) {
        *word = meld_word(m);
    }
    let input = kernel::ScoreInput {
        hand: win.hand.map(u32::from),
        win_tile: u32::from(win.win),
        melds,
        n_melds: win.melds.len() as u32,
        flags: flags.iter().filter(|(on, _)| *on).fold(0, |acc, (_, f)| acc | f),
        round_wind: u32::from(c.round_wind),
        seat_wind: u32::from(c.seat_wind),
        dora: up_to_five(&c.dora),
        n_dora: c.dora.len() as u32,
        ura: up_to_five(&c.ura),
        n_ura: c.ura.len() as u32,
        aka: u32::from(win.aka),
        kita: 0,
        honba: c.honba,
        sticks: c.sticks,
    };
    Ok(bytemuck::cast(input))
}

/// What yaku `id` of `variant` is worth in a hand: its closed or open han, or for a yakuman its
/// weight (capped at 1 where the variant counts no double yakuman).
pub fn yaku_worth(variant: Variant, id: usize, concealed: bool) -> YakuHan {
    with_variant!(variant, v => {
        if v::YAKU_YAKUMAN[id] > 0 {
            YakuHan::Yakuman(if v::DOUBLE_YAKUMAN { v::YAKU_YAKUMAN[id] } else { 1 })
        } else if concealed {
            YakuHan::Han(v::YAKU_HAN_CLOSED[id])
        } else {
            YakuHan::Han(v::YAKU_HAN_OPEN[id])
        }
    })
}

/// The part of a pao win of `yakuman` yakuman that the seat liable for yakuman `pao` covers, as
/// [numerator, denominator] (the scoring kernel's `pao_share` under `variant`'s spec).
pub fn pao_share(variant: Variant, yakuman: u32, pao: u32) -> [u32; 2] {
    with_variant!(variant, v => v::pao_share(yakuman, pao))
}

/// Decodes one score output (SCORE_OUT_WORDS words) of `variant`.
pub fn decode_score(variant: Variant, w: &[u32]) -> Result<Score, ScoreError> {
    let o: kernel::ScoreOutput = bytemuck::pod_read_unaligned(bytemuck::cast_slice(&w[..SCORE_OUT_WORDS]));
    match o.status {
        kernel::STATUS_WIN => {}
        kernel::STATUS_NOT_COMPLETE => return Err(ScoreError::NotComplete),
        kernel::STATUS_NO_YAKU => return Err(ScoreError::NoYaku),
        _ => return Err(bad("rejected by the scoring kernel")),
    }
    let concealed = o.concealed != 0;
    let mut yaku = Vec::new();
    with_variant!(variant, v => {
        for i in 0..v::YAKU_COUNT as usize {
            let held = if i < 32 { o.yaku_lo >> i & 1 } else { o.yaku_hi >> (i - 32) & 1 };
            if held == 1 {
                yaku.push(Yaku { name: v::host::YAKU_NAMES[i], han: yaku_worth(variant, i, concealed) });
            }
        }
    });
    for (name, n) in [("dora", o.dora), ("aka", o.aka), ("ura", o.ura)] {
        if n > 0 {
            yaku.push(Yaku {
                name,
                han: YakuHan::Han(n),
            });
        }
    }
    let payment = if o.ron > 0 {
        Payment::Ron { discarder: o.ron }
    } else {
        Payment::Tsumo {
            dealer: (o.dealer_pays > 0).then_some(o.dealer_pays),
            others: o.others_pay,
        }
    };
    Ok(Score {
        han: o.han,
        fu: o.fu,
        yakuman: o.yakuman,
        yaku,
        base: o.base,
        payment,
        gain: o.gain,
    })
}

/// Runs the scoring kernel over `inputs` (SCORE_IN_WORDS each) into `outputs`, on the calling thread.
pub fn score_batch(variant: Variant, inputs: &[u32], outputs: &mut [u32]) {
    with_variant!(variant, v => {
        let ins: &[kernel::ScoreInput] = bytemuck::cast_slice(inputs);
        let outs: &mut [kernel::ScoreOutput] = bytemuck::cast_slice_mut(outputs);
        for (i, o) in ins.iter().zip(outs.iter_mut()) {
            *o = v::score_hand(*i);
        }
    })
}

/// As [`score_batch`], split over the current rayon pool.
pub fn score_batch_par(variant: Variant, inputs: &[u32], outputs: &mut [u32]) {
    with_variant!(variant, v => {
        let ins: &[kernel::ScoreInput] = bytemuck::cast_slice(inputs);
        let outs: &mut [kernel::ScoreOutput] = bytemuck::cast_slice_mut(outputs);
        ins.par_iter().zip(outs.par_iter_mut()).with_min_len(64).for_each(|(i, o)| *o = v::score_hand(*i));
    })
}

/// Scores one winning hand under `variant`'s rules.
pub fn score(variant: Variant, win: &Win) -> Result<Score, ScoreError> {
    let input = score_input(win)?;
    let mut out = [0u32; SCORE_OUT_WORDS];
    score_batch(variant, &input, &mut out);
    decode_score(variant, &out)
}
