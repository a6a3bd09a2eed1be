//! # ulx3s — a slave on the Radiona ULX3S (ECP5)
//!
//! Purpose: the board top `merkur_ulx3s`: a slave's [`crate::top::synth_top`]
//! `merkur_top` clocked by the ECP5's PLL (`EHXPLLL`) from the board's
//! 25 MHz oscillator — `clk` at 2 × the line rate and `clk90`, its 90°
//! copy, both from one PLL so their phase is fixed — with the fibres, the
//! sensor inputs and the diagnostic outputs on the two GPIO headers, the
//! user requests on buttons, the diagnostic select on the DIP switch and
//! the state on the LEDs. Pins: [`crate::top::boards::ulx3s`] (one source,
//! `gen/constraints/ulx3s.lpf`).
//!
//! The PLL module `merkur_pll` is not here: `merkur synth --board ulx3s`
//! has Project Trellis' `ecppll` compute it for the run's clock (any line
//! rate the PLL can make from 25 MHz) and writes it beside the top as
//! `pll.v`; [`PLL_BLACKBOX`] declares its ports for lint.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clk_25mhz` | in | 1 | board oscillator |
//! | `pi`, `si` | in | 1 | primary and secondary fibre receivers (J1) |
//! | `po`, `so` | out | 1 | primary and secondary fibre transmitters (J1) |
//! | `btn[3:1]` | in | 3 | FIRE1 → IRQ1, FIRE2 → IRQ2, UP → FAILSAFE request |
//! | `sw[2:0]` | in | 3 | `i_diag_sel` |
//! | `led[3:0]` | out | 4 | 1:0 mode (0 N, 1 WU, 2 WD), 2 failsafe, 3 PLL locked |
//! | `sensor[15:0]` | in | 16 | sensor value (J2) |
//! | `diag[15:0]` | out | 16 | `o_diag` (J1) |
//!
//! Latency: as `merkur_top`; the PLL locks within its datasheet time after
//! configuration. The node has no reset input: it starts from its
//! flip-flops' initial values when the bitstream loads, and its clock runs
//! from the PLL's output whether or not it is locked yet (`led[3]` shows
//! the lock). Holding the node until lock would need a reset or clock
//! enable the node does not have; not done here, not tested on hardware.
//!
//! Both PLL outputs go through a `DCCA` onto a global clock network, so
//! the capture's four sample edges keep the PLL's quarter-clock spacing:
//! nextpnr-ecp5 promotes only a clock with five or more clock loads, and
//! `clk90` has four (the capture's), so without the `DCCA` it ran on
//! general routing with a delay of its own ([`ECP5_BLACKBOXES`] declares
//! the primitive for lint).

use crate::top::synth_top::{node_top, NodeStatic};
use merkur_model::scenario::Kind;

/// Port declaration of the PLL module that `ecppll` writes, as a black box
/// for Yosys checks and Verilator lint without the PLL (a body-less module:
/// its outputs are undriven and its input unused, hence the two waivers).
pub const PLL_BLACKBOX: &str = r#"// merkur_pll (written by ecppll at build time): ports only.
/* verilator lint_off UNDRIVEN */
/* verilator lint_off UNUSEDSIGNAL */
(* blackbox *)
module merkur_pll(clk_25mhz, clk, clk90, locked);
    input wire clk_25mhz;
    output wire clk;
    output wire clk90;
    output wire locked;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
/* verilator lint_on UNDRIVEN */
"#;

/// The ECP5 primitive the top instantiates (`DCCA`, a global clock
/// buffer), ports only, for Verilator (Yosys knows it from its ECP5 cell
/// library).
pub const ECP5_BLACKBOXES: &str = r#"// ECP5 primitives, port declarations for lint only.
// A port declaration without a body: its output undriven, inputs unused.
/* verilator lint_off UNDRIVEN */
/* verilator lint_off UNUSEDSIGNAL */
module DCCA(CLKI, CE, CLKO);
    input wire CLKI;
    input wire CE;
    output wire CLKO;
endmodule
/* verilator lint_on UNUSEDSIGNAL */
/* verilator lint_on UNDRIVEN */
"#;

const TOP: &str = r#"
// merkur_ulx3s: a slave on the Radiona ULX3S (rtl/src/top/ulx3s.rs).
module merkur_ulx3s(clk_25mhz, pi, si, po, so, btn, sw, led, sensor, diag);
    input wire clk_25mhz;
    input wire pi;
    input wire si;
    output wire po;
    output wire so;
    input wire [3:1] btn;
    input wire [2:0] sw;
    output wire [3:0] led;
    input wire [15:0] sensor;
    output wire [15:0] diag;
    wire clk_pll;
    wire clk90_pll;
    wire clk;
    wire clk90;
    wire locked;
    merkur_pll pll(.clk_25mhz(clk_25mhz), .clk(clk_pll), .clk90(clk90_pll), .locked(locked));
    // Both clocks on global networks, so the capture's four sample edges
    // keep the PLL's quarter-clock spacing: nextpnr-ecp5 promotes only a
    // clock with 5 or more clock loads, and clk90 has 4.
    DCCA gclk(.CLKI(clk_pll), .CE(1'b1), .CLKO(clk));
    DCCA gclk90(.CLKI(clk90_pll), .CE(1'b1), .CLKO(clk90));
    assign led[3] = locked;
    merkur_top node(.clk(clk), .clk90(clk90), .pi(pi), .si(si), .po(po), .so(so),
        .i_irq1(btn[1]), .i_irq2(btn[2]), .i_fs_req(btn[3]),
        .o_mode(led[1:0]), .o_failsafe(led[2]), .i_diag_sel(sw), .o_diag(diag),
        .i_sensor(sensor));
endmodule
"#;

/// The Verilog of the ULX3S top for a slave: the node's `merkur_top` and
/// `merkur_ulx3s` (the PLL module comes from `ecppll`).
pub fn ulx3s_verilog(st: &NodeStatic) -> Result<String, String> {
    if !matches!(st.kind, Kind::Sensor | Kind::Actuator) {
        return Err(format!(
            "the ULX3S top carries a slave, not a {}: a master's parallel host port needs more pins than the board's 56 header pins",
            st.kind.name()
        ));
    }
    if !st.diag {
        return Err(
            "the ULX3S top wires the diagnostic mux to the board (its DIP switch and \
                    header J1): build it with the diagnostic mux"
                .into(),
        );
    }
    let mut v = node_top(st)?;
    v.push_str(TOP);
    Ok(v)
}
