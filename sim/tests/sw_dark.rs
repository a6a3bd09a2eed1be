//! sw_dark in Verilator against a naive reference: seeded random output
//! pairs and switchbox changes (some closer together than the dark time);
//! outside the dark time the outputs are the switchbox's, for
//! `DARK_CLOCKS` clocks after a change both hold the level each line had —
//! PO not when the change keeps its source (`i_keep_po`, the special
//! master between N and WU: its own frame is not cut, issue 19).

use merkur_rtl::emit::verilog::block_verilog;
use merkur_rtl::node::sw_dark::SwDark;
use merkur_sim::{verilator::Model, Rng};

/// A node whose switchbox changes mode keeps both outputs dark for 12 bit
/// times (docs/protocol.md §10, "Dark after a change"), at 2 core clocks per
/// bit time (§9, "Receiver"). From the spec, not from the block's constant.
const DARK_CLOCKS: u64 = 12 * 2;

#[test]
fn dark_after_every_change_else_transparent() {
    let seed = Rng::seed(0xda4c);
    let mut rng = Rng::new(seed);
    let mut m = Model::build(&block_verilog(SwDark::default())).unwrap();
    let (clk, change, keep, i_po, i_so, o_po, o_so) = (
        m.port("clock"),
        m.port("i_change"),
        m.port("i_keep_po"),
        m.port("i_po"),
        m.port("i_so"),
        m.port("o_po"),
        m.port("o_so"),
    );
    // The reference: clocks of dark left, whether PO is darkened, and each
    // line's level.
    let (mut dark, mut dark_po, mut lvl) = (0u64, true, [0u64; 2]);
    let (mut dark_clocks, mut changes, mut kept) = (0, 0, 0);
    for t in 0..200_000u64 {
        // A change now and then; sometimes twice within the dark time.
        let ch = rng.below(if dark > 0 { 20 } else { 60 }) == 0;
        let kp = rng.below(3) == 0;
        let ins = [rng.below(4), rng.below(4)];
        m.set(change, ch as u64);
        m.set(keep, kp as u64);
        m.set(i_po, ins[0]);
        m.set(i_so, ins[1]);
        m.eval();
        let want = match (dark > 0, dark_po) {
            (false, _) => ins,
            (true, true) => [lvl[0] * 3, lvl[1] * 3],
            (true, false) => [ins[0], lvl[1] * 3],
        };
        let got = [m.get(o_po), m.get(o_so)];
        assert_eq!(
            got, want,
            "seed {seed} (MERKUR_SEED), clock {t}: outputs (PO, SO) with {dark} dark clocks left"
        );
        dark_clocks += (dark > 0) as u64;
        changes += ch as u64;
        kept += (ch && kp) as u64;
        lvl = [want[0] >> 1, want[1] >> 1];
        if ch {
            dark = DARK_CLOCKS;
            dark_po = !kp;
        } else {
            dark = dark.saturating_sub(1);
        }
        m.tick(clk);
    }
    // The run did what it claims: many changes, and dark most of their time.
    assert!(changes > 1000, "seed {seed}: only {changes} changes");
    assert!(
        kept > changes / 5,
        "seed {seed}: only {kept} changes kept PO"
    );
    assert!(
        dark_clocks > changes * DARK_CLOCKS / 2,
        "seed {seed}: dark for only {dark_clocks} clocks"
    );
}
