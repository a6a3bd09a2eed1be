//! The scenario's faults applied to a frame in flight (docs/protocol.md §4,
//! docs/scenarios.md): bit flips and bursts of garbage on a fibre.

use super::*;

/// The faults of one cycle that act inside its packets.
pub(super) struct CycleFaults {
    /// Fibres that break before a slot (fibre, slot).
    pub(super) cut_fibre: Vec<(Fibre, usize)>,
    /// Nodes that die before a slot (node, slot).
    pub(super) cut_node: Vec<(usize, usize)>,
    /// Bit flips (fibre, target, bit).
    pub(super) flips: Vec<(Fibre, FlipTarget, u32)>,
    /// Bursts of garbage.
    pub(super) bursts: Vec<Fault>,
}

impl Ring {
    pub(super) fn apply_flips(
        &self,
        frame: &mut Frame,
        fib: Fibre,
        flips: &[(Fibre, FlipTarget, u32)],
    ) {
        let ext = self.cfg.ext;
        for &(f, t, bit) in flips {
            if f != fib {
                continue;
            }
            match t {
                FlipTarget::Cs => frame.hdr = HeaderRx::NoCs,
                // A header already rejected further up (its H0 good) whose
                // H0 is now hit: the next receiver stops at this fresh,
                // unmarked damage (§4, §9), and so does the clock base (§8).
                FlipTarget::H0 if frame.hdr == HeaderRx::Bad && !frame.hdr_bad.0 => {
                    frame.hdr_bad.0 = true;
                    frame.hdr_marked = false;
                }
                FlipTarget::H0 | FlipTarget::H1 => {
                    if let HeaderRx::Ok(h) = frame.hdr {
                        let (w, other) = if t == FlipTarget::H0 {
                            (h.h0(self.cfg.slots), h.h1())
                        } else {
                            (h.h1(), h.h0(self.cfg.slots))
                        };
                        // A flip of a header word's last bit also hits the
                        // next word's first bit.
                        let next = if t == FlipTarget::H0 {
                            Some(other)
                        } else {
                            match frame.words.first() {
                                Some(Slot::Data(w)) => Some(*w),
                                _ => None,
                            }
                        };
                        let (r, r2) = line::flip_and_decode(&w, next.as_ref(), ext, bit as usize);
                        if t == FlipTarget::H1 {
                            if let (Some(r2), Some(first)) = (r2, frame.words.first_mut()) {
                                *first = rx_slot(r2);
                            }
                        }
                        let (h0, h1) = match (t, r, r2) {
                            (FlipTarget::H0, Rx::Ok(a), Some(Rx::Ok(b))) => (a, b),
                            (FlipTarget::H1, Rx::Ok(b), _) => (other, b),
                            _ => {
                                frame.hdr = HeaderRx::Bad;
                                // H0 bad (the receiver stops there), or H0
                                // good and H1 bad.
                                frame.hdr_bad =
                                    (t == FlipTarget::H0 && !matches!(r, Rx::Ok(_)), true);
                                continue;
                            }
                        };
                        frame.hdr = match Header::decode(&h0, &h1, self.cfg.slots) {
                            Some(h) => HeaderRx::Ok(h),
                            None => HeaderRx::Bad,
                        };
                    }
                }
                FlipTarget::Slot(s) => flip_word(&mut frame.words, s, bit, ext),
                FlipTarget::RtxHead | FlipTarget::Rtx(_) => {}
            }
        }
    }

    /// A burst of garbage on the fibre (protocol §4, scenario `kind =
    /// "burst"`): the line's code bits in the burst become
    /// [`line::garbage`], the level returns after it, and every word it
    /// touched is decoded again, exactly. A word the model knows only as
    /// bad or missing stays as it is where the burst leaves its last group
    /// alone, and is bad where it does not (its code is not known), and so
    /// is every word after it that the burst reaches.
    pub(super) fn apply_burst(&self, frame: &mut Frame, burst: Fault) {
        let Fault::Burst {
            target,
            bit,
            len,
            pattern,
            ..
        } = burst
        else {
            return;
        };
        let HeaderRx::Ok(h) = frame.hdr else {
            // No receiver reads past a rejected header, nor a frame whose
            // delimiter it missed.
            return;
        };
        let ext = self.cfg.ext;
        let w = line::word_bits(ext) as usize;
        let slots = self.cfg.slots;
        // Code bits of H0, H1 and the slots (None: not known).
        let mut words: Vec<Option<Vec<u8>>> = vec![
            Some(line::word_code_bits(&h.h0(slots), ext)),
            Some(line::word_code_bits(&h.h1(), ext)),
        ];
        words.extend(frame.words.iter().map(|x| match x {
            Slot::Data(d) => Some(line::word_code_bits(d, ext)),
            Slot::Void => Some(line::void_code_bits(ext)),
            _ => None,
        }));
        let start = match target {
            FlipTarget::H0 => 0,
            FlipTarget::H1 => w,
            FlipTarget::Slot(s) => (2 + s) * w,
            FlipTarget::Cs | FlipTarget::RtxHead | FlipTarget::Rtx(_) => return,
        } + bit as usize;
        let len = len as usize;
        let g = line::garbage(pattern, len);
        // The level's XOR mask m: c' = c ^ m[t] ^ m[t-1]; in the burst c' is
        // the garbage, so m[t] = m[t-1] ^ c ^ g; after it m = 0.
        let mut m = Some(0u8);
        let mut touched = vec![false; words.len()];
        let mut lost = vec![false; words.len()];
        let end = (start + len + 1).min(words.len() * w);
        for t in start..end {
            let (wi, bi) = (t / w, t % w);
            touched[wi] = true;
            let in_burst = t < start + len;
            match (&mut words[wi], m) {
                (Some(code), Some(mv)) => {
                    let c = code[bi];
                    code[bi] = if in_burst { g[t - start] } else { c ^ mv };
                    m = in_burst.then_some(mv ^ c ^ code[bi]);
                }
                // After a word whose code is not known, the level is not
                // known either.
                (Some(_), None) => lost[wi] = true,
                (None, _) => m = None,
            }
        }
        let rx = |wi: usize| -> Option<line::Rx> {
            match &words[wi] {
                Some(_) if lost[wi] => Some(line::Rx::Bad(Lead::Other)),
                Some(c) => Some(line::decode_word(c, ext)),
                // Its last group untouched: it stays what it was.
                None if start + len <= (wi + 1) * w - 5 => None,
                None => Some(line::Rx::Bad(Lead::Other)),
            }
        };
        for (wi, _) in touched.iter().enumerate().skip(2).filter(|(_, t)| **t) {
            if let Some(r) = rx(wi) {
                frame.words[wi - 2] = rx_slot(r);
            }
        }
        if touched[0] || touched[1] {
            let (a, b) = (rx(0), rx(1));
            frame.hdr_marked = false;
            frame.hdr = match (&a, &b) {
                (Some(line::Rx::Ok(h0)), Some(line::Rx::Ok(h1))) => {
                    match Header::decode(h0, h1, slots) {
                        Some(h) => HeaderRx::Ok(h),
                        None => HeaderRx::Bad,
                    }
                }
                _ => HeaderRx::Bad,
            };
            let bad = |r: &Option<line::Rx>| !matches!(r, Some(line::Rx::Ok(_)));
            frame.hdr_bad = (bad(&a), bad(&b));
        }
    }
}
