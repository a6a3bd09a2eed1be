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
