// Formal properties of cdr's loss-of-signal detector (protocol §9).
//
// Loss of signal is "no line transition for 32 bit times". The CDR sees the
// line as 4 samples per core clock, 8 per bit time, 2 clocks per bit time
// (§16), so 32 bit times are 64 clocks. A clock "has an edge" when one of
// its samples differs from the sample before it (the first one from the
// last sample of the clock before). Proved by k-induction:
//
// - los_rises: after 64 clocks without an edge, o_los is high (registered:
//   it shows in the clock after the 64th);
// - los_not_early: o_los is high only after 64 clocks without an edge, so
//   never on a line that toggles at least every 4 bit times (8 clocks), as
//   every legal stream does (§2);
// - los_falls: the clock after an edge, o_los is low again;
// - code_is_decode: o_code beside a recovered bit is its NRZI decode, its
//   level against the bit before's (the first against a low line).
module cdr_props (
    input wire clock,
    input wire [3:0] i_samples
);
    localparam QUIET = 64;

    wire o_valid, o_bit, o_code, o_los;
    wire [1:0] o_phase;
    wire [5:0] quiet_q;
    wire calm_q, mute_q, last_q;
    cdr dut (
        .clock(clock), .i_samples(i_samples), .o_valid(o_valid),
        .o_bit(o_bit), .o_code(o_code), .o_los(o_los), .o_phase(o_phase),
        .quiet_q(quiet_q), .calm_q(calm_q), .mute_q(mute_q), .last_q(last_q)
    );

    // Shadow: the last sample of the clock before, and clocks since the
    // last clock with an edge (saturating). Power-up: the line was low,
    // and has been quiet for "0" clocks (the detector starts unraised).
    reg prev = 1'b0;
    reg [7:0] quiet = 8'd0;
    wire any_edge = (i_samples ^ {i_samples[2:0], prev}) != 4'b0;
    always @(posedge clock) begin
        prev <= i_samples[3];
        quiet <= any_edge ? 8'd0 : (quiet == 8'd255 ? quiet : quiet + 8'd1);
    end

    always @(*) begin
        los_rises: assert (quiet < QUIET || o_los);
        los_not_early: assert (!o_los || quiet >= QUIET);
        if (quiet <= 8) los_never_while_toggling: assert (!o_los);
        // Induction invariants: the detector's counter is the shadow's
        // (`calm`: the clock before had no edge; 0 stands for 64 or more).
        inv_last: assert (last_q == prev);
        inv_calm: assert (calm_q == (quiet != 0));
        if (quiet != 0) inv_quiet: assert (quiet_q == (quiet >= QUIET ? 0 : quiet));
        inv_mute: assert (mute_q == (quiet >= 16));

        cover_los: cover (o_los);
        cover_idle_line: cover (quiet == 7 && !o_los);
    end
    // Shadow: the level of the last recovered bit before this clock's.
    reg last_bit = 1'b0;
    always @(posedge clock) if (o_valid) last_bit <= o_bit;
    always @(*) begin
        if (o_valid) code_is_decode: assert (o_code == (o_bit ^ last_bit));
        // Induction invariant: between bits the level is the last bit's.
        if (!o_valid) inv_level: assert (o_bit == last_bit);
        cover_code_1: cover (o_valid && o_code);
        cover_code_0: cover (o_valid && !o_code);
    end

    reg was_los = 1'b0;
    always @(posedge clock) was_los <= o_los;
    always @(*) cover_recovered: cover (was_los && quiet == 0 && !o_los);
endmodule
