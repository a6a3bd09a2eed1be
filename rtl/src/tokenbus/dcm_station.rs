//! # dcm_station — one token-bus station's redundancy hardware (docs/protocol.md Part II)
//!
//! Purpose: the paper's Figure 5 in one block, emitted as `merkur_dcm_station`: the
//! Dual Channel Manager ([`crate::tokenbus::dcm`]) between the MAC and the two PHYs,
//! and the Redundancy Management Module — fault detection from the MAC's
//! events ([`crate::tokenbus::rmm_detect`]), status frame production
//! ([`crate::tokenbus::rmm_sfp`]) and check ([`crate::tokenbus::rmm_sfc`]), and the fault
//! correction machine ([`crate::tokenbus::rmm_fcm`]). One clock is one octet time.
//! The report to the network manager is `o_state`, `o_cause`, `o_stale`,
//! the channel status registers and the interrupt `o_irq`.
//!
//! Status byte of the status frame: bit 7 active channel, bits 6:4 state,
//! bit 3 dual mode (Auto_Normal), bit 2 channel B good, bit 1 channel A
//! good, bit 0 host status.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_rx_a`, `i_rx_b`, `o_tx_a`, `o_tx_b` | in/out | 11 | PHY A / B symbols |
//! | `i_tx`, `o_rx` | in/out | 11 | MAC symbols |
//! | `i_ev` | in | 6 | MAC events (see rmm_detect) |
//! | `i_sf_sent` | in | 1 | MAC took the status word |
//! | `i_rx_sf`, `i_rx_sa`, `i_rx_sfw` | in | 1/8/16 | MAC received a status frame |
//! | `i_cmd_rx`, `i_cmd_ch` | in | 1 | MAC received a switch command |
//! | `i_cmd_sent` | in | 1 | MAC sent our switch command |
//! | `i_init`, `i_auto`, `i_host_ok` | in | 1 | host |
//! | `i_addr`, `i_stations` | in | 5/32 | own address, configured stations |
//! | `i_sf_period`, `i_chk_period`, `i_good_limit` | in | 16 | periods and limits, octets |
//! | `o_act`, `o_state`, `o_cause`, `o_irq` | out | 1/3/4/1 | channel, machine, report |
//! | `o_sf_pend`, `o_sf_word` | out | 1/16 | status frame due, its bytes |
//! | `o_cmd_req`, `o_cmd_ch` | out | 1 | broadcast the switch command |
//! | `o_stat_a`, `o_stat_b` | out | 16 | channel status registers |
//! | `o_stale`, `o_chk_ok`, `o_chk_sw`, `o_ev_seen` | out | 32/1/1/6 | status check (stale, OK, SWITCH), events seen |
//! | `i_nm_addr`, `o_nm_word`, `o_nm_valid` | in/out | 5/16/1 | network manager reads a station's stored status frame |
//!
//! Latency: as its blocks; `o_rx` one octet after the PHY symbol.
//!
//! ```text
//!            +-----------------------------------------------+
//!  PHY A <-->|  dcm  --fault/bad/in_frame-->  rmm_fcm        |<-- host
//!  PHY B <-->|   ^  <-----------sw------------/  ^   ^       |--> report, irq
//!            |   |                     rmm_detect  rmm_sfc   |
//!  MAC   <-->|---+-- events, frames ------/  rmm_sfp /       |
//!            +-----------------------------------------------+
//! ```

use crate::tokenbus::dcm::Dcm;
use crate::tokenbus::rmm_detect::RmmDetect;
use crate::tokenbus::rmm_fcm::RmmFcm;
use crate::tokenbus::rmm_sfc::RmmSfc;
use crate::tokenbus::rmm_sfp::RmmSfp;
use rust_hdl::prelude::*;

/// One station's DCM and RMM.
#[derive(LogicBlock, Default)]
pub struct DcmStation {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// PHY A symbol.
    pub i_rx_a: Signal<In, Bits<11>>,
    /// PHY B symbol.
    pub i_rx_b: Signal<In, Bits<11>>,
    /// MAC symbol.
    pub i_tx: Signal<In, Bits<11>>,
    /// MAC events.
    pub i_ev: Signal<In, Bits<6>>,
    /// MAC took the status word.
    pub i_sf_sent: Signal<In, Bit>,
    /// Status frame received.
    pub i_rx_sf: Signal<In, Bit>,
    /// Its source address.
    pub i_rx_sa: Signal<In, Bits<8>>,
    /// Its status bytes.
    pub i_rx_sfw: Signal<In, Bits<16>>,
    /// Switch command received.
    pub i_cmd_rx: Signal<In, Bit>,
    /// Its target channel.
    pub i_cmd_ch: Signal<In, Bit>,
    /// Our switch command went out.
    pub i_cmd_sent: Signal<In, Bit>,
    /// Host: initialised.
    pub i_init: Signal<In, Bit>,
    /// Host: AUTO_SW_MODE.
    pub i_auto: Signal<In, Bit>,
    /// Host status.
    pub i_host_ok: Signal<In, Bit>,
    /// Own address.
    pub i_addr: Signal<In, Bits<5>>,
    /// Configured stations.
    pub i_stations: Signal<In, Bits<32>>,
    /// Status frame period.
    pub i_sf_period: Signal<In, Bits<16>>,
    /// Status check period.
    pub i_chk_period: Signal<In, Bits<16>>,
    /// Good limit.
    pub i_good_limit: Signal<In, Bits<16>>,
    /// To PHY A.
    pub o_tx_a: Signal<Out, Bits<11>>,
    /// To PHY B.
    pub o_tx_b: Signal<Out, Bits<11>>,
    /// To the MAC.
    pub o_rx: Signal<Out, Bits<11>>,
    /// Active channel.
    pub o_act: Signal<Out, Bit>,
    /// Fault correction state.
    pub o_state: Signal<Out, Bits<3>>,
    /// Report cause.
    pub o_cause: Signal<Out, Bits<4>>,
    /// Report interrupt.
    pub o_irq: Signal<Out, Bit>,
    /// Status frame due.
    pub o_sf_pend: Signal<Out, Bit>,
    /// Status word.
    pub o_sf_word: Signal<Out, Bits<16>>,
    /// Broadcast the switch command.
    pub o_cmd_req: Signal<Out, Bit>,
    /// Its target.
    pub o_cmd_ch: Signal<Out, Bit>,
    /// Status register A.
    pub o_stat_a: Signal<Out, Bits<16>>,
    /// Status register B.
    pub o_stat_b: Signal<Out, Bits<16>>,
    /// Stale stations.
    pub o_stale: Signal<Out, Bits<32>>,
    /// Status Check = OK.
    pub o_chk_ok: Signal<Out, Bit>,
    /// Status Check = SWITCH.
    pub o_chk_sw: Signal<Out, Bit>,
    /// Events seen.
    pub o_ev_seen: Signal<Out, Bits<6>>,
    /// Network manager: station whose stored status frame to read.
    pub i_nm_addr: Signal<In, Bits<5>>,
    /// Its stored status frame.
    pub o_nm_word: Signal<Out, Bits<16>>,
    /// `o_nm_word` is valid (no scan running).
    pub o_nm_valid: Signal<Out, Bit>,
    dcm: Dcm,
    detect: RmmDetect,
    sfp: RmmSfp,
    sfc: RmmSfc,
    fcm: RmmFcm,
    status: Signal<Local, Bits<8>>,
}

impl Logic for DcmStation {
    #[hdl_gen]
    fn update(&mut self) {
        self.dcm.clock.next = self.clock.val();
        self.detect.clock.next = self.clock.val();
        self.sfp.clock.next = self.clock.val();
        self.sfc.clock.next = self.clock.val();
        self.fcm.clock.next = self.clock.val();
        // DCM.
        self.dcm.i_rx_a.next = self.i_rx_a.val();
        self.dcm.i_rx_b.next = self.i_rx_b.val();
        self.dcm.i_tx.next = self.i_tx.val();
        self.dcm.i_sw.next = self.fcm.o_sw.val();
        self.dcm.i_good_limit.next = self.i_good_limit.val();
        // Fault detection.
        self.detect.i_ev.next = self.i_ev.val();
        // Fault correction.
        self.fcm.i_init.next = self.i_init.val();
        self.fcm.i_auto.next = self.i_auto.val();
        self.fcm.i_sc.next = self.detect.o_sc.val();
        self.fcm.i_ns.next = self.detect.o_ns.val();
        self.fcm.i_chk_ok.next = self.sfc.o_chk_ok.val();
        self.fcm.i_chk_sw.next = self.sfc.o_chk_sw.val();
        self.fcm.i_fault_a.next = self.dcm.o_fault_a.val();
        self.fcm.i_fault_b.next = self.dcm.o_fault_b.val();
        self.fcm.i_bad_a.next = self.dcm.o_bad_a.val();
        self.fcm.i_bad_b.next = self.dcm.o_bad_b.val();
        self.fcm.i_act.next = self.dcm.o_act.val();
        self.fcm.i_in_frame.next = self.dcm.o_in_frame.val();
        self.fcm.i_cmd_rx.next = self.i_cmd_rx.val();
        self.fcm.i_cmd_ch.next = self.i_cmd_ch.val();
        self.fcm.i_cmd_sent.next = self.i_cmd_sent.val();
        // Status frame production: the status byte.
        self.status.next = (bit_cast::<8, 3>(self.fcm.o_state.val()) | 0) << 4;
        if self.dcm.o_act.val() {
            self.status.next = self.status.val() | 0x80;
        }
        if self.fcm.o_state.val() == 2 {
            self.status.next = self.status.val() | 0x08;
        }
        if !self.dcm.o_bad_b.val() {
            self.status.next = self.status.val() | 0x04;
        }
        if !self.dcm.o_bad_a.val() {
            self.status.next = self.status.val() | 0x02;
        }
        if self.i_host_ok.val() {
            self.status.next = self.status.val() | 0x01;
        }
        self.sfp.i_sf_period.next = self.i_sf_period.val();
        self.sfp.i_sf_sent.next = self.i_sf_sent.val();
        self.sfp.i_status.next = self.status.val();
        // Status frame check.
        self.sfc.i_chk_period.next = self.i_chk_period.val();
        self.sfc.i_addr.next = self.i_addr.val();
        self.sfc.i_stations.next = self.i_stations.val();
        self.sfc.i_bad_a.next = self.dcm.o_bad_a.val();
        self.sfc.i_bad_b.next = self.dcm.o_bad_b.val();
        self.sfc.i_act.next = self.dcm.o_act.val();
        self.sfc.i_rx_sf.next = self.i_rx_sf.val();
        self.sfc.i_rx_sa.next = self.i_rx_sa.val();
        self.sfc.i_rx_sfw.next = self.i_rx_sfw.val();
        self.sfc.i_nm_addr.next = self.i_nm_addr.val();
        self.o_nm_word.next = self.sfc.o_nm_word.val();
        self.o_nm_valid.next = self.sfc.o_nm_valid.val();
        // Outputs.
        self.o_tx_a.next = self.dcm.o_tx_a.val();
        self.o_tx_b.next = self.dcm.o_tx_b.val();
        self.o_rx.next = self.dcm.o_rx.val();
        self.o_act.next = self.dcm.o_act.val();
        self.o_state.next = self.fcm.o_state.val();
        self.o_cause.next = self.fcm.o_cause.val();
        self.o_irq.next = self.fcm.o_irq.val() | self.sfc.o_rise.val();
        self.o_sf_pend.next = self.sfp.o_sf_pend.val();
        self.o_sf_word.next = self.sfp.o_sf_word.val();
        self.o_cmd_req.next = self.fcm.o_cmd_req.val();
        self.o_cmd_ch.next = self.fcm.o_cmd_ch.val();
        self.o_stat_a.next = self.dcm.o_stat_a.val();
        self.o_stat_b.next = self.dcm.o_stat_b.val();
        self.o_stale.next = self.sfc.o_stale.val();
        self.o_chk_ok.next = self.sfc.o_chk_ok.val();
        self.o_chk_sw.next = self.sfc.o_chk_sw.val();
        self.o_ev_seen.next = self.detect.o_ev_seen.val();
    }
}

/// The Verilog of the station, top module `merkur_dcm_station` (its blocks as
/// `merkur_dcm_station__...` submodules), every memory zero at power-up.
pub fn dcm_verilog() -> String {
    let v = crate::emit::verilog::block_verilog(DcmStation::default());
    crate::emit::verilog::rename_top(&v, "merkur_dcm_station")
}
