//! Switchover latency and frames lost per fault class of the IEEE 802.4
//! DCM + RMM, measured on the RTL (every station's `merkur_dcm_station` in
//! Verilator, closed loop with the model's token bus) for every token-bus
//! scenario in tb-data/, at 5 and 10 Mbit/s. Prints Markdown tables for
//! docs/benchmarks.md; exits 1 if any run disagrees with the model.
//!
//! Run: `cargo run --release -p merkur-sim --example bench_dcm`
//!
//! The token bus is timed in octets (docs/protocol.md §16): the latency in
//! octets is the same at both rates, µs = octets × 8 / rate.

use merkur_model::rmm::state;
use merkur_model::tbconfig::{ChanFault, TbEvent};
use merkur_sim::dcm_sim::{self, Options};
use std::collections::BTreeMap;

fn main() {
    println!("| scenario | fault | class | stations switched | first..last switch, octets | µs at 5 Mbit/s | µs at 10 Mbit/s | receptions lost (RTL = model) |");
    println!("|---|---|---|---|---|---|---|---|");
    let mut by_class: BTreeMap<String, (u64, u64, u64)> = BTreeMap::new();
    let mut octets = 0u64;
    let mut wall = 0.0;
    let mut bad = false;
    for s in dcm_sim::scenarios().expect("tb-data") {
        let (cfg, name) = (&s.cfg, &s.cfg.name);
        let r = dcm_sim::run(cfg, &Options::default()).expect("runs");
        octets += r.compared;
        wall += r.wall.as_secs_f64();
        if let Some(m) = r.mismatches.first() {
            eprintln!("{name}: RTL disagrees with the model: {m}");
            bad = true;
        }
        assert_eq!(r.rtl.lost_by_fault, r.model.lost_by_fault);
        // Which channels carry a lasting fault (short, open, drop) so far.
        let mut down = [false; 2];
        for (k, e) in cfg.events.iter().enumerate() {
            if !e.what.is_fault() {
                continue;
            }
            if let TbEvent::Chan(c, f) = e.what {
                match f {
                    ChanFault::Repair => down[c as usize] = false,
                    ChanFault::Noise(_) => {}
                    _ => down[c as usize] = true,
                }
            }
            // The class with its setting: dual mode on everywhere (every
            // powered station in Auto_Normal) or not, both channels down.
            let states: Vec<u8> = r
                .rtl
                .outs
                .iter()
                .filter_map(|o| o[e.at as usize])
                .map(|o| o.state)
                .collect();
            let setting = if down[0] && down[1] {
                "both channels down"
            } else if states.iter().all(|&s| s == state::AUTO_NORMAL) {
                "dual mode on"
            } else {
                "dual mode off somewhere"
            };
            let lost = r.rtl.lost_by_fault[k];
            let (sw, lat, us5, us10) = match r.rtl.switch_latency(k) {
                None => ("0".to_string(), "-".to_string(), "-".into(), "-".into()),
                Some((a, b, n)) => (
                    n.to_string(),
                    format!("{a}..{b}"),
                    format!("{:.1}..{:.1}", a as f64 * 1.6, b as f64 * 1.6),
                    format!("{:.1}..{:.1}", a as f64 * 0.8, b as f64 * 0.8),
                ),
            };
            println!(
                "| {name} | {} @{} | {} | {sw} | {lat} | {us5} | {us10} | {lost} |",
                e.what,
                e.at,
                e.what.class()
            );
            let c = by_class
                .entry(format!("{}, {setting}", e.what.class()))
                .or_default();
            c.0 += lost;
            c.1 += 1;
            c.2 = c.2.max(lost);
        }
    }
    println!();
    println!(
        "| fault class, setting at the fault | faults | receptions lost, total | worst fault |"
    );
    println!("|---|---|---|---|");
    for (c, (lost, n, worst)) in &by_class {
        println!("| {c} | {n} | {lost} | {worst} |");
    }
    println!();
    println!(
        "RTL: {octets} station-octets in {wall:.2} s = {:.2} M station-octets/s",
        octets as f64 / wall / 1e6
    );
    if bad {
        std::process::exit(1);
    }
}
