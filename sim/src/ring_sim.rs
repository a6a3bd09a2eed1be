//! Runs a scenario's whole ring as Verilog in Verilator ([`merkur_rtl::harness::ring_top`])
//! and compares it with the reference model's cycle records (the same records
//! the golden trace in `tb-data/` is written from): every word every fibre
//! carried in every cycle, the headers, and at the end every node's state
//! (mode, failsafe, error counters, interrupts received, actuator outputs,
//! masters' data memories read over Wishbone), and every alarm each master
//! delivered to its host (its alarm queue, drained over Wishbone during the
//! run as a host would, [`alarms`]).
//!
//! The driver does what a scenario's environment does, at the moment the
//! model says: sensor values per cycle, host writes and user requests
//! "before cycle c" (after frame c−1 has passed the node, before frame c).

use crate::verilator::Model;
use crate::wishbone::Wishbone;
use crate::Rng;
use merkur_model::config::{Config, Fault, Fibre, FlipTarget};
use merkur_model::line::{Lead, Word};
use merkur_model::ring::{self, table1, Carry, CycleRecord, EventKind, HeaderRx, Mode, Port, Slot};
use merkur_model::scenario::{IrqLine, Kind};
use merkur_rtl::harness::ring_top::{
    cap_slots, cfg as field, ring_verilog_with, status as st, INC_NOMINAL, TICKS_PER_BIT,
};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::node::mdb::{ST_FS_CLEAR, ST_FS_HOST, ST_JOIN, ST_RUN, ST_STOP, WB_CFG, WB_STATUS};
use std::path::Path;
use std::time::{Duration, Instant};

pub mod alarms;
mod drive;

/// One difference between RTL and model.
#[derive(Debug, Clone)]
pub struct Mismatch {
    /// Cycle (the last cycle for end-of-run state).
    pub cycle: u32,
    /// Where: a fibre (`P3`), a node (`node 5`).
    pub place: String,
    /// What: `slot 4`, `H1`, `perr`, `db[7]` …
    pub what: String,
    /// The model's value.
    pub expected: String,
    /// The RTL's value.
    pub got: String,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "cycle {} {} {}: expected {}, got {}",
            self.cycle, self.place, self.what, self.expected, self.got
        )
    }
}

/// One node's row of the summary table.
#[derive(Debug, Clone)]
pub struct NodeRow {
    /// Node index.
    pub node: usize,
    /// Kind name.
    pub kind: &'static str,
    /// Mode name (RTL).
    pub mode: &'static str,
    /// Failsafe (RTL).
    pub failsafe: bool,
    /// Bad words at INPUT (RTL).
    pub perr: u64,
    /// Alarms delivered to the host (RTL, masters; every reason).
    pub irqs: u64,
    /// Mismatches found at this node.
    pub mismatches: usize,
}

/// The result of one run.
#[derive(Debug)]
pub struct Report {
    /// Cycles compared.
    pub cycles: u32,
    /// Words (slots and headers) compared.
    pub words: u64,
    /// Every mismatch, in the order found.
    pub mismatches: Vec<Mismatch>,
    /// Simulation ticks (`TICKS_PER_BIT` per bit time).
    pub ticks: u64,
    /// Wall time of the simulation (without the Verilator build).
    pub wall: Duration,
    /// Wall time of the Verilator build (0 when cached).
    pub build: Duration,
    /// Measured cycle period at the special master, bit times.
    pub period_bits: f64,
    /// Forwarding delay of every node but the special master, bit times:
    /// when the last frame's H1 was decoded on the node's PO fibre minus on
    /// its PI fibre (identical monitors on one clock; each reading is
    /// quantised to the monitors' clock, half a bit time).
    pub fwd_delay_bits: Vec<f64>,
    /// Per-node summary.
    pub rows: Vec<NodeRow>,
    /// The run's ports per tick, when [`Options::record`] asked for it.
    pub recording: Option<crate::verilator::Recording>,
    /// Per fault of the scenario (in its order), the tick it was injected.
    pub fault_ticks: Vec<Option<u64>>,
    /// Switchbox changes seen while faults were injected: (node, tick, new
    /// mode code); polled every 2 bit times.
    pub mode_ticks: Vec<(usize, u64, u64)>,
    /// Per node, the tick it was first seen in failsafe (same polling).
    pub fs_ticks: Vec<Option<u64>>,
    /// Per cycle, whether its frame came back whole to the special master
    /// (a good H1 and every slot, on PI or SI), as the RTL's monitors saw it.
    pub returned_whole: Vec<bool>,
    /// Per master (node index, in ring order): the ring's shape at the end
    /// as it reconstructs it from its alarm queue, the nodes whose last
    /// RECONFIG announced a wrap (protocol §11).
    pub shapes: Vec<(usize, Shape)>,
    /// Per cycle, the tick at which the driver saw its frame start (a
    /// cycle without a frame, before a backup's takeover: the next one's).
    pub starts: Vec<u64>,
}

/// A ring's shape as a master sees it: the wrapped nodes and their modes.
pub type Shape = Vec<(usize, Mode)>;

/// A run's progress report: called with (cycles started, cycles).
#[derive(Clone)]
pub struct Progress(pub std::sync::Arc<dyn Fn(u32, u32) + Send + Sync>);

impl std::fmt::Debug for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Progress(..)")
    }
}

/// Options of a run.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Write an FST waveform here.
    pub wave: Option<std::path::PathBuf>,
    /// Seed of the clock phases.
    pub seed: u64,
    /// Told (cycles started, cycles) as the frames go out and at the end.
    pub progress: Option<Progress>,
    /// Record every tick's ports for a replay in another simulator
    /// ([`Report::recording`]).
    pub record: bool,
    /// Print to stderr, per cycle and DATA-carrying fibre, every word the
    /// RTL's monitor decoded (the model's beside it in brackets where they
    /// differ, before the window rules), and every fault injection and
    /// switchbox change with its tick: the run as a table to read next to
    /// the golden trace.
    pub dump: bool,
}

/// What the RTL ring does not model yet, as a message naming the field.
pub fn unsupported(cfg: &Config) -> Option<String> {
    if cfg
        .faults
        .iter()
        .any(|(_, f)| matches!(f, Fault::Flip { .. } | Fault::Burst { .. }))
    {
        let recs = ring::run(cfg);
        let n = cfg.nodes.len();
        for (i, &(c, f)) in cfg.faults.iter().enumerate() {
            if let Some(why) = flip_unsupported(&recs, n, c, f) {
                return Some(format!("fault[{i}] (cycle {c}, {f}): {why}"));
            }
        }
    }
    if cfg.period >= 1 << 16 {
        return Some(format!(
            "frame.period_bits = {}: the RTL period register has 16 bits",
            cfg.period
        ));
    }
    None
}

/// The harness arms a flip in the idle gap before its packet and finds the
/// packet by its J K ([`merkur_rtl::harness::ring_top`]): the fibre must carry one
/// packet in the cycle, after an idle gap the driver can see.
pub fn flip_unsupported(recs: &[CycleRecord], n: usize, c: u32, f: Fault) -> Option<String> {
    let (fibre, target, bit) = match f {
        Fault::Flip { fibre, target, bit } => (fibre, target, bit),
        Fault::Burst {
            fibre, target, bit, ..
        } => (fibre, target, bit),
        _ => return None,
    };
    if matches!(target, FlipTarget::RtxHead | FlipTarget::Rtx(_)) {
        let fi = fibre.index(n);
        let on = recs[c as usize]
            .rtx
            .as_ref()
            .is_some_and(|x| x.fibres.contains(&fi));
        if !on {
            return Some(format!(
                "fibre = {fibre}: the cycle's retransmission packet does not travel it (by the model); the RTL harness places a flip in a packet it carries"
            ));
        }
        if target == FlipTarget::RtxHead && bit < 2 {
            return Some(format!(
                "bit = {bit}: the RTL harness finds J K by its first 0 code bit (bit 2) and can flip delimiter bits 2..9 only"
            ));
        }
        return None;
    }
    if target == FlipTarget::Cs && bit < 2 {
        return Some(format!(
            "bit = {bit}: the RTL harness finds J K by its first 0 code bit (bit 2) and can flip delimiter bits 2..9 only (a single error anywhere in J K destroys it, protocol §3)"
        ));
    }
    let fi = fibre.index(n);
    let rec = &recs[c as usize];
    let one = match rec.fibres[fi] {
        Carry::Data(_) => c == 0 || matches!(recs[c as usize - 1].fibres[fi], Carry::Data(_)),
        Carry::Sec { .. } => true,
        _ => false,
    };
    if !one || rec.sec_with_data.iter().any(|&(x, _)| x == fi) {
        return Some(format!(
            "fibre = {fibre}: in this cycle the fibre does not carry one frame or SEC after another (a wrap in progress); the RTL harness cannot place the flip"
        ));
    }
    // Garbage can make a good header word of another value (2 parity bits:
    // about 1 word in 128); the harness's monitors file a frame's words
    // under the CYC of its H1, so a changed CYC would file it wrongly.
    if let (Fault::Burst { .. }, Carry::Data(fr)) = (f, &rec.fibres[fi]) {
        if let HeaderRx::Ok(h) = fr.hdr {
            if h.cyc as u32 != c & 7 {
                return Some(format!(
                    "the garbage makes H1 another good word with CYC = {}; the RTL harness files a frame's words under the CYC of its H1",
                    h.cyc
                ));
            }
        }
    }
    None
}

/// Line bit `bit` of a fault's target, counted from the packet's first line
/// bit (J K 10 bits, then two header words and the slots, `w` = 25 or 30
/// line bits each, protocol §3, §6).
fn packet_bit(target: FlipTarget, bit: u32, w: u64) -> u64 {
    let word = match target {
        FlipTarget::Cs => 0,
        FlipTarget::H0 => 10,
        FlipTarget::H1 => 10 + w,
        FlipTarget::Slot(s) => 10 + w * (2 + s as u64),
        // The retransmission packet (protocol §8): J K, H0, H1, then its
        // request words.
        FlipTarget::RtxHead => 0,
        FlipTarget::Rtx(j) => 10 + w * (2 + j as u64),
    };
    word + bit as u64
}

/// When the driver writes a fault's configuration.
enum When {
    /// Before slot s (None: the delimiter) of the cycle, timed on these
    /// fibres' monitors (breaks, repairs, deaths).
    Slot(Vec<usize>, Option<usize>),
    /// A flip of the DATA frame on this fibre: armed when the previous
    /// frame has ended there.
    FrameEnded(usize),
    /// A flip of the SEC on this fibre: armed when this many SECs passed.
    Secs(usize, u64),
    /// A flip of the cycle's retransmission packet on this fibre: armed
    /// when the cycle's frame has ended there.
    RtxNext(usize),
    /// When the clock base has started the cycle's frame (a restart).
    Started,
}

struct Ring {
    m: Model,
    clk: usize,
    cfg_we: usize,
    cfg_sel: usize,
    cfg_field: usize,
    cfg_val: usize,
    rd_en: usize,
    rd_sel: usize,
    rd_field: usize,
    rd: usize,
    cap_en: usize,
    cap_f: usize,
    cap_i: usize,
    cap: usize,
    wb_node: usize,
    wb: Wishbone,
    ticks: u64,
    /// Per fibre and capture buffer, the H1 entry last compared: a fibre
    /// without frames keeps it, and CYC (3 bits) repeats every 8 cycles.
    h1_seen: Vec<[u64; 4]>,
    /// Capture entries per cycle and fibre.
    capn: usize,
    /// Per cycle, the frames sent before it ([`frames_before`]).
    ep: Vec<u32>,
    /// See [`Report::returned_whole`].
    whole: Vec<bool>,
    /// Per slot, whether its Alive bit runs inverted against the model's
    /// since the last recovery window (None: not yet seen after it).
    alive_inv: Vec<Option<bool>>,
    /// [`Options::dump`].
    dump: bool,
}

impl Ring {
    fn tick(&mut self) {
        self.m.tick(self.clk);
        self.ticks += 1;
    }
    fn cfg(&mut self, sel: usize, field: u32, val: u64) {
        self.m.set(self.cfg_we, 1);
        self.m.set(self.cfg_sel, sel as u64);
        self.m.set(self.cfg_field, field as u64);
        self.m.set(self.cfg_val, val);
        self.tick();
        self.m.set(self.cfg_we, 0);
    }
    /// A status read: the ring top's read multiplexer works only while its
    /// enable is high (so the simulation does not evaluate it every tick).
    fn rd(&mut self, sel: usize, field: u32) -> u64 {
        self.m.set(self.rd_en, 1);
        self.m.set(self.rd_sel, sel as u64);
        self.m.set(self.rd_field, field as u64);
        self.m.eval();
        let v = self.m.get(self.rd);
        self.m.set(self.rd_en, 0);
        v
    }
    fn cap(&mut self, fibre: usize, idx: usize) -> u64 {
        self.m.set(self.cap_en, 1);
        self.m.set(self.cap_f, fibre as u64);
        self.m.set(self.cap_i, idx as u64);
        self.m.eval();
        let v = self.m.get(self.cap);
        self.m.set(self.cap_en, 0);
        v
    }
    /// One Wishbone B4 classic transfer with master `node` (on its own
    /// clock; the ring runs on meanwhile).
    fn wb(&mut self, node: usize, adr: u16, write: Option<u16>) -> Result<u16, String> {
        self.m.set(self.wb_node, node as u64);
        let clk = self.clk;
        let (v, ticks) = self
            .wb
            .transfer(&mut self.m, &mut |m| m.tick(clk), adr, write)
            .map_err(|e| format!("node {node}: {e}"))?;
        self.ticks += ticks as u64;
        Ok(v)
    }
}

/// The trace token of a slot (docs/traces.md), as the golden trace prints it.
fn slot_token(s: &Slot) -> String {
    let mut o = String::new();
    merkur_model::trace::word_token(&mut o, s);
    o
}

/// Whether a captured entry was written in cycle `cyc`: its CYC matches
/// and the ring's clock bases had sent 0 to 4 frames more than `ep` (the
/// frames sent before cycle `cyc`, [`frames_before`]) when it was written
/// (not an entry left from 8 cycles before; `ring_top`).
fn fresh(e: u64, cyc: u32, ep: u32) -> bool {
    (e >> 20) & 7 == (cyc & 7) as u64 && ((e >> 23) as u32).wrapping_sub(ep) & 0xff <= 4
}

/// Per cycle, the frames the model's clock bases sent before it (a cycle
/// without a clock base sends none, protocol §8), with the total last.
fn frames_before(recs: &[CycleRecord]) -> Vec<u32> {
    let mut v = vec![0];
    for rec in recs {
        let last = *v.last().expect("one entry");
        v.push(last + !rec.path.is_empty() as u32);
    }
    v
}

/// A captured entry of cycle `cyc` as the slot the monitor saw.
fn cap_slot(e: u64, cyc: u32, ep: u32) -> Slot {
    if !fresh(e, cyc, ep) {
        return Slot::Missing;
    }
    match (e >> 18) & 3 {
        1 => Slot::Data(Word {
            data: (e & 0xffff) as u16,
            alive: (e >> 16) & 1 == 1,
            alarm: (e >> 17) & 1 == 1,
            // The reason nibble of extended-alarm words (0 otherwise).
            reason: ((e >> 31) & 0xf) as u8,
        }),
        3 => Slot::Void,
        // A bad word's ALARM field tells whether it was marked (ring_top).
        _ if (e >> 17) & 1 == 1 => Slot::Marked(Lead::Other),
        _ => Slot::Bad(Lead::Other),
    }
}

fn fibre_name(f: usize, n: usize) -> String {
    Fibre::from_index(f, n).to_string()
}

/// The RTL node kind of each node of `cfg`: a backup master carries the
/// special master's logic (protocol §8), so in the RTL it is a
/// `merkur_special_master` with a priority.
pub fn rtl_kinds(cfg: &Config) -> Vec<Kind> {
    cfg.nodes
        .iter()
        .map(|x| match x.backup {
            Some(_) => Kind::SpecialMaster,
            None => x.kind,
        })
        .collect()
}

/// Builds (or finds in the cache) the Verilator model that [`run`] uses
/// for `cfg` (with tracing when `wave`), so that a caller can show the
/// build as a step of its own; [`run`] then finds it in the process.
pub fn build_model(cfg: &Config, wave: bool) -> Result<(), String> {
    let traced = wave || crate::verilator::wave_env().is_some();
    crate::verilator::build_library_top(&ring_verilog_of(cfg), "merkur_ring", traced).map(|_| ())
}

/// The ring Verilog that runs `cfg` ([`ring_verilog_once`] of its RTL
/// kinds, with power-on resets where it restarts nodes).
pub fn ring_verilog_of(cfg: &Config) -> std::sync::Arc<String> {
    let restarts = cfg
        .faults
        .iter()
        .any(|(_, f)| matches!(f, Fault::Restart { .. }));
    let format = if cfg.ext {
        WordFormat::ExtendedAlarm
    } else {
        WordFormat::Basic
    };
    ring_verilog_once(&rtl_kinds(cfg), cfg.slots, restarts, format)
}

/// The ring Verilog of `kinds` with `slots` slots of words in `format`
/// (and power-on resets with `restarts`), generated once per process: a
/// campaign builds each ring's model and then runs hundreds of cases of
/// it, and generating ring100's text takes about 0.1 s.
pub fn ring_verilog_once(
    kinds: &[Kind],
    slots: usize,
    restarts: bool,
    format: WordFormat,
) -> std::sync::Arc<String> {
    use std::collections::HashMap;
    use std::sync::{Arc, Mutex, OnceLock};
    type Done = HashMap<(String, usize, bool, WordFormat), Arc<String>>;
    static DONE: OnceLock<Mutex<Done>> = OnceLock::new();
    let done = DONE.get_or_init(|| Mutex::new(HashMap::new()));
    let key = (format!("{kinds:?}"), slots, restarts, format);
    if let Some(v) = done.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return v.clone();
    }
    let v = Arc::new(ring_verilog_with(kinds, slots, restarts, format));
    done.lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(key, v.clone());
    v
}

/// Runs `cfg` (whose model records are `recs`) as RTL and compares: the
/// phases are in `sim/src/ring_sim/drive.rs`.
pub fn run(cfg: &Config, recs: &[CycleRecord], opts: &Options) -> Result<Report, String> {
    if let Some(why) = unsupported(cfg) {
        return Err(why);
    }
    let mut d = drive::Drive::open(cfg, recs, opts)?;
    d.start()?;
    d.run_loop()?;
    d.finish()
}

/// A packed status field (`st::MODES`, `st::FRAME_V`): one read gives
/// `per` nodes' or fibres' values of `bits` bits each; each group is read
/// at most once per use (a read is a whole evaluation of the model, and the
/// harness polls every node and fibre).
struct Packed {
    field: u32,
    per: usize,
    bits: usize,
    groups: Vec<Option<u64>>,
}

impl Packed {
    fn new(field: u32, per: usize, bits: usize) -> Self {
        Packed {
            field,
            per,
            bits,
            groups: vec![],
        }
    }

    /// Node or fibre `i`'s value.
    fn get(&mut self, r: &mut Ring, i: usize) -> u64 {
        let g = i / self.per;
        if self.groups.len() <= g {
            self.groups.resize(g + 1, None);
        }
        let v = match self.groups[g] {
            Some(v) => v,
            None => {
                let v = r.rd(g, self.field);
                self.groups[g] = Some(v);
                v
            }
        };
        v >> (self.bits * (i % self.per)) & ((1 << self.bits) - 1)
    }
}

/// Every node's error counters (perr, ferr, aerr, serr) read just after a
/// frame ended on its INPUT (the fibre the model's mode says), per cycle: the
/// driver compares their per-cycle increments with the model's outside the
/// recovery windows (protocol §13).
struct Snapshots {
    /// Per node: the next cycle to take, and when a frame's end was seen,
    /// the tick to read at (the node's decoder trails the monitor's).
    next: Vec<u32>,
    due: Vec<Option<(u32, u64)>>,
    got: Vec<std::collections::BTreeMap<u32, [u64; 4]>>,
    /// Per cycle with a retransmission packet (protocol §8): the fibres it
    /// travels and the ticks from the frame's H1 until it has passed
    /// (its bad words count in the cycle).
    pub(crate) rtx_tail: Vec<Option<(Vec<usize>, u64)>>,
}

const COUNTERS: [(u32, &str); 4] = [
    (st::PERR, "perr"),
    (st::FERR, "ferr"),
    (st::AERR, "aerr"),
    (st::SERR, "serr"),
];

impl Snapshots {
    fn new(n: usize, cfg: &Config, recs: &[CycleRecord]) -> Self {
        let rtx = merkur_rtl::top::synth_top::RtxStatic::of(cfg);
        let head = 10 + 2 * cfg.word_bits() as u64;
        let rtx_tail = recs
            .iter()
            .map(|rec| {
                let x = rec.rtx.as_ref()?;
                let at = if rec.nodes[rec.base].rw {
                    rtx.at_wrapped
                } else {
                    rtx.at
                } as u64;
                let bits = (at + x.bits as u64 + 8).saturating_sub(head);
                Some((x.fibres.clone(), bits * TICKS_PER_BIT as u64))
            })
            .collect();
        Snapshots {
            next: vec![0; n],
            due: vec![None; n],
            got: vec![Default::default(); n],
            rtx_tail,
        }
    }

    /// The fibre on node k's INPUT in cycle c, by the model.
    fn input(recs: &[CycleRecord], n: usize, k: usize, c: u32) -> usize {
        let mode = match c {
            0 => Mode::N,
            _ => recs[c as usize - 1].nodes[k].mode,
        };
        match table1(mode).0 {
            Port::Si => n + k,
            _ => (k + n - 1) % n,
        }
    }

    fn poll(&mut self, r: &mut Ring, recs: &[CycleRecord], starts: &[u64], sent: u32) {
        let n = self.next.len();
        // The fibres' FRAME fields, read packed and only where needed.
        let mut frame_v = Packed::new(st::FRAME_V, st::FRAMES_PER_READ, 4);
        for k in 0..n {
            if let Some((c, at)) = self.due[k] {
                if r.ticks >= at {
                    let v = COUNTERS.map(|(fd, _)| r.rd(k, fd));
                    self.got[k].insert(c, v);
                    self.due[k] = None;
                    self.next[k] = c + 1;
                }
                continue;
            }
            let c = self.next[k];
            if c >= sent || c as usize >= recs.len() {
                continue;
            }
            if sent > c + 2 {
                // Frame c never ended at this node (a fault): no snapshot.
                self.next[k] = c + 1;
                continue;
            }
            let f = Self::input(recs, n, k, c);
            let fr = frame_v.get(r, f);
            if fr >> 3 & 1 != 0 || fr & 7 != (c & 7) as u64 {
                continue;
            }
            // Frame c has ended on the fibre, if its H1 came after the
            // frame's start (read only now: a read costs a pass).
            let th1 = r.rd(f, st::TH1);
            if th1.wrapping_sub(starts[c as usize]) & 0xffff_ffff < 1 << 31 {
                // 8 bit times: the node has counted the last word; the next
                // frame's first slot is at least 80 bit times away. With a
                // retransmission packet on the fibre, 8 bit times after it.
                let mut at = r.ticks + 8 * TICKS_PER_BIT as u64;
                if let Some((fs, tail)) = &self.rtx_tail[c as usize] {
                    if fs.contains(&f) {
                        let h1 = starts[c as usize]
                            + (th1.wrapping_sub(starts[c as usize]) & 0xffff_ffff);
                        at = at.max(h1 + tail);
                    }
                }
                self.due[k] = Some((c, at));
            }
        }
    }

    /// Per-cycle increments outside the windows against the model's.
    fn compare(
        &self,
        cfg: &Config,
        recs: &[CycleRecord],
        in_window: impl Fn(u32) -> bool,
        mism: &mut Vec<Mismatch>,
    ) {
        for (k, got) in self.got.iter().enumerate() {
            let kind = cfg.nodes[k].kind;
            for (&c, v) in got.range(1..) {
                let Some(p) = got.get(&(c - 1)) else { continue };
                if in_window(c) || !recs[c as usize].nodes[k].up {
                    continue;
                }
                let (now, was) = (&recs[c as usize].nodes[k], &recs[c as usize - 1].nodes[k]);
                let want = [
                    now.perr - was.perr,
                    now.ferr - was.ferr,
                    now.aerr - was.aerr,
                    now.serr - was.serr,
                ];
                for (i, (_, name)) in COUNTERS.iter().enumerate() {
                    let applies = match i {
                        // (Not while a slot is stranded: whether its last
                        // word is checked, stale, or VOID is bit timing.)
                        2 => kind.is_master() && !stranded(cfg, &recs[c as usize]),
                        3 => k == recs[c as usize].base,
                        _ => true,
                    };
                    let g = v[i].wrapping_sub(p[i]) & 0xffff;
                    if applies && g != want[i] as u64 {
                        mism.push(Mismatch {
                            cycle: c,
                            place: format!("node {k}"),
                            what: format!("{name} increment"),
                            expected: want[i].to_string(),
                            got: g.to_string(),
                        });
                    }
                }
            }
        }
    }
}

/// What the driver learnt of a fibre's pace ([`frame_over`]).
#[derive(Clone, Copy, Default)]
pub(crate) struct Pace {
    /// Ticks from a frame's start to its H1 there (the last H1 decoded).
    pub(crate) off: Option<u64>,
    /// The fibre's TH1 that `off` was learnt from (or found too old).
    th1: Option<u64>,
}

/// Frame `k` has passed fibre `f`: its H1 (not an older one with the same
/// CYC) was seen and its last slot too; or, when a bit error made it
/// invisible there, as long after its start as the fibre's last visible
/// frame took to end (learnt into `pace`, once per H1 decoded there),
/// plus 8 bit times: in the idle gap before the next.
#[allow(clippy::too_many_arguments)]
fn frame_over(
    r: &mut Ring,
    f: usize,
    k: u32,
    starts: &[u64],
    sent: u32,
    pace: &mut [Pace],
    period: u64,
    slot_bits: u64,
) -> bool {
    let fr = r.rd(f, st::FRAME);
    let th1 = r.rd(f, st::TH1);
    let prev = starts[k as usize];
    let ended = fr >> 3 & 1 == 0
        && fr & 7 == (k & 7) as u64
        && th1.wrapping_sub(prev) & 0xffff_ffff < 1 << 31;
    if pace[f].th1 != Some(th1) {
        pace[f].th1 = Some(th1);
        // The frame TH1 belongs to: the CYC of the H1 decoded with it
        // (FRAME's CYC also counts on across a damaged H1, where TH1
        // stays).
        let cyc = ((r.rd(f, st::H1) >> 12) & 7) as u32;
        if let Some(j) = (0..sent).rev().find(|j| j & 7 == cyc) {
            let d = th1.wrapping_sub(starts[j as usize]) & 0xffff_ffff;
            if d < 2 * period * TICKS_PER_BIT as u64 {
                pace[f].off = Some(d);
            }
        }
    }
    let tail = (slot_bits + 8) * TICKS_PER_BIT as u64;
    ended || pace[f].off.is_some_and(|o| r.ticks >= prev + o + tail)
}

/// Whether some slot's writer is off the frame's path in this cycle (dead,
/// or cut off by a split ring): protocol §13, stranded slots.
fn stranded(cfg: &Config, rec: &CycleRecord) -> bool {
    cfg.writer.iter().any(|w| !rec.path.contains(w))
}

/// [`Options::dump`]: one fibre's capture of cycle `c`, the model's word
/// in brackets where it differs; `?` marks a header not written this cycle.
fn dump_fibre(r: &mut Ring, f: usize, c: u32, frame: &ring::Frame) {
    let b = (c & 3) as usize;
    let capn = r.capn;
    let mut line = format!("cycle {c} {}:", fibre_name(f, r.h1_seen.len() / 2));
    for i in 0..2 {
        let e = r.cap(f, 4 * capn + 2 * b + i);
        let stale = if fresh(e, c, r.ep[c as usize]) {
            ""
        } else {
            "?"
        };
        line += &format!(" H{i} {:04x}{stale}", e & 0xffff);
    }
    line += " |";
    for (slot, w) in frame.words.iter().enumerate() {
        let g = cap_slot(r.cap(f, b * capn + slot), c, r.ep[c as usize]);
        let (want, got) = (slot_token(w), slot_token(&g));
        if want == got {
            line += &format!(" {got}");
        } else {
            line += &format!(" {got}[{want}]");
        }
    }
    eprintln!("{line}");
}

/// A recovery window's first and last cycle, if any.
type Span = Option<(u32, u32)>;

/// Marks cycle `c` whole when the clock base got its frame back complete,
/// on its PI or its SI fibre: H1 and every slot fresh and present.
fn mark_whole(r: &mut Ring, cfg: &Config, recs: &[CycleRecord], c: u32) {
    let (capn, ep) = (r.capn, r.ep[c as usize]);
    let sm = recs[c as usize].base;
    let n = cfg.nodes.len();
    for f in [(sm + n - 1) % n, n + sm] {
        let h1 = r.cap(f, 4 * capn + 2 * (c & 3) as usize + 1);
        let mut whole = fresh(h1, c, ep) && (h1 >> 18) & 3 == 1;
        for slot in 0..cfg.slots {
            let e = r.cap(f, (c & 3) as usize * capn + slot);
            whole &= fresh(e, c, ep) && (e >> 18) & 3 != 0;
        }
        if whole {
            r.whole[c as usize] = true;
        }
    }
}

/// Inside a recovery window `win` (protocol §13) slot `slot` may show
/// nothing, a bad word, VOID, or data that the model put in that slot on
/// any fibre or that the slot's writer produced, from the cycle before the
/// window to its end (Alive and alarm flags are bit timing there): never a
/// foreign value. Outside a window, the repeat tail's rule.
fn legal_in_window(
    cfg: &Config,
    recs: &[CycleRecord],
    c: u32,
    (win, tail): (Span, Span),
    slot: usize,
    got: &Slot,
) -> bool {
    let Some((a, z)) = win else {
        return repeat_tail(cfg, recs, c, tail, slot, got);
    };
    let Slot::Data(g) = got else { return true };
    let span = &recs[a.saturating_sub(1) as usize..=z as usize];
    // A RECONFIG alarm (§11) of a mode its sender had in the window:
    // which of its modes is pending when it next writes depends on
    // bit timing (a switchbox change just before or after a frame
    // start; protocol §13).
    let sender = cfg.nodes.iter().position(|nd| nd.address == slot);
    let reconfig = !cfg.ext
        && g.alarm
        && sender.is_some_and(|w| {
            span.iter().any(|x| {
                g.data & !SEQ_BIT
                    == (merkur_model::ring::reason::reconfig(x.nodes[w].mode) as u16) << 12
            })
        });
    reconfig
        || span.iter().any(|x| {
            x.produced.get(slot) == Some(&g.data)
                || x.fibres.iter().any(|carry| match carry {
                    Carry::Data(fr) => {
                        matches!(fr.words.get(slot), Some(Slot::Data(m)) if m.data == g.data)
                    }
                    _ => false,
                })
        })
}

/// A slot whose writer is off the frame's path (a ring split by a second
/// fault, protocol §13), or frozen in failsafe, carries what the last frame
/// before the split brought back, which is bit timing: VOID, or data the
/// model showed in that slot before (up to cycle `c`) — never a foreign
/// value.
fn stranded_word(cfg: &Config, recs: &[CycleRecord], c: u32, slot: usize, got: &Slot) -> bool {
    let (rec, w) = (&recs[c as usize], cfg.writer[slot]);
    if rec.path.contains(&w) && !rec.nodes[w].failsafe {
        return false;
    }
    let Slot::Data(g) = got else {
        return matches!(got, Slot::Void);
    };
    recs[..=c as usize].iter().any(|x| {
        x.produced.get(slot) == Some(&g.data)
            || x.fibres.iter().any(|carry| {
                matches!(carry, Carry::Data(fr)
                if matches!(fr.words.get(slot), Some(Slot::Data(m)) if m.data == g.data))
            })
    })
}

/// Compares every fibre's capture of cycle `c` with the model. `spans`: the
/// recovery window that holds cycle `c`, and the one whose repeat tail
/// holds it (protocol §13). One pass over the captures, with each window
/// rule ([`legal_in_window`], [`stranded_word`]) at the words it applies to.
fn compare_cycle(
    r: &mut Ring,
    cfg: &Config,
    recs: &[CycleRecord],
    c: u32,
    spans: (Span, Span),
    mism: &mut Vec<Mismatch>,
    words: &mut u64,
) {
    let capn = r.capn;
    let ep = r.ep[c as usize];
    let sm = recs[c as usize].base;
    let win = spans.0;
    mark_whole(r, cfg, recs, c);
    let n = cfg.nodes.len();
    let rec = &recs[c as usize];
    let b = (c & 3) as usize;
    if win.is_some() {
        r.alive_inv.iter_mut().for_each(|x| *x = None);
    }
    // The last frame of a clock base that dies at the next cycle's start,
    // on the fibres back into it: its neighbours' wrap (their loss of
    // signal, 32 bit times after the death) may cut its tail, as a frame's
    // round trip outlasts the gap before the next frame (protocol §13).
    // Nobody alive reads those words.
    let dies = |k: usize| recs.get(c as usize + 1).is_some_and(|x| !x.nodes[k].up);
    let cut_back = |f: usize| dies(sm) && (f == (sm + n - 1) % n || f == n + sm);
    for (f, carry) in rec.fibres.iter().enumerate() {
        let hdr = |r: &mut Ring, i: usize| r.cap(f, 4 * capn + 2 * b + i);
        let mut push = |what: String, e: String, g: String| {
            mism.push(Mismatch {
                cycle: c,
                place: fibre_name(f, n),
                what,
                expected: e,
                got: g,
            })
        };
        match carry {
            Carry::Data(frame) => {
                let HeaderRx::Ok(h) = frame.hdr else {
                    continue;
                };
                for (i, want) in [h.h0(cfg.slots).data, h.h1().data].into_iter().enumerate() {
                    let e = hdr(r, i);
                    if i == 1 {
                        r.h1_seen[f][b] = e;
                    }
                    *words += 1;
                    let ok = fresh(e, c, ep) && (e & 0xffff) as u16 == want;
                    // A window's headers carry what the nodes knew at the
                    // bit-level moment (RWC, FS, HOP): not compared.
                    if !ok && win.is_none() {
                        let g = if fresh(e, c, ep) {
                            format!("{:04x}", e & 0xffff)
                        } else {
                            "none".into()
                        };
                        push(format!("H{i}"), format!("{want:04x}"), g);
                    }
                }
                if r.dump {
                    dump_fibre(r, f, c, frame);
                }
                for (slot, w) in frame.words.iter().enumerate() {
                    let e = r.cap(f, b * capn + slot);
                    let g = cap_slot(e, c, ep);
                    let (want, got) = (slot_token(w), slot_token(&g));
                    *words += 1;
                    // The Alive bit's phase counts the frames its writer
                    // processed; after a window it may run inverted (which
                    // frames a node lost there is bit timing), but then
                    // constantly so: learnt from the first fibre, held.
                    if let (Slot::Data(m), Slot::Data(x), None) = (w, g, win) {
                        let inv = m.alive != x.alive;
                        if m.data == x.data && m.alarm == x.alarm {
                            match r.alive_inv[slot] {
                                None => {
                                    r.alive_inv[slot] = Some(inv);
                                    continue;
                                }
                                Some(v) if v == inv => continue,
                                _ => {}
                            }
                        }
                    }
                    let cut = cut_back(f) && g == Slot::Missing;
                    if want != got
                        && !legal_in_window(cfg, recs, c, spans, slot, &g)
                        && !stranded_word(cfg, recs, c, slot, &g)
                        && !cut
                    {
                        push(format!("slot {slot}"), want, got);
                    }
                }
            }
            _ => {
                // No frame on this fibre in this cycle.
                let e = hdr(r, 1);
                let stale = e == r.h1_seen[f][b];
                if !stale && win.is_none() && fresh(e, c, ep) && (e >> 18) & 3 == 1 {
                    push(
                        "frame".into(),
                        "none".into(),
                        format!("H1 {:04x}", e & 0xffff),
                    );
                }
            }
        }
    }
}

/// The SEQ bit of a basic-variant alarm word (protocol §11).
const SEQ_BIT: u16 = 0x0800;

/// After a recovery window `tail` = (a, z), for [`ring::REPEAT_TAIL`]
/// cycles (protocol §13): the home slot of a node that sent an alarm inside
/// the window may carry a repeat of it (an alarm of a reason it sent there,
/// or a RECONFIG of a mode it had), or — where the model repeats an alarm
/// that the RTL got through — the data its writer produced since the
/// window began.
fn repeat_tail(
    cfg: &Config,
    recs: &[CycleRecord],
    c: u32,
    tail: Option<(u32, u32)>,
    slot: usize,
    got: &Slot,
) -> bool {
    let Some((a, z)) = tail else { return false };
    let Some(w) = cfg.nodes.iter().position(|nd| nd.address == slot) else {
        return false;
    };
    let span = &recs[a.saturating_sub(1) as usize..=c as usize];
    let sent: Vec<u8> = recs[a as usize..=z as usize]
        .iter()
        .flat_map(|x| &x.events)
        .filter(|e| e.node == w)
        .filter_map(|e| match e.kind {
            EventKind::AlarmTx { reason, .. } => Some(reason),
            _ => None,
        })
        .collect();
    if sent.is_empty() {
        return false;
    }
    let Slot::Data(g) = got else { return false };
    if g.alarm {
        // The reason: D[15:12], or the extended variant's N1 (§6, §11).
        let r = if cfg.ext {
            g.reason & 7
        } else {
            (g.data >> 12) as u8
        };
        sent.contains(&r)
            || span
                .iter()
                .any(|x| r == merkur_model::ring::reason::reconfig(x.nodes[w].mode))
    } else {
        span.iter().any(|x| x.produced.get(slot) == Some(&g.data))
    }
}

/// A GTKWave save file for a ring's waveform: per node its clock, lines,
/// mode and failsafe, per fibre its line, grouped.
pub fn gtkw(cfg: &Config, wave: &Path) -> String {
    let n = cfg.nodes.len();
    let mut g = format!("[dumpfile] \"{}\"\n", wave.display());
    for (k, nd) in cfg.nodes.iter().enumerate() {
        g.push_str(&format!("@800200\n-node {k} {}\n@28\n", nd.kind.name()));
        for sig in ["nclk", "fs", "fired"] {
            g.push_str(&format!("TOP.merkur_ring.{sig}_{k}\n"));
        }
        g.push_str(&format!(
            "@22\nTOP.merkur_ring.mode_{k}[1:0]\nTOP.merkur_ring.perr_{k}[15:0]\n@1000200\n-node {k} {}\n",
            nd.kind.name()
        ));
    }
    g.push_str("@800200\n-fibres\n@28\n");
    for f in 0..2 * n {
        g.push_str(&format!("TOP.merkur_ring.line_{f}\n"));
    }
    g.push_str("@1000200\n-fibres\n");
    g
}
