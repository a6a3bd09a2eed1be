//! Verilog emission of single blocks (for tests, lint and synthesis checks).

use rust_hdl::prelude::*;

/// The Verilog of a block as a top module named `top`, after rust-hdl's
/// connectivity and logic-loop checks.
pub fn block_verilog<U: Block>(mut uut: U) -> String {
    uut.connect_all();
    generate_verilog(&uut)
}

/// Every block with its default parameters: (name = file name in `rtl/src`, Verilog).
pub fn all_blocks() -> Vec<(&'static str, String)> {
    vec![
        ("enc4b5b", block_verilog(crate::enc4b5b::Enc4b5b::default())),
        ("dec5b4b", block_verilog(crate::dec5b4b::Dec5b4b::default())),
        ("cdr", block_verilog(crate::cdr::Cdr::default())),
        ("nrzi_tx", block_verilog(crate::nrzi_tx::NrziTx::default())),
        (
            "rx_framer",
            block_verilog(crate::rx_framer::RxFramer::new()),
        ),
        ("rx_word", block_verilog(crate::rx_word::RxWord::new(false))),
        (
            "rx_word_ext",
            block_verilog(crate::rx_word::RxWord::new(true)),
        ),
        (
            "monitor",
            block_verilog(crate::monitor::Monitor::new(false)),
        ),
    ]
}

/// The lint waiver file (`rtl/lint/waivers.vlt`), each waiver commented.
pub const WAIVERS: &str = include_str!("../lint/waivers.vlt");
