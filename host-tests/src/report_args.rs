//! The command line the report programs share (`--out DIR`, `--runs N`, `--mcu FILE`: the
//! flags `cargo xtask report` passes), parsed with clap. Each program names itself and its
//! default number of timed runs; one with flags of its own flattens [`ReportArgs`] into its
//! parser and calls [`parse_with_runs`].

use std::path::PathBuf;

use clap::{Args, FromArgMatches, Parser};

/// `--out`, `--runs` and `--mcu`.
#[derive(Args, Clone, Debug)]
pub struct ReportArgs {
    /// Output directory for the report's markdown, plots and frames
    #[arg(long, value_name = "DIR", default_value = "target/report")]
    pub out: PathBuf,
    /// Timed runs per variant (host ns/px: their median)
    #[arg(long, value_name = "N")]
    pub runs: u32,
    /// Microcontroller instruction counts (mcu.tsv, written by `cargo xtask report`)
    #[arg(long, value_name = "FILE")]
    pub mcu: Option<PathBuf>,
}

impl ReportArgs {
    /// Parses the process's arguments for the program `name` (described by `about`), with
    /// `runs` timed runs unless `--runs` says otherwise. A bad flag prints clap's usage
    /// error and exits with code 2.
    pub fn parse(name: &'static str, about: &'static str, runs: &'static str) -> Self {
        let cmd = Self::augment_args(clap::Command::new(name)).about(about);
        from_matches(with_runs(cmd, runs))
    }
}

/// Parses the process's arguments into `P` (a parser that flattens [`ReportArgs`]), with
/// `runs` timed runs unless `--runs` says otherwise.
pub fn parse_with_runs<P: Parser>(runs: &'static str) -> P {
    from_matches(with_runs(P::command(), runs))
}

/// `cmd` with `runs` as the default of `--runs` (the derive makes it required: it has no
/// default of its own, each program has its own).
fn with_runs(cmd: clap::Command, runs: &'static str) -> clap::Command {
    cmd.mut_arg("runs", |a| a.default_value(runs).required(false))
}

fn from_matches<T: FromArgMatches>(mut cmd: clap::Command) -> T {
    let matches = cmd.get_matches_mut();
    T::from_arg_matches(&matches).unwrap_or_else(|e| e.format(&mut cmd).exit())
}
