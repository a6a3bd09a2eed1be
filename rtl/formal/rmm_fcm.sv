// Formal properties of rmm_fcm, the 802.4 fault correction machine
// (protocol §21, the paper's section 3). One clock is one octet. Every
// input is free in every octet. Proved by k-induction.
//
// - the machine has exactly the five states, and its next state and
//   report (cause register, interrupt) are exactly those of §21's table,
//   first matching row first; written out again below as `row`;
// - a fault switch (Auto_Normal → Medium_Error) toggles the channel in the
//   octet of the fault; a commanded switch happens only outside a frame,
//   only for a command received or sent (pending), and at the first octet
//   outside a frame that is not a fault switch; the status check's switch
//   (rows 14 and 15, §20 Status Check = SWITCH) is pending like a command,
//   to the standby;
// - covers: every row of the table fires (so every state is reached and
//   every state has a way out; IDLE is left only by `init`).
module rmm_fcm_props (
    input wire clock,
    input wire i_init, input wire i_auto, input wire i_sc, input wire i_ns,
    input wire i_chk_ok, input wire i_chk_sw, input wire i_fault_a, input wire i_fault_b,
    input wire i_bad_a, input wire i_bad_b, input wire i_act,
    input wire i_in_frame, input wire i_cmd_rx, input wire i_cmd_ch,
    input wire i_cmd_sent
);
    // States: rmm_fcm's `o_state` encoding (its port table).
    localparam [2:0] IDLE = 3'd0, MANUAL = 3'd1, AUTO = 3'd2, CONFIG = 3'd3, MEDIUM = 3'd4;
    // Causes: the report register's encoding (model/src/rmm.rs, `cause`).
    localparam [3:0] C_INIT = 4'd1, C_CHECK_OK = 4'd2, C_AUTO_CMD = 4'd3,
        C_ACTIVE_FAULT = 4'd4, C_NS = 4'd5, C_STANDBY_FAULT = 4'd6, C_SC = 4'd7,
        C_CMD_RX = 4'd8, C_CMD_SENT = 4'd9, C_SWITCHED = 4'd10, C_BOTH = 4'd11,
        C_CHECK_SW = 4'd12;

    wire o_sw, o_irq, o_cmd_req, o_cmd_ch;
    wire [2:0] o_state;
    wire [3:0] o_cause;
    wire pend_q, pend_ch_q;
    rmm_fcm dut (
        .clock(clock), .i_init(i_init), .i_auto(i_auto), .i_sc(i_sc),
        .i_ns(i_ns), .i_chk_ok(i_chk_ok), .i_chk_sw(i_chk_sw), .i_fault_a(i_fault_a),
        .i_fault_b(i_fault_b), .i_bad_a(i_bad_a), .i_bad_b(i_bad_b),
        .i_act(i_act), .i_in_frame(i_in_frame), .i_cmd_rx(i_cmd_rx),
        .i_cmd_ch(i_cmd_ch), .i_cmd_sent(i_cmd_sent), .o_sw(o_sw),
        .o_state(o_state), .o_cause(o_cause), .o_irq(o_irq),
        .o_cmd_req(o_cmd_req), .o_cmd_ch(o_cmd_ch),
        .pend_q(pend_q), .pend_ch_q(pend_ch_q)
    );

    // ---- §21, row by row --------------------------------------------------
    wire both = i_bad_a & i_bad_b;
    wire active_fault = i_act ? i_fault_b : i_fault_a;
    wire standby_faulty = i_act ? (i_fault_a | i_bad_a) : (i_fault_b | i_bad_b);
    reg [3:0] row;        // 0: no row fires, else 1 … 13 in table order,
                          // 14 and 15 the status check's rows
    reg [2:0] to;
    reg [3:0] cause;
    always @(*) begin
        row = 0; to = o_state; cause = o_cause;
        if (o_state != IDLE && both) begin row = 1; to = IDLE; cause = C_BOTH; end
        else case (o_state)
            IDLE: if (i_init && !both) begin row = 2; to = MANUAL; cause = C_INIT; end
            MANUAL:
                if (i_cmd_rx) begin row = 3; to = MANUAL; cause = C_CMD_RX; end
                else if (i_chk_ok) begin row = 4; to = AUTO; cause = C_CHECK_OK; end
                else if (i_auto) begin row = 5; to = AUTO; cause = C_AUTO_CMD; end
                else if (i_chk_sw) begin row = 14; to = MANUAL; cause = C_CHECK_SW; end
            AUTO:
                if ((active_fault | i_ns) & standby_faulty) begin row = 6; to = MANUAL; cause = C_STANDBY_FAULT; end
                else if (active_fault | i_ns) begin row = 7; to = MEDIUM; cause = active_fault ? C_ACTIVE_FAULT : C_NS; end
                else if (standby_faulty) begin row = 8; to = MANUAL; cause = C_STANDBY_FAULT; end
                else if (i_sc) begin row = 9; to = CONFIG; cause = C_SC; end
                else if (i_cmd_rx) begin row = 10; to = MANUAL; cause = C_CMD_RX; end
                else if (i_chk_sw) begin row = 15; to = MANUAL; cause = C_CHECK_SW; end
            MEDIUM: begin row = 11; to = MANUAL; cause = C_SWITCHED; end
            CONFIG:
                if (i_cmd_rx) begin row = 12; to = MANUAL; cause = C_CMD_RX; end
                else if (i_cmd_sent) begin row = 13; to = MANUAL; cause = C_CMD_SENT; end
            default: ;
        endcase
    end
    wire fault_switch = row == 7;
    wire new_cmd = row == 3 || row == 10 || row == 12 || row == 13 || row == 14 || row == 15;
    wire new_ch = row == 13 ? o_cmd_ch : (row == 14 || row == 15) ? ~i_act : i_cmd_ch;

    // Shadow: a commanded switch waiting for the end of a frame.
    reg pend = 1'b0, pend_ch = 1'b0;
    wire done = pend & ~i_in_frame & ~fault_switch;
    always @(posedge clock) begin
        if (row == 1) pend <= 1'b0;
        else if (new_cmd) begin pend <= 1'b1; pend_ch <= new_ch; end
        else if (done) pend <= 1'b0;
    end

    reg past_valid = 1'b0;
    reg [3:0] last_row = 0;
    reg [2:0] last_to = IDLE;
    reg [3:0] last_cause = 0;
    always @(posedge clock) begin
        past_valid <= 1'b1;
        last_row <= row; last_to <= to; last_cause <= cause;
    end

    always @(*) begin
        states: assert (o_state <= MEDIUM);
        if (past_valid) begin
            next_state: assert (o_state == last_to);
            report: assert (o_cause == last_cause && o_irq == (last_row != 0));
        end
        fault_now: assert (!fault_switch || o_sw);
        if (o_sw && !fault_switch) cmd_between_frames: assert (!i_in_frame && pend);
        if (done) cmd_first_chance: assert (o_sw == (pend_ch != i_act));
        inv_pend: assert (pend_q == pend && (!pend || pend_ch_q == pend_ch));

        cover_both: cover (row == 1);
        cover_init: cover (row == 2);
        cover_manual_cmd: cover (row == 3);
        cover_check_ok: cover (row == 4);
        cover_auto_cmd: cover (row == 5);
        cover_standby_and_active: cover (row == 6);
        cover_fault_switch: cover (row == 7 && !i_ns);
        cover_ns_switch: cover (row == 7 && !active_fault);
        cover_standby: cover (row == 8);
        cover_sc: cover (row == 9);
        cover_auto_cmd_rx: cover (row == 10);
        cover_switched: cover (row == 11);
        cover_config_cmd_rx: cover (row == 12);
        cover_cmd_sent: cover (row == 13);
        cover_manual_check_sw: cover (row == 14);
        cover_auto_check_sw: cover (row == 15);
        cover_cmd_waits: cover (pend && i_in_frame);
        cover_cmd_switch: cover (o_sw && !fault_switch);
    end
endmodule
