//! # cdr — clock and data recovery by oversampling (protocol §9)
//!
//! Purpose: recovers line bits from an asynchronous NRZI line sampled 4 times
//! per bit time. The core clock runs at 2× the line rate and takes 2 samples
//! per clock (a DDR input register in hardware: `i_samples[0]` is the sample at
//! the rising edge, `i_samples[1]` half a clock later). Every transition
//! restarts a sample counter; the bit is taken 2 samples after the last
//! transition and every 4 samples after that, so the sampling point follows
//! the incoming stream: frequency offsets between the sender's and the
//! receiver's clocks (±1000 ppm each) and edge jitter are absorbed without
//! slipping a bit. Tested (`testbenches/tests/cdr.rs`): 10^6 bits at ±2000 ppm
//! relative offset with every bit boundary moved by up to ±0.45 sample;
//! ±0.7 sample slips. So a node's transmitter must place its edges with
//! half-clock (one-sample) resolution: a DDR output register, not a plain
//! flip-flop, in the node top. At most one bit is recovered per clock;
//! the recovered bit rate is the sender's, so a node that transmits one bit
//! per recovered bit retransmits on the recovered timing.
//!
//! Loss of signal: no transition for 64 samples (16 bit times) raises
//! `o_los` until the next transition.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_samples` | in | 2 | clock | line samples, bit 0 first in time |
//! | `o_valid` | out | 1 | clock | `o_bit` holds a recovered bit |
//! | `o_bit` | out | 1 | clock | recovered line level (NRZI, not yet decoded) |
//! | `o_los` | out | 1 | clock | loss of signal (no edge for 16 bit times) |
//! | `o_phase` | out | 1 | clock | the bit's centre was sample 0 or 1 of its clock |
//!
//! Latency: `o_valid`/`o_bit` are registered: a bit appears one clock after
//! the clock whose samples contained its centre (2 samples after its edge).
//!
//! ```text
//! samples   0 0 0 0 | 1 1 1 1 | 1 1 1 1 | 0 0 0 0     (4 per bit, 2 per clock)
//! count     . . 2 .   0 1 2 3   0 1 2 3   0 1 2 3      (restarts at each edge)
//! take          ^         ^         ^         ^        (count == 2)
//! o_valid   ____/‾\_____/‾\_______/‾\_______/‾\__     (one clock later)
//! o_bit          0        1         1         0
//! ```

use rust_hdl::prelude::*;

/// Samples without a transition before `o_los` rises (16 bit times).
pub const LOS_SAMPLES: u64 = 64;

/// Oversampling clock and data recovery.
#[derive(LogicBlock)]
pub struct Cdr {
    /// Core clock (2× line rate).
    pub clock: Signal<In, Clock>,
    /// Two line samples per clock, bit 0 earlier.
    pub i_samples: Signal<In, Bits<2>>,
    /// A recovered bit is valid.
    pub o_valid: Signal<Out, Bit>,
    /// Recovered line level.
    pub o_bit: Signal<Out, Bit>,
    /// Loss of signal.
    pub o_los: Signal<Out, Bit>,
    /// Which sample of its clock was the bit's centre (0 first, 1 second):
    /// lets a transmitter repeat the edge with half-clock resolution.
    pub o_phase: Signal<Out, Bit>,
    quiet_last: Constant<Bits<7>>,
    last: DFF<Bit>,
    phase: DFF<Bit>,
    count: DFF<Bits<2>>,
    quiet: DFF<Bits<7>>,
    rx_valid: DFF<Bit>,
    rx_bit: DFF<Bit>,
    los_flag: DFF<Bit>,
    edge_a: Signal<Local, Bit>,
    edge_b: Signal<Local, Bit>,
    count_a: Signal<Local, Bits<2>>,
    count_b: Signal<Local, Bits<2>>,
}

impl Default for Cdr {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_samples: Default::default(),
            o_valid: Default::default(),
            o_bit: Default::default(),
            o_los: Default::default(),
            o_phase: Default::default(),
            // Two samples per clock: LOS_SAMPLES / 2 clocks, counted from 0.
            quiet_last: Constant::new((LOS_SAMPLES / 2 - 1).to_bits()),
            last: Default::default(),
            phase: Default::default(),
            count: Default::default(),
            quiet: Default::default(),
            rx_valid: Default::default(),
            rx_bit: Default::default(),
            los_flag: Default::default(),
            edge_a: Default::default(),
            edge_b: Default::default(),
            count_a: Default::default(),
            count_b: Default::default(),
        }
    }
}

impl Logic for Cdr {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last, phase, count, quiet, rx_valid, rx_bit, los_flag);
        // First sample of this clock.
        self.edge_a.next = self.i_samples.val().get_bit(0) ^ self.last.q.val();
        self.count_a.next = self.count.q.val() + 1;
        if self.edge_a.val() {
            self.count_a.next = 0.into();
        }
        // Second sample.
        self.edge_b.next = self.i_samples.val().get_bit(1) ^ self.i_samples.val().get_bit(0);
        self.count_b.next = self.count_a.val() + 1;
        if self.edge_b.val() {
            self.count_b.next = 0.into();
        }
        self.last.d.next = self.i_samples.val().get_bit(1);
        self.count.d.next = self.count_b.val();
        // Take the sample 2 after an edge, then every 4.
        self.rx_valid.d.next = false;
        if self.count_a.val() == 2 {
            self.rx_valid.d.next = true;
            self.rx_bit.d.next = self.i_samples.val().get_bit(0);
            self.phase.d.next = false;
        }
        if self.count_b.val() == 2 {
            self.rx_valid.d.next = true;
            self.rx_bit.d.next = self.i_samples.val().get_bit(1);
            self.phase.d.next = true;
        }
        // Loss of signal: 64 samples (32 clocks) without an edge.
        if self.edge_a.val() | self.edge_b.val() {
            self.quiet.d.next = 0.into();
            self.los_flag.d.next = false;
        } else if self.quiet.q.val() == self.quiet_last.val() {
            self.los_flag.d.next = true;
        } else {
            self.quiet.d.next = self.quiet.q.val() + 1;
        }
        self.o_valid.next = self.rx_valid.q.val();
        self.o_bit.next = self.rx_bit.q.val();
        self.o_los.next = self.los_flag.q.val();
        self.o_phase.next = self.phase.q.val();
    }
}
