//! Waveforms with one switch: MERKUR_WAVE=<file.fst> makes every Verilated
//! model built in the process write an FST (signals named by block instance
//! and port, as rust-hdl names them).

use merkur_rtl::{monitor::Monitor, verilog::block_verilog};
use merkur_testbenches::verilator::Model;

#[test]
fn merkur_wave_writes_an_fst() {
    let path = std::env::temp_dir().join(format!("merkur-wave-{}.fst", std::process::id()));
    // This test binary has this one test, so setting the variable is safe.
    std::env::set_var("MERKUR_WAVE", &path);
    {
        let mut m = Model::build(&block_verilog(Monitor::new(false))).unwrap();
        let (clk, s) = (m.port("clock"), m.port("i_samples"));
        for t in 0..2000u64 {
            m.set(s, if (t / 2) % 2 == 0 { 0b1111 } else { 0 });
            m.tick(clk);
        }
    }
    std::env::remove_var("MERKUR_WAVE");
    let bytes = std::fs::read(&path).expect("FST written");
    let _ = std::fs::remove_file(&path);
    assert!(
        bytes.len() > 1000,
        "FST has content ({} bytes)",
        bytes.len()
    );
    // FST files start with a header block (type 0) whose first fields are the
    // start time; the block type byte is 0.
    assert_eq!(bytes[0], 0, "FST header block");
}
