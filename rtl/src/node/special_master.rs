//! # special_master — the ring's clock base, and a backup that can become it (protocol §5, §8)
//!
//! Purpose: the one master per ring that starts every cycle, and the
//! flying special master's backups (protocol §8): with `i_prio` = 0 the
//! node is the clock base from power-up (everything below); with `i_prio`
//! = p ≥ 1 it is a **backup**: a master like [`crate::node::master`] (its
//! forwarder [`Fwd`] in master mode on OUTPUT, BSR repeated on BSS in mode
//! N, alarms through the forwarder and read back at INPUT, failsafe left at
//! a CLR header) whose clock base waits for its election. Its election
//! timer counts bit times since the last packet started on INPUT (J K, or
//! [`START_BITS`] code bits that show a DATA frame's start with one line-bit
//! error); when it reaches
//! `i_elect` ((1.5 + p) periods) while the node is armed, not in failsafe
//! and did not know the ring wrapped at its last good header, the node
//! becomes the clock base for good (`o_base`): [`TAKEOVER_LEAD_BITS`] of
//! idles on OUTPUT, then a frame every period with CYC continuing the count
//! (the last good header's + 1 + p), an empty return store, and what a
//! clock base learns from returning frames started afresh. A backup's
//! clock-base logic is this block's; the forwarder is unused (and removed
//! by synthesis) where `i_prio` is tied to 0.
//!
//! As the clock base: every
//! `i_period` bit times of its own clock it sends a DATA frame on PO (J K,
//! H0 = `{00, FS, RWC, S−1}`, H1 = `{RWP, CYC, HOP = 0}`, S slot words) and a
//! SEC packet on SO (H0 = `{01, 00, CYC[11:0]}`, H1 = NOT H0). The frame that
//! returns on PI fills the **return store**, a slot-indexed memory (S words
//! with the cycle they returned in), from which the next frame is built
//! (protocol §8: the paper's FIFO; it cannot overflow, and a slot that did
//! not return last cycle is sent as VOID). An entry is sent once: it is
//! marked not valid in the clock after its word is taken, so a slot whose
//! frame came back with a bad header, or not at all, is VOID however many
//! cycles ago it last returned (CYC has only 3 bits). Per slot of the outgoing frame:
//! - LOCAL: `{data memory, Alive}`, or an alarm in the home slot (§11, with
//!   alternation and SEQ in `D[11]`; the alarm stays in flight until the
//!   frame returns with it good, and is sent again otherwise);
//! - ACT: the returned word with the data memory's value and the actuator's
//!   Alive; a VOID is regenerated with the Alive the actuator would send;
//!   an alarm passes;
//! - otherwise the returned word; an alarm that returns after the SM already
//!   retransmitted an alarm in that slot is not sent again (VOID).
//!
//! Like every master it has the real-time database [`Mdb`] (data memory,
//! configuration, Alive check, interrupts, Wishbone host port): frames start
//! once the host has loaded the configuration and set the start bit.
//!
//! Secondary relay: a DATA frame arriving on SI (the ring is wrapped) is
//! passed on to SO like in every node in mode N, held back [`RELAY_BITS`]
//! bits until its H1 shows it is DATA; every other packet is dropped there
//! (the SM's own SEC coming back, the remains of a TST that a node in mode
//! N cut, a fragment), so nothing but frames circulates on the secondary
//! ring, a closed loop through the pass-throughs (while BSR is dark behind a
//! relayed frame the held bits go out on the node's own timing, so a dark
//! gap behind the frame does not cut its tail); a SEC is sent at the
//! cycle's start only when the last returned frame had RWC = 0 (protocol
//! §8).
//!
//! Failsafe (protocol §12): it enters failsafe like every node (FS in a
//! returned header without CLR, a second structural fault, its CS timeout:
//! 3.5 periods without a returned packet other than a TST, a FAILSAFE
//! alarm), and it alone brings the ring out: it keeps `hop_ref`, the HOP of
//! the last good header back with FS = 0 outside failsafe; in failsafe,
//! after 2 frames back in a row with HOP ≥ `hop_ref` (every node reached
//! again: the ring is no longer split) — and its host's FS_CLEAR where
//! FS_HOST is set or a FAILSAFE request came back — it leaves failsafe at a
//! period tick and sends CLR frames (H0's ALIVE bit) until one comes back
//! with FS = 0; if the 4th does not, it enters failsafe again.
//!
//! Switchbox: like every node ([`crate::node::slave`]; protocol §10) it wraps
//! when its INPUT or BSR fails (frames then leave on OUTPUT and return on
//! INPUT of its row of Table 1, headers carry RWC, no SEC is sent, BSS
//! carries TST), reintegrates ([`UNWRAP_LEAD_BITS`] before a period tick
//! when it is the WD end), and sends RECONFIG alarms in its home slot; after
//! every change its outputs are dark for 12 bit times ([`crate::node::sw_dark`]) —
//! but for PO between N and WU, where PO carries its own frame generator
//! before and after, so a wrap never cuts the frame it is sending (issue
//! 19) — and a packet the relay was holding from the old BSR line is
//! dropped.
//!
//! Parameters: the word format ([`WordFormat`], protocol §4 or §6). With
//! extended-alarm words the store keeps each entry's reason nibble in its
//! top four bits (0 with basic words), the home slot's alarm keeps the data memory's value and
//! goes in N1, an ACT slot's alarm word gets the data memory's value too,
//! and the secondary relay holds a packet back [`RELAY_BITS_EXT`] bits.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate (also the Wishbone clock) |
//! | `i_pi`, `i_si` | in | 4 | clock | physical inputs, 4 samples per clock (quadrature DDR) |
//! | `o_po`, `o_so` | out | 2 | clock | physical outputs, DDR pairs |
//! | `i_address` | in | 12 | static | home slot |
//! | `i_slots_m1` | in | 12 | static | slots per frame − 1 |
//! | `i_period` | in | 20 | static | cycle period P in bit times (protocol §8) |
//! | `i_cs_timeout` | in | 20 | static | clocks without a returned packet other than a TST before failsafe (3.5 periods; 2.5 + the highest backup priority in a ring with backups, §8) |
//! | `i_prio` | in | 3 | static | 0: the clock base from power-up; 1–7: a backup of this priority |
//! | `i_elect` | in | 20 | static | a backup's election time in bit times ((1.5 + `i_prio`) periods) |
//! | `i_flying` | in | 1 | static | the ring has backups: a priority-0 node that its host starts with JOIN after a restart ([`Mdb`], protocol §12) rejoins as a master and never starts a clock base (0: a ring without backups, whose special master's restart restarts the ring: its host starts it with bit 0; synthesis removes the forwarder) |
//! | `i_wb_*`, `o_wb_*` | | | clock | Wishbone B4 classic host port, see [`Mdb`] |
//! | `i_irq1`, `i_irq2`, `i_fs_req` | in | 1 | clock | user requests (alarms in the home slot) |
//! | `o_irq1`, `o_irq2`, `o_irq_fs`, `o_irq_rc` | out | 1 | clock | alarm received, by reason: IRQ1, IRQ2, FAILSAFE, RECONFIG 4–6 (one clock per alarm word; each also goes into the alarm queue, `mdb`) |
//! | `o_alarmq` | out | 1 | clock | the alarm queue is not empty (level) |
//! | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD) |
//! | `o_failsafe` | out | 1 | clock | failsafe (left by the special master itself, protocol §12) |
//! | `o_irq_fsc` | out | 1 | clock | failsafe entered or left (one clock) |
//! | `o_perr`, `o_ferr`, `o_aerr`, `o_serr` | out | 16 | clock | error counters (`serr`: SEC packets that did not return) |
//! | `o_hop` | out | 12 | clock | HOP of the last returned frame (N − 1 in a healthy ring) |
//! | `o_cycles` | out | 16 | clock | frames sent |
//! | `o_running` | out | 1 | clock | the host started the ring |
//! | `o_base` | out | 1 | clock | the node is the clock base (priority 0, or elected) |
//!
//! Latency: a frame's J starts 1–5 bit times after its period tick; a
//! returned word is in the store ≈ 3.5 bit times after its last line bit.
//!
//! ```text
//! period     |<------------------------- P bit times ------------------------>|
//! PO         | J K | H0 | H1 | slot 0 | ... | slot S-1 |~~~~~~ idle ~~~~~~~~~~~| J K ...
//! SO         | J K | H0 | H1 |~~~~~~~~~~~~~~~~~~~~~ idle ~~~~~~~~~~~~~~~~~~~~~| J K ...
//! PI (back)        ...L later...  | J K | H0 | H1 | slot 0 | ... -> return store
//! ```

use crate::line::dec5b4b::Dec5b4b;
use crate::line::retime::Retime;
use crate::line::word_rx::WordFormat;
use crate::node::fwd::Fwd;
use crate::node::mdb::Mdb;
use crate::node::pkt_tx::PktTx;
use crate::node::port_rx::PortRx;
use crate::node::sw_dark::SwDark;
use crate::node::switch_ctl::SwitchPipe;
use crate::node::switchbox::Switchbox;
use crate::node::tst_tx::TstTx;
use rust_hdl::prelude::*;

/// Bits the secondary relay holds a packet back while the header shows
/// whether it is a DATA frame (relayed) or not (the SM's own SEC coming
/// back, dropped): more than J K + H0 + H1 (60) plus decoding latency.
pub const RELAY_BITS: u64 = 76;
/// [`RELAY_BITS`] with extended-alarm words: two header words are 10 bits
/// longer (protocol §6).
pub const RELAY_BITS_EXT: u64 = RELAY_BITS + 10;
// The delay line `rdl` is a `Bits<76>` read at bit 75, and `rdx` its
// 10-bit extension for extended words (rust-hdl widths are literals):
// keep them in step with RELAY_BITS.
const _: () = assert!(RELAY_BITS == 76 && RELAY_BITS_EXT == 86);
/// Bit times before its period tick at which a WD special master unwraps:
/// the outputs are dark for 12 after the change ([`crate::node::sw_dark`]), and
/// the previous frame and its idles have left (a period is at least the
/// frame plus 20 bit times).
pub const UNWRAP_LEAD_BITS: u64 = 16;
/// Code bits by which a backup's election timer sees a DATA frame whose J K
/// a bit error destroyed (protocol §8): 9 idle 1s, J K but for one
/// line-bit error, and H0's first four groups, which carry S − 1 (the
/// first one's part unless the error reached it).
pub const START_BITS: u64 = 39;
// `in_code` is a `Bits<39>` (rust-hdl widths are literals).
const _: () = assert!(START_BITS == 39);
/// Requests an RTX carries at most (protocol §8): the clock base's list of
/// damaged critical slots has this many places.
pub const RTX_MAX: usize = merkur_model::config::RTX_MAX;
/// Bit times of idles an elected backup sends on OUTPUT before its first
/// frame (protocol §8): more than the 20 between packets, so that
/// receivers that saw a dark stretch relock first.
pub const TAKEOVER_LEAD_BITS: u64 = 48;

/// Special master.
#[derive(LogicBlock)]
pub struct SpecialMaster {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Primary input.
    pub i_pi: Signal<In, Bits<4>>,
    /// Secondary input.
    pub i_si: Signal<In, Bits<4>>,
    /// Primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Secondary output.
    pub o_so: Signal<Out, Bits<2>>,
    /// Home slot.
    pub i_address: Signal<In, Bits<12>>,
    /// Slots − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Cycle period in bit times.
    pub i_period: Signal<In, Bits<20>>,
    /// CS timeout in clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Backup priority: 0 the clock base from power-up, 1–7 a backup.
    pub i_prio: Signal<In, Bits<3>>,
    /// A backup's election time in bit times ((1.5 + priority) periods).
    pub i_elect: Signal<In, Bits<20>>,
    /// The ring has backups: with priority 0, a restart's JOIN makes the
    /// node a master that never starts a clock base (protocol §8, §12).
    pub i_flying: Signal<In, Bit>,
    /// Retransmission on demand (protocol §8): bit times after the period
    /// tick at which the RTX goes, in the healthy ring and in a ring it
    /// knows wrapped (`T`).
    pub i_rtx_at: Signal<In, Bits<20>>,
    /// See `i_rtx_at`.
    pub i_rtx_atw: Signal<In, Bits<20>>,
    /// Requests an RTX has room for in the period, healthy and wrapped (0:
    /// no RTX; at most [`RTX_MAX`]).
    pub i_rtx_k: Signal<In, Bits<5>>,
    /// See `i_rtx_k`.
    pub i_rtx_kw: Signal<In, Bits<5>>,
    /// Wishbone cycle.
    pub i_wb_cyc: Signal<In, Bit>,
    /// Wishbone strobe.
    pub i_wb_stb: Signal<In, Bit>,
    /// Wishbone write enable.
    pub i_wb_we: Signal<In, Bit>,
    /// Wishbone word address.
    pub i_wb_adr: Signal<In, Bits<14>>,
    /// Wishbone write data.
    pub i_wb_dat: Signal<In, Bits<16>>,
    /// Wishbone read data.
    pub o_wb_dat: Signal<Out, Bits<16>>,
    /// Wishbone acknowledge.
    pub o_wb_ack: Signal<Out, Bit>,
    /// User interrupt 1 request.
    pub i_irq1: Signal<In, Bit>,
    /// User interrupt 2 request.
    pub i_irq2: Signal<In, Bit>,
    /// User failsafe request.
    pub i_fs_req: Signal<In, Bit>,
    /// IRQ1 alarm received.
    pub o_irq1: Signal<Out, Bit>,
    /// IRQ2 alarm received.
    pub o_irq2: Signal<Out, Bit>,
    /// FAILSAFE alarm received.
    pub o_irq_fs: Signal<Out, Bit>,
    /// RECONFIG alarm received.
    pub o_irq_rc: Signal<Out, Bit>,
    /// The alarm queue is not empty.
    pub o_alarmq: Signal<Out, Bit>,
    /// Switchbox mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// Failsafe.
    pub o_failsafe: Signal<Out, Bit>,
    /// Failsafe entered or left.
    pub o_irq_fsc: Signal<Out, Bit>,
    /// Bad words at INPUT.
    pub o_perr: Signal<Out, Bits<16>>,
    /// Rejected headers at INPUT.
    pub o_ferr: Signal<Out, Bits<16>>,
    /// Alive-check failures.
    pub o_aerr: Signal<Out, Bits<16>>,
    /// SEC failures.
    pub o_serr: Signal<Out, Bits<16>>,
    /// HOP of the last returned frame.
    pub o_hop: Signal<Out, Bits<12>>,
    /// Frames sent.
    pub o_cycles: Signal<Out, Bits<16>>,
    /// Running.
    pub o_running: Signal<Out, Bit>,
    /// The node is the clock base (from power-up, or elected).
    pub o_base: Signal<Out, Bit>,
    rx_in: PortRx,
    rx_bsr: PortRx,
    ftx: PktTx,
    stx: PktTx,
    rep: Retime,
    sbox: Switchbox,
    dark: SwDark,
    tst: TstTx,
    swc: SwitchPipe,
    pend_rc: DFF<Bit>,
    ret_rwp: DFF<Bit>,
    sw_flush: DFF<Bit>,
    wrapped: Signal<Local, Bit>,
    rw: Signal<Local, Bit>,
    bss_pair: Signal<Local, Bits<2>>,
    relay_len: Constant<Bits<7>>,
    unwrap_lead: Constant<Bits<20>>,
    /// 1 in the period counter's width: `bcnt + one` wraps in 20 bits in
    /// the Verilog as in Rust (a bare `+ 1` is a 32-bit sum in Verilog).
    /// The counter's next value is the same either way (0 after the last
    /// bit time); the sized sum keeps the comparison free of mixed widths.
    one: Constant<Bits<20>>,
    jk_bits: Constant<Bits<10>>,
    takeover_lead: Constant<Bits<20>>,
    unwrap_at: Signal<Local, Bit>,
    rdl: DFF<Bits<76>>,
    rdx: DFF<Bits<10>>,
    rcd: DFF<Bits<7>>,
    rcd_run: DFF<Bit>,
    rdata: DFF<Bit>,
    relay: DFF<Bit>,
    /// Clocks since the last bit on BSR, recovered or the relay's own.
    rdead: DFF<Bits<2>>,
    /// The relay sends a bit of its own (BSR dark).
    rsyn: Signal<Local, Bit>,
    /// The relay's delay line shifts: a recovered bit, or one of its own.
    rshift: Signal<Local, Bit>,
    mdb: Mdb,
    store: RAM<Bits<26>, 12>,
    /// A store entry was sent: mark it not valid (in the next clock the
    /// return path does not write).
    st_used: DFF<Bit>,
    st_used_slot: DFF<Bits<12>>,
    sent_alarm: RAM<Bit, 12>,
    aact: RAM<Bit, 12>,
    st_r: DFF<Bits<26>>,
    aact_r: DFF<Bit>,
    // Extended-alarm words (protocol §6); the reason nibble of the word
    // sent; INPUT's alarm SEQ and reason as the format carries them.
    ext: Constant<Bit>,
    // Retransmission on demand is built in ([`SpecialMaster::with_rtx`]).
    rtx_on: Constant<Bit>,
    w_rn: Signal<Local, Bits<4>>,
    rx_seq: Signal<Local, Bit>,
    rx_rsn: Signal<Local, Bits<4>>,
    half: DFF<Bit>,
    bcnt: DFF<Bits<20>>,
    cyc: DFF<Bits<12>>,
    cycles: DFF<Bits<16>>,
    toggle: DFF<Bit>,
    fbusy: DFF<Bit>,
    failsafe: DFF<Bit>,
    fs_tx: DFF<Bit>,
    ret_rwc: DFF<Bit>,
    ret_cyc: DFF<Bits<3>>,
    hop: DFF<Bits<12>>,
    armed: DFF<Bit>,
    ferr_owed: DFF<Bits<12>>,
    /// The returning frame's number: CYC's 3 bits say how far back from
    /// the SM's own 12-bit count it was sent (0 or 1 frames).
    cyc_back: Signal<Local, Bits<3>>,
    ret_num: Signal<Local, Bits<12>>,
    /// Number of the last frame that came back with a good header.
    last_num: DFF<Bits<12>>,
    cyc_gap: Signal<Local, Bits<12>>,
    ferr_sum: Signal<Local, Bits<17>>,
    quiet: DFF<Bits<20>>,
    sec_sent: DFF<Bit>,
    // Leaving failsafe (protocol §12).
    hop_ref: DFF<Bits<12>>,
    whole: DFF<Bits<2>>,
    clr_sent: DFF<Bits<3>>,
    ret_fs: DFF<Bit>,
    ret_clr: DFF<Bit>,
    ret_seen: DFF<Bit>,
    fs_request: DFF<Bit>,
    host_clear: DFF<Bit>,
    leave: Signal<Local, Bit>,
    clr_fail: Signal<Local, Bit>,
    sec_ok: DFF<Bit>,
    sec_word: DFF<Bits<16>>,
    serr: DFF<Bits<16>>,
    perr: DFF<Bits<16>>,
    ferr: DFF<Bits<16>>,
    pend_fs: DFF<Bit>,
    pend_i1: DFF<Bit>,
    pend_i2: DFF<Bit>,
    prev_alarm: DFF<Bit>,
    /// The alarm in flight (sent, not read back yet, protocol §11), its
    /// reason, the SEQ the next new alarm gets, and the read-back due in
    /// the returning frame.
    fl_v: DFF<Bit>,
    fl_r: DFF<Bits<4>>,
    nxt: DFF<Bit>,
    await_rb: DFF<Bit>,
    seq_tx: Signal<Local, Bit>,
    tick: Signal<Local, Bit>,
    st: Signal<Local, Bits<26>>,
    st_ok: Signal<Local, Bit>,
    prev_cyc: Signal<Local, Bits<3>>,
    reason: Signal<Local, Bits<4>>,
    send_alarm: Signal<Local, Bit>,
    w_data: Signal<Local, Bits<16>>,
    w_alive: Signal<Local, Bit>,
    w_alarm: Signal<Local, Bit>,
    w_void: Signal<Local, Bit>,
    home: Signal<Local, Bit>,
    h0: Signal<Local, Bits<16>>,
    h1: Signal<Local, Bits<16>>,
    sec_h0: Signal<Local, Bits<16>>,
    st_word: Signal<Local, Bits<26>>,
    // A backup before its election: a master (protocol §8).
    fwd: Fwd,
    txs: SlotSel,
    fs_cleared: DFF<Bit>,
    /// Elected (a backup that took over the clock base).
    cb: DFF<Bit>,
    /// Priority 0 restarted in a ring with backups (JOIN): a master; a
    /// register copy for [`SlotSel`].
    join_r: DFF<Bit>,
    /// The clock base now: elected, or priority 0.
    base: Signal<Local, Bit>,
    /// Bit times since the last packet started on INPUT (election timer).
    et: DFF<Bits<20>>,
    /// INPUT's last 39 code bits (newest in bit 0).
    in_code: DFF<Bits<39>>,
    /// The delimiter-like ten code bits against J K: their difference,
    /// it without its lowest 1, and whether it is one line-bit error at
    /// most (no code bit, one, or two neighbours: NRZI).
    jk_x: Signal<Local, Bits<10>>,
    jk_z: Signal<Local, Bits<10>>,
    jk_z1: Signal<Local, Bits<10>>,
    jk_ok: Signal<Local, Bit>,
    /// A packet start whose J K one line-bit error destroyed.
    jk_bad: Signal<Local, Bit>,
    /// Bit times since the packet on INPUT started.
    since_jk: DFF<Bits<20>>,
    /// CYC of the last DATA frame and of the last SEC that restarted the
    /// election timer (and whether there was one).
    dcyc: DFF<Bits<3>>,
    dcyc_v: DFF<Bit>,
    scyc: DFF<Bits<12>>,
    scyc_v: DFF<Bit>,
    g0: Dec5b4b,
    g1: Dec5b4b,
    g2: Dec5b4b,
    g3: Dec5b4b,
    jk_s: Signal<Local, Bit>,
    /// The ring was known wrapped at the last good header processed.
    rw_hdr: DFF<Bit>,
    /// CYC of the last good header processed, and the gap to the next.
    last_cyc3: DFF<Bits<3>>,
    cyc_gap3: Signal<Local, Bits<3>>,
    /// The takeover frame's CYC: the last good header's plus 1 + priority.
    cyc_take: Signal<Local, Bits<3>>,
    fwd_cut: DFF<Bit>,
    rep_cut: DFF<Bit>,
    pass_code: Signal<Local, Bit>,
    // Retransmission on demand (protocol §8): the CRIT bits (from the
    // host's configuration writes); the damaged critical slots of the
    // period's returning frame, in slot order (`dl0` …); the search (0 the frame is
    // not back, 1 following its slot words, 2 going through the slots it
    // did not bring, 3 done) and its next slot; the slot being checked
    // (its CRIT bit is read) and whether it counts when critical; the RTX
    // being sent, its requests, the slot of the request being sent.
    crit: RAM<Bit, 12>,
    // (Eight registers, not a memory: a block RAM more would cost the
    // HX8K its 2048-slot special master.)
    dl0: DFF<Bits<12>>,
    dl1: DFF<Bits<12>>,
    dl2: DFF<Bits<12>>,
    dl3: DFF<Bits<12>>,
    dl4: DFF<Bits<12>>,
    dl5: DFF<Bits<12>>,
    dl6: DFF<Bits<12>>,
    dl7: DFF<Bits<12>>,
    dcount: DFF<Bits<5>>,
    dst: DFF<Bits<2>>,
    dnext: DFF<Bits<12>>,
    c_v: DFF<Bit>,
    c_slot: DFF<Bits<12>>,
    c_dmg: DFF<Bit>,
    rtxm: DFF<Bit>,
    rk: DFF<Bits<5>>,
    rtx_req: DFF<Bits<12>>,
    d_inpkt: DFF<Bit>,
    s2_rtx: DFF<Bit>,
    bsr_h0ok: DFF<Bit>,
    rtx_cap: DFF<Bits<5>>,
    rtx_t: DFF<Bits<20>>,
    at_t: DFF<Bit>,
    rtx_go: Signal<Local, Bit>,
    rtx_h0: Signal<Local, Bits<16>>,
    cyc_m1: Signal<Local, Bits<12>>,
    rtx_m1: Signal<Local, Bits<12>>,
    rtx_max: Constant<Bits<5>>,
}

impl Default for SpecialMaster {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl SpecialMaster {
    /// A special master for words in `format` (protocol §4, §6), with
    /// retransmission on demand.
    pub fn new(format: WordFormat) -> Self {
        Self::with_rtx(format, true)
    }

    /// A special master for words in `format`; without retransmission on
    /// demand when `rtx` is false (a ring without critical slots: it never
    /// sends an RTX, and synthesis drops that logic).
    // One long field list: every signal and child block of the struct
    // above, each at its power-up value.
    pub fn with_rtx(format: WordFormat, rtx: bool) -> Self {
        let ext = format == WordFormat::ExtendedAlarm;
        Self {
            clock: Default::default(),
            i_pi: Default::default(),
            i_si: Default::default(),
            o_po: Default::default(),
            o_so: Default::default(),
            i_address: Default::default(),
            i_slots_m1: Default::default(),
            i_period: Default::default(),
            i_cs_timeout: Default::default(),
            i_wb_cyc: Default::default(),
            i_wb_stb: Default::default(),
            i_wb_we: Default::default(),
            i_wb_adr: Default::default(),
            i_wb_dat: Default::default(),
            o_wb_dat: Default::default(),
            o_wb_ack: Default::default(),
            i_irq1: Default::default(),
            i_irq2: Default::default(),
            i_fs_req: Default::default(),
            o_irq1: Default::default(),
            o_irq2: Default::default(),
            o_irq_fs: Default::default(),
            o_irq_rc: Default::default(),
            o_alarmq: Default::default(),
            o_mode: Default::default(),
            o_failsafe: Default::default(),
            o_irq_fsc: Default::default(),
            o_perr: Default::default(),
            o_ferr: Default::default(),
            o_aerr: Default::default(),
            o_serr: Default::default(),
            o_hop: Default::default(),
            o_cycles: Default::default(),
            o_running: Default::default(),
            o_base: Default::default(),
            i_prio: Default::default(),
            i_elect: Default::default(),
            i_flying: Default::default(),
            i_rtx_at: Default::default(),
            i_rtx_atw: Default::default(),
            i_rtx_k: Default::default(),
            i_rtx_kw: Default::default(),
            rx_in: PortRx::new(format),
            rx_bsr: PortRx::new(format),
            ftx: PktTx::new(format),
            stx: PktTx::new(format),
            rep: Default::default(),
            sbox: Default::default(),
            dark: Default::default(),
            tst: TstTx::new(format),
            swc: Default::default(),
            pend_rc: Default::default(),
            ret_rwp: Default::default(),
            sw_flush: Default::default(),
            wrapped: Default::default(),
            rw: Default::default(),
            bss_pair: Default::default(),
            relay_len: Constant::new(
                (if ext { RELAY_BITS_EXT } else { RELAY_BITS } - 14).to_bits(),
            ),
            rdl: Default::default(),
            rdx: Default::default(),
            rcd: Default::default(),
            rcd_run: Default::default(),
            rdata: Default::default(),
            relay: Default::default(),
            rdead: Default::default(),
            rsyn: Default::default(),
            rshift: Default::default(),
            mdb: Mdb::new(format),
            store: Default::default(),
            st_used: Default::default(),
            st_used_slot: Default::default(),
            sent_alarm: Default::default(),
            aact: Default::default(),
            st_r: Default::default(),
            aact_r: Default::default(),
            half: Default::default(),
            bcnt: Default::default(),
            cyc: Default::default(),
            cycles: Default::default(),
            toggle: Default::default(),
            fbusy: Default::default(),
            failsafe: Default::default(),
            fs_tx: Default::default(),
            ret_rwc: Default::default(),
            ret_cyc: Default::default(),
            hop: Default::default(),
            armed: Default::default(),
            ferr_owed: Default::default(),
            cyc_back: Default::default(),
            ret_num: Default::default(),
            last_num: Default::default(),
            cyc_gap: Default::default(),
            ferr_sum: Default::default(),
            quiet: Default::default(),
            sec_sent: Default::default(),
            hop_ref: Default::default(),
            whole: Default::default(),
            clr_sent: Default::default(),
            ret_fs: Default::default(),
            ret_clr: Default::default(),
            ret_seen: Default::default(),
            fs_request: Default::default(),
            host_clear: Default::default(),
            leave: Default::default(),
            clr_fail: Default::default(),
            sec_ok: Default::default(),
            sec_word: Default::default(),
            serr: Default::default(),
            perr: Default::default(),
            ferr: Default::default(),
            pend_fs: Default::default(),
            pend_i1: Default::default(),
            pend_i2: Default::default(),
            prev_alarm: Default::default(),
            fl_v: Default::default(),
            fl_r: Default::default(),
            nxt: Default::default(),
            await_rb: Default::default(),
            seq_tx: Default::default(),
            tick: Default::default(),
            unwrap_lead: Constant::new(UNWRAP_LEAD_BITS.to_bits()),
            one: Constant::new(1.into()),
            jk_bits: Constant::new(crate::line::framer_rx::JK_BITS.to_bits()),
            takeover_lead: Constant::new(TAKEOVER_LEAD_BITS.to_bits()),
            unwrap_at: Default::default(),
            st: Default::default(),
            st_ok: Default::default(),
            prev_cyc: Default::default(),
            reason: Default::default(),
            send_alarm: Default::default(),
            w_data: Default::default(),
            w_alive: Default::default(),
            w_alarm: Default::default(),
            w_void: Default::default(),
            home: Default::default(),
            h0: Default::default(),
            h1: Default::default(),
            sec_h0: Default::default(),
            st_word: Default::default(),
            fwd: Fwd::with_rtx(format, rtx),
            ext: Constant::new(ext),
            rtx_on: Constant::new(rtx),
            w_rn: Default::default(),
            rx_seq: Default::default(),
            rx_rsn: Default::default(),
            txs: Default::default(),
            fs_cleared: Default::default(),
            cb: Default::default(),
            join_r: Default::default(),
            base: Default::default(),
            et: Default::default(),
            rw_hdr: Default::default(),
            last_cyc3: Default::default(),
            cyc_gap3: Default::default(),
            cyc_take: Default::default(),
            fwd_cut: Default::default(),
            rep_cut: Default::default(),
            in_code: Default::default(),
            jk_x: Default::default(),
            jk_z: Default::default(),
            jk_z1: Default::default(),
            jk_ok: Default::default(),
            jk_bad: Default::default(),
            since_jk: Default::default(),
            dcyc: Default::default(),
            dcyc_v: Default::default(),
            scyc: Default::default(),
            scyc_v: Default::default(),
            g0: Default::default(),
            g1: Default::default(),
            g2: Default::default(),
            g3: Default::default(),
            jk_s: Default::default(),
            pass_code: Default::default(),
            crit: Default::default(),
            dl0: Default::default(),
            dl1: Default::default(),
            dl2: Default::default(),
            dl3: Default::default(),
            dl4: Default::default(),
            dl5: Default::default(),
            dl6: Default::default(),
            dl7: Default::default(),
            dcount: Default::default(),
            dst: Default::default(),
            dnext: Default::default(),
            c_v: Default::default(),
            c_slot: Default::default(),
            c_dmg: Default::default(),
            rtxm: Default::default(),
            rk: Default::default(),
            rtx_req: Default::default(),
            d_inpkt: Default::default(),
            s2_rtx: Default::default(),
            bsr_h0ok: Default::default(),
            rtx_cap: Default::default(),
            rtx_t: Default::default(),
            at_t: Default::default(),
            rtx_go: Default::default(),
            rtx_h0: Default::default(),
            cyc_m1: Default::default(),
            rtx_m1: Default::default(),
            rtx_max: Constant::new((RTX_MAX as u64).to_bits()),
        }
    }
}

impl Logic for SpecialMaster {
    // One function of about 800 lines: rust-hdl's `#[hdl_gen]` turns one
    // `update` into the block's Verilog and cannot call helper methods
    // ("Unsupported set method"). Its sections, in order: receive ports
    // and period, headers, the frame's words, alarms, failsafe exit and
    // SEC check, the returning frame, switchbox, store, database, relay and
    // outputs, and last the backup's role before its election.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            st_r,
            aact_r,
            half,
            bcnt,
            cyc,
            cycles,
            toggle,
            fbusy,
            failsafe,
            fs_tx,
            ret_rwc,
            ret_cyc,
            hop,
            armed,
            quiet,
            sec_sent,
            sec_ok,
            sec_word,
            serr,
            perr,
            ferr,
            pend_fs,
            pend_i1,
            pend_i2,
            prev_alarm,
            fl_v,
            fl_r,
            nxt,
            await_rb,
            ferr_owed,
            rdl,
            rdx,
            rcd,
            rcd_run,
            rdata,
            relay,
            rdead,
            pend_rc,
            ret_rwp,
            sw_flush,
            hop_ref,
            whole,
            clr_sent,
            ret_fs,
            ret_clr,
            ret_seen,
            fs_request,
            host_clear,
            st_used,
            st_used_slot,
            last_num,
            cb,
            join_r,
            et,
            rw_hdr,
            last_cyc3,
            fwd_cut,
            rep_cut,
            in_code,
            fs_cleared,
            since_jk,
            dcyc,
            dcyc_v,
            scyc,
            scyc_v,
            dcount,
            dst,
            dnext,
            c_v,
            c_slot,
            c_dmg,
            rtxm,
            rk,
            rtx_req,
            d_inpkt,
            s2_rtx,
            bsr_h0ok,
            dl0,
            dl1,
            dl2,
            dl3,
            dl4,
            dl5,
            dl6,
            dl7,
            rtx_cap,
            rtx_t,
            at_t
        );
        // The clock base: priority 0 from power-up (but after a restart in
        // a ring with backups: JOIN), a backup once elected.
        self.base.next = self.cb.q.val()
            | ((self.i_prio.val() == 0) & !(self.mdb.o_join.val() & self.i_flying.val()));
        self.join_r.d.next = self.mdb.o_join.val() & self.i_flying.val();
        // The slot whose memories the send side reads: the frame
        // generator's, or the forwarder's before the election ([`SlotSel`]).
        self.txs.i_ftx.next = self.ftx.o_slot.val();
        self.txs.i_fwd.next = self.fwd.o_slot.val();
        self.txs.i_cb.next = self.cb.q.val();
        self.txs.i_prio.next = self.i_prio.val();
        self.txs.i_join.next = self.join_r.q.val();
        self.txs.i_rtxm.next = self.rtxm.q.val();
        self.txs.i_rtx.next = self.rtx_req.q.val();
        self.mdb.i_tx_slot.next = self.txs.o_slot.val();
        self.aact.read_address.next = self.txs.o_slot.val();
        self.o_base.next = self.base.val();
        self.sbox.i_mode.next = self.swc.o_mode.val();
        self.sbox.i_pi.next = self.i_pi.val();
        self.sbox.i_si.next = self.i_si.val();
        self.tst.clock.next = self.clock.val();
        self.wrapped.next = self.swc.o_mode.val() != 0;
        // The ring is wrapped: this node, or the last returned header.
        self.rw.next = self.wrapped.val() | self.ret_rwc.q.val() | self.ret_rwp.q.val();
        self.rx_in.clock.next = self.clock.val();
        self.rx_bsr.clock.next = self.clock.val();
        self.ftx.clock.next = self.clock.val();
        self.stx.clock.next = self.clock.val();
        self.mdb.clock.next = self.clock.val();
        self.store.read_clock.next = self.clock.val();
        self.store.write_clock.next = self.clock.val();
        self.crit.read_clock.next = self.clock.val();
        self.crit.write_clock.next = self.clock.val();
        self.sent_alarm.read_clock.next = self.clock.val();
        self.sent_alarm.write_clock.next = self.clock.val();
        self.aact.read_clock.next = self.clock.val();
        self.aact.write_clock.next = self.clock.val();

        // Receive ports (mode N: INPUT = PI, BSR = SI).
        self.rx_in.i_samples.next = self.sbox.o_input.val();
        self.rx_bsr.i_samples.next = self.sbox.o_bsr.val();
        self.rx_in.i_slots_m1.next = self.i_slots_m1.val();
        self.rx_bsr.i_slots_m1.next = self.i_slots_m1.val();
        self.rx_in.i_address.next = self.i_address.val();
        self.rx_bsr.i_address.next = self.i_address.val();
        // In mode N a TST where DATA is expected is a failure; not during
        // the grace period after unwrapping.
        self.rx_in.i_tst_fail.next = !self.wrapped.val() & self.swc.o_grace_over.val();
        self.rx_bsr.i_tst_fail.next = !self.wrapped.val() & self.swc.o_grace_over.val();

        // The period: one tick every i_period bit times once running.
        self.half.d.next = !self.half.q.val();
        self.tick.next = false;
        self.unwrap_at.next = false;
        if self.base.val() & self.mdb.o_running.val() & self.half.q.val() {
            if (self.bcnt.q.val() + self.unwrap_lead.val()) == self.i_period.val() {
                self.unwrap_at.next = true;
            }
            self.bcnt.d.next = self.bcnt.q.val() + 1;
            if (self.bcnt.q.val() + self.one.val()) == self.i_period.val() {
                self.bcnt.d.next = 0.into();
            }
            if self.bcnt.q.val() == 0 {
                self.tick.next = true;
            }
        }

        // Headers (protocol §5).
        self.h0.next = bit_cast::<16, 12>(self.i_slots_m1.val()) | 0;
        if self.failsafe.q.val() {
            self.h0.next = self.h0.val() | 0x2000;
        }
        if self.wrapped.val() {
            self.h0.next = self.h0.val() | 0x1000;
        }
        self.h1.next = 0.into();
        if self.ret_rwc.q.val() {
            self.h1.next = 0x8000.into();
        }
        self.h1.next =
            self.h1.val() | ((bit_cast::<16, 3>(self.cyc.q.val().get_bits::<3>(0)) | 0) << 12);
        self.sec_h0.next = bit_cast::<16, 12>(self.cyc.q.val()) | 0x4000;
        self.ftx.i_start.next = self.tick.val();
        self.ftx.i_slots.next = true;
        self.ftx.i_slots_m1.next = self.i_slots_m1.val();
        self.ftx.i_h0.next = self.h0.val();
        self.ftx.i_h1.next = self.h1.val();
        // The RTX (protocol §8): H0 = {11, 11, CYC of the frame it
        // repairs} (CYC counted on at that frame's end), H1 = NOT H0, two
        // words per request.
        self.cyc_m1.next = self.cyc.q.val() - 1;
        self.rtx_h0.next = (bit_cast::<16, 12>(self.cyc_m1.val()) | 0) | 0xf000;
        self.rtx_m1.next = ((bit_cast::<12, 5>(self.rk.q.val()) | 0) << 1) - 1;
        if self.rtxm.q.val() {
            self.ftx.i_slots_m1.next = self.rtx_m1.val();
            self.ftx.i_h0.next = self.rtx_h0.val();
            self.ftx.i_h1.next = !self.rtx_h0.val();
        }
        // CLR in the frames it sends while it brings the ring out of
        // failsafe (H0's ALIVE bit, protocol §12).
        self.ftx.i_h0_alive.next = self.clr_sent.q.val() != 0;
        self.stx.i_h0_alive.next = false;
        self.stx.i_start.next = self.tick.val() & !self.ret_rwc.q.val() & !self.wrapped.val();
        self.stx.i_slots.next = false;
        self.stx.i_slots_m1.next = self.i_slots_m1.val();
        self.stx.i_h0.next = self.sec_h0.val();
        self.stx.i_h1.next = !self.sec_h0.val();
        self.stx.i_word_data.next = 0.into();
        self.stx.i_word_alive.next = false;
        self.stx.i_word_alarm.next = false;
        self.stx.i_word_void.next = false;
        self.stx.i_word_rn.next = 0.into();

        // The word of slot ftx.o_slot (protocol §7, §8): store, data memory,
        // configuration, actuator Alive, all read at that slot.
        self.store.read_address.next = self.ftx.o_slot.val();
        // The store's and the Alive memory's read data, registered (issue
        // 20: block RAM outputs go to one flip-flop, not through logic);
        // the slot is set 60 bit times before its word is taken and
        // advances when it is, 25 bit times before the next is due.
        self.st_r.d.next = self.store.read_data.val();
        self.aact_r.d.next = self.aact.read_data.val();
        self.st.next = self.st_r.q.val();
        // Returned last cycle: valid bit and the previous cycle's CYC.
        // (CYC − 1 in 3 bits: rust-hdl literals are 32 bits wide, so the
        // subtraction is truncated in its own signal before comparing.)
        self.prev_cyc.next = self.cyc.q.val().get_bits::<3>(0) - 1;
        self.st_ok.next =
            self.st.val().get_bit(18) & (self.st.val().get_bits::<3>(19) == self.prev_cyc.val());
        self.w_data.next = self.st.val().get_bits::<16>(0);
        self.w_alive.next = self.st.val().get_bit(16);
        self.w_alarm.next = self.st.val().get_bit(17);
        self.w_void.next = !self.st_ok.val();
        self.w_rn.next = self.st.val().get_bits::<4>(22);
        self.home.next = self.ftx.o_slot.val() == self.i_address.val();
        // Alarm queue of the home slot: FAILSAFE > RECONFIG > IRQ1 > IRQ2.
        self.reason.next = 2.into();
        if self.pend_i1.q.val() {
            self.reason.next = 1.into();
        }
        if self.pend_rc.q.val() {
            self.reason.next = 4.into();
            if self.swc.o_mode.val() == 1 {
                self.reason.next = 5.into();
            }
            if self.swc.o_mode.val() == 2 {
                self.reason.next = 6.into();
            }
        }
        // A repeat of the alarm in flight goes first, with its SEQ; a
        // FAILSAFE request before it, with SEQ 0 (§11).
        self.seq_tx.next = self.nxt.q.val();
        if self.fl_v.q.val() {
            self.reason.next = self.fl_r.q.val();
            self.seq_tx.next = !self.nxt.q.val();
        }
        if self.pend_fs.q.val() {
            self.reason.next = 3.into();
            self.seq_tx.next = false;
        }
        // Only where the data block lets the node write (not before its
        // host started it, not in the reload frame).
        self.send_alarm.next = self.home.val()
            & ((self.mdb.o_tx_cfg.val() == 1) | (self.mdb.o_tx_cfg.val() == 3))
            & (self.pend_fs.q.val()
                | self.fl_v.q.val()
                | self.pend_rc.q.val()
                | self.pend_i1.q.val()
                | self.pend_i2.q.val())
            & !self.prev_alarm.q.val();
        // What goes in the slot: the data block decides, as for the
        // forwarder (LOCAL, ACT, only an alarm in a home slot without a
        // value, protocol §12); a slot it does not write keeps the store's word.
        if !self.fs_tx.q.val() {
            if self.mdb.o_tx_cfg.val() == 1 {
                // LOCAL.
                self.w_data.next = self.mdb.o_tx_data.val();
                self.w_alive.next = self.toggle.q.val();
                self.w_alarm.next = false;
                self.w_void.next = false;
                self.w_rn.next = 0.into();
            }
            // (send_alarm only where the slot takes an alarm: 1 or 3.)
            // Extended variant: the data memory's value stays, the alarm
            // goes in N1 (§6).
            if self.send_alarm.val() {
                if self.ext.val() {
                    self.w_data.next = self.mdb.o_tx_data.val();
                    self.w_rn.next = self.reason.val() & 7;
                    if self.seq_tx.val() {
                        self.w_rn.next = self.w_rn.val() | 8;
                    }
                } else {
                    self.w_data.next = (bit_cast::<16, 4>(self.reason.val()) | 0) << 12;
                    if self.seq_tx.val() {
                        self.w_data.next = self.w_data.val() | 0x0800;
                    }
                }
                self.w_alive.next = self.toggle.q.val();
                self.w_alarm.next = true;
                self.w_void.next = false;
            }
            if self.mdb.o_tx_cfg.val() == 2 {
                // ACT.
                if !self.st_ok.val() {
                    self.w_data.next = self.mdb.o_tx_data.val();
                    self.w_alive.next = !self.aact_r.q.val();
                    self.w_alarm.next = false;
                    self.w_void.next = false;
                    self.w_rn.next = 0.into();
                } else if !self.w_alarm.val() | self.ext.val() {
                    // (An alarm passes; extended: with the data put in.)
                    self.w_data.next = self.mdb.o_tx_data.val();
                }
            }
        }
        // An RTX's words: an index word {slot}, then the data word, VOID
        // or, for a slot the clock base writes, the value and Alive it
        // wrote into the frame (it toggled at the frame's end; an ACT
        // slot: the actuator's Alive as it last had it).
        if self.rtxm.q.val() {
            self.w_data.next = bit_cast::<16, 12>(self.rtx_req.q.val()) | 0;
            self.w_alive.next = false;
            self.w_alarm.next = false;
            self.w_void.next = false;
            self.w_rn.next = 0.into();
            if self.ftx.o_slot.val().get_bit(0) {
                self.w_data.next = 0.into();
                self.w_void.next = true;
                if !self.fs_tx.q.val() & (self.mdb.o_tx_cfg.val() == 1) {
                    self.w_data.next = self.mdb.o_tx_data.val();
                    self.w_alive.next = !self.toggle.q.val();
                    self.w_void.next = false;
                }
                if !self.fs_tx.q.val() & (self.mdb.o_tx_cfg.val() == 2) {
                    self.w_data.next = self.mdb.o_tx_data.val();
                    self.w_alive.next = self.aact_r.q.val();
                    self.w_void.next = false;
                }
            }
        }
        self.ftx.i_word_data.next = self.w_data.val();
        self.ftx.i_word_alive.next = self.w_alive.val();
        self.ftx.i_word_alarm.next = self.w_alarm.val();
        self.ftx.i_word_void.next = self.w_void.val();
        self.ftx.i_word_rn.next = self.w_rn.val();
        // What a taken word leaves behind (in the clock it is taken): its
        // alarm flag (the retransmit-once rule), the actuator Alive, the
        // alarm queue.
        self.sent_alarm.write_enable.next = self.ftx.o_take.val() & !self.rtxm.q.val();
        self.sent_alarm.write_address.next = self.ftx.o_slot.val();
        self.sent_alarm.write_data.next = self.w_alarm.val() & !self.w_void.val();
        self.aact.write_enable.next = false;
        self.aact.write_address.next = self.ftx.o_slot.val();
        self.aact.write_data.next = self.w_alive.val();
        if self.ftx.o_take.val()
            & !self.rtxm.q.val()
            & !self.fs_tx.q.val()
            & (self.mdb.o_tx_cfg.val() == 2)
        {
            self.aact.write_enable.next = true;
        }
        if self.ftx.o_take.val() & self.home.val() & !self.rtxm.q.val() {
            self.prev_alarm.d.next = self.send_alarm.val() & !self.fs_tx.q.val();
            if !self.fs_tx.q.val() {
                self.await_rb.d.next = self.send_alarm.val() & !self.pend_fs.q.val();
            }
            // Decided from the flags, not from the reason they select
            // (timing: the reason depends on the switchbox mode).
            if self.send_alarm.val() & !self.fs_tx.q.val() {
                if self.pend_fs.q.val() {
                    self.pend_fs.d.next = false;
                    self.failsafe.d.next = true;
                    self.fs_request.d.next = true;
                } else if !self.fl_v.q.val() {
                    // A new alarm (not a repeat): in flight.
                    self.fl_v.d.next = true;
                    self.fl_r.d.next = self.reason.val();
                    self.nxt.d.next = !self.nxt.q.val();
                    if self.pend_rc.q.val() {
                        self.pend_rc.d.next = false;
                    } else if self.pend_i1.q.val() {
                        self.pend_i1.d.next = false;
                    } else {
                        self.pend_i2.d.next = false;
                    }
                }
            }
        }
        if self.i_irq1.val() {
            self.pend_i1.d.next = true;
        }
        if self.i_irq2.val() {
            self.pend_i2.d.next = true;
        }
        if self.i_fs_req.val() {
            self.pend_fs.d.next = true;
        }
        // Frame start and end: CYC, the Alive toggle, the SEC check.
        self.fbusy.d.next = self.ftx.o_busy.val();
        if self.fbusy.q.val() & !self.ftx.o_busy.val() & !self.rtxm.q.val() {
            // CYC counts frames sent: during frame c it is c.
            self.toggle.d.next = !self.toggle.q.val();
            self.cyc.d.next = self.cyc.q.val() + 1;
        }
        // Leaving failsafe at a period tick (protocol §12): after frames
        // came back whole twice in a row, and with the host's FS_CLEAR where
        // that is needed; or failing safe again when the 4th CLR frame did
        // not come back with FS = 0.
        self.leave.next = self.tick.val()
            & self.failsafe.q.val()
            & (self.whole.q.val() >= 2)
            & (!(self.mdb.o_fs_host.val() | self.fs_request.q.val()) | self.host_clear.q.val());
        self.clr_fail.next =
            self.tick.val() & !self.failsafe.q.val() & (self.clr_sent.q.val() >= 4);
        // (Registered: the database's input then does not depend on this
        // block's logic, which reads its outputs; one clock later changes
        // nothing, the clear is a status bit.)
        self.fs_cleared.d.next = self.leave.val() & self.host_clear.q.val();
        self.mdb.i_fs_cleared.next = self.fs_cleared.q.val();
        if self.mdb.o_fs_clear.val() {
            self.host_clear.d.next = true;
        }
        if self.tick.val() {
            self.ret_seen.d.next = false;
            if !self.ret_seen.q.val() {
                // The last frame did not come back: not whole.
                self.whole.d.next = 0.into();
            }
            if self.leave.val() {
                self.failsafe.d.next = false;
                self.clr_sent.d.next = 1.into();
                self.whole.d.next = 0.into();
                self.fs_request.d.next = false;
                self.host_clear.d.next = false;
            } else if self.clr_fail.val() {
                self.failsafe.d.next = true;
                self.clr_sent.d.next = 0.into();
            } else if self.clr_sent.q.val() != 0 {
                self.clr_sent.d.next = self.clr_sent.q.val() + 1;
            }
        }
        if self.tick.val() {
            // A frame is written as the SM's state at its start says: a
            // failsafe entered while it is sent applies from the next one
            // (protocol §12).
            self.fs_tx.d.next = (self.failsafe.q.val() & !self.leave.val()) | self.clr_fail.val();
            self.sec_word.d.next = !self.sec_h0.val();
            if self.cycles.q.val() != 0xffff {
                self.cycles.d.next = self.cycles.q.val() + 1;
            }
            self.sec_sent.d.next = !self.ret_rwc.q.val() & !self.wrapped.val();
            self.sec_ok.d.next = false;
            if self.sec_sent.q.val() & !self.sec_ok.q.val() & (self.serr.q.val() != 0xffff) {
                self.serr.d.next = self.serr.q.val() + 1;
            }
        }
        if self.rx_bsr.o_wvalid.val()
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_kind.val() == 1)
            & (self.rx_bsr.o_ptype.val() == 1)
            & (self.rx_bsr.o_data.val() == self.sec_word.q.val())
        {
            self.sec_ok.d.next = true;
        }

        // Frames without a good header back since the last one (protocol
        // §9): from the SM's own frame count, so 8 or more in a row count
        // too (CYC alone has 3 bits).
        self.cyc_back.next =
            self.cyc.q.val().get_bits::<3>(0) - self.rx_in.o_data.val().get_bits::<3>(12);
        self.ret_num.next = self.cyc.q.val() - (bit_cast::<12, 3>(self.cyc_back.val()) | 0);
        self.cyc_gap.next = self.ret_num.val() - self.last_num.q.val() - 1;
        // The returning frame (protocol §5, §8, §12); every returned packet
        // but a TST restarts the CS timeout (a damaged header too).
        if self.armed.q.val() & (self.quiet.q.val() != 0xfffff) {
            self.quiet.d.next = self.quiet.q.val() + 1;
        }
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 0)
            & !(self.rx_in.o_ok.val() & (self.rx_in.o_ptype.val() == 2))
        {
            self.quiet.d.next = 0.into();
        }
        if self.rx_in.o_wvalid.val() & self.rx_in.o_ok.val() & (self.rx_in.o_ptype.val() == 0) {
            if self.rx_in.o_kind.val() == 0 {
                self.ret_rwc.d.next = self.rx_in.o_data.val().get_bit(12);
                self.ret_fs.d.next = self.rx_in.o_data.val().get_bit(13);
                self.ret_clr.d.next = self.rx_in.o_alive.val();
                // FS without CLR (in CLR frames FS = 1 is a node that has
                // not left yet, protocol §12).
                if self.rx_in.o_data.val().get_bit(13) & !self.rx_in.o_alive.val() {
                    self.failsafe.d.next = true;
                }
                // A backup before its election leaves failsafe like every
                // node: at a CLR header with FS = 0 (§12).
                if !self.base.val()
                    & !self.rx_in.o_data.val().get_bit(13)
                    & self.rx_in.o_alive.val()
                {
                    self.failsafe.d.next = false;
                }
            }
            if self.rx_in.o_kind.val() == 1 {
                self.ret_cyc.d.next = self.rx_in.o_data.val().get_bits::<3>(12);
                self.ret_rwp.d.next = self.rx_in.o_data.val().get_bit(15);
                // Cycles without a good frame back: the gap in frame numbers.
                if self.armed.q.val() {
                    self.ferr_owed.d.next = self.cyc_gap.val();
                }
                self.last_num.d.next = self.ret_num.val();
                self.hop.d.next = self.rx_in.o_data.val().get_bits::<12>(0);
                self.armed.d.next = true;
                // Leaving failsafe (protocol §12): hop_ref outside failsafe;
                // in failsafe, frames back whole (HOP ≥ hop_ref) in a row;
                // a CLR frame back with FS = 0: every node has left.
                self.ret_seen.d.next = true;
                if self.failsafe.q.val() {
                    self.whole.d.next = 0.into();
                    if self.rx_in.o_data.val().get_bits::<12>(0) >= self.hop_ref.q.val() {
                        self.whole.d.next = self.whole.q.val() + 1;
                        if self.whole.q.val() == 3 {
                            self.whole.d.next = 3.into();
                        }
                    }
                } else {
                    self.whole.d.next = 0.into();
                    if !self.ret_fs.q.val() {
                        self.hop_ref.d.next = self.rx_in.o_data.val().get_bits::<12>(0);
                    }
                }
                if (self.clr_sent.q.val() != 0) & self.ret_clr.q.val() & !self.ret_fs.q.val() {
                    self.clr_sent.d.next = 0.into();
                }
            }
        }
        // INPUT's alarm reason and SEQ: D[15:12], D[11]; extended: N1 (§11).
        self.rx_rsn.next = self.rx_in.o_data.val().get_bits::<4>(12);
        self.rx_seq.next = self.rx_in.o_data.val().get_bit(11);
        if self.ext.val() {
            self.rx_rsn.next = self.rx_in.o_reason.val() & 7;
            self.rx_seq.next = self.rx_in.o_reason.val().get_bit(3);
        }
        // A FAILSAFE alarm that comes back (or the SM's own): the ring leaves
        // that failsafe only with the host's FS_CLEAR (protocol §12).
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 2)
            & self.rx_in.o_ok.val()
            & self.rx_in.o_alarm.val()
            & (self.rx_rsn.val() == 3)
        {
            self.fs_request.d.next = true;
        }
        if self.armed.q.val() & (self.quiet.q.val() == self.i_cs_timeout.val()) {
            self.failsafe.d.next = true;
        }
        // A backup before its election sends its alarms like every node
        // (crate::node::slave): through the forwarder, read back at INPUT in the
        // next frame.
        if !self.base.val() & self.fwd.o_alarm_sent.val() {
            if self.fwd.o_sent_reason.val() == 3 {
                self.pend_fs.d.next = false;
                self.failsafe.d.next = true;
            } else if !self.fl_v.q.val() {
                self.nxt.d.next = !self.nxt.q.val();
                self.fl_v.d.next = true;
                self.fl_r.d.next = self.fwd.o_sent_reason.val();
                if self.fwd.o_sent_reason.val() == 1 {
                    self.pend_i1.d.next = false;
                } else if self.fwd.o_sent_reason.val() == 2 {
                    self.pend_i2.d.next = false;
                } else {
                    self.pend_rc.d.next = false;
                }
            }
        }
        if !self.base.val()
            & self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 2)
            & self.rx_in.o_own.val()
            & !self.fwd.o_prev_alarm.val()
            & !self.failsafe.q.val()
            & self.rx_in.o_ok.val()
            & self.rx_in.o_alarm.val()
            & (self.rx_seq.val() != self.nxt.q.val())
        {
            self.fl_v.d.next = false;
        }
        // Switchbox decisions, as every node's (crate::node::switch_ctl); a WD
        // special master unwraps UNWRAP_LEAD_BITS before its next period
        // tick, so that the dark time after the change (crate::node::sw_dark) is
        // over before the frame starts.
        self.swc.clock.next = self.clock.val();
        self.swc.i_armed.next = self.armed.q.val();
        self.swc.i_hard_in.next = self.rx_in.o_hard.val();
        self.swc.i_hard_bsr.next = self.rx_bsr.o_hard.val();
        self.swc.i_run_in.next = self.rx_in.o_run.val();
        self.swc.i_run_bsr.next = self.rx_bsr.o_run.val();
        self.swc.i_los_in.next = self.rx_in.o_los.val();
        self.swc.i_los_bsr.next = self.rx_bsr.o_los.val();
        self.swc.i_rw.next = self.rw.val();
        self.swc.i_fs.next = self.failsafe.q.val();
        self.swc.i_tst_ack.next = self.rx_bsr.o_tst.val() & self.rx_bsr.o_ack.val();
        // The clock base's frame boundary is its period tick (less the
        // unwrap lead); a backup forwards, and its boundary is where its
        // OUTPUT has sent the packet that ended on INPUT (SwitchPipe).
        self.swc.i_frame_start.next = self.unwrap_at.val();
        self.swc.i_fwd.next = !self.base.val();
        self.swc.i_in_pkt.next = self.rx_in.o_inpkt.val();
        self.swc.i_tst_in.next = self.rx_in.o_tst.val();
        self.swc.i_tst_bsr.next = self.rx_bsr.o_tst.val();
        self.swc.i_bsr_data.next = self.rx_bsr.o_wvalid.val()
            & (self.rx_bsr.o_kind.val() == 0)
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_ptype.val() == 0);
        self.swc.i_cs_timeout.next = self.i_cs_timeout.val();
        if self.swc.o_fs_set.val() {
            self.failsafe.d.next = true;
        }
        if self.swc.o_change.val() {
            self.pend_rc.d.next = true;
            // A RECONFIG in flight is replaced by the newer one (§11).
            if self.fl_r.q.val().get_bit(2) {
                self.fl_v.d.next = false;
            }
        }
        // The read-back: the home slot's word as the frame returns (outside
        // failsafe); the alarm itself, good, ends it.
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 2)
            & self.rx_in.o_own.val()
            & self.await_rb.q.val()
            & !self.failsafe.q.val()
        {
            // One writer per slot: a good alarm word with the SEQ in
            // flight is the alarm itself.
            self.await_rb.d.next = false;
            if self.rx_in.o_ok.val()
                & self.rx_in.o_alarm.val()
                & (self.rx_seq.val() != self.nxt.q.val())
            {
                self.fl_v.d.next = false;
            }
        }
        if self.rx_in.o_wvalid.val()
            & ((self.rx_in.o_kind.val() == 2)
                | ((self.rx_in.o_kind.val() == 3) & !self.failsafe.q.val()))
            & !self.rx_in.o_ok.val()
            & !self.rx_in.o_void.val()
            & (self.perr.q.val() != 0xffff)
        {
            self.perr.d.next = self.perr.q.val() + 1;
        }
        self.ferr_sum.next = (bit_cast::<17, 16>(self.ferr.q.val()) | 0)
            + (bit_cast::<17, 12>(self.ferr_owed.q.val()) | 0);
        if self.ferr_owed.q.val() != 0 {
            self.ferr_owed.d.next = 0.into();
            self.ferr.d.next = self.ferr_sum.val().get_bits::<16>(0);
            if self.ferr_sum.val().get_bit(16) {
                self.ferr.d.next = 0xffff.into();
            }
        }
        if self.mdb.o_irq_fs.val() {
            self.failsafe.d.next = true;
        }
        // The return store: {N1 (extended words; 0 with basic ones), CYC,
        // valid, ALARM, ALIVE, data}; a bad or VOID word, or an alarm coming
        // back after the SM sent an alarm in that slot, is stored as not
        // valid (sent as VOID).
        self.sent_alarm.read_address.next = self.rx_in.o_slot.val();
        self.st_word.next = (bit_cast::<26, 16>(self.mdb.o_s2_data.val()) | 0)
            | ((bit_cast::<26, 3>(self.ret_cyc.q.val()) | 0) << 19);
        // (An RTX's copies are the repaired frame's, of the cycle before
        // CYC's count until the next frame ends: also after a damaged
        // header, and when they come back after the next period tick, §8.)
        if self.s2_rtx.q.val() {
            self.st_word.next = (bit_cast::<26, 16>(self.mdb.o_s2_data.val()) | 0)
                | ((bit_cast::<26, 3>(self.prev_cyc.val()) | 0) << 19);
        }
        if self.ext.val() {
            self.st_word.next =
                self.st_word.val() | ((bit_cast::<26, 4>(self.mdb.o_s2_rn.val()) | 0) << 22);
        }
        if self.mdb.o_s2_alive.val() {
            self.st_word.next = self.st_word.val() | 0x10000;
        }
        if self.mdb.o_s2_alarm.val() {
            self.st_word.next = self.st_word.val() | 0x20000;
        }
        if self.mdb.o_s2_ok.val() & !(self.mdb.o_s2_alarm.val() & self.sent_alarm.read_data.val()) {
            self.st_word.next = self.st_word.val() | 0x40000;
        }
        // (Only as the clock base: a backup's store starts empty, §8.)
        self.store.write_enable.next = self.mdb.o_s2.val() & self.base.val();
        self.store.write_address.next = self.mdb.o_s2_slot.val();
        self.store.write_data.next = self.st_word.val();
        // An entry is good for one frame (protocol §8): the clock after its
        // word is taken it is written not valid, or the clock after that if
        // a returned word is written then (o_s2 is one clock per word; a
        // slot's word returns at least a hop after it was sent, so the two
        // never meet in one slot).
        if self.st_used.q.val() & !self.mdb.o_s2.val() {
            self.st_used.d.next = false;
            self.store.write_enable.next = true;
            self.store.write_address.next = self.st_used_slot.q.val();
            self.store.write_data.next = 0.into();
        }
        if self.ftx.o_take.val() & !self.rtxm.q.val() {
            self.st_used.d.next = true;
            self.st_used_slot.d.next = self.ftx.o_slot.val();
        }

        // Retransmission on demand (protocol §8). The CRIT bits, as the
        // host configures them.
        self.crit.write_enable.next = self.mdb.o_cfgw.val() & self.rtx_on.val();
        self.crit.write_address.next = self.mdb.o_cfgw_slot.val();
        self.crit.write_data.next = self.mdb.o_cfgw_crit.val();
        // Omission detection: the returning frame's critical slots whose
        // words come back bad, or do not come back (a frame cut short: the
        // slots after its last word; a rejected header: every slot). A
        // frame that does not come back requests nothing. A slot's CRIT
        // bit is read in the clock it is checked, and counted in the next.
        self.crit.read_address.next = self.rx_in.o_slot.val();
        if self.dst.q.val() == 2 {
            self.crit.read_address.next = self.dnext.q.val();
        }
        self.d_inpkt.d.next = self.rx_in.o_inpkt.val();
        self.c_v.d.next = false;
        if (self.dst.q.val() == 0)
            & self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 1)
            & self.rx_in.o_ok.val()
            & (self.rx_in.o_ptype.val() == 0)
        {
            self.dst.d.next = 1.into();
            self.dnext.d.next = 0.into();
        }
        // (A rejected header counts when H0 was read: a good H0 whose fields
        // are wrong, or a damaged H1; an unreadable H0 is no frame.)
        if (self.dst.q.val() == 0)
            & self.rx_in.o_hdr_bad.val()
            & ((self.rx_in.o_kind.val() == 1) | self.rx_in.o_ok.val())
        {
            self.dst.d.next = 2.into();
            self.dnext.d.next = 0.into();
        }
        if (self.dst.q.val() == 1) & self.d_inpkt.q.val() & !self.rx_in.o_inpkt.val() {
            self.dst.d.next = 2.into();
        }
        if (self.dst.q.val() == 1) & self.rx_in.o_wvalid.val() & (self.rx_in.o_kind.val() == 2) {
            self.c_v.d.next = true;
            self.c_slot.d.next = self.rx_in.o_slot.val();
            self.c_dmg.d.next = !self.rx_in.o_ok.val() & !self.rx_in.o_void.val();
            self.dnext.d.next = self.rx_in.o_slot.val() + 1;
            if self.rx_in.o_slot.val() == self.i_slots_m1.val() {
                self.dst.d.next = 3.into();
            }
        }
        if self.dst.q.val() == 2 {
            self.c_v.d.next = true;
            self.c_slot.d.next = self.dnext.q.val();
            self.c_dmg.d.next = true;
            self.dnext.d.next = self.dnext.q.val() + 1;
            if self.dnext.q.val() == self.i_slots_m1.val() {
                self.dst.d.next = 3.into();
            }
        }
        if self.c_v.q.val()
            & self.c_dmg.q.val()
            & self.crit.read_data.val()
            & (self.dcount.q.val() != self.rtx_max.val())
        {
            self.dcount.d.next = self.dcount.q.val() + 1;
            if self.dcount.q.val() == 0 {
                self.dl0.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 1 {
                self.dl1.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 2 {
                self.dl2.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 3 {
                self.dl3.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 4 {
                self.dl4.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 5 {
                self.dl5.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 6 {
                self.dl6.d.next = self.c_slot.q.val();
            }
            if self.dcount.q.val() == 7 {
                self.dl7.d.next = self.c_slot.q.val();
            }
        }
        // The RTX goes T bit times after the period tick (the frame's J K
        // follows the tick by a group at most), when the frame came back:
        // by then the word of every critical slot has returned or never
        // will (the later slots' words may still be arriving). With the
        // damaged slots in order, as many as the period has room for, not
        // in failsafe.
        // (Registered, issue 20: T and the room follow the wrap a clock
        // later, and the comparison with the period counter is taken in the
        // clock between two of its steps, which changes nothing.)
        self.rtx_t.d.next = self.i_rtx_at.val();
        self.rtx_cap.d.next = self.i_rtx_k.val();
        if self.rw.val() {
            self.rtx_t.d.next = self.i_rtx_atw.val();
            self.rtx_cap.d.next = self.i_rtx_kw.val();
        }
        self.at_t.d.next = self.bcnt.q.val() == self.rtx_t.q.val();
        self.rtx_go.next = self.rtx_on.val()
            & self.base.val()
            & self.mdb.o_running.val()
            & self.half.q.val()
            & self.at_t.q.val()
            & (self.dst.q.val() != 0)
            & (self.dcount.q.val() != 0)
            & (self.rtx_cap.q.val() != 0)
            & !self.fs_tx.q.val()
            & !self.failsafe.q.val();
        if self.rtx_go.val() {
            self.ftx.i_start.next = true;
            self.rtxm.d.next = true;
            self.rk.d.next = self.dcount.q.val();
            if self.dcount.q.val() > self.rtx_cap.q.val() {
                self.rk.d.next = self.rtx_cap.q.val();
            }
        }
        // The request being sent (word `ftx.o_slot`, its pair's entry).
        self.rtx_req.d.next = self.dl0.q.val();
        if self.ftx.o_slot.val().get_bits::<3>(1) == 1 {
            self.rtx_req.d.next = self.dl1.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 2 {
            self.rtx_req.d.next = self.dl2.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 3 {
            self.rtx_req.d.next = self.dl3.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 4 {
            self.rtx_req.d.next = self.dl4.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 5 {
            self.rtx_req.d.next = self.dl5.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 6 {
            self.rtx_req.d.next = self.dl6.q.val();
        }
        if self.ftx.o_slot.val().get_bits::<3>(1) == 7 {
            self.rtx_req.d.next = self.dl7.q.val();
        }
        // A period starts: the search starts afresh.
        if self.tick.val() {
            self.dst.d.next = 0.into();
            self.dcount.d.next = 0.into();
            self.rtxm.d.next = false;
        }

        // The database.
        self.mdb.i_wb_cyc.next = self.i_wb_cyc.val();
        self.mdb.i_wb_stb.next = self.i_wb_stb.val();
        self.mdb.i_wb_we.next = self.i_wb_we.val();
        self.mdb.i_wb_adr.next = self.i_wb_adr.val();
        self.mdb.i_wb_dat.next = self.i_wb_dat.val();
        self.o_wb_dat.next = self.mdb.o_wb_dat.val();
        self.o_wb_ack.next = self.mdb.o_wb_ack.val();
        self.mdb.i_home.next = self.i_address.val();
        self.mdb.i_slots_m1.next = self.i_slots_m1.val();
        self.mdb.i_fs.next = self.failsafe.q.val();
        self.mdb.i_mode.next = self.swc.o_mode.val();
        // INPUT's words; of an RTX only its good requests' data words, as
        // the slot words of the slots named (protocol §8), outside failsafe:
        // the clock base takes them like a master, and into its store.
        self.mdb.i_wvalid.next = self.rx_in.o_wvalid.val()
            & ((self.rx_in.o_ptype.val() != 3) | (self.rx_in.o_kind.val() == 0));
        self.mdb.i_kind.next = self.rx_in.o_kind.val();
        self.mdb.i_slot.next = self.rx_in.o_slot.val();
        self.mdb.i_rtx.next = false;
        if (self.rx_in.o_kind.val() == 3) & self.rtx_on.val() {
            self.mdb.i_wvalid.next = self.rx_in.o_wvalid.val()
                & self.rx_in.o_slot.val().get_bit(0)
                & self.fwd.o_rtx_ok.val()
                & !self.failsafe.q.val();
            self.mdb.i_kind.next = 2.into();
            self.mdb.i_slot.next = self.fwd.o_rtx_idx.val();
            self.mdb.i_rtx.next = true;
        }
        // (In step with the database's `o_s2`.)
        self.s2_rtx.d.next = self.mdb.i_rtx.val();
        self.mdb.i_data.next = self.rx_in.o_data.val();
        self.mdb.i_alive.next = self.rx_in.o_alive.val();
        self.mdb.i_alarm.next = self.rx_in.o_alarm.val();
        self.mdb.i_reason.next = self.rx_in.o_reason.val();
        self.mdb.i_ok.next = self.rx_in.o_ok.val();
        self.mdb.i_hdr_bad.next = self.rx_in.o_hdr_bad.val();

        self.o_irq1.next = self.mdb.o_irq1.val();
        self.o_irq2.next = self.mdb.o_irq2.val();
        self.o_irq_fs.next = self.mdb.o_irq_fs.val();
        self.o_irq_rc.next = self.mdb.o_irq_rc.val();
        self.o_alarmq.next = self.mdb.o_alarmq.val();
        self.o_mode.next = self.swc.o_mode.val();
        self.o_failsafe.next = self.failsafe.q.val();
        self.o_irq_fsc.next = self.mdb.o_irq_fsc.val();
        self.o_perr.next = self.perr.q.val();
        self.o_ferr.next = self.ferr.q.val();
        self.o_aerr.next = self.mdb.o_aerr.val();
        self.o_serr.next = self.serr.q.val();
        self.o_hop.next = self.hop.q.val();
        self.o_cycles.next = self.cycles.q.val();
        self.o_running.next = self.mdb.o_running.val();

        // Secondary relay (protocol §8): a DATA frame on BSR (a wrapped
        // ring) goes on to BSS, RELAY_BITS later; the decision is taken at
        // its H1, before its J has left the delay line. A SEC start hands
        // SO back to the SEC generator. While BSR is dark (no bit in the
        // third clock: a live line gives one every 2 clocks, 3 at most)
        // the delay line of a relayed frame shifts on the node's own
        // timing, a bit with no edge every other clock, until it holds no
        // edge: a dark gap behind a frame (an upstream node's switchbox
        // change) goes on as one, instead of holding the frame's last
        // RELAY_BITS back until the line comes back, by when the next
        // node has ended the packet.
        self.rsyn.next = false;
        if self.rx_bsr.o_bvalid.val() {
            self.rdead.d.next = 0.into();
        } else if self.rdead.q.val() == 2 {
            self.rdead.d.next = 1.into();
            self.rsyn.next = self.base.val()
                & self.relay.q.val()
                & ((self.rdl.q.val() != 0) | (self.ext.val() & (self.rdx.q.val() != 0)));
        } else {
            self.rdead.d.next = self.rdead.q.val() + 1;
        }
        self.rshift.next = self.rx_bsr.o_bvalid.val() | self.rsyn.val();
        self.rep.clock.next = self.clock.val();
        self.rep.i_valid.next = self.rshift.val();
        self.rep.i_code.next = self.rdl.q.val().get_bit(75);
        if self.ext.val() {
            self.rep.i_code.next = self.rdx.q.val().get_bit(9);
        }
        self.rep.i_phase.next = self.rx_bsr.o_phase.val();
        if self.rshift.val() {
            // The delay line holds code bits (level changes).
            self.rdl.d.next = self.rdl.q.val() << 1;
            self.rdx.d.next = self.rdx.q.val() << 1;
            if self.rdl.q.val().get_bit(75) {
                self.rdx.d.next = (self.rdx.q.val() << 1) | 1;
            }
            if self.rx_bsr.o_bvalid.val() & self.rx_bsr.o_code.val() {
                self.rdl.d.next = (self.rdl.q.val() << 1) | 1;
            }
            if self.rcd_run.q.val() {
                self.rcd.d.next = self.rcd.q.val() - 1;
                if self.rcd.q.val() == 1 {
                    // Relayed only when its H1 showed DATA: anything else
                    // (the SM's own SEC, a TST's remains, a fragment)
                    // would otherwise go round the secondary ring, which
                    // is a closed loop in a healthy ring, for ever.
                    self.rcd_run.d.next = false;
                    self.relay.d.next = self.rdata.q.val();
                }
            }
        }
        // (A retransmission packet takes the frame's path too, and so does
        // a frame whose H1 a bit error damaged after a good H0: it goes on
        // to the special master's INPUT, which reads its header as
        // damaged, §8.)
        if self.rx_bsr.o_wvalid.val() & (self.rx_bsr.o_kind.val() == 0) {
            self.bsr_h0ok.d.next = self.rx_bsr.o_ok.val();
        }
        if self.rx_bsr.o_wvalid.val()
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_kind.val() == 1)
            & ((self.rx_bsr.o_ptype.val() == 0) | (self.rx_bsr.o_ptype.val() == 3))
        {
            self.rdata.d.next = true;
        }
        if self.rx_bsr.o_wvalid.val()
            & !self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_kind.val() == 1)
            & self.bsr_h0ok.q.val()
            & (self.rx_bsr.o_ptype.val() == 0)
        {
            self.rdata.d.next = true;
        }
        if self.rx_bsr.o_start.val() {
            // The J entered about 10 bits ago: it leaves the delay line
            // RELAY_BITS − 10 bits from now; switch 4 bits before.
            self.rcd.d.next = self.relay_len.val();
            self.rcd_run.d.next = true;
            self.rdata.d.next = false;
        }
        if self.stx.i_start.val() {
            self.relay.d.next = false;
        }
        if self.sw_flush.q.val() {
            // BSR moved to another line (into or out of WU): a packet the
            // old line was carrying is not relayed.
            self.rcd_run.d.next = false;
            self.rdata.d.next = false;
            self.relay.d.next = false;
        }
        // BSS: the SEC or the relayed frame in mode N, TST when wrapped.
        self.tst.i_ack.next = self.rx_bsr.o_tst.val();
        // At a switch the TST generator starts with a dark lead-in, and
        // the receivers, whose lines change, drop what they were in.
        self.tst.i_restart.next = self.swc.o_tst_start.val();
        // (Registered: the switch decision depends on what they report.)
        self.sw_flush.d.next = self.swc.o_relink.val();
        self.rx_in.i_flush.next = self.sw_flush.q.val();
        self.rx_bsr.i_flush.next = self.sw_flush.q.val();
        self.tst.i_address.next = self.i_address.val();
        self.bss_pair.next = self.stx.o_line.val();
        if self.relay.q.val() {
            self.bss_pair.next = self.rep.o_line.val();
        }
        if self.wrapped.val() {
            self.bss_pair.next = self.tst.o_line.val();
        }
        self.sbox.i_output.next = self.ftx.o_line.val();
        self.sbox.i_bss.next = self.bss_pair.val();
        // After a switchbox change both outputs are dark for a while, so
        // no downstream receiver splices the old source with the new.
        self.dark.clock.next = self.clock.val();
        self.dark.i_change.next = self.swc.o_change.val();
        // PO carries the frame generator in N and in WU: a change between
        // the two (into or out of WU) does not cut the SM's own frame.
        self.dark.i_keep_po.next = self.swc.o_relink.val();
        self.dark.i_po.next = self.sbox.o_po.val();
        self.dark.i_so.next = self.sbox.o_so.val();
        self.o_po.next = self.dark.o_po.val();
        self.o_so.next = self.dark.o_so.val();

        // A backup before its election (protocol §8): a master like any other
        // ([`crate::node::master`]: the forwarder in master mode on OUTPUT, BSR
        // repeated on BSS in mode N, failsafe left at a CLR header), with an
        // election timer that makes it the clock base. Everything here is
        // overridden by the clock base's logic above once `base` is set (or
        // from power-up with priority 0), so that node is the special master
        // exactly as before.
        // The forwarder, as in a master (crate::node::slave).
        self.fwd.clock.next = self.clock.val();
        self.fwd.i_bvalid.next = self.rx_in.o_bvalid.val();
        self.fwd.i_code.next = self.rx_in.o_code.val();
        self.fwd.i_phase.next = self.rx_in.o_phase.val();
        self.fwd.i_hdr_bad.next = self.rx_in.o_hdr_bad.val()
            | (self.rx_in.o_wvalid.val()
                & (self.rx_in.o_kind.val() == 0)
                & self.rx_in.o_ok.val()
                & (self.rx_in.o_ptype.val() != 0)
                & (self.rx_in.o_ptype.val() != 3));
        self.fwd.i_armed.next = self.armed.q.val();
        self.fwd.i_wvalid.next = self.rx_in.o_wvalid.val();
        self.fwd.i_wkind.next = self.rx_in.o_kind.val();
        self.fwd.i_wodd.next = self.rx_in.o_slot.val().get_bit(0);
        self.fwd.i_wok.next = self.rx_in.o_ok.val();
        self.fwd.i_walarm.next = self.rx_in.o_alarm.val();
        self.fwd.i_wdata.next = self.rx_in.o_data.val();
        self.fwd.i_ptype.next = self.rx_in.o_ptype.val();
        if !self.rx_in.o_inpkt.val() {
            self.fwd_cut.d.next = false;
        }
        if self.rx_in.o_wvalid.val()
            & (self.rx_in.o_kind.val() == 0)
            & self.rx_in.o_ok.val()
            & (self.rx_in.o_ptype.val() == 2)
        {
            self.fwd_cut.d.next = true;
        }
        self.fwd.i_mute.next = self.fwd_cut.q.val();
        self.fwd.i_slots_m1.next = self.i_slots_m1.val();
        self.fwd.i_address.next = self.i_address.val();
        self.fwd.i_actuator.next = false;
        self.fwd.i_sensor_data.next = 0.into();
        self.fwd.i_act_out.next = 0.into();
        self.fwd.i_fs.next = self.failsafe.q.val();
        self.fwd.i_wrapped.next = self.wrapped.val();
        self.fwd.i_master.next = true;
        self.fwd.i_alarm_req.next = !self.base.val()
            & (self.pend_fs.q.val()
                | self.fl_v.q.val()
                | self.pend_rc.q.val()
                | self.pend_i1.q.val()
                | self.pend_i2.q.val());
        self.fwd.i_alarm_reason.next = self.reason.val();
        self.fwd.i_alarm_seq.next = self.seq_tx.val();
        // As in a master (crate::node::master): the data block decides what goes
        // in each slot (protocol §12), once the host started the node.
        self.fwd.i_slot_cfg.next = 0.into();
        if self.mdb.o_running.val() {
            self.fwd.i_slot_cfg.next = self.mdb.o_tx_cfg.val();
        }
        self.fwd.i_slot_data.next = self.mdb.o_tx_data.val();
        self.fwd.i_slot_alive.next = self.aact.read_data.val();
        // BSR repeated bit for bit in mode N; a TST's rest cut (protocol §9).
        if !self.rx_bsr.o_inpkt.val() {
            self.rep_cut.d.next = false;
        }
        if self.rx_bsr.o_wvalid.val()
            & (self.rx_bsr.o_kind.val() == 0)
            & self.rx_bsr.o_ok.val()
            & (self.rx_bsr.o_ptype.val() == 2)
        {
            self.rep_cut.d.next = true;
        }
        self.pass_code.next = self.rx_bsr.o_code.val() | self.rep_cut.q.val();
        // What a header tells a master (crate::node::slave): the ring known
        // wrapped, and the frames missed since the last good one.
        self.cyc_gap3.next = self.rx_in.o_data.val().get_bits::<3>(12) - self.last_cyc3.q.val() - 1;
        self.cyc_take.next = self.last_cyc3.q.val() + self.i_prio.val() + 1;
        // Election timer (protocol §8): bit times since the last packet
        // that restarted it started on INPUT (below): its J K (`o_start`),
        // or, where a bit error destroyed a DATA frame's J K,
        // [`START_BITS`] code bits that show idle 1s (the 9 oldest), ten
        // that are J K but for one line-bit error (one code bit, or two
        // neighbours: NRZI) and H0's first four groups, which carry S − 1
        // (the first group's two bits of it unless the error, at J K's last
        // bit, reached it). Inside a packet data never has nine 1s in a row. What
        // circulates in a ring wrapped around the dead clock base, where
        // nothing filters it, is idles and dark stretches of up to 8 0s,
        // and after them, where a node relocked, short runs of 0s: with
        // only two data groups after the J K (until 2026-12-04) such a
        // line showed "J K but for one error, 0, 7" (a dark stretch of 7,
        // five 1s, two 0s) to a backup of an 8-node ring, whose timer then
        // restarted and expired after its CS timeout: the ring failed
        // safe instead of taking over. Now a false start needs two more
        // groups and twelve bits of S − 1 to match; it
        // is not proven impossible (garbage is any string), it is not seen
        // in the full campaign (docs/campaign/campaign.md).
        if self.half.q.val() & (self.et.q.val() != 0xfffff) {
            self.et.d.next = self.et.q.val() + 1;
        }
        if self.rx_in.o_bvalid.val() {
            self.in_code.d.next = self.in_code.q.val() << 1;
            if self.rx_in.o_code.val() {
                self.in_code.d.next = (self.in_code.q.val() << 1) | 1;
            }
        }
        self.jk_x.next = self.in_code.q.val().get_bits::<10>(20) ^ self.jk_bits.val();
        self.jk_z.next = self.jk_x.val() & (self.jk_x.val() - 1);
        self.jk_z1.next = self.jk_z.val() - 1;
        self.jk_ok.next = (self.jk_z.val() == 0)
            | ((self.jk_x.val() == (self.jk_z.val() | (self.jk_z.val() >> 1)))
                & ((self.jk_z.val() & self.jk_z1.val()) == 0));
        self.g0.i_code.next = self.in_code.q.val().get_bits::<5>(15);
        self.g1.i_code.next = self.in_code.q.val().get_bits::<5>(10);
        self.g2.i_code.next = self.in_code.q.val().get_bits::<5>(5);
        self.g3.i_code.next = self.in_code.q.val().get_bits::<5>(0);
        // H0 = {00, FS, RWC, S − 1}, least significant bits first (protocol
        // §4): its groups carry {ALARM, ALIVE, D1, D0}, D[5:2], D[9:6],
        // D[13:10], so S − 1 is in the low two bits of the first and the
        // fourth and in the second and the third.
        self.jk_s.next = self.g1.o_data.val()
            & self.g2.o_data.val()
            & self.g3.o_data.val()
            & (self.g1.o_nibble.val() == self.i_slots_m1.val().get_bits::<4>(2))
            & (self.g2.o_nibble.val() == self.i_slots_m1.val().get_bits::<4>(6))
            & (self.g3.o_nibble.val().get_bits::<2>(0) == self.i_slots_m1.val().get_bits::<2>(10));
        // Extended words (protocol §6): the second group is the reason
        // nibble, 0 in a header; S − 1's bits 9:0 follow in the same window.
        if self.ext.val() {
            self.jk_s.next = self.g1.o_data.val()
                & self.g2.o_data.val()
                & self.g3.o_data.val()
                & (self.g1.o_nibble.val() == 0)
                & (self.g2.o_nibble.val() == self.i_slots_m1.val().get_bits::<4>(2))
                & (self.g3.o_nibble.val() == self.i_slots_m1.val().get_bits::<4>(6));
        }
        self.jk_bad.next = (self.in_code.q.val().get_bits::<9>(30) == 0x1ff)
            & self.jk_ok.val()
            & (self.jk_x.val() != 0)
            & ((self.g0.o_data.val()
                & (self.g0.o_nibble.val().get_bits::<2>(0)
                    == self.i_slots_m1.val().get_bits::<2>(0)))
                | self.jk_x.val().get_bit(0))
            & self.jk_s.val();
        // Bit times since the packet now on INPUT started.
        if self.half.q.val() & (self.since_jk.q.val() != 0xfffff) {
            self.since_jk.d.next = self.since_jk.q.val() + 1;
        }
        if self.rx_in.o_start.val() | self.jk_bad.val() {
            self.since_jk.d.next = 0.into();
        }
        // Which packets restart the timer (counted from their start): a
        // DATA frame with a CYC other than the last one's, a SEC with a
        // CYC other than the last one's, a TST, and a damaged packet (a
        // rejected header or a destroyed J K: a bit error). Not a packet
        // seen again: in a ring wrapped around the dead clock base nothing
        // absorbs what was on its way when it died (the rest of its last
        // frame, its SEC), and that circulates, once per ring latency,
        // until a clock base takes it off (protocol §8).
        if self.rx_in.o_wvalid.val() & self.rx_in.o_ok.val() {
            if (self.rx_in.o_kind.val() == 1)
                & (self.rx_in.o_ptype.val() == 0)
                & (!self.dcyc_v.q.val()
                    | (self.rx_in.o_data.val().get_bits::<3>(12) != self.dcyc.q.val()))
            {
                self.dcyc_v.d.next = true;
                self.dcyc.d.next = self.rx_in.o_data.val().get_bits::<3>(12);
                self.et.d.next = self.since_jk.q.val();
            }
            if (self.rx_in.o_kind.val() == 0)
                & (self.rx_in.o_ptype.val() == 1)
                & (!self.scyc_v.q.val()
                    | (self.rx_in.o_data.val().get_bits::<12>(0) != self.scyc.q.val()))
            {
                self.scyc_v.d.next = true;
                self.scyc.d.next = self.rx_in.o_data.val().get_bits::<12>(0);
                self.et.d.next = self.since_jk.q.val();
            }
            if (self.rx_in.o_kind.val() == 0) & (self.rx_in.o_ptype.val() == 2) {
                self.et.d.next = self.since_jk.q.val();
            }
        }
        if self.rx_in.o_hdr_bad.val() | self.jk_bad.val() {
            self.et.d.next = self.since_jk.q.val();
            if self.jk_bad.val() {
                self.et.d.next = 0.into();
            }
        }
        if self.base.val() {
            self.et.d.next = 0.into();
        }
        // (A frame seen again, circulating in a ring wrapped around the
        // dead clock base, is not a new header: its RWC, which a wrapped
        // node set on its way round, does not make the backup ineligible.)
        if !self.base.val()
            & self.rx_in.o_wvalid.val()
            & self.rx_in.o_ok.val()
            & (self.rx_in.o_ptype.val() == 0)
            & (self.rx_in.o_kind.val() == 1)
            & (!self.dcyc_v.q.val()
                | (self.rx_in.o_data.val().get_bits::<3>(12) != self.dcyc.q.val()))
        {
            self.rw_hdr.d.next =
                self.ret_rwc.q.val() | self.rx_in.o_data.val().get_bit(15) | self.wrapped.val();
            self.last_cyc3.d.next = self.rx_in.o_data.val().get_bits::<3>(12);
            self.ferr_owed.d.next = 0.into();
            if self.armed.q.val() {
                self.ferr_owed.d.next = bit_cast::<12, 3>(self.cyc_gap3.val()) | 0;
            }
        }
        if !self.base.val() {
            self.toggle.d.next = self.fwd.o_toggle.val();
        }
        if !self.base.val() {
            self.swc.i_rw.next = self.rw_hdr.q.val();
        }
        if !self.base.val() {
            // Actuator Alive, as in a master: a good word in an ACT slot
            // sets it, a regenerated VOID flips it (protocol §7).
            self.aact.write_enable.next = false;
            self.aact.write_address.next = self.mdb.o_s2_slot.val();
            self.aact.write_data.next = self.mdb.o_s2_alive.val();
            if self.mdb.o_s2.val()
                & self.mdb.o_s2_ok.val()
                & self.mdb.o_s2_act.val()
                & !self.failsafe.q.val()
            {
                self.aact.write_enable.next = true;
            }
            if self.fwd.o_regen.val() {
                self.aact.write_enable.next = true;
                self.aact.write_address.next = self.fwd.o_slot.val();
                self.aact.write_data.next = !self.aact.read_data.val();
            }
        }
        if !self.base.val() {
            self.rep.i_valid.next = self.rx_bsr.o_bvalid.val();
            self.rep.i_code.next = self.pass_code.val();
            self.bss_pair.next = self.rep.o_line.val();
            if self.wrapped.val() {
                self.bss_pair.next = self.tst.o_line.val();
            }
            self.sbox.i_output.next = self.fwd.o_line.val();
            self.sbox.i_bss.next = self.bss_pair.val();
            self.dark.i_keep_po.next = false;
        }
        if !self.base.val() {
            // Takeover (protocol §8): the timer ran out, and the backup is
            // armed, not in failsafe, and did not know the ring wrapped at
            // its last good header (the clock base's death as a first
            // fault). It starts a frame at once, CYC continuing the count;
            // what a clock base learns from returning frames starts afresh.
            if self.mdb.o_running.val()
                & (self.i_prio.val() != 0)
                & self.armed.q.val()
                & !self.failsafe.q.val()
                & !self.rw_hdr.q.val()
                & (self.et.q.val() == self.i_elect.val())
            {
                self.cb.d.next = true;
                // The first frame TAKEOVER_LEAD_BITS later: its OUTPUT
                // carried the forwarder's stream until now (idles, or a
                // dark stretch circulating in the ring wrapped around the
                // dead clock base), and the receivers downstream relock on
                // idles before the frame's J K.
                self.bcnt.d.next = self.i_period.val() - self.takeover_lead.val();
                self.cyc.d.next = bit_cast::<12, 3>(self.cyc_take.val()) | 0;
                self.last_num.d.next = (bit_cast::<12, 3>(self.cyc_take.val()) | 0) - 1;
                self.ret_rwc.d.next = false;
                self.ret_rwp.d.next = false;
                self.hop_ref.d.next = 0.into();
                self.whole.d.next = 0.into();
                self.clr_sent.d.next = 0.into();
                self.fs_request.d.next = false;
                self.host_clear.d.next = false;
            }
        }
    }
}

/// The slot whose memories a backup's send side reads (the database's and
/// the actuator Alive memory's read address): the frame generator's once
/// the node is the clock base, else the forwarder's. A block of its own so
/// that the address is not computed in [`SpecialMaster`]'s logic, which
/// reads the database's outputs: Verilator orders a block's combinational
/// logic as one piece, and the database's outputs depend on its inputs
/// there, so the mux inside the node would be a combinational loop
/// (UNOPTFLAT).
#[derive(LogicBlock, Default)]
pub struct SlotSel {
    /// The frame generator's slot.
    pub i_ftx: Signal<In, Bits<12>>,
    /// The forwarder's slot.
    pub i_fwd: Signal<In, Bits<12>>,
    /// Elected (the node's `cb` register).
    pub i_cb: Signal<In, Bit>,
    /// Backup priority (0: the clock base from power-up).
    pub i_prio: Signal<In, Bits<3>>,
    /// Priority 0 restarted in a ring with backups: a master (a register).
    pub i_join: Signal<In, Bit>,
    /// The clock base sends an RTX (a register): the slot of its request.
    pub i_rtxm: Signal<In, Bit>,
    /// See `i_rtxm`.
    pub i_rtx: Signal<In, Bits<12>>,
    /// The slot to read.
    pub o_slot: Signal<Out, Bits<12>>,
}

impl Logic for SlotSel {
    #[hdl_gen]
    fn update(&mut self) {
        self.o_slot.next = self.i_ftx.val();
        if self.i_rtxm.val() {
            self.o_slot.next = self.i_rtx.val();
        }
        if !self.i_cb.val() & ((self.i_prio.val() != 0) | self.i_join.val()) {
            self.o_slot.next = self.i_fwd.val();
        }
    }
}
