//! The FPGA bitstream flows of `merkur synth`: Yosys → nextpnr → the
//! bitstream packer for the iCE40 (`ice40-hx8k`, `ice40-hx1k`,
//! `ice40-up5k`) and the ECP5 (`ecp5-85`,
//! `ecp5-45`), over one or more placement seeds, with the results read
//! from the tools' machine-readable output (Yosys `stat -json`, nextpnr
//! `--report`), never from their logs.
//!
//! Two tool sets (`--flow`): `yowasp` (the default: Yosys and nextpnr from
//! PyPI, scripts/requirements-synth.txt, in .tools/venv) and `debian`
//! (Yosys 0.23 and nextpnr-ice40 0.4 of scripts/tools.lock; iCE40 only).
//! docs/synthesis.md compares them on the same nodes.

use super::{write, BlockRam, NodeResult};
use merkur_rtl::top::synth_top::{node_top, NodeStatic};
use merkur_rtl::top::{boards, ulx3s};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Which tools run (`--flow`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Flow {
    /// YoWASP's Yosys and nextpnr (PyPI, WebAssembly): the pinned tools in .tools/venv.
    Yowasp,
    /// Debian bookworm's Yosys 0.23 and nextpnr-ice40 0.4 (iCE40 only).
    Debian,
}

impl Flow {
    /// Its `--flow` name.
    pub fn name(self) -> &'static str {
        match self {
            Flow::Yowasp => "yowasp",
            Flow::Debian => "debian",
        }
    }

    /// The command of a tool (`yosys`, `nextpnr-ice40`, `icepack`, …).
    pub fn tool(self, name: &str) -> String {
        match self {
            Flow::Yowasp => format!("yowasp-{name}"),
            Flow::Debian => name.to_string(),
        }
    }
}

/// FPGA families.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Lattice iCE40.
    Ice40,
    /// Lattice ECP5.
    Ecp5,
}

/// One FPGA target.
#[derive(Clone, Debug)]
pub struct Fpga {
    /// Family.
    pub family: Family,
    /// nextpnr's device option (`--hx8k`, `--85k`).
    pub device_arg: &'static str,
    /// Package.
    pub package: &'static str,
    /// Speed grade (ECP5: 6, 7 or 8).
    pub speed: Option<u8>,
    /// Block RAM.
    pub bram: BlockRam,
    /// Yosys option sets for the family's `synth_*` command, tried in order
    /// until one gives a netlist that places on at least one seed and meets
    /// the design clock there (see [`STRATEGIES_TIGHT`], [`STRATEGIES_HX8K`]);
    /// `""` is Yosys' default.
    pub strategies: &'static [&'static str],
}

/// Yosys' defaults: the one strategy of the devices a node fits with room
/// to spare.
pub const STRATEGIES_DEFAULT: &[&str] = &[""];

/// For a device the lean slave fills to 95–99 % (the iCE40-HX1K), after
/// Yosys' default: clock enables only where 16 or more flip-flops share one,
/// without carry chains (the quick one: about 4 s of Yosys, where ABC9's
/// sequential mode `-dff` takes about 2 min on the slave in YoWASP's Yosys;
/// the lean actuator fits with it, the lean sensor needs 12 cells too
/// many since its fresh word's hold flip-flop); then ABC9's sequential mode
/// without carry chains and without clock-enable flip-flops (the fewest
/// control sets, so nextpnr can pack eight cells to a logic block; with
/// `-dff` alone the sets need more blocks than the device has); last that
/// with clock enables where 16 share one. A `-dff` strategy that crashes
/// (YoWASP's WebAssembly stack, unless the venv's `sitecustomize.py`
/// enlarged it: docs/synthesis.md) hands on to the next. ABC's mapping
/// moves by a few cells with the text it reads, so which one fits a node
/// moves too. Measured in docs/benchmarks.md ("The smallest iCE40").
pub const STRATEGIES_TIGHT: &[&str] = &[
    "",
    "-nocarry -dffe_min_ce_use 16",
    "-dff -nocarry -nodffe",
    "-dff -nocarry -dffe_min_ce_use 16",
];

/// For the HX8K, where every node fits with room to spare: Yosys' defaults,
/// then, for a node they leave below the design clock, clock enables put
/// into LUTs (`-nodffe`: fewer control sets, so nextpnr packs and places
/// more freely; the special master with retransmission on demand misses
/// 100 MHz with the first and meets it with the second, docs/benchmarks.md).
pub const STRATEGIES_HX8K: &[&str] = &["", "-nodffe"];

/// For the slow UP5K: the sequential mapping first (faster: docs/benchmarks.md),
/// Yosys' default where it crashes.
pub const STRATEGIES_FAST_FIRST: &[&str] = &["-dff -nocarry -nodffe", ""];

/// ECP5 speed grades nextpnr-ecp5 knows.
pub const ECP5_SPEEDS: [u8; 3] = [6, 7, 8];

/// The FPGA of a target name, `None` for targets without a bitstream flow.
pub fn fpga(target: &str, speed: Option<u8>) -> Option<Fpga> {
    let ecp5 = |device_arg, device, count| Fpga {
        family: Family::Ecp5,
        device_arg,
        package: "CABGA381",
        speed: Some(speed.unwrap_or(8)),
        bram: BlockRam {
            device,
            cell: "DP16KD",
            count,
            // 18 kbit in the ×9/×18 configurations.
            bits: 18432,
        },
        strategies: STRATEGIES_DEFAULT,
    };
    let ice40 = |device_arg, package, device, count, strategies| Fpga {
        family: Family::Ice40,
        device_arg,
        package,
        speed: None,
        bram: BlockRam {
            device,
            cell: "SB_RAM40_4K",
            count,
            bits: 4096,
        },
        strategies,
    };
    match target {
        "ice40-hx8k" => Some(ice40("--hx8k", "ct256", "iCE40-HX8K", 32, STRATEGIES_HX8K)),
        // The smallest HX (1,280 logic cells), in its largest package.
        "ice40-hx1k" => Some(ice40("--hx1k", "tq144", "iCE40-HX1K", 16, STRATEGIES_TIGHT)),
        // The UltraPlus (5,280 logic cells, slower), in its QFN-48.
        "ice40-up5k" => Some(ice40(
            "--up5k",
            "sg48",
            "iCE40-UP5K",
            30,
            STRATEGIES_FAST_FIRST,
        )),
        "ecp5-85" => Some(ecp5("--85k", "LFE5U-85F", 208)),
        "ecp5-45" => Some(ecp5("--45k", "LFE5U-45F", 108)),
        _ => None,
    }
}

/// One clock's timing over the seeds.
#[derive(Serialize, Debug, Clone, Default)]
pub struct ClockTiming {
    /// The clock net as nextpnr names it.
    pub name: String,
    /// The constraint, MHz.
    pub constraint_mhz: f64,
    /// Fmax per seed (in the order of `NodeResult::seeds`), MHz.
    pub fmax_mhz: Vec<f64>,
}

/// The core clock among nextpnr's clock names: the net named after the
/// node top's `clk` port (`clk$SB_IO_IN_$glb_clk`,
/// `$glbnet$clk$TRELLIS_IO_IN`) or, inside a board top that makes it with
/// a PLL, after the port it drives (`$glbnet$node.cap_pi.clk`).
fn is_core_clock(name: &str) -> bool {
    // Critical paths name their ends with the edge: "posedge clk$…".
    let n = name
        .trim_start_matches("posedge ")
        .trim_start_matches("negedge ")
        .trim_start_matches("$glbnet$");
    n == "clk" || n.starts_with("clk$") || n.ends_with(".clk")
}

/// The capture edge a critical path's end names (`negedge clk90$…`), in
/// quarters of the core clock after `clk` rises: `clk` ↑ 0, `clk90` ↑ 1,
/// `clk` ↓ 2, `clk90` ↓ 3; `None` for another clock or `<async>`.
fn capture_edge(end: &str) -> Option<u32> {
    let (edge, clock) = end.split_once(' ')?;
    let n = clock.trim_start_matches("$glbnet$");
    let clk90 = n == "clk90" || n.starts_with("clk90$") || n.ends_with(".clk90");
    let q = match (clk90, is_core_clock(clock), edge) {
        (true, _, "posedge") => 1,
        (true, _, "negedge") => 3,
        (false, true, "posedge") => 0,
        (false, true, "negedge") => 2,
        _ => return None,
    };
    Some(q)
}

/// The core clock the quadrature capture's transfers allow, MHz, and the
/// transfer that sets it (`negedge clk90 → posedge clk: 1.60 ns in 1/4
/// of a clock`). nextpnr takes `clk` and `clk90` for unrelated clocks: it
/// reports the paths between them but holds them to no constraint, and
/// its Fmax of `clk` leaves them out. A path from one capture edge to the
/// next has the quarters of a clock between them, so its delay (clock to
/// output, routing, setup; both clocks on global networks) × 4 / quarters
/// is a clock period it needs. `None` when the report has no such path.
fn quadrature_fmax(report: &serde_json::Value) -> Option<(f64, String)> {
    let paths = report["critical_paths"].as_array()?;
    paths
        .iter()
        .filter_map(|p| {
            let (from, to) = (p["from"].as_str()?, p["to"].as_str()?);
            let (a, b) = (capture_edge(from)?, capture_edge(to)?);
            if a % 2 == 0 && b % 2 == 0 {
                return None; // clk to clk: in nextpnr's Fmax
            }
            let quarters = super::capture_quarters(a, b);
            let ns: f64 = p["path"]
                .as_array()?
                .iter()
                .filter_map(|s| s["delay"].as_f64())
                .sum();
            let mhz = 1000.0 * f64::from(quarters) / (4.0 * ns);
            let what = format!(
                "{} → {}: {ns:.2} ns in {quarters}/4 of a clock",
                from.split('$').next().unwrap_or(from),
                to.split('$').next().unwrap_or(to)
            );
            Some((mhz, what))
        })
        .min_by(|x, y| x.0.total_cmp(&y.0))
}

/// Runs a tool in `dir` (YoWASP tools see only that folder), its output in
/// `log`; (exit success, output).
pub fn run_tool_status(
    dir: &Path,
    prog: &str,
    args: &[&str],
    log: &str,
) -> Result<(bool, String), String> {
    let o = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| {
            format!(
                "error: cannot run {prog}: {e} (scripts/ensure-tools.sh installs the tools; \
                 the YoWASP ones go to .tools/venv/bin, which ./run puts on PATH)"
            )
        })?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    write(dir, log, &text)?;
    Ok((o.status.success(), text))
}

/// As [`run_tool_status`], but stopped after `limit` (then `None`): for a
/// tool that may search for a long time without an answer.
fn run_tool_limited(
    dir: &Path,
    prog: &str,
    args: &[&str],
    log: &str,
    limit: std::time::Duration,
) -> Result<Option<(bool, String)>, String> {
    let path = dir.join(log);
    let file = std::fs::File::create(&path)
        .map_err(|e| format!("error: cannot write {}: {e}", path.display()))?;
    let err = file
        .try_clone()
        .map_err(|e| format!("error: cannot write {}: {e}", path.display()))?;
    let mut child = Command::new(prog)
        .args(args)
        .current_dir(dir)
        .stdout(file)
        .stderr(err)
        .spawn()
        .map_err(|e| format!("error: cannot run {prog}: {e}"))?;
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(st) = child
            .try_wait()
            .map_err(|e| format!("error: {prog}: {e}"))?
        {
            break Some(st);
        }
        if start.elapsed() >= limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(std::time::Duration::from_millis(200));
    };
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    Ok(status.map(|st| (st.success(), text)))
}

/// How long nextpnr's SA placer may look for a placement the heap placer
/// could not legalise (on the HX1K it takes about 10 s when one exists;
/// where none exists it can search far longer).
const SA_LIMIT: std::time::Duration = std::time::Duration::from_secs(300);

/// As [`run_tool_status`], an error with the log's tail when it fails.
pub fn run_tool(dir: &Path, prog: &str, args: &[&str], log: &str) -> Result<String, String> {
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

pub fn read_json(dir: &Path, name: &str) -> Result<serde_json::Value, String> {
    let p = dir.join(name);
    let text = std::fs::read_to_string(&p)
        .map_err(|e| format!("error: cannot read {}: {e}", p.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("error: {}: {e}", p.display()))
}

/// The `merkur_top` module of a Yosys JSON file (`stat -json` or
/// `write_json`), whether or not Yosys escaped its name.
pub fn yosys_top(json: &serde_json::Value) -> Option<&serde_json::Value> {
    json["modules"].as_object().and_then(|m| {
        m.iter()
            .find(|(k, _)| k.trim_start_matches('\\') == "merkur_top")
            .map(|(_, v)| v)
    })
}

/// Cell counts of the top module from Yosys' `stat -json`.
pub fn yosys_cells(stat: &serde_json::Value) -> Vec<(String, u64)> {
    let m = yosys_top(stat).unwrap_or(&stat["design"]);
    m["num_cells_by_type"]
        .as_object()
        .map(|o| {
            o.iter()
                .filter_map(|(k, v)| Some((k.clone(), v.as_u64()?)))
                .collect()
        })
        .unwrap_or_default()
}

/// Sum of the cells whose type matches.
pub fn sum_cells(cells: &[(String, u64)], pred: impl Fn(&str) -> bool) -> u64 {
    cells.iter().filter(|(n, _)| pred(n)).map(|(_, c)| c).sum()
}

/// nextpnr's utilisation lines in its log ("ICESTORM_RAM: 54/ 32"), as
/// (cell type, used, available): nextpnr writes no report when it cannot
/// place, so this is the one place the log is read.
fn pnr_utilisation(log: &str) -> impl Iterator<Item = (&str, u64, u64)> {
    log.lines().filter_map(|l| {
        let (name, rest) = l.trim_start_matches("Info:").trim().split_once(':')?;
        let (used, avail) = rest.split_once('/')?;
        let used: u64 = used.trim().parse().ok()?;
        let avail: u64 = avail.split_whitespace().next()?.parse().ok()?;
        Some((name.trim(), used, avail))
    })
}

/// The cell types over 100 %, as "54 ICESTORM_RAM of 32".
fn pnr_overfull(log: &str) -> Vec<String> {
    pnr_utilisation(log)
        .filter(|&(_, used, avail)| used > avail)
        .map(|(name, used, avail)| format!("{used} {name} of {avail}"))
        .collect()
}

/// One cell type's use, as "1179 of 1280 ICESTORM_LC".
fn pnr_usage(log: &str, cell: &str) -> Option<String> {
    pnr_utilisation(log)
        .find(|&(name, _, _)| name == cell)
        .map(|(_, used, avail)| format!("{used} of {avail} {cell}"))
}

/// The core clock's critical path from a nextpnr report (with
/// `--detailed-timing-report`): one line per step, delay and net.
fn critical_path(report: &serde_json::Value) -> Vec<String> {
    let Some(paths) = report["critical_paths"].as_array() else {
        return vec![];
    };
    let Some(p) = paths.iter().find(|p| {
        is_core_clock(p["from"].as_str().unwrap_or(""))
            && is_core_clock(p["to"].as_str().unwrap_or(""))
    }) else {
        return vec![];
    };
    p["path"]
        .as_array()
        .map(|steps| {
            steps
                .iter()
                .map(|s| {
                    let cell = |e: &str| s[e]["cell"].as_str().unwrap_or("").to_string();
                    format!(
                        "{:6.2} ns {:9} {} → {}{}",
                        s["delay"].as_f64().unwrap_or(0.0),
                        s["type"].as_str().unwrap_or(""),
                        cell("from"),
                        cell("to"),
                        s["net"]
                            .as_str()
                            .map(|n| format!(" (net {n})"))
                            .unwrap_or_default()
                    )
                })
                .collect()
        })
        .unwrap_or_default()
}

/// Yosys' script for a family: reads `files`, synthesizes `top` with the
/// options `opts` (a strategy of [`Fpga::strategies`]).
fn yosys_script(family: Family, files: &[&str], top: &str, opts: &str) -> String {
    // The defaults of each Yosys: 0.70 maps with ABC9 by default, 0.23
    // with ABC. (`-dff`, ABC9's sequential mode, aborted on some nodes with
    // Yosys 0.70 under wasmtime's default WebAssembly stack: the masters,
    // the lean actuator; the synthesis venv enlarges it, docs/synthesis.md;
    // a strategy list goes on to the next one after a crash.)
    let synth = synth_command(family);
    let opts = if opts.is_empty() {
        String::new()
    } else {
        format!(" {opts}")
    };
    format!(
        "read_verilog {}; {synth}{opts} -top {top} -json top.json; tee -q -o stat.json stat -json",
        files.join(" ")
    )
}

/// Yosys' synthesis command for a family.
fn synth_command(family: Family) -> &'static str {
    match family {
        Family::Ice40 => "synth_ice40",
        Family::Ecp5 => "synth_ecp5",
    }
}

/// A strategy's name in reports.
fn strategy_name(family: Family, opts: &str) -> String {
    let synth = synth_command(family);
    if opts.is_empty() {
        format!("`{synth}` (Yosys' defaults)")
    } else {
        format!("`{synth} {opts}`")
    }
}

/// Writes the node's Verilog (the board's top when the node goes on a
/// board) and its constraints; (files Yosys reads, top module, nextpnr's
/// constraint arguments).
fn sources(
    dir: &Path,
    st: &NodeStatic,
    board: Option<&boards::Board>,
    flow: Flow,
    clock: f64,
    r: &mut NodeResult,
) -> Result<(Vec<&'static str>, &'static str, Vec<String>), String> {
    let Some(b) = board else {
        write(dir, "top.v", &node_top(st)?)?;
        r.artifacts.push("top.v".into());
        r.reason = "I/O placed by nextpnr (no board pinout for this node and device)".into();
        return Ok((vec!["top.v"], "merkur_top", vec![]));
    };
    write(dir, b.file, &boards::constraints_file(b))?;
    r.artifacts.extend(["top.v".into(), b.file.to_string()]);
    if b.name == "ulx3s" {
        write(dir, "top.v", &ulx3s::ulx3s_verilog(st)?)?;
        // Project Trellis' PLL calculator: clk and clk90 from 25 MHz.
        let f = format!("{clock}");
        run_tool(
            dir,
            &flow.tool("ecppll"),
            &[
                "-n",
                "merkur_pll",
                "--clkin_name",
                "clk_25mhz",
                "-i",
                "25",
                "--clkout0_name",
                "clk",
                "-o",
                &f,
                "--clkout1_name",
                "clk90",
                "--clkout1",
                &f,
                "--phase1",
                "90",
                "-f",
                "pll.v",
            ],
            "ecppll.log",
        )?;
        r.artifacts.extend(["pll.v".into(), "ecppll.log".into()]);
        r.reason = format!("on the ULX3S ({}), clocks from its PLL", b.file);
        Ok((
            vec!["pll.v", "top.v"],
            "merkur_ulx3s",
            vec!["--lpf".into(), b.file.into()],
        ))
    } else {
        write(dir, "top.v", &node_top(st)?)?;
        r.reason = format!("pins of {} ({})", b.name, b.file);
        Ok((
            vec!["top.v"],
            "merkur_top",
            vec!["--pcf".into(), b.file.into()],
        ))
    }
}

/// What one synthesis strategy gave.
enum Outcome {
    /// Placed on at least one seed: the best seed's index in `r.seeds` and
    /// its core-clock Fmax.
    Placed(usize, f64),
    /// It does not fit: why ("it needs …", or the placer's verdict).
    DoesNotFit(String),
    /// Yosys failed: the last line of its log.
    YosysFailed(String),
}

/// Builds one node: per strategy ([`Fpga::strategies`]) Yosys once and
/// nextpnr once per seed, until a strategy's netlist places and meets the
/// design clock on its best seed; when none meets it, the fastest strategy
/// that placed is kept. Then the bitstream of the kept strategy's best
/// seed. `r` gets the resources, every clock's Fmax per placed seed, the
/// strategy, the status, the critical path when timing failed, and in its
/// notes what the other strategies gave.
#[allow(clippy::too_many_arguments)]
pub fn build(
    dir: &Path,
    st: &NodeStatic,
    f: &Fpga,
    board: Option<&boards::Board>,
    flow: Flow,
    clock: f64,
    seeds: &[u64],
    r: &mut NodeResult,
) -> Result<(), String> {
    let (files, top, pins) = sources(dir, st, board, flow, clock, r)?;
    let base = r.artifacts.len();
    let mut tried: Vec<String> = vec![];
    let mut misfit: Option<String> = None;
    let mut aside: Option<Aside> = None;
    let job = Job {
        dir,
        f,
        flow,
        files: &files,
        top,
        pins: &pins,
        clock,
    };
    for (k, opts) in f.strategies.iter().enumerate() {
        r.artifacts.truncate(base);
        r.seeds.clear();
        r.clocks.clear();
        r.notes.clear();
        r.critical_path.clear();
        let name = strategy_name(f.family, opts);
        r.strategy = name.clone();
        match job.strategy(opts, seeds, r)? {
            Outcome::Placed(bi, fmax) if fmax >= clock => {
                if let Some(a) = aside.take() {
                    a.discard()?;
                }
                if !tried.is_empty() {
                    r.notes
                        .insert(0, format!("before it: {}", tried.join("; ")));
                }
                return job.finish(bi, fmax, r);
            }
            Outcome::Placed(bi, fmax) => {
                tried.push(format!(
                    "{name}: Fmax {fmax:.2} MHz (best of {} placed seeds) < {clock} MHz",
                    r.seeds.len()
                ));
                let own = &r.artifacts[base..];
                if aside.as_ref().is_some_and(|a| a.fmax >= fmax) {
                    remove_files(dir, own)?;
                } else {
                    if let Some(a) = aside.take() {
                        a.discard()?;
                    }
                    aside = Some(Aside::keep(dir, k, own, r.clone(), bi, fmax)?);
                }
            }
            Outcome::DoesNotFit(why) => {
                tried.push(format!("{name}: {why}"));
                misfit = Some(why);
            }
            Outcome::YosysFailed(tail) => tried.push(format!("{name}: Yosys failed ({tail})")),
        }
    }
    if let Some(a) = aside {
        // No strategy met the clock: the fastest one's files go back.
        let (bi, fmax) = (a.bi, a.fmax);
        *r = a.restore()?;
        if tried.len() > 1 {
            r.notes
                .insert(0, format!("Yosys strategies tried: {}", tried.join("; ")));
        }
        return job.finish(bi, fmax, r);
    }
    let Some(why) = misfit else {
        return Err(format!(
            "error: {} failed in {} (log yosys.log): {}",
            flow.tool("yosys"),
            dir.display(),
            tried.join("; ")
        ));
    };
    r.status = "does not fit".into();
    r.reason = if tried.len() == 1 {
        why
    } else {
        format!("{why} (Yosys strategies tried: {})", tried.join("; "))
    };
    Ok(())
}

/// A strategy that placed but missed the design clock, set aside while the
/// next ones are tried: its report and its files (moved to a folder of
/// their own, since the next strategy writes the same names).
struct Aside {
    dir: PathBuf,
    folder: PathBuf,
    files: Vec<String>,
    r: NodeResult,
    bi: usize,
    fmax: f64,
}

impl Aside {
    /// Moves `files` of `dir` to `dir/strategy-<k>`.
    fn keep(
        dir: &Path,
        k: usize,
        files: &[String],
        r: NodeResult,
        bi: usize,
        fmax: f64,
    ) -> Result<Self, String> {
        let folder = dir.join(format!("strategy-{k}"));
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("error: cannot create {}: {e}", folder.display()))?;
        move_files(dir, &folder, files)?;
        Ok(Aside {
            dir: dir.to_path_buf(),
            folder,
            files: files.to_vec(),
            r,
            bi,
            fmax,
        })
    }

    /// Its files back in place (over the later strategy's), its report.
    fn restore(self) -> Result<NodeResult, String> {
        remove_files(&self.dir, &self.files)?;
        move_files(&self.folder, &self.dir, &self.files)?;
        self.discard()?;
        Ok(self.r)
    }

    /// Its folder removed (a faster strategy replaces it, or its files
    /// are back in place).
    fn discard(&self) -> Result<(), String> {
        std::fs::remove_dir_all(&self.folder)
            .map_err(|e| format!("error: cannot remove {}: {e}", self.folder.display()))
    }
}

/// Moves the named files (those that exist) from `from` to `to`.
fn move_files(from: &Path, to: &Path, files: &[String]) -> Result<(), String> {
    for name in files {
        let src = from.join(name);
        if src.exists() {
            std::fs::rename(&src, to.join(name))
                .map_err(|e| format!("error: cannot move {}: {e}", src.display()))?;
        }
    }
    Ok(())
}

/// Removes the named files of `dir` (those that exist).
fn remove_files(dir: &Path, files: &[String]) -> Result<(), String> {
    for name in files {
        let p = dir.join(name);
        if p.exists() {
            std::fs::remove_file(&p)
                .map_err(|e| format!("error: cannot remove {}: {e}", p.display()))?;
        }
    }
    Ok(())
}

/// One node's build: where, with what, for which clock.
struct Job<'a> {
    dir: &'a Path,
    f: &'a Fpga,
    flow: Flow,
    files: &'a [&'static str],
    top: &'static str,
    pins: &'a [String],
    clock: f64,
}

impl Job<'_> {
    /// Yosys with `opts`, then nextpnr on every seed (the heap placer, and
    /// the simulated-annealing one for a seed the heap placer cannot
    /// legalise: on a nearly full device it still finds a placement).
    fn strategy(&self, opts: &str, seeds: &[u64], r: &mut NodeResult) -> Result<Outcome, String> {
        let (dir, f) = (self.dir, self.f);
        let (ok, ylog) = run_tool_status(
            dir,
            &self.flow.tool("yosys"),
            &["-p", &yosys_script(f.family, self.files, self.top, opts)],
            "yosys.log",
        )?;
        r.artifacts.push("yosys.log".into());
        if !ok {
            let last = ylog.lines().rev().find(|l| !l.trim().is_empty());
            return Ok(Outcome::YosysFailed(
                last.unwrap_or("no output").trim().to_string(),
            ));
        }
        let cells = yosys_cells(&read_json(dir, "stat.json")?);
        let (lut, ff, ram) = match f.family {
            Family::Ice40 => ("SB_LUT4", "SB_DFF", "SB_RAM40"),
            Family::Ecp5 => ("LUT4", "TRELLIS_FF", "DP16KD"),
        };
        r.luts = Some(sum_cells(&cells, |n| n == lut));
        r.ffs = Some(sum_cells(&cells, |n| n.starts_with(ff)));
        r.brams = Some(sum_cells(&cells, |n| n.starts_with(ram)));
        r.brams_available = Some(f.bram.count);
        r.artifacts
            .extend(["top.json", "stat.json"].map(String::from));
        let mut best: Option<(usize, f64)> = None;
        let mut unplaced = String::new();
        for &seed in seeds {
            let mut placed = false;
            let mut why_unplaced = "no legal placement (heap and SA placers)".to_string();
            for placer in ["heap", "sa"] {
                let log = format!("nextpnr-s{seed}.log");
                if !r.artifacts.contains(&log) {
                    r.artifacts.push(log.clone());
                }
                let Some((done, plog)) = self.place(seed, placer)? else {
                    why_unplaced = format!(
                        "the heap placer found no legal placement, the SA placer none in {} s (stopped)",
                        SA_LIMIT.as_secs()
                    );
                    break;
                };
                if done {
                    placed = true;
                    if placer == "sa" {
                        r.notes.push(format!(
                            "seed {seed}: placed by nextpnr's SA placer (the heap placer found \
                             no legal placement)"
                        ));
                    }
                    break;
                }
                let over = pnr_overfull(&plog);
                if !over.is_empty() {
                    return Ok(Outcome::DoesNotFit(format!("it needs {}", over.join(", "))));
                }
                if !plog.contains("Unable to find legal placement")
                    && !plog.contains("failed to place")
                {
                    return Err(format!(
                        "error: {} failed in {} (log {log})",
                        self.flow.tool(self.pnr()),
                        dir.display()
                    ));
                }
                unplaced =
                    pnr_usage(&plog, self.lc()).unwrap_or_else(|| format!("its {}s", self.lc()));
            }
            if !placed {
                r.notes.push(format!("seed {seed}: {why_unplaced}"));
                continue;
            }
            let report = format!("report-s{seed}.json");
            r.artifacts.extend([report.clone(), self.placed_file(seed)]);
            let rep = read_json(dir, &report)?;
            read_timing(&rep, seed, r.seeds.len(), r)?;
            read_utilisation(&rep, f.family, r);
            let fmax = r.fmax_mhz.unwrap_or(0.0);
            if best.map_or(true, |(_, b)| fmax > b) {
                best = Some((r.seeds.len(), fmax));
                r.critical_path = critical_path(&rep);
            }
            r.seeds.push(seed);
        }
        Ok(match best {
            Some((i, fmax)) => Outcome::Placed(i, fmax),
            None => Outcome::DoesNotFit(format!(
                "nextpnr found no legal placement with {unplaced} (\"design is probably at \
                 utilisation limit\"; heap and SA placers, seeds {seeds:?})"
            )),
        })
    }

    fn pnr(&self) -> &'static str {
        match self.f.family {
            Family::Ice40 => "nextpnr-ice40",
            Family::Ecp5 => "nextpnr-ecp5",
        }
    }

    fn lc(&self) -> &'static str {
        match self.f.family {
            Family::Ice40 => "ICESTORM_LC",
            Family::Ecp5 => "TRELLIS_COMB",
        }
    }

    /// The placed-and-routed design's file of a seed.
    fn placed_file(&self, seed: u64) -> String {
        match self.f.family {
            Family::Ice40 => format!("top-s{seed}.asc"),
            Family::Ecp5 => format!("top-s{seed}.config"),
        }
    }

    /// nextpnr on one seed with one placer: (placed and routed, its log);
    /// `None` when the SA placer ran out of time ([`SA_LIMIT`]).
    fn place(&self, seed: u64, placer: &str) -> Result<Option<(bool, String)>, String> {
        let f = self.f;
        let s = seed.to_string();
        let out_arg = match f.family {
            Family::Ice40 => "--asc",
            Family::Ecp5 => "--textcfg",
        };
        let out_file = self.placed_file(seed);
        let report = format!("report-s{seed}.json");
        let speed = f.speed.map(|x| x.to_string());
        let freq = format!("{}", self.clock);
        let mut args: Vec<&str> = vec![f.device_arg, "--package", f.package];
        if let Some(sp) = &speed {
            args.extend(["--speed", sp]);
        }
        args.extend([
            "--json",
            "top.json",
            out_arg,
            &out_file,
            "--freq",
            &freq,
            "--seed",
            &s,
            "--placer",
            placer,
            "--timing-allow-fail",
            "--report",
            &report,
            "--detailed-timing-report",
        ]);
        args.extend(self.pins.iter().map(String::as_str));
        let (prog, log) = (self.flow.tool(self.pnr()), format!("nextpnr-s{seed}.log"));
        if placer == "sa" {
            return run_tool_limited(self.dir, &prog, &args, &log, SA_LIMIT);
        }
        run_tool_status(self.dir, &prog, &args, &log).map(Some)
    }

    /// The bitstream of the best seed (`bi` in `r.seeds`), the timing
    /// summary and the status.
    fn finish(&self, bi: usize, fmax: f64, r: &mut NodeResult) -> Result<(), String> {
        let (dir, clock) = (self.dir, self.clock);
        let core = r
            .clocks
            .iter()
            .find(|c| is_core_clock(&c.name))
            .ok_or_else(|| {
                format!(
                    "error: no core clock in {}",
                    dir.join("report-s*.json").display()
                )
            })?;
        r.fmax_mhz = Some(fmax);
        r.max_line_rate_mbps = Some(fmax / 2.0);
        r.fmax_min_mhz = core.fmax_mhz.iter().cloned().reduce(f64::min);
        r.fmax_median_mhz = median(&core.fmax_mhz);
        let seed = r.seeds[bi];
        r.seed = Some(seed);
        let (pack, bit) = match self.f.family {
            Family::Ice40 => ("icepack", "top.bin"),
            Family::Ecp5 => ("ecppack", "top.bit"),
        };
        run_tool(
            dir,
            &self.flow.tool(pack),
            &[&self.placed_file(seed), bit],
            &format!("{pack}.log"),
        )?;
        r.artifacts.push(bit.into());
        if fmax >= clock {
            r.status = "ok".into();
            r.critical_path.clear();
        } else {
            r.status = "timing failed".into();
            r.reason = format!(
                "Fmax {fmax:.2} MHz < {clock} MHz design clock (best of {} placed seeds)",
                r.seeds.len()
            );
        }
        Ok(())
    }
}

/// The middle value (the mean of the two middle ones for an even count).
fn median(v: &[f64]) -> Option<f64> {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(s[n / 2]),
        _ => Some((s[n / 2 - 1] + s[n / 2]) / 2.0),
    }
}

/// Every clock's Fmax from the report of `seed` (index `i` in
/// `r.seeds`); the core clock's, bounded by the quadrature capture's
/// transfers ([`quadrature_fmax`], with a note when they set it), goes to
/// `r.fmax_mhz` for this seed.
fn read_timing(
    rep: &serde_json::Value,
    seed: u64,
    i: usize,
    r: &mut NodeResult,
) -> Result<(), String> {
    let clocks = rep["fmax"]
        .as_object()
        .ok_or("error: nextpnr report without fmax")?;
    r.fmax_mhz = None;
    for (name, v) in clocks {
        let achieved = v["achieved"].as_f64().unwrap_or(0.0);
        let c = match r.clocks.iter_mut().find(|c| &c.name == name) {
            Some(c) => c,
            None => {
                r.clocks.push(ClockTiming {
                    name: name.clone(),
                    constraint_mhz: v["constraint"].as_f64().unwrap_or(0.0),
                    fmax_mhz: vec![],
                });
                r.clocks.last_mut().expect("pushed")
            }
        };
        c.fmax_mhz.resize(i, f64::NAN);
        if is_core_clock(name) {
            // The capture's transfers between clk and clk90 bound it too.
            let core = match quadrature_fmax(rep) {
                Some((q, what)) if q < achieved => {
                    r.notes.push(format!(
                        "seed {seed}: the quadrature capture's {what} allows {q:.2} MHz \
                         (nextpnr's Fmax of the core clock alone: {achieved:.2} MHz)"
                    ));
                    q
                }
                _ => achieved,
            };
            c.fmax_mhz.push(core);
            r.fmax_mhz = Some(core);
        } else {
            c.fmax_mhz.push(achieved);
        }
    }
    Ok(())
}

/// Logic cells and I/O used and available from a report.
fn read_utilisation(rep: &serde_json::Value, family: Family, r: &mut NodeResult) {
    let u = &rep["utilization"];
    let get = |k: &str| (u[k]["used"].as_u64(), u[k]["available"].as_u64());
    let (lc, io) = match family {
        Family::Ice40 => ("ICESTORM_LC", "SB_IO"),
        Family::Ecp5 => ("TRELLIS_COMB", "TRELLIS_IO"),
    };
    (r.lcs, r.lcs_available) = get(lc);
    r.ios = get(io).0;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tool that runs past its limit is stopped and reported as such; one
    /// that ends in time gives its status and output.
    #[test]
    fn a_limited_tool_is_stopped_at_its_limit() {
        let dir = std::env::temp_dir().join(format!("merkur-limit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let limit = std::time::Duration::from_millis(500);
        let t = std::time::Instant::now();
        let r = run_tool_limited(&dir, "sleep", &["30"], "sleep.log", limit).unwrap();
        assert!(r.is_none());
        assert!(t.elapsed() < std::time::Duration::from_secs(10));
        let r = run_tool_limited(
            &dir,
            "sh",
            &["-c", "echo placed; exit 3"],
            "sh.log",
            std::time::Duration::from_secs(10),
        )
        .unwrap();
        assert_eq!(r, Some((false, "placed\n".to_string())));
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A report shaped like nextpnr-ice40's (names as it writes them): the
    /// core clock's own path is left to its Fmax; of the capture's
    /// transfers, 1.6 ns in a quarter clock (156.25 MHz) binds before
    /// 1.5 ns in three quarters (500 MHz); `<async>` and other clocks are
    /// not capture edges.
    #[test]
    fn quadrature_transfers_bound_the_core_clock() {
        let path = |from: &str, to: &str, steps: &[f64]| {
            let steps: Vec<_> = steps
                .iter()
                .map(|d| serde_json::json!({"delay": d, "type": "routing"}))
                .collect();
            serde_json::json!({"from": from, "to": to, "path": steps})
        };
        let (clk, clk90) = ("clk$SB_IO_IN_$glb_clk", "clk90$SB_IO_IN_$glb_clk");
        let rep = serde_json::json!({"critical_paths": [
            path(&format!("posedge {clk}"), &format!("posedge {clk}"), &[5.0, 4.0]),
            path(&format!("posedge {clk90}"), &format!("posedge {clk}"), &[0.5, 1.0]),
            path(&format!("negedge {clk90}"), &format!("posedge {clk}"), &[0.54, 0.59, 0.47]),
            path("<async>", &format!("negedge {clk90}"), &[9.0]),
            path("posedge other", &format!("posedge {clk}"), &[9.0]),
        ]});
        let (mhz, what) = quadrature_fmax(&rep).unwrap();
        assert!((mhz - 156.25).abs() < 1e-9, "{mhz}");
        assert_eq!(
            what,
            "negedge clk90 → posedge clk: 1.60 ns in 1/4 of a clock"
        );
        // It bounds the seed's Fmax of the core clock, with a note.
        let mut r = NodeResult::default();
        let mut rep = rep;
        rep["fmax"] = serde_json::json!({clk: {"achieved": 170.0, "constraint": 100.0}});
        read_timing(&rep, 7, 0, &mut r).unwrap();
        assert!((r.fmax_mhz.unwrap() - 156.25).abs() < 1e-9);
        assert!(r.notes[0].starts_with("seed 7: the quadrature capture's negedge clk90"));
        assert!((r.clocks[0].fmax_mhz[0] - 156.25).abs() < 1e-9);
        // Without transfers, nextpnr's Fmax stands.
        let rep = serde_json::json!({"fmax": {clk: {"achieved": 120.0, "constraint": 100.0}}});
        let mut r = NodeResult::default();
        read_timing(&rep, 1, 0, &mut r).unwrap();
        assert_eq!(r.fmax_mhz, Some(120.0));
        assert!(r.notes.is_empty());
        assert_eq!(capture_edge("posedge $glbnet$node.cap_pi.clk90"), Some(1));
        assert_eq!(capture_edge("negedge $glbnet$clk$TRELLIS_IO_IN"), Some(2));
        assert_eq!(capture_edge("<async>"), None);
    }
}
