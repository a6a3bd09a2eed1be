//! Simulation speed of one block, side by side in one run: Verilator through
//! our binding, Icarus Verilog (`iverilog` + `vvp`) on the same emitted
//! Verilog, and rust-hdl's own `Simulation` on the same Rust description.
//!
//! Run: `cargo run --release -p merkur-sim --example bench_blocks [CLOCKS]`
//! The block is the fibre monitor (cdr + framer_rx + word_rx, 12-bit slot
//! counter), driven with the line samples of idles and frames.

use merkur_model::line::{nrzi_encode, push_group, CODE_I, CODE_J, CODE_K, DATA_CODES};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, line::monitor::Monitor};
use merkur_sim::verilator::Model;
use rust_hdl::prelude::*;
use std::time::Instant;

fn samples(clocks: usize) -> Vec<u64> {
    // A repeating frame: idles, J K, 50 data groups; 8 samples per bit, 4 per clock.
    let mut code = vec![];
    (0..8).for_each(|_| push_group(&mut code, CODE_I));
    push_group(&mut code, CODE_J);
    push_group(&mut code, CODE_K);
    (0..50).for_each(|i| push_group(&mut code, DATA_CODES[i % 16]));
    let mut level = 0;
    let line = nrzi_encode(&code, &mut level);
    (0..clocks)
        .map(|c| {
            let b = line[(c / 2) % line.len()] as u64;
            b * 0b1111
        })
        .collect()
}

fn verilator(verilog: &str, s: &[u64]) -> f64 {
    let mut m = Model::build(verilog).expect("verilator build");
    let (clk, smp, wv) = (m.port("clock"), m.port("i_samples"), m.port("o_wvalid"));
    m.set(m.port("i_slots_m1"), 99);
    let t = Instant::now();
    let mut words = 0u64;
    for &x in s {
        m.set(smp, x);
        m.tick(clk);
        words += m.get(wv);
    }
    std::hint::black_box(words);
    s.len() as f64 / t.elapsed().as_secs_f64()
}

fn icarus(verilog: &str, s: &[u64]) -> Result<f64, String> {
    let d = std::env::temp_dir().join(format!("merkur-bench-{}", std::process::id()));
    std::fs::create_dir_all(&d).map_err(|e| e.to_string())?;
    let mem: String = s.iter().map(|x| format!("{x:x}\n")).collect();
    std::fs::write(d.join("samples.hex"), mem).map_err(|e| e.to_string())?;
    let tb = format!(
        "module tb; reg clock = 0; reg [3:0] s; reg [3:0] mem [0:{n}]; integer i; integer words = 0;\n\
         wire o_wvalid; top dut(.clock(clock), .i_samples(s), .i_slots_m1(12'd99), .i_address(12'd0), .o_wvalid(o_wvalid));\n\
         initial begin $readmemh(\"samples.hex\", mem); for (i = 0; i < {n}; i = i + 1) begin s = mem[i]; #1 clock = 1; #1 clock = 0; if (o_wvalid) words = words + 1; end $display(\"%0d\", words); $finish; end endmodule\n",
        n = s.len()
    );
    std::fs::write(d.join("tb.v"), tb).map_err(|e| e.to_string())?;
    std::fs::write(d.join("top.v"), verilog).map_err(|e| e.to_string())?;
    let ok = std::process::Command::new("iverilog")
        .args(["-o", "sim.vvp", "tb.v", "top.v"])
        .current_dir(&d)
        .status()
        .map_err(|e| e.to_string())?;
    if !ok.success() {
        return Err("iverilog failed".into());
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

fn rust_hdl_sim(s: &[u64]) -> f64 {
    let n = s.len();
    let data: Vec<u64> = s.to_vec();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Monitor>| x.clock.next = !x.clock.val());
    sim.add_testbench(move |mut sim: Sim<Monitor>| {
        let mut x = sim.init()?;
        x.i_slots_m1.next = 99.into();
        for v in &data {
            x.i_samples.next = (*v).into();
            wait_clock_cycle!(sim, clock, x);
        }
        sim.done(x)
    });
    let mut uut = Monitor::new(WordFormat::Basic);
    uut.connect_all();
    let t = Instant::now();
    sim.run(Box::new(uut), (n as u64 + 4) * 10)
        .expect("rust-hdl simulation");
    n as f64 / t.elapsed().as_secs_f64()
}

fn main() {
    let clocks: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(2_000_000);
    let v = block_verilog(Monitor::new(WordFormat::Basic));
    let s = samples(clocks);
    let vl = verilator(&v, &s);
    let ic = icarus(&v, &s[..clocks.min(200_000)]).unwrap_or_else(|e| {
        eprintln!("icarus: {e}");
        f64::NAN
    });
    let rh = rust_hdl_sim(&s[..clocks.min(5_000)]);
    println!("monitor block, clocks/s (higher is better):");
    println!("  verilator (merkur binding): {vl:>12.0}");
    println!(
        "  icarus (iverilog/vvp):      {ic:>12.0}   verilator/icarus = {:.0}x",
        vl / ic
    );
    println!(
        "  rust-hdl Simulation:        {rh:>12.0}   verilator/rust-hdl = {:.0}x",
        vl / rh
    );
}
