//! # emit
//!
//! Verilog emission: rust-hdl's text made readable, literals sized, each module with a header, the per-block entry points.
//!
//! - [`verilog`]: Verilog emission of single blocks (tests, lint, synthesis checks)
//! - [`readable`]: our emission pass after rust-hdl's (registers in clocked blocks, plain names)
//! - [`literals`]: rust-hdl's 32-bit literals sized to what they meet
//! - [`headers`]: each emitted module's header: its block and its doc
//! - [`standard`]: the committed Verilog of the standard nodes (`gen/verilog/`)

pub mod headers;
pub mod literals;
pub mod readable;
pub mod standard;
pub mod verilog;
