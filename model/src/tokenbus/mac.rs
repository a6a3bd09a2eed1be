//! A station's token-bus MAC (docs/protocol.md §17, the simplified IEEE 802.4
//! medium access): token passing, solicit-successor windows, the ring
//! init, and the pulses it gives its RMM.

use super::*;

/// MAC states (the numbers of the paper's Table 1 where they exist).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum St {
    Offline,
    Idle,
    ClaimListen,
    UseToken,
    AwaitResponse,
    CheckTokenPass,
    /// Waiting for its response window.
    Respond,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Query {
    Solicit1,
    WhoFollows(u8),
    Solicit2(u8),
}

/// A frame the MAC received.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Rx {
    pub(super) fc: u8,
    pub(super) da: u8,
    pub(super) sa: u8,
    pub(super) data: Vec<u8>,
}

/// One station's token-bus MAC.
#[derive(Debug, Clone)]
pub(super) struct Mac {
    pub(super) ts: u8,
    pub(super) n: u8,
    pub(super) ns: u8,
    pub(super) ps: u8,
    pub(super) in_ring: bool,
    pub(super) st: St,
    pub(super) timer: u32,
    pub(super) tries: u8,
    pub(super) holds: u32,
    pub(super) seq: u16,
    pub(super) data_len: usize,
    pub(super) txq: VecDeque<u16>,
    pub(super) after: St,
    pub(super) query: Query,
    pub(super) rxbuf: Vec<u8>,
    pub(super) rx_in: bool,
    pub(super) idle: u32,
    pub(super) resp_frame: Vec<u16>,
    /// (asker, our successor) once our set_successor goes out.
    pub(super) resp_to: (u8, u8),
    pub(super) leaving: bool,
    pub(super) babble: u32,
}

/// What a MAC does in one tick.
#[derive(Debug, Default)]
pub(super) struct MacOut {
    pub(super) tx: u16,
    pub(super) ev: u8,
    pub(super) sf_sent: bool,
    pub(super) cmd_sent: bool,
    pub(super) rx_sf: Option<(u8, u16)>,
    pub(super) cmd_rx: Option<bool>,
    pub(super) data_rx: Option<(u8, u16)>,
    pub(super) data_tx: Option<u16>,
}

impl Mac {
    pub(super) fn new(ts: u8, n: u8, data_len: usize) -> Mac {
        Mac {
            ts,
            n,
            ns: ts,
            ps: ts,
            in_ring: false,
            st: St::Offline,
            timer: INIT_TICKS,
            tries: 0,
            holds: 0,
            seq: 0,
            data_len,
            txq: VecDeque::new(),
            after: St::Idle,
            query: Query::Solicit1,
            rxbuf: vec![],
            rx_in: false,
            idle: 0,
            resp_frame: vec![],
            resp_to: (0, 0),
            leaving: false,
            babble: 0,
        }
    }

    /// Ring distance from this station downwards to `a` minus one: the
    /// response rank of `a` to this station's solicit.
    pub(super) fn rank(&self, from: u8, a: u8) -> u32 {
        (from as u32 + self.n as u32 - a as u32 - 1) % self.n as u32
    }

    /// Addresses strictly between TS and NS going down (all others when alone).
    pub(super) fn gap(&self) -> u32 {
        if self.ns == self.ts {
            self.n as u32 - 1
        } else {
            self.rank(self.ts, self.ns)
        }
    }

    pub(super) fn send(&mut self, f: Vec<u16>, after: St) {
        if !self.txq.is_empty() {
            self.txq.push_back(sym::SIL);
        }
        self.txq.extend(f);
        self.after = after;
    }

    /// Receives one delivered symbol; a complete valid frame is returned.
    pub(super) fn receive(&mut self, s: u16) -> Option<Rx> {
        match sym::kind(s) {
            sym::SD => {
                self.rx_in = true;
                self.rxbuf.clear();
                None
            }
            sym::DATA if self.rx_in => {
                self.rxbuf.push(s as u8);
                None
            }
            sym::ED if self.rx_in => {
                self.rx_in = false;
                let b = std::mem::take(&mut self.rxbuf);
                if b.len() >= 4 && fcs(&b[..b.len() - 1]) == b[b.len() - 1] {
                    Some(Rx {
                        fc: b[0],
                        da: b[1],
                        sa: b[2],
                        data: b[3..b.len() - 1].to_vec(),
                    })
                } else {
                    None
                }
            }
            _ => {
                self.rx_in = false;
                None
            }
        }
    }

    pub(super) fn pass_token(&mut self) {
        let f = frame(fc::TOKEN, self.ns, self.ts, &[]);
        self.send(f, St::CheckTokenPass);
    }

    pub(super) fn ask(&mut self, q: Query) {
        self.query = q;
        let f = match q {
            Query::Solicit1 => frame(fc::SOLICIT1, self.ns, self.ts, &[]),
            Query::WhoFollows(_) => frame(fc::WHO_FOLLOWS, BROADCAST, self.ts, &[self.ns]),
            Query::Solicit2(_) => frame(fc::SOLICIT2, BROADCAST, self.ts, &[]),
        };
        self.send(f, St::AwaitResponse);
    }

    /// The response window of a query this station was asked.
    pub(super) fn window(&self, q: Query) -> u32 {
        match q {
            Query::Solicit1 => RANK_TICKS * self.gap() + SLOT_TIME,
            Query::WhoFollows(_) => SLOT_TIME,
            Query::Solicit2(_) => RANK_TICKS * (self.n as u32 - 1) + SLOT_TIME,
        }
    }

    /// Starts a token hold: queued RMM frames, one data frame, then a
    /// solicit or the token pass.
    pub(super) fn use_token(&mut self, hw: &RmmOut, o: &mut MacOut) {
        self.st = St::UseToken;
        self.holds += 1;
        if self.leaving {
            // Graceful exit: tell the predecessor who follows, pass the token on.
            self.leaving = false;
            let f = frame(fc::SET_SUCCESSOR, self.ps, self.ts, &[self.ns]);
            self.send(f, St::UseToken);
            let t = frame(fc::TOKEN, self.ns, self.ts, &[]);
            self.send(t, St::Offline);
            self.in_ring = false;
            o.ev |= ev::EXIT_RING;
            return;
        }
        if hw.cmd_req {
            let f = frame(fc::SWITCH, BROADCAST, self.ts, &[hw.cmd_ch as u8]);
            self.send(f, St::UseToken);
            o.cmd_sent = true;
        }
        if hw.sf_pend {
            let w = hw.sf_word;
            let f = frame(fc::STATUS, BROADCAST, self.ts, &[(w >> 8) as u8, w as u8]);
            self.send(f, St::UseToken);
            o.sf_sent = true;
        }
        let mut d = vec![0u8; self.data_len];
        d[0] = (self.seq >> 8) as u8;
        d[1] = self.seq as u8;
        let f = frame(fc::DATA, BROADCAST, self.ts, &d);
        o.data_tx = Some(self.seq);
        self.seq = self.seq.wrapping_add(1);
        self.send(f, St::UseToken);
        let solicit = self.gap() > 0 && (self.ns == self.ts || self.holds % INTER_SOLICIT == 0);
        if solicit {
            self.ask(Query::Solicit1);
        } else {
            self.tries = 0;
            self.pass_token();
        }
    }

    /// One tick. `rx` is the symbol the DCM delivers. One match over the
    /// MAC's states (about 160 lines): the state machine in one place.
    pub(super) fn step(&mut self, hw: &RmmOut) -> MacOut {
        let mut o = MacOut::default();
        let rx = hw.rx;
        let frame_in = self.receive(rx);
        // Frames every powered station takes whatever it is doing.
        if let Some(f) = &frame_in {
            match f.fc {
                fc::DATA if f.data.len() >= 2 => {
                    o.data_rx = Some((f.sa, (f.data[0] as u16) << 8 | f.data[1] as u16))
                }
                fc::STATUS if f.data.len() == 2 => {
                    o.rx_sf = Some((f.sa, (f.data[0] as u16) << 8 | f.data[1] as u16))
                }
                fc::SWITCH if f.data.len() == 1 => o.cmd_rx = Some(f.data[0] & 1 == 1),
                _ => {}
            }
        }
        if self.st == St::Offline && self.txq.is_empty() {
            if self.timer > 0 {
                self.timer -= 1;
                if self.timer == 0 {
                    self.st = St::Idle;
                    self.idle = 0;
                    o.ev |= ev::INITIALIZE;
                }
            }
            return o;
        }
        let heard = rx != sym::SIL;
        // Transmitting: one symbol per tick, then the state that follows.
        if let Some(s) = self.txq.pop_front() {
            o.tx = s;
            if self.txq.is_empty() {
                self.st = self.after;
                self.timer = 0;
                if self.st == St::AwaitResponse {
                    self.timer = self.window(self.query);
                } else if self.st == St::CheckTokenPass {
                    self.timer = SLOT_TIME;
                } else if self.st == St::Idle || self.st == St::Offline {
                    self.idle = 0;
                }
            }
            return o;
        }
        match self.st {
            St::Offline => {}
            St::Idle => {
                self.idle = if heard { 0 } else { self.idle + 1 };
                if let Some(f) = frame_in {
                    self.idle_frame(&f, hw, &mut o);
                }
                if self.st == St::Idle && self.idle >= BUS_IDLE {
                    let pad = vec![0u8; 2 * self.ts as usize + 1];
                    let f = frame(fc::CLAIM, BROADCAST, self.ts, &pad);
                    self.send(f, St::ClaimListen);
                    // Transmitting the claim (UseToken stands for "sending").
                    self.st = St::UseToken;
                    o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                }
            }
            St::ClaimListen => {
                self.timer += 1;
                if heard {
                    self.in_ring = false;
                    self.st = St::Idle;
                    self.idle = 0;
                } else if self.timer >= SLOT_TIME {
                    o.ev |= ev::WON_CONTENTION;
                    self.in_ring = true;
                    self.ns = self.ts;
                    self.ps = self.ts;
                    self.use_token(hw, &mut o);
                    o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                }
            }
            St::UseToken => {}
            St::CheckTokenPass => {
                if heard {
                    self.st = St::Idle;
                    self.idle = 0;
                } else if self.timer <= 1 {
                    if self.tries == 0 {
                        self.tries = 1;
                        self.pass_token();
                    } else {
                        self.ask(Query::WhoFollows(0));
                    }
                    o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                } else {
                    self.timer -= 1;
                }
            }
            St::AwaitResponse => {
                if let Some(f) = &frame_in {
                    if f.fc == fc::SET_SUCCESSOR && f.da == self.ts && f.data.len() == 1 {
                        let old = self.ns;
                        self.ns = f.data[0];
                        if self.ns != old {
                            o.ev |= match self.query {
                                Query::Solicit1 => ev::HEAR_SUCCESSOR,
                                _ => ev::NEW_SUCCESSOR,
                            };
                        }
                        self.tries = 0;
                        self.pass_token();
                        o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                        return o;
                    }
                }
                // Anything else heard in a response window (noise, another
                // station's frame) means another station holds a token too:
                // drop ours (802.4's duplicate-token rule) and enter the ring
                // again by answering a solicit_successor.
                if frame_in.is_some() || sym::kind(rx) == sym::ERR {
                    self.in_ring = false;
                    self.st = St::Idle;
                    self.idle = 0;
                    return o;
                }
                if self.timer > 1 {
                    self.timer -= 1;
                } else if !self.rx_in {
                    match self.query {
                        Query::Solicit1 => {
                            if self.ns == self.ts {
                                // Alone: keep the token.
                                self.use_token(hw, &mut o);
                            } else {
                                self.tries = 0;
                                self.pass_token();
                            }
                        }
                        Query::WhoFollows(0) => self.ask(Query::WhoFollows(1)),
                        Query::WhoFollows(_) => self.ask(Query::Solicit2(0)),
                        Query::Solicit2(0) => self.ask(Query::Solicit2(1)),
                        Query::Solicit2(_) => {
                            o.ev |= ev::NO_SUCCESSOR_8;
                            self.in_ring = false;
                            self.st = St::Idle;
                            self.idle = 0;
                            return o;
                        }
                    }
                    o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                }
            }
            St::Respond => {
                if heard {
                    self.st = St::Idle;
                    self.idle = 0;
                } else if self.timer <= 1 {
                    let f = std::mem::take(&mut self.resp_frame);
                    (self.ps, self.ns) = self.resp_to;
                    self.in_ring = true;
                    self.send(f, St::Idle);
                    o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
                } else {
                    self.timer -= 1;
                }
            }
        }
        o
    }

    /// A valid frame heard while idle.
    pub(super) fn idle_frame(&mut self, f: &Rx, hw: &RmmOut, o: &mut MacOut) {
        match f.fc {
            fc::TOKEN if f.da == self.ts => {
                self.ps = f.sa;
                self.in_ring = true;
                self.use_token(hw, o);
                o.tx = self.txq.pop_front().unwrap_or(sym::SIL);
            }
            fc::SET_SUCCESSOR
                if f.da == self.ts && f.data.len() == 1 && self.in_ring && self.ns != f.data[0] =>
            {
                // Our successor leaves: its successor follows us.
                self.ns = f.data[0];
                o.ev |= ev::NEW_SUCCESSOR;
            }
            fc::SOLICIT1 if !self.in_ring && !self.leaving => {
                // Stations strictly between the soliciter and its successor.
                let gap = if f.da == f.sa {
                    self.n as u32 - 1
                } else {
                    self.rank(f.sa, f.da)
                };
                let k = self.rank(f.sa, self.ts);
                if k < gap {
                    self.respond(f.sa, f.da, k);
                }
            }
            fc::SOLICIT2 => {
                let k = self.rank(f.sa, self.ts);
                let ns = if self.in_ring { self.ns } else { f.sa };
                self.respond(f.sa, ns, k);
            }
            fc::WHO_FOLLOWS if f.data.len() == 1 && self.in_ring && self.ps == f.data[0] => {
                let ns = self.ns;
                self.respond(f.sa, ns, 0);
                // Our predecessor is now the asker.
            }
            _ => {}
        }
    }

    /// Answers `asker` with set_successor in response window `k`; our new
    /// successor will be `ns`.
    pub(super) fn respond(&mut self, asker: u8, ns: u8, k: u32) {
        self.resp_frame = frame(fc::SET_SUCCESSOR, asker, self.ts, &[self.ts]);
        self.st = St::Respond;
        self.timer = RANK_TICKS * k + 1;
        self.resp_to = (asker, ns);
    }
}
