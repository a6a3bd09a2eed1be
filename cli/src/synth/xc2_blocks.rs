//! Where a CoolRunner-II mapping spends its macrocells and product terms,
//! block by block: read from Yosys' netlist (`write_json`) after
//! `synth_coolrunner2`, for the refusal of a node that does not fit and for
//! the report of one that does (docs/synthesis.md, "What the CPLD costs,
//! block by block").
//!
//! Each macrocell (`MACROCELL_XOR`) is counted with its product terms (the
//! `ANDTERM`s of its OR term and its PTC input) for the register it feeds,
//! and the register for the block that holds it: the instance path of its
//! output, two levels deep (`node.fwd`, `node.rx_in`; `node` for the node's
//! own registers). A macrocell that feeds no register is logic that Yosys
//! factored out for several: "shared logic". Product terms on a register's
//! clock enable, set or reset and on output enables belong to no macrocell
//! and are not counted here.

use std::collections::{HashMap, HashSet};

use serde_json::Value;

/// One block's share of a CoolRunner-II mapping.
#[derive(Debug, PartialEq, Eq)]
pub struct BlockCost {
    /// Instance path (two levels), or `shared logic`.
    pub block: String,
    /// Macrocells.
    pub macrocells: u64,
    /// Product terms of those macrocells.
    pub pterms: u64,
}

/// A `merkur_top` netlist from Yosys' JSON with each net bit's driver
/// and readers: what [`block_costs`] and the timing estimate
/// (`super::xc2_timing`) walk.
pub struct Graph<'a> {
    /// The cells by name.
    pub cells: &'a serde_json::Map<String, Value>,
    /// The cell that drives each net bit.
    pub driver: HashMap<u64, &'a str>,
    /// The cells and input ports that read each net bit.
    pub readers: HashMap<u64, Vec<(&'a str, &'a str)>>,
    /// Every name Yosys kept for each net bit (`$`-names left out).
    pub names: HashMap<u64, Vec<String>>,
}

impl<'a> Graph<'a> {
    /// The graph of `merkur_top`; `None` when the netlist has no such
    /// module, or it has no cells or net names.
    pub fn new(netlist: &'a Value) -> Option<Self> {
        let top = super::fpga::yosys_top(netlist)?;
        let cells = top["cells"].as_object()?;
        let names = bit_names(top["netnames"].as_object()?);
        let mut driver = HashMap::new();
        let mut readers: HashMap<u64, Vec<(&str, &str)>> = HashMap::new();
        for (cn, c) in cells {
            let Some(dirs) = c["port_directions"].as_object() else {
                continue;
            };
            for (port, dir) in dirs {
                for bit in bits(&c["connections"][port]) {
                    if dir == "output" {
                        driver.insert(bit, cn.as_str());
                    } else {
                        readers
                            .entry(bit)
                            .or_default()
                            .push((cn.as_str(), port.as_str()));
                    }
                }
            }
        }
        Some(Self {
            cells,
            driver,
            readers,
            names,
        })
    }

    /// A cell's type (`""` for a name that is not a cell).
    pub fn kind(&self, cell: &str) -> &'a str {
        self.cells
            .get(cell)
            .and_then(|c| c["type"].as_str())
            .unwrap_or("")
    }

    /// The net bits on one port of a cell.
    pub fn port(&self, cell: &str, port: &str) -> Vec<u64> {
        self.cells
            .get(cell)
            .map(|c| bits(&c["connections"][port]).collect())
            .unwrap_or_default()
    }

    /// The cell driving a net bit, if it is of type `kind`.
    fn driven_by(&self, bit: u64, kind: &str) -> Option<&'a str> {
        self.driver
            .get(&bit)
            .copied()
            .filter(|d| self.kind(d) == kind)
    }

    /// The product terms (`ANDTERM`s) of a macrocell: its OR term's and
    /// its PTC input's.
    pub fn terms(&self, macrocell: &str) -> HashSet<&'a str> {
        let mut terms = HashSet::new();
        for bit in self.port(macrocell, "IN_PTC") {
            terms.extend(self.driven_by(bit, "ANDTERM"));
        }
        for bit in self.port(macrocell, "IN_ORTERM") {
            let Some(or) = self.driven_by(bit, "ORTERM") else {
                continue;
            };
            for and in self.port(or, "IN") {
                terms.extend(self.driven_by(and, "ANDTERM"));
            }
        }
        terms
    }

    /// A register's name for a reader: from the names of its output
    /// ([`register_name`]); its cell name when its output has none.
    pub fn register_label(&self, reg: &str) -> String {
        self.port(reg, "Q")
            .first()
            .and_then(|q| self.names.get(q))
            .map(|aliases| register_name(aliases))
            .filter(|n| !n.is_empty())
            .unwrap_or_else(|| reg.to_string())
    }

    /// The register (flip-flop or latch) whose data input (`D`, `T`) a
    /// net bit feeds, if any.
    pub fn register_fed_by(&self, bit: u64) -> Option<&'a str> {
        self.readers.get(&bit)?.iter().find_map(|(r, port)| {
            (is_register(self.kind(r)) && matches!(*port, "D" | "T")).then_some(*r)
        })
    }
}

/// A CoolRunner-II register cell (`FDCP`, `FTCP_N`, `LDCP`, …).
pub fn is_register(kind: &str) -> bool {
    kind.starts_with("FD") || kind.starts_with("FT") || kind.starts_with("LD")
}

/// The product terms (`ANDTERM`s) of `merkur_top` that differ from each
/// other: the macrocells of one function block share a product term they
/// all use (its PLA, Xilinx DS090; the fitter places them so), so a design
/// with more than this count cannot fit, while one with more `ANDTERM`s
/// may. 0 when the netlist has no such module.
pub fn distinct_pterms(netlist: &Value) -> u64 {
    let Some(g) = Graph::new(netlist) else {
        return 0;
    };
    let mut seen = HashSet::new();
    for c in g.cells.values().filter(|c| c["type"] == "ANDTERM") {
        let mut t: Vec<u64> = bits(&c["connections"]["IN"]).collect();
        let mut f: Vec<u64> = bits(&c["connections"]["IN_B"]).collect();
        t.sort_unstable();
        f.sort_unstable();
        seen.insert((t, f));
    }
    seen.len() as u64
}

/// The blocks of `merkur_top` in a Yosys JSON netlist, most product terms
/// first; an empty list when the netlist has no such module.
pub fn block_costs(netlist: &Value) -> Vec<BlockCost> {
    let Some(g) = Graph::new(netlist) else {
        return Vec::new();
    };
    let mut sums: HashMap<String, (u64, u64)> = HashMap::new();
    for cn in g.cells.keys() {
        if g.kind(cn) != "MACROCELL_XOR" {
            continue;
        }
        let reg = g
            .port(cn, "OUT")
            .first()
            .and_then(|&o| g.register_fed_by(o));
        let block = reg
            .and_then(|r| g.port(r, "Q").first().copied())
            .and_then(|q| g.names.get(&q))
            .map(|aliases| block_of(aliases))
            .unwrap_or_else(|| "shared logic".to_string());
        let e = sums.entry(block).or_default();
        e.0 += 1;
        e.1 += g.terms(cn).len() as u64;
    }
    let mut out: Vec<BlockCost> = sums
        .into_iter()
        .map(|(block, (macrocells, pterms))| BlockCost {
            block,
            macrocells,
            pterms,
        })
        .collect();
    out.sort_by(|a, b| b.pterms.cmp(&a.pterms).then(a.block.cmp(&b.block)));
    out
}

/// The first `n` blocks as one line: `node.fwd 1632 product terms (170
/// macrocells), …`.
pub fn summary(costs: &[BlockCost], n: usize) -> String {
    costs
        .iter()
        .take(n)
        .map(|c| {
            format!(
                "{} {} product terms ({} macrocells)",
                c.block, c.pterms, c.macrocells
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The net bits of a connection (constants such as `"0"` left out).
fn bits(v: &Value) -> impl Iterator<Item = u64> + '_ {
    v.as_array().into_iter().flatten().filter_map(Value::as_u64)
}

/// Every name Yosys kept for each net bit (`$`-names left out).
fn bit_names(netnames: &serde_json::Map<String, Value>) -> HashMap<u64, Vec<String>> {
    let mut m: HashMap<u64, Vec<String>> = HashMap::new();
    for (name, net) in netnames {
        if name.starts_with('$') {
            continue;
        }
        for bit in bits(&net["bits"]) {
            m.entry(bit)
                .or_default()
                .push(name.trim_start_matches('\\').to_string());
        }
    }
    m
}

/// The block of a register, from the names of its output
/// ([`register_name`]), cut to two levels below the top.
fn block_of(aliases: &[String]) -> String {
    let reg = register_name(aliases);
    let path: Vec<&str> = reg.split('.').collect();
    let inst = &path[..path.len().saturating_sub(1)];
    if inst.is_empty() {
        "top".to_string()
    } else {
        inst[..inst.len().min(2)].join(".")
    }
}

/// The name of a register among the names of its output: its own name
/// (rust-hdl calls a flip-flop's output `<name>_q`) if there is one; else
/// the longest instance path that is not an input port (`i_*`) of a block
/// that reads it, such as the top's capture register `cap_pi.q` feeding
/// `node.sbox.i_pi`.
fn register_name(aliases: &[String]) -> String {
    let base: Vec<String> = aliases
        .iter()
        .map(|a| a.split('[').next().unwrap_or(a).to_string())
        .collect();
    let deepest = |names: &mut dyn Iterator<Item = &String>| {
        names
            .max_by_key(|a| (a.matches('.').count(), (*a).clone()))
            .cloned()
    };
    let is_input = |a: &String| a.rsplit('.').next().is_some_and(|l| l.starts_with("i_"));
    deepest(&mut base.iter().filter(|a| a.ends_with("_q")))
        .or_else(|| deepest(&mut base.iter().filter(|a| !is_input(a))))
        .or_else(|| deepest(&mut base.iter()))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Identical product terms (the same true and inverted inputs, in any
    /// order) count once; one that reads an input the other way does not.
    #[test]
    fn identical_product_terms_count_once() {
        let t = |ins: &[u64], inb: &[u64], out: u64| {
            serde_json::json!({"type": "ANDTERM",
                "port_directions": {"OUT": "output", "IN": "input", "IN_B": "input"},
                "connections": {"OUT": [out], "IN": ins, "IN_B": inb}})
        };
        let netlist = serde_json::json!({"modules": {"merkur_top": {
            "netnames": {"x": {"bits": [10, 11, 12]}},
            "cells": {
                "a1": t(&[10, 11], &[12], 1),
                "a2": t(&[11, 10], &[12], 2),
                "a3": t(&[10], &[11, 12], 3),
                "a4": t(&[10, 11, 12], &[], 4),
            }
        }}});
        assert_eq!(distinct_pterms(&netlist), 3);
        assert_eq!(distinct_pterms(&serde_json::json!({})), 0);
    }

    /// A hand-written netlist: a register in `node.fwd` fed by a macrocell
    /// of two product terms (OR term) and one PTC term, a register in `node`
    /// fed by one product term, and a macrocell that feeds no register.
    #[test]
    fn costs_per_block() {
        let netlist = serde_json::json!({"modules": {"merkur_top": {
            "netnames": {
                "node.fwd.slot_q": {"bits": [10, 11]},
                "nc_slot": {"bits": [10, 11]},
                "node.fwd.o_slot": {"bits": [10, 11]},
                "node.quiet_q": {"bits": [12]},
                "$abc$1": {"bits": [20]}
            },
            "cells": {
                "a1": {"type": "ANDTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [1], "IN": [12]}},
                "a2": {"type": "ANDTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [2], "IN": [11]}},
                "a3": {"type": "ANDTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [3], "IN": [10]}},
                "o1": {"type": "ORTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [4], "IN": [1, 2]}},
                "m1": {"type": "MACROCELL_XOR",
                       "port_directions": {"OUT": "output", "IN_ORTERM": "input", "IN_PTC": "input"},
                       "connections": {"OUT": [5], "IN_ORTERM": [4], "IN_PTC": [3]}},
                "f1": {"type": "FDCP", "port_directions": {"Q": "output", "D": "input"},
                       "connections": {"Q": [10], "D": [5]}},
                "o2": {"type": "ORTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [6], "IN": [3]}},
                "m2": {"type": "MACROCELL_XOR",
                       "port_directions": {"OUT": "output", "IN_ORTERM": "input"},
                       "connections": {"OUT": [7], "IN_ORTERM": [6]}},
                "f2": {"type": "FTCP", "port_directions": {"Q": "output", "T": "input"},
                       "connections": {"Q": [12], "T": [7]}},
                "o3": {"type": "ORTERM", "port_directions": {"OUT": "output", "IN": "input"},
                       "connections": {"OUT": [8], "IN": [1, 2, 3]}},
                "m3": {"type": "MACROCELL_XOR",
                       "port_directions": {"OUT": "output", "IN_ORTERM": "input"},
                       "connections": {"OUT": [20], "IN_ORTERM": [8]}}
            }
        }}});
        let got = block_costs(&netlist);
        // Most product terms first; a tie goes by name.
        let want = [("node.fwd", 1, 3), ("shared logic", 1, 3), ("node", 1, 1)];
        let want: Vec<BlockCost> = want
            .iter()
            .map(|&(b, m, p)| BlockCost {
                block: b.into(),
                macrocells: m,
                pterms: p,
            })
            .collect();
        assert_eq!(got, want);
        assert_eq!(
            summary(&got, 2),
            "node.fwd 3 product terms (1 macrocells), shared logic 3 product terms (1 macrocells)"
        );
    }

    #[test]
    fn no_top_module_no_blocks() {
        let netlist = serde_json::json!({"modules": {"other": {"cells": {}, "netnames": {}}}});
        assert!(block_costs(&netlist).is_empty());
        assert!(block_costs(&serde_json::json!({})).is_empty());
    }

    #[test]
    fn register_names_win_over_ports() {
        let a = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            block_of(&a(&[
                "nc_data[3]",
                "node.rx_in.mon.word.data_q[3]",
                "node.o_data[3]"
            ])),
            "node.rx_in"
        );
        assert_eq!(block_of(&a(&["node.quiet_q"])), "node");
        assert_eq!(
            block_of(&a(&[
                "cap_pi.q[1]",
                "node.i_pi[1]",
                "node.sbox.i_pi[1]",
                "pi_s[1]"
            ])),
            "cap_pi"
        );
        assert_eq!(block_of(&a(&["o_mode"])), "top");
    }
}
