//! # merkur-rtl
//!
//! The MERKUR hardware blocks in rust-hdl (pinned 0.46), one file per block.
//! Each block's doc comment gives its purpose, a port table (width, clock
//! domain), its latency and a timing diagram. Protocol tables come from
//! `merkur-model`, the one source of truth (docs/protocol.md).
//!
//! Port names carry their side: `i_*` inputs, `o_*` outputs; `clock` is the
//! node's core clock.
//!
//! Blocks:
//! - [`chain8`]: eight slaves in a row (test top)
//! - [`dcm`]: IEEE 802.4 Dual Channel Manager (transmit on both, receive from the active channel, channel status)
//! - [`dcm_station`]: one token-bus station's DCM + RMM (`merkur_dcm`)
//! - [`boards`]: the boards' pins and clocks, the one source of the constraint files (`constraints/`)
//! - [`cdr`]: 8×-oversampling clock and data recovery, loss of signal
//! - [`enc4b5b`]: symbol → 4B/5B code group
//! - [`dec5b4b`]: code group → nibble / control flags
//! - [`formal`]: the formal proofs of the control blocks (property wrappers in `rtl/formal/`)
//! - [`fwd`]: cut-through forwarder, the slot shift register (slave and master mode)
//! - [`master`]: the master node (Figure 7): slave ring logic + database
//! - [`mdb`]: a master's database: data and configuration memory, Alive check, interrupts, Wishbone
//! - [`monitor`]: cdr + rx_framer + rx_word, the fibre monitor and receive half of a node
//! - [`nrzi_tx`]: serializer with NRZI
//! - [`pkt_tx`]: packet generator (DATA frames, SEC) of the special master
//! - [`power_on`]: a power-on reset for the ring top's restarted nodes
//! - [`readable`]: our emission pass after rust-hdl's (registers in clocked blocks, plain names), with [`literals`] (rust-hdl's 32-bit literals sized to what they meet) and [`headers`] (each module's block and its doc)
//! - [`retime`]: elastic output buffer, sends forwarded bits on the node's own clock
//! - [`ring_top`]: Verilog of a whole ring for simulation (clock gates, fibres, fault points, monitors)
//! - [`rmm_detect`]: RMM fault detection from the six MAC events (SC, NS)
//! - [`rmm_fcm`]: RMM fault correction machine (five states)
//! - [`rmm_sfc`]: RMM status frame check (3 bytes per station in block RAM)
//! - [`rmm_sfp`]: RMM status frame production (live counter, status byte)
//! - [`rx_framer`]: NRZI decode, J K detection, group alignment
//! - [`stream_ctrl`]: channel failure (pcf/scf) and test signal (ptst/stst)
//! - [`port_rx`]: monitor + stream controller, one per logical input
//! - [`switchbox`]: the paper's Table 1
//! - [`sw_dark`]: both physical outputs dark for 12 bit times after a switchbox change
//! - [`slave`]: the slave node top (Figure 6)
//! - [`special_master`]: the clock base: frames every period, return store, SEC
//! - [`switch_ctl`]: a node's switchbox decisions (protocol §10, §12): wrap, failsafe, reintegration
//! - [`synth_top`]: a node as a chip, the top level synthesis builds (synchronisers, diagnostic mux)
//! - [`tst_tx`]: link test packets of a wrapped node
//! - [`verilog`]: Verilog emission of single blocks (tests, lint, synthesis checks)
//! - [`xem6010`]: board top of a master (or the special master) on the Opal Kelly XEM6010
//! - [`ulx3s`]: board top of a slave on the Radiona ULX3S (ECP5 PLL, pins)
//! - [`rx_word`]: word assembly, parity check, header check, slot counter

pub mod boards;
pub mod cdr;
pub mod chain8;
pub mod dcm;
pub mod dcm_station;
pub mod dec5b4b;
pub mod enc4b5b;
pub mod formal;
pub mod fwd;
pub mod headers;
pub mod literals;
pub mod master;
pub mod mdb;
pub mod monitor;
pub mod nrzi_tx;
pub mod pkt_tx;
pub mod port_rx;
pub mod power_on;
pub mod readable;
pub mod retime;
pub mod ring_top;
pub mod rmm_detect;
pub mod rmm_fcm;
pub mod rmm_sfc;
pub mod rmm_sfp;
pub mod rx_framer;
pub mod rx_word;
pub mod slave;
pub mod special_master;
pub mod stream_ctrl;
pub mod sw_dark;
pub mod switch_ctl;
pub mod switchbox;
pub mod synth_top;
pub mod tst_tx;
pub mod ulx3s;
pub mod verilog;
pub mod xem6010;
