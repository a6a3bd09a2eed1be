//! # pkt_tx — packet generator of the special master (protocol §3–§5)
//!
//! Purpose: sends one packet per `i_start` on the node's own clock: J K, the
//! header words H0 and H1 (ALARM = 0; ALIVE = 0 but for H0's CLR flag,
//! `i_h0_alive`, protocol §5, §12), and — for a DATA frame
//! (`i_slots` = 1) — `i_slots_m1 + 1` slot words, each taken from
//! `i_word_*` when its turn comes (`o_take` is high in that clock; `o_slot`
//! is the slot whose word must be on `i_word_*`; it moves to the first slot
//! when a frame starts, 60 bit times before that slot is due). A VOID word (`i_word_void`) is five S
//! groups. Idles (all ones) between packets. Words are encoded as the
//! protocol's §4 (flags first, two odd parities last), 4B/5B, NRZI.
//!
//! Parameters: the word format ([`WordFormat`]); extended-alarm words
//! (protocol §6) have six groups, N1 = `i_word_rn` after the first (0 in
//! the headers), and a VOID is six S groups.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_start` | in | 1 | clock | start a packet at the next group boundary (ignored while busy) |
//! | `i_slots` | in | 1 | clock | the packet carries slot words (DATA) |
//! | `i_slots_m1` | in | 12 | static | slot words − 1 |
//! | `i_h0`, `i_h1` | in | 16 | clock | header words, taken when they are due |
//! | `i_h0_alive` | in | 1 | clock | H0's ALIVE bit (a DATA frame's CLR), taken with `i_h0` |
//! | `i_word_data` | in | 16 | clock | data of slot `o_slot` |
//! | `i_word_alive`, `i_word_alarm`, `i_word_void` | in | 1 | clock | its flags / VOID |
//! | `i_word_rn` | in | 4 | clock | its reason nibble N1 (extended-alarm words; unused otherwise) |
//! | `o_slot` | out | 12 | clock | slot whose word is due next |
//! | `o_take` | out | 1 | clock | the word of `o_slot` is taken in this clock (combinational) |
//! | `o_busy` | out | 1 | clock | a packet is being sent |
//! | `o_line` | out | 2 | clock | line, DDR pair |
//!
//! Latency: the J group starts 1–5 bit times after `i_start` (group
//! boundary); each word's fields are taken 5 bit times before its first bit.
//!
//! ```text
//! i_start  _/‾\_________________________________________________
//! o_line   ~idle~| J K | H0 | H1 | slot 0 | slot 1 | ... |~idle~
//! o_take   ______________________^ (slot 0)  ^ (slot 1)  ...
//! ```

use crate::line::enc4b5b::Enc4b5b;
use crate::line::nrzi_tx::NrziTx;
use crate::line::word_rx::WordFormat;
use rust_hdl::prelude::*;

/// Packet generator.
#[derive(LogicBlock)]
pub struct PktTx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Start a packet.
    pub i_start: Signal<In, Bit>,
    /// The packet carries slot words.
    pub i_slots: Signal<In, Bit>,
    /// Slot words − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Header word 0.
    pub i_h0: Signal<In, Bits<16>>,
    /// Header word 1.
    pub i_h1: Signal<In, Bits<16>>,
    /// H0's ALIVE bit (CLR).
    pub i_h0_alive: Signal<In, Bit>,
    /// Slot word data.
    pub i_word_data: Signal<In, Bits<16>>,
    /// Slot word ALIVE.
    pub i_word_alive: Signal<In, Bit>,
    /// Slot word ALARM.
    pub i_word_alarm: Signal<In, Bit>,
    /// Slot word is VOID.
    pub i_word_void: Signal<In, Bit>,
    /// Slot word's reason nibble (extended-alarm words).
    pub i_word_rn: Signal<In, Bits<4>>,
    /// Slot whose word is due.
    pub o_slot: Signal<Out, Bits<12>>,
    /// Word taken.
    pub o_take: Signal<Out, Bit>,
    /// Busy.
    pub o_busy: Signal<Out, Bit>,
    /// Line (DDR pair).
    pub o_line: Signal<Out, Bits<2>>,
    enc: Enc4b5b,
    tx: NrziTx,
    half: DFF<Bit>,
    pend: DFF<Bit>,
    busy: DFF<Bit>,
    wcnt: DFF<Bits<2>>,
    grp: DFF<Bits<3>>,
    slot: DFF<Bits<12>>,
    last: DFF<Bit>,
    w_data: DFF<Bits<16>>,
    w_alive: DFF<Bit>,
    w_alarm: DFF<Bit>,
    w_void: DFF<Bit>,
    w_rn: DFF<Bits<4>>,
    // Extended-alarm words; a word's last group (4 or 5); the data group
    // `grp` is (0..4, the last one 4; 7 the extended variant's N1).
    ext: Constant<Bit>,
    last_g: Constant<Bits<3>>,
    dg: Signal<Local, Bits<3>>,
    nib: Signal<Local, Bits<4>>,
    p_a: Signal<Local, Bit>,
    p_b: Signal<Local, Bit>,
    sym: Signal<Local, Bits<5>>,
}

impl Default for PktTx {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl PktTx {
    /// A packet generator for words in `format`.
    pub fn new(format: WordFormat) -> Self {
        let ext = format == WordFormat::ExtendedAlarm;
        Self {
            clock: Default::default(),
            i_start: Default::default(),
            i_slots: Default::default(),
            i_slots_m1: Default::default(),
            i_h0: Default::default(),
            i_h1: Default::default(),
            i_h0_alive: Default::default(),
            i_word_data: Default::default(),
            i_word_alive: Default::default(),
            i_word_alarm: Default::default(),
            i_word_void: Default::default(),
            i_word_rn: Default::default(),
            o_slot: Default::default(),
            o_take: Default::default(),
            o_busy: Default::default(),
            o_line: Default::default(),
            enc: Default::default(),
            tx: Default::default(),
            half: Default::default(),
            pend: Default::default(),
            busy: Default::default(),
            wcnt: Default::default(),
            grp: Default::default(),
            slot: Default::default(),
            last: Default::default(),
            w_data: Default::default(),
            w_alive: Default::default(),
            w_alarm: Default::default(),
            w_void: Default::default(),
            w_rn: Default::default(),
            ext: Constant::new(ext),
            last_g: Constant::new(if ext { 5u64 } else { 4 }.to_bits()),
            dg: Default::default(),
            nib: Default::default(),
            p_a: Default::default(),
            p_b: Default::default(),
            sym: Default::default(),
        }
    }
}

impl Logic for PktTx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, half, pend, busy, wcnt, grp, slot, last, w_data, w_alive, w_alarm, w_void,
            w_rn
        );
        self.tx.clock.next = self.clock.val();
        self.half.d.next = !self.half.q.val();
        self.tx.i_bit_en.next = self.half.q.val();
        if self.i_start.val() & !self.busy.q.val() {
            self.pend.d.next = true;
        }
        // Parities of the current word (protocol §4).
        self.p_a.next = !(self.w_alarm.q.val()
            ^ self.w_alive.q.val()
            ^ self.w_rn.q.val().get_bit(3)
            ^ self.w_rn.q.val().get_bit(2)
            ^ self.w_data.q.val().get_bit(5)
            ^ self.w_data.q.val().get_bit(4)
            ^ self.w_data.q.val().get_bit(9)
            ^ self.w_data.q.val().get_bit(8)
            ^ self.w_data.q.val().get_bit(13)
            ^ self.w_data.q.val().get_bit(12)
            ^ self.w_data.q.val().get_bit(15));
        self.p_b.next = !(self.w_alive.q.val()
            ^ self.w_rn.q.val().get_bit(2)
            ^ self.w_rn.q.val().get_bit(1)
            ^ self.w_rn.q.val().get_bit(0)
            ^ self.w_data.q.val().get_bit(1)
            ^ self.w_data.q.val().get_bit(0)
            ^ self.w_data.q.val().get_bit(4)
            ^ self.w_data.q.val().get_bit(3)
            ^ self.w_data.q.val().get_bit(2)
            ^ self.w_data.q.val().get_bit(8)
            ^ self.w_data.q.val().get_bit(7)
            ^ self.w_data.q.val().get_bit(6)
            ^ self.w_data.q.val().get_bit(12)
            ^ self.w_data.q.val().get_bit(11)
            ^ self.w_data.q.val().get_bit(10)
            ^ self.w_data.q.val().get_bit(15)
            ^ self.w_data.q.val().get_bit(14));
        // Nibble `grp` of the current word.
        self.dg.next = self.grp.q.val();
        if self.ext.val() & (self.grp.q.val() != 0) {
            self.dg.next = self.grp.q.val() - 1;
            if self.grp.q.val() == 1 {
                self.dg.next = 7.into();
            }
        }
        self.nib.next = self.w_data.q.val().get_bits::<4>(0) & 3;
        if self.w_alarm.q.val() {
            self.nib.next = self.nib.val() | 8;
        }
        if self.w_alive.q.val() {
            self.nib.next = self.nib.val() | 4;
        }
        if self.dg.val() == 7 {
            self.nib.next = self.w_rn.q.val();
        }
        if self.dg.val() == 1 {
            self.nib.next = self.w_data.q.val().get_bits::<4>(2);
        }
        if self.dg.val() == 2 {
            self.nib.next = self.w_data.q.val().get_bits::<4>(6);
        }
        if self.dg.val() == 3 {
            self.nib.next = self.w_data.q.val().get_bits::<4>(10);
        }
        if self.dg.val() == 4 {
            self.nib.next = (self.w_data.q.val().get_bits::<4>(12) >> 1) & 6;
            if self.p_a.val() {
                self.nib.next = self.nib.val() | 8;
            }
            if self.p_b.val() {
                self.nib.next = self.nib.val() | 1;
            }
        }
        // The symbol due now: idle, J (starting), K, S (VOID) or a nibble.
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
        if self.w_void.q.val() {
            self.sym.next = 19.into(); // SYM_S
        }
        if self.wcnt.q.val() == 0 {
            self.sym.next = 17.into(); // SYM_K
        }
        if !self.busy.q.val() {
            self.sym.next = 18.into(); // SYM_I
            if self.pend.q.val() {
                self.sym.next = 16.into(); // SYM_J
            }
        }
        self.enc.i_sym.next = self.sym.val();
        self.tx.i_code.next = self.enc.o_code.val();

        self.o_take.next = false;
        if self.tx.o_take.val() {
            if !self.busy.q.val() {
                if self.pend.q.val() {
                    self.busy.d.next = true;
                    self.pend.d.next = false;
                    self.wcnt.d.next = 0.into();
                    self.grp.d.next = self.last_g.val();
                    self.slot.d.next = 0.into();
                    self.last.d.next = false;
                }
            } else if self.grp.q.val() == self.last_g.val() {
                // The next word.
                self.grp.d.next = 0.into();
                self.w_rn.d.next = 0.into();
                self.w_alive.d.next = false;
                self.w_alarm.d.next = false;
                self.w_void.d.next = false;
                if self.wcnt.q.val() == 0 {
                    self.wcnt.d.next = 1.into();
                    self.w_data.d.next = self.i_h0.val();
                    self.w_alive.d.next = self.i_h0_alive.val();
                } else if self.wcnt.q.val() == 1 {
                    self.wcnt.d.next = 2.into();
                    self.w_data.d.next = self.i_h1.val();
                } else if ((self.wcnt.q.val() == 2) & !self.i_slots.val())
                    | ((self.wcnt.q.val() == 3) & self.last.q.val())
                {
                    self.busy.d.next = false;
                } else {
                    // The word of slot `slot` goes out next.
                    self.slot.d.next = self.slot.q.val() + 1;
                    self.last.d.next = self.slot.q.val() == self.i_slots_m1.val();
                    self.wcnt.d.next = 3.into();
                    self.w_data.d.next = self.i_word_data.val();
                    self.w_alive.d.next = self.i_word_alive.val();
                    self.w_alarm.d.next = self.i_word_alarm.val();
                    self.w_void.d.next = self.i_word_void.val();
                    // (Basic words have none: a constant 0 here lets
                    // synthesis drop whatever feeds `i_word_rn`.)
                    if self.ext.val() {
                        self.w_rn.d.next = self.i_word_rn.val();
                    }
                    self.o_take.next = true;
                }
            } else {
                self.grp.d.next = self.grp.q.val() + 1;
            }
        }
        self.o_slot.next = self.slot.q.val();
        self.o_busy.next = self.busy.q.val() | self.pend.q.val();
        self.o_line.next = 0.into();
        if self.tx.o_line.val() {
            self.o_line.next = 3.into();
        }
    }
}
