//! Verilog emission of single blocks (for tests, lint and synthesis checks).

use crate::line::word_rx::WordFormat;
use rust_hdl::prelude::*;

/// The Verilog of a block as a top module named `top`, after rust-hdl's
/// connectivity and logic-loop checks, rewritten by our emission pass
/// ([`crate::emit::readable`]: registers in clocked blocks, `__` for `$`, sized
/// literals), a header before every module ([`crate::emit::headers`]: the block,
/// its source file and, once per block, its documentation), with every
/// memory zero at power-up ([`zero_memories`]).
pub fn block_verilog<U: Block>(mut uut: U) -> String {
    uut.connect_all();
    let root = std::any::type_name::<U>();
    let root = root.split('<').next().unwrap_or(root);
    let root = root.rsplit("::").next().unwrap_or(root);
    let text = crate::emit::readable::readable(&generate_verilog(&uut));
    zero_memories(&crate::emit::headers::with_headers(&text, root))
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

/// The depth the masters' memories get for a ring of `slots` slots: the
/// slot count rounded up to a power of two, at least 256 (one iCE40 block
/// RAM holds 256 × 16 bits, so less saves nothing) and at most 4096 (the
/// 12-bit slot number).
pub fn mem_depth(slots: usize) -> usize {
    slots.next_power_of_two().clamp(256, 4096)
}

/// Resizes every rust-hdl memory deeper than `depth` (a power of two) to
/// `depth` entries: the low address bits index it, a read of an address at
/// or above `depth` gives 0 and a write there is ignored — what the full
/// memory does for addresses nothing writes. The masters and the special
/// master address every memory by slot number, and a ring of S slots uses
/// slots 0 … S−1 only, so with `depth ≥ S` the node behaves as with 4096
/// entries (the host port reads 0 from, and cannot write, slots the ring
/// does not have; docs/synthesis.md). Applied to the Verilog of
/// [`zero_memories`] (the zeroing loop is resized with the memory).
///
/// Panics when `depth` is not a power of two or a memory of rust-hdl's
/// shape is not found whole (the emitted text changed): a generator bug,
/// caught by the tests.
pub fn size_memories(verilog: &str, depth: usize) -> String {
    assert!(depth.is_power_of_two(), "memory depth {depth}");
    let a = depth.trailing_zeros();
    let mut out = String::with_capacity(verilog.len());
    // Address width of the memory being resized, until its write is done.
    let mut aw: Option<u32> = None;
    let mut width = 0usize;
    let mut pending = 0;
    for line in verilog.lines() {
        let t = line.trim();
        let mut l = line.to_string();
        if let Some((w, d)) = t
            .strip_prefix("reg[")
            .and_then(|r| r.split_once(":0] mem["))
            .and_then(|(w, tail)| Some((w, tail.strip_suffix(":0];")?)))
        {
            let d: usize = d.parse().expect("memory depth");
            if d + 1 > depth {
                assert!((d + 1).is_power_of_two(), "memory depth {}", d + 1);
                aw = Some((d + 1).trailing_zeros());
                width = w.parse::<usize>().expect("memory width") + 1;
                pending = 4;
                l = format!("    reg[{w}:0] mem[{}:0];", depth - 1);
            }
        } else if let Some(n) = aw {
            let hi = format!("{}:{a}", n - 1);
            let zero = format!("{}'d0", n - a);
            if t.starts_with("initial for (mem_i = 0;") {
                l = l.replace(
                    &format!("mem_i <= {}", (1usize << n) - 1),
                    &format!("mem_i <= {}", depth - 1),
                );
                pending -= 1;
            } else if t == "read_data <= mem[read_address];" {
                l = format!(
                    "       read_data <= (read_address[{hi}] == {zero}) ? mem[read_address[{}:0]] : {{{width}{{1'b0}}}};",
                    a - 1
                );
                pending -= 1;
            } else if t == "if (write_enable) begin" {
                l = format!("       if (write_enable && write_address[{hi}] == {zero}) begin");
                pending -= 1;
            } else if t == "mem[write_address] <= write_data;" {
                l = format!("          mem[write_address[{}:0]] <= write_data;", a - 1);
                pending -= 1;
            } else if t.starts_with("endmodule") {
                assert_eq!(pending, 0, "memory of unexpected shape before {t}");
                aw = None;
            }
        }
        out.push_str(&l);
        out.push('\n');
    }
    assert!(aw.is_none(), "memory module without its end");
    out
}

/// Renames the top module of [`block_verilog`]'s text from `top` to `name`
/// (and its children `top__x` to `name__x`), so that several blocks can be
/// read into one tool run (the formal proofs, [`crate::formal`], and a
/// ring's node modules, [`crate::harness::ring_top`]). Only module headers,
/// instantiations, `endmodule` comments and the module names in the headers'
/// comments change.
pub fn rename_top(verilog: &str, name: &str) -> String {
    let mut out = String::with_capacity(verilog.len() + 256);
    for line in verilog.lines() {
        let t = line.trim_start();
        let indent = &line[..line.len() - t.len()];
        let l = if let Some(rest) = t.strip_prefix("module top") {
            format!("{indent}module {name}{rest}")
        } else if let Some(rest) = t.strip_prefix("endmodule // top") {
            format!("{indent}endmodule // {name}{rest}")
        } else if let Some(rest) = t.strip_prefix("top__").filter(|r| r.ends_with('(')) {
            format!("{indent}{name}__{rest}")
        } else if t.starts_with("//") {
            // Module names in the headers (crate::emit::headers) are in backticks.
            line.replace("`top`", &format!("`{name}`"))
                .replace("`top__", &format!("`{name}__"))
        } else {
            line.to_string()
        };
        out.push_str(&l);
        out.push('\n');
    }
    out
}

/// Every memory of a Verilog text: (width in bits, depth), in order.
pub fn memories(verilog: &str) -> Vec<(usize, usize)> {
    verilog
        .lines()
        .filter_map(|l| {
            let (w, tail) = l.trim().strip_prefix("reg[")?.split_once(":0] mem[")?;
            let d = tail.strip_suffix(":0];")?;
            Some((w.parse::<usize>().ok()? + 1, d.parse::<usize>().ok()? + 1))
        })
        .collect()
}

/// Every block with its default parameters: (name = file name under `rtl/src`, Verilog).
pub fn all_blocks() -> Vec<(&'static str, String)> {
    use crate::{harness::*, line::*, node::*, tokenbus::*};
    vec![
        ("enc4b5b", block_verilog(enc4b5b::Enc4b5b::default())),
        ("dec5b4b", block_verilog(dec5b4b::Dec5b4b::default())),
        ("cdr", block_verilog(cdr::Cdr::default())),
        ("nrzi_tx", block_verilog(nrzi_tx::NrziTx::default())),
        ("framer_rx", block_verilog(framer_rx::FramerRx::new())),
        (
            "word_rx",
            block_verilog(word_rx::WordRx::new(WordFormat::Basic)),
        ),
        (
            "word_rx_ext",
            block_verilog(word_rx::WordRx::new(WordFormat::ExtendedAlarm)),
        ),
        (
            "monitor",
            block_verilog(monitor::Monitor::new(WordFormat::Basic)),
        ),
        ("switchbox", block_verilog(switchbox::Switchbox::default())),
        ("sw_dark", block_verilog(sw_dark::SwDark::default())),
        (
            "switch_ctl",
            block_verilog(switch_ctl::SwitchCtl::default()),
        ),
        (
            "stream_ctl",
            block_verilog(stream_ctl::StreamCtl::default()),
        ),
        (
            "port_rx",
            block_verilog(port_rx::PortRx::new(WordFormat::Basic)),
        ),
        ("retime", block_verilog(retime::Retime::default())),
        (
            "retime_write_shifts",
            block_verilog(retime::Retime::new(retime::Layout::WriteShifts)),
        ),
        ("fwd", block_verilog(fwd::Fwd::new(WordFormat::Basic))),
        (
            "fwd_ext",
            block_verilog(fwd::Fwd::new(WordFormat::ExtendedAlarm)),
        ),
        ("tst_tx", block_verilog(tst_tx::TstTx::default())),
        (
            "tst_tx_ext",
            block_verilog(tst_tx::TstTx::new(WordFormat::ExtendedAlarm)),
        ),
        ("slave", block_verilog(slave::Slave::default())),
        (
            "slave_no_rtx",
            block_verilog(slave::Slave::with_rtx(WordFormat::Basic, false)),
        ),
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
pub const WAIVERS: &str = include_str!("../../lint/waivers.vlt");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rename_top_renames_modules_and_instances_only() {
        let v = block_verilog(crate::node::special_master::SpecialMaster::default());
        let r = rename_top(&v, "special_master");
        assert!(r.contains("module special_master(clock,"));
        assert!(r.contains("module special_master__dark(clock,"), "{r}");
        assert!(r.contains("    special_master__dark dark("), "{r}");
        assert!(r.contains("endmodule // special_master__dark"), "{r}");
        assert!(!r.contains("module top"), "{r}");
        assert!(!r.lines().any(|l| l.trim_start().starts_with("top__")));
        // The headers' module names follow (crate::emit::headers).
        assert!(
            v.contains("Documented at module `top__rx_bsr` above."),
            "the second receive port's header names the first"
        );
        assert!(r.contains("Documented at module `special_master__rx_bsr` above."));
        assert!(!r.contains("`top"), "{r}");
        // Signals are not touched.
        assert_eq!(r.matches("dark__").count(), v.matches("dark__").count());
        assert_eq!(r.lines().count(), v.lines().count());
    }

    #[test]
    fn memories_are_resized_with_every_access_guarded() {
        let full = block_verilog(crate::node::special_master::SpecialMaster::default());
        let mems = memories(&full);
        // The return store, the sent-alarm, alarm-ACT and CRIT bits, and
        // the database's data, two configuration copies and Alive state,
        // 4096 deep; the database's alarm queue, 32 deep (16 entries of two
        // words), which keeps its depth.
        assert_eq!(mems.len(), 9, "{mems:?}");
        assert_eq!(
            mems.iter().filter(|&&(_, d)| d == 4096).count(),
            8,
            "{mems:?}"
        );
        assert!(mems.contains(&(16, 32)), "{mems:?}");
        let sized = size_memories(&full, 256);
        let after = memories(&sized);
        assert_eq!(
            after,
            mems.iter()
                .map(|&(w, d)| (w, d.min(256)))
                .collect::<Vec<_>>()
        );
        let count = |v: &str, pat: &str| v.matches(pat).count();
        assert_eq!(count(&sized, "mem_i <= 255;"), 8);
        assert_eq!(
            count(
                &sized,
                "(read_address[11:8] == 4'd0) ? mem[read_address[7:0]]"
            ),
            8
        );
        assert_eq!(
            count(
                &sized,
                "if (write_enable && write_address[11:8] == 4'd0) begin"
            ),
            8
        );
        assert_eq!(count(&sized, "mem[write_address[7:0]] <= write_data;"), 8);
        assert_eq!(
            count(&sized, "mem[read_address]"),
            1,
            "the queue's own read"
        );
        // Full depth: the text is left as it is.
        assert_eq!(size_memories(&full, 4096), full);
    }

    #[test]
    fn memory_depth_follows_the_slot_count() {
        assert_eq!(mem_depth(1), 256);
        assert_eq!(mem_depth(100), 256);
        assert_eq!(mem_depth(256), 256);
        assert_eq!(mem_depth(257), 512);
        assert_eq!(mem_depth(2048), 2048);
        assert_eq!(mem_depth(2049), 4096);
        assert_eq!(mem_depth(4096), 4096);
    }
}
