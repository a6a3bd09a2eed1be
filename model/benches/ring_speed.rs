//! Speed of the reference model on the 100-node ring of tb-data/ring100.toml.
//! Run: `cargo bench -p merkur-model --bench ring_speed`
//! Reports communication cycles per second and slots per second (one slot =
//! one 16-bit slot word carried once around the whole ring, through every
//! node, with the per-cycle record the trace writer needs).

use merkur_model::{config, ring::Ring};
use std::time::Instant;

fn main() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../tb-data/ring100.toml");
    let text = std::fs::read_to_string(path).expect("tb-data/ring100.toml");
    let mut cfg = config::load("tb-data/ring100.toml", &text).expect("valid");
    let cycles: u32 = std::env::var("MERKUR_BENCH_CYCLES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(5000);
    cfg.cycles = cycles;
    let slots = cfg.slots as f64;
    let nodes = cfg.nodes.len();
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let mut ring = Ring::new(cfg.clone());
        let t = Instant::now();
        let mut sink = 0u64;
        for _ in 0..cycles {
            let r = ring.step();
            sink = sink.wrapping_add(r.nodes[0].db[1] as u64);
        }
        let dt = t.elapsed().as_secs_f64();
        std::hint::black_box(sink);
        best = best.min(dt);
    }
    let cps = cycles as f64 / best;
    println!(
        "ring100: {nodes} nodes, {} slots, {cycles} cycles in {best:.3} s (best of 3)",
        slots as usize
    );
    println!(
        "  {cps:.0} cycles/s, {:.2} M slots/s, {:.1} M node-slot steps/s",
        cps * slots / 1e6,
        cps * slots * nodes as f64 / 1e6
    );
    println!(
        "  = {:.1} simulated ms per wall second at 50 Mbit/s (cycle {:.1} us)",
        cps * cfg.cycle_us() / 1000.0,
        cfg.cycle_us()
    );
}
