//! Clock and data recovery in Verilator: locks to a stream whose bit clock is
//! off by up to ±2000 ppm from the receiver's (two nodes at ±1000 ppm), with
//! random phase and edge jitter of ±1.4 samples (of 8 per bit), and never
//! slips a bit over 10^6 bits; ±2.2 samples of jitter does make it fail (so
//! the first test can fail); every edge interval one line-bit error can
//! leave inside a packet is read whole (8 bit times), a longer one mutes;
//! loss of signal within 32 bit times of a dark line and never on a live one;
//! `o_code` beside each bit is the code the line was NRZI-encoded from.

use merkur_model::line::{nrzi_encode, push_group, CODE_K, CODE_S, DATA_CODES};
use merkur_rtl::{
    emit::verilog::block_verilog,
    line::cdr::{Cdr, LOS_SAMPLES, MUTE_SAMPLES},
};
use merkur_sim::{line_samples, sample_words, verilator::Model, Rng, SAMPLES_PER_BIT};

/// `bits` code bits of random data groups.
fn data_code(rng: &mut Rng, bits: usize) -> Vec<u8> {
    let mut code = vec![];
    while code.len() < bits {
        push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
    }
    code.truncate(bits);
    code
}

/// Line levels of `bits` NRZI bits of random data groups.
fn line_levels(rng: &mut Rng, bits: usize) -> Vec<u8> {
    nrzi_encode(&data_code(rng, bits), &mut 0)
}

struct Run {
    bits: Vec<u8>,
    /// `o_code` beside each bit.
    codes: Vec<u8>,
    los_seen: bool,
}

fn run(m: &mut Model, samples: &[u8]) -> Run {
    let (clk, s, v, b, c, los) = (
        m.port("clock"),
        m.port("i_samples"),
        m.port("o_valid"),
        m.port("o_bit"),
        m.port("o_code"),
        m.port("o_los"),
    );
    let mut bits = vec![];
    let mut codes = vec![];
    let mut los_seen = false;
    for word in sample_words(samples) {
        m.set(s, word);
        m.tick(clk);
        if m.get(v) == 1 {
            bits.push(m.get(b) as u8);
            codes.push(m.get(c) as u8);
        }
        los_seen |= m.get(los) == 1;
    }
    Run {
        bits,
        codes,
        los_seen,
    }
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
    let code = data_code(&mut rng, nbits);
    let levels = nrzi_encode(&code, &mut 0);
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
    if let Some(i) = (0..n).find(|&i| got[i] != sent[i]) {
        return Some(format!(
            "{ctx}: bit {} recovered wrong (slip or error) after {i} good bits",
            off + i
        ));
    }
    // The NRZI decode beside each bit: the code the line was made from
    // (the bit before a compared one was recovered right too).
    let codes = &r.codes[skip..];
    (1..n)
        .find(|&i| codes[i] != code[off + i])
        .map(|i| format!("{ctx}: bit {}'s o_code is {}", off + i, codes[i]))
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

/// The longest run of zero code bits that one NRZI line-bit error (two
/// adjacent code bits inverted, protocol §2) leaves inside a packet: every
/// K, data or S group followed by three data or S groups, every flip after
/// the K (a flip in J K destroys the delimiter: no packet starts).
fn longest_single_error_run() -> usize {
    let inside: Vec<u8> = DATA_CODES.iter().copied().chain([CODE_S]).collect();
    let firsts: Vec<u8> = inside.iter().copied().chain([CODE_K]).collect();
    let mut worst = 0;
    let mut code = Vec::with_capacity(20);
    for &g0 in &firsts {
        for &g1 in &inside {
            for &g2 in &inside {
                for &g3 in &inside {
                    code.clear();
                    for g in [g0, g1, g2, g3] {
                        push_group(&mut code, g);
                    }
                    let from = if g0 == CODE_K { 5 } else { 0 };
                    for i in from..code.len() - 1 {
                        let mut c = code.clone();
                        c[i] ^= 1;
                        c[i + 1] ^= 1;
                        let run = c[from..]
                            .split(|&b| b == 1)
                            .map(<[u8]>::len)
                            .max()
                            .unwrap_or(0);
                        worst = worst.max(run);
                    }
                }
            }
        }
    }
    worst
}

/// Recovered bits of a stream of random data groups with a run of `zeros`
/// zero code bits after every 40 code bits, at `delta_ppm` with jitter.
fn run_with_zero_runs(
    m: &mut Model,
    rng: &mut Rng,
    zeros: usize,
    delta_ppm: f64,
) -> (Vec<u8>, Vec<u8>) {
    let mut code = vec![];
    while code.len() < 4000 {
        for _ in 0..8 {
            push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
        }
        code.push(1);
        code.extend(std::iter::repeat(0).take(zeros));
        code.push(1);
    }
    let mut level = 0;
    let levels = nrzi_encode(&code, &mut level);
    let phase = rng.below(800) as f64 / 100.0;
    let samples = line_samples(&levels, delta_ppm, phase, 1.4, rng);
    (levels, run(m, &samples).bits)
}

#[test]
fn single_error_runs_are_read_whole_longer_ones_mute() {
    let seed = Rng::seed(0xcd7);
    let worst = longest_single_error_run();
    let mute_bits = (MUTE_SAMPLES / SAMPLES_PER_BIT as u64) as usize;
    // A run of z zeros is an edge interval of z + 1 bit times.
    assert!(
        worst < mute_bits,
        "one line-bit error leaves {worst} zero code bits in a packet; the CDR mutes after {mute_bits} bit times"
    );
    let mut m = Model::build(&block_verilog(Cdr::default())).unwrap();
    let mut rng = Rng::new(seed);
    for delta_ppm in [-2000.0, 0.0, 2000.0] {
        // The longest interval that must be read whole: every bit comes.
        let (sent, got) = run_with_zero_runs(&mut m, &mut rng, mute_bits - 1, delta_ppm);
        let Some((off, skip)) = align(&sent, &got) else {
            panic!("seed {seed} (MERKUR_SEED), {delta_ppm} ppm: never locked");
        };
        let n = (got.len() - skip).min(sent.len() - off);
        assert!(
            n + off + 8 >= sent.len() && got[skip..skip + n] == sent[off..off + n],
            "seed {seed} (MERKUR_SEED), {delta_ppm} ppm: a {mute_bits}-bit edge interval was not read whole"
        );
        // One zero more: the line counts as dark and bits are missing.
        let (sent, got) = run_with_zero_runs(&mut m, &mut rng, mute_bits, delta_ppm);
        assert!(
            got.len() + 50 < sent.len(),
            "seed {seed} (MERKUR_SEED), {delta_ppm} ppm: a {}-bit edge interval did not mute ({} of {} bits)",
            mute_bits + 1,
            got.len(),
            sent.len()
        );
    }
}

#[test]
fn loss_of_signal_within_32_bit_times() {
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
            clocks <= 72,
            "seed {seed}: no loss of signal after {clocks} clocks"
        );
    }
    // Protocol §9: 32 bit times = 256 samples = 64 clocks, plus the register stage.
    assert_eq!(
        LOS_SAMPLES,
        32 * SAMPLES_PER_BIT as u64,
        "the block's constant is the spec's"
    );
    assert!(clocks >= 62, "loss of signal too early: {clocks} clocks");
    // The next edge clears it.
    m.set(s, (last ^ 1) * 0b1111);
    m.tick(clk);
    m.tick(clk);
    assert_eq!(m.get(los), 0);
}
