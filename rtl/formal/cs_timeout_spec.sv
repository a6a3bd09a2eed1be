// The CS timeout as protocol §12 item 4 reads, for the proofs of the nodes
// that keep one (`slave`, `special_master`): a count of the clocks since
// the last header word on INPUT other than a good TST's (a frame's or a
// SEC's H0, good or damaged: the ring is alive), counted once the node is
// armed and stopping at its highest value; `due` in the clock after the
// count equals the timeout in an armed node (failsafe must then be set).
// Written here from the spec, not taken from a node.
module cs_timeout_spec (
    input wire clock,
    input wire armed, input wire [19:0] timeout,
    input wire rx_wvalid, input wire [1:0] rx_kind, input wire rx_ok,
    input wire [1:0] rx_ptype,
    output reg [19:0] count, output reg due
);
    initial count = 20'd0;
    initial due = 1'b0;
    wire returned = rx_wvalid & (rx_kind == 2'd0) & ~(rx_ok & (rx_ptype == 2'd2));
    always @(posedge clock) begin
        if (returned) count <= 20'd0;
        else if (armed && count != 20'hfffff) count <= count + 20'd1;
        due <= armed && count == timeout;
    end
endmodule
