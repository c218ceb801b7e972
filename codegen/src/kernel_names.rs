//! The names the kernel code mentions. A plain option is a constant only the kernel gives meaning
//! to, so one whose constant the kernel never names is a typo or a leftover: with this set the
//! checker says so instead of emitting a constant nothing reads.

use crate::diag::Diagnostic;
use proc_macro2::{TokenStream, TokenTree};
use std::collections::BTreeSet;
use std::str::FromStr;

/// Every identifier in the kernel sources, as (path, text) pairs. Comments and strings do not count.
pub fn collect(files: &[(&str, &str)]) -> Result<BTreeSet<String>, Vec<Diagnostic>> {
    let mut names = BTreeSet::new();
    let mut errors = Vec::new();
    for &(path, text) in files {
        match TokenStream::from_str(text) {
            Ok(tokens) => walk(tokens, &mut names),
            Err(e) => {
                let start = e.span().start();
                errors.push(Diagnostic {
                    file: path.to_string(),
                    line: start.line.max(1),
                    column: start.column + 1,
                    message: format!("cannot read the kernel code (looking for the option constants it reads): {e}"),
                });
            }
        }
    }
    if errors.is_empty() {
        Ok(names)
    } else {
        Err(errors)
    }
}

fn walk(tokens: TokenStream, names: &mut BTreeSet<String>) {
    for tree in tokens {
        match tree {
            TokenTree::Ident(id) => {
                names.insert(id.to_string());
            }
            TokenTree::Group(g) => walk(g.stream(), names),
            TokenTree::Punct(_) | TokenTree::Literal(_) => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_and_strings_are_not_reads() {
        let names = collect(&[(
            "k.rs",
            "// PAO\nfn f() -> bool { let s = \"DOUBLE_RON\"; { RED_FIVES } }",
        )])
        .unwrap();
        assert!(names.contains("RED_FIVES"));
        assert!(!names.contains("PAO") && !names.contains("DOUBLE_RON"));
    }
}
