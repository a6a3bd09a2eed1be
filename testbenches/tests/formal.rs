//! Every formal proof of `merkur_rtl::formal` (SymbiYosys + Boolector,
//! docs/verification.md), and the flow's own check: a deliberately broken
//! property fails with a counterexample waveform.

use merkur_rtl::formal::{proofs, Proof};
use merkur_testbenches::formal::{run, run_all, table, Status, Tools};
use std::path::PathBuf;

fn out_dir(name: &str) -> PathBuf {
    let d = merkur_testbenches::repo_root()
        .join("target/formal")
        .join(name);
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

/// Table 1 with the WU row's BSR wrong (SI instead of PI): the proof must
/// fail on that assertion and leave the counterexample as a VCD waveform.
#[test]
fn a_wrong_table_1_row_fails_with_a_waveform() {
    let tools = Tools::for_tests().unwrap();
    let mut p = proofs()
        .into_iter()
        .find(|p| p.name == "switchbox")
        .unwrap();
    let right = "row_wu_bsr: assert (o_bsr == i_pi);";
    assert!(p.props.contains(right));
    p.props = Box::leak(
        p.props
            .replace(right, "row_wu_bsr: assert (o_bsr == i_si);")
            .into_boxed_str(),
    );
    let r = run(&p, &out_dir("broken"), &tools).unwrap();
    eprintln!("{}", table(std::slice::from_ref(&r)));
    let prove = &r.tasks[0];
    assert_eq!(prove.status, Status::Fail, "{:?}", prove.detail);
    assert!(
        prove.detail.iter().any(|d| d.contains("row_wu_bsr")),
        "{:?}",
        prove.detail
    );
    let vcd = std::fs::read_to_string(prove.trace.as_ref().expect("a counterexample")).unwrap();
    assert!(vcd.contains("$var") && vcd.contains("i_mode"), "{vcd}");
    // The covers do not depend on the broken assertion.
    assert_eq!(r.tasks[1].status, Status::Pass);
}

/// mdb's bounded check with the ACK deadline one clock instead of four: ABC
/// must find the failure, and the runner must report the assertion and a
/// counterexample waveform (from its second run under smtbmc).
#[test]
fn a_wrong_bounded_property_fails_with_a_waveform() {
    let tools = Tools::for_tests().unwrap();
    let mut p = proofs().into_iter().find(|p| p.name == "mdb").unwrap();
    let right = "wb_ack_in_time: assert (waited <= 4);";
    assert!(p.props.contains(right));
    p.props = Box::leak(
        p.props
            .replace(right, "wb_ack_in_time: assert (waited <= 1);")
            .into_boxed_str(),
    );
    p.tasks.retain(|t| t.mode == merkur_rtl::formal::Mode::Bmc);
    assert_eq!(p.tasks.len(), 1);
    let r = run(&p, &out_dir("broken_bmc"), &tools).unwrap();
    eprintln!("{}", table(std::slice::from_ref(&r)));
    let bmc = &r.tasks[0];
    assert_eq!(bmc.status, Status::Fail, "{:?}", bmc.detail);
    assert!(
        bmc.detail.iter().any(|d| d.contains("wb_ack_in_time")),
        "{:?}",
        bmc.detail
    );
    let sby_log = std::fs::read_to_string(out_dir("broken_bmc").join("mdb/sby.log")).unwrap();
    assert!(
        sby_log.contains("engine_0 (abc bmc3) returned FAIL"),
        "{sby_log}"
    );
    let vcd = std::fs::read_to_string(bmc.trace.as_ref().expect("a counterexample")).unwrap();
    assert!(vcd.contains("$var") && vcd.contains("o_wb_ack"), "{vcd}");
}
