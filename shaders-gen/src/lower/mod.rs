//! Lowering of kernel-subset functions and consts to WGSL text.
//!
//! Expressions are lowered with an optional expected type (`want`): Rust infers unsuffixed
//! integer literals from context, WGSL needs them spelled `1u`/`1i`, so the expected type
//! flows down from annotations, parameters, the other operand, etc.

mod expr;
mod stmt;

use std::collections::{HashMap, HashSet};

use crate::diag::{Diag, Result};
use crate::items::{contains_array, Program};
use crate::names::wgsl_ident;
use crate::types::Ty;

pub(crate) use expr::Val;

#[derive(Clone)]
pub(crate) struct Local {
    pub wgsl: String,
    pub ty: Ty,
    /// A WGSL `var` (Rust `let mut`, or a copy kept in a var).
    pub var: bool,
    /// Rust allows assigning to it (`let mut`, `mut` parameter).
    pub mutable: bool,
}

/// What `break` targets, innermost last. WGSL's `break` inside `switch` leaves the switch,
/// Rust's `break` inside `match` leaves the loop, so a `break` in an arm sets a flag that is
/// tested after the switch.
enum Breakable {
    Loop,
    Switch { flag: Option<String> },
}

pub(crate) struct Lowerer<'p, 'a> {
    prog: &'p Program<'a>,
    diag: Diag<'a>,
    scopes: Vec<HashMap<String, Local>>,
    used: HashSet<String>,
    out: String,
    indent: usize,
    ret: Ty,
    breakables: Vec<Breakable>,
    /// Lowering a module-scope const initialiser.
    in_const: bool,
}

impl<'p, 'a> Lowerer<'p, 'a> {
    fn new(prog: &'p Program<'a>, file: usize) -> Self {
        Lowerer {
            prog,
            diag: prog.diag(file),
            scopes: vec![HashMap::new()],
            used: prog.module_names.clone(),
            out: String::new(),
            indent: 0,
            ret: Ty::Unit,
            breakables: Vec::new(),
            in_const: false,
        }
    }

    fn line(&mut self, text: &str) {
        for _ in 0..self.indent {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }

    /// Declares a Rust local and returns its WGSL name. WGSL forbids redeclaring a name in
    /// the same scope (Rust shadowing does that), so every local gets a function-unique name.
    fn declare(&mut self, rust: &str, ty: Ty, var: bool, mutable: bool) -> String {
        let base = if rust == "_" {
            "unused".to_string()
        } else {
            wgsl_ident(rust)
        };
        let wgsl = self.fresh(&base);
        if let Some(scope) = self.scopes.last_mut() {
            scope.insert(
                rust.to_string(),
                Local {
                    wgsl: wgsl.clone(),
                    ty,
                    var,
                    mutable,
                },
            );
        }
        wgsl
    }

    fn fresh(&mut self, base: &str) -> String {
        let mut name = base.to_string();
        let mut n = 1;
        while self.used.contains(&name) {
            name = format!("{base}_{n}");
            n += 1;
        }
        self.used.insert(name.clone());
        name
    }

    fn lookup(&self, rust: &str) -> Option<&Local> {
        self.scopes.iter().rev().find_map(|s| s.get(rust))
    }

    fn contains_array(&self, ty: &Ty) -> bool {
        contains_array(&self.prog.structs, ty)
    }
}

/// Lowers one function to WGSL.
pub(crate) fn lower_fn(prog: &Program, name: &str) -> Result<String> {
    let Some(f) = prog.fns.get(name) else {
        return Ok(String::new());
    };
    let mut lw = Lowerer::new(prog, f.file);
    lw.ret = f.ret.clone();
    let mut params = Vec::new();
    // Parameters are immutable in WGSL: a `mut` parameter (or one holding arrays, see
    // `contains_array`) arrives under another name and is copied into a `var`.
    let mut copies = Vec::new();
    for p in &f.params {
        if p.mutable || lw.contains_array(&p.ty) {
            let arg = lw.fresh(&format!("{}_arg", wgsl_ident(&p.name)));
            let local = lw.declare(&p.name, p.ty.clone(), true, p.mutable);
            params.push(format!("{arg}: {}", p.ty.wgsl()));
            copies.push(format!("var {local}: {} = {arg};", p.ty.wgsl()));
        } else {
            let local = lw.declare(&p.name, p.ty.clone(), false, false);
            params.push(format!("{local}: {}", p.ty.wgsl()));
        }
    }
    let ret = if f.ret == Ty::Unit {
        String::new()
    } else {
        format!(" -> {}", f.ret.wgsl())
    };
    lw.line(&format!("fn {}({}){ret} {{", wgsl_ident(name), params.join(", ")));
    lw.indent += 1;
    for c in &copies {
        lw.line(c);
    }
    lw.fn_body(&f.item.block)?;
    lw.indent -= 1;
    lw.line("}");
    Ok(lw.out)
}

/// Lowers one module-scope const. Array-holding consts become `var<private>`: naga's SPIR-V
/// backend would copy a `const` array into a temporary on every dynamically indexed read.
/// Kernels never write them (Rust consts are immutable), so the semantics are the same.
pub(crate) fn lower_const(prog: &Program, name: &str) -> Result<String> {
    let Some(c) = prog.consts.get(name) else {
        return Ok(String::new());
    };
    let mut lw = Lowerer::new(prog, c.file);
    lw.in_const = true;
    let value = lw.typed(&c.item.expr, Some(&c.ty))?;
    let kind = if c.private { "var<private>" } else { "const" };
    Ok(format!(
        "{kind} {}: {} = {};\n",
        wgsl_ident(name),
        c.ty.wgsl(),
        value.code
    ))
}

/// Emits a struct declaration (fields in declaration order; all kernel types are 4-byte
/// scalars or arrays of them, so the layout matches `#[repr(C)]`).
pub(crate) fn lower_struct(prog: &Program, name: &str) -> String {
    let Some(s) = prog.structs.get(name) else {
        return String::new();
    };
    let mut out = format!("struct {} {{\n", wgsl_ident(name));
    for (field, ty) in &s.fields {
        out.push_str(&format!("    {}: {},\n", wgsl_ident(field), ty.wgsl()));
    }
    out.push_str("}\n");
    out
}
