//! `merkur synth`: runs the open synthesis tools on a scenario's nodes and
//! writes the artifacts and a report (docs/synthesis.md).
//!
//! Targets: `ice40-hx8k` (Yosys `synth_ice40` → nextpnr-ice40 `--hx8k
//! --package ct256` → `icepack`: a bitstream, timing at the design clock),
//! `xc2c256` (Yosys `synth_coolrunner2`: macrocells and product terms; no
//! fitter exists in the open tools), `xc6s` (Yosys `synth_xilinx -family
//! xc6s`: resource counts), `xem6010` (the board top of a master or the
//! special master, its `.ucf` and an ISE script; Yosys checks and counts
//! it; with the `xem6010` cargo feature and Opal Kelly's FrontPanel HDL and
//! Xilinx ISE installed, ISE builds the bitstream).

use merkur_model::config::Config;
use merkur_model::scenario::Kind;
use merkur_rtl::boards;
use merkur_rtl::synth_top::{node_top, NodeStatic};
use merkur_rtl::xem6010;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Synthesis targets.
pub const TARGETS: [&str; 4] = ["ice40-hx8k", "xc2c256", "xc6s", "xem6010"];

/// XC2C256 limits: macrocells, product terms (16 function blocks × 56),
/// user I/O in its largest package (FT256).
const XC2C256_MC: u64 = 256;
const XC2C256_PT: u64 = 896;
const XC2C256_IO: u64 = 184;

/// One node's result.
#[derive(Serialize, Debug, Default, Clone)]
pub struct NodeResult {
    /// Ring index in the scenario.
    pub node: usize,
    /// Kind.
    pub kind: String,
    /// `ok`, `timing failed`, `does not fit` or `not attempted`.
    pub status: String,
    /// Why, when not `ok`.
    pub reason: String,
    /// LUTs (LUT4 on iCE40, LUT1–6 on Spartan-6).
    pub luts: Option<u64>,
    /// Flip-flops.
    pub ffs: Option<u64>,
    /// Block RAMs (SB_RAM40_4K on iCE40; RAMB16 + RAMB8 on Spartan-6).
    pub brams: Option<u64>,
    /// iCE40 logic cells after packing (nextpnr).
    pub lcs: Option<u64>,
    /// I/O pins used.
    pub ios: Option<u64>,
    /// Fmax of the core clock (nextpnr), MHz.
    pub fmax_mhz: Option<f64>,
    /// The line rate that Fmax allows (core clock = 2 × line rate), Mbit/s.
    pub max_line_rate_mbps: Option<f64>,
    /// CoolRunner-II macrocells (MACROCELL_XOR cells).
    pub macrocells: Option<u64>,
    /// CoolRunner-II product terms (ANDTERM cells).
    pub pterms: Option<u64>,
    /// Critical path (nets) when timing failed.
    pub critical_path: Vec<String>,
    /// Files written for this node, relative to the output folder.
    pub artifacts: Vec<String>,
}

/// The report.
#[derive(Serialize, Debug)]
pub struct Report {
    /// Command line.
    pub command: String,
    /// Scenario.
    pub scenario: String,
    /// Target.
    pub target: String,
    /// Design line rate, Mbit/s.
    pub line_rate_mbps: f64,
    /// Design core clock, MHz.
    pub clock_mhz: f64,
    /// Tool versions.
    pub tools: Vec<String>,
    /// Per node.
    pub nodes: Vec<NodeResult>,
}

/// Options of one run.
pub struct Opts<'a> {
    pub target: &'a str,
    pub nodes: &'a [usize],
    pub line_rate: Option<f64>,
    pub output: Option<&'a Path>,
    pub seed: u64,
}

fn kind_label(k: Kind) -> &'static str {
    match k {
        Kind::Sensor | Kind::Actuator => "slave",
        Kind::Master => "master",
        Kind::SpecialMaster => "special_master",
    }
}

/// The nodes a run builds: the given ones, else the special master, the
/// first master and the first slave of the ring (for the XEM6010 only
/// masters and the special master).
fn pick_nodes(cfg: &Config, given: &[usize], target: &str) -> Result<Vec<usize>, String> {
    let n = cfg.nodes.len();
    if !given.is_empty() {
        for &k in given {
            if k >= n {
                return Err(format!(
                    "error: --node {k}: the ring has nodes 0 … {}",
                    n - 1
                ));
            }
            if target == "xem6010" && matches!(cfg.nodes[k].kind, Kind::Sensor | Kind::Actuator) {
                return Err(format!(
                    "error: --node {k} is a {}; the XEM6010 top carries a master or the special master",
                    cfg.nodes[k].kind.name()
                ));
            }
        }
        return Ok(given.to_vec());
    }
    let mut out = vec![cfg.sm];
    if let Some(m) = cfg.nodes.iter().position(|x| x.kind == Kind::Master) {
        out.push(m);
    }
    if target != "xem6010" {
        if let Some(s) = cfg
            .nodes
            .iter()
            .position(|x| matches!(x.kind, Kind::Sensor | Kind::Actuator))
        {
            out.push(s);
        }
    }
    Ok(out)
}

fn run_tool(dir: &Path, prog: &str, args: &[&str], log: &str) -> Result<String, String> {
    match run_tool_status(dir, prog, args, log)? {
        (true, text) => Ok(text),
        (false, text) => {
            let tail: Vec<&str> = text.lines().rev().take(15).collect();
            Err(format!(
                "error: {prog} failed in {} (log {}):\n{}",
                dir.display(),
                log,
                tail.into_iter().rev().collect::<Vec<_>>().join("\n")
            ))
        }
    }
}

/// Runs a tool, writes its output to `log`; (exit success, output).
fn run_tool_status(
    dir: &Path,
    prog: &str,
    args: &[&str],
    log: &str,
) -> Result<(bool, String), String> {
    let o = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| format!("error: cannot run {prog}: {e} (./run test installs the tools)"))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::write(dir.join(log), &text)
        .map_err(|e| format!("error: cannot write {}: {e}", dir.join(log).display()))?;
    Ok((o.status.success(), text))
}

/// nextpnr's utilisation lines over 100 % ("ICESTORM_RAM:    54/   32").
fn pnr_overfull(log: &str) -> Vec<String> {
    log.lines()
        .filter_map(|l| {
            let (name, rest) = l.trim_start_matches("Info:").trim().split_once(':')?;
            let (used, avail) = rest.split_once('/')?;
            let used: u64 = used.trim().parse().ok()?;
            let avail: u64 = avail.split_whitespace().next()?.parse().ok()?;
            (used > avail).then(|| format!("{used} {name} of {avail}"))
        })
        .collect()
}

/// Cell counts from the last `stat` of a Yosys log: (cell type, count).
fn yosys_cells(log: &str) -> Vec<(String, u64)> {
    let start = log.rfind("Number of cells:").unwrap_or(log.len());
    log[start..]
        .lines()
        .skip(1)
        .map_while(|l| {
            let mut it = l.split_whitespace();
            let (a, b) = (it.next()?, it.next()?);
            Some((a.to_string(), b.parse::<u64>().ok()?))
        })
        .collect()
}

fn sum_cells(cells: &[(String, u64)], pred: impl Fn(&str) -> bool) -> u64 {
    cells.iter().filter(|(n, _)| pred(n)).map(|(_, c)| c).sum()
}

/// nextpnr's "ICESTORM_LC:  1593/ 7680" line.
fn pnr_used(log: &str, what: &str) -> Option<u64> {
    log.lines().find_map(|l| {
        let rest = l.split_once(&format!("{what}:"))?.1;
        rest.split('/').next()?.trim().parse().ok()
    })
}

/// Fmax of the core clock and whether it passed, from the last report.
fn pnr_fmax(log: &str) -> Option<(f64, bool)> {
    log.lines()
        .rev()
        .filter(|l| l.contains("Max frequency for clock 'clk$"))
        .find_map(|l| {
            let rest = l.split_once("': ")?.1;
            let mhz = rest.split_whitespace().next()?.parse().ok()?;
            Some((mhz, rest.contains("PASS")))
        })
}

/// The net names of the core clock's critical path.
fn pnr_critical_path(log: &str) -> Vec<String> {
    let mut out = vec![];
    let mut on = false;
    for l in log.lines() {
        if l.contains("Critical path report for clock 'clk$") {
            on = true;
            out.clear();
            out.push(l.trim_start_matches("Info: ").trim().to_string());
            continue;
        }
        if on {
            let t = l.trim_start_matches("Info:").trim();
            if t.is_empty() || t.starts_with("Critical path report") || t.starts_with("Max") {
                on = false;
            } else if t.contains(" Net ") {
                out.push(t.to_string());
            }
        }
    }
    out
}

fn write(dir: &Path, name: &str, text: &str) -> Result<(), String> {
    std::fs::write(dir.join(name), text)
        .map_err(|e| format!("error: cannot write {}: {e}", dir.join(name).display()))
}

fn ice40(
    dir: &Path,
    st: &NodeStatic,
    clock: f64,
    seed: u64,
    r: &mut NodeResult,
) -> Result<(), String> {
    write(dir, "top.v", &node_top(st)?)?;
    r.artifacts.push("top.v".into());
    let slave = matches!(st.kind, Kind::Sensor | Kind::Actuator);
    let ylog = run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_verilog top.v; synth_ice40 -top merkur_top -json top.json; stat",
        ],
        "yosys.log",
    )?;
    let cells = yosys_cells(&ylog);
    r.luts = Some(sum_cells(&cells, |n| n == "SB_LUT4"));
    r.ffs = Some(sum_cells(&cells, |n| n.starts_with("SB_DFF")));
    r.brams = Some(sum_cells(&cells, |n| n.starts_with("SB_RAM40")));
    let freq = format!("{clock}");
    let seed = seed.to_string();
    let mut args = vec![
        "--hx8k",
        "--package",
        "ct256",
        "--json",
        "top.json",
        "--asc",
        "top.asc",
        "--freq",
        &freq,
        "--seed",
        &seed,
        "--timing-allow-fail",
    ];
    if slave {
        let b = boards::ice40_hx8k_breakout();
        write(dir, "top.pcf", &boards::constraints_file(&b))?;
        r.artifacts.push("top.pcf".into());
        args.extend(["--pcf", "top.pcf"]);
    } else {
        r.reason = "I/O placed by nextpnr (no board pinout: the parallel host port is wider than the breakout's headers)".into();
    }
    let (placed, plog) = run_tool_status(dir, "nextpnr-ice40", &args, "nextpnr.log")?;
    r.lcs = pnr_used(&plog, "ICESTORM_LC");
    r.ios = pnr_used(&plog, "SB_IO");
    r.artifacts
        .extend(["top.json".into(), "yosys.log".into(), "nextpnr.log".into()]);
    if !placed {
        let over = pnr_overfull(&plog);
        if over.is_empty() {
            return Err(format!(
                "error: nextpnr-ice40 failed in {} (log nextpnr.log)",
                dir.display()
            ));
        }
        r.status = "does not fit".into();
        r.reason = format!("needs {} (iCE40-HX8K)", over.join(", "));
        return Ok(());
    }
    let (fmax, pass) = pnr_fmax(&plog).ok_or_else(|| {
        format!(
            "error: no Fmax for clk in {}",
            dir.join("nextpnr.log").display()
        )
    })?;
    r.fmax_mhz = Some(fmax);
    r.max_line_rate_mbps = Some(fmax / 2.0);
    run_tool(dir, "icepack", &["top.asc", "top.bin"], "icepack.log")?;
    r.artifacts.extend(["top.asc".into(), "top.bin".into()]);
    if pass {
        r.status = "ok".into();
    } else {
        r.status = "timing failed".into();
        r.reason = format!("Fmax {fmax:.2} MHz < {clock} MHz design clock");
        r.critical_path = pnr_critical_path(&plog);
    }
    Ok(())
}

/// `synth_coolrunner2` in its steps, with memories (ROM tables included)
/// mapped to flip-flops first and without `extract_counter`, which crashes
/// Yosys 0.23 on the nodes (`dict::at()` out of range); the T flip-flops of
/// counters are still found by the `map_tff` step.
const XC2_SCRIPT: &str =
    "read_verilog top.v; hierarchy -top merkur_top; proc; flatten; memory; opt; \
    synth_coolrunner2 -top merkur_top -run :fine; \
    techmap -map +/coolrunner2/cells_counter_map.v; clean; opt -fast -full; \
    techmap -map +/techmap.v -map +/coolrunner2/cells_latch.v; opt -fast; \
    dfflibmap -prepare -liberty +/coolrunner2/xc2_dff.lib; \
    synth_coolrunner2 -top merkur_top -run map_tff:; write_edif top.edif; stat";

fn xc2c256(dir: &Path, st: &NodeStatic, r: &mut NodeResult) -> Result<(), String> {
    if !matches!(st.kind, Kind::Sensor | Kind::Actuator) {
        r.status = "not attempted".into();
        r.reason = "a master's memories (≥ 64 kbit) cannot map to a CPLD without block RAM".into();
        return Ok(());
    }
    write(dir, "top.v", &node_top(st)?)?;
    let ylog = run_tool(dir, "yosys", &["-p", XC2_SCRIPT], "yosys.log")?;
    let cells = yosys_cells(&ylog);
    let mc = sum_cells(&cells, |n| n == "MACROCELL_XOR");
    let pt = sum_cells(&cells, |n| n == "ANDTERM");
    let io = sum_cells(&cells, |n| {
        n.starts_with("IOBUF") || n == "IBUF" || n == "OBUF"
    });
    r.macrocells = Some(mc);
    r.pterms = Some(pt);
    r.ffs = Some(sum_cells(&cells, |n| {
        n.starts_with("FD") || n.starts_with("FT") || n.starts_with("LD")
    }));
    r.ios = Some(io);
    r.artifacts
        .extend(["top.v".into(), "top.edif".into(), "yosys.log".into()]);
    let mut why = vec![];
    if mc > XC2C256_MC {
        why.push(format!("{mc} macrocells > {XC2C256_MC}"));
    }
    if pt > XC2C256_PT {
        why.push(format!("{pt} product terms > {XC2C256_PT}"));
    }
    if io > XC2C256_IO {
        why.push(format!("{io} I/O > {XC2C256_IO}"));
    }
    if why.is_empty() {
        r.status = "ok".into();
        r.reason = "within the device's macrocells, product terms and I/O (no open fitter: routing not checked)".into();
    } else {
        r.status = "does not fit".into();
        r.reason = why.join(", ");
    }
    Ok(())
}

fn xilinx_counts(r: &mut NodeResult, log: &str) {
    let cells = yosys_cells(log);
    r.luts = Some(sum_cells(&cells, |n| n.starts_with("LUT")));
    r.ffs = Some(sum_cells(&cells, |n| n.starts_with("FD")));
    r.brams = Some(sum_cells(&cells, |n| n.starts_with("RAMB")));
    r.ios = Some(sum_cells(&cells, |n| {
        n.starts_with("IBUF") || n.starts_with("OBUF") || n.starts_with("IOBUF")
    }));
}

fn xc6s(dir: &Path, st: &NodeStatic, r: &mut NodeResult) -> Result<(), String> {
    write(dir, "top.v", &node_top(st)?)?;
    let ylog = run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_verilog top.v; synth_xilinx -flatten -family xc6s -top merkur_top; write_edif top.edif; stat",
        ],
        "yosys.log",
    )?;
    xilinx_counts(r, &ylog);
    r.artifacts
        .extend(["top.v".into(), "top.edif".into(), "yosys.log".into()]);
    r.status = "ok".into();
    r.reason = "resource counts only (a Spartan-6 bitstream and timing need Xilinx ISE)".into();
    Ok(())
}

/// The ISE project script (Opal Kelly's FrontPanel files copied beside it).
const ISE_TCL: &str = "\
# Build the XEM6010 bitstream with Xilinx ISE 14.7 (see README.md here).
project new merkur_xem6010.xise
project set family Spartan6
project set device xc6slx45
project set package fgg484
project set speed -2
xfile add top.v xem6010.ucf okLibrary.v okCoreHarness.ngc okWireIn.ngc okWireOut.ngc okTriggerIn.ngc TFIFO64x8a_64x8b.ngc
project set top merkur_xem6010
process run \"Generate Programming File\" -force rerun_all
project close
";

/// FrontPanel HDL files the ISE project needs (from `$FP_PATH/XEM6010-LX45/`).
pub const FP_ASSETS: [&str; 6] = [
    "okLibrary.v",
    "okCoreHarness.ngc",
    "okWireIn.ngc",
    "okWireOut.ngc",
    "okTriggerIn.ngc",
    "TFIFO64x8a_64x8b.ngc",
];

fn xem(dir: &Path, st: &NodeStatic, r: &mut NodeResult) -> Result<(), String> {
    let top = xem6010::xem6010_verilog(st)?;
    write(dir, "top.v", &top)?;
    write(dir, "ok_blackbox.v", xem6010::OK_BLACKBOXES)?;
    let b = boards::xem6010();
    write(dir, "xem6010.ucf", &boards::constraints_file(&b))?;
    write(dir, "merkur_xem6010.tcl", ISE_TCL)?;
    write(
        dir,
        "README.md",
        &format!(
            "# XEM6010 build of node {} ({})\n\n\
             Needs Opal Kelly's FrontPanel HDL for the XEM6010-LX45 and Xilinx ISE 14.7:\n\n\
             ```sh\n\
             cp $FP_PATH/XEM6010-LX45/{{{}}} .\n\
             $ISE_PATH/xtclsh merkur_xem6010.tcl   # -> merkur_xem6010.bit\n\
             ```\n\n\
             or build merkur with `--features xem6010` (FP_PATH, ISE_PATH and\n\
             OK_FRONTPANEL_DIR set at compile time), and `merkur synth --target xem6010`\n\
             runs these steps itself. `ok_blackbox.v` is for Yosys/Verilator only.\n",
            r.node,
            r.kind,
            FP_ASSETS.join(",")
        ),
    )?;
    let ylog = run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_verilog top.v; read_verilog -lib ok_blackbox.v; synth_xilinx -flatten -family xc6s -top merkur_xem6010; stat",
        ],
        "yosys.log",
    )?;
    xilinx_counts(r, &ylog);
    r.artifacts.extend(
        [
            "top.v",
            "ok_blackbox.v",
            "xem6010.ucf",
            "merkur_xem6010.tcl",
            "README.md",
            "yosys.log",
        ]
        .map(String::from),
    );
    r.status = "ok".into();
    r.reason = ise(dir)?;
    Ok(())
}

/// Without the `xem6010` feature: what a user with ISE runs.
#[cfg(not(feature = "xem6010"))]
fn ise(_dir: &Path) -> Result<String, String> {
    Ok("top, UCF and ISE script written; the bitstream needs ISE and FrontPanel (README.md in the node folder)".into())
}

/// With the `xem6010` feature: copy FrontPanel's files (paths from
/// rust-hdl-bsp-ok-xem6010's ISE options, set at compile time) and run ISE.
#[cfg(feature = "xem6010")]
fn ise(dir: &Path) -> Result<String, String> {
    use rust_hdl_bsp_ok_xem6010::xem6010::synth::ISEOptions;
    let opts = ISEOptions::default();
    for a in &opts.assets {
        let src = Path::new(a);
        let name = src.file_name().unwrap_or_default();
        if FP_ASSETS.iter().any(|x| name == *x) {
            std::fs::copy(src, dir.join(name))
                .map_err(|e| format!("error: cannot copy {}: {e}", src.display()))?;
        }
    }
    let out = run_tool(
        dir,
        &format!("{}/xtclsh", opts.ise_path),
        &["merkur_xem6010.tcl"],
        "ise.log",
    )?;
    if out.contains("Process \"Generate Programming File\" completed successfully")
        && out.contains("All constraints were met.")
    {
        Ok("ISE: bitstream merkur_xem6010.bit, all constraints met".into())
    } else {
        Err(format!(
            "error: ISE did not finish with all constraints met: {}",
            dir.join("ise.log").display()
        ))
    }
}

fn tool_version(prog: &str, arg: &str) -> String {
    Command::new(prog)
        .arg(arg)
        .output()
        .ok()
        .map(|o| {
            let t = format!(
                "{}{}",
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            );
            t.lines().next().unwrap_or("").trim().to_string()
        })
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| format!("{prog}: not found"))
}

/// Runs the synthesis; `Ok(false)` when a node failed timing, or did not
/// fit the device of a bitstream target.
pub fn run(scenario: &Path, o: &Opts) -> Result<bool, String> {
    if !TARGETS.contains(&o.target) {
        return Err(format!(
            "error: --target {}: unknown target; targets: {}",
            o.target,
            TARGETS.join(", ")
        ));
    }
    let (_, cfg) = crate::read_scenario(scenario)?;
    let rate = match o.line_rate {
        None => cfg.line_rate_mbps,
        Some(r) if r.is_finite() && r > 0.0 && r <= 500.0 => r,
        Some(r) => {
            return Err(format!(
                "error: --line-rate {r} must be above 0 and at most 500 (Mbit/s)"
            ))
        }
    };
    let clock = 2.0 * rate;
    let nodes = pick_nodes(&cfg, o.nodes, o.target)?;
    if nodes.is_empty() {
        return Err(format!(
            "error: {}: no node to build for --target {}",
            scenario.display(),
            o.target
        ));
    }
    let out = o.output.map(PathBuf::from).unwrap_or_else(|| {
        PathBuf::from("merkur-synth").join(format!("{}-{}", cfg.name, o.target))
    });
    std::fs::create_dir_all(&out)
        .map_err(|e| format!("error: --output {}: cannot create: {e}", out.display()))?;
    let tools = vec![
        tool_version("yosys", "-V"),
        tool_version("nextpnr-ice40", "--version"),
    ];
    let mut results = vec![];
    for &k in &nodes {
        let nd = &cfg.nodes[k];
        let st = NodeStatic {
            kind: nd.kind,
            address: nd.address,
            slots: cfg.slots,
            period: cfg.period,
        };
        let label = format!("node{k}-{}", kind_label(nd.kind));
        // Built in a scratch folder and moved into place when complete.
        let tmp = out.join(format!(".{label}.{}.tmp", std::process::id()));
        let _ = std::fs::remove_dir_all(&tmp);
        std::fs::create_dir_all(&tmp)
            .map_err(|e| format!("error: cannot create {}: {e}", tmp.display()))?;
        let mut r = NodeResult {
            node: k,
            kind: nd.kind.name().to_string(),
            ..Default::default()
        };
        eprintln!("synth {}: node {k} ({}) …", o.target, r.kind);
        let res = match o.target {
            "ice40-hx8k" => ice40(&tmp, &st, clock, o.seed, &mut r),
            "xc2c256" => xc2c256(&tmp, &st, &mut r),
            "xc6s" => xc6s(&tmp, &st, &mut r),
            _ => xem(&tmp, &st, &mut r),
        };
        if let Err(e) = res {
            let keep = out.join(format!("{label}.failed"));
            let _ = std::fs::remove_dir_all(&keep);
            let _ = std::fs::rename(&tmp, &keep);
            return Err(format!("{e}\n(tool logs kept in {})", keep.display()));
        }
        let dest = out.join(&label);
        let _ = std::fs::remove_dir_all(&dest);
        std::fs::rename(&tmp, &dest)
            .map_err(|e| format!("error: cannot move {} into place: {e}", dest.display()))?;
        r.artifacts = r.artifacts.iter().map(|a| format!("{label}/{a}")).collect();
        eprintln!("  {}{}", r.status, summary(&r));
        results.push(r);
    }
    let report = Report {
        command: std::iter::once("merkur".to_string())
            .chain(std::env::args().skip(1))
            .collect::<Vec<_>>()
            .join(" "),
        scenario: scenario.display().to_string(),
        target: o.target.to_string(),
        line_rate_mbps: rate,
        clock_mhz: clock,
        tools,
        nodes: results,
    };
    let json = serde_json::to_string_pretty(&report).map_err(|e| format!("error: {e}"))?;
    crate::write_atomic(&out.join("synth.json"), &json)?;
    crate::write_atomic(&out.join("synth.md"), &markdown(&report))?;
    eprintln!(
        "wrote {} and {}",
        out.join("synth.md").display(),
        out.join("synth.json").display()
    );
    // A bitstream target fails when a node gave no usable bitstream; the
    // mapping-only targets report a device overflow as a result.
    let bitstream = o.target == "ice40-hx8k";
    Ok(report
        .nodes
        .iter()
        .all(|r| r.status != "timing failed" && !(bitstream && r.status == "does not fit")))
}

fn opt<T: std::fmt::Display>(v: &Option<T>) -> String {
    v.as_ref().map_or("—".into(), |x| x.to_string())
}

fn summary(r: &NodeResult) -> String {
    let mut s = String::new();
    if let Some(f) = r.fmax_mhz {
        s.push_str(&format!(", Fmax {f:.2} MHz"));
    }
    if let Some(m) = r.macrocells {
        s.push_str(&format!(", {m} macrocells"));
    }
    if let Some(l) = r.luts {
        s.push_str(&format!(", {l} LUTs"));
    }
    if !r.reason.is_empty() {
        s.push_str(&format!(" ({})", r.reason));
    }
    s
}

/// The Markdown report.
pub fn markdown(r: &Report) -> String {
    let mut s = format!(
        "# merkur synth: {} on {}\n\n`{}`\n\nDesign line rate {} Mbit/s, core clock {} MHz (2 × line rate; 8 samples per bit \
         by quadrature DDR capture). Tools: {}.\n\n",
        r.scenario,
        r.target,
        r.command,
        r.line_rate_mbps,
        r.clock_mhz,
        r.tools.join("; ")
    );
    s.push_str("| node | kind | status | LUTs | FFs | BRAM | LCs | I/O | Fmax MHz | max line rate Mbit/s | macrocells | product terms | note |\n");
    s.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for n in &r.nodes {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            n.node,
            n.kind,
            n.status,
            opt(&n.luts),
            opt(&n.ffs),
            opt(&n.brams),
            opt(&n.lcs),
            opt(&n.ios),
            n.fmax_mhz.map_or("—".into(), |f| format!("{f:.2}")),
            n.max_line_rate_mbps
                .map_or("—".into(), |f| format!("{f:.1}")),
            opt(&n.macrocells),
            opt(&n.pterms),
            n.reason
        ));
    }
    for n in r.nodes.iter().filter(|n| !n.critical_path.is_empty()) {
        s.push_str(&format!(
            "\n## Critical path, node {} ({})\n\n```text\n{}\n```\n",
            n.node,
            n.kind,
            n.critical_path.join("\n")
        ));
    }
    s.push_str("\n## Artifacts\n\n");
    for n in &r.nodes {
        s.push_str(&format!("- node {}: {}\n", n.node, n.artifacts.join(", ")));
    }
    s
}
