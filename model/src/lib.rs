//! # merkur-model
//!
//! The pure-Rust reference model of the MERKUR ring (docs/protocol.md). It is
//! the only writer of golden data in `tb-data/`: RTL is checked against it,
//! never the other way round. No `rust-hdl` here.
//!
//! - [`line`](mod@line): 4B/5B, NRZI, word format, parity, start delimiter (bit-exact).
//! - [`scenario`] / [`config`]: scenario files and their validation.
//! - [`ring`]: the cycle-level ring simulation.
//! - [`trace`]: the golden trace format.
//! - [`rmm`], [`tokenbus`], [`tbconfig`]: the IEEE 802.4 Dual Channel
//!   Manager and Redundancy Management Module, the token bus around them,
//!   token-bus scenario files (docs/protocol.md Part II).

#![deny(missing_docs)]

pub mod config;
pub mod line;
pub mod ring;
pub mod rmm;
pub mod scenario;
pub mod tbconfig;
pub mod tokenbus;
pub mod trace;
