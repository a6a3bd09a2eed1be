//! The IEEE 802.4 DCM + RMM (`merkur_dcm_station`) in Verilator against the
//! reference model, in closed loop with the model's token bus: every
//! token-bus scenario in tb-data/ (every state and transition of the fault
//! correction machine is reached, see `every_transition_is_reached`), every
//! output of every station in every octet.

use merkur_model::rmm::{cause, state, RmmOut};
use merkur_model::tbconfig::TbConfig;
use merkur_sim::dcm_sim::{self, Options, Report, Scenario};
use std::collections::BTreeSet;
use std::sync::OnceLock;

/// Every token-bus scenario of tb-data/, each run once through the RTL for
/// all the tests of this file.
fn runs() -> &'static [(Scenario, Report)] {
    static RUNS: OnceLock<Vec<(Scenario, Report)>> = OnceLock::new();
    RUNS.get_or_init(|| {
        let v: Vec<(Scenario, Report)> = dcm_sim::scenarios()
            .unwrap()
            .into_iter()
            .map(|s| {
                let r = dcm_sim::run(&s.cfg, &Options::default())
                    .unwrap_or_else(|e| panic!("{}: {e}", s.name));
                (s, r)
            })
            .collect();
        assert!(v.len() >= 9, "token-bus scenarios present: {}", v.len());
        v
    })
}

#[test]
fn every_token_bus_scenario_agrees_with_the_model_octet_for_octet() {
    let mut failed = vec![];
    for (s, r) in runs() {
        let name = &s.name;
        println!(
            "{name}: {} station-octets compared in {:.2} s, {} mismatches",
            r.compared,
            r.wall.as_secs_f64(),
            r.mismatches.len()
        );
        assert!(r.compared >= s.cfg.ticks, "{name}: nothing compared");
        // The RTL run, written as a trace, is the committed golden trace.
        let mine = merkur_model::tokenbus::render(&s.cfg, &s.text, &r.rtl);
        if let Some(line) = merkur_model::trace::first_difference(&mine, &s.golden().unwrap()) {
            failed.push(format!(
                "{name}: the RTL's trace differs from the golden trace at line {line}"
            ));
        }
        if let Some(m) = r.mismatches.first() {
            failed.push(format!(
                "{name}: {} mismatches, first {m}",
                r.mismatches.len()
            ));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// One scenario's RTL run; panics with its first mismatch.
fn rtl(name: &str) -> (&'static TbConfig, &'static Report) {
    let (s, r) = runs()
        .iter()
        .find(|(s, _)| s.name == format!("tb-data/{name}.toml"))
        .unwrap_or_else(|| panic!("no scenario {name}"));
    assert!(
        r.mismatches.is_empty(),
        "{name}: {}",
        r.mismatches.first().unwrap()
    );
    (&s.cfg, r)
}

/// (from, to, cause) of every transition and command report in a run.
fn transitions(outs: &[Vec<Option<RmmOut>>]) -> BTreeSet<(u8, u8, u8)> {
    let mut s = BTreeSet::new();
    for st in outs {
        for w in st.windows(2) {
            if let (Some(p), Some(o)) = (w[0], w[1]) {
                let report = o.irq && (o.cause != p.cause || o.stale & !p.stale == 0);
                if p.state != o.state || report {
                    s.insert((p.state, o.state, o.cause));
                }
            }
        }
    }
    s
}

#[test]
fn every_transition_is_reached_in_rtl() {
    // docs/protocol.md §21. Auto_Normal and Medium_Error never go to IDLE
    // directly: both channels are latched bad one octet after their faults,
    // and in that octet Auto_Normal has already left for Manual_Normal
    // (standby fault) and Medium_Error always leaves after one octet.
    let want: BTreeSet<(u8, u8, u8)> = [
        (state::IDLE, state::MANUAL_NORMAL, cause::INIT),
        (state::MANUAL_NORMAL, state::MANUAL_NORMAL, cause::CMD_RX),
        (state::MANUAL_NORMAL, state::AUTO_NORMAL, cause::CHECK_OK),
        (state::MANUAL_NORMAL, state::AUTO_NORMAL, cause::AUTO_CMD),
        (state::MANUAL_NORMAL, state::MANUAL_NORMAL, cause::CHECK_SW),
        (state::MANUAL_NORMAL, state::IDLE, cause::BOTH),
        (state::AUTO_NORMAL, state::MEDIUM_ERROR, cause::ACTIVE_FAULT),
        (state::AUTO_NORMAL, state::MEDIUM_ERROR, cause::NS),
        (
            state::AUTO_NORMAL,
            state::MANUAL_NORMAL,
            cause::STANDBY_FAULT,
        ),
        (state::AUTO_NORMAL, state::CONFIG_ERROR, cause::SC),
        (state::AUTO_NORMAL, state::MANUAL_NORMAL, cause::CMD_RX),
        (state::AUTO_NORMAL, state::MANUAL_NORMAL, cause::CHECK_SW),
        (state::MEDIUM_ERROR, state::MANUAL_NORMAL, cause::SWITCHED),
        (state::CONFIG_ERROR, state::MANUAL_NORMAL, cause::CMD_RX),
        (state::CONFIG_ERROR, state::MANUAL_NORMAL, cause::CMD_SENT),
        (state::CONFIG_ERROR, state::IDLE, cause::BOTH),
    ]
    .into_iter()
    .collect();
    let mut got = BTreeSet::new();
    for (s, r) in runs() {
        assert!(r.mismatches.is_empty(), "{}: {}", s.name, r.mismatches[0]);
        got.extend(transitions(&r.rtl.outs));
    }
    let name = |t: &(u8, u8, u8)| {
        format!(
            "{} -> {} ({})",
            state::name(t.0),
            state::name(t.1),
            cause::name(t.2)
        )
    };
    let missing: Vec<String> = want.difference(&got).map(name).collect();
    let unknown: Vec<String> = got.difference(&want).map(name).collect();
    assert!(
        missing.is_empty(),
        "transitions no scenario reaches: {missing:?}"
    );
    assert!(
        unknown.is_empty(),
        "transitions outside the table: {unknown:?}"
    );
}

#[test]
fn single_channel_faults_in_auto_normal_lose_no_frame() {
    for name in [
        "dcm8_active_short",
        "dcm8_standby_open",
        "dcm8_drop_active",
        "dcm8_noise",
    ] {
        let (cfg, r) = rtl(name);
        let first = cfg.events[0].at;
        // Every station is in Auto_Normal when the first fault strikes.
        for (k, o) in r.rtl.outs.iter().enumerate() {
            let o = o[first as usize].expect("powered");
            assert_eq!(
                o.state,
                state::AUTO_NORMAL,
                "{name}: station {k} at the fault"
            );
        }
        assert!(r.rtl.frames_sent > 100, "{name}: traffic");
        assert_eq!(r.rtl.receptions_lost, 0, "{name}: frames lost");
    }
    // 32 stations at 5 Mbit/s: the drop cable fault loses nothing either
    // (the station death after it loses the frame the station was sending).
    let (cfg, r) = rtl("dcm32_drop");
    let first = cfg.events[0].at as usize;
    assert!(r
        .rtl
        .outs
        .iter()
        .all(|o| o[first].unwrap().state == state::AUTO_NORMAL));
    assert_eq!(
        r.rtl.lost_by_fault[0], 0,
        "dcm32_drop: frames lost to the drop cable fault"
    );
    assert_eq!(
        r.rtl.switch_latency(0).map(|s| s.2),
        Some(32),
        "every station switched"
    );
    // The same kind of fault with dual mode off does lose frames: the test
    // above is not blind.
    let (_, r) = rtl("dcm8_manual");
    assert!(r.rtl.receptions_lost > 100, "{}", r.rtl.receptions_lost);
}

#[test]
fn with_dual_mode_off_the_status_check_switches_every_station() {
    // docs/protocol.md §20 Status Check = SWITCH, in RTL: the intermittent
    // fault raises no MAC event and every live station (7 of 8) switches;
    // the bursts after the last switch lose nothing.
    let (cfg, r) = rtl("dcm8_status_switch");
    assert_eq!(
        r.rtl.switch_latency(1).map(|s| s.2),
        Some(7),
        "every live station switched"
    );
    let last = r.rtl.switches[1].iter().map(|x| x.1).max().unwrap() + cfg.events[1].at;
    for (f, e) in cfg.events.iter().enumerate().filter(|(_, e)| e.at > last) {
        assert_eq!(r.rtl.lost_by_fault[f], 0, "burst at {}", e.at);
    }
    assert!(r
        .rtl
        .outs
        .iter()
        .flatten()
        .flatten()
        .any(|o| o.chk_sw && !o.chk_ok));
}

#[test]
fn a_fault_of_both_channels_reaches_idle_and_the_repair_auto_normal() {
    let (cfg, r) = rtl("dcm8_both");
    let repair = cfg.events.iter().map(|e| e.at).max().unwrap() as usize;
    for (k, o) in r.rtl.outs.iter().enumerate() {
        assert!(
            o[..repair].iter().any(|o| o.unwrap().state == state::IDLE),
            "station {k} never reached IDLE"
        );
        assert!(
            o[..repair]
                .iter()
                .rev()
                .take(100)
                .all(|o| o.unwrap().state == state::IDLE),
            "station {k} not in IDLE before the repair"
        );
        assert_eq!(
            o.last().unwrap().unwrap().state,
            state::AUTO_NORMAL,
            "station {k}"
        );
    }
}

#[test]
fn stations_return_to_auto_normal_after_repair() {
    for name in [
        "dcm8_active_short",
        "dcm8_standby_open",
        "dcm8_noise",
        "dcm8_kill",
    ] {
        let (_, r) = rtl(name);
        for (k, o) in r.rtl.outs.iter().enumerate() {
            let last = o.last().unwrap().expect("powered at the end");
            assert_eq!(last.state, state::AUTO_NORMAL, "{name}: station {k}");
            assert_eq!(last.stat_a & 1, 0, "{name}: station {k} channel A");
            assert_eq!(last.stat_b & 1, 0, "{name}: station {k} channel B");
            assert_eq!(last.stale, 0, "{name}: station {k} stale");
        }
        // ... having left it on the way.
        assert!(
            r.rtl
                .outs
                .iter()
                .flatten()
                .flatten()
                .any(|o| o.state == state::MANUAL_NORMAL),
            "{name}"
        );
    }
}

#[test]
fn a_dead_station_is_flagged_stale_by_the_status_check() {
    let (_, r) = rtl("dcm8_kill");
    // Station 3 dies at 5000, restarts at 8000.
    for (k, o) in r.rtl.outs.iter().enumerate() {
        if k == 3 {
            continue;
        }
        assert!(
            o[5000..8000].iter().any(|o| o.unwrap().stale == 1 << 3),
            "station {k} never flagged station 3"
        );
    }
}

#[test]
fn seeded_random_fault_schedules_agree_with_the_model() {
    use merkur_model::tbconfig::{ChanFault, Scheduled, TbEvent};
    use merkur_sim::Rng;
    let seed = Rng::seed(0x0dc3);
    let mut rng = Rng::new(seed);
    for case in 0..16 {
        let n = 3 + rng.below(8) as usize;
        let mut events = vec![];
        let mut at = 3500;
        for _ in 0..1 + rng.below(4) {
            at += 200 + rng.below(2500);
            let c = rng.below(2) == 1;
            let s = rng.below(n as u64) as usize;
            let what = match rng.below(10) {
                0 => TbEvent::Chan(c, ChanFault::Short),
                1 => TbEvent::Chan(c, ChanFault::Open(1 + rng.below(n as u64 - 1) as u8)),
                2 => TbEvent::Chan(c, ChanFault::Drop(s as u8)),
                3 => TbEvent::Chan(c, ChanFault::Noise(1 + rng.below(60) as u32)),
                4 => TbEvent::Chan(c, ChanFault::Repair),
                5 => TbEvent::Kill(s),
                6 => TbEvent::Restart(s),
                7 => TbEvent::Leave(s),
                8 => TbEvent::Babble(s, 1 + rng.below(300) as u32),
                _ => TbEvent::Auto(Some(s)),
            };
            events.push(Scheduled { at, what });
        }
        let cfg = TbConfig {
            name: format!("random{case}"),
            stations: n,
            ticks: at + 3000,
            rate_mbps: 10.0,
            data_len: 2 + rng.below(8) as usize,
            sf_period: 200 + rng.below(100) as u16,
            check_period: 1000 + rng.below(500) as u16,
            good_limit: 500 + rng.below(2000) as u16,
            events,
        };
        let r = dcm_sim::run(&cfg, &Options::default()).unwrap();
        assert!(
            r.mismatches.is_empty(),
            "seed {seed} (MERKUR_SEED={seed}) case {case} {cfg:?}: {} mismatches, first {}",
            r.mismatches.len(),
            r.mismatches[0]
        );
    }
}
