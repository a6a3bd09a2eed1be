//! Switchbox decisions in Verilator (protocol §10, §12): a first fault wraps
//! (INPUT → WU, BSR → WD), a fault while the ring is known wrapped, or on
//! both ports at once, fails safe; nothing happens before the node is armed
//! or while it settles after a change; a WD node reintegrates at a frame
//! start after hearing ACKed TST long enough, a WU node at a DATA header on
//! BSR after an ACK.

use merkur_rtl::slave::{REINTEGRATE_CLOCKS, SETTLE_CLOCKS};
use merkur_rtl::switch_ctl::SwitchCtl;
use merkur_rtl::verilog::block_verilog;
use merkur_testbenches::verilator::Model;

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
        c.set("i_cf_in", 1);
        c.ticks(1);
        c.set("i_cf_in", 0);
        c.ticks(SETTLE_CLOCKS);
        c
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
    c.set("i_cf_in", 1);
    c.ticks(5);
    assert_eq!(c.get("o_mode"), 0);
    c.set("i_armed", 1);
    assert_eq!((c.get("o_change"), c.get("o_fs_set")), (1, 0));
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 1, "INPUT failed: WU");
    // Wrapped: INPUT failing again is the second fault.
    assert_eq!(c.get("o_fs_set"), 0, "settling after the change");
    c.ticks(SETTLE_CLOCKS);
    assert_eq!(c.get("o_fs_set"), 1, "wrapped and INPUT fails: failsafe");

    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_cf_bsr", 1);
    c.set("i_rw", 1);
    assert_eq!(c.get("o_fs_set"), 1, "BSR fails, ring known wrapped");
    c.ticks(1);
    assert_eq!(c.get("o_mode"), 2, "and the node wraps down");

    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_cf_in", 1);
    c.set("i_cf_bsr", 1);
    assert_eq!(c.get("o_fs_set"), 1, "both at once");
}

#[test]
fn a_wrapped_node_reintegrates() {
    // WD: ACKed TST for the reintegration time, then a frame start.
    let mut c = Ctl::new();
    c.set("i_armed", 1);
    c.set("i_cf_bsr", 1);
    c.ticks(1);
    c.set("i_cf_bsr", 0);
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

    // WU: an ACK, then a DATA header on BSR; not in failsafe.
    let mut c = Ctl::wrapped_up();
    c.set("i_bsr_data", 1);
    c.ticks(3);
    assert_eq!(c.get("o_mode"), 1, "no ACK heard yet");
    c.set("i_tst_ack", 1);
    c.set("i_fs", 1);
    c.ticks(3);
    assert_eq!(c.get("o_mode"), 1, "failsafe nodes do not reintegrate");
    c.set("i_fs", 0);
    c.ticks(2);
    assert_eq!(c.get("o_mode"), 0);

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
