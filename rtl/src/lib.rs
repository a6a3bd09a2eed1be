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
//! The blocks, in folders by layer (docs/architecture.md has the table
//! paper name → block → file → test → generated module):
//! - [`line`](mod@line): the line layer: 4B/5B, NRZI, clock and data recovery, framing, word assembly, the fibre monitor, the elastic output buffer
//! - [`node`]: the ring nodes and their blocks (the paper's Figures 6 and 7): receive ports, stream controller, switchbox and its control, forwarder, test and packet generators, the master's database, the three node tops
//! - [`tokenbus`]: the IEEE 802.4 Dual Channel Manager of the PICNET paper: the DCM and the redundancy management blocks (RMM) of one token-bus station
//! - [`top`]: a node as a chip: the synthesis top, the boards' pins and the board tops
//! - [`harness`]: simulation harnesses, never synthesized onto a board: the Verilog of a whole ring, a chain of eight slaves, the power-on reset of restarted nodes
//! - [`emit`]: Verilog emission: rust-hdl's text made readable, literals sized, each module with a header, the per-block entry points
//! - [`formal`]: the formal proofs of the control blocks (property wrappers in `rtl/formal/`)

#![deny(missing_docs)]

pub mod emit;
pub mod formal;
pub mod harness;
pub mod line;
pub mod node;
pub mod tokenbus;
pub mod top;
