//! Scenario files (TOML): the ring, frame options, stimulus, host writes,
//! interrupt requests and faults. Parsing never panics; every error names the
//! field, its value, and the file:line:column where it stands.
//!
//! The format is documented in `docs/scenarios.md`.

use serde::Deserialize;
use std::fmt;
use toml::Spanned;

/// Most slots a frame can carry (12-bit slot counter).
pub const MAX_SLOTS: usize = 4096;
/// Most nodes a ring can have (12-bit HOP field).
pub const MAX_NODES: usize = 4095;
/// Largest clock offset a node may have, in ppm (docs/protocol.md §9).
pub const MAX_PPM: f64 = 1000.0;
/// Most cycles one scenario may run.
pub const MAX_CYCLES: u32 = 1_000_000;

/// A scenario error: message plus where it stands.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScenarioError {
    /// File name as given by the caller.
    pub file: String,
    /// 1-based line (0 when unknown).
    pub line: usize,
    /// 1-based column (0 when unknown).
    pub col: usize,
    /// What is wrong, naming the field and its value.
    pub msg: String,
    /// The offending source line, for display.
    pub source_line: String,
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "error: {}", self.msg)?;
        if self.line > 0 {
            write!(f, "\n  --> {}:{}:{}", self.file, self.line, self.col)?;
            let num = self.line.to_string();
            let pad = " ".repeat(num.len());
            write!(
                f,
                "\n{pad} |\n{num} | {}\n{pad} | {}^",
                self.source_line,
                " ".repeat(self.col.saturating_sub(1))
            )?;
        } else {
            write!(f, "\n  --> {}", self.file)?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

/// Node kinds (docs/protocol.md §7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// Slave that writes its one slot.
    Sensor,
    /// Slave that reads its one slot and proves life with the Alive bit.
    Actuator,
    /// Master with data and configuration memory.
    Master,
    /// The one master that is the clock base and makes frames.
    SpecialMaster,
}

impl Kind {
    /// Name as written in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Sensor => "sensor",
            Kind::Actuator => "actuator",
            Kind::Master => "master",
            Kind::SpecialMaster => "special_master",
        }
    }
    /// Masters and the special master.
    pub fn is_master(self) -> bool {
        matches!(self, Kind::Master | Kind::SpecialMaster)
    }
}

/// `[[node]]`: one node, in ring order (node i's PO feeds node i+1's PI).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawNode {
    /// Node kind.
    pub kind: Spanned<Kind>,
    /// Home slot: the slave's slot, or the master slot its alarms go in.
    pub address: Spanned<u32>,
    /// Masters: slots this master's host writes (must include `address`).
    #[serde(default)]
    pub slots: Option<Spanned<Vec<Spanned<u32>>>>,
    /// Masters: actuator slots whose data this master writes.
    #[serde(default)]
    pub serves: Option<Spanned<Vec<Spanned<u32>>>>,
    /// Clock frequency offset of this node's oscillator in ppm.
    #[serde(default)]
    pub ppm: Option<Spanned<f64>>,
    /// Masters: check the Alive bit of every slot they do not write.
    #[serde(default)]
    pub alive_check: Option<bool>,
    /// Special master: leave failsafe by itself (`auto`) or only after its
    /// host's clear command too (`host`).
    #[serde(default)]
    pub fs_exit: Option<Spanned<FsExit>>,
    /// Masters: a backup clock base of this priority (1..7, 1 first;
    /// protocol §8, the flying special master).
    #[serde(default)]
    pub backup: Option<Spanned<u32>>,
}

/// How the special master leaves failsafe (docs/protocol.md §12).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum FsExit {
    /// By itself, when the ring is whole again.
    #[default]
    Auto,
    /// When the ring is whole again and its host gave the clear command.
    Host,
}

/// `[[fs_clear]]`: the special master's host writes the failsafe clear
/// command before `cycle`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFsClear {
    /// Cycle before which the command is written.
    pub cycle: Spanned<u32>,
}

/// `[frame]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawFrame {
    /// Extended-alarm variant: a reason nibble in every word (protocol §6).
    #[serde(default)]
    pub alarm_bits: bool,
    /// Cycle period in bit times; omitted = the smallest legal period.
    #[serde(default)]
    pub period_bits: Option<Spanned<u32>>,
    /// Line rate in Mbit/s used for summaries (default 50).
    #[serde(default)]
    pub line_rate_mbps: Option<Spanned<f64>>,
    /// Critical slots, retransmitted on demand (protocol §8).
    #[serde(default)]
    pub critical: Option<Spanned<Vec<u32>>>,
}

/// Stimulus generator kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Generator {
    /// value = slot * 0x0101 + cycle (mod 2^16): easy to read in traces.
    #[default]
    Counter,
    /// Seeded pseudo-random 16-bit values (splitmix64 of seed, slot, cycle).
    Random,
    /// Sensors hold 0 unless a `[[stimulus.value]]` says otherwise.
    Explicit,
}

/// `[[stimulus.value]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawValue {
    /// From this cycle on.
    pub cycle: Spanned<u32>,
    /// Sensor slot.
    pub slot: Spanned<u32>,
    /// 16-bit value.
    pub data: Spanned<u32>,
}

/// `[stimulus]`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct RawStimulus {
    /// How sensor values are made.
    #[serde(default)]
    pub generator: Generator,
    /// Explicit values (override the generator from their cycle on).
    #[serde(default)]
    pub value: Vec<RawValue>,
}

/// `[[host_write]]`: a master's host writes its data memory before `cycle`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawHostWrite {
    /// Cycle before which the write lands.
    pub cycle: Spanned<u32>,
    /// Master node index.
    pub node: Spanned<u32>,
    /// Slot this master writes (local or served actuator slot).
    pub slot: Spanned<u32>,
    /// 16-bit value.
    pub data: Spanned<u32>,
}

/// Interrupt lines a node can raise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, PartialOrd, Ord, Hash)]
#[serde(rename_all = "snake_case")]
pub enum IrqLine {
    /// User interrupt 1 (alarm reason 1).
    Irq1,
    /// User interrupt 2 (alarm reason 2).
    Irq2,
    /// User failsafe request (alarm reason 3).
    Failsafe,
}

/// `[[irq]]`: a node's user logic raises an interrupt before `cycle`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawIrq {
    /// Cycle before which the request is raised.
    pub cycle: Spanned<u32>,
    /// Node index.
    pub node: Spanned<u32>,
    /// Which line.
    pub line: Spanned<IrqLine>,
}

/// Fault kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    /// A fibre stops carrying light.
    Break,
    /// A repaired fibre carries light again.
    Repair,
    /// A node dies: all its outputs go dark.
    Kill,
    /// A dead node gets power again and rejoins (protocol §12).
    Restart,
    /// One line bit of one word on one fibre is inverted.
    Flip,
    /// A fibre carries garbage for some line bits of a frame.
    Burst,
}

/// `[[fault]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFault {
    /// What happens.
    pub kind: Spanned<FaultKind>,
    /// Cycle in which it happens.
    pub cycle: Spanned<u32>,
    /// Break/repair/kill: slot before whose first bit it happens (omitted:
    /// before the cycle's start delimiter). Flip: the slot word hit.
    #[serde(default)]
    pub slot: Option<Spanned<u32>>,
    /// Break/repair/flip: fibre name `P<k>` (node k PO -> node k+1 PI) or
    /// `S<k>` (node k+1 SO -> node k SI).
    #[serde(default)]
    pub fibre: Option<Spanned<String>>,
    /// Kill, restart: node index.
    #[serde(default)]
    pub node: Option<Spanned<u32>>,
    /// Flip: word hit when not a slot: "cs", "h0" or "h1".
    #[serde(default)]
    pub word: Option<Spanned<String>>,
    /// Flip, burst: line bit within the word, 0 = first bit on the line.
    #[serde(default)]
    pub bit: Option<Spanned<u32>>,
    /// Burst: how many line bits carry garbage.
    #[serde(default)]
    pub length: Option<Spanned<u32>>,
    /// Burst: the garbage pattern's seed (0..=255; default from the
    /// scenario's seed and the fault's place in the file).
    #[serde(default)]
    pub pattern: Option<Spanned<u32>>,
}

/// The whole file as parsed, before validation.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScenario {
    /// Free-text name.
    #[serde(default)]
    pub name: Option<String>,
    /// Free-text description.
    #[serde(default)]
    pub description: Option<String>,
    /// Seed of every pseudo-random choice in this scenario.
    #[serde(default)]
    pub seed: u64,
    /// Communication cycles to run.
    pub cycles: Spanned<u32>,
    /// Frame options.
    #[serde(default)]
    pub frame: RawFrame,
    /// Nodes in ring order.
    #[serde(default)]
    pub node: Vec<RawNode>,
    /// Sensor stimulus.
    #[serde(default)]
    pub stimulus: RawStimulus,
    /// Host writes.
    #[serde(default)]
    pub host_write: Vec<RawHostWrite>,
    /// Interrupt requests.
    #[serde(default)]
    pub irq: Vec<RawIrq>,
    /// Failsafe clear commands of the special master's host.
    #[serde(default)]
    pub fs_clear: Vec<RawFsClear>,
    /// Faults.
    #[serde(default)]
    pub fault: Vec<RawFault>,
}

/// Converts byte offsets into line/column for error messages.
pub struct SourceMap<'a> {
    file: &'a str,
    text: &'a str,
}

impl<'a> SourceMap<'a> {
    /// Wraps a source text.
    pub fn new(file: &'a str, text: &'a str) -> Self {
        SourceMap { file, text }
    }

    /// An error at byte offset `at` (None: whole file).
    pub fn error(&self, at: Option<usize>, msg: impl Into<String>) -> ScenarioError {
        let msg = msg.into();
        let Some(at) = at else {
            return ScenarioError {
                file: self.file.to_string(),
                line: 0,
                col: 0,
                msg,
                source_line: String::new(),
            };
        };
        let at = at.min(self.text.len());
        let before = &self.text[..at];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map(|i| i + 1).unwrap_or(0);
        let col = self.text[line_start..at].chars().count() + 1;
        let source_line = self.text[line_start..]
            .lines()
            .next()
            .unwrap_or("")
            .to_string();
        ScenarioError {
            file: self.file.to_string(),
            line,
            col,
            msg,
            source_line,
        }
    }

    /// An error pointing at a spanned value.
    pub fn at<T>(&self, s: &Spanned<T>, msg: impl Into<String>) -> ScenarioError {
        self.error(Some(s.span().start), msg)
    }
}

/// Parses TOML text into the raw scenario (syntax, types, unknown keys).
pub fn parse_raw(file: &str, text: &str) -> Result<RawScenario, ScenarioError> {
    let map = SourceMap::new(file, text);
    toml::from_str::<RawScenario>(text).map_err(|e| {
        let msg = e.message().trim().to_string();
        map.error(e.span().map(|s| s.start), msg)
    })
}
