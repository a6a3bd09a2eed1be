//! # synth_top — a node as a chip: the top level that synthesis builds
//!
//! Purpose: wraps one node ([`crate::node::slave`], [`crate::node::master`] or
//! [`crate::node::special_master`]) into a top module `merkur_top` with physical
//! pins: one pin per fibre, the quadrature DDR input capture and the DDR
//! output the node's ports assume (protocol §9), its static configuration
//! (home slot, slots per frame, sensor/actuator, CS timeout, cycle period)
//! tied to constants from the ring scenario, asynchronous user inputs
//! synchronised, and the error counters behind a small diagnostic mux (so a
//! board needs 16 pins for them, not 48, and synthesis keeps them). The
//! device-independent capture and output stages are the modules
//! `merkur_ddr_in` and `merkur_ddr_out` below; `merkur synth` builds this
//! top for every target (docs/synthesis.md). For a slave or a master the
//! capture register makes the switchbox's input choice (the node's
//! `o_cap_si`, `i_cap_sel` tied 1): `i_pi` then carries INPUT's samples
//! and `i_si` BSR's (issue 21: the clock recoveries read flip-flops, not
//! a multiplexer; the same samples in the same clocks).
//!
//! | port | dir | width | kinds | meaning |
//! |---|---|---|---|---|
//! | `clk` | in | 1 | all | core clock, 2× line rate |
//! | `clk90` | in | 1 | all | the core clock shifted by 90° (a PLL/DCM output) |
//! | `pi`, `si` | in | 1 | all | primary and secondary fibre inputs (receiver outputs) |
//! | `po`, `so` | out | 1 | all | primary and secondary fibre outputs (transmitter inputs) |
//! | `i_irq1`, `i_irq2`, `i_fs_req` | in | 1 | all | user requests (asynchronous; synchronised here) |
//! | `o_mode` | out | 2 | all | switchbox mode (0 N, 1 WU, 2 WD) |
//! | `o_failsafe` | out | 1 | all | failsafe |
//! | `i_diag_sel` | in | 3 | all (with `diag`) | which value `o_diag` shows (below) |
//! | `o_diag` | out | 16 | all (with `diag`) | 0 perr, 1 ferr, 2 aerr, 3 serr, 4 hop, 5 frames sent, 6 actuator register (values a kind lacks read 0) |
//! | `i_sensor` | in | 16 | slave (without `diag`: sensor) | sensor value (synchronised here bit by bit: a value changing at a capture edge can arrive mixed, old and new bits; drive it from a register on `clk` or a handshake, docs/synthesis.md). Without `sensor_sync` it is not synchronised: it must come from a register on `clk` |
//! | `o_act` | out | 16 | actuator without `diag` | actuator output register |
//! | `i_wb_cyc`, `i_wb_stb`, `i_wb_we`, `i_wb_adr[13:0]`, `i_wb_dat[15:0]` | in | | master, SM | Wishbone B4 host port on `clk` ([`crate::node::mdb`]) |
//! | `o_wb_dat[15:0]`, `o_wb_ack` | out | | master, SM | Wishbone read data, acknowledge |
//! | `o_irq1`, `o_irq2`, `o_irq_fs`, `o_running` | out | 1 | master, SM | interrupts received, ring started |
//! | `o_irq_rc`, `o_alarmq` | out | 1 | master, SM | RECONFIG alarm received; the alarm queue is not empty (protocol §11) |
//! | `o_irq_fsc` | out | 1 | master, SM | failsafe entered or left (protocol §12) |
//!
//! Latency: inputs reach the node 1–1.75 clocks after the pin (capture +
//! one register); outputs leave 1 clock after the node's DDR pair (the
//! negative-edge half a half clock later); `o_diag` is registered.
//!
//! ```text
//!              clk ↑   clk90 ↑  clk ↓   clk90 ↓   clk ↑
//! pi sampled    s0       s1       s2       s3     ─▶ i_pi = {s3,s2,s1,s0} (s0 first; si's when o_cap_si)
//! o_po pair    {b1,b0} registered at clk ↑ ─▶ po = b0 (clk high), b1 (clk low)
//! ```

use merkur_model::config::MAX_PERIOD_BITS;
use merkur_model::scenario::Kind;

/// Clocks without the start of a packet other than a TST before a node
/// enters failsafe: 3.5 cycle periods (3 per protocol §12 rule 4, plus
/// margin for ±1000 ppm clocks and where in its period a frame passes), at
/// 2 clocks per bit time. The nodes' 20-bit port holds it for every legal
/// period (`MAX_PERIOD_BITS`, protocol §8); [`check`] refuses others.
pub fn cs_timeout_clocks(period_bits: u64) -> u64 {
    ring_cs_timeout_clocks(period_bits, 3)
}

/// The CS timeout in clocks for a ring whose timeout is `cycles` periods
/// by protocol §12 rule 4 (3 without backup clock bases, 2 + the highest
/// backup priority with them, §8): `cycles` + 0.5 periods, at 2 clocks per
/// bit time.
pub fn ring_cs_timeout_clocks(period_bits: u64, cycles: u32) -> u64 {
    (2 * cycles as u64 + 1) * period_bits
}

/// A backup clock base's election time in bit times: (1.5 + `prio`)
/// periods (protocol §8).
pub fn elect_bits(period_bits: u64, prio: u8) -> u64 {
    (3 + 2 * prio as u64) * period_bits / 2
}

// The 20-bit CS timeout counter saturates at 2²⁰ − 1: the longest legal
// period must stay below it.
const _: () = assert!(7 * (MAX_PERIOD_BITS as u64) < 0xfffff);

/// The static configuration of one node, as the top ties it.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeStatic {
    /// Node kind (sensor and actuator are both the slave module).
    pub kind: Kind,
    /// Home slot.
    pub address: usize,
    /// Slots per frame.
    pub slots: usize,
    /// Cycle period in bit times (special master only).
    pub period: u32,
    /// The diagnostic mux (`i_diag_sel`, `o_diag`) and the error counters
    /// behind it. Without it (`merkur synth --diag off`) the top is lean:
    /// a sensor has `i_sensor`, an actuator its register on `o_act`, and
    /// synthesis drops the counters that nothing reads (docs/synthesis.md).
    pub diag: bool,
    /// The sensor value's synchroniser (two flip-flops per bit on `clk`).
    /// Without it (`merkur synth --sensor-sync off`) `i_sensor` goes to
    /// the node as it is and must come from a register on `clk` (issue
    /// 21: 32 flip-flops that a small device cannot spare; a user whose
    /// source is on another clock needs a handshake for the value's
    /// coherence anyway, docs/synthesis.md). The requests keep theirs.
    pub sensor_sync: bool,
    /// The word format of the ring (protocol §4, or §6 with
    /// `[frame] alarm_bits = true`).
    pub format: WordFormat,
    /// Retransmission on demand (special master only; all 0 without
    /// critical slots).
    pub rtx: RtxStatic,
    /// Where a slave's or a master's retime buffers keep their bits: the
    /// same behaviour clock for clock ([`Layout`]); `merkur synth` takes
    /// [`Layout::WriteShifts`] for a CoolRunner-II (fewer product terms)
    /// and [`Layout::SendShifts`] for an FPGA (shorter paths). The special
    /// master keeps [`Layout::SendShifts`].
    pub layout: Layout,
}

/// The clock base's retransmission timing (protocol §8), static like the
/// period: the RTX goes `at` bit times after the period tick (`at_wrapped`
/// in a ring it knows wrapped) with at most `k` (`k_wrapped`) requests.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RtxStatic {
    /// T in the healthy ring, bit times.
    pub at: u32,
    /// T in a wrapped ring.
    pub at_wrapped: u32,
    /// Requests that fit in the healthy ring (0: none is sent).
    pub k: u32,
    /// Requests that fit in a wrapped ring.
    pub k_wrapped: u32,
}

impl RtxStatic {
    /// The timing of a scenario's ring, from the model's rules.
    pub fn of(cfg: &merkur_model::config::Config) -> RtxStatic {
        RtxStatic {
            at: cfg.rtx_start(false).unwrap_or(0),
            at_wrapped: cfg.rtx_start(true).unwrap_or(0),
            k: cfg.rtx_capacity(false) as u32,
            k_wrapped: cfg.rtx_capacity(true) as u32,
        }
    }
}

/// The device-independent capture and output stages (see the module doc).
pub const DDR_IO: &str = r#"// merkur_ddr_in: quadrature DDR capture of one line, four samples per clk,
// q[0] first in time (taken at clk rising), q[3] last (clk90 falling).
// s: this line's samples before the register, for the other line's
// capture. With sel high the register takes the other line's (alt)
// instead: the switchbox's input choice made in the capture register, by
// the node's o_cap_si (a slave or a master; tie sel low for the special
// master). In an iCE40 the choice is the LUT every flip-flop has in
// front of it and in a CoolRunner-II the register's own product terms, so
// the quarter clock from s3 to q carries no more logic levels there; in
// an ECP5 it is one LUT (that transfer has room to spare there).
module merkur_ddr_in(clk, clk90, d, alt, sel, s, q);
    input wire clk;
    input wire clk90;
    input wire d;
    input wire [3:0] alt;
    input wire sel;
    output wire [3:0] s;
    output reg [3:0] q = 4'd0;
    reg s0 = 1'b0;
    reg s1 = 1'b0;
    reg s2 = 1'b0;
    reg s3 = 1'b0;
    always @(posedge clk) s0 <= d;
    always @(posedge clk90) s1 <= d;
    always @(negedge clk) s2 <= d;
    always @(negedge clk90) s3 <= d;
    assign s = {s3, s2, s1, s0};
    always @(posedge clk) q <= sel ? alt : s;
endmodule

// merkur_ddr_out: DDR output of a pair registered on clk: d[0] while clk is
// high, d[1] while it is low (one clock later). Two flip-flops XORed, so
// only one input of the XOR changes at a time (no clock in the data path).
module merkur_ddr_out(clk, d, q);
    input wire clk;
    input wire [1:0] d;
    output wire q;
    reg p = 1'b0;
    reg n = 1'b0;
    reg d1 = 1'b0;
    always @(posedge clk) begin
        p <= d[0] ^ n;
        d1 <= d[1];
    end
    always @(negedge clk) n <= d1 ^ p;
    assign q = p ^ n;
endmodule
"#;

use crate::harness::ring_top::{module_name as node_module, node_verilog_with};
use crate::line::retime::Layout;
use crate::line::word_rx::WordFormat;

/// Refuses a configuration the ports cannot carry.
pub fn check(st: &NodeStatic) -> Result<(), String> {
    if st.slots == 0 || st.slots > 4096 {
        return Err(format!("slots {} must be 1 … 4096", st.slots));
    }
    if st.address >= st.slots {
        return Err(format!(
            "address {} must be below the slot count {}",
            st.address, st.slots
        ));
    }
    if !(1..=MAX_PERIOD_BITS).contains(&st.period) {
        return Err(format!(
            "period {} bit times: the nodes' 20-bit period and CS timeout ports carry 1 … {MAX_PERIOD_BITS}",
            st.period
        ));
    }
    Ok(())
}

/// The Verilog of `merkur_top` for one node, with the node's modules and
/// the DDR stages: a complete synthesis input.
pub fn node_top(st: &NodeStatic) -> Result<String, String> {
    check(st)?;
    let slave = matches!(st.kind, Kind::Sensor | Kind::Actuator);
    let sm = st.kind == Kind::SpecialMaster;
    let mut v = String::new();
    v.push_str(&format!(
        "// merkur_top: one {} node (home slot {}, {} slots{}), for synthesis.\n\
         // Generated by merkur-rtl (rtl/src/top/synth_top.rs); do not edit.\n",
        st.kind.name(),
        st.address,
        st.slots,
        if sm {
            format!(", period {} bit times", st.period)
        } else {
            String::new()
        }
    ));
    // (A slave of a ring without critical slots is built without
    // retransmission on demand: smaller, protocol §8.)
    v.push_str(&node_verilog_with(
        st.kind,
        st.slots,
        st.format,
        st.rtx.k > 0,
        st.layout,
    ));
    v.push_str(DDR_IO);
    let act = st.kind == Kind::Actuator;
    let mut ports = vec![
        "clk",
        "clk90",
        "pi",
        "si",
        "po",
        "so",
        "i_irq1",
        "i_irq2",
        "i_fs_req",
        "o_mode",
        "o_failsafe",
    ];
    if st.diag {
        ports.extend(["i_diag_sel", "o_diag"]);
    }
    if slave && (st.diag || !act) {
        ports.push("i_sensor");
    }
    if act && !st.diag {
        ports.push("o_act");
    }
    if !slave {
        ports.extend([
            "i_wb_cyc",
            "i_wb_stb",
            "i_wb_we",
            "i_wb_adr",
            "i_wb_dat",
            "o_wb_dat",
            "o_wb_ack",
            "o_irq1",
            "o_irq2",
            "o_irq_fs",
            "o_irq_rc",
            "o_alarmq",
            "o_irq_fsc",
            "o_running",
        ]);
    }
    v.push_str(&format!("\nmodule merkur_top({});\n", ports.join(", ")));
    v.push_str(
        "    input wire clk;\n    input wire clk90;\n    input wire pi;\n    input wire si;\n\
         \x20   output wire po;\n    output wire so;\n    input wire i_irq1;\n    input wire i_irq2;\n\
         \x20   input wire i_fs_req;\n    output wire [1:0] o_mode;\n    output wire o_failsafe;\n",
    );
    if st.diag {
        v.push_str("    input wire [2:0] i_diag_sel;\n    output reg [15:0] o_diag = 16'd0;\n");
    }
    if ports.contains(&"i_sensor") {
        v.push_str("    input wire [15:0] i_sensor;\n");
    }
    if ports.contains(&"o_act") {
        v.push_str("    output wire [15:0] o_act;\n");
    }
    if !slave {
        v.push_str(
            "    input wire i_wb_cyc;\n    input wire i_wb_stb;\n    input wire i_wb_we;\n\
             \x20   input wire [13:0] i_wb_adr;\n    input wire [15:0] i_wb_dat;\n\
             \x20   output wire [15:0] o_wb_dat;\n    output wire o_wb_ack;\n    output wire o_irq1;\n\
             \x20   output wire o_irq2;\n    output wire o_irq_fs;\n    output wire o_irq_rc;\n    output wire o_alarmq;\n    output wire o_irq_fsc;\n    output wire o_running;\n",
        );
    }
    v.push_str(
        "    // Fibre capture and output. A slave's or a master's capture makes its\n\
         \x20   // switchbox's input choice (the node's o_cap_si): pi_s then carries\n\
         \x20   // INPUT's samples, si_s BSR's.\n\
         \x20   wire [3:0] pi_s;\n    wire [3:0] si_s;\n    wire [3:0] pi_raw;\n    wire [3:0] si_raw;\n    wire sel_si;\n\
         \x20   wire [1:0] po_pair;\n    wire [1:0] so_pair;\n\
         \x20   merkur_ddr_in cap_pi(.clk(clk), .clk90(clk90), .d(pi), .alt(si_raw), .sel(sel_si), .s(pi_raw), .q(pi_s));\n\
         \x20   merkur_ddr_in cap_si(.clk(clk), .clk90(clk90), .d(si), .alt(pi_raw), .sel(sel_si), .s(si_raw), .q(si_s));\n\
         \x20   merkur_ddr_out out_po(.clk(clk), .d(po_pair), .q(po));\n\
         \x20   merkur_ddr_out out_so(.clk(clk), .d(so_pair), .q(so));\n\
         \x20   // User requests: two-flip-flop synchronisers.\n\
         \x20   reg [2:0] req_m = 3'd0;\n    reg [2:0] req = 3'd0;\n\
         \x20   always @(posedge clk) begin\n        req_m <= {i_fs_req, i_irq2, i_irq1};\n        req <= req_m;\n    end\n",
    );
    // Values only the diagnostic mux reads: without it, named as unused
    // (and removed by synthesis).
    let (lint_off, lint_on) = if st.diag {
        ("", "")
    } else {
        (
            "    // Read only by the diagnostic mux, which this build leaves out.\n\
             \x20   /* verilator lint_off UNUSEDSIGNAL */\n",
            "    /* verilator lint_on UNUSEDSIGNAL */\n",
        )
    };
    v.push_str(&format!(
        "{lint_off}    wire [15:0] perr;\n    wire [15:0] ferr;\n{lint_on}"
    ));
    let a = st.address;
    let s1 = st.slots - 1;
    let to = cs_timeout_clocks(st.period as u64);
    let common = format!(
        ".clock(clk), .i_pi(pi_s), .i_si(si_s), .o_po(po_pair), .o_so(so_pair),\n\
         \x20       .i_address(12'd{a}), .i_slots_m1(12'd{s1}), .i_cs_timeout(20'd{to}),\n\
         \x20       .i_irq1(req[0]), .i_irq2(req[1]), .i_fs_req(req[2]),\n\
         \x20       .o_mode(o_mode), .o_failsafe(o_failsafe), .o_perr(perr), .o_ferr(ferr)"
    );
    let lint = (lint_off, lint_on);
    let diag_tail = if slave {
        slave_instance(&mut v, st, &ports, &common, lint)
    } else {
        master_instance(&mut v, st, &common, lint)
    };
    if st.diag {
        v.push_str(&format!(
            "    always @(posedge clk)\n        case (i_diag_sel)\n\
             \x20           3'd0: o_diag <= perr;\n            3'd1: o_diag <= ferr;\n{diag_tail}\
             \x20           default: o_diag <= 16'd0;\n        endcase\n"
        ));
    }
    v.push_str("endmodule\n");
    Ok(v)
}

/// The slave module's instance in `merkur_top` (its sensor input's
/// synchroniser, its actuator register's wire); the diagnostic mux's cases
/// it adds.
fn slave_instance(
    v: &mut String,
    st: &NodeStatic,
    ports: &[&str],
    common: &str,
    (lint_off, lint_on): (&str, &str),
) -> &'static str {
    let act = st.kind == Kind::Actuator;
    let actb = u8::from(act);
    let sensor = if ports.contains(&"i_sensor") && !st.sensor_sync {
        "i_sensor"
    } else if ports.contains(&"i_sensor") {
        v.push_str(
            "    reg [15:0] sensor_m = 16'd0;\n    reg [15:0] sensor = 16'd0;\n\
             \x20   always @(posedge clk) begin\n        sensor_m <= i_sensor;\n        sensor <= sensor_m;\n    end\n",
        );
        "sensor"
    } else {
        "16'd0"
    };
    if ports.contains(&"o_act") {
        v.push_str("    wire [15:0] act_data;\n    assign o_act = act_data;\n");
    } else {
        v.push_str(&format!("{lint_off}    wire [15:0] act_data;\n{lint_on}"));
    }
    v.push_str(&format!(
        "    // Master-mode outputs of the slave module, unused in a slave.\n\
         \x20   /* verilator lint_off UNUSEDSIGNAL */\n\
         \x20   wire [11:0] nc_fwd_slot;\n    wire nc_regen;\n    wire nc_wvalid;\n    wire [1:0] nc_kind;\n\
         \x20   wire [11:0] nc_slot;\n    wire [15:0] nc_data;\n    wire nc_alive;\n    wire nc_alarm;\n    wire [3:0] nc_reason;\n    wire nc_ok;\n    wire nc_hdr_bad;\n    wire nc_rtx;\n\
         \x20   /* verilator lint_on UNUSEDSIGNAL */\n\
         \x20   {}  node(\n        {common},\n\
         \x20       .i_cap_sel(1'b1), .o_cap_si(sel_si), .i_actuator(1'b{actb}), .i_sensor_data({sensor}),\n\
         \x20       .i_master(1'b0), .i_slot_cfg(2'd0), .i_slot_data(16'd0), .i_slot_alive(1'b0), .i_fs_set(1'b0),\n\
         \x20       .o_fwd_slot(nc_fwd_slot), .o_regen(nc_regen), .o_wvalid(nc_wvalid), .o_kind(nc_kind),\n\
         \x20       .o_slot(nc_slot), .o_data(nc_data), .o_alive(nc_alive), .o_alarm(nc_alarm), .o_reason(nc_reason), .o_ok(nc_ok), .o_hdr_bad(nc_hdr_bad), .o_rtx(nc_rtx),\n\
         \x20       .o_act_data(act_data));\n",
        node_module(st.kind)
    ));
    "            3'd6: o_diag <= act_data;\n"
}

/// A master's or the special master's instance in `merkur_top` (the
/// Wishbone port to pins); the diagnostic mux's cases it adds.
fn master_instance(
    v: &mut String,
    st: &NodeStatic,
    common: &str,
    (lint_off, lint_on): (&str, &str),
) -> &'static str {
    let sm = st.kind == Kind::SpecialMaster;
    if sm {
        v.push_str("    // The special master's switchbox makes its own input choice.\n    assign sel_si = 1'b0;\n");
    }
    v.push_str(&format!("{lint_off}    wire [15:0] aerr;\n"));
    let extra = if sm {
        v.push_str("    wire [15:0] serr;\n    wire [11:0] hop;\n    wire [15:0] cycles;\n");
        v.push_str("    /* verilator lint_off UNUSEDSIGNAL */\n    wire base; // always 1 here: i_prio is 0, the clock base from power-up\n    /* verilator lint_on UNUSEDSIGNAL */\n");
        format!(
            ",\n        .i_period(20'd{}), .i_prio(3'd0), .i_elect(20'd0), .i_flying(1'b0), .i_rtx_at(20'd{}), .i_rtx_atw(20'd{}), .i_rtx_k(5'd{}), .i_rtx_kw(5'd{}),\n        .o_serr(serr), .o_hop(hop), .o_cycles(cycles), .o_base(base)",
            st.period, st.rtx.at, st.rtx.at_wrapped, st.rtx.k, st.rtx.k_wrapped
        )
    } else {
        ",\n        .i_cap_sel(1'b1), .o_cap_si(sel_si)".to_string()
    };
    v.push_str(lint_on);
    v.push_str(&format!(
        "    {} node(\n        {common},\n\
         \x20       .i_wb_cyc(i_wb_cyc), .i_wb_stb(i_wb_stb), .i_wb_we(i_wb_we), .i_wb_adr(i_wb_adr),\n\
         \x20       .i_wb_dat(i_wb_dat), .o_wb_dat(o_wb_dat), .o_wb_ack(o_wb_ack),\n\
         \x20       .o_irq1(o_irq1), .o_irq2(o_irq2), .o_irq_fs(o_irq_fs), .o_irq_rc(o_irq_rc), .o_alarmq(o_alarmq), .o_irq_fsc(o_irq_fsc), .o_aerr(aerr),\n\
         \x20       .o_running(o_running){extra});\n",
        node_module(st.kind)
    ));
    if sm {
        "            3'd2: o_diag <= aerr;\n            3'd3: o_diag <= serr;\n\
         \x20           3'd4: o_diag <= {4'd0, hop};\n            3'd5: o_diag <= cycles;\n"
    } else {
        "            3'd2: o_diag <= aerr;\n"
    }
}
