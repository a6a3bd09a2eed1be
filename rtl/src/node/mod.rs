//! # node
//!
//! The ring nodes and their blocks (the paper's Figures 6 and 7): receive ports, stream controller, switchbox and its control, forwarder, test and packet generators, the master's database, the three node tops.
//!
//! - [`port_rx`]: monitor + stream controller, one per logical input
//! - [`stream_ctl`]: channel failure (pcf/scf) and test signal (ptst/stst)
//! - [`switchbox`]: the paper's Table 1
//! - [`switch_ctl`]: a node's switchbox decisions (protocol §10, §12): wrap, failsafe, reintegration
//! - [`sw_dark`]: both physical outputs dark for 12 bit times after a switchbox change
//! - [`fwd`]: cut-through forwarder, the slot shift register (slave and master mode)
//! - [`tst_tx`]: link test packets of a wrapped node
//! - [`pkt_tx`]: packet generator (DATA frames, SEC) of the special master
//! - [`mdb`]: a master's database: data and configuration memory, Alive check, interrupts, Wishbone
//! - [`slave`]: the slave node top (Figure 6)
//! - [`master`]: the master node (Figure 7): slave ring logic + database
//! - [`special_master`]: the clock base: frames every period, return store, SEC

pub mod fwd;
pub mod master;
pub mod mdb;
pub mod pkt_tx;
pub mod port_rx;
pub mod slave;
pub mod special_master;
pub mod stream_ctl;
pub mod sw_dark;
pub mod switch_ctl;
pub mod switchbox;
pub mod tst_tx;
