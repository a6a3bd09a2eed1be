//! `merkur synth`: runs the open synthesis tools on a scenario's nodes and
//! writes the artifacts and a report (docs/synthesis.md).
//!
//! Targets: `ice40-hx8k`, `ice40-hx1k`, `ice40-up5k` (Yosys `synth_ice40` →
//! nextpnr-ice40 → `icepack`: a bitstream, timing at the design clock),
//! `ecp5-85` and `ecp5-45` (Yosys `synth_ecp5` → nextpnr-ecp5 → `ecppack`:
//! a `.bit`; [`fpga`] has both FPGA flows, over placement seeds, read from
//! the tools' JSON), the CoolRunner-II CPLDs `xc2c32a` … `xc2c512` (Yosys
//! `synth_coolrunner2`: macrocells and product terms against the device;
//! a node that cannot fit is refused, exit status 2, nothing written),
//! `xc6s` (Yosys `synth_xilinx -family
//! xc6s`: resource counts), `xem6010` (the board top of a master or the
//! special master, its `.ucf` and an ISE script; Yosys checks and counts
//! it; with the `xem6010` cargo feature and Opal Kelly's FrontPanel HDL and
//! Xilinx ISE installed, ISE builds the bitstream).

use fpga::{read_json, run_tool, sum_cells, yosys_cells};
use merkur_model::config::Config;
use merkur_model::scenario::Kind;
use merkur_rtl::emit::verilog;
use merkur_rtl::harness::ring_top::node_verilog;
use merkur_rtl::line::retime::Layout;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::top::boards;
use merkur_rtl::top::synth_top::{self, node_top, NodeStatic};
use merkur_rtl::top::xem6010;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::Command;

mod fpga;
mod xc2_blocks;
mod xc2_cover;
mod xc2_fit;
#[cfg(test)]
mod xc2_jed_sim;
mod xc2_pins;
mod xc2_timing;
pub use fpga::Flow;

/// Synthesis targets besides the CoolRunner-IIs ([`CPLDS`]).
pub const TARGETS: [&str; 7] = [
    "ice40-hx8k",
    "ice40-hx1k",
    "ice40-up5k",
    "ecp5-85",
    "ecp5-45",
    "xc6s",
    "xem6010",
];

/// Every target name, the CPLDs' among them (the values `--target` takes).
pub fn all_targets() -> Vec<&'static str> {
    let mut v = TARGETS.to_vec();
    v.splice(5..5, CPLDS.iter().map(|c| c.name));
    v
}

/// A CoolRunner-II device: Xilinx DS090 (CoolRunner-II CPLD family data
/// sheet), its family table: macrocells, function blocks (each with a PLA
/// of 56 product terms shared by its 16 macrocells) and the user I/O of
/// the device's largest package.
#[derive(Clone, Copy, Debug)]
pub struct Cpld {
    /// Target name.
    pub name: &'static str,
    /// As Xilinx names it.
    pub device: &'static str,
    /// Macrocells.
    pub macrocells: u64,
    /// Function blocks (16 macrocells, 56 product terms each).
    pub blocks: u64,
    /// User I/O, largest package.
    pub io: u64,
    /// That package, as the fitter names it (`FT256`): every pad of the
    /// die is bonded in it.
    pub package: &'static str,
    /// Its pins: (function block, macrocell, package pin) of every pad
    /// ([`xc2_pins`], generated from Project Combine's database).
    pub pins: &'static [(u8, u8, &'static str)],
    /// Speed grades, fastest first: the delays of [`xc2_timing`]'s line
    /// rate estimate.
    pub speeds: [xc2_timing::Speed; 2],
}

impl Cpld {
    /// Product terms (56 per function block).
    pub fn pterms(&self) -> u64 {
        56 * self.blocks
    }
}

/// The quarters of a core clock from a launching capture edge to the
/// capturing one, each given in quarters after `clk` rises (`clk` ↑ 0,
/// `clk90` ↑ 1, `clk` ↓ 2, `clk90` ↓ 3): the next edge of its kind, a
/// whole clock from an edge to itself. The quadrature capture's transfers
/// between `clk` and `clk90` have that fraction of a clock (the FPGAs'
/// [`fpga`] report and the CoolRunner-II estimate, `xc2_timing`).
pub fn capture_quarters(from: u32, to: u32) -> u32 {
    match (to % 4 + 4 - from % 4) % 4 {
        0 => 4,
        q => q,
    }
}

/// The CoolRunner-II family: sizes from Xilinx DS090's family table,
/// speed grades from Project Combine's database ([`xc2_timing`]).
pub const CPLDS: [Cpld; 6] = [
    Cpld {
        name: "xc2c32a",
        device: "XC2C32A",
        macrocells: 32,
        blocks: 2,
        io: 33,
        package: "VQ44",
        pins: xc2_pins::XC2C32A_VQ44,
        speeds: [
            xc2_timing::sp("-4", [600, 600, 600, 300, 1500]),
            xc2_timing::sp("-6", [700, 1400, 1600, 700, 1800]),
        ],
    },
    Cpld {
        name: "xc2c64a",
        device: "XC2C64A",
        macrocells: 64,
        blocks: 4,
        io: 64,
        package: "VQ100",
        pins: xc2_pins::XC2C64A_VQ100,
        speeds: [
            xc2_timing::sp("-5", [400, 1500, 900, 500, 1400]),
            xc2_timing::sp("-7", [700, 3000, 1600, 700, 1800]),
        ],
    },
    Cpld {
        name: "xc2c128",
        device: "XC2C128",
        macrocells: 128,
        blocks: 8,
        io: 100,
        package: "TQ144",
        pins: xc2_pins::XC2C128_TQ144,
        speeds: [
            xc2_timing::sp("-6", [400, 1800, 800, 900, 1400]),
            xc2_timing::sp("-7", [700, 3400, 1600, 700, 1400]),
        ],
    },
    Cpld {
        name: "xc2c256",
        device: "XC2C256",
        macrocells: 256,
        blocks: 16,
        io: 184,
        package: "FT256",
        pins: xc2_pins::XC2C256_FT256,
        speeds: [
            xc2_timing::sp("-6", [400, 1700, 800, 500, 1300]),
            xc2_timing::sp("-7", [700, 3000, 1600, 700, 1800]),
        ],
    },
    Cpld {
        name: "xc2c384",
        device: "XC2C384",
        macrocells: 384,
        blocks: 24,
        io: 240,
        package: "FG324",
        pins: xc2_pins::XC2C384_FG324,
        speeds: [
            xc2_timing::sp("-7", [200, 2200, 900, 500, 1700]),
            xc2_timing::sp("-10", [700, 4500, 1600, 700, 2000]),
        ],
    },
    Cpld {
        name: "xc2c512",
        device: "XC2C512",
        macrocells: 512,
        blocks: 32,
        io: 270,
        package: "FG324",
        pins: xc2_pins::XC2C512_FG324,
        speeds: [
            xc2_timing::sp("-7", [400, 3300, 900, 500, 1400]),
            xc2_timing::sp("-10", [700, 4500, 1600, 700, 1800]),
        ],
    },
];

/// The CPLD of a target name.
pub fn cpld(target: &str) -> Option<Cpld> {
    CPLDS.iter().copied().find(|c| c.name == target)
}

/// One node's result.
#[derive(Serialize, Debug, Default, Clone)]
pub struct NodeResult {
    /// Ring index in the scenario.
    pub node: usize,
    /// Kind.
    pub kind: String,
    /// `ok`, `timing failed` or `not attempted` in a report; `does not fit`
    /// only on the way to [`run`]'s refusal.
    pub status: String,
    /// Why, when not `ok`.
    pub reason: String,
    /// LUTs (LUT4 on iCE40 and ECP5, LUT1–6 on Spartan-6).
    pub luts: Option<u64>,
    /// Flip-flops.
    pub ffs: Option<u64>,
    /// Block RAMs (SB_RAM40_4K on iCE40, DP16KD on ECP5, RAMB16 + RAMB8 on
    /// Spartan-6).
    pub brams: Option<u64>,
    /// Block RAMs the device has (bitstream targets).
    pub brams_available: Option<u64>,
    /// Logic cells after packing (nextpnr: ICESTORM_LC on iCE40,
    /// TRELLIS_COMB on ECP5).
    pub lcs: Option<u64>,
    /// Logic cells the device has.
    pub lcs_available: Option<u64>,
    /// I/O pins used.
    pub ios: Option<u64>,
    /// Placement seeds run (nextpnr `--seed`).
    pub seeds: Vec<u64>,
    /// The seed whose bitstream was kept (the best Fmax).
    pub seed: Option<u64>,
    /// Every clock's Fmax per seed (nextpnr's report).
    pub clocks: Vec<fpga::ClockTiming>,
    /// Fmax of the core clock (nextpnr), MHz: the best seed's.
    pub fmax_mhz: Option<f64>,
    /// The core clock's lowest Fmax over the seeds, MHz.
    pub fmax_min_mhz: Option<f64>,
    /// The core clock's median Fmax over the seeds, MHz.
    pub fmax_median_mhz: Option<f64>,
    /// The line rate that Fmax allows (core clock = 2 × line rate), Mbit/s.
    pub max_line_rate_mbps: Option<f64>,
    /// CoolRunner-II macrocells (MACROCELL_XOR cells).
    pub macrocells: Option<u64>,
    /// CoolRunner-II product terms (ANDTERM cells).
    pub pterms: Option<u64>,
    /// Critical path (nets) when timing failed.
    pub critical_path: Vec<String>,
    /// The Yosys strategy whose netlist was kept (bitstream targets: the
    /// first that placed and met the design clock, else the fastest that
    /// placed; the last one tried when none fits): the synthesis command
    /// and options.
    pub strategy: String,
    /// What the build had to do beyond the first strategy and the heap
    /// placer (strategies that did not fit or missed the design clock,
    /// with their need or Fmax; seeds placed by the SA placer or not at
    /// all).
    pub notes: Vec<String>,
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
    /// Tool set of the FPGA flows (`yowasp` or `debian`).
    pub flow: String,
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
    /// First nextpnr seed.
    pub seed: u64,
    /// How many seeds (seed, seed + 1, …).
    pub seeds: u64,
    /// `--flow`.
    pub flow: Flow,
    /// `--speed` (ECP5).
    pub speed: Option<u8>,
    /// `--board`.
    pub board: Option<&'a str>,
    /// `--diag` (on: the diagnostic mux and the counters behind it).
    pub diag: bool,
    /// `--sensor-sync` (on: the sensor value's synchroniser).
    pub sensor_sync: bool,
    /// `--jobs`: nodes built at a time (`None`: the machine's cores).
    pub jobs: Option<usize>,
}

/// Boards a slave can be built for, per FPGA target (`--board`).
const BOARDS: [(&str, &str); 3] = [
    ("ice40-hx8k-breakout", "ice40-hx8k"),
    ("ulx3s", "ecp5-85"),
    ("ulx3s", "ecp5-45"),
];

/// The board of a run: `--board`, checked against the target, or the
/// iCE40-HX8K breakout by default on that target (not for a lean top,
/// `--diag off`, whose ports no board file names; nor the XEM6010 target,
/// a board top whose host reads the mux). Slaves go on it; masters
/// are placed freely (their parallel host port is wider than any of these
/// boards' headers).
fn board_of(
    target: &str,
    board: Option<&str>,
    diag: bool,
) -> Result<Option<boards::Board>, String> {
    if target == "xem6010" && !diag {
        return Err(
            "error: --target xem6010 --diag off: the XEM6010 top reads the diagnostic \
                    mux over FrontPanel (WireOut 0x22)"
                .into(),
        );
    }
    let Some(name) = board else {
        return Ok((target == "ice40-hx8k" && diag).then(boards::ice40_hx8k_breakout));
    };
    if !diag {
        return Err(format!(
            "error: --board {name} --diag off: the boards' pin files wire the diagnostic mux; \
             a lean top (--diag off) is placed without a board"
        ));
    }
    let list = || {
        BOARDS
            .iter()
            .map(|(b, t)| format!("{b} (--target {t})"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !BOARDS.iter().any(|(b, _)| *b == name) {
        return Err(format!(
            "error: --board {name}: unknown board; boards: {}{}",
            list(),
            if name == "xem6010" {
                " (the XEM6010 is its own target: --target xem6010)"
            } else {
                ""
            }
        ));
    }
    if !BOARDS.iter().any(|&(b, t)| b == name && t == target) {
        return Err(format!(
            "error: --board {name} does not carry --target {target}; boards: {}",
            list()
        ));
    }
    Ok(boards::by_name(name))
}

/// A device's block RAM, for the memory budget checked before any tool runs.
#[derive(Clone, Debug)]
pub struct BlockRam {
    /// The device as its vendor names it.
    device: &'static str,
    /// The primitive nextpnr counts.
    cell: &'static str,
    /// How many the device has.
    count: u64,
    /// Bits per block (data bits of its widest configuration).
    bits: u64,
}

/// Blocks a node's memories (width, depth as written) need at least when
/// the slot memories are sized `depth` deep (those deeper are, the others
/// keep theirs: [`verilog::size_memories`]): each memory takes
/// ⌈width · depth / bits⌉ blocks, at least one (a lower bound: a fitter
/// never needs fewer, so a refusal is never wrong; Yosys 0.23 reaches it
/// on the iCE40, docs/synthesis.md).
fn blocks_needed(mems: &[(usize, usize)], depth: usize, bits: u64) -> u64 {
    mems.iter()
        .map(|&(w, d)| ((w * d.min(depth)) as u64).div_ceil(bits).max(1))
        .sum()
}

/// Refuses, before anything is written, a node whose memories cannot fit
/// the target's block RAM, naming the slot count, the need, the device's
/// limit and the largest slot count that fits this node kind.
fn memory_budget(b: &BlockRam, k: usize, st: &NodeStatic) -> Result<(), String> {
    let mems = verilog::memories(&node_verilog(st.kind, 4096, st.format));
    let depth = verilog::mem_depth(st.slots);
    let need = blocks_needed(&mems, depth, b.bits);
    if need <= b.count {
        return Ok(());
    }
    let fits = (8..=12)
        .rev()
        .map(|a| 1usize << a)
        .find(|&d| blocks_needed(&mems, d, b.bits) <= b.count);
    Err(format!(
        "error: slots {}: node {k} ({}) needs at least {need} {} block RAMs for its memories \
         ({depth} entries deep), the {} has {}; {}",
        st.slots,
        kind_label(st.kind),
        b.cell,
        b.device,
        b.count,
        match fits {
            Some(d) => format!("at most {d} slots fit a {} on it", kind_label(st.kind)),
            None => format!("no {} fits it", kind_label(st.kind)),
        }
    ))
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

fn write(dir: &Path, name: &str, text: &str) -> Result<(), String> {
    std::fs::write(dir.join(name), text)
        .map_err(|e| format!("error: cannot write {}: {e}", dir.join(name).display()))
}

/// `synth_coolrunner2` in its steps, with memories (ROM tables included)
/// mapped to flip-flops first and without `extract_counter`, which crashes
/// Yosys 0.23 on the nodes (`dict::at()` out of range); the T flip-flops of
/// counters are still found by the `map_tff` step. Before it,
/// [`XC2_SAT_PASSES`] rounds of `opt_dff -sat` remove the flip-flops that
/// can never leave their initial value. Its `map_cells` step is
/// [`XC2_MAP_CELLS`], which puts the clocks on global clock buffers.
fn xc2_script() -> String {
    format!(
        "read_verilog top.v; hierarchy -top merkur_top; proc; flatten; memory; opt; \
         {}synth_coolrunner2 -top merkur_top -run :fine; \
         techmap -map +/coolrunner2/cells_counter_map.v; clean; opt -fast -full; \
         techmap -map +/techmap.v -map +/coolrunner2/cells_latch.v; opt -fast; \
         dfflibmap -prepare -liberty +/coolrunner2/xc2_dff.lib; \
         synth_coolrunner2 -top merkur_top -run map_tff:map_cells; {XC2_MAP_CELLS} \
         synth_coolrunner2 -top merkur_top -run check:; write_json top.json",
        "opt_dff -sat; opt_clean; ".repeat(XC2_SAT_PASSES)
    )
}

/// Maps `dir/top.v` to a CoolRunner-II netlist: [`xc2_script`], then
/// each macrocell's product terms chosen again ([`xc2_cover`]), then Yosys
/// once more for the netlist's check, `top.edif`, `top.json` and
/// `stat.json`. Returns what the second step changed, or why it kept
/// Yosys' cover (ABC failed).
fn xc2_map(dir: &Path) -> Result<Result<xc2_cover::Recovered, String>, String> {
    run_tool(dir, "yosys", &["-p", &xc2_script()], "yosys.log")?;
    let recovered = xc2_cover::recover(dir);
    run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_json top.json; hierarchy -top merkur_top; check -noinit -assert; \
             write_edif top.edif; write_json top.json; tee -q -o stat.json stat -json",
        ],
        "yosys-cover.log",
    )?;
    Ok(recovered)
}

/// `synth_coolrunner2`'s `map_cells` step (Yosys 0.23) with `clkbufmap`
/// before the pads: every flip-flop's clock (`clk`, `clk90`) comes from a
/// `BUFG`, the global clock network (FCLK) of a GCK pin. Without it,
/// `coolrunner2_fixup` gives each flip-flop a clock of its own through a
/// product term (one `ANDTERM` per flip-flop: 569 on ring8's sensor), as
/// it must for a clock that no `BUFG` drives. The flip-flop cells are
/// marked as clock sinks (`clkbuf_sink`), which Yosys 0.23's CoolRunner-II
/// library does not do (docs/synthesis.md).
const XC2_MAP_CELLS: &str = "dfflibmap -liberty +/coolrunner2/xc2_dff.lib; \
     dffinit -ff FDCP Q INIT; dffinit -ff FDCP_N Q INIT; dffinit -ff FTCP Q INIT; \
     dffinit -ff FTCP_N Q INIT; dffinit -ff LDCP Q INIT; dffinit -ff LDCP_N Q INIT; \
     coolrunner2_sop; clean; read_verilog -lib +/coolrunner2/cells_sim.v; \
     setattr -set clkbuf_sink 1 =FDCP/w:C =FDCP_N/w:C =FTCP/w:C =FTCP_N/w:C; \
     clkbufmap -buf BUFG O:I; \
     iopadmap -bits -inpad IBUF O:I -outpad IOBUFE I:IO -inoutpad IOBUFE O:IO \
     -toutpad IOBUFE E:I:IO -tinoutpad IOBUFE E:O:I:IO; \
     attrmvcp -attr src -attr LOC t:IOBUFE n:*; \
     attrmvcp -attr src -attr LOC -driven t:IBUF n:*; \
     coolrunner2_fixup; splitnets; clean;";

/// Rounds of `opt_dff -sat` in [`xc2_script`]. A counter that counts down
/// from a static value (the switch controller's grace counter: half the
/// CS timeout, 20 bits wide) never sets the bits above that value's
/// highest one. `opt_dff -sat` proves one such bit constant per round,
/// from the top down, because each proof needs the bit above it already
/// gone; so a 20-bit counter needs up to 20 rounds. On ring8's sensor this
/// removes 9 flip-flops and about 290 product terms
/// (docs/benchmarks.md).
const XC2_SAT_PASSES: usize = 20;

/// Maps a slave to a CoolRunner-II; status `does not fit` (which [`run`]
/// turns into a refusal) when it cannot fit the device, naming what it
/// needs and what the device has, where its product terms go and how fast
/// it would run; `timing failed` when it fits but Xilinx's delay model
/// gives the fastest speed grade less than the design clock (`clock`,
/// MHz).
fn xc2c(
    dir: &Path,
    st: &NodeStatic,
    c: &Cpld,
    clock: f64,
    r: &mut NodeResult,
) -> Result<(), String> {
    if !matches!(st.kind, Kind::Sensor | Kind::Actuator) {
        r.status = "not attempted".into();
        r.reason = "a master's memories (≥ 64 kbit) cannot map to a CPLD without block RAM".into();
        return Ok(());
    }
    write(dir, "top.v", &node_top(st)?)?;
    match xc2_map(dir)? {
        Ok(c) => r.notes.push(format!(
            "product terms chosen again per macrocell (D or T register, polarity): {} → {}; \
             {} registers made T flip-flops, {} D",
            c.pterms_before, c.pterms_after, c.to_t, c.to_d
        )),
        Err(e) => r.notes.push(format!("Yosys' product terms kept: {e}")),
    }
    let cells = yosys_cells(&read_json(dir, "stat.json")?);
    let mc = sum_cells(&cells, |n| n == "MACROCELL_XOR");
    let pt = sum_cells(&cells, |n| n == "ANDTERM");
    let io = sum_cells(&cells, |n| {
        n.starts_with("IOBUF") || n == "IBUF" || n == "OBUF"
    });
    r.macrocells = Some(mc);
    r.pterms = Some(pt);
    let ffs = sum_cells(&cells, |n| {
        n.starts_with("FD") || n.starts_with("FT") || n.starts_with("LD")
    });
    r.ffs = Some(ffs);
    r.ios = Some(io);
    r.artifacts
        .extend(["top.v", "top.edif", "top.json", "stat.json", "yosys.log"].map(String::from));
    let netlist = read_json(dir, "top.json")?;
    let costs = xc2_blocks::block_costs(&netlist);
    let paths = xc2_timing::paths(&netlist);
    let timing = xc2_timing::summary(c, &paths);
    // Identical product terms share a site in a function block, so the
    // different ones are what the device must hold at least.
    let distinct = xc2_blocks::distinct_pterms(&netlist);
    let over = mc > c.macrocells || distinct > c.pterms() || io > c.io;
    if over {
        r.status = "does not fit".into();
        r.reason = format!(
            "it needs {mc} macrocells ({ffs} of them for flip-flops), {pt} product terms \
             ({distinct} different ones; a function block's macrocells share a product term \
             they all use) and {io} I/O; \
             the {} has {} \
             macrocells, {} product terms ({} function blocks × 56) and at most {} user I/O",
            c.device,
            c.macrocells,
            c.pterms(),
            c.blocks,
            c.io,
        );
        if !costs.is_empty() {
            r.reason += &format!(". Most product terms: {}", xc2_blocks::summary(&costs, 4));
        }
        if let Some(t) = &timing {
            r.reason += &format!(". If it fit: {t}");
        }
        return Ok(());
    }
    if !costs.is_empty() {
        r.notes.push(format!(
            "product terms by block: {}",
            xc2_blocks::summary(&costs, costs.len())
        ));
    }
    match xc2_fit::fit(dir, c) {
        Ok(pins) => {
            r.artifacts.extend(["top.jed", "top.ucf"].map(String::from));
            r.notes.push(format!(
                "pins (top.ucf): {}",
                pins.iter()
                    .map(|p| format!("{} {}", p.port, p.pin))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
            r.status = "ok".into();
            r.reason = format!(
                "placed and routed on the {} by the open fitter (xc2par, third_party/README.md): \
                 top.jed, pins in top.ucf; the bitstream is checked in simulation, not yet on a \
                 device (docs/synthesis.md)",
                xc2_fit::part(c)
            );
        }
        Err(e) if e.starts_with("error:") => return Err(e),
        Err(e) => {
            r.status = "does not fit".into();
            r.reason = e;
            return Ok(());
        }
    }
    if let (Some(t), Some((mhz, _))) = (timing, xc2_timing::fmax(&paths, &c.speeds[0])) {
        r.fmax_mhz = Some(mhz);
        r.max_line_rate_mbps = Some(mhz / 2.0);
        r.notes.push(t);
        if mhz < clock {
            r.status = "timing failed".into();
            r.reason = format!(
                "{mhz:.1} MHz by Xilinx's delay model at the fastest speed grade < {clock} MHz \
                 design clock (estimated from the mapping, docs/synthesis.md)"
            );
        }
    }
    Ok(())
}

fn xilinx_counts(r: &mut NodeResult, dir: &Path) -> Result<(), String> {
    let cells = yosys_cells(&read_json(dir, "stat.json")?);
    r.luts = Some(sum_cells(&cells, |n| n.starts_with("LUT")));
    r.ffs = Some(sum_cells(&cells, |n| n.starts_with("FD")));
    r.brams = Some(sum_cells(&cells, |n| n.starts_with("RAMB")));
    r.ios = Some(sum_cells(&cells, |n| {
        n.starts_with("IBUF") || n.starts_with("OBUF") || n.starts_with("IOBUF")
    }));
    Ok(())
}

fn xc6s(dir: &Path, st: &NodeStatic, r: &mut NodeResult) -> Result<(), String> {
    write(dir, "top.v", &node_top(st)?)?;
    run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_verilog top.v; synth_xilinx -flatten -family xc6s -top merkur_top; write_edif top.edif; \
             tee -q -o stat.json stat -json",
        ],
        "yosys.log",
    )?;
    xilinx_counts(r, dir)?;
    r.artifacts
        .extend(["top.v", "top.edif", "stat.json", "yosys.log"].map(String::from));
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
    run_tool(
        dir,
        "yosys",
        &[
            "-p",
            "read_verilog top.v; read_verilog -lib ok_blackbox.v; \
             synth_xilinx -flatten -family xc6s -top merkur_xem6010; tee -q -o stat.json stat -json",
        ],
        "yosys.log",
    )?;
    xilinx_counts(r, dir)?;
    r.artifacts.extend(
        [
            "top.v",
            "ok_blackbox.v",
            "xem6010.ucf",
            "merkur_xem6010.tcl",
            "README.md",
            "stat.json",
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

/// Whether a program is on PATH.
fn on_path(prog: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|p| std::env::split_paths(&p).any(|d| d.join(prog).is_file()))
}

/// The tools a target runs, each checked to be on PATH before anything is
/// written; their versions for the report.
fn tools_of(target: &str, f: Option<&fpga::Fpga>, flow: fpga::Flow) -> Result<Vec<String>, String> {
    let progs: Vec<(String, &str)> = match f {
        Some(f) => {
            let (pnr, pack) = match f.family {
                fpga::Family::Ice40 => ("nextpnr-ice40", "icepack"),
                fpga::Family::Ecp5 => ("nextpnr-ecp5", "ecppack"),
            };
            vec![
                (flow.tool("yosys"), "-V"),
                (flow.tool(pnr), "--version"),
                (flow.tool(pack), ""),
            ]
        }
        None => vec![("yosys".to_string(), "-V")],
    };
    let missing: Vec<&str> = progs
        .iter()
        .filter(|(p, _)| !on_path(p))
        .map(|(p, _)| p.as_str())
        .collect();
    if !missing.is_empty() {
        let how = if flow == fpga::Flow::Yowasp && f.is_some() {
            "scripts/install-tools.sh --synth installs the pinned YoWASP tools into .tools/venv; \
             put .tools/venv/bin on PATH (./run does)"
        } else {
            "scripts/install-tools.sh installs the pinned Debian tools"
        };
        return Err(format!(
            "error: --target {target}: {} not found on PATH ({how})",
            missing.join(", ")
        ));
    }
    Ok(progs
        .iter()
        .filter(|(_, arg)| !arg.is_empty())
        .map(|(p, arg)| tool_version(p, arg))
        .collect())
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

/// The tool set and the FPGA of a run from `--flow`, `--speed`, `--seeds`
/// and the board (the ULX3S carries speed grade 6 parts, so that is its
/// default); refuses what cannot run. `None`: a target without a
/// bitstream flow.
fn fpga_of(
    o: &Opts,
    board: Option<&boards::Board>,
) -> Result<(fpga::Flow, Option<fpga::Fpga>), String> {
    let flow = o.flow;
    if let Some(sp) = o.speed {
        if !o.target.starts_with("ecp5") {
            return Err(format!(
                "error: --speed {sp}: speed grades are for the ECP5 targets (ecp5-85, ecp5-45)"
            ));
        }
        if !fpga::ECP5_SPEEDS.contains(&sp) {
            return Err(format!(
                "error: --speed {sp}: the ECP5 speed grades are 6, 7 and 8"
            ));
        }
    }
    if !(1..=16).contains(&o.seeds) {
        return Err(format!(
            "error: --seeds {}: must be 1 … 16 (placement seeds {} on)",
            o.seeds, o.seed
        ));
    }
    let speed = match board {
        Some(b) if b.name == "ulx3s" => o.speed.or(Some(6)),
        _ => o.speed,
    };
    let f = fpga::fpga(o.target, speed);
    if flow == fpga::Flow::Debian && f.as_ref().is_some_and(|f| f.family != fpga::Family::Ice40) {
        return Err(format!(
            "error: --flow debian --target {}: Debian's tools have no nextpnr-ecp5; use --flow yowasp",
            o.target
        ));
    }
    Ok((flow, f))
}

/// Runs the synthesis; `Ok(false)` when a node failed timing; `Err` (exit
/// status 2, nothing written) for bad input, a missing tool or a node the
/// device cannot hold.
pub fn run(scenario: &Path, o: &Opts) -> Result<bool, String> {
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
    let jobs = match o.jobs {
        Some(0) => return Err("error: --jobs 0: at least one node must be built at a time".into()),
        Some(n) => n,
        None => merkur_sim::jobs::cores(),
    };
    let board = board_of(o.target, o.board, o.diag)?;
    let (flow, fpga) = fpga_of(o, board.as_ref())?;
    let nodes = pick_nodes(&cfg, o.nodes, o.target)?;
    // A board asked for by name carries what it can; the default board
    // (the breakout on the HX8K) takes the slaves and leaves masters free.
    if let (Some(b), Some(_)) = (&board, o.board) {
        let slave = |k: usize| matches!(cfg.nodes[k].kind, Kind::Sensor | Kind::Actuator);
        if let Some(&k) = o.nodes.iter().find(|&&k| k < cfg.nodes.len() && !slave(k)) {
            return Err(format!(
                "error: --node {k} is a {}; --board {} carries a slave (a master's parallel host port \
                 needs more pins than the board has)",
                cfg.nodes[k].kind.name(),
                b.name
            ));
        }
    }
    if nodes.is_empty() {
        return Err(format!(
            "error: {}: no node to build for --target {}",
            scenario.display(),
            o.target
        ));
    }
    // Everything that can be refused is refused before the output exists.
    let statics: Vec<NodeStatic> = nodes
        .iter()
        .map(|&k| NodeStatic {
            kind: cfg.nodes[k].kind,
            address: cfg.nodes[k].address,
            slots: cfg.slots,
            period: cfg.period,
            rtx: synth_top::RtxStatic::of(&cfg),
            // A CoolRunner-II's macrocells are sums of product terms: its
            // retime buffers shift at a write (issue 21, docs/synthesis.md).
            layout: if cpld(o.target).is_some() {
                Layout::WriteShifts
            } else {
                Layout::SendShifts
            },
            diag: o.diag,
            sensor_sync: o.sensor_sync,
            format: if cfg.ext {
                WordFormat::ExtendedAlarm
            } else {
                WordFormat::Basic
            },
        })
        .collect();
    for (&k, st) in nodes.iter().zip(&statics) {
        synth_top::check(st).map_err(|e| format!("error: node {k}: {e}"))?;
        if let Some(f) = &fpga {
            memory_budget(&f.bram, k, st)?;
        }
    }
    let tools = tools_of(o.target, fpga.as_ref(), flow)?;
    let out = o.output.map(PathBuf::from).unwrap_or_else(|| {
        PathBuf::from("merkur-synth").join(format!("{}-{}", cfg.name, o.target))
    });
    let out_existed = out.exists();
    std::fs::create_dir_all(&out)
        .map_err(|e| format!("error: --output {}: cannot create: {e}", out.display()))?;
    let seeds: Vec<u64> = (0..o.seeds).map(|i| o.seed + i).collect();
    let job = NodeJob {
        out: &out,
        cfg: &cfg,
        target: o.target,
        fpga: fpga.as_ref(),
        board: board.as_ref(),
        flow,
        clock,
        seeds: &seeds,
    };
    // Every node is built in a scratch folder of its own, side by side;
    // they move into place together when all are built, so a refused or
    // failed node leaves nothing of the run behind but its kept logs.
    let items: Vec<(usize, &NodeStatic)> = nodes.iter().copied().zip(&statics).collect();
    let built = match merkur_sim::jobs::run(&items, jobs, |&(k, st)| job.build(k, st)) {
        Ok(b) => b,
        Err(e) => {
            for &(k, _) in &items {
                let _ = std::fs::remove_dir_all(job.scratch(k));
            }
            if !out_existed {
                // Only when empty: a failed node's logs stay.
                let _ = std::fs::remove_dir(&out);
            }
            return Err(e);
        }
    };
    let mut results = vec![];
    for (tmp, dest, r) in &built {
        let _ = std::fs::remove_dir_all(dest);
        std::fs::rename(tmp, dest)
            .map_err(|e| format!("error: cannot move {} into place: {e}", dest.display()))?;
        results.push(r.clone());
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
        flow: o.flow.name().to_string(),
        tools,
        nodes: results,
    };
    write_report(&out, &report)?;
    // A node that misses timing fails the run (exit status 1); one that
    // does not fit was refused above (2).
    Ok(report.nodes.iter().all(|r| r.status != "timing failed"))
}

/// What every node of a run is built with.
struct NodeJob<'a> {
    out: &'a Path,
    cfg: &'a Config,
    target: &'a str,
    fpga: Option<&'a fpga::Fpga>,
    board: Option<&'a boards::Board>,
    flow: fpga::Flow,
    clock: f64,
    seeds: &'a [u64],
}

impl NodeJob<'_> {
    /// Node `k`'s folder in the output (`node<k>-<kind>`).
    fn label(&self, k: usize) -> String {
        format!("node{k}-{}", kind_label(self.cfg.nodes[k].kind))
    }

    /// Node `k`'s scratch folder, moved into place when every node is built.
    fn scratch(&self, k: usize) -> PathBuf {
        self.out
            .join(format!(".{}.{}.tmp", self.label(k), std::process::id()))
    }

    /// Builds node `k` in its scratch folder: `(scratch, destination,
    /// result)`. A node the device cannot hold is refused (its folder
    /// removed); a failed tool keeps its folder as `<label>.failed`.
    fn build(&self, k: usize, st: &NodeStatic) -> Result<(PathBuf, PathBuf, NodeResult), String> {
        let label = self.label(k);
        let tmp = self.scratch(k);
        let _ = std::fs::remove_dir_all(&tmp);
        std::fs::create_dir_all(&tmp)
            .map_err(|e| format!("error: cannot create {}: {e}", tmp.display()))?;
        let mut r = NodeResult {
            node: k,
            kind: st.kind.name().to_string(),
            ..Default::default()
        };
        let step =
            crate::progress::Step::start(format!("synth {}: node {k} ({})", self.target, r.kind));
        let res = match self.target {
            _ if self.fpga.is_some() => {
                let f = self.fpga.expect("checked");
                let slave = matches!(st.kind, Kind::Sensor | Kind::Actuator);
                let b = self.board.filter(|_| slave);
                fpga::build(&tmp, st, f, b, self.flow, self.clock, self.seeds, &mut r)
            }
            t if cpld(t).is_some() => {
                let c = cpld(t).expect("matched");
                xc2c(&tmp, st, &c, self.clock, &mut r)
            }
            "xc6s" => xc6s(&tmp, st, &mut r),
            _ => xem(&tmp, st, &mut r),
        };
        step.done(match &res {
            Ok(()) => &r.status,
            Err(_) => "failed",
        });
        if res.is_ok() && r.status == "does not fit" {
            // The device cannot hold the node: refused, nothing left behind.
            let _ = std::fs::remove_dir_all(&tmp);
            return Err(format!(
                "error: node {k} ({}) does not fit the {}: {}",
                r.kind,
                device_name(self.target, self.fpga),
                r.reason
            ));
        }
        if let Err(e) = res {
            let keep = self.out.join(format!("{label}.failed"));
            let _ = std::fs::remove_dir_all(&keep);
            let _ = std::fs::rename(&tmp, &keep);
            return Err(format!("{e}\n(tool logs kept in {})", keep.display()));
        }
        r.artifacts = r.artifacts.iter().map(|a| format!("{label}/{a}")).collect();
        crate::progress::line(&format!("  node {k}: {}{}", r.status, summary(&r)));
        Ok((tmp, self.out.join(&label), r))
    }
}

/// Writes `synth.json` and `synth.md` into `out`.
fn write_report(out: &Path, report: &Report) -> Result<(), String> {
    let json = serde_json::to_string_pretty(report).map_err(|e| format!("error: {e}"))?;
    crate::write_atomic(&out.join("synth.json"), &json)?;
    crate::write_atomic(&out.join("synth.md"), &markdown(report))?;
    eprintln!(
        "wrote {} and {}",
        out.join("synth.md").display(),
        out.join("synth.json").display()
    );
    Ok(())
}

/// The device of a target, as its vendor names it.
fn device_name(target: &str, f: Option<&fpga::Fpga>) -> String {
    match (f, cpld(target)) {
        (Some(f), _) => f.bram.device.to_string(),
        (None, Some(c)) => c.device.to_string(),
        _ => target.to_string(),
    }
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
    s.push_str(&format!("Flow: {}.\n\n", r.flow));
    s.push_str("| node | kind | status | LUTs | FFs | BRAM | LCs | I/O | Fmax MHz (best) | min / median over seeds | max line rate Mbit/s | macrocells | product terms | note |\n");
    s.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    let of = |u: &Option<u64>, a: &Option<u64>| match (u, a) {
        (Some(u), Some(a)) => format!("{u} / {a}"),
        _ => opt(u),
    };
    let mhz = |f: Option<f64>| f.map_or("—".into(), |f| format!("{f:.2}"));
    for n in &r.nodes {
        let spread = match (n.fmax_min_mhz, n.fmax_median_mhz) {
            (Some(lo), Some(md)) => format!("{lo:.2} / {md:.2} ({} seeds)", n.seeds.len()),
            _ => "—".into(),
        };
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            n.node,
            n.kind,
            n.status,
            opt(&n.luts),
            opt(&n.ffs),
            of(&n.brams, &n.brams_available),
            of(&n.lcs, &n.lcs_available),
            opt(&n.ios),
            mhz(n.fmax_mhz),
            spread,
            n.max_line_rate_mbps
                .map_or("—".into(), |f| format!("{f:.1}")),
            opt(&n.macrocells),
            opt(&n.pterms),
            n.reason
        ));
    }
    for n in r.nodes.iter().filter(|n| !n.clocks.is_empty()) {
        s.push_str(&format!(
            "\nClocks of node {} (nextpnr, seeds {:?}):\n\n",
            n.node, n.seeds
        ));
        for c in &n.clocks {
            let v: Vec<String> = c.fmax_mhz.iter().map(|f| format!("{f:.2}")).collect();
            s.push_str(&format!(
                "- `{}`: constraint {:.1} MHz, Fmax {} MHz\n",
                c.name,
                c.constraint_mhz,
                v.join(", ")
            ));
        }
    }
    for n in r.nodes.iter().filter(|n| !n.strategy.is_empty()) {
        s.push_str(&format!(
            "\nSynthesis of node {}: {}.\n",
            n.node, n.strategy
        ));
        for note in &n.notes {
            s.push_str(&format!("- {note}\n"));
        }
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
