//! The open CoolRunner-II fit: `xc2par` (vendored with the changes of
//! third_party/README.md) places and routes Yosys' netlist (`top.json`)
//! on the device's fastest speed grade in its largest package and writes
//! the `.jed`; [`fit`] also writes the pin placement as a Xilinx `.ucf`
//! (docs/synthesis.md, "The open fitter").

use super::{write, Cpld};
use std::collections::BTreeMap;
use std::path::Path;

/// Where the fitter put one port bit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pin {
    /// `name` or `name<bit>` (a bus), as a `.ucf` names it.
    pub port: String,
    /// Function block, from 0 (`FB1` in Xilinx's reports is 0).
    pub fb: u32,
    /// Macrocell in the function block, from 0.
    pub mc: u32,
    /// Package pin.
    pub pin: &'static str,
    /// The global clock (`GCK` index) the pin drives, if any.
    pub gck: Option<u32>,
}

/// Placement iterations before the fitter gives up (xc2par's own default).
const MAX_ITER: u32 = 1000;

/// The part name the fitter takes: device, fastest grade, package
/// (`XC2C256-6-FT256`).
pub fn part(c: &Cpld) -> String {
    format!("{}{}-{}", c.device, c.speeds[0].grade, c.package)
}

/// Places and routes `dir/top.json` on `c`: writes `dir/top.jed` and
/// `dir/top.ucf` and returns the pins, or why the fitter found no
/// placement (nothing written).
pub fn fit(dir: &Path, c: &Cpld) -> Result<Vec<Pin>, String> {
    let json = std::fs::read(dir.join("top.json"))
        .map_err(|e| format!("error: cannot read {}: {e}", dir.join("top.json").display()))?;
    let netlist: serde_json::Value = serde_json::from_slice(&json)
        .map_err(|e| format!("error: {}: {e}", dir.join("top.json").display()))?;
    let part = part(c);
    let dev = xc2bit::XC2DeviceSpeedPackage::from_str(&part)
        .ok_or_else(|| format!("error: the fitter does not know the part {part}"))?;
    let mut jed = Vec::new();
    let placed = xc2par::xc2par_flow_with_pins(
        xc2par::XC2ParOptions::new().max_iter(MAX_ITER),
        dev,
        json.as_slice(),
        &mut jed,
        None,
    )
    .map_err(|e| fit_error(&part, e))?;
    let pins = name_pins(&netlist, &placed, c.pins)?;
    let jed =
        String::from_utf8(jed).map_err(|_| "error: the fitter's .jed is not text".to_string())?;
    write(dir, "top.jed", &jed)?;
    write(dir, "top.ucf", &ucf(&part, &pins))?;
    Ok(pins)
}

/// Why the fitter stopped: a design the device cannot hold, or that the
/// fitter found no placement for, is refused (no `error:` prefix); a
/// netlist it cannot read is a failure of the flow (`error:`).
fn fit_error(part: &str, e: xc2par::PARFlowError) -> String {
    use xc2par::{PARFlowError as F, PARSanityResult as S};
    let why = match e {
        F::PARIterationsExceeded => format!(
            "no placement in {MAX_ITER} iterations: the totals fit, but not each function \
             block's 40 inputs and 56 product terms"
        ),
        F::PARSanityCheckFailed(s) => match s {
            S::FailureTooManyMCs => "the design needs more macrocells than the device has",
            S::FailureTooManyPTerms => "the design needs more product terms than the device has",
            S::FailureTooManyBufgClk => "the design needs more than 3 global clocks",
            S::FailureTooManyBufgGTS => "the design needs more than 4 global output enables",
            S::FailureTooManyBufgGSR => "the design needs more than 1 global set/reset",
            S::FailureGlobalNetWrongLoc => {
                "the design has a global net on a pin that cannot drive it"
            }
            S::FailurePTCNeverSatisfiable | S::Ok => {
                "the design needs product term C twice in a macrocell"
            }
        }
        .to_string(),
        e => {
            return format!(
                "error: the open fitter (xc2par) cannot read the netlist for the {part}: {e}"
            )
        }
    };
    format!("the open fitter (xc2par) on the {part}: {why}")
}

/// The port bit of every pad cell (`IBUF`, `IOBUFE`) of Yosys' netlist:
/// the cell whose pad connection is that bit of a top-level port.
fn pad_ports(netlist: &serde_json::Value) -> BTreeMap<String, String> {
    let m = &netlist["modules"]["merkur_top"];
    let mut bit_port = BTreeMap::new();
    for (name, p) in m["ports"].as_object().into_iter().flatten() {
        let bits = p["bits"].as_array().cloned().unwrap_or_default();
        for (i, b) in bits.iter().enumerate() {
            let label = if bits.len() == 1 {
                name.clone()
            } else {
                format!("{name}<{i}>")
            };
            bit_port.insert(b.to_string(), label);
        }
    }
    let mut out = BTreeMap::new();
    for (name, cell) in m["cells"].as_object().into_iter().flatten() {
        let pad = match cell["type"].as_str() {
            Some("IBUF") => "I",
            Some("IOBUFE") => "IO",
            _ => continue,
        };
        if let Some(port) = cell["connections"][pad]
            .get(0)
            .and_then(|b| bit_port.get(&b.to_string()))
        {
            out.insert(name.clone(), port.clone());
        }
    }
    out
}

/// Names the fitter's pin macrocells by port. xc2par names a pin's
/// macrocell after the cells it merged, the pad cell last, so the pad
/// cell is the longest pad cell name that ends the macrocell's name.
fn name_pins(
    netlist: &serde_json::Value,
    placed: &[xc2par::XC2PinPlacement],
    package: &'static [(u8, u8, &'static str)],
) -> Result<Vec<Pin>, String> {
    let pads = pad_ports(netlist);
    let mut pins = vec![];
    for p in placed {
        let port = pads
            .iter()
            .filter(|(cell, _)| p.name == **cell || p.name.ends_with(&format!("_{cell}")))
            .max_by_key(|(cell, _)| cell.len())
            .map(|(_, port)| port.clone())
            .ok_or_else(|| format!("error: the fitter's pin {} is no port's pad", p.name))?;
        let pin = package
            .iter()
            .find(|&&(fb, mc, _)| u32::from(fb) == p.fb && u32::from(mc) == p.mc)
            .map(|&(_, _, pin)| pin)
            .ok_or_else(|| {
                format!(
                    "error: the fitter put {port} on FB{}_{}, which has no pad",
                    p.fb + 1,
                    p.mc + 1
                )
            })?;
        pins.push(Pin {
            port,
            fb: p.fb,
            mc: p.mc,
            pin,
            gck: p.gck,
        });
    }
    pins.sort_by(|a, b| a.port.cmp(&b.port));
    Ok(pins)
}

/// The pins as a Xilinx `.ucf`, which ISE's CPLD fitter also takes: the
/// open fitter's placement, for a board made to it.
fn ucf(part: &str, pins: &[Pin]) -> String {
    let mut s = format!(
        "# Pins of merkur_top on the {part}, as the open fitter (xc2par) placed them:\n\
         # package pin, and function block and macrocell counted from 1 as\n\
         # Xilinx's reports count them (written by merkur synth).\n"
    );
    for p in pins {
        let gck = p.gck.map(|g| format!(", GCK{g}")).unwrap_or_default();
        s += &format!(
            "NET \"{}\" LOC = \"{}\";  # FB{}_{}{gck}\n",
            p.port,
            p.pin,
            p.fb + 1,
            p.mc + 1
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::super::xc2_jed_sim::Device;
    use super::super::{cpld, read_json, xc2_map, CPLDS};
    use super::*;
    use merkur_sim::Rng;
    use std::collections::HashSet;
    use xc2bit::{fb_mc_num_to_iob_num, iob_num_to_fb_mc_num, XC2Device, XC2ZIAInput};

    fn xc2bit_device(name: &str) -> XC2Device {
        xc2bit::XC2DeviceSpeedPackage::from_str(&part(&cpld(name).unwrap()))
            .expect("the fitter knows every target's part")
            .dev
    }

    /// The generated ZIA maps (third_party/README.md) are maps: in every
    /// row of every device each choice is a different signal of that
    /// device, and every macrocell's feedback and every pad reaches at
    /// least one row. The placeholders they replaced had one choice,
    /// `IBuf{ibuf: 0}`, everywhere.
    #[test]
    fn zia_maps_reach_every_macrocell_and_pad() {
        for name in ["xc2c128", "xc2c256", "xc2c384", "xc2c512"] {
            let dev = xc2bit_device(name);
            let mut reached = HashSet::new();
            for r in 0..xc2bit::INPUTS_PER_ANDTERM {
                let row = xc2bit::zia_table_get_row(dev, r);
                let distinct: HashSet<_> = row.iter().collect();
                assert_eq!(distinct.len(), row.len(), "{name} row {r} repeats a choice");
                for &c in row {
                    match c {
                        XC2ZIAInput::Macrocell { fb, mc } => {
                            assert!((fb as usize) < dev.num_fbs() && mc < 16, "{name} {c:?}");
                        }
                        XC2ZIAInput::IBuf { ibuf } => {
                            let (fb, mc) = iob_num_to_fb_mc_num(dev, u32::from(ibuf))
                                .unwrap_or_else(|| panic!("{name} row {r}: no pad {ibuf}"));
                            assert!((fb as usize) < dev.num_fbs() && mc < 16);
                        }
                        _ => panic!("{name} row {r}: {c:?} among the signals"),
                    }
                    reached.insert(c);
                }
            }
            let signals = dev.num_fbs() * 16 + dev.num_iobs();
            assert_eq!(reached.len(), signals, "{name}: signals that reach no row");
        }
    }

    /// Every target's part is one the fitter knows, and its pin table
    /// (from Project Combine's package bonds) has a pin for exactly the
    /// macrocells that xc2bit gives a pad: two sources that agree.
    #[test]
    fn package_pins_are_the_pads_xc2bit_knows() {
        for c in CPLDS {
            let dev = xc2bit_device(c.name);
            let pins = c.pins;
            let names: HashSet<_> = pins.iter().map(|p| p.2).collect();
            assert_eq!(names.len(), pins.len(), "{}: a pin twice", c.device);
            let table: HashSet<_> = pins.iter().map(|p| (p.0 as u32, p.1 as u32)).collect();
            let pads: HashSet<_> = (0..dev.num_fbs() as u32)
                .flat_map(|fb| (0..16).map(move |mc| (fb, mc)))
                .filter(|&(fb, mc)| fb_mc_num_to_iob_num(dev, fb, mc).is_some())
                .collect();
            assert_eq!(table, pads, "{}", c.device);
            // The data sheet's user I/O: the pads, and the XC2C32A's input-only pin.
            let extra = u64::from(c.device == "XC2C32A");
            assert_eq!(pins.len() as u64 + extra, c.io, "{}", c.device);
        }
    }

    /// The test design: counters, an LFSR and samples on all four edges of
    /// two clocks, as a merkur slave's capture has them (`clk` ↑ and ↓,
    /// `clk90` ↑ and ↓), with inputs through pads, registered outputs and
    /// one combinational output. Small enough for the XC2C64A.
    const DESIGN: &str = "module merkur_top(clk, clk90, d, en, k, cnt, lfsr, sh, par, hold, any);
  input clk, clk90, d, en;
  input [3:0] k;
  output reg [7:0] cnt = 8'd3;
  output reg [15:0] lfsr = 16'hace1;
  output reg [3:0] sh = 4'd0;
  output reg par = 1'b0;
  output reg hold = 1'b1;
  output wire any;
  always @(posedge clk) if (en) cnt <= cnt + {4'd0, k};
  always @(posedge clk) lfsr <= {lfsr[14:0], lfsr[15] ^ lfsr[13] ^ lfsr[12] ^ lfsr[10] ^ d};
  always @(posedge clk90) par <= ^sh & en;
  always @(negedge clk) hold <= sh[3] ^ lfsr[0];
  always @(negedge clk90) sh <= {sh[2:0], d ^ cnt[0]};
  assign any = (|lfsr[15:8]) & cnt[7];
endmodule
";

    /// [`DESIGN`], naively: its registers after each clock edge.
    #[derive(Clone, Copy, Debug, PartialEq)]
    struct Reference {
        cnt: u8,
        lfsr: u16,
        sh: u8,
        par: bool,
        hold: bool,
    }

    impl Reference {
        /// Edge `e` of a clock: 0 `clk` ↑, 1 `clk90` ↑, 2 `clk` ↓, 3 `clk90` ↓.
        fn edge(&mut self, e: u32, d: bool, en: bool, k: u8) {
            let bit = |x: u16, i: u32| (x >> i) & 1;
            match e {
                0 => {
                    if en {
                        self.cnt = self.cnt.wrapping_add(k);
                    }
                    let l = self.lfsr;
                    let fb = bit(l, 15) ^ bit(l, 13) ^ bit(l, 12) ^ bit(l, 10) ^ u16::from(d);
                    self.lfsr = (l << 1) | fb;
                }
                1 => self.par = (self.sh.count_ones() % 2 == 1) && en,
                2 => self.hold = ((self.sh >> 3) & 1 == 1) ^ (self.lfsr & 1 == 1),
                _ => self.sh = ((self.sh << 1) & 0xf) | u8::from(d ^ (self.cnt & 1 == 1)),
            }
        }

        /// Every output port bit's level, by `.ucf` name.
        fn outputs(&self) -> Vec<(String, bool)> {
            let mut v = vec![];
            let mut bus = |name: &str, val: u32, n: u32| {
                for i in 0..n {
                    v.push((format!("{name}<{i}>"), (val >> i) & 1 == 1));
                }
            };
            bus("cnt", self.cnt.into(), 8);
            bus("lfsr", self.lfsr.into(), 16);
            bus("sh", self.sh.into(), 4);
            v.push(("par".into(), self.par));
            v.push(("hold".into(), self.hold));
            v.push(("any".into(), self.lfsr >> 8 != 0 && self.cnt >> 7 == 1));
            v
        }
    }

    /// Synthesises `verilog` with `merkur synth`'s CoolRunner-II mapping
    /// (Yosys, then the covers chosen again: `super::super::xc2_cover`),
    /// fits it on `c` and returns the folder with `top.jed` and the pins.
    /// With `MERKUR_KEEP_XC2_FIT=<dir>` the folders stay, as
    /// `<dir>/<label>-<target>` (scripts/check-xc2-jed.sh reads their
    /// `.jed`).
    fn build(c: &Cpld, label: &str, verilog: &str) -> (std::path::PathBuf, Vec<Pin>) {
        let dir = match std::env::var_os("MERKUR_KEEP_XC2_FIT") {
            Some(d) => std::path::PathBuf::from(d).join(format!("{label}-{}", c.name)),
            None => std::env::temp_dir().join(format!(
                "merkur-xc2fit-{}-{label}-{}",
                std::process::id(),
                c.name
            )),
        };
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("top.v"), verilog).unwrap();
        xc2_map(&dir)
            .unwrap_or_else(|e| panic!("{e}"))
            .unwrap_or_else(|e| panic!("the covers were not chosen again: {e}"));
        // A net that nothing drives or reads, as Yosys 0.23 leaves in a
        // merkur node (`node.reason[0]` on ring8's sensor): the fitter
        // must pass it by (third_party/README.md).
        let mut j: serde_json::Value = read_json(&dir, "top.json").unwrap();
        j["modules"]["merkur_top"]["netnames"]["dangling"] =
            serde_json::json!({"hide_name": 0, "bits": [1_000_000], "attributes": {}});
        std::fs::write(dir.join("top.json"), j.to_string()).unwrap();
        let pins = fit(&dir, c).unwrap_or_else(|e| panic!("{}: {e}", c.device));
        (dir, pins)
    }

    /// A fitted design on the model of its device, driven and read by
    /// port name through the fitter's pins.
    struct Board {
        dev: Device,
        pins: Vec<Pin>,
        part: &'static str,
        seed: u64,
    }

    impl Board {
        /// The `.jed` in `dir`, on the model of the device.
        fn open(dir: &std::path::Path, pins: Vec<Pin>, part: &'static str, seed: u64) -> Board {
            let dev = Device::from_jed(&std::fs::read(dir.join("top.jed")).unwrap());
            Board {
                dev,
                pins,
                part,
                seed,
            }
        }

        fn pin(&self, port: &str) -> &Pin {
            self.pins
                .iter()
                .find(|p| p.port == port)
                .unwrap_or_else(|| panic!("{}: no pin for {port}", self.part))
        }
        /// The global clock that `port` drives.
        fn gck(&self, port: &str) -> u32 {
            self.pin(port)
                .gck
                .unwrap_or_else(|| panic!("{}: {port} not on a GCK", self.part))
        }
        /// Drives input bus `port` (`width` bits; 1: a single pin).
        fn drive(&mut self, port: &str, width: u32, value: u64) {
            for i in 0..width {
                let name = if width == 1 {
                    port.to_string()
                } else {
                    format!("{port}<{i}>")
                };
                let (fb, mc) = (self.pin(&name).fb, self.pin(&name).mc);
                self.dev.set_pad(fb, mc, (value >> i) & 1 == 1);
            }
        }
        /// Every output pad against the reference's levels.
        fn check(&self, want: &[(String, bool)], when: &str) {
            for (port, level) in want {
                let p = self.pin(port);
                assert_eq!(
                    self.dev.out_pad(p.fb, p.mc),
                    *level,
                    "{}: {port} {when} (seed {}, MERKUR_SEED to repeat)",
                    self.part,
                    self.seed
                );
            }
        }
    }

    /// The open fitter's `.jed`, read back and run ([`Device`]), computes
    /// [`DESIGN`]: every output pad agrees with the reference model after
    /// every clock edge of 400 cycles of seeded random inputs. On the
    /// XC2C64A (xc2bit's ZIA map from hardware fuzzing) and on the XC2C256
    /// and XC2C512 (the maps generated from Project Combine). The clocks
    /// are on global clock pins and the `.ucf` names every port bit.
    #[test]
    fn the_fitted_jed_computes_the_design() {
        let seed = Rng::seed(21);
        for name in ["xc2c64a", "xc2c256", "xc2c512"] {
            let c = cpld(name).unwrap();
            let (dir, pins) = build(&c, "small", DESIGN);
            assert_eq!(pins.len(), 39, "{}: every port bit placed", c.device);
            let ucf = std::fs::read_to_string(dir.join("top.ucf")).unwrap();
            for p in &pins {
                assert!(ucf.contains(&format!("NET \"{}\" LOC = \"{}\";", p.port, p.pin)));
            }
            let mut b = Board::open(&dir, pins, c.device, seed);
            let (clk, clk90) = (b.gck("clk"), b.gck("clk90"));
            let mut reference = Reference {
                cnt: 3,
                lfsr: 0xace1,
                sh: 0,
                par: false,
                hold: true,
            };
            let mut rng = Rng::new(seed);
            b.check(&reference.outputs(), "at power-up");
            for cycle in 0..400 {
                let (d, en, k) = (rng.below(2) == 1, rng.below(4) != 0, rng.below(16) as u8);
                b.drive("d", 1, d.into());
                b.drive("en", 1, en.into());
                b.drive("k", 4, k.into());
                for (e, (g, rising)) in [(clk, true), (clk90, true), (clk, false), (clk90, false)]
                    .into_iter()
                    .enumerate()
                {
                    b.dev.clock(g, rising);
                    reference.edge(e as u32, d, en, k);
                    b.check(
                        &reference.outputs(),
                        &format!("after edge {e} of cycle {cycle}"),
                    );
                }
            }
            if std::env::var_os("MERKUR_KEEP_XC2_FIT").is_none() {
                let _ = std::fs::remove_dir_all(&dir);
            }
        }
    }

    /// Registers of the crowded design ([`crowded_design`]).
    const CROWDED: usize = 10;

    /// A design that fills the XC2C256 as a slave would: [`CROWDED`]
    /// 16-bit shift registers with feedback, each enabled by a bit of the
    /// one before, a multiplexer over them and a shift register on
    /// `clk90` ↓; about two thirds of the macrocells and 85 % of the
    /// product terms. The placer needs many iterations to place it.
    fn crowded_design() -> String {
        let mut v = String::from(
            "module merkur_top(clk, clk90, d, en, sel, q, p);\n  input clk, clk90, d, en;\n  \
             input [3:0] sel;\n  output reg [3:0] q = 4'd0;\n  output reg [7:0] p = 8'd0;\n",
        );
        for i in 0..CROWDED {
            v += &format!("  reg [15:0] c{i} = 16'd{};\n", i * 7 + 1);
        }
        for i in 0..CROWDED {
            let prev = (i + CROWDED - 1) % CROWDED;
            v += &format!(
                "  always @(posedge clk) if (en ^ c{prev}[{}]) c{i} <= {{c{i}[14:0], c{i}[15] ^ c{i}[{}] ^ d}};\n",
                i % 16,
                (i * 3) % 15
            );
        }
        v += "  always @(posedge clk) case (sel)\n";
        for i in 0..CROWDED {
            v += &format!("    4'd{i}: q <= c{i}[3:0];\n");
        }
        v += "    default: q <= q ^ c0[7:4];\n  endcase\n";
        v += "  always @(negedge clk90) p <= {p[6:0], ^q};\nendmodule\n";
        v
    }

    /// [`crowded_design`], naively.
    struct Crowded {
        c: [u16; CROWDED],
        q: u8,
        p: u8,
    }

    impl Crowded {
        fn clk_rise(&mut self, d: bool, en: bool, sel: usize) {
            let old = self.c;
            for i in 0..CROWDED {
                let prev = old[(i + CROWDED - 1) % CROWDED];
                if en ^ ((prev >> (i % 16)) & 1 == 1) {
                    let x = old[i];
                    let fb = (x >> 15) ^ (x >> ((i * 3) % 15)) ^ u16::from(d);
                    self.c[i] = (x << 1) | (fb & 1);
                }
            }
            self.q = if sel < CROWDED {
                (old[sel] & 0xf) as u8
            } else {
                self.q ^ ((old[0] >> 4) & 0xf) as u8
            };
        }

        fn clk90_fall(&mut self) {
            self.p = (self.p << 1) | (self.q.count_ones() % 2) as u8;
        }

        fn outputs(&self) -> Vec<(String, bool)> {
            let q = (0..4).map(|i| (format!("q<{i}>"), (self.q >> i) & 1 == 1));
            let p = (0..8).map(|i| (format!("p<{i}>"), (self.p >> i) & 1 == 1));
            q.chain(p).collect()
        }
    }

    /// The placer at work: [`crowded_design`] on the XC2C256 is placed,
    /// and its `.jed` computes the design for 200 cycles of seeded random
    /// inputs, as [`the_fitted_jed_computes_the_design`] checks.
    #[test]
    fn a_crowded_xc2c256_is_placed_and_computes() {
        let seed = Rng::seed(2121);
        let c = cpld("xc2c256").unwrap();
        let (dir, pins) = build(&c, "crowded", &crowded_design());
        let netlist: serde_json::Value = read_json(&dir, "top.json").unwrap();
        let count = |t: &str| {
            netlist["modules"]["merkur_top"]["cells"]
                .as_object()
                .unwrap()
                .values()
                .filter(|x| x["type"] == t)
                .count() as u64
        };
        let (mc, pt) = (count("MACROCELL_XOR"), count("ANDTERM"));
        assert!(
            mc * 100 >= 60 * c.macrocells && pt * 100 >= 80 * c.pterms(),
            "the design no longer crowds the device: {mc} macrocells, {pt} product terms"
        );
        let mut b = Board::open(&dir, pins, c.device, seed);
        let (clk, clk90) = (b.gck("clk"), b.gck("clk90"));
        let mut r = Crowded {
            c: std::array::from_fn(|i| (i * 7 + 1) as u16),
            q: 0,
            p: 0,
        };
        let mut rng = Rng::new(seed);
        b.check(&r.outputs(), "at power-up");
        for cycle in 0..200 {
            let (d, en, sel) = (rng.below(2) == 1, rng.below(2) == 1, rng.below(16) as usize);
            b.drive("d", 1, d.into());
            b.drive("en", 1, en.into());
            b.drive("sel", 4, sel as u64);
            b.dev.clock(clk, true);
            r.clk_rise(d, en, sel);
            b.check(&r.outputs(), &format!("after clk rose, cycle {cycle}"));
            b.dev.clock(clk90, true);
            b.dev.clock(clk, false);
            b.dev.clock(clk90, false);
            r.clk90_fall();
            b.check(&r.outputs(), &format!("after clk90 fell, cycle {cycle}"));
        }
        if std::env::var_os("MERKUR_KEEP_XC2_FIT").is_none() {
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
}
