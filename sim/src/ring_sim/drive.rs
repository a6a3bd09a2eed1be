//! The run of one scenario's ring, in phases: the [`Plan`] worked out from
//! the scenario and the model's records before the run (what the driver
//! does and when), the start (configuration, masters, requests of cycle 0),
//! the tick loop ([`Drive::run_loop`]: frame starts, host writes, requests,
//! faults, polling), and the end-of-run comparisons ([`Drive::finish`]).

use super::*;

/// Cycle spans, first and last cycle (the recovery windows).
type Spans = Vec<(u32, u32)>;

/// A fault of the scenario waiting for its moment: (fault index, cycle,
/// when, configuration write (select, field, value)).
type Pending = (usize, u32, When, (usize, u32, u64));

/// What the driver does and when, from the scenario and the model's
/// records, before the run.
pub(super) struct Plan {
    /// The nodes with a clock base (the special master and the backups).
    clock_bases: Vec<usize>,
    /// The masters, the special master last (its start bit starts the frames).
    order: Vec<usize>,
    /// The cycles in which the model's clock base sent a frame (all but
    /// those between the clock base's death and a backup's takeover, §8).
    framed: Vec<u32>,
    last_framed: u32,
    /// User requests: (cycle, node, request bits).
    reqs: Vec<(u32, usize, u64)>,
    /// Host writes after the start: (cycle, node, address, data).
    writes: Vec<(u32, usize, usize, u16)>,
    /// The faults not yet injected.
    faults: Vec<Pending>,
    /// The recovery windows (protocol §13), and the same extended by
    /// their repeat tails, overlapping ones merged.
    wins: Spans,
    ext: Spans,
}

impl Plan {
    pub(super) fn new(cfg: &Config, recs: &[CycleRecord]) -> Result<Plan, String> {
        let n = cfg.nodes.len();
        let rtl_kinds = rtl_kinds(cfg);
        let clock_bases: Vec<usize> = (0..n)
            .filter(|&k| rtl_kinds[k] == Kind::SpecialMaster)
            .collect();
        let mut order: Vec<usize> = (0..n)
            .filter(|&k| cfg.nodes[k].kind == Kind::Master)
            .collect();
        order.push(cfg.sm);
        let framed: Vec<u32> = (0..cfg.cycles)
            .filter(|&c| !recs[c as usize].path.is_empty())
            .collect();
        let last_framed = *framed.last().ok_or("the model's ring sends no frame")?;
        let (wins, ext) = Self::windows(cfg, recs);
        Ok(Plan {
            clock_bases,
            order,
            framed,
            last_framed,
            reqs: Self::requests(cfg),
            writes: Self::writes(cfg, recs),
            faults: Self::faults(cfg, recs),
            wins,
            ext,
        })
    }

    /// The user requests per cycle and node, their bits or-ed together.
    /// Requests of cycle 0 are raised at the start, later ones after the
    /// previous frame has passed the node.
    fn requests(cfg: &Config) -> Vec<(u32, usize, u64)> {
        let mut reqs: Vec<(u32, usize, u64)> = vec![];
        for &(c, node, line) in &cfg.irqs {
            let bit = match line {
                IrqLine::Irq1 => 1,
                IrqLine::Irq2 => 2,
                IrqLine::Failsafe => 4,
            };
            match reqs.iter_mut().find(|x| x.0 == c && x.1 == node) {
                Some(x) => x.2 |= bit,
                None => reqs.push((c, node, bit)),
            }
        }
        reqs.sort();
        reqs
    }

    /// Host writes after the start, and the clock base's host's failsafe
    /// clear commands (to its status register), by cycle.
    fn writes(cfg: &Config, recs: &[CycleRecord]) -> Vec<(u32, usize, usize, u16)> {
        // The clock base at cycle c's start (the special master, or the
        // backup that took over, protocol §8).
        let base_before = |c: u32| match c {
            0 => cfg.sm,
            _ => recs[c as usize - 1].base,
        };
        let mut writes: Vec<(u32, usize, usize, u16)> = cfg
            .host_writes
            .iter()
            .copied()
            .chain(
                cfg.fs_clears
                    .iter()
                    .map(|&c| (c, base_before(c), WB_STATUS as usize, ST_FS_CLEAR)),
            )
            .filter(|w| w.0 > 0)
            .collect();
        writes.sort_by_key(|w| w.0);
        writes
    }

    /// Every fault and when to inject it. Breaks and repairs are timed on
    /// the fibre's monitor, before slot s or before the delimiter; a death
    /// on the fibres out of the node that carry the model's frame (a
    /// wrapped ring passes some nodes twice): before slot s when the first
    /// of them has shown slot s − 1, before the delimiter when all have
    /// ended the previous frame. Flips and bursts wait for the previous
    /// frame (or SEC) on their fibre; a restart for its cycle's frame.
    fn faults(cfg: &Config, recs: &[CycleRecord]) -> Vec<Pending> {
        let n = cfg.nodes.len();
        cfg.faults
            .iter()
            .enumerate()
            .map(|(i, &(c, f))| match f {
                Fault::Break { fibre, slot } | Fault::Repair { fibre, slot } => {
                    let fi = fibre.index(n);
                    let dark = matches!(f, Fault::Break { .. });
                    (
                        i,
                        c,
                        When::Slot(vec![fi], slot),
                        (fi, field::BREAK, dark as u64),
                    )
                }
                // A restart's node gets power when its cycle's frame starts
                // (the power-on reset, then the node's fibres: `inject`).
                Fault::Restart { node } => (i, c, When::Started, (node, field::POR, 1)),
                Fault::Kill { node, slot } => {
                    let rec = &recs[if slot.is_some() {
                        c
                    } else {
                        c.saturating_sub(1)
                    } as usize];
                    let outs: Vec<usize> = [node, n + (node + n - 1) % n]
                        .into_iter()
                        .filter(|&fi| matches!(rec.fibres[fi], Carry::Data(_)))
                        .collect();
                    (i, c, When::Slot(outs, slot), (node, field::KILL, 1))
                }
                Fault::Burst {
                    fibre,
                    target,
                    bit,
                    len,
                    pattern,
                } => {
                    let fi = fibre.index(n);
                    let at = packet_bit(target, bit, cfg.word_bits() as u64);
                    let val = at | (len as u64) << 12 | (pattern as u64) << 24;
                    (i, c, When::FrameEnded(fi), (fi, field::FLIP, val))
                }
                Fault::Flip { fibre, target, bit } => {
                    let fi = fibre.index(n);
                    let at = packet_bit(target, bit, cfg.word_bits() as u64);
                    let when = match (target, &recs[c as usize].fibres[fi]) {
                        (FlipTarget::RtxHead | FlipTarget::Rtx(_), _) => When::RtxNext(fi),
                        (_, Carry::Sec { .. }) => When::Secs(fi, Self::secs_before(recs, c, fi)),
                        _ => When::FrameEnded(fi),
                    };
                    (i, c, when, (fi, field::FLIP, at))
                }
            })
            .collect()
    }

    /// Good SEC packets on fibre `fi` before cycle `c`, by the model.
    fn secs_before(recs: &[CycleRecord], c: u32, fi: usize) -> u64 {
        recs[..c as usize]
            .iter()
            .map(|x| {
                matches!(x.fibres[fi], Carry::Sec { ok: true }) as u64
                    + x.sec_with_data
                        .iter()
                        .filter(|&&(y, ok)| y == fi && ok)
                        .count() as u64
            })
            .sum()
    }

    /// The recovery windows, and the windows extended by the cycles after
    /// them in which an alarm sent inside may be repeated (protocol §11,
    /// §13), overlapping ones merged.
    fn windows(cfg: &Config, recs: &[CycleRecord]) -> (Spans, Spans) {
        let wins: Vec<(u32, u32)> = ring::windows(cfg, recs)
            .into_iter()
            .map(|(a, z, _)| (a, z))
            .collect();
        let mut ext: Vec<(u32, u32)> = vec![];
        for &(a, z) in &wins {
            match ext.last_mut() {
                Some(last) if a <= last.1 + 1 => last.1 = last.1.max(z + ring::REPEAT_TAIL),
                _ => ext.push((a, z + ring::REPEAT_TAIL)),
            }
        }
        (wins, ext)
    }

    /// The recovery window that holds cycle `c`.
    fn win_of(&self, c: u32) -> Span {
        self.wins.iter().copied().find(|&(a, z)| a <= c && c <= z)
    }

    /// The extended window that holds cycle `c`.
    fn ext_of(&self, c: u32) -> Span {
        self.ext.iter().copied().find(|&(a, z)| a <= c && c <= z)
    }

    /// A cycle in a window's repeat tail: the cycles before it from the
    /// window's start.
    fn tail_of(&self, c: u32) -> Span {
        self.ext_of(c)
            .filter(|_| self.win_of(c).is_none())
            .map(|(a, _)| (a, c - 1))
    }
}

/// A run in progress: the ring, the plan, and what the loop has seen.
pub(super) struct Drive<'a> {
    r: Ring,
    cfg: &'a Config,
    recs: &'a [CycleRecord],
    opts: &'a Options,
    plan: Plan,
    /// Start of the simulation's wall time (after the build).
    t1: Instant,
    /// The Verilator build's wall time.
    build: Duration,
    mism: Vec<Mismatch>,
    /// Words compared.
    words: u64,
    /// Frames the clock bases have started.
    sent: u32,
    /// Cycles compared.
    compared: u32,
    /// Per cycle, the tick its frame started.
    starts: Vec<u64>,
    /// The tick the last frame was started.
    stopped_at: Option<u64>,
    snaps: Snapshots,
    alq: alarms::AlarmQueues,
    /// Per fault, the tick it was injected.
    fault_ticks: Vec<Option<u64>>,
    /// Per fault timed in the idle gap, the tick to inject at.
    gap_at: Vec<Option<u64>>,
    /// Per fibre: ticks from a frame's start to its H1 there.
    pace: Vec<Pace>,
    mode_ticks: Vec<(usize, u64, u64)>,
    fs_ticks: Vec<Option<u64>>,
    /// Per node, the switchbox mode last polled.
    modes: Vec<u64>,
    /// Per frame start, the SEC packets seen per fibre before it.
    nsec_at: Vec<Vec<u64>>,
}

impl<'a> Drive<'a> {
    /// Builds (or takes from the cache) the ring's model and sets up the
    /// driver's view of it.
    pub(super) fn open(
        cfg: &'a Config,
        recs: &'a [CycleRecord],
        opts: &'a Options,
    ) -> Result<Drive<'a>, String> {
        let plan = Plan::new(cfg, recs)?;
        let n = cfg.nodes.len();
        let verilog = ring_verilog_of(cfg);
        let t0 = Instant::now();
        let mut m = Model::build_top_traced(&verilog, "merkur_ring", opts.wave.as_deref())?;
        let build = t0.elapsed();
        if opts.record {
            let clk = m.port("clk");
            m.start_recording(clk);
        }
        let p = |name: &str| m.port(name);
        let r = Ring {
            clk: p("clk"),
            cfg_we: p("i_cfg_we"),
            cfg_sel: p("i_cfg_sel"),
            cfg_field: p("i_cfg_field"),
            cfg_val: p("i_cfg_val"),
            rd_en: p("i_rd_en"),
            rd_sel: p("i_rd_sel"),
            rd_field: p("i_rd_field"),
            rd: p("o_rd"),
            cap_en: p("i_cap_en"),
            cap_f: p("i_cap_fibre"),
            cap_i: p("i_cap_idx"),
            cap: p("o_cap"),
            wb_node: p("i_wb_node"),
            wb: Wishbone::new(&m),
            m,
            ticks: 0,
            h1_seen: vec![[u64::MAX; 4]; 2 * n],
            capn: cap_slots(cfg.slots),
            ep: frames_before(recs),
            whole: vec![false; cfg.cycles as usize],
            alive_inv: vec![Some(false); cfg.slots],
            dump: opts.dump,
        };
        Ok(Drive {
            r,
            cfg,
            recs,
            opts,
            t1: Instant::now(),
            build,
            mism: vec![],
            words: 0,
            sent: 0,
            compared: 0,
            starts: vec![],
            stopped_at: None,
            snaps: Snapshots::new(n, cfg, recs),
            alq: alarms::AlarmQueues::new(cfg),
            fault_ticks: vec![None; cfg.faults.len()],
            gap_at: vec![None; cfg.faults.len()],
            pace: vec![Default::default(); 2 * n],
            mode_ticks: vec![],
            fs_ticks: vec![None; n],
            modes: vec![0; n],
            nsec_at: vec![],
            plan,
        })
    }

    /// Every node's configuration, the receivers locked, the masters
    /// loaded and started (the special master last), the requests of
    /// cycle 0 raised.
    pub(super) fn start(&mut self) -> Result<(), String> {
        let (s, period) = (self.cfg.slots, self.period());
        let (cfg, r) = (self.cfg, &mut self.r);
        let mut rng = Rng::new(self.opts.seed ^ cfg.seed);
        // Shared configuration: S−1, CS timeout 3.5 periods (3 per protocol
        // §12 plus margin for the clock offsets; 2.5 + the highest backup
        // priority with backups, §8: synth_top::ring_cs_timeout_clocks),
        // period.
        r.cfg(0, field::SLOTS_M1, s as u64 - 1);
        r.cfg(
            0,
            field::CS_TIMEOUT,
            merkur_rtl::top::synth_top::ring_cs_timeout_clocks(period, cfg.cs_timeout_cycles()),
        );
        r.cfg(0, field::PERIOD, period);
        // Retransmission timing (protocol §8) in every clock-base node (a
        // ring without critical slots leaves the power-up 0: none is sent).
        let rtx = merkur_rtl::top::synth_top::RtxStatic::of(cfg);
        for (k, nd) in cfg.nodes.iter().enumerate() {
            if nd.kind == Kind::SpecialMaster && cfg.last_critical().is_some() {
                r.cfg(k, field::RTX_AT, rtx.at as u64);
                r.cfg(k, field::RTX_ATW, rtx.at_wrapped as u64);
                r.cfg(k, field::RTX_K, (rtx.k | rtx.k_wrapped << 5) as u64);
            }
        }
        for (k, p) in cfg.backups() {
            r.cfg(k, field::PRIO, p as u64);
            r.cfg(
                k,
                field::ELECT,
                merkur_rtl::top::synth_top::elect_bits(period, p),
            );
        }
        for (k, nd) in cfg.nodes.iter().enumerate() {
            let inc = (INC_NOMINAL as f64 * (1.0 + nd.ppm * 1e-6)).round() as u64;
            r.cfg(k, field::INC, inc);
            r.cfg(k, field::PHASE, rng.next_u64() & 0xffff_ffff);
            r.cfg(k, field::ADDRESS, nd.address as u64);
            if nd.kind == Kind::Sensor {
                for c in 0..4u32.min(cfg.cycles) {
                    let v = merkur_model::ring::sensor_value(cfg, nd.address, c);
                    r.cfg(k, field::SENSOR, ((c as u64 & 3) << 16) | v as u64);
                }
            }
        }
        // Let every receiver lock to the idle lines.
        for _ in 0..400 * TICKS_PER_BIT {
            r.tick();
        }
        // Masters: configuration bytes, host writes of cycle 0, start; the
        // special master last (its start bit starts the frames).
        for &k in &self.plan.order {
            for slot in 0..s {
                let b = cfg.config_byte(k, slot);
                if b != 0 {
                    r.wb(k, WB_CFG + slot as u16, Some(b as u16))?;
                }
            }
            for &(c, node, slot, data) in &cfg.host_writes {
                if c == 0 && node == k {
                    r.wb(k, slot as u16, Some(data))?;
                }
            }
        }
        // The special master's failsafe exit (protocol §12): host exit, and a
        // clear command given before the start.
        for &k in &self.plan.clock_bases {
            if cfg.nodes[k].fs_exit_host {
                r.wb(k, WB_STATUS, Some(ST_FS_HOST))?;
            }
        }
        if cfg.fs_clears.contains(&0) {
            r.wb(cfg.sm, WB_STATUS, Some(ST_FS_CLEAR))?;
        }
        for &(_, node, bits) in self.plan.reqs.iter().filter(|x| x.0 == 0) {
            r.cfg(node, field::REQUEST, 0xc0 | bits);
        }
        self.plan.reqs.retain(|x| x.0 > 0);
        for &k in &self.plan.order {
            r.wb(k, WB_STATUS, Some(ST_RUN))?;
        }
        Ok(())
    }

    /// Nodes in the ring.
    fn n(&self) -> usize {
        self.cfg.nodes.len()
    }

    /// The cycle period, bit times.
    fn period(&self) -> u64 {
        self.cfg.period as u64
    }

    /// The fibre that feeds node `k`'s PI: P(k−1).
    fn pi_fibre(&self, k: usize) -> usize {
        (k + self.n() - 1) % self.n()
    }

    /// Ticks the ring until the last frame is back (or the ring has had
    /// its chance), doing every 4 ticks what the environment does now.
    pub(super) fn run_loop(&mut self) -> Result<(), String> {
        let cycles = self.cfg.cycles as u64;
        let limit = (cycles + 4) * self.period() * TICKS_PER_BIT as u64 * 2 + 100_000;
        loop {
            self.r.tick();
            if self.r.ticks % 4 != 0 {
                continue;
            }
            if self.r.ticks > limit {
                return Err(self.unfinished());
            }
            self.frame_starts()?;
            self.host_writes()?;
            self.requests();
            self.faults()?;
            if self.r.ticks % 16 == 0 {
                self.poll();
            }
            if self.stopped() {
                return Ok(());
            }
        }
    }

    /// The error of a ring that did not finish.
    fn unfinished(&mut self) -> String {
        let n = self.n();
        let ends: Vec<String> = (0..2 * n)
            .map(|f| format!("{} {}", fibre_name(f, n), self.r.rd(f, st::NEND)))
            .collect();
        format!(
            "the ring did not finish: {} of {} frames sent after {} ticks; frames ended per fibre: {}",
            self.sent,
            self.cfg.cycles,
            self.r.ticks,
            ends.join(", ")
        )
    }

    /// Cycles started: the frames the clock bases sent (a backup's after
    /// the special master's, protocol §8), each the model's next cycle with
    /// a frame; cycles without one (before a takeover) pass with the next
    /// frame, or two periods after the last at the run's end. At each: the
    /// SEC count, the stop command, the sensors' values two cycles ahead,
    /// the comparison of the cycle two back, the alarm queues.
    fn frame_starts(&mut self) -> Result<(), String> {
        let (cfg, recs) = (self.cfg, self.recs);
        let n = self.n();
        // (Summed in the ring top: one read.)
        let frames = self.r.rd(0, st::FRAMES_ALL) as usize;
        let framed = &self.plan.framed;
        let quiet_end = frames >= framed.len()
            && self
                .starts
                .last()
                .is_some_and(|&t| self.r.ticks > t + 2 * self.period() * TICKS_PER_BIT as u64);
        let now = match frames {
            0 => 0,
            _ if quiet_end => cfg.cycles,
            f => framed[(f - 1).min(framed.len() - 1)] + 1,
        };
        while self.sent < now {
            // Frame `sent` started (or, in a cycle without one, the next did).
            self.starts.push(self.r.ticks);
            // SEC packets seen per fibre before frame `sent` (a SEC starts
            // with its frame and is back within the period).
            let secs = (0..2 * n).map(|f| self.r.rd(f, st::NSEC)).collect();
            self.nsec_at.push(secs);
            let c = self.sent;
            self.sent += 1;
            if let Some(p) = &self.opts.progress {
                (p.0)(c, cfg.cycles);
            }
            if c == self.plan.last_framed {
                self.r.wb(recs[c as usize].base, WB_STATUS, Some(ST_STOP))?;
            }
            for (k, nd) in cfg.nodes.iter().enumerate() {
                // Cycle c+2 reuses the entry of cycle c−2, which has passed
                // every node (a frame's trip is shorter than 2 periods).
                if nd.kind == Kind::Sensor && c + 2 < cfg.cycles {
                    let v = merkur_model::ring::sensor_value(cfg, nd.address, c + 2);
                    self.r
                        .cfg(k, field::SENSOR, (((c + 2) as u64 & 3) << 16) | v as u64);
                }
            }
            if c >= 2 {
                let spans = (self.plan.win_of(c - 2), self.plan.tail_of(c - 2));
                compare_cycle(
                    &mut self.r,
                    cfg,
                    recs,
                    c - 2,
                    spans,
                    &mut self.mism,
                    &mut self.words,
                );
                self.compared = c - 1;
            }
            // The masters' alarm queues, as a host drains them: at a frame
            // start, and while a fault is due (its timing must not wait on
            // host transfers) only when half full.
            let due = self.plan.faults.iter().any(|f| f.1 <= self.sent + 1);
            let min = if due { alarms::AlarmQueues::HIGH } else { 1 };
            self.alq.drain(&mut self.r, min)?;
        }
        Ok(())
    }

    /// Host writes of cycle c: once frame c−1 has passed the node (a
    /// master: ended on its PI fibre; a clock base, the special master or
    /// a backup: sent on its PO).
    fn host_writes(&mut self) -> Result<(), String> {
        let mut i = 0;
        while i < self.plan.writes.len() {
            let (c, node, slot, data) = self.plan.writes[i];
            if c > self.sent {
                break;
            }
            let pace = if self.plan.clock_bases.contains(&node) {
                node
            } else {
                self.pi_fibre(node)
            };
            if self.frame_over(pace, c - 1) {
                self.r.wb(node, slot as u16, Some(data))?;
                self.plan.writes.remove(i);
            } else {
                i += 1;
            }
        }
        Ok(())
    }

    /// Requests of cycle c: armed for the end of frame c−1 on the fibre
    /// that paces the node (the ring top raises them then).
    fn requests(&mut self) {
        while let Some(&(c, node, bits)) = self.plan.reqs.first() {
            if c > self.sent {
                break;
            }
            self.r.cfg(
                node,
                field::REQUEST,
                0x40 | ((((c - 1) & 7) as u64) << 3) | bits,
            );
            self.plan.reqs.remove(0);
        }
    }

    /// [`frame_over`] of frame `k` on fibre `f`, with this run's state.
    fn frame_over(&mut self, f: usize, k: u32) -> bool {
        let period = self.period();
        frame_over(
            &mut self.r,
            f,
            k,
            &self.starts,
            self.sent,
            &mut self.pace,
            period,
            self.cfg.word_bits() as u64 * self.cfg.slots as u64,
        )
    }

    /// Whether the retransmission packet of cycle `k` (protocol §8) has
    /// passed fibre `f`, or none travelled it by the model: the next
    /// packet there is then cycle k + 1's frame. Timed from the fibre's
    /// frame offset (measured at its H1, 10 + 2W bit times after its J K)
    /// plus the packet's tail after H1 (`Snapshots::rtx_tail`: the RTX's
    /// start T and length, and 8 bit times).
    fn rtx_over(&self, f: usize, k: u32) -> bool {
        let Some((fibres, tail)) = &self.snaps.rtx_tail[k as usize] else {
            return true;
        };
        if !fibres.contains(&f) {
            return true;
        }
        let Some(off) = self.pace[f].off else {
            return true;
        };
        self.r.ticks >= self.starts[k as usize] + off + tail
    }

    /// Injects every fault whose moment has come.
    fn faults(&mut self) -> Result<(), String> {
        let mut i = 0;
        while i < self.plan.faults.len() {
            if self.fault_due(i) {
                let (idx, _, _, write) = self.plan.faults.remove(i);
                self.inject(idx, write)?;
            } else {
                i += 1;
            }
        }
        Ok(())
    }

    /// Whether pending fault `i` is due now. Breaks and repairs: "before
    /// slot s of cycle c" when the fibre's monitor has decoded slot s − 1
    /// of frame c; "before the delimiter" when frame c − 1 has ended on the
    /// fibre or, on a fibre without frames, when the special master has
    /// started frame c.
    fn fault_due(&mut self, i: usize) -> bool {
        let (idx, c) = (self.plan.faults[i].0, self.plan.faults[i].1);
        let sent = self.sent;
        match self.plan.faults[i].2 {
            When::Slot(ref fis, slot) => {
                let r = &mut self.r;
                let ats: Vec<(bool, u32, u64)> = fis
                    .iter()
                    .map(|&fi| {
                        let at = r.rd(fi, st::AT);
                        (at >> 31 == 1, (at >> 28 & 7) as u32, at & 0xfff)
                    })
                    .collect();
                match slot {
                    None => {
                        // In the idle gap: 10 bit times after frame c − 1
                        // ended, so that the next node has its last word
                        // out and confirmed by idles. (CYC has 3 bits:
                        // frame c − 1 of this epoch, which the special
                        // master has started.)
                        let ended = !ats.is_empty()
                            && sent >= c
                            && ats
                                .iter()
                                .all(|&(infr, cyc, _)| !infr && cyc == c.wrapping_sub(1) & 7);
                        if ended && self.gap_at[idx].is_none() {
                            self.gap_at[idx] = Some(self.r.ticks + 10 * TICKS_PER_BIT as u64);
                        }
                        // (A repaired fibre carries light again from the
                        // end of cycle c, protocol §12: it carried nothing,
                        // so when the special master starts frame c + 1.)
                        let dark = matches!(self.cfg.faults[idx].1, Fault::Repair { .. });
                        c == 0
                            || sent > c + 1
                            || (!dark && self.gap_at[idx].is_some_and(|t| self.r.ticks >= t))
                    }
                    Some(s) => {
                        let want = if s == 0 { 0xfff } else { s as u64 - 1 };
                        sent > c + 1
                            || (sent > c
                                && ats
                                    .iter()
                                    .any(|&(infr, cyc, last)| infr && cyc == c & 7 && last == want))
                    }
                }
            }
            When::FrameEnded(fi) => {
                c == 0
                    || sent > c + 1
                    || (sent >= c && self.frame_over(fi, c - 1) && self.rtx_over(fi, c - 1))
            }
            When::Secs(fi, k) => c == 0 || sent > c + 1 || self.r.rd(fi, st::NSEC) >= k,
            When::RtxNext(fi) => sent > c && self.frame_over(fi, c),
            When::Started => sent > c,
        }
    }

    /// Injects fault `idx`: its configuration write; a restart powers the
    /// node on (protocol §12): held in its power-on reset for 4 bit times
    /// (8 of its clocks), then alive; a master's host loads its
    /// configuration again and starts it with JOIN (a reload frame first).
    fn inject(&mut self, idx: usize, (sel, fd, val): (usize, u32, u64)) -> Result<(), String> {
        let r = &mut self.r;
        self.fault_ticks[idx] = Some(r.ticks);
        if r.dump {
            eprintln!(
                "tick {}: fault {idx} injected (frames sent {})",
                r.ticks, self.sent
            );
        }
        r.cfg(sel, fd, val);
        if fd == field::POR {
            for _ in 0..4 * TICKS_PER_BIT {
                r.tick();
            }
            r.cfg(sel, field::KILL, 0);
            r.cfg(sel, field::POR, 0);
            if self.cfg.nodes[sel].kind.is_master() {
                for slot in 0..self.cfg.slots {
                    let b = self.cfg.config_byte(sel, slot);
                    if b != 0 {
                        r.wb(sel, WB_CFG + slot as u16, Some(b as u16))?;
                    }
                }
                r.wb(sel, WB_STATUS, Some(ST_JOIN))?;
            }
        }
        Ok(())
    }

    /// Every 16 ticks: the per-cycle counter snapshots, and with faults
    /// the switchbox modes and failsafe of every node.
    fn poll(&mut self) {
        self.snaps
            .poll(&mut self.r, self.recs, &self.starts, self.sent);
        if self.cfg.faults.is_empty() {
            return;
        }
        let n = self.n();
        let r = &mut self.r;
        let mut modes_v = Packed::new(st::MODES, st::MODES_PER_READ, 3);
        for k in 0..n {
            let mf = modes_v.get(r, k);
            let m = mf & 3;
            if m != self.modes[k] {
                self.modes[k] = m;
                self.mode_ticks.push((k, r.ticks, m));
                if r.dump {
                    let name = ["N", "WU", "WD"].get(m as usize).unwrap_or(&"?");
                    eprintln!(
                        "tick {}: node {k} switchbox -> {name} (frames sent {})",
                        r.ticks, self.sent
                    );
                }
            }
            if self.fs_ticks[k].is_none() && mf >> 2 == 1 {
                self.fs_ticks[k] = Some(r.ticks);
            }
        }
    }

    /// Whether the run is over: the last frame has come back to the
    /// special master (frames lost to a fault do not count), or, in a ring
    /// that a fault left without a way back, two periods have passed since
    /// the last frame was started.
    fn stopped(&mut self) -> bool {
        if self.sent == self.cfg.cycles && self.stopped_at.is_none() {
            self.stopped_at = Some(self.r.ticks);
        }
        let Some(t) = self.stopped_at else {
            return false;
        };
        let last_framed = self.plan.last_framed;
        let pi = self.pi_fibre(self.recs[last_framed as usize].base);
        let back = self.r.rd(pi, st::FRAME);
        self.r.rd(pi, st::NEND) >= self.cfg.cycles as u64
            || (back >> 3 & 1 == 0 && back & 7 == (last_framed & 7) as u64)
            || self.r.ticks > t + 2 * self.period() * TICKS_PER_BIT as u64
    }

    /// End-of-run state of every node, read at once (the special master
    /// has stopped; the CS timeout will put every node in failsafe 2.5
    /// periods later): the `st` fields of [`FINAL_FIELDS`], in order.
    fn final_state(&mut self) -> Vec<Vec<u64>> {
        (0..self.n())
            .map(|k| FINAL_FIELDS.iter().map(|&f| self.r.rd(k, f)).collect())
            .collect()
    }

    /// SEC packets per fibre and cycle, outside the recovery windows.
    fn compare_secs(&mut self) {
        let n = self.n();
        let secs = (0..2 * n).map(|f| self.r.rd(f, st::NSEC)).collect();
        self.nsec_at.push(secs);
        for (c, rec) in self.recs.iter().enumerate() {
            if self.plan.win_of(c as u32).is_some() || c + 1 >= self.nsec_at.len() {
                continue;
            }
            let mut want = vec![0u64; 2 * n];
            for (f, carry) in rec.fibres.iter().enumerate() {
                want[f] += matches!(carry, Carry::Sec { ok: true }) as u64;
            }
            for &(f, ok) in &rec.sec_with_data {
                want[f] += ok as u64;
            }
            for (f, &w) in want.iter().enumerate() {
                let got = self.nsec_at[c + 1][f] - self.nsec_at[c][f];
                if got != w {
                    self.mism.push(Mismatch {
                        cycle: c as u32,
                        place: fibre_name(f, n),
                        what: "SEC packets".into(),
                        expected: w.to_string(),
                        got: got.to_string(),
                    });
                }
            }
        }
    }

    /// Node `k`'s end-of-run state (`v`, [`FINAL_FIELDS`]) against the
    /// model's last record; its summary row. `settled`: no run of bad words
    /// reaches the end (then the modes and the last HOP are compared).
    fn compare_node(&mut self, k: usize, v: &[u64], settled: bool) -> Result<NodeRow, String> {
        let (cfg, recs) = (self.cfg, self.recs);
        let last = recs.last().expect("at least one cycle");
        let last_cycle = cfg.cycles - 1;
        let nd = &cfg.nodes[k];
        let want = &last.nodes[k];
        // A dead node has no state to compare (its RTL runs on, unheard).
        let dead = !want.up;
        let no_windows = self.plan.wins.is_empty();
        let place = format!("node {k}");
        let mut found = vec![];
        let mut check = |what: &str, e: u64, g: u64| {
            if e != g && !dead {
                found.push(Mismatch {
                    cycle: last_cycle,
                    place: place.clone(),
                    what: what.into(),
                    expected: e.to_string(),
                    got: g.to_string(),
                });
            }
        };
        if settled {
            check("mode", want.mode.code() as u64, v[0]);
        }
        check("failsafe", want.failsafe as u64, v[1]);
        // With a recovery window, counters are compared per cycle outside
        // it (`Snapshots`); without, their totals too.
        if no_windows {
            check("perr", want.perr as u64, v[2]);
            check("ferr", want.ferr as u64, v[3]);
            if nd.kind.is_master() {
                check("aerr", want.aerr as u64, v[4]);
            }
        }
        if k == last.base {
            if no_windows {
                check("serr", want.serr as u64, v[5]);
            }
            // HOP of the last frame that came back (none came in the last
            // cycle: the register keeps an older one).
            if let (Some(h), true) = (want.hop, settled) {
                check("hop", h as u64, v[6]);
            }
        }
        if nd.kind == Kind::Actuator {
            check("output", want.output as u64, v[7]);
        }
        if nd.kind.is_master() {
            let irq = irqs_of(recs, k);
            check("IRQ1 alarms received", irq[0], v[8]);
            check("IRQ2 alarms received", irq[1], v[9]);
            check("FAILSAFE alarms received", irq[2], v[10]);
            check("failsafe-change interrupts", irq[3], v[11]);
        }
        self.mism.extend(found);
        let irqs = if nd.kind.is_master() {
            self.compare_db(k, dead)?;
            v[8] + v[9] + v[10] + v[12]
        } else {
            0
        };
        Ok(NodeRow {
            node: k,
            kind: nd.kind.name(),
            mode: ["N", "WU", "WD", "?"][(v[0] & 3) as usize],
            failsafe: v[1] == 1,
            perr: v[2],
            irqs,
            mismatches: 0,
        })
    }

    /// Master `k`'s data memory, read over Wishbone, against the model's.
    fn compare_db(&mut self, k: usize, dead: bool) -> Result<(), String> {
        let (cfg, recs) = (self.cfg, self.recs);
        let last = recs.last().expect("at least one cycle");
        let want = &last.nodes[k];
        // A memory frozen by failsafe in a window (protocol §13).
        let frozen = want.failsafe && !self.plan.wins.is_empty();
        for slot in 0..self.cfg.slots {
            let g = self.r.wb(k, slot as u16, None)? as u64;
            // A stranded slot (its writer off the path after a split), or
            // a frozen memory: any value the model showed in the slot
            // before.
            let off_path = frozen || !last.path.contains(&cfg.writer[slot]);
            let stranded = off_path
                && (recs
                    .iter()
                    .any(|x| x.produced.get(slot).is_some_and(|&p| p as u64 == g))
                    || recs.iter().any(|x| {
                        x.fibres.iter().any(|carry| {
                            matches!(carry, Carry::Data(fr)
                                if matches!(fr.words.get(slot), Some(Slot::Data(m)) if m.data as u64 == g))
                        })
                    }));
            if g != want.db[slot] as u64 && !dead && !stranded {
                self.mism.push(Mismatch {
                    cycle: cfg.cycles - 1,
                    place: format!("node {k}"),
                    what: format!("db[{slot}]"),
                    expected: format!("{:04x}", want.db[slot]),
                    got: format!("{g:04x}"),
                });
            }
            self.words += 1;
        }
        Ok(())
    }

    /// Confirmed delivery (protocol §11): once every window and its
    /// repeats are over, and nobody is in failsafe (`quiet_end`), each
    /// master's view of the ring's shape is the RTL's own (its live
    /// nodes' switchbox modes, from `state`).
    fn compare_shapes(&mut self, shapes: &[(usize, Shape)], state: &[Vec<u64>]) {
        let last = self.recs.last().expect("at least one cycle");
        let up = |j: usize| last.nodes[j].up;
        let real: Vec<(usize, Mode)> = (0..self.n())
            .filter(|&j| up(j))
            .filter_map(|j| match state[j][0] & 3 {
                1 => Some((j, Mode::Wu)),
                2 => Some((j, Mode::Wd)),
                _ => None,
            })
            .collect();
        let show = |v: &[(usize, Mode)]| {
            let s: Vec<String> = v
                .iter()
                .map(|(j, m)| format!("node {j} {}", m.name()))
                .collect();
            if s.is_empty() {
                "every node in N".to_string()
            } else {
                s.join(", ")
            }
        };
        for (k, shape) in shapes.iter().filter(|(k, _)| up(*k)) {
            let seen: Vec<(usize, Mode)> = shape.iter().copied().filter(|&(j, _)| up(j)).collect();
            if seen != real {
                self.mism.push(Mismatch {
                    cycle: self.cfg.cycles - 1,
                    place: format!("node {k}"),
                    what: "ring shape from the alarm queue".into(),
                    expected: show(&real),
                    got: show(&seen),
                });
            }
        }
    }

    /// Forwarding delay of every node but the clock bases whose PI and PO
    /// fibres both carried the last frame, bit times.
    fn forward_delays(&mut self) -> Vec<f64> {
        let n = self.n();
        let last_cyc = ((self.cfg.cycles - 1) & 7) as u64;
        let mut out = vec![];
        for k in (0..n).filter(|k| !self.plan.clock_bases.contains(k)) {
            let pi = self.pi_fibre(k);
            let r = &mut self.r;
            let both = [pi, k]
                .iter()
                .all(|&f| r.rd(f, st::FRAME) & 7 == last_cyc && r.rd(f, st::NEND) > 0);
            let d = r.rd(k, st::TH1).wrapping_sub(r.rd(pi, st::TH1)) & 0xffff_ffff;
            if both && d < 64 * TICKS_PER_BIT as u64 {
                out.push(d as f64 / TICKS_PER_BIT as f64);
            }
        }
        out
    }

    /// The mean period between consecutive frames of one clock base, bit
    /// times (0 without two such frames).
    fn period_bits(&self) -> f64 {
        let recs = self.recs;
        let gaps: Vec<u64> = (1..self.starts.len())
            .filter(|&c| {
                let (a, b) = (&recs[c - 1], &recs[c]);
                !a.path.is_empty() && !b.path.is_empty() && a.path[0] == b.path[0]
            })
            .map(|c| self.starts[c] - self.starts[c - 1])
            .collect();
        if gaps.is_empty() {
            0.0
        } else {
            gaps.iter().sum::<u64>() as f64 / gaps.len() as f64 / TICKS_PER_BIT as f64
        }
    }

    /// The end of the run: the cycles not yet compared, the SEC counts,
    /// the alarm queues drained, every node's state and memory, the
    /// counter snapshots, the ring's shape at every master; the report.
    pub(super) fn finish(mut self) -> Result<Report, String> {
        let (cfg, recs) = (self.cfg, self.recs);
        let last_cycle = cfg.cycles - 1;
        if let Some(p) = &self.opts.progress {
            (p.0)(cfg.cycles, cfg.cycles);
        }
        let last = recs.last().expect("at least one cycle");
        let state = self.final_state();
        for c in self.compared..cfg.cycles {
            let spans = (self.plan.win_of(c), self.plan.tail_of(c));
            compare_cycle(
                &mut self.r,
                cfg,
                recs,
                c,
                spans,
                &mut self.mism,
                &mut self.words,
            );
        }
        self.compare_secs();
        // Runs of bad words in a window that reaches the end of the run
        // (protocol §13): which further links they wrap is bit timing, so
        // the final switchbox modes and the last HOP are not compared.
        let settled = !recs.iter().flat_map(|r| &r.events).any(|e| {
            matches!(e.kind, EventKind::BadWords { .. })
                && e.cycle + ring::BAD_WORDS_WINDOW >= last_cycle
        });
        // The alarm queues, drained to the end.
        let ext_of = |c: u32| self.plan.ext_of(c);
        self.alq.finish(
            cfg,
            &mut self.r,
            recs,
            &ext_of,
            &|k| last.nodes[k].up,
            &mut self.mism,
        )?;
        let mut rows = vec![];
        for (k, v) in state.iter().enumerate() {
            rows.push(self.compare_node(k, v, settled)?);
        }
        let wins = &self.plan.wins;
        let in_window = |c: u32| wins.iter().any(|&(a, z)| a <= c && c <= z);
        self.snaps.compare(cfg, recs, in_window, &mut self.mism);
        let mut shapes = vec![];
        for &k in self.alq.masters() {
            let own = match self.r.wb(k, WB_STATUS, None)? >> 4 & 3 {
                1 => Mode::Wu,
                2 => Mode::Wd,
                _ => Mode::N,
            };
            shapes.push((k, self.alq.shape(cfg, k, own)));
        }
        let quiet_end = settled
            && self.plan.ext.iter().all(|&(_, z)| z < last_cycle)
            && state.iter().all(|v| v[1] == 0);
        if quiet_end {
            self.compare_shapes(&shapes, &state);
        }
        // Every mismatch placed at a node counts in its row (the per-cycle
        // counters' and the alarm queue's and the ring shape's too).
        for row in &mut rows {
            let place = format!("node {}", row.node);
            row.mismatches = self.mism.iter().filter(|m| m.place == place).count();
        }
        let fwd_delay_bits = self.forward_delays();
        let period_bits = self.period_bits();
        Ok(Report {
            cycles: cfg.cycles,
            words: self.words,
            mismatches: self.mism,
            ticks: self.r.ticks,
            wall: self.t1.elapsed(),
            build: self.build,
            period_bits,
            fwd_delay_bits,
            rows,
            recording: self.r.m.take_recording(),
            fault_ticks: self.fault_ticks,
            mode_ticks: self.mode_ticks,
            fs_ticks: self.fs_ticks,
            returned_whole: self.r.whole.clone(),
            shapes,
            starts: self.starts,
        })
    }
}

/// The status fields read per node at the end of the run, in the order
/// [`Drive::compare_node`] indexes them.
const FINAL_FIELDS: [u32; 13] = [
    st::MODE,
    st::FS,
    st::PERR,
    st::FERR,
    st::AERR,
    st::SERR,
    st::HOP,
    st::ACT,
    st::IRQ1,
    st::IRQ2,
    st::IRQFS,
    st::IRQFSC,
    st::IRQRC,
];

/// The interrupts node `k` received by the model: IRQ1, IRQ2 and FAILSAFE
/// alarms, and failsafe-change interrupts both ways (§12).
fn irqs_of(recs: &[CycleRecord], k: usize) -> [u64; 4] {
    let mut irq = [0u64; 4];
    for rec in recs {
        for ev in rec.events.iter().filter(|ev| ev.node == k) {
            match ev.kind {
                EventKind::Irq { reason: 1, .. } => irq[0] += 1,
                EventKind::Irq { reason: 2, .. } => irq[1] += 1,
                EventKind::Irq { reason: 3, .. } => irq[2] += 1,
                EventKind::Failsafe(_) | EventKind::FailsafeExit => irq[3] += 1,
                _ => {}
            }
        }
    }
    irq
}
