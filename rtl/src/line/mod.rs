//! # line
//!
//! The line layer: 4B/5B, NRZI, clock and data recovery, framing, word assembly, the fibre monitor, the elastic output buffer.
//!
//! - [`enc4b5b`]: symbol → 4B/5B code group
//! - [`dec5b4b`]: code group → nibble / control flags
//! - [`nrzi_tx`]: serializer with NRZI
//! - [`cdr`]: 8×-oversampling clock and data recovery, loss of signal
//! - [`rx_framer`]: NRZI decode, J K detection, group alignment
//! - [`rx_word`]: word assembly, parity check, header check, slot counter
//! - [`monitor`]: cdr + rx_framer + rx_word, the fibre monitor and receive half of a node
//! - [`retime`]: elastic output buffer, sends forwarded bits on the node's own clock

pub mod cdr;
pub mod dec5b4b;
pub mod enc4b5b;
pub mod monitor;
pub mod nrzi_tx;
pub mod retime;
pub mod rx_framer;
pub mod rx_word;
