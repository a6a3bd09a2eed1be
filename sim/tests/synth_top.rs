//! The synthesis tops (rtl/src/top/synth_top.rs, rtl/src/top/xem6010.rs): the DDR
//! capture and output stages deliver samples and pairs in the order the
//! node's ports assume (Icarus, seeded random lines); the XEM6010 bridge
//! reads and writes a real master's memories over Wishbone (Icarus); every
//! top is `verilator --lint-only -Wall` clean.

use merkur_model::scenario::Kind;
use merkur_rtl::emit::verilog::WAIVERS;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::top::synth_top::{node_top, NodeStatic, DDR_IO};
use merkur_rtl::top::ulx3s::{ulx3s_verilog, ECP5_BLACKBOXES, PLL_BLACKBOX};
use merkur_rtl::top::xem6010::{
    xem6010_core_verilog, xem6010_verilog, OK_BLACKBOXES, XILINX_BLACKBOXES,
};
use merkur_sim::Rng;
use std::path::PathBuf;
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("merkur-synthtop-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Compiles `files` with Icarus and runs them; returns stdout.
fn icarus(name: &str, files: &[(&str, &str)]) -> String {
    let d = scratch(name);
    for (f, text) in files {
        std::fs::write(d.join(f), text).unwrap();
    }
    let mut args = vec!["-o".to_string(), "sim.vvp".to_string()];
    args.extend(
        files
            .iter()
            .filter(|(f, _)| f.ends_with(".v"))
            .map(|(f, _)| f.to_string()),
    );
    let o = Command::new("iverilog")
        .args(&args)
        .current_dir(&d)
        .output()
        .expect("iverilog runs");
    assert!(
        o.status.success(),
        "iverilog: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = Command::new("vvp")
        .args(["-n", "sim.vvp"])
        .current_dir(&d)
        .output()
        .expect("vvp runs");
    assert!(
        o.status.success(),
        "vvp: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let _ = std::fs::remove_dir_all(&d);
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn st(kind: Kind) -> NodeStatic {
    NodeStatic {
        kind,
        address: 3,
        slots: 9,
        period: 330,
        rtx: Default::default(),
        layout: Default::default(),
        diag: true,
        sensor_sync: true,
        format: WordFormat::Basic,
    }
}

#[test]
fn ddr_stages_keep_the_order_of_samples_and_pairs() {
    let seed = Rng::seed(0xdd1);
    let mut rng = Rng::new(seed);
    const N: usize = 200;
    // Line level per quarter clock (10 time units; the clock period is 40),
    // changing halfway between sampling instants.
    let v: Vec<u8> = (0..4 * N).map(|_| rng.below(2) as u8).collect();
    // The other line (SI to the first's PI) and, per clock, the node's
    // capture choice (o_cap_si: take the other line's samples).
    let v2: Vec<u8> = (0..4 * N).map(|_| rng.below(2) as u8).collect();
    let sels: Vec<u8> = (0..N).map(|_| rng.below(2) as u8).collect();
    let pairs: Vec<u8> = (0..N).map(|_| rng.below(4) as u8).collect();
    let hex = |xs: &[u8]| xs.iter().map(|x| format!("{x:x}\n")).collect::<String>();
    let tb = format!(
        r#"`timescale 1ns/1ps
module tb;
    // clk rises at 40k, clk90 at 40k+10: samples at 10j for quarter j.
    reg clk = 1'b1;
    reg clk90 = 1'b0;
    reg d = 1'b0;
    reg d2 = 1'b0;
    reg sel = 1'b0;
    reg [1:0] pair = 2'd0;
    reg [0:0] lv [0:{l}];
    reg [0:0] lv2 [0:{l}];
    reg [0:0] sv [0:{n1}];
    reg [1:0] pv [0:{n1}];
    wire [3:0] q;
    wire [3:0] q2;
    wire [3:0] s1;
    wire [3:0] s2;
    wire line;
    integer j;
    integer k;
    merkur_ddr_in cap(.clk(clk), .clk90(clk90), .d(d), .alt(s2), .sel(sel), .s(s1), .q(q));
    merkur_ddr_in cap2(.clk(clk), .clk90(clk90), .d(d2), .alt(s1), .sel(sel), .s(s2), .q(q2));
    merkur_ddr_out out(.clk(clk), .d(pair), .q(line));
    always #20 clk = ~clk;
    initial begin #10 clk90 = 1'b1; forever #20 clk90 = ~clk90; end
    initial begin
        $readmemh("lv.hex", lv);
        $readmemh("pv.hex", pv);
        $readmemh("lv2.hex", lv2);
        $readmemh("sv.hex", sv);
        d = lv[0][0];
        d2 = lv2[0][0];
        // quarter j's level is driven over [10j-5, 10j+5)
        #5;
        for (j = 1; j <= {l}; j = j + 1) begin
            d = lv[j][0];
            d2 = lv2[j][0];
            #10;
        end
    end
    initial begin
        for (k = 1; k < {n}; k = k + 1) begin
            @(posedge clk);
            #1;
            // the samples of clock k-1; the pair of clock k (as a register
            // updated at this edge would give it)
            $display("Q %0d %h", k, q);
            $display("R %0d %h", k, q2);
            pair = pv[k];
            sel = sv[k][0];
            #10 $display("H %0d %b", k, line);
            #20 $display("L %0d %b", k, line);
        end
        $finish;
    end
endmodule
"#,
        l = 4 * N - 1,
        n1 = N - 1,
        n = N
    );
    let out = icarus(
        "ddr",
        &[
            ("tb.v", &tb),
            ("ddr.v", DDR_IO),
            ("lv.hex", &hex(&v)),
            ("pv.hex", &hex(&pairs)),
            ("lv2.hex", &hex(&v2)),
            ("sv.hex", &hex(&sels)),
        ],
    );
    let mut checked = 0;
    for l in out.lines() {
        let f: Vec<&str> = l.split_whitespace().collect();
        if f.len() != 3 {
            continue;
        }
        let k: usize = f[1].parse().unwrap();
        match f[0] {
            // Just after clk rises (clock k): the four samples of clock
            // k − 1, quarter 4(k − 1) first in bit 0; of the other line
            // when the choice in clock k − 1 was high (the register takes
            // it with the samples).
            "Q" | "R" if k >= 2 => {
                let q = u8::from_str_radix(f[2], 16).unwrap();
                let m = k - 1;
                let own = if f[0] == "Q" { &v } else { &v2 };
                let other = if f[0] == "Q" { &v2 } else { &v };
                let line = if sels[m] == 1 { other } else { own };
                let want = line[4 * m]
                    | line[4 * m + 1] << 1
                    | line[4 * m + 2] << 2
                    | line[4 * m + 3] << 3;
                assert_eq!(
                    q, want,
                    "seed {seed}: capture {} in clock {m} (choice {}): got {q:04b}, want {want:04b}",
                    f[0], sels[m]
                );
                checked += 1;
            }
            // The pair of clock k − 1 goes out in clock k: bit 0 while clk
            // is high, bit 1 while it is low.
            "H" if k >= 2 => {
                let want = pairs[k - 1] & 1;
                assert_eq!(
                    f[2],
                    want.to_string(),
                    "seed {seed}: first half of clock {k}"
                );
                checked += 1;
            }
            "L" if k >= 2 => {
                let want = pairs[k - 1] >> 1;
                assert_eq!(
                    f[2],
                    want.to_string(),
                    "seed {seed}: second half of clock {k}"
                );
                checked += 1;
            }
            _ => {}
        }
    }
    assert!(
        checked > 4 * (N - 10),
        "seed {seed}: only {checked} checks ran:\n{out}"
    );
}

#[test]
fn the_xem6010_bridge_reads_and_writes_a_master_over_wishbone() {
    let core = xem6010_core_verilog(&st(Kind::Master)).unwrap();
    // Host transfers as FrontPanel makes them: wires set, then a one-clock
    // trigger; the host waits for busy to fall.
    let tb = r#"`timescale 1ns/1ps
module tb;
    reg clk = 1'b0;
    reg clk90 = 1'b0;
    reg [15:0] adr = 16'd0;
    reg [15:0] dat = 16'd0;
    reg [15:0] trig = 16'd0;
    wire [15:0] rdat;
    wire [15:0] status;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [15:0] diag;
    wire [7:0] led;
    wire po;
    wire so;
    always #5 clk = ~clk;
    initial begin #2.5 clk90 = 1'b1; forever #5 clk90 = ~clk90; end
    merkur_xem6010_core core(.clk(clk), .clk90(clk90), .pi(1'b0), .si(1'b0), .po(po), .so(so),
        .i_adr(adr), .i_dat(dat), .i_ctl(16'd0), .i_trig(trig),
        .o_rdat(rdat), .o_status(status), .o_diag(diag), .o_led(led));
    task xfer(input we, input [15:0] a, input [15:0] d);
        integer w;
        begin
            adr = a; dat = d;
            repeat (4) @(posedge clk);
            #1 trig = we ? 16'd1 : 16'd2;
            @(posedge clk);
            #1 trig = 16'd0;
            w = 0;
            while (status[0] !== 1'b0 || w < 2) begin
                @(posedge clk);
                w = w + 1;
                if (w > 50) begin $display("TIMEOUT"); $finish; end
            end
            #1;
            if (!we) $display("R %h %h", a, rdat);
        end
    endtask
    initial begin
        repeat (10) @(posedge clk);
        xfer(1, 16'h1003, 16'h0008);   // slot 3: LOCAL
        xfer(0, 16'h1003, 16'h0000);
        xfer(1, 16'h0003, 16'hbeef);   // LOCAL slot: written
        xfer(0, 16'h0003, 16'h0000);
        xfer(1, 16'h0004, 16'h1234);   // not LOCAL: refused
        xfer(0, 16'h0004, 16'h0000);
        xfer(0, 16'h2000, 16'h0000);   // status: data write refused (bit 2)
        $finish;
    end
endmodule
"#;
    let out = icarus("bridge", &[("tb.v", tb), ("core.v", &core)]);
    let reads: Vec<&str> = out.lines().filter(|l| l.starts_with('R')).collect();
    assert!(
        !out.contains("TIMEOUT"),
        "a transfer never finished:\n{out}"
    );
    assert_eq!(reads.len(), 4, "{out}");
    assert_eq!(reads[0], "R 1003 0008", "{out}");
    assert_eq!(reads[1], "R 0003 beef", "{out}");
    assert_eq!(reads[2], "R 0004 0000", "{out}");
    let st = u16::from_str_radix(reads[3].split_whitespace().nth(2).unwrap(), 16).unwrap();
    assert_eq!(
        st & 0b101,
        0b100,
        "status {st:04x}: not running, data write refused"
    );
}

fn lint(name: &str, top: &str, files: &[(&str, &str)]) {
    let d = scratch(&format!("lint-{name}"));
    let mut paths = vec![d.join("waivers.vlt")];
    std::fs::write(&paths[0], WAIVERS).unwrap();
    for (f, text) in files {
        std::fs::write(d.join(f), text).unwrap();
        paths.push(d.join(f));
    }
    let refs: Vec<&std::path::Path> = paths.iter().map(|p| p.as_path()).collect();
    if let Err(err) = merkur_sim::verilator::lint(&refs, top) {
        panic!("{name}: lint:\n{err}");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn every_synthesis_top_is_lint_clean() {
    for kind in [
        Kind::Sensor,
        Kind::Actuator,
        Kind::Master,
        Kind::SpecialMaster,
    ] {
        let v = node_top(&st(kind)).unwrap();
        lint(kind.name(), "merkur_top", &[("top.v", &v)]);
        // The lean top (`merkur synth --diag off`): no diagnostic mux; a
        // sensor keeps its input, an actuator shows its register on o_act.
        let lean = node_top(&NodeStatic {
            diag: false,
            ..st(kind)
        })
        .unwrap();
        lint(
            &format!("lean-{}", kind.name()),
            "merkur_top",
            &[("top.v", &lean)],
        );
        let head = lean.split("module merkur_top(").nth(1).unwrap();
        let ports = &head[..head.find(')').unwrap()];
        assert!(
            !ports.contains("o_diag") && !ports.contains("i_diag_sel"),
            "{ports}"
        );
        assert_eq!(ports.contains("i_sensor"), kind == Kind::Sensor, "{ports}");
        assert_eq!(ports.contains("o_act"), kind == Kind::Actuator, "{ports}");
        if kind == Kind::Actuator {
            assert!(
                lean.contains("assign o_act = act_data;") && lean.contains(".o_act_data(act_data)")
            );
        }
        if kind == Kind::Sensor {
            // The sensor value through its two-flip-flop synchroniser …
            assert!(
                lean.contains("sensor_m <= i_sensor;")
                    && lean.contains("sensor <= sensor_m;")
                    && lean.contains(".i_sensor_data(sensor)"),
                "{lean}"
            );
            // … or, with `--sensor-sync off`, straight from the pins.
            let bare = node_top(&NodeStatic {
                diag: false,
                sensor_sync: false,
                ..st(kind)
            })
            .unwrap();
            lint("bare-sensor", "merkur_top", &[("top.v", &bare)]);
            assert!(
                !bare.contains("sensor_m") && bare.contains(".i_sensor_data(i_sensor)"),
                "{bare}"
            );
        }
    }
    for kind in [Kind::Sensor, Kind::Actuator] {
        let v = ulx3s_verilog(&st(kind)).unwrap();
        lint(
            &format!("ulx3s-{}", kind.name()),
            "merkur_ulx3s",
            &[
                ("top.v", &v),
                ("pll.v", PLL_BLACKBOX),
                ("ecp5.v", ECP5_BLACKBOXES),
            ],
        );
    }
    for kind in [Kind::Master, Kind::SpecialMaster] {
        let v = xem6010_verilog(&st(kind)).unwrap();
        lint(
            &format!("xem6010-{}", kind.name()),
            "merkur_xem6010",
            &[
                ("top.v", &v),
                ("ok.v", OK_BLACKBOXES),
                ("xilinx.v", XILINX_BLACKBOXES),
            ],
        );
    }
}

#[test]
fn bad_node_configurations_are_refused() {
    let mut s = st(Kind::Sensor);
    s.slots = 5000;
    assert!(node_top(&s).unwrap_err().contains("slots 5000"));
    let mut s = st(Kind::Sensor);
    s.address = 9;
    assert!(node_top(&s).unwrap_err().contains("address 9"));
    // The 20-bit period and CS timeout ports (protocol §8: P ≤ 149,796).
    let mut s = st(Kind::SpecialMaster);
    s.period = 149_796;
    assert!(node_top(&s).is_ok());
    s.period = 149_797;
    assert!(node_top(&s).unwrap_err().contains("period 149797"));
    assert!(xem6010_verilog(&st(Kind::Sensor))
        .unwrap_err()
        .contains("not a sensor"));
    assert!(ulx3s_verilog(&st(Kind::Master))
        .unwrap_err()
        .contains("not a master"));
    let lean = |kind| NodeStatic {
        diag: false,
        ..st(kind)
    };
    assert!(ulx3s_verilog(&lean(Kind::Sensor))
        .unwrap_err()
        .contains("diagnostic mux"));
    assert!(xem6010_verilog(&lean(Kind::Master))
        .unwrap_err()
        .contains("diagnostic mux"));
}
