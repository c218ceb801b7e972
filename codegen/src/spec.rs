//! The checked spec: what the emitters read. Built only by `check`, so holding a [`Spec`] means
//! every rule in the files passed the checker.

use crate::expr::{Expr, Type};
use std::fmt;

/// Action kinds the kernel knows, in the reference order. `count` is the block size, except for
/// `discard`, whose size follows `red_fives` (34 tile types, plus 3 red fives).
pub const ACTION_KINDS: [ActionKindInfo; 19] = [
    ActionKindInfo::new("discard", 34, Need::Always),
    ActionKindInfo::new("self_kan", 34, Need::Always),
    ActionKindInfo::new("tsumogiri", 1, Need::Always),
    ActionKindInfo::new("riichi", 1, Need::Always),
    ActionKindInfo::new("tsumo", 1, Need::Always),
    ActionKindInfo::new("ron", 1, Need::Always),
    ActionKindInfo::new("pon", 1, Need::Always),
    ActionKindInfo::new("pon_red", 1, Need::RedFives),
    ActionKindInfo::new("open_kan", 1, Need::Always),
    ActionKindInfo::new("chi_left", 1, Need::FourSeats),
    ActionKindInfo::new("chi_left_red", 1, Need::FourSeatsRedFives),
    ActionKindInfo::new("chi_middle", 1, Need::FourSeats),
    ActionKindInfo::new("chi_middle_red", 1, Need::FourSeatsRedFives),
    ActionKindInfo::new("chi_right", 1, Need::FourSeats),
    ActionKindInfo::new("chi_right_red", 1, Need::FourSeatsRedFives),
    ActionKindInfo::new("pass", 1, Need::Always),
    ActionKindInfo::new("kyuushu", 1, Need::AbortiveDraws),
    ActionKindInfo::new("kita", 1, Need::ThreeSeats),
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
    /// Present exactly when `[game] seats = 4`: three players have no chi.
    FourSeats,
    /// Present exactly when `[game] seats = 4` and `[tiles] red_fives = true`.
    FourSeatsRedFives,
    /// Present exactly when `[game] seats = 3`: North set aside (kita).
    ThreeSeats,
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

/// A plain option: a bool or integer key of `[tiles]`, `[scoring]`, `[claims]`, `[draws]`,
/// `[liability]` or `[game]`. Each becomes `pub const <KEY IN SCREAMING_CASE>` in the kernel code,
/// so a new option needs only its line in the variant files and the kernel code that reads it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VariantOption {
    pub section: String,
    pub name: String,
    pub value: OptionValue,
}

/// The value of a plain option: a TOML boolean, or a TOML integer that fits a `u32`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OptionValue {
    Bool(bool),
    U32(u32),
}

impl OptionValue {
    /// `true`, or an integer above 0: what an option that needs another asks of it.
    pub fn is_set(self) -> bool {
        match self {
            OptionValue::Bool(b) => b,
            OptionValue::U32(n) => n > 0,
        }
    }
}

impl fmt::Display for OptionValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OptionValue::Bool(b) => write!(f, "{b}"),
            OptionValue::U32(n) => write!(f, "{n}"),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Variant {
    pub name: String,
    pub description: String,
    /// Also in `options`; a field because the action layout depends on it.
    pub red_fives: bool,
    /// Also in `options`; a field because the `kyuushu` action depends on it.
    pub abortive_draws: bool,
    /// `[game] seats`, 3 or 4; also in `options`. The chi and kita actions and the uma follow it.
    pub seats: u32,
    /// `[yaku_rules]`: bool options visible to conditions, sorted by name.
    pub yaku_rules: Vec<(String, bool)>,
    /// The plain options, in file order (section by section, keys as written).
    pub options: Vec<VariantOption>,
    /// In thousands of points, first place first; 0 past the last seat.
    pub uma: [i32; 4],
    pub illegal_action_penalty: f32,
    pub num_actions: u32,
    pub actions: Vec<ActionBlock>,
}

impl Variant {
    /// The plain option `name`, from whichever section declares it.
    pub fn option_value(&self, name: &str) -> Option<OptionValue> {
        self.options.iter().find(|o| o.name == name).map(|o| o.value)
    }

    /// A plain bool option; `None` if absent or an integer.
    pub fn bool_option(&self, name: &str) -> Option<bool> {
        match self.option_value(name)? {
            OptionValue::Bool(b) => Some(b),
            OptionValue::U32(_) => None,
        }
    }

    /// A plain integer option; `None` if absent or a bool.
    pub fn u32_option(&self, name: &str) -> Option<u32> {
        match self.option_value(name)? {
            OptionValue::U32(n) => Some(n),
            OptionValue::Bool(_) => None,
        }
    }
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
