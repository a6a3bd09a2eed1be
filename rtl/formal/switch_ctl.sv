// Formal properties of switch_ctl, with the switchbox it drives
// (protocol §9 channel failure, §10 decisions and Table 1, §12 failsafe and
// reintegration). Every input is free in every clock, but the CS timeout
// (static). Proved by k-induction; the covers show every decision happens.
//
// The times are the protocol's, in core clocks (2 per bit time, §16):
//   SETTLE      50 bit times after a change the stream controllers are
//               not acted on (§10)                          = 100 clocks
//   REINTEGRATE a WD node unwraps after 2 TST periods (130 bit times) of
//               its partner's ACKed TST (§12)               = 260 clocks
// The decision rule is the model's (model/src/ring.rs, `resolve`, per
// node), written out again below as `ref_*`.
//
// Failsafe itself is a register of the node (slave.rs), not of this block:
// here `o_fs_set` is the decision to enter it. Protocol §12 (issue 28)
// lets a node in failsafe reintegrate (that is how a ring that failed
// safe becomes whole again), so "failsafe is left only by reset" is not a
// property of this design; what is proved instead is that a WU node in
// failsafe unwraps only at a DATA header on BSR (`reint_wu`).
//
// Restart and rejoin (§12): an unarmed node in mode N wraps up on a TST on
// its lit INPUT (and on nothing else), a wrapped node reintegrates armed or
// not, and a node still rejoining (`joined` not yet set: from power-up
// until a frame boundary in mode N, armed, with no TST on INPUT or BSR)
// turns round at its WU unwrap (WU -> WD) when a TST arrives on INPUT.
module switch_ctl_props (
    input wire clock,
    input wire i_armed,
    input wire i_hard_in,
    input wire i_hard_bsr,
    input wire i_run_in,
    input wire i_run_bsr,
    input wire i_los_in,
    input wire i_los_bsr,
    input wire i_rw,
    input wire i_fs,
    input wire i_tst_ack,
    input wire i_frame_start,
    input wire i_bsr_data,
    input wire i_in_pkt,
    input wire i_tst_in,
    input wire i_tst_bsr,
    input wire [19:0] i_cs_timeout,
    input wire [3:0] i_pi,
    input wire [3:0] i_si,
    input wire [1:0] i_output,
    input wire [1:0] i_bss
);
    localparam [1:0] N = 2'd0, WU = 2'd1, WD = 2'd2;
    localparam SETTLE = 100;
    localparam REINTEGRATE = 260;

    wire [1:0] o_mode;
    wire o_change, o_relink, o_tst_start, o_fs_set, o_grace_over;
    // Internal registers, exposed for the induction invariants only.
    wire [6:0] settle_q;
    wire [8:0] ack_time_q;
    wire [19:0] grace_q;
    wire chg_q, run_q, seen_ack_q, pend_up_q, joined_q, busy_q, ack_done_q;
    switch_ctl dut (
        .clock(clock), .i_armed(i_armed), .i_hard_in(i_hard_in),
        .i_hard_bsr(i_hard_bsr), .i_run_in(i_run_in), .i_run_bsr(i_run_bsr),
        .i_los_in(i_los_in), .i_los_bsr(i_los_bsr), .i_rw(i_rw), .i_fs(i_fs),
        .i_tst_ack(i_tst_ack), .i_frame_start(i_frame_start),
        .i_bsr_data(i_bsr_data), .i_in_pkt(i_in_pkt),
        .i_tst_in(i_tst_in), .i_tst_bsr(i_tst_bsr),
        .i_cs_timeout(i_cs_timeout), .o_mode(o_mode), .o_change(o_change),
        .o_relink(o_relink), .o_tst_start(o_tst_start), .o_fs_set(o_fs_set),
        .o_grace_over(o_grace_over),
        .settle_q(settle_q), .ack_time_q(ack_time_q), .grace_q(grace_q),
        .chg_q(chg_q), .run_q(run_q),
        .seen_ack_q(seen_ack_q), .pend_up_q(pend_up_q), .joined_q(joined_q),
        .busy_q(busy_q), .ack_done_q(ack_done_q)
    );

    wire [3:0] o_input, o_bsr;
    wire [1:0] o_po, o_so;
    switchbox sbox (
        .i_mode(o_mode), .i_pi(i_pi), .i_si(i_si), .i_output(i_output),
        .i_bss(i_bss), .o_input(o_input), .o_bsr(o_bsr), .o_po(o_po),
        .o_so(o_so)
    );

    // ---- environment -------------------------------------------------
    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    always @(posedge clock)
        if (past_valid) cs_static: assume (i_cs_timeout == $past(i_cs_timeout));

    // ---- the reference decision (model: resolve, one node) -----------
    // Mode N: a structural failure (hard) or, in a ring not known wrapped,
    // a run of bad words fails a channel; INPUT first (§10).
    wire ref_fail_in = i_hard_in | (i_run_in & ~i_rw);
    wire ref_fail_bsr = i_hard_bsr | (i_run_bsr & ~i_rw);
    wire [1:0] ref_new_n = ref_fail_in ? WU : ref_fail_bsr ? WD : N;
    // Failsafe (§12 items 1, 2): a structural fault while the ring is
    // known wrapped, or both inputs dark; a wrapped node: INPUT dark.
    wire ref_fs_n = ((i_hard_in | i_hard_bsr) & i_rw) | (i_los_in & i_los_bsr);
    wire ref_fs_wrapped = i_los_in;

    // ---- shadow state of the specification ----------------------------
    // Clocks since the last mode change (saturating; "settled" at power-up).
    reg [8:0] since = 9'd511;
    // Clocks of ACKed TST heard while acting in this wrapped mode.
    reg [8:0] acks = 9'd0;
    // A DATA header on BSR after an ACK (or in failsafe) in this WU mode.
    reg wu_ok = 1'b0;
    // Grace after unwrapping: CS timeout / 2 clocks (§12).
    reg [19:0] grace = 20'd0;
    // Whole again after power-up (§12).
    reg joined = 1'b0;
    wire settled = since >= SETTLE;
    wire acting = i_armed & settled;
    // An unarmed node's one decision: a TST on its lit INPUT in mode N.
    wire wake = ~i_armed & settled & (o_mode == N) & i_tst_in & ~i_los_in;
    // A rejoining node's WU unwrap turns round when a TST is on INPUT.
    wire ref_turn = (o_mode == WU) & ~joined & i_tst_in;
    always @(posedge clock) begin
        since <= o_change ? 9'd0 : (since == 9'd511 ? since : since + 9'd1);
        grace <= (o_change & (next_mode == N)) ? (i_cs_timeout >> 1)
               : (grace == 0 ? grace : grace - 20'd1);
        if (i_armed & (o_mode == N) & i_frame_start & ~i_tst_in & ~i_tst_bsr) joined <= 1'b1;
        if (o_change) begin
            acks <= 0;
            wu_ok <= 1'b0;
        end else if (settled & (o_mode != N)) begin
            if (i_tst_ack & (acks != 9'd511)) acks <= acks + 9'd1;
            if ((o_mode == WU) & ((acks != 0 | i_fs) & i_bsr_data)) wu_ok <= 1'b1;
        end
    end
    // The mode after this clock edge.
    reg [1:0] next_mode;
    always @(*) next_mode = o_change ? (o_mode == N ? (i_armed ? ref_new_n : WU) : (ref_turn ? WD : N)) : o_mode;

    // ---- properties ----------------------------------------------------
    always @(*) begin
        // Table 1: the mode is always one of the three rows, and the
        // switchbox routes exactly that row.
        mode_valid: assert (o_mode != 2'd3);
        case (o_mode)
            WU: row_wu: assert (o_input == i_si && o_bsr == i_pi && o_po == i_output && o_so == i_bss);
            WD: row_wd: assert (o_input == i_pi && o_bsr == i_si && o_po == i_bss && o_so == i_output);
            default: row_n: assert (o_input == i_pi && o_bsr == i_si && o_po == i_output && o_so == i_bss);
        endcase
        // Nothing is decided while the receivers settle after a change
        // (§10); before the first good frame, no failsafe, and in mode N
        // only the wrap on a TST (§12).
        if (!settled) quiet_change: assert (!o_change);
        if (!acting) quiet_fs: assert (!o_fs_set);
        if (!i_armed && o_mode == N) begin
            unarmed_wake: assert (o_change == wake);
            if (wake) unarmed_wake_wu: assert (next_mode == WU);
        end
        // Mode N: the model's decision, and exactly it.
        if (acting && o_mode == N) begin
            n_change: assert (o_change == (ref_new_n != N));
            n_fs: assert (o_fs_set == ref_fs_n);
            // A single failure: INPUT → WU, BSR alone → WD (§10).
            if (ref_fail_in) n_single_in_wu: assert (next_mode == WU);
            if (!ref_fail_in && ref_fail_bsr) n_single_bsr_wd: assert (next_mode == WD);
            // A run of bad words never fails safe (§9, §12, issue 28).
            if (!i_hard_in && !i_hard_bsr && !(i_los_in && i_los_bsr)) n_run_no_fs: assert (!o_fs_set);
        end
        // Wrapped: the second fault is INPUT going dark; the only change
        // is back to N (reintegration).
        if (acting && o_mode != N) begin
            wrapped_fs: assert (o_fs_set == ref_fs_wrapped);
        end
        // Reintegration (§12): a WD node after REINTEGRATE clocks of ACKed
        // TST, at a frame start; a WU node at a DATA header on BSR after an
        // ACK (in failsafe: the header alone), never inside a packet on INPUT.
        if (o_change && o_mode == WD) reint_wd: assert (acks >= REINTEGRATE && i_frame_start);
        if (o_change && o_mode == WU) reint_wu: assert (!i_in_pkt && (wu_ok || ((acks != 0 | i_fs) & i_bsr_data)));
        // A WU node turns round (WD) only while rejoining with a TST on
        // INPUT; otherwise an unwrap goes to N.
        if (o_change && o_mode == WU) turn_rule: assert ((next_mode == WD) == ref_turn);
        if (o_change && o_mode == WD) wd_to_n: assert (next_mode == N);
        // TST starts exactly when a node wraps or turns round; the
        // receivers move exactly when the node goes into or out of WU
        // (INPUT and BSR swap).
        tst_start: assert (o_tst_start == (o_change && (o_mode == N || next_mode == WD)));
        relink: assert (o_relink == (o_change && (o_mode == WU || next_mode == WU)));
        // After unwrapping, a TST on a mode-N input is no failure for half
        // a CS timeout (§12).
        grace_rule: assert (o_grace_over == (grace == 0));

        // Induction invariants: the block's counters are the shadow's.
        // The counters start in the clock after a change (since 0, `chg`),
        // so then they may still hold the old mode's values; nothing reads
        // them in that clock. busy is settle != 0 (the count down tests
        // it). The reintegration state is cleared while busy (from since
        // 1), so it is the shadow's from since 2; ack_time stops at
        // REINTEGRATE, where ack_done is set.
        inv_chg: assert (chg_q == (since == 0));
        if (since != 0) begin
            inv_settle: assert (since >= SETTLE ? settle_q == 0 : settle_q == SETTLE - since);
            inv_busy: assert (busy_q == (settle_q != 0));
        end
        if (since >= 2) begin
            inv_acks: assert (ack_time_q == (acks >= REINTEGRATE ? REINTEGRATE : acks)
                              && seen_ack_q == (acks != 0));
            inv_ack_done: assert (ack_done_q == (acks >= REINTEGRATE));
            inv_pend: assert (pend_up_q == (wu_ok && o_mode == WU));
        end
        // The grace counter runs a clock behind: loaded in the clock after
        // an unwrap (`chg` in mode N), then the shadow's value while `run`
        // is set.
        inv_run: assert (run_q == (grace != 0));
        if (chg_q && o_mode == N) inv_load: assert (grace == (i_cs_timeout >> 1));
        if (!chg_q && run_q) inv_grace: assert (grace_q == grace);
        inv_joined: assert (joined_q == joined);
        if (o_mode == N) inv_n: assert (acks == 0 && !wu_ok);

        // Every decision happens (the properties above are not vacuous).
        cover_n_wu: cover (acting && o_mode == N && next_mode == WU);
        cover_n_wd: cover (acting && o_mode == N && next_mode == WD);
        cover_fs_rw: cover (acting && o_mode == N && o_fs_set && i_rw && !(i_los_in && i_los_bsr));
        cover_fs_both_dark: cover (acting && o_mode == N && o_fs_set && i_los_in && i_los_bsr && !i_rw);
        cover_fs_wrapped: cover (acting && o_mode != N && o_fs_set);
        cover_run_wraps: cover (acting && o_mode == N && o_change && !i_hard_in && !i_hard_bsr);
        cover_wu_n: cover (o_change && o_mode == WU && !i_fs);
        cover_wu_n_fs: cover (o_change && o_mode == WU && i_fs && !i_tst_ack && acks == 0);
        cover_wd_n: cover (o_change && o_mode == WD);
        cover_wake: cover (wake && o_change);
        cover_turn: cover (o_change && o_mode == WU && next_mode == WD);
    end
endmodule
