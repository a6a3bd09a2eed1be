//! Data age (docs/protocol.md §8, retransmission on demand): how old each
//! copy of a slot is at the end of a cycle, counted in cycles from the one
//! in which the slot's writer wrote the value.

use super::*;

/// The data age of every copy the ring delivers at the end of cycle
/// `r.cycle`, per (node, slot): a master's memory of each slot it does not
/// write, an actuator's output register; `None` before its first value.
/// Dead nodes are left out.
pub fn ages(cfg: &Config, r: &CycleRecord) -> Vec<((usize, usize), Option<u32>)> {
    let age = |born: Option<u32>| born.map(|b| r.cycle - b);
    let mut v = vec![];
    for (k, st) in r.nodes.iter().enumerate() {
        if !st.up {
            continue;
        }
        match cfg.nodes[k].kind {
            Kind::Actuator => v.push(((k, cfg.nodes[k].address), age(st.out_born))),
            Kind::Master | Kind::SpecialMaster => {
                for (s, &born) in st.db_born.iter().enumerate() {
                    if cfg.writer[s] != k {
                        v.push(((k, s), age(born)));
                    }
                }
            }
            Kind::Sensor => {}
        }
    }
    v
}
