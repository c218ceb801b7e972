//! The checked spec: what the emitters read. Built only by `check`, so holding a [`Spec`] means
//! every rule in the files passed the checker.

use crate::expr::{Expr, Type};

/// Action kinds the kernel knows, in the reference order. `count` is the block size, except for
/// `discard`, whose size follows `red_fives` (34 tile types, plus 3 red fives).
pub const ACTION_KINDS: [ActionKindInfo; 18] = [
    ActionKindInfo::new("discard", 34, Need::Always),
    ActionKindInfo::new("self_kan", 34, Need::Always),
    ActionKindInfo::new("tsumogiri", 1, Need::Always),
    ActionKindInfo::new("riichi", 1, Need::Always),
    ActionKindInfo::new("tsumo", 1, Need::Always),
    ActionKindInfo::new("ron", 1, Need::Always),
    ActionKindInfo::new("pon", 1, Need::Always),
    ActionKindInfo::new("pon_red", 1, Need::RedFives),
    ActionKindInfo::new("open_kan", 1, Need::Always),
    ActionKindInfo::new("chi_left", 1, Need::Always),
    ActionKindInfo::new("chi_left_red", 1, Need::RedFives),
    ActionKindInfo::new("chi_middle", 1, Need::Always),
    ActionKindInfo::new("chi_middle_red", 1, Need::RedFives),
    ActionKindInfo::new("chi_right", 1, Need::Always),
    ActionKindInfo::new("chi_right_red", 1, Need::RedFives),
    ActionKindInfo::new("pass", 1, Need::Always),
    ActionKindInfo::new("kyuushu", 1, Need::AbortiveDraws),
    ActionKindInfo::new("dummy", 1, Need::Always),
];

/// When a layout must (and may) contain an action kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Need {
    Always,
    /// Present exactly when `[tiles] red_fives = true`.
    RedFives,
    /// Present exactly when `[draws] abortive_draws = true` (kyuushu is also the confirmation of
    /// every abortive draw).
    AbortiveDraws,
}

#[derive(Clone, Copy, Debug)]
pub struct ActionKindInfo {
    pub name: &'static str,
    pub count: u32,
    pub need: Need,
}

impl ActionKindInfo {
    const fn new(name: &'static str, count: u32, need: Need) -> Self {
        ActionKindInfo { name, count, need }
    }
}

/// Number of discard ids: one per tile type, plus one per red five.
pub fn discard_count(red_fives: bool) -> u32 {
    if red_fives {
        37
    } else {
        34
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActionBlock {
    pub kind: String,
    pub first: u32,
    pub count: u32,
}

/// A `Features` field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Feature {
    pub name: String,
    pub ty: Type,
}

/// One yaku, with its index in the yaku table (its position in `rules/yaku.toml`).
#[derive(Clone, Debug)]
pub struct Yaku {
    pub index: usize,
    pub name: String,
    pub han_closed: u32,
    /// 0 = not allowed with an open hand.
    pub han_open: u32,
    /// 0 for a normal yaku, else the yakuman weight (1 or 2).
    pub yakuman: u32,
    /// The condition text as written.
    pub when: String,
    pub condition: Expr,
    /// Indices of the yaku this one removes when both hold, transitively closed.
    pub supersedes: Vec<usize>,
    pub description: String,
}

#[derive(Clone, Debug)]
pub struct Variant {
    pub name: String,
    pub description: String,
    pub red_fives: bool,
    /// `[yaku_rules]`: bool options visible to conditions, sorted by name.
    pub yaku_rules: Vec<(String, bool)>,
    pub kiriage_mangan: bool,
    pub kazoe_yakuman: bool,
    pub multiple_yakuman: bool,
    pub double_yakuman: bool,
    pub honba_ron_points: u32,
    pub honba_tsumo_points: u32,
    pub riichi_stick_points: u32,
    pub double_ron: bool,
    pub triple_ron_abort: bool,
    pub abortive_draws: bool,
    pub nagashi_mangan: bool,
    pub pao: bool,
    pub starting_points: u32,
    pub riichi_min_points: u32,
    pub bust_below_zero: bool,
    pub target_points: u32,
    pub west_extension: bool,
    pub dealer_top_stop: bool,
    /// In thousands of points, first place first.
    pub uma: [i32; 4],
    pub illegal_action_penalty: f32,
    pub num_actions: u32,
    pub actions: Vec<ActionBlock>,
}

/// A checked spec: one variant, the yaku table and the feature list.
#[derive(Clone, Debug)]
pub struct Spec {
    pub variant: Variant,
    pub yaku: Vec<Yaku>,
    pub features: Vec<Feature>,
}

impl Spec {
    pub fn yaku(&self, name: &str) -> Option<&Yaku> {
        self.yaku.iter().find(|y| y.name == name)
    }

    /// A `[yaku_rules]` option of the variant.
    pub fn option(&self, name: &str) -> Option<bool> {
        self.variant.yaku_rules.iter().find(|(n, _)| n == name).map(|&(_, v)| v)
    }

    pub fn feature(&self, name: &str) -> Option<&Feature> {
        self.features.iter().find(|f| f.name == name)
    }

    pub fn action(&self, kind: &str) -> Option<&ActionBlock> {
        self.variant.actions.iter().find(|a| a.kind == kind)
    }
}
