//! # slave — the MERKUR slave node (the paper's Figure 6)
//!
//! Purpose: one sensor or actuator node: the switchbox (Table 1), a
//! supervised receive port on INPUT and on BSR (clock recovery, framer,
//! words, stream controllers), the cut-through forwarder (slot shift
//! register) from INPUT to OUTPUT, the secondary pass-through (BSR → BSS in
//! mode N, retimed; a TST from a neighbour is cut after its H0, protocol §9)
//! or the link-test generator (BSS in modes WU, WD), the mode and
//! failsafe logic (protocol §10, §12; after every switchbox change both
//! outputs are dark for 12 bit times, [`crate::node::sw_dark`]), the
//! interrupt/alarm queue (§11) with confirmed delivery (the alarm in flight
//! is read back at INPUT in the next frame and sent again, same SEQ, if it
//! did not come round good), the
//! actuator's output register and the error counters. A [`crate::node::master`]
//! is this block with `i_master` = 1 and a database beside it.
//!
//! Retransmission on demand (protocol §8): the forwarder fills a sensor's
//! requests and puts an actuator's Alive into its copy; an actuator takes
//! a good copy of its slot from an RTX into its output register (no Alive
//! check), and an RTX's bad request words count in `o_perr`.
//!
//! Parameters: the word format ([`WordFormat`], protocol §4 or §6), for
//! its receive ports, forwarder and TST generator; in the extended-alarm
//! variant an alarm's SEQ is read back from the reason nibble and an
//! actuator takes an alarm word's data into its output register.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_pi`, `i_si` | in | 4 | clock | physical inputs, 4 samples per clock (quadrature DDR); with `i_cap_sel` INPUT's and BSR's |
//! | `i_cap_sel` | in | 1 | static | 0: the switchbox chooses INPUT and BSR from `i_pi` and `i_si`; 1: the capture register in front already did, by `o_cap_si` (below) |
//! | `o_cap_si` | out | 1 | clock | for a capture register that makes the switchbox's input choice: take SI as INPUT and PI as BSR in this clock (the mode in the next clock is WU; a register) |
//! | `o_po`, `o_so` | out | 2 | clock | physical outputs, DDR pairs |
//! | `i_address` | in | 12 | static (DIP switches) | home slot |
//! | `i_slots_m1` | in | 12 | static | slots per frame − 1 |
//! | `i_actuator` | in | 1 | static | 1 actuator, 0 sensor |
//! | `i_cs_timeout` | in | 20 | static | clocks without the start of a packet other than a TST on INPUT before failsafe (3.5 cycle periods, protocol §12 rule 4) |
//! | `i_sensor_data` | in | 16 | clock | sensor value |
//! | `i_irq1`, `i_irq2`, `i_fs_req` | in | 1 | clock | user requests (a high clock queues the alarm) |
//! | `o_act_data` | out | 16 | clock | actuator output register |
//! | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD) |
//! | `o_failsafe` | out | 1 | clock | failsafe (until a CLR header brings the node out, protocol §12) |
//! | `o_perr` | out | 16 | clock | bad words seen at INPUT (saturating) |
//! | `o_ferr` | out | 16 | clock | frame errors: rejected headers at INPUT (saturating) |
//! | `i_master`, `i_slot_cfg`, `i_slot_data`, `i_slot_alive`, `i_fs_set` | in | 1, 2, 16, 1, 1 | clock | master mode (tied 0 in a slave): see [`crate::node::master`] |
//! | `o_fwd_slot`, `o_regen` | out | 12, 1 | clock | master mode: the forwarder's slot, VOID regenerated |
//! | `o_wvalid`, `o_kind`, `o_slot`, `o_data`, `o_alive`, `o_alarm`, `o_reason`, `o_ok`, `o_hdr_bad` | out | | clock | INPUT's words (`o_reason`: the extended variant's reason nibble, else 0) and rejected headers, for a master's memories |
//! | `o_rtx` | out | 1 | clock | the word is an RTX's copy of slot `o_slot` (its data word after a good index word, as a slot word, `o_kind` = 2; outside failsafe); an RTX's other words do not show (protocol §8) |
//!
//! Latency: INPUT to OUTPUT 9.5–10.5 bit times from the samples at `i_pi`
//! to the line at `o_po` (the CDR, one group and a bit, the retime buffer:
//! [`Fwd`]); 10–11 from fibre to fibre with a top's capture register in
//! front (`merkur_ddr_in`; measured in the ring, docs/benchmarks.md); BSR to BSS ≈ 3.5 bit times (the CDR
//! and [`Retime`]). A switch decision acts two clocks after the receivers'
//! report ([`SwitchPipe`]).
//!
//! ```text
//! PI ─┐            ┌─ port_rx (INPUT) ── fwd ── OUTPUT ─┐            ┌─ sw_dark ─ PO
//!     ├─ switchbox ┤                                     ├─ switchbox ┤
//! SI ─┘            └─ port_rx (BSR) ─ repeater / tst_tx ─ BSS ─┘     └─ sw_dark ─ SO
//! ```

use crate::line::retime::{Layout, Retime};
use crate::line::word_rx::WordFormat;
use crate::node::fwd::Fwd;
use crate::node::port_rx::PortRx;
use crate::node::sw_dark::SwDark;
use crate::node::switch_ctl::SwitchPipe;
use crate::node::switchbox::Switchbox;
use crate::node::tst_tx::TstTx;
use rust_hdl::prelude::*;

/// Slave node.
#[derive(LogicBlock)]
pub struct Slave {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Primary input.
    pub i_pi: Signal<In, Bits<4>>,
    /// Secondary input.
    pub i_si: Signal<In, Bits<4>>,
    /// The capture in front made the switchbox's input choice.
    pub i_cap_sel: Signal<In, Bit>,
    /// The capture's choice for the next clock: SI as INPUT.
    pub o_cap_si: Signal<Out, Bit>,
    /// Primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Secondary output.
    pub o_so: Signal<Out, Bits<2>>,
    /// Home slot.
    pub i_address: Signal<In, Bits<12>>,
    /// Slots − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Actuator (1) or sensor (0).
    pub i_actuator: Signal<In, Bit>,
    /// CS timeout in clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Sensor value.
    pub i_sensor_data: Signal<In, Bits<16>>,
    /// User interrupt 1 request.
    pub i_irq1: Signal<In, Bit>,
    /// User interrupt 2 request.
    pub i_irq2: Signal<In, Bit>,
    /// User failsafe request.
    pub i_fs_req: Signal<In, Bit>,
    /// Master node (the forwarder writes the slots `i_slot_cfg` marks).
    pub i_master: Signal<In, Bit>,
    /// Master: configuration of slot `o_fwd_slot` (bit 0 LOCAL, bit 1 ACT).
    pub i_slot_cfg: Signal<In, Bits<2>>,
    /// Master: data memory of slot `o_fwd_slot`.
    pub i_slot_data: Signal<In, Bits<16>>,
    /// Master: last actuator Alive of slot `o_fwd_slot`.
    pub i_slot_alive: Signal<In, Bit>,
    /// Master: enter failsafe (a FAILSAFE alarm was received).
    pub i_fs_set: Signal<In, Bit>,
    /// Master: slot the forwarder is at.
    pub o_fwd_slot: Signal<Out, Bits<12>>,
    /// Master: an ACT slot's VOID was regenerated.
    pub o_regen: Signal<Out, Bit>,
    /// INPUT word complete (for the master's memories).
    pub o_wvalid: Signal<Out, Bit>,
    /// Its kind (0 H0, 1 H1, 2 slot).
    pub o_kind: Signal<Out, Bits<2>>,
    /// Its slot.
    pub o_slot: Signal<Out, Bits<12>>,
    /// Its data.
    pub o_data: Signal<Out, Bits<16>>,
    /// Its ALIVE bit.
    pub o_alive: Signal<Out, Bit>,
    /// Its ALARM bit.
    pub o_alarm: Signal<Out, Bit>,
    /// Its reason nibble (extended-alarm words; 0 otherwise).
    pub o_reason: Signal<Out, Bits<4>>,
    /// Good word.
    pub o_ok: Signal<Out, Bit>,
    /// INPUT rejected a DATA header (or a header it could not read).
    pub o_hdr_bad: Signal<Out, Bit>,
    /// The word is a retransmission's copy of slot `o_slot` (protocol §8).
    pub o_rtx: Signal<Out, Bit>,
    /// Actuator output register.
    pub o_act_data: Signal<Out, Bits<16>>,
    /// Mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// Failsafe.
    pub o_failsafe: Signal<Out, Bit>,
    /// Bad words at INPUT.
    pub o_perr: Signal<Out, Bits<16>>,
    /// Rejected headers at INPUT.
    pub o_ferr: Signal<Out, Bits<16>>,
    sbox: Switchbox,
    dark: SwDark,
    swc: SwitchPipe,
    rx_in: PortRx,
    rx_bsr: PortRx,
    fwd: Fwd,
    tst: TstTx,
    rep: Retime,
    rep_cut: DFF<Bit>,
    fwd_cut: DFF<Bit>,
    failsafe: DFF<Bit>,
    rw: DFF<Bit>,
    h0_rwc: DFF<Bit>,
    sw_flush: DFF<Bit>,
    armed: DFF<Bit>,
    last_cyc: DFF<Bits<3>>,
    ferr_owed: DFF<Bits<3>>,
    cyc_gap: Signal<Local, Bits<3>>,
    quiet: DFF<Bits<20>>,
    /// `quiet` stands at its highest value (0xfffff) and stops there: the
    /// test in its own register, so that the counter's bits do not each
    /// repeat a 20-bit comparison (on a CoolRunner-II, bit k of the
    /// counter as a T flip-flop takes 20 − k product terms with the
    /// comparison and one without; docs/benchmarks.md).
    quiet_max: DFF<Bit>,
    /// A header restarted the CS timeout in the clock before: `quiet` and
    /// `quiet_max` then stand for 0, whatever they hold. The restart is a
    /// flip-flop of its own, so that the counter's bits read one literal
    /// for it instead of the header test's product terms (issue 21; the
    /// counter is exact: its next value is what it would have been one
    /// clock after a restart, and the failsafe test reads 0 while this is
    /// set).
    quiet_clr: DFF<Bit>,
    /// The CS timeout is due: the count (0 while `quiet_clr` is set)
    /// equals `i_cs_timeout` in an armed node; failsafe follows.
    cs_due: Signal<Local, Bit>,
    pend_fs: DFF<Bit>,
    pend_rc: DFF<Bit>,
    pend_i1: DFF<Bit>,
    pend_i2: DFF<Bit>,
    /// The alarm in flight (sent, not read back yet, protocol §11): 0 none,
    /// 1 IRQ1, 2 IRQ2, 3 RECONFIG (its reason is the node's mode: a mode
    /// change replaces it).
    fl_k: DFF<Bits<2>>,
    /// The SEQ the next new alarm gets (the one in flight has the other).
    nxt: DFF<Bit>,
    seq_tx: Signal<Local, Bit>,
    e_rc: Signal<Local, Bit>,
    e_i1: Signal<Local, Bit>,
    act_data: DFF<Bits<16>>,
    perr: DFF<Bits<16>>,
    ferr: DFF<Bits<16>>,
    reason: Signal<Local, Bits<4>>,
    // Extended-alarm words; the SEQ of INPUT's word (D[11], or N1 bit 3).
    ext: Constant<Bit>,
    // Retransmission on demand is built in (see [`Slave::with_rtx`]).
    rtx_on: Constant<Bit>,
    rx_seq: Signal<Local, Bit>,
    wrapped: Signal<Local, Bit>,
    out_pair: Signal<Local, Bits<2>>,
    bss_pair: Signal<Local, Bits<2>>,
}

impl Default for Slave {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl Slave {
    /// A slave node for words in `format`, with retransmission on demand.
    pub fn new(format: WordFormat) -> Self {
        Self::with_rtx(format, true)
    }

    /// A slave node for words in `format`; without retransmission on
    /// demand (`rtx` false, for a ring without critical slots: `merkur
    /// synth` builds it so for the smallest devices) it passes an RTX on
    /// unchanged, as a SEC.
    pub fn with_rtx(format: WordFormat, rtx: bool) -> Self {
        Self {
            clock: Default::default(),
            i_pi: Default::default(),
            i_si: Default::default(),
            i_cap_sel: Default::default(),
            o_cap_si: Default::default(),
            o_po: Default::default(),
            o_so: Default::default(),
            i_address: Default::default(),
            i_slots_m1: Default::default(),
            i_actuator: Default::default(),
            i_cs_timeout: Default::default(),
            i_sensor_data: Default::default(),
            i_irq1: Default::default(),
            i_irq2: Default::default(),
            i_fs_req: Default::default(),
            i_master: Default::default(),
            i_slot_cfg: Default::default(),
            i_slot_data: Default::default(),
            i_slot_alive: Default::default(),
            i_fs_set: Default::default(),
            o_fwd_slot: Default::default(),
            o_regen: Default::default(),
            o_wvalid: Default::default(),
            o_kind: Default::default(),
            o_slot: Default::default(),
            o_data: Default::default(),
            o_alive: Default::default(),
            o_alarm: Default::default(),
            o_reason: Default::default(),
            o_ok: Default::default(),
            o_hdr_bad: Default::default(),
            o_rtx: Default::default(),
            o_act_data: Default::default(),
            o_mode: Default::default(),
            o_failsafe: Default::default(),
            o_perr: Default::default(),
            o_ferr: Default::default(),
            sbox: Default::default(),
            dark: Default::default(),
            swc: Default::default(),
            rx_in: PortRx::new(format),
            rx_bsr: PortRx::new(format),
            fwd: Fwd::with_rtx(format, rtx),
            tst: TstTx::new(format),
            ext: Constant::new(format == WordFormat::ExtendedAlarm),
            rtx_on: Constant::new(rtx),
            rx_seq: Default::default(),
            rep: Default::default(),
            rep_cut: Default::default(),
            fwd_cut: Default::default(),
            failsafe: Default::default(),
            rw: Default::default(),
            h0_rwc: Default::default(),
            sw_flush: Default::default(),
            armed: Default::default(),
            last_cyc: Default::default(),
            ferr_owed: Default::default(),
            cyc_gap: Default::default(),
            quiet: Default::default(),
            quiet_max: Default::default(),
            quiet_clr: Default::default(),
            cs_due: Default::default(),
            pend_fs: Default::default(),
            pend_rc: Default::default(),
            pend_i1: Default::default(),
            pend_i2: Default::default(),
            fl_k: Default::default(),
            nxt: Default::default(),
            seq_tx: Default::default(),
            e_rc: Default::default(),
            e_i1: Default::default(),
            act_data: Default::default(),
            perr: Default::default(),
            ferr: Default::default(),
            reason: Default::default(),
            wrapped: Default::default(),
            out_pair: Default::default(),
            bss_pair: Default::default(),
        }
    }

    /// The same slave with both retime buffers (the forwarder's and the
    /// BSR repeater's) in `layout` (see [`Layout`]: the same behaviour
    /// clock for clock; [`Layout::WriteShifts`] for product-term devices).
    pub fn with_layout(mut self, layout: Layout) -> Self {
        self.fwd = self.fwd.with_layout(layout);
        self.rep = Retime::new(layout);
        self
    }
}

impl Logic for Slave {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, failsafe, rw, armed, quiet, quiet_max, quiet_clr, pend_fs, pend_rc,
            pend_i1, pend_i2, act_data, perr, ferr, rep_cut, fwd_cut, last_cyc, ferr_owed, h0_rwc,
            sw_flush, fl_k, nxt
        );
        self.rx_in.clock.next = self.clock.val();
        self.rx_bsr.clock.next = self.clock.val();
        self.fwd.clock.next = self.clock.val();
        self.tst.clock.next = self.clock.val();
        self.wrapped.next = self.swc.o_mode.val() != 0;

        // Switchbox.
        self.sbox.i_mode.next = self.swc.o_mode.val();
        self.sbox.i_pi.next = self.i_pi.val();
        self.sbox.i_si.next = self.i_si.val();
        self.rx_in.i_samples.next = self.sbox.o_input.val();
        self.rx_bsr.i_samples.next = self.sbox.o_bsr.val();
        // Or the capture register in front made that choice, with the
        // mode this clock's switchbox uses, a clock ahead (issue 21: the
        // clock recoveries then read their samples from flip-flops, not
        // through a multiplexer; the same samples in the same clocks).
        if self.i_cap_sel.val() {
            self.rx_in.i_samples.next = self.i_pi.val();
            self.rx_bsr.i_samples.next = self.i_si.val();
        }
        self.o_cap_si.next = self.swc.o_wu_next.val();
        self.rx_in.i_slots_m1.next = self.i_slots_m1.val();
        self.rx_in.i_address.next = self.i_address.val();
        self.rx_bsr.i_slots_m1.next = self.i_slots_m1.val();
        self.rx_bsr.i_address.next = self.i_address.val();
        // In mode N a TST where DATA is expected is a failure; not during
        // the grace period after unwrapping.
        self.rx_in.i_tst_fail.next = !self.wrapped.val() & self.swc.o_grace_over.val();
        self.rx_bsr.i_tst_fail.next = !self.wrapped.val() & self.swc.o_grace_over.val();

        // Forwarder INPUT -> OUTPUT.
        self.fwd.i_bvalid.next = self.rx_in.o_bvalid.val();
        self.fwd.i_code.next = self.rx_in.o_code.val();
        self.fwd.i_phase.next = self.rx_in.o_phase.val();
        // A rejected header, or a SEC/TST packet on INPUT (a wrapped node's
        // INPUT is a secondary fibre): passed on unchanged, not processed.
        // An RTX (type 11) is processed: its requests (protocol §8).
        self.fwd.i_hdr_bad.next = self.rx_in.o_hdr_bad.val()
            | (self.rx_in.o_wvalid.val()
                & (self.rx_in.o_kind.val() == 0)
                & self.rx_in.o_ok.val()
                & (self.rx_in.o_ptype.val() != 0)
                & ((self.rx_in.o_ptype.val() != 3) | !self.rtx_on.val()));
        self.fwd.i_armed.next = self.armed.q.val();
        self.fwd.i_wvalid.next = self.rx_in.o_wvalid.val();
        self.fwd.i_wkind.next = self.rx_in.o_kind.val();
        self.fwd.i_wodd.next = self.rx_in.o_slot.val().get_bit(0);
        self.fwd.i_wok.next = self.rx_in.o_ok.val();
        self.fwd.i_walarm.next = self.rx_in.o_alarm.val();
        self.fwd.i_wdata.next = self.rx_in.o_data.val();
        self.fwd.i_ptype.next = self.rx_in.o_ptype.val();
        // A TST on INPUT (a wrapped neighbour's link test, before this node
        // has wrapped) is for this node only: from its H0 on the rest goes
        // out as idles, so the next node sees no TST (protocol §9).
        if !self.rx_in.o_inpkt.val() {
            self.fwd_cut.d.next = false;
        }
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 0)
            & self.rx_in.o_ok.val()
            & (self.rx_in.o_ptype.val() == 2)
        {
            self.fwd_cut.d.next = true;
        }
        self.fwd.i_mute.next = self.fwd_cut.q.val();
        self.fwd.i_slots_m1.next = self.i_slots_m1.val();
        self.fwd.i_address.next = self.i_address.val();
        self.fwd.i_actuator.next = self.i_actuator.val();
        self.fwd.i_sensor_data.next = self.i_sensor_data.val();
        self.fwd.i_act_out.next = self.act_data.q.val();
        self.fwd.i_fs.next = self.failsafe.q.val();
        self.fwd.i_wrapped.next = self.wrapped.val();
        self.fwd.i_master.next = self.i_master.val();
        self.fwd.i_slot_cfg.next = self.i_slot_cfg.val();
        self.fwd.i_slot_data.next = self.i_slot_data.val();
        self.fwd.i_slot_alive.next = self.i_slot_alive.val();
        self.o_fwd_slot.next = self.fwd.o_slot.val();
        self.o_regen.next = self.fwd.o_regen.val();
        // INPUT's words for a master's memories. Of an RTX only its good
        // requests' data words go on, as slot words of the slot named
        // (`o_rtx`; protocol §8), and not in failsafe; its head and index
        // words stay here.
        self.o_wvalid.next = self.rx_in.o_wvalid.val()
            & ((self.rx_in.o_ptype.val() != 3) | (self.rx_in.o_kind.val() == 0));
        self.o_kind.next = self.rx_in.o_kind.val();
        self.o_slot.next = self.rx_in.o_slot.val();
        self.o_rtx.next = false;
        if (self.rx_in.o_kind.val() == 3) & self.rtx_on.val() {
            self.o_wvalid.next = self.rx_in.o_wvalid.val()
                & self.rx_in.o_slot.val().get_bit(0)
                & self.fwd.o_rtx_ok.val()
                & !self.failsafe.q.val();
            self.o_kind.next = 2.into();
            self.o_slot.next = self.fwd.o_rtx_idx.val();
            self.o_rtx.next = true;
        }
        self.o_data.next = self.rx_in.o_data.val();
        self.o_alive.next = self.rx_in.o_alive.val();
        self.o_alarm.next = self.rx_in.o_alarm.val();
        self.o_reason.next = self.rx_in.o_reason.val();
        self.o_ok.next = self.rx_in.o_ok.val();
        if self.i_fs_set.val() {
            self.failsafe.d.next = true;
        }

        // Alarm queue: FAILSAFE > the alarm in flight (a repeat, with its
        // SEQ) > RECONFIG > IRQ1 > IRQ2 (protocol §11); FAILSAFE has SEQ 0.
        self.e_rc.next = self.pend_rc.q.val();
        self.e_i1.next = self.pend_i1.q.val();
        self.seq_tx.next = self.nxt.q.val();
        if self.fl_k.q.val() != 0 {
            self.e_rc.next = self.fl_k.q.val() == 3;
            self.e_i1.next = self.fl_k.q.val() == 1;
            self.seq_tx.next = !self.nxt.q.val();
        }
        self.reason.next = 2.into();
        if self.e_i1.val() {
            self.reason.next = 1.into();
        }
        if self.e_rc.val() {
            self.reason.next = 4.into();
            if self.swc.o_mode.val() == 1 {
                self.reason.next = 5.into();
            }
            if self.swc.o_mode.val() == 2 {
                self.reason.next = 6.into();
            }
        }
        if self.pend_fs.q.val() {
            self.reason.next = 3.into();
            self.seq_tx.next = false;
        }
        self.fwd.i_alarm_req.next = self.pend_fs.q.val()
            | (self.fl_k.q.val() != 0)
            | self.pend_rc.q.val()
            | self.pend_i1.q.val()
            | self.pend_i2.q.val();
        self.fwd.i_alarm_reason.next = self.reason.val();
        self.fwd.i_alarm_seq.next = self.seq_tx.val();
        // What was sent (by the reason the forwarder took, even if the queue
        // changed since): a new alarm leaves the queue and is in flight; a
        // repeat changes nothing. (A RECONFIG repeat that a mode change
        // overtook after the forwarder took it counts as new: it then
        // fails its read-back, and the repeat has the new mode and SEQ.)
        if self.fwd.o_alarm_sent.val() {
            if self.fwd.o_sent_reason.val() == 3 {
                self.pend_fs.d.next = false;
                self.failsafe.d.next = true;
            } else if self.fl_k.q.val() == 0 {
                self.nxt.d.next = !self.nxt.q.val();
                if self.fwd.o_sent_reason.val() == 1 {
                    self.pend_i1.d.next = false;
                    self.fl_k.d.next = 1.into();
                } else if self.fwd.o_sent_reason.val() == 2 {
                    self.pend_i2.d.next = false;
                    self.fl_k.d.next = 2.into();
                } else {
                    self.pend_rc.d.next = false;
                    self.fl_k.d.next = 3.into();
                }
            }
        }
        self.rx_seq.next = self.rx_in.o_data.val().get_bit(11);
        if self.ext.val() {
            self.rx_seq.next = self.rx_in.o_reason.val().get_bit(3);
        }
        // The read-back: the home slot's word at INPUT in the frame after
        // the one that carried the alarm (outside failsafe). The forwarder
        // decides the home slot at its first group, before the word
        // completes at INPUT, so the frame that carried the alarm shows
        // `o_prev_alarm` high there and the next one (data: alternation)
        // low. The slot has one writer, so a good alarm word with the SEQ
        // in flight is the alarm itself, and ends it.
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 2)
            & self.rx_in.o_own.val()
            & !self.fwd.o_prev_alarm.val()
            & !self.failsafe.q.val()
            & self.rx_in.o_ok.val()
            & self.rx_in.o_alarm.val()
            & (self.rx_seq.val() != self.nxt.q.val())
        {
            self.fl_k.d.next = 0.into();
        }

        // CS timeout: no packet but TSTs for i_cs_timeout clocks (the
        // counter restarts below at every H0 that is not a good TST's: a
        // frame whose header a bit error damaged still shows the ring is
        // alive, protocol §12 rule 4).
        // `quiet_clr` set: the count stands for 0 (and `quiet_max` for
        // false), so it goes on from 0.
        self.quiet_clr.d.next = false;
        if self.quiet_clr.q.val() {
            self.quiet.d.next = 0.into();
            if self.armed.q.val() {
                self.quiet.d.next = 1.into();
            }
            self.quiet_max.d.next = false;
        } else if self.armed.q.val() & !self.quiet_max.q.val() {
            self.quiet.d.next = self.quiet.q.val() + 1;
            self.quiet_max.d.next = self.quiet.q.val() == 0xffffe;
        }
        // New requests after the clearing: a request in the clock its
        // predecessor went out is kept.
        if self.i_irq1.val() {
            self.pend_i1.d.next = true;
        }
        if self.i_irq2.val() {
            self.pend_i2.d.next = true;
        }
        if self.i_fs_req.val() {
            self.pend_fs.d.next = true;
        }
        self.cyc_gap.next = self.rx_in.o_data.val().get_bits::<3>(12) - self.last_cyc.q.val() - 1;
        // What INPUT's headers say: FS, ring wrapped (RWC in H0, RWP in H1).
        if self.rx_in.o_wvalid.val() & self.rx_in.o_ok.val() & (self.rx_in.o_ptype.val() == 0) {
            if self.rx_in.o_kind.val() == 0 {
                // RWC waits for H1 (RWP): the node's knowledge changes once
                // per header, not for the 25 bit times between its words.
                self.h0_rwc.d.next = self.rx_in.o_data.val().get_bit(12);
                // FS without CLR puts the node into failsafe; CLR (the
                // header's ALIVE bit) with FS = 0 brings it out (§12).
                if self.rx_in.o_data.val().get_bit(13) & !self.rx_in.o_alive.val() {
                    self.failsafe.d.next = true;
                }
                if !self.rx_in.o_data.val().get_bit(13) & self.rx_in.o_alive.val() {
                    self.failsafe.d.next = false;
                }
            }
            if self.rx_in.o_kind.val() == 1 {
                self.armed.d.next = true;
                // Cycles without a good frame: the gap in CYC since the
                // last one (counted when the next one comes).
                self.last_cyc.d.next = self.rx_in.o_data.val().get_bits::<3>(12);
                if self.armed.q.val() {
                    self.ferr_owed.d.next = self.cyc_gap.val();
                }
                self.rw.d.next =
                    self.h0_rwc.q.val() | self.rx_in.o_data.val().get_bit(15) | self.wrapped.val();
            }
            // Actuator output register: its own slot, good data (in the
            // extended variant an alarm word's too).
            if (self.rx_in.o_kind.val() == 2)
                & self.rx_in.o_own.val()
                & (!self.rx_in.o_alarm.val() | self.ext.val())
                & self.i_actuator.val()
                & !self.failsafe.q.val()
            {
                self.act_data.d.next = self.rx_in.o_data.val();
            }
        }
        // An RTX's copy of the actuator's slot (protocol §8): a good data
        // word after a good index word that named it; no Alive check.
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 3)
            & self.rx_in.o_slot.val().get_bit(0)
            & self.rx_in.o_ok.val()
            & !self.rx_in.o_alarm.val()
            & self.fwd.o_rtx_own.val()
            & self.i_actuator.val()
            & !self.failsafe.q.val()
        {
            self.act_data.d.next = self.rx_in.o_data.val();
        }
        // Error counters (saturating): bad slot words (an RTX's request
        // words too, outside failsafe); missed cycles, one per clock from
        // the CYC gap.
        if self.rx_in.o_wvalid.val()
            & ((self.rx_in.o_kind.val() == 2)
                | ((self.rx_in.o_kind.val() == 3) & !self.failsafe.q.val()))
            & !self.rx_in.o_ok.val()
            & !self.rx_in.o_void.val()
            & (self.perr.q.val() != 0xffff)
        {
            self.perr.d.next = self.perr.q.val() + 1;
        }
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 0)
            & !(self.rx_in.o_ok.val() & (self.rx_in.o_ptype.val() == 2))
        {
            self.quiet_clr.d.next = true;
        }
        if self.ferr_owed.q.val() != 0 {
            self.ferr_owed.d.next = self.ferr_owed.q.val() - 1;
            if self.ferr.q.val() != 0xffff {
                self.ferr.d.next = self.ferr.q.val() + 1;
            }
        }
        self.cs_due.next = self.armed.q.val()
            & ((self.quiet_clr.q.val() & (self.i_cs_timeout.val() == 0))
                | (!self.quiet_clr.q.val() & (self.quiet.q.val() == self.i_cs_timeout.val())));
        if self.cs_due.val() {
            self.failsafe.d.next = true;
        }
        // Switchbox decisions (protocol §10, §12): crate::node::switch_ctl.
        self.swc.clock.next = self.clock.val();
        self.swc.i_armed.next = self.armed.q.val();
        self.swc.i_hard_in.next = self.rx_in.o_hard.val();
        self.swc.i_hard_bsr.next = self.rx_bsr.o_hard.val();
        self.swc.i_run_in.next = self.rx_in.o_run.val();
        self.swc.i_run_bsr.next = self.rx_bsr.o_run.val();
        self.swc.i_los_in.next = self.rx_in.o_los.val();
        self.swc.i_los_bsr.next = self.rx_bsr.o_los.val();
        self.swc.i_rw.next = self.rw.q.val();
        self.swc.i_fs.next = self.failsafe.q.val();
        self.swc.i_tst_ack.next = self.rx_bsr.o_tst.val() & self.rx_bsr.o_ack.val();
        // A WD node unwraps between frames, once OUTPUT has sent the one
        // that ended on INPUT (SwitchPipe with `i_fwd`; `i_frame_start` is
        // the clock base's period tick, which a slave has not).
        self.swc.i_fwd.next = true;
        self.swc.i_frame_start.next = false;
        self.swc.i_in_pkt.next = self.rx_in.o_inpkt.val();
        self.swc.i_tst_in.next = self.rx_in.o_tst.val();
        self.swc.i_tst_bsr.next = self.rx_bsr.o_tst.val();
        self.swc.i_bsr_data.next = self.rx_bsr.o_wvalid.val()
            & (self.rx_bsr.o_kind.val() == 0)
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_ptype.val() == 0);
        self.swc.i_cs_timeout.next = self.i_cs_timeout.val();
        if self.swc.o_fs_set.val() {
            self.failsafe.d.next = true;
        }
        if self.swc.o_change.val() {
            self.pend_rc.d.next = true;
            // A RECONFIG in flight is replaced by the newer one (§11).
            if self.fl_k.q.val() == 3 {
                self.fl_k.d.next = 0.into();
            }
        }

        // OUTPUT: the forwarded stream; while INPUT is dark the retime
        // buffer sends idles on the node's own timing, so a break stays a
        // break of one link.
        self.out_pair.next = self.fwd.o_line.val();
        // BSS: in mode N the BSR stream repeated bit for bit; wrapped: TST.
        // (Retimed like OUTPUT, so the secondary ring's edges do not
        // wander either.)
        self.rep.clock.next = self.clock.val();
        self.rep.i_valid.next = self.rx_bsr.o_bvalid.val();
        // A TST on BSR is a link test between two neighbours, not for the
        // next node: once its H0 shows TST the rest goes out as idles, so
        // no complete TST (H1 = NOT H0) leaves this node; the cut ends
        // with the packet (before the next J K arrives).
        if !self.rx_bsr.o_inpkt.val() {
            self.rep_cut.d.next = false;
        }
        if self.rx_bsr.o_wvalid.val()
            & (self.rx_bsr.o_kind.val() == 0)
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_ptype.val() == 2)
        {
            self.rep_cut.d.next = true;
        }
        self.rep.i_code.next = self.rx_bsr.o_code.val();
        if self.rep_cut.q.val() {
            self.rep.i_code.next = true;
        }
        self.rep.i_phase.next = self.rx_bsr.o_phase.val();
        self.tst.i_ack.next = self.rx_bsr.o_tst.val();
        // At a switch the TST generator starts with a dark lead-in, and
        // the receivers, whose lines change, drop what they were in.
        self.tst.i_restart.next = self.swc.o_tst_start.val();
        // (Registered: the switch decision depends on what they report.)
        self.sw_flush.d.next = self.swc.o_relink.val();
        self.rx_in.i_flush.next = self.sw_flush.q.val();
        self.rx_bsr.i_flush.next = self.sw_flush.q.val();
        self.tst.i_address.next = self.i_address.val();
        self.bss_pair.next = self.rep.o_line.val();
        if self.wrapped.val() {
            self.bss_pair.next = self.tst.o_line.val();
        }
        self.sbox.i_output.next = self.out_pair.val();
        self.sbox.i_bss.next = self.bss_pair.val();
        // After a switchbox change both outputs are dark for a while, so
        // no downstream receiver splices the old source with the new.
        self.dark.clock.next = self.clock.val();
        self.dark.i_change.next = self.swc.o_change.val();
        self.dark.i_keep_po.next = false;
        self.dark.i_po.next = self.sbox.o_po.val();
        self.dark.i_so.next = self.sbox.o_so.val();
        self.o_po.next = self.dark.o_po.val();
        self.o_so.next = self.dark.o_so.val();

        self.o_act_data.next = self.act_data.q.val();
        self.o_mode.next = self.swc.o_mode.val();
        self.o_failsafe.next = self.failsafe.q.val();
        self.o_perr.next = self.perr.q.val();
        self.o_ferr.next = self.ferr.q.val();
        self.o_hdr_bad.next = self.rx_in.o_hdr_bad.val();
    }
}
