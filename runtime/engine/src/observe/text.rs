//! Observations as text for people: what `rinshan observe` prints and the golden snapshots pin.
//! Reads the record through the field table only, as any consumer would.

use std::fmt::Write as _;

use super::fields::{Dtype, Rows, EVENT_KINDS, PLANE_ROWS, SCALARS, SEAT_ROWS};
use super::form::Form;
use crate::generated::kernel as k;
use crate::{Tile, TileType};

const SEATS: [&str; 4] = ["self", "right", "across", "left"];

/// The elements of field `name` of a `form` record, widened to i64.
pub fn field_values(form: Form, record: &[u8], name: &str) -> Vec<i64> {
    let Some(f) = form.field(name) else {
        return Vec::new();
    };
    let Some(bytes) = record.get(f.offset..f.offset + f.len()) else {
        return Vec::new();
    };
    match f.dtype {
        Dtype::U8 => bytes.iter().map(|&b| i64::from(b)).collect(),
        Dtype::I8 => bytes.iter().map(|&b| i64::from(b as i8)).collect(),
        Dtype::I16 => bytes
            .chunks(2)
            .map(|c| i64::from(i16::from_le_bytes([c[0], c[1]])))
            .collect(),
        // Bit-rows use 34 bits: below i64's sign.
        Dtype::U64 => bytes
            .chunks(8)
            .map(|c| i64::from_le_bytes(c.try_into().unwrap_or([0; 8])))
            .collect(),
    }
}

/// [`field_values`] of a field of bytes or 16-bit values, as the text below reads them.
fn values(form: Form, record: &[u8], name: &str) -> Vec<i32> {
    field_values(form, record, name)
        .into_iter()
        .map(|v| i32::try_from(v).unwrap_or(i32::MAX))
        .collect()
}

fn type_name(t: usize) -> String {
    TileType::new(t as u8).map_or(format!("?{t}"), |t| t.name())
}

fn tile_name(v: i32) -> String {
    if v < 0 {
        return "-".into();
    }
    u8::try_from(v)
        .ok()
        .and_then(Tile::from_value)
        .map_or(format!("?{v}"), |t| t.name())
}

/// A value as printed: a flag as `yes`/`no`, anything else as its number.
fn value_text(v: i32, flag: bool) -> String {
    match (flag, v) {
        (true, 0) => "no".into(),
        (true, 1) => "yes".into(),
        _ => v.to_string(),
    }
}

fn scalars_text(out: &mut String, scalars: &[i32]) {
    for s in SCALARS {
        let i = s.index as usize;
        let vals: Vec<String> = scalars[i..i + s.count as usize]
            .iter()
            .map(|&v| value_text(v, s.flag))
            .collect();
        let _ = writeln!(out, "  {:<16} {}", s.name, vals.join(" "));
    }
}

/// A record of `form` as text: the nonzero plane rows (or the token fields) and the scalars.
pub fn describe(form: Form, record: &[u8]) -> String {
    let mut out = String::new();
    if record.len() != form.bytes() {
        return format!(
            "not a {form} record: {} bytes, a {form} record has {}\n",
            record.len(),
            form.bytes()
        );
    }
    match form {
        Form::Packed => {
            // Shown as the planes it unpacks to (the lengths were checked above).
            let planes = super::unpack_planes(record).unwrap_or_default();
            return describe(Form::Planes, &planes);
        }
        Form::Planes => {
            let planes = values(form, record, "planes");
            let mut names: Vec<(u32, String)> = PLANE_ROWS
                .iter()
                .flat_map(|r| {
                    (0..r.count).map(move |i| {
                        (
                            r.row + i,
                            if r.count == 1 {
                                r.name.to_string()
                            } else {
                                format!("{}{}", r.name, i + 1)
                            },
                        )
                    })
                })
                .collect();
            for seat in 0..4u32 {
                for r in SEAT_ROWS {
                    names.push((
                        k::P_SEAT + seat * k::P_SEAT_ROWS + r.row,
                        format!("{}.{}", SEATS[seat as usize], r.name),
                    ));
                }
            }
            names.sort();
            out.push_str("planes (nonzero cells):\n");
            for (row, name) in names {
                let cells: Vec<String> = (0..34)
                    .filter_map(|t| {
                        let v = planes[row as usize * 34 + t];
                        (v != 0).then(|| {
                            if v == 1 {
                                type_name(t)
                            } else {
                                format!("{}={v}", type_name(t))
                            }
                        })
                    })
                    .collect();
                if !cells.is_empty() {
                    let _ = writeln!(out, "  {row:>2} {name:<20} {}", cells.join(" "));
                }
            }
        }
        Form::Tokens => {
            let hand = values(form, record, "hand");
            let red = values(form, record, "hand_red");
            let mut tiles = Vec::new();
            for (t, &n) in hand.iter().enumerate() {
                let reds = if t < 27 && t % 9 == 4 { red[t / 9] } else { 0 };
                for i in 0..n {
                    tiles.push(if i < reds {
                        tile_name(34 + (t / 9) as i32)
                    } else {
                        type_name(t)
                    });
                }
            }
            let _ = writeln!(out, "hand: {}", tiles.join(" "));
            let one = |n: &str| values(form, record, n).first().copied().unwrap_or(-1);
            let _ = writeln!(
                out,
                "drawn: {}  target: {}",
                tile_name(one("drawn")),
                tile_name(one("target"))
            );
            let melds = values(form, record, "melds");
            let kinds = ["chi", "pon", "open kan", "closed kan", "added kan"];
            for seat in 0..4 {
                let list: Vec<String> = (0..4)
                    .filter_map(|i| {
                        let m = &melds[(seat * 4 + i) * 4..(seat * 4 + i) * 4 + 4];
                        (m[0] >= 0).then(|| {
                            // `from` is relative to the meld's owner.
                            let from = match m[3] {
                                1 => " from its right",
                                2 => " from across it",
                                3 => " from its left",
                                _ => "",
                            };
                            format!(
                                "{} {}{} (reds {})",
                                kinds.get(m[0] as usize).unwrap_or(&"?"),
                                type_name(m[1] as usize),
                                from,
                                m[2]
                            )
                        })
                    })
                    .collect();
                if !list.is_empty() {
                    let _ = writeln!(out, "melds of {}: {}", SEATS[seat], list.join(", "));
                }
            }
            let dora: Vec<String> = values(form, record, "dora_indicators")
                .into_iter()
                .filter(|&v| v >= 0)
                .map(tile_name)
                .collect();
            let _ = writeln!(out, "dora indicators: {}", dora.join(" "));
            let seen = values(form, record, "tiles_seen");
            let seen: Vec<String> = seen
                .iter()
                .enumerate()
                .filter(|(_, &n)| n > 0)
                .map(|(t, n)| format!("{}={n}", type_name(t)))
                .collect();
            let _ = writeln!(out, "tiles seen: {}", seen.join(" "));
            let events = values(form, record, "events");
            let n = one("events_len").max(0) as usize;
            out.push_str("events:\n");
            for e in events.chunks(4).take(n) {
                let kind = EVENT_KINDS.iter().find(|x| x.0 as i32 == e[0]).map_or("?", |x| x.1);
                let seat = SEATS.get(e[1] as usize).unwrap_or(&"?");
                let tile = if e[2] >= 0 {
                    format!(" {}", tile_name(e[2]))
                } else if e[0] == k::EV_DRAW as i32 {
                    " ?".into()
                } else {
                    String::new()
                };
                let flags = if e[3] != 0 {
                    format!(" [flags {}]", e[3])
                } else {
                    String::new()
                };
                let _ = writeln!(out, "  {seat:<6} {kind}{tile}{flags}");
            }
        }
        Form::Analysis | Form::Oracle => {
            for f in form.fields() {
                let vals = values(form, record, f.name);
                if f.shape.last() == Some(&34) {
                    for (r, row) in vals.chunks(34).enumerate() {
                        let cells: Vec<String> = row
                            .iter()
                            .enumerate()
                            .filter(|(_, &v)| v != 0)
                            .map(|(t, v)| format!("{}={v}", type_name(t)))
                            .collect();
                        let label = if f.shape.len() > 1 {
                            format!("{}[{r}]", f.name)
                        } else {
                            f.name.to_string()
                        };
                        let _ = writeln!(out, "{label}: {}", cells.join(" "));
                    }
                } else if matches!(f.name, "wall" | "rinshan" | "dora_indicators" | "ura_indicators") {
                    let tiles: Vec<String> = vals.iter().map(|&v| tile_name(v)).collect();
                    let _ = writeln!(out, "{}: {}", f.name, tiles.join(" "));
                } else {
                    let nums: Vec<String> = vals.iter().map(|&v| value_text(v, f.flag)).collect();
                    let _ = writeln!(out, "{}: {}", f.name, nums.join(" "));
                }
            }
            return out;
        }
    }
    out.push_str("scalars:\n");
    scalars_text(&mut out, &values(form, record, "scalars"));
    out
}

/// Markdown documenting every field of both forms: the page the README points to (also printed by
/// `rinshan observe --fields`).
pub fn fields_markdown() -> String {
    use std::fmt::Write as _;
    let mut md = String::from(
        "# Observation fields\n\nGenerated from `rinshan_engine::observe` (`rinshan observe --fields`); \
         a test keeps this page equal to it.\n\nSeats are ego-centric: 0 = the observer, 1 = right \
         (plays next), 2 = across, 3 = left. Tile types 0..33 are 1-9m, 1-9p, 1-9s, E S W N, \
         white green red; tile values 0..36 add red 5m/5p/5s as 34/35/36; -1 = none.\n",
    );
    for form in Form::ALL {
        let _ = write!(
            md,
            "\n## `{form}`: {} bytes\n\n| field | dtype | shape | byte offset | meaning |\n|---|---|---|---|---|\n",
            form.bytes()
        );
        for f in form.fields() {
            let _ = writeln!(
                md,
                "| `{}` | {} | {:?} | {} | {} |",
                f.name,
                f.dtype.name(),
                f.shape,
                f.offset,
                f.doc
            );
        }
    }
    md.push_str(
        "\n## Plane rows\n\nThe `packed` form holds each yes/no row as a row of `bits` and each other row as a row \
         of `counts`.\n\n| rows | name | max | packed | meaning |\n|---|---|---|---|---|\n",
    );
    let mut all: Vec<Rows> = PLANE_ROWS.to_vec();
    for seat in 0..4 {
        for r in SEAT_ROWS {
            all.push(Rows {
                row: k::P_SEAT + seat * k::P_SEAT_ROWS + r.row,
                ..r
            });
        }
    }
    all.sort_by_key(|r| r.row);
    let seat_name = ["self", "right", "across", "left"];
    for r in all {
        let rows = if r.count == 1 {
            r.row.to_string()
        } else {
            format!("{}-{}", r.row, r.row + r.count - 1)
        };
        let name = if r.row >= k::P_SEAT && r.row < k::P_SEAT + 4 * k::P_SEAT_ROWS {
            format!(
                "{}.{}",
                seat_name[((r.row - k::P_SEAT) / k::P_SEAT_ROWS) as usize],
                r.name
            )
        } else {
            r.name.to_string()
        };
        let packed: Vec<String> = (r.row..r.row + r.count)
            .map(|row| match super::packed_row(row) {
                super::PackedRow::Bits(i) => format!("bits[{i}]"),
                super::PackedRow::Counts(i) => format!("counts[{i}]"),
            })
            .collect();
        let _ = writeln!(
            md,
            "| {rows} | `{name}` | {} | {} | {} |",
            r.max,
            packed.join(", "),
            r.doc
        );
    }
    md.push_str("\n## Scalars\n\n| index | name | meaning |\n|---|---|---|\n");
    for s in SCALARS {
        let idx = if s.count == 1 {
            s.index.to_string()
        } else {
            format!("{}-{}", s.index, s.index + s.count - 1)
        };
        let _ = writeln!(md, "| {idx} | `{}` | {} |", s.name, s.doc);
    }
    md.push_str("\n## Event kinds (`events[:, 0]`)\n\n| kind | name | meaning |\n|---|---|---|\n");
    for (kind, name, doc) in EVENT_KINDS {
        let _ = writeln!(md, "| {kind} | `{name}` | {doc} |");
    }
    md
}
