//! A validated ring configuration, built from a [`RawScenario`].
//! Every rule of docs/protocol.md §7 and §10 that a configuration can break
//! is checked here, with an error naming the field and value.

use crate::line::word_bits;
use crate::scenario::*;
use std::collections::BTreeMap;
use std::fmt;
use toml::Spanned;

/// Bits of the start delimiter JK.
pub const JK_BITS: u32 = 10;
/// Smallest gap between frames: 4 idle groups.
pub const MIN_GAP_BITS: u32 = 20;
/// Upper bound of one node's delay on the processing path, in bit times.
pub const NODE_DELAY_BITS: u32 = 12;
/// Upper bound of one node's delay on the secondary pass-through, in bit times.
pub const PASS_DELAY_BITS: u32 = 12;
/// Reintegration needs this many TST periods inside one cycle.
pub const MIN_PERIOD_BITS: u32 = 300;

/// A fibre: `P(k)` runs node k PO -> node k+1 PI, `S(k)` node k+1 SO -> node k SI.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Fibre {
    /// Primary fibre k.
    P(usize),
    /// Secondary fibre k.
    S(usize),
}

impl Fibre {
    /// The fibre's index in a ring of `n` nodes: `P(k)` is k, `S(k)` is
    /// n + k — the order of the model's fibre list, the golden trace's and
    /// the RTL ring top's fibres (the one helper for it; [`Fibre::from_index`]
    /// is its inverse).
    pub fn index(self, n: usize) -> usize {
        match self {
            Fibre::P(k) => k,
            Fibre::S(k) => n + k,
        }
    }

    /// The fibre of index `f` (< 2n) in a ring of `n` nodes.
    pub fn from_index(f: usize, n: usize) -> Fibre {
        if f < n {
            Fibre::P(f)
        } else {
            Fibre::S(f - n)
        }
    }
}

impl fmt::Display for Fibre {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fibre::P(k) => write!(f, "P{k}"),
            Fibre::S(k) => write!(f, "S{k}"),
        }
    }
}

impl Fibre {
    /// Parses `P3` / `S0` for a ring of `n` nodes.
    pub fn parse(s: &str, n: usize) -> Result<Fibre, String> {
        let bad = || {
            format!(
                "fibre = \"{s}\" is not a fibre of this ring: use P0..P{m} or S0..S{m}",
                m = n - 1
            )
        };
        let (kind, num) = s.split_at(s.char_indices().nth(1).map(|(i, _)| i).unwrap_or(0));
        let k: usize = num.parse().map_err(|_| bad())?;
        if k >= n {
            return Err(bad());
        }
        match kind {
            "P" | "p" => Ok(Fibre::P(k)),
            "S" | "s" => Ok(Fibre::S(k)),
            _ => Err(bad()),
        }
    }
}

/// Which word of a frame a bit flip hits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlipTarget {
    /// The start delimiter JK.
    Cs,
    /// Header word 0.
    H0,
    /// Header word 1.
    H1,
    /// A slot word.
    Slot(usize),
    /// The retransmission packet's start delimiter or header (§8): the
    /// packet is lost to every node behind the error.
    RtxHead,
    /// Word j of the retransmission packet after its header (request
    /// j / 2: its index word if j is even, its data word if odd).
    Rtx(usize),
}

impl fmt::Display for FlipTarget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FlipTarget::Cs => write!(f, "cs"),
            FlipTarget::H0 => write!(f, "h0"),
            FlipTarget::H1 => write!(f, "h1"),
            FlipTarget::Slot(s) => write!(f, "s{s}"),
            FlipTarget::RtxHead => write!(f, "rtx_head"),
            FlipTarget::Rtx(j) => write!(f, "rtx{j}"),
        }
    }
}

/// A validated fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// Fibre goes dark before `slot` (None: before the start delimiter).
    Break {
        /// The fibre.
        fibre: Fibre,
        /// Slot before which it happens (None: before the delimiter).
        slot: Option<usize>,
    },
    /// Fibre carries light again.
    Repair {
        /// The fibre.
        fibre: Fibre,
        /// Slot before which it happens (None: before the delimiter).
        slot: Option<usize>,
    },
    /// Node dies before `slot`.
    Kill {
        /// The node.
        node: usize,
        /// Slot before which it happens (None: before the delimiter).
        slot: Option<usize>,
    },
    /// A dead node gets power again before the cycle's start delimiter
    /// and rejoins (protocol §12).
    Restart {
        /// The node.
        node: usize,
    },
    /// One line bit inverted.
    Flip {
        /// The fibre.
        fibre: Fibre,
        /// The word hit.
        target: FlipTarget,
        /// Line bit within that word.
        bit: u32,
    },
    /// Garbage on the line for `len` bits of a DATA frame, from line bit
    /// `bit` of `target` (a header word or a slot) on
    /// ([`crate::line::garbage`] of `pattern`).
    Burst {
        /// The fibre.
        fibre: Fibre,
        /// The word it starts in (H0, H1 or a slot).
        target: FlipTarget,
        /// Line bit within that word where it starts.
        bit: u32,
        /// Line bits of garbage.
        len: u32,
        /// Seed of the garbage.
        pattern: u8,
    },
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let at = |s: &Option<usize>| s.map(|s| format!("s{s}")).unwrap_or_else(|| "cs".into());
        match self {
            Fault::Break { fibre, slot } => write!(f, "break {fibre} at {}", at(slot)),
            Fault::Repair { fibre, slot } => write!(f, "repair {fibre} at {}", at(slot)),
            Fault::Kill { node, slot } => write!(f, "kill node{node} at {}", at(slot)),
            Fault::Restart { node } => write!(f, "restart node{node}"),
            Fault::Flip { fibre, target, bit } => write!(f, "flip {fibre} {target} bit {bit}"),
            Fault::Burst {
                fibre,
                target,
                bit,
                len,
                pattern,
            } => write!(
                f,
                "burst {fibre} {target} bit {bit} for {len} bits (pattern {pattern})"
            ),
        }
    }
}

/// What kind of writer a slot has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlotKind {
    /// Written by a sensor slave.
    Sensor,
    /// Written by a master's host (LOCAL).
    Local,
    /// Data written by a master, Alive by the actuator slave `actuator`.
    Act {
        /// The actuator node.
        actuator: usize,
    },
}

/// One validated node.
#[derive(Debug, Clone)]
pub struct NodeCfg {
    /// Kind.
    pub kind: Kind,
    /// Home slot.
    pub address: usize,
    /// Masters: LOCAL slots.
    pub slots: Vec<usize>,
    /// Masters: served actuator slots.
    pub serves: Vec<usize>,
    /// Clock offset, ppm.
    pub ppm: f64,
    /// Masters: Alive check enabled on foreign slots.
    pub alive_check: bool,
    /// Special master (and a backup once it is the clock base): leaves
    /// failsafe only after its host's clear command too (`fs_exit =
    /// "host"`, protocol §12).
    pub fs_exit_host: bool,
    /// Masters: backup clock base of this priority (1 first; protocol §8).
    pub backup: Option<u8>,
}

/// A validated scenario.
#[derive(Debug, Clone)]
pub struct Config {
    /// Name.
    pub name: String,
    /// Seed.
    pub seed: u64,
    /// Cycles to run.
    pub cycles: u32,
    /// Extended-alarm frame variant.
    pub ext: bool,
    /// Cycle period, bit times.
    pub period: u32,
    /// Line rate for summaries, Mbit/s.
    pub line_rate_mbps: f64,
    /// Nodes in ring order.
    pub nodes: Vec<NodeCfg>,
    /// Slots per frame.
    pub slots: usize,
    /// Writer (data source) of each slot.
    pub writer: Vec<usize>,
    /// Kind of each slot.
    pub slot_kind: Vec<SlotKind>,
    /// Index of the special master.
    pub sm: usize,
    /// Sensor stimulus generator.
    pub generator: Generator,
    /// Explicit sensor values: slot -> (from cycle -> value).
    pub values: BTreeMap<usize, BTreeMap<u32, u16>>,
    /// Host writes: (cycle, node, slot, data), in file order.
    pub host_writes: Vec<(u32, usize, usize, u16)>,
    /// Interrupt requests: (cycle, node, line).
    pub irqs: Vec<(u32, usize, IrqLine)>,
    /// Cycles before which the special master's host writes the failsafe
    /// clear command (protocol §12).
    pub fs_clears: Vec<u32>,
    /// Faults: (cycle, fault), in file order.
    pub faults: Vec<(u32, Fault)>,
    /// Per slot: critical, retransmitted on demand (protocol §8; the
    /// configuration byte's CRIT bit).
    pub critical: Vec<bool>,
}

/// Bits of a master's configuration byte (protocol §7).
pub mod cfg_bits {
    /// Last valid slot of the frame.
    pub const LAST: u8 = 1;
    /// Actuator slot served by this master.
    pub const ACT: u8 = 2;
    /// Check the Alive bit of this slot.
    pub const ALIVE_EN: u8 = 4;
    /// Written by this master's host.
    pub const LOCAL: u8 = 8;
    /// A critical slot, retransmitted on demand.
    pub const CRIT: u8 = 16;
}

impl Config {
    /// Nodes that die during the run (kill faults).
    pub fn killed(&self) -> Vec<usize> {
        self.faults
            .iter()
            .filter_map(|(_, f)| match f {
                Fault::Kill { node, .. } => Some(*node),
                _ => None,
            })
            .collect()
    }

    /// The configuration byte of `slot` in master `node` (protocol §7): LAST
    /// for slot S−1, ACT for served slots, LOCAL for its own slots, ALIVE_EN
    /// for every other slot unless `alive_check = false`.
    pub fn config_byte(&self, node: usize, slot: usize) -> u8 {
        let mut b = 0;
        if slot + 1 == self.slots {
            b |= cfg_bits::LAST;
        }
        if self.writer[slot] == node {
            match self.slot_kind[slot] {
                SlotKind::Act { .. } => b |= cfg_bits::ACT,
                SlotKind::Local => b |= cfg_bits::LOCAL,
                SlotKind::Sensor => {}
            }
        }
        if self.nodes[node].alive_check && b & cfg_bits::LOCAL == 0 {
            b |= cfg_bits::ALIVE_EN;
        }
        if self.critical[slot] {
            b |= cfg_bits::CRIT;
        }
        b
    }

    /// The smallest legal period of this ring (protocol §8): the ring's
    /// own, and with critical slots room for one retransmission request.
    pub fn min_period(&self) -> u32 {
        let n = self.nodes.len();
        let ring = min_period(self.slots, n, self.ext);
        self.last_critical().map_or(ring, |c| {
            ring.max(rtx_min_period(self.slots, n, self.ext, c))
        })
    }

    /// The critical slots, in order (protocol §8).
    pub fn critical_slots(&self) -> Vec<usize> {
        (0..self.slots).filter(|&s| self.critical[s]).collect()
    }

    /// The highest critical slot, if any.
    pub fn last_critical(&self) -> Option<usize> {
        self.critical.iter().rposition(|&c| c)
    }

    /// When the clock base sends its retransmission packet (protocol §8),
    /// bit times after the frame's J K; `None` without critical slots.
    pub fn rtx_start(&self, wrapped: bool) -> Option<u32> {
        let c = self.last_critical()?;
        Some(rtx_start(
            self.slots,
            self.nodes.len(),
            self.ext,
            c,
            wrapped,
        ))
    }

    /// The shortest legal period whose healthy ring has room for `k`
    /// retransmission requests (at most [`RTX_MAX`]) per cycle (protocol
    /// §8); `None` without critical slots.
    pub fn period_for_requests(&self, k: usize) -> Option<u32> {
        let c = self.last_critical()?;
        let k = k.min(RTX_MAX);
        let need = rtx_period(self.slots, self.nodes.len(), self.ext, c, k);
        Some(self.min_period().max(need))
    }

    /// How many requests fit in the retransmission packet of a cycle
    /// (protocol §8): 0 without critical slots or when none fits.
    pub fn rtx_capacity(&self, wrapped: bool) -> usize {
        let n = self.nodes.len();
        self.last_critical().map_or(0, |c| {
            rtx_capacity(self.period, self.slots, n, self.ext, c, wrapped)
        })
    }

    /// The configuration as a scenario file (docs/scenarios.md) that
    /// [`load`] reads back to the same configuration: how a generated case
    /// (a campaign's) becomes a file a user can check, trace and simulate.
    pub fn to_scenario(&self, description: &str) -> String {
        use std::fmt::Write;
        let q = |s: &str| format!("{s:?}");
        let mut o = String::new();
        let _ = writeln!(o, "name = {}", q(&self.name));
        let _ = writeln!(o, "description = {}", q(description));
        let _ = writeln!(o, "seed = {}\ncycles = {}\n", self.seed, self.cycles);
        let _ = writeln!(
            o,
            "[frame]\nalarm_bits = {}\nperiod_bits = {}\nline_rate_mbps = {:?}",
            self.ext, self.period, self.line_rate_mbps
        );
        let crit: Vec<String> = self
            .critical_slots()
            .iter()
            .map(|s| s.to_string())
            .collect();
        if !crit.is_empty() {
            let _ = writeln!(o, "critical = [{}]", crit.join(", "));
        }
        let _ = writeln!(o);
        let generator = match self.generator {
            Generator::Counter => "counter",
            Generator::Random => "random",
            Generator::Explicit => "explicit",
        };
        let _ = writeln!(o, "[stimulus]\ngenerator = {}\n", q(generator));
        for (slot, by_cycle) in &self.values {
            for (cycle, data) in by_cycle {
                let _ = writeln!(
                    o,
                    "[[stimulus.value]]\ncycle = {cycle}\nslot = {slot}\ndata = 0x{data:04x}\n"
                );
            }
        }
        let list = |v: &[usize]| {
            let items: Vec<String> = v.iter().map(|x| x.to_string()).collect();
            format!("[{}]", items.join(", "))
        };
        for nd in &self.nodes {
            let _ = writeln!(o, "[[node]]\nkind = {}", q(nd.kind.name()));
            let _ = writeln!(o, "address = {}", nd.address);
            if nd.kind.is_master() {
                let _ = writeln!(o, "slots = {}", list(&nd.slots));
                let _ = writeln!(o, "serves = {}", list(&nd.serves));
                let _ = writeln!(o, "alive_check = {}", nd.alive_check);
            }
            if nd.fs_exit_host {
                let _ = writeln!(o, "fs_exit = \"host\"");
            }
            if let Some(b) = nd.backup {
                let _ = writeln!(o, "backup = {b}");
            }
            let _ = writeln!(o, "ppm = {:?}\n", nd.ppm);
        }
        for (cycle, node, slot, data) in &self.host_writes {
            let _ = writeln!(
                o,
                "[[host_write]]\ncycle = {cycle}\nnode = {node}\nslot = {slot}\ndata = 0x{data:04x}\n"
            );
        }
        for (cycle, node, line) in &self.irqs {
            let line = match line {
                IrqLine::Irq1 => "irq1",
                IrqLine::Irq2 => "irq2",
                IrqLine::Failsafe => "failsafe",
            };
            let _ = writeln!(
                o,
                "[[irq]]\ncycle = {cycle}\nnode = {node}\nline = {}\n",
                q(line)
            );
        }
        for cycle in &self.fs_clears {
            let _ = writeln!(o, "[[fs_clear]]\ncycle = {cycle}\n");
        }
        for (cycle, f) in &self.faults {
            let _ = writeln!(o, "[[fault]]\ncycle = {cycle}");
            let slot = |o: &mut String, s: &Option<usize>| {
                if let Some(s) = s {
                    let _ = writeln!(o, "slot = {s}");
                }
            };
            match f {
                Fault::Break { fibre, slot: s } => {
                    let _ = writeln!(o, "kind = \"break\"\nfibre = \"{fibre}\"");
                    slot(&mut o, s);
                }
                Fault::Repair { fibre, slot: s } => {
                    let _ = writeln!(o, "kind = \"repair\"\nfibre = \"{fibre}\"");
                    slot(&mut o, s);
                }
                Fault::Kill { node, slot: s } => {
                    let _ = writeln!(o, "kind = \"kill\"\nnode = {node}");
                    slot(&mut o, s);
                }
                Fault::Restart { node } => {
                    let _ = writeln!(o, "kind = \"restart\"\nnode = {node}");
                }
                Fault::Burst {
                    fibre,
                    target,
                    bit,
                    len,
                    pattern,
                } => {
                    let _ = writeln!(
                        o,
                        "kind = \"burst\"\nfibre = \"{fibre}\"\nbit = {bit}\nlength = {len}\npattern = {pattern}"
                    );
                    match target {
                        FlipTarget::Slot(s) => {
                            let _ = writeln!(o, "slot = {s}");
                        }
                        other => {
                            let _ = writeln!(o, "word = \"{other}\"");
                        }
                    }
                }
                Fault::Flip { fibre, target, bit } => {
                    let _ = writeln!(o, "kind = \"flip\"\nfibre = \"{fibre}\"\nbit = {bit}");
                    match target {
                        FlipTarget::Slot(s) => {
                            let _ = writeln!(o, "slot = {s}");
                        }
                        other => {
                            let _ = writeln!(o, "word = \"{other}\"");
                        }
                    }
                }
            }
            o.push('\n');
        }
        o
    }

    /// Backup clock bases: (node, priority), lowest priority first.
    pub fn backups(&self) -> Vec<(usize, u8)> {
        let mut v: Vec<(usize, u8)> = self
            .nodes
            .iter()
            .enumerate()
            .filter_map(|(i, x)| x.backup.map(|b| (i, b)))
            .collect();
        v.sort_by_key(|x| x.1);
        v
    }

    /// Cycles without a start delimiter at INPUT that put a node into
    /// failsafe (protocol §12 rule 4): 3, or 2 + the highest backup
    /// priority (protocol §8).
    pub fn cs_timeout_cycles(&self) -> u32 {
        2 + self.backups().last().map_or(1, |b| b.1 as u32)
    }

    /// Line bits of one word.
    pub fn word_bits(&self) -> u32 {
        word_bits(self.ext)
    }
    /// Frame length in bit times: JK, two header words, the slots.
    pub fn frame_bits(&self) -> u32 {
        frame_bits(self.slots, self.ext)
    }
    /// Cycle time in microseconds at the configured line rate.
    pub fn cycle_us(&self) -> f64 {
        self.period as f64 / self.line_rate_mbps
    }
}

/// Frame length in bit times.
pub fn frame_bits(slots: usize, ext: bool) -> u32 {
    JK_BITS + (2 + slots as u32) * word_bits(ext)
}

/// When the clock base sends a retransmission packet (protocol §8,
/// "Retransmission on demand"), in bit times after the frame's J K: once
/// the frame has left and the word of the highest critical slot `c_max`
/// has returned in a ring whose latency is at most `N · 12` (`N · 24`
/// when `wrapped`), plus the gap.
pub fn rtx_start(slots: usize, nodes: usize, ext: bool, c_max: usize, wrapped: bool) -> u32 {
    let back = latency_bound(nodes, wrapped) + JK_BITS + word_bits(ext) * (c_max as u32 + 3);
    frame_bits(slots, ext).max(back) + MIN_GAP_BITS
}

/// Requests one retransmission packet carries at most (protocol §8: the
/// clock base's list of damaged critical slots has this many places).
pub const RTX_MAX: usize = 8;

/// How many requests fit in a retransmission packet (protocol §8) whose
/// copies are back at the clock base by the next period tick, in a ring
/// whose latency is at most `N · 12` (`N · 24` when `wrapped`; more than
/// the 20-bit gap the packet must leave before the next frame): at most
/// [`RTX_MAX`].
pub fn rtx_capacity(
    period: u32,
    slots: usize,
    nodes: usize,
    ext: bool,
    c_max: usize,
    wrapped: bool,
) -> usize {
    let fixed = rtx_start(slots, nodes, ext, c_max, wrapped)
        + rtx_bits(0, ext)
        + latency_bound(nodes, wrapped);
    ((period.saturating_sub(fixed) / (2 * word_bits(ext))) as usize).min(RTX_MAX)
}

/// The ring latency the retransmission timing allows for (protocol §8):
/// `N · 12` bit times, `N · 24` in a wrapped ring.
fn latency_bound(nodes: usize, wrapped: bool) -> u32 {
    let per_node = if wrapped {
        NODE_DELAY_BITS + PASS_DELAY_BITS
    } else {
        NODE_DELAY_BITS
    };
    nodes as u32 * per_node
}

/// The period a ring with critical slots up to `c_max` needs at least
/// for one retransmission request in the healthy ring (protocol §8).
pub fn rtx_min_period(slots: usize, nodes: usize, ext: bool, c_max: usize) -> u32 {
    rtx_period(slots, nodes, ext, c_max, 1)
}

/// The period a ring with critical slots up to `c_max` needs at least
/// for `k` retransmission requests in the healthy ring (protocol §8).
pub fn rtx_period(slots: usize, nodes: usize, ext: bool, c_max: usize, k: usize) -> u32 {
    rtx_start(slots, nodes, ext, c_max, false) + rtx_bits(k, ext) + latency_bound(nodes, false)
}

/// Bit times of a retransmission packet with `k` requests: J K, two
/// header words, an index and a data word per request.
pub fn rtx_bits(k: usize, ext: bool) -> u32 {
    JK_BITS + (2 + 2 * k as u32) * word_bits(ext)
}

/// Highest backup clock-base priority (protocol §8).
pub const MAX_BACKUP: u32 = 7;

/// Longest legal cycle period in bit times (docs/protocol.md §8): the nodes'
/// 20-bit period and CS timeout registers hold 7 · P clocks.
pub const MAX_PERIOD_BITS: u32 = 149_796;

/// Smallest legal cycle period (docs/protocol.md §8): room for the frame and
/// its gap, for the worst-case wrapped ring latency plus one word of
/// processing in the special master, and for a reintegration handshake.
pub fn min_period(slots: usize, nodes: usize, ext: bool) -> u32 {
    let f = frame_bits(slots, ext) + MIN_GAP_BITS;
    let latency = nodes as u32 * (NODE_DELAY_BITS + PASS_DELAY_BITS) + word_bits(ext);
    f.max(latency).max(MIN_PERIOD_BITS)
}

/// Where a `flip` or `burst` fault hits: `word` ("cs" for a flip only,
/// "h0", "h1") or `slot`, one of the two.
fn fault_target(
    m: &SourceMap,
    f: &RawFault,
    j: usize,
    slots: usize,
    kind: &str,
    rtx_words: usize,
) -> Result<FlipTarget, ScenarioError> {
    let flip = kind == "flip";
    let words = if flip {
        "(\"cs\", \"h0\", \"h1\")"
    } else {
        "(\"h0\", \"h1\")"
    };
    match (&f.word, &f.slot) {
        (Some(x), None) => match x.get_ref().as_str() {
            "cs" if flip => Ok(FlipTarget::Cs),
            "h0" => Ok(FlipTarget::H0),
            "h1" => Ok(FlipTarget::H1),
            r if flip && r.starts_with("rtx") => rtx_target(m, x, j, rtx_words),
            other => Err(m.at(
                x,
                if flip {
                    format!("fault[{j}].word = \"{other}\": use \"cs\", \"h0\", \"h1\" (\"rtx_head\", \"rtx<j>\" in the retransmission packet), or give `slot` instead")
                } else {
                    format!("fault[{j}].word = \"{other}\": a burst starts in \"h0\", \"h1\" or a `slot` (not in the start delimiter)")
                },
            )),
        },
        (None, Some(sl)) => {
            let v = *sl.get_ref() as usize;
            if v >= slots {
                return Err(m.at(
                    sl,
                    format!("fault[{j}].slot = {v}: the frame has slots 0..{}", slots - 1),
                ));
            }
            Ok(FlipTarget::Slot(v))
        }
        (Some(x), Some(_)) => {
            Err(m.at(x, format!("fault[{j}]: give either `word` or `slot`, not both")))
        }
        (None, None) => Err(m.at(
            &f.kind,
            format!("fault[{j}]: kind = \"{kind}\" needs `slot` or `word` {words}"),
        )),
    }
}

/// A flip in the retransmission packet (protocol §8): `word = "rtx_head"`
/// or `"rtx<j>"`, j below twice the requests that fit.
fn rtx_target(
    m: &SourceMap,
    x: &Spanned<String>,
    j: usize,
    rtx_words: usize,
) -> Result<FlipTarget, ScenarioError> {
    let w = x.get_ref().as_str();
    if rtx_words == 0 {
        return Err(m.at(
            x,
            format!("fault[{j}].word = \"{w}\": there is no retransmission packet without `frame.critical` slots"),
        ));
    }
    if w == "rtx_head" {
        return Ok(FlipTarget::RtxHead);
    }
    match w[3..].parse::<usize>() {
        Ok(i) if i < rtx_words => Ok(FlipTarget::Rtx(i)),
        _ => Err(m.at(
            x,
            format!(
                "fault[{j}].word = \"{w}\": the retransmission packet has \"rtx_head\" and words \"rtx0\"..\"rtx{}\" (two per request that fits)",
                rtx_words - 1
            ),
        )),
    }
}

/// A `kind = "burst"` fault (its fibre already read): where it starts
/// (a header word or a slot, not the start delimiter: garbage there would
/// move the packet's start), its length, inside the frame, and its pattern.
fn burst(
    m: &SourceMap,
    f: &RawFault,
    j: usize,
    fibre: Fibre,
    slots: usize,
    ext: bool,
    seed: u64,
) -> Result<Fault, ScenarioError> {
    let w = word_bits(ext);
    let target = fault_target(m, f, j, slots, "burst", 0)?;
    let b = f.bit.as_ref().expect("checked");
    if *b.get_ref() >= w {
        return Err(m.at(
            b,
            format!(
                "fault[{j}].bit = {}: a word has line bits 0..{}",
                b.get_ref(),
                w - 1
            ),
        ));
    }
    let l = f.length.as_ref().expect("checked");
    let start = match target {
        FlipTarget::H0 => 0,
        FlipTarget::H1 => w,
        FlipTarget::Slot(s) => (2 + s as u32) * w,
        FlipTarget::Cs | FlipTarget::RtxHead | FlipTarget::Rtx(_) => unreachable!("refused above"),
    } + b.get_ref();
    let room = (2 + slots as u32) * w - start;
    if *l.get_ref() == 0 || *l.get_ref() > room {
        return Err(m.at(
            l,
            format!(
                "fault[{j}].length = {}: a burst from there has 1..={room} line bits before the frame ends",
                l.get_ref()
            ),
        ));
    }
    let pattern = match &f.pattern {
        Some(p) if *p.get_ref() > 255 => {
            return Err(m.at(
                p,
                format!("fault[{j}].pattern = {}: use 0..=255", p.get_ref()),
            ))
        }
        Some(p) => *p.get_ref() as u8,
        None => (crate::ring::splitmix(seed ^ (j as u64) << 32) & 0xff) as u8,
    };
    Ok(Fault::Burst {
        fibre,
        target,
        bit: *b.get_ref(),
        len: *l.get_ref(),
        pattern,
    })
}

fn slot_list(v: &Option<Spanned<Vec<Spanned<u32>>>>) -> Vec<&Spanned<u32>> {
    v.as_ref()
        .map(|l| l.get_ref().iter().collect())
        .unwrap_or_default()
}

/// Reads and validates a scenario file's text. `file` is used in messages.
pub fn load(file: &str, text: &str) -> Result<Config, ScenarioError> {
    let raw = parse_raw(file, text)?;
    validate(file, text, &raw)
}

/// Validates a parsed scenario: the ring, the nodes and who writes which
/// slot, the frame's timing, the stimulus, the faults, in that order (the
/// first error is reported).
pub fn validate(file: &str, text: &str, raw: &RawScenario) -> Result<Config, ScenarioError> {
    let m = SourceMap::new(file, text);
    let (n, cycles, sm) = check_ring(&m, raw)?;
    let own = check_nodes(&m, raw)?;
    let slots = own.writer.len();
    let ext = raw.frame.alarm_bits;
    let critical = critical_slots(&m, raw, slots)?;
    let (period, line_rate_mbps) = check_timing(&m, raw, &own.nodes, slots, ext, &critical)?;
    let at = Fields {
        m: &m,
        n,
        cycles,
        slots,
    };
    let stim = check_stimulus(&at, raw, &own)?;
    let rtx_words = critical
        .iter()
        .rposition(|&c| c)
        .map_or(0, |c| 2 * rtx_capacity(period, slots, n, ext, c, false));
    let mut faults = vec![];
    for (j, f) in raw.fault.iter().enumerate() {
        let c = at.cycle(&f.cycle, format!("fault[{j}].cycle"))?;
        let ctx = FaultCtx {
            at: &at,
            f,
            j,
            sm,
            nodes: &own.nodes,
            ext,
            rtx_words,
            seed: raw.seed,
        };
        let fault = ctx.check(c, &faults)?;
        faults.push((c, fault));
    }
    Ok(Config {
        name: raw.name.clone().unwrap_or_else(|| file.to_string()),
        seed: raw.seed,
        cycles,
        ext,
        period,
        line_rate_mbps,
        nodes: own.nodes,
        slots,
        writer: own.writer,
        slot_kind: own.slot_kind,
        sm,
        generator: raw.stimulus.generator,
        values: stim.values,
        host_writes: stim.host_writes,
        irqs: stim.irqs,
        fs_clears: stim.fs_clears,
        faults,
        critical,
    })
}

/// The ring as a whole: 2 to [`MAX_NODES`] nodes, 1 to [`MAX_CYCLES`]
/// cycles, exactly one special master. Returns (nodes, cycles, the special
/// master).
fn check_ring(m: &SourceMap, raw: &RawScenario) -> Result<(usize, u32, usize), ScenarioError> {
    let n = raw.node.len();
    if n < 2 {
        return Err(m.error(
            raw.node.first().map(|x| x.kind.span().start),
            format!("node: a ring needs at least 2 [[node]] entries, found {n}"),
        ));
    }
    if n > MAX_NODES {
        return Err(m.error(
            None,
            format!("node: {n} nodes, at most {MAX_NODES} are allowed"),
        ));
    }
    let cycles = *raw.cycles.get_ref();
    if cycles == 0 || cycles > MAX_CYCLES {
        return Err(m.at(
            &raw.cycles,
            format!("cycles = {cycles} must be between 1 and {MAX_CYCLES}"),
        ));
    }
    let sms: Vec<usize> = (0..n)
        .filter(|&i| *raw.node[i].kind.get_ref() == Kind::SpecialMaster)
        .collect();
    if sms.is_empty() {
        return Err(m.error(
            Some(raw.node[0].kind.span().start),
            "node[0].kind: the ring has no special master; exactly one node needs kind = \"special_master\"",
        ));
    }
    if sms.len() > 1 {
        return Err(m.at(
            &raw.node[sms[1]].kind,
            format!(
                "node[{}].kind = \"special_master\": a ring has exactly one special master, node[{}] already is",
                sms[1], sms[0]
            ),
        ));
    }
    Ok((n, cycles, sms[0]))
}

/// The nodes and who writes which slot.
struct Ownership {
    nodes: Vec<NodeCfg>,
    /// Per slot, its writer.
    writer: Vec<usize>,
    /// Per slot, its kind.
    slot_kind: Vec<SlotKind>,
}

/// A slot number of the scenario (`field` names it in the message).
fn check_slot(m: &SourceMap, s: &Spanned<u32>, field: String) -> Result<usize, ScenarioError> {
    let v = *s.get_ref() as usize;
    if v >= MAX_SLOTS {
        Err(m.at(
            s,
            format!(
                "{field} = {v} is out of range: slots are 0..{}",
                MAX_SLOTS - 1
            ),
        ))
    } else {
        Ok(v)
    }
}

/// Node `node` writes `slot` (named `field`, at `at`): refused when the
/// slot has a writer already.
fn claim(
    m: &SourceMap,
    raw: &RawScenario,
    writer: &mut BTreeMap<usize, usize>,
    (slot, at, field): (usize, &Spanned<u32>, String),
    node: usize,
) -> Result<(), ScenarioError> {
    if let Some(other) = writer.get(&slot) {
        return Err(m.at(
            at,
            format!(
                "{field} = {slot}: slot {slot} already has a writer, node[{other}] ({}); every slot has exactly one",
                raw.node[*other].kind.get_ref().name()
            ),
        ));
    }
    writer.insert(slot, node);
    Ok(())
}

/// Every node's settings and the slots it writes: a sensor its address, a
/// master its `slots` and the actuator slots it `serves`; every actuator
/// served, every slot 0..S−1 with exactly one writer.
fn check_nodes(m: &SourceMap, raw: &RawScenario) -> Result<Ownership, ScenarioError> {
    let mut writer: BTreeMap<usize, usize> = BTreeMap::new();
    let mut kinds: BTreeMap<usize, SlotKind> = BTreeMap::new();
    let mut nodes = Vec::with_capacity(raw.node.len());
    // Actuators first so that `serves` can be matched against them.
    let mut actuator_of: BTreeMap<usize, usize> = BTreeMap::new();
    for (i, rn) in raw.node.iter().enumerate() {
        let mut cfg = node_cfg(m, raw, i)?;
        let address = cfg.address;
        match cfg.kind {
            Kind::Sensor => {
                let field = format!("node[{i}].address");
                claim(m, raw, &mut writer, (address, &rn.address, field), i)?;
                kinds.insert(address, SlotKind::Sensor);
            }
            Kind::Actuator => {
                if let Some(other) = actuator_of.get(&address) {
                    return Err(m.at(
                        &rn.address,
                        format!("node[{i}].address = {address}: actuator node[{other}] already reads slot {address}"),
                    ));
                }
                actuator_of.insert(address, i);
            }
            Kind::Master | Kind::SpecialMaster => {
                if rn.slots.is_none() {
                    return Err(m.at(
                        &rn.kind,
                        format!("node[{i}].slots is missing: a master lists the slots its host writes (at least its address {address})"),
                    ));
                }
                for s in slot_list(&rn.slots) {
                    let v = check_slot(m, s, format!("node[{i}].slots"))?;
                    claim(m, raw, &mut writer, (v, s, format!("node[{i}].slots")), i)?;
                    kinds.insert(v, SlotKind::Local);
                    cfg.slots.push(v);
                }
                if !cfg.slots.contains(&address) {
                    return Err(m.at(
                        &rn.address,
                        format!("node[{i}].address = {address} is not one of node[{i}].slots: a master's alarms go in a slot it writes"),
                    ));
                }
                for s in slot_list(&rn.serves) {
                    let v = check_slot(m, s, format!("node[{i}].serves"))?;
                    cfg.serves.push(v);
                }
            }
        }
        nodes.push(cfg);
    }
    // Served actuator slots.
    for (i, rn) in raw.node.iter().enumerate() {
        for s in slot_list(&rn.serves) {
            let v = *s.get_ref() as usize;
            let Some(&act) = actuator_of.get(&v) else {
                return Err(m.at(
                    s,
                    format!("node[{i}].serves = {v}: no actuator has address {v}"),
                ));
            };
            claim(m, raw, &mut writer, (v, s, format!("node[{i}].serves")), i)?;
            kinds.insert(v, SlotKind::Act { actuator: act });
        }
    }
    for (&slot, &act) in &actuator_of {
        if !writer.contains_key(&slot) {
            return Err(m.at(
                &raw.node[act].address,
                format!("node[{act}].address = {slot}: no master serves this actuator; add {slot} to one master's `serves`"),
            ));
        }
    }
    let slots = writer.keys().next_back().map(|s| s + 1).unwrap_or(0);
    if let Some(gap) = (0..slots).find(|s| !writer.contains_key(s)) {
        return Err(m.error(
            None,
            format!(
                "node: slot {gap} has no writer; slots must be numbered 0..{} without gaps",
                slots - 1
            ),
        ));
    }
    Ok(Ownership {
        nodes,
        writer: (0..slots).map(|s| writer[&s]).collect(),
        slot_kind: (0..slots).map(|s| kinds[&s]).collect(),
    })
}

/// Node `i`'s own settings (address, clock offset, the fields only masters
/// have, backup priority, failsafe exit), its slot lists still empty.
fn node_cfg(m: &SourceMap, raw: &RawScenario, i: usize) -> Result<NodeCfg, ScenarioError> {
    let rn = &raw.node[i];
    let kind = *rn.kind.get_ref();
    let address = check_slot(m, &rn.address, format!("node[{i}].address"))?;
    let ppm = rn.ppm.as_ref().map(|p| *p.get_ref()).unwrap_or(0.0);
    if let Some(p) = &rn.ppm {
        if !ppm.is_finite() || ppm.abs() > MAX_PPM {
            return Err(m.at(
                p,
                format!("node[{i}].ppm = {ppm} is out of range: clock offsets are within ±{MAX_PPM} ppm"),
            ));
        }
    }
    if !kind.is_master() {
        for (f, v) in [("slots", &rn.slots), ("serves", &rn.serves)] {
            if let Some(v) = v {
                return Err(m.at(
                    v,
                    format!(
                        "node[{i}].{f}: a {} owns exactly its address slot; `{f}` is for masters",
                        kind.name()
                    ),
                ));
            }
        }
        if rn.alive_check.is_some() {
            return Err(m.error(
                Some(rn.kind.span().start),
                format!("node[{i}].alive_check: only masters check Alive bits"),
            ));
        }
    }
    let backup = match &rn.backup {
        None => None,
        Some(b) => Some(check_backup(m, raw, i, b)?),
    };
    if let Some(x) = &rn.fs_exit {
        if kind != Kind::SpecialMaster && backup.is_none() {
            return Err(m.at(
                x,
                format!(
                    "node[{i}].fs_exit: a {} does not decide when the ring leaves failsafe; only the special master (or a backup, once it is the clock base) does",
                    kind.name()
                ),
            ));
        }
    }
    Ok(NodeCfg {
        kind,
        address,
        slots: vec![],
        serves: vec![],
        ppm,
        alive_check: rn.alive_check.unwrap_or(true),
        fs_exit_host: rn.fs_exit.as_ref().map(|x| *x.get_ref()) == Some(FsExit::Host),
        backup,
    })
}

/// Node `i`'s backup priority `b`: only masters, 1..[`MAX_BACKUP`], each
/// priority once.
fn check_backup(
    m: &SourceMap,
    raw: &RawScenario,
    i: usize,
    b: &Spanned<u32>,
) -> Result<u8, ScenarioError> {
    let kind = *raw.node[i].kind.get_ref();
    if kind != Kind::Master {
        return Err(m.at(
            b,
            format!(
                "node[{i}].backup = {}: only a master can be a backup clock base (this node is a {}){}",
                b.get_ref(),
                kind.name(),
                if kind == Kind::SpecialMaster {
                    ", and the special master is the clock base already"
                } else {
                    ""
                }
            ),
        ));
    }
    let p = *b.get_ref();
    if !(1..=MAX_BACKUP).contains(&p) {
        return Err(m.at(
            b,
            format!("node[{i}].backup = {p} is out of range: priorities are 1..{MAX_BACKUP} (1 takes over first)"),
        ));
    }
    if let Some(other) = (0..i).find(|&o| {
        raw.node[o].backup.as_ref().map(|x| *x.get_ref()) == Some(p)
            && raw.node[o].kind.get_ref() == &Kind::Master
    }) {
        return Err(m.at(
            b,
            format!("node[{i}].backup = {p}: node[{other}] already has priority {p}; backup priorities are distinct"),
        ));
    }
    Ok(p as u8)
}

/// The frame's timing: the cycle period (room for the frame, the wrapped
/// ring and, with critical slots, one retransmission request; countable
/// by the nodes, the backups' CS timeout included) and the line rate.
fn check_timing(
    m: &SourceMap,
    raw: &RawScenario,
    nodes: &[NodeCfg],
    slots: usize,
    ext: bool,
    critical: &[bool],
) -> Result<(u32, f64), ScenarioError> {
    let n = nodes.len();
    let min = min_period(slots, n, ext);
    // With critical slots, room for one request in the healthy ring.
    let rtx_min = critical
        .iter()
        .rposition(|&c| c)
        .map(|c| (c, rtx_min_period(slots, n, ext, c)));
    if let (Some((c, need)), Some(p), Some(cr)) =
        (rtx_min, &raw.frame.period_bits, &raw.frame.critical)
    {
        let v = *p.get_ref();
        if v >= min && v < need {
            return Err(m.at(
                cr,
                format!(
                    "frame.critical: critical slot {c} needs room for a retransmission packet after the frame (protocol §8): frame.period_bits = {v} leaves none; it must be at least {need} bit times (the packet leaves {} bit times after the J K and one request takes {}, plus {} for its copy to come back, the latency bound N · 12; lower critical slots need less)",
                    rtx_start(slots, n, ext, c, false),
                    rtx_bits(1, ext),
                    latency_bound(n, false)
                ),
            ));
        }
    }
    let period = match &raw.frame.period_bits {
        None => min.max(rtx_min.map_or(0, |x| x.1)),
        Some(p) => {
            let v = *p.get_ref();
            if v < min {
                return Err(m.at(
                    p,
                    format!(
                        "frame.period_bits = {v} is shorter than the ring can hold: {slots} slots on {n} nodes need at least {min} bit times (frame {} + gap {MIN_GAP_BITS}, wrapped-ring latency {}, reintegration {MIN_PERIOD_BITS})",
                        frame_bits(slots, ext),
                        n as u32 * (NODE_DELAY_BITS + PASS_DELAY_BITS) + word_bits(ext)
                    ),
                ));
            }
            if v > MAX_PERIOD_BITS {
                return Err(m.at(
                    p,
                    format!(
                        "frame.period_bits = {v} is longer than the nodes can count: at most {MAX_PERIOD_BITS} bit times (20-bit period and CS timeout registers, docs/protocol.md §8)"
                    ),
                ));
            }
            v
        }
    };
    // The CS timeout with backups, (2.5 + p_max) periods, in the nodes'
    // 20-bit registers at 2 clocks per bit time (protocol §8).
    if let Some((i, pmax)) = nodes
        .iter()
        .enumerate()
        .filter_map(|(i, x)| x.backup.map(|b| (i, b)))
        .max_by_key(|x| x.1)
    {
        let clocks = (5 + 2 * pmax as u64) * period as u64;
        if clocks >= 1 << 20 {
            return Err(m.at(
                raw.node[i].backup.as_ref().expect("a backup"),
                format!(
                    "node[{i}].backup = {pmax}: with a period of {period} bit times the CS timeout of {} periods needs {clocks} clocks, more than the nodes' 20-bit register holds; use a lower priority or a shorter period",
                    2.5 + pmax as f64
                ),
            ));
        }
    }
    let line_rate_mbps = match &raw.frame.line_rate_mbps {
        None => 50.0,
        Some(r) => {
            let v = *r.get_ref();
            if !(v.is_finite() && v > 0.0 && v <= 1000.0) {
                return Err(m.at(
                    r,
                    format!("frame.line_rate_mbps = {v} must be above 0 and at most 1000"),
                ));
            }
            v
        }
    };
    Ok((period, line_rate_mbps))
}

/// The checks of a cycle, a data word or a node number in the stimulus and
/// the faults.
struct Fields<'a> {
    m: &'a SourceMap<'a>,
    n: usize,
    cycles: u32,
    slots: usize,
}

impl Fields<'_> {
    fn cycle(&self, c: &Spanned<u32>, field: String) -> Result<u32, ScenarioError> {
        let v = *c.get_ref();
        if v >= self.cycles {
            Err(self.m.at(
                c,
                format!(
                    "{field} = {v} is past the end of the run (cycles = {})",
                    self.cycles
                ),
            ))
        } else {
            Ok(v)
        }
    }

    fn data(&self, d: &Spanned<u32>, field: String) -> Result<u16, ScenarioError> {
        let v = *d.get_ref();
        u16::try_from(v).map_err(|_| {
            self.m
                .at(d, format!("{field} = {v} does not fit in 16 bits"))
        })
    }

    fn node(&self, d: &Spanned<u32>, field: String) -> Result<usize, ScenarioError> {
        let v = *d.get_ref() as usize;
        if v >= self.n {
            Err(self.m.at(
                d,
                format!("{field} = {v}: the ring has nodes 0..{}", self.n - 1),
            ))
        } else {
            Ok(v)
        }
    }
}

/// The scenario's stimulus, checked.
struct Stimulus {
    values: BTreeMap<usize, BTreeMap<u32, u16>>,
    host_writes: Vec<(u32, usize, usize, u16)>,
    irqs: Vec<(u32, usize, IrqLine)>,
    fs_clears: Vec<u32>,
}

/// Sensor values, host writes (only a master's, only to slots it writes),
/// user requests and failsafe clear commands.
fn check_stimulus(
    at: &Fields,
    raw: &RawScenario,
    own: &Ownership,
) -> Result<Stimulus, ScenarioError> {
    let m = at.m;
    let mut values: BTreeMap<usize, BTreeMap<u32, u16>> = BTreeMap::new();
    for (j, v) in raw.stimulus.value.iter().enumerate() {
        let c = at.cycle(&v.cycle, format!("stimulus.value[{j}].cycle"))?;
        let s = *v.slot.get_ref() as usize;
        if s >= at.slots || own.slot_kind[s] != SlotKind::Sensor {
            return Err(m.at(
                &v.slot,
                format!("stimulus.value[{j}].slot = {s} is not a sensor slot"),
            ));
        }
        let d = at.data(&v.data, format!("stimulus.value[{j}].data"))?;
        values.entry(s).or_default().insert(c, d);
    }
    let mut host_writes = vec![];
    for (j, w) in raw.host_write.iter().enumerate() {
        let c = at.cycle(&w.cycle, format!("host_write[{j}].cycle"))?;
        let nd = at.node(&w.node, format!("host_write[{j}].node"))?;
        if !own.nodes[nd].kind.is_master() {
            return Err(m.at(
                &w.node,
                format!(
                    "host_write[{j}].node = {nd} is a {}, only masters have a host",
                    own.nodes[nd].kind.name()
                ),
            ));
        }
        let s = *w.slot.get_ref() as usize;
        if s >= at.slots || own.writer[s] != nd {
            return Err(m.at(
                &w.slot,
                format!("host_write[{j}].slot = {s} is not written by node[{nd}]; a host writes only its LOCAL and served actuator slots"),
            ));
        }
        let d = at.data(&w.data, format!("host_write[{j}].data"))?;
        host_writes.push((c, nd, s, d));
    }
    let mut irqs = vec![];
    for (j, q) in raw.irq.iter().enumerate() {
        let c = at.cycle(&q.cycle, format!("irq[{j}].cycle"))?;
        let nd = at.node(&q.node, format!("irq[{j}].node"))?;
        irqs.push((c, nd, *q.line.get_ref()));
    }
    let mut fs_clears = vec![];
    for (j, q) in raw.fs_clear.iter().enumerate() {
        fs_clears.push(at.cycle(&q.cycle, format!("fs_clear[{j}].cycle"))?);
    }
    Ok(Stimulus {
        values,
        host_writes,
        irqs,
        fs_clears,
    })
}

/// One `[[fault]]` entry (`fault[j]`) and what its check needs.
struct FaultCtx<'a> {
    at: &'a Fields<'a>,
    f: &'a RawFault,
    j: usize,
    /// The special master.
    sm: usize,
    nodes: &'a [NodeCfg],
    ext: bool,
    /// Words a retransmission packet can carry (0 without critical slots).
    rtx_words: usize,
    seed: u64,
}

impl FaultCtx<'_> {
    fn kind_name(&self) -> &'static str {
        match *self.f.kind.get_ref() {
            FaultKind::Break => "break",
            FaultKind::Repair => "repair",
            FaultKind::Kill => "kill",
            FaultKind::Restart => "restart",
            FaultKind::Flip => "flip",
            FaultKind::Burst => "burst",
        }
    }

    /// `field` must be there for this kind.
    fn need(&self, present: bool, field: &str) -> Result<(), ScenarioError> {
        if present {
            Ok(())
        } else {
            Err(self.at.m.at(
                &self.f.kind,
                format!(
                    "fault[{}].{field} is missing: kind = \"{}\" needs it",
                    self.j,
                    self.kind_name()
                ),
            ))
        }
    }

    /// `field` (where it starts, if present) means nothing for this kind.
    fn forbid(&self, present: Option<usize>, field: &str) -> Result<(), ScenarioError> {
        match present {
            None => Ok(()),
            Some(at) => Err(self.at.m.error(
                Some(at),
                format!(
                    "fault[{}].{field} has no meaning for kind = \"{}\"",
                    self.j,
                    self.kind_name()
                ),
            )),
        }
    }

    /// Forbids each of the fields named (`node`, `fibre`, `word`, `slot`,
    /// `bit`, `length`, `pattern`).
    fn forbid_all(&self, fields: &[&str]) -> Result<(), ScenarioError> {
        let f = self.f;
        let span = |o: &Option<Spanned<String>>| o.as_ref().map(|s| s.span().start);
        let spanu = |o: &Option<Spanned<u32>>| o.as_ref().map(|s| s.span().start);
        for &name in fields {
            let at = match name {
                "node" => spanu(&f.node),
                "fibre" => span(&f.fibre),
                "word" => span(&f.word),
                "slot" => spanu(&f.slot),
                "bit" => spanu(&f.bit),
                "length" => spanu(&f.length),
                "pattern" => spanu(&f.pattern),
                _ => unreachable!("a fault field"),
            };
            self.forbid(at, name)?;
        }
        Ok(())
    }

    fn fibre(&self) -> Result<Fibre, ScenarioError> {
        let fs = self.f.fibre.as_ref().expect("checked by need");
        Fibre::parse(fs.get_ref(), self.at.n)
            .map_err(|e| self.at.m.at(fs, format!("fault[{}].{e}", self.j)))
    }

    fn slot(&self) -> Result<Option<usize>, ScenarioError> {
        match &self.f.slot {
            None => Ok(None),
            Some(s) => {
                let v = *s.get_ref() as usize;
                if v >= self.at.slots {
                    Err(self.at.m.at(
                        s,
                        format!(
                            "fault[{}].slot = {v}: the frame has slots 0..{}",
                            self.j,
                            self.at.slots - 1
                        ),
                    ))
                } else {
                    Ok(Some(v))
                }
            }
        }
    }

    fn node(&self) -> Result<(usize, &Spanned<u32>), ScenarioError> {
        let ns = self.f.node.as_ref().expect("checked by need");
        Ok((self.at.node(ns, format!("fault[{}].node", self.j))?, ns))
    }

    /// The fault of cycle `c`, after the faults before it (`earlier`).
    fn check(&self, c: u32, earlier: &[(u32, Fault)]) -> Result<Fault, ScenarioError> {
        let (f, j, m) = (self.f, self.j, self.at.m);
        let kind = *f.kind.get_ref();
        Ok(match kind {
            FaultKind::Break | FaultKind::Repair => {
                self.need(f.fibre.is_some(), "fibre")?;
                self.forbid_all(&["node", "word", "bit", "length", "pattern"])?;
                let fibre = self.fibre()?;
                let slot = self.slot()?;
                if kind == FaultKind::Break {
                    Fault::Break { fibre, slot }
                } else {
                    Fault::Repair { fibre, slot }
                }
            }
            FaultKind::Kill => {
                self.need(f.node.is_some(), "node")?;
                self.forbid_all(&["fibre", "word", "bit", "length", "pattern"])?;
                let (node, ns) = self.node()?;
                if node == self.sm && self.nodes.iter().all(|x| x.backup.is_none()) {
                    return Err(m.at(
                        ns,
                        format!("fault[{j}].node = {node} is the special master, and no master is a backup clock base: its death would stop the ring (give a master `backup = 1`, protocol §8)"),
                    ));
                }
                Fault::Kill {
                    node,
                    slot: self.slot()?,
                }
            }
            FaultKind::Restart => {
                self.need(f.node.is_some(), "node")?;
                self.forbid_all(&["fibre", "word", "slot", "bit", "length", "pattern"])?;
                let (node, ns) = self.node()?;
                if !dead_before(earlier, node, c) {
                    return Err(m.at(
                        ns,
                        format!(
                            "fault[{j}].node = {node}: a restart in cycle {c} needs the node dead before it (a kill in an earlier cycle, listed before the restart); node {node} is alive then"
                        ),
                    ));
                }
                Fault::Restart { node }
            }
            FaultKind::Burst => {
                self.need(f.fibre.is_some(), "fibre")?;
                self.need(f.bit.is_some(), "bit")?;
                self.need(f.length.is_some(), "length")?;
                self.forbid_all(&["node"])?;
                let fibre = self.fibre()?;
                burst(m, f, j, fibre, self.at.slots, self.ext, self.seed)?
            }
            FaultKind::Flip => {
                self.need(f.fibre.is_some(), "fibre")?;
                self.need(f.bit.is_some(), "bit")?;
                self.forbid_all(&["node", "length", "pattern"])?;
                let fibre = self.fibre()?;
                self.flip(fibre)?
            }
        })
    }

    /// A flip on `fibre`: its target word and a line bit inside it.
    fn flip(&self, fibre: Fibre) -> Result<Fault, ScenarioError> {
        let (f, j, ext) = (self.f, self.j, self.ext);
        let target = fault_target(self.at.m, f, j, self.at.slots, "flip", self.rtx_words)?;
        let b = f.bit.as_ref().expect("checked");
        let (max, what) = match target {
            FlipTarget::Cs => (JK_BITS, "start delimiter"),
            FlipTarget::RtxHead => (
                JK_BITS + 2 * word_bits(ext),
                "retransmission packet's head (J K, H0, H1)",
            ),
            _ => (word_bits(ext), "word"),
        };
        if *b.get_ref() >= max {
            return Err(self.at.m.at(
                b,
                format!(
                    "fault[{j}].bit = {}: a {what} has line bits 0..{}",
                    b.get_ref(),
                    max - 1
                ),
            ));
        }
        Ok(Fault::Flip {
            fibre,
            target,
            bit: *b.get_ref(),
        })
    }
}

/// Whether `node` is dead at cycle `c` after the `earlier` faults: killed
/// in an earlier cycle, not restarted since (faults in file order; kills
/// and restarts of one node alternate in time).
fn dead_before(earlier: &[(u32, Fault)], node: usize, c: u32) -> bool {
    let mut life: Vec<(u32, bool)> = earlier
        .iter()
        .filter_map(|(fc, x)| match *x {
            Fault::Kill { node: y, .. } if y == node => Some((*fc, false)),
            Fault::Restart { node: y } if y == node => Some((*fc, true)),
            _ => None,
        })
        .collect();
    life.sort();
    life.iter().rev().find(|x| x.0 < c).is_some_and(|x| !x.1)
}

/// `[frame] critical`: slots of the frame, each once (protocol §8).
fn critical_slots(
    m: &SourceMap,
    raw: &RawScenario,
    slots: usize,
) -> Result<Vec<bool>, ScenarioError> {
    let mut v = vec![false; slots];
    let Some(list) = &raw.frame.critical else {
        return Ok(v);
    };
    for &s in list.get_ref() {
        let s = s as usize;
        if s >= slots {
            return Err(m.at(
                list,
                format!(
                    "frame.critical: slot {s} is not in the frame (slots 0..{})",
                    slots - 1
                ),
            ));
        }
        if v[s] {
            return Err(m.at(list, format!("frame.critical: slot {s} is listed twice")));
        }
        v[s] = true;
    }
    Ok(v)
}
