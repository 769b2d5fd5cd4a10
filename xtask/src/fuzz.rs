//! `cargo xtask fuzz [N] [SEED]`: the randomized robustness run (`host_tests::fuzz`),
//! built with the `ci` profile (optimized, with overflow checks and debug assertions).

use std::process::ExitCode;

use clap::Args;

use crate::cmd::cargo;

/// Cases of the CI run: under a minute on a 2-core machine after the build.
pub(crate) const CI_CASES: u64 = 400_000;

/// Flags of `cargo xtask fuzz`.
#[derive(Args, Debug)]
pub(crate) struct FuzzArgs {
    /// Number of cases (each: one random triangle drawn whole and in bands, one quad).
    #[arg(default_value_t = CI_CASES)]
    pub(crate) n: u64,
    /// Seed of the first case (case k uses SEED + k, so a failing seed is a reproducer).
    #[arg(default_value_t = 1)]
    pub(crate) seed: u64,
}

/// Runs `n` cases from `seed`; `Err` when the run found anything (or did not run).
pub(crate) fn run(n: u64, seed: u64) -> Result<(), String> {
    let (n, seed) = (n.to_string(), seed.to_string());
    cargo(&[
        "run",
        "-p",
        "host-tests",
        "--profile",
        "ci",
        "--bin",
        "fuzz",
        "--",
        &n,
        &seed,
    ])
    .run()
}

pub(crate) fn fuzz(a: &FuzzArgs) -> ExitCode {
    match run(a.n, a.seed) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("fuzz: {e}");
            ExitCode::FAILURE
        }
    }
}
