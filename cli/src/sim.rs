//! `merkur verilog` and `merkur sim`: the scenario's ring as Verilog, and its
//! Verilator run compared with the reference model.

use crate::{progress, read_scenario, write_atomic};
use merkur_model::config::Config;
use merkur_model::ring;
use merkur_rtl::emit::verilog::WAIVERS;
use merkur_sim::ring_sim::{self, Options};
use std::path::Path;
use std::time::{Duration, Instant};

/// Writes `<name>_ring.v` and `waivers.vlt` into `dir`.
pub fn verilog(path: &Path, dir: &Path) -> Result<(), String> {
    let (_, cfg) = read_scenario(path)?;
    // What `merkur sim` runs: backups as clock-base nodes, power-on
    // resets where the scenario restarts nodes.
    let kinds = ring_sim::rtl_kinds(&cfg);
    let v = ring_sim::ring_verilog_of(&cfg);
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("error: --output {}: cannot create: {e}", dir.display()))?;
    let file = dir.join(format!("{}_ring.v", cfg.name));
    write_atomic(&file, &v)?;
    write_atomic(&dir.join("waivers.vlt"), WAIVERS)?;
    eprintln!(
        "wrote {} (top merkur_ring, {} nodes, {} fibres, {} lines) and {}",
        file.display(),
        kinds.len(),
        2 * kinds.len(),
        v.lines().count(),
        dir.join("waivers.vlt").display()
    );
    eprintln!(
        "lint: verilator --lint-only -Wall {}/waivers.vlt {} --top-module merkur_ring",
        dir.display(),
        file.display()
    );
    Ok(())
}

/// Builds (or finds in the cache) the ring's Verilator model, shown as a
/// step; its wall time.
pub(crate) fn build_ring(cfg: &Config, wave: bool) -> Result<Duration, String> {
    let step = progress::Step::start(format!(
        "building the Verilator model of {} ({} nodes; cached by the hash of its Verilog)",
        cfg.name,
        cfg.nodes.len()
    ));
    let t = Instant::now();
    ring_sim::build_model(cfg, wave).map_err(|e| format!("error: {e}"))?;
    step.done("ready");
    Ok(t.elapsed())
}

/// A run's cycle count onto `bar`.
pub(crate) fn cycle_progress(bar: &std::sync::Arc<progress::Bar>) -> ring_sim::Progress {
    let bar = bar.clone();
    ring_sim::Progress(std::sync::Arc::new(move |c, _| bar.set(u64::from(c), "")))
}

/// A `--wave` file must be named `*.fst` (that is what is written).
pub(crate) fn check_wave_name(w: &Path) -> Result<(), String> {
    if w.extension().map_or(true, |e| e != "fst") {
        return Err(format!(
            "error: --wave {}: the waveform is written as FST; name the file *.fst",
            w.display()
        ));
    }
    Ok(())
}

/// Writes the GTKWave save file beside the waveform `w` and says where both are.
pub(crate) fn write_gtkw(cfg: &merkur_model::config::Config, w: &Path) -> Result<(), String> {
    let g = w.with_extension("gtkw");
    write_atomic(&g, &ring_sim::gtkw(cfg, w))?;
    println!("waveform: {} (gtkwave {})", w.display(), g.display());
    Ok(())
}

/// Runs the ring in Verilator; `Ok(false)` when it differs from the model.
pub fn sim(
    path: &Path,
    wave: Option<&Path>,
    seed: u64,
    show: usize,
    dump: bool,
) -> Result<bool, String> {
    let (_, cfg) = read_scenario(path)?;
    if let Some(why) = ring_sim::unsupported(&cfg) {
        return Err(format!(
            "error: {}: not simulated in RTL: {why}",
            path.display()
        ));
    }
    if let Some(w) = wave {
        check_wave_name(w)?;
    }
    let recs = ring::run(&cfg);
    let build = build_ring(&cfg, wave.is_some())?;
    let bar = std::sync::Arc::new(progress::Bar::new(u64::from(cfg.cycles), "cycles"));
    let opts = Options {
        wave: wave.map(Path::to_path_buf),
        seed,
        progress: (!dump).then(|| cycle_progress(&bar)),
        record: false,
        dump,
    };
    let run = ring_sim::run(&cfg, &recs, &opts);
    bar.finish();
    let rep = run.map_err(|e| format!("error: {e}"))?;
    println!(
        "{}: {} cycles, {} words compared, period {:.1} bit times ({:.2} us at {} Mbit/s)",
        cfg.name,
        rep.cycles,
        rep.words,
        rep.period_bits,
        rep.period_bits / cfg.line_rate_mbps,
        cfg.line_rate_mbps
    );
    println!(
        "simulated {} ticks ({} bit times) in {:.2} s (build {:.1} s)",
        rep.ticks,
        rep.ticks / u64::from(merkur_rtl::harness::ring_top::TICKS_PER_BIT),
        rep.wall.as_secs_f64(),
        build.as_secs_f64()
    );
    let d = &rep.fwd_delay_bits;
    if !d.is_empty() {
        let min = d.iter().cloned().fold(f64::INFINITY, f64::min);
        let max = d.iter().cloned().fold(0.0, f64::max);
        let mean = d.iter().sum::<f64>() / d.len() as f64;
        println!(
            "forwarding delay (PI fibre to PO fibre, {} nodes): min {min:.1} / mean {mean:.2} / max {max:.1} bit times = {:.0} ns mean at {} Mbit/s",
            d.len(),
            mean * 1000.0 / cfg.line_rate_mbps,
            cfg.line_rate_mbps
        );
    }
    println!("node  kind            mode  failsafe  perr  irqs  mismatches");
    for r in &rep.rows {
        println!(
            "{:>4}  {:<14}  {:<4}  {:<8}  {:>4}  {:>4}  {:>10}",
            r.node, r.kind, r.mode, r.failsafe, r.perr, r.irqs, r.mismatches
        );
    }
    print_shapes(&rep.shapes);
    if let Some(w) = wave {
        write_gtkw(&cfg, w)?;
    }
    match rep.mismatches.first() {
        None => {
            println!("PASS: the RTL ring agrees with the model's golden trace");
            Ok(true)
        }
        Some(m) => {
            println!("FAIL: {} mismatches; first: {m}", rep.mismatches.len());
            for m in rep.mismatches.iter().skip(1).take(show.saturating_sub(1)) {
                println!("      {m}");
            }
            Ok(false)
        }
    }
}

/// Prints the ring's shape as each master reconstructs it from the RECONFIG
/// alarms in its queue (protocol §11), masters that agree on one line.
fn print_shapes(shapes: &[(usize, ring_sim::Shape)]) {
    let mut groups: Vec<(&ring_sim::Shape, Vec<usize>)> = vec![];
    for (k, shape) in shapes {
        match groups.iter_mut().find(|g| g.0 == shape) {
            Some(g) => g.1.push(*k),
            None => groups.push((shape, vec![*k])),
        }
    }
    for (shape, ks) in groups {
        let who: Vec<String> = ks.iter().map(usize::to_string).collect();
        let what = if shape.is_empty() {
            "every node in N".to_string()
        } else {
            let w: Vec<String> = shape
                .iter()
                .map(|(node, m)| format!("node {node} {}", m.name()))
                .collect();
            format!("wrapped: {}", w.join(", "))
        };
        println!(
            "ring shape from the alarm queue{} of node{} {}: {what}",
            if ks.len() > 1 { "s" } else { "" },
            if ks.len() > 1 { "s" } else { "" },
            who.join(", ")
        );
    }
}
