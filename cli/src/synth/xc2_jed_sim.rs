//! A behavioural model of a CoolRunner-II programmed by a `.jed`, for the
//! tests of the open fit ([`super::xc2_fit`]): the bitstream is read back
//! with xc2bit and every function block evaluated as the device computes
//! (ZIA row → AND terms → OR term → XOR → register), so a test can drive
//! the pads and compare the outputs with the design's own reference model.
//!
//! Only what a merkur top uses is modelled: registers on the global clocks
//! (either edge), D and T flip-flops, feedback from the XOR or the register,
//! pad inputs and push-pull outputs. Anything else that a bitstream uses
//! (latches, product-term clocks, sets and resets, clock enables,
//! tristates) is refused with a panic naming it, so a test cannot pass by
//! ignoring it.

use xc2bit::{
    get_ptc, iob_num_to_fb_mc_num, XC2Bitstream, XC2BitstreamBits, XC2IOBOBufMode, XC2IOBZIAMode,
    XC2MCFeedbackMode, XC2MCRegClkSrc, XC2MCRegMode, XC2MCRegResetSrc, XC2MCRegSetSrc,
    XC2MCXorMode, XC2ZIAInput, ANDTERMS_PER_FB, INPUTS_PER_ANDTERM, MCS_PER_FB,
};

/// A programmed device and its state.
pub struct Device {
    bits: XC2BitstreamBits,
    /// Register of each macrocell, `[fb][mc]`.
    q: Vec<[bool; MCS_PER_FB]>,
    /// XOR output of each macrocell, settled.
    x: Vec<[bool; MCS_PER_FB]>,
    /// Level at each pad, `[fb][mc]`, as the test drives it.
    pad: Vec<[bool; MCS_PER_FB]>,
}

/// An I/O buffer's settings the model needs.
struct Iob {
    zia: XC2IOBZIAMode,
    uses_ff: bool,
    mode: XC2IOBOBufMode,
}

impl Device {
    /// Reads a `.jed`; registers start at their power-up values.
    pub fn from_jed(jed: &[u8]) -> Device {
        let file = jedec::JEDECFile::from_bytes(jed).expect("the .jed parses");
        let bits = XC2Bitstream::from_jed(&file)
            .expect("xc2bit decodes the .jed (every ZIA row a known choice)")
            .bits;
        let n = bits.get_fb().len();
        let q = bits
            .get_fb()
            .iter()
            .map(|fb| std::array::from_fn(|m| fb.mcs[m].init_state))
            .collect();
        let mut d = Device {
            bits,
            q,
            x: vec![[false; MCS_PER_FB]; n],
            pad: vec![[false; MCS_PER_FB]; n],
        };
        d.settle();
        d
    }

    fn iob(&self, fb: usize, mc: usize) -> Option<Iob> {
        let dev = self.bits.device_type();
        let i = xc2bit::fb_mc_num_to_iob_num(dev, fb as u32, mc as u32)? as usize;
        if dev.is_small_iob() {
            let b = self.bits.get_small_iob(i)?;
            Some(Iob {
                zia: b.zia_mode,
                uses_ff: b.obuf_uses_ff,
                mode: b.obuf_mode,
            })
        } else {
            let b = self.bits.get_large_iob(i)?;
            Some(Iob {
                zia: b.zia_mode,
                uses_ff: b.obuf_uses_ff,
                mode: b.obuf_mode,
            })
        }
    }

    /// What ZIA row `r` of function block `fb` carries.
    fn zia(&self, fb: usize, r: usize) -> bool {
        match *self.bits.get_fb()[fb].get_zia(r) {
            XC2ZIAInput::One => true,
            XC2ZIAInput::Zero => false,
            XC2ZIAInput::Macrocell { fb: f, mc: m } => {
                let (f, m) = (f as usize, m as usize);
                match self.bits.get_fb()[f].mcs[m].fb_mode {
                    XC2MCFeedbackMode::COMB => self.x[f][m],
                    XC2MCFeedbackMode::REG => self.q[f][m],
                    XC2MCFeedbackMode::Disabled => {
                        panic!("FB{fb} row {r} reads macrocell {f}/{m}, whose feedback is off")
                    }
                }
            }
            XC2ZIAInput::IBuf { ibuf } => {
                let dev = self.bits.device_type();
                let (f, m) = iob_num_to_fb_mc_num(dev, u32::from(ibuf)).expect("a pad");
                let (f, m) = (f as usize, m as usize);
                match self.iob(f, m).expect("a pad").zia {
                    XC2IOBZIAMode::PAD => self.pad[f][m],
                    XC2IOBZIAMode::REG => self.q[f][m],
                    XC2IOBZIAMode::Disabled => {
                        panic!("FB{fb} row {r} reads pad {f}/{m}, whose input is off")
                    }
                }
            }
            XC2ZIAInput::DedicatedInput => panic!("the XC2C32A's input-only pad is not modelled"),
        }
    }

    /// Every XOR output of function block `fb` from its ZIA rows now.
    fn eval_fb(&self, fb: usize) -> [bool; MCS_PER_FB] {
        let b = &self.bits.get_fb()[fb];
        let rows: Vec<bool> = (0..INPUTS_PER_ANDTERM).map(|r| self.zia(fb, r)).collect();
        let pt: Vec<bool> = (0..ANDTERMS_PER_FB)
            .map(|i| {
                let t = b.get_andterm(i);
                (0..INPUTS_PER_ANDTERM).all(|r| (!t.get(r) || rows[r]) && (!t.get_b(r) || !rows[r]))
            })
            .collect();
        std::array::from_fn(|m| {
            let or = (0..ANDTERMS_PER_FB).any(|i| b.or_terms[m].get(i) && pt[i]);
            let ptc = pt[get_ptc(m as u32) as usize];
            match b.mcs[m].xor_mode {
                XC2MCXorMode::ZERO => or,
                XC2MCXorMode::ONE => !or,
                XC2MCXorMode::PTC => or ^ ptc,
                XC2MCXorMode::PTCB => !(or ^ ptc),
            }
        })
    }

    /// Evaluates the logic until it settles (a design without
    /// combinational loops settles in as many rounds as its depth).
    fn settle(&mut self) {
        for _ in 0..64 {
            let next: Vec<_> = (0..self.x.len()).map(|f| self.eval_fb(f)).collect();
            if next == self.x {
                return;
            }
            self.x = next;
        }
        panic!("the logic does not settle in 64 rounds (a combinational loop)");
    }

    /// Drives the pad of macrocell `fb`/`mc` (the logic settles).
    pub fn set_pad(&mut self, fb: u32, mc: u32, level: bool) {
        self.pad[fb as usize][mc as usize] = level;
        self.settle();
    }

    /// The level an output pad drives.
    pub fn out_pad(&self, fb: u32, mc: u32) -> bool {
        let (f, m) = (fb as usize, mc as usize);
        let iob = self.iob(f, m).expect("an output pad");
        assert!(
            iob.mode == XC2IOBOBufMode::PushPull,
            "pad {f}/{m}: output mode {:?} is not modelled",
            iob.mode
        );
        if iob.uses_ff {
            self.q[f][m]
        } else {
            self.x[f][m]
        }
    }

    /// An edge of global clock `gck` (rising or falling): every register
    /// clocked by it takes its input together, then the logic settles.
    pub fn clock(&mut self, gck: u32, rising: bool) {
        assert!(
            self.bits.get_global_nets().gck_enable[gck as usize],
            "GCK{gck} is not enabled"
        );
        let mut next = self.q.clone();
        for (f, b) in self.bits.get_fb().iter().enumerate() {
            for (m, mc) in b.mcs.iter().enumerate() {
                let src = match mc.clk_src {
                    XC2MCRegClkSrc::GCK0 => 0,
                    XC2MCRegClkSrc::GCK1 => 1,
                    XC2MCRegClkSrc::GCK2 => 2,
                    XC2MCRegClkSrc::PTC | XC2MCRegClkSrc::CTC => {
                        let read = mc.fb_mode == XC2MCFeedbackMode::REG
                            || self
                                .iob(f, m)
                                .is_some_and(|i| i.uses_ff || i.zia == XC2IOBZIAMode::REG);
                        assert!(
                            !read,
                            "macrocell {f}/{m}: a product-term clock is not modelled"
                        );
                        continue;
                    }
                };
                if src != gck || !(mc.is_ddr || rising != mc.clk_invert_pol) {
                    continue;
                }
                assert!(
                    mc.s_src == XC2MCRegSetSrc::Disabled && mc.r_src == XC2MCRegResetSrc::Disabled,
                    "macrocell {f}/{m}: set and reset are not modelled"
                );
                let d = if mc.ff_in_ibuf {
                    self.pad[f][m]
                } else {
                    self.x[f][m]
                };
                next[f][m] = match mc.reg_mode {
                    XC2MCRegMode::DFF => d,
                    XC2MCRegMode::TFF => self.q[f][m] ^ d,
                    m2 => panic!("macrocell {f}/{m}: register mode {m2:?} is not modelled"),
                };
            }
        }
        self.q = next;
        self.settle();
    }
}
