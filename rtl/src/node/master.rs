//! # master — a MERKUR master node (the paper's Figure 7)
//!
//! Purpose: a node with a host: the ring logic of a [`Slave`] (switchbox,
//! receive ports, stream controllers, mode and failsafe logic, alarm queue)
//! with its forwarder in master mode, plus the real-time database [`Mdb`]
//! (data memory 4096 × 16, configuration memory, Alive check, interrupts,
//! Wishbone host port). Per slot, by its configuration (protocol §7):
//! LOCAL slots leave with `{data memory, Alive}` (or an alarm in the home
//! slot), ACT slots get the data memory's value with the actuator's Alive
//! kept (a VOID is regenerated with the Alive the actuator would send),
//! every other good word updates the data memory.
//!
//! The ring logic runs from power-up; the master writes slots only after the
//! host has loaded the configuration and set the start bit (`0x2000` bit 0),
//! after which configuration writes are refused. After a restart (power
//! lost and back, protocol §12) the host loads the configuration again and
//! starts it with JOIN (`0x2000` bit 6): it reads one frame without writing
//! (the reload frame) and writes an own slot only once it has a value, from
//! the ring or from its host ([`Mdb`]).
//!
//! Parameters: the word format ([`crate::line::word_rx::WordFormat`],
//! protocol §4 or §6), for the [`Slave`] and the [`Mdb`].
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock, 2× line rate (also the Wishbone clock) |
//! | `i_pi`, `i_si` | in | 4 | clock | physical inputs, 4 samples per clock (quadrature DDR); with `i_cap_sel` INPUT's and BSR's |
//! | `i_cap_sel`, `o_cap_si` | in, out | 1, 1 | static, clock | the capture register in front makes the switchbox's input choice, as [`Slave`]'s |
//! | `o_po`, `o_so` | out | 2 | clock | physical outputs, DDR pairs |
//! | `i_address` | in | 12 | static | home slot (one of the LOCAL slots) |
//! | `i_slots_m1` | in | 12 | static | slots per frame − 1 |
//! | `i_cs_timeout` | in | 20 | static | clocks without a good frame before failsafe |
//! | `i_wb_*`, `o_wb_*` | | | clock | Wishbone B4 classic host port, see [`Mdb`] |
//! | `i_irq1`, `i_irq2`, `i_fs_req` | in | 1 | clock | user requests (alarms in the home slot) |
//! | `o_irq1`, `o_irq2`, `o_irq_fs`, `o_irq_rc` | out | 1 | clock | alarm received, by reason: IRQ1, IRQ2, FAILSAFE, RECONFIG 4–6 (one clock per alarm word; each also goes into the alarm queue, `mdb`) |
//! | `o_alarmq` | out | 1 | clock | the alarm queue is not empty (level) |
//! | `o_irq_fsc` | out | 1 | clock | failsafe entered or left (one clock; protocol §12) |
//! | `o_mode` | out | 2 | clock | switchbox mode |
//! | `o_failsafe` | out | 1 | clock | failsafe |
//! | `o_perr`, `o_ferr`, `o_aerr` | out | 16 | clock | error counters |
//! | `o_running` | out | 1 | clock | the host started the ring |
//!
//! Latency: as [`Slave`] (INPUT to OUTPUT 9.5–10.5 bit times); a received
//! word is in the data memory ≈ 4 bit times after its last line bit.
//!
//! ```text
//! PI/SI ─ switchbox ─ port_rx ─ fwd (master mode) ─ switchbox ─ PO/SO
//!                        │         ▲ data, cfg, Alive of o_fwd_slot
//!                        └──────▶ mdb ◀──▶ Wishbone host
//! ```

use crate::line::retime::Layout;
use crate::line::word_rx::WordFormat;
use crate::node::mdb::Mdb;
use crate::node::slave::Slave;
use rust_hdl::prelude::*;

/// Master node.
#[derive(LogicBlock, Default)]
pub struct Master {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Primary input.
    pub i_pi: Signal<In, Bits<4>>,
    /// Secondary input.
    pub i_si: Signal<In, Bits<4>>,
    /// The capture in front made the switchbox's input choice.
    pub i_cap_sel: Signal<In, Bit>,
    /// The capture's choice for the next clock: SI as INPUT.
    pub o_cap_si: Signal<Out, Bit>,
    /// Primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Secondary output.
    pub o_so: Signal<Out, Bits<2>>,
    /// Home slot.
    pub i_address: Signal<In, Bits<12>>,
    /// Slots − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// CS timeout in clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Wishbone cycle.
    pub i_wb_cyc: Signal<In, Bit>,
    /// Wishbone strobe.
    pub i_wb_stb: Signal<In, Bit>,
    /// Wishbone write enable.
    pub i_wb_we: Signal<In, Bit>,
    /// Wishbone word address.
    pub i_wb_adr: Signal<In, Bits<14>>,
    /// Wishbone write data.
    pub i_wb_dat: Signal<In, Bits<16>>,
    /// Wishbone read data.
    pub o_wb_dat: Signal<Out, Bits<16>>,
    /// Wishbone acknowledge.
    pub o_wb_ack: Signal<Out, Bit>,
    /// User interrupt 1 request.
    pub i_irq1: Signal<In, Bit>,
    /// User interrupt 2 request.
    pub i_irq2: Signal<In, Bit>,
    /// User failsafe request.
    pub i_fs_req: Signal<In, Bit>,
    /// IRQ1 alarm received.
    pub o_irq1: Signal<Out, Bit>,
    /// IRQ2 alarm received.
    pub o_irq2: Signal<Out, Bit>,
    /// FAILSAFE alarm received.
    pub o_irq_fs: Signal<Out, Bit>,
    /// RECONFIG alarm received.
    pub o_irq_rc: Signal<Out, Bit>,
    /// The alarm queue is not empty.
    pub o_alarmq: Signal<Out, Bit>,
    /// Failsafe entered or left.
    pub o_irq_fsc: Signal<Out, Bit>,
    /// Mode.
    pub o_mode: Signal<Out, Bits<2>>,
    /// Failsafe.
    pub o_failsafe: Signal<Out, Bit>,
    /// Bad words at INPUT.
    pub o_perr: Signal<Out, Bits<16>>,
    /// Rejected headers at INPUT.
    pub o_ferr: Signal<Out, Bits<16>>,
    /// Alive-check failures.
    pub o_aerr: Signal<Out, Bits<16>>,
    /// Running.
    pub o_running: Signal<Out, Bit>,
    node: Slave,
    mdb: Mdb,
    aact: RAM<Bit, 12>,
}

impl Master {
    /// A master node for words in `format` (protocol §4, §6), with
    /// retransmission on demand.
    pub fn new(format: WordFormat) -> Self {
        Self::with_rtx(format, true)
    }

    /// A master node for words in `format`; without retransmission on
    /// demand when `rtx` is false (a ring without critical slots,
    /// [`Slave::with_rtx`]).
    pub fn with_rtx(format: WordFormat, rtx: bool) -> Self {
        Self {
            node: Slave::with_rtx(format, rtx),
            mdb: Mdb::new(format),
            ..Default::default()
        }
    }

    /// The same master with its retime buffers in `layout`
    /// ([`Slave::with_layout`]).
    pub fn with_layout(mut self, layout: Layout) -> Self {
        self.node = self.node.with_layout(layout);
        self
    }
}

impl Logic for Master {
    #[hdl_gen]
    fn update(&mut self) {
        self.node.clock.next = self.clock.val();
        self.mdb.clock.next = self.clock.val();
        self.aact.read_clock.next = self.clock.val();
        self.aact.write_clock.next = self.clock.val();

        self.node.i_pi.next = self.i_pi.val();
        self.node.i_si.next = self.i_si.val();
        self.node.i_cap_sel.next = self.i_cap_sel.val();
        self.o_cap_si.next = self.node.o_cap_si.val();
        self.o_po.next = self.node.o_po.val();
        self.o_so.next = self.node.o_so.val();
        self.node.i_address.next = self.i_address.val();
        self.node.i_slots_m1.next = self.i_slots_m1.val();
        self.node.i_actuator.next = false;
        self.node.i_cs_timeout.next = self.i_cs_timeout.val();
        self.node.i_sensor_data.next = 0.into();
        self.node.i_irq1.next = self.i_irq1.val();
        self.node.i_irq2.next = self.i_irq2.val();
        self.node.i_fs_req.next = self.i_fs_req.val();
        self.node.i_master.next = true;
        self.node.i_fs_set.next = self.mdb.o_irq_fs.val();

        // What the forwarder writes in each slot: the data block decides
        // (LOCAL, ACT, an alarm only; protocol §12), once the host started
        // the node.
        self.node.i_slot_cfg.next = 0.into();
        if self.mdb.o_running.val() {
            self.node.i_slot_cfg.next = self.mdb.o_tx_cfg.val();
        }
        self.node.i_slot_data.next = self.mdb.o_tx_data.val();
        self.mdb.i_tx_slot.next = self.node.o_fwd_slot.val();
        self.aact.read_address.next = self.node.o_fwd_slot.val();
        self.node.i_slot_alive.next = self.aact.read_data.val();
        // Actuator Alive: a regenerated VOID flips it; a good word in an ACT
        // slot sets it (protocol §7).
        self.aact.write_enable.next = false;
        self.aact.write_address.next = self.mdb.o_s2_slot.val();
        self.aact.write_data.next = self.mdb.o_s2_alive.val();
        if self.mdb.o_s2.val()
            & self.mdb.o_s2_ok.val()
            & self.mdb.o_s2_act.val()
            & !self.node.o_failsafe.val()
        {
            self.aact.write_enable.next = true;
        }
        if self.node.o_regen.val() {
            self.aact.write_enable.next = true;
            self.aact.write_address.next = self.node.o_fwd_slot.val();
            self.aact.write_data.next = !self.aact.read_data.val();
        }

        // The database.
        self.mdb.i_wb_cyc.next = self.i_wb_cyc.val();
        self.mdb.i_wb_stb.next = self.i_wb_stb.val();
        self.mdb.i_wb_we.next = self.i_wb_we.val();
        self.mdb.i_wb_adr.next = self.i_wb_adr.val();
        self.mdb.i_wb_dat.next = self.i_wb_dat.val();
        self.o_wb_dat.next = self.mdb.o_wb_dat.val();
        self.o_wb_ack.next = self.mdb.o_wb_ack.val();
        self.mdb.i_home.next = self.i_address.val();
        self.mdb.i_slots_m1.next = self.i_slots_m1.val();
        self.mdb.i_fs.next = self.node.o_failsafe.val();
        self.mdb.i_mode.next = self.node.o_mode.val();
        self.mdb.i_wvalid.next = self.node.o_wvalid.val();
        self.mdb.i_kind.next = self.node.o_kind.val();
        self.mdb.i_slot.next = self.node.o_slot.val();
        self.mdb.i_data.next = self.node.o_data.val();
        self.mdb.i_alive.next = self.node.o_alive.val();
        self.mdb.i_alarm.next = self.node.o_alarm.val();
        self.mdb.i_reason.next = self.node.o_reason.val();
        self.mdb.i_ok.next = self.node.o_ok.val();
        self.mdb.i_hdr_bad.next = self.node.o_hdr_bad.val();
        self.mdb.i_rtx.next = self.node.o_rtx.val();

        self.o_irq1.next = self.mdb.o_irq1.val();
        self.o_irq2.next = self.mdb.o_irq2.val();
        self.o_irq_fs.next = self.mdb.o_irq_fs.val();
        self.o_irq_rc.next = self.mdb.o_irq_rc.val();
        self.o_alarmq.next = self.mdb.o_alarmq.val();
        self.o_irq_fsc.next = self.mdb.o_irq_fsc.val();
        // FS_CLEAR is the special master's; a master ignores it.
        self.mdb.i_fs_cleared.next = false;
        self.o_mode.next = self.node.o_mode.val();
        self.o_failsafe.next = self.node.o_failsafe.val();
        self.o_perr.next = self.node.o_perr.val();
        self.o_ferr.next = self.node.o_ferr.val();
        self.o_aerr.next = self.mdb.o_aerr.val();
        self.o_running.next = self.mdb.o_running.val();
    }
}
