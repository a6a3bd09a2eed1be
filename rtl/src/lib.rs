//! # merkur-rtl
//!
//! The MERKUR hardware blocks in rust-hdl (pinned 0.46). Empty until issue 3
//! (the slave node's blocks); it depends on `merkur-model` only for the
//! protocol constants the RTL must share with the reference model.

/// Re-export of the line-code constants the RTL encoders use.
pub use merkur_model::line::{CODE_I, CODE_J, CODE_K, CODE_S, DATA_CODES};

// rust-hdl is linked so the pinned version is built and checked in CI.
pub use rust_hdl;
