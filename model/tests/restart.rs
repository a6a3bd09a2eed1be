//! Restart and rejoin (protocol §12, issue 22): a dead node that gets power
//! again comes back link by link through the TST handshake, without
//! failsafe; a restarted master reloads its memory from the ring before it
//! writes; from the end of the recovery window every memory and output is
//! the fault-free ring's again — except a restarted master's own LOCAL
//! slots that the ring no longer carried (VOID), which keep their value at
//! every other master and wait for its host.
//!
//! Seeded like the property tests (MERKUR_SEED; printed on failure).

mod common;
use common::*;
use merkur_model::config::{Config, Fault, SlotKind};
use merkur_model::ring::{self, CycleRecord, EventKind, Mode};
use merkur_model::scenario::Kind;
use proptest::prelude::*;

/// Nodes restarted in the run.
fn restarted(cfg: &Config) -> Vec<usize> {
    cfg.faults
        .iter()
        .filter_map(|(_, f)| match f {
            Fault::Restart { node } => Some(*node),
            _ => None,
        })
        .collect()
}

/// What the ring delivers, per (node, slot), for the comparison with the
/// fault-free ring: every master's memory and actuator's output, but a
/// restarted master's own LOCAL slots at that master (their value came
/// back only if the ring still carried it; its host writes them again).
fn delivered_after_restart(cfg: &Config, r: &CycleRecord) -> Vec<((usize, usize), u16)> {
    let back = restarted(cfg);
    let mut v = vec![];
    for (k, st) in r.nodes.iter().enumerate() {
        match cfg.nodes[k].kind {
            Kind::Actuator => v.push(((k, cfg.nodes[k].address), st.output)),
            Kind::Master | Kind::SpecialMaster => {
                for (s, &x) in st.db.iter().enumerate() {
                    let own_local = cfg.writer[s] == k && cfg.slot_kind[s] == SlotKind::Local;
                    if !(back.contains(&k) && own_local) {
                        v.push(((k, s), x));
                    }
                }
            }
            Kind::Sensor => {}
        }
    }
    v
}

/// The checks every restart must pass; `Err` names what failed.
fn check_rejoin(cfg: &Config) -> Result<(), String> {
    let recs = ring::run(cfg);
    let mut clean = cfg.clone();
    clean.faults.clear();
    let base = ring::run(&clean);
    for r in &recs {
        if let Some(k) = r.nodes.iter().position(|x| x.failsafe) {
            return Err(format!("cycle {}: node {k} in failsafe", r.cycle));
        }
    }
    let last = recs.last().unwrap();
    if let Some(k) = last.nodes.iter().position(|x| !x.up || x.mode != Mode::N) {
        return Err(format!("node {k} not back (up, mode N) at the end"));
    }
    // Only the restarted node and its two neighbours miss frames while it
    // rejoins (the WU end of each link loses the frame it unwraps at, §12);
    // the ring stays closed for everybody else.
    let n = cfg.nodes.len();
    let dead = cfg.killed();
    for (i, (c, f)) in cfg.faults.iter().enumerate() {
        let Fault::Restart { node } = *f else {
            continue;
        };
        let spared = [(node + n - 1) % n, node, (node + 1) % n];
        let till = cfg.faults.get(i + 1).map_or(cfg.cycles, |x| x.0);
        for r in &recs[*c as usize..till as usize] {
            let missing: Vec<usize> = (0..n)
                .filter(|k| !spared.contains(k) && !dead.contains(k) && !r.path.contains(k))
                .collect();
            if !missing.is_empty() {
                return Err(format!(
                    "cycle {}: nodes {missing:?} got no frame while node {node} rejoined",
                    r.cycle
                ));
            }
        }
    }
    let end = ring::windows(cfg, &recs)
        .iter()
        .map(|w| w.1)
        .max()
        .unwrap_or(0);
    for (a, b) in recs.iter().zip(&base).filter(|(a, _)| a.cycle > end) {
        let (x, y) = (
            delivered_after_restart(cfg, a),
            delivered_after_restart(cfg, b),
        );
        if x != y {
            let diff: Vec<_> = x.iter().zip(&y).filter(|(p, q)| p != q).collect();
            return Err(format!(
                "cycle {} (windows end {end}): (faulty, fault-free) {diff:?}",
                a.cycle
            ));
        }
    }
    Ok(())
}

#[test]
fn the_starter_scenario_rejoins_a_slave_and_a_master() {
    let path = format!(
        "{}/../tb-data/ring8_restart.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let cfg = merkur_model::config::load(&path, &text).unwrap();
    if let Err(e) = check_rejoin(&cfg) {
        panic!("{e}");
    }
    // The restarted master's memory is the ring's after its reload, but
    // for its LOCAL slot 9, which the ring lost (VOID) and its host writes
    // again in cycle 30; the actuator slot 7 it serves came back from the
    // ring (the actuator's output).
    let recs = ring::run(&cfg);
    let at = |c: usize| &recs[c].nodes[3].db;
    assert_eq!(at(26)[7], 0x0707);
    assert_eq!(at(29)[9], 0x0000);
    assert_eq!(at(30)[9], 0x3030);
    assert_eq!(recs[29].nodes[0].db[9], 0x9999, "the others kept the value");
}

#[test]
fn sampled_restarts_of_slaves_and_masters() {
    let (mut r, s) = runner(64);
    let strat = (
        3usize..=100,
        any::<usize>(),
        prop::collection::vec(0u8..3, 1..16),
        any::<usize>(),
        3u32..6,
        3u32..7,
        prop::option::of(0u32..3),
    );
    let res = r.run(&strat, |(n, smr, pick, pos, c, gap, slot)| {
        let sm = smr % n;
        let mut node = pos % n;
        if node == sm {
            node = (node + 1) % n;
        }
        let slot = slot.map(|x| format!("slot = {x}\n")).unwrap_or_default();
        let back = c + gap;
        let text = ring_text(
            &kinds(n, sm, &pick),
            back + 14,
            &format!(
                "\n[[fault]]\nkind = \"kill\"\ncycle = {c}\n{slot}node = {node}\n\
                 \n[[fault]]\nkind = \"restart\"\ncycle = {back}\nnode = {node}\n"
            ),
        );
        let cfg = load(&text);
        let res = check_rejoin(&cfg);
        prop_assert!(res.is_ok(), "{}\n{text}", res.unwrap_err());
        Ok(())
    });
    if let Err(e) = res {
        panic!("MERKUR_SEED={s}: {e}");
    }
}

/// The special master dies, a backup takes over, the special master gets
/// power again: it rejoins as a master and never starts a clock base (§8,
/// §12).
#[test]
fn a_restarted_special_master_rejoins_as_a_master() {
    let kinds = [
        "special_master",
        "sensor",
        "master",
        "actuator",
        "sensor",
        "sensor",
    ];
    let text = with_backups(
        ring_text(
            &kinds,
            24,
            "\n[[fault]]\nkind = \"kill\"\ncycle = 3\nnode = 0\n\
             \n[[fault]]\nkind = \"restart\"\ncycle = 9\nnode = 0\n",
        ),
        &[(2, 1)],
    );
    let cfg = load(&text);
    let recs = ring::run(&cfg);
    let takeovers: Vec<(u32, usize)> = recs
        .iter()
        .flat_map(|r| &r.events)
        .filter(|e| matches!(e.kind, EventKind::Takeover { .. }))
        .map(|e| (e.cycle, e.node))
        .collect();
    assert_eq!(takeovers, vec![(4, 2)], "{text}");
    let last = recs.last().unwrap();
    assert_eq!(last.base, 2, "{text}");
    assert_eq!(last.path.first(), Some(&2), "{text}");
    assert!(
        last.path.contains(&0),
        "the old special master forwards: {text}"
    );
    for r in &recs {
        assert!(
            r.nodes.iter().all(|x| !x.failsafe),
            "cycle {}\n{text}",
            r.cycle
        );
    }
    assert!(last.nodes.iter().all(|x| x.mode == Mode::N), "{text}");
}
