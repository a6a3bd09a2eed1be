//! The master's database alone (`merkur_rtl::node::mdb`): its alarm queue
//! (protocol §11) against a naive queue kept here from the stimulus —
//! seeded random received words (headers with their CYC, some of them in
//! failsafe; alarm words with random SEQ, so that about half are repeats
//! (§11: not delivered, but noted in failsafe too); data words; good and
//! bad, in the home slot and others) and host removals at random moments,
//! with the queue run full so that overflow is exercised.
//! (The memories, the Alive check and the host port's refusals are checked
//! in every ring run, `ring.rs`, and in the formal proofs, `formal.rs`.)

use merkur_rtl::emit::verilog::block_verilog;
use merkur_rtl::node::mdb::{
    Mdb, ALQ_CLEAR_OVF, ALQ_POP, ST_RUN, WB_ALQ_CTL, WB_ALQ_HEAD, WB_ALQ_OVF, WB_STATUS,
};
use merkur_sim::wishbone::Wishbone;
use merkur_sim::{verilator::Model, Rng};
use std::collections::VecDeque;

/// Entries the queue keeps (protocol §11).
const DEPTH: usize = 16;

struct Bench {
    m: Model,
    bus: Wishbone,
    clk: usize,
    /// Interrupt pulses seen, per line: IRQ1, IRQ2, FAILSAFE, RECONFIG.
    pulses: [u64; 4],
    lines: [usize; 4],
    alarmq: usize,
}

impl Bench {
    fn new() -> Bench {
        let m = Model::build(&block_verilog(Mdb::default())).unwrap();
        let bus = Wishbone::new(&m);
        let clk = m.port("clock");
        let lines = ["o_irq1", "o_irq2", "o_irq_fs", "o_irq_rc"].map(|p| m.port(p));
        let alarmq = m.port("o_alarmq");
        Bench {
            m,
            bus,
            clk,
            pulses: [0; 4],
            lines,
            alarmq,
        }
    }

    fn tick(&mut self) {
        self.m.tick(self.clk);
        for (i, &l) in self.lines.iter().enumerate() {
            self.pulses[i] += self.m.get(l);
        }
    }

    fn wb(&mut self, adr: u16, write: Option<u16>) -> u16 {
        let (clk, lines) = (self.clk, self.lines);
        let pulses = &mut self.pulses;
        self.bus
            .transfer(
                &mut self.m,
                &mut |m| {
                    m.tick(clk);
                    for (i, &l) in lines.iter().enumerate() {
                        pulses[i] += m.get(l);
                    }
                },
                adr,
                write,
            )
            .unwrap()
            .0
    }

    /// One received word, then a few idle clocks.
    fn word(&mut self, kind: u64, slot: u64, data: u64, alarm: bool, ok: bool) {
        for (p, v) in [
            ("i_wvalid", 1),
            ("i_kind", kind),
            ("i_slot", slot),
            ("i_data", data),
            ("i_alarm", alarm as u64),
            ("i_ok", ok as u64),
        ] {
            let port = self.m.port(p);
            self.m.set(port, v);
        }
        self.tick();
        let v = self.m.port("i_wvalid");
        self.m.set(v, 0);
        for _ in 0..4 {
            self.tick();
        }
    }
}

/// An entry as the host reads it: `{reason, slot}` and CYC.
type Entry = (u16, u16);

#[test]
fn the_alarm_queue_keeps_sixteen_in_order_counts_the_rest_and_drains() {
    let seed = Rng::seed(0xa1a);
    let mut rng = Rng::new(seed);
    let mut b = Bench::new();
    let home = 1 + rng.below(30);
    let home_port = b.m.port("i_home");
    b.m.set(home_port, home);
    // The host starts it (the repeat filter works from then on, §11).
    b.wb(WB_STATUS, Some(ST_RUN));
    let mut want: VecDeque<Entry> = VecDeque::new();
    let mut overflow = 0u64;
    let mut pulses = [0u64; 4];
    let mut cyc = 0u64;
    // The naive repeat filter: per slot the last SEQ read (1 at reset), and
    // whether the frame is read in failsafe (nothing delivered).
    let mut last_seq = [true; 32];
    let mut fs = false;
    let fs_port = b.m.port("i_fs");
    let mut repeats = 0;
    for step in 0..3000 {
        let ctx = format!("seed {seed}, step {step}");
        match rng.below(10) {
            // A header: the CYC of the words that follow.
            0 => {
                cyc = rng.below(8);
                fs = rng.below(6) == 0;
                b.m.set(fs_port, fs as u64);
                b.word(1, 0, cyc << 12, false, true);
            }
            // A host removal (rarer early on, so the queue fills).
            1 if step > 1500 || rng.below(4) == 0 => {
                let ctl = b.wb(WB_ALQ_CTL, None);
                assert_eq!(ctl as usize & 0x1f, want.len(), "{ctx}: entries");
                assert_eq!(b.m.get(b.alarmq) == 1, !want.is_empty(), "{ctx}: o_alarmq");
                let head = b.wb(WB_ALQ_HEAD, None);
                match want.pop_front() {
                    Some((w, c)) => {
                        assert_eq!((head, ctl >> 12 & 7), (w, c), "{ctx}: oldest entry");
                    }
                    None => assert_eq!(head, 0, "{ctx}: an empty queue reads 0"),
                }
                b.wb(WB_ALQ_CTL, Some(ALQ_POP));
            }
            // A slot word: data or an alarm, good or bad, sometimes in the
            // home slot (never delivered).
            _ => {
                let slot = if rng.below(8) == 0 {
                    home
                } else {
                    rng.below(32)
                };
                let alarm = rng.below(2) == 0;
                let ok = rng.below(10) != 0;
                let reason = 1 + rng.below(6);
                let seq = rng.below(2) == 1;
                let data = if alarm {
                    reason << 12 | (seq as u64) << 11
                } else {
                    rng.below(1 << 16)
                };
                b.word(2, slot, data, alarm, ok);
                let mut new = reason == 3;
                if alarm && ok && slot != home && reason != 3 {
                    new = seq != last_seq[slot as usize];
                    last_seq[slot as usize] = seq;
                    repeats += !new as u32;
                }
                if alarm && ok && slot != home && new && !fs {
                    let line = match reason {
                        1 => 0,
                        2 => 1,
                        3 => 2,
                        _ => 3,
                    };
                    pulses[line] += 1;
                    if want.len() < DEPTH {
                        want.push_back(((reason << 12 | slot) as u16, cyc as u16));
                    } else {
                        overflow += 1;
                    }
                }
            }
        }
    }
    assert!(overflow > 0, "seed {seed}: the queue never filled");
    assert!(repeats > 100, "seed {seed}: only {repeats} repeats");
    assert_eq!(b.pulses, pulses, "seed {seed}: interrupt pulses per line");
    assert_eq!(
        b.wb(WB_ALQ_OVF, None) as u64,
        overflow,
        "seed {seed}: overflow"
    );
    b.wb(WB_ALQ_CTL, Some(ALQ_CLEAR_OVF));
    assert_eq!(b.wb(WB_ALQ_OVF, None), 0, "seed {seed}: overflow cleared");
    // Drained to the end as a host does it.
    while let Some((w, c)) = want.pop_front() {
        let ctl = b.wb(WB_ALQ_CTL, None);
        assert_eq!(ctl as usize & 0x1f, want.len() + 1, "seed {seed}: entries");
        assert_eq!(b.wb(WB_ALQ_HEAD, None), w, "seed {seed}: oldest entry");
        assert_eq!(ctl >> 12 & 7, c, "seed {seed}: its CYC");
        b.wb(WB_ALQ_CTL, Some(ALQ_POP));
    }
    assert_eq!(b.wb(WB_ALQ_CTL, None), 0, "seed {seed}: empty");
    assert_eq!(b.m.get(b.alarmq), 0, "seed {seed}: o_alarmq low when empty");
}

#[test]
fn a_full_queue_takes_an_alarm_in_the_clock_an_entry_is_removed() {
    // Fill it, then let a removal and a delivery meet in one clock: the
    // new alarm is kept (none is counted lost) and becomes the newest.
    let mut b = Bench::new();
    let home_port = b.m.port("i_home");
    b.m.set(home_port, 31);
    b.word(1, 0, 5 << 12, false, true);
    for s in 0..DEPTH as u64 {
        b.word(2, s, 1 << 12, true, true);
    }
    assert_eq!(b.wb(WB_ALQ_CTL, None) & 0x1f, DEPTH as u16);
    // The word is read in one clock, delivered in the next (stage 2) and
    // queued in the one after; the removal takes effect in the clock after
    // the one its strobe is seen in.
    for (p, v) in [
        ("i_wvalid", 1),
        ("i_kind", 2),
        ("i_slot", 20),
        ("i_data", 2 << 12),
        ("i_alarm", 1),
        ("i_ok", 1),
    ] {
        let port = b.m.port(p);
        b.m.set(port, v);
    }
    b.tick();
    let v = b.m.port("i_wvalid");
    b.m.set(v, 0);
    let ports = ["i_wb_cyc", "i_wb_stb", "i_wb_we", "i_wb_adr", "i_wb_dat"].map(|p| b.m.port(p));
    for (&p, v) in ports
        .iter()
        .zip([1, 1, 1, WB_ALQ_CTL as u64, ALQ_POP as u64])
    {
        b.m.set(p, v);
    }
    b.tick();
    assert_eq!(
        b.m.get(b.m.port("o_wb_ack")),
        1,
        "the removal is acknowledged"
    );
    for &p in &ports[..3] {
        b.m.set(p, 0);
    }
    for _ in 0..4 {
        b.tick();
    }
    assert_eq!(b.wb(WB_ALQ_OVF, None), 0, "no alarm lost");
    assert_eq!(b.wb(WB_ALQ_CTL, None) & 0x1f, DEPTH as u16, "still full");
    let mut out = vec![];
    for _ in 0..DEPTH {
        out.push(b.wb(WB_ALQ_HEAD, None));
        b.wb(WB_ALQ_CTL, Some(ALQ_POP));
    }
    let mut expect: Vec<u16> = (1..DEPTH as u16).map(|s| 1 << 12 | s).collect();
    expect.push(2 << 12 | 20);
    assert_eq!(out, expect, "oldest first, the new alarm last");
}

/// A restarted master (protocol §12) against a naive model kept here: the
/// host loads the configuration (LOCAL home slot 3 and slot 9, ACT slot 7;
/// LAST reads back for slot S − 1 only, §7)
/// and starts it with JOIN or, in about a third of the seeds' runs, with
/// bit 0 (a power-up: every slot has a value). Seeded random received
/// words (good and bad headers, some in failsafe; good, bad and alarm data
/// words in the own slots and others) and host writes (own slots, and
/// others, which are refused); after each step the send side's look-up of
/// a random slot (`o_tx_cfg`: what the node writes there, nothing in the
/// reload frame), and now and then the data memory as the host reads it.
#[test]
fn a_joined_master_reads_a_reload_frame_and_writes_an_own_slot_only_with_a_value() {
    const SLOTS: usize = 12;
    const HOME: usize = 3;
    let own = |s: usize| [3usize, 7, 9].contains(&s);
    let seed = Rng::seed(0x701e);
    let mut rng = Rng::new(seed);
    for run in 0..6 {
        let mut b = Bench::new();
        let home_port = b.m.port("i_home");
        b.m.set(home_port, HOME as u64);
        let m1 = b.m.port("i_slots_m1");
        b.m.set(m1, SLOTS as u64 - 1);
        // LAST is not stored (protocol §7): it reads 1 for slot S − 1 only.
        for (s, cfg) in [(3u16, 9u16), (9, 8), (7, 2)] {
            b.wb(merkur_rtl::node::mdb::WB_CFG + s, Some(cfg));
        }
        let cfg_of = |b: &mut Bench, s: u16| b.wb(merkur_rtl::node::mdb::WB_CFG + s, None);
        assert_eq!(
            cfg_of(&mut b, 3),
            8,
            "seed {seed}, run {run}: LAST written, not S - 1"
        );
        assert_eq!(
            cfg_of(&mut b, SLOTS as u16 - 1),
            1,
            "seed {seed}, run {run}: LAST of S - 1"
        );
        let join = rng.below(3) != 0;
        let start = if join {
            merkur_rtl::node::mdb::ST_JOIN
        } else {
            ST_RUN
        };
        b.wb(WB_STATUS, Some(start));
        // The naive model.
        let mut rl = if join { 1 } else { 0 };
        let mut hv = [false; SLOTS];
        let mut db = [0u16; SLOTS];
        let mut fs_frame = false;
        let fs_port = b.m.port("i_fs");
        let tx_port = b.m.port("i_tx_slot");
        let cfg_port = b.m.port("o_tx_cfg");
        let status = b.wb(WB_STATUS, None);
        assert_eq!(
            status >> 8 & 1 == 1,
            join,
            "seed {seed}, run {run}: status bit 8 (JOIN)"
        );
        for step in 0..600 {
            let ctx = format!("seed {seed}, run {run} (join {join}), step {step}");
            match rng.below(8) {
                // A header, good or bad, in failsafe now and then.
                0 => {
                    let fs = rng.below(5) == 0;
                    let ok = rng.below(6) != 0;
                    b.m.set(fs_port, fs as u64);
                    b.word(1, 0, rng.below(8) << 12, false, ok);
                    if ok {
                        fs_frame = fs;
                        if !fs {
                            rl = match rl {
                                1 => 2,
                                _ => 0,
                            };
                        }
                    }
                }
                // A host write: an own slot takes it and has a value.
                1 => {
                    let s = rng.below(SLOTS as u64) as usize;
                    let d = rng.below(1 << 16) as u16;
                    b.wb(s as u16, Some(d));
                    if own(s) {
                        db[s] = d;
                        hv[s] = true;
                    }
                }
                // A received data word: good, bad or an alarm.
                _ => {
                    let s = if rng.below(2) == 0 {
                        [3usize, 7, 9][rng.below(3) as usize]
                    } else {
                        rng.below(SLOTS as u64) as usize
                    };
                    let d = rng.below(1 << 16) as u16;
                    let ok = rng.below(5) != 0;
                    let alarm = rng.below(6) == 0;
                    b.word(2, s as u64, d as u64, alarm, ok);
                    if ok && !alarm && !fs_frame && (!own(s) || (join && !hv[s])) {
                        db[s] = d;
                        hv[s] |= own(s);
                    }
                }
            }
            let s = rng.below(SLOTS as u64) as usize;
            b.m.set(tx_port, s as u64);
            for _ in 0..4 {
                b.tick();
            }
            // The naive model's decision: LOCAL slots 3 (home) and 9, ACT
            // slot 7; nothing in the reload frame; an own slot only with a
            // value, the home slot without one only an alarm (protocol §12).
            let value = !join || hv[s];
            let want = match s {
                _ if rl != 0 => 0,
                3 | 9 if value => 1,
                HOME => 3,
                7 if value => 2,
                _ => 0,
            };
            assert_eq!(b.m.get(cfg_port), want, "{ctx}: o_tx_cfg of slot {s}");
            if rng.below(10) == 0 {
                let s = rng.below(SLOTS as u64) as usize;
                assert_eq!(b.wb(s as u16, None), db[s], "{ctx}: data memory, slot {s}");
            }
        }
    }
}
