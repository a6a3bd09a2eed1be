//! The pinned tools of scripts/tools.lock are installed at exactly those
//! versions and run, and so are the YoWASP synthesis tools of
//! scripts/requirements-synth.txt. `./run test` installs them first when
//! missing.

use merkur_sim::pinned_tools;
use std::process::Command;

#[test]
fn pinned_tools_are_installed_at_their_versions() {
    let tools = pinned_tools().expect("tools.lock parses");
    assert!(tools.len() >= 6, "tools.lock lists the six tools");
    for t in &tools {
        let out = Command::new("dpkg-query")
            .args(["-W", "-f=${Version}", &t.package])
            .output()
            .unwrap_or_else(|e| {
                panic!(
                    "dpkg-query not runnable ({e}); install {} {} by hand",
                    t.package, t.version
                )
            });
        let got = String::from_utf8_lossy(&out.stdout).to_string();
        assert_eq!(
            got, t.version,
            "package {} is at {got:?}, tools.lock pins {:?}: run scripts/install-tools.sh",
            t.package, t.version
        );
    }
}

/// The upstream version of a Debian version: no epoch, no Debian revision
/// (`0.4-1+b1` → `0.4`).
fn upstream(debian: &str) -> &str {
    let v = debian.split_once(':').map_or(debian, |(_, v)| v);
    v.rsplit_once('-').map_or(v, |(u, _)| u)
}

/// Each pinned tool that says its version prints the version tools.lock
/// pins (read from the lock, so a new pin is checked without editing this
/// test); yosys-abc, the formal flow's bounded-check engine, comes with the
/// pinned yosys package and runs.
#[test]
fn pinned_tools_run() {
    let tools = pinned_tools().expect("tools.lock parses");
    let pin = |pkg: &str| -> String {
        let t = tools
            .iter()
            .find(|t| t.package == pkg)
            .unwrap_or_else(|| panic!("tools.lock pins {pkg}"));
        upstream(&t.version).to_string()
    };
    for (cmd, arg, expect) in [
        (
            "verilator",
            "--version",
            format!("Verilator {}", pin("verilator")),
        ),
        ("yosys", "-V", format!("Yosys {}", pin("yosys"))),
        (
            "nextpnr-ice40",
            "--version",
            format!("(Version {}-", pin("nextpnr-ice40")),
        ),
        (
            "iverilog",
            "-V",
            format!("Icarus Verilog version {}", pin("iverilog")),
        ),
        ("yosys-abc", "-cversion", "UC Berkeley, ABC".to_string()),
        (
            "clang++",
            "--version",
            format!("clang version {}", pin("clang")),
        ),
    ] {
        let out = Command::new(cmd)
            .arg(arg)
            .output()
            .unwrap_or_else(|e| panic!("{cmd} does not run: {e}"));
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            text.contains(&expect),
            "{cmd} {arg} printed {text:?}, expected {expect:?}"
        );
    }
}

/// The YoWASP synthesis tools in .tools/venv are exactly the versions of
/// scripts/requirements-synth.txt (`./run` installs them with pip
/// `--require-hashes`, so the wheels are the pinned ones too).
#[test]
fn synthesis_venv_holds_the_pinned_versions() {
    let root = merkur_sim::repo_root();
    let lock = std::fs::read_to_string(root.join("scripts/requirements-synth.txt")).unwrap();
    let pins: Vec<(String, String)> = lock
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let spec = l.split_whitespace().next().unwrap();
            let (n, v) = spec.split_once("==").expect("name==version");
            (n.to_lowercase(), v.to_string())
        })
        .collect();
    assert!(pins.len() >= 4, "requirements-synth.txt lists the tools");
    let pip = root.join(".tools/venv/bin/pip");
    let out = Command::new(&pip)
        .args(["freeze", "--disable-pip-version-check"])
        .output()
        .unwrap_or_else(|e| {
            panic!(
                "{} not runnable ({e}): run scripts/install-tools.sh --synth",
                pip.display()
            )
        });
    let frozen = String::from_utf8_lossy(&out.stdout).to_lowercase();
    for (n, v) in &pins {
        assert!(
            frozen.lines().any(|l| l == format!("{n}=={v}")),
            "{n}=={v} not installed in .tools/venv (pip freeze: {frozen}); run scripts/install-tools.sh --synth"
        );
    }
}
