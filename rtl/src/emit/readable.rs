//! # readable — our emission pass after rust-hdl's
//!
//! rust-hdl 0.46 writes every `DFF` as a child module of its own (`module
//! merkur_slave$armed(d,q,clock)`: an `initial` and a one-line `always
//! @(posedge clock)`), connects it through three stub signals (`armed$d`,
//! `armed$q`, `armed$clock`) and names every child module and stub signal
//! with a `$`. An 8-node ring came to 833 modules, 703 of them one
//! flip-flop each. [`readable`] rewrites that text, behaviour unchanged:
//!
//! - **registers are `reg`s of the block they belong to**: the flip-flop
//!   modules and their instances are gone; the register is `armed_q` (what
//!   the Rust source reads as `armed.q`), its next value `armed_d` (the
//!   Rust `armed.d`, which the block's logic assigns), and the block ends
//!   with two lines per register, `initial armed_q = 1'h0;` (the power-up
//!   value) and `always @(posedge clock) armed_q <= armed_d;` (a register
//!   named like the field alone would hide a child instance of that name,
//!   which Verilator's VARHIDDEN reports);
//! - **a child's port that the logic only copies from an input of the
//!   block** (every `x$clock = clock;`) is connected to that input directly
//!   and its stub is gone;
//! - **names use `__` instead of `$`**, in module names (`merkur_slave__sbox`,
//!   a child block of `merkur_slave`) and signals (`sbox__o_input`, the
//!   child's port): legal Verilog-2001 names without escapes; [`readable`]
//!   checks that no two declarations of a module meet after renaming;
//! - rust-hdl's section comments say what the sections hold ("Registers
//!   and child block ports", "Child blocks", "Combinational logic"), and
//!   empty ones go;
//! - **literals take the width of what they meet** where that cannot change
//!   a value ([`crate::emit::literals`]: `dark_q - 5'h1` for rust-hdl's
//!   `dark_q - 32'h1`, `o_po[1]` for `o_po[32'h1]`), so the text lints
//!   without a WIDTH waiver.
//!
//! The logic modules (one per rust-hdl block), the ROM and memory modules and
//! every statement of the combinational logic are kept as rust-hdl wrote
//! them, but for their literals. The ring, block, Icarus and formal tests run this text; a change of
//! behaviour would show there.

use std::collections::{HashMap, HashSet};

/// A flip-flop module of rust-hdl's: its width (`""` or `"[w:0]"`) and
/// power-up value (a Verilog literal).
#[derive(Debug, Clone, PartialEq, Eq)]
struct Dff {
    width: String,
    init: String,
}

/// One module of the text: its name, its header line and its body lines
/// (between the header and `endmodule`).
struct Module<'a> {
    name: &'a str,
    header: &'a str,
    body: Vec<&'a str>,
    end: &'a str,
}

/// The text with one space for every run of white space.
fn norm(line: &str) -> String {
    line.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The modules of a rust-hdl text, in order. Panics on text outside a
/// module other than blank lines (rust-hdl writes none: a generator bug).
fn modules(v: &str) -> Vec<Module<'_>> {
    let mut out = vec![];
    let mut cur: Option<Module> = None;
    for line in v.lines() {
        if let Some(m) = cur.as_mut() {
            if line.starts_with("endmodule") {
                m.end = line;
                out.push(cur.take().expect("module"));
            } else {
                m.body.push(line);
            }
        } else if let Some(rest) = line.strip_prefix("module ") {
            let name = rest.split('(').next().expect("module name").trim();
            cur = Some(Module {
                name,
                header: line,
                body: vec![],
                end: "",
            });
        } else {
            assert!(line.trim().is_empty(), "text outside a module: {line}");
        }
    }
    assert!(cur.is_none(), "module without endmodule");
    out
}

/// `Some` when the module is one of rust-hdl's flip-flops.
fn dff(m: &Module) -> Option<Dff> {
    let lines: Vec<String> = m
        .body
        .iter()
        .map(|l| norm(l))
        .filter(|l| !l.is_empty())
        .collect();
    let [args, d, q, clock, custom, ini, q0, end0, alw, next, end1] = lines.as_slice() else {
        return None;
    };
    let width = |l: &str, pre: &str, port: &str| -> Option<String> {
        let rest = l.strip_prefix(pre)?.strip_suffix(port)?;
        Some(rest.trim().to_string())
    };
    let wd = width(d, "input wire", " d;").or_else(|| (d == "input wire d;").then(String::new))?;
    let wq = width(q, "output reg", " q;").or_else(|| (q == "output reg q;").then(String::new))?;
    let init = q0.strip_prefix("q = ")?.strip_suffix(';')?.to_string();
    let fixed = [
        (args, "// Module arguments"),
        (clock, "input wire clock;"),
        (custom, "// Update code (custom)"),
        (ini, "initial begin"),
        (end0, "end"),
        (alw, "always @(posedge clock) begin"),
        (next, "q <= d;"),
        (end1, "end"),
    ];
    (m.header.trim() == format!("module {}(d,q,clock);", m.name)
        && wd == wq
        && fixed.iter().all(|(l, want)| l.as_str() == *want))
    .then_some(Dff { width: wd, init })
}

/// A register of a logic module: the DFF instance's name, its flip-flop,
/// and the clock it is taken on (an input of the module, or its stub).
struct Reg {
    name: String,
    dff: Dff,
    clock: String,
}

/// Rewrites rust-hdl's Verilog as the module doc says. Panics when the text
/// is not of rust-hdl's shape (a DFF instance with other connections, a
/// name that meets another after renaming): a generator bug, caught by the
/// tests.
pub fn readable(v: &str) -> String {
    crate::emit::literals::size_literals(&registers_and_names(v))
}

/// [`readable`] without the literal sizing of [`crate::emit::literals`]: the
/// registers, connections, names and headings only. The equivalence test
/// proves the two texts the same design (sim/tests/literals.rs).
pub fn registers_and_names(v: &str) -> String {
    let mods = modules(v);
    let dffs: HashMap<&str, Dff> = mods
        .iter()
        .filter_map(|m| dff(m).map(|d| (m.name, d)))
        .collect();
    let mut out = String::with_capacity(v.len());
    let mut names = HashSet::new();
    for m in mods.iter().filter(|m| !dffs.contains_key(m.name)) {
        let text = module(m, &dffs);
        let new = rename(m.name, &HashMap::new());
        assert!(names.insert(new.clone()), "two modules named {new}");
        check_unique(&new, &text);
        out.push_str(&text);
    }
    out
}

/// One logic (or ROM, or memory) module, rewritten.
fn module(m: &Module, dffs: &HashMap<&str, Dff>) -> String {
    let inputs: HashSet<String> = m
        .body
        .iter()
        .filter_map(|l| {
            let n = norm(l);
            let rest = n.strip_prefix("input wire ")?.strip_suffix(';')?;
            Some(rest.rsplit(' ').next()?.to_string())
        })
        .collect();
    // Registers from the DFF instances, in order.
    let mut regs: Vec<Reg> = vec![];
    let mut body: Vec<String> = vec![];
    let mut i = 0;
    while i < m.body.len() {
        let n = norm(m.body[i]);
        let inst = n
            .strip_suffix('(')
            .and_then(|h| h.split_once(' '))
            .filter(|(module, _)| dffs.contains_key(module));
        if let Some((module, name)) = inst {
            let mut conns = vec![];
            i += 1;
            while norm(m.body[i]) != ");" {
                conns.push(norm(m.body[i]).trim_end_matches(',').to_string());
                i += 1;
            }
            let want = ["d", "q", "clock"].map(|p| format!(".{p}({name}${p})"));
            assert_eq!(conns, want, "DFF instance {name} of {module} in {}", m.name);
            regs.push(Reg {
                name: name.to_string(),
                dff: dffs[module].clone(),
                clock: format!("{name}$clock"),
            });
        } else {
            body.push(m.body[i].to_string());
        }
        i += 1;
    }
    let direct = direct_inputs(&body, &inputs);
    // Stubs that become a direct connection: their declaration and their
    // one assignment go; every use reads the input.
    let mut map: HashMap<String, String> = direct.clone().into_iter().collect();
    for r in regs.iter_mut() {
        map.insert(format!("{}$q", r.name), format!("{}_q", r.name));
        map.insert(format!("{}$d", r.name), format!("{}_d", r.name));
        if let Some(c) = direct.get(&r.clock) {
            r.clock = c.clone();
        }
    }
    let reg_q: HashSet<String> = regs.iter().map(|r| format!("{}$q", r.name)).collect();
    let mut text = String::new();
    text.push_str(&rename(m.header, &map));
    text.push('\n');
    let mut in_logic = false;
    for l in &body {
        let n = norm(l);
        let declared = n
            .strip_suffix(';')
            .filter(|d| d.starts_with("reg ") || d.starts_with("wire "))
            .and_then(|d| d.rsplit(' ').next());
        if let Some(sig) = declared {
            if direct.contains_key(sig) {
                continue;
            }
            if reg_q.contains(sig) {
                // The flip-flop's output: the register itself.
                let w = l
                    .trim_start()
                    .strip_prefix("wire")
                    .expect("DFF output stub");
                let indent = &l[..l.len() - l.trim_start().len()];
                text.push_str(&format!("{indent}reg{}\n", rename(w, &map)));
                continue;
            }
        }
        if n == "always @(*) begin" {
            in_logic = true;
        }
        if in_logic {
            if let Some((lhs, _)) = n.strip_suffix(';').and_then(|s| s.split_once(" = ")) {
                if direct.contains_key(lhs)
                    && l.starts_with("        ")
                    && !l.starts_with("         ")
                {
                    continue;
                }
            }
        }
        text.push_str(&rename(l, &map));
        text.push('\n');
    }
    let mut text = headings(&text);
    if !regs.is_empty() {
        text.push_str(&registers(&regs));
    }
    text.push_str(&rename(m.end, &map));
    text.push('\n');
    text
}

/// rust-hdl's section comments named for what they hold; a section left
/// empty (its comment followed by a blank line or the end) goes.
fn headings(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::with_capacity(text.len());
    for (i, l) in lines.iter().enumerate() {
        let t = l.trim();
        let next = lines.get(i + 1).map(|n| n.trim()).unwrap_or("");
        let renamed = match t {
            "// Stub signals" => Some("// Registers and child block ports"),
            "// Sub module instances" => Some("// Child blocks"),
            "// Update code" if next.starts_with("always @(*)") => Some("// Combinational logic"),
            _ => None,
        };
        if t.is_empty() {
            // One blank line at most, with no trailing spaces (rust-hdl
            // indents its blank lines; a dropped heading leaves two).
            if !out.is_empty() && !out.ends_with("\n\n") {
                out.push('\n');
            }
            continue;
        }
        if let Some(r) = renamed {
            if next.is_empty() {
                continue;
            }
            out.push_str(&l.replace(t, r));
        } else {
            out.push_str(l.trim_end());
        }
        out.push('\n');
    }
    out
}

/// Stub signals that the combinational block assigns exactly once, at its
/// top level (unconditionally), from an input of the module, and reads
/// nowhere before: stub → input.
fn direct_inputs(body: &[String], inputs: &HashSet<String>) -> HashMap<String, String> {
    let mut assigned: HashMap<String, usize> = HashMap::new();
    let mut cand: HashMap<String, String> = HashMap::new();
    let mut read_before: HashSet<String> = HashSet::new();
    let mut in_logic = false;
    for l in body {
        let n = norm(l);
        if n == "always @(*) begin" {
            in_logic = true;
            continue;
        }
        if !in_logic {
            continue;
        }
        let top = l.starts_with("        ") && !l.starts_with("         ");
        let (lhs, rhs) = match n.strip_suffix(';').and_then(|s| s.split_once(" = ")) {
            Some((a, b)) => (Some(a.to_string()), b.to_string()),
            None => (None, n.clone()),
        };
        for t in idents(&rhs) {
            if !cand.contains_key(t) {
                read_before.insert(t.to_string());
            }
        }
        if let Some(lhs) = lhs {
            let base = lhs.split('[').next().unwrap_or(&lhs).to_string();
            *assigned.entry(base.clone()).or_default() += 1;
            if top && base == lhs && base.contains('$') && inputs.contains(rhs.as_str()) {
                cand.insert(base, rhs);
            }
        }
    }
    cand.retain(|s, _| assigned.get(s) == Some(&1) && !read_before.contains(s));
    cand
}

/// The register section of a module: per register its power-up value and
/// the clocked assignment of its next value, one line each. (One `always`
/// block per module reads as well, but Yosys maps it differently: the lean
/// sensor then needed 1,287 iCE40 logic cells, 7 more than an HX1K has, and
/// with one line per register 1,269, both before the literal sizing;
/// docs/architecture.md. The cell counts of ABC's mapping move with the
/// order of the netlist.)
fn registers(regs: &[Reg]) -> String {
    let map = HashMap::new();
    let mut s = String::from(
        "    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge\n",
    );
    for r in regs {
        let (q, d, clock) = (
            format!("{}_q", r.name),
            format!("{}_d", r.name),
            rename(&r.clock, &map),
        );
        s.push_str(&format!("    initial {q} = {};\n", r.dff.init));
        s.push_str(&format!("    always @(posedge {clock}) {q} <= {d};\n"));
    }
    s
}

/// The identifiers of a line (`$display` and other system names excluded).
fn idents(line: &str) -> Vec<&str> {
    let mut out = vec![];
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'$') {
                i += 1;
            }
            // A literal's base and digits (`32'h1f`) follow a quote.
            if start == 0 || b[start - 1] != b'\'' {
                out.push(&line[start..i]);
            }
        } else if c == b'$' || c.is_ascii_digit() {
            // A system name, or a number: skip its characters.
            i += 1;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
        } else {
            i += 1;
        }
    }
    out
}

/// The line with every identifier looked up in `map` (exact names) and
/// every `$` inside an identifier written `__`.
fn rename(line: &str, map: &HashMap<String, String>) -> String {
    let mut out = String::with_capacity(line.len() + 8);
    let b = line.as_bytes();
    let mut i = 0;
    let mut last = 0;
    while i < b.len() {
        let c = b[i];
        if (c.is_ascii_alphabetic() || c == b'_') && (i == 0 || b[i - 1] != b'\'') {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'$') {
                i += 1;
            }
            let id = &line[start..i];
            out.push_str(&line[last..start]);
            match map.get(id) {
                Some(to) => out.push_str(&to.replace('$', "__")),
                None => out.push_str(&id.replace('$', "__")),
            }
            last = i;
        } else if c == b'$' || c.is_ascii_digit() || c == b'\'' {
            i += 1;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
        } else {
            i += 1;
        }
    }
    out.push_str(&line[last..]);
    out
}

/// Panics when two declarations of a module (ports, registers, wires,
/// constants) have one name.
fn check_unique(module: &str, text: &str) {
    let mut seen = HashSet::new();
    for l in text.lines() {
        let n = norm(l);
        let decl = ["input ", "output ", "reg ", "wire ", "localparam "]
            .iter()
            .any(|k| n.starts_with(k));
        if !decl || !n.ends_with(';') {
            continue;
        }
        let lhs = n.split(" = ").next().unwrap_or(&n).trim_end_matches(';');
        let name = lhs.rsplit(' ').next().unwrap_or(lhs);
        let name = name.split('[').next().unwrap_or(name);
        assert!(
            seen.insert(name.to_string()),
            "{module}: two declarations of {name} after renaming"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rust_hdl::prelude::*;

    /// rust-hdl's text of a block and ours.
    fn both<U: Block>(mut uut: U) -> (String, String) {
        uut.connect_all();
        let raw = generate_verilog(&uut);
        let ours = readable(&raw);
        (raw, ours)
    }

    #[test]
    fn every_flip_flop_becomes_a_register_of_its_block() {
        for (name, (raw, ours)) in [
            ("slave", both(crate::node::slave::Slave::default())),
            ("master", both(crate::node::master::Master::default())),
            (
                "special master",
                both(crate::node::special_master::SpecialMaster::default()),
            ),
        ] {
            let raw_mods = modules(&raw);
            let flops: Vec<Dff> = raw_mods.iter().filter_map(dff).collect();
            let bits = |w: &str| -> usize {
                w.strip_prefix('[')
                    .and_then(|w| w.strip_suffix(":0]"))
                    .map_or(1, |h| h.parse::<usize>().expect("width") + 1)
            };
            let raw_bits: usize = flops.iter().map(|d| bits(&d.width)).sum();
            let mods = modules(&ours);
            assert!(mods.iter().all(|m| dff(m).is_none()), "{name}");
            assert_eq!(mods.len(), raw_mods.len() - flops.len(), "{name}");
            // One clocked assignment and one power-up value per flip-flop,
            // and as many register bits.
            let takes = ours
                .lines()
                .filter(|l| l.trim().ends_with("_d;") && l.contains("_q <= "))
                .count();
            assert_eq!(takes, flops.len(), "{name}");
            let mut reg_bits = 0;
            for m in &mods {
                for l in &m.body {
                    let n = norm(l);
                    if let Some(r) = n.strip_prefix("reg ").and_then(|r| r.strip_suffix(';')) {
                        let (w, sig) = r.rsplit_once(' ').unwrap_or(("", r));
                        let base = sig.strip_suffix("_q");
                        let clocked = base.is_some_and(|b| {
                            m.body
                                .iter()
                                .any(|x| norm(x).ends_with(&format!(") {b}_q <= {b}_d;")))
                        });
                        if clocked {
                            reg_bits += bits(w);
                        }
                    }
                }
            }
            assert_eq!(reg_bits, raw_bits, "{name}");
            assert!(!ours.contains('$'), "{name}: a $ is left");
            assert!(
                ours.len() * 3 < raw.len() * 2,
                "{name}: {} of {} bytes",
                ours.len(),
                raw.len()
            );
        }
    }

    #[test]
    fn a_clock_copied_from_an_input_is_connected_directly() {
        let (raw, ours) = both(crate::node::sw_dark::SwDark::default());
        assert!(raw.contains("dark$clock = clock;"));
        assert!(!ours.contains("dark__clock"), "{ours}");
        assert!(
            ours.contains("    always @(posedge clock) dark_q <= dark_d;"),
            "{ours}"
        );
    }

    #[test]
    fn identifiers_are_renamed_literals_and_system_names_are_not() {
        let map = HashMap::from([("a$q".to_string(), "a".to_string())]);
        assert_eq!(
            rename("x$d = a$q + 32'h1f; $display(b$c);", &map),
            "x__d = a + 32'h1f; $display(b__c);"
        );
        assert_eq!(idents("x$d = a$q[32'h1] & 4'b1010;"), vec!["x$d", "a$q"]);
    }
}
