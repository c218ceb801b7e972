//! Which kernel files every variant shares. A kernel file that names nothing a variant defines
//! (its generated constants and functions), directly or through the items of another file that
//! does, compiles the same for every variant: a host build emits it once (one `GameState`, one
//! `ScoreInput` for all variants) and each variant module uses it.

use std::collections::HashSet;

use syn::visit::Visit;

use crate::diag::Diag;
use crate::{Error, Source};

/// For each of `kernel`, whether it is shared by every variant; `variant` holds each variant's
/// generated sources (any one of them differing between variants makes what names it
/// variant-specific).
pub fn shared_files(kernel: &[Source], variant: &[Source]) -> Result<Vec<bool>, Error> {
    let mut per_variant = HashSet::new();
    for src in variant {
        per_variant.extend(parse(src)?.defined);
    }
    let files: Vec<Names> = kernel.iter().map(parse).collect::<Result<_, _>>()?;
    let mut shared: Vec<bool> = files.iter().map(|f| f.used.is_disjoint(&per_variant)).collect();
    // A file using an item of a variant-specific file is variant-specific too (to a fixpoint).
    loop {
        let specific: HashSet<&String> = files
            .iter()
            .zip(&shared)
            .filter(|(_, &s)| !s)
            .flat_map(|(f, _)| &f.defined)
            .collect();
        let mut changed = false;
        for (f, s) in files.iter().zip(shared.iter_mut()) {
            if *s && f.used.iter().any(|name| specific.contains(name)) {
                *s = false;
                changed = true;
            }
        }
        if !changed {
            return Ok(shared);
        }
    }
}

/// The items a file defines and every identifier it mentions.
struct Names {
    defined: HashSet<String>,
    used: HashSet<String>,
}

fn parse(src: &Source) -> Result<Names, Error> {
    let file =
        syn::parse_file(&src.text).map_err(|e| Diag { file: &src.path }.at(e.span(), format!("syntax error: {e}")))?;
    let defined = file
        .items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Const(c) => Some(c.ident.to_string()),
            syn::Item::Fn(f) => Some(f.sig.ident.to_string()),
            syn::Item::Struct(s) => Some(s.ident.to_string()),
            _ => None,
        })
        .collect();
    let mut idents = Idents(HashSet::new());
    idents.visit_file(&file);
    Ok(Names {
        defined,
        used: idents.0,
    })
}

struct Idents(HashSet<String>);

impl<'ast> Visit<'ast> for Idents {
    fn visit_ident(&mut self, ident: &'ast syn::Ident) {
        self.0.insert(ident.to_string());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn src(path: &str, text: &str) -> Source {
        Source {
            path: path.into(),
            text: text.into(),
        }
    }

    #[test]
    fn files_naming_a_variant_item_directly_or_through_another_file_are_not_shared() {
        let kernel = [
            src("layout.rs", "pub struct S { pub a: u32 } const K: u32 = 1;"),
            src("uses_variant.rs", "fn f() -> bool { DOUBLE_RON }"),
            src("uses_f.rs", "fn g() -> bool { f() && K == 1u32 }"),
            src("plain.rs", "fn h(s: S) -> u32 { s.a + K }"),
        ];
        let variant = [src("red_consts.rs", "pub const DOUBLE_RON: bool = true;")];
        let shared = shared_files(&kernel, &variant).expect("parses");
        assert_eq!(shared, [true, false, false, true]);
    }

    #[test]
    fn a_syntax_error_is_located() {
        let e = shared_files(&[src("bad.rs", "fn (")], &[]).expect_err("syntax error");
        assert_eq!(e.file, "bad.rs");
    }
}
