//! The suit tables built by `rinshan-codegen` at build time, embedded as little-endian words.
//! The kernels read them through the `table` intrinsic; the GPU backend uploads the same bytes.

#[repr(C, align(4))]
struct Aligned<T: ?Sized>(T);

static BYTES: &Aligned<[u8]> = &Aligned(*include_bytes!(concat!(env!("OUT_DIR"), "/tables.bin")));

/// The whole table region as bytes (for upload to a storage buffer).
pub fn bytes() -> &'static [u8] {
    &BYTES.0
}

/// The table intrinsic of the kernel subset: word `i` of the table region.
#[inline(always)]
pub fn table(i: u32) -> u32 {
    let o = i as usize * 4;
    let b = &BYTES.0[o..o + 4];
    u32::from_le_bytes([b[0], b[1], b[2], b[3]])
}
