//! Progress of a long series of steps (the QEMU runs of `cargo xtask mcu`) on stderr, so
//! that stdout keeps only the tables.
//!
//! On a terminal: an `indicatif` bar (elapsed time, position, the current step) with a line
//! per finished step printed above it. Under CI (env `CI` set) or when stderr is not a
//! terminal (a log file): plain lines, one when a step starts and one with its time when it
//! is done, and no redrawn bar.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};

/// `n` steps, announced one by one with [`Progress::start`] and [`Progress::done`].
pub(crate) struct Progress {
    prefix: &'static str,
    n: usize,
    k: usize,
    what: String,
    step_t0: Instant,
    /// `None`: plain lines.
    bar: Option<ProgressBar>,
}

impl Progress {
    /// `n` steps whose lines start with `prefix` (`mcu`); a bar unless CI or not a terminal.
    pub(crate) fn new(prefix: &'static str, n: usize) -> Self {
        let plain = std::env::var_os("CI").is_some() || !std::io::stderr().is_terminal();
        let bar = (!plain).then(|| {
            let style = ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40.cyan/blue}] {pos}/{len} {msg}",
            )
            .expect("template")
            .progress_chars("=> ");
            ProgressBar::new(n as u64).with_style(style)
        });
        Progress {
            prefix,
            n,
            k: 0,
            what: String::new(),
            step_t0: Instant::now(),
            bar,
        }
    }

    /// The next step, `what` (e.g. `cube on Cortex-M4F`), begins.
    pub(crate) fn start(&mut self, what: &str) {
        self.k += 1;
        self.what = what.to_string();
        self.step_t0 = Instant::now();
        match &self.bar {
            Some(b) => b.set_message(what.to_string()),
            None => eprintln!("{} ...", self.head()),
        }
    }

    /// The current step ended: `ok` false when it failed (the caller reports why).
    pub(crate) fn done(&mut self, ok: bool) {
        let line = done_line(&self.head(), ok, self.step_t0.elapsed());
        match &self.bar {
            Some(b) => {
                b.println(line);
                b.inc(1);
            }
            None => eprintln!("{line}"),
        }
    }

    /// Removes the bar (before the tables go to stdout, or before an error message).
    pub(crate) fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }

    /// `mcu: [3/84] cube on Cortex-M4F`.
    fn head(&self) -> String {
        format!("{}: [{}/{}] {}", self.prefix, self.k, self.n, self.what)
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

/// `mcu: [3/84] cube on Cortex-M4F: 4.2 s`, or `...: FAILED after 4.2 s`.
fn done_line(head: &str, ok: bool, t: Duration) -> String {
    let s = t.as_secs_f64();
    if ok {
        format!("{head}: {s:.1} s")
    } else {
        format!("{head}: FAILED after {s:.1} s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines() {
        let t = Duration::from_millis(4_240);
        assert_eq!(
            done_line("mcu: [3/84] cube on Cortex-M4F", true, t),
            "mcu: [3/84] cube on Cortex-M4F: 4.2 s"
        );
        assert_eq!(
            done_line("mcu: [3/84] cube on Cortex-M4F", false, t),
            "mcu: [3/84] cube on Cortex-M4F: FAILED after 4.2 s"
        );
        let mut p = Progress {
            prefix: "mcu",
            n: 84,
            k: 2,
            what: String::new(),
            step_t0: Instant::now(),
            bar: None,
        };
        p.start("whole_sphere_footprint on Cortex-M4F");
        assert_eq!(p.head(), "mcu: [3/84] whole_sphere_footprint on Cortex-M4F");
    }
}
