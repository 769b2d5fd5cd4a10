//! `cargo xtask fuzz [N] [SEED]`: `N` random cases from `SEED` (see `host_tests::fuzz`),
//! with a progress bar, then the counts; exits non-zero if anything went wrong.

use std::process::ExitCode;

use clap::Parser;
use host_tests::fuzz;
use indicatif::{ProgressBar, ProgressStyle};

/// Random draws checked for panics, out-of-bounds writes, depth-rule violations and
/// band/whole-frame mismatches.
#[derive(Parser, Debug)]
struct Args {
    /// Number of cases (one random triangle, drawn whole and in bands, and one quad each).
    #[arg(default_value_t = 200_000)]
    n: u64,
    /// First case's seed.
    #[arg(default_value_t = 1)]
    seed: u64,
}

fn main() -> ExitCode {
    let a = Args::parse();
    // Panics are counted, not printed one by one.
    std::panic::set_hook(Box::new(|_| {}));
    let bar = ProgressBar::new(a.n);
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} {wide_bar} {pos}/{len} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let c = fuzz::run(a.n, a.seed, |done, c| {
        bar.set_position(done);
        bar.set_message(format!(
            "panics {} depth {} oob {} mismatches {}",
            c.panics, c.depth_violations, c.out_of_bounds, c.mismatches
        ));
    });
    bar.finish_and_clear();
    println!(
        "fuzz: {} cases from seed {}: {} triangles ({} with a technique shader; {} draws writing {} pixels), {} quads, {} refused; panics {}, depth-rule violations {}, out-of-bounds writes {}, mismatches {}",
        a.n, a.seed, c.triangles, c.shaded, c.drawn, c.pixels, c.quads, c.refused, c.panics, c.depth_violations, c.out_of_bounds, c.mismatches
    );
    if let Some(s) = c.first_failure {
        println!("fuzz: first failing case: seed {s} (host_tests::fuzz::case({s}))");
    }
    if c.clean() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
