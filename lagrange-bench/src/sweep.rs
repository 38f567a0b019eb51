//! The timed phase: every method over its ladder on every problem — lagrange's fixed-step methods
//! over numbers of steps, lagrange's adaptive methods and the peers over tolerances — one [`Row`]
//! per run.

use crate::diffsol_peer;
use crate::peer::{run_peer, PeerMethod};
use crate::runs::{run_adaptive, run_diffsol, run_fixed, Adaptive, Fixed, RunResult};
use crate::setup::{distance, Problem, Setup};
use indicatif::{ProgressBar, ProgressStyle};
use lagrange_core::Mechanism;
use std::time::Instant;

/// One measured run.
#[derive(Clone, Debug)]
pub struct Row {
    pub problem: &'static str,
    pub method: String,
    /// "h = …" or "tol = …".
    pub setting: String,
    /// Step size or tolerance, for sorting.
    pub setting_value: f64,
    pub steps: usize,
    pub rhs_evals: usize,
    pub jacobian_evals: usize,
    pub seconds: f64,
    pub end_error: f64,
    pub max_energy_error: f64,
    /// "ok", or why the run failed.
    pub status: String,
}

/// The progress line on stderr (drawn only when stderr is a terminal).
pub struct Progress(ProgressBar);

impl Progress {
    fn new(total: usize) -> Self {
        let bar = ProgressBar::new(total as u64);
        bar.set_style(
            ProgressStyle::with_template("[{bar:30}] {pos:>3}/{len} {elapsed:>4}  {wide_msg}")
                .expect("a valid progress template")
                .progress_chars("#> "),
        );
        Progress(bar)
    }

    /// One more run started, described by `what`.
    fn tick(&mut self, what: &str) {
        self.0.set_message(what.to_string());
        self.0.inc(1);
    }

    fn finish(&self) {
        self.0.finish();
    }
}

/// Every problem's runs, in the list's order, with a progress line over all of them.
pub fn run_all(problems: &[Box<dyn Problem>], quick: bool) -> Vec<Row> {
    let total = problems.iter().map(|p| p.run_count()).sum();
    let mut progress = Progress::new(total);
    let mut rows = Vec::new();
    for problem in problems {
        problem.time_runs(quick, &mut rows, &mut progress);
    }
    progress.finish();
    rows
}

/// Runs `run(track_energy)` once tracking the energy (warm-up), then repeats untracked and keeps
/// the fastest time.
fn measure<const N: usize>(
    quick: bool,
    mut run: impl FnMut(bool) -> RunResult<N>,
) -> (RunResult<N>, f64) {
    let t0 = Instant::now();
    let first = run(true);
    let once = t0.elapsed().as_secs_f64();
    if first.is_err() {
        return (first, once);
    }
    let repeats = if quick {
        1
    } else if once < 0.05 {
        7
    } else if once < 0.5 {
        3
    } else {
        1
    };
    let mut best = f64::INFINITY;
    for _ in 0..repeats {
        let t = Instant::now();
        let r = run(false);
        best = best.min(t.elapsed().as_secs_f64());
        std::hint::black_box(&r);
    }
    (first, best)
}

/// The fixed-step methods that apply to a setup.
fn fixed_methods<M, const N: usize, const N2: usize>(setup: &Setup<M, N, N2>) -> Vec<Fixed> {
    let mut methods = vec![Fixed::Rk4, Fixed::Midpoint, Fixed::Gauss];
    if !setup.constrained {
        methods.push(Fixed::Variational);
        if setup.verlet {
            methods.push(Fixed::Verlet);
        }
    }
    methods
}

/// The number of runs of [`run_setup`].
pub fn count_runs<M, const N: usize, const N2: usize>(setup: &Setup<M, N, N2>) -> usize {
    let adaptive = if setup.jacobian_times.is_some() { 7 } else { 5 };
    fixed_methods(setup).len() * setup.steps.len() + adaptive * setup.tolerances.len()
}

/// Where on its ladder a run is: n fixed steps of size h, or a tolerance.
#[derive(Clone, Copy)]
enum Rung {
    Steps { n: usize, h: f64 },
    Tolerance(f64),
}

impl Rung {
    /// How the progress line names it.
    fn progress(self) -> String {
        match self {
            Rung::Steps { n, .. } => format!("n = {n}"),
            Rung::Tolerance(tol) => format!("tol = {tol:.1e}"),
        }
    }

    /// The row's setting, and the value it sorts by.
    fn setting(self) -> (String, f64) {
        match self {
            Rung::Steps { h, .. } => (format!("h = {h:.3e}"), h),
            Rung::Tolerance(tol) => (format!("tol = {tol:.1e}"), tol),
        }
    }
}

/// Where the runs of one problem go.
struct Sweep<'a> {
    quick: bool,
    rows: &'a mut Vec<Row>,
    progress: &'a mut Progress,
}

impl Sweep<'_> {
    /// Times `run` of `method` at `rung` on `setup` and records it as a row.
    fn time<M, const N: usize, const N2: usize>(
        &mut self,
        setup: &Setup<M, N, N2>,
        method: &str,
        rung: Rung,
        run: impl FnMut(bool) -> RunResult<N>,
    ) {
        let name = setup.name;
        self.progress
            .tick(&format!("{name} / {method} / {}", rung.progress()));
        let measured = measure(self.quick, run);
        let row = row(name, method, rung.setting(), &setup.reference, measured);
        self.rows.push(row);
    }
}

/// One problem's runs: each fixed-step method over the steps ladder, then at each tolerance
/// lagrange's adaptive methods, the `ode_solvers` peer and, on the stiff problems, diffsol.
pub fn run_setup<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
    quick: bool,
    rows: &mut Vec<Row>,
    progress: &mut Progress,
) {
    let mut sweep = Sweep {
        quick,
        rows,
        progress,
    };
    for method in &fixed_methods(setup) {
        for &n in &setup.steps {
            let h = (setup.t_end - setup.start.t) / n as f64;
            sweep.time(setup, method.name(), Rung::Steps { n, h }, |track| {
                run_fixed(setup, method, n, track)
            });
        }
    }
    for &tol in &setup.tolerances {
        let rung = Rung::Tolerance(tol);
        for method in [Adaptive::Dopri5, Adaptive::Dop853, Adaptive::Radau5] {
            sweep.time(setup, method.name(), rung, |track| {
                run_adaptive(setup, method, tol, track)
            });
        }
        for method in [PeerMethod::Dopri5, PeerMethod::Dop853] {
            sweep.time(setup, method.name(), rung, |track| {
                run_peer(setup, method, tol, track)
            });
        }
        if setup.jacobian_times.is_some() {
            for method in [diffsol_peer::Method::Bdf, diffsol_peer::Method::Esdirk34] {
                sweep.time(setup, method.name(), rung, |_| {
                    run_diffsol(setup, method, tol)
                });
            }
        }
    }
}

/// The row of one measured run: its end-point error against `reference`, or why it failed (with
/// the commas of the message turned into semicolons).
fn row<const N: usize>(
    problem: &'static str,
    method: &str,
    (setting, setting_value): (String, f64),
    reference: &([f64; N], [f64; N]),
    (result, seconds): (RunResult<N>, f64),
) -> Row {
    let (steps, rhs_evals, jacobian_evals, end_error, max_energy_error, status) = match result {
        Ok((q, v, rhs, jac, de, steps)) => (
            steps,
            rhs,
            jac,
            distance(&q, &v, reference),
            de,
            "ok".into(),
        ),
        Err(e) => (0, 0, 0, f64::NAN, f64::NAN, e.replace(',', ";")),
    };
    Row {
        problem,
        method: method.to_string(),
        setting,
        setting_value,
        steps,
        rhs_evals,
        jacobian_evals,
        seconds,
        end_error,
        max_energy_error,
        status,
    }
}
