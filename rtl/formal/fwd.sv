// Formal properties of the forwarder's fresh word (protocol §4: a node
// writes its fresh word into its own slot). The whole forwarder is under
// proof; every input is free in every clock. Proved by k-induction.
//
// The f_* registers hold the fresh word for stage B: they follow it
// (`fresh_data`) in every clock between words, and hold it from the
// clock a word's first group is pending for stage B (`g_pend`) until the
// word is done (`gidx` back at 0). The forwarder takes that condition
// from one flip-flop of its own (`f_hold`, issue 21: one literal in each
// f_* bit's product terms instead of the four of `gidx` and `g_pend`),
// set from their next values.
//
// - f_data_follows, f_data_holds: `f_data` is the fresh word of the clock
//   before when no word was under way then, and unchanged when one was:
//   the condition as stated from `gidx` and `g_pend`, not from `f_hold`.
// - inv_f_hold: the flip-flop is that condition in every clock (the
//   induction's invariant).
//
// The cover shows that a word's hold is reached (a group pending after a
// J K), so the environment is not vacuous.
module fwd_props (
    input wire clock,
    input wire i_bvalid, input wire i_code, input wire [1:0] i_phase,
    input wire i_hdr_bad, input wire i_mute,
    input wire [11:0] i_slots_m1, input wire [11:0] i_address,
    input wire i_actuator, input wire [15:0] i_sensor_data,
    input wire [15:0] i_act_out, input wire i_fs, input wire i_wrapped,
    input wire i_alarm_req, input wire [3:0] i_alarm_reason,
    input wire i_alarm_seq, input wire i_master, input wire [1:0] i_slot_cfg,
    input wire [15:0] i_slot_data, input wire i_slot_alive, input wire i_armed,
    input wire i_wvalid, input wire [1:0] i_wkind, input wire i_wodd,
    input wire i_wok, input wire i_walarm, input wire [15:0] i_wdata,
    input wire [1:0] i_ptype
);
    wire [2:0] gidx_q;
    wire g_pend_q, f_hold_q;
    wire [15:0] f_data_q, fresh_data;
    fwd dut (
        .clock(clock), .i_bvalid(i_bvalid), .i_code(i_code), .i_phase(i_phase),
        .i_hdr_bad(i_hdr_bad), .i_mute(i_mute), .i_slots_m1(i_slots_m1),
        .i_address(i_address), .i_actuator(i_actuator),
        .i_sensor_data(i_sensor_data), .i_act_out(i_act_out), .i_fs(i_fs),
        .i_wrapped(i_wrapped), .i_alarm_req(i_alarm_req),
        .i_alarm_reason(i_alarm_reason), .i_alarm_seq(i_alarm_seq),
        .i_master(i_master), .i_slot_cfg(i_slot_cfg),
        .i_slot_data(i_slot_data), .i_slot_alive(i_slot_alive),
        .i_armed(i_armed), .i_wvalid(i_wvalid), .i_wkind(i_wkind),
        .i_wodd(i_wodd), .i_wok(i_wok), .i_walarm(i_walarm),
        .i_wdata(i_wdata), .i_ptype(i_ptype),
        .o_slot(), .o_rtx_own(), .o_rtx_idx(), .o_rtx_ok(), .o_regen(),
        .o_alarm_sent(), .o_sent_reason(), .o_prev_alarm(), .o_pkt_done(),
        .o_toggle(), .o_line(),
        .gidx_q(gidx_q), .g_pend_q(g_pend_q), .f_hold_q(f_hold_q),
        .f_data_q(f_data_q), .fresh_data(fresh_data)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    always @(posedge clock) if (past_valid) begin
        if ($past(gidx_q == 3'd0 && !g_pend_q))
            f_data_follows: assert (f_data_q == $past(fresh_data));
        else
            f_data_holds: assert (f_data_q == $past(f_data_q));
    end
    always @(*) begin
        inv_f_hold: assert (f_hold_q == (gidx_q != 3'd0 || g_pend_q));
        cover_hold: cover (g_pend_q && gidx_q == 3'd0);
    end
endmodule
