//! The packed form on the host: where each planes row is in it, and unpacking a record into the
//! planes' bytes. Both read the kernel's `plane_row_binary` and `packed_index`
//! (rules/kernel/view_layout.rs), where the layout is declared.

use crate::generated::kernel as k;

/// Where a planes row is in the packed form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PackedRow {
    /// Row `i` of `bits` (a yes/no row, bit t = tile type t).
    Bits(u32),
    /// Row `i` of `counts` (one byte per tile type).
    Counts(u32),
}

/// Where planes row `row` (0..64) is in the packed form.
pub fn packed_row(row: u32) -> PackedRow {
    if k::plane_row_binary(row) {
        PackedRow::Bits(k::packed_index(row))
    } else {
        PackedRow::Counts(k::packed_index(row))
    }
}

/// The planes record ([`super::Form::Planes`] bytes) that a packed record
/// ([`super::Form::Packed`] bytes) stands for; `None` when `packed` is not one record.
pub fn unpack_planes(packed: &[u8]) -> Option<Vec<u8>> {
    if packed.len() != super::Form::Packed.bytes() {
        return None;
    }
    let counts_at = k::PACKED_BITS as usize * 8;
    let scalars_at = counts_at + k::PACKED_COUNTS as usize * 34;
    let plane_bytes = k::PLANE_ROWS as usize * 34;
    let mut planes = vec![0u8; super::Form::Planes.bytes()];
    for (row, cells) in planes[..plane_bytes].chunks_mut(34).enumerate() {
        match packed_row(row as u32) {
            PackedRow::Bits(i) => {
                let at = i as usize * 8;
                let set = u64::from_le_bytes(packed.get(at..at + 8)?.try_into().ok()?);
                for (t, cell) in cells.iter_mut().enumerate() {
                    *cell = ((set >> t) & 1) as u8;
                }
            }
            PackedRow::Counts(i) => {
                let at = counts_at + i as usize * 34;
                cells.copy_from_slice(packed.get(at..at + 34)?);
            }
        }
    }
    planes[plane_bytes..].copy_from_slice(packed.get(scalars_at..)?);
    Some(planes)
}
