//! Stimulus from the model and reading back what a monitor decodes: shared by
//! the node and chain tests.

use crate::verilator::Model;
use crate::Rng;
use merkur_model::line::{
    lead_of, mark_code_bits, push_group, void_code_bits, word_code_bits, Lead, Word, CODE_I,
    CODE_J, CODE_K,
};
use merkur_model::ring::{rtx_head, Frame, HeaderRx, Slot};

/// Code bits of a bad word whose first group shows `lead` (the model keeps
/// only that of a bad word): a word with that first group and an error in
/// its third group; `ext`: in the extended-alarm format (protocol §6).
pub fn bad_word(lead: Lead, ext: bool, rng: &mut Rng) -> Vec<u8> {
    let mut c = match lead {
        Lead::S => void_code_bits(ext),
        Lead::Alarm => word_code_bits(
            &Word {
                data: if ext { 0 } else { 0x1000 },
                alarm: true,
                reason: if ext { 1 } else { 0 },
                ..Word::default()
            },
            ext,
        ),
        Lead::Data | Lead::Other => word_code_bits(
            &Word {
                data: rng.next_u64() as u16,
                ..Word::default()
            },
            ext,
        ),
    };
    if lead == Lead::Other {
        // An invalid group that still has an edge: no line-bit error
        // silences a line for 8 bit times (a receiver takes that as dead).
        c[..5].copy_from_slice(&[0, 0, 1, 0, 0]);
    }
    assert_eq!(lead_of(c[..5].iter().fold(0, |a, &b| a << 1 | b)), lead);
    // Two adjacent code bits of group 2: what one NRZI line-bit error does.
    c[11] ^= 1;
    c[12] ^= 1;
    c
}

/// Appends the code bits of a model frame with a good header (J K, H0, H1,
/// slots; bad slots rebuilt by [`bad_word`]), in the extended-alarm format
/// when `ext`. Panics on frames the model shows with a bad header or missing
/// words: callers pick complete frames.
pub fn frame_code(code: &mut Vec<u8>, f: &Frame, slots: usize, ext: bool, rng: &mut Rng) {
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    let HeaderRx::Ok(h) = f.hdr else {
        panic!("frame_code needs a good header")
    };
    code.extend(word_code_bits(&h.h0(slots), ext));
    code.extend(word_code_bits(&h.h1(), ext));
    slot_code(code, &f.words, ext, rng);
}

/// Appends the code bits of slot words (bad ones rebuilt by [`bad_word`]).
fn slot_code(code: &mut Vec<u8>, words: &[Slot], ext: bool, rng: &mut Rng) {
    for w in words {
        match w {
            Slot::Data(d) => code.extend(word_code_bits(d, ext)),
            Slot::Void => code.extend(void_code_bits(ext)),
            Slot::Bad(l) => code.extend(bad_word(*l, ext, rng)),
            Slot::Marked(l) => code.extend(mark_code_bits(&bad_word(*l, ext, rng))),
            Slot::Missing => panic!("stimulus needs complete packets"),
        }
    }
}

/// Appends the code bits of a retransmission packet that repairs the frame
/// of cycle `cyc` (protocol §8: J K, the head of
/// [`merkur_model::ring::rtx_head`], the request words as the model has
/// them on a fibre, [`merkur_model::ring::RtxOnFibre`]).
pub fn rtx_code(code: &mut Vec<u8>, cyc: u32, words: &[Slot], ext: bool, rng: &mut Rng) {
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    for w in rtx_head(cyc) {
        code.extend(word_code_bits(&w, ext));
    }
    slot_code(code, words, ext, rng);
}

/// Appends one TST packet (protocol §5) and its idle group: 65 bit times
/// (75 in the extended-alarm format, `ext`).
pub fn tst_code(code: &mut Vec<u8>, ack: bool, addr: u16, ext: bool) {
    push_group(code, CODE_J);
    push_group(code, CODE_K);
    let d = 0x8000 | (ack as u16) << 12 | (addr & 0xfff);
    for data in [d, !d] {
        code.extend(word_code_bits(
            &Word {
                data,
                ..Word::default()
            },
            ext,
        ));
    }
    push_group(code, CODE_I);
}

/// A slot as a monitor reports it (bad words by class only).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Seen {
    /// Good word: data, Alive, Alarm, the reason nibble (extended-alarm
    /// words; 0 in the basic format).
    Word(u16, bool, bool, u8),
    /// VOID.
    Void,
    /// Bad, damaged on the fibre it was read on.
    Bad,
    /// Bad and marked by a forwarder (protocol §4).
    Marked,
}

/// How the model's slot must look to a monitor.
pub fn seen(s: &Slot) -> Seen {
    match s {
        Slot::Data(d) => Seen::Word(d.data, d.alive, d.alarm, d.reason),
        Slot::Void => Seen::Void,
        Slot::Marked(_) => Seen::Marked,
        _ => Seen::Bad,
    }
}

/// Collects packets from a Verilated [`merkur_rtl::line::monitor::Monitor`]:
/// header words (0xdead when bad) and slots.
pub struct PacketReader {
    start: usize,
    wvalid: usize,
    kind: usize,
    data: usize,
    alive: usize,
    alarm: usize,
    reason: usize,
    ok: usize,
    void: usize,
    marked: usize,
    /// Packets so far: (header words, slots).
    pub packets: Vec<(Vec<u16>, Vec<Seen>)>,
}

impl PacketReader {
    /// Looks up the monitor's ports.
    pub fn new(m: &Model) -> PacketReader {
        PacketReader {
            start: m.port("o_start"),
            wvalid: m.port("o_wvalid"),
            kind: m.port("o_kind"),
            data: m.port("o_data"),
            alive: m.port("o_alive"),
            alarm: m.port("o_alarm"),
            reason: m.port("o_reason"),
            ok: m.port("o_ok"),
            void: m.port("o_void"),
            marked: m.port("o_marked"),
            packets: vec![],
        }
    }

    /// Reads the monitor's outputs after a clock.
    pub fn sample(&mut self, m: &Model) {
        if m.get(self.start) == 1 {
            self.packets.push((vec![], vec![]));
        }
        if m.get(self.wvalid) == 1 {
            let Some(cur) = self.packets.last_mut() else {
                return;
            };
            let ok = m.get(self.ok) == 1;
            if m.get(self.kind) < 2 {
                cur.0
                    .push(if ok { m.get(self.data) as u16 } else { 0xdead });
            } else {
                cur.1.push(if ok {
                    Seen::Word(
                        m.get(self.data) as u16,
                        m.get(self.alive) == 1,
                        m.get(self.alarm) == 1,
                        m.get(self.reason) as u8,
                    )
                } else if m.get(self.void) == 1 {
                    Seen::Void
                } else if m.get(self.marked) == 1 {
                    Seen::Marked
                } else {
                    Seen::Bad
                });
            }
        }
    }
}
