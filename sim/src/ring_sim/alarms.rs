//! The masters' alarm queues (protocol §11) in a ring run: the driver drains
//! them over Wishbone as a host would, and compares what it drained with the
//! alarms the model delivers to each master — exactly (reason, slot, CYC,
//! order) outside the recovery windows, by the window rule inside them
//! (protocol §13).

use super::{Mismatch, Ring};
use merkur_model::config::Config;
use merkur_model::ring::{reason, CycleRecord, EventKind, Mode};
use merkur_rtl::harness::ring_top::status as st;
use merkur_rtl::node::mdb::{ALQ_DEPTH, ALQ_POP, WB_ALQ_CTL, WB_ALQ_HEAD, WB_ALQ_OVF};

/// One entry of a master's alarm queue.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entry {
    /// Reason code (protocol §11).
    pub reason: u8,
    /// The slot the alarm came in (its sender's address).
    pub slot: u16,
    /// CYC of the frame that carried it.
    pub cyc: u8,
}

impl std::fmt::Display for Entry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = match self.reason {
            reason::IRQ1 => "IRQ1".to_string(),
            reason::IRQ2 => "IRQ2".to_string(),
            reason::FAILSAFE => "FAILSAFE".to_string(),
            r @ reason::RECONFIG_N..=reason::RECONFIG_WD => {
                format!("RECONFIG({})", mode_of(r).map_or("?", Mode::name))
            }
            r => format!("reason {r}"),
        };
        write!(f, "{name} from slot {} in CYC {}", self.slot, self.cyc)
    }
}

/// The switchbox mode a RECONFIG reason announces.
pub fn mode_of(r: u8) -> Option<Mode> {
    match r {
        reason::RECONFIG_N => Some(Mode::N),
        reason::RECONFIG_WU => Some(Mode::Wu),
        reason::RECONFIG_WD => Some(Mode::Wd),
        _ => None,
    }
}

/// The ring top's per-master interrupt counts, one per reason line: every
/// delivered alarm pulses exactly one of them and enters the queue.
const LINES: [u32; 4] = [st::IRQ1, st::IRQ2, st::IRQFS, st::IRQRC];

/// Every master's drained queue.
pub(super) struct AlarmQueues {
    masters: Vec<usize>,
    /// Per node: the entries drained, oldest first.
    pub got: Vec<Vec<Entry>>,
}

impl AlarmQueues {
    pub fn new(cfg: &Config) -> Self {
        AlarmQueues {
            masters: (0..cfg.nodes.len())
                .filter(|&k| cfg.nodes[k].kind.is_master())
                .collect(),
            got: vec![vec![]; cfg.nodes.len()],
        }
    }

    /// Alarms delivered to master `k` and not drained yet (read without a
    /// clock: the ring top's counters).
    fn pending(&self, r: &mut Ring, k: usize) -> u64 {
        let delivered: u64 = LINES.iter().map(|&f| r.rd(k, f)).sum();
        delivered.saturating_sub(self.got[k].len() as u64)
    }

    /// Drains every master with at least `min` (≥ 1) alarms pending. A host
    /// transfer runs the ring on meanwhile, so the driver calls it with
    /// `min` = 1 only where no fault is due.
    pub fn drain(&mut self, r: &mut Ring, min: u64) -> Result<(), String> {
        for i in 0..self.masters.len() {
            let k = self.masters[i];
            if self.pending(r, k) >= min.max(1) {
                self.drain_one(r, k)?;
            }
        }
        Ok(())
    }

    /// Half the queue: where the driver drains even with a fault due.
    pub const HIGH: u64 = ALQ_DEPTH as u64 / 2;

    fn drain_one(&mut self, r: &mut Ring, k: usize) -> Result<(), String> {
        loop {
            let ctl = r.wb(k, WB_ALQ_CTL, None)?;
            if ctl & 0x1f == 0 {
                return Ok(());
            }
            let head = r.wb(k, WB_ALQ_HEAD, None)?;
            self.got[k].push(Entry {
                reason: (head >> 12) as u8,
                slot: head & 0xfff,
                cyc: (ctl >> 12 & 7) as u8,
            });
            r.wb(k, WB_ALQ_CTL, Some(ALQ_POP))?;
        }
    }

    /// Drains every queue and checks it with the model's deliveries: the
    /// entries (see the module doc), no overflow, and one interrupt pulse per
    /// RECONFIG entry. `win` gives the recovery window of a cycle; `up`
    /// whether a node is alive at the end (a dead node runs on unheard).
    pub fn finish(
        &mut self,
        cfg: &Config,
        r: &mut Ring,
        recs: &[CycleRecord],
        win: &dyn Fn(u32) -> Option<(u32, u32)>,
        up: &dyn Fn(usize) -> bool,
        mism: &mut Vec<Mismatch>,
    ) -> Result<(), String> {
        let last = recs.len().saturating_sub(1) as u32;
        let sent = sent_in_windows(cfg, recs, win);
        for i in 0..self.masters.len() {
            let k = self.masters[i];
            self.drain_one(r, k)?;
            if !up(k) {
                continue;
            }
            let place = format!("node {k}");
            let ovf = r.wb(k, WB_ALQ_OVF, None)?;
            if ovf != 0 {
                mism.push(Mismatch {
                    cycle: last,
                    place: place.clone(),
                    what: "alarm queue overflow".into(),
                    expected: "0 (the driver drains the queue before it fills)".into(),
                    got: ovf.to_string(),
                });
            }
            let rc = self.got[k]
                .iter()
                .filter(|e| mode_of(e.reason).is_some())
                .count() as u64;
            let pulses = r.rd(k, st::IRQRC);
            if pulses != rc {
                mism.push(Mismatch {
                    cycle: last,
                    place: place.clone(),
                    what: "RECONFIG interrupts (one per RECONFIG entry in the queue)".into(),
                    expected: rc.to_string(),
                    got: pulses.to_string(),
                });
            }
            let want = delivered(recs, k);
            if let Some(m) = compare(&want, &sent, &self.got[k], win) {
                mism.push(Mismatch { place, ..m });
            }
        }
        Ok(())
    }

    /// The ring's shape as master `k` reconstructs it from its queue and its
    /// own mode (`own`, from its status register): the nodes whose last
    /// RECONFIG announced a wrap, by address (a node that sent none is in N).
    pub fn shape(&self, cfg: &Config, k: usize, own: Mode) -> Vec<(usize, Mode)> {
        let mut last: Vec<Option<Mode>> = vec![None; cfg.nodes.len()];
        last[k] = Some(own);
        for e in &self.got[k] {
            if let (Some(m), Some(node)) = (
                mode_of(e.reason),
                cfg.nodes
                    .iter()
                    .position(|nd| nd.address == e.slot as usize),
            ) {
                last[node] = Some(m);
            }
        }
        last.iter()
            .enumerate()
            .filter_map(|(node, m)| m.filter(|&m| m != Mode::N).map(|m| (node, m)))
            .collect()
    }

    /// The masters, in ring order.
    pub fn masters(&self) -> &[usize] {
        &self.masters
    }
}

/// The alarms the model delivers to master `k`, in order, with their cycles.
fn delivered(recs: &[CycleRecord], k: usize) -> Vec<(u32, Entry)> {
    recs.iter()
        .flat_map(|rec| &rec.events)
        .filter(|ev| ev.node == k)
        .filter_map(|ev| match ev.kind {
            EventKind::Irq { slot, reason } => Some((
                ev.cycle,
                Entry {
                    reason,
                    slot: slot as u16,
                    cyc: (ev.cycle & 7) as u8,
                },
            )),
            _ => None,
        })
        .collect()
}

/// An alarm a node sent inside a recovery window: (cycle, its slot, reason).
type Sent = (u32, u16, u8);

/// The alarms the model's nodes send inside recovery windows, and the
/// RECONFIG of every switchbox change there (protocol §13: a RECONFIG
/// alarm of a mode its sender had in the window is bit timing, as for the
/// values a node holds — e.g. a node that wraps at a second fault sends it
/// in the RTL when a frame starts between its wrap and its failsafe, where
/// the model's node fails safe at the same cycle's end and sends nothing).
fn sent_in_windows(
    cfg: &Config,
    recs: &[CycleRecord],
    win: &dyn Fn(u32) -> Option<(u32, u32)>,
) -> Vec<Sent> {
    recs.iter()
        .flat_map(|rec| &rec.events)
        .filter(|ev| win(ev.cycle).is_some())
        .filter_map(|ev| {
            let slot = cfg.nodes[ev.node].address as u16;
            match ev.kind {
                EventKind::AlarmTx { reason, .. } => Some((ev.cycle, slot, reason)),
                EventKind::Mode { to, .. } => Some((ev.cycle, slot, reason::reconfig(to))),
                _ => None,
            }
        })
        .collect()
}

/// Compares a queue with the model's deliveries; the first difference
/// (comparing further would only repeat it shifted). The deliveries outside
/// the windows entry for entry, in order. Around them, entries the window
/// rule allows (which frame a fault damages, and so which alarm has to be
/// repeated and when, is bit timing): an alarm that a node sent inside a
/// window (`sent`), with its reason (RECONFIG: any mode — which change is
/// pending when the sender next writes is bit timing), in a frame of that
/// window (its CYC). `win` gives the windows extended by their repeat
/// tails (protocol §13).
fn compare(
    want: &[(u32, Entry)],
    sent: &[Sent],
    got: &[Entry],
    win: &dyn Fn(u32) -> Option<(u32, u32)>,
) -> Option<Mismatch> {
    let allowed = |g: &Entry| {
        sent.iter().any(|&(c, slot, reason)| {
            let (a, z) = win(c).unwrap_or((c, c));
            slot == g.slot
                && (reason == g.reason
                    || (mode_of(reason).is_some() && mode_of(g.reason).is_some()))
                && (a..=z).any(|x| (x & 7) as u8 == g.cyc)
        })
    };
    let strict: Vec<(u32, Entry)> = want
        .iter()
        .copied()
        .filter(|&(c, _)| win(c).is_none())
        .collect();
    let mut j = 0;
    for &(c, e) in &strict {
        while j < got.len() && got[j] != e && allowed(&got[j]) {
            j += 1;
        }
        if got.get(j) != Some(&e) {
            return Some(Mismatch {
                cycle: c,
                place: String::new(),
                what: format!("alarm queue entry {j}"),
                expected: e.to_string(),
                got: got.get(j).map_or("none".into(), Entry::to_string),
            });
        }
        j += 1;
    }
    while j < got.len() && allowed(&got[j]) {
        j += 1;
    }
    (j < got.len()).then(|| Mismatch {
        cycle: strict.last().map_or(0, |w| w.0),
        place: String::new(),
        what: format!("alarm queue entry {j}"),
        expected: "none".into(),
        got: got[j].to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(reason: u8, slot: u16, cyc: u8) -> Entry {
        Entry { reason, slot, cyc }
    }

    #[test]
    fn outside_windows_every_entry_must_match() {
        let want = [(3, e(1, 2, 3)), (9, e(2, 5, 1))];
        let none = |_: u32| None;
        let cmp = |got: &[Entry]| compare(&want, &[], got, &none);
        assert!(cmp(&[e(1, 2, 3), e(2, 5, 1)]).is_none());
        let m = cmp(&[e(1, 2, 3), e(2, 5, 2)]).unwrap();
        assert_eq!((m.cycle, m.what.as_str()), (9, "alarm queue entry 1"));
        assert!(cmp(&[e(1, 2, 3)]).is_some(), "one missing");
        assert!(cmp(&[e(2, 5, 1), e(1, 2, 3)]).is_some(), "out of order");
        assert!(
            cmp(&[e(1, 2, 3), e(2, 5, 1), e(1, 2, 4)]).is_some(),
            "one too many"
        );
    }

    #[test]
    fn inside_a_window_the_rule_allows_bit_timing() {
        // Window cycles 10..13: node of slot 4 sent RECONFIG(WD) in cycle
        // 11; the model delivered it in 11. It may come as RECONFIG(N) of
        // the same slot a frame later, twice, or not at all; not from another
        // slot, not as a user alarm, not outside the window's frames.
        let w = |c: u32| (10..=13).contains(&c).then_some((10, 13));
        let want = [(11, e(6, 4, 3)), (20, e(1, 2, 4))];
        let sent = [(11, 4, 6)];
        let cmp = |got: &[Entry]| compare(&want, &sent, got, &w);
        assert!(cmp(&[e(6, 4, 3), e(1, 2, 4)]).is_none());
        assert!(cmp(&[e(4, 4, 4), e(1, 2, 4)]).is_none());
        assert!(cmp(&[e(1, 2, 4)]).is_none(), "lost in the window");
        assert!(
            cmp(&[e(6, 4, 3), e(4, 4, 5), e(1, 2, 4)]).is_none(),
            "both changes"
        );
        assert!(cmp(&[e(6, 5, 3), e(1, 2, 4)]).is_some(), "another sender");
        assert!(cmp(&[e(1, 4, 3), e(1, 2, 4)]).is_some(), "another reason");
        assert!(
            cmp(&[e(6, 4, 6), e(1, 2, 4)]).is_some(),
            "outside the window"
        );
        assert!(
            cmp(&[e(1, 2, 4), e(6, 4, 3)]).is_none(),
            "after: CYC decides"
        );
        // A window of which the model delivered nothing to this master.
        assert!(compare(&want[1..], &sent, &[e(6, 4, 2), e(1, 2, 4)], &w).is_none());
    }
}
