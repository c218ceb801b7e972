//! rinshan-render: pictures of a game: the table decoded from a state ([`board`]), drawn as SVG
//! ([`svg`]) with three tile modes, rasterised to PNG with a bundled font ([`png`]), and a whole
//! logged game as one self-contained HTML replay page ([`html`]).
//!
//! Depends on `rinshan-engine` (states, tiles) and `rinshan-logs` (the logged games a replay page
//! shows); the web page (`rinshan-serve`), the `rinshan` command and the Python package use it.

#![warn(missing_docs)]

pub mod board;
pub mod html;
mod options;
pub mod png;
pub mod svg;
mod tiles;

pub use board::{Board, LastAction, Meld, MeldKind, RiverTile, RoundEndInput, RoundResult, WinLine};
pub use options::{Options, TileMode};
pub use svg::{round_name, sprite, svg};
pub use tiles::label as tile_label;
