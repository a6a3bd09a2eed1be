// Formal properties of the special master's clock base and CS timeout
// (protocol §8, §12). The whole special master is under proof (its
// memories 256 deep, as for a ring of up to 256 slots); every input is
// free in every clock but the static configuration. Proved by k-induction.
//
// - one_frame_per_period: once the host has started the ring, the period
//   tick (`tick`, which starts the frame generator; its other start, a
//   retransmission packet T bit times later, §8, is not a tick) comes
//   exactly once every P bit times of the node's clock (P = i_period; a
//   bit time is 2 clocks, §16): never sooner, and never more than P bit
//   times without one while running;
// - cs_timeout: after its first returned frame, the special master
//   counts the clocks since the last returned packet other than a TST
//   (a header word back on INPUT, good or damaged, that is not a good
//   TST H0); when the count reaches the CS timeout it enters failsafe in
//   the next clock (§12 item 4), and the count, which is the only way the
//   timeout is decided, cannot reach it sooner (inv_quiet).
//
// The covers show a second period tick. The CS timeout's trigger (armed:
// a frame has come back) is not covered here: a bounded search to a
// returned frame (about 130 clocks of the whole special master) runs the
// solver out of memory (Boolector in WebAssembly: 4 GiB). Its trigger is
// shown in simulation instead: sim/tests/special_master.rs,
// `the_cs_timeout_fires_on_time` (failsafe CS + 3 clocks after the last
// returned header word).
module special_master_props (
    input wire clock,
    input wire [3:0] i_pi, input wire [3:0] i_si,
    input wire [11:0] i_address, input wire [11:0] i_slots_m1,
    input wire [19:0] i_period, input wire [19:0] i_cs_timeout,
    input wire i_wb_cyc, input wire i_wb_stb, input wire i_wb_we,
    input wire [13:0] i_wb_adr, input wire [15:0] i_wb_dat,
    input wire i_irq1, input wire i_irq2, input wire i_fs_req,
    input wire [19:0] i_rtx_at, input wire [19:0] i_rtx_atw,
    input wire [4:0] i_rtx_k, input wire [4:0] i_rtx_kw
);
    // Periods: from 2 bit times (wider than protocol §8, whose shortest
    // period holds a whole frame: the tick logic must not care) up to §8's
    // longest, 149,796 bit times.
    localparam [19:0] P_MAX = 20'd149796;

    wire tick, running, half_q, armed_q, failsafe_q, rx_wvalid, rx_ok;
    wire [1:0] rx_kind, rx_ptype;
    wire [19:0] bcnt_q, quiet_q;
    special_master dut (
        .clock(clock), .i_pi(i_pi), .i_si(i_si), .i_address(i_address),
        .i_slots_m1(i_slots_m1), .i_period(i_period),
        .i_cs_timeout(i_cs_timeout), .i_wb_cyc(i_wb_cyc),
        .i_wb_stb(i_wb_stb), .i_wb_we(i_wb_we), .i_wb_adr(i_wb_adr),
        .i_wb_dat(i_wb_dat), .i_irq1(i_irq1), .i_irq2(i_irq2),
        .i_fs_req(i_fs_req),
        // The clock base from power-up, in a ring without backups (a
        // backup's election and a restarted special master's JOIN into a
        // ring with backups are not under proof here).
        .i_prio(3'd0), .i_elect(20'd0), .i_flying(1'b0),
        .i_rtx_at(i_rtx_at), .i_rtx_atw(i_rtx_atw), .i_rtx_k(i_rtx_k), .i_rtx_kw(i_rtx_kw),
        .tick(tick), .mdb__o_running(running), .half_q(half_q),
        .bcnt_q(bcnt_q), .quiet_q(quiet_q), .armed_q(armed_q),
        .failsafe_q(failsafe_q), .rx_in__o_wvalid(rx_wvalid),
        .rx_in__o_kind(rx_kind), .rx_in__o_ok(rx_ok), .rx_in__o_ptype(rx_ptype)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    always @(posedge clock) if (past_valid) begin
        static_cfg: assume (i_period == $past(i_period) && i_cs_timeout == $past(i_cs_timeout)
                            && i_slots_m1 == $past(i_slots_m1) && i_address == $past(i_address)
                            && i_rtx_at == $past(i_rtx_at) && i_rtx_atw == $past(i_rtx_atw)
                            && i_rtx_k == $past(i_rtx_k) && i_rtx_kw == $past(i_rtx_kw));
    end
    always @(*) period_range: assume (i_period >= 20'd2 && i_period <= P_MAX);

    // ---- the period --------------------------------------------------------
    // Bit times counted while running since the last tick (1 at the tick's
    // own bit), and whether there was one.
    reg [19:0] bits = 20'd0;
    reg ticked = 1'b0;
    wire bit_time = running & half_q;
    always @(posedge clock) begin
        if (tick) begin
            bits <= 20'd1;
            ticked <= 1'b1;
        end else if (bit_time) bits <= bits + 20'd1;
    end
    always @(*) begin
        if (tick && ticked) one_frame_per_period: assert (bits == i_period);
        if (ticked) at_most_one_period: assert (bits <= i_period);
        if (tick) tick_on_a_bit: assert (bit_time);
        inv_bits: assert (!ticked || bits != 0);
        inv_bcnt: assert (ticked ? bcnt_q == (bits == i_period ? 20'd0 : bits) : bcnt_q == 20'd0);
        cover_second_tick: cover (tick && ticked && i_period == 20'd5);
    end

    // ---- the CS timeout ------------------------------------------------------
    wire [19:0] quiet;
    wire timeout_due;
    cs_timeout_spec spec (
        .clock(clock), .armed(armed_q), .timeout(i_cs_timeout),
        .rx_wvalid(rx_wvalid), .rx_kind(rx_kind), .rx_ok(rx_ok), .rx_ptype(rx_ptype),
        .count(quiet), .due(timeout_due)
    );
    always @(*) begin
        inv_quiet: assert (quiet_q == quiet);
        if (timeout_due) cs_timeout: assert (failsafe_q);
    end
endmodule
