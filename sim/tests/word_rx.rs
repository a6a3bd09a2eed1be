//! word_rx in Verilator against the model: every word of random packets
//! (data, alarm, VOID, words with a single line-bit error, words a
//! forwarder marked, bad and foreign headers, TST packets) is classified and
//! decoded as `merkur_model::line::
//! decode_word` says; the slot counter, own-slot flag and packet end follow
//! protocol §5; `o_compl` says whether a good word's data is the
//! complement of the good word before it (a TST's H1 = NOT H0).

use merkur_model::line::{
    decode_word, mark_code_bits, nrzi_decode, nrzi_encode, push_group, word_code_bits, Lead, Rx,
    Word, CODE_S,
};
use merkur_model::ring::Header;
use merkur_rtl::{
    emit::verilog::block_verilog,
    line::word_rx::{WordFormat, WordRx},
};
use merkur_sim::{verilator::Model, Rng};

const SLOTS: usize = 12;
const ADDRESS: u64 = 5;

#[derive(Debug, PartialEq)]
struct Out {
    kind: u64,
    slot: u64,
    rx: Rx,
    own: bool,
}

/// Every word kind through the block, seeded. About 220 lines: the
/// stimulus of each kind and what the block must say of it side by side.
fn check(ext: bool) {
    let seed = Rng::seed(0x3077 + ext as u64);
    let mut rng = Rng::new(seed);
    let wbits = if ext { 30 } else { 25 };
    let format = if ext {
        WordFormat::ExtendedAlarm
    } else {
        WordFormat::Basic
    };
    let mut m = Model::build(&block_verilog(WordRx::new(format))).unwrap();
    let p = |m: &Model, n: &str| m.port(n);
    let (clk, st, gv, gr) = (
        p(&m, "clock"),
        p(&m, "i_start"),
        p(&m, "i_gvalid"),
        p(&m, "i_group"),
    );
    let marked = m.port("o_marked");
    let compl = m.port("o_compl");
    // The framer's idle flag beside the group (framer_rx's test checks it).
    let idle = m.port("i_idle");
    let (end, wv, kind, slot, data, alive, alarm, reason, ok, void, own, hbad) = (
        p(&m, "o_end"),
        p(&m, "o_wvalid"),
        p(&m, "o_kind"),
        p(&m, "o_slot"),
        p(&m, "o_data"),
        p(&m, "o_alive"),
        p(&m, "o_alarm"),
        p(&m, "o_reason"),
        p(&m, "o_ok"),
        p(&m, "o_void"),
        p(&m, "o_own"),
        p(&m, "o_hdr_bad"),
    );
    m.set(p(&m, "i_slots_m1"), SLOTS as u64 - 1);
    m.set(p(&m, "i_address"), ADDRESS);
    for pkt in 0..400 {
        let ctx = format!("seed {seed} (MERKUR_SEED), ext {ext}, packet {pkt}");
        // Build the packet's words.
        let sort = rng.below(10);
        let mut words: Vec<Option<Word>> = vec![];
        let (h0, h1) = if sort == 0 {
            // A TST packet: type 10, ACK, address; H1 = NOT H0.
            let d = 0x8000 | (rng.below(2) << 12) as u16 | rng.below(4096) as u16;
            (
                Word {
                    data: d,
                    ..Word::default()
                },
                Word {
                    data: !d,
                    ..Word::default()
                },
            )
        } else {
            let h = Header {
                fs: rng.below(2) == 1,
                rwc: rng.below(2) == 1,
                rwp: false,
                cyc: rng.below(8) as u8,
                hop: rng.below(4096) as u16,
                clr: rng.below(2) == 1,
            };
            let slots = if sort == 1 { SLOTS + 1 } else { SLOTS };
            (h.h0(slots), h.h1())
        };
        words.push(Some(h0));
        words.push(Some(h1));
        if sort != 0 {
            for _ in 0..SLOTS {
                words.push(if rng.below(8) == 0 {
                    None
                } else {
                    Some(Word {
                        data: rng.next_u64() as u16,
                        alive: rng.below(2) == 1,
                        alarm: rng.below(6) == 0,
                        reason: if ext { rng.below(16) as u8 } else { 0 },
                    })
                });
            }
        }
        let mut code = vec![];
        for (i, w) in words.iter().enumerate() {
            match w {
                // Now and then a slot word a forwarder marked (§4).
                Some(w) if i >= 2 && rng.below(10) == 0 => {
                    code.extend(mark_code_bits(&word_code_bits(w, ext)))
                }
                Some(w) => code.extend(word_code_bits(w, ext)),
                None => (0..wbits / 5).for_each(|_| push_group(&mut code, CODE_S)),
            }
        }
        if rng.below(3) == 0 {
            let mut level = 0;
            let mut line = nrzi_encode(&code, &mut level);
            let b = rng.below(code.len() as u64 - 1) as usize + 1;
            line[b] ^= 1;
            code = nrzi_decode(&line, 0);
        }
        // What the model says the receiver must produce.
        // Bad words are compared by class (their first group is not an output).
        let rx: Vec<Rx> = code
            .chunks(wbits)
            .map(|c| match decode_word(c, ext) {
                Rx::Bad(_) => Rx::Bad(Lead::Other),
                Rx::Marked(_) => Rx::Marked(Lead::Other),
                r => r,
            })
            .collect();
        let hdr_ok = |r: &Rx| matches!(r, Rx::Ok(w) if !w.alarm);
        let mut expect = vec![];
        let mut expect_hdr_bad = false;
        let h0_ok = hdr_ok(&rx[0])
            && match rx[0] {
                Rx::Ok(w) => w.data >> 14 != 0 || (w.data & 0xfff) as usize == SLOTS - 1,
                _ => false,
            };
        expect.push(Out {
            kind: 0,
            slot: 0,
            rx: rx[0],
            own: false,
        });
        if !h0_ok {
            expect_hdr_bad = true;
        } else {
            expect.push(Out {
                kind: 1,
                slot: 0,
                rx: rx[1],
                own: false,
            });
            let is_data = matches!(rx[0], Rx::Ok(w) if w.data >> 14 == 0);
            if !hdr_ok(&rx[1]) {
                expect_hdr_bad = is_data;
            } else if is_data {
                for s in 0..SLOTS {
                    expect.push(Out {
                        kind: 2,
                        slot: s as u64,
                        rx: rx[2 + s],
                        own: s as u64 == ADDRESS,
                    });
                }
            }
        }
        // Drive it.
        m.set(st, 1);
        m.set(gv, 0);
        m.tick(clk);
        m.set(st, 0);
        let groups: Vec<u64> = code
            .chunks(5)
            .map(|c| c.iter().fold(0u64, |a, &b| a << 1 | b as u64))
            .collect();
        let mut got = vec![];
        let mut got_compl = vec![];
        let (mut ends, mut hdr_bads) = (0, 0);
        let mut gi = 0;
        let mut tail = 0;
        while tail < 4 {
            let send = gi < groups.len() && rng.below(3) != 0;
            m.set(gv, send as u64);
            m.set(gr, if send { groups[gi] } else { 0 });
            m.set(idle, u64::from(send && groups[gi] == 31));
            if send {
                gi += 1;
            }
            if gi == groups.len() {
                tail += 1;
            }
            m.tick(clk);
            if m.get(wv) == 1 {
                let r = if m.get(ok) == 1 {
                    Rx::Ok(Word {
                        data: m.get(data) as u16,
                        alive: m.get(alive) == 1,
                        alarm: m.get(alarm) == 1,
                        reason: m.get(reason) as u8,
                    })
                } else if m.get(void) == 1 {
                    Rx::Void
                } else if m.get(marked) == 1 {
                    Rx::Marked(Lead::Other)
                } else {
                    Rx::Bad(Lead::Other)
                };
                got_compl.push(m.get(compl) == 1);
                // Data bits of a bad word are not specified; compare the class.
                got.push(Out {
                    kind: m.get(kind),
                    slot: m.get(slot),
                    rx: r,
                    own: m.get(own) == 1,
                });
            }
            ends += m.get(end);
            hdr_bads += m.get(hbad);
        }
        assert_eq!(got, expect, "{ctx}");
        for i in 1..expect.len() {
            if let (Rx::Ok(a), Rx::Ok(b)) = (expect[i - 1].rx, expect[i].rx) {
                assert_eq!(
                    got_compl[i],
                    b.data == !a.data,
                    "{ctx}: o_compl of word {i} ({:04x} after {:04x})",
                    b.data,
                    a.data
                );
            }
        }
        assert_eq!(ends, 1, "{ctx}: exactly one packet end");
        assert_eq!(hdr_bads, expect_hdr_bad as u64, "{ctx}: header rejection");
    }
}

#[test]
fn word_rx_matches_the_model() {
    check(false);
}

#[test]
fn word_rx_ext_matches_the_model() {
    check(true);
}
