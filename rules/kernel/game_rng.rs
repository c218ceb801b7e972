// Counter-based randomness on 32-bit words: the n-th number of a stream is a pure function of
// (seed, stream, n), so the CPU and the GPU draw the same walls whatever the batch layout.

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32" constants).
fn mix32(x0: u32) -> u32 {
    let mut x: u32 = x0;
    x ^= x >> 16u32;
    x = x.wrapping_mul(0x7feb352du32);
    x ^= x >> 15u32;
    x = x.wrapping_mul(0x846ca68bu32);
    x ^= x >> 16u32;
    x
}

fn random_word(seed: [u32; 2], stream: u32, n: u32) -> u32 {
    mix32(mix32(mix32(seed[0] ^ 0x9e3779b9u32) ^ seed[1]) ^ mix32(stream.wrapping_mul(0x85ebca6bu32) ^ n))
}

// Uniform in 0..bound (bound > 0) without modulo bias: reject the low `2^32 mod bound` values.
fn random_below(seed: [u32; 2], stream: u32, counter: &mut u32, bound: u32) -> u32 {
    let threshold: u32 = (0u32.wrapping_sub(bound)) % bound;
    let mut r: u32 = random_word(seed, stream, *counter);
    *counter += 1u32;
    while r < threshold {
        r = random_word(seed, stream, *counter);
        *counter += 1u32;
    }
    r % bound
}
