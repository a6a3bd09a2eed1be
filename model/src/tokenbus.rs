//! The IEEE 802.4 token bus around the redundancy hardware
//! (docs/protocol.md, Part II): N stations, each a token-bus MAC over a
//! Dual Channel Manager and two physical channels (bus cables) that can
//! open, short, lose a station's drop cable or carry noise.
//!
//! Time advances in octet times (ticks). Per tick, in this order:
//! 1. every live station's MAC reads its RMM's outputs (the symbol the DCM
//!    delivered, the status word, the switch command request) and decides
//!    what it transmits and which pulses it gives the RMM;
//! 2. each DCM gates the MAC's symbol (jabber inhibit) onto both PHYs;
//! 3. each channel combines what reaches every station (none → silence,
//!    one → that symbol, more → a collision, `ERR`; noise → `ERR`);
//! 4. every RMM is clocked with its inputs.
//!
//! The RMM behind each station is any [`StationHw`]: the reference model
//! ([`crate::rmm::Rmm`]) for golden traces, the Verilated RTL in the
//! simulation library (`merkur-sim`). The MAC simplifies 802.4 as docs/protocol.md §17 lists.

use crate::rmm::{self, ev, sym, Rmm, RmmConfig, RmmIn, RmmOut};
use crate::tbconfig::{ChanFault, TbConfig, TbEvent};
use std::collections::{BTreeSet, VecDeque};

/// Slot time, octets: the longest wait for a reply.
pub const SLOT_TIME: u32 = 8;
/// Octets between the response windows of successive responders.
pub const RANK_TICKS: u32 = 2;
/// Silent octets after which an idle station claims the token.
pub const BUS_IDLE: u32 = 7 * SLOT_TIME + RANK_TICKS * rmm::MAX_STATIONS as u32;
/// Octets from power-on to the MAC's `initialize` event.
pub const INIT_TICKS: u32 = 4;
/// Token holds between two solicit_successor_1 (while the ring has a gap).
pub const INTER_SOLICIT: u32 = 4;

/// Frame control octets.
pub mod fc {
    /// Token.
    pub const TOKEN: u8 = 0x08;
    /// Claim token.
    pub const CLAIM: u8 = 0x00;
    /// Solicit successor with one response window (stations between TS and NS).
    pub const SOLICIT1: u8 = 0x01;
    /// Solicit successor, any station.
    pub const SOLICIT2: u8 = 0x02;
    /// Who follows (data: the failed successor's address).
    pub const WHO_FOLLOWS: u8 = 0x03;
    /// Set successor (data: the new successor's address).
    pub const SET_SUCCESSOR: u8 = 0x0c;
    /// Application data (data: sequence number, filler).
    pub const DATA: u8 = 0x40;
    /// RMM status frame (data: live counter, status byte).
    pub const STATUS: u8 = 0x41;
    /// RMM channel switch command (data: target channel).
    pub const SWITCH: u8 = 0x42;
}

/// Octets after which a data frame has certainly been delivered (its
/// length plus the DCM's octet).
const FRAME_SETTLE: u64 = 48;

/// Broadcast address.
pub const BROADCAST: u8 = 0xff;

/// Frame check sequence: the complement of the octet sum.
pub fn fcs(octets: &[u8]) -> u8 {
    !octets.iter().fold(0u8, |a, &b| a.wrapping_add(b))
}

/// The symbols of a frame: SD, FC, DA, SA, data, FCS, ED.
pub fn frame(fc: u8, da: u8, sa: u8, data: &[u8]) -> Vec<u16> {
    let mut o = vec![fc, da, sa];
    o.extend_from_slice(data);
    o.push(fcs(&o));
    let mut s = vec![sym::SD];
    s.extend(o.iter().map(|&b| sym::data(b)));
    s.push(sym::ED);
    s
}

/// The redundancy hardware of one station, as the bus drives it.
pub trait StationHw {
    /// Outputs this tick.
    fn out(&mut self) -> RmmOut;
    /// What PHY A and PHY B send for the MAC's symbol this tick.
    fn tx_out(&mut self, tx: u16) -> [u16; 2];
    /// Clocks one tick with these inputs.
    fn clock(&mut self, i: &RmmIn);
}

impl StationHw for Rmm {
    fn out(&mut self) -> RmmOut {
        Rmm::out(self, true)
    }
    fn tx_out(&mut self, tx: u16) -> [u16; 2] {
        let s = Rmm::tx_out(self, tx);
        [s, s]
    }
    fn clock(&mut self, i: &RmmIn) {
        Rmm::clock(self, i)
    }
}

/// MAC states (the numbers of the paper's Table 1 where they exist).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum St {
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
enum Query {
    Solicit1,
    WhoFollows(u8),
    Solicit2(u8),
}

/// A frame the MAC received.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Rx {
    fc: u8,
    da: u8,
    sa: u8,
    data: Vec<u8>,
}

/// One station's token-bus MAC.
#[derive(Debug, Clone)]
struct Mac {
    ts: u8,
    n: u8,
    ns: u8,
    ps: u8,
    in_ring: bool,
    st: St,
    timer: u32,
    tries: u8,
    holds: u32,
    seq: u16,
    data_len: usize,
    txq: VecDeque<u16>,
    after: St,
    query: Query,
    rxbuf: Vec<u8>,
    rx_in: bool,
    idle: u32,
    resp_frame: Vec<u16>,
    /// (asker, our successor) once our set_successor goes out.
    resp_to: (u8, u8),
    leaving: bool,
    babble: u32,
}

/// What a MAC does in one tick.
#[derive(Debug, Default)]
struct MacOut {
    tx: u16,
    ev: u8,
    sf_sent: bool,
    cmd_sent: bool,
    rx_sf: Option<(u8, u16)>,
    cmd_rx: Option<bool>,
    data_rx: Option<(u8, u16)>,
    data_tx: Option<u16>,
}

impl Mac {
    fn new(ts: u8, n: u8, data_len: usize) -> Mac {
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
    fn rank(&self, from: u8, a: u8) -> u32 {
        (from as u32 + self.n as u32 - a as u32 - 1) % self.n as u32
    }

    /// Addresses strictly between TS and NS going down (all others when alone).
    fn gap(&self) -> u32 {
        if self.ns == self.ts {
            self.n as u32 - 1
        } else {
            self.rank(self.ts, self.ns)
        }
    }

    fn send(&mut self, f: Vec<u16>, after: St) {
        if !self.txq.is_empty() {
            self.txq.push_back(sym::SIL);
        }
        self.txq.extend(f);
        self.after = after;
    }

    /// Receives one delivered symbol; a complete valid frame is returned.
    fn receive(&mut self, s: u16) -> Option<Rx> {
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

    fn pass_token(&mut self) {
        let f = frame(fc::TOKEN, self.ns, self.ts, &[]);
        self.send(f, St::CheckTokenPass);
    }

    fn ask(&mut self, q: Query) {
        self.query = q;
        let f = match q {
            Query::Solicit1 => frame(fc::SOLICIT1, self.ns, self.ts, &[]),
            Query::WhoFollows(_) => frame(fc::WHO_FOLLOWS, BROADCAST, self.ts, &[self.ns]),
            Query::Solicit2(_) => frame(fc::SOLICIT2, BROADCAST, self.ts, &[]),
        };
        self.send(f, St::AwaitResponse);
    }

    /// The response window of a query this station was asked.
    fn window(&self, q: Query) -> u32 {
        match q {
            Query::Solicit1 => RANK_TICKS * self.gap() + SLOT_TIME,
            Query::WhoFollows(_) => SLOT_TIME,
            Query::Solicit2(_) => RANK_TICKS * (self.n as u32 - 1) + SLOT_TIME,
        }
    }

    /// Starts a token hold: queued RMM frames, one data frame, then a
    /// solicit or the token pass.
    fn use_token(&mut self, hw: &RmmOut, o: &mut MacOut) {
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

    /// One tick. `rx` is the symbol the DCM delivers.
    fn step(&mut self, hw: &RmmOut) -> MacOut {
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
    fn idle_frame(&mut self, f: &Rx, hw: &RmmOut, o: &mut MacOut) {
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
    fn respond(&mut self, asker: u8, ns: u8, k: u32) {
        self.resp_frame = frame(fc::SET_SUCCESSOR, asker, self.ts, &[self.ts]);
        self.st = St::Respond;
        self.timer = RANK_TICKS * k + 1;
        self.resp_to = (asker, ns);
    }
}

/// Channel state.
#[derive(Debug, Clone, Default)]
struct Channel {
    short: bool,
    opens: BTreeSet<u8>,
    drops: BTreeSet<u8>,
    noise_until: u64,
}

impl Channel {
    fn connected(&self, r: usize, s: usize) -> bool {
        let (lo, hi) = (r.min(s), r.max(s));
        !self.short
            && !self.drops.contains(&(r as u8))
            && !self.drops.contains(&(s as u8))
            && !self
                .opens
                .iter()
                .any(|&p| lo < p as usize && p as usize <= hi)
    }
}

/// A change seen in a run, in the golden trace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Change {
    /// Tick.
    pub t: u64,
    /// Station.
    pub station: usize,
    /// What changed.
    pub what: String,
}

/// The result of a run.
#[derive(Debug, Clone, Default)]
pub struct TbRun {
    /// Changes in order (the body of the golden trace).
    pub changes: Vec<Change>,
    /// Every station's RMM outputs every tick (`None` while powered off).
    pub outs: Vec<Vec<Option<RmmOut>>>,
    /// Data frames sent.
    pub frames_sent: u64,
    /// (frame, live receiver) pairs expected.
    pub receptions_expected: u64,
    /// Of those, not received.
    pub receptions_lost: u64,
    /// Frames lost per fault window (fault index → receptions lost while it
    /// was the last fault injected).
    pub lost_by_fault: Vec<u64>,
    /// Per fault: every station's first channel switch after it (while it
    /// is the last fault injected), as (station, octets after the fault).
    pub switches: Vec<Vec<(usize, u64)>>,
}

impl TbRun {
    /// Octets from fault `f` to the first and to the last station's first
    /// channel switch, and how many stations switched.
    pub fn switch_latency(&self, f: usize) -> Option<(u64, u64, usize)> {
        let s = &self.switches[f];
        let first = s.iter().map(|x| x.1).min()?;
        let last = s.iter().map(|x| x.1).max()?;
        Some((first, last, s.len()))
    }
}

/// Runs a scenario with the RMM of every station made by `hw` (called at
/// every power-on of a station with its configuration).
pub fn run_with(
    cfg: &TbConfig,
    hw: &mut dyn FnMut(RmmConfig) -> Result<Box<dyn StationHw>, String>,
    record_outs: bool,
) -> Result<TbRun, String> {
    let n = cfg.stations;
    let stations_mask = if n == 32 { u32::MAX } else { (1u32 << n) - 1 };
    let rcfg = |k: usize| RmmConfig {
        addr: k as u8,
        stations: stations_mask,
        sf_period: cfg.sf_period,
        check_period: cfg.check_period,
        good_limit: cfg.good_limit,
    };
    let mut macs: Vec<Option<Mac>> = vec![];
    let mut hws: Vec<Option<Box<dyn StationHw>>> = vec![];
    for k in 0..n {
        macs.push(Some(Mac::new(k as u8, n as u8, cfg.data_len)));
        hws.push(Some(hw(rcfg(k))?));
    }
    let mut chans = [Channel::default(), Channel::default()];
    let mut run = TbRun {
        outs: vec![vec![]; n],
        lost_by_fault: vec![0; cfg.events.len()],
        switches: vec![vec![]; cfg.events.len()],
        ..TbRun::default()
    };
    let mut init = vec![false; n];
    let mut prev: Vec<Option<RmmOut>> = vec![None; n];
    // Data frames in flight: (sender, seq) → receivers expected.
    let mut pending: Vec<(usize, u16, u64, Vec<bool>)> = vec![];
    let mut received: Vec<BTreeSet<(usize, u16)>> = vec![BTreeSet::new(); n];
    let mut ev_i = 0;
    let mut last_fault: Option<usize> = None;
    for t in 0..cfg.ticks {
        // Scenario events at this tick.
        let mut auto_now = vec![false; n];
        while ev_i < cfg.events.len() && cfg.events[ev_i].at == t {
            let e = &cfg.events[ev_i];
            match &e.what {
                TbEvent::Chan(c, f) => {
                    let ch = &mut chans[*c as usize];
                    match f {
                        ChanFault::Short => ch.short = true,
                        ChanFault::Open(p) => {
                            ch.opens.insert(*p);
                        }
                        ChanFault::Drop(s) => {
                            ch.drops.insert(*s);
                        }
                        ChanFault::Noise(d) => ch.noise_until = t + *d as u64,
                        ChanFault::Repair => *ch = Channel::default(),
                    }
                }
                TbEvent::Kill(s) => {
                    macs[*s] = None;
                    hws[*s] = None;
                    init[*s] = false;
                }
                TbEvent::Restart(s) => {
                    if macs[*s].is_none() {
                        macs[*s] = Some(Mac::new(*s as u8, n as u8, cfg.data_len));
                        hws[*s] = Some(hw(rcfg(*s))?);
                    }
                }
                TbEvent::Leave(s) => {
                    if let Some(m) = macs[*s].as_mut() {
                        m.leaving = true;
                    }
                }
                TbEvent::Babble(s, d) => {
                    if let Some(m) = macs[*s].as_mut() {
                        m.babble = *d;
                    }
                }
                TbEvent::Auto(None) => auto_now.fill(true),
                TbEvent::Auto(Some(s)) => auto_now[*s] = true,
            }
            if e.what.is_fault() {
                last_fault = Some(ev_i);
            }
            run.changes.push(Change {
                t,
                station: usize::MAX,
                what: format!("inject {}", e.what),
            });
            ev_i += 1;
        }
        // 1. MACs.
        let alive: Vec<bool> = macs.iter().map(|m| m.is_some()).collect();
        let mut ins = vec![RmmIn::default(); n];
        let mut txs = vec![sym::SIL; n];
        let mut outs: Vec<Option<RmmOut>> = vec![None; n];
        for k in 0..n {
            let (Some(mac), Some(h)) = (macs[k].as_mut(), hws[k].as_mut()) else {
                continue;
            };
            let o = h.out();
            outs[k] = Some(o);
            let mut m = mac.step(&o);
            if mac.babble > 0 {
                mac.babble -= 1;
                m.tx = sym::ERR;
            }
            if m.ev & ev::INITIALIZE != 0 {
                init[k] = true;
            }
            txs[k] = m.tx;
            let i = &mut ins[k];
            i.tx = m.tx;
            i.ev = m.ev;
            i.sf_sent = m.sf_sent;
            i.cmd_sent = m.cmd_sent;
            if let Some((sa, w)) = m.rx_sf {
                i.rx_sf = true;
                i.rx_sa = sa;
                i.rx_sfw = w;
            }
            if let Some(c) = m.cmd_rx {
                i.cmd_rx = true;
                i.cmd_ch = c;
            }
            i.init = init[k];
            i.auto = auto_now[k];
            i.host_ok = true;
            // The network manager reads the stored status frames in turn.
            i.nm_addr = (t % n as u64) as u8;
            if let Some((sa, seq)) = m.data_rx {
                received[k].insert((sa as usize, seq));
            }
            if let Some(seq) = m.data_tx {
                run.frames_sent += 1;
                pending.push((k, seq, t, alive.clone()));
            }
            for b in 0..6 {
                if m.ev >> b & 1 == 1 {
                    run.changes.push(Change {
                        t,
                        station: k,
                        what: format!("mac {}", ev::NAMES[b]),
                    });
                }
            }
        }
        // 2. DCM transmit gating, 3. channels.
        let mut on_air = vec![[sym::SIL; 2]; n];
        for k in 0..n {
            if let Some(h) = hws[k].as_mut() {
                on_air[k] = h.tx_out(txs[k]);
            }
        }
        for (c, ch) in chans.iter().enumerate() {
            for r in 0..n {
                if hws[r].is_none() {
                    continue;
                }
                let s = if t < ch.noise_until {
                    sym::ERR
                } else {
                    let mut heard = sym::SIL;
                    let mut count = 0;
                    for (s, x) in on_air.iter().enumerate() {
                        let x = x[c];
                        if s != r && x != sym::SIL && ch.connected(r, s) {
                            count += 1;
                            heard = x;
                        }
                    }
                    if count > 1 {
                        sym::ERR
                    } else {
                        heard
                    }
                };
                if c == 0 {
                    ins[r].rx_a = s;
                } else {
                    ins[r].rx_b = s;
                }
            }
        }
        // 4. RMMs.
        for k in 0..n {
            if let Some(h) = hws[k].as_mut() {
                h.clock(&ins[k]);
            }
        }
        // Record.
        for k in 0..n {
            let o = outs[k];
            if record_outs {
                run.outs[k].push(o);
            }
            log_changes(&mut run, t, k, prev[k].as_ref(), o.as_ref());
            if let (Some(p), Some(o), Some(f)) = (prev[k], o, last_fault) {
                if p.act != o.act && !run.switches[f].iter().any(|x| x.0 == k) {
                    run.switches[f].push((k, t - cfg.events[f].at));
                }
            }
            prev[k] = o;
        }
    }
    // Settle every data frame: each receiver powered when it was sent should
    // have it (frames still on the bus at the end are not counted).
    let frame_len = (cfg.data_len + 6) as u64;
    for (s, seq, sent, alive) in pending {
        if sent + FRAME_SETTLE > cfg.ticks {
            run.frames_sent -= 1;
            continue;
        }
        // A loss counts against the last fault injected before the frame ended.
        let f = cfg
            .events
            .iter()
            .rposition(|e| e.what.is_fault() && e.at <= sent + frame_len)
            .unwrap_or(usize::MAX);
        for (r, &a) in alive.iter().enumerate() {
            if r == s || !a {
                continue;
            }
            run.receptions_expected += 1;
            if !received[r].contains(&(s, seq)) {
                run.receptions_lost += 1;
                if f != usize::MAX {
                    run.lost_by_fault[f] += 1;
                }
            }
        }
    }
    Ok(run)
}

fn log_changes(run: &mut TbRun, t: u64, k: usize, p: Option<&RmmOut>, o: Option<&RmmOut>) {
    let mut push = |what: String| {
        run.changes.push(Change {
            t,
            station: k,
            what,
        })
    };
    match (p, o) {
        (_, None) => {
            if p.is_some() {
                push("power off".into());
            }
        }
        (None, Some(o)) => {
            push(format!(
                "power on state {} act {}",
                rmm::state::name(o.state),
                if o.act { 'B' } else { 'A' }
            ));
        }
        (Some(p), Some(o)) => {
            if p.state != o.state {
                push(format!(
                    "state {} -> {} ({})",
                    rmm::state::name(p.state),
                    rmm::state::name(o.state),
                    rmm::cause::name(o.cause)
                ));
            } else if o.irq && o.stale & !p.stale == 0 {
                push(format!("report {}", rmm::cause::name(o.cause)));
            }
            if p.act != o.act {
                push(format!("active {}", if o.act { 'B' } else { 'A' }));
            }
            for (c, (ps, os)) in [('A', (p.stat_a, o.stat_a)), ('B', (p.stat_b, o.stat_b))] {
                if ps & 1 != os & 1 {
                    push(format!(
                        "channel {c} {}",
                        if os & 1 == 1 { "bad" } else { "good" }
                    ));
                }
                if ps >> 2 & 1 != os >> 2 & 1 && c == 'A' {
                    push(format!("jabber {}", os >> 2 & 1));
                }
            }
            if p.stale != o.stale {
                push(format!("stale {:08x}", o.stale));
            }
            if o.chk_ok && !p.chk_ok {
                push("status check ok".into());
            }
            if o.chk_sw && !p.chk_sw {
                push(format!(
                    "status check switch (active {} suspect)",
                    if o.act { 'B' } else { 'A' }
                ));
            }
            if o.cmd_req && !p.cmd_req {
                push(format!(
                    "switch command to {}",
                    if o.cmd_ch { 'B' } else { 'A' }
                ));
            }
        }
    }
}

/// Runs a scenario through the reference model.
pub fn run(cfg: &TbConfig) -> TbRun {
    run_with(cfg, &mut |c| Ok(Box::new(Rmm::new(c))), true)
        .expect("the reference model is always constructible")
}

/// Renders the golden trace of a token-bus run (docs/traces.md).
pub fn render(cfg: &TbConfig, source: &str, r: &TbRun) -> String {
    use std::fmt::Write;
    let mut o = String::new();
    let _ = writeln!(o, "# merkur token-bus golden trace");
    let _ = writeln!(o, "# format 1");
    let _ = writeln!(o, "# generator merkur-model {}", env!("CARGO_PKG_VERSION"));
    let _ = writeln!(o, "# scenario {}", cfg.name);
    let _ = writeln!(
        o,
        "# scenario-sha256 {}",
        crate::trace::scenario_hash(source)
    );
    let _ = writeln!(
        o,
        "# stations {} ticks {} data_len {} sf_period {} check_period {} good_limit {}",
        cfg.stations, cfg.ticks, cfg.data_len, cfg.sf_period, cfg.check_period, cfg.good_limit
    );
    for c in &r.changes {
        if c.station == usize::MAX {
            let _ = writeln!(o, "{} - {}", c.t, c.what);
        } else {
            let _ = writeln!(o, "{} {} {}", c.t, c.station, c.what);
        }
    }
    let _ = writeln!(
        o,
        "summary frames_sent {} receptions_expected {} receptions_lost {}",
        r.frames_sent, r.receptions_expected, r.receptions_lost
    );
    for (k, e) in cfg.events.iter().enumerate() {
        if e.what.is_fault() {
            let lat = match r.switch_latency(k) {
                None => "no station switched".to_string(),
                Some((a, b, n)) => format!("{n} stations switched after {a}..{b} octets"),
            };
            let _ = writeln!(
                o,
                "fault {} at {} ({}): {lat}, receptions lost {}",
                e.what,
                e.at,
                e.what.class(),
                r.lost_by_fault[k]
            );
        }
    }
    o
}
