//! How a picture is drawn: the tile mode, the seat at the bottom, what is face up.

/// How tiles are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TileMode {
    /// The traditional faces.
    Ja,
    /// The faces with a Latin label in the corner (`5m`, `E`, `Rd`; red fives marked).
    En,
    /// The labels alone.
    Ascii,
}

impl TileMode {
    /// Every mode.
    pub const ALL: [TileMode; 3] = [TileMode::Ja, TileMode::En, TileMode::Ascii];

    /// The name users write: `ja`, `en` or `ascii`.
    pub fn name(self) -> &'static str {
        match self {
            TileMode::Ja => "ja",
            TileMode::En => "en",
            TileMode::Ascii => "ascii",
        }
    }
}

impl std::fmt::Display for TileMode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for TileMode {
    type Err = rinshan_engine::UnknownName;

    fn from_str(name: &str) -> Result<TileMode, rinshan_engine::UnknownName> {
        rinshan_engine::UnknownName::find("tile mode", name, &TileMode::ALL)
    }
}

/// How a board is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Options {
    /// The tile mode.
    pub tiles: TileMode,
    /// The seat drawn at the bottom, whose hand is face up.
    pub pov: u32,
    /// Show every hand face up.
    pub reveal: bool,
    /// Put the faces used in the document's own `<defs>` (a standalone file); `false` for boards
    /// shown in a page that carries [`sprite`](crate::sprite) once.
    pub defs: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            tiles: TileMode::En,
            pov: 0,
            reveal: false,
            defs: true,
        }
    }
}
