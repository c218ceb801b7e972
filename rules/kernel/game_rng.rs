// Randomness: ChaCha8 (Bernstein's ChaCha with 8 rounds, in his layout: a 64-bit block counter
// and a 64-bit stream id, as the rand_chacha crate's ChaCha8Rng) keyed by the game's whole 64-bit
// seed and what the numbers are for (the wall, the first dealer, an agent's choice); the stream id
// says where (the game, then the round or the step). The n-th word of a stream is a pure function
// of (seed, purpose, stream, n), so the CPU and the GPU draw the same walls whatever the batch
// layout, and nobody who sees some of a game's tiles can work out the rest without searching the
// 2^64 seeds.

pub const RNG_WALL: u32 = 1;
pub const RNG_DEALER: u32 = 2;
pub const RNG_AGENT: u32 = 3;

// One stream: its key (the seed and the purpose), its id, and the block of 16 words being read.
pub struct Rng {
    pub seed: [u32; 2],
    pub purpose: u32,
    pub stream: [u32; 2],
    pub block: u32,
    pub words: [u32; 16],
    pub next: u32,
}

fn rotl(x: u32, n: u32) -> u32 {
    (x << n) | (x >> (32u32 - n))
}

fn quarter_round(x: &mut [u32; 16], a: u32, b: u32, c: u32, d: u32) {
    x[a as usize] = x[a as usize].wrapping_add(x[b as usize]);
    x[d as usize] = rotl(x[d as usize] ^ x[a as usize], 16u32);
    x[c as usize] = x[c as usize].wrapping_add(x[d as usize]);
    x[b as usize] = rotl(x[b as usize] ^ x[c as usize], 12u32);
    x[a as usize] = x[a as usize].wrapping_add(x[b as usize]);
    x[d as usize] = rotl(x[d as usize] ^ x[a as usize], 8u32);
    x[c as usize] = x[c as usize].wrapping_add(x[d as usize]);
    x[b as usize] = rotl(x[b as usize] ^ x[c as usize], 7u32);
}

// The block `counter` of a stream: "expand 32-byte k", the 256-bit key (the seed, the purpose,
// then zeros), the 64-bit counter, the 64-bit stream id; 8 rounds; the input added back.
pub fn chacha8_block(seed: [u32; 2], purpose: u32, stream: [u32; 2], counter: u32) -> [u32; 16] {
    let input: [u32; 16] = [
        0x61707865u32, 0x3320646eu32, 0x79622d32u32, 0x6b206574u32,
        seed[0], seed[1], purpose, 0u32, 0u32, 0u32, 0u32, 0u32,
        counter, 0u32, stream[0], stream[1],
    ];
    let mut x: [u32; 16] = input;
    for _round in 0u32..4u32 {
        quarter_round(&mut x, 0u32, 4u32, 8u32, 12u32);
        quarter_round(&mut x, 1u32, 5u32, 9u32, 13u32);
        quarter_round(&mut x, 2u32, 6u32, 10u32, 14u32);
        quarter_round(&mut x, 3u32, 7u32, 11u32, 15u32);
        quarter_round(&mut x, 0u32, 5u32, 10u32, 15u32);
        quarter_round(&mut x, 1u32, 6u32, 11u32, 12u32);
        quarter_round(&mut x, 2u32, 7u32, 8u32, 13u32);
        quarter_round(&mut x, 3u32, 4u32, 9u32, 14u32);
    }
    for i in 0u32..16u32 {
        x[i as usize] = x[i as usize].wrapping_add(input[i as usize]);
    }
    x
}

// The stream of `purpose` (RNG_*) at (a, b): for a wall the game and the round, for an agent the
// step.
pub fn rng_new(seed: [u32; 2], purpose: u32, a: u32, b: u32) -> Rng {
    let stream: [u32; 2] = [a, b];
    Rng {
        seed: seed,
        purpose: purpose,
        stream: stream,
        block: 0u32,
        words: chacha8_block(seed, purpose, stream, 0u32),
        next: 0u32,
    }
}

pub fn rng_word(r: &mut Rng) -> u32 {
    if r.next == 16u32 {
        r.block += 1u32;
        r.words = chacha8_block(r.seed, r.purpose, r.stream, r.block);
        r.next = 0u32;
    }
    let w: u32 = r.words[r.next as usize];
    r.next += 1u32;
    w
}

// The 64-bit product of two words as [high, low], from 16-bit halves (no u64 in the kernel).
pub fn mul_wide(a: u32, b: u32) -> [u32; 2] {
    let a0: u32 = a & 0xffffu32;
    let a1: u32 = a >> 16u32;
    let b0: u32 = b & 0xffffu32;
    let b1: u32 = b >> 16u32;
    let ll: u32 = a0 * b0;
    let lh: u32 = a0 * b1;
    let hl: u32 = a1 * b0;
    let mid: u32 = (ll >> 16u32) + (lh & 0xffffu32) + (hl & 0xffffu32);
    let high: u32 = a1 * b1 + (lh >> 16u32) + (hl >> 16u32) + (mid >> 16u32);
    [high, (mid << 16u32) | (ll & 0xffffu32)]
}

// Uniform in 0..bound (bound > 0) without bias, by Lemire's multiply-and-shift: the high word of
// word * bound, rejecting the few words whose low word falls below `2^32 mod bound`; the division
// that finds that threshold runs only when a low word is below `bound` (about bound / 2^32 of the
// draws).
pub fn random_below(r: &mut Rng, bound: u32) -> u32 {
    let mut m: [u32; 2] = mul_wide(rng_word(r), bound);
    if m[1] < bound {
        let threshold: u32 = (0u32.wrapping_sub(bound)) % bound;
        while m[1] < threshold {
            m = mul_wide(rng_word(r), bound);
        }
    }
    m[0]
}

// The k-th (from 0) legal action of a mask that has more than k: the word by its bit counts, then
// the bit by a binary search over the word's halves, quarters and so on. No branch on k, which is
// random: a loop over the actions (or the bits) ends at a random place, and its exit was
// mispredicted on most calls. The host's random policy (`Rng::pick_legal`) uses it too.
pub fn nth_legal(mask: [u32; 3], k: u32) -> u32 {
    let c0: u32 = mask[0].count_ones();
    let c1: u32 = mask[1].count_ones();
    let in1: u32 = (k >= c0) as u32;
    let in2: u32 = (k >= c0 + c1) as u32;
    let i: u32 = in1 + in2;
    let mut w: u32 = mask[i as usize];
    let mut left: u32 = k - c0 * in1 - c1 * in2;
    let mut at: u32 = 0u32;
    for step in 0u32..5u32 {
        let width: u32 = 16u32 >> step;
        let low: u32 = (w & ((1u32 << width) - 1u32)).count_ones();
        let up: u32 = (left >= low) as u32;
        left -= low * up;
        w = w >> (width * up);
        at += width * up;
    }
    i * 32u32 + at
}
