//! # ring_top — a whole ring for simulation: nodes, fibres, fault points, monitors
//!
//! Purpose: `merkur verilog` and `merkur sim` wire N nodes (the scenario's
//! kinds in ring order) over duplex fibres into one Verilog top,
//! `merkur_ring`. It is a **simulation harness** around the product blocks
//! ([`crate::node::slave`], [`crate::node::master`], [`crate::node::special_master`],
//! [`crate::line::monitor`]), written as Verilog text because its shape (N
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
//! gate exists only here. The clock, the node's registered inputs and the
//! counters of its interrupt pulses are one module per node,
//! `merkur_node_env` (`NODE_ENV_MODULE` below).
//!
//! **Fibres.** Fibre P*k* (node k PO → node k+1 PI) and S*k* (node k+1 SO →
//! node k SI) are line levels at tick resolution: the sender's DDR pair
//! shows bit 0 in the 2 ticks after its clock edge and bit 1 until its next
//! edge; the receiver's 4 samples are the line in the last 4 ticks (oldest
//! in bit 0), taken into a register at the receiver's clock edge, as the
//! capture register of every synthesis top (`merkur_ddr_in`'s `q`) takes
//! them (for a slave or a master choosing PI or SI as INPUT by the node's
//! `o_cap_si`, as that register does): the node's logic reads them in
//! the clock after. Everything else
//! the top gives a node (address, slot count, CS timeout, period, sensor
//! value, user requests, a special master's backup priority and election
//! time, a master's Wishbone) goes through a register on the node's clock
//! too, as in silicon, where they are constants or synchronised. Besides being
//! the silicon's timing, this keeps every input of a node still between
//! its own clock edges, so Verilator evaluates a node's logic at its edges
//! only, not at every tick (issue 24: ring100 1.7× faster,
//! docs/benchmarks.md). **Sub-tick time.** The gated clock puts a node's
//! edges on ticks, an oscillator does not: a clock period of 3 or 5 ticks
//! (how the accumulator makes the offset) moves an edge by up to a tick =
//! one receive sample, at the sender's line and at the receiver's samples,
//! two samples on one edge interval, where a link has one sample of margin
//! for a retimer's short bit (protocol §9, [`crate::line::cdr`]): a fault-free
//! 100-node ring lost frames at some offsets. So each half on the line
//! carries its clock edge's time before the tick in eighths of a tick (the
//! accumulator's excess after its carry), the fibre delays it with the
//! level, and a receiver's sample in a tick where the line changed shows the
//! new level only when the sender's half started no later than its own
//! edge's time: a link sees its two oscillators' edge intervals to a
//! quarter of a sample. Each
//! fibre has a **fault point** (break: the line goes dark, as when its
//! sender dies; flip: one line bit of the next packet is inverted, on the
//! sender's own bit grid — the harness finds it from the line's edges, a
//! boundary every 4 DDR halves between them — so the receiver sees exactly
//! the single line-bit error the model applies; burst: from such a bit on,
//! the line carries the model's garbage for a number of bits, made by the
//! same generator, the level inverted where the garbage's code bit differs
//! from the sender's; the line and its fault point are one module per fibre,
//! `merkur_fibre` (`FIBRE_MODULE` below), so that a simulator runs one copy of
//! their code for every fibre) and a **monitor** (clock recovery,
//! framer, word decoder at the nominal rate) whose DATA words are captured
//! per cycle: entry `(cyc & 3) · CAP + slot` holds `{EPOCH[7:0], CYC[2:0],
//! status[1:0], ALARM, ALIVE, data[15:0]}` with status 1 good, 2 bad, 3
//! VOID and EPOCH the ring's frame count (low 8 bits; frames sent by the special master and the backups) when it was
//! written; a slot whose entry has another CYC, or an EPOCH that is not
//! 0…4 frames after the cycle's (left from 8 cycles before), was missing
//! in that cycle; entries
//! `4 · CAP + 2 (cyc & 3) + {0, 1}` hold the frame's H0 and H1.
//!
//! **Ports.**
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clk` | in | 1 | simulation tick (8 per nominal bit time) |
//! | `i_cfg_we`, `i_cfg_sel`, `i_cfg_field`, `i_cfg_val` | in | 1, 16, 8, 32 | configuration write (table below) |
//! | `i_rd_en`, `i_rd_sel`, `i_rd_field` | in | 1, 16, 8 | status read enable and address |
//! | `o_rd` | out | 32 | status read data (combinational; 0 while `i_rd_en` is low) |
//! | `i_cap_en`, `i_cap_fibre`, `i_cap_idx` | in | 1, 16, log2(4·CAP) | capture read enable and address (fibre P0.. then S0..) |
//! | `o_cap` | out | 32 | captured entry (combinational; 0 while `i_cap_en` is low) |
//! | `i_wb_node`, `i_wb_cyc`, `i_wb_stb`, `i_wb_we`, `i_wb_adr`, `i_wb_dat` | in | | Wishbone of master `i_wb_node`, registered on that node's clock (a transfer takes one node clock more than the block's own) |
//! | `o_wb_dat`, `o_wb_ack` | out | 16, 1 | its Wishbone answer |
//!
//! Configuration fields ([`cfg`](mod@cfg); `i_cfg_sel` = node or fibre index; global
//! fields ignore it) and status fields ([`status`]; `i_rd_sel` = node or
//! fibre index, or for the packed fields a group of them: the driver polls
//! every node's mode and every fibre's frame state, and each read costs
//! the simulator a whole evaluation pass) are named in this file and used
//! by name by the driver (`sim/src/ring_sim.rs`). A user
//! request is raised at once (`now`) or when the node's pacing monitor (its
//! PI fibre; the special master's PO) sees the end of the DATA frame with
//! the request's CYC, i.e. before the next frame; a sensor sees the value
//! of the frame whose H1 its PI fibre showed last (its slot comes after).

use crate::emit::verilog::{block_verilog, mem_depth, rename_top, size_memories};
use crate::line::retime::Layout;
use crate::line::word_rx::WordFormat;
use merkur_model::scenario::Kind;

/// Ticks of the simulation clock per nominal bit time (one tick per
/// receive sample, [`crate::line::cdr::SAMPLES_PER_BIT`]).
pub const TICKS_PER_BIT: u32 = crate::line::cdr::SAMPLES_PER_BIT as u32;

/// A node's clock increment per tick at 0 ppm: its clock (2 per bit time)
/// is a quarter of the tick rate on a 32-bit accumulator.
pub const INC_NOMINAL: u64 = 1 << 30;

/// Configuration fields of `merkur_ring` (`i_cfg_field`).
pub mod cfg {
    /// Node: clock increment per tick ([`INC_NOMINAL`](super::INC_NOMINAL) at 0 ppm).
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
    /// Node: 1 holds the node in its power-on reset (a restart, protocol
    /// §12; only a ring top built with restarts,
    /// [`super::ring_verilog_with`], connects it), 0 releases it.
    pub const POR: u32 = 11;
    /// Clock-base node (`merkur_special_master`): backup priority (0: the
    /// clock base from power-up; protocol §8).
    pub const PRIO: u32 = 5;
    /// Clock-base node: election time in bit times ((1.5 + priority)
    /// periods, protocol §8).
    pub const ELECT: u32 = 6;
    /// Fibre: arm a flip of line bit `val[11:0]` of the next packet (bit 0 =
    /// the first bit of its J K; counted from J's first 0 code bit, so
    /// bits 0 and 1 cannot be hit and are refused by the driver); with
    /// `val[23:12]` ≠ 0, a burst of that many bits of garbage from there
    /// (`merkur_model::line::garbage` of the pattern `val[31:24]`).
    pub const FLIP: u32 = 9;
    /// Clock-base node: bit times after the period tick at which a
    /// retransmission packet goes (protocol §8), `val[19:0]` in the
    /// healthy ring; [`RTX_ATW`] in a wrapped one.
    pub const RTX_AT: u32 = 12;
    /// Clock-base node: as [`RTX_AT`], in a ring it knows wrapped.
    pub const RTX_ATW: u32 = 13;
    /// Clock-base node: requests that fit, `val[4:0]` healthy and
    /// `val[9:5]` wrapped (0: none is sent).
    pub const RTX_K: u32 = 14;
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
    /// Clock-base node (special master, backup): frames it sent while
    /// alive (a dead node's logic runs on, unheard).
    pub const FRAMES: u32 = 15;
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
    /// Nodes `MODES_PER_READ·sel …`: `{failsafe, mode[1:0]}` of each in 3
    /// bits, the first node lowest (one read for many nodes: each read
    /// costs the simulator a whole evaluation pass).
    pub const MODES: u32 = 25;
    /// Fibres `FRAMES_PER_READ·sel …`: the [`FRAME`] field of each in 4
    /// bits, the first fibre lowest.
    pub const FRAME_V: u32 = 26;
    /// `sel` 0: the [`FRAMES`] of every clock-base node (the special
    /// masters), summed.
    pub const FRAMES_ALL: u32 = 27;
    /// Nodes per [`MODES`] read.
    pub const MODES_PER_READ: usize = 10;
    /// Fibres per [`FRAME_V`] read.
    pub const FRAMES_PER_READ: usize = 8;
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
/// ring of `slots` slots of words in `format`: the memories are
/// [`mem_depth`]`(slots)` deep ([`size_memories`]). Simulation and
/// synthesis both use this text.
pub fn node_verilog(kind: Kind, slots: usize, format: WordFormat) -> String {
    node_verilog_with(kind, slots, format, true, Layout::SendShifts)
}

/// [`node_verilog`], with the node built without retransmission on demand
/// when `rtx` is false ([`crate::node::slave::Slave::with_rtx`] and the
/// masters' `with_rtx`: for a ring without critical slots), and a slave's
/// or a master's retime buffers in `layout` (the same behaviour,
/// [`crate::node::slave::Slave::with_layout`]; the special master keeps
/// [`Layout::SendShifts`]).
pub fn node_verilog_with(
    kind: Kind,
    slots: usize,
    format: WordFormat,
    rtx: bool,
    layout: Layout,
) -> String {
    let v = match kind {
        Kind::Sensor | Kind::Actuator => {
            block_verilog(crate::node::slave::Slave::with_rtx(format, rtx).with_layout(layout))
        }
        Kind::Master => {
            block_verilog(crate::node::master::Master::with_rtx(format, rtx).with_layout(layout))
        }
        Kind::SpecialMaster => block_verilog(crate::node::special_master::SpecialMaster::with_rtx(
            format, rtx,
        )),
    };
    rename_top(&size_memories(&v, mem_depth(slots)), module_name(kind))
}

/// Capture entries per cycle buffer: slots rounded up to a power of two.
pub fn cap_slots(slots: usize) -> usize {
    slots.next_power_of_two().max(2)
}

/// The fibre module of the ring top (`@BREAK@` and `@FLIP@` stand for the
/// configuration fields [`cfg::BREAK`] and [`cfg::FLIP`]).
const FIBRE_MODULE: &str = r#"// ---- merkur_fibre: one fibre of the simulated ring (rtl/src/harness/ring_top.rs) ----
// The line from a sender's output to a receiver's input, 4 ticks long, with
// the fault point of the ring top's module doc: break (the line dark while
// field BREAK is 1, or while the sender is dead), flip and burst (field
// FLIP: armed for the next packet, on the sender's own bit grid). One module
// for every fibre, so that a simulator runs one copy of its code for all of
// them (docs/benchmarks.md, issue 24).
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clk` | in | 1 | simulation tick |
// | `i_tick` | in | 32 | ticks since the start |
// | `i_txl` | in | 1 | the sender's line level this tick (the half of its DDR output pair on the line) |
// | `i_hs` | in | 1 | a new half of the sender's DDR pair starts this tick |
// | `i_hfrac` | in | 3 | that half's sub-tick time (`merkur_node_env`'s `o_hfrac`) |
// | `i_dead` | in | 1 | the sender is dead: the line is dark |
// | `i_index` | in | 16 | the fibre's index (P0.. then S0..; constant) |
// | `i_cfg_we`, `i_cfg_sel`, `i_cfg_field`, `i_cfg_val` | in | 1, 16, 8, 32 | the ring top's configuration write; this fibre's when `i_cfg_sel` = `i_index` (fields BREAK, FLIP) |
// | `o_line` | out | 1 | the line level at the receiver: the sender's 4 ticks before, faults applied |
// | `o_sh` | out | 3 | the three line levels before `o_line`, newest first |
// | `o_old` | out | 1 | the line level before those |
// | `o_fr` | out | 12 | the sender's sub-tick time in the ticks of `{o_line, o_sh}` (3 bits each, in that order) |
module merkur_fibre(clk, i_tick, i_txl, i_hs, i_hfrac, i_dead, i_index, i_cfg_we, i_cfg_sel, i_cfg_field, i_cfg_val,
    o_line, o_sh, o_old, o_fr);
    input wire clk;
    input wire [31:0] i_tick;
    input wire i_txl;
    input wire i_hs;
    input wire [2:0] i_hfrac;
    input wire i_dead;
    input wire [15:0] i_index;
    input wire i_cfg_we;
    input wire [15:0] i_cfg_sel;
    input wire [7:0] i_cfg_field;
    input wire [31:0] i_cfg_val;
    output o_line;
    output [2:0] o_sh;
    output o_old;
    output [11:0] o_fr;
    reg o_line = 1'b0;
    reg [2:0] o_sh = 3'd0;
    reg o_old = 1'b0;
    reg [11:0] o_fr = 12'd0;
    // The sender's sub-tick time, delayed with its level (a change of the level is a half's start; the dark line of
    // a break or a death starts at a tick the harness chose and takes the time that is there: it has none).
    reg [11:0] frd = 12'd0;
    reg brk = 1'b0;
    // Flip point. The sender's bit grid from its line (a boundary at every edge, else 4 DDR halves after the last;
    // a 5-half bit shows as an edge one half after a boundary without one, so such a boundary is confirmed a half
    // later), code 1s in a row, and the armed flip: J found (its first 0 code bit after 5 or more 1s), count to line
    // bit fl_tgt, invert from that boundary to the next. The line is the sender's delayed by 4 ticks, so a flip
    // decided a half late still starts on time.
    reg hp = 1'b0, pend = 1'b0, fl_arm = 1'b0, fl_run = 1'b0, fl_open = 1'b0, trk = 1'b0;
    reg [2:0] hc = 3'd0, ones = 3'd0;
    reg [3:0] txd = 4'd0;
    reg [11:0] fl_tgt = 12'd0, fl_cnt = 12'd0;
    reg [31:0] tc = 32'd0, fl_is = 32'hffffffff, fl_ie = 32'hffffffff;
    // Burst: bits left, the configured length and pattern, the generator (merkur_model::line::garbage), the level mask
    // in force (bu_m from tick bu_t, bu_pm before), and the return of the level after the last bit.
    reg [11:0] bu_len = 12'd0, bu_cfg = 12'd0;
    reg [15:0] bu_s = 16'd0;
    reg [1:0] bu_z = 2'd0;
    reg [3:0] bu_o = 4'd0;
    reg bu_m = 1'b0, bu_pm = 1'b0, bu_ret = 1'b0;
    reg [31:0] bu_t = 32'hffffffff;
    always @(posedge clk) begin : tick_step
        // The fault point's values at this tick, worked out only while it works (trk): as wires, a simulator would
        // compute them at every tick on every fibre (5 % of ring100's time, docs/benchmarks.md).
        reg lvl_edge, b1, b0, bev, jdet, hit, bu_start, bu_bit, bu_g, inv;
        reg [2:0] hn;
        reg [31:0] bt, tickd;
        txd <= {txd[2:0], i_txl};
        o_sh <= {o_line, o_sh[2:1]};
        o_old <= o_sh[0];
        frd <= {frd[8:0], i_hfrac};
        o_fr <= {frd[11:9], o_fr[11:3]};
        o_line <= (brk | i_dead) ? 1'b0 : txd[3];
        if (trk) begin
            lvl_edge = i_txl != hp;
            hn = hc + 3'd1;
            b1 = i_hs & lvl_edge;
            b0 = i_hs & !lvl_edge & pend;
            bev = b1 | b0;
            bt = b1 ? i_tick : tc;
            jdet = b0 & (ones >= 3'd5) & fl_arm;
            hit = (jdet & fl_tgt == 12'd2) | (bev & fl_run & fl_cnt == 12'd1);
            tickd = i_tick - 32'd4;
            bu_start = hit & (bu_cfg != 12'd0);
            bu_bit = bev & (bu_start | (bu_len != 12'd0));
            bu_g = (bu_start | (bu_len == 12'd1)) ? 1'b1 : ((bu_z == 2'd2) ? 1'b1 : ((bu_o == 4'd9) ? 1'b0 : bu_s[0]));
            inv = ((tickd >= fl_is) & (tickd < fl_ie)) ^ ((tickd >= bu_t) ? bu_m : bu_pm);
            o_line <= (brk | i_dead) ? 1'b0 : (txd[3] ^ inv);
            if (i_hs) begin
                hp <= i_txl;
                if (lvl_edge) begin
                    hc <= 3'd0;
                    pend <= 1'b0;
                end else if (pend) begin
                    hc <= 3'd1;
                    pend <= 1'b0;
                end else begin
                    hc <= hn;
                    if (hn == 3'd4) begin
                        pend <= 1'b1;
                        tc <= i_tick;
                    end
                end
            end
            if (bev) begin
                ones <= b0 ? 3'd0 : (ones == 3'd7 ? 3'd7 : ones + 3'd1);
                if (jdet) begin
                    fl_arm <= 1'b0;
                    fl_run <= fl_tgt > 12'd2;
                    fl_cnt <= fl_tgt - 12'd2;
                end else if (fl_run) begin
                    fl_cnt <= fl_cnt - 12'd1;
                    if (fl_cnt == 12'd1) fl_run <= 1'b0;
                end
                if (hit & (bu_cfg == 12'd0)) begin
                    fl_is <= bt;
                    fl_ie <= 32'hffffffff;
                    fl_open <= 1'b1;
                end else if (fl_open) begin
                    fl_ie <= bt;
                    fl_open <= 1'b0;
                end
                if (bu_bit) begin
                    // A garbage bit from this boundary: the mask makes the line's code bit the garbage's.
                    bu_pm <= bu_m;
                    bu_m <= (bu_start ? 1'b0 : bu_m) ^ b1 ^ bu_g;
                    bu_t <= bt;
                    bu_s <= bu_s[0] ? ({1'b0, bu_s[15:1]} ^ 16'hb400) : {1'b0, bu_s[15:1]};
                    bu_z <= bu_g ? 2'd0 : bu_z + 2'd1;
                    bu_o <= bu_g ? bu_o + 4'd1 : 4'd0;
                    bu_len <= (bu_start ? bu_cfg : bu_len) - 12'd1;
                    bu_ret <= (bu_start ? bu_cfg : bu_len) == 12'd1;
                    if (bu_start) begin
                        bu_z <= 2'd0;
                        bu_o <= 4'd1;
                        bu_cfg <= 12'd0;
                    end
                end else if (bu_ret) begin
                    // After the last garbage bit the level is the sender's again.
                    bu_pm <= bu_m;
                    bu_m <= 1'b0;
                    bu_t <= bt;
                    bu_ret <= 1'b0;
                end
            end
            // The fault point works only while a flip or burst is armed or running; arming it starts the bit grid
            // afresh from the line's level (an armed packet is always after an idle gap: edges every bit, ones
            // enough).
            trk <= fl_arm | fl_run | fl_open | (bu_len != 12'd0) | bu_ret | bu_m | (tickd < fl_ie) | (tickd < bu_t);
        end
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@BREAK@) brk <= i_cfg_val[0];
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@FLIP@) begin
            fl_arm <= 1'b1;
            fl_run <= 1'b0;
            fl_tgt <= i_cfg_val[11:0];
            trk <= 1'b1;
            hp <= i_txl;
            hc <= 3'd0;
            pend <= 1'b0;
            ones <= 3'd0;
            bu_cfg <= i_cfg_val[23:12];
            bu_s <= {i_cfg_val[31:24], 8'ha5};
        end
    end
endmodule
"#;

/// The node surroundings module of the ring top (`@INC@`, `@PHASE@`,
/// `@KILL@`, `@ADDRESS@`, `@REQUEST@` and `@SENSOR@` stand for the
/// configuration fields of [`cfg`]).
const NODE_ENV_MODULE: &str = r#"// ---- merkur_node_env: what the simulated ring gives one node (rtl/src/harness/ring_top.rs) ----
// The node's clock (a 32-bit accumulator adds the configured increment every tick; its carry, latched on the
// falling edge, gates the next tick: glitch-free), its DDR output's half on the line, its death, and every input
// registered on its own clock as a synthesis top does (the sample windows, address, slot count, CS timeout,
// period, sensor value, user requests), plus counters of its interrupt pulses. One module for every node, so
// that a simulator runs one copy of its code for all of them (docs/benchmarks.md, issue 24).
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clk` | in | 1 | simulation tick |
// | `i_index` | in | 16 | the node's index (constant) |
// | `i_cfg_we`, `i_cfg_sel`, `i_cfg_field`, `i_cfg_val` | in | 1, 16, 8, 32 | the ring top's configuration write; this node's when `i_cfg_sel` = `i_index` (fields INC, PHASE, KILL, POR, ADDRESS, REQUEST, SENSOR) |
// | `i_incyc`, `i_innew` | in | 3, 1 | CYC of the last DATA frame on the fibre that brings the node its frames, and its end (one monitor clock) |
// | `i_pi`, `i_si` | in | 4, 4 | the PI and SI fibres' last 4 line levels (oldest in bit 0) |
// | `i_pio`, `i_sio` | in | 1, 1 | the level before the oldest of them |
// | `i_pif`, `i_sif` | in | 12, 12 | for each of the 4 levels (3 bits each, oldest in bits 2:0), the sub-tick time of the sender's half that starts in that tick: eighths of a tick before it |
// | `i_sel_si` | in | 1 | the node's `o_cap_si`: the capture register takes SI's samples into `o_pi` and PI's into `o_si` (the switchbox's input choice, as every synthesis top's capture makes it for a slave or a master; 0 for the special master) |
// | `i_slots_m1`, `i_cs_timeout`, `i_period` | in | 12, 20, 20 | the ring's configuration |
// | `i_irq` | in | 5 | the node's interrupt pulses `{fs change, reconfig, failsafe, irq2, irq1}` |
// | `nclk` | in | 1 | the node's clock: `clk` gated by `o_enl`, made in the ring top for every node at once (no `i_` prefix: a clock, like the nodes' `clock`, not a value the build keeps per instance) |
// | `o_enl` | out | 1 | the node's clock enable for this tick (latched while `clk` is low) |
// | `o_hs` | out | 1 | a new half of the node's DDR output pair starts on the line this tick |
// | `o_hfrac` | out | 3 | the sub-tick time of that half: its clock edge's, eighths of a tick before the tick |
// | `o_first` | out | 1 | the line carries the first half (bit 0) of the node's DDR pair |
// | `o_dead` | out | 1 | the node is dead (its output fibres dark) |
// | `o_por` | out | 1 | the node is held in its power-on reset (a restart) |
// | `o_pi` … `o_period` | out | | the inputs above and the node's address, user request `{fs, irq2, irq1}` and sensor value (chosen by `i_incyc`), registered on `nclk` |
// | `o_nirq1`, `o_nirq2`, `o_nirqfs`, `o_nirqrc`, `o_nirqfsc` | out | 16 each | interrupt pulses counted while the node is alive |
module merkur_node_env(clk, i_index, i_cfg_we, i_cfg_sel, i_cfg_field, i_cfg_val, i_incyc, i_innew, i_pi, i_si,
    i_pio, i_sio, i_pif, i_sif, i_sel_si, i_slots_m1, i_cs_timeout, i_period, i_irq, nclk, o_enl, o_hs, o_hfrac, o_first, o_dead,
    o_por, o_pi, o_si, o_addr, o_slots_m1,
    o_cs_timeout, o_period, o_ureq, o_sens, o_nirq1, o_nirq2, o_nirqfs, o_nirqrc, o_nirqfsc);
    input wire clk;
    input wire [15:0] i_index;
    input wire i_cfg_we;
    input wire [15:0] i_cfg_sel;
    input wire [7:0] i_cfg_field;
    input wire [31:0] i_cfg_val;
    input wire [2:0] i_incyc;
    input wire i_innew;
    input wire [3:0] i_pi;
    input wire [3:0] i_si;
    input wire i_pio;
    input wire i_sio;
    input wire [11:0] i_pif;
    input wire [11:0] i_sif;
    input wire i_sel_si;
    input wire [11:0] i_slots_m1;
    input wire [19:0] i_cs_timeout;
    input wire [19:0] i_period;
    input wire [4:0] i_irq;
    input wire nclk;
    output reg o_enl = 1'b0;
    output wire o_hs;
    output reg [2:0] o_hfrac = 3'd0;
    output wire o_first;
    output reg o_dead = 1'b0;
    output reg o_por = 1'b0;
    output reg [3:0] o_pi = 4'd0;
    output reg [3:0] o_si = 4'd0;
    output reg [11:0] o_addr = 12'd0;
    output reg [11:0] o_slots_m1 = 12'd0;
    output reg [19:0] o_cs_timeout = 20'd0;
    output reg [19:0] o_period = 20'd0;
    output reg [2:0] o_ureq = 3'd0;
    output reg [15:0] o_sens = 16'd0;
    output reg [15:0] o_nirq1 = 16'd0;
    output reg [15:0] o_nirq2 = 16'd0;
    output reg [15:0] o_nirqfs = 16'd0;
    output reg [15:0] o_nirqrc = 16'd0;
    output reg [15:0] o_nirqfsc = 16'd0;
    reg [31:0] inc = 32'h40000000;
    reg [31:0] acc = 32'd0;
    reg en = 1'b0;
    reg fired = 1'b0, fired2 = 1'b0, selp = 1'b0;
    assign o_hs = fired | (selp & !fired2);
    assign o_first = fired | fired2;
    // Sub-tick time. The gated clock puts every edge on a tick; the oscillator's edge was earlier by the
    // accumulator's excess after its carry over the increment: `frac` eighths of a tick (inc is 2^30 to 0.1 %, an
    // excess of 2^30 or more only below a fast node's inc). It is the time of the clock edge to come (the carry's
    // tick is the one before the edge) until the next carry, at least 3 ticks later; `o_hfrac` keeps it for both
    // halves of that clock on the line. A receiver takes its samples at its own edge's sub-tick time (`o_pi`
    // below), so a link sees the edge intervals the two oscillators make, not those plus a tick of rounding at each
    // end: that was 2 samples, more than the one sample of margin a retimer's short bit leaves (cdr, retime).
    wire [32:0] sum = {1'b0, acc} + {1'b0, inc};
    reg [2:0] frac = 3'd0;
    always @(posedge clk) begin
        {en, acc} <= sum;
        if (sum[32]) frac <= sum[30] ? 3'd7 : sum[29:27];
        if (o_enl) o_hfrac <= frac;
        fired <= o_enl;
        fired2 <= fired;
        selp <= fired | fired2;
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@INC@) inc <= i_cfg_val;
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@PHASE@) acc <= i_cfg_val;
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@KILL@) o_dead <= i_cfg_val[0];
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@POR@) o_por <= i_cfg_val[0];
    end
    // The enable, latched while the tick is low so that the gated clock has no glitch. The ring top gates `clk`
    // with it for all its nodes in one expression (a simulator evaluates that at every change of `clk`; one
    // expression instead of one per node was 8 % of ring100's time, docs/benchmarks.md).
    always @(negedge clk) o_enl <= en;
    // A user request is raised at once (`now`) or when the frame with its CYC has ended on the node's input fibre.
    reg [11:0] addr = 12'd0;
    reg [7:0] req = 8'd0;
    reg [3:0] reqhold = 4'd0;
    reg [2:0] reqbits = 3'd0;
    always @(posedge clk) begin
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@ADDRESS@) addr <= i_cfg_val[11:0];
        if (reqhold != 4'd0) reqhold <= reqhold - 4'd1;
        if (req[6] && (req[7] || (i_innew && i_incyc == req[5:3]))) begin
            reqbits <= req[2:0];
            reqhold <= 4'd8;
            req[6] <= 1'b0;
        end
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@REQUEST@) req <= i_cfg_val[7:0];
    end
    wire [2:0] ureq = (reqhold != 4'd0) ? reqbits : 3'd0;
    // A sensor's four values, chosen by the CYC of the frame whose H1 its input fibre showed last.
    reg [15:0] sens_0 = 16'd0, sens_1 = 16'd0, sens_2 = 16'd0, sens_3 = 16'd0;
    always @(posedge clk) begin
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@SENSOR@ && i_cfg_val[17:16] == 2'd0) sens_0 <= i_cfg_val[15:0];
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@SENSOR@ && i_cfg_val[17:16] == 2'd1) sens_1 <= i_cfg_val[15:0];
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@SENSOR@ && i_cfg_val[17:16] == 2'd2) sens_2 <= i_cfg_val[15:0];
        if (i_cfg_we && i_cfg_sel == i_index && i_cfg_field == 8'd@SENSOR@ && i_cfg_val[17:16] == 2'd3) sens_3 <= i_cfg_val[15:0];
    end
    wire [15:0] sens = i_incyc[1:0] == 2'd0 ? sens_0 : i_incyc[1:0] == 2'd1 ? sens_1 : i_incyc[1:0] == 2'd2 ? sens_2 : sens_3;
    // A sample in the tick where the line changed shows the new level only if the sender's half started no later
    // than the sample was taken (its fraction before the tick at least this node's). Worked out at the node's own
    // edges only (the fibres change every tick).
    wire [4:0] pi_l = {i_pi, i_pio};
    wire [4:0] si_l = {i_si, i_sio};
    integer j;
    function automatic smp(input [4:0] l, input [11:0] f, input [2:0] fr, input integer k);
        smp = (l[k + 1] != l[k]) && (f[3 * k +: 3] < fr) ? l[k] : l[k + 1];
    endfunction
    always @(posedge nclk) begin
        for (j = 0; j < 4; j = j + 1) begin
            o_pi[j] <= i_sel_si ? smp(si_l, i_sif, frac, j) : smp(pi_l, i_pif, frac, j);
            o_si[j] <= i_sel_si ? smp(pi_l, i_pif, frac, j) : smp(si_l, i_sif, frac, j);
        end
        o_addr <= addr;
        o_slots_m1 <= i_slots_m1;
        o_cs_timeout <= i_cs_timeout;
        o_period <= i_period;
        o_ureq <= ureq;
        o_sens <= sens;
        // A dead node (its logic runs on in simulation) raises no interrupt.
        if (i_irq[0] && !o_dead) o_nirq1 <= o_nirq1 + 16'd1;
        if (i_irq[1] && !o_dead) o_nirq2 <= o_nirq2 + 16'd1;
        if (i_irq[2] && !o_dead) o_nirqfs <= o_nirqfs + 16'd1;
        if (i_irq[3] && !o_dead) o_nirqrc <= o_nirqrc + 16'd1;
        if (i_irq[4] && !o_dead) o_nirqfsc <= o_nirqfsc + 16'd1;
    end
endmodule
"#;

/// The Verilog of every module the ring needs plus the `merkur_ring` top.
pub fn ring_verilog(kinds: &[Kind], slots: usize) -> String {
    ring_verilog_with(kinds, slots, false, WordFormat::Basic)
}

/// [`ring_verilog`], with `restarts`: every node with a power-on reset
/// ([`crate::harness::power_on`]) that configuration field [`cfg::POR`] drives, for
/// scenarios that restart nodes (protocol §12). Without, the nodes keep
/// rust-hdl's text (a reset on every register costs simulation time); and
/// with words in `format` (the nodes and the fibre monitors).
pub fn ring_verilog_with(
    kinds: &[Kind],
    slots: usize,
    restarts: bool,
    format: WordFormat,
) -> String {
    let n = kinds.len();
    let cap = cap_slots(slots);
    let mut out = String::new();
    out.push_str(&format!(
        "// merkur ring: {n} nodes ({}), capture {cap} slots per cycle.\n\
         // Generated by merkur-rtl (rtl/src/harness/ring_top.rs); do not edit.\n",
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
        let v = node_verilog(k, slots, format);
        if restarts {
            out.push_str(&crate::harness::power_on::with_power_on_reset(
                &v,
                &[module_name(k)],
            ));
        } else {
            out.push_str(&v);
        }
    }
    out.push_str(&rename_top(
        &block_verilog(crate::line::monitor::Monitor::new(format)),
        "merkur_monitor",
    ));
    out.push_str(
        &FIBRE_MODULE
            .replace("@BREAK@", &cfg::BREAK.to_string())
            .replace("@FLIP@", &cfg::FLIP.to_string()),
    );
    out.push_str(
        &NODE_ENV_MODULE
            .replace("@INC@", &cfg::INC.to_string())
            .replace("@PHASE@", &cfg::PHASE.to_string())
            .replace("@KILL@", &cfg::KILL.to_string())
            .replace("@POR@", &cfg::POR.to_string())
            .replace("@ADDRESS@", &cfg::ADDRESS.to_string())
            .replace("@REQUEST@", &cfg::REQUEST.to_string())
            .replace("@SENSOR@", &cfg::SENSOR.to_string()),
    );
    out.push_str(&top(
        kinds,
        cap,
        restarts,
        format == WordFormat::ExtendedAlarm,
    ));
    out
}

/// Node `k` of the ring top: its surroundings (`merkur_node_env`) and its
/// instance (`flying`: the ring has backups, [`crate::node::special_master`]'s
/// `i_flying`).
fn node(k: usize, kind: Kind, n: usize, restarts: bool, flying: bool) -> String {
    let mut v = String::new();
    let w = |v: &mut String, s: &str| {
        v.push_str(s);
        v.push('\n');
    };
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
    let pi = format!("{{line_{pi_f}, sh_{pi_f}}}");
    let si = format!("{{line_{}, sh_{}}}", n + k, n + k);
    w(
        &mut v,
        &format!(
            "    // ---- node {k}: {kind} ----\n\
             \x20   wire [1:0] mode_{k};\n\
             \x20   // The node's capture choice (SI as INPUT); 0 for the special master, whose switchbox chooses.\n    wire capsi_{k};\n\
             \x20   // The fibre that brings the node its frames: PI, or SI when wrapped up (WU).\n\
             \x20   wire [2:0] incyc_{k} = {in_cyc};\n    wire innew_{k} = {in_new};\n\
             \x20   wire nclk_{k} = nclk[{k}];
    wire hs_{k}, first_{k}, dead_{k}{por_w};\n    wire [2:0] hfrac_{k};\n{por_u}\
             \x20   wire [3:0] pi_r_{k}, si_r_{k};\n    wire [11:0] addr_r_{k}, slots_m1_r_{k};\n    wire [19:0] cs_timeout_r_{k};\n    wire [2:0] ureq_r_{k};\n\
             \x20   wire [15:0] nirq1_{k}, nirq2_{k}, nirqfs_{k}, nirqrc_{k}, nirqfsc_{k};\n\
             \x20   wire irq1_{k}, irq2_{k}, irqfs_{k}, irqrc_{k}, irqfsc_{k};\n\
             \x20   /* verilator lint_off UNUSEDSIGNAL */\n    // A sensor's value and the special master's period: the other kinds leave them.\n\
             \x20   wire [15:0] sens_r_{k};\n    wire [19:0] period_r_{k};\n    /* verilator lint_on UNUSEDSIGNAL */\n\
             \x20   merkur_node_env env_{k}(.clk(clk), .i_index(16'd{k}),\n\
             \x20       .i_cfg_we(i_cfg_we), .i_cfg_sel(i_cfg_sel), .i_cfg_field(i_cfg_field), .i_cfg_val(i_cfg_val),\n\
             \x20       .i_incyc(incyc_{k}), .i_innew(innew_{k}), .i_pi({pi}), .i_si({si}),\n\
             \x20       .i_pio(old_{pi_f}), .i_sio(old_{sif}), .i_pif(fr_{pi_f}), .i_sif(fr_{sif}), .i_sel_si(capsi_{k}), .i_slots_m1(slots_m1), .i_cs_timeout(cs_timeout), .i_period(period),\n\
             \x20       .i_irq({{irqfsc_{k}, irqrc_{k}, irqfs_{k}, irq2_{k}, irq1_{k}}}),\n\
             \x20       .nclk(nclk_{k}), .o_enl(enl[{k}]), .o_hs(hs_{k}), .o_hfrac(hfrac_{k}), .o_first(first_{k}), .o_dead(dead_{k}), .o_por(por_{k}), .o_pi(pi_r_{k}), .o_si(si_r_{k}), .o_addr(addr_r_{k}),\n\
             \x20       .o_slots_m1(slots_m1_r_{k}), .o_cs_timeout(cs_timeout_r_{k}), .o_period(period_r_{k}), .o_ureq(ureq_r_{k}), .o_sens(sens_r_{k}),\n\
             \x20       .o_nirq1(nirq1_{k}), .o_nirq2(nirq2_{k}), .o_nirqfs(nirqfs_{k}), .o_nirqrc(nirqrc_{k}), .o_nirqfsc(nirqfsc_{k}));\n\
             \x20   wire [1:0] po_{k}, so_{k};\n    wire fs_{k};\n    wire [15:0] perr_{k}, ferr_{k};",
            kind = kind.name(),
            sif = n + k,
            por_w = if restarts { format!(", por_{k}") } else { String::new() },
            por_u = if restarts {
                String::new()
            } else {
                format!("    /* verilator lint_off UNUSEDSIGNAL */\n    wire por_{k}; // no restart in this ring: the node has no power-on reset\n    /* verilator lint_on UNUSEDSIGNAL */\n")
            },
        ),
    );
    let por = if restarts {
        format!(".i_por(por_{k}), ")
    } else {
        String::new()
    };
    let common = format!(
        "{por}.clock(nclk_{k}), .i_pi(pi_r_{k}), .i_si(si_r_{k}), .o_po(po_{k}), .o_so(so_{k}), .i_address(addr_r_{k}), .i_slots_m1(slots_m1_r_{k}), .i_cs_timeout(cs_timeout_r_{k}), .i_irq1(ureq_r_{k}[0]), .i_irq2(ureq_r_{k}[1]), .i_fs_req(ureq_r_{k}[2])"
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
                     \x20   wire [11:0] u_fslot_{k}, u_slot_{k};\n    wire [15:0] u_data_{k};\n    wire [1:0] u_kind_{k};\n    wire u_regen_{k}, u_wvalid_{k}, u_alive_{k}, u_alarm_{k}, u_ok_{k}, u_hdr_bad_{k}, u_rtx_{k};\n    wire [3:0] u_reason_{k};\n    /* verilator lint_on UNUSEDSIGNAL */\n\
                     \x20   merkur_slave n{k}({common}, .i_cap_sel(1'b1), .o_cap_si(capsi_{k}), .i_actuator(1'b{act}), .i_sensor_data({sens}),\n\
                     \x20       .i_master(1'b0), .i_slot_cfg(2'd0), .i_slot_data(16'd0), .i_slot_alive(1'b0), .i_fs_set(1'b0),\n\
                     \x20       .o_fwd_slot(u_fslot_{k}), .o_regen(u_regen_{k}), .o_wvalid(u_wvalid_{k}), .o_kind(u_kind_{k}), .o_slot(u_slot_{k}), .o_data(u_data_{k}),\n\
                     \x20       .o_alive(u_alive_{k}), .o_alarm(u_alarm_{k}), .o_reason(u_reason_{k}), .o_ok(u_ok_{k}), .o_hdr_bad(u_hdr_bad_{k}), .o_rtx(u_rtx_{k}),\n\
                     \x20       .o_act_data(act_{k}), .o_mode(mode_{k}), .o_failsafe(fs_{k}), .o_perr(perr_{k}), .o_ferr(ferr_{k}));\n\
                     \x20   wire [15:0] aerr_{k} = 16'd0;\n    wire [15:0] serr_{k} = 16'd0;\n    wire [11:0] hop_{k} = 12'd0;\n    wire [15:0] cycles_{k} = 16'd0;\n    wire [15:0] frames_{k} = 16'd0;\n    wire run_{k} = 1'b1;\n    assign irq1_{k} = 1'b0;\n    assign irq2_{k} = 1'b0;\n    assign irqfs_{k} = 1'b0;\n    assign irqrc_{k} = 1'b0;\n    assign irqfsc_{k} = 1'b0;"
                ),
            );
        }
        Kind::Master | Kind::SpecialMaster => {
            let (defs, extra) = if kind == Kind::SpecialMaster {
                (
                    format!(
                        "    wire [15:0] serr_{k};\n    wire [11:0] hop_{k};\n    wire [15:0] cycles_{k};\n    assign capsi_{k} = 1'b0;\n\
                         \x20   // Backup priority and election time (static: written before the start).\n\
                         \x20   reg [2:0] prio_{k} = 3'd0;\n    reg [19:0] elect_{k} = 20'd0;\n\
                         \x20   // Retransmission timing (static: written before the start).\n\
                         \x20   reg [19:0] rtx_at_{k} = 20'd0;\n    reg [19:0] rtx_atw_{k} = 20'd0;\n    reg [9:0] rtx_k_{k} = 10'd0;\n\
                         \x20   always @(posedge clk) begin\n\
                         \x20       if (i_cfg_we && i_cfg_sel == 16'd{k} && i_cfg_field == 8'd{pf}) prio_{k} <= i_cfg_val[2:0];\n\
                         \x20       if (i_cfg_we && i_cfg_sel == 16'd{k} && i_cfg_field == 8'd{ef}) elect_{k} <= i_cfg_val[19:0];\n\
                         \x20       if (i_cfg_we && i_cfg_sel == 16'd{k} && i_cfg_field == 8'd{ra}) rtx_at_{k} <= i_cfg_val[19:0];\n\
                         \x20       if (i_cfg_we && i_cfg_sel == 16'd{k} && i_cfg_field == 8'd{rw}) rtx_atw_{k} <= i_cfg_val[19:0];\n\
                         \x20       if (i_cfg_we && i_cfg_sel == 16'd{k} && i_cfg_field == 8'd{rk}) rtx_k_{k} <= i_cfg_val[9:0];\n\
                         \x20   end\n\
                         \x20   // On the node's clock, as its other inputs (so that its logic is evaluated at its own edges only).\n\
                         \x20   reg [2:0] prio_r_{k} = 3'd0;\n    reg [19:0] elect_r_{k} = 20'd0;\n\
                         \x20   reg [19:0] rtx_at_r_{k} = 20'd0;\n    reg [19:0] rtx_atw_r_{k} = 20'd0;\n    reg [9:0] rtx_k_r_{k} = 10'd0;\n\
                         \x20   always @(posedge nclk_{k}) begin\n        prio_r_{k} <= prio_{k};\n        elect_r_{k} <= elect_{k};\n\
                         \x20       rtx_at_r_{k} <= rtx_at_{k};\n        rtx_atw_r_{k} <= rtx_atw_{k};\n        rtx_k_r_{k} <= rtx_k_{k};\n    end\n\
                         \x20   // Frames sent while alive (the epoch of the capture, and the driver's frame count).\n\
                         \x20   reg [15:0] cyc_was_{k} = 16'd0;\n    reg [15:0] frames_{k} = 16'd0;\n\
                         \x20   always @(posedge clk) begin\n        cyc_was_{k} <= cycles_{k};\n\
                         \x20       if (!dead_{k} && cycles_{k} != cyc_was_{k}) frames_{k} <= frames_{k} + 16'd1;\n    end\n\
                         \x20   /* verilator lint_off UNUSEDSIGNAL */\n    wire base_{k}; // the driver counts frames by `frames`\n    /* verilator lint_on UNUSEDSIGNAL */",
                        pf = cfg::PRIO,
                        ef = cfg::ELECT,
                        ra = cfg::RTX_AT,
                        rw = cfg::RTX_ATW,
                        rk = cfg::RTX_K
                    ),
                    format!(".i_period(period_r_{k}), .i_prio(prio_r_{k}), .i_elect(elect_r_{k}), .i_flying(1'b{}),\n        .i_rtx_at(rtx_at_r_{k}), .i_rtx_atw(rtx_atw_r_{k}), .i_rtx_k(rtx_k_r_{k}[4:0]), .i_rtx_kw(rtx_k_r_{k}[9:5]),\n        .o_serr(serr_{k}), .o_hop(hop_{k}), .o_cycles(cycles_{k}), .o_base(base_{k}),", u8::from(flying)),
                )
            } else {
                (
                    format!("    wire [15:0] serr_{k} = 16'd0;\n    wire [11:0] hop_{k} = 12'd0;\n    wire [15:0] cycles_{k} = 16'd0;\n    wire [15:0] frames_{k} = 16'd0;"),
                    format!(".i_cap_sel(1'b1), .o_cap_si(capsi_{k}),"),
                )
            };
            w(
                &mut v,
                &format!(
                    "{defs}\n    wire [15:0] aerr_{k};\n    wire [15:0] act_{k} = 16'd0;\n    wire run_{k};\n    /* verilator lint_off UNUSEDSIGNAL */\n    wire alarmq_{k}; // the queue's level interrupt: the driver reads the queue over Wishbone\n    /* verilator lint_on UNUSEDSIGNAL */\n    wire [15:0] wbdat_{k};\n    wire wback_{k};\n\
                     \x20   // The harness's Wishbone, registered on the node's clock like its other inputs (a transfer takes one\n\
                     \x20   // node clock more; the harness drops STB once it sees ACK, before the node's next edge).\n\
                     \x20   reg wb_cyc_{k} = 1'b0, wb_stb_{k} = 1'b0, wb_we_{k} = 1'b0;\n    reg [13:0] wb_adr_{k} = 14'd0;\n    reg [15:0] wb_dat_{k} = 16'd0;\n\
                     \x20   always @(posedge nclk_{k}) begin\n\
                     \x20       wb_cyc_{k} <= i_wb_cyc && i_wb_node == 16'd{k};\n        wb_stb_{k} <= i_wb_stb && i_wb_node == 16'd{k};\n\
                     \x20       wb_we_{k} <= i_wb_we;\n        wb_adr_{k} <= i_wb_adr;\n        wb_dat_{k} <= i_wb_dat;\n    end\n\
                     \x20   {m} n{k}({common}, {extra}\n\
                     \x20       .i_wb_cyc(wb_cyc_{k}), .i_wb_stb(wb_stb_{k}), .i_wb_we(wb_we_{k}), .i_wb_adr(wb_adr_{k}), .i_wb_dat(wb_dat_{k}),\n\
                     \x20       .o_wb_dat(wbdat_{k}), .o_wb_ack(wback_{k}), .o_irq1(irq1_{k}), .o_irq2(irq2_{k}), .o_irq_fs(irqfs_{k}), .o_irq_rc(irqrc_{k}), .o_alarmq(alarmq_{k}), .o_irq_fsc(irqfsc_{k}),\n\
                     \x20       .o_mode(mode_{k}), .o_failsafe(fs_{k}), .o_perr(perr_{k}), .o_ferr(ferr_{k}), .o_aerr(aerr_{k}), .o_running(run_{k}));",
                    m = module_name(kind)
                ),
            );
        }
    }
    v
}

/// Fibre `f` of the ring top: the line and its fault point
/// (`merkur_fibre`), its monitor and the capture of what the monitor decodes.
/// With `ext` (extended-alarm words, protocol §6) an entry has the word's
/// reason nibble on top (35 bits).
fn fibre(f: usize, n: usize, capw: usize, ext: bool) -> String {
    let mut v = String::new();
    let w = |v: &mut String, s: &str| {
        v.push_str(s);
        v.push('\n');
    };
    let name = merkur_model::config::Fibre::from_index(f, n).to_string();
    let (src, port) = if f < n {
        (f, "po")
    } else {
        ((f - n + 1) % n, "so")
    };
    w(
        &mut v,
        &format!(
            "    // ---- fibre {name} (from node {src}) ----\n\
             \x20   wire line_{f}, old_{f};\n    wire [2:0] sh_{f};\n    wire [11:0] fr_{f};\n\
             \x20   wire txl_{f} = first_{src} ? {port}_{src}[0] : {port}_{src}[1];\n\
             \x20   // The line and its fault point (module `merkur_fibre` above).\n\
             \x20   merkur_fibre fib_{f}(.clk(clk), .i_tick(tick), .i_txl(txl_{f}), .i_hs(hs_{src}), .i_hfrac(hfrac_{src}), .i_dead(dead_{src}),\n\
             \x20       .i_index(16'd{f}),\n\
             \x20       .i_cfg_we(i_cfg_we), .i_cfg_sel(i_cfg_sel), .i_cfg_field(i_cfg_field), .i_cfg_val(i_cfg_val), .o_line(line_{f}), .o_sh(sh_{f}),\n\
             \x20       .o_old(old_{f}), .o_fr(fr_{f}));\n\
             \x20   wire m_los_{f}, m_wvalid_{f}, m_alive_{f}, m_alarm_{f}, m_ok_{f}, m_void_{f}, m_marked_{f};\n    wire [1:0] m_kind_{f}, m_ptype_{f};\n    wire [11:0] m_slot_{f};\n    wire [15:0] m_data_{f};\n\
             \x20   {reason_decl}\
             \x20   wire m_hdrbad_{f};\n    /* verilator lint_off UNUSEDSIGNAL */\n    // Monitor outputs the capture does not need.\n    wire m_bvalid_{f}, m_code_{f}, m_start_{f}, m_inpkt_{f}, m_own_{f}, m_compl_{f};\n    {reason_unused}wire [1:0] m_phase_{f};\n    /* verilator lint_on UNUSEDSIGNAL */\n\
             \x20   merkur_monitor mon_{f}(.clock(mclk), .i_samples({{line_{f}, sh_{f}}}), .i_slots_m1(slots_m1), .i_address(12'hfff), .i_flush(1'b0),\n\
             \x20       .o_los(m_los_{f}), .o_bvalid(m_bvalid_{f}), .o_code(m_code_{f}), .o_phase(m_phase_{f}), .o_start(m_start_{f}), .o_inpkt(m_inpkt_{f}),\n\
             \x20       .o_wvalid(m_wvalid_{f}), .o_kind(m_kind_{f}), .o_slot(m_slot_{f}), .o_data(m_data_{f}), .o_alive(m_alive_{f}), .o_alarm(m_alarm_{f}),\n\
             \x20       .o_reason(m_reason_{f}), .o_ok(m_ok_{f}), .o_compl(m_compl_{f}), .o_void(m_void_{f}), .o_marked(m_marked_{f}), .o_own(m_own_{f}), .o_hdr_bad(m_hdrbad_{f}), .o_ptype(m_ptype_{f}));\n\
             \x20   reg [{top}:0] cap_{f} [0:{last}];\n    integer ci_{f};\n    initial for (ci_{f} = 0; ci_{f} <= {last}; ci_{f} = ci_{f} + 1) cap_{f}[ci_{f}] = {width}'d0;\n    reg [31:0] th1_{f} = 32'd0;\n    reg [11:0] lslot_{f} = 12'hfff;\n    reg [15:0] h0_{f} = 16'd0, h1_{f} = 16'd0, nsec_{f} = 16'd0, ntst_{f} = 16'd0, nend_{f} = 16'd0;\n    reg infr_{f} = 1'b0;\n\
             \x20   wire [1:0] mstat_{f} = m_ok_{f} ? 2'd1 : (m_void_{f} ? 2'd3 : 2'd2);\n\
             \x20   // A bad word's ALARM field in the capture says whether it was marked (protocol §4).\n\
             \x20   wire mflag_{f} = (m_ok_{f} | m_void_{f}) ? m_alarm_{f} : m_marked_{f};\n\
             \x20   // The capture memory is written with blocking assignments: only the harness reads it, between evaluations,\n\
             \x20   // so the write takes effect at the same moment as a nonblocking one; a simulator then needs no deferred-write\n\
             \x20   // flags for each of its three write sites, which it cleared and tested at every monitor clock on every fibre.\n\
             \x20   /* verilator lint_off BLKSEQ */\n\
             \x20   always @(posedge mclk) begin\n        hdr_new_{f} <= 1'b0;\n\
             \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd0 && m_ok_{f}) h0_{f} <= m_data_{f};\n\
             \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd0) begin\n\
             \x20           h1_{f} <= m_data_{f};\n            th1_{f} <= tick;\n            lslot_{f} <= 12'hfff;\n            hdr_cyc_{f} <= m_data_{f}[14:12];\n            infr_{f} <= 1'b1;\n\
             \x20           cap_{f}[{{1'b1, {hz}m_data_{f}[13:12], 1'b0}}] = {{{rz}epoch, m_data_{f}[14:12], 2'd1, 2'd0, h0_{f}}};\n\
             \x20           cap_{f}[{{1'b1, {hz}m_data_{f}[13:12], 1'b1}}] = {{{rz}epoch, m_data_{f}[14:12], 2'd1, 2'd0, m_data_{f}}};\n        end\n\
             \x20       // A DATA frame whose H1 was damaged (after a good H0: the header is rejected at H1) is the next cycle's all\n\
             \x20       // the same: a sensor that missed it fills a retransmission request of that cycle with that cycle's value\n\
             \x20       // (protocol §8).\n\
             \x20       if (m_hdrbad_{f} && m_kind_{f} == 2'd1 && m_ptype_{f} == 2'd0) hdr_cyc_{f} <= hdr_cyc_{f} + 3'd1;\n\
             \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd1) nsec_{f} <= nsec_{f} + 16'd1;\n\
             \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd1 && m_ok_{f} && m_ptype_{f} == 2'd2) ntst_{f} <= ntst_{f} + 16'd1;\n\
             \x20       if (m_wvalid_{f} && m_kind_{f} == 2'd2) begin\n            lslot_{f} <= m_slot_{f};\n\
             \x20           cap_{f}[{{1'b0, hdr_cyc_{f}[1:0], m_slot_{f}[{cb}:0]}}] = {{{rn}epoch, hdr_cyc_{f}, mstat_{f}, mflag_{f}, m_alive_{f}, m_data_{f}}};\n\
             \x20           if (m_slot_{f} == slots_m1) begin\n                infr_{f} <= 1'b0;\n                hdr_new_{f} <= 1'b1;\n                nend_{f} <= nend_{f} + 16'd1;\n            end\n        end\n    end\n    /* verilator lint_on BLKSEQ */",
            hz = if capw > 4 { format!("{}'d0, ", capw - 4) } else { String::new() },
            last = (1usize << capw) - 1,
            top = if ext { 34 } else { 30 },
            width = if ext { 35 } else { 31 },
            rz = if ext { "4'd0, " } else { "" },
            rn = if ext { format!("m_reason_{f}, ") } else { String::new() },
            reason_decl = if ext {
                format!("wire [3:0] m_reason_{f};\n")
            } else {
                String::new()
            },
            reason_unused = if ext {
                String::new()
            } else {
                format!("wire [3:0] m_reason_{f};\n    ")
            },
            cb = capw - 4,
        ),
    );
    v
}

/// The harness's read multiplexers: status fields, captured entries and
/// the masters' Wishbone answers.
fn read_muxes(kinds: &[Kind], ext: bool) -> String {
    let n = kinds.len();
    let nf = 2 * n;
    // The capture read: 32 bits (31-bit entries), 64 with extended words
    // (35-bit entries).
    let (cw, pad) = if ext { (64, "29'd0") } else { (32, "1'b0") };
    let mut v = String::new();
    let w = |v: &mut String, s: &str| {
        v.push_str(s);
        v.push('\n');
    };
    // Status read: every field by name (`status`), `K` = node or fibre.
    let node_fields: [(u32, &str); 16] = [
        (status::FRAMES, "{16'd0, frames_K}"),
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
    // Packed fields: many nodes or fibres in one read.
    let packed =
        |count: usize, per: usize, field: u32, bits: usize, item: &dyn Fn(usize) -> String| {
            let mut lines = String::new();
            for g in 0..count.div_ceil(per) {
                let range = g * per..((g + 1) * per).min(count);
                let pad = 32 - bits * range.len();
                let mut items: Vec<String> = range.rev().map(item).collect();
                if pad > 0 {
                    items.insert(0, format!("{pad}'d0"));
                }
                lines.push_str(&format!(
                    "            {{16'd{g}, 8'd{field}}}: o_rd = {{{}}};\n",
                    items.join(", ")
                ));
            }
            lines
        };
    v.push_str(&packed(n, status::MODES_PER_READ, status::MODES, 3, &|k| {
        format!("fs_{k}, mode_{k}")
    }));
    v.push_str(&packed(
        nf,
        status::FRAMES_PER_READ,
        status::FRAME_V,
        4,
        &|f| format!("infr_{f}, hdr_cyc_{f}"),
    ));
    let bases: Vec<String> = (0..n)
        .filter(|&k| kinds[k] == Kind::SpecialMaster)
        .map(|k| format!("{{16'd0, frames_{k}}}"))
        .collect();
    if !bases.is_empty() {
        w(
            &mut v,
            &format!(
                "            {{16'd0, 8'd{}}}: o_rd = {};",
                status::FRAMES_ALL,
                bases.join(" + ")
            ),
        );
    }
    w(
        &mut v,
        "            default: o_rd = 32'd0;\n        endcase\n    end",
    );
    // Capture read.
    w(
        &mut v,
        &format!("    always @(*) begin\n        o_cap = {cw}'d0;\n        if (i_cap_en) case (i_cap_fibre)"),
    );
    for f in 0..nf {
        w(
            &mut v,
            &format!("            16'd{f}: o_cap = {{{pad}, cap_{f}[i_cap_idx]}};"),
        );
    }
    w(
        &mut v,
        &format!("            default: o_cap = {cw}'d0;\n        endcase\n    end"),
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
    v
}

fn top(kinds: &[Kind], cap: usize, restarts: bool, ext: bool) -> String {
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
         \x20   input wire i_cap_en;\n    input wire [15:0] i_cap_fibre;\n    input wire [CAPW-1:0] i_cap_idx;\n    output reg [CAPB-1:0] o_cap;\n\
         \x20   input wire [15:0] i_wb_node;\n    input wire i_wb_cyc;\n    input wire i_wb_stb;\n    input wire i_wb_we;\n\
         \x20   input wire [13:0] i_wb_adr;\n    input wire [15:0] i_wb_dat;\n    output reg [15:0] o_wb_dat;\n    output reg o_wb_ack;",
    );
    v = v.replace("CAPW-1", &(capw - 1).to_string());
    v = v.replace("CAPB-1", if ext { "63" } else { "31" });
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
    // Nodes: their surroundings (`merkur_node_env`: clock, inputs), instances.
    // Every node's clock: the tick gated by the node's enable, all in one expression.
    w(
        &mut v,
        &format!(
            "    wire [{m}:0] enl;\n    wire [{m}:0] nclk = {{{n}{{clk}}}} & enl;",
            m = n - 1
        ),
    );
    // A ring with backups (more than one clock-base node, protocol §8).
    let flying = kinds.iter().filter(|&&x| x == Kind::SpecialMaster).count() > 1;
    for (k, &kind) in kinds.iter().enumerate() {
        v.push_str(&node(k, kind, n, restarts, flying));
    }
    // Capture entries carry the ring's frame count when written (its low 8
    // bits: the frames every clock-base node has sent, the special master
    // and the backups, protocol §8), so that an entry left from 8 cycles
    // before (CYC has 3 bits) is not read as this cycle's.
    let bases: Vec<String> = kinds
        .iter()
        .enumerate()
        .filter(|&(_, &k)| k == Kind::SpecialMaster)
        .map(|(k, _)| format!("frames_{k}[7:0]"))
        .collect();
    assert!(!bases.is_empty(), "a ring has a special master");
    w(
        &mut v,
        &format!("    wire [7:0] epoch = {};", bases.join(" + ")),
    );
    // Fibres: line levels, fault points, monitors, capture.
    for f in 0..nf {
        v.push_str(&fibre(f, n, capw, ext));
    }
    v.push_str(&read_muxes(kinds, ext));
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
