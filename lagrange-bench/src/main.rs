//! `cargo run --release -p lagrange-bench --bin work-precision [-- --quick] [--out DIR]`
//!
//! What accuracy costs: every integrator of `lagrange-core` over a ladder of step sizes (fixed-step
//! methods) or tolerances (Dopri5, Dop853, Radau5), on problems with exact or high-precision
//! reference solutions — among them a stiff chain (stiff springs, ω up to 2613, explicit methods
//! held to their stability bound) and a constrained pendulum — with peers on hand-written
//! equations of the same problems: the `ode_solvers` crate's Dopri5 and Dop853 everywhere, and
//! `diffsol`'s BDF and ESDIRK3(4) on the stiff chain. Before any timing, each peer's end state at
//! tol 1e-8 is compared with lagrange's (the report lists the distances). For each (problem,
//! method, setting) it records the end-point error (max norm over q and v), the maximum energy
//! error over the run, right-hand-side evaluations (and Jacobian evaluations of the implicit
//! methods; for diffsol, its Jacobian-vector products) and the wall time (minimum over repeats
//! after a warm-up run, which is also the run that tracks the energy), and the machine's load
//! averages before and after. Writes `results.csv`, `report.md` and SVG plots into
//! `reports/work-precision/` (or `--out DIR`).

mod agreement;
mod diffsol_peer;
mod dop853_steps;
mod fpu;
mod kepler;
mod load;
mod peer;
mod pendulums;
mod plot;
mod problem_set;
mod problems;
mod report;
mod runs;
mod setup;
mod stiff;
mod sweep;

use clap::Parser;
use std::path::PathBuf;

/// The command line.
#[derive(Parser, Debug)]
#[command(
    name = "work-precision",
    about = "Every integrator of lagrange-core over a ladder of step sizes and tolerances on seven \
             problems, with ode_solvers and diffsol as peers: results.csv, report.md and SVG plots."
)]
struct Args {
    /// A shorter ladder and one timing repeat: a smoke run in seconds, not a report.
    #[arg(long)]
    quick: bool,
    /// Instead of the report: the accepted and rejected steps and evaluations of Dop853 with
    /// β = 0.04 and β = 0 against the peer's Dop853, on every problem and tolerance (no timing).
    #[arg(long)]
    dop853_steps: bool,
    /// Where the CSV, markdown and SVG files are written.
    #[arg(long, value_name = "DIR", default_value = "reports/work-precision")]
    out: PathBuf,
}

fn main() {
    let Args {
        quick,
        out,
        dop853_steps,
    } = Args::parse();
    std::fs::create_dir_all(&out).expect("create output directory");
    let set = problem_set::build(quick);
    if dop853_steps {
        dop853_steps::print(&set.problems);
        return;
    }
    // Before timing: the peers solve the same problems as lagrange.
    let load_before = report::load_average();
    let agreement: Vec<String> = set
        .problems
        .iter()
        .filter_map(|p| p.peer_agreement())
        .collect();
    let rows = sweep::run_all(&set.problems, quick);
    let load_after = report::load_average();

    // Long run: energy error against time on Kepler over 1000 periods.
    eprintln!("long run: Kepler energy over 1000 periods");
    let long = plot::kepler_long_run(if quick { 100 } else { 1000 });

    report::write_csv(&out, &rows);
    let notes = report::notes(&load_before, &load_after, &set, &agreement);
    report::write_markdown(&out, &rows, &notes, quick);
    for problem in &set.problems {
        plot::work_precision(&out, problem.name(), &rows);
    }
    plot::energy_long_run(&out, &long);
    eprintln!("wrote {}", out.display());
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn command_line() {
        Args::command().debug_assert();
        let a = Args::try_parse_from(["work-precision"]).unwrap();
        assert!(!a.quick);
        assert_eq!(a.out, PathBuf::from("reports/work-precision"));
        let a = Args::try_parse_from(["work-precision", "--quick", "--out", "/tmp/x"]).unwrap();
        assert!(a.quick);
        assert_eq!(a.out, PathBuf::from("/tmp/x"));
        assert!(Args::try_parse_from(["work-precision", "--out"]).is_err());
        assert!(Args::try_parse_from(["work-precision", "--fast"]).is_err());
    }
}
