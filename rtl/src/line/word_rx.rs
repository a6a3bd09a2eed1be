//! # word_rx — word assembler, parity check, slot counter (protocol §4, §5, §7)
//!
//! Purpose: the receive half of the paper's slot shift register. It collects
//! the code groups of a packet (from [`crate::line::framer_rx`]) into words,
//! decodes them (4B/5B), checks both odd parities, counts words into header
//! words and slots (or a retransmission packet's request words, protocol
//! §8), checks the header (type, slot count), compares the slot
//! number with the node's address (DIP switches → `i_address`) and tells the
//! framer when the packet ends: after its last word, or at the third idle
//! group in a row (a packet cut short upstream: the word in progress and the
//! rest are not received; one line-bit error touches at most two groups, so
//! it costs a word, never the packet).
//!
//! Parameters (refused at build when invalid): `ext` — extended-alarm words
//! of 6 groups instead of 5 (protocol §6).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_start` | in | 1 | clock | packet start (J K found) |
//! | `i_gvalid` | in | 1 | clock | `i_group` is valid |
//! | `i_group` | in | 5 | clock | code group |
//! | `i_idle` | in | 1 | clock | `i_group` is the idle group 11111 (from [`crate::line::framer_rx`]'s register) |
//! | `i_slots_m1` | in | 12 | static | configured slot count − 1 |
//! | `i_address` | in | 12 | static | node address (home slot) |
//! | `o_end` | out | 1 | clock | packet over (to the framer's `i_end`) |
//! | `o_wvalid` | out | 1 | clock | a word is complete |
//! | `o_kind` | out | 2 | clock | 0 H0, 1 H1, 2 slot, 3 an RTX's request word (after a good RTX head: H1 = NOT H0) |
//! | `o_slot` | out | 12 | clock | slot number (`o_kind` = 2); the request word's number (`o_kind` = 3: even an index word, odd a data word) |
//! | `o_data` | out | 16 | clock | data bits |
//! | `o_alive`, `o_alarm` | out | 1 | clock | flag bits |
//! | `o_reason` | out | 4 | clock | reason nibble (ext only, else 0) |
//! | `o_ok` | out | 1 | clock | all groups data, both parities odd |
//! | `o_compl` | out | 1 | clock | its 16 data bits are the complement of the previous word's (a TST's H1 = NOT H0, protocol §9; meaningful for a good word whose predecessor in the packet was good) |
//! | `o_void` | out | 1 | clock | all groups S (VOID word) |
//! | `o_marked` | out | 1 | clock | bad, its last group T: a forwarder marked it (damaged on an earlier fibre, protocol §4) |
//! | `o_own` | out | 1 | clock | slot word of `i_address` |
//! | `o_hdr_bad` | out | 1 | clock | DATA header rejected; packet dropped |
//! | `o_ptype` | out | 2 | clock | packet type from a good H0 (00 DATA, 01 SEC, 10 TST, 11 RTX) |
//!
//! Latency: outputs are registered, one clock after the word's last group;
//! the word's fields (`o_kind` … `o_ptype`) are the decoder's own registers,
//! not copies: they hold from `o_wvalid` until the next group arrives (on a
//! line at least 5 bit times later), and a consumer takes them before that
//! (issue 21: no second copy of a word in the slave);
//! `o_end` and `o_hdr_bad` one clock later (the header is checked on the
//! registered word).
//!
//! ```text
//! i_start   _/‾\__________________________________________________
//! i_gvalid  _____/‾\_/‾\_/‾\_/‾\_/‾\___ ... _/‾\_/‾\ ... _/‾\_______
//!                 H0 (5 groups)              H1        last slot
//! o_wvalid  _______________________/‾\_______/‾\______ ... __/‾\____
//! o_kind                            0         1               2
//! o_end     _____________________________________________ ... /‾\____
//! ```

use crate::line::dec5b4b::Dec5b4b;
use rust_hdl::prelude::*;
use std::collections::BTreeMap;

/// Word assembler and checker.
#[derive(LogicBlock)]
pub struct WordRx {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Packet start.
    pub i_start: Signal<In, Bit>,
    /// Group valid.
    pub i_gvalid: Signal<In, Bit>,
    /// Code group.
    pub i_group: Signal<In, Bits<5>>,
    /// The group is an idle.
    pub i_idle: Signal<In, Bit>,
    /// Slot count − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Node address.
    pub i_address: Signal<In, Bits<12>>,
    /// End of packet.
    pub o_end: Signal<Out, Bit>,
    /// Word complete.
    pub o_wvalid: Signal<Out, Bit>,
    /// 0 H0, 1 H1, 2 slot, 3 RTX request word.
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
    /// Data bits = NOT the previous word's.
    pub o_compl: Signal<Out, Bit>,
    /// VOID word.
    pub o_void: Signal<Out, Bit>,
    /// Marked word (last group T).
    pub o_marked: Signal<Out, Bit>,
    /// Own slot.
    pub o_own: Signal<Out, Bit>,
    /// Header rejected.
    pub o_hdr_bad: Signal<Out, Bit>,
    /// Packet type of the current packet.
    pub o_ptype: Signal<Out, Bits<2>>,
    dec: Dec5b4b,
    // The nibble moved to bits 23:20 (a wiring table: rust-hdl has no
    // lint-clean zero-extending concatenation).
    nib_top: ROM<Bits<24>, 4>,
    last_group: Constant<Bits<3>>,
    // Word being assembled.
    gcount: DFF<Bits<3>>,
    idles: DFF<Bits<2>>,
    /// The word's nibbles as they arrived, the last at the top (bits
    /// 23:20): every group shifts the register by one nibble, so each bit
    /// takes the bit above it or holds (issue 21: no multiplexer in front
    /// of a data bit, and the 4B/5B decoder feeds only the top nibble).
    /// A basic word's N0 ends in bits 7:4, an extended word's in 3:0 (its
    /// N1 in 7:4); `o_data`, `o_alarm`, `o_alive` and `o_reason` are
    /// wired from the nibbles (where each data bit sits: the comment at
    /// the `data` signal).
    raw: DFF<Bits<24>>,
    par_a: DFF<Bit>,
    par_b: DFF<Bit>,
    all_data: DFF<Bit>,
    all_s: DFF<Bit>,
    // Packet state.
    active: DFF<Bit>,
    wcount: DFF<Bits<2>>,
    slot: DFF<Bits<12>>,
    /// The slot counter steps (`slot_inc`) or clears (`slot_clr`) in the
    /// clock after the one that decides it, from these registers (issue
    /// 21: so a counter bit's logic is its carry and one register, not
    /// the whole condition again; on a CoolRunner-II a T input of two
    /// product terms instead of a D input of 17).
    slot_inc: DFF<Bit>,
    slot_clr: DFF<Bit>,
    ptype: DFF<Bits<2>>,
    // Registered outputs.
    // A word was published in the clock before: check its header.
    check: DFF<Bit>,
    end_r: DFF<Bit>,
    wvalid_r: DFF<Bit>,
    kind_r: DFF<Bits<2>>,
    adv: DFF<Bit>,
    ok_r: DFF<Bit>,
    compl: DFF<Bit>,
    compl_r: DFF<Bit>,
    void_r: DFF<Bit>,
    marked_r: DFF<Bit>,
    own_r: DFF<Bit>,
    hdr_bad_r: DFF<Bit>,
    // Combinational helpers.
    nib: Signal<Local, Bits<4>>,
    // The word's data bits (protocol §4), wired from `raw`.
    data: Signal<Local, Bits<16>>,
    // Its ALARM and ALIVE bits and (extended words) its reason nibble
    // N1, wired from `raw` too (0 for basic words).
    alarm: Signal<Local, Bit>,
    alive: Signal<Local, Bit>,
    reason: Signal<Local, Bits<4>>,
    // The previous word's nibble this group replaces (for `o_compl`):
    // the nibble at N0's place in `raw`.
    prev_nib: Signal<Local, Bits<4>>,
    // D15:D14 (the last group's middle bits), D13:D2 and D1:D0 (N0's
    // low bits), each at its place in `data`.
    d_lo: Signal<Local, Bits<16>>,
    d_hi: Signal<Local, Bits<16>>,
    d_mid: Signal<Local, Bits<16>>,
    w_pa: Signal<Local, Bit>,
    w_pb: Signal<Local, Bit>,
    w_all_data: Signal<Local, Bit>,
    w_all_s: Signal<Local, Bit>,
    w_ok: Signal<Local, Bit>,
    w_compl: Signal<Local, Bit>,
}

/// The word format a receiver reads (protocol §6): the parameter of
/// [`WordRx`], [`crate::line::monitor::Monitor`] and [`crate::node::port_rx::PortRx`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WordFormat {
    /// 25-bit words (five code groups): the basic variant.
    Basic,
    /// 30-bit words with a reason nibble (six code groups): the
    /// extended-alarm variant.
    ExtendedAlarm,
}

impl WordRx {
    /// A word assembler for 25-bit words ([`WordFormat::Basic`]) or 30-bit
    /// extended-alarm words ([`WordFormat::ExtendedAlarm`]).
    pub fn new(format: WordFormat) -> Self {
        let ext = format == WordFormat::ExtendedAlarm;
        Self {
            clock: Default::default(),
            i_start: Default::default(),
            i_gvalid: Default::default(),
            i_group: Default::default(),
            i_idle: Default::default(),
            i_slots_m1: Default::default(),
            i_address: Default::default(),
            o_end: Default::default(),
            o_wvalid: Default::default(),
            o_kind: Default::default(),
            o_slot: Default::default(),
            o_data: Default::default(),
            o_alive: Default::default(),
            o_alarm: Default::default(),
            o_reason: Default::default(),
            o_ok: Default::default(),
            o_compl: Default::default(),
            o_void: Default::default(),
            o_marked: Default::default(),
            o_own: Default::default(),
            o_hdr_bad: Default::default(),
            o_ptype: Default::default(),
            dec: Default::default(),
            nib_top: ROM::new(
                (0..16u64)
                    .map(|n| (n.to_bits(), (n << 20).to_bits()))
                    .collect::<BTreeMap<Bits<4>, Bits<24>>>(),
            ),
            last_group: Constant::new(if ext { 5u64 } else { 4u64 }.to_bits()),
            gcount: Default::default(),
            idles: Default::default(),
            raw: Default::default(),
            par_a: Default::default(),
            par_b: Default::default(),
            all_data: Default::default(),
            all_s: Default::default(),
            active: Default::default(),
            wcount: Default::default(),
            slot: Default::default(),
            slot_inc: Default::default(),
            slot_clr: Default::default(),
            ptype: Default::default(),
            check: Default::default(),
            end_r: Default::default(),
            wvalid_r: Default::default(),
            kind_r: Default::default(),
            adv: Default::default(),
            ok_r: Default::default(),
            compl: Default::default(),
            compl_r: Default::default(),
            void_r: Default::default(),
            marked_r: Default::default(),
            own_r: Default::default(),
            hdr_bad_r: Default::default(),
            nib: Default::default(),
            data: Default::default(),
            alarm: Default::default(),
            alive: Default::default(),
            reason: Default::default(),
            prev_nib: Default::default(),
            d_lo: Default::default(),
            d_hi: Default::default(),
            d_mid: Default::default(),
            w_pa: Default::default(),
            w_pb: Default::default(),
            w_all_data: Default::default(),
            w_all_s: Default::default(),
            w_ok: Default::default(),
            w_compl: Default::default(),
        }
    }
}

impl Logic for WordRx {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, gcount, raw, par_a, par_b, all_data, all_s, active, wcount, slot,
            slot_inc, slot_clr, ptype, check, end_r, wvalid_r, kind_r, adv, ok_r, compl, compl_r,
            void_r, marked_r, own_r, hdr_bad_r, idles
        );
        self.dec.i_code.next = self.i_group.val();
        self.nib.next = self.dec.o_nibble.val();
        self.nib_top.address.next = self.dec.o_nibble.val();
        // The word's data bits from its nibbles (protocol §4): N0 = {ALARM,
        // ALIVE, D1, D0}, [ext: N1 = REASON], D[5:2], D[9:6], D[13:10],
        // last = {PA, D15, D14, PB}. In `raw` D[13:2] are bits 19:8 in
        // both formats; D1:D0 are bits 5:4 (basic) or 1:0 (extended);
        // D15:D14 are bits 22:21.
        self.d_hi.next = self.raw.q.val().get_bits::<16>(7) & 0xc000;
        self.d_mid.next = self.raw.q.val().get_bits::<16>(6) & 0x3ffc;
        self.d_lo.next = self.raw.q.val().get_bits::<16>(4) & 3;
        self.prev_nib.next = self.raw.q.val().get_bits::<4>(4);
        self.alarm.next = self.raw.q.val().get_bit(7);
        self.alive.next = self.raw.q.val().get_bit(6);
        self.reason.next = 0.into();
        if self.last_group.val() == 5 {
            self.d_lo.next = self.raw.q.val().get_bits::<16>(0) & 3;
            self.prev_nib.next = self.raw.q.val().get_bits::<4>(0);
            self.alarm.next = self.raw.q.val().get_bit(3);
            self.alive.next = self.raw.q.val().get_bit(2);
            self.reason.next = self.raw.q.val().get_bits::<4>(4);
        }
        self.data.next = self.d_hi.val() | self.d_mid.val() | self.d_lo.val();
        self.w_pa.next = self.par_a.q.val() ^ self.nib.val().get_bit(3) ^ self.nib.val().get_bit(2);
        self.w_pb.next = self.par_b.q.val()
            ^ self.nib.val().get_bit(2)
            ^ self.nib.val().get_bit(1)
            ^ self.nib.val().get_bit(0);
        self.w_all_data.next = self.all_data.q.val() & self.dec.o_data.val();
        self.w_all_s.next = self.all_s.q.val() & self.dec.o_s.val();
        self.w_ok.next = self.w_all_data.val() & self.w_pa.val() & self.w_pb.val();
        // The nibble a group pushes out of N0's place in `raw` is the
        // previous word's at the place this group takes: comparing them
        // group by group tells whether this word's data is the complement
        // of the previous one's, without a copy of that word. Only the
        // data bits count (not ALARM, ALIVE, REASON or the parities).
        self.w_compl.next = self.compl.q.val() & (self.nib.val() == !self.prev_nib.val());
        if self.gcount.q.val() == 0 {
            self.w_compl.next =
                self.nib.val().get_bits::<2>(0) == !self.prev_nib.val().get_bits::<2>(0);
        }
        if self.gcount.q.val() == self.last_group.val() {
            self.w_compl.next = self.compl.q.val()
                & (self.nib.val().get_bits::<2>(1) == !self.prev_nib.val().get_bits::<2>(1));
        }
        if (self.gcount.q.val() == 1) & (self.last_group.val() == 5) {
            self.w_compl.next = self.compl.q.val();
        }

        self.slot_inc.d.next = false;
        self.slot_clr.d.next = false;
        if self.slot_clr.q.val() {
            self.slot.d.next = 0.into();
        } else if self.slot_inc.q.val() {
            self.slot.d.next = self.slot.q.val() + 1;
        }
        self.end_r.d.next = false;
        self.wvalid_r.d.next = false;
        self.hdr_bad_r.d.next = false;
        self.check.d.next = false;
        // Every group shifts in, whether a packet is open or not: the
        // word's nibbles are read in its last group's clock, so groups
        // between packets (and the third idle, which ends one) only change
        // `raw` after the fields' hold has ended (issue 21: on a
        // CoolRunner-II each `raw` bit is then two product terms, not
        // seven).
        if self.i_gvalid.val() {
            self.raw.d.next = (self.raw.q.val() >> 4) | self.nib_top.data.val();
        }
        if self.i_start.val() {
            self.active.d.next = true;
            self.gcount.d.next = 0.into();
            self.wcount.d.next = 0.into();
            self.slot_clr.d.next = true;
            self.adv.d.next = false;
            self.ptype.d.next = 0.into();
            self.par_a.d.next = false;
            self.par_b.d.next = false;
            self.all_data.d.next = true;
            self.all_s.d.next = true;
            self.idles.d.next = 0.into();
        } else if self.i_gvalid.val()
            & self.active.q.val()
            & self.i_idle.val()
            & (self.idles.q.val() == 2)
        {
            // The third idle group in a row: the packet was cut short (a
            // break upstream); the word in progress and the rest are not
            // received. (One line-bit error touches at most two groups.)
            self.end_r.d.next = true;
            self.active.d.next = false;
            self.idles.d.next = 0.into();
        } else if self.i_gvalid.val() & self.active.q.val() {
            self.idles.d.next = 0.into();
            if self.i_idle.val() {
                self.idles.d.next = self.idles.q.val() + 1;
            }
            if self.gcount.q.val() == 0 {
                // The slot number moves on as the next slot word begins
                // (a clock later: `slot_inc`), so the one just published
                // stays on `o_slot` until then.
                if self.adv.q.val() {
                    self.slot_inc.d.next = true;
                    self.adv.d.next = false;
                }
            }
            self.par_a.d.next = self.w_pa.val();
            self.par_b.d.next = self.w_pb.val();
            self.all_data.d.next = self.w_all_data.val();
            self.all_s.d.next = self.w_all_s.val();
            self.compl.d.next = self.w_compl.val();
            self.gcount.d.next = self.gcount.q.val() + 1;
            if self.gcount.q.val() == self.last_group.val() {
                // Word complete: publish it and start the next one.
                self.gcount.d.next = 0.into();
                self.par_a.d.next = false;
                self.par_b.d.next = false;
                self.all_data.d.next = true;
                self.all_s.d.next = true;
                self.wvalid_r.d.next = true;
                self.kind_r.d.next = self.wcount.q.val();
                self.ok_r.d.next = self.w_ok.val();
                self.compl_r.d.next = self.w_compl.val();
                self.void_r.d.next = self.w_all_s.val();
                // The forwarder's mark, T (merkur_model::line::CODE_T).
                self.marked_r.d.next = self.i_group.val() == 0b01101;
                self.own_r.d.next =
                    (self.wcount.q.val() == 2) & (self.slot.q.val() == self.i_address.val());
                self.check.d.next = true;
                if self.wcount.q.val() == 0 {
                    // H0: its type; checked the next clock.
                    self.wcount.d.next = 1.into();
                    self.ptype.d.next = self.nib.val().get_bits::<2>(1);
                } else if self.wcount.q.val() == 1 {
                    self.wcount.d.next = 2.into();
                } else {
                    self.adv.d.next = true;
                }
            }
        }
        // The word published in the clock before, checked (issue 20: a
        // word's decode and what its header decides are a clock apart; the
        // next group is at least 5 clocks away).
        if self.check.q.val() {
            if self.kind_r.q.val() == 0 {
                // H0: type and slot count.
                if !self.ok_r.q.val()
                    | self.alarm.val()
                    | ((self.data.val().get_bits::<2>(14) == 0)
                        & (self.data.val().get_bits::<12>(0) != self.i_slots_m1.val()))
                {
                    self.hdr_bad_r.d.next = true;
                    self.end_r.d.next = true;
                    self.active.d.next = false;
                }
            } else if self.kind_r.q.val() == 1 {
                // H1; SEC and TST packets end here, and an RTX whose H1 is
                // not NOT H0. An RTX goes on with its request words
                // (kind 3, numbered from 0 in `o_slot`) until the idles.
                if !self.ok_r.q.val() | self.alarm.val() {
                    self.hdr_bad_r.d.next = self.ptype.q.val() == 0;
                    self.end_r.d.next = true;
                    self.active.d.next = false;
                } else if (self.ptype.q.val() == 3) & self.compl_r.q.val() {
                    self.wcount.d.next = 3.into();
                    self.slot_clr.d.next = true;
                    self.adv.d.next = false;
                } else if self.ptype.q.val() != 0 {
                    self.end_r.d.next = true;
                    self.active.d.next = false;
                }
            } else if (self.kind_r.q.val() == 2) & (self.slot.q.val() == self.i_slots_m1.val()) {
                self.end_r.d.next = true;
                self.active.d.next = false;
            }
        }
        self.o_end.next = self.end_r.q.val();
        self.o_wvalid.next = self.wvalid_r.q.val();
        self.o_kind.next = self.kind_r.q.val();
        self.o_slot.next = self.slot.q.val();
        self.o_data.next = self.data.val();
        self.o_alive.next = self.alive.val();
        self.o_alarm.next = self.alarm.val();
        self.o_reason.next = self.reason.val();
        self.o_ok.next = self.ok_r.q.val();
        self.o_compl.next = self.compl_r.q.val();
        self.o_void.next = self.void_r.q.val();
        self.o_marked.next = self.marked_r.q.val();
        self.o_own.next = self.own_r.q.val();
        self.o_hdr_bad.next = self.hdr_bad_r.q.val();
        self.o_ptype.next = self.ptype.q.val();
    }
}
