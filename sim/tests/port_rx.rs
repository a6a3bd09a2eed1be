//! A supervised receive port (monitor + stream controller) in Verilator:
//! no channel failure and no test signal on a healthy DATA stream at
//! ±1500 ppm; channel failure within 32 bit times of a dark line; TST packets
//! give the test signal (and channel failure only where TST means failure),
//! which ends 130 bit times after the last; 8 consecutive bad words are a
//! channel failure, 7 are not, and the failure lasts until a good word or
//! until the input moves to another line.

use merkur_model::line::{nrzi_encode, push_group, word_code_bits, Word, CODE_I, CODE_J, CODE_K};
use merkur_model::ring::Header;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::node::stream_ctl::{BAD_WORDS, TST_HOLD_CLOCKS};
use merkur_rtl::{emit::verilog::block_verilog, node::port_rx::PortRx};
use merkur_sim::stim::tst_code;
use merkur_sim::{line_samples, sample_words, verilator::Model, Rng};

const SLOTS: usize = 16;

fn idles(code: &mut Vec<u8>, n: usize) {
    (0..n).for_each(|_| push_group(code, CODE_I));
}

fn data_frame(code: &mut Vec<u8>, rng: &mut Rng, bad_from: usize, bad_count: usize) -> Vec<usize> {
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    let h = Header {
        hop: 3,
        ..Header::default()
    };
    code.extend(word_code_bits(&h.h0(SLOTS), false));
    code.extend(word_code_bits(&h.h1(), false));
    let mut flips = vec![];
    for s in 0..SLOTS {
        if s >= bad_from && s < bad_from + bad_count {
            flips.push(code.len() + 6);
        }
        code.extend(word_code_bits(
            &Word {
                data: rng.next_u64() as u16,
                alive: s % 2 == 0,
                ..Word::default()
            },
            false,
        ));
    }
    flips
}

struct Probe {
    m: Model,
    clk: usize,
    smp: usize,
    flush: usize,
    cf: usize,
    tst: usize,
    ack: usize,
}

impl Probe {
    fn new(tst_fail: bool) -> Probe {
        let mut m = Model::build(&block_verilog(PortRx::new(WordFormat::Basic))).unwrap();
        m.set(m.port("i_slots_m1"), SLOTS as u64 - 1);
        m.set(m.port("i_tst_fail"), tst_fail as u64);
        let (clk, smp, flush, cf, tst, ack) = (
            m.port("clock"),
            m.port("i_samples"),
            m.port("i_flush"),
            m.port("o_cf"),
            m.port("o_tst"),
            m.port("o_ack"),
        );
        Probe {
            m,
            clk,
            smp,
            flush,
            cf,
            tst,
            ack,
        }
    }
    /// Runs the samples; returns per clock (cf, tst, ack).
    fn run(&mut self, pairs: &[u64]) -> Vec<(bool, bool, bool)> {
        pairs
            .iter()
            .map(|&p| {
                self.m.set(self.smp, p);
                self.m.tick(self.clk);
                (
                    self.m.get(self.cf) == 1,
                    self.m.get(self.tst) == 1,
                    self.m.get(self.ack) == 1,
                )
            })
            .collect()
    }
}

fn to_pairs(code: &[u8], flips: &[usize], ppm: f64, rng: &mut Rng) -> Vec<u64> {
    let mut level = 0;
    let mut line = nrzi_encode(code, &mut level);
    for &f in flips {
        line[f] ^= 1;
    }
    sample_words(&line_samples(&line, ppm, 1.7, 0.6, rng))
}

#[test]
fn healthy_stream_then_dark_line() {
    let seed = Rng::seed(0x9071);
    let mut rng = Rng::new(seed);
    for ppm in [1500.0, -1500.0] {
        let mut code = vec![];
        idles(&mut code, 8);
        for _ in 0..50 {
            data_frame(&mut code, &mut rng, 0, 0);
            idles(&mut code, 6);
        }
        let pairs = to_pairs(&code, &[], ppm, &mut rng);
        let mut p = Probe::new(true);
        let out = p.run(&pairs);
        assert!(
            out.iter().all(|&(cf, tst, _)| !cf && !tst),
            "seed {seed}, {ppm} ppm: failure or test signal on a healthy line"
        );
        // Dark: the line keeps its last level.
        let last = *pairs.last().unwrap() >> 1 & 1;
        let dark = vec![last * 0b1111; 100];
        let out = p.run(&dark);
        let first = out
            .iter()
            .position(|&(cf, _, _)| cf)
            .expect("channel failure on a dark line");
        // 32 bit times = 64 clocks after the last edge (which is up to one bit
        // before the dark part starts), plus two register stages.
        assert!(
            first <= 66,
            "seed {seed}: channel failure only after {first} clocks"
        );
        assert!(
            first >= 58,
            "seed {seed}: channel failure too early ({first} clocks)"
        );
    }
}

#[test]
fn test_signal_and_its_end() {
    let seed = Rng::seed(0x7577);
    let mut rng = Rng::new(seed);
    for (tst_fail, ack) in [(false, true), (true, false)] {
        let mut code = vec![];
        idles(&mut code, 8);
        for _ in 0..20 {
            tst_code(&mut code, ack, 0x123, false);
        }
        let n_tst = code.len();
        idles(&mut code, 80);
        let pairs = to_pairs(&code, &[], 800.0, &mut rng);
        let mut p = Probe::new(tst_fail);
        let out = p.run(&pairs);
        let first = out.iter().position(|&(_, t, _)| t).expect("test signal");
        assert!(
            first < 2 * (40 + 130),
            "seed {seed}: test signal late ({first} clocks)"
        );
        assert_eq!(out[first + 5].2, ack, "ACK bit");
        let cf_any = out.iter().any(|&(cf, _, _)| cf);
        assert_eq!(
            cf_any, tst_fail,
            "seed {seed}: channel failure iff TST counts as failure"
        );
        // The test signal ends 130 bit times after the last TST (± a bit).
        let end_of_tst = n_tst * 2; // clocks (2 per bit)
        let last_on = out.iter().rposition(|&(_, t, _)| t).unwrap();
        let held = last_on as i64 - end_of_tst as i64;
        assert!(
            (250..=275).contains(&held),
            "seed {seed}: test signal held {held} clocks after the last TST"
        );
    }
}

#[test]
fn eight_bad_words_are_a_channel_failure_seven_are_not() {
    // Protocol §9: 8 consecutive bad words; a test signal held 130 bit times.
    assert_eq!(BAD_WORDS, 8, "the block's constant is the spec's");
    assert_eq!(
        TST_HOLD_CLOCKS,
        130 * 2,
        "the block's constant is the spec's"
    );
    let seed = Rng::seed(0xbad8);
    let mut rng = Rng::new(seed);
    for (n, expect) in [(7usize, false), (8, true)] {
        let mut code = vec![];
        idles(&mut code, 8);
        data_frame(&mut code, &mut rng, 0, 0);
        idles(&mut code, 6);
        let flips = data_frame(&mut code, &mut rng, 3, n);
        idles(&mut code, 6);
        data_frame(&mut code, &mut rng, 0, 0);
        idles(&mut code, 6);
        let pairs = to_pairs(&code, &flips, -600.0, &mut rng);
        let mut p = Probe::new(false);
        let out = p.run(&pairs);
        assert_eq!(
            out.iter().any(|&(cf, _, _)| cf),
            expect,
            "seed {seed}: {n} bad words"
        );
        assert!(!out.last().unwrap().0, "the next good word ends it");
    }
}

/// A run of bad words belongs to one line: when the switchbox moves the
/// input to another (`i_flush`), the failure it caused ends and the count
/// restarts; without the move it lasts until the next good word.
#[test]
fn a_move_to_another_line_ends_a_bad_word_failure() {
    let seed = Rng::seed(0xf105);
    let mut rng = Rng::new(seed);
    for moved in [false, true] {
        let mut code = vec![];
        idles(&mut code, 8);
        data_frame(&mut code, &mut rng, 0, 0);
        idles(&mut code, 6);
        // The frame ends in 8 bad words; idles follow.
        let flips = data_frame(&mut code, &mut rng, SLOTS - 8, 8);
        idles(&mut code, 40);
        let pairs = to_pairs(&code, &flips, 400.0, &mut rng);
        let mut p = Probe::new(false);
        let out = p.run(&pairs[..pairs.len() - 120]);
        assert!(
            out.last().unwrap().0,
            "seed {seed}: 8 bad words fail the channel"
        );
        if moved {
            p.m.set(p.flush, 1);
            p.run(&pairs[pairs.len() - 120..pairs.len() - 119]);
            p.m.set(p.flush, 0);
        }
        let rest = p.run(&pairs[pairs.len() - 119..]);
        let failed = rest.iter().skip(2).filter(|&&(cf, _, _)| cf).count();
        assert_eq!(
            failed,
            if moved { 0 } else { rest.len() - 2 },
            "seed {seed}, moved {moved}: clocks of channel failure after the run"
        );
    }
}
