//! Fuzzed scenario files (issue 26, item 3): the ring and token-bus readers
//! get valid tb-data files mutated — truncated, with a range deleted, a
//! line repeated, a number or a key's whole value replaced by a huge,
//! negative, fractional or malformed one, random bytes inserted, two files spliced — and random
//! bytes. Every input must either be refused with an error that says
//! `error:` and names the file (with `file:line:column` when the problem
//! has a place in the text) or be accepted and then run through the model.
//! Never a panic. Accepted runs are bounded: a mutation may legally ask for
//! a million cycles, so the model runs only inputs of at most
//! [`RUN_BUDGET`] node-cycles (every tb-data scenario is far below it).
//!
//! Seeded (MERKUR_SEED, printed on failure); MERKUR_FUZZ_CASES sets the
//! number of inputs (default 20,000 in CI, a few seconds; docs/benchmarks.md has a
//! long run).

use merkur_model::{config, ring, tbconfig, tokenbus};
use proptest::prelude::*;
use proptest::test_runner::{Config as PConfig, RngAlgorithm, TestRng, TestRunner};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};

/// Inputs refused, accepted and run, accepted and only read.
static REFUSED: AtomicU64 = AtomicU64::new(0);
static RAN: AtomicU64 = AtomicU64::new(0);
static READ: AtomicU64 = AtomicU64::new(0);

fn ran(budget_ok: bool) {
    let c = if budget_ok { &RAN } else { &READ };
    c.fetch_add(1, Ordering::Relaxed);
}

const DEFAULT_SEED: u64 = 0x6675_7a7a;
/// Node-cycles above which an accepted input is not run (only read).
const RUN_BUDGET: u64 = 4_000;

fn tb_data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tb-data")
}

/// Every scenario of tb-data/ (valid ring and token-bus files) and of
/// tb-data/bad/ (invalid on purpose): the material the mutations start from.
fn corpus() -> Vec<String> {
    let mut out = vec![];
    for dir in [tb_data(), tb_data().join("bad")] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        out.extend(files.iter().map(|p| std::fs::read_to_string(p).unwrap()));
    }
    assert!(out.len() >= 30, "corpus of {} files", out.len());
    out
}

/// One mutation of a text.
#[derive(Debug, Clone)]
enum Mutation {
    Truncate(usize),
    Delete(usize, usize),
    RepeatLine(usize),
    Number(usize, String),
    Value(usize, String),
    Insert(usize, Vec<u8>),
    Splice(usize, usize, usize),
    Bytes(Vec<u8>),
}

fn mutation(files: usize) -> impl Strategy<Value = Mutation> {
    let number = prop_oneof![
        Just("18446744073709551616".to_string()),
        Just("-1".to_string()),
        Just("0".to_string()),
        Just("4294967296".to_string()),
        Just("1e309".to_string()),
        Just("nan".to_string()),
        Just("0.5".to_string()),
        Just("0x".to_string()),
        Just("[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]".to_string()),
        any::<i64>().prop_map(|v| v.to_string()),
        any::<u16>().prop_map(|v| v.to_string()),
    ];
    prop_oneof![
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), 0usize..200).prop_map(|(a, n)| Mutation::Delete(a, n)),
        any::<usize>().prop_map(Mutation::RepeatLine),
        (any::<usize>(), number.clone()).prop_map(|(a, n)| Mutation::Number(a, n)),
        (any::<usize>(), number).prop_map(|(a, n)| Mutation::Value(a, n)),
        (
            any::<usize>(),
            proptest::collection::vec(any::<u8>(), 1..16)
        )
            .prop_map(|(a, b)| Mutation::Insert(a, b)),
        (0..files, any::<usize>(), any::<usize>()).prop_map(|(f, a, b)| Mutation::Splice(f, a, b)),
        proptest::collection::vec(any::<u8>(), 0..400).prop_map(Mutation::Bytes),
    ]
}

fn apply(text: &str, m: &Mutation, corpus: &[String]) -> String {
    let b = text.as_bytes();
    let at = |x: usize| if b.is_empty() { 0 } else { x % (b.len() + 1) };
    let bytes: Vec<u8> = match m {
        Mutation::Truncate(x) => b[..at(*x)].to_vec(),
        Mutation::Delete(x, n) => {
            let s = at(*x);
            let e = (s + n).min(b.len());
            [&b[..s], &b[e..]].concat()
        }
        Mutation::RepeatLine(x) => {
            let lines: Vec<&str> = text.lines().collect();
            if lines.is_empty() {
                return text.to_string();
            }
            let k = x % lines.len();
            let mut out: Vec<&str> = lines.clone();
            out.insert(k, lines[k]);
            return out.join("\n");
        }
        Mutation::Number(x, n) => {
            // The number nearest after the position.
            let s = at(*x);
            let Some(off) = b[s..].iter().position(u8::is_ascii_digit) else {
                return text.to_string();
            };
            let start = s + off;
            let len = b[start..]
                .iter()
                .take_while(|c| c.is_ascii_alphanumeric() || **c == b'.')
                .count();
            [&b[..start], n.as_bytes(), &b[start + len..]].concat()
        }
        Mutation::Value(x, v) => {
            // The value of the k-th `key = value` line.
            let lines: Vec<&str> = text.lines().collect();
            let keyed: Vec<usize> = (0..lines.len())
                .filter(|&i| lines[i].contains('='))
                .collect();
            if keyed.is_empty() {
                return text.to_string();
            }
            let k = keyed[x % keyed.len()];
            let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
            let key = lines[k].split('=').next().unwrap_or("");
            out[k] = format!("{key}= {v}");
            return out.join("\n");
        }
        Mutation::Insert(x, ins) => {
            let s = at(*x);
            [&b[..s], ins, &b[s..]].concat()
        }
        Mutation::Splice(f, x, y) => {
            let o = corpus[*f].as_bytes();
            let y = if o.is_empty() { 0 } else { y % (o.len() + 1) };
            [&b[..at(*x)], &o[y..]].concat()
        }
        Mutation::Bytes(r) => r.clone(),
    };
    String::from_utf8_lossy(&bytes).into_owned()
}

/// Reads (and, within the budget, runs) one input; a description of what
/// went wrong, or `None`.
fn check(text: &str) -> Option<String> {
    const FILE: &str = "fuzz.toml";
    let r = catch_unwind(AssertUnwindSafe(|| {
        if tbconfig::is_token_bus(text) {
            match tbconfig::load(FILE, text) {
                Ok(cfg) => {
                    let ok = (cfg.stations as u64).saturating_mul(cfg.ticks / 256) <= RUN_BUDGET;
                    if ok {
                        let _ = tokenbus::run(&cfg);
                    }
                    ran(ok);
                    Ok(())
                }
                Err(e) => Err(e.to_string()),
            }
        } else {
            match config::load(FILE, text) {
                Ok(cfg) => {
                    let ok =
                        (cfg.nodes.len() as u64).saturating_mul(cfg.cycles as u64) <= RUN_BUDGET;
                    if ok {
                        let _ = ring::run(&cfg);
                    }
                    ran(ok);
                    Ok(())
                }
                Err(e) => Err(e.to_string()),
            }
        }
    }));
    match r {
        Err(p) => Some(format!(
            "panic: {}",
            p.downcast_ref::<String>()
                .cloned()
                .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
        Ok(Ok(())) => None,
        Ok(Err(msg)) if !msg.starts_with("error: ") || !msg.contains(FILE) => Some(format!(
            "error message without `error:` and the file: {msg}"
        )),
        Ok(Err(_)) => {
            REFUSED.fetch_add(1, Ordering::Relaxed);
            None
        }
    }
}

#[test]
fn mutated_scenarios_are_refused_clearly_or_run() {
    let seed: u64 = std::env::var("MERKUR_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED);
    let cases: u32 = std::env::var("MERKUR_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000);
    let corpus = corpus();
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(
        PConfig {
            cases,
            failure_persistence: None,
            ..PConfig::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &bytes),
    );
    // Panics are caught per input; keep their default report quiet.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let n = corpus.len();
    let strategy = (0..n, proptest::collection::vec(mutation(n), 1..4));
    let result = runner.run(&strategy, |(f, ms)| {
        let mut text = corpus[f].clone();
        for m in &ms {
            text = apply(&text, m, &corpus);
        }
        if let Some(what) = check(&text) {
            return Err(TestCaseError::fail(format!(
                "{what}\n--- input ---\n{text}"
            )));
        }
        Ok(())
    });
    std::panic::set_hook(hook);
    if let Err(e) = result {
        panic!("fuzz (MERKUR_SEED={seed}, {cases} inputs): {e}");
    }
    let (r, a, o) = (
        REFUSED.load(Ordering::Relaxed),
        RAN.load(Ordering::Relaxed),
        READ.load(Ordering::Relaxed),
    );
    println!("fuzz: {cases} inputs (seed {seed}): {r} refused, {a} accepted and run, {o} accepted and read only");
    // The mutations must reach both sides of the reader.
    assert!(r > 0 && a > 0, "refused {r}, run {a}");
}
