//! Retransmission on demand (protocol §8, issue 23), measured in the
//! reference model: data age of critical and other slots under random
//! single bit errors (and bursts), with and without the retransmission
//! packet, against the same ring without errors; and the bandwidth spent.
//!
//! `cargo run --release -p merkur-model --example rtx_age -- [CYCLES] [SEED]`
//!
//! Rings: tb-data/ring8, ring32 and ring100, with the first tenth of their
//! slots after slot 0 critical (early slots: the packet leaves right after
//! the frame), at the minimum period (room for one request) and at the
//! period with room for a request per critical slot. Bit
//! errors: every line bit of every DATA frame and retransmission packet on
//! every fibre they cross is inverted with probability BER, at most one
//! error per packet per fibre and no word hit twice in a cycle (single
//! errors, as `merkur campaign` injects them); bursts: one run of 25 to 75
//! garbage bits in a DATA frame per cycle with probability BURST.

use merkur_model::config::{self, Config, Fault, Fibre, FlipTarget};
use merkur_model::ring::{self, age_stats, splitmix, Carry, CycleRecord};

/// Uniform draws from the model's seed mixer (counter mode).
struct Draw(u64, u64);

impl Draw {
    fn u64(&mut self) -> u64 {
        self.1 += 1;
        splitmix(self.0 ^ splitmix(self.1))
    }
    fn unit(&mut self) -> f64 {
        (self.u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn below(&mut self, n: u64) -> u64 {
        self.u64() % n.max(1)
    }
}

/// Bit errors and bursts on the fibres the clean run's frames cross.
/// `slots_only`: errors in the DATA frames' slot words only (no header,
/// no start delimiter, no retransmission packet), to separate what the
/// retransmission repairs from what it cannot see.
fn errors(
    cfg: &Config,
    clean: &[CycleRecord],
    ber: f64,
    burst: f64,
    slots_only: bool,
    seed: u64,
) -> Vec<(u32, Fault)> {
    let n = cfg.nodes.len();
    let w = cfg.word_bits() as u64;
    let frame = cfg.frame_bits() as u64;
    let rtx_words = 2 * cfg.rtx_capacity(false) as u64;
    let head = 10 + 2 * w;
    let mut d = Draw(seed, 0);
    let mut v = vec![];
    let p_of = |bits: u64| 1.0 - (1.0 - ber).powi(bits as i32);
    for rec in clean.iter().skip(1) {
        let c = rec.cycle;
        let mut hit: Vec<(bool, u64)> = vec![];
        let data_fibres = rec
            .fibres
            .iter()
            .filter(|x| matches!(x, Carry::Data(_)))
            .count() as f64;
        for (fi, carry) in rec.fibres.iter().enumerate() {
            if !matches!(carry, Carry::Data(_)) {
                continue;
            }
            let fb = Fibre::from_index(fi, n);
            // One flip per word and cycle (`.0`: in the retransmission
            // packet): a second error in a word is a double error.
            let place = |hit: &mut Vec<(bool, u64)>,
                         v: &mut Vec<(u32, Fault)>,
                         word: (bool, u64),
                         target: FlipTarget,
                         bit: u64| {
                if !hit.contains(&word) {
                    hit.push(word);
                    let bit = bit as u32;
                    v.push((
                        c,
                        Fault::Flip {
                            fibre: fb,
                            target,
                            bit,
                        },
                    ));
                }
            };
            let (lo, bits) = if slots_only {
                (head, frame - head)
            } else {
                (0, frame)
            };
            if d.unit() < p_of(bits) {
                let at = lo + d.below(bits);
                let (target, bit, word) = match at {
                    0..=9 => (FlipTarget::Cs, at, 0),
                    a if a < 10 + w => (FlipTarget::H0, a - 10, 1),
                    a if a < head => (FlipTarget::H1, a - 10 - w, 2),
                    a => (
                        FlipTarget::Slot(((a - head) / w) as usize),
                        (a - head) % w,
                        3 + (a - head) / w,
                    ),
                };
                place(&mut hit, &mut v, (false, word), target, bit);
            }
            if !slots_only && rtx_words > 0 && d.unit() < p_of(head + rtx_words * w) {
                let at = d.below(head + rtx_words * w);
                let (target, bit, word) = if at < head {
                    (FlipTarget::RtxHead, at, 0)
                } else {
                    let j = (at - head) / w;
                    (FlipTarget::Rtx(j as usize), (at - head) % w, 1 + j)
                };
                place(&mut hit, &mut v, (true, word), target, bit);
            }
            if burst > 0.0 && d.unit() < burst / data_fibres {
                let len = 25 + d.below(51) as u32;
                let s = d.below(cfg.slots.saturating_sub(3) as u64) as usize;
                v.push((
                    c,
                    Fault::Burst {
                        fibre: fb,
                        target: FlipTarget::Slot(s),
                        bit: d.below(w) as u32,
                        len,
                        pattern: d.below(256) as u8,
                    },
                ));
            }
        }
    }
    v
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let cycles: u32 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(2000);
    let seed: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(23);
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../tb-data");
    println!("| ring | critical slots | room for requests | period with / without (µs) | errors | retransmission | critical: worst / mean age, copies older than error-free | other slots: worst / mean age, older | packets, requests (not fitted) | bits per cycle (% of period) |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for name in ["ring8", "ring32", "ring100"] {
        let path = format!("{root}/{name}.toml");
        let text = std::fs::read_to_string(&path).expect("tb-data ring");
        let mut base = config::load(&path, &text).expect("valid ring");
        base.cycles = cycles;
        base.faults.clear();
        let bare = base.min_period();
        let last = (base.slots / 10).max(1);
        for s in 1..=last {
            base.critical[s] = true;
        }
        // The smallest period with room for one request, and the smallest
        // with room for a request per critical slot (at most
        // `config::RTX_MAX`), by the model's rule.
        let want = last.min(config::RTX_MAX);
        let room_all = base.period_for_requests(want).expect("critical slots");
        let all = if want == last {
            "all".to_string()
        } else {
            format!("{want} (the most)")
        };
        for (room, period) in [("1", base.min_period()), (all.as_str(), room_all)] {
            base.period = period;
            let us = |p: u32| p as f64 / base.line_rate_mbps;
            let clean = ring::run(&base);
            for (label, ber, burst, slots_only) in [
                ("BER 1e-4", 1e-4, 0.0, false),
                ("BER 1e-4 in slot words only", 1e-4, 0.0, true),
                ("BER 1e-5 + bursts 5 %", 1e-5, 0.05, false),
            ] {
                let mut faulty = base.clone();
                faulty.faults = errors(&base, &clean, ber, burst, slots_only, seed);
                for with in [true, false] {
                    let mut cfg = faulty.clone();
                    if !with {
                        cfg.critical.iter_mut().for_each(|x| *x = false);
                    }
                    let recs = ring::run(&cfg);
                    // Slot classes from the critical list of the ring with it.
                    let [crit, other] = age_stats(&faulty, &faulty.critical, &recs, &clean, 3);
                    let rtx: Vec<_> = recs.iter().filter_map(|r| r.rtx.as_ref()).collect();
                    let bits: u64 = rtx.iter().map(|x| x.bits as u64).sum();
                    let reqs: usize = rtx.iter().map(|x| x.slots.len()).sum();
                    let left: usize = rtx.iter().map(|x| x.left).sum();
                    let per = bits as f64 / cycles as f64;
                    println!(
                        "| {name} | 1..={last} | {room} | {:.1} / {:.1} | {label} ({} injected) | {} | {} / {:.3}, {} of {} | {} / {:.3}, {} of {} | {}, {reqs} ({left}) | {per:.1} ({:.2} %) |",
                        us(base.period),
                        us(bare),
                        faulty.faults.len(),
                        if with { "on" } else { "off" },
                        crit.worst,
                        crit.mean(),
                        crit.older,
                        crit.copies,
                        other.worst,
                        other.mean(),
                        other.older,
                        other.copies,
                        rtx.len(),
                        100.0 * per / base.period as f64,
                    );
                }
            }
        }
    }
    println!("\n{cycles} cycles per run, seed {seed}; ages from cycle 3 on, over every master's memory of the slots it does not write and every actuator's output.");
}
