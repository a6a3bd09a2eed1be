//! # enc4b5b — 4B/5B symbol encoder (protocol §2)
//!
//! Purpose: maps a symbol number to its 5-bit code group. Symbols 0..=15 are
//! data nibbles; [`SYM_J`], [`SYM_K`], [`SYM_I`], [`SYM_S`] are the control
//! groups. Any other symbol number gives I (idle), so the line never carries
//! an undefined group.
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `i_sym` | in | 5 | — (combinational) | symbol number |
//! | `o_code` | out | 5 | — | code group, bit 4 sent first |
//!
//! Latency: combinational (0 clocks).
//!
//! ```text
//! i_sym   ==X== 0x0 ==X== 0x10 (J) ==X== 0x12 (I) ==
//! o_code  ==X= 11110 =X== 11000 ====X== 11111 =====
//! ```

use merkur_model::line::{CODE_I, CODE_J, CODE_K, CODE_S, DATA_CODES};
use rust_hdl::prelude::*;
use std::collections::BTreeMap;

/// Symbol number of J.
pub const SYM_J: u8 = 16;
/// Symbol number of K.
pub const SYM_K: u8 = 17;
/// Symbol number of I (idle).
pub const SYM_I: u8 = 18;
/// Symbol number of S (set; VOID words).
pub const SYM_S: u8 = 19;

/// The code group of every symbol number 0..32 (the table the ROM holds).
pub fn table() -> Vec<u8> {
    (0..32u8)
        .map(|s| match s {
            0..=15 => DATA_CODES[s as usize],
            SYM_J => CODE_J,
            SYM_K => CODE_K,
            SYM_S => CODE_S,
            _ => CODE_I,
        })
        .collect()
}

/// 4B/5B encoder.
#[derive(LogicBlock)]
pub struct Enc4b5b {
    /// Symbol number.
    pub i_sym: Signal<In, Bits<5>>,
    /// Code group.
    pub o_code: Signal<Out, Bits<5>>,
    rom: ROM<Bits<5>, 5>,
}

impl Default for Enc4b5b {
    fn default() -> Self {
        let map: BTreeMap<Bits<5>, Bits<5>> = table()
            .into_iter()
            .enumerate()
            .map(|(i, c)| (Bits::<5>::from(i as u64), Bits::<5>::from(c as u64)))
            .collect();
        Self {
            i_sym: Default::default(),
            o_code: Default::default(),
            rom: ROM::new(map),
        }
    }
}

impl Logic for Enc4b5b {
    #[hdl_gen]
    fn update(&mut self) {
        self.rom.address.next = self.i_sym.val();
        self.o_code.next = self.rom.data.val();
    }
}
