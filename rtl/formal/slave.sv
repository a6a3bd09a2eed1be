// Formal properties of the slave's CS timeout (protocol §12 item 4). The
// whole slave is under proof; every input is free in every clock but the
// static configuration. Proved by k-induction.
//
// - cs_timeout: once armed (it has taken a good H1), the slave counts the
//   clocks since the last header word on INPUT other than a good TST's
//   (`returned`: a frame's or a SEC's H0, good or damaged, shows the ring
//   is alive); when the count reaches the CS timeout it enters failsafe
//   in the next clock.
// - inv_quiet, inv_quiet_max: the slave's counter is the spec's count.
//   The slave restarts it through a flip-flop of its own (`quiet_clr`,
//   issue 21: one literal in each counter bit's product terms instead of
//   the header test's); while that is set, the count stands for 0 whatever
//   `quiet` holds, and `quiet` already holds the count of the clock after.
//   So the count is exact.
// - cs_due_exact: the slave decides the timeout (`cs_due`, which alone
//   sets failsafe for it) in exactly the clocks in which the spec's count
//   equals the timeout in an armed node: not sooner, not later.
//
// The cover shows only that the environment is not vacuous (failsafe
// reached); the timeout itself is too deep for a cover (a good H1, two
// whole words): slave_modes.rs shows it in simulation.
//
// The reference count is the spec's (rtl/formal/cs_timeout_spec.sv, a
// counter that a header restarts and that stops at its highest value),
// not taken from the slave.
module slave_props (
    input wire clock,
    input wire [3:0] i_pi, input wire [3:0] i_si, input wire i_cap_sel,
    input wire [11:0] i_address, input wire [11:0] i_slots_m1,
    input wire i_actuator, input wire [19:0] i_cs_timeout,
    input wire [15:0] i_sensor_data,
    input wire i_irq1, input wire i_irq2, input wire i_fs_req,
    input wire i_master, input wire [1:0] i_slot_cfg,
    input wire [15:0] i_slot_data, input wire i_slot_alive, input wire i_fs_set
);
    wire armed_q, failsafe_q, cs_due, quiet_clr_q, quiet_max_q, rx_wvalid, rx_ok;
    wire [1:0] rx_kind, rx_ptype;
    wire [19:0] quiet_q;
    slave dut (
        .clock(clock), .i_pi(i_pi), .i_si(i_si), .i_cap_sel(i_cap_sel),
        .i_address(i_address), .i_slots_m1(i_slots_m1),
        .i_actuator(i_actuator), .i_cs_timeout(i_cs_timeout),
        .i_sensor_data(i_sensor_data), .i_irq1(i_irq1), .i_irq2(i_irq2),
        .i_fs_req(i_fs_req), .i_master(i_master), .i_slot_cfg(i_slot_cfg),
        .i_slot_data(i_slot_data), .i_slot_alive(i_slot_alive),
        .i_fs_set(i_fs_set),
        .armed_q(armed_q), .failsafe_q(failsafe_q), .quiet_q(quiet_q),
        .quiet_clr_q(quiet_clr_q), .quiet_max_q(quiet_max_q), .cs_due(cs_due),
        .rx_in__o_wvalid(rx_wvalid), .rx_in__o_kind(rx_kind),
        .rx_in__o_ok(rx_ok), .rx_in__o_ptype(rx_ptype)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    always @(posedge clock) if (past_valid) begin
        static_cfg: assume (i_cs_timeout == $past(i_cs_timeout)
                            && i_slots_m1 == $past(i_slots_m1) && i_address == $past(i_address)
                            && i_actuator == $past(i_actuator) && i_master == $past(i_master));
    end

    wire [19:0] quiet;
    wire timeout_due;
    cs_timeout_spec spec (
        .clock(clock), .armed(armed_q), .timeout(i_cs_timeout),
        .rx_wvalid(rx_wvalid), .rx_kind(rx_kind), .rx_ok(rx_ok), .rx_ptype(rx_ptype),
        .count(quiet), .due(timeout_due)
    );
    always @(*) begin
        inv_quiet: assert ((quiet_clr_q ? 20'd0 : quiet_q) == quiet);
        inv_quiet_max: assert ((!quiet_clr_q && quiet_max_q) == (quiet == 20'hfffff));
        cs_due_exact: assert (cs_due == (armed_q && quiet == i_cs_timeout));
        if (timeout_due) cs_timeout: assert (failsafe_q);
        // The environment is not vacuous: the slave's own failsafe
        // register moves (here through the host's request, `i_fs_set`).
        cover_failsafe: cover (failsafe_q);
    end
endmodule
