//! `merkur`: the command-line tool of the merkur project.
//!
//! Subcommands that exist work; nothing here is a placeholder.

#![deny(missing_docs)]

use clap::{Parser, Subcommand};
use merkur_model::{config, ring, trace};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

mod campaign;
mod dcm;
mod demo;
mod progress;
mod prove;
mod sim;
mod synth;

#[derive(Parser)]
#[command(
    name = "merkur",
    version,
    about = "MERKUR fault-tolerant ring fieldbus: scenarios, golden traces, demo",
    long_about = "MERKUR fault-tolerant ring fieldbus.\n\nScenario files are TOML (docs/scenarios.md); the protocol is docs/protocol.md.",
    after_long_help = "Exit status: 0 success (RTL and model agree, timing met); 1 a run that worked and found \
a disagreement, an accepted bit error or a missed timing; 2 bad input (scenario, argument, target, a \
configuration the device cannot hold) or a tool that cannot run."
)]
struct Cli {
    /// Folder of the built Verilator models (default: $MERKUR_VERILATOR_CACHE, else
    /// $XDG_CACHE_HOME/merkur/verilator or ~/.cache/merkur/verilator)
    #[arg(long, global = true, value_name = "DIR")]
    cache_dir: Option<PathBuf>,
    #[command(subcommand)]
    cmd: Cmd,
}

// The command line, parsed once per run: the size of its largest variant
// (the campaign's options) costs nothing worth a box.
#[allow(clippy::large_enum_variant)]
#[derive(Subcommand)]
enum Cmd {
    /// Validate a scenario and print a summary of its ring (or of its token bus: a file with a
    /// `[token_bus]` table is an IEEE 802.4 Dual Channel Manager scenario).
    Check {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Line rate in Mbit/s for the cycle time (default: the scenario's frame.line_rate_mbps, else 50).
        #[arg(long, value_name = "MBPS")]
        line_rate: Option<f64>,
    },
    /// Run the reference model on a scenario (ring or token bus) and write its golden trace.
    Trace {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Output file; written atomically (nothing is left behind on error). Omit to print to stdout.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// Write the Verilog of a scenario's ring (node modules, monitors, the `merkur_ring` top) and the lint waivers;
    /// for a token-bus scenario, the station's DCM + RMM (`merkur_dcm_station`).
    Verilog {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Output directory (created if missing); files are written atomically.
        #[arg(short, long, value_name = "DIR")]
        output: PathBuf,
    },
    /// Run a scenario's ring as Verilog in Verilator and compare it with the model's golden trace;
    /// for a token-bus scenario, every station's DCM + RMM against the model, octet for octet.
    Sim {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Write an FST waveform (and a GTKWave save file beside it, FILE.gtkw).
        #[arg(long, value_name = "FILE")]
        wave: Option<PathBuf>,
        /// Seed of the nodes' clock phases (ring scenarios).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// How many mismatches to list on a failure.
        #[arg(long, value_name = "N", default_value_t = 10)]
        show: usize,
        /// Ring scenarios: print every word the RTL carried on every fibre, cycle by cycle (the
        /// model's in brackets where it differs), and every fault and switchbox change with its
        /// simulation tick, to stderr.
        #[arg(long)]
        dump: bool,
    },
    /// Run a fault-injection campaign through the RTL (Verilator) and the model and compare
    /// them: every single fibre break and node death, double faults, repairs, repaired double
    /// breaks, bit-error, burst and clock-offset runs; writes a Markdown and JSON report. Exit
    /// status 1 on any mismatch or accepted bit error.
    Campaign {
        /// Base ring scenario (repeatable; its own faults are dropped). Default: tb-data/ring8.toml,
        /// with --full also ring32.toml and ring100.toml.
        #[arg(long = "ring", value_name = "FILE")]
        rings: Vec<PathBuf>,
        /// The full campaign: rings of 8, 32 and 100 nodes; on 8 and 32 nodes every single
        /// fault, on 100 nodes 30 sampled (`--singles`); every double fault on rings up to 16
        /// nodes, 32 sampled on bigger ones (8 on 100 nodes); repairs (every fibre up to 16
        /// nodes, 8 sampled on bigger rings); repaired double breaks (every ordered pair of links
        /// up to 16 nodes, 8 on 32, 4 on 100; else 8 sampled); BER 1e-3 … 1e-7; bursts.
        #[arg(long)]
        full: bool,
        /// Single faults per ring: a number (seeded sample) or `all` (default: all).
        #[arg(long, value_name = "N|all", value_parser = campaign::parse_count)]
        singles: Option<campaign::Count>,
        /// Double faults per ring: a number (seeded sample) or `all`. Default 24 (with --full: see there).
        #[arg(long, value_name = "N|all", value_parser = campaign::parse_count)]
        doubles: Option<campaign::Count>,
        /// Bit error rates, comma-separated, each 0 … 0.5 (`none` for no bit-error runs).
        /// Default 1e-4 (with --full: 1e-3,1e-4,1e-5,1e-6,1e-7).
        #[arg(long, value_name = "LIST", value_parser = campaign::parse_ber)]
        ber: Option<campaign::BerList>,
        /// Runs per bit error rate.
        #[arg(long, value_name = "N", default_value_t = 2)]
        ber_runs: usize,
        /// Burst runs per ring: one burst of garbage 1 … 100 bit times long on a primary fibre
        /// each, and one of 250 more (default 4; with --full 8).
        #[arg(long, value_name = "N")]
        bursts: Option<usize>,
        /// Every case runs its nodes at clock offsets drawn from the case's seed, uniform within
        /// ±PPM, with three neighbours at alternating extremes among them (0: every node at 0 ppm).
        #[arg(
            long,
            value_name = "PPM",
            default_value = "1000",
            allow_negative_numbers = true,
            value_parser = campaign::parse_ppm
        )]
        ppm: f64,
        /// Repair (reintegration) cases: every fibre breaks and is repaired (8 sampled fibres on
        /// rings of more than 16 nodes).
        #[arg(long)]
        repairs: bool,
        /// Campaign seed (fault slots, samples, bit positions, clock offsets and phases).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Parallel simulations (default: the machine's cores).
        #[arg(long, value_name = "N")]
        jobs: Option<usize>,
        /// Run only shard K of N (cases i with i mod N = K − 1); merge the reports with --merge.
        #[arg(long, value_name = "K/N", value_parser = campaign::parse_shard)]
        shard: Option<(usize, usize)>,
        /// Run only the case of this name (as the report lists it).
        #[arg(long, value_name = "NAME")]
        case: Option<String>,
        /// With --case: write the case's RTL run as an FST waveform (GTKWave save file beside it).
        #[arg(long, value_name = "FILE", requires = "case")]
        wave: Option<PathBuf>,
        /// With --case: write the case as a scenario file instead of running it; `merkur sim FILE
        /// --seed SEED` (the command is printed) then runs it as the campaign does.
        #[arg(long, value_name = "FILE", requires = "case")]
        export: Option<PathBuf>,
        /// Write campaign.md and campaign.json into this directory (else the Markdown goes to stdout).
        #[arg(short, long, value_name = "DIR")]
        output: Option<PathBuf>,
        /// Merge these JSON reports (from shards) instead of running (no option of a run goes
        /// with it).
        #[arg(long, value_name = "FILE", num_args = 1.., conflicts_with_all = [
            "rings", "full", "singles", "doubles", "ber", "ber_runs", "bursts", "ppm", "repairs",
            "seed", "jobs", "shard", "case", "wave", "export", "model_only", "only",
        ])]
        merge: Vec<PathBuf>,
        /// Run the reference model only (the protocol's behaviour, cheaply, e.g. with many
        /// --ber-runs); no RTL, no comparison.
        #[arg(long)]
        model_only: bool,
        /// Only cases of these classes, comma-separated.
        #[arg(
            long,
            value_name = "LIST",
            value_delimiter = ',',
            value_parser = clap::builder::PossibleValuesParser::new(campaign::CLASSES)
        )]
        only: Vec<String>,
    },
    /// Prove the control blocks' formal properties (SymbiYosys + Boolector, installed by
    /// scripts/install-tools.sh --synth; docs/verification.md). Exit status 1 when a property
    /// fails (its counterexample is written as a VCD waveform) or a cover is not reached.
    Prove {
        /// Only this proof (repeatable); see --list.
        #[arg(long, value_name = "NAME")]
        only: Vec<String>,
        /// Working directory: every proof's files, logs and counterexamples.
        #[arg(short, long, value_name = "DIR", default_value = "merkur-prove")]
        output: PathBuf,
        /// List the proofs and what each proves, and exit.
        #[arg(long)]
        list: bool,
    },
    /// Synthesize a scenario's nodes with the open tools and write the artifacts and a report
    /// (synth.md, synth.json): iCE40 and ECP5 bitstreams and timing, CoolRunner-II mapping,
    /// Spartan-6 resources, or the XEM6010 board top. Exit status 1 when an FPGA node misses
    /// timing at the design clock; 2 when a node cannot fit the device (its memories, logic
    /// cells, I/O, or a CPLD's macrocells and product terms: nothing is written).
    Synth {
        /// Scenario file (TOML): the ring whose nodes are built (home slots, slots, period).
        scenario: PathBuf,
        /// ice40-hx8k, ice40-hx1k, ice40-up5k, ecp5-85, ecp5-45 (bitstreams, nextpnr timing),
        /// xc2c32a, xc2c64a, xc2c128, xc2c256, xc2c384, xc2c512 (CoolRunner-II mapping against
        /// the device), xc6s (Spartan-6 resources) or xem6010 (board top, UCF, ISE script;
        /// bitstream with --features xem6010).
        #[arg(long, value_name = "TARGET",
              value_parser = clap::builder::PossibleValuesParser::new(synth::all_targets()))]
        target: String,
        /// Build this node (ring index; repeatable). Default: the special master, the first
        /// master and the first slave (XEM6010: the special master and the first master).
        #[arg(long = "node", value_name = "K")]
        nodes: Vec<usize>,
        /// Design line rate in Mbit/s (core clock = 2×); default the scenario's (50).
        #[arg(long, value_name = "MBPS")]
        line_rate: Option<f64>,
        /// Output folder (default `merkur-synth/<scenario name>-<target>`).
        #[arg(short, long, value_name = "DIR")]
        output: Option<PathBuf>,
        /// nextpnr placement seed (the first, with --seeds).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Placement seeds to run per node (seed, seed + 1, …): the report gives the core
        /// clock's Fmax min/median/max and the best seed's bitstream is kept.
        #[arg(long, default_value_t = 1, value_name = "N")]
        seeds: u64,
        /// Tool set of the FPGA targets: yowasp (pinned PyPI Yosys and nextpnr in
        /// .tools/venv, the default) or debian (Yosys 0.23, nextpnr-ice40 0.4; iCE40 only).
        #[arg(long, value_enum, default_value_t = synth::Flow::Yowasp, value_name = "FLOW")]
        flow: synth::Flow,
        /// ECP5 speed grade: 6, 7 or 8 (default 8; 6 with --board ulx3s, the board's parts).
        #[arg(long, value_name = "GRADE")]
        speed: Option<u8>,
        /// Board whose pins (gen/constraints/) a slave gets: ice40-hx8k-breakout (the default on
        /// ice40-hx8k) or ulx3s (ecp5-85, ecp5-45: the board top with its PLL). Masters are
        /// placed freely.
        #[arg(long, value_name = "BOARD")]
        board: Option<String>,
        /// The diagnostic mux (i_diag_sel, o_diag) and the error counters behind it: on, or
        /// off for a lean top (a sensor's i_sensor, an actuator's register on o_act, I/O
        /// placed freely; the counters are left out). Boards need it on.
        #[arg(long, default_value = "on", value_parser = ["on", "off"], value_name = "ON|OFF")]
        diag: String,
        /// The sensor value's synchroniser (two flip-flops per bit): on, or off for a sensor
        /// whose i_sensor comes from a register on the core clock (32 flip-flops fewer; a
        /// value from another clock needs a handshake for its coherence anyway). The user
        /// requests keep theirs.
        #[arg(long, default_value = "on", value_parser = ["on", "off"], value_name = "ON|OFF")]
        sensor_sync: String,
        /// Nodes built at a time (default: the machine's cores; each node's tools run one
        /// after the other in its own folder).
        #[arg(long, value_name = "N")]
        jobs: Option<usize>,
    },
    /// Run the built-in 8-node ring with one line break through the model (explained cycle
    /// by cycle) and through the RTL in Verilator, and show that they agree.
    Demo {
        /// Where the RTL run's FST waveform goes (a GTKWave save file beside it, FILE.gtkw).
        #[arg(long, value_name = "FILE", default_value_os_t = default_demo_wave())]
        wave: PathBuf,
        /// The model only (no Verilator run).
        #[arg(long)]
        model_only: bool,
    },
}

fn default_demo_wave() -> PathBuf {
    std::env::temp_dir()
        .join("merkur-demo")
        .join("demo_8_break.fst")
}

/// A scenario file's text. The campaign's default rings
/// ([`campaign::EMBEDDED_RINGS`]) are built in: a `tb-data/ring*.toml` of
/// theirs that is not in the current folder (an installed `merkur` run
/// outside the checkout) reads the embedded copy.
fn read_text(path: &Path) -> Result<String, String> {
    match std::fs::read_to_string(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => campaign::EMBEDDED_RINGS
            .iter()
            .find(|(name, _)| Path::new(name) == path)
            .map(|(_, text)| text.to_string())
            .ok_or(e),
        r => r,
    }
    .map_err(|e| format!("error: cannot read scenario {}: {e}", path.display()))
}

/// A ring scenario (token-bus scenarios are refused with a clear error:
/// only `check`, `trace`, `verilog` and `sim` take them).
pub(crate) fn read_scenario(path: &Path) -> Result<(String, config::Config), String> {
    let text = read_text(path)?;
    if merkur_model::tbconfig::is_token_bus(&text) {
        return Err(format!(
            "error: {} is a token-bus scenario ([token_bus]); this command takes MERKUR ring scenarios (token-bus scenarios run with check, trace, verilog and sim)",
            path.display()
        ));
    }
    let name = path.display().to_string();
    let cfg = config::load(&name, &text).map_err(|e| e.to_string())?;
    Ok((text, cfg))
}

/// Writes `data` to `path` through a temporary file in the same directory,
/// so a failed run never leaves a half-written file.
pub(crate) fn write_atomic(path: &Path, data: &str) -> Result<(), String> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let fname = path
        .file_name()
        .ok_or_else(|| format!("error: --output {} is not a file name", path.display()))?;
    let tmp = dir.join(format!(
        ".{}.{}.tmp",
        fname.to_string_lossy(),
        std::process::id()
    ));
    std::fs::write(&tmp, data).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("error: cannot write {}: {e}", path.display())
    })?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("error: cannot write {}: {e}", path.display())
    })
}

fn check(path: &Path, line_rate: Option<f64>) -> Result<(), String> {
    let (_, cfg) = read_scenario(path)?;
    let rate = match line_rate {
        None => cfg.line_rate_mbps,
        Some(r) if r.is_finite() && r > 0.0 && r <= 1000.0 => r,
        Some(r) => {
            return Err(format!(
                "error: --line-rate {r} must be above 0 and at most 1000 (Mbit/s)"
            ))
        }
    };
    let count = |k: merkur_model::scenario::Kind| cfg.nodes.iter().filter(|n| n.kind == k).count();
    use merkur_model::scenario::Kind::*;
    println!("scenario   {} ({})", cfg.name, path.display());
    println!(
        "ring       {} nodes: {} special master (node {}), {} masters, {} sensors, {} actuators",
        cfg.nodes.len(),
        count(SpecialMaster),
        cfg.sm,
        count(Master),
        count(Sensor),
        count(Actuator)
    );
    let backups = cfg.backups();
    if !backups.is_empty() {
        let list: Vec<String> = backups
            .iter()
            .map(|(k, p)| format!("node {k} priority {p}"))
            .collect();
        println!(
            "backups    {} (flying special master, protocol §8); CS timeout {} cycles",
            list.join(", "),
            cfg.cs_timeout_cycles()
        );
    }
    println!(
        "frame      {} slots, {} words, {} bit times{}",
        cfg.slots,
        if cfg.ext {
            "30-bit (extended alarm)"
        } else {
            "25-bit"
        },
        cfg.frame_bits(),
        if cfg.ext {
            ", alarms carried beside the data"
        } else {
            ""
        }
    );
    println!(
        "cycle      {} bit times = {:.2} us at {} Mbit/s (minimum legal period {})",
        cfg.period,
        cfg.period as f64 / rate,
        rate,
        cfg.min_period()
    );
    if let (Some(t), Some(tw)) = (cfg.rtx_start(false), cfg.rtx_start(true)) {
        let crit: Vec<String> = cfg.critical_slots().iter().map(|s| s.to_string()).collect();
        println!(
            "critical   slots {}: retransmission at bit {t} of the period ({tw} in a wrapped ring), room for {} requests ({} wrapped)",
            crit.join(", "),
            cfg.rtx_capacity(false),
            cfg.rtx_capacity(true)
        );
    }
    println!(
        "run        {} cycles, seed {}, {} host writes, {} interrupt requests, {} faults",
        cfg.cycles,
        cfg.seed,
        cfg.host_writes.len(),
        cfg.irqs.len(),
        cfg.faults.len()
    );
    for (c, f) in &cfg.faults {
        println!("fault      cycle {c}: {f}");
    }
    for (a, b, d) in ring::windows(&cfg, &ring::run(&cfg)) {
        println!("window     cycles {a}..={b}: {d}");
    }
    println!("ok");
    Ok(())
}

fn trace_cmd(path: &Path, output: Option<&Path>) -> Result<(), String> {
    let (text, cfg) = read_scenario(path)?;
    let recs = ring::run(&cfg);
    let out = trace::render(&cfg, &text, &recs);
    match output {
        None => {
            print!("{out}");
            Ok(())
        }
        Some(p) => {
            write_atomic(p, &out)?;
            eprintln!(
                "wrote {} ({} cycles, {} bytes)",
                p.display(),
                cfg.cycles,
                out.len()
            );
            Ok(())
        }
    }
}

/// `merkur campaign`: `Ok(false)` when a case disagrees with the model or a
/// bit error was accepted.
fn campaign_cmd(cmd: &Cmd) -> Result<bool, String> {
    let Cmd::Campaign {
        rings,
        full,
        singles,
        doubles,
        ber,
        ber_runs,
        bursts,
        ppm,
        repairs,
        seed,
        jobs,
        shard,
        case,
        wave,
        export,
        output,
        merge,
        model_only,
        only,
    } = cmd
    else {
        unreachable!("called for the campaign command")
    };
    let command = std::iter::once("merkur".to_string())
        .chain(std::env::args().skip(1))
        .collect::<Vec<_>>()
        .join(" ");
    let report = if !merge.is_empty() {
        campaign::merge(merge)?
    } else {
        let doubles = match doubles {
            None if *full => None,
            None => Some(24),
            Some(c) => c.limit(),
        };
        let ber = match ber {
            Some(b) => b.0.clone(),
            None if *full => vec![1e-3, 1e-4, 1e-5, 1e-6, 1e-7],
            None => vec![1e-4],
        };
        let jobs = match jobs {
            Some(0) => return Err("error: --jobs 0: at least one simulation must run".into()),
            Some(j) => *j,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let plan = campaign::Plan {
            rings: if rings.is_empty() {
                campaign::default_rings(*full)
            } else {
                rings.clone()
            },
            singles: singles.and_then(campaign::Count::limit),
            full: *full,
            doubles,
            ber,
            ber_runs: *ber_runs,
            bursts: bursts.unwrap_or(if *full { 8 } else { 4 }),
            ppm: *ppm,
            repairs: *repairs || *full,
            seed: *seed,
            jobs,
            shard: shard.unwrap_or((1, 1)),
            case: case.clone(),
            wave: wave.clone(),
            export: export.clone(),
            model_only: *model_only,
            only: only.clone(),
        };
        if plan.export.is_some() {
            return campaign::export(&plan).map(|()| true);
        }
        campaign::run(&plan, command)?
    };
    match output {
        Some(dir) => campaign::write(&report, dir)?,
        None => print!("{}", campaign::markdown(&report)),
    }
    let bad = report.cases.iter().filter(|c| c.mismatches > 0).count();
    let accepted: u32 = report.cases.iter().map(|c| c.accepted).sum();
    eprintln!(
        "{}: {} cases, {bad} with mismatches, {accepted} single-bit errors accepted",
        if bad == 0 && accepted == 0 {
            "PASS"
        } else {
            "FAIL"
        },
        report.cases.len()
    );
    Ok(bad == 0 && accepted == 0)
}

/// The file's text when it is a token-bus scenario, `None` for a ring
/// scenario (or anything else, which the ring parser then reports).
fn token_bus(path: &Path) -> Result<Option<String>, String> {
    let text = read_text(path)?;
    Ok(merkur_model::tbconfig::is_token_bus(&text).then_some(text))
}

fn main() -> ExitCode {
    // Output piped into a reader that stops early (`merkur check F | head`):
    // end quietly, as other Unix tools do, instead of panicking in println!.
    #[cfg(unix)]
    // SAFETY: called first thing in main, before any thread exists; resets
    // one signal to its default action.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    if let Some(d) = &cli.cache_dir {
        // Read by merkur_sim::verilator::cache_root; set before any thread
        // exists.
        std::env::set_var("MERKUR_VERILATOR_CACHE", d);
    }
    let r = match &cli.cmd {
        Cmd::Check {
            scenario,
            line_rate,
        } => match token_bus(scenario) {
            Err(e) => Err(e),
            Ok(Some(_)) if line_rate.is_some() => Err(format!(
                "error: --line-rate is for ring scenarios; {} is a token-bus scenario (token_bus.rate_mbps sets its rate)",
                scenario.display()
            )),
            Ok(Some(text)) => dcm::check(scenario, &text),
            Ok(None) => check(scenario, *line_rate),
        },
        Cmd::Trace { scenario, output } => match token_bus(scenario) {
            Err(e) => Err(e),
            Ok(Some(text)) => dcm::trace(scenario, &text, output.as_deref()),
            Ok(None) => trace_cmd(scenario, output.as_deref()),
        },
        Cmd::Verilog { scenario, output } => match token_bus(scenario) {
            Err(e) => Err(e),
            Ok(Some(text)) => dcm::verilog(scenario, &text, output),
            Ok(None) => sim::verilog(scenario, output),
        },
        Cmd::Sim {
            scenario,
            wave,
            seed,
            show,
            dump,
        } => {
            let r = match token_bus(scenario) {
                Err(e) => Err(e),
                Ok(Some(text)) => dcm::sim(scenario, &text, wave.as_deref(), *show),
                Ok(None) => sim::sim(scenario, wave.as_deref(), *seed, *show, *dump),
            };
            match r {
                Ok(true) => Ok(()),
                Ok(false) => return ExitCode::from(1),
                Err(e) => Err(e),
            }
        }
        Cmd::Synth {
            scenario,
            target,
            nodes,
            line_rate,
            output,
            seed,
            seeds,
            flow,
            speed,
            board,
            diag,
            sensor_sync,
            jobs,
        } => {
            let o = synth::Opts {
                target,
                nodes,
                line_rate: *line_rate,
                output: output.as_deref(),
                seed: *seed,
                seeds: *seeds,
                flow: *flow,
                speed: *speed,
                board: board.as_deref(),
                diag: diag == "on",
                sensor_sync: sensor_sync == "on",
                jobs: *jobs,
            };
            match synth::run(scenario, &o) {
                Ok(true) => Ok(()),
                Ok(false) => return ExitCode::from(1),
                Err(e) => Err(e),
            }
        }
        Cmd::Prove { only, output, list } => match prove::run(only, output, *list) {
            Ok(true) => Ok(()),
            Ok(false) => return ExitCode::from(1),
            Err(e) => Err(e),
        },
        Cmd::Demo { wave, model_only } => demo::run((!*model_only).then_some(wave.as_path())),
        Cmd::Campaign { .. } => match campaign_cmd(&cli.cmd) {
            Ok(true) => Ok(()),
            Ok(false) => return ExitCode::from(1),
            Err(e) => Err(e),
        },
    };
    match r {
        Ok(()) => ExitCode::SUCCESS,
        // Bad input (a scenario, an argument, a file that cannot be
        // written, a missing tool): exit code 2, as clap's own argument
        // errors; 1 is kept for a run that worked and found a mismatch or
        // a missed timing.
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}
