//! Table checks: independent oracles (reference statistics, brute-force costs and splitters)
//! prove what the tables mean; the hash pin only catches unintended change.

use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;
use std::time::Instant;

use rinshan_codegen::tables::{
    self, cost_d, decomp, honor_code, pack_costs, pairs, suit_code, CostRow, Tables, HONOR_CODES, SUIT_CODES,
};

fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(|| {
        let start = Instant::now();
        let t = tables::build();
        eprintln!(
            "tables::build: {:?} ({} words, {} decompositions)",
            start.elapsed(),
            t.words.len(),
            t.n_decomps
        );
        t
    })
}

/// Random codes per brute-force test (the whole file runs in about 15 s unoptimised).
const SAMPLES: usize = 2000;

/// splitmix64: enough randomness for sampling, and reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

fn decode<const N: usize>(mut code: usize) -> [u8; N] {
    let mut c = [0u8; N];
    for i in (0..N).rev() {
        c[i] = (code % 5) as u8;
        code /= 5;
    }
    c
}

/// Adds a set (0..7 run start, 7..16 triplet) to suit counts; false if a count would pass 4.
fn add_set(c: &mut [u8; 9], v: usize) -> bool {
    if v < 7 {
        c[v..v + 3].iter_mut().for_each(|x| *x += 1);
    } else {
        c[v - 7] += 3;
    }
    c.iter().all(|&x| x <= 4)
}

/// Sample codes: a third uniform, a third random tiles (0..=14), a third random sets + pair with
/// a tile added or removed now and then, so complete and near-complete suits are well covered.
fn sample_suits(rng: &mut Rng, n: usize) -> Vec<[u8; 9]> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let mut c = [0u8; 9];
        let ok = match out.len() % 3 {
            0 => {
                c = decode(rng.below(SUIT_CODES));
                true
            }
            1 => (0..rng.below(15)).all(|_| {
                let p = rng.below(9);
                c[p] += 1;
                c[p] <= 4
            }),
            _ => {
                let ok = (0..rng.below(5)).all(|_| add_set(&mut c, rng.below(16)));
                if rng.below(2) == 0 {
                    c[rng.below(9)] += 2;
                }
                match rng.below(4) {
                    0 => c[rng.below(9)] += 1,
                    1 => {
                        let p = rng.below(9);
                        c[p] = c[p].saturating_sub(1);
                    }
                    _ => {}
                }
                ok && c.iter().all(|&x| x <= 4)
            }
        };
        if ok {
            out.push(c);
        }
    }
    out
}

/// Every target of `m` sets and `h` pairs from `shapes`, counts <= 4, deduplicated.
fn targets<const N: usize>(shapes: &[[u8; N]], m: usize, h: usize) -> Vec<[u8; N]> {
    let mut all = BTreeSet::new();
    let mut stack = vec![(0usize, 0usize, [0u8; N])];
    while let Some((start, used, acc)) = stack.pop() {
        if used == m {
            if h == 0 {
                all.insert(acc);
            } else {
                for p in 0..N {
                    let mut t = acc;
                    t[p] += 2;
                    if t[p] <= 4 {
                        all.insert(t);
                    }
                }
            }
            continue;
        }
        for (k, s) in shapes.iter().enumerate().skip(start) {
            let mut t = acc;
            t.iter_mut().zip(s).for_each(|(a, b)| *a += b);
            if t.iter().all(|&x| x <= 4) {
                stack.push((k, used + 1, t));
            }
        }
    }
    all.into_iter().collect()
}

fn suit_shapes() -> Vec<[u8; 9]> {
    (0..16)
        .map(|v| {
            let mut c = [0; 9];
            add_set(&mut c, v);
            c
        })
        .collect()
}

fn honor_shapes() -> Vec<[u8; 7]> {
    (0..7)
        .map(|p| {
            let mut c = [0; 7];
            c[p] = 3;
            c
        })
        .collect()
}

/// Fewest tiles missing over all targets; a target is dropped once it cannot beat the best so far
/// (only to keep the unoptimised test quick).
fn brute_d<const N: usize>(targets: &[[u8; N]], c: &[u8; N]) -> u32 {
    assert!(!targets.is_empty());
    let mut best = u32::MAX;
    for t in targets {
        let mut missing = 0;
        for (&t, &c) in t.iter().zip(c) {
            missing += u32::from(t.saturating_sub(c));
            if missing >= best {
                break;
            }
        }
        best = best.min(missing);
    }
    best
}

fn check_costs<const N: usize>(
    shapes: &[[u8; N]],
    samples: &[[u8; N]],
    code_of: impl Fn(&[u8; N]) -> usize,
    word_of: impl Fn(usize) -> u32,
) {
    for m in 0..=4 {
        for h in 0..=1 {
            let ts = targets(shapes, m, h);
            for c in samples {
                let got = cost_d(word_of(code_of(c)), m, h);
                assert_eq!(got, brute_d(&ts, c), "D({m},{h}) of {c:?}");
            }
        }
    }
}

#[test]
fn suit_costs_match_brute_force() {
    let t = tables();
    let mut rng = Rng(1);
    let mut samples = sample_suits(&mut rng, SAMPLES);
    // Every suit of at most 3 tiles too: the small cases are where off-by-ones hide.
    samples.extend((0..SUIT_CODES).map(decode::<9>).filter(|c| c.iter().sum::<u8>() <= 3));
    check_costs(&suit_shapes(), &samples, suit_code, |c| t.suit_cost_word(c));
}

#[test]
fn honor_costs_match_brute_force() {
    let t = tables();
    let mut rng = Rng(2);
    let samples: Vec<[u8; 7]> = (0..SAMPLES)
        .map(|i| {
            if i % 2 == 0 {
                decode(rng.below(HONOR_CODES))
            } else {
                // Honor hands are mostly pairs and triplets: sample those shapes more.
                let mut c = [0u8; 7];
                for _ in 0..rng.below(6) {
                    let p = rng.below(7);
                    c[p] = (c[p] + [1, 2, 3][rng.below(3)]).min(4);
                }
                c
            }
        })
        .collect();
    check_costs(&honor_shapes(), &samples, honor_code, |c| t.honor_cost_word(c));
}

#[test]
fn complete_suits_cost_nothing() {
    // A suit with a decomposition into n sets and h pairs needs no tile for (n, h).
    let t = tables();
    for code in 0..SUIT_CODES {
        for d in t.decomps_of(code).chunks_exact(2) {
            let pair = usize::from(d[0] & 15 != decomp::NO_PAIR);
            let n = (d[0] >> decomp::W0_NSETS_SHIFT & 7) as usize;
            assert_eq!(cost_d(t.suit_cost_word(code), n, pair), 0, "code {code}");
        }
    }
}

type Reading = (Option<u8>, Vec<u8>);

/// Lowest tile first: it must start a run, or sit in a triplet or the pair. A hand holds at most
/// four sets, so longer splits (of suits over 14 tiles) do not count.
fn split(c: &mut [u8; 9], pair: Option<u8>, sets: &mut Vec<u8>, out: &mut BTreeSet<Reading>) {
    let Some(i) = c.iter().position(|&x| x > 0) else {
        let mut s = sets.clone();
        s.sort_unstable();
        out.insert((pair, s));
        return;
    };
    let room = sets.len() < 4;
    if room && c[i] >= 3 {
        c[i] -= 3;
        sets.push(7 + i as u8);
        split(c, pair, sets, out);
        sets.pop();
        c[i] += 3;
    }
    if room && i <= 6 && c[i + 1] > 0 && c[i + 2] > 0 {
        c[i..i + 3].iter_mut().for_each(|x| *x -= 1);
        sets.push(i as u8);
        split(c, pair, sets, out);
        sets.pop();
        c[i..i + 3].iter_mut().for_each(|x| *x += 1);
    }
    if pair.is_none() && c[i] >= 2 {
        c[i] -= 2;
        split(c, Some(i as u8), sets, out);
        c[i] += 2;
    }
}

fn table_readings(t: &Tables, code: usize) -> Vec<Reading> {
    t.decomps_of(code)
        .chunks_exact(2)
        .map(|d| {
            let pair = (d[0] & 15) as u8;
            let n = d[0] >> decomp::W0_NSETS_SHIFT & 7;
            let sets = (0..n)
                .map(|k| (d[0] >> (decomp::W0_SETS_SHIFT + 4 * k) & 15) as u8)
                .collect();
            ((pair != decomp::NO_PAIR as u8).then_some(pair), sets)
        })
        .collect()
}

/// The yaku word, recomputed from a reading and the suit's counts.
fn expected_word1(c: &[u8; 9], (pair, sets): &Reading) -> u32 {
    let mut w = 0;
    let mut mult = [0u32; 7];
    for &v in sets {
        if v < 7 {
            w |= 1 << v;
            mult[usize::from(v)] += 1;
        } else {
            w |= 1 << (7 + v - 7);
        }
    }
    w |= mult.iter().map(|m| m / 2).sum::<u32>() << 16;
    let end = |p: u8| p == 0 || p == 8;
    let outside = sets.iter().all(|&v| if v < 7 { v == 0 || v == 6 } else { end(v - 7) }) && pair.is_none_or(end);
    if outside {
        w |= 1 << 18;
    }
    let floor = [3, 1, 1, 1, 1, 1, 1, 1, 3];
    if c.iter().map(|&x| u32::from(x)).sum::<u32>() == 14 && c.iter().zip(floor).all(|(&x, f)| x >= f) {
        w |= 1 << 19;
    }
    w
}

#[test]
fn decompositions_match_brute_force_splitter() {
    let t = tables();
    let mut rng = Rng(3);
    let samples = sample_suits(&mut rng, SAMPLES);
    let mut complete = 0;
    for c in &samples {
        let code = suit_code(c);
        let mut want = BTreeSet::new();
        split(&mut c.clone(), None, &mut Vec::new(), &mut want);
        let got = table_readings(t, code);
        // Strictly increasing means sorted and free of duplicates.
        assert!(got.windows(2).all(|w| w[0] < w[1]), "{c:?}: {got:?} not sorted");
        for (_, sets) in &got {
            assert!(sets.windows(2).all(|w| w[0] <= w[1]), "{c:?}: sets unsorted");
        }
        assert_eq!(got, want.into_iter().collect::<Vec<_>>(), "{c:?}");
        for (d, r) in t.decomps_of(code).chunks_exact(2).zip(&got) {
            assert_eq!(d[1], expected_word1(c, r), "{c:?} {r:?}");
        }
        complete += usize::from(!got.is_empty());
    }
    // The sampler must really exercise complete suits.
    assert!(complete * 4 > samples.len(), "only {complete} complete samples");
}

#[test]
fn reference_completeness_statistics() {
    let t = tables();
    let complete = (0..SUIT_CODES).filter(|&c| !t.decomps_of(c).is_empty()).count();
    assert_eq!(complete, 21_743);

    // The reference's tuple: (pair, run-start mask, triplet mask, identical-run pairs, outside,
    // nine gates) is exactly (pair field, word 1), identical runs collapsing into one mask bit.
    let mut by_distinct = BTreeMap::<usize, usize>::new();
    for code in 0..SUIT_CODES {
        let tuples: BTreeSet<(u32, u32)> = t.decomps_of(code).chunks_exact(2).map(|d| (d[0] & 15, d[1])).collect();
        *by_distinct.entry(tuples.len()).or_default() += 1;
    }
    let at_least_two: usize = by_distinct.range(2..).map(|(_, n)| n).sum();
    assert_eq!(at_least_two, 1_568, "{by_distinct:?}");
    assert_eq!(by_distinct.get(&4), Some(&16), "{by_distinct:?}");
    assert_eq!(by_distinct.range(5..).count(), 0, "{by_distinct:?}");
}

/// The proof that one word per code is enough: on every code, D(0, 0) is 0, each set increment
/// D(m, 0) - D(m-1, 0) is in 0..=3 and each pair increment D(m, 1) - D(m, 0) in 0..=2, so the row
/// packs, decodes back to itself, and is exactly the table's word.
fn check_packing(rows: &[CostRow], word_of: impl Fn(usize) -> u32) {
    for (code, row) in rows.iter().enumerate() {
        assert_eq!(row[0], 0, "code {code}: D(0, 0) = {row:?}");
        for m in 0..5 {
            if m > 0 {
                let inc = i32::from(row[2 * m]) - i32::from(row[2 * m - 2]);
                assert!(
                    (0..=3).contains(&inc),
                    "code {code}: set increment {inc} at m = {m}: {row:?}"
                );
            }
            let inc = i32::from(row[2 * m + 1]) - i32::from(row[2 * m]);
            assert!(
                (0..=2).contains(&inc),
                "code {code}: pair increment {inc} at m = {m}: {row:?}"
            );
        }
        let word = pack_costs(row).expect("an in-range row packs");
        assert!(word < 1 << 18, "code {code}: {word:#x} uses more than 18 bits");
        assert_eq!(word, word_of(code) & pairs::COST_MASK, "code {code}: table word");
        for m in 0..5 {
            for h in 0..2 {
                assert_eq!(cost_d(word, m, h), u32::from(row[2 * m + h]), "code {code}: D({m},{h})");
            }
        }
    }
}

#[test]
fn cost_increments_fit_two_bits_for_every_code() {
    let t = tables();
    let suits = tables::suit_cost_rows();
    assert_eq!(suits.len(), SUIT_CODES);
    check_packing(&suits, |c| t.suit_cost_word(c));
    let honors = tables::honor_cost_rows();
    assert_eq!(honors.len(), HONOR_CODES);
    check_packing(&honors, |c| t.honor_cost_word(c));
    // Out-of-range rows are refused rather than wrapped.
    assert_eq!(pack_costs(&[0, 3, 4, 7, 8, 11, 12, 15, 16, 19]), None);
    assert_eq!(pack_costs(&[1, 3, 3, 5, 6, 8, 9, 11, 12, 14]), None);
    assert_eq!(
        pack_costs(&[0, 2, 3, 5, 6, 8, 9, 11, 12, 14]),
        Some(0b10_10_10_10_10_11_11_11_11)
    );
}

fn d_row(word: u32) -> [[u32; 5]; 2] {
    [0, 1].map(|h| [0, 1, 2, 3, 4].map(|m| cost_d(word, m, h)))
}

fn suit(tiles: &str) -> [u8; 9] {
    let mut c = [0u8; 9];
    for b in tiles.bytes() {
        c[usize::from(b - b'1')] += 1;
    }
    c
}

#[test]
fn hand_checked_values() {
    let t = tables();
    let row = |c: &[u8; 9]| d_row(t.suit_cost_word(suit_code(c)));
    assert_eq!(row(&[0; 9]), [[0, 3, 6, 9, 12], [2, 5, 8, 11, 14]]);
    assert_eq!(row(&suit("1")), [[0, 2, 5, 8, 11], [1, 4, 7, 10, 13]]);
    // Four 1s: a triplet and a pair of 1s would need five, so one of them is built elsewhere.
    assert_eq!(row(&suit("1111")), [[0, 0, 2, 5, 8], [0, 2, 4, 7, 10]]);
    assert_eq!(row(&suit("11123456789999"))[1][4], 0);
    // 111 234 567 999 leaves 8 and 9 unused.
    assert_eq!(row(&suit("11123456789999"))[0][4], 0);
    assert_eq!(row(&suit("147"))[0], [0, 2, 4, 6, 9]);
    assert_eq!(d_row(t.honor_cost_word(0)), [[0, 3, 6, 9, 12], [2, 5, 8, 11, 14]]);
    assert_eq!(
        d_row(t.honor_cost_word(honor_code(&[4, 0, 0, 0, 0, 0, 0]))),
        [[0, 0, 3, 6, 9], [0, 2, 5, 8, 11]]
    );
    assert_eq!(d_row(t.honor_cost_word(honor_code(&[3, 3, 3, 3, 2, 0, 0])))[1][4], 0);
    // Four singles grow into triplets (2 each) and a fifth into the pair (1).
    assert_eq!(d_row(t.honor_cost_word(honor_code(&[1, 1, 1, 1, 1, 1, 1])))[1][4], 9);

    assert_eq!(suit_code(&suit("123")), 5usize.pow(8) + 5usize.pow(7) + 5usize.pow(6));
    assert_eq!(suit_code(&suit("9")), 1);
    assert_eq!(honor_code(&[1, 0, 0, 0, 0, 0, 0]), 5usize.pow(6));

    let decomps = |s: &str| t.decomps_of(suit_code(&suit(s))).to_vec();
    assert_eq!(decomps(""), [decomp::NO_PAIR, decomp::W1_OUTSIDE_BIT]);
    assert_eq!(decomps("123"), [15 | 1 << 4, 1 | decomp::W1_OUTSIDE_BIT]);
    assert_eq!(decomps("99"), [8, decomp::W1_OUTSIDE_BIT]);
    assert_eq!(
        decomps("111222333"),
        [
            15 | 3 << 4,
            1 | 1 << 16 | decomp::W1_OUTSIDE_BIT,
            15 | 3 << 4 | 7 << 8 | 8 << 12 | 9 << 16,
            0b111 << 7,
        ]
    );
    let gates = decomps("11123456789999");
    assert!(!gates.is_empty());
    assert!(gates.chunks(2).all(|d| d[1] & decomp::W1_NINE_GATES_BIT != 0));
    let not_gates = decomps("11122233344455");
    assert!(!not_gates.is_empty());
    assert!(not_gates.chunks(2).all(|d| d[1] & decomp::W1_NINE_GATES_BIT == 0));
    assert!(decomps("1112345678999").is_empty());
    assert!(decomps("1").is_empty());
}

#[test]
fn layout_and_exports() {
    let t = tables();
    assert_eq!(t.suit_cost, 0);
    assert_eq!(t.honor_cost as usize, SUIT_CODES);
    assert_eq!(t.decomp_index as usize, SUIT_CODES + HONOR_CODES);
    assert_eq!(t.decomps as usize, t.decomp_index as usize + SUIT_CODES);
    let (s, h) = (t.suit_rows.len(), t.honor_rows.len());
    assert_eq!(t.suit_pairs as usize, t.decomps as usize + 2 * t.n_decomps as usize);
    let (sp, shp) = (t.suit_pair_rows.len(), t.suit_honor_pair_rows.len());
    assert_eq!(t.suit_honor_pairs as usize, t.suit_pairs as usize + s * s);
    assert_eq!(t.missing as usize, t.suit_honor_pairs as usize + s * h);
    assert_eq!(t.words.len(), t.missing as usize + sp * shp);
    assert_eq!(
        t.kernel_consts(),
        format!(
            "const T_SUIT_COST: u32 = 0u32;\nconst T_HONOR_COST: u32 = {}u32;\n\
             const T_DECOMP_INDEX: u32 = {}u32;\nconst T_DECOMPS: u32 = {}u32;\n\
             const T_SUIT_PAIRS: u32 = {}u32;\nconst T_SUIT_HONOR_PAIRS: u32 = {}u32;\n\
             const T_MISSING: u32 = {}u32;\n\
             const T_SUIT_ROWS: u32 = {s}u32;\nconst T_HONOR_ROWS: u32 = {h}u32;\n\
             const T_SUIT_PAIR_ROWS: u32 = {sp}u32;\nconst T_SUIT_HONOR_PAIR_ROWS: u32 = {shp}u32;\n\
             const T_ROW_SHIFT: u32 = 18u32;\nconst T_MISSING_BITS: u32 = 4u32;\n",
            t.honor_cost, t.decomp_index, t.decomps, t.suit_pairs, t.suit_honor_pairs, t.missing
        )
    );
    let bytes = t.to_le_bytes();
    assert_eq!(bytes.len(), 4 * t.words.len());
    assert_eq!(
        bytes[4 * t.decomps as usize..][..4],
        t.words[t.decomps as usize].to_le_bytes()
    );
    // Every decomposition is reachable from exactly one index entry, in order.
    let mut next = 0;
    for code in 0..SUIT_CODES {
        let e = t.words[t.decomp_index as usize + code];
        if e & 15 != 0 {
            assert_eq!(e >> 4, next, "code {code}");
            next += e & 15;
        }
    }
    assert_eq!(next, t.n_decomps);
}

/// D(m, h) of two groups taken as one, by brute force over the targets' splits between them:
/// the fewest tiles over every way to build `m1` of the sets and `h1` of the pairs in the first.
fn brute_combined(a: u32, b: u32, m: usize, h: usize) -> u32 {
    (0..=m)
        .flat_map(|m1| (0..=h).map(move |h1| (m1, h1)))
        .map(|(m1, h1)| cost_d(a, m1, h1) + cost_d(b, m - m1, h - h1))
        .min()
        .expect("at least one split")
}

/// Every cost word and every pair table word carries the number of its row among the distinct
/// rows of its kind, and the pair tables hold, for every two rows, the row of the two groups taken
/// as one.
#[test]
fn pair_tables_combine_every_two_rows() {
    let t = tables();
    // Few distinct rows: what makes a table of every pair small (its size is in the docs).
    assert_eq!((t.suit_rows.len(), t.honor_rows.len()), (126, 55));
    assert_eq!((t.suit_pair_rows.len(), t.suit_honor_pair_rows.len()), (180, 165));
    let (s, h) = (t.suit_rows.len(), t.honor_rows.len());
    for (rows, words) in [
        (
            &t.suit_rows,
            (0..SUIT_CODES).map(|c| t.suit_cost_word(c)).collect::<Vec<_>>(),
        ),
        (&t.honor_rows, (0..HONOR_CODES).map(|c| t.honor_cost_word(c)).collect()),
        (
            &t.suit_pair_rows,
            (0..s * s).map(|i| t.suit_pair_word(i / s, i % s)).collect(),
        ),
        (
            &t.suit_honor_pair_rows,
            (0..s * h).map(|i| t.suit_honor_pair_word(i / h, i % h)).collect(),
        ),
    ] {
        assert!(rows.windows(2).all(|w| w[0] < w[1]), "rows ascending and distinct");
        for (code, w) in words.iter().enumerate() {
            let n = (w >> pairs::ROW_SHIFT) as usize;
            assert_eq!(
                rows.get(n),
                Some(&(w & pairs::COST_MASK)),
                "code {code}: row number {n}"
            );
        }
    }
    let check = |a: u32, b: u32, word: u32| {
        for m in 0..5 {
            for h in 0..2 {
                assert_eq!(
                    cost_d(word, m, h),
                    brute_combined(a, b, m, h),
                    "rows {a:#x} and {b:#x}: D({m},{h})"
                );
            }
        }
    };
    for (i, &a) in t.suit_rows.iter().enumerate() {
        for (j, &b) in t.suit_rows.iter().enumerate() {
            check(a, b, t.suit_pair_word(i, j));
        }
        for (j, &b) in t.honor_rows.iter().enumerate() {
            check(a, b, t.suit_honor_pair_word(i, j));
        }
    }
    // By hand: an empty suit and the honors' 1-1-1 (three honor singles) need a set and the
    // pair from somewhere: two tiles turn two singles into a triplet, one more pairs the third.
    let empty = t.suit_cost_word(0) & pairs::COST_MASK;
    let singles = t.honor_cost_word(honor_code(&[1, 1, 1, 0, 0, 0, 0])) & pairs::COST_MASK;
    let (i, j) = (
        t.suit_rows.binary_search(&empty).expect("a row"),
        t.honor_rows.binary_search(&singles).expect("a row"),
    );
    assert_eq!(cost_d(t.suit_honor_pair_word(i, j), 1, 1), 3);
    assert_eq!(cost_d(t.suit_honor_pair_word(i, j), 0, 0), 0);
}

/// The `missing` table holds, for every combined suit row and combined suit-honor row, the tiles
/// the two miss together for each number of sets with the pair; and the whole chain the shanten
/// kernel reads (four cost words, two pair words, one `missing` word) gives the brute-force
/// combination of the four groups' rows on sampled hands.
#[test]
fn missing_table_combines_the_pair_rows() {
    let t = tables();
    let bits = pairs::MISSING_BITS as usize;
    for (i, &a) in t.suit_pair_rows.iter().enumerate() {
        for (j, &b) in t.suit_honor_pair_rows.iter().enumerate() {
            let word = t.missing_word(i, j);
            assert_eq!(word >> (5 * bits), 0, "rows {i} and {j}: bits above m = 4");
            for m in 0..5 {
                assert_eq!(
                    (word >> (bits * m)) as usize & ((1 << bits) - 1),
                    brute_combined(a, b, m, 1) as usize,
                    "rows {i} and {j}, {m} sets"
                );
            }
        }
    }
    let mut rng = Rng(17);
    let number = |w: u32| (w >> pairs::ROW_SHIFT) as usize;
    for _ in 0..SAMPLES {
        let codes: [usize; 4] = [
            rng.below(SUIT_CODES),
            rng.below(SUIT_CODES),
            rng.below(SUIT_CODES),
            rng.below(HONOR_CODES),
        ];
        let w = [
            t.suit_cost_word(codes[0]),
            t.suit_cost_word(codes[1]),
            t.suit_cost_word(codes[2]),
            t.honor_cost_word(codes[3]),
        ];
        let a = t.suit_pair_word(number(w[0]), number(w[1]));
        let b = t.suit_honor_pair_word(number(w[2]), number(w[3]));
        let word = t.missing_word(number(a), number(b));
        for m in 0..5 {
            // Every split of the sets and the pair among the four groups.
            let mut best = u32::MAX;
            for m0 in 0..=m {
                for m1 in 0..=m - m0 {
                    for m2 in 0..=m - m0 - m1 {
                        for pair in 0..4 {
                            let ms = [m0, m1, m2, m - m0 - m1 - m2];
                            let cost: u32 = (0..4).map(|g| cost_d(w[g], ms[g], usize::from(g == pair))).sum();
                            best = best.min(cost);
                        }
                    }
                }
            }
            assert_eq!(
                (word >> (bits * m)) & ((1 << bits) - 1),
                best,
                "codes {codes:?}, {m} sets"
            );
        }
    }
}

#[test]
fn region_hashes_are_pinned() {
    let got = tables().region_hashes();
    eprintln!("{got:#x?}");
    assert_eq!(
        got,
        [
            // The cost words carry their rows' numbers since the pair tables came.
            ("suit_cost", 0xfff5_422e_f38e_ab32),
            ("honor_cost", 0xbd85_c3bf_1d52_db13),
            ("decomp_index", 0x3c6c_3388_ab75_fba0),
            ("decomps", 0x473f_b73d_ba79_a3b0),
            // The pair tables' words carry their rows' numbers since the `missing` table came.
            ("suit_pairs", 0xb3d3_a91b_9935_4a50),
            ("suit_honor_pairs", 0x35b7_a55f_289c_9560),
            ("missing", 0xa7bf_b3e1_62b9_fa35),
        ]
    );
}
