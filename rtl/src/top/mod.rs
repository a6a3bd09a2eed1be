//! # top
//!
//! A node as a chip: the synthesis top, the boards' pins and the board tops.
//!
//! - [`boards`]: the boards' pins and clocks, the one source of the constraint files (`gen/constraints/`)
//! - [`synth_top`]: a node as a chip, the top level synthesis builds (synchronisers, diagnostic mux)
//! - [`ulx3s`]: board top of a slave on the Radiona ULX3S (ECP5 PLL, pins)
//! - [`xem6010`]: board top of a master (or the special master) on the Opal Kelly XEM6010

pub mod boards;
pub mod synth_top;
pub mod ulx3s;
pub mod xem6010;
