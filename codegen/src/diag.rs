//! Errors that point into the spec files.
//!
//! Every problem found while reading or checking the spec becomes a [`Diagnostic`] with a 1-based
//! line and column, so a user editing `rules/` can jump straight to the offending text.

use std::fmt;

/// One error in a spec file. Line and column are 1-based; the column counts characters, not bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: error: {}",
            self.file, self.line, self.column, self.message
        )
    }
}

impl std::error::Error for Diagnostic {}

/// All diagnostics, one per line, for a build script's panic message or a CLI.
pub fn render(errors: &[Diagnostic]) -> String {
    errors.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n")
}

/// A source file with a byte-offset -> line:column map.
pub(crate) struct Source<'a> {
    pub path: &'a str,
    pub text: &'a str,
    line_starts: Vec<usize>,
}

impl<'a> Source<'a> {
    pub fn new(path: &'a str, text: &'a str) -> Self {
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Source {
            path,
            text,
            line_starts,
        }
    }

    /// Line and column (1-based, column in characters) of a byte offset; offsets past the end or
    /// inside a multi-byte character are clamped so a bad span can never panic.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = match self.line_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i - 1,
        };
        let start = self.line_starts[line];
        let column = self.text[start..offset].chars().count() + 1;
        (line + 1, column)
    }

    pub fn error_at(&self, offset: usize, message: impl Into<String>) -> Diagnostic {
        let (line, column) = self.line_col(offset);
        Diagnostic {
            file: self.path.to_string(),
            line,
            column,
            message: message.into(),
        }
    }

    /// Maps a toml/serde error (which carries a byte span into this file) to a diagnostic.
    pub fn toml_error(&self, err: &toml::de::Error) -> Diagnostic {
        let offset = err.span().map_or(0, |s| s.start);
        let mut message = err.message().trim_end().replace('\n', " ");
        // serde names Rust types; the spec author thinks in toml types.
        for (rust, toml) in [
            ("expected i64", "expected an integer"),
            ("expected i32", "expected a 32-bit signed integer"),
            ("expected u32", "expected a non-negative integer"),
            ("expected f64", "expected a number"),
        ] {
            message = message.replace(rust, toml);
        }
        self.error_at(offset, message)
    }
}

/// Levenshtein distance on characters; inputs are short identifiers.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.chars().enumerate() {
        cur[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let subst = prev[j] + usize::from(ca != *cb);
            cur[j + 1] = subst.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

/// The closest candidates to `word`, if any is close enough to be a plausible typo. At most three
/// are returned so a message never dumps a whole vocabulary.
pub(crate) fn suggest<'c>(word: &str, candidates: impl IntoIterator<Item = &'c str>) -> Vec<&'c str> {
    let limit = (word.chars().count() / 3).max(2);
    let mut scored: Vec<(usize, &str)> = candidates
        .into_iter()
        .map(|c| (edit_distance(word, c), c))
        .filter(|&(d, _)| d <= limit)
        .collect();
    scored.sort();
    let Some(&(best, _)) = scored.first() else {
        return Vec::new();
    };
    scored
        .into_iter()
        .filter(|&(d, _)| d == best)
        .take(3)
        .map(|(_, c)| c)
        .collect()
}

/// " (did you mean `x`?)" or "" — appended to messages about unknown names.
pub(crate) fn did_you_mean<'c>(word: &str, candidates: impl IntoIterator<Item = &'c str>) -> String {
    let found = suggest(word, candidates);
    if found.is_empty() {
        return String::new();
    }
    let list: Vec<String> = found.iter().map(|c| format!("`{c}`")).collect();
    format!(" (did you mean {}?)", list.join(" or "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_characters() {
        let s = Source::new("f", "ab\nc\u{e9}d\n");
        assert_eq!(s.line_col(0), (1, 1));
        assert_eq!(s.line_col(3), (2, 1));
        assert_eq!(s.line_col(6), (2, 3));
        assert_eq!(s.line_col(999), (3, 1));
    }

    #[test]
    fn suggestions_are_close_and_few() {
        assert_eq!(suggest("tsumoo", ["tsumo", "riichi", "runs"]), vec!["tsumo"]);
        assert!(suggest("xyzzy", ["tsumo", "riichi"]).is_empty());
    }
}
