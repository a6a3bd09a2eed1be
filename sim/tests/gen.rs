//! The committed Verilog of the standard nodes (`gen/verilog/`,
//! rtl/src/emit/standard.rs): each file is exactly what the generator
//! writes (nothing else is in the folder), and each node file is
//! `verilator --lint-only -Wall` clean with the committed waivers alone,
//! its top module the node.

use merkur_rtl::emit::standard::standard_files;
use merkur_sim::repo_root;
use merkur_sim::verilator::lint;

#[test]
fn committed_verilog_matches_the_generator() {
    let dir = repo_root().join("gen/verilog");
    let files = standard_files();
    for f in &files {
        let path = dir.join(f.name);
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            committed == f.text,
            "{} drifted from its generator; regenerate it: cargo run -p merkur-sim --example gen",
            path.display()
        );
    }
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("gen/verilog")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n != "README.md")
        .collect();
    names.sort();
    let mut want: Vec<String> = files.iter().map(|f| f.name.to_string()).collect();
    want.sort();
    assert_eq!(
        names, want,
        "gen/verilog holds a file the generator does not write"
    );
}

#[test]
fn committed_node_files_are_lint_clean_with_their_waivers() {
    let dir = repo_root().join("gen/verilog");
    let waivers = dir.join("waivers.vlt");
    for f in standard_files().iter().filter(|f| f.name.ends_with(".v")) {
        let top = f.name.trim_end_matches(".v");
        let text = std::fs::read_to_string(dir.join(f.name)).expect("committed file");
        assert!(
            text.contains(&format!("\nmodule {top}(")),
            "{}: no top module {top}",
            f.name
        );
        if let Err(e) = lint(&[&waivers, &dir.join(f.name)], top) {
            panic!("gen/verilog/{}: lint:\n{e}", f.name);
        }
    }
}

/// The timing diagrams of docs/timing/ (sim/src/timing.rs) are what the
/// RTL does today: each is drawn again from its scenario's RTL run and
/// must be the committed file, byte for byte; nothing else is in the folder.
#[test]
fn committed_timing_diagrams_match_the_rtl() {
    use merkur_sim::timing::{diagrams, render_all};
    let dir = repo_root().join("docs/timing");
    let work = std::env::temp_dir().join(format!("merkur-timing-test-{}", std::process::id()));
    let all = diagrams();
    let drawn = render_all(&all, &work).unwrap_or_else(|e| panic!("{e}"));
    for (file, svg) in &drawn {
        let path = dir.join(file);
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            &committed == svg,
            "{} drifted from the RTL run it is drawn from; regenerate it: cargo run -p merkur-sim --example gen",
            path.display()
        );
    }
    let _ = std::fs::remove_dir_all(&work);
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("docs/timing")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut want: Vec<String> = all.iter().map(|d| d.file.to_string()).collect();
    want.sort();
    assert_eq!(names, want, "docs/timing holds a file no diagram draws");
}
