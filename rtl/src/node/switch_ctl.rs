//! # switch_ctl — a node's switchbox decisions (protocol §10, §12)
//!
//! Purpose: the local fault management of every node, the special master
//! included: from its two stream controllers it decides the switchbox mode
//! (Table 1), the failsafe of a second fault, and reintegration when a
//! repaired link's partner acknowledges its TST. No central station: each
//! node runs one of these on what it sees.
//!
//! - mode N: INPUT fails → WU; else BSR fails → WD. A structural failure
//!   (`i_hard_*`: loss of signal, a TST where DATA is expected) while the
//!   node knows the ring is wrapped is the second fault: failsafe, and so is
//!   loss of signal on both at once. A run of bad words (`i_run_*`, a
//!   transient) counts only while the ring is not known wrapped (a soft
//!   wrap), and never for failsafe (protocol §9, §12);
//! - wrapped: loss of signal on INPUT → failsafe; the partner's TST with
//!   ACK heard on BSR → a WD node unwraps at the next frame start after
//!   [`REINTEGRATE_CLOCKS`] of it, a WU node when a DATA
//!   header arrives on BSR after it and no packet is arriving on INPUT (if
//!   one is — the frame that went the long way round — when it ends, so it
//!   is not cut into the new one); in failsafe too (issue 28: that is how a
//!   ring that failed safe becomes whole again), where a WU node takes a
//!   DATA header on BSR for the ACK (its upstream neighbour forwards the
//!   ring's frames to it, so it is not wrapped towards it: the special
//!   master's downstream neighbour, cut off with it, hears no TST);
//! - stream controllers act only once the node is armed (its first good
//!   frame) and not for [`SETTLE_CLOCKS`] after a change (the
//!   receivers lock to their new lines); after unwrapping, a TST where DATA
//!   is expected is not a failure for half a CS timeout (`o_grace_over`);
//! - restart and rejoin (§12): an unarmed node in mode N wraps up (WU) on a
//!   TST where DATA is expected on a lit INPUT (a restarted node between
//!   wrapped neighbours), and unwraps like an armed one; a node that is
//!   still rejoining (from power-up until, at a frame boundary, it is in
//!   mode N, armed, with no TST on INPUT or BSR: `joined`) turns round at
//!   its WU unwrap (WU → WD) when a TST arrives on INPUT (its downstream
//!   neighbour is wrapped towards it), so the ring stays closed.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_armed` | in | 1 | clock | the node has received its first good frame |
//! | `i_hard_in`, `i_hard_bsr` | in | 1 | clock | structural channel failure on INPUT, on BSR ([`crate::node::stream_ctl`]) |
//! | `i_run_in`, `i_run_bsr` | in | 1 | clock | a run of bad words on INPUT, on BSR |
//! | `i_los_in`, `i_los_bsr` | in | 1 | clock | loss of signal on INPUT, on BSR |
//! | `i_rw` | in | 1 | clock | the node knows the ring is wrapped |
//! | `i_fs` | in | 1 | clock | the node is in failsafe |
//! | `i_tst_ack` | in | 1 | clock | a TST with ACK is being heard on BSR |
//! | `i_frame_start` | in | 1 | clock | a frame boundary: between frames on INPUT (a slave: a packet ended there and OUTPUT has sent it, [`SwitchPipe`]); the special master's period tick |
//! | `i_bsr_data` | in | 1 | clock | a good DATA H0 on BSR |
//! | `i_in_pkt` | in | 1 | clock | a packet is arriving on INPUT (a slave: or OUTPUT is still sending it, [`SwitchPipe`]) |
//! | `i_tst_in`, `i_tst_bsr` | in | 1 | clock | a TST was heard on INPUT, on BSR, in the last 130 bit times ([`crate::node::stream_ctl`] `o_tst`) |
//! | `i_cs_timeout` | in | 20 | static | CS timeout, clocks |
//! | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD), registered |
//! | `o_change` | out | 1 | clock | the mode changes at the next clock edge (combinational) |
//! | `o_relink` | out | 1 | clock | … and INPUT and BSR move to other lines (into or out of WU) |
//! | `o_tst_start` | out | 1 | clock | … and the TST generator goes onto an output (N → WU, WD) |
//! | `o_fs_set` | out | 1 | clock | enter failsafe (combinational) |
//! | `o_grace_over` | out | 1 | clock | a TST on a mode-N input counts as failure again |
//!
//! Latency: a decision takes effect at the next clock edge (`o_mode`).
//!
//! ```text
//! i_hard_in ____/‾‾‾‾‾‾‾‾‾
//! o_change  ____/‾\________        (mode N, ring not known wrapped)
//! o_mode    ==N===X==WU====
//! ```

use rust_hdl::prelude::*;

/// Clocks a repaired link must show ACKed TST before a WD node unwraps (2 TST periods).
pub const REINTEGRATE_CLOCKS: u64 = 260;
// `ack_time` (9 bits) counts up to REINTEGRATE_CLOCKS and stops there.
const _: () = assert!(REINTEGRATE_CLOCKS < 512);
/// Clocks after a switchbox change during which the stream controllers are
/// not acted on (50 bit times: the receivers lock to their new lines).
pub const SETTLE_CLOCKS: u64 = 100;
/// Clocks from the end of a packet on INPUT until a forwarding node's
/// OUTPUT has sent its last bit and the frame boundary is reached (10 bit
/// times). The packet's last bits are still in the forwarder, the retime
/// buffer and the output register then: `unwrapping_cuts_no_frame`
/// (sim/tests/slave_modes.rs) fails below 16 clocks. With the 12 dark bit
/// times of the change after it, the boundary stays inside the 20-bit
/// minimum gap plus the next frame's forwarding delay (protocol §8, §12).
pub const DRAIN_CLOCKS: u64 = 20;
// `drain` (5 bits) counts down from DRAIN_CLOCKS.
const _: () = assert!(DRAIN_CLOCKS < 32);

/// Switchbox decision logic.
#[derive(LogicBlock)]
pub struct SwitchCtl {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// First good frame seen.
    pub i_armed: Signal<In, Bit>,
    /// Structural channel failure on INPUT.
    pub i_hard_in: Signal<In, Bit>,
    /// Structural channel failure on BSR.
    pub i_hard_bsr: Signal<In, Bit>,
    /// A run of bad words on INPUT.
    pub i_run_in: Signal<In, Bit>,
    /// A run of bad words on BSR.
    pub i_run_bsr: Signal<In, Bit>,
    /// Loss of signal on INPUT.
    pub i_los_in: Signal<In, Bit>,
    /// Loss of signal on BSR.
    pub i_los_bsr: Signal<In, Bit>,
    /// The ring is known wrapped.
    pub i_rw: Signal<In, Bit>,
    /// The node is in failsafe.
    pub i_fs: Signal<In, Bit>,
    /// Partner's TST with ACK on BSR.
    pub i_tst_ack: Signal<In, Bit>,
    /// A frame starts.
    pub i_frame_start: Signal<In, Bit>,
    /// A good DATA H0 on BSR.
    pub i_bsr_data: Signal<In, Bit>,
    /// A packet is arriving on INPUT.
    pub i_in_pkt: Signal<In, Bit>,
    /// A TST heard on INPUT.
    pub i_tst_in: Signal<In, Bit>,
    /// A TST heard on BSR.
    pub i_tst_bsr: Signal<In, Bit>,
    /// CS timeout, clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// The mode changes at the next edge.
    pub o_change: Signal<Out, Bit>,
    /// The receivers' lines move.
    pub o_relink: Signal<Out, Bit>,
    /// TST goes onto an output.
    pub o_tst_start: Signal<Out, Bit>,
    /// Enter failsafe.
    pub o_fs_set: Signal<Out, Bit>,
    /// Grace period over.
    pub o_grace_over: Signal<Out, Bit>,
    reint_m1: Constant<Bits<9>>,
    settle_start: Constant<Bits<7>>,
    mode: DFF<Bits<2>>,
    /// The mode changed at the last clock edge. The counters start in the
    /// clock after a change, from this register, a count further on
    /// (issue 21: the change decision is not repeated in front of every
    /// counter bit; on a CoolRunner-II each bit is a T flip-flop of two
    /// product terms).
    chg: DFF<Bit>,
    /// Settling after a change: `busy` (with `chg`) is what `settle != 0`
    /// would be with the counter loaded at the change itself.
    settle: DFF<Bits<7>>,
    busy: DFF<Bit>,
    /// The grace period after unwrapping (half a CS timeout): `run` is
    /// what `grace != 0` would be with the counter loaded at the unwrap
    /// itself; the counter starts the clock after (from `chg` in mode N:
    /// only an unwrap changes into mode N).
    grace: DFF<Bits<20>>,
    run: DFF<Bit>,
    ack_time: DFF<Bits<9>>,
    ack_done: DFF<Bit>,
    seen_ack: DFF<Bit>,
    pend_up: DFF<Bit>,
    joined: DFF<Bit>,
    new_mode: Signal<Local, Bits<2>>,
    fail_in: Signal<Local, Bit>,
    fail_bsr: Signal<Local, Bit>,
    up_ok: Signal<Local, Bit>,
    acting: Signal<Local, Bit>,
    live: Signal<Local, Bit>,
    wake: Signal<Local, Bit>,
    turn: Signal<Local, Bit>,
    in_n: Signal<Local, Bit>,
    go_wu: Signal<Local, Bit>,
    go_wd: Signal<Local, Bit>,
    unwrap: Signal<Local, Bit>,
    bsr_ok: Signal<Local, Bit>,
    ack_inc: Signal<Local, Bit>,
    grace_l: Signal<Local, Bits<20>>,
    grace_m: Signal<Local, Bits<20>>,
}

impl Default for SwitchCtl {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_armed: Default::default(),
            i_hard_in: Default::default(),
            i_hard_bsr: Default::default(),
            i_run_in: Default::default(),
            i_run_bsr: Default::default(),
            i_los_in: Default::default(),
            i_los_bsr: Default::default(),
            i_rw: Default::default(),
            i_fs: Default::default(),
            i_tst_ack: Default::default(),
            i_frame_start: Default::default(),
            i_bsr_data: Default::default(),
            i_in_pkt: Default::default(),
            i_tst_in: Default::default(),
            i_tst_bsr: Default::default(),
            i_cs_timeout: Default::default(),
            o_mode: Default::default(),
            o_change: Default::default(),
            o_relink: Default::default(),
            o_tst_start: Default::default(),
            o_fs_set: Default::default(),
            o_grace_over: Default::default(),
            reint_m1: Constant::new((REINTEGRATE_CLOCKS - 1).to_bits()),
            settle_start: Constant::new(SETTLE_CLOCKS.to_bits()),
            mode: Default::default(),
            settle: Default::default(),
            busy: Default::default(),
            grace: Default::default(),
            chg: Default::default(),
            run: Default::default(),
            ack_time: Default::default(),
            ack_done: Default::default(),
            seen_ack: Default::default(),
            pend_up: Default::default(),
            joined: Default::default(),
            new_mode: Default::default(),
            fail_in: Default::default(),
            fail_bsr: Default::default(),
            up_ok: Default::default(),
            acting: Default::default(),
            live: Default::default(),
            wake: Default::default(),
            turn: Default::default(),
            in_n: Default::default(),
            go_wu: Default::default(),
            go_wd: Default::default(),
            unwrap: Default::default(),
            bsr_ok: Default::default(),
            ack_inc: Default::default(),
            grace_l: Default::default(),
            grace_m: Default::default(),
        }
    }
}

impl Logic for SwitchCtl {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, mode, chg, settle, busy, grace, run, ack_time, ack_done, seen_ack,
            pend_up, joined
        );
        self.chg.d.next = false;
        // The grace period: the counter, loaded a clock after the unwrap
        // with one less, counts down to 0 in the clock the grace ends.
        self.grace_l.next = self.i_cs_timeout.val() >> 1;
        // Every bit below the load value's highest one (the count never
        // leaves them, so in a top with a constant CS timeout synthesis
        // drops the bits above, as with the 20-bit `grace != 0` test before).
        self.grace_m.next = self.grace_l.val() | (self.grace_l.val() >> 1);
        self.grace_m.next = self.grace_m.val() | (self.grace_m.val() >> 2);
        self.grace_m.next = self.grace_m.val() | (self.grace_m.val() >> 4);
        self.grace_m.next = self.grace_m.val() | (self.grace_m.val() >> 8);
        self.grace_m.next = self.grace_m.val() | (self.grace_m.val() >> 16);
        if self.chg.q.val() & (self.mode.q.val() == 0) {
            self.grace.d.next = self.grace_l.val() - 1;
            self.run.d.next = self.grace_l.val() > 1;
        } else if self.run.q.val() {
            self.grace.d.next = (self.grace.q.val() - 1) & self.grace_m.val();
            self.run.d.next = self.grace.q.val() != 1;
        }
        // Settling: loaded the clock after a change with one less, then
        // counting down while `busy`, not while a 7-bit test of its own
        // value holds: on a CoolRunner-II each of its bits would repeat
        // that test's product terms (docs/benchmarks.md).
        if self.chg.q.val() {
            self.settle.d.next = self.settle_start.val() - 1;
        } else if self.busy.q.val() {
            self.settle.d.next = self.settle.q.val() - 1;
        }
        // `busy` is `settle != 0` from the clock after `chg` on, kept in
        // its own register (issue 20: the decisions read flip-flops, not a
        // 7-bit compare).
        self.busy.d.next = self.chg.q.val() | (self.settle.q.val() > 1);
        // The decisions as flat expressions (issue 20: a few levels of
        // logic from registered inputs to the change).
        self.live.next = !self.busy.q.val() & !self.chg.q.val();
        self.acting.next = self.i_armed.val() & self.live.val();
        // In failsafe a DATA header on BSR is as good as the ACK (§12).
        self.up_ok.next = self.seen_ack.q.val() | self.i_fs.val();
        // A run of bad words wraps only a ring not known to be wrapped.
        self.fail_in.next = self.i_hard_in.val() | (self.i_run_in.val() & !self.i_rw.val());
        self.fail_bsr.next = self.i_hard_bsr.val() | (self.i_run_bsr.val() & !self.i_rw.val());
        self.in_n.next = self.mode.q.val() == 0;
        // An unarmed node wraps on a TST where DATA is expected on a lit
        // INPUT, and only on that (§12: a restarted node between wrapped
        // neighbours; no frame could reach it otherwise). No grace test
        // (§12): the decision stays free of the 20-bit grace counter; the
        // rule differs only for an unarmed node that hears a TST on INPUT
        // within half a CS timeout of unwrapping into mode N.
        self.wake.next =
            !self.i_armed.val() & self.live.val() & self.i_tst_in.val() & !self.i_los_in.val();
        self.go_wu.next =
            self.in_n.val() & ((self.acting.val() & self.fail_in.val()) | self.wake.val());
        self.go_wd.next =
            self.acting.val() & self.in_n.val() & !self.fail_in.val() & self.fail_bsr.val();
        self.bsr_ok.next = self.up_ok.val() & self.i_bsr_data.val();
        // Unwrapping needs no first frame: a restarted node's neighbours
        // reintegrate with it before it can have one (§12).
        self.unwrap.next = self.live.val()
            & (((self.mode.q.val() == 2) & self.ack_done.q.val() & self.i_frame_start.val())
                | ((self.mode.q.val() == 1)
                    & (self.pend_up.q.val() | self.bsr_ok.val())
                    & !self.i_in_pkt.val()));
        // A rejoining node whose downstream neighbour is wrapped towards
        // it (its TST on INPUT, SI in WU) turns round instead (§12).
        self.turn.next = self.unwrap.val()
            & (self.mode.q.val() == 1)
            & !self.joined.q.val()
            & self.i_tst_in.val();
        self.new_mode.next = self.mode.q.val();
        if self.unwrap.val() {
            self.new_mode.next = 0.into();
        }
        if self.turn.val() {
            self.new_mode.next = 2.into();
        }
        if self.go_wd.val() {
            self.new_mode.next = 2.into();
        }
        if self.go_wu.val() {
            self.new_mode.next = 1.into();
        }
        self.o_change.next = self.go_wu.val() | self.go_wd.val() | self.unwrap.val();
        self.o_relink.next = self.go_wu.val() | (self.unwrap.val() & (self.mode.q.val() == 1));
        self.o_tst_start.next = self.go_wu.val() | self.go_wd.val() | self.turn.val();
        // Mode N: the second structural fault; or both lines dark at once.
        // Wrapped: INPUT dark.
        self.o_fs_set.next = self.acting.val()
            & ((self.in_n.val()
                & (((self.i_hard_in.val() | self.i_hard_bsr.val()) & self.i_rw.val())
                    | (self.i_los_in.val() & self.i_los_bsr.val())))
                | (!self.in_n.val() & self.i_los_in.val()));
        // Wrapped: the partner's ACKed TST, and a WU node's DATA header on
        // BSR after it.
        // `ack_time` stops where `ack_done` is set, so it never passes
        // REINTEGRATE_CLOCKS (< 512, checked above).
        self.ack_inc.next =
            self.live.val() & !self.in_n.val() & self.i_tst_ack.val() & !self.ack_done.q.val();
        if self.live.val() & !self.in_n.val() & self.i_tst_ack.val() {
            self.seen_ack.d.next = true;
        }
        if self.ack_inc.val() {
            self.ack_time.d.next = self.ack_time.q.val() + 1;
        }
        if self.live.val() & (self.mode.q.val() == 1) & self.bsr_ok.val() {
            self.pend_up.d.next = true;
        }
        // `ack_done` is `ack_time >= REINTEGRATE_CLOCKS`, in its own
        // register (cleared with `ack_time` after a change, below).
        if (self.ack_time.q.val() == self.reint_m1.val()) & self.ack_inc.val() {
            self.ack_done.d.next = true;
        }
        // Whole again (§12): at a frame boundary in mode N, armed, with no
        // TST on INPUT or BSR.
        if self.i_armed.val()
            & self.in_n.val()
            & self.i_frame_start.val()
            & !self.i_tst_in.val()
            & !self.i_tst_bsr.val()
        {
            self.joined.d.next = true;
        }
        if self.o_change.val() {
            self.mode.d.next = self.new_mode.val();
            self.chg.d.next = true;
            if self.unwrap.val() & !self.turn.val() {
                self.run.d.next = self.grace_l.val() != 0;
            }
        }
        // The reintegration state starts afresh after a change: cleared
        // while `busy` (from the second clock after the change until the
        // receivers settled), when nothing reads or sets it (each of them
        // needs `live`) (issue 21: one literal in front of these
        // registers, not the change decision).
        if self.busy.q.val() {
            self.ack_time.d.next = 0.into();
            self.ack_done.d.next = false;
            self.seen_ack.d.next = false;
            self.pend_up.d.next = false;
        }
        self.o_mode.next = self.mode.q.val();
        self.o_grace_over.next = !self.run.q.val();
    }
}

/// [`SwitchCtl`] between two rows of flip-flops, as the nodes use it: the
/// receivers' reports (loss of signal, channel failures, ACKed TST, frame
/// boundaries, DATA headers on BSR) are registered on the way in and the
/// decisions on the way out, so that a recovered bit, the decision it
/// leads to and what the node does with it (switchbox, dark time, TST
/// generator, failsafe, RECONFIG alarm) are three clocks, not one long
/// path (issue 20). The mode, the change and its companions leave
/// together, so the node sees one consistent decision, two clocks (one bit
/// time) after the report that caused it. Ports as [`SwitchCtl`];
/// `i_armed`, `i_rw`, `i_fs` and `i_cs_timeout` (node registers and a
/// static value) go in directly.
///
/// A node that forwards INPUT to OUTPUT (`i_fwd`: a slave, a master, a
/// backup that is not the clock base) has its frame boundary where its
/// OUTPUT has sent a packet's last bit, [`DRAIN_CLOCKS`] after the packet
/// ended on INPUT (`i_in_pkt` falling), and counts the packet as arriving
/// until then: a WD end that unwraps, or a WU end that waits for the frame
/// coming the long way round, does not cut that frame's last word
/// (protocol §12). The clock base (`i_fwd` = 0) sends its own frames: its
/// boundary is `i_frame_start`.
///
/// ```text
/// i_in_pkt     ‾‾‾‾\_______________________
/// OUTPUT       =frame====\_________________   (the forwarder's last bits)
/// frame bound. ______________________/‾\____   DRAIN_CLOCKS + 1 after i_in_pkt fell
/// ```
#[derive(LogicBlock)]
pub struct SwitchPipe {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// The node has received its first good frame.
    pub i_armed: Signal<In, Bit>,
    /// Structural failure on INPUT.
    pub i_hard_in: Signal<In, Bit>,
    /// Structural failure on BSR.
    pub i_hard_bsr: Signal<In, Bit>,
    /// Run of bad words on INPUT.
    pub i_run_in: Signal<In, Bit>,
    /// Run of bad words on BSR.
    pub i_run_bsr: Signal<In, Bit>,
    /// Loss of signal on INPUT.
    pub i_los_in: Signal<In, Bit>,
    /// Loss of signal on BSR.
    pub i_los_bsr: Signal<In, Bit>,
    /// The node knows the ring is wrapped.
    pub i_rw: Signal<In, Bit>,
    /// The node is in failsafe.
    pub i_fs: Signal<In, Bit>,
    /// An ACKed TST is heard on BSR.
    pub i_tst_ack: Signal<In, Bit>,
    /// A frame boundary.
    pub i_frame_start: Signal<In, Bit>,
    /// A good DATA H0 on BSR.
    pub i_bsr_data: Signal<In, Bit>,
    /// A packet is arriving on INPUT.
    pub i_in_pkt: Signal<In, Bit>,
    /// A TST heard on INPUT.
    pub i_tst_in: Signal<In, Bit>,
    /// A TST heard on BSR.
    pub i_tst_bsr: Signal<In, Bit>,
    /// CS timeout, clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// The node forwards INPUT to OUTPUT: its frame boundary is a packet's
    /// end on OUTPUT (else `i_frame_start`).
    pub i_fwd: Signal<In, Bit>,
    /// Switchbox mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// `o_mode` will be WU in the next clock (a register: the decision
    /// on its way out), for a capture register that makes the switchbox's
    /// input choice ([`crate::node::slave`]'s `i_cap_sel`).
    pub o_wu_next: Signal<Out, Bit>,
    /// The mode changed at this clock's edge.
    pub o_change: Signal<Out, Bit>,
    /// … and INPUT and BSR moved to other lines.
    pub o_relink: Signal<Out, Bit>,
    /// … and the TST generator went onto an output.
    pub o_tst_start: Signal<Out, Bit>,
    /// Enter failsafe.
    pub o_fs_set: Signal<Out, Bit>,
    /// A TST on a mode-N input counts as failure again.
    pub o_grace_over: Signal<Out, Bit>,
    ctl: SwitchCtl,
    hard_in: DFF<Bit>,
    hard_bsr: DFF<Bit>,
    run_in: DFF<Bit>,
    run_bsr: DFF<Bit>,
    los_in: DFF<Bit>,
    los_bsr: DFF<Bit>,
    tst_ack: DFF<Bit>,
    frame_start: DFF<Bit>,
    bsr_data: DFF<Bit>,
    in_pkt: DFF<Bit>,
    tst_in: DFF<Bit>,
    tst_bsr: DFF<Bit>,
    /// Clocks until OUTPUT has sent the packet that ended on INPUT.
    drain: DFF<Bits<5>>,
    /// OUTPUT has just sent a packet's last bit.
    out_end: DFF<Bit>,
    drain_start: Constant<Bits<5>>,
    mode: DFF<Bits<2>>,
    change: DFF<Bit>,
    relink: DFF<Bit>,
    tst_start: DFF<Bit>,
    fs_set: DFF<Bit>,
    grace_over: DFF<Bit>,
}

impl Default for SwitchPipe {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_armed: Default::default(),
            i_hard_in: Default::default(),
            i_hard_bsr: Default::default(),
            i_run_in: Default::default(),
            i_run_bsr: Default::default(),
            i_los_in: Default::default(),
            i_los_bsr: Default::default(),
            i_rw: Default::default(),
            i_fs: Default::default(),
            i_tst_ack: Default::default(),
            i_frame_start: Default::default(),
            i_bsr_data: Default::default(),
            i_in_pkt: Default::default(),
            i_tst_in: Default::default(),
            i_tst_bsr: Default::default(),
            i_cs_timeout: Default::default(),
            i_fwd: Default::default(),
            o_mode: Default::default(),
            o_wu_next: Default::default(),
            o_change: Default::default(),
            o_relink: Default::default(),
            o_tst_start: Default::default(),
            o_fs_set: Default::default(),
            o_grace_over: Default::default(),
            ctl: Default::default(),
            hard_in: Default::default(),
            hard_bsr: Default::default(),
            run_in: Default::default(),
            run_bsr: Default::default(),
            los_in: Default::default(),
            los_bsr: Default::default(),
            tst_ack: Default::default(),
            frame_start: Default::default(),
            bsr_data: Default::default(),
            in_pkt: Default::default(),
            tst_in: Default::default(),
            tst_bsr: Default::default(),
            drain: Default::default(),
            out_end: Default::default(),
            drain_start: Constant::new(DRAIN_CLOCKS.to_bits()),
            mode: Default::default(),
            change: Default::default(),
            relink: Default::default(),
            tst_start: Default::default(),
            fs_set: Default::default(),
            grace_over: Default::default(),
        }
    }
}

impl Logic for SwitchPipe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            hard_in,
            hard_bsr,
            run_in,
            run_bsr,
            los_in,
            los_bsr,
            tst_ack,
            frame_start,
            bsr_data,
            in_pkt,
            tst_in,
            tst_bsr,
            drain,
            out_end,
            mode,
            change,
            relink,
            tst_start,
            fs_set,
            grace_over
        );
        self.ctl.clock.next = self.clock.val();
        self.hard_in.d.next = self.i_hard_in.val();
        self.hard_bsr.d.next = self.i_hard_bsr.val();
        self.run_in.d.next = self.i_run_in.val();
        self.run_bsr.d.next = self.i_run_bsr.val();
        self.los_in.d.next = self.i_los_in.val();
        self.los_bsr.d.next = self.i_los_bsr.val();
        self.tst_ack.d.next = self.i_tst_ack.val();
        self.frame_start.d.next = self.i_frame_start.val();
        self.bsr_data.d.next = self.i_bsr_data.val();
        self.in_pkt.d.next = self.i_in_pkt.val();
        self.tst_in.d.next = self.i_tst_in.val();
        self.tst_bsr.d.next = self.i_tst_bsr.val();
        self.ctl.i_armed.next = self.i_armed.val();
        self.ctl.i_hard_in.next = self.hard_in.q.val();
        self.ctl.i_hard_bsr.next = self.hard_bsr.q.val();
        self.ctl.i_run_in.next = self.run_in.q.val();
        self.ctl.i_run_bsr.next = self.run_bsr.q.val();
        self.ctl.i_los_in.next = self.los_in.q.val();
        self.ctl.i_los_bsr.next = self.los_bsr.q.val();
        self.ctl.i_rw.next = self.i_rw.val();
        self.ctl.i_fs.next = self.i_fs.val();
        self.ctl.i_tst_ack.next = self.tst_ack.q.val();
        // A forwarding node: OUTPUT sends a packet's last bit about
        // DRAIN_CLOCKS after it ended on INPUT.
        if self.i_in_pkt.val() {
            self.drain.d.next = self.drain_start.val();
        } else if self.drain.q.val() != 0 {
            self.drain.d.next = self.drain.q.val() - 1;
        }
        self.out_end.d.next = (self.drain.q.val() == 1) & !self.i_in_pkt.val();
        self.ctl.i_frame_start.next = self.frame_start.q.val();
        self.ctl.i_in_pkt.next = self.in_pkt.q.val();
        if self.i_fwd.val() {
            self.ctl.i_frame_start.next = self.out_end.q.val();
            self.ctl.i_in_pkt.next = self.in_pkt.q.val() | (self.drain.q.val() != 0);
        }
        self.ctl.i_bsr_data.next = self.bsr_data.q.val();
        self.ctl.i_tst_in.next = self.tst_in.q.val();
        self.ctl.i_tst_bsr.next = self.tst_bsr.q.val();
        self.ctl.i_cs_timeout.next = self.i_cs_timeout.val();
        self.mode.d.next = self.ctl.o_mode.val();
        self.change.d.next = self.ctl.o_change.val();
        self.relink.d.next = self.ctl.o_relink.val();
        self.tst_start.d.next = self.ctl.o_tst_start.val();
        self.fs_set.d.next = self.ctl.o_fs_set.val();
        self.grace_over.d.next = self.ctl.o_grace_over.val();
        self.o_mode.next = self.mode.q.val();
        self.o_wu_next.next = self.ctl.o_mode.val() == 1;
        self.o_change.next = self.change.q.val();
        self.o_relink.next = self.relink.q.val();
        self.o_tst_start.next = self.tst_start.q.val();
        self.o_fs_set.next = self.fs_set.q.val();
        self.o_grace_over.next = self.grace_over.q.val();
    }
}
