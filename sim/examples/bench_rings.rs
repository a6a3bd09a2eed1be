//! Whole rings in Verilator, side by side in one run: tb-data/ring8.toml
//! run for 200 cycles, tb-data/ring32.toml and tb-data/ring100.toml, each
//! against the model's golden trace (a run that disagrees is an error, so
//! a figure is never the speed of a broken ring). Prints ticks, simulation
//! wall time (without the build), ticks/s, wall time per simulated cycle
//! (the bit times run over the period measured at the special master),
//! simulated time per wall second and the build time (0 when cached), as
//! the Markdown table of docs/benchmarks.md.
//!
//! Run: `cargo run --release -p merkur-sim --example bench_rings`
//! (`-- 3` runs each ring three times and keeps the fastest).

use merkur_model::{config, ring};
use merkur_sim::ring_sim::{self, Options};
use std::time::Duration;

fn main() {
    let repeat: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("repeat count"))
        .unwrap_or(1)
        .max(1);
    let root = merkur_sim::repo_root();
    println!(
        "| ring | ticks | period (bit times) | sim wall | ticks/s | wall per simulated cycle | simulated µs per wall s | build |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for (file, cycles) in [
        ("tb-data/ring8.toml", Some(200)),
        ("tb-data/ring32.toml", None),
        ("tb-data/ring100.toml", None),
    ] {
        let path = root.join(file);
        let text = std::fs::read_to_string(&path).expect("scenario");
        let mut cfg = config::load(file, &text).expect("a valid scenario");
        if let Some(c) = cycles {
            cfg.cycles = c;
        }
        let recs = ring::run(&cfg);
        let opts = Options {
            wave: None,
            seed: 1,
            progress: None,
            record: false,
            dump: false,
        };
        let mut best: Option<(Duration, ring_sim::Report)> = None;
        let mut build = Duration::ZERO;
        for _ in 0..repeat {
            let rep = ring_sim::run(&cfg, &recs, &opts).expect("the ring runs");
            assert!(
                rep.mismatches.is_empty(),
                "{file}: the RTL disagrees with the model: {:?}",
                rep.mismatches.first()
            );
            build += rep.build;
            if best.as_ref().map_or(true, |(w, _)| rep.wall < *w) {
                best = Some((rep.wall, rep));
            }
        }
        let (wall, rep) = best.unwrap();
        let s = wall.as_secs_f64();
        let bits = rep.ticks as f64 / f64::from(merkur_rtl::harness::ring_top::TICKS_PER_BIT);
        let sim_us = bits / cfg.line_rate_mbps;
        // Simulated cycles: the bit times run over the period the special
        // master measured.
        let cycles_run = bits / rep.period_bits;
        println!(
            "| {} ({} nodes) | {} | {:.1} | {:.2} s | {:.1} k | {:.1} ms | {:.1} | {:.1} s |",
            cfg.name,
            cfg.nodes.len(),
            rep.ticks,
            rep.period_bits,
            s,
            rep.ticks as f64 / s / 1e3,
            s * 1e3 / cycles_run,
            sim_us / s,
            build.as_secs_f64()
        );
    }
}
