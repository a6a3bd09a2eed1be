//! Hand-checked vectors and exhaustive checks of the line level
//! (docs/protocol.md §2–§4).

use merkur_model::line::*;

#[test]
fn code_table_hand_vectors() {
    // FDDI / 100BASE-X 4B/5B, checked against the standard's table by hand.
    assert_eq!(encode_nibble(0x0), 0b11110);
    assert_eq!(encode_nibble(0x1), 0b01001);
    assert_eq!(encode_nibble(0x5), 0b01011);
    assert_eq!(encode_nibble(0x9), 0b10011);
    assert_eq!(encode_nibble(0xF), 0b11101);
    assert_eq!(decode_group(0b11000), Symbol::J);
    assert_eq!(decode_group(0b10001), Symbol::K);
    assert_eq!(decode_group(0b11111), Symbol::I);
    assert_eq!(decode_group(0b11001), Symbol::S);
    assert_eq!(decode_group(0b00000), Symbol::Invalid(0));
    for n in 0..16u8 {
        assert_eq!(decode_group(encode_nibble(n)), Symbol::Data(n));
    }
}

#[test]
fn nrzi_hand_vector() {
    let mut level = 0;
    assert_eq!(
        nrzi_encode(&[1, 0, 1, 1, 0], &mut level),
        vec![1, 1, 0, 1, 1]
    );
    assert_eq!(level, 1);
    assert_eq!(nrzi_decode(&[1, 1, 0, 1, 1], 0), vec![1, 0, 1, 1, 0]);
}

#[test]
fn word_hand_vectors() {
    // All-zero word: parity A over bits 3,2 sees no ones -> PA = 1;
    // parity B over bits 2,1,0 sees none -> PB = 1. Last nibble 1001.
    let z = Word::default();
    assert_eq!(word_nibbles(&z, false), vec![0, 0, 0, 0, 0b1001]);
    // 0x1234 with Alive (protocol §4 layout, worked by hand):
    // N0 = {ALARM 0, ALIVE 1, D1 0, D0 0} = 0100; D[5:2] = 1101; D[9:6] = 1000;
    // D[13:10] = 0100; last = {PA, D15 0, D14 0, PB}.
    // A (bits 3,2): 1 + 2 + 1 + 1 = 5, odd -> PA = 0.
    // B (bits 2,1,0): 1 + 2 + 0 + 1 = 4, even -> PB = 1. Last = 0001.
    let w = Word {
        data: 0x1234,
        alive: true,
        alarm: false,
        reason: 0,
    };
    assert_eq!(word_nibbles(&w, false), vec![0x4, 0xD, 0x8, 0x4, 0x1]);
    let bits = word_code_bits(&w, false);
    let s: String = bits.iter().map(|b| char::from(b'0' + b)).collect();
    assert_eq!(
        s,
        "01010".to_string() + "11011" + "10010" + "01010" + "01001"
    );
    assert_eq!(decode_word(&bits, false), Rx::Ok(w));
    // RECONFIG(WU) alarm, reason 5 in D[15:12]: data 0x5000, Alarm set.
    // N0 = 1000; D[5:2] = 0; D[9:6] = 0; D[13:10] = 0100; D15 0, D14 1.
    // A: 1 + 0 + 0 + 1 + 0 = 2, even -> PA = 1. B: 0 + 0 + 0 + 1 + 1 = 2 -> PB = 1.
    let a = Word {
        data: 0x5000,
        alive: false,
        alarm: true,
        reason: 0,
    };
    assert_eq!(word_nibbles(&a, false), vec![0x8, 0x0, 0x0, 0x4, 0b1011]);
    // VOID: five S groups.
    let mut v = vec![];
    for _ in 0..5 {
        push_group(&mut v, CODE_S);
    }
    assert_eq!(decode_word(&v, false), Rx::Void);
}

#[test]
fn every_word_round_trips() {
    for data in 0..=u16::MAX {
        for (alive, alarm) in [(false, false), (true, false), (false, true), (true, true)] {
            let w = Word {
                data,
                alive,
                alarm,
                reason: 0,
            };
            assert_eq!(decode_word(&word_code_bits(&w, false), false), Rx::Ok(w));
        }
    }
}

/// Exhaustive: every single NRZI line-bit flip in every possible 25-bit word
/// is caught (the word decodes Bad), and the following word, which shares
/// the damage when the last bit flips, is never turned into another good word.
#[test]
fn every_single_line_bit_flip_is_detected() {
    let next = Word {
        data: 0xa5c3,
        alive: true,
        alarm: false,
        reason: 0,
    };
    let mut checked = 0u64;
    for data in 0..=u16::MAX {
        for (alive, alarm) in [(false, false), (true, false), (false, true), (true, true)] {
            let w = Word {
                data,
                alive,
                alarm,
                reason: 0,
            };
            for bit in 0..25 {
                let (a, b) = flip_and_decode(&w, Some(&next), false, bit);
                // (Marked: the error turned the last group into T, §4.)
                assert!(
                    matches!(a, Rx::Bad(_) | Rx::Marked(_)),
                    "flip of bit {bit} in {w:?} not detected"
                );
                if let Some(Rx::Ok(b)) = b {
                    assert_eq!(b, next, "flip of bit {bit} in {w:?} changed the next word");
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 65536 * 4 * 25);
}

/// The extended-alarm word (30 bits): sampled, seeded.
#[test]
fn extended_word_flips_are_detected() {
    let mut x: u64 = 0x5eed_0001;
    for _ in 0..40_000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let w = Word {
            data: x as u16,
            alive: x & (1 << 20) != 0,
            alarm: x & (1 << 21) != 0,
            reason: ((x >> 24) & 0xf) as u8,
        };
        assert_eq!(decode_word(&word_code_bits(&w, true), true), Rx::Ok(w));
        for bit in 0..30 {
            let (a, _) = flip_and_decode(&w, None, true, bit);
            assert!(
                matches!(a, Rx::Bad(_) | Rx::Marked(_)),
                "seed 0x5eed0001: flip of bit {bit} in {w:?}"
            );
        }
    }
}

/// JK appears nowhere in any sequence of data, idle and S groups, at any
/// bit offset: data cannot imitate the start delimiter.
#[test]
fn jk_cannot_be_imitated_by_data() {
    let mut groups: Vec<u8> = DATA_CODES.to_vec();
    groups.push(CODE_I);
    groups.push(CODE_S);
    groups.push(CODE_T);
    for &a in &groups {
        for &b in &groups {
            for &c in &groups {
                let mut bits = vec![];
                push_group(&mut bits, a);
                push_group(&mut bits, b);
                push_group(&mut bits, c);
                assert!(
                    find_jk(&bits).is_empty(),
                    "JK inside {a:05b} {b:05b} {c:05b}"
                );
            }
        }
    }
}

/// One line-bit flip in an idle stream never makes a JK (no false frame
/// starts between frames), and a flipped JK is never still a JK.
#[test]
fn single_flips_make_and_break_no_jk() {
    let mut code = vec![];
    for _ in 0..8 {
        push_group(&mut code, CODE_I);
    }
    for p in 0..code.len() {
        let mut level = 0;
        let mut line = nrzi_encode(&code, &mut level);
        line[p] ^= 1;
        assert!(
            find_jk(&nrzi_decode(&line, 0)).is_empty(),
            "flip {p} in idles made a JK"
        );
    }
    let mut jk = vec![];
    push_group(&mut jk, CODE_I);
    push_group(&mut jk, CODE_J);
    push_group(&mut jk, CODE_K);
    push_group(&mut jk, encode_nibble(0));
    assert_eq!(find_jk(&jk), vec![5]);
    for p in 5..15 {
        let mut level = 0;
        let mut line = nrzi_encode(&jk, &mut level);
        line[p] ^= 1;
        assert!(
            !find_jk(&nrzi_decode(&line, 0)).contains(&5),
            "flip {p} kept the JK"
        );
    }
}

/// Inside packets the line toggles at least every 4 bit times with every
/// group a packet can hold — data, S, idle and the forwarder's mark T
/// (protocol §2, §4): no run of more than three 0 code bits across any
/// two groups.
#[test]
fn no_long_zero_runs_with_any_packet_group() {
    let mut groups: Vec<u8> = DATA_CODES.to_vec();
    groups.extend([CODE_I, CODE_S, CODE_T]);
    for &a in &groups {
        for &b in &groups {
            let mut bits = vec![];
            push_group(&mut bits, a);
            push_group(&mut bits, b);
            let longest = bits.split(|&x| x == 1).map(|z| z.len()).max().unwrap_or(0);
            assert!(longest <= 3, "{a:05b} {b:05b}: {longest} zeros in a row");
        }
    }
    // T is no data group: a marked word is never good.
    assert!(matches!(decode_group(CODE_T), Symbol::Invalid(_)));
}
