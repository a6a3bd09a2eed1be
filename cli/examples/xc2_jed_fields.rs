//! Prints a CoolRunner-II `.jed` as xc2bit reads it, in the format of Project
//! Combine's `coolrunner2_dis` (its field and value names), for the
//! cross-check of scripts/check-xc2-jed.sh: the fields xc2bit decodes, and
//! only those, so that every line can be compared.
//!
//! `cargo run --release --example xc2_jed_fields -- top.jed`

use xc2bit::*;
fn zname(dev: XC2Device, z: XC2ZIAInput) -> String {
    match z {
        XC2ZIAInput::One => "VCC".into(),
        XC2ZIAInput::Zero => "GND".into(),
        XC2ZIAInput::Macrocell { fb, mc } => format!("MC_C0B{fb}MC{mc}"),
        XC2ZIAInput::IBuf { ibuf } => {
            let (f, m) = iob_num_to_fb_mc_num(dev, ibuf as u32).unwrap();
            format!("IOB_C0B{f}MC{m}")
        }
        XC2ZIAInput::DedicatedInput => "IPAD0".into(),
    }
}
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let bytes = std::fs::read(&a[1]).unwrap();
    let jed = jedec::JEDECFile::from_bytes(&bytes).unwrap();
    let bs = XC2Bitstream::from_jed(&jed).unwrap();
    let bits = bs.bits;
    let dev = bits.device_type();
    let g = bits.get_global_nets();
    println!(
        "GLOBAL: FCLK0_ENABLE={} FCLK1_ENABLE={} FCLK2_ENABLE={}",
        g.gck_enable[0] as u8, g.gck_enable[1] as u8, g.gck_enable[2] as u8
    );
    for (f, fb) in bits.get_fb().iter().enumerate() {
        let mut im: Vec<String> = (0..40)
            .map(|r| format!("IM[{r}].MUX={}", zname(dev, *fb.get_zia(r))))
            .collect();
        im.sort();
        println!("FB {f}: {}", im.join(" "));
        for (m, mc) in fb.mcs.iter().enumerate() {
            let clk = match mc.clk_src {
                XC2MCRegClkSrc::GCK0 => "FCLK0",
                XC2MCRegClkSrc::GCK1 => "FCLK1",
                XC2MCRegClkSrc::GCK2 => "FCLK2",
                XC2MCRegClkSrc::PTC => "PT",
                XC2MCRegClkSrc::CTC => "CT4",
            };
            let rm = match mc.reg_mode {
                XC2MCRegMode::DFF => "DFF",
                XC2MCRegMode::TFF => "TFF",
                XC2MCRegMode::LATCH => "LATCH",
                XC2MCRegMode::DFFCE => "DFFCE",
            };
            let zm = match mc.fb_mode {
                XC2MCFeedbackMode::Disabled => "NONE",
                XC2MCFeedbackMode::COMB => "XOR",
                XC2MCFeedbackMode::REG => "REG",
            };
            let xm = match mc.xor_mode {
                XC2MCXorMode::ZERO => "GND",
                XC2MCXorMode::ONE => "VCC",
                XC2MCXorMode::PTC => "PT",
                XC2MCXorMode::PTCB => "PT_INV",
            };
            let rs = match mc.r_src {
                XC2MCRegResetSrc::Disabled => "GND",
                XC2MCRegResetSrc::PTA => "PT",
                XC2MCRegResetSrc::GSR => "FSR",
                XC2MCRegResetSrc::CTR => "CT5",
            };
            let ss = match mc.s_src {
                XC2MCRegSetSrc::Disabled => "GND",
                XC2MCRegSetSrc::PTA => "PT",
                XC2MCRegSetSrc::GSR => "FSR",
                XC2MCRegSetSrc::CTS => "CT6",
            };
            let mut s = format!("MC {f} {m}: CLK_DDR={} CLK_INV={} CLK_MUX={clk} MC_ZIA_MUX={zm} REG_INIT={} REG_MODE={rm} RST_MUX={rs} SET_MUX={ss} XOR_MUX={xm}", mc.is_ddr as u8, mc.clk_invert_pol as u8, mc.init_state as u8);
            if let Some(i) = fb_mc_num_to_iob_num(dev, f as u32, m as u32) {
                let (z, ff, om) = if dev.is_small_iob() {
                    let b = bits.get_small_iob(i as usize).unwrap();
                    (b.zia_mode, b.obuf_uses_ff, b.obuf_mode)
                } else {
                    let b = bits.get_large_iob(i as usize).unwrap();
                    (b.zia_mode, b.obuf_uses_ff, b.obuf_mode)
                };
                let zs = match z {
                    XC2IOBZIAMode::PAD => "IBUF",
                    XC2IOBZIAMode::REG => "REG",
                    XC2IOBZIAMode::Disabled => "NONE",
                };
                let os = match om {
                    XC2IOBOBufMode::PushPull => "VCC",
                    XC2IOBOBufMode::Disabled => "GND",
                    XC2IOBOBufMode::OpenDrain => "OPEN_DRAIN",
                    XC2IOBOBufMode::TriStatePTB => "PT",
                    XC2IOBOBufMode::TriStateCTE => "CT7",
                    XC2IOBOBufMode::TriStateGTS0 => "FOE0",
                    XC2IOBOBufMode::TriStateGTS1 => "FOE1",
                    XC2IOBOBufMode::TriStateGTS2 => "FOE2",
                    XC2IOBOBufMode::TriStateGTS3 => "FOE3",
                    XC2IOBOBufMode::CGND => "IS_GND",
                };
                s += &format!(
                    " IOB_ZIA_MUX={zs} MC_IOB_MUX={} OE_MUX={os} REG_D_MUX={}",
                    if ff { "REG" } else { "XOR" },
                    if mc.ff_in_ibuf { "IBUF" } else { "XOR" }
                );
            }
            println!("{s}");
        }
        for j in 0..56 {
            let t = fb.get_andterm(j);
            let mut v = vec![];
            for k in 0..40 {
                if t.get(k) {
                    v.push(format!("{k}"));
                }
                if t.get_b(k) {
                    v.push(format!("!{k}"));
                }
            }
            if !v.is_empty() {
                println!("PT {f} {j}: {}", v.join(" "));
            }
        }
        for j in 0..16 {
            let v: Vec<String> = (0..56)
                .filter(|&k| fb.or_terms[j].get(k))
                .map(|k| k.to_string())
                .collect();
            if !v.is_empty() {
                println!("ST {f} {j}: {}", v.join(" "));
            }
        }
    }
}
