//! # rmm_fcm — the fault correction machine (docs/protocol.md §21)
//!
//! Purpose: the paper's Fault Correction Sub-module: exactly five states
//! and the transitions of its section 3, one octet per step. Priorities
//! (first match wins):
//!
//! | from | condition | to | action / cause |
//! |---|---|---|---|
//! | any but IDLE | both channels bad | IDLE | `both`; pending commands dropped |
//! | IDLE | initialised (`i_init`) and not both bad | Manual_Normal | `init` |
//! | Manual_Normal | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
//! | Manual_Normal | Status Check = OK | Auto_Normal | `check_ok` |
//! | Manual_Normal | AUTO_SW_MODE | Auto_Normal | `auto_cmd` |
//! | Manual_Normal | Status Check = SWITCH | Manual_Normal | switch to the standby between frames; `check_sw` |
//! | Auto_Normal | active fault or NS, standby faulty | Manual_Normal | `standby_fault` |
//! | Auto_Normal | active fault or NS | Medium_Error | switch **now**; `active_fault` / `ns` |
//! | Auto_Normal | standby faulty | Manual_Normal | dual mode off; `standby_fault` |
//! | Auto_Normal | SC | Config_Error | broadcast the switch command; `sc` |
//! | Auto_Normal | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
//! | Auto_Normal | Status Check = SWITCH | Manual_Normal | switch to the standby between frames; `check_sw` |
//! | Medium_Error | — | Manual_Normal | `switched` |
//! | Config_Error | switch command received | Manual_Normal | switch between frames; `cmd_rx` |
//! | Config_Error | own command sent | Manual_Normal | switch between frames; `cmd_sent` |
//!
//! "Active fault" is the DCM's combinational fault of the active channel
//! this octet; "standby faulty" its combinational fault or latched `bad`.
//! A commanded switch (a switch command, or the status check's switch)
//! waits while the MAC is inside a frame (`i_in_frame`) and never falls in
//! the octet of a fault switch. Every transition or
//! command writes the cause register and raises the report interrupt
//! (`o_irq`, one octet).
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | octet clock |
//! | `i_init`, `i_auto` | in | 1 | host: initialised (level), AUTO_SW_MODE (pulse) |
//! | `i_sc`, `i_ns` | in | 1 | from rmm_detect |
//! | `i_chk_ok`, `i_chk_sw` | in | 1 | from rmm_sfc: Status Check = OK, = SWITCH |
//! | `i_fault_a`, `i_fault_b`, `i_bad_a`, `i_bad_b`, `i_act`, `i_in_frame` | in | 1 | from the DCM |
//! | `i_cmd_rx`, `i_cmd_ch` | in | 1 | MAC: switch command received, its target |
//! | `i_cmd_sent` | in | 1 | MAC: our command went out |
//! | `o_sw` | out | 1 | to the DCM: toggle the active channel now (combinational) |
//! | `o_state` | out | 3 | 0 IDLE, 1 Manual_Normal, 2 Auto_Normal, 3 Config_Error, 4 Medium_Error |
//! | `o_cause` | out | 4 | report register: cause of the last transition or command |
//! | `o_irq` | out | 1 | report interrupt |
//! | `o_cmd_req`, `o_cmd_ch` | out | 1 | to the MAC: broadcast the switch command to this channel |
//!
//! Latency: the state changes one octet after its condition; a fault switch
//! takes effect in the octet of the fault.
//!
//! ```text
//! octet      n            n+1           n+2
//! i_fault_a  1 (A active)
//! o_sw       1
//! o_state    Auto_Normal  Medium_Error  Manual_Normal
//! i_act      A            B             B
//! ```

use merkur_model::rmm::{cause, state};
use rust_hdl::prelude::*;

/// The fault correction machine.
#[derive(LogicBlock)]
pub struct RmmFcm {
    /// Octet clock.
    pub clock: Signal<In, Clock>,
    /// Host: initialisation finished.
    pub i_init: Signal<In, Bit>,
    /// Host: AUTO_SW_MODE.
    pub i_auto: Signal<In, Bit>,
    /// SC event.
    pub i_sc: Signal<In, Bit>,
    /// NS event.
    pub i_ns: Signal<In, Bit>,
    /// Status Check = OK.
    pub i_chk_ok: Signal<In, Bit>,
    /// Status Check = SWITCH.
    pub i_chk_sw: Signal<In, Bit>,
    /// Fault of A this octet.
    pub i_fault_a: Signal<In, Bit>,
    /// Fault of B this octet.
    pub i_fault_b: Signal<In, Bit>,
    /// A faulty (latched).
    pub i_bad_a: Signal<In, Bit>,
    /// B faulty (latched).
    pub i_bad_b: Signal<In, Bit>,
    /// Active channel.
    pub i_act: Signal<In, Bit>,
    /// The MAC is inside a frame.
    pub i_in_frame: Signal<In, Bit>,
    /// Switch command received.
    pub i_cmd_rx: Signal<In, Bit>,
    /// Its target channel.
    pub i_cmd_ch: Signal<In, Bit>,
    /// Our switch command went out.
    pub i_cmd_sent: Signal<In, Bit>,
    /// Toggle the active channel now.
    pub o_sw: Signal<Out, Bit>,
    /// State.
    pub o_state: Signal<Out, Bits<3>>,
    /// Cause of the last transition.
    pub o_cause: Signal<Out, Bits<4>>,
    /// Report interrupt.
    pub o_irq: Signal<Out, Bit>,
    /// Broadcast the switch command.
    pub o_cmd_req: Signal<Out, Bit>,
    /// Its target channel.
    pub o_cmd_ch: Signal<Out, Bit>,
    s_idle: Constant<Bits<3>>,
    s_manual: Constant<Bits<3>>,
    s_auto: Constant<Bits<3>>,
    s_config: Constant<Bits<3>>,
    s_medium: Constant<Bits<3>>,
    c_init: Constant<Bits<4>>,
    c_check_ok: Constant<Bits<4>>,
    c_auto_cmd: Constant<Bits<4>>,
    c_active_fault: Constant<Bits<4>>,
    c_ns: Constant<Bits<4>>,
    c_standby_fault: Constant<Bits<4>>,
    c_sc: Constant<Bits<4>>,
    c_cmd_rx: Constant<Bits<4>>,
    c_cmd_sent: Constant<Bits<4>>,
    c_switched: Constant<Bits<4>>,
    c_both: Constant<Bits<4>>,
    c_check_sw: Constant<Bits<4>>,
    st: DFF<Bits<3>>,
    cause: DFF<Bits<4>>,
    irq: DFF<Bit>,
    pend: DFF<Bit>,
    pend_ch: DFF<Bit>,
    cmd_req: DFF<Bit>,
    cmd_ch: DFF<Bit>,
    f_act: Signal<Local, Bit>,
    f_stb: Signal<Local, Bit>,
    b_stb: Signal<Local, Bit>,
    both: Signal<Local, Bit>,
    cs_set: Signal<Local, Bit>,
    cs: Signal<Local, Bits<4>>,
    new_cmd: Signal<Local, Bit>,
    sw_now: Signal<Local, Bit>,
    sw_cmd: Signal<Local, Bit>,
}

fn k3(v: u8) -> Constant<Bits<3>> {
    Constant::new((v as u64).to_bits())
}

fn k4(v: u8) -> Constant<Bits<4>> {
    Constant::new((v as u64).to_bits())
}

impl Default for RmmFcm {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            i_init: Default::default(),
            i_auto: Default::default(),
            i_sc: Default::default(),
            i_ns: Default::default(),
            i_chk_ok: Default::default(),
            i_chk_sw: Default::default(),
            i_fault_a: Default::default(),
            i_fault_b: Default::default(),
            i_bad_a: Default::default(),
            i_bad_b: Default::default(),
            i_act: Default::default(),
            i_in_frame: Default::default(),
            i_cmd_rx: Default::default(),
            i_cmd_ch: Default::default(),
            i_cmd_sent: Default::default(),
            o_sw: Default::default(),
            o_state: Default::default(),
            o_cause: Default::default(),
            o_irq: Default::default(),
            o_cmd_req: Default::default(),
            o_cmd_ch: Default::default(),
            s_idle: k3(state::IDLE),
            s_manual: k3(state::MANUAL_NORMAL),
            s_auto: k3(state::AUTO_NORMAL),
            s_config: k3(state::CONFIG_ERROR),
            s_medium: k3(state::MEDIUM_ERROR),
            c_init: k4(cause::INIT),
            c_check_ok: k4(cause::CHECK_OK),
            c_auto_cmd: k4(cause::AUTO_CMD),
            c_active_fault: k4(cause::ACTIVE_FAULT),
            c_ns: k4(cause::NS),
            c_standby_fault: k4(cause::STANDBY_FAULT),
            c_sc: k4(cause::SC),
            c_cmd_rx: k4(cause::CMD_RX),
            c_cmd_sent: k4(cause::CMD_SENT),
            c_switched: k4(cause::SWITCHED),
            c_both: k4(cause::BOTH),
            c_check_sw: k4(cause::CHECK_SW),
            st: Default::default(),
            cause: Default::default(),
            irq: Default::default(),
            pend: Default::default(),
            pend_ch: Default::default(),
            cmd_req: Default::default(),
            cmd_ch: Default::default(),
            f_act: Default::default(),
            f_stb: Default::default(),
            b_stb: Default::default(),
            both: Default::default(),
            cs_set: Default::default(),
            cs: Default::default(),
            new_cmd: Default::default(),
            sw_now: Default::default(),
            sw_cmd: Default::default(),
        }
    }
}

impl Logic for RmmFcm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, st, cause, irq, pend, pend_ch, cmd_req, cmd_ch);
        if self.i_act.val() {
            self.f_act.next = self.i_fault_b.val();
            self.f_stb.next = self.i_fault_a.val();
            self.b_stb.next = self.i_bad_a.val();
        } else {
            self.f_act.next = self.i_fault_a.val();
            self.f_stb.next = self.i_fault_b.val();
            self.b_stb.next = self.i_bad_b.val();
        }
        self.both.next = self.i_bad_a.val() & self.i_bad_b.val();
        self.cs_set.next = false;
        self.cs.next = self.cause.q.val();
        self.new_cmd.next = false;
        self.sw_now.next = false;
        if (self.st.q.val() != self.s_idle.val()) & self.both.val() {
            self.st.d.next = self.s_idle.val();
            self.cs_set.next = true;
            self.cs.next = self.c_both.val();
            self.pend.d.next = false;
            self.cmd_req.d.next = false;
        } else if self.st.q.val() == self.s_idle.val() {
            if self.i_init.val() & !self.both.val() {
                self.st.d.next = self.s_manual.val();
                self.cs_set.next = true;
                self.cs.next = self.c_init.val();
            }
        } else if self.st.q.val() == self.s_manual.val() {
            if self.i_cmd_rx.val() {
                self.pend.d.next = true;
                self.pend_ch.d.next = self.i_cmd_ch.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_cmd_rx.val();
            } else if self.i_chk_ok.val() {
                self.st.d.next = self.s_auto.val();
                self.cs_set.next = true;
                self.cs.next = self.c_check_ok.val();
            } else if self.i_auto.val() {
                self.st.d.next = self.s_auto.val();
                self.cs_set.next = true;
                self.cs.next = self.c_auto_cmd.val();
            } else if self.i_chk_sw.val() {
                self.pend.d.next = true;
                self.pend_ch.d.next = !self.i_act.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_check_sw.val();
            }
        } else if self.st.q.val() == self.s_auto.val() {
            if self.f_act.val() | self.i_ns.val() {
                self.cs_set.next = true;
                if self.f_stb.val() | self.b_stb.val() {
                    self.st.d.next = self.s_manual.val();
                    self.cs.next = self.c_standby_fault.val();
                } else {
                    self.st.d.next = self.s_medium.val();
                    self.sw_now.next = true;
                    if self.f_act.val() {
                        self.cs.next = self.c_active_fault.val();
                    } else {
                        self.cs.next = self.c_ns.val();
                    }
                }
            } else if self.f_stb.val() | self.b_stb.val() {
                self.st.d.next = self.s_manual.val();
                self.cs_set.next = true;
                self.cs.next = self.c_standby_fault.val();
            } else if self.i_sc.val() {
                self.st.d.next = self.s_config.val();
                self.cs_set.next = true;
                self.cs.next = self.c_sc.val();
                self.cmd_req.d.next = true;
                self.cmd_ch.d.next = !self.i_act.val();
            } else if self.i_cmd_rx.val() {
                self.st.d.next = self.s_manual.val();
                self.pend.d.next = true;
                self.pend_ch.d.next = self.i_cmd_ch.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_cmd_rx.val();
            } else if self.i_chk_sw.val() {
                self.st.d.next = self.s_manual.val();
                self.pend.d.next = true;
                self.pend_ch.d.next = !self.i_act.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_check_sw.val();
            }
        } else if self.st.q.val() == self.s_medium.val() {
            self.st.d.next = self.s_manual.val();
            self.cs_set.next = true;
            self.cs.next = self.c_switched.val();
        } else if self.st.q.val() == self.s_config.val() {
            if self.i_cmd_rx.val() {
                self.st.d.next = self.s_manual.val();
                self.cmd_req.d.next = false;
                self.pend.d.next = true;
                self.pend_ch.d.next = self.i_cmd_ch.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_cmd_rx.val();
            } else if self.i_cmd_sent.val() {
                self.st.d.next = self.s_manual.val();
                self.cmd_req.d.next = false;
                self.pend.d.next = true;
                self.pend_ch.d.next = self.cmd_ch.q.val();
                self.new_cmd.next = true;
                self.cs_set.next = true;
                self.cs.next = self.c_cmd_sent.val();
            }
        }
        // The commanded switch, between frames.
        self.sw_cmd.next = false;
        if self.pend.q.val() & !self.i_in_frame.val() & !self.sw_now.val() {
            self.sw_cmd.next = self.pend_ch.q.val() != self.i_act.val();
            if !self.new_cmd.val() {
                self.pend.d.next = false;
            }
        }
        self.o_sw.next = self.sw_now.val() | self.sw_cmd.val();
        self.cause.d.next = self.cs.val();
        self.irq.d.next = self.cs_set.val();
        self.o_state.next = self.st.q.val();
        self.o_cause.next = self.cause.q.val();
        self.o_irq.next = self.irq.q.val();
        self.o_cmd_req.next = self.cmd_req.q.val();
        self.o_cmd_ch.next = self.cmd_ch.q.val();
    }
}
