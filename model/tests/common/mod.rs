//! Helpers shared by the model's integration tests.
#![allow(dead_code)]

use merkur_model::config::{self, Config, SlotKind};
use merkur_model::ring::{self, CycleRecord};
use merkur_model::scenario::Kind;

/// Loads a scenario from text, panicking with the error's display.
pub fn load(text: &str) -> Config {
    config::load("test.toml", text).unwrap_or_else(|e| panic!("{e}\n--- scenario ---\n{text}"))
}

/// Nodes killed by the end of the run.
pub fn killed(cfg: &Config) -> Vec<usize> {
    cfg.killed()
}

/// What the ring delivers, per (node, slot): masters' data memories and
/// actuators' outputs, leaving out dead nodes and slots written by them.
pub fn delivered(cfg: &Config, r: &CycleRecord) -> Vec<((usize, usize), u16)> {
    let dead = killed(cfg);
    let mut v = vec![];
    for (k, st) in r.nodes.iter().enumerate() {
        if dead.contains(&k) {
            continue;
        }
        match cfg.nodes[k].kind {
            Kind::Actuator => {
                let s = cfg.nodes[k].address;
                if !dead.contains(&cfg.writer[s]) {
                    v.push(((k, s), st.output));
                }
            }
            Kind::Master | Kind::SpecialMaster => {
                for (s, &x) in st.db.iter().enumerate() {
                    let w = cfg.writer[s];
                    let act_dead = matches!(cfg.slot_kind[s], SlotKind::Act { actuator } if dead.contains(&actuator));
                    if !dead.contains(&w) && !act_dead {
                        v.push(((k, s), x));
                    }
                }
            }
            Kind::Sensor => {}
        }
    }
    v
}

/// Runs a scenario and the same scenario without faults.
pub fn run_pair(cfg: &Config) -> (Vec<CycleRecord>, Vec<CycleRecord>) {
    let mut clean = cfg.clone();
    clean.faults.clear();
    (ring::run(cfg), ring::run(&clean))
}

/// First cycle from which the faulty run delivers exactly what the clean one
/// does, through the end (None: never).
pub fn exact_from(cfg: &Config, a: &[CycleRecord], b: &[CycleRecord]) -> Option<u32> {
    let mut from = None;
    for (x, y) in a.iter().zip(b) {
        if delivered(cfg, x) == delivered(cfg, y) {
            from.get_or_insert(x.cycle);
        } else {
            from = None;
        }
    }
    from
}

/// A ring description for tests: one node per entry, node i has address i;
/// masters write slot i; each actuator is served by the special master.
pub fn ring_text(kinds: &[&str], cycles: u32, extra: &str) -> String {
    let sm = kinds
        .iter()
        .position(|k| *k == "special_master")
        .expect("one SM");
    let acts: Vec<String> = kinds
        .iter()
        .enumerate()
        .filter(|(_, k)| **k == "actuator")
        .map(|(i, _)| i.to_string())
        .collect();
    let mut t = format!("seed = 1\ncycles = {cycles}\n");
    for (i, k) in kinds.iter().enumerate() {
        t += &format!("\n[[node]]\nkind = \"{k}\"\naddress = {i}\n");
        if *k == "master" || *k == "special_master" {
            t += &format!("slots = [{i}]\n");
        }
        if i == sm && !acts.is_empty() {
            t += &format!("serves = [{}]\n", acts.join(", "));
        }
    }
    for (i, k) in kinds.iter().enumerate() {
        if *k == "master" || *k == "special_master" {
            t += &format!(
                "\n[[host_write]]\ncycle = 1\nnode = {i}\nslot = {i}\ndata = {}\n",
                0x1000 + i
            );
        }
    }
    for a in &acts {
        t += &format!(
            "\n[[host_write]]\ncycle = 2\nnode = {sm}\nslot = {a}\ndata = {}\n",
            0x2000 + a.parse::<u32>().unwrap()
        );
    }
    t + extra
}
