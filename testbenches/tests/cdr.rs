//! Clock and data recovery in Verilator: locks to a stream whose bit clock is
//! off by up to ±2000 ppm from the receiver's (two nodes at ±1000 ppm), with
//! random phase and edge jitter of ±1.4 samples (of 8 per bit), and never
//! slips a bit over 10^6 bits; ±2.2 samples of jitter does make it fail (so
//! the first test can fail); loss of signal within 16 bit times of a dark
//! line and never on a live one.

use merkur_model::line::{nrzi_encode, push_group, DATA_CODES};
use merkur_rtl::{
    cdr::{Cdr, LOS_SAMPLES},
    verilog::block_verilog,
};
use merkur_testbenches::{line_samples, sample_words, verilator::Model, Rng, SAMPLES_PER_BIT};

/// Line levels of `bits` NRZI bits of random data groups.
fn line_levels(rng: &mut Rng, bits: usize) -> Vec<u8> {
    let mut code = vec![];
    while code.len() < bits {
        push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
    }
    code.truncate(bits);
    let mut level = 0;
    nrzi_encode(&code, &mut level)
}

struct Run {
    bits: Vec<u8>,
    los_seen: bool,
}

fn run(m: &mut Model, samples: &[u8]) -> Run {
    let (clk, s, v, b, los) = (
        m.port("clock"),
        m.port("i_samples"),
        m.port("o_valid"),
        m.port("o_bit"),
        m.port("o_los"),
    );
    let mut bits = vec![];
    let mut los_seen = false;
    for word in sample_words(samples) {
        m.set(s, word);
        m.tick(clk);
        if m.get(v) == 1 {
            bits.push(m.get(b) as u8);
        }
        los_seen |= m.get(los) == 1;
    }
    Run { bits, los_seen }
}

/// Finds where `got` (after skipping the first 16 bits) starts in `sent`.
fn align(sent: &[u8], got: &[u8]) -> Option<(usize, usize)> {
    let skip = 16;
    (0..64).find_map(|off| {
        let ok =
            (0..256).all(|i| got.get(skip + i).is_some() && sent.get(off + i) == got.get(skip + i));
        ok.then_some((off, skip))
    })
}

/// The first wrong bit (after locking) of each run, as an error message.
fn first_error(
    m: &mut Model,
    seed: u64,
    delta_ppm: f64,
    nbits: usize,
    jitter: f64,
) -> Option<String> {
    let mut rng = Rng::new(seed ^ (delta_ppm as i64 as u64));
    let levels = line_levels(&mut rng, nbits);
    let phase = rng.below(800) as f64 / 100.0;
    let samples = line_samples(&levels, delta_ppm, phase, jitter, &mut rng);
    let r = run(m, &samples);
    let ctx =
        format!("seed {seed} (MERKUR_SEED), {delta_ppm} ppm, phase {phase}, jitter ±{jitter}");
    if r.los_seen {
        return Some(format!("{ctx}: loss of signal on a live line"));
    }
    let Some((off, skip)) = align(&levels, &r.bits) else {
        return Some(format!("{ctx}: never locked"));
    };
    let got = &r.bits[skip..];
    let sent = &levels[off..];
    let n = got.len().min(sent.len());
    if n + off + skip + 8 < nbits {
        return Some(format!("{ctx}: recovered {} of {nbits} bits", r.bits.len()));
    }
    (0..n).find(|&i| got[i] != sent[i]).map(|i| {
        format!(
            "{ctx}: bit {} recovered wrong (slip or error) after {i} good bits",
            off + i
        )
    })
}

#[test]
fn two_samples_of_jitter_do_fail() {
    let seed = Rng::seed(0xcd6);
    let mut m = Model::build(&block_verilog(Cdr::default())).unwrap();
    assert!(
        first_error(&mut m, seed, 1000.0, 100_000, 2.2).is_some(),
        "seed {seed}: ±2.2 samples of edge jitter should make an interval misread"
    );
}

#[test]
fn locks_and_never_slips_at_2000_ppm_with_jitter() {
    let seed = Rng::seed(0xcd5);
    let mut m = Model::build(&block_verilog(Cdr::default())).unwrap();
    for (delta_ppm, nbits) in [
        (-2000.0, 1_000_000),
        (2000.0, 1_000_000),
        (-1000.0, 200_000),
        (0.0, 200_000),
        (1000.0, 200_000),
    ] {
        if let Some(e) = first_error(&mut m, seed, delta_ppm, nbits, 1.4) {
            panic!("{e}");
        }
    }
}

#[test]
fn loss_of_signal_within_16_bit_times() {
    let seed = Rng::seed(0x105);
    let mut rng = Rng::new(seed);
    let mut m = Model::build(&block_verilog(Cdr::default())).unwrap();
    let levels = line_levels(&mut rng, 2000);
    let mut samples = line_samples(&levels, 0.0, 1.3, 0.2, &mut rng);
    samples.truncate(samples.len() / 4 * 4);
    let r = run(&mut m, &samples);
    assert!(!r.los_seen, "seed {seed}: no loss of signal on a live line");
    // Now the line goes dark (stays at its level).
    let (clk, s, los) = (m.port("clock"), m.port("i_samples"), m.port("o_los"));
    let last = *samples.last().unwrap() as u64;
    let mut clocks = 0;
    while m.get(los) == 0 {
        m.set(s, last * 0b1111);
        m.tick(clk);
        clocks += 1;
        assert!(
            clocks <= 40,
            "seed {seed}: no loss of signal after {clocks} clocks"
        );
    }
    // Protocol §9: 16 bit times = 128 samples = 32 clocks, plus the register stage.
    assert_eq!(
        LOS_SAMPLES,
        16 * SAMPLES_PER_BIT as u64,
        "the block's constant is the spec's"
    );
    assert!(clocks >= 30, "loss of signal too early: {clocks} clocks");
    // The next edge clears it.
    m.set(s, (last ^ 1) * 0b1111);
    m.tick(clk);
    m.tick(clk);
    assert_eq!(m.get(los), 0);
}
