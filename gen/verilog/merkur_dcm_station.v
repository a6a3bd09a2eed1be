// merkur_dcm_station.v — one IEEE 802.4 token-bus station's Dual Channel Manager with its redundancy management (RMM)
//
// Generated Verilog; do not edit. Generator: merkur-rtl 0.1.0 (rust-hdl 0.46.0),
// from rtl/src/tokenbus/dcm_station.rs. `cargo run -p merkur-sim --example gen` rewrites this file and
// sim/tests/gen.rs fails when it drifts from the generator.
//
// Top module: merkur_dcm_station. Build parameters: none.
// Every other setting is a port (the port table is in the header of module merkur_dcm_station
// below). Clock: `clock`, twice the line rate (100 MHz for 50 Mbit/s); the fibre
// inputs take 4 samples per clock (quadrature DDR capture), the outputs give a DDR
// pair (docs/protocol.md §9; `merkur_ddr_in`/`merkur_ddr_out` in rtl/src/top/synth_top.rs).
// Lint: verilator --lint-only -Wall waivers.vlt merkur_dcm_station.v --top-module merkur_dcm_station

// --------------------------------------------------------------------------
// DcmStation: One station's DCM and RMM. (rtl/src/tokenbus/dcm_station.rs)
//
// # dcm_station — one token-bus station's redundancy hardware (docs/protocol.md Part II)
//
// Purpose: the paper's Figure 5 in one block, emitted as `merkur_dcm_station`: the
// Dual Channel Manager ([`crate::tokenbus::dcm`]) between the MAC and the two PHYs,
// and the Redundancy Management Module — fault detection from the MAC's
// events ([`crate::tokenbus::rmm_detect`]), status frame production
// ([`crate::tokenbus::rmm_sfp`]) and check ([`crate::tokenbus::rmm_sfc`]), and the fault
// correction machine ([`crate::tokenbus::rmm_fcm`]). One clock is one octet time.
// The report to the network manager is `o_state`, `o_cause`, `o_stale`,
// the channel status registers and the interrupt `o_irq`.
//
// Status byte of the status frame: bit 7 active channel, bits 6:4 state,
// bit 3 dual mode (Auto_Normal), bit 2 channel B good, bit 1 channel A
// good, bit 0 host status.
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_rx_a`, `i_rx_b`, `o_tx_a`, `o_tx_b` | in/out | 11 | PHY A / B symbols |
// | `i_tx`, `o_rx` | in/out | 11 | MAC symbols |
// | `i_ev` | in | 6 | MAC events (see rmm_detect) |
// | `i_sf_sent` | in | 1 | MAC took the status word |
// | `i_rx_sf`, `i_rx_sa`, `i_rx_sfw` | in | 1/8/16 | MAC received a status frame |
// | `i_cmd_rx`, `i_cmd_ch` | in | 1 | MAC received a switch command |
// | `i_cmd_sent` | in | 1 | MAC sent our switch command |
// | `i_init`, `i_auto`, `i_host_ok` | in | 1 | host |
// | `i_addr`, `i_stations` | in | 5/32 | own address, configured stations |
// | `i_sf_period`, `i_chk_period`, `i_good_limit` | in | 16 | periods and limits, octets |
// | `o_act`, `o_state`, `o_cause`, `o_irq` | out | 1/3/4/1 | channel, machine, report |
// | `o_sf_pend`, `o_sf_word` | out | 1/16 | status frame due, its bytes |
// | `o_cmd_req`, `o_cmd_ch` | out | 1 | broadcast the switch command |
// | `o_stat_a`, `o_stat_b` | out | 16 | channel status registers |
// | `o_stale`, `o_chk_ok`, `o_chk_sw`, `o_ev_seen` | out | 32/1/1/6 | status check (stale, OK, SWITCH), events seen |
// | `i_nm_addr`, `o_nm_word`, `o_nm_valid` | in/out | 5/16/1 | network manager reads a station's stored status frame |
//
// Latency: as its blocks; `o_rx` one octet after the PHY symbol.
//
// ```text
//            +-----------------------------------------------+
//  PHY A <-->|  dcm  --fault/bad/in_frame-->  rmm_fcm        |<-- host
//  PHY B <-->|   ^  <-----------sw------------/  ^   ^       |--> report, irq
//            |   |                     rmm_detect  rmm_sfc   |
//  MAC   <-->|---+-- events, frames ------/  rmm_sfp /       |
//            +-----------------------------------------------+
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station(clock,i_rx_a,i_rx_b,i_tx,i_ev,i_sf_sent,i_rx_sf,i_rx_sa,i_rx_sfw,i_cmd_rx,i_cmd_ch,i_cmd_sent,i_init,i_auto,i_host_ok,i_addr,i_stations,i_sf_period,i_chk_period,i_good_limit,o_tx_a,o_tx_b,o_rx,o_act,o_state,o_cause,o_irq,o_sf_pend,o_sf_word,o_cmd_req,o_cmd_ch,o_stat_a,o_stat_b,o_stale,o_chk_ok,o_chk_sw,o_ev_seen,i_nm_addr,o_nm_word,o_nm_valid);

    // Module arguments
    input wire  clock;
    input wire  [10:0] i_rx_a;
    input wire  [10:0] i_rx_b;
    input wire  [10:0] i_tx;
    input wire  [5:0] i_ev;
    input wire  i_sf_sent;
    input wire  i_rx_sf;
    input wire  [7:0] i_rx_sa;
    input wire  [15:0] i_rx_sfw;
    input wire  i_cmd_rx;
    input wire  i_cmd_ch;
    input wire  i_cmd_sent;
    input wire  i_init;
    input wire  i_auto;
    input wire  i_host_ok;
    input wire  [4:0] i_addr;
    input wire  [31:0] i_stations;
    input wire  [15:0] i_sf_period;
    input wire  [15:0] i_chk_period;
    input wire  [15:0] i_good_limit;
    output reg  [10:0] o_tx_a;
    output reg  [10:0] o_tx_b;
    output reg  [10:0] o_rx;
    output reg  o_act;
    output reg  [2:0] o_state;
    output reg  [3:0] o_cause;
    output reg  o_irq;
    output reg  o_sf_pend;
    output reg  [15:0] o_sf_word;
    output reg  o_cmd_req;
    output reg  o_cmd_ch;
    output reg  [15:0] o_stat_a;
    output reg  [15:0] o_stat_b;
    output reg  [31:0] o_stale;
    output reg  o_chk_ok;
    output reg  o_chk_sw;
    output reg  [5:0] o_ev_seen;
    input wire  [4:0] i_nm_addr;
    output reg  [15:0] o_nm_word;
    output reg  o_nm_valid;

    // Registers and child block ports
    reg  dcm__i_sw;
    wire  [10:0] dcm__o_tx_a;
    wire  [10:0] dcm__o_tx_b;
    wire  [10:0] dcm__o_rx;
    wire  dcm__o_act;
    wire  dcm__o_fault_a;
    wire  dcm__o_fault_b;
    wire  dcm__o_bad_a;
    wire  dcm__o_bad_b;
    wire  dcm__o_in_frame;
    wire  [15:0] dcm__o_stat_a;
    wire  [15:0] dcm__o_stat_b;
    wire  detect__o_sc;
    wire  detect__o_ns;
    wire  [5:0] detect__o_ev_seen;
    reg  [7:0] sfp__i_status;
    wire  sfp__o_sf_pend;
    wire  [15:0] sfp__o_sf_word;
    reg  sfc__i_bad_a;
    reg  sfc__i_bad_b;
    reg  sfc__i_act;
    wire  [31:0] sfc__o_stale;
    wire  sfc__o_chk_ok;
    wire  sfc__o_chk_sw;
    wire  sfc__o_rise;
    wire  [15:0] sfc__o_nm_word;
    wire  sfc__o_nm_valid;
    reg  fcm__i_sc;
    reg  fcm__i_ns;
    reg  fcm__i_chk_ok;
    reg  fcm__i_chk_sw;
    reg  fcm__i_fault_a;
    reg  fcm__i_fault_b;
    reg  fcm__i_bad_a;
    reg  fcm__i_bad_b;
    reg  fcm__i_act;
    reg  fcm__i_in_frame;
    wire  fcm__o_sw;
    wire  [2:0] fcm__o_state;
    wire  [3:0] fcm__o_cause;
    wire  fcm__o_irq;
    wire  fcm__o_cmd_req;
    wire  fcm__o_cmd_ch;

    // Local signals
    reg  [7:0] status;

    // Child blocks
    merkur_dcm_station__dcm dcm(
        .clock(clock),
        .i_rx_a(i_rx_a),
        .i_rx_b(i_rx_b),
        .i_tx(i_tx),
        .i_sw(dcm__i_sw),
        .i_good_limit(i_good_limit),
        .o_tx_a(dcm__o_tx_a),
        .o_tx_b(dcm__o_tx_b),
        .o_rx(dcm__o_rx),
        .o_act(dcm__o_act),
        .o_fault_a(dcm__o_fault_a),
        .o_fault_b(dcm__o_fault_b),
        .o_bad_a(dcm__o_bad_a),
        .o_bad_b(dcm__o_bad_b),
        .o_in_frame(dcm__o_in_frame),
        .o_stat_a(dcm__o_stat_a),
        .o_stat_b(dcm__o_stat_b)
    );
    merkur_dcm_station__detect detect(
        .clock(clock),
        .i_ev(i_ev),
        .o_sc(detect__o_sc),
        .o_ns(detect__o_ns),
        .o_ev_seen(detect__o_ev_seen)
    );
    merkur_dcm_station__sfp sfp(
        .clock(clock),
        .i_sf_period(i_sf_period),
        .i_sf_sent(i_sf_sent),
        .i_status(sfp__i_status),
        .o_sf_pend(sfp__o_sf_pend),
        .o_sf_word(sfp__o_sf_word)
    );
    merkur_dcm_station__sfc sfc(
        .clock(clock),
        .i_chk_period(i_chk_period),
        .i_addr(i_addr),
        .i_stations(i_stations),
        .i_bad_a(sfc__i_bad_a),
        .i_bad_b(sfc__i_bad_b),
        .i_act(sfc__i_act),
        .i_rx_sf(i_rx_sf),
        .i_rx_sa(i_rx_sa),
        .i_rx_sfw(i_rx_sfw),
        .o_stale(sfc__o_stale),
        .o_chk_ok(sfc__o_chk_ok),
        .o_chk_sw(sfc__o_chk_sw),
        .o_rise(sfc__o_rise),
        .i_nm_addr(i_nm_addr),
        .o_nm_word(sfc__o_nm_word),
        .o_nm_valid(sfc__o_nm_valid)
    );
    merkur_dcm_station__fcm fcm(
        .clock(clock),
        .i_init(i_init),
        .i_auto(i_auto),
        .i_sc(fcm__i_sc),
        .i_ns(fcm__i_ns),
        .i_chk_ok(fcm__i_chk_ok),
        .i_chk_sw(fcm__i_chk_sw),
        .i_fault_a(fcm__i_fault_a),
        .i_fault_b(fcm__i_fault_b),
        .i_bad_a(fcm__i_bad_a),
        .i_bad_b(fcm__i_bad_b),
        .i_act(fcm__i_act),
        .i_in_frame(fcm__i_in_frame),
        .i_cmd_rx(i_cmd_rx),
        .i_cmd_ch(i_cmd_ch),
        .i_cmd_sent(i_cmd_sent),
        .o_sw(fcm__o_sw),
        .o_state(fcm__o_state),
        .o_cause(fcm__o_cause),
        .o_irq(fcm__o_irq),
        .o_cmd_req(fcm__o_cmd_req),
        .o_cmd_ch(fcm__o_cmd_ch)
    );

    // Combinational logic
    always @(*) begin
        dcm__i_sw = fcm__o_sw;
        fcm__i_sc = detect__o_sc;
        fcm__i_ns = detect__o_ns;
        fcm__i_chk_ok = sfc__o_chk_ok;
        fcm__i_chk_sw = sfc__o_chk_sw;
        fcm__i_fault_a = dcm__o_fault_a;
        fcm__i_fault_b = dcm__o_fault_b;
        fcm__i_bad_a = dcm__o_bad_a;
        fcm__i_bad_b = dcm__o_bad_b;
        fcm__i_act = dcm__o_act;
        fcm__i_in_frame = dcm__o_in_frame;
        status = (({5'h0, fcm__o_state}) | 8'h0) << 4;
        if (dcm__o_act) begin
            status = status | 8'h80;
        end
        if (fcm__o_state == 3'h2) begin
            status = status | 8'h8;
        end
        if (~dcm__o_bad_b) begin
            status = status | 8'h4;
        end
        if (~dcm__o_bad_a) begin
            status = status | 8'h2;
        end
        if (i_host_ok) begin
            status = status | 8'h1;
        end
        sfp__i_status = status;
        sfc__i_bad_a = dcm__o_bad_a;
        sfc__i_bad_b = dcm__o_bad_b;
        sfc__i_act = dcm__o_act;
        o_nm_word = sfc__o_nm_word;
        o_nm_valid = sfc__o_nm_valid;
        o_tx_a = dcm__o_tx_a;
        o_tx_b = dcm__o_tx_b;
        o_rx = dcm__o_rx;
        o_act = dcm__o_act;
        o_state = fcm__o_state;
        o_cause = fcm__o_cause;
        o_irq = fcm__o_irq | sfc__o_rise;
        o_sf_pend = sfp__o_sf_pend;
        o_sf_word = sfp__o_sf_word;
        o_cmd_req = fcm__o_cmd_req;
        o_cmd_ch = fcm__o_cmd_ch;
        o_stat_a = dcm__o_stat_a;
        o_stat_b = dcm__o_stat_b;
        o_stale = sfc__o_stale;
        o_chk_ok = sfc__o_chk_ok;
        o_chk_sw = sfc__o_chk_sw;
        o_ev_seen = detect__o_ev_seen;
    end

endmodule // merkur_dcm_station
// --------------------------------------------------------------------------
// `dcm`: Dcm, Dual Channel Manager. (rtl/src/tokenbus/dcm.rs)
//
// # dcm — IEEE 802.4 Dual Channel Manager (docs/protocol.md §18)
//
// Purpose: one station's two physical channels (bus cables A and B) behind
// one token-bus MAC. The MAC's symbol goes out on **both** PHYs (unless the
// jabber inhibit is on); the MAC receives from the **active** channel only.
// A status register per channel holds what a PHY can observe.
//
// The interface is octet-wide: one symbol per clock (one clock = one octet
// time), bits 10:8 the kind (0 silence, 1 start delimiter, 2 data octet in
// bits 7:0, 3 end delimiter, 4 noise/collision/framing error).
//
// Per channel, every octet:
// - **divergence**: the other channel carries a frame symbol (SD, data, ED)
//   and this one carries something else — this channel lost or garbled
//   what every transmitter sent on both;
// - **silence**: no carrier for [`SIL_LIMIT`] octets (`sil` saturates);
// - `o_fault_*` (combinational) = divergence | silence;
// - `bad` (registered) is set by a fault and cleared after `i_good_limit`
//   fault-free octets; framing errors (kind 4) are counted (saturating).
//
// Switching: `i_sw` toggles the active channel **in this octet**: the
// symbol delivered next clock already comes from the new channel, so a
// fault switch (the fault correction machine answers a divergence in the
// same octet) hands the MAC the standby's copy of the frame without a gap;
// commanded switches are timed by the machine to fall between frames
// (`o_in_frame`).
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_rx_a`, `i_rx_b` | in | 11 | symbols from PHY A / B |
// | `i_tx` | in | 11 | symbol from the MAC |
// | `i_sw` | in | 1 | toggle the active channel now |
// | `i_good_limit` | in | 16 | fault-free octets before a channel is good again |
// | `o_tx_a`, `o_tx_b` | out | 11 | to PHY A / B (combinational: `i_tx`, or silence while jabbering) |
// | `o_rx` | out | 11 | to the MAC: the active channel, one octet late |
// | `o_act` | out | 1 | active channel (0 A, 1 B) |
// | `o_fault_a`, `o_fault_b` | out | 1 | combinational fault of this octet |
// | `o_bad_a`, `o_bad_b` | out | 1 | latched channel fault |
// | `o_in_frame` | out | 1 | the MAC is inside a frame (SD delivered, no ED yet) |
// | `o_stat_a`, `o_stat_b` | out | 16 | status register: `errors[15:8]`, `carrier[3]`, `jabber[2]`, `silent[1]`, `bad[0]` |
//
// Latency: `o_rx` one octet after the symbol on the wire; a fault is seen
// in the octet it happens (`o_fault_*`), latched one octet later.
//
// ```text
// octet      n      n+1    n+2
// i_rx_a     D5     --     --        A dies after octet n
// i_rx_b     D5     D6     D7
// o_fault_a  0      1      1
// i_sw       0      1      0         (from the fault correction machine)
// o_act      A      A      B
// o_rx       ..     D5     D6   D7   the MAC misses nothing
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station__dcm(clock,i_rx_a,i_rx_b,i_tx,i_sw,i_good_limit,o_tx_a,o_tx_b,o_rx,o_act,o_fault_a,o_fault_b,o_bad_a,o_bad_b,o_in_frame,o_stat_a,o_stat_b);

    // Module arguments
    input wire  clock;
    input wire  [10:0] i_rx_a;
    input wire  [10:0] i_rx_b;
    input wire  [10:0] i_tx;
    input wire  i_sw;
    input wire  [15:0] i_good_limit;
    output reg  [10:0] o_tx_a;
    output reg  [10:0] o_tx_b;
    output reg  [10:0] o_rx;
    output reg  o_act;
    output reg  o_fault_a;
    output reg  o_fault_b;
    output reg  o_bad_a;
    output reg  o_bad_b;
    output reg  o_in_frame;
    output reg  [15:0] o_stat_a;
    output reg  [15:0] o_stat_b;

    // Constant declarations
    localparam  sil_limit = 8'h88;
    localparam  jab_limit = 8'h80;

    // Registers and child block ports
    reg  act_d;
    reg  act_q;
    reg  [10:0] rx_d;
    reg  [10:0] rx_q;
    reg  in_frame_d;
    reg  in_frame_q;
    reg  [7:0] tx_cnt_d;
    reg  [7:0] tx_cnt_q;
    reg  [7:0] sil_a_d;
    reg  [7:0] sil_a_q;
    reg  [7:0] sil_b_d;
    reg  [7:0] sil_b_q;
    reg  [15:0] good_a_d;
    reg  [15:0] good_a_q;
    reg  [15:0] good_b_d;
    reg  [15:0] good_b_q;
    reg  bad_a_d;
    reg  bad_a_q;
    reg  bad_b_d;
    reg  bad_b_q;
    reg  [7:0] err_a_d;
    reg  [7:0] err_a_q;
    reg  [7:0] err_b_d;
    reg  [7:0] err_b_q;
    reg  car_a_d;
    reg  car_a_q;
    reg  car_b_d;
    reg  car_b_q;

    // Local signals
    reg  [2:0] kind_a;
    reg  [2:0] kind_b;
    reg  fault_a;
    reg  fault_b;
    reg  [15:0] good_a_n;
    reg  [15:0] good_b_n;
    reg  jab;
    reg  act_n;
    reg  [10:0] deliv;
    reg  [15:0] stat_a;
    reg  [15:0] stat_b;

    // Combinational logic
    always @(*) begin
        act_d = act_q;
        rx_d = rx_q;
        in_frame_d = in_frame_q;
        tx_cnt_d = tx_cnt_q;
        sil_a_d = sil_a_q;
        sil_b_d = sil_b_q;
        good_a_d = good_a_q;
        good_b_d = good_b_q;
        bad_a_d = bad_a_q;
        bad_b_d = bad_b_q;
        err_a_d = err_a_q;
        err_b_d = err_b_q;
        car_a_d = car_a_q;
        car_b_d = car_b_q;
        kind_a = i_rx_a[(8)+:(3)];
        kind_b = i_rx_b[(8)+:(3)];
        fault_a = ((kind_b != 3'h0) & (kind_b < 3'h4) & (i_rx_a != i_rx_b)) | (sil_a_q == sil_limit);
        fault_b = ((kind_a != 3'h0) & (kind_a < 3'h4) & (i_rx_b != i_rx_a)) | (sil_b_q == sil_limit);
        if (i_rx_a != 11'h0) begin
            sil_a_d = 8'h0;
        end
        else if (sil_a_q != sil_limit) begin
            sil_a_d = sil_a_q + 8'h1;
        end
        if (i_rx_b != 11'h0) begin
            sil_b_d = 8'h0;
        end
        else if (sil_b_q != sil_limit) begin
            sil_b_d = sil_b_q + 8'h1;
        end
        if (fault_a) begin
            good_a_n = 16'h0;
        end
        else if (good_a_q >= i_good_limit) begin
            good_a_n = i_good_limit;
        end
        else begin
            good_a_n = good_a_q + 16'h1;
        end
        if (fault_b) begin
            good_b_n = 16'h0;
        end
        else if (good_b_q >= i_good_limit) begin
            good_b_n = i_good_limit;
        end
        else begin
            good_b_n = good_b_q + 16'h1;
        end
        good_a_d = good_a_n;
        good_b_d = good_b_n;
        bad_a_d = fault_a | (bad_a_q & (good_a_n != i_good_limit));
        bad_b_d = fault_b | (bad_b_q & (good_b_n != i_good_limit));
        if ((kind_a == 3'h4) & (err_a_q != 8'hff)) begin
            err_a_d = err_a_q + 8'h1;
        end
        if ((kind_b == 3'h4) & (err_b_q != 8'hff)) begin
            err_b_d = err_b_q + 8'h1;
        end
        car_a_d = i_rx_a != 11'h0;
        car_b_d = i_rx_b != 11'h0;
        jab = tx_cnt_q == jab_limit;
        if (i_tx == 11'h0) begin
            tx_cnt_d = 8'h0;
        end
        else if (~jab) begin
            tx_cnt_d = tx_cnt_q + 8'h1;
        end
        if (jab) begin
            o_tx_a = 11'h0;
            o_tx_b = 11'h0;
        end
        else begin
            o_tx_a = i_tx;
            o_tx_b = i_tx;
        end
        act_n = act_q ^ i_sw;
        act_d = act_n;
        if (act_n) begin
            deliv = i_rx_b;
        end
        else begin
            deliv = i_rx_a;
        end
        rx_d = deliv;
        if (deliv[(8)+:(3)] == 3'h1) begin
            in_frame_d = 1'b1;
        end
        else if (deliv[(8)+:(3)] != 3'h2) begin
            in_frame_d = 1'b0;
        end
        o_rx = rx_q;
        o_act = act_q;
        o_fault_a = fault_a;
        o_fault_b = fault_b;
        o_bad_a = bad_a_q;
        o_bad_b = bad_b_q;
        o_in_frame = in_frame_q;
        stat_a = (({8'h0, err_a_q}) | 16'h0) << 8;
        stat_b = (({8'h0, err_b_q}) | 16'h0) << 8;
        if (car_a_q) begin
            stat_a = stat_a | 16'h8;
        end
        if (car_b_q) begin
            stat_b = stat_b | 16'h8;
        end
        if (jab) begin
            stat_a = stat_a | 16'h4;
            stat_b = stat_b | 16'h4;
        end
        if (sil_a_q == sil_limit) begin
            stat_a = stat_a | 16'h2;
        end
        if (sil_b_q == sil_limit) begin
            stat_b = stat_b | 16'h2;
        end
        if (bad_a_q) begin
            stat_a = stat_a | 16'h1;
        end
        if (bad_b_q) begin
            stat_b = stat_b | 16'h1;
        end
        o_stat_a = stat_a;
        o_stat_b = stat_b;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial act_q = 1'h0;
    always @(posedge clock) act_q <= act_d;
    initial rx_q = 11'h0;
    always @(posedge clock) rx_q <= rx_d;
    initial in_frame_q = 1'h0;
    always @(posedge clock) in_frame_q <= in_frame_d;
    initial tx_cnt_q = 8'h0;
    always @(posedge clock) tx_cnt_q <= tx_cnt_d;
    initial sil_a_q = 8'h0;
    always @(posedge clock) sil_a_q <= sil_a_d;
    initial sil_b_q = 8'h0;
    always @(posedge clock) sil_b_q <= sil_b_d;
    initial good_a_q = 16'h0;
    always @(posedge clock) good_a_q <= good_a_d;
    initial good_b_q = 16'h0;
    always @(posedge clock) good_b_q <= good_b_d;
    initial bad_a_q = 1'h0;
    always @(posedge clock) bad_a_q <= bad_a_d;
    initial bad_b_q = 1'h0;
    always @(posedge clock) bad_b_q <= bad_b_d;
    initial err_a_q = 8'h0;
    always @(posedge clock) err_a_q <= err_a_d;
    initial err_b_q = 8'h0;
    always @(posedge clock) err_b_q <= err_b_d;
    initial car_a_q = 1'h0;
    always @(posedge clock) car_a_q <= car_a_d;
    initial car_b_q = 1'h0;
    always @(posedge clock) car_b_q <= car_b_d;
endmodule // merkur_dcm_station__dcm
// --------------------------------------------------------------------------
// `detect`: RmmDetect, Fault detection from MAC events. (rtl/src/tokenbus/rmm_detect.rs)
//
// # rmm_detect — fault detection from the MAC's events (docs/protocol.md §19)
//
// Purpose: the paper's Fault Detection Sub-module. Of the token-bus MAC's
// event interrupts it uses six: new_successor, won_contention and
// hear_successor make **SC** (the logical ring's configuration changed);
// initialize, exit_ring and no_successor_8 make **NS**. The events seen are
// kept (sticky) for the report to the network manager.
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_ev` | in | 6 | event pulses: bit 0 new_successor, 1 won_contention, 2 hear_successor, 3 initialize, 4 exit_ring, 5 no_successor_8 |
// | `o_sc` | out | 1 | SC this octet (combinational) |
// | `o_ns` | out | 1 | NS this octet (combinational) |
// | `o_ev_seen` | out | 6 | events seen since power-on (registered) |
//
// Latency: `o_sc`/`o_ns` in the octet of the event; `o_ev_seen` one octet later.
//
// ```text
// i_ev       000000  000100  000000
// o_sc       0       1       0
// o_ev_seen  000000  000000  000100
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station__detect(clock,i_ev,o_sc,o_ns,o_ev_seen);

    // Module arguments
    input wire  clock;
    input wire  [5:0] i_ev;
    output reg  o_sc;
    output reg  o_ns;
    output reg  [5:0] o_ev_seen;

    // Registers and child block ports
    reg  [5:0] seen_d;
    reg  [5:0] seen_q;

    // Combinational logic
    always @(*) begin
        seen_d = seen_q;
        o_sc = i_ev[(0)+:(3)] != 3'h0;
        o_ns = i_ev[(3)+:(3)] != 3'h0;
        seen_d = seen_q | i_ev;
        o_ev_seen = seen_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial seen_q = 6'h0;
    always @(posedge clock) seen_q <= seen_d;
endmodule // merkur_dcm_station__detect
// --------------------------------------------------------------------------
// `fcm`: RmmFcm, The fault correction machine. (rtl/src/tokenbus/rmm_fcm.rs)
//
// # rmm_fcm — the fault correction machine (docs/protocol.md §21)
//
// Purpose: the paper's Fault Correction Sub-module: exactly five states
// and the transitions of its section 3, one octet per step. Priorities
// (first match wins):
//
// | from | condition | to | action / cause |
// |---|---|---|---|
// | any but IDLE | both channels bad | IDLE | `both`; pending commands dropped |
// | IDLE | initialised (`i_init`) and not both bad | Manual_Normal | `init` |
// | Manual_Normal | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
// | Manual_Normal | Status Check = OK | Auto_Normal | `check_ok` |
// | Manual_Normal | AUTO_SW_MODE | Auto_Normal | `auto_cmd` |
// | Manual_Normal | Status Check = SWITCH | Manual_Normal | switch to the standby between frames; `check_sw` |
// | Auto_Normal | active fault or NS, standby faulty | Manual_Normal | `standby_fault` |
// | Auto_Normal | active fault or NS | Medium_Error | switch **now**; `active_fault` / `ns` |
// | Auto_Normal | standby faulty | Manual_Normal | dual mode off; `standby_fault` |
// | Auto_Normal | SC | Config_Error | broadcast the switch command; `sc` |
// | Auto_Normal | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
// | Auto_Normal | Status Check = SWITCH | Manual_Normal | switch to the standby between frames; `check_sw` |
// | Medium_Error | — | Manual_Normal | `switched` |
// | Config_Error | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
// | Config_Error | own command sent | Manual_Normal | switch between frames; `cmd_sent` |
//
// "Active fault" is the DCM's combinational fault of the active channel
// this octet; "standby faulty" its combinational fault or latched `bad`.
// A commanded switch (a switch command, or the status check's switch)
// waits while the MAC is inside a frame (`i_in_frame`) and never falls in
// the octet of a fault switch. Every transition or
// command writes the cause register and raises the report interrupt
// (`o_irq`, one octet).
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_init`, `i_auto` | in | 1 | host: initialised (level), AUTO_SW_MODE (pulse) |
// | `i_sc`, `i_ns` | in | 1 | from rmm_detect |
// | `i_chk_ok`, `i_chk_sw` | in | 1 | from rmm_sfc: Status Check = OK, = SWITCH |
// | `i_fault_a`, `i_fault_b`, `i_bad_a`, `i_bad_b`, `i_act`, `i_in_frame` | in | 1 | from the DCM |
// | `i_cmd_rx`, `i_cmd_ch` | in | 1 | MAC: switch command received, its target |
// | `i_cmd_sent` | in | 1 | MAC: our command went out |
// | `o_sw` | out | 1 | to the DCM: toggle the active channel now (combinational) |
// | `o_state` | out | 3 | 0 IDLE, 1 Manual_Normal, 2 Auto_Normal, 3 Config_Error, 4 Medium_Error |
// | `o_cause` | out | 4 | report register: cause of the last transition or command |
// | `o_irq` | out | 1 | report interrupt |
// | `o_cmd_req`, `o_cmd_ch` | out | 1 | to the MAC: broadcast the switch command to this channel |
//
// Latency: the state changes one octet after its condition; a fault switch
// takes effect in the octet of the fault.
//
// ```text
// octet      n            n+1           n+2
// i_fault_a  1 (A active)
// o_sw       1
// o_state    Auto_Normal  Medium_Error  Manual_Normal
// i_act      A            B             B
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station__fcm(clock,i_init,i_auto,i_sc,i_ns,i_chk_ok,i_chk_sw,i_fault_a,i_fault_b,i_bad_a,i_bad_b,i_act,i_in_frame,i_cmd_rx,i_cmd_ch,i_cmd_sent,o_sw,o_state,o_cause,o_irq,o_cmd_req,o_cmd_ch);

    // Module arguments
    input wire  clock;
    input wire  i_init;
    input wire  i_auto;
    input wire  i_sc;
    input wire  i_ns;
    input wire  i_chk_ok;
    input wire  i_chk_sw;
    input wire  i_fault_a;
    input wire  i_fault_b;
    input wire  i_bad_a;
    input wire  i_bad_b;
    input wire  i_act;
    input wire  i_in_frame;
    input wire  i_cmd_rx;
    input wire  i_cmd_ch;
    input wire  i_cmd_sent;
    output reg  o_sw;
    output reg  [2:0] o_state;
    output reg  [3:0] o_cause;
    output reg  o_irq;
    output reg  o_cmd_req;
    output reg  o_cmd_ch;

    // Constant declarations
    localparam  s_idle = 3'b0;
    localparam  s_manual = 3'b1;
    localparam  s_auto = 3'b10;
    localparam  s_config = 3'b11;
    localparam  s_medium = 3'b100;
    localparam  c_init = 4'h1;
    localparam  c_check_ok = 4'h2;
    localparam  c_auto_cmd = 4'h3;
    localparam  c_active_fault = 4'h4;
    localparam  c_ns = 4'h5;
    localparam  c_standby_fault = 4'h6;
    localparam  c_sc = 4'h7;
    localparam  c_cmd_rx = 4'h8;
    localparam  c_cmd_sent = 4'h9;
    localparam  c_switched = 4'ha;
    localparam  c_both = 4'hb;
    localparam  c_check_sw = 4'hc;

    // Registers and child block ports
    reg  [2:0] st_d;
    reg  [2:0] st_q;
    reg  [3:0] cause_d;
    reg  [3:0] cause_q;
    reg  irq_d;
    reg  irq_q;
    reg  pend_d;
    reg  pend_q;
    reg  pend_ch_d;
    reg  pend_ch_q;
    reg  cmd_req_d;
    reg  cmd_req_q;
    reg  cmd_ch_d;
    reg  cmd_ch_q;

    // Local signals
    reg  f_act;
    reg  f_stb;
    reg  b_stb;
    reg  both;
    reg  cs_set;
    reg  [3:0] cs;
    reg  new_cmd;
    reg  sw_now;
    reg  sw_cmd;

    // Combinational logic
    always @(*) begin
        st_d = st_q;
        cause_d = cause_q;
        irq_d = irq_q;
        pend_d = pend_q;
        pend_ch_d = pend_ch_q;
        cmd_req_d = cmd_req_q;
        cmd_ch_d = cmd_ch_q;
        if (i_act) begin
            f_act = i_fault_b;
            f_stb = i_fault_a;
            b_stb = i_bad_a;
        end
        else begin
            f_act = i_fault_a;
            f_stb = i_fault_b;
            b_stb = i_bad_b;
        end
        both = i_bad_a & i_bad_b;
        cs_set = 1'b0;
        cs = cause_q;
        new_cmd = 1'b0;
        sw_now = 1'b0;
        if ((st_q != s_idle) & both) begin
            st_d = s_idle;
            cs_set = 1'b1;
            cs = c_both;
            pend_d = 1'b0;
            cmd_req_d = 1'b0;
        end
        else if (st_q == s_idle) begin
            if (i_init & ~both) begin
                st_d = s_manual;
                cs_set = 1'b1;
                cs = c_init;
            end
        end
        else if (st_q == s_manual) begin
            if (i_cmd_rx) begin
                pend_d = 1'b1;
                pend_ch_d = i_cmd_ch;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_cmd_rx;
            end
            else if (i_chk_ok) begin
                st_d = s_auto;
                cs_set = 1'b1;
                cs = c_check_ok;
            end
            else if (i_auto) begin
                st_d = s_auto;
                cs_set = 1'b1;
                cs = c_auto_cmd;
            end
            else if (i_chk_sw) begin
                pend_d = 1'b1;
                pend_ch_d = ~i_act;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_check_sw;
            end
        end
        else if (st_q == s_auto) begin
            if (f_act | i_ns) begin
                cs_set = 1'b1;
                if (f_stb | b_stb) begin
                    st_d = s_manual;
                    cs = c_standby_fault;
                end
                else begin
                    st_d = s_medium;
                    sw_now = 1'b1;
                    if (f_act) begin
                        cs = c_active_fault;
                    end
                    else begin
                        cs = c_ns;
                    end
                end
            end
            else if (f_stb | b_stb) begin
                st_d = s_manual;
                cs_set = 1'b1;
                cs = c_standby_fault;
            end
            else if (i_sc) begin
                st_d = s_config;
                cs_set = 1'b1;
                cs = c_sc;
                cmd_req_d = 1'b1;
                cmd_ch_d = ~i_act;
            end
            else if (i_cmd_rx) begin
                st_d = s_manual;
                pend_d = 1'b1;
                pend_ch_d = i_cmd_ch;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_cmd_rx;
            end
            else if (i_chk_sw) begin
                st_d = s_manual;
                pend_d = 1'b1;
                pend_ch_d = ~i_act;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_check_sw;
            end
        end
        else if (st_q == s_medium) begin
            st_d = s_manual;
            cs_set = 1'b1;
            cs = c_switched;
        end
        else if (st_q == s_config) begin
            if (i_cmd_rx) begin
                st_d = s_manual;
                cmd_req_d = 1'b0;
                pend_d = 1'b1;
                pend_ch_d = i_cmd_ch;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_cmd_rx;
            end
            else if (i_cmd_sent) begin
                st_d = s_manual;
                cmd_req_d = 1'b0;
                pend_d = 1'b1;
                pend_ch_d = cmd_ch_q;
                new_cmd = 1'b1;
                cs_set = 1'b1;
                cs = c_cmd_sent;
            end
        end
        sw_cmd = 1'b0;
        if (pend_q & ~i_in_frame & ~sw_now) begin
            sw_cmd = pend_ch_q != i_act;
            if (~new_cmd) begin
                pend_d = 1'b0;
            end
        end
        o_sw = sw_now | sw_cmd;
        cause_d = cs;
        irq_d = cs_set;
        o_state = st_q;
        o_cause = cause_q;
        o_irq = irq_q;
        o_cmd_req = cmd_req_q;
        o_cmd_ch = cmd_ch_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial st_q = 3'h0;
    always @(posedge clock) st_q <= st_d;
    initial cause_q = 4'h0;
    always @(posedge clock) cause_q <= cause_d;
    initial irq_q = 1'h0;
    always @(posedge clock) irq_q <= irq_d;
    initial pend_q = 1'h0;
    always @(posedge clock) pend_q <= pend_d;
    initial pend_ch_q = 1'h0;
    always @(posedge clock) pend_ch_q <= pend_ch_d;
    initial cmd_req_q = 1'h0;
    always @(posedge clock) cmd_req_q <= cmd_req_d;
    initial cmd_ch_q = 1'h0;
    always @(posedge clock) cmd_ch_q <= cmd_ch_d;
endmodule // merkur_dcm_station__fcm
// --------------------------------------------------------------------------
// `sfc`: RmmSfc, Status frame check. (rtl/src/tokenbus/rmm_sfc.rs)
//
// # rmm_sfc — status frame check (docs/protocol.md §20)
//
// Purpose: the paper's Status Frame Check Sub-module. Every received status
// frame is written into block RAM by its source address: **3 bytes per
// station** — the 2 status bytes of the latest frame (`st`, 32 × 16) and the
// live counter seen at the previous check (`prev`, 32 × 8). Every
// `i_chk_period` octets a scan visits the 32 addresses, one per octet
// (34 octets with the read latency): a configured station (`i_stations`,
// not this one) whose live counter has not moved since the last scan is
// flagged **stale**; the scan ends with **Status Check = OK** (`o_chk_ok`,
// one octet) when no station is stale, every station reports both channels
// good, and this station's own channels are good (`i_bad_a`, `i_bad_b`
// clear). The same scan is the backup fault detector: it collects, per
// channel, whether a fresh (not stale) configured station reports it not
// good, and ends with **Status Check = SWITCH** (`o_chk_sw`, one octet) when
// the active channel (`i_act`) is suspect — own `bad` or a fresh report —
// and the standby is clear — own `bad` clear and no fresh report.
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_chk_period` | in | 16 | check period, octets (≥ 64) |
// | `i_addr` | in | 5 | own address |
// | `i_stations` | in | 32 | configured stations (bit per address) |
// | `i_bad_a`, `i_bad_b` | in | 1 | own channels faulty (the DCM's latched `bad`) |
// | `i_act` | in | 1 | own active channel (0 A, 1 B) |
// | `i_rx_sf` | in | 1 | a valid status frame was received |
// | `i_rx_sa` | in | 8 | its source address (≥ 32 ignored) |
// | `i_rx_sfw` | in | 16 | its status bytes |
// | `o_stale` | out | 32 | stations whose live counter stopped |
// | `o_chk_ok` | out | 1 | Status Check = OK |
// | `o_chk_sw` | out | 1 | Status Check = SWITCH (protocol §20) |
// | `o_rise` | out | 1 | a station became stale (report interrupt) |
// | `i_nm_addr` | in | 5 | network manager: station whose stored status to read between scans |
// | `o_nm_word`, `o_nm_valid` | out | 16/1 | its latest status frame, one octet later; valid outside scans |
//
// Latency: a scan starts the octet after the period ends; station k's
// verdict is registered at octet k+2 of the scan, `o_chk_ok` and
// `o_chk_sw` after k = 31.
//
// ```text
// octet     0(start) 1      2      ..     33     34
// read      -        st[0]  st[1]  ..     st[31]
// verdict   -        -      s0     ..     s30    s31, o_chk_ok / o_chk_sw
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station__sfc(clock,i_chk_period,i_addr,i_stations,i_bad_a,i_bad_b,i_act,i_rx_sf,i_rx_sa,i_rx_sfw,o_stale,o_chk_ok,o_chk_sw,o_rise,i_nm_addr,o_nm_word,o_nm_valid);

    // Module arguments
    input wire  clock;
    input wire  [15:0] i_chk_period;
    input wire  [4:0] i_addr;
    input wire  [31:0] i_stations;
    input wire  i_bad_a;
    input wire  i_bad_b;
    input wire  i_act;
    input wire  i_rx_sf;
    input wire  [7:0] i_rx_sa;
    input wire  [15:0] i_rx_sfw;
    output reg  [31:0] o_stale;
    output reg  o_chk_ok;
    output reg  o_chk_sw;
    output reg  o_rise;
    input wire  [4:0] i_nm_addr;
    output reg  [15:0] o_nm_word;
    output reg  o_nm_valid;

    // Registers and child block ports
    reg  [4:0] st__read_address;
    wire  [15:0] st__read_data;
    reg  [4:0] st__write_address;
    reg  st__write_enable;
    reg  [4:0] prev__read_address;
    wire  [7:0] prev__read_data;
    reg  [4:0] prev__write_address;
    reg  [7:0] prev__write_data;
    reg  prev__write_enable;
    reg  [15:0] cnt_d;
    reg  [15:0] cnt_q;
    reg  scanning_d;
    reg  scanning_q;
    reg  [4:0] scan_i_d;
    reg  [4:0] scan_i_q;
    reg  s2_valid_d;
    reg  s2_valid_q;
    reg  [4:0] s2_i_d;
    reg  [4:0] s2_i_q;
    reg  all_ok_d;
    reg  all_ok_q;
    reg  a_bad_d;
    reg  a_bad_q;
    reg  b_bad_d;
    reg  b_bad_q;
    reg  [31:0] stale_d;
    reg  [31:0] stale_q;
    reg  chk_ok_d;
    reg  chk_ok_q;
    reg  chk_sw_d;
    reg  chk_sw_q;
    reg  rise_d;
    reg  rise_q;
    reg  nm_valid_d;
    reg  nm_valid_q;

    // Local signals
    reg  [16:0] cnt_p1;
    reg  member;
    reg  stale_k;
    reg  good_k;
    reg  all_ok_n;
    reg  fresh;
    reg  a_bad_n;
    reg  b_bad_n;
    reg  suspect;
    reg  clear;
    reg  [31:0] stale_n;
    reg  [31:0] mask;

    // Child blocks
    merkur_dcm_station__sfc__st st(
        .read_address(st__read_address),
        .read_clock(clock),
        .read_data(st__read_data),
        .write_address(st__write_address),
        .write_clock(clock),
        .write_data(i_rx_sfw),
        .write_enable(st__write_enable)
    );
    merkur_dcm_station__sfc__prev prev(
        .read_address(prev__read_address),
        .read_clock(clock),
        .read_data(prev__read_data),
        .write_address(prev__write_address),
        .write_clock(clock),
        .write_data(prev__write_data),
        .write_enable(prev__write_enable)
    );

    // Combinational logic
    always @(*) begin
        cnt_d = cnt_q;
        scanning_d = scanning_q;
        scan_i_d = scan_i_q;
        s2_valid_d = s2_valid_q;
        s2_i_d = s2_i_q;
        all_ok_d = all_ok_q;
        a_bad_d = a_bad_q;
        b_bad_d = b_bad_q;
        stale_d = stale_q;
        chk_ok_d = chk_ok_q;
        chk_sw_d = chk_sw_q;
        rise_d = rise_q;
        nm_valid_d = nm_valid_q;
        st__write_enable = i_rx_sf & (i_rx_sa < 8'h20);
        st__write_address = i_rx_sa[(0)+:(5)];
        cnt_p1 = ({1'h0, cnt_q}) + 17'h1;
        if (cnt_p1 >= ({1'h0, i_chk_period})) begin
            cnt_d = 16'h0;
            scanning_d = 1'b1;
            scan_i_d = 5'h0;
        end
        else begin
            cnt_d = cnt_q + 16'h1;
            if (scanning_q) begin
                scanning_d = scan_i_q != 5'h1f;
                scan_i_d = scan_i_q + 5'h1;
            end
        end
        if (scanning_q) begin
            st__read_address = scan_i_q;
        end
        else begin
            st__read_address = i_nm_addr;
        end
        nm_valid_d = ~scanning_q;
        prev__read_address = scan_i_q;
        s2_valid_d = scanning_q;
        s2_i_d = scan_i_q;
        member = (((i_stations >> s2_i_q) & 32'h1) == 32'h1) & (s2_i_q != i_addr);
        stale_k = member & (st__read_data[(8)+:(8)] == prev__read_data);
        good_k = ~member | (~stale_k & st__read_data[1] & st__read_data[2]);
        mask = ((32'h1) & 32'hffffffff) << s2_i_q;
        stale_n = stale_q;
        all_ok_n = all_ok_q;
        chk_ok_d = 1'b0;
        chk_sw_d = 1'b0;
        fresh = member & ~stale_k;
        a_bad_n = a_bad_q;
        b_bad_n = b_bad_q;
        prev__write_enable = 1'b0;
        prev__write_address = s2_i_q;
        prev__write_data = st__read_data[(8)+:(8)];
        if (s2_valid_q) begin
            prev__write_enable = member;
            if (stale_k) begin
                stale_n = stale_q | mask;
            end
            else begin
                stale_n = stale_q & ~mask;
            end
            if (s2_i_q == 5'h0) begin
                all_ok_n = good_k;
            end
            else begin
                all_ok_n = all_ok_q & good_k;
            end
            chk_ok_d = (s2_i_q == 5'h1f) & all_ok_n & ~i_bad_a & ~i_bad_b;
            a_bad_n = fresh & ~st__read_data[1];
            b_bad_n = fresh & ~st__read_data[2];
            if (s2_i_q != 5'h0) begin
                a_bad_n = a_bad_n | a_bad_q;
                b_bad_n = b_bad_n | b_bad_q;
            end
        end
        if (i_act) begin
            suspect = i_bad_b | b_bad_n;
            clear = ~i_bad_a & ~a_bad_n;
        end
        else begin
            suspect = i_bad_a | a_bad_n;
            clear = ~i_bad_b & ~b_bad_n;
        end
        chk_sw_d = s2_valid_q & (s2_i_q == 5'h1f) & suspect & clear;
        a_bad_d = a_bad_n;
        b_bad_d = b_bad_n;
        all_ok_d = all_ok_n;
        stale_d = stale_n;
        rise_d = (stale_n & ~stale_q) != 32'h0;
        o_stale = stale_q;
        o_chk_ok = chk_ok_q;
        o_chk_sw = chk_sw_q;
        o_rise = rise_q;
        o_nm_word = st__read_data;
        o_nm_valid = nm_valid_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial cnt_q = 16'h0;
    always @(posedge clock) cnt_q <= cnt_d;
    initial scanning_q = 1'h0;
    always @(posedge clock) scanning_q <= scanning_d;
    initial scan_i_q = 5'h0;
    always @(posedge clock) scan_i_q <= scan_i_d;
    initial s2_valid_q = 1'h0;
    always @(posedge clock) s2_valid_q <= s2_valid_d;
    initial s2_i_q = 5'h0;
    always @(posedge clock) s2_i_q <= s2_i_d;
    initial all_ok_q = 1'h0;
    always @(posedge clock) all_ok_q <= all_ok_d;
    initial a_bad_q = 1'h0;
    always @(posedge clock) a_bad_q <= a_bad_d;
    initial b_bad_q = 1'h0;
    always @(posedge clock) b_bad_q <= b_bad_d;
    initial stale_q = 32'h0;
    always @(posedge clock) stale_q <= stale_d;
    initial chk_ok_q = 1'h0;
    always @(posedge clock) chk_ok_q <= chk_ok_d;
    initial chk_sw_q = 1'h0;
    always @(posedge clock) chk_sw_q <= chk_sw_d;
    initial rise_q = 1'h0;
    always @(posedge clock) rise_q <= rise_d;
    initial nm_valid_q = 1'h0;
    always @(posedge clock) nm_valid_q <= nm_valid_d;
endmodule // merkur_dcm_station__sfc
// --------------------------------------------------------------------------
// `prev` of `merkur_dcm_station__sfc`: a memory (rust-hdl RAM): written on `write_clock`, read one clock after
// `read_address` on `read_clock`.
// --------------------------------------------------------------------------
module merkur_dcm_station__sfc__prev(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);

    // Module arguments
    input wire  [4:0] read_address;
    input wire  read_clock;
    output reg  [7:0] read_data;
    input wire  [4:0] write_address;
    input wire  write_clock;
    input wire  [7:0] write_data;
    input wire  write_enable;

    // Update code (custom)
    reg[7:0] mem[31:0];
    integer mem_i;
    initial for (mem_i = 0; mem_i <= 31; mem_i = mem_i + 1) mem[mem_i] = 0;

    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end

    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end

endmodule // merkur_dcm_station__sfc__prev
// --------------------------------------------------------------------------
// `st` of `merkur_dcm_station__sfc`: a memory (rust-hdl RAM): written on `write_clock`, read one clock after
// `read_address` on `read_clock`.
// --------------------------------------------------------------------------
module merkur_dcm_station__sfc__st(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);

    // Module arguments
    input wire  [4:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [4:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;

    // Update code (custom)
    reg[15:0] mem[31:0];
    integer mem_i;
    initial for (mem_i = 0; mem_i <= 31; mem_i = mem_i + 1) mem[mem_i] = 0;

    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end

    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end

endmodule // merkur_dcm_station__sfc__st
// --------------------------------------------------------------------------
// `sfp`: RmmSfp, Status frame production. (rtl/src/tokenbus/rmm_sfp.rs)
//
// # rmm_sfp — status frame production (docs/protocol.md §20)
//
// Purpose: the paper's Status Frame Production Sub-module. Every
// `i_sf_period` octets the station's **live counter** advances and a status
// frame becomes due (`o_sf_pend`); the MAC sends it at its next token hold,
// taking `o_sf_word` (live counter, status byte) and pulsing `i_sf_sent`.
// The status byte (host status, both channels' status, dual mode, state,
// active channel) is made by the station top from the live registers.
//
// | port | dir | width | meaning |
// |---|---|---|---|
// | `clock` | in | 1 | octet clock |
// | `i_sf_period` | in | 16 | production period, octets (≥ 2) |
// | `i_sf_sent` | in | 1 | the MAC took the word into a frame |
// | `i_status` | in | 8 | status byte |
// | `o_sf_pend` | out | 1 | a status frame is due |
// | `o_sf_word` | out | 16 | live counter << 8 \| status byte |
//
// Latency: `o_sf_pend` rises one octet after the period ends, falls one
// octet after `i_sf_sent` (unless the next period ends in that octet).
//
// ```text
// octet      P-1    P      ..     s      s+1
// o_sf_pend  0      1      1      1      0
// live       k      k+1    k+1    k+1    k+1
// i_sf_sent  0      0      0      1      0
// ```
// --------------------------------------------------------------------------
module merkur_dcm_station__sfp(clock,i_sf_period,i_sf_sent,i_status,o_sf_pend,o_sf_word);

    // Module arguments
    input wire  clock;
    input wire  [15:0] i_sf_period;
    input wire  i_sf_sent;
    input wire  [7:0] i_status;
    output reg  o_sf_pend;
    output reg  [15:0] o_sf_word;

    // Registers and child block ports
    reg  [15:0] cnt_d;
    reg  [15:0] cnt_q;
    reg  [7:0] live_d;
    reg  [7:0] live_q;
    reg  pend_d;
    reg  pend_q;

    // Local signals
    reg  [16:0] cnt_p1;
    reg  due;

    // Combinational logic
    always @(*) begin
        cnt_d = cnt_q;
        live_d = live_q;
        pend_d = pend_q;
        cnt_p1 = ({1'h0, cnt_q}) + 17'h1;
        due = cnt_p1 >= ({1'h0, i_sf_period});
        if (due) begin
            cnt_d = 16'h0;
            live_d = live_q + 8'h1;
            pend_d = 1'b1;
        end
        else begin
            cnt_d = cnt_q + 16'h1;
            if (i_sf_sent) begin
                pend_d = 1'b0;
            end
        end
        o_sf_pend = pend_q;
        o_sf_word = ((({8'h0, live_q}) | 16'h0) << 8) | (({8'h0, i_status}) | 16'h0);
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial cnt_q = 16'h0;
    always @(posedge clock) cnt_q <= cnt_d;
    initial live_q = 8'h0;
    always @(posedge clock) live_q <= live_d;
    initial pend_q = 1'h0;
    always @(posedge clock) pend_q <= pend_d;
endmodule // merkur_dcm_station__sfp
