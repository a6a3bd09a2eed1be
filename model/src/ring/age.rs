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

/// Data age of one class of copies over a run (protocol §8).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AgeStat {
    /// Copies counted (per node, slot and cycle).
    pub copies: u64,
    /// Sum of their ages, in cycles.
    pub sum: u64,
    /// The oldest, in cycles.
    pub worst: u32,
    /// Copies older than the same copy in the reference run.
    pub older: u64,
}

impl AgeStat {
    /// Mean age in cycles (0 without copies).
    pub fn mean(&self) -> f64 {
        self.sum as f64 / self.copies.max(1) as f64
    }
}

/// Data age of the copies of critical slots (`[0]`) and of the other slots
/// (`[1]`, by `critical`, per slot) in `recs`, from cycle `from` on, and
/// how many were older than in `reference` (the same ring without the
/// errors, cycle for cycle). Copies without a value yet are left out.
pub fn age_stats(
    cfg: &Config,
    critical: &[bool],
    recs: &[CycleRecord],
    reference: &[CycleRecord],
    from: usize,
) -> [AgeStat; 2] {
    let mut st = [AgeStat::default(); 2];
    for (r, q) in recs.iter().zip(reference).skip(from) {
        let want: std::collections::BTreeMap<_, _> = ages(cfg, q).into_iter().collect();
        for ((k, s), age) in ages(cfg, r) {
            let Some(a) = age else { continue };
            let x = &mut st[usize::from(!critical[s])];
            x.copies += 1;
            x.sum += a as u64;
            x.worst = x.worst.max(a);
            if want.get(&(k, s)).copied().flatten().is_some_and(|b| a > b) {
                x.older += 1;
            }
        }
    }
    st
}
