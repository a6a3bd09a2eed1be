//! One slave node's fault handling in Verilator (protocol §9–§12): its PI
//! goes dark → it wraps to WU (Table 1 row 2), takes the frame from SI,
//! sends TST on SO and a RECONFIG(WU) alarm in its slot; the partner's TST
//! with ACK and then a DATA frame on PI → it reintegrates (mode N,
//! RECONFIG(N)); with the ring known wrapped (RWC in the headers) a dark PI
//! is a second fault → failsafe, FS set in the headers it forwards and its
//! slot no longer written. Every run drives a second copy of the slave
//! behind a capture register that makes its switchbox's input choice
//! (`i_cap_sel`, `o_cap_si`, as the synthesis tops build it), which must
//! do the same in every clock.

use merkur_model::line::{nrzi_encode, push_group, Word, CODE_I};
use merkur_model::ring::{Frame, Header, HeaderRx, Mode, Slot};
use merkur_rtl::line::word_rx::WordFormat;
use merkur_rtl::{emit::verilog::block_verilog, line::monitor::Monitor, node::slave::Slave};
use merkur_sim::stim::{frame_code, tst_code, PacketReader, Seen};
use merkur_sim::{line_samples, pair_to_samples, sample_words, verilator::Model, Rng};

const SLOTS: usize = 4;
const ADDRESS: u64 = 2;
const PERIOD: usize = 300;

/// What one port carries during one cycle period.
#[derive(Clone, Copy)]
enum Seg {
    Frame { rwc: bool },
    Idle,
    Dark,
    Tst { ack: bool },
}

fn segment(code: &mut Vec<u8>, seg: Seg, cycle: u8, ext: bool, rng: &mut Rng) {
    let start = code.len();
    match seg {
        Seg::Frame { rwc } => {
            let f = Frame {
                hdr: HeaderRx::Ok(Header {
                    rwc,
                    cyc: cycle & 7,
                    hop: 1,
                    ..Header::default()
                }),
                hdr_bad: (false, false),
                hdr_marked: false,
                words: (0..SLOTS)
                    .map(|s| {
                        Slot::Data(Word {
                            data: 0x1000 * s as u16 + cycle as u16,
                            alive: cycle % 2 == 1,
                            ..Word::default()
                        })
                    })
                    .collect(),
            };
            frame_code(code, &f, SLOTS, ext, rng);
        }
        Seg::Tst { ack } => {
            let tst_bits = if ext { 75 } else { 65 };
            while code.len() < start + PERIOD - tst_bits {
                tst_code(code, ack, 3, ext);
            }
        }
        Seg::Idle | Seg::Dark => {}
    }
    let fill = if matches!(seg, Seg::Dark) { 0 } else { 1 };
    while code.len() < start + PERIOD {
        code.push(fill);
    }
}

#[test]
fn wrap_reintegrate_and_failsafe() {
    wrap_reintegrate_and_failsafe_in(WordFormat::Basic, true);
}

/// The slave `merkur synth` builds for a ring without critical slots
/// (without retransmission on demand, protocol §8): the same story.
#[test]
fn wrap_reintegrate_and_failsafe_without_retransmission() {
    wrap_reintegrate_and_failsafe_in(WordFormat::Basic, false);
}

/// The same story with extended-alarm words (protocol §6): six-group words
/// and TSTs, the RECONFIG alarms in the reason nibble with the sensor's
/// value in the data bits.
#[test]
fn wrap_reintegrate_and_failsafe_extended() {
    wrap_reintegrate_and_failsafe_in(WordFormat::ExtendedAlarm, true);
}

/// One slave through wrap, link test, reintegration, a second fault,
/// failsafe and CLR, step by step (about 170 lines: one story, each step's
/// stimulus beside its check).
/// One slave's run through a plan of (PI, SI) segments, one per cycle
/// period, with SI's stream `si_shift` bit times behind PI's: the modes it
/// went through (with the bit time of each change), when it entered
/// failsafe, and the packets its PO and SO carried.
struct Run {
    modes: Vec<(u64, usize)>,
    fs_at: Option<usize>,
    rpo: PacketReader,
    rso: PacketReader,
}

fn run(
    format: WordFormat,
    rtx: bool,
    plan: &[(Seg, Seg)],
    si_shift: usize,
    rng: &mut Rng,
    ctx: &str,
) -> Run {
    let ext = format == WordFormat::ExtendedAlarm;
    let (mut pi_code, mut si_code) = (vec![], vec![]);
    (0..8).for_each(|_| {
        push_group(&mut pi_code, CODE_I);
        push_group(&mut si_code, CODE_I);
    });
    si_code.extend(std::iter::repeat(1).take(si_shift));
    for (c, (pi, si)) in plan.iter().enumerate() {
        segment(&mut pi_code, *pi, c as u8, ext, rng);
        segment(&mut si_code, *si, c as u8, ext, rng);
    }
    let pi = sample_words(&line_samples(
        &nrzi_encode(&pi_code, &mut 0),
        400.0,
        1.3,
        0.4,
        rng,
    ));
    let si = sample_words(&line_samples(
        &nrzi_encode(&si_code, &mut 0),
        -300.0,
        0.6,
        0.4,
        rng,
    ));
    let n = pi.len().min(si.len());

    let mut s = Model::build(&block_verilog(Slave::with_rtx(format, rtx))).unwrap();
    // The same slave behind a capture register that makes its switchbox's
    // input choice (`i_cap_sel`, as every synthesis top and the ring
    // harness build it): it must do the same in every clock.
    let mut s2 = Model::build(&block_verilog(Slave::with_rtx(format, rtx))).unwrap();
    let mut mpo = Model::build(&block_verilog(Monitor::new(format))).unwrap();
    let mut mso = Model::build(&block_verilog(Monitor::new(format))).unwrap();
    let p = |m: &Model, x: &str| m.port(x);
    for (name, v) in [
        ("i_address", ADDRESS),
        ("i_slots_m1", SLOTS as u64 - 1),
        ("i_cs_timeout", 4 * PERIOD as u64 * 2),
        ("i_sensor_data", 0xabcd),
    ] {
        let i = p(&s, name);
        s.set(i, v);
        s2.set(i, v);
    }
    let sel = p(&s2, "i_cap_sel");
    s2.set(sel, 1);
    let cap_si = p(&s2, "o_cap_si");
    // o_cap_si after each clock: the capture register takes it at the
    // next edge, and the node reads the samples in the clock after.
    let mut choice: Vec<u64> = vec![];
    let watch = ["o_po", "o_so", "o_mode", "o_failsafe", "o_perr", "o_ferr"].map(|x| (x, p(&s, x)));
    for m in [&mut mpo, &mut mso] {
        let i = p(m, "i_slots_m1");
        m.set(i, SLOTS as u64 - 1);
    }
    let (clk, ipi, isi, opo, oso, omode, ofs) = (
        p(&s, "clock"),
        p(&s, "i_pi"),
        p(&s, "i_si"),
        p(&s, "o_po"),
        p(&s, "o_so"),
        p(&s, "o_mode"),
        p(&s, "o_failsafe"),
    );
    let (pclk, psmp, sclk, ssmp) = (
        p(&mpo, "clock"),
        p(&mpo, "i_samples"),
        p(&mso, "clock"),
        p(&mso, "i_samples"),
    );
    let mut rpo = PacketReader::new(&mpo);
    let mut rso = PacketReader::new(&mso);
    let mut modes: Vec<(u64, usize)> = vec![];
    let mut fs_at = None;
    for t in 0..n {
        s.set(ipi, pi[t]);
        s.set(isi, si[t]);
        s.tick(clk);
        let si_in = t >= 2 && choice[t - 2] == 1;
        s2.set(ipi, if si_in { si[t] } else { pi[t] });
        s2.set(isi, if si_in { pi[t] } else { si[t] });
        s2.tick(clk);
        choice.push(s2.get(cap_si));
        for (name, w) in watch {
            assert_eq!(
                s.get(w),
                s2.get(w),
                "{ctx}: clock {t}: the slave behind the selecting capture differs in {name}"
            );
        }
        let mode = s.get(omode);
        if modes.last().map(|&(m, _)| m) != Some(mode) {
            modes.push((mode, t / 2));
        }
        if fs_at.is_none() && s.get(ofs) == 1 {
            fs_at = Some(t / 2);
        }
        mpo.set(psmp, pair_to_samples(s.get(opo)));
        mpo.tick(pclk);
        rpo.sample(&mpo);
        mso.set(ssmp, pair_to_samples(s.get(oso)));
        mso.tick(sclk);
        rso.sample(&mso);
    }
    Run {
        modes,
        fs_at,
        rpo,
        rso,
    }
}

/// The cycles whose frame came out whole (every slot a good word) on one
/// of these outputs, in the order they came; a frame's cycle is its slot
/// 0's data ([`segment`]).
fn whole_frames(outs: &[&PacketReader]) -> Vec<u16> {
    let mut v: Vec<u16> = outs
        .iter()
        .flat_map(|r| r.packets.iter())
        .filter(|p| p.1.len() == SLOTS && p.1.iter().all(|w| matches!(w, Seen::Word(..))))
        .filter_map(|p| match p.1[0] {
            Seen::Word(d, ..) => Some(d),
            _ => None,
        })
        .collect();
    v.sort_unstable();
    v
}

/// Unwrapping cuts no frame (protocol §12, "Reintegration"): a WD end
/// unwraps at a frame boundary once its OUTPUT has sent the frame's last
/// bit, so the frame it passed last goes round whole; a WU end waits for
/// the frame that is arriving on INPUT (the one that went the long way
/// round) in the same way, and loses only the one whose header showed it
/// the link is back. Every frame on PI comes out whole on PO or SO, but
/// that one.
#[test]
fn unwrapping_cuts_no_frame() {
    for format in [WordFormat::Basic, WordFormat::ExtendedAlarm] {
        let seed = Rng::seed(0x0c07);
        let mut rng = Rng::new(seed);
        let ctx = format!("{format:?}, seed {seed} (MERKUR_SEED)");
        use Seg::*;
        let (n, wu, wd) = (
            Mode::N.code() as u64,
            Mode::Wu.code() as u64,
            Mode::Wd.code() as u64,
        );
        let healthy = Frame { rwc: false };
        // WD end: SI goes dark in a gap between frames (SI runs 170 bit
        // times behind PI), then carries the partner's ACKed TST for two
        // periods: the node unwraps at the end of a frame it sends on SO.
        let mut plan: Vec<(Seg, Seg)> = vec![];
        plan.extend(std::iter::repeat((healthy, Idle)).take(5));
        plan.extend(std::iter::repeat((healthy, Dark)).take(3));
        plan.extend(std::iter::repeat((healthy, Tst { ack: true })).take(2));
        plan.extend(std::iter::repeat((healthy, Idle)).take(4));
        let r = run(format, true, &plan, 170, &mut rng, &ctx);
        let seq: Vec<u64> = r.modes.iter().map(|&(m, _)| m).collect();
        assert_eq!(seq, vec![n, wd, n], "{ctx}: WD end, modes {:?}", r.modes);
        let all: Vec<u16> = (0..plan.len() as u16).collect();
        assert_eq!(
            whole_frames(&[&r.rpo, &r.rso]),
            all,
            "{ctx}: WD end (unwrapped at bit {}), frames whole on PO or SO",
            r.modes[2].1
        );
        // WU end: PI goes dark, the frames come the long way round on SI
        // (200 bit times behind PI, so that each still arrives when PI's
        // next one starts), PI carries the partner's ACKed TST, then
        // frames again: the node unwraps at the end of the frame arriving
        // on SI (cycle 9), and loses PI's frame of cycle 10.
        let mut plan: Vec<(Seg, Seg)> = vec![];
        plan.extend(std::iter::repeat((healthy, Idle)).take(5));
        plan.extend(std::iter::repeat((Dark, healthy)).take(3));
        plan.extend(std::iter::repeat((Tst { ack: true }, healthy)).take(2));
        plan.extend(std::iter::repeat((healthy, Idle)).take(4));
        let r = run(format, true, &plan, 200, &mut rng, &ctx);
        let seq: Vec<u64> = r.modes.iter().map(|&(m, _)| m).collect();
        assert_eq!(seq, vec![n, wu, n], "{ctx}: WU end, modes {:?}", r.modes);
        let want: Vec<u16> = (0..plan.len() as u16).filter(|&c| c != 10).collect();
        assert_eq!(
            whole_frames(&[&r.rpo, &r.rso]),
            want,
            "{ctx}: WU end (unwrapped at bit {}), frames whole on PO or SO",
            r.modes[2].1
        );
    }
}

fn wrap_reintegrate_and_failsafe_in(format: WordFormat, rtx: bool) {
    let ext = format == WordFormat::ExtendedAlarm;
    let seed = Rng::seed(0x5a7e);
    let mut rng = Rng::new(seed);
    let ctx = format!("{format:?}, seed {seed} (MERKUR_SEED)");
    use Seg::*;
    // (PI, SI) per cycle period.
    let mut plan: Vec<(Seg, Seg)> = vec![];
    plan.extend(std::iter::repeat((Frame { rwc: false }, Idle)).take(5)); // 0..4 healthy
    plan.extend(std::iter::repeat((Dark, Frame { rwc: false })).take(5)); // 5..9 PI broken: frames come back on SI
    plan.extend(std::iter::repeat((Tst { ack: true }, Frame { rwc: false })).take(2)); // 10,11 repaired: partner's TST
    plan.extend(std::iter::repeat((Frame { rwc: false }, Idle)).take(5)); // 12..16 unwrapped
    plan.extend(std::iter::repeat((Frame { rwc: true }, Idle)).take(3)); // 17..19 ring wrapped elsewhere
    plan.extend(std::iter::repeat((Dark, Frame { rwc: true })).take(3)); // 20..22 second fault
    let Run {
        modes,
        fs_at,
        rpo,
        rso,
    } = run(format, rtx, &plan, 0, &mut rng, &ctx);
    let bit = |cycle: usize| 40 + cycle * PERIOD;
    // Mode sequence: N, WU (when PI went dark), N (after the repair), WU
    // again (second fault, with failsafe).
    let seq: Vec<u64> = modes.iter().map(|&(m, _)| m).collect();
    let (n, wu) = (Mode::N.code() as u64, Mode::Wu.code() as u64);
    assert_eq!(seq, vec![n, wu, n, wu], "{ctx}: mode sequence {modes:?}");
    let wrap_at = modes[1].1;
    assert!(
        wrap_at > bit(5) && wrap_at < bit(5) + 40,
        "{ctx}: wrapped {} bit times after PI went dark",
        wrap_at as i64 - bit(5) as i64
    );
    let unwrap_at = modes[2].1;
    assert!(
        unwrap_at >= bit(12) && unwrap_at < bit(12) + 80,
        "{ctx}: reintegrated at bit {unwrap_at}, first DATA on PI at {}",
        bit(12)
    );
    let fs = fs_at.expect("failsafe after the second fault");
    assert!(
        fs > bit(20) && fs < bit(20) + 40,
        "{ctx}: failsafe at bit {fs}"
    );

    // SO: TST packets (type 10) while wrapped, ACK once PI carries the partner's TST.
    let tst: Vec<(u16, u16)> = rso
        .packets
        .iter()
        .filter(|p| p.0.len() == 2 && p.0[0] >> 14 == 2)
        .map(|p| (p.0[0], p.0[1]))
        .collect();
    assert!(tst.len() > 15, "{ctx}: TST packets on SO ({})", tst.len());
    let bad: Vec<_> = tst
        .iter()
        .filter(|&&(h0, h1)| !(h1 == !h0 && h0 & 0xfff == ADDRESS as u16))
        .collect();
    assert!(bad.len() <= 1, "{ctx}: TST format: {bad:x?}");
    assert!(
        tst.iter().any(|&(h0, _)| h0 & 0x1000 == 0) && tst.iter().any(|&(h0, _)| h0 & 0x1000 != 0),
        "{ctx}: ACK 0 then 1"
    );

    // PO: the slave's own slot (2) carries RECONFIG(WU) = 0x5000 (SEQ 0)
    // after the wrap, RECONFIG(N) = 0x4800 (SEQ 1, the next alarm) after
    // the reintegration, and otherwise its sensor value; after failsafe, FS
    // in H0 and the slot left as it came. (Nothing goes round this bench,
    // so no alarm is read back: each is repeated, with its SEQ, every other
    // frame until the next replaces it, protocol §11.) Extended words: the
    // data is the sensor value, the reason nibble {SEQ, reason} 0x5 and 0xc.
    let own: Vec<&Seen> = rpo
        .packets
        .iter()
        .filter(|p| p.1.len() == SLOTS)
        .map(|p| &p.1[2])
        .collect();
    // An alarm as (data, reason nibble) in the format.
    let alarm = |w: u16| {
        if ext {
            (0xabcd, (w >> 12) as u8 & 7 | ((w >> 11) as u8 & 1) << 3)
        } else {
            (w, 0)
        }
    };
    let pos = |w: u16| {
        let (data, rn) = alarm(w);
        own.iter()
            .position(|s| matches!(s, Seen::Word(d, _, true, r) if *d == data && *r == rn))
    };
    let wu = pos(0x5000).unwrap_or_else(|| panic!("{ctx}: RECONFIG(WU) alarm on PO: {own:?}"));
    let n_ = pos(0x4800).unwrap_or_else(|| panic!("{ctx}: RECONFIG(N) alarm on PO: {own:?}"));
    assert!(
        pos(0x4000).is_none() && pos(0x5800).is_none(),
        "{ctx}: SEQ: {own:?}"
    );
    assert!(wu < n_, "{ctx}: WU alarm before N alarm");
    assert!(
        matches!(own[wu + 1], Seen::Word(0xabcd, _, false, _)),
        "{ctx}: alternation: data after the alarm"
    );
    let fs_frames: Vec<_> = rpo
        .packets
        .iter()
        .filter(|p| p.0.first().is_some_and(|h0| h0 & 0x2000 != 0))
        .collect();
    assert!(!fs_frames.is_empty(), "{ctx}: FS set in forwarded headers");
    for f in &fs_frames {
        assert!(
            !matches!(f.1.get(2), Some(Seen::Word(0xabcd, _, _, _))),
            "{ctx}: failsafe node still writes its slot"
        );
    }
}

/// The CS timeout (protocol §12 item 4): an armed slave whose INPUT stays
/// alive but carries no packet after a frame enters failsafe `i_cs_timeout`
/// clocks after that frame's H0 — not before that word's last bit was in
/// and within the receiver's latency after (8 bit times, as the special
/// master's test allows). The formal proof `slave` (rtl/formal/slave.sv)
/// shows the count is exact for every input; this run shows its trigger,
/// which is too deep for a cover (two frames' words).
#[test]
fn the_cs_timeout_fires_on_time() {
    let seed = Rng::seed(0xc5_51);
    let mut rng = Rng::new(seed);
    let ctx = format!("seed {seed}");
    // Two frames (the first arms the node: a good H1), then a live but
    // empty INPUT; BSR idles throughout.
    let mut plan = vec![(Seg::Frame { rwc: false }, Seg::Idle); 2];
    plan.extend([(Seg::Idle, Seg::Idle); 6]);
    let r = run(WordFormat::Basic, true, &plan, 0, &mut rng, &ctx);
    // `run`'s lead-in of 8 idle groups, one period, then J K and H0 of the
    // second frame (bit times; `run` sets i_cs_timeout to 4 periods in
    // clocks, 2 clocks a bit time).
    let h0_end = 8 * 5 + PERIOD + 10 + 25;
    let cs_bits = 4 * PERIOD;
    let fs = r
        .fs_at
        .unwrap_or_else(|| panic!("{ctx}: no failsafe at all"));
    eprintln!("failsafe {} bit times after the last H0", fs - h0_end);
    assert!(
        fs >= h0_end + cs_bits && fs <= h0_end + cs_bits + 8,
        "{ctx}: failsafe {} bit times after the last H0 ended, CS timeout {cs_bits}",
        fs as i64 - h0_end as i64
    );
    assert_eq!(
        r.modes.iter().map(|&(m, _)| m).collect::<Vec<_>>(),
        vec![Mode::N.code() as u64],
        "{ctx}: the node stays in mode N"
    );
}
