//! The emitted Verilog is portable: the same file runs under Icarus Verilog
//! and gives, clock for clock, the same outputs as under Verilator — the
//! slave node for the model's frames of tb-data/chain9.toml (node 1), and the
//! whole 8-node ring of tb-data/ring8.toml replayed tick for tick (which also
//! gives the simulators' speed ratio, docs/benchmarks.md).

use merkur_model::config;
use merkur_model::line::{nrzi_encode, push_group, CODE_I};
use merkur_model::ring::{self, sensor_value, Carry};
use merkur_model::scenario::Kind;
use merkur_rtl::harness::ring_top::ring_verilog;
use merkur_rtl::{emit::verilog::block_verilog, node::slave::Slave};
use merkur_sim::ring_sim::{self, Options};
use merkur_sim::stim::frame_code;
use merkur_sim::verilator::{parse_ports, Dir};
use merkur_sim::{line_samples, repo_root, sample_words, verilator::Model, Rng};
use std::process::Command;
use std::time::Instant;

/// Runs `tb.v` (which reads `stim.hex` and writes `out.txt`) with `top.v`
/// under Icarus in a scratch folder; returns `out.txt` and how long `vvp`
/// took.
fn icarus(name: &str, top: &str, tb: &str, stim: &str) -> (String, std::time::Duration) {
    let d = std::env::temp_dir().join(format!("merkur-icarus-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    std::fs::write(d.join("top.v"), top).unwrap();
    std::fs::write(d.join("tb.v"), tb).unwrap();
    std::fs::write(d.join("stim.hex"), stim).unwrap();
    let st = Command::new("iverilog")
        .args(["-o", "sim.vvp", "tb.v", "top.v"])
        .current_dir(&d)
        .output()
        .expect("iverilog runs");
    assert!(
        st.status.success(),
        "iverilog: {}",
        String::from_utf8_lossy(&st.stderr)
    );
    let t0 = Instant::now();
    let st = Command::new("vvp")
        .args(["-n", "sim.vvp"])
        .current_dir(&d)
        .output()
        .expect("vvp runs");
    let took = t0.elapsed();
    assert!(
        st.status.success(),
        "vvp: {}",
        String::from_utf8_lossy(&st.stderr)
    );
    let got = std::fs::read_to_string(d.join("out.txt")).unwrap();
    let _ = std::fs::remove_dir_all(&d);
    (got, took)
}

#[test]
fn ring8_under_icarus_matches_verilator() {
    let seed = Rng::seed(0x1cb);
    let text = std::fs::read_to_string(repo_root().join("tb-data/ring8.toml")).unwrap();
    let cfg = config::load("ring8.toml", &text).unwrap();
    let recs = ring::run(&cfg);
    let opts = Options {
        seed,
        record: true,
        ..Default::default()
    };
    let rep = ring_sim::run(&cfg, &recs, &opts).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    assert!(
        rep.mismatches.is_empty(),
        "seed {seed}: Verilator run passes"
    );
    let rec = rep.recording.expect("recorded");
    let kinds: Vec<Kind> = cfg.nodes.iter().map(|x| x.kind).collect();
    let v = ring_verilog(&kinds, cfg.slots);
    let ports = parse_ports(&v, "merkur_ring").unwrap();
    // Inputs from the packed word (first input in the top bits), outputs
    // written after every tick.
    let mut hi = rec.width;
    let mut conns = vec![];
    let mut decls = vec![];
    let mut outs = vec![];
    for p in &ports {
        match p.dir {
            Dir::In if p.name == "clk" => conns.push(".clk(clk)".to_string()),
            Dir::In => {
                conns.push(format!(".{}(s[{}:{}])", p.name, hi - 1, hi - p.width));
                hi -= p.width;
            }
            Dir::Out => {
                decls.push(format!("wire [{}:0] {};", p.width - 1, p.name));
                conns.push(format!(".{0}({0})", p.name));
                outs.push(p.name.clone());
            }
        }
    }
    assert_eq!(hi, 0, "every input bit connected");
    let n = rec.ticks;
    let tb = format!(
        "module tb; reg clk = 0; reg [{w}:0] mem [0:{last}]; reg [{w}:0] s; integer i, f;\n{decls}\n\
         merkur_ring dut({conns});\n\
         initial begin $readmemh(\"stim.hex\", mem); f = $fopen(\"out.txt\", \"w\");\n\
           for (i = 0; i < {n}; i = i + 1) begin s = mem[i]; clk = 0; #1 clk = 1; #1 $fwrite(f, \"{fmt}\\n\", {outs}); end\n\
           $fclose(f); $finish; end endmodule\n",
        w = rec.width - 1,
        last = n - 1,
        decls = decls.join(" "),
        conns = conns.join(", "),
        fmt = vec!["%0h"; outs.len()].join(" "),
        outs = outs.join(", "),
    );
    let (got, icarus_wall) = icarus("ring", &v, &tb, &rec.stim);
    if let Some(i) = got.lines().zip(rec.out.lines()).position(|(a, b)| a != b) {
        panic!(
            "seed {seed}: Icarus and Verilator differ first at tick {i} (of {n}): {:?} vs {:?}",
            got.lines().nth(i),
            rec.out.lines().nth(i)
        );
    }
    assert_eq!(got.lines().count() as u64, n, "Icarus ran every tick");
    eprintln!(
        "ring8, {n} ticks: Verilator {:.3} s (whole driven run), Icarus {:.2} s (vvp), ratio {:.0}x",
        rep.wall.as_secs_f64(),
        icarus_wall.as_secs_f64(),
        icarus_wall.as_secs_f64() / rep.wall.as_secs_f64()
    );
}

#[test]
fn slave_under_icarus_matches_verilator() {
    let seed = Rng::seed(0x1ca);
    let mut rng = Rng::new(seed);
    let text = std::fs::read_to_string(repo_root().join("tb-data/chain9.toml")).unwrap();
    let cfg = config::load("chain9.toml", &text).unwrap();
    let recs = ring::run(&cfg);
    let mut code = vec![];
    (0..8).for_each(|_| push_group(&mut code, CODE_I));
    for r in recs.iter().take(4) {
        let Carry::Data(f) = &r.fibres[0] else {
            unreachable!()
        };
        let start = code.len();
        frame_code(&mut code, f, cfg.slots, cfg.ext, &mut rng);
        while code.len() < start + cfg.period as usize || code.len() % 5 != 0 {
            push_group(&mut code, CODE_I);
        }
    }
    let line = nrzi_encode(&code, &mut 0);
    let pi = sample_words(&line_samples(&line, 700.0, 1.1, 0.5, &mut rng));
    let idle: Vec<u8> = nrzi_encode(&vec![1u8; code.len()], &mut 0);
    let si = sample_words(&line_samples(&idle, -700.0, 0.4, 0.5, &mut rng));
    let n = pi.len().min(si.len());
    let sensor = sensor_value(&cfg, 1, 2) as u64;

    let v = block_verilog(Slave::default());
    let mut m = Model::build(&v).unwrap();
    let p = |m: &Model, s: &str| m.port(s);
    let cfgp = [
        ("i_address", 1u64),
        ("i_slots_m1", cfg.slots as u64 - 1),
        ("i_actuator", 0),
        ("i_cs_timeout", 4000),
        ("i_sensor_data", sensor),
    ];
    for (name, val) in cfgp {
        let i = p(&m, name);
        m.set(i, val);
    }
    let (clk, ipi, isi, opo, oso) = (
        p(&m, "clock"),
        p(&m, "i_pi"),
        p(&m, "i_si"),
        p(&m, "o_po"),
        p(&m, "o_so"),
    );
    let mut want = String::new();
    for t in 0..n {
        m.set(ipi, pi[t]);
        m.set(isi, si[t]);
        m.tick(clk);
        want += &format!("{}{}\n", m.get(opo), m.get(oso));
    }

    let stim: String = (0..n)
        .map(|t| format!("{:02x}\n", pi[t] | si[t] << 4))
        .collect();
    let tb = format!(
        "module tb; reg clock = 0; reg [3:0] pi = 0, si = 0; wire [1:0] po, so; reg [7:0] mem [0:{n}]; integer i, f;\n\
         wire [15:0] act; wire [1:0] mode; wire fs; wire [15:0] perr, ferr;\n\
         top dut(.clock(clock), .i_pi(pi), .i_si(si), .i_cap_sel(1'b0), .o_po(po), .o_so(so), .i_address(12'd1), .i_slots_m1(12'd{sm1}),\n\
           .i_actuator(1'b0), .i_cs_timeout(16'd4000), .i_sensor_data(16'd{sensor}), .i_irq1(1'b0), .i_irq2(1'b0), .i_fs_req(1'b0),\n\
           .o_act_data(act), .o_mode(mode), .o_failsafe(fs), .o_perr(perr), .o_ferr(ferr));\n\
         initial begin $readmemh(\"stim.hex\", mem); f = $fopen(\"out.txt\", \"w\");\n\
           for (i = 0; i < {n}; i = i + 1) begin pi = mem[i][3:0]; si = mem[i][7:4]; #1 clock = 1; #1 clock = 0; $fwrite(f, \"%0d%0d\\n\", po, so); end\n\
           $fclose(f); $finish; end endmodule\n",
        sm1 = cfg.slots - 1
    );
    let (got, _) = icarus("slave", &v, &tb, &stim);
    if let Some(i) = got.lines().zip(want.lines()).position(|(a, b)| a != b) {
        panic!("seed {seed}: Icarus and Verilator differ first at clock {i} (of {n})");
    }
    assert_eq!(got.lines().count(), n);
    // The comparison is not vacuous: the output line is live (it toggles).
    let po: Vec<u8> = want.lines().map(|l| l.as_bytes()[0]).collect();
    let edges = po.windows(2).filter(|w| w[0] != w[1]).count();
    assert!(
        edges > n / 8,
        "the slave's output toggles ({edges} changes in {n} clocks)"
    );
}
