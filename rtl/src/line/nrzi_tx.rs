//! # nrzi_tx — code-group serializer with NRZI (protocol §2)
//!
//! Purpose: sends 5-bit code groups bit by bit, most significant bit first,
//! NRZI-modulated: a 1 toggles `o_line`, a 0 keeps it. One bit per
//! `i_bit_en` (the node's bit-time enable, tied high when the core clock is
//! the bit clock). The group on `i_code` is taken in the clock where `o_take`
//! is high (the first bit time of each group), so the feeding logic has the
//! whole previous group's time to prepare it.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_bit_en` | in | 1 | clock | one bit time |
//! | `i_code` | in | 5 | clock | next code group, sampled when `o_take` |
//! | `o_take` | out | 1 | clock | `i_code` is taken in this clock |
//! | `o_line` | out | 1 | clock | NRZI line level (registered) |
//!
//! Latency: `o_line` shows a group's first bit one clock after the clock in
//! which `o_take` was high; a group occupies 5 bit times.
//!
//! ```text
//! clock     _/‾\_/‾\_/‾\_/‾\_/‾\_/‾\_/‾\_
//! i_bit_en  ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾ (tied high)
//! o_take    ‾‾‾\___________________/‾‾‾‾
//! i_code    = G0 =================== G1 =
//! code bit      g0[4] g0[3] g0[2] g0[1] g0[0] g1[4]
//! o_line    ____ toggles on every 1 bit ____
//! ```

use rust_hdl::prelude::*;

/// Serializer + NRZI modulator.
#[derive(LogicBlock, Default)]
pub struct NrziTx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Bit-time enable.
    pub i_bit_en: Signal<In, Bit>,
    /// Next code group.
    pub i_code: Signal<In, Bits<5>>,
    /// `i_code` is taken in this clock.
    pub o_take: Signal<Out, Bit>,
    /// Line level.
    pub o_line: Signal<Out, Bit>,
    shift: DFF<Bits<5>>,
    count: DFF<Bits<3>>,
    level: DFF<Bit>,
}

impl Logic for NrziTx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, shift, count, level);
        self.o_take.next = self.i_bit_en.val() & (self.count.q.val() == 0);
        self.o_line.next = self.level.q.val();
        if self.i_bit_en.val() {
            if self.count.q.val() == 0 {
                self.level.d.next = self.level.q.val() ^ self.i_code.val().get_bit(4);
                self.shift.d.next = self.i_code.val() << 1;
            } else {
                self.level.d.next = self.level.q.val() ^ self.shift.q.val().get_bit(4);
                self.shift.d.next = self.shift.q.val() << 1;
            }
            if self.count.q.val() == 4 {
                self.count.d.next = 0.into();
            } else {
                self.count.d.next = self.count.q.val() + 1;
            }
        }
    }
}
