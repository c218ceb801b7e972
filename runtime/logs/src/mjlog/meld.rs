//! The `m` code of an mjlog `N` tag: one 16-bit number for a call or a kan (the layout in
//! NegativeMjark/tenhou-log's "Meld Format" and <http://p.tenhou.net/img/mentsu136.txt>). Bits
//! 0-1 say where the tile came from ((discarder - caller) mod 4; 0 for a closed kan); bit 2 marks
//! a chi, bit 3 a pon, bit 4 an added kan, bit 5 a North set aside (three-player); none of them,
//! an open or closed kan. The high bits name the tiles.

/// Tile ids 0..135: type = id / 4, four copies each.
pub type TileId = u8;

/// A decoded meld, tiles as ids.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Meld {
    /// A sequence called from the seat before.
    Chi {
        /// The tile taken.
        called: TileId,
        /// The caller's two tiles, lower id first.
        own: [TileId; 2],
    },
    /// A triplet on another seat's discard.
    Pon {
        /// The tile taken.
        called: TileId,
        /// The caller's two tiles, lower id first.
        own: [TileId; 2],
        /// Seats from the caller to the discarder: 1 next, 2 across, 3 before.
        from: u8,
    },
    /// A tile added to a pon.
    AddedKan {
        /// The tile added.
        added: TileId,
        /// The pon's tile taken.
        called: TileId,
        /// The pon's own two tiles, lower id first.
        own: [TileId; 2],
        /// As the pon's.
        from: u8,
    },
    /// An open kan on a discard.
    OpenKan {
        /// The tile taken.
        called: TileId,
        /// The caller's three tiles, lower id first.
        own: [TileId; 3],
        /// As a pon's.
        from: u8,
    },
    /// A closed kan: the four copies.
    ClosedKan {
        /// Ids, lowest first.
        tiles: [TileId; 4],
    },
    /// Three-player's North set aside (nukidora).
    North {
        /// Its id.
        tile: TileId,
    },
}

/// Ids `kind * 4 + copy` for every copy in `copies`.
fn ids(kind: u16, copies: impl Iterator<Item = u16>) -> Vec<TileId> {
    copies.map(|c| (kind * 4 + c) as TileId).collect()
}

/// Decodes a meld code; `None` when it names no tile (a type past the 34th).
pub fn decode(m: u16) -> Option<Meld> {
    let from = (m & 3) as u8;
    if m & 0x4 != 0 {
        let t = m >> 10;
        let (called, base) = (t % 3, t / 3);
        let low = (base / 7) * 9 + base % 7;
        if base >= 21 {
            return None;
        }
        let tiles: Vec<TileId> = (0..3)
            .map(|i| ((low + i) * 4 + ((m >> (3 + 2 * i)) & 3)) as TileId)
            .collect();
        let own: Vec<TileId> = (0..3).filter(|&i| i != called).map(|i| tiles[usize::from(i)]).collect();
        return Some(Meld::Chi {
            called: tiles[usize::from(called)],
            own: [own[0], own[1]],
        });
    }
    if m & 0x18 != 0 {
        let t = m >> 9;
        let (called, kind) = (t % 3, t / 3);
        if kind >= 34 {
            return None;
        }
        let other = (m >> 5) & 3;
        let three = ids(kind, (0..4).filter(|&c| c != other));
        let own: Vec<TileId> = (0..3).filter(|&i| i != called).map(|i| three[usize::from(i)]).collect();
        let (called, own) = (three[usize::from(called)], [own[0], own[1]]);
        return Some(if m & 0x8 != 0 {
            Meld::Pon { called, own, from }
        } else {
            Meld::AddedKan {
                added: (kind * 4 + other) as TileId,
                called,
                own,
                from,
            }
        });
    }
    if m & 0x20 != 0 {
        let tile = m >> 8;
        return (tile < 136).then_some(Meld::North { tile: tile as TileId });
    }
    let called = m >> 8;
    if called >= 136 {
        return None;
    }
    let all = ids(called / 4, 0..4);
    if from == 0 {
        return Some(Meld::ClosedKan {
            tiles: [all[0], all[1], all[2], all[3]],
        });
    }
    let own: Vec<TileId> = all.into_iter().filter(|&id| u16::from(id) != called).collect();
    Some(Meld::OpenKan {
        called: called as TileId,
        own: [own[0], own[1], own[2]],
        from,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The worked codes of the format notes (NegativeMjark/tenhou-log, mjx-convert's doctests),
    /// with the copies worked out by hand from the bit layout. Every meld of the real logs in
    /// tests/data/mjlog is checked against its tenhou.net/6 twin in `mjlog::tests`.
    #[test]
    fn documented_codes_decode() {
        let cases: [(u16, Meld); 5] = [
            // Chi from the seat before: 3s 4s 5s (ids 82, 86, 90), the 3s taken.
            (
                49495,
                Meld::Chi {
                    called: 82,
                    own: [86, 90],
                },
            ),
            // Pon of the red dragon (type 33) from across; copy 3 is left out, the second of the
            // remaining three taken.
            (
                51306,
                Meld::Pon {
                    called: 133,
                    own: [132, 134],
                    from: 2,
                },
            ),
            // Added kan of 1s (type 18) on a pon from across; copy 1 (id 73) added, the pon's
            // third remaining copy (75) the one taken.
            (
                28722,
                Meld::AddedKan {
                    added: 73,
                    called: 75,
                    own: [72, 74],
                    from: 2,
                },
            ),
            // Closed kan of the white dragon (type 31).
            (
                31744,
                Meld::ClosedKan {
                    tiles: [124, 125, 126, 127],
                },
            ),
            // Open kan of 9s (type 26, id 106) from the seat before.
            (
                27139,
                Meld::OpenKan {
                    called: 106,
                    own: [104, 105, 107],
                    from: 3,
                },
            ),
        ];
        for (code, meld) in cases {
            assert_eq!(decode(code), Some(meld), "m={code}");
        }
    }

    #[test]
    fn codes_past_the_last_tile_are_refused() {
        // A chi whose lowest tile would be past 7s, a pon or kan of a 35th type.
        assert_eq!(decode(63 << 10 | 0x4 | 3), None);
        assert_eq!(decode(102 << 9 | 0x8 | 1), None);
        assert_eq!(decode(136 << 8 | 1), None);
        for code in 0..=u16::MAX {
            let _ = decode(code);
        }
    }
}
