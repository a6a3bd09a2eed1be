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

mod mac;
mod report;
use mac::*;
pub use report::*;

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

impl Mac {}

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

/// Runs a scenario with the RMM of every station made by `hw` (called at
/// every power-on of a station with its configuration).
///
/// One loop of about 230 lines: the four steps of a tick (the module doc)
/// in their order, on state they all share (the stations, the channels,
/// the frames in flight, the log of changes).
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

/// Runs a scenario through the reference model.
pub fn run(cfg: &TbConfig) -> TbRun {
    run_with(cfg, &mut |c| Ok(Box::new(Rmm::new(c))), true)
        .expect("the reference model is always constructible")
}
