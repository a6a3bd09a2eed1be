//! `merkur campaign`: a fault-injection campaign through the RTL (Verilator)
//! and the reference model, compared case by case under the recovery-window
//! rules of docs/protocol.md §13, with a Markdown and JSON report.
//!
//! Cases per base ring (its own faults dropped): every single fibre break
//! (primary and secondary) and every node death but the special master's;
//! double faults (the second 4 cycles after the first, on a link the first
//! did not darken), all or a seeded sample; repairs of every fibre;
//! double breaks, both repaired (out of failsafe); bit-error runs at given
//! bit error rates (line bits of every packet on every fibre, at most one
//! per packet and fibre, which is what the harness can place) and bursts
//! of garbage; faults on the special master's own four fibres with and
//! without host writes in flight; clock-offset runs (fault-free, a break,
//! every node at an extreme alternating round the ring). Every case runs
//! its nodes at clock offsets drawn from its own seed within ±`--ppm`
//! (three neighbours at alternating extremes among them), printed with a
//! failing case. Everything is derived from `--seed`, so a case list is
//! the same on every machine, `--case NAME` reruns one case exactly, and
//! `--shard K/N` splits it; `--merge` joins shard reports.

use crate::progress;
use merkur_model::config::{Config, Fault, Fibre, FlipTarget, RTX_MAX};
use merkur_model::ring::{self, splitmix, table1, Carry, CycleRecord, EventKind, Mode, Port, Slot};
use merkur_model::scenario::Kind;
use merkur_rtl::harness::ring_top::TICKS_PER_BIT;
use merkur_sim::ring_sim::{self, Options};
use merkur_sim::Rng;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Cycle of the (first) fault in generated cases.
const FAULT_CYCLE: u32 = 3;
/// Bit-error runs: cycles with errors (1 ..= this), then
/// [`CLEAN_CYCLES`] without, to see the ring heal.
const BER_CYCLES: u32 = 8;
/// Bit-error runs: clean cycles after the errors.
const CLEAN_CYCLES: u32 = 5;

/// What to run.
pub struct Plan {
    /// Base rings (scenario files).
    pub rings: Vec<PathBuf>,
    /// Single faults per ring: a seeded sample of k, or None: all (with
    /// `full`, 30 sampled on rings of more than 32 nodes).
    pub singles: Option<usize>,
    /// The `--full` preset's sampling by ring size.
    pub full: bool,
    /// Double faults per ring: a seeded sample of k, or None: all on rings
    /// of up to 16 nodes, a sample of 32 on bigger ones (8 above 32 nodes).
    pub doubles: Option<usize>,
    /// Bit error rates; runs per rate.
    pub ber: Vec<f64>,
    /// Runs per bit error rate.
    pub ber_runs: usize,
    /// Burst runs per ring (and one long burst).
    pub bursts: usize,
    /// Every case's nodes run at offsets drawn within ±this many ppm.
    pub ppm: f64,
    /// Repair cases.
    pub repairs: bool,
    /// Campaign seed.
    pub seed: u64,
    /// Parallel simulations.
    pub jobs: usize,
    /// This shard, 1-based, of how many.
    pub shard: (usize, usize),
    /// Only the case with this name.
    pub case: Option<String>,
    /// Waveform of the one case `case` names.
    pub wave: Option<PathBuf>,
    /// Write the one case `case` names as a scenario file here.
    pub export: Option<PathBuf>,
    /// Run the model only (the protocol's behaviour, many runs cheaply):
    /// no RTL, no comparison.
    pub model_only: bool,
    /// Only cases of these classes (empty: all); each one of [`CLASSES`]
    /// (clap checks `--only` against them).
    pub only: Vec<String>,
}

/// One case's result (a row of the JSON report).
#[derive(Serialize, Deserialize, Clone, Debug)]
pub struct CaseResult {
    /// Unique name: ring/class/detail.
    pub name: String,
    /// Base ring name.
    pub ring: String,
    /// Nodes in the ring.
    pub nodes: usize,
    /// Fault class.
    pub class: String,
    /// The faults, as `merkur check` prints them.
    pub faults: Vec<String>,
    /// RTL phase seed.
    pub seed: u64,
    /// Every node's clock offset, ppm (drawn from the case's seed).
    #[serde(default)]
    pub ppm: Vec<f64>,
    /// Mismatches against the model (after the window rules).
    pub mismatches: usize,
    /// The first few, or the error that stopped the run.
    pub first: Vec<String>,
    /// Words compared.
    pub words: u64,
    /// Model: every live node out of failsafe at the end, after a
    /// structural fault.
    pub healed: bool,
    /// Model: some live node in failsafe at the end.
    pub failsafe: bool,
    /// Model: slot words that came back to the special master good in the
    /// fault-free ring but not in this one.
    pub words_lost: u64,
    /// Model: frames that did not come back whole, where the fault-free
    /// ring's did.
    pub cycles_lost: u32,
    /// RTL: the same, as the special master's input monitors saw it.
    pub rtl_cycles_lost: u32,
    /// Model: cycles from the first fault until every live node's memory
    /// equals the fault-free ring's for good (None: never in the run).
    pub cycles_to_recover: Option<u32>,
    /// Model: cycles after the cycle of the last fault (for bit errors: the
    /// last cycle with errors) until every live node's memory equals the
    /// fault-free ring's for good (None: never in the run).
    #[serde(default)]
    pub cycles_after_last: Option<u32>,
    /// Bit-error cases: the bit error rate.
    #[serde(default)]
    pub ber: Option<f64>,
    /// Retransmission cases: data age by slot class and the packets'
    /// cost (model).
    #[serde(default)]
    pub rtx: Option<RtxAge>,
    /// Whether the RTL ran (false: `--model-only`).
    #[serde(default = "yes")]
    pub rtl: bool,
    /// RTL: bit times from the first fault to the first switchbox change.
    pub detect_bits: Option<f64>,
    /// RTL: bit times from the first fault to the last switchbox change it
    /// caused (the ring is wrapped at both ends).
    pub switchover_bits: Option<f64>,
    /// RTL: bit times from the last fault until every live node is in
    /// failsafe.
    pub failsafe_bits: Option<f64>,
    /// RTL: bit times from the clock base's death to the first frame of
    /// the backup that took over (protocol §8).
    #[serde(default)]
    pub takeover_bits: Option<f64>,
    /// The ring's cycle period in bit times.
    #[serde(default)]
    pub period_bits: Option<f64>,
    /// Line rate of the ring (Mbit/s), for µs.
    pub mbps: f64,
    /// Bit flips injected.
    pub flips: u32,
    /// Flipped words the receiver took as good (single-bit errors
    /// accepted; must be 0).
    pub accepted: u32,
    /// Wall seconds of the RTL run.
    pub wall_s: f64,
}

/// A retransmission case's data age (protocol §8) by slot class, from
/// cycle 1 on, over every live master's memory of the slots it does not
/// write and every actuator's output (model).
#[derive(Serialize, Deserialize, Clone, Debug)]
pub struct RtxAge {
    /// Retransmission on (the slots critical) or off (the same ring,
    /// period and frame errors, no slot critical).
    pub on: bool,
    /// The critical slots (of the ring with retransmission on).
    pub critical: Vec<usize>,
    /// Copies of the critical slots.
    pub crit: AgeClass,
    /// Copies of the other slots.
    pub other: AgeClass,
    /// Retransmission packets sent.
    pub packets: u32,
    /// Requests they carried.
    pub requests: u32,
    /// Damaged critical slots that did not fit a packet.
    pub left: u32,
    /// Line bits the packets took.
    pub bits: u64,
}

/// Data age of one class of copies.
#[derive(Serialize, Deserialize, Clone, Copy, Debug)]
pub struct AgeClass {
    /// Copies counted (per node, slot and cycle).
    pub copies: u64,
    /// The oldest, in cycles.
    pub worst: u32,
    /// Mean age, in cycles.
    pub mean: f64,
    /// Copies older than in the same ring without errors.
    pub older: u64,
}

impl From<ring::AgeStat> for AgeClass {
    fn from(a: ring::AgeStat) -> Self {
        AgeClass {
            copies: a.copies,
            worst: a.worst,
            mean: a.mean(),
            older: a.older,
        }
    }
}

/// The whole report.
#[derive(Serialize, Deserialize, Debug, Default)]
pub struct Report {
    /// The command line(s) that produced it.
    pub commands: Vec<String>,
    /// Every case.
    pub cases: Vec<CaseResult>,
}

struct Case {
    name: String,
    ring: String,
    class: &'static str,
    cfg: Config,
    seed: u64,
    /// Bit-error cases: the rate.
    ber: Option<f64>,
    /// Retransmission cases: on or off, and the slot classes (critical
    /// per slot, of the ring with it on).
    rtx: Option<(bool, Vec<bool>)>,
}

fn yes() -> bool {
    true
}

fn hash_name(seed: u64, name: &str) -> u64 {
    name.bytes()
        .fold(splitmix(seed), |h, b| splitmix(h ^ b as u64))
}

/// The single structural faults of a ring: (label, fault, links it darkens).
fn singles(base: &Config) -> Vec<(String, Fault, Vec<usize>)> {
    let n = base.nodes.len();
    let mut v = vec![];
    for k in 0..n {
        v.push((
            Fibre::P(k).to_string(),
            Fault::Break {
                fibre: Fibre::P(k),
                slot: None,
            },
            vec![k],
        ));
    }
    for k in 0..n {
        v.push((
            Fibre::S(k).to_string(),
            Fault::Break {
                fibre: Fibre::S(k),
                slot: None,
            },
            vec![k],
        ));
    }
    for k in (0..n).filter(|&k| k != base.sm) {
        // A dead node darkens both its links.
        v.push((
            format!("n{k}"),
            Fault::Kill {
                node: k,
                slot: None,
            },
            vec![k, (k + n - 1) % n],
        ));
    }
    v
}

fn with_slot(f: Fault, slot: Option<usize>) -> Fault {
    match f {
        Fault::Break { fibre, .. } => Fault::Break { fibre, slot },
        Fault::Kill { node, .. } => Fault::Kill { node, slot },
        Fault::Repair { fibre, .. } => Fault::Repair { fibre, slot },
        other => other,
    }
}

fn slot_label(s: Option<usize>) -> String {
    s.map(|s| format!(".s{s}")).unwrap_or_default()
}

/// The cases of one base ring as they are planned: each gets its RTL phase
/// seed and its nodes' clock offsets from its name.
struct Planner<'a> {
    ring: &'a str,
    plan: &'a Plan,
    clean: Config,
    out: Vec<Case>,
}

impl Planner<'_> {
    /// Adds a case; every node's clock offset is drawn from the case's seed
    /// ([`draw_offsets`]).
    fn push(&mut self, name: String, class: &'static str, mut cfg: Config) {
        let seed = hash_name(self.plan.seed, &name);
        draw_offsets(&mut cfg, self.plan.ppm, seed);
        self.out.push(Case {
            name,
            ring: self.ring.to_string(),
            class,
            cfg,
            seed,
            ber: None,
            rtx: None,
        });
    }
    /// A seeded stream for a choice named `what`.
    fn rng(&self, what: &str) -> Rng {
        Rng::new(hash_name(self.plan.seed, &format!("{}/{what}", self.ring)))
    }
    /// Before the delimiter one time in four, else before a seeded slot.
    fn slot_of(&self, name: &str) -> Option<usize> {
        let h = hash_name(self.plan.seed ^ 0x51, name);
        (h % 4 != 0).then(|| (h >> 8) as usize % self.clean.slots)
    }
}

/// Every node's clock offset for a case: uniform in ±`bound` ppm (whole
/// ppm), and among them three neighbours at alternating extremes (+, −, +
/// or −, +, −, at a seeded place): a node at +bound feeding one at −bound,
/// and one at −bound feeding one at +bound, the largest difference a link
/// can see, both ways.
fn draw_offsets(cfg: &mut Config, bound: f64, seed: u64) {
    let n = cfg.nodes.len();
    let mut r = Rng::new(seed ^ 0x0ff5_e75e);
    for nd in cfg.nodes.iter_mut() {
        nd.ppm = ((r.unit() * 2.0 - 1.0) * bound).round();
    }
    let i = r.below(n as u64) as usize;
    let sign = if r.below(2) == 0 { 1.0 } else { -1.0 };
    for (k, s) in [sign, -sign, sign].into_iter().enumerate() {
        cfg.nodes[(i + k) % n].ppm = s * bound;
    }
}

/// The first k of a seeded shuffle of `v` (all of it when k ≥ its length).
fn sample<T>(v: &mut Vec<T>, k: usize, r: &mut Rng) {
    for i in 0..v.len().min(k) {
        let j = i + r.below((v.len() - i) as u64) as usize;
        v.swap(i, j);
    }
    v.truncate(k);
}

/// Builds the case list of one base ring.
fn cases_of(ring_name: &str, base: &Config, plan: &Plan) -> Vec<Case> {
    let mut clean = base.clone();
    clean.faults.clear();
    let mut p = Planner {
        ring: ring_name,
        plan,
        clean,
        out: vec![],
    };
    single_cases(&mut p);
    sm_fibre_cases(&mut p);
    takeover_cases(&mut p);
    double_cases(&mut p);
    if plan.repairs {
        repair_cases(&mut p);
    }
    double_repair_cases(&mut p);
    restart_cases(&mut p);
    ber_cases(&mut p);
    rtx_cases(&mut p);
    burst_cases(&mut p);
    offset_cases(&mut p);
    p.out
}

/// Every single fibre break and node death (30 sampled on rings of more
/// than 32 nodes with `--full`), each before a seeded slot of cycle 3.
fn single_cases(p: &mut Planner) {
    let ones = singles(&p.clean);
    let n = p.clean.nodes.len();
    let mut picked: Vec<usize> = (0..ones.len()).collect();
    let k = match p.plan.singles {
        None if p.plan.full && n > 32 => Some(30),
        d => d,
    };
    if let Some(k) = k {
        sample(&mut picked, k, &mut p.rng("singles"));
        picked.sort_unstable();
    }
    for (label, f, _) in picked.iter().map(|&i| ones[i].clone()) {
        let class = match f {
            Fault::Break {
                fibre: Fibre::P(_), ..
            } => "break-primary",
            Fault::Break { .. } => "break-secondary",
            _ => "node-death",
        };
        let key = format!("{}/{class}/{label}", p.ring);
        let s = p.slot_of(&key);
        let mut cfg = p.clean.clone();
        cfg.cycles = FAULT_CYCLE + 7;
        cfg.faults = vec![(FAULT_CYCLE, with_slot(f, s))];
        p.push(format!("{key}@{FAULT_CYCLE}{}", slot_label(s)), class, cfg);
    }
}

/// The special master's own four fibres (into its PI and SI, out of its PO
/// and SO: issue 19, a break of its SO took the ring into failsafe under
/// some clock offsets), each before the delimiter and before two seeded
/// slots of cycle 3, with and without host writes in flight (every master
/// writes every slot it owns in cycles 3 and 4).
fn sm_fibre_cases(p: &mut Planner) {
    let n = p.clean.nodes.len();
    let sm = p.clean.sm;
    let fibres = [
        Fibre::P((sm + n - 1) % n),
        Fibre::P(sm),
        Fibre::S(sm),
        Fibre::S((sm + n - 1) % n),
    ];
    let mut r = p.rng("sm-fibres");
    for fibre in fibres {
        let slots = [
            None,
            Some(r.below(p.clean.slots as u64) as usize),
            Some(r.below(p.clean.slots as u64) as usize),
        ];
        for s in slots {
            for writes in [false, true] {
                let mut cfg = p.clean.clone();
                cfg.cycles = FAULT_CYCLE + 7;
                cfg.faults = vec![(FAULT_CYCLE, Fault::Break { fibre, slot: s })];
                let tag = if writes {
                    for c in [FAULT_CYCLE, FAULT_CYCLE + 1] {
                        for (k, nd) in p.clean.nodes.iter().enumerate() {
                            for &slot in nd.slots.iter().chain(&nd.serves) {
                                cfg.host_writes.push((c, k, slot, r.next_u64() as u16));
                            }
                        }
                    }
                    "+writes"
                } else {
                    ""
                };
                p.push(
                    format!(
                        "{}/sm-fibres/{fibre}@{FAULT_CYCLE}{}{tag}",
                        p.ring,
                        slot_label(s)
                    ),
                    "sm-fibres",
                    cfg,
                );
            }
        }
    }
}

/// The special master's death with the masters as backups (protocol §8):
/// every order of priorities 1, 2, … over the masters (a ring with one
/// master: priority 1, 2 and 3), each with the death before the delimiter
/// and before a seeded slot of cycle 3; 3 sampled on rings of more than 32
/// nodes.
fn takeover_cases(p: &mut Planner) {
    let masters: Vec<usize> = (0..p.clean.nodes.len())
        .filter(|&k| p.clean.nodes[k].kind == Kind::Master)
        .collect();
    if masters.is_empty() {
        return;
    }
    let mut orders: Vec<Vec<u8>> = if masters.len() == 1 {
        vec![vec![1], vec![2], vec![3]]
    } else {
        permutations(masters.len())
    };
    let mut r = p.rng("sm-takeover");
    let mut cases = vec![];
    for prios in orders.drain(..) {
        let s = Some(r.below(p.clean.slots as u64) as usize);
        for slot in [None, s] {
            cases.push((prios.clone(), slot));
        }
    }
    if p.clean.nodes.len() > 32 {
        sample(&mut cases, 3, &mut r);
    }
    let sm = p.clean.sm;
    for (prios, slot) in cases {
        let mut cfg = p.clean.clone();
        for (&k, &pr) in masters.iter().zip(&prios) {
            cfg.nodes[k].backup = Some(pr);
        }
        cfg.cycles = FAULT_CYCLE + 9;
        cfg.faults = vec![(FAULT_CYCLE, Fault::Kill { node: sm, slot })];
        let order: Vec<String> = masters
            .iter()
            .zip(&prios)
            .map(|(k, pr)| format!("n{k}p{pr}"))
            .collect();
        p.push(
            format!(
                "{}/sm-takeover/{}@{FAULT_CYCLE}{}",
                p.ring,
                order.join(","),
                slot_label(slot)
            ),
            "sm-takeover",
            cfg,
        );
    }
}

/// Every order of the priorities 1..=m (m ≤ 7), in lexicographic order.
fn permutations(m: usize) -> Vec<Vec<u8>> {
    let mut out = vec![];
    let mut cur: Vec<u8> = vec![];
    fn go(m: usize, cur: &mut Vec<u8>, out: &mut Vec<Vec<u8>>) {
        if cur.len() == m {
            out.push(cur.clone());
            return;
        }
        for p in 1..=m as u8 {
            if !cur.contains(&p) {
                cur.push(p);
                go(m, cur, out);
                cur.pop();
            }
        }
    }
    go(m, &mut cur, &mut out);
    out
}

/// Double faults: the second, 4 cycles after the first, on a link the
/// first did not darken; all or a seeded sample.
fn double_cases(p: &mut Planner) {
    let ones = singles(&p.clean);
    let n = p.clean.nodes.len();
    let second = FAULT_CYCLE + 4;
    let mut pairs = vec![];
    for (a, (la, fa, da)) in ones.iter().enumerate() {
        for (b, (lb, fb, db)) in ones.iter().enumerate() {
            if a == b || db.iter().any(|l| da.contains(l)) {
                continue;
            }
            // A killed node cannot be hit again.
            if let (Fault::Kill { node: x, .. }, Fault::Kill { node: y, .. }) = (fa, fb) {
                if x == y {
                    continue;
                }
            }
            pairs.push((la.clone(), *fa, lb.clone(), *fb));
        }
    }
    let k = match p.plan.doubles {
        None if n > 32 => Some(8),
        None if n > 16 => Some(32),
        d => d,
    };
    if let Some(k) = k {
        sample(&mut pairs, k, &mut p.rng("doubles"));
    }
    for (la, fa, lb, fb) in pairs {
        let mut cfg = p.clean.clone();
        cfg.cycles = second + 5;
        cfg.faults = vec![(FAULT_CYCLE, fa), (second, fb)];
        p.push(
            format!("{}/double/{la}@{FAULT_CYCLE}+{lb}@{second}", p.ring),
            "double",
            cfg,
        );
    }
}

/// Repairs: every fibre on rings of up to 16 nodes, 8 sampled on bigger
/// ones, broken in cycle 3 and repaired 3 cycles later.
fn repair_cases(p: &mut Planner) {
    let n = p.clean.nodes.len();
    let mut fibres: Vec<Fibre> = (0..n).map(Fibre::P).chain((0..n).map(Fibre::S)).collect();
    if n > 16 {
        sample(&mut fibres, 8, &mut p.rng("repairs"));
    }
    for f in fibres {
        let mut cfg = p.clean.clone();
        let fix = FAULT_CYCLE + 3;
        cfg.cycles = fix + 7;
        let brk = Fault::Break {
            fibre: f,
            slot: None,
        };
        let rep = Fault::Repair {
            fibre: f,
            slot: None,
        };
        cfg.faults = vec![(FAULT_CYCLE, brk), (fix, rep)];
        p.push(
            format!("{}/repair/{f}@{FAULT_CYCLE}-{fix}", p.ring),
            "repair",
            cfg,
        );
    }
}

/// Restarts (protocol §12): every slave and every master (not the special
/// master nor a backup) on rings of up to 16 nodes, 4 slaves and 2 masters
/// sampled on bigger ones, dies before a seeded slot (or the delimiter) of
/// cycle 3 and gets power again before cycle 6 (a master: its host loads
/// the configuration and starts it with JOIN, and writes nothing after);
/// the case runs 14 cycles past the restart (the rejoin's window and its
/// tail, then exact).
fn restart_cases(p: &mut Planner) {
    let n = p.clean.nodes.len();
    let mut slaves: Vec<usize> = (0..n)
        .filter(|&k| !p.clean.nodes[k].kind.is_master())
        .collect();
    let mut masters: Vec<usize> = (0..n)
        .filter(|&k| p.clean.nodes[k].kind == Kind::Master && p.clean.nodes[k].backup.is_none())
        .collect();
    if n > 16 {
        sample(&mut slaves, 4, &mut p.rng("restarts"));
        slaves.sort_unstable();
        sample(&mut masters, 2, &mut p.rng("master restarts"));
        masters.sort_unstable();
    }
    slaves.extend(masters);
    for k in slaves {
        let on = FAULT_CYCLE + 3;
        let key = format!("{}/restart/n{k}", p.ring);
        let slot = p.slot_of(&key);
        let mut cfg = p.clean.clone();
        cfg.cycles = on + 14;
        cfg.faults = vec![
            (FAULT_CYCLE, Fault::Kill { node: k, slot }),
            (on, Fault::Restart { node: k }),
        ];
        p.push(
            format!("{key}@{FAULT_CYCLE}{}-{on}", slot_label(slot)),
            "restart",
            cfg,
        );
    }
    restart_clock_base_cases(p);
}

/// Restarts in a ring with backups (every master a backup, priorities in
/// node order, seven at most; protocol §8, §12): the special master dies before a seeded
/// slot of cycle 3, the backup of priority 1 takes over, and the old
/// special master gets power again before cycle 9 (its host starts it with
/// JOIN: it rejoins as a master and never starts a clock base); and the
/// backup of priority 1 dies and restarts (cycles 3 and 6) while the
/// special master lives. Each runs 14 cycles past the restart.
fn restart_clock_base_cases(p: &mut Planner) {
    let masters: Vec<usize> = (0..p.clean.nodes.len())
        .filter(|&k| p.clean.nodes[k].kind == Kind::Master)
        .take(7)
        .collect();
    let Some(&first) = masters.first() else {
        return;
    };
    let sm = p.clean.sm;
    for (k, on) in [(sm, FAULT_CYCLE + 6), (first, FAULT_CYCLE + 3)] {
        let role = if k == sm { "sm" } else { "backup" };
        let key = format!("{}/restart/{role}-n{k}", p.ring);
        let slot = p.slot_of(&key);
        let mut cfg = p.clean.clone();
        for (i, &m) in masters.iter().enumerate() {
            cfg.nodes[m].backup = Some(i as u8 + 1);
        }
        cfg.cycles = on + 14;
        cfg.faults = vec![
            (FAULT_CYCLE, Fault::Kill { node: k, slot }),
            (on, Fault::Restart { node: k }),
        ];
        p.push(
            format!("{key}@{FAULT_CYCLE}{}-{on}", slot_label(slot)),
            "restart",
            cfg,
        );
    }
}

/// Double breaks, both repaired (protocol §12, issue 28): two fibres of
/// different links break in cycles 3 and 7 (the second takes the ring into
/// failsafe) and are repaired in cycles 9 and 10; the case runs 14 cycles
/// past the last repair (reintegration in failsafe, link by link where a
/// node was cut off, two frames back whole, the CLR frames). 8 seeded
/// pairs per ring; with `--full` every ordered pair on rings of up to 16
/// nodes, 8 on bigger ones, 4 on 100 nodes.
fn double_repair_cases(p: &mut Planner) {
    let n = p.clean.nodes.len();
    let second = FAULT_CYCLE + 4;
    let mut pairs = vec![];
    for a in 0..2 * n {
        for b in 0..2 * n {
            // Fibre k < n is P(k), else S(k − n); both on link k mod n.
            if a % n != b % n {
                pairs.push((a, b));
            }
        }
    }
    let k = match (p.plan.full, n) {
        (true, 0..=16) => None,
        (true, 17..=32) | (false, _) => Some(8),
        (true, _) => Some(4),
    };
    if let Some(k) = k {
        sample(&mut pairs, k, &mut p.rng("double-repairs"));
    }
    let fibre = |x: usize| if x < n { Fibre::P(x) } else { Fibre::S(x - n) };
    for (a, b) in pairs {
        let (fa, fb) = (fibre(a), fibre(b));
        let (ra, rb) = (second + 2, second + 3);
        let mut cfg = p.clean.clone();
        cfg.cycles = rb + 14;
        let brk = |fibre| Fault::Break { fibre, slot: None };
        let rep = |fibre| Fault::Repair { fibre, slot: None };
        cfg.faults = vec![
            (FAULT_CYCLE, brk(fa)),
            (second, brk(fb)),
            (ra, rep(fb)),
            (rb, rep(fa)),
        ];
        p.push(
            format!(
                "{}/double-repair/{fa}@{FAULT_CYCLE}+{fb}@{second}-{ra}-{rb}",
                p.ring
            ),
            "double-repair",
            cfg,
        );
    }
}

/// Bit-error runs: per rate, `ber_runs` runs: errors in cycles 1 …
/// [`BER_CYCLES`], then [`CLEAN_CYCLES`] clean ones.
fn ber_cases(p: &mut Planner) {
    for &ber in &p.plan.ber {
        for run in 0..p.plan.ber_runs {
            let name = format!("{}/ber/{ber:e}#{run}", p.ring);
            let mut cfg = p.clean.clone();
            cfg.cycles = 1 + BER_CYCLES + CLEAN_CYCLES;
            cfg.faults = ber_flips(&cfg, ber, hash_name(p.plan.seed, &name));
            p.push(name, "bit-errors", cfg);
            if let Some(c) = p.out.last_mut() {
                c.ber = Some(ber);
            }
        }
    }
}

/// Retransmission on demand (protocol §8): the ring with its slots 1 ..=
/// slots / 3 critical (at least one, at most [`RTX_MAX`]), at the
/// shortest period with room for a request per critical slot (the ring's
/// own if longer); per bit error rate, `ber_runs` runs with errors in
/// cycles 1 ..= [`BER_CYCLES`] — in the DATA frames as [`ber_flips`]
/// places them and in the retransmission packets ([`rtx_flips`]) — then
/// [`CLEAN_CYCLES`] clean. Each run twice: `on`, and `off` (the same ring,
/// period and frame errors, no slot critical), so that the report sets
/// the data age of both side by side.
fn rtx_cases(p: &mut Planner) {
    let mut on = p.clean.clone();
    let last = (on.slots / 3).clamp(1, RTX_MAX).min(on.slots - 1);
    for s in 1..=last {
        on.critical[s] = true;
    }
    let Some(period) = on.period_for_requests(last) else {
        return;
    };
    on.period = on.period.max(period);
    on.cycles = 1 + BER_CYCLES + CLEAN_CYCLES;
    if ring_sim::unsupported(&on).is_some() {
        return;
    }
    let classes = on.critical.clone();
    for &ber in &p.plan.ber {
        for run in 0..p.plan.ber_runs {
            let name = format!("{}/retransmission/{ber:e}#{run}", p.ring);
            let seed = hash_name(p.plan.seed, &name);
            let mut off = on.clone();
            off.critical.iter_mut().for_each(|x| *x = false);
            let data = ber_flips(&off, ber, seed);
            let mut with = on.clone();
            with.faults = data.clone();
            with.faults.extend(rtx_flips(&with, ber, seed ^ 0x7274));
            with.faults.sort_by_key(|&(c, _)| c);
            with.faults = placeable(&with, with.faults.clone());
            off.faults = data;
            for (tag, cfg, yes) in [("on", with, true), ("off", off, false)] {
                p.push(format!("{name}/{tag}"), "retransmission", cfg);
                if let Some(c) = p.out.last_mut() {
                    c.ber = Some(ber);
                    c.rtx = Some((yes, classes.clone()));
                }
            }
        }
    }
}

/// Bursts of garbage (protocol §4, scenario `kind = "burst"`): `bursts`
/// runs per ring, one burst each in cycle 3 on a seeded primary fibre, from
/// a seeded line bit of the frame that starts with an edge (which the RTL
/// harness places exactly), 1 … 100 bit times long, then clean; and one of
/// 250 bit times (ten words: a run of bad words on that fibre, a soft wrap
/// that reintegrates, §9).
fn burst_cases(p: &mut Planner) {
    let n = p.clean.nodes.len();
    let recs = ring::run(&p.clean);
    let c = FAULT_CYCLE;
    let w = p.clean.word_bits() as usize;
    let room = (2 + p.clean.slots) * w;
    for run in 0..p.plan.bursts + 1 {
        let name = format!("{}/burst/#{run}", p.ring);
        let mut r = Rng::new(hash_name(p.plan.seed, &name));
        let long = run == p.plan.bursts;
        let len = if long { 250 } else { 1 + r.below(100) as usize };
        let k = r.below(n as u64) as usize;
        let Carry::Data(fr) = &recs[c as usize].fibres[k] else {
            continue;
        };
        // Line bits from H0's first on whose code bit is 1, with room for
        // the burst before the frame ends.
        let ones: Vec<usize> = code_ones(&p.clean, fr)
            .into_iter()
            .filter(|&b| b >= 10 && b - 10 + len <= room)
            .map(|b| b - 10)
            .collect();
        if ones.is_empty() {
            continue;
        }
        // (A few tries: garbage that makes H1 another good header word
        // cannot be placed by the RTL harness, ring_sim::flip_unsupported.)
        for _ in 0..8 {
            let at = ones[r.below(ones.len() as u64) as usize];
            let target = match at / w {
                0 => FlipTarget::H0,
                1 => FlipTarget::H1,
                s => FlipTarget::Slot(s - 2),
            };
            let mut cfg = p.clean.clone();
            cfg.cycles = c + 1 + CLEAN_CYCLES + 2;
            cfg.faults = vec![(
                c,
                Fault::Burst {
                    fibre: Fibre::P(k),
                    target,
                    bit: (at % w) as u32,
                    len: len as u32,
                    pattern: r.below(256) as u8,
                },
            )];
            if ring_sim::unsupported(&cfg).is_none() {
                p.push(name, "burst", cfg);
                break;
            }
        }
    }
}

/// Clock offsets on their own: a fault-free run and one with a break of a
/// seeded primary fibre, at the drawn offsets like every case, and a
/// fault-free run with every node at an extreme, alternating round the ring
/// (every link between opposite extremes).
fn offset_cases(p: &mut Planner) {
    if p.plan.ppm == 0.0 {
        return;
    }
    let n = p.clean.nodes.len();
    let mut r = p.rng("clock-offset");
    for run in 0..2 {
        let mut cfg = p.clean.clone();
        cfg.cycles = 10;
        if run == 1 {
            let k = r.below(n as u64) as usize;
            let brk = Fault::Break {
                fibre: Fibre::P(k),
                slot: None,
            };
            cfg.faults = vec![(FAULT_CYCLE, brk)];
        }
        p.push(
            format!("{}/clock-offset/drawn#{run}", p.ring),
            "clock-offset",
            cfg,
        );
    }
    let mut cfg = p.clean.clone();
    cfg.cycles = 10;
    let name = format!("{}/clock-offset/alternating", p.ring);
    p.push(name, "clock-offset", cfg);
    let bound = p.plan.ppm;
    if let Some(c) = p.out.last_mut() {
        for (k, nd) in c.cfg.nodes.iter_mut().enumerate() {
            nd.ppm = if k % 2 == 0 { bound } else { -bound };
        }
    }
}

/// Seeded line-bit errors at rate `ber` on every packet of every fibre of
/// the fault-free run in cycles 1 ..= [`BER_CYCLES`], at most one per
/// packet and fibre.
fn ber_flips(cfg: &Config, ber: f64, seed: u64) -> Vec<(u32, Fault)> {
    let recs = ring::run(cfg);
    let n = cfg.nodes.len();
    let mut r = Rng::new(seed);
    let mut v = vec![];
    for rec in recs.iter().skip(1).take(BER_CYCLES as usize) {
        // Words already hit in this cycle (on any fibre): a second flip in
        // a word that travels on damaged is a double error, which these
        // runs do not inject (the report says so).
        let mut hit: Vec<usize> = vec![];
        for (fi, carry) in rec.fibres.iter().enumerate() {
            // The frame's code bits (DATA frames: the harness places a flip
            // exactly only on a line bit that starts with an edge, a code 1;
            // where it has to estimate a boundary it can be half a bit off,
            // which a receiver reads as a slip, not as one bit error).
            let Carry::Data(fr) = carry else { continue };
            let ones = code_ones(cfg, fr);
            // Line bits per word: 25, or 30 with extended-alarm words (§6).
            let w = cfg.word_bits() as usize;
            let bits = 10 + w * (2 + cfg.slots);
            // P(at least one error in the packet), then a uniform position
            // among the bits the harness can place.
            let p = 1.0 - (1.0 - ber).powi(bits as i32);
            if r.unit() >= p || ones.is_empty() {
                continue;
            }
            let at = ones[r.below(ones.len() as u64) as usize];
            let (target, bit) = match at {
                0..=9 => (FlipTarget::Cs, at),
                _ if at < 10 + w => (FlipTarget::H0, at - 10),
                _ if at < 10 + 2 * w => (FlipTarget::H1, at - 10 - w),
                _ => (
                    FlipTarget::Slot((at - 10 - 2 * w) / w),
                    (at - 10 - 2 * w) % w,
                ),
            };
            let fibre = Fibre::from_index(fi, n);
            push_single(&mut v, &mut hit, w, at, rec.cycle, fibre, (target, bit));
        }
    }
    placeable(cfg, v)
}

/// Adds the flip of line bit `at` of a packet on `fibre` in cycle `c`
/// (`target`, and the bit in it) unless a word it touches — its own and,
/// at a word's last bit, the next (protocol §4); J K counts as word 0 —
/// was hit already in the cycle (`hit`, word positions in packets of `w`
/// line bits per word): a second flip in a word that travels on damaged
/// is a double error, which the campaign does not inject.
fn push_single(
    v: &mut Vec<(u32, Fault)>,
    hit: &mut Vec<usize>,
    w: usize,
    at: usize,
    c: u32,
    fibre: Fibre,
    (target, bit): (FlipTarget, usize),
) {
    let word = |a: usize| if a < 10 { 0 } else { 1 + (a - 10) / w };
    let words = [word(at), word(at + 1)];
    if words.iter().any(|x| hit.contains(x)) {
        return;
    }
    hit.extend(words);
    v.push((
        c,
        Fault::Flip {
            fibre,
            target,
            bit: bit as u32,
        },
    ));
}

/// The flips of `v` the RTL harness can place in `cfg`'s ring: errors can
/// change what a fibre carries later (a lost frame, a failsafe, a
/// retransmission packet), so only the flips that
/// [`ring_sim::flip_unsupported`] passes in the run with the errors
/// before them are kept.
fn placeable(cfg: &Config, mut v: Vec<(u32, Fault)>) -> Vec<(u32, Fault)> {
    let n = cfg.nodes.len();
    for _ in 0..8 {
        let mut with = cfg.clone();
        with.faults = v.clone();
        let got = ring::run(&with);
        let before = v.len();
        v.retain(|&(c, f)| ring_sim::flip_unsupported(&got, n, c, f).is_none());
        if v.len() == before {
            break;
        }
    }
    v
}

/// Seeded line-bit errors at rate `ber` in the retransmission packets
/// (protocol §8) of cycles 1 ..= [`BER_CYCLES`] as the run with `cfg`'s
/// faults sends them: on every fibre a packet travels, at most one, at a
/// code-1 line bit of its J K or of a request word the fibre carries good
/// or VOID (as [`code_ones`]), no word hit twice in a cycle.
fn rtx_flips(cfg: &Config, ber: f64, seed: u64) -> Vec<(u32, Fault)> {
    let recs = ring::run(cfg);
    let n = cfg.nodes.len();
    let w = cfg.word_bits() as usize;
    let head = 10 + 2 * w;
    let mut r = Rng::new(seed);
    let mut v = vec![];
    for rec in recs.iter().skip(1).take(BER_CYCLES as usize) {
        let Some(x) = &rec.rtx else { continue };
        let mut hit: Vec<usize> = vec![];
        for (&fi, on) in x.fibres.iter().zip(&x.on) {
            // P(at least one error in the packet), then a uniform position
            // among the bits the harness can place.
            let p = 1.0 - (1.0 - ber).powi(x.bits as i32);
            // (Without errors of its own on this fibre, the packet arrives
            // as it entered.)
            let ones = packet_ones(cfg, None, &on.words);
            if r.unit() >= p || !on.head_ok || ones.is_empty() {
                continue;
            }
            let at = ones[r.below(ones.len() as u64) as usize];
            let (target, bit) = if at < head {
                (FlipTarget::RtxHead, at)
            } else {
                (FlipTarget::Rtx((at - head) / w), (at - head) % w)
            };
            let fibre = Fibre::from_index(fi, n);
            push_single(&mut v, &mut hit, w, at, rec.cycle, fibre, (target, bit));
        }
    }
    v
}

/// Line-bit positions (from the J) of a DATA frame whose code bit is 1,
/// among the bits the harness can reach (from 2 on) in words whose code the
/// model knows (good or VOID).
fn code_ones(cfg: &Config, fr: &merkur_model::ring::Frame) -> Vec<usize> {
    let merkur_model::ring::HeaderRx::Ok(h) = fr.hdr else {
        return vec![];
    };
    packet_ones(cfg, Some([h.h0(cfg.slots), h.h1()]), &fr.words)
}

/// Line-bit positions (from the J) of a packet whose code bit is 1, among
/// the bits the harness can reach (from 2 on): J K, the header words when
/// given, and the words whose code the model knows (good or VOID).
fn packet_ones(
    cfg: &Config,
    header: Option<[merkur_model::line::Word; 2]>,
    words: &[Slot],
) -> Vec<usize> {
    use merkur_model::line::{push_group, void_code_bits, word_code_bits, CODE_J, CODE_K};
    let mut code: Vec<Option<u8>> = vec![];
    let mut jk = vec![];
    push_group(&mut jk, CODE_J);
    push_group(&mut jk, CODE_K);
    code.extend(jk.into_iter().map(Some));
    match header {
        Some(hw) => {
            for w in hw {
                code.extend(word_code_bits(&w, cfg.ext).into_iter().map(Some));
            }
        }
        None => code.extend(std::iter::repeat(None).take(2 * cfg.word_bits() as usize)),
    }
    for w in words {
        match w {
            Slot::Data(d) => code.extend(word_code_bits(d, cfg.ext).into_iter().map(Some)),
            Slot::Void => code.extend(void_code_bits(cfg.ext).into_iter().map(Some)),
            _ => code.extend(std::iter::repeat(None).take(cfg.word_bits() as usize)),
        }
    }
    code.iter()
        .enumerate()
        .filter(|&(i, b)| i >= 2 && *b == Some(1))
        .map(|(i, _)| i)
        .collect()
}

/// The special master's INPUT fibre in cycle c.
fn sm_input(cfg: &Config, recs: &[CycleRecord], c: usize) -> usize {
    let n = cfg.nodes.len();
    // (The clock base of cycle c: the special master, or a backup that
    // took over, protocol §8.)
    let sm = recs[c].base;
    let mode = if c == 0 {
        Mode::N
    } else {
        recs[c - 1].nodes[sm].mode
    };
    match table1(mode).0 {
        Port::Si => n + sm,
        _ => (sm + n - 1) % n,
    }
}

/// Whether cycle c's frame came back whole to the special master: its
/// header good (a damaged one hides the frame from every node after the
/// damage) and every word there.
fn returned_whole(cfg: &Config, recs: &[CycleRecord], c: usize) -> bool {
    match &recs[c].fibres[sm_input(cfg, recs, c)] {
        Carry::Data(fr) => {
            matches!(fr.hdr, merkur_model::ring::HeaderRx::Ok(_))
                && !fr.words.iter().any(|w| matches!(w, Slot::Missing))
        }
        _ => false,
    }
}

/// Per slot, whether it came back good to the special master in cycle c.
fn returned(cfg: &Config, recs: &[CycleRecord], c: usize) -> Vec<bool> {
    match &recs[c].fibres[sm_input(cfg, recs, c)] {
        Carry::Data(fr) => fr
            .words
            .iter()
            .map(|w| matches!(w, Slot::Data(_)))
            .collect(),
        _ => vec![false; cfg.slots],
    }
}

/// Runs one case through the model (and, unless `model_only`, the RTL)
/// and measures it against the same ring without faults.
fn run_case(case: &Case, wave: Option<&Path>, model_only: bool) -> CaseResult {
    let cfg = &case.cfg;
    let recs = ring::run(cfg);
    let clean = ring::run(&clean_config(cfg, &recs));
    let mut res = model_result(case, &recs, &clean, model_only);
    if model_only {
        return res;
    }
    if let Some(why) = ring_sim::unsupported(cfg) {
        res.mismatches = 1;
        res.first = vec![format!("not simulated in RTL: {why}")];
        return res;
    }
    let opts = Options {
        seed: case.seed,
        wave: wave.map(Path::to_path_buf),
        ..Default::default()
    };
    match ring_sim::run(cfg, &recs, &opts) {
        Ok(rep) => {
            rtl_result(&mut res, cfg, &recs, &clean, &rep);
            fault_timing(&mut res, cfg, &recs, &rep);
        }
        Err(e) => {
            res.mismatches = 1;
            res.first = vec![format!("error: {e}")];
        }
    }
    res
}

/// The case's ring without faults, the reference of what it should
/// deliver. After a takeover, a fault-free ring with the new clock base
/// (protocol §8, "Memories after the takeover": the retransmission point
/// moved with it).
fn clean_config(cfg: &Config, recs: &[CycleRecord]) -> Config {
    let mut clean_cfg = cfg.clone();
    clean_cfg.faults.clear();
    if let Some(e) = recs
        .iter()
        .flat_map(|x| &x.events)
        .find(|e| matches!(e.kind, EventKind::Takeover { .. }))
    {
        clean_cfg.sm = e.node;
    }
    clean_cfg
}

/// The structural faults of a case (breaks, repairs, deaths, restarts:
/// not the flips and bursts), in order.
fn structural_faults(cfg: &Config) -> Vec<(u32, Fault)> {
    cfg.faults
        .iter()
        .copied()
        .filter(|(_, f)| !matches!(f, Fault::Flip { .. } | Fault::Burst { .. }))
        .collect()
}

/// The model's side of a case's result: failsafe, words and cycles lost
/// against the clean ring `clean`, cycles to recover.
fn model_result(
    case: &Case,
    recs: &[CycleRecord],
    clean: &[CycleRecord],
    model_only: bool,
) -> CaseResult {
    let cfg = &case.cfg;
    let structural = structural_faults(cfg);
    let dead = cfg.killed();
    let last = recs.last().expect("cycles > 0");
    let failsafe = last
        .nodes
        .iter()
        .enumerate()
        .any(|(k, x)| x.failsafe && !dead.contains(&k));
    let mut words_lost = 0;
    let mut cycles_lost = 0;
    for c in 0..recs.len() {
        let (a, b) = (returned(cfg, recs, c), returned(cfg, clean, c));
        words_lost += a.iter().zip(&b).filter(|(x, y)| **y && !**x).count() as u64;
        if returned_whole(cfg, clean, c) && !returned_whole(cfg, recs, c) {
            cycles_lost += 1;
        }
    }
    let first_fault = cfg.faults.iter().map(|&(c, _)| c).min();
    let mut from = None;
    for (x, y) in recs.iter().zip(clean) {
        if ring::delivered(cfg, x) == ring::delivered(cfg, y) {
            from.get_or_insert(x.cycle);
        } else {
            from = None;
        }
    }
    let cycles_to_recover = match (first_fault, from) {
        (Some(c), Some(f)) => Some(f.saturating_sub(c)),
        (None, _) => Some(0),
        _ => None,
    };
    let last_fault = cfg.faults.iter().map(|&(c, _)| c).max();
    let cycles_after_last = match (last_fault, from) {
        (Some(c), Some(f)) => Some(f.saturating_sub(c + 1)),
        (None, _) => Some(0),
        _ => None,
    };
    let flips = cfg
        .faults
        .iter()
        .filter(|(_, f)| matches!(f, Fault::Flip { .. }))
        .count() as u32;
    CaseResult {
        name: case.name.clone(),
        ring: case.ring.clone(),
        nodes: cfg.nodes.len(),
        class: case.class.to_string(),
        faults: cfg
            .faults
            .iter()
            .map(|(c, f)| format!("cycle {c}: {f}"))
            .collect(),
        seed: case.seed,
        ppm: cfg.nodes.iter().map(|x| x.ppm).collect(),
        mismatches: 0,
        first: vec![],
        words: 0,
        healed: !structural.is_empty() && !failsafe,
        failsafe,
        words_lost,
        cycles_lost,
        rtl_cycles_lost: 0,
        cycles_to_recover,
        cycles_after_last,
        ber: case.ber,
        rtx: case
            .rtx
            .as_ref()
            .map(|(on, critical)| rtx_age(cfg, *on, critical, recs, clean)),
        rtl: !model_only,
        detect_bits: None,
        switchover_bits: None,
        failsafe_bits: None,
        takeover_bits: None,
        period_bits: Some(cfg.period as f64),
        mbps: cfg.line_rate_mbps,
        flips,
        accepted: 0,
        wall_s: 0.0,
    }
}

/// A retransmission case's data age by slot class against the clean ring,
/// and its packets (model).
fn rtx_age(
    cfg: &Config,
    on: bool,
    critical: &[bool],
    recs: &[CycleRecord],
    clean: &[CycleRecord],
) -> RtxAge {
    let [crit, other] = ring::age_stats(cfg, critical, recs, clean, 1);
    let sent: Vec<_> = recs
        .iter()
        .filter_map(|r| r.rtx.as_ref())
        .filter(|x| !x.slots.is_empty())
        .collect();
    RtxAge {
        on,
        critical: (0..critical.len()).filter(|&s| critical[s]).collect(),
        crit: crit.into(),
        other: other.into(),
        packets: sent.len() as u32,
        requests: sent.iter().map(|x| x.slots.len() as u32).sum(),
        left: recs
            .iter()
            .filter_map(|r| r.rtx.as_ref())
            .map(|x| x.left as u32)
            .sum(),
        bits: sent.iter().map(|x| x.bits as u64).sum(),
    }
}

/// The RTL run's side: its mismatches, the cycles whose frame did not
/// come back whole, and every flipped word the RTL took as good where the
/// model says bad.
fn rtl_result(
    res: &mut CaseResult,
    cfg: &Config,
    recs: &[CycleRecord],
    clean: &[CycleRecord],
    rep: &ring_sim::Report,
) {
    res.wall_s = rep.wall.as_secs_f64();
    res.rtl_cycles_lost = (0..recs.len())
        .filter(|&c| returned_whole(cfg, clean, c) && !rep.returned_whole[c])
        .count() as u32;
    res.words = rep.words;
    res.mismatches = rep.mismatches.len();
    res.first = rep
        .mismatches
        .iter()
        .take(5)
        .map(|m| m.to_string())
        .collect();
    for (c, f) in &cfg.faults {
        if let Fault::Flip { fibre, target, .. } = f {
            let what = match target {
                FlipTarget::Slot(s) => format!("slot {s}"),
                _ => continue,
            };
            let place = fibre.to_string();
            res.accepted += rep
                .mismatches
                .iter()
                .filter(|m| m.cycle == *c && m.place == place && m.what == what)
                .filter(|m| m.got.len() >= 5 && m.expected == "x")
                .count() as u32;
        }
    }
}

/// The RTL's timing of the faults, in bit times: from the first
/// structural fault to the first and the last switchbox change it caused
/// (detection, switchover), from the clock base's death to the elected
/// backup's first frame (takeover), from the last structural fault to the
/// last live node in failsafe.
fn fault_timing(res: &mut CaseResult, cfg: &Config, recs: &[CycleRecord], rep: &ring_sim::Report) {
    let structural = structural_faults(cfg);
    let dead = cfg.killed();
    let bits = |t: u64| t as f64 / TICKS_PER_BIT as f64;
    if let Some(Some(t0)) = structural
        .first()
        .and_then(|x| cfg.faults.iter().position(|y| y == x))
        .map(|i| rep.fault_ticks[i])
    {
        // Switchbox changes the first fault caused: before any later fault
        // and within two periods.
        let until = structural
            .get(1)
            .and_then(|x| cfg.faults.iter().position(|y| y == x))
            .and_then(|i| rep.fault_ticks[i])
            .unwrap_or(u64::MAX)
            .min(t0 + 2 * cfg.period as u64 * TICKS_PER_BIT as u64);
        let ch: Vec<u64> = rep
            .mode_ticks
            .iter()
            .filter(|&&(k, t, _)| t > t0 && t < until && !dead.contains(&k))
            .map(|&(_, t, _)| t)
            .collect();
        res.detect_bits = ch.iter().min().map(|&t| bits(t - t0));
        res.switchover_bits = ch.iter().max().map(|&t| bits(t - t0));
    }
    // The takeover (protocol §8): from the clock base's death to the
    // elected backup's first frame.
    let takeover = recs
        .iter()
        .flat_map(|x| &x.events)
        .find(|e| matches!(e.kind, EventKind::Takeover { .. }))
        .map(|e| e.cycle as usize);
    let death = cfg
        .faults
        .iter()
        .position(|&(_, f)| matches!(f, Fault::Kill { node, .. } if node == cfg.sm));
    if let (Some(t), Some(Some(t0))) = (takeover, death.map(|i| rep.fault_ticks[i])) {
        res.takeover_bits = rep.starts.get(t).map(|&s| bits(s.saturating_sub(t0)));
    }
    if res.failsafe {
        if let Some(Some(tl)) = cfg
            .faults
            .iter()
            .rposition(|(_, f)| !matches!(f, Fault::Flip { .. } | Fault::Burst { .. }))
            .map(|i| rep.fault_ticks[i])
        {
            let live: Vec<Option<u64>> = rep
                .fs_ticks
                .iter()
                .enumerate()
                .filter(|(k, _)| !dead.contains(k))
                .map(|(_, t)| *t)
                .collect();
            if live.iter().all(|t| t.is_some()) {
                let t = live.iter().flatten().max().copied().unwrap_or(tl);
                res.failsafe_bits = Some(bits(t.saturating_sub(tl)));
            }
        }
    }
}

/// The case classes, as the report names them and `--only` takes them.
pub const CLASSES: &[&str] = &[
    "break-primary",
    "break-secondary",
    "node-death",
    "sm-fibres",
    "sm-takeover",
    "double",
    "repair",
    "double-repair",
    "restart",
    "bit-errors",
    "retransmission",
    "burst",
    "clock-offset",
];

/// `--shard K/N` as clap parses it (1 ≤ K ≤ N).
pub fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || "expected K/N with 1 <= K <= N, e.g. 2/4".to_string();
    let (k, n) = s.split_once('/').ok_or_else(bad)?;
    let (k, n): (usize, usize) = (
        k.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if k == 0 || n == 0 || k > n {
        return Err(bad());
    }
    Ok((k, n))
}

/// How many cases `--singles`/`--doubles` ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Count {
    /// Every case of the class.
    All,
    /// A seeded sample of this many.
    Sample(usize),
}

impl Count {
    /// The sample size, `None` for every case.
    pub fn limit(self) -> Option<usize> {
        match self {
            Count::All => None,
            Count::Sample(n) => Some(n),
        }
    }
}

/// `--singles`/`--doubles` as clap parses them: a number or `all`.
pub fn parse_count(s: &str) -> Result<Count, String> {
    match s.trim() {
        "all" => Ok(Count::All),
        x => x
            .parse()
            .map(Count::Sample)
            .map_err(|_| "expected a number of cases or `all`".to_string()),
    }
}

/// The highest bit error rate `--ber` takes (one bit in two).
pub const MAX_BER: f64 = 0.5;

/// The widest clock offset `--ppm` takes (protocol §8: oscillators within
/// ±1000 ppm).
pub const MAX_PPM: f64 = 1000.0;

/// `--ber`: bit error rates, or none.
#[derive(Clone, Debug, PartialEq)]
pub struct BerList(pub Vec<f64>);

/// `--ber` as clap parses it: a comma list of rates in 0 ..= [`MAX_BER`],
/// or `none`.
pub fn parse_ber(s: &str) -> Result<BerList, String> {
    if s.trim().is_empty() || s.trim() == "none" {
        return Ok(BerList(vec![]));
    }
    s.split(',')
        .map(|x| {
            let v: f64 = x
                .trim()
                .parse()
                .map_err(|_| format!("`{}` is not a number", x.trim()))?;
            if !(v.is_finite() && (0.0..=MAX_BER).contains(&v)) {
                return Err(format!("{v} is outside 0 ..= {MAX_BER}"));
            }
            Ok(v)
        })
        .collect::<Result<_, _>>()
        .map(BerList)
}

/// `--ppm` as clap parses it: a bound in 0 ..= [`MAX_PPM`].
pub fn parse_ppm(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() && (0.0..=MAX_PPM).contains(&v) {
        Ok(v)
    } else {
        Err(format!(
            "outside 0 ..= {MAX_PPM} (protocol §8: oscillators within ±{MAX_PPM} ppm)"
        ))
    }
}

/// Every case of the plan, in order.
fn all_cases(plan: &Plan) -> Result<Vec<Case>, String> {
    let mut cases = vec![];
    for path in &plan.rings {
        let (_, base) = crate::read_scenario(path)?;
        let ring_name = base.name.clone();
        if let Some(why) = ring_sim::unsupported(&Config {
            faults: vec![],
            ..base.clone()
        }) {
            return Err(format!(
                "error: --ring {}: not simulated in RTL: {why}",
                path.display()
            ));
        }
        cases.extend(cases_of(&ring_name, &base, plan));
    }
    if !plan.only.is_empty() {
        cases.retain(|c| plan.only.iter().any(|o| o == c.class));
    }
    if let Some(want) = &plan.case {
        cases.retain(|c| &c.name == want);
        if cases.is_empty() {
            return Err(format!("error: --case {want}: no such case in this campaign (names are listed in the report)"));
        }
    }
    Ok(cases)
}

/// Writes the case `--case` names as a scenario file (`--export`) and
/// prints the command that runs it as the campaign does.
pub fn export(plan: &Plan) -> Result<(), String> {
    let (Some(name), Some(file)) = (&plan.case, &plan.export) else {
        return Err("error: --export needs --case: one case is written as a scenario".into());
    };
    let cases = all_cases(plan)?;
    let case = &cases[0];
    let text = format!(
        "# merkur campaign case {name} (campaign seed {}); its RTL run: merkur sim FILE --seed {}\n{}",
        plan.seed,
        case.seed,
        case.cfg.to_scenario(&format!("campaign case {name}"))
    );
    crate::write_atomic(file, &text)?;
    eprintln!(
        "wrote {}; run it as the campaign does: merkur sim {} --seed {}",
        file.display(),
        file.display(),
        case.seed
    );
    Ok(())
}

/// Runs the campaign; returns the report.
pub fn run(plan: &Plan, command: String) -> Result<Report, String> {
    let cases = all_cases(plan)?;
    let total = cases.len();
    let (k, n) = plan.shard;
    let mine: Vec<Case> = cases
        .into_iter()
        .enumerate()
        .filter(|(i, _)| i % n == k - 1)
        .map(|(_, c)| c)
        .collect();
    eprintln!(
        "campaign: {} cases (shard {k}/{n} of {total}), {} parallel; Verilator models are built once per ring and cached",
        mine.len(),
        plan.jobs
    );
    // Build (or find) each ring's Verilator model once, before the workers.
    // (One model per ring text: a ring with backups or restarts is
    // another text than the same ring without.)
    let mut built = std::collections::BTreeSet::new();
    for c in mine.iter().filter(|_| !plan.model_only) {
        let v = ring_sim::ring_verilog_of(&c.cfg);
        if built.insert(std::sync::Arc::as_ptr(&v) as usize) {
            let step = progress::Step::start(format!("model of {}", c.ring));
            merkur_sim::verilator::Model::build_top_traced(&v, "merkur_ring", None)?;
            step.done("ready");
        }
    }
    let done = AtomicUsize::new(0);
    let failed = AtomicUsize::new(0);
    let bar = progress::Bar::new(mine.len() as u64, "cases");
    let workers = progress::Workers::new(plan.jobs.min(mine.len()));
    let run = merkur_sim::jobs::run(&mine, plan.jobs, |case| {
        let r = workers.run(&case.name, || {
            run_case(case, plan.wave.as_deref(), plan.model_only)
        });
        let d = done.fetch_add(1, Ordering::SeqCst) + 1;
        let bad = r.mismatches > 0;
        let f = failed.fetch_add(usize::from(bad), Ordering::SeqCst) + usize::from(bad);
        bar.set(d as u64, &format!("{f} with mismatches"));
        if bad {
            progress::line(&format!(
                "MISMATCH {} (seed {}, offsets ppm {}): {}",
                case.name,
                case.seed,
                offsets(&case.cfg),
                r.first.join("; ")
            ));
        }
        Ok(r)
    });
    workers.finish();
    bar.finish();
    let mut cases = run?;
    cases.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(Report {
        commands: vec![command],
        cases,
    })
}

/// The nodes' clock offsets, `+310,-640,…` in node order.
fn offsets(cfg: &Config) -> String {
    ppm_list(&cfg.nodes.iter().map(|x| x.ppm).collect::<Vec<_>>())
}

fn ppm_list(v: &[f64]) -> String {
    v.iter()
        .map(|p| format!("{p:+}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// Joins shard reports (cases by name; a case in two reports must agree).
pub fn merge(paths: &[PathBuf]) -> Result<Report, String> {
    let mut by_name: BTreeMap<String, CaseResult> = BTreeMap::new();
    let mut commands = vec![];
    for p in paths {
        let text = std::fs::read_to_string(p)
            .map_err(|e| format!("error: --merge {}: cannot read: {e}", p.display()))?;
        let r: Report = serde_json::from_str(&text).map_err(|e| {
            format!(
                "error: --merge {}: not a campaign JSON report: {e}",
                p.display()
            )
        })?;
        commands.extend(r.commands);
        for c in r.cases {
            by_name.insert(c.name.clone(), c);
        }
    }
    Ok(Report {
        commands,
        cases: by_name.into_values().collect(),
    })
}

fn us(bits: f64, mbps: f64) -> f64 {
    bits / mbps
}

fn stat<I: Iterator<Item = f64>>(it: I) -> (usize, f64, f64) {
    let v: Vec<f64> = it.collect();
    if v.is_empty() {
        return (0, 0.0, 0.0);
    }
    let max = v.iter().cloned().fold(f64::MIN, f64::max);
    (v.len(), v.iter().sum::<f64>() / v.len() as f64, max)
}

/// The Markdown report.
pub fn markdown(r: &Report) -> String {
    let mut o = String::new();
    o += "# merkur fault-injection campaign\n\n";
    o += "Produced by:\n\n";
    for c in &r.commands {
        o += &format!("    {c}\n");
    }
    if r.cases.iter().all(|c| !c.rtl) {
        o += "\n**Model only** (`--model-only`): every case ran through the reference model, none through the RTL, so nothing was compared and the *RTL* columns are empty; the *model* columns are the protocol's behaviour.\n\n";
    } else {
        o += "\nEvery case runs the ring through the reference model and through the RTL (Verilator) and compares them under the recovery-window rules of docs/protocol.md §13. *Model* columns are the protocol's behaviour (the RTL agreed wherever mismatches are 0); *RTL* columns are measured in the Verilator run (switchbox and failsafe states polled every 2 bit times). Times in µs are at the ring's line rate.\n\n";
    }
    let mism: usize = r.cases.iter().filter(|c| c.mismatches > 0).count();
    let accepted: u32 = r.cases.iter().map(|c| c.accepted).sum();
    let flips: u32 = r.cases.iter().map(|c| c.flips).sum();
    o += &format!(
        "**{} cases, {} with mismatches against the model; {} bit flips injected, {} single-bit errors accepted.** Multi-bit errors in one word: not injected (at most one flip per packet and fibre, and per word and cycle across the ring: a word damaged on one hop travels on damaged, and a second flip on a later hop can restore both parities, which is a double error), so none can be reported undetected here; the model's exhaustive check of every single line-bit error is `model/tests/line.rs`.\n\n",
        r.cases.len(), mism, flips, accepted
    );
    let mut groups: BTreeMap<(usize, String, String), Vec<&CaseResult>> = BTreeMap::new();
    for c in &r.cases {
        groups
            .entry((c.nodes, c.ring.clone(), c.class.clone()))
            .or_default()
            .push(c);
    }
    o += "| ring | class | cases | mismatches | healed | failsafe | words lost (max) | frames lost, model / RTL (max) | cycles to recover (max) | detection, bit times (mean / max) | switchover, µs (mean / max) | failsafe latency, µs (max) | flips | accepted |\n";
    o += "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for ((_, ring, class), cs) in &groups {
        let (nd, dm, dx) = stat(cs.iter().filter_map(|c| c.detect_bits));
        let (ns, sm, sx) = stat(
            cs.iter()
                .filter_map(|c| c.switchover_bits.map(|b| us(b, c.mbps))),
        );
        let (nf, _, fx) = stat(
            cs.iter()
                .filter_map(|c| c.failsafe_bits.map(|b| us(b, c.mbps))),
        );
        let frames = format!(
            "{} / {}",
            cs.iter().map(|c| c.cycles_lost).max().unwrap_or(0),
            cs.iter().map(|c| c.rtl_cycles_lost).max().unwrap_or(0)
        );
        let rec = cs.iter().map(|c| c.cycles_to_recover);
        let structural = cs
            .iter()
            .any(|c| c.switchover_bits.is_some() || c.healed || c.failsafe);
        let rec_max = if !structural {
            "–".to_string()
        } else if rec.clone().any(|x| x.is_none()) {
            "never (failsafe)".to_string()
        } else {
            rec.flatten().max().unwrap_or(0).to_string()
        };
        o +=
            &format!(
            "| {ring} | {class} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            cs.len(),
            cs.iter().filter(|c| c.mismatches > 0).count(),
            cs.iter().filter(|c| c.healed).count(),
            cs.iter().filter(|c| c.failsafe).count(),
            cs.iter().map(|c| c.words_lost).max().unwrap_or(0),
            frames,
            rec_max,
            if nd > 0 { format!("{dm:.1} / {dx:.1}") } else { "–".into() },
            if ns > 0 { format!("{sm:.2} / {sx:.2}") } else { "–".into() },
            if nf > 0 { format!("{fx:.2}") } else { "–".into() },
            cs.iter().map(|c| c.flips).sum::<u32>(),
            cs.iter().map(|c| c.accepted).sum::<u32>(),
        );
    }
    o += &ber_table(r);
    o += &rtx_table(r);
    o += &takeover_table(r);
    let bad: Vec<&CaseResult> = r.cases.iter().filter(|c| c.mismatches > 0).collect();
    if !bad.is_empty() {
        o += "\n## Cases with mismatches\n\n";
        for c in bad {
            o += &format!(
                "- `{}` (seed {}, node offsets {} ppm, {} mismatches; rerun: the command above with `--case '{}'`, and `--wave FILE` for its waveform): {}\n",
                c.name,
                c.seed,
                ppm_list(&c.ppm),
                c.mismatches,
                c.name,
                c.first.join("; ")
            );
        }
    }
    o += "\nColumns: *healed* — after a structural fault every live node is out of failsafe at the end (model); *words lost* — slot words that came back to the special master good in the fault-free ring but not in this one (the cut frame's rest and the RECONFIG alarms' home slots); *frames lost* — frames that did not come back whole to the special master where the fault-free ring's did (model / RTL monitors: a break in the last ~100 bit times of a frame also costs the next frame's head in RTL, protocol §13); *cycles to recover* — from the first fault until every live node holds what the fault-free ring's nodes hold, for good (`merkur_model::ring::delivered`: slots whose writer lives, and a master's ACT slots whose actuator lives); *detection* — from the fault to the first switchbox change (RTL); *switchover* — to the last one it caused, the ring wrapped at both ends (RTL); *failsafe latency* — from the second fault until every live node is in failsafe (RTL); *accepted* — flipped words a receiver took as good.\n";
    o
}

/// The takeovers by ring: from the special master's death to the elected
/// backup's first frame (RTL), in bit times, µs and periods.
fn takeover_table(r: &Report) -> String {
    let mut by_ring: BTreeMap<(usize, String), Vec<&CaseResult>> = BTreeMap::new();
    for c in r.cases.iter().filter(|c| c.takeover_bits.is_some()) {
        by_ring
            .entry((c.nodes, c.ring.clone()))
            .or_default()
            .push(c);
    }
    if by_ring.is_empty() {
        return String::new();
    }
    let mut o = String::from(
        "\n## Takeovers (the flying special master, protocol §8)\n\nFrom the special master's death to the first frame of the backup that took over, in the RTL (the death's moment is the harness's fault injection, the frame's the frame counter's change, both at 4-tick resolution).\n\n| ring | takeovers | bit times (min / mean / max) | µs (mean / max) | periods (max) |\n|---|---|---|---|---|\n",
    );
    for ((_, ring), cs) in &by_ring {
        let b: Vec<f64> = cs.iter().filter_map(|c| c.takeover_bits).collect();
        let (n, mean, max) = stat(b.iter().copied());
        let min = b.iter().cloned().fold(f64::MAX, f64::min);
        let mbps = cs[0].mbps;
        let period = cs[0].period_bits.unwrap_or(0.0);
        let periods = if period > 0.0 {
            format!("{:.2}", max / period)
        } else {
            "–".into()
        };
        o += &format!(
            "| {ring} | {n} | {min:.0} / {mean:.0} / {max:.0} | {:.1} / {:.1} | {periods} |\n",
            us(mean, mbps),
            us(max, mbps)
        );
    }
    o
}

/// The bit-error runs by ring and rate: what a rate costs (model).
fn ber_table(r: &Report) -> String {
    let mut by: BTreeMap<(usize, String, u64), Vec<&CaseResult>> = BTreeMap::new();
    for c in r.cases.iter().filter(|c| c.class == "bit-errors") {
        let rate = c.ber.unwrap_or(0.0);
        // Keyed by the rate's bits, highest rate first.
        by.entry((c.nodes, c.ring.clone(), u64::MAX - rate.to_bits()))
            .or_default()
            .push(c);
    }
    if by.is_empty() {
        return String::new();
    }
    let mut o = format!("\n## Bit errors by rate\n\nErrors in cycles 1 … {BER_CYCLES} (at most one per packet and fibre), then {CLEAN_CYCLES} clean cycles. *Healthy after* — cycles after the last cycle with errors until every live node's memory equals the fault-free ring's for good (model).\n\n");
    o += "| ring | BER | runs | runs in failsafe at the end | flips (mean) | words lost (mean / max) | frames lost (mean / max) | healthy after, cycles (max) |\n";
    o += "|---|---|---|---|---|---|---|---|\n";
    for ((_, ring, _), cs) in &by {
        let n = cs.len() as f64;
        let mean = |f: &dyn Fn(&CaseResult) -> f64| cs.iter().map(|c| f(c)).sum::<f64>() / n;
        let never = cs.iter().filter(|c| c.cycles_after_last.is_none()).count();
        let after = match cs.iter().filter_map(|c| c.cycles_after_last).max() {
            Some(m) if never == 0 => m.to_string(),
            Some(m) => format!("{m}; never in {never}"),
            None => format!("never in {never}"),
        };
        o += &format!(
            "| {ring} | {:e} | {} | {} | {:.1} | {:.1} / {} | {:.2} / {} | {after} |\n",
            cs[0].ber.unwrap_or(0.0),
            cs.len(),
            cs.iter().filter(|c| c.failsafe).count(),
            mean(&|c| c.flips as f64),
            mean(&|c| c.words_lost as f64),
            cs.iter().map(|c| c.words_lost).max().unwrap_or(0),
            mean(&|c| c.cycles_lost as f64),
            cs.iter().map(|c| c.cycles_lost).max().unwrap_or(0),
        );
    }
    o
}

/// The retransmission runs by ring, rate and on/off: data age per slot
/// class and the bandwidth the packets took (model).
fn rtx_table(r: &Report) -> String {
    type Key = (usize, String, u64, bool);
    let mut by: BTreeMap<Key, Vec<(&CaseResult, &RtxAge)>> = BTreeMap::new();
    for c in &r.cases {
        if let Some(x) = &c.rtx {
            let rate = c.ber.unwrap_or(0.0);
            by.entry((c.nodes, c.ring.clone(), u64::MAX - rate.to_bits(), !x.on))
                .or_default()
                .push((c, x));
        }
    }
    if by.is_empty() {
        return String::new();
    }
    let mut o = format!("\n## Retransmission on demand: data age by slot class\n\nProtocol §8. The ring with slots 1 … slots / 3 critical (at most {RTX_MAX}) at the shortest period with room for a request per critical slot; errors in cycles 1 … {BER_CYCLES} in the DATA frames and the retransmission packets (at most one per packet and fibre), then {CLEAN_CYCLES} clean cycles. *Off* — the same ring, period and frame errors with no slot critical. Ages in cycles, from cycle 1 on, over every live master's memory of the slots it does not write and every actuator's output; *older* — copies older than the same copy in the ring without errors (the goal for critical slots with retransmission on: 0). Model; the RTL agreed wherever the case has no mismatches.\n\n");
    o += "| ring | BER | retransmission | runs | flips (mean) | critical: worst / mean age, older of copies | other slots: worst / mean age, older of copies | packets, requests (not fitted) | bits per cycle (% of period) |\n";
    o += "|---|---|---|---|---|---|---|---|---|\n";
    for ((_, ring, _, _), cs) in &by {
        let class = |f: &dyn Fn(&RtxAge) -> AgeClass| {
            let v: Vec<AgeClass> = cs.iter().map(|(_, x)| f(x)).collect();
            let copies: u64 = v.iter().map(|a| a.copies).sum();
            let sum: f64 = v.iter().map(|a| a.mean * a.copies as f64).sum();
            format!(
                "{} / {:.3}, {} of {copies}",
                v.iter().map(|a| a.worst).max().unwrap_or(0),
                sum / copies.max(1) as f64,
                v.iter().map(|a| a.older).sum::<u64>()
            )
        };
        let (c0, x0) = cs[0];
        let n = cs.len() as f64;
        let cycles = n * (1 + BER_CYCLES + CLEAN_CYCLES) as f64;
        let bits: u64 = cs.iter().map(|(_, x)| x.bits).sum();
        let per = bits as f64 / cycles.max(1.0);
        o += &format!(
            "| {ring} | {:e} | {} | {} | {:.1} | {} | {} | {}, {} ({}) | {per:.1} ({:.2} %) |\n",
            c0.ber.unwrap_or(0.0),
            if x0.on { "on" } else { "off" },
            cs.len(),
            cs.iter().map(|(c, _)| c.flips as f64).sum::<f64>() / n,
            class(&|x| x.crit),
            class(&|x| x.other),
            cs.iter().map(|(_, x)| x.packets).sum::<u32>(),
            cs.iter().map(|(_, x)| x.requests).sum::<u32>(),
            cs.iter().map(|(_, x)| x.left).sum::<u32>(),
            100.0 * per / c0.period_bits.unwrap_or(f64::INFINITY),
        );
    }
    o
}

/// Writes `campaign.md` and `campaign.json` into `dir` (atomically).
pub fn write(report: &Report, dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("error: --output {}: cannot create: {e}", dir.display()))?;
    let json = serde_json::to_string_pretty(report).map_err(|e| format!("error: {e}"))?;
    crate::write_atomic(&dir.join("campaign.json"), &json)?;
    crate::write_atomic(&dir.join("campaign.md"), &markdown(report))?;
    eprintln!(
        "wrote {} and {}",
        dir.join("campaign.md").display(),
        dir.join("campaign.json").display()
    );
    Ok(())
}

/// The campaign's default rings, built into the binary (an installed
/// `merkur campaign` runs from any folder): their names (as in the
/// checkout, where the same files are) and texts.
pub const EMBEDDED_RINGS: [(&str, &str); 3] = [
    (
        "tb-data/ring8.toml",
        include_str!("../../tb-data/ring8.toml"),
    ),
    (
        "tb-data/ring32.toml",
        include_str!("../../tb-data/ring32.toml"),
    ),
    (
        "tb-data/ring100.toml",
        include_str!("../../tb-data/ring100.toml"),
    ),
];

/// Default base rings: the 8-node ring, or 8, 32 and 100 nodes
/// ([`EMBEDDED_RINGS`]).
pub fn default_rings(full: bool) -> Vec<PathBuf> {
    let k = if full { EMBEDDED_RINGS.len() } else { 1 };
    EMBEDDED_RINGS[..k]
        .iter()
        .map(|(name, _)| PathBuf::from(name))
        .collect()
}
