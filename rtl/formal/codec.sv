// Formal properties of the line code, enc4b5b and dec5b4b (protocol §2,
// §3). Combinational: proved for every input by induction of depth 1.
//
// - the code table is protocol §2's, written out here;
// - decode(encode(x)) = x for every nibble and every control symbol;
// - J K (11000 10001) appears at no bit offset of any sequence of data,
//   idle and S groups (§3's proof obligation; the model's
//   `jk_cannot_be_imitated_by_data` checks it by enumeration);
// - no sequence of valid groups (J only as the start of J K) has four 0
//   code bits in a row, so the NRZI
//   line toggles at least every 4 bit times (§2, the loss-of-signal bound
//   of §9 rests on it).
//
// Symbol numbers at the encoder (enc4b5b's port): 0–15 nibbles, 16 J,
// 17 K, 18 I, 19 S.
module codec_props (
    input wire [4:0] i_a,
    input wire [4:0] i_b,
    input wire [4:0] i_c
);
    localparam [4:0] J = 5'd16, K = 5'd17, I = 5'd18, S = 5'd19;

    // Protocol §2, row by row.
    function [4:0] code_of(input [4:0] sym);
        case (sym)
            5'h0: code_of = 5'b11110; 5'h1: code_of = 5'b01001;
            5'h2: code_of = 5'b10100; 5'h3: code_of = 5'b10101;
            5'h4: code_of = 5'b01010; 5'h5: code_of = 5'b01011;
            5'h6: code_of = 5'b01110; 5'h7: code_of = 5'b01111;
            5'h8: code_of = 5'b10010; 5'h9: code_of = 5'b10011;
            5'hA: code_of = 5'b10110; 5'hB: code_of = 5'b10111;
            5'hC: code_of = 5'b11010; 5'hD: code_of = 5'b11011;
            5'hE: code_of = 5'b11100; 5'hF: code_of = 5'b11101;
            J: code_of = 5'b11000; K: code_of = 5'b10001;
            I: code_of = 5'b11111; S: code_of = 5'b11001;
            default: code_of = 5'bxxxxx;
        endcase
    endfunction

    wire [4:0] ca, cb, cc;
    enc4b5b enc_a (.i_sym(i_a), .o_code(ca));
    enc4b5b enc_b (.i_sym(i_b), .o_code(cb));
    enc4b5b enc_c (.i_sym(i_c), .o_code(cc));

    wire [3:0] nib;
    wire is_data, is_j, is_k, is_i, is_s;
    dec5b4b dec (
        .i_code(ca), .o_nibble(nib), .o_data(is_data), .o_j(is_j),
        .o_k(is_k), .o_i(is_i), .o_s(is_s)
    );

    wire a_valid = i_a <= S;
    // A group of the data stream: a nibble, idle or S (not J, not K).
    wire a_stream = i_a < J || i_a == I || i_a == S;
    wire b_stream = i_b < J || i_b == I || i_b == S;
    wire c_stream = i_c < J || i_c == I || i_c == S;
    wire [14:0] bits = {ca, cb, cc}; // bit 14 is sent first

    integer o;
    reg jk_seen, four_zeros;
    always @(*) begin
        jk_seen = 1'b0;
        four_zeros = 1'b0;
        for (o = 0; o <= 5; o = o + 1)
            if (bits[14 - o -: 10] == 10'b11000_10001) jk_seen = 1'b1;
        for (o = 0; o <= 11; o = o + 1)
            if (bits[14 - o -: 4] == 4'b0000) four_zeros = 1'b1;
    end

    always @(*) begin
        if (a_valid) begin
            table_row: assert (ca == code_of(i_a));
            roundtrip_data: assert (is_data == (i_a < J) && (i_a >= J || nib == i_a[3:0]));
            roundtrip_ctl: assert (is_j == (i_a == J) && is_k == (i_a == K) && is_i == (i_a == I) && is_s == (i_a == S));
        end
        if (a_stream && b_stream && c_stream) no_jk_in_data: assert (!jk_seen);
        if (a_valid && i_b <= S && i_c <= S && (i_a != J || i_b == K) && (i_b != J || i_c == K))
            toggles_every_4: assert (!four_zeros);
        // Any other symbol number sends I, so the line never carries an
        // undefined group (enc4b5b's documented choice).
        if (!a_valid) other_is_idle: assert (ca == 5'b11111);

        cover_data: cover (a_valid && is_data && nib == 4'hA);
        cover_jk: cover (i_a == J && i_b == K && jk_seen);
        cover_stream: cover (a_stream && b_stream && c_stream && i_a != i_b);
        cover_run_of_three: cover (i_a == J && i_b == K && bits[12 -: 3] == 3'b000);
    end
endmodule
