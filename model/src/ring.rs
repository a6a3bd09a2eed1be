//! The cycle-level ring simulation (docs/protocol.md §5–§12).
//!
//! One call of [`Ring::step`] simulates one communication cycle: the special
//! master emits a frame, the frame follows the path the switchboxes make
//! (processing at each node's INPUT, pass-through on the secondary ring), the
//! secondary test frame and the link tests (TST) run, and at the end of the
//! cycle every stream controller's verdict is resolved into switchbox changes,
//! failsafe entries and reintegrations, which take effect from the next cycle.

use crate::config::*;
use crate::line::{self, Lead, Rx, Word};
use crate::scenario::{Generator, IrqLine, Kind};
use std::collections::BTreeSet;
use std::fmt;

mod age;
mod clock_base;
mod events;
mod faults;
mod frame;
mod node;
mod record;
mod rtx;
mod switching;
pub use age::{age_stats, ages, AgeStat};
use clock_base::*;
pub use events::*;
use faults::*;
pub use frame::*;
pub use node::*;
pub use record::*;
use switching::*;

/// The ring.
#[derive(Debug, Clone)]
pub struct Ring {
    /// Configuration.
    pub cfg: Config,
    /// Node states.
    pub nodes: Vec<NodeState>,
    /// Cycle to run next.
    pub cycle: u32,
    /// Broken fibres.
    pub broken: BTreeSet<Fibre>,
    /// Per link k (node k → node k+1): the cycle at whose end its two
    /// nodes were first seen wrapped towards each other (k in WD, k+1 in
    /// WU) with both fibres carrying light: from then on they hear each
    /// other's TST (§12).
    pair_since: Vec<Option<u32>>,
    /// Per link: its WU end has heard the WD end's TST with ACK (the
    /// handshake is done) and has not changed mode since.
    acked: Vec<bool>,
    /// Per node: the cycle at whose end it unwrapped (→ N); for the next
    /// cycle a TST where DATA is expected is not a failure (§12, grace).
    unwrapped_at: Vec<Option<u32>>,
    /// Special master's return store (next cycle's words).
    store: Vec<Slot>,
    /// Words the special master emitted this cycle (alarm retransmit rule).
    emitted: Vec<Slot>,
    /// RWC of the last returned header.
    returned_rwc: bool,
    /// The special master's failsafe exit (§12).
    exit: SmExit,
    /// WU ends of links that reintegrated at the end of the last cycle:
    /// this cycle's frame reaches their INPUT without its start delimiter.
    lose_next: Vec<usize>,
    /// The clock base: the special master, or the backup that took over
    /// from it (§8, the flying special master).
    pub base: usize,
    /// Per slot of the packet in flight: the cycle its word's value was
    /// written by the slot's writer (data age, not on the line).
    cur_born: Vec<Option<u32>>,
    /// The same for the return store.
    store_born: Vec<Option<u32>>,
    /// Critical slots whose word of this cycle's frame came back bad or
    /// not at all, or every critical slot when the frame came back with
    /// its header damaged (§8, retransmission on demand), in slot order.
    damaged: Vec<usize>,
}

impl Ring {
    /// A ring in its power-up state (all switchboxes N, memories zero).
    pub fn new(cfg: Config) -> Ring {
        let n = cfg.nodes.len();
        let s = cfg.slots;
        let nodes = (0..n).map(|k| fresh_node(&cfg, k)).collect();
        Ring {
            nodes,
            cycle: 0,
            broken: BTreeSet::new(),
            pair_since: vec![None; n],
            acked: vec![false; n],
            unwrapped_at: vec![None; n],
            store: vec![Slot::Void; s],
            cur_born: vec![None; s],
            store_born: vec![None; s],
            damaged: vec![],
            emitted: vec![Slot::Void; s],
            returned_rwc: false,
            exit: SmExit::default(),
            lose_next: vec![],
            base: cfg.sm,
            cfg,
        }
    }

    fn n(&self) -> usize {
        self.cfg.nodes.len()
    }

    /// Fibre leaving node `k` at port `p` (PO or SO).
    pub fn out_fibre(&self, k: usize, p: Port) -> Fibre {
        let n = self.n();
        match p {
            Port::Po => Fibre::P(k),
            Port::So => Fibre::S((k + n - 1) % n),
            _ => unreachable!("inputs have no outgoing fibre"),
        }
    }

    /// Fibre entering node `k` at port `p` (PI or SI).
    pub fn in_fibre(&self, k: usize, p: Port) -> Fibre {
        fibre_into(self.n(), k, p)
    }

    /// Sender node and port of a fibre.
    pub fn src(&self, f: Fibre) -> (usize, Port) {
        let n = self.n();
        match f {
            Fibre::P(k) => (k, Port::Po),
            Fibre::S(k) => ((k + 1) % n, Port::So),
        }
    }

    /// Receiver node and port of a fibre.
    pub fn dst(&self, f: Fibre) -> (usize, Port) {
        let n = self.n();
        match f {
            Fibre::P(k) => ((k + 1) % n, Port::Pi),
            Fibre::S(k) => (k, Port::Si),
        }
    }

    fn fibre_index(&self, f: Fibre) -> usize {
        f.index(self.n())
    }

    /// Light on a fibre at the start of the cycle (static carrier view).
    fn lit(&self, f: Fibre) -> bool {
        !self.broken.contains(&f) && self.nodes[self.src(f).0].up
    }

    /// A fibre carries TST: its sender is wrapped and this is its BSS.
    fn carries_tst(&self, f: Fibre) -> bool {
        let (k, p) = self.src(f);
        self.lit(f) && self.nodes[k].mode != Mode::N && table1(self.nodes[k].mode).3 == p
    }

    fn event(&self, ev: &mut Vec<Event>, cycle: u32, at: At, node: usize, kind: EventKind) {
        ev.push(Event {
            cycle,
            at,
            node,
            kind,
        });
    }

    fn enter_failsafe(&mut self, ev: &mut Vec<Event>, k: usize, at: At, cause: FsCause) {
        if k == self.base && cause == FsCause::Request {
            self.exit.request = true;
        }
        if !self.nodes[k].failsafe {
            self.nodes[k].failsafe = true;
            let c = self.cycle;
            self.event(ev, c, at, k, EventKind::Failsafe(cause));
        }
    }

    /// Runs one cycle and returns what happened: the environment before
    /// it, the cycle's faults, the DATA frame, the SEC and the
    /// retransmission packet from the clock base, the link tests, frame
    /// supervision, the faults that act at the end, and the stream
    /// controllers' verdicts.
    pub fn step(&mut self) -> CycleRecord {
        let c = self.cycle;
        let n = self.n();
        let mut ev = Vec::new();
        for nd in &mut self.nodes {
            nd.cf_words = [false; 2];
        }
        // 1. Host writes and interrupt requests land before the cycle.
        self.before_cycle(c, &mut ev);
        // 2. Faults of this cycle.
        let (faults, cf) = self.cycle_faults(c);
        let produced: Vec<u16> = (0..self.cfg.slots)
            .map(|s| self.source_value(s, c))
            .collect();
        let mut fibres = self.idle_fibres();
        let mut got_frame = vec![false; n];
        let mut path = vec![];

        // 3. The data frame, from the clock base (a backup takes over when
        // it is dead, §8).
        let base = self.clock_base(&mut ev);
        // The SEC decision is made at the cycle's start, from the RWC of
        // the last frame that returned before it (protocol §8).
        let sec_rwc = self.returned_rwc;
        let mut sec_with_data = vec![];
        let mut rtx = None;
        let mut rtx_acted = vec![false; n];
        if let Some(sm) = base {
            got_frame[sm] =
                self.data_frame(sm, &cf, &mut fibres, &mut got_frame, &mut path, &mut ev);
            // 4. The secondary test frame.
            if self.nodes[sm].mode == Mode::N && !sec_rwc {
                sec_with_data = self.sec_frame(sm, &cf, &mut fibres, &mut ev);
            }
            // 4b. The retransmission packet, after the frame (§8).
            rtx = self.rtx_packet(sm, &cf, &mut rtx_acted, &mut ev);
        }

        // 5. Link tests from wrapped nodes.
        self.link_tests(&mut fibres);
        // 6. Frame supervision and the CS timeout.
        let rtx_jk = rtx.as_ref().map_or(&[][..], |x| &x.jk[..]);
        let packet_in = self.supervise(&got_frame, &fibres, rtx_jk, &mut ev);
        // Faults that take effect at the end of the cycle.
        self.end_faults(&cf, &faults);
        // 7. Stream controllers and switchboxes.
        let frame_in = self.inputs_carry(
            &fibres,
            |x| matches!(x, Carry::Data(f) if f.hdr != HeaderRx::NoCs),
        );
        let tst_in = self.inputs_carry(&fibres, |x| matches!(x, Carry::Tst { .. }));
        self.resolve(
            &mut ev,
            &Inputs {
                packet: &packet_in,
                frame: &frame_in,
                tst: &tst_in,
            },
        );
        // Alive flip-flops toggle after each frame a node processed (the
        // special master after each frame it sent), and in a node that
        // missed the frame but wrote into the retransmission packet (§8).
        for (k, nd) in self.nodes.iter_mut().enumerate() {
            if got_frame[k] || base == Some(k) || rtx_acted[k] {
                nd.toggle = !nd.toggle;
            }
        }
        self.cycle += 1;
        CycleRecord {
            cycle: c,
            fibres,
            nodes: self.nodes.clone(),
            events: ev,
            produced,
            path,
            base: self.base,
            sec_with_data,
            rtx,
        }
    }

    /// Before cycle `c`: its host writes and interrupt requests land, and
    /// the host's failsafe clear command.
    fn before_cycle(&mut self, c: u32, ev: &mut Vec<Event>) {
        for &(wc, node, slot, data) in &self.cfg.host_writes {
            if wc == c {
                self.nodes[node].db[slot] = data;
                self.nodes[node].valid[slot] = true;
            }
        }
        let irqs: Vec<(usize, IrqLine)> = self
            .cfg
            .irqs
            .iter()
            .filter(|(qc, _, _)| *qc == c)
            .map(|&(_, node, line)| (node, line))
            .collect();
        for (node, line) in irqs {
            let r = match line {
                IrqLine::Irq1 => reason::IRQ1,
                IrqLine::Irq2 => reason::IRQ2,
                IrqLine::Failsafe => reason::FAILSAFE,
            };
            self.nodes[node].pending.insert(Pending {
                prio: prio(r),
                reason: r,
            });
        }
        if self.cfg.fs_clears.contains(&c) {
            self.exit.host_clear = true;
            let sm = self.base;
            self.event(ev, c, At::Hdr, sm, EventKind::FsClear);
        }
    }

    /// The faults of cycle `c`: breaks and deaths before the cycle act now
    /// (a restart too: the node in its power-up state); the rest, inside
    /// the cycle, are returned for the frame's way round.
    fn cycle_faults(&mut self, c: u32) -> (Vec<Fault>, CycleFaults) {
        let faults: Vec<Fault> = self
            .cfg
            .faults
            .iter()
            .filter(|(fc, _)| *fc == c)
            .map(|(_, f)| *f)
            .collect();
        let mut cut_fibre: Vec<(Fibre, usize)> = vec![];
        let mut cut_node: Vec<(usize, usize)> = vec![];
        for f in &faults {
            match *f {
                Fault::Break { fibre, slot: None } => {
                    self.broken.insert(fibre);
                }
                Fault::Break {
                    fibre,
                    slot: Some(s),
                } => cut_fibre.push((fibre, s)),
                Fault::Kill { node, slot: None } => self.nodes[node].up = false,
                Fault::Restart { node } => {
                    // Power-up state (§12); a master reloads from the ring.
                    let mut fresh = fresh_node(&self.cfg, node);
                    fresh.reload = self.cfg.nodes[node].kind.is_master();
                    fresh.valid.iter_mut().for_each(|v| *v = false);
                    self.nodes[node] = fresh;
                    self.unwrapped_at[node] = None;
                    self.lose_next.retain(|&x| x != node);
                }
                Fault::Kill {
                    node,
                    slot: Some(s),
                } => cut_node.push((node, s)),
                _ => {}
            }
        }
        let flips: Vec<(Fibre, FlipTarget, u32)> = faults
            .iter()
            .filter_map(|f| match *f {
                Fault::Flip { fibre, target, bit } => Some((fibre, target, bit)),
                _ => None,
            })
            .collect();
        let bursts: Vec<Fault> = faults
            .iter()
            .copied()
            .filter(|f| matches!(f, Fault::Burst { .. }))
            .collect();
        let cf = CycleFaults {
            cut_fibre,
            cut_node,
            flips,
            bursts,
        };
        (faults, cf)
    }

    /// Every fibre at the cycle's start: idle where it carries light,
    /// silent where not (P0…P(n−1), then S0…S(n−1)).
    fn idle_fibres(&self) -> Vec<Carry> {
        let n = self.n();
        (0..n)
            .map(Fibre::P)
            .chain((0..n).map(Fibre::S))
            .map(|f| {
                if self.lit(f) {
                    Carry::Idle
                } else {
                    Carry::Silent
                }
            })
            .collect()
    }

    /// Section 5: every wrapped node sends TST on its BSS, acknowledging
    /// when its BSR hears TST.
    fn link_tests(&mut self, fibres: &mut [Carry]) {
        for k in 0..self.n() {
            if !self.nodes[k].up || self.nodes[k].mode == Mode::N {
                continue;
            }
            let (_, _, bsr, bss) = table1(self.nodes[k].mode);
            let f = self.out_fibre(k, bss);
            if self.lit(f) {
                let ack = self.carries_tst(self.in_fibre(k, bsr));
                let fi = self.fibre_index(f);
                fibres[fi] = Carry::Tst { ack };
                let (r, port) = self.dst(f);
                self.nodes[r].bad_run[usize::from(port == Port::Si)] = 0;
            }
        }
    }

    /// Section 6: every live node's frame supervision (frame errors, the
    /// Alive check's memory), its CS timeout (rule 4, §12) and a backup's
    /// election timer (§8). `rtx_jk`: the nodes that saw the
    /// retransmission packet's J K. Returns per node whether a packet
    /// other than a TST started on its INPUT.
    fn supervise(
        &mut self,
        got_frame: &[bool],
        fibres: &[Carry],
        rtx_jk: &[usize],
        ev: &mut Vec<Event>,
    ) -> Vec<bool> {
        let cs_timeout = self.cfg.cs_timeout_cycles();
        let mut packet_in = vec![false; self.n()];
        for (k, &got) in got_frame.iter().enumerate() {
            if !self.nodes[k].up {
                continue;
            }
            if !got {
                // No frame read this cycle: the next Alive check has nothing
                // to compare with.
                self.nodes[k].last_alive.iter_mut().for_each(|a| *a = None);
            }
            if got {
                // A node other than the special master counts the cycles
                // without a good frame from the gap in CYC's 3 bits at the
                // next good header: 8 or more in a row count modulo 8
                // (protocol §9); the special master counts every one.
                if k != self.base {
                    self.nodes[k].ferr -= 8 * (self.nodes[k].missed / 8);
                }
                self.nodes[k].missed = 0;
                self.nodes[k].armed = true;
            } else if self.nodes[k].armed {
                self.nodes[k].ferr += 1;
                self.nodes[k].missed += 1;
            }
            // Rule 4 (§12): cycles without the start delimiter of a packet
            // other than a TST on INPUT (a frame whose header is damaged
            // still shows its J K; a wrapped neighbour's TST can reach the
            // INPUT of a node cut off between two wraps).
            let inp = self.in_fibre(k, table1(self.nodes[k].mode).0);
            let jk = match &fibres[self.fibre_index(inp)] {
                Carry::Data(f) => f.hdr != HeaderRx::NoCs,
                Carry::Sec { .. } => true,
                Carry::Tst { .. } | Carry::Silent | Carry::Idle => false,
            };
            // The retransmission packet's J K counts as well (§8).
            let jk = jk || rtx_jk.contains(&k);
            packet_in[k] = jk;
            // A backup's election timer (§8): any packet on INPUT, or the
            // body of a frame whose J K was destroyed, restarts it.
            let any = !matches!(fibres[self.fibre_index(inp)], Carry::Silent | Carry::Idle);
            self.nodes[k].quiet = if any { 0 } else { self.nodes[k].quiet + 1 };
            if got || jk {
                self.nodes[k].no_cs = 0;
            } else if self.nodes[k].armed {
                self.nodes[k].no_cs += 1;
                if self.nodes[k].no_cs >= cs_timeout {
                    self.enter_failsafe(ev, k, At::End, FsCause::Timeout);
                }
            }
        }
        packet_in
    }

    /// The faults that take effect at the end of the cycle: breaks and
    /// deaths inside it, and repairs (light again from the next cycle).
    fn end_faults(&mut self, cf: &CycleFaults, faults: &[Fault]) {
        for (f, _) in &cf.cut_fibre {
            self.broken.insert(*f);
        }
        for (k, _) in &cf.cut_node {
            self.nodes[*k].up = false;
        }
        for f in faults {
            if let Fault::Repair { fibre, .. } = *f {
                self.broken.remove(&fibre);
            }
        }
    }
}
