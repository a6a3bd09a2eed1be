//! # framer_rx — start-delimiter (CS) detector, group aligner (protocol §2, §3)
//!
//! Purpose: turns recovered code bits (NRZI-decoded by [`crate::line::cdr`])
//! into code groups. While hunting it
//! compares the last 10 code bits with J K at every bit position; on a match
//! it pulses `o_start` and from then on emits one 5-bit group every 5 code
//! bits, until the word layer says the packet has ended (`i_end`: after the
//! last slot, after a TST/SEC packet's two words, on a bad header, on loss of
//! signal). The end is not taken from the line: one flipped line bit can turn
//! two data groups into idles, and that must cost one word, not the frame.
//! J K inside a packet is not searched for, so data can never re-align a
//! packet (and §3 shows data cannot imitate J K anyway).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_valid` | in | 1 | clock | `i_code` holds a recovered bit (from [`crate::line::cdr`]) |
//! | `i_code` | in | 1 | clock | its code bit (1: the line level changed) |
//! | `i_end` | in | 1 | clock | leave the packet, hunt for J K again |
//! | `o_start` | out | 1 | clock | J K found; the next group is the packet's first |
//! | `o_gvalid` | out | 1 | clock | `o_group` holds a group of the packet |
//! | `o_group` | out | 5 | clock | code group, bit 4 first on the line |
//! | `o_idle` | out | 1 | clock | `o_group` is the idle group 11111 (decided with it, so the word layer's packet-end check starts from a flip-flop) |
//! | `o_inpkt` | out | 1 | clock | aligned inside a packet |
//!
//! Latency: registered outputs, one clock after the `i_valid` that completes
//! the delimiter or group.
//!
//! ```text
//! code bits  1 1 1 1 1 | 1 1 0 0 0 | 1 0 0 0 1 | g g g g g | g g g g g | 1 1 1 1 1
//!                 I          J           K         group 0     group 1       I
//! o_start    ______________________/‾\_____________________________________________
//! o_gvalid   __________________________________/‾\_________/‾\_________/‾\________
//! i_end      ____________________________________________________/‾\__________
//! o_inpkt    ______________________/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\___________
//! ```

use rust_hdl::prelude::*;

/// J K as 10 code bits, J first (bit 9 first on the line).
pub const JK_BITS: u64 = 0b11000_10001;

/// J K hunter and group aligner.
#[derive(LogicBlock)]
pub struct FramerRx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// A recovered bit is valid.
    pub i_valid: Signal<In, Bit>,
    /// Its code bit (NRZI-decoded).
    pub i_code: Signal<In, Bit>,
    /// End of packet (from the word layer).
    pub i_end: Signal<In, Bit>,
    /// J K found.
    pub o_start: Signal<Out, Bit>,
    /// A group is valid.
    pub o_gvalid: Signal<Out, Bit>,
    /// The group.
    pub o_group: Signal<Out, Bits<5>>,
    /// The group is an idle (11111).
    pub o_idle: Signal<Out, Bit>,
    /// Inside a packet.
    pub o_inpkt: Signal<Out, Bit>,
    window: DFF<Bits<10>>,
    inpkt: DFF<Bit>,
    count: DFF<Bits<3>>,
    start: DFF<Bit>,
    gvalid: DFF<Bit>,
    group: DFF<Bits<5>>,
    idle: DFF<Bit>,
    shifted: Signal<Local, Bits<10>>,
    jk: Constant<Bits<10>>,
}

impl FramerRx {
    /// A framer (no parameters).
    pub fn new() -> Self {
        Self {
            clock: Default::default(),
            i_valid: Default::default(),
            i_code: Default::default(),
            i_end: Default::default(),
            o_start: Default::default(),
            o_gvalid: Default::default(),
            o_group: Default::default(),
            o_idle: Default::default(),
            o_inpkt: Default::default(),
            window: Default::default(),
            inpkt: Default::default(),
            count: Default::default(),
            start: Default::default(),
            gvalid: Default::default(),
            group: Default::default(),
            idle: Default::default(),
            shifted: Default::default(),
            jk: Constant::new(JK_BITS.to_bits()),
        }
    }
}

impl Default for FramerRx {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FramerRx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, window, inpkt, count, start, gvalid, group, idle);
        self.start.d.next = false;
        self.gvalid.d.next = false;
        self.shifted.next = self.window.q.val() << 1;
        if self.i_code.val() {
            self.shifted.next = (self.window.q.val() << 1) | 1;
        }
        if self.i_valid.val() {
            self.window.d.next = self.shifted.val();
            if self.inpkt.q.val() {
                if self.count.q.val() == 4 {
                    self.count.d.next = 0.into();
                    self.gvalid.d.next = true;
                    self.group.d.next = self.shifted.val().get_bits::<5>(0);
                    self.idle.d.next = self.shifted.val().get_bits::<5>(0) == 31;
                } else {
                    self.count.d.next = self.count.q.val() + 1;
                }
            } else if self.shifted.val() == self.jk.val() {
                self.inpkt.d.next = true;
                self.start.d.next = true;
                self.count.d.next = 0.into();
            }
        }
        if self.i_end.val() {
            self.inpkt.d.next = false;
        }
        self.o_start.next = self.start.q.val();
        self.o_gvalid.next = self.gvalid.q.val();
        self.o_group.next = self.group.q.val();
        self.o_idle.next = self.idle.q.val();
        self.o_inpkt.next = self.inpkt.q.val();
    }
}
