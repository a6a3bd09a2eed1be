//! # stream_ctl — stream controller: channel failure and test signal (protocol §9)
//!
//! Purpose: supervises one logical input (INPUT: the primary controller,
//! `pcf`/`ptst`; BSR: the secondary one, `scf`/`stst`) from the words its
//! receive chain ([`crate::line::monitor`]) decodes.
//!
//! Channel failure `o_cf` is any of:
//! - loss of signal (no line transition for 32 bit times, from the CDR);
//! - a test signal while `i_tst_fail` (mode N on INPUT: a TST where DATA is
//!   expected means the upstream neighbour has wrapped);
//! - 8 consecutive bad words damaged on this fibre (parity or code errors;
//!   VOID words are not bad, marked words — damaged on an earlier fibre,
//!   protocol §4 — leave the count as it is), until the next good word, or
//!   until the switchbox moves the input to another line (`i_flush`: a run
//!   is a property of one channel; carried over, it would make a node that
//!   wrapped because of it fail safe as soon as the settling time after the
//!   change is over).
//!
//! The first two are structural (`o_hard`: a dark fibre, a dead or wrapped
//! neighbour), the last a transient (`o_run`): a node decides differently on
//! them (protocol §9, §12; [`crate::node::switch_ctl`]).
//!
//! Test signal `o_tst`: a good TST packet (H0 type 10, H1 = NOT H0) was
//! received within the last 130 bit times (2 TST periods); `o_ack` is the
//! ACK bit of the last one.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_los` | in | 1 | clock | loss of signal |
//! | `i_wvalid`, `i_kind`, `i_ok`, `i_void`, `i_marked`, `i_compl`, `i_ptype` | in | | clock | word outputs of the receive chain (`i_compl`: data = NOT the previous word's, [`crate::line::word_rx`]) |
//! | `i_d12` | in | 1 | clock | the word's data bit 12 (a TST's H1 carries NOT ACK there) |
//! | `i_tst_fail` | in | 1 | static | a test signal counts as channel failure |
//! | `i_flush` | in | 1 | clock | the input moved to another line: the run of bad words restarts |
//! | `o_cf` | out | 1 | clock | channel failure (`o_hard` or `o_run`) |
//! | `o_hard` | out | 1 | clock | loss of signal, or a test signal while `i_tst_fail` |
//! | `o_run` | out | 1 | clock | 8 bad words in a row damaged on this fibre |
//! | `o_tst` | out | 1 | clock | test signal |
//! | `o_ack` | out | 1 | clock | ACK of the last TST |
//!
//! Latency: registered, one clock after the word or LOS that decides.
//!
//! ```text
//! words      TST   TST   TST   (idle ...............................)
//! o_tst      __/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\____   130 bit times after the last
//! o_cf       __/‾‾‾‾ ... (only with i_tst_fail) ‾‾‾‾‾‾‾‾‾‾‾‾\____
//! ```

use rust_hdl::prelude::*;

/// Clocks a test signal is held after the last TST (130 bit times).
pub const TST_HOLD_CLOCKS: u64 = 260;
/// Consecutive bad words that make a channel failure.
pub const BAD_WORDS: u64 = 8;

/// Stream controller.
#[derive(LogicBlock)]
pub struct StreamCtl {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Loss of signal.
    pub i_los: Signal<In, Bit>,
    /// Word complete.
    pub i_wvalid: Signal<In, Bit>,
    /// 0 H0, 1 H1, 2 slot.
    pub i_kind: Signal<In, Bits<2>>,
    /// Word good.
    pub i_ok: Signal<In, Bit>,
    /// VOID word.
    pub i_void: Signal<In, Bit>,
    /// Marked word (damaged on an earlier fibre).
    pub i_marked: Signal<In, Bit>,
    /// The word's data bit 12 (in a TST's H1: NOT ACK).
    pub i_d12: Signal<In, Bit>,
    /// The word's data is the complement of the previous word's.
    pub i_compl: Signal<In, Bit>,
    /// Packet type.
    pub i_ptype: Signal<In, Bits<2>>,
    /// A test signal counts as channel failure.
    pub i_tst_fail: Signal<In, Bit>,
    /// The input moved to another line.
    pub i_flush: Signal<In, Bit>,
    /// Channel failure.
    pub o_cf: Signal<Out, Bit>,
    /// Structural channel failure (loss of signal, a TST where DATA is expected).
    pub o_hard: Signal<Out, Bit>,
    /// A run of bad words damaged on this fibre.
    pub o_run: Signal<Out, Bit>,
    /// Test signal.
    pub o_tst: Signal<Out, Bit>,
    /// ACK bit of the last TST.
    pub o_ack: Signal<Out, Bit>,
    /// What `hold` takes in the clock after a load (`TST_HOLD_CLOCKS` − 2:
    /// in that clock it stands for `TST_HOLD_CLOCKS` − 1).
    hold_after: Constant<Bits<9>>,
    bad_max: Constant<Bits<4>>,
    bad: DFF<Bits<4>>,
    hold: DFF<Bits<9>>,
    /// A TST loaded the hold in the clock before: `hold` then stands for
    /// `TST_HOLD_CLOCKS` − 1, whatever it holds (issue 21: the load is one literal
    /// in each counter bit's product terms, not the TST test's).
    hold_ld: DFF<Bit>,
    tst: DFF<Bit>,
    ack: DFF<Bit>,
    hard: DFF<Bit>,
    run: DFF<Bit>,
}

impl Default for StreamCtl {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_los: Default::default(),
            i_wvalid: Default::default(),
            i_kind: Default::default(),
            i_ok: Default::default(),
            i_void: Default::default(),
            i_marked: Default::default(),
            i_d12: Default::default(),
            i_compl: Default::default(),
            i_ptype: Default::default(),
            i_tst_fail: Default::default(),
            i_flush: Default::default(),
            o_cf: Default::default(),
            o_hard: Default::default(),
            o_run: Default::default(),
            o_tst: Default::default(),
            o_ack: Default::default(),
            hold_after: Constant::new((TST_HOLD_CLOCKS - 2).to_bits()),
            bad_max: Constant::new(BAD_WORDS.to_bits()),
            bad: Default::default(),
            hold: Default::default(),
            hold_ld: Default::default(),
            tst: Default::default(),
            ack: Default::default(),
            hard: Default::default(),
            run: Default::default(),
        }
    }
}

impl Logic for StreamCtl {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, bad, hold, hold_ld, tst, ack, hard, run);
        if self.i_wvalid.val() {
            if self.i_ok.val() {
                self.bad.d.next = 0.into();
            } else if !self.i_void.val()
                & !self.i_marked.val()
                & (self.bad.q.val() != self.bad_max.val())
            {
                self.bad.d.next = self.bad.q.val() + 1;
            }
        }
        if self.i_flush.val() {
            self.bad.d.next = 0.into();
        }
        // A good TST packet: H1 completes good, type 10, H1 = NOT H0 (the
        // word decoder compares them as H1 arrives; H1 follows a good H0,
        // or the packet would have ended at it). ACK is H0's bit 12, i.e.
        // NOT H1's.
        // `hold` counts down while `tst` holds, and `tst` ends in the
        // clock after it reached 0 (it then wraps round; nothing reads it
        // until the next TST loads it). A load is `hold_ld`: in the clock
        // after it `hold` stands for `TST_HOLD_CLOCKS` − 1 (not 0). Issue 21: the
        // counter bits read two flip-flops, not a 9-bit zero test nor the
        // TST test (on a CoolRunner-II a T flip-flop of two product terms
        // each).
        self.hold_ld.d.next = false;
        if self.tst.q.val() {
            self.hold.d.next = self.hold.q.val() - 1;
            if self.hold_ld.q.val() {
                self.hold.d.next = self.hold_after.val();
            }
            if !self.hold_ld.q.val() & (self.hold.q.val() == 0) {
                self.tst.d.next = false;
            }
        }
        if self.i_wvalid.val()
            & (self.i_kind.val() == 1)
            & self.i_ok.val()
            & (self.i_ptype.val() == 2)
            & self.i_compl.val()
        {
            self.tst.d.next = true;
            self.ack.d.next = !self.i_d12.val();
            self.hold_ld.d.next = true;
        }
        self.hard.d.next = self.i_los.val() | (self.tst.q.val() & self.i_tst_fail.val());
        self.run.d.next = (self.bad.q.val() == self.bad_max.val()) & !self.i_flush.val();
        self.o_cf.next = self.hard.q.val() | self.run.q.val();
        self.o_hard.next = self.hard.q.val();
        self.o_run.next = self.run.q.val();
        self.o_tst.next = self.tst.q.val();
        self.o_ack.next = self.ack.q.val();
    }
}
