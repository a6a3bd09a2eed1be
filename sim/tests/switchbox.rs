//! Switchbox in Verilator: Table 1 exhaustively, against the model's
//! `ring::table1` (every mode, every value of every input).

use merkur_model::ring::{table1, Mode, Port};
use merkur_rtl::emit::verilog::block_verilog;
use merkur_rtl::node::switchbox::{Switchbox, MODE_N, MODE_WD, MODE_WU};
use merkur_sim::verilator::Model;

#[test]
fn table1_exhaustively() {
    let mut m = Model::build(&block_verilog(Switchbox::default())).unwrap();
    let p = |m: &Model, n: &str| m.port(n);
    let (mode, pi, si, out, bss) = (
        p(&m, "i_mode"),
        p(&m, "i_pi"),
        p(&m, "i_si"),
        p(&m, "i_output"),
        p(&m, "i_bss"),
    );
    let (inp, bsr, po, so) = (
        p(&m, "o_input"),
        p(&m, "o_bsr"),
        p(&m, "o_po"),
        p(&m, "o_so"),
    );
    // Mode codes are the model's (protocol §11 RECONFIG codes); code 3 is unused and acts as N.
    assert_eq!(
        [MODE_N, MODE_WU, MODE_WD],
        [
            Mode::N.code() as u64,
            Mode::Wu.code() as u64,
            Mode::Wd.code() as u64
        ]
    );
    let cases = [Mode::N, Mode::Wu, Mode::Wd].map(|m| (m.code() as u64, m));
    for (code, md) in cases.into_iter().chain([(3, Mode::N)]) {
        let (t_in, t_out, t_bsr, t_bss) = table1(md);
        for v in 0..4096u64 {
            let (vpi, vsi, vout, vbss) = (v & 15, v >> 4 & 15, v >> 8 & 3, v >> 10 & 3);
            m.set(mode, code);
            m.set(pi, vpi);
            m.set(si, vsi);
            m.set(out, vout);
            m.set(bss, vbss);
            m.eval();
            let phys_in = |port: Port| if port == Port::Pi { vpi } else { vsi };
            assert_eq!(m.get(inp), phys_in(t_in), "mode {code}: INPUT");
            assert_eq!(m.get(bsr), phys_in(t_bsr), "mode {code}: BSR");
            // A physical output carries the logical stream mapped to it.
            let at = |port: Port| {
                if t_out == port {
                    vout
                } else if t_bss == port {
                    vbss
                } else {
                    u64::MAX
                }
            };
            assert_eq!(m.get(po), at(Port::Po), "mode {code}: PO");
            assert_eq!(m.get(so), at(Port::So), "mode {code}: SO");
        }
    }
}
