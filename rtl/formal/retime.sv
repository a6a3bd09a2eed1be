// Formal properties of retime, the elastic output buffer (protocol §9).
// Bounded model check from power-up, 300 clocks (150 bit times; ABC's
// bmc3 checks them in about 10 s, where smtbmc with Boolector ran out of
// memory at 200).
//
// Environment: the bits come from a sender whose clock differs from the
// node's by a constant rate the solver picks (anyconst), sampled where
// the CDR samples them: a bit k is centred at phi + k·(8 + d) receive
// samples (8 samples per bit time at equal clocks, 4 per core clock,
// §16), and arrives in the clock of that sample with `i_phase` = the
// sample within the clock. Positions are kept in 1/4096 sample.
//   RATE_PPM: |d| ≤ 8 samples × RATE_PPM. The proof uses 20,000 ppm, ten
//   times the ±2000 ppm a node's clock may be off (protocol §9): a rate
//   that far off needs a correction every 12 bit times or so, so the
//   corrections happen inside the bound (at 2000 ppm the first one would
//   come only after about 250 bit times); every rate within ±2000 ppm is
//   one of the rates checked.
// The code bits are free.
//
// - no_slip: once running, the buffer never under- or overflows;
// - correction_half_clock: a bit lasts 4 half clocks, or 3 or 5 (a
//   correction of one half clock);
// - correction_gap: two corrections are at least 8 bits apart.
module retime_props (
    input wire clock,
    input wire i_code
);
    localparam RATE_PPM = 20000;
    localparam integer UNIT = 4096;           // 1 sample
    localparam integer CLOCK = 4 * UNIT;      // one core clock
    localparam integer NOMINAL = 8 * UNIT;    // one bit time
    localparam integer DMAX = NOMINAL * (RATE_PPM / 100) / 10000;  // no 32-bit overflow

    (* anyconst *) reg signed [15:0] d;       // the sender's bit period − 8 samples
    (* anyconst *) reg [16:0] phi;            // where the first bit is centred
    always @(*) begin
        rate: assume (d >= -DMAX && d <= DMAX);
        first: assume (phi < NOMINAL);
    end

    // Position of the next bit's centre from the start of this clock.
    reg [19:0] next = 20'd0;
    reg started = 1'b0;
    wire [19:0] pos = started ? next : {3'd0, phi};
    wire i_valid = pos < CLOCK;
    wire [1:0] i_phase = pos / UNIT;
    always @(posedge clock) begin
        started <= 1'b1;
        next <= i_valid ? pos + NOMINAL + {{4{d[15]}}, d} - CLOCK : pos - CLOCK;
    end

    wire [1:0] o_line;
    wire o_slip, send0, send1, run_q;
    wire [2:0] len;
    retime dut (
        .clock(clock), .i_valid(i_valid), .i_code(i_code), .i_phase(i_phase),
        .o_line(o_line), .o_slip(o_slip),
        .send0(send0), .send1(send1), .len(len), .run_q(run_q)
    );

    // Bits started since the last correction (saturating; power-up: many).
    reg [4:0] since_corr = 5'd31;
    wire bit_start = send0 | send1;
    wire corr = bit_start && len != 3'd4;
    always @(posedge clock)
        if (bit_start) since_corr <= corr ? 5'd0 : (since_corr == 5'd31 ? since_corr : since_corr + 5'd1);

    always @(*) begin
        no_slip: assert (!o_slip);
        if (bit_start) correction_half_clock: assert (len >= 3'd3 && len <= 3'd5);
        if (corr) correction_gap: assert (since_corr >= 5'd7);

        cover_shorter: cover (corr && len == 3'd3);
        cover_longer: cover (corr && len == 3'd5);
        cover_running: cover (run_q && d == DMAX);
        cover_second_correction: cover (corr && since_corr != 5'd31);
    end
endmodule
