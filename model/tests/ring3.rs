//! A 3-node ring (special master, master, actuator... see RING) with each of
//! its 6 fibres broken, each node killed, a double fault and a repair.

mod common;
use common::*;
use merkur_model::ring::{self, EventKind, FsCause, Mode};

const KINDS: [&str; 3] = ["special_master", "master", "actuator"];
const FAULT_CYCLE: u32 = 4;

fn fibre_fault(f: &str, slot: u32) -> String {
    format!(
        "\n[[fault]]\nkind = \"break\"\ncycle = {FAULT_CYCLE}\nslot = {slot}\nfibre = \"{f}\"\n"
    )
}

#[test]
fn fault_free_ring_delivers_every_value() {
    let cfg = load(&ring_text(&KINDS, 8, ""));
    let recs = ring::run(&cfg);
    let last = recs.last().unwrap();
    // Special master (node 0) and master (node 1) both hold every slot's
    // host value; the actuator outputs what the special master writes.
    assert_eq!(last.nodes[0].db, vec![0x1000, 0x1001, 0x2002]);
    assert_eq!(last.nodes[1].db, vec![0x1000, 0x1001, 0x2002]);
    assert_eq!(last.nodes[2].output, 0x2002);
    for r in &recs {
        assert!(
            r.events.is_empty(),
            "no events in a healthy ring: {:?}",
            r.events
        );
        assert!(r.nodes.iter().all(|n| n.mode == Mode::N && !n.failsafe));
        assert!(r
            .nodes
            .iter()
            .all(|n| n.perr == 0 && n.aerr == 0 && n.serr == 0));
    }
}

#[test]
fn each_of_the_six_fibres_broken() {
    for k in 0..3usize {
        for p in ["P", "S"] {
            for slot in [0u32, 2] {
                let name = format!("{p}{k}");
                let cfg = load(&ring_text(&KINDS, 12, &fibre_fault(&name, slot)));
                let (a, b) = run_pair(&cfg);
                // Both ends of link k wrap: node k to row 3, node k+1 to row 2.
                let last = a.last().unwrap();
                assert_eq!(last.nodes[k].mode, Mode::Wd, "{name}: node {k}");
                assert_eq!(
                    last.nodes[(k + 1) % 3].mode,
                    Mode::Wu,
                    "{name}: node {}",
                    k + 1
                );
                assert!(
                    last.nodes.iter().all(|n| !n.failsafe),
                    "{name}: no failsafe"
                );
                let from = exact_from(&cfg, &a, &b).expect("recovers");
                assert!(
                    from <= FAULT_CYCLE + 3,
                    "{name} slot {slot}: exact only from cycle {from}, window promises {}",
                    FAULT_CYCLE + 3
                );
                // Before the fault, identical.
                for c in 0..FAULT_CYCLE as usize {
                    assert_eq!(delivered(&cfg, &a[c]), delivered(&cfg, &b[c]));
                }
                // Every wrapped node told every master: RECONFIG alarms.
                let irqs = a
                    .iter()
                    .flat_map(|r| &r.events)
                    .filter(|e| matches!(e.kind, EventKind::Irq { reason: 5 | 6, .. }))
                    .count();
                assert!(
                    irqs >= 2,
                    "{name}: masters heard the reconfiguration ({irqs})"
                );
            }
        }
    }
}

#[test]
fn each_node_killed() {
    for node in 1..3 {
        let f = format!(
            "\n[[fault]]\nkind = \"kill\"\ncycle = {FAULT_CYCLE}\nslot = 1\nnode = {node}\n"
        );
        let cfg = load(&ring_text(&KINDS, 12, &f));
        let (a, b) = run_pair(&cfg);
        let last = a.last().unwrap();
        assert!(!last.nodes[node].up);
        assert_eq!(
            last.nodes[(node + 1) % 3].mode,
            Mode::Wu,
            "downstream neighbour"
        );
        assert_eq!(
            last.nodes[(node + 2) % 3].mode,
            Mode::Wd,
            "upstream neighbour"
        );
        assert!(last.nodes.iter().all(|n| !n.failsafe));
        let from = exact_from(&cfg, &a, &b).expect("recovers");
        assert!(
            from <= FAULT_CYCLE + 3,
            "kill {node}: exact only from {from}"
        );
        if node == 2 {
            // The dead actuator's Alive stops: both masters notice.
            let lost: Vec<usize> = a
                .iter()
                .flat_map(|r| &r.events)
                .filter(|e| matches!(e.kind, EventKind::AliveLost { slot: 2 }))
                .map(|e| e.node)
                .collect();
            assert_eq!(lost.len(), 2, "alive lost at both masters: {lost:?}");
        }
    }
    // The special master cannot be killed (no flying master yet).
    let f = "\n[[fault]]\nkind = \"kill\"\ncycle = 4\nnode = 0\n";
    let e = merkur_model::config::load("t.toml", &ring_text(&KINDS, 12, f)).unwrap_err();
    assert!(
        e.msg.contains("fault[0].node = 0 is the special master"),
        "{e}"
    );
}

#[test]
fn double_fault_forces_failsafe_everywhere() {
    let f = fibre_fault("P0", 1)
        + "\n[[fault]]\nkind = \"break\"\ncycle = 9\nslot = 0\nfibre = \"P1\"\n";
    let cfg = load(&ring_text(&KINDS, 14, &f));
    let recs = ring::run(&cfg);
    assert!(
        recs[8].nodes.iter().all(|n| !n.failsafe),
        "one fault: no failsafe"
    );
    // Cycle 9 + the CS timeout's 3 cycles (protocol §12, rule 4).
    for r in &recs[12..] {
        assert!(
            r.nodes.iter().all(|n| n.failsafe),
            "cycle {}: all failsafe",
            r.cycle
        );
    }
    let second: Vec<usize> = recs
        .iter()
        .flat_map(|r| &r.events)
        .filter(|e| e.kind == EventKind::Failsafe(FsCause::SecondFault))
        .map(|e| e.node)
        .collect();
    assert!(
        !second.is_empty(),
        "a stream controller saw the second fault"
    );
    // Memories are frozen in failsafe.
    assert_eq!(recs[11].nodes[1].db, recs[13].nodes[1].db);
}

#[test]
fn repaired_fibre_is_reintegrated() {
    let f = fibre_fault("P1", 1) + "\n[[fault]]\nkind = \"repair\"\ncycle = 8\nfibre = \"P1\"\n";
    let cfg = load(&ring_text(&KINDS, 16, &f));
    let (a, b) = run_pair(&cfg);
    assert_eq!(a[7].nodes[1].mode, Mode::Wd);
    // Unwrapped at the end of cycle 9 (one full cycle of TST handshake).
    assert!(a[9].nodes.iter().all(|n| n.mode == Mode::N));
    assert!(a[15].nodes.iter().all(|n| !n.failsafe && !n.rw));
    let from = exact_from(&cfg, &a, &b).expect("recovers");
    assert!(from <= 8 + 4, "exact from {from}");
    // A second fault after reintegration is a first fault again.
    let f2 = f + "\n[[fault]]\nkind = \"break\"\ncycle = 13\nfibre = \"S2\"\n";
    let cfg = load(&ring_text(&KINDS, 20, &f2));
    let r = ring::run(&cfg);
    assert!(r.last().unwrap().nodes.iter().all(|n| !n.failsafe));
}

#[test]
fn table1_rows_hand_vectors() {
    use merkur_model::ring::{table1, Port::*};
    // The paper's Table 1: (INPUT, OUTPUT, BSR, BSS).
    assert_eq!(table1(Mode::N), (Pi, Po, Si, So), "all 4 ports ok");
    assert_eq!(table1(Mode::Wu), (Si, Po, Pi, So), "SO or PI defective");
    assert_eq!(table1(Mode::Wd), (Pi, So, Si, Po), "SI or PO defective");
}

#[test]
fn table1_rows_are_chosen_by_the_defective_port() {
    // Node 1's PI dead (P0 broken): row 2 at node 1. Its partner node 0 sees
    // node 1's TST on SI and takes row 3 ("PO defective").
    let cfg = load(&ring_text(&KINDS, 6, &fibre_fault("P0", 0)));
    let r = ring::run(&cfg);
    assert_eq!(
        (r[4].nodes[1].mode, r[4].nodes[0].mode),
        (Mode::Wu, Mode::Wd)
    );
    // Node 1's SI dead (S1 broken, node 2 SO -> node 1 SI): row 3 at node 1,
    // row 2 at node 2 ("SO defective").
    let cfg = load(&ring_text(&KINDS, 6, &fibre_fault("S1", 0)));
    let r = ring::run(&cfg);
    assert_eq!(
        (r[4].nodes[1].mode, r[4].nodes[2].mode),
        (Mode::Wd, Mode::Wu)
    );
}

#[test]
fn a_4096_slot_frame_runs_and_4097_is_refused() {
    let slots: Vec<String> = (2..4096).map(|s| s.to_string()).collect();
    let text = format!(
        "cycles = 3\n[[node]]\nkind = \"special_master\"\naddress = 0\nslots = [0]\n\n[[node]]\nkind = \"master\"\naddress = 1\nslots = [1, {}]\nppm = -1000\n\n[[host_write]]\ncycle = 0\nnode = 1\nslot = 4095\ndata = 0xfeed\n",
        slots.join(", ")
    );
    let cfg = load(&text);
    assert_eq!(cfg.slots, 4096);
    assert_eq!(cfg.frame_bits(), 10 + 4098 * 25);
    let r = ring::run(&cfg);
    assert_eq!(r[2].nodes[0].db[4095], 0xfeed, "the SM holds slot 4095");
    let bad = text.replace("slots = [1, ", "slots = [1, 4096, ");
    let e = merkur_model::config::load("t.toml", &bad).unwrap_err();
    assert!(
        e.msg.contains("node[1].slots = 4096 is out of range"),
        "{e}"
    );
}
