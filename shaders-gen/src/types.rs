//! The kernel subset's type model: parsing Rust types, WGSL spelling.

use std::collections::HashMap;

use crate::diag::{Diag, Result};
use crate::names::wgsl_ident;

#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Ty {
    U32,
    I32,
    F32,
    Bool,
    Array(Box<Ty>, u32),
    /// By Rust name.
    Struct(String),
    /// `&mut T` parameter: `ptr<function, T>`.
    Ptr(Box<Ty>),
    Unit,
    /// An unsuffixed integer literal (or arithmetic on such) whose type is not known yet.
    IntLit,
}

impl Ty {
    pub fn wgsl(&self) -> String {
        match self {
            Ty::U32 => "u32".into(),
            Ty::I32 => "i32".into(),
            Ty::F32 => "f32".into(),
            Ty::Bool => "bool".into(),
            Ty::Array(elem, n) => format!("array<{}, {n}>", elem.wgsl()),
            Ty::Struct(name) => wgsl_ident(name),
            Ty::Ptr(inner) => format!("ptr<function, {}>", inner.wgsl()),
            Ty::Unit => "()".into(),
            Ty::IntLit => "{integer}".into(),
        }
    }

    /// How the type reads in Rust, for messages.
    pub fn rust(&self) -> String {
        match self {
            Ty::U32 => "u32".into(),
            Ty::I32 => "i32".into(),
            Ty::F32 => "f32".into(),
            Ty::Bool => "bool".into(),
            Ty::Array(elem, n) => format!("[{}; {n}]", elem.rust()),
            Ty::Struct(name) => name.clone(),
            Ty::Ptr(inner) => format!("&mut {}", inner.rust()),
            Ty::Unit => "()".into(),
            Ty::IntLit => "{integer}".into(),
        }
    }

    pub fn is_int(&self) -> bool {
        matches!(self, Ty::U32 | Ty::I32)
    }

    pub fn is_numeric(&self) -> bool {
        matches!(self, Ty::U32 | Ty::I32 | Ty::F32)
    }

    pub fn is_scalar(&self) -> bool {
        matches!(self, Ty::U32 | Ty::I32 | Ty::F32 | Ty::Bool)
    }
}

/// What type parsing needs to know about the module.
pub(crate) struct TypeScope<'a> {
    pub structs: &'a HashMap<String, ()>,
    /// Integer values of integer consts, for array lengths.
    pub const_values: &'a HashMap<String, u64>,
}

/// Parses a type in a value position (struct field, `let`, return, const).
pub(crate) fn parse_ty(diag: Diag, scope: &TypeScope, ty: &syn::Type) -> Result<Ty> {
    match ty {
        syn::Type::Paren(p) => parse_ty(diag, scope, &p.elem),
        syn::Type::Group(g) => parse_ty(diag, scope, &g.elem),
        syn::Type::Path(p) => {
            if p.qself.is_some() || p.path.segments.len() != 1 {
                return Err(diag.node(
                    ty,
                    "only plain type names are supported (u32, i32, f32, bool, [T; N] or a struct defined in the kernel sources)",
                ));
            }
            let seg = &p.path.segments[0];
            let name = seg.ident.to_string();
            let heap = ["Vec", "Box", "String", "VecDeque", "HashMap", "BTreeMap", "Rc", "Arc"];
            if heap.contains(&name.as_str()) {
                return Err(diag.node(
                    ty,
                    format!("`{name}` needs a heap, which GPU kernels do not have; use a fixed-size array `[T; N]` (plus a u32 length if needed)"),
                ));
            }
            if name == "Option" || name == "Result" {
                return Err(diag.node(
                    ty,
                    format!("`{name}` is not supported; return a struct with a `bool`/u32 status field, or use a sentinel value"),
                ));
            }
            if !seg.arguments.is_none() {
                return Err(diag.node(ty, "generic types are not supported; use concrete types"));
            }
            match name.as_str() {
                "u32" => Ok(Ty::U32),
                "i32" => Ok(Ty::I32),
                "f32" => Ok(Ty::F32),
                "bool" => Ok(Ty::Bool),
                "u8" | "u16" | "u64" | "u128" | "usize" => Err(diag.node(
                    ty,
                    format!("`{name}` is not available in WGSL; use `u32` (`as usize` is only allowed directly inside an index: `a[i as usize]`)"),
                )),
                "i8" | "i16" | "i64" | "i128" | "isize" => {
                    Err(diag.node(ty, format!("`{name}` is not available in WGSL; use `i32`")))
                }
                "f64" => Err(diag.node(ty, "`f64` is not available in WGSL; use `f32`")),
                "char" | "str" => Err(diag.node(ty, "text types are not supported; encode characters as u32")),
                "Self" => Err(diag.node(ty, "`Self` is not supported; write the struct name")),
                _ if scope.structs.contains_key(&name) => Ok(Ty::Struct(name)),
                _ => Err(diag.node(
                    ty,
                    format!("unknown type `{name}`; use u32, i32, f32, bool, [T; N] or a struct defined in the kernel sources"),
                )),
            }
        }
        syn::Type::Array(a) => {
            let elem = parse_ty(diag, scope, &a.elem)?;
            let len = eval_len(diag, scope.const_values, &a.len)?;
            Ok(Ty::Array(Box::new(elem), len))
        }
        syn::Type::Reference(r) if matches!(&*r.elem, syn::Type::Slice(_)) => Err(diag.node(
            ty,
            "slices are not supported; use a fixed-size array `[T; N]` (plus a u32 length if needed)",
        )),
        syn::Type::Reference(r) => Err(diag.node(
            ty,
            if r.mutability.is_some() {
                "`&mut T` is only allowed as the type of a function parameter"
            } else {
                "shared references `&T` are not supported; pass the value itself (kernel types are Copy)"
            },
        )),
        syn::Type::Slice(_) => Err(diag.node(
            ty,
            "slices are not supported; use a fixed-size array `[T; N]` (plus a u32 length if needed)",
        )),
        syn::Type::Tuple(t) if t.elems.is_empty() => Ok(Ty::Unit),
        syn::Type::Tuple(_) => Err(diag.node(ty, "tuples are not supported; use a struct with named fields")),
        syn::Type::Ptr(_) => Err(diag.node(ty, "raw pointers are not supported; use a `&mut T` parameter")),
        syn::Type::ImplTrait(_) | syn::Type::TraitObject(_) => {
            Err(diag.node(ty, "traits are not supported; use concrete types and free functions"))
        }
        syn::Type::Infer(_) => Err(diag.node(ty, "write the type out instead of `_`")),
        _ => Err(diag.node(ty, "unsupported type; use u32, i32, f32, bool, [T; N] or a struct")),
    }
}

/// An array length: an integer literal, or an integer const (arithmetic allowed).
pub(crate) fn eval_len(diag: Diag, consts: &HashMap<String, u64>, e: &syn::Expr) -> Result<u32> {
    let v = eval_const_int(consts, e).ok_or_else(|| {
        diag.node(
            e,
            "array length must be an integer literal or an integer const (e.g. `[u32; 34]` or `[u32; N]`)",
        )
    })?;
    match u32::try_from(v) {
        Ok(n) if n > 0 => Ok(n),
        _ => Err(diag.node(e, "array length must be between 1 and 4294967295")),
    }
}

/// Evaluates an integer expression made of literals, known consts and arithmetic.
pub(crate) fn eval_const_int(consts: &HashMap<String, u64>, e: &syn::Expr) -> Option<u64> {
    match e {
        syn::Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Int(i), ..
        }) => i.base10_parse::<u64>().ok(),
        syn::Expr::Paren(p) => eval_const_int(consts, &p.expr),
        syn::Expr::Group(g) => eval_const_int(consts, &g.expr),
        syn::Expr::Path(p) => consts.get(&p.path.get_ident()?.to_string()).copied(),
        syn::Expr::Cast(c) => eval_const_int(consts, &c.expr),
        syn::Expr::Binary(b) => {
            let l = eval_const_int(consts, &b.left)?;
            let r = eval_const_int(consts, &b.right)?;
            match b.op {
                syn::BinOp::Add(_) => l.checked_add(r),
                syn::BinOp::Sub(_) => l.checked_sub(r),
                syn::BinOp::Mul(_) => l.checked_mul(r),
                syn::BinOp::Div(_) => l.checked_div(r),
                syn::BinOp::Rem(_) => l.checked_rem(r),
                syn::BinOp::Shl(_) => l.checked_shl(u32::try_from(r).ok()?),
                syn::BinOp::Shr(_) => l.checked_shr(u32::try_from(r).ok()?),
                syn::BinOp::BitAnd(_) => Some(l & r),
                syn::BinOp::BitOr(_) => Some(l | r),
                syn::BinOp::BitXor(_) => Some(l ^ r),
                _ => None,
            }
        }
        _ => None,
    }
}
