//! # fwd — cut-through forwarder: the slave's slot shift register (protocol §4, §5, §7)
//!
//! Purpose: repeats the INPUT stream on OUTPUT, bit for bit on the recovered
//! timing, five code bits (one group) behind, and changes what the node
//! changes on the way:
//! - H0: sets FS when the node is in failsafe, RWC when it is wrapped;
//! - H1: adds 1 to HOP (carry running forward through the nibbles);
//! - its own slot (`i_address`; in a master (`i_master`) every slot whose
//!   `i_slot_cfg` is LOCAL or ACT): a **sensor** or a master's LOCAL slot writes a fresh word
//!   `{i_sensor_data, ALIVE = toggle}` or an alarm; an **actuator** replaces
//!   ALIVE with its toggle, or — when the first group shows VOID or an alarm
//!   (its own, coming back) — writes `{i_act_out, toggle}`, or its alarm;
//!   a **master's ACT slot** gets `i_slot_data` with the actuator's ALIVE
//!   kept, or — on VOID — `{i_slot_data, NOT i_slot_alive}` (`o_regen`);
//! - parities are fixed in the word's last group from the changes made
//!   (delta parity), so a word that arrived bad leaves bad — and **marked**:
//!   its last group goes out as T (protocol §4), so the next receivers know
//!   it was damaged before their fibre (their stream controllers count only
//!   their own fibre's errors);
//! - H0's FS bit: set when the node is in failsafe, unless the header
//!   carries CLR (its ALIVE bit, in the first group) and arrived with FS = 0:
//!   the node leaves failsafe at that header (protocol §12).
//!
//! Everything else, including J K, idles, bad groups and packets after a
//! rejected header (`i_hdr_bad`), passes unchanged; three idle groups in a
//! row end a packet that was cut short upstream (as [`crate::rx_word`]), and
//! so does a dead INPUT (no bit for [`DEAD_CLOCKS`]: the clock recovery
//! muted), which also refills the
//! group delay with idles. A frame whose header was processed toggles the
//! Alive flip-flop even when it was cut short. The Alive flip-flop
//! toggles after each processed DATA packet. Alarms: `i_alarm_req` with
//! `i_alarm_reason` is sent in the home slot if the previous cycle's home word
//! was data (alternation); `o_alarm_sent` pulses when it goes out.
//! The output bits go through a [`Retime`] buffer and out on the node's own
//! clock (DDR pair), so the receiver's sampling error is not passed on.
//!
//! Parameters: none (basic 25-bit words; the extended-alarm variant is not
//! implemented by this block yet).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_bvalid`, `i_level`, `i_phase` | in | 1, 1, 2 | clock | recovered INPUT bits (from [`crate::port_rx`]) |
//! | `i_hdr_bad` | in | 1 | clock | header rejected, or not a DATA packet: pass the rest unchanged |
//! | `i_mute` | in | 1 | clock | send idles for the code bits arriving from now on (a TST's rest) |
//! | `i_slots_m1`, `i_address` | in | 12 | static | slot count − 1, home slot |
//! | `i_actuator` | in | 1 | static | 1 actuator, 0 sensor |
//! | `i_sensor_data` | in | 16 | clock | sensor value (sampled at its slot) |
//! | `i_act_out` | in | 16 | clock | actuator output register |
//! | `i_fs`, `i_wrapped` | in | 1 | clock | node in failsafe / wrapped |
//! | `i_alarm_req`, `i_alarm_reason` | in | 1, 4 | clock | alarm to send |
//! | `i_master` | in | 1 | static | master mode: per-slot writes from `i_slot_cfg` |
//! | `i_slot_cfg`, `i_slot_data`, `i_slot_alive` | in | 2, 16, 1 | clock | master: configuration (bit 0 LOCAL, bit 1 ACT), data memory and actuator Alive of slot `o_slot`, valid by the word's first group |
//! | `o_slot` | out | 12 | clock | slot of the word passing |
//! | `o_regen` | out | 1 | clock | master: an ACT slot's VOID was regenerated |
//! | `o_alarm_sent`, `o_sent_reason` | out | 1, 4 | clock | the alarm went out, and which |
//! | `o_pkt_done` | out | 1 | clock | a DATA packet's last slot went through |
//! | `o_toggle` | out | 1 | clock | the Alive flip-flop |
//! | `o_line` | out | 2 | clock | OUTPUT line, DDR pair (bit 0 first) |
//!
//! Latency: 5 bit times (one group) from INPUT bit to the retime buffer,
//! which sends it 2.5 ± 0.5 bit times after its receive clock; with the
//! CDR 8–9.5 bit times from line to line (measured at the fibres of rings
//! of 8 to 100 nodes: mean 8.3–8.6, docs/benchmarks.md).
//!
//! ```text
//! in code   | N0 | N1 | N2 | N3 | N4 | ...
//! out code       | N0'| N1'| N2'| N3'| N4'|        N0 decides, N4' fixes the parities
//! ```

use crate::retime::Retime;
use rust_hdl::prelude::*;

/// Clocks without a recovered bit after which INPUT counts as dead (3 bit
/// times; a live line gives a bit every 2 clocks, 3 at most): shorter
/// than the gap a switchbox change leaves after a receiver muted (12 dark
/// bit times, [`crate::sw_dark`], less the 8 of the mute), and than the one
/// an upstream node whose input stopped leaves ([`crate::retime::QUIET_BITS`]
/// less the 8 of the mute).
pub const DEAD_CLOCKS: u64 = 6;

// Word actions (register `action`, rust-hdl emits literals, not Rust consts):
// 0 pass, 1 H0 (FS/RWC), 2 H1 (HOP + 1), 3 fresh word, 4 actuator ALIVE,
// 5 master ACT slot (data from the data memory, ALIVE kept).

/// Cut-through forwarder of a slave node.
#[derive(LogicBlock)]
pub struct Fwd {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Recovered bit valid.
    pub i_bvalid: Signal<In, Bit>,
    /// Recovered line level.
    pub i_level: Signal<In, Bit>,
    /// Sample phase of the recovered bit.
    pub i_phase: Signal<In, Bits<2>>,
    /// Header rejected.
    pub i_hdr_bad: Signal<In, Bit>,
    /// Idles instead of the arriving code bits.
    pub i_mute: Signal<In, Bit>,
    /// Slot count − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Home slot.
    pub i_address: Signal<In, Bits<12>>,
    /// Actuator (1) or sensor (0).
    pub i_actuator: Signal<In, Bit>,
    /// Sensor value.
    pub i_sensor_data: Signal<In, Bits<16>>,
    /// Actuator output register.
    pub i_act_out: Signal<In, Bits<16>>,
    /// Failsafe.
    pub i_fs: Signal<In, Bit>,
    /// Wrapped.
    pub i_wrapped: Signal<In, Bit>,
    /// Alarm to send.
    pub i_alarm_req: Signal<In, Bit>,
    /// Its reason.
    pub i_alarm_reason: Signal<In, Bits<4>>,
    /// Master node: the slot's writer is decided by `i_slot_cfg`.
    pub i_master: Signal<In, Bit>,
    /// Configuration of slot `o_slot` (bit 0 LOCAL, bit 1 ACT).
    pub i_slot_cfg: Signal<In, Bits<2>>,
    /// Data memory of slot `o_slot`.
    pub i_slot_data: Signal<In, Bits<16>>,
    /// Last actuator Alive seen in slot `o_slot` (ACT slots).
    pub i_slot_alive: Signal<In, Bit>,
    /// Slot number of the word now passing (for the memory look-ups).
    pub o_slot: Signal<Out, Bits<12>>,
    /// A VOID in an ACT slot was regenerated (the Alive flips).
    pub o_regen: Signal<Out, Bit>,
    /// Alarm sent.
    pub o_alarm_sent: Signal<Out, Bit>,
    /// The reason of the alarm sent (valid with `o_alarm_sent`).
    pub o_sent_reason: Signal<Out, Bits<4>>,
    /// DATA packet done.
    pub o_pkt_done: Signal<Out, Bit>,
    /// Alive flip-flop.
    pub o_toggle: Signal<Out, Bit>,
    /// Output line (DDR pair).
    pub o_line: Signal<Out, Bits<2>>,
    jk: Constant<Bits<10>>,
    dead_after: Constant<Bits<4>>,
    prev: DFF<Bit>,
    window: DFF<Bits<10>>,
    delay: DFF<Bits<5>>,
    inpkt: DFF<Bit>,
    idles: DFF<Bits<2>>,
    quiet: DFF<Bits<4>>,
    bitc: DFF<Bits<3>>,
    gidx: DFF<Bits<3>>,
    wcount: DFF<Bits<2>>,
    slot: DFF<Bits<12>>,
    dead: DFF<Bit>,
    action: DFF<Bits<3>>,
    // The incoming word so far (for the mark): parities, all data, all S.
    in_pa: DFF<Bit>,
    in_pb: DFF<Bit>,
    in_data: DFF<Bit>,
    in_s: DFF<Bit>,
    // H0 carries CLR (its ALIVE bit).
    clr_h0: DFF<Bit>,
    d_a: DFF<Bit>,
    d_b: DFF<Bit>,
    carry: DFF<Bit>,
    f_data: DFF<Bits<16>>,
    f_alive: DFF<Bit>,
    f_alarm: DFF<Bit>,
    toggle: DFF<Bit>,
    prev_alarm: DFF<Bit>,
    out: Retime,
    sent: DFF<Bit>,
    sent_reason: DFF<Bits<4>>,
    done: DFF<Bit>,
    regen: DFF<Bit>,
    code: Signal<Local, Bit>,
    shifted: Signal<Local, Bits<10>>,
    group: Signal<Local, Bits<5>>,
    nib: Signal<Local, Bits<4>>,
    g_data: Signal<Local, Bit>,
    g_s: Signal<Local, Bit>,
    code_out: Signal<Local, Bits<5>>,
    act_now: Signal<Local, Bits<3>>,
    nib_out: Signal<Local, Bits<4>>,
    recode: Signal<Local, Bit>,
    diff: Signal<Local, Bits<4>>,
    n_data: Signal<Local, Bits<16>>,
    n_alive: Signal<Local, Bit>,
    n_alarm: Signal<Local, Bit>,
    p_a: Signal<Local, Bit>,
    p_b: Signal<Local, Bit>,
    send_alarm: Signal<Local, Bit>,
    own: Signal<Local, Bit>,
    home: Signal<Local, Bit>,
    cut: Signal<Local, Bit>,
    pre_b2: Signal<Local, Bit>,
    pre_b1: Signal<Local, Bit>,
    out_bit: Signal<Local, Bit>,
    arrived_bad: Signal<Local, Bit>,
}

impl Default for Fwd {
    fn default() -> Self {
        Self::new()
    }
}

impl Fwd {
    /// A forwarder (no parameters).
    pub fn new() -> Self {
        Self {
            clock: Default::default(),
            i_bvalid: Default::default(),
            i_level: Default::default(),
            i_phase: Default::default(),
            i_hdr_bad: Default::default(),
            i_mute: Default::default(),
            i_slots_m1: Default::default(),
            i_address: Default::default(),
            i_actuator: Default::default(),
            i_sensor_data: Default::default(),
            i_act_out: Default::default(),
            i_fs: Default::default(),
            i_wrapped: Default::default(),
            i_alarm_req: Default::default(),
            i_alarm_reason: Default::default(),
            i_master: Default::default(),
            i_slot_cfg: Default::default(),
            i_slot_data: Default::default(),
            i_slot_alive: Default::default(),
            o_slot: Default::default(),
            o_regen: Default::default(),
            o_alarm_sent: Default::default(),
            o_sent_reason: Default::default(),
            o_pkt_done: Default::default(),
            o_toggle: Default::default(),
            o_line: Default::default(),
            jk: Constant::new(crate::rx_framer::JK_BITS.to_bits()),
            dead_after: Constant::new(DEAD_CLOCKS.to_bits()),
            prev: Default::default(),
            window: Default::default(),
            delay: Default::default(),
            inpkt: Default::default(),
            idles: Default::default(),
            quiet: Default::default(),
            bitc: Default::default(),
            gidx: Default::default(),
            wcount: Default::default(),
            slot: Default::default(),
            dead: Default::default(),
            action: Default::default(),
            in_pa: Default::default(),
            in_pb: Default::default(),
            in_data: Default::default(),
            in_s: Default::default(),
            clr_h0: Default::default(),
            d_a: Default::default(),
            d_b: Default::default(),
            carry: Default::default(),
            f_data: Default::default(),
            f_alive: Default::default(),
            f_alarm: Default::default(),
            toggle: Default::default(),
            prev_alarm: Default::default(),
            out: Default::default(),
            sent: Default::default(),
            sent_reason: Default::default(),
            done: Default::default(),
            regen: Default::default(),
            code: Default::default(),
            shifted: Default::default(),
            group: Default::default(),
            nib: Default::default(),
            g_data: Default::default(),
            g_s: Default::default(),
            code_out: Default::default(),
            act_now: Default::default(),
            nib_out: Default::default(),
            recode: Default::default(),
            diff: Default::default(),
            n_data: Default::default(),
            n_alive: Default::default(),
            n_alarm: Default::default(),
            p_a: Default::default(),
            p_b: Default::default(),
            send_alarm: Default::default(),
            own: Default::default(),
            home: Default::default(),
            cut: Default::default(),
            pre_b2: Default::default(),
            pre_b1: Default::default(),
            out_bit: Default::default(),
            arrived_bad: Default::default(),
        }
    }
}

impl Logic for Fwd {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            prev,
            window,
            delay,
            inpkt,
            idles,
            quiet,
            bitc,
            gidx,
            wcount,
            slot,
            dead,
            action,
            d_a,
            d_b,
            carry,
            f_data,
            f_alive,
            f_alarm,
            toggle,
            prev_alarm,
            sent,
            sent_reason,
            done,
            regen,
            in_pa,
            in_pb,
            in_data,
            in_s,
            clr_h0
        );
        // NRZI decode and the group that completes with this bit.
        self.code.next = self.i_level.val() ^ self.prev.q.val();
        self.shifted.next = self.window.q.val() << 1;
        if self.code.val() {
            self.shifted.next = (self.window.q.val() << 1) | 1;
        }
        self.group.next = self.shifted.val().get_bits::<5>(0);
        // 4B/5B decode, written out: a ROM instance here would be read in the
        // same always block that addresses it, which Verilator cannot order.
        self.nib.next = 0.into();
        self.g_data.next = false;
        if self.group.val() == 0b11110 {
            self.nib.next = 0.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b01001 {
            self.nib.next = 1.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10100 {
            self.nib.next = 2.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10101 {
            self.nib.next = 3.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b01010 {
            self.nib.next = 4.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b01011 {
            self.nib.next = 5.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b01110 {
            self.nib.next = 6.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b01111 {
            self.nib.next = 7.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10010 {
            self.nib.next = 8.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10011 {
            self.nib.next = 9.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10110 {
            self.nib.next = 10.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b10111 {
            self.nib.next = 11.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b11010 {
            self.nib.next = 12.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b11011 {
            self.nib.next = 13.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b11100 {
            self.nib.next = 14.into();
            self.g_data.next = true;
        }
        if self.group.val() == 0b11101 {
            self.nib.next = 15.into();
            self.g_data.next = true;
        }
        self.g_s.next = self.group.val() == 0b11001;

        // What to do with the word that starts with this group. A slave
        // writes its home slot; a master every slot its configuration marks
        // LOCAL or ACT (its home slot is one of its LOCAL slots).
        self.home.next = (self.wcount.q.val() == 2)
            & (self.slot.q.val() == self.i_address.val())
            & !self.dead.q.val()
            & !self.i_fs.val();
        self.own.next = self.home.val();
        if self.i_master.val() {
            self.own.next = (self.wcount.q.val() == 2)
                & (self.i_slot_cfg.val() != 0)
                & !self.dead.q.val()
                & !self.i_fs.val();
        }
        self.send_alarm.next = self.home.val() & self.i_alarm_req.val() & !self.prev_alarm.q.val();
        self.act_now.next = self.action.q.val();
        if self.gidx.q.val() == 0 {
            self.act_now.next = 0.into();
            if !self.dead.q.val() {
                if self.wcount.q.val() == 0 {
                    self.act_now.next = 1.into();
                }
                if self.wcount.q.val() == 1 {
                    self.act_now.next = 2.into();
                }
            }
            if self.own.val() {
                // Sensor, LOCAL slot: always fresh. Actuator (from the first
                // group): its alarm, VOID (S) or an alarm coming back ->
                // fresh; data -> replace ALIVE; anything else -> leaves bad.
                // Master, ACT slot: data -> replace the data, keep ALIVE;
                // VOID -> fresh with the Alive the actuator would send;
                // anything else (an alarm, an invalid group) passes.
                self.act_now.next = 3.into();
                if self.i_actuator.val() & !self.i_master.val() & !self.send_alarm.val() {
                    if self.g_data.val() & !self.nib.val().get_bit(3) {
                        self.act_now.next = 4.into();
                    }
                    if !self.g_data.val() & !self.g_s.val() {
                        self.act_now.next = 0.into();
                    }
                }
                if self.i_master.val() & self.i_slot_cfg.val().get_bit(1) & !self.send_alarm.val() {
                    self.act_now.next = 0.into();
                    if self.g_data.val() & !self.nib.val().get_bit(3) {
                        self.act_now.next = 5.into();
                    }
                    if self.g_s.val() {
                        self.act_now.next = 3.into();
                    }
                }
            }
        }
        // The fresh word (own slot): decided at its first group.
        self.n_data.next = self.f_data.q.val();
        self.n_alive.next = self.f_alive.q.val();
        self.n_alarm.next = self.f_alarm.q.val();
        if self.gidx.q.val() == 0 {
            self.n_alive.next = self.toggle.q.val();
            self.n_alarm.next = self.send_alarm.val();
            self.n_data.next = self.i_sensor_data.val();
            if self.i_actuator.val() {
                self.n_data.next = self.i_act_out.val();
            }
            if self.i_master.val() {
                self.n_data.next = self.i_slot_data.val();
                if self.i_slot_cfg.val().get_bit(1) {
                    self.n_alive.next = !self.i_slot_alive.val();
                }
            }
            if self.send_alarm.val() {
                self.n_data.next = 0.into();
                if self.i_alarm_reason.val().get_bit(0) {
                    self.n_data.next = self.n_data.val() | 0x1000;
                }
                if self.i_alarm_reason.val().get_bit(1) {
                    self.n_data.next = self.n_data.val() | 0x2000;
                }
                if self.i_alarm_reason.val().get_bit(2) {
                    self.n_data.next = self.n_data.val() | 0x4000;
                }
                if self.i_alarm_reason.val().get_bit(3) {
                    self.n_data.next = self.n_data.val() | 0x8000;
                }
            }
        }
        // Parities of the fresh word (protocol §4).
        self.p_a.next = !(self.n_alarm.val()
            ^ self.n_alive.val()
            ^ self.n_data.val().get_bit(5)
            ^ self.n_data.val().get_bit(4)
            ^ self.n_data.val().get_bit(9)
            ^ self.n_data.val().get_bit(8)
            ^ self.n_data.val().get_bit(13)
            ^ self.n_data.val().get_bit(12)
            ^ self.n_data.val().get_bit(15));
        self.p_b.next = !(self.n_alive.val()
            ^ self.n_data.val().get_bit(1)
            ^ self.n_data.val().get_bit(0)
            ^ self.n_data.val().get_bit(4)
            ^ self.n_data.val().get_bit(3)
            ^ self.n_data.val().get_bit(2)
            ^ self.n_data.val().get_bit(8)
            ^ self.n_data.val().get_bit(7)
            ^ self.n_data.val().get_bit(6)
            ^ self.n_data.val().get_bit(12)
            ^ self.n_data.val().get_bit(11)
            ^ self.n_data.val().get_bit(10)
            ^ self.n_data.val().get_bit(15)
            ^ self.n_data.val().get_bit(14));

        self.pre_b2.next = false;
        self.pre_b1.next = false;
        // The outgoing nibble, and whether the group is re-encoded.
        self.nib_out.next = self.nib.val();
        self.recode.next = false;
        if self.act_now.val() == 3 {
            self.recode.next = true;
            self.nib_out.next = self.n_data.val().get_bits::<4>(0) & 3;
            if self.n_alarm.val() {
                self.nib_out.next = self.nib_out.val() | 8;
            }
            if self.n_alive.val() {
                self.nib_out.next = self.nib_out.val() | 4;
            }
            if self.gidx.q.val() == 1 {
                self.nib_out.next = self.n_data.val().get_bits::<4>(2);
            }
            if self.gidx.q.val() == 2 {
                self.nib_out.next = self.n_data.val().get_bits::<4>(6);
            }
            if self.gidx.q.val() == 3 {
                self.nib_out.next = self.n_data.val().get_bits::<4>(10);
            }
            if self.gidx.q.val() == 4 {
                self.nib_out.next = (self.n_data.val().get_bits::<4>(12) >> 1) & 6;
                if self.p_a.val() {
                    self.nib_out.next = self.nib_out.val() | 8;
                }
                if self.p_b.val() {
                    self.nib_out.next = self.nib_out.val() | 1;
                }
            }
        }
        if self.g_data.val() & (self.act_now.val() != 0) & (self.act_now.val() != 3) {
            self.recode.next = true;
            if (self.act_now.val() == 1) & (self.gidx.q.val() == 3) {
                // FS: a node in failsafe sets it, but not in a CLR header
                // (whose FS, arriving 0, says the node leaves failsafe).
                if self.i_fs.val() & !self.clr_h0.q.val() {
                    self.nib_out.next = self.nib_out.val() | 8;
                }
                if self.i_wrapped.val() {
                    self.nib_out.next = self.nib_out.val() | 4;
                }
            }
            if (self.act_now.val() == 2) & (self.gidx.q.val() == 0) {
                self.nib_out.next = self.nib.val() + 1;
                if self.nib.val().get_bits::<2>(0) == 3 {
                    self.nib_out.next = self.nib.val() & 12;
                }
            }
            if (self.act_now.val() == 2)
                & ((self.gidx.q.val() == 1) | (self.gidx.q.val() == 2))
                & self.carry.q.val()
            {
                self.nib_out.next = self.nib.val() + 1;
            }
            if (self.act_now.val() == 2) & (self.gidx.q.val() == 3) & self.carry.q.val() {
                self.nib_out.next = self.nib.val() + 1;
                if self.nib.val().get_bits::<2>(0) == 3 {
                    self.nib_out.next = self.nib.val() & 12;
                }
            }
            if (self.act_now.val() == 4) & (self.gidx.q.val() == 0) {
                self.nib_out.next = self.nib.val() & 11;
                if self.toggle.q.val() {
                    self.nib_out.next = self.nib_out.val() | 4;
                }
            }
            // Master ACT slot: the data bits from the data memory.
            if self.act_now.val() == 5 {
                if self.gidx.q.val() == 0 {
                    self.nib_out.next =
                        (self.nib.val() & 12) | (self.n_data.val().get_bits::<4>(0) & 3);
                }
                if self.gidx.q.val() == 1 {
                    self.nib_out.next = self.n_data.val().get_bits::<4>(2);
                }
                if self.gidx.q.val() == 2 {
                    self.nib_out.next = self.n_data.val().get_bits::<4>(6);
                }
                if self.gidx.q.val() == 3 {
                    self.nib_out.next = self.n_data.val().get_bits::<4>(10);
                }
                if self.gidx.q.val() == 4 {
                    self.nib_out.next =
                        (self.nib.val() & 9) | ((self.n_data.val().get_bits::<4>(12) >> 1) & 6);
                }
            }
            // Delta parity: the changes of groups 0..3 and of this group's
            // data bits (D15, D14).
            self.pre_b2.next = self.nib.val().get_bit(2) ^ self.nib_out.val().get_bit(2);
            self.pre_b1.next = self.nib.val().get_bit(1) ^ self.nib_out.val().get_bit(1);
            if self.gidx.q.val() == 4 {
                if self.d_a.q.val() ^ self.pre_b2.val() {
                    self.nib_out.next = self.nib_out.val() ^ 8;
                }
                if self.d_b.q.val() ^ self.pre_b2.val() ^ self.pre_b1.val() {
                    self.nib_out.next = self.nib_out.val() ^ 1;
                }
            }
        }
        self.diff.next = self.nib.val() ^ self.nib_out.val();
        // The word that completes with this group arrived bad (not five
        // data groups with both parities odd, not a VOID): its last group
        // leaves as the mark T (protocol §4), unless the node wrote a fresh
        // word in its place. Not after a rejected header (`dead`: the packet
        // passes unchanged, and nobody downstream reads it).
        self.arrived_bad.next = !(self.in_data.q.val()
            & self.g_data.val()
            & (self.in_pa.q.val() ^ self.nib.val().get_bit(3) ^ self.nib.val().get_bit(2))
            & (self.in_pb.q.val()
                ^ self.nib.val().get_bit(2)
                ^ self.nib.val().get_bit(1)
                ^ self.nib.val().get_bit(0)))
            & !(self.in_s.q.val() & self.g_s.val());
        // 4B/5B encode, written out (see the decoder above).
        self.code_out.next = 0b11110.into();
        if self.nib_out.val() == 1 {
            self.code_out.next = 0b01001.into();
        }
        if self.nib_out.val() == 2 {
            self.code_out.next = 0b10100.into();
        }
        if self.nib_out.val() == 3 {
            self.code_out.next = 0b10101.into();
        }
        if self.nib_out.val() == 4 {
            self.code_out.next = 0b01010.into();
        }
        if self.nib_out.val() == 5 {
            self.code_out.next = 0b01011.into();
        }
        if self.nib_out.val() == 6 {
            self.code_out.next = 0b01110.into();
        }
        if self.nib_out.val() == 7 {
            self.code_out.next = 0b01111.into();
        }
        if self.nib_out.val() == 8 {
            self.code_out.next = 0b10010.into();
        }
        if self.nib_out.val() == 9 {
            self.code_out.next = 0b10011.into();
        }
        if self.nib_out.val() == 10 {
            self.code_out.next = 0b10110.into();
        }
        if self.nib_out.val() == 11 {
            self.code_out.next = 0b10111.into();
        }
        if self.nib_out.val() == 12 {
            self.code_out.next = 0b11010.into();
        }
        if self.nib_out.val() == 13 {
            self.code_out.next = 0b11011.into();
        }
        if self.nib_out.val() == 14 {
            self.code_out.next = 0b11100.into();
        }
        if self.nib_out.val() == 15 {
            self.code_out.next = 0b11101.into();
        }

        // Shift the bit through the one-group delay line.
        self.out_bit.next = self.delay.q.val().get_bit(4);
        self.sent.d.next = false;
        self.done.d.next = false;
        self.cut.next = false;
        self.regen.d.next = false;
        if self.i_bvalid.val() {
            self.prev.d.next = self.i_level.val();
            self.window.d.next = self.shifted.val();
            self.delay.d.next = self.delay.q.val() << 1;
            if self.code.val() | self.i_mute.val() {
                self.delay.d.next = (self.delay.q.val() << 1) | 1;
            }
            if self.inpkt.q.val() {
                if (self.bitc.q.val() == 4) & (self.group.val() == 31) & (self.idles.q.val() == 2) {
                    // The third idle group in a row: the packet was cut
                    // short upstream (as rx_word); pass the rest unchanged.
                    self.cut.next = true;
                } else if self.bitc.q.val() == 4 {
                    // A group is complete.
                    self.bitc.d.next = 0.into();
                    self.idles.d.next = 0.into();
                    if self.group.val() == 31 {
                        self.idles.d.next = self.idles.q.val() + 1;
                    }
                    if self.recode.val() {
                        self.delay.d.next = self.code_out.val();
                    }
                    if (self.gidx.q.val() == 4)
                        & self.arrived_bad.val()
                        & !self.dead.q.val()
                        & (self.action.q.val() != 3)
                    {
                        // T (merkur_model::line::CODE_T).
                        self.delay.d.next = 0b01101.into();
                    }
                    // The incoming word so far.
                    self.in_pa.d.next =
                        self.in_pa.q.val() ^ self.nib.val().get_bit(3) ^ self.nib.val().get_bit(2);
                    self.in_pb.d.next = self.in_pb.q.val()
                        ^ self.nib.val().get_bit(2)
                        ^ self.nib.val().get_bit(1)
                        ^ self.nib.val().get_bit(0);
                    self.in_data.d.next = self.in_data.q.val() & self.g_data.val();
                    self.in_s.d.next = self.in_s.q.val() & self.g_s.val();
                    if self.gidx.q.val() == 0 {
                        self.in_pa.d.next = self.nib.val().get_bit(3) ^ self.nib.val().get_bit(2);
                        self.in_pb.d.next = self.nib.val().get_bit(2)
                            ^ self.nib.val().get_bit(1)
                            ^ self.nib.val().get_bit(0);
                        self.in_data.d.next = self.g_data.val();
                        self.in_s.d.next = self.g_s.val();
                        if self.wcount.q.val() == 0 {
                            self.clr_h0.d.next = self.nib.val().get_bit(2);
                        }
                    }
                    if self.gidx.q.val() == 0 {
                        self.action.d.next = self.act_now.val();
                        self.d_a.d.next = false;
                        self.d_b.d.next = false;
                        self.carry.d.next = false;
                        self.f_data.d.next = self.n_data.val();
                        self.f_alive.d.next = self.n_alive.val();
                        self.f_alarm.d.next = self.n_alarm.val();
                        self.regen.d.next = self.own.val()
                            & self.i_master.val()
                            & self.i_slot_cfg.val().get_bit(1)
                            & (self.act_now.val() == 3);
                        if self.home.val() {
                            self.prev_alarm.d.next = self.send_alarm.val();
                            self.sent.d.next = self.send_alarm.val();
                            self.sent_reason.d.next = self.i_alarm_reason.val();
                        }
                    }
                    self.d_a.d.next =
                        self.d_a.q.val() ^ self.diff.val().get_bit(3) ^ self.diff.val().get_bit(2);
                    self.d_b.d.next = self.d_b.q.val()
                        ^ self.diff.val().get_bit(2)
                        ^ self.diff.val().get_bit(1)
                        ^ self.diff.val().get_bit(0);
                    if self.gidx.q.val() == 0 {
                        self.d_a.d.next = self.diff.val().get_bit(3) ^ self.diff.val().get_bit(2);
                        self.d_b.d.next = self.diff.val().get_bit(2)
                            ^ self.diff.val().get_bit(1)
                            ^ self.diff.val().get_bit(0);
                        self.carry.d.next = self.nib.val().get_bits::<2>(0) == 3;
                    } else {
                        self.carry.d.next = self.carry.q.val() & (self.nib.val() == 15);
                    }
                    self.gidx.d.next = self.gidx.q.val() + 1;
                    if self.gidx.q.val() == 4 {
                        // A word is complete.
                        self.gidx.d.next = 0.into();
                        if self.wcount.q.val() == 2 {
                            self.slot.d.next = self.slot.q.val() + 1;
                            if self.slot.q.val() == self.i_slots_m1.val() {
                                self.inpkt.d.next = false;
                                if !self.dead.q.val() {
                                    self.done.d.next = true;
                                    self.toggle.d.next = !self.toggle.q.val();
                                }
                            }
                        } else {
                            self.wcount.d.next = self.wcount.q.val() + 1;
                        }
                    }
                } else {
                    self.bitc.d.next = self.bitc.q.val() + 1;
                }
            } else if self.shifted.val() == self.jk.val() {
                self.inpkt.d.next = true;
                self.bitc.d.next = 0.into();
                self.gidx.d.next = 0.into();
                self.wcount.d.next = 0.into();
                self.slot.d.next = 0.into();
                self.dead.d.next = false;
                self.idles.d.next = 0.into();
            }
        }
        // Out on the node's own timing.
        self.out.clock.next = self.clock.val();
        self.out.i_valid.next = self.i_bvalid.val();
        self.out.i_code.next = self.out_bit.val();
        self.out.i_phase.next = self.i_phase.val();
        // INPUT went dead (no bit for DEAD_CLOCKS: the CDR takes none from
        // a line without edges): the packet is over, and the group delay
        // line is refilled with idles, so that no stale bits go out when
        // bits come again (from another port after a wrap).
        if self.i_bvalid.val() {
            self.quiet.d.next = 0.into();
        } else if self.quiet.q.val() != 15 {
            self.quiet.d.next = self.quiet.q.val() + 1;
        }
        if self.quiet.q.val() == self.dead_after.val() {
            self.delay.d.next = 31.into();
            self.cut.next = true;
        }
        // A packet cut short ends here; a frame whose header was processed
        // still counts (the Alive flip-flop toggles, as at its end).
        if self.cut.val() {
            self.inpkt.d.next = false;
            self.idles.d.next = 0.into();
            if self.inpkt.q.val() & (self.wcount.q.val() == 2) & !self.dead.q.val() {
                self.done.d.next = true;
                self.toggle.d.next = !self.toggle.q.val();
            }
        }
        if self.i_hdr_bad.val() {
            self.dead.d.next = true;
        }
        self.o_slot.next = self.slot.q.val();
        self.o_regen.next = self.regen.q.val();
        self.o_alarm_sent.next = self.sent.q.val();
        self.o_sent_reason.next = self.sent_reason.q.val();
        self.o_pkt_done.next = self.done.q.val();
        self.o_toggle.next = self.toggle.q.val();
        self.o_line.next = self.out.o_line.val();
    }
}
