//! # switch_ctl — a node's switchbox decisions (protocol §10, §12)
//!
//! Purpose: the local fault management of every node, the special master
//! included: from its two stream controllers it decides the switchbox mode
//! (Table 1), the failsafe of a second fault, and reintegration when a
//! repaired link's partner acknowledges its TST. No central station: each
//! node runs one of these on what it sees.
//!
//! - mode N: INPUT fails → WU; else BSR fails → WD. A structural failure
//!   (`i_hard_*`: loss of signal, a TST where DATA is expected) while the
//!   node knows the ring is wrapped is the second fault: failsafe, and so is
//!   loss of signal on both at once. A run of bad words (`i_run_*`, a
//!   transient) counts only while the ring is not known wrapped (a soft
//!   wrap), and never for failsafe (protocol §9, §12);
//! - wrapped: loss of signal on INPUT → failsafe; the partner's TST with
//!   ACK heard on BSR → a WD node unwraps at the next frame start after
//!   [`crate::slave::REINTEGRATE_CLOCKS`] of it, a WU node when a DATA
//!   header arrives on BSR after it and no packet is arriving on INPUT (if
//!   one is — the frame that went the long way round — when it ends, so it
//!   is not cut into the new one); in failsafe too (issue 28: that is how a
//!   ring that failed safe becomes whole again), where a WU node takes a
//!   DATA header on BSR for the ACK (its upstream neighbour forwards the
//!   ring's frames to it, so it is not wrapped towards it: the special
//!   master's downstream neighbour, cut off with it, hears no TST);
//! - stream controllers act only once the node is armed (its first good
//!   frame) and not for [`crate::slave::SETTLE_CLOCKS`] after a change (the
//!   receivers lock to their new lines); after unwrapping, a TST where DATA
//!   is expected is not a failure for half a CS timeout (`o_grace_over`).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_armed` | in | 1 | clock | the node has received its first good frame |
//! | `i_hard_in`, `i_hard_bsr` | in | 1 | clock | structural channel failure on INPUT, on BSR ([`crate::stream_ctrl`]) |
//! | `i_run_in`, `i_run_bsr` | in | 1 | clock | a run of bad words on INPUT, on BSR |
//! | `i_los_in`, `i_los_bsr` | in | 1 | clock | loss of signal on INPUT, on BSR |
//! | `i_rw` | in | 1 | clock | the node knows the ring is wrapped |
//! | `i_fs` | in | 1 | clock | the node is in failsafe |
//! | `i_tst_ack` | in | 1 | clock | a TST with ACK is being heard on BSR |
//! | `i_frame_start` | in | 1 | clock | a frame boundary: between frames on INPUT (a slave: a packet ended there); the special master's period tick |
//! | `i_bsr_data` | in | 1 | clock | a good DATA H0 on BSR |
//! | `i_in_pkt` | in | 1 | clock | a packet is arriving on INPUT |
//! | `i_cs_timeout` | in | 20 | static | CS timeout, clocks |
//! | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD), registered |
//! | `o_change` | out | 1 | clock | the mode changes at the next clock edge (combinational) |
//! | `o_relink` | out | 1 | clock | … and INPUT and BSR move to other lines (into or out of WU) |
//! | `o_tst_start` | out | 1 | clock | … and the TST generator goes onto an output (N → WU, WD) |
//! | `o_fs_set` | out | 1 | clock | enter failsafe (combinational) |
//! | `o_grace_over` | out | 1 | clock | a TST on a mode-N input counts as failure again |
//!
//! Latency: a decision takes effect at the next clock edge (`o_mode`).
//!
//! ```text
//! i_hard_in ____/‾‾‾‾‾‾‾‾‾
//! o_change  ____/‾\________        (mode N, ring not known wrapped)
//! o_mode    ==N===X==WU====
//! ```

use crate::slave::{REINTEGRATE_CLOCKS, SETTLE_CLOCKS};
use rust_hdl::prelude::*;

/// Switchbox decision logic.
#[derive(LogicBlock)]
pub struct SwitchCtl {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// First good frame seen.
    pub i_armed: Signal<In, Bit>,
    /// Structural channel failure on INPUT.
    pub i_hard_in: Signal<In, Bit>,
    /// Structural channel failure on BSR.
    pub i_hard_bsr: Signal<In, Bit>,
    /// A run of bad words on INPUT.
    pub i_run_in: Signal<In, Bit>,
    /// A run of bad words on BSR.
    pub i_run_bsr: Signal<In, Bit>,
    /// Loss of signal on INPUT.
    pub i_los_in: Signal<In, Bit>,
    /// Loss of signal on BSR.
    pub i_los_bsr: Signal<In, Bit>,
    /// The ring is known wrapped.
    pub i_rw: Signal<In, Bit>,
    /// The node is in failsafe.
    pub i_fs: Signal<In, Bit>,
    /// Partner's TST with ACK on BSR.
    pub i_tst_ack: Signal<In, Bit>,
    /// A frame starts.
    pub i_frame_start: Signal<In, Bit>,
    /// A good DATA H0 on BSR.
    pub i_bsr_data: Signal<In, Bit>,
    /// A packet is arriving on INPUT.
    pub i_in_pkt: Signal<In, Bit>,
    /// CS timeout, clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// The mode changes at the next edge.
    pub o_change: Signal<Out, Bit>,
    /// The receivers' lines move.
    pub o_relink: Signal<Out, Bit>,
    /// TST goes onto an output.
    pub o_tst_start: Signal<Out, Bit>,
    /// Enter failsafe.
    pub o_fs_set: Signal<Out, Bit>,
    /// Grace period over.
    pub o_grace_over: Signal<Out, Bit>,
    reintegrate: Constant<Bits<9>>,
    settle_start: Constant<Bits<7>>,
    mode: DFF<Bits<2>>,
    settle: DFF<Bits<7>>,
    grace: DFF<Bits<20>>,
    ack_time: DFF<Bits<9>>,
    seen_ack: DFF<Bit>,
    pend_up: DFF<Bit>,
    new_mode: Signal<Local, Bits<2>>,
    fail_in: Signal<Local, Bit>,
    fail_bsr: Signal<Local, Bit>,
    up_ok: Signal<Local, Bit>,
}

impl Default for SwitchCtl {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_armed: Default::default(),
            i_hard_in: Default::default(),
            i_hard_bsr: Default::default(),
            i_run_in: Default::default(),
            i_run_bsr: Default::default(),
            i_los_in: Default::default(),
            i_los_bsr: Default::default(),
            i_rw: Default::default(),
            i_fs: Default::default(),
            i_tst_ack: Default::default(),
            i_frame_start: Default::default(),
            i_bsr_data: Default::default(),
            i_in_pkt: Default::default(),
            i_cs_timeout: Default::default(),
            o_mode: Default::default(),
            o_change: Default::default(),
            o_relink: Default::default(),
            o_tst_start: Default::default(),
            o_fs_set: Default::default(),
            o_grace_over: Default::default(),
            reintegrate: Constant::new(REINTEGRATE_CLOCKS.to_bits()),
            settle_start: Constant::new(SETTLE_CLOCKS.to_bits()),
            mode: Default::default(),
            settle: Default::default(),
            grace: Default::default(),
            ack_time: Default::default(),
            seen_ack: Default::default(),
            pend_up: Default::default(),
            new_mode: Default::default(),
            fail_in: Default::default(),
            fail_bsr: Default::default(),
            up_ok: Default::default(),
        }
    }
}

impl Logic for SwitchCtl {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mode, settle, grace, ack_time, seen_ack, pend_up);
        if self.grace.q.val() != 0 {
            self.grace.d.next = self.grace.q.val() - 1;
        }
        if self.settle.q.val() != 0 {
            self.settle.d.next = self.settle.q.val() - 1;
        }
        self.o_fs_set.next = false;
        self.new_mode.next = self.mode.q.val();
        // In failsafe a DATA header on BSR is as good as the ACK (§12).
        self.up_ok.next = self.seen_ack.q.val() | self.i_fs.val();
        // A run of bad words wraps only a ring not known to be wrapped.
        self.fail_in.next = self.i_hard_in.val() | (self.i_run_in.val() & !self.i_rw.val());
        self.fail_bsr.next = self.i_hard_bsr.val() | (self.i_run_bsr.val() & !self.i_rw.val());
        if !self.i_armed.val() | (self.settle.q.val() != 0) {
        } else if self.mode.q.val() == 0 {
            if self.fail_in.val() {
                self.new_mode.next = 1.into();
            } else if self.fail_bsr.val() {
                self.new_mode.next = 2.into();
            }
            // The second structural fault; or both lines dark at once.
            if ((self.i_hard_in.val() | self.i_hard_bsr.val()) & self.i_rw.val())
                | (self.i_los_in.val() & self.i_los_bsr.val())
            {
                self.o_fs_set.next = true;
            }
        } else {
            if self.i_los_in.val() {
                self.o_fs_set.next = true;
            }
            if self.i_tst_ack.val() {
                self.seen_ack.d.next = true;
                if self.ack_time.q.val() != 511 {
                    self.ack_time.d.next = self.ack_time.q.val() + 1;
                }
            }
            if (self.mode.q.val() == 2)
                & (self.ack_time.q.val() >= self.reintegrate.val())
                & self.i_frame_start.val()
            {
                self.new_mode.next = 0.into();
            }
            if (self.mode.q.val() == 1) & self.up_ok.val() & self.i_bsr_data.val() {
                self.pend_up.d.next = true;
            }
            if (self.mode.q.val() == 1)
                & (self.pend_up.q.val() | (self.up_ok.val() & self.i_bsr_data.val()))
                & !self.i_in_pkt.val()
            {
                self.new_mode.next = 0.into();
            }
        }
        self.o_change.next = self.new_mode.val() != self.mode.q.val();
        self.o_relink.next =
            self.o_change.val() & ((self.mode.q.val() == 1) != (self.new_mode.val() == 1));
        self.o_tst_start.next = self.o_change.val() & (self.mode.q.val() == 0);
        if self.new_mode.val() != self.mode.q.val() {
            self.mode.d.next = self.new_mode.val();
            self.settle.d.next = self.settle_start.val();
            self.ack_time.d.next = 0.into();
            self.seen_ack.d.next = false;
            self.pend_up.d.next = false;
            if self.new_mode.val() == 0 {
                self.grace.d.next = self.i_cs_timeout.val() >> 1;
            }
        }
        self.o_mode.next = self.mode.q.val();
        self.o_grace_over.next = self.grace.q.val() == 0;
    }
}
