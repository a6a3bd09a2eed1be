//! Every formal proof of `merkur_rtl::formal` (SymbiYosys + Boolector,
//! docs/verification.md), and the flow's own check: a deliberately broken
//! property fails with a counterexample waveform.

use merkur_rtl::formal::{proofs, Proof};
use merkur_sim::formal::{run, run_all, table, Status, Tools};
use std::path::PathBuf;

fn out_dir(name: &str) -> PathBuf {
    let d = merkur_sim::repo_root().join("target/formal").join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_proof_holds() {
    let tools = Tools::for_tests().unwrap();
    let dir = out_dir("all");
    let ps = proofs();
    // Two at a time (the machine has two cores), each worker taking the next
    // proof as it finishes one.
    let refs: Vec<&Proof> = ps.iter().collect();
    let results = run_all(&refs, &dir, &tools, 2, &|_| {}).unwrap();
    let t = table(&results);
    eprintln!("{t}");
    assert!(results.iter().all(|r| r.passed()), "a proof failed:\n{t}");
    assert_eq!(results.len(), ps.len());
}

/// Proof `name` with its property text `right` replaced by `wrong` (which
/// must be there: a mutation that misses leaves a test that cannot fail).
fn broken(name: &str, right: &str, wrong: &str) -> Proof {
    let mut p = proofs().into_iter().find(|p| p.name == name).unwrap();
    assert!(
        p.props.contains(right),
        "{name}: {right:?} not in its properties"
    );
    p.props = Box::leak(p.props.replace(right, wrong).into_boxed_str());
    p
}

/// The one task's failure names `label` and leaves a waveform with `signal`.
fn fails_with_waveform(t: &merkur_sim::formal::TaskResult, label: &str, signal: &str) {
    assert_eq!(t.status, Status::Fail, "{:?}", t.detail);
    assert!(t.detail.iter().any(|d| d.contains(label)), "{:?}", t.detail);
    let vcd = std::fs::read_to_string(t.trace.as_ref().expect("a counterexample")).unwrap();
    assert!(vcd.contains("$var") && vcd.contains(signal), "{vcd}");
}

/// Table 1 with the WU row's BSR wrong (SI instead of PI): the proof must
/// fail on that assertion and leave the counterexample as a VCD waveform.
#[test]
fn a_wrong_table_1_row_fails_with_a_waveform() {
    let tools = Tools::for_tests().unwrap();
    let p = broken(
        "switchbox",
        "row_wu_bsr: assert (o_bsr == i_pi);",
        "row_wu_bsr: assert (o_bsr == i_si);",
    );
    let r = run(&p, &out_dir("broken"), &tools).unwrap();
    eprintln!("{}", table(std::slice::from_ref(&r)));
    fails_with_waveform(&r.tasks[0], "row_wu_bsr", "i_mode");
    // The covers do not depend on the broken assertion.
    assert_eq!(r.tasks[1].status, Status::Pass);
}

/// mdb's bounded check with the ACK deadline one clock instead of four: ABC
/// must find the failure, and the runner must report the assertion and a
/// counterexample waveform (from its second run under smtbmc).
#[test]
fn a_wrong_bounded_property_fails_with_a_waveform() {
    let tools = Tools::for_tests().unwrap();
    let mut p = broken(
        "mdb",
        "wb_ack_in_time: assert (waited <= 4);",
        "wb_ack_in_time: assert (waited <= 1);",
    );
    p.tasks.retain(|t| t.mode == merkur_rtl::formal::Mode::Bmc);
    assert_eq!(p.tasks.len(), 1);
    let r = run(&p, &out_dir("broken_bmc"), &tools).unwrap();
    eprintln!("{}", table(std::slice::from_ref(&r)));
    fails_with_waveform(&r.tasks[0], "wb_ack_in_time", "o_wb_ack");
    let sby_log = std::fs::read_to_string(out_dir("broken_bmc").join("mdb/sby.log")).unwrap();
    assert!(
        sby_log.contains("engine_0 (abc bmc3) returned FAIL"),
        "{sby_log}"
    );
}
