//! # boards — the one source of pin truth
//!
//! Purpose: the pin assignment of every board merkur supports, from which
//! the committed files in `gen/constraints/` are generated (`merkur synth`
//! writes the same text beside each build; the test
//! `sim/tests/boards.rs` fails when a committed file drifts from
//! [`constraints_file`], when a ball is used twice, or when a port of the
//! board's top is left unconstrained).
//!
//! | board | file | top | device |
//! |---|---|---|---|
//! | `ice40-hx8k-breakout` | `gen/constraints/ice40-hx8k-breakout.pcf` | `merkur_top` of a slave ([`crate::top::synth_top`]) | iCE40-HX8K-CT256 |
//! | `xem6010` | `gen/constraints/xem6010.ucf` | `merkur_xem6010` ([`crate::top::xem6010`]) | XC6SLX45-2FGG484 |
//! | `ulx3s` | `gen/constraints/ulx3s.lpf` | `merkur_ulx3s` of a slave ([`crate::top::ulx3s`]) | LFE5U-85F (or -45F, -25F) CABGA381 |
//!
//! The iCE40 breakout has no clock the node can run on (its oscillator is
//! 12 MHz and the node needs 2× the line rate and a 90° copy): `clk` and
//! `clk90` come in on header J1 (`clk` on the global-buffer ball H16). The
//! masters' parallel Wishbone port has more pins than the breakout's
//! headers; masters go on the XEM6010, whose USB host interface is bridged
//! to the Wishbone port.

/// One constrained top-level pin.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Pin {
    /// Port bit as the top names it (`i_sensor[3]`, `led[0]`, `clk`).
    pub port: String,
    /// Package ball.
    pub ball: &'static str,
    /// Where it is on the board.
    pub note: &'static str,
}

/// A board.
#[derive(Debug, Clone)]
pub struct Board {
    /// Name (`--board` / the constraints file's stem).
    pub name: &'static str,
    /// Constraints file in `gen/constraints/`.
    pub file: &'static str,
    /// Top module the pins belong to.
    pub top: &'static str,
    /// Device and package.
    pub device: &'static str,
    /// Every pin.
    pub pins: Vec<Pin>,
    /// Timing constraints and remarks emitted before the pins (file syntax).
    pub preamble: &'static str,
}

fn bus(pins: &mut Vec<Pin>, port: &str, balls: &[&'static str], note: &'static str) {
    for (i, b) in balls.iter().enumerate() {
        pins.push(Pin {
            port: format!("{port}[{i}]"),
            ball: b,
            note,
        });
    }
}

fn one(pins: &mut Vec<Pin>, port: &str, ball: &'static str, note: &'static str) {
    pins.push(Pin {
        port: port.to_string(),
        ball,
        note,
    });
}

/// The Lattice iCE40-HX8K breakout board, a slave's `merkur_top`.
pub fn ice40_hx8k_breakout() -> Board {
    let mut p = vec![];
    one(&mut p, "clk", "H16", "J1, global buffer input GBIN2");
    one(&mut p, "clk90", "G16", "J1");
    one(&mut p, "pi", "C16", "J1: primary fibre receiver");
    one(&mut p, "si", "D16", "J1: secondary fibre receiver");
    one(&mut p, "po", "E16", "J1: primary fibre transmitter");
    one(&mut p, "so", "F16", "J1: secondary fibre transmitter");
    one(&mut p, "i_irq1", "J15", "J1");
    one(&mut p, "i_irq2", "G14", "J1");
    one(&mut p, "i_fs_req", "K14", "J1");
    bus(&mut p, "i_diag_sel", &["K15", "M16", "N16"], "J1");
    bus(&mut p, "o_mode", &["B5", "B4"], "LED D2, D3");
    one(&mut p, "o_failsafe", "A2", "LED D4");
    bus(
        &mut p,
        "i_sensor",
        &[
            "T1", "R2", "R3", "T5", "T6", "T7", "T9", "P8", "T10", "T11", "N10", "N12", "T13",
            "T15", "R16", "T2",
        ],
        "J3",
    );
    bus(
        &mut p,
        "o_diag",
        &[
            "B16", "D14", "D15", "E14", "F15", "G15", "H14", "F14", "J14", "K16", "L16", "M15",
            "P15", "A5", "B6", "A6",
        ],
        "J1 (bits 0–12), J2 (13–15)",
    );
    Board {
        name: "ice40-hx8k-breakout",
        file: "ice40-hx8k-breakout.pcf",
        top: "merkur_top (slave)",
        device: "iCE40-HX8K-CT256",
        pins: p,
        preamble: "",
    }
}

/// Opal Kelly XEM6010-LX45: a master's or special master's `merkur_xem6010`.
pub fn xem6010() -> Board {
    let mut p = vec![];
    bus(
        &mut p,
        "hi_in",
        &["Y12", "AB20", "AB7", "AB8", "AA4", "AB4", "Y3", "AB3"],
        "host interface",
    );
    bus(&mut p, "hi_out", &["Y19", "AA8"], "host interface");
    bus(
        &mut p,
        "hi_inout",
        &[
            "AB12", "AA12", "Y13", "AB18", "AA18", "V15", "AB2", "AA2", "Y7", "Y4", "W4", "AB6",
            "AA6", "U13", "U14", "AA20",
        ],
        "host interface",
    );
    one(&mut p, "hi_aa", "W11", "host interface");
    one(&mut p, "hi_muxsel", "AA22", "host interface");
    one(
        &mut p,
        "sys_clk",
        "AB13",
        "PLL (CY22393) output, set to 100 MHz",
    );
    bus(
        &mut p,
        "led",
        &[
            "Y17", "AB17", "AA14", "AB14", "AA16", "AB16", "AA10", "AB10",
        ],
        "LEDs D1–D8",
    );
    one(
        &mut p,
        "pi",
        "W20",
        "expansion connector: primary fibre receiver (verify)",
    );
    one(
        &mut p,
        "si",
        "W22",
        "expansion connector: secondary fibre receiver (verify)",
    );
    one(
        &mut p,
        "po",
        "V21",
        "expansion connector: primary fibre transmitter (verify)",
    );
    one(
        &mut p,
        "so",
        "V22",
        "expansion connector: secondary fibre transmitter (verify)",
    );
    Board {
        name: "xem6010",
        file: "xem6010.ucf",
        top: "merkur_xem6010 (master or special master)",
        device: "XC6SLX45-2FGG484",
        pins: p,
        preamble: XEM6010_TIMING,
    }
}

/// Clock periods and FrontPanel host-interface timing of the XEM6010 (the
/// values of Opal Kelly's FrontPanel HDL for USB 2.0 boards, as
/// `rust-hdl-ok-core` carries them).
const XEM6010_TIMING: &str = "\
CONFIG VCCAUX = \"3.3\"; # required for Spartan-6
NET \"hi_in<0>\" TNM_NET = \"okHostClk\";
TIMESPEC \"TS_okHostClk\" = PERIOD \"okHostClk\" 20.83 ns HIGH 50%;
NET \"hi_inout<*>\" TNM = \"okHostINOUT_grp\";
TIMEGRP \"okHostINOUT_grp\" OFFSET = IN 9.83 ns VALID 9.83 ns BEFORE \"hi_in<0>\" RISING;
TIMEGRP \"okHostINOUT_grp\" OFFSET = OUT 11.63 ns AFTER \"hi_in<0>\" RISING;
NET \"hi_out<0>\" OFFSET = OUT 11.93 ns AFTER \"hi_in<0>\" RISING;
NET \"hi_out<1>\" OFFSET = OUT 11.93 ns AFTER \"hi_in<0>\" RISING;
NET \"hi_in<*>\" OFFSET = IN 14.3 ns VALID 20.83 ns BEFORE \"hi_in<0>\" RISING;
NET \"sys_clk\" TNM_NET = \"SystemClk\";
TIMESPEC \"TS_SystemClk\" = PERIOD \"SystemClk\" 10 ns HIGH 50%;
";

/// The Radiona ULX3S (ECP5, CABGA381; the 25F, 45F and 85F share the
/// ball map): a slave's `merkur_ulx3s`. Balls from the board's published
/// constraints (emard/ulx3s, `doc/constraints/ulx3s_v20.lpf`, PCB v2.x–3.0):
/// fibres and `diag` on header J1, `sensor` on J2 (pins 5–24, clear of
/// the pins shared with the WiFi module), buttons, DIP switch and LEDs.
pub fn ulx3s() -> Board {
    let mut p = vec![];
    one(&mut p, "clk_25mhz", "G2", "25 MHz oscillator");
    one(
        &mut p,
        "pi",
        "B11",
        "J1 pin 5 (GP0): primary fibre receiver",
    );
    one(
        &mut p,
        "si",
        "A10",
        "J1 pin 7 (GP1): secondary fibre receiver",
    );
    one(
        &mut p,
        "po",
        "A9",
        "J1 pin 9 (GP2): primary fibre transmitter",
    );
    one(
        &mut p,
        "so",
        "B9",
        "J1 pin 11 (GP3): secondary fibre transmitter",
    );
    for (i, (ball, name)) in [("R1", "FIRE1"), ("T1", "FIRE2"), ("R18", "UP")]
        .into_iter()
        .enumerate()
    {
        p.push(Pin {
            port: format!("btn[{}]", i + 1),
            ball,
            note: name,
        });
    }
    bus(&mut p, "sw", &["E8", "D8", "D7"], "DIP switch SW1–SW3");
    bus(&mut p, "led", &["B2", "C2", "C1", "D2"], "LEDs D0–D3");
    bus(
        &mut p,
        "sensor",
        &[
            "U18", "U17", "N17", "P16", "N16", "M17", "L16", "L17", "H18", "H17", "F17", "G18",
            "D18", "E17", "C18", "D17",
        ],
        "J2 (GP14/GN14 … GP21/GN21)",
    );
    bus(
        &mut p,
        "diag",
        &[
            "C11", "A11", "B10", "C10", "A7", "A8", "C8", "B8", "C6", "C7", "A6", "B6", "A4", "A5",
            "A2", "B1",
        ],
        "J1 (GN0–GN3, GP4/GN4 … GP9/GN9)",
    );
    Board {
        name: "ulx3s",
        file: "ulx3s.lpf",
        top: "merkur_ulx3s (slave)",
        device: "LFE5U-85F-6BG381C (also -45F, -25F)",
        pins: p,
        preamble: "FREQUENCY PORT \"clk_25mhz\" 25 MHZ;\n",
    }
}

/// Every board.
pub fn all() -> Vec<Board> {
    vec![ice40_hx8k_breakout(), xem6010(), ulx3s()]
}

/// The board of this name.
pub fn by_name(name: &str) -> Option<Board> {
    all().into_iter().find(|b| b.name == name)
}

/// The constraints file of a board (`.pcf` for nextpnr-ice40, `.lpf` for
/// nextpnr-ecp5, `.ucf` for ISE).
pub fn constraints_file(b: &Board) -> String {
    let mut s = format!(
        "# {} — {} on {}\n# Generated by merkur-rtl (rtl/src/top/boards.rs), the one source of pin truth; do not edit.\n",
        b.name, b.top, b.device
    );
    let ucf = b.file.ends_with(".ucf");
    let lpf = b.file.ends_with(".lpf");
    if lpf {
        s.push_str(b.preamble);
    }
    if ucf {
        s.push_str(
            "# The four fibre balls on the expansion connector are not checked against\n\
             # Opal Kelly's XEM6010 pin list (not available where this was written):\n\
             # check them against the board's pin list before connecting fibres.\n",
        );
        s.push_str(b.preamble);
    }
    for p in &b.pins {
        if ucf {
            let port = p.port.replace('[', "<").replace(']', ">");
            s.push_str(&format!(
                "NET \"{port}\" LOC = \"{}\" | IOSTANDARD = LVCMOS33; # {}\n",
                p.ball, p.note
            ));
        } else if lpf {
            s.push_str(&format!(
                "LOCATE COMP \"{}\" SITE \"{}\"; # {}\nIOBUF PORT \"{}\" IO_TYPE=LVCMOS33;\n",
                p.port, p.ball, p.note, p.port
            ));
        } else {
            s.push_str(&format!("set_io {} {} # {}\n", p.port, p.ball, p.note));
        }
    }
    s
}
