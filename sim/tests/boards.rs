//! Board constraints (rtl/src/top/boards.rs, the one source of pin truth): the
//! committed files in `constraints/` are exactly what the generator writes,
//! no ball is used twice, and every port bit of the board's top is
//! constrained (and nothing else is).

use merkur_model::scenario::Kind;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::top::boards::{self, Board};
use merkur_rtl::top::synth_top::{node_top, NodeStatic};
use merkur_rtl::top::ulx3s::ulx3s_verilog;
use merkur_rtl::top::xem6010::xem6010_verilog;
use merkur_sim::repo_root;
use std::collections::BTreeSet;

#[test]
fn committed_constraints_match_the_generator() {
    for b in boards::all() {
        let path = repo_root().join("gen/constraints").join(b.file);
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            committed == boards::constraints_file(&b),
            "{} drifted from rtl/src/top/boards.rs; regenerate it: \
             cargo run -p merkur-sim --example gen",
            path.display()
        );
    }
}

#[test]
fn no_ball_is_used_twice() {
    for b in boards::all() {
        let mut seen = BTreeSet::new();
        for p in &b.pins {
            assert!(
                seen.insert(p.ball),
                "{}: ball {} used twice",
                b.name,
                p.ball
            );
        }
    }
}

/// Port bits of module `top` in `verilog` (`name` or `name[i]`).
fn port_bits(verilog: &str, top: &str) -> BTreeSet<String> {
    let start = verilog
        .find(&format!("module {top}("))
        .unwrap_or_else(|| panic!("no module {top}"));
    let body = &verilog[start..];
    let body = &body[..body.find("endmodule").unwrap()];
    let mut out = BTreeSet::new();
    for l in body.lines() {
        let t = l.trim();
        let decl = ["input wire", "output wire", "output reg", "inout wire"]
            .iter()
            .find_map(|k| t.strip_prefix(k));
        let Some(rest) = decl else { continue };
        let rest = rest.trim();
        let (width, name) = if let Some(r) = rest.strip_prefix('[') {
            let (range, n) = r.split_once(']').unwrap();
            let (hi, lo) = range.split_once(':').unwrap();
            let bound = |x: &str| x.trim().parse::<usize>().unwrap();
            (Some((bound(hi), bound(lo))), n.trim())
        } else {
            (None, rest)
        };
        let name = name.split([';', ' ', '=']).next().unwrap();
        match width {
            None => {
                out.insert(name.to_string());
            }
            Some((hi, lo)) => {
                for i in lo..=hi {
                    out.insert(format!("{name}[{i}]"));
                }
            }
        }
    }
    out
}

fn check_covers(b: &Board, verilog: &str, top: &str) {
    let ports = port_bits(verilog, top);
    assert!(!ports.is_empty());
    let pins: BTreeSet<String> = b.pins.iter().map(|p| p.port.clone()).collect();
    let missing: Vec<_> = ports.difference(&pins).collect();
    let extra: Vec<_> = pins.difference(&ports).collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "{}: unconstrained ports {missing:?}, pins of no port {extra:?}",
        b.name
    );
}

#[test]
fn every_top_level_port_is_constrained() {
    let st = |kind| NodeStatic {
        kind,
        address: 1,
        slots: 9,
        period: 330,
        rtx: Default::default(),
        layout: Default::default(),
        diag: true,
        sensor_sync: true,
        format: WordFormat::Basic,
    };
    for kind in [Kind::Sensor, Kind::Actuator] {
        check_covers(
            &boards::ice40_hx8k_breakout(),
            &node_top(&st(kind)).unwrap(),
            "merkur_top",
        );
        check_covers(
            &boards::ulx3s(),
            &ulx3s_verilog(&st(kind)).unwrap(),
            "merkur_ulx3s",
        );
    }
    for kind in [Kind::Master, Kind::SpecialMaster] {
        check_covers(
            &boards::xem6010(),
            &xem6010_verilog(&st(kind)).unwrap(),
            "merkur_xem6010",
        );
    }
}
