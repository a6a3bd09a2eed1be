//! # standard — the committed Verilog of the standard nodes (`gen/verilog/`)
//!
//! For users who take Verilog and never run Rust: the three ring nodes
//! (slave, master, special master) and the 802.4 station, each in one file
//! whose top module is the node, with a file header (what it is, the
//! generator and its version, the build parameters, how to lint it) before
//! the module headers of [`crate::emit::headers`] (each block's doc: port
//! table, latency, timing diagram). The waiver file the files need for
//! `verilator --lint-only -Wall` is written beside them.
//!
//! The nodes take their whole configuration through ports (home address,
//! slots per frame, cycle period, CS timeout, …: see each port table), so
//! one file serves every ring; only the masters' memories are sized, to
//! [`STANDARD_SLOTS`] slots (one iCE40 block RAM each). `merkur verilog`
//! writes the nodes of a given ring, memories sized to it (up to 4096
//! slots).
//!
//! `cargo run -p merkur-sim --example gen` rewrites the files;
//! `sim/tests/gen.rs` fails when a committed file differs from
//! [`standard_files`] or is not lint-clean.

use crate::emit::verilog::WAIVERS;
use crate::harness::ring_top::node_verilog;
use crate::line::word_rx::WordFormat;
use merkur_model::scenario::Kind;

/// Slots the standard masters' memories hold: rings of up to 256 slots.
pub const STANDARD_SLOTS: usize = 256;

/// One committed file: its name in `gen/verilog/` and its text.
pub struct StandardFile {
    /// File name (`merkur_slave.v`).
    pub name: &'static str,
    /// The file's text.
    pub text: String,
}

/// The file header of a standard node: `what` it is, its top `module`, the
/// rust-hdl `source` it is generated from, and its build `parameters`.
fn header(module: &str, what: &str, source: &str, parameters: &str) -> String {
    format!(
        "// {module}.v — {what}\n\
         //\n\
         // Generated Verilog; do not edit. Generator: merkur-rtl {version} (rust-hdl 0.46.0),\n\
         // from {source}. `cargo run -p merkur-sim --example gen` rewrites this file and\n\
         // sim/tests/gen.rs fails when it drifts from the generator.\n\
         //\n\
         // Top module: {module}. Build parameters: {parameters}\n\
         // Every other setting is a port (the port table is in the header of module {module}\n\
         // below). Clock: `clock`, twice the line rate (100 MHz for 50 Mbit/s); the fibre\n\
         // inputs take 4 samples per clock (quadrature DDR capture), the outputs give a DDR\n\
         // pair (docs/protocol.md §9; `merkur_ddr_in`/`merkur_ddr_out` in rtl/src/top/synth_top.rs).\n\
         // Lint: verilator --lint-only -Wall waivers.vlt {module}.v --top-module {module}\n\n",
        version = env!("CARGO_PKG_VERSION"),
    )
}

/// Every file of `gen/verilog/`, in order: the four node files and the
/// lint waivers.
pub fn standard_files() -> Vec<StandardFile> {
    let sized = format!(
        "memories for rings of up to {STANDARD_SLOTS} slots (`merkur verilog` sizes them to a ring of up to 4096)."
    );
    let node = |kind: Kind, name, what, source, parameters: &str| StandardFile {
        name,
        text: header(
            crate::harness::ring_top::module_name(kind),
            what,
            source,
            parameters,
        ) + &node_verilog(kind, STANDARD_SLOTS, WordFormat::Basic),
    };
    vec![
        node(
            Kind::Sensor,
            "merkur_slave.v",
            "the MERKUR slave node (a sensor or an actuator, by its `i_actuator` port)",
            "rtl/src/node/slave.rs",
            "none.",
        ),
        node(
            Kind::Master,
            "merkur_master.v",
            "the MERKUR master node: the slave's ring logic and the database (Wishbone host port)",
            "rtl/src/node/master.rs",
            &sized,
        ),
        node(
            Kind::SpecialMaster,
            "merkur_special_master.v",
            "the MERKUR special master (the ring's clock base; also a backup clock base)",
            "rtl/src/node/special_master.rs",
            &sized,
        ),
        StandardFile {
            name: "merkur_dcm_station.v",
            text: header(
                "merkur_dcm_station",
                "one IEEE 802.4 token-bus station's Dual Channel Manager with its redundancy management (RMM)",
                "rtl/src/tokenbus/dcm_station.rs",
                "none.",
            ) + &crate::tokenbus::dcm_station::dcm_verilog(),
        },
        StandardFile {
            name: "waivers.vlt",
            text: WAIVERS.to_string(),
        },
    ]
}
