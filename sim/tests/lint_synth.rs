//! Every block: `verilator --lint-only -Wall` clean (with the commented
//! waivers of rtl/lint/waivers.vlt only) and synthesizable by Yosys for iCE40.
//! Cell counts are printed (sizes are recorded in docs/benchmarks.md, not
//! asserted here).

use merkur_rtl::emit::verilog::{all_blocks, mem_depth, size_memories, WAIVERS};
use merkur_sim::jobs;
use merkur_sim::verilator::lint;
use std::process::Command;

fn scratch() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("merkur-lint-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The blocks, the largest first (they are last in `all_blocks`), so that
/// the small ones fill the time beside them in the work queue.
fn blocks_largest_first() -> Vec<(&'static str, String)> {
    let mut b = all_blocks();
    b.reverse();
    b
}

#[test]
fn every_block_is_lint_clean() {
    let d = scratch();
    let waivers = d.join("waivers.vlt");
    std::fs::write(&waivers, WAIVERS).unwrap();
    let results = jobs::run(&blocks_largest_first(), jobs::cores(), |(name, v)| {
        let f = d.join(format!("{name}.v"));
        std::fs::write(&f, v).map_err(|e| format!("{name}: {e}"))?;
        Ok(lint(&[&waivers, &f], "top")
            .err()
            .map(|err| format!("{name}: lint:\n{err}")))
    })
    .unwrap();
    let failed: Vec<String> = results.into_iter().flatten().collect();
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

#[test]
fn every_block_synthesizes_for_ice40() {
    let d = scratch();
    // chain8 is a test top (eight slaves), not a block anyone synthesizes.
    let blocks: Vec<_> = blocks_largest_first()
        .into_iter()
        .filter(|(n, _)| *n != "chain8")
        .collect();
    // The memories as every user of a block gets them (`merkur synth`, the ring
    // tops, gen/verilog): as deep as the ring's slot count needs, here the
    // smallest depth, which serves rings up to 256 slots. The masters' default
    // 4,096-entry memories differ only in their depth, and Yosys spent 137 of
    // this test's CPU seconds mapping them (docs/benchmarks.md, issue 24).
    let depth = mem_depth(1);
    let cells = jobs::run(&blocks, jobs::cores(), |(name, v)| {
        let f = d.join(format!("{name}_synth.v"));
        std::fs::write(&f, size_memories(v, depth)).map_err(|e| format!("{name}: {e}"))?;
        let o = Command::new("yosys")
            .arg("-p")
            .arg(format!(
                "read_verilog {}; synth_ice40 -top top; check -assert; stat",
                f.display()
            ))
            .output()
            .map_err(|e| format!("{name}: cannot run yosys: {e}"))?;
        let out = String::from_utf8_lossy(&o.stdout);
        if !o.status.success() {
            return Err(format!(
                "{name}: yosys failed:\n{out}\n{}",
                String::from_utf8_lossy(&o.stderr)
            ));
        }
        let cells = out
            .lines()
            .rev()
            .find_map(|l| l.trim().strip_prefix("Number of cells:"))
            .map(|n| n.trim().to_string())
            .ok_or(format!("{name}: stat printed no cell count"))?;
        if cells == "0" {
            return Err(format!("{name}: synthesized to nothing"));
        }
        Ok(format!("{name}: {cells} iCE40 cells"))
    })
    .unwrap_or_else(|e| panic!("{e}"));
    for c in cells {
        println!("{c}");
    }
}

/// The ring top `merkur verilog` writes (here for tb-data/ring8.toml: all
/// four node kinds), without and with the nodes' power-on resets (a ring
/// that restarts nodes, rtl/src/harness/power_on.rs), and with
/// extended-alarm words (protocol §6): lint-clean and accepted by
/// Yosys (elaboration, process and design checks; it is a simulation
/// harness, not a bitstream).
#[test]
fn the_ring_top_is_lint_clean_and_checked_by_yosys() {
    let d = scratch();
    let waivers = d.join("waivers_ring.vlt");
    std::fs::write(&waivers, WAIVERS).unwrap();
    let name = "ring8.toml";
    let root = merkur_sim::repo_root();
    let text = std::fs::read_to_string(root.join("tb-data").join(name)).unwrap();
    let cfg = merkur_model::config::load(name, &text).unwrap();
    let kinds: Vec<_> = cfg.nodes.iter().map(|n| n.kind).collect();
    use merkur_rtl::line::word_rx::WordFormat;
    for (restarts, format) in [
        (false, WordFormat::Basic),
        (true, WordFormat::Basic),
        (false, WordFormat::ExtendedAlarm),
    ] {
        let v =
            merkur_rtl::harness::ring_top::ring_verilog_with(&kinds, cfg.slots, restarts, format);
        assert_eq!(
            v.contains("i_por"),
            restarts,
            "power-on reset only with restarts"
        );
        let f = d.join(format!("ring8_ring_{restarts}_{format:?}.v"));
        std::fs::write(&f, &v).unwrap();
        if let Err(err) = lint(&[&waivers, &f], "merkur_ring") {
            panic!("ring top (restarts {restarts}, {format:?}) lint:\n{err}");
        }
        let o = Command::new("yosys")
            .arg("-p")
            .arg(format!(
                "read_verilog {}; hierarchy -check -top merkur_ring; proc; check -assert",
                f.display()
            ))
            .output()
            .expect("yosys runs");
        assert!(
            o.status.success(),
            "ring top (restarts {restarts}): yosys failed:\n{}\n{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        );
    }
}
