//! Errors pointing into the kernel sources.

use std::fmt;

use proc_macro2::Span;

/// A translation error located in a kernel source file (1-based line and column).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: {}", self.file, self.line, self.column, self.message)
    }
}

impl std::error::Error for Error {}

pub(crate) type Result<T> = std::result::Result<T, Error>;

/// Builds errors for one source file.
#[derive(Clone, Copy)]
pub(crate) struct Diag<'a> {
    pub file: &'a str,
}

impl Diag<'_> {
    pub fn at(&self, span: Span, message: impl Into<String>) -> Error {
        let start = span.start();
        Error {
            file: self.file.to_string(),
            line: start.line,
            // proc-macro2 columns are 0-based (in chars); editors count from 1.
            column: start.column + 1,
            message: message.into(),
        }
    }

    pub fn node(&self, node: &impl syn::spanned::Spanned, message: impl Into<String>) -> Error {
        self.at(node.span(), message)
    }

    /// An error not tied to a place in the sources (e.g. a bad `Entry`).
    pub fn whole_file(&self, message: impl Into<String>) -> Error {
        Error {
            file: self.file.to_string(),
            line: 1,
            column: 1,
            message: message.into(),
        }
    }
}
