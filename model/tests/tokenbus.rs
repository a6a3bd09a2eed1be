//! The token-bus model (docs/protocol.md Part II): ring formation, the MAC
//! events real faults raise, frame format, scenario validation.

use merkur_model::rmm::sym;
use merkur_model::tbconfig;
use merkur_model::tokenbus::{self, fc, Change};

fn load(name: &str) -> tbconfig::TbConfig {
    let p = format!("{}/../tb-data/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&p).unwrap();
    tbconfig::load(&p, &text).unwrap_or_else(|e| panic!("{e}"))
}

fn events<'a>(ch: &'a [Change], what: &str) -> Vec<&'a Change> {
    ch.iter()
        .filter(|c| c.what == format!("mac {what}"))
        .collect()
}

#[test]
fn the_logical_ring_forms_in_descending_address_order() {
    let cfg = load("dcm8_normal");
    let r = tokenbus::run(&cfg);
    // One claim winner, the highest address; every other station joins by
    // answering a solicit_successor of its upper neighbour (hear_successor).
    let won = events(&r.changes, "won_contention");
    assert_eq!(won.len(), 1);
    assert_eq!(won[0].station, 7);
    let heard: Vec<usize> = events(&r.changes, "hear_successor")
        .iter()
        .map(|c| c.station)
        .collect();
    assert_eq!(heard, vec![7, 6, 5, 4, 3, 2, 1]);
    assert!(events(&r.changes, "initialize").len() == 8);
    assert!(r.frames_sent > 300);
    assert_eq!(r.receptions_lost, 0);
    assert_eq!(r.receptions_expected, r.frames_sent * 7);
}

#[test]
fn a_dead_station_makes_its_predecessor_find_a_new_successor() {
    let cfg = load("dcm8_kill");
    let r = tokenbus::run(&cfg);
    let ns: Vec<&Change> = events(&r.changes, "new_successor");
    assert_eq!(ns.len(), 1, "{ns:?}");
    assert_eq!(ns[0].station, 4, "station 3's predecessor is 4");
    assert!(ns[0].t > 5000 && ns[0].t < 5200, "{:?}", ns[0]);
    // The restarted station raises initialize and is admitted again.
    assert!(events(&r.changes, "initialize")
        .iter()
        .any(|c| c.station == 3 && c.t > 8000));
    assert!(events(&r.changes, "hear_successor")
        .iter()
        .any(|c| c.station == 4 && c.t > 8000));
}

#[test]
fn a_leaving_station_raises_exit_ring_and_its_predecessor_new_successor() {
    let r = tokenbus::run(&load("dcm8_leave"));
    let exit = events(&r.changes, "exit_ring");
    assert_eq!(exit.len(), 1);
    assert_eq!(exit[0].station, 5);
    assert!(events(&r.changes, "new_successor")
        .iter()
        .any(|c| c.station == 6 && c.t > exit[0].t));
}

#[test]
fn a_silent_bus_makes_the_token_holder_give_up_with_no_successor_8() {
    let r = tokenbus::run(&load("dcm8_both"));
    assert!(!events(&r.changes, "no_successor_8").is_empty());
    // and the stations claim the token again when the bus comes back.
    assert!(events(&r.changes, "won_contention")
        .iter()
        .any(|c| c.t > 5000));
}

#[test]
fn frames_carry_a_checked_sequence() {
    let f = tokenbus::frame(fc::TOKEN, 3, 4, &[]);
    assert_eq!(f.len(), 6);
    assert_eq!(f[0], sym::SD);
    assert_eq!(*f.last().unwrap(), sym::ED);
    let body: Vec<u8> = f[1..f.len() - 1].iter().map(|&s| s as u8).collect();
    assert_eq!(body[..3], [fc::TOKEN, 3, 4]);
    // FCS: complement of the octet sum.
    assert_eq!(body[3], !(fc::TOKEN.wrapping_add(3).wrapping_add(4)));
}

#[test]
fn scenario_defaults_and_event_order() {
    let text = "[token_bus]\nstations = 3\nticks = 500\n\n[[fault]]\nat = 300\nkind = \"kill\"\nstation = 2\n\n[[fault]]\nat = 100\nkind = \"noise\"\nchannel = \"b\"\nduration = 5\n";
    let c = tbconfig::load("x.toml", text).unwrap();
    assert_eq!(c.name, "x");
    assert_eq!((c.rate_mbps, c.data_len), (10.0, 4));
    assert_eq!(
        (c.sf_period, c.check_period, c.good_limit),
        (256, 1024, 2048)
    );
    assert_eq!(c.events[0].at, 100, "events sorted by time");
    assert!((c.tick_us() - 0.8).abs() < 1e-12);
    assert!(tbconfig::is_token_bus(text));
    assert!(!tbconfig::is_token_bus("cycles = 3\n"));
    assert!(!tbconfig::is_token_bus("not toml ["));
}

#[test]
fn scenario_errors_name_the_field_and_where_it_stands() {
    let text = "[token_bus]\nstations = 3\nticks = 500\n\n[[fault]]\nat = 10\nkind = \"open\"\nchannel = \"A\"\nposition = 3\n";
    let e = tbconfig::load("f.toml", text).unwrap_err();
    assert_eq!((e.line, e.col), (9, 12));
    assert!(e.msg.contains("fault.position = 3"), "{}", e.msg);
    let e = tbconfig::load(
        "f.toml",
        "[token_bus]\nstations = 3\nticks = 500\n\n[[fault]]\nat = 10\nkind = \"kill\"\nstation = 1\nduration = 4\n",
    )
    .unwrap_err();
    assert!(e.msg.contains("takes no `duration`"), "{}", e.msg);
    assert_eq!(e.line, 9);
}

#[test]
fn the_status_check_switches_what_no_mac_event_and_no_dual_mode_can() {
    use merkur_model::rmm::{cause, state};
    let cfg = load("dcm8_status_switch");
    let r = tokenbus::run(&cfg);
    let first_burst = cfg.events[1].at;
    // The intermittent fault raises none of the six MAC events.
    let late: Vec<&Change> = r
        .changes
        .iter()
        .filter(|c| c.t >= first_burst && c.what.starts_with("mac "))
        .collect();
    assert!(late.is_empty(), "{late:?}");
    // Every live station (7 died at power-up) switches to B once, in the
    // Manual_Normal the dead station keeps it in (station 1 leaves the
    // Auto_Normal its host asked for), on the status check's own cause.
    let mut switched_at = vec![];
    for (k, outs) in r.outs.iter().enumerate().take(7) {
        let o: Vec<_> = outs.iter().map(|o| o.expect("powered")).collect();
        let sw: Vec<usize> = (1..o.len()).filter(|&t| o[t].act != o[t - 1].act).collect();
        assert_eq!(sw.len(), 1, "station {k} switches {sw:?}");
        let t = sw[0];
        assert!(o[t].act, "station {k} switches to B");
        assert!(t as u64 > first_burst);
        assert_eq!(o[t].state, state::MANUAL_NORMAL, "station {k}");
        let pulse = (0..t).rev().find(|&u| o[u].chk_sw).expect("a SWITCH pulse");
        assert!(
            t - pulse <= 30,
            "station {k}: the switch waits only for the frame's end"
        );
        assert_eq!(o[pulse + 1].cause, cause::CHECK_SW, "station {k}");
        assert!(o[..t]
            .iter()
            .all(|x| x.state != state::AUTO_NORMAL || k == 1));
        switched_at.push((k, pulse));
    }
    // Station 3 did not see the first burst itself: its own channel A was
    // good at its scan, and the switch came from the others' status frames.
    let (_, p3) = switched_at[3];
    let o3 = r.outs[3][p3].unwrap();
    assert_eq!(o3.stat_a & 1, 0, "station 3's own A was good at {p3}");
    assert!(switched_at.iter().all(|&(k, p)| k == 3 || p < p3));
    // After every station has switched, the bursts cost nothing.
    let last = switched_at.iter().map(|x| x.1).max().unwrap() as u64;
    for (f, e) in cfg.events.iter().enumerate() {
        if e.at > last {
            assert_eq!(r.lost_by_fault[f], 0, "burst at {}", e.at);
        }
    }
    // Not blind: with the check period beyond the run nobody switches and
    // the later bursts do lose frames.
    let mut off = cfg.clone();
    off.check_period = u16::MAX;
    let r_off = tokenbus::run(&off);
    assert!(r_off
        .outs
        .iter()
        .take(7)
        .all(|o| o.iter().all(|x| x.map_or(true, |x| !x.chk_sw))));
    let later: u64 = cfg
        .events
        .iter()
        .enumerate()
        .filter(|(_, e)| e.at > last)
        .map(|(f, _)| r_off.lost_by_fault[f])
        .sum();
    assert!(
        later > 0,
        "the later bursts lose nothing even without the switch"
    );
    assert!(r_off.receptions_lost > r.receptions_lost);
}
