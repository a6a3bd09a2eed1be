//! What a run leaves (docs/protocol.md §13): the record of each cycle, the one
//! recovery measure ([`delivered`]), the recovery windows RTL and model are
//! compared with, and [`run`].

use super::*;

/// What the ring delivers in cycle record `r`, per (node, slot): the live
/// masters' data memories and the live actuators' outputs, leaving out
/// slots written by a node killed by the end of `cfg`'s run and a master's
/// ACT slots whose actuator was killed (their values follow the dead node,
/// not the ring). The one measure of recovery: a faulty run has recovered
/// from the cycle on which it delivers, with this `cfg`, what the same ring
/// without faults delivers (the model's tests, `merkur campaign`, `merkur
/// demo`).
pub fn delivered(cfg: &Config, r: &CycleRecord) -> Vec<((usize, usize), u16)> {
    let dead = cfg.killed();
    let mut v = vec![];
    for (k, st) in r.nodes.iter().enumerate() {
        if dead.contains(&k) {
            continue;
        }
        match cfg.nodes[k].kind {
            Kind::Actuator => {
                let s = cfg.nodes[k].address;
                if !dead.contains(&cfg.writer[s]) {
                    v.push(((k, s), st.output));
                }
            }
            Kind::Master | Kind::SpecialMaster => {
                for (s, &x) in st.db.iter().enumerate() {
                    let act_dead = matches!(cfg.slot_kind[s],
                        SlotKind::Act { actuator } if dead.contains(&actuator));
                    if !dead.contains(&cfg.writer[s]) && !act_dead {
                        v.push(((k, s), x));
                    }
                }
            }
            Kind::Sensor => {}
        }
    }
    v
}

/// Everything the model observed in one cycle.
#[derive(Debug, Clone)]
pub struct CycleRecord {
    /// Cycle number.
    pub cycle: u32,
    /// Content of every fibre: P0..P(n-1), then S0..S(n-1).
    pub fibres: Vec<Carry>,
    /// Node states at the end of the cycle.
    pub nodes: Vec<NodeState>,
    /// Events, in order.
    pub events: Vec<Event>,
    /// Value each slot's writer produced this cycle.
    pub produced: Vec<u16>,
    /// Processing path this cycle (node indices, the clock base first;
    /// empty when no frame was sent).
    pub path: Vec<usize>,
    /// The clock base after the cycle (the special master, or the backup
    /// that took over, §8).
    pub base: usize,
    /// Fibres on which the SEC went ahead of the DATA frame that the fibre
    /// shows (a ring wrapped in this cycle), with the SEC's `ok`.
    pub sec_with_data: Vec<(usize, bool)>,
    /// The retransmission packet the clock base sent this cycle (§8).
    pub rtx: Option<RtxRecord>,
}

/// A retransmission packet of one cycle (protocol §8).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RtxRecord {
    /// The slots it requested, in order.
    pub slots: Vec<usize>,
    /// Damaged critical slots that did not fit.
    pub left: usize,
    /// Line bits it took.
    pub bits: u32,
    /// Per request: the clock base got a good copy back.
    pub back: Vec<bool>,
    /// Fibres it travelled (indices as in `fibres`), in order.
    pub fibres: Vec<usize>,
    /// Nodes whose INPUT it reached with its start delimiter and header
    /// intact (a packet for §12's rule 4).
    pub jk: Vec<usize>,
    /// Per fibre of `fibres`: the packet as it arrives at the fibre's far
    /// end (errors on the fibre included; not in the trace).
    pub on: Vec<RtxOnFibre>,
}

/// The retransmission packet on one fibre (protocol §8).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RtxOnFibre {
    /// Its head (J K, H0, H1) arrives intact.
    pub head_ok: bool,
    /// Index and data words, pair by pair.
    pub words: Vec<Slot>,
}

/// Recovery windows the spec promises (docs/protocol.md §13): for each
/// structural fault at cycle c, cycles c..=c+3 (break, kill) or c..=c+4
/// (repair); c..=c+5 for a channel failure that a run of bad words caused
/// (`records`: the run's cycles; it wraps the link and, the fibres being
/// lit, reintegrates it). Bit flips have none. Returned as
/// (first, last, description), clipped to the run, in cycle order.
pub fn windows(cfg: &Config, records: &[CycleRecord]) -> Vec<(u32, u32, String)> {
    let last = cfg.cycles.saturating_sub(1);
    let n = cfg.nodes.len();
    // The clock base before cycle c (§8: a backup may have taken over).
    let base_before = |c: u32| {
        c.checked_sub(1)
            .and_then(|p| records.get(p as usize))
            .map_or(cfg.sm, |r| r.base)
    };
    let mut v: Vec<(u32, u32, String)> = cfg
        .faults
        .iter()
        .filter_map(|(c, f)| {
            let mut end = *c
                + match f {
                    Fault::Break { .. } | Fault::Kill { .. } => 3,
                    Fault::Repair { .. } => REPAIR_WINDOW,
                    // Rejoining (§12): to RESTART_WINDOW cycles after the
                    // node and both neighbours are back in mode N.
                    Fault::Restart { node } => {
                        let nb = [(node + n - 1) % n, *node, (node + 1) % n];
                        let settled = records
                            .iter()
                            .skip(*c as usize)
                            .find(|r| nb.iter().all(|&x| r.nodes[x].mode == Mode::N))
                            .map_or(last, |r| r.cycle);
                        settled.saturating_sub(*c) + RESTART_WINDOW
                    }
                    Fault::Flip { .. } | Fault::Burst { .. } => return None,
                };
            // A repair of a ring in failsafe: which frames come back whole
            // after the reintegrations is bit timing, and so is the cycle
            // the special master brings the ring out (§12, §13).
            let in_fs = records
                .get(*c as usize)
                .is_some_and(|r| r.nodes[r.base].failsafe);
            if let (Fault::Repair { .. }, true) = (f, in_fs) {
                let exit = records
                    .iter()
                    .flat_map(|r| &r.events)
                    .find(|e| {
                        e.cycle > *c
                            && matches!(e.kind, EventKind::FailsafeExit)
                            && records.get(e.cycle as usize).map(|r| r.base) == Some(e.node)
                    })
                    .map_or(last, |e| e.cycle + EXIT_WINDOW);
                end = end.max(exit);
            }
            // The clock base's death: the window runs to 3 cycles after a
            // backup's takeover (§8, §13), to the end without one.
            if let Fault::Kill { node, .. } = f {
                if *node == base_before(*c) {
                    let takeover = records
                        .iter()
                        .flat_map(|r| &r.events)
                        .find(|e| e.cycle >= *c && matches!(e.kind, EventKind::Takeover { .. }))
                        .map_or(last, |e| e.cycle + 3);
                    end = end.max(takeover);
                }
            }
            Some((*c, end.min(last), f.to_string()))
        })
        .collect();
    for e in records.iter().flat_map(|r| &r.events) {
        if let EventKind::BadWords { port } = e.kind {
            v.push((
                e.cycle,
                (e.cycle + BAD_WORDS_WINDOW).min(last),
                format!(
                    "bad words on {} (node {} {})",
                    fibre_into(n, e.node, port),
                    e.node,
                    port.name()
                ),
            ));
        }
    }
    v.sort_by_key(|w| w.0);
    v
}

/// Cycles after a restarted node's rejoin (it and both neighbours back in
/// mode N) that its recovery window covers (protocol §13): the WU end of
/// the last link loses a frame, the RECONFIG(N) alarms follow, and a
/// restarted master's first writes reach every memory a cycle later.
pub const RESTART_WINDOW: u32 = 4;

/// Cycles after a repair's first cycle that its recovery window covers
/// (protocol §13): the WD end unwraps at the end of c+1 or c+2, the WU end
/// loses the next frame, and the RECONFIG(N) alarms follow.
pub const REPAIR_WINDOW: u32 = 5;

/// Cycles after the special master's failsafe exit that the window of a
/// repair made in failsafe covers (protocol §13): the RTL's reintegrations
/// can each come a cycle later than the model's, and so its exit; then the
/// writers refresh every memory (a cycle downstream of a writer, one more
/// upstream through the special master's retransmission).
pub const EXIT_WINDOW: u32 = 4;

/// Cycles after a bad-word channel failure's cycle that its recovery window
/// covers (protocol §13): a repair's — the link is lit all along, so the
/// handshake starts inside that cycle's frame and the WD end unwraps at the
/// end of frame c, c+1 or c+2.
pub const BAD_WORDS_WINDOW: u32 = REPAIR_WINDOW;

/// Runs a whole scenario.
pub fn run(cfg: &Config) -> Vec<CycleRecord> {
    let mut ring = Ring::new(cfg.clone());
    (0..cfg.cycles).map(|_| ring.step()).collect()
}

/// Cycles after a recovery window in which a node that sent an alarm inside
/// it may still repeat it (protocol §11, §13): which frame a fault damages
/// is bit timing, so an alarm the RTL lost where the model did not (or the
/// other way round) is read back in the next cycle, repeated in the one
/// after, and retransmitted by the special master to the nodes before its
/// sender in the third.
pub const REPEAT_TAIL: u32 = 3;
