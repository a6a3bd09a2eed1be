//! Line level of the MERKUR protocol (docs/protocol.md §2–§4): the 4B/5B code,
//! NRZI, the word format with its two odd parities, and the packet start JK.
//!
//! Everything here is bit-exact: the RTL's encoder and decoder are checked
//! against these functions, and the model applies injected bit errors by
//! really encoding a word, flipping a line bit and decoding it again.

/// 4B/5B code groups for data nibbles 0..=15 (FDDI / 100BASE-X table), MSB
/// of the 5-bit group sent first.
pub const DATA_CODES: [u8; 16] = [
    0b11110, 0b01001, 0b10100, 0b10101, 0b01010, 0b01011, 0b01110, 0b01111, 0b10010, 0b10011,
    0b10110, 0b10111, 0b11010, 0b11011, 0b11100, 0b11101,
];
/// First half of the packet start delimiter.
pub const CODE_J: u8 = 0b11000;
/// Second half of the packet start delimiter.
pub const CODE_K: u8 = 0b10001;
/// Idle: all ones, so the NRZI line toggles every bit time between packets.
pub const CODE_I: u8 = 0b11111;
/// Set: five of them form the VOID word.
pub const CODE_S: u8 = 0b11001;
/// Mark: a forwarder sends it as the last group of a word that arrived bad
/// (protocol §4), so the next receivers can tell it from a word damaged on
/// their own fibre. Not a data group, J K cannot be imitated with it, and it
/// keeps runs of 0 code bits at 3 (`model/tests/line.rs`).
pub const CODE_T: u8 = 0b01101;
/// Line bits per code group.
pub const GROUP_BITS: u32 = 5;

/// One decoded 5-bit code group.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Symbol {
    /// A data nibble.
    Data(u8),
    /// J (first half of the start delimiter).
    J,
    /// K (second half of the start delimiter).
    K,
    /// Idle.
    I,
    /// Set (VOID words).
    S,
    /// Any other 5-bit pattern: a line error.
    Invalid(u8),
}

/// Encodes one nibble (only the low 4 bits are used) into its code group.
pub fn encode_nibble(n: u8) -> u8 {
    DATA_CODES[(n & 0xf) as usize]
}

/// Decodes a 5-bit code group.
pub fn decode_group(g: u8) -> Symbol {
    let g = g & 0x1f;
    if let Some(n) = DATA_CODES.iter().position(|&c| c == g) {
        return Symbol::Data(n as u8);
    }
    match g {
        CODE_J => Symbol::J,
        CODE_K => Symbol::K,
        CODE_I => Symbol::I,
        CODE_S => Symbol::S,
        other => Symbol::Invalid(other),
    }
}

/// NRZI encoding: a code bit 1 toggles the line, a 0 keeps it.
/// `level` is the line level before the first bit and is updated.
pub fn nrzi_encode(code_bits: &[u8], level: &mut u8) -> Vec<u8> {
    code_bits
        .iter()
        .map(|&b| {
            *level ^= b & 1;
            *level
        })
        .collect()
}

/// NRZI decoding: a code bit is 1 where the line changed. `prev` is the line
/// level before the first bit.
pub fn nrzi_decode(line_bits: &[u8], prev: u8) -> Vec<u8> {
    let mut p = prev;
    line_bits
        .iter()
        .map(|&l| {
            let b = (l ^ p) & 1;
            p = l;
            b
        })
        .collect()
}

/// The content of one word (a slot or a header word). See protocol §4.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Word {
    /// 16 data bits.
    pub data: u16,
    /// Alive bit: toggled every cycle by the node that proves life in this slot.
    pub alive: bool,
    /// Alarm bit: the word is an alarm packet (reason in `data[15:12]`, or in
    /// `reason` with the extended-alarm frame variant).
    pub alarm: bool,
    /// Alarm reason nibble of the extended-alarm frame variant (0 when unused).
    pub reason: u8,
}

/// Nibbles of a word in transmission order (protocol §4), with both odd
/// parities filled in:
///
/// ```text
/// N0 = {ALARM, ALIVE, D1, D0}   first on the line: a node knows what the
///                                word is before it must forward the rest
/// [ext: REASON]                  extended-alarm variant only
/// D[5:2], D[9:6], D[13:10]
/// last = {PA, D15, D14, PB}      parities last: fixed up by a node that
///                                changed bits on the way
/// ```
pub fn word_nibbles(w: &Word, ext: bool) -> Vec<u8> {
    let d = w.data;
    let mut n: Vec<u8> = vec![((w.alarm as u8) << 3) | ((w.alive as u8) << 2) | (d & 3) as u8];
    if ext {
        n.push(w.reason & 0xf);
    }
    n.push(((d >> 2) & 0xf) as u8);
    n.push(((d >> 6) & 0xf) as u8);
    n.push(((d >> 10) & 0xf) as u8);
    n.push((((d >> 14) & 3) as u8) << 1);
    // Parity A: odd over bits 3,2 of every nibble; parity B: odd over bits
    // 2,1,0 of every nibble. Computed with both parity bits 0, then set.
    let ones_a: u32 = n.iter().map(|x| (x & 0b1100).count_ones()).sum();
    let ones_b: u32 = n.iter().map(|x| (x & 0b0111).count_ones()).sum();
    let last = n.len() - 1;
    n[last] |= ((ones_a % 2 == 0) as u8) << 3 | (ones_b % 2 == 0) as u8;
    n
}

/// The word a nibble sequence (in transmission order) carries; parity is not
/// checked here.
pub fn word_from_nibbles(n: &[u8], ext: bool) -> Word {
    let k = if ext { 2 } else { 1 };
    let last = n[n.len() - 1];
    let data = (n[0] & 3) as u16
        | (n[k] as u16) << 2
        | (n[k + 1] as u16) << 6
        | (n[k + 2] as u16) << 10
        | (((last >> 1) & 3) as u16) << 14;
    Word {
        data,
        alive: n[0] & 0b0100 != 0,
        alarm: n[0] & 0b1000 != 0,
        reason: if ext { n[1] } else { 0 },
    }
}

/// Both parities of a received nibble sequence hold.
pub fn parity_ok(n: &[u8]) -> bool {
    let ones_a: u32 = n.iter().map(|x| (x & 0b1100).count_ones()).sum();
    let ones_b: u32 = n.iter().map(|x| (x & 0b0111).count_ones()).sum();
    ones_a % 2 == 1 && ones_b % 2 == 1
}

/// Code bits (MSB of each group first) of a word.
pub fn word_code_bits(w: &Word, ext: bool) -> Vec<u8> {
    let mut bits = Vec::new();
    for nib in word_nibbles(w, ext) {
        push_group(&mut bits, encode_nibble(nib));
    }
    bits
}

/// Appends the 5 bits of a code group, MSB first.
pub fn push_group(bits: &mut Vec<u8>, g: u8) {
    for i in (0..GROUP_BITS).rev() {
        bits.push((g >> i) & 1);
    }
}

/// What the first group of a word shows: cut-through nodes decide from it
/// alone (protocol §4, §7), so a bad word's first group still matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lead {
    /// A data nibble with ALARM = 0.
    Data,
    /// A data nibble with ALARM = 1.
    Alarm,
    /// An S group (the start of a VOID word).
    S,
    /// Anything else.
    Other,
}

/// Classifies a word's first code group.
pub fn lead_of(group: u8) -> Lead {
    match decode_group(group) {
        Symbol::Data(n) if n & 0b1000 != 0 => Lead::Alarm,
        Symbol::Data(_) => Lead::Data,
        Symbol::S => Lead::S,
        _ => Lead::Other,
    }
}

/// What a receiver makes of one word's worth of code groups.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rx {
    /// All groups are data and both parities hold.
    Ok(Word),
    /// All groups S: the special master could not refresh this slot.
    Void,
    /// Anything else: parity error or invalid/control group; what its first
    /// group showed.
    Bad(Lead),
    /// Bad with a T as its last group: a forwarder marked it, it was damaged
    /// before the fibre it was read on (protocol §4).
    Marked(Lead),
}

/// Code bits of a VOID word.
pub fn void_code_bits(ext: bool) -> Vec<u8> {
    let mut v = vec![];
    for _ in 0..if ext { 6 } else { 5 } {
        push_group(&mut v, CODE_S);
    }
    v
}

/// Decodes the code bits of one word (25 bits, 30 with `ext`).
pub fn decode_word(code_bits: &[u8], ext: bool) -> Rx {
    let groups = if ext { 6 } else { 5 };
    if code_bits.len() != groups * GROUP_BITS as usize {
        return Rx::Bad(Lead::Other);
    }
    let first = code_bits[..5].iter().fold(0u8, |a, &b| (a << 1) | (b & 1));
    let lead = lead_of(first);
    let last = code_bits[code_bits.len() - 5..]
        .iter()
        .fold(0u8, |a, &b| (a << 1) | (b & 1));
    if last == CODE_T {
        return Rx::Marked(lead);
    }
    let mut nibs = Vec::with_capacity(groups);
    let mut all_s = true;
    for g in code_bits.chunks(GROUP_BITS as usize) {
        let v = g.iter().fold(0u8, |a, &b| (a << 1) | (b & 1));
        match decode_group(v) {
            Symbol::Data(n) => {
                nibs.push(n);
                all_s = false;
            }
            Symbol::S => {}
            _ => return Rx::Bad(lead),
        }
    }
    if all_s && nibs.is_empty() {
        return Rx::Void;
    }
    if nibs.len() != groups || !parity_ok(&nibs) {
        return Rx::Bad(lead);
    }
    Rx::Ok(word_from_nibbles(&nibs, ext))
}

/// Sends `w` (followed by `next`, or an idle group when it is the last word)
/// over a line, flips line bit `bit` of `w` (0-based; must be below the word's
/// line length) and decodes both again. NRZI turns one line-bit flip into two
/// adjacent code-bit flips, so a flip of the last bit of `w` also damages the
/// first bit of `next`. This is how the model applies an injected bit error.
pub fn flip_and_decode(w: &Word, next: Option<&Word>, ext: bool, bit: usize) -> (Rx, Option<Rx>) {
    let n = next.map(|n| word_code_bits(n, ext));
    flip_code_and_decode(&word_code_bits(w, ext), n.as_deref(), ext, bit)
}

/// As [`flip_and_decode`], on the code bits of a word (a data word or a VOID).
pub fn flip_code_and_decode(
    code: &[u8],
    next: Option<&[u8]>,
    ext: bool,
    bit: usize,
) -> (Rx, Option<Rx>) {
    let mut full = code.to_vec();
    match next {
        Some(n) => full.extend_from_slice(n),
        None => push_group(&mut full, CODE_I),
    }
    let mut level = 0;
    let mut line = nrzi_encode(&full, &mut level);
    line[bit] ^= 1;
    let back = nrzi_decode(&line, 0);
    let first = decode_word(&back[..code.len()], ext);
    let second = next.map(|_| decode_word(&back[code.len()..], ext));
    (first, second)
}

/// The code bits a forwarder sends for a word that arrived bad (protocol
/// §4): its first groups as they came (`code`, the word's code bits as
/// received), the last group replaced by [`CODE_T`].
pub fn mark_code_bits(code: &[u8]) -> Vec<u8> {
    let mut v = code[..code.len() - 5].to_vec();
    push_group(&mut v, CODE_T);
    v
}

/// The code bits a fibre carries instead of `len` bits during a burst of
/// garbage (a scenario's `kind = "burst"`, protocol §4): pseudo-random from
/// `pattern` (a 16-bit Galois LFSR, taps 0xB400, from `pattern << 8 | 0xA5`,
/// one step per bit), but the line toggles at least every 3 bit times (no
/// more than two 0s in a row: the receivers keep their bit lock, nobody
/// mutes) and never 10 times in a row (no three idle groups: no receiver
/// ends the packet), and on the first and the last bit. The RTL harness
/// (`merkur_rtl::harness::ring_top`) makes the same sequence.
pub fn garbage(pattern: u8, len: usize) -> Vec<u8> {
    let mut s: u16 = (pattern as u16) << 8 | 0xA5;
    let (mut zeros, mut ones) = (0, 0);
    (0..len)
        .map(|i| {
            let r = (s & 1) as u8;
            s >>= 1;
            if r == 1 {
                s ^= 0xB400;
            }
            let mut g = r;
            if zeros >= 2 {
                g = 1;
            }
            if ones >= 9 {
                g = 0;
            }
            if i == 0 || i + 1 == len {
                g = 1;
            }
            if g == 1 {
                ones += 1;
                zeros = 0;
            } else {
                zeros += 1;
                ones = 0;
            }
            g
        })
        .collect()
}

/// Line bits of one word.
pub fn word_bits(ext: bool) -> u32 {
    if ext {
        30
    } else {
        25
    }
}

/// Finds every position where the 10-bit JK delimiter appears in a code-bit
/// stream. Receivers hunt for it at every bit position while idle.
pub fn find_jk(code_bits: &[u8]) -> Vec<usize> {
    let mut pat = Vec::new();
    push_group(&mut pat, CODE_J);
    push_group(&mut pat, CODE_K);
    code_bits
        .windows(pat.len())
        .enumerate()
        .filter(|(_, w)| *w == pat.as_slice())
        .map(|(i, _)| i)
        .collect()
}
