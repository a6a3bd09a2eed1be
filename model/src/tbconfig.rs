//! Token-bus scenario files (TOML, docs/scenarios.md "Token-bus scenarios"):
//! the bus, the redundancy parameters and the faults. A file is a token-bus
//! scenario when it has a `[token_bus]` table. Parsing never panics; every
//! error names the field and its value with file:line:column.

use crate::scenario::{ScenarioError, SourceMap};
use serde::Deserialize;
use std::fmt;
use toml::Spanned;

/// Most octet times one scenario may run.
pub const MAX_TICKS: u64 = 2_000_000;

/// `[token_bus]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBus {
    /// Stations on the bus, addresses 0..stations−1 in cable order.
    pub stations: Spanned<u32>,
    /// Octet times to run.
    pub ticks: Spanned<u64>,
    /// Bus rate in Mbit/s for summaries (an octet time is 8 bits).
    #[serde(default)]
    pub rate_mbps: Option<Spanned<f64>>,
    /// Data octets of an application frame (≥ 2: the sequence number).
    #[serde(default)]
    pub data_len: Option<Spanned<u32>>,
    /// Status frame production period, octets.
    #[serde(default)]
    pub sf_period: Option<Spanned<u32>>,
    /// Status check period, octets.
    #[serde(default)]
    pub check_period: Option<Spanned<u32>>,
    /// Fault-free octets before a faulty channel counts as good again.
    #[serde(default)]
    pub good_limit: Option<Spanned<u32>>,
}

/// `[[fault]]` kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RawKind {
    /// The channel's cable is shorted: nobody hears anything on it.
    Short,
    /// The cable is cut between station `position − 1` and `position`.
    Open,
    /// Station `station`'s drop cable to the channel is cut.
    Drop,
    /// The channel carries noise for `duration` octets.
    Noise,
    /// Every fault of the channel is repaired.
    Repair,
    /// Station `station` loses power.
    Kill,
    /// Station `station` powers on again.
    Restart,
    /// Station `station` leaves the logical ring (exit_ring).
    Leave,
    /// Station `station`'s transmitter babbles for `duration` octets.
    Babble,
    /// Host command AUTO_SW_MODE to `station` (omitted: every station).
    Auto,
}

/// `[[fault]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTbFault {
    /// Octet time.
    pub at: Spanned<u64>,
    /// What happens.
    pub kind: Spanned<RawKind>,
    /// Channel `A` or `B`.
    #[serde(default)]
    pub channel: Option<Spanned<String>>,
    /// Station.
    #[serde(default)]
    pub station: Option<Spanned<u32>>,
    /// Open: cable position.
    #[serde(default)]
    pub position: Option<Spanned<u32>>,
    /// Noise, babble: octets.
    #[serde(default)]
    pub duration: Option<Spanned<u32>>,
}

/// The whole file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTb {
    /// Free-text name.
    #[serde(default)]
    pub name: Option<String>,
    /// Free-text description.
    #[serde(default)]
    pub description: Option<String>,
    /// The bus.
    pub token_bus: RawBus,
    /// Faults and commands.
    #[serde(default)]
    pub fault: Vec<RawTbFault>,
}

/// A channel fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChanFault {
    /// Shorted.
    Short,
    /// Open at a position.
    Open(u8),
    /// A station's drop cable cut.
    Drop(u8),
    /// Noise for octets.
    Noise(u32),
    /// All repaired.
    Repair,
}

/// A scenario event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TbEvent {
    /// On channel (false A, true B).
    Chan(bool, ChanFault),
    /// Power off.
    Kill(usize),
    /// Power on.
    Restart(usize),
    /// Leave the ring.
    Leave(usize),
    /// Babble for octets.
    Babble(usize, u32),
    /// AUTO_SW_MODE to one or all stations.
    Auto(Option<usize>),
}

impl TbEvent {
    /// Faults (not host commands).
    pub fn is_fault(&self) -> bool {
        !matches!(self, TbEvent::Auto(_))
    }
    /// Fault class for reports.
    pub fn class(&self) -> &'static str {
        match self {
            TbEvent::Chan(_, ChanFault::Short) => "channel short",
            TbEvent::Chan(_, ChanFault::Open(_)) => "cable open",
            TbEvent::Chan(_, ChanFault::Drop(_)) => "drop cable open",
            TbEvent::Chan(_, ChanFault::Noise(_)) => "noise burst",
            TbEvent::Chan(_, ChanFault::Repair) => "repair",
            TbEvent::Kill(_) => "station death",
            TbEvent::Restart(_) => "station restart",
            TbEvent::Leave(_) => "station leaves",
            TbEvent::Babble(..) => "babbling station",
            TbEvent::Auto(_) => "AUTO_SW_MODE",
        }
    }
}

impl fmt::Display for TbEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ch = |b: &bool| if *b { 'B' } else { 'A' };
        match self {
            TbEvent::Chan(c, ChanFault::Short) => write!(f, "short {}", ch(c)),
            TbEvent::Chan(c, ChanFault::Open(p)) => write!(f, "open {} at {p}", ch(c)),
            TbEvent::Chan(c, ChanFault::Drop(s)) => write!(f, "drop {} station {s}", ch(c)),
            TbEvent::Chan(c, ChanFault::Noise(d)) => write!(f, "noise {} for {d}", ch(c)),
            TbEvent::Chan(c, ChanFault::Repair) => write!(f, "repair {}", ch(c)),
            TbEvent::Kill(s) => write!(f, "kill station {s}"),
            TbEvent::Restart(s) => write!(f, "restart station {s}"),
            TbEvent::Leave(s) => write!(f, "leave station {s}"),
            TbEvent::Babble(s, d) => write!(f, "babble station {s} for {d}"),
            TbEvent::Auto(None) => write!(f, "auto all"),
            TbEvent::Auto(Some(s)) => write!(f, "auto station {s}"),
        }
    }
}

/// A scheduled event.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scheduled {
    /// Octet time.
    pub at: u64,
    /// What.
    pub what: TbEvent,
}

/// A validated token-bus scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct TbConfig {
    /// Name.
    pub name: String,
    /// Stations.
    pub stations: usize,
    /// Octet times.
    pub ticks: u64,
    /// Mbit/s for summaries.
    pub rate_mbps: f64,
    /// Data octets per application frame.
    pub data_len: usize,
    /// Status frame period.
    pub sf_period: u16,
    /// Status check period.
    pub check_period: u16,
    /// Good limit.
    pub good_limit: u16,
    /// Events in time order.
    pub events: Vec<Scheduled>,
}

impl TbConfig {
    /// Microseconds per octet time.
    pub fn tick_us(&self) -> f64 {
        8.0 / self.rate_mbps
    }
}

/// True when the TOML text has a top-level `[token_bus]` table.
pub fn is_token_bus(text: &str) -> bool {
    text.parse::<toml::Table>()
        .map(|t| t.contains_key("token_bus"))
        .unwrap_or(false)
}

/// Parses and validates a token-bus scenario; `file` names it in errors.
/// About 200 lines of checks in the order of the file's tables (the bus,
/// the stations, the faults), each naming its field and value.
pub fn load(file: &str, text: &str) -> Result<TbConfig, ScenarioError> {
    let map = SourceMap::new(file, text);
    let raw: RawTb = toml::from_str(text).map_err(|e| {
        let msg = e.message().trim().to_string();
        map.error(e.span().map(|s| s.start), msg)
    })?;
    let b = &raw.token_bus;
    let n = *b.stations.get_ref();
    if !(2..=32).contains(&n) {
        return Err(map.at(
            &b.stations,
            format!("token_bus.stations = {n}: a bus has 2 to 32 stations"),
        ));
    }
    let ticks = *b.ticks.get_ref();
    if ticks == 0 || ticks > MAX_TICKS {
        return Err(map.at(
            &b.ticks,
            format!("token_bus.ticks = {ticks}: must be 1 to {MAX_TICKS}"),
        ));
    }
    let rate = match &b.rate_mbps {
        None => 10.0,
        Some(r) => {
            let v = *r.get_ref();
            if !(v.is_finite() && v > 0.0 && v <= 100.0) {
                return Err(map.at(
                    r,
                    format!("token_bus.rate_mbps = {v}: must be above 0 and at most 100"),
                ));
            }
            v
        }
    };
    let ranged = |f: &Option<Spanned<u32>>,
                  name: &str,
                  default: u32,
                  lo: u32,
                  hi: u32|
     -> Result<u32, ScenarioError> {
        match f {
            None => Ok(default),
            Some(s) => {
                let v = *s.get_ref();
                if v < lo || v > hi {
                    Err(map.at(s, format!("token_bus.{name} = {v}: must be {lo} to {hi}")))
                } else {
                    Ok(v)
                }
            }
        }
    };
    let data_len = ranged(&b.data_len, "data_len", 4, 2, 32)?;
    let sf_period = ranged(&b.sf_period, "sf_period", 256, 2, 65535)?;
    let check_period = ranged(&b.check_period, "check_period", 1024, 64, 65535)?;
    let good_limit = ranged(&b.good_limit, "good_limit", 2048, 1, 65535)?;
    if check_period <= sf_period {
        let s = b.check_period.as_ref().or(b.sf_period.as_ref());
        let msg = format!(
            "token_bus.check_period = {check_period} must be longer than sf_period = {sf_period}: a station's live counter must advance between two checks"
        );
        return Err(match s {
            Some(s) => map.at(s, msg),
            None => map.error(None, msg),
        });
    }
    let mut events = vec![];
    for f in &raw.fault {
        let at = *f.at.get_ref();
        if at >= ticks {
            return Err(map.at(
                &f.at,
                format!(
                    "fault.at = {at}: the scenario runs {ticks} octet times (0 to {})",
                    ticks - 1
                ),
            ));
        }
        let kind = *f.kind.get_ref();
        let kname = format!("{kind:?}").to_lowercase();
        let need = |what: &str| map.at(&f.kind, format!("fault kind = \"{kname}\" needs `{what}`"));
        let refuse = |s: usize, what: &str| {
            map.error(
                Some(s),
                format!("fault kind = \"{kname}\" takes no `{what}`"),
            )
        };
        let channel = match &f.channel {
            None => None,
            Some(c) => match c.get_ref().as_str() {
                "A" | "a" => Some(false),
                "B" | "b" => Some(true),
                v => {
                    return Err(map.at(
                        c,
                        format!("fault.channel = \"{v}\": expected \"A\" or \"B\""),
                    ))
                }
            },
        };
        let station = match &f.station {
            None => None,
            Some(s) => {
                let v = *s.get_ref();
                if v >= n {
                    return Err(map.at(
                        s,
                        format!("fault.station = {v}: the bus has stations 0 to {}", n - 1),
                    ));
                }
                Some(v as usize)
            }
        };
        let duration = match &f.duration {
            None => None,
            Some(d) => {
                let v = *d.get_ref();
                if v == 0 || v as u64 > MAX_TICKS {
                    return Err(
                        map.at(d, format!("fault.duration = {v}: must be 1 to {MAX_TICKS}"))
                    );
                }
                Some(v)
            }
        };
        let is_chan = matches!(
            kind,
            RawKind::Short | RawKind::Open | RawKind::Drop | RawKind::Noise | RawKind::Repair
        );
        if let (false, Some(c)) = (is_chan, &f.channel) {
            return Err(refuse(c.span().start, "channel"));
        }
        if let (true, None) = (is_chan, channel) {
            return Err(need("channel"));
        }
        if let (false, Some(p)) = (kind == RawKind::Open, &f.position) {
            return Err(refuse(p.span().start, "position"));
        }
        let takes_station = !matches!(
            kind,
            RawKind::Short | RawKind::Open | RawKind::Noise | RawKind::Repair
        );
        if let (false, Some(s)) = (takes_station, &f.station) {
            return Err(refuse(s.span().start, "station"));
        }
        let takes_duration = matches!(kind, RawKind::Noise | RawKind::Babble);
        if let (false, Some(d)) = (takes_duration, &f.duration) {
            return Err(refuse(d.span().start, "duration"));
        }
        let c = channel.unwrap_or(false);
        let what = match kind {
            RawKind::Short => TbEvent::Chan(c, ChanFault::Short),
            RawKind::Repair => TbEvent::Chan(c, ChanFault::Repair),
            RawKind::Open => {
                let Some(p) = &f.position else {
                    return Err(need("position"));
                };
                let v = *p.get_ref();
                if v == 0 || v >= n {
                    return Err(map.at(
                        p,
                        format!(
                            "fault.position = {v}: an open lies between two stations, 1 to {}",
                            n - 1
                        ),
                    ));
                }
                TbEvent::Chan(c, ChanFault::Open(v as u8))
            }
            RawKind::Drop => TbEvent::Chan(
                c,
                ChanFault::Drop(station.ok_or_else(|| need("station"))? as u8),
            ),
            RawKind::Noise => TbEvent::Chan(
                c,
                ChanFault::Noise(duration.ok_or_else(|| need("duration"))?),
            ),
            RawKind::Kill => TbEvent::Kill(station.ok_or_else(|| need("station"))?),
            RawKind::Restart => TbEvent::Restart(station.ok_or_else(|| need("station"))?),
            RawKind::Leave => TbEvent::Leave(station.ok_or_else(|| need("station"))?),
            RawKind::Babble => TbEvent::Babble(
                station.ok_or_else(|| need("station"))?,
                duration.ok_or_else(|| need("duration"))?,
            ),
            RawKind::Auto => TbEvent::Auto(station),
        };
        events.push(Scheduled { at, what });
    }
    events.sort_by_key(|e| e.at);
    Ok(TbConfig {
        name: raw.name.clone().unwrap_or_else(|| {
            std::path::Path::new(file)
                .file_stem()
                .map(|s| s.to_string_lossy().to_string())
                .unwrap_or_else(|| "token_bus".into())
        }),
        stations: n as usize,
        ticks,
        rate_mbps: rate,
        data_len: data_len as usize,
        sf_period: sf_period as u16,
        check_period: check_period as u16,
        good_limit: good_limit as u16,
        events,
    })
}
