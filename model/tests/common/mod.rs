//! Helpers shared by the model's integration tests.
#![allow(dead_code)]

use merkur_model::config::{self, Config};
use merkur_model::ring::{self, CycleRecord};
use proptest::test_runner::{Config as PConfig, RngAlgorithm, TestRng, TestRunner};

/// Loads a scenario from text, panicking with the error's display.
pub fn load(text: &str) -> Config {
    config::load("test.toml", text).unwrap_or_else(|e| panic!("{e}\n--- scenario ---\n{text}"))
}

/// Nodes killed by the end of the run.
pub fn killed(cfg: &Config) -> Vec<usize> {
    cfg.killed()
}

/// What the ring delivers, per (node, slot): [`ring::delivered`].
pub fn delivered(cfg: &Config, r: &CycleRecord) -> Vec<((usize, usize), u16)> {
    ring::delivered(cfg, r)
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

/// Adds `backup = p` to the masters of a [`ring_text`] ring, per (node, p)
/// (protocol §8, the flying special master).
pub fn with_backups(mut text: String, prios: &[(usize, u8)]) -> String {
    for &(k, p) in prios {
        let at = format!("kind = \"master\"\naddress = {k}\n");
        let i = text
            .find(&at)
            .unwrap_or_else(|| panic!("node {k} is a master"));
        text.insert_str(i + at.len(), &format!("backup = {p}\n"));
    }
    text
}

/// The property tests' seed when MERKUR_SEED is not set.
pub const DEFAULT_SEED: u64 = 0x6d65_726b_7572;

/// The property tests' seed: MERKUR_SEED, or [`DEFAULT_SEED`]; the tests
/// print it on failure.
pub fn seed() -> u64 {
    std::env::var("MERKUR_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED)
}

/// A proptest runner of `cases` cases seeded from [`seed`], and the seed.
pub fn runner(cases: u32) -> (TestRunner, u64) {
    let s = seed();
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&s.to_le_bytes());
    let cfg = PConfig {
        cases,
        failure_persistence: None,
        ..PConfig::default()
    };
    (
        TestRunner::new_with_rng(cfg, TestRng::from_seed(RngAlgorithm::ChaCha, &bytes)),
        s,
    )
}

/// Kinds of a random ring: one special master at `sm`, the others drawn
/// from `pick` (0 sensor, 1 actuator, 2 master).
pub fn kinds(n: usize, sm: usize, pick: &[u8]) -> Vec<&'static str> {
    (0..n)
        .map(|i| {
            if i == sm {
                "special_master"
            } else {
                ["sensor", "actuator", "master"][pick[i % pick.len()] as usize % 3]
            }
        })
        .collect()
}
