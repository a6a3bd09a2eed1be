//! # rmm_detect — fault detection from the MAC's events (docs/protocol.md §19)
//!
//! Purpose: the paper's Fault Detection Sub-module. Of the token-bus MAC's
//! event interrupts it uses six: new_successor, won_contention and
//! hear_successor make **SC** (the logical ring's configuration changed);
//! initialize, exit_ring and no_successor_8 make **NS**. The events seen are
//! kept (sticky) for the report to the network manager.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_ev` | in | 6 | event pulses: bit 0 new_successor, 1 won_contention, 2 hear_successor, 3 initialize, 4 exit_ring, 5 no_successor_8 |
//! | `o_sc` | out | 1 | SC this octet (combinational) |
//! | `o_ns` | out | 1 | NS this octet (combinational) |
//! | `o_ev_seen` | out | 6 | events seen since power-on (registered) |
//!
//! Latency: `o_sc`/`o_ns` in the octet of the event; `o_ev_seen` one octet later.
//!
//! ```text
//! i_ev       000000  000100  000000
//! o_sc       0       1       0
//! o_ev_seen  000000  000000  000100
//! ```

use rust_hdl::prelude::*;

/// Fault detection from MAC events.
#[derive(LogicBlock, Default)]
pub struct RmmDetect {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// MAC event pulses.
    pub i_ev: Signal<In, Bits<6>>,
    /// Successor changed.
    pub o_sc: Signal<Out, Bit>,
    /// No successor / ring entry or exit.
    pub o_ns: Signal<Out, Bit>,
    /// Events seen (sticky).
    pub o_ev_seen: Signal<Out, Bits<6>>,
    seen: DFF<Bits<6>>,
}

impl Logic for RmmDetect {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, seen);
        self.o_sc.next = self.i_ev.val().get_bits::<3>(0) != 0;
        self.o_ns.next = self.i_ev.val().get_bits::<3>(3) != 0;
        self.seen.d.next = self.seen.q.val() | self.i_ev.val();
        self.o_ev_seen.next = self.seen.q.val();
    }
}
