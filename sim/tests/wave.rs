//! Waveforms with one switch: MERKUR_WAVE=<file.fst> makes every Verilated
//! model built in the process write an FST (signals named by block instance
//! and port, as rust-hdl names them). The FST is read back with an
//! independent reader (the `fst-reader` crate): its scopes and signals are
//! the block's, and the stimulus is in it, value change by value change.

use fst_reader::{FstFilter, FstHierarchyEntry, FstReader, FstSignalValue};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, line::monitor::Monitor};
use merkur_sim::verilator::Model;
use std::collections::HashMap;

/// Every signal of the FST by its full dotted name: (handle, width).
fn signals(r: &mut FstReader<std::io::BufReader<std::fs::File>>) -> HashMap<String, (usize, u32)> {
    let mut scope: Vec<String> = vec![];
    let mut out = HashMap::new();
    r.read_hierarchy(|e| match e {
        FstHierarchyEntry::Scope { name, .. } => scope.push(name),
        FstHierarchyEntry::UpScope => {
            scope.pop();
        }
        FstHierarchyEntry::Var {
            name,
            length,
            handle,
            ..
        } => {
            // Verilator names a vector `name [hi:lo]`; the width is `length`.
            let base = name.split(' ').next().unwrap_or(&name);
            let full = format!("{}.{base}", scope.join("."));
            out.insert(full, (handle.get_index(), length));
        }
        _ => {}
    })
    .expect("the hierarchy reads");
    out
}

#[test]
fn merkur_wave_writes_an_fst() {
    let path = std::env::temp_dir().join(format!("merkur-wave-{}.fst", std::process::id()));
    // This test binary has this one test, so setting the variable is safe.
    std::env::set_var("MERKUR_WAVE", &path);
    // The stimulus: the sample word alternates between 1111 and 0000 every
    // two clocks.
    const CLOCKS: u64 = 2000;
    {
        let mut m = Model::build(&block_verilog(Monitor::new(WordFormat::Basic))).unwrap();
        let (clk, s) = (m.port("clock"), m.port("i_samples"));
        for t in 0..CLOCKS {
            m.set(s, if (t / 2) % 2 == 0 { 0b1111 } else { 0 });
            m.tick(clk);
        }
    }
    std::env::remove_var("MERKUR_WAVE");
    let file = std::fs::File::open(&path).expect("FST written");
    let mut r = FstReader::open(std::io::BufReader::new(file)).expect("a readable FST");
    let sigs = signals(&mut r);
    let _ = std::fs::remove_file(&path);
    let mut names: Vec<&String> = sigs.keys().collect();
    names.sort();
    // The block's ports under the model's top scope (`top`, the block
    // `top` in it), and its child blocks (rtl/src/line/monitor.rs: clock
    // recovery `cdr`, `framer`, word decoder `word` and its 5B/4B decoder
    // `dec`) by instance and port, with their widths.
    for (name, width) in [
        ("top.top.clock", 1),
        ("top.top.i_samples", 4),
        ("top.top.o_los", 1),
        ("top.top.o_data", 16),
        ("top.top.cdr.i_samples", 4),
        ("top.top.cdr.o_los", 1),
        ("top.top.framer.o_start", 1),
        ("top.top.framer.o_group", 5),
        ("top.top.word.o_data", 16),
        ("top.top.word.o_slot", 12),
        ("top.top.word.dec.o_nibble", 4),
    ] {
        let got = sigs.get(name).map(|s| s.1);
        assert_eq!(got, Some(width), "{name} in the FST: {names:?}");
    }
    // The stimulus, read back: i_samples changes every two clocks.
    let (samples, _) = sigs["top.top.i_samples"];
    let mut changes = 0u64;
    let mut values = std::collections::BTreeSet::new();
    r.read_signals(&FstFilter::all(), |_, h, v| {
        if h.get_index() == samples {
            if let FstSignalValue::String(b) = v {
                values.insert(String::from_utf8_lossy(b).into_owned());
                changes += 1;
            }
        }
        Ok::<(), ()>(())
    })
    .expect("the values read");
    let want: std::collections::BTreeSet<String> =
        ["0000", "1111"].iter().map(|s| s.to_string()).collect();
    assert_eq!(values, want, "i_samples' values");
    assert!(
        changes >= CLOCKS / 2 - 2,
        "i_samples changed {changes} times in {CLOCKS} clocks (every two clocks)"
    );
}
