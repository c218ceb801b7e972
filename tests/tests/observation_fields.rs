//! The observation's field table is the one description of every field: it covers each record
//! exactly (fields in bounds, not overlapping; plane rows and scalars each described once) and
//! docs/observation.md is the page it generates.

use rinshan_engine::generated::kernel as k;
use rinshan_engine::observe::{fields_markdown, Form, PLANE_ROWS, SCALARS, SEAT_ROWS};

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
fn docs_observation_md_is_the_generated_reference() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/observation.md");
    let page = std::fs::read_to_string(&path).expect("docs/observation.md");
    assert!(
        page == fields_markdown(),
        "docs/observation.md differs from `rinshan observe --fields`: regenerate it with\n  cargo run --release -- observe --fields > docs/observation.md"
    );
}
