//! Verilog emission of single blocks (for tests, lint and synthesis checks).

use rust_hdl::prelude::*;

/// The Verilog of a block as a top module named `top`, after rust-hdl's
/// connectivity and logic-loop checks, with every memory zero at power-up
/// ([`zero_memories`]).
pub fn block_verilog<U: Block>(mut uut: U) -> String {
    uut.connect_all();
    zero_memories(&generate_verilog(&uut))
}

/// Gives every rust-hdl memory (`reg[W:0] mem[D:0];`) an `initial` loop
/// that clears it. The blocks rely on memories starting at zero, as FPGA
/// block RAM does (iCE40 and Xilinx bitstreams initialise it; Yosys keeps
/// the zero init), and as Verilator's `--x-initial fast` happens to give;
/// without the loop Icarus starts them at x and a special master's return
/// store, read before its first frame has come back, differs.
pub fn zero_memories(verilog: &str) -> String {
    let mut out = String::with_capacity(verilog.len() + 1024);
    for line in verilog.lines() {
        out.push_str(line);
        out.push('\n');
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("reg[") {
            if let Some((_, tail)) = rest.split_once(":0] mem[") {
                if let Some(depth) = tail.strip_suffix(":0];") {
                    out.push_str(&format!(
                        "    integer mem_i;\n    initial for (mem_i = 0; mem_i <= {depth}; mem_i = mem_i + 1) mem[mem_i] = 0;\n"
                    ));
                }
            }
        }
    }
    out
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
        ("sw_dark", block_verilog(sw_dark::SwDark::default())),
        (
            "switch_ctl",
            block_verilog(switch_ctl::SwitchCtl::default()),
        ),
        (
            "stream_ctrl",
            block_verilog(stream_ctrl::StreamCtrl::default()),
        ),
        ("port_rx", block_verilog(port_rx::PortRx::new(false))),
        ("retime", block_verilog(retime::Retime::default())),
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
        ("dcm", block_verilog(dcm::Dcm::default())),
        (
            "rmm_detect",
            block_verilog(rmm_detect::RmmDetect::default()),
        ),
        ("rmm_sfp", block_verilog(rmm_sfp::RmmSfp::default())),
        ("rmm_sfc", block_verilog(rmm_sfc::RmmSfc::default())),
        ("rmm_fcm", block_verilog(rmm_fcm::RmmFcm::default())),
        (
            "dcm_station",
            block_verilog(dcm_station::DcmStation::default()),
        ),
    ]
}

/// The lint waiver file (`rtl/lint/waivers.vlt`), each waiver commented.
pub const WAIVERS: &str = include_str!("../lint/waivers.vlt");
