//! # mdb — a master's real-time database: memories, host port, Alive check, interrupts
//!
//! Purpose: the part every master (and the special master) has beside its
//! ring logic (protocol §7, §11; the paper's Figure 7):
//! - **data memory** 4096 × 16 (one block-RAM port pair), the real-time
//!   database: the ring side reads slot `i_tx_slot` for what the node sends
//!   and writes every good word of a slot it does not write itself; the host
//!   reads and writes it through Wishbone;
//! - **configuration memory**, one byte per slot (bits 0 LAST, 1 ACT,
//!   2 ALIVE_EN, 3 LOCAL; bits 3:1 kept), in two copies (ring send side,
//!   ring receive side + host), writable only before the ring runs. LAST
//!   is not stored (protocol §7: the header carries S − 1): the host reads
//!   it as 1 for slot `i_slots_m1`. Bit 0 of each copy holds ring state
//!   instead: the receive copy's, the SEQ that a new alarm of that slot
//!   has (the inverse of the last one read there; 0 after reset and after
//!   a configuration write); the send copy's, the slot's has-value bit
//!   (below);
//! - **Alive check** per slot with ALIVE_EN (state memory: valid, last
//!   Alive, lost, and the CYC that wrote it, so a slot missing in the
//!   previous cycle is not compared), counted in `aerr`;
//! - **interrupts and the alarm queue** (protocol §11): every good alarm
//!   word in a slot other than the home slot (outside failsafe) that is
//!   not a repeat (its SEQ equal to the slot's last, §11) pulses
//!   `o_irq1` / `o_irq2` / `o_irq_fs` / `o_irq_rc` (RECONFIG, reasons 4–6)
//!   by its reason and goes into a 16-entry queue `{reason, slot, CYC}` that
//!   the host reads oldest first; a full queue keeps its entries and counts
//!   the alarm it could not keep (`overflow`); `o_alarmq` is high while the
//!   queue is not empty. The queue is one 32 × 16 memory (one block RAM),
//!   an entry's two words written in two clocks (received words are 25 bit
//!   times apart, so alarms are too). `o_irq_fsc` pulses when the node enters or leaves
//!   failsafe (the status register's bit 3 says which; protocol §12).
//!
//! Every memory here is written 4096 deep (the 12-bit slot number); the
//! Verilog that simulation and synthesis use is sized to the ring's slot
//! count ([`crate::emit::verilog::size_memories`]): slots beyond it read 0 from
//! the host port and take no writes.
//!
//! Host port: **Wishbone B4 classic** (16-bit data, 14-bit word address),
//! one transfer per `i_wb_cyc & i_wb_stb`, acknowledged after 1–4 clocks:
//!
//! | address | R/W | meaning |
//! |---|---|---|
//! | 0x0000–0x0FFF | R/W | data memory, slot = address; a write to a slot that is neither LOCAL nor ACT is refused (not written, `status[2]` set) |
//! | 0x1000–0x1FFF | R/W | configuration byte of slot address − 0x1000; a write while running is refused (`status[1]` set); LAST (bit 0) is not stored and reads 1 for slot `i_slots_m1` |
//! | 0x2000 | R | status: 0 running, 1 config write refused, 2 data write refused, 3 failsafe, 5:4 mode, 6 FS_HOST, 7 FS_CLEAR given and not yet used, 8 started by JOIN, 9 the reload frame not yet read |
//! | 0x2000 | W | bit 0 = 1: start (the ring runs, configuration locked); bits 1, 2 = 1: clear those flags; bit 3 = 1: stop (a special master sends no more frames); bit 4 = 1: FS_CLEAR, the host allows the ring out of failsafe (a special master; protocol §12); bit 5: FS_HOST, the ring leaves failsafe only after FS_CLEAR (a special master; written before the start, refused while running: `status[1]`); bit 6 = 1: JOIN, start after a restart (below; refused while running: `status[1]`) |
//! | 0x2001 | R | `aerr` Alive-check failures (saturating) |
//! | 0x2002 | R | last alarm delivered: reason `[15:12]`, slot `[11:0]` |
//! | 0x2003 | R | alarm queue, oldest entry: reason `[15:12]`, slot `[11:0]` (0: the queue is empty) |
//! | 0x2004 | R | alarm queue: entries `[4:0]` (0–16), CYC of the oldest entry `[14:12]` |
//! | 0x2004 | W | bit 0 = 1: remove the oldest entry (none: ignored); bit 1 = 1: clear the overflow count |
//! | 0x2005 | R | alarm queue overflow: alarms not kept because the queue was full (saturating) |
//!
//! **Restart (protocol §12).** A master that got power again is started
//! with JOIN (`0x2000` bit 6) instead of bit 0, after its host loaded the
//! configuration again: its first frame read with a good header outside
//! failsafe is the **reload frame**, in which it writes nothing (`o_tx_cfg` 0);
//! and each of its own slots (LOCAL or ACT) has a value only once a good
//! data word came by in it (taken into the data memory, which it otherwise
//! never does for its own slots) or its host wrote it — one has-value bit
//! per slot, zero at power-up, in the send copy of the configuration
//! (bit 0: LAST is not stored), so no memory grows; the receive side reads
//! it in the clock a word arrives (the send side's look-up waits that
//! clock).
//! Until then the send side reports the slot as one it does not write (but
//! for an alarm in its home slot, `o_tx_cfg` 3). A
//! master started with bit 0 has a value for every slot from the start.
//!
//! A host drains the queue with: read 0x2004; while entries > 0, read 0x2003
//! (and 0x2004's CYC), write 1 to 0x2004.
//!
//! Parameters: the word format ([`WordFormat`]): in the extended-alarm
//! variant (protocol §6) an alarm's reason and SEQ come from the reason
//! nibble `i_reason` and its data is taken like a data word's.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `clock` | in | 1 | — | core clock |
//! | `i_wb_cyc`, `i_wb_stb`, `i_wb_we` | in | 1 | clock | Wishbone cycle, strobe, write enable |
//! | `i_wb_adr` | in | 14 | clock | Wishbone word address |
//! | `i_wb_dat` | in | 16 | clock | Wishbone write data |
//! | `o_wb_dat` | out | 16 | clock | Wishbone read data (valid with `o_wb_ack`) |
//! | `o_wb_ack` | out | 1 | clock | Wishbone acknowledge (one clock) |
//! | `i_home` | in | 12 | static | home slot (no interrupt for its own alarms) |
//! | `i_slots_m1` | in | 12 | static | slots per frame − 1 (the slot whose configuration reads LAST) |
//! | `i_fs` | in | 1 | clock | node in failsafe: no updates from the next frame header on (status bit at once) |
//! | `i_mode` | in | 2 | clock | switchbox mode (status register) |
//! | `i_wvalid`, `i_kind`, `i_slot`, `i_data`, `i_alive`, `i_alarm`, `i_reason`, `i_ok` | in | | clock | received words (from the node's INPUT port; `i_reason` the extended variant's reason nibble) |
//! | `i_rtx` | in | 1 | clock | the word is a retransmission's copy of slot `i_slot` (protocol §8; the node maps an RTX's good data word to `i_kind` = 2 and the slot its index word named): data memory only, no Alive check or state, no alarm, `o_s2_act` low |
//! | `i_hdr_bad` | in | 1 | clock | INPUT rejected a header: that frame was not read (no Alive check in the next one) |
//! | `i_tx_slot` | in | 12 | clock | slot the send side needs next |
//! | `o_tx_data` | out | 16 | clock | data memory of `i_tx_slot`, valid 2–4 clocks after it changes (the host's data reads and the received words take a clock of the look-up each) |
//! | `o_tx_cfg` | out | 2 | clock | what the node writes in `i_tx_slot` (same timing): 0 nothing, 1 LOCAL (its data), 2 ACT (its data, the actuator's Alive kept), 3 its home slot without a value (only an alarm, protocol §12); 0 in the reload frame; an own slot is 1 or 2 only with a value (always, but after JOIN see above). The one decision for the forwarder of a master (which writes only while `o_running`) and both send paths of a special master |
//! | `o_join` | out | 1 | clock | started by JOIN |
//! | `o_s2`, `o_s2_slot`, `o_s2_act`, `o_s2_ok`, `o_s2_alive`, `o_s2_alarm`, `o_s2_data`, `o_s2_rn` | out | | clock | the received slot word with its configuration, 2 clocks after `i_wvalid` |
//! | `o_cfgw`, `o_cfgw_slot`, `o_cfgw_crit` | out | 1, 12, 1 | clock | the host wrote slot `o_cfgw_slot`'s configuration byte (one clock, combinational from the bus), and its CRIT bit (bit 4, protocol §7; not stored here, and read back as 0) |
//! | `o_running` | out | 1 | clock | the host started the ring |
//! | `o_irq1`, `o_irq2`, `o_irq_fs`, `o_irq_rc` | out | 1 | clock | alarm received, by reason: IRQ1, IRQ2, FAILSAFE, RECONFIG 4–6 (one clock per alarm word) |
//! | `o_alarmq` | out | 1 | clock | the alarm queue is not empty (level) |
//! | `o_irq_fsc` | out | 1 | clock | failsafe changed (one clock, each way) |
//! | `o_fs_host`, `o_fs_clear` | out | 1 | clock | FS_HOST set; FS_CLEAR written (one clock) |
//! | `o_aerr` | out | 16 | clock | Alive-check failures |
//!
//! Latency: a good word is in the data memory 2 clocks after `i_wvalid`
//! (an own slot's taken after JOIN: 3, or 4 behind a host write).
//!
//! ```text
//! clock      _/‾\_/‾\_/‾\_/‾\_/‾\_
//! i_wvalid   _/‾‾‾\_______________     stage 1: read cfg, Alive state
//! o_s2       _____/‾‾‾\___________     stage 2: write data, Alive state; irq
//! wb stb     _/‾‾‾‾‾‾‾‾‾‾‾\_______
//! wb ack     _________/‾‾‾\_______     data read: 2 clocks
//! ```

use crate::line::word_rx::WordFormat;
use rust_hdl::prelude::*;

// Configuration bits: `merkur_model::config::cfg_bits` (LAST 1, ACT 2,
// ALIVE_EN 4, LOCAL 8); rust-hdl emits literals, so the logic below writes
// them as numbers and the ring test binds them to the model's constants.
/// Status register bit 0: running (write 1: start).
pub const ST_RUN: u16 = 1;
/// Status register bit 3 on write: stop (the special master sends no more frames).
pub const ST_STOP: u16 = 8;
/// Status register bit 4 on write: FS_CLEAR, the host allows the ring out of
/// failsafe (read: bit 7 until the special master uses it).
pub const ST_FS_CLEAR: u16 = 16;
/// Status register bit 5 on write: FS_HOST, leave failsafe only after
/// FS_CLEAR (read back at bit 6).
pub const ST_FS_HOST: u16 = 32;
/// Status register bit 6 on write: JOIN, start a restarted master (a
/// reload frame first, own slots without a value; protocol §12). Read:
/// bit 8 started by JOIN, bit 9 the reload frame not yet read.
pub const ST_JOIN: u16 = 64;
/// Wishbone address of the status / control register.
pub const WB_STATUS: u16 = 0x2000;
/// Wishbone address of the Alive error counter.
pub const WB_AERR: u16 = 0x2001;
/// Wishbone address of the last interrupt.
pub const WB_LAST_IRQ: u16 = 0x2002;
/// Wishbone address of the alarm queue's oldest entry.
pub const WB_ALQ_HEAD: u16 = 0x2003;
/// Wishbone address of the alarm queue's level and head CYC (write: remove,
/// clear overflow).
pub const WB_ALQ_CTL: u16 = 0x2004;
/// Wishbone address of the alarm queue's overflow count.
pub const WB_ALQ_OVF: u16 = 0x2005;
/// Alarm queue control bit 0 on write: remove the oldest entry.
pub const ALQ_POP: u16 = 1;
/// Alarm queue control bit 1 on write: clear the overflow count.
pub const ALQ_CLEAR_OVF: u16 = 2;
/// Entries of the alarm queue (protocol §11).
pub const ALQ_DEPTH: usize = 16;
/// Wishbone base of the configuration memory.
pub const WB_CFG: u16 = 0x1000;

/// A master's database.
#[derive(LogicBlock)]
pub struct Mdb {
    /// Core clock.
    pub clock: Signal<In, Clock>,
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
    /// Home slot.
    pub i_home: Signal<In, Bits<12>>,
    /// Slots − 1 (the slot whose configuration reads LAST).
    pub i_slots_m1: Signal<In, Bits<12>>,
    /// Failsafe.
    pub i_fs: Signal<In, Bit>,
    /// Switchbox mode.
    pub i_mode: Signal<In, Bits<2>>,
    /// Word valid.
    pub i_wvalid: Signal<In, Bit>,
    /// Word kind.
    pub i_kind: Signal<In, Bits<2>>,
    /// Word slot.
    pub i_slot: Signal<In, Bits<12>>,
    /// Word data.
    pub i_data: Signal<In, Bits<16>>,
    /// Word ALIVE.
    pub i_alive: Signal<In, Bit>,
    /// Word ALARM.
    pub i_alarm: Signal<In, Bit>,
    /// Received word's reason nibble (extended-alarm words; 0 otherwise).
    pub i_reason: Signal<In, Bits<4>>,
    /// Word good.
    pub i_ok: Signal<In, Bit>,
    /// The word (`i_kind` = 2) is a retransmission's copy of slot
    /// `i_slot` (protocol §8): taken without an Alive check, never an alarm.
    pub i_rtx: Signal<In, Bit>,
    /// A header was rejected at INPUT.
    pub i_hdr_bad: Signal<In, Bit>,
    /// Slot the send side needs.
    pub i_tx_slot: Signal<In, Bits<12>>,
    /// Data memory of `i_tx_slot`.
    pub o_tx_data: Signal<Out, Bits<16>>,
    /// What the node writes in `i_tx_slot`: 0 nothing, 1 LOCAL, 2 ACT, 3
    /// its home slot without a value (only an alarm).
    pub o_tx_cfg: Signal<Out, Bits<2>>,
    /// Started by JOIN (after a restart).
    pub o_join: Signal<Out, Bit>,
    /// Stage 2 valid.
    pub o_s2: Signal<Out, Bit>,
    /// Stage 2 slot.
    pub o_s2_slot: Signal<Out, Bits<12>>,
    /// Stage 2 slot is ACT.
    pub o_s2_act: Signal<Out, Bit>,
    /// The host wrote a configuration byte (one clock): its slot and its
    /// CRIT bit (bit 4, protocol §7), which the clock base keeps.
    pub o_cfgw: Signal<Out, Bit>,
    /// See `o_cfgw`.
    pub o_cfgw_slot: Signal<Out, Bits<12>>,
    /// See `o_cfgw`.
    pub o_cfgw_crit: Signal<Out, Bit>,
    /// Stage 2 good.
    pub o_s2_ok: Signal<Out, Bit>,
    /// Stage 2 ALIVE.
    pub o_s2_alive: Signal<Out, Bit>,
    /// Stage 2 ALARM.
    pub o_s2_alarm: Signal<Out, Bit>,
    /// Stage 2 data.
    pub o_s2_data: Signal<Out, Bits<16>>,
    /// Stage 2: its reason nibble (extended-alarm words).
    pub o_s2_rn: Signal<Out, Bits<4>>,
    /// Running.
    pub o_running: Signal<Out, Bit>,
    /// IRQ1 alarm received.
    pub o_irq1: Signal<Out, Bit>,
    /// IRQ2 alarm received.
    pub o_irq2: Signal<Out, Bit>,
    /// FAILSAFE alarm received.
    pub o_irq_fs: Signal<Out, Bit>,
    /// RECONFIG alarm (reason 4–6) received.
    pub o_irq_rc: Signal<Out, Bit>,
    /// The alarm queue is not empty.
    pub o_alarmq: Signal<Out, Bit>,
    /// Failsafe entered or left.
    pub o_irq_fsc: Signal<Out, Bit>,
    /// FS_HOST is set.
    pub o_fs_host: Signal<Out, Bit>,
    /// FS_CLEAR was written.
    pub o_fs_clear: Signal<Out, Bit>,
    /// The special master used the FS_CLEAR it was given.
    pub i_fs_cleared: Signal<In, Bit>,
    /// Alive-check failures.
    pub o_aerr: Signal<Out, Bits<16>>,
    db: RAM<Bits<16>, 12>,
    cfg_tx: RAM<Bits<4>, 12>,
    cfg_rx: RAM<Bits<4>, 12>,
    ast: RAM<Bits<6>, 12>,
    /// Started by JOIN (after a restart).
    join: DFF<Bit>,
    /// The reload frame: 0 none (read, or no JOIN), 1 JOIN given and no
    /// good header read since, 2 its header read (its words pass).
    rl: DFF<Bits<2>>,
    // Alarm queue, 16 entries of two words in one memory (one block RAM):
    // {reason, slot} at an even address, {CYC at bits 14:12} after it. The
    // pointers count in twos (bit 0 selects the word).
    alq: RAM<Bits<16>, 5>,
    alq_wr: DFF<Bits<5>>,
    alq_rd: DFF<Bits<5>>,
    alq_level: DFF<Bits<5>>,
    alq_ovf: DFF<Bits<16>>,
    /// An alarm delivered the clock before, and its first word (the queue
    /// decides a clock after stage 2: timing).
    alq_in: DFF<Bit>,
    alq_word: DFF<Bits<16>>,
    /// The entry's second word is written in this clock.
    alq_w2: DFF<Bit>,
    /// A removal the host asked for the clock before (it takes effect a
    /// clock after its transfer: timing).
    alq_out: DFF<Bit>,
    /// CYC of the frame being read, at bits 14:12 (the header's bits).
    hdr_cyc: DFF<Bits<16>>,
    /// CYC of the entry whose second word is due.
    alq_c: DFF<Bits<16>>,
    alq_push: Signal<Local, Bit>,
    alq_pop: Signal<Local, Bit>,
    alq_keep: Signal<Local, Bit>,
    // Send-side look-up.
    tx_served: DFF<Bit>,
    tx_data: DFF<Bits<16>>,
    tx_cfg: DFF<Bits<4>>,
    tx_home: DFF<Bit>,
    /// The host writes the data memory of the slot a received word in
    /// stage 1 is (its has-value bit was read before the write).
    hwsame: DFF<Bit>,
    // Stage 3 (protocol §12): a good data word of an own slot after JOIN,
    // taken if the slot has no value (its has-value bit registered here:
    // the block RAM's read data goes into no logic, timing).
    t3: DFF<Bit>,
    t3_hv: DFF<Bit>,
    t3_slot: DFF<Bits<12>>,
    t3_data: DFF<Bits<16>>,
    t3_cfg: DFF<Bits<4>>,
    // Receive pipeline.
    s2: DFF<Bit>,
    s2_rtx: DFF<Bit>,
    s2_slot: DFF<Bits<12>>,
    s2_ok: DFF<Bit>,
    s2_alive: DFF<Bit>,
    s2_alarm: DFF<Bit>,
    /// The word's configuration was read while the ring ran (so no host
    /// write can come between the read and the SEQ write).
    s2_run: DFF<Bit>,
    s2_data: DFF<Bits<16>>,
    // Extended-alarm words: the reason nibble of the word in stage 2, and
    // the alarm's reason and SEQ as the format carries them.
    ext: Constant<Bit>,
    s2_rn: DFF<Bits<4>>,
    s2_rsn: Signal<Local, Bits<4>>,
    s2_seq: Signal<Local, Bit>,
    irq1: DFF<Bit>,
    irq2: DFF<Bit>,
    irq_fs: DFF<Bit>,
    irq_rc: DFF<Bit>,
    irq_fsc: DFF<Bit>,
    fs_was: DFF<Bit>,
    fs_host: DFF<Bit>,
    fs_clear: DFF<Bit>,
    fs_clear_held: DFF<Bit>,
    aerr: DFF<Bits<16>>,
    last_irq: DFF<Bits<16>>,
    cur_cyc: DFF<Bits<3>>,
    fs_frame: DFF<Bit>,
    /// Since the last good header: a header rejected, so a frame was not
    /// read (CYC alone cannot tell 8 lost frames from none).
    unread: DFF<Bit>,
    /// The frame before this one was read (no rejected header and no
    /// failsafe frame between its header and this one's).
    read_prev: DFF<Bit>,
    // Host port.
    running: DFF<Bit>,
    err_cfg: DFF<Bit>,
    err_wr: DFF<Bit>,
    hstate: DFF<Bits<3>>,
    ack: DFF<Bit>,
    rdat: DFF<Bits<16>>,
    // The slot's configuration read for a host write (LOCAL or ACT may
    // be written), checked the clock after the read.
    perm: DFF<Bits<4>>,
    aerr_inc: DFF<Bit>,
    stat: Signal<Local, Bits<16>>,
    /// The send side's slot has a value to write (protocol §12).
    tx_value: Signal<Local, Bit>,
    irq_word: Signal<Local, Bits<16>>,
    s2_cfg: Signal<Local, Bits<4>>,
    s2_ast: Signal<Local, Bits<6>>,
    new_ast: Signal<Local, Bits<6>>,
    prev_cyc: Signal<Local, Bits<3>>,
    ast_valid: Signal<Local, Bit>,
    /// Stage 2: a good alarm word of another node's slot; FAILSAFE; not a
    /// repeat.
    s2_alrm: Signal<Local, Bit>,
    s2_fsr: Signal<Local, Bit>,
    s2_new: Signal<Local, Bit>,
    ast_word: Signal<Local, Bits<6>>,
    s2_write: Signal<Local, Bit>,
    /// Stage 2: the slot is the node's own (LOCAL or ACT).
    s2_own: Signal<Local, Bit>,
    /// Stage 3: the own slot's word is taken now (it had no value).
    s3_take: Signal<Local, Bit>,
    /// The host writes the data memory in this clock.
    host_wr: Signal<Local, Bit>,
    host_req: Signal<Local, Bit>,
    adr_data: Signal<Local, Bit>,
    adr_cfg: Signal<Local, Bit>,
}
impl Default for Mdb {
    fn default() -> Self {
        Self::new(WordFormat::Basic)
    }
}

impl Mdb {
    /// A database for words in `format` (protocol §4, §6).
    pub fn new(format: WordFormat) -> Self {
        Self {
            clock: Default::default(),
            i_wb_cyc: Default::default(),
            i_wb_stb: Default::default(),
            i_wb_we: Default::default(),
            i_wb_adr: Default::default(),
            i_wb_dat: Default::default(),
            o_wb_dat: Default::default(),
            o_wb_ack: Default::default(),
            i_home: Default::default(),
            i_slots_m1: Default::default(),
            i_fs: Default::default(),
            i_mode: Default::default(),
            i_wvalid: Default::default(),
            i_kind: Default::default(),
            i_slot: Default::default(),
            i_data: Default::default(),
            i_alive: Default::default(),
            i_alarm: Default::default(),
            i_reason: Default::default(),
            i_ok: Default::default(),
            i_rtx: Default::default(),
            i_hdr_bad: Default::default(),
            i_tx_slot: Default::default(),
            o_tx_data: Default::default(),
            o_tx_cfg: Default::default(),
            o_join: Default::default(),
            o_s2: Default::default(),
            o_s2_slot: Default::default(),
            o_s2_act: Default::default(),
            o_cfgw: Default::default(),
            o_cfgw_slot: Default::default(),
            o_cfgw_crit: Default::default(),
            o_s2_ok: Default::default(),
            o_s2_alive: Default::default(),
            o_s2_alarm: Default::default(),
            o_s2_data: Default::default(),
            o_s2_rn: Default::default(),
            o_running: Default::default(),
            o_irq1: Default::default(),
            o_irq2: Default::default(),
            o_irq_fs: Default::default(),
            o_irq_rc: Default::default(),
            o_alarmq: Default::default(),
            o_irq_fsc: Default::default(),
            o_fs_host: Default::default(),
            o_fs_clear: Default::default(),
            i_fs_cleared: Default::default(),
            o_aerr: Default::default(),
            db: Default::default(),
            cfg_tx: Default::default(),
            cfg_rx: Default::default(),
            ast: Default::default(),
            join: Default::default(),
            rl: Default::default(),
            alq: Default::default(),
            alq_wr: Default::default(),
            alq_rd: Default::default(),
            alq_level: Default::default(),
            alq_ovf: Default::default(),
            alq_in: Default::default(),
            alq_word: Default::default(),
            alq_w2: Default::default(),
            alq_out: Default::default(),
            hdr_cyc: Default::default(),
            alq_c: Default::default(),
            alq_push: Default::default(),
            alq_pop: Default::default(),
            alq_keep: Default::default(),
            tx_served: Default::default(),
            tx_data: Default::default(),
            tx_cfg: Default::default(),
            tx_home: Default::default(),
            hwsame: Default::default(),
            t3: Default::default(),
            t3_hv: Default::default(),
            t3_slot: Default::default(),
            t3_data: Default::default(),
            t3_cfg: Default::default(),
            s2: Default::default(),
            s2_rtx: Default::default(),
            s2_slot: Default::default(),
            s2_ok: Default::default(),
            s2_alive: Default::default(),
            s2_alarm: Default::default(),
            s2_run: Default::default(),
            s2_data: Default::default(),
            ext: Constant::new(format == WordFormat::ExtendedAlarm),
            s2_rn: Default::default(),
            s2_rsn: Default::default(),
            s2_seq: Default::default(),
            irq1: Default::default(),
            irq2: Default::default(),
            irq_fs: Default::default(),
            irq_rc: Default::default(),
            irq_fsc: Default::default(),
            fs_was: Default::default(),
            fs_host: Default::default(),
            fs_clear: Default::default(),
            fs_clear_held: Default::default(),
            aerr: Default::default(),
            last_irq: Default::default(),
            cur_cyc: Default::default(),
            fs_frame: Default::default(),
            unread: Default::default(),
            read_prev: Default::default(),
            running: Default::default(),
            err_cfg: Default::default(),
            err_wr: Default::default(),
            hstate: Default::default(),
            ack: Default::default(),
            rdat: Default::default(),
            perm: Default::default(),
            aerr_inc: Default::default(),
            stat: Default::default(),
            tx_value: Default::default(),
            irq_word: Default::default(),
            s2_cfg: Default::default(),
            s2_ast: Default::default(),
            new_ast: Default::default(),
            prev_cyc: Default::default(),
            ast_valid: Default::default(),
            s2_alrm: Default::default(),
            s2_fsr: Default::default(),
            s2_new: Default::default(),
            ast_word: Default::default(),
            s2_write: Default::default(),
            s2_own: Default::default(),
            s3_take: Default::default(),
            host_wr: Default::default(),
            host_req: Default::default(),
            adr_data: Default::default(),
            adr_cfg: Default::default(),
        }
    }
}

impl Logic for Mdb {
    // One long function: rust-hdl's `#[hdl_gen]` turns one `update` into
    // the block's Verilog and cannot call helper methods.
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            tx_served,
            tx_data,
            tx_cfg,
            tx_home,
            hwsame,
            t3,
            t3_hv,
            t3_slot,
            t3_data,
            t3_cfg,
            join,
            rl,
            s2,
            s2_rtx,
            s2_slot,
            s2_ok,
            s2_alive,
            s2_alarm,
            s2_run,
            s2_data,
            s2_rn,
            irq1,
            irq2,
            irq_fs,
            irq_rc,
            irq_fsc,
            fs_was,
            fs_host,
            fs_clear,
            fs_clear_held,
            aerr,
            last_irq,
            running,
            err_cfg,
            err_wr,
            hstate,
            ack,
            rdat,
            perm,
            aerr_inc,
            cur_cyc,
            fs_frame,
            unread,
            read_prev,
            alq_wr,
            alq_rd,
            alq_level,
            alq_ovf,
            alq_in,
            alq_word,
            alq_w2,
            alq_out,
            hdr_cyc,
            alq_c
        );
        self.db.read_clock.next = self.clock.val();
        self.db.write_clock.next = self.clock.val();
        self.cfg_tx.read_clock.next = self.clock.val();
        self.cfg_tx.write_clock.next = self.clock.val();
        self.cfg_rx.read_clock.next = self.clock.val();
        self.cfg_rx.write_clock.next = self.clock.val();
        self.ast.read_clock.next = self.clock.val();
        self.ast.write_clock.next = self.clock.val();
        self.alq.read_clock.next = self.clock.val();
        self.alq.write_clock.next = self.clock.val();
        self.alq_push.next = false;
        self.alq_pop.next = false;
        self.alq.read_address.next = self.alq_rd.q.val();
        self.stat.next = 0.into();
        self.irq_word.next = 0.into();
        self.host_req.next = self.i_wb_cyc.val() & self.i_wb_stb.val() & !self.ack.q.val();
        self.adr_data.next = self.i_wb_adr.val().get_bits::<2>(12) == 0;
        self.adr_cfg.next = self.i_wb_adr.val().get_bits::<2>(12) == 1;

        // Send side: the data memory's and the send copy's read ports serve
        // i_tx_slot in every clock the host does not read the data memory
        // and no word is received (stage 1 reads the send copy's has-value
        // bit): at most two clocks in a row, so the look-up follows
        // i_tx_slot and host writes within 2-4 clocks.
        self.tx_served.d.next = true;
        self.db.read_address.next = self.i_tx_slot.val();
        self.cfg_tx.read_address.next = self.i_tx_slot.val();
        if self.tx_served.q.val() {
            self.tx_data.d.next = self.db.read_data.val();
            self.tx_cfg.d.next = self.cfg_tx.read_data.val();
        }
        self.tx_home.d.next = self.i_tx_slot.val() == self.i_home.val();
        self.o_tx_data.next = self.tx_data.q.val();
        // What the node writes in the slot: LOCAL (configuration bit 3) or
        // ACT (bit 1), not in the reload frame after a restart, and only
        // with a value (protocol §12); a LOCAL home slot without one takes
        // only an alarm (3). (A forwarder writes only while the host runs
        // the node, `o_running`; a frame the clock base started is written
        // to its end.)
        self.tx_value.next = !self.join.q.val() | self.tx_cfg.q.val().get_bit(0);
        self.o_tx_cfg.next = 0.into();
        if self.rl.q.val() == 0 {
            if self.tx_cfg.q.val().get_bit(3) {
                if self.tx_value.val() {
                    self.o_tx_cfg.next = 1.into();
                } else if self.tx_home.q.val() {
                    self.o_tx_cfg.next = 3.into();
                }
            }
            if self.tx_cfg.q.val().get_bit(1) & self.tx_value.val() {
                self.o_tx_cfg.next = 2.into();
            }
        }
        self.o_join.next = self.join.q.val();

        // Receive pipeline, stage 1: read the slot's configuration and
        // Alive state.
        self.cfg_rx.read_address.next = self.i_slot.val();
        self.ast.read_address.next = self.i_slot.val();
        // The has-value bit of the received word's slot (protocol §12):
        // the send copy's read port serves stage 1 in its clock.
        if self.i_wvalid.val() {
            self.cfg_tx.read_address.next = self.i_slot.val();
            self.tx_served.d.next = false;
        }
        self.s2.d.next = self.i_wvalid.val() & (self.i_kind.val() == 2);
        self.s2_rtx.d.next = self.i_rtx.val();
        self.s2_slot.d.next = self.i_slot.val();
        self.s2_ok.d.next = self.i_ok.val();
        self.s2_alive.d.next = self.i_alive.val();
        self.s2_alarm.d.next = self.i_alarm.val();
        self.s2_run.d.next = self.running.q.val();
        self.s2_data.d.next = self.i_data.val();
        self.s2_rn.d.next = self.i_reason.val();
        // An alarm's reason and SEQ: D[15:12], D[11]; extended words:
        // N1 = {SEQ, REASON[2:0]} (protocol §11).
        self.s2_rsn.next = self.s2_data.q.val().get_bits::<4>(12);
        self.s2_seq.next = self.s2_data.q.val().get_bit(11);
        if self.ext.val() {
            self.s2_rsn.next = self.s2_rn.q.val() & 7;
            self.s2_seq.next = self.s2_rn.q.val().get_bit(3);
        }
        // Stage 2: update data, Alive state, interrupts (protocol §7, §11).
        self.s2_cfg.next = self.cfg_rx.read_data.val();
        self.s2_ast.next = self.ast.read_data.val();
        self.irq1.d.next = false;
        self.irq2.d.next = false;
        // An Alive-check failure counts a clock after it is found (issue
        // 20: the block RAM read and the 16-bit count are a clock apart).
        self.aerr_inc.d.next = false;
        if self.aerr_inc.q.val() & (self.aerr.q.val() != 0xffff) {
            self.aerr.d.next = self.aerr.q.val() + 1;
        }
        self.irq_fs.d.next = false;
        self.irq_rc.d.next = false;
        // Failsafe entered or left: one clock.
        self.fs_was.d.next = self.i_fs.val();
        self.irq_fsc.d.next = self.fs_was.q.val() != self.i_fs.val();
        self.fs_clear.d.next = false;
        if self.i_fs_cleared.val() {
            self.fs_clear_held.d.next = false;
        }
        self.s2_write.next = false;
        self.s2_own.next = false;
        self.s3_take.next = false;
        self.host_wr.next = false;
        self.hwsame.d.next = false;
        self.t3.d.next = false;
        // Alive state: bit 0 valid, bit 1 last Alive, bit 2 lost, bits 5:3
        // the CYC of the frame that wrote it: a state not written in the
        // previous cycle (the slot was missing, or no frame came) has
        // nothing to compare with (protocol §7). The CYC tag has 3 bits, so
        // a frame read after rejected headers or failsafe frames compares
        // with nothing either (eight lost frames leave the tag matching).
        if self.i_hdr_bad.val() {
            self.unread.d.next = true;
        }
        if self.i_wvalid.val() & (self.i_kind.val() == 1) & self.i_ok.val() {
            self.cur_cyc.d.next = self.i_data.val().get_bits::<3>(12);
            self.hdr_cyc.d.next = self.i_data.val() & 0x7000;
            // Failsafe as of this frame's header: a FAILSAFE alarm read
            // in a slot stops updates from the next frame (protocol §12).
            self.fs_frame.d.next = self.i_fs.val();
            self.read_prev.d.next = !self.unread.q.val() & !self.fs_frame.q.val();
            self.unread.d.next = false;
            // The reload frame (protocol §12): the first good header read
            // outside failsafe after JOIN starts it, the next ends it.
            if !self.i_fs.val() & (self.rl.q.val() == 1) {
                self.rl.d.next = 2.into();
            }
            if !self.i_fs.val() & (self.rl.q.val() == 2) {
                self.rl.d.next = 0.into();
            }
        }
        self.prev_cyc.next = self.cur_cyc.q.val() - 1;
        self.ast_valid.next = self.s2_ast.val().get_bit(0)
            & (self.s2_ast.val().get_bits::<3>(3) == self.prev_cyc.val())
            & self.read_prev.q.val();
        self.new_ast.next = self.s2_ast.val() & 4;
        self.ast.write_enable.next = false;
        self.ast.write_address.next = self.s2_slot.q.val();
        // Alarm SEQ per slot (protocol §11), in bit 0 of the receive copy
        // of the configuration (LAST is not stored),
        // inverted: the SEQ a new alarm of that slot has (0 after reset and
        // after a host write: the sender's first alarm is new). A good
        // alarm word with the other SEQ is a repeat. Kept in failsafe
        // frames too; FAILSAFE alarms are never repeats. Written only while
        // the ring runs, for a word whose configuration was read while it
        // ran (the host writes the configuration before: a word read before
        // a host write must not write its old bits back).
        self.cfg_rx.write_enable.next = false;
        self.cfg_rx.write_address.next = self.s2_slot.q.val();
        self.cfg_rx.write_data.next = self.s2_cfg.val() | 1;
        if self.s2_seq.val() {
            self.cfg_rx.write_data.next = self.s2_cfg.val() & 14;
        }
        self.s2_alrm.next = self.s2.q.val()
            & !self.s2_rtx.q.val()
            & self.s2_ok.q.val()
            & self.s2_alarm.q.val()
            & (self.s2_slot.q.val() != self.i_home.val());
        self.s2_fsr.next = self.s2_rsn.val() == 3;
        if self.s2_alrm.val() & !self.s2_fsr.val() & self.s2_run.q.val() & self.running.q.val() {
            self.cfg_rx.write_enable.next = true;
        }
        // (Before its host starts it, a master filters nothing.)
        self.s2_new.next = self.s2_fsr.val()
            | !self.s2_run.q.val()
            | (self.s2_seq.val() == self.s2_cfg.val().get_bit(0));
        if self.s2.q.val() & !self.fs_frame.q.val() {
            // (A retransmitted copy leaves the Alive state alone.)
            self.ast.write_enable.next = !self.s2_rtx.q.val();
            if self.s2_ok.q.val() {
                if self.s2_alrm.val() & self.s2_new.val() {
                    // rust-hdl widens only with a masked cast (a lint
                    // warning), so the slot is copied bit by bit.
                    self.irq_word.next = 0.into();
                    if self.s2_rsn.val().get_bit(0) {
                        self.irq_word.next = 0x1000.into();
                    }
                    if self.s2_rsn.val().get_bit(1) {
                        self.irq_word.next = self.irq_word.val() | 0x2000;
                    }
                    if self.s2_rsn.val().get_bit(2) {
                        self.irq_word.next = self.irq_word.val() | 0x4000;
                    }
                    if self.s2_rsn.val().get_bit(3) {
                        self.irq_word.next = self.irq_word.val() | 0x8000;
                    }
                    if self.s2_slot.q.val().get_bit(0) {
                        self.irq_word.next = self.irq_word.val() | 1;
                    }
                    if self.s2_slot.q.val().get_bit(1) {
                        self.irq_word.next = self.irq_word.val() | 2;
                    }
                    if self.s2_slot.q.val().get_bit(2) {
                        self.irq_word.next = self.irq_word.val() | 4;
                    }
                    if self.s2_slot.q.val().get_bit(3) {
                        self.irq_word.next = self.irq_word.val() | 8;
                    }
                    if self.s2_slot.q.val().get_bit(4) {
                        self.irq_word.next = self.irq_word.val() | 16;
                    }
                    if self.s2_slot.q.val().get_bit(5) {
                        self.irq_word.next = self.irq_word.val() | 32;
                    }
                    if self.s2_slot.q.val().get_bit(6) {
                        self.irq_word.next = self.irq_word.val() | 64;
                    }
                    if self.s2_slot.q.val().get_bit(7) {
                        self.irq_word.next = self.irq_word.val() | 128;
                    }
                    if self.s2_slot.q.val().get_bit(8) {
                        self.irq_word.next = self.irq_word.val() | 256;
                    }
                    if self.s2_slot.q.val().get_bit(9) {
                        self.irq_word.next = self.irq_word.val() | 512;
                    }
                    if self.s2_slot.q.val().get_bit(10) {
                        self.irq_word.next = self.irq_word.val() | 1024;
                    }
                    if self.s2_slot.q.val().get_bit(11) {
                        self.irq_word.next = self.irq_word.val() | 2048;
                    }
                    self.last_irq.d.next = self.irq_word.val();
                    self.alq_push.next = true;
                    if self.s2_rsn.val() == 1 {
                        self.irq1.d.next = true;
                    }
                    if self.s2_rsn.val() == 2 {
                        self.irq2.d.next = true;
                    }
                    if self.s2_rsn.val() == 3 {
                        self.irq_fs.d.next = true;
                    }
                    if (self.s2_rsn.val() >= 4) & (self.s2_rsn.val() <= 6) {
                        self.irq_rc.d.next = true;
                    }
                }
                // A slot of its own only in stage 3, after JOIN, while it
                // has no value (protocol §12: the send copy's bit 0, read
                // in stage 1; a host write of the slot in the clock of that
                // read counts).
                self.s2_own.next = (self.s2_cfg.val() & 10) != 0;
                // An alarm word's data only in the extended variant (§6).
                self.s2_write.next = (!self.s2_alarm.q.val() | self.ext.val()) & !self.s2_own.val();
                self.t3.d.next = (!self.s2_alarm.q.val() | self.ext.val())
                    & self.s2_own.val()
                    & self.join.q.val();
                self.t3_hv.d.next = self.cfg_tx.read_data.val().get_bit(0) | self.hwsame.q.val();
                self.t3_slot.d.next = self.s2_slot.q.val();
                self.t3_data.d.next = self.s2_data.q.val();
                self.t3_cfg.d.next = self.s2_cfg.val();
                if self.s2_cfg.val().get_bit(2) & !self.s2_rtx.q.val() {
                    self.new_ast.next = (self.s2_ast.val() & 4) | 1;
                    if self.s2_alive.q.val() {
                        self.new_ast.next = (self.s2_ast.val() & 4) | 3;
                    }
                    if self.ast_valid.val() {
                        if self.s2_ast.val().get_bit(1) == self.s2_alive.q.val() {
                            self.new_ast.next = self.new_ast.val() | 4;
                            self.aerr_inc.d.next = true;
                        } else {
                            self.new_ast.next = self.new_ast.val() & 3;
                        }
                    }
                }
            }
        }
        // The state as written, with this cycle's CYC.
        self.ast_word.next = self.new_ast.val() & 7;
        if self.cur_cyc.q.val().get_bit(0) {
            self.ast_word.next = self.ast_word.val() | 8;
        }
        if self.cur_cyc.q.val().get_bit(1) {
            self.ast_word.next = self.ast_word.val() | 16;
        }
        if self.cur_cyc.q.val().get_bit(2) {
            self.ast_word.next = self.ast_word.val() | 32;
        }
        self.ast.write_data.next = self.ast_word.val();
        self.db.write_enable.next = self.s2_write.val();
        self.db.write_address.next = self.s2_slot.q.val();
        self.db.write_data.next = self.s2_data.q.val();

        // Host port (Wishbone B4 classic). States: 0 idle, 1 data read
        // returns, 3 permission read returns, 4 write pending, 5 config read
        // returns, 7 acknowledged.
        self.ack.d.next = false;
        self.cfg_tx.write_enable.next = false;
        self.o_cfgw.next = false;
        self.o_cfgw_slot.next = self.i_wb_adr.val().get_bits::<12>(0);
        self.o_cfgw_crit.next = self.i_wb_dat.val().get_bit(4);
        self.cfg_tx.write_address.next = self.i_wb_adr.val().get_bits::<12>(0);
        // A configuration write stores bits 3:1 (LAST is not stored, its
        // bit is the has-value bit, protocol §7, §12).
        self.cfg_tx.write_data.next = self.i_wb_dat.val().get_bits::<4>(0) & 14;
        if !self.host_req.val() {
            self.hstate.d.next = 0.into();
        } else if self.hstate.q.val() == 0 {
            if self.adr_data.val() {
                if self.i_wb_we.val() {
                    if !self.i_wvalid.val() {
                        self.cfg_rx.read_address.next = self.i_wb_adr.val().get_bits::<12>(0);
                        self.hstate.d.next = 3.into();
                    }
                } else {
                    self.db.read_address.next = self.i_wb_adr.val().get_bits::<12>(0);
                    self.tx_served.d.next = false;
                    self.hstate.d.next = 1.into();
                }
            } else if self.adr_cfg.val() {
                if self.i_wb_we.val() {
                    if self.running.q.val() {
                        self.err_cfg.d.next = true;
                    } else {
                        // The receive copy's bit 0 starts at 0 (a new
                        // alarm has SEQ 0: the sender's first is new).
                        self.cfg_tx.write_enable.next = true;
                        self.o_cfgw.next = true;
                        self.cfg_rx.write_enable.next = true;
                        self.cfg_rx.write_address.next = self.i_wb_adr.val().get_bits::<12>(0);
                        self.cfg_rx.write_data.next = self.i_wb_dat.val().get_bits::<4>(0) & 14;
                    }
                    self.ack.d.next = true;
                } else if !self.i_wvalid.val() {
                    // Bits 3:1 from the receive copy (its bit 0 is the
                    // alarm SEQ); LAST is not stored: slot S − 1 has it.
                    self.cfg_rx.read_address.next = self.i_wb_adr.val().get_bits::<12>(0);
                    self.hstate.d.next = 5.into();
                }
            } else {
                self.ack.d.next = true;
                self.rdat.d.next = 0.into();
                if self.i_wb_adr.val() == 0x2000 {
                    self.stat.next = 0.into();
                    if self.i_mode.val().get_bit(0) {
                        self.stat.next = self.stat.val() | 16;
                    }
                    if self.i_mode.val().get_bit(1) {
                        self.stat.next = self.stat.val() | 32;
                    }
                    if self.running.q.val() {
                        self.stat.next = self.stat.val() | 1;
                    }
                    if self.err_cfg.q.val() {
                        self.stat.next = self.stat.val() | 2;
                    }
                    if self.err_wr.q.val() {
                        self.stat.next = self.stat.val() | 4;
                    }
                    if self.i_fs.val() {
                        self.stat.next = self.stat.val() | 8;
                    }
                    if self.fs_host.q.val() {
                        self.stat.next = self.stat.val() | 64;
                    }
                    if self.fs_clear_held.q.val() {
                        self.stat.next = self.stat.val() | 128;
                    }
                    if self.join.q.val() {
                        self.stat.next = self.stat.val() | 256;
                    }
                    if self.rl.q.val() != 0 {
                        self.stat.next = self.stat.val() | 512;
                    }
                    self.rdat.d.next = self.stat.val();
                    if self.i_wb_we.val() {
                        if self.i_wb_dat.val().get_bit(4) {
                            self.fs_clear.d.next = true;
                            self.fs_clear_held.d.next = true;
                        }
                        if self.i_wb_dat.val().get_bit(5) {
                            if self.running.q.val() {
                                self.err_cfg.d.next = true;
                            } else {
                                self.fs_host.d.next = true;
                            }
                        }
                        if self.i_wb_dat.val().get_bit(0) {
                            self.running.d.next = true;
                        }
                        if self.i_wb_dat.val().get_bit(6) {
                            if self.running.q.val() {
                                self.err_cfg.d.next = true;
                            } else {
                                self.running.d.next = true;
                                self.join.d.next = true;
                                self.rl.d.next = 1.into();
                            }
                        }
                        if self.i_wb_dat.val().get_bit(1) {
                            self.err_cfg.d.next = false;
                        }
                        if self.i_wb_dat.val().get_bit(2) {
                            self.err_wr.d.next = false;
                        }
                        if self.i_wb_dat.val().get_bit(3) {
                            self.running.d.next = false;
                        }
                    }
                }
                if self.i_wb_adr.val() == 0x2001 {
                    self.rdat.d.next = self.aerr.q.val();
                }
                if self.i_wb_adr.val() == 0x2002 {
                    self.rdat.d.next = self.last_irq.q.val();
                }
                // The alarm queue (protocol §11): its reads return from
                // the memory in state 6; a removal is done here.
                if !self.i_wb_we.val() & (self.i_wb_adr.val() == 0x2003) {
                    self.ack.d.next = false;
                    self.alq.read_address.next = self.alq_rd.q.val();
                    self.hstate.d.next = 6.into();
                }
                if !self.i_wb_we.val() & (self.i_wb_adr.val() == 0x2004) {
                    self.ack.d.next = false;
                    self.alq.read_address.next = self.alq_rd.q.val() | 1;
                    self.hstate.d.next = 6.into();
                }
                if self.i_wb_we.val()
                    & (self.i_wb_adr.val() == 0x2004)
                    & self.i_wb_dat.val().get_bit(0)
                    & (self.alq_level.q.val() != 0)
                {
                    self.alq_pop.next = true;
                }
                if (self.i_wb_adr.val() == 0x2004)
                    & self.i_wb_we.val()
                    & self.i_wb_dat.val().get_bit(1)
                {
                    self.alq_ovf.d.next = 0.into();
                }
                if self.i_wb_adr.val() == 0x2005 {
                    self.rdat.d.next = self.alq_ovf.q.val();
                }
            }
        } else if self.hstate.q.val() == 1 {
            // The data memory read of the previous clock.
            self.rdat.d.next = self.db.read_data.val();
            self.ack.d.next = true;
            self.hstate.d.next = 7.into();
        } else if self.hstate.q.val() == 3 {
            // The slot's configuration: LOCAL or ACT may be written.
            self.perm.d.next = self.cfg_rx.read_data.val();
            self.hstate.d.next = 4.into();
        } else if self.hstate.q.val() == 4 {
            // Write in a clock without a received word in stage 2 (the
            // receive side writes only then; waiting on stage 2 itself, not
            // on its write decision, keeps the block RAM's read data out of
            // this state machine: a clock later at most, once per word).
            if (self.perm.q.val() & 10) == 0 {
                self.err_wr.d.next = true;
                self.ack.d.next = true;
                self.hstate.d.next = 7.into();
            } else if !self.s2.q.val() {
                self.db.write_enable.next = true;
                self.db.write_address.next = self.i_wb_adr.val().get_bits::<12>(0);
                self.db.write_data.next = self.i_wb_dat.val();
                // The host's value (protocol §12): the has-value bit, in
                // the send copy's bit 0 (bits 3:1 as configured).
                self.cfg_tx.write_enable.next = true;
                self.cfg_tx.write_data.next = (self.perm.q.val() & 14) | 1;
                self.hwsame.d.next = self.i_wvalid.val()
                    & (self.i_slot.val() == self.i_wb_adr.val().get_bits::<12>(0));
                self.host_wr.next = true;
                self.ack.d.next = true;
                self.hstate.d.next = 7.into();
            }
        } else if self.hstate.q.val() == 6 {
            // The alarm queue's word read the previous clock: the oldest
            // entry, or its CYC with the level (0x2004); 0 when empty.
            self.stat.next = 0.into();
            if self.alq_level.q.val() != 0 {
                self.stat.next = self.alq.read_data.val();
            }
            if self.i_wb_adr.val() == 0x2004 {
                self.stat.next = self.stat.val() & 0x7000;
                if self.alq_level.q.val().get_bit(0) {
                    self.stat.next = self.stat.val() | 1;
                }
                if self.alq_level.q.val().get_bit(1) {
                    self.stat.next = self.stat.val() | 2;
                }
                if self.alq_level.q.val().get_bit(2) {
                    self.stat.next = self.stat.val() | 4;
                }
                if self.alq_level.q.val().get_bit(3) {
                    self.stat.next = self.stat.val() | 8;
                }
                if self.alq_level.q.val().get_bit(4) {
                    self.stat.next = self.stat.val() | 16;
                }
            }
            self.rdat.d.next = self.stat.val();
            self.ack.d.next = true;
            self.hstate.d.next = 7.into();
        } else if self.hstate.q.val() == 5 {
            self.stat.next = 0.into();
            if self.i_wb_adr.val().get_bits::<12>(0) == self.i_slots_m1.val() {
                self.stat.next = self.stat.val() | 1;
            }
            if self.cfg_rx.read_data.val().get_bit(1) {
                self.stat.next = self.stat.val() | 2;
            }
            if self.cfg_rx.read_data.val().get_bit(2) {
                self.stat.next = self.stat.val() | 4;
            }
            if self.cfg_rx.read_data.val().get_bit(3) {
                self.stat.next = self.stat.val() | 8;
            }
            self.rdat.d.next = self.stat.val();
            self.ack.d.next = true;
            self.hstate.d.next = 7.into();
        }
        // Stage 3: the own slot's word taken (protocol §12): the data
        // memory and the has-value bit. A host write in this clock goes
        // first, and the take waits a clock (the host's transfers are two
        // clocks apart at least, received words three) — or is dropped if
        // the host wrote this very slot (its value counts).
        if self.t3.q.val() & !self.t3_hv.q.val() {
            if self.host_wr.val() {
                self.t3.d.next = self.t3_slot.q.val() != self.i_wb_adr.val().get_bits::<12>(0);
            } else {
                self.s3_take.next = true;
            }
        }
        if self.s3_take.val() {
            self.db.write_enable.next = true;
            self.db.write_address.next = self.t3_slot.q.val();
            self.db.write_data.next = self.t3_data.q.val();
            self.cfg_tx.write_enable.next = true;
            self.cfg_tx.write_address.next = self.t3_slot.q.val();
            self.cfg_tx.write_data.next = (self.t3_cfg.q.val() & 14) | 1;
        }
        self.o_wb_ack.next = self.ack.q.val();
        self.o_wb_dat.next = self.rdat.q.val();

        // Alarm queue: an alarm delivered in stage 2 is kept the clock after
        // when there is room (a removal taking effect then makes room; the
        // host's transfers are 2 clocks apart at least), its first
        // word then, its CYC the next clock, when it counts; otherwise it is
        // counted lost.
        self.alq_in.d.next = self.alq_push.val();
        if self.alq_push.val() {
            self.alq_word.d.next = self.irq_word.val();
        }
        self.alq_out.d.next = self.alq_pop.val();
        self.alq_keep.next =
            self.alq_in.q.val() & ((self.alq_level.q.val() != 16) | self.alq_out.q.val());
        self.alq_w2.d.next = self.alq_keep.val();
        self.alq.write_address.next = self.alq_wr.q.val();
        self.alq.write_data.next = self.alq_word.q.val();
        self.alq.write_enable.next = self.alq_keep.val();
        if self.alq_keep.val() {
            self.alq_c.d.next = self.hdr_cyc.q.val();
        }
        if self.alq_w2.q.val() {
            self.alq.write_address.next = self.alq_wr.q.val() | 1;
            self.alq.write_data.next = self.alq_c.q.val();
            self.alq.write_enable.next = true;
            self.alq_wr.d.next = self.alq_wr.q.val() + 2;
        }
        if self.alq_out.q.val() {
            self.alq_rd.d.next = self.alq_rd.q.val() + 2;
        }
        if self.alq_w2.q.val() & !self.alq_out.q.val() {
            self.alq_level.d.next = self.alq_level.q.val() + 1;
        }
        if !self.alq_w2.q.val() & self.alq_out.q.val() {
            self.alq_level.d.next = self.alq_level.q.val() - 1;
        }
        if self.alq_in.q.val() & !self.alq_keep.val() & (self.alq_ovf.q.val() != 0xffff) {
            self.alq_ovf.d.next = self.alq_ovf.q.val() + 1;
        }

        self.o_s2.next = self.s2.q.val();
        self.o_s2_slot.next = self.s2_slot.q.val();
        self.o_s2_act.next = self.s2_cfg.val().get_bit(1) & !self.s2_rtx.q.val();
        self.o_s2_ok.next = self.s2_ok.q.val();
        self.o_s2_alive.next = self.s2_alive.q.val();
        self.o_s2_alarm.next = self.s2_alarm.q.val();
        self.o_s2_data.next = self.s2_data.q.val();
        self.o_s2_rn.next = self.s2_rn.q.val();
        self.o_running.next = self.running.q.val();
        self.o_irq1.next = self.irq1.q.val();
        self.o_irq2.next = self.irq2.q.val();
        self.o_irq_fs.next = self.irq_fs.q.val();
        self.o_irq_rc.next = self.irq_rc.q.val();
        self.o_alarmq.next = self.alq_level.q.val() != 0;
        self.o_irq_fsc.next = self.irq_fsc.q.val();
        self.o_fs_host.next = self.fs_host.q.val();
        self.o_fs_clear.next = self.fs_clear.q.val();
        self.o_aerr.next = self.aerr.q.val();
    }
}
