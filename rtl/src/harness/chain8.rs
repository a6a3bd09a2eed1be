//! # chain8 — eight slave nodes in a row (a test top, not a product block)
//!
//! Purpose: the slave chain of the issue-3 tests: node k's PO feeds node k+1's
//! PI and node k+1's SO feeds node k's SI; the chain's first PI and last SI
//! come from the testbench (the model's frames and idles), its last PO and
//! first SO go to the testbench. All nodes share the core clock; the
//! testbench's line runs at its own rate, so the chain must follow it.
//! Per-node ports are numbered 0..7 in chain order.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock of every node |
//! | `i_pi`, `i_si` | in | 4 | clock | chain inputs (4 samples per clock) |
//! | `o_po`, `o_so` | out | 2 | clock | chain outputs |
//! | `i_slots_m1`, `i_cs_timeout` | in | 12, 20 | static | shared configuration |
//! | `i_address<k>`, `i_actuator<k>`, `i_sensor<k>`, `i_irq1_<k>` | in | | clock | node k's [`Slave`] inputs |
//! | `o_act<k>`, `o_mode<k>`, `o_fs<k>`, `o_perr<k>` | out | | clock | node k's [`Slave`] outputs |
//!
//! Latency: 8 × the slave's INPUT-to-OUTPUT latency.
//!
//! ```text
//! i_pi -> n0 -> n1 -> ... -> n7 -> o_po        (primary)
//! o_so <- n0 <- n1 <- ... <- n7 <- i_si        (secondary)
//! ```

use crate::node::slave::Slave;
use rust_hdl::prelude::*;

/// A link between two nodes on the same clock: each DDR half of the
/// sender's pair is two of the receiver's four samples.
#[derive(LogicBlock, Default)]
pub struct Loopback {
    /// Sender's DDR pair.
    pub i_pair: Signal<In, Bits<2>>,
    /// Receiver's samples.
    pub o_samples: Signal<Out, Bits<4>>,
}

impl Logic for Loopback {
    #[hdl_gen]
    fn update(&mut self) {
        self.o_samples.next = 0.into();
        if self.i_pair.val() == 1 {
            self.o_samples.next = 3.into();
        }
        if self.i_pair.val() == 2 {
            self.o_samples.next = 12.into();
        }
        if self.i_pair.val() == 3 {
            self.o_samples.next = 15.into();
        }
    }
}

/// Eight slaves in a row.
#[derive(LogicBlock, Default)]
pub struct Chain8 {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Chain primary input.
    pub i_pi: Signal<In, Bits<4>>,
    /// Chain secondary input.
    pub i_si: Signal<In, Bits<4>>,
    /// Chain primary output.
    pub o_po: Signal<Out, Bits<2>>,
    /// Chain secondary output.
    pub o_so: Signal<Out, Bits<2>>,
    /// Slots − 1.
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// CS timeout in clocks.
    pub i_cs_timeout: Signal<In, Bits<20>>,
    /// Node 0: home slot.
    pub i_address0: Signal<In, Bits<12>>,
    /// Node 0: actuator (1) or sensor (0).
    pub i_actuator0: Signal<In, Bit>,
    /// Node 0: sensor value.
    pub i_sensor0: Signal<In, Bits<16>>,
    /// Node 0: user interrupt 1 request.
    pub i_irq1_0: Signal<In, Bit>,
    /// Node 0: actuator output.
    pub o_act0: Signal<Out, Bits<16>>,
    /// Node 0: mode.
    pub o_mode0: Signal<Out, Bits<2>>,
    /// Node 0: failsafe.
    pub o_fs0: Signal<Out, Bit>,
    /// Node 0: bad words at INPUT.
    pub o_perr0: Signal<Out, Bits<16>>,
    /// Node 1: home slot.
    pub i_address1: Signal<In, Bits<12>>,
    /// Node 1: actuator (1) or sensor (0).
    pub i_actuator1: Signal<In, Bit>,
    /// Node 1: sensor value.
    pub i_sensor1: Signal<In, Bits<16>>,
    /// Node 1: user interrupt 1 request.
    pub i_irq1_1: Signal<In, Bit>,
    /// Node 1: actuator output.
    pub o_act1: Signal<Out, Bits<16>>,
    /// Node 1: mode.
    pub o_mode1: Signal<Out, Bits<2>>,
    /// Node 1: failsafe.
    pub o_fs1: Signal<Out, Bit>,
    /// Node 1: bad words at INPUT.
    pub o_perr1: Signal<Out, Bits<16>>,
    /// Node 2: home slot.
    pub i_address2: Signal<In, Bits<12>>,
    /// Node 2: actuator (1) or sensor (0).
    pub i_actuator2: Signal<In, Bit>,
    /// Node 2: sensor value.
    pub i_sensor2: Signal<In, Bits<16>>,
    /// Node 2: user interrupt 1 request.
    pub i_irq1_2: Signal<In, Bit>,
    /// Node 2: actuator output.
    pub o_act2: Signal<Out, Bits<16>>,
    /// Node 2: mode.
    pub o_mode2: Signal<Out, Bits<2>>,
    /// Node 2: failsafe.
    pub o_fs2: Signal<Out, Bit>,
    /// Node 2: bad words at INPUT.
    pub o_perr2: Signal<Out, Bits<16>>,
    /// Node 3: home slot.
    pub i_address3: Signal<In, Bits<12>>,
    /// Node 3: actuator (1) or sensor (0).
    pub i_actuator3: Signal<In, Bit>,
    /// Node 3: sensor value.
    pub i_sensor3: Signal<In, Bits<16>>,
    /// Node 3: user interrupt 1 request.
    pub i_irq1_3: Signal<In, Bit>,
    /// Node 3: actuator output.
    pub o_act3: Signal<Out, Bits<16>>,
    /// Node 3: mode.
    pub o_mode3: Signal<Out, Bits<2>>,
    /// Node 3: failsafe.
    pub o_fs3: Signal<Out, Bit>,
    /// Node 3: bad words at INPUT.
    pub o_perr3: Signal<Out, Bits<16>>,
    /// Node 4: home slot.
    pub i_address4: Signal<In, Bits<12>>,
    /// Node 4: actuator (1) or sensor (0).
    pub i_actuator4: Signal<In, Bit>,
    /// Node 4: sensor value.
    pub i_sensor4: Signal<In, Bits<16>>,
    /// Node 4: user interrupt 1 request.
    pub i_irq1_4: Signal<In, Bit>,
    /// Node 4: actuator output.
    pub o_act4: Signal<Out, Bits<16>>,
    /// Node 4: mode.
    pub o_mode4: Signal<Out, Bits<2>>,
    /// Node 4: failsafe.
    pub o_fs4: Signal<Out, Bit>,
    /// Node 4: bad words at INPUT.
    pub o_perr4: Signal<Out, Bits<16>>,
    /// Node 5: home slot.
    pub i_address5: Signal<In, Bits<12>>,
    /// Node 5: actuator (1) or sensor (0).
    pub i_actuator5: Signal<In, Bit>,
    /// Node 5: sensor value.
    pub i_sensor5: Signal<In, Bits<16>>,
    /// Node 5: user interrupt 1 request.
    pub i_irq1_5: Signal<In, Bit>,
    /// Node 5: actuator output.
    pub o_act5: Signal<Out, Bits<16>>,
    /// Node 5: mode.
    pub o_mode5: Signal<Out, Bits<2>>,
    /// Node 5: failsafe.
    pub o_fs5: Signal<Out, Bit>,
    /// Node 5: bad words at INPUT.
    pub o_perr5: Signal<Out, Bits<16>>,
    /// Node 6: home slot.
    pub i_address6: Signal<In, Bits<12>>,
    /// Node 6: actuator (1) or sensor (0).
    pub i_actuator6: Signal<In, Bit>,
    /// Node 6: sensor value.
    pub i_sensor6: Signal<In, Bits<16>>,
    /// Node 6: user interrupt 1 request.
    pub i_irq1_6: Signal<In, Bit>,
    /// Node 6: actuator output.
    pub o_act6: Signal<Out, Bits<16>>,
    /// Node 6: mode.
    pub o_mode6: Signal<Out, Bits<2>>,
    /// Node 6: failsafe.
    pub o_fs6: Signal<Out, Bit>,
    /// Node 6: bad words at INPUT.
    pub o_perr6: Signal<Out, Bits<16>>,
    /// Node 7: home slot.
    pub i_address7: Signal<In, Bits<12>>,
    /// Node 7: actuator (1) or sensor (0).
    pub i_actuator7: Signal<In, Bit>,
    /// Node 7: sensor value.
    pub i_sensor7: Signal<In, Bits<16>>,
    /// Node 7: user interrupt 1 request.
    pub i_irq1_7: Signal<In, Bit>,
    /// Node 7: actuator output.
    pub o_act7: Signal<Out, Bits<16>>,
    /// Node 7: mode.
    pub o_mode7: Signal<Out, Bits<2>>,
    /// Node 7: failsafe.
    pub o_fs7: Signal<Out, Bit>,
    /// Node 7: bad words at INPUT.
    pub o_perr7: Signal<Out, Bits<16>>,
    n0: Slave,
    n1: Slave,
    n2: Slave,
    n3: Slave,
    n4: Slave,
    n5: Slave,
    n6: Slave,
    n7: Slave,
    lp1: Loopback,
    lp2: Loopback,
    lp3: Loopback,
    lp4: Loopback,
    lp5: Loopback,
    lp6: Loopback,
    lp7: Loopback,
    ls0: Loopback,
    ls1: Loopback,
    ls2: Loopback,
    ls3: Loopback,
    ls4: Loopback,
    ls5: Loopback,
    ls6: Loopback,
}

impl Logic for Chain8 {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        self.n0.clock.next = self.clock.val();
        self.n0.i_slots_m1.next = self.i_slots_m1.val();
        self.n0.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n0.i_address.next = self.i_address0.val();
        self.n0.i_actuator.next = self.i_actuator0.val();
        self.n0.i_sensor_data.next = self.i_sensor0.val();
        self.n0.i_irq1.next = self.i_irq1_0.val();
        self.n0.i_irq2.next = false;
        self.n0.i_fs_req.next = false;
        self.n0.i_master.next = false;
        self.n0.i_slot_cfg.next = 0.into();
        self.n0.i_slot_data.next = 0.into();
        self.n0.i_slot_alive.next = false;
        self.n0.i_fs_set.next = false;
        self.n0.i_cap_sel.next = false;
        self.o_act0.next = self.n0.o_act_data.val();
        self.o_mode0.next = self.n0.o_mode.val();
        self.o_fs0.next = self.n0.o_failsafe.val();
        self.o_perr0.next = self.n0.o_perr.val();
        self.n0.i_pi.next = self.i_pi.val();
        self.o_so.next = self.n0.o_so.val();
        self.n1.clock.next = self.clock.val();
        self.n1.i_slots_m1.next = self.i_slots_m1.val();
        self.n1.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n1.i_address.next = self.i_address1.val();
        self.n1.i_actuator.next = self.i_actuator1.val();
        self.n1.i_sensor_data.next = self.i_sensor1.val();
        self.n1.i_irq1.next = self.i_irq1_1.val();
        self.n1.i_irq2.next = false;
        self.n1.i_fs_req.next = false;
        self.n1.i_master.next = false;
        self.n1.i_slot_cfg.next = 0.into();
        self.n1.i_slot_data.next = 0.into();
        self.n1.i_slot_alive.next = false;
        self.n1.i_fs_set.next = false;
        self.n1.i_cap_sel.next = false;
        self.o_act1.next = self.n1.o_act_data.val();
        self.o_mode1.next = self.n1.o_mode.val();
        self.o_fs1.next = self.n1.o_failsafe.val();
        self.o_perr1.next = self.n1.o_perr.val();
        self.lp1.i_pair.next = self.n0.o_po.val();
        self.n1.i_pi.next = self.lp1.o_samples.val();
        self.ls0.i_pair.next = self.n1.o_so.val();
        self.n0.i_si.next = self.ls0.o_samples.val();
        self.n2.clock.next = self.clock.val();
        self.n2.i_slots_m1.next = self.i_slots_m1.val();
        self.n2.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n2.i_address.next = self.i_address2.val();
        self.n2.i_actuator.next = self.i_actuator2.val();
        self.n2.i_sensor_data.next = self.i_sensor2.val();
        self.n2.i_irq1.next = self.i_irq1_2.val();
        self.n2.i_irq2.next = false;
        self.n2.i_fs_req.next = false;
        self.n2.i_master.next = false;
        self.n2.i_slot_cfg.next = 0.into();
        self.n2.i_slot_data.next = 0.into();
        self.n2.i_slot_alive.next = false;
        self.n2.i_fs_set.next = false;
        self.n2.i_cap_sel.next = false;
        self.o_act2.next = self.n2.o_act_data.val();
        self.o_mode2.next = self.n2.o_mode.val();
        self.o_fs2.next = self.n2.o_failsafe.val();
        self.o_perr2.next = self.n2.o_perr.val();
        self.lp2.i_pair.next = self.n1.o_po.val();
        self.n2.i_pi.next = self.lp2.o_samples.val();
        self.ls1.i_pair.next = self.n2.o_so.val();
        self.n1.i_si.next = self.ls1.o_samples.val();
        self.n3.clock.next = self.clock.val();
        self.n3.i_slots_m1.next = self.i_slots_m1.val();
        self.n3.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n3.i_address.next = self.i_address3.val();
        self.n3.i_actuator.next = self.i_actuator3.val();
        self.n3.i_sensor_data.next = self.i_sensor3.val();
        self.n3.i_irq1.next = self.i_irq1_3.val();
        self.n3.i_irq2.next = false;
        self.n3.i_fs_req.next = false;
        self.n3.i_master.next = false;
        self.n3.i_slot_cfg.next = 0.into();
        self.n3.i_slot_data.next = 0.into();
        self.n3.i_slot_alive.next = false;
        self.n3.i_fs_set.next = false;
        self.n3.i_cap_sel.next = false;
        self.o_act3.next = self.n3.o_act_data.val();
        self.o_mode3.next = self.n3.o_mode.val();
        self.o_fs3.next = self.n3.o_failsafe.val();
        self.o_perr3.next = self.n3.o_perr.val();
        self.lp3.i_pair.next = self.n2.o_po.val();
        self.n3.i_pi.next = self.lp3.o_samples.val();
        self.ls2.i_pair.next = self.n3.o_so.val();
        self.n2.i_si.next = self.ls2.o_samples.val();
        self.n4.clock.next = self.clock.val();
        self.n4.i_slots_m1.next = self.i_slots_m1.val();
        self.n4.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n4.i_address.next = self.i_address4.val();
        self.n4.i_actuator.next = self.i_actuator4.val();
        self.n4.i_sensor_data.next = self.i_sensor4.val();
        self.n4.i_irq1.next = self.i_irq1_4.val();
        self.n4.i_irq2.next = false;
        self.n4.i_fs_req.next = false;
        self.n4.i_master.next = false;
        self.n4.i_slot_cfg.next = 0.into();
        self.n4.i_slot_data.next = 0.into();
        self.n4.i_slot_alive.next = false;
        self.n4.i_fs_set.next = false;
        self.n4.i_cap_sel.next = false;
        self.o_act4.next = self.n4.o_act_data.val();
        self.o_mode4.next = self.n4.o_mode.val();
        self.o_fs4.next = self.n4.o_failsafe.val();
        self.o_perr4.next = self.n4.o_perr.val();
        self.lp4.i_pair.next = self.n3.o_po.val();
        self.n4.i_pi.next = self.lp4.o_samples.val();
        self.ls3.i_pair.next = self.n4.o_so.val();
        self.n3.i_si.next = self.ls3.o_samples.val();
        self.n5.clock.next = self.clock.val();
        self.n5.i_slots_m1.next = self.i_slots_m1.val();
        self.n5.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n5.i_address.next = self.i_address5.val();
        self.n5.i_actuator.next = self.i_actuator5.val();
        self.n5.i_sensor_data.next = self.i_sensor5.val();
        self.n5.i_irq1.next = self.i_irq1_5.val();
        self.n5.i_irq2.next = false;
        self.n5.i_fs_req.next = false;
        self.n5.i_master.next = false;
        self.n5.i_slot_cfg.next = 0.into();
        self.n5.i_slot_data.next = 0.into();
        self.n5.i_slot_alive.next = false;
        self.n5.i_fs_set.next = false;
        self.n5.i_cap_sel.next = false;
        self.o_act5.next = self.n5.o_act_data.val();
        self.o_mode5.next = self.n5.o_mode.val();
        self.o_fs5.next = self.n5.o_failsafe.val();
        self.o_perr5.next = self.n5.o_perr.val();
        self.lp5.i_pair.next = self.n4.o_po.val();
        self.n5.i_pi.next = self.lp5.o_samples.val();
        self.ls4.i_pair.next = self.n5.o_so.val();
        self.n4.i_si.next = self.ls4.o_samples.val();
        self.n6.clock.next = self.clock.val();
        self.n6.i_slots_m1.next = self.i_slots_m1.val();
        self.n6.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n6.i_address.next = self.i_address6.val();
        self.n6.i_actuator.next = self.i_actuator6.val();
        self.n6.i_sensor_data.next = self.i_sensor6.val();
        self.n6.i_irq1.next = self.i_irq1_6.val();
        self.n6.i_irq2.next = false;
        self.n6.i_fs_req.next = false;
        self.n6.i_master.next = false;
        self.n6.i_slot_cfg.next = 0.into();
        self.n6.i_slot_data.next = 0.into();
        self.n6.i_slot_alive.next = false;
        self.n6.i_fs_set.next = false;
        self.n6.i_cap_sel.next = false;
        self.o_act6.next = self.n6.o_act_data.val();
        self.o_mode6.next = self.n6.o_mode.val();
        self.o_fs6.next = self.n6.o_failsafe.val();
        self.o_perr6.next = self.n6.o_perr.val();
        self.lp6.i_pair.next = self.n5.o_po.val();
        self.n6.i_pi.next = self.lp6.o_samples.val();
        self.ls5.i_pair.next = self.n6.o_so.val();
        self.n5.i_si.next = self.ls5.o_samples.val();
        self.n7.clock.next = self.clock.val();
        self.n7.i_slots_m1.next = self.i_slots_m1.val();
        self.n7.i_cs_timeout.next = self.i_cs_timeout.val();
        self.n7.i_address.next = self.i_address7.val();
        self.n7.i_actuator.next = self.i_actuator7.val();
        self.n7.i_sensor_data.next = self.i_sensor7.val();
        self.n7.i_irq1.next = self.i_irq1_7.val();
        self.n7.i_irq2.next = false;
        self.n7.i_fs_req.next = false;
        self.n7.i_master.next = false;
        self.n7.i_slot_cfg.next = 0.into();
        self.n7.i_slot_data.next = 0.into();
        self.n7.i_slot_alive.next = false;
        self.n7.i_fs_set.next = false;
        self.n7.i_cap_sel.next = false;
        self.o_act7.next = self.n7.o_act_data.val();
        self.o_mode7.next = self.n7.o_mode.val();
        self.o_fs7.next = self.n7.o_failsafe.val();
        self.o_perr7.next = self.n7.o_perr.val();
        self.lp7.i_pair.next = self.n6.o_po.val();
        self.n7.i_pi.next = self.lp7.o_samples.val();
        self.ls6.i_pair.next = self.n7.o_so.val();
        self.n6.i_si.next = self.ls6.o_samples.val();
        self.o_po.next = self.n7.o_po.val();
        self.n7.i_si.next = self.i_si.val();
    }
}
