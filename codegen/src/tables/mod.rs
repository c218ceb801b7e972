//! Per-suit tables keyed by base-5 codes, built from first principles at build time.
//!
//! Everything lives in one flat `Vec<u32>` so the runtime can upload it to the GPU as a single
//! storage buffer and the CPU can `include_bytes!` the same bytes; regions are found by offset.
//!
//! | region | words per entry | content |
//! |---|---|---|
//! | `suit_cost` | 1 per suit code | D as increments: D(m, 0) - D(m-1, 0) at bits `2(m-1)..2m` (m = 1..=4), D(m, 1) - D(m, 0) at bits `8+2m..10+2m` (m = 0..=4); the row's number from bit 18 (see [`pairs`]) |
//! | `honor_cost` | 1 per honor code | the same for honors (triplets and pairs only) |
//! | `decomp_index` | 1 per suit code | `(first << 4) \| count` into `decomps` |
//! | `decomps` | 2 per decomposition | word 0: pair and sets; word 1: yaku bits (see [`decomp`]) |
//! | `suit_pairs` | 1 per pair of suit rows | the two rows combined, packed as a cost word; its number among the distinct combined rows from bit 18 |
//! | `suit_honor_pairs` | 1 per suit row and honor row | the same for a suit and the honors |
//! | `missing` | 1 per combined suit row and combined suit-honor row (by number) | the tiles missing for m sets and the pair, the two combined rows together, at bits `4m..4m+4` (m = 0..=4) |
//!
//! D is exact (see the `cost` module), so per-suit costs can be combined exactly by the shanten kernel.
//! D(0, 0) is always 0 and every increment fits 2 bits (checked on every code at every build), so a
//! row of ten costs packs into one word: half the bytes of two 4-bit-field words, and one load.

mod code;
mod cost;
pub mod decomp;
pub mod pairs;

pub use code::{honor_code, suit_code, HONOR_CODES, SUIT_CODES};
pub use cost::{pack as pack_costs, CostRow};

/// Bits of the count field in a `decomp_index` word.
pub const INDEX_COUNT_BITS: u32 = 4;

/// All tables in one buffer, with each region's offset (in words).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Tables {
    pub words: Vec<u32>,
    pub suit_cost: u32,
    pub honor_cost: u32,
    pub decomp_index: u32,
    pub decomps: u32,
    /// Number of decompositions (the `decomps` region holds twice as many words).
    pub n_decomps: u32,
    pub suit_pairs: u32,
    pub suit_honor_pairs: u32,
    pub missing: u32,
    /// The distinct suit and honor cost rows (cost words without their numbers), by number.
    pub suit_rows: Vec<u32>,
    pub honor_rows: Vec<u32>,
    /// The distinct rows of the two pair tables (combined rows without their numbers), by number.
    pub suit_pair_rows: Vec<u32>,
    pub suit_honor_pair_rows: Vec<u32>,
}

/// Builds every table. Deterministic: the same words on every run and machine.
pub fn build() -> Tables {
    let decomps = decomp::all();
    let n_decomps = decomps.len();

    let suit_cost = 0;
    let honor_cost = suit_cost + SUIT_CODES;
    let decomp_index = honor_cost + HONOR_CODES;
    let decomps_at = decomp_index + SUIT_CODES;
    let pairs_at = decomps_at + 2 * n_decomps;
    let mut words = vec![0u32; pairs_at];

    cost::build::<9>(&cost::suit_sets(), &mut words[suit_cost..honor_cost]);
    cost::build::<7>(&cost::honor_sets(), &mut words[honor_cost..decomp_index]);
    let suit_rows = pairs::distinct(&words[suit_cost..honor_cost]);
    let honor_rows = pairs::distinct(&words[honor_cost..decomp_index]);
    let mut suit_pairs = vec![0u32; suit_rows.len() * suit_rows.len()];
    let mut suit_honor_pairs = vec![0u32; suit_rows.len() * honor_rows.len()];
    pairs::build(&suit_rows, &suit_rows, &mut suit_pairs);
    pairs::build(&suit_rows, &honor_rows, &mut suit_honor_pairs);
    pairs::number(&mut words[suit_cost..honor_cost], &suit_rows);
    pairs::number(&mut words[honor_cost..decomp_index], &honor_rows);
    let suit_pair_rows = pairs::distinct(&suit_pairs);
    let suit_honor_pair_rows = pairs::distinct(&suit_honor_pairs);
    let missing = pairs::missing(&suit_pair_rows, &suit_honor_pair_rows);
    pairs::number(&mut suit_pairs, &suit_pair_rows);
    pairs::number(&mut suit_honor_pairs, &suit_honor_pair_rows);
    let suit_honor_at = pairs_at + suit_pairs.len();
    let missing_at = suit_honor_at + suit_honor_pairs.len();
    words.extend(suit_pairs);
    words.extend(suit_honor_pairs);
    words.extend(missing);

    let (index, list) = words[decomp_index..].split_at_mut(SUIT_CODES);
    // `decomps` is sorted by code, so each code's decompositions are one contiguous run.
    let mut first = 0;
    while first < n_decomps {
        let code = decomps[first].0;
        let count = decomps[first..].iter().take_while(|d| d.0 == code).count();
        assert!(count < 1 << INDEX_COUNT_BITS, "code {code}: {count} decompositions");
        index[code] = (first as u32) << INDEX_COUNT_BITS | count as u32;
        first += count;
    }
    for ((code, d), out) in decomps.iter().zip(list.chunks_exact_mut(2)) {
        out[0] = d.word0();
        out[1] = d.word1(&code::decode::<9>(*code));
    }

    let offset = |x: usize| u32::try_from(x).expect("tables exceed u32 offsets");
    Tables {
        words,
        suit_cost: offset(suit_cost),
        honor_cost: offset(honor_cost),
        decomp_index: offset(decomp_index),
        decomps: offset(decomps_at),
        n_decomps: offset(n_decomps),
        suit_pairs: offset(pairs_at),
        suit_honor_pairs: offset(suit_honor_at),
        missing: offset(missing_at),
        suit_rows,
        honor_rows,
        suit_pair_rows,
        suit_honor_pair_rows,
    }
}

impl Tables {
    /// Kernel-subset Rust consts, one `const NAME: u32 = <n>u32;` a line: the region offsets, then
    /// the numbers of suit and honor rows and of the two pair tables' rows (the strides of the
    /// tables indexed by them), where a cost word's row number starts, and the bits of each count
    /// of a `missing` word.
    pub fn kernel_consts(&self) -> String {
        let counts = [
            ("SUIT_ROWS", self.suit_rows.len()),
            ("HONOR_ROWS", self.honor_rows.len()),
            ("SUIT_PAIR_ROWS", self.suit_pair_rows.len()),
            ("SUIT_HONOR_PAIR_ROWS", self.suit_honor_pair_rows.len()),
            ("ROW_SHIFT", pairs::ROW_SHIFT as usize),
            ("MISSING_BITS", pairs::MISSING_BITS as usize),
        ];
        self.regions()
            .iter()
            .map(|&(name, at, _)| (name.to_uppercase(), at as usize))
            .chain(counts.map(|(name, n)| (name.to_string(), n)))
            .map(|(name, n)| format!("const T_{name}: u32 = {n}u32;\n"))
            .collect()
    }

    /// Little-endian bytes of `words`, for writing to OUT_DIR and `include_bytes!`.
    pub fn to_le_bytes(&self) -> Vec<u8> {
        self.words.iter().flat_map(|w| w.to_le_bytes()).collect()
    }

    /// 64-bit FNV-1a over each region's little-endian bytes, by region name.
    pub fn region_hashes(&self) -> Vec<(&'static str, u64)> {
        self.regions()
            .into_iter()
            .map(|(name, at, len)| (name, fnv1a(&self.words[at as usize..][..len])))
            .collect()
    }

    /// The packed cost word of a suit code (its row's number from bit [`pairs::ROW_SHIFT`]).
    pub fn suit_cost_word(&self, code: usize) -> u32 {
        self.words[self.suit_cost as usize + code]
    }

    /// The packed cost word of an honor code.
    pub fn honor_cost_word(&self, code: usize) -> u32 {
        self.words[self.honor_cost as usize + code]
    }

    /// The `decomps` words (two per decomposition) of a suit code; empty if it is incomplete.
    pub fn decomps_of(&self, code: usize) -> &[u32] {
        let entry = self.words[self.decomp_index as usize + code];
        let first = (entry >> INDEX_COUNT_BITS) as usize;
        let count = (entry & ((1 << INDEX_COUNT_BITS) - 1)) as usize;
        &self.words[self.decomps as usize + 2 * first..][..2 * count]
    }

    /// The combined row of suit rows `i` and `j` (by number).
    pub fn suit_pair_word(&self, i: usize, j: usize) -> u32 {
        self.words[self.suit_pairs as usize + i * self.suit_rows.len() + j]
    }

    /// The combined row of suit row `i` and honor row `j`.
    pub fn suit_honor_pair_word(&self, i: usize, j: usize) -> u32 {
        self.words[self.suit_honor_pairs as usize + i * self.honor_rows.len() + j]
    }

    /// The `missing` word of combined suit row `i` and combined suit-honor row `j` (by number).
    pub fn missing_word(&self, i: usize, j: usize) -> u32 {
        self.words[self.missing as usize + i * self.suit_honor_pair_rows.len() + j]
    }

    fn regions(&self) -> [(&'static str, u32, usize); 7] {
        let (s, h) = (self.suit_rows.len(), self.honor_rows.len());
        let (sp, shp) = (self.suit_pair_rows.len(), self.suit_honor_pair_rows.len());
        [
            ("suit_cost", self.suit_cost, SUIT_CODES),
            ("honor_cost", self.honor_cost, HONOR_CODES),
            ("decomp_index", self.decomp_index, SUIT_CODES),
            ("decomps", self.decomps, 2 * self.n_decomps as usize),
            ("suit_pairs", self.suit_pairs, s * s),
            ("suit_honor_pairs", self.suit_honor_pairs, s * h),
            ("missing", self.missing, sp * shp),
        ]
    }
}

/// D(m, h) out of a packed cost word.
pub fn cost_d(word: u32, m: usize, h: usize) -> u32 {
    cost::unpack(word, m, h)
}

/// D(m, h) of every suit code, unpacked (what `suit_cost` packs), for checks.
pub fn suit_cost_rows() -> Vec<CostRow> {
    cost::rows::<9>(&cost::suit_sets())
}

/// D(m, h) of every honor code, unpacked (what `honor_cost` packs), for checks.
pub fn honor_cost_rows() -> Vec<CostRow> {
    cost::rows::<7>(&cost::honor_sets())
}

fn fnv1a(words: &[u32]) -> u64 {
    words
        .iter()
        .flat_map(|w| w.to_le_bytes())
        .fold(0xcbf2_9ce4_8422_2325, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        })
}
