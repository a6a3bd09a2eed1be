//! Every block: `verilator --lint-only -Wall` clean (with the commented
//! waivers of rtl/lint/waivers.vlt only) and synthesizable by Yosys for iCE40.
//! Cell counts are printed (sizes are recorded in docs/benchmarks.md, not
//! asserted here).

use merkur_rtl::verilog::{all_blocks, WAIVERS};
use std::process::Command;

fn scratch() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("merkur-lint-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_block_is_lint_clean() {
    let d = scratch();
    let waivers = d.join("waivers.vlt");
    std::fs::write(&waivers, WAIVERS).unwrap();
    for (name, v) in all_blocks() {
        let f = d.join(format!("{name}.v"));
        std::fs::write(&f, &v).unwrap();
        let o = Command::new("verilator")
            .args(["--lint-only", "-Wall", "--top-module", "top"])
            .arg(&waivers)
            .arg(&f)
            .output()
            .expect("verilator runs");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            o.status.success() && !err.contains("%Warning"),
            "{name}: lint:\n{err}"
        );
    }
}

#[test]
fn every_block_synthesizes_for_ice40() {
    let d = scratch();
    // chain8 is a test top (eight slaves), not a block anyone synthesizes.
    for (name, v) in all_blocks().into_iter().filter(|(n, _)| *n != "chain8") {
        let f = d.join(format!("{name}_synth.v"));
        std::fs::write(&f, &v).unwrap();
        let o = Command::new("yosys")
            .arg("-p")
            .arg(format!(
                "read_verilog {}; synth_ice40 -top top; check -assert; stat",
                f.display()
            ))
            .output()
            .expect("yosys runs");
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(
            o.status.success(),
            "{name}: yosys failed:\n{out}\n{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let cells = out
            .lines()
            .rev()
            .find_map(|l| l.trim().strip_prefix("Number of cells:"))
            .map(|n| n.trim().to_string())
            .expect("stat printed a cell count");
        assert_ne!(cells, "0", "{name}: synthesized to nothing");
        println!("{name}: {cells} iCE40 cells");
    }
}
