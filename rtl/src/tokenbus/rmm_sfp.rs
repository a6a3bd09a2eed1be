//! # rmm_sfp — status frame production (docs/protocol.md §20)
//!
//! Purpose: the paper's Status Frame Production Sub-module. Every
//! `i_sf_period` octets the station's **live counter** advances and a status
//! frame becomes due (`o_sf_pend`); the MAC sends it at its next token hold,
//! taking `o_sf_word` (live counter, status byte) and pulsing `i_sf_sent`.
//! The status byte (host status, both channels' status, dual mode, state,
//! active channel) is made by the station top from the live registers.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_sf_period` | in | 16 | production period, octets (≥ 2) |
//! | `i_sf_sent` | in | 1 | the MAC took the word into a frame |
//! | `i_status` | in | 8 | status byte |
//! | `o_sf_pend` | out | 1 | a status frame is due |
//! | `o_sf_word` | out | 16 | live counter << 8 \| status byte |
//!
//! Latency: `o_sf_pend` rises one octet after the period ends, falls one
//! octet after `i_sf_sent` (unless the next period ends in that octet).
//!
//! ```text
//! octet      P-1    P      ..     s      s+1
//! o_sf_pend  0      1      1      1      0
//! live       k      k+1    k+1    k+1    k+1
//! i_sf_sent  0      0      0      1      0
//! ```

use rust_hdl::prelude::*;

/// Status frame production.
#[derive(LogicBlock, Default)]
pub struct RmmSfp {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// Production period, octets.
    pub i_sf_period: Signal<In, Bits<16>>,
    /// The MAC took the status word.
    pub i_sf_sent: Signal<In, Bit>,
    /// Status byte.
    pub i_status: Signal<In, Bits<8>>,
    /// A status frame is due.
    pub o_sf_pend: Signal<Out, Bit>,
    /// Live counter and status byte.
    pub o_sf_word: Signal<Out, Bits<16>>,
    cnt: DFF<Bits<16>>,
    /// `cnt + 1` in 17 bits: it never wraps, so the comparison with the
    /// period is the same as Verilog's 32-bit sum, with no mixed widths.
    cnt_p1: Signal<Local, Bits<17>>,
    live: DFF<Bits<8>>,
    pend: DFF<Bit>,
    due: Signal<Local, Bit>,
}

impl Logic for RmmSfp {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, cnt, live, pend);
        self.cnt_p1.next = bit_cast::<17, 16>(self.cnt.q.val()) + 1;
        self.due.next = self.cnt_p1.val() >= bit_cast::<17, 16>(self.i_sf_period.val());
        if self.due.val() {
            self.cnt.d.next = 0.into();
            self.live.d.next = self.live.q.val() + 1;
            self.pend.d.next = true;
        } else {
            self.cnt.d.next = self.cnt.q.val() + 1;
            if self.i_sf_sent.val() {
                self.pend.d.next = false;
            }
        }
        self.o_sf_pend.next = self.pend.q.val();
        self.o_sf_word.next = ((bit_cast::<16, 8>(self.live.q.val()) | 0) << 8)
            | (bit_cast::<16, 8>(self.i_status.val()) | 0);
    }
}
