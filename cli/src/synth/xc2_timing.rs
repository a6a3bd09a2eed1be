//! How fast a CoolRunner-II mapping could run: the longest register to
//! register paths of Yosys' netlist, counted in macrocells, and the core
//! clock they allow by Xilinx's delay model of each device and speed grade
//! (issue 21, deliverable 5; docs/synthesis.md, "Line rate on the
//! CoolRunner-II").
//!
//! No open tool analyses CoolRunner-II timing, so this is an estimate from
//! the mapping, not from a fitted design: each macrocell between two
//! registers is one pass through the interconnect (ZIA) and the PLA, as
//! Yosys mapped it. A fitter may split or merge macrocells differently.
//!
//! The delays are the ones Xilinx's timing simulator (ISE `tsim`) uses, as
//! Project Combine records them per device and speed grade
//! (`databases/coolrunner2.txt` of github.com/prjunnamed/prjcombine,
//! 0BSD/Apache-2.0; the CoolRunner-II speed data extracted by its
//! `xcpld_speed` tool). A path from a register through `d` macrocells to a
//! register takes
//!
//! ```text
//! DEL_CLK_Q + d × (DEL_UIM_IMUX + DEL_IMUX_OR) + (d − 1) × DEL_D_Q_COMB
//!           + SETUPHOLD_D_CLK_PT_FCLK (setup)
//! ```
//!
//! clock to output, `d` passes through the ZIA and a product term and OR
//! gate, the macrocell outputs between them, and the setup time against a
//! global clock. Both clocks (`clk`, `clk90`) are global (`BUFG`), so their
//! distribution delay is the same at both ends and drops out.
//!
//! The quadrature capture takes samples on four edges a quarter clock
//! apart (`clk` ↑, `clk90` ↑, `clk` ↓, `clk90` ↓, in that order), so a path
//! from one edge to the next has that fraction of the clock period: the
//! `clk90` ↓ sample reaches its `clk` ↑ register in a quarter clock.
//! Paths from pins and to pins are not counted (they are the board's
//! timing, not the core clock's).

use std::collections::HashMap;

use serde_json::Value;

use super::xc2_blocks::{is_register, Graph};
use super::Cpld;

/// One speed grade's delays, picoseconds (see the module doc).
#[derive(Debug, Clone, Copy)]
pub struct Speed {
    /// As Xilinx names it (`-7`).
    pub grade: &'static str,
    /// `DEL_CLK_Q`: clock to register output.
    pub clk_q: u32,
    /// `DEL_UIM_IMUX`: a macrocell output through the ZIA to a PLA input.
    pub uim_imux: u32,
    /// `DEL_IMUX_OR`: a PLA input through a product term and the OR gate.
    pub imux_or: u32,
    /// `DEL_D_Q_COMB`: a combinational macrocell's output.
    pub d_q_comb: u32,
    /// `SETUPHOLD_D_CLK_PT_FCLK`: setup of a product-term input to a
    /// global clock.
    pub setup: u32,
}

/// One speed grade from its delays in the order of [`Speed`]'s fields
/// (`DEL_CLK_Q`, `DEL_UIM_IMUX`, `DEL_IMUX_OR`, `DEL_D_Q_COMB`,
/// `SETUPHOLD_D_CLK_PT_FCLK` setup; ps, from Project Combine's database,
/// see the module doc), for [`super::CPLDS`].
pub const fn sp(grade: &'static str, v: [u32; 5]) -> Speed {
    Speed {
        grade,
        clk_q: v[0],
        uim_imux: v[1],
        imux_or: v[2],
        d_q_comb: v[3],
        setup: v[4],
    }
}

/// A clock edge of the quadrature capture, in quarters of the core clock
/// after `clk` rises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Edge {
    /// `clk` ↑.
    ClkRise = 0,
    /// `clk90` ↑.
    Clk90Rise = 1,
    /// `clk` ↓.
    ClkFall = 2,
    /// `clk90` ↓.
    Clk90Fall = 3,
}

impl Edge {
    fn name(self) -> &'static str {
        match self {
            Edge::ClkRise => "clk ↑",
            Edge::Clk90Rise => "clk90 ↑",
            Edge::ClkFall => "clk ↓",
            Edge::Clk90Fall => "clk90 ↓",
        }
    }
}

/// The quarters of a clock from a launching edge to the capturing edge
/// ([`super::capture_quarters`]).
fn quarters(from: Edge, to: Edge) -> u32 {
    super::capture_quarters(from as u32, to as u32)
}

/// The deepest path between two clock edges.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Path {
    /// The launching register's edge.
    pub from: Edge,
    /// The capturing register's edge.
    pub to: Edge,
    /// Macrocells on the way, the capturing register's own included.
    pub macrocells: u32,
    /// The capturing register, by the names of its output (the cell
    /// name when it has none).
    pub register: String,
}

impl Path {
    /// The core clock period this path needs at a speed grade, ps.
    pub fn period_ps(&self, s: &Speed) -> f64 {
        let d = self.macrocells.max(1);
        let delay = s.clk_q + d * (s.uim_imux + s.imux_or) + (d - 1) * s.d_q_comb + s.setup;
        f64::from(delay) * 4.0 / f64::from(quarters(self.from, self.to))
    }
}

/// The deepest register-to-register path for each pair of clock edges in
/// a CoolRunner-II netlist (Yosys JSON after `synth_coolrunner2`), in
/// edge order; empty without `merkur_top`.
pub fn paths(netlist: &Value) -> Vec<Path> {
    let Some(g) = Graph::new(netlist) else {
        return Vec::new();
    };
    let mut depth = Depths {
        g: &g,
        memo: HashMap::new(),
    };
    let mut worst: HashMap<(Edge, Edge), Path> = HashMap::new();
    for reg in g.cells.keys() {
        let Some(to) = edge_of(&g, reg) else {
            continue;
        };
        let data = g.port(reg, "D").into_iter().chain(g.port(reg, "T"));
        for bit in data {
            for (from, d) in depth.feeding(bit) {
                let p = worst.entry((from, to)).or_insert_with(|| Path {
                    from,
                    to,
                    macrocells: 0,
                    register: String::new(),
                });
                let name = g.register_label(reg);
                if (d, name.as_str()) > (p.macrocells, p.register.as_str()) {
                    p.macrocells = d;
                    p.register = name;
                }
            }
        }
    }
    let mut out: Vec<Path> = worst.into_values().collect();
    out.sort_by_key(|p| (p.from, p.to));
    out
}

/// The fastest core clock (MHz) the paths allow at a speed grade, and the
/// path that sets it.
pub fn fmax<'p>(paths: &'p [Path], s: &Speed) -> Option<(f64, &'p Path)> {
    paths
        .iter()
        .map(|p| (p.period_ps(s), p))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(t, p)| (1e6 / t, p))
}

/// One line for the report: each speed grade's core clock and line rate
/// (half the clock), the path that sets them, and the deepest logic.
pub fn summary(c: &Cpld, paths: &[Path]) -> Option<String> {
    let device = c.device;
    let grades: Vec<String> = c
        .speeds
        .iter()
        .filter_map(|s| {
            let (mhz, _) = fmax(paths, s)?;
            Some(format!(
                "{device}{} {mhz:.1} MHz, {:.1} Mbit/s",
                s.grade,
                mhz / 2.0
            ))
        })
        .collect();
    let (_, p) = fmax(paths, &c.speeds[0])?;
    let deepest = paths.iter().max_by_key(|p| p.macrocells)?;
    Some(format!(
        "core clock and line rate by Xilinx's delay model: {}; set by {} ({} from {} to {}, \
         {} of a clock); deepest logic {}, into {}",
        grades.join("; "),
        p.register,
        macrocells(p.macrocells),
        p.from.name(),
        p.to.name(),
        match quarters(p.from, p.to) {
            4 => "all",
            3 => "three quarters",
            2 => "half",
            _ => "a quarter",
        },
        macrocells(deepest.macrocells),
        deepest.register,
    ))
}

/// `1 macrocell`, `3 macrocells`.
fn macrocells(n: u32) -> String {
    format!("{n} macrocell{}", if n == 1 { "" } else { "s" })
}

/// A register's clock edge: its clock traced back through `BUFG` and
/// `IBUF` to a net named `clk` or `clk90`; `None` for any other clock.
fn edge_of(g: &Graph, reg: &str) -> Option<Edge> {
    let kind = g.kind(reg);
    if !is_register(kind) {
        return None;
    }
    let mut bit = *g.port(reg, "C").first()?;
    let mut clock = None;
    for _ in 0..3 {
        for name in g.names.get(&bit).into_iter().flatten() {
            match name.rsplit('.').next() {
                Some("clk90") => clock = Some(true),
                Some("clk") => clock = Some(false),
                _ => {}
            }
        }
        let Some(&buf) = g.driver.get(&bit) else {
            break;
        };
        if !matches!(g.kind(buf), "BUFG" | "IBUF") {
            break;
        }
        bit = *g.port(buf, "I").first()?;
    }
    let falling = kind.ends_with("_N");
    Some(match (clock?, falling) {
        (false, false) => Edge::ClkRise,
        (true, false) => Edge::Clk90Rise,
        (false, true) => Edge::ClkFall,
        (true, true) => Edge::Clk90Fall,
    })
}

/// For each macrocell, the most macrocells from a register of each clock
/// edge to its output (its own included), memoised.
struct Depths<'g, 'a> {
    g: &'g Graph<'a>,
    memo: HashMap<String, HashMap<Edge, u32>>,
}

impl Depths<'_, '_> {
    /// The deepest paths into a register's data input bit: through a
    /// macrocell, or straight from a register (which the fitter routes
    /// through one macrocell). Pins count for nothing.
    fn feeding(&mut self, bit: u64) -> HashMap<Edge, u32> {
        let Some(&d) = self.g.driver.get(&bit) else {
            return HashMap::new();
        };
        if self.g.kind(d) == "MACROCELL_XOR" {
            return self.macrocell(d);
        }
        edge_of(self.g, d).map(|e| (e, 1)).into_iter().collect()
    }

    fn macrocell(&mut self, mc: &str) -> HashMap<Edge, u32> {
        if let Some(m) = self.memo.get(mc) {
            return m.clone();
        }
        // A combinational loop would recurse forever: mark the cell first.
        self.memo.insert(mc.to_string(), HashMap::new());
        let mut out: HashMap<Edge, u32> = HashMap::new();
        for term in self.g.terms(mc) {
            let inputs = self.g.port(term, "IN").into_iter();
            for bit in inputs.chain(self.g.port(term, "IN_B")) {
                let Some(&src) = self.g.driver.get(&bit) else {
                    continue;
                };
                let found: Vec<(Edge, u32)> = if self.g.kind(src) == "MACROCELL_XOR" {
                    self.macrocell(src).into_iter().collect()
                } else {
                    edge_of(self.g, src).map(|e| (e, 0)).into_iter().collect()
                };
                for (e, d) in found {
                    let v = out.entry(e).or_default();
                    *v = (*v).max(d + 1);
                }
            }
        }
        self.memo.insert(mc.to_string(), out.clone());
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::{cpld, CPLDS};
    use super::*;

    /// A netlist with the clocks through `IBUF` and `BUFG`: register `a`
    /// (`clk90` ↓) feeds `q` (`clk` ↑) through one macrocell; `q` feeds
    /// `r` (`clk` ↑) through two macrocells in a row.
    fn netlist() -> Value {
        let cell = |t: &str, dirs: Value, conns: Value| serde_json::json!({"type": t, "port_directions": dirs, "connections": conns});
        let buf = serde_json::json!({"I": "input", "O": "output"});
        let ff = serde_json::json!({"C": "input", "D": "input", "Q": "output"});
        let and = serde_json::json!({"IN": "input", "IN_B": "input", "OUT": "output"});
        let or = serde_json::json!({"IN": "input", "OUT": "output"});
        let mc = serde_json::json!({"IN_ORTERM": "input", "OUT": "output"});
        serde_json::json!({"modules": {"merkur_top": {
            "netnames": {"clk": {"bits": [1]}, "clk90": {"bits": [2]}},
            "cells": {
                "ib0": cell("IBUF", buf.clone(), serde_json::json!({"I": [1], "O": [3]})),
                "bg0": cell("BUFG", buf.clone(), serde_json::json!({"I": [3], "O": [4]})),
                "ib1": cell("IBUF", buf.clone(), serde_json::json!({"I": [2], "O": [5]})),
                "bg1": cell("BUFG", buf, serde_json::json!({"I": [5], "O": [6]})),
                "a": cell("FDCP_N", ff.clone(), serde_json::json!({"C": [6], "D": [7], "Q": [10]})),
                "t1": cell("ANDTERM", and.clone(), serde_json::json!({"IN": [10], "IN_B": [], "OUT": [11]})),
                "o1": cell("ORTERM", or.clone(), serde_json::json!({"IN": [11], "OUT": [12]})),
                "m1": cell("MACROCELL_XOR", mc.clone(), serde_json::json!({"IN_ORTERM": [12], "OUT": [13]})),
                "q": cell("FDCP", ff.clone(), serde_json::json!({"C": [4], "D": [13], "Q": [20]})),
                "t2": cell("ANDTERM", and.clone(), serde_json::json!({"IN": [], "IN_B": [20], "OUT": [21]})),
                "o2": cell("ORTERM", or.clone(), serde_json::json!({"IN": [21], "OUT": [22]})),
                "m2": cell("MACROCELL_XOR", mc.clone(), serde_json::json!({"IN_ORTERM": [22], "OUT": [23]})),
                "t3": cell("ANDTERM", and, serde_json::json!({"IN": [23, 20], "IN_B": [], "OUT": [24]})),
                "o3": cell("ORTERM", or, serde_json::json!({"IN": [24], "OUT": [25]})),
                "m3": cell("MACROCELL_XOR", mc, serde_json::json!({"IN_ORTERM": [25], "OUT": [26]})),
                "r": cell("FDCP", ff, serde_json::json!({"C": [4], "D": [26], "Q": [30]}))
            }
        }}})
    }

    #[test]
    fn deepest_path_per_edge_pair() {
        let got = paths(&netlist());
        let want = vec![
            Path {
                from: Edge::ClkRise,
                to: Edge::ClkRise,
                macrocells: 2,
                register: "r".into(),
            },
            Path {
                from: Edge::Clk90Fall,
                to: Edge::ClkRise,
                macrocells: 1,
                register: "q".into(),
            },
        ];
        assert_eq!(got, want);
    }

    /// The XC2C512-7's figures worked by hand: two macrocells in a whole
    /// clock take 0.4 + 2 × (3.3 + 0.9) + 0.5 + 1.4 = 10.7 ns; one
    /// macrocell in a quarter clock 0.4 + 3.3 + 0.9 + 1.4 = 6.0 ns, so a
    /// 24.0 ns clock, 41.7 MHz, which sets the limit.
    #[test]
    fn quarter_clock_capture_sets_the_clock() {
        let p = paths(&netlist());
        let c = cpld("xc2c512").unwrap();
        let s = c.speeds[0];
        assert_eq!(s.grade, "-7");
        assert!((p[0].period_ps(&s) - 10_700.0).abs() < 1e-6);
        assert!((p[1].period_ps(&s) - 24_000.0).abs() < 1e-6);
        let (mhz, by) = fmax(&p, &s).unwrap();
        assert!((mhz - 1e6 / 24_000.0).abs() < 1e-9);
        assert_eq!(by.register, "q");
        let line = summary(&c, &p).unwrap();
        assert!(
            line.contains("XC2C512-7 41.7 MHz, 20.8 Mbit/s")
                && line.contains("set by q (1 macrocell from clk90 ↓ to clk ↑, a quarter")
                && line.ends_with("deepest logic 2 macrocells, into r"),
            "{line}"
        );
    }

    #[test]
    fn edges_and_quarters() {
        assert_eq!(quarters(Edge::ClkRise, Edge::ClkRise), 4);
        assert_eq!(quarters(Edge::Clk90Fall, Edge::ClkRise), 1);
        assert_eq!(quarters(Edge::Clk90Rise, Edge::ClkRise), 3);
        assert_eq!(quarters(Edge::ClkRise, Edge::ClkFall), 2);
        assert!(paths(&serde_json::json!({})).is_empty());
        // Every device of the family has its two grades, fastest first.
        for c in CPLDS {
            let s = c.speeds;
            let one = Path {
                from: Edge::ClkRise,
                to: Edge::ClkRise,
                macrocells: 1,
                register: "x".into(),
            };
            assert!(one.period_ps(&s[0]) < one.period_ps(&s[1]), "{}", c.name);
        }
    }
}
