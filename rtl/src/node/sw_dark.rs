//! # sw_dark — dark physical outputs after a switchbox change (protocol §10)
//!
//! Purpose: when a node's switchbox changes mode, what its PO and SO carry
//! comes from another source (OUTPUT, the secondary pass-through, the TST
//! generator) in the middle of whatever the old source was sending. A
//! downstream receiver inside a packet would take the new source's bits as
//! the rest of its word (a splice that can pass both parities with a foreign
//! value) or stay inside a cut TST until three idle groups have passed. So
//! for [`DARK_CLOCKS`] (12 bit times) after a change both outputs hold their
//! level: every downstream receiver mutes ([`crate::line::cdr::MUTE_SAMPLES`], 8
//! bit times) and ends its packet, dropping the word it was in (not
//! received, protocol §5), and hunts for the next J K; 12 bit times are
//! well under loss of signal (32), so no stream controller fails. An
//! output whose source stays the same (`i_keep_po`: the special master's
//! PO, its own frame generator in N and in WU) is not darkened, so the
//! frame it is sending is not cut.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate |
//! | `i_change` | in | 1 | clock | the switchbox mode changes at the next clock edge |
//! | `i_keep_po` | in | 1 | clock | with `i_change`: PO keeps its source (not darkened) |
//! | `i_po`, `i_so` | in | 2 | clock | the switchbox's physical outputs, DDR pairs |
//! | `o_po`, `o_so` | out | 2 | clock | the same, dark (level held) for [`DARK_CLOCKS`] after a change |
//!
//! Latency: combinational (0 clocks) outside the dark time.
//!
//! ```text
//! i_change  __/‾\______________________________
//! i_po      ==X===X===X===X===X===X===X===X====   (new source from the next clock)
//! o_po      ==X===|___ level held, 24 clocks __|X===X====
//! ```

use rust_hdl::prelude::*;

/// Clocks both outputs stay dark after a switchbox change (12 bit times:
/// more than the 8 after which a receiver mutes plus the 2 after which it
/// ends a packet, well under the 32 of loss of signal).
pub const DARK_CLOCKS: u64 = 24;

/// Dark time of the physical outputs after a switchbox change.
#[derive(LogicBlock)]
pub struct SwDark {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// The mode changes at the next clock edge.
    pub i_change: Signal<In, Bit>,
    /// PO keeps its source across this change (not darkened).
    pub i_keep_po: Signal<In, Bit>,
    /// Physical primary output from the switchbox.
    pub i_po: Signal<In, Bits<2>>,
    /// Physical secondary output from the switchbox.
    pub i_so: Signal<In, Bits<2>>,
    /// Physical primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Physical secondary output.
    pub o_so: Signal<Out, Bits<2>>,
    dark_clocks: Constant<Bits<5>>,
    dark: DFF<Bits<5>>,
    dark_po: DFF<Bit>,
    lvl_po: DFF<Bit>,
    lvl_so: DFF<Bit>,
}

impl Default for SwDark {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_change: Default::default(),
            i_keep_po: Default::default(),
            i_po: Default::default(),
            i_so: Default::default(),
            o_po: Default::default(),
            o_so: Default::default(),
            dark_clocks: Constant::new(DARK_CLOCKS.to_bits()),
            dark: Default::default(),
            dark_po: Default::default(),
            lvl_po: Default::default(),
            lvl_so: Default::default(),
        }
    }
}

impl Logic for SwDark {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, dark, dark_po, lvl_po, lvl_so);
        self.o_po.next = self.i_po.val();
        self.o_so.next = self.i_so.val();
        if self.dark.q.val() != 0 {
            // Dark: the level the line had (the second half of the last
            // pair sent) for the whole clock.
            self.dark.d.next = self.dark.q.val() - 1;
            if self.dark_po.q.val() {
                self.o_po.next = 0.into();
                if self.lvl_po.q.val() {
                    self.o_po.next = 3.into();
                }
            }
            self.o_so.next = 0.into();
            if self.lvl_so.q.val() {
                self.o_so.next = 3.into();
            }
        }
        self.lvl_po.d.next = self.o_po.val().get_bit(1);
        self.lvl_so.d.next = self.o_so.val().get_bit(1);
        if self.i_change.val() {
            self.dark.d.next = self.dark_clocks.val();
            self.dark_po.d.next = !self.i_keep_po.val();
        }
    }
}
