// Tile vocabulary shared by every kernel. Tile types 0..33: 0-8 man 1-9, 9-17 pin 1-9, 18-26 sou 1-9,
// 27-30 winds E S W N, 31-33 dragons white green red.

const N_TYPES: u32 = 34;
const FIRST_HONOR: u32 = 27;
const FIRST_DRAGON: u32 = 31;
const EAST: u32 = 27;
const NORTH: u32 = 30;

fn is_honor(t: u32) -> bool {
    t >= FIRST_HONOR
}

// Without short-circuits: on a random tile each `||` was a branch the CPU mispredicted.
fn is_terminal_or_honor(t: u32) -> bool {
    let r: u32 = t % 9u32;
    ((t >= FIRST_HONOR) as u32 | (r == 0u32) as u32 | (r == 8u32) as u32) != 0u32
}

fn is_dragon(t: u32) -> bool {
    t >= FIRST_DRAGON
}

fn is_wind(t: u32) -> bool {
    t >= FIRST_HONOR && t < FIRST_DRAGON
}

// 2s 3s 4s 6s 8s and the green dragon: the only tiles ryuuiisou admits.
fn is_green(t: u32) -> bool {
    t == 19u32 || t == 20u32 || t == 21u32 || t == 23u32 || t == 25u32 || t == 32u32
}


// Base-5 code of one suit's nine counts, 1 as the most significant digit (the tables' key).
fn suit_code(counts: [u32; 34], suit: u32) -> u32 {
    let mut code: u32 = 0u32;
    for i in 0u32..9u32 {
        code = code * 5u32 + counts[(suit * 9u32 + i) as usize];
    }
    code
}

fn honor_code(counts: [u32; 34]) -> u32 {
    let mut code: u32 = 0u32;
    for i in 0u32..7u32 {
        code = code * 5u32 + counts[(FIRST_HONOR + i) as usize];
    }
    code
}
