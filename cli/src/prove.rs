//! `merkur prove`: runs the formal proofs of the control blocks
//! (`merkur_rtl::formal`, property wrappers in `rtl/formal/`) in
//! SymbiYosys with Boolector and prints a table of verdicts. A failed
//! assertion names its label and leaves its counterexample as a VCD
//! waveform in the output directory.

use merkur_rtl::formal::{proofs, Proof};
use merkur_sim::formal::{run_all, table, Tools};
use std::path::Path;

/// Runs the proofs named in `only` (all when empty) in `dir`; `Ok(false)`
/// when one failed.
pub fn run(only: &[String], dir: &Path, list: bool) -> Result<bool, String> {
    let all = proofs();
    if list {
        for p in &all {
            println!("{:<16} {}", p.name, p.what);
        }
        return Ok(true);
    }
    for o in only {
        if !all.iter().any(|p| p.name == o) {
            let names: Vec<&str> = all.iter().map(|p| p.name).collect();
            return Err(format!(
                "error: --only {o:?}: no such proof; proofs: {}",
                names.join(", ")
            ));
        }
    }
    let chosen: Vec<&Proof> = all
        .iter()
        .filter(|p| only.is_empty() || only.iter().any(|o| o == p.name))
        .collect();
    let tools = Tools::find(None)?;
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("error: cannot create {}: {e}", dir.display()))?;
    // As many proofs at a time as the machine has cores.
    let jobs = std::thread::available_parallelism().map_or(1, |n| n.get());
    let results = run_all(&chosen, dir, &tools, jobs, &|p| {
        eprintln!("proving {} ({})", p.name, p.what)
    })?;
    print!("{}", table(&results));
    let ok = results.iter().all(|r| r.passed());
    if !ok {
        eprintln!(
            "a proof failed: the counterexample waveforms are named above (open them in GTKWave)"
        );
    }
    Ok(ok)
}
