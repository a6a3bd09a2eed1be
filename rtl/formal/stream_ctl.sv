// Formal properties of stream_ctl (protocol §9). The word inputs are
// free in every clock (any sequence of words the receive chain could
// give, and more); `i_tst_fail` is static. Proved by k-induction.
//
// - run_8: a run of 8 bad words damaged on this fibre (bad: not good, not
//   VOID, not marked) with no good word and no flush among or after them
//   raises o_run; run_7: fewer never do. o_run shows two clocks after the
//   8th bad word (the count, then the flag, are registered);
// - a good word of any kind ends the run; VOID and marked words leave it;
//   a flush (the input moved to another line) restarts it;
// - hard: o_hard is loss of signal, or a test signal where it counts as a
//   failure, one clock later; o_cf is o_hard or o_run;
// - tst_hold: a good TST (H1 good with packet type TST and H1 = NOT H0,
//   which the word decoder reports as `i_compl`; an H1 always follows a
//   good H0 of its packet) raises o_tst in the next clock and holds it
//   for 2 TST periods, 130 bit times = 260 clocks (§9), after the last
//   one; o_ack is the ACK bit (H0 bit 12 = NOT H1 bit 12) of the last one.
module stream_ctl_props (
    input wire clock,
    input wire i_los,
    input wire i_wvalid,
    input wire [1:0] i_kind,
    input wire i_ok,
    input wire i_void,
    input wire i_marked,
    input wire i_d12,
    input wire i_compl,
    input wire [1:0] i_ptype,
    input wire i_tst_fail,
    input wire i_flush
);
    localparam RUN = 8;
    localparam HOLD = 260;
    localparam [1:0] H0 = 2'd0, H1 = 2'd1, PT_TST = 2'd2;

    wire o_cf, o_hard, o_run, o_tst, o_ack;
    wire [3:0] bad_q;
    wire [8:0] hold_q;
    wire hold_ld_q;
    stream_ctl dut (
        .clock(clock), .i_los(i_los), .i_wvalid(i_wvalid), .i_kind(i_kind),
        .i_ok(i_ok), .i_void(i_void), .i_marked(i_marked), .i_d12(i_d12), .i_compl(i_compl),
        .i_ptype(i_ptype), .i_tst_fail(i_tst_fail), .i_flush(i_flush),
        .o_cf(o_cf), .o_hard(o_hard), .o_run(o_run), .o_tst(o_tst),
        .o_ack(o_ack), .bad_q(bad_q), .hold_q(hold_q),
        .hold_ld_q(hold_ld_q)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    always @(posedge clock) if (past_valid) tst_fail_static: assume (i_tst_fail == $past(i_tst_fail));

    // ---- shadow of the specification ----------------------------------
    wire good = i_wvalid & i_ok;
    wire bad = i_wvalid & ~i_ok & ~i_void & ~i_marked;
    // Bad words of the current run so far (saturating at RUN).
    reg [3:0] run = 4'd0;
    // The TST decision.
    wire tst_now = good & (i_kind == H1) & (i_ptype == PT_TST) & i_compl;
    // Clocks since the last good TST (0: none yet).
    reg [9:0] age = 10'd0;
    reg ack = 1'b0;
    always @(posedge clock) begin
        if (i_flush | good) run <= 4'd0;
        else if (bad & (run != RUN)) run <= run + 4'd1;
        if (tst_now) begin
            age <= 10'd1;
            ack <= ~i_d12;
        end else if (age != 0 && age != 10'd1023) age <= age + 10'd1;
    end

    // ---- properties ----------------------------------------------------
    always @(posedge clock) if (past_valid) begin
        run_8: assert (o_run == ($past(run) == RUN && !$past(i_flush)));
        if ($past(run) < RUN) run_7: assert (!o_run);
        hard: assert (o_hard == ($past(i_los) || ($past(o_tst) && $past(i_tst_fail))));
    end
    always @(*) begin
        cf: assert (o_cf == (o_hard | o_run));
        tst_hold: assert (o_tst == (age != 0 && age <= HOLD));
        tst_ack: assert (o_ack == ack);
        // Induction invariants.
        inv_bad: assert (bad_q == run);
        // (The counter is read only while the TST is held.)
        // (The counter is loaded through hold_ld_q: in the clock after a
        // TST it stands for HOLD - 1.)
        if (age != 0 && age <= HOLD) inv_hold: assert ((hold_ld_q ? HOLD - 1 : hold_q) == HOLD - age);
        inv_hold_ld: assert (!hold_ld_q || age == 1);

        cover_run: cover (o_run);
        cover_tst_ends: cover (age == HOLD + 1 && !o_tst);
        cover_tst_ack: cover (o_tst && o_ack);
    end
    always @(posedge clock) if (past_valid) begin
        cover_run_across_void: cover (run == RUN && $past(i_wvalid & i_void) && $past(run) != 0);
        cover_tst_fails: cover (o_hard && !$past(i_los));
    end
endmodule
