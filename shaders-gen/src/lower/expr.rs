//! Expression lowering.

use syn::spanned::Spanned;

use super::Lowerer;
use crate::diag::{Error, Result};
use crate::names::wgsl_ident;
use crate::types::{eval_len, parse_ty, Ty, TypeScope};

/// How tightly a lowered expression binds, to parenthesise only where WGSL needs it
/// (WGSL refuses some mixes Rust allows, e.g. `a & b == c`, so binary children of a
/// different operator are always parenthesised).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Prec {
    Atom,
    Unary,
    Binary(&'static str),
}

#[derive(Clone, Debug)]
pub(crate) struct Val {
    pub code: String,
    pub ty: Ty,
    pub prec: Prec,
}

impl Val {
    fn atom(code: String, ty: Ty) -> Val {
        Val {
            code,
            ty,
            prec: Prec::Atom,
        }
    }

    /// As an operand of binary `op`, on the left or the right.
    fn operand(&self, op: &str, left: bool) -> String {
        match self.prec {
            Prec::Atom | Prec::Unary => self.code.clone(),
            Prec::Binary(inner) if left && inner == op && LEFT_ASSOC.contains(&op) => self.code.clone(),
            Prec::Binary(_) => format!("({})", self.code),
        }
    }

    /// As the operand of a prefix operator or the base of `.field` / `[index]`.
    pub fn tight(&self) -> String {
        match self.prec {
            Prec::Atom => self.code.clone(),
            _ => format!("({})", self.code),
        }
    }
}

const LEFT_ASSOC: &[&str] = &["+", "-", "*", "/", "%", "&", "|", "^", "&&", "||"];

fn is_untyped(ty: &Ty) -> bool {
    *ty == Ty::IntLit
}

pub(crate) fn macro_message(mac: &syn::Macro) -> String {
    let name = mac
        .path
        .segments
        .last()
        .map(|s| s.ident.to_string())
        .unwrap_or_default();
    match name.as_str() {
        "panic" | "assert" | "assert_eq" | "assert_ne" | "debug_assert" | "debug_assert_eq" | "debug_assert_ne"
        | "unreachable" | "todo" | "unimplemented" => format!(
            "`{name}!` is not supported: GPU kernels cannot panic; return a status value (or clamp the input) instead"
        ),
        "println" | "print" | "eprintln" | "eprint" | "dbg" | "format" | "write" | "writeln" => format!(
            "`{name}!` is not supported: there is no printing on the GPU; remove it and test the function natively"
        ),
        "vec" => "`vec!` needs a heap, which GPU kernels do not have; use a fixed-size array `[v; N]`".into(),
        "matches" => "`matches!` is not supported; compare with `==` or use `match` as a statement".into(),
        _ => format!("macros (`{name}!`) are not supported in kernel code; write the code out"),
    }
}

/// The message for an expression kind the subset never accepts in value position.
pub(crate) fn unsupported_expr(e: &syn::Expr) -> String {
    use syn::Expr as E;
    match e {
        E::Closure(_) => "closures are not supported; write a separate `fn`".into(),
        E::Macro(m) => macro_message(&m.mac),
        E::Range(_) => "ranges are only supported as the bounds of `for i in a..b`".into(),
        E::Tuple(_) => "tuples are not supported; use a struct with named fields".into(),
        E::Try(_) => "`?` needs Option/Result, which are not supported; return a status field instead".into(),
        E::Let(_) => "`if let` / `while let` are not supported (no Option or enums); compare values with `==`".into(),
        E::Async(_) | E::Await(_) => "async is not supported".into(),
        E::Unsafe(_) => "`unsafe` blocks are not supported".into(),
        E::RawAddr(_) => "raw pointers are not supported; use a `&mut T` parameter".into(),
        E::Reference(_) => "references are only supported as call arguments `f(&mut x)` for `&mut T` parameters; pass values otherwise".into(),
        E::Assign(_) => "an assignment cannot be used as a value; write it as its own statement".into(),
        E::Match(_) => "`match` used as a value is not supported; declare `let mut x: T = ...;` and assign it in each arm".into(),
        E::Loop(_) | E::While(_) | E::ForLoop(_) => "loops cannot be used as values (`break value` is not supported); assign a `let mut` variable before `break`".into(),
        E::Return(_) | E::Break(_) | E::Continue(_) => "`return`/`break`/`continue` cannot be used as values; write them as statements".into(),
        E::Infer(_) => "`_` is only allowed as `_ = value;`".into(),
        E::Block(_) => "a block with statements cannot be used as a value; declare `let mut x: T = ...;` and assign it inside".into(),
        _ => "unsupported expression in the kernel subset".into(),
    }
}

impl Lowerer<'_, '_> {
    fn err(&self, node: &impl Spanned, msg: impl Into<String>) -> Error {
        self.diag.node(node, msg)
    }

    /// Lowers `e`; the result may still be an untyped integer (`Ty::IntLit`).
    pub(super) fn expr(&mut self, e: &syn::Expr, want: Option<&Ty>) -> Result<Val> {
        let want = want.filter(|t| !is_untyped(t));
        use syn::Expr as E;
        match e {
            E::Lit(l) => self.lit(&l.lit, want, false),
            E::Paren(p) => {
                let v = self.expr(&p.expr, want)?;
                Ok(Val::atom(v.tight(), v.ty))
            }
            E::Group(g) => self.expr(&g.expr, want),
            E::Path(p) => self.path(p),
            E::Unary(u) => self.unary(u, want),
            E::Binary(b) => self.binary(b, want),
            E::Cast(c) => self.cast(c),
            E::Field(f) => self.field(f),
            E::Index(i) => self.index(i),
            E::Call(c) => self.call(c),
            E::MethodCall(m) => self.method(m, want),
            E::Struct(s) => self.struct_lit(s),
            E::Array(a) => self.array_lit(a, want),
            E::Repeat(r) => self.repeat(r, want),
            E::If(i) => self.select(i, want),
            E::Block(b) if b.label.is_none() => match single_expr(&b.block) {
                Some(inner) => self.expr(inner, want),
                None => Err(self.err(e, unsupported_expr(e))),
            },
            _ => Err(self.err(e, unsupported_expr(e))),
        }
    }

    /// Reads through a `&mut` parameter.
    pub(super) fn load(&self, v: Val) -> Val {
        match v.ty {
            Ty::Ptr(inner) => Val {
                code: format!("*{}", v.code),
                ty: *inner,
                prec: Prec::Unary,
            },
            _ => v,
        }
    }

    /// Lowers `e` to a value with a known type (any type if `want` is `None`).
    pub(super) fn value(&mut self, e: &syn::Expr, want: Option<&Ty>) -> Result<Val> {
        let v = self.expr(e, want)?;
        let v = self.load(v);
        if is_untyped(&v.ty) {
            return Err(self.err(
                e,
                "cannot infer the type of this integer expression; add a suffix (`0u32`, `0i32`) or a type annotation",
            ));
        }
        Ok(v)
    }

    /// Lowers `e` to a value of exactly type `want`.
    pub(super) fn typed(&mut self, e: &syn::Expr, want: Option<&Ty>) -> Result<Val> {
        let v = self.value(e, want)?;
        if let Some(w) = want {
            if v.ty != *w {
                return Err(self.err(
                    e,
                    format!(
                        "expected `{}`, found `{}`; convert with `as {}` if that is intended",
                        w.rust(),
                        v.ty.rust(),
                        w.rust()
                    ),
                ));
            }
        }
        Ok(v)
    }

    fn lit(&mut self, lit: &syn::Lit, want: Option<&Ty>, negated: bool) -> Result<Val> {
        match lit {
            syn::Lit::Int(i) => {
                let ty = match i.suffix() {
                    "" => match want {
                        Some(t @ (Ty::U32 | Ty::I32)) => t.clone(),
                        Some(Ty::F32) => return Err(self.err(i, "expected `f32`; write a float literal such as `1.0`")),
                        _ => Ty::IntLit,
                    },
                    "u32" => Ty::U32,
                    "i32" => Ty::I32,
                    "f32" => Ty::F32,
                    "usize" => {
                        return Err(self.err(
                            i,
                            "`usize` literals are not supported; write a `u32` literal (indices need no suffix)",
                        ))
                    }
                    "f64" => return Err(self.err(i, "`f64` is not available in WGSL; use `f32`")),
                    other => {
                        return Err(self.err(
                            i,
                            format!("`{other}` is not available in WGSL; use a `u32` or `i32` literal"),
                        ))
                    }
                };
                // Negative literal patterns (`-1 =>`) arrive as one negative literal.
                let signed = i
                    .base10_parse::<i128>()
                    .map_err(|_| self.err(i, "integer literal out of range"))?;
                let (negated, sign) = if signed < 0 { (true, "-") } else { (negated, "") };
                if signed < 0 && ty == Ty::U32 {
                    return Err(self.err(i, "a `u32` cannot be negative"));
                }
                let value = signed.unsigned_abs();
                let max: u128 = match ty {
                    Ty::U32 | Ty::IntLit => u32::MAX.into(),
                    Ty::I32 if negated => 1 << 31,
                    Ty::I32 => (1 << 31) - 1,
                    _ => u128::MAX,
                };
                if value > max {
                    return Err(self.err(
                        i,
                        format!(
                            "integer literal {value} is out of range for `{}`; kernel integers are 32-bit (u32 or i32)",
                            if ty == Ty::IntLit { "u32".into() } else { ty.rust() }
                        ),
                    ));
                }
                if sign == "-" && ty == Ty::I32 && value == 1 << 31 {
                    return Ok(Val::atom("i32(-2147483648)".into(), Ty::I32));
                }
                let code = match ty {
                    Ty::U32 => format!("{value}u"),
                    Ty::I32 => format!("{sign}{value}i"),
                    Ty::F32 => format!("{sign}{value}.0f"),
                    _ => format!("{sign}{value}"),
                };
                let prec = if sign.is_empty() { Prec::Atom } else { Prec::Unary };
                Ok(Val { code, ty, prec })
            }
            syn::Lit::Float(f) => {
                match f.suffix() {
                    "" | "f32" => {}
                    "f64" => return Err(self.err(f, "`f64` is not available in WGSL; use `f32`")),
                    other => return Err(self.err(f, format!("unsupported literal suffix `{other}`"))),
                }
                if matches!(want, Some(Ty::U32 | Ty::I32)) {
                    return Err(self.err(f, "expected an integer; write an integer literal"));
                }
                let digits = f.base10_digits();
                let code = if digits.contains(['.', 'e', 'E']) {
                    format!("{digits}f")
                } else {
                    format!("{digits}.0f")
                };
                Ok(Val::atom(code, Ty::F32))
            }
            syn::Lit::Bool(b) => Ok(Val::atom(b.value.to_string(), Ty::Bool)),
            other => Err(self.err(other, "only integer, float and bool literals are supported")),
        }
    }

    fn path(&mut self, p: &syn::ExprPath) -> Result<Val> {
        if p.qself.is_some() {
            return Err(self.err(p, "qualified paths are not supported"));
        }
        if let Some(ident) = p.path.get_ident() {
            let name = ident.to_string();
            if let Some(local) = self.lookup(&name) {
                return Ok(Val::atom(local.wgsl.clone(), local.ty.clone()));
            }
            if let Some(c) = self.prog.consts.get(&name) {
                if self.in_const && c.private {
                    return Err(self.err(
                        p,
                        format!("a const initialiser cannot read `{name}`: consts holding arrays are emitted as `var<private>` (so kernels can index them cheaply); write the value out"),
                    ));
                }
                return Ok(Val::atom(wgsl_ident(&name), c.ty.clone()));
            }
            if self.prog.fns.contains_key(&name) {
                return Err(self.err(p, format!("functions cannot be used as values; call `{name}(...)`")));
            }
            return Err(self.err(p, format!("unknown name `{name}`; kernel code can use locals, parameters and consts defined in the kernel sources")));
        }
        let segs: Vec<String> = p.path.segments.iter().map(|s| s.ident.to_string()).collect();
        let val = match (segs.first().map(String::as_str), segs.get(1).map(String::as_str), segs.len()) {
            (Some("u32"), Some("MAX"), 2) => Val::atom("4294967295u".into(), Ty::U32),
            (Some("u32"), Some("MIN"), 2) => Val::atom("0u".into(), Ty::U32),
            (Some("i32"), Some("MAX"), 2) => Val::atom("2147483647i".into(), Ty::I32),
            (Some("i32"), Some("MIN"), 2) => Val::atom("i32(-2147483648)".into(), Ty::I32),
            _ => {
                return Err(self.err(
                    p,
                    "paths like `a::b` are not supported (except `u32::MAX`, `u32::MIN`, `i32::MAX`, `i32::MIN`); refer to items by their plain name",
                ))
            }
        };
        Ok(val)
    }

    fn unary(&mut self, u: &syn::ExprUnary, want: Option<&Ty>) -> Result<Val> {
        match u.op {
            syn::UnOp::Neg(_) => {
                if let syn::Expr::Lit(syn::ExprLit {
                    lit: lit @ syn::Lit::Int(_),
                    ..
                }) = &*u.expr
                {
                    let v = self.lit(lit, want, true)?;
                    if v.ty == Ty::I32 && v.code == "2147483648i" {
                        // Not a valid WGSL i32 literal; the abstract-int form converts exactly.
                        return Ok(Val::atom("i32(-2147483648)".into(), Ty::I32));
                    }
                    if v.ty == Ty::U32 {
                        return Err(self.err(u, "cannot negate a `u32`; use `0u32.wrapping_sub(x)` or an `i32`"));
                    }
                    return Ok(Val {
                        code: format!("-{}", v.code),
                        ty: v.ty,
                        prec: Prec::Unary,
                    });
                }
                let v = self.expr(&u.expr, want)?;
                let v = self.load(v);
                match v.ty {
                    Ty::I32 | Ty::F32 | Ty::IntLit => Ok(Val {
                        code: format!("-{}", v.tight()),
                        ty: v.ty,
                        prec: Prec::Unary,
                    }),
                    Ty::U32 => Err(self.err(u, "cannot negate a `u32`; use `0u32.wrapping_sub(x)` or an `i32`")),
                    ref t => Err(self.err(u, format!("cannot negate a `{}`", t.rust()))),
                }
            }
            syn::UnOp::Not(_) => {
                let v = self.expr(&u.expr, want)?;
                let v = self.load(v);
                match v.ty {
                    Ty::Bool => Ok(Val {
                        code: format!("!{}", v.tight()),
                        ty: v.ty,
                        prec: Prec::Unary,
                    }),
                    // Rust's `!` on integers is bitwise complement.
                    Ty::U32 | Ty::I32 | Ty::IntLit => Ok(Val {
                        code: format!("~{}", v.tight()),
                        ty: v.ty,
                        prec: Prec::Unary,
                    }),
                    ref t => Err(self.err(u, format!("`!` is not defined for `{}`", t.rust()))),
                }
            }
            syn::UnOp::Deref(_) => {
                let v = self.expr(&u.expr, None)?;
                if !matches!(v.ty, Ty::Ptr(_)) {
                    return Err(self.err(u, "`*` only applies to `&mut T` parameters"));
                }
                Ok(self.load(v))
            }
            _ => Err(self.err(u, "unsupported unary operator")),
        }
    }

    /// Lowers both operands of a binary operator, letting an untyped literal on one side
    /// take the type of the other side.
    pub(super) fn operands(&mut self, l: &syn::Expr, r: &syn::Expr, want: Option<&Ty>) -> Result<(Val, Val)> {
        let want = want.filter(|t| t.is_scalar());
        let lv = self.expr(l, want)?;
        let mut lv = self.load(lv);
        let rwant = if is_untyped(&lv.ty) {
            want.cloned()
        } else {
            Some(lv.ty.clone())
        };
        let rv = self.expr(r, rwant.as_ref())?;
        let rv = self.load(rv);
        if is_untyped(&lv.ty) && !is_untyped(&rv.ty) {
            let again = self.expr(l, Some(&rv.ty))?;
            lv = self.load(again);
        }
        if !is_untyped(&lv.ty) && !is_untyped(&rv.ty) && lv.ty != rv.ty {
            return Err(self.err(
                r,
                format!(
                    "mismatched operand types `{}` and `{}`; convert one with `as`",
                    lv.ty.rust(),
                    rv.ty.rust()
                ),
            ));
        }
        Ok((lv, rv))
    }

    /// The right operand of a shift: WGSL wants a u32 amount.
    pub(super) fn shift_amount(&mut self, r: &syn::Expr) -> Result<Val> {
        let v = self.expr(r, None)?;
        let mut v = self.load(v);
        if is_untyped(&v.ty) {
            v = self.value(r, Some(&Ty::U32))?;
        }
        match v.ty {
            Ty::U32 => Ok(v),
            Ty::I32 => Ok(Val::atom(format!("u32({})", v.code), Ty::U32)),
            ref t => Err(self.err(r, format!("shift amounts must be integers, found `{}`", t.rust()))),
        }
    }

    fn binary(&mut self, b: &syn::ExprBinary, want: Option<&Ty>) -> Result<Val> {
        use syn::BinOp as B;
        let (op, kind) = match b.op {
            B::Add(_) => ("+", Kind::Arith),
            B::Sub(_) => ("-", Kind::Arith),
            B::Mul(_) => ("*", Kind::Arith),
            B::Div(_) => ("/", Kind::Arith),
            B::Rem(_) => ("%", Kind::Arith),
            B::BitAnd(_) => ("&", Kind::Bit),
            B::BitOr(_) => ("|", Kind::Bit),
            B::BitXor(_) => ("^", Kind::Bit),
            B::And(_) => ("&&", Kind::Logic),
            B::Or(_) => ("||", Kind::Logic),
            B::Eq(_) => ("==", Kind::Cmp),
            B::Ne(_) => ("!=", Kind::Cmp),
            B::Lt(_) => ("<", Kind::Cmp),
            B::Le(_) => ("<=", Kind::Cmp),
            B::Gt(_) => (">", Kind::Cmp),
            B::Ge(_) => (">=", Kind::Cmp),
            B::Shl(_) => ("<<", Kind::Shift),
            B::Shr(_) => (">>", Kind::Shift),
            _ => {
                return Err(self.err(
                    b,
                    "compound assignment cannot be used as a value; write it as its own statement",
                ))
            }
        };
        match kind {
            Kind::Arith | Kind::Bit => {
                let (l, r) = self.operands(&b.left, &b.right, want)?;
                let ok = match kind {
                    Kind::Arith => l.ty.is_numeric() || is_untyped(&l.ty),
                    _ => l.ty.is_int() || l.ty == Ty::Bool || is_untyped(&l.ty),
                };
                if !ok {
                    return Err(self.err(b, format!("`{op}` is not defined for `{}`", l.ty.rust())));
                }
                // WGSL has no `^` on bool; for bools it is `!=`.
                let op = if op == "^" && l.ty == Ty::Bool { "!=" } else { op };
                let code = format!("{} {op} {}", l.operand(op, true), r.operand(op, false));
                let ty = if is_untyped(&l.ty) { r.ty } else { l.ty };
                Ok(Val {
                    code,
                    ty,
                    prec: Prec::Binary(op),
                })
            }
            Kind::Logic => {
                let l = self.typed(&b.left, Some(&Ty::Bool))?;
                let r = self.typed(&b.right, Some(&Ty::Bool))?;
                let code = format!("{} {op} {}", l.operand(op, true), r.operand(op, false));
                Ok(Val {
                    code,
                    ty: Ty::Bool,
                    prec: Prec::Binary(op),
                })
            }
            Kind::Cmp => {
                let (l, r) = self.operands(&b.left, &b.right, None)?;
                if is_untyped(&l.ty) {
                    return Err(self.err(
                        b,
                        "cannot infer the integer type of this comparison; add a suffix (`0u32`, `0i32`)",
                    ));
                }
                if !l.ty.is_scalar() {
                    return Err(self.err(
                        b,
                        format!(
                            "`{op}` only compares u32/i32/f32/bool values, not `{}`; compare fields one by one",
                            l.ty.rust()
                        ),
                    ));
                }
                let code = format!("{} {op} {}", l.operand(op, true), r.operand(op, false));
                Ok(Val {
                    code,
                    ty: Ty::Bool,
                    prec: Prec::Binary(op),
                })
            }
            Kind::Shift => {
                let l = self.expr(&b.left, want.filter(|t| t.is_int()))?;
                let l = self.load(l);
                if !(l.ty.is_int() || is_untyped(&l.ty)) {
                    return Err(self.err(b, format!("`{op}` is not defined for `{}`", l.ty.rust())));
                }
                let r = self.shift_amount(&b.right)?;
                let code = format!("{} {op} {}", l.operand(op, true), r.operand(op, false));
                Ok(Val {
                    code,
                    ty: l.ty,
                    prec: Prec::Binary(op),
                })
            }
        }
    }

    fn cast(&mut self, c: &syn::ExprCast) -> Result<Val> {
        if let syn::Type::Path(p) = &*c.ty {
            if p.path.is_ident("usize") {
                return Err(self.err(
                    &c.ty,
                    "`as usize` is only allowed directly inside an index (`a[i as usize]`); keep other values u32",
                ));
            }
        }
        let target = parse_ty(self.diag, &self.type_scope(), &c.ty)?;
        if !target.is_numeric() {
            return Err(self.err(&c.ty, "casts (`as`) are only supported to u32, i32 and f32"));
        }
        let v = self.expr(&c.expr, None)?;
        let mut v = self.load(v);
        if is_untyped(&v.ty) {
            if target.is_int() {
                return self.value(&c.expr, Some(&target));
            }
            // Rust types an unconstrained literal as i32 before the cast.
            v = self.value(&c.expr, Some(&Ty::I32))?;
        }
        if v.ty == target {
            return Ok(v);
        }
        match v.ty {
            Ty::Bool => {
                let (zero, one) = match target {
                    Ty::U32 => ("0u", "1u"),
                    Ty::I32 => ("0i", "1i"),
                    _ => ("0.0f", "1.0f"),
                };
                Ok(Val::atom(format!("select({zero}, {one}, {})", v.code), target))
            }
            Ty::U32 | Ty::I32 | Ty::F32 => Ok(Val::atom(format!("{}({})", target.wgsl(), v.code), target)),
            ref t => Err(self.err(c, format!("cannot cast `{}` with `as`", t.rust()))),
        }
    }

    pub(super) fn type_scope(&self) -> TypeScope<'_> {
        TypeScope {
            structs: &self.prog.struct_names,
            const_values: &self.prog.const_values,
        }
    }

    fn field(&mut self, f: &syn::ExprField) -> Result<Val> {
        let base = self.expr(&f.base, None)?;
        let base = self.load(base);
        let syn::Member::Named(ident) = &f.member else {
            return Err(self.err(f, "tuple fields are not supported; use a struct with named fields"));
        };
        let Ty::Struct(sname) = &base.ty else {
            return Err(self.err(f, format!("`{}` has no fields", base.ty.rust())));
        };
        let name = ident.to_string();
        let field_ty = self
            .prog
            .structs
            .get(sname)
            .and_then(|s| s.fields.iter().find(|(n, _)| *n == name))
            .map(|(_, t)| t.clone())
            .ok_or_else(|| self.err(ident, format!("struct `{sname}` has no field `{name}`")))?;
        Ok(Val::atom(format!("{}.{}", base.tight(), wgsl_ident(&name)), field_ty))
    }

    fn index(&mut self, i: &syn::ExprIndex) -> Result<Val> {
        let base = self.expr(&i.expr, None)?;
        let base = self.load(base);
        let Ty::Array(elem, _) = &base.ty else {
            return Err(self.err(&i.expr, format!("only arrays can be indexed, not `{}`", base.ty.rust())));
        };
        if matches!(&*i.index, syn::Expr::Range(_)) {
            return Err(self.err(&i.index, "slices are not supported; index elements one by one"));
        }
        // `as usize` is what Rust needs to index; WGSL indexes with u32/i32 directly.
        let mut index_expr = match &*i.index {
            syn::Expr::Cast(c) if matches!(&*c.ty, syn::Type::Path(p) if p.path.is_ident("usize")) => &*c.expr,
            other => other,
        };
        // `a[(i % 9) as usize]`: the parentheses were only needed for the cast.
        while let syn::Expr::Paren(p) = index_expr {
            index_expr = &p.expr;
        }
        let idx = self.value(index_expr, Some(&Ty::U32))?;
        if !idx.ty.is_int() {
            return Err(self.err(
                index_expr,
                format!("array indices must be u32 or i32, found `{}`", idx.ty.rust()),
            ));
        }
        Ok(Val::atom(format!("{}[{}]", base.tight(), idx.code), (**elem).clone()))
    }

    fn call(&mut self, c: &syn::ExprCall) -> Result<Val> {
        let syn::Expr::Path(p) = &*c.func else {
            return Err(self.err(&c.func, "only calls of functions by name are supported"));
        };
        let Some(ident) = p.path.get_ident() else {
            return Err(self.err(
                &c.func,
                "calls through paths (`a::b()`) are not supported; call functions defined in the kernel sources by name, and use methods like `x.min(y)` for builtins",
            ));
        };
        let name = ident.to_string();
        if self.in_const {
            return Err(self.err(c, "const initialisers cannot call functions; write the value out"));
        }
        if name == "table" {
            if c.args.len() != 1 {
                return Err(self.err(c, "`table` takes one u32 index: `table(i)`"));
            }
            let i = self.typed(&c.args[0], Some(&Ty::U32))?;
            return Ok(Val::atom(format!("tables[{}]", i.code), Ty::U32));
        }
        let prog = self.prog;
        let Some(f) = prog.fns.get(&name) else {
            let msg = match name.as_str() {
                "Some" | "None" | "Ok" | "Err" => "Option/Result are not supported; return a struct with a status field or use a sentinel value".to_string(),
                _ => format!("function `{name}` is not defined in the kernel sources (only those and the `table(i)` intrinsic can be called)"),
            };
            return Err(self.err(&c.func, msg));
        };
        if f.params.len() != c.args.len() {
            return Err(self.err(
                c,
                format!("`{name}` takes {} arguments, {} given", f.params.len(), c.args.len()),
            ));
        }
        let mut args = Vec::new();
        for (arg, param) in c.args.iter().zip(&f.params) {
            match &param.ty {
                Ty::Ptr(inner) => args.push(self.pointer_arg(arg, inner)?),
                ty => args.push(self.typed(arg, Some(ty))?.code),
            }
        }
        Ok(Val::atom(
            format!("{}({})", wgsl_ident(&name), args.join(", ")),
            f.ret.clone(),
        ))
    }

    /// An argument for a `&mut T` parameter: `&mut local` or a `&mut` parameter passed on.
    fn pointer_arg(&mut self, arg: &syn::Expr, inner: &Ty) -> Result<String> {
        let whole_local = "only a whole local variable can be passed as `&mut`: copy the value into a local (`let mut tmp = x.f;`), pass `&mut tmp`, then copy it back (`x.f = tmp;`)";
        let (code, ty) = match arg {
            syn::Expr::Reference(r) if r.mutability.is_some() => {
                let syn::Expr::Path(p) = &*r.expr else {
                    return Err(self.err(arg, whole_local));
                };
                let Some(local) = p.path.get_ident().and_then(|id| self.lookup(&id.to_string())) else {
                    return Err(self.err(arg, whole_local));
                };
                if matches!(local.ty, Ty::Ptr(_)) {
                    return Err(self.err(arg, "pass a `&mut` parameter on as it is (`g(p)`), not `&mut p`"));
                }
                if !local.mutable {
                    return Err(self.err(arg, "only `let mut` variables can be passed as `&mut`"));
                }
                (format!("&{}", local.wgsl), local.ty.clone())
            }
            syn::Expr::Reference(_) => return Err(self.err(arg, "this parameter is `&mut T`; pass `&mut x`")),
            syn::Expr::Path(p) => match p.path.get_ident().and_then(|id| self.lookup(&id.to_string())) {
                Some(super::Local {
                    wgsl, ty: Ty::Ptr(t), ..
                }) => (wgsl.clone(), (**t).clone()),
                _ => {
                    return Err(self.err(
                        arg,
                        "this parameter is `&mut T`; pass `&mut x` for a `let mut` local `x`",
                    ))
                }
            },
            _ => {
                return Err(self.err(
                    arg,
                    "this parameter is `&mut T`; pass `&mut x` for a `let mut` local `x`",
                ))
            }
        };
        if ty != *inner {
            return Err(self.err(
                arg,
                format!("expected `&mut {}`, found `&mut {}`", inner.rust(), ty.rust()),
            ));
        }
        Ok(code)
    }

    fn method(&mut self, m: &syn::ExprMethodCall, want: Option<&Ty>) -> Result<Val> {
        if m.turbofish.is_some() {
            return Err(self.err(m, "generic method calls are not supported"));
        }
        let name = m.method.to_string();
        let argc = |n: usize| -> Result<()> {
            if m.args.len() == n {
                Ok(())
            } else {
                Err(self.diag.node(m, format!("`.{name}()` takes {n} argument(s)")))
            }
        };
        match name.as_str() {
            "min" | "max" | "wrapping_add" | "wrapping_sub" | "wrapping_mul" => {
                argc(1)?;
                let (a, b) = self.operands(&m.receiver, &m.args[0], want)?;
                let ok = if name.starts_with("wrapping") { a.ty.is_int() || is_untyped(&a.ty) } else { a.ty.is_numeric() || is_untyped(&a.ty) };
                if !ok {
                    return Err(self.err(m, format!("`.{name}()` is not defined for `{}`", a.ty.rust())));
                }
                let ty = if is_untyped(&a.ty) { b.ty.clone() } else { a.ty.clone() };
                // WGSL integer arithmetic already wraps.
                let op = match name.as_str() {
                    "wrapping_add" => "+",
                    "wrapping_sub" => "-",
                    "wrapping_mul" => "*",
                    _ => return Ok(Val::atom(format!("{name}({}, {})", a.code, b.code), ty)),
                };
                let code = format!("{} {op} {}", a.operand(op, true), b.operand(op, false));
                Ok(Val { code, ty, prec: Prec::Binary(op) })
            }
            "count_ones" | "trailing_zeros" | "leading_zeros" => {
                argc(0)?;
                let v = self.value(&m.receiver, None)?;
                let builtin = match name.as_str() {
                    "count_ones" => "countOneBits",
                    "trailing_zeros" => "countTrailingZeros",
                    _ => "countLeadingZeros",
                };
                match v.ty {
                    Ty::U32 => Ok(Val::atom(format!("{builtin}({})", v.code), Ty::U32)),
                    // Rust returns u32 for these on every integer type.
                    Ty::I32 => Ok(Val::atom(format!("u32({builtin}({}))", v.code), Ty::U32)),
                    ref t => Err(self.err(m, format!("`.{name}()` is not defined for `{}`", t.rust()))),
                }
            }
            "abs" => {
                argc(0)?;
                let v = self.value(&m.receiver, want)?;
                match v.ty {
                    Ty::I32 | Ty::F32 => Ok(Val::atom(format!("abs({})", v.code), v.ty)),
                    ref t => Err(self.err(m, format!("`.abs()` is not defined for `{}`", t.rust()))),
                }
            }
            // Kernel types are Copy, so clone is a plain copy.
            "clone" => {
                argc(0)?;
                self.value(&m.receiver, want)
            }
            "iter" | "iter_mut" | "into_iter" | "map" | "sum" | "fold" | "enumerate" | "zip" | "rev" | "step_by"
            | "filter" | "any" | "all" | "collect" | "len" | "contains" | "position" | "copied" | "cloned" => Err(self.err(
                &m.method,
                format!("`.{name}()` is not supported (no iterators or slice methods); use an index loop `for i in 0..N {{ ... a[i as usize] ... }}`"),
            )),
            _ => Err(self.err(
                &m.method,
                format!("method `.{name}()` is not supported; available: min, max, count_ones, trailing_zeros, leading_zeros, wrapping_add/sub/mul, abs, clone; otherwise write a free function"),
            )),
        }
    }

    fn struct_lit(&mut self, s: &syn::ExprStruct) -> Result<Val> {
        if s.rest.is_some() || s.dot2_token.is_some() {
            return Err(self.err(s, "`..base` in struct literals is not supported; list every field"));
        }
        let Some(name) = s.path.get_ident().map(|i| i.to_string()) else {
            return Err(self.err(
                &s.path,
                "struct literals must name a struct defined in the kernel sources",
            ));
        };
        let prog = self.prog;
        let Some(def) = prog.structs.get(&name) else {
            return Err(self.err(&s.path, format!("unknown struct `{name}`")));
        };
        let mut given: Vec<(String, &syn::Expr, &syn::FieldValue)> = Vec::new();
        for fv in &s.fields {
            let syn::Member::Named(id) = &fv.member else {
                return Err(self.err(fv, "tuple fields are not supported"));
            };
            let fname = id.to_string();
            if !def.fields.iter().any(|(n, _)| *n == fname) {
                return Err(self.err(id, format!("struct `{name}` has no field `{fname}`")));
            }
            if given.iter().any(|(n, _, _)| *n == fname) {
                return Err(self.err(id, format!("field `{fname}` given twice")));
            }
            given.push((fname, &fv.expr, fv));
        }
        let mut args = Vec::new();
        for (fname, fty) in &def.fields {
            let Some((_, e, _)) = given.iter().find(|(n, _, _)| n == fname) else {
                return Err(self.err(s, format!("missing field `{fname}` in `{name}` literal")));
            };
            args.push(self.typed(e, Some(fty))?.code);
        }
        Ok(Val::atom(
            format!("{}({})", wgsl_ident(&name), args.join(", ")),
            Ty::Struct(name),
        ))
    }

    fn array_lit(&mut self, a: &syn::ExprArray, want: Option<&Ty>) -> Result<Val> {
        if a.elems.is_empty() {
            return Err(self.err(a, "empty arrays are not supported"));
        }
        let elem_want = match want {
            Some(Ty::Array(e, _)) => Some((**e).clone()),
            _ => None,
        };
        let mut vals = Vec::new();
        for e in &a.elems {
            let v = self.expr(e, elem_want.as_ref())?;
            vals.push(self.load(v));
        }
        let elem_ty = match vals.iter().find(|v| !is_untyped(&v.ty)) {
            Some(v) => v.ty.clone(),
            None => {
                return Err(self.err(
                    a,
                    "cannot infer the element type of this array; add a suffix (`0u32`) or a type annotation",
                ))
            }
        };
        let mut codes = Vec::new();
        for (e, v) in a.elems.iter().zip(vals) {
            let v = if is_untyped(&v.ty) {
                self.typed(e, Some(&elem_ty))?
            } else {
                v
            };
            if v.ty != elem_ty {
                return Err(self.err(e, format!("array elements must all be `{}`", elem_ty.rust())));
            }
            codes.push(v.code);
        }
        let ty = Ty::Array(Box::new(elem_ty), codes.len() as u32);
        Ok(Val::atom(format!("{}({})", ty.wgsl(), codes.join(", ")), ty))
    }

    fn repeat(&mut self, r: &syn::ExprRepeat, want: Option<&Ty>) -> Result<Val> {
        let n = eval_len(self.diag, &self.prog.const_values, &r.len)?;
        let elem_want = match want {
            Some(Ty::Array(e, _)) => Some((**e).clone()),
            _ => None,
        };
        let v = self.value(&r.expr, elem_want.as_ref())?;
        let ty = Ty::Array(Box::new(v.ty.clone()), n);
        if is_zero(&r.expr) {
            // The zero-value constructor, instead of N copies of zero.
            return Ok(Val::atom(format!("{}()", ty.wgsl()), ty));
        }
        if n > 256 {
            return Err(self.err(r, "repeat expressions with a non-zero value are limited to 256 elements; start from zeros (`[0u32; N]`) and fill in a loop"));
        }
        if !self.is_pure(&r.expr) {
            return Err(self.err(
                &r.expr,
                "the repeated value must not have side effects; compute it into a local first",
            ));
        }
        let copies = vec![v.code; n as usize];
        Ok(Val::atom(format!("{}({})", ty.wgsl(), copies.join(", ")), ty))
    }

    /// `if c { a } else { b }` as a value: WGSL's `select`, which evaluates both sides, so
    /// both must be single side-effect-free expressions.
    fn select(&mut self, i: &syn::ExprIf, want: Option<&Ty>) -> Result<Val> {
        let advice = "an `if` used as a value must have single side-effect-free expressions in both branches (it becomes WGSL `select`); otherwise declare `let mut x: T = ...;` and assign it in `if`/`else` statements";
        let Some((_, else_expr)) = &i.else_branch else {
            return Err(self.err(i, "an `if` used as a value needs an `else` branch"));
        };
        let Some(then_expr) = single_expr(&i.then_branch) else {
            return Err(self.err(i, advice));
        };
        let else_single = match &**else_expr {
            syn::Expr::Block(b) => match single_expr(&b.block) {
                Some(e) => Some(e),
                None => return Err(self.err(&**else_expr, advice)),
            },
            // `else if` chains are nested selects; the inner `select` checks its branches.
            _ => None,
        };
        if !self.is_pure(then_expr) || else_single.is_some_and(|e| !self.is_pure(e)) {
            return Err(self.err(i, advice));
        }
        let cond = self.typed(&i.cond, Some(&Ty::Bool))?;
        let (a, b) = self.operands(then_expr, else_expr, want)?;
        let ty = if is_untyped(&a.ty) { b.ty.clone() } else { a.ty.clone() };
        Ok(Val::atom(format!("select({}, {}, {})", b.code, a.code, cond.code), ty))
    }

    /// Whether evaluating `e` cannot change any variable (so it may be evaluated
    /// speculatively or more than once).
    pub(super) fn is_pure(&self, e: &syn::Expr) -> bool {
        use syn::visit::Visit;
        struct Purity<'l, 'p, 'a> {
            lw: &'l Lowerer<'p, 'a>,
            pure: bool,
        }
        impl<'ast> Visit<'ast> for Purity<'_, '_, '_> {
            fn visit_expr(&mut self, e: &'ast syn::Expr) {
                use syn::Expr as E;
                match e {
                    E::Assign(_)
                    | E::Reference(_)
                    | E::Macro(_)
                    | E::Loop(_)
                    | E::While(_)
                    | E::ForLoop(_)
                    | E::Match(_)
                    | E::Return(_)
                    | E::Break(_)
                    | E::Continue(_)
                    | E::Closure(_) => self.pure = false,
                    E::Binary(b) if is_compound(&b.op) => self.pure = false,
                    // Passing a `&mut` parameter on lets the callee write through it.
                    E::Call(c) => {
                        for arg in &c.args {
                            if let E::Path(p) = arg {
                                if let Some(local) = p.path.get_ident().and_then(|id| self.lw.lookup(&id.to_string())) {
                                    if matches!(local.ty, Ty::Ptr(_)) {
                                        self.pure = false;
                                    }
                                }
                            }
                        }
                    }
                    _ => {}
                }
                syn::visit::visit_expr(self, e);
            }
        }
        let mut p = Purity { lw: self, pure: true };
        p.visit_expr(e);
        p.pure
    }
}

#[derive(Clone, Copy)]
enum Kind {
    Arith,
    Bit,
    Logic,
    Cmp,
    Shift,
}

pub(crate) fn is_compound(op: &syn::BinOp) -> bool {
    use syn::BinOp as B;
    matches!(
        op,
        B::AddAssign(_)
            | B::SubAssign(_)
            | B::MulAssign(_)
            | B::DivAssign(_)
            | B::RemAssign(_)
            | B::BitXorAssign(_)
            | B::BitAndAssign(_)
            | B::BitOrAssign(_)
            | B::ShlAssign(_)
            | B::ShrAssign(_)
    )
}

/// The expression of a block that is just `{ expr }`.
pub(crate) fn single_expr(block: &syn::Block) -> Option<&syn::Expr> {
    match block.stmts.as_slice() {
        [syn::Stmt::Expr(e, None)] => Some(e),
        _ => None,
    }
}

/// A zero value (`0`, `0u32`, `0.0`, `false`, or a repeat of one).
fn is_zero(e: &syn::Expr) -> bool {
    match e {
        syn::Expr::Lit(l) => match &l.lit {
            syn::Lit::Int(i) => i.base10_digits() == "0",
            syn::Lit::Float(f) => f
                .base10_parse::<f64>()
                .is_ok_and(|v| v == 0.0 && !f.base10_digits().starts_with('-')),
            syn::Lit::Bool(b) => !b.value,
            _ => false,
        },
        syn::Expr::Repeat(r) => is_zero(&r.expr),
        syn::Expr::Paren(p) => is_zero(&p.expr),
        _ => false,
    }
}
