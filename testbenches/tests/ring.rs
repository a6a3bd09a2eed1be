//! Whole rings in Verilator against the model (issue 4): every fault-free
//! scenario the RTL covers runs with its clock offsets and random phases and
//! must agree word for word, header for header and in every node's final
//! state; a deliberately wrong expectation must be reported; the master's
//! host bus refuses what it must.

use merkur_model::config::{self, cfg_bits};
use merkur_model::ring::{self, Slot};
use merkur_rtl::master::Master;
use merkur_rtl::mdb::{ST_RUN, WB_CFG, WB_STATUS};
use merkur_rtl::verilog::block_verilog;
use merkur_testbenches::ring_sim::{run, Options};
use merkur_testbenches::wishbone::Wishbone;
use merkur_testbenches::{repo_root, verilator::Model, Rng};

fn load(name: &str) -> config::Config {
    let text = std::fs::read_to_string(repo_root().join("tb-data").join(name)).unwrap();
    config::load(name, &text).unwrap()
}

fn passes(name: &str) {
    let seed = Rng::seed(0x7105);
    let cfg = load(name);
    let recs = ring::run(&cfg);
    let opts = Options {
        seed,
        ..Default::default()
    };
    let rep = run(&cfg, &recs, &opts).unwrap_or_else(|e| panic!("{name}: {e}"));
    let first: Vec<String> = rep
        .mismatches
        .iter()
        .take(5)
        .map(|m| m.to_string())
        .collect();
    assert!(
        rep.mismatches.is_empty(),
        "{name}, seed {seed} (MERKUR_SEED): {} mismatches: {first:#?}",
        rep.mismatches.len()
    );
    let words = (cfg.nodes.len() * 2) as u64; // at least the headers of P fibres
    assert!(
        rep.words > words * cfg.cycles as u64,
        "{name}: too few words compared"
    );
    // The special master keeps the scenario's period on its own clock.
    let ppm = cfg.nodes[cfg.sm].ppm;
    let want = cfg.period as f64 / (1.0 + ppm * 1e-6);
    assert!(
        (rep.period_bits - want).abs() < 2.0,
        "{name}: period {} bit times, want {want}",
        rep.period_bits
    );
}

#[test]
fn ring2_agrees_with_the_model() {
    passes("ring2.toml");
}

#[test]
fn ring3_agrees_with_the_model() {
    passes("ring3.toml");
}

#[test]
fn ring8_agrees_with_the_model() {
    passes("ring8.toml");
}

#[test]
fn ring8_interrupts_agree_with_the_model() {
    passes("ring8_irq.toml");
}

/// 32 hops at clocks from −1000 to +934 ppm: edge errors must not add up
/// along the chain (the retimed forwarder, docs/architecture.md).
#[test]
fn ring32_agrees_with_the_model() {
    passes("ring32.toml");
}

/// `merkur demo`'s ring: the primary fibre P3 breaks in the middle of
/// cycle 4's frame; nodes 4 and 3 wrap, the special master relays the
/// wrapped frame on its secondary ports, every word, SEC and node state
/// agrees with the model.
#[test]
fn demo_line_break_agrees_with_the_model() {
    passes("demo_8_break.toml");
}

/// Single faults (protocol §10, §13): a primary and a secondary fibre
/// break, a node dies; a second fault splits the ring into failsafe; a
/// user FAILSAFE request. Compared through the recovery windows.
#[test]
fn ring8_primary_break_agrees_with_the_model() {
    passes("ring8_break_primary.toml");
}

#[test]
fn ring8_secondary_break_agrees_with_the_model() {
    passes("ring8_break_secondary.toml");
}

#[test]
fn ring8_node_death_agrees_with_the_model() {
    passes("ring8_kill.toml");
}

#[test]
fn ring8_double_fault_failsafe_agrees_with_the_model() {
    passes("ring8_double.toml");
}

/// Single line-bit errors on the sender's bit grid: slot words (one at a
/// word's last bit, hitting the next word too), a header, a delimiter, a
/// SEC header; every one detected where the model says.
#[test]
fn ring8_bit_errors_agree_with_the_model() {
    passes("ring8_parity.toml");
}

#[test]
fn ring8_failsafe_request_agrees_with_the_model() {
    passes("ring8_failsafe_request.toml");
}

/// The window rules do not hide errors after the window: a counter
/// increment the model did not make, in a cycle after the break's window,
/// is reported, and so is a wrong word there.
#[test]
fn after_a_window_the_comparison_is_exact() {
    let cfg = load("ring8_break_primary.toml");
    let (_, z, _) = ring::windows(&cfg)[0].clone();
    let c = z as usize + 2;
    let mut recs = ring::run(&cfg);
    for rec in &mut recs[c..] {
        rec.nodes[4].perr += 1;
    }
    let ring::Carry::Data(f) = &mut recs[c].fibres[2] else {
        panic!("P2 carries the frame in cycle {c}")
    };
    let Slot::Data(w) = &mut f.words[6] else {
        panic!("slot 6 is good")
    };
    w.data ^= 0x0010;
    let rep = run(&cfg, &recs, &Options::default()).unwrap();
    let found: Vec<(u32, &str, &str)> = rep
        .mismatches
        .iter()
        .map(|m| (m.cycle, m.place.as_str(), m.what.as_str()))
        .collect();
    assert_eq!(
        found,
        [
            (c as u32, "P2", "slot 6"),
            (c as u32, "node 4", "perr increment")
        ],
        "{:#?}",
        rep.mismatches
    );
}

/// The BRIEF §6 size: 100 nodes, 100 slots of 16 bit, ±1000 ppm.
#[test]
fn ring100_agrees_with_the_model() {
    passes("ring100.toml");
}

/// The checker can fail: one slot of one fibre changed in the expectation
/// is reported at exactly that place.
#[test]
fn a_wrong_expectation_is_reported() {
    let cfg = load("ring2.toml");
    let mut recs = ring::run(&cfg);
    let ring::Carry::Data(f) = &mut recs[3].fibres[1] else {
        panic!("P1 carries the frame in cycle 3")
    };
    let Slot::Data(w) = &mut f.words[1] else {
        panic!("slot 1 is good")
    };
    w.data ^= 0x0100;
    let rep = run(&cfg, &recs, &Options::default()).unwrap();
    assert_eq!(rep.mismatches.len(), 1, "{:#?}", rep.mismatches);
    let m = &rep.mismatches[0];
    assert_eq!(
        (m.cycle, m.place.as_str(), m.what.as_str()),
        (3, "P1", "slot 1")
    );
    eprintln!("first mismatch of the broken expectation: {m}");
}

fn wb(m: &mut Model, bus: &Wishbone, adr: u16, write: Option<u16>) -> u16 {
    let clk = m.port("clock");
    bus.transfer(m, &mut |m| m.tick(clk), adr, write).unwrap().0
}

#[test]
fn the_host_bus_refuses_foreign_slots_and_late_configuration() {
    let mut m = Model::build(&block_verilog(Master::default())).unwrap();
    let bus = Wishbone::new(&m);
    let local = cfg_bits::LOCAL as u16;
    // Before the start: configuration is written and read back.
    wb(&mut m, &bus, WB_CFG + 3, Some(local));
    assert_eq!(wb(&mut m, &bus, WB_CFG + 3, None), local);
    assert_eq!(wb(&mut m, &bus, WB_STATUS, None) & 7, 0);
    // A LOCAL slot takes data; a slot the master does not write refuses it.
    wb(&mut m, &bus, 3, Some(0x1234));
    assert_eq!(wb(&mut m, &bus, 3, None), 0x1234);
    wb(&mut m, &bus, 4, Some(0x5678));
    assert_eq!(wb(&mut m, &bus, 4, None), 0, "foreign slot written");
    assert_eq!(
        wb(&mut m, &bus, WB_STATUS, None) & 4,
        4,
        "data write refusal flagged"
    );
    // Running: configuration writes are refused and flagged.
    wb(&mut m, &bus, WB_STATUS, Some(ST_RUN | 4));
    assert_eq!(wb(&mut m, &bus, WB_STATUS, None) & 7, 1);
    wb(&mut m, &bus, WB_CFG + 4, Some(local));
    assert_eq!(
        wb(&mut m, &bus, WB_CFG + 4, None),
        0,
        "configuration changed while running"
    );
    assert_eq!(
        wb(&mut m, &bus, WB_STATUS, None) & 2,
        2,
        "configuration refusal flagged"
    );
}
