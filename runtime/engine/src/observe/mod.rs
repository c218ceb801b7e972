//! What an agent sees: the observation forms written by the view kernel (`rules/kernel/view.rs`),
//! and the one table that documents every field (name, dtype, shape, meaning, scale). The CLI's
//! `observe --fields` and docs/observation.md are generated from it; bindings read it too.
//!
//! Every form is a fixed-size record of little-endian bytes; a field is a typed view at a byte
//! offset. Seats are ego-centric: 0 = the observer, 1 = its right (next to play), 2 = across,
//! 3 = left. Tiles are types 0..33 (1-9m, 1-9p, 1-9s, E S W N, white green red) or, where a
//! physical tile is named, values 0..36 with 34/35/36 = red 5m/5p/5s; -1 = none.

mod fields;
mod form;
mod hidden;
mod packed;
mod table_view;
mod text;

pub use fields::{
    Dtype, Field, Rows, Scalar, ANALYSIS_FIELDS, EVENT_KINDS, ORACLE_FIELDS, PACKED_FIELDS, PLANES_FIELDS, PLANE_ROWS,
    SCALARS, SEAT_ROWS, TOKENS_FIELDS,
};
pub(crate) use form::observe_cpu;
pub use form::{record, Form};
pub use hidden::{hidden_wall_places, resample_hidden, OwnDraws};
pub use packed::{packed_row, unpack_planes, PackedRow};
pub(crate) use table_view::TableView;
pub use text::{describe, field_values, fields_markdown};
