//! What a token-bus run leaves: every station's channel and status changes
//! ([`TbRun`]) and the golden trace text rendered from them (docs/traces.md).

use super::*;

/// A change seen in a run, in the golden trace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Change {
    /// Tick.
    pub t: u64,
    /// Station.
    pub station: usize,
    /// What changed.
    pub what: String,
}

/// The result of a run.
#[derive(Debug, Clone, Default)]
pub struct TbRun {
    /// Changes in order (the body of the golden trace).
    pub changes: Vec<Change>,
    /// Every station's RMM outputs every tick (`None` while powered off).
    pub outs: Vec<Vec<Option<RmmOut>>>,
    /// Data frames sent.
    pub frames_sent: u64,
    /// (frame, live receiver) pairs expected.
    pub receptions_expected: u64,
    /// Of those, not received.
    pub receptions_lost: u64,
    /// Frames lost per fault window (fault index → receptions lost while it
    /// was the last fault injected).
    pub lost_by_fault: Vec<u64>,
    /// Per fault: every station's first channel switch after it (while it
    /// is the last fault injected), as (station, octets after the fault).
    pub switches: Vec<Vec<(usize, u64)>>,
}

impl TbRun {
    /// Octets from fault `f` to the first and to the last station's first
    /// channel switch, and how many stations switched.
    pub fn switch_latency(&self, f: usize) -> Option<(u64, u64, usize)> {
        let s = &self.switches[f];
        let first = s.iter().map(|x| x.1).min()?;
        let last = s.iter().map(|x| x.1).max()?;
        Some((first, last, s.len()))
    }
}

pub(super) fn log_changes(
    run: &mut TbRun,
    t: u64,
    k: usize,
    p: Option<&RmmOut>,
    o: Option<&RmmOut>,
) {
    let mut push = |what: String| {
        run.changes.push(Change {
            t,
            station: k,
            what,
        })
    };
    match (p, o) {
        (_, None) => {
            if p.is_some() {
                push("power off".into());
            }
        }
        (None, Some(o)) => {
            push(format!(
                "power on state {} act {}",
                rmm::state::name(o.state),
                if o.act { 'B' } else { 'A' }
            ));
        }
        (Some(p), Some(o)) => {
            if p.state != o.state {
                push(format!(
                    "state {} -> {} ({})",
                    rmm::state::name(p.state),
                    rmm::state::name(o.state),
                    rmm::cause::name(o.cause)
                ));
            } else if o.irq && o.stale & !p.stale == 0 {
                push(format!("report {}", rmm::cause::name(o.cause)));
            }
            if p.act != o.act {
                push(format!("active {}", if o.act { 'B' } else { 'A' }));
            }
            for (c, (ps, os)) in [('A', (p.stat_a, o.stat_a)), ('B', (p.stat_b, o.stat_b))] {
                if ps & 1 != os & 1 {
                    push(format!(
                        "channel {c} {}",
                        if os & 1 == 1 { "bad" } else { "good" }
                    ));
                }
                if ps >> 2 & 1 != os >> 2 & 1 && c == 'A' {
                    push(format!("jabber {}", os >> 2 & 1));
                }
            }
            if p.stale != o.stale {
                push(format!("stale {:08x}", o.stale));
            }
            if o.chk_ok && !p.chk_ok {
                push("status check ok".into());
            }
            if o.chk_sw && !p.chk_sw {
                push(format!(
                    "status check switch (active {} suspect)",
                    if o.act { 'B' } else { 'A' }
                ));
            }
            if o.cmd_req && !p.cmd_req {
                push(format!(
                    "switch command to {}",
                    if o.cmd_ch { 'B' } else { 'A' }
                ));
            }
        }
    }
}

/// Renders the golden trace of a token-bus run (docs/traces.md).
pub fn render(cfg: &TbConfig, source: &str, r: &TbRun) -> String {
    use std::fmt::Write;
    let mut o = String::new();
    let _ = writeln!(o, "# merkur token-bus golden trace");
    let _ = writeln!(o, "# format 1");
    let _ = writeln!(o, "# generator merkur-model {}", env!("CARGO_PKG_VERSION"));
    let _ = writeln!(o, "# scenario {}", cfg.name);
    let _ = writeln!(
        o,
        "# scenario-sha256 {}",
        crate::trace::scenario_hash(source)
    );
    let _ = writeln!(
        o,
        "# stations {} ticks {} data_len {} sf_period {} check_period {} good_limit {}",
        cfg.stations, cfg.ticks, cfg.data_len, cfg.sf_period, cfg.check_period, cfg.good_limit
    );
    for c in &r.changes {
        if c.station == usize::MAX {
            let _ = writeln!(o, "{} - {}", c.t, c.what);
        } else {
            let _ = writeln!(o, "{} {} {}", c.t, c.station, c.what);
        }
    }
    let _ = writeln!(
        o,
        "summary frames_sent {} receptions_expected {} receptions_lost {}",
        r.frames_sent, r.receptions_expected, r.receptions_lost
    );
    for (k, e) in cfg.events.iter().enumerate() {
        if e.what.is_fault() {
            let lat = match r.switch_latency(k) {
                None => "no station switched".to_string(),
                Some((a, b, n)) => format!("{n} stations switched after {a}..{b} octets"),
            };
            let _ = writeln!(
                o,
                "fault {} at {} ({}): {lat}, receptions lost {}",
                e.what,
                e.at,
                e.what.class(),
                r.lost_by_fault[k]
            );
        }
    }
    o
}
