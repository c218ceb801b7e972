// Rows of 34 cells four to a word, as the planes hold them (byte t of a row is tile type t): packing
// a row's cells into words, aligning them to where the row starts, and writing them. The writers
// of rules/kernel/view.rs and view_packed.rs write every row they fill a word at a time through
// these; the host writes its seat blocks' yes/no rows through `set_cells`.

// Four bits to the low bit of four bytes (the shifted copies of `n` do not overlap, so no carry).
fn spread4(n: u32) -> u32 {
    ((n & 15u32) * 0x204081u32) & 0x01010101u32
}

// The cells of a row (each below 256) four to a word: word j holds types 4j..4j+3, the last word
// types 32 and 33. Writing a row a word at a time instead of a byte at a time.
fn pack_cells(v: [u32; 34]) -> [u32; 9] {
    let mut p: [u32; 9] = [0u32; 9];
    for j in 0u32..8u32 {
        let i: u32 = j * 4u32;
        p[j as usize] = v[i as usize]
            | (v[(i + 1u32) as usize] << 8u32)
            | (v[(i + 2u32) as usize] << 16u32)
            | (v[(i + 3u32) as usize] << 24u32);
    }
    p[8] = v[32] | (v[33] << 8u32);
    p
}

// Cell `t` of packed cells.
fn cell_of(p: [u32; 9], t: u32) -> u32 {
    (p[(t / 4u32) as usize] >> ((t % 4u32) * 8u32)) & 255u32
}

// One in cell `t` of packed cells, in its word (t / 4).
fn cell_one(t: u32) -> u32 {
    1u32 << ((t % 4u32) * 8u32)
}

// Packed cells each capped at 4, whatever their values: a byte's top bit is set first when it is
// 128 or more, or when its low seven bits minus 5 do not borrow (each byte is at least 128 once
// or-ed with it, so no borrow crosses a byte).
fn cells_at_most_4(x: u32) -> u32 {
    let over: u32 = ((((x | 0x80808080u32) - 0x05050505u32) | x) & 0x80808080u32) >> 7u32;
    let m: u32 = over * 255u32;
    (x & !m) | (0x04040404u32 & m)
}

// The low 16 bits' four nibbles, each to the low nibble of a byte.
fn nibbles_to_cells(x: u32) -> u32 {
    let a: u32 = (x | (x << 8u32)) & 0x00ff00ffu32;
    (a | (a << 4u32)) & 0x0f0f0f0fu32
}

// The seat's concealed counts as packed cells, straight from the hand's words (4 bits per type,
// 8 types a word): `pack_cells(hand_counts(s, seat))` without the 34 counts between.
fn hand_cells(s: &mut GameState, seat: u32) -> [u32; 9] {
    let mut p: [u32; 9] = [0u32; 9];
    for w in 0u32..4u32 {
        let word: u32 = s.hands[(seat * 5u32 + w) as usize];
        p[(w * 2u32) as usize] = nibbles_to_cells(word & 0xffffu32);
        p[(w * 2u32 + 1u32) as usize] = nibbles_to_cells(word >> 16u32);
    }
    p[8] = nibbles_to_cells(s.hands[(seat * 5u32 + 4u32) as usize] & 0xffu32);
    p
}

// Packed cells (`pack_cells`) as the nine words row `row` spans from its first word: 34 = 8 * 4 + 2,
// so even rows start on a word boundary and odd rows half-way into one.
fn at_row(p: [u32; 9], row: u32) -> [u32; 9] {
    if (row & 1u32) == 0u32 {
        return p;
    }
    let mut q: [u32; 9] = [0u32; 9];
    q[0] = p[0] << 16u32;
    for j in 1u32..9u32 {
        q[j as usize] = (p[(j - 1u32) as usize] >> 16u32) | (p[j as usize] << 16u32);
    }
    q
}

// Packed cells of at most 4 each, as 1 where the cell is above `k` and 0 elsewhere: adding 127 - k
// to a byte sets its top bit exactly then, and no byte carries into the next.
fn cells_above(p: [u32; 9], k: u32) -> [u32; 9] {
    let mut q: [u32; 9] = [0u32; 9];
    for j in 0u32..9u32 {
        q[j as usize] = ((p[j as usize] + (127u32 - k) * 0x01010101u32) >> 7u32) & 0x01010101u32;
    }
    q
}

// Writes packed cells into row `row` of zeroed planes.
fn put_row(o: &mut ObsPlanes, row: u32, p: [u32; 9]) {
    let w: u32 = row * 34u32 / 4u32;
    let q: [u32; 9] = at_row(p, row);
    for j in 0u32..9u32 {
        o.planes[(w + j) as usize] |= q[j as usize];
    }
}

// The cells of a yes/no row as packed cells: 1 where the type is in `set` (34 bits), 0 elsewhere.
// `pub`: the host writes the seat blocks' yes/no rows it keeps with it.
pub fn set_cells(set: [u32; 2]) -> [u32; 9] {
    let mut p: [u32; 9] = [0u32; 9];
    for j in 0u32..8u32 {
        p[j as usize] = spread4(set[0] >> (j * 4u32));
    }
    p[8] = spread4(set[1] & 3u32);
    p
}

// Sets the cells of row `row` whose types are in `set` (34 bits) to 1, four cells a word.
// The rows are zeroed, so an empty set (most waits and kan rows) writes nothing.
fn put_set(o: &mut ObsPlanes, row: u32, set: [u32; 2]) {
    if (set[0] | set[1]) != 0u32 {
        put_row(o, row, set_cells(set));
    }
}
