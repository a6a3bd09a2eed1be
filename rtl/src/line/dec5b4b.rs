//! # dec5b4b — 4B/5B code group decoder (protocol §2, §4)
//!
//! Purpose: classifies a received 5-bit code group: a data nibble, one of the
//! control groups J, K, I, S, or invalid (none of the flags set).
//!
//! | port | dir | width | clock domain | meaning |
//! |---|---|---|---|---|
//! | `i_code` | in | 5 | — (combinational) | code group, bit 4 received first |
//! | `o_nibble` | out | 4 | — | data nibble (0 unless `o_data`) |
//! | `o_data` | out | 1 | — | the group is a data nibble |
//! | `o_j`, `o_k`, `o_i`, `o_s` | out | 1 | — | the group is J / K / I / S |
//!
//! Latency: combinational (0 clocks).
//!
//! ```text
//! i_code   ==X= 01001 =X= 11000 =X= 00000 ==
//! o_nibble ==X== 0x1 ==X== 0x0 ==X== 0x0 ===
//! o_data   __/‾‾‾‾‾‾‾‾\_________________
//! o_j      ___________/‾‾‾‾‾‾‾\_________
//! ```

use merkur_model::line::{decode_group, Symbol};
use rust_hdl::prelude::*;
use std::collections::BTreeMap;

/// The ROM word for each code group: bits 3:0 nibble, 4 data, 5 J, 6 K, 7 I, 8 S.
/// Built from the model's decoder, the one source of the table.
pub fn table() -> Vec<u16> {
    (0..32u8)
        .map(|g| match decode_group(g) {
            Symbol::Data(n) => n as u16 | 1 << 4,
            Symbol::J => 1 << 5,
            Symbol::K => 1 << 6,
            Symbol::I => 1 << 7,
            Symbol::S => 1 << 8,
            Symbol::Invalid(_) => 0,
        })
        .collect()
}

/// 4B/5B decoder.
#[derive(LogicBlock)]
pub struct Dec5b4b {
    /// Code group.
    pub i_code: Signal<In, Bits<5>>,
    /// Data nibble.
    pub o_nibble: Signal<Out, Bits<4>>,
    /// Data group.
    pub o_data: Signal<Out, Bit>,
    /// J group.
    pub o_j: Signal<Out, Bit>,
    /// K group.
    pub o_k: Signal<Out, Bit>,
    /// I group.
    pub o_i: Signal<Out, Bit>,
    /// S group.
    pub o_s: Signal<Out, Bit>,
    rom: ROM<Bits<9>, 5>,
}

impl Default for Dec5b4b {
    fn default() -> Self {
        let map: BTreeMap<Bits<5>, Bits<9>> = table()
            .into_iter()
            .enumerate()
            .map(|(i, c)| (Bits::<5>::from(i as u64), Bits::<9>::from(c as u64)))
            .collect();
        Self {
            i_code: Default::default(),
            o_nibble: Default::default(),
            o_data: Default::default(),
            o_j: Default::default(),
            o_k: Default::default(),
            o_i: Default::default(),
            o_s: Default::default(),
            rom: ROM::new(map),
        }
    }
}

impl Logic for Dec5b4b {
    #[hdl_gen]
    fn update(&mut self) {
        self.rom.address.next = self.i_code.val();
        self.o_nibble.next = self.rom.data.val().get_bits::<4>(0);
        self.o_data.next = self.rom.data.val().get_bit(4);
        self.o_j.next = self.rom.data.val().get_bit(5);
        self.o_k.next = self.rom.data.val().get_bit(6);
        self.o_i.next = self.rom.data.val().get_bit(7);
        self.o_s.next = self.rom.data.val().get_bit(8);
    }
}
