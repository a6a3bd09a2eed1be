//! # xc2_cover — each macrocell's product terms chosen again: D or T register, either polarity
//!
//! Yosys 0.23's `synth_coolrunner2` covers the logic with ABC's `cover`
//! and keeps every register a D flip-flop, except the few whose input it
//! finds as an XOR with the register's own output (its `map_tff` step).
//! A CoolRunner-II macrocell can do more (Xilinx DS090, "Macrocell
//! configuration"): its register is a D or a T flip-flop, and the XOR gate
//! in front of it can invert the sum of products. A counter bit shows the
//! difference: as a D input, bit k of a counter with an enable takes k + 2
//! product terms; as a T input, one (the enable and the bits below). This
//! is the choice a CPLD fitter makes for each macrocell; Yosys 0.23 does
//! not, so `merkur synth` makes it here, on Yosys' mapped netlist
//! (`top.json`):
//!
//! 1. every macrocell's function is written out over the signals its
//!    product terms read (registers, pads and the macrocells of shared
//!    logic that Yosys factored out; they stay as they are), and for a
//!    macrocell that feeds only a register, also the register's other
//!    input: T = D xor Q for a D flip-flop, D = T xor Q for a T one;
//! 2. ABC (`yosys-abc`, part of Yosys) gives each function an irredundant
//!    sum of products (`strash; collapse; sop`: from its BDD, in whichever
//!    polarity has fewer cubes);
//! 3. a macrocell takes the cover with the fewest product terms, if that
//!    is fewer than Yosys' own, it reads at most 40 signals (a function
//!    block's ZIA inputs, as Yosys' `abc -sop -I 40` keeps) and it is not
//!    a constant; the macrocell's XOR inverts a cover of the complement,
//!    and its register changes mode when the other input was cheaper;
//! 4. ABC's `cec` proves that every changed macrocell, read back from the
//!    rewritten netlist, gives its register the same next state as before
//!    ([`recover`] keeps Yosys' cover otherwise).
//!
//! The macrocells stay the same in number. Tests: below (a counter-rich
//! design gets T flip-flops; an inverted product term and a register left
//! in its old mode are refused by the proof), and the fitted-`.jed` tests
//! of `super::xc2_fit`, which run every design through this step and
//! simulate the `.jed` against a reference model. Measured on ring8's
//! slaves in docs/benchmarks.md.

use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;
use std::path::Path;

use serde_json::{json, Map, Value};

use super::fpga::{read_json, run_tool_status};
use super::xc2_blocks::Graph;

/// Signals one macrocell's product terms may read: a function block's ZIA
/// inputs (Xilinx DS090), the limit Yosys' `abc -sop -I 40` keeps.
const MAX_INPUTS: usize = 40;

/// A literal: a net bit, and whether it is read true (`false`: inverted).
type Lit = (u64, bool);

/// A sum of products, in a polarity: the function is the OR of `cubes`
/// when `onset`, its complement otherwise.
#[derive(Debug, Clone, PartialEq)]
struct Cover {
    cubes: Vec<Vec<Lit>>,
    onset: bool,
}

impl Cover {
    fn inputs(&self) -> usize {
        self.cubes
            .iter()
            .flatten()
            .map(|l| l.0)
            .collect::<HashSet<_>>()
            .len()
    }
}

/// One macrocell of Yosys' netlist: its `MACROCELL_XOR`, the cells of its
/// sum of products and, when it feeds only a register, that register.
struct Macrocell {
    xor: String,
    /// `ANDTERM`s of the OR term, then the PTC one (if any).
    terms: Vec<String>,
    or: Option<String>,
    cubes: Vec<Vec<Lit>>,
    ptc: Option<Vec<Lit>>,
    invert: bool,
    /// (register cell, its output bit, it is a T flip-flop).
    reg: Option<(String, u64, bool)>,
}

/// What [`recover`] changed.
#[derive(Debug, Default, PartialEq, Eq)]
pub struct Recovered {
    /// Product terms before and after.
    pub pterms_before: usize,
    pub pterms_after: usize,
    /// Macrocells given a new cover; of them, registers that changed mode.
    pub macrocells: usize,
    pub to_t: usize,
    pub to_d: usize,
}

/// Re-covers the macrocells of `dir/top.json` (Yosys' CoolRunner-II
/// netlist) as the module documentation says and writes it back, once
/// ABC's `cec` has proven every changed macrocell's new register input
/// equal to its old one. ABC's files stay in `dir` (`cover.blif`,
/// `covered.blif`, `before.blif`, `after.blif`, `abc.log`, `cec.log`). An
/// ABC that fails or a proof that does not hold leaves `top.json` as it
/// was (`Err` with the reason; the caller keeps Yosys' cover).
pub fn recover(dir: &Path) -> Result<Recovered, String> {
    let mut netlist = read_json(dir, "top.json")?;
    let g = Graph::new(&netlist).ok_or("top.json has no module merkur_top with cells")?;
    let before = g.cells.values().filter(|c| c["type"] == "ANDTERM").count();
    let mut next_bit = max_bit(&g) + 1;
    let mcs = macrocells(&netlist);
    let mut funcs = Vec::new();
    for (k, mc) in mcs.iter().enumerate() {
        funcs.push(Func {
            name: format!("s{k}"),
            mc,
            xor_q: None,
        });
        if let Some((_, q, _)) = mc.reg {
            funcs.push(Func {
                name: format!("x{k}"),
                mc,
                xor_q: Some(q),
            });
        }
    }
    let covers = abc_covers(dir, &blif(&funcs, &HashSet::new()))?;
    let mut out = Recovered {
        pterms_before: before,
        pterms_after: before,
        ..Default::default()
    };
    let mut changed: HashMap<&str, &Macrocell> = HashMap::new();
    let cells = netlist["modules"]["merkur_top"]["cells"]
        .as_object_mut()
        .ok_or("top.json: merkur_top has no cells")?;
    for (k, mc) in mcs.iter().enumerate() {
        let same = covers.get(&format!("s{k}"));
        let other = covers.get(&format!("x{k}"));
        let mut best: Option<(&Cover, bool)> = None;
        for (cover, flip) in [(same, false), (other, true)] {
            let Some(c) = cover else { continue };
            let bound = best.map_or(mc.terms.len(), |b| b.0.cubes.len());
            if c.cubes.len() < bound && !constant(c) && c.inputs() <= MAX_INPUTS {
                best = Some((c, flip));
            }
        }
        let Some((cover, flip)) = best else { continue };
        out.pterms_after -= mc.terms.len() - cover.cubes.len();
        out.macrocells += 1;
        rewrite(cells, mc, cover, &mut next_bit);
        if flip {
            let (reg, _, t) = mc.reg.as_ref().expect("only a register's macrocell flips");
            switch_mode(&mut cells[reg.as_str()], *t);
            if *t {
                out.to_d += 1;
            } else {
                out.to_t += 1;
            }
        }
        changed.insert(&mc.xor, mc);
    }
    prove(dir, &netlist, &changed)?;
    std::fs::write(dir.join("top.json"), netlist.to_string())
        .map_err(|e| format!("cannot write top.json: {e}"))?;
    Ok(out)
}

/// ABC's irredundant covers of the functions of the BLIF model `model`.
fn abc_covers(dir: &Path, model: &str) -> Result<HashMap<String, Cover>, String> {
    std::fs::write(dir.join("cover.blif"), model)
        .map_err(|e| format!("cannot write cover.blif: {e}"))?;
    let script = "read_blif cover.blif; strash; collapse; sop; write_blif covered.blif";
    let (ok, log) = run_tool_status(dir, "yosys-abc", &["-c", script], "abc.log")?;
    if !ok || log.contains("Error") {
        return Err(format!(
            "yosys-abc failed (log {})",
            dir.join("abc.log").display()
        ));
    }
    let text = std::fs::read_to_string(dir.join("covered.blif"))
        .map_err(|e| format!("cannot read covered.blif: {e}"))?;
    read_blif(&text)
}

/// Proves with ABC's `cec` that each changed macrocell of the rewritten
/// `netlist` (read again, as the fitter will read it)
/// gives its register the same next state as before: the same function
/// for a register that kept its mode, that function xor the register's
/// output for one that changed it (D to T or back, as the rewritten
/// netlist has the register).
fn prove(dir: &Path, netlist: &Value, changed: &HashMap<&str, &Macrocell>) -> Result<(), String> {
    if changed.is_empty() {
        return Ok(());
    }
    let now: HashMap<String, Macrocell> = macrocells(netlist)
        .into_iter()
        .filter(|m| changed.contains_key(m.xor.as_str()))
        .map(|m| (m.xor.clone(), m))
        .collect();
    if now.len() != changed.len() {
        return Err("a rewritten macrocell cannot be read back".into());
    }
    let mut old = Vec::new();
    let mut new = Vec::new();
    let mut names: Vec<&&str> = changed.keys().collect();
    names.sort();
    for (i, x) in names.into_iter().enumerate() {
        let mc = changed[*x];
        // The register's mode as the netlist now has it, not as intended.
        let q = match (&mc.reg, &now[*x].reg) {
            (Some((_, q, t0)), Some((_, _, t1))) if t0 != t1 => Some(*q),
            _ => None,
        };
        old.push(Func {
            name: format!("c{i}"),
            mc,
            xor_q: None,
        });
        new.push(Func {
            name: format!("c{i}"),
            mc: &now[*x],
            xor_q: q,
        });
    }
    let all: Vec<&Macrocell> = old.iter().chain(&new).map(|f| f.mc).collect();
    let inputs = reads(&all);
    for (file, funcs) in [("before.blif", &old), ("after.blif", &new)] {
        std::fs::write(dir.join(file), blif(funcs, &inputs))
            .map_err(|e| format!("cannot write {file}: {e}"))?;
    }
    let (_, log) = run_tool_status(
        dir,
        "yosys-abc",
        &["-c", "cec before.blif after.blif"],
        "cec.log",
    )?;
    if log.contains("Networks are equivalent") {
        Ok(())
    } else {
        Err(format!(
            "ABC's cec does not prove the new covers equal (log {})",
            dir.join("cec.log").display()
        ))
    }
}

/// A cover that is a constant (no product term, or one that reads
/// nothing): kept as Yosys mapped it, since a macrocell without product
/// terms is not what the fitter expects.
fn constant(c: &Cover) -> bool {
    c.cubes.is_empty() || c.cubes.iter().any(|q| q.is_empty())
}

/// The net bits of a connection; `None` when one is a constant.
fn nets(v: &Value) -> Option<Vec<u64>> {
    v.as_array()?.iter().map(Value::as_u64).collect()
}

/// The highest net bit of the netlist, so that new nets can follow it.
fn max_bit(g: &Graph) -> u64 {
    g.driver
        .keys()
        .chain(g.readers.keys())
        .chain(g.names.keys())
        .copied()
        .max()
        .unwrap_or(1)
}

/// The macrocells of `merkur_top` whose sum of products can be read:
/// every bit a net (not a constant), every product term and OR term read
/// once.
fn macrocells(netlist: &Value) -> Vec<Macrocell> {
    let Some(g) = Graph::new(netlist) else {
        return Vec::new();
    };
    // A cell whose one output is read once.
    let once = |c: &str| match g.port(c, "OUT")[..] {
        [b] => g.readers.get(&b).map_or(0, Vec::len) == 1,
        _ => false,
    };
    let term = |b: Option<u64>| -> Option<(String, Vec<Lit>)> {
        let name = *g.driver.get(&b?)?;
        if g.kind(name) != "ANDTERM" || !once(name) {
            return None;
        }
        let conn = &g.cells[name]["connections"];
        let mut lits: Vec<Lit> = nets(&conn["IN"])?.into_iter().map(|b| (b, true)).collect();
        lits.extend(nets(&conn["IN_B"])?.into_iter().map(|b| (b, false)));
        Some((name.to_string(), lits))
    };
    let mut out = Vec::new();
    'mc: for (name, c) in g.cells {
        if c["type"] != "MACROCELL_XOR" {
            continue;
        }
        let conn = &c["connections"];
        let mut mc = Macrocell {
            xor: name.clone(),
            terms: Vec::new(),
            or: None,
            cubes: Vec::new(),
            ptc: None,
            invert: c["parameters"]["INVERT_OUT"]
                .as_str()
                .is_some_and(|s| s.contains('1')),
            reg: None,
        };
        if let Some(b) = conn["IN_ORTERM"].as_array().and_then(|a| a.first()) {
            let Some(&or) = b.as_u64().and_then(|b| g.driver.get(&b)) else {
                continue;
            };
            if g.kind(or) == "ORTERM" && once(or) {
                for b in g.cells[or]["connections"]["IN"]
                    .as_array()
                    .into_iter()
                    .flatten()
                {
                    let Some((t, lits)) = term(b.as_u64()) else {
                        continue 'mc;
                    };
                    mc.terms.push(t);
                    mc.cubes.push(lits);
                }
                mc.or = Some(or.to_string());
            } else {
                let Some((t, lits)) = term(b.as_u64()) else {
                    continue;
                };
                mc.terms.push(t);
                mc.cubes.push(lits);
            }
        }
        if let Some(b) = conn["IN_PTC"].as_array().and_then(|a| a.first()) {
            let Some((t, lits)) = term(b.as_u64()) else {
                continue;
            };
            mc.terms.push(t);
            mc.ptc = Some(lits);
        }
        let [out_bit] = g.port(name, "OUT")[..] else {
            continue;
        };
        if mc.terms.is_empty() {
            continue;
        }
        if let Some([(reg, port)]) = g.readers.get(&out_bit).map(Vec::as_slice) {
            let t = match (g.kind(reg), *port) {
                ("FDCP" | "FDCP_N", "D") => Some(false),
                ("FTCP" | "FTCP_N", "T") => Some(true),
                _ => None,
            };
            if let (Some(t), [q]) = (t, g.port(reg, "Q").as_slice()) {
                mc.reg = Some((reg.to_string(), *q, t));
            }
        }
        out.push(mc);
    }
    out
}

/// A function for ABC: macrocell `mc`'s, or (`xor_q`) that xor a
/// register's output.
struct Func<'a> {
    name: String,
    mc: &'a Macrocell,
    xor_q: Option<u64>,
}

/// A BLIF model of `funcs` as its outputs, over the net bits (`n<bit>`)
/// they read; `inputs` are declared too, so that two models can be
/// compared by ABC's `cec`.
fn blif(funcs: &[Func], inputs: &HashSet<u64>) -> String {
    let mut inputs = inputs.clone();
    let mut body = String::new();
    let names = |body: &mut String, out: &str, cubes: &[Vec<Lit>]| {
        let mut ins: Vec<u64> = cubes.iter().flatten().map(|l| l.0).collect();
        ins.sort_unstable();
        ins.dedup();
        let _ = write!(body, ".names");
        for b in &ins {
            let _ = write!(body, " n{b}");
        }
        let _ = writeln!(body, " {out}");
        for cube in cubes {
            let row: Option<String> = ins
                .iter()
                .map(
                    |b| match (cube.contains(&(*b, true)), cube.contains(&(*b, false))) {
                        (true, true) => None,
                        (true, false) => Some('1'),
                        (false, true) => Some('0'),
                        (false, false) => Some('-'),
                    },
                )
                .collect();
            if let Some(row) = row {
                let _ = writeln!(body, "{row} 1");
            }
        }
        ins
    };
    for f in funcs {
        let n = &f.name;
        inputs.extend(names(&mut body, &format!("{n}_or"), &f.mc.cubes));
        let ptc: Vec<Vec<Lit>> = f.mc.ptc.iter().cloned().collect();
        inputs.extend(names(&mut body, &format!("{n}_ptc"), &ptc));
        let xor = if f.mc.invert {
            "00 1\n11 1"
        } else {
            "10 1\n01 1"
        };
        match f.xor_q {
            None => {
                let _ = writeln!(body, ".names {n}_or {n}_ptc {n}\n{xor}");
            }
            Some(q) => {
                inputs.insert(q);
                let _ = writeln!(body, ".names {n}_or {n}_ptc {n}_mc\n{xor}");
                let _ = writeln!(body, ".names {n}_mc n{q} {n}\n10 1\n01 1");
            }
        }
    }
    let mut ins: Vec<u64> = inputs.into_iter().collect();
    ins.sort_unstable();
    let mut text = String::from(".model cover\n.inputs");
    for b in ins {
        let _ = write!(text, " n{b}");
    }
    text += "\n.outputs";
    for f in funcs {
        let _ = write!(text, " {}", f.name);
    }
    text + "\n" + &body + ".end\n"
}

/// Every net bit that the functions of `mcs` read, their registers'
/// outputs included.
fn reads(mcs: &[&Macrocell]) -> HashSet<u64> {
    let mut out = HashSet::new();
    for mc in mcs {
        out.extend(mc.cubes.iter().chain(&mc.ptc).flatten().map(|l| l.0));
        out.extend(mc.reg.as_ref().map(|r| r.1));
    }
    out
}

/// BLIF nodes by output name: their inputs, and their rows (pattern,
/// output value).
type Nodes = HashMap<String, (Vec<String>, Vec<(String, char)>)>;

/// The covers of `covered.blif` (ABC's `write_blif` after `collapse;
/// sop`), by output name. Each output is a node over the inputs (`n<bit>`),
/// or a buffer or inverter of another output's node.
fn read_blif(text: &str) -> Result<HashMap<String, Cover>, String> {
    let joined = text.replace("\\\n", " ");
    let mut nodes: Nodes = HashMap::new();
    let mut outputs = Vec::new();
    let mut cur: Option<String> = None;
    for line in joined.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(rest) = line.strip_prefix(".outputs") {
            outputs.extend(rest.split_whitespace().map(String::from));
            cur = None;
        } else if let Some(rest) = line.strip_prefix(".names") {
            let mut sig: Vec<String> = rest.split_whitespace().map(String::from).collect();
            let out = sig.pop().ok_or("covered.blif: .names without an output")?;
            nodes.insert(out.clone(), (sig, Vec::new()));
            cur = Some(out);
        } else if line.starts_with('.') {
            cur = None;
        } else if let Some(n) = &cur {
            let node = nodes.get_mut(n).expect("inserted above");
            let (pat, val) = match line.rsplit_once(' ') {
                Some((p, v)) => (p.trim().to_string(), v),
                None => (String::new(), line),
            };
            let val = val.chars().next().filter(|c| *c == '0' || *c == '1');
            let val = val.ok_or_else(|| format!("covered.blif: bad cube line `{line}`"))?;
            node.1.push((pat, val));
        }
    }
    let mut covers = HashMap::new();
    for o in outputs {
        if let Some(c) = resolve(&nodes, &o, 0) {
            covers.insert(o, c);
        }
    }
    Ok(covers)
}

fn resolve(nodes: &Nodes, name: &str, depth: usize) -> Option<Cover> {
    let (ins, rows) = nodes.get(name)?;
    let onset = rows.first().map_or(true, |r| r.1 == '1');
    if rows.iter().any(|r| (r.1 == '1') != onset) {
        return None;
    }
    let pis: Option<Vec<u64>> = ins
        .iter()
        .map(|s| s.strip_prefix('n').and_then(|b| b.parse().ok()))
        .collect();
    if let Some(pis) = pis {
        let mut cubes = Vec::new();
        for (pat, _) in rows {
            let mut cube = Vec::new();
            for (b, ch) in pis.iter().zip(pat.chars()) {
                match ch {
                    '1' => cube.push((*b, true)),
                    '0' => cube.push((*b, false)),
                    _ => {}
                }
            }
            cubes.push(cube);
        }
        return Some(Cover { cubes, onset });
    }
    // A buffer or inverter of another node.
    match (&ins[..], &rows[..]) {
        ([inner], [(pat, _)]) if depth < 4 => {
            let c = resolve(nodes, inner, depth + 1)?;
            let same = (pat == "1") == onset;
            Some(Cover {
                onset: c.onset == same,
                cubes: c.cubes,
            })
        }
        _ => None,
    }
}

fn bin32(v: usize) -> String {
    format!("{v:032b}")
}

/// Replaces macrocell `mc`'s product terms with `cover`'s.
fn rewrite(cells: &mut Map<String, Value>, mc: &Macrocell, cover: &Cover, next: &mut u64) {
    for t in mc.terms.iter().chain(&mc.or) {
        cells.remove(t);
    }
    let mut outs = Vec::new();
    for (i, cube) in cover.cubes.iter().enumerate() {
        let t: Vec<u64> = cube.iter().filter(|l| l.1).map(|l| l.0).collect();
        let f: Vec<u64> = cube.iter().filter(|l| !l.1).map(|l| l.0).collect();
        let out = *next;
        *next += 1;
        outs.push(out);
        cells.insert(
            format!("{}$cover$and{i}", mc.xor),
            json!({
                "hide_name": 1, "type": "ANDTERM", "attributes": {},
                "parameters": {"TRUE_INP": bin32(t.len()), "COMP_INP": bin32(f.len())},
                "port_directions": {"IN": "input", "IN_B": "input", "OUT": "output"},
                "connections": {"IN": t, "IN_B": f, "OUT": [out]},
            }),
        );
    }
    let or_out = *next;
    *next += 1;
    cells.insert(
        format!("{}$cover$or", mc.xor),
        json!({
            "hide_name": 1, "type": "ORTERM", "attributes": {},
            "parameters": {"WIDTH": bin32(outs.len())},
            "port_directions": {"IN": "input", "OUT": "output"},
            "connections": {"IN": outs, "OUT": [or_out]},
        }),
    );
    let x = &mut cells[mc.xor.as_str()];
    x["parameters"]["INVERT_OUT"] = json!(bin32(usize::from(!cover.onset)));
    let out = x["connections"]["OUT"].clone();
    x["connections"] = json!({"IN_ORTERM": [or_out], "OUT": out});
    x["port_directions"] = json!({"IN_ORTERM": "input", "OUT": "output"});
}

/// A register from D to T flip-flop (`t`: from T to D), the same clock,
/// set, reset and initial value.
fn switch_mode(reg: &mut Value, t: bool) {
    let (from, to) = if t { ("T", "D") } else { ("D", "T") };
    let kind = reg["type"].as_str().unwrap_or("").to_string();
    let new = match (kind.as_str(), t) {
        ("FDCP", false) => "FTCP",
        ("FDCP_N", false) => "FTCP_N",
        ("FTCP", true) => "FDCP",
        ("FTCP_N", true) => "FDCP_N",
        _ => unreachable!("only D and T flip-flops are given to switch_mode"),
    };
    reg["type"] = json!(new);
    for key in ["connections", "port_directions"] {
        if let Some(m) = reg[key].as_object_mut() {
            if let Some(v) = m.remove(from) {
                m.insert(to.to_string(), v);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counters as a slave has them (a clear, an enable, a load, a count
    /// down to 0), a shift register and a decode: the logic whose D-input
    /// covers are large.
    const COUNTERS: &str = "module merkur_top(clk, en, clr, ld, d, cnt, down, sh, hit);
  input clk, en, clr, ld;
  input [7:0] d;
  output reg [11:0] cnt = 12'd0;
  output reg [9:0] down = 10'd700;
  output reg [7:0] sh = 8'd0;
  output hit;
  always @(posedge clk) if (clr) cnt <= 12'd0; else if (en) cnt <= cnt + 12'd1;
  always @(posedge clk) if (ld) down <= {2'b0, d}; else if (down != 10'd0) down <= down - 10'd1;
  always @(posedge clk) if (en) sh <= {sh[6:0], d[0] ^ sh[7]};
  assign hit = (cnt == 12'd2310) | (down == 10'd0);
endmodule
";

    fn mapped(label: &str) -> std::path::PathBuf {
        let dir =
            std::env::temp_dir().join(format!("merkur-xc2cover-{}-{label}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("top.v"), COUNTERS).unwrap();
        super::super::run_tool(
            &dir,
            "yosys",
            &["-p", &super::super::xc2_script()],
            "yosys.log",
        )
        .unwrap_or_else(|e| panic!("{e}"));
        dir
    }

    fn and_terms(dir: &Path) -> usize {
        let j = read_json(dir, "top.json").unwrap();
        let cells = j["modules"]["merkur_top"]["cells"].as_object().unwrap();
        cells.values().filter(|c| c["type"] == "ANDTERM").count()
    }

    fn registers(dir: &Path) -> (usize, usize) {
        let j = read_json(dir, "top.json").unwrap();
        let cells = j["modules"]["merkur_top"]["cells"].as_object().unwrap();
        let n = |k: &str| cells.values().filter(|c| c["type"] == k).count();
        (n("FDCP"), n("FTCP"))
    }

    /// The counters' bits become T flip-flops and the product terms fewer;
    /// `recover` returns only after ABC's `cec` has proven each new cover,
    /// and the netlist it writes is what it reports.
    #[test]
    fn counters_become_t_flip_flops() {
        let dir = mapped("counters");
        let (d0, t0) = registers(&dir);
        let terms_before = and_terms(&dir);
        let r = recover(&dir).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(r.pterms_before, terms_before);
        let (d1, t1) = registers(&dir);
        assert_eq!(d0 + t0, 30, "the design's 30 registers");
        assert_eq!(t1, t0 + r.to_t - r.to_d);
        assert_eq!(d1 + t1, d0 + t0);
        assert!(r.to_t >= 12, "the up-counter's bits at least: {r:?}");
        assert_eq!(and_terms(&dir), r.pterms_after);
        assert!(r.pterms_after < terms_before, "{r:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A cover that is not the macrocell's function is refused: one
    /// product term's literals inverted, or a register left in its old
    /// mode after its cover changed to the other one's.
    #[test]
    fn a_wrong_cover_is_not_proven() {
        let dir = mapped("wrong");
        recover(&dir).unwrap_or_else(|e| panic!("{e}"));
        let j = read_json(&dir, "top.json").unwrap();
        let mcs = macrocells(&j);
        let mc = mcs
            .iter()
            .find(|m| m.reg.as_ref().is_some_and(|r| r.2))
            .expect("a T register");
        let mut changed = HashMap::new();
        changed.insert(mc.xor.as_str(), mc);
        prove(&dir, &j, &changed).expect("the netlist as written is its own function");

        let mut swapped = j.clone();
        let t = &mut swapped["modules"]["merkur_top"]["cells"][mc.terms[0].as_str()]["connections"];
        let (a, b) = (t["IN"].clone(), t["IN_B"].clone());
        t["IN"] = b;
        t["IN_B"] = a;
        assert!(
            prove(&dir, &swapped, &changed).is_err(),
            "inverted literals proven"
        );

        let mut moded = j.clone();
        let reg = &mc.reg.as_ref().unwrap().0;
        switch_mode(
            &mut moded["modules"]["merkur_top"]["cells"][reg.as_str()],
            true,
        );
        assert!(
            prove(&dir, &moded, &changed).is_err(),
            "a T cover on a D register proven"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
