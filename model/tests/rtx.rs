//! Retransmission on demand (protocol §8, issue 23): a critical slot damaged
//! by a bit error is as young at every node as in the same ring without the
//! error, when the retransmission packet fits and is not hit itself; no
//! errors, no extra traffic; a non-critical slot is not retransmitted.
//!
//! Seeded like the property tests (MERKUR_SEED; printed on failure).

mod common;
use common::*;
use merkur_model::config::{Config, Fault, Fibre, FlipTarget};
use merkur_model::ring::{self, ages, CycleRecord, EventKind};
use proptest::prelude::*;
use std::collections::BTreeMap;

fn tb(name: &str) -> Config {
    let p = format!("{}/../tb-data/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    load(&std::fs::read_to_string(p).unwrap())
}

/// The same ring without its bit errors (breaks, kills and repairs kept).
fn without_flips(cfg: &Config) -> Config {
    let mut c = cfg.clone();
    c.faults.retain(|(_, f)| !matches!(f, Fault::Flip { .. }));
    c
}

/// The same ring without critical slots (no retransmission).
fn without_rtx(cfg: &Config) -> Config {
    let mut c = cfg.clone();
    c.critical.iter_mut().for_each(|x| *x = false);
    c
}

fn age_map(cfg: &Config, r: &CycleRecord) -> BTreeMap<(usize, usize), Option<u32>> {
    ages(cfg, r).into_iter().collect()
}

/// Copies of slot `s` (over every reader) older at the end of cycle `c` in
/// run `a` than in run `b`.
fn older(cfg: &Config, a: &[CycleRecord], b: &[CycleRecord], c: usize, s: usize) -> Vec<usize> {
    // No value yet counts as older than any.
    let (x, y) = (age_map(cfg, &a[c]), age_map(cfg, &b[c]));
    x.iter()
        .filter(|((_, slot), _)| *slot == s)
        .filter(|(key, age)| {
            age.unwrap_or(u32::MAX) > y.get(key).copied().flatten().unwrap_or(u32::MAX)
        })
        .map(|((k, _), _)| *k)
        .collect()
}

#[test]
fn the_starter_scenario_retransmits_what_its_errors_damage() {
    let cfg = tb("ring8_rtx");
    let recs = ring::run(&cfg);
    let reference = ring::run(&without_flips(&cfg));
    let plain = ring::run(&without_rtx(&cfg));
    // No errors, no extra traffic.
    assert!(reference.iter().all(|r| r.rtx.is_none()));
    let rtx = |c: usize| recs[c].rtx.clone();
    // Cycle 2: slot 1 damaged before master 3; the copy comes back good
    // and every copy is as young as without the error, this cycle and the
    // next (the special master's next frame serves the nodes upstream).
    let x = rtx(2).expect("an RTX in cycle 2");
    assert_eq!(
        (x.slots.as_slice(), x.back.as_slice()),
        (&[1][..], &[true][..])
    );
    for c in [2, 3] {
        assert!(older(&cfg, &recs, &reference, c, 1).is_empty(), "cycle {c}");
    }
    // Not blind: without retransmission the copies behind the error, the
    // special master's (it reads the frame as it returns) and master 3's,
    // are a cycle older.
    assert_eq!(older(&cfg, &plain, &reference, 2, 1), vec![0, 3]);
    // Cycle 3: the actuator slot 7, refilled by master 3, reaches actuator 7.
    assert_eq!(rtx(3).expect("cycle 3").slots, vec![7]);
    assert!(older(&cfg, &recs, &reference, 3, 7).is_empty());
    assert!(older(&cfg, &plain, &reference, 3, 7).contains(&7));
    // Cycle 4: two requests; the second's copy is hit on P6, so the copy
    // behind the hit (the special master's) keeps the older value, as
    // without the feature, and so does master 3 in the next cycle (it is
    // upstream of the writer and served by the special master's store).
    let x = rtx(4).expect("cycle 4");
    assert_eq!((x.slots, x.back), (vec![2, 4], vec![true, false]));
    assert!(older(&cfg, &recs, &reference, 4, 2).is_empty());
    assert_eq!(older(&cfg, &recs, &reference, 4, 4), vec![0]);
    assert_eq!(older(&cfg, &recs, &reference, 5, 4), vec![3]);
    // Cycle 5: slot 6 is not critical.
    assert!(rtx(5).is_none());
    assert!(!older(&cfg, &recs, &reference, 5, 6).is_empty());
    // Cycle 6: the packet's head is hit on P3: master 3, before the hit,
    // takes its copy; nobody behind the hit does (the special master).
    assert_eq!(rtx(6).expect("cycle 6").back, vec![false]);
    assert_eq!(older(&cfg, &plain, &reference, 6, 1), vec![0, 3]);
    assert_eq!(older(&cfg, &recs, &reference, 6, 1), vec![0]);
    // Cycle 12, the ring wrapped around P5: the packet takes the frame's
    // path through the secondary fibres and repairs the copy.
    let x = rtx(12).expect("cycle 12");
    let n = cfg.nodes.len();
    assert!(x.fibres.iter().any(|&f| f >= n), "{:?}", x.fibres);
    assert_eq!(x.back, vec![true]);
    assert!(older(&cfg, &recs, &reference, 12, 2).is_empty());
    // Cycle 14: the frame's H1 is hit on P1, so everyone behind node 1
    // ignores the frame; every critical slot is requested and the wrapped
    // ring's room takes two: slots 1 and 2 are as young as without the
    // error, 4 and 7 are not.
    let x = rtx(14).expect("cycle 14");
    assert_eq!((x.slots.as_slice(), x.left), (&[1, 2][..], 2));
    assert_eq!(cfg.rtx_capacity(true), 2);
    for s in [1, 2] {
        assert!(older(&cfg, &recs, &reference, 14, s).is_empty(), "slot {s}");
    }
    assert!(!older(&cfg, &recs, &reference, 14, 4).is_empty());
    // No failsafe anywhere.
    assert!(recs.iter().all(|r| r.nodes.iter().all(|s| !s.failsafe)));
}

#[test]
fn a_period_without_room_refuses_and_the_minimum_has_room_for_one() {
    let text = ring_text(
        &["special_master", "sensor", "sensor", "master", "sensor"],
        6,
        "",
    )
    .replace("cycles = 6\n", "cycles = 6\n\n[frame]\ncritical = [4]\n");
    let cfg = load(&text);
    assert_eq!(cfg.period, cfg.min_period());
    assert_eq!(cfg.rtx_capacity(false), 1);
    assert_eq!(cfg.rtx_capacity(true), 0);
    let short = text.replace(
        "critical = [4]",
        &format!("period_bits = {}\ncritical = [4]", cfg.period - 1),
    );
    let e = merkur_model::config::load("t.toml", &short).unwrap_err();
    assert!(
        e.msg.contains("frame.critical: critical slot 4"),
        "{}",
        e.msg
    );
}

#[test]
fn a_rejected_header_hit_again_in_h0_requests_nothing() {
    // Cycle 14 of ring8_rtx: H1 hit on P1, every critical slot requested.
    // A second error, in H0 on P4, leaves the clock base a frame whose H0
    // is unreadable: nothing is requested (§8).
    let mut cfg = tb("ring8_rtx");
    cfg.faults.retain(|&(c, _)| c != 14);
    let h1 = (
        14,
        Fault::Flip {
            fibre: Fibre::P(1),
            target: FlipTarget::H1,
            bit: 5,
        },
    );
    let h0 = (
        14,
        Fault::Flip {
            fibre: Fibre::P(4),
            target: FlipTarget::H0,
            bit: 11,
        },
    );
    let mut once = cfg.clone();
    once.faults.push(h1);
    let mut twice = once.clone();
    twice.faults.push(h0);
    let (a, b) = (ring::run(&once), ring::run(&twice));
    assert_eq!(a[14].rtx.as_ref().map(|x| x.slots.len()), Some(2));
    assert!(b[14].rtx.is_none(), "{:?}", b[14].rtx);
}

#[test]
fn an_actuator_missing_the_frame_writes_its_alive_into_a_copy_damaged_after_its_lead() {
    // ring8_rtx with slot 7 (actuator 7, served by master 3) the only
    // critical slot. Cycle 4: H1 hit on P5, so nodes 6 and 7 miss the frame
    // and the RTX requests slot 7; master 3 fills it; the copy is hit on P6
    // (after its first group, `damaged`) or not (`good`).
    let mut cfg = tb("ring8_rtx");
    cfg.faults.clear();
    cfg.critical.iter_mut().for_each(|x| *x = false);
    cfg.critical[7] = true;
    let flip = |fibre, target, bit| (4, Fault::Flip { fibre, target, bit });
    let mut good = cfg.clone();
    good.faults.push(flip(Fibre::P(5), FlipTarget::H1, 5));
    let mut damaged = good.clone();
    damaged
        .faults
        .push(flip(Fibre::P(6), FlipTarget::Rtx(1), 12));
    let (g, d, clean) = (ring::run(&good), ring::run(&damaged), ring::run(&cfg));
    assert_eq!(g[4].rtx.as_ref().map(|x| x.slots.clone()), Some(vec![7]));
    assert_eq!(d[4].rtx.as_ref().map(|x| x.back.clone()), Some(vec![false]));
    // The good copy reaches the actuator's output, the damaged one not.
    assert_eq!(g[4].nodes[7].out_born, Some(4));
    assert_ne!(d[4].nodes[7].out_born, Some(4));
    // Either way the actuator wrote its Alive into the copy (§8), so its
    // Alive toggles as if it had processed the frame; node 6, a sensor
    // that missed it and wrote nothing, does not.
    for r in [&g, &d] {
        assert_eq!(r[4].nodes[7].toggle, clean[4].nodes[7].toggle);
        assert_ne!(r[4].nodes[6].toggle, clean[4].nodes[6].toggle);
    }
}

/// A flip in the frame's word `target` on the fibre into path position
/// `hop` (the fibre the frame leaves node path[hop - 1] on), bit `bit`.
fn frame_flip(
    recs: &[CycleRecord],
    n: usize,
    c: u32,
    hop: usize,
    target: FlipTarget,
    bit: u32,
) -> Option<(u32, Fault)> {
    let path = &recs[c as usize].path;
    let from = *path.get(hop.checked_sub(1)?)?;
    Some((
        c,
        Fault::Flip {
            fibre: Fibre::P(from % n),
            target,
            bit,
        },
    ))
}

#[test]
fn random_rings_and_errors_a_repaired_copy_is_never_older() {
    let (mut runner, seed) = runner(200);
    // Cases whose retransmission came back good at least once: the
    // property below is not vacuous.
    let repaired = std::sync::atomic::AtomicUsize::new(0);
    let strat = (
        5usize..=10,
        proptest::collection::vec(0u8..3, 10),
        proptest::collection::vec(any::<bool>(), 10),
        1u32..5,
        proptest::collection::vec((1usize..10, 0usize..10, 0u32..25, 0u8..5), 1..4),
        proptest::option::of((0usize..4, 0u32..25)),
    );
    let r = runner.run(&strat, |(n, pick, crit, c, hits, rtx_hit)| {
        let kinds = kinds(n, 0, &pick);
        let mut cfg = load(&ring_text(&kinds, 7, ""));
        for s in 0..cfg.slots {
            cfg.critical[s] = crit[s % crit.len()];
        }
        if cfg.last_critical().is_none() {
            cfg.critical[cfg.slots - 1] = true;
        }
        cfg.period = cfg.min_period() + 150;
        let clean = ring::run(&cfg);
        for &(hop, s, bit, what) in &hits {
            // Mostly slot words, sometimes a header word (the frame is
            // then lost behind the error and every critical slot requested).
            let target = match what {
                3 => FlipTarget::H0,
                4 => FlipTarget::H1,
                _ => FlipTarget::Slot(s % cfg.slots),
            };
            if let Some(f) = frame_flip(&clean, n, c, hop % n + 1, target, bit) {
                cfg.faults.push(f);
            }
        }
        if let Some((j, bit)) = rtx_hit {
            cfg.faults.push((
                c,
                Fault::Flip {
                    fibre: Fibre::P(1 % n),
                    target: FlipTarget::Rtx(j),
                    bit,
                },
            ));
        }
        let with = ring::run(&cfg);
        let plain = ring::run(&without_rtx(&cfg));
        let reference = ring::run(&without_flips(&cfg));
        let cu = c as usize;
        // The retransmission raises no Alive alarm of its own.
        let lost = |recs: &[CycleRecord]| -> Vec<(u32, usize, usize)> {
            recs.iter()
                .flat_map(|r| &r.events)
                .filter_map(|e| match e.kind {
                    EventKind::AliveLost { slot } => Some((e.cycle, e.node, slot)),
                    _ => None,
                })
                .collect()
        };
        let extra: Vec<_> = lost(&with)
            .into_iter()
            .filter(|x| !lost(&plain).contains(x))
            .collect();
        prop_assert!(
            extra.is_empty(),
            "alive-lost only with the retransmission: {extra:?}"
        );
        // Never older with the retransmission than without it.
        for cc in cu..with.len() {
            let (a, b) = (age_map(&cfg, &with[cc]), age_map(&cfg, &plain[cc]));
            for (key, age) in &a {
                prop_assert!(
                    age.unwrap_or(u32::MAX) <= b[key].unwrap_or(u32::MAX),
                    "cycle {cc} copy {key:?}: {age:?} with, {:?} without",
                    b[key]
                );
            }
        }
        // A request that came back good: every copy behind the writer (the
        // special master's too: it reads the frame as it returns) as young
        // as without the errors in this cycle, and every copy in the next
        // one. Copies between the special master and the writer may be a
        // cycle older in this one: an error there damages the previous
        // cycle's copy the special master retransmits, and the writer
        // overwrites the word, so nobody can see it (protocol §8).
        if let Some(x) = &with[cu].rtx {
            if x.back.contains(&true) {
                repaired.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            }
            let path = &with[cu].path;
            for (i, &s) in x.slots.iter().enumerate() {
                let Some(pw) = path.iter().position(|&k| k == cfg.writer[s]) else {
                    continue;
                };
                if !x.back[i] {
                    continue;
                }
                let upstream = &path[1.min(pw)..pw];
                let now: Vec<usize> = older(&cfg, &with, &reference, cu, s)
                    .into_iter()
                    .filter(|k| !upstream.contains(k))
                    .collect();
                prop_assert!(
                    now.is_empty(),
                    "slot {s}: nodes {now:?} older in cycle {cu}"
                );
                let next = older(&cfg, &with, &reference, cu + 1, s);
                prop_assert!(
                    next.is_empty(),
                    "slot {s}: nodes {next:?} older in cycle {}",
                    cu + 1
                );
            }
        }
        Ok(())
    });
    if let Err(e) = r {
        panic!("{e} (MERKUR_SEED={seed})");
    }
    let n = repaired.into_inner();
    assert!(
        n >= 40,
        "only {n} of 200 cases repaired a copy (MERKUR_SEED={seed})"
    );
}
