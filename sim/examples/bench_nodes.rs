//! Simulated clocks per second of the slave node and of a chain of 8 slaves,
//! side by side in one run: Verilator through our binding, Icarus Verilog
//! (`iverilog` + `vvp`, wall time including start-up) on the same emitted
//! Verilog, and rust-hdl's own `Simulation` on the same Rust description.
//!
//! Run: `cargo run --release -p merkur-sim --example bench_nodes`
//! Stimulus: the primary input carries idles and 100-slot frames; every
//! other input is static.

use merkur_model::line::{nrzi_encode, push_group, CODE_I, CODE_J, CODE_K, DATA_CODES};
use merkur_rtl::{emit::verilog::block_verilog, harness::chain8::Chain8, node::slave::Slave};
use merkur_sim::verilator::Model;
use rust_hdl::prelude::*;
use std::time::Instant;

fn stimulus(clocks: usize) -> Vec<u64> {
    let mut code = vec![];
    (0..8).for_each(|_| push_group(&mut code, CODE_I));
    push_group(&mut code, CODE_J);
    push_group(&mut code, CODE_K);
    (0..102 * 5).for_each(|i| push_group(&mut code, DATA_CODES[(i * 7) % 16]));
    let line = nrzi_encode(&code, &mut 0);
    (0..clocks)
        .map(|c| {
            let b = line[(c / 2) % line.len()] as u64;
            b * 0b1111
        })
        .collect()
}

/// (name, value) of the static inputs of each top.
fn statics(chain: bool) -> Vec<(String, u64)> {
    let mut v = vec![
        ("i_slots_m1".to_string(), 99u64),
        ("i_cs_timeout".into(), 60000),
    ];
    if chain {
        for k in 0..8 {
            v.push((format!("i_address{k}"), k as u64 + 1));
        }
    } else {
        v.push(("i_address".into(), 1));
        // The node's own switchbox chooses its inputs.
        v.push(("i_cap_sel".into(), 0));
    }
    v
}

fn verilator(verilog: &str, chain: bool, s: &[u64]) -> f64 {
    let mut m = Model::build(verilog).expect("verilator build");
    for (n, x) in statics(chain) {
        let i = m.port(&n);
        m.set(i, x);
    }
    let (clk, pi, si) = (m.port("clock"), m.port("i_pi"), m.port("i_si"));
    let t = Instant::now();
    for &x in s {
        m.set(pi, x);
        m.set(si, x);
        m.tick(clk);
    }
    s.len() as f64 / t.elapsed().as_secs_f64()
}

fn icarus(verilog: &str, chain: bool, s: &[u64]) -> Result<f64, String> {
    let d = std::env::temp_dir().join(format!("merkur-benchn-{}-{chain}", std::process::id()));
    std::fs::create_dir_all(&d).map_err(|e| e.to_string())?;
    let mem: String = s.iter().map(|x| format!("{x:x}\n")).collect();
    std::fs::write(d.join("s.hex"), mem).map_err(|e| e.to_string())?;
    let conns: Vec<String> = statics(chain)
        .iter()
        .map(|(n, x)| format!(".{n}({x})"))
        .collect();
    let tb = format!(
        "module tb; reg clock = 0; reg [3:0] x; reg [3:0] mem [0:{n}]; integer i;\n\
         top dut(.clock(clock), .i_pi(x), .i_si(x), {c});\n\
         initial begin $readmemh(\"s.hex\", mem); for (i = 0; i < {n}; i = i + 1) begin x = mem[i]; #1 clock = 1; #1 clock = 0; end $finish; end endmodule\n",
        n = s.len(),
        c = conns.join(", ")
    );
    std::fs::write(d.join("tb.v"), tb).map_err(|e| e.to_string())?;
    std::fs::write(d.join("top.v"), verilog).map_err(|e| e.to_string())?;
    let ok = std::process::Command::new("iverilog")
        .args(["-o", "sim.vvp", "tb.v", "top.v"])
        .current_dir(&d)
        .output()
        .map_err(|e| e.to_string())?;
    if !ok.status.success() {
        return Err(String::from_utf8_lossy(&ok.stderr).to_string());
    }
    let t = Instant::now();
    let o = std::process::Command::new("vvp")
        .args(["-n", "sim.vvp"])
        .current_dir(&d)
        .output()
        .map_err(|e| e.to_string())?;
    let dt = t.elapsed().as_secs_f64();
    let _ = std::fs::remove_dir_all(&d);
    if !o.status.success() {
        return Err("vvp failed".into());
    }
    Ok(s.len() as f64 / dt)
}

fn rust_hdl_slave(s: &[u64]) -> f64 {
    let data = s.to_vec();
    let n = s.len();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Slave>| x.clock.next = !x.clock.val());
    sim.add_testbench(move |mut sim: Sim<Slave>| {
        let mut x = sim.init()?;
        x.i_slots_m1.next = 99.into();
        x.i_address.next = 1.into();
        x.i_cs_timeout.next = 60000.into();
        for v in &data {
            x.i_pi.next = (*v).into();
            x.i_si.next = (*v).into();
            wait_clock_cycle!(sim, clock, x);
        }
        sim.done(x)
    });
    let mut uut = Slave::default();
    uut.connect_all();
    let t = Instant::now();
    sim.run(Box::new(uut), (n as u64 + 4) * 10)
        .expect("rust-hdl simulation");
    n as f64 / t.elapsed().as_secs_f64()
}

fn rust_hdl_chain(s: &[u64]) -> f64 {
    let data = s.to_vec();
    let n = s.len();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Chain8>| x.clock.next = !x.clock.val());
    sim.add_testbench(move |mut sim: Sim<Chain8>| {
        let mut x = sim.init()?;
        x.i_slots_m1.next = 99.into();
        x.i_cs_timeout.next = 60000.into();
        for v in &data {
            x.i_pi.next = (*v).into();
            x.i_si.next = (*v).into();
            wait_clock_cycle!(sim, clock, x);
        }
        sim.done(x)
    });
    let mut uut = Chain8::default();
    uut.connect_all();
    let t = Instant::now();
    sim.run(Box::new(uut), (n as u64 + 4) * 10)
        .expect("rust-hdl simulation");
    n as f64 / t.elapsed().as_secs_f64()
}

fn main() {
    let s = stimulus(2_000_000);
    for chain in [false, true] {
        let (name, v) = if chain {
            ("chain of 8 slaves", block_verilog(Chain8::default()))
        } else {
            ("slave node", block_verilog(Slave::default()))
        };
        let vl = verilator(&v, chain, &s[..if chain { 1_000_000 } else { 2_000_000 }]);
        let ic =
            icarus(&v, chain, &s[..if chain { 20_000 } else { 100_000 }]).unwrap_or_else(|e| {
                eprintln!("icarus: {e}");
                f64::NAN
            });
        let rh = if chain {
            rust_hdl_chain(&s[..500])
        } else {
            rust_hdl_slave(&s[..2_000])
        };
        println!("{name}, clocks/s:");
        println!("  verilator (merkur binding): {vl:>12.0}");
        println!(
            "  icarus (iverilog/vvp):      {ic:>12.0}   verilator/icarus   = {:.0}x",
            vl / ic
        );
        println!(
            "  rust-hdl Simulation:        {rh:>12.0}   verilator/rust-hdl = {:.0}x",
            vl / rh
        );
    }
}
