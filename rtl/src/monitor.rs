//! # monitor — fibre monitor: decodes what a line carries (protocol §2–§5)
//!
//! Purpose: the receive chain of a node without the node: [`Cdr`] →
//! [`RxFramer`] → [`RxWord`]. Ring tops put one on every fibre; its word
//! outputs are what is compared with the model's trace (cycle, slot, data,
//! parity ok), and its packet and slot position is where a fault is placed at
//! a given (cycle, slot). It is also the receive half of every node.
//!
//! Parameters: `ext` (extended-alarm words), as [`RxWord::new`].
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_samples` | in | 4 | clock | line samples (quadrature DDR, 8 per bit), bit 0 first |
//! | `i_slots_m1`, `i_address` | in | 12 | static | as [`RxWord`] |
//! | `o_los` | out | 1 | clock | loss of signal |
//! | `o_bvalid`, `o_level`, `o_phase` | out | 1, 1, 2 | clock | recovered bit stream (from the CDR) |
//! | `o_start` | out | 1 | clock | J K found |
//! | `o_inpkt` | out | 1 | clock | inside a packet |
//! | `o_wvalid` … `o_ptype` | out | | clock | as [`RxWord`] |
//!
//! Latency from a word's last line bit to `o_wvalid`: CDR 2–3 clocks +
//! framer 1 + word 1 ≈ 2.5 bit times.
//!
//! ```text
//! line      ~~~| J K | H0 | H1 | slot 0 | ... | slot S-1 |~~~ idle
//! o_start        ^
//! o_wvalid            ^    ^     ^              ^   (each ~2.5 bit times after its word)
//! ```

use crate::cdr::Cdr;
use crate::rx_framer::RxFramer;
use crate::rx_word::RxWord;
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
    /// Loss of signal.
    pub o_los: Signal<Out, Bit>,
    /// Recovered bit valid (from the CDR).
    pub o_bvalid: Signal<Out, Bit>,
    /// Recovered line level.
    pub o_level: Signal<Out, Bit>,
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
    /// VOID word.
    pub o_void: Signal<Out, Bit>,
    /// Own slot.
    pub o_own: Signal<Out, Bit>,
    /// Header rejected.
    pub o_hdr_bad: Signal<Out, Bit>,
    /// Packet type.
    pub o_ptype: Signal<Out, Bits<2>>,
    cdr: Cdr,
    framer: RxFramer,
    word: RxWord,
}

impl Monitor {
    /// A monitor for basic (`ext = false`) or extended-alarm words.
    pub fn new(ext: bool) -> Self {
        Self {
            clock: Default::default(),
            i_samples: Default::default(),
            i_slots_m1: Default::default(),
            i_address: Default::default(),
            o_los: Default::default(),
            o_bvalid: Default::default(),
            o_level: Default::default(),
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
            o_void: Default::default(),
            o_own: Default::default(),
            o_hdr_bad: Default::default(),
            o_ptype: Default::default(),
            cdr: Default::default(),
            framer: RxFramer::new(),
            word: RxWord::new(ext),
        }
    }
}

impl Logic for Monitor {
    #[hdl_gen]
    fn update(&mut self) {
        self.cdr.clock.next = self.clock.val();
        self.framer.clock.next = self.clock.val();
        self.word.clock.next = self.clock.val();
        self.cdr.i_samples.next = self.i_samples.val();
        self.framer.i_valid.next = self.cdr.o_valid.val();
        self.framer.i_level.next = self.cdr.o_bit.val();
        self.framer.i_end.next = self.word.o_end.val() | self.cdr.o_los.val();
        self.word.i_start.next = self.framer.o_start.val();
        self.word.i_gvalid.next = self.framer.o_gvalid.val();
        self.word.i_group.next = self.framer.o_group.val();
        self.word.i_slots_m1.next = self.i_slots_m1.val();
        self.word.i_address.next = self.i_address.val();
        self.o_los.next = self.cdr.o_los.val();
        self.o_bvalid.next = self.cdr.o_valid.val();
        self.o_level.next = self.cdr.o_bit.val();
        self.o_phase.next = self.cdr.o_phase.val();
        self.o_start.next = self.framer.o_start.val();
        self.o_inpkt.next = self.framer.o_inpkt.val();
        self.o_wvalid.next = self.word.o_wvalid.val();
        self.o_kind.next = self.word.o_kind.val();
        self.o_slot.next = self.word.o_slot.val();
        self.o_data.next = self.word.o_data.val();
        self.o_alive.next = self.word.o_alive.val();
        self.o_alarm.next = self.word.o_alarm.val();
        self.o_reason.next = self.word.o_reason.val();
        self.o_ok.next = self.word.o_ok.val();
        self.o_void.next = self.word.o_void.val();
        self.o_own.next = self.word.o_own.val();
        self.o_hdr_bad.next = self.word.o_hdr_bad.val();
        self.o_ptype.next = self.word.o_ptype.val();
    }
}
