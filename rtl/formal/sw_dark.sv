// Formal properties of sw_dark, the dark time after a switchbox change
// (protocol §10). Every input is free in every clock. Proved by
// k-induction.
//
// - dark_so, dark_po: for 12 bit times (24 clocks, §16) after a change
//   both physical outputs hold the level they had in the clock of the
//   change (a DDR pair with both halves equal), PO not when it keeps its
//   source (`i_keep_po`, the special master's frame generator); a change
//   inside the dark time starts it again;
// - pass: outside the dark time the outputs are the switchbox's.
module sw_dark_props (
    input wire clock,
    input wire i_change,
    input wire i_keep_po,
    input wire [1:0] i_po,
    input wire [1:0] i_so
);
    localparam DARK = 24;

    wire [1:0] o_po, o_so;
    wire [4:0] dark_q;
    wire dark_po_q, lvl_po_q, lvl_so_q;
    sw_dark dut (
        .clock(clock), .i_change(i_change), .i_keep_po(i_keep_po),
        .i_po(i_po), .i_so(i_so), .o_po(o_po), .o_so(o_so),
        .dark_q(dark_q), .dark_po_q(dark_po_q), .lvl_po_q(lvl_po_q),
        .lvl_so_q(lvl_so_q)
    );

    // Shadow: clocks of dark time left, whether PO darkens, the levels
    // the outputs had at the change (the last half of their last pair).
    reg [4:0] left = 5'd0;
    reg po_dark = 1'b0;
    reg po_lvl = 1'b0, so_lvl = 1'b0;
    always @(posedge clock) begin
        po_lvl <= o_po[1];
        so_lvl <= o_so[1];
        if (i_change) begin
            left <= DARK;
            po_dark <= !i_keep_po;
        end else if (left != 0) left <= left - 5'd1;
    end

    always @(*) begin
        if (left != 0) begin
            dark_so: assert (o_so == {2{so_lvl}});
            if (po_dark) dark_po: assert (o_po == {2{po_lvl}});
            else keep_po: assert (o_po == i_po);
        end else begin
            pass: assert (o_po == i_po && o_so == i_so);
        end
        inv: assert (dark_q == left && (left == 0 || dark_po_q == po_dark)
                     && lvl_po_q == po_lvl && lvl_so_q == so_lvl);

        cover_dark_end: cover (left == 1 && po_dark);
        cover_kept: cover (left == 5 && !po_dark && i_po != o_so);
        cover_restart: cover (left == 3 && i_change);
    end
endmodule
