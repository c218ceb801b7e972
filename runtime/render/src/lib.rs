//! rinshan-render: pictures of a game: the table decoded from a state ([`board`]), drawn as SVG
//! ([`svg`](mod@svg)) with three tile modes, rasterised to PNG with a bundled font ([`png`]), and a whole
//! logged game as one self-contained HTML replay page ([`html`]).
//!
//! Depends on `rinshan-engine` (states, tiles) and `rinshan-logs` (the logged games a replay page
//! shows); the web page (`rinshan-serve`), the `rinshan` command and the Python package use it.
//!
//! A freshly dealt table drawn from seat 0's side, its hand face up:
//!
//! ```
//! use rinshan_engine::env::{Config, Env};
//! use rinshan_engine::Variant;
//! use rinshan_render::{svg, Board, Options};
//!
//! let mut env = Env::new(Config::new(Variant::Red, 1))?;
//! env.reset()?;
//! let state = &env.game_states()?[0];
//! let picture = svg(&Board::from_state(state, Variant::Red), &Options::default());
//! assert!(picture.starts_with("<svg") && picture.ends_with("</svg>"));
//! # Ok::<(), rinshan_engine::env::EnvError>(())
//! ```

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
