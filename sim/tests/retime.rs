//! Retime buffer in Verilator, behind a CDR: a stream whose bit clock is off
//! by up to ±2000 ppm from the node's, with edge jitter, comes out on the
//! node's own clock bit for bit (no slip), every edge interval of k bits
//! lasts 4k ± 1 output half clocks (at most one correction per interval),
//! and the number of corrections is what the clock offset needs (the buffer
//! follows the rate, it does not hunt); when the input stops the line sends
//! no edge at the underflow and stays dark long enough for a downstream
//! receiver to mute, but not for loss of signal.

use merkur_model::line::{nrzi_decode, nrzi_encode, push_group, DATA_CODES};
use merkur_rtl::{
    emit::verilog::block_verilog,
    line::cdr::{Cdr, LOS_SAMPLES, MUTE_SAMPLES},
    line::retime::{Layout, Retime},
    node::fwd::DEAD_CLOCKS,
};
use merkur_sim::{
    line_samples, sample_words, timed_samples, verilator::Model, Rng, SAMPLES_PER_BIT,
};

/// What one run showed.
struct Out {
    /// Output level per half clock.
    halves: Vec<u8>,
    /// `o_slip` pulses.
    slips: usize,
}

fn run(cdr: &mut Model, rt: &mut Model, samples: &[u8]) -> Out {
    let (cclk, cs, cv, cb, cp) = (
        cdr.port("clock"),
        cdr.port("i_samples"),
        cdr.port("o_valid"),
        cdr.port("o_code"),
        cdr.port("o_phase"),
    );
    let (rclk, rv, rl, rp, rline, rslip) = (
        rt.port("clock"),
        rt.port("i_valid"),
        rt.port("i_code"),
        rt.port("i_phase"),
        rt.port("o_line"),
        rt.port("o_slip"),
    );
    let mut out = Out {
        halves: vec![],
        slips: 0,
    };
    for word in sample_words(samples) {
        cdr.set(cs, word);
        cdr.tick(cclk);
        rt.set(rv, cdr.get(cv));
        rt.set(rl, cdr.get(cb));
        rt.set(rp, cdr.get(cp));
        rt.tick(rclk);
        let pair = rt.get(rline);
        out.halves.push((pair & 1) as u8);
        out.halves.push((pair >> 1) as u8);
        out.slips += rt.get(rslip) as usize;
    }
    out
}

/// Checks one stream; returns the number of corrections seen.
fn check(seed: u64, delta_ppm: f64, nbits: usize, jitter: f64) -> Result<usize, String> {
    let mut rng = Rng::new(seed ^ (delta_ppm as i64 as u64));
    let mut code = vec![];
    while code.len() < nbits {
        push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
    }
    let levels = nrzi_encode(&code, &mut 0);
    let phase = rng.below(800) as f64 / 100.0;
    let samples = line_samples(&levels, delta_ppm, phase, jitter, &mut rng);
    let mut cdr = Model::build(&block_verilog(Cdr::default())).unwrap();
    let mut rt = Model::build(&block_verilog(Retime::default())).unwrap();
    let out = run(&mut cdr, &mut rt, &samples);
    let ctx = format!("seed {seed} (MERKUR_SEED), {delta_ppm} ppm, jitter ±{jitter}");
    if out.slips != 0 {
        return Err(format!("{ctx}: {} slips", out.slips));
    }
    // Runs of equal level between edges, from the first edge to the last.
    let h = &out.halves;
    let edges: Vec<usize> = (1..h.len()).filter(|&i| h[i] != h[i - 1]).collect();
    let mut bits = vec![];
    let mut corrections = 0;
    for w in edges.windows(2) {
        let len = w[1] - w[0];
        let k = (len + 2) / 4;
        if k == 0 || len.abs_diff(4 * k) > 1 {
            return Err(format!(
                "{ctx}: an edge interval of {len} half clocks at half clock {} (not 4k ± 1)",
                w[0]
            ));
        }
        corrections += (len != 4 * k) as usize;
        bits.extend(std::iter::repeat(h[w[0]]).take(k));
    }
    // The code bits out are the code bits in (after the first few): the
    // buffer sends level changes, so its absolute level may be the other.
    let (bits, levels) = (code_of(&bits), code_of(&levels));
    let (off, n) =
        line_up(&bits[16..], &levels, 64, nbits).map_err(|e| format!("{ctx}: output {e}"))?;
    if let Some(i) = (0..n).find(|&i| bits[16 + i] != levels[off + i]) {
        return Err(format!("{ctx}: bit {} out wrong (slip)", off + i));
    }
    Ok(corrections)
}

/// The code bits of NRZI `levels` from the second level on.
fn code_of(levels: &[u8]) -> Vec<u8> {
    levels
        .first()
        .map_or(vec![], |&l0| nrzi_decode(&levels[1..], l0))
}

/// Where `got` (code bits read, the first few skipped by the caller)
/// starts in `sent`: the first offset below `offsets` at which 256 bits
/// agree; and how many bits the two then have in common, at least
/// `nbits` − 64.
fn line_up(
    got: &[u8],
    sent: &[u8],
    offsets: usize,
    nbits: usize,
) -> Result<(usize, usize), String> {
    let off = (0..offsets)
        .find(|&off| (0..256).all(|i| got.get(i) == sent.get(off + i)))
        .ok_or("never matches the input")?;
    let n = got.len().min(sent.len() - off);
    if n + 64 < nbits {
        return Err(format!("has only {n} of {nbits} bits"));
    }
    Ok((off, n))
}

#[test]
fn follows_2000_ppm_on_its_own_clock_without_slips() {
    let seed = Rng::seed(0x7e7);
    let nbits = 200_000;
    for delta_ppm in [-2000.0, -500.0, 0.0, 1000.0, 2000.0] {
        let corrections = check(seed, delta_ppm, nbits, 1.0).unwrap_or_else(|e| panic!("{e}"));
        // Each correction moves the output by 2 receive samples.
        let need = nbits as f64 * SAMPLES_PER_BIT as f64 * delta_ppm.abs() * 1e-6 / 2.0;
        assert!(
            (corrections as f64) >= need * 0.9 - 2.0 && (corrections as f64) <= need * 1.1 + 8.0,
            "seed {seed}: {delta_ppm} ppm: {corrections} corrections, the offset needs {need:.0}"
        );
    }
}

#[test]
fn a_stopped_input_leaves_the_line_dark_then_idles() {
    let seed = Rng::seed(0x7e8);
    let mut rng = Rng::new(seed);
    let spb = SAMPLES_PER_BIT as u64;
    let (mute, los) = (MUTE_SAMPLES / spb, LOS_SAMPLES / spb);
    for round in 0..40 {
        let delta_ppm = [-2000.0, 0.0, 2000.0][round % 3];
        let mut code = vec![];
        for _ in 0..40 + rng.below(40) {
            push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
        }
        let levels = nrzi_encode(&code, &mut 0);
        let phase = rng.below(800) as f64 / 100.0;
        let mut samples = line_samples(&levels, delta_ppm, phase, 1.0, &mut rng);
        // The input dies: its last level for 60 bit times.
        let last = *samples.last().unwrap();
        samples.extend(std::iter::repeat(last).take(60 * SAMPLES_PER_BIT));
        let mut cdr = Model::build(&block_verilog(Cdr::default())).unwrap();
        let mut rt = Model::build(&block_verilog(Retime::default())).unwrap();
        let out = run(&mut cdr, &mut rt, &samples);
        let h = &out.halves;
        let edges: Vec<usize> = (1..h.len()).filter(|&i| h[i] != h[i - 1]).collect();
        // The longest edge-free stretch of the output, in bit times (4 half clocks).
        let (at, gap) = edges
            .windows(2)
            .map(|w| (w[1] - w[0]) as u64)
            .enumerate()
            .max_by_key(|&(_, g)| g)
            .unwrap();
        let ctx = format!("seed {seed} (MERKUR_SEED), round {round}, {delta_ppm} ppm");
        // Dark from the last data edge long enough for the next node's
        // receiver to mute and its forwarder to see a dead input (plus 2
        // bit times of margin): it ends the packet the input stopped in.
        let dead = DEAD_CLOCKS / 2;
        assert!(
            gap >= 4 * (mute + dead + 2),
            "{ctx}: the output was dark for only {gap} half clocks"
        );
        assert!(
            gap + 8 < 4 * los,
            "{ctx}: the output was dark for {gap} half clocks, near loss of signal"
        );
        // Then idles: an edge every bit time to the end.
        assert!(
            edges.len() > at + 40 && edges[at + 1..].windows(2).all(|w| w[1] - w[0] <= 5),
            "{ctx}: no idles after the dark time"
        );
        assert_eq!(out.slips, 1, "{ctx}: one underflow");
    }
}

/// One link behind a retimer: a random data stream at `up_ppm` from node B
/// goes through B's receiver and retimer; B's output (its DDR halves, the
/// short and long bits among them) reaches a receiver C whose sample period
/// makes each of B's halves 2·(1 + `down_ppm`·10⁻⁶) samples, with every
/// half boundary moved by uniform jitter in ±`jitter` samples. Returns how
/// many of the stream's code bits C read wrong (after lining the two up).
fn link(seed: u64, up_ppm: f64, down_ppm: f64, nbits: usize, jitter: f64) -> Result<usize, String> {
    let mut rng = Rng::new(seed ^ (up_ppm as i64 as u64) ^ ((down_ppm as i64 as u64) << 20));
    let mut code = vec![];
    while code.len() < nbits {
        push_group(&mut code, DATA_CODES[rng.below(16) as usize]);
    }
    let levels = nrzi_encode(&code, &mut 0);
    let phase = rng.below(800) as f64 / 100.0;
    let samples = line_samples(&levels, up_ppm, phase, 0.0, &mut rng);
    let mut cdr = Model::build(&block_verilog(Cdr::default())).unwrap();
    let mut rt = Model::build(&block_verilog(Retime::default())).unwrap();
    let out = run(&mut cdr, &mut rt, &samples);
    let ctx = format!("seed {seed} (MERKUR_SEED), {up_ppm}/{down_ppm} ppm, jitter ±{jitter}");
    if out.slips != 0 {
        return Err(format!("{ctx}: the retimer slipped {} times", out.slips));
    }
    let phase = rng.below(200) as f64 / 100.0;
    let at_c = timed_samples(&out.halves, 2.0, down_ppm, phase, jitter, &mut rng);
    let mut c = Model::build(&block_verilog(Cdr::default())).unwrap();
    let (clk, s, v, b) = (
        c.port("clock"),
        c.port("i_samples"),
        c.port("o_valid"),
        c.port("o_bit"),
    );
    let mut got = vec![];
    for word in sample_words(&at_c) {
        c.set(s, word);
        c.tick(clk);
        if c.get(v) == 1 {
            got.push(c.get(b) as u8);
        }
    }
    let (got, sent) = (code_of(&got), code_of(&levels));
    // B sends idles until its buffer runs; skip them, then line up.
    let (off, n) =
        line_up(&got[32..], &sent, 96, nbits).map_err(|e| format!("{ctx}: C's stream {e}"))?;
    Ok((0..n).filter(|&i| got[32 + i] != sent[off + i]).count())
}

/// The link's jitter budget (protocol §9): the retimer's short bit (3 half
/// clocks, 6 samples) leaves one sample before the receiver's limit (5), the
/// long bit two. With the receiver off by ±2000 ppm from the retimer and
/// half a sample of jitter on every edge (under one on an interval), every
/// bit arrives; with 1.2 samples on every edge (up to 2.4 on an interval)
/// bits are lost, so the budget is no wider than protocol §9 says. (The
/// simulated ring top adds at most a quarter of a sample, `ring_top`.)
#[test]
fn a_retimed_stream_crosses_a_link_within_its_jitter_budget() {
    let seed = Rng::seed(0x11c);
    let nbits = 100_000;
    for (up, down) in [(-2000.0, 2000.0), (2000.0, -2000.0), (-1000.0, -1000.0)] {
        let wrong = link(seed, up, down, nbits, 0.45).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            wrong, 0,
            "seed {seed} (MERKUR_SEED): {up}/{down} ppm: {wrong} bits wrong"
        );
    }
    let over = link(seed, -2000.0, 2000.0, nbits, 1.2);
    assert!(
        over.as_ref().map_or(true, |&wrong| wrong > 0),
        "seed {seed} (MERKUR_SEED): 1.2 samples of jitter per edge lost no bit: {over:?}"
    );
}

/// The buffer's two layouts ([`Layout`]: a send shifts, for the FPGAs; a
/// write shifts, for the CoolRunner-II) are one behaviour. Driven with the
/// same seeded random inputs, in stretches that run at the line rate with
/// jitter, too fast (overflow), too slow and stopped (underflow, the dark
/// time, idles), with any receive phase, both give the same line and slips
/// in every clock.
#[test]
fn both_layouts_agree_clock_for_clock() {
    let seed = Rng::seed(0x1a7);
    let mut rng = Rng::new(seed);
    let mut a = Model::build(&block_verilog(Retime::new(Layout::SendShifts))).unwrap();
    let mut b = Model::build(&block_verilog(Retime::new(Layout::WriteShifts))).unwrap();
    let names = ["clock", "i_valid", "i_code", "i_phase", "o_line", "o_slip"];
    let pa: Vec<_> = names.iter().map(|n| a.port(n)).collect();
    let pb: Vec<_> = names.iter().map(|n| b.port(n)).collect();
    let (mut slips, mut edges, mut last) = (0, 0, 0);
    let (mut rate, mut left, mut gap) = (0, 0, 0u64);
    for clock in 0..300_000u64 {
        if left == 0 {
            // A new stretch: a bit every 2 clocks on average, 1 to 3 apart
            // (0), every clock (1: overflow), every 3 (2: underflow), none
            // (3: the input stopped), or at random (4).
            rate = rng.below(5);
            left = 50 + rng.below(1500);
        }
        left -= 1;
        gap += 1;
        let valid = match rate {
            0 => gap >= 3 || (gap == 2 && rng.below(3) < 2) || (gap == 1 && rng.below(4) == 0),
            1 => true,
            2 => gap >= 3,
            3 => false,
            _ => rng.below(2) == 1,
        };
        if valid {
            gap = 0;
        }
        let ins = [u64::from(valid), rng.below(2), rng.below(4)];
        for (m, p) in [(&mut a, &pa), (&mut b, &pb)] {
            for (k, v) in ins.iter().enumerate() {
                m.set(p[k + 1], *v);
            }
            m.tick(p[0]);
        }
        let (la, lb) = (a.get(pa[4]), b.get(pb[4]));
        let (sa, sb) = (a.get(pa[5]), b.get(pb[5]));
        assert!(
            la == lb && sa == sb,
            "seed {seed} (MERKUR_SEED), clock {clock}: SendShifts line {la} slip {sa}, \
             WriteShifts line {lb} slip {sb}"
        );
        slips += sa;
        edges += u64::from(la != last);
        last = la;
    }
    // The stimulus reached what the layouts differ in: a running buffer,
    // its restarts.
    assert!(
        slips > 100 && edges > 10_000,
        "seed {seed}: {slips} slips, {edges} edges"
    );
}
