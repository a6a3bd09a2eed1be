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
//! row end a packet that was cut short upstream (as [`crate::line::word_rx`]), and
//! so does a dead INPUT (no bit for [`DEAD_CLOCKS`]: the clock recovery
//! muted), which also refills the
//! group delay with idles. A frame whose header was processed toggles the
//! Alive flip-flop even when it was cut short. The Alive flip-flop
//! toggles after each processed DATA packet. Alarms: `i_alarm_req` with
//! `i_alarm_reason` and `i_alarm_seq` is sent in the home slot if the previous
//! cycle's home word was data (alternation); `o_alarm_sent` pulses when it
//! goes out.
//! The output bits go through a [`Retime`] buffer and out on the node's own
//! clock (DDR pair), so the receiver's sampling error is not passed on.
//!
//! Retransmission on demand (protocol §8): a good H0 of type 11 on the
//! input port's word bus (`i_wvalid` …) makes the packet an RTX. Its H0 is
//! treated as a frame's (FS and RWC are already 1 there, so nothing
//! changes), H1 passes unchanged, and the request words pass on, marked
//! when they arrive bad; the packet ends at the third idle group. A data
//! word whose good index word named the home slot is written: a
//! **sensor** (armed, not in failsafe) writes `{its current sample, the
//! Alive it wrote into this cycle's frame}` over whatever the word brings; an
//! **actuator** puts that Alive into a data word (its master's copy). A
//! node that wrote into the RTX without having processed the cycle's
//! frame (the last header before it was not an RTX's and no frame ended
//! since) toggles its Alive flip-flop at the RTX's end, as the frame
//! would have. In a **master** (`i_master`) `o_slot` shows the requested
//! slot, and a data word whose slot its data block writes (`i_slot_cfg`
//! 1 or 2) is written `{i_slot_data, its Alive there}` (an ACT slot: the
//! actuator's last Alive, `i_slot_alive`).
//!
//! Parameters: the word format ([`WordFormat`], as [`crate::line::word_rx`]).
//! In the extended-alarm variant (protocol §6) every word has a sixth group,
//! N1 = `{SEQ, REASON[2:0]}`, after the first: the forwarder passes it on
//! (headers, data, a master's ACT slot), writes it in a fresh word (the
//! alarm's SEQ and reason, 0 in a data word) and clears it with the ALARM
//! bit when an actuator rewrites its slot; an alarm keeps the data bits
//! (the sender's value), and an actuator or a master takes an alarm word's
//! data as it takes a data word's. Data and HOP groups move one group on;
//! FS and RWC are in H0's fifth group.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_bvalid`, `i_code`, `i_phase` | in | 1, 1, 2 | clock | recovered INPUT bits, NRZI-decoded (from [`crate::node::port_rx`]) |
//! | `i_hdr_bad` | in | 1 | clock | header rejected, or not a DATA packet: pass the rest unchanged |
//! | `i_mute` | in | 1 | clock | send idles for the code bits arriving from now on (a TST's rest) |
//! | `i_slots_m1`, `i_address` | in | 12 | static | slot count − 1, home slot |
//! | `i_actuator` | in | 1 | static | 1 actuator, 0 sensor |
//! | `i_sensor_data` | in | 16 | clock | sensor value (sampled at its slot) |
//! | `i_act_out` | in | 16 | clock | actuator output register |
//! | `i_fs`, `i_wrapped` | in | 1 | clock | node in failsafe / wrapped |
//! | `i_alarm_req`, `i_alarm_reason`, `i_alarm_seq` | in | 1, 4, 1 | clock | alarm to send, its reason and SEQ (basic: `D[15:12]`, `D[11]`; extended: N1) |
//! | `i_master` | in | 1 | static | master mode: per-slot writes from `i_slot_cfg` |
//! | `i_slot_cfg`, `i_slot_data`, `i_slot_alive` | in | 2, 16, 1 | clock | master: what it writes in slot `o_slot` (0 nothing, 1 LOCAL, 2 ACT, 3 its home slot without a value: only an alarm, protocol §12), data memory and actuator Alive of that slot, valid by the word's first group |
//! | `i_armed` | in | 1 | clock | the node has processed a good header (it may fill RTX requests) |
//! | `i_wvalid`, `i_wkind`, `i_wodd`, `i_wok`, `i_walarm`, `i_wdata`, `i_ptype` | in | 1, 2, 1, 1, 1, 16, 2 | clock | INPUT's words from the receive port ([`crate::line::word_rx`]: `i_wodd` is `o_slot`'s bit 0, an RTX data word) |
//! | `o_slot` | out | 12 | clock | slot of the word passing (in an RTX: the slot its request names) |
//! | `o_rtx_own` | out | 1 | clock | the RTX request passing names the home slot (from its good index word to the next index word) |
//! | `o_rtx_idx`, `o_rtx_ok` | out | 12, 1 | clock | the slot that request names, and whether its index word was good |
//! | `o_regen` | out | 1 | clock | master: an ACT slot's VOID was regenerated |
//! | `o_alarm_sent`, `o_sent_reason` | out | 1, 4 | clock | the alarm went out, and which |
//! | `o_prev_alarm` | out | 1 | clock | the last home-slot word sent was an alarm (so the next must be data) |
//! | `o_pkt_done` | out | 1 | clock | a DATA packet's last slot went through |
//! | `o_toggle` | out | 1 | clock | the Alive flip-flop |
//! | `o_line` | out | 2 | clock | OUTPUT line, DDR pair (bit 0 first) |
//!
//! Pipeline (issue 20: every stage a few levels of logic at 2 × the line
//! rate): stage A decodes a group in the clock its last bit arrives (and
//! the action of a word's first group); stage B, the next clock, decides
//! the rewrite from registers (the word flags and the fresh word are
//! prepared a clock ahead, `pre_*`, `f_*`; a fresh word's parities, like a
//! rewritten word's, come from the incoming word's and the changes made);
//! stage C, the clock after, encodes it into the delay line and sums the
//! delta parity.
//!
//! Latency: 6 bit times (one group and one bit, so that stage C's rewrite
//! is in place before the group's first bit leaves) from INPUT bit to the
//! retime buffer, which sends it 2.5 ± 0.5 bit times after its receive
//! clock; with the CDR 9.5–10.5 bit times from the node's input samples
//! to its output line, 10–11 from fibre to fibre with the top's capture
//! register (measured at the fibres, docs/benchmarks.md).
//!
//! ```text
//! in code   | N0 | N1 | N2 | N3 | N4 | ...
//! out code       | N0'| N1'| N2'| N3'| N4'|        N0 decides, N4' fixes the parities
//! ```
//!
//! (Extended variant: six groups, the last one N5'.)

use crate::line::retime::{Layout, Retime};
use crate::line::word_rx::WordFormat;
use rust_hdl::prelude::*;

/// Clocks without a recovered bit after which INPUT counts as dead (3 bit
/// times; a live line gives a bit every 2 clocks, 3 at most): shorter
/// than the gap a switchbox change leaves after a receiver muted (12 dark
/// bit times, [`crate::node::sw_dark`], less the 8 of the mute), and than the one
/// an upstream node whose input stopped leaves ([`crate::line::retime::QUIET_BITS`]
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
    /// Its code bit (1: the line level changed).
    pub i_code: Signal<In, Bit>,
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
    /// The alarm's SEQ bit (`D[11]`, protocol §11).
    pub i_alarm_seq: Signal<In, Bit>,
    /// Master node: the slot's writer is decided by `i_slot_cfg`.
    pub i_master: Signal<In, Bit>,
    /// Configuration of slot `o_slot` (bit 0 LOCAL, bit 1 ACT).
    pub i_slot_cfg: Signal<In, Bits<2>>,
    /// Data memory of slot `o_slot`.
    pub i_slot_data: Signal<In, Bits<16>>,
    /// Last actuator Alive seen in slot `o_slot` (ACT slots).
    pub i_slot_alive: Signal<In, Bit>,
    /// The node is armed (has processed a good header): it may fill
    /// retransmission requests (protocol §8).
    pub i_armed: Signal<In, Bit>,
    /// INPUT's words, from the receive port ([`crate::line::word_rx`]): a
    /// word is complete.
    pub i_wvalid: Signal<In, Bit>,
    /// Its kind (0 H0, 1 H1, 2 slot, 3 RTX request word).
    pub i_wkind: Signal<In, Bits<2>>,
    /// An RTX request word is a data word (odd number), not an index word.
    pub i_wodd: Signal<In, Bit>,
    /// The word is good.
    pub i_wok: Signal<In, Bit>,
    /// Its ALARM bit.
    pub i_walarm: Signal<In, Bit>,
    /// Its data.
    pub i_wdata: Signal<In, Bits<16>>,
    /// The packet's type (from a good H0).
    pub i_ptype: Signal<In, Bits<2>>,
    /// Slot number of the word now passing (for the memory look-ups).
    pub o_slot: Signal<Out, Bits<12>>,
    /// The RTX request being passed names the home slot (from its good
    /// index word until the next index word).
    pub o_rtx_own: Signal<Out, Bit>,
    /// The slot the RTX request being passed names, and whether its index
    /// word was good (same timing).
    pub o_rtx_idx: Signal<Out, Bits<12>>,
    /// See `o_rtx_idx`.
    pub o_rtx_ok: Signal<Out, Bit>,
    /// A VOID in an ACT slot was regenerated (the Alive flips).
    pub o_regen: Signal<Out, Bit>,
    /// Alarm sent.
    pub o_alarm_sent: Signal<Out, Bit>,
    /// The reason of the alarm sent (valid with `o_alarm_sent`).
    pub o_sent_reason: Signal<Out, Bits<4>>,
    /// The last home-slot word sent carried an alarm (alternation state).
    pub o_prev_alarm: Signal<Out, Bit>,
    /// DATA packet done.
    pub o_pkt_done: Signal<Out, Bit>,
    /// Alive flip-flop.
    pub o_toggle: Signal<Out, Bit>,
    /// Output line (DDR pair).
    pub o_line: Signal<Out, Bits<2>>,
    jk: Constant<Bits<10>>,
    dead_after: Constant<Bits<4>>,
    // Extended-alarm words (six groups, N1 the reason nibble).
    ext: Constant<Bit>,
    // Retransmission on demand is built in (see [`Fwd::with_rtx`]).
    rtx_on: Constant<Bit>,
    window: DFF<Bits<10>>,
    delay: DFF<Bits<6>>,
    // Stage B → C: the group as it leaves (`c_nib`, written when
    // `c_write`, or the mark T when `c_mark`), as it came (`c_orig`), the
    // word's first group (`c_first`), a bit arrived in stage B (`c_shift`).
    c_pend: DFF<Bit>,
    c_nib: DFF<Bits<4>>,
    c_orig: DFF<Bits<4>>,
    c_write: DFF<Bit>,
    c_mark: DFF<Bit>,
    c_first: DFF<Bit>,
    c_shift: DFF<Bit>,
    // The group that completed in the clock before, decoded (stage A → B).
    g_pend: DFF<Bit>,
    g_cut: DFF<Bit>,
    g_nib: DFF<Bits<4>>,
    g_dat: DFF<Bit>,
    g_sym_s: DFF<Bit>,
    g_act: DFF<Bits<3>>,
    inpkt: DFF<Bit>,
    idles: DFF<Bits<2>>,
    quiet: DFF<Bits<4>>,
    bitc: DFF<Bits<3>>,
    gidx: DFF<Bits<3>>,
    wcount: DFF<Bits<2>>,
    slot: DFF<Bits<12>>,
    /// The slot counter steps (`slot_inc`) or clears (`slot_clr`) a clock
    /// after the stage that decides it, from these registers (issue 21,
    /// as [`crate::line::word_rx`]'s).
    slot_inc: DFF<Bit>,
    slot_clr: DFF<Bit>,
    dead: DFF<Bit>,
    action: DFF<Bits<3>>,
    // Retransmission on demand (protocol §8): the packet is an RTX; the
    // slot its last index word named, and whether that word was good and
    // named a slot; a frame was processed since the last header that was
    // not an RTX's (the node toggled its Alive for this cycle); the node
    // wrote into this RTX; the last index word was good and named the home
    // slot.
    rtx: DFF<Bit>,
    idx: DFF<Bits<12>>,
    idx_ok: DFF<Bit>,
    framed: DFF<Bit>,
    rtx_wrote: DFF<Bit>,
    idx_own: DFF<Bit>,
    // The incoming word so far (for the mark, and a fresh word's
    // parities): parities, all data, all S.
    in_pa: DFF<Bit>,
    in_pb: DFF<Bit>,
    in_data: DFF<Bit>,
    in_s: DFF<Bit>,
    // H0 carries CLR (its ALIVE bit).
    clr_h0: DFF<Bit>,
    // The changes made to the word so far (delta parity).
    d_a: DFF<Bit>,
    d_b: DFF<Bit>,
    carry: DFF<Bit>,
    f_data: DFF<Bits<16>>,
    f_alive: DFF<Bit>,
    f_alarm: DFF<Bit>,
    f_reason: DFF<Bits<4>>,
    // The fresh word's N1 (extended variant): {SEQ, REASON[2:0]} or 0.
    f_rn: DFF<Bits<4>>,
    /// The f_* registers hold (`f_hold`): set in every clock in which a
    /// word is under way in stage B (`gidx` not 0) or a group is pending
    /// for it (`g_pend`), from those registers' next values, so that each
    /// f_* bit's load and hold read one register instead of the four
    /// (issue 21; proved exact, rtl/formal/fwd.sv).
    f_hold: DFF<Bit>,
    pre_home: DFF<Bit>,
    at_home: DFF<Bit>,
    fs_r: DFF<Bit>,
    wr_r: DFF<Bit>,
    pre_own: DFF<Bit>,
    toggle: DFF<Bit>,
    prev_alarm: DFF<Bit>,
    out: Retime,
    sent: DFF<Bit>,
    sent_reason: DFF<Bits<4>>,
    done: DFF<Bit>,
    regen: DFF<Bit>,
    shifted: Signal<Local, Bits<10>>,
    group: Signal<Local, Bits<5>>,
    dec_nib: Signal<Local, Bits<4>>,
    dec_data: Signal<Local, Bit>,
    dec_s: Signal<Local, Bit>,
    nib: Signal<Local, Bits<4>>,
    g_data: Signal<Local, Bit>,
    g_s: Signal<Local, Bit>,
    code_w: Signal<Local, Bits<5>>,
    code_w6: Signal<Local, Bits<6>>,
    in_code: Signal<Local, Bit>,
    code_out: Signal<Local, Bits<5>>,
    act_now: Signal<Local, Bits<3>>,
    act_c: Signal<Local, Bits<3>>,
    nib_out: Signal<Local, Bits<4>>,
    recode: Signal<Local, Bit>,
    diff: Signal<Local, Bits<4>>,
    home_c: Signal<Local, Bit>,
    own_c: Signal<Local, Bit>,
    rtx_own_c: Signal<Local, Bit>,
    addr16: Signal<Local, Bits<16>>,
    alive_now: Signal<Local, Bit>,
    send_c: Signal<Local, Bit>,
    fresh_data: Signal<Local, Bits<16>>,
    fresh_alive: Signal<Local, Bit>,
    fresh_rn: Signal<Local, Bits<4>>,
    // The data group a group is (0..4, the last one 4 in both formats; 7
    // the extended variant's reason nibble N1).
    dg: Signal<Local, Bits<3>>,
    cut: Signal<Local, Bit>,
    pa_fix: Signal<Local, Bit>,
    pb_fix: Signal<Local, Bit>,
    inc2: Signal<Local, Bits<4>>,
    inc4: Signal<Local, Bits<4>>,
    out_bit: Signal<Local, Bit>,
    arrived_bad: Signal<Local, Bit>,
}

impl Default for Fwd {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl Fwd {
    /// A forwarder of words in `format`, with retransmission on demand.
    pub fn new(format: WordFormat) -> Self {
        Self::with_rtx(format, true)
    }

    /// A forwarder of words in `format`; without retransmission on demand
    /// (`rtx` false: a ring without critical slots) an RTX's words are
    /// never processed, and synthesis drops that logic.
    pub fn with_rtx(format: WordFormat, rtx: bool) -> Self {
        Self {
            clock: Default::default(),
            i_bvalid: Default::default(),
            i_code: Default::default(),
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
            i_alarm_seq: Default::default(),
            i_master: Default::default(),
            i_slot_cfg: Default::default(),
            i_slot_data: Default::default(),
            i_slot_alive: Default::default(),
            i_armed: Default::default(),
            i_wvalid: Default::default(),
            i_wkind: Default::default(),
            i_wodd: Default::default(),
            i_wok: Default::default(),
            i_walarm: Default::default(),
            i_wdata: Default::default(),
            i_ptype: Default::default(),
            o_rtx_own: Default::default(),
            o_rtx_idx: Default::default(),
            o_rtx_ok: Default::default(),
            o_slot: Default::default(),
            o_regen: Default::default(),
            o_alarm_sent: Default::default(),
            o_sent_reason: Default::default(),
            o_prev_alarm: Default::default(),
            o_pkt_done: Default::default(),
            o_toggle: Default::default(),
            o_line: Default::default(),
            jk: Constant::new(crate::line::framer_rx::JK_BITS.to_bits()),
            dead_after: Constant::new(DEAD_CLOCKS.to_bits()),
            ext: Constant::new(format == WordFormat::ExtendedAlarm),
            rtx_on: Constant::new(rtx),
            window: Default::default(),
            delay: Default::default(),
            c_pend: Default::default(),
            c_nib: Default::default(),
            c_orig: Default::default(),
            c_write: Default::default(),
            c_mark: Default::default(),
            c_first: Default::default(),
            c_shift: Default::default(),
            g_pend: Default::default(),
            g_cut: Default::default(),
            g_nib: Default::default(),
            g_dat: Default::default(),
            g_sym_s: Default::default(),
            g_act: Default::default(),
            inpkt: Default::default(),
            idles: Default::default(),
            quiet: Default::default(),
            bitc: Default::default(),
            gidx: Default::default(),
            wcount: Default::default(),
            slot: Default::default(),
            slot_inc: Default::default(),
            slot_clr: Default::default(),
            dead: Default::default(),
            action: Default::default(),
            rtx: Default::default(),
            idx: Default::default(),
            idx_ok: Default::default(),
            framed: Default::default(),
            rtx_wrote: Default::default(),
            idx_own: Default::default(),
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
            f_reason: Default::default(),
            f_rn: Default::default(),
            f_hold: Default::default(),
            pre_home: Default::default(),
            at_home: Default::default(),
            fs_r: Default::default(),
            wr_r: Default::default(),
            pre_own: Default::default(),
            toggle: Default::default(),
            prev_alarm: Default::default(),
            out: Default::default(),
            sent: Default::default(),
            sent_reason: Default::default(),
            done: Default::default(),
            regen: Default::default(),
            shifted: Default::default(),
            group: Default::default(),
            dec_nib: Default::default(),
            dec_data: Default::default(),
            dec_s: Default::default(),
            nib: Default::default(),
            g_data: Default::default(),
            g_s: Default::default(),
            code_w: Default::default(),
            code_w6: Default::default(),
            in_code: Default::default(),
            code_out: Default::default(),
            act_now: Default::default(),
            act_c: Default::default(),
            nib_out: Default::default(),
            recode: Default::default(),
            diff: Default::default(),
            home_c: Default::default(),
            own_c: Default::default(),
            rtx_own_c: Default::default(),
            addr16: Default::default(),
            alive_now: Default::default(),
            send_c: Default::default(),
            fresh_data: Default::default(),
            fresh_alive: Default::default(),
            fresh_rn: Default::default(),
            dg: Default::default(),
            cut: Default::default(),
            pa_fix: Default::default(),
            pb_fix: Default::default(),
            inc2: Default::default(),
            inc4: Default::default(),
            out_bit: Default::default(),
            arrived_bad: Default::default(),
        }
    }

    /// The same forwarder with its output buffer in `layout` (see
    /// [`Layout`]: the same behaviour; [`Layout::WriteShifts`] for
    /// product-term devices).
    pub fn with_layout(mut self, layout: Layout) -> Self {
        self.out = Retime::new(layout);
        self
    }
}

impl Logic for Fwd {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            window,
            delay,
            c_pend,
            c_nib,
            c_orig,
            c_write,
            c_mark,
            c_first,
            c_shift,
            g_pend,
            g_cut,
            g_nib,
            g_dat,
            g_sym_s,
            g_act,
            inpkt,
            idles,
            quiet,
            bitc,
            gidx,
            wcount,
            slot,
            slot_inc,
            slot_clr,
            dead,
            action,
            rtx,
            idx,
            idx_ok,
            framed,
            rtx_wrote,
            idx_own,
            d_a,
            d_b,
            carry,
            f_data,
            f_alive,
            f_alarm,
            f_reason,
            f_rn,
            f_hold,
            pre_home,
            at_home,
            fs_r,
            wr_r,
            pre_own,
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
        // The group that completes with this bit.
        self.shifted.next = self.window.q.val() << 1;
        if self.i_code.val() {
            self.shifted.next = (self.window.q.val() << 1) | 1;
        }
        self.group.next = self.shifted.val().get_bits::<5>(0);
        // 4B/5B decode, written out: a ROM instance here would be read in the
        // same always block that addresses it, which Verilator cannot order.
        self.dec_nib.next = 0.into();
        self.dec_data.next = false;
        if self.group.val() == 0b11110 {
            self.dec_nib.next = 0.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b01001 {
            self.dec_nib.next = 1.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10100 {
            self.dec_nib.next = 2.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10101 {
            self.dec_nib.next = 3.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b01010 {
            self.dec_nib.next = 4.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b01011 {
            self.dec_nib.next = 5.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b01110 {
            self.dec_nib.next = 6.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b01111 {
            self.dec_nib.next = 7.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10010 {
            self.dec_nib.next = 8.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10011 {
            self.dec_nib.next = 9.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10110 {
            self.dec_nib.next = 10.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b10111 {
            self.dec_nib.next = 11.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b11010 {
            self.dec_nib.next = 12.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b11011 {
            self.dec_nib.next = 13.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b11100 {
            self.dec_nib.next = 14.into();
            self.dec_data.next = true;
        }
        if self.group.val() == 0b11101 {
            self.dec_nib.next = 15.into();
            self.dec_data.next = true;
        }
        self.dec_s.next = self.group.val() == 0b11001;
        // Stage B works on the group stage A registered (issue 20: the
        // group's decode and its rewrite are a clock apart).
        self.nib.next = self.g_nib.q.val();
        self.g_data.next = self.g_dat.q.val();
        self.g_s.next = self.g_sym_s.q.val();
        self.dg.next = self.gidx.q.val();
        if self.ext.val() & (self.gidx.q.val() != 0) {
            self.dg.next = self.gidx.q.val() - 1;
            if self.gidx.q.val() == 1 {
                self.dg.next = 7.into();
            }
        }

        // What to do with the word that starts with this group. A slave
        // writes its home slot; a master every slot its configuration marks
        // LOCAL or ACT (its home slot is one of its LOCAL slots).
        // The node's failsafe and wrap, registered here (issue 20: they come
        // from the far side of the node; a header shows them a clock later).
        self.fs_r.d.next = self.i_fs.val();
        self.wr_r.d.next = self.i_wrapped.val();
        // Decided a clock ahead, from the word counters (issue 20: stage B
        // reads registers): whether the next word is the node's.
        // The slot comparison is registered (`at_home`): the counters it
        // reads settle two clocks after a word completes, ten or more
        // before the next word's first group reads what it decides
        // (issue 21: the HX1K's longest path, and a 12-literal product in
        // every fresh-word bit on a CoolRunner-II).
        self.at_home.d.next =
            (self.wcount.q.val() == 2) & (self.slot.q.val() == self.i_address.val());
        self.home_c.next =
            self.at_home.q.val() & !self.rtx.q.val() & !self.dead.q.val() & !self.fs_r.q.val();
        // An RTX's data word whose index word named a slot the node writes:
        // its home slot; in a master, a slot its data block writes (LOCAL or
        // ACT with a value, `i_slot_cfg` read at the requested slot).
        self.rtx_own_c.next = self.rtx.q.val()
            & (self.wcount.q.val() == 2)
            & self.slot.q.val().get_bit(0)
            & self.idx_own.q.val()
            & !self.i_master.val()
            & !self.dead.q.val()
            & !self.fs_r.q.val();
        if self.i_master.val() {
            self.rtx_own_c.next = self.rtx.q.val()
                & (self.wcount.q.val() == 2)
                & self.slot.q.val().get_bit(0)
                & self.idx_ok.q.val()
                & ((self.i_slot_cfg.val() == 1) | (self.i_slot_cfg.val() == 2))
                & !self.dead.q.val()
                & !self.fs_r.q.val();
        }
        // The Alive bit the node wrote in this cycle's frame: the
        // flip-flop toggled at the frame's end when it processed it.
        self.alive_now.next = self.toggle.q.val() ^ (self.rtx.q.val() & self.framed.q.val());
        // An alarm goes in the home slot when the node writes it (a master:
        // when its configuration lets it, `i_slot_cfg` not 0).
        self.send_c.next = self.home_c.val()
            & self.i_alarm_req.val()
            & !self.prev_alarm.q.val()
            & (!self.i_master.val() | (self.i_slot_cfg.val() != 0));
        self.own_c.next = self.home_c.val();
        if self.i_master.val() {
            // 3: a home slot without a value (protocol §12): only an alarm.
            self.own_c.next = (self.wcount.q.val() == 2)
                & !self.rtx.q.val()
                & (self.i_slot_cfg.val() != 0)
                & ((self.i_slot_cfg.val() != 3) | self.send_c.val())
                & !self.dead.q.val()
                & !self.fs_r.q.val();
        }
        self.pre_home.d.next = self.home_c.val();
        self.pre_own.d.next = self.own_c.val();
        // The word's action, decided in stage A from the group as it
        // completes (its first group decides; the others keep `action`),
        // registered for stage B (`act_now`).
        self.act_c.next = self.action.q.val();
        if self.gidx.q.val() == 0 {
            self.act_c.next = 0.into();
            if !self.dead.q.val() {
                if self.wcount.q.val() == 0 {
                    self.act_c.next = 1.into();
                }
                if (self.wcount.q.val() == 1) & !self.rtx.q.val() {
                    self.act_c.next = 2.into();
                }
            }
            if self.own_c.val() {
                // Sensor, LOCAL slot: always fresh. Actuator (from the first
                // group): its alarm, VOID (S) or an alarm coming back ->
                // fresh; data -> replace ALIVE; anything else -> leaves bad.
                // Master, ACT slot: data -> replace the data, keep ALIVE;
                // VOID -> fresh with the Alive the actuator would send;
                // anything else (an alarm, an invalid group) passes.
                self.act_c.next = 3.into();
                // (Extended variant: an alarm word carries data, so the
                // same as a data word.)
                if self.i_actuator.val() & !self.i_master.val() & !self.send_c.val() {
                    if self.dec_data.val() & (!self.dec_nib.val().get_bit(3) | self.ext.val()) {
                        self.act_c.next = 4.into();
                    }
                    if !self.dec_data.val() & !self.dec_s.val() {
                        self.act_c.next = 0.into();
                    }
                }
                if self.i_master.val() & (self.i_slot_cfg.val() == 2) & !self.send_c.val() {
                    self.act_c.next = 0.into();
                    if self.dec_data.val() & (!self.dec_nib.val().get_bit(3) | self.ext.val()) {
                        self.act_c.next = 5.into();
                    }
                    if self.dec_s.val() {
                        self.act_c.next = 3.into();
                    }
                }
            }
            // An RTX request for the home slot (protocol §8): a sensor,
            // armed, fills the data word with the word it wrote into the
            // frame; an actuator puts its Alive into a data word (the copy
            // its master filled).
            if self.rtx_own_c.val() {
                if (!self.i_actuator.val() | self.i_master.val()) & self.i_armed.val() {
                    self.act_c.next = 3.into();
                }
                if self.i_actuator.val()
                    & !self.i_master.val()
                    & self.dec_data.val()
                    & (!self.dec_nib.val().get_bit(3) | self.ext.val())
                {
                    self.act_c.next = 4.into();
                }
            }
        }
        self.act_now.next = self.g_act.q.val();
        // The fresh word (own slot, protocol §4): the f_* registers follow
        // it between words and hold it from the word's first group to its
        // last (stage B reads registers, issue 20).
        self.fresh_alive.next = self.toggle.q.val();
        self.fresh_data.next = self.i_sensor_data.val();
        if self.i_actuator.val() {
            self.fresh_data.next = self.i_act_out.val();
        }
        if self.i_master.val() {
            self.fresh_data.next = self.i_slot_data.val();
            if self.i_slot_cfg.val() == 2 {
                self.fresh_alive.next = !self.i_slot_alive.val();
            }
        }
        // An RTX fill: a sensor's current sample (protocol §8), with the
        // Alive it wrote into the frame (or would have, had it missed it).
        // A master: its data memory, and for an ACT slot the actuator's
        // Alive as it last saw it.
        if self.rtx.q.val() {
            self.fresh_alive.next = self.alive_now.val();
            if self.i_master.val() & (self.i_slot_cfg.val() == 2) {
                self.fresh_alive.next = self.i_slot_alive.val();
            }
        }
        self.fresh_rn.next = 0.into();
        if self.send_c.val() & self.ext.val() {
            self.fresh_rn.next = self.i_alarm_reason.val() & 7;
            if self.i_alarm_seq.val() {
                self.fresh_rn.next = self.fresh_rn.val() | 8;
            }
        }
        if self.send_c.val() & !self.ext.val() {
            self.fresh_data.next = 0.into();
            if self.i_alarm_reason.val().get_bit(0) {
                self.fresh_data.next = self.fresh_data.val() | 0x1000;
            }
            if self.i_alarm_reason.val().get_bit(1) {
                self.fresh_data.next = self.fresh_data.val() | 0x2000;
            }
            if self.i_alarm_reason.val().get_bit(2) {
                self.fresh_data.next = self.fresh_data.val() | 0x4000;
            }
            if self.i_alarm_reason.val().get_bit(3) {
                self.fresh_data.next = self.fresh_data.val() | 0x8000;
            }
            if self.i_alarm_seq.val() {
                self.fresh_data.next = self.fresh_data.val() | 0x0800;
            }
        }
        if !self.f_hold.q.val() {
            self.f_data.d.next = self.fresh_data.val();
            self.f_alive.d.next = self.fresh_alive.val();
            self.f_alarm.d.next = self.send_c.val();
            self.f_reason.d.next = self.i_alarm_reason.val();
            self.f_rn.d.next = self.fresh_rn.val();
        }

        self.pa_fix.next = false;
        self.pb_fix.next = false;
        self.inc2.next = self.nib.val() ^ 1;
        if self.nib.val().get_bit(0) {
            self.inc2.next = self.nib.val() ^ 3;
        }
        self.inc4.next = self.inc2.val();
        if self.nib.val().get_bits::<2>(0) == 3 {
            self.inc4.next = self.nib.val() ^ 7;
            if self.nib.val().get_bit(2) {
                self.inc4.next = self.nib.val() ^ 15;
            }
        }
        // The outgoing nibble, and whether the group is re-encoded.
        self.nib_out.next = self.nib.val();
        self.recode.next = false;
        if self.act_now.val() == 3 {
            self.recode.next = true;
            self.nib_out.next = self.f_data.q.val().get_bits::<4>(0) & 3;
            if self.f_alarm.q.val() {
                self.nib_out.next = self.nib_out.val() | 8;
            }
            if self.f_alive.q.val() {
                self.nib_out.next = self.nib_out.val() | 4;
            }
            if self.dg.val() == 7 {
                self.nib_out.next = self.f_rn.q.val();
            }
            if self.dg.val() == 1 {
                self.nib_out.next = self.f_data.q.val().get_bits::<4>(2);
            }
            if self.dg.val() == 2 {
                self.nib_out.next = self.f_data.q.val().get_bits::<4>(6);
            }
            if self.dg.val() == 3 {
                self.nib_out.next = self.f_data.q.val().get_bits::<4>(10);
            }
            if self.dg.val() == 4 {
                // The parities (protocol §4: odd), over the groups
                // before as they left: as they came (`in_pa`, `in_pb`)
                // changed by what the node wrote (`d_a`, `d_b`), as a
                // rewritten word's delta parity (issue 21: no parity tree
                // over the fresh word in front of a register).
                self.nib_out.next = (self.f_data.q.val().get_bits::<4>(12) >> 1) & 6;
                if !(self.in_pa.q.val() ^ self.d_a.q.val() ^ self.f_data.q.val().get_bit(15)) {
                    self.nib_out.next = self.nib_out.val() | 8;
                }
                if !(self.in_pb.q.val()
                    ^ self.d_b.q.val()
                    ^ self.f_data.q.val().get_bit(15)
                    ^ self.f_data.q.val().get_bit(14))
                {
                    self.nib_out.next = self.nib_out.val() | 1;
                }
            }
        }
        if self.g_data.val() & (self.act_now.val() != 0) & (self.act_now.val() != 3) {
            self.recode.next = true;
            if (self.act_now.val() == 1) & (self.dg.val() == 3) {
                // FS: a node in failsafe sets it, but not in a CLR header
                // (whose FS, arriving 0, says the node leaves failsafe).
                if self.fs_r.q.val() & !self.clr_h0.q.val() {
                    self.nib_out.next = self.nib_out.val() | 8;
                }
                if self.wr_r.q.val() {
                    self.nib_out.next = self.nib_out.val() | 4;
                }
            }
            // HOP + 1 (without adders, issue 20): the first nibble's two HOP
            // bits wrap into the last one's (carry), the others are whole.
            if (self.act_now.val() == 2) & (self.gidx.q.val() == 0) {
                self.nib_out.next = self.inc2.val();
            }
            if (self.act_now.val() == 2)
                & ((self.dg.val() == 1) | (self.dg.val() == 2))
                & self.carry.q.val()
            {
                self.nib_out.next = self.inc4.val();
            }
            if (self.act_now.val() == 2) & (self.dg.val() == 3) & self.carry.q.val() {
                self.nib_out.next = self.inc2.val();
            }
            // The actuator's ALIVE; ALARM cleared (it is 0 here in the
            // basic variant) and, extended, the reason nibble too.
            if (self.act_now.val() == 4) & (self.gidx.q.val() == 0) {
                self.nib_out.next = self.nib.val() & 3;
                if self.alive_now.val() {
                    self.nib_out.next = self.nib_out.val() | 4;
                }
            }
            if (self.act_now.val() == 4) & (self.dg.val() == 7) {
                self.nib_out.next = 0.into();
            }
            // Master ACT slot: the data bits from the data memory.
            if self.act_now.val() == 5 {
                if self.gidx.q.val() == 0 {
                    self.nib_out.next =
                        (self.nib.val() & 12) | (self.f_data.q.val().get_bits::<4>(0) & 3);
                }
                if self.dg.val() == 1 {
                    self.nib_out.next = self.f_data.q.val().get_bits::<4>(2);
                }
                if self.dg.val() == 2 {
                    self.nib_out.next = self.f_data.q.val().get_bits::<4>(6);
                }
                if self.dg.val() == 3 {
                    self.nib_out.next = self.f_data.q.val().get_bits::<4>(10);
                }
            }
            // Delta parity in the last group: the changes of the groups
            // before (d_a, d_b) and, in an ACT slot, of this group's data
            // bits (D15, D14); the other actions leave the last group's
            // data bits as they came.
            if self.dg.val() == 4 {
                self.pa_fix.next = self.d_a.q.val();
                self.pb_fix.next = self.d_b.q.val();
                if self.act_now.val() == 5 {
                    self.nib_out.next =
                        (self.nib.val() & 9) | ((self.f_data.q.val().get_bits::<4>(12) >> 1) & 6);
                    self.pa_fix.next = self.d_a.q.val()
                        ^ self.nib.val().get_bit(2)
                        ^ self.f_data.q.val().get_bit(15);
                    self.pb_fix.next = self.d_b.q.val()
                        ^ self.nib.val().get_bit(2)
                        ^ self.f_data.q.val().get_bit(15)
                        ^ self.nib.val().get_bit(1)
                        ^ self.f_data.q.val().get_bit(14);
                }
                if self.pa_fix.val() {
                    self.nib_out.next = self.nib_out.val() ^ 8;
                }
                if self.pb_fix.val() {
                    self.nib_out.next = self.nib_out.val() ^ 1;
                }
            }
        }
        self.diff.next = self.c_orig.q.val() ^ self.c_nib.q.val();
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
        if self.c_nib.q.val() == 1 {
            self.code_out.next = 0b01001.into();
        }
        if self.c_nib.q.val() == 2 {
            self.code_out.next = 0b10100.into();
        }
        if self.c_nib.q.val() == 3 {
            self.code_out.next = 0b10101.into();
        }
        if self.c_nib.q.val() == 4 {
            self.code_out.next = 0b01010.into();
        }
        if self.c_nib.q.val() == 5 {
            self.code_out.next = 0b01011.into();
        }
        if self.c_nib.q.val() == 6 {
            self.code_out.next = 0b01110.into();
        }
        if self.c_nib.q.val() == 7 {
            self.code_out.next = 0b01111.into();
        }
        if self.c_nib.q.val() == 8 {
            self.code_out.next = 0b10010.into();
        }
        if self.c_nib.q.val() == 9 {
            self.code_out.next = 0b10011.into();
        }
        if self.c_nib.q.val() == 10 {
            self.code_out.next = 0b10110.into();
        }
        if self.c_nib.q.val() == 11 {
            self.code_out.next = 0b10111.into();
        }
        if self.c_nib.q.val() == 12 {
            self.code_out.next = 0b11010.into();
        }
        if self.c_nib.q.val() == 13 {
            self.code_out.next = 0b11011.into();
        }
        if self.c_nib.q.val() == 14 {
            self.code_out.next = 0b11100.into();
        }
        if self.c_nib.q.val() == 15 {
            self.code_out.next = 0b11101.into();
        }

        // The delay line: one group and one bit. A group's code bits are
        // in bits 4:0 once its last bit has arrived (stage A); stage C, two
        // clocks later, writes the rewritten group over them (where the bit
        // of stage B's clock, if one came, has moved them), and when a bit
        // arrives in that clock too, the rewritten first bit goes out
        // directly (a group's first bit leaves at the second bit after it).
        self.out_bit.next = self.delay.q.val().get_bit(5);
        self.in_code.next = self.i_code.val() | self.i_mute.val();
        self.sent.d.next = false;
        self.done.d.next = false;
        self.cut.next = false;
        self.regen.d.next = false;
        self.g_pend.d.next = false;
        self.slot_inc.d.next = false;
        self.slot_clr.d.next = false;
        if self.slot_clr.q.val() {
            self.slot.d.next = 0.into();
        } else if self.slot_inc.q.val() {
            self.slot.d.next = self.slot.q.val() + 1;
        }
        // Stage A: the recovered bit.
        if self.i_bvalid.val() {
            self.window.d.next = self.shifted.val();
            self.delay.d.next = self.delay.q.val() << 1;
            if self.in_code.val() {
                self.delay.d.next = (self.delay.q.val() << 1) | 1;
            }
            if self.inpkt.q.val() {
                if self.bitc.q.val() == 4 {
                    // A group is complete: stage B takes it next clock,
                    // unless it is the third idle group in a row: then the
                    // packet was cut short upstream (as word_rx), and the
                    // rest passes unchanged.
                    self.bitc.d.next = 0.into();
                    self.idles.d.next = 0.into();
                    if self.group.val() == 31 {
                        self.idles.d.next = self.idles.q.val() + 1;
                    }
                    self.g_pend.d.next = true;
                    self.g_cut.d.next = (self.group.val() == 31) & (self.idles.q.val() == 2);
                    if (self.group.val() == 31) & (self.idles.q.val() == 2) {
                        self.cut.next = true;
                    }
                    self.g_nib.d.next = self.dec_nib.val();
                    self.g_dat.d.next = self.dec_data.val();
                    self.g_sym_s.d.next = self.dec_s.val();
                    self.g_act.d.next = self.act_c.val();
                } else {
                    self.bitc.d.next = self.bitc.q.val() + 1;
                }
            } else if self.shifted.val() == self.jk.val() {
                self.inpkt.d.next = true;
                self.bitc.d.next = 0.into();
                self.gidx.d.next = 0.into();
                self.wcount.d.next = 0.into();
                self.slot_clr.d.next = true;
                self.dead.d.next = false;
                self.idles.d.next = 0.into();
                self.rtx.d.next = false;
                self.idx_ok.d.next = false;
                self.idx_own.d.next = false;
                self.rtx_wrote.d.next = false;
            }
        }
        // Stage B: the group completed in the clock before (groups complete
        // at least 5 clocks apart, so stage B never meets stage A's next
        // group, a cut or a J K; a bit may arrive in the same clock).
        self.c_pend.d.next = false;
        if self.g_pend.q.val() & !self.g_cut.q.val() {
            // To stage C: the group as it leaves, and what it came as.
            self.c_pend.d.next = true;
            self.c_nib.d.next = self.nib_out.val();
            self.c_orig.d.next = self.nib.val();
            self.c_write.d.next = self.recode.val();
            self.c_first.d.next = self.gidx.q.val() == 0;
            self.c_shift.d.next = self.i_bvalid.val();
            // The mark: T (merkur_model::line::CODE_T) in the last group.
            self.c_mark.d.next = (self.dg.val() == 4)
                & self.arrived_bad.val()
                & !self.dead.q.val()
                & (self.action.q.val() != 3);
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
                self.carry.d.next = false;
                self.regen.d.next = self.pre_own.q.val()
                    & self.i_master.val()
                    & (self.i_slot_cfg.val() == 2)
                    & (self.act_now.val() == 3);
                if (self.act_now.val() >= 3) & self.rtx.q.val() {
                    self.rtx_wrote.d.next = true;
                }
                if self.pre_home.q.val() {
                    self.prev_alarm.d.next = self.f_alarm.q.val();
                    self.sent.d.next = self.f_alarm.q.val();
                    self.sent_reason.d.next = self.f_reason.q.val();
                }
            }
            if self.gidx.q.val() == 0 {
                self.carry.d.next = self.nib.val().get_bits::<2>(0) == 3;
            } else if self.dg.val() != 7 {
                self.carry.d.next = self.carry.q.val() & (self.nib.val() == 15);
            }
            self.gidx.d.next = self.gidx.q.val() + 1;
            if self.dg.val() == 4 {
                // A word is complete.
                self.gidx.d.next = 0.into();
                if self.wcount.q.val() == 2 {
                    self.slot_inc.d.next = true;
                    if (self.slot.q.val() == self.i_slots_m1.val()) & !self.rtx.q.val() {
                        self.inpkt.d.next = false;
                        if !self.dead.q.val() {
                            self.done.d.next = true;
                            self.toggle.d.next = !self.toggle.q.val();
                            self.framed.d.next = true;
                        }
                    }
                } else {
                    self.wcount.d.next = self.wcount.q.val() + 1;
                }
            }
        }
        // Stage C, the clock after stage B: the group is encoded and
        // written over its code bits in the delay line, which the bits of
        // the two clocks since (`c_shift`, `i_bvalid`) have moved on; and
        // the changes made (delta parity, protocol §4) are summed for the
        // word's last group.
        self.code_w.next = self.code_out.val();
        if self.c_mark.q.val() {
            self.code_w.next = 0b01101.into();
        }
        self.code_w6.next = bit_cast::<6, 5>(self.code_w.val()) | 0;
        if self.c_pend.q.val() & (self.c_write.q.val() | self.c_mark.q.val()) {
            if self.c_shift.q.val() {
                // The group is in bits 5:1, the bit since in bit 0; a bit
                // arriving now sends the group's first bit, rewritten.
                self.delay.d.next = (self.delay.q.val() & 1) | (self.code_w6.val() << 1);
                self.out_bit.next = self.code_w.val().get_bit(4);
                if self.i_bvalid.val() {
                    self.delay.d.next = (self.code_w6.val() << 2)
                        | ((self.delay.q.val() & 1) << 1)
                        | (bit_cast::<6, 1>(self.in_code.val().into()) | 0);
                }
            } else {
                // The group is in bits 4:0.
                self.delay.d.next = (self.delay.q.val() & 32) | self.code_w6.val();
                if self.i_bvalid.val() {
                    self.delay.d.next = (self.code_w6.val() << 1)
                        | (bit_cast::<6, 1>(self.in_code.val().into()) | 0);
                }
            }
        }
        if self.c_pend.q.val() {
            self.d_a.d.next =
                self.d_a.q.val() ^ self.diff.val().get_bit(3) ^ self.diff.val().get_bit(2);
            self.d_b.d.next = self.d_b.q.val()
                ^ self.diff.val().get_bit(2)
                ^ self.diff.val().get_bit(1)
                ^ self.diff.val().get_bit(0);
            if self.c_first.q.val() {
                self.d_a.d.next = self.diff.val().get_bit(3) ^ self.diff.val().get_bit(2);
                self.d_b.d.next = self.diff.val().get_bit(2)
                    ^ self.diff.val().get_bit(1)
                    ^ self.diff.val().get_bit(0);
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
            self.delay.d.next = 63.into();
            self.cut.next = true;
        }
        // A packet cut short ends here; a frame whose header was processed
        // still counts (the Alive flip-flop toggles, as at its end).
        if self.cut.val() {
            self.inpkt.d.next = false;
            self.idles.d.next = 0.into();
            if self.inpkt.q.val()
                & (self.wcount.q.val() == 2)
                & !self.dead.q.val()
                & !self.rtx.q.val()
            {
                self.done.d.next = true;
                self.toggle.d.next = !self.toggle.q.val();
                self.framed.d.next = true;
            }
            // A node that missed the frame but wrote into the RTX toggles
            // as if it had processed the frame (protocol §8).
            if self.inpkt.q.val() & self.rtx.q.val() & self.rtx_wrote.q.val() & !self.framed.q.val()
            {
                self.toggle.d.next = !self.toggle.q.val();
                self.framed.d.next = true;
            }
        }
        // INPUT's words: a good H0 of type 11 makes the packet an RTX; any
        // other H0 starts a new cycle's packets (no frame processed yet).
        // An RTX's good index word names the slot of the next data word.
        if self.i_wvalid.val() & (self.i_wkind.val() == 0) {
            self.rtx.d.next = self.i_wok.val() & (self.i_ptype.val() == 3) & self.rtx_on.val();
            if !(self.i_wok.val() & (self.i_ptype.val() == 3)) {
                self.framed.d.next = false;
            }
        }
        self.addr16.next = bit_cast::<16, 12>(self.i_address.val()) | 0;
        if self.i_wvalid.val() & (self.i_wkind.val() == 3) & !self.i_wodd.val() {
            self.idx.d.next = self.i_wdata.val().get_bits::<12>(0);
            self.idx_ok.d.next = self.i_wok.val()
                & !self.i_walarm.val()
                & (self.i_wdata.val().get_bits::<4>(12) == 0)
                & (self.i_wdata.val().get_bits::<12>(0) <= self.i_slots_m1.val());
            // (The home slot is below S: no range check. A slave needs only
            // this bit, so synthesis drops `idx` there.)
            self.idx_own.d.next = self.rtx_on.val()
                & self.i_wok.val()
                & !self.i_walarm.val()
                & (self.i_wdata.val() == self.addr16.val());
        }
        if self.i_hdr_bad.val() {
            self.dead.d.next = true;
        }
        // The f_* registers' hold in the next clock, from `gidx`'s and
        // `g_pend`'s next values (their last assignments are above).
        self.f_hold.d.next = (self.gidx.d.val() != 0) | self.g_pend.d.val();
        self.o_slot.next = self.slot.q.val();
        self.o_rtx_own.next = self.idx_own.q.val();
        self.o_rtx_idx.next = self.idx.q.val();
        self.o_rtx_ok.next = self.idx_ok.q.val();
        // In an RTX the memories are read at the requested slot.
        if self.rtx.q.val() {
            self.o_slot.next = self.idx.q.val();
        }
        self.o_regen.next = self.regen.q.val();
        self.o_alarm_sent.next = self.sent.q.val();
        self.o_sent_reason.next = self.sent_reason.q.val();
        self.o_prev_alarm.next = self.prev_alarm.q.val();
        self.o_pkt_done.next = self.done.q.val();
        self.o_toggle.next = self.toggle.q.val();
        self.o_line.next = self.out.o_line.val();
    }
}
