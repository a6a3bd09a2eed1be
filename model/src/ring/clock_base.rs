//! The clock base's part of the cycle (docs/protocol.md §8, §12): which node
//! sends the frame (the special master or the backup that took over), the
//! DATA and SEC frames on their way round, the return store, the special
//! master's failsafe bookkeeping.

use super::*;

/// What the special master keeps to bring the ring out of failsafe
/// (protocol §12).
#[derive(Debug, Clone, Default)]
pub(super) struct SmExit {
    /// HOP of the last good header back with FS = 0 outside failsafe.
    pub(super) hop_ref: Option<u16>,
    /// Frames back whole in a row, in failsafe.
    pub(super) whole: u32,
    /// CLR frames sent since it left failsafe (0: not clearing).
    pub(super) clr_sent: u32,
    /// The failsafe began with (or saw) a FAILSAFE request: leave only on
    /// the host's clear command.
    pub(super) request: bool,
    /// The host gave the clear command.
    pub(super) host_clear: bool,
}

impl Ring {
    /// The clock base that sends this cycle's frame (§8): the special
    /// master, or the backup that took over from it. When the clock base is
    /// dead, the eligible backup of lowest priority p whose INPUT has been
    /// quiet for p cycles takes over now; `None`: no frame this cycle.
    pub(super) fn clock_base(&mut self, ev: &mut Vec<Event>) -> Option<usize> {
        if self.nodes[self.base].up {
            return Some(self.base);
        }
        let (k, prio) = self.cfg.backups().into_iter().find(|&(k, p)| {
            let nd = &self.nodes[k];
            nd.up && nd.armed && nd.elig && !nd.failsafe && nd.quiet >= u32::from(p)
        })?;
        self.base = k;
        // What a clock base learns from returning frames starts afresh; the
        // return store is empty, as after a frame that did not come back.
        self.store = vec![Slot::Void; self.cfg.slots];
        self.store_born = vec![None; self.cfg.slots];
        self.emitted = vec![Slot::Void; self.cfg.slots];
        self.returned_rwc = false;
        self.exit = SmExit::default();
        let c = self.cycle;
        self.event(ev, c, At::Hdr, k, EventKind::Takeover { prio });
        Some(k)
    }

    /// Section 3 of a cycle: clock base `sm` sends the DATA frame, every
    /// node on its path processes or passes it, and it comes back (or not)
    /// into the return store. Returns whether `sm` got a good header back.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn data_frame(
        &mut self,
        sm: usize,
        f: &CycleFaults,
        fibres: &mut [Carry],
        got_frame: &mut [bool],
        path: &mut Vec<usize>,
        ev: &mut Vec<Event>,
    ) -> bool {
        let c = self.cycle;
        let n = self.n();
        let s_count = self.cfg.slots;
        let clr = self.sm_frame_start(ev);
        let hdr = Header {
            fs: self.nodes[sm].failsafe,
            rwc: self.nodes[sm].mode != Mode::N,
            rwp: self.returned_rwc,
            cyc: (c & 7) as u8,
            hop: 0,
            clr,
        };
        let mut frame = Frame {
            hdr: HeaderRx::Ok(hdr),
            hdr_bad: (false, false),
            hdr_marked: false,
            words: self.store.clone(),
        };
        self.cur_born = self.store_born.clone();
        if !self.nodes[sm].failsafe {
            for s in 0..s_count {
                self.write_slot(sm, s, &mut frame.words[s], ev);
            }
        }
        // The clock base dies while it sends (a kill before slot s).
        let dies = f.cut_node.iter().find(|(nd, _)| *nd == sm).map(|x| x.1);
        if let Some(s) = dies {
            truncate(&mut frame, s);
        }
        let dies = dies.is_some();
        self.emitted = frame.words.clone();
        path.push(sm);
        let mut fib = self.out_fibre(sm, table1(self.nodes[sm].mode).1);
        let mut returned = None;
        for _hop in 0..4 * n + 4 {
            if !self.lit(fib) {
                break;
            }
            if let Some(&(_, s)) = f.cut_fibre.iter().find(|(x, _)| *x == fib) {
                truncate(&mut frame, s);
            }
            self.apply_flips(&mut frame, fib, &f.flips);
            for b in &f.bursts {
                if let Fault::Burst { fibre, .. } = *b {
                    if fibre == fib {
                        self.apply_burst(&mut frame, *b);
                    }
                }
            }
            let fi = self.fibre_index(fib);
            fibres[fi] = Carry::Data(frame.clone());
            let (k, port) = self.dst(fib);
            if !self.nodes[k].up {
                break;
            }
            let (inp, out, bsr, bss) = table1(self.nodes[k].mode);
            // A run of bad words on the receiver: channel failure at
            // that word (§9). In mode N the node wraps there (§10), so
            // its outputs carry nothing of this frame from that word on.
            let cf_at = if port == inp || (port == bsr && self.nodes[k].mode == Mode::N) {
                self.count_bad_words(k, port, &frame, ev)
            } else {
                None
            };
            let cut_at = cf_at.filter(|_| self.nodes[k].mode == Mode::N);
            if port == inp && self.lose_next.contains(&k) {
                // A WU end that unwrapped at this frame's J K on PI.
                frame.hdr = HeaderRx::NoCs;
            }
            if port == inp {
                if k == sm {
                    if let Some(at) = cut_at {
                        cut(&mut frame, at);
                    }
                    returned = Some(frame.clone());
                    break;
                }
                path.push(k);
                got_frame[k] = self.process(k, &mut frame, ev);
                mark(&mut frame);
                if let Some(&(_, s)) = f.cut_node.iter().find(|(nd, _)| *nd == k) {
                    truncate(&mut frame, s);
                }
                if let Some(at) = cut_at {
                    cut(&mut frame, at);
                }
                fib = self.out_fibre(k, out);
            } else if port == bsr && self.nodes[k].mode == Mode::N {
                if let Some(&(_, s)) = f.cut_node.iter().find(|(nd, _)| *nd == k) {
                    truncate(&mut frame, s);
                }
                if let Some(at) = cut_at {
                    cut(&mut frame, at);
                }
                fib = self.out_fibre(k, bss);
            } else {
                break;
            }
        }
        if dies {
            returned = None;
        }
        self.sm_return(returned, ev)
    }

    /// Section 4 of a cycle: the secondary test frame of clock base `sm`
    /// in mode N (§8). Returns the fibres where it went ahead of a DATA
    /// frame, with its `ok`.
    pub(super) fn sec_frame(
        &mut self,
        sm: usize,
        f: &CycleFaults,
        fibres: &mut [Carry],
        ev: &mut Vec<Event>,
    ) -> Vec<(usize, bool)> {
        let c = self.cycle;
        let n = self.n();
        let mut sec_with_data = vec![];
        let mut ok = true;
        let mut lost = false;
        let mut back = false;
        let mut fib = self.out_fibre(sm, Port::So);
        for _ in 0..2 * n + 2 {
            if !self.lit(fib) || f.cut_fibre.iter().any(|(x, _)| *x == fib) {
                break;
            }
            for &(ff, t, _) in &f.flips {
                if ff == fib {
                    match t {
                        FlipTarget::Cs => lost = true,
                        FlipTarget::H0 | FlipTarget::H1 => ok = false,
                        FlipTarget::Slot(_) | FlipTarget::RtxHead | FlipTarget::Rtx(_) => {}
                    }
                }
            }
            if lost {
                break;
            }
            let fi = self.fibre_index(fib);
            let (k, port) = self.dst(fib);
            if ok && self.nodes[k].up {
                // Its good header words end a run of bad words (§9).
                self.nodes[k].bad_run[usize::from(port == Port::Si)] = 0;
            }
            // A fibre that also carries the (wrapped) DATA frame shows
            // the frame; the SEC that went ahead of it is listed apart.
            if matches!(fibres[fi], Carry::Data(_)) {
                sec_with_data.push((fi, ok));
            } else {
                fibres[fi] = Carry::Sec { ok };
            }
            if !self.nodes[k].up || f.cut_node.iter().any(|(nd, _)| *nd == k) {
                break;
            }
            let (inp, out, bsr, bss) = table1(self.nodes[k].mode);
            if port == bsr && self.nodes[k].mode == Mode::N {
                if k == sm {
                    back = true;
                    break;
                }
                fib = self.out_fibre(k, bss);
            } else if port == inp && k != sm {
                // A forwarder passes a SEC on its INPUT unchanged (a
                // wrapped node's INPUT is a secondary fibre, §5).
                fib = self.out_fibre(k, out);
            } else {
                break;
            }
        }
        if !(back && ok) {
            self.nodes[sm].serr += 1;
            self.event(ev, c, At::End, sm, EventKind::SecFail);
        }
        sec_with_data
    }

    /// The special master receives the returning frame.
    /// The special master at its frame start (§12): leaves failsafe after
    /// [`WHOLE_RETURNS`] frames came back whole (and the host's clear
    /// command where it is needed); returns whether this frame carries CLR.
    pub(super) fn sm_frame_start(&mut self, ev: &mut Vec<Event>) -> bool {
        let sm = self.base;
        let c = self.cycle;
        if self.nodes[sm].failsafe {
            let host = self.cfg.nodes[sm].fs_exit_host || self.exit.request;
            if self.exit.whole >= WHOLE_RETURNS && (!host || self.exit.host_clear) {
                self.nodes[sm].failsafe = false;
                self.event(ev, c, At::Hdr, sm, EventKind::FailsafeExit);
                self.exit = SmExit {
                    hop_ref: self.exit.hop_ref,
                    clr_sent: 1,
                    ..SmExit::default()
                };
            }
        } else if self.exit.clr_sent >= CLR_TRIES {
            // The last CLR frame came back with FS = 1 (or not at all):
            // some node keeps failing safe.
            self.exit.clr_sent = 0;
            self.enter_failsafe(ev, sm, At::Hdr, FsCause::ClearFailed);
        } else if self.exit.clr_sent > 0 {
            self.exit.clr_sent += 1;
        }
        self.exit.clr_sent > 0
    }

    /// The special master's failsafe bookkeeping for a good header that
    /// came back (§12): `hop_ref`, frames back whole, the CLR frames, and
    /// rule 3.
    pub(super) fn exit_return(&mut self, h: &Header, ev: &mut Vec<Event>) {
        let sm = self.base;
        let was_fs = self.nodes[sm].failsafe;
        if !was_fs && !h.fs {
            self.exit.hop_ref = Some(h.hop);
        }
        if was_fs && h.hop >= self.exit.hop_ref.unwrap_or(0) {
            self.exit.whole += 1;
        } else {
            self.exit.whole = 0;
        }
        if self.exit.clr_sent > 0 && h.clr && !h.fs {
            // Every node on the path has left failsafe.
            self.exit.clr_sent = 0;
        }
        if h.fs && !h.clr {
            self.enter_failsafe(ev, sm, At::Hdr, FsCause::Header);
        }
    }

    pub(super) fn sm_return(&mut self, returned: Option<Frame>, ev: &mut Vec<Event>) -> bool {
        let sm = self.base;
        let s_count = self.cfg.slots;
        self.damaged.clear();
        let Some(frame) = returned else {
            self.store = vec![Slot::Void; s_count];
            self.store_born = vec![None; s_count];
            self.nodes[sm].hop = None;
            self.exit.whole = 0;
            return false;
        };
        // A FAILSAFE request that comes back: the ring leaves that failsafe
        // only on the host's clear command (§12).
        let ext = self.cfg.ext;
        if frame.words.iter().any(|w| match w {
            Slot::Data(d) if d.alarm => alarm_of(d, ext).0 == reason::FAILSAFE,
            _ => false,
        }) {
            self.exit.request = true;
        }
        let HeaderRx::Ok(h) = frame.hdr else {
            // The frame came back, its header damaged after a good H0:
            // every node behind the damage ignored it, so every critical
            // slot is requested (§8). Without its start delimiter or with
            // H0 unreadable it is no frame to the clock base (and a wrapped
            // ring's relay drops it): nothing is requested.
            if frame.hdr == HeaderRx::Bad && !frame.hdr_bad.0 {
                self.damaged = self.cfg.critical_slots();
            }
            self.store = vec![Slot::Void; s_count];
            self.store_born = vec![None; s_count];
            self.nodes[sm].hop = None;
            self.exit.whole = 0;
            return false;
        };
        self.returned_rwc = h.rwc;
        self.nodes[sm].hop = Some(h.hop);
        self.nodes[sm].rw = h.rwc || h.rwp || self.nodes[sm].mode != Mode::N;
        self.exit_return(&h, ev);
        let failsafe = self.nodes[sm].failsafe;
        if failsafe {
            self.count_errors(sm, &frame);
            // Nothing read: no Alive check against this frame (§7).
            self.nodes[sm].last_alive.iter_mut().for_each(|a| *a = None);
            self.note_seqs(sm, &frame);
        }
        for s in 0..s_count {
            let w = frame.words[s];
            if !failsafe {
                self.read_slot(sm, s, w, ev);
            }
            if self.cfg.critical[s] && matches!(w, Slot::Bad(_) | Slot::Marked(_) | Slot::Missing) {
                self.damaged.push(s);
            }
            self.store_born[s] = match w {
                Slot::Data(_) => self.cur_born[s],
                _ => None,
            };
            self.store[s] = match w {
                Slot::Data(d) => {
                    // An alarm word is retransmitted once: if an alarm comes
                    // back in a slot where the SM sent one, its owner did
                    // not replace it (it sends none in the cycle after an
                    // alarm, §11), so it is not sent a third time (§8). (In
                    // the extended variant a master may have put new data
                    // in it: still the same alarm.)
                    if d.alarm && matches!(self.emitted[s], Slot::Data(e) if e.alarm) {
                        Slot::Void
                    } else {
                        w
                    }
                }
                _ => Slot::Void,
            };
        }
        true
    }
}
