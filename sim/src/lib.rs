//! # merkur-sim
//!
//! - [`verilator`]: our Verilator binding (build at run time, cache by hash,
//!   load, drive ports from Rust, FST waveforms with `MERKUR_WAVE`);
//! - [`jobs`]: the one work queue for jobs run side by side (model
//!   objects, proofs, campaign cases, the block tests' tool runs);
//! - [`stim`]: line stimulus from the model's frames, reading monitors back;
//! - [`timing`]: the timing diagrams of docs/timing/, drawn from RTL runs;
//! - line sampling with clock offsets and jitter ([`line_samples`]), seeded
//!   random numbers ([`Rng`]), the pinned tool list ([`pinned_tools`]).
//!
//! The tests in `tests/` check every RTL block against the reference model.

#![deny(missing_docs)]

pub use merkur_rtl::line::cdr::{SAMPLES_PER_BIT, SAMPLES_PER_CLOCK};
use std::path::PathBuf;

/// One pinned tool from `scripts/tools.lock`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PinnedTool {
    /// Debian package.
    pub package: String,
    /// Exact Debian version.
    pub version: String,
    /// Command the package provides.
    pub command: String,
}

/// Path of the repository root.
pub fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("crate lives in the workspace")
        .to_path_buf()
}

/// Parses `scripts/tools.lock`.
pub fn pinned_tools() -> Result<Vec<PinnedTool>, String> {
    let path = repo_root().join("scripts/tools.lock");
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut out = vec![];
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() != 3 {
            return Err(format!(
                "{}:{}: expected `package version command`, found {line:?}",
                path.display(),
                i + 1
            ));
        }
        out.push(PinnedTool {
            package: f[0].into(),
            version: f[1].into(),
            command: f[2].into(),
        });
    }
    Ok(out)
}

pub mod dcm_sim;
pub mod formal;
pub mod jobs;
pub mod ring_sim;
pub mod stim;
pub mod timing;
pub mod verilator;
pub mod wishbone;

/// A small seeded generator for stimulus (xorshift64*). Tests print the seed
/// on failure; `MERKUR_SEED` overrides the default.
pub struct Rng(u64);

impl Rng {
    /// From a seed (0 is mapped to a fixed non-zero state).
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x9e37_79b9_7f4a_7c15 | 1)
    }
    /// The seed to use: `MERKUR_SEED` if set, else `default`.
    pub fn seed(default: u64) -> u64 {
        std::env::var("MERKUR_SEED")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(default)
    }
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in 0..n (0 for n = 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Line samples of NRZI `levels` sent by a node whose bit period is
/// [`SAMPLES_PER_BIT`]·(1+δ) receiver samples (δ = `delta_ppm`·10⁻⁶), starting at `phase` samples, with
/// every bit boundary moved by uniform jitter in ±`jitter` samples. The
/// first bit is stretched by the phase: lead a stream with idles.
pub fn line_samples(
    levels: &[u8],
    delta_ppm: f64,
    phase: f64,
    jitter: f64,
    rng: &mut Rng,
) -> Vec<u8> {
    timed_samples(
        levels,
        SAMPLES_PER_BIT as f64,
        delta_ppm,
        phase,
        jitter,
        rng,
    )
}

/// [`line_samples`] for `levels` that each last `per_level` receiver
/// samples at 0 ppm: a bit each ([`SAMPLES_PER_BIT`]), or a half clock of a
/// DDR output pair (2).
pub fn timed_samples(
    levels: &[u8],
    per_level: f64,
    delta_ppm: f64,
    phase: f64,
    jitter: f64,
    rng: &mut Rng,
) -> Vec<u8> {
    let period = per_level * (1.0 + delta_ppm * 1e-6);
    let mut out = Vec::with_capacity((levels.len() as f64 * per_level) as usize + 8);
    let mut k = 0usize;
    let mut next = phase + period;
    let mut t = 0.0;
    while k < levels.len() {
        while t >= next && k < levels.len() {
            k += 1;
            let j = (rng.below(1 << 16) as f64 / 65536.0 * 2.0 - 1.0) * jitter;
            next = phase + (k + 1) as f64 * period + j;
        }
        if k < levels.len() {
            out.push(levels[k]);
        }
        t += 1.0;
    }
    out
}

/// Samples grouped per clock as the input port value `i_samples` (bit 0
/// first in time); a last incomplete group is dropped.
pub fn sample_words(samples: &[u8]) -> Vec<u64> {
    samples
        .chunks_exact(SAMPLES_PER_CLOCK)
        .map(|w| w.iter().rev().fold(0u64, |a, &s| a << 1 | s as u64))
        .collect()
}

/// What a receiver on the sender's clock samples from a DDR output pair:
/// each half of the clock is two of its four samples.
pub fn pair_to_samples(pair: u64) -> u64 {
    ((pair & 1) * 0b0011) | ((pair >> 1 & 1) * 0b1100)
}
