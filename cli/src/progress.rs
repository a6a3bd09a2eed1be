//! Progress on stderr, one helper for every command.
//!
//! On a terminal, progress uses `indicatif`: a spinner with the elapsed time
//! for each step that takes a while (a Verilator build, a synthesis run), a
//! bar for a run's cycles and for a campaign's cases, and one line per
//! campaign worker that names the case it is running. All of them share one
//! `MultiProgress`, so parallel steps do not overwrite each other.
//!
//! In a log (stderr is not a terminal, e.g. CI), progress is plain lines:
//! one when a step starts and one when it ends, and a bar's state every
//! tenth of the way. A log never gets carriage returns.

use indicatif::{MultiProgress, ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

/// Whether progress is drawn (stderr is a terminal).
pub fn tty() -> bool {
    std::io::stderr().is_terminal()
}

/// The one set of live progress lines.
fn multi() -> &'static MultiProgress {
    static M: OnceLock<MultiProgress> = OnceLock::new();
    M.get_or_init(|| MultiProgress::with_draw_target(ProgressDrawTarget::stderr()))
}

/// Prints a line on stderr above the live progress lines (plainly in a
/// log).
pub fn line(text: &str) {
    if tty() {
        multi().suspend(|| eprintln!("{text}"));
    } else {
        eprintln!("{text}");
    }
}

/// One step that takes a while.
pub struct Step {
    bar: Option<ProgressBar>,
    what: String,
    t0: Instant,
}

impl Step {
    /// Starts the step `what` ("building the Verilator model of ring8").
    pub fn start(what: impl Into<String>) -> Step {
        let what = what.into();
        let bar = if tty() {
            let b = multi().add(ProgressBar::new_spinner());
            b.set_style(
                ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
                    .expect("a valid template"),
            );
            b.set_message(what.clone());
            b.enable_steady_tick(Duration::from_millis(120));
            Some(b)
        } else {
            eprintln!("{what} …");
            None
        };
        Step {
            bar,
            what,
            t0: Instant::now(),
        }
    }

    /// Ends the step with its outcome ("ready", "met timing at 104 MHz").
    pub fn done(self, outcome: &str) {
        let text = format!(
            "{}: {outcome} ({:.1} s)",
            self.what,
            self.t0.elapsed().as_secs_f64()
        );
        match self.bar {
            Some(b) => {
                b.finish_and_clear();
                multi().remove(&b);
                line(&text);
            }
            None => eprintln!("{text}"),
        }
    }
}

/// A count of things done (cycles, cases) out of a known total.
pub struct Bar {
    bar: Option<ProgressBar>,
    what: &'static str,
    total: u64,
    t0: Instant,
}

impl Bar {
    /// A bar over `total` `what` ("cycles", "cases").
    pub fn new(total: u64, what: &'static str) -> Bar {
        let bar = tty().then(|| {
            let b = multi().add(ProgressBar::new(total));
            b.set_style(
                ProgressStyle::with_template(
                    "[{bar:30}] {pos}/{len} {prefix}{msg} ({elapsed}, ~{eta} left)",
                )
                .expect("a valid template")
                .progress_chars("#>."),
            );
            b.set_prefix(what);
            b
        });
        Bar {
            bar,
            what,
            total,
            t0: Instant::now(),
        }
    }

    /// Sets the count to `done`, with a note (`3 with mismatches`).
    pub fn set(&self, done: u64, note: &str) {
        match &self.bar {
            Some(b) => {
                b.set_position(done);
                b.set_message(if note.is_empty() {
                    String::new()
                } else {
                    format!(", {note}")
                });
            }
            None => {
                // In a log: every tenth of the way and at the end.
                let t = self.total.max(1);
                if done == self.total || (done * 10) / t != (done.saturating_sub(1) * 10) / t {
                    let sep = if note.is_empty() { "" } else { ", " };
                    eprintln!(
                        "{done}/{} {}{sep}{note} ({:.0} s)",
                        self.total,
                        self.what,
                        self.t0.elapsed().as_secs_f64()
                    );
                }
            }
        }
    }

    /// Removes the bar from the terminal.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
            multi().remove(b);
        }
    }
}

/// One line per parallel worker, naming what it runs (terminal only).
pub struct Workers {
    lines: Vec<ProgressBar>,
    free: Mutex<Vec<usize>>,
}

impl Workers {
    /// `n` worker lines.
    pub fn new(n: usize) -> Workers {
        let lines: Vec<ProgressBar> = if tty() {
            (0..n)
                .map(|_| {
                    let b = multi().add(ProgressBar::new_spinner());
                    b.set_style(
                        ProgressStyle::with_template("  {spinner} {msg}")
                            .expect("a valid template"),
                    );
                    b.set_message("idle");
                    b.enable_steady_tick(Duration::from_millis(200));
                    b
                })
                .collect()
        } else {
            vec![]
        };
        Workers {
            free: Mutex::new((0..lines.len()).rev().collect()),
            lines,
        }
    }

    /// Shows `what` on a free line while `f` runs.
    pub fn run<R>(&self, what: &str, f: impl FnOnce() -> R) -> R {
        let take = || self.free.lock().unwrap_or_else(|e| e.into_inner()).pop();
        let slot = take();
        if let Some(i) = slot {
            self.lines[i].set_message(what.to_string());
        }
        let r = f();
        if let Some(i) = slot {
            self.lines[i].set_message("idle");
            self.free.lock().unwrap_or_else(|e| e.into_inner()).push(i);
        }
        r
    }

    /// Removes the lines from the terminal.
    pub fn finish(&self) {
        for b in &self.lines {
            b.finish_and_clear();
            multi().remove(b);
        }
    }
}
