//! The special master's secondary relay in Verilator (protocol §8): in mode
//! N it passes a DATA frame that arrives on SI (a ring wrapped elsewhere)
//! on to SO, and nothing else — not its own SEC coming back, not a TST, not
//! the remains of a TST that a node in mode N cut after its H0. In a
//! healthy ring the secondary fibres form a closed loop through the
//! pass-throughs; a packet the relay let through after a frame went round
//! it for ever (found by the campaign: a repair on a 100-node ring, where
//! such remains made the last node fail safe three laps later). A dark gap
//! right behind a frame does not hold the frame's tail back in the relay
//! (found by the campaign with seed 11: a reintegration's dark time behind
//! the frame cost its last three words).

use merkur_model::line::{nrzi_encode, push_group, word_code_bits, Word, CODE_I, CODE_J, CODE_K};
use merkur_model::ring::{Frame, Header, HeaderRx, Slot};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{
    emit::verilog::block_verilog, line::monitor::Monitor, node::special_master::SpecialMaster,
};
use merkur_sim::stim::{frame_code, seen, tst_code, PacketReader, Seen};
use merkur_sim::{line_samples, pair_to_samples, sample_words, verilator::Model, Rng};

const SLOTS: usize = 4;

fn idle(code: &mut Vec<u8>, groups: usize) {
    (0..groups).for_each(|_| push_group(code, CODE_I));
}

/// J K and two header words, then idles.
fn header_only(code: &mut Vec<u8>, h0: u16, h1: Option<u16>) {
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    for d in std::iter::once(h0).chain(h1) {
        code.extend(word_code_bits(
            &Word {
                data: d,
                ..Word::default()
            },
            false,
        ));
    }
    idle(code, 8);
}

fn data_frame(code: &mut Vec<u8>, cyc: u8, rng: &mut Rng) -> (u16, Vec<Seen>) {
    let f = Frame {
        hdr: HeaderRx::Ok(Header {
            rwc: true,
            cyc,
            hop: 40,
            ..Header::default()
        }),
        hdr_bad: (false, false),
        hdr_marked: false,
        words: (0..SLOTS)
            .map(|s| {
                Slot::Data(Word {
                    data: 0x1111 * (s as u16 + 1) + cyc as u16,
                    alive: s % 2 == 0,
                    ..Word::default()
                })
            })
            .collect(),
    };
    frame_code(code, &f, SLOTS, false, rng);
    idle(code, 8);
    let HeaderRx::Ok(h) = f.hdr else {
        unreachable!()
    };
    (h.h1().data, f.words.iter().map(seen).collect())
}

#[test]
fn the_secondary_relay_passes_frames_only() {
    let seed = Rng::seed(0x5e1a);
    let mut rng = Rng::new(seed);
    // SI: frame, SEC, TST, the remains of a cut TST, frame, the remains
    // again; every packet well apart.
    let mut si = vec![];
    idle(&mut si, 40);
    let mut sent = vec![data_frame(&mut si, 3, &mut rng)];
    header_only(&mut si, 0x4003, Some(!0x4003)); // SEC, CYC 3
    tst_code(&mut si, false, 85, false);
    idle(&mut si, 8);
    header_only(&mut si, 0x9055, None); // TST of node 85 cut after H0
    sent.push(data_frame(&mut si, 4, &mut rng));
    header_only(&mut si, 0x8055, None);
    header_only(&mut si, 0x4004, Some(!0x4004));
    // A frame with a dark gap 10 bit times behind it (an upstream node's
    // switchbox change: 12 dark bit times, §10): it goes on whole, not
    // held in the relay's delay line until the line comes back.
    sent.push(data_frame(&mut si, 5, &mut rng));
    si.truncate(si.len() - 30);
    si.extend([0; 12]);
    idle(&mut si, 60);
    let si = sample_words(&line_samples(
        &nrzi_encode(&si, &mut 0),
        300.0,
        0.7,
        0.4,
        &mut rng,
    ));
    let pi = sample_words(&line_samples(
        &nrzi_encode(&vec![1; si.len() / 2 + 8], &mut 0),
        0.0,
        0.3,
        0.4,
        &mut rng,
    ));

    let mut m = Model::build(&block_verilog(SpecialMaster::default())).unwrap();
    let mut mon = Model::build(&block_verilog(Monitor::new(WordFormat::Basic))).unwrap();
    for (name, v) in [
        ("i_address", 0),
        ("i_slots_m1", SLOTS as u64 - 1),
        ("i_period", 400),
        ("i_cs_timeout", 1600),
    ] {
        let i = m.port(name);
        m.set(i, v);
    }
    let i = mon.port("i_slots_m1");
    mon.set(i, SLOTS as u64 - 1);
    let (clk, ipi, isi, oso, omode) = (
        m.port("clock"),
        m.port("i_pi"),
        m.port("i_si"),
        m.port("o_so"),
        m.port("o_mode"),
    );
    let (mclk, msmp) = (mon.port("clock"), mon.port("i_samples"));
    let mut so = PacketReader::new(&mon);
    for t in 0..si.len().min(pi.len()) {
        m.set(ipi, pi[t]);
        m.set(isi, si[t]);
        m.tick(clk);
        assert_eq!(
            m.get(omode),
            0,
            "seed {seed}: the special master left mode N"
        );
        mon.set(msmp, pair_to_samples(m.get(oso)));
        mon.tick(mclk);
        so.sample(&mon);
    }
    let ctx = format!("seed {seed} (MERKUR_SEED)");
    // Nothing but the two frames on SO, whole (its own SEC generator is
    // off: the ring is not running).
    let got: Vec<(u16, Vec<Seen>)> = so
        .packets
        .iter()
        .map(|(h, w)| (h.get(1).copied().unwrap_or(0xdead), w.clone()))
        .collect();
    assert_eq!(
        got,
        sent,
        "{ctx}: SO carried {:x?}",
        so.packets.iter().map(|p| &p.0).collect::<Vec<_>>()
    );
}

/// The CS timeout (protocol §12 item 4): after a frame has come back (the
/// special master is armed), the special master enters failsafe when no
/// packet other than a TST has come back for `i_cs_timeout` clocks —
/// counted from its last returned header word, so not before
/// `i_cs_timeout` clocks after that word's last bit was on the line and
/// within the receiver's latency after that. The formal proof
/// (rtl/formal/special_master.sv) shows the count is exact for every input;
/// this run shows the timeout's trigger happens (a bounded model check to
/// a returned frame is too deep for the solver).
#[test]
fn the_cs_timeout_fires_on_time() {
    const CS: u64 = 600;
    let seed = Rng::seed(0xc5);
    let mut rng = Rng::new(seed);
    // The first frame arms the special master (it counts only once armed);
    // the second one's header is the last packet back.
    let mut pi = vec![];
    idle(&mut pi, 40);
    data_frame(&mut pi, 1, &mut rng);
    idle(&mut pi, 20);
    let before = pi.len();
    data_frame(&mut pi, 2, &mut rng);
    // J K (10 code bits) and H0 (one word) end here.
    let h0_end_bit = before + 10 + word_code_bits(&Word::default(), false).len();
    idle(&mut pi, 400);
    let samples = |code: &[u8], rng: &mut Rng| {
        sample_words(&line_samples(
            &nrzi_encode(code, &mut 0),
            0.0,
            0.5,
            0.0,
            rng,
        ))
    };
    let pi = samples(&pi, &mut rng);
    let si = samples(&vec![1; pi.len() / 2 + 8], &mut rng);

    let mut m = Model::build(&block_verilog(SpecialMaster::default())).unwrap();
    for (name, v) in [
        ("i_address", 0),
        ("i_slots_m1", SLOTS as u64 - 1),
        ("i_period", 400),
        ("i_cs_timeout", CS),
    ] {
        let i = m.port(name);
        m.set(i, v);
    }
    let (clk, ipi, isi, ofs) = (
        m.port("clock"),
        m.port("i_pi"),
        m.port("i_si"),
        m.port("o_failsafe"),
    );
    let mut fs_at = None;
    for t in 0..pi.len().min(si.len()) {
        m.set(ipi, pi[t]);
        m.set(isi, si[t]);
        m.tick(clk);
        if fs_at.is_none() && m.get(ofs) == 1 {
            fs_at = Some(t as u64);
        }
    }
    // Two clocks per bit time (protocol §16).
    let h0_end = 2 * h0_end_bit as u64;
    let fs_at = fs_at.unwrap_or_else(|| panic!("seed {seed}: no failsafe at all"));
    eprintln!(
        "failsafe {} clocks after the returned H0 ended",
        fs_at - h0_end
    );
    assert!(
        fs_at >= h0_end + CS && fs_at <= h0_end + CS + 16,
        "seed {seed}: failsafe {} clocks after the returned H0 ended, CS timeout {CS}",
        fs_at as i64 - h0_end as i64
    );
}
