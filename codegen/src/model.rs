//! The spec files as written, read with serde. Every table denies unknown keys so a typo is an
//! error with a location rather than a silently ignored rule. Values that later checks must point
//! at are `Spanned`. The checked, location-free form lives in `spec`.

use serde::Deserialize;
use serde_spanned::Spanned;
use std::collections::BTreeMap;

/// `rules/variants/<name>.toml`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VariantFile {
    pub variant: VariantSection,
    pub tiles: OptionTable,
    /// Free-form bool options that yaku conditions may name (e.g. `open_tanyao`); a variant may
    /// have none.
    #[serde(default)]
    pub yaku_rules: BTreeMap<Spanned<String>, Spanned<bool>>,
    pub scoring: OptionTable,
    pub claims: OptionTable,
    pub draws: OptionTable,
    pub liability: OptionTable,
    pub game: OptionTable,
    pub actions: ActionsSection,
}

/// A section of plain options, read as whatever values it holds so that a new option needs no
/// field here; `check::options` types them. The map is sorted by key; the key spans give the file
/// order.
pub type OptionTable = Spanned<BTreeMap<Spanned<String>, Spanned<toml::Value>>>;

impl VariantFile {
    /// The option sections with their names.
    pub fn option_sections(&self) -> [(&'static str, &OptionTable); 6] {
        [
            ("tiles", &self.tiles),
            ("scoring", &self.scoring),
            ("claims", &self.claims),
            ("draws", &self.draws),
            ("liability", &self.liability),
            ("game", &self.game),
        ]
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VariantSection {
    pub name: Spanned<String>,
    pub description: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActionsSection {
    pub num_actions: Spanned<u32>,
    pub layout: Spanned<Vec<Spanned<ActionBlockRaw>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActionBlockRaw {
    pub kind: Spanned<String>,
    pub count: Option<Spanned<u32>>,
}

/// `rules/yaku.toml`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct YakuFile {
    pub yaku: Vec<Spanned<YakuRaw>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct YakuRaw {
    pub name: Spanned<String>,
    // Signed so that `han_closed = -1` gets a range message, not a serde type message.
    pub han_closed: Option<Spanned<i64>>,
    pub han_open: Option<Spanned<i64>>,
    pub yakuman: Option<Spanned<i64>>,
    pub when: Spanned<String>,
    #[serde(default)]
    pub supersedes: Vec<Spanned<String>>,
    pub description: String,
}
