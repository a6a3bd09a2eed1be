//! # xem6010 — a master (or the special master) on the Opal Kelly XEM6010
//!
//! Purpose: the board top `merkur_xem6010`: the node's [`crate::top::synth_top`]
//! `merkur_top` clocked by a Spartan-6 clock manager (`DCM_SP`, not the
//! 802.4 Dual Channel Manager) from the board's PLL clock
//! (`clk` = `sys_clk`, `clk90` its 90° copy), fibres on the expansion
//! connector, status on the LEDs, and the board's USB host interface
//! (Opal Kelly FrontPanel: `okHost`, endpoints) bridged to the node's
//! Wishbone host port by `merkur_xem6010_core`. The FrontPanel modules are
//! Opal Kelly's proprietary netlists: here they are black boxes
//! ([`OK_BLACKBOXES`] declares their ports for Yosys and Verilator); a
//! bitstream needs Xilinx ISE and the FrontPanel HDL (docs/synthesis.md).
//!
//! Host protocol (FrontPanel endpoints; the host calls `UpdateWireIns`
//! before `ActivateTriggerIn` and polls `busy`):
//!
//! | endpoint | kind | meaning |
//! |---|---|---|
//! | 0x00 | WireIn | Wishbone word address `[13:0]` |
//! | 0x01 | WireIn | write data |
//! | 0x02 | WireIn | `[2:0]` diagnostic select (`o_diag` of [`crate::top::synth_top`]) |
//! | 0x40 | TriggerIn | bit 0 write, bit 1 read, bit 2 clear the interrupt flags, bits 3/4/5 request IRQ1/IRQ2/FAILSAFE |
//! | 0x20 | WireOut | read data of the last read |
//! | 0x21 | WireOut | status: 0 busy, 2:1 mode, 3 failsafe, 4 running, 5 IRQ1 seen, 6 IRQ2 seen, 7 FAILSAFE seen, 8 failsafe change seen (entered or left, protocol §12), 9 RECONFIG seen, 10 alarm queue not empty (read it over the host port, protocol §11) |
//! | 0x22 | WireOut | diagnostic value |
//!
//! `merkur_xem6010_core` ports (all on `clk` but the wire inputs, which the
//! host holds still while a trigger is in flight and which are
//! resynchronised here):
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clk`, `clk90` | in | 1 | core clock and its 90° copy |
//! | `pi`, `si`, `po`, `so` | | 1 | fibres |
//! | `i_adr`, `i_dat`, `i_ctl` | in | 16 | WireIns 0x00–0x02 |
//! | `i_trig` | in | 16 | TriggerIn 0x40 (one-clock pulses on `clk`) |
//! | `o_rdat`, `o_status`, `o_diag` | out | 16 | WireOuts 0x20–0x22 |
//! | `o_led` | out | 8 | LEDs, active low: 0 running, 1 mode WU, 2 mode WD, 3 failsafe, 4–6 interrupts seen, 7 busy |
//!
//! Latency: a Wishbone transfer starts the clock after its trigger and
//! takes the node's 1–4 clocks ([`crate::node::mdb`]); `busy` is high throughout.
//!
//! ```text
//! clk        _/‾\_/‾\_/‾\_/‾\_/‾\_/‾\_
//! i_trig[1]  _/‾‾‾\_________________   read
//! busy       _____/‾‾‾‾‾‾‾‾‾‾‾‾\_____
//! wb_ack     _____________/‾‾‾\_____
//! o_rdat     ================X= data
//! ```

use crate::top::synth_top::{node_top, NodeStatic};

/// Port declarations of Opal Kelly's FrontPanel modules (USB 2.0 boards:
/// `ok1` 31 bits, `ok2` 17 bits) as black boxes, for Yosys and Verilator
/// only; ISE takes Opal Kelly's own `okLibrary.v` and netlists.
pub const OK_BLACKBOXES: &str = r#"// FrontPanel (Opal Kelly) module ports, black boxes: not for ISE.
// Port declarations without bodies: outputs undriven, inputs unused.
/* verilator lint_off UNDRIVEN */
/* verilator lint_off UNUSEDSIGNAL */
/* verilator lint_off UNUSEDPARAM */
(* blackbox *)
module okHost(hi_in, hi_out, hi_inout, hi_aa, ti_clk, ok1, ok2);
    input wire [7:0] hi_in;
    output wire [1:0] hi_out;
    inout wire [15:0] hi_inout;
    inout wire hi_aa;
    output wire ti_clk;
    output wire [30:0] ok1;
    input wire [16:0] ok2;
endmodule
(* blackbox *)
module okWireOR(ok2, ok2s);
    parameter N = 1;
    output wire [16:0] ok2;
    input wire [N*17-1:0] ok2s;
endmodule
(* blackbox *)
module okWireIn(ok1, ep_addr, ep_dataout);
    input wire [30:0] ok1;
    input wire [7:0] ep_addr;
    output wire [15:0] ep_dataout;
endmodule
(* blackbox *)
module okWireOut(ok1, ok2, ep_addr, ep_datain);
    input wire [30:0] ok1;
    output wire [16:0] ok2;
    input wire [7:0] ep_addr;
    input wire [15:0] ep_datain;
endmodule
(* blackbox *)
module okTriggerIn(ok1, ep_addr, ep_clk, ep_trigger);
    input wire [30:0] ok1;
    input wire [7:0] ep_addr;
    input wire ep_clk;
    output wire [15:0] ep_trigger;
endmodule
"#;

/// Black-box port declarations of the Spartan-6 primitives the board top
/// uses, for Verilator (Yosys knows them from its Xilinx cell library).
pub const XILINX_BLACKBOXES: &str = r#"// Spartan-6 primitives, port declarations for lint only.
// Port declarations without bodies: outputs undriven, inputs unused.
/* verilator lint_off UNDRIVEN */
/* verilator lint_off UNUSEDSIGNAL */
/* verilator lint_off UNUSEDPARAM */
module DCM_SP(CLKIN, CLKFB, RST, CLK0, CLK90, LOCKED);
    parameter CLKIN_PERIOD = 10.0;
    parameter CLK_FEEDBACK = "1X";
    input wire CLKIN;
    input wire CLKFB;
    input wire RST;
    output wire CLK0;
    output wire CLK90;
    output wire LOCKED;
endmodule
module BUFG(I, O);
    input wire I;
    output wire O;
endmodule
"#;

/// The bridge and the node, without FrontPanel or Xilinx primitives.
const CORE: &str = r#"
// merkur_xem6010_core: FrontPanel endpoints <-> the node's Wishbone port.
module merkur_xem6010_core(clk, clk90, pi, si, po, so, i_adr, i_dat, i_ctl, i_trig, o_rdat, o_status, o_diag, o_led);
    input wire clk;
    input wire clk90;
    input wire pi;
    input wire si;
    output wire po;
    output wire so;
    input wire [15:0] i_adr;
    input wire [15:0] i_dat;
    input wire [15:0] i_ctl;
    /* verilator lint_off UNUSEDSIGNAL */
    input wire [15:0] i_trig;   // bits 15:6 are not used
    /* verilator lint_on UNUSEDSIGNAL */
    output reg [15:0] o_rdat = 16'd0;
    output wire [15:0] o_status;
    output wire [15:0] o_diag;
    output wire [7:0] o_led;
    // WireIns come from the host clock: resynchronise (the host holds them
    // still while a trigger is in flight).
    /* verilator lint_off UNUSEDSIGNAL */
    reg [15:0] adr_m = 16'd0;
    reg [15:0] adr_s = 16'd0;
    reg [15:0] ctl_m = 16'd0;
    reg [15:0] ctl_s = 16'd0;
    /* verilator lint_on UNUSEDSIGNAL */
    reg [15:0] dat_m = 16'd0;
    reg [15:0] dat_s = 16'd0;
    always @(posedge clk) begin
        adr_m <= i_adr;
        adr_s <= adr_m;
        dat_m <= i_dat;
        dat_s <= dat_m;
        ctl_m <= i_ctl;
        ctl_s <= ctl_m;
    end
    // One Wishbone transfer per trigger.
    reg busy = 1'b0;
    reg we = 1'b0;
    reg [13:0] adr = 14'd0;
    reg [15:0] wdat = 16'd0;
    wire [15:0] wb_rdat;
    wire wb_ack;
    always @(posedge clk) begin
        if (!busy && (i_trig[0] || i_trig[1])) begin
            busy <= 1'b1;
            we <= i_trig[0];
            adr <= adr_s[13:0];
            wdat <= dat_s;
        end else if (busy && wb_ack) begin
            busy <= 1'b0;
            if (!we) o_rdat <= wb_rdat;
        end
    end
    // Interrupts seen, until cleared.
    wire irq1;
    wire irq2;
    wire irq_fs;
    wire irq_fsc;
    wire irq_rc;
    wire alarmq;
    reg [4:0] seen = 5'd0;
    always @(posedge clk)
        if (i_trig[2]) seen <= 5'd0;
        else seen <= seen | {irq_rc, irq_fsc, irq_fs, irq2, irq1};
    wire [1:0] mode;
    wire failsafe;
    wire running;
    merkur_top node(.clk(clk), .clk90(clk90), .pi(pi), .si(si), .po(po), .so(so),
        .i_irq1(i_trig[3]), .i_irq2(i_trig[4]), .i_fs_req(i_trig[5]), .o_mode(mode), .o_failsafe(failsafe),
        .i_diag_sel(ctl_s[2:0]), .o_diag(o_diag),
        .i_wb_cyc(busy), .i_wb_stb(busy), .i_wb_we(we), .i_wb_adr(adr), .i_wb_dat(wdat),
        .o_wb_dat(wb_rdat), .o_wb_ack(wb_ack),
        .o_irq1(irq1), .o_irq2(irq2), .o_irq_fs(irq_fs), .o_irq_rc(irq_rc), .o_alarmq(alarmq), .o_irq_fsc(irq_fsc),
        .o_running(running));
    assign o_status = {5'd0, alarmq, seen, running, failsafe, mode, busy};
    assign o_led = ~{busy, seen[2:0], failsafe, mode == 2'd2, mode == 2'd1, running};
endmodule
"#;

/// The board top proper (FrontPanel endpoints, the DCM_SP clock manager, core).
const TOP: &str = r#"
// merkur_xem6010: the board top (pins: gen/constraints/xem6010.ucf).
module merkur_xem6010(hi_in, hi_out, hi_inout, hi_aa, hi_muxsel, sys_clk, led, pi, si, po, so);
    input wire [7:0] hi_in;
    output wire [1:0] hi_out;
    inout wire [15:0] hi_inout;
    inout wire hi_aa;
    output wire hi_muxsel;
    input wire sys_clk;
    output wire [7:0] led;
    input wire pi;
    input wire si;
    output wire po;
    output wire so;
    assign hi_muxsel = 1'b0;
    // Core clock (2x the line rate: 100 MHz for 50 Mbit/s) and its 90° copy.
    wire clk0;
    wire clk90_0;
    wire clk;
    wire clk90;
    /* verilator lint_off UNUSEDSIGNAL */
    wire locked;
    /* verilator lint_on UNUSEDSIGNAL */
    DCM_SP #(.CLKIN_PERIOD(10.0), .CLK_FEEDBACK("1X")) dcm(.CLKIN(sys_clk), .CLKFB(clk), .RST(1'b0),
        .CLK0(clk0), .CLK90(clk90_0), .LOCKED(locked));
    BUFG bufg0(.I(clk0), .O(clk));
    BUFG bufg90(.I(clk90_0), .O(clk90));
    // FrontPanel host interface and endpoints.
    /* verilator lint_off UNUSEDSIGNAL */
    wire ti_clk;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [30:0] ok1;
    wire [16:0] ok2;
    wire [3*17-1:0] ok2x;
    wire [15:0] w_adr;
    wire [15:0] w_dat;
    wire [15:0] w_ctl;
    wire [15:0] trig;
    wire [15:0] rdat;
    wire [15:0] status;
    wire [15:0] diag;
    okHost host(.hi_in(hi_in), .hi_out(hi_out), .hi_inout(hi_inout), .hi_aa(hi_aa), .ti_clk(ti_clk), .ok1(ok1), .ok2(ok2));
    okWireOR #(.N(3)) wire_or(.ok2(ok2), .ok2s(ok2x));
    okWireIn wi00(.ok1(ok1), .ep_addr(8'h00), .ep_dataout(w_adr));
    okWireIn wi01(.ok1(ok1), .ep_addr(8'h01), .ep_dataout(w_dat));
    okWireIn wi02(.ok1(ok1), .ep_addr(8'h02), .ep_dataout(w_ctl));
    okTriggerIn ti40(.ok1(ok1), .ep_addr(8'h40), .ep_clk(clk), .ep_trigger(trig));
    okWireOut wo20(.ok1(ok1), .ok2(ok2x[0*17 +: 17]), .ep_addr(8'h20), .ep_datain(rdat));
    okWireOut wo21(.ok1(ok1), .ok2(ok2x[1*17 +: 17]), .ep_addr(8'h21), .ep_datain(status));
    okWireOut wo22(.ok1(ok1), .ok2(ok2x[2*17 +: 17]), .ep_addr(8'h22), .ep_datain(diag));
    merkur_xem6010_core core(.clk(clk), .clk90(clk90), .pi(pi), .si(si), .po(po), .so(so),
        .i_adr(w_adr), .i_dat(w_dat), .i_ctl(w_ctl), .i_trig(trig),
        .o_rdat(rdat), .o_status(status), .o_diag(diag), .o_led(led));
endmodule
"#;

/// The Verilog of the XEM6010 top for a master or special master node:
/// the node's `merkur_top`, the bridge core and `merkur_xem6010` (the
/// FrontPanel modules and Xilinx primitives stay external).
pub fn xem6010_verilog(st: &NodeStatic) -> Result<String, String> {
    use merkur_model::scenario::Kind;
    if !matches!(st.kind, Kind::Master | Kind::SpecialMaster) {
        return Err(format!(
            "the XEM6010 top carries a master or the special master, not a {}",
            st.kind.name()
        ));
    }
    let mut v = xem6010_core_verilog(st)?;
    v.push_str(TOP);
    Ok(v)
}

/// The core alone (node + bridge), for simulation tests.
pub fn xem6010_core_verilog(st: &NodeStatic) -> Result<String, String> {
    if !st.diag {
        return Err(
            "the XEM6010 top reads the diagnostic mux over FrontPanel (WireOut 0x22): \
                    build it with the diagnostic mux"
                .into(),
        );
    }
    let mut v = node_top(st)?;
    v.push_str(CORE);
    Ok(v)
}
