//! Line-code blocks in Verilator against the model (protocol §2).

use merkur_model::line::{
    decode_group, nrzi_encode, push_group, Symbol, CODE_I, CODE_J, CODE_K, CODE_S, DATA_CODES,
};
use merkur_rtl::{
    emit::verilog::block_verilog, line::dec5b4b::Dec5b4b, line::enc4b5b::Enc4b5b,
    line::nrzi_tx::NrziTx,
};
use merkur_sim::{verilator::Model, Rng};

#[test]
fn enc4b5b_every_symbol() {
    let mut m = Model::build(&block_verilog(Enc4b5b::default())).unwrap();
    let (i, o) = (m.port("i_sym"), m.port("o_code"));
    for sym in 0..32u64 {
        m.set(i, sym);
        m.eval();
        let want = match sym {
            0..=15 => DATA_CODES[sym as usize],
            16 => CODE_J,
            17 => CODE_K,
            19 => CODE_S,
            _ => CODE_I,
        };
        assert_eq!(m.get(o) as u8, want, "symbol {sym}");
    }
}

#[test]
fn dec5b4b_every_group_and_round_trip() {
    let mut m = Model::build(&block_verilog(Dec5b4b::default())).unwrap();
    let p = |m: &Model, n: &str| m.port(n);
    let (i, nib, data, j, k, idle, s) = (
        p(&m, "i_code"),
        p(&m, "o_nibble"),
        p(&m, "o_data"),
        p(&m, "o_j"),
        p(&m, "o_k"),
        p(&m, "o_i"),
        p(&m, "o_s"),
    );
    for g in 0..32u8 {
        m.set(i, g as u64);
        m.eval();
        let got = (m.get(data), m.get(j), m.get(k), m.get(idle), m.get(s));
        match decode_group(g) {
            Symbol::Data(n) => {
                assert_eq!(got, (1, 0, 0, 0, 0), "group {g:05b}");
                assert_eq!(m.get(nib) as u8, n, "group {g:05b}");
            }
            Symbol::J => assert_eq!(got, (0, 1, 0, 0, 0)),
            Symbol::K => assert_eq!(got, (0, 0, 1, 0, 0)),
            Symbol::I => assert_eq!(got, (0, 0, 0, 1, 0)),
            Symbol::S => assert_eq!(got, (0, 0, 0, 0, 1)),
            Symbol::Invalid(_) => assert_eq!(got, (0, 0, 0, 0, 0), "group {g:05b} must be invalid"),
        }
    }
    // decode(encode(x)) = x for every nibble.
    for n in 0..16u8 {
        m.set(i, DATA_CODES[n as usize] as u64);
        m.eval();
        assert_eq!((m.get(data), m.get(nib) as u8), (1, n));
    }
}

/// Random groups, random bit-enable pattern (and tied high): the line equals
/// the model's NRZI encoding bit for bit.
#[test]
fn nrzi_tx_matches_the_model() {
    let seed = Rng::seed(0x6e727a69);
    let mut m = Model::build(&block_verilog(NrziTx::default())).unwrap();
    let (clk, en, code, take, line) = (
        m.port("clock"),
        m.port("i_bit_en"),
        m.port("i_code"),
        m.port("o_take"),
        m.port("o_line"),
    );
    for dense in [true, false] {
        let mut rng = Rng::new(seed ^ dense as u64);
        let all: Vec<u8> = DATA_CODES
            .iter()
            .copied()
            .chain([CODE_J, CODE_K, CODE_I, CODE_S])
            .collect();
        let groups: Vec<u8> = (0..4000)
            .map(|_| all[rng.below(all.len() as u64) as usize])
            .collect();
        // Reset state by sending idles until the serializer is at a group start.
        let mut sent = vec![];
        let mut next = 0usize;
        let mut line_bits = vec![];
        let mut started = false;
        let mut level0 = 0u8;
        let mut cycles = 0;
        while line_bits.len() < groups.len() * 5 {
            cycles += 1;
            assert!(cycles < 200_000, "seed {seed}: serializer stalled");
            let bit_en = dense || rng.below(3) == 0;
            m.set(en, bit_en as u64);
            let g = if started {
                groups.get(next).copied().unwrap_or(CODE_I)
            } else {
                CODE_I
            };
            m.set(code, g as u64);
            m.set(clk, 0);
            m.eval();
            let taking = m.get(take) == 1;
            if taking && !started {
                started = true;
                level0 = m.get(line) as u8;
                m.set(code, groups[0] as u64);
                m.eval();
            }
            let took = taking && started;
            m.set(clk, 1);
            m.eval();
            if took {
                sent.push(groups[next]);
                next += 1;
            }
            if bit_en && started {
                line_bits.push(m.get(line) as u8);
            }
        }
        let mut code_bits = vec![];
        for g in &groups {
            push_group(&mut code_bits, *g);
        }
        let mut level = level0;
        let want = nrzi_encode(&code_bits, &mut level);
        assert_eq!(line_bits.len(), want.len());
        if let Some(i) = line_bits.iter().zip(&want).position(|(a, b)| a != b) {
            panic!("seed {seed} (MERKUR_SEED to repeat), dense={dense}: line bit {i} is {}, model says {}", line_bits[i], want[i]);
        }
    }
}
