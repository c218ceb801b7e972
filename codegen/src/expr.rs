//! The yaku condition language: `when = "concealed && standard && runs == 4"`.
//!
//! Grammar, loosest binding first:
//! ```text
//! or      := and ( "||" and )*
//! and     := cmp ( "&&" cmp )*
//! cmp     := sum ( ("==" | "!=" | "<" | "<=" | ">" | ">=") sum )?   // not chained
//! sum     := unary ( ("+" | "-") unary )*
//! unary   := "!" unary | primary
//! primary := identifier | unsigned integer | "(" or ")"
//! ```
//! Two types, bool and int. Identifiers name a `Features` field (bool or u32) or a boolean option
//! from the variant's `[yaku_rules]`. Offsets in errors are byte offsets into the condition text;
//! the caller maps them to the file.

use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;

/// Literals stay small so that sums of them can never overflow the kernel's `i32` arithmetic.
pub const MAX_LITERAL: u32 = 65_535;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Type {
    Bool,
    Int,
}

impl Type {
    fn plural(self) -> &'static str {
        match self {
            Type::Bool => "bool",
            Type::Int => "integer",
        }
    }
}

impl fmt::Display for Type {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Type::Bool => "a bool",
            Type::Int => "an integer",
        })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Value {
    Bool(bool),
    Int(i64),
}

impl Value {
    /// Truthiness; only reached for integers if the expression was never type-checked.
    pub fn as_bool(self) -> bool {
        match self {
            Value::Bool(b) => b,
            Value::Int(i) => i != 0,
        }
    }

    pub fn as_int(self) -> i64 {
        match self {
            Value::Bool(b) => i64::from(b),
            Value::Int(i) => i,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Or,
    And,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    Add,
    Sub,
}

impl BinOp {
    pub fn symbol(self) -> &'static str {
        match self {
            BinOp::Or => "||",
            BinOp::And => "&&",
            BinOp::Eq => "==",
            BinOp::Ne => "!=",
            BinOp::Lt => "<",
            BinOp::Le => "<=",
            BinOp::Gt => ">",
            BinOp::Ge => ">=",
            BinOp::Add => "+",
            BinOp::Sub => "-",
        }
    }
}

/// A parsed condition. Spans are byte ranges in the condition text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expr {
    Ident {
        name: String,
        span: Range<usize>,
    },
    Int {
        value: u32,
        span: Range<usize>,
    },
    Not {
        operand: Box<Expr>,
        span: Range<usize>,
    },
    Binary {
        op: BinOp,
        op_span: Range<usize>,
        lhs: Box<Expr>,
        rhs: Box<Expr>,
    },
}

impl Expr {
    pub fn span(&self) -> Range<usize> {
        match self {
            Expr::Ident { span, .. } | Expr::Int { span, .. } | Expr::Not { span, .. } => span.clone(),
            Expr::Binary { lhs, rhs, .. } => lhs.span().start..rhs.span().end,
        }
    }

    /// Every identifier the condition names, in order of appearance.
    pub fn idents(&self) -> Vec<&str> {
        let mut out = Vec::new();
        self.collect_idents(&mut out);
        out
    }

    fn collect_idents<'a>(&'a self, out: &mut Vec<&'a str>) {
        match self {
            Expr::Ident { name, .. } => out.push(name),
            Expr::Int { .. } => {}
            Expr::Not { operand, .. } => operand.collect_idents(out),
            Expr::Binary { lhs, rhs, .. } => {
                lhs.collect_idents(out);
                rhs.collect_idents(out);
            }
        }
    }
}

/// An error at a byte offset of the condition text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExprError {
    pub offset: usize,
    pub message: String,
}

fn err<T>(offset: usize, message: impl Into<String>) -> Result<T, ExprError> {
    Err(ExprError {
        offset,
        message: message.into(),
    })
}

#[derive(Clone, Debug, PartialEq, Eq)]
enum Tok {
    Ident(String),
    Int(u32),
    Op(&'static str),
    LParen,
    RParen,
    End,
}

impl fmt::Display for Tok {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tok::Ident(s) => write!(f, "`{s}`"),
            Tok::Int(i) => write!(f, "`{i}`"),
            Tok::Op(s) => write!(f, "`{s}`"),
            Tok::LParen => f.write_str("`(`"),
            Tok::RParen => f.write_str("`)`"),
            Tok::End => f.write_str("the end of the condition"),
        }
    }
}

fn lex(src: &str) -> Result<Vec<(Tok, Range<usize>)>, ExprError> {
    let bytes = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_alphabetic() || c == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            out.push((Tok::Ident(src[start..i].to_string()), start..i));
            continue;
        }
        if c.is_ascii_digit() {
            while i < bytes.len() && bytes[i].is_ascii_alphanumeric() {
                i += 1;
            }
            let text = &src[start..i];
            let value = match text.parse::<u32>() {
                Ok(v) if v <= MAX_LITERAL => v,
                Ok(_) | Err(_) if text.bytes().all(|b| b.is_ascii_digit()) => {
                    return err(
                        start,
                        format!("integer `{text}` is too large; literals go up to {MAX_LITERAL}"),
                    )
                }
                _ => {
                    return err(
                        start,
                        format!("`{text}` is not a number; write an unsigned decimal integer such as `4`"),
                    )
                }
            };
            out.push((Tok::Int(value), start..i));
            continue;
        }
        let two = src.get(i..i + 2).unwrap_or("");
        let op: Option<&'static str> = match two {
            "&&" => Some("&&"),
            "||" => Some("||"),
            "==" => Some("=="),
            "!=" => Some("!="),
            "<=" => Some("<="),
            ">=" => Some(">="),
            _ => None,
        };
        if let Some(op) = op {
            out.push((Tok::Op(op), i..i + 2));
            i += 2;
            continue;
        }
        let tok = match c {
            b'!' => Tok::Op("!"),
            b'<' => Tok::Op("<"),
            b'>' => Tok::Op(">"),
            b'+' => Tok::Op("+"),
            b'-' => Tok::Op("-"),
            b'(' => Tok::LParen,
            b')' => Tok::RParen,
            b'&' => return err(i, "unexpected `&`; write `&&` for \"and\""),
            b'|' => return err(i, "unexpected `|`; write `||` for \"or\""),
            b'=' => return err(i, "unexpected `=`; write `==` to compare"),
            _ => {
                let ch = src[i..].chars().next().unwrap_or('?');
                return err(
                    i,
                    format!(
                        "unexpected character `{ch}`; conditions use names, numbers, \
                         `&&` `||` `!` `==` `!=` `<` `<=` `>` `>=` `+` `-` and parentheses"
                    ),
                );
            }
        };
        i += 1;
        out.push((tok, start..i));
    }
    out.push((Tok::End, src.len()..src.len()));
    Ok(out)
}

struct Parser {
    toks: Vec<(Tok, Range<usize>)>,
    pos: usize,
}

impl Parser {
    fn peek(&self) -> &(Tok, Range<usize>) {
        // `lex` always ends with `End` and the parser never advances past it.
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }

    fn bump(&mut self) -> (Tok, Range<usize>) {
        let t = self.peek().clone();
        if t.0 != Tok::End {
            self.pos += 1;
        }
        t
    }

    fn peek_op(&self, ops: &[&'static str]) -> Option<&'static str> {
        match &self.peek().0 {
            Tok::Op(o) if ops.contains(o) => Some(o),
            _ => None,
        }
    }

    fn binary_chain(
        &mut self,
        ops: &[&'static str],
        next: fn(&mut Parser) -> Result<Expr, ExprError>,
    ) -> Result<Expr, ExprError> {
        let mut lhs = next(self)?;
        while let Some(op) = self.peek_op(ops) {
            let (_, op_span) = self.bump();
            let rhs = next(self)?;
            lhs = Expr::Binary {
                op: op_from_symbol(op),
                op_span,
                lhs: Box::new(lhs),
                rhs: Box::new(rhs),
            };
        }
        Ok(lhs)
    }

    fn or(&mut self) -> Result<Expr, ExprError> {
        self.binary_chain(&["||"], Parser::and)
    }

    fn and(&mut self) -> Result<Expr, ExprError> {
        self.binary_chain(&["&&"], Parser::cmp)
    }

    fn cmp(&mut self) -> Result<Expr, ExprError> {
        const CMP: [&str; 6] = ["==", "!=", "<", "<=", ">", ">="];
        let lhs = self.sum()?;
        let Some(op) = self.peek_op(&CMP) else {
            return Ok(lhs);
        };
        let (_, op_span) = self.bump();
        let rhs = self.sum()?;
        if self.peek_op(&CMP).is_some() {
            let at = self.peek().1.start;
            return err(
                at,
                "comparisons cannot be chained; write `a < b && b < c` instead of `a < b < c`",
            );
        }
        Ok(Expr::Binary {
            op: op_from_symbol(op),
            op_span,
            lhs: Box::new(lhs),
            rhs: Box::new(rhs),
        })
    }

    fn sum(&mut self) -> Result<Expr, ExprError> {
        self.binary_chain(&["+", "-"], Parser::unary)
    }

    fn unary(&mut self) -> Result<Expr, ExprError> {
        if self.peek_op(&["!"]).is_some() {
            let (_, bang) = self.bump();
            let operand = self.unary()?;
            let span = bang.start..operand.span().end;
            return Ok(Expr::Not {
                operand: Box::new(operand),
                span,
            });
        }
        self.primary()
    }

    fn primary(&mut self) -> Result<Expr, ExprError> {
        let (tok, span) = self.bump();
        match tok {
            Tok::Ident(name) => Ok(Expr::Ident { name, span }),
            Tok::Int(value) => Ok(Expr::Int { value, span }),
            Tok::LParen => {
                let inner = self.or()?;
                let (close, close_span) = self.bump();
                if close != Tok::RParen {
                    return err(
                        close_span.start,
                        format!("expected `)` to close the `(` at offset {}, found {close}", span.start),
                    );
                }
                Ok(inner)
            }
            Tok::End if span.start == 0 => err(
                0,
                "empty condition; write a bool expression over features, e.g. `riichi`",
            ),
            other => err(
                span.start,
                format!("expected a name, a number, `!` or `(`, found {other}"),
            ),
        }
    }
}

fn op_from_symbol(s: &str) -> BinOp {
    match s {
        "||" => BinOp::Or,
        "&&" => BinOp::And,
        "==" => BinOp::Eq,
        "!=" => BinOp::Ne,
        "<" => BinOp::Lt,
        "<=" => BinOp::Le,
        ">" => BinOp::Gt,
        ">=" => BinOp::Ge,
        "+" => BinOp::Add,
        _ => BinOp::Sub,
    }
}

/// Parses a condition. Offsets in the error are byte offsets into `src`.
pub fn parse(src: &str) -> Result<Expr, ExprError> {
    let toks = lex(src)?;
    let mut p = Parser { toks, pos: 0 };
    let e = p.or()?;
    let (tok, span) = p.bump();
    if tok != Tok::End {
        let hint = match &tok {
            Tok::Ident(w) if w == "and" => "; write `&&`",
            Tok::Ident(w) if w == "or" => "; write `||`",
            Tok::RParen => "; this `)` has no matching `(`",
            _ => "; join conditions with `&&` or `||`",
        };
        return err(
            span.start,
            format!("expected an operator or the end of the condition, found {tok}{hint}"),
        );
    }
    Ok(e)
}

/// What names a condition may use, with their types.
#[derive(Clone, Debug, Default)]
pub struct Scope {
    pub names: BTreeMap<String, Type>,
}

/// Type-checks `expr` (parsed from `src`) and requires the whole condition to be a bool.
pub fn check(expr: &Expr, src: &str, scope: &Scope) -> Result<(), ExprError> {
    match type_of(expr, src, scope)? {
        Type::Bool => Ok(()),
        Type::Int => err(
            expr.span().start,
            format!(
                "the condition must be a bool, but `{}` is an integer; compare it, e.g. `{} > 0`",
                text(src, expr),
                text(src, expr)
            ),
        ),
    }
}

fn text<'s>(src: &'s str, e: &Expr) -> &'s str {
    src.get(e.span()).unwrap_or("?")
}

fn type_of(expr: &Expr, src: &str, scope: &Scope) -> Result<Type, ExprError> {
    match expr {
        Expr::Int { .. } => Ok(Type::Int),
        Expr::Ident { name, span } => match scope.names.get(name) {
            Some(t) => Ok(*t),
            None => err(
                span.start,
                format!(
                    "unknown name `{name}`{}; a condition may name a field of `struct Features` \
                     (rules/kernel/features.rs) or a bool option of the variant's `[yaku_rules]`",
                    crate::diag::did_you_mean(name, scope.names.keys().map(String::as_str))
                ),
            ),
        },
        Expr::Not { operand, .. } => {
            if type_of(operand, src, scope)? == Type::Int {
                let t = text(src, operand);
                return err(
                    operand.span().start,
                    format!("`!` needs a bool, but `{t}` is an integer; write `{t} == 0`"),
                );
            }
            Ok(Type::Bool)
        }
        Expr::Binary { op, op_span, lhs, rhs } => {
            let lt = type_of(lhs, src, scope)?;
            let rt = type_of(rhs, src, scope)?;
            let sym = op.symbol();
            let want = |want: Type, side: &Expr, got: Type| -> Result<(), ExprError> {
                if got == want {
                    return Ok(());
                }
                let t = text(src, side);
                let fix = match want {
                    Type::Bool => format!("compare it, e.g. `{t} > 0`"),
                    Type::Int => "use a count (an integer feature) here".to_string(),
                };
                err(
                    side.span().start,
                    format!("`{sym}` needs {} operands, but `{t}` is {got}; {fix}", want.plural()),
                )
            };
            match op {
                BinOp::And | BinOp::Or => {
                    want(Type::Bool, lhs, lt)?;
                    want(Type::Bool, rhs, rt)?;
                    Ok(Type::Bool)
                }
                BinOp::Add | BinOp::Sub => {
                    want(Type::Int, lhs, lt)?;
                    want(Type::Int, rhs, rt)?;
                    Ok(Type::Int)
                }
                BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => {
                    want(Type::Int, lhs, lt)?;
                    want(Type::Int, rhs, rt)?;
                    Ok(Type::Bool)
                }
                BinOp::Eq | BinOp::Ne => {
                    if lt != rt {
                        let (b, i) = if lt == Type::Bool { (lhs, rhs) } else { (rhs, lhs) };
                        let bt = text(src, b);
                        return err(
                            op_span.start,
                            format!(
                                "`{sym}` compares a bool (`{bt}`) with an integer (`{}`); \
                                 for a bool write `{bt}` or `!{bt}`",
                                text(src, i)
                            ),
                        );
                    }
                    Ok(Type::Bool)
                }
            }
        }
    }
}

/// Evaluates a condition. `lookup` gives each name's value. Meant for checked expressions; an
/// unchecked one mixing types is evaluated with bool <-> int coercion (false = 0) rather than
/// panicking. Integer arithmetic is exact (i64), matching the kernel for realistic feature values.
pub fn eval(expr: &Expr, lookup: &dyn Fn(&str) -> Value) -> Value {
    match expr {
        Expr::Int { value, .. } => Value::Int(i64::from(*value)),
        Expr::Ident { name, .. } => lookup(name),
        Expr::Not { operand, .. } => Value::Bool(!eval(operand, lookup).as_bool()),
        Expr::Binary { op, lhs, rhs, .. } => {
            let l = eval(lhs, lookup);
            match op {
                // Short-circuit like the generated Rust does.
                BinOp::And => Value::Bool(l.as_bool() && eval(rhs, lookup).as_bool()),
                BinOp::Or => Value::Bool(l.as_bool() || eval(rhs, lookup).as_bool()),
                _ => {
                    let r = eval(rhs, lookup);
                    match op {
                        BinOp::Eq => Value::Bool(l == r || l.as_int() == r.as_int()),
                        BinOp::Ne => Value::Bool(l.as_int() != r.as_int()),
                        BinOp::Lt => Value::Bool(l.as_int() < r.as_int()),
                        BinOp::Le => Value::Bool(l.as_int() <= r.as_int()),
                        BinOp::Gt => Value::Bool(l.as_int() > r.as_int()),
                        BinOp::Ge => Value::Bool(l.as_int() >= r.as_int()),
                        BinOp::Add => Value::Int(l.as_int().wrapping_add(r.as_int())),
                        BinOp::Sub => Value::Int(l.as_int().wrapping_sub(r.as_int())),
                        BinOp::And | BinOp::Or => unreachable!("handled above"),
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scope() -> Scope {
        let mut s = Scope::default();
        for b in ["riichi", "tsumo", "concealed", "open_tanyao"] {
            s.names.insert(b.into(), Type::Bool);
        }
        for i in ["runs", "kans"] {
            s.names.insert(i.into(), Type::Int);
        }
        s
    }

    fn parse_check(src: &str) -> Result<Expr, ExprError> {
        let e = parse(src)?;
        check(&e, src, &scope())?;
        Ok(e)
    }

    #[test]
    fn precedence() {
        let e = parse("!riichi || tsumo && runs + 1 == 4").unwrap();
        let Expr::Binary { op: BinOp::Or, rhs, .. } = &e else {
            panic!("{e:?}")
        };
        let Expr::Binary {
            op: BinOp::And, rhs, ..
        } = &**rhs
        else {
            panic!("{rhs:?}")
        };
        assert!(matches!(&**rhs, Expr::Binary { op: BinOp::Eq, .. }));
    }

    #[test]
    fn evaluates() {
        let e = parse_check("concealed && (runs - 1 >= 2 || kans == 4)").unwrap();
        let v = |runs: i64, kans: i64| {
            move |n: &str| match n {
                "concealed" => Value::Bool(true),
                "runs" => Value::Int(runs),
                "kans" => Value::Int(kans),
                _ => Value::Bool(false),
            }
        };
        assert_eq!(eval(&e, &v(3, 0)), Value::Bool(true));
        assert_eq!(eval(&e, &v(2, 0)), Value::Bool(false));
        assert_eq!(eval(&e, &v(0, 4)), Value::Bool(true));
    }

    #[test]
    fn errors_point_at_the_culprit() {
        let e = parse_check("runs && tsumo").unwrap_err();
        assert_eq!(e.offset, 0);
        assert!(e.message.contains("`runs > 0`"), "{}", e.message);
        let e = parse_check("riichi == 2").unwrap_err();
        assert_eq!(e.offset, 7);
        let e = parse_check("riichi & tsumo").unwrap_err();
        assert_eq!((e.offset, e.message.contains("`&&`")), (7, true));
        let e = parse_check("tsumoo").unwrap_err();
        assert!(e.message.contains("did you mean `tsumo`"), "{}", e.message);
        let e = parse_check("runs < 2 < 3").unwrap_err();
        assert_eq!(e.offset, 9);
        let e = parse_check("(riichi").unwrap_err();
        assert_eq!(e.offset, 7);
        let e = parse_check("riichi tsumo").unwrap_err();
        assert_eq!(e.offset, 7);
        assert!(parse_check("").is_err());
        assert!(parse_check("99999999999").is_err());
        assert!(parse_check("runs").is_err());
    }
}
