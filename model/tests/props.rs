//! Property tests over random rings of 2..100 nodes (seeded; the seed is
//! printed on failure and can be set with MERKUR_SEED):
//! - after one break or node death, every surviving node's copy of every
//!   live writer's slot equals the fault-free ring's from the end of the
//!   recovery window on, and nobody enters failsafe;
//! - after a second fault, every node is in failsafe by the end of its window;
//! - two breaks on two links, both repaired: the ring leaves failsafe, every
//!   node is back in mode N and delivers what the fault-free ring does;
//! - with a fault, user interrupts and bit errors in alarm words, every
//!   master learns every alarm exactly once, and each node's last mode.

mod common;
use common::*;
use merkur_model::ring;
use proptest::prelude::*;

/// A structural fault: 0 break P, 1 break S, 2 kill.
fn fault_text(kind: u8, pos: usize, n: usize, sm: usize, cycle: u32, slot: Option<u32>) -> String {
    let slot = slot.map(|s| format!("slot = {s}\n")).unwrap_or_default();
    match kind {
        0 => format!(
            "\n[[fault]]\nkind = \"break\"\ncycle = {cycle}\n{slot}fibre = \"P{}\"\n",
            pos % n
        ),
        1 => format!(
            "\n[[fault]]\nkind = \"break\"\ncycle = {cycle}\n{slot}fibre = \"S{}\"\n",
            pos % n
        ),
        _ => {
            let mut node = pos % n;
            if node == sm {
                node = (node + 1) % n;
            }
            format!("\n[[fault]]\nkind = \"kill\"\ncycle = {cycle}\n{slot}node = {node}\n")
        }
    }
}

#[test]
fn single_fault_recovers_within_window() {
    let (mut r, s) = runner(48);
    let strat = (
        2usize..=100,
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        0u8..3,
        any::<usize>(),
        3u32..6,
        prop::option::of(0u32..2),
    );
    let res = r.run(&strat, |(n, smr, pick, fk, pos, c, slot)| {
        let sm = smr % n;
        let fk = if n == 2 { fk % 2 } else { fk };
        let text = ring_text(
            &kinds(n, sm, &pick),
            c + 8,
            &fault_text(fk, pos, n, sm, c, slot),
        );
        let cfg = load(&text);
        let (a, b) = run_pair(&cfg);
        let from = exact_from(&cfg, &a, &b);
        prop_assert!(
            matches!(from, Some(f) if f <= c + 3),
            "fault at {c}: exact only from {from:?}\n{text}"
        );
        for rec in &a {
            prop_assert!(
                rec.nodes.iter().all(|x| !x.failsafe),
                "failsafe after one fault\n{text}"
            );
        }
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

#[test]
fn second_fault_forces_failsafe() {
    let (mut r, s) = runner(48);
    let strat = (
        3usize..=100,
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        (0u8..3, any::<usize>()),
        (0u8..2, 1usize..1000),
        3u32..6,
    );
    let res = r.run(&strat, |(n, smr, pick, (fk1, pos1), (fk2, off), c)| {
        let sm = smr % n;
        let f1 = fault_text(fk1, pos1, n, sm, c, Some(0));
        // Second fault: a fibre break on a link that the first fault did not
        // already darken (a kill darkens both links of the node).
        let link1 = pos1 % n;
        let mut killed = if fk1 == 2 { pos1 % n } else { usize::MAX };
        if killed == sm {
            killed = (sm + 1) % n;
        }
        let mut link2 = (link1 + off) % n;
        let mut guard = 0;
        while link2 == link1
            || (killed != usize::MAX && (link2 == killed || (link2 + 1) % n == killed))
        {
            link2 = (link2 + 1) % n;
            guard += 1;
            if guard > n {
                return Ok(()); // no such link in this tiny ring
            }
        }
        let c2 = c + 4;
        let f2 = fault_text(fk2, link2, n, sm, c2, None);
        let text = ring_text(&kinds(n, sm, &pick), c2 + 5, &(f1 + &f2));
        let cfg = load(&text);
        let recs = ring::run(&cfg);
        // The loop without the special master times out after
        // CS_TIMEOUT_CYCLES cycles without a start delimiter (§12, rule 4).
        for rec in &recs[(c2 + ring::CS_TIMEOUT_CYCLES) as usize..] {
            for (k, st) in rec.nodes.iter().enumerate() {
                prop_assert!(
                    !st.up || st.failsafe,
                    "cycle {}: node {k} not failsafe\n{text}",
                    rec.cycle
                );
            }
        }
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

/// Two fibre breaks on two different links (the second takes the ring into
/// failsafe), both repaired (protocol §12, issue 28): whatever the links —
/// neighbours that cut a node off, the special master's own — the links
/// reintegrate, the special master brings the ring out of failsafe, every
/// node ends in mode N, and from some cycle on every node delivers exactly
/// what the fault-free ring's does.
#[test]
fn a_repaired_double_break_heals() {
    let (mut r, s) = runner(48);
    let strat = (
        3usize..=100,
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        (0u8..2, any::<usize>()),
        (0u8..2, 1usize..1000),
        0u8..3,
    );
    let res = r.run(&strat, |(n, smr, pick, (fk1, pos1), (fk2, off), place)| {
        let sm = smr % n;
        // Two links anywhere; two links of one node (cut off between
        // them); the special master's two links.
        let (link1, link2) = match place {
            0 => (pos1 % n, (pos1 + off) % n),
            1 => (pos1 % n, (pos1 + 1 + (off % 2) * (n - 2)) % n),
            _ => {
                let (a, b) = ((sm + n - 1) % n, sm);
                if off % 2 == 0 {
                    (a, b)
                } else {
                    (b, a)
                }
            }
        };
        if link2 == link1 {
            return Ok(());
        }
        let c = 3;
        let brk = |fk: u8, link: usize, cycle: u32| fault_text(fk, link, n, sm, cycle, None);
        let fibre = |fk: u8, link: usize| format!("{}{link}", ["P", "S"][fk as usize]);
        let rep = |fk: u8, link: usize, cycle: u32| {
            format!(
                "\n[[fault]]\nkind = \"repair\"\ncycle = {cycle}\nfibre = \"{}\"\n",
                fibre(fk, link)
            )
        };
        let faults = brk(fk1, link1, c)
            + &brk(fk2, link2, c + 4)
            + &rep(fk2, link2, c + 6)
            + &rep(fk1, link1, c + 7);
        let text = ring_text(&kinds(n, sm, &pick), c + 30, &faults);
        let cfg = load(&text);
        let (a, b) = run_pair(&cfg);
        prop_assert!(
            a[(c + 8) as usize].nodes.iter().all(|x| x.failsafe),
            "the second break takes the ring into failsafe\n{text}"
        );
        let last = a.last().unwrap();
        for (k, x) in last.nodes.iter().enumerate() {
            prop_assert!(
                !x.failsafe && x.mode == ring::Mode::N,
                "node {k} ends {:?}, failsafe {}\n{text}",
                x.mode,
                x.failsafe
            );
        }
        let from = exact_from(&cfg, &a, &b);
        prop_assert!(
            from.is_some(),
            "never delivers as the fault-free ring\n{text}"
        );
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

/// Confirmed delivery (protocol §11): with a structural fault (and its
/// repair), user interrupts and bit errors aimed at alarm words, every
/// master that stays up learns every IRQ1/IRQ2 alarm of every other live
/// node exactly once, and the last RECONFIG it got from each node is that
/// node's switchbox mode at the end. Rings that fail safe are skipped
/// (alarms are not sent in failsafe); the test checks enough cases ran.
#[test]
fn every_alarm_reaches_every_master_once() {
    use merkur_model::ring::{EventKind, Mode};
    use std::collections::BTreeMap;
    let (mut r, s) = runner(64);
    let strat = (
        3usize..=40,
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        (0u8..3, any::<usize>(), 3u32..6, any::<bool>()),
        prop::collection::vec((any::<usize>(), 2u32..12, any::<bool>()), 1..6),
        prop::collection::vec((any::<usize>(), any::<usize>(), 0u32..25, 1u32..3), 0..6),
    );
    let checked = std::cell::Cell::new(0);
    let res = r.run(&strat, |(n, smr, pick, (fk, pos, c, repair), irqs, flips)| {
        let sm = smr % n;
        let fk = if n == 2 { fk % 2 } else { fk };
        let mut extra = fault_text(fk, pos, n, sm, c, None);
        if repair && fk < 2 {
            extra += &format!(
                "\n[[fault]]\nkind = \"repair\"\ncycle = {}\nfibre = \"{}{}\"\n",
                c + 4,
                ["P", "S"][fk as usize],
                pos % n
            );
        }
        for &(node, cycle, one) in &irqs {
            let line = if one { "irq1" } else { "irq2" };
            extra += &format!(
                "\n[[irq]]\ncycle = {cycle}\nnode = {}\nline = \"{line}\"\n",
                node % n
            );
        }
        // Bit errors in the senders' slots, one or two cycles after they
        // raised their lines (where their alarms travel).
        for (i, &(fib, which, bit, late)) in flips.iter().enumerate() {
            let (node, cycle, _) = irqs[which % irqs.len()];
            extra += &format!(
                "\n[[fault]]\nkind = \"flip\"\ncycle = {}\nfibre = \"P{}\"\nslot = {}\nbit = {bit}\n",
                cycle + late + (i as u32 % 2),
                fib % n,
                node % n
            );
        }
        let text = ring_text(&kinds(n, sm, &pick), 32, &extra);
        let cfg = load(&text);
        let recs = ring::run(&cfg);
        if recs.iter().any(|x| x.nodes.iter().any(|y| y.failsafe)) {
            return Ok(());
        }
        checked.set(checked.get() + 1);
        let last = recs.last().unwrap();
        let up = |k: usize| last.nodes[k].up;
        // New alarms sent per (sender, reason); deliveries per (master,
        // slot, reason); the last RECONFIG per (master, slot).
        let mut sent: BTreeMap<(usize, u8), u32> = BTreeMap::new();
        let mut got: BTreeMap<(usize, usize, u8), u32> = BTreeMap::new();
        let mut shape: BTreeMap<(usize, usize), u8> = BTreeMap::new();
        for ev in recs.iter().flat_map(|x| &x.events) {
            match ev.kind {
                EventKind::AlarmTx {
                    reason,
                    repeat: false,
                } => *sent.entry((ev.node, reason)).or_default() += 1,
                EventKind::Irq { slot, reason } => {
                    *got.entry((ev.node, slot, reason)).or_default() += 1;
                    if (4..=6).contains(&reason) {
                        shape.insert((ev.node, slot), reason);
                    }
                }
                _ => {}
            }
        }
        for m in (0..n).filter(|&m| cfg.nodes[m].kind.is_master() && up(m)) {
            for k in (0..n).filter(|&k| k != m && up(k)) {
                let a = cfg.nodes[k].address;
                for reason in [1u8, 2] {
                    let tx = sent.get(&(k, reason)).copied().unwrap_or(0);
                    let rx = got.get(&(m, a, reason)).copied().unwrap_or(0);
                    prop_assert_eq!(
                        tx,
                        rx,
                        "master {} got IRQ{} of node {} {} times, sent {}\n{}",
                        m,
                        reason,
                        k,
                        rx,
                        tx,
                        text
                    );
                }
                let mode = match shape.get(&(m, a)) {
                    Some(&r) if r == ring::reason::RECONFIG_WU => Mode::Wu,
                    Some(&r) if r == ring::reason::RECONFIG_WD => Mode::Wd,
                    _ => Mode::N,
                };
                prop_assert_eq!(
                    mode,
                    last.nodes[k].mode,
                    "master {} sees node {} in {:?}, it is in {:?}\n{}",
                    m,
                    k,
                    mode,
                    last.nodes[k].mode,
                    text
                );
            }
        }
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
    let checked = checked.get();
    assert!(
        checked >= 32,
        "only {checked} of 64 rings stayed out of failsafe"
    );
}
