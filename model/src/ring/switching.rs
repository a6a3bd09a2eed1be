//! The end of a cycle (docs/protocol.md §9, §10, §12): every stream
//! controller's verdict resolved into switchbox changes, failsafe entries
//! and reintegrations, which take effect from the next cycle.

use super::*;

impl Ring {
    /// End-of-cycle resolution of every stream controller into switchbox
    /// changes, failsafe entries and reintegrations (protocol §9, §10, §12).
    pub(super) fn resolve(&mut self, ev: &mut Vec<Event>, seen: &Inputs) {
        let n = self.n();
        let c = self.cycle;
        // A node that unwrapped at the end of the last cycle does not take
        // a TST where DATA is expected for a failure yet (§12: its partner
        // may still be sending it).
        let grace: Vec<bool> = self
            .unwrapped_at
            .iter()
            .map(|u| u.is_some_and(|u| u + 1 == c))
            .collect();
        let start: Vec<Mode> = self.nodes.iter().map(|x| x.mode).collect();
        let rw: Vec<bool> = self
            .nodes
            .iter()
            .map(|x| x.rw || x.mode != Mode::N)
            .collect();
        let mut changed = true;
        let mut guard = 0;
        while changed && guard < 4 * n + 4 {
            changed = false;
            guard += 1;
            for k in 0..n {
                if !self.nodes[k].up {
                    continue;
                }
                let mode = self.nodes[k].mode;
                let (inp, _, bsr, _) = table1(mode);
                let fi = self.in_fibre(k, inp);
                let fb = self.in_fibre(k, bsr);
                let words = |p: Port| self.nodes[k].cf_words[usize::from(p == Port::Si)];
                // Structural: loss of signal, or a TST where DATA is
                // expected (the neighbour wrapped); a run of bad words is a
                // transient and wraps only a ring not known wrapped (§9, §12).
                let tst_fails = mode == Mode::N && !grace[k];
                let hard_in = !self.lit(fi) || (tst_fails && self.carries_tst(fi));
                let hard_bsr = !self.lit(fb) || (tst_fails && self.carries_tst(fb));
                let soft = mode == Mode::N && !rw[k];
                let armed = self.nodes[k].armed;
                // Stream controllers act once the node is armed, but for a
                // TST where DATA is expected on INPUT (§12, a restarted node
                // between wrapped neighbours).
                // (Without the grace after unwrapping: the RTL keeps this
                // decision free of the grace counter, protocol §12.)
                let in_fail = if armed {
                    hard_in || (soft && words(inp))
                } else {
                    mode == Mode::N && self.lit(fi) && self.carries_tst(fi)
                };
                let bsr_fail = armed && (hard_bsr || (soft && words(bsr)));
                let new = match mode {
                    Mode::N if in_fail => Some(Mode::Wu),
                    Mode::N if bsr_fail => Some(Mode::Wd),
                    _ => None,
                };
                let second = match mode {
                    Mode::N => (!self.lit(fi) && !self.lit(fb)) || ((hard_in || hard_bsr) && rw[k]),
                    _ => !self.lit(fi),
                };
                if second && armed && start[k] == mode {
                    self.enter_failsafe(ev, k, At::End, FsCause::SecondFault);
                }
                if let Some(m) = new {
                    self.nodes[k].mode = m;
                    changed = true;
                }
            }
        }
        self.reintegrate(seen);
        // A rejoining node is whole again once it is in mode N, armed, and
        // no TST arrives on its INPUT or BSR.
        for (k, &was) in start.iter().enumerate() {
            let (inp, _, bsr, _) = table1(self.nodes[k].mode);
            let tst =
                self.carries_tst(self.in_fibre(k, inp)) || self.carries_tst(self.in_fibre(k, bsr));
            let nd = &mut self.nodes[k];
            if nd.rejoin && nd.armed && was == Mode::N && nd.mode == Mode::N && !tst {
                nd.rejoin = false;
            }
        }

        for (k, &from) in start.iter().enumerate() {
            let to = self.nodes[k].mode;
            if from != to {
                self.event(ev, c, At::End, k, EventKind::Mode { from, to });
                self.unwrapped_at[k] = (to == Mode::N).then_some(c);
                // A WU end's handshake belongs to its stay in WU.
                let link = (k + n - 1) % n;
                if from == Mode::Wu {
                    self.acked[link] = false;
                }
                let nd = &mut self.nodes[k];
                if (from == Mode::Wu) != (to == Mode::Wu) {
                    // INPUT and BSR move to other lines: a run of bad
                    // words belongs to the old ones (§9).
                    nd.bad_run = [0; 2];
                }
                nd.pending
                    .retain(|p| prio(p.reason) != prio(reason::RECONFIG_N));
                // A RECONFIG in flight is replaced too (only the newest mode
                // is kept, §11).
                if nd
                    .inflight
                    .is_some_and(|p| prio(p.reason) == prio(reason::RECONFIG_N))
                {
                    nd.inflight = None;
                }
                let r = reason::reconfig(to);
                nd.pending.insert(Pending {
                    prio: prio(r),
                    reason: r,
                });
            }
        }
    }
}

/// What each node's INPUT carried in the cycle (step 6), for the
/// end-of-cycle decisions.
pub(super) struct Inputs<'a> {
    /// A packet's J K other than a TST (a frame, a SEC): rule 4's timer.
    pub(super) packet: &'a [bool],
    /// A frame with its J K.
    pub(super) frame: &'a [bool],
    /// The TST of an upstream neighbour wrapped towards the node.
    pub(super) tst: &'a [bool],
}

impl Ring {
    /// Per node, whether what its INPUT carried this cycle is `what`.
    pub(super) fn inputs_carry(
        &self,
        fibres: &[Carry],
        what: impl Fn(&Carry) -> bool,
    ) -> Vec<bool> {
        (0..self.n())
            .map(|k| {
                let inp = self.in_fibre(k, table1(self.nodes[k].mode).0);
                what(&fibres[self.fibre_index(inp)])
            })
            .collect()
    }

    /// Reintegration (§12) at the end of the cycle, link by link (link k
    /// joins node k, its WD end, to node k + 1, its WU end). Two nodes
    /// wrapped towards each other over a link whose fibres both carry
    /// light hear each other's TST, however they got there (a repair, a
    /// soft wrap, a node that re-wrapped after unwrapping); the handshake
    /// is done by the end of the next cycle (≤ 4 TST periods ≤ P). Then:
    /// - the WD end unwraps at a frame boundary: a packet (a frame, or the
    ///   TST of an upstream neighbour wrapped towards it: a node cut off
    ///   between two wraps) ended on its INPUT, or, the special master,
    ///   its period tick; in the loop without the special master of a
    ///   split ring no packet comes, and it waits;
    /// - the WU end unwraps at the next frame's J K on its BSR (PI), so its
    ///   INPUT misses that frame (`lose_next`): with the WD end if a frame
    ///   follows through it, else (it unwrapped on a TST) as soon as one
    ///   does — its handshake is done, and it keeps waiting in WU; in
    ///   failsafe, at the first frame on its BSR, handshake or not.
    pub(super) fn reintegrate(&mut self, seen: &Inputs) {
        let n = self.n();
        let c = self.cycle;
        let sm = self.base;
        let was_lost = std::mem::take(&mut self.lose_next);
        // A node forwards a frame on PO next cycle: it is not wrapped
        // towards PO (not WD), a frame reaches its INPUT (it had one, or it
        // just lost one to its own unwrapping) and it does not lose it.
        let forwards = |r: &Ring, k: usize| {
            r.nodes[k].up
                && r.nodes[k].mode != Mode::Wd
                && (k == sm || seen.frame[k] || was_lost.contains(&k))
        };
        for a in 0..n {
            let b = (a + 1) % n;
            let lit = self.lit(Fibre::P(a)) && self.lit(Fibre::S(a));
            let pair = lit && self.nodes[a].mode == Mode::Wd && self.nodes[b].mode == Mode::Wu;
            if !pair {
                self.pair_since[a] = None;
            }
            if !lit || self.nodes[b].mode != Mode::Wu {
                self.acked[a] = false;
            }
            if pair {
                let since = *self.pair_since[a].get_or_insert(c);
                if since < c {
                    self.acked[a] = true;
                    let boundary = seen.packet[a] || seen.tst[a] || a == sm;
                    if boundary {
                        // The WD end unwraps; its frame, if one follows,
                        // takes the WU end along.
                        self.nodes[a].mode = Mode::N;
                        self.pair_since[a] = None;
                    }
                }
            }
            // In failsafe a frame on BSR is as good as the ACK (the upstream
            // neighbour forwards the ring's frames: it is not wrapped
            // towards this node; the special master's downstream
            // neighbour, cut off with it, hears no TST from it).
            let up_ok = self.acked[a]
                || (self.nodes[b].failsafe
                    && self.nodes[b].mode == Mode::Wu
                    && self.lit(Fibre::P(a)));
            if up_ok && self.nodes[a].mode != Mode::Wd && forwards(self, a) {
                // A rejoining node whose downstream neighbour is wrapped
                // towards it (its TST on SI) turns round to it instead
                // (WU → WD), so the ring stays closed (§12).
                let next = self.nodes[b].rejoin && self.carries_tst(Fibre::S(b));
                self.nodes[b].mode = if next { Mode::Wd } else { Mode::N };
                self.acked[a] = false;
                self.lose_next.push(b);
            }
        }
    }
}
