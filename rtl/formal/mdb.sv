// Formal properties of mdb, a master's database and host port (protocol
// §7, the port table of rtl/src/node/mdb.rs). Bounded model check from
// power-up (the memories' contents are state that k-induction cannot
// pin down without a model of every word); memories 256 deep.
//
// Environment: a Wishbone B4 classic master holds CYC, STB, WE, ADR and
// DAT from a request until its ACK; received words (`i_wvalid`) come at
// least 4 clocks apart (on the ring they are 25 bit times = 50 clocks
// apart); everything else is free.
//
// - wb_ack_only_for_request: no ACK without CYC·STB;
// - wb_one_ack: every transfer gets one ACK, one clock long;
// - wb_ack_in_time: ACK within 4 clocks of the request (the port table);
// - data_write_refused: a host write to a data slot whose configuration
//   is neither LOCAL nor ACT never writes the data memory (for one slot
//   X chosen by the solver, so for every slot);
// - data_write_is_the_request: a host write writes what was asked where
//   it was asked;
// - cfg_locked: the host never writes the configuration while the ring
//   runs; its writes (bit 0 of the send copy clear: LAST is not stored)
//   go to both copies; the receive copy's own writes (bit 0, the alarm SEQ
//   of protocol §11) come only while the ring runs;
// - has_value_with_data: the send copy's other writes set its bit 0, the
//   has-value bit (protocol §12), and only with a write of the data
//   memory (the host's, or a word of an own slot taken from the ring).
//   (That they keep bits 3:1 as the host wrote them needs the memory's
//   contents, which this bounded check from power-up does not model
//   faithfully: the ring runs check it, every word of every master.)
module mdb_props (
    input wire clock,
    input wire i_wb_cyc, input wire i_wb_stb, input wire i_wb_we,
    input wire [13:0] i_wb_adr, input wire [15:0] i_wb_dat,
    input wire [11:0] i_home, input wire [11:0] i_slots_m1, input wire i_fs, input wire [1:0] i_mode,
    input wire i_wvalid, input wire [1:0] i_kind, input wire [11:0] i_slot,
    input wire [15:0] i_data, input wire i_alive, input wire i_alarm,
    input wire i_ok, input wire i_hdr_bad, input wire [11:0] i_tx_slot,
    input wire i_fs_cleared
);
    // Configuration bits (protocol §7): LOCAL 8, ACT 2.
    localparam [3:0] OWNS = 4'b1010;

    wire [15:0] o_wb_dat;
    wire o_wb_ack, o_running;
    wire db_we, cfg_tx_we, cfg_rx_we, s2_write, s3_take;
    wire [11:0] db_waddr, cfg_rx_waddr;
    wire [15:0] db_wdata;
    wire [3:0] cfg_rx_wdata, cfg_tx_wdata;
    mdb dut (
        .clock(clock), .i_wb_cyc(i_wb_cyc), .i_wb_stb(i_wb_stb),
        .i_wb_we(i_wb_we), .i_wb_adr(i_wb_adr), .i_wb_dat(i_wb_dat),
        .o_wb_dat(o_wb_dat), .o_wb_ack(o_wb_ack), .i_home(i_home), .i_slots_m1(i_slots_m1),
        .i_fs(i_fs), .i_mode(i_mode), .i_wvalid(i_wvalid), .i_kind(i_kind),
        .i_slot(i_slot), .i_data(i_data), .i_alive(i_alive),
        .i_alarm(i_alarm), .i_ok(i_ok), .i_hdr_bad(i_hdr_bad),
        .i_tx_slot(i_tx_slot), .i_fs_cleared(i_fs_cleared),
        .o_running(o_running),
        .db__write_enable(db_we), .db__write_address(db_waddr),
        .db__write_data(db_wdata), .cfg_tx__write_enable(cfg_tx_we), .cfg_tx__write_data(cfg_tx_wdata),
        .cfg_rx__write_enable(cfg_rx_we), .cfg_rx__write_address(cfg_rx_waddr),
        .cfg_rx__write_data(cfg_rx_wdata), .s2_write(s2_write),
        .s3_take(s3_take)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;

    // ---- environment -------------------------------------------------------
    wire req = i_wb_cyc & i_wb_stb;
    reg [2:0] since_word = 3'd7;
    always @(posedge clock) since_word <= i_wvalid ? 3'd0 : (since_word == 3'd7 ? since_word : since_word + 3'd1);
    always @(*) if (i_wvalid) words_apart: assume (since_word >= 3'd3);
    always @(posedge clock) if (past_valid && $past(req && !o_wb_ack)) begin
        wb_master_holds: assume (req && i_wb_we == $past(i_wb_we) && i_wb_adr == $past(i_wb_adr)
                                 && i_wb_dat == $past(i_wb_dat));
    end

    // ---- shadow: one slot's configuration ------------------------------------
    (* anyconst *) reg [11:0] x;
    reg [3:0] cfg_x = 4'd0;
    always @(posedge clock) if (cfg_rx_we && cfg_rx_waddr == x) cfg_x <= cfg_rx_wdata;

    // Clocks a request has waited for its ACK.
    reg [3:0] waited = 4'd0;
    always @(posedge clock) waited <= (req && !o_wb_ack) ? waited + 4'd1 : 4'd0;

    // ---- properties ----------------------------------------------------------
    reg ring_due = 1'b0;  // a word was received in the clock before
    always @(posedge clock) ring_due <= i_wvalid;
    // (An own slot's word taken after JOIN is written in stage 3, s3_take.)
    wire host_write = db_we && !ring_due && !s3_take;
    always @(*) begin
        if (o_wb_ack) wb_ack_only_for_request: assert (req);
        wb_ack_in_time: assert (waited <= 4);
        if (s2_write) ring_writes_after_a_word: assert (ring_due);
        if (host_write) begin
            data_write_is_the_request: assert (req && i_wb_we && i_wb_adr[13:12] == 2'd0
                                               && db_waddr == i_wb_adr[11:0] && db_wdata == i_wb_dat);
            if (db_waddr == x) data_write_refused: assert ((cfg_x & OWNS) != 0);
        end
        if (cfg_tx_we && !cfg_tx_wdata[0]) begin
            cfg_locked: assert (!o_running);
            cfg_copies: assert (cfg_rx_we);
        end
        if (cfg_tx_we && cfg_tx_wdata[0]) has_value_with_data: assert (db_we);
        if (cfg_rx_we && !cfg_tx_we) cfg_seq_while_running: assert (o_running);

        cover_refused: cover (o_wb_ack && i_wb_we && i_wb_adr == {2'd0, x} && (cfg_x & OWNS) == 0);
        cover_written: cover (host_write && db_waddr == x);
        cover_cfg_refused: cover (o_wb_ack && i_wb_we && i_wb_adr[13:12] == 2'd1 && o_running);
        cover_slow_ack: cover (o_wb_ack && waited == 4);
        cover_seq: cover (cfg_rx_we && !cfg_tx_we && cfg_rx_waddr == x);
    end
    always @(posedge clock) if (past_valid) begin
        if (o_wb_ack) wb_one_ack: assert (!$past(o_wb_ack));
    end
endmodule
