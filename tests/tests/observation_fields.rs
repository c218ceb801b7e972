//! The observation's field table is the one description of every field: it covers each record
//! exactly (fields in bounds, not overlapping; plane rows and scalars each described once) and
//! docs/observation.md is the page it generates. The packed form holds every plane row once: the
//! yes/no ones (documented largest value 1) as bits, the others as bytes.

use rinshan_engine::generated::kernel as k;
use rinshan_engine::observe::{fields_markdown, packed_row, Form, PackedRow, PLANE_ROWS, SCALARS, SEAT_ROWS};

#[test]
fn fields_lie_inside_their_record_without_overlapping() {
    for form in Form::ALL {
        let mut spans: Vec<(usize, usize, &str)> = form
            .fields()
            .iter()
            .map(|f| (f.offset, f.offset + f.len(), f.name))
            .collect();
        spans.sort();
        for w in spans.windows(2) {
            assert!(w[0].1 <= w[1].0, "{form}: `{}` overlaps `{}`", w[0].2, w[1].2);
        }
        let last = spans.last().expect("fields");
        assert!(
            last.1 <= form.bytes(),
            "{form}: `{}` ends at byte {} of {}",
            last.2,
            last.1,
            form.bytes()
        );
        // Padding is at most what word alignment needs between fields.
        let used: usize = spans.iter().map(|s| s.1 - s.0).sum();
        assert!(
            form.bytes() - used < 4 * spans.len(),
            "{form}: {} of {} bytes unused",
            form.bytes() - used,
            form.bytes()
        );
    }
}

#[test]
fn every_plane_row_and_scalar_is_described_once() {
    let mut rows = vec![0u32; k::PLANE_ROWS as usize];
    for r in PLANE_ROWS {
        for i in 0..r.count {
            rows[(r.row + i) as usize] += 1;
        }
    }
    for seat in 0..4 {
        for r in SEAT_ROWS {
            rows[(k::P_SEAT + seat * k::P_SEAT_ROWS + r.row) as usize] += 1;
        }
    }
    assert!(rows.iter().all(|&n| n == 1), "rows described {rows:?} times");
    assert_eq!(SEAT_ROWS.len() as u32, k::P_SEAT_ROWS);
    let mut scalars = vec![0u32; k::SCALARS as usize];
    for s in SCALARS {
        for i in 0..s.count {
            scalars[(s.index + i) as usize] += 1;
        }
    }
    assert!(scalars.iter().all(|&n| n == 1), "scalars described {scalars:?} times");
}

#[test]
fn packed_rows_hold_each_plane_row_once_yes_no_rows_as_bits() {
    let mut maxima = vec![0u32; k::PLANE_ROWS as usize];
    for r in PLANE_ROWS {
        for i in 0..r.count {
            maxima[(r.row + i) as usize] = r.max;
        }
    }
    for seat in 0..4 {
        for r in SEAT_ROWS {
            maxima[(k::P_SEAT + seat * k::P_SEAT_ROWS + r.row) as usize] = r.max;
        }
    }
    let mut bits = vec![None; k::PACKED_BITS as usize];
    let mut counts = vec![None; k::PACKED_COUNTS as usize];
    for (row, &max) in maxima.iter().enumerate() {
        let row = row as u32;
        let (slots, i) = match packed_row(row) {
            PackedRow::Bits(i) => {
                assert_eq!(max, 1, "row {row} (largest value {max}) packed as bits");
                (&mut bits, i)
            }
            PackedRow::Counts(i) => {
                assert!(max > 1, "row {row} (yes/no) packed as bytes");
                (&mut counts, i)
            }
        };
        let slot = slots
            .get_mut(i as usize)
            .unwrap_or_else(|| panic!("row {row} packed at {i}, past the end"));
        assert_eq!(*slot, None, "row {row} packed where row {slot:?} is");
        *slot = Some(row);
    }
    assert!(bits.iter().all(Option::is_some), "bit-rows unused: {bits:?}");
    assert!(counts.iter().all(Option::is_some), "count rows unused: {counts:?}");
}

#[test]
fn docs_observation_md_is_the_generated_reference() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/observation.md");
    let page = std::fs::read_to_string(&path).expect("docs/observation.md");
    assert!(
        page == fields_markdown(),
        "docs/observation.md differs from `rinshan observe --fields`: regenerate it with\n  cargo run --release -- observe --fields > docs/observation.md"
    );
}
