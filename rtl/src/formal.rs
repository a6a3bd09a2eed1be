//! # formal — the properties proved of the control blocks
//!
//! Each proof is a SystemVerilog wrapper in `rtl/formal/<name>.sv`: it
//! instantiates the block's emitted Verilog (the same text that is
//! simulated and synthesized, its top module renamed to the block's name by
//! [`crate::emit::verilog::rename_top`]) and states the block's properties as
//! immediate assertions (`assert`), input constraints (`assume`) and reach
//! checks (`cover`) in plain `always` blocks, with the protocol section
//! each one comes from. Expected values are written from docs/protocol.md,
//! never taken from the block's own constants (register encodings come
//! from the port tables and the model).
//!
//! Some proofs need an internal signal of the block: a register to state an
//! invariant that k-induction can use (a counter the wrapper shadows), or
//! a strobe that says what the block does in a clock (the elastic buffer's bit
//! start, a memory's write port); the runner makes it a port of the block
//! with Yosys' `expose` ([`Proof::expose`]), the block itself is not changed.
//!
//! The runner (SymbiYosys with the Boolector solver, both installed by
//! `scripts/install-tools.sh --synth`) is `merkur_sim::formal`;
//! `merkur prove` and `cargo test` (sim/tests/formal.rs) run every
//! proof. docs/verification.md lists the properties in words.

use crate::emit::verilog::{block_verilog, rename_top};

/// What a task of a proof does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Bounded model check: no assertion fails in the first `depth` clocks
    /// from power-up, for every input sequence.
    Bmc,
    /// k-induction of length `depth`: the assertions hold in every
    /// reachable state, for ever (the base case is a BMC of `depth`).
    Prove,
    /// Every `cover` is reached within `depth` clocks (a property whose
    /// trigger never happens would otherwise pass vacuously).
    Cover,
}

impl Mode {
    /// SymbiYosys' name of the mode.
    pub fn sby(self) -> &'static str {
        match self {
            Mode::Bmc => "bmc",
            Mode::Prove => "prove",
            Mode::Cover => "cover",
        }
    }
}

/// One task: a mode and its depth in clocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Task {
    /// Mode.
    pub mode: Mode,
    /// Depth (clocks).
    pub depth: u32,
}

/// A proof: a property wrapper around one or more blocks.
#[derive(Debug, Clone)]
pub struct Proof {
    /// Name (= the wrapper's file name in `rtl/formal/`, its module is `<name>_props`).
    pub name: &'static str,
    /// One line: what is proved.
    pub what: &'static str,
    /// The blocks under proof: (module name, Verilog).
    pub duts: Vec<(&'static str, String)>,
    /// Internal wires made ports of a block for the wrapper: (module, wire).
    pub expose: Vec<(&'static str, &'static str)>,
    /// The wrapper's text.
    pub props: &'static str,
    /// The tasks, run in this order.
    pub tasks: Vec<Task>,
}

impl Proof {
    /// The wrapper's top module.
    pub fn top(&self) -> String {
        format!("{}_props", self.name)
    }
}

fn dut(name: &'static str, verilog: String) -> (&'static str, String) {
    let v = rename_top(&verilog, name);
    (name, v)
}

const fn task(mode: Mode, depth: u32) -> Task {
    Task { mode, depth }
}

/// Every proof of the project.
pub fn proofs() -> Vec<Proof> {
    vec![
        codec(),
        nrzi_tx(),
        cdr(),
        stream_ctl(),
        switchbox(),
        switch_ctl(),
        sw_dark(),
        retime(),
        retime_layouts(),
        rmm_fcm(),
        mdb(),
        special_master(),
        slave(),
        fwd(),
    ]
}

fn codec() -> Proof {
    Proof {
        name: "codec",
        what: "4B/5B: the code table, decode(encode(x)) = x, no J K inside data, \
               a toggle every 4 bit times",
        duts: vec![
            dut(
                "enc4b5b",
                block_verilog(crate::line::enc4b5b::Enc4b5b::default()),
            ),
            dut(
                "dec5b4b",
                block_verilog(crate::line::dec5b4b::Dec5b4b::default()),
            ),
        ],
        expose: vec![],
        props: include_str!("../formal/codec.sv"),
        tasks: vec![task(Mode::Prove, 1), task(Mode::Cover, 1)],
    }
}

fn cdr() -> Proof {
    Proof {
        name: "cdr",
        what: "loss of signal: raised after 32 bit times without an edge, never earlier; each bit's code is its NRZI decode",
        duts: vec![dut("cdr", block_verilog(crate::line::cdr::Cdr::default()))],
        expose: vec![("cdr", "quiet_q"), ("cdr", "calm_q"), ("cdr", "mute_q"), ("cdr", "last_q")],
        props: include_str!("../formal/cdr.sv"),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 70)],
    }
}

fn stream_ctl() -> Proof {
    let v = block_verilog(crate::node::stream_ctl::StreamCtl::default());
    Proof {
        name: "stream_ctl",
        what: "channel failure: 8 bad words raise a run, 7 never; TST held 130 bit times",
        duts: vec![dut("stream_ctl", v)],
        expose: ["bad_q", "hold_q", "hold_ld_q"]
            .map(|w| ("stream_ctl", w))
            .to_vec(),
        props: include_str!("../formal/stream_ctl.sv"),
        // The longest cover: a TST (2 words) and its 260-clock hold.
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 266)],
    }
}

fn sw_dark() -> Proof {
    Proof {
        name: "sw_dark",
        what: "dark time: both outputs hold their level 12 bit times after a change",
        duts: vec![dut(
            "sw_dark",
            block_verilog(crate::node::sw_dark::SwDark::default()),
        )],
        expose: ["dark_q", "dark_po_q", "lvl_po_q", "lvl_so_q"]
            .map(|w| ("sw_dark", w))
            .to_vec(),
        props: include_str!("../formal/sw_dark.sv"),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 30)],
    }
}

fn retime() -> Proof {
    Proof {
        name: "retime",
        what: "elastic buffer: no slip for a sender 20,000 ppm off, one-half-clock corrections 8 bits apart",
        duts: vec![dut("retime", block_verilog(crate::line::retime::Retime::default()))],
        expose: ["send0", "send1", "len", "run_q"].map(|w| ("retime", w)).to_vec(),
        props: include_str!("../formal/retime.sv"),
        tasks: vec![task(Mode::Bmc, 300), task(Mode::Cover, 100)],
    }
}

fn retime_layouts() -> Proof {
    use crate::line::retime::{Layout, Retime};
    let regs = [
        "sr_q", "cnt_q", "rem_q", "lvl_q", "run_q", "dark_q", "since_q", "hi_q", "lo_q", "gap_q",
        "pair_q", "slip_q",
    ];
    Proof {
        name: "retime_layouts",
        what:
            "elastic buffer: the layout a write shifts (CoolRunner-II) sends what the one a send \
               shifts sends, in every clock, for ever",
        duts: vec![
            dut(
                "retime_send_shifts",
                block_verilog(Retime::new(Layout::SendShifts)),
            ),
            dut(
                "retime_write_shifts",
                block_verilog(Retime::new(Layout::WriteShifts)),
            ),
        ],
        expose: ["retime_send_shifts", "retime_write_shifts"]
            .into_iter()
            .flat_map(|m| regs.map(|w| (m, w)))
            .collect(),
        props: include_str!("../formal/retime_layouts.sv"),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 60)],
    }
}

fn rmm_fcm() -> Proof {
    Proof {
        name: "rmm_fcm",
        what: "802.4 fault correction machine: five states, exactly §21's transitions",
        duts: vec![dut(
            "rmm_fcm",
            block_verilog(crate::tokenbus::rmm_fcm::RmmFcm::default()),
        )],
        expose: vec![("rmm_fcm", "pend_q"), ("rmm_fcm", "pend_ch_q")],
        props: include_str!("../formal/rmm_fcm.sv"),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 8)],
    }
}

fn mdb() -> Proof {
    let v =
        crate::emit::verilog::size_memories(&block_verilog(crate::node::mdb::Mdb::default()), 256);
    let wires = [
        "db__write_enable",
        "db__write_address",
        "db__write_data",
        "cfg_tx__write_enable",
        "cfg_tx__write_data",
        "cfg_rx__write_enable",
        "cfg_rx__write_address",
        "cfg_rx__write_data",
        "s2_write",
        "s3_take",
    ];
    Proof {
        name: "mdb",
        what: "host port: Wishbone handshake, refused data and configuration writes",
        duts: vec![dut("mdb", v)],
        expose: wires.map(|w| ("mdb", w)).to_vec(),
        props: include_str!("../formal/mdb.sv"),
        tasks: vec![task(Mode::Bmc, 20), task(Mode::Cover, 16)],
    }
}

fn special_master() -> Proof {
    // Memories 256 deep (a ring of up to 256 slots): the properties do not
    // involve them, and the proof stays small.
    let v = crate::emit::verilog::size_memories(
        &block_verilog(crate::node::special_master::SpecialMaster::default()),
        256,
    );
    let wires = [
        "tick",
        "mdb__o_running",
        "half_q",
        "bcnt_q",
        "quiet_q",
        "armed_q",
        "failsafe_q",
        "rx_in__o_wvalid",
        "rx_in__o_kind",
        "rx_in__o_ok",
        "rx_in__o_ptype",
    ];
    Proof {
        name: "special_master",
        what: "clock base: one frame start every period; the CS timeout exactly on time",
        duts: vec![dut("special_master", v)],
        expose: wires.map(|w| ("special_master", w)).to_vec(),
        props: concat!(
            include_str!("../formal/special_master.sv"),
            include_str!("../formal/cs_timeout_spec.sv")
        ),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 20)],
    }
}

fn slave() -> Proof {
    let wires = [
        "armed_q",
        "failsafe_q",
        "quiet_q",
        "quiet_clr_q",
        "quiet_max_q",
        "cs_due",
        "rx_in__o_wvalid",
        "rx_in__o_kind",
        "rx_in__o_ok",
        "rx_in__o_ptype",
    ];
    Proof {
        name: "slave",
        what: "the slave's CS timeout exactly on time, its counter restarted through a flip-flop",
        // The slave without retransmission on demand (`merkur synth`'s for
        // a ring without critical slots): the counter is the same in both,
        // and the proof is smaller.
        duts: vec![dut(
            "slave",
            block_verilog(crate::node::slave::Slave::with_rtx(
                crate::line::word_rx::WordFormat::Basic,
                false,
            )),
        )],
        expose: wires.map(|w| ("slave", w)).to_vec(),
        props: concat!(
            include_str!("../formal/slave.sv"),
            include_str!("../formal/cs_timeout_spec.sv")
        ),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 4)],
    }
}

fn fwd() -> Proof {
    Proof {
        name: "fwd",
        what: "the forwarder's fresh word: followed between words, held through a word, \
               its hold taken from one flip-flop",
        duts: vec![dut(
            "fwd",
            block_verilog(crate::node::fwd::Fwd::new(
                crate::line::word_rx::WordFormat::Basic,
            )),
        )],
        expose: ["gidx_q", "g_pend_q", "f_hold_q", "f_data_q", "fresh_data"]
            .map(|w| ("fwd", w))
            .to_vec(),
        props: include_str!("../formal/fwd.sv"),
        // The cover: a J K (10 bits) and a whole group after it.
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 24)],
    }
}

fn nrzi_tx() -> Proof {
    Proof {
        name: "nrzi_tx",
        what:
            "serializer: a group every 5 bit times, MSB first, the line toggles exactly on 1 bits",
        duts: vec![dut(
            "nrzi_tx",
            block_verilog(crate::line::nrzi_tx::NrziTx::default()),
        )],
        expose: vec![("nrzi_tx", "count_q"), ("nrzi_tx", "shift_q")],
        props: include_str!("../formal/nrzi_tx.sv"),
        tasks: vec![task(Mode::Prove, 2), task(Mode::Cover, 12)],
    }
}

fn switchbox() -> Proof {
    Proof {
        name: "switchbox",
        what: "Table 1: every mode routes the four ports as its row says",
        duts: vec![sbox()],
        expose: vec![],
        props: include_str!("../formal/switchbox.sv"),
        tasks: vec![task(Mode::Prove, 1), task(Mode::Cover, 1)],
    }
}

fn sbox() -> (&'static str, String) {
    let v = block_verilog(crate::node::switchbox::Switchbox::default());
    dut("switchbox", v)
}

fn switch_ctl() -> Proof {
    let v = block_verilog(crate::node::switch_ctl::SwitchCtl::default());
    let regs = [
        "settle_q",
        "ack_time_q",
        "grace_q",
        "chg_q",
        "run_q",
        "seen_ack_q",
        "pend_up_q",
        "joined_q",
        "busy_q",
        "ack_done_q",
    ];
    Proof {
        name: "switch_ctl",
        what: "switchbox decisions: Table 1 rows only, the model's decision rule, settle, \
               failsafe on a second fault, reintegration",
        duts: vec![dut("switch_ctl", v), sbox()],
        expose: regs.map(|w| ("switch_ctl", w)).to_vec(),
        props: include_str!("../formal/switch_ctl.sv"),
        // The longest cover (WD → N) needs a change, 100 clocks of
        // settling and 260 of ACKed TST.
        tasks: vec![task(Mode::Prove, 4), task(Mode::Cover, 370)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_proof_has_its_wrapper_and_a_cover() {
        let ps = proofs();
        let mut names: Vec<&str> = ps.iter().map(|p| p.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), ps.len(), "proof names are unique");
        for p in &ps {
            assert!(
                p.props.contains(&format!("module {}", p.top())),
                "{}: wrapper module {} missing",
                p.name,
                p.top()
            );
            assert!(p.props.contains("cover"), "{}: no cover", p.name);
            assert!(
                p.tasks.iter().any(|t| t.mode == Mode::Cover),
                "{}: no cover task",
                p.name
            );
            for (m, v) in &p.duts {
                assert!(v.contains(&format!("module {m}(")), "{}: {m}", p.name);
            }
        }
    }
}
