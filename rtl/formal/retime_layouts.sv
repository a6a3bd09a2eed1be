// Formal equivalence of retime's two buffer layouts (issue 21): the
// elastic output buffer that a send shifts (`Layout::SendShifts`, the
// FPGAs' and the simulated ring's) and the one that a write shifts
// (`Layout::WriteShifts`, the CoolRunner-II's) give the same line and
// the same slips in every clock, for ever, whatever arrives (every input
// free in every clock). k-induction over these invariants:
//
// - every register but the buffer is the same in both;
// - the buffer: SendShifts keeps its unsent bits oldest first from bit 0,
//   WriteShifts the last 8 bits written, newest in bit 7; bit j of the
//   first is bit (j − cnt) mod 8 of the second, for every j below the
//   count and below 8 (in the dark, where writes still count and the
//   count may pass 8, the first keeps the bit last written at j);
// - a running buffer holds at most 8 bits, and a dark one does not run
//   (what a send reads is then one of those bits).
module retime_layouts_props (
    input wire clock,
    input wire i_valid,
    input wire i_code,
    input wire [1:0] i_phase
);
    wire [1:0] a_line, b_line;
    wire a_slip, b_slip;
    wire [7:0] a_sr, b_sr;
    wire [3:0] a_cnt, b_cnt, a_gap, b_gap;
    wire [2:0] a_rem, b_rem, a_hi, b_hi, a_lo, b_lo;
    wire [4:0] a_since, b_since;
    wire [1:0] a_pair, b_pair;
    wire a_lvl, b_lvl, a_run, b_run, a_dark, b_dark, a_slip_q, b_slip_q;

    retime_send_shifts a (
        .clock(clock), .i_valid(i_valid), .i_code(i_code), .i_phase(i_phase),
        .o_line(a_line), .o_slip(a_slip),
        .sr_q(a_sr), .cnt_q(a_cnt), .rem_q(a_rem), .lvl_q(a_lvl), .run_q(a_run),
        .dark_q(a_dark), .since_q(a_since), .hi_q(a_hi), .lo_q(a_lo), .gap_q(a_gap),
        .pair_q(a_pair), .slip_q(a_slip_q)
    );
    retime_write_shifts b (
        .clock(clock), .i_valid(i_valid), .i_code(i_code), .i_phase(i_phase),
        .o_line(b_line), .o_slip(b_slip),
        .sr_q(b_sr), .cnt_q(b_cnt), .rem_q(b_rem), .lvl_q(b_lvl), .run_q(b_run),
        .dark_q(b_dark), .since_q(b_since), .hi_q(b_hi), .lo_q(b_lo), .gap_q(b_gap),
        .pair_q(b_pair), .slip_q(b_slip_q)
    );

    // Bit j of the buffers disagree (j below the count).
    reg [7:0] bad;
    integer j;
    always @(*)
        for (j = 0; j < 8; j = j + 1)
            bad[j] = j < a_cnt && a_sr[j] != b_sr[(j - a_cnt) & 7];

    always @(*) begin
        same_line: assert (a_line == b_line);
        same_slip: assert (a_slip == b_slip);
        same_buffer: assert (bad == 8'd0);
        same_state: assert (a_cnt == b_cnt && a_rem == b_rem && a_lvl == b_lvl
            && a_run == b_run && a_dark == b_dark && a_since == b_since
            && a_hi == b_hi && a_lo == b_lo && a_gap == b_gap && a_pair == b_pair
            && a_slip_q == b_slip_q);
        running_holds_8: assert (!a_run || a_cnt <= 4'd8);
        dark_not_running: assert (!(a_dark && a_run));

        cover_full: cover (a_run && a_cnt == 4'd8);
        cover_dark_count: cover (a_dark && a_cnt > 4'd8);
    end
endmodule
