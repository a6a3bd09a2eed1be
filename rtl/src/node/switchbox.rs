//! # switchbox — the paper's Table 1 (protocol §10)
//!
//! Purpose: connects the physical ports PI, SI, PO, SO to the logical
//! streams INPUT, BSR (receive) and OUTPUT, BSS (send) by the node's mode.
//! Inputs are carried as 4-sample words (quadrature DDR capture, one word
//! per core clock), outputs as DDR pairs (two halves per core clock).
//!
//! | mode | code | INPUT | OUTPUT | BSR | BSS |
//! |---|---|---|---|---|---|
//! | N (all 4 ports ok) | 0 | PI | PO | SI | SO |
//! | WU (SO or PI defective) | 1 | SI | PO | PI | SO |
//! | WD (SI or PO defective) | 2 | PI | SO | SI | PO |
//! | (unused) | 3 | as N | | | |
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `i_mode` | in | 2 | clock (static between changes) | mode code |
//! | `i_pi`, `i_si` | in | 4 | clock | physical inputs (samples) |
//! | `i_output`, `i_bss` | in | 2 | clock | logical outputs of the node |
//! | `o_input`, `o_bsr` | out | 4 | clock | logical inputs of the node |
//! | `o_po`, `o_so` | out | 2 | clock | physical outputs |
//!
//! Latency: combinational (0 clocks); the node registers its I/O. A slave
//! or a master can leave the input half to the capture register in front
//! of it ([`crate::node::slave`]'s `i_cap_sel`, as every synthesis top
//! does), which then makes the same choice a clock ahead.
//!
//! ```text
//! i_mode   == N ==X== WU ==========
//! o_input  == PI =X== SI ==========
//! o_bsr    == SI =X== PI ==========
//! o_po     == OUTPUT ==============
//! o_so     == BSS =================
//! ```

use rust_hdl::prelude::*;

/// Mode code of row 1 (N).
pub const MODE_N: u64 = 0;
/// Mode code of row 2 (WU).
pub const MODE_WU: u64 = 1;
/// Mode code of row 3 (WD).
pub const MODE_WD: u64 = 2;

/// Table 1 multiplexer.
#[derive(LogicBlock, Default)]
pub struct Switchbox {
    /// Mode.
    pub i_mode: Signal<In, Bits<2>>,
    /// Physical primary input.
    pub i_pi: Signal<In, Bits<4>>,
    /// Physical secondary input.
    pub i_si: Signal<In, Bits<4>>,
    /// Logical OUTPUT stream.
    pub i_output: Signal<In, Bits<2>>,
    /// Logical BSS stream.
    pub i_bss: Signal<In, Bits<2>>,
    /// Logical INPUT stream.
    pub o_input: Signal<Out, Bits<4>>,
    /// Logical BSR stream.
    pub o_bsr: Signal<Out, Bits<4>>,
    /// Physical primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Physical secondary output.
    pub o_so: Signal<Out, Bits<2>>,
}

impl Logic for Switchbox {
    #[hdl_gen]
    fn update(&mut self) {
        self.o_input.next = self.i_pi.val();
        self.o_bsr.next = self.i_si.val();
        self.o_po.next = self.i_output.val();
        self.o_so.next = self.i_bss.val();
        if self.i_mode.val() == 1 {
            self.o_input.next = self.i_si.val();
            self.o_bsr.next = self.i_pi.val();
        }
        if self.i_mode.val() == 2 {
            self.o_po.next = self.i_bss.val();
            self.o_so.next = self.i_output.val();
        }
    }
}
