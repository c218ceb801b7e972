//! Collects the module-level items of all kernel sources and checks the module-wide rules
//! (supported item kinds, unique names, no recursion).

use std::collections::{HashMap, HashSet};

use syn::visit::Visit;

use crate::diag::{Diag, Result};
use crate::names::wgsl_ident;
use crate::types::{eval_const_int, parse_ty, Ty, TypeScope};

pub(crate) struct StructDef {
    pub fields: Vec<(String, Ty)>,
}

pub(crate) struct ConstDef<'a> {
    pub ty: Ty,
    /// Emitted as `var<private>` (see `lower::lower_const`).
    pub private: bool,
    pub item: &'a syn::ItemConst,
    pub file: usize,
}

pub(crate) struct Param {
    pub name: String,
    pub mutable: bool,
    pub ty: Ty,
}

pub(crate) struct FnDef<'a> {
    pub params: Vec<Param>,
    pub ret: Ty,
    pub item: &'a syn::ItemFn,
    pub file: usize,
}

/// A module-level item in source order, by Rust name.
pub(crate) enum Decl {
    Struct(String),
    Const(String),
    Fn(String),
}

pub(crate) struct Program<'a> {
    pub paths: Vec<&'a str>,
    pub structs: HashMap<String, StructDef>,
    pub struct_names: HashMap<String, ()>,
    pub consts: HashMap<String, ConstDef<'a>>,
    pub fns: HashMap<String, FnDef<'a>>,
    pub order: Vec<Decl>,
    /// Values of the integer consts (for array lengths).
    pub const_values: HashMap<String, u64>,
    /// WGSL names declared at module scope; locals must not shadow them.
    pub module_names: HashSet<String>,
}

const ALLOWED_ATTRS: &[&str] = &[
    "derive", "doc", "allow", "inline", "repr", "must_use", "warn", "expect", "rustfmt",
];

fn check_attrs(diag: Diag, attrs: &[syn::Attribute]) -> Result<()> {
    for attr in attrs {
        let path = attr.path();
        let name = path.segments.first().map(|s| s.ident.to_string()).unwrap_or_default();
        if !ALLOWED_ATTRS.contains(&name.as_str()) {
            return Err(diag.node(
                attr,
                format!("attribute `{name}` is not supported; only derive, doc, allow, inline and repr (which are ignored) may be used"),
            ));
        }
    }
    Ok(())
}

fn reject_generics(diag: Diag, generics: &syn::Generics) -> Result<()> {
    if !generics.params.is_empty() || generics.where_clause.is_some() {
        return Err(diag.node(
            generics,
            "generics and lifetimes are not supported; write the function or struct for concrete types",
        ));
    }
    Ok(())
}

fn unsupported_item(diag: Diag, item: &syn::Item) -> crate::diag::Error {
    let msg = match item {
        syn::Item::Use(_) => {
            "`use` items are not supported: all kernel sources form one module; refer to items by their plain name"
        }
        syn::Item::Mod(_) => "`mod` items are not supported: pass each file as a separate `Source` instead",
        syn::Item::Impl(_) => "impl blocks are not supported; write free functions taking the struct as a parameter",
        syn::Item::Trait(_) | syn::Item::TraitAlias(_) => {
            "traits are not supported; write free functions for concrete types"
        }
        syn::Item::Enum(_) => "enums are not supported; use u32 consts",
        syn::Item::Static(_) => "statics are not supported; use a `const`",
        syn::Item::Macro(_) => "macros are not supported in kernel sources; write the items out",
        syn::Item::Type(_) => "type aliases are not supported; write the type out",
        syn::Item::Union(_) => "unions are not supported; use a struct",
        _ => "unsupported item; kernel sources may contain only `const`, `struct` and `fn` items",
    };
    diag.node(item, msg)
}

impl<'a> Program<'a> {
    pub fn collect(paths: Vec<&'a str>, files: &'a [syn::File]) -> Result<Program<'a>> {
        let mut struct_items: Vec<(usize, &syn::ItemStruct)> = Vec::new();
        let mut const_items: Vec<(usize, &syn::ItemConst)> = Vec::new();
        let mut fn_items: Vec<(usize, &syn::ItemFn)> = Vec::new();
        let mut order = Vec::new();
        let mut seen: HashMap<String, ()> = HashMap::new();
        let mut module_names = HashSet::new();

        for (fi, file) in files.iter().enumerate() {
            let diag = Diag { file: paths[fi] };
            check_attrs(diag, &file.attrs)?;
            for item in &file.items {
                let ident = match item {
                    syn::Item::Struct(s) => {
                        check_attrs(diag, &s.attrs)?;
                        reject_generics(diag, &s.generics)?;
                        struct_items.push((fi, s));
                        order.push(Decl::Struct(s.ident.to_string()));
                        &s.ident
                    }
                    syn::Item::Const(c) => {
                        check_attrs(diag, &c.attrs)?;
                        reject_generics(diag, &c.generics)?;
                        const_items.push((fi, c));
                        order.push(Decl::Const(c.ident.to_string()));
                        &c.ident
                    }
                    syn::Item::Fn(f) => {
                        check_attrs(diag, &f.attrs)?;
                        fn_items.push((fi, f));
                        order.push(Decl::Fn(f.sig.ident.to_string()));
                        &f.sig.ident
                    }
                    other => return Err(unsupported_item(diag, other)),
                };
                let name = ident.to_string();
                if name == "table" || name == "tables" {
                    return Err(diag.node(ident, format!("`{name}` is reserved for the table intrinsic (`table(i)` reads the `tables` buffer); pick another name")));
                }
                if seen.insert(name.clone(), ()).is_some() || !module_names.insert(wgsl_ident(&name)) {
                    return Err(diag.node(
                        ident,
                        format!("`{name}` is defined twice in the kernel sources; rename one"),
                    ));
                }
            }
        }

        let struct_names: HashMap<String, ()> = struct_items.iter().map(|(_, s)| (s.ident.to_string(), ())).collect();
        let const_values = const_int_values(&const_items);
        let scope = TypeScope {
            structs: &struct_names,
            const_values: &const_values,
        };

        let mut structs = HashMap::new();
        for &(fi, s) in &struct_items {
            let diag = Diag { file: paths[fi] };
            let syn::Fields::Named(named) = &s.fields else {
                return Err(diag.node(s, "only structs with named fields are supported (`struct S { a: u32 }`); tuple and unit structs are not"));
            };
            if named.named.is_empty() {
                return Err(diag.node(s, "WGSL structs need at least one field"));
            }
            let mut fields = Vec::new();
            for field in &named.named {
                check_attrs(diag, &field.attrs)?;
                let Some(ident) = &field.ident else {
                    return Err(diag.node(field, "fields must be named"));
                };
                let ty = parse_ty(diag, &scope, &field.ty)?;
                if ty == Ty::Unit {
                    return Err(diag.node(&field.ty, "`()` fields are not supported"));
                }
                fields.push((ident.to_string(), ty));
            }
            structs.insert(s.ident.to_string(), StructDef { fields });
        }

        let mut consts = HashMap::new();
        for &(fi, c) in &const_items {
            let diag = Diag { file: paths[fi] };
            // Rust needs `usize` consts for array lengths (`[u32; N]`); they are plain u32
            // values on the GPU, so `N as u32` and `for i in 0..N` lower naturally.
            let ty = match &*c.ty {
                syn::Type::Path(p) if p.path.is_ident("usize") => Ty::U32,
                other => parse_ty(diag, &scope, other)?,
            };
            if ty == Ty::Unit {
                return Err(diag.node(&c.ty, "`()` consts are not supported"));
            }
            let private = contains_array(&structs, &ty);
            consts.insert(
                c.ident.to_string(),
                ConstDef {
                    ty,
                    private,
                    item: c,
                    file: fi,
                },
            );
        }

        let mut fns = HashMap::new();
        for &(fi, f) in &fn_items {
            let diag = Diag { file: paths[fi] };
            let sig = &f.sig;
            reject_generics(diag, &sig.generics)?;
            if sig.asyncness.is_some() || sig.abi.is_some() || sig.variadic.is_some() {
                return Err(diag.node(
                    sig,
                    "only plain `fn` items are supported (no async, extern or variadic)",
                ));
            }
            if !matches!(sig.safety, syn::Safety::Default) {
                return Err(diag.node(sig, "`unsafe fn` is not supported"));
            }
            let mut params = Vec::new();
            for input in &sig.inputs {
                let pat_ty = match input {
                    syn::FnArg::Typed(t) => t,
                    syn::FnArg::Receiver(r) => {
                        return Err(diag.node(
                            r,
                            "methods are not supported; write a free function taking the struct as a parameter",
                        ))
                    }
                };
                let (name, mutable) = match &*pat_ty.pat {
                    syn::Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                        (p.ident.to_string(), p.mutability.is_some())
                    }
                    syn::Pat::Wild(_) => ("_".to_string(), false),
                    other => {
                        return Err(diag.node(
                            other,
                            "parameters must be plain names (`x: u32`); destructuring is not supported",
                        ))
                    }
                };
                let ty = match &*pat_ty.ty {
                    syn::Type::Reference(r) if r.mutability.is_some() => {
                        if r.lifetime.is_some() {
                            return Err(diag.node(r, "lifetimes are not supported; write `&mut T`"));
                        }
                        let inner = parse_ty(diag, &scope, &r.elem)?;
                        if mutable {
                            return Err(diag.node(pat_ty, "`mut p: &mut T` is not supported; drop the `mut`"));
                        }
                        Ty::Ptr(Box::new(inner))
                    }
                    other => parse_ty(diag, &scope, other)?,
                };
                if ty == Ty::Unit {
                    return Err(diag.node(pat_ty, "`()` parameters are not supported"));
                }
                params.push(Param { name, mutable, ty });
            }
            let ret = match &sig.output {
                syn::ReturnType::Default => Ty::Unit,
                syn::ReturnType::Type(_, ty) => {
                    if matches!(&**ty, syn::Type::Never(_)) {
                        return Err(diag.node(ty, "diverging functions (`-> !`) are not supported"));
                    }
                    parse_ty(diag, &scope, ty)?
                }
            };
            fns.insert(
                sig.ident.to_string(),
                FnDef {
                    params,
                    ret,
                    item: f,
                    file: fi,
                },
            );
        }

        let program = Program {
            paths,
            structs,
            struct_names,
            consts,
            fns,
            order,
            const_values,
            module_names,
        };
        program.check_recursion()?;
        Ok(program)
    }

    pub fn diag(&self, file: usize) -> Diag<'a> {
        Diag { file: self.paths[file] }
    }

    /// Rejects direct and indirect recursion: WGSL forbids it, and call cycles would
    /// otherwise surface as an obscure naga error on the generated code.
    fn check_recursion(&self) -> Result<()> {
        let mut graph: HashMap<&str, Vec<(String, proc_macro2::Span)>> = HashMap::new();
        for (name, f) in &self.fns {
            let mut calls = CallCollector {
                fns: &self.fns,
                calls: Vec::new(),
            };
            calls.visit_block(&f.item.block);
            graph.insert(name.as_str(), calls.calls);
        }
        // Visit in source order so the reported cycle is deterministic.
        let mut done: HashSet<String> = HashSet::new();
        for decl in &self.order {
            let Decl::Fn(name) = decl else { continue };
            let mut stack = vec![name.clone()];
            self.dfs(&graph, &mut stack, &mut done)?;
        }
        Ok(())
    }

    fn dfs(
        &self,
        graph: &HashMap<&str, Vec<(String, proc_macro2::Span)>>,
        stack: &mut Vec<String>,
        done: &mut HashSet<String>,
    ) -> Result<()> {
        let Some(current) = stack.last().cloned() else {
            return Ok(());
        };
        if done.contains(&current) {
            return Ok(());
        }
        for (callee, span) in graph.get(current.as_str()).map(Vec::as_slice).unwrap_or(&[]) {
            if let Some(pos) = stack.iter().position(|s| s == callee) {
                let mut cycle: Vec<&str> = stack[pos..].iter().map(String::as_str).collect();
                cycle.push(callee);
                let file = self.fns.get(&current).map_or(0, |f| f.file);
                return Err(self.diag(file).at(
                    *span,
                    format!(
                        "recursion is not supported on the GPU ({}); rewrite it as a loop with an explicit stack array",
                        cycle.join(" -> ")
                    ),
                ));
            }
            stack.push(callee.clone());
            self.dfs(graph, stack, done)?;
            stack.pop();
        }
        done.insert(current);
        Ok(())
    }
}

struct CallCollector<'p, 'a> {
    fns: &'p HashMap<String, FnDef<'a>>,
    calls: Vec<(String, proc_macro2::Span)>,
}

impl<'ast> Visit<'ast> for CallCollector<'_, '_> {
    fn visit_expr_call(&mut self, call: &'ast syn::ExprCall) {
        if let syn::Expr::Path(p) = &*call.func {
            if let Some(ident) = p.path.get_ident() {
                let name = ident.to_string();
                if self.fns.contains_key(&name) {
                    self.calls.push((name, syn::spanned::Spanned::span(call)));
                }
            }
        }
        syn::visit::visit_expr_call(self, call);
    }
}

/// Arrays (directly or inside structs) are kept in `var`s: naga's SPIR-V backend copies a
/// value array into a temporary on every dynamic index, a `var` is indexed in place.
pub(crate) fn contains_array(structs: &HashMap<String, StructDef>, ty: &Ty) -> bool {
    match ty {
        Ty::Array(..) => true,
        Ty::Struct(name) => structs
            .get(name)
            .is_some_and(|s| s.fields.iter().any(|(_, t)| contains_array(structs, t))),
        _ => false,
    }
}

/// Values of integer consts, for array lengths. Consts may refer to consts defined later,
/// so iterate until nothing changes.
fn const_int_values(items: &[(usize, &syn::ItemConst)]) -> HashMap<String, u64> {
    let mut values = HashMap::new();
    loop {
        let before = values.len();
        for (_, c) in items {
            let name = c.ident.to_string();
            if values.contains_key(&name) {
                continue;
            }
            if let Some(v) = eval_const_int(&values, &c.expr) {
                values.insert(name, v);
            }
        }
        if values.len() == before {
            return values;
        }
    }
}
