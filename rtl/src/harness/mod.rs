//! # harness
//!
//! Simulation harnesses, never synthesized onto a board: the Verilog of a whole ring, a chain of eight slaves, the power-on reset of restarted nodes.
//!
//! - [`ring_top`]: Verilog of a whole ring for simulation (clock gates, fibres, fault points, monitors)
//! - [`chain8`]: eight slaves in a row (test top)
//! - [`power_on`]: a power-on reset for the ring top's restarted nodes

pub mod chain8;
pub mod power_on;
pub mod ring_top;
