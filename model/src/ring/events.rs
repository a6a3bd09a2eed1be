//! What a cycle reports (docs/protocol.md §10–§13): failsafe causes, the
//! alarm reasons, where an event happens and the events themselves.

use super::*;

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
