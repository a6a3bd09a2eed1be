//! A node's part of the cycle (docs/protocol.md §6–§11): its state at power-up,
//! the processing of a frame at its INPUT, its stream controllers' bad-word
//! runs, reading and writing slots, the values its sensors produce and the
//! alarms it sends.

use super::*;

/// A pending alarm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Pending {
    pub(super) prio: u8,
    pub(super) reason: u8,
}

/// An alarm word's reason and SEQ (protocol §11): basic variant
/// `D[15:12]`, `D[11]`; extended variant `N1 = {SEQ, reason[2:0]}`.
pub(super) fn alarm_of(d: &Word, ext: bool) -> (u8, bool) {
    if ext {
        (d.reason & 7, d.reason & 8 != 0)
    } else {
        ((d.data >> 12) as u8, d.data & 0x800 != 0)
    }
}

pub(super) fn prio(reason: u8) -> u8 {
    match reason {
        reason::FAILSAFE => 0,
        reason::RECONFIG_N..=reason::RECONFIG_WD => 1,
        reason::IRQ1 => 2,
        _ => 3,
    }
}

/// State of one node at the end of a cycle.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeState {
    /// Switchbox mode for the next cycle.
    pub mode: Mode,
    /// Not killed.
    pub up: bool,
    /// In failsafe (until the special master brings the ring out, §12).
    pub failsafe: bool,
    /// The node knows the ring is wrapped (last valid header, or itself).
    pub rw: bool,
    /// Armed: has seen its first valid frame.
    pub armed: bool,
    /// Cycles in a row without a good frame at INPUT (for `ferr`).
    pub(super) missed: u32,
    /// Consecutive cycles without a start delimiter at INPUT (rule 4).
    pub no_cs: u32,
    /// Words with a parity/code error seen at INPUT (cumulative).
    pub perr: u32,
    /// Cycles without a valid frame at INPUT, after arming (cumulative).
    pub ferr: u32,
    /// Alive-check failures (cumulative; masters).
    pub aerr: u32,
    /// Secondary test failures (cumulative; special master).
    pub serr: u32,
    /// HOP value this node put in the header this cycle (SM: HOP returned).
    pub hop: Option<u16>,
    /// Masters: the data memory (real-time database).
    pub db: Vec<u16>,
    /// Masters: per slot, the cycle in which the writer wrote the value
    /// `db` holds (its data age is the cycle minus this); `None` before
    /// the first.
    pub db_born: Vec<Option<u32>>,
    /// Actuators: the output register.
    pub output: u16,
    /// Actuators: the cycle in which the output register's value was
    /// written by its master.
    pub out_born: Option<u32>,
    /// An actuator's output register before its own slot's word of this
    /// frame updated it: the data of an alarm it sends there in the
    /// extended variant (§6; a cut-through node decides the word at its
    /// first group, before the new value has passed).
    pub(super) out_before: u16,
    /// The node's Alive flip-flop (value used this cycle).
    pub toggle: bool,
    pub(super) last_alive: Vec<Option<bool>>,
    pub(super) alive_lost: Vec<bool>,
    pub(super) act_alive: Vec<bool>,
    /// The last home-slot word written carried an alarm: the next carries
    /// none (§11's alternation in the basic variant; in the extended one
    /// the pacing §6 asks for, as a cut-through node decides its home word
    /// from the first group, before the read-back's word has ended).
    pub(super) prev_home_alarm: bool,
    pub(super) pending: BTreeSet<Pending>,
    /// The alarm in flight: sent, not yet read back (§11).
    pub(super) inflight: Option<Pending>,
    /// An alarm went out in the last home-slot write; the next home-slot
    /// read reads it back.
    pub(super) awaiting: bool,
    /// SEQ of the last alarm sent (a new one gets the other value).
    pub(super) seq: bool,
    /// Masters: per slot, the SEQ of the last good alarm word read there.
    pub(super) last_seq: Vec<bool>,
    /// Consecutive bad words per receiver (PI, SI), across packets (§9).
    pub(super) bad_run: [u32; 2],
    /// This cycle: a run of bad words reached [`BAD_WORDS`] on PI, SI.
    pub(super) cf_words: [bool; 2],
    /// Cycles in a row whose INPUT carried no packet (frame, frame body,
    /// SEC or TST): a backup's election timer (§8).
    pub quiet: u32,
    /// At its last good header the node did not know the ring was wrapped
    /// (§8: a backup may then take over as from a first fault).
    pub(super) elig: bool,
    /// A restarted master before its reload frame (§12): it reads every
    /// slot, its own too, and writes nothing.
    pub(super) reload: bool,
    /// Masters: per slot, the data memory holds a value to write: always,
    /// but after a restart (§12) only once the reload frame brought a good
    /// word or the host wrote it (its LOCAL and ACT slots are written only
    /// then; the reload leaves what the host wrote).
    pub(super) valid: Vec<bool>,
    /// From power-up (a restart is one) until it is whole (§12: mode N,
    /// armed, no TST on INPUT or BSR): when its upstream link reintegrates
    /// and its downstream neighbour is wrapped towards it, it turns to WD
    /// instead of N.
    pub(super) rejoin: bool,
}

/// A node at power-up (§12): switchbox N, not armed, memories zero.
pub(super) fn fresh_node(cfg: &Config, k: usize) -> NodeState {
    // Per-slot state only masters keep.
    let m = if cfg.nodes[k].kind.is_master() {
        cfg.slots
    } else {
        0
    };
    NodeState {
        mode: Mode::N,
        up: true,
        failsafe: false,
        rw: false,
        armed: false,
        missed: 0,
        no_cs: 0,
        perr: 0,
        ferr: 0,
        aerr: 0,
        serr: 0,
        hop: None,
        db: vec![0; m],
        db_born: vec![None; m],
        output: 0,
        out_born: None,
        out_before: 0,
        toggle: false,
        last_alive: vec![None; m],
        alive_lost: vec![false; m],
        act_alive: vec![false; m],
        prev_home_alarm: false,
        pending: BTreeSet::new(),
        inflight: None,
        awaiting: false,
        seq: true,
        last_seq: vec![true; m],
        bad_run: [0; 2],
        cf_words: [false; 2],
        quiet: 0,
        elig: false,
        reload: false,
        valid: vec![true; m],
        rejoin: true,
    }
}

/// SplitMix64 finaliser: the model's (and the campaign's) seed mixer.
pub fn splitmix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = x;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A sensor's value in a cycle (docs/scenarios.md, stimulus).
pub fn sensor_value(cfg: &Config, slot: usize, cycle: u32) -> u16 {
    if let Some(v) = cfg
        .values
        .get(&slot)
        .and_then(|m| m.range(..=cycle).next_back())
    {
        return *v.1;
    }
    match cfg.generator {
        Generator::Counter => {
            ((slot as u32).wrapping_mul(0x0101).wrapping_add(cycle) & 0xffff) as u16
        }
        Generator::Random => {
            (splitmix(cfg.seed ^ splitmix(((slot as u64) << 32) | cycle as u64)) & 0xffff) as u16
        }
        Generator::Explicit => 0,
    }
}

impl Ring {
    /// Value the writer of slot `s` produces in cycle `c` (without alarms).
    pub(super) fn source_value(&self, s: usize, c: u32) -> u16 {
        match self.cfg.slot_kind[s] {
            SlotKind::Sensor => sensor_value(&self.cfg, s, c),
            _ => self.nodes[self.cfg.writer[s]].db[s],
        }
    }

    /// A node's processing of the frame at its INPUT. Returns whether the
    /// header was valid.
    pub(super) fn process(&mut self, k: usize, frame: &mut Frame, ev: &mut Vec<Event>) -> bool {
        let HeaderRx::Ok(mut h) = frame.hdr else {
            // Frame ignored (the receiver drops the packet at its rejected
            // header, protocol §9: no perr for its words); forwarded as it is.
            return false;
        };
        if h.clr && !h.fs && self.nodes[k].failsafe {
            // The special master brings the ring out of failsafe (§12).
            self.nodes[k].failsafe = false;
            let c = self.cycle;
            self.event(ev, c, At::Hdr, k, EventKind::FailsafeExit);
        }
        if h.fs && !h.clr {
            self.enter_failsafe(ev, k, At::Hdr, FsCause::Header);
        }
        let wrapped = self.nodes[k].mode != Mode::N;
        self.nodes[k].rw = h.rwc || h.rwp || wrapped;
        self.nodes[k].elig = !self.nodes[k].rw;
        h.hop = (h.hop + 1) & 0xfff;
        h.rwc |= wrapped;
        self.nodes[k].hop = Some(h.hop);
        if self.nodes[k].failsafe {
            h.fs = true;
            frame.hdr = HeaderRx::Ok(h);
            self.count_errors(k, frame);
            // A frame in failsafe updates nothing: the next Alive check
            // has nothing to compare with (§7). Alarm SEQs are still noted.
            self.nodes[k].last_alive.iter_mut().for_each(|a| *a = None);
            self.note_seqs(k, frame);
            return true;
        }
        frame.hdr = HeaderRx::Ok(h);
        if self.nodes[k].reload {
            self.reload(k, frame, ev);
            return true;
        }
        for s in 0..frame.words.len() {
            self.read_slot(k, s, frame.words[s], ev);
            if !self.nodes[k].failsafe {
                self.write_slot(k, s, &mut frame.words[s], ev);
            }
        }
        true
    }

    /// A restarted master's reload frame (§12): it reads the frame like
    /// any master (taking the good words of its own slots too, as long as
    /// it has no value for them: `valid`) and writes nothing.
    pub(super) fn reload(&mut self, k: usize, frame: &Frame, ev: &mut Vec<Event>) {
        for (s, &w) in frame.words.iter().enumerate() {
            self.read_slot(k, s, w, ev);
        }
        self.nodes[k].reload = false;
    }

    /// A stream controller's run of bad words (§9) on node `k`'s receiver
    /// `port` over the words of `frame`: a good word ends it, VOID and
    /// missing words leave it, a rejected header ends the packet. Returns
    /// where the node's outputs lose the frame when the run reaches
    /// [`BAD_WORDS`] in an armed node (a header word, or a slot), which then
    /// reports channel failure at the end of the cycle.
    pub(super) fn count_bad_words(
        &mut self,
        k: usize,
        port: Port,
        frame: &Frame,
        ev: &mut Vec<Event>,
    ) -> Option<At> {
        let p = usize::from(port == Port::Si);
        let mut run = self.nodes[k].bad_run[p];
        let mut hit = None;
        let mut bump = |run: &mut u32, at: At| {
            if *run < BAD_WORDS {
                *run += 1;
                if *run == BAD_WORDS && hit.is_none() {
                    hit = Some(at);
                }
            }
        };
        match frame.hdr {
            HeaderRx::NoCs => return None,
            // Bad words a forwarder marked were damaged further up: they
            // say nothing about this fibre and leave the run as it is (§4).
            HeaderRx::Bad => match (frame.hdr_bad, frame.hdr_marked) {
                ((true, _), false) => bump(&mut run, At::Hdr),
                ((true, _), true) => {}
                ((false, h1), marked) => {
                    run = 0;
                    if h1 && !marked {
                        bump(&mut run, At::Hdr);
                    }
                }
            },
            HeaderRx::Ok(_) => {
                run = 0;
                for (s, w) in frame.words.iter().enumerate() {
                    match w {
                        Slot::Data(_) => run = 0,
                        Slot::Bad(_) => bump(&mut run, At::Slot(s)),
                        Slot::Marked(_) | Slot::Void | Slot::Missing => {}
                    }
                }
            }
        }
        self.nodes[k].bad_run[p] = run;
        let at = hit?;
        if !self.nodes[k].armed {
            return None;
        }
        self.nodes[k].cf_words[p] = true;
        let c = self.cycle;
        self.event(ev, c, at, k, EventKind::BadWords { port });
        Some(at)
    }

    pub(super) fn count_errors(&mut self, k: usize, frame: &Frame) {
        let bad = frame.words.iter().filter(|w| w.is_bad()).count() as u32;
        self.nodes[k].perr += bad;
    }

    /// A master in failsafe reads no slot but keeps each slot's alarm SEQ
    /// (§11), so a repeat of an alarm it saw is not taken for a new one.
    pub(super) fn note_seqs(&mut self, k: usize, frame: &Frame) {
        if !self.cfg.nodes[k].kind.is_master() {
            return;
        }
        let ext = self.cfg.ext;
        let home = self.cfg.nodes[k].address;
        for (s, w) in frame.words.iter().enumerate() {
            if let Slot::Data(d) = w {
                let (r, q) = alarm_of(d, ext);
                if d.alarm && s != home && r != reason::FAILSAFE {
                    self.nodes[k].last_seq[s] = q;
                }
            }
        }
    }

    pub(super) fn read_slot(&mut self, k: usize, s: usize, w: Slot, ev: &mut Vec<Event>) {
        let c = self.cycle;
        let ext = self.cfg.ext;
        let kind = self.cfg.nodes[k].kind;
        if s == self.cfg.nodes[k].address && self.nodes[k].awaiting {
            // The read-back of the alarm sent last time (§11): the slot
            // has one writer, so a good alarm word with the SEQ in flight
            // is that alarm.
            let nd = &mut self.nodes[k];
            nd.awaiting = false;
            if let Slot::Data(d) = w {
                if d.alarm && alarm_of(&d, ext).1 == nd.seq {
                    nd.inflight = None;
                }
            }
        }
        if kind == Kind::Actuator && s == self.cfg.nodes[k].address {
            self.nodes[k].out_before = self.nodes[k].output;
        }
        match w {
            Slot::Bad(_) | Slot::Marked(_) => {
                self.nodes[k].perr += 1;
                if kind.is_master() {
                    self.nodes[k].last_alive[s] = None;
                }
            }
            Slot::Data(d) => {
                if kind == Kind::Actuator && s == self.cfg.nodes[k].address && (ext || !d.alarm) {
                    self.nodes[k].output = d.data;
                    self.nodes[k].out_born = self.cur_born[s];
                }
                if kind.is_master() {
                    let own = self.cfg.writer[s] == k;
                    let (r, q) = alarm_of(&d, ext);
                    // A master never re-delivers its own alarm coming back,
                    // nor a repeat of one it has seen (§11).
                    if d.alarm && s != self.cfg.nodes[k].address {
                        let repeat = r != reason::FAILSAFE && self.nodes[k].last_seq[s] == q;
                        if r != reason::FAILSAFE {
                            self.nodes[k].last_seq[s] = q;
                        }
                        if !repeat {
                            let irq = EventKind::Irq { slot: s, reason: r };
                            self.event(ev, c, At::Slot(s), k, irq);
                            if r == reason::FAILSAFE {
                                self.enter_failsafe(ev, k, At::Slot(s), FsCause::Request);
                            }
                        }
                    }
                    // Its own slots only while it has no value for them
                    // after a restart (§12).
                    if (!own || !self.nodes[k].valid[s]) && (ext || !d.alarm) {
                        self.nodes[k].db[s] = d.data;
                        self.nodes[k].db_born[s] = self.cur_born[s];
                        self.nodes[k].valid[s] = true;
                    }
                    let check = self.cfg.nodes[k].alive_check
                        && !matches!(self.cfg.slot_kind[s], SlotKind::Local if own);
                    if check {
                        if let Some(prev) = self.nodes[k].last_alive[s] {
                            if prev == d.alive {
                                self.nodes[k].aerr += 1;
                                if !self.nodes[k].alive_lost[s] {
                                    self.nodes[k].alive_lost[s] = true;
                                    self.event(
                                        ev,
                                        c,
                                        At::Slot(s),
                                        k,
                                        EventKind::AliveLost { slot: s },
                                    );
                                }
                            } else if self.nodes[k].alive_lost[s] {
                                self.nodes[k].alive_lost[s] = false;
                                self.event(
                                    ev,
                                    c,
                                    At::Slot(s),
                                    k,
                                    EventKind::AliveRestored { slot: s },
                                );
                            }
                        }
                        self.nodes[k].last_alive[s] = Some(d.alive);
                    }
                }
            }
            Slot::Void | Slot::Missing => {
                if kind.is_master() {
                    self.nodes[k].last_alive[s] = None;
                }
            }
        }
    }

    /// Picks the alarm to send in the home slot this cycle, if any, with
    /// its SEQ (§11): a FAILSAFE request first, then a repeat of the alarm
    /// in flight, then the pending alarm of highest priority.
    pub(super) fn take_alarm(&mut self, k: usize, ev: &mut Vec<Event>) -> Option<(Pending, bool)> {
        let nd = &mut self.nodes[k];
        let fs = Pending {
            prio: prio(reason::FAILSAFE),
            reason: reason::FAILSAFE,
        };
        let mut repeat = false;
        let p = if nd.prev_home_alarm || nd.awaiting {
            None
        } else if nd.pending.remove(&fs) {
            Some((fs, false))
        } else if let Some(p) = nd.inflight {
            repeat = true;
            Some((p, nd.seq))
        } else if let Some(p) = nd.pending.pop_first() {
            nd.seq = !nd.seq;
            nd.inflight = Some(p);
            Some((p, nd.seq))
        } else {
            None
        };
        nd.prev_home_alarm = p.is_some();
        nd.awaiting = p.is_some_and(|(p, _)| p.reason != reason::FAILSAFE);
        if let Some((p, _)) = p {
            let c = self.cycle;
            let at = At::Slot(self.cfg.nodes[k].address);
            let tx = EventKind::AlarmTx {
                reason: p.reason,
                repeat,
            };
            self.event(ev, c, at, k, tx);
            if p.reason == reason::FAILSAFE {
                self.enter_failsafe(ev, k, at, FsCause::Request);
            }
        }
        p
    }

    pub(super) fn alarm_word(&self, k: usize, (p, seq): (Pending, bool), data: u16) -> Word {
        if self.cfg.ext {
            Word {
                data,
                alive: self.nodes[k].toggle,
                alarm: true,
                reason: p.reason | (seq as u8) << 3,
            }
        } else {
            Word {
                data: (p.reason as u16) << 12 | (seq as u16) << 11,
                alive: self.nodes[k].toggle,
                alarm: true,
                reason: 0,
            }
        }
    }

    pub(super) fn write_slot(&mut self, k: usize, s: usize, w: &mut Slot, ev: &mut Vec<Event>) {
        if *w == Slot::Missing {
            return;
        }
        let cfgn = &self.cfg.nodes[k];
        let home = s == cfgn.address;
        let c = self.cycle;
        match (cfgn.kind, self.cfg.slot_kind[s]) {
            (Kind::Sensor, SlotKind::Sensor) if home => {
                let v = sensor_value(&self.cfg, s, c);
                *w = Slot::Data(self.fresh_word(k, v, ev, true));
                self.cur_born[s] = Some(c);
            }
            (Kind::Master | Kind::SpecialMaster, SlotKind::Local) if self.cfg.writer[s] == k => {
                let v = self.nodes[k].db[s];
                if self.nodes[k].valid[s] {
                    *w = Slot::Data(self.fresh_word(k, v, ev, home));
                    self.cur_born[s] = Some(c);
                } else if home {
                    // No value yet after a restart (§12): an alarm still goes.
                    if let Some(p) = self.take_alarm(k, ev) {
                        *w = Slot::Data(self.alarm_word(k, p, v));
                    }
                }
            }
            (Kind::Master | Kind::SpecialMaster, SlotKind::Act { .. })
                if self.cfg.writer[s] == k && !self.nodes[k].valid[s] => {}
            (Kind::Master | Kind::SpecialMaster, SlotKind::Act { .. })
                if self.cfg.writer[s] == k =>
            {
                // Data goes in, the actuator's Alive passes through. A VOID
                // (slot not returned last cycle) is regenerated with the
                // Alive the actuator would toggle to, so a dead actuator's
                // Alive still stops toggling and every master notices.
                match w {
                    Slot::Data(d) => {
                        self.nodes[k].act_alive[s] = d.alive;
                        if self.cfg.ext || !d.alarm {
                            d.data = self.nodes[k].db[s];
                            self.cur_born[s] = Some(c);
                        }
                    }
                    // Data replaced from the first group on; still bad.
                    Slot::Bad(Lead::Data) | Slot::Marked(Lead::Data) => {}
                    Slot::Void | Slot::Bad(Lead::S) | Slot::Marked(Lead::S) => {
                        let alive = !self.nodes[k].act_alive[s];
                        self.nodes[k].act_alive[s] = alive;
                        *w = Slot::Data(Word {
                            data: self.nodes[k].db[s],
                            alive,
                            alarm: false,
                            reason: 0,
                        });
                        self.cur_born[s] = Some(c);
                    }
                    _ => {}
                }
            }
            (Kind::Actuator, SlotKind::Act { actuator }) if actuator == k => {
                // The actuator decides from the word's first group (protocol
                // §4, §7): an alarm of its own replaces the word; a bad word
                // passes on bad (its data has already been forwarded; in the
                // extended variant an alarm word's too, §6); anything else
                // leaves as {output register, its Alive}. An alarm word
                // carries the register as it was before this word (the
                // extended variant's data; the basic one has none).
                let v = self.nodes[k].output;
                let passes_bad = match *w {
                    Slot::Bad(l) | Slot::Marked(l) => {
                        matches!(l, Lead::Data | Lead::Other) || (l == Lead::Alarm && self.cfg.ext)
                    }
                    _ => false,
                };
                if let Some(p) = self.take_alarm(k, ev) {
                    let before = self.nodes[k].out_before;
                    *w = Slot::Data(self.alarm_word(k, p, before));
                } else if !passes_bad {
                    *w = Slot::Data(Word {
                        data: v,
                        alive: self.nodes[k].toggle,
                        alarm: false,
                        reason: 0,
                    });
                    self.cur_born[s] = self.nodes[k].out_born;
                }
            }
            _ => {}
        }
    }

    pub(super) fn fresh_word(&mut self, k: usize, v: u16, ev: &mut Vec<Event>, home: bool) -> Word {
        if home {
            if let Some(p) = self.take_alarm(k, ev) {
                return self.alarm_word(k, p, v);
            }
        }
        Word {
            data: v,
            alive: self.nodes[k].toggle,
            alarm: false,
            reason: 0,
        }
    }
}
