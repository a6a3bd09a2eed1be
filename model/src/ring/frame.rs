//! What travels on the fibres (docs/protocol.md §3–§5): switchbox modes
//! and ports (the paper's Table 1), slots, the header words, a frame and
//! what a fibre carries in a cycle, and the cuts a fault makes in a frame.

use super::*;

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
pub(super) fn fibre_into(n: usize, k: usize, p: Port) -> Fibre {
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

/// The two header words of the retransmission packet that repairs the
/// frame of cycle `cyc` (protocol §5, §8): H0 = `{11, 11, CYC[11:0]}`,
/// H1 = NOT H0.
pub fn rtx_head(cyc: u32) -> [Word; 2] {
    let h0 = 0xf000 | (cyc as u16 & 0xfff);
    [h0, !h0].map(|data| Word {
        data,
        ..Word::default()
    })
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
pub(super) fn mark(frame: &mut Frame) {
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
pub(super) fn cut(frame: &mut Frame, at: At) {
    match at {
        At::Slot(s) => truncate(frame, s),
        _ => {
            frame.hdr = HeaderRx::NoCs;
            truncate(frame, 0);
        }
    }
}

pub(super) fn truncate(frame: &mut Frame, from: usize) {
    for w in frame.words.iter_mut().skip(from) {
        *w = Slot::Missing;
    }
}

pub(super) fn rx_slot(r: Rx) -> Slot {
    match r {
        Rx::Ok(w) => Slot::Data(w),
        Rx::Void => Slot::Void,
        Rx::Bad(l) => Slot::Bad(l),
        Rx::Marked(l) => Slot::Marked(l),
    }
}
