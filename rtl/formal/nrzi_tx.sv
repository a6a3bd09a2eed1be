// Formal properties of nrzi_tx, the serializer (protocol §2). Every input
// is free in every clock. Proved by k-induction.
//
// - groups: a code group is taken every 5 bit times (the first at the
//   first bit time), and its 5 bits go out most significant first;
// - nrzi: in the clock after a bit time the line has toggled exactly when
//   that bit is 1 (NRZI: decoding the line gives the code bits back);
// - nothing moves between bit times.
module nrzi_tx_props (
    input wire clock,
    input wire i_bit_en,
    input wire [4:0] i_code
);
    wire o_take, o_line;
    wire [2:0] count_q;
    wire [4:0] shift_q;
    nrzi_tx dut (
        .clock(clock), .i_bit_en(i_bit_en), .i_code(i_code),
        .o_take(o_take), .o_line(o_line), .count_q(count_q), .shift_q(shift_q)
    );

    // Shadow: the group being sent and the index of its next bit
    // (5: the next bit time takes a new group).
    reg [4:0] group = 5'd0;
    reg [2:0] next = 3'd5;
    wire [4:0] g = (next == 5) ? i_code : group;
    wire [2:0] idx = (next == 5) ? 3'd4 : next;
    wire bit_now = g[idx];
    reg past_en = 1'b0, past_bit = 1'b0, past_line = 1'b0;
    always @(posedge clock) begin
        past_en <= i_bit_en;
        past_bit <= bit_now;
        past_line <= o_line;
        if (i_bit_en) begin
            group <= g;
            next <= (idx == 0) ? 3'd5 : idx - 3'd1;
        end
    end

    always @(*) begin
        groups: assert (o_take == (i_bit_en && next == 5));
        if (past_en) nrzi: assert (o_line == (past_line ^ past_bit));
        else hold: assert (o_line == past_line);
        // Induction invariants: the counter and the shift register hold
        // the shadow's position and the group's unsent bits.
        inv_next: assert (next <= 3 || next == 5);
        inv_count: assert (count_q == (next == 5 ? 3'd0 : 3'd4 - next));
        if (next != 5) inv_shift: assert ((shift_q >> (3'd4 - next)) == (group & ((5'd1 << (next + 1)) - 5'd1)));

        cover_toggle: cover (past_en && past_bit && o_take);
        cover_hold: cover (past_en && !past_bit && next == 2);
    end
endmodule
