//! Eight slave nodes in a row (rtl/src/harness/chain8.rs) in Verilator carry the
//! model's frames bit-exactly: the line the model says leaves the special
//! master (fibre P0 of tb-data/chain9.toml, with its injected errors) enters
//! the chain at a clock offset with jitter; what leaves the last slave must be
//! what the model says arrives back at the special master (fibre P8), cycle by
//! cycle, slot by slot: sensor values, actuator Alive bits, HOP, interrupts
//! with alternation, bad words still bad. At the end every actuator's output
//! and every node's parity-error count equal the model's.

use merkur_model::config;
use merkur_model::line::{nrzi_encode, push_group, CODE_I};
use merkur_model::ring::{self, sensor_value, Carry, HeaderRx};
use merkur_model::scenario::Kind;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, harness::chain8::Chain8, line::monitor::Monitor};
use merkur_sim::stim::{frame_code, seen, PacketReader, Seen};
use merkur_sim::{line_samples, pair_to_samples, repo_root, sample_words, verilator::Model, Rng};

#[test]
fn eight_slaves_carry_the_models_frames() {
    let seed = Rng::seed(0xc8a1);
    let name = "chain9.toml";
    let text = std::fs::read_to_string(repo_root().join("tb-data").join(name)).unwrap();
    let cfg = config::load(name, &text).unwrap();
    assert_eq!(cfg.nodes.len(), 9);
    let recs = ring::run(&cfg);
    for ppm in [1000.0, -1000.0] {
        let mut rng = Rng::new(seed ^ (ppm as i64 as u64));
        // The line into the chain: the model's P0, frame by frame, one period apart.
        let mut code = vec![];
        (0..8).for_each(|_| push_group(&mut code, CODE_I));
        let mut starts = vec![];
        for r in &recs {
            let Carry::Data(f) = &r.fibres[0] else {
                panic!("P0 carries the frame")
            };
            let start = code.len();
            starts.push(start);
            frame_code(&mut code, f, cfg.slots, cfg.ext, &mut rng);
            while code.len() < start + cfg.period as usize || code.len() % 5 != 0 {
                push_group(&mut code, CODE_I);
            }
        }
        (0..40).for_each(|_| push_group(&mut code, CODE_I));
        let mut level = 0;
        let line = nrzi_encode(&code, &mut level);
        let pairs = sample_words(&line_samples(&line, ppm, 0.9, 0.5, &mut rng));
        // Idles on the last node's SI (the secondary ring's carrier).
        let mut idle_code = vec![];
        (0..code.len() / 5 + 10).for_each(|_| push_group(&mut idle_code, CODE_I));
        let idle_line = nrzi_encode(&idle_code, &mut 0);
        let idle_pairs = sample_words(&line_samples(&idle_line, -ppm, 2.3, 0.5, &mut rng));

        let mut c8 = Model::build(&block_verilog(Chain8::default())).unwrap();
        let mut mo = Model::build(&block_verilog(Monitor::new(WordFormat::Basic))).unwrap();
        let p = |m: &Model, s: &str| m.port(s);
        c8.set(p(&c8, "i_slots_m1"), cfg.slots as u64 - 1);
        c8.set(p(&c8, "i_cs_timeout"), 4 * 2 * cfg.period as u64);
        let (mos, moa) = (p(&mo, "i_slots_m1"), p(&mo, "i_address"));
        mo.set(mos, cfg.slots as u64 - 1);
        mo.set(moa, 4095);
        let mut sensor_port = vec![];
        let mut irq_port = vec![];
        for k in 0..8 {
            let node = k + 1;
            let (a, act) = (
                p(&c8, &format!("i_address{k}")),
                p(&c8, &format!("i_actuator{k}")),
            );
            c8.set(a, cfg.nodes[node].address as u64);
            c8.set(act, (cfg.nodes[node].kind == Kind::Actuator) as u64);
            sensor_port.push(p(&c8, &format!("i_sensor{k}")));
            irq_port.push(p(&c8, &format!("i_irq1_{k}")));
        }
        let (clk, pi, si, po) = (
            p(&c8, "clock"),
            p(&c8, "i_pi"),
            p(&c8, "i_si"),
            p(&c8, "o_po"),
        );
        let (oclk, osmp) = (p(&mo, "clock"), p(&mo, "i_samples"));
        let mut reader = PacketReader::new(&mo);
        for (t, &pair) in pairs.iter().enumerate() {
            // Node k's inputs belong to the frame that has reached it: the
            // frame enters the chain at `starts[c]` and needs at least 8
            // bit times per node (the slave's latency is 9.5–10.5), so a
            // value is set before the frame reaches the node.
            for k in 0..8 {
                let node = k + 1;
                let here = (t / 2).saturating_sub(8 * (k + 1));
                let c = starts.iter().rposition(|&s| s <= here).unwrap_or(0);
                c8.set(
                    sensor_port[k],
                    sensor_value(&cfg, cfg.nodes[node].address, c as u32) as u64,
                );
                let raise = here == starts[c] + 1
                    && cfg
                        .irqs
                        .iter()
                        .any(|&(ic, n, _)| ic as usize == c && n == node);
                c8.set(irq_port[k], raise as u64);
            }
            c8.set(pi, pair);
            c8.set(si, idle_pairs[t.min(idle_pairs.len() - 1)]);
            c8.tick(clk);
            mo.set(osmp, pair_to_samples(c8.get(po)));
            mo.tick(oclk);
            reader.sample(&mo);
        }
        let got = reader.packets;
        let ctx = format!("{ppm} ppm, seed {seed} (MERKUR_SEED)");
        assert_eq!(got.len(), recs.len(), "{ctx}: frames out of the chain");
        for (r, (hdr, slots)) in recs.iter().zip(&got) {
            let Carry::Data(f) = &r.fibres[8] else {
                panic!("P8 carries the frame")
            };
            let HeaderRx::Ok(h) = f.hdr else { panic!() };
            assert_eq!(
                hdr,
                &vec![h.h0(cfg.slots).data, h.h1().data],
                "{ctx}: cycle {}: header (HOP)",
                r.cycle
            );
            let want: Vec<Seen> = f.words.iter().map(seen).collect();
            assert_eq!(
                slots, &want,
                "{ctx}: cycle {}: slots leaving the chain",
                r.cycle
            );
        }
        let last = recs.last().unwrap();
        for k in 0..8 {
            let node = k + 1;
            let mode = c8.get(p(&c8, &format!("o_mode{k}")));
            assert_eq!(mode, 0, "{ctx}: node {node} stays in mode N");
            assert_eq!(
                c8.get(p(&c8, &format!("o_fs{k}"))),
                0,
                "{ctx}: node {node} not failsafe"
            );
            assert_eq!(
                c8.get(p(&c8, &format!("o_perr{k}"))),
                last.nodes[node].perr as u64,
                "{ctx}: node {node} perr"
            );
            if cfg.nodes[node].kind == Kind::Actuator {
                assert_eq!(
                    c8.get(p(&c8, &format!("o_act{k}"))),
                    last.nodes[node].output as u64,
                    "{ctx}: node {node} output"
                );
            }
        }
    }
}
