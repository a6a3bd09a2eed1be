//! # tst_tx — link test (TST) packet generator (protocol §5, §9, §12)
//!
//! Purpose: what a wrapped node sends on BSS: a TST packet every 65 bit
//! times on its own clock: J K, H0 = `{10, 0, ACK, ADDR}`, H1 = NOT H0, one
//! idle group. ACK tells the partner that its TST is heard.
//!
//! Parameters: the word format ([`WordFormat`]); extended-alarm words have
//! a reason nibble N1 = 0 after the first group, and a TST takes 75 bit times.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_ack` | in | 1 | clock | ACK bit (partner's TST heard), taken at each packet start |
//! | `i_address` | in | 12 | static | node address |
//! | `i_restart` | in | 1 | clock | the output is switched to this generator: a dark lead-in of 12 bit times, an idle group, then TST |
//! | `o_line` | out | 2 | clock | line, DDR pair |
//!
//! Latency: free running; one bit every 2 clocks, a packet every 130 clocks.
//! After `i_restart` the line holds its level for 12 bit times, the dark
//! time of every switchbox change ([`crate::node::sw_dark`]: a receiver that was
//! inside a word of the stream this replaces mutes and drops it,
//! [`crate::line::monitor`], rather than completing it with TST bits), then one
//! idle group and the next TST.
//!
//! ```text
//! o_line   | J K | H0 (25) | H1 = ~H0 (25) | I | J K | ...      65 bit times each
//! ```

use crate::line::enc4b5b::Enc4b5b;
use crate::line::nrzi_tx::NrziTx;
use crate::line::word_rx::WordFormat;
use rust_hdl::prelude::*;

// The lead-in is the switchbox's dark time (a literal in `update`).
const _: () = assert!(crate::node::sw_dark::DARK_CLOCKS == 24);

/// TST generator.
#[derive(LogicBlock)]
pub struct TstTx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// ACK bit.
    pub i_ack: Signal<In, Bit>,
    /// Node address.
    pub i_address: Signal<In, Bits<12>>,
    /// Switched onto an output: dark lead-in, then TST.
    pub i_restart: Signal<In, Bit>,
    /// Line (DDR pair).
    pub o_line: Signal<Out, Bits<2>>,
    enc: Enc4b5b,
    tx: NrziTx,
    // Extended-alarm words; the group that starts H1; the idle group.
    ext: Constant<Bit>,
    h1_at: Constant<Bits<4>>,
    idle_at: Constant<Bits<4>>,
    half: DFF<Bit>,
    dark: DFF<Bits<5>>,
    gnum: DFF<Bits<4>>,
    ack: DFF<Bit>,
    word: Signal<Local, Bits<16>>,
    // The group within the word (0 first), and the data group it is (as
    // in `fwd`: 0..4, the last one 4; 7 the extended variant's N1).
    wg: Signal<Local, Bits<4>>,
    dg: Signal<Local, Bits<4>>,
    nib: Signal<Local, Bits<4>>,
    p_a: Signal<Local, Bit>,
    p_b: Signal<Local, Bit>,
    sym: Signal<Local, Bits<5>>,
}

impl Default for TstTx {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl TstTx {
    /// A TST generator for words in `format`.
    pub fn new(format: WordFormat) -> Self {
        let ext = format == WordFormat::ExtendedAlarm;
        Self {
            clock: Default::default(),
            i_ack: Default::default(),
            i_address: Default::default(),
            i_restart: Default::default(),
            o_line: Default::default(),
            enc: Default::default(),
            tx: Default::default(),
            ext: Constant::new(ext),
            h1_at: Constant::new(if ext { 8u64 } else { 7 }.to_bits()),
            idle_at: Constant::new(if ext { 14u64 } else { 12 }.to_bits()),
            half: Default::default(),
            dark: Default::default(),
            gnum: Default::default(),
            ack: Default::default(),
            word: Default::default(),
            wg: Default::default(),
            dg: Default::default(),
            nib: Default::default(),
            p_a: Default::default(),
            p_b: Default::default(),
            sym: Default::default(),
        }
    }
}

impl Logic for TstTx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, half, gnum, ack, dark);
        self.tx.clock.next = self.clock.val();
        self.half.d.next = !self.half.q.val();
        self.tx.i_bit_en.next = self.half.q.val() & (self.dark.q.val() == 0);
        if self.dark.q.val() != 0 {
            self.dark.d.next = self.dark.q.val() - 1;
        }
        // H0 = {10, 0, ACK, ADDR}; H1 = NOT H0.
        self.word.next = bit_cast::<16, 12>(self.i_address.val()) | 0x8000;
        // ACK is taken once per packet, so H0 and H1 always agree.
        if self.ack.q.val() {
            self.word.next = self.word.val() | 0x1000;
        }
        self.wg.next = self.gnum.q.val() - 2;
        if self.gnum.q.val() >= self.h1_at.val() {
            self.word.next = !self.word.val();
            self.wg.next = self.gnum.q.val() - self.h1_at.val();
        }
        self.dg.next = self.wg.val();
        if self.ext.val() & (self.wg.val() != 0) {
            self.dg.next = self.wg.val() - 1;
            if self.wg.val() == 1 {
                self.dg.next = 7.into();
            }
        }
        self.p_a.next = !(self.word.val().get_bit(5)
            ^ self.word.val().get_bit(4)
            ^ self.word.val().get_bit(9)
            ^ self.word.val().get_bit(8)
            ^ self.word.val().get_bit(13)
            ^ self.word.val().get_bit(12)
            ^ self.word.val().get_bit(15));
        self.p_b.next = !(self.word.val().get_bit(1)
            ^ self.word.val().get_bit(0)
            ^ self.word.val().get_bit(4)
            ^ self.word.val().get_bit(3)
            ^ self.word.val().get_bit(2)
            ^ self.word.val().get_bit(8)
            ^ self.word.val().get_bit(7)
            ^ self.word.val().get_bit(6)
            ^ self.word.val().get_bit(12)
            ^ self.word.val().get_bit(11)
            ^ self.word.val().get_bit(10)
            ^ self.word.val().get_bit(15)
            ^ self.word.val().get_bit(14));
        // Data group g of the word: N0 = {0, 0, D1, D0}, [ext: N1 = 0],
        // D[5:2], D[9:6], D[13:10], {PA, D15, D14, PB}.
        self.nib.next = self.word.val().get_bits::<4>(0) & 3;
        if self.dg.val() == 7 {
            self.nib.next = 0.into();
        }
        if self.dg.val() == 1 {
            self.nib.next = self.word.val().get_bits::<4>(2);
        }
        if self.dg.val() == 2 {
            self.nib.next = self.word.val().get_bits::<4>(6);
        }
        if self.dg.val() == 3 {
            self.nib.next = self.word.val().get_bits::<4>(10);
        }
        if self.dg.val() == 4 {
            self.nib.next = (self.word.val().get_bits::<4>(12) >> 1) & 6;
            if self.p_a.val() {
                self.nib.next = self.nib.val() | 8;
            }
            if self.p_b.val() {
                self.nib.next = self.nib.val() | 1;
            }
        }
        self.sym.next = 0.into();
        if self.nib.val().get_bit(0) {
            self.sym.next = self.sym.val() | 1;
        }
        if self.nib.val().get_bit(1) {
            self.sym.next = self.sym.val() | 2;
        }
        if self.nib.val().get_bit(2) {
            self.sym.next = self.sym.val() | 4;
        }
        if self.nib.val().get_bit(3) {
            self.sym.next = self.sym.val() | 8;
        }
        if self.gnum.q.val() == 0 {
            self.sym.next = 16.into(); // SYM_J
        }
        if self.gnum.q.val() == 1 {
            self.sym.next = 17.into(); // SYM_K
        }
        if self.gnum.q.val() == self.idle_at.val() {
            self.sym.next = 18.into(); // SYM_I
        }
        self.enc.i_sym.next = self.sym.val();
        self.tx.i_code.next = self.enc.o_code.val();
        if self.tx.o_take.val() {
            self.gnum.d.next = self.gnum.q.val() + 1;
            if self.gnum.q.val() == self.idle_at.val() {
                self.gnum.d.next = 0.into();
                self.ack.d.next = self.i_ack.val();
            }
        }
        if self.i_restart.val() {
            // crate::node::sw_dark::DARK_CLOCKS (checked at the top of the file).
            self.dark.d.next = 24.into();
            self.gnum.d.next = self.idle_at.val();
        }
        self.o_line.next = 0.into();
        if self.tx.o_line.val() {
            self.o_line.next = 3.into();
        }
    }
}
