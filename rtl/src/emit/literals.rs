//! # literals — rust-hdl's 32-bit literals sized to what they meet
//!
//! rust-hdl writes every integer constant of a block's logic as a 32-bit
//! literal (`dark_d = dark_q - 32'h1;`, `if (state_q == 32'h2)`,
//! `o_po[32'h1]`), so every such statement mixes widths and Verilator's
//! `-Wall` reports WIDTH on it. [`size_literals`], part of our emission pass
//! ([`crate::emit::readable`]), rewrites a literal only where the statement's
//! value cannot change (Verilog-2005 §5.4, expression bit lengths; every
//! merkur signal is unsigned):
//!
//! - **an index** (`x[32'h1]`, `x[(32'hc)+:(4)]`) and **a shift amount**
//!   (`x >> 32'h1`) are self-determined: the literal becomes the plain
//!   number (`x[1]`, `x >> 1`);
//! - **a comparison with a signal** (`s == 32'h2`, `s >= 32'h2`; `s` a
//!   declared signal, a bit or a part of one, of width `w`): both sides are
//!   zero-extended to the wider, so a value that fits in `w` bits compares
//!   the same as a `w`-bit literal (`s == 2'h2`); one that does not fit is
//!   left as it is (the comparison is constant, and Verilator says so);
//! - **an assignment** `t = e;` to a signal `t` of width `w`: when `e` is
//!   built only from `+ - * & | ^ ~ <<` (whose low `w` bits depend only on
//!   the low `w` bits of their operands, in any width at least `w`) over
//!   signals, literals and self-determined terms (comparisons, `&&`, `||`,
//!   `!`, reductions, concatenations, and `s >> n` of a signal no wider
//!   than `w`), every 32-bit literal in it whose value fits takes the width
//!   `w`. The expression is then evaluated in at least `w` bits and the
//!   `w` bits kept are the same. Anything else in `e` (a `>>` of a sum, a
//!   division, a `? :`) leaves the statement's literals as they are.
//!
//! A line the parser does not understand is kept as it was. What stays
//! after the pass is what the lint waivers still name (rtl/lint/waivers.vlt);
//! the block, ring, Icarus and formal tests run the rewritten text.

use std::collections::HashMap;

/// Rewrites the literals of a text of modules. A module's declarations
/// come before its logic (rust-hdl's order), so one pass collects a
/// module's widths and then rewrites its logic.
pub fn size_literals(text: &str) -> String {
    let mut widths = HashMap::new();
    let mut out = String::with_capacity(text.len());
    let mut in_logic = false;
    for line in text.split_inclusive('\n') {
        let t = line.trim();
        if t.starts_with("module ") {
            widths.clear();
            in_logic = false;
        } else if t == "always @(*) begin" {
            in_logic = true;
        } else if t.starts_with("always @(posedge") || t.starts_with("initial") {
            in_logic = false;
        } else if !in_logic {
            declare(t, &mut widths);
        }
        if in_logic {
            out.push_str(&statement(line, &widths).unwrap_or_else(|| line.to_string()));
        } else {
            out.push_str(line);
        }
    }
    out
}

/// Notes the width of a scalar declaration (a port, `reg`, `wire`, or
/// `localparam` with a sized literal); arrays (memories) are left out.
fn declare(line: &str, w: &mut HashMap<String, u32>) {
    let n: Vec<&str> = line.split_whitespace().collect();
    let Some(last) = n.last() else { return };
    if n[0] == "localparam" && n.len() == 4 && n[2] == "=" {
        if let Some((bits, _)) = n[3].trim_end_matches(';').split_once('\'') {
            if let Ok(b) = bits.parse() {
                w.insert(n[1].to_string(), b);
            }
        }
        return;
    }
    let decl = matches!(n[0], "input" | "output" | "reg" | "wire");
    let Some(name) = last.strip_suffix(';') else {
        return;
    };
    if !decl || !is_ident(name) {
        return;
    }
    let width = match n.iter().find(|p| p.starts_with('[')) {
        Some(range) => match range_width(range) {
            Some(r) => r,
            None => return,
        },
        None => 1,
    };
    w.insert(name.to_string(), width);
}

/// `[hi:lo]` → `hi - lo + 1`.
fn range_width(r: &str) -> Option<u32> {
    let (hi, lo) = r.strip_prefix('[')?.strip_suffix(']')?.split_once(':')?;
    let (hi, lo): (u32, u32) = (hi.trim().parse().ok()?, lo.trim().parse().ok()?);
    (hi >= lo).then(|| hi - lo + 1)
}

fn is_ident(s: &str) -> bool {
    let mut c = s.chars();
    c.next()
        .is_some_and(|f| f.is_ascii_alphabetic() || f == '_')
        && c.all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
}

/// One line of combinational logic, rewritten; `None` when it is not a
/// statement this pass knows (kept as it is).
fn statement(line: &str, widths: &HashMap<String, u32>) -> Option<String> {
    let t = line.trim_start();
    let indent = &line[..line.len() - t.len()];
    let (body, nl) = match t.strip_suffix('\n') {
        Some(b) => (b, "\n"),
        None => (t, ""),
    };
    let mut edits = vec![];
    let toks = tokens(body)?;
    let cond = ["if (", "else if (", "end else if ("]
        .iter()
        .find_map(|p| body.strip_prefix(p));
    if let Some(rest) = cond {
        rest.strip_suffix(") begin")?;
        let start = body.len() - rest.len();
        let expr = &toks[toks.iter().position(|k| k.at == start)?..toks.len() - 2];
        let e = Parser::new(expr, widths).whole()?;
        visit(&e, None, body, &mut edits);
    } else if let Some(eq) = toks.iter().position(|k| k.text == "=") {
        if toks.last()?.text != ";" {
            return None;
        }
        let lhs = Parser::new(&toks[..eq], widths).whole()?;
        visit(&lhs, None, body, &mut edits);
        let target = match &lhs {
            Expr::Prim { width, .. } => *width,
            _ => None,
        };
        let e = Parser::new(&toks[eq + 1..toks.len() - 1], widths).whole()?;
        let ctx = target.filter(|&w| safe(&e, w));
        visit(&e, ctx, body, &mut edits);
    } else {
        return None;
    }
    Some(format!("{indent}{}{nl}", apply(body, edits)))
}

/// The text with the rewrites made (they do not overlap).
fn apply(text: &str, mut edits: Edits) -> String {
    let mut s = text.to_string();
    edits.sort_by_key(|(at, _, _)| std::cmp::Reverse(*at));
    for (at, len, new) in edits {
        s.replace_range(at..at + len, &new);
    }
    s
}

/// A token and its byte offset in the statement.
#[derive(Debug, Clone)]
struct Tok<'a> {
    text: &'a str,
    at: usize,
}

fn tokens(s: &str) -> Option<Vec<Tok<'_>>> {
    const OPS: [&str; 25] = [
        "+:", "==", "!=", "<=", ">=", "<<", ">>", "&&", "||", "<", ">", "+", "-", "*", "&", "|",
        "^", "~", "!", "(", ")", "[", "]", "{", "}",
    ];
    let b = s.as_bytes();
    let mut out = vec![];
    let mut i = 0;
    while i < b.len() {
        let c = b[i] as char;
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        if c.is_ascii_alphanumeric() || c == '_' || c == '\'' {
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'\'') {
                i += 1;
            }
        } else if let Some(op) = OPS.iter().find(|o| s[i..].starts_with(**o)) {
            i += op.len();
        } else if matches!(c, ':' | ';' | '=' | ',' | '?') {
            i += 1;
        } else {
            return None;
        }
        out.push(Tok {
            text: &s[start..i],
            at: start,
        });
    }
    Some(out)
}

/// A parsed expression. `Prim` is a signal, a bit or a part of one (its
/// width when known); `Lit` a sized literal; `Opaque` a self-determined
/// term whose inside is visited on its own (concatenation, reduction).
#[derive(Debug)]
enum Expr {
    Lit {
        at: usize,
        len: usize,
        width: u32,
        value: Option<u128>,
    },
    Num(u32),
    Prim {
        width: Option<u32>,
        index: Vec<Expr>,
        span: (usize, usize),
    },
    Unary(Box<Expr>),
    Binary(String, Box<Expr>, Box<Expr>, (usize, usize)),
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    Opaque(Vec<Expr>),
}

struct Parser<'a, 'b> {
    toks: &'b [Tok<'a>],
    pos: usize,
    widths: &'b HashMap<String, u32>,
}

/// Binary operators by binding strength, weakest first.
const LEVELS: [&[&str]; 9] = [
    &["||"],
    &["&&"],
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", "<=", ">", ">="],
    &["<<", ">>"],
    &["+", "-"],
];

impl<'a, 'b> Parser<'a, 'b> {
    fn new(toks: &'b [Tok<'a>], widths: &'b HashMap<String, u32>) -> Self {
        Parser {
            toks,
            pos: 0,
            widths,
        }
    }

    /// The whole token run as one expression, or `None`.
    fn whole(mut self) -> Option<Expr> {
        let e = self.ternary()?;
        (self.pos == self.toks.len()).then_some(e)
    }

    fn peek(&self) -> Option<&'a str> {
        self.toks.get(self.pos).map(|t| t.text)
    }

    fn eat(&mut self, s: &str) -> Option<()> {
        (self.peek()? == s).then(|| self.pos += 1)
    }

    /// Byte range from token `start` to the last token taken.
    fn span(&self, start: usize) -> (usize, usize) {
        let last = &self.toks[self.pos - 1];
        (self.toks[start].at, last.at + last.text.len())
    }

    fn ternary(&mut self) -> Option<Expr> {
        let c = self.binary(0)?;
        if self.peek() == Some("?") {
            self.pos += 1;
            let a = self.ternary()?;
            self.eat(":")?;
            let b = self.ternary()?;
            return Some(Expr::Ternary(Box::new(c), Box::new(a), Box::new(b)));
        }
        Some(c)
    }

    fn binary(&mut self, level: usize) -> Option<Expr> {
        if level == LEVELS.len() {
            return self.mul();
        }
        let start = self.pos;
        let mut l = self.binary(level + 1)?;
        while let Some(op) = self.peek().filter(|p| LEVELS[level].contains(p)) {
            self.pos += 1;
            let r = self.binary(level + 1)?;
            l = Expr::Binary(op.to_string(), Box::new(l), Box::new(r), self.span(start));
        }
        Some(l)
    }

    fn mul(&mut self) -> Option<Expr> {
        let start = self.pos;
        let mut l = self.unary()?;
        while self.peek() == Some("*") {
            self.pos += 1;
            let r = self.unary()?;
            l = Expr::Binary("*".into(), Box::new(l), Box::new(r), self.span(start));
        }
        Some(l)
    }

    fn unary(&mut self) -> Option<Expr> {
        let p = self.peek()?;
        if matches!(p, "~" | "!" | "-" | "&" | "|" | "^") {
            self.pos += 1;
            let e = self.unary()?;
            return Some(match p {
                "~" | "-" => Expr::Unary(Box::new(e)),
                // Logical not and the reductions: one bit, operand
                // self-determined.
                _ => Expr::Opaque(vec![e]),
            });
        }
        self.primary()
    }

    fn primary(&mut self) -> Option<Expr> {
        let t = self.toks.get(self.pos)?.clone();
        let start = self.pos;
        self.pos += 1;
        if t.text == "(" {
            let e = self.ternary()?;
            self.eat(")")?;
            return Some(e);
        }
        if t.text == "{" {
            let mut items = vec![];
            loop {
                items.push(self.ternary()?);
                if self.peek() == Some("{") {
                    // Replication `{n{x}}`: the count was parsed; the
                    // replicated concatenation follows.
                    items.push(self.primary()?);
                }
                match self.peek()? {
                    "," => self.pos += 1,
                    "}" => break,
                    _ => return None,
                }
            }
            self.pos += 1;
            return Some(Expr::Opaque(items));
        }
        if let Some((bits, rest)) = t.text.split_once('\'') {
            let width = bits.parse().ok()?;
            let (base, digits) = rest.split_at(1);
            let radix = match base {
                "h" => 16,
                "b" => 2,
                "d" => 10,
                "o" => 8,
                _ => return None,
            };
            let value = u128::from_str_radix(&digits.replace('_', ""), radix).ok();
            return Some(Expr::Lit {
                at: t.at,
                len: t.text.len(),
                width,
                value,
            });
        }
        if t.text.bytes().all(|c| c.is_ascii_digit()) {
            return t.text.parse().ok().map(Expr::Num);
        }
        if !is_ident(t.text) {
            return None;
        }
        let mut width = self.widths.get(t.text).copied();
        let mut index = vec![];
        if self.peek() == Some("[") {
            self.pos += 1;
            let a = self.ternary()?;
            width = match self.peek()? {
                "]" => Some(1),
                ":" => {
                    self.pos += 1;
                    let b = self.ternary()?;
                    let w = match (&a, &b) {
                        (Expr::Num(hi), Expr::Num(lo)) => (hi >= lo).then(|| hi - lo + 1),
                        _ => None,
                    };
                    index.push(b);
                    w
                }
                "+:" => {
                    self.pos += 1;
                    let b = self.ternary()?;
                    let w = match &b {
                        Expr::Num(n) => Some(*n),
                        _ => None,
                    };
                    index.push(b);
                    w
                }
                _ => return None,
            };
            index.insert(0, a);
            self.eat("]")?;
        }
        Some(Expr::Prim {
            width,
            index,
            span: self.span(start),
        })
    }
}

/// Whether every 32-bit literal of `e` that fits may take the assignment's
/// width `w` without changing the `w` bits assigned (module doc).
fn safe(e: &Expr, w: u32) -> bool {
    match e {
        Expr::Lit { .. } | Expr::Num(_) | Expr::Prim { .. } | Expr::Opaque(_) => true,
        Expr::Unary(x) => safe(x, w),
        Expr::Binary(op, l, r, _) => match op.as_str() {
            "+" | "-" | "*" | "&" | "|" | "^" => safe(l, w) && safe(r, w),
            "<<" => safe(l, w),
            ">>" => matches!(**l, Expr::Prim { width: Some(lw), .. } if lw <= w),
            // Comparisons and logical operators: one bit, operands
            // self-determined.
            "==" | "!=" | "<" | "<=" | ">" | ">=" | "&&" | "||" => true,
            _ => false,
        },
        Expr::Ternary(..) => false,
    }
}

/// A literal of 32 bits whose value is known.
fn lit32(e: &Expr) -> Option<(usize, usize, u128)> {
    match e {
        Expr::Lit {
            at,
            len,
            width: 32,
            value: Some(v),
        } => Some((*at, *len, *v)),
        _ => None,
    }
}

fn fits(v: u128, w: u32) -> bool {
    w < 128 && v < (1u128 << w)
}

/// Rewrites of a statement: (byte offset, length, new text).
type Edits = Vec<(usize, usize, String)>;

/// The literal as the plain number, when it is a 32-bit one.
fn plain(e: &Expr, edits: &mut Edits) -> bool {
    if let Some((at, len, v)) = lit32(e) {
        edits.push((at, len, v.to_string()));
        true
    } else {
        false
    }
}

/// The width of a comparison operand built from `& | ^` over signals of
/// known width and literals: such an operand has the same value in any
/// width at least its signals' widest (`None` for anything else).
fn bitwise_width(e: &Expr) -> Option<u32> {
    match e {
        Expr::Prim { width, .. } => *width,
        Expr::Lit { width: 32, .. } => Some(0),
        Expr::Lit { width, .. } => Some(*width),
        Expr::Binary(op, l, r, _) if matches!(op.as_str(), "&" | "|" | "^") => {
            Some(bitwise_width(l)?.max(bitwise_width(r)?))
        }
        _ => None,
    }
}

/// Every 32-bit literal of a bitwise operand (see [`bitwise_width`]).
fn lits32(e: &Expr, out: &mut Vec<(usize, usize, u128)>) {
    if let Some(l) = lit32(e) {
        out.push(l);
    } else if let Expr::Binary(_, l, r, _) = e {
        lits32(l, out);
        lits32(r, out);
    }
}

/// rust-hdl's bit cast, `(x) & N'h<all ones>`: for a signal `x` narrower
/// than `N`, the zero extension `{(N - w)'h0, x}`; for a signal wider,
/// its low bits `x[N-1:0]`. Same value in any context, one width.
fn bit_cast(l: &Expr, r: &Expr, span: (usize, usize), src: &str) -> Option<(usize, usize, String)> {
    let Expr::Lit {
        width: n,
        value: Some(mask),
        ..
    } = r
    else {
        return None;
    };
    let Expr::Prim {
        width: Some(w),
        index,
        span: (ps, pe),
    } = l
    else {
        return None;
    };
    if *n >= 128 || *mask != (1u128 << n) - 1 {
        return None;
    }
    // The signal's text with its own index rewritten.
    let mut sub = vec![];
    visit(l, None, src, &mut sub);
    let x = apply(
        &src[*ps..*pe],
        sub.into_iter()
            .map(|(at, len, t)| (at - ps, len, t))
            .collect(),
    );
    let new = if w < n {
        format!("{{{}'h0, {x}}}", n - w)
    } else if w > n && index.is_empty() {
        format!("{x}[{}:0]", n - 1)
    } else {
        return None;
    };
    Some((span.0, span.1 - span.0, new))
}

/// A comparison's rewrites: when one side is a bitwise operand of width
/// `w` (a signal, or `& | ^` of signals and literals) and every 32-bit
/// literal on both sides fits in `w`, they all take `w`.
fn comparison(l: &Expr, r: &Expr, src: &str, edits: &mut Edits) {
    for (a, b) in [(l, r), (r, l)] {
        let (Some(wa), Some(wb)) = (bitwise_width(a), bitwise_width(b)) else {
            continue;
        };
        let w = wa.max(wb);
        let mut lits = vec![];
        lits32(a, &mut lits);
        lits32(b, &mut lits);
        if w > 0 && !lits.is_empty() && lits.iter().all(|&(_, _, v)| fits(v, w)) {
            for (at, len, v) in lits {
                edits.push((at, len, format!("{w}'h{v:x}")));
            }
            // The signals' own indexes and bit casts.
            for x in [a, b] {
                visit_bitwise(x, src, edits);
            }
            return;
        }
    }
    visit(l, None, src, edits);
    visit(r, None, src, edits);
}

/// The parts of a bitwise operand other than its 32-bit literals.
fn visit_bitwise(e: &Expr, src: &str, edits: &mut Edits) {
    match e {
        Expr::Binary(_, l, r, _) => {
            visit_bitwise(l, src, edits);
            visit_bitwise(r, src, edits);
        }
        _ if lit32(e).is_some() => {}
        _ => visit(e, None, src, edits),
    }
}

/// Collects the rewrites of `e`. `ctx` is the width the literals of an
/// assignment's safe region take.
fn visit(e: &Expr, ctx: Option<u32>, src: &str, edits: &mut Edits) {
    match e {
        Expr::Lit { .. } => {
            if let (Some((at, len, v)), Some(w)) = (lit32(e), ctx) {
                if fits(v, w) {
                    edits.push((at, len, format!("{w}'h{v:x}")));
                }
            }
        }
        Expr::Num(_) => {}
        Expr::Prim { index, .. } => {
            for i in index {
                if !plain(i, edits) {
                    visit(i, None, src, edits);
                }
            }
        }
        Expr::Unary(x) => visit(x, ctx, src, edits),
        Expr::Opaque(items) => items.iter().for_each(|i| visit(i, None, src, edits)),
        Expr::Ternary(c, a, b) => {
            visit(c, None, src, edits);
            visit(a, None, src, edits);
            visit(b, None, src, edits);
        }
        Expr::Binary(op, l, r, span) => match op.as_str() {
            "<<" | ">>" => {
                visit(l, if op == "<<" { ctx } else { None }, src, edits);
                if !plain(r, edits) {
                    visit(r, None, src, edits);
                }
            }
            "==" | "!=" | "<" | "<=" | ">" | ">=" => comparison(l, r, src, edits),
            "&&" | "||" => {
                visit(l, None, src, edits);
                visit(r, None, src, edits);
            }
            "&" if bit_cast(l, r, *span, src).is_some() => {
                edits.extend(bit_cast(l, r, *span, src));
            }
            _ => {
                visit(l, ctx, src, edits);
                visit(r, ctx, src, edits);
            }
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(decls: &str, line: &str) -> String {
        let m = format!(
            "module m(a);\n{decls}\n    always @(*) begin\n        {line}\n    end\nendmodule\n"
        );
        let out = size_literals(&m);
        out.lines()
            .nth(decls.lines().count() + 2)
            .unwrap()
            .trim()
            .to_string()
    }

    const D: &str = "    input wire [4:0] a;\n    reg [4:0] b;\n    reg [1:0] p;\n    reg f;\n    reg [15:0] word;\n    reg [3:0] nib;\n    localparam k = 5'b11000;";

    /// Each statement, rewritten, is the one expected.
    fn check(cases: &[(&str, &str)]) {
        for (line, want) in cases {
            assert_eq!(run(D, line), *want, "{line}");
        }
    }

    #[test]
    fn assignments_take_their_target_width() {
        check(&[
            ("b = a - 32'h1;", "b = a - 5'h1;"),
            ("p = 32'h3;", "p = 2'h3;"),
            ("word = word | 32'h1000;", "word = word | 16'h1000;"),
            ("b = (a << 32'h1) | 32'h1;", "b = (a << 1) | 5'h1;"),
            ("b = ~a & 32'h3;", "b = ~a & 5'h3;"),
        ]);
    }

    #[test]
    fn indexes_shift_amounts_and_comparisons() {
        check(&[
            ("f = p[32'h1];", "f = p[1];"),
            ("nib = word[(32'hc)+:(4)];", "nib = word[(12)+:(4)];"),
            ("if (a != 32'h0) begin", "if (a != 5'h0) begin"),
            (
                "end else if (32'h2 == p) begin",
                "end else if (2'h2 == p) begin",
            ),
            (
                "f = (a >= 32'h2) | ((a == 32'h1) & ~p[32'h1]);",
                "f = (a >= 5'h2) | ((a == 5'h1) & ~p[1]);",
            ),
            ("b = k;", "b = k;"),
        ]);
    }

    #[test]
    fn what_could_change_the_value_is_kept() {
        check(&[
            // The sum's carry reaches bit 4 through `>>` only in 32 bits.
            (
                "b = ((a + b) >> 32'h1) & 32'h1f;",
                "b = ((a + b) >> 1) & 32'h1f;",
            ),
            // A value that does not fit the target or the signal compared.
            ("p = 32'h7;", "p = 32'h7;"),
            ("if (p == 32'h5) begin", "if (p == 32'h5) begin"),
            // A comparison of a sum: both sides widen together.
            ("f = (a + 32'h1) == b;", "f = (a + 32'h1) == b;"),
            // A `>>` of a signal no wider than the target is safe.
            ("nib = (nib >> 32'h1) & 32'h6;", "nib = (nib >> 1) & 4'h6;"),
            // Lines that are not statements stay.
            ("case (a)", "case (a)"),
            // `~` sets the high bits of a 32-bit operand: not a bitwise operand.
            ("if ((~p) == 32'h0) begin", "if ((~p) == 32'h0) begin"),
        ]);
    }

    #[test]
    fn bitwise_comparisons_and_bit_casts() {
        check(&[
            (
                "else if ((nib & 32'ha) == 32'h0) begin",
                "else if ((nib & 4'ha) == 4'h0) begin",
            ),
            (
                "word = ((a) & 16'hffff) | 32'h8000;",
                "word = ({11'h0, a}) | 16'h8000;",
            ),
            ("nib = ((word) & 4'hf) | 4'h0;", "nib = (word[3:0]) | 4'h0;"),
            // A part is narrowed only by extension.
            (
                "word = (word[(0)+:(3)]) & 16'hffff;",
                "word = {13'h0, word[(0)+:(3)]};",
            ),
            (
                "word = (word[(32'h1)+:(3)]) & 16'hffff;",
                "word = {13'h0, word[(1)+:(3)]};",
            ),
            (
                "nib = (word[(0)+:(8)]) & 4'hf;",
                "nib = (word[(0)+:(8)]) & 4'hf;",
            ),
        ]);
    }
}
