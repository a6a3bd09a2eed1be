//! The golden trace format (docs/traces.md): one plain-text file per
//! scenario, one block per cycle, diff-able line by line.

use crate::config::Config;
use crate::ring::{self, At, Carry, CycleRecord, EventKind, HeaderRx, Slot};
use crate::scenario::Kind;
use sha2::{Digest, Sha256};
use std::fmt::Write;

/// Version of the trace format; bump on any change of the text layout.
pub const FORMAT: u32 = 1;

/// The first line (1-based) where two traces differ, `None` when equal.
pub fn first_difference(got: &str, want: &str) -> Option<usize> {
    if got == want {
        return None;
    }
    let (g, w) = (got.lines().count(), want.lines().count());
    Some(
        got.lines()
            .zip(want.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(g.min(w))
            + 1,
    )
}

/// Hex SHA-256 of a scenario file's bytes.
pub fn scenario_hash(text: &str) -> String {
    let d = Sha256::digest(text.as_bytes());
    d.iter().map(|b| format!("{b:02x}")).collect()
}

/// Appends the trace token of a slot word (docs/traces.md): `1234+`,
/// `!4000-`, `…r3`, `x`, `v`, `.`.
pub fn word_token(out: &mut String, w: &Slot) {
    match w {
        Slot::Data(d) => {
            if d.alarm {
                out.push('!');
            }
            let _ = write!(out, "{:04x}{}", d.data, if d.alive { '+' } else { '-' });
            if d.reason != 0 {
                let _ = write!(out, "r{:x}", d.reason);
            }
        }
        Slot::Void => out.push('v'),
        Slot::Bad(_) => out.push('x'),
        Slot::Marked(_) => out.push('m'),
        Slot::Missing => out.push('.'),
    }
}

fn event_text(k: &EventKind) -> String {
    match k {
        EventKind::Mode { from, to } => format!("mode {}>{}", from.name(), to.name()),
        EventKind::Failsafe(c) => format!("failsafe {c}"),
        EventKind::FailsafeExit => "failsafe-exit".to_string(),
        EventKind::FsClear => "fs-clear".to_string(),
        EventKind::AlarmTx { reason, repeat } => {
            format!("alarm-tx r{reason}{}", if *repeat { " repeat" } else { "" })
        }
        EventKind::Irq { slot, reason } => format!("irq s{slot} r{reason}"),
        EventKind::AliveLost { slot } => format!("alive-lost s{slot}"),
        EventKind::AliveRestored { slot } => format!("alive-ok s{slot}"),
        EventKind::SecFail => "sec-fail".to_string(),
        EventKind::Takeover { prio } => format!("takeover p{prio}"),
        EventKind::BadWords { port } => format!("bad-words {}", port.name().to_lowercase()),
        EventKind::Rtx { sent, requested } => format!("rtx {sent}/{requested}"),
    }
}

/// Renders the trace of a run. `source` is the scenario file's text (hashed
/// into the header).
pub fn render(cfg: &Config, source: &str, records: &[CycleRecord]) -> String {
    let n = cfg.nodes.len();
    let mut o = String::new();
    let _ = writeln!(o, "# merkur golden trace");
    let _ = writeln!(o, "# format {FORMAT}");
    let _ = writeln!(o, "# generator merkur-model {}", env!("CARGO_PKG_VERSION"));
    let _ = writeln!(o, "# scenario {}", cfg.name);
    let _ = writeln!(o, "# scenario-sha256 {}", scenario_hash(source));
    let _ = writeln!(o, "# seed {}", cfg.seed);
    let _ = writeln!(
        o,
        "# nodes {n} slots {} ext {} period {} frame {} sm {} cycles {}",
        cfg.slots,
        cfg.ext as u8,
        cfg.period,
        cfg.frame_bits(),
        cfg.sm,
        cfg.cycles
    );
    let kinds: Vec<&str> = cfg.nodes.iter().map(|x| x.kind.name()).collect();
    let _ = writeln!(o, "# kinds {}", kinds.join(","));
    let writers: Vec<String> = cfg.writer.iter().map(|w| w.to_string()).collect();
    let _ = writeln!(o, "# writers {}", writers.join(","));
    let critical: Vec<String> = cfg.critical_slots().iter().map(|s| s.to_string()).collect();
    if !critical.is_empty() {
        let _ = writeln!(o, "# critical {}", critical.join(","));
    }
    for (a, b, d) in ring::windows(cfg, records) {
        let _ = writeln!(o, "window {a} {b} {d}");
    }
    for r in records {
        let path: Vec<String> = r.path.iter().map(|k| k.to_string()).collect();
        let _ = writeln!(o, "cycle {} path {}", r.cycle, path.join(","));
        let src: Vec<String> = r.produced.iter().map(|v| format!("{v:04x}")).collect();
        let _ = writeln!(o, " src {}", src.join(" "));
        // Fibre index: P0..P(n-1), then S0..S(n-1).
        let fibre_name = |i: usize| crate::config::Fibre::from_index(i, n).to_string();
        for (i, f) in r.fibres.iter().enumerate() {
            let _ = write!(o, " {} ", fibre_name(i));
            match f {
                Carry::Silent => o.push('-'),
                Carry::Idle => o.push('I'),
                Carry::Sec { ok } => o.push_str(if *ok { "SEC" } else { "SEC!" }),
                Carry::Tst { ack } => {
                    let _ = write!(o, "TST{}", *ack as u8);
                }
                Carry::Data(fr) => {
                    match fr.hdr {
                        HeaderRx::Ok(h) => {
                            let _ = write!(
                                o,
                                "D fs{} rwc{} rwp{} cyc{} hop{}{} |",
                                h.fs as u8,
                                h.rwc as u8,
                                h.rwp as u8,
                                h.cyc,
                                h.hop,
                                if h.clr { " clr1" } else { "" }
                            );
                        }
                        HeaderRx::Bad => o.push_str("D hdr-bad |"),
                        HeaderRx::NoCs => o.push_str("D no-cs |"),
                    }
                    for w in &fr.words {
                        o.push(' ');
                        word_token(&mut o, w);
                    }
                }
            }
            o.push('\n');
        }
        if !r.sec_with_data.is_empty() {
            // The SEC that went ahead of a (wrapped) DATA frame on a fibre.
            o.push_str(" sec-ahead");
            for &(i, ok) in &r.sec_with_data {
                let _ = write!(o, " {}{}", fibre_name(i), if ok { "" } else { "!" });
            }
            o.push('\n');
        }
        if let Some(x) = &r.rtx {
            // The retransmission packet (§8): its requests, those that did
            // not fit, which came back good, and the fibres it travelled.
            o.push_str(" rtx");
            for s in &x.slots {
                let _ = write!(o, " s{s}");
            }
            let back: String = x.back.iter().map(|&b| if b { '1' } else { '0' }).collect();
            let _ = write!(o, " left {} back {back} via", x.left);
            for &i in &x.fibres {
                let _ = write!(o, " {}", fibre_name(i));
            }
            o.push('\n');
        }
        for (k, st) in r.nodes.iter().enumerate() {
            let _ = write!(
                o,
                " node {k} {} up{} fs{} rw{} hop{} perr{} ferr{} aerr{} serr{}",
                st.mode.name(),
                st.up as u8,
                st.failsafe as u8,
                st.rw as u8,
                st.hop.map(|h| h.to_string()).unwrap_or_else(|| "-".into()),
                st.perr,
                st.ferr,
                st.aerr,
                st.serr
            );
            match cfg.nodes[k].kind {
                Kind::Actuator => {
                    let _ = write!(o, " out {:04x}", st.output);
                }
                Kind::Master | Kind::SpecialMaster => {
                    o.push_str(" db");
                    for v in &st.db {
                        let _ = write!(o, " {v:04x}");
                    }
                }
                Kind::Sensor => {}
            }
            o.push('\n');
        }
        for e in &r.events {
            let at = match e.at {
                At::Hdr => "hdr".to_string(),
                At::Slot(s) => format!("s{s}"),
                At::End => "end".to_string(),
            };
            let _ = writeln!(
                o,
                " ev {} {at} node{} {}",
                e.cycle,
                e.node,
                event_text(&e.kind)
            );
        }
    }
    o
}
