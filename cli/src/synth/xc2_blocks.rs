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

/// The blocks of `merkur_top` in a Yosys JSON netlist, most product terms
/// first; an empty list when the netlist has no such module.
pub fn block_costs(netlist: &Value) -> Vec<BlockCost> {
    let Some(top) = super::fpga::yosys_top(netlist) else {
        return Vec::new();
    };
    let empty = serde_json::Map::new();
    let cells = top["cells"].as_object().unwrap_or(&empty);
    let names = bit_names(top["netnames"].as_object().unwrap_or(&empty));
    let mut driver: HashMap<u64, &str> = HashMap::new();
    let mut readers: HashMap<u64, Vec<(&str, &str)>> = HashMap::new();
    for (cn, c) in cells {
        let dirs = c["port_directions"].as_object().unwrap_or(&empty);
        for (port, dir) in dirs {
            for bit in bits(&c["connections"][port]) {
                if dir == "output" {
                    driver.insert(bit, cn);
                } else {
                    readers.entry(bit).or_default().push((cn, port));
                }
            }
        }
    }
    let kind = |cn: &str| cells[cn]["type"].as_str().unwrap_or("");
    let mut sums: HashMap<String, (u64, u64)> = HashMap::new();
    for (cn, c) in cells {
        if kind(cn) != "MACROCELL_XOR" {
            continue;
        }
        let out = bits(&c["connections"]["OUT"]).next();
        let reg = out.and_then(|o| {
            readers.get(&o)?.iter().find_map(|(r, port)| {
                let is_ff = kind(r).starts_with("FD") || kind(r).starts_with("FT");
                (is_ff && matches!(*port, "D" | "T")).then_some(*r)
            })
        });
        let block = reg
            .and_then(|r| bits(&cells[r]["connections"]["Q"]).next())
            .and_then(|q| names.get(&q))
            .map(|aliases| block_of(aliases))
            .unwrap_or_else(|| "shared logic".to_string());
        let mut terms: HashSet<&str> = HashSet::new();
        for bit in bits(&c["connections"]["IN_PTC"]) {
            terms.extend(driver.get(&bit).filter(|d| kind(d) == "ANDTERM"));
        }
        for bit in bits(&c["connections"]["IN_ORTERM"]) {
            let Some(or) = driver.get(&bit).filter(|d| kind(d) == "ORTERM") else {
                continue;
            };
            for and in bits(&cells[*or]["connections"]["IN"]) {
                terms.extend(driver.get(&and).filter(|d| kind(d) == "ANDTERM"));
            }
        }
        let e = sums.entry(block).or_default();
        e.0 += 1;
        e.1 += terms.len() as u64;
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

/// The block of a register, from the names of its output: the name of the
/// register itself (rust-hdl calls a flip-flop's output `<name>_q`) if
/// there is one; else the longest instance path that is not an input port
/// (`i_*`) of a block that reads it, such as the top's capture register
/// `cap_pi.q` feeding `node.sbox.i_pi`; cut to two levels below the top.
fn block_of(aliases: &[String]) -> String {
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
    let reg = deepest(&mut base.iter().filter(|a| a.ends_with("_q")))
        .or_else(|| deepest(&mut base.iter().filter(|a| !is_input(a))))
        .or_else(|| deepest(&mut base.iter()))
        .unwrap_or_default();
    let path: Vec<&str> = reg.split('.').collect();
    let inst = &path[..path.len().saturating_sub(1)];
    if inst.is_empty() {
        "top".to_string()
    } else {
        inst[..inst.len().min(2)].join(".")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
