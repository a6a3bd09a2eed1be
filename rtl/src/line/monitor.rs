//! # monitor — fibre monitor: decodes what a line carries (protocol §2–§5)
//!
//! Purpose: the receive chain of a node without the node: [`Cdr`] →
//! [`FramerRx`] → [`WordRx`]. Ring tops put one on every fibre; its word
//! outputs are what is compared with the model's trace (cycle, slot, data,
//! parity ok), and its packet and slot position is where a fault is placed at
//! a given (cycle, slot). It is also the receive half of every node.
//!
//! Parameters: the word format ([`WordFormat`]), as [`WordRx::new`].
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_samples` | in | 4 | clock | line samples (quadrature DDR, 8 per bit), bit 0 first |
//! | `i_slots_m1`, `i_address` | in | 12 | static | as [`WordRx`] |
//! | `i_flush` | in | 1 | clock | the input was switched to another line: the packet ends, a held word is dropped |
//! | `o_los` | out | 1 | clock | loss of signal |
//! | `o_bvalid`, `o_code`, `o_phase` | out | 1, 1, 2 | clock | recovered bit stream (from the CDR: `o_code` 1 where the line level changed) |
//! | `o_start` | out | 1 | clock | J K found |
//! | `o_inpkt` | out | 1 | clock | inside a packet |
//! | `o_wvalid` … `o_ptype` | out | | clock | as [`WordRx`] |
//!
//! **Confirmation.** A word is passed on only when the line shows an edge
//! (a code 1) after its last bit: every group that can follow a word (data,
//! S, idle) has a 1 in its first two bits. A word the line died in would
//! otherwise be completed by the zeros the clock recovery reads from a dark
//! line before it mutes, and could pass both parities with a foreign
//! value; with no recovered bit for [`DROP_CLOCKS`] clocks the held word is dropped
//! (not received, as the model's "missing") and the packet ends there. Upstream nodes keep their line
//! dark after such a stop ([`crate::line::retime::QUIET_BITS`]), so no idle can
//! confirm it either.
//!
//! The held word is not copied: the outputs are the word decoder's
//! registers, which keep it until the next group is complete — 3 bit
//! times or more after the confirming edge, which must come within the
//! next group's first two bits. Consumers take a word in the clock of
//! `o_wvalid` (issue 21: one copy of a word instead of three).
//!
//! Latency from a word's last line bit to `o_wvalid`: CDR 2–3 clocks +
//! framer 1 + word 1 + the registered outputs 1 ≈ 3 bit times, plus up to
//! 2 bit times until the confirming edge.
//!
//! ```text
//! line      ~~~| J K | H0 | H1 | slot 0 | ... | slot S-1 |~~~ idle
//! o_start        ^
//! o_wvalid            ^    ^     ^              ^   (each ~2.5 bit times after its word)
//! ```

use crate::line::cdr::Cdr;
use crate::line::framer_rx::FramerRx;
use crate::line::word_rx::{WordFormat, WordRx};
use rust_hdl::prelude::*;

/// Fibre monitor / receive chain.
#[derive(LogicBlock)]
pub struct Monitor {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Line samples.
    pub i_samples: Signal<In, Bits<4>>,
    /// Slot count − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Node address.
    pub i_address: Signal<In, Bits<12>>,
    /// The input was switched to another line: end the packet, drop the
    /// held word.
    pub i_flush: Signal<In, Bit>,
    /// Loss of signal.
    pub o_los: Signal<Out, Bit>,
    /// Recovered bit valid (from the CDR).
    pub o_bvalid: Signal<Out, Bit>,
    /// Its code bit (1: the line level changed).
    pub o_code: Signal<Out, Bit>,
    /// Sample phase of the recovered bit.
    pub o_phase: Signal<Out, Bits<2>>,
    /// Packet start.
    pub o_start: Signal<Out, Bit>,
    /// Inside a packet.
    pub o_inpkt: Signal<Out, Bit>,
    /// Word complete.
    pub o_wvalid: Signal<Out, Bit>,
    /// 0 H0, 1 H1, 2 slot.
    pub o_kind: Signal<Out, Bits<2>>,
    /// Slot number.
    pub o_slot: Signal<Out, Bits<12>>,
    /// Data.
    pub o_data: Signal<Out, Bits<16>>,
    /// Alive bit.
    pub o_alive: Signal<Out, Bit>,
    /// Alarm bit.
    pub o_alarm: Signal<Out, Bit>,
    /// Reason nibble (ext).
    pub o_reason: Signal<Out, Bits<4>>,
    /// Word good.
    pub o_ok: Signal<Out, Bit>,
    /// Data = NOT the previous word's.
    pub o_compl: Signal<Out, Bit>,
    /// VOID word.
    pub o_void: Signal<Out, Bit>,
    /// Marked word (last group T, protocol §4).
    pub o_marked: Signal<Out, Bit>,
    /// Own slot.
    pub o_own: Signal<Out, Bit>,
    /// Header rejected.
    pub o_hdr_bad: Signal<Out, Bit>,
    /// Packet type.
    pub o_ptype: Signal<Out, Bits<2>>,
    cdr: Cdr,
    framer: FramerRx,
    word: WordRx,
    quiet: DFF<Bits<3>>,
    // A held word waits for its confirming edge.
    emit: DFF<Bit>,
    p_valid: DFF<Bit>,
    conf_edge: Signal<Local, Bit>,
    drop_after: Constant<Bits<3>>,
}

/// Clocks without a recovered bit after which a held word is dropped (a
/// live line gives a bit every 2 clocks, 3 at most).
pub const DROP_CLOCKS: u64 = 4;

impl Monitor {
    /// A monitor for words of `format`.
    pub fn new(format: WordFormat) -> Self {
        Self {
            clock: Default::default(),
            i_samples: Default::default(),
            i_slots_m1: Default::default(),
            i_address: Default::default(),
            i_flush: Default::default(),
            o_los: Default::default(),
            o_bvalid: Default::default(),
            o_code: Default::default(),
            o_phase: Default::default(),
            o_start: Default::default(),
            o_inpkt: Default::default(),
            o_wvalid: Default::default(),
            o_kind: Default::default(),
            o_slot: Default::default(),
            o_data: Default::default(),
            o_alive: Default::default(),
            o_alarm: Default::default(),
            o_reason: Default::default(),
            o_ok: Default::default(),
            o_compl: Default::default(),
            o_void: Default::default(),
            o_marked: Default::default(),
            o_own: Default::default(),
            o_hdr_bad: Default::default(),
            o_ptype: Default::default(),
            cdr: Default::default(),
            framer: FramerRx::new(),
            word: WordRx::new(format),
            quiet: Default::default(),
            emit: Default::default(),
            p_valid: Default::default(),
            conf_edge: Default::default(),
            drop_after: Constant::new(DROP_CLOCKS.to_bits()),
        }
    }
}

impl Logic for Monitor {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, quiet, emit, p_valid);
        self.cdr.clock.next = self.clock.val();
        self.framer.clock.next = self.clock.val();
        self.word.clock.next = self.clock.val();
        self.cdr.i_samples.next = self.i_samples.val();
        self.framer.i_valid.next = self.cdr.o_valid.val();
        self.framer.i_code.next = self.cdr.o_code.val();
        // A packet ends after its last word, at the third idle group (word_rx),
        // or when the line goes quiet (the clock recovery muted: a dead or
        // switched line; what comes next is another stream).
        self.framer.i_end.next = self.word.o_end.val()
            | self.cdr.o_los.val()
            | (self.quiet.q.val() == self.drop_after.val())
            | self.i_flush.val();
        self.word.i_start.next = self.framer.o_start.val();
        self.word.i_gvalid.next = self.framer.o_gvalid.val();
        self.word.i_group.next = self.framer.o_group.val();
        self.word.i_idle.next = self.framer.o_idle.val();
        self.word.i_slots_m1.next = self.i_slots_m1.val();
        self.word.i_address.next = self.i_address.val();
        self.o_los.next = self.cdr.o_los.val();
        self.o_bvalid.next = self.cdr.o_valid.val();
        self.o_code.next = self.cdr.o_code.val();
        self.o_phase.next = self.cdr.o_phase.val();
        self.o_start.next = self.framer.o_start.val();
        self.o_inpkt.next = self.framer.o_inpkt.val();
        self.o_hdr_bad.next = self.word.o_hdr_bad.val();
        // Confirmation: a code 1 (the level changes) after the word.
        self.conf_edge.next = self.cdr.o_valid.val() & self.cdr.o_code.val();
        if self.cdr.o_valid.val() {
            self.quiet.d.next = 0.into();
        } else if self.quiet.q.val() != 7 {
            self.quiet.d.next = self.quiet.q.val() + 1;
        }
        // The word on the outputs: the held one, the clock after its
        // confirming edge (registered outputs: the receive chain and what
        // a node decides on a word are a clock apart, issue 20).
        self.emit.d.next = false;
        self.o_wvalid.next = self.emit.q.val();
        self.o_kind.next = self.word.o_kind.val();
        self.o_slot.next = self.word.o_slot.val();
        self.o_data.next = self.word.o_data.val();
        self.o_alive.next = self.word.o_alive.val();
        self.o_alarm.next = self.word.o_alarm.val();
        self.o_reason.next = self.word.o_reason.val();
        self.o_ok.next = self.word.o_ok.val();
        self.o_compl.next = self.word.o_compl.val();
        self.o_void.next = self.word.o_void.val();
        self.o_marked.next = self.word.o_marked.val();
        self.o_own.next = self.word.o_own.val();
        self.o_ptype.next = self.word.o_ptype.val();
        if self.p_valid.q.val() & self.conf_edge.val() {
            self.emit.d.next = true;
            self.p_valid.d.next = false;
        }
        if self.p_valid.q.val()
            & ((self.quiet.q.val() == self.drop_after.val()) | self.i_flush.val())
        {
            self.p_valid.d.next = false;
        }
        if self.word.o_wvalid.val() {
            self.p_valid.d.next = !self.conf_edge.val();
            self.emit.d.next = self.conf_edge.val();
        }
    }
}
