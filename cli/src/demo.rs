//! `merkur demo`: the reference model on a built-in 8-node ring with one line
//! break, explained cycle by cycle and compared with the same ring without
//! the fault; then the same ring as RTL in Verilator (every node on its own
//! clock), compared word for word with the model, with a waveform.

use merkur_model::config::{self, Config};
use merkur_model::ring::{self, CycleRecord, EventKind};

/// The embedded scenario (also in tb-data/, where its golden trace lives).
pub const SCENARIO: &str = include_str!("../../tb-data/demo_8_break.toml");

fn reason_name(r: u8) -> String {
    use merkur_model::ring::reason::*;
    match r {
        IRQ1 => "IRQ1".into(),
        IRQ2 => "IRQ2".into(),
        FAILSAFE => "FAILSAFE".into(),
        RECONFIG_N => "RECONFIG(N)".into(),
        RECONFIG_WU => "RECONFIG(WU)".into(),
        RECONFIG_WD => "RECONFIG(WD)".into(),
        r => format!("reason {r}"),
    }
}

pub fn run(wave: Option<&std::path::Path>) -> Result<(), String> {
    let cfg = config::load("tb-data/demo_8_break.toml", SCENARIO).map_err(|e| e.to_string())?;
    let mut clean = cfg.clone();
    clean.faults.clear();
    let faulty = ring::run(&cfg);
    let reference = ring::run(&clean);
    println!(
        "merkur demo: {} nodes, {} slots, frame {} bit times, cycle {:.1} us at {} Mbit/s",
        cfg.nodes.len(),
        cfg.slots,
        cfg.frame_bits(),
        cfg.cycle_us(),
        cfg.line_rate_mbps
    );
    for (c, f) in &cfg.faults {
        println!("fault: cycle {c}: {f}");
    }
    println!("(reference model; each line compares with the same ring without the fault)\n");
    let mut first_exact = None;
    for (r, g) in faulty.iter().zip(&reference) {
        let a = ring::delivered(&cfg, r);
        let b = ring::delivered(&cfg, g);
        let diff = a.iter().zip(&b).filter(|(x, y)| x != y).count();
        let modes: String = r
            .nodes
            .iter()
            .map(|n| format!("{:>2}", n.mode.name()))
            .collect::<Vec<_>>()
            .join(" ");
        let path: Vec<String> = r.path.iter().map(|k| k.to_string()).collect();
        println!(
            "cycle {:>2}  path {:<16} switchboxes [{}]  {}",
            r.cycle,
            path.join(">"),
            modes,
            if diff == 0 {
                "memories = fault-free".to_string()
            } else {
                format!("{diff} values still old")
            }
        );
        for e in &r.events {
            let what = match &e.kind {
                EventKind::Mode { from, to } => format!(
                    "switchbox {} -> {} (from next cycle)",
                    from.name(),
                    to.name()
                ),
                EventKind::AlarmTx { reason, repeat } => format!(
                    "sends alarm {} in its slot{}",
                    reason_name(*reason),
                    if *repeat {
                        " again (not read back)"
                    } else {
                        ""
                    }
                ),
                EventKind::Irq { slot, reason } => {
                    format!(
                        "raises host interrupt: {} from slot {slot}",
                        reason_name(*reason)
                    )
                }
                EventKind::Failsafe(c) => format!("enters FAILSAFE ({c})"),
                EventKind::FailsafeExit => "leaves FAILSAFE (the ring is whole again)".to_string(),
                EventKind::FsClear => "its host allows the ring out of failsafe".to_string(),
                EventKind::AliveLost { slot } => format!("alive lost in slot {slot}"),
                EventKind::AliveRestored { slot } => format!("alive back in slot {slot}"),
                EventKind::SecFail => "secondary test frame did not return".to_string(),
                EventKind::Takeover { prio } => {
                    format!("takes over as the clock base (backup priority {prio})")
                }
                EventKind::BadWords { port } => format!(
                    "{} bad words in a row on {}: channel failure",
                    merkur_model::ring::BAD_WORDS,
                    port.name()
                ),
                EventKind::Rtx { sent, requested } => format!(
                    "retransmission packet for {sent} of {requested} damaged critical slots"
                ),
            };
            println!("            node {} at {}: {what}", e.node, e.at);
        }
        if diff == 0 && first_exact.is_none() && r.cycle >= cfg.faults[0].0 {
            first_exact = Some(r.cycle);
        } else if diff != 0 {
            first_exact = None;
        }
    }
    let last = faulty.last().expect("cycles >= 1");
    let fs = last.nodes.iter().filter(|n| n.failsafe).count();
    println!();
    match first_exact {
        Some(c) => println!(
            "result: after the break every memory equals the fault-free ring's from cycle {c} on; {fs} nodes in failsafe."
        ),
        None => println!("result: memories differ from the fault-free ring at the end; {fs} nodes in failsafe."),
    }
    match wave {
        Some(w) => rtl(&cfg, &faulty, w),
        None => Ok(()),
    }
}

/// The same scenario as RTL in Verilator, against the model's records.
fn rtl(cfg: &Config, recs: &[CycleRecord], wave: &std::path::Path) -> Result<(), String> {
    use merkur_sim::ring_sim::{self, Options};
    crate::sim::check_wave_name(wave)?;
    if let Some(dir) = wave.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| {
            format!(
                "error: --wave {}: cannot create {}: {e}",
                wave.display(),
                dir.display()
            )
        })?;
    }
    let ppm = cfg.nodes.iter().map(|n| n.ppm);
    println!(
        "\nthe same ring as RTL (Verilator; every node on its own clock, {:+.0} .. {:+.0} ppm):",
        ppm.clone().fold(f64::INFINITY, f64::min),
        ppm.fold(f64::NEG_INFINITY, f64::max)
    );
    crate::sim::build_ring(cfg, true)?;
    let bar = std::sync::Arc::new(crate::progress::Bar::new(u64::from(cfg.cycles), "cycles"));
    let opts = Options {
        wave: Some(wave.to_path_buf()),
        seed: 1,
        progress: Some(crate::sim::cycle_progress(&bar)),
        record: false,
        dump: false,
    };
    let run = ring_sim::run(cfg, recs, &opts);
    bar.finish();
    let rep = run.map_err(|e| format!("error: RTL run: {e}"))?;
    println!(
        "RTL: {} words on {} fibres over {} cycles compared with the model; cycle time measured {:.1} bit times = {:.2} us at {} Mbit/s",
        rep.words,
        2 * cfg.nodes.len(),
        rep.cycles,
        rep.period_bits,
        rep.period_bits / cfg.line_rate_mbps,
        cfg.line_rate_mbps
    );
    crate::sim::write_gtkw(cfg, wave)?;
    match rep.mismatches.first() {
        None => {
            println!("RTL agrees with the model: every word, header and node state.");
            Ok(())
        }
        Some(m) => Err(format!(
            "RTL differs from the model: {} mismatches; first: {m}",
            rep.mismatches.len()
        )),
    }
}
