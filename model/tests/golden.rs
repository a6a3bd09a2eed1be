//! Drift guard: every committed golden trace in tb-data/ is regenerated from
//! its scenario and must match byte for byte. A change to the model that
//! changes a trace must regenerate it on purpose:
//! `cargo run -p merkur -- trace tb-data/X.toml -o tb-data/X.trace`.

use merkur_model::{config, ring, tbconfig, tokenbus, trace};
use std::path::PathBuf;

fn tb_data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tb-data")
}

#[test]
fn committed_traces_match_the_model() {
    let mut scenarios: Vec<PathBuf> = std::fs::read_dir(tb_data())
        .expect("tb-data exists")
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    scenarios.sort();
    assert!(scenarios.len() >= 12, "starter set present: {scenarios:?}");
    let mut drift = vec![];
    for sc in &scenarios {
        let text = std::fs::read_to_string(sc).unwrap();
        let name = format!("tb-data/{}", sc.file_name().unwrap().to_string_lossy());
        let got = if tbconfig::is_token_bus(&text) {
            let cfg = tbconfig::load(&name, &text).unwrap_or_else(|e| panic!("{e}"));
            tokenbus::render(&cfg, &text, &tokenbus::run(&cfg))
        } else {
            let cfg = config::load(&name, &text).unwrap_or_else(|e| panic!("{e}"));
            trace::render(&cfg, &text, &ring::run(&cfg))
        };
        let tr = sc.with_extension("trace");
        let want = std::fs::read_to_string(&tr)
            .unwrap_or_else(|_| panic!("{} has no committed trace {}", sc.display(), tr.display()));
        if let Some(line) = trace::first_difference(&got, &want) {
            drift.push(format!(
                "{} (first difference at line {line})",
                tr.display()
            ));
        }
    }
    assert!(
        drift.is_empty(),
        "golden traces drifted from the model:\n{}",
        drift.join("\n")
    );
}

#[test]
fn trace_header_names_version_hash_and_seed() {
    let text = std::fs::read_to_string(tb_data().join("ring3.toml")).unwrap();
    let cfg = config::load("ring3.toml", &text).unwrap();
    let t = trace::render(&cfg, &text, &ring::run(&cfg));
    assert!(t.contains(&format!(
        "# generator merkur-model {}\n",
        env!("CARGO_PKG_VERSION")
    )));
    assert!(t.contains(&format!(
        "# scenario-sha256 {}\n",
        trace::scenario_hash(&text)
    )));
    assert!(t.contains("# seed 3\n"));
    // sha256 of "abc", the FIPS 180-2 test vector.
    assert_eq!(
        trace::scenario_hash("abc"),
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
    );
}

/// `Config::to_scenario` writes a file that reads back to the same
/// configuration, for every ring scenario of tb-data/ (breaks, repairs,
/// deaths, flips, interrupts and host writes among them, and ring8 with
/// explicit sensor values added).
#[test]
fn a_configuration_written_as_a_scenario_reads_back_the_same() {
    let mut n = 0;
    for e in std::fs::read_dir(tb_data()).expect("tb-data exists") {
        let p = e.expect("dir entry").path();
        if p.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let mut text = std::fs::read_to_string(&p).unwrap();
        if tbconfig::is_token_bus(&text) {
            continue;
        }
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if name == "ring8.toml" {
            text += "\n[[stimulus.value]]\ncycle = 2\nslot = 1\ndata = 0x1234\n";
        }
        let cfg = config::load(&name, &text).unwrap_or_else(|e| panic!("{e}"));
        let written = cfg.to_scenario("written back");
        let again = config::load(&name, &written)
            .unwrap_or_else(|e| panic!("{name} written back does not load:\n{e}\n{written}"));
        assert_eq!(
            format!("{cfg:?}"),
            format!("{again:?}"),
            "{name}: written back as\n{written}"
        );
        n += 1;
    }
    assert!(n >= 15, "only {n} ring scenarios");
}
