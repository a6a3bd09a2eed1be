//! # rmm_sfc — status frame check (docs/protocol.md §20)
//!
//! Purpose: the paper's Status Frame Check Sub-module. Every received status
//! frame is written into block RAM by its source address: **3 bytes per
//! station** — the 2 status bytes of the latest frame (`st`, 32 × 16) and the
//! live counter seen at the previous check (`prev`, 32 × 8). Every
//! `i_chk_period` octets a scan visits the 32 addresses, one per octet
//! (34 octets with the read latency): a configured station (`i_stations`,
//! not this one) whose live counter has not moved since the last scan is
//! flagged **stale**; the scan ends with **Status Check = OK** (`o_chk_ok`,
//! one octet) when no station is stale, every station reports both channels
//! good, and this station's own channels are good (`i_bad_a`, `i_bad_b`
//! clear). The same scan is the backup fault detector: it collects, per
//! channel, whether a fresh (not stale) configured station reports it not
//! good, and ends with **Status Check = SWITCH** (`o_chk_sw`, one octet) when
//! the active channel (`i_act`) is suspect — own `bad` or a fresh report —
//! and the standby is clear — own `bad` clear and no fresh report.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_chk_period` | in | 16 | check period, octets (≥ 64) |
//! | `i_addr` | in | 5 | own address |
//! | `i_stations` | in | 32 | configured stations (bit per address) |
//! | `i_bad_a`, `i_bad_b` | in | 1 | own channels faulty (the DCM's latched `bad`) |
//! | `i_act` | in | 1 | own active channel (0 A, 1 B) |
//! | `i_rx_sf` | in | 1 | a valid status frame was received |
//! | `i_rx_sa` | in | 8 | its source address (≥ 32 ignored) |
//! | `i_rx_sfw` | in | 16 | its status bytes |
//! | `o_stale` | out | 32 | stations whose live counter stopped |
//! | `o_chk_ok` | out | 1 | Status Check = OK |
//! | `o_chk_sw` | out | 1 | Status Check = SWITCH (protocol §20) |
//! | `o_rise` | out | 1 | a station became stale (report interrupt) |
//! | `i_nm_addr` | in | 5 | network manager: station whose stored status to read between scans |
//! | `o_nm_word`, `o_nm_valid` | out | 16/1 | its latest status frame, one octet later; valid outside scans |
//!
//! Latency: a scan starts the octet after the period ends; station k's
//! verdict is registered at octet k+2 of the scan, `o_chk_ok` and
//! `o_chk_sw` after k = 31.
//!
//! ```text
//! octet     0(start) 1      2      ..     33     34
//! read      -        st[0]  st[1]  ..     st[31]
//! verdict   -        -      s0     ..     s30    s31, o_chk_ok / o_chk_sw
//! ```

use rust_hdl::prelude::*;

/// Status frame check.
#[derive(LogicBlock, Default)]
pub struct RmmSfc {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// Check period, octets.
    pub i_chk_period: Signal<In, Bits<16>>,
    /// Own address.
    pub i_addr: Signal<In, Bits<5>>,
    /// Configured stations.
    pub i_stations: Signal<In, Bits<32>>,
    /// Own channel A faulty.
    pub i_bad_a: Signal<In, Bit>,
    /// Own channel B faulty.
    pub i_bad_b: Signal<In, Bit>,
    /// Own active channel.
    pub i_act: Signal<In, Bit>,
    /// Status frame received.
    pub i_rx_sf: Signal<In, Bit>,
    /// Its source address.
    pub i_rx_sa: Signal<In, Bits<8>>,
    /// Its status bytes.
    pub i_rx_sfw: Signal<In, Bits<16>>,
    /// Stale stations.
    pub o_stale: Signal<Out, Bits<32>>,
    /// Status Check = OK.
    pub o_chk_ok: Signal<Out, Bit>,
    /// Status Check = SWITCH.
    pub o_chk_sw: Signal<Out, Bit>,
    /// A station became stale.
    pub o_rise: Signal<Out, Bit>,
    /// Network manager read address.
    pub i_nm_addr: Signal<In, Bits<5>>,
    /// Stored status frame of that station.
    pub o_nm_word: Signal<Out, Bits<16>>,
    /// `o_nm_word` is from `i_nm_addr` (not a scan read).
    pub o_nm_valid: Signal<Out, Bit>,
    st: RAM<Bits<16>, 5>,
    prev: RAM<Bits<8>, 5>,
    cnt: DFF<Bits<16>>,
    /// `cnt + 1` in 17 bits: it never wraps, so the comparison with the
    /// period is the same as Verilog's 32-bit sum, with no mixed widths.
    cnt_p1: Signal<Local, Bits<17>>,
    scanning: DFF<Bit>,
    scan_i: DFF<Bits<5>>,
    s2_valid: DFF<Bit>,
    s2_i: DFF<Bits<5>>,
    all_ok: DFF<Bit>,
    a_bad: DFF<Bit>,
    b_bad: DFF<Bit>,
    stale: DFF<Bits<32>>,
    chk_ok: DFF<Bit>,
    chk_sw: DFF<Bit>,
    rise: DFF<Bit>,
    nm_valid: DFF<Bit>,
    member: Signal<Local, Bit>,
    stale_k: Signal<Local, Bit>,
    good_k: Signal<Local, Bit>,
    all_ok_n: Signal<Local, Bit>,
    fresh: Signal<Local, Bit>,
    a_bad_n: Signal<Local, Bit>,
    b_bad_n: Signal<Local, Bit>,
    suspect: Signal<Local, Bit>,
    clear: Signal<Local, Bit>,
    stale_n: Signal<Local, Bits<32>>,
    mask: Signal<Local, Bits<32>>,
}

impl Logic for RmmSfc {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, cnt, scanning, scan_i, s2_valid, s2_i, all_ok, a_bad, b_bad, stale,
            chk_ok, chk_sw, rise, nm_valid
        );
        self.st.read_clock.next = self.clock.val();
        self.st.write_clock.next = self.clock.val();
        self.prev.read_clock.next = self.clock.val();
        self.prev.write_clock.next = self.clock.val();
        // Received status frames.
        self.st.write_enable.next = self.i_rx_sf.val() & (self.i_rx_sa.val() < 32);
        self.st.write_address.next = self.i_rx_sa.val().get_bits::<5>(0);
        self.st.write_data.next = self.i_rx_sfw.val();
        // The check period and the scan (stage 1: read).
        self.cnt_p1.next = bit_cast::<17, 16>(self.cnt.q.val()) + 1;
        if self.cnt_p1.val() >= bit_cast::<17, 16>(self.i_chk_period.val()) {
            self.cnt.d.next = 0.into();
            self.scanning.d.next = true;
            self.scan_i.d.next = 0.into();
        } else {
            self.cnt.d.next = self.cnt.q.val() + 1;
            if self.scanning.q.val() {
                self.scanning.d.next = self.scan_i.q.val() != 31;
                self.scan_i.d.next = self.scan_i.q.val() + 1;
            }
        }
        // Between scans the network manager reads the status memory.
        if self.scanning.q.val() {
            self.st.read_address.next = self.scan_i.q.val();
        } else {
            self.st.read_address.next = self.i_nm_addr.val();
        }
        self.nm_valid.d.next = !self.scanning.q.val();
        self.prev.read_address.next = self.scan_i.q.val();
        self.s2_valid.d.next = self.scanning.q.val();
        self.s2_i.d.next = self.scan_i.q.val();
        // Stage 2: the verdict on station s2_i.
        self.member.next = (((self.i_stations.val() >> self.s2_i.q.val()) & 1) == 1)
            & (self.s2_i.q.val() != self.i_addr.val());
        self.stale_k.next = self.member.val()
            & (self.st.read_data.val().get_bits::<8>(8) == self.prev.read_data.val());
        self.good_k.next = !self.member.val()
            | (!self.stale_k.val()
                & self.st.read_data.val().get_bit(1)
                & self.st.read_data.val().get_bit(2));
        self.mask.next = bits::<32>(1) << self.s2_i.q.val();
        self.stale_n.next = self.stale.q.val();
        self.all_ok_n.next = self.all_ok.q.val();
        self.chk_ok.d.next = false;
        self.chk_sw.d.next = false;
        // Status Check = SWITCH: a fresh station's report of each channel.
        self.fresh.next = self.member.val() & !self.stale_k.val();
        self.a_bad_n.next = self.a_bad.q.val();
        self.b_bad_n.next = self.b_bad.q.val();
        self.prev.write_enable.next = false;
        self.prev.write_address.next = self.s2_i.q.val();
        self.prev.write_data.next = self.st.read_data.val().get_bits::<8>(8);
        if self.s2_valid.q.val() {
            self.prev.write_enable.next = self.member.val();
            if self.stale_k.val() {
                self.stale_n.next = self.stale.q.val() | self.mask.val();
            } else {
                self.stale_n.next = self.stale.q.val() & !self.mask.val();
            }
            if self.s2_i.q.val() == 0 {
                self.all_ok_n.next = self.good_k.val();
            } else {
                self.all_ok_n.next = self.all_ok.q.val() & self.good_k.val();
            }
            self.chk_ok.d.next = (self.s2_i.q.val() == 31)
                & self.all_ok_n.val()
                & !self.i_bad_a.val()
                & !self.i_bad_b.val();
            self.a_bad_n.next = self.fresh.val() & !self.st.read_data.val().get_bit(1);
            self.b_bad_n.next = self.fresh.val() & !self.st.read_data.val().get_bit(2);
            if self.s2_i.q.val() != 0 {
                self.a_bad_n.next = self.a_bad_n.val() | self.a_bad.q.val();
                self.b_bad_n.next = self.b_bad_n.val() | self.b_bad.q.val();
            }
        }
        if self.i_act.val() {
            self.suspect.next = self.i_bad_b.val() | self.b_bad_n.val();
            self.clear.next = !self.i_bad_a.val() & !self.a_bad_n.val();
        } else {
            self.suspect.next = self.i_bad_a.val() | self.a_bad_n.val();
            self.clear.next = !self.i_bad_b.val() & !self.b_bad_n.val();
        }
        self.chk_sw.d.next = self.s2_valid.q.val()
            & (self.s2_i.q.val() == 31)
            & self.suspect.val()
            & self.clear.val();
        self.a_bad.d.next = self.a_bad_n.val();
        self.b_bad.d.next = self.b_bad_n.val();
        self.all_ok.d.next = self.all_ok_n.val();
        self.stale.d.next = self.stale_n.val();
        self.rise.d.next = (self.stale_n.val() & !self.stale.q.val()) != 0;
        self.o_stale.next = self.stale.q.val();
        self.o_chk_ok.next = self.chk_ok.q.val();
        self.o_chk_sw.next = self.chk_sw.q.val();
        self.o_rise.next = self.rise.q.val();
        self.o_nm_word.next = self.st.read_data.val();
        self.o_nm_valid.next = self.nm_valid.q.val();
    }
}
