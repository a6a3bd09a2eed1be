//! # port_rx — one supervised receive port: [`Monitor`] + [`StreamCtl`]
//!
//! Purpose: what a node has on each logical input (INPUT and BSR): the receive
//! chain (CDR, framer, word decoder) and its stream controller.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_samples` | in | 4 | clock | line samples (quadrature DDR, 8 per bit) |
//! | `i_slots_m1`, `i_address` | in | 12 | static | as [`crate::line::word_rx::WordRx`] |
//! | `i_tst_fail` | in | 1 | static | as [`StreamCtl`] |
//! | `i_flush` | in | 1 | clock | as [`Monitor`]; the stream controller's run of bad words restarts |
//! | `o_start`, `o_inpkt`, `o_wvalid`, `o_kind`, `o_slot`, `o_data`, `o_alive`, `o_alarm`, `o_ok`, `o_void`, `o_marked`, `o_own`, `o_hdr_bad`, `o_ptype` | out | | clock | as [`Monitor`] |
//! | `o_los`, `o_cf`, `o_hard`, `o_run`, `o_tst`, `o_ack` | out | 1 | clock | loss of signal; as [`StreamCtl`] |
//! | `o_bvalid`, `o_code`, `o_phase` | out | 1, 1, 2 | clock | recovered bit stream (from the CDR: `o_code` 1 where the line level changed) |
//!
//! Latency: as [`Monitor`]; stream-controller outputs one clock later.
//!
//! ```text
//! i_samples ~~~~~~ line ~~~~~~|______ dark ______________________
//! o_los     ____________________________________/‾‾‾‾‾‾‾‾‾‾‾‾‾‾   32 bit times later
//! o_cf      _____________________________________/‾‾‾‾‾‾‾‾‾‾‾‾‾
//! ```

use crate::line::monitor::Monitor;
use crate::line::word_rx::WordFormat;
use crate::node::stream_ctl::StreamCtl;
use rust_hdl::prelude::*;

/// Supervised receive port.
#[derive(LogicBlock)]
pub struct PortRx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Line samples.
    pub i_samples: Signal<In, Bits<4>>,
    /// Slot count − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Node address.
    pub i_address: Signal<In, Bits<12>>,
    /// A test signal counts as channel failure.
    pub i_tst_fail: Signal<In, Bit>,
    /// The switchbox moved this input to another line (see [`Monitor`]).
    pub i_flush: Signal<In, Bit>,
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
    /// Marked word (damaged on an earlier fibre, protocol §4).
    pub o_marked: Signal<Out, Bit>,
    /// Own slot.
    pub o_own: Signal<Out, Bit>,
    /// Header rejected.
    pub o_hdr_bad: Signal<Out, Bit>,
    /// Packet type.
    pub o_ptype: Signal<Out, Bits<2>>,
    /// Loss of signal.
    pub o_los: Signal<Out, Bit>,
    /// Recovered bit valid (from the CDR).
    pub o_bvalid: Signal<Out, Bit>,
    /// Its code bit (1: the line level changed).
    pub o_code: Signal<Out, Bit>,
    /// Sample phase of the recovered bit.
    pub o_phase: Signal<Out, Bits<2>>,
    /// Channel failure.
    pub o_cf: Signal<Out, Bit>,
    /// Structural channel failure.
    pub o_hard: Signal<Out, Bit>,
    /// Channel failure by a run of bad words.
    pub o_run: Signal<Out, Bit>,
    /// Test signal.
    pub o_tst: Signal<Out, Bit>,
    /// ACK of the last TST.
    pub o_ack: Signal<Out, Bit>,
    mon: Monitor,
    ctrl: StreamCtl,
}

impl PortRx {
    /// A port for words of `format`.
    pub fn new(format: WordFormat) -> Self {
        Self {
            clock: Default::default(),
            i_samples: Default::default(),
            i_slots_m1: Default::default(),
            i_address: Default::default(),
            i_flush: Default::default(),
            i_tst_fail: Default::default(),
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
            o_marked: Default::default(),
            o_own: Default::default(),
            o_hdr_bad: Default::default(),
            o_ptype: Default::default(),
            o_los: Default::default(),
            o_bvalid: Default::default(),
            o_code: Default::default(),
            o_phase: Default::default(),
            o_cf: Default::default(),
            o_hard: Default::default(),
            o_run: Default::default(),
            o_tst: Default::default(),
            o_ack: Default::default(),
            mon: Monitor::new(format),
            ctrl: Default::default(),
        }
    }
}

impl Logic for PortRx {
    #[hdl_gen]
    fn update(&mut self) {
        self.mon.clock.next = self.clock.val();
        self.ctrl.clock.next = self.clock.val();
        self.mon.i_samples.next = self.i_samples.val();
        self.mon.i_slots_m1.next = self.i_slots_m1.val();
        self.mon.i_address.next = self.i_address.val();
        self.mon.i_flush.next = self.i_flush.val();
        self.ctrl.i_los.next = self.mon.o_los.val();
        self.ctrl.i_wvalid.next = self.mon.o_wvalid.val();
        self.ctrl.i_kind.next = self.mon.o_kind.val();
        self.ctrl.i_ok.next = self.mon.o_ok.val();
        self.ctrl.i_void.next = self.mon.o_void.val();
        self.ctrl.i_marked.next = self.mon.o_marked.val();
        self.ctrl.i_d12.next = self.mon.o_data.val().get_bit(12);
        self.ctrl.i_compl.next = self.mon.o_compl.val();
        self.ctrl.i_ptype.next = self.mon.o_ptype.val();
        self.ctrl.i_tst_fail.next = self.i_tst_fail.val();
        self.ctrl.i_flush.next = self.i_flush.val();
        self.o_start.next = self.mon.o_start.val();
        self.o_inpkt.next = self.mon.o_inpkt.val();
        self.o_wvalid.next = self.mon.o_wvalid.val();
        self.o_kind.next = self.mon.o_kind.val();
        self.o_slot.next = self.mon.o_slot.val();
        self.o_data.next = self.mon.o_data.val();
        self.o_alive.next = self.mon.o_alive.val();
        self.o_alarm.next = self.mon.o_alarm.val();
        self.o_reason.next = self.mon.o_reason.val();
        self.o_ok.next = self.mon.o_ok.val();
        self.o_void.next = self.mon.o_void.val();
        self.o_marked.next = self.mon.o_marked.val();
        self.o_own.next = self.mon.o_own.val();
        self.o_hdr_bad.next = self.mon.o_hdr_bad.val();
        self.o_ptype.next = self.mon.o_ptype.val();
        self.o_los.next = self.mon.o_los.val();
        self.o_bvalid.next = self.mon.o_bvalid.val();
        self.o_code.next = self.mon.o_code.val();
        self.o_phase.next = self.mon.o_phase.val();
        self.o_cf.next = self.ctrl.o_cf.val();
        self.o_hard.next = self.ctrl.o_hard.val();
        self.o_run.next = self.ctrl.o_run.val();
        self.o_tst.next = self.ctrl.o_tst.val();
        self.o_ack.next = self.ctrl.o_ack.val();
    }
}
