//! Property tests over random rings of 2..100 nodes (seeded; the seed is
//! printed on failure and can be set with MERKUR_SEED):
//! - after one break or node death, every surviving node's copy of every
//!   live writer's slot equals the fault-free ring's from the end of the
//!   recovery window on, and nobody enters failsafe;
//! - after a second fault, every node is in failsafe by the end of its window;
//! - two breaks on two links, both repaired: the ring leaves failsafe, every
//!   node is back in mode N and delivers what the fault-free ring does.

mod common;
use common::*;
use merkur_model::ring;
use proptest::prelude::*;
use proptest::test_runner::{Config as PConfig, RngAlgorithm, TestRng, TestRunner};

const DEFAULT_SEED: u64 = 0x6d65_726b_7572;

fn seed() -> u64 {
    std::env::var("MERKUR_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED)
}

fn runner(cases: u32) -> (TestRunner, u64) {
    let s = seed();
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&s.to_le_bytes());
    let cfg = PConfig {
        cases,
        failure_persistence: None,
        ..PConfig::default()
    };
    (
        TestRunner::new_with_rng(cfg, TestRng::from_seed(RngAlgorithm::ChaCha, &bytes)),
        s,
    )
}

/// Kinds of a random ring: one special master at `sm`, the others drawn
/// from `pick` (0 sensor, 1 actuator, 2 master).
fn kinds(n: usize, sm: usize, pick: &[u8]) -> Vec<&'static str> {
    (0..n)
        .map(|i| {
            if i == sm {
                "special_master"
            } else {
                ["sensor", "actuator", "master"][pick[i % pick.len()] as usize % 3]
            }
        })
        .collect()
}

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
