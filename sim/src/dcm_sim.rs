//! Token-bus scenarios through the RTL: every station's DCM + RMM
//! (`merkur_dcm_station`, rtl/src/tokenbus/dcm_station.rs) is its own Verilated instance,
//! driven by the model's token-bus MACs and channels
//! ([`merkur_model::tokenbus::run_with`]) in closed loop, and every output
//! of every station in every octet is compared with the reference RMM's
//! run of the same scenario (the golden trace's source).

use crate::verilator::Model;
use merkur_model::rmm::{RmmConfig, RmmIn, RmmOut};
use merkur_model::tbconfig::TbConfig;
use merkur_model::tokenbus::{self, StationHw, TbRun};
use merkur_rtl::tokenbus::dcm_station::dcm_verilog;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Port indices of `merkur_dcm_station`.
struct Ports {
    clock: usize,
    rx_a: usize,
    rx_b: usize,
    tx: usize,
    ev: usize,
    sf_sent: usize,
    rx_sf: usize,
    rx_sa: usize,
    rx_sfw: usize,
    cmd_rx: usize,
    cmd_ch: usize,
    cmd_sent: usize,
    init: usize,
    auto: usize,
    host_ok: usize,
    nm_addr: usize,
    o_tx_a: usize,
    o_tx_b: usize,
    o_rx: usize,
    o_act: usize,
    o_state: usize,
    o_cause: usize,
    o_irq: usize,
    o_sf_pend: usize,
    o_sf_word: usize,
    o_cmd_req: usize,
    o_cmd_ch: usize,
    o_stat_a: usize,
    o_stat_b: usize,
    o_stale: usize,
    o_chk_ok: usize,
    o_chk_sw: usize,
    o_ev_seen: usize,
    o_nm_word: usize,
    o_nm_valid: usize,
}

impl Ports {
    fn of(m: &Model) -> Ports {
        Ports {
            clock: m.port("clock"),
            rx_a: m.port("i_rx_a"),
            rx_b: m.port("i_rx_b"),
            tx: m.port("i_tx"),
            ev: m.port("i_ev"),
            sf_sent: m.port("i_sf_sent"),
            rx_sf: m.port("i_rx_sf"),
            rx_sa: m.port("i_rx_sa"),
            rx_sfw: m.port("i_rx_sfw"),
            cmd_rx: m.port("i_cmd_rx"),
            cmd_ch: m.port("i_cmd_ch"),
            cmd_sent: m.port("i_cmd_sent"),
            init: m.port("i_init"),
            auto: m.port("i_auto"),
            host_ok: m.port("i_host_ok"),
            nm_addr: m.port("i_nm_addr"),
            o_tx_a: m.port("o_tx_a"),
            o_tx_b: m.port("o_tx_b"),
            o_rx: m.port("o_rx"),
            o_act: m.port("o_act"),
            o_state: m.port("o_state"),
            o_cause: m.port("o_cause"),
            o_irq: m.port("o_irq"),
            o_sf_pend: m.port("o_sf_pend"),
            o_sf_word: m.port("o_sf_word"),
            o_cmd_req: m.port("o_cmd_req"),
            o_cmd_ch: m.port("o_cmd_ch"),
            o_stat_a: m.port("o_stat_a"),
            o_stat_b: m.port("o_stat_b"),
            o_stale: m.port("o_stale"),
            o_chk_ok: m.port("o_chk_ok"),
            o_chk_sw: m.port("o_chk_sw"),
            o_ev_seen: m.port("o_ev_seen"),
            o_nm_word: m.port("o_nm_word"),
            o_nm_valid: m.port("o_nm_valid"),
        }
    }
}

/// One station's Verilated `merkur_dcm_station`.
struct VStation {
    m: Model,
    p: Ports,
}

impl VStation {
    fn new(verilog: &str, c: RmmConfig, wave: Option<&Path>) -> Result<VStation, String> {
        let mut m = Model::build_top_traced(verilog, "merkur_dcm_station", wave)?;
        let p = Ports::of(&m);
        for (name, v) in [
            ("i_addr", c.addr as u64),
            ("i_stations", c.stations as u64),
            ("i_sf_period", c.sf_period as u64),
            ("i_chk_period", c.check_period as u64),
            ("i_good_limit", c.good_limit as u64),
        ] {
            let i = m.port(name);
            m.set(i, v);
        }
        m.set(p.host_ok, 1);
        m.set(p.clock, 0);
        m.eval();
        Ok(VStation { m, p })
    }
}

impl StationHw for VStation {
    fn out(&mut self) -> RmmOut {
        let (m, p) = (&self.m, &self.p);
        RmmOut {
            rx: m.get(p.o_rx) as u16,
            act: m.get(p.o_act) == 1,
            state: m.get(p.o_state) as u8,
            cause: m.get(p.o_cause) as u8,
            irq: m.get(p.o_irq) == 1,
            sf_pend: m.get(p.o_sf_pend) == 1,
            sf_word: m.get(p.o_sf_word) as u16,
            cmd_req: m.get(p.o_cmd_req) == 1,
            cmd_ch: m.get(p.o_cmd_ch) == 1,
            stat_a: m.get(p.o_stat_a) as u16,
            stat_b: m.get(p.o_stat_b) as u16,
            stale: m.get(p.o_stale) as u32,
            chk_ok: m.get(p.o_chk_ok) == 1,
            chk_sw: m.get(p.o_chk_sw) == 1,
            ev_seen: m.get(p.o_ev_seen) as u8,
            nm_word: m.get(p.o_nm_word) as u16,
            nm_valid: m.get(p.o_nm_valid) == 1,
        }
    }

    fn tx_out(&mut self, tx: u16) -> [u16; 2] {
        self.m.set(self.p.tx, tx as u64);
        self.m.eval();
        [
            self.m.get(self.p.o_tx_a) as u16,
            self.m.get(self.p.o_tx_b) as u16,
        ]
    }

    fn clock(&mut self, i: &RmmIn) {
        let (m, p) = (&mut self.m, &self.p);
        for (port, v) in [
            (p.rx_a, i.rx_a as u64),
            (p.rx_b, i.rx_b as u64),
            (p.tx, i.tx as u64),
            (p.ev, i.ev as u64),
            (p.sf_sent, i.sf_sent as u64),
            (p.rx_sf, i.rx_sf as u64),
            (p.rx_sa, i.rx_sa as u64),
            (p.rx_sfw, i.rx_sfw as u64),
            (p.cmd_rx, i.cmd_rx as u64),
            (p.cmd_ch, i.cmd_ch as u64),
            (p.cmd_sent, i.cmd_sent as u64),
            (p.init, i.init as u64),
            (p.auto, i.auto as u64),
            (p.host_ok, i.host_ok as u64),
            (p.nm_addr, i.nm_addr as u64),
        ] {
            m.set(port, v);
        }
        m.tick(p.clock);
    }
}

/// A token-bus scenario of `tb-data/`.
#[derive(Debug, Clone)]
pub struct Scenario {
    /// `tb-data/<file>.toml`.
    pub name: String,
    /// The file's text.
    pub text: String,
    /// Validated.
    pub cfg: TbConfig,
}

impl Scenario {
    /// The committed golden trace beside it.
    pub fn golden(&self) -> Result<String, String> {
        let p = crate::repo_root().join(self.name.replace(".toml", ".trace"));
        std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))
    }
}

/// Every token-bus scenario (a `[token_bus]` table) in `tb-data/`, by name.
pub fn scenarios() -> Result<Vec<Scenario>, String> {
    let dir = crate::repo_root().join("tb-data");
    let mut v = vec![];
    for e in std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let p = e.map_err(|e| e.to_string())?.path();
        if p.extension().and_then(|x| x.to_str()) != Some("toml") {
            continue;
        }
        let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
        if !merkur_model::tbconfig::is_token_bus(&text) {
            continue;
        }
        let name = format!(
            "tb-data/{}",
            p.file_name().unwrap_or_default().to_string_lossy()
        );
        let cfg = merkur_model::tbconfig::load(&name, &text).map_err(|e| e.to_string())?;
        v.push(Scenario { name, text, cfg });
    }
    v.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(v)
}

/// Options of a run.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Write one FST waveform per station power-on: `<stem>.s<k>.fst`
    /// (a restart adds `.r<n>`).
    pub wave: Option<PathBuf>,
}

/// What a run found.
#[derive(Debug)]
pub struct Report {
    /// The reference run (golden).
    pub model: TbRun,
    /// The RTL run.
    pub rtl: TbRun,
    /// Every (tick, station) output that differs, as text (first 1000).
    pub mismatches: Vec<String>,
    /// Outputs compared (stations × octets powered).
    pub compared: u64,
    /// Waveform files written.
    pub waves: Vec<PathBuf>,
    /// Wall time of the RTL run.
    pub wall: Duration,
    /// Time to build (or find) the Verilated library.
    pub build: Duration,
}

/// The fields of two output records that differ.
pub fn diff(a: &RmmOut, b: &RmmOut) -> Vec<String> {
    let mut d = vec![];
    macro_rules! f {
        ($($x:ident),*) => {$(
            if a.$x != b.$x {
                d.push(format!("{} model {:x?} rtl {:x?}", stringify!($x), a.$x, b.$x));
            }
        )*};
    }
    f!(
        rx, act, state, cause, irq, sf_pend, sf_word, cmd_req, cmd_ch, stat_a, stat_b, stale,
        chk_ok, chk_sw, ev_seen, nm_word, nm_valid
    );
    d
}

/// The station's Verilog, emitted once per process.
fn station_verilog() -> &'static str {
    static V: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    V.get_or_init(dcm_verilog)
}

/// Builds (or finds in the cache) the Verilator model of the station that
/// [`run`] uses (with tracing when `wave`), so that a caller can show the
/// build as a step of its own; [`run`] then finds it in the process.
pub fn build_model(wave: bool) -> Result<(), String> {
    crate::verilator::build_library_top(station_verilog(), "merkur_dcm_station", wave).map(|_| ())
}

/// Runs `cfg` through the RTL and compares it with the reference model.
pub fn run(cfg: &TbConfig, opts: &Options) -> Result<Report, String> {
    let verilog = station_verilog();
    if let Some(w) = &opts.wave {
        if let Some(dir) = w.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| {
                format!(
                    "--wave {}: cannot create {}: {e}",
                    w.display(),
                    dir.display()
                )
            })?;
        }
    }
    let t0 = Instant::now();
    // Build (or find) the library once before the run.
    crate::verilator::build_library_top(verilog, "merkur_dcm_station", opts.wave.is_some())?;
    let build = t0.elapsed();
    let model = tokenbus::run(cfg);
    let mut waves = vec![];
    let mut powered = vec![0u32; cfg.stations];
    let t1 = Instant::now();
    let rtl = tokenbus::run_with(
        cfg,
        &mut |c: RmmConfig| {
            let k = c.addr as usize;
            let wave = opts.wave.as_ref().map(|w| {
                let stem = w
                    .file_stem()
                    .map(|s| s.to_string_lossy().to_string())
                    .unwrap_or_default();
                let r = powered[k];
                let name = if r == 0 {
                    format!("{stem}.s{k}.fst")
                } else {
                    format!("{stem}.s{k}.r{r}.fst")
                };
                w.with_file_name(name)
            });
            powered[k] += 1;
            if let Some(w) = &wave {
                waves.push(w.clone());
            }
            Ok(Box::new(VStation::new(verilog, c, wave.as_deref())?) as Box<dyn StationHw>)
        },
        true,
    )?;
    let wall = t1.elapsed();
    let mut mismatches = vec![];
    let mut compared = 0;
    for k in 0..cfg.stations {
        for (t, (a, b)) in model.outs[k].iter().zip(&rtl.outs[k]).enumerate() {
            match (a, b) {
                (Some(a), Some(b)) => {
                    compared += 1;
                    for d in diff(a, b) {
                        if mismatches.len() < 1000 {
                            mismatches.push(format!("octet {t} station {k}: {d}"));
                        }
                    }
                }
                (None, None) => {}
                _ => mismatches.push(format!("octet {t} station {k}: powered differently")),
            }
        }
    }
    // Order by time so the first listed is the first that went wrong.
    mismatches.sort_by_key(|m| {
        m.split_whitespace()
            .nth(1)
            .and_then(|t| t.parse::<u64>().ok())
            .unwrap_or(u64::MAX)
    });
    Ok(Report {
        model,
        rtl,
        mismatches,
        compared,
        waves,
        wall,
        build,
    })
}
