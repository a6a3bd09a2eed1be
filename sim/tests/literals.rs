//! The literal sizing of our emission pass (`merkur_rtl::emit::literals`) changes
//! no bit: Yosys proves a block's Verilog with rust-hdl's 32-bit literals
//! and with the sized ones the same design (`equiv_make`, `equiv_simple
//! -seq`, `equiv_induct`: every matched signal equal in every reachable
//! state). A deliberately wrong literal must fail the same check.
//! Checked: the slave, the master, the special master and the 802.4 Dual
//! Channel Manager (about 35 s together on two cores).

use merkur_rtl::emit::readable::{readable, registers_and_names};
use merkur_rtl::emit::verilog::{size_memories, zero_memories};
use merkur_sim::formal::Tools;
use rust_hdl::core::prelude::*;
use std::path::PathBuf;
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("merkur-literals-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The block's text before and after the literal sizing. A master's
/// memories are cut to 16 words, as a ring of 16 slots has them
/// (`size_memories`): the proof maps memories into logic, and 4,096 words
/// would take it hours; the logic around them is the same at any depth.
fn both<U: Block>(mut uut: U, depth: Option<usize>) -> (String, String) {
    uut.connect_all();
    let raw = generate_verilog(&uut);
    let cut = |v: String| match depth {
        Some(d) => size_memories(&v, d),
        None => v,
    };
    (
        cut(zero_memories(&registers_and_names(&raw))),
        cut(zero_memories(&readable(&raw))),
    )
}

/// Whether Yosys proves `gold` and `gate` (top module `top`) equivalent;
/// the log's last lines on failure.
fn equivalent(name: &str, gold: &str, gate: &str) -> Result<(), String> {
    let d = scratch(name);
    std::fs::write(d.join("gold.v"), gold).unwrap();
    std::fs::write(d.join("gate.v"), gate).unwrap();
    // ROMs and memories become logic (`memory`): the SAT step cannot model
    // memory cells.
    let read = |f: &str| {
        format!(
            "read_verilog {f}.v\nhierarchy -top top\nproc\nflatten\nopt_clean\nmemory\nopt_clean\n\
             rename top {f}\ndesign -stash {f}\n"
        )
    };
    let script = format!(
        "{}{}design -copy-from gold -as gold gold\ndesign -copy-from gate -as gate gate\n\
         equiv_make gold gate equiv\nhierarchy -top equiv\nequiv_simple -seq 2\nequiv_induct\n\
         equiv_status -assert\n",
        read("gold"),
        read("gate")
    );
    std::fs::write(d.join("equiv.ys"), script).unwrap();
    let tools = Tools::for_tests()?;
    // YoWASP's Yosys reads files relative to its working directory.
    let o = Command::new(&tools.yosys)
        .current_dir(&d)
        .args(["-q", "-l", "equiv.log", "equiv.ys"])
        .output()
        .map_err(|e| format!("cannot run {}: {e}", tools.yosys.display()))?;
    let log = std::fs::read_to_string(d.join("equiv.log")).unwrap_or_default();
    let tail: Vec<&str> = log.lines().rev().take(12).collect();
    let tail: Vec<&str> = tail.into_iter().rev().collect();
    if o.status.success() && log.contains("Equivalence successfully proven!") {
        std::fs::remove_dir_all(&d).ok();
        Ok(())
    } else {
        Err(format!(
            "{name} (files in {}):\n{}",
            d.display(),
            tail.join("\n")
        ))
    }
}

fn check<U: Block>(name: &str, uut: U, depth: Option<usize>) {
    let (gold, gate) = both(uut, depth);
    assert_ne!(gold, gate, "{name}: no literal was sized");
    equivalent(name, &gold, &gate).unwrap();
}

#[test]
fn a_wrong_literal_is_found() {
    let (gold, gate) = both(merkur_rtl::node::sw_dark::SwDark::default(), None);
    equivalent("sw_dark", &gold, &gate).unwrap();
    let wrong = gate.replacen("dark_q - 5'h1", "dark_q - 5'h2", 1);
    assert_ne!(wrong, gate, "the sized decrement is in the text");
    assert!(equivalent("sw_dark_wrong", &gold, &wrong).is_err());
}

#[test]
fn the_slave_is_unchanged() {
    check("slave", merkur_rtl::node::slave::Slave::default(), None);
}

#[test]
fn the_dual_channel_manager_is_unchanged() {
    check("dcm", merkur_rtl::tokenbus::dcm::Dcm::default(), None);
}

#[test]
fn the_master_is_unchanged() {
    check(
        "master",
        merkur_rtl::node::master::Master::default(),
        Some(16),
    );
}

#[test]
fn the_special_master_is_unchanged() {
    check(
        "special_master",
        merkur_rtl::node::special_master::SpecialMaster::default(),
        Some(16),
    );
}
