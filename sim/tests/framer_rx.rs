//! framer_rx in Verilator: finds every packet start, groups every packet
//! exactly as the model's code-bit stream has them, ignores packets whose
//! J K was destroyed, and is not fooled by single line-bit errors in data;
//! `o_idle` flags exactly the idle groups (a packet cut short upstream
//! carries them, protocol §5).

use merkur_model::line::{
    find_jk, nrzi_decode, nrzi_encode, push_group, word_code_bits, Word, CODE_I, CODE_J, CODE_K,
    CODE_S,
};
use merkur_rtl::{emit::verilog::block_verilog, line::framer_rx::FramerRx};
use merkur_sim::{verilator::Model, Rng};

struct Frame {
    /// Index of the first code bit after J K.
    body: usize,
    words: usize,
    jk_destroyed: bool,
}

#[test]
fn frames_are_found_and_grouped_like_the_model() {
    let seed = Rng::seed(0xf4a3);
    let mut rng = Rng::new(seed);
    let mut code = vec![];
    let mut frames = vec![];
    let mut flips = vec![];
    for _ in 0..300 {
        for _ in 0..4 + rng.below(6) {
            push_group(&mut code, CODE_I);
        }
        let jk_at = code.len();
        push_group(&mut code, CODE_J);
        push_group(&mut code, CODE_K);
        let body = code.len();
        let words = 2 + 1 + rng.below(20) as usize;
        for _ in 0..words {
            if rng.below(8) == 0 {
                for _ in 0..5 {
                    push_group(&mut code, CODE_S);
                }
            } else if rng.below(12) == 0 {
                // Idles inside the packet (the framer groups them like any
                // other code; the word layer ends a cut packet at them).
                for _ in 0..5 {
                    push_group(&mut code, CODE_I);
                }
            } else {
                let w = Word {
                    data: rng.next_u64() as u16,
                    alive: rng.below(2) == 1,
                    alarm: rng.below(5) == 0,
                    reason: 0,
                };
                code.extend(word_code_bits(&w, false));
            }
        }
        let kind = rng.below(6);
        let jk_destroyed = kind == 0;
        if jk_destroyed {
            flips.push(jk_at + rng.below(10) as usize);
        } else if kind == 1 {
            flips.push(body + rng.below((words * 25) as u64) as usize);
        }
        frames.push(Frame {
            body,
            words,
            jk_destroyed,
        });
    }
    for _ in 0..8 {
        push_group(&mut code, CODE_I);
    }
    let mut level = 0;
    let mut line = nrzi_encode(&code, &mut level);
    for &f in &flips {
        line[f] ^= 1;
    }
    let decoded = nrzi_decode(&line, 0);
    // The model's view: every J K in the decoded stream outside packets.
    let live: Vec<&Frame> = frames.iter().filter(|f| !f.jk_destroyed).collect();
    for f in &frames {
        let found = find_jk(&decoded[f.body - 10..f.body]).len() == 1;
        assert_eq!(found, !f.jk_destroyed, "seed {seed}: stream construction");
    }

    let mut m = Model::build(&block_verilog(FramerRx::new())).unwrap();
    let (clk, v, code_in, end, start, gv, grp) = (
        m.port("clock"),
        m.port("i_valid"),
        m.port("i_code"),
        m.port("i_end"),
        m.port("o_start"),
        m.port("o_gvalid"),
        m.port("o_group"),
    );
    let idle = m.port("o_idle");
    let mut idles_seen = 0;
    let mut got: Vec<Vec<u8>> = vec![];
    let mut expect_groups = 0usize;
    let mut i = 0;
    let mut idle_clocks = 0;
    let mut end_pending = false;
    while i < line.len() || idle_clocks < 4 {
        let valid = i < line.len() && rng.below(4) != 0;
        if i >= line.len() {
            idle_clocks += 1;
        }
        m.set(v, valid as u64);
        // The code bits as the clock recovery gives them (the model's
        // NRZI decode of the line).
        m.set(code_in, if valid { decoded[i] as u64 } else { 0 });
        if valid {
            i += 1;
        }
        // The word layer: a one-clock end pulse after the packet's last group.
        m.set(end, end_pending as u64);
        end_pending = false;
        m.tick(clk);
        if m.get(start) == 1 {
            let n = got.len();
            assert!(
                n < live.len(),
                "seed {seed}: more packet starts than packets"
            );
            expect_groups = live[n].words * 5;
            got.push(vec![]);
        }
        if m.get(gv) == 1 {
            let cur = got.last_mut().expect("group before any start");
            assert!(
                cur.len() < expect_groups,
                "seed {seed}: group after the packet's end"
            );
            cur.push(m.get(grp) as u8);
            idles_seen += m.get(idle);
            assert_eq!(
                m.get(idle),
                u64::from(m.get(grp) == 31),
                "seed {seed}: o_idle beside group {:05b}",
                m.get(grp)
            );
            end_pending = cur.len() == expect_groups;
        }
    }
    assert_eq!(got.len(), live.len(), "seed {seed}: packets found");
    assert!(idles_seen > 0, "seed {seed}: o_idle never rose");
    for (k, (g, f)) in got.iter().zip(&live).enumerate() {
        let want: Vec<u8> = decoded[f.body..f.body + f.words * 25]
            .chunks(5)
            .map(|c| c.iter().fold(0u8, |a, &b| a << 1 | b))
            .collect();
        assert_eq!(
            g, &want,
            "seed {seed} (MERKUR_SEED): packet {k} grouped differently from the model"
        );
    }
}
