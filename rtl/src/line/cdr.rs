//! # cdr — clock and data recovery by oversampling (protocol §9)
//!
//! Purpose: recovers line bits from an asynchronous NRZI line sampled
//! [`SAMPLES_PER_BIT`] = 8 times per bit time. The core clock runs at 2× the
//! line rate and takes [`SAMPLES_PER_CLOCK`] = 4 samples per clock (quadrature
//! DDR capture in hardware: both edges of the core clock and of its 90°
//! copy; `i_samples[0]` is the earliest). Every transition restarts a sample
//! counter; the bit is taken 4 samples after the last transition (the first
//! sample showing the new level) and every 8 samples after that, so the
//! sampling point follows the incoming stream: clock offsets between the
//! sender and the receiver (±1000 ppm each) and edge jitter are absorbed
//! without slipping a bit. An edge interval of k bits is read as k bits when
//! it measures 8k − 3 … 8k + 4 samples: the sender's retimer
//! ([`crate::line::retime`]) moves an edge by at most 2 samples (one output half
//! clock), which leaves a sample of margin. Tested
//! (`sim/tests/cdr.rs`): 10^6 bits at ±2000 ppm relative offset with
//! every bit boundary moved by up to ±1.4 samples; ±2.2 samples is shown to
//! fail. At most one bit is recovered per clock, with its level (`o_bit`)
//! and its code (`o_code`, NRZI-decoded: the level changed), so the
//! framer, the forwarder and the repeaters read one decode, not one each.
//!
//! A dead line: after [`MUTE_SAMPLES`] (8 bit times) without a transition no
//! more bits are taken, so a break passes on a cut-short packet, not a run
//! of zeros. Legal streams toggle at least every 4 bit times, but one
//! line-bit error inverts two adjacent code bits and can leave up to 6 zero
//! code bits inside a packet (an edge interval of 7 bit times; tested,
//! `sim/tests/cdr.rs`): that must cost a word, not mute the receiver
//! for the rest of the frame (protocol §5). An interval of up to 8 bit
//! times is read whole. Loss of signal: no transition for [`LOS_SAMPLES`] =
//! 256 samples (32 bit times) raises `o_los` until the next transition.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_samples` | in | 4 | clock | line samples, bit 0 first in time |
//! | `o_valid` | out | 1 | clock | `o_bit` holds a recovered bit |
//! | `o_bit` | out | 1 | clock | recovered line level (NRZI, not yet decoded) |
//! | `o_code` | out | 1 | clock | the bit decoded: 1 when its level differs from the previous recovered bit's (NRZI 1) |
//! | `o_los` | out | 1 | clock | loss of signal (no edge for 32 bit times) |
//! | `o_phase` | out | 2 | clock | which sample of its clock the bit was taken from (0 first) |
//!
//! Latency: `o_valid`/`o_bit`/`o_code`/`o_phase` are registered: a bit appears one
//! clock after the clock whose samples contained its centre (4 samples after
//! its edge), so 0.5–1 bit time after the edge.
//!
//! ```text
//! samples  0 0 0 0 0 0 0 0 | 1 1 1 1 1 1 1 1 | 1 1 1 1 1 1 1 1 | 0 0 ...   (8 per bit, 4 per clock)
//! count    . . . . 4 . . .   0 1 2 3 4 5 6 7   0 1 2 3 4 5 6 7   0         (restarts at each edge)
//! take             ^                 ^                 ^                   (count == 4)
//! o_valid  ________/‾‾\_____________/‾‾\_____________/‾‾\____              (one clock later)
//! o_bit             0                 1                 1
//! ```

use rust_hdl::prelude::*;

/// Line samples per bit time.
pub const SAMPLES_PER_BIT: usize = 8;
/// Line samples per core clock (the width of `i_samples`).
pub const SAMPLES_PER_CLOCK: usize = 4;
/// Samples without a transition after which no more bits are taken (8 bit
/// times: legal streams toggle at least every 4, a single line-bit error
/// leaves an interval of at most 7), so a line that went dark does not
/// deliver a long run of zeros.
pub const MUTE_SAMPLES: u64 = 8 * SAMPLES_PER_BIT as u64;
/// Samples without a transition before `o_los` rises (32 bit times: more
/// than the longest dark time of a live line, a switch's dark time right
/// after a stopped input's, [`crate::node::sw_dark`], [`crate::line::retime::QUIET_BITS`];
/// protocol §9).
pub const LOS_SAMPLES: u64 = 32 * SAMPLES_PER_BIT as u64;

/// Oversampling clock and data recovery.
#[derive(LogicBlock)]
pub struct Cdr {
    /// Core clock (2× line rate).
    pub clock: Signal<In, Clock>,
    /// Four line samples per clock, bit 0 earliest.
    pub i_samples: Signal<In, Bits<4>>,
    /// A recovered bit is valid.
    pub o_valid: Signal<Out, Bit>,
    /// Recovered line level.
    pub o_bit: Signal<Out, Bit>,
    /// The recovered bit's code (its level differs from the previous
    /// bit's): the NRZI decode in the register beside the level, so that
    /// no reader repeats it in front of its own registers (issue 21: on a
    /// CoolRunner-II an XOR in front of a register doubles its product
    /// terms).
    pub o_code: Signal<Out, Bit>,
    /// Loss of signal.
    pub o_los: Signal<Out, Bit>,
    /// Which sample of its clock the bit was taken from (0 first): the
    /// bit's arrival time to a quarter clock, for a retimer's phase measure.
    pub o_phase: Signal<Out, Bits<2>>,
    quiet_last: Constant<Bits<6>>,
    /// The count one clock before muting (`MUTE_SAMPLES` / 4 − 1).
    mute_last: Constant<Bits<6>>,
    last: DFF<Bit>,
    phase: DFF<Bits<2>>,
    count: DFF<Bits<3>>,
    /// Clocks without an edge up to this one, from registers: `calm` says
    /// the clock before had no edge; without it the count is 0, with it
    /// the count is `quiet`, where 0 stands for 64 or more (then `o_los`
    /// is already raised: `los_flag`). Issue 21: the four samples' edge
    /// test is one register in front of the counter, not repeated in front
    /// of every counter bit, and the tests below are a bit or two (on a
    /// CoolRunner-II each counter bit is a T flip-flop of two product
    /// terms).
    quiet: DFF<Bits<6>>,
    calm: DFF<Bit>,
    /// The count is past `mute_last`: no bits are taken. Registered
    /// (from the next count), so the take reads one flip-flop.
    mute: DFF<Bit>,
    rx_valid: DFF<Bit>,
    rx_bit: DFF<Bit>,
    rx_code: DFF<Bit>,
    los_flag: DFF<Bit>,
    prior: Signal<Local, Bits<4>>,
    edges: Signal<Local, Bits<4>>,
    still: Signal<Local, Bit>,
    clean: Signal<Local, Bit>,
    take_at: Signal<Local, Bits<2>>,
    taken: Signal<Local, Bit>,
}

impl Default for Cdr {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_samples: Default::default(),
            o_valid: Default::default(),
            o_bit: Default::default(),
            o_code: Default::default(),
            o_los: Default::default(),
            o_phase: Default::default(),
            // LOS_SAMPLES / SAMPLES_PER_CLOCK clocks, counted from 0.
            quiet_last: Constant::new((LOS_SAMPLES / SAMPLES_PER_CLOCK as u64 - 1).to_bits()),
            mute_last: Constant::new((MUTE_SAMPLES / SAMPLES_PER_CLOCK as u64 - 1).to_bits()),
            last: Default::default(),
            phase: Default::default(),
            count: Default::default(),
            quiet: Default::default(),
            calm: Default::default(),
            mute: Default::default(),
            rx_valid: Default::default(),
            rx_bit: Default::default(),
            rx_code: Default::default(),
            los_flag: Default::default(),
            prior: Default::default(),
            edges: Default::default(),
            still: Default::default(),
            clean: Default::default(),
            take_at: Default::default(),
            taken: Default::default(),
        }
    }
}

impl Logic for Cdr {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, last, phase, count, quiet, calm, mute, rx_valid, rx_bit, rx_code, los_flag
        );
        // Each sample's predecessor, and where the level changed.
        self.prior.next = self.i_samples.val() << 1;
        if self.last.q.val() {
            self.prior.next = (self.i_samples.val() << 1) | 1;
        }
        self.edges.next = self.i_samples.val() ^ self.prior.val();
        // The sample counter through the clock's four samples: 0 on the
        // first sample of a new level, else one more than before (modulo
        // 8). Written without adders, so it maps to a few levels of LUTs
        // (issue 20): after the clock the counter is 3 − j when the last
        // edge of the clock is at sample j, and 4 more than before (bit 2
        // flipped) when the clock has no edge.
        self.count.d.next = self.count.q.val() ^ 4;
        if self.edges.val().get_bit(0) {
            self.count.d.next = 3.into();
        }
        if self.edges.val().get_bit(1) {
            self.count.d.next = 2.into();
        }
        if self.edges.val().get_bit(2) {
            self.count.d.next = 1.into();
        }
        if self.edges.val().get_bit(3) {
            self.count.d.next = 0.into();
        }
        self.last.d.next = self.i_samples.val().get_bit(3);
        // Take the sample at count 4 (the bit's centre). A sample after an
        // edge of this clock counts at most 3, so the take is at sample
        // k = 3 − count (count 0 … 3, the two low bits inverted), when no
        // edge comes before it: at most one per clock.
        // (A line without an edge for 8 bit times is dead, not a run of
        // zeros: legal streams toggle at least every 4, one line-bit error
        // leaves at most 7; no bits from it: `mute`.)
        self.clean.next = !self.edges.val().get_bit(0);
        if self.count.q.val().get_bits::<2>(0) == 2 {
            self.clean.next = !self.edges.val().get_bit(0) & !self.edges.val().get_bit(1);
        }
        if self.count.q.val().get_bits::<2>(0) == 1 {
            self.clean.next = !self.edges.val().get_bit(0)
                & !self.edges.val().get_bit(1)
                & !self.edges.val().get_bit(2);
        }
        if self.count.q.val().get_bits::<2>(0) == 0 {
            self.clean.next = !self.edges.val().any();
        }
        self.take_at.next = !self.count.q.val().get_bits::<2>(0);
        self.taken.next = self.i_samples.val().get_bit(self.take_at.val().index());
        self.rx_valid.d.next = false;
        if !self.count.q.val().get_bit(2) & self.clean.val() & !self.mute.q.val() {
            self.rx_valid.d.next = true;
            self.rx_bit.d.next = self.taken.val();
            self.rx_code.d.next = self.taken.val() ^ self.rx_bit.q.val();
            self.phase.d.next = self.take_at.val();
        }
        // Loss of signal: LOS_SAMPLES samples without an edge, i.e. the
        // count now at `quiet_last` (63, see `quiet`) or beyond, and no
        // edge in this clock. `quiet` takes what the count will be if
        // this clock has no edge: one more than now (1 when the count is
        // 0, without `calm`), and 0 for 64 or more (it stops there).
        self.still.next = !self.edges.val().any();
        self.calm.d.next = self.still.val();
        if !self.calm.q.val() {
            self.quiet.d.next = 1.into();
        } else if !self.los_flag.q.val() {
            self.quiet.d.next = self.quiet.q.val() + 1;
        }
        // Muted from the next clock on: no edge now, and the count now at
        // `mute_last` or more.
        self.mute.d.next = self.still.val()
            & self.calm.q.val()
            & (self.los_flag.q.val() | (self.quiet.q.val() >= self.mute_last.val()));
        if !self.still.val() {
            self.los_flag.d.next = false;
        } else if self.calm.q.val() & (self.quiet.q.val() == self.quiet_last.val()) {
            self.los_flag.d.next = true;
        }
        self.o_valid.next = self.rx_valid.q.val();
        self.o_bit.next = self.rx_bit.q.val();
        self.o_code.next = self.rx_code.q.val();
        self.o_los.next = self.los_flag.q.val();
        self.o_phase.next = self.phase.q.val();
    }
}
