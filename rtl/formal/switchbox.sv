// Formal properties of switchbox: the paper's Table 1 (protocol §10).
//
//   mode | INPUT | OUTPUT | BSR | BSS
//   N    | PI    | PO     | SI  | SO
//   WU   | SI    | PO     | PI  | SO
//   WD   | PI    | SO     | SI  | PO
//
// The table is written here from the protocol, row by row; the block's
// own constants are not used. Code 3 is not a mode: it routes as N (the
// block's documented choice); switch_ctl never produces it (switch_ctl.sv).
// Combinational: proved for every input by induction of depth 1.
module switchbox_props (
    input wire [1:0] i_mode,
    input wire [3:0] i_pi,
    input wire [3:0] i_si,
    input wire [1:0] i_output,
    input wire [1:0] i_bss
);
    wire [3:0] o_input, o_bsr;
    wire [1:0] o_po, o_so;
    switchbox dut (
        .i_mode(i_mode), .i_pi(i_pi), .i_si(i_si), .i_output(i_output),
        .i_bss(i_bss), .o_input(o_input), .o_bsr(o_bsr), .o_po(o_po),
        .o_so(o_so)
    );

    always @(*) begin
        case (i_mode)
            2'd1: begin // WU: SO or PI defective
                row_wu_input: assert (o_input == i_si);
                row_wu_bsr: assert (o_bsr == i_pi);
                row_wu_po: assert (o_po == i_output);
                row_wu_so: assert (o_so == i_bss);
            end
            2'd2: begin // WD: SI or PO defective
                row_wd_input: assert (o_input == i_pi);
                row_wd_bsr: assert (o_bsr == i_si);
                row_wd_po: assert (o_po == i_bss);
                row_wd_so: assert (o_so == i_output);
            end
            default: begin // N (and the unused code 3)
                row_n_input: assert (o_input == i_pi);
                row_n_bsr: assert (o_bsr == i_si);
                row_n_po: assert (o_po == i_output);
                row_n_so: assert (o_so == i_bss);
            end
        endcase
        // Every row is exercised (no property is vacuous).
        cover_n: cover (i_mode == 2'd0);
        cover_wu: cover (i_mode == 2'd1);
        cover_wd: cover (i_mode == 2'd2);
    end
endmodule
