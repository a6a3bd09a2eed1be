//! The cut-through forwarder in Verilator against the model, node by node:
//! the line the model says arrives at a slave (fibre P(k-1), every cycle of a
//! tb-data scenario, at a clock offset with jitter) goes through the
//! forwarder, a monitor decodes what comes out, and that must be what the
//! model says leaves the node (fibre Pk): headers (HOP + 1), the node's own
//! slot (sensor value or actuator Alive, alarms), everything else unchanged,
//! bad words still bad.

use merkur_model::config::{self, Config};
use merkur_model::line::{nrzi_encode, push_group, CODE_I};
use merkur_model::ring::{
    self, rtx_head, sensor_value, Carry, CycleRecord, EventKind, HeaderRx, RtxOnFibre, Slot,
};
use merkur_model::scenario::Kind;
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, line::monitor::Monitor, node::fwd::Fwd};
use merkur_sim::stim::{frame_code, rtx_code, seen, PacketReader, Seen};
use merkur_sim::{line_samples, pair_to_samples, repo_root, sample_words, verilator::Model, Rng};

fn check_node(cfg: &Config, recs: &[CycleRecord], k: usize, ppm: f64, seed: u64) {
    let n = cfg.nodes.len();
    let mut rng = Rng::new(seed ^ k as u64);
    let inp = k - 1; // fibre P(k-1) feeds node k
    let mut code = vec![];
    (0..8).for_each(|_| push_group(&mut code, CODE_I));
    let mut cycles = vec![];
    // Packets expected on Pk: (cycle, what, (header words, slot words)
    // unless the model's Pk was hit itself).
    let mut expect = vec![];
    for r in recs {
        let (Carry::Data(fi), Carry::Data(fo)) = (&r.fibres[inp], &r.fibres[k]) else {
            continue;
        };
        // The model's Pk already carries errors injected on Pk itself: the
        // cycle's packets go through (the node's Alive toggles) unchecked.
        let hit_out = cfg.faults.iter().any(|(c, f)| {
            *c == r.cycle
                && matches!(f, config::Fault::Flip { fibre: config::Fibre::P(x), .. } if *x == k)
        });
        if fi.hdr != fo.hdr && !matches!(fi.hdr, HeaderRx::Ok(_))
            || fi.words.contains(&Slot::Missing)
        {
            continue;
        }
        if !matches!(fi.hdr, HeaderRx::Ok(_)) {
            // A frame the node misses is not fed (this stimulus has no
            // damaged headers). With retransmission the node's Alive then
            // depends on the cycle's RTX (protocol §8: it toggles when it
            // fills a request): the check ends here.
            if cfg.critical.contains(&true) {
                break;
            }
            continue;
        }
        let start = code.len();
        frame_code(&mut code, fi, cfg.slots, cfg.ext, &mut rng);
        cycles.push((r.cycle, start, fo.clone()));
        let want = match fo.hdr {
            HeaderRx::Ok(h) if !hit_out => Some((
                vec![h.h0(cfg.slots).data, h.h1().data],
                fo.words.iter().map(seen).collect::<Vec<Seen>>(),
            )),
            _ => None,
        };
        expect.push((r.cycle, "frame", want));
        // The cycle's retransmission packet (protocol §8), 20 bit times
        // after the frame, as it arrives on P(k-1) and leaves on Pk.
        if let Some((ri, ro)) = rtx_through(r, inp, k) {
            (0..4).for_each(|_| push_group(&mut code, CODE_I));
            rtx_code(&mut code, r.cycle, &ri.words, cfg.ext, &mut rng);
            let head = rtx_head(r.cycle).map(|w| w.data).to_vec();
            let want = (head, ro.words.iter().map(seen).collect());
            expect.push((r.cycle, "retransmission", (!hit_out).then_some(want)));
        }
        (0..4).for_each(|_| push_group(&mut code, CODE_I));
        while code.len() < start + cfg.period as usize || code.len() % 5 != 0 {
            push_group(&mut code, CODE_I);
        }
    }
    let mut level = 0;
    let line = nrzi_encode(&code, &mut level);
    let pairs = sample_words(&line_samples(&line, ppm, 2.1, 0.5, &mut rng));

    let format = if cfg.ext {
        WordFormat::ExtendedAlarm
    } else {
        WordFormat::Basic
    };
    let mut f = Model::build(&block_verilog(Fwd::new(format))).unwrap();
    let mut mi = Model::build(&block_verilog(Monitor::new(format))).unwrap();
    let mut mo = Model::build(&block_verilog(Monitor::new(format))).unwrap();
    let p = |m: &Model, s: &str| m.port(s);
    for m in [&mut mi, &mut mo] {
        let (a, b) = (p(m, "i_slots_m1"), p(m, "i_address"));
        m.set(a, cfg.slots as u64 - 1);
        m.set(b, cfg.nodes[k].address as u64);
    }
    f.set(p(&f, "i_slots_m1"), cfg.slots as u64 - 1);
    f.set(p(&f, "i_address"), cfg.nodes[k].address as u64);
    let actuator = cfg.nodes[k].kind == Kind::Actuator;
    f.set(p(&f, "i_actuator"), actuator as u64);
    let (freq, frsn, fseq) = (
        p(&f, "i_alarm_req"),
        p(&f, "i_alarm_reason"),
        p(&f, "i_alarm_seq"),
    );
    let (fclk, fv, fc, fph, fhb, fsd, fao, fline) = (
        p(&f, "clock"),
        p(&f, "i_bvalid"),
        p(&f, "i_code"),
        p(&f, "i_phase"),
        p(&f, "i_hdr_bad"),
        p(&f, "i_sensor_data"),
        p(&f, "i_act_out"),
        p(&f, "o_line"),
    );
    let (iclk, ismp, ibv, icd, iph, ihb) = (
        p(&mi, "clock"),
        p(&mi, "i_samples"),
        p(&mi, "o_bvalid"),
        p(&mi, "o_code"),
        p(&mi, "o_phase"),
        p(&mi, "o_hdr_bad"),
    );
    let (oclk, osmp) = (p(&mo, "clock"), p(&mo, "i_samples"));
    // The input port's words, as a node wires them to its forwarder (for
    // the retransmission packet's requests; the node is armed).
    f.set(p(&f, "i_armed"), 1);
    let bus: Vec<(usize, usize, bool)> = [
        ("i_wvalid", "o_wvalid", false),
        ("i_wkind", "o_kind", false),
        ("i_wodd", "o_slot", true),
        ("i_wok", "o_ok", false),
        ("i_walarm", "o_alarm", false),
        ("i_wdata", "o_data", false),
        ("i_ptype", "o_ptype", false),
    ]
    .iter()
    .map(|&(a, b, bit0)| (p(&f, a), p(&mi, b), bit0))
    .collect();
    let mut reader = PacketReader::new(&mo);
    let slot = cfg.nodes[k].address;
    let mut ci = 0usize;
    for (clock, &pair) in pairs.iter().enumerate() {
        // Which cycle's frame is on the line now (for the sensor value and
        // the actuator's output register before this cycle).
        while ci + 1 < cycles.len() && clock * 2 / 4 >= cycles[ci + 1].1 {
            ci += 1;
        }
        let c = cycles[ci].0;
        f.set(fsd, sensor_value(cfg, slot, c) as u64);
        let out_before = if c == 0 {
            0
        } else {
            recs[c as usize - 1].nodes[k].output
        };
        f.set(fao, out_before as u64);
        // The node's interrupt logic (not part of this block): the alarm the
        // model says this node sends in this cycle is requested.
        let alarm = recs[c as usize].events.iter().find_map(|e| match e.kind {
            EventKind::AlarmTx { reason, .. } if e.node == k => Some(reason),
            _ => None,
        });
        f.set(freq, alarm.is_some() as u64);
        f.set(frsn, alarm.unwrap_or(0) as u64);
        // Its SEQ (protocol §11: D[11], extended N1 bit 3), as the model's
        // word shows it.
        let seq = match cycles[ci].2.words.get(slot) {
            Some(Slot::Data(d)) if d.alarm && cfg.ext => (d.reason as u16 >> 3) & 1,
            Some(Slot::Data(d)) if d.alarm => (d.data >> 11) & 1,
            _ => 0,
        };
        f.set(fseq, seq as u64);
        mi.set(ismp, pair);
        mi.tick(iclk);
        f.set(fv, mi.get(ibv));
        f.set(fc, mi.get(icd));
        f.set(fph, mi.get(iph));
        f.set(fhb, mi.get(ihb));
        for &(fi, mi_port, bit0) in &bus {
            let v = mi.get(mi_port);
            f.set(fi, if bit0 { v & 1 } else { v });
        }
        f.tick(fclk);
        mo.set(osmp, pair_to_samples(f.get(fline)));
        mo.tick(oclk);
        reader.sample(&mo);
    }
    let got = reader.packets;
    let ctx = format!(
        "node {k} of {n} ({}), {ppm} ppm, seed {seed} (MERKUR_SEED)",
        cfg.nodes[k].kind.name()
    );
    assert_eq!(got.len(), expect.len(), "{ctx}: packets out");
    for ((c, what, want), (hdr, slots)) in expect.iter().zip(&got) {
        let Some((head, want)) = want else {
            continue;
        };
        assert_eq!(hdr, head, "{ctx}: cycle {c}: {what}: header out");
        assert_eq!(slots, want, "{ctx}: cycle {c}: {what}: words out");
    }
}

/// The retransmission packet of cycle `r` as the model has it arriving on
/// fibre `inp` and, forwarded by the node between them, on fibre `out`:
/// when its head arrives intact and complete.
fn rtx_through(r: &CycleRecord, inp: usize, out: usize) -> Option<(&RtxOnFibre, &RtxOnFibre)> {
    let x = r.rtx.as_ref()?;
    let i = x.fibres.windows(2).position(|w| w == [inp, out])?;
    let (ri, ro) = (&x.on[i], &x.on[i + 1]);
    (ri.head_ok && !ri.words.contains(&Slot::Missing)).then_some((ri, ro))
}

fn run(name: &str, nodes: &[usize], ppm: f64) {
    let seed = Rng::seed(0xf3d);
    let text = std::fs::read_to_string(repo_root().join("tb-data").join(name)).unwrap();
    let cfg = config::load(name, &text).unwrap();
    let recs = ring::run(&cfg);
    for &k in nodes {
        check_node(&cfg, &recs, k, ppm, seed);
    }
}

#[test]
fn sensors_and_actuators_forward_like_the_model() {
    run("ring8.toml", &[1, 2, 5, 7], 1000.0);
}

#[test]
fn retransmission_requests_forward_like_the_model() {
    // Sensors 1, 2 and 4 fill their critical slots' requests (a copy hit
    // before the writer is written over); actuator 7 puts its Alive into
    // the copy master 3 filled; the others pass the packet on, marking
    // the words that arrive bad.
    run("ring8_rtx.toml", &[1, 2, 4, 5, 6, 7], -700.0);
}

#[test]
fn bad_words_and_alarms_forward_like_the_model() {
    run("ring8_parity.toml", &[2, 4, 5], -1800.0);
    run("ring8_irq.toml", &[2, 5], 700.0);
}

#[test]
fn extended_alarm_words_forward_like_the_model() {
    // Sensors 2 and 6 and actuator 7 send alarms (the reason nibble, data
    // kept); actuator 5 rewrites its slot; every node adds HOP in the
    // six-group headers.
    run("ring8_ext_alarm.toml", &[1, 2, 5, 6, 7], 900.0);
}
