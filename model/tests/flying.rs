//! The flying special master (protocol §8, issue 22): when the clock base
//! dies, the eligible backup of the lowest priority takes over one cycle
//! after the first frame that did not come; every other backup stands
//! down; no node fails safe; every master's memory and every actuator's
//! output equal the fault-free ring's (except what the dead node wrote)
//! from the end of the recovery window on. After a first fault the clock
//! base's death is a second fault: failsafe, no takeover.
//!
//! Seeded like the property tests (MERKUR_SEED; printed on failure).

mod common;
use common::*;
use merkur_model::config::{Config, SlotKind};
use merkur_model::ring::{self, CycleRecord, EventKind};
use merkur_model::scenario::Kind;
use proptest::prelude::*;

/// Every takeover: (cycle, node, priority).
fn takeovers(recs: &[CycleRecord]) -> Vec<(u32, usize, u8)> {
    recs.iter()
        .flat_map(|r| &r.events)
        .filter_map(|e| match e.kind {
            EventKind::Takeover { prio } => Some((e.cycle, e.node, prio)),
            _ => None,
        })
        .collect()
}

/// `kinds` with `backup = p` added to the masters in `prios` (node, p), and
/// the special master killed in cycle `c` (before `slot`, or its J K).
fn flying_text(kinds: &[&str], prios: &[(usize, u8)], c: u32, slot: Option<u32>) -> String {
    let sm = kinds.iter().position(|k| *k == "special_master").unwrap();
    let slot = slot.map(|s| format!("slot = {s}\n")).unwrap_or_default();
    let t = ring_text(
        kinds,
        c + 10,
        &format!("\n[[fault]]\nkind = \"kill\"\ncycle = {c}\n{slot}node = {sm}\n"),
    );
    with_backups(t, prios)
}

/// The checks every single death of the clock base must pass; `Err` names
/// what failed.
fn check_takeover(cfg: &Config, c: u32, slot: Option<u32>) -> Result<(), String> {
    let a = ring::run(cfg);
    let t = takeovers(&a);
    let first = cfg.backups()[0];
    // The first frame that does not come: cycle c, or c + 1 when the
    // clock base dies inside frame c (its start went round).
    let missing = c + u32::from(slot.is_some());
    let want = (missing + u32::from(first.1), first.0, first.1);
    if t != vec![want] {
        return Err(format!("takeovers {t:?}, expected [{want:?}]"));
    }
    for r in &a {
        if let Some(k) = r.nodes.iter().position(|x| x.failsafe) {
            return Err(format!("cycle {}: node {k} in failsafe", r.cycle));
        }
    }
    let end = ring::windows(cfg, &a)
        .iter()
        .map(|w| w.1)
        .max()
        .unwrap_or(0);
    path_ages_hold(cfg, &a, end + 1)?;
    // The rule holds in the fault-free ring from its second cycle.
    let mut clean = cfg.clone();
    clean.faults.clear();
    path_ages_hold(&clean, &ring::run(&clean), 2).map_err(|e| format!("fault-free: {e}"))
}

/// From cycle `from` on, every living master's copy of every slot that a
/// living node writes, and every living actuator's output, hold the
/// writer's value of the same cycle when the writer comes before the reader
/// on that cycle's path (from the clock base; the clock base reads the
/// frame as it returns), and of the cycle before otherwise (§7, §8). This
/// is the fault-free ring's promise for the ring as it now is: the clock
/// base moved, so some slots are a cycle younger or older at some readers
/// than in the ring before the death.
fn path_ages_hold(cfg: &Config, recs: &[CycleRecord], from: u32) -> Result<(), String> {
    let dead = cfg.killed();
    for r in recs.iter().filter(|r| r.cycle >= from) {
        let pos = |k: usize| r.path.iter().position(|&x| x == k);
        let value = |w: usize, k: usize, s: usize| {
            let age = match (pos(w), pos(k)) {
                (Some(pw), Some(pk)) if pk == 0 || pw < pk => 0,
                _ => 1,
            };
            recs[(r.cycle - age) as usize].produced[s]
        };
        for (k, st) in r.nodes.iter().enumerate() {
            if dead.contains(&k) {
                continue;
            }
            let check = |s: usize, got: u16| {
                let w = cfg.writer[s];
                let act_dead = matches!(cfg.slot_kind[s], SlotKind::Act { actuator } if dead.contains(&actuator));
                if w == k || dead.contains(&w) || act_dead {
                    return Ok(());
                }
                let want = value(w, k, s);
                if got == want {
                    Ok(())
                } else {
                    Err(format!(
                        "cycle {}: node {k} has {got:04x} in slot {s}, its writer node {w} gives {want:04x} (path {:?})",
                        r.cycle, r.path
                    ))
                }
            };
            match cfg.nodes[k].kind {
                Kind::Actuator => check(cfg.nodes[k].address, st.output)?,
                Kind::Master | Kind::SpecialMaster => {
                    for (s, &x) in st.db.iter().enumerate() {
                        check(s, x)?;
                    }
                }
                Kind::Sensor => {}
            }
        }
    }
    Ok(())
}

#[test]
fn every_priority_order_on_8_nodes() {
    let kinds = [
        "special_master",
        "sensor",
        "master",
        "actuator",
        "master",
        "sensor",
        "master",
        "actuator",
    ];
    let masters = [2usize, 4, 6];
    let orders = [
        [1u8, 2, 3],
        [1, 3, 2],
        [2, 1, 3],
        [2, 3, 1],
        [3, 1, 2],
        [3, 2, 1],
    ];
    for order in orders {
        let prios: Vec<(usize, u8)> = masters.iter().copied().zip(order).collect();
        for c in [3u32, 4] {
            for slot in [None, Some(0), Some(4)] {
                let text = flying_text(&kinds, &prios, c, slot);
                let cfg = load(&text);
                if let Err(e) = check_takeover(&cfg, c, slot) {
                    panic!("priorities {prios:?}, kill in cycle {c} slot {slot:?}: {e}\n{text}");
                }
                // Not an empty check: in the takeover's own frame the slots
                // of sensor 1 (written after every master on the new path)
                // are VOID at the masters, which keep older values.
                let recs = ring::run(&cfg);
                let t = takeovers(&recs)[0].0;
                assert!(
                    path_ages_hold(&cfg, &recs, t).is_err(),
                    "{prios:?}, {c}, {slot:?}: the takeover frame passes the age check"
                );
            }
        }
    }
}

#[test]
fn sampled_rings_of_up_to_100_nodes() {
    let (mut r, s) = runner(64);
    let strat = (
        prop::sample::select(vec![8usize, 32, 100]),
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        any::<u64>(),
        3u32..6,
        prop::option::of(0u32..4),
    );
    let res = r.run(&strat, |(n, smr, pick, shuffle, c, slot)| {
        let sm = smr % n;
        let mut kinds = kinds(n, sm, &pick);
        // At least one master besides the special master.
        let m = (sm + 1 + (shuffle as usize % (n - 1))) % n;
        kinds[m] = "master";
        let masters: Vec<usize> = (0..n).filter(|&k| kinds[k] == "master").collect();
        // Up to three backups, priorities 1..=k in a shuffled order.
        let nb = masters.len().min(1 + (shuffle >> 8) as usize % 3);
        let mut prios: Vec<(usize, u8)> = (0..nb)
            .map(|i| {
                (
                    masters[(i * 7 + (shuffle >> 16) as usize) % masters.len()],
                    0,
                )
            })
            .collect();
        prios.sort();
        prios.dedup();
        let mut order: Vec<u8> = (1..=prios.len() as u8).collect();
        let turn = (shuffle >> 24) as usize % order.len();
        order.rotate_left(turn);
        for (p, o) in prios.iter_mut().zip(order) {
            p.1 = o;
        }
        let text = flying_text(&kinds, &prios, c, slot);
        let cfg = load(&text);
        let res = check_takeover(&cfg, c, slot);
        prop_assert!(res.is_ok(), "{}\n{text}", res.unwrap_err());
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

/// A fibre break first (the ring knows it is wrapped), then the special
/// master's death: two faults. No backup takes over, and every living
/// node is in failsafe once the CS timeout has run out (§8, §12 rule 4).
#[test]
fn the_clock_base_dying_after_a_break_is_a_second_fault() {
    let kinds = [
        "special_master",
        "sensor",
        "master",
        "actuator",
        "master",
        "sensor",
    ];
    let c = 7;
    let mut text = flying_text(&kinds, &[(2, 1), (4, 2)], c, None);
    text += "\n[[fault]]\nkind = \"break\"\ncycle = 3\nfibre = \"P3\"\n";
    let cfg = load(&text);
    let recs = ring::run(&cfg);
    assert_eq!(takeovers(&recs), vec![], "{text}");
    let from = (c + cfg.cs_timeout_cycles()) as usize;
    for r in &recs[from..] {
        for (k, st) in r.nodes.iter().enumerate() {
            assert!(!st.up || st.failsafe, "cycle {}: node {k}\n{text}", r.cycle);
        }
    }
}

/// The CS timeout grows with the highest priority, so that the last
/// backup's slot comes before it (§8).
#[test]
fn the_cs_timeout_covers_the_last_priority() {
    let kinds = ["special_master", "master", "sensor", "master"];
    let cfg = load(&flying_text(&kinds, &[(1, 1), (3, 5)], 3, None));
    assert_eq!(cfg.cs_timeout_cycles(), 7);
    let cfg = load(&ring_text(&kinds, 5, ""));
    assert_eq!(cfg.cs_timeout_cycles(), ring::CS_TIMEOUT_CYCLES);
}

/// The starter scenarios (tb-data/ring8_sm_kill.toml, ring100_sm_kill.toml)
/// pass the same checks.
#[test]
fn the_starter_scenarios() {
    for (name, c) in [("ring8_sm_kill", 4), ("ring100_sm_kill", 3)] {
        let path = format!("{}/../tb-data/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        let cfg = merkur_model::config::load(&path, &text).unwrap();
        if let Err(e) = check_takeover(&cfg, c, None) {
            panic!("{name}: {e}");
        }
    }
}

/// The other order: the special master dies, a backup takes over, then a
/// fibre breaks (the second fault: failsafe everywhere), and the break is
/// repaired: the new clock base brings the ring out of failsafe by the
/// exit of §12, with the HOP reference it learnt from its own frames.
#[test]
fn a_break_after_the_takeover_fails_safe_and_the_new_base_heals_it() {
    let kinds = [
        "special_master",
        "sensor",
        "master",
        "actuator",
        "master",
        "sensor",
        "sensor",
    ];
    let mut text = flying_text(&kinds, &[(2, 1), (4, 2)], 3, None);
    text += "\n[[fault]]\nkind = \"break\"\ncycle = 8\nfibre = \"P4\"\n";
    text += "\n[[fault]]\nkind = \"repair\"\ncycle = 12\nfibre = \"P4\"\n";
    text = text.replace("cycles = 13", "cycles = 30");
    let cfg = load(&text);
    let recs = ring::run(&cfg);
    assert_eq!(takeovers(&recs), vec![(4, 2, 1)], "{text}");
    let fs_at = |c: usize| recs[c].nodes.iter().filter(|x| x.up && x.failsafe).count();
    assert!(
        fs_at(11) > 0,
        "the break after the takeover is a second fault\n{text}"
    );
    let last = recs.last().unwrap();
    assert!(
        last.nodes.iter().all(|x| !x.failsafe),
        "the new clock base brings the ring out of failsafe\n{text}"
    );
    assert!(
        recs.iter()
            .flat_map(|r| &r.events)
            .any(|e| e.node == 2 && matches!(e.kind, EventKind::FailsafeExit)),
        "{text}"
    );
}

/// No false election (§8). The model elects only when the clock base is
/// dead; what keeps the RTL's timers from electing a second clock base is
/// the margin the spec claims: under a single structural fault that is not
/// the clock base's death, with bit errors on top (up to 8 flips, on any
/// fibre, in the J K, a header word or a slot), no living backup of
/// priority p ever goes more than p cycles without a packet (or a frame's
/// body) on its INPUT, so its timer of (1.5 + p) periods never expires.
#[test]
fn no_backup_takes_over_while_the_clock_base_lives() {
    let (mut r, s) = runner(64);
    let strat = (
        (3usize..=100, any::<usize>()),
        prop::collection::vec(0u8..3, 1..16),
        (0u8..4, any::<usize>(), 3u32..6),
        prop::collection::vec((any::<u32>(), any::<u32>(), 0u8..4, 0u32..25), 0..8),
    );
    let res = r.run(&strat, |((n, smr), pick, (fk, pos, c), flips)| {
        let sm = smr % n;
        let mut kinds = kinds(n, sm, &pick);
        let m = (sm + 1 + pos % (n - 1)) % n;
        kinds[m] = "master";
        let masters: Vec<usize> = (0..n).filter(|&k| kinds[k] == "master").collect();
        let prios: Vec<(usize, u8)> = masters.iter().take(3).copied().zip(1u8..).collect();
        // A structural fault (0 break P, 1 break S, 2 kill) or none (3).
        let mut extra = String::new();
        match fk {
            0 | 1 => {
                let f = if fk == 0 { "P" } else { "S" };
                extra += &format!(
                    "\n[[fault]]\nkind = \"break\"\ncycle = {c}\nfibre = \"{f}{}\"\n",
                    pos % n
                );
            }
            2 => {
                let mut node = pos % n;
                if node == sm {
                    node = (node + 1) % n;
                }
                extra += &format!("\n[[fault]]\nkind = \"kill\"\ncycle = {c}\nnode = {node}\n");
            }
            _ => {}
        }
        let cycles = c + 12;
        let mut flipped = std::collections::BTreeSet::new();
        for (fc, ff, t, bit) in flips {
            let cyc = 1 + fc % (cycles - 1);
            let fibre = if ff % 2 == 0 { "P" } else { "S" };
            let fibre = format!("{fibre}{}", (ff / 2) as usize % n);
            // One flip per fibre and cycle.
            if !flipped.insert((cyc, fibre.clone())) {
                continue;
            }
            let target = match t {
                0 => format!("word = \"cs\"\nbit = {}", 2 + bit % 8),
                1 => format!("word = \"h0\"\nbit = {bit}"),
                2 => format!("word = \"h1\"\nbit = {bit}"),
                _ => format!("slot = {}\nbit = {bit}", bit as usize % n),
            };
            extra += &format!(
                "\n[[fault]]\nkind = \"flip\"\ncycle = {cyc}\nfibre = \"{fibre}\"\n{target}\n"
            );
        }
        let text = with_backups(ring_text(&kinds, cycles, &extra), &prios);
        let cfg = load(&text);
        let recs = ring::run(&cfg);
        prop_assert!(takeovers(&recs).is_empty(), "a backup took over\n{text}");
        for r in &recs {
            for &(k, p) in &prios {
                let q = r.nodes[k].quiet;
                prop_assert!(
                    !r.nodes[k].up || q <= u32::from(p),
                    "cycle {}: backup {k} (priority {p}) quiet for {q} cycles\n{text}",
                    r.cycle
                );
            }
        }
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

/// Two frames in a row whose J K a bit error destroyed just upstream of the
/// priority-1 backup: it sees the frames' bodies, so its election timer
/// does not run (a timer on start delimiters would have been quiet for two
/// cycles, past its slot, §8).
#[test]
fn lost_start_delimiters_do_not_start_the_election_timer() {
    let kinds = ["special_master", "sensor", "master", "sensor", "sensor"];
    // The clock base lives.
    let mut text = with_backups(ring_text(&kinds, 10, ""), &[(2, 1)]);
    for c in [4, 5] {
        text += &format!(
            "\n[[fault]]\nkind = \"flip\"\ncycle = {c}\nfibre = \"P1\"\nword = \"cs\"\nbit = 4\n"
        );
    }
    let cfg = load(&text);
    let recs = ring::run(&cfg);
    for c in [4usize, 5] {
        assert_eq!(recs[c].nodes[2].quiet, 0, "cycle {c}\n{text}");
        assert_eq!(
            recs[c].nodes[2].no_cs,
            (c - 3) as u32,
            "the J K is gone\n{text}"
        );
    }
    assert!(takeovers(&recs).is_empty());
}
