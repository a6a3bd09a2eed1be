//! Wishbone B4 classic transfers from a testbench (the host port of
//! [`merkur_rtl::node::mdb`], alone or through the ring top).

use crate::verilator::Model;

/// The Wishbone ports of a model.
#[derive(Debug, Clone, Copy)]
pub struct Wishbone {
    cyc: usize,
    stb: usize,
    we: usize,
    adr: usize,
    dat_w: usize,
    dat_r: usize,
    ack: usize,
}

/// Clock ticks a transfer may wait for its acknowledge.
const ACK_TICKS: u32 = 200;

impl Wishbone {
    /// The ports `i_wb_cyc`, `i_wb_stb`, `i_wb_we`, `i_wb_adr`, `i_wb_dat`,
    /// `o_wb_dat`, `o_wb_ack` of `m`.
    pub fn new(m: &Model) -> Wishbone {
        Wishbone {
            cyc: m.port("i_wb_cyc"),
            stb: m.port("i_wb_stb"),
            we: m.port("i_wb_we"),
            adr: m.port("i_wb_adr"),
            dat_w: m.port("i_wb_dat"),
            dat_r: m.port("o_wb_dat"),
            ack: m.port("o_wb_ack"),
        }
    }

    /// One transfer: a write of `write` or a read; `tick` advances the
    /// slave's clock by one cycle. Returns the data read (or acknowledged)
    /// and the ticks used.
    pub fn transfer(
        &self,
        m: &mut Model,
        tick: &mut dyn FnMut(&mut Model),
        adr: u16,
        write: Option<u16>,
    ) -> Result<(u16, u32), String> {
        m.set(self.adr, adr as u64);
        m.set(self.we, write.is_some() as u64);
        m.set(self.dat_w, write.unwrap_or(0) as u64);
        m.set(self.cyc, 1);
        m.set(self.stb, 1);
        for t in 1..=ACK_TICKS {
            tick(m);
            if m.get(self.ack) == 1 {
                let v = m.get(self.dat_r) as u16;
                m.set(self.cyc, 0);
                m.set(self.stb, 0);
                // The acknowledge ends at the slave's next clock edge (in a
                // ring the node's clock is not every tick): wait for it, so
                // the next transfer never sees this one's acknowledge.
                let mut used = t;
                while m.get(self.ack) == 1 && used < 2 * ACK_TICKS {
                    tick(m);
                    used += 1;
                }
                return Ok((v, used));
            }
        }
        m.set(self.cyc, 0);
        m.set(self.stb, 0);
        Err(format!(
            "Wishbone: no acknowledge for address {adr:#06x} within {ACK_TICKS} clocks"
        ))
    }
}
