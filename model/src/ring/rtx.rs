//! Retransmission on demand (docs/protocol.md §8, after FTT-CAN): when
//! critical slots of this cycle's frame came back damaged, the clock base
//! sends a retransmission packet (RTX) after the frame, in the same
//! period; the slots' writers fill in a fresh copy of the value they wrote
//! into the frame, and every node behind them takes it.

use super::*;

/// The retransmission packet in flight.
struct Rtx {
    /// Its head (J K, H0, H1) is intact: nodes act on the packet.
    head_ok: bool,
    /// A forwarder passed the damaged head on: the damage is from further
    /// up, not counted again by a stream controller (§4).
    head_marked: bool,
    /// Per request: the index word (the slot number), then the data word.
    words: Vec<Slot>,
    /// Per request: the cycle its data word's value was written (data
    /// age, not on the line).
    born: Vec<Option<u32>>,
}

impl Ring {
    /// Section 4b of a cycle: the clock base `sm`, whose frame came back
    /// with critical slots damaged (or with its header damaged), sends the
    /// RTX for those that fit (§8) along the frame's path. `acted`: the
    /// nodes whose Alive flip-flop toggles at the end of the cycle — those
    /// that processed the frame, and those that missed it but filled a
    /// request or put their Alive into one here (as if they had processed
    /// the frame, §8).
    pub(super) fn rtx_packet(
        &mut self,
        sm: usize,
        f: &CycleFaults,
        acted: &mut [bool],
        ev: &mut Vec<Event>,
    ) -> Option<RtxRecord> {
        if self.damaged.is_empty() || self.nodes[sm].failsafe {
            return None;
        }
        let c = self.cycle;
        let ext = self.cfg.ext;
        let requested = self.damaged.len();
        let k = requested.min(self.cfg.rtx_capacity(self.nodes[sm].rw));
        let slots: Vec<usize> = self.damaged[..k].to_vec();
        self.event(ev, c, At::End, sm, EventKind::Rtx { sent: k, requested });
        let mut rec = RtxRecord {
            slots: slots.clone(),
            left: requested - k,
            bits: 0,
            back: vec![false; k],
            fibres: vec![],
            jk: vec![],
            on: vec![],
        };
        if k == 0 {
            return Some(rec);
        }
        rec.bits = rtx_bits(k, ext);
        let mut p = Rtx {
            head_ok: true,
            head_marked: false,
            words: slots
                .iter()
                .flat_map(|&s| {
                    let index = Word {
                        data: s as u16,
                        alive: false,
                        alarm: false,
                        reason: 0,
                    };
                    [Slot::Data(index), Slot::Void]
                })
                .collect(),
            born: vec![None; k],
        };
        // The clock base fills the requests for its own slots as it sends.
        if self.rtx_fill(sm, &mut p) {
            acted[sm] = true;
        }
        let mut fib = self.out_fibre(sm, table1(self.nodes[sm].mode).1);
        let mut returned = false;
        for _ in 0..4 * self.n() + 4 {
            // A fibre that broke during the frame is dark by now.
            if !self.lit(fib) || f.cut_fibre.iter().any(|(x, _)| *x == fib) {
                break;
            }
            for &(ff, t, bit) in &f.flips {
                match t {
                    FlipTarget::RtxHead if ff == fib => p.head_ok = false,
                    FlipTarget::Rtx(j) if ff == fib => flip_word(&mut p.words, j, bit, ext),
                    _ => {}
                }
            }
            rec.fibres.push(self.fibre_index(fib));
            rec.on.push(RtxOnFibre {
                head_ok: p.head_ok,
                words: p.words.clone(),
            });
            let (r, port) = self.dst(fib);
            if !self.nodes[r].up || f.cut_node.iter().any(|(x, _)| *x == r) {
                break;
            }
            let mode = self.nodes[r].mode;
            let (inp, out, bsr, bss) = table1(mode);
            let counted = port == inp || (port == bsr && mode == Mode::N);
            // A node whose stream controller failed on this receiver during
            // the frame wrapped at that word (§10): nothing more passes.
            if counted && mode == Mode::N && self.nodes[r].cf_words[usize::from(port == Port::Si)] {
                break;
            }
            if counted && self.rtx_bad_words(r, port, &p, ev) && mode == Mode::N {
                break;
            }
            if port == inp && p.head_ok {
                rec.jk.push(r);
            }
            if port == inp {
                if r == sm {
                    returned = true;
                    break;
                }
                if !self.nodes[r].failsafe && p.head_ok && self.rtx_node(r, &mut p) {
                    acted[r] = true;
                }
                // A forwarder marks what arrived bad (§4).
                for w in p.words.iter_mut() {
                    if let Slot::Bad(l) = *w {
                        *w = Slot::Marked(l);
                    }
                }
                p.head_marked |= !p.head_ok;
                fib = self.out_fibre(r, out);
            } else if port == bsr && mode == Mode::N {
                fib = self.out_fibre(r, bss);
            } else {
                break;
            }
        }
        if returned && p.head_ok {
            rec.back = self.rtx_return(sm, &p);
        }
        Some(rec)
    }

    /// A stream controller's run of bad words (§9) over the RTX's words on
    /// node `k`'s receiver `port`, as over a frame's. Returns whether the
    /// run reached [`BAD_WORDS`] in an armed node (channel failure).
    fn rtx_bad_words(&mut self, k: usize, port: Port, p: &Rtx, ev: &mut Vec<Event>) -> bool {
        let pi = usize::from(port == Port::Si);
        let mut run = self.nodes[k].bad_run[pi];
        let mut hit = false;
        let mut bump = |run: &mut u32| {
            if *run < BAD_WORDS {
                *run += 1;
                hit |= *run == BAD_WORDS;
            }
        };
        if !p.head_ok {
            if !p.head_marked {
                bump(&mut run);
            }
        } else {
            run = 0;
            for w in &p.words {
                match w {
                    Slot::Data(_) => run = 0,
                    Slot::Bad(_) => bump(&mut run),
                    Slot::Marked(_) | Slot::Void | Slot::Missing => {}
                }
            }
        }
        self.nodes[k].bad_run[pi] = run;
        if !hit || !self.nodes[k].armed {
            return false;
        }
        self.nodes[k].cf_words[pi] = true;
        let c = self.cycle;
        self.event(ev, c, At::End, k, EventKind::BadWords { port });
        true
    }

    /// Node `k` processes the RTX (its head intact): counts its bad words,
    /// fills the requests it writes (once armed) and takes the copies it
    /// reads. Returns whether it wrote into the packet (a request filled,
    /// an actuator's Alive).
    fn rtx_node(&mut self, k: usize, p: &mut Rtx) -> bool {
        self.nodes[k].perr += p.words.iter().filter(|w| w.is_bad()).count() as u32;
        let mut wrote = self.nodes[k].armed && self.rtx_fill(k, p);
        for i in 0..p.born.len() {
            if let Some(s) = self.rtx_index(&p.words[2 * i]) {
                let born = p.born[i];
                wrote |= self.rtx_take(k, s, &mut p.words[2 * i + 1], born);
            }
        }
        wrote
    }

    /// The slot a good index word names.
    fn rtx_index(&self, w: &Slot) -> Option<usize> {
        match w {
            Slot::Data(d) if !d.alarm && (d.data as usize) < self.cfg.slots => {
                Some(d.data as usize)
            }
            _ => None,
        }
    }

    /// Node `k` fills the data word of every request for a slot it writes,
    /// whatever it arrives as (VOID, or damaged on the way): the value it wrote into this cycle's frame (or
    /// would have, had it not missed it), with the Alive bit it wrote
    /// there (an actuator slot: the actuator's, as last seen), never an
    /// alarm (§8). Returns whether it filled one.
    fn rtx_fill(&mut self, k: usize, p: &mut Rtx) -> bool {
        let c = self.cycle;
        let mut filled = false;
        for i in 0..p.born.len() {
            let Some(s) = self.rtx_index(&p.words[2 * i]) else {
                continue;
            };
            let nd = &self.nodes[k];
            let (data, alive) = match (self.cfg.nodes[k].kind, self.cfg.slot_kind[s]) {
                (Kind::Sensor, SlotKind::Sensor) if self.cfg.nodes[k].address == s => {
                    (sensor_value(&self.cfg, s, c), nd.toggle)
                }
                (Kind::Master | Kind::SpecialMaster, SlotKind::Local)
                    if self.cfg.writer[s] == k && nd.valid[s] =>
                {
                    (nd.db[s], nd.toggle)
                }
                (Kind::Master | Kind::SpecialMaster, SlotKind::Act { .. })
                    if self.cfg.writer[s] == k && nd.valid[s] =>
                {
                    (nd.db[s], nd.act_alive[s])
                }
                _ => continue,
            };
            p.words[2 * i + 1] = Slot::Data(Word {
                data,
                alive,
                alarm: false,
                reason: 0,
            });
            p.born[i] = Some(c);
            filled = true;
        }
        filled
    }

    /// Node `k` takes a good copy of slot `s` from the RTX, as it would
    /// have taken the frame's word but without an Alive check (§8); an
    /// actuator puts its own Alive into its slot's copy, as in the frame,
    /// also into one damaged after its first group, which reads as data
    /// (returns whether it did).
    fn rtx_take(&mut self, k: usize, s: usize, w: &mut Slot, born: Option<u32>) -> bool {
        let own = matches!(self.cfg.slot_kind[s], SlotKind::Act { actuator } if actuator == k);
        let Slot::Data(d) = w else {
            return own
                && match *w {
                    Slot::Bad(l) | Slot::Marked(l) => {
                        l == Lead::Data || (l == Lead::Alarm && self.cfg.ext)
                    }
                    _ => false,
                };
        };
        let kind = self.cfg.nodes[k].kind;
        let nd = &mut self.nodes[k];
        if kind.is_master() && (self.cfg.writer[s] != k || !nd.valid[s]) {
            nd.db[s] = d.data;
            nd.db_born[s] = born;
            nd.valid[s] = true;
        }
        if own {
            nd.output = d.data;
            nd.out_born = born;
            d.alive = nd.toggle;
            return true;
        }
        false
    }

    /// The RTX back at the clock base: it takes the good copies like any
    /// master and puts them into its return store for the next frame, so
    /// that the nodes before the writers get them as without errors (§8).
    /// Returns, per request, whether a good copy came back.
    fn rtx_return(&mut self, sm: usize, p: &Rtx) -> Vec<bool> {
        self.nodes[sm].perr += p.words.iter().filter(|w| w.is_bad()).count() as u32;
        let mut back = vec![false; p.born.len()];
        for (i, ok) in back.iter_mut().enumerate() {
            let Some(s) = self.rtx_index(&p.words[2 * i]) else {
                continue;
            };
            let mut w = p.words[2 * i + 1];
            if let Slot::Data(_) = w {
                self.rtx_take(sm, s, &mut w, p.born[i]);
                self.store[s] = w;
                self.store_born[s] = p.born[i];
                *ok = true;
            }
        }
        back
    }
}
