//! # line
//!
//! The line layer: 4B/5B, NRZI, clock and data recovery, framing, word assembly, the fibre monitor, the elastic output buffer.
//!
//! - [`enc4b5b`]: symbol → 4B/5B code group
//! - [`dec5b4b`]: code group → nibble / control flags
//! - [`nrzi_tx`]: serializer with NRZI
//! - [`cdr`]: 8×-oversampling clock and data recovery, NRZI decode, loss of signal
//! - [`framer_rx`]: J K detection, group alignment
//! - [`word_rx`]: word assembly, parity check, header check, slot counter
//! - [`monitor`]: cdr + framer_rx + word_rx, the fibre monitor and receive half of a node
//! - [`retime`]: elastic output buffer, sends forwarded bits on the node's own clock

pub mod cdr;
pub mod dec5b4b;
pub mod enc4b5b;
pub mod framer_rx;
pub mod monitor;
pub mod nrzi_tx;
pub mod retime;
pub mod word_rx;
