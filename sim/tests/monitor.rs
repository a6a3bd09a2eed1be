//! The fibre monitor (cdr + framer_rx + word_rx) in Verilator decodes what
//! the reference model says each fibre carried, cycle by cycle, slot by slot,
//! from a line whose bit clock is off by ±2000 ppm (two nodes at ±1000 ppm)
//! with jitter. The model's fibre contents (tb-data scenarios) are turned
//! into line bits with the model's own encoder; the monitor's words must
//! match the model's decoded slots (good words exactly, VOID, bad and marked
//! words by class), bad headers must be rejected and destroyed delimiters
//! not found.

use merkur_model::config;
use merkur_model::line::{
    mark_code_bits, nrzi_encode, push_group, word_code_bits, Word, CODE_I, CODE_J, CODE_K, CODE_S,
};
use merkur_model::ring::{self, Carry, HeaderRx, Slot};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, line::monitor::Monitor};
use merkur_sim::stim::Seen;
use merkur_sim::{line_samples, repo_root, sample_words, verilator::Model, Rng};

struct Packet {
    hdr: HeaderRx,
    slots: Vec<Seen>,
}

fn encode_packet(
    code: &mut Vec<u8>,
    fr: &ring::Frame,
    slots: usize,
    flips: &mut Vec<usize>,
    rng: &mut Rng,
) -> Option<Packet> {
    if fr.words.contains(&Slot::Missing) {
        return None;
    }
    let jk = code.len();
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    let h = match fr.hdr {
        HeaderRx::Ok(h) => h,
        _ => ring::Header::default(),
    };
    let h0_at = code.len();
    code.extend(word_code_bits(&h.h0(slots), false));
    code.extend(word_code_bits(&h.h1(), false));
    match fr.hdr {
        HeaderRx::NoCs => flips.push(jk + rng.below(10) as usize),
        HeaderRx::Bad => flips.push(h0_at + 3 + rng.below(20) as usize),
        HeaderRx::Ok(_) => {}
    }
    let mut seen = vec![];
    for w in &fr.words {
        let at = code.len();
        match w {
            Slot::Data(d) => {
                code.extend(word_code_bits(d, false));
                seen.push(Seen::Word(d.data, d.alive, d.alarm, d.reason));
            }
            Slot::Void => {
                (0..5).for_each(|_| push_group(code, CODE_S));
                seen.push(Seen::Void);
            }
            Slot::Bad(_) => {
                // The model keeps only "bad"; any single error inside the
                // word's first four groups is one (not in its last group,
                // which an error can turn into the mark T, nor at its last
                // bit, which would also hit the next word).
                code.extend(word_code_bits(
                    &Word {
                        data: rng.next_u64() as u16,
                        ..Word::default()
                    },
                    false,
                ));
                flips.push(at + rng.below(19) as usize);
                seen.push(Seen::Bad);
            }
            Slot::Marked(_) => {
                // A bad word a forwarder marked: its last group T.
                let w = Word {
                    data: rng.next_u64() as u16,
                    ..Word::default()
                };
                code.extend(mark_code_bits(&word_code_bits(&w, false)));
                seen.push(Seen::Marked);
            }
            Slot::Missing => unreachable!(),
        }
    }
    Some(Packet {
        hdr: fr.hdr,
        slots: seen,
    })
}

fn run_scenario(name: &str, delta_ppm: f64) {
    let seed = Rng::seed(0x3017) ^ name.len() as u64;
    let mut rng = Rng::new(seed);
    let text = std::fs::read_to_string(repo_root().join("tb-data").join(name)).unwrap();
    let cfg = config::load(name, &text).unwrap();
    let recs = ring::run(&cfg);
    let mut code = vec![];
    // Idles first: the receiver locks on them before the first packet.
    (0..8).for_each(|_| push_group(&mut code, CODE_I));
    let mut flips = vec![];
    let mut packets = vec![];
    for r in &recs {
        for f in &r.fibres {
            if let Carry::Data(fr) = f {
                let start = code.len();
                if let Some(p) = encode_packet(&mut code, fr, cfg.slots, &mut flips, &mut rng) {
                    packets.push(p);
                }
                while code.len() < start + cfg.period as usize || code.len() % 5 != 0 {
                    push_group(&mut code, CODE_I);
                }
            }
        }
    }
    let mut level = 0;
    let mut line = nrzi_encode(&code, &mut level);
    for &f in &flips {
        line[f] ^= 1;
    }
    let phase = rng.below(800) as f64 / 100.0;
    let samples = line_samples(&line, delta_ppm, phase, 0.6, &mut rng);
    let mut m = Model::build(&block_verilog(Monitor::new(WordFormat::Basic))).unwrap();
    let p = |m: &Model, n: &str| m.port(n);
    let (marked, reason) = (p(&m, "o_marked"), p(&m, "o_reason"));
    let (clk, smp, wv, kind, data, alive, alarm, ok, void, hbad, start) = (
        p(&m, "clock"),
        p(&m, "i_samples"),
        p(&m, "o_wvalid"),
        p(&m, "o_kind"),
        p(&m, "o_data"),
        p(&m, "o_alive"),
        p(&m, "o_alarm"),
        p(&m, "o_ok"),
        p(&m, "o_void"),
        p(&m, "o_hdr_bad"),
        p(&m, "o_start"),
    );
    m.set(p(&m, "i_slots_m1"), cfg.slots as u64 - 1);
    m.set(p(&m, "i_address"), 0);
    let mut got: Vec<(bool, Vec<Seen>)> = vec![];
    for word in sample_words(&samples) {
        m.set(smp, word);
        m.tick(clk);
        if m.get(start) == 1 {
            got.push((false, vec![]));
        }
        if m.get(hbad) == 1 {
            got.last_mut().expect("header after start").0 = true;
        }
        if m.get(wv) == 1 && m.get(kind) == 2 {
            let s = if m.get(ok) == 1 {
                Seen::Word(
                    m.get(data) as u16,
                    m.get(alive) == 1,
                    m.get(alarm) == 1,
                    m.get(reason) as u8,
                )
            } else if m.get(void) == 1 {
                Seen::Void
            } else if m.get(marked) == 1 {
                Seen::Marked
            } else {
                Seen::Bad
            };
            got.last_mut().expect("slot after start").1.push(s);
        }
    }
    let expect: Vec<(bool, Vec<Seen>)> = packets
        .iter()
        .filter(|p| p.hdr != HeaderRx::NoCs)
        .map(|p| match p.hdr {
            HeaderRx::Bad => (true, vec![]),
            _ => (false, p.slots.clone()),
        })
        .collect();
    let ctx = format!("{name} at {delta_ppm} ppm, seed {seed} (MERKUR_SEED)");
    if got.len() != expect.len() {
        let i = got
            .iter()
            .zip(&expect)
            .position(|(g, e)| g != e)
            .unwrap_or(got.len().min(expect.len()));
        panic!(
            "{ctx}: {} packets found, model has {}; first difference at packet {i}: got {:?}, model {:?}",
            got.len(),
            expect.len(),
            got.get(i),
            expect.get(i)
        );
    }
    for (i, (g, e)) in got.iter().zip(&expect).enumerate() {
        assert_eq!(g, e, "{ctx}: packet {i} differs from the model");
    }
}

#[test]
fn monitor_decodes_the_models_fibres_parity_scenario() {
    run_scenario("ring8_parity.toml", 2000.0);
    run_scenario("ring8_parity.toml", -2000.0);
}

#[test]
fn monitor_decodes_the_models_fibres_alarms_and_wraps() {
    run_scenario("ring8_irq.toml", -1500.0);
    run_scenario("demo_8_break.toml", 1000.0);
}
