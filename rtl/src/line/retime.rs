//! # retime — elastic output buffer: sends recovered bits on the node's own clock (protocol §9)
//!
//! Purpose: a node retransmits at the rate of the stream it receives, but a
//! transmitter that repeats every edge where its receiver saw it also repeats
//! that receiver's sampling error, and on a long ring those errors add up
//! hop by hop until an edge moves by half a bit. This block breaks the chain:
//! code bits (1: the line toggles) go into a small buffer at the receive
//! timing and come out on the node's own clock, one bit per 4 half clocks (the DDR output's two halves
//! per clock); to follow the stream's rate it makes one bit 3 or 5 half
//! clocks long now and then. So an edge on the line is off by at most one
//! output half clock (2 receiver samples) from where the node's clock puts
//! it, whatever the input did, and a downstream receiver
//! ([`crate::line::cdr`]: 8k − 3 … 8k + 4 samples for a k-bit interval) has a
//! sample of margin on every link.
//!
//! **Phase measure.** At each write the block computes how long, in receive
//! samples (quarter clocks), the new bit will wait until it is sent:
//! `lag = 2·rem + 8·cnt − i_phase`, with `rem` the half clocks to the next
//! send at the start of the next clock, `cnt` the bits buffered and
//! `i_phase` the sample of its clock the bit was taken from. The target is
//! [`TARGET`] = 20 (2.5 bit times; a bit sent in the clock after its write
//! has a lag of 5–8). After [`VOTES`] writes in a row with
//! `lag` more than [`BAND`] above (below) the target, the next bit is sent
//! 3 (5) half clocks long, at most once per [`GAP`] bits, so that no edge
//! interval on the line carries two corrections. That follows a clock
//! difference of up to 1/(4·GAP) (31 000 ppm); a node's offset needs
//! ±2000 ppm.
//!
//! **Start and errors.** Until two bits have arrived it sends idles (NRZI
//! ones: the line toggles every bit) on its own bit grid; from the second
//! bit on it sends the buffer, from the grid's next boundary. A send with an empty buffer
//! (underflow: the input stopped) or a write into a full one (overflow)
//! pulses `o_slip` and empties the buffer; an underflow sends no idle edge
//! (the zeros the receiver read from a dying line before it muted would be
//! confirmed by it): the line stays dark until [`QUIET_BITS`] bit times
//! after the last edge it sent, so a downstream receiver mutes and drops the
//! word the input stopped in ([`crate::line::monitor`]) and a downstream
//! forwarder sees its input dead ([`crate::node::fwd::DEAD_CLOCKS`]); then it
//! sends idles, so the next node sees a live line again long before loss
//! of signal (32 bit times); the next bits start again. Counted from the
//! last edge *sent*, the gap is the same on every hop whatever the
//! pipeline in front of the buffer held back (a forwarder keeps a group of
//! the zeros read from a dying line in its delay line: counted from the
//! underflow, the gap shrank by that much per hop until a node no longer
//! saw it, issue 19). A live stream within ±2000 ppm never slips.
//!
//! **The buffer's layout** ([`Layout`], the block's one parameter; the
//! same behaviour clock for clock either way, proof `retime_layouts`):
//! with [`Layout::SendShifts`] the oldest bit sits in bit 0, a send
//! shifts it out and a write goes in behind the unsent bits, decoded by
//! the count: the bit to send is one flip-flop, short paths for LUT
//! devices (the ring's nodes and every FPGA top). With
//! [`Layout::WriteShifts`] a write shifts the new bit in at bit 7 and a
//! send reads the count's bit from the top (bit 8 − count): no write
//! decoder in every buffer bit, for product-term devices (`merkur synth
//! --target xc2c*`; issue 21). In the Verilog the layout is the
//! `localparam write_shifts` (1: `WriteShifts`).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_valid` | in | 1 | clock | a bit to send (at most one per clock) |
//! | `i_code` | in | 1 | clock | its code bit: 1 = the line toggles (NRZI) |
//! | `i_phase` | in | 2 | clock | its receive sample within the clock ([`crate::line::cdr`]'s `o_phase`) |
//! | `o_line` | out | 2 | clock | OUTPUT line, DDR pair (bit 0 first) |
//! | `o_slip` | out | 1 | clock | pulse: underflow or overflow, the buffer restarted |
//!
//! Latency: a bit is sent [`TARGET`] receive samples (2.5 bit times,
//! ± [`BAND`]) after the clock of its receive sample, plus the output
//! register.
//!
//! ```text
//! i_valid   _/‾\___/‾\___/‾\___/‾\___/‾\___     (receive timing: jitters)
//! rem         3 1 3 1 3 1 3 1 3 1 3 1 3 1        (half clocks to the next send)
//! o_line    ==X=======X=======X=======X====      (own clock: 4 half clocks per bit)
//! correction: one bit of 3 or 5 half clocks, at most every GAP bits
//! ```

use rust_hdl::prelude::*;

/// Target wait of a bit in the buffer, receive samples (quarter clocks).
pub const TARGET: u64 = 20;
/// After an underflow (which itself sends no edge) the line carries no
/// edge until this many bit times after the last edge sent: more than a
/// downstream receiver needs to mute (8, [`crate::line::cdr::MUTE_SAMPLES`]) and
/// then end its packet (2 more; a forwarder 3, [`crate::node::fwd::DEAD_CLOCKS`]),
/// with 5 bit times of margin. It ends early enough that a forwarder whose
/// input died (its output's last edge ≤ 10 bit times after its input's)
/// sends idles before its own loss of signal wraps it (32 bit times after
/// its input's last edge, [`crate::line::cdr::LOS_SAMPLES`]; protocol §9).
pub const QUIET_BITS: u64 = 16;
/// Dead band around [`TARGET`], receive samples.
pub const BAND: u64 = 4;
/// Writes in a row outside the band before a correction.
pub const VOTES: u64 = 4;
/// Sent bits between two corrections, at least.
pub const GAP: u64 = 8;
/// Bits the buffer holds.
pub const DEPTH: u64 = 8;

// The phase decision (`late`, `early` in `update`) is written out for a
// band of 16 … 24 samples and 8 samples per buffered bit.
const _: () = assert!(TARGET + BAND == 24 && TARGET - BAND == 16);
// The overflow decision (`over`) is written out for a buffer of 8 bits.
const _: () = assert!(DEPTH == 8);

/// Where the buffer keeps its bits (see the module doc): the same
/// behaviour, a different cost per device family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Layout {
    /// The oldest bit in bit 0: a send shifts, a write is decoded by the
    /// count (LUT devices: the bit to send is a flip-flop).
    #[default]
    SendShifts,
    /// The newest bit in bit 7: a write shifts, a send reads bit 8 − count
    /// (product-term devices: each buffer bit takes its neighbour or
    /// holds).
    WriteShifts,
}

/// Elastic output buffer with its own bit timing.
#[derive(LogicBlock)]
pub struct Retime {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// A bit to send.
    pub i_valid: Signal<In, Bit>,
    /// Its code bit (1: the line toggles at the bit's start).
    pub i_code: Signal<In, Bit>,
    /// Its receive sample within the clock.
    pub i_phase: Signal<In, Bits<2>>,
    /// Output line (DDR pair).
    pub o_line: Signal<Out, Bits<2>>,
    /// The buffer under- or overflowed.
    pub o_slip: Signal<Out, Bit>,
    quiet_bits: Constant<Bits<5>>,
    /// [`Layout::WriteShifts`].
    write_shifts: Constant<Bit>,
    votes: Constant<Bits<3>>,
    gap_min: Constant<Bits<4>>,
    sr: DFF<Bits<8>>,
    cnt: DFF<Bits<4>>,
    rem: DFF<Bits<3>>,
    lvl: DFF<Bit>,
    run: DFF<Bit>,
    dark: DFF<Bit>,
    since: DFF<Bits<5>>,
    hi: DFF<Bits<3>>,
    lo: DFF<Bits<3>>,
    gap: DFF<Bits<4>>,
    pair: DFF<Bits<2>>,
    slip: DFF<Bit>,
    send0: Signal<Local, Bit>,
    send1: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    under: Signal<Local, Bit>,
    oldest: Signal<Local, Bit>,
    // WriteShifts: the index of the bit to send (8 − count) and the
    // buffer shifted down by it.
    rpos: Signal<Local, Bits<3>>,
    rsel: Signal<Local, Bits<8>>,
    sr_shift: Signal<Local, Bits<8>>,
    wpos: Signal<Local, Bits<3>>,
    wmask: Signal<Local, Bits<8>>,
    one: Constant<Bits<8>>,
    new_lvl: Signal<Local, Bit>,
    len: Signal<Local, Bits<3>>,
    cnt_next: Signal<Local, Bits<4>>,
    rem_next: Signal<Local, Bits<3>>,
    t_neg: Signal<Local, Bit>,
    t_pos: Signal<Local, Bit>,
    t_lt8: Signal<Local, Bit>,
    t_gt8: Signal<Local, Bit>,
    c_is0: Signal<Local, Bit>,
    c_is1: Signal<Local, Bit>,
    c_is2: Signal<Local, Bit>,
    c_is3: Signal<Local, Bit>,
    c_ge4: Signal<Local, Bit>,
    late: Signal<Local, Bit>,
    early: Signal<Local, Bit>,
    start2: Signal<Local, Bit>,
    over: Signal<Local, Bit>,
}

impl Default for Retime {
    fn default() -> Self {
        Self::new(Layout::default())
    }
}

impl Retime {
    /// A buffer with its bits in `layout`.
    pub fn new(layout: Layout) -> Self {
        Self {
            clock: Default::default(),
            i_valid: Default::default(),
            i_code: Default::default(),
            i_phase: Default::default(),
            o_line: Default::default(),
            o_slip: Default::default(),
            quiet_bits: Constant::new((QUIET_BITS - 2).to_bits()),
            write_shifts: Constant::new(layout == Layout::WriteShifts),
            votes: Constant::new(VOTES.to_bits()),
            gap_min: Constant::new(GAP.to_bits()),
            sr: Default::default(),
            cnt: Default::default(),
            rem: Default::default(),
            lvl: Default::default(),
            run: Default::default(),
            dark: Default::default(),
            since: Default::default(),
            hi: Default::default(),
            lo: Default::default(),
            gap: Default::default(),
            pair: Default::default(),
            slip: Default::default(),
            send0: Default::default(),
            send1: Default::default(),
            take: Default::default(),
            under: Default::default(),
            oldest: Default::default(),
            rpos: Default::default(),
            rsel: Default::default(),
            sr_shift: Default::default(),
            wpos: Default::default(),
            wmask: Default::default(),
            one: Constant::new(1.into()),
            new_lvl: Default::default(),
            len: Default::default(),
            cnt_next: Default::default(),
            rem_next: Default::default(),
            t_neg: Default::default(),
            t_pos: Default::default(),
            t_lt8: Default::default(),
            t_gt8: Default::default(),
            c_is0: Default::default(),
            c_is1: Default::default(),
            c_is2: Default::default(),
            c_is3: Default::default(),
            c_ge4: Default::default(),
            late: Default::default(),
            early: Default::default(),
            start2: Default::default(),
            over: Default::default(),
        }
    }
}

impl Logic for Retime {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, sr, cnt, rem, lvl, run, dark, since, hi, lo, gap, pair, slip);
        // A bit boundary in the first or the second half of this clock (the
        // bit grid runs always; without buffered bits it sends idles).
        self.send0.next = self.rem.q.val() == 0;
        self.send1.next = self.rem.q.val() == 1;
        self.take.next =
            (self.send0.val() | self.send1.val()) & self.run.q.val() & (self.cnt.q.val() != 0);
        // The buffer is a FIFO. SendShifts: the oldest bit in bit 0 (a
        // send shifts it out, a write goes in behind the unsent bits), so
        // the bit to send is one flip-flop, not a mux by the count (issue
        // 20). WriteShifts: the newest bit in bit 7, the oldest unsent one
        // cnt − 1 below it (issue 21).
        self.oldest.next = self.sr.q.val().get_bit(0);
        self.rpos.next = (!self.cnt.q.val().get_bits::<3>(0)) + 1;
        self.rsel.next = self.sr.q.val() >> self.rpos.val();
        if self.write_shifts.val() {
            self.oldest.next = (self.rsel.val() & 1) != 0;
        }
        // Underflow: a bit boundary while running with nothing buffered.
        self.under.next =
            (self.send0.val() | self.send1.val()) & self.run.q.val() & (self.cnt.q.val() == 0);
        self.new_lvl.next = self.lvl.q.val();
        if (self.send0.val() | self.send1.val()) & !self.dark.q.val() & !self.under.val() {
            // An idle bit (NRZI 1: the level toggles); not at an underflow,
            // which starts the dark time.
            self.new_lvl.next = !self.lvl.q.val();
        }
        if (self.send0.val() | self.send1.val())
            & self.dark.q.val()
            & (self.since.q.val() >= self.quiet_bits.val())
        {
            // The bit starting at the next boundary is QUIET_BITS after the
            // last edge: the dark time is over.
            self.dark.d.next = false;
        }
        if self.take.val() {
            // Code bits, not levels, are buffered, so the line stays
            // continuous when sending switches between idles and data.
            self.new_lvl.next = self.lvl.q.val() ^ self.oldest.val();
        }
        // The DDR pair: the new level from the half where its bit starts.
        self.pair.d.next = 0.into();
        if self.lvl.q.val() {
            self.pair.d.next = 3.into();
        }
        if self.send0.val() & self.new_lvl.val() {
            self.pair.d.next = 3.into();
        }
        if self.send0.val() & !self.new_lvl.val() {
            self.pair.d.next = 0.into();
        }
        if self.send1.val() & (self.new_lvl.val() != self.lvl.q.val()) {
            // Bit 0 keeps the old level, bit 1 shows the new one.
            self.pair.d.next = 1.into();
            if self.new_lvl.val() {
                self.pair.d.next = 2.into();
            }
        }
        self.lvl.d.next = self.new_lvl.val();
        // Bit boundaries since the last edge sent (saturating).
        if self.send0.val() | self.send1.val() {
            if self.new_lvl.val() != self.lvl.q.val() {
                self.since.d.next = 0.into();
            } else if self.since.q.val() != 31 {
                self.since.d.next = self.since.q.val() + 1;
            }
        }
        // The length of the bit starting now: 4 half clocks, or a correction.
        self.len.next = 4.into();
        if self.run.q.val() & (self.gap.q.val() >= self.gap_min.val()) {
            if self.hi.q.val() >= self.votes.val() {
                self.len.next = 3.into();
            }
            if self.lo.q.val() >= self.votes.val() {
                self.len.next = 5.into();
            }
        }
        // (rem − 2, len − 2 and len − 1 written without subtractors: this
        // is on the core clock's critical path, issue 20.)
        self.rem_next.next = self.rem.q.val() ^ 2;
        if !self.rem.q.val().get_bit(1) {
            self.rem_next.next = self.rem.q.val() ^ 6;
        }
        if self.send0.val() | self.send1.val() {
            if self.gap.q.val() != 15 {
                self.gap.d.next = self.gap.q.val() + 1;
            }
            if self.len.val() != 4 {
                self.gap.d.next = 0.into();
                self.hi.d.next = 0.into();
                self.lo.d.next = 0.into();
            }
        }
        if self.send0.val() {
            self.rem_next.next = 2.into();
            if self.len.val() == 3 {
                self.rem_next.next = 1.into();
            }
            if self.len.val() == 5 {
                self.rem_next.next = 3.into();
            }
        }
        if self.send1.val() {
            self.rem_next.next = 3.into();
            if self.len.val() == 3 {
                self.rem_next.next = 2.into();
            }
            if self.len.val() == 5 {
                self.rem_next.next = 4.into();
            }
        }
        // Buffer: a send shifts the oldest bit out, a write goes in behind
        // the unsent ones; count what is unsent.
        self.sr_shift.next = self.sr.q.val();
        if self.take.val() {
            self.sr_shift.next = self.sr.q.val() >> 1;
        }
        self.sr.d.next = self.sr_shift.val();
        // Behind the cnt unsent bits (cnt − 1 after a send now).
        self.wpos.next = self.cnt.q.val().get_bits::<3>(0);
        if self.take.val() {
            self.wpos.next = self.cnt.q.val().get_bits::<3>(0) - 1;
        }
        self.wmask.next = self.one.val() << self.wpos.val();
        self.cnt_next.next = self.cnt.q.val();
        if self.take.val() & !self.i_valid.val() {
            self.cnt_next.next = self.cnt.q.val() - 1;
        }
        if self.i_valid.val() {
            self.sr.d.next = self.sr_shift.val() & !self.wmask.val();
            if self.i_code.val() {
                self.sr.d.next = self.sr_shift.val() | self.wmask.val();
            }
            if !self.take.val() {
                self.cnt_next.next = self.cnt.q.val() + 1;
            }
        }
        if self.write_shifts.val() {
            // Every write shifts the buffer down and puts its bit on top;
            // a send leaves it.
            self.sr.d.next = self.sr.q.val();
            if self.i_valid.val() {
                self.sr.d.next = self.sr.q.val() >> 1;
                if self.i_code.val() {
                    self.sr.d.next = (self.sr.q.val() >> 1) | 128;
                }
            }
        }
        // The wait of the bit written now, in receive samples, against the
        // band: lag = 8·cnt_next + 2·rem_next − i_phase (modulo 256, as an
        // 8-bit sum would give it) above TARGET + BAND (`late`) or below
        // TARGET − BAND (`early`). Decided per buffered-bit count without
        // an adder (issue 20: this is on the core clock's critical path);
        // with t = 2·rem_next − i_phase (−3 … 14): 0 bits: late when t < 0
        // (the sum wraps), else early; 1: early when t < 8; 2: late when
        // t > 8, early when t < 0; 3: late when t > 0; 4 or more: late.
        self.t_neg.next = ((self.rem_next.val() == 0) & (self.i_phase.val() != 0))
            | ((self.rem_next.val() == 1) & (self.i_phase.val() == 3));
        self.t_pos.next = (self.rem_next.val() >= 2)
            | ((self.rem_next.val() == 1) & !self.i_phase.val().get_bit(1));
        self.t_lt8.next = (self.rem_next.val() <= 3)
            | ((self.rem_next.val() == 4) & (self.i_phase.val() != 0))
            | ((self.rem_next.val() == 5) & (self.i_phase.val() == 3));
        self.t_gt8.next = (self.rem_next.val() >= 6)
            | ((self.rem_next.val() == 5) & !self.i_phase.val().get_bit(1));
        // (Only read when a bit is written: then cnt_next is cnt when a bit
        // is also sent, else cnt + 1, which wraps to 0 only from 15, a
        // count the buffer never holds.)
        self.c_is0.next = self.cnt.q.val() == 15;
        self.c_is1.next = self.cnt.q.val() == 0;
        self.c_is2.next = self.cnt.q.val() == 1;
        self.c_is3.next = self.cnt.q.val() == 2;
        self.c_ge4.next = (self.cnt.q.val() >= 3) & (self.cnt.q.val() != 15);
        if self.take.val() {
            self.c_is1.next = self.cnt.q.val() == 1;
            self.c_is2.next = self.cnt.q.val() == 2;
            self.c_is3.next = self.cnt.q.val() == 3;
            self.c_ge4.next = self.cnt.q.val() >= 4;
            self.c_is0.next = false;
        }
        self.late.next = self.c_ge4.val()
            | (self.c_is0.val() & self.t_neg.val())
            | (self.c_is2.val() & self.t_gt8.val())
            | (self.c_is3.val() & self.t_pos.val());
        self.early.next = (self.c_is0.val() & !self.t_neg.val())
            | (self.c_is1.val() & self.t_lt8.val())
            | (self.c_is2.val() & self.t_neg.val());
        if self.run.q.val() & self.i_valid.val() {
            if self.late.val() {
                if self.hi.q.val() != 7 {
                    self.hi.d.next = self.hi.q.val() + 1;
                }
                self.lo.d.next = 0.into();
            } else if self.early.val() {
                if self.lo.q.val() != 7 {
                    self.lo.d.next = self.lo.q.val() + 1;
                }
                self.hi.d.next = 0.into();
            } else {
                self.hi.d.next = 0.into();
                self.lo.d.next = 0.into();
            }
        }
        self.rem.d.next = self.rem_next.val();
        self.cnt.d.next = self.cnt_next.val();
        self.slip.d.next = false;
        if self.dark.q.val() {
            // Dark after an underflow: what arrives is not sent.
            self.cnt_next.next = 0.into();
        }
        // (The start and the overflow are read from the count itself, not
        // from `cnt_next`'s arithmetic: this is the slave's critical path,
        // issue 20. Not running nothing is sent, so the count after a write
        // is 2 when it was 1. The count after this clock is cnt + 1, cnt − 1
        // or cnt (4 bits, wrapping), 0 in the dark; writes in the dark still
        // count, so cnt can exceed DEPTH there.)
        self.start2.next =
            !self.run.q.val() & self.i_valid.val() & !self.dark.q.val() & (self.cnt.q.val() == 1);
        self.over.next = !self.dark.q.val()
            & ((self.i_valid.val()
                & !self.take.val()
                & (self.cnt.q.val() >= 8)
                & (self.cnt.q.val() != 15))
                | (self.take.val() & !self.i_valid.val() & (self.cnt.q.val() >= 10))
                | ((self.i_valid.val() == self.take.val()) & (self.cnt.q.val() >= 9)));
        if self.start2.val() {
            // The second bit: send from the next bit boundary on (the grid
            // keeps its phase, so the line has no short bit; the wait is
            // 13–22, and the band pulls it to the target).
            self.run.d.next = true;
            self.hi.d.next = 0.into();
            self.lo.d.next = 0.into();
            self.gap.d.next = 0.into();
        }
        if self.under.val() | self.over.val() {
            // Underflow or overflow: start again with the next bit.
            self.slip.d.next = true;
            self.run.d.next = false;
            self.cnt.d.next = 0.into();
        }
        if self.under.val() {
            // Underflow (the input stopped): the line stays dark until
            // QUIET_BITS after its last edge, so that downstream receivers
            // mute and drop a word that was cut short (its last bits would
            // otherwise be completed by idles) and downstream forwarders
            // end the packet, then idles again.
            self.dark.d.next = true;
        }
        self.o_line.next = self.pair.q.val();
        self.o_slip.next = self.slip.q.val();
    }
}
