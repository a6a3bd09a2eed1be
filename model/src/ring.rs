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
mod rtx;
pub use age::ages;

/// Switchbox mode: the rows of the paper's Table 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    /// Row 1, all ports ok: INPUT=PI, OUTPUT=PO, BSR=SI, BSS=SO.
    N,
    /// Row 2, SO or PI defective: INPUT=SI, OUTPUT=PO, BSR=PI, BSS=SO.
    Wu,
    /// Row 3, SI or PO defective: INPUT=PI, OUTPUT=SO, BSR=SI, BSS=PO.
    Wd,
}

impl Mode {
    /// Code used in RECONFIG alarms and traces.
    pub fn code(self) -> u16 {
        match self {
            Mode::N => 0,
            Mode::Wu => 1,
            Mode::Wd => 2,
        }
    }
    /// Name in traces.
    pub fn name(self) -> &'static str {
        match self {
            Mode::N => "N",
            Mode::Wu => "WU",
            Mode::Wd => "WD",
        }
    }
}

/// Physical ports of a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Port {
    /// Primary in.
    Pi,
    /// Primary out.
    Po,
    /// Secondary in.
    Si,
    /// Secondary out.
    So,
}

impl Port {
    /// Name as in the paper: PI, PO, SI, SO.
    pub fn name(self) -> &'static str {
        match self {
            Port::Pi => "PI",
            Port::Po => "PO",
            Port::Si => "SI",
            Port::So => "SO",
        }
    }
}

/// Fibre entering node `k` of an `n`-node ring at port `p` (PI or SI).
fn fibre_into(n: usize, k: usize, p: Port) -> Fibre {
    match p {
        Port::Pi => Fibre::P((k + n - 1) % n),
        Port::Si => Fibre::S(k),
        _ => unreachable!("outputs have no incoming fibre"),
    }
}

/// Table 1: (INPUT, OUTPUT, BSR, BSS) of a mode.
pub fn table1(m: Mode) -> (Port, Port, Port, Port) {
    match m {
        Mode::N => (Port::Pi, Port::Po, Port::Si, Port::So),
        Mode::Wu => (Port::Si, Port::Po, Port::Pi, Port::So),
        Mode::Wd => (Port::Pi, Port::So, Port::Si, Port::Po),
    }
}

/// What a fibre carried in one slot position of a frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slot {
    /// A word with good parity.
    Data(Word),
    /// The VOID word (five S groups).
    Void,
    /// A word that failed parity or held a non-data group; what its first
    /// group showed (cut-through nodes decide from it).
    Bad(Lead),
    /// A bad word that a forwarder marked (its last group T, protocol §4):
    /// damaged before the fibre it is read on.
    Marked(Lead),
    /// Nothing: the line went dark before this slot.
    Missing,
}

impl Slot {
    /// Bad, marked or not.
    pub fn is_bad(&self) -> bool {
        matches!(self, Slot::Bad(_) | Slot::Marked(_))
    }
}

/// Decoded header fields (docs/protocol.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Header {
    /// Failsafe seen upstream.
    pub fs: bool,
    /// Some node on the path this cycle is wrapped.
    pub rwc: bool,
    /// The ring was wrapped in the previous cycle (set by the special master).
    pub rwp: bool,
    /// Cycle counter, 3 bits.
    pub cyc: u8,
    /// Processing nodes passed so far.
    pub hop: u16,
    /// CLR, H0's ALIVE bit: leave failsafe (protocol §12).
    pub clr: bool,
}

impl Header {
    /// Header word 0 for a frame of `slots` slots.
    pub fn h0(&self, slots: usize) -> Word {
        Word {
            data: ((self.fs as u16) << 13)
                | ((self.rwc as u16) << 12)
                | ((slots as u16 - 1) & 0xfff),
            alive: self.clr,
            ..Word::default()
        }
    }
    /// Header word 1.
    pub fn h1(&self) -> Word {
        Word {
            data: ((self.rwp as u16) << 15) | (((self.cyc & 7) as u16) << 12) | (self.hop & 0xfff),
            ..Word::default()
        }
    }
    /// Decodes two header words; None when the type or slot count is wrong.
    pub fn decode(h0: &Word, h1: &Word, slots: usize) -> Option<Header> {
        if h0.data >> 14 != 0 || (h0.data & 0xfff) as usize != slots - 1 || h0.alarm || h1.alarm {
            return None;
        }
        Some(Header {
            fs: h0.data & (1 << 13) != 0,
            rwc: h0.data & (1 << 12) != 0,
            rwp: h1.data & (1 << 15) != 0,
            cyc: ((h1.data >> 12) & 7) as u8,
            hop: h1.data & 0xfff,
            clr: h0.alive,
        })
    }
}

/// Header as a receiver sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeaderRx {
    /// Both header words decoded.
    Ok(Header),
    /// Start delimiter found, header word bad: frame ignored.
    Bad,
    /// Start delimiter not found: frame invisible.
    NoCs,
}

/// A data frame on a fibre.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Frame {
    /// Header.
    pub hdr: HeaderRx,
    /// With a bad header: which of its words a receiver reads as bad
    /// (H0, H1; a header whose words are good but whose fields are not is
    /// rejected too). A stream controller counts them (§9).
    pub hdr_bad: (bool, bool),
    /// The bad header words were marked by a forwarder (§4): damaged
    /// before this fibre, not counted in its receiver's run.
    pub hdr_marked: bool,
    /// One entry per slot.
    pub words: Vec<Slot>,
}

/// What one fibre carried during one cycle.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Carry {
    /// No light (broken fibre or dead sender).
    Silent,
    /// Idle groups only.
    Idle,
    /// The cycle's data frame (possibly passed through).
    Data(Frame),
    /// The secondary test frame; `ok` = still intact.
    Sec {
        /// Intact.
        ok: bool,
    },
    /// Link test packets from a wrapped node; `ack` = it hears its partner's TST.
    Tst {
        /// Acknowledge bit.
        ack: bool,
    },
}

/// Why a node entered failsafe.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FsCause {
    /// A stream controller failed while the ring was known to be wrapped.
    SecondFault,
    /// A header with FS=1 arrived.
    Header,
    /// No start delimiter at INPUT for [`CS_TIMEOUT_CYCLES`] cycles (more
    /// with backup clock bases, [`Config::cs_timeout_cycles`]).
    Timeout,
    /// A FAILSAFE alarm (user request) was sent or received.
    Request,
    /// The special master's 4th CLR frame came back with FS = 1.
    ClearFailed,
}

/// Cycles without a start delimiter at INPUT that put a node into
/// failsafe (protocol §12, rule 4), in a ring without backup clock bases.
pub const CS_TIMEOUT_CYCLES: u32 = 3;
/// Frames back whole in a row after which the special master leaves
/// failsafe (protocol §12).
pub const WHOLE_RETURNS: u32 = 2;
/// CLR frames the special master sends before it gives up and fails safe
/// again (protocol §12).
pub const CLR_TRIES: u32 = 4;

impl fmt::Display for FsCause {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FsCause::SecondFault => "second-fault",
            FsCause::Header => "header",
            FsCause::Timeout => "timeout",
            FsCause::Request => "request",
            FsCause::ClearFailed => "clear-failed",
        })
    }
}

/// Alarm reason codes (docs/protocol.md §11).
pub mod reason {
    /// User interrupt 1.
    pub const IRQ1: u8 = 1;
    /// User interrupt 2.
    pub const IRQ2: u8 = 2;
    /// Failsafe request.
    pub const FAILSAFE: u8 = 3;
    /// Switchbox reconfiguration to mode N (reintegrated).
    pub const RECONFIG_N: u8 = 4;
    /// Switchbox reconfiguration to mode WU (Table 1 row 2).
    pub const RECONFIG_WU: u8 = 5;
    /// Switchbox reconfiguration to mode WD (Table 1 row 3).
    pub const RECONFIG_WD: u8 = 6;
    /// The RECONFIG reason for a new mode.
    pub fn reconfig(m: super::Mode) -> u8 {
        RECONFIG_N + m.code() as u8
    }
}

/// Where in a cycle an event happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum At {
    /// At the start delimiter / header.
    Hdr,
    /// In a slot.
    Slot(usize),
    /// After the frame (end-of-cycle resolution).
    End,
}

impl fmt::Display for At {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            At::Hdr => write!(f, "hdr"),
            At::Slot(s) => write!(f, "s{s}"),
            At::End => write!(f, "end"),
        }
    }
}

/// Something that happened.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EventKind {
    /// Switchbox change, effective from the next cycle.
    Mode {
        /// Old mode.
        from: Mode,
        /// New mode.
        to: Mode,
    },
    /// Failsafe entered.
    Failsafe(FsCause),
    /// Failsafe left (the special master at its frame start, every other
    /// node at a CLR header; protocol §12).
    FailsafeExit,
    /// The special master's host gave the failsafe clear command.
    FsClear,
    /// The node put an alarm word in its home slot.
    AlarmTx {
        /// Reason code.
        reason: u8,
        /// A repeat of the alarm in flight (its read-back failed, §11).
        repeat: bool,
    },
    /// A master received an alarm and raised it to its host.
    Irq {
        /// Slot the alarm came in (the sender's address).
        slot: usize,
        /// Reason code.
        reason: u8,
    },
    /// A master saw the Alive bit of a slot stop toggling.
    AliveLost {
        /// Slot.
        slot: usize,
    },
    /// It toggles again.
    AliveRestored {
        /// Slot.
        slot: usize,
    },
    /// The special master's secondary test frame did not return intact.
    SecFail,
    /// A backup became the clock base: the special master (or the backup
    /// before it) was dead (§8).
    Takeover {
        /// Its backup priority.
        prio: u8,
    },
    /// A stream controller saw [`BAD_WORDS`] bad words in a row on this
    /// receiver (PI or SI), at the event's slot: a run (§9), a transient
    /// that wraps a node in a ring not known to be wrapped (soft wrap).
    BadWords {
        /// The receiver.
        port: Port,
    },
    /// The clock base sent a retransmission packet (§8) with `sent` of the
    /// `requested` damaged critical slots (0 when none fitted).
    Rtx {
        /// Requests in the packet.
        sent: usize,
        /// Critical slots that came back damaged.
        requested: usize,
    },
}

/// Consecutive bad words that make a run (protocol §9).
pub const BAD_WORDS: u32 = 8;

/// An event stamped with cycle, position and node.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Event {
    /// Cycle.
    pub cycle: u32,
    /// Position in the cycle.
    pub at: At,
    /// Node.
    pub node: usize,
    /// What.
    pub kind: EventKind,
}

/// A pending alarm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Pending {
    prio: u8,
    reason: u8,
}

/// An alarm word's reason and SEQ (protocol §11): basic variant
/// `D[15:12]`, `D[11]`; extended variant `N1 = {SEQ, reason[2:0]}`.
fn alarm_of(d: &Word, ext: bool) -> (u8, bool) {
    if ext {
        (d.reason & 7, d.reason & 8 != 0)
    } else {
        ((d.data >> 12) as u8, d.data & 0x800 != 0)
    }
}

fn prio(reason: u8) -> u8 {
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
    missed: u32,
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
    /// The node's Alive flip-flop (value used this cycle).
    pub toggle: bool,
    last_alive: Vec<Option<bool>>,
    alive_lost: Vec<bool>,
    act_alive: Vec<bool>,
    prev_home_alarm: bool,
    pending: BTreeSet<Pending>,
    /// The alarm in flight: sent, not yet read back (§11).
    inflight: Option<Pending>,
    /// An alarm went out in the last home-slot write; the next home-slot
    /// read reads it back.
    awaiting: bool,
    /// SEQ of the last alarm sent (a new one gets the other value).
    seq: bool,
    /// Masters: per slot, the SEQ of the last good alarm word read there.
    last_seq: Vec<bool>,
    /// Consecutive bad words per receiver (PI, SI), across packets (§9).
    bad_run: [u32; 2],
    /// This cycle: a run of bad words reached [`BAD_WORDS`] on PI, SI.
    cf_words: [bool; 2],
    /// Cycles in a row whose INPUT carried no packet (frame, frame body,
    /// SEC or TST): a backup's election timer (§8).
    pub quiet: u32,
    /// At its last good header the node did not know the ring was wrapped
    /// (§8: a backup may then take over as from a first fault).
    elig: bool,
    /// A restarted master before its reload frame (§12): it reads every
    /// slot, its own too, and writes nothing.
    reload: bool,
    /// Masters: per slot, the data memory holds a value to write: always,
    /// but after a restart (§12) only once the reload frame brought a good
    /// word or the host wrote it (its LOCAL and ACT slots are written only
    /// then; the reload leaves what the host wrote).
    valid: Vec<bool>,
    /// From power-up (a restart is one) until it is whole (§12: mode N,
    /// armed, no TST on INPUT or BSR): when its upstream link reintegrates
    /// and its downstream neighbour is wrapped towards it, it turns to WD
    /// instead of N.
    rejoin: bool,
}

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

/// The faults of one cycle that act inside its packets.
struct CycleFaults {
    /// Fibres that break before a slot (fibre, slot).
    cut_fibre: Vec<(Fibre, usize)>,
    /// Nodes that die before a slot (node, slot).
    cut_node: Vec<(usize, usize)>,
    /// Bit flips (fibre, target, bit).
    flips: Vec<(Fibre, FlipTarget, u32)>,
    /// Bursts of garbage.
    bursts: Vec<Fault>,
}

/// What the special master keeps to bring the ring out of failsafe
/// (protocol §12).
#[derive(Debug, Clone, Default)]
struct SmExit {
    /// HOP of the last good header back with FS = 0 outside failsafe.
    hop_ref: Option<u16>,
    /// Frames back whole in a row, in failsafe.
    whole: u32,
    /// CLR frames sent since it left failsafe (0: not clearing).
    clr_sent: u32,
    /// The failsafe began with (or saw) a FAILSAFE request: leave only on
    /// the host's clear command.
    request: bool,
    /// The host gave the clear command.
    host_clear: bool,
}

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

    /// Runs one cycle and returns what happened.
    pub fn step(&mut self) -> CycleRecord {
        let c = self.cycle;
        let n = self.n();
        let s_count = self.cfg.slots;
        let mut ev = Vec::new();
        for nd in &mut self.nodes {
            nd.cf_words = [false; 2];
        }

        // 1. Host writes and interrupt requests land before the cycle.
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
            self.event(&mut ev, c, At::Hdr, sm, EventKind::FsClear);
        }
        // 2. Faults of this cycle.
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
        let produced: Vec<u16> = (0..s_count).map(|s| self.source_value(s, c)).collect();

        let mut fibres: Vec<Carry> = Vec::with_capacity(2 * n);
        for k in 0..n {
            fibres.push(if self.lit(Fibre::P(k)) {
                Carry::Idle
            } else {
                Carry::Silent
            });
        }
        for k in 0..n {
            fibres.push(if self.lit(Fibre::S(k)) {
                Carry::Idle
            } else {
                Carry::Silent
            });
        }
        let mut got_frame = vec![false; n];
        let mut path = vec![];
        let cf = CycleFaults {
            cut_fibre,
            cut_node,
            flips,
            bursts,
        };

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
        for k in 0..n {
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

        // 6. Frame supervision and the CS timeout.
        let cs_timeout = self.cfg.cs_timeout_cycles();
        let mut packet_in = vec![false; n];
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
            let jk = jk || rtx.as_ref().is_some_and(|x| x.jk.contains(&k));
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
                    self.enter_failsafe(&mut ev, k, At::End, FsCause::Timeout);
                }
            }
        }
        // Faults that take effect at the end of the cycle.
        for (f, _) in &cf.cut_fibre {
            self.broken.insert(*f);
        }
        for (k, _) in &cf.cut_node {
            self.nodes[*k].up = false;
        }
        for f in &faults {
            if let Fault::Repair { fibre, .. } = *f {
                self.broken.remove(&fibre);
            }
        }
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

    /// The clock base that sends this cycle's frame (§8): the special
    /// master, or the backup that took over from it. When the clock base is
    /// dead, the eligible backup of lowest priority p whose INPUT has been
    /// quiet for p cycles takes over now; `None`: no frame this cycle.
    fn clock_base(&mut self, ev: &mut Vec<Event>) -> Option<usize> {
        if self.nodes[self.base].up {
            return Some(self.base);
        }
        let (k, prio) = self.cfg.backups().into_iter().find(|&(k, p)| {
            let nd = &self.nodes[k];
            nd.up && nd.armed && nd.elig && !nd.failsafe && nd.quiet >= u32::from(p)
        })?;
        self.base = k;
        // What a clock base learns from returning frames starts afresh; the
        // return store is empty, as after a frame that did not come back.
        self.store = vec![Slot::Void; self.cfg.slots];
        self.store_born = vec![None; self.cfg.slots];
        self.emitted = vec![Slot::Void; self.cfg.slots];
        self.returned_rwc = false;
        self.exit = SmExit::default();
        let c = self.cycle;
        self.event(ev, c, At::Hdr, k, EventKind::Takeover { prio });
        Some(k)
    }

    /// Section 3 of a cycle: clock base `sm` sends the DATA frame, every
    /// node on its path processes or passes it, and it comes back (or not)
    /// into the return store. Returns whether `sm` got a good header back.
    #[allow(clippy::too_many_arguments)]
    fn data_frame(
        &mut self,
        sm: usize,
        f: &CycleFaults,
        fibres: &mut [Carry],
        got_frame: &mut [bool],
        path: &mut Vec<usize>,
        ev: &mut Vec<Event>,
    ) -> bool {
        let c = self.cycle;
        let n = self.n();
        let s_count = self.cfg.slots;
        let clr = self.sm_frame_start(ev);
        let hdr = Header {
            fs: self.nodes[sm].failsafe,
            rwc: self.nodes[sm].mode != Mode::N,
            rwp: self.returned_rwc,
            cyc: (c & 7) as u8,
            hop: 0,
            clr,
        };
        let mut frame = Frame {
            hdr: HeaderRx::Ok(hdr),
            hdr_bad: (false, false),
            hdr_marked: false,
            words: self.store.clone(),
        };
        self.cur_born = self.store_born.clone();
        if !self.nodes[sm].failsafe {
            for s in 0..s_count {
                self.write_slot(sm, s, &mut frame.words[s], ev);
            }
        }
        // The clock base dies while it sends (a kill before slot s).
        let dies = f.cut_node.iter().find(|(nd, _)| *nd == sm).map(|x| x.1);
        if let Some(s) = dies {
            truncate(&mut frame, s);
        }
        let dies = dies.is_some();
        self.emitted = frame.words.clone();
        path.push(sm);
        let mut fib = self.out_fibre(sm, table1(self.nodes[sm].mode).1);
        let mut returned = None;
        for _hop in 0..4 * n + 4 {
            if !self.lit(fib) {
                break;
            }
            if let Some(&(_, s)) = f.cut_fibre.iter().find(|(x, _)| *x == fib) {
                truncate(&mut frame, s);
            }
            self.apply_flips(&mut frame, fib, &f.flips);
            for b in &f.bursts {
                if let Fault::Burst { fibre, .. } = *b {
                    if fibre == fib {
                        self.apply_burst(&mut frame, *b);
                    }
                }
            }
            let fi = self.fibre_index(fib);
            fibres[fi] = Carry::Data(frame.clone());
            let (k, port) = self.dst(fib);
            if !self.nodes[k].up {
                break;
            }
            let (inp, out, bsr, bss) = table1(self.nodes[k].mode);
            // A run of bad words on the receiver: channel failure at
            // that word (§9). In mode N the node wraps there (§10), so
            // its outputs carry nothing of this frame from that word on.
            let cf_at = if port == inp || (port == bsr && self.nodes[k].mode == Mode::N) {
                self.count_bad_words(k, port, &frame, ev)
            } else {
                None
            };
            let cut_at = cf_at.filter(|_| self.nodes[k].mode == Mode::N);
            if port == inp && self.lose_next.contains(&k) {
                // A WU end that unwrapped at this frame's J K on PI.
                frame.hdr = HeaderRx::NoCs;
            }
            if port == inp {
                if k == sm {
                    if let Some(at) = cut_at {
                        cut(&mut frame, at);
                    }
                    returned = Some(frame.clone());
                    break;
                }
                path.push(k);
                got_frame[k] = self.process(k, &mut frame, ev);
                mark(&mut frame);
                if let Some(&(_, s)) = f.cut_node.iter().find(|(nd, _)| *nd == k) {
                    truncate(&mut frame, s);
                }
                if let Some(at) = cut_at {
                    cut(&mut frame, at);
                }
                fib = self.out_fibre(k, out);
            } else if port == bsr && self.nodes[k].mode == Mode::N {
                if let Some(&(_, s)) = f.cut_node.iter().find(|(nd, _)| *nd == k) {
                    truncate(&mut frame, s);
                }
                if let Some(at) = cut_at {
                    cut(&mut frame, at);
                }
                fib = self.out_fibre(k, bss);
            } else {
                break;
            }
        }
        if dies {
            returned = None;
        }
        self.sm_return(returned, ev)
    }

    /// Section 4 of a cycle: the secondary test frame of clock base `sm`
    /// in mode N (§8). Returns the fibres where it went ahead of a DATA
    /// frame, with its `ok`.
    fn sec_frame(
        &mut self,
        sm: usize,
        f: &CycleFaults,
        fibres: &mut [Carry],
        ev: &mut Vec<Event>,
    ) -> Vec<(usize, bool)> {
        let c = self.cycle;
        let n = self.n();
        let mut sec_with_data = vec![];
        let mut ok = true;
        let mut lost = false;
        let mut back = false;
        let mut fib = self.out_fibre(sm, Port::So);
        for _ in 0..2 * n + 2 {
            if !self.lit(fib) || f.cut_fibre.iter().any(|(x, _)| *x == fib) {
                break;
            }
            for &(ff, t, _) in &f.flips {
                if ff == fib {
                    match t {
                        FlipTarget::Cs => lost = true,
                        FlipTarget::H0 | FlipTarget::H1 => ok = false,
                        FlipTarget::Slot(_) | FlipTarget::RtxHead | FlipTarget::Rtx(_) => {}
                    }
                }
            }
            if lost {
                break;
            }
            let fi = self.fibre_index(fib);
            let (k, port) = self.dst(fib);
            if ok && self.nodes[k].up {
                // Its good header words end a run of bad words (§9).
                self.nodes[k].bad_run[usize::from(port == Port::Si)] = 0;
            }
            // A fibre that also carries the (wrapped) DATA frame shows
            // the frame; the SEC that went ahead of it is listed apart.
            if matches!(fibres[fi], Carry::Data(_)) {
                sec_with_data.push((fi, ok));
            } else {
                fibres[fi] = Carry::Sec { ok };
            }
            if !self.nodes[k].up || f.cut_node.iter().any(|(nd, _)| *nd == k) {
                break;
            }
            let (inp, out, bsr, bss) = table1(self.nodes[k].mode);
            if port == bsr && self.nodes[k].mode == Mode::N {
                if k == sm {
                    back = true;
                    break;
                }
                fib = self.out_fibre(k, bss);
            } else if port == inp && k != sm {
                // A forwarder passes a SEC on its INPUT unchanged (a
                // wrapped node's INPUT is a secondary fibre, §5).
                fib = self.out_fibre(k, out);
            } else {
                break;
            }
        }
        if !(back && ok) {
            self.nodes[sm].serr += 1;
            self.event(ev, c, At::End, sm, EventKind::SecFail);
        }
        sec_with_data
    }

    /// Value the writer of slot `s` produces in cycle `c` (without alarms).
    fn source_value(&self, s: usize, c: u32) -> u16 {
        match self.cfg.slot_kind[s] {
            SlotKind::Sensor => sensor_value(&self.cfg, s, c),
            _ => self.nodes[self.cfg.writer[s]].db[s],
        }
    }

    fn apply_flips(&self, frame: &mut Frame, fib: Fibre, flips: &[(Fibre, FlipTarget, u32)]) {
        let ext = self.cfg.ext;
        for &(f, t, bit) in flips {
            if f != fib {
                continue;
            }
            match t {
                FlipTarget::Cs => frame.hdr = HeaderRx::NoCs,
                FlipTarget::H0 | FlipTarget::H1 => {
                    if let HeaderRx::Ok(h) = frame.hdr {
                        let (w, other) = if t == FlipTarget::H0 {
                            (h.h0(self.cfg.slots), h.h1())
                        } else {
                            (h.h1(), h.h0(self.cfg.slots))
                        };
                        // A flip of a header word's last bit also hits the
                        // next word's first bit.
                        let next = if t == FlipTarget::H0 {
                            Some(other)
                        } else {
                            match frame.words.first() {
                                Some(Slot::Data(w)) => Some(*w),
                                _ => None,
                            }
                        };
                        let (r, r2) = line::flip_and_decode(&w, next.as_ref(), ext, bit as usize);
                        if t == FlipTarget::H1 {
                            if let (Some(r2), Some(first)) = (r2, frame.words.first_mut()) {
                                *first = rx_slot(r2);
                            }
                        }
                        let (h0, h1) = match (t, r, r2) {
                            (FlipTarget::H0, Rx::Ok(a), Some(Rx::Ok(b))) => (a, b),
                            (FlipTarget::H1, Rx::Ok(b), _) => (other, b),
                            _ => {
                                frame.hdr = HeaderRx::Bad;
                                // H0 bad (the receiver stops there), or H0
                                // good and H1 bad.
                                frame.hdr_bad =
                                    (t == FlipTarget::H0 && !matches!(r, Rx::Ok(_)), true);
                                continue;
                            }
                        };
                        frame.hdr = match Header::decode(&h0, &h1, self.cfg.slots) {
                            Some(h) => HeaderRx::Ok(h),
                            None => HeaderRx::Bad,
                        };
                    }
                }
                FlipTarget::Slot(s) => flip_word(&mut frame.words, s, bit, ext),
                FlipTarget::RtxHead | FlipTarget::Rtx(_) => {}
            }
        }
    }

    /// A burst of garbage on the fibre (protocol §4, scenario `kind =
    /// "burst"`): the line's code bits in the burst become
    /// [`line::garbage`], the level returns after it, and every word it
    /// touched is decoded again, exactly. A word the model knows only as
    /// bad or missing stays as it is where the burst leaves its last group
    /// alone, and is bad where it does not (its code is not known), and so
    /// is every word after it that the burst reaches.
    fn apply_burst(&self, frame: &mut Frame, burst: Fault) {
        let Fault::Burst {
            target,
            bit,
            len,
            pattern,
            ..
        } = burst
        else {
            return;
        };
        let HeaderRx::Ok(h) = frame.hdr else {
            // No receiver reads past a rejected header, nor a frame whose
            // delimiter it missed.
            return;
        };
        let ext = self.cfg.ext;
        let w = line::word_bits(ext) as usize;
        let slots = self.cfg.slots;
        // Code bits of H0, H1 and the slots (None: not known).
        let mut words: Vec<Option<Vec<u8>>> = vec![
            Some(line::word_code_bits(&h.h0(slots), ext)),
            Some(line::word_code_bits(&h.h1(), ext)),
        ];
        words.extend(frame.words.iter().map(|x| match x {
            Slot::Data(d) => Some(line::word_code_bits(d, ext)),
            Slot::Void => Some(line::void_code_bits(ext)),
            _ => None,
        }));
        let start = match target {
            FlipTarget::H0 => 0,
            FlipTarget::H1 => w,
            FlipTarget::Slot(s) => (2 + s) * w,
            FlipTarget::Cs | FlipTarget::RtxHead | FlipTarget::Rtx(_) => return,
        } + bit as usize;
        let len = len as usize;
        let g = line::garbage(pattern, len);
        // The level's XOR mask m: c' = c ^ m[t] ^ m[t-1]; in the burst c' is
        // the garbage, so m[t] = m[t-1] ^ c ^ g; after it m = 0.
        let mut m = Some(0u8);
        let mut touched = vec![false; words.len()];
        let mut lost = vec![false; words.len()];
        let end = (start + len + 1).min(words.len() * w);
        for t in start..end {
            let (wi, bi) = (t / w, t % w);
            touched[wi] = true;
            let in_burst = t < start + len;
            match (&mut words[wi], m) {
                (Some(code), Some(mv)) => {
                    let c = code[bi];
                    code[bi] = if in_burst { g[t - start] } else { c ^ mv };
                    m = in_burst.then_some(mv ^ c ^ code[bi]);
                }
                // After a word whose code is not known, the level is not
                // known either.
                (Some(_), None) => lost[wi] = true,
                (None, _) => m = None,
            }
        }
        let rx = |wi: usize| -> Option<line::Rx> {
            match &words[wi] {
                Some(_) if lost[wi] => Some(line::Rx::Bad(Lead::Other)),
                Some(c) => Some(line::decode_word(c, ext)),
                // Its last group untouched: it stays what it was.
                None if start + len <= (wi + 1) * w - 5 => None,
                None => Some(line::Rx::Bad(Lead::Other)),
            }
        };
        for (wi, _) in touched.iter().enumerate().skip(2).filter(|(_, t)| **t) {
            if let Some(r) = rx(wi) {
                frame.words[wi - 2] = rx_slot(r);
            }
        }
        if touched[0] || touched[1] {
            let (a, b) = (rx(0), rx(1));
            frame.hdr_marked = false;
            frame.hdr = match (&a, &b) {
                (Some(line::Rx::Ok(h0)), Some(line::Rx::Ok(h1))) => {
                    match Header::decode(h0, h1, slots) {
                        Some(h) => HeaderRx::Ok(h),
                        None => HeaderRx::Bad,
                    }
                }
                _ => HeaderRx::Bad,
            };
            let bad = |r: &Option<line::Rx>| !matches!(r, Some(line::Rx::Ok(_)));
            frame.hdr_bad = (bad(&a), bad(&b));
        }
    }

    /// A node's processing of the frame at its INPUT. Returns whether the
    /// header was valid.
    fn process(&mut self, k: usize, frame: &mut Frame, ev: &mut Vec<Event>) -> bool {
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
    fn reload(&mut self, k: usize, frame: &Frame, ev: &mut Vec<Event>) {
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
    fn count_bad_words(
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

    fn count_errors(&mut self, k: usize, frame: &Frame) {
        let bad = frame.words.iter().filter(|w| w.is_bad()).count() as u32;
        self.nodes[k].perr += bad;
    }

    /// The special master receives the returning frame.
    /// The special master at its frame start (§12): leaves failsafe after
    /// [`WHOLE_RETURNS`] frames came back whole (and the host's clear
    /// command where it is needed); returns whether this frame carries CLR.
    fn sm_frame_start(&mut self, ev: &mut Vec<Event>) -> bool {
        let sm = self.base;
        let c = self.cycle;
        if self.nodes[sm].failsafe {
            let host = self.cfg.nodes[sm].fs_exit_host || self.exit.request;
            if self.exit.whole >= WHOLE_RETURNS && (!host || self.exit.host_clear) {
                self.nodes[sm].failsafe = false;
                self.event(ev, c, At::Hdr, sm, EventKind::FailsafeExit);
                self.exit = SmExit {
                    hop_ref: self.exit.hop_ref,
                    clr_sent: 1,
                    ..SmExit::default()
                };
            }
        } else if self.exit.clr_sent >= CLR_TRIES {
            // The last CLR frame came back with FS = 1 (or not at all):
            // some node keeps failing safe.
            self.exit.clr_sent = 0;
            self.enter_failsafe(ev, sm, At::Hdr, FsCause::ClearFailed);
        } else if self.exit.clr_sent > 0 {
            self.exit.clr_sent += 1;
        }
        self.exit.clr_sent > 0
    }

    /// The special master's failsafe bookkeeping for a good header that
    /// came back (§12): `hop_ref`, frames back whole, the CLR frames, and
    /// rule 3.
    fn exit_return(&mut self, h: &Header, ev: &mut Vec<Event>) {
        let sm = self.base;
        let was_fs = self.nodes[sm].failsafe;
        if !was_fs && !h.fs {
            self.exit.hop_ref = Some(h.hop);
        }
        if was_fs && h.hop >= self.exit.hop_ref.unwrap_or(0) {
            self.exit.whole += 1;
        } else {
            self.exit.whole = 0;
        }
        if self.exit.clr_sent > 0 && h.clr && !h.fs {
            // Every node on the path has left failsafe.
            self.exit.clr_sent = 0;
        }
        if h.fs && !h.clr {
            self.enter_failsafe(ev, sm, At::Hdr, FsCause::Header);
        }
    }

    fn sm_return(&mut self, returned: Option<Frame>, ev: &mut Vec<Event>) -> bool {
        let sm = self.base;
        let s_count = self.cfg.slots;
        self.damaged.clear();
        let Some(frame) = returned else {
            self.store = vec![Slot::Void; s_count];
            self.store_born = vec![None; s_count];
            self.nodes[sm].hop = None;
            self.exit.whole = 0;
            return false;
        };
        // A FAILSAFE request that comes back: the ring leaves that failsafe
        // only on the host's clear command (§12).
        let ext = self.cfg.ext;
        if frame.words.iter().any(|w| match w {
            Slot::Data(d) if d.alarm => alarm_of(d, ext).0 == reason::FAILSAFE,
            _ => false,
        }) {
            self.exit.request = true;
        }
        let HeaderRx::Ok(h) = frame.hdr else {
            // The frame came back, its header (or start delimiter) damaged:
            // every node behind the damage ignored it, so every critical
            // slot is requested (§8).
            self.damaged = self.cfg.critical_slots();
            self.store = vec![Slot::Void; s_count];
            self.store_born = vec![None; s_count];
            self.nodes[sm].hop = None;
            self.exit.whole = 0;
            return false;
        };
        self.returned_rwc = h.rwc;
        self.nodes[sm].hop = Some(h.hop);
        self.nodes[sm].rw = h.rwc || h.rwp || self.nodes[sm].mode != Mode::N;
        self.exit_return(&h, ev);
        let failsafe = self.nodes[sm].failsafe;
        if failsafe {
            self.count_errors(sm, &frame);
            // Nothing read: no Alive check against this frame (§7).
            self.nodes[sm].last_alive.iter_mut().for_each(|a| *a = None);
            self.note_seqs(sm, &frame);
        }
        for s in 0..s_count {
            let w = frame.words[s];
            if !failsafe {
                self.read_slot(sm, s, w, ev);
            }
            if self.cfg.critical[s] && matches!(w, Slot::Bad(_) | Slot::Marked(_) | Slot::Missing) {
                self.damaged.push(s);
            }
            self.store_born[s] = match w {
                Slot::Data(_) => self.cur_born[s],
                _ => None,
            };
            self.store[s] = match w {
                Slot::Data(d) => {
                    // An alarm word is retransmitted once: if it comes back
                    // unchanged from a retransmission, its owner did not
                    // replace it, so it is not sent a third time.
                    if d.alarm && self.emitted[s] == w {
                        Slot::Void
                    } else {
                        w
                    }
                }
                _ => Slot::Void,
            };
        }
        true
    }

    /// A master in failsafe reads no slot but keeps each slot's alarm SEQ
    /// (§11), so a repeat of an alarm it saw is not taken for a new one.
    fn note_seqs(&mut self, k: usize, frame: &Frame) {
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

    fn read_slot(&mut self, k: usize, s: usize, w: Slot, ev: &mut Vec<Event>) {
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
    fn take_alarm(&mut self, k: usize, ev: &mut Vec<Event>) -> Option<(Pending, bool)> {
        let ext = self.cfg.ext;
        let nd = &mut self.nodes[k];
        let fs = Pending {
            prio: prio(reason::FAILSAFE),
            reason: reason::FAILSAFE,
        };
        let mut repeat = false;
        let p = if (!ext && nd.prev_home_alarm) || nd.awaiting {
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
        nd.prev_home_alarm = p.is_some() && !ext;
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

    fn alarm_word(&self, k: usize, (p, seq): (Pending, bool), data: u16) -> Word {
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

    fn write_slot(&mut self, k: usize, s: usize, w: &mut Slot, ev: &mut Vec<Event>) {
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
                // passes on bad (its data has already been forwarded);
                // anything else leaves as {output register, its Alive}.
                let v = self.nodes[k].output;
                if let Some(p) = self.take_alarm(k, ev) {
                    *w = Slot::Data(self.alarm_word(k, p, v));
                } else if !matches!(
                    *w,
                    Slot::Bad(Lead::Data | Lead::Other) | Slot::Marked(Lead::Data | Lead::Other)
                ) {
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

    fn fresh_word(&mut self, k: usize, v: u16, ev: &mut Vec<Event>, home: bool) -> Word {
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

    /// End-of-cycle resolution of every stream controller into switchbox
    /// changes, failsafe entries and reintegrations (protocol §9, §10, §12).
    fn resolve(&mut self, ev: &mut Vec<Event>, seen: &Inputs) {
        let n = self.n();
        let c = self.cycle;
        // A node that unwrapped at the end of the last cycle does not take
        // a TST where DATA is expected for a failure yet (§12: its partner
        // may still be sending it).
        let grace: Vec<bool> = self
            .unwrapped_at
            .iter()
            .map(|u| u.is_some_and(|u| u + 1 == c))
            .collect();
        let start: Vec<Mode> = self.nodes.iter().map(|x| x.mode).collect();
        let rw: Vec<bool> = self
            .nodes
            .iter()
            .map(|x| x.rw || x.mode != Mode::N)
            .collect();
        let mut changed = true;
        let mut guard = 0;
        while changed && guard < 4 * n + 4 {
            changed = false;
            guard += 1;
            for k in 0..n {
                if !self.nodes[k].up {
                    continue;
                }
                let mode = self.nodes[k].mode;
                let (inp, _, bsr, _) = table1(mode);
                let fi = self.in_fibre(k, inp);
                let fb = self.in_fibre(k, bsr);
                let words = |p: Port| self.nodes[k].cf_words[usize::from(p == Port::Si)];
                // Structural: loss of signal, or a TST where DATA is
                // expected (the neighbour wrapped); a run of bad words is a
                // transient and wraps only a ring not known wrapped (§9, §12).
                let tst_fails = mode == Mode::N && !grace[k];
                let hard_in = !self.lit(fi) || (tst_fails && self.carries_tst(fi));
                let hard_bsr = !self.lit(fb) || (tst_fails && self.carries_tst(fb));
                let soft = mode == Mode::N && !rw[k];
                let armed = self.nodes[k].armed;
                // Stream controllers act once the node is armed, but for a
                // TST where DATA is expected on INPUT (§12, a restarted node
                // between wrapped neighbours).
                // (Without the grace after unwrapping: the RTL keeps this
                // decision free of the grace counter, protocol §12.)
                let in_fail = if armed {
                    hard_in || (soft && words(inp))
                } else {
                    mode == Mode::N && self.lit(fi) && self.carries_tst(fi)
                };
                let bsr_fail = armed && (hard_bsr || (soft && words(bsr)));
                let new = match mode {
                    Mode::N if in_fail => Some(Mode::Wu),
                    Mode::N if bsr_fail => Some(Mode::Wd),
                    _ => None,
                };
                let second = match mode {
                    Mode::N => (!self.lit(fi) && !self.lit(fb)) || ((hard_in || hard_bsr) && rw[k]),
                    _ => !self.lit(fi),
                };
                if second && armed && start[k] == mode {
                    self.enter_failsafe(ev, k, At::End, FsCause::SecondFault);
                }
                if let Some(m) = new {
                    self.nodes[k].mode = m;
                    changed = true;
                }
            }
        }
        self.reintegrate(seen);
        // A rejoining node is whole again once it is in mode N, armed, and
        // no TST arrives on its INPUT or BSR.
        for (k, &was) in start.iter().enumerate() {
            let (inp, _, bsr, _) = table1(self.nodes[k].mode);
            let tst =
                self.carries_tst(self.in_fibre(k, inp)) || self.carries_tst(self.in_fibre(k, bsr));
            let nd = &mut self.nodes[k];
            if nd.rejoin && nd.armed && was == Mode::N && nd.mode == Mode::N && !tst {
                nd.rejoin = false;
            }
        }

        for (k, &from) in start.iter().enumerate() {
            let to = self.nodes[k].mode;
            if from != to {
                self.event(ev, c, At::End, k, EventKind::Mode { from, to });
                self.unwrapped_at[k] = (to == Mode::N).then_some(c);
                // A WU end's handshake belongs to its stay in WU.
                let link = (k + n - 1) % n;
                if from == Mode::Wu {
                    self.acked[link] = false;
                }
                let nd = &mut self.nodes[k];
                if (from == Mode::Wu) != (to == Mode::Wu) {
                    // INPUT and BSR move to other lines: a run of bad
                    // words belongs to the old ones (§9).
                    nd.bad_run = [0; 2];
                }
                nd.pending
                    .retain(|p| prio(p.reason) != prio(reason::RECONFIG_N));
                // A RECONFIG in flight is replaced too (only the newest mode
                // is kept, §11).
                if nd
                    .inflight
                    .is_some_and(|p| prio(p.reason) == prio(reason::RECONFIG_N))
                {
                    nd.inflight = None;
                }
                let r = reason::reconfig(to);
                nd.pending.insert(Pending {
                    prio: prio(r),
                    reason: r,
                });
            }
        }
    }
}

/// What each node's INPUT carried in the cycle (step 6), for the
/// end-of-cycle decisions.
struct Inputs<'a> {
    /// A packet's J K other than a TST (a frame, a SEC): rule 4's timer.
    packet: &'a [bool],
    /// A frame with its J K.
    frame: &'a [bool],
    /// The TST of an upstream neighbour wrapped towards the node.
    tst: &'a [bool],
}

impl Ring {
    /// Per node, whether what its INPUT carried this cycle is `what`.
    fn inputs_carry(&self, fibres: &[Carry], what: impl Fn(&Carry) -> bool) -> Vec<bool> {
        (0..self.n())
            .map(|k| {
                let inp = self.in_fibre(k, table1(self.nodes[k].mode).0);
                what(&fibres[self.fibre_index(inp)])
            })
            .collect()
    }

    /// Reintegration (§12) at the end of the cycle, link by link (link k
    /// joins node k, its WD end, to node k + 1, its WU end). Two nodes
    /// wrapped towards each other over a link whose fibres both carry
    /// light hear each other's TST, however they got there (a repair, a
    /// soft wrap, a node that re-wrapped after unwrapping); the handshake
    /// is done by the end of the next cycle (≤ 4 TST periods ≤ P). Then:
    /// - the WD end unwraps at a frame boundary: a packet (a frame, or the
    ///   TST of an upstream neighbour wrapped towards it: a node cut off
    ///   between two wraps) ended on its INPUT, or, the special master,
    ///   its period tick; in the loop without the special master of a
    ///   split ring no packet comes, and it waits;
    /// - the WU end unwraps at the next frame's J K on its BSR (PI), so its
    ///   INPUT misses that frame (`lose_next`): with the WD end if a frame
    ///   follows through it, else (it unwrapped on a TST) as soon as one
    ///   does — its handshake is done, and it keeps waiting in WU; in
    ///   failsafe, at the first frame on its BSR, handshake or not.
    fn reintegrate(&mut self, seen: &Inputs) {
        let n = self.n();
        let c = self.cycle;
        let sm = self.base;
        let was_lost = std::mem::take(&mut self.lose_next);
        // A node forwards a frame on PO next cycle: it is not wrapped
        // towards PO (not WD), a frame reaches its INPUT (it had one, or it
        // just lost one to its own unwrapping) and it does not lose it.
        let forwards = |r: &Ring, k: usize| {
            r.nodes[k].up
                && r.nodes[k].mode != Mode::Wd
                && (k == sm || seen.frame[k] || was_lost.contains(&k))
        };
        for a in 0..n {
            let b = (a + 1) % n;
            let lit = self.lit(Fibre::P(a)) && self.lit(Fibre::S(a));
            let pair = lit && self.nodes[a].mode == Mode::Wd && self.nodes[b].mode == Mode::Wu;
            if !pair {
                self.pair_since[a] = None;
            }
            if !lit || self.nodes[b].mode != Mode::Wu {
                self.acked[a] = false;
            }
            if pair {
                let since = *self.pair_since[a].get_or_insert(c);
                if since < c {
                    self.acked[a] = true;
                    let boundary = seen.packet[a] || seen.tst[a] || a == sm;
                    if boundary {
                        // The WD end unwraps; its frame, if one follows,
                        // takes the WU end along.
                        self.nodes[a].mode = Mode::N;
                        self.pair_since[a] = None;
                    }
                }
            }
            // In failsafe a frame on BSR is as good as the ACK (the upstream
            // neighbour forwards the ring's frames: it is not wrapped
            // towards this node; the special master's downstream
            // neighbour, cut off with it, hears no TST from it).
            let up_ok = self.acked[a]
                || (self.nodes[b].failsafe
                    && self.nodes[b].mode == Mode::Wu
                    && self.lit(Fibre::P(a)));
            if up_ok && self.nodes[a].mode != Mode::Wd && forwards(self, a) {
                // A rejoining node whose downstream neighbour is wrapped
                // towards it (its TST on SI) turns round to it instead
                // (WU → WD), so the ring stays closed (§12).
                let next = self.nodes[b].rejoin && self.carries_tst(Fibre::S(b));
                self.nodes[b].mode = if next { Mode::Wd } else { Mode::N };
                self.acked[a] = false;
                self.lose_next.push(b);
            }
        }
    }
}

/// A node at power-up (§12): switchbox N, not armed, memories zero.
fn fresh_node(cfg: &Config, k: usize) -> NodeState {
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

/// One line bit of word `s` of a packet's words inverted (protocol §4): the
/// word is decoded again bit-exactly; an error in its last bit also hits
/// the next word's first. A word already bad or missing stays as it is.
pub(crate) fn flip_word(words: &mut [Slot], s: usize, bit: u32, ext: bool) {
    let code = |w: &Slot| match w {
        Slot::Data(d) => Some(line::word_code_bits(d, ext)),
        Slot::Void => Some(line::void_code_bits(ext)),
        _ => None,
    };
    let Some(this) = words.get(s).and_then(code) else {
        return;
    };
    let next = words.get(s + 1).and_then(code);
    let (r, r2) = line::flip_code_and_decode(&this, next.as_deref(), ext, bit as usize);
    words[s] = rx_slot(r);
    if let Some(r2) = r2 {
        words[s + 1] = rx_slot(r2);
    }
}

/// A forwarder marks what arrived bad (§4): the words of a frame whose
/// header it processed, and the first bad word of a rejected header (after
/// it the forwarder passes the packet unchanged).
fn mark(frame: &mut Frame) {
    match frame.hdr {
        HeaderRx::Ok(_) => {
            for w in frame.words.iter_mut() {
                if let Slot::Bad(l) = *w {
                    *w = Slot::Marked(l);
                }
            }
        }
        HeaderRx::Bad => frame.hdr_marked |= frame.hdr_bad.0 || frame.hdr_bad.1,
        HeaderRx::NoCs => {}
    }
}

/// A node wraps at `at` inside `frame` (§10): from there its output carries
/// nothing of it; at a header word, not even the start delimiter.
fn cut(frame: &mut Frame, at: At) {
    match at {
        At::Slot(s) => truncate(frame, s),
        _ => {
            frame.hdr = HeaderRx::NoCs;
            truncate(frame, 0);
        }
    }
}

fn truncate(frame: &mut Frame, from: usize) {
    for w in frame.words.iter_mut().skip(from) {
        *w = Slot::Missing;
    }
}

fn rx_slot(r: Rx) -> Slot {
    match r {
        Rx::Ok(w) => Slot::Data(w),
        Rx::Void => Slot::Void,
        Rx::Bad(l) => Slot::Bad(l),
        Rx::Marked(l) => Slot::Marked(l),
    }
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
