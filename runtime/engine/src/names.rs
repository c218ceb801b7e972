//! Names users write for the things they choose (a variant, mode, backend, agent, observation
//! form), and the error for a name that is none of them.

/// A name that is none of the known ones (a variant, mode, backend ...), with the ones it could be.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownName {
    /// What was named: `variant`, `mode`, `backend`.
    pub what: &'static str,
    /// The name as given.
    pub name: String,
    /// The known names, as users write them.
    pub known: Vec<String>,
}

impl UnknownName {
    pub(crate) fn new<T: std::fmt::Display>(what: &'static str, name: &str, known: &[T]) -> UnknownName {
        UnknownName {
            what,
            name: name.to_string(),
            known: known.iter().map(ToString::to_string).collect(),
        }
    }

    /// The one of `all` written `name` (as its `Display` writes it), or the error naming them.
    pub fn find<T: Copy + std::fmt::Display>(what: &'static str, name: &str, all: &[T]) -> Result<T, UnknownName> {
        all.iter()
            .copied()
            .find(|t| t.to_string() == name)
            .ok_or_else(|| UnknownName::new(what, name, all))
    }
}

impl std::fmt::Display for UnknownName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "unknown {} `{}` (known: {})",
            self.what,
            self.name,
            self.known.join(", ")
        )
    }
}

impl std::error::Error for UnknownName {}
