//! Timing diagrams drawn from real simulation runs (`docs/timing/*.svg`).
//!
//! Each [`Diagram`] names a scenario of `tb-data/`, the signals to show
//! (by their names in the run's FST waveform: the RTL's block instances and
//! ports) and where to look: an [`Anchor`] (the n-th time a signal takes a
//! value) and a window around it. [`render_all`] runs each scenario once through the
//! RTL with a waveform, reads the waveform back (the `fst-reader` crate) and
//! draws the SVG. Nothing is drawn by hand: a diagram shows what the RTL
//! did. `cargo run -p merkur-sim --example gen` rewrites them and
//! `sim/tests/gen.rs` fails when a committed diagram drifts.
//!
//! Drawing: a one-bit signal is a line between its two levels; a vector is
//! a row of boxes with its value (hex, decimal or the model's name for it)
//! where the box is wide enough to read. Where a signal changes faster than
//! the drawing can show (more than one change per pixel, e.g. a fibre's
//! line bits over several cycles), the stretch is a grey band: the signal
//! is busy there.

use crate::dcm_sim;
use crate::ring_sim;
use fst_reader::{FstFilter, FstHierarchyEntry, FstReader, FstSignalValue};
use merkur_model::config;
use merkur_model::line::{self, Symbol};
use merkur_model::ring::{self, Mode};
use merkur_model::rmm;
use merkur_model::tbconfig;
use merkur_rtl::harness::ring_top::TICKS_PER_BIT;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// How a row's value is written.
#[derive(Clone, Copy)]
pub enum Fmt {
    /// One bit: drawn as a level.
    Bit,
    /// A vector in hex.
    Hex,
    /// A vector in decimal.
    Dec,
    /// A vector named by the model (a mode, a state, a cause).
    Named(fn(u64) -> String),
}

/// One row: a label and the FST name of its signal.
pub struct Row {
    /// What the row shows.
    pub label: String,
    /// Full dotted name in the waveform (`top.top.mon_0.o_slot`).
    pub signal: String,
    /// How its value is written.
    pub fmt: Fmt,
    /// Show the value only as sampled when this one-bit signal rises (a
    /// word where its valid strobe says so), held until the next rise.
    pub strobe: Option<String>,
}

/// Where a diagram looks: the `nth` time (from 1) `signal` changes to
/// `value`; the window's time 0.
pub struct Anchor {
    /// Full dotted name in the waveform.
    pub signal: String,
    /// The value it changes to.
    pub value: u64,
    /// Which time (1 = the first).
    pub nth: usize,
}

/// The run a diagram is drawn from.
pub enum Source {
    /// A MERKUR ring scenario through the RTL ring top (one waveform; time
    /// in bit times, counted by the ring top's tick counter).
    Ring(&'static str),
    /// A token-bus scenario through the RTL DCM stations: the waveform of
    /// one station (time in octet times, its clock's rising edges).
    Dcm {
        /// Scenario file in the repository.
        scenario: &'static str,
        /// Station whose waveform is drawn.
        station: usize,
    },
}

/// One timing diagram.
pub struct Diagram {
    /// File name in docs/timing/.
    pub file: &'static str,
    /// Title drawn at its top.
    pub title: &'static str,
    /// The run.
    pub source: Source,
    /// Rows, top to bottom.
    pub rows: Vec<Row>,
    /// Time 0.
    pub anchor: Anchor,
    /// Window before time 0, in the source's unit (bit or octet times).
    pub before: u64,
    /// Window after time 0, in the source's unit.
    pub after: u64,
}

/// A signal of the simulated design by its name in the waveform: the
/// model's `top` scope, the design's top module (`top`) in it.
fn top(name: &str) -> String {
    format!("top.top.{name}")
}

/// A node mode by its code (protocol §11; the model's names).
fn mode_name(v: u64) -> String {
    [Mode::N, Mode::Wu, Mode::Wd]
        .into_iter()
        .find(|m| u64::from(m.code()) == v)
        .map_or("?".into(), |m| m.name().into())
}

/// A 5-bit code group as the model decodes it (protocol §2): a data
/// nibble in hex, or J, K, I (idle), S (set), T (mark).
fn group_name(v: u64) -> String {
    match line::decode_group(v as u8) {
        Symbol::Data(n) => format!("{n:x}"),
        Symbol::J => "J".into(),
        Symbol::K => "K".into(),
        Symbol::I => "I".into(),
        Symbol::S => "S".into(),
        Symbol::Invalid(g) if g == line::CODE_T => "T".into(),
        Symbol::Invalid(g) => format!("?{g:05b}"),
    }
}

/// A received word's kind (rtl/src/line/word_rx.rs `o_kind`; protocol
/// §3: the two header words, then the slots).
fn kind_name(v: u64) -> String {
    match v {
        0 => "H0".into(),
        1 => "H1".into(),
        2 => "slot".into(),
        _ => "?".into(),
    }
}

/// A token-bus PHY/MAC symbol (protocol Part II: bits 10:8 the kind):
/// `sil`, `SD`, a data octet in hex, `ED`, `noise`.
fn symbol_name(v: u64) -> String {
    let v = v as u16;
    match rmm::sym::kind(v) {
        rmm::sym::SIL => "sil".into(),
        rmm::sym::SD => "SD".into(),
        rmm::sym::DATA => format!("{:02x}", v & 0xff),
        rmm::sym::ED => "ED".into(),
        rmm::sym::ERR => "noise".into(),
        _ => format!("?{v:x}"),
    }
}

fn state_name(v: u64) -> String {
    rmm::state::name(v as u8).into()
}

fn cause_name(v: u64) -> String {
    rmm::cause::name(v as u8).into()
}

fn channel_name(v: u64) -> String {
    if v == 0 { "A" } else { "B" }.into()
}

/// The diagrams in docs/timing/.
pub fn diagrams() -> Vec<Diagram> {
    let row = |label: &str, name: &str, fmt| Row {
        label: label.to_string(),
        signal: top(name),
        fmt,
        strobe: None,
    };
    let word = |label: &str, name: &str, fmt, strobe: &str| Row {
        label: label.to_string(),
        signal: top(name),
        fmt,
        strobe: Some(top(strobe)),
    };
    let mut wrap_rows = vec![
        row("P3 line (node 3 → 4)", "line_3", Fmt::Bit),
        row("P3 in packet", "mon_3.o_inpkt", Fmt::Bit),
        row("S3 in packet (4 → 3)", "mon_11.o_inpkt", Fmt::Bit),
        row("S2 in packet (3 → 2)", "mon_10.o_inpkt", Fmt::Bit),
    ];
    for k in 0..8 {
        wrap_rows.push(row(
            &format!("node {k} mode"),
            &format!("mode_{k}"),
            Fmt::Named(mode_name),
        ));
    }
    vec![
        Diagram {
            file: "frame.svg",
            title: "A frame on fibre P0 (special master → node 1), ring3",
            source: Source::Ring("tb-data/ring3.toml"),
            rows: vec![
                row("P0 line", "line_0", Fmt::Bit),
                row("frame start", "mon_0.framer__o_start", Fmt::Bit),
                row("in packet", "mon_0.o_inpkt", Fmt::Bit),
                word(
                    "5B group",
                    "mon_0.framer__o_group",
                    Fmt::Named(group_name),
                    "mon_0.framer__o_gvalid",
                ),
                row("word valid", "mon_0.o_wvalid", Fmt::Bit),
                word(
                    "word kind",
                    "mon_0.o_kind",
                    Fmt::Named(kind_name),
                    "mon_0.o_wvalid",
                ),
                word("slot", "mon_0.o_slot", Fmt::Dec, "mon_0.o_wvalid"),
                word("data", "mon_0.o_data", Fmt::Hex, "mon_0.o_wvalid"),
            ],
            anchor: Anchor {
                signal: top("mon_0.framer__o_start"),
                value: 1,
                nth: 3,
            },
            before: 8,
            after: 160,
        },
        Diagram {
            file: "slot.svg",
            title: "One slot through a node: node 1 writes its sensor value into slot 1, ring3",
            source: Source::Ring("tb-data/ring3.toml"),
            rows: vec![
                row("P0 line (into node 1)", "line_0", Fmt::Bit),
                word("P0 word: slot", "mon_0.o_slot", Fmt::Dec, "mon_0.o_wvalid"),
                word("P0 word: data", "mon_0.o_data", Fmt::Hex, "mon_0.o_wvalid"),
                row("node 1 input slot", "n1.rx_in__o_slot", Fmt::Dec),
                row("node 1 output slot", "n1.fwd__o_slot", Fmt::Dec),
                row("P1 line (out of node 1)", "line_1", Fmt::Bit),
                word("P1 word: slot", "mon_1.o_slot", Fmt::Dec, "mon_1.o_wvalid"),
                word("P1 word: data", "mon_1.o_data", Fmt::Hex, "mon_1.o_wvalid"),
            ],
            anchor: Anchor {
                signal: top("mon_0.o_slot"),
                value: 1,
                nth: 3,
            },
            before: 24,
            after: 56,
        },
        Diagram {
            file: "wrap.svg",
            title: "A wrap after a line break: P3 breaks, nodes 3 and 4 wrap, demo_8_break",
            source: Source::Ring("tb-data/demo_8_break.toml"),
            rows: wrap_rows,
            anchor: Anchor {
                signal: top("fib_3.brk"),
                value: 1,
                nth: 1,
            },
            before: 300,
            after: 1500,
        },
        Diagram {
            file: "dcm_switch.svg",
            title: "A DCM switchover: station 3's drop cable to channel A is cut, dcm8_drop_active",
            source: Source::Dcm {
                scenario: "tb-data/dcm8_drop_active.toml",
                station: 3,
            },
            rows: vec![
                row("PHY A symbol", "i_rx_a", Fmt::Named(symbol_name)),
                row("PHY B symbol", "i_rx_b", Fmt::Named(symbol_name)),
                row("fault A", "dcm__o_fault_a", Fmt::Bit),
                row("fault B", "dcm__o_fault_b", Fmt::Bit),
                row("FCM state", "o_state", Fmt::Named(state_name)),
                row("cause", "o_cause", Fmt::Named(cause_name)),
                row("interrupt", "o_irq", Fmt::Bit),
                row("active channel", "o_act", Fmt::Named(channel_name)),
                row("MAC symbol", "o_rx", Fmt::Named(symbol_name)),
            ],
            anchor: Anchor {
                signal: top("o_act"),
                value: 1,
                nth: 1,
            },
            before: 6,
            after: 14,
        },
    ]
}

/// Value changes of the signals asked for: (FST time, value) per name.
type Changes = HashMap<String, Vec<(u64, u64)>>;

/// Reads the changes of `names` from the FST at `path`.
fn read_changes(path: &Path, names: &[&str]) -> Result<Changes, String> {
    let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut r = FstReader::open(std::io::BufReader::new(file))
        .map_err(|e| format!("{}: not a readable FST: {e:?}", path.display()))?;
    let mut scope: Vec<String> = vec![];
    let mut handle_of: HashMap<String, usize> = HashMap::new();
    r.read_hierarchy(|e| match e {
        FstHierarchyEntry::Scope { name, .. } => scope.push(name),
        FstHierarchyEntry::UpScope => {
            scope.pop();
        }
        FstHierarchyEntry::Var { name, handle, .. } => {
            // Verilator names a vector `name [hi:lo]`.
            let base = name.split(' ').next().unwrap_or(&name);
            handle_of.insert(format!("{}.{base}", scope.join(".")), handle.get_index());
        }
        _ => {}
    })
    .map_err(|e| format!("{}: hierarchy: {e:?}", path.display()))?;
    let mut by_handle: HashMap<usize, Vec<(u64, u64)>> = HashMap::new();
    for n in names {
        let h = *handle_of
            .get(*n)
            .ok_or_else(|| format!("{}: no signal {n} in the waveform", path.display()))?;
        by_handle.insert(h, vec![]);
    }
    r.read_signals(&FstFilter::all(), |t, h, v| {
        if let (Some(list), FstSignalValue::String(b)) = (by_handle.get_mut(&h.get_index()), v) {
            // Two-state Verilator values: 0 and 1 only.
            let v = b.iter().fold(0u64, |a, c| (a << 1) | u64::from(*c == b'1'));
            if list.last().map(|l| l.1) != Some(v) {
                list.push((t, v));
            }
        }
        Ok::<(), ()>(())
    })
    .map_err(|e| format!("{}: values: {e:?}", path.display()))?;
    Ok(names
        .iter()
        .map(|n| (n.to_string(), by_handle[&handle_of[*n]].clone()))
        .collect())
}

impl Source {
    /// The scenario file.
    fn scenario(&self) -> &'static str {
        match self {
            Source::Ring(f) => f,
            Source::Dcm { scenario, .. } => scenario,
        }
    }

    /// The waveform this source's diagrams read, in the folder its run
    /// wrote ([`simulate`]).
    fn wave(&self, dir: &Path) -> PathBuf {
        match self {
            Source::Ring(_) => dir.join("ring.fst"),
            // dcm_sim writes `<stem>.s<k>.fst` per station.
            Source::Dcm { station, .. } => dir.join(format!("dcm.s{station}.fst")),
        }
    }
}

/// Runs the source's scenario through the RTL (checked against the model)
/// with its waveforms written into `dir`.
fn simulate(src: &Source, dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let f = src.scenario();
    let text =
        std::fs::read_to_string(crate::repo_root().join(f)).map_err(|e| format!("{f}: {e}"))?;
    let agree = match src {
        Source::Ring(_) => {
            let cfg = config::load(f, &text).map_err(|e| e.to_string())?;
            let opts = ring_sim::Options {
                wave: Some(src.wave(dir)),
                ..Default::default()
            };
            ring_sim::run(&cfg, &ring::run(&cfg), &opts)?
                .mismatches
                .is_empty()
        }
        Source::Dcm { .. } => {
            let cfg = tbconfig::load(f, &text).map_err(|e| e.to_string())?;
            let opts = dcm_sim::Options {
                wave: Some(dir.join("dcm.fst")),
            };
            dcm_sim::run(&cfg, &opts)?.mismatches.is_empty()
        }
    };
    if !agree {
        return Err(format!("{f}: the RTL disagrees with the model"));
    }
    Ok(())
}

/// The source's time base: the signal that counts its ticks (the ring
/// top's tick counter, [`TICKS_PER_BIT`] ticks to a bit time; a station's
/// clock, whose rising edges [`Clock`] counts, one per octet time), the
/// unit's name, and ticks per unit.
fn time_base(src: &Source) -> (&'static str, &'static str, u64) {
    match src {
        Source::Ring(_) => ("top.top.tick", "bit times", u64::from(TICKS_PER_BIT)),
        Source::Dcm { .. } => ("top.top.clock", "octet times", 1),
    }
}

/// FST times to the source's ticks (the time base read from the waveform).
struct Clock {
    /// (FST time, ticks from the start) at every change.
    marks: Vec<(u64, u64)>,
}

impl Clock {
    fn new(src: &Source, changes: &[(u64, u64)]) -> Clock {
        let marks = match src {
            Source::Ring(_) => changes.to_vec(),
            // Count rising edges.
            Source::Dcm { .. } => changes
                .iter()
                .filter(|c| c.1 == 1)
                .enumerate()
                .map(|(i, c)| (c.0, i as u64 + 1))
                .collect(),
        };
        Clock { marks }
    }

    fn at(&self, t: u64) -> u64 {
        match self.marks.partition_point(|m| m.0 <= t) {
            0 => 0,
            i => self.marks[i - 1].1,
        }
    }
}

/// Draws every diagram of `ds`, running each scenario once in `work` (a
/// scratch folder; two diagrams of one scenario read the same run's
/// waveforms): (file name, SVG) in the order of `ds`.
pub fn render_all(ds: &[Diagram], work: &Path) -> Result<Vec<(&'static str, String)>, String> {
    let mut runs: HashMap<&str, PathBuf> = HashMap::new();
    let mut out = vec![];
    for d in ds {
        let key = d.source.scenario();
        if !runs.contains_key(key) {
            let dir = work.join(format!("run{}", runs.len()));
            simulate(&d.source, &dir).map_err(|e| format!("{}: {e}", d.file))?;
            runs.insert(key, dir);
        }
        let svg = draw(d, &d.source.wave(&runs[key])).map_err(|e| format!("{}: {e}", d.file))?;
        out.push((d.file, svg));
    }
    Ok(out)
}

/// The diagram `d` drawn from the waveform `fst`.
fn draw(d: &Diagram, fst: &Path) -> Result<String, String> {
    let (base, unit, per_unit) = time_base(&d.source);
    let mut names: Vec<&str> = d.rows.iter().map(|r| r.signal.as_str()).collect();
    names.extend(d.rows.iter().filter_map(|r| r.strobe.as_deref()));
    names.push(&d.anchor.signal);
    names.push(base);
    let ch = read_changes(fst, &names)?;
    let clock = Clock::new(&d.source, &ch[base]);
    let zero = ch[&d.anchor.signal]
        .iter()
        .filter(|c| c.1 == d.anchor.value)
        .nth(d.anchor.nth - 1)
        .map(|c| clock.at(c.0))
        .ok_or_else(|| {
            format!(
                "the anchor {} does not become {} {} times",
                d.anchor.signal, d.anchor.value, d.anchor.nth
            )
        })?;
    let start = zero.saturating_sub(d.before * per_unit);
    let end = zero + d.after * per_unit;
    let last = clock.at(u64::MAX);
    if end > last {
        return Err(format!(
            "the window ends at {} {unit} after the anchor, the run {} after it",
            d.after,
            (last - zero) / per_unit
        ));
    }
    let rows: Vec<(&Row, Vec<(u64, u64)>)> = d
        .rows
        .iter()
        .map(|r| {
            let v = match &r.strobe {
                None => ch[&r.signal].clone(),
                Some(s) => sampled(&ch[&r.signal], &ch[s]),
            };
            (r, v.iter().map(|c| (clock.at(c.0), c.1)).collect())
        })
        .collect();
    Ok(svg(d, &rows, start, zero, end, unit, per_unit))
}

/// `value` sampled at each rise of `strobe` (FST times).
fn sampled(value: &[(u64, u64)], strobe: &[(u64, u64)]) -> Vec<(u64, u64)> {
    strobe
        .iter()
        .filter(|s| s.1 == 1)
        .map(|s| {
            let i = value.partition_point(|v| v.0 <= s.0);
            (s.0, if i > 0 { value[i - 1].1 } else { 0 })
        })
        .collect()
}

const WIDTH: f64 = 960.0;
const LABEL: f64 = 190.0;
const RIGHT: f64 = 20.0;
const ROW: f64 = 30.0;
const HIGH: f64 = 18.0;
const TOP: f64 = 40.0;
/// Changes closer than this (pixels) make a busy band.
const BUSY: f64 = 2.0;

/// The row's segments in the window: (from, to, value) in ticks, the value
/// at the window's start included.
fn segments(ch: &[(u64, u64)], start: u64, end: u64) -> Vec<(u64, u64, u64)> {
    let first = ch.partition_point(|c| c.0 <= start);
    let mut v = if first > 0 { ch[first - 1].1 } else { 0 };
    let mut from = start;
    let mut out = vec![];
    for &(t, x) in ch[first..].iter().take_while(|c| c.0 < end) {
        if t > from {
            out.push((from, t, v));
        }
        from = t;
        v = x;
    }
    out.push((from, end, v));
    out
}

/// The SVG of the diagram: `rows` with their changes in ticks.
fn svg(
    d: &Diagram,
    rows: &[(&Row, Vec<(u64, u64)>)],
    start: u64,
    zero: u64,
    end: u64,
    unit: &str,
    per_unit: u64,
) -> String {
    let x0 = LABEL;
    let x1 = WIDTH - RIGHT;
    let xs = |t: u64| x0 + (t - start) as f64 * (x1 - x0) / (end - start) as f64;
    let rel = |t: u64| (t as f64 - zero as f64) / per_unit as f64;
    let mut notes = vec![];
    let mut body = String::new();
    for (i, (row, ch)) in rows.iter().enumerate() {
        let y = TOP + ROW * i as f64;
        let p = Place {
            label: &row.label,
            hi: y + 4.0,
            lo: y + 4.0 + HIGH,
            xs: &xs,
            rel: &rel,
        };
        let _ = writeln!(
            body,
            "<text x=\"10\" y=\"{:.1}\">{}</text>",
            p.lo - 4.0,
            esc(&row.label)
        );
        draw_row(
            &mut body,
            row.fmt,
            &segments(ch, start, end),
            &p,
            &mut notes,
        );
    }
    let axis_y = TOP + ROW * rows.len() as f64 + 10.0;
    let height = axis_y + 40.0 + 16.0 * notes.len() as f64;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{height}\" \
         viewBox=\"0 0 {WIDTH} {height}\" font-family=\"monospace\" font-size=\"11\">"
    );
    let _ = writeln!(
        s,
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
         <text x=\"10\" y=\"20\" font-size=\"13\" font-weight=\"bold\">{}</text>",
        esc(d.title)
    );
    s.push_str(&body);
    axis(&mut s, start, zero, end, per_unit, unit, &xs, axis_y);
    for (i, n) in notes.iter().enumerate() {
        let _ = writeln!(
            s,
            "<text x=\"{x0:.1}\" y=\"{:.1}\">{}</text>",
            axis_y + 48.0 + 16.0 * i as f64,
            esc(n)
        );
    }
    s.push_str("</svg>\n");
    s
}

/// Where a row is drawn: its label, its top and bottom, ticks to x and to
/// time relative to the anchor (in the unit).
struct Place<'a> {
    label: &'a str,
    hi: f64,
    lo: f64,
    xs: &'a dyn Fn(u64) -> f64,
    rel: &'a dyn Fn(u64) -> f64,
}

/// One row's drawing; a named value whose box is too narrow for its name
/// goes to `notes` (drawn under the axis).
fn draw_row(
    s: &mut String,
    fmt: Fmt,
    segs: &[(u64, u64, u64)],
    p: &Place,
    notes: &mut Vec<String>,
) {
    let (xs, hi, lo) = (p.xs, p.hi, p.lo);
    let mut i = 0;
    let mid = (hi + lo) / 2.0;
    while i < segs.len() {
        // A run of narrow segments is a busy band.
        let mut j = i;
        while j < segs.len() && xs(segs[j].1) - xs(segs[j].0) < BUSY {
            j += 1;
        }
        if j > i + 1 {
            let (a, b) = (xs(segs[i].0), xs(segs[j - 1].1));
            let _ = writeln!(
                s,
                "<rect x=\"{a:.1}\" y=\"{hi:.1}\" width=\"{:.1}\" height=\"{HIGH}\" fill=\"#bbb\"/>",
                (b - a).max(0.5)
            );
            i = j;
            continue;
        }
        let (from, to, v) = segs[i];
        let (a, b) = (xs(from), xs(to));
        match fmt {
            Fmt::Bit => {
                let y = if v == 0 { lo } else { hi };
                let _ = writeln!(
                    s,
                    "<line x1=\"{a:.1}\" y1=\"{y:.1}\" x2=\"{b:.1}\" y2=\"{y:.1}\" stroke=\"#036\" stroke-width=\"1.5\"/>"
                );
                if i + 1 < segs.len() && (segs[i + 1].2 == 0) != (v == 0) {
                    let _ = writeln!(
                        s,
                        "<line x1=\"{b:.1}\" y1=\"{hi:.1}\" x2=\"{b:.1}\" y2=\"{lo:.1}\" stroke=\"#036\" stroke-width=\"1.5\"/>"
                    );
                }
            }
            _ => {
                let e = 2.0_f64.min((b - a) / 2.0);
                let _ = writeln!(
                    s,
                    "<polygon points=\"{a:.1},{mid:.1} {:.1},{hi:.1} {:.1},{hi:.1} {b:.1},{mid:.1} {:.1},{lo:.1} {:.1},{lo:.1}\" fill=\"#eef4fa\" stroke=\"#036\"/>",
                    a + e,
                    b - e,
                    b - e,
                    a + e
                );
                let text = match fmt {
                    Fmt::Hex => format!("{v:x}"),
                    Fmt::Dec => v.to_string(),
                    Fmt::Named(f) => f(v),
                    Fmt::Bit => unreachable!("drawn above"),
                };
                if b - a > 6.6 * text.chars().count() as f64 + 6.0 {
                    let _ = writeln!(
                        s,
                        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
                        (a + b) / 2.0,
                        mid + 4.0,
                        esc(&text)
                    );
                } else if matches!(fmt, Fmt::Named(_)) {
                    notes.push(format!(
                        "{} from {} to {}: {text}",
                        p.label,
                        (p.rel)(from),
                        (p.rel)(to)
                    ));
                }
            }
        }
        i += 1;
    }
}

/// The time axis: time 0 at the anchor, ticks at a round step.
#[allow(clippy::too_many_arguments)]
fn axis(
    s: &mut String,
    start: u64,
    zero: u64,
    end: u64,
    per_unit: u64,
    unit: &str,
    xs: &dyn Fn(u64) -> f64,
    y: f64,
) {
    let span = (end - start) as f64 / per_unit as f64;
    let step = [
        1u64, 2, 4, 5, 8, 10, 16, 20, 40, 50, 80, 100, 200, 400, 500, 1000,
    ]
    .into_iter()
    .find(|s| span / *s as f64 <= 12.0)
    .unwrap_or(2000);
    let _ = writeln!(
        s,
        "<line x1=\"{:.1}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"black\"/>",
        xs(start),
        xs(end)
    );
    let first = -((((zero - start) / per_unit) / step) as i64) * step as i64;
    let mut k = first;
    while zero as i64 + k * per_unit as i64 <= end as i64 {
        let t = (zero as i64 + k * per_unit as i64) as u64;
        if t >= start {
            let x = xs(t);
            let _ = writeln!(
                s,
                "<line x1=\"{x:.1}\" y1=\"{:.1}\" x2=\"{x:.1}\" y2=\"{:.1}\" stroke=\"{}\"/>\n\
                 <text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{k}</text>",
                if k == 0 { TOP } else { y - 4.0 },
                y + 4.0,
                if k == 0 { "#c00" } else { "black" },
                y + 16.0
            );
        }
        k += step as i64;
    }
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{unit} (0: the anchor)</text>",
        xs(end),
        y + 32.0
    );
}

/// Escapes text for SVG.
fn esc(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
