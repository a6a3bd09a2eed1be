//! # dcm — IEEE 802.4 Dual Channel Manager (docs/protocol.md §18)
//!
//! Purpose: one station's two physical channels (bus cables A and B) behind
//! one token-bus MAC. The MAC's symbol goes out on **both** PHYs (unless the
//! jabber inhibit is on); the MAC receives from the **active** channel only.
//! A status register per channel holds what a PHY can observe.
//!
//! The interface is octet-wide: one symbol per clock (one clock = one octet
//! time), bits 10:8 the kind (0 silence, 1 start delimiter, 2 data octet in
//! bits 7:0, 3 end delimiter, 4 noise/collision/framing error).
//!
//! Per channel, every octet:
//! - **divergence**: the other channel carries a frame symbol (SD, data, ED)
//!   and this one carries something else — this channel lost or garbled
//!   what every transmitter sent on both;
//! - **silence**: no carrier for [`SIL_LIMIT`] octets (`sil` saturates);
//! - `o_fault_*` (combinational) = divergence | silence;
//! - `bad` (registered) is set by a fault and cleared after `i_good_limit`
//!   fault-free octets; framing errors (kind 4) are counted (saturating).
//!
//! Switching: `i_sw` toggles the active channel **in this octet**: the
//! symbol delivered next clock already comes from the new channel, so a
//! fault switch (the fault correction machine answers a divergence in the
//! same octet) hands the MAC the standby's copy of the frame without a gap;
//! commanded switches are timed by the machine to fall between frames
//! (`o_in_frame`).
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_rx_a`, `i_rx_b` | in | 11 | symbols from PHY A / B |
//! | `i_tx` | in | 11 | symbol from the MAC |
//! | `i_sw` | in | 1 | toggle the active channel now |
//! | `i_good_limit` | in | 16 | fault-free octets before a channel is good again |
//! | `o_tx_a`, `o_tx_b` | out | 11 | to PHY A / B (combinational: `i_tx`, or silence while jabbering) |
//! | `o_rx` | out | 11 | to the MAC: the active channel, one octet late |
//! | `o_act` | out | 1 | active channel (0 A, 1 B) |
//! | `o_fault_a`, `o_fault_b` | out | 1 | combinational fault of this octet |
//! | `o_bad_a`, `o_bad_b` | out | 1 | latched channel fault |
//! | `o_in_frame` | out | 1 | the MAC is inside a frame (SD delivered, no ED yet) |
//! | `o_stat_a`, `o_stat_b` | out | 16 | status register: `errors[15:8]`, `carrier[3]`, `jabber[2]`, `silent[1]`, `bad[0]` |
//!
//! Latency: `o_rx` one octet after the symbol on the wire; a fault is seen
//! in the octet it happens (`o_fault_*`), latched one octet later.
//!
//! ```text
//! octet      n      n+1    n+2
//! i_rx_a     D5     --     --        A dies after octet n
//! i_rx_b     D5     D6     D7
//! o_fault_a  0      1      1
//! i_sw       0      1      0         (from the fault correction machine)
//! o_act      A      A      B
//! o_rx       ..     D5     D6   D7   the MAC misses nothing
//! ```

use merkur_model::rmm::{JABBER_LIMIT, SIL_LIMIT};
use rust_hdl::prelude::*;

/// Dual Channel Manager.
#[derive(LogicBlock)]
pub struct Dcm {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// Symbol from PHY A.
    pub i_rx_a: Signal<In, Bits<11>>,
    /// Symbol from PHY B.
    pub i_rx_b: Signal<In, Bits<11>>,
    /// Symbol from the MAC.
    pub i_tx: Signal<In, Bits<11>>,
    /// Toggle the active channel in this octet.
    pub i_sw: Signal<In, Bit>,
    /// Fault-free octets before a faulty channel is good again.
    pub i_good_limit: Signal<In, Bits<16>>,
    /// To PHY A.
    pub o_tx_a: Signal<Out, Bits<11>>,
    /// To PHY B.
    pub o_tx_b: Signal<Out, Bits<11>>,
    /// To the MAC.
    pub o_rx: Signal<Out, Bits<11>>,
    /// Active channel.
    pub o_act: Signal<Out, Bit>,
    /// Fault of A in this octet.
    pub o_fault_a: Signal<Out, Bit>,
    /// Fault of B in this octet.
    pub o_fault_b: Signal<Out, Bit>,
    /// A is faulty (latched).
    pub o_bad_a: Signal<Out, Bit>,
    /// B is faulty (latched).
    pub o_bad_b: Signal<Out, Bit>,
    /// Inside a delivered frame.
    pub o_in_frame: Signal<Out, Bit>,
    /// Status register A.
    pub o_stat_a: Signal<Out, Bits<16>>,
    /// Status register B.
    pub o_stat_b: Signal<Out, Bits<16>>,
    sil_limit: Constant<Bits<8>>,
    jab_limit: Constant<Bits<8>>,
    act: DFF<Bit>,
    rx: DFF<Bits<11>>,
    in_frame: DFF<Bit>,
    tx_cnt: DFF<Bits<8>>,
    sil_a: DFF<Bits<8>>,
    sil_b: DFF<Bits<8>>,
    good_a: DFF<Bits<16>>,
    good_b: DFF<Bits<16>>,
    bad_a: DFF<Bit>,
    bad_b: DFF<Bit>,
    err_a: DFF<Bits<8>>,
    err_b: DFF<Bits<8>>,
    car_a: DFF<Bit>,
    car_b: DFF<Bit>,
    kind_a: Signal<Local, Bits<3>>,
    kind_b: Signal<Local, Bits<3>>,
    fault_a: Signal<Local, Bit>,
    fault_b: Signal<Local, Bit>,
    good_a_n: Signal<Local, Bits<16>>,
    good_b_n: Signal<Local, Bits<16>>,
    jab: Signal<Local, Bit>,
    act_n: Signal<Local, Bit>,
    deliv: Signal<Local, Bits<11>>,
    stat_a: Signal<Local, Bits<16>>,
    stat_b: Signal<Local, Bits<16>>,
}

impl Default for Dcm {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_rx_a: Default::default(),
            i_rx_b: Default::default(),
            i_tx: Default::default(),
            i_sw: Default::default(),
            i_good_limit: Default::default(),
            o_tx_a: Default::default(),
            o_tx_b: Default::default(),
            o_rx: Default::default(),
            o_act: Default::default(),
            o_fault_a: Default::default(),
            o_fault_b: Default::default(),
            o_bad_a: Default::default(),
            o_bad_b: Default::default(),
            o_in_frame: Default::default(),
            o_stat_a: Default::default(),
            o_stat_b: Default::default(),
            sil_limit: Constant::new((SIL_LIMIT as u64).to_bits()),
            jab_limit: Constant::new((JABBER_LIMIT as u64).to_bits()),
            act: Default::default(),
            rx: Default::default(),
            in_frame: Default::default(),
            tx_cnt: Default::default(),
            sil_a: Default::default(),
            sil_b: Default::default(),
            good_a: Default::default(),
            good_b: Default::default(),
            bad_a: Default::default(),
            bad_b: Default::default(),
            err_a: Default::default(),
            err_b: Default::default(),
            car_a: Default::default(),
            car_b: Default::default(),
            kind_a: Default::default(),
            kind_b: Default::default(),
            fault_a: Default::default(),
            fault_b: Default::default(),
            good_a_n: Default::default(),
            good_b_n: Default::default(),
            jab: Default::default(),
            act_n: Default::default(),
            deliv: Default::default(),
            stat_a: Default::default(),
            stat_b: Default::default(),
        }
    }
}

impl Logic for Dcm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, act, rx, in_frame, tx_cnt, sil_a, sil_b, good_a, good_b, bad_a, bad_b,
            err_a, err_b, car_a, car_b
        );
        self.kind_a.next = self.i_rx_a.val().get_bits::<3>(8);
        self.kind_b.next = self.i_rx_b.val().get_bits::<3>(8);
        // Divergence: the other channel carries a frame symbol we do not.
        self.fault_a.next = ((self.kind_b.val() != 0)
            & (self.kind_b.val() < 4)
            & (self.i_rx_a.val() != self.i_rx_b.val()))
            | (self.sil_a.q.val() == self.sil_limit.val());
        self.fault_b.next = ((self.kind_a.val() != 0)
            & (self.kind_a.val() < 4)
            & (self.i_rx_b.val() != self.i_rx_a.val()))
            | (self.sil_b.q.val() == self.sil_limit.val());
        // Silence counters.
        if self.i_rx_a.val() != 0 {
            self.sil_a.d.next = 0.into();
        } else if self.sil_a.q.val() != self.sil_limit.val() {
            self.sil_a.d.next = self.sil_a.q.val() + 1;
        }
        if self.i_rx_b.val() != 0 {
            self.sil_b.d.next = 0.into();
        } else if self.sil_b.q.val() != self.sil_limit.val() {
            self.sil_b.d.next = self.sil_b.q.val() + 1;
        }
        // Good counters and the latched fault.
        if self.fault_a.val() {
            self.good_a_n.next = 0.into();
        } else if self.good_a.q.val() >= self.i_good_limit.val() {
            self.good_a_n.next = self.i_good_limit.val();
        } else {
            self.good_a_n.next = self.good_a.q.val() + 1;
        }
        if self.fault_b.val() {
            self.good_b_n.next = 0.into();
        } else if self.good_b.q.val() >= self.i_good_limit.val() {
            self.good_b_n.next = self.i_good_limit.val();
        } else {
            self.good_b_n.next = self.good_b.q.val() + 1;
        }
        self.good_a.d.next = self.good_a_n.val();
        self.good_b.d.next = self.good_b_n.val();
        self.bad_a.d.next = self.fault_a.val()
            | (self.bad_a.q.val() & (self.good_a_n.val() != self.i_good_limit.val()));
        self.bad_b.d.next = self.fault_b.val()
            | (self.bad_b.q.val() & (self.good_b_n.val() != self.i_good_limit.val()));
        // Framing errors and carrier.
        if (self.kind_a.val() == 4) & (self.err_a.q.val() != 255) {
            self.err_a.d.next = self.err_a.q.val() + 1;
        }
        if (self.kind_b.val() == 4) & (self.err_b.q.val() != 255) {
            self.err_b.d.next = self.err_b.q.val() + 1;
        }
        self.car_a.d.next = self.i_rx_a.val() != 0;
        self.car_b.d.next = self.i_rx_b.val() != 0;
        // Transmit on both, with the jabber inhibit.
        self.jab.next = self.tx_cnt.q.val() == self.jab_limit.val();
        if self.i_tx.val() == 0 {
            self.tx_cnt.d.next = 0.into();
        } else if !self.jab.val() {
            self.tx_cnt.d.next = self.tx_cnt.q.val() + 1;
        }
        if self.jab.val() {
            self.o_tx_a.next = 0.into();
            self.o_tx_b.next = 0.into();
        } else {
            self.o_tx_a.next = self.i_tx.val();
            self.o_tx_b.next = self.i_tx.val();
        }
        // Receive from the active channel.
        self.act_n.next = self.act.q.val() ^ self.i_sw.val();
        self.act.d.next = self.act_n.val();
        if self.act_n.val() {
            self.deliv.next = self.i_rx_b.val();
        } else {
            self.deliv.next = self.i_rx_a.val();
        }
        self.rx.d.next = self.deliv.val();
        if self.deliv.val().get_bits::<3>(8) == 1 {
            self.in_frame.d.next = true;
        } else if self.deliv.val().get_bits::<3>(8) != 2 {
            self.in_frame.d.next = false;
        }
        self.o_rx.next = self.rx.q.val();
        self.o_act.next = self.act.q.val();
        self.o_fault_a.next = self.fault_a.val();
        self.o_fault_b.next = self.fault_b.val();
        self.o_bad_a.next = self.bad_a.q.val();
        self.o_bad_b.next = self.bad_b.q.val();
        self.o_in_frame.next = self.in_frame.q.val();
        // Status registers: errors[15:8], carrier[3], jabber[2], silent[1], bad[0].
        self.stat_a.next = (bit_cast::<16, 8>(self.err_a.q.val()) | 0) << 8;
        self.stat_b.next = (bit_cast::<16, 8>(self.err_b.q.val()) | 0) << 8;
        if self.car_a.q.val() {
            self.stat_a.next = self.stat_a.val() | 8;
        }
        if self.car_b.q.val() {
            self.stat_b.next = self.stat_b.val() | 8;
        }
        if self.jab.val() {
            self.stat_a.next = self.stat_a.val() | 4;
            self.stat_b.next = self.stat_b.val() | 4;
        }
        if self.sil_a.q.val() == self.sil_limit.val() {
            self.stat_a.next = self.stat_a.val() | 2;
        }
        if self.sil_b.q.val() == self.sil_limit.val() {
            self.stat_b.next = self.stat_b.val() | 2;
        }
        if self.bad_a.q.val() {
            self.stat_a.next = self.stat_a.val() | 1;
        }
        if self.bad_b.q.val() {
            self.stat_b.next = self.stat_b.val() | 1;
        }
        self.o_stat_a.next = self.stat_a.val();
        self.o_stat_b.next = self.stat_b.val();
    }
}
