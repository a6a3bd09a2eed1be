// merkur_slave.v — the MERKUR slave node (a sensor or an actuator, by its `i_actuator` port)
//
// Generated Verilog; do not edit. Generator: merkur-rtl 0.1.0 (rust-hdl 0.46.0),
// from rtl/src/node/slave.rs. `cargo run -p merkur-sim --example gen` rewrites this file and
// sim/tests/gen.rs fails when it drifts from the generator.
//
// Top module: merkur_slave. Build parameters: none.
// Every other setting is a port (the port table is in the header of module merkur_slave
// below). Clock: `clock`, twice the line rate (100 MHz for 50 Mbit/s); the fibre
// inputs take 4 samples per clock (quadrature DDR capture), the outputs give a DDR
// pair (docs/protocol.md §9; `merkur_ddr_in`/`merkur_ddr_out` in rtl/src/top/synth_top.rs).
// Lint: verilator --lint-only -Wall waivers.vlt merkur_slave.v --top-module merkur_slave

// --------------------------------------------------------------------------
// Slave: Slave node. (rtl/src/node/slave.rs)
//
// # slave — the MERKUR slave node (the paper's Figure 6)
//
// Purpose: one sensor or actuator node: the switchbox (Table 1), a
// supervised receive port on INPUT and on BSR (clock recovery, framer,
// words, stream controllers), the cut-through forwarder (slot shift
// register) from INPUT to OUTPUT, the secondary pass-through (BSR → BSS in
// mode N, retimed; a TST from a neighbour is cut after its H0, protocol §9)
// or the link-test generator (BSS in modes WU, WD), the mode and
// failsafe logic (protocol §10, §12; after every switchbox change both
// outputs are dark for 12 bit times, [`crate::node::sw_dark`]), the
// interrupt/alarm queue (§11) with confirmed delivery (the alarm in flight
// is read back at INPUT in the next frame and sent again, same SEQ, if it
// did not come round good), the
// actuator's output register and the error counters. A [`crate::node::master`]
// is this block with `i_master` = 1 and a database beside it.
//
// Retransmission on demand (protocol §8): the forwarder fills a sensor's
// requests and puts an actuator's Alive into its copy; an actuator takes
// a good copy of its slot from an RTX into its output register (no Alive
// check), and an RTX's bad request words count in `o_perr`.
//
// Parameters: the word format ([`WordFormat`], protocol §4 or §6), for
// its receive ports, forwarder and TST generator; in the extended-alarm
// variant an alarm's SEQ is read back from the reason nibble and an
// actuator takes an alarm word's data into its output register.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_pi`, `i_si` | in | 4 | clock | physical inputs, 4 samples per clock (quadrature DDR); with `i_cap_sel` INPUT's and BSR's |
// | `i_cap_sel` | in | 1 | static | 0: the switchbox chooses INPUT and BSR from `i_pi` and `i_si`; 1: the capture register in front already did, by `o_cap_si` (below) |
// | `o_cap_si` | out | 1 | clock | for a capture register that makes the switchbox's input choice: take SI as INPUT and PI as BSR in this clock (the mode in the next clock is WU; a register) |
// | `o_po`, `o_so` | out | 2 | clock | physical outputs, DDR pairs |
// | `i_address` | in | 12 | static (DIP switches) | home slot |
// | `i_slots_m1` | in | 12 | static | slots per frame − 1 |
// | `i_actuator` | in | 1 | static | 1 actuator, 0 sensor |
// | `i_cs_timeout` | in | 20 | static | clocks without the start of a packet other than a TST on INPUT before failsafe (3.5 cycle periods, protocol §12 rule 4) |
// | `i_sensor_data` | in | 16 | clock | sensor value |
// | `i_irq1`, `i_irq2`, `i_fs_req` | in | 1 | clock | user requests (a high clock queues the alarm) |
// | `o_act_data` | out | 16 | clock | actuator output register |
// | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD) |
// | `o_failsafe` | out | 1 | clock | failsafe (until a CLR header brings the node out, protocol §12) |
// | `o_perr` | out | 16 | clock | bad words seen at INPUT (saturating) |
// | `o_ferr` | out | 16 | clock | frame errors: rejected headers at INPUT (saturating) |
// | `i_master`, `i_slot_cfg`, `i_slot_data`, `i_slot_alive`, `i_fs_set` | in | 1, 2, 16, 1, 1 | clock | master mode (tied 0 in a slave): see [`crate::node::master`] |
// | `o_fwd_slot`, `o_regen` | out | 12, 1 | clock | master mode: the forwarder's slot, VOID regenerated |
// | `o_wvalid`, `o_kind`, `o_slot`, `o_data`, `o_alive`, `o_alarm`, `o_reason`, `o_ok`, `o_hdr_bad` | out | | clock | INPUT's words (`o_reason`: the extended variant's reason nibble, else 0) and rejected headers, for a master's memories |
// | `o_rtx` | out | 1 | clock | the word is an RTX's copy of slot `o_slot` (its data word after a good index word, as a slot word, `o_kind` = 2; outside failsafe); an RTX's other words do not show (protocol §8) |
//
// Latency: INPUT to OUTPUT 9.5–10.5 bit times from the samples at `i_pi`
// to the line at `o_po` (the CDR, one group and a bit, the retime buffer:
// [`Fwd`]); 10–11 from fibre to fibre with a top's capture register in
// front (`merkur_ddr_in`; measured in the ring, docs/benchmarks.md); BSR to BSS ≈ 3.5 bit times (the CDR
// and [`Retime`]). A switch decision acts two clocks after the receivers'
// report ([`SwitchPipe`]).
//
// ```text
// PI ─┐            ┌─ port_rx (INPUT) ── fwd ── OUTPUT ─┐            ┌─ sw_dark ─ PO
//     ├─ switchbox ┤                                     ├─ switchbox ┤
// SI ─┘            └─ port_rx (BSR) ─ repeater / tst_tx ─ BSS ─┘     └─ sw_dark ─ SO
// ```
// --------------------------------------------------------------------------
module merkur_slave(clock,i_pi,i_si,i_cap_sel,o_cap_si,o_po,o_so,i_address,i_slots_m1,i_actuator,i_cs_timeout,i_sensor_data,i_irq1,i_irq2,i_fs_req,i_master,i_slot_cfg,i_slot_data,i_slot_alive,i_fs_set,o_fwd_slot,o_regen,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_hdr_bad,o_rtx,o_act_data,o_mode,o_failsafe,o_perr,o_ferr);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_pi;
    input wire  [3:0] i_si;
    input wire  i_cap_sel;
    output reg  o_cap_si;
    output reg  [1:0] o_po;
    output reg  [1:0] o_so;
    input wire  [11:0] i_address;
    input wire  [11:0] i_slots_m1;
    input wire  i_actuator;
    input wire  [19:0] i_cs_timeout;
    input wire  [15:0] i_sensor_data;
    input wire  i_irq1;
    input wire  i_irq2;
    input wire  i_fs_req;
    input wire  i_master;
    input wire  [1:0] i_slot_cfg;
    input wire  [15:0] i_slot_data;
    input wire  i_slot_alive;
    input wire  i_fs_set;
    output reg  [11:0] o_fwd_slot;
    output reg  o_regen;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_hdr_bad;
    output reg  o_rtx;
    output reg  [15:0] o_act_data;
    output reg  [1:0] o_mode;
    output reg  o_failsafe;
    output reg  [15:0] o_perr;
    output reg  [15:0] o_ferr;

    // Constant declarations
    localparam  ext = 1'b0;
    localparam  rtx_on = 1'b1;

    // Registers and child block ports
    reg  [1:0] sbox__i_mode;
    reg  [1:0] sbox__i_output;
    reg  [1:0] sbox__i_bss;
    wire  [3:0] sbox__o_input;
    wire  [3:0] sbox__o_bsr;
    wire  [1:0] sbox__o_po;
    wire  [1:0] sbox__o_so;
    reg  dark__i_change;
    reg  dark__i_keep_po;
    reg  [1:0] dark__i_po;
    reg  [1:0] dark__i_so;
    wire  [1:0] dark__o_po;
    wire  [1:0] dark__o_so;
    reg  swc__i_armed;
    reg  swc__i_hard_in;
    reg  swc__i_hard_bsr;
    reg  swc__i_run_in;
    reg  swc__i_run_bsr;
    reg  swc__i_los_in;
    reg  swc__i_los_bsr;
    reg  swc__i_rw;
    reg  swc__i_fs;
    reg  swc__i_tst_ack;
    reg  swc__i_frame_start;
    reg  swc__i_bsr_data;
    reg  swc__i_in_pkt;
    reg  swc__i_tst_in;
    reg  swc__i_tst_bsr;
    reg  swc__i_fwd;
    wire  [1:0] swc__o_mode;
    wire  swc__o_wu_next;
    wire  swc__o_change;
    wire  swc__o_relink;
    wire  swc__o_tst_start;
    wire  swc__o_fs_set;
    wire  swc__o_grace_over;
    reg  [3:0] rx_in__i_samples;
    reg  rx_in__i_tst_fail;
    reg  rx_in__i_flush;
    wire  rx_in__o_start;
    wire  rx_in__o_inpkt;
    wire  rx_in__o_wvalid;
    wire  [1:0] rx_in__o_kind;
    wire  [11:0] rx_in__o_slot;
    wire  [15:0] rx_in__o_data;
    wire  rx_in__o_alive;
    wire  rx_in__o_alarm;
    wire  [3:0] rx_in__o_reason;
    wire  rx_in__o_ok;
    wire  rx_in__o_void;
    wire  rx_in__o_marked;
    wire  rx_in__o_own;
    wire  rx_in__o_hdr_bad;
    wire  [1:0] rx_in__o_ptype;
    wire  rx_in__o_los;
    wire  rx_in__o_bvalid;
    wire  rx_in__o_code;
    wire  [1:0] rx_in__o_phase;
    wire  rx_in__o_cf;
    wire  rx_in__o_hard;
    wire  rx_in__o_run;
    wire  rx_in__o_tst;
    wire  rx_in__o_ack;
    reg  [3:0] rx_bsr__i_samples;
    reg  rx_bsr__i_tst_fail;
    reg  rx_bsr__i_flush;
    wire  rx_bsr__o_start;
    wire  rx_bsr__o_inpkt;
    wire  rx_bsr__o_wvalid;
    wire  [1:0] rx_bsr__o_kind;
    wire  [11:0] rx_bsr__o_slot;
    wire  [15:0] rx_bsr__o_data;
    wire  rx_bsr__o_alive;
    wire  rx_bsr__o_alarm;
    wire  [3:0] rx_bsr__o_reason;
    wire  rx_bsr__o_ok;
    wire  rx_bsr__o_void;
    wire  rx_bsr__o_marked;
    wire  rx_bsr__o_own;
    wire  rx_bsr__o_hdr_bad;
    wire  [1:0] rx_bsr__o_ptype;
    wire  rx_bsr__o_los;
    wire  rx_bsr__o_bvalid;
    wire  rx_bsr__o_code;
    wire  [1:0] rx_bsr__o_phase;
    wire  rx_bsr__o_cf;
    wire  rx_bsr__o_hard;
    wire  rx_bsr__o_run;
    wire  rx_bsr__o_tst;
    wire  rx_bsr__o_ack;
    reg  fwd__i_bvalid;
    reg  fwd__i_code;
    reg  [1:0] fwd__i_phase;
    reg  fwd__i_hdr_bad;
    reg  fwd__i_mute;
    reg  [15:0] fwd__i_act_out;
    reg  fwd__i_fs;
    reg  fwd__i_wrapped;
    reg  fwd__i_alarm_req;
    reg  [3:0] fwd__i_alarm_reason;
    reg  fwd__i_alarm_seq;
    reg  fwd__i_armed;
    reg  fwd__i_wvalid;
    reg  [1:0] fwd__i_wkind;
    reg  fwd__i_wodd;
    reg  fwd__i_wok;
    reg  fwd__i_walarm;
    reg  [15:0] fwd__i_wdata;
    reg  [1:0] fwd__i_ptype;
    wire  [11:0] fwd__o_slot;
    wire  fwd__o_rtx_own;
    wire  [11:0] fwd__o_rtx_idx;
    wire  fwd__o_rtx_ok;
    wire  fwd__o_regen;
    wire  fwd__o_alarm_sent;
    wire  [3:0] fwd__o_sent_reason;
    wire  fwd__o_prev_alarm;
    wire  fwd__o_pkt_done;
    wire  fwd__o_toggle;
    wire  [1:0] fwd__o_line;
    reg  tst__i_ack;
    reg  tst__i_restart;
    wire  [1:0] tst__o_line;
    reg  rep__i_valid;
    reg  rep__i_code;
    reg  [1:0] rep__i_phase;
    wire  [1:0] rep__o_line;
    wire  rep__o_slip;
    reg  rep_cut_d;
    reg  rep_cut_q;
    reg  fwd_cut_d;
    reg  fwd_cut_q;
    reg  failsafe_d;
    reg  failsafe_q;
    reg  rw_d;
    reg  rw_q;
    reg  h0_rwc_d;
    reg  h0_rwc_q;
    reg  sw_flush_d;
    reg  sw_flush_q;
    reg  armed_d;
    reg  armed_q;
    reg  [2:0] last_cyc_d;
    reg  [2:0] last_cyc_q;
    reg  [2:0] ferr_owed_d;
    reg  [2:0] ferr_owed_q;
    reg  [19:0] quiet_d;
    reg  [19:0] quiet_q;
    reg  quiet_max_d;
    reg  quiet_max_q;
    reg  quiet_clr_d;
    reg  quiet_clr_q;
    reg  pend_fs_d;
    reg  pend_fs_q;
    reg  pend_rc_d;
    reg  pend_rc_q;
    reg  pend_i1_d;
    reg  pend_i1_q;
    reg  pend_i2_d;
    reg  pend_i2_q;
    reg  [1:0] fl_k_d;
    reg  [1:0] fl_k_q;
    reg  nxt_d;
    reg  nxt_q;
    reg  [15:0] act_data_d;
    reg  [15:0] act_data_q;
    reg  [15:0] perr_d;
    reg  [15:0] perr_q;
    reg  [15:0] ferr_d;
    reg  [15:0] ferr_q;

    // Local signals
    reg  [2:0] cyc_gap;
    reg  cs_due;
    reg  seq_tx;
    reg  e_rc;
    reg  e_i1;
    reg  [3:0] reason;
    reg  rx_seq;
    reg  wrapped;
    reg  [1:0] out_pair;
    reg  [1:0] bss_pair;

    // Child blocks
    merkur_slave__sbox sbox(
        .i_mode(sbox__i_mode),
        .i_pi(i_pi),
        .i_si(i_si),
        .i_output(sbox__i_output),
        .i_bss(sbox__i_bss),
        .o_input(sbox__o_input),
        .o_bsr(sbox__o_bsr),
        .o_po(sbox__o_po),
        .o_so(sbox__o_so)
    );
    merkur_slave__dark dark(
        .clock(clock),
        .i_change(dark__i_change),
        .i_keep_po(dark__i_keep_po),
        .i_po(dark__i_po),
        .i_so(dark__i_so),
        .o_po(dark__o_po),
        .o_so(dark__o_so)
    );
    merkur_slave__swc swc(
        .clock(clock),
        .i_armed(swc__i_armed),
        .i_hard_in(swc__i_hard_in),
        .i_hard_bsr(swc__i_hard_bsr),
        .i_run_in(swc__i_run_in),
        .i_run_bsr(swc__i_run_bsr),
        .i_los_in(swc__i_los_in),
        .i_los_bsr(swc__i_los_bsr),
        .i_rw(swc__i_rw),
        .i_fs(swc__i_fs),
        .i_tst_ack(swc__i_tst_ack),
        .i_frame_start(swc__i_frame_start),
        .i_bsr_data(swc__i_bsr_data),
        .i_in_pkt(swc__i_in_pkt),
        .i_tst_in(swc__i_tst_in),
        .i_tst_bsr(swc__i_tst_bsr),
        .i_cs_timeout(i_cs_timeout),
        .i_fwd(swc__i_fwd),
        .o_mode(swc__o_mode),
        .o_wu_next(swc__o_wu_next),
        .o_change(swc__o_change),
        .o_relink(swc__o_relink),
        .o_tst_start(swc__o_tst_start),
        .o_fs_set(swc__o_fs_set),
        .o_grace_over(swc__o_grace_over)
    );
    merkur_slave__rx_in rx_in(
        .clock(clock),
        .i_samples(rx_in__i_samples),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .i_tst_fail(rx_in__i_tst_fail),
        .i_flush(rx_in__i_flush),
        .o_start(rx_in__o_start),
        .o_inpkt(rx_in__o_inpkt),
        .o_wvalid(rx_in__o_wvalid),
        .o_kind(rx_in__o_kind),
        .o_slot(rx_in__o_slot),
        .o_data(rx_in__o_data),
        .o_alive(rx_in__o_alive),
        .o_alarm(rx_in__o_alarm),
        .o_reason(rx_in__o_reason),
        .o_ok(rx_in__o_ok),
        .o_void(rx_in__o_void),
        .o_marked(rx_in__o_marked),
        .o_own(rx_in__o_own),
        .o_hdr_bad(rx_in__o_hdr_bad),
        .o_ptype(rx_in__o_ptype),
        .o_los(rx_in__o_los),
        .o_bvalid(rx_in__o_bvalid),
        .o_code(rx_in__o_code),
        .o_phase(rx_in__o_phase),
        .o_cf(rx_in__o_cf),
        .o_hard(rx_in__o_hard),
        .o_run(rx_in__o_run),
        .o_tst(rx_in__o_tst),
        .o_ack(rx_in__o_ack)
    );
    merkur_slave__rx_bsr rx_bsr(
        .clock(clock),
        .i_samples(rx_bsr__i_samples),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .i_tst_fail(rx_bsr__i_tst_fail),
        .i_flush(rx_bsr__i_flush),
        .o_start(rx_bsr__o_start),
        .o_inpkt(rx_bsr__o_inpkt),
        .o_wvalid(rx_bsr__o_wvalid),
        .o_kind(rx_bsr__o_kind),
        .o_slot(rx_bsr__o_slot),
        .o_data(rx_bsr__o_data),
        .o_alive(rx_bsr__o_alive),
        .o_alarm(rx_bsr__o_alarm),
        .o_reason(rx_bsr__o_reason),
        .o_ok(rx_bsr__o_ok),
        .o_void(rx_bsr__o_void),
        .o_marked(rx_bsr__o_marked),
        .o_own(rx_bsr__o_own),
        .o_hdr_bad(rx_bsr__o_hdr_bad),
        .o_ptype(rx_bsr__o_ptype),
        .o_los(rx_bsr__o_los),
        .o_bvalid(rx_bsr__o_bvalid),
        .o_code(rx_bsr__o_code),
        .o_phase(rx_bsr__o_phase),
        .o_cf(rx_bsr__o_cf),
        .o_hard(rx_bsr__o_hard),
        .o_run(rx_bsr__o_run),
        .o_tst(rx_bsr__o_tst),
        .o_ack(rx_bsr__o_ack)
    );
    merkur_slave__fwd fwd(
        .clock(clock),
        .i_bvalid(fwd__i_bvalid),
        .i_code(fwd__i_code),
        .i_phase(fwd__i_phase),
        .i_hdr_bad(fwd__i_hdr_bad),
        .i_mute(fwd__i_mute),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .i_actuator(i_actuator),
        .i_sensor_data(i_sensor_data),
        .i_act_out(fwd__i_act_out),
        .i_fs(fwd__i_fs),
        .i_wrapped(fwd__i_wrapped),
        .i_alarm_req(fwd__i_alarm_req),
        .i_alarm_reason(fwd__i_alarm_reason),
        .i_alarm_seq(fwd__i_alarm_seq),
        .i_master(i_master),
        .i_slot_cfg(i_slot_cfg),
        .i_slot_data(i_slot_data),
        .i_slot_alive(i_slot_alive),
        .i_armed(fwd__i_armed),
        .i_wvalid(fwd__i_wvalid),
        .i_wkind(fwd__i_wkind),
        .i_wodd(fwd__i_wodd),
        .i_wok(fwd__i_wok),
        .i_walarm(fwd__i_walarm),
        .i_wdata(fwd__i_wdata),
        .i_ptype(fwd__i_ptype),
        .o_slot(fwd__o_slot),
        .o_rtx_own(fwd__o_rtx_own),
        .o_rtx_idx(fwd__o_rtx_idx),
        .o_rtx_ok(fwd__o_rtx_ok),
        .o_regen(fwd__o_regen),
        .o_alarm_sent(fwd__o_alarm_sent),
        .o_sent_reason(fwd__o_sent_reason),
        .o_prev_alarm(fwd__o_prev_alarm),
        .o_pkt_done(fwd__o_pkt_done),
        .o_toggle(fwd__o_toggle),
        .o_line(fwd__o_line)
    );
    merkur_slave__tst tst(
        .clock(clock),
        .i_ack(tst__i_ack),
        .i_address(i_address),
        .i_restart(tst__i_restart),
        .o_line(tst__o_line)
    );
    merkur_slave__rep rep(
        .clock(clock),
        .i_valid(rep__i_valid),
        .i_code(rep__i_code),
        .i_phase(rep__i_phase),
        .o_line(rep__o_line),
        .o_slip(rep__o_slip)
    );

    // Combinational logic
    always @(*) begin
        failsafe_d = failsafe_q;
        rw_d = rw_q;
        armed_d = armed_q;
        quiet_d = quiet_q;
        quiet_max_d = quiet_max_q;
        quiet_clr_d = quiet_clr_q;
        pend_fs_d = pend_fs_q;
        pend_rc_d = pend_rc_q;
        pend_i1_d = pend_i1_q;
        pend_i2_d = pend_i2_q;
        act_data_d = act_data_q;
        perr_d = perr_q;
        ferr_d = ferr_q;
        rep_cut_d = rep_cut_q;
        fwd_cut_d = fwd_cut_q;
        last_cyc_d = last_cyc_q;
        ferr_owed_d = ferr_owed_q;
        h0_rwc_d = h0_rwc_q;
        sw_flush_d = sw_flush_q;
        fl_k_d = fl_k_q;
        nxt_d = nxt_q;
        wrapped = swc__o_mode != 2'h0;
        sbox__i_mode = swc__o_mode;
        rx_in__i_samples = sbox__o_input;
        rx_bsr__i_samples = sbox__o_bsr;
        if (i_cap_sel) begin
            rx_in__i_samples = i_pi;
            rx_bsr__i_samples = i_si;
        end
        o_cap_si = swc__o_wu_next;
        rx_in__i_tst_fail = ~wrapped & swc__o_grace_over;
        rx_bsr__i_tst_fail = ~wrapped & swc__o_grace_over;
        fwd__i_bvalid = rx_in__o_bvalid;
        fwd__i_code = rx_in__o_code;
        fwd__i_phase = rx_in__o_phase;
        fwd__i_hdr_bad = rx_in__o_hdr_bad | (rx_in__o_wvalid & (rx_in__o_kind == 2'h0) & rx_in__o_ok & (rx_in__o_ptype != 2'h0) & ((rx_in__o_ptype != 2'h3) | ~rtx_on));
        fwd__i_armed = armed_q;
        fwd__i_wvalid = rx_in__o_wvalid;
        fwd__i_wkind = rx_in__o_kind;
        fwd__i_wodd = rx_in__o_slot[0];
        fwd__i_wok = rx_in__o_ok;
        fwd__i_walarm = rx_in__o_alarm;
        fwd__i_wdata = rx_in__o_data;
        fwd__i_ptype = rx_in__o_ptype;
        if (~rx_in__o_inpkt) begin
            fwd_cut_d = 1'b0;
        end
        if (rx_in__o_wvalid & (rx_in__o_kind == 2'h0) & rx_in__o_ok & (rx_in__o_ptype == 2'h2)) begin
            fwd_cut_d = 1'b1;
        end
        fwd__i_mute = fwd_cut_q;
        fwd__i_act_out = act_data_q;
        fwd__i_fs = failsafe_q;
        fwd__i_wrapped = wrapped;
        o_fwd_slot = fwd__o_slot;
        o_regen = fwd__o_regen;
        o_wvalid = rx_in__o_wvalid & ((rx_in__o_ptype != 2'h3) | (rx_in__o_kind == 2'h0));
        o_kind = rx_in__o_kind;
        o_slot = rx_in__o_slot;
        o_rtx = 1'b0;
        if ((rx_in__o_kind == 2'h3) & rtx_on) begin
            o_wvalid = rx_in__o_wvalid & rx_in__o_slot[0] & fwd__o_rtx_ok & ~failsafe_q;
            o_kind = 2'h2;
            o_slot = fwd__o_rtx_idx;
            o_rtx = 1'b1;
        end
        o_data = rx_in__o_data;
        o_alive = rx_in__o_alive;
        o_alarm = rx_in__o_alarm;
        o_reason = rx_in__o_reason;
        o_ok = rx_in__o_ok;
        if (i_fs_set) begin
            failsafe_d = 1'b1;
        end
        e_rc = pend_rc_q;
        e_i1 = pend_i1_q;
        seq_tx = nxt_q;
        if (fl_k_q != 2'h0) begin
            e_rc = fl_k_q == 2'h3;
            e_i1 = fl_k_q == 2'h1;
            seq_tx = ~nxt_q;
        end
        reason = 4'h2;
        if (e_i1) begin
            reason = 4'h1;
        end
        if (e_rc) begin
            reason = 4'h4;
            if (swc__o_mode == 2'h1) begin
                reason = 4'h5;
            end
            if (swc__o_mode == 2'h2) begin
                reason = 4'h6;
            end
        end
        if (pend_fs_q) begin
            reason = 4'h3;
            seq_tx = 1'b0;
        end
        fwd__i_alarm_req = pend_fs_q | (fl_k_q != 2'h0) | pend_rc_q | pend_i1_q | pend_i2_q;
        fwd__i_alarm_reason = reason;
        fwd__i_alarm_seq = seq_tx;
        if (fwd__o_alarm_sent) begin
            if (fwd__o_sent_reason == 4'h3) begin
                pend_fs_d = 1'b0;
                failsafe_d = 1'b1;
            end
            else if (fl_k_q == 2'h0) begin
                nxt_d = ~nxt_q;
                if (fwd__o_sent_reason == 4'h1) begin
                    pend_i1_d = 1'b0;
                    fl_k_d = 2'h1;
                end
                else if (fwd__o_sent_reason == 4'h2) begin
                    pend_i2_d = 1'b0;
                    fl_k_d = 2'h2;
                end
                else begin
                    pend_rc_d = 1'b0;
                    fl_k_d = 2'h3;
                end
            end
        end
        rx_seq = rx_in__o_data[11];
        if (ext) begin
            rx_seq = rx_in__o_reason[3];
        end
        if (rx_in__o_wvalid & (rx_in__o_kind == 2'h2) & rx_in__o_own & ~fwd__o_prev_alarm & ~failsafe_q & rx_in__o_ok & rx_in__o_alarm & (rx_seq != nxt_q)) begin
            fl_k_d = 2'h0;
        end
        quiet_clr_d = 1'b0;
        if (quiet_clr_q) begin
            quiet_d = 20'h0;
            if (armed_q) begin
                quiet_d = 20'h1;
            end
            quiet_max_d = 1'b0;
        end
        else if (armed_q & ~quiet_max_q) begin
            quiet_d = quiet_q + 20'h1;
            quiet_max_d = quiet_q == 20'hffffe;
        end
        if (i_irq1) begin
            pend_i1_d = 1'b1;
        end
        if (i_irq2) begin
            pend_i2_d = 1'b1;
        end
        if (i_fs_req) begin
            pend_fs_d = 1'b1;
        end
        cyc_gap = rx_in__o_data[(12)+:(3)] - last_cyc_q - 3'h1;
        if (rx_in__o_wvalid & rx_in__o_ok & (rx_in__o_ptype == 2'h0)) begin
            if (rx_in__o_kind == 2'h0) begin
                h0_rwc_d = rx_in__o_data[12];
                if (rx_in__o_data[13] & ~rx_in__o_alive) begin
                    failsafe_d = 1'b1;
                end
                if (~rx_in__o_data[13] & rx_in__o_alive) begin
                    failsafe_d = 1'b0;
                end
            end
            if (rx_in__o_kind == 2'h1) begin
                armed_d = 1'b1;
                last_cyc_d = rx_in__o_data[(12)+:(3)];
                if (armed_q) begin
                    ferr_owed_d = cyc_gap;
                end
                rw_d = h0_rwc_q | rx_in__o_data[15] | wrapped;
            end
            if ((rx_in__o_kind == 2'h2) & rx_in__o_own & (~rx_in__o_alarm | ext) & i_actuator & ~failsafe_q) begin
                act_data_d = rx_in__o_data;
            end
        end
        if (rx_in__o_wvalid & (rx_in__o_kind == 2'h3) & rx_in__o_slot[0] & rx_in__o_ok & ~rx_in__o_alarm & fwd__o_rtx_own & i_actuator & ~failsafe_q) begin
            act_data_d = rx_in__o_data;
        end
        if (rx_in__o_wvalid & ((rx_in__o_kind == 2'h2) | ((rx_in__o_kind == 2'h3) & ~failsafe_q)) & ~rx_in__o_ok & ~rx_in__o_void & (perr_q != 16'hffff)) begin
            perr_d = perr_q + 16'h1;
        end
        if (rx_in__o_wvalid & (rx_in__o_kind == 2'h0) & ~(rx_in__o_ok & (rx_in__o_ptype == 2'h2))) begin
            quiet_clr_d = 1'b1;
        end
        if (ferr_owed_q != 3'h0) begin
            ferr_owed_d = ferr_owed_q - 3'h1;
            if (ferr_q != 16'hffff) begin
                ferr_d = ferr_q + 16'h1;
            end
        end
        cs_due = armed_q & ((quiet_clr_q & (i_cs_timeout == 20'h0)) | (~quiet_clr_q & (quiet_q == i_cs_timeout)));
        if (cs_due) begin
            failsafe_d = 1'b1;
        end
        swc__i_armed = armed_q;
        swc__i_hard_in = rx_in__o_hard;
        swc__i_hard_bsr = rx_bsr__o_hard;
        swc__i_run_in = rx_in__o_run;
        swc__i_run_bsr = rx_bsr__o_run;
        swc__i_los_in = rx_in__o_los;
        swc__i_los_bsr = rx_bsr__o_los;
        swc__i_rw = rw_q;
        swc__i_fs = failsafe_q;
        swc__i_tst_ack = rx_bsr__o_tst & rx_bsr__o_ack;
        swc__i_fwd = 1'b1;
        swc__i_frame_start = 1'b0;
        swc__i_in_pkt = rx_in__o_inpkt;
        swc__i_tst_in = rx_in__o_tst;
        swc__i_tst_bsr = rx_bsr__o_tst;
        swc__i_bsr_data = rx_bsr__o_wvalid & (rx_bsr__o_kind == 2'h0) & rx_bsr__o_ok & (rx_bsr__o_ptype == 2'h0);
        if (swc__o_fs_set) begin
            failsafe_d = 1'b1;
        end
        if (swc__o_change) begin
            pend_rc_d = 1'b1;
            if (fl_k_q == 2'h3) begin
                fl_k_d = 2'h0;
            end
        end
        out_pair = fwd__o_line;
        rep__i_valid = rx_bsr__o_bvalid;
        if (~rx_bsr__o_inpkt) begin
            rep_cut_d = 1'b0;
        end
        if (rx_bsr__o_wvalid & (rx_bsr__o_kind == 2'h0) & rx_bsr__o_ok & (rx_bsr__o_ptype == 2'h2)) begin
            rep_cut_d = 1'b1;
        end
        rep__i_code = rx_bsr__o_code;
        if (rep_cut_q) begin
            rep__i_code = 1'b1;
        end
        rep__i_phase = rx_bsr__o_phase;
        tst__i_ack = rx_bsr__o_tst;
        tst__i_restart = swc__o_tst_start;
        sw_flush_d = swc__o_relink;
        rx_in__i_flush = sw_flush_q;
        rx_bsr__i_flush = sw_flush_q;
        bss_pair = rep__o_line;
        if (wrapped) begin
            bss_pair = tst__o_line;
        end
        sbox__i_output = out_pair;
        sbox__i_bss = bss_pair;
        dark__i_change = swc__o_change;
        dark__i_keep_po = 1'b0;
        dark__i_po = sbox__o_po;
        dark__i_so = sbox__o_so;
        o_po = dark__o_po;
        o_so = dark__o_so;
        o_act_data = act_data_q;
        o_mode = swc__o_mode;
        o_failsafe = failsafe_q;
        o_perr = perr_q;
        o_ferr = ferr_q;
        o_hdr_bad = rx_in__o_hdr_bad;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial rep_cut_q = 1'h0;
    always @(posedge clock) rep_cut_q <= rep_cut_d;
    initial fwd_cut_q = 1'h0;
    always @(posedge clock) fwd_cut_q <= fwd_cut_d;
    initial failsafe_q = 1'h0;
    always @(posedge clock) failsafe_q <= failsafe_d;
    initial rw_q = 1'h0;
    always @(posedge clock) rw_q <= rw_d;
    initial h0_rwc_q = 1'h0;
    always @(posedge clock) h0_rwc_q <= h0_rwc_d;
    initial sw_flush_q = 1'h0;
    always @(posedge clock) sw_flush_q <= sw_flush_d;
    initial armed_q = 1'h0;
    always @(posedge clock) armed_q <= armed_d;
    initial last_cyc_q = 3'h0;
    always @(posedge clock) last_cyc_q <= last_cyc_d;
    initial ferr_owed_q = 3'h0;
    always @(posedge clock) ferr_owed_q <= ferr_owed_d;
    initial quiet_q = 20'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial quiet_max_q = 1'h0;
    always @(posedge clock) quiet_max_q <= quiet_max_d;
    initial quiet_clr_q = 1'h0;
    always @(posedge clock) quiet_clr_q <= quiet_clr_d;
    initial pend_fs_q = 1'h0;
    always @(posedge clock) pend_fs_q <= pend_fs_d;
    initial pend_rc_q = 1'h0;
    always @(posedge clock) pend_rc_q <= pend_rc_d;
    initial pend_i1_q = 1'h0;
    always @(posedge clock) pend_i1_q <= pend_i1_d;
    initial pend_i2_q = 1'h0;
    always @(posedge clock) pend_i2_q <= pend_i2_d;
    initial fl_k_q = 2'h0;
    always @(posedge clock) fl_k_q <= fl_k_d;
    initial nxt_q = 1'h0;
    always @(posedge clock) nxt_q <= nxt_d;
    initial act_data_q = 16'h0;
    always @(posedge clock) act_data_q <= act_data_d;
    initial perr_q = 16'h0;
    always @(posedge clock) perr_q <= perr_d;
    initial ferr_q = 16'h0;
    always @(posedge clock) ferr_q <= ferr_d;
endmodule // merkur_slave
// --------------------------------------------------------------------------
// `dark`: SwDark, Dark time of the physical outputs after a switchbox change. (rtl/src/node/sw_dark.rs)
//
// # sw_dark — dark physical outputs after a switchbox change (protocol §10)
//
// Purpose: when a node's switchbox changes mode, what its PO and SO carry
// comes from another source (OUTPUT, the secondary pass-through, the TST
// generator) in the middle of whatever the old source was sending. A
// downstream receiver inside a packet would take the new source's bits as
// the rest of its word (a splice that can pass both parities with a foreign
// value) or stay inside a cut TST until three idle groups have passed. So
// for [`DARK_CLOCKS`] (12 bit times) after a change both outputs hold their
// level: every downstream receiver mutes ([`crate::line::cdr::MUTE_SAMPLES`], 8
// bit times) and ends its packet, dropping the word it was in (not
// received, protocol §5), and hunts for the next J K; 12 bit times are
// well under loss of signal (32), so no stream controller fails. An
// output whose source stays the same (`i_keep_po`: the special master's
// PO, its own frame generator in N and in WU) is not darkened, so the
// frame it is sending is not cut.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_change` | in | 1 | clock | the switchbox mode changes at the next clock edge |
// | `i_keep_po` | in | 1 | clock | with `i_change`: PO keeps its source (not darkened) |
// | `i_po`, `i_so` | in | 2 | clock | the switchbox's physical outputs, DDR pairs |
// | `o_po`, `o_so` | out | 2 | clock | the same, dark (level held) for [`DARK_CLOCKS`] after a change |
//
// Latency: combinational (0 clocks) outside the dark time.
//
// ```text
// i_change  __/‾\______________________________
// i_po      ==X===X===X===X===X===X===X===X====   (new source from the next clock)
// o_po      ==X===|___ level held, 24 clocks __|X===X====
// ```
// --------------------------------------------------------------------------
module merkur_slave__dark(clock,i_change,i_keep_po,i_po,i_so,o_po,o_so);

    // Module arguments
    input wire  clock;
    input wire  i_change;
    input wire  i_keep_po;
    input wire  [1:0] i_po;
    input wire  [1:0] i_so;
    output reg  [1:0] o_po;
    output reg  [1:0] o_so;

    // Constant declarations
    localparam  dark_clocks = 5'b11000;

    // Registers and child block ports
    reg  [4:0] dark_d;
    reg  [4:0] dark_q;
    reg  dark_po_d;
    reg  dark_po_q;
    reg  lvl_po_d;
    reg  lvl_po_q;
    reg  lvl_so_d;
    reg  lvl_so_q;

    // Combinational logic
    always @(*) begin
        dark_d = dark_q;
        dark_po_d = dark_po_q;
        lvl_po_d = lvl_po_q;
        lvl_so_d = lvl_so_q;
        o_po = i_po;
        o_so = i_so;
        if (dark_q != 5'h0) begin
            dark_d = dark_q - 5'h1;
            if (dark_po_q) begin
                o_po = 2'h0;
                if (lvl_po_q) begin
                    o_po = 2'h3;
                end
            end
            o_so = 2'h0;
            if (lvl_so_q) begin
                o_so = 2'h3;
            end
        end
        lvl_po_d = o_po[1];
        lvl_so_d = o_so[1];
        if (i_change) begin
            dark_d = dark_clocks;
            dark_po_d = ~i_keep_po;
        end
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial dark_q = 5'h0;
    always @(posedge clock) dark_q <= dark_d;
    initial dark_po_q = 1'h0;
    always @(posedge clock) dark_po_q <= dark_po_d;
    initial lvl_po_q = 1'h0;
    always @(posedge clock) lvl_po_q <= lvl_po_d;
    initial lvl_so_q = 1'h0;
    always @(posedge clock) lvl_so_q <= lvl_so_d;
endmodule // merkur_slave__dark
// --------------------------------------------------------------------------
// `fwd`: Fwd, Cut-through forwarder of a slave node. (rtl/src/node/fwd.rs)
//
// # fwd — cut-through forwarder: the slave's slot shift register (protocol §4, §5, §7)
//
// Purpose: repeats the INPUT stream on OUTPUT, bit for bit on the recovered
// timing, five code bits (one group) behind, and changes what the node
// changes on the way:
// - H0: sets FS when the node is in failsafe, RWC when it is wrapped;
// - H1: adds 1 to HOP (carry running forward through the nibbles);
// - its own slot (`i_address`; in a master (`i_master`) every slot whose
//   `i_slot_cfg` is LOCAL or ACT): a **sensor** or a master's LOCAL slot writes a fresh word
//   `{i_sensor_data, ALIVE = toggle}` or an alarm; an **actuator** replaces
//   ALIVE with its toggle, or — when the first group shows VOID or an alarm
//   (its own, coming back) — writes `{i_act_out, toggle}`, or its alarm;
//   a **master's ACT slot** gets `i_slot_data` with the actuator's ALIVE
//   kept, or — on VOID — `{i_slot_data, NOT i_slot_alive}` (`o_regen`);
// - parities are fixed in the word's last group from the changes made
//   (delta parity), so a word that arrived bad leaves bad — and **marked**:
//   its last group goes out as T (protocol §4), so the next receivers know
//   it was damaged before their fibre (their stream controllers count only
//   their own fibre's errors);
// - H0's FS bit: set when the node is in failsafe, unless the header
//   carries CLR (its ALIVE bit, in the first group) and arrived with FS = 0:
//   the node leaves failsafe at that header (protocol §12).
//
// Everything else, including J K, idles, bad groups and packets after a
// rejected header (`i_hdr_bad`), passes unchanged; three idle groups in a
// row end a packet that was cut short upstream (as [`crate::line::word_rx`]), and
// so does a dead INPUT (no bit for [`DEAD_CLOCKS`]: the clock recovery
// muted), which also refills the
// group delay with idles. A frame whose header was processed toggles the
// Alive flip-flop even when it was cut short. The Alive flip-flop
// toggles after each processed DATA packet. Alarms: `i_alarm_req` with
// `i_alarm_reason` and `i_alarm_seq` is sent in the home slot if the previous
// cycle's home word was data (alternation); `o_alarm_sent` pulses when it
// goes out.
// The output bits go through a [`Retime`] buffer and out on the node's own
// clock (DDR pair), so the receiver's sampling error is not passed on.
//
// Retransmission on demand (protocol §8): a good H0 of type 11 on the
// input port's word bus (`i_wvalid` …) makes the packet an RTX. Its H0 is
// treated as a frame's (FS and RWC are already 1 there, so nothing
// changes), H1 passes unchanged, and the request words pass on, marked
// when they arrive bad; the packet ends at the third idle group. A data
// word whose good index word named the home slot is written: a
// **sensor** (armed, not in failsafe) writes `{its current sample, the
// Alive it wrote into this cycle's frame}` over whatever the word brings; an
// **actuator** puts that Alive into a data word (its master's copy). A
// node that wrote into the RTX without having processed the cycle's
// frame (the last header before it was not an RTX's and no frame ended
// since) toggles its Alive flip-flop at the RTX's end, as the frame
// would have. In a **master** (`i_master`) `o_slot` shows the requested
// slot, and a data word whose slot its data block writes (`i_slot_cfg`
// 1 or 2) is written `{i_slot_data, its Alive there}` (an ACT slot: the
// actuator's last Alive, `i_slot_alive`).
//
// Parameters: the word format ([`WordFormat`], as [`crate::line::word_rx`]).
// In the extended-alarm variant (protocol §6) every word has a sixth group,
// N1 = `{SEQ, REASON[2:0]}`, after the first: the forwarder passes it on
// (headers, data, a master's ACT slot), writes it in a fresh word (the
// alarm's SEQ and reason, 0 in a data word) and clears it with the ALARM
// bit when an actuator rewrites its slot; an alarm keeps the data bits
// (the sender's value), and an actuator or a master takes an alarm word's
// data as it takes a data word's. Data and HOP groups move one group on;
// FS and RWC are in H0's fifth group.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_bvalid`, `i_code`, `i_phase` | in | 1, 1, 2 | clock | recovered INPUT bits, NRZI-decoded (from [`crate::node::port_rx`]) |
// | `i_hdr_bad` | in | 1 | clock | header rejected, or not a DATA packet: pass the rest unchanged |
// | `i_mute` | in | 1 | clock | send idles for the code bits arriving from now on (a TST's rest) |
// | `i_slots_m1`, `i_address` | in | 12 | static | slot count − 1, home slot |
// | `i_actuator` | in | 1 | static | 1 actuator, 0 sensor |
// | `i_sensor_data` | in | 16 | clock | sensor value (sampled at its slot) |
// | `i_act_out` | in | 16 | clock | actuator output register |
// | `i_fs`, `i_wrapped` | in | 1 | clock | node in failsafe / wrapped |
// | `i_alarm_req`, `i_alarm_reason`, `i_alarm_seq` | in | 1, 4, 1 | clock | alarm to send, its reason and SEQ (basic: `D[15:12]`, `D[11]`; extended: N1) |
// | `i_master` | in | 1 | static | master mode: per-slot writes from `i_slot_cfg` |
// | `i_slot_cfg`, `i_slot_data`, `i_slot_alive` | in | 2, 16, 1 | clock | master: what it writes in slot `o_slot` (0 nothing, 1 LOCAL, 2 ACT, 3 its home slot without a value: only an alarm, protocol §12), data memory and actuator Alive of that slot, valid by the word's first group |
// | `i_armed` | in | 1 | clock | the node has processed a good header (it may fill RTX requests) |
// | `i_wvalid`, `i_wkind`, `i_wodd`, `i_wok`, `i_walarm`, `i_wdata`, `i_ptype` | in | 1, 2, 1, 1, 1, 16, 2 | clock | INPUT's words from the receive port ([`crate::line::word_rx`]: `i_wodd` is `o_slot`'s bit 0, an RTX data word) |
// | `o_slot` | out | 12 | clock | slot of the word passing (in an RTX: the slot its request names) |
// | `o_rtx_own` | out | 1 | clock | the RTX request passing names the home slot (from its good index word to the next index word) |
// | `o_rtx_idx`, `o_rtx_ok` | out | 12, 1 | clock | the slot that request names, and whether its index word was good |
// | `o_regen` | out | 1 | clock | master: an ACT slot's VOID was regenerated |
// | `o_alarm_sent`, `o_sent_reason` | out | 1, 4 | clock | the alarm went out, and which |
// | `o_prev_alarm` | out | 1 | clock | the last home-slot word sent was an alarm (so the next must be data) |
// | `o_pkt_done` | out | 1 | clock | a DATA packet's last slot went through |
// | `o_toggle` | out | 1 | clock | the Alive flip-flop |
// | `o_line` | out | 2 | clock | OUTPUT line, DDR pair (bit 0 first) |
//
// Pipeline (issue 20: every stage a few levels of logic at 2 × the line
// rate): stage A decodes a group in the clock its last bit arrives (and
// the action of a word's first group); stage B, the next clock, decides
// the rewrite from registers (the word flags and the fresh word are
// prepared a clock ahead, `pre_*`, `f_*`; a fresh word's parities, like a
// rewritten word's, come from the incoming word's and the changes made);
// stage C, the clock after, encodes it into the delay line and sums the
// delta parity.
//
// Latency: 6 bit times (one group and one bit, so that stage C's rewrite
// is in place before the group's first bit leaves) from INPUT bit to the
// retime buffer, which sends it 2.5 ± 0.5 bit times after its receive
// clock; with the CDR 9.5–10.5 bit times from the node's input samples
// to its output line, 10–11 from fibre to fibre with the top's capture
// register (measured at the fibres, docs/benchmarks.md).
//
// ```text
// in code   | N0 | N1 | N2 | N3 | N4 | ...
// out code       | N0'| N1'| N2'| N3'| N4'|        N0 decides, N4' fixes the parities
// ```
//
// (Extended variant: six groups, the last one N5'.)
// --------------------------------------------------------------------------
module merkur_slave__fwd(clock,i_bvalid,i_code,i_phase,i_hdr_bad,i_mute,i_slots_m1,i_address,i_actuator,i_sensor_data,i_act_out,i_fs,i_wrapped,i_alarm_req,i_alarm_reason,i_alarm_seq,i_master,i_slot_cfg,i_slot_data,i_slot_alive,i_armed,i_wvalid,i_wkind,i_wodd,i_wok,i_walarm,i_wdata,i_ptype,o_slot,o_rtx_own,o_rtx_idx,o_rtx_ok,o_regen,o_alarm_sent,o_sent_reason,o_prev_alarm,o_pkt_done,o_toggle,o_line);

    // Module arguments
    input wire  clock;
    input wire  i_bvalid;
    input wire  i_code;
    input wire  [1:0] i_phase;
    input wire  i_hdr_bad;
    input wire  i_mute;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    input wire  i_actuator;
    input wire  [15:0] i_sensor_data;
    input wire  [15:0] i_act_out;
    input wire  i_fs;
    input wire  i_wrapped;
    input wire  i_alarm_req;
    input wire  [3:0] i_alarm_reason;
    input wire  i_alarm_seq;
    input wire  i_master;
    input wire  [1:0] i_slot_cfg;
    input wire  [15:0] i_slot_data;
    input wire  i_slot_alive;
    input wire  i_armed;
    input wire  i_wvalid;
    input wire  [1:0] i_wkind;
    input wire  i_wodd;
    input wire  i_wok;
    input wire  i_walarm;
    input wire  [15:0] i_wdata;
    input wire  [1:0] i_ptype;
    output reg  [11:0] o_slot;
    output reg  o_rtx_own;
    output reg  [11:0] o_rtx_idx;
    output reg  o_rtx_ok;
    output reg  o_regen;
    output reg  o_alarm_sent;
    output reg  [3:0] o_sent_reason;
    output reg  o_prev_alarm;
    output reg  o_pkt_done;
    output reg  o_toggle;
    output reg  [1:0] o_line;

    // Constant declarations
    localparam  jk = 10'b1100010001;
    localparam  dead_after = 4'h6;
    localparam  ext = 1'b0;
    localparam  rtx_on = 1'b1;

    // Registers and child block ports
    reg  [9:0] window_d;
    reg  [9:0] window_q;
    reg  [5:0] delay_d;
    reg  [5:0] delay_q;
    reg  c_pend_d;
    reg  c_pend_q;
    reg  [3:0] c_nib_d;
    reg  [3:0] c_nib_q;
    reg  [3:0] c_orig_d;
    reg  [3:0] c_orig_q;
    reg  c_write_d;
    reg  c_write_q;
    reg  c_mark_d;
    reg  c_mark_q;
    reg  c_first_d;
    reg  c_first_q;
    reg  c_shift_d;
    reg  c_shift_q;
    reg  g_pend_d;
    reg  g_pend_q;
    reg  g_cut_d;
    reg  g_cut_q;
    reg  [3:0] g_nib_d;
    reg  [3:0] g_nib_q;
    reg  g_dat_d;
    reg  g_dat_q;
    reg  g_sym_s_d;
    reg  g_sym_s_q;
    reg  [2:0] g_act_d;
    reg  [2:0] g_act_q;
    reg  inpkt_d;
    reg  inpkt_q;
    reg  [1:0] idles_d;
    reg  [1:0] idles_q;
    reg  [3:0] quiet_d;
    reg  [3:0] quiet_q;
    reg  [2:0] bitc_d;
    reg  [2:0] bitc_q;
    reg  [2:0] gidx_d;
    reg  [2:0] gidx_q;
    reg  [1:0] wcount_d;
    reg  [1:0] wcount_q;
    reg  [11:0] slot_d;
    reg  [11:0] slot_q;
    reg  slot_inc_d;
    reg  slot_inc_q;
    reg  slot_clr_d;
    reg  slot_clr_q;
    reg  dead_d;
    reg  dead_q;
    reg  [2:0] action_d;
    reg  [2:0] action_q;
    reg  rtx_d;
    reg  rtx_q;
    reg  [11:0] idx_d;
    reg  [11:0] idx_q;
    reg  idx_ok_d;
    reg  idx_ok_q;
    reg  framed_d;
    reg  framed_q;
    reg  rtx_wrote_d;
    reg  rtx_wrote_q;
    reg  idx_own_d;
    reg  idx_own_q;
    reg  in_pa_d;
    reg  in_pa_q;
    reg  in_pb_d;
    reg  in_pb_q;
    reg  in_data_d;
    reg  in_data_q;
    reg  in_s_d;
    reg  in_s_q;
    reg  clr_h0_d;
    reg  clr_h0_q;
    reg  d_a_d;
    reg  d_a_q;
    reg  d_b_d;
    reg  d_b_q;
    reg  carry_d;
    reg  carry_q;
    reg  [15:0] f_data_d;
    reg  [15:0] f_data_q;
    reg  f_alive_d;
    reg  f_alive_q;
    reg  f_alarm_d;
    reg  f_alarm_q;
    reg  [3:0] f_reason_d;
    reg  [3:0] f_reason_q;
    reg  [3:0] f_rn_d;
    reg  [3:0] f_rn_q;
    reg  f_hold_d;
    reg  f_hold_q;
    reg  pre_home_d;
    reg  pre_home_q;
    reg  at_home_d;
    reg  at_home_q;
    reg  fs_r_d;
    reg  fs_r_q;
    reg  wr_r_d;
    reg  wr_r_q;
    reg  pre_own_d;
    reg  pre_own_q;
    reg  toggle_d;
    reg  toggle_q;
    reg  prev_alarm_d;
    reg  prev_alarm_q;
    reg  out__i_code;
    wire  [1:0] out__o_line;
    wire  out__o_slip;
    reg  sent_d;
    reg  sent_q;
    reg  [3:0] sent_reason_d;
    reg  [3:0] sent_reason_q;
    reg  done_d;
    reg  done_q;
    reg  regen_d;
    reg  regen_q;

    // Local signals
    reg  [9:0] shifted;
    reg  [4:0] group;
    reg  [3:0] dec_nib;
    reg  dec_data;
    reg  dec_s;
    reg  [3:0] nib;
    reg  g_data;
    reg  g_s;
    reg  [4:0] code_w;
    reg  [5:0] code_w6;
    reg  in_code;
    reg  [4:0] code_out;
    reg  [2:0] act_now;
    reg  [2:0] act_c;
    reg  [3:0] nib_out;
    reg  recode;
    reg  [3:0] diff;
    reg  home_c;
    reg  own_c;
    reg  rtx_own_c;
    reg  [15:0] addr16;
    reg  alive_now;
    reg  send_c;
    reg  [15:0] fresh_data;
    reg  fresh_alive;
    reg  [3:0] fresh_rn;
    reg  [2:0] dg;
    reg  cut;
    reg  pa_fix;
    reg  pb_fix;
    reg  [3:0] inc2;
    reg  [3:0] inc4;
    reg  out_bit;
    reg  arrived_bad;

    // Child blocks
    merkur_slave__fwd__out out(
        .clock(clock),
        .i_valid(i_bvalid),
        .i_code(out__i_code),
        .i_phase(i_phase),
        .o_line(out__o_line),
        .o_slip(out__o_slip)
    );

    // Combinational logic
    always @(*) begin
        window_d = window_q;
        delay_d = delay_q;
        c_pend_d = c_pend_q;
        c_nib_d = c_nib_q;
        c_orig_d = c_orig_q;
        c_write_d = c_write_q;
        c_mark_d = c_mark_q;
        c_first_d = c_first_q;
        c_shift_d = c_shift_q;
        g_pend_d = g_pend_q;
        g_cut_d = g_cut_q;
        g_nib_d = g_nib_q;
        g_dat_d = g_dat_q;
        g_sym_s_d = g_sym_s_q;
        g_act_d = g_act_q;
        inpkt_d = inpkt_q;
        idles_d = idles_q;
        quiet_d = quiet_q;
        bitc_d = bitc_q;
        gidx_d = gidx_q;
        wcount_d = wcount_q;
        slot_d = slot_q;
        slot_inc_d = slot_inc_q;
        slot_clr_d = slot_clr_q;
        dead_d = dead_q;
        action_d = action_q;
        rtx_d = rtx_q;
        idx_d = idx_q;
        idx_ok_d = idx_ok_q;
        framed_d = framed_q;
        rtx_wrote_d = rtx_wrote_q;
        idx_own_d = idx_own_q;
        d_a_d = d_a_q;
        d_b_d = d_b_q;
        carry_d = carry_q;
        f_data_d = f_data_q;
        f_alive_d = f_alive_q;
        f_alarm_d = f_alarm_q;
        f_reason_d = f_reason_q;
        f_rn_d = f_rn_q;
        f_hold_d = f_hold_q;
        pre_home_d = pre_home_q;
        at_home_d = at_home_q;
        fs_r_d = fs_r_q;
        wr_r_d = wr_r_q;
        pre_own_d = pre_own_q;
        toggle_d = toggle_q;
        prev_alarm_d = prev_alarm_q;
        sent_d = sent_q;
        sent_reason_d = sent_reason_q;
        done_d = done_q;
        regen_d = regen_q;
        in_pa_d = in_pa_q;
        in_pb_d = in_pb_q;
        in_data_d = in_data_q;
        in_s_d = in_s_q;
        clr_h0_d = clr_h0_q;
        shifted = window_q << 1;
        if (i_code) begin
            shifted = (window_q << 1) | 10'h1;
        end
        group = shifted[(0)+:(5)];
        dec_nib = 4'h0;
        dec_data = 1'b0;
        if (group == 5'h1e) begin
            dec_nib = 4'h0;
            dec_data = 1'b1;
        end
        if (group == 5'h9) begin
            dec_nib = 4'h1;
            dec_data = 1'b1;
        end
        if (group == 5'h14) begin
            dec_nib = 4'h2;
            dec_data = 1'b1;
        end
        if (group == 5'h15) begin
            dec_nib = 4'h3;
            dec_data = 1'b1;
        end
        if (group == 5'ha) begin
            dec_nib = 4'h4;
            dec_data = 1'b1;
        end
        if (group == 5'hb) begin
            dec_nib = 4'h5;
            dec_data = 1'b1;
        end
        if (group == 5'he) begin
            dec_nib = 4'h6;
            dec_data = 1'b1;
        end
        if (group == 5'hf) begin
            dec_nib = 4'h7;
            dec_data = 1'b1;
        end
        if (group == 5'h12) begin
            dec_nib = 4'h8;
            dec_data = 1'b1;
        end
        if (group == 5'h13) begin
            dec_nib = 4'h9;
            dec_data = 1'b1;
        end
        if (group == 5'h16) begin
            dec_nib = 4'ha;
            dec_data = 1'b1;
        end
        if (group == 5'h17) begin
            dec_nib = 4'hb;
            dec_data = 1'b1;
        end
        if (group == 5'h1a) begin
            dec_nib = 4'hc;
            dec_data = 1'b1;
        end
        if (group == 5'h1b) begin
            dec_nib = 4'hd;
            dec_data = 1'b1;
        end
        if (group == 5'h1c) begin
            dec_nib = 4'he;
            dec_data = 1'b1;
        end
        if (group == 5'h1d) begin
            dec_nib = 4'hf;
            dec_data = 1'b1;
        end
        dec_s = group == 5'h19;
        nib = g_nib_q;
        g_data = g_dat_q;
        g_s = g_sym_s_q;
        dg = gidx_q;
        if (ext & (gidx_q != 3'h0)) begin
            dg = gidx_q - 3'h1;
            if (gidx_q == 3'h1) begin
                dg = 3'h7;
            end
        end
        fs_r_d = i_fs;
        wr_r_d = i_wrapped;
        at_home_d = (wcount_q == 2'h2) & (slot_q == i_address);
        home_c = at_home_q & ~rtx_q & ~dead_q & ~fs_r_q;
        rtx_own_c = rtx_q & (wcount_q == 2'h2) & slot_q[0] & idx_own_q & ~i_master & ~dead_q & ~fs_r_q;
        if (i_master) begin
            rtx_own_c = rtx_q & (wcount_q == 2'h2) & slot_q[0] & idx_ok_q & ((i_slot_cfg == 2'h1) | (i_slot_cfg == 2'h2)) & ~dead_q & ~fs_r_q;
        end
        alive_now = toggle_q ^ (rtx_q & framed_q);
        send_c = home_c & i_alarm_req & ~prev_alarm_q & (~i_master | (i_slot_cfg != 2'h0));
        own_c = home_c;
        if (i_master) begin
            own_c = (wcount_q == 2'h2) & ~rtx_q & (i_slot_cfg != 2'h0) & ((i_slot_cfg != 2'h3) | send_c) & ~dead_q & ~fs_r_q;
        end
        pre_home_d = home_c;
        pre_own_d = own_c;
        act_c = action_q;
        if (gidx_q == 3'h0) begin
            act_c = 3'h0;
            if (~dead_q) begin
                if (wcount_q == 2'h0) begin
                    act_c = 3'h1;
                end
                if ((wcount_q == 2'h1) & ~rtx_q) begin
                    act_c = 3'h2;
                end
            end
            if (own_c) begin
                act_c = 3'h3;
                if (i_actuator & ~i_master & ~send_c) begin
                    if (dec_data & (~dec_nib[3] | ext)) begin
                        act_c = 3'h4;
                    end
                    if (~dec_data & ~dec_s) begin
                        act_c = 3'h0;
                    end
                end
                if (i_master & (i_slot_cfg == 2'h2) & ~send_c) begin
                    act_c = 3'h0;
                    if (dec_data & (~dec_nib[3] | ext)) begin
                        act_c = 3'h5;
                    end
                    if (dec_s) begin
                        act_c = 3'h3;
                    end
                end
            end
            if (rtx_own_c) begin
                if ((~i_actuator | i_master) & i_armed) begin
                    act_c = 3'h3;
                end
                if (i_actuator & ~i_master & dec_data & (~dec_nib[3] | ext)) begin
                    act_c = 3'h4;
                end
            end
        end
        act_now = g_act_q;
        fresh_alive = toggle_q;
        fresh_data = i_sensor_data;
        if (i_actuator) begin
            fresh_data = i_act_out;
        end
        if (i_master) begin
            fresh_data = i_slot_data;
            if (i_slot_cfg == 2'h2) begin
                fresh_alive = ~i_slot_alive;
            end
        end
        if (rtx_q) begin
            fresh_alive = alive_now;
            if (i_master & (i_slot_cfg == 2'h2)) begin
                fresh_alive = i_slot_alive;
            end
        end
        fresh_rn = 4'h0;
        if (send_c & ext) begin
            fresh_rn = i_alarm_reason & 4'h7;
            if (i_alarm_seq) begin
                fresh_rn = fresh_rn | 4'h8;
            end
        end
        if (send_c & ~ext) begin
            fresh_data = 16'h0;
            if (i_alarm_reason[0]) begin
                fresh_data = fresh_data | 16'h1000;
            end
            if (i_alarm_reason[1]) begin
                fresh_data = fresh_data | 16'h2000;
            end
            if (i_alarm_reason[2]) begin
                fresh_data = fresh_data | 16'h4000;
            end
            if (i_alarm_reason[3]) begin
                fresh_data = fresh_data | 16'h8000;
            end
            if (i_alarm_seq) begin
                fresh_data = fresh_data | 16'h800;
            end
        end
        if (~f_hold_q) begin
            f_data_d = fresh_data;
            f_alive_d = fresh_alive;
            f_alarm_d = send_c;
            f_reason_d = i_alarm_reason;
            f_rn_d = fresh_rn;
        end
        pa_fix = 1'b0;
        pb_fix = 1'b0;
        inc2 = nib ^ 4'h1;
        if (nib[0]) begin
            inc2 = nib ^ 4'h3;
        end
        inc4 = inc2;
        if (nib[(0)+:(2)] == 2'h3) begin
            inc4 = nib ^ 4'h7;
            if (nib[2]) begin
                inc4 = nib ^ 4'hf;
            end
        end
        nib_out = nib;
        recode = 1'b0;
        if (act_now == 3'h3) begin
            recode = 1'b1;
            nib_out = f_data_q[(0)+:(4)] & 4'h3;
            if (f_alarm_q) begin
                nib_out = nib_out | 4'h8;
            end
            if (f_alive_q) begin
                nib_out = nib_out | 4'h4;
            end
            if (dg == 3'h7) begin
                nib_out = f_rn_q;
            end
            if (dg == 3'h1) begin
                nib_out = f_data_q[(2)+:(4)];
            end
            if (dg == 3'h2) begin
                nib_out = f_data_q[(6)+:(4)];
            end
            if (dg == 3'h3) begin
                nib_out = f_data_q[(10)+:(4)];
            end
            if (dg == 3'h4) begin
                nib_out = (f_data_q[(12)+:(4)] >> 1) & 4'h6;
                if (~(in_pa_q ^ d_a_q ^ f_data_q[15])) begin
                    nib_out = nib_out | 4'h8;
                end
                if (~(in_pb_q ^ d_b_q ^ f_data_q[15] ^ f_data_q[14])) begin
                    nib_out = nib_out | 4'h1;
                end
            end
        end
        if (g_data & (act_now != 3'h0) & (act_now != 3'h3)) begin
            recode = 1'b1;
            if ((act_now == 3'h1) & (dg == 3'h3)) begin
                if (fs_r_q & ~clr_h0_q) begin
                    nib_out = nib_out | 4'h8;
                end
                if (wr_r_q) begin
                    nib_out = nib_out | 4'h4;
                end
            end
            if ((act_now == 3'h2) & (gidx_q == 3'h0)) begin
                nib_out = inc2;
            end
            if ((act_now == 3'h2) & ((dg == 3'h1) | (dg == 3'h2)) & carry_q) begin
                nib_out = inc4;
            end
            if ((act_now == 3'h2) & (dg == 3'h3) & carry_q) begin
                nib_out = inc2;
            end
            if ((act_now == 3'h4) & (gidx_q == 3'h0)) begin
                nib_out = nib & 4'h3;
                if (alive_now) begin
                    nib_out = nib_out | 4'h4;
                end
            end
            if ((act_now == 3'h4) & (dg == 3'h7)) begin
                nib_out = 4'h0;
            end
            if (act_now == 3'h5) begin
                if (gidx_q == 3'h0) begin
                    nib_out = (nib & 4'hc) | (f_data_q[(0)+:(4)] & 4'h3);
                end
                if (dg == 3'h1) begin
                    nib_out = f_data_q[(2)+:(4)];
                end
                if (dg == 3'h2) begin
                    nib_out = f_data_q[(6)+:(4)];
                end
                if (dg == 3'h3) begin
                    nib_out = f_data_q[(10)+:(4)];
                end
            end
            if (dg == 3'h4) begin
                pa_fix = d_a_q;
                pb_fix = d_b_q;
                if (act_now == 3'h5) begin
                    nib_out = (nib & 4'h9) | ((f_data_q[(12)+:(4)] >> 1) & 4'h6);
                    pa_fix = d_a_q ^ nib[2] ^ f_data_q[15];
                    pb_fix = d_b_q ^ nib[2] ^ f_data_q[15] ^ nib[1] ^ f_data_q[14];
                end
                if (pa_fix) begin
                    nib_out = nib_out ^ 4'h8;
                end
                if (pb_fix) begin
                    nib_out = nib_out ^ 4'h1;
                end
            end
        end
        diff = c_orig_q ^ c_nib_q;
        arrived_bad = ~(in_data_q & g_data & (in_pa_q ^ nib[3] ^ nib[2]) & (in_pb_q ^ nib[2] ^ nib[1] ^ nib[0])) & ~(in_s_q & g_s);
        code_out = 5'h1e;
        if (c_nib_q == 4'h1) begin
            code_out = 5'h9;
        end
        if (c_nib_q == 4'h2) begin
            code_out = 5'h14;
        end
        if (c_nib_q == 4'h3) begin
            code_out = 5'h15;
        end
        if (c_nib_q == 4'h4) begin
            code_out = 5'ha;
        end
        if (c_nib_q == 4'h5) begin
            code_out = 5'hb;
        end
        if (c_nib_q == 4'h6) begin
            code_out = 5'he;
        end
        if (c_nib_q == 4'h7) begin
            code_out = 5'hf;
        end
        if (c_nib_q == 4'h8) begin
            code_out = 5'h12;
        end
        if (c_nib_q == 4'h9) begin
            code_out = 5'h13;
        end
        if (c_nib_q == 4'ha) begin
            code_out = 5'h16;
        end
        if (c_nib_q == 4'hb) begin
            code_out = 5'h17;
        end
        if (c_nib_q == 4'hc) begin
            code_out = 5'h1a;
        end
        if (c_nib_q == 4'hd) begin
            code_out = 5'h1b;
        end
        if (c_nib_q == 4'he) begin
            code_out = 5'h1c;
        end
        if (c_nib_q == 4'hf) begin
            code_out = 5'h1d;
        end
        out_bit = delay_q[5];
        in_code = i_code | i_mute;
        sent_d = 1'b0;
        done_d = 1'b0;
        cut = 1'b0;
        regen_d = 1'b0;
        g_pend_d = 1'b0;
        slot_inc_d = 1'b0;
        slot_clr_d = 1'b0;
        if (slot_clr_q) begin
            slot_d = 12'h0;
        end
        else if (slot_inc_q) begin
            slot_d = slot_q + 12'h1;
        end
        if (i_bvalid) begin
            window_d = shifted;
            delay_d = delay_q << 1;
            if (in_code) begin
                delay_d = (delay_q << 1) | 6'h1;
            end
            if (inpkt_q) begin
                if (bitc_q == 3'h4) begin
                    bitc_d = 3'h0;
                    idles_d = 2'h0;
                    if (group == 5'h1f) begin
                        idles_d = idles_q + 2'h1;
                    end
                    g_pend_d = 1'b1;
                    g_cut_d = (group == 5'h1f) & (idles_q == 2'h2);
                    if ((group == 5'h1f) & (idles_q == 2'h2)) begin
                        cut = 1'b1;
                    end
                    g_nib_d = dec_nib;
                    g_dat_d = dec_data;
                    g_sym_s_d = dec_s;
                    g_act_d = act_c;
                end
                else begin
                    bitc_d = bitc_q + 3'h1;
                end
            end
            else if (shifted == jk) begin
                inpkt_d = 1'b1;
                bitc_d = 3'h0;
                gidx_d = 3'h0;
                wcount_d = 2'h0;
                slot_clr_d = 1'b1;
                dead_d = 1'b0;
                idles_d = 2'h0;
                rtx_d = 1'b0;
                idx_ok_d = 1'b0;
                idx_own_d = 1'b0;
                rtx_wrote_d = 1'b0;
            end
        end
        c_pend_d = 1'b0;
        if (g_pend_q & ~g_cut_q) begin
            c_pend_d = 1'b1;
            c_nib_d = nib_out;
            c_orig_d = nib;
            c_write_d = recode;
            c_first_d = gidx_q == 3'h0;
            c_shift_d = i_bvalid;
            c_mark_d = (dg == 3'h4) & arrived_bad & ~dead_q & (action_q != 3'h3);
            in_pa_d = in_pa_q ^ nib[3] ^ nib[2];
            in_pb_d = in_pb_q ^ nib[2] ^ nib[1] ^ nib[0];
            in_data_d = in_data_q & g_data;
            in_s_d = in_s_q & g_s;
            if (gidx_q == 3'h0) begin
                in_pa_d = nib[3] ^ nib[2];
                in_pb_d = nib[2] ^ nib[1] ^ nib[0];
                in_data_d = g_data;
                in_s_d = g_s;
                if (wcount_q == 2'h0) begin
                    clr_h0_d = nib[2];
                end
            end
            if (gidx_q == 3'h0) begin
                action_d = act_now;
                carry_d = 1'b0;
                regen_d = pre_own_q & i_master & (i_slot_cfg == 2'h2) & (act_now == 3'h3);
                if ((act_now >= 3'h3) & rtx_q) begin
                    rtx_wrote_d = 1'b1;
                end
                if (pre_home_q) begin
                    prev_alarm_d = f_alarm_q;
                    sent_d = f_alarm_q;
                    sent_reason_d = f_reason_q;
                end
            end
            if (gidx_q == 3'h0) begin
                carry_d = nib[(0)+:(2)] == 2'h3;
            end
            else if (dg != 3'h7) begin
                carry_d = carry_q & (nib == 4'hf);
            end
            gidx_d = gidx_q + 3'h1;
            if (dg == 3'h4) begin
                gidx_d = 3'h0;
                if (wcount_q == 2'h2) begin
                    slot_inc_d = 1'b1;
                    if ((slot_q == i_slots_m1) & ~rtx_q) begin
                        inpkt_d = 1'b0;
                        if (~dead_q) begin
                            done_d = 1'b1;
                            toggle_d = ~toggle_q;
                            framed_d = 1'b1;
                        end
                    end
                end
                else begin
                    wcount_d = wcount_q + 2'h1;
                end
            end
        end
        code_w = code_out;
        if (c_mark_q) begin
            code_w = 5'hd;
        end
        code_w6 = ({1'h0, code_w}) | 6'h0;
        if (c_pend_q & (c_write_q | c_mark_q)) begin
            if (c_shift_q) begin
                delay_d = (delay_q & 6'h1) | (code_w6 << 1);
                out_bit = code_w[4];
                if (i_bvalid) begin
                    delay_d = (code_w6 << 2) | ((delay_q & 6'h1) << 1) | (({5'h0, in_code}) | 6'h0);
                end
            end
            else begin
                delay_d = (delay_q & 6'h20) | code_w6;
                if (i_bvalid) begin
                    delay_d = (code_w6 << 1) | (({5'h0, in_code}) | 6'h0);
                end
            end
        end
        if (c_pend_q) begin
            d_a_d = d_a_q ^ diff[3] ^ diff[2];
            d_b_d = d_b_q ^ diff[2] ^ diff[1] ^ diff[0];
            if (c_first_q) begin
                d_a_d = diff[3] ^ diff[2];
                d_b_d = diff[2] ^ diff[1] ^ diff[0];
            end
        end
        out__i_code = out_bit;
        if (i_bvalid) begin
            quiet_d = 4'h0;
        end
        else if (quiet_q != 4'hf) begin
            quiet_d = quiet_q + 4'h1;
        end
        if (quiet_q == dead_after) begin
            delay_d = 6'h3f;
            cut = 1'b1;
        end
        if (cut) begin
            inpkt_d = 1'b0;
            idles_d = 2'h0;
            if (inpkt_q & (wcount_q == 2'h2) & ~dead_q & ~rtx_q) begin
                done_d = 1'b1;
                toggle_d = ~toggle_q;
                framed_d = 1'b1;
            end
            if (inpkt_q & rtx_q & rtx_wrote_q & ~framed_q) begin
                toggle_d = ~toggle_q;
                framed_d = 1'b1;
            end
        end
        if (i_wvalid & (i_wkind == 2'h0)) begin
            rtx_d = i_wok & (i_ptype == 2'h3) & rtx_on;
            if (~(i_wok & (i_ptype == 2'h3))) begin
                framed_d = 1'b0;
            end
        end
        addr16 = ({4'h0, i_address}) | 16'h0;
        if (i_wvalid & (i_wkind == 2'h3) & ~i_wodd) begin
            idx_d = i_wdata[(0)+:(12)];
            idx_ok_d = i_wok & ~i_walarm & (i_wdata[(12)+:(4)] == 4'h0) & (i_wdata[(0)+:(12)] <= i_slots_m1);
            idx_own_d = rtx_on & i_wok & ~i_walarm & (i_wdata == addr16);
        end
        if (i_hdr_bad) begin
            dead_d = 1'b1;
        end
        f_hold_d = (gidx_d != 3'h0) | g_pend_d;
        o_slot = slot_q;
        o_rtx_own = idx_own_q;
        o_rtx_idx = idx_q;
        o_rtx_ok = idx_ok_q;
        if (rtx_q) begin
            o_slot = idx_q;
        end
        o_regen = regen_q;
        o_alarm_sent = sent_q;
        o_sent_reason = sent_reason_q;
        o_prev_alarm = prev_alarm_q;
        o_pkt_done = done_q;
        o_toggle = toggle_q;
        o_line = out__o_line;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial window_q = 10'h0;
    always @(posedge clock) window_q <= window_d;
    initial delay_q = 6'h0;
    always @(posedge clock) delay_q <= delay_d;
    initial c_pend_q = 1'h0;
    always @(posedge clock) c_pend_q <= c_pend_d;
    initial c_nib_q = 4'h0;
    always @(posedge clock) c_nib_q <= c_nib_d;
    initial c_orig_q = 4'h0;
    always @(posedge clock) c_orig_q <= c_orig_d;
    initial c_write_q = 1'h0;
    always @(posedge clock) c_write_q <= c_write_d;
    initial c_mark_q = 1'h0;
    always @(posedge clock) c_mark_q <= c_mark_d;
    initial c_first_q = 1'h0;
    always @(posedge clock) c_first_q <= c_first_d;
    initial c_shift_q = 1'h0;
    always @(posedge clock) c_shift_q <= c_shift_d;
    initial g_pend_q = 1'h0;
    always @(posedge clock) g_pend_q <= g_pend_d;
    initial g_cut_q = 1'h0;
    always @(posedge clock) g_cut_q <= g_cut_d;
    initial g_nib_q = 4'h0;
    always @(posedge clock) g_nib_q <= g_nib_d;
    initial g_dat_q = 1'h0;
    always @(posedge clock) g_dat_q <= g_dat_d;
    initial g_sym_s_q = 1'h0;
    always @(posedge clock) g_sym_s_q <= g_sym_s_d;
    initial g_act_q = 3'h0;
    always @(posedge clock) g_act_q <= g_act_d;
    initial inpkt_q = 1'h0;
    always @(posedge clock) inpkt_q <= inpkt_d;
    initial idles_q = 2'h0;
    always @(posedge clock) idles_q <= idles_d;
    initial quiet_q = 4'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial bitc_q = 3'h0;
    always @(posedge clock) bitc_q <= bitc_d;
    initial gidx_q = 3'h0;
    always @(posedge clock) gidx_q <= gidx_d;
    initial wcount_q = 2'h0;
    always @(posedge clock) wcount_q <= wcount_d;
    initial slot_q = 12'h0;
    always @(posedge clock) slot_q <= slot_d;
    initial slot_inc_q = 1'h0;
    always @(posedge clock) slot_inc_q <= slot_inc_d;
    initial slot_clr_q = 1'h0;
    always @(posedge clock) slot_clr_q <= slot_clr_d;
    initial dead_q = 1'h0;
    always @(posedge clock) dead_q <= dead_d;
    initial action_q = 3'h0;
    always @(posedge clock) action_q <= action_d;
    initial rtx_q = 1'h0;
    always @(posedge clock) rtx_q <= rtx_d;
    initial idx_q = 12'h0;
    always @(posedge clock) idx_q <= idx_d;
    initial idx_ok_q = 1'h0;
    always @(posedge clock) idx_ok_q <= idx_ok_d;
    initial framed_q = 1'h0;
    always @(posedge clock) framed_q <= framed_d;
    initial rtx_wrote_q = 1'h0;
    always @(posedge clock) rtx_wrote_q <= rtx_wrote_d;
    initial idx_own_q = 1'h0;
    always @(posedge clock) idx_own_q <= idx_own_d;
    initial in_pa_q = 1'h0;
    always @(posedge clock) in_pa_q <= in_pa_d;
    initial in_pb_q = 1'h0;
    always @(posedge clock) in_pb_q <= in_pb_d;
    initial in_data_q = 1'h0;
    always @(posedge clock) in_data_q <= in_data_d;
    initial in_s_q = 1'h0;
    always @(posedge clock) in_s_q <= in_s_d;
    initial clr_h0_q = 1'h0;
    always @(posedge clock) clr_h0_q <= clr_h0_d;
    initial d_a_q = 1'h0;
    always @(posedge clock) d_a_q <= d_a_d;
    initial d_b_q = 1'h0;
    always @(posedge clock) d_b_q <= d_b_d;
    initial carry_q = 1'h0;
    always @(posedge clock) carry_q <= carry_d;
    initial f_data_q = 16'h0;
    always @(posedge clock) f_data_q <= f_data_d;
    initial f_alive_q = 1'h0;
    always @(posedge clock) f_alive_q <= f_alive_d;
    initial f_alarm_q = 1'h0;
    always @(posedge clock) f_alarm_q <= f_alarm_d;
    initial f_reason_q = 4'h0;
    always @(posedge clock) f_reason_q <= f_reason_d;
    initial f_rn_q = 4'h0;
    always @(posedge clock) f_rn_q <= f_rn_d;
    initial f_hold_q = 1'h0;
    always @(posedge clock) f_hold_q <= f_hold_d;
    initial pre_home_q = 1'h0;
    always @(posedge clock) pre_home_q <= pre_home_d;
    initial at_home_q = 1'h0;
    always @(posedge clock) at_home_q <= at_home_d;
    initial fs_r_q = 1'h0;
    always @(posedge clock) fs_r_q <= fs_r_d;
    initial wr_r_q = 1'h0;
    always @(posedge clock) wr_r_q <= wr_r_d;
    initial pre_own_q = 1'h0;
    always @(posedge clock) pre_own_q <= pre_own_d;
    initial toggle_q = 1'h0;
    always @(posedge clock) toggle_q <= toggle_d;
    initial prev_alarm_q = 1'h0;
    always @(posedge clock) prev_alarm_q <= prev_alarm_d;
    initial sent_q = 1'h0;
    always @(posedge clock) sent_q <= sent_d;
    initial sent_reason_q = 4'h0;
    always @(posedge clock) sent_reason_q <= sent_reason_d;
    initial done_q = 1'h0;
    always @(posedge clock) done_q <= done_d;
    initial regen_q = 1'h0;
    always @(posedge clock) regen_q <= regen_d;
endmodule // merkur_slave__fwd
// --------------------------------------------------------------------------
// `out`: Retime, Elastic output buffer with its own bit timing. (rtl/src/line/retime.rs)
//
// # retime — elastic output buffer: sends recovered bits on the node's own clock (protocol §9)
//
// Purpose: a node retransmits at the rate of the stream it receives, but a
// transmitter that repeats every edge where its receiver saw it also repeats
// that receiver's sampling error, and on a long ring those errors add up
// hop by hop until an edge moves by half a bit. This block breaks the chain:
// code bits (1: the line toggles) go into a small buffer at the receive
// timing and come out on the node's own clock, one bit per 4 half clocks (the DDR output's two halves
// per clock); to follow the stream's rate it makes one bit 3 or 5 half
// clocks long now and then. So an edge on the line is off by at most one
// output half clock (2 receiver samples) from where the node's clock puts
// it, whatever the input did, and a downstream receiver
// ([`crate::line::cdr`]: 8k − 3 … 8k + 4 samples for a k-bit interval) has a
// sample of margin on every link.
//
// **Phase measure.** At each write the block computes how long, in receive
// samples (quarter clocks), the new bit will wait until it is sent:
// `lag = 2·rem + 8·cnt − i_phase`, with `rem` the half clocks to the next
// send at the start of the next clock, `cnt` the bits buffered and
// `i_phase` the sample of its clock the bit was taken from. The target is
// [`TARGET`] = 20 (2.5 bit times; a bit sent in the clock after its write
// has a lag of 5–8). After [`VOTES`] writes in a row with
// `lag` more than [`BAND`] above (below) the target, the next bit is sent
// 3 (5) half clocks long, at most once per [`GAP`] bits, so that no edge
// interval on the line carries two corrections. That follows a clock
// difference of up to 1/(4·GAP) (31 000 ppm); a node's offset needs
// ±2000 ppm.
//
// **Start and errors.** Until two bits have arrived it sends idles (NRZI
// ones: the line toggles every bit) on its own bit grid; from the second
// bit on it sends the buffer, from the grid's next boundary. A send with an empty buffer
// (underflow: the input stopped) or a write into a full one (overflow)
// pulses `o_slip` and empties the buffer; an underflow sends no idle edge
// (the zeros the receiver read from a dying line before it muted would be
// confirmed by it): the line stays dark until [`QUIET_BITS`] bit times
// after the last edge it sent, so a downstream receiver mutes and drops the
// word the input stopped in ([`crate::line::monitor`]) and a downstream
// forwarder sees its input dead ([`crate::node::fwd::DEAD_CLOCKS`]); then it
// sends idles, so the next node sees a live line again long before loss
// of signal (32 bit times); the next bits start again. Counted from the
// last edge *sent*, the gap is the same on every hop whatever the
// pipeline in front of the buffer held back (a forwarder keeps a group of
// the zeros read from a dying line in its delay line: counted from the
// underflow, the gap shrank by that much per hop until a node no longer
// saw it, issue 19). A live stream within ±2000 ppm never slips.
//
// **The buffer's layout** ([`Layout`], the block's one parameter; the
// same behaviour clock for clock either way, proof `retime_layouts`):
// with [`Layout::SendShifts`] the oldest bit sits in bit 0, a send
// shifts it out and a write goes in behind the unsent bits, decoded by
// the count: the bit to send is one flip-flop, short paths for LUT
// devices (the ring's nodes and every FPGA top). With
// [`Layout::WriteShifts`] a write shifts the new bit in at bit 7 and a
// send reads the count's bit from the top (bit 8 − count): no write
// decoder in every buffer bit, for product-term devices (`merkur synth
// --target xc2c*`; issue 21). In the Verilog the layout is the
// `localparam write_shifts` (1: `WriteShifts`).
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_valid` | in | 1 | clock | a bit to send (at most one per clock) |
// | `i_code` | in | 1 | clock | its code bit: 1 = the line toggles (NRZI) |
// | `i_phase` | in | 2 | clock | its receive sample within the clock ([`crate::line::cdr`]'s `o_phase`) |
// | `o_line` | out | 2 | clock | OUTPUT line, DDR pair (bit 0 first) |
// | `o_slip` | out | 1 | clock | pulse: underflow or overflow, the buffer restarted |
//
// Latency: a bit is sent [`TARGET`] receive samples (2.5 bit times,
// ± [`BAND`]) after the clock of its receive sample, plus the output
// register.
//
// ```text
// i_valid   _/‾\___/‾\___/‾\___/‾\___/‾\___     (receive timing: jitters)
// rem         3 1 3 1 3 1 3 1 3 1 3 1 3 1        (half clocks to the next send)
// o_line    ==X=======X=======X=======X====      (own clock: 4 half clocks per bit)
// correction: one bit of 3 or 5 half clocks, at most every GAP bits
// ```
// --------------------------------------------------------------------------
module merkur_slave__fwd__out(clock,i_valid,i_code,i_phase,o_line,o_slip);

    // Module arguments
    input wire  clock;
    input wire  i_valid;
    input wire  i_code;
    input wire  [1:0] i_phase;
    output reg  [1:0] o_line;
    output reg  o_slip;

    // Constant declarations
    localparam  quiet_bits = 5'b1110;
    localparam  write_shifts = 1'b0;
    localparam  votes = 3'b100;
    localparam  gap_min = 4'h8;
    localparam  one = 8'h1;

    // Registers and child block ports
    reg  [7:0] sr_d;
    reg  [7:0] sr_q;
    reg  [3:0] cnt_d;
    reg  [3:0] cnt_q;
    reg  [2:0] rem_d;
    reg  [2:0] rem_q;
    reg  lvl_d;
    reg  lvl_q;
    reg  run_d;
    reg  run_q;
    reg  dark_d;
    reg  dark_q;
    reg  [4:0] since_d;
    reg  [4:0] since_q;
    reg  [2:0] hi_d;
    reg  [2:0] hi_q;
    reg  [2:0] lo_d;
    reg  [2:0] lo_q;
    reg  [3:0] gap_d;
    reg  [3:0] gap_q;
    reg  [1:0] pair_d;
    reg  [1:0] pair_q;
    reg  slip_d;
    reg  slip_q;

    // Local signals
    reg  send0;
    reg  send1;
    reg  take;
    reg  under;
    reg  oldest;
    reg  [2:0] rpos;
    reg  [7:0] rsel;
    reg  [7:0] sr_shift;
    reg  [2:0] wpos;
    reg  [7:0] wmask;
    reg  new_lvl;
    reg  [2:0] len;
    reg  [3:0] cnt_next;
    reg  [2:0] rem_next;
    reg  t_neg;
    reg  t_pos;
    reg  t_lt8;
    reg  t_gt8;
    reg  c_is0;
    reg  c_is1;
    reg  c_is2;
    reg  c_is3;
    reg  c_ge4;
    reg  late;
    reg  early;
    reg  start2;
    reg  over;

    // Combinational logic
    always @(*) begin
        sr_d = sr_q;
        cnt_d = cnt_q;
        rem_d = rem_q;
        lvl_d = lvl_q;
        run_d = run_q;
        dark_d = dark_q;
        since_d = since_q;
        hi_d = hi_q;
        lo_d = lo_q;
        gap_d = gap_q;
        pair_d = pair_q;
        slip_d = slip_q;
        send0 = rem_q == 3'h0;
        send1 = rem_q == 3'h1;
        take = (send0 | send1) & run_q & (cnt_q != 4'h0);
        oldest = sr_q[0];
        rpos = (~cnt_q[(0)+:(3)]) + 3'h1;
        rsel = sr_q >> rpos;
        if (write_shifts) begin
            oldest = (rsel & 8'h1) != 8'h0;
        end
        under = (send0 | send1) & run_q & (cnt_q == 4'h0);
        new_lvl = lvl_q;
        if ((send0 | send1) & ~dark_q & ~under) begin
            new_lvl = ~lvl_q;
        end
        if ((send0 | send1) & dark_q & (since_q >= quiet_bits)) begin
            dark_d = 1'b0;
        end
        if (take) begin
            new_lvl = lvl_q ^ oldest;
        end
        pair_d = 2'h0;
        if (lvl_q) begin
            pair_d = 2'h3;
        end
        if (send0 & new_lvl) begin
            pair_d = 2'h3;
        end
        if (send0 & ~new_lvl) begin
            pair_d = 2'h0;
        end
        if (send1 & (new_lvl != lvl_q)) begin
            pair_d = 2'h1;
            if (new_lvl) begin
                pair_d = 2'h2;
            end
        end
        lvl_d = new_lvl;
        if (send0 | send1) begin
            if (new_lvl != lvl_q) begin
                since_d = 5'h0;
            end
            else if (since_q != 5'h1f) begin
                since_d = since_q + 5'h1;
            end
        end
        len = 3'h4;
        if (run_q & (gap_q >= gap_min)) begin
            if (hi_q >= votes) begin
                len = 3'h3;
            end
            if (lo_q >= votes) begin
                len = 3'h5;
            end
        end
        rem_next = rem_q ^ 3'h2;
        if (~rem_q[1]) begin
            rem_next = rem_q ^ 3'h6;
        end
        if (send0 | send1) begin
            if (gap_q != 4'hf) begin
                gap_d = gap_q + 4'h1;
            end
            if (len != 3'h4) begin
                gap_d = 4'h0;
                hi_d = 3'h0;
                lo_d = 3'h0;
            end
        end
        if (send0) begin
            rem_next = 3'h2;
            if (len == 3'h3) begin
                rem_next = 3'h1;
            end
            if (len == 3'h5) begin
                rem_next = 3'h3;
            end
        end
        if (send1) begin
            rem_next = 3'h3;
            if (len == 3'h3) begin
                rem_next = 3'h2;
            end
            if (len == 3'h5) begin
                rem_next = 3'h4;
            end
        end
        sr_shift = sr_q;
        if (take) begin
            sr_shift = sr_q >> 1;
        end
        sr_d = sr_shift;
        wpos = cnt_q[(0)+:(3)];
        if (take) begin
            wpos = cnt_q[(0)+:(3)] - 3'h1;
        end
        wmask = one << wpos;
        cnt_next = cnt_q;
        if (take & ~i_valid) begin
            cnt_next = cnt_q - 4'h1;
        end
        if (i_valid) begin
            sr_d = sr_shift & ~wmask;
            if (i_code) begin
                sr_d = sr_shift | wmask;
            end
            if (~take) begin
                cnt_next = cnt_q + 4'h1;
            end
        end
        if (write_shifts) begin
            sr_d = sr_q;
            if (i_valid) begin
                sr_d = sr_q >> 1;
                if (i_code) begin
                    sr_d = (sr_q >> 1) | 8'h80;
                end
            end
        end
        t_neg = ((rem_next == 3'h0) & (i_phase != 2'h0)) | ((rem_next == 3'h1) & (i_phase == 2'h3));
        t_pos = (rem_next >= 3'h2) | ((rem_next == 3'h1) & ~i_phase[1]);
        t_lt8 = (rem_next <= 3'h3) | ((rem_next == 3'h4) & (i_phase != 2'h0)) | ((rem_next == 3'h5) & (i_phase == 2'h3));
        t_gt8 = (rem_next >= 3'h6) | ((rem_next == 3'h5) & ~i_phase[1]);
        c_is0 = cnt_q == 4'hf;
        c_is1 = cnt_q == 4'h0;
        c_is2 = cnt_q == 4'h1;
        c_is3 = cnt_q == 4'h2;
        c_ge4 = (cnt_q >= 4'h3) & (cnt_q != 4'hf);
        if (take) begin
            c_is1 = cnt_q == 4'h1;
            c_is2 = cnt_q == 4'h2;
            c_is3 = cnt_q == 4'h3;
            c_ge4 = cnt_q >= 4'h4;
            c_is0 = 1'b0;
        end
        late = c_ge4 | (c_is0 & t_neg) | (c_is2 & t_gt8) | (c_is3 & t_pos);
        early = (c_is0 & ~t_neg) | (c_is1 & t_lt8) | (c_is2 & t_neg);
        if (run_q & i_valid) begin
            if (late) begin
                if (hi_q != 3'h7) begin
                    hi_d = hi_q + 3'h1;
                end
                lo_d = 3'h0;
            end
            else if (early) begin
                if (lo_q != 3'h7) begin
                    lo_d = lo_q + 3'h1;
                end
                hi_d = 3'h0;
            end
            else begin
                hi_d = 3'h0;
                lo_d = 3'h0;
            end
        end
        rem_d = rem_next;
        cnt_d = cnt_next;
        slip_d = 1'b0;
        if (dark_q) begin
            cnt_next = 4'h0;
        end
        start2 = ~run_q & i_valid & ~dark_q & (cnt_q == 4'h1);
        over = ~dark_q & ((i_valid & ~take & (cnt_q >= 4'h8) & (cnt_q != 4'hf)) | (take & ~i_valid & (cnt_q >= 4'ha)) | ((i_valid == take) & (cnt_q >= 4'h9)));
        if (start2) begin
            run_d = 1'b1;
            hi_d = 3'h0;
            lo_d = 3'h0;
            gap_d = 4'h0;
        end
        if (under | over) begin
            slip_d = 1'b1;
            run_d = 1'b0;
            cnt_d = 4'h0;
        end
        if (under) begin
            dark_d = 1'b1;
        end
        o_line = pair_q;
        o_slip = slip_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial sr_q = 8'h0;
    always @(posedge clock) sr_q <= sr_d;
    initial cnt_q = 4'h0;
    always @(posedge clock) cnt_q <= cnt_d;
    initial rem_q = 3'h0;
    always @(posedge clock) rem_q <= rem_d;
    initial lvl_q = 1'h0;
    always @(posedge clock) lvl_q <= lvl_d;
    initial run_q = 1'h0;
    always @(posedge clock) run_q <= run_d;
    initial dark_q = 1'h0;
    always @(posedge clock) dark_q <= dark_d;
    initial since_q = 5'h0;
    always @(posedge clock) since_q <= since_d;
    initial hi_q = 3'h0;
    always @(posedge clock) hi_q <= hi_d;
    initial lo_q = 3'h0;
    always @(posedge clock) lo_q <= lo_d;
    initial gap_q = 4'h0;
    always @(posedge clock) gap_q <= gap_d;
    initial pair_q = 2'h0;
    always @(posedge clock) pair_q <= pair_d;
    initial slip_q = 1'h0;
    always @(posedge clock) slip_q <= slip_d;
endmodule // merkur_slave__fwd__out
// --------------------------------------------------------------------------
// `rep`: Retime, Elastic output buffer with its own bit timing. (rtl/src/line/retime.rs)
// Documented at module `merkur_slave__fwd__out` above.
// --------------------------------------------------------------------------
module merkur_slave__rep(clock,i_valid,i_code,i_phase,o_line,o_slip);

    // Module arguments
    input wire  clock;
    input wire  i_valid;
    input wire  i_code;
    input wire  [1:0] i_phase;
    output reg  [1:0] o_line;
    output reg  o_slip;

    // Constant declarations
    localparam  quiet_bits = 5'b1110;
    localparam  write_shifts = 1'b0;
    localparam  votes = 3'b100;
    localparam  gap_min = 4'h8;
    localparam  one = 8'h1;

    // Registers and child block ports
    reg  [7:0] sr_d;
    reg  [7:0] sr_q;
    reg  [3:0] cnt_d;
    reg  [3:0] cnt_q;
    reg  [2:0] rem_d;
    reg  [2:0] rem_q;
    reg  lvl_d;
    reg  lvl_q;
    reg  run_d;
    reg  run_q;
    reg  dark_d;
    reg  dark_q;
    reg  [4:0] since_d;
    reg  [4:0] since_q;
    reg  [2:0] hi_d;
    reg  [2:0] hi_q;
    reg  [2:0] lo_d;
    reg  [2:0] lo_q;
    reg  [3:0] gap_d;
    reg  [3:0] gap_q;
    reg  [1:0] pair_d;
    reg  [1:0] pair_q;
    reg  slip_d;
    reg  slip_q;

    // Local signals
    reg  send0;
    reg  send1;
    reg  take;
    reg  under;
    reg  oldest;
    reg  [2:0] rpos;
    reg  [7:0] rsel;
    reg  [7:0] sr_shift;
    reg  [2:0] wpos;
    reg  [7:0] wmask;
    reg  new_lvl;
    reg  [2:0] len;
    reg  [3:0] cnt_next;
    reg  [2:0] rem_next;
    reg  t_neg;
    reg  t_pos;
    reg  t_lt8;
    reg  t_gt8;
    reg  c_is0;
    reg  c_is1;
    reg  c_is2;
    reg  c_is3;
    reg  c_ge4;
    reg  late;
    reg  early;
    reg  start2;
    reg  over;

    // Combinational logic
    always @(*) begin
        sr_d = sr_q;
        cnt_d = cnt_q;
        rem_d = rem_q;
        lvl_d = lvl_q;
        run_d = run_q;
        dark_d = dark_q;
        since_d = since_q;
        hi_d = hi_q;
        lo_d = lo_q;
        gap_d = gap_q;
        pair_d = pair_q;
        slip_d = slip_q;
        send0 = rem_q == 3'h0;
        send1 = rem_q == 3'h1;
        take = (send0 | send1) & run_q & (cnt_q != 4'h0);
        oldest = sr_q[0];
        rpos = (~cnt_q[(0)+:(3)]) + 3'h1;
        rsel = sr_q >> rpos;
        if (write_shifts) begin
            oldest = (rsel & 8'h1) != 8'h0;
        end
        under = (send0 | send1) & run_q & (cnt_q == 4'h0);
        new_lvl = lvl_q;
        if ((send0 | send1) & ~dark_q & ~under) begin
            new_lvl = ~lvl_q;
        end
        if ((send0 | send1) & dark_q & (since_q >= quiet_bits)) begin
            dark_d = 1'b0;
        end
        if (take) begin
            new_lvl = lvl_q ^ oldest;
        end
        pair_d = 2'h0;
        if (lvl_q) begin
            pair_d = 2'h3;
        end
        if (send0 & new_lvl) begin
            pair_d = 2'h3;
        end
        if (send0 & ~new_lvl) begin
            pair_d = 2'h0;
        end
        if (send1 & (new_lvl != lvl_q)) begin
            pair_d = 2'h1;
            if (new_lvl) begin
                pair_d = 2'h2;
            end
        end
        lvl_d = new_lvl;
        if (send0 | send1) begin
            if (new_lvl != lvl_q) begin
                since_d = 5'h0;
            end
            else if (since_q != 5'h1f) begin
                since_d = since_q + 5'h1;
            end
        end
        len = 3'h4;
        if (run_q & (gap_q >= gap_min)) begin
            if (hi_q >= votes) begin
                len = 3'h3;
            end
            if (lo_q >= votes) begin
                len = 3'h5;
            end
        end
        rem_next = rem_q ^ 3'h2;
        if (~rem_q[1]) begin
            rem_next = rem_q ^ 3'h6;
        end
        if (send0 | send1) begin
            if (gap_q != 4'hf) begin
                gap_d = gap_q + 4'h1;
            end
            if (len != 3'h4) begin
                gap_d = 4'h0;
                hi_d = 3'h0;
                lo_d = 3'h0;
            end
        end
        if (send0) begin
            rem_next = 3'h2;
            if (len == 3'h3) begin
                rem_next = 3'h1;
            end
            if (len == 3'h5) begin
                rem_next = 3'h3;
            end
        end
        if (send1) begin
            rem_next = 3'h3;
            if (len == 3'h3) begin
                rem_next = 3'h2;
            end
            if (len == 3'h5) begin
                rem_next = 3'h4;
            end
        end
        sr_shift = sr_q;
        if (take) begin
            sr_shift = sr_q >> 1;
        end
        sr_d = sr_shift;
        wpos = cnt_q[(0)+:(3)];
        if (take) begin
            wpos = cnt_q[(0)+:(3)] - 3'h1;
        end
        wmask = one << wpos;
        cnt_next = cnt_q;
        if (take & ~i_valid) begin
            cnt_next = cnt_q - 4'h1;
        end
        if (i_valid) begin
            sr_d = sr_shift & ~wmask;
            if (i_code) begin
                sr_d = sr_shift | wmask;
            end
            if (~take) begin
                cnt_next = cnt_q + 4'h1;
            end
        end
        if (write_shifts) begin
            sr_d = sr_q;
            if (i_valid) begin
                sr_d = sr_q >> 1;
                if (i_code) begin
                    sr_d = (sr_q >> 1) | 8'h80;
                end
            end
        end
        t_neg = ((rem_next == 3'h0) & (i_phase != 2'h0)) | ((rem_next == 3'h1) & (i_phase == 2'h3));
        t_pos = (rem_next >= 3'h2) | ((rem_next == 3'h1) & ~i_phase[1]);
        t_lt8 = (rem_next <= 3'h3) | ((rem_next == 3'h4) & (i_phase != 2'h0)) | ((rem_next == 3'h5) & (i_phase == 2'h3));
        t_gt8 = (rem_next >= 3'h6) | ((rem_next == 3'h5) & ~i_phase[1]);
        c_is0 = cnt_q == 4'hf;
        c_is1 = cnt_q == 4'h0;
        c_is2 = cnt_q == 4'h1;
        c_is3 = cnt_q == 4'h2;
        c_ge4 = (cnt_q >= 4'h3) & (cnt_q != 4'hf);
        if (take) begin
            c_is1 = cnt_q == 4'h1;
            c_is2 = cnt_q == 4'h2;
            c_is3 = cnt_q == 4'h3;
            c_ge4 = cnt_q >= 4'h4;
            c_is0 = 1'b0;
        end
        late = c_ge4 | (c_is0 & t_neg) | (c_is2 & t_gt8) | (c_is3 & t_pos);
        early = (c_is0 & ~t_neg) | (c_is1 & t_lt8) | (c_is2 & t_neg);
        if (run_q & i_valid) begin
            if (late) begin
                if (hi_q != 3'h7) begin
                    hi_d = hi_q + 3'h1;
                end
                lo_d = 3'h0;
            end
            else if (early) begin
                if (lo_q != 3'h7) begin
                    lo_d = lo_q + 3'h1;
                end
                hi_d = 3'h0;
            end
            else begin
                hi_d = 3'h0;
                lo_d = 3'h0;
            end
        end
        rem_d = rem_next;
        cnt_d = cnt_next;
        slip_d = 1'b0;
        if (dark_q) begin
            cnt_next = 4'h0;
        end
        start2 = ~run_q & i_valid & ~dark_q & (cnt_q == 4'h1);
        over = ~dark_q & ((i_valid & ~take & (cnt_q >= 4'h8) & (cnt_q != 4'hf)) | (take & ~i_valid & (cnt_q >= 4'ha)) | ((i_valid == take) & (cnt_q >= 4'h9)));
        if (start2) begin
            run_d = 1'b1;
            hi_d = 3'h0;
            lo_d = 3'h0;
            gap_d = 4'h0;
        end
        if (under | over) begin
            slip_d = 1'b1;
            run_d = 1'b0;
            cnt_d = 4'h0;
        end
        if (under) begin
            dark_d = 1'b1;
        end
        o_line = pair_q;
        o_slip = slip_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial sr_q = 8'h0;
    always @(posedge clock) sr_q <= sr_d;
    initial cnt_q = 4'h0;
    always @(posedge clock) cnt_q <= cnt_d;
    initial rem_q = 3'h0;
    always @(posedge clock) rem_q <= rem_d;
    initial lvl_q = 1'h0;
    always @(posedge clock) lvl_q <= lvl_d;
    initial run_q = 1'h0;
    always @(posedge clock) run_q <= run_d;
    initial dark_q = 1'h0;
    always @(posedge clock) dark_q <= dark_d;
    initial since_q = 5'h0;
    always @(posedge clock) since_q <= since_d;
    initial hi_q = 3'h0;
    always @(posedge clock) hi_q <= hi_d;
    initial lo_q = 3'h0;
    always @(posedge clock) lo_q <= lo_d;
    initial gap_q = 4'h0;
    always @(posedge clock) gap_q <= gap_d;
    initial pair_q = 2'h0;
    always @(posedge clock) pair_q <= pair_d;
    initial slip_q = 1'h0;
    always @(posedge clock) slip_q <= slip_d;
endmodule // merkur_slave__rep
// --------------------------------------------------------------------------
// `rx_bsr`: PortRx, Supervised receive port. (rtl/src/node/port_rx.rs)
//
// # port_rx — one supervised receive port: [`Monitor`] + [`StreamCtl`]
//
// Purpose: what a node has on each logical input (INPUT and BSR): the receive
// chain (CDR, framer, word decoder) and its stream controller.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_samples` | in | 4 | clock | line samples (quadrature DDR, 8 per bit) |
// | `i_slots_m1`, `i_address` | in | 12 | static | as [`crate::line::word_rx::WordRx`] |
// | `i_tst_fail` | in | 1 | static | as [`StreamCtl`] |
// | `i_flush` | in | 1 | clock | as [`Monitor`]; the stream controller's run of bad words restarts |
// | `o_start`, `o_inpkt`, `o_wvalid`, `o_kind`, `o_slot`, `o_data`, `o_alive`, `o_alarm`, `o_ok`, `o_void`, `o_marked`, `o_own`, `o_hdr_bad`, `o_ptype` | out | | clock | as [`Monitor`] |
// | `o_los`, `o_cf`, `o_hard`, `o_run`, `o_tst`, `o_ack` | out | 1 | clock | loss of signal; as [`StreamCtl`] |
// | `o_bvalid`, `o_code`, `o_phase` | out | 1, 1, 2 | clock | recovered bit stream (from the CDR: `o_code` 1 where the line level changed) |
//
// Latency: as [`Monitor`]; stream-controller outputs one clock later.
//
// ```text
// i_samples ~~~~~~ line ~~~~~~|______ dark ______________________
// o_los     ____________________________________/‾‾‾‾‾‾‾‾‾‾‾‾‾‾   32 bit times later
// o_cf      _____________________________________/‾‾‾‾‾‾‾‾‾‾‾‾‾
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr(clock,i_samples,i_slots_m1,i_address,i_tst_fail,i_flush,o_start,o_inpkt,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_void,o_marked,o_own,o_hdr_bad,o_ptype,o_los,o_bvalid,o_code,o_phase,o_cf,o_hard,o_run,o_tst,o_ack);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    input wire  i_tst_fail;
    input wire  i_flush;
    output reg  o_start;
    output reg  o_inpkt;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;
    output reg  o_los;
    output reg  o_bvalid;
    output reg  o_code;
    output reg  [1:0] o_phase;
    output reg  o_cf;
    output reg  o_hard;
    output reg  o_run;
    output reg  o_tst;
    output reg  o_ack;

    // Registers and child block ports
    wire  mon__o_los;
    wire  mon__o_bvalid;
    wire  mon__o_code;
    wire  [1:0] mon__o_phase;
    wire  mon__o_start;
    wire  mon__o_inpkt;
    wire  mon__o_wvalid;
    wire  [1:0] mon__o_kind;
    wire  [11:0] mon__o_slot;
    wire  [15:0] mon__o_data;
    wire  mon__o_alive;
    wire  mon__o_alarm;
    wire  [3:0] mon__o_reason;
    wire  mon__o_ok;
    wire  mon__o_compl;
    wire  mon__o_void;
    wire  mon__o_marked;
    wire  mon__o_own;
    wire  mon__o_hdr_bad;
    wire  [1:0] mon__o_ptype;
    reg  ctrl__i_los;
    reg  ctrl__i_wvalid;
    reg  [1:0] ctrl__i_kind;
    reg  ctrl__i_ok;
    reg  ctrl__i_void;
    reg  ctrl__i_marked;
    reg  ctrl__i_d12;
    reg  ctrl__i_compl;
    reg  [1:0] ctrl__i_ptype;
    wire  ctrl__o_cf;
    wire  ctrl__o_hard;
    wire  ctrl__o_run;
    wire  ctrl__o_tst;
    wire  ctrl__o_ack;

    // Child blocks
    merkur_slave__rx_bsr__mon mon(
        .clock(clock),
        .i_samples(i_samples),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .i_flush(i_flush),
        .o_los(mon__o_los),
        .o_bvalid(mon__o_bvalid),
        .o_code(mon__o_code),
        .o_phase(mon__o_phase),
        .o_start(mon__o_start),
        .o_inpkt(mon__o_inpkt),
        .o_wvalid(mon__o_wvalid),
        .o_kind(mon__o_kind),
        .o_slot(mon__o_slot),
        .o_data(mon__o_data),
        .o_alive(mon__o_alive),
        .o_alarm(mon__o_alarm),
        .o_reason(mon__o_reason),
        .o_ok(mon__o_ok),
        .o_compl(mon__o_compl),
        .o_void(mon__o_void),
        .o_marked(mon__o_marked),
        .o_own(mon__o_own),
        .o_hdr_bad(mon__o_hdr_bad),
        .o_ptype(mon__o_ptype)
    );
    merkur_slave__rx_bsr__ctrl ctrl(
        .clock(clock),
        .i_los(ctrl__i_los),
        .i_wvalid(ctrl__i_wvalid),
        .i_kind(ctrl__i_kind),
        .i_ok(ctrl__i_ok),
        .i_void(ctrl__i_void),
        .i_marked(ctrl__i_marked),
        .i_d12(ctrl__i_d12),
        .i_compl(ctrl__i_compl),
        .i_ptype(ctrl__i_ptype),
        .i_tst_fail(i_tst_fail),
        .i_flush(i_flush),
        .o_cf(ctrl__o_cf),
        .o_hard(ctrl__o_hard),
        .o_run(ctrl__o_run),
        .o_tst(ctrl__o_tst),
        .o_ack(ctrl__o_ack)
    );

    // Combinational logic
    always @(*) begin
        ctrl__i_los = mon__o_los;
        ctrl__i_wvalid = mon__o_wvalid;
        ctrl__i_kind = mon__o_kind;
        ctrl__i_ok = mon__o_ok;
        ctrl__i_void = mon__o_void;
        ctrl__i_marked = mon__o_marked;
        ctrl__i_d12 = mon__o_data[12];
        ctrl__i_compl = mon__o_compl;
        ctrl__i_ptype = mon__o_ptype;
        o_start = mon__o_start;
        o_inpkt = mon__o_inpkt;
        o_wvalid = mon__o_wvalid;
        o_kind = mon__o_kind;
        o_slot = mon__o_slot;
        o_data = mon__o_data;
        o_alive = mon__o_alive;
        o_alarm = mon__o_alarm;
        o_reason = mon__o_reason;
        o_ok = mon__o_ok;
        o_void = mon__o_void;
        o_marked = mon__o_marked;
        o_own = mon__o_own;
        o_hdr_bad = mon__o_hdr_bad;
        o_ptype = mon__o_ptype;
        o_los = mon__o_los;
        o_bvalid = mon__o_bvalid;
        o_code = mon__o_code;
        o_phase = mon__o_phase;
        o_cf = ctrl__o_cf;
        o_hard = ctrl__o_hard;
        o_run = ctrl__o_run;
        o_tst = ctrl__o_tst;
        o_ack = ctrl__o_ack;
    end

endmodule // merkur_slave__rx_bsr
// --------------------------------------------------------------------------
// `ctrl`: StreamCtl, Stream controller. (rtl/src/node/stream_ctl.rs)
//
// # stream_ctl — stream controller: channel failure and test signal (protocol §9)
//
// Purpose: supervises one logical input (INPUT: the primary controller,
// `pcf`/`ptst`; BSR: the secondary one, `scf`/`stst`) from the words its
// receive chain ([`crate::line::monitor`]) decodes.
//
// Channel failure `o_cf` is any of:
// - loss of signal (no line transition for 32 bit times, from the CDR);
// - a test signal while `i_tst_fail` (mode N on INPUT: a TST where DATA is
//   expected means the upstream neighbour has wrapped);
// - 8 consecutive bad words damaged on this fibre (parity or code errors;
//   VOID words are not bad, marked words — damaged on an earlier fibre,
//   protocol §4 — leave the count as it is), until the next good word, or
//   until the switchbox moves the input to another line (`i_flush`: a run
//   is a property of one channel; carried over, it would make a node that
//   wrapped because of it fail safe as soon as the settling time after the
//   change is over).
//
// The first two are structural (`o_hard`: a dark fibre, a dead or wrapped
// neighbour), the last a transient (`o_run`): a node decides differently on
// them (protocol §9, §12; [`crate::node::switch_ctl`]).
//
// Test signal `o_tst`: a good TST packet (H0 type 10, H1 = NOT H0) was
// received within the last 130 bit times (2 TST periods); `o_ack` is the
// ACK bit of the last one.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_los` | in | 1 | clock | loss of signal |
// | `i_wvalid`, `i_kind`, `i_ok`, `i_void`, `i_marked`, `i_compl`, `i_ptype` | in | | clock | word outputs of the receive chain (`i_compl`: data = NOT the previous word's, [`crate::line::word_rx`]) |
// | `i_d12` | in | 1 | clock | the word's data bit 12 (a TST's H1 carries NOT ACK there) |
// | `i_tst_fail` | in | 1 | static | a test signal counts as channel failure |
// | `i_flush` | in | 1 | clock | the input moved to another line: the run of bad words restarts |
// | `o_cf` | out | 1 | clock | channel failure (`o_hard` or `o_run`) |
// | `o_hard` | out | 1 | clock | loss of signal, or a test signal while `i_tst_fail` |
// | `o_run` | out | 1 | clock | 8 bad words in a row damaged on this fibre |
// | `o_tst` | out | 1 | clock | test signal |
// | `o_ack` | out | 1 | clock | ACK of the last TST |
//
// Latency: registered, one clock after the word or LOS that decides.
//
// ```text
// words      TST   TST   TST   (idle ...............................)
// o_tst      __/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\____   130 bit times after the last
// o_cf       __/‾‾‾‾ ... (only with i_tst_fail) ‾‾‾‾‾‾‾‾‾‾‾‾\____
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__ctrl(clock,i_los,i_wvalid,i_kind,i_ok,i_void,i_marked,i_d12,i_compl,i_ptype,i_tst_fail,i_flush,o_cf,o_hard,o_run,o_tst,o_ack);

    // Module arguments
    input wire  clock;
    input wire  i_los;
    input wire  i_wvalid;
    input wire  [1:0] i_kind;
    input wire  i_ok;
    input wire  i_void;
    input wire  i_marked;
    input wire  i_d12;
    input wire  i_compl;
    input wire  [1:0] i_ptype;
    input wire  i_tst_fail;
    input wire  i_flush;
    output reg  o_cf;
    output reg  o_hard;
    output reg  o_run;
    output reg  o_tst;
    output reg  o_ack;

    // Constant declarations
    localparam  hold_after = 9'b100000010;
    localparam  bad_max = 4'h8;

    // Registers and child block ports
    reg  [3:0] bad_d;
    reg  [3:0] bad_q;
    reg  [8:0] hold_d;
    reg  [8:0] hold_q;
    reg  hold_ld_d;
    reg  hold_ld_q;
    reg  tst_d;
    reg  tst_q;
    reg  ack_d;
    reg  ack_q;
    reg  hard_d;
    reg  hard_q;
    reg  run_d;
    reg  run_q;

    // Combinational logic
    always @(*) begin
        bad_d = bad_q;
        hold_d = hold_q;
        hold_ld_d = hold_ld_q;
        tst_d = tst_q;
        ack_d = ack_q;
        hard_d = hard_q;
        run_d = run_q;
        if (i_wvalid) begin
            if (i_ok) begin
                bad_d = 4'h0;
            end
            else if (~i_void & ~i_marked & (bad_q != bad_max)) begin
                bad_d = bad_q + 4'h1;
            end
        end
        if (i_flush) begin
            bad_d = 4'h0;
        end
        hold_ld_d = 1'b0;
        if (tst_q) begin
            hold_d = hold_q - 9'h1;
            if (hold_ld_q) begin
                hold_d = hold_after;
            end
            if (~hold_ld_q & (hold_q == 9'h0)) begin
                tst_d = 1'b0;
            end
        end
        if (i_wvalid & (i_kind == 2'h1) & i_ok & (i_ptype == 2'h2) & i_compl) begin
            tst_d = 1'b1;
            ack_d = ~i_d12;
            hold_ld_d = 1'b1;
        end
        hard_d = i_los | (tst_q & i_tst_fail);
        run_d = (bad_q == bad_max) & ~i_flush;
        o_cf = hard_q | run_q;
        o_hard = hard_q;
        o_run = run_q;
        o_tst = tst_q;
        o_ack = ack_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial bad_q = 4'h0;
    always @(posedge clock) bad_q <= bad_d;
    initial hold_q = 9'h0;
    always @(posedge clock) hold_q <= hold_d;
    initial hold_ld_q = 1'h0;
    always @(posedge clock) hold_ld_q <= hold_ld_d;
    initial tst_q = 1'h0;
    always @(posedge clock) tst_q <= tst_d;
    initial ack_q = 1'h0;
    always @(posedge clock) ack_q <= ack_d;
    initial hard_q = 1'h0;
    always @(posedge clock) hard_q <= hard_d;
    initial run_q = 1'h0;
    always @(posedge clock) run_q <= run_d;
endmodule // merkur_slave__rx_bsr__ctrl
// --------------------------------------------------------------------------
// `mon`: Monitor, Fibre monitor / receive chain. (rtl/src/line/monitor.rs)
//
// # monitor — fibre monitor: decodes what a line carries (protocol §2–§5)
//
// Purpose: the receive chain of a node without the node: [`Cdr`] →
// [`FramerRx`] → [`WordRx`]. Ring tops put one on every fibre; its word
// outputs are what is compared with the model's trace (cycle, slot, data,
// parity ok), and its packet and slot position is where a fault is placed at
// a given (cycle, slot). It is also the receive half of every node.
//
// Parameters: the word format ([`WordFormat`]), as [`WordRx::new`].
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_samples` | in | 4 | clock | line samples (quadrature DDR, 8 per bit), bit 0 first |
// | `i_slots_m1`, `i_address` | in | 12 | static | as [`WordRx`] |
// | `i_flush` | in | 1 | clock | the input was switched to another line: the packet ends, a held word is dropped |
// | `o_los` | out | 1 | clock | loss of signal |
// | `o_bvalid`, `o_code`, `o_phase` | out | 1, 1, 2 | clock | recovered bit stream (from the CDR: `o_code` 1 where the line level changed) |
// | `o_start` | out | 1 | clock | J K found |
// | `o_inpkt` | out | 1 | clock | inside a packet |
// | `o_wvalid` … `o_ptype` | out | | clock | as [`WordRx`] |
//
// **Confirmation.** A word is passed on only when the line shows an edge
// (a code 1) after its last bit: every group that can follow a word (data,
// S, idle) has a 1 in its first two bits. A word the line died in would
// otherwise be completed by the zeros the clock recovery reads from a dark
// line before it mutes, and could pass both parities with a foreign
// value; with no recovered bit for [`DROP_CLOCKS`] clocks the held word is dropped
// (not received, as the model's "missing") and the packet ends there. Upstream nodes keep their line
// dark after such a stop ([`crate::line::retime::QUIET_BITS`]), so no idle can
// confirm it either.
//
// The held word is not copied: the outputs are the word decoder's
// registers, which keep it until the next group is complete — 3 bit
// times or more after the confirming edge, which must come within the
// next group's first two bits. Consumers take a word in the clock of
// `o_wvalid` (issue 21: one copy of a word instead of three).
//
// Latency from a word's last line bit to `o_wvalid`: CDR 2–3 clocks +
// framer 1 + word 1 + the registered outputs 1 ≈ 3 bit times, plus up to
// 2 bit times until the confirming edge.
//
// ```text
// line      ~~~| J K | H0 | H1 | slot 0 | ... | slot S-1 |~~~ idle
// o_start        ^
// o_wvalid            ^    ^     ^              ^   (each ~2.5 bit times after its word)
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon(clock,i_samples,i_slots_m1,i_address,i_flush,o_los,o_bvalid,o_code,o_phase,o_start,o_inpkt,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_compl,o_void,o_marked,o_own,o_hdr_bad,o_ptype);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    input wire  i_flush;
    output reg  o_los;
    output reg  o_bvalid;
    output reg  o_code;
    output reg  [1:0] o_phase;
    output reg  o_start;
    output reg  o_inpkt;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_compl;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;

    // Constant declarations
    localparam  drop_after = 3'b100;

    // Registers and child block ports
    wire  cdr__o_valid;
    wire  cdr__o_bit;
    wire  cdr__o_code;
    wire  cdr__o_los;
    wire  [1:0] cdr__o_phase;
    reg  framer__i_valid;
    reg  framer__i_code;
    reg  framer__i_end;
    wire  framer__o_start;
    wire  framer__o_gvalid;
    wire  [4:0] framer__o_group;
    wire  framer__o_idle;
    wire  framer__o_inpkt;
    reg  word__i_start;
    reg  word__i_gvalid;
    reg  [4:0] word__i_group;
    reg  word__i_idle;
    wire  word__o_end;
    wire  word__o_wvalid;
    wire  [1:0] word__o_kind;
    wire  [11:0] word__o_slot;
    wire  [15:0] word__o_data;
    wire  word__o_alive;
    wire  word__o_alarm;
    wire  [3:0] word__o_reason;
    wire  word__o_ok;
    wire  word__o_compl;
    wire  word__o_void;
    wire  word__o_marked;
    wire  word__o_own;
    wire  word__o_hdr_bad;
    wire  [1:0] word__o_ptype;
    reg  [2:0] quiet_d;
    reg  [2:0] quiet_q;
    reg  emit_d;
    reg  emit_q;
    reg  p_valid_d;
    reg  p_valid_q;

    // Local signals
    reg  conf_edge;

    // Child blocks
    merkur_slave__rx_bsr__mon__cdr cdr(
        .clock(clock),
        .i_samples(i_samples),
        .o_valid(cdr__o_valid),
        .o_bit(cdr__o_bit),
        .o_code(cdr__o_code),
        .o_los(cdr__o_los),
        .o_phase(cdr__o_phase)
    );
    merkur_slave__rx_bsr__mon__framer framer(
        .clock(clock),
        .i_valid(framer__i_valid),
        .i_code(framer__i_code),
        .i_end(framer__i_end),
        .o_start(framer__o_start),
        .o_gvalid(framer__o_gvalid),
        .o_group(framer__o_group),
        .o_idle(framer__o_idle),
        .o_inpkt(framer__o_inpkt)
    );
    merkur_slave__rx_bsr__mon__word word(
        .clock(clock),
        .i_start(word__i_start),
        .i_gvalid(word__i_gvalid),
        .i_group(word__i_group),
        .i_idle(word__i_idle),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .o_end(word__o_end),
        .o_wvalid(word__o_wvalid),
        .o_kind(word__o_kind),
        .o_slot(word__o_slot),
        .o_data(word__o_data),
        .o_alive(word__o_alive),
        .o_alarm(word__o_alarm),
        .o_reason(word__o_reason),
        .o_ok(word__o_ok),
        .o_compl(word__o_compl),
        .o_void(word__o_void),
        .o_marked(word__o_marked),
        .o_own(word__o_own),
        .o_hdr_bad(word__o_hdr_bad),
        .o_ptype(word__o_ptype)
    );

    // Combinational logic
    always @(*) begin
        quiet_d = quiet_q;
        emit_d = emit_q;
        p_valid_d = p_valid_q;
        framer__i_valid = cdr__o_valid;
        framer__i_code = cdr__o_code;
        framer__i_end = word__o_end | cdr__o_los | (quiet_q == drop_after) | i_flush;
        word__i_start = framer__o_start;
        word__i_gvalid = framer__o_gvalid;
        word__i_group = framer__o_group;
        word__i_idle = framer__o_idle;
        o_los = cdr__o_los;
        o_bvalid = cdr__o_valid;
        o_code = cdr__o_code;
        o_phase = cdr__o_phase;
        o_start = framer__o_start;
        o_inpkt = framer__o_inpkt;
        o_hdr_bad = word__o_hdr_bad;
        conf_edge = cdr__o_valid & cdr__o_code;
        if (cdr__o_valid) begin
            quiet_d = 3'h0;
        end
        else if (quiet_q != 3'h7) begin
            quiet_d = quiet_q + 3'h1;
        end
        emit_d = 1'b0;
        o_wvalid = emit_q;
        o_kind = word__o_kind;
        o_slot = word__o_slot;
        o_data = word__o_data;
        o_alive = word__o_alive;
        o_alarm = word__o_alarm;
        o_reason = word__o_reason;
        o_ok = word__o_ok;
        o_compl = word__o_compl;
        o_void = word__o_void;
        o_marked = word__o_marked;
        o_own = word__o_own;
        o_ptype = word__o_ptype;
        if (p_valid_q & conf_edge) begin
            emit_d = 1'b1;
            p_valid_d = 1'b0;
        end
        if (p_valid_q & ((quiet_q == drop_after) | i_flush)) begin
            p_valid_d = 1'b0;
        end
        if (word__o_wvalid) begin
            p_valid_d = ~conf_edge;
            emit_d = conf_edge;
        end
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial quiet_q = 3'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial emit_q = 1'h0;
    always @(posedge clock) emit_q <= emit_d;
    initial p_valid_q = 1'h0;
    always @(posedge clock) p_valid_q <= p_valid_d;
endmodule // merkur_slave__rx_bsr__mon
// --------------------------------------------------------------------------
// `cdr`: Cdr, Oversampling clock and data recovery. (rtl/src/line/cdr.rs)
//
// # cdr — clock and data recovery by oversampling (protocol §9)
//
// Purpose: recovers line bits from an asynchronous NRZI line sampled
// [`SAMPLES_PER_BIT`] = 8 times per bit time. The core clock runs at 2× the
// line rate and takes [`SAMPLES_PER_CLOCK`] = 4 samples per clock (quadrature
// DDR capture in hardware: both edges of the core clock and of its 90°
// copy; `i_samples[0]` is the earliest). Every transition restarts a sample
// counter; the bit is taken 4 samples after the last transition (the first
// sample showing the new level) and every 8 samples after that, so the
// sampling point follows the incoming stream: clock offsets between the
// sender and the receiver (±1000 ppm each) and edge jitter are absorbed
// without slipping a bit. An edge interval of k bits is read as k bits when
// it measures 8k − 3 … 8k + 4 samples: the sender's retimer
// ([`crate::line::retime`]) moves an edge by at most 2 samples (one output half
// clock), which leaves a sample of margin. Tested
// (`sim/tests/cdr.rs`): 10^6 bits at ±2000 ppm relative offset with
// every bit boundary moved by up to ±1.4 samples; ±2.2 samples is shown to
// fail. At most one bit is recovered per clock, with its level (`o_bit`)
// and its code (`o_code`, NRZI-decoded: the level changed), so the
// framer, the forwarder and the repeaters read one decode, not one each.
//
// A dead line: after [`MUTE_SAMPLES`] (8 bit times) without a transition no
// more bits are taken, so a break passes on a cut-short packet, not a run
// of zeros. Legal streams toggle at least every 4 bit times, but one
// line-bit error inverts two adjacent code bits and can leave up to 6 zero
// code bits inside a packet (an edge interval of 7 bit times; tested,
// `sim/tests/cdr.rs`): that must cost a word, not mute the receiver
// for the rest of the frame (protocol §5). An interval of up to 8 bit
// times is read whole. Loss of signal: no transition for [`LOS_SAMPLES`] =
// 256 samples (32 bit times) raises `o_los` until the next transition.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_samples` | in | 4 | clock | line samples, bit 0 first in time |
// | `o_valid` | out | 1 | clock | `o_bit` holds a recovered bit |
// | `o_bit` | out | 1 | clock | recovered line level (NRZI, not yet decoded) |
// | `o_code` | out | 1 | clock | the bit decoded: 1 when its level differs from the previous recovered bit's (NRZI 1) |
// | `o_los` | out | 1 | clock | loss of signal (no edge for 32 bit times) |
// | `o_phase` | out | 2 | clock | which sample of its clock the bit was taken from (0 first) |
//
// Latency: `o_valid`/`o_bit`/`o_code`/`o_phase` are registered: a bit appears one
// clock after the clock whose samples contained its centre (4 samples after
// its edge), so 0.5–1 bit time after the edge.
//
// ```text
// samples  0 0 0 0 0 0 0 0 | 1 1 1 1 1 1 1 1 | 1 1 1 1 1 1 1 1 | 0 0 ...   (8 per bit, 4 per clock)
// count    . . . . 4 . . .   0 1 2 3 4 5 6 7   0 1 2 3 4 5 6 7   0         (restarts at each edge)
// take             ^                 ^                 ^                   (count == 4)
// o_valid  ________/‾‾\_____________/‾‾\_____________/‾‾\____              (one clock later)
// o_bit             0                 1                 1
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__cdr(clock,i_samples,o_valid,o_bit,o_code,o_los,o_phase);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    output reg  o_valid;
    output reg  o_bit;
    output reg  o_code;
    output reg  o_los;
    output reg  [1:0] o_phase;

    // Constant declarations
    localparam  quiet_last = 6'b111111;
    localparam  mute_last = 6'b1111;

    // Registers and child block ports
    reg  last_d;
    reg  last_q;
    reg  [1:0] phase_d;
    reg  [1:0] phase_q;
    reg  [2:0] count_d;
    reg  [2:0] count_q;
    reg  [5:0] quiet_d;
    reg  [5:0] quiet_q;
    reg  calm_d;
    reg  calm_q;
    reg  mute_d;
    reg  mute_q;
    reg  rx_valid_d;
    reg  rx_valid_q;
    reg  rx_bit_d;
    reg  rx_bit_q;
    reg  rx_code_d;
    reg  rx_code_q;
    reg  los_flag_d;
    reg  los_flag_q;

    // Local signals
    reg  [3:0] prior;
    reg  [3:0] edges;
    reg  still;
    reg  clean;
    reg  [1:0] take_at;
    reg  taken;

    // Combinational logic
    always @(*) begin
        last_d = last_q;
        phase_d = phase_q;
        count_d = count_q;
        quiet_d = quiet_q;
        calm_d = calm_q;
        mute_d = mute_q;
        rx_valid_d = rx_valid_q;
        rx_bit_d = rx_bit_q;
        rx_code_d = rx_code_q;
        los_flag_d = los_flag_q;
        prior = i_samples << 1;
        if (last_q) begin
            prior = (i_samples << 1) | 4'h1;
        end
        edges = i_samples ^ prior;
        count_d = count_q ^ 3'h4;
        if (edges[0]) begin
            count_d = 3'h3;
        end
        if (edges[1]) begin
            count_d = 3'h2;
        end
        if (edges[2]) begin
            count_d = 3'h1;
        end
        if (edges[3]) begin
            count_d = 3'h0;
        end
        last_d = i_samples[3];
        clean = ~edges[0];
        if (count_q[(0)+:(2)] == 2'h2) begin
            clean = ~edges[0] & ~edges[1];
        end
        if (count_q[(0)+:(2)] == 2'h1) begin
            clean = ~edges[0] & ~edges[1] & ~edges[2];
        end
        if (count_q[(0)+:(2)] == 2'h0) begin
            clean = ~|edges;
        end
        take_at = ~count_q[(0)+:(2)];
        taken = i_samples[take_at];
        rx_valid_d = 1'b0;
        if (~count_q[2] & clean & ~mute_q) begin
            rx_valid_d = 1'b1;
            rx_bit_d = taken;
            rx_code_d = taken ^ rx_bit_q;
            phase_d = take_at;
        end
        still = ~|edges;
        calm_d = still;
        if (~calm_q) begin
            quiet_d = 6'h1;
        end
        else if (~los_flag_q) begin
            quiet_d = quiet_q + 6'h1;
        end
        mute_d = still & calm_q & (los_flag_q | (quiet_q >= mute_last));
        if (~still) begin
            los_flag_d = 1'b0;
        end
        else if (calm_q & (quiet_q == quiet_last)) begin
            los_flag_d = 1'b1;
        end
        o_valid = rx_valid_q;
        o_bit = rx_bit_q;
        o_code = rx_code_q;
        o_los = los_flag_q;
        o_phase = phase_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial last_q = 1'h0;
    always @(posedge clock) last_q <= last_d;
    initial phase_q = 2'h0;
    always @(posedge clock) phase_q <= phase_d;
    initial count_q = 3'h0;
    always @(posedge clock) count_q <= count_d;
    initial quiet_q = 6'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial calm_q = 1'h0;
    always @(posedge clock) calm_q <= calm_d;
    initial mute_q = 1'h0;
    always @(posedge clock) mute_q <= mute_d;
    initial rx_valid_q = 1'h0;
    always @(posedge clock) rx_valid_q <= rx_valid_d;
    initial rx_bit_q = 1'h0;
    always @(posedge clock) rx_bit_q <= rx_bit_d;
    initial rx_code_q = 1'h0;
    always @(posedge clock) rx_code_q <= rx_code_d;
    initial los_flag_q = 1'h0;
    always @(posedge clock) los_flag_q <= los_flag_d;
endmodule // merkur_slave__rx_bsr__mon__cdr
// --------------------------------------------------------------------------
// `framer`: FramerRx, J K hunter and group aligner. (rtl/src/line/framer_rx.rs)
//
// # framer_rx — start-delimiter (CS) detector, group aligner (protocol §2, §3)
//
// Purpose: turns recovered code bits (NRZI-decoded by [`crate::line::cdr`])
// into code groups. While hunting it
// compares the last 10 code bits with J K at every bit position; on a match
// it pulses `o_start` and from then on emits one 5-bit group every 5 code
// bits, until the word layer says the packet has ended (`i_end`: after the
// last slot, after a TST/SEC packet's two words, on a bad header, on loss of
// signal). The end is not taken from the line: one flipped line bit can turn
// two data groups into idles, and that must cost one word, not the frame.
// J K inside a packet is not searched for, so data can never re-align a
// packet (and §3 shows data cannot imitate J K anyway).
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock |
// | `i_valid` | in | 1 | clock | `i_code` holds a recovered bit (from [`crate::line::cdr`]) |
// | `i_code` | in | 1 | clock | its code bit (1: the line level changed) |
// | `i_end` | in | 1 | clock | leave the packet, hunt for J K again |
// | `o_start` | out | 1 | clock | J K found; the next group is the packet's first |
// | `o_gvalid` | out | 1 | clock | `o_group` holds a group of the packet |
// | `o_group` | out | 5 | clock | code group, bit 4 first on the line |
// | `o_idle` | out | 1 | clock | `o_group` is the idle group 11111 (decided with it, so the word layer's packet-end check starts from a flip-flop) |
// | `o_inpkt` | out | 1 | clock | aligned inside a packet |
//
// Latency: registered outputs, one clock after the `i_valid` that completes
// the delimiter or group.
//
// ```text
// code bits  1 1 1 1 1 | 1 1 0 0 0 | 1 0 0 0 1 | g g g g g | g g g g g | 1 1 1 1 1
//                 I          J           K         group 0     group 1       I
// o_start    ______________________/‾\_____________________________________________
// o_gvalid   __________________________________/‾\_________/‾\_________/‾\________
// i_end      ____________________________________________________/‾\__________
// o_inpkt    ______________________/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\___________
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__framer(clock,i_valid,i_code,i_end,o_start,o_gvalid,o_group,o_idle,o_inpkt);

    // Module arguments
    input wire  clock;
    input wire  i_valid;
    input wire  i_code;
    input wire  i_end;
    output reg  o_start;
    output reg  o_gvalid;
    output reg  [4:0] o_group;
    output reg  o_idle;
    output reg  o_inpkt;

    // Constant declarations
    localparam  jk = 10'b1100010001;

    // Registers and child block ports
    reg  [9:0] window_d;
    reg  [9:0] window_q;
    reg  inpkt_d;
    reg  inpkt_q;
    reg  [2:0] count_d;
    reg  [2:0] count_q;
    reg  start_d;
    reg  start_q;
    reg  gvalid_d;
    reg  gvalid_q;
    reg  [4:0] group_d;
    reg  [4:0] group_q;
    reg  idle_d;
    reg  idle_q;

    // Local signals
    reg  [9:0] shifted;

    // Combinational logic
    always @(*) begin
        window_d = window_q;
        inpkt_d = inpkt_q;
        count_d = count_q;
        start_d = start_q;
        gvalid_d = gvalid_q;
        group_d = group_q;
        idle_d = idle_q;
        start_d = 1'b0;
        gvalid_d = 1'b0;
        shifted = window_q << 1;
        if (i_code) begin
            shifted = (window_q << 1) | 10'h1;
        end
        if (i_valid) begin
            window_d = shifted;
            if (inpkt_q) begin
                if (count_q == 3'h4) begin
                    count_d = 3'h0;
                    gvalid_d = 1'b1;
                    group_d = shifted[(0)+:(5)];
                    idle_d = shifted[(0)+:(5)] == 5'h1f;
                end
                else begin
                    count_d = count_q + 3'h1;
                end
            end
            else if (shifted == jk) begin
                inpkt_d = 1'b1;
                start_d = 1'b1;
                count_d = 3'h0;
            end
        end
        if (i_end) begin
            inpkt_d = 1'b0;
        end
        o_start = start_q;
        o_gvalid = gvalid_q;
        o_group = group_q;
        o_idle = idle_q;
        o_inpkt = inpkt_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial window_q = 10'h0;
    always @(posedge clock) window_q <= window_d;
    initial inpkt_q = 1'h0;
    always @(posedge clock) inpkt_q <= inpkt_d;
    initial count_q = 3'h0;
    always @(posedge clock) count_q <= count_d;
    initial start_q = 1'h0;
    always @(posedge clock) start_q <= start_d;
    initial gvalid_q = 1'h0;
    always @(posedge clock) gvalid_q <= gvalid_d;
    initial group_q = 5'h0;
    always @(posedge clock) group_q <= group_d;
    initial idle_q = 1'h0;
    always @(posedge clock) idle_q <= idle_d;
endmodule // merkur_slave__rx_bsr__mon__framer
// --------------------------------------------------------------------------
// `word`: WordRx, Word assembler and checker. (rtl/src/line/word_rx.rs)
//
// # word_rx — word assembler, parity check, slot counter (protocol §4, §5, §7)
//
// Purpose: the receive half of the paper's slot shift register. It collects
// the code groups of a packet (from [`crate::line::framer_rx`]) into words,
// decodes them (4B/5B), checks both odd parities, counts words into header
// words and slots (or a retransmission packet's request words, protocol
// §8), checks the header (type, slot count), compares the slot
// number with the node's address (DIP switches → `i_address`) and tells the
// framer when the packet ends: after its last word, or at the third idle
// group in a row (a packet cut short upstream: the word in progress and the
// rest are not received; one line-bit error touches at most two groups, so
// it costs a word, never the packet).
//
// Parameters (refused at build when invalid): `ext` — extended-alarm words
// of 6 groups instead of 5 (protocol §6).
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock |
// | `i_start` | in | 1 | clock | packet start (J K found) |
// | `i_gvalid` | in | 1 | clock | `i_group` is valid |
// | `i_group` | in | 5 | clock | code group |
// | `i_idle` | in | 1 | clock | `i_group` is the idle group 11111 (from [`crate::line::framer_rx`]'s register) |
// | `i_slots_m1` | in | 12 | static | configured slot count − 1 |
// | `i_address` | in | 12 | static | node address (home slot) |
// | `o_end` | out | 1 | clock | packet over (to the framer's `i_end`) |
// | `o_wvalid` | out | 1 | clock | a word is complete |
// | `o_kind` | out | 2 | clock | 0 H0, 1 H1, 2 slot, 3 an RTX's request word (after a good RTX head: H1 = NOT H0) |
// | `o_slot` | out | 12 | clock | slot number (`o_kind` = 2); the request word's number (`o_kind` = 3: even an index word, odd a data word) |
// | `o_data` | out | 16 | clock | data bits |
// | `o_alive`, `o_alarm` | out | 1 | clock | flag bits |
// | `o_reason` | out | 4 | clock | reason nibble (ext only, else 0) |
// | `o_ok` | out | 1 | clock | all groups data, both parities odd |
// | `o_compl` | out | 1 | clock | its 16 data bits are the complement of the previous word's (a TST's H1 = NOT H0, protocol §9; meaningful for a good word whose predecessor in the packet was good) |
// | `o_void` | out | 1 | clock | all groups S (VOID word) |
// | `o_marked` | out | 1 | clock | bad, its last group T: a forwarder marked it (damaged on an earlier fibre, protocol §4) |
// | `o_own` | out | 1 | clock | slot word of `i_address` |
// | `o_hdr_bad` | out | 1 | clock | DATA header rejected; packet dropped |
// | `o_ptype` | out | 2 | clock | packet type from a good H0 (00 DATA, 01 SEC, 10 TST, 11 RTX) |
//
// Latency: outputs are registered, one clock after the word's last group;
// the word's fields (`o_kind` … `o_ptype`) are the decoder's own registers,
// not copies: they hold from `o_wvalid` until the next group arrives (on a
// line at least 5 bit times later), and a consumer takes them before that
// (issue 21: no second copy of a word in the slave);
// `o_end` and `o_hdr_bad` one clock later (the header is checked on the
// registered word).
//
// ```text
// i_start   _/‾\__________________________________________________
// i_gvalid  _____/‾\_/‾\_/‾\_/‾\_/‾\___ ... _/‾\_/‾\ ... _/‾\_______
//                 H0 (5 groups)              H1        last slot
// o_wvalid  _______________________/‾\_______/‾\______ ... __/‾\____
// o_kind                            0         1               2
// o_end     _____________________________________________ ... /‾\____
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__word(clock,i_start,i_gvalid,i_group,i_idle,i_slots_m1,i_address,o_end,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_compl,o_void,o_marked,o_own,o_hdr_bad,o_ptype);

    // Module arguments
    input wire  clock;
    input wire  i_start;
    input wire  i_gvalid;
    input wire  [4:0] i_group;
    input wire  i_idle;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    output reg  o_end;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_compl;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;

    // Constant declarations
    localparam  last_group = 3'b100;

    // Registers and child block ports
    wire  [3:0] dec__o_nibble;
    wire  dec__o_data;
    wire  dec__o_j;
    wire  dec__o_k;
    wire  dec__o_i;
    wire  dec__o_s;
    reg  [3:0] nib_top__address;
    wire  [23:0] nib_top__data;
    reg  [2:0] gcount_d;
    reg  [2:0] gcount_q;
    reg  [1:0] idles_d;
    reg  [1:0] idles_q;
    reg  [23:0] raw_d;
    reg  [23:0] raw_q;
    reg  par_a_d;
    reg  par_a_q;
    reg  par_b_d;
    reg  par_b_q;
    reg  all_data_d;
    reg  all_data_q;
    reg  all_s_d;
    reg  all_s_q;
    reg  active_d;
    reg  active_q;
    reg  [1:0] wcount_d;
    reg  [1:0] wcount_q;
    reg  [11:0] slot_d;
    reg  [11:0] slot_q;
    reg  slot_inc_d;
    reg  slot_inc_q;
    reg  slot_clr_d;
    reg  slot_clr_q;
    reg  [1:0] ptype_d;
    reg  [1:0] ptype_q;
    reg  check_d;
    reg  check_q;
    reg  end_r_d;
    reg  end_r_q;
    reg  wvalid_r_d;
    reg  wvalid_r_q;
    reg  [1:0] kind_r_d;
    reg  [1:0] kind_r_q;
    reg  adv_d;
    reg  adv_q;
    reg  ok_r_d;
    reg  ok_r_q;
    reg  compl_d;
    reg  compl_q;
    reg  compl_r_d;
    reg  compl_r_q;
    reg  void_r_d;
    reg  void_r_q;
    reg  marked_r_d;
    reg  marked_r_q;
    reg  own_r_d;
    reg  own_r_q;
    reg  hdr_bad_r_d;
    reg  hdr_bad_r_q;

    // Local signals
    reg  [3:0] nib;
    reg  [15:0] data;
    reg  alarm;
    reg  alive;
    reg  [3:0] reason;
    reg  [3:0] prev_nib;
    reg  [15:0] d_lo;
    reg  [15:0] d_hi;
    reg  [15:0] d_mid;
    reg  w_pa;
    reg  w_pb;
    reg  w_all_data;
    reg  w_all_s;
    reg  w_ok;
    reg  w_compl;

    // Child blocks
    merkur_slave__rx_bsr__mon__word__dec dec(
        .i_code(i_group),
        .o_nibble(dec__o_nibble),
        .o_data(dec__o_data),
        .o_j(dec__o_j),
        .o_k(dec__o_k),
        .o_i(dec__o_i),
        .o_s(dec__o_s)
    );
    merkur_slave__rx_bsr__mon__word__nib_top nib_top(
        .address(nib_top__address),
        .data(nib_top__data)
    );

    // Combinational logic
    always @(*) begin
        gcount_d = gcount_q;
        raw_d = raw_q;
        par_a_d = par_a_q;
        par_b_d = par_b_q;
        all_data_d = all_data_q;
        all_s_d = all_s_q;
        active_d = active_q;
        wcount_d = wcount_q;
        slot_d = slot_q;
        slot_inc_d = slot_inc_q;
        slot_clr_d = slot_clr_q;
        ptype_d = ptype_q;
        check_d = check_q;
        end_r_d = end_r_q;
        wvalid_r_d = wvalid_r_q;
        kind_r_d = kind_r_q;
        adv_d = adv_q;
        ok_r_d = ok_r_q;
        compl_d = compl_q;
        compl_r_d = compl_r_q;
        void_r_d = void_r_q;
        marked_r_d = marked_r_q;
        own_r_d = own_r_q;
        hdr_bad_r_d = hdr_bad_r_q;
        idles_d = idles_q;
        nib = dec__o_nibble;
        nib_top__address = dec__o_nibble;
        d_hi = raw_q[(7)+:(16)] & 16'hc000;
        d_mid = raw_q[(6)+:(16)] & 16'h3ffc;
        d_lo = raw_q[(4)+:(16)] & 16'h3;
        prev_nib = raw_q[(4)+:(4)];
        alarm = raw_q[7];
        alive = raw_q[6];
        reason = 4'h0;
        if (last_group == 3'h5) begin
            d_lo = raw_q[(0)+:(16)] & 16'h3;
            prev_nib = raw_q[(0)+:(4)];
            alarm = raw_q[3];
            alive = raw_q[2];
            reason = raw_q[(4)+:(4)];
        end
        data = d_hi | d_mid | d_lo;
        w_pa = par_a_q ^ nib[3] ^ nib[2];
        w_pb = par_b_q ^ nib[2] ^ nib[1] ^ nib[0];
        w_all_data = all_data_q & dec__o_data;
        w_all_s = all_s_q & dec__o_s;
        w_ok = w_all_data & w_pa & w_pb;
        w_compl = compl_q & (nib == ~prev_nib);
        if (gcount_q == 3'h0) begin
            w_compl = nib[(0)+:(2)] == ~prev_nib[(0)+:(2)];
        end
        if (gcount_q == last_group) begin
            w_compl = compl_q & (nib[(1)+:(2)] == ~prev_nib[(1)+:(2)]);
        end
        if ((gcount_q == 3'h1) & (last_group == 3'h5)) begin
            w_compl = compl_q;
        end
        slot_inc_d = 1'b0;
        slot_clr_d = 1'b0;
        if (slot_clr_q) begin
            slot_d = 12'h0;
        end
        else if (slot_inc_q) begin
            slot_d = slot_q + 12'h1;
        end
        end_r_d = 1'b0;
        wvalid_r_d = 1'b0;
        hdr_bad_r_d = 1'b0;
        check_d = 1'b0;
        if (i_gvalid) begin
            raw_d = (raw_q >> 4) | nib_top__data;
        end
        if (i_start) begin
            active_d = 1'b1;
            gcount_d = 3'h0;
            wcount_d = 2'h0;
            slot_clr_d = 1'b1;
            adv_d = 1'b0;
            ptype_d = 2'h0;
            par_a_d = 1'b0;
            par_b_d = 1'b0;
            all_data_d = 1'b1;
            all_s_d = 1'b1;
            idles_d = 2'h0;
        end
        else if (i_gvalid & active_q & i_idle & (idles_q == 2'h2)) begin
            end_r_d = 1'b1;
            active_d = 1'b0;
            idles_d = 2'h0;
        end
        else if (i_gvalid & active_q) begin
            idles_d = 2'h0;
            if (i_idle) begin
                idles_d = idles_q + 2'h1;
            end
            if (gcount_q == 3'h0) begin
                if (adv_q) begin
                    slot_inc_d = 1'b1;
                    adv_d = 1'b0;
                end
            end
            par_a_d = w_pa;
            par_b_d = w_pb;
            all_data_d = w_all_data;
            all_s_d = w_all_s;
            compl_d = w_compl;
            gcount_d = gcount_q + 3'h1;
            if (gcount_q == last_group) begin
                gcount_d = 3'h0;
                par_a_d = 1'b0;
                par_b_d = 1'b0;
                all_data_d = 1'b1;
                all_s_d = 1'b1;
                wvalid_r_d = 1'b1;
                kind_r_d = wcount_q;
                ok_r_d = w_ok;
                compl_r_d = w_compl;
                void_r_d = w_all_s;
                marked_r_d = i_group == 5'hd;
                own_r_d = (wcount_q == 2'h2) & (slot_q == i_address);
                check_d = 1'b1;
                if (wcount_q == 2'h0) begin
                    wcount_d = 2'h1;
                    ptype_d = nib[(1)+:(2)];
                end
                else if (wcount_q == 2'h1) begin
                    wcount_d = 2'h2;
                end
                else begin
                    adv_d = 1'b1;
                end
            end
        end
        if (check_q) begin
            if (kind_r_q == 2'h0) begin
                if (~ok_r_q | alarm | ((data[(14)+:(2)] == 2'h0) & (data[(0)+:(12)] != i_slots_m1))) begin
                    hdr_bad_r_d = 1'b1;
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
            end
            else if (kind_r_q == 2'h1) begin
                if (~ok_r_q | alarm) begin
                    hdr_bad_r_d = ptype_q == 2'h0;
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
                else if ((ptype_q == 2'h3) & compl_r_q) begin
                    wcount_d = 2'h3;
                    slot_clr_d = 1'b1;
                    adv_d = 1'b0;
                end
                else if (ptype_q != 2'h0) begin
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
            end
            else if ((kind_r_q == 2'h2) & (slot_q == i_slots_m1)) begin
                end_r_d = 1'b1;
                active_d = 1'b0;
            end
        end
        o_end = end_r_q;
        o_wvalid = wvalid_r_q;
        o_kind = kind_r_q;
        o_slot = slot_q;
        o_data = data;
        o_alive = alive;
        o_alarm = alarm;
        o_reason = reason;
        o_ok = ok_r_q;
        o_compl = compl_r_q;
        o_void = void_r_q;
        o_marked = marked_r_q;
        o_own = own_r_q;
        o_hdr_bad = hdr_bad_r_q;
        o_ptype = ptype_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial gcount_q = 3'h0;
    always @(posedge clock) gcount_q <= gcount_d;
    initial idles_q = 2'h0;
    always @(posedge clock) idles_q <= idles_d;
    initial raw_q = 24'h0;
    always @(posedge clock) raw_q <= raw_d;
    initial par_a_q = 1'h0;
    always @(posedge clock) par_a_q <= par_a_d;
    initial par_b_q = 1'h0;
    always @(posedge clock) par_b_q <= par_b_d;
    initial all_data_q = 1'h0;
    always @(posedge clock) all_data_q <= all_data_d;
    initial all_s_q = 1'h0;
    always @(posedge clock) all_s_q <= all_s_d;
    initial active_q = 1'h0;
    always @(posedge clock) active_q <= active_d;
    initial wcount_q = 2'h0;
    always @(posedge clock) wcount_q <= wcount_d;
    initial slot_q = 12'h0;
    always @(posedge clock) slot_q <= slot_d;
    initial slot_inc_q = 1'h0;
    always @(posedge clock) slot_inc_q <= slot_inc_d;
    initial slot_clr_q = 1'h0;
    always @(posedge clock) slot_clr_q <= slot_clr_d;
    initial ptype_q = 2'h0;
    always @(posedge clock) ptype_q <= ptype_d;
    initial check_q = 1'h0;
    always @(posedge clock) check_q <= check_d;
    initial end_r_q = 1'h0;
    always @(posedge clock) end_r_q <= end_r_d;
    initial wvalid_r_q = 1'h0;
    always @(posedge clock) wvalid_r_q <= wvalid_r_d;
    initial kind_r_q = 2'h0;
    always @(posedge clock) kind_r_q <= kind_r_d;
    initial adv_q = 1'h0;
    always @(posedge clock) adv_q <= adv_d;
    initial ok_r_q = 1'h0;
    always @(posedge clock) ok_r_q <= ok_r_d;
    initial compl_q = 1'h0;
    always @(posedge clock) compl_q <= compl_d;
    initial compl_r_q = 1'h0;
    always @(posedge clock) compl_r_q <= compl_r_d;
    initial void_r_q = 1'h0;
    always @(posedge clock) void_r_q <= void_r_d;
    initial marked_r_q = 1'h0;
    always @(posedge clock) marked_r_q <= marked_r_d;
    initial own_r_q = 1'h0;
    always @(posedge clock) own_r_q <= own_r_d;
    initial hdr_bad_r_q = 1'h0;
    always @(posedge clock) hdr_bad_r_q <= hdr_bad_r_d;
endmodule // merkur_slave__rx_bsr__mon__word
// --------------------------------------------------------------------------
// `dec`: Dec5b4b, 4B/5B decoder. (rtl/src/line/dec5b4b.rs)
//
// # dec5b4b — 4B/5B code group decoder (protocol §2, §4)
//
// Purpose: classifies a received 5-bit code group: a data nibble, one of the
// control groups J, K, I, S, or invalid (none of the flags set).
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `i_code` | in | 5 | — (combinational) | code group, bit 4 received first |
// | `o_nibble` | out | 4 | — | data nibble (0 unless `o_data`) |
// | `o_data` | out | 1 | — | the group is a data nibble |
// | `o_j`, `o_k`, `o_i`, `o_s` | out | 1 | — | the group is J / K / I / S |
//
// Latency: combinational (0 clocks).
//
// ```text
// i_code   ==X= 01001 =X= 11000 =X= 00000 ==
// o_nibble ==X== 0x1 ==X== 0x0 ==X== 0x0 ===
// o_data   __/‾‾‾‾‾‾‾‾\_________________
// o_j      ___________/‾‾‾‾‾‾‾\_________
// ```
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__word__dec(i_code,o_nibble,o_data,o_j,o_k,o_i,o_s);

    // Module arguments
    input wire  [4:0] i_code;
    output reg  [3:0] o_nibble;
    output reg  o_data;
    output reg  o_j;
    output reg  o_k;
    output reg  o_i;
    output reg  o_s;

    // Registers and child block ports
    wire  [8:0] rom__data;

    // Child blocks
    merkur_slave__rx_bsr__mon__word__dec__rom rom(
        .address(i_code),
        .data(rom__data)
    );

    // Combinational logic
    always @(*) begin
        o_nibble = rom__data[(0)+:(4)];
        o_data = rom__data[4];
        o_j = rom__data[5];
        o_k = rom__data[6];
        o_i = rom__data[7];
        o_s = rom__data[8];
    end

endmodule // merkur_slave__rx_bsr__mon__word__dec
// --------------------------------------------------------------------------
// `rom` of `merkur_slave__rx_bsr__mon__word__dec`: a table (rust-hdl ROM), read combinationally.
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__word__dec__rom(address,data);

    // Module arguments
    input wire  [4:0] address;
    output reg  [8:0] data;

    // Update code (custom)
    always @*
    case (address)
        5'b0: data = 9'b0;
      5'b1: data = 9'b0;
      5'b10: data = 9'b0;
      5'b11: data = 9'b0;
      5'b100: data = 9'b0;
      5'b101: data = 9'b0;
      5'b110: data = 9'b0;
      5'b111: data = 9'b0;
      5'b1000: data = 9'b0;
      5'b1001: data = 9'b10001;
      5'b1010: data = 9'b10100;
      5'b1011: data = 9'b10101;
      5'b1100: data = 9'b0;
      5'b1101: data = 9'b0;
      5'b1110: data = 9'b10110;
      5'b1111: data = 9'b10111;
      5'b10000: data = 9'b0;
      5'b10001: data = 9'b1000000;
      5'b10010: data = 9'b11000;
      5'b10011: data = 9'b11001;
      5'b10100: data = 9'b10010;
      5'b10101: data = 9'b10011;
      5'b10110: data = 9'b11010;
      5'b10111: data = 9'b11011;
      5'b11000: data = 9'b100000;
      5'b11001: data = 9'b100000000;
      5'b11010: data = 9'b11100;
      5'b11011: data = 9'b11101;
      5'b11100: data = 9'b11110;
      5'b11101: data = 9'b11111;
      5'b11110: data = 9'b10000;
      5'b11111: data = 9'b10000000;
      default: data = 9'b0;
    endcase

endmodule // merkur_slave__rx_bsr__mon__word__dec__rom
// --------------------------------------------------------------------------
// `nib_top` of `merkur_slave__rx_bsr__mon__word`: a table (rust-hdl ROM), read combinationally.
// --------------------------------------------------------------------------
module merkur_slave__rx_bsr__mon__word__nib_top(address,data);

    // Module arguments
    input wire  [3:0] address;
    output reg  [23:0] data;

    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 24'h0;
      4'h1: data = 24'h100000;
      4'h2: data = 24'h200000;
      4'h3: data = 24'h300000;
      4'h4: data = 24'h400000;
      4'h5: data = 24'h500000;
      4'h6: data = 24'h600000;
      4'h7: data = 24'h700000;
      4'h8: data = 24'h800000;
      4'h9: data = 24'h900000;
      4'ha: data = 24'ha00000;
      4'hb: data = 24'hb00000;
      4'hc: data = 24'hc00000;
      4'hd: data = 24'hd00000;
      4'he: data = 24'he00000;
      4'hf: data = 24'hf00000;
      default: data = 24'h0;
    endcase

endmodule // merkur_slave__rx_bsr__mon__word__nib_top
// --------------------------------------------------------------------------
// `rx_in`: PortRx, Supervised receive port. (rtl/src/node/port_rx.rs)
// Documented at module `merkur_slave__rx_bsr` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in(clock,i_samples,i_slots_m1,i_address,i_tst_fail,i_flush,o_start,o_inpkt,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_void,o_marked,o_own,o_hdr_bad,o_ptype,o_los,o_bvalid,o_code,o_phase,o_cf,o_hard,o_run,o_tst,o_ack);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    input wire  i_tst_fail;
    input wire  i_flush;
    output reg  o_start;
    output reg  o_inpkt;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;
    output reg  o_los;
    output reg  o_bvalid;
    output reg  o_code;
    output reg  [1:0] o_phase;
    output reg  o_cf;
    output reg  o_hard;
    output reg  o_run;
    output reg  o_tst;
    output reg  o_ack;

    // Registers and child block ports
    wire  mon__o_los;
    wire  mon__o_bvalid;
    wire  mon__o_code;
    wire  [1:0] mon__o_phase;
    wire  mon__o_start;
    wire  mon__o_inpkt;
    wire  mon__o_wvalid;
    wire  [1:0] mon__o_kind;
    wire  [11:0] mon__o_slot;
    wire  [15:0] mon__o_data;
    wire  mon__o_alive;
    wire  mon__o_alarm;
    wire  [3:0] mon__o_reason;
    wire  mon__o_ok;
    wire  mon__o_compl;
    wire  mon__o_void;
    wire  mon__o_marked;
    wire  mon__o_own;
    wire  mon__o_hdr_bad;
    wire  [1:0] mon__o_ptype;
    reg  ctrl__i_los;
    reg  ctrl__i_wvalid;
    reg  [1:0] ctrl__i_kind;
    reg  ctrl__i_ok;
    reg  ctrl__i_void;
    reg  ctrl__i_marked;
    reg  ctrl__i_d12;
    reg  ctrl__i_compl;
    reg  [1:0] ctrl__i_ptype;
    wire  ctrl__o_cf;
    wire  ctrl__o_hard;
    wire  ctrl__o_run;
    wire  ctrl__o_tst;
    wire  ctrl__o_ack;

    // Child blocks
    merkur_slave__rx_in__mon mon(
        .clock(clock),
        .i_samples(i_samples),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .i_flush(i_flush),
        .o_los(mon__o_los),
        .o_bvalid(mon__o_bvalid),
        .o_code(mon__o_code),
        .o_phase(mon__o_phase),
        .o_start(mon__o_start),
        .o_inpkt(mon__o_inpkt),
        .o_wvalid(mon__o_wvalid),
        .o_kind(mon__o_kind),
        .o_slot(mon__o_slot),
        .o_data(mon__o_data),
        .o_alive(mon__o_alive),
        .o_alarm(mon__o_alarm),
        .o_reason(mon__o_reason),
        .o_ok(mon__o_ok),
        .o_compl(mon__o_compl),
        .o_void(mon__o_void),
        .o_marked(mon__o_marked),
        .o_own(mon__o_own),
        .o_hdr_bad(mon__o_hdr_bad),
        .o_ptype(mon__o_ptype)
    );
    merkur_slave__rx_in__ctrl ctrl(
        .clock(clock),
        .i_los(ctrl__i_los),
        .i_wvalid(ctrl__i_wvalid),
        .i_kind(ctrl__i_kind),
        .i_ok(ctrl__i_ok),
        .i_void(ctrl__i_void),
        .i_marked(ctrl__i_marked),
        .i_d12(ctrl__i_d12),
        .i_compl(ctrl__i_compl),
        .i_ptype(ctrl__i_ptype),
        .i_tst_fail(i_tst_fail),
        .i_flush(i_flush),
        .o_cf(ctrl__o_cf),
        .o_hard(ctrl__o_hard),
        .o_run(ctrl__o_run),
        .o_tst(ctrl__o_tst),
        .o_ack(ctrl__o_ack)
    );

    // Combinational logic
    always @(*) begin
        ctrl__i_los = mon__o_los;
        ctrl__i_wvalid = mon__o_wvalid;
        ctrl__i_kind = mon__o_kind;
        ctrl__i_ok = mon__o_ok;
        ctrl__i_void = mon__o_void;
        ctrl__i_marked = mon__o_marked;
        ctrl__i_d12 = mon__o_data[12];
        ctrl__i_compl = mon__o_compl;
        ctrl__i_ptype = mon__o_ptype;
        o_start = mon__o_start;
        o_inpkt = mon__o_inpkt;
        o_wvalid = mon__o_wvalid;
        o_kind = mon__o_kind;
        o_slot = mon__o_slot;
        o_data = mon__o_data;
        o_alive = mon__o_alive;
        o_alarm = mon__o_alarm;
        o_reason = mon__o_reason;
        o_ok = mon__o_ok;
        o_void = mon__o_void;
        o_marked = mon__o_marked;
        o_own = mon__o_own;
        o_hdr_bad = mon__o_hdr_bad;
        o_ptype = mon__o_ptype;
        o_los = mon__o_los;
        o_bvalid = mon__o_bvalid;
        o_code = mon__o_code;
        o_phase = mon__o_phase;
        o_cf = ctrl__o_cf;
        o_hard = ctrl__o_hard;
        o_run = ctrl__o_run;
        o_tst = ctrl__o_tst;
        o_ack = ctrl__o_ack;
    end

endmodule // merkur_slave__rx_in
// --------------------------------------------------------------------------
// `ctrl`: StreamCtl, Stream controller. (rtl/src/node/stream_ctl.rs)
// Documented at module `merkur_slave__rx_bsr__ctrl` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__ctrl(clock,i_los,i_wvalid,i_kind,i_ok,i_void,i_marked,i_d12,i_compl,i_ptype,i_tst_fail,i_flush,o_cf,o_hard,o_run,o_tst,o_ack);

    // Module arguments
    input wire  clock;
    input wire  i_los;
    input wire  i_wvalid;
    input wire  [1:0] i_kind;
    input wire  i_ok;
    input wire  i_void;
    input wire  i_marked;
    input wire  i_d12;
    input wire  i_compl;
    input wire  [1:0] i_ptype;
    input wire  i_tst_fail;
    input wire  i_flush;
    output reg  o_cf;
    output reg  o_hard;
    output reg  o_run;
    output reg  o_tst;
    output reg  o_ack;

    // Constant declarations
    localparam  hold_after = 9'b100000010;
    localparam  bad_max = 4'h8;

    // Registers and child block ports
    reg  [3:0] bad_d;
    reg  [3:0] bad_q;
    reg  [8:0] hold_d;
    reg  [8:0] hold_q;
    reg  hold_ld_d;
    reg  hold_ld_q;
    reg  tst_d;
    reg  tst_q;
    reg  ack_d;
    reg  ack_q;
    reg  hard_d;
    reg  hard_q;
    reg  run_d;
    reg  run_q;

    // Combinational logic
    always @(*) begin
        bad_d = bad_q;
        hold_d = hold_q;
        hold_ld_d = hold_ld_q;
        tst_d = tst_q;
        ack_d = ack_q;
        hard_d = hard_q;
        run_d = run_q;
        if (i_wvalid) begin
            if (i_ok) begin
                bad_d = 4'h0;
            end
            else if (~i_void & ~i_marked & (bad_q != bad_max)) begin
                bad_d = bad_q + 4'h1;
            end
        end
        if (i_flush) begin
            bad_d = 4'h0;
        end
        hold_ld_d = 1'b0;
        if (tst_q) begin
            hold_d = hold_q - 9'h1;
            if (hold_ld_q) begin
                hold_d = hold_after;
            end
            if (~hold_ld_q & (hold_q == 9'h0)) begin
                tst_d = 1'b0;
            end
        end
        if (i_wvalid & (i_kind == 2'h1) & i_ok & (i_ptype == 2'h2) & i_compl) begin
            tst_d = 1'b1;
            ack_d = ~i_d12;
            hold_ld_d = 1'b1;
        end
        hard_d = i_los | (tst_q & i_tst_fail);
        run_d = (bad_q == bad_max) & ~i_flush;
        o_cf = hard_q | run_q;
        o_hard = hard_q;
        o_run = run_q;
        o_tst = tst_q;
        o_ack = ack_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial bad_q = 4'h0;
    always @(posedge clock) bad_q <= bad_d;
    initial hold_q = 9'h0;
    always @(posedge clock) hold_q <= hold_d;
    initial hold_ld_q = 1'h0;
    always @(posedge clock) hold_ld_q <= hold_ld_d;
    initial tst_q = 1'h0;
    always @(posedge clock) tst_q <= tst_d;
    initial ack_q = 1'h0;
    always @(posedge clock) ack_q <= ack_d;
    initial hard_q = 1'h0;
    always @(posedge clock) hard_q <= hard_d;
    initial run_q = 1'h0;
    always @(posedge clock) run_q <= run_d;
endmodule // merkur_slave__rx_in__ctrl
// --------------------------------------------------------------------------
// `mon`: Monitor, Fibre monitor / receive chain. (rtl/src/line/monitor.rs)
// Documented at module `merkur_slave__rx_bsr__mon` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon(clock,i_samples,i_slots_m1,i_address,i_flush,o_los,o_bvalid,o_code,o_phase,o_start,o_inpkt,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_compl,o_void,o_marked,o_own,o_hdr_bad,o_ptype);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    input wire  i_flush;
    output reg  o_los;
    output reg  o_bvalid;
    output reg  o_code;
    output reg  [1:0] o_phase;
    output reg  o_start;
    output reg  o_inpkt;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_compl;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;

    // Constant declarations
    localparam  drop_after = 3'b100;

    // Registers and child block ports
    wire  cdr__o_valid;
    wire  cdr__o_bit;
    wire  cdr__o_code;
    wire  cdr__o_los;
    wire  [1:0] cdr__o_phase;
    reg  framer__i_valid;
    reg  framer__i_code;
    reg  framer__i_end;
    wire  framer__o_start;
    wire  framer__o_gvalid;
    wire  [4:0] framer__o_group;
    wire  framer__o_idle;
    wire  framer__o_inpkt;
    reg  word__i_start;
    reg  word__i_gvalid;
    reg  [4:0] word__i_group;
    reg  word__i_idle;
    wire  word__o_end;
    wire  word__o_wvalid;
    wire  [1:0] word__o_kind;
    wire  [11:0] word__o_slot;
    wire  [15:0] word__o_data;
    wire  word__o_alive;
    wire  word__o_alarm;
    wire  [3:0] word__o_reason;
    wire  word__o_ok;
    wire  word__o_compl;
    wire  word__o_void;
    wire  word__o_marked;
    wire  word__o_own;
    wire  word__o_hdr_bad;
    wire  [1:0] word__o_ptype;
    reg  [2:0] quiet_d;
    reg  [2:0] quiet_q;
    reg  emit_d;
    reg  emit_q;
    reg  p_valid_d;
    reg  p_valid_q;

    // Local signals
    reg  conf_edge;

    // Child blocks
    merkur_slave__rx_in__mon__cdr cdr(
        .clock(clock),
        .i_samples(i_samples),
        .o_valid(cdr__o_valid),
        .o_bit(cdr__o_bit),
        .o_code(cdr__o_code),
        .o_los(cdr__o_los),
        .o_phase(cdr__o_phase)
    );
    merkur_slave__rx_in__mon__framer framer(
        .clock(clock),
        .i_valid(framer__i_valid),
        .i_code(framer__i_code),
        .i_end(framer__i_end),
        .o_start(framer__o_start),
        .o_gvalid(framer__o_gvalid),
        .o_group(framer__o_group),
        .o_idle(framer__o_idle),
        .o_inpkt(framer__o_inpkt)
    );
    merkur_slave__rx_in__mon__word word(
        .clock(clock),
        .i_start(word__i_start),
        .i_gvalid(word__i_gvalid),
        .i_group(word__i_group),
        .i_idle(word__i_idle),
        .i_slots_m1(i_slots_m1),
        .i_address(i_address),
        .o_end(word__o_end),
        .o_wvalid(word__o_wvalid),
        .o_kind(word__o_kind),
        .o_slot(word__o_slot),
        .o_data(word__o_data),
        .o_alive(word__o_alive),
        .o_alarm(word__o_alarm),
        .o_reason(word__o_reason),
        .o_ok(word__o_ok),
        .o_compl(word__o_compl),
        .o_void(word__o_void),
        .o_marked(word__o_marked),
        .o_own(word__o_own),
        .o_hdr_bad(word__o_hdr_bad),
        .o_ptype(word__o_ptype)
    );

    // Combinational logic
    always @(*) begin
        quiet_d = quiet_q;
        emit_d = emit_q;
        p_valid_d = p_valid_q;
        framer__i_valid = cdr__o_valid;
        framer__i_code = cdr__o_code;
        framer__i_end = word__o_end | cdr__o_los | (quiet_q == drop_after) | i_flush;
        word__i_start = framer__o_start;
        word__i_gvalid = framer__o_gvalid;
        word__i_group = framer__o_group;
        word__i_idle = framer__o_idle;
        o_los = cdr__o_los;
        o_bvalid = cdr__o_valid;
        o_code = cdr__o_code;
        o_phase = cdr__o_phase;
        o_start = framer__o_start;
        o_inpkt = framer__o_inpkt;
        o_hdr_bad = word__o_hdr_bad;
        conf_edge = cdr__o_valid & cdr__o_code;
        if (cdr__o_valid) begin
            quiet_d = 3'h0;
        end
        else if (quiet_q != 3'h7) begin
            quiet_d = quiet_q + 3'h1;
        end
        emit_d = 1'b0;
        o_wvalid = emit_q;
        o_kind = word__o_kind;
        o_slot = word__o_slot;
        o_data = word__o_data;
        o_alive = word__o_alive;
        o_alarm = word__o_alarm;
        o_reason = word__o_reason;
        o_ok = word__o_ok;
        o_compl = word__o_compl;
        o_void = word__o_void;
        o_marked = word__o_marked;
        o_own = word__o_own;
        o_ptype = word__o_ptype;
        if (p_valid_q & conf_edge) begin
            emit_d = 1'b1;
            p_valid_d = 1'b0;
        end
        if (p_valid_q & ((quiet_q == drop_after) | i_flush)) begin
            p_valid_d = 1'b0;
        end
        if (word__o_wvalid) begin
            p_valid_d = ~conf_edge;
            emit_d = conf_edge;
        end
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial quiet_q = 3'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial emit_q = 1'h0;
    always @(posedge clock) emit_q <= emit_d;
    initial p_valid_q = 1'h0;
    always @(posedge clock) p_valid_q <= p_valid_d;
endmodule // merkur_slave__rx_in__mon
// --------------------------------------------------------------------------
// `cdr`: Cdr, Oversampling clock and data recovery. (rtl/src/line/cdr.rs)
// Documented at module `merkur_slave__rx_bsr__mon__cdr` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__cdr(clock,i_samples,o_valid,o_bit,o_code,o_los,o_phase);

    // Module arguments
    input wire  clock;
    input wire  [3:0] i_samples;
    output reg  o_valid;
    output reg  o_bit;
    output reg  o_code;
    output reg  o_los;
    output reg  [1:0] o_phase;

    // Constant declarations
    localparam  quiet_last = 6'b111111;
    localparam  mute_last = 6'b1111;

    // Registers and child block ports
    reg  last_d;
    reg  last_q;
    reg  [1:0] phase_d;
    reg  [1:0] phase_q;
    reg  [2:0] count_d;
    reg  [2:0] count_q;
    reg  [5:0] quiet_d;
    reg  [5:0] quiet_q;
    reg  calm_d;
    reg  calm_q;
    reg  mute_d;
    reg  mute_q;
    reg  rx_valid_d;
    reg  rx_valid_q;
    reg  rx_bit_d;
    reg  rx_bit_q;
    reg  rx_code_d;
    reg  rx_code_q;
    reg  los_flag_d;
    reg  los_flag_q;

    // Local signals
    reg  [3:0] prior;
    reg  [3:0] edges;
    reg  still;
    reg  clean;
    reg  [1:0] take_at;
    reg  taken;

    // Combinational logic
    always @(*) begin
        last_d = last_q;
        phase_d = phase_q;
        count_d = count_q;
        quiet_d = quiet_q;
        calm_d = calm_q;
        mute_d = mute_q;
        rx_valid_d = rx_valid_q;
        rx_bit_d = rx_bit_q;
        rx_code_d = rx_code_q;
        los_flag_d = los_flag_q;
        prior = i_samples << 1;
        if (last_q) begin
            prior = (i_samples << 1) | 4'h1;
        end
        edges = i_samples ^ prior;
        count_d = count_q ^ 3'h4;
        if (edges[0]) begin
            count_d = 3'h3;
        end
        if (edges[1]) begin
            count_d = 3'h2;
        end
        if (edges[2]) begin
            count_d = 3'h1;
        end
        if (edges[3]) begin
            count_d = 3'h0;
        end
        last_d = i_samples[3];
        clean = ~edges[0];
        if (count_q[(0)+:(2)] == 2'h2) begin
            clean = ~edges[0] & ~edges[1];
        end
        if (count_q[(0)+:(2)] == 2'h1) begin
            clean = ~edges[0] & ~edges[1] & ~edges[2];
        end
        if (count_q[(0)+:(2)] == 2'h0) begin
            clean = ~|edges;
        end
        take_at = ~count_q[(0)+:(2)];
        taken = i_samples[take_at];
        rx_valid_d = 1'b0;
        if (~count_q[2] & clean & ~mute_q) begin
            rx_valid_d = 1'b1;
            rx_bit_d = taken;
            rx_code_d = taken ^ rx_bit_q;
            phase_d = take_at;
        end
        still = ~|edges;
        calm_d = still;
        if (~calm_q) begin
            quiet_d = 6'h1;
        end
        else if (~los_flag_q) begin
            quiet_d = quiet_q + 6'h1;
        end
        mute_d = still & calm_q & (los_flag_q | (quiet_q >= mute_last));
        if (~still) begin
            los_flag_d = 1'b0;
        end
        else if (calm_q & (quiet_q == quiet_last)) begin
            los_flag_d = 1'b1;
        end
        o_valid = rx_valid_q;
        o_bit = rx_bit_q;
        o_code = rx_code_q;
        o_los = los_flag_q;
        o_phase = phase_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial last_q = 1'h0;
    always @(posedge clock) last_q <= last_d;
    initial phase_q = 2'h0;
    always @(posedge clock) phase_q <= phase_d;
    initial count_q = 3'h0;
    always @(posedge clock) count_q <= count_d;
    initial quiet_q = 6'h0;
    always @(posedge clock) quiet_q <= quiet_d;
    initial calm_q = 1'h0;
    always @(posedge clock) calm_q <= calm_d;
    initial mute_q = 1'h0;
    always @(posedge clock) mute_q <= mute_d;
    initial rx_valid_q = 1'h0;
    always @(posedge clock) rx_valid_q <= rx_valid_d;
    initial rx_bit_q = 1'h0;
    always @(posedge clock) rx_bit_q <= rx_bit_d;
    initial rx_code_q = 1'h0;
    always @(posedge clock) rx_code_q <= rx_code_d;
    initial los_flag_q = 1'h0;
    always @(posedge clock) los_flag_q <= los_flag_d;
endmodule // merkur_slave__rx_in__mon__cdr
// --------------------------------------------------------------------------
// `framer`: FramerRx, J K hunter and group aligner. (rtl/src/line/framer_rx.rs)
// Documented at module `merkur_slave__rx_bsr__mon__framer` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__framer(clock,i_valid,i_code,i_end,o_start,o_gvalid,o_group,o_idle,o_inpkt);

    // Module arguments
    input wire  clock;
    input wire  i_valid;
    input wire  i_code;
    input wire  i_end;
    output reg  o_start;
    output reg  o_gvalid;
    output reg  [4:0] o_group;
    output reg  o_idle;
    output reg  o_inpkt;

    // Constant declarations
    localparam  jk = 10'b1100010001;

    // Registers and child block ports
    reg  [9:0] window_d;
    reg  [9:0] window_q;
    reg  inpkt_d;
    reg  inpkt_q;
    reg  [2:0] count_d;
    reg  [2:0] count_q;
    reg  start_d;
    reg  start_q;
    reg  gvalid_d;
    reg  gvalid_q;
    reg  [4:0] group_d;
    reg  [4:0] group_q;
    reg  idle_d;
    reg  idle_q;

    // Local signals
    reg  [9:0] shifted;

    // Combinational logic
    always @(*) begin
        window_d = window_q;
        inpkt_d = inpkt_q;
        count_d = count_q;
        start_d = start_q;
        gvalid_d = gvalid_q;
        group_d = group_q;
        idle_d = idle_q;
        start_d = 1'b0;
        gvalid_d = 1'b0;
        shifted = window_q << 1;
        if (i_code) begin
            shifted = (window_q << 1) | 10'h1;
        end
        if (i_valid) begin
            window_d = shifted;
            if (inpkt_q) begin
                if (count_q == 3'h4) begin
                    count_d = 3'h0;
                    gvalid_d = 1'b1;
                    group_d = shifted[(0)+:(5)];
                    idle_d = shifted[(0)+:(5)] == 5'h1f;
                end
                else begin
                    count_d = count_q + 3'h1;
                end
            end
            else if (shifted == jk) begin
                inpkt_d = 1'b1;
                start_d = 1'b1;
                count_d = 3'h0;
            end
        end
        if (i_end) begin
            inpkt_d = 1'b0;
        end
        o_start = start_q;
        o_gvalid = gvalid_q;
        o_group = group_q;
        o_idle = idle_q;
        o_inpkt = inpkt_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial window_q = 10'h0;
    always @(posedge clock) window_q <= window_d;
    initial inpkt_q = 1'h0;
    always @(posedge clock) inpkt_q <= inpkt_d;
    initial count_q = 3'h0;
    always @(posedge clock) count_q <= count_d;
    initial start_q = 1'h0;
    always @(posedge clock) start_q <= start_d;
    initial gvalid_q = 1'h0;
    always @(posedge clock) gvalid_q <= gvalid_d;
    initial group_q = 5'h0;
    always @(posedge clock) group_q <= group_d;
    initial idle_q = 1'h0;
    always @(posedge clock) idle_q <= idle_d;
endmodule // merkur_slave__rx_in__mon__framer
// --------------------------------------------------------------------------
// `word`: WordRx, Word assembler and checker. (rtl/src/line/word_rx.rs)
// Documented at module `merkur_slave__rx_bsr__mon__word` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__word(clock,i_start,i_gvalid,i_group,i_idle,i_slots_m1,i_address,o_end,o_wvalid,o_kind,o_slot,o_data,o_alive,o_alarm,o_reason,o_ok,o_compl,o_void,o_marked,o_own,o_hdr_bad,o_ptype);

    // Module arguments
    input wire  clock;
    input wire  i_start;
    input wire  i_gvalid;
    input wire  [4:0] i_group;
    input wire  i_idle;
    input wire  [11:0] i_slots_m1;
    input wire  [11:0] i_address;
    output reg  o_end;
    output reg  o_wvalid;
    output reg  [1:0] o_kind;
    output reg  [11:0] o_slot;
    output reg  [15:0] o_data;
    output reg  o_alive;
    output reg  o_alarm;
    output reg  [3:0] o_reason;
    output reg  o_ok;
    output reg  o_compl;
    output reg  o_void;
    output reg  o_marked;
    output reg  o_own;
    output reg  o_hdr_bad;
    output reg  [1:0] o_ptype;

    // Constant declarations
    localparam  last_group = 3'b100;

    // Registers and child block ports
    wire  [3:0] dec__o_nibble;
    wire  dec__o_data;
    wire  dec__o_j;
    wire  dec__o_k;
    wire  dec__o_i;
    wire  dec__o_s;
    reg  [3:0] nib_top__address;
    wire  [23:0] nib_top__data;
    reg  [2:0] gcount_d;
    reg  [2:0] gcount_q;
    reg  [1:0] idles_d;
    reg  [1:0] idles_q;
    reg  [23:0] raw_d;
    reg  [23:0] raw_q;
    reg  par_a_d;
    reg  par_a_q;
    reg  par_b_d;
    reg  par_b_q;
    reg  all_data_d;
    reg  all_data_q;
    reg  all_s_d;
    reg  all_s_q;
    reg  active_d;
    reg  active_q;
    reg  [1:0] wcount_d;
    reg  [1:0] wcount_q;
    reg  [11:0] slot_d;
    reg  [11:0] slot_q;
    reg  slot_inc_d;
    reg  slot_inc_q;
    reg  slot_clr_d;
    reg  slot_clr_q;
    reg  [1:0] ptype_d;
    reg  [1:0] ptype_q;
    reg  check_d;
    reg  check_q;
    reg  end_r_d;
    reg  end_r_q;
    reg  wvalid_r_d;
    reg  wvalid_r_q;
    reg  [1:0] kind_r_d;
    reg  [1:0] kind_r_q;
    reg  adv_d;
    reg  adv_q;
    reg  ok_r_d;
    reg  ok_r_q;
    reg  compl_d;
    reg  compl_q;
    reg  compl_r_d;
    reg  compl_r_q;
    reg  void_r_d;
    reg  void_r_q;
    reg  marked_r_d;
    reg  marked_r_q;
    reg  own_r_d;
    reg  own_r_q;
    reg  hdr_bad_r_d;
    reg  hdr_bad_r_q;

    // Local signals
    reg  [3:0] nib;
    reg  [15:0] data;
    reg  alarm;
    reg  alive;
    reg  [3:0] reason;
    reg  [3:0] prev_nib;
    reg  [15:0] d_lo;
    reg  [15:0] d_hi;
    reg  [15:0] d_mid;
    reg  w_pa;
    reg  w_pb;
    reg  w_all_data;
    reg  w_all_s;
    reg  w_ok;
    reg  w_compl;

    // Child blocks
    merkur_slave__rx_in__mon__word__dec dec(
        .i_code(i_group),
        .o_nibble(dec__o_nibble),
        .o_data(dec__o_data),
        .o_j(dec__o_j),
        .o_k(dec__o_k),
        .o_i(dec__o_i),
        .o_s(dec__o_s)
    );
    merkur_slave__rx_in__mon__word__nib_top nib_top(
        .address(nib_top__address),
        .data(nib_top__data)
    );

    // Combinational logic
    always @(*) begin
        gcount_d = gcount_q;
        raw_d = raw_q;
        par_a_d = par_a_q;
        par_b_d = par_b_q;
        all_data_d = all_data_q;
        all_s_d = all_s_q;
        active_d = active_q;
        wcount_d = wcount_q;
        slot_d = slot_q;
        slot_inc_d = slot_inc_q;
        slot_clr_d = slot_clr_q;
        ptype_d = ptype_q;
        check_d = check_q;
        end_r_d = end_r_q;
        wvalid_r_d = wvalid_r_q;
        kind_r_d = kind_r_q;
        adv_d = adv_q;
        ok_r_d = ok_r_q;
        compl_d = compl_q;
        compl_r_d = compl_r_q;
        void_r_d = void_r_q;
        marked_r_d = marked_r_q;
        own_r_d = own_r_q;
        hdr_bad_r_d = hdr_bad_r_q;
        idles_d = idles_q;
        nib = dec__o_nibble;
        nib_top__address = dec__o_nibble;
        d_hi = raw_q[(7)+:(16)] & 16'hc000;
        d_mid = raw_q[(6)+:(16)] & 16'h3ffc;
        d_lo = raw_q[(4)+:(16)] & 16'h3;
        prev_nib = raw_q[(4)+:(4)];
        alarm = raw_q[7];
        alive = raw_q[6];
        reason = 4'h0;
        if (last_group == 3'h5) begin
            d_lo = raw_q[(0)+:(16)] & 16'h3;
            prev_nib = raw_q[(0)+:(4)];
            alarm = raw_q[3];
            alive = raw_q[2];
            reason = raw_q[(4)+:(4)];
        end
        data = d_hi | d_mid | d_lo;
        w_pa = par_a_q ^ nib[3] ^ nib[2];
        w_pb = par_b_q ^ nib[2] ^ nib[1] ^ nib[0];
        w_all_data = all_data_q & dec__o_data;
        w_all_s = all_s_q & dec__o_s;
        w_ok = w_all_data & w_pa & w_pb;
        w_compl = compl_q & (nib == ~prev_nib);
        if (gcount_q == 3'h0) begin
            w_compl = nib[(0)+:(2)] == ~prev_nib[(0)+:(2)];
        end
        if (gcount_q == last_group) begin
            w_compl = compl_q & (nib[(1)+:(2)] == ~prev_nib[(1)+:(2)]);
        end
        if ((gcount_q == 3'h1) & (last_group == 3'h5)) begin
            w_compl = compl_q;
        end
        slot_inc_d = 1'b0;
        slot_clr_d = 1'b0;
        if (slot_clr_q) begin
            slot_d = 12'h0;
        end
        else if (slot_inc_q) begin
            slot_d = slot_q + 12'h1;
        end
        end_r_d = 1'b0;
        wvalid_r_d = 1'b0;
        hdr_bad_r_d = 1'b0;
        check_d = 1'b0;
        if (i_gvalid) begin
            raw_d = (raw_q >> 4) | nib_top__data;
        end
        if (i_start) begin
            active_d = 1'b1;
            gcount_d = 3'h0;
            wcount_d = 2'h0;
            slot_clr_d = 1'b1;
            adv_d = 1'b0;
            ptype_d = 2'h0;
            par_a_d = 1'b0;
            par_b_d = 1'b0;
            all_data_d = 1'b1;
            all_s_d = 1'b1;
            idles_d = 2'h0;
        end
        else if (i_gvalid & active_q & i_idle & (idles_q == 2'h2)) begin
            end_r_d = 1'b1;
            active_d = 1'b0;
            idles_d = 2'h0;
        end
        else if (i_gvalid & active_q) begin
            idles_d = 2'h0;
            if (i_idle) begin
                idles_d = idles_q + 2'h1;
            end
            if (gcount_q == 3'h0) begin
                if (adv_q) begin
                    slot_inc_d = 1'b1;
                    adv_d = 1'b0;
                end
            end
            par_a_d = w_pa;
            par_b_d = w_pb;
            all_data_d = w_all_data;
            all_s_d = w_all_s;
            compl_d = w_compl;
            gcount_d = gcount_q + 3'h1;
            if (gcount_q == last_group) begin
                gcount_d = 3'h0;
                par_a_d = 1'b0;
                par_b_d = 1'b0;
                all_data_d = 1'b1;
                all_s_d = 1'b1;
                wvalid_r_d = 1'b1;
                kind_r_d = wcount_q;
                ok_r_d = w_ok;
                compl_r_d = w_compl;
                void_r_d = w_all_s;
                marked_r_d = i_group == 5'hd;
                own_r_d = (wcount_q == 2'h2) & (slot_q == i_address);
                check_d = 1'b1;
                if (wcount_q == 2'h0) begin
                    wcount_d = 2'h1;
                    ptype_d = nib[(1)+:(2)];
                end
                else if (wcount_q == 2'h1) begin
                    wcount_d = 2'h2;
                end
                else begin
                    adv_d = 1'b1;
                end
            end
        end
        if (check_q) begin
            if (kind_r_q == 2'h0) begin
                if (~ok_r_q | alarm | ((data[(14)+:(2)] == 2'h0) & (data[(0)+:(12)] != i_slots_m1))) begin
                    hdr_bad_r_d = 1'b1;
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
            end
            else if (kind_r_q == 2'h1) begin
                if (~ok_r_q | alarm) begin
                    hdr_bad_r_d = ptype_q == 2'h0;
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
                else if ((ptype_q == 2'h3) & compl_r_q) begin
                    wcount_d = 2'h3;
                    slot_clr_d = 1'b1;
                    adv_d = 1'b0;
                end
                else if (ptype_q != 2'h0) begin
                    end_r_d = 1'b1;
                    active_d = 1'b0;
                end
            end
            else if ((kind_r_q == 2'h2) & (slot_q == i_slots_m1)) begin
                end_r_d = 1'b1;
                active_d = 1'b0;
            end
        end
        o_end = end_r_q;
        o_wvalid = wvalid_r_q;
        o_kind = kind_r_q;
        o_slot = slot_q;
        o_data = data;
        o_alive = alive;
        o_alarm = alarm;
        o_reason = reason;
        o_ok = ok_r_q;
        o_compl = compl_r_q;
        o_void = void_r_q;
        o_marked = marked_r_q;
        o_own = own_r_q;
        o_hdr_bad = hdr_bad_r_q;
        o_ptype = ptype_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial gcount_q = 3'h0;
    always @(posedge clock) gcount_q <= gcount_d;
    initial idles_q = 2'h0;
    always @(posedge clock) idles_q <= idles_d;
    initial raw_q = 24'h0;
    always @(posedge clock) raw_q <= raw_d;
    initial par_a_q = 1'h0;
    always @(posedge clock) par_a_q <= par_a_d;
    initial par_b_q = 1'h0;
    always @(posedge clock) par_b_q <= par_b_d;
    initial all_data_q = 1'h0;
    always @(posedge clock) all_data_q <= all_data_d;
    initial all_s_q = 1'h0;
    always @(posedge clock) all_s_q <= all_s_d;
    initial active_q = 1'h0;
    always @(posedge clock) active_q <= active_d;
    initial wcount_q = 2'h0;
    always @(posedge clock) wcount_q <= wcount_d;
    initial slot_q = 12'h0;
    always @(posedge clock) slot_q <= slot_d;
    initial slot_inc_q = 1'h0;
    always @(posedge clock) slot_inc_q <= slot_inc_d;
    initial slot_clr_q = 1'h0;
    always @(posedge clock) slot_clr_q <= slot_clr_d;
    initial ptype_q = 2'h0;
    always @(posedge clock) ptype_q <= ptype_d;
    initial check_q = 1'h0;
    always @(posedge clock) check_q <= check_d;
    initial end_r_q = 1'h0;
    always @(posedge clock) end_r_q <= end_r_d;
    initial wvalid_r_q = 1'h0;
    always @(posedge clock) wvalid_r_q <= wvalid_r_d;
    initial kind_r_q = 2'h0;
    always @(posedge clock) kind_r_q <= kind_r_d;
    initial adv_q = 1'h0;
    always @(posedge clock) adv_q <= adv_d;
    initial ok_r_q = 1'h0;
    always @(posedge clock) ok_r_q <= ok_r_d;
    initial compl_q = 1'h0;
    always @(posedge clock) compl_q <= compl_d;
    initial compl_r_q = 1'h0;
    always @(posedge clock) compl_r_q <= compl_r_d;
    initial void_r_q = 1'h0;
    always @(posedge clock) void_r_q <= void_r_d;
    initial marked_r_q = 1'h0;
    always @(posedge clock) marked_r_q <= marked_r_d;
    initial own_r_q = 1'h0;
    always @(posedge clock) own_r_q <= own_r_d;
    initial hdr_bad_r_q = 1'h0;
    always @(posedge clock) hdr_bad_r_q <= hdr_bad_r_d;
endmodule // merkur_slave__rx_in__mon__word
// --------------------------------------------------------------------------
// `dec`: Dec5b4b, 4B/5B decoder. (rtl/src/line/dec5b4b.rs)
// Documented at module `merkur_slave__rx_bsr__mon__word__dec` above.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__word__dec(i_code,o_nibble,o_data,o_j,o_k,o_i,o_s);

    // Module arguments
    input wire  [4:0] i_code;
    output reg  [3:0] o_nibble;
    output reg  o_data;
    output reg  o_j;
    output reg  o_k;
    output reg  o_i;
    output reg  o_s;

    // Registers and child block ports
    wire  [8:0] rom__data;

    // Child blocks
    merkur_slave__rx_in__mon__word__dec__rom rom(
        .address(i_code),
        .data(rom__data)
    );

    // Combinational logic
    always @(*) begin
        o_nibble = rom__data[(0)+:(4)];
        o_data = rom__data[4];
        o_j = rom__data[5];
        o_k = rom__data[6];
        o_i = rom__data[7];
        o_s = rom__data[8];
    end

endmodule // merkur_slave__rx_in__mon__word__dec
// --------------------------------------------------------------------------
// `rom` of `merkur_slave__rx_in__mon__word__dec`: a table (rust-hdl ROM), read combinationally.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__word__dec__rom(address,data);

    // Module arguments
    input wire  [4:0] address;
    output reg  [8:0] data;

    // Update code (custom)
    always @*
    case (address)
        5'b0: data = 9'b0;
      5'b1: data = 9'b0;
      5'b10: data = 9'b0;
      5'b11: data = 9'b0;
      5'b100: data = 9'b0;
      5'b101: data = 9'b0;
      5'b110: data = 9'b0;
      5'b111: data = 9'b0;
      5'b1000: data = 9'b0;
      5'b1001: data = 9'b10001;
      5'b1010: data = 9'b10100;
      5'b1011: data = 9'b10101;
      5'b1100: data = 9'b0;
      5'b1101: data = 9'b0;
      5'b1110: data = 9'b10110;
      5'b1111: data = 9'b10111;
      5'b10000: data = 9'b0;
      5'b10001: data = 9'b1000000;
      5'b10010: data = 9'b11000;
      5'b10011: data = 9'b11001;
      5'b10100: data = 9'b10010;
      5'b10101: data = 9'b10011;
      5'b10110: data = 9'b11010;
      5'b10111: data = 9'b11011;
      5'b11000: data = 9'b100000;
      5'b11001: data = 9'b100000000;
      5'b11010: data = 9'b11100;
      5'b11011: data = 9'b11101;
      5'b11100: data = 9'b11110;
      5'b11101: data = 9'b11111;
      5'b11110: data = 9'b10000;
      5'b11111: data = 9'b10000000;
      default: data = 9'b0;
    endcase

endmodule // merkur_slave__rx_in__mon__word__dec__rom
// --------------------------------------------------------------------------
// `nib_top` of `merkur_slave__rx_in__mon__word`: a table (rust-hdl ROM), read combinationally.
// --------------------------------------------------------------------------
module merkur_slave__rx_in__mon__word__nib_top(address,data);

    // Module arguments
    input wire  [3:0] address;
    output reg  [23:0] data;

    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 24'h0;
      4'h1: data = 24'h100000;
      4'h2: data = 24'h200000;
      4'h3: data = 24'h300000;
      4'h4: data = 24'h400000;
      4'h5: data = 24'h500000;
      4'h6: data = 24'h600000;
      4'h7: data = 24'h700000;
      4'h8: data = 24'h800000;
      4'h9: data = 24'h900000;
      4'ha: data = 24'ha00000;
      4'hb: data = 24'hb00000;
      4'hc: data = 24'hc00000;
      4'hd: data = 24'hd00000;
      4'he: data = 24'he00000;
      4'hf: data = 24'hf00000;
      default: data = 24'h0;
    endcase

endmodule // merkur_slave__rx_in__mon__word__nib_top
// --------------------------------------------------------------------------
// `sbox`: Switchbox, Table 1 multiplexer. (rtl/src/node/switchbox.rs)
//
// # switchbox — the paper's Table 1 (protocol §10)
//
// Purpose: connects the physical ports PI, SI, PO, SO to the logical
// streams INPUT, BSR (receive) and OUTPUT, BSS (send) by the node's mode.
// Inputs are carried as 4-sample words (quadrature DDR capture, one word
// per core clock), outputs as DDR pairs (two halves per core clock).
//
// | mode | code | INPUT | OUTPUT | BSR | BSS |
// |---|---|---|---|---|---|
// | N (all 4 ports ok) | 0 | PI | PO | SI | SO |
// | WU (SO or PI defective) | 1 | SI | PO | PI | SO |
// | WD (SI or PO defective) | 2 | PI | SO | SI | PO |
// | (unused) | 3 | as N | | | |
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `i_mode` | in | 2 | clock (static between changes) | mode code |
// | `i_pi`, `i_si` | in | 4 | clock | physical inputs (samples) |
// | `i_output`, `i_bss` | in | 2 | clock | logical outputs of the node |
// | `o_input`, `o_bsr` | out | 4 | clock | logical inputs of the node |
// | `o_po`, `o_so` | out | 2 | clock | physical outputs |
//
// Latency: combinational (0 clocks); the node registers its I/O. A slave
// or a master can leave the input half to the capture register in front
// of it ([`crate::node::slave`]'s `i_cap_sel`, as every synthesis top
// does), which then makes the same choice a clock ahead.
//
// ```text
// i_mode   == N ==X== WU ==========
// o_input  == PI =X== SI ==========
// o_bsr    == SI =X== PI ==========
// o_po     == OUTPUT ==============
// o_so     == BSS =================
// ```
// --------------------------------------------------------------------------
module merkur_slave__sbox(i_mode,i_pi,i_si,i_output,i_bss,o_input,o_bsr,o_po,o_so);

    // Module arguments
    input wire  [1:0] i_mode;
    input wire  [3:0] i_pi;
    input wire  [3:0] i_si;
    input wire  [1:0] i_output;
    input wire  [1:0] i_bss;
    output reg  [3:0] o_input;
    output reg  [3:0] o_bsr;
    output reg  [1:0] o_po;
    output reg  [1:0] o_so;

    // Combinational logic
    always @(*) begin
        o_input = i_pi;
        o_bsr = i_si;
        o_po = i_output;
        o_so = i_bss;
        if (i_mode == 2'h1) begin
            o_input = i_si;
            o_bsr = i_pi;
        end
        if (i_mode == 2'h2) begin
            o_po = i_bss;
            o_so = i_output;
        end
    end

endmodule // merkur_slave__sbox
// --------------------------------------------------------------------------
// `swc`: SwitchPipe, [`SwitchCtl`] between two rows of flip-flops, as the nodes use it: the receivers' reports (loss of signal, channel failures, ACKed TST, frame boundaries, DATA headers on BSR) are registered on the way in and the decisions on the way out, so that a recovered bit, the decision it leads to and what the node does with it (switchbox, dark time, TST generator, failsafe, RECONFIG alarm) are three clocks, not one long path (issue 20). The mode, the change and its companions leave together, so the node sees one consistent decision, two clocks (one bit time) after the report that caused it. Ports as [`SwitchCtl`]; `i_armed`, `i_rw`, `i_fs` and `i_cs_timeout` (node registers and a static value) go in directly.  A node that forwards INPUT to OUTPUT (`i_fwd`: a slave, a master, a backup that is not the clock base) has its frame boundary where its OUTPUT has sent a packet's last bit, [`DRAIN_CLOCKS`] after the packet ended on INPUT (`i_in_pkt` falling), and counts the packet as arriving until then: a WD end that unwraps, or a WU end that waits for the frame coming the long way round, does not cut that frame's last word (protocol §12). The clock base (`i_fwd` = 0) sends its own frames: its boundary is `i_frame_start`.  ```text i_in_pkt     ‾‾‾‾\_______________________ OUTPUT       =frame====\_________________   (the forwarder's last bits) frame bound. ______________________/‾\____   DRAIN_CLOCKS + 1 after i_in_pkt fell ``` (rtl/src/node/switch_ctl.rs)
//
// # switch_ctl — a node's switchbox decisions (protocol §10, §12)
//
// Purpose: the local fault management of every node, the special master
// included: from its two stream controllers it decides the switchbox mode
// (Table 1), the failsafe of a second fault, and reintegration when a
// repaired link's partner acknowledges its TST. No central station: each
// node runs one of these on what it sees.
//
// - mode N: INPUT fails → WU; else BSR fails → WD. A structural failure
//   (`i_hard_*`: loss of signal, a TST where DATA is expected) while the
//   node knows the ring is wrapped is the second fault: failsafe, and so is
//   loss of signal on both at once. A run of bad words (`i_run_*`, a
//   transient) counts only while the ring is not known wrapped (a soft
//   wrap), and never for failsafe (protocol §9, §12);
// - wrapped: loss of signal on INPUT → failsafe; the partner's TST with
//   ACK heard on BSR → a WD node unwraps at the next frame start after
//   [`REINTEGRATE_CLOCKS`] of it, a WU node when a DATA
//   header arrives on BSR after it and no packet is arriving on INPUT (if
//   one is — the frame that went the long way round — when it ends, so it
//   is not cut into the new one); in failsafe too (issue 28: that is how a
//   ring that failed safe becomes whole again), where a WU node takes a
//   DATA header on BSR for the ACK (its upstream neighbour forwards the
//   ring's frames to it, so it is not wrapped towards it: the special
//   master's downstream neighbour, cut off with it, hears no TST);
// - stream controllers act only once the node is armed (its first good
//   frame) and not for [`SETTLE_CLOCKS`] after a change (the
//   receivers lock to their new lines); after unwrapping, a TST where DATA
//   is expected is not a failure for half a CS timeout (`o_grace_over`);
// - restart and rejoin (§12): an unarmed node in mode N wraps up (WU) on a
//   TST where DATA is expected on a lit INPUT (a restarted node between
//   wrapped neighbours), and unwraps like an armed one; a node that is
//   still rejoining (from power-up until, at a frame boundary, it is in
//   mode N, armed, with no TST on INPUT or BSR: `joined`) turns round at
//   its WU unwrap (WU → WD) when a TST arrives on INPUT (its downstream
//   neighbour is wrapped towards it), so the ring stays closed.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock |
// | `i_armed` | in | 1 | clock | the node has received its first good frame |
// | `i_hard_in`, `i_hard_bsr` | in | 1 | clock | structural channel failure on INPUT, on BSR ([`crate::node::stream_ctl`]) |
// | `i_run_in`, `i_run_bsr` | in | 1 | clock | a run of bad words on INPUT, on BSR |
// | `i_los_in`, `i_los_bsr` | in | 1 | clock | loss of signal on INPUT, on BSR |
// | `i_rw` | in | 1 | clock | the node knows the ring is wrapped |
// | `i_fs` | in | 1 | clock | the node is in failsafe |
// | `i_tst_ack` | in | 1 | clock | a TST with ACK is being heard on BSR |
// | `i_frame_start` | in | 1 | clock | a frame boundary: between frames on INPUT (a slave: a packet ended there and OUTPUT has sent it, [`SwitchPipe`]); the special master's period tick |
// | `i_bsr_data` | in | 1 | clock | a good DATA H0 on BSR |
// | `i_in_pkt` | in | 1 | clock | a packet is arriving on INPUT (a slave: or OUTPUT is still sending it, [`SwitchPipe`]) |
// | `i_tst_in`, `i_tst_bsr` | in | 1 | clock | a TST was heard on INPUT, on BSR, in the last 130 bit times ([`crate::node::stream_ctl`] `o_tst`) |
// | `i_cs_timeout` | in | 20 | static | CS timeout, clocks |
// | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD), registered |
// | `o_change` | out | 1 | clock | the mode changes at the next clock edge (combinational) |
// | `o_relink` | out | 1 | clock | … and INPUT and BSR move to other lines (into or out of WU) |
// | `o_tst_start` | out | 1 | clock | … and the TST generator goes onto an output (N → WU, WD) |
// | `o_fs_set` | out | 1 | clock | enter failsafe (combinational) |
// | `o_grace_over` | out | 1 | clock | a TST on a mode-N input counts as failure again |
//
// Latency: a decision takes effect at the next clock edge (`o_mode`).
//
// ```text
// i_hard_in ____/‾‾‾‾‾‾‾‾‾
// o_change  ____/‾\________        (mode N, ring not known wrapped)
// o_mode    ==N===X==WU====
// ```
// --------------------------------------------------------------------------
module merkur_slave__swc(clock,i_armed,i_hard_in,i_hard_bsr,i_run_in,i_run_bsr,i_los_in,i_los_bsr,i_rw,i_fs,i_tst_ack,i_frame_start,i_bsr_data,i_in_pkt,i_tst_in,i_tst_bsr,i_cs_timeout,i_fwd,o_mode,o_wu_next,o_change,o_relink,o_tst_start,o_fs_set,o_grace_over);

    // Module arguments
    input wire  clock;
    input wire  i_armed;
    input wire  i_hard_in;
    input wire  i_hard_bsr;
    input wire  i_run_in;
    input wire  i_run_bsr;
    input wire  i_los_in;
    input wire  i_los_bsr;
    input wire  i_rw;
    input wire  i_fs;
    input wire  i_tst_ack;
    input wire  i_frame_start;
    input wire  i_bsr_data;
    input wire  i_in_pkt;
    input wire  i_tst_in;
    input wire  i_tst_bsr;
    input wire  [19:0] i_cs_timeout;
    input wire  i_fwd;
    output reg  [1:0] o_mode;
    output reg  o_wu_next;
    output reg  o_change;
    output reg  o_relink;
    output reg  o_tst_start;
    output reg  o_fs_set;
    output reg  o_grace_over;

    // Constant declarations
    localparam  drain_start = 5'b10100;

    // Registers and child block ports
    reg  ctl__i_hard_in;
    reg  ctl__i_hard_bsr;
    reg  ctl__i_run_in;
    reg  ctl__i_run_bsr;
    reg  ctl__i_los_in;
    reg  ctl__i_los_bsr;
    reg  ctl__i_tst_ack;
    reg  ctl__i_frame_start;
    reg  ctl__i_bsr_data;
    reg  ctl__i_in_pkt;
    reg  ctl__i_tst_in;
    reg  ctl__i_tst_bsr;
    wire  [1:0] ctl__o_mode;
    wire  ctl__o_change;
    wire  ctl__o_relink;
    wire  ctl__o_tst_start;
    wire  ctl__o_fs_set;
    wire  ctl__o_grace_over;
    reg  hard_in_d;
    reg  hard_in_q;
    reg  hard_bsr_d;
    reg  hard_bsr_q;
    reg  run_in_d;
    reg  run_in_q;
    reg  run_bsr_d;
    reg  run_bsr_q;
    reg  los_in_d;
    reg  los_in_q;
    reg  los_bsr_d;
    reg  los_bsr_q;
    reg  tst_ack_d;
    reg  tst_ack_q;
    reg  frame_start_d;
    reg  frame_start_q;
    reg  bsr_data_d;
    reg  bsr_data_q;
    reg  in_pkt_d;
    reg  in_pkt_q;
    reg  tst_in_d;
    reg  tst_in_q;
    reg  tst_bsr_d;
    reg  tst_bsr_q;
    reg  [4:0] drain_d;
    reg  [4:0] drain_q;
    reg  out_end_d;
    reg  out_end_q;
    reg  [1:0] mode_d;
    reg  [1:0] mode_q;
    reg  change_d;
    reg  change_q;
    reg  relink_d;
    reg  relink_q;
    reg  tst_start_d;
    reg  tst_start_q;
    reg  fs_set_d;
    reg  fs_set_q;
    reg  grace_over_d;
    reg  grace_over_q;

    // Child blocks
    merkur_slave__swc__ctl ctl(
        .clock(clock),
        .i_armed(i_armed),
        .i_hard_in(ctl__i_hard_in),
        .i_hard_bsr(ctl__i_hard_bsr),
        .i_run_in(ctl__i_run_in),
        .i_run_bsr(ctl__i_run_bsr),
        .i_los_in(ctl__i_los_in),
        .i_los_bsr(ctl__i_los_bsr),
        .i_rw(i_rw),
        .i_fs(i_fs),
        .i_tst_ack(ctl__i_tst_ack),
        .i_frame_start(ctl__i_frame_start),
        .i_bsr_data(ctl__i_bsr_data),
        .i_in_pkt(ctl__i_in_pkt),
        .i_tst_in(ctl__i_tst_in),
        .i_tst_bsr(ctl__i_tst_bsr),
        .i_cs_timeout(i_cs_timeout),
        .o_mode(ctl__o_mode),
        .o_change(ctl__o_change),
        .o_relink(ctl__o_relink),
        .o_tst_start(ctl__o_tst_start),
        .o_fs_set(ctl__o_fs_set),
        .o_grace_over(ctl__o_grace_over)
    );

    // Combinational logic
    always @(*) begin
        hard_in_d = hard_in_q;
        hard_bsr_d = hard_bsr_q;
        run_in_d = run_in_q;
        run_bsr_d = run_bsr_q;
        los_in_d = los_in_q;
        los_bsr_d = los_bsr_q;
        tst_ack_d = tst_ack_q;
        frame_start_d = frame_start_q;
        bsr_data_d = bsr_data_q;
        in_pkt_d = in_pkt_q;
        tst_in_d = tst_in_q;
        tst_bsr_d = tst_bsr_q;
        drain_d = drain_q;
        out_end_d = out_end_q;
        mode_d = mode_q;
        change_d = change_q;
        relink_d = relink_q;
        tst_start_d = tst_start_q;
        fs_set_d = fs_set_q;
        grace_over_d = grace_over_q;
        hard_in_d = i_hard_in;
        hard_bsr_d = i_hard_bsr;
        run_in_d = i_run_in;
        run_bsr_d = i_run_bsr;
        los_in_d = i_los_in;
        los_bsr_d = i_los_bsr;
        tst_ack_d = i_tst_ack;
        frame_start_d = i_frame_start;
        bsr_data_d = i_bsr_data;
        in_pkt_d = i_in_pkt;
        tst_in_d = i_tst_in;
        tst_bsr_d = i_tst_bsr;
        ctl__i_hard_in = hard_in_q;
        ctl__i_hard_bsr = hard_bsr_q;
        ctl__i_run_in = run_in_q;
        ctl__i_run_bsr = run_bsr_q;
        ctl__i_los_in = los_in_q;
        ctl__i_los_bsr = los_bsr_q;
        ctl__i_tst_ack = tst_ack_q;
        if (i_in_pkt) begin
            drain_d = drain_start;
        end
        else if (drain_q != 5'h0) begin
            drain_d = drain_q - 5'h1;
        end
        out_end_d = (drain_q == 5'h1) & ~i_in_pkt;
        ctl__i_frame_start = frame_start_q;
        ctl__i_in_pkt = in_pkt_q;
        if (i_fwd) begin
            ctl__i_frame_start = out_end_q;
            ctl__i_in_pkt = in_pkt_q | (drain_q != 5'h0);
        end
        ctl__i_bsr_data = bsr_data_q;
        ctl__i_tst_in = tst_in_q;
        ctl__i_tst_bsr = tst_bsr_q;
        mode_d = ctl__o_mode;
        change_d = ctl__o_change;
        relink_d = ctl__o_relink;
        tst_start_d = ctl__o_tst_start;
        fs_set_d = ctl__o_fs_set;
        grace_over_d = ctl__o_grace_over;
        o_mode = mode_q;
        o_wu_next = ctl__o_mode == 2'h1;
        o_change = change_q;
        o_relink = relink_q;
        o_tst_start = tst_start_q;
        o_fs_set = fs_set_q;
        o_grace_over = grace_over_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial hard_in_q = 1'h0;
    always @(posedge clock) hard_in_q <= hard_in_d;
    initial hard_bsr_q = 1'h0;
    always @(posedge clock) hard_bsr_q <= hard_bsr_d;
    initial run_in_q = 1'h0;
    always @(posedge clock) run_in_q <= run_in_d;
    initial run_bsr_q = 1'h0;
    always @(posedge clock) run_bsr_q <= run_bsr_d;
    initial los_in_q = 1'h0;
    always @(posedge clock) los_in_q <= los_in_d;
    initial los_bsr_q = 1'h0;
    always @(posedge clock) los_bsr_q <= los_bsr_d;
    initial tst_ack_q = 1'h0;
    always @(posedge clock) tst_ack_q <= tst_ack_d;
    initial frame_start_q = 1'h0;
    always @(posedge clock) frame_start_q <= frame_start_d;
    initial bsr_data_q = 1'h0;
    always @(posedge clock) bsr_data_q <= bsr_data_d;
    initial in_pkt_q = 1'h0;
    always @(posedge clock) in_pkt_q <= in_pkt_d;
    initial tst_in_q = 1'h0;
    always @(posedge clock) tst_in_q <= tst_in_d;
    initial tst_bsr_q = 1'h0;
    always @(posedge clock) tst_bsr_q <= tst_bsr_d;
    initial drain_q = 5'h0;
    always @(posedge clock) drain_q <= drain_d;
    initial out_end_q = 1'h0;
    always @(posedge clock) out_end_q <= out_end_d;
    initial mode_q = 2'h0;
    always @(posedge clock) mode_q <= mode_d;
    initial change_q = 1'h0;
    always @(posedge clock) change_q <= change_d;
    initial relink_q = 1'h0;
    always @(posedge clock) relink_q <= relink_d;
    initial tst_start_q = 1'h0;
    always @(posedge clock) tst_start_q <= tst_start_d;
    initial fs_set_q = 1'h0;
    always @(posedge clock) fs_set_q <= fs_set_d;
    initial grace_over_q = 1'h0;
    always @(posedge clock) grace_over_q <= grace_over_d;
endmodule // merkur_slave__swc
// --------------------------------------------------------------------------
// `ctl`: SwitchCtl, Switchbox decision logic. (rtl/src/node/switch_ctl.rs)
//
// # switch_ctl — a node's switchbox decisions (protocol §10, §12)
//
// Purpose: the local fault management of every node, the special master
// included: from its two stream controllers it decides the switchbox mode
// (Table 1), the failsafe of a second fault, and reintegration when a
// repaired link's partner acknowledges its TST. No central station: each
// node runs one of these on what it sees.
//
// - mode N: INPUT fails → WU; else BSR fails → WD. A structural failure
//   (`i_hard_*`: loss of signal, a TST where DATA is expected) while the
//   node knows the ring is wrapped is the second fault: failsafe, and so is
//   loss of signal on both at once. A run of bad words (`i_run_*`, a
//   transient) counts only while the ring is not known wrapped (a soft
//   wrap), and never for failsafe (protocol §9, §12);
// - wrapped: loss of signal on INPUT → failsafe; the partner's TST with
//   ACK heard on BSR → a WD node unwraps at the next frame start after
//   [`REINTEGRATE_CLOCKS`] of it, a WU node when a DATA
//   header arrives on BSR after it and no packet is arriving on INPUT (if
//   one is — the frame that went the long way round — when it ends, so it
//   is not cut into the new one); in failsafe too (issue 28: that is how a
//   ring that failed safe becomes whole again), where a WU node takes a
//   DATA header on BSR for the ACK (its upstream neighbour forwards the
//   ring's frames to it, so it is not wrapped towards it: the special
//   master's downstream neighbour, cut off with it, hears no TST);
// - stream controllers act only once the node is armed (its first good
//   frame) and not for [`SETTLE_CLOCKS`] after a change (the
//   receivers lock to their new lines); after unwrapping, a TST where DATA
//   is expected is not a failure for half a CS timeout (`o_grace_over`);
// - restart and rejoin (§12): an unarmed node in mode N wraps up (WU) on a
//   TST where DATA is expected on a lit INPUT (a restarted node between
//   wrapped neighbours), and unwraps like an armed one; a node that is
//   still rejoining (from power-up until, at a frame boundary, it is in
//   mode N, armed, with no TST on INPUT or BSR: `joined`) turns round at
//   its WU unwrap (WU → WD) when a TST arrives on INPUT (its downstream
//   neighbour is wrapped towards it), so the ring stays closed.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock |
// | `i_armed` | in | 1 | clock | the node has received its first good frame |
// | `i_hard_in`, `i_hard_bsr` | in | 1 | clock | structural channel failure on INPUT, on BSR ([`crate::node::stream_ctl`]) |
// | `i_run_in`, `i_run_bsr` | in | 1 | clock | a run of bad words on INPUT, on BSR |
// | `i_los_in`, `i_los_bsr` | in | 1 | clock | loss of signal on INPUT, on BSR |
// | `i_rw` | in | 1 | clock | the node knows the ring is wrapped |
// | `i_fs` | in | 1 | clock | the node is in failsafe |
// | `i_tst_ack` | in | 1 | clock | a TST with ACK is being heard on BSR |
// | `i_frame_start` | in | 1 | clock | a frame boundary: between frames on INPUT (a slave: a packet ended there and OUTPUT has sent it, [`SwitchPipe`]); the special master's period tick |
// | `i_bsr_data` | in | 1 | clock | a good DATA H0 on BSR |
// | `i_in_pkt` | in | 1 | clock | a packet is arriving on INPUT (a slave: or OUTPUT is still sending it, [`SwitchPipe`]) |
// | `i_tst_in`, `i_tst_bsr` | in | 1 | clock | a TST was heard on INPUT, on BSR, in the last 130 bit times ([`crate::node::stream_ctl`] `o_tst`) |
// | `i_cs_timeout` | in | 20 | static | CS timeout, clocks |
// | `o_mode` | out | 2 | clock | switchbox mode (0 N, 1 WU, 2 WD), registered |
// | `o_change` | out | 1 | clock | the mode changes at the next clock edge (combinational) |
// | `o_relink` | out | 1 | clock | … and INPUT and BSR move to other lines (into or out of WU) |
// | `o_tst_start` | out | 1 | clock | … and the TST generator goes onto an output (N → WU, WD) |
// | `o_fs_set` | out | 1 | clock | enter failsafe (combinational) |
// | `o_grace_over` | out | 1 | clock | a TST on a mode-N input counts as failure again |
//
// Latency: a decision takes effect at the next clock edge (`o_mode`).
//
// ```text
// i_hard_in ____/‾‾‾‾‾‾‾‾‾
// o_change  ____/‾\________        (mode N, ring not known wrapped)
// o_mode    ==N===X==WU====
// ```
// --------------------------------------------------------------------------
module merkur_slave__swc__ctl(clock,i_armed,i_hard_in,i_hard_bsr,i_run_in,i_run_bsr,i_los_in,i_los_bsr,i_rw,i_fs,i_tst_ack,i_frame_start,i_bsr_data,i_in_pkt,i_tst_in,i_tst_bsr,i_cs_timeout,o_mode,o_change,o_relink,o_tst_start,o_fs_set,o_grace_over);

    // Module arguments
    input wire  clock;
    input wire  i_armed;
    input wire  i_hard_in;
    input wire  i_hard_bsr;
    input wire  i_run_in;
    input wire  i_run_bsr;
    input wire  i_los_in;
    input wire  i_los_bsr;
    input wire  i_rw;
    input wire  i_fs;
    input wire  i_tst_ack;
    input wire  i_frame_start;
    input wire  i_bsr_data;
    input wire  i_in_pkt;
    input wire  i_tst_in;
    input wire  i_tst_bsr;
    input wire  [19:0] i_cs_timeout;
    output reg  [1:0] o_mode;
    output reg  o_change;
    output reg  o_relink;
    output reg  o_tst_start;
    output reg  o_fs_set;
    output reg  o_grace_over;

    // Constant declarations
    localparam  reint_m1 = 9'b100000011;
    localparam  settle_start = 7'b1100100;

    // Registers and child block ports
    reg  [1:0] mode_d;
    reg  [1:0] mode_q;
    reg  chg_d;
    reg  chg_q;
    reg  [6:0] settle_d;
    reg  [6:0] settle_q;
    reg  busy_d;
    reg  busy_q;
    reg  [19:0] grace_d;
    reg  [19:0] grace_q;
    reg  run_d;
    reg  run_q;
    reg  [8:0] ack_time_d;
    reg  [8:0] ack_time_q;
    reg  ack_done_d;
    reg  ack_done_q;
    reg  seen_ack_d;
    reg  seen_ack_q;
    reg  pend_up_d;
    reg  pend_up_q;
    reg  joined_d;
    reg  joined_q;

    // Local signals
    reg  [1:0] new_mode;
    reg  fail_in;
    reg  fail_bsr;
    reg  up_ok;
    reg  acting;
    reg  live;
    reg  wake;
    reg  turn;
    reg  in_n;
    reg  go_wu;
    reg  go_wd;
    reg  unwrap;
    reg  bsr_ok;
    reg  ack_inc;
    reg  [19:0] grace_l;
    reg  [19:0] grace_m;

    // Combinational logic
    always @(*) begin
        mode_d = mode_q;
        chg_d = chg_q;
        settle_d = settle_q;
        busy_d = busy_q;
        grace_d = grace_q;
        run_d = run_q;
        ack_time_d = ack_time_q;
        ack_done_d = ack_done_q;
        seen_ack_d = seen_ack_q;
        pend_up_d = pend_up_q;
        joined_d = joined_q;
        chg_d = 1'b0;
        grace_l = i_cs_timeout >> 1;
        grace_m = grace_l | (grace_l >> 1);
        grace_m = grace_m | (grace_m >> 2);
        grace_m = grace_m | (grace_m >> 4);
        grace_m = grace_m | (grace_m >> 8);
        grace_m = grace_m | (grace_m >> 16);
        if (chg_q & (mode_q == 2'h0)) begin
            grace_d = grace_l - 20'h1;
            run_d = grace_l > 20'h1;
        end
        else if (run_q) begin
            grace_d = (grace_q - 20'h1) & grace_m;
            run_d = grace_q != 20'h1;
        end
        if (chg_q) begin
            settle_d = settle_start - 7'h1;
        end
        else if (busy_q) begin
            settle_d = settle_q - 7'h1;
        end
        busy_d = chg_q | (settle_q > 7'h1);
        live = ~busy_q & ~chg_q;
        acting = i_armed & live;
        up_ok = seen_ack_q | i_fs;
        fail_in = i_hard_in | (i_run_in & ~i_rw);
        fail_bsr = i_hard_bsr | (i_run_bsr & ~i_rw);
        in_n = mode_q == 2'h0;
        wake = ~i_armed & live & i_tst_in & ~i_los_in;
        go_wu = in_n & ((acting & fail_in) | wake);
        go_wd = acting & in_n & ~fail_in & fail_bsr;
        bsr_ok = up_ok & i_bsr_data;
        unwrap = live & (((mode_q == 2'h2) & ack_done_q & i_frame_start) | ((mode_q == 2'h1) & (pend_up_q | bsr_ok) & ~i_in_pkt));
        turn = unwrap & (mode_q == 2'h1) & ~joined_q & i_tst_in;
        new_mode = mode_q;
        if (unwrap) begin
            new_mode = 2'h0;
        end
        if (turn) begin
            new_mode = 2'h2;
        end
        if (go_wd) begin
            new_mode = 2'h2;
        end
        if (go_wu) begin
            new_mode = 2'h1;
        end
        o_change = go_wu | go_wd | unwrap;
        o_relink = go_wu | (unwrap & (mode_q == 2'h1));
        o_tst_start = go_wu | go_wd | turn;
        o_fs_set = acting & ((in_n & (((i_hard_in | i_hard_bsr) & i_rw) | (i_los_in & i_los_bsr))) | (~in_n & i_los_in));
        ack_inc = live & ~in_n & i_tst_ack & ~ack_done_q;
        if (live & ~in_n & i_tst_ack) begin
            seen_ack_d = 1'b1;
        end
        if (ack_inc) begin
            ack_time_d = ack_time_q + 9'h1;
        end
        if (live & (mode_q == 2'h1) & bsr_ok) begin
            pend_up_d = 1'b1;
        end
        if ((ack_time_q == reint_m1) & ack_inc) begin
            ack_done_d = 1'b1;
        end
        if (i_armed & in_n & i_frame_start & ~i_tst_in & ~i_tst_bsr) begin
            joined_d = 1'b1;
        end
        if (o_change) begin
            mode_d = new_mode;
            chg_d = 1'b1;
            if (unwrap & ~turn) begin
                run_d = grace_l != 20'h0;
            end
        end
        if (busy_q) begin
            ack_time_d = 9'h0;
            ack_done_d = 1'b0;
            seen_ack_d = 1'b0;
            pend_up_d = 1'b0;
        end
        o_mode = mode_q;
        o_grace_over = ~run_q;
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial mode_q = 2'h0;
    always @(posedge clock) mode_q <= mode_d;
    initial chg_q = 1'h0;
    always @(posedge clock) chg_q <= chg_d;
    initial settle_q = 7'h0;
    always @(posedge clock) settle_q <= settle_d;
    initial busy_q = 1'h0;
    always @(posedge clock) busy_q <= busy_d;
    initial grace_q = 20'h0;
    always @(posedge clock) grace_q <= grace_d;
    initial run_q = 1'h0;
    always @(posedge clock) run_q <= run_d;
    initial ack_time_q = 9'h0;
    always @(posedge clock) ack_time_q <= ack_time_d;
    initial ack_done_q = 1'h0;
    always @(posedge clock) ack_done_q <= ack_done_d;
    initial seen_ack_q = 1'h0;
    always @(posedge clock) seen_ack_q <= seen_ack_d;
    initial pend_up_q = 1'h0;
    always @(posedge clock) pend_up_q <= pend_up_d;
    initial joined_q = 1'h0;
    always @(posedge clock) joined_q <= joined_d;
endmodule // merkur_slave__swc__ctl
// --------------------------------------------------------------------------
// `tst`: TstTx, TST generator. (rtl/src/node/tst_tx.rs)
//
// # tst_tx — link test (TST) packet generator (protocol §5, §9, §12)
//
// Purpose: what a wrapped node sends on BSS: a TST packet every 65 bit
// times on its own clock: J K, H0 = `{10, 0, ACK, ADDR}`, H1 = NOT H0, one
// idle group. ACK tells the partner that its TST is heard.
//
// Parameters: the word format ([`WordFormat`]); extended-alarm words have
// a reason nibble N1 = 0 after the first group, and a TST takes 75 bit times.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock, 2× line rate |
// | `i_ack` | in | 1 | clock | ACK bit (partner's TST heard), taken at each packet start |
// | `i_address` | in | 12 | static | node address |
// | `i_restart` | in | 1 | clock | the output is switched to this generator: a dark lead-in of 12 bit times, an idle group, then TST |
// | `o_line` | out | 2 | clock | line, DDR pair |
//
// Latency: free running; one bit every 2 clocks, a packet every 130 clocks.
// After `i_restart` the line holds its level for 12 bit times, the dark
// time of every switchbox change ([`crate::node::sw_dark`]: a receiver that was
// inside a word of the stream this replaces mutes and drops it,
// [`crate::line::monitor`], rather than completing it with TST bits), then one
// idle group and the next TST.
//
// ```text
// o_line   | J K | H0 (25) | H1 = ~H0 (25) | I | J K | ...      65 bit times each
// ```
// --------------------------------------------------------------------------
module merkur_slave__tst(clock,i_ack,i_address,i_restart,o_line);

    // Module arguments
    input wire  clock;
    input wire  i_ack;
    input wire  [11:0] i_address;
    input wire  i_restart;
    output reg  [1:0] o_line;

    // Constant declarations
    localparam  ext = 1'b0;
    localparam  h1_at = 4'h7;
    localparam  idle_at = 4'hc;

    // Registers and child block ports
    reg  [4:0] enc__i_sym;
    wire  [4:0] enc__o_code;
    reg  tx__i_bit_en;
    reg  [4:0] tx__i_code;
    wire  tx__o_take;
    wire  tx__o_line;
    reg  half_d;
    reg  half_q;
    reg  [4:0] dark_d;
    reg  [4:0] dark_q;
    reg  [3:0] gnum_d;
    reg  [3:0] gnum_q;
    reg  ack_d;
    reg  ack_q;

    // Local signals
    reg  [15:0] word;
    reg  [3:0] wg;
    reg  [3:0] dg;
    reg  [3:0] nib;
    reg  p_a;
    reg  p_b;
    reg  [4:0] sym;

    // Child blocks
    merkur_slave__tst__enc enc(
        .i_sym(enc__i_sym),
        .o_code(enc__o_code)
    );
    merkur_slave__tst__tx tx(
        .clock(clock),
        .i_bit_en(tx__i_bit_en),
        .i_code(tx__i_code),
        .o_take(tx__o_take),
        .o_line(tx__o_line)
    );

    // Combinational logic
    always @(*) begin
        half_d = half_q;
        gnum_d = gnum_q;
        ack_d = ack_q;
        dark_d = dark_q;
        half_d = ~half_q;
        tx__i_bit_en = half_q & (dark_q == 5'h0);
        if (dark_q != 5'h0) begin
            dark_d = dark_q - 5'h1;
        end
        word = ({4'h0, i_address}) | 16'h8000;
        if (ack_q) begin
            word = word | 16'h1000;
        end
        wg = gnum_q - 4'h2;
        if (gnum_q >= h1_at) begin
            word = ~word;
            wg = gnum_q - h1_at;
        end
        dg = wg;
        if (ext & (wg != 4'h0)) begin
            dg = wg - 4'h1;
            if (wg == 4'h1) begin
                dg = 4'h7;
            end
        end
        p_a = ~(word[5] ^ word[4] ^ word[9] ^ word[8] ^ word[13] ^ word[12] ^ word[15]);
        p_b = ~(word[1] ^ word[0] ^ word[4] ^ word[3] ^ word[2] ^ word[8] ^ word[7] ^ word[6] ^ word[12] ^ word[11] ^ word[10] ^ word[15] ^ word[14]);
        nib = word[(0)+:(4)] & 4'h3;
        if (dg == 4'h7) begin
            nib = 4'h0;
        end
        if (dg == 4'h1) begin
            nib = word[(2)+:(4)];
        end
        if (dg == 4'h2) begin
            nib = word[(6)+:(4)];
        end
        if (dg == 4'h3) begin
            nib = word[(10)+:(4)];
        end
        if (dg == 4'h4) begin
            nib = (word[(12)+:(4)] >> 1) & 4'h6;
            if (p_a) begin
                nib = nib | 4'h8;
            end
            if (p_b) begin
                nib = nib | 4'h1;
            end
        end
        sym = 5'h0;
        if (nib[0]) begin
            sym = sym | 5'h1;
        end
        if (nib[1]) begin
            sym = sym | 5'h2;
        end
        if (nib[2]) begin
            sym = sym | 5'h4;
        end
        if (nib[3]) begin
            sym = sym | 5'h8;
        end
        if (gnum_q == 4'h0) begin
            sym = 5'h10;
        end
        if (gnum_q == 4'h1) begin
            sym = 5'h11;
        end
        if (gnum_q == idle_at) begin
            sym = 5'h12;
        end
        enc__i_sym = sym;
        tx__i_code = enc__o_code;
        if (tx__o_take) begin
            gnum_d = gnum_q + 4'h1;
            if (gnum_q == idle_at) begin
                gnum_d = 4'h0;
                ack_d = i_ack;
            end
        end
        if (i_restart) begin
            dark_d = 5'h18;
            gnum_d = idle_at;
        end
        o_line = 2'h0;
        if (tx__o_line) begin
            o_line = 2'h3;
        end
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial half_q = 1'h0;
    always @(posedge clock) half_q <= half_d;
    initial dark_q = 5'h0;
    always @(posedge clock) dark_q <= dark_d;
    initial gnum_q = 4'h0;
    always @(posedge clock) gnum_q <= gnum_d;
    initial ack_q = 1'h0;
    always @(posedge clock) ack_q <= ack_d;
endmodule // merkur_slave__tst
// --------------------------------------------------------------------------
// `enc`: Enc4b5b, 4B/5B encoder. (rtl/src/line/enc4b5b.rs)
//
// # enc4b5b — 4B/5B symbol encoder (protocol §2)
//
// Purpose: maps a symbol number to its 5-bit code group. Symbols 0..=15 are
// data nibbles; [`SYM_J`], [`SYM_K`], [`SYM_I`], [`SYM_S`] are the control
// groups. Any other symbol number gives I (idle), so the line never carries
// an undefined group.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `i_sym` | in | 5 | — (combinational) | symbol number |
// | `o_code` | out | 5 | — | code group, bit 4 sent first |
//
// Latency: combinational (0 clocks).
//
// ```text
// i_sym   ==X== 0x0 ==X== 0x10 (J) ==X== 0x12 (I) ==
// o_code  ==X= 11110 =X== 11000 ====X== 11111 =====
// ```
// --------------------------------------------------------------------------
module merkur_slave__tst__enc(i_sym,o_code);

    // Module arguments
    input wire  [4:0] i_sym;
    output reg  [4:0] o_code;

    // Registers and child block ports
    wire  [4:0] rom__data;

    // Child blocks
    merkur_slave__tst__enc__rom rom(
        .address(i_sym),
        .data(rom__data)
    );

    // Combinational logic
    always @(*) begin
        o_code = rom__data;
    end

endmodule // merkur_slave__tst__enc
// --------------------------------------------------------------------------
// `rom` of `merkur_slave__tst__enc`: a table (rust-hdl ROM), read combinationally.
// --------------------------------------------------------------------------
module merkur_slave__tst__enc__rom(address,data);

    // Module arguments
    input wire  [4:0] address;
    output reg  [4:0] data;

    // Update code (custom)
    always @*
    case (address)
        5'b0: data = 5'b11110;
      5'b1: data = 5'b1001;
      5'b10: data = 5'b10100;
      5'b11: data = 5'b10101;
      5'b100: data = 5'b1010;
      5'b101: data = 5'b1011;
      5'b110: data = 5'b1110;
      5'b111: data = 5'b1111;
      5'b1000: data = 5'b10010;
      5'b1001: data = 5'b10011;
      5'b1010: data = 5'b10110;
      5'b1011: data = 5'b10111;
      5'b1100: data = 5'b11010;
      5'b1101: data = 5'b11011;
      5'b1110: data = 5'b11100;
      5'b1111: data = 5'b11101;
      5'b10000: data = 5'b11000;
      5'b10001: data = 5'b10001;
      5'b10010: data = 5'b11111;
      5'b10011: data = 5'b11001;
      5'b10100: data = 5'b11111;
      5'b10101: data = 5'b11111;
      5'b10110: data = 5'b11111;
      5'b10111: data = 5'b11111;
      5'b11000: data = 5'b11111;
      5'b11001: data = 5'b11111;
      5'b11010: data = 5'b11111;
      5'b11011: data = 5'b11111;
      5'b11100: data = 5'b11111;
      5'b11101: data = 5'b11111;
      5'b11110: data = 5'b11111;
      5'b11111: data = 5'b11111;
      default: data = 5'b0;
    endcase

endmodule // merkur_slave__tst__enc__rom
// --------------------------------------------------------------------------
// `tx`: NrziTx, Serializer + NRZI modulator. (rtl/src/line/nrzi_tx.rs)
//
// # nrzi_tx — code-group serializer with NRZI (protocol §2)
//
// Purpose: sends 5-bit code groups bit by bit, most significant bit first,
// NRZI-modulated: a 1 toggles `o_line`, a 0 keeps it. One bit per
// `i_bit_en` (the node's bit-time enable, tied high when the core clock is
// the bit clock). The group on `i_code` is taken in the clock where `o_take`
// is high (the first bit time of each group), so the feeding logic has the
// whole previous group's time to prepare it.
//
// | port | dir | width | clock domain | meaning |
// |---|---|---|---|---|
// | `clock` | in | 1 | — | core clock |
// | `i_bit_en` | in | 1 | clock | one bit time |
// | `i_code` | in | 5 | clock | next code group, sampled when `o_take` |
// | `o_take` | out | 1 | clock | `i_code` is taken in this clock |
// | `o_line` | out | 1 | clock | NRZI line level (registered) |
//
// Latency: `o_line` shows a group's first bit one clock after the clock in
// which `o_take` was high; a group occupies 5 bit times.
//
// ```text
// clock     _/‾\_/‾\_/‾\_/‾\_/‾\_/‾\_/‾\_
// i_bit_en  ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾ (tied high)
// o_take    ‾‾‾\___________________/‾‾‾‾
// i_code    = G0 =================== G1 =
// code bit      g0[4] g0[3] g0[2] g0[1] g0[0] g1[4]
// o_line    ____ toggles on every 1 bit ____
// ```
// --------------------------------------------------------------------------
module merkur_slave__tst__tx(clock,i_bit_en,i_code,o_take,o_line);

    // Module arguments
    input wire  clock;
    input wire  i_bit_en;
    input wire  [4:0] i_code;
    output reg  o_take;
    output reg  o_line;

    // Registers and child block ports
    reg  [4:0] shift_d;
    reg  [4:0] shift_q;
    reg  [2:0] count_d;
    reg  [2:0] count_q;
    reg  level_d;
    reg  level_q;

    // Combinational logic
    always @(*) begin
        shift_d = shift_q;
        count_d = count_q;
        level_d = level_q;
        o_take = i_bit_en & (count_q == 3'h0);
        o_line = level_q;
        if (i_bit_en) begin
            if (count_q == 3'h0) begin
                level_d = level_q ^ i_code[4];
                shift_d = i_code << 1;
            end
            else begin
                level_d = level_q ^ shift_q[4];
                shift_d = shift_q << 1;
            end
            if (count_q == 3'h4) begin
                count_d = 3'h0;
            end
            else begin
                count_d = count_q + 3'h1;
            end
        end
    end

    // Registers: the power-up value, and the next value (`<register>_d`, set above) at each clock edge
    initial shift_q = 5'h0;
    always @(posedge clock) shift_q <= shift_d;
    initial count_q = 3'h0;
    always @(posedge clock) count_q <= count_d;
    initial level_q = 1'h0;
    always @(posedge clock) level_q <= level_d;
endmodule // merkur_slave__tst__tx
