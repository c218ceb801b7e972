//! Seeds of the envs' games, derived from the configured seed.

/// splitmix64's finalizer.
pub(super) fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The 64-bit seed of env `index` at the `epoch`-th [`Env::reset`](crate::env::Env::reset) of an env seeded with `seed`.
pub fn env_seed(seed: u64, index: u64, epoch: u64) -> u64 {
    let a = mix64(seed.wrapping_add(0x9E37_79B9_7F4A_7C15));
    let b = mix64(a ^ index.wrapping_mul(0xD6E8_FEB8_6659_FD93));
    mix64(b ^ epoch.wrapping_mul(0xA076_1D64_78BD_642F).wrapping_add(1))
}
