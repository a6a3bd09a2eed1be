//! Token-bus scenarios (a `[token_bus]` table): `merkur check`, `trace`,
//! `verilog` and `sim` for the IEEE 802.4 Dual Channel Manager and its
//! Redundancy Management Module (docs/protocol.md Part II).

use crate::write_atomic;
use merkur_model::rmm;
use merkur_model::tbconfig::{self, TbConfig};
use merkur_model::tokenbus::{self, TbRun};
use merkur_rtl::emit::verilog::WAIVERS;
use merkur_rtl::tokenbus::dcm_station::dcm_verilog;
use merkur_sim::dcm_sim::{self, Options};
use std::path::Path;

/// Reads and validates a token-bus scenario.
pub fn read(path: &Path, text: &str) -> Result<TbConfig, String> {
    tbconfig::load(&path.display().to_string(), text).map_err(|e| e.to_string())
}

/// `merkur check`.
pub fn check(path: &Path, text: &str) -> Result<(), String> {
    let cfg = read(path, text)?;
    println!("scenario   {} ({}) — token bus", cfg.name, path.display());
    println!(
        "bus        {} stations on channels A and B, {} Mbit/s (octet time {:.2} us)",
        cfg.stations,
        cfg.rate_mbps,
        cfg.tick_us()
    );
    println!(
        "frame      token {} octets, data frame {} octets, status frame {} octets",
        tokenbus::frame(tokenbus::fc::TOKEN, 0, 0, &[]).len(),
        tokenbus::frame(tokenbus::fc::DATA, 0, 0, &vec![0; cfg.data_len]).len(),
        tokenbus::frame(tokenbus::fc::STATUS, 0, 0, &[0, 0]).len()
    );
    println!(
        "rmm        status frame every {} octets, status check every {}, channel good after {} clean octets",
        cfg.sf_period, cfg.check_period, cfg.good_limit
    );
    println!(
        "run        {} octet times = {:.1} us",
        cfg.ticks,
        cfg.ticks as f64 * cfg.tick_us()
    );
    for e in &cfg.events {
        println!("fault      octet {}: {} ({})", e.at, e.what, e.what.class());
    }
    println!("ok");
    Ok(())
}

/// `merkur trace`: the reference model's golden trace.
pub fn trace(path: &Path, text: &str, output: Option<&Path>) -> Result<(), String> {
    let cfg = read(path, text)?;
    let run = tokenbus::run(&cfg);
    let out = tokenbus::render(&cfg, text, &run);
    match output {
        None => print!("{out}"),
        Some(p) => {
            write_atomic(p, &out)?;
            eprintln!(
                "wrote {} ({} octet times, {} lines)",
                p.display(),
                cfg.ticks,
                out.lines().count()
            );
        }
    }
    Ok(())
}

/// `merkur verilog`: `merkur_dcm_station.v` (one station's DCM + RMM) and the waivers.
pub fn verilog(path: &Path, text: &str, dir: &Path) -> Result<(), String> {
    let cfg = read(path, text)?;
    let v = dcm_verilog();
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("error: --output {}: cannot create: {e}", dir.display()))?;
    let file = dir.join("merkur_dcm_station.v");
    write_atomic(&file, &v)?;
    write_atomic(&dir.join("waivers.vlt"), WAIVERS)?;
    eprintln!(
        "wrote {} (top merkur_dcm_station: one station's DCM + RMM, {} lines; the scenario's {} stations each use one, addresses and periods are ports) and {}",
        file.display(),
        v.lines().count(),
        cfg.stations,
        dir.join("waivers.vlt").display()
    );
    eprintln!(
        "lint: verilator --lint-only -Wall {}/waivers.vlt {} --top-module merkur_dcm_station",
        dir.display(),
        file.display()
    );
    Ok(())
}

/// The per-fault table of a run: class, switchover, frames lost.
pub fn fault_table(cfg: &TbConfig, r: &TbRun) -> String {
    let mut o = String::from(
        "fault                          class              switched  first..last switch         receptions lost\n",
    );
    for (k, e) in cfg.events.iter().enumerate() {
        if !e.what.is_fault() {
            continue;
        }
        let sw = match r.switch_latency(k) {
            None => format!("{:>8}  {:<25}", 0, "-"),
            Some((a, b, n)) => format!(
                "{n:>8}  {:<25}",
                format!(
                    "{a}..{b} oct = {:.1}..{:.1} us",
                    a as f64 * cfg.tick_us(),
                    b as f64 * cfg.tick_us()
                )
            ),
        };
        o += &format!(
            "{:<30} {:<18} {sw}  {:>5}\n",
            format!("{} @{}", e.what, e.at),
            e.what.class(),
            r.lost_by_fault[k]
        );
    }
    o
}

/// `merkur sim`: every station's `merkur_dcm_station` in Verilator against the model.
pub fn sim(path: &Path, text: &str, wave: Option<&Path>, show: usize) -> Result<bool, String> {
    let cfg = read(path, text)?;
    if let Some(w) = wave {
        crate::sim::check_wave_name(w)?;
    }
    let step = crate::progress::Step::start(format!(
        "building the Verilator model of merkur_dcm_station (cached by the hash of its Verilog; {} stations, each its own instance)",
        cfg.stations
    ));
    let t = std::time::Instant::now();
    dcm_sim::build_model(wave.is_some()).map_err(|e| format!("error: {e}"))?;
    step.done("ready");
    let build = t.elapsed();
    let opts = Options {
        wave: wave.map(Path::to_path_buf),
    };
    let r = dcm_sim::run(&cfg, &opts).map_err(|e| format!("error: {e}"))?;
    println!(
        "{}: {} stations, {} octet times ({:.1} us at {} Mbit/s), {} station-octets compared",
        cfg.name,
        cfg.stations,
        cfg.ticks,
        cfg.ticks as f64 * cfg.tick_us(),
        cfg.rate_mbps,
        r.compared
    );
    println!(
        "simulated in {:.2} s (build {:.1} s)",
        r.wall.as_secs_f64(),
        build.as_secs_f64()
    );
    println!("station  state          active  channel A  channel B  stale     events seen");
    for k in 0..cfg.stations {
        match r.rtl.outs[k].last().copied().flatten() {
            None => println!("{k:>7}  (powered off)"),
            Some(o) => {
                let names: Vec<&str> = (0..6)
                    .filter(|b| o.ev_seen >> b & 1 == 1)
                    .map(|b| rmm::ev::NAMES[b])
                    .collect();
                println!(
                    "{k:>7}  {:<13}  {:<6}  {:<9}  {:<9}  {:08x}  {}",
                    rmm::state::name(o.state),
                    if o.act { "B" } else { "A" },
                    if o.stat_a & 1 == 1 { "bad" } else { "good" },
                    if o.stat_b & 1 == 1 { "bad" } else { "good" },
                    o.stale,
                    names.join(",")
                );
            }
        }
    }
    println!(
        "data frames: {} sent, {} receptions expected, {} lost (model: {} lost)",
        r.rtl.frames_sent,
        r.rtl.receptions_expected,
        r.rtl.receptions_lost,
        r.model.receptions_lost
    );
    print!("{}", fault_table(&cfg, &r.rtl));
    for w in &r.waves {
        println!("waveform: {}", w.display());
    }
    // The RTL run written as a trace against the committed golden trace
    // beside the scenario, when there is one.
    let golden = path.with_extension("trace");
    let mut trace_ok = true;
    if let Ok(want) = std::fs::read_to_string(&golden) {
        let got = tokenbus::render(&cfg, text, &r.rtl);
        match merkur_model::trace::first_difference(&got, &want) {
            None => println!(
                "golden trace {}: the RTL's trace is identical",
                golden.display()
            ),
            Some(line) => {
                trace_ok = false;
                println!(
                    "golden trace {}: the RTL's trace differs at line {line} (regenerate it with `merkur trace` if the scenario changed)",
                    golden.display()
                );
            }
        }
    }
    match r.mismatches.first() {
        None if trace_ok => {
            println!("PASS: every station's RTL agrees with the model in every octet");
            Ok(true)
        }
        None => {
            println!(
                "FAIL: the RTL agrees with the model run, but not with the committed golden trace"
            );
            Ok(false)
        }
        Some(m) => {
            println!("FAIL: {} mismatches; first: {m}", r.mismatches.len());
            for m in r.mismatches.iter().skip(1).take(show.saturating_sub(1)) {
                println!("      {m}");
            }
            Ok(false)
        }
    }
}
