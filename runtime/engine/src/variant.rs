//! The rule variants as users name them (`red`, `no-red`, ...), and what the host reads of their spec.

use crate::generated::Variant;
use crate::names::UnknownName;

impl Variant {
    /// Parses a variant name as users write it: `red`, `no-red` or `no_red`.
    pub fn from_name(name: &str) -> Option<Variant> {
        let wanted = name.replace('-', "_");
        Variant::ALL.iter().copied().find(|v| v.name() == wanted)
    }

    /// The spec's one-line summary of its rules (`[variant] description`).
    pub fn description(self) -> &'static str {
        with_variant!(self, v => v::host::VARIANT_DESCRIPTION)
    }

    /// The spec's plain options as (section, name, value), in file order.
    pub fn options(self) -> &'static [(&'static str, &'static str, &'static str)] {
        with_variant!(self, v => &v::host::OPTIONS)
    }

    /// The value of the plain option `name` (`"true"`, `"1000"`), if the spec has it.
    pub fn option(self, name: &str) -> Option<&'static str> {
        self.options().iter().find(|o| o.1 == name).map(|o| o.2)
    }

    /// Each player's points at the start of a game (`[game] starting_points` of the spec).
    pub fn starting_points(self) -> u32 {
        with_variant!(self, v => v::STARTING_POINTS)
    }
}

impl std::fmt::Display for Variant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name().replace('_', "-"))
    }
}

impl std::str::FromStr for Variant {
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Variant, UnknownName> {
        Variant::from_name(name).ok_or_else(|| UnknownName::new("variant", name, Variant::ALL))
    }
}
