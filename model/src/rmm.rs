//! Reference model of one station's IEEE 802.4 redundancy hardware
//! (docs/protocol.md, Part II): the Dual Channel Manager (DCM) and the
//! Redundancy Management Module (RMM: fault detection, status frame
//! production, status frame check, fault correction machine).
//!
//! It is written as the register transfer the RTL must equal, one call of
//! [`Rmm::clock`] per octet time: every output is either a register or a
//! documented function of registers and the current inputs. The token bus
//! around it ([`crate::tokenbus`]) is what makes its inputs.

/// Symbol kinds on the octet-wide PHY interface (bits 10:8 of a symbol).
pub mod sym {
    /// Silence: no carrier.
    pub const SIL: u16 = 0;
    /// Start delimiter.
    pub const SD: u16 = 1 << 8;
    /// A data octet: `DATA | byte`.
    pub const DATA: u16 = 2 << 8;
    /// End delimiter.
    pub const ED: u16 = 3 << 8;
    /// Noise, a collision or an invalid symbol (framing error).
    pub const ERR: u16 = 4 << 8;
    /// Kind bits of a symbol.
    pub fn kind(s: u16) -> u16 {
        s & 0x700
    }
    /// A data octet symbol.
    pub fn data(b: u8) -> u16 {
        DATA | b as u16
    }
    /// SD, DATA or ED: part of a frame.
    pub fn is_frame(s: u16) -> bool {
        matches!(kind(s), SD | DATA | ED)
    }
}

/// Consecutive silent octets after which a channel counts as silent
/// (longer than the token bus's longest legal silence plus one claim).
pub const SIL_LIMIT: u16 = 136;
/// Consecutive transmitted (non-silent) octets after which the DCM's jabber
/// inhibit cuts both transmitters (longer than the longest frame, 69 octets).
pub const JABBER_LIMIT: u16 = 128;
/// Most stations (addresses 0..=31).
pub const MAX_STATIONS: usize = 32;

/// Fault correction machine states (the paper's Figure 4).
pub mod state {
    /// Power off, or both channels faulty.
    pub const IDLE: u8 = 0;
    /// Dual mode off: the active channel is not changed on a fault.
    pub const MANUAL_NORMAL: u8 = 1;
    /// Dual mode on: a fault of the active channel switches channels.
    pub const AUTO_NORMAL: u8 = 2;
    /// SC event in Auto_Normal: broadcasting the channel switch command.
    pub const CONFIG_ERROR: u8 = 3;
    /// The active channel failed (or NS): switched to the standby channel.
    pub const MEDIUM_ERROR: u8 = 4;
    /// Name in traces.
    pub fn name(s: u8) -> &'static str {
        match s {
            IDLE => "IDLE",
            MANUAL_NORMAL => "Manual_Normal",
            AUTO_NORMAL => "Auto_Normal",
            CONFIG_ERROR => "Config_Error",
            MEDIUM_ERROR => "Medium_Error",
            _ => "?",
        }
    }
}

/// Causes written to the report register with every transition or command.
pub mod cause {
    /// Nothing yet.
    pub const NONE: u8 = 0;
    /// Initialisation finished (IDLE → Manual_Normal).
    pub const INIT: u8 = 1;
    /// Status Check = OK (Manual_Normal → Auto_Normal).
    pub const CHECK_OK: u8 = 2;
    /// AUTO_SW_MODE host command (Manual_Normal → Auto_Normal).
    pub const AUTO_CMD: u8 = 3;
    /// Fault of the active channel (Auto_Normal → Medium_Error).
    pub const ACTIVE_FAULT: u8 = 4;
    /// NS event (Auto_Normal → Medium_Error).
    pub const NS: u8 = 5;
    /// Fault of the standby channel (→ Manual_Normal).
    pub const STANDBY_FAULT: u8 = 6;
    /// SC event (Auto_Normal → Config_Error).
    pub const SC: u8 = 7;
    /// Switch command received (→ Manual_Normal).
    pub const CMD_RX: u8 = 8;
    /// Own switch command sent (Config_Error → Manual_Normal).
    pub const CMD_SENT: u8 = 9;
    /// Switch done (Medium_Error → Manual_Normal).
    pub const SWITCHED: u8 = 10;
    /// Both channels faulty (→ IDLE).
    pub const BOTH: u8 = 11;
    /// Status Check = SWITCH (→ Manual_Normal, switch between frames).
    pub const CHECK_SW: u8 = 12;
    /// Name in traces.
    pub fn name(c: u8) -> &'static str {
        [
            "none",
            "init",
            "check_ok",
            "auto_cmd",
            "active_fault",
            "ns",
            "standby_fault",
            "sc",
            "cmd_rx",
            "cmd_sent",
            "switched",
            "both",
            "check_sw",
        ]
        .get(c as usize)
        .copied()
        .unwrap_or("?")
    }
}

/// The six MAC events (bit positions of [`RmmIn::ev`]).
pub mod ev {
    /// new_successor (SC).
    pub const NEW_SUCCESSOR: u8 = 1 << 0;
    /// won_contention (SC).
    pub const WON_CONTENTION: u8 = 1 << 1;
    /// hear_successor (SC).
    pub const HEAR_SUCCESSOR: u8 = 1 << 2;
    /// initialize (NS).
    pub const INITIALIZE: u8 = 1 << 3;
    /// exit_ring (NS).
    pub const EXIT_RING: u8 = 1 << 4;
    /// no_successor_8 (NS).
    pub const NO_SUCCESSOR_8: u8 = 1 << 5;
    /// Events that make SC.
    pub const SC_MASK: u8 = 0b000111;
    /// Events that make NS.
    pub const NS_MASK: u8 = 0b111000;
    /// Names by bit.
    pub const NAMES: [&str; 6] = [
        "new_successor",
        "won_contention",
        "hear_successor",
        "initialize",
        "exit_ring",
        "no_successor_8",
    ];
}

/// Static configuration of a station's RMM (ports in the RTL).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RmmConfig {
    /// Own address, 0..=31.
    pub addr: u8,
    /// Stations expected on the bus (bit i: address i).
    pub stations: u32,
    /// Status frame production period, octets (≥ 2).
    pub sf_period: u16,
    /// Status check period, octets (≥ 40: a scan takes 34).
    pub check_period: u16,
    /// Fault-free octets after which a faulty channel counts as good again.
    pub good_limit: u16,
}

/// Inputs of one octet time.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RmmIn {
    /// Symbol from PHY A.
    pub rx_a: u16,
    /// Symbol from PHY B.
    pub rx_b: u16,
    /// Symbol the MAC transmits.
    pub tx: u16,
    /// MAC events (pulses, [`ev`]).
    pub ev: u8,
    /// The MAC took the status word into a status frame.
    pub sf_sent: bool,
    /// A valid status frame was received.
    pub rx_sf: bool,
    /// Its source address.
    pub rx_sa: u8,
    /// Its two status bytes (live counter << 8 | status).
    pub rx_sfw: u16,
    /// A valid channel switch command was received.
    pub cmd_rx: bool,
    /// Its target channel (false A, true B).
    pub cmd_ch: bool,
    /// The MAC took our switch command into a frame.
    pub cmd_sent: bool,
    /// Host: initialisation finished (level).
    pub init: bool,
    /// Host: AUTO_SW_MODE command (pulse).
    pub auto: bool,
    /// Host status bit for the status frame (level).
    pub host_ok: bool,
    /// Network manager: station whose stored status frame to read.
    pub nm_addr: u8,
}

/// Registered outputs (and the status word) of one octet time.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RmmOut {
    /// Symbol delivered to the MAC (the active channel, one octet late).
    pub rx: u16,
    /// Active channel (false A, true B).
    pub act: bool,
    /// Fault correction state ([`state`]).
    pub state: u8,
    /// Cause of the last transition or command ([`cause`]).
    pub cause: u8,
    /// Report interrupt (one octet per report).
    pub irq: bool,
    /// A status frame is due.
    pub sf_pend: bool,
    /// Status word: live counter << 8 | status byte.
    pub sf_word: u16,
    /// Broadcast the channel switch command.
    pub cmd_req: bool,
    /// Its target channel.
    pub cmd_ch: bool,
    /// Status register of channel A (err count << 8 | carrier << 3 | jabber << 2 | silent << 1 | bad).
    pub stat_a: u16,
    /// Status register of channel B.
    pub stat_b: u16,
    /// Stations whose live counter stopped (bit per address).
    pub stale: u32,
    /// Status check = OK (pulse at the end of a scan).
    pub chk_ok: bool,
    /// Status check = SWITCH (pulse at the end of a scan, §20).
    pub chk_sw: bool,
    /// MAC events seen (sticky).
    pub ev_seen: u8,
    /// The stored status frame read for the network manager (or by the scan).
    pub nm_word: u16,
    /// `nm_word` is the station `nm_addr` asked for (no scan running).
    pub nm_valid: bool,
}

#[derive(Debug, Clone, Copy, Default)]
struct Chan {
    sil: u16,
    good: u16,
    bad: bool,
    err: u8,
    carrier: bool,
}

/// One station's DCM + RMM.
#[derive(Debug, Clone)]
pub struct Rmm {
    cfg: RmmConfig,
    // DCM
    act: bool,
    rx: u16,
    in_frame: bool,
    tx_cnt: u16,
    ch: [Chan; 2],
    // fault detection
    ev_seen: u8,
    // status frame production
    sf_cnt: u16,
    live: u8,
    sf_pend: bool,
    // status frame check
    st_mem: Vec<u16>,
    prev_mem: Vec<u8>,
    chk_cnt: u16,
    scanning: bool,
    scan_i: u8,
    s2_valid: bool,
    s2_i: u8,
    st_rd: u16,
    prev_rd: u8,
    all_ok: bool,
    /// Per channel: a fresh station of this scan reported it not good.
    any_bad: [bool; 2],
    stale: u32,
    chk_ok: bool,
    chk_sw: bool,
    nm_valid: bool,
    // fault correction machine
    state: u8,
    cause: u8,
    irq: bool,
    pend: bool,
    pend_ch: bool,
    cmd_req: bool,
    cmd_ch: bool,
}

impl Rmm {
    /// Power-up state: every register and both memories zero.
    pub fn new(cfg: RmmConfig) -> Rmm {
        Rmm {
            cfg,
            act: false,
            rx: sym::SIL,
            in_frame: false,
            tx_cnt: 0,
            ch: [Chan::default(); 2],
            ev_seen: 0,
            sf_cnt: 0,
            live: 0,
            sf_pend: false,
            st_mem: vec![0; MAX_STATIONS],
            prev_mem: vec![0; MAX_STATIONS],
            chk_cnt: 0,
            scanning: false,
            scan_i: 0,
            s2_valid: false,
            s2_i: 0,
            st_rd: 0,
            prev_rd: 0,
            all_ok: false,
            any_bad: [false; 2],
            stale: 0,
            chk_ok: false,
            chk_sw: false,
            nm_valid: false,
            state: state::IDLE,
            cause: cause::NONE,
            irq: false,
            pend: false,
            pend_ch: false,
            cmd_req: false,
            cmd_ch: false,
        }
    }

    /// The jabber inhibit is on.
    fn jabber(&self) -> bool {
        self.tx_cnt == JABBER_LIMIT
    }

    /// What both PHYs transmit for the MAC's symbol `tx` this octet time
    /// (combinational: silence while the jabber inhibit is on).
    pub fn tx_out(&self, tx: u16) -> u16 {
        if self.jabber() {
            sym::SIL
        } else {
            tx
        }
    }

    fn stat(&self, c: usize) -> u16 {
        let h = &self.ch[c];
        (h.err as u16) << 8
            | (h.carrier as u16) << 3
            | (self.jabber() as u16) << 2
            | ((h.sil == SIL_LIMIT) as u16) << 1
            | h.bad as u16
    }

    /// The status byte of the status frame.
    fn status_byte(&self, host_ok: bool) -> u8 {
        (self.act as u8) << 7
            | (self.state & 7) << 4
            | ((self.state == state::AUTO_NORMAL) as u8) << 3
            | (!self.ch[1].bad as u8) << 2
            | (!self.ch[0].bad as u8) << 1
            | host_ok as u8
    }

    /// Outputs this octet time (`host_ok` is the current host input).
    pub fn out(&self, host_ok: bool) -> RmmOut {
        RmmOut {
            rx: self.rx,
            act: self.act,
            state: self.state,
            cause: self.cause,
            irq: self.irq,
            sf_pend: self.sf_pend,
            sf_word: (self.live as u16) << 8 | self.status_byte(host_ok) as u16,
            cmd_req: self.cmd_req,
            cmd_ch: self.cmd_ch,
            stat_a: self.stat(0),
            stat_b: self.stat(1),
            stale: self.stale,
            chk_ok: self.chk_ok,
            chk_sw: self.chk_sw,
            ev_seen: self.ev_seen,
            nm_word: self.st_rd,
            nm_valid: self.nm_valid,
        }
    }

    /// One octet time: computes every register's next value from the
    /// registers and `i`, then updates them all (docs/protocol.md §18–§21).
    ///
    /// One function of about 250 lines, as the RTL's `update` it is
    /// checked against octet for octet: every next value in the order of
    /// the hardware blocks (DCM, fault detection, status frame check, fault
    /// correction machine), so that model and RTL read side by side.
    pub fn clock(&mut self, i: &RmmIn) {
        let cfg = self.cfg;
        // --- DCM: per-channel supervision (combinational) ---
        let rx = [i.rx_a, i.rx_b];
        let mut fault = [false; 2];
        let mut next_ch = self.ch;
        for c in 0..2 {
            let (me, other) = (rx[c], rx[1 - c]);
            let div = sym::is_frame(other) && me != other;
            let h = &self.ch[c];
            fault[c] = div || h.sil == SIL_LIMIT;
            let n = &mut next_ch[c];
            n.sil = if me == sym::SIL {
                (h.sil + 1).min(SIL_LIMIT)
            } else {
                0
            };
            n.good = if fault[c] {
                0
            } else if h.good >= cfg.good_limit {
                cfg.good_limit
            } else {
                h.good + 1
            };
            n.bad = fault[c] || (h.bad && n.good != cfg.good_limit);
            n.err = if sym::kind(me) == sym::ERR {
                h.err.saturating_add(1)
            } else {
                h.err
            };
            n.carrier = me != sym::SIL;
        }
        let a = self.act as usize;
        let (f_act, f_stb) = (fault[a], fault[1 - a]);
        let (b_stb, both) = (self.ch[1 - a].bad, self.ch[0].bad && self.ch[1].bad);
        // --- fault detection ---
        let sc = i.ev & ev::SC_MASK != 0;
        let ns = i.ev & ev::NS_MASK != 0;
        // --- fault correction machine ---
        let mut st = self.state;
        let mut cs: Option<u8> = None;
        let mut sw_now = false;
        let mut pend = self.pend;
        let mut pend_ch = self.pend_ch;
        let mut cmd_req = self.cmd_req;
        let mut cmd_ch = self.cmd_ch;
        // The deferred (commanded) switch: between frames, not in the octet
        // of a fault switch.
        let mut sw_cmd = false;
        if self.state != state::IDLE && both {
            st = state::IDLE;
            cs = Some(cause::BOTH);
            pend = false;
            cmd_req = false;
        } else {
            match self.state {
                state::IDLE if i.init && !both => {
                    st = state::MANUAL_NORMAL;
                    cs = Some(cause::INIT);
                }
                state::MANUAL_NORMAL => {
                    if i.cmd_rx {
                        pend = true;
                        pend_ch = i.cmd_ch;
                        cs = Some(cause::CMD_RX);
                    } else if self.chk_ok {
                        st = state::AUTO_NORMAL;
                        cs = Some(cause::CHECK_OK);
                    } else if i.auto {
                        st = state::AUTO_NORMAL;
                        cs = Some(cause::AUTO_CMD);
                    } else if self.chk_sw {
                        pend = true;
                        pend_ch = !self.act;
                        cs = Some(cause::CHECK_SW);
                    }
                }
                state::AUTO_NORMAL => {
                    if f_act || ns {
                        if f_stb || b_stb {
                            st = state::MANUAL_NORMAL;
                            cs = Some(cause::STANDBY_FAULT);
                        } else {
                            st = state::MEDIUM_ERROR;
                            sw_now = true;
                            cs = Some(if f_act {
                                cause::ACTIVE_FAULT
                            } else {
                                cause::NS
                            });
                        }
                    } else if f_stb || b_stb {
                        st = state::MANUAL_NORMAL;
                        cs = Some(cause::STANDBY_FAULT);
                    } else if sc {
                        st = state::CONFIG_ERROR;
                        cs = Some(cause::SC);
                        cmd_req = true;
                        cmd_ch = !self.act;
                    } else if i.cmd_rx {
                        st = state::MANUAL_NORMAL;
                        pend = true;
                        pend_ch = i.cmd_ch;
                        cs = Some(cause::CMD_RX);
                    } else if self.chk_sw {
                        st = state::MANUAL_NORMAL;
                        pend = true;
                        pend_ch = !self.act;
                        cs = Some(cause::CHECK_SW);
                    }
                }
                state::MEDIUM_ERROR => {
                    st = state::MANUAL_NORMAL;
                    cs = Some(cause::SWITCHED);
                }
                state::CONFIG_ERROR => {
                    if i.cmd_rx {
                        st = state::MANUAL_NORMAL;
                        cmd_req = false;
                        pend = true;
                        pend_ch = i.cmd_ch;
                        cs = Some(cause::CMD_RX);
                    } else if i.cmd_sent {
                        st = state::MANUAL_NORMAL;
                        cmd_req = false;
                        pend = true;
                        pend_ch = self.cmd_ch;
                        cs = Some(cause::CMD_SENT);
                    }
                }
                _ => {}
            }
        }
        if self.pend && !self.in_frame && !sw_now {
            sw_cmd = self.pend_ch != self.act;
            // A new command this octet replaces the one just carried out.
            let new_cmd = matches!(cs, Some(cause::CMD_RX | cause::CMD_SENT | cause::CHECK_SW));
            if !new_cmd {
                pend = false;
            }
        }
        let act = self.act ^ (sw_now || sw_cmd);
        let delivered = rx[act as usize];
        // --- status frame production ---
        let sf_due = self.sf_cnt + 1 >= cfg.sf_period;
        let sf_cnt = if sf_due { 0 } else { self.sf_cnt + 1 };
        let live = self.live.wrapping_add(sf_due as u8);
        let sf_pend = sf_due || (self.sf_pend && !i.sf_sent);
        // --- status frame check ---
        let chk_start = self.chk_cnt + 1 >= cfg.check_period;
        let chk_cnt = if chk_start { 0 } else { self.chk_cnt + 1 };
        let (scanning, scan_i) = if chk_start {
            (true, 0)
        } else if self.scanning {
            (self.scan_i != 31, (self.scan_i + 1) & 31)
        } else {
            (false, self.scan_i)
        };
        // Between scans the network manager reads the status memory.
        let st_rd = if self.scanning {
            self.st_mem[self.scan_i as usize]
        } else {
            self.st_mem[(i.nm_addr & 31) as usize]
        };
        let prev_rd = self.prev_mem[self.scan_i as usize];
        let own_good = !self.ch[0].bad && !self.ch[1].bad;
        let mut stale = self.stale;
        let mut all_ok = self.all_ok;
        let mut any_bad = self.any_bad;
        let mut chk_ok = false;
        let mut chk_sw = false;
        let mut prev_write: Option<(usize, u8)> = None;
        if self.s2_valid {
            let k = self.s2_i as usize;
            let member = cfg.stations >> k & 1 == 1 && k != cfg.addr as usize;
            let live_k = (self.st_rd >> 8) as u8;
            let stale_k = member && live_k == self.prev_rd;
            let good_k = !member || (!stale_k && self.st_rd & 0b110 == 0b110);
            if member {
                prev_write = Some((k, live_k));
            }
            stale = stale & !(1 << k) | (stale_k as u32) << k;
            all_ok = if k == 0 {
                good_k
            } else {
                self.all_ok && good_k
            };
            chk_ok = k == 31 && all_ok && own_good;
            // §20 Status Check = SWITCH: what fresh stations report.
            let fresh = member && !stale_k;
            for (c, bit) in [(0, 0b010), (1, 0b100)] {
                let bad_c = fresh && self.st_rd & bit == 0;
                any_bad[c] = bad_c || (k != 0 && self.any_bad[c]);
            }
            let (a, s) = (self.act as usize, 1 - self.act as usize);
            let suspect = self.ch[a].bad || any_bad[a];
            let clear = !self.ch[s].bad && !any_bad[s];
            chk_sw = k == 31 && suspect && clear;
        }
        let stale_rise = stale & !self.stale != 0;
        // --- commit ---
        if i.rx_sf && (i.rx_sa as usize) < MAX_STATIONS {
            self.st_mem[i.rx_sa as usize] = i.rx_sfw;
        }
        if let Some((k, v)) = prev_write {
            self.prev_mem[k] = v;
        }
        self.ch = next_ch;
        self.in_frame = match sym::kind(delivered) {
            sym::SD => true,
            sym::DATA => self.in_frame,
            _ => false,
        };
        self.rx = delivered;
        self.act = act;
        self.tx_cnt = if i.tx == sym::SIL {
            0
        } else {
            (self.tx_cnt + 1).min(JABBER_LIMIT)
        };
        self.ev_seen |= i.ev & 0x3f;
        self.sf_cnt = sf_cnt;
        self.live = live;
        self.sf_pend = sf_pend;
        self.chk_cnt = chk_cnt;
        self.nm_valid = !self.scanning;
        self.s2_valid = self.scanning;
        self.s2_i = self.scan_i;
        self.scanning = scanning;
        self.scan_i = scan_i;
        self.st_rd = st_rd;
        self.prev_rd = prev_rd;
        self.all_ok = all_ok;
        self.any_bad = any_bad;
        self.stale = stale;
        self.chk_ok = chk_ok;
        self.chk_sw = chk_sw;
        self.irq = cs.is_some() || stale_rise;
        if let Some(c) = cs {
            self.cause = c;
        }
        self.state = st;
        self.pend = pend;
        self.pend_ch = pend_ch;
        self.cmd_req = cmd_req;
        self.cmd_ch = cmd_ch;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg() -> RmmConfig {
        RmmConfig {
            addr: 0,
            stations: 0b11,
            sf_period: 10,
            check_period: 50,
            good_limit: 20,
        }
    }

    #[test]
    fn divergence_on_the_active_channel_switches_in_the_same_octet() {
        let mut r = Rmm::new(cfg());
        r.clock(&RmmIn {
            init: true,
            ..Default::default()
        });
        r.clock(&RmmIn {
            auto: true,
            ..Default::default()
        });
        assert_eq!(r.out(true).state, state::AUTO_NORMAL);
        // A carries nothing, B carries a frame octet: A is faulty, the
        // octet is delivered from B.
        r.clock(&RmmIn {
            rx_b: sym::SD,
            ..Default::default()
        });
        let o = r.out(true);
        assert!(o.act);
        assert_eq!(o.rx, sym::SD);
        assert_eq!(o.state, state::MEDIUM_ERROR);
        r.clock(&RmmIn::default());
        assert_eq!(r.out(true).state, state::MANUAL_NORMAL);
    }

    /// A station in Manual_Normal (address 0, station 1 configured) that
    /// receives one status frame from station 1 with status byte `st1`
    /// before the first scan; `div_a`: its own channel A misses what B
    /// carries from octet 5 on. Returns the octets at which Status Check = SWITCH pulsed and
    /// the outputs after the run.
    fn scan_with_report(st1: u8, live1: u8, div_a: bool) -> (Vec<usize>, RmmOut) {
        let mut r = Rmm::new(cfg());
        let mut pulses = vec![];
        for t in 0..120 {
            let mut i = RmmIn {
                init: true,
                ..Default::default()
            };
            if t >= 5 && div_a {
                // B carries frame octets A misses, all along.
                i.rx_b = sym::data(0x55);
            }
            if t == 10 {
                i.rx_sf = true;
                i.rx_sa = 1;
                i.rx_sfw = (live1 as u16) << 8 | st1 as u16;
            }
            r.clock(&i);
            if r.out(true).chk_sw {
                pulses.push(t);
            }
        }
        (pulses, r.out(true))
    }

    #[test]
    fn a_fresh_report_of_a_bad_active_channel_switches_at_the_end_of_the_scan() {
        // Station 1 reports A bad (bit 1 clear) and B good (bit 2 set); this
        // station's own channels are good. The scan starts at octet 49 and
        // its verdict on address 31 is registered 34 octets later.
        let (pulses, o) = scan_with_report(0b100, 1, false);
        assert_eq!(pulses, vec![49 + 33]);
        assert!(o.act, "switched to B");
        assert_eq!(o.state, state::MANUAL_NORMAL);
        assert_eq!(o.cause, cause::CHECK_SW);
    }

    #[test]
    fn a_stale_report_is_evidence_of_nothing() {
        // The same report with the live counter still at its power-up value:
        // station 1 is stale, its status byte does not count.
        let (pulses, o) = scan_with_report(0b100, 0, false);
        assert!(pulses.is_empty(), "{pulses:?}");
        assert!(!o.act);
    }

    #[test]
    fn a_standby_reported_bad_vetoes_the_switch() {
        // Own A latched bad (a divergence), but station 1 reports B bad.
        let (pulses, o) = scan_with_report(0b010, 1, true);
        assert!(pulses.is_empty(), "{pulses:?}");
        assert!(!o.act);
        // With station 1 reporting both good, the own latch alone switches.
        let (pulses, o) = scan_with_report(0b110, 1, true);
        assert_eq!(pulses, vec![49 + 33]);
        assert!(o.act);
    }

    #[test]
    fn a_commanded_switch_waits_for_the_end_of_the_frame() {
        let mut r = Rmm::new(cfg());
        r.clock(&RmmIn {
            init: true,
            ..Default::default()
        });
        let frame = [sym::SD, sym::data(1), sym::data(2), sym::ED];
        for (k, &s) in frame.iter().enumerate() {
            r.clock(&RmmIn {
                rx_a: s,
                rx_b: s,
                cmd_rx: k == 1,
                cmd_ch: true,
                ..Default::default()
            });
            assert!(!r.out(true).act, "switched inside the frame at octet {k}");
        }
        r.clock(&RmmIn::default());
        assert!(r.out(true).act);
    }
}
