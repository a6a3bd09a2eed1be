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
    use crate::*;
    vec![
        ("enc4b5b", block_verilog(enc4b5b::Enc4b5b::default())),
        ("dec5b4b", block_verilog(dec5b4b::Dec5b4b::default())),
        ("cdr", block_verilog(cdr::Cdr::default())),
        ("nrzi_tx", block_verilog(nrzi_tx::NrziTx::default())),
        ("rx_framer", block_verilog(rx_framer::RxFramer::new())),
        ("rx_word", block_verilog(rx_word::RxWord::new(false))),
        ("rx_word_ext", block_verilog(rx_word::RxWord::new(true))),
        ("monitor", block_verilog(monitor::Monitor::new(false))),
        ("switchbox", block_verilog(switchbox::Switchbox::default())),
        (
            "stream_ctrl",
            block_verilog(stream_ctrl::StreamCtrl::default()),
        ),
        ("port_rx", block_verilog(port_rx::PortRx::new(false))),
        ("fwd", block_verilog(fwd::Fwd::new())),
        ("tst_tx", block_verilog(tst_tx::TstTx::default())),
        ("slave", block_verilog(slave::Slave::new())),
        ("pkt_tx", block_verilog(pkt_tx::PktTx::default())),
        ("mdb", block_verilog(mdb::Mdb::default())),
        ("master", block_verilog(master::Master::default())),
        (
            "special_master",
            block_verilog(special_master::SpecialMaster::default()),
        ),
        ("chain8", block_verilog(chain8::Chain8::default())),
    ]
}

/// The lint waiver file (`rtl/lint/waivers.vlt`), each waiver commented.
pub const WAIVERS: &str = include_str!("../lint/waivers.vlt");
