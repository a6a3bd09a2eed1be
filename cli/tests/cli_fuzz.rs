//! The `merkur` command line under random arguments (issue 26): every
//! subcommand with random flags and values — empty, negative, huge, not a
//! number, unicode, paths that do not exist or are directories, bad and
//! good scenarios, random words. Every run must end (within [`LIMIT`]) with
//! exit code 0, 1 or 2, never a panic; exit code 2 with an error message on
//! stderr and nothing written into the output directory.
//!
//! Heavy runs are kept out of the fuzz, not out of the check: `sim`,
//! `campaign` and `synth` always get one argument that must be refused
//! (otherwise a valid combination would start a Verilator build, a
//! campaign or a synthesis, minutes each; those run in cli.rs).
//!
//! Seeded (MERKUR_SEED, printed on failure); MERKUR_CLI_FUZZ_CASES sets
//! the number of runs (default 1,000 in CI, about 5 s; 20,000 in
//! docs/benchmarks.md).

use merkur_sim::Rng;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_secs(60);

fn root() -> PathBuf {
    merkur_sim::repo_root()
}

fn pick<'a>(rng: &mut Rng, xs: &[&'a str]) -> &'a str {
    xs[rng.below(xs.len() as u64) as usize]
}

/// A value for any flag: mostly wrong, sometimes right.
fn value(rng: &mut Rng) -> String {
    match rng.below(12) {
        0 => String::new(),
        1 => "-1".into(),
        2 => "18446744073709551616".into(),
        3 => "9".repeat(1 + rng.below(400) as usize),
        4 => pick(rng, &["NaN", "inf", "-inf", "1e309", "0x10", "1.5", "0"]).into(),
        5 => pick(rng, &["ü", "ring8", "--", "-", "%s%n", "a b", "🦀"]).into(),
        6 => rng.below(100_000).to_string(),
        7 => pick(rng, &["1/2", "3/2", "0/0", "2/1", "x/y"]).into(),
        8 => pick(
            rng,
            &[
                "ice40-hx8k",
                "ecp5-85",
                "xc2c64a",
                "debian",
                "yowasp",
                "ulx3s",
                "switch_ctl",
                "bit-errors",
                "double,node-death",
            ],
        )
        .into(),
        _ => scenario(rng),
    }
}

/// A scenario argument: good, bad, missing, a directory.
fn scenario(rng: &mut Rng) -> String {
    match rng.below(5) {
        0 => {
            let good = [
                "tb-data/ring8.toml",
                "tb-data/ring2.toml",
                "tb-data/dcm8_normal.toml",
                "tb-data/chain9.toml",
            ];
            repo_path(pick(rng, &good))
        }
        1 | 2 => {
            let bad = std::fs::read_dir(root().join("tb-data/bad"))
                .unwrap()
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect::<Vec<_>>();
            bad[rng.below(bad.len() as u64) as usize]
                .display()
                .to_string()
        }
        3 => match rng.below(4) {
            0 => repo_path("tb-data"),
            1 => repo_path("README.md"),
            _ => pick(rng, &["/nonexistent/x.toml", "", "/dev/null"]).into(),
        },
        _ => repo_path("tb-data/ring8.trace"),
    }
}

/// A file of the repository, by absolute path (the runs' working directory
/// is a scratch directory).
fn repo_path(rel: &str) -> String {
    root().join(rel).display().to_string()
}

/// A value for an output flag: inside the scratch directory (where a
/// relative path lands too), or one that cannot be written. Never a path
/// of the repository: an accepted run would overwrite it.
fn output(rng: &mut Rng, out: &Path) -> String {
    match rng.below(6) {
        0 => String::new(),
        1 => "/nonexistent/dir/x".into(),
        2 => out.display().to_string(),
        3 => pick(rng, &["x", "y.fst", "d/e", "-", "ü"]).into(),
        _ => out
            .join(pick(rng, &["x", "y.fst", "d/e"]))
            .display()
            .to_string(),
    }
}

/// One argument that every heavy subcommand must refuse.
fn refused_arg(rng: &mut Rng, sub: &str) -> Vec<String> {
    let v: Vec<&str> = match (sub, rng.below(3)) {
        ("campaign", 0) => vec!["--jobs", "0"],
        ("campaign", 1) => vec!["--only", "no-such-class"],
        ("campaign", _) => vec!["--ppm", "-5"],
        ("synth", 0) => vec!["--target", "xc9500"],
        ("synth", 1) => vec!["--flow", "vivado"],
        ("synth", _) => vec!["--seeds", "0"],
        (_, _) => vec!["--seed", "not-a-number"],
    };
    v.into_iter().map(String::from).collect()
}

const FLAGS: &[(&str, &[&str])] = &[
    ("check", &["--line-rate"]),
    ("trace", &["-o", "--output"]),
    ("verilog", &["-o", "--output"]),
    ("sim", &["--wave", "--seed", "--show", "--dump"]),
    (
        "campaign",
        &[
            "--seed",
            "--jobs",
            "--shard",
            "--case",
            "--only",
            "--ppm",
            "--doubles",
            "--singles",
            "--bursts",
            "--ber-runs",
            "--model-only",
            "-o",
        ],
    ),
    (
        "synth",
        &[
            "--target",
            "--node",
            "--line-rate",
            "--seed",
            "--seeds",
            "--flow",
            "--speed",
            "--board",
            "-o",
        ],
    ),
    ("prove", &["--only", "--list", "-o"]),
    ("demo", &["--model-only", "--wave"]),
];

/// Flags that take no value.
const SWITCHES: &[&str] = &["--show", "--dump", "--model-only", "--list"];

fn args(rng: &mut Rng, out: &Path) -> Vec<String> {
    let (sub, flags) = FLAGS[rng.below(FLAGS.len() as u64) as usize];
    let mut a = vec![sub.to_string()];
    if rng.below(8) == 0 {
        a[0] = pick(rng, &["chek", "", "--version", "help", "-x"]).into();
    }
    if !matches!(sub, "prove" | "demo") && rng.below(6) != 0 {
        a.push(scenario(rng));
    }
    for _ in 0..rng.below(4) {
        let f = pick(rng, flags);
        a.push(f.into());
        if !SWITCHES.contains(&f) {
            if matches!(f, "-o" | "--output" | "--wave") {
                a.push(output(rng, out));
            } else {
                a.push(value(rng));
            }
        }
    }
    match sub {
        "sim" | "campaign" | "synth" => a.extend(refused_arg(rng, sub)),
        // A prove that runs is slow too: list, or name no proof.
        "prove" if !a.iter().any(|x| x == "--list") => {
            a.extend(["--only".into(), "no-such-proof".into()])
        }
        // The demo without --model-only builds the RTL ring.
        "demo" if !a.iter().any(|x| x == "--model-only") => a.push("--model-only".into()),
        _ => {}
    }
    a
}

/// `git status` of the repository (a run must never write into it).
fn repo_state() -> String {
    let o = Command::new("git")
        .args(["status", "--porcelain", "--untracked-files=all"])
        .current_dir(root())
        .output()
        .unwrap();
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn empty(dir: &Path) -> bool {
    std::fs::read_dir(dir).map_or(true, |mut d| d.next().is_none())
}

#[test]
fn random_arguments_never_panic_or_hang() {
    let seed = Rng::seed(0xc11);
    let cases: u64 = std::env::var("MERKUR_CLI_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mut rng = Rng::new(seed);
    let before = repo_state();
    let out = std::env::temp_dir().join(format!("merkur-cli-fuzz-{}", std::process::id()));
    let mut codes = [0u64; 3];
    for case in 0..cases {
        let _ = std::fs::remove_dir_all(&out);
        std::fs::create_dir_all(&out).unwrap();
        let a = args(&mut rng, &out);
        let ctx = format!("seed {seed} (MERKUR_SEED), case {case}: merkur {a:?}");
        let t0 = Instant::now();
        let mut child = Command::new(env!("CARGO_BIN_EXE_merkur"))
            .args(&a)
            .current_dir(&out)
            .env("TMPDIR", &out)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break s;
            }
            if t0.elapsed() > LIMIT {
                let _ = child.kill();
                panic!("{ctx}: still running after {LIMIT:?}");
            }
            std::thread::sleep(Duration::from_millis(2));
        };
        let mut err = String::new();
        use std::io::Read;
        child
            .stderr
            .take()
            .unwrap()
            .read_to_string(&mut err)
            .unwrap();
        assert!(!err.contains("panicked"), "{ctx}: {err}");
        let code = status
            .code()
            .unwrap_or_else(|| panic!("{ctx}: killed by a signal"));
        assert!((0..=2).contains(&code), "{ctx}: exit code {code}: {err}");
        if code == 2 {
            assert!(
                err.contains("error"),
                "{ctx}: exit 2 without an error: {err}"
            );
            assert!(
                empty(&out),
                "{ctx}: refused but wrote into {}",
                out.display()
            );
        }
        codes[code as usize] += 1;
    }
    let _ = std::fs::remove_dir_all(&out);
    assert_eq!(
        repo_state(),
        before,
        "seed {seed}: the fuzz changed the repository"
    );
    eprintln!(
        "{cases} runs: {} accepted, {} failed (1), {} refused (2)",
        codes[0], codes[1], codes[2]
    );
    assert!(
        codes[0] > 0 && codes[2] > 0,
        "the fuzz reaches both sides: {codes:?}"
    );
}
