//! Statement lowering.

use std::collections::HashMap;

use super::expr::{is_compound, macro_message, single_expr, unsupported_expr};
use super::{Breakable, Lowerer};
use crate::diag::Result;
use crate::names::wgsl_ident;
use crate::types::{parse_ty, Ty};

impl Lowerer<'_, '_> {
    pub(super) fn fn_body(&mut self, block: &syn::Block) -> Result<()> {
        let valued = self.ret != Ty::Unit;
        self.stmts(&block.stmts, valued)?;
        if valued {
            if let Some(syn::Stmt::Expr(syn::Expr::Loop(_), _)) = block.stmts.last() {
                // naga wants every valued function to end in `return`, even after a loop
                // that only leaves through `return`.
                self.line("// unreachable: the loop above only exits through `return`");
                let zero = format!("return {}();", self.ret.wgsl());
                self.line(&zero);
            }
        }
        Ok(())
    }

    fn block(&mut self, block: &syn::Block, ret_pos: bool) -> Result<()> {
        self.scopes.push(HashMap::new());
        let r = self.stmts(&block.stmts, ret_pos);
        self.scopes.pop();
        r
    }

    /// `ret_pos`: the block's tail expression is the function's return value.
    fn stmts(&mut self, stmts: &[syn::Stmt], ret_pos: bool) -> Result<()> {
        for (i, s) in stmts.iter().enumerate() {
            let last = i + 1 == stmts.len();
            match s {
                syn::Stmt::Local(l) => self.local(l)?,
                syn::Stmt::Item(item) => {
                    return Err(self.diag.node(
                        item,
                        "items inside functions are not supported; move it to module level",
                    ))
                }
                syn::Stmt::Macro(m) => return Err(self.diag.node(m, macro_message(&m.mac))),
                syn::Stmt::Expr(e, None) if ret_pos && last => self.tail_return(e)?,
                syn::Stmt::Expr(e, _) => self.stmt_expr(e)?,
            }
        }
        Ok(())
    }

    fn tail_return(&mut self, e: &syn::Expr) -> Result<()> {
        use syn::Expr as E;
        match e {
            E::If(i) if i.else_branch.is_some() => self.if_stmt(i, true),
            E::Match(m) => self.match_stmt(m, true),
            E::Block(b) if b.label.is_none() && single_expr(&b.block).is_none() => {
                self.line("{");
                self.indent += 1;
                self.block(&b.block, true)?;
                self.indent -= 1;
                self.line("}");
                Ok(())
            }
            E::Loop(_) | E::Return(_) => self.stmt_expr(e),
            _ => {
                let ret = self.ret.clone();
                let v = self.typed(e, Some(&ret))?;
                self.line(&format!("return {};", v.code));
                Ok(())
            }
        }
    }

    fn no_label(&self, label: &Option<syn::Label>) -> Result<()> {
        match label {
            Some(l) => Err(self
                .diag
                .node(l, "loop labels are not supported; use a `bool` flag and plain `break`")),
            None => Ok(()),
        }
    }

    fn stmt_expr(&mut self, e: &syn::Expr) -> Result<()> {
        use syn::Expr as E;
        match e {
            E::Assign(a) => self.assign(a),
            E::Binary(b) if is_compound(&b.op) => self.compound(b),
            E::If(i) => self.if_stmt(i, false),
            E::While(w) => {
                self.no_label(&w.label)?;
                let cond = self.typed(&w.cond, Some(&Ty::Bool))?;
                self.line(&format!("while {} {{", cond.code));
                self.loop_body(&w.body)
            }
            E::Loop(l) => {
                self.no_label(&l.label)?;
                self.line("loop {");
                self.loop_body(&l.body)
            }
            E::ForLoop(f) => self.for_loop(f),
            E::Match(m) => self.match_stmt(m, false),
            E::Block(b) => {
                self.no_label(&b.label)?;
                self.line("{");
                self.indent += 1;
                self.block(&b.block, false)?;
                self.indent -= 1;
                self.line("}");
                Ok(())
            }
            E::Return(r) => {
                match &r.expr {
                    None => self.line("return;"),
                    Some(v) => {
                        let ret = self.ret.clone();
                        let v = self.typed(v, Some(&ret))?;
                        self.line(&format!("return {};", v.code));
                    }
                }
                Ok(())
            }
            E::Break(b) => {
                if b.label.is_some() {
                    return Err(self
                        .diag
                        .node(b, "loop labels are not supported; use a `bool` flag and plain `break`"));
                }
                if b.expr.is_some() {
                    return Err(self.diag.node(
                        b,
                        "`break value` is not supported; assign a `let mut` variable, then `break`",
                    ));
                }
                self.emit_break(b)
            }
            E::Continue(c) => {
                if c.label.is_some() {
                    return Err(self.diag.node(
                        c,
                        "loop labels are not supported; use a `bool` flag and plain `continue`",
                    ));
                }
                self.line("continue;");
                Ok(())
            }
            E::Call(_) | E::MethodCall(_) => {
                let v = self.expr(e, None)?;
                let v = self.load(v);
                if v.ty == Ty::Unit {
                    self.line(&format!("{};", v.code));
                } else {
                    self.line(&format!("_ = {};", v.code));
                }
                Ok(())
            }
            E::Tuple(t) if t.elems.is_empty() => Ok(()),
            E::Paren(p) => self.stmt_expr(&p.expr),
            E::Group(g) => self.stmt_expr(&g.expr),
            _ => {
                // Lower it for its diagnostics; a side-effect-free statement is a mistake.
                self.expr(e, None)?;
                Err(self.diag.node(
                    e,
                    "this expression statement has no effect; remove it or assign it (`_ = value;`)",
                ))
            }
        }
    }

    fn loop_body(&mut self, body: &syn::Block) -> Result<()> {
        self.breakables.push(Breakable::Loop);
        self.indent += 1;
        let r = self.block(body, false);
        self.indent -= 1;
        self.breakables.pop();
        r?;
        self.line("}");
        Ok(())
    }

    fn emit_break(&mut self, at: &impl syn::spanned::Spanned) -> Result<()> {
        let needs_flag = match self.breakables.last() {
            None => return Err(self.diag.node(at, "`break` outside a loop")),
            Some(Breakable::Loop) => false,
            Some(Breakable::Switch { flag }) => flag.is_none(),
        };
        if needs_flag {
            let name = self.fresh("exit_loop");
            if let Some(Breakable::Switch { flag }) = self.breakables.last_mut() {
                *flag = Some(name);
            }
        }
        if let Some(Breakable::Switch { flag: Some(flag) }) = self.breakables.last() {
            let set = format!("{flag} = true;");
            self.line(&set);
        }
        self.line("break;");
        Ok(())
    }

    /// Checks that `e` names something Rust lets us assign to, and lowers it.
    fn place(&mut self, e: &syn::Expr) -> Result<super::Val> {
        let mut root = e;
        let mut through_ptr = false;
        loop {
            root = match root {
                syn::Expr::Field(f) => &f.base,
                syn::Expr::Index(i) => &i.expr,
                syn::Expr::Paren(p) => &p.expr,
                syn::Expr::Unary(u) if matches!(u.op, syn::UnOp::Deref(_)) => {
                    through_ptr = true;
                    &u.expr
                }
                _ => break,
            };
        }
        let syn::Expr::Path(p) = root else {
            return Err(self
                .diag
                .node(e, "can only assign to variables, their fields and elements"));
        };
        let name = p.path.get_ident().map(|i| i.to_string()).unwrap_or_default();
        let Some(local) = self.lookup(&name) else {
            let what = if self.prog.consts.contains_key(&name) {
                "consts cannot be assigned"
            } else {
                "can only assign to local variables"
            };
            return Err(self.diag.node(root, what));
        };
        let is_ptr = matches!(local.ty, Ty::Ptr(_));
        if is_ptr {
            if !through_ptr && std::ptr::eq(root, e) {
                return Err(self.diag.node(e, "assign through the reference: `*p = value;`"));
            }
        } else if !(local.var && local.mutable) {
            return Err(self
                .diag
                .node(root, format!("cannot assign to `{name}`; declare it with `let mut`")));
        }
        let v = self.expr(e, None)?;
        Ok(self.load(v))
    }

    fn assign(&mut self, a: &syn::ExprAssign) -> Result<()> {
        if let syn::Expr::Infer(_) = &*a.left {
            let v = self.value(&a.right, None)?;
            self.line(&format!("_ = {};", v.code));
            return Ok(());
        }
        let place = self.place(&a.left)?;
        let v = self.typed(&a.right, Some(&place.ty))?;
        self.line(&format!("{} = {};", place.code, v.code));
        Ok(())
    }

    fn compound(&mut self, b: &syn::ExprBinary) -> Result<()> {
        use syn::BinOp as B;
        let place = self.place(&b.left)?;
        let op = match b.op {
            B::AddAssign(_) => "+=",
            B::SubAssign(_) => "-=",
            B::MulAssign(_) => "*=",
            B::DivAssign(_) => "/=",
            B::RemAssign(_) => "%=",
            B::BitXorAssign(_) => "^=",
            B::BitAndAssign(_) => "&=",
            B::BitOrAssign(_) => "|=",
            B::ShlAssign(_) => "<<=",
            _ => ">>=",
        };
        let ok = match op {
            "+=" | "-=" | "*=" | "/=" | "%=" => place.ty.is_numeric(),
            "<<=" | ">>=" => place.ty.is_int(),
            _ => place.ty.is_int() || place.ty == Ty::Bool,
        };
        if !ok {
            return Err(self
                .diag
                .node(b, format!("`{op}` is not defined for `{}`", place.ty.rust())));
        }
        let rhs = if op == "<<=" || op == ">>=" {
            self.shift_amount(&b.right)?
        } else {
            self.typed(&b.right, Some(&place.ty))?
        };
        if op == "^=" && place.ty == Ty::Bool {
            // WGSL has no `^` on bool.
            self.line(&format!("{} = {} != {};", place.code, place.code, rhs.tight()));
        } else {
            self.line(&format!("{} {op} {};", place.code, rhs.code));
        }
        Ok(())
    }

    fn local(&mut self, l: &syn::Local) -> Result<()> {
        let (pat, ann) = match &l.pat {
            syn::Pat::Type(pt) => (&*pt.pat, Some(&*pt.ty)),
            p => (p, None),
        };
        let (name, mutable) = match pat {
            syn::Pat::Ident(pi) if pi.by_ref.is_none() && pi.subpat.is_none() => {
                (pi.ident.to_string(), pi.mutability.is_some())
            }
            syn::Pat::Wild(_) => ("_".to_string(), false),
            syn::Pat::Tuple(_) | syn::Pat::TupleStruct(_) => {
                return Err(self
                    .diag
                    .node(pat, "tuples are not supported; use a struct with named fields"))
            }
            other => {
                return Err(self.diag.node(
                    other,
                    "destructuring is not supported; bind a plain name (`let x = ...;`)",
                ))
            }
        };
        let ann_ty = match ann {
            Some(t) => Some(parse_ty(self.diag, &self.type_scope(), t)?),
            None => None,
        };
        let Some(init) = &l.init else {
            let Some(ty) = ann_ty else {
                return Err(self
                    .diag
                    .node(l, format!("`let {name};` needs a type annotation (`let {name}: u32;`)")));
            };
            let wgsl = self.declare(&name, ty.clone(), true, true);
            self.line(&format!("var {wgsl}: {};", ty.wgsl()));
            return Ok(());
        };
        if let Some((_, diverge)) = &init.diverge {
            return Err(self.diag.node(&**diverge, "`let ... else` is not supported"));
        }
        let v = match &ann_ty {
            Some(t) => self.typed(&init.expr, Some(t))?,
            None => {
                let v = self.expr(&init.expr, None)?;
                if v.ty == Ty::IntLit {
                    return Err(self.diag.node(
                        &init.expr,
                        format!("cannot infer the type of `{name}`; write a suffixed literal (`0u32`, `0i32`) or annotate it (`let {name}: u32 = ...;`)"),
                    ));
                }
                if let Ty::Ptr(_) = v.ty {
                    return Err(self.diag.node(
                        &init.expr,
                        "references cannot be stored in locals; use the `&mut` parameter directly",
                    ));
                }
                v
            }
        };
        if v.ty == Ty::Unit {
            return Err(self.diag.node(&init.expr, "this expression has no value"));
        }
        if name == "_" {
            self.line(&format!("_ = {};", v.code));
            return Ok(());
        }
        let var = mutable || self.contains_array(&v.ty);
        let wgsl = self.declare(&name, v.ty.clone(), var, mutable);
        let kw = if var { "var" } else { "let" };
        self.line(&format!("{kw} {wgsl}: {} = {};", v.ty.wgsl(), v.code));
        Ok(())
    }

    fn if_stmt(&mut self, i: &syn::ExprIf, ret_pos: bool) -> Result<()> {
        let cond = self.typed(&i.cond, Some(&Ty::Bool))?;
        self.line(&format!("if {} {{", cond.code));
        self.indent += 1;
        self.block(&i.then_branch, ret_pos)?;
        self.indent -= 1;
        let mut next = &i.else_branch;
        while let Some((_, e)) = next {
            match &**e {
                syn::Expr::If(ei) => {
                    let cond = self.typed(&ei.cond, Some(&Ty::Bool))?;
                    self.line(&format!("}} else if {} {{", cond.code));
                    self.indent += 1;
                    self.block(&ei.then_branch, ret_pos)?;
                    self.indent -= 1;
                    next = &ei.else_branch;
                }
                syn::Expr::Block(b) => {
                    self.line("} else {");
                    self.indent += 1;
                    self.block(&b.block, ret_pos)?;
                    self.indent -= 1;
                    next = &None;
                }
                other => return Err(self.diag.node(other, unsupported_expr(other))),
            }
        }
        self.line("}");
        Ok(())
    }

    fn for_loop(&mut self, f: &syn::ExprForLoop) -> Result<()> {
        self.no_label(&f.label)?;
        let name = match &*f.pat {
            syn::Pat::Ident(pi) if pi.by_ref.is_none() && pi.subpat.is_none() => {
                if pi.mutability.is_some() {
                    return Err(self.diag.node(
                        &*f.pat,
                        "`for mut i` is not supported (changing `i` would change the iteration in WGSL); copy it: `let mut j = i;`",
                    ));
                }
                pi.ident.to_string()
            }
            syn::Pat::Wild(_) => "_".to_string(),
            other => return Err(self.diag.node(other, "the loop variable must be a plain name")),
        };
        let range_advice =
            "only `for i in a..b` and `for i in a..=b` are supported (no iterators); index arrays with `a[i as usize]`";
        let syn::Expr::Range(range) = &*f.expr else {
            return Err(self.diag.node(&*f.expr, range_advice));
        };
        let (Some(start), Some(end)) = (&range.start, &range.end) else {
            return Err(self.diag.node(range, range_advice));
        };
        let (mut s, mut e) = self.operands(start, end, None)?;
        if s.ty == Ty::IntLit {
            // Both bounds are unsuffixed literals: u32, the kernel subset's index type.
            s = self.typed(start, Some(&Ty::U32))?;
            e = self.typed(end, Some(&Ty::U32))?;
        }
        if !s.ty.is_int() {
            return Err(self.diag.node(
                range,
                format!("range bounds must be u32 or i32, found `{}`", s.ty.rust()),
            ));
        }
        let ty = s.ty.clone();
        // Rust evaluates the end once; WGSL re-evaluates the condition, so anything that
        // could change during the loop is hoisted into a `let`.
        let hoist = !self.is_stable(end);
        self.scopes.push(HashMap::new());
        let var_name = self.declare(&name, ty.clone(), true, false);
        let end_code = if hoist {
            let end_name = self.fresh(&format!("{}_end", wgsl_ident(if name == "_" { "i" } else { &name })));
            self.line("{");
            self.indent += 1;
            self.line(&format!("let {end_name}: {} = {};", ty.wgsl(), e.code));
            end_name
        } else {
            e.code
        };
        let cmp = if matches!(range.limits, syn::RangeLimits::Closed(_)) {
            "<="
        } else {
            "<"
        };
        self.line(&format!(
            "for (var {var_name}: {} = {}; {var_name} {cmp} {end_code}; {var_name}++) {{",
            ty.wgsl(),
            s.code
        ));
        let r = self.loop_body(&f.body);
        self.scopes.pop();
        r?;
        if hoist {
            self.indent -= 1;
            self.line("}");
        }
        Ok(())
    }

    /// Whether `e` has the same value for the whole loop.
    fn is_stable(&self, e: &syn::Expr) -> bool {
        match e {
            syn::Expr::Lit(_) => true,
            syn::Expr::Path(p) => match p.path.get_ident().map(|i| i.to_string()) {
                Some(name) => match self.lookup(&name) {
                    Some(local) => !local.mutable && !matches!(local.ty, Ty::Ptr(_)),
                    None => self.prog.consts.contains_key(&name),
                },
                None => true,
            },
            syn::Expr::Paren(p) => self.is_stable(&p.expr),
            syn::Expr::Group(g) => self.is_stable(&g.expr),
            syn::Expr::Unary(u) => !matches!(u.op, syn::UnOp::Deref(_)) && self.is_stable(&u.expr),
            syn::Expr::Binary(b) => !is_compound(&b.op) && self.is_stable(&b.left) && self.is_stable(&b.right),
            syn::Expr::Cast(c) => self.is_stable(&c.expr),
            syn::Expr::Field(f) => self.is_stable(&f.base),
            _ => false,
        }
    }

    fn match_stmt(&mut self, m: &syn::ExprMatch, ret_pos: bool) -> Result<()> {
        let scrut = self.value(&m.expr, None)?;
        if !scrut.ty.is_int() {
            return Err(self.diag.node(
                &m.expr,
                format!(
                    "`match` is only supported on u32/i32 values (it becomes a WGSL `switch`), not `{}`; use if/else",
                    scrut.ty.rust()
                ),
            ));
        }
        let flag_at = self.out.len();
        let flag_indent = self.indent;
        self.line(&format!("switch {} {{", scrut.code));
        self.indent += 1;
        self.breakables.push(Breakable::Switch { flag: None });
        let r = self.arms(m, &scrut.ty, ret_pos);
        let flag = match self.breakables.pop() {
            Some(Breakable::Switch { flag }) => flag,
            _ => None,
        };
        r?;
        self.indent -= 1;
        self.line("}");
        if let Some(flag) = flag {
            let decl = format!("{}var {flag}: bool = false;\n", "    ".repeat(flag_indent));
            self.out.insert_str(flag_at, &decl);
            self.line(&format!("if {flag} {{"));
            self.indent += 1;
            self.emit_break(m)?;
            self.indent -= 1;
            self.line("}");
        }
        Ok(())
    }

    fn arms(&mut self, m: &syn::ExprMatch, ty: &Ty, ret_pos: bool) -> Result<()> {
        let mut has_default = false;
        for arm in &m.arms {
            let mut selectors = Vec::new();
            self.selectors(&arm.pat, ty, &mut selectors)?;
            has_default |= selectors.iter().any(|s| s == "default");
            if selectors == ["default"] {
                self.line("default: {");
            } else {
                self.line(&format!("case {}: {{", selectors.join(", ")));
            }
            let body_at = self.out.len();
            self.indent += 1;
            self.scopes.push(HashMap::new());
            let r = match &*arm.body {
                syn::Expr::Block(b) if b.label.is_none() => self.stmts(&b.block.stmts, ret_pos),
                e if ret_pos => self.tail_return(e),
                e => self.stmt_expr(e),
            };
            self.scopes.pop();
            r?;
            self.indent -= 1;
            if self.out.len() == body_at && self.out.ends_with("{\n") {
                // An empty arm reads better as `{}` on one line.
                self.out.truncate(body_at - 1);
                self.out.push_str("}\n");
            } else {
                self.line("}");
            }
        }
        if !has_default {
            self.line("default: {}");
        }
        Ok(())
    }

    fn selectors(&mut self, pat: &syn::Pat, ty: &Ty, out: &mut Vec<String>) -> Result<()> {
        match pat {
            syn::Pat::Lit(l) => {
                let e = syn::Expr::Lit(l.clone());
                out.push(self.typed(&e, Some(ty))?.code);
            }
            syn::Pat::Or(o) => {
                for case in &o.cases {
                    self.selectors(case, ty, out)?;
                }
            }
            syn::Pat::Paren(p) => self.selectors(&p.pat, ty, out)?,
            syn::Pat::Wild(_) => out.push("default".into()),
            syn::Pat::Path(p) => {
                let name = p.path.get_ident().map(|i| i.to_string()).unwrap_or_default();
                match self.prog.consts.get(&name) {
                    Some(c) if !c.private && c.ty == *ty => out.push(wgsl_ident(&name)),
                    _ => {
                        return Err(self.diag.node(
                            p,
                            format!(
                                "match arms may name integer consts of type `{}`; `{name}` is not one",
                                ty.rust()
                            ),
                        ))
                    }
                }
            }
            syn::Pat::Range(_) => {
                return Err(self.diag.node(
                    pat,
                    "ranges in match arms are not supported; list the values (`1 | 2 | 3 =>`) or use if/else",
                ))
            }
            syn::Pat::Guard(_) => {
                return Err(self
                    .diag
                    .node(pat, "match guards (`if`) are not supported; use if/else inside the arm"))
            }
            syn::Pat::Ident(_) => {
                return Err(self.diag.node(
                    pat,
                    "binding patterns are not supported; use `_` and refer to the matched value",
                ))
            }
            _ => {
                return Err(self.diag.node(
                    pat,
                    "match arms support integer literals, integer consts, `|` and `_` only",
                ))
            }
        }
        Ok(())
    }
}
