//! # ring_top — a whole ring for simulation: nodes, fibres, fault points, monitors
//!
//! Purpose: `merkur verilog` and `merkur sim` wire N nodes (the scenario's
//! kinds in ring order) over duplex fibres into one Verilog top,
//! `merkur_ring`. It is a **simulation harness** around the product blocks
//! ([`crate::slave`], [`crate::master`], [`crate::special_master`],
//! [`crate::monitor`]), written as Verilog text because its shape (N
//! instances, 2N fibres) is the scenario's. Everything a scenario varies at
//! run time — node addresses, clock offsets and phases, sensor values, user
//! requests, period, slot count, fault points — is a register written
//! through one configuration port, so one Verilator build serves every
//! scenario with the same node kinds and slot-count class.
//!
//! **Clocks.** The top's `clk` is the simulation tick, 8 ticks per nominal
//! bit time (one receive sample). Node k runs on its own clock
//! `nclk_k = clk & en_k`: a 32-bit fractional accumulator adds `inc_k`
//! (≈ 2³⁰ · (1 + ppm·10⁻⁶), a quarter of the tick rate = 2× the line rate)
//! every tick and its carry enables the next tick's
//! edge (the enable is latched on the falling edge, so the gated clock has no
//! glitch); the accumulator's start value is the node's random phase. So
//! every node has its scenario's frequency offset and its own phase, with one
//! evaluation per tick. In synthesis the node's clock is its oscillator; this
//! gate exists only here.
//!
//! **Fibres.** Fibre P*k* (node k PO → node k+1 PI) and S*k* (node k+1 SO →
//! node k SI) are line levels at tick resolution: the sender's DDR pair
//! shows bit 0 in the 2 ticks after its clock edge and bit 1 until its next
//! edge; the receiver's 4 samples are the line in the last 4 ticks (oldest
//! in bit 0), taken into a register at the receiver's clock edge, as the
//! capture register of every synthesis top (`merkur_ddr_in`'s `q`) takes
//! them: the node's logic reads them in the clock after. Everything else
//! the top gives a node (address, slot count, CS timeout, period, sensor
//! value, user requests) goes through a register on the node's clock too,
//! as in silicon, where they are constants or synchronised. Besides being
//! the silicon's timing, this keeps every input of a node still between
//! its own clock edges, so Verilator evaluates a node's logic at its edges
//! only, not at every tick (issue 24: ring100 1.7× faster,
//! docs/benchmarks.md). A node clock period of 3 or 5 ticks (how the accumulator
//! makes the offset) moves that node's edges or samples by one tick = one
//! receive sample; the receiver's margin (`cdr`, `retime`) covers it. Each
//! fibre has a **fault point** (break: the line goes dark, as when its
//! sender dies; flip: one line bit of the next packet is inverted, on the
//! sender's own bit grid — the harness finds it from the line's edges, a
//! boundary every 4 DDR halves between them — so the receiver sees exactly
//! the single line-bit error the model applies; burst: from such a bit on,
//! the line carries the model's garbage for a number of bits, made by the
//! same generator, the level inverted where the garbage's code bit differs
//! from the sender's) and a **monitor** (clock recovery,
//! framer, word decoder at the nominal rate) whose DATA words are captured
//! per cycle: entry `(cyc & 3) · CAP + slot` holds `{EPOCH[7:0], CYC[2:0],
//! status[1:0], ALARM, ALIVE, data[15:0]}` with status 1 good, 2 bad, 3
//! VOID and EPOCH the special master's frame count (low 8 bits) when it was
//! written; a slot whose entry has another CYC, or an EPOCH that is not
//! 0…4 frames after the cycle's (left from 8 cycles before), was missing
//! in that cycle; entries
//! `4 · CAP + 2 (cyc & 3) + {0, 1}` hold the frame's H0 and H1.
//!
//! **Ports.**
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clk` | in | 1 | simulation tick (4 per nominal bit time) |
//! | `i_cfg_we`, `i_cfg_sel`, `i_cfg_field`, `i_cfg_val` | in | 1, 16, 8, 32 | configuration write (table below) |
//! | `i_rd_en`, `i_rd_sel`, `i_rd_field` | in | 1, 16, 8 | status read enable and address |
//! | `o_rd` | out | 32 | status read data (combinational; 0 while `i_rd_en` is low) |
//! | `i_cap_en`, `i_cap_fibre`, `i_cap_idx` | in | 1, 16, log2(4·CAP) | capture read enable and address (fibre P0.. then S0..) |
//! | `o_cap` | out | 32 | captured entry (combinational; 0 while `i_cap_en` is low) |
//! | `i_wb_node`, `i_wb_cyc`, `i_wb_stb`, `i_wb_we`, `i_wb_adr`, `i_wb_dat` | in | | Wishbone of master `i_wb_node` (its own clock) |
//! | `o_wb_dat`, `o_wb_ack` | out | 16, 1 | its Wishbone answer |
//!
//! Configuration fields ([`cfg`]; `i_cfg_sel` = node or fibre index; global
//! fields ignore it) and status fields ([`status`]) are named in this file
//! and used by name by the driver (`testbenches/src/ring_sim.rs`). A user
//! request is raised at once (`now`) or when the node's pacing monitor (its
//! PI fibre; the special master's PO) sees the end of the DATA frame with
//! the request's CYC, i.e. before the next frame; a sensor sees the value
//! of the frame whose H1 its PI fibre showed last (its slot comes after).

use crate::verilog::{block_verilog, mem_depth, rename_top, size_memories};
use merkur_model::scenario::Kind;

/// Ticks of the simulation clock per nominal bit time (one tick per
/// receive sample, [`crate::cdr::SAMPLES_PER_BIT`]).
pub const TICKS_PER_BIT: u32 = crate::cdr::SAMPLES_PER_BIT as u32;

/// A node's clock increment per tick at 0 ppm: its clock (2 per bit time)
/// is a quarter of the tick rate on a 32-bit accumulator.
pub const INC_NOMINAL: u64 = 1 << 30;

/// Configuration fields of `merkur_ring` (`i_cfg_field`).
pub mod cfg {
    /// Node: clock increment per tick ([`INC_NOMINAL`] at 0 ppm).
    pub const INC: u32 = 0;
    /// Node: clock accumulator start value (phase).
    pub const PHASE: u32 = 1;
    /// Node: home slot.
    pub const ADDRESS: u32 = 2;
    /// Sensor: value for cycles with CYC ≡ `val[17:16]` (mod 4).
    pub const SENSOR: u32 = 3;
    /// Node: user request `{now, armed, CYC[2:0], fs, irq2, irq1}`.
    pub const REQUEST: u32 = 4;
    /// Fibre: 1 dark, 0 lit.
    pub const BREAK: u32 = 8;
    /// Node: 1 dead (both its output fibres dark), 0 alive.
    pub const KILL: u32 = 10;
    /// Fibre: arm a flip of line bit `val[11:0]` of the next packet (bit 0 =
    /// the first bit of its J K; counted from J's first 0 code bit, so
    /// bits 0 and 1 cannot be hit and are refused by the driver); with
    /// `val[23:12]` ≠ 0, a burst of that many bits of garbage from there
    /// (`merkur_model::line::garbage` of the pattern `val[31:24]`).
    pub const FLIP: u32 = 9;
    /// Global: slots − 1.
    pub const SLOTS_M1: u32 = 16;
    /// Global: CS timeout in node clocks.
    pub const CS_TIMEOUT: u32 = 17;
    /// Global: cycle period in bit times.
    pub const PERIOD: u32 = 18;
}

/// Status fields of `merkur_ring` (`i_rd_field`): node fields for
/// `i_rd_sel` = node, fibre fields for `i_rd_sel` = fibre.
pub mod status {
    /// Node: switchbox mode.
    pub const MODE: u32 = 0;
    /// Node: failsafe.
    pub const FS: u32 = 1;
    /// Node: bad words at INPUT.
    pub const PERR: u32 = 2;
    /// Node: rejected headers at INPUT.
    pub const FERR: u32 = 3;
    /// Master: Alive-check failures.
    pub const AERR: u32 = 4;
    /// Special master: SEC failures.
    pub const SERR: u32 = 5;
    /// Special master: HOP returned.
    pub const HOP: u32 = 6;
    /// Actuator: output register.
    pub const ACT: u32 = 7;
    /// Special master: frames sent.
    pub const CYCLES: u32 = 8;
    /// Master: IRQ1 alarms received.
    pub const IRQ1: u32 = 9;
    /// Master: IRQ2 alarms received.
    pub const IRQ2: u32 = 10;
    /// Master: FAILSAFE alarms received.
    pub const IRQFS: u32 = 11;
    /// Master: running.
    pub const RUN: u32 = 12;
    /// Master: failsafe-change interrupts (entered or left, protocol §12).
    pub const IRQFSC: u32 = 13;
    /// Master: RECONFIG alarms received (reasons 4–6, protocol §11).
    pub const IRQRC: u32 = 14;
    /// Fibre: `{in frame, last CYC[2:0]}`.
    pub const FRAME: u32 = 16;
    /// Fibre: last DATA H1.
    pub const H1: u32 = 17;
    /// Fibre: last DATA H0.
    pub const H0: u32 = 18;
    /// Fibre: SEC packets seen.
    pub const NSEC: u32 = 19;
    /// Fibre: TST packets seen.
    pub const NTST: u32 = 20;
    /// Fibre: loss of signal.
    pub const LOS: u32 = 21;
    /// Fibre: DATA frames ended.
    pub const NEND: u32 = 22;
    /// Fibre: simulation tick (low 32 bits) at which the monitor decoded the
    /// last DATA H1; between the fibres into and out of a node, the node's
    /// forwarding delay (the monitors are identical and on one clock).
    pub const TH1: u32 = 23;
    /// Fibre: `{in frame, CYC[2:0] of the last DATA H1, 16 zero bits, last
    /// slot decoded since (FFF: none yet)}`, for the driver's fault timing.
    pub const AT: u32 = 24;
}

/// Module name of a node kind in the ring Verilog.
pub fn module_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Sensor | Kind::Actuator => "merkur_slave",
        Kind::Master => "merkur_master",
        Kind::SpecialMaster => "merkur_special_master",
    }
}

/// The Verilog of a node kind's modules, named after [`module_name`], for a
/// ring of `slots` slots: the memories are [`mem_depth`]`(slots)` deep
/// ([`size_memories`]). Simulation and synthesis both use this text.
pub fn node_verilog(kind: Kind, slots: usize) -> String {
    let v = match kind {
        Kind::Sensor | Kind::Actuator => block_verilog(crate::slave::Slave::new()),
        Kind::Master => block_verilog(crate::master::Master::default()),
        Kind::SpecialMaster => block_verilog(crate::special_master::SpecialMaster::default()),
    };
    rename_top(&size_memories(&v, mem_depth(slots)), module_name(kind))
}

/// Capture entries per cycle buffer: slots rounded up to a power of two.
pub fn cap_slots(slots: usize) -> usize {
    slots.next_power_of_two().max(2)
}

/// The Verilog of every module the ring needs plus the `merkur_ring` top.
pub fn ring_verilog(kinds: &[Kind], slots: usize) -> String {
    let n = kinds.len();
    let cap = cap_slots(slots);
    let mut out = String::new();
    out.push_str(&format!(
        "// merkur ring: {n} nodes ({}), capture {cap} slots per cycle.\n\
         // Generated by merkur-rtl (rtl/src/ring_top.rs); do not edit.\n",
        kinds.iter().map(|k| k.name()).collect::<Vec<_>>().join(",")
    ));
    let mut need: Vec<Kind> = vec![];
    for &k in kinds {
        let k = if k == Kind::Actuator { Kind::Sensor } else { k };
        if !need.contains(&k) {
            need.push(k);
        }
    }
    for k in need {
        out.push_str(&node_verilog(k, slots));
    }
    out.push_str(&rename_top(
        &block_verilog(crate::monitor::Monitor::new(false)),
        "merkur_monitor",
    ));
    out.push_str(&top(kinds, cap));
    out
}

/// Node `k`'s inputs, registered on its own clock (module doc: the
/// capture register of a synthesis top; the configuration constant or
/// synchronised there): the sample windows `pi`, `si`, the address, slot
/// count, CS timeout and requests; a sensor's value; the special master's
/// period.
fn node_inputs(k: usize, kind: Kind, pi: &str, si: &str) -> String {
    let (mut regs, mut loads) = (
        format!(
            "    reg [3:0] pi_r_{k} = 4'd0, si_r_{k} = 4'd0;\n    reg [11:0] addr_r_{k} = 12'd0, slots_m1_r_{k} = 12'd0;\n\
             \x20   reg [19:0] cs_timeout_r_{k} = 20'd0;\n    reg [2:0] ureq_r_{k} = 3'd0;\n"
        ),
        format!(
            "        pi_r_{k} <= {pi};\n        si_r_{k} <= {si};\n        addr_r_{k} <= addr_{k};\n\
             \x20       slots_m1_r_{k} <= slots_m1;\n        cs_timeout_r_{k} <= cs_timeout;\n        ureq_r_{k} <= ureq_{k};\n"
        ),
    );
    if kind == Kind::Sensor {
        regs += &format!("    reg [15:0] sens_r_{k} = 16'd0;\n");
        loads += &format!("        sens_r_{k} <= sens_{k};\n");
    }
    if kind == Kind::SpecialMaster {
        regs += &format!("    reg [19:0] period_r_{k} = 20'd0;\n");
        loads += &format!("        period_r_{k} <= period;\n");
    }
    format!("{regs}    always @(posedge nclk_{k}) begin\n{loads}    end")
}

fn top(kinds: &[Kind], cap: usize) -> String {
    let n = kinds.len();
    let nf = 2 * n;
    let capw = (8 * cap).trailing_zeros() as usize;
    let mut v = String::new();
    let w = |v: &mut String, s: &str| {
        v.push_str(s);
        v.push('\n');
    };
    w(
        &mut v,
        "module merkur_ring(clk, i_cfg_we, i_cfg_sel, i_cfg_field, i_cfg_val, i_rd_en, i_rd_sel, i_rd_field, o_rd,\n\
         \x20   i_cap_en, i_cap_fibre, i_cap_idx, o_cap, i_wb_node, i_wb_cyc, i_wb_stb, i_wb_we, i_wb_adr, i_wb_dat, o_wb_dat, o_wb_ack);",
    );
    w(
        &mut v,
        "    input wire clk;\n    input wire i_cfg_we;\n    input wire [15:0] i_cfg_sel;\n    input wire [7:0] i_cfg_field;\n    input wire [31:0] i_cfg_val;\n\
         \x20   input wire i_rd_en;\n    input wire [15:0] i_rd_sel;\n    input wire [7:0] i_rd_field;\n    output reg [31:0] o_rd;\n\
         \x20   input wire i_cap_en;\n    input wire [15:0] i_cap_fibre;\n    input wire [CAPW-1:0] i_cap_idx;\n    output reg [31:0] o_cap;\n\
         \x20   input wire [15:0] i_wb_node;\n    input wire i_wb_cyc;\n    input wire i_wb_stb;\n    input wire i_wb_we;\n\
         \x20   input wire [13:0] i_wb_adr;\n    input wire [15:0] i_wb_dat;\n    output reg [15:0] o_wb_dat;\n    output reg o_wb_ack;",
    );
    v = v.replace("CAPW-1", &(capw - 1).to_string());
    w(
        &mut v,
        "    // Shared configuration.\n    reg [11:0] slots_m1 = 12'd0;\n    reg [19:0] cs_timeout = 20'hfffff;\n    reg [19:0] period = 20'd0;\n\
         \x20   // Ticks since the start (for the fibres' H1 times).\n    reg [31:0] tick = 32'd0;\n    always @(posedge clk) tick <= tick + 32'd1;\n\
         \x20   // Monitors run at the nominal rate (a quarter of the tick rate).\n    reg [1:0] mcnt = 2'd0;\n    always @(posedge clk) mcnt <= mcnt + 2'd1;\n\
         \x20   reg men_l = 1'b0;\n    always @(negedge clk) men_l <= mcnt == 2'd3;\n    wire mclk = clk & men_l;",
    );
    // Each fibre monitor's last DATA header (used by the nodes' stimulus).
    w(
        &mut v,
        "    /* verilator lint_off UNUSEDSIGNAL */\n    // Only the fibres into a node's PI drive its stimulus (mode N).",
    );
    for f in 0..nf {
        w(
            &mut v,
            &format!("    reg [2:0] hdr_cyc_{f} = 3'd0;\n    reg hdr_new_{f} = 1'b0;"),
        );
    }
    w(&mut v, "    /* verilator lint_on UNUSEDSIGNAL */");
    // Nodes: clock gates, configuration, instances.
    let hit = |sel: usize, field: u32| {
        format!("i_cfg_we && i_cfg_sel == 16'd{sel} && i_cfg_field == 8'd{field}")
    };
    for (k, &kind) in kinds.iter().enumerate() {
        // The fibre whose frame ends pace the node's stimulus: its PI
        // (P(k-1)); for the special master, which builds frames, its PO.
        let pi_f = (k + n - 1) % n;
        let up = if kind == Kind::SpecialMaster { k } else { pi_f };
        let (in_cyc, in_new) = if kind == Kind::SpecialMaster {
            (format!("hdr_cyc_{up}"), format!("hdr_new_{up}"))
        } else {
            (
                format!(
                    "(mode_{k} == 2'd1) ? hdr_cyc_{si} : hdr_cyc_{up}",
                    si = n + k
                ),
                format!(
                    "(mode_{k} == 2'd1) ? hdr_new_{si} : hdr_new_{up}",
                    si = n + k
                ),
            )
        };
        let (h_inc, h_phase, h_addr, h_req, h_kill) = (
            hit(k, cfg::INC),
            hit(k, cfg::PHASE),
            hit(k, cfg::ADDRESS),
            hit(k, cfg::REQUEST),
            hit(k, cfg::KILL),
        );
        w(
            &mut v,
            &format!(
                "    // ---- node {k}: {kind} ----\n\
                 \x20   wire [1:0] mode_{k};\n\
                 \x20   // The fibre that brings the node its frames: PI, or SI when wrapped up (WU).\n\
                 \x20   wire [2:0] incyc_{k} = {in_cyc};\n    wire innew_{k} = {in_new};\n\
                 \x20   reg [31:0] inc_{k} = 32'h40000000;\n    reg [31:0] acc_{k} = 32'd0;\n    reg en_{k} = 1'b0;\n    reg enl_{k} = 1'b0;\n    reg fired_{k} = 1'b0, fired2_{k} = 1'b0, selp_{k} = 1'b0;\n    reg dead_{k} = 1'b0;\n    // A new half of the node's DDR output pair starts on the line (tick resolution).\n    wire hs_{k} = fired_{k} | (selp_{k} & !fired2_{k});\n\
                 \x20   always @(posedge clk) begin\n        {{en_{k}, acc_{k}}} <= {{1'b0, acc_{k}}} + {{1'b0, inc_{k}}};\n        fired_{k} <= enl_{k};\n        fired2_{k} <= fired_{k};\n        selp_{k} <= fired_{k} | fired2_{k};\n\
                 \x20       if ({h_inc}) inc_{k} <= i_cfg_val;\n\
                 \x20       if ({h_phase}) acc_{k} <= i_cfg_val;\n        if ({h_kill}) dead_{k} <= i_cfg_val[0];\n    end\n\
                 \x20   always @(negedge clk) enl_{k} <= en_{k};\n    wire nclk_{k} = clk & enl_{k};\n\
                 \x20   reg [11:0] addr_{k} = 12'd0;\n\
                 \x20   reg [7:0] req_{k} = 8'd0;\n    reg [3:0] reqhold_{k} = 4'd0;\n    reg [2:0] reqbits_{k} = 3'd0;\n\
                 \x20   always @(posedge clk) begin\n\
                 \x20       if ({h_addr}) addr_{k} <= i_cfg_val[11:0];\n\
                 \x20       if (reqhold_{k} != 4'd0) reqhold_{k} <= reqhold_{k} - 4'd1;\n\
                 \x20       if (req_{k}[6] && (req_{k}[7] || (innew_{k} && incyc_{k} == req_{k}[5:3]))) begin\n\
                 \x20           reqbits_{k} <= req_{k}[2:0];\n            reqhold_{k} <= 4'd8;\n            req_{k}[6] <= 1'b0;\n        end\n\
                 \x20       if ({h_req}) req_{k} <= i_cfg_val[7:0];\n    end\n\
                 \x20   wire [2:0] ureq_{k} = (reqhold_{k} != 4'd0) ? reqbits_{k} : 3'd0;\n\
                 \x20   wire [1:0] po_{k}, so_{k};\n    wire fs_{k};\n    wire [15:0] perr_{k}, ferr_{k};",
                kind = kind.name()
            ),
        );
        if kind == Kind::Sensor {
            // Four values, chosen by the CYC of the frame whose H1 the
            // sensor's PI fibre showed last.
            let h = hit(k, cfg::SENSOR);
            let regs: Vec<String> = (0..4)
                .map(|i| format!("        if ({h} && i_cfg_val[17:16] == 2'd{i}) sens_{k}_{i} <= i_cfg_val[15:0];"))
                .collect();
            w(
                &mut v,
                &format!(
                    "    reg [15:0] sens_{k}_0 = 16'd0, sens_{k}_1 = 16'd0, sens_{k}_2 = 16'd0, sens_{k}_3 = 16'd0;\n\
                     \x20   always @(posedge clk) begin\n{}\n    end\n    wire [1:0] sel_{k} = incyc_{k}[1:0];\n\
                     \x20   wire [15:0] sens_{k} = sel_{k} == 2'd0 ? sens_{k}_0 : sel_{k} == 2'd1 ? sens_{k}_1 : sel_{k} == 2'd2 ? sens_{k}_2 : sens_{k}_3;",
                    regs.join("\n")
                ),
            );
        }
        let pi = format!("{{line_{pi_f}, sh_{pi_f}}}");
        let si = format!("{{line_{}, sh_{}}}", n + k, n + k);
        w(&mut v, &node_inputs(k, kind, &pi, &si));
        let common = format!(
            ".clock(nclk_{k}), .i_pi(pi_r_{k}), .i_si(si_r_{k}), .o_po(po_{k}), .o_so(so_{k}), .i_address(addr_r_{k}), .i_slots_m1(slots_m1_r_{k}), .i_cs_timeout(cs_timeout_r_{k}), .i_irq1(ureq_r_{k}[0]), .i_irq2(ureq_r_{k}[1]), .i_fs_req(ureq_r_{k}[2])"
        );
        match kind {
            Kind::Sensor | Kind::Actuator => {
                let (act, sens) = if kind == Kind::Actuator {
                    (1, "16'd0".to_string())
                } else {
                    (0, format!("sens_r_{k}"))
                };
                w(
                    &mut v,
                    &format!(
                        "    wire [15:0] act_{k};\n    /* verilator lint_off UNUSEDSIGNAL */\n    // A slave's master-side outputs are not used in a ring.\n\
                         \x20   wire [11:0] u_fslot_{k}, u_slot_{k};\n    wire [15:0] u_data_{k};\n    wire [1:0] u_kind_{k};\n    wire u_regen_{k}, u_wvalid_{k}, u_alive_{k}, u_alarm_{k}, u_ok_{k}, u_hdr_bad_{k};\n    /* verilator lint_on UNUSEDSIGNAL */\n\
                         \x20   merkur_slave n{k}({common}, .i_actuator(1'b{act}), .i_sensor_data({sens}),\n\
                         \x20       .i_master(1'b0), .i_slot_cfg(2'd0), .i_slot_data(16'd0), .i_slot_alive(1'b0), .i_fs_set(1'b0),\n\
                         \x20       .o_fwd_slot(u_fslot_{k}), .o_regen(u_regen_{k}), .o_wvalid(u_wvalid_{k}), .o_kind(u_kind_{k}), .o_slot(u_slot_{k}), .o_data(u_data_{k}),\n\
                         \x20       .o_alive(u_alive_{k}), .o_alarm(u_alarm_{k}), .o_ok(u_ok_{k}), .o_hdr_bad(u_hdr_bad_{k}),\n\
                         \x20       .o_act_data(act_{k}), .o_mode(mode_{k}), .o_failsafe(fs_{k}), .o_perr(perr_{k}), .o_ferr(ferr_{k}));\n\
                         \x20   wire [15:0] aerr_{k} = 16'd0;\n    wire [15:0] serr_{k} = 16'd0;\n    wire [11:0] hop_{k} = 12'd0;\n    wire [15:0] cycles_{k} = 16'd0;\n    wire run_{k} = 1'b1;\n    wire irq1_{k} = 1'b0, irq2_{k} = 1'b0, irqfs_{k} = 1'b0, irqrc_{k} = 1'b0, irqfsc_{k} = 1'b0;"
                    ),
                );
            }
            Kind::Master | Kind::SpecialMaster => {
                let (defs, extra) = if kind == Kind::SpecialMaster {
                    (
                        format!("    wire [15:0] serr_{k};\n    wire [11:0] hop_{k};\n    wire [15:0] cycles_{k};"),
                        format!(".i_period(period_r_{k}), .o_serr(serr_{k}), .o_hop(hop_{k}), .o_cycles(cycles_{k}),"),
                    )
                } else {
                    (
                        format!("    wire [15:0] serr_{k} = 16'd0;\n    wire [11:0] hop_{k} = 12'd0;\n    wire [15:0] cycles_{k} = 16'd0;"),
                        String::new(),
                    )
                };
                w(
                    &mut v,
                    &format!(
                        "{defs}\n    wire [15:0] aerr_{k};\n    wire [15:0] act_{k} = 16'd0;\n    wire run_{k};\n    wire irq1_{k}, irq2_{k}, irqfs_{k}, irqrc_{k}, irqfsc_{k};\n    /* verilator lint_off UNUSEDSIGNAL */\n    wire alarmq_{k}; // the queue's level interrupt: the driver reads the queue over Wishbone\n    /* verilator lint_on UNUSEDSIGNAL */\n    wire [15:0] wbdat_{k};\n    wire wback_{k};\n\
                         \x20   wire wbsel_{k} = i_wb_node == 16'd{k};\n\
                         \x20   {m} n{k}({common}, {extra}\n\
                         \x20       .i_wb_cyc(i_wb_cyc & wbsel_{k}), .i_wb_stb(i_wb_stb & wbsel_{k}), .i_wb_we(i_wb_we), .i_wb_adr(i_wb_adr), .i_wb_dat(i_wb_dat),\n\
                         \x20       .o_wb_dat(wbdat_{k}), .o_wb_ack(wback_{k}), .o_irq1(irq1_{k}), .o_irq2(irq2_{k}), .o_irq_fs(irqfs_{k}), .o_irq_rc(irqrc_{k}), .o_alarmq(alarmq_{k}), .o_irq_fsc(irqfsc_{k}),\n\
                         \x20       .o_mode(mode_{k}), .o_failsafe(fs_{k}), .o_perr(perr_{k}), .o_ferr(ferr_{k}), .o_aerr(aerr_{k}), .o_running(run_{k}));",
                        m = module_name(kind)
                    ),
                );
            }
        }
        w(
            &mut v,
            &format!(
                "    reg [15:0] nirq1_{k} = 16'd0, nirq2_{k} = 16'd0, nirqfs_{k} = 16'd0, nirqrc_{k} = 16'd0, nirqfsc_{k} = 16'd0;\n\
                 \x20   always @(posedge nclk_{k}) begin\n        if (irq1_{k}) nirq1_{k} <= nirq1_{k} + 16'd1;\n        if (irq2_{k}) nirq2_{k} <= nirq2_{k} + 16'd1;\n        if (irqfs_{k}) nirqfs_{k} <= nirqfs_{k} + 16'd1;\n        if (irqrc_{k}) nirqrc_{k} <= nirqrc_{k} + 16'd1;\n        if (irqfsc_{k}) nirqfsc_{k} <= nirqfsc_{k} + 16'd1;\n    end"
            ),
        );
    }
    // Capture entries carry the special master's frame count when written
    // (its low 8 bits), so that an entry left from 8 cycles before (CYC has
    // 3 bits) is not read as this cycle's.
    let sm = kinds
        .iter()
        .position(|&k| k == Kind::SpecialMaster)
        .expect("a ring has a special master");
    w(&mut v, &format!("    wire [7:0] epoch = cycles_{sm}[7:0];"));
    // Fibres: line levels, fault points, monitors, capture.
    for f in 0..nf {
        let (src, port, name) = if f < n {
            (f, "po", format!("P{f}"))
        } else {
            ((f - n + 1) % n, "so", format!("S{}", f - n))
        };
        w(
            &mut v,
            &format!(
                "    // ---- fibre {name} (from node {src}) ----\n\
                 \x20   reg line_{f} = 1'b0, brk_{f} = 1'b0;\n    reg [2:0] sh_{f} = 3'd0;\n\
                 \x20   wire txl_{f} = (fired_{src} | fired2_{src}) ? {port}_{src}[0] : {port}_{src}[1];\n\
                 \x20   // Flip point. The sender's bit grid from its line (a boundary at every edge, else 4 DDR halves after the last;\n\
                 \x20   // a 5-half bit shows as an edge one half after a boundary without one, so such a boundary is confirmed a half\n\
                 \x20   // later), code 1s in a row, and the armed flip: J found (its first 0 code bit after 5 or more 1s), count to line\n\
                 \x20   // bit fl_tgt, invert from that boundary to the next. The line is the sender's delayed by 4 ticks, so a flip\n\
                 \x20   // decided a half late still starts on time.\n\
                 \x20   reg hp_{f} = 1'b0, pend_{f} = 1'b0, fl_arm_{f} = 1'b0, fl_run_{f} = 1'b0, fl_open_{f} = 1'b0, trk_{f} = 1'b0;\n\
                 \x20   reg [2:0] hc_{f} = 3'd0, ones_{f} = 3'd0;\n    reg [3:0] txd_{f} = 4'd0;\n    reg [11:0] fl_tgt_{f} = 12'd0, fl_cnt_{f} = 12'd0;\n\
                 \x20   reg [31:0] tc_{f} = 32'd0, fl_is_{f} = 32'hffffffff, fl_ie_{f} = 32'hffffffff;\n\
                 \x20   wire edge_{f} = txl_{f} != hp_{f};\n    wire [2:0] hn_{f} = hc_{f} + 3'd1;\n\
                 \x20   wire b1_{f} = hs_{src} & edge_{f};\n    wire b0_{f} = hs_{src} & !edge_{f} & pend_{f};\n\
                 \x20   wire bev_{f} = b1_{f} | b0_{f};\n    wire [31:0] bt_{f} = b1_{f} ? tick : tc_{f};\n\
                 \x20   wire jdet_{f} = b0_{f} & (ones_{f} >= 3'd5) & fl_arm_{f};\n\
                 \x20   wire hit_{f} = (jdet_{f} & fl_tgt_{f} == 12'd2) | (bev_{f} & fl_run_{f} & fl_cnt_{f} == 12'd1);\n\
                 \x20   wire [31:0] tickd_{f} = tick - 32'd4;\n\
                 \x20   // Burst: bits left, the configured length and pattern, the generator (merkur_model::line::garbage), the level mask\n\
                 \x20   // in force (bu_m from tick bu_t, bu_pm before), and the return of the level after the last bit.\n\
                 \x20   reg [11:0] bu_len_{f} = 12'd0, bu_cfg_{f} = 12'd0;\n    reg [15:0] bu_s_{f} = 16'd0;\n    reg [1:0] bu_z_{f} = 2'd0;\n    reg [3:0] bu_o_{f} = 4'd0;\n\
                 \x20   reg bu_m_{f} = 1'b0, bu_pm_{f} = 1'b0, bu_ret_{f} = 1'b0;\n    reg [31:0] bu_t_{f} = 32'hffffffff;\n\
                 \x20   wire bu_start_{f} = hit_{f} & (bu_cfg_{f} != 12'd0);\n    wire bu_bit_{f} = bev_{f} & (bu_start_{f} | (bu_len_{f} != 12'd0));\n\
                 \x20   wire bu_gr_{f} = (bu_z_{f} == 2'd2) ? 1'b1 : ((bu_o_{f} == 4'd9) ? 1'b0 : bu_s_{f}[0]);\n\
                 \x20   wire bu_g_{f} = (bu_start_{f} | (bu_len_{f} == 12'd1)) ? 1'b1 : bu_gr_{f};\n\
                 \x20   wire [15:0] bu_sn_{f} = bu_s_{f}[0] ? ({{1'b0, bu_s_{f}[15:1]}} ^ 16'hb400) : {{1'b0, bu_s_{f}[15:1]}};\n\
                 \x20   wire inv_{f} = trk_{f} & (((tickd_{f} >= fl_is_{f}) & (tickd_{f} < fl_ie_{f})) ^ ((tickd_{f} >= bu_t_{f}) ? bu_m_{f} : bu_pm_{f}));\n\
                 \x20   always @(posedge clk) begin\n        txd_{f} <= {{txd_{f}[2:0], txl_{f}}};\n\
                 \x20       line_{f} <= (brk_{f} | dead_{src}) ? 1'b0 : (txd_{f}[3] ^ inv_{f});\n        sh_{f} <= {{line_{f}, sh_{f}[2:1]}};\n\
                 \x20       if (trk_{f} & hs_{src}) begin\n            hp_{f} <= txl_{f};\n\
                 \x20           if (edge_{f}) begin\n                hc_{f} <= 3'd0;\n                pend_{f} <= 1'b0;\n            end else if (pend_{f}) begin\n                hc_{f} <= 3'd1;\n                pend_{f} <= 1'b0;\n\
                 \x20           end else begin\n                hc_{f} <= hn_{f};\n                if (hn_{f} == 3'd4) begin\n                    pend_{f} <= 1'b1;\n                    tc_{f} <= tick;\n                end\n            end\n        end\n\
                 \x20       if (trk_{f} & bev_{f}) begin\n            ones_{f} <= b0_{f} ? 3'd0 : (ones_{f} == 3'd7 ? 3'd7 : ones_{f} + 3'd1);\n\
                 \x20           if (jdet_{f}) begin\n                fl_arm_{f} <= 1'b0;\n                fl_run_{f} <= fl_tgt_{f} > 12'd2;\n                fl_cnt_{f} <= fl_tgt_{f} - 12'd2;\n\
                 \x20           end else if (fl_run_{f}) begin\n                fl_cnt_{f} <= fl_cnt_{f} - 12'd1;\n                if (fl_cnt_{f} == 12'd1) fl_run_{f} <= 1'b0;\n            end\n\
                 \x20           if (hit_{f} & (bu_cfg_{f} == 12'd0)) begin\n                fl_is_{f} <= bt_{f};\n                fl_ie_{f} <= 32'hffffffff;\n                fl_open_{f} <= 1'b1;\n            end else if (fl_open_{f}) begin\n                fl_ie_{f} <= bt_{f};\n                fl_open_{f} <= 1'b0;\n            end\n\
                 \x20           if (bu_bit_{f}) begin\n                // A garbage bit from this boundary: the mask makes the line's code bit the garbage's.\n\
                 \x20               bu_pm_{f} <= bu_m_{f};\n                bu_m_{f} <= (bu_start_{f} ? 1'b0 : bu_m_{f}) ^ b1_{f} ^ bu_g_{f};\n                bu_t_{f} <= bt_{f};\n                bu_s_{f} <= bu_sn_{f};\n\
                 \x20               bu_z_{f} <= bu_g_{f} ? 2'd0 : bu_z_{f} + 2'd1;\n                bu_o_{f} <= bu_g_{f} ? bu_o_{f} + 4'd1 : 4'd0;\n\
                 \x20               bu_len_{f} <= (bu_start_{f} ? bu_cfg_{f} : bu_len_{f}) - 12'd1;\n                bu_ret_{f} <= (bu_start_{f} ? bu_cfg_{f} : bu_len_{f}) == 12'd1;\n\
                 \x20               if (bu_start_{f}) begin\n                    bu_z_{f} <= 2'd0;\n                    bu_o_{f} <= 4'd1;\n                    bu_cfg_{f} <= 12'd0;\n                end\n\
                 \x20           end else if (bu_ret_{f}) begin\n                // After the last garbage bit the level is the sender's again.\n\
                 \x20               bu_pm_{f} <= bu_m_{f};\n                bu_m_{f} <= 1'b0;\n                bu_t_{f} <= bt_{f};\n                bu_ret_{f} <= 1'b0;\n            end\n        end\n\
                 \x20       // The fault point works only while a flip or burst is armed or running (trk); arming it starts the bit grid\n\
                 \x20       // afresh from the line's level (an armed packet is always after an idle gap: edges every bit, ones enough).\n\
                 \x20       trk_{f} <= trk_{f} & (fl_arm_{f} | fl_run_{f} | fl_open_{f} | (bu_len_{f} != 12'd0) | bu_ret_{f} | bu_m_{f} | (tickd_{f} < fl_ie_{f}) | (tickd_{f} < bu_t_{f}));\n\
                 \x20       if (i_cfg_we && i_cfg_sel == 16'd{f} && i_cfg_field == 8'd{c_brk}) brk_{f} <= i_cfg_val[0];\n\
                 \x20       if (i_cfg_we && i_cfg_sel == 16'd{f} && i_cfg_field == 8'd{c_flip}) begin\n            fl_arm_{f} <= 1'b1;\n            fl_run_{f} <= 1'b0;\n            fl_tgt_{f} <= i_cfg_val[11:0];\n\
                 \x20           trk_{f} <= 1'b1;\n            hp_{f} <= txl_{f};\n            hc_{f} <= 3'd0;\n            pend_{f} <= 1'b0;\n            ones_{f} <= 3'd0;\n\
                 \x20           bu_cfg_{f} <= i_cfg_val[23:12];\n            bu_s_{f} <= {{i_cfg_val[31:24], 8'ha5}};\n        end\n    end\n\
                 \x20   wire m_los_{f}, m_wvalid_{f}, m_alive_{f}, m_alarm_{f}, m_ok_{f}, m_void_{f}, m_marked_{f};\n    wire [1:0] m_kind_{f}, m_ptype_{f};\n    wire [11:0] m_slot_{f};\n    wire [15:0] m_data_{f};\n\
                 \x20   /* verilator lint_off UNUSEDSIGNAL */\n    // Monitor outputs the capture does not need.\n    wire m_bvalid_{f}, m_level_{f}, m_start_{f}, m_inpkt_{f}, m_own_{f}, m_hdrbad_{f}, m_compl_{f};\n    wire [3:0] m_reason_{f};\n    wire [1:0] m_phase_{f};\n    /* verilator lint_on UNUSEDSIGNAL */\n\
                 \x20   merkur_monitor mon_{f}(.clock(mclk), .i_samples({{line_{f}, sh_{f}}}), .i_slots_m1(slots_m1), .i_address(12'hfff), .i_flush(1'b0),\n\
                 \x20       .o_los(m_los_{f}), .o_bvalid(m_bvalid_{f}), .o_level(m_level_{f}), .o_phase(m_phase_{f}), .o_start(m_start_{f}), .o_inpkt(m_inpkt_{f}),\n\
                 \x20       .o_wvalid(m_wvalid_{f}), .o_kind(m_kind_{f}), .o_slot(m_slot_{f}), .o_data(m_data_{f}), .o_alive(m_alive_{f}), .o_alarm(m_alarm_{f}),\n\
                 \x20       .o_reason(m_reason_{f}), .o_ok(m_ok_{f}), .o_compl(m_compl_{f}), .o_void(m_void_{f}), .o_marked(m_marked_{f}), .o_own(m_own_{f}), .o_hdr_bad(m_hdrbad_{f}), .o_ptype(m_ptype_{f}));\n\
                 \x20   reg [30:0] cap_{f} [0:{last}];\n    integer ci_{f};\n    initial for (ci_{f} = 0; ci_{f} <= {last}; ci_{f} = ci_{f} + 1) cap_{f}[ci_{f}] = 31'd0;\n    reg [31:0] th1_{f} = 32'd0;\n    reg [11:0] lslot_{f} = 12'hfff;\n    reg [15:0] h0_{f} = 16'd0, h1_{f} = 16'd0, nsec_{f} = 16'd0, ntst_{f} = 16'd0, nend_{f} = 16'd0;\n    reg infr_{f} = 1'b0;\n\
                 \x20   wire [1:0] mstat_{f} = m_ok_{f} ? 2'd1 : (m_void_{f} ? 2'd3 : 2'd2);\n\
                 \x20   // A bad word's ALARM field in the capture says whether it was marked (protocol §4).\n\
                 \x20   wire mflag_{f} = (m_ok_{f} | m_void_{f}) ? m_alarm_{f} : m_marked_{f};\n\
                 \x20   always @(posedge mclk) begin\n        hdr_new_{f} <= 1'b0;\n\
                 \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd0 && m_ok_{f}) h0_{f} <= m_data_{f};\n\
                 \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd0) begin\n\
                 \x20           h1_{f} <= m_data_{f};\n            th1_{f} <= tick;\n            lslot_{f} <= 12'hfff;\n            hdr_cyc_{f} <= m_data_{f}[14:12];\n            infr_{f} <= 1'b1;\n\
                 \x20           cap_{f}[{{1'b1, {hz}m_data_{f}[13:12], 1'b0}}] <= {{epoch, m_data_{f}[14:12], 2'd1, 2'd0, h0_{f}}};\n\
                 \x20           cap_{f}[{{1'b1, {hz}m_data_{f}[13:12], 1'b1}}] <= {{epoch, m_data_{f}[14:12], 2'd1, 2'd0, m_data_{f}}};\n        end\n\
                 \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd1) nsec_{f} <= nsec_{f} + 16'd1;\n\
                 \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd2) ntst_{f} <= ntst_{f} + 16'd1;\n\
                 \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd2) begin\n            lslot_{f} <= m_slot_{f};\n\
                 \x20           cap_{f}[{{1'b0, hdr_cyc_{f}[1:0], m_slot_{f}[{cb}:0]}}] <= {{epoch, hdr_cyc_{f}, mstat_{f}, mflag_{f}, m_alive_{f}, m_data_{f}}};\n\
                 \x20           if (m_slot_{f} == slots_m1) begin\n                infr_{f} <= 1'b0;\n                hdr_new_{f} <= 1'b1;\n                nend_{f} <= nend_{f} + 16'd1;\n            end\n        end\n    end",
                c_brk = cfg::BREAK,
                c_flip = cfg::FLIP,
                hz = if capw > 4 { format!("{}'d0, ", capw - 4) } else { String::new() },
                last = 8 * cap - 1,
                cb = capw - 4,
            ),
        );
    }
    // Status read: every field by name (`status`), `K` = node or fibre.
    let node_fields: [(u32, &str); 15] = [
        (status::MODE, "{30'd0, mode_K}"),
        (status::FS, "{31'd0, fs_K}"),
        (status::PERR, "{16'd0, perr_K}"),
        (status::FERR, "{16'd0, ferr_K}"),
        (status::AERR, "{16'd0, aerr_K}"),
        (status::SERR, "{16'd0, serr_K}"),
        (status::HOP, "{20'd0, hop_K}"),
        (status::ACT, "{16'd0, act_K}"),
        (status::CYCLES, "{16'd0, cycles_K}"),
        (status::IRQ1, "{16'd0, nirq1_K}"),
        (status::IRQ2, "{16'd0, nirq2_K}"),
        (status::IRQFS, "{16'd0, nirqfs_K}"),
        (status::IRQFSC, "{16'd0, nirqfsc_K}"),
        (status::IRQRC, "{16'd0, nirqrc_K}"),
        (status::RUN, "{31'd0, run_K}"),
    ];
    let fibre_fields: [(u32, &str); 9] = [
        (status::AT, "{infr_K, hdr_cyc_K, 16'd0, lslot_K}"),
        (status::TH1, "th1_K"),
        (status::FRAME, "{28'd0, infr_K, hdr_cyc_K}"),
        (status::H1, "{16'd0, h1_K}"),
        (status::H0, "{16'd0, h0_K}"),
        (status::NSEC, "{16'd0, nsec_K}"),
        (status::NTST, "{16'd0, ntst_K}"),
        (status::LOS, "{31'd0, m_los_K}"),
        (status::NEND, "{16'd0, nend_K}"),
    ];
    w(
        &mut v,
        "    // The read multiplexers work only while the harness reads (i_rd_en, i_cap_en): a simulator evaluates\n\
         \x20   // them whenever a status register changes, i.e. at every tick, and they have a case per node and fibre field.\n\
         \x20   always @(*) begin\n        o_rd = 32'd0;\n        if (i_rd_en) case ({i_rd_sel, i_rd_field})",
    );
    for (count, fields) in [(n, &node_fields[..]), (nf, &fibre_fields[..])] {
        for i in 0..count {
            for (field, expr) in fields {
                let expr = expr.replace('K', &i.to_string());
                w(
                    &mut v,
                    &format!("            {{16'd{i}, 8'd{field}}}: o_rd = {expr};"),
                );
            }
        }
    }
    w(
        &mut v,
        "            default: o_rd = 32'd0;\n        endcase\n    end",
    );
    // Capture read.
    w(
        &mut v,
        "    always @(*) begin\n        o_cap = 32'd0;\n        if (i_cap_en) case (i_cap_fibre)",
    );
    for f in 0..nf {
        w(
            &mut v,
            &format!("            16'd{f}: o_cap = {{1'b0, cap_{f}[i_cap_idx]}};"),
        );
    }
    w(
        &mut v,
        "            default: o_cap = 32'd0;\n        endcase\n    end",
    );
    // Wishbone answer.
    w(
        &mut v,
        "    always @(*) begin\n        o_wb_dat = 16'd0;\n        o_wb_ack = 1'b0;",
    );
    for (k, &kind) in kinds.iter().enumerate() {
        if kind.is_master() {
            w(
                &mut v,
                &format!("        if (i_wb_node == 16'd{k}) begin\n            o_wb_dat = wbdat_{k};\n            o_wb_ack = wback_{k};\n        end"),
            );
        }
    }
    w(&mut v, "    end");
    // Global configuration.
    w(
        &mut v,
        &format!(
            "    always @(posedge clk) begin\n        if (i_cfg_we && i_cfg_field == 8'd{}) slots_m1 <= i_cfg_val[11:0];\n\
             \x20       if (i_cfg_we && i_cfg_field == 8'd{}) cs_timeout <= i_cfg_val[19:0];\n\
             \x20       if (i_cfg_we && i_cfg_field == 8'd{}) period <= i_cfg_val[19:0];\n    end\nendmodule",
            cfg::SLOTS_M1,
            cfg::CS_TIMEOUT,
            cfg::PERIOD
        ),
    );
    v
}
