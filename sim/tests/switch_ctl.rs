//! Switchbox decisions in Verilator (protocol §9, §10, §12): a first fault
//! wraps (INPUT → WU, BSR → WD); a structural fault while the ring is known
//! wrapped, or loss of signal on both ports at once, fails safe; a run of
//! bad words (a transient) wraps only a ring not known wrapped and never
//! fails safe; nothing happens before the node is armed or while it settles
//! after a change; a WD node reintegrates at a frame start after hearing
//! ACKed TST long enough, a WU node at a DATA header on BSR after an ACK —
//! in failsafe too, where the DATA header alone is enough.

use merkur_rtl::emit::verilog::block_verilog;
use merkur_rtl::node::switch_ctl::SwitchCtl;
use merkur_sim::verilator::Model;

/// Core clocks per bit time: the core clock is twice the line rate
/// (docs/protocol.md §9, "Receiver").
const CLOCKS_PER_BIT: u64 = 2;
/// After a switchbox change a node ignores its stream controllers for 50 bit
/// times (protocol §10). From the spec, not from the block's constant.
const SETTLE_CLOCKS: u64 = 50 * CLOCKS_PER_BIT;
/// A WD node unwraps after 2 ACKed TST (protocol §12, "Reintegration"),
/// that is 2 TST periods of 65 bit times (§9, "Test signal").
const REINTEGRATE_CLOCKS: u64 = 130 * CLOCKS_PER_BIT;

struct Ctl {
    m: Model,
    clk: usize,
}

impl Ctl {
    fn new() -> Ctl {
        let mut m = Model::build(&block_verilog(SwitchCtl::default())).unwrap();
        let clk = m.port("clock");
        let t = m.port("i_cs_timeout");
        m.set(t, 1000);
        Ctl { m, clk }
    }
    fn set(&mut self, name: &str, v: u64) {
        let p = self.m.port(name);
        self.m.set(p, v);
    }
    fn get(&mut self, name: &str) -> u64 {
        self.m.eval();
        let p = self.m.port(name);
        self.m.get(p)
    }
    /// Armed, wrapped up (WU) by a failure of INPUT, settled.
    fn wrapped_up() -> Ctl {
        let mut c = Ctl::new();
        c.set("i_armed", 1);
        c.set("i_hard_in", 1);
        c.ticks(1);
        c.set("i_hard_in", 0);
        c.ticks(SETTLE_CLOCKS);
        c
    }
    /// A dark INPUT (loss of signal is a structural failure too).
    fn dark_in(&mut self, v: u64) {
        self.set("i_los_in", v);
        self.set("i_hard_in", v);
    }
    fn ticks(&mut self, n: u64) {
        for _ in 0..n {
            self.m.tick(self.clk);
        }
    }
}

#[test]
fn first_fault_wraps_second_fails_safe() {
    let mut c = Ctl::new();
    // Not armed: a dead INPUT changes nothing (power-up: every line dark).
    c.dark_in(1);
    c.ticks(5);
    assert_eq!(c.get("o_mode"), 0);
    c.set("i_armed", 1);
    assert_eq!((c.get("o_change"), c.get("o_fs_set")), (1, 0));
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 1, "INPUT failed: WU");
    // Wrapped: INPUT losing signal again is the second fault.
    assert_eq!(c.get("o_fs_set"), 0, "settling after the change");
    c.ticks(SETTLE_CLOCKS);
    assert_eq!(c.get("o_fs_set"), 1, "wrapped and INPUT dark: failsafe");

    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_hard_bsr", 1);
    c.set("i_rw", 1);
    assert_eq!(c.get("o_fs_set"), 1, "BSR fails, ring known wrapped");
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 2, "and the node wraps down");

    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.dark_in(1);
    c.set("i_los_bsr", 1);
    c.set("i_hard_bsr", 1);
    assert_eq!(c.get("o_fs_set"), 1, "both dark at once");
}

#[test]
fn a_run_of_bad_words_is_a_transient() {
    // A ring not known wrapped: a run wraps the link (a soft wrap).
    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_run_in", 1);
    assert_eq!((c.get("o_change"), c.get("o_fs_set")), (1, 0));
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 1, "a run on INPUT: WU");
    // Wrapped: a run on INPUT, or on both ports, fails nothing.
    c.ticks(SETTLE_CLOCKS);
    c.set("i_run_bsr", 1);
    c.ticks(5);
    assert_eq!(
        (c.get("o_mode"), c.get("o_fs_set")),
        (1, 0),
        "wrapped, runs"
    );

    // A ring known wrapped: a run wraps nothing and fails nothing.
    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_rw", 1);
    c.set("i_run_in", 1);
    c.set("i_run_bsr", 1);
    assert_eq!((c.get("o_change"), c.get("o_fs_set")), (0, 0));
    c.ticks(5);
    assert_eq!(c.get("o_mode"), 0, "known wrapped: no second wrap");
    // A neighbour's TST where DATA is expected is structural: failsafe.
    c.set("i_hard_bsr", 1);
    assert_eq!(c.get("o_fs_set"), 1, "TST on BSR, known wrapped");
}

#[test]
fn a_wrapped_node_reintegrates() {
    // WD: ACKed TST for the reintegration time, then a frame start.
    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_hard_bsr", 1);
    c.ticks(1);
    c.set("i_hard_bsr", 0);
    assert_eq!(c.get("o_mode"), 2);
    c.ticks(SETTLE_CLOCKS);
    c.set("i_tst_ack", 1);
    c.set("i_frame_start", 1);
    c.ticks(REINTEGRATE_CLOCKS - 1);
    assert_eq!(c.get("o_mode"), 2, "not before the ACKs lasted");
    c.ticks(2);
    assert_eq!(c.get("o_mode"), 0, "unwrapped at a frame start");
    assert_eq!(c.get("o_grace_over"), 0, "grace period after unwrapping");
    c.set("i_tst_ack", 0);
    c.set("i_frame_start", 0);
    c.ticks(500);
    assert_eq!(c.get("o_grace_over"), 1, "half the CS timeout later");

    // WU: an ACK, then a DATA header on BSR.
    let mut c = Ctl::wrapped_up();
    c.set("i_bsr_data", 1);
    c.ticks(3);
    assert_eq!(c.get("o_mode"), 1, "no ACK heard yet");
    c.set("i_tst_ack", 1);
    c.ticks(2);
    assert_eq!(c.get("o_mode"), 0);

    // WU in failsafe: a DATA header on BSR is as good as the ACK (the
    // special master's downstream neighbour, cut off with it, protocol §12).
    let mut c = Ctl::wrapped_up();
    c.set("i_fs", 1);
    c.ticks(3);
    assert_eq!(c.get("o_mode"), 1, "no frame on BSR yet");
    c.set("i_bsr_data", 1);
    c.ticks(2);
    assert_eq!(c.get("o_mode"), 0, "the frame is the ACK in failsafe");

    // WU while a packet is still arriving on INPUT (the frame that went the
    // long way round): the DATA header on BSR is remembered, and the node
    // unwraps when that packet has ended, not in the middle of it.
    let mut c = Ctl::wrapped_up();
    c.set("i_tst_ack", 1);
    c.ticks(2);
    c.set("i_in_pkt", 1);
    c.set("i_bsr_data", 1);
    c.ticks(1);
    c.set("i_bsr_data", 0);
    c.ticks(40);
    assert_eq!(c.get("o_mode"), 1, "not inside the INPUT packet");
    c.set("i_in_pkt", 0);
    assert_eq!(c.get("o_relink"), 1, "the receivers move when it has ended");
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 0);
}
