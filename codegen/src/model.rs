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
    pub tiles: TilesSection,
    /// Free-form bool options that yaku conditions may name (e.g. `open_tanyao`); a variant may
    /// have none.
    #[serde(default)]
    pub yaku_rules: BTreeMap<Spanned<String>, Spanned<bool>>,
    pub scoring: ScoringSection,
    pub claims: ClaimsSection,
    pub draws: DrawsSection,
    pub liability: LiabilitySection,
    pub game: GameSection,
    pub actions: ActionsSection,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VariantSection {
    pub name: Spanned<String>,
    pub description: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TilesSection {
    pub red_fives: Spanned<bool>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScoringSection {
    pub kiriage_mangan: bool,
    pub kazoe_yakuman: bool,
    pub multiple_yakuman: bool,
    pub double_yakuman: bool,
    pub honba_ron_points: u32,
    pub honba_tsumo_points: u32,
    pub riichi_stick_points: u32,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimsSection {
    pub double_ron: bool,
    pub triple_ron_abort: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DrawsSection {
    pub abortive_draws: Spanned<bool>,
    pub nagashi_mangan: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LiabilitySection {
    pub pao: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GameSection {
    pub starting_points: Spanned<u32>,
    pub riichi_min_points: u32,
    pub bust_below_zero: bool,
    pub target_points: u32,
    pub west_extension: bool,
    pub dealer_top_stop: bool,
    pub uma: Spanned<Vec<i32>>,
    pub illegal_action_penalty: Spanned<f64>,
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
