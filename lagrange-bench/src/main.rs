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

mod diffsol_peer;
mod dop853_steps;
mod fpu;
mod kepler;
mod load;
mod pendulums;
mod plot;
mod problems;
mod stiff;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use lagrange_core::integrate::{Dop853, ImplicitStepStats, NewtonMemory, Stepper};
use lagrange_core::Coordinates;
use lagrange_core::{
    Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Radau5, Rk4, State,
    StormerVerlet, Variational,
};
use pendulums::*;
use problems::*;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;
use stiff::*;

/// One measured run.
#[derive(Clone, Debug)]
struct Row {
    problem: &'static str,
    method: String,
    /// "h = …" or "tol = …".
    setting: String,
    /// Step size or tolerance, for sorting.
    setting_value: f64,
    steps: usize,
    rhs_evals: usize,
    jacobian_evals: usize,
    seconds: f64,
    end_error: f64,
    max_energy_error: f64,
    /// "ok", or why the run failed.
    status: String,
}

/// A problem: mechanism, start, end time, reference end state, hand-written accelerations.
struct Setup<M, const N: usize> {
    name: &'static str,
    mechanism: M,
    start: State<[f64; N]>,
    t_end: f64,
    reference: ([f64; N], [f64; N]),
    rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
    /// Fixed-step ladder: numbers of steps.
    steps: Vec<usize>,
    /// Tolerance ladder of the adaptive methods.
    tolerances: Vec<f64>,
    /// Whether Störmer–Verlet applies (constant mass matrix).
    verlet: bool,
    /// Whether the mechanism has constraints (the variational integrator and Störmer–Verlet
    /// refuse it).
    constrained: bool,
    /// The Jacobian-vector product of the first-order system, by hand: given for the stiff
    /// problems, on which diffsol's implicit solvers run as a second peer.
    jacobian_times: Option<diffsol_peer::JacobianTimes<N>>,
    /// Energy error above which a run counts as unstable (relative to 1 + |E₀|).
    unstable_energy: f64,
}

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

/// The progress line on stderr (drawn only when stderr is a terminal).
struct Progress(ProgressBar);

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

/// A state in the mechanism's own coordinates type.
fn in_coordinates<M: Mechanism<N>, const N: usize>(s: &State<[f64; N]>) -> State<M::Coords> {
    State::new(s.t, M::Coords::from_array(s.q), M::Coords::from_array(s.v))
}

fn distance<const N: usize>(q: &[f64; N], v: &[f64; N], r: &([f64; N], [f64; N])) -> f64 {
    q.iter()
        .zip(&r.0)
        .chain(v.iter().zip(&r.1))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

/// What one run returns: end state, evaluations, Jacobian evaluations, max energy error (NaN when
/// not tracked), or an error message.
type RunResult<const N: usize> = Result<([f64; N], [f64; N], usize, usize, f64, usize), String>;

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

enum Fixed {
    Rk4,
    Midpoint,
    Gauss,
    Variational,
    Verlet,
}

impl Fixed {
    fn name(&self) -> &'static str {
        match self {
            Fixed::Rk4 => Rk4::NAME,
            Fixed::Midpoint => ImplicitMidpoint::NAME,
            Fixed::Gauss => GaussLegendre2::NAME,
            Fixed::Variational => Variational::NAME,
            Fixed::Verlet => StormerVerlet::NAME,
        }
    }
}

/// n steps of a fixed-step method from the start; returns the end state and costs.
fn run_fixed<M: Mechanism<N>, const N: usize>(
    setup: &Setup<M, N>,
    method: &Fixed,
    n: usize,
    track: bool,
) -> RunResult<N> {
    let m = &setup.mechanism;
    let mut s = in_coordinates::<M, N>(&setup.start);
    let h = (setup.t_end - s.t) / n as f64;
    let e0 = m.energy(&s).map_err(|e| e.to_string())?;
    let mut max_de = if track { 0.0f64 } else { f64::NAN };
    let (mut rhs, mut jac) = (0usize, 0usize);
    // The implicit methods run as a solver does: the Newton matrix and the stage predictor are
    // kept from step to step. Evaluations: plain evaluations of the canonical field plus the
    // velocity recovery's passes of the momenta plus the momenta and q̈ at the step's start.
    let add = |st: ImplicitStepStats, rhs: &mut usize, jac: &mut usize| {
        *rhs += st.field_evaluations + st.velocity_iterations + 2;
        *jac += st.jacobian_evaluations;
    };
    let mut memory1 = NewtonMemory::<N, 1>::default();
    let mut memory2 = NewtonMemory::<N, 2>::default();
    for _ in 0..n {
        let r = match method {
            Fixed::Rk4 => m.step::<Rk4>(&mut s, h).map(|_| rhs += 4),
            Fixed::Verlet => m.step::<StormerVerlet>(&mut s, h).map(|_| rhs += 3),
            Fixed::Midpoint => ImplicitMidpoint::step_with_memory(m, &mut memory1, &mut s, h)
                .map(|st| add(st, &mut rhs, &mut jac)),
            Fixed::Gauss => GaussLegendre2::step_with_memory(m, &mut memory2, &mut s, h)
                .map(|st| add(st, &mut rhs, &mut jac)),
            Fixed::Variational => Variational::step_with_stats(m, &mut s, h).map(|st| {
                // predictor, constraint test, final momentum rate, momenta; Newton iterations
                // evaluate with Jacobians.
                rhs += 4;
                jac += st.iterations + st.velocity_iterations;
            }),
        };
        r.map_err(|e| e.to_string())?;
        if track {
            let de = (m.energy(&s).map_err(|e| e.to_string())? - e0).abs();
            if de.is_nan() || de > setup.unstable_energy * (1.0 + e0.abs()) {
                return Err(format!(
                    "unstable (energy error {de:.2e} at t = {:.3})",
                    s.t
                ));
            }
            max_de = max_de.max(de);
        }
    }
    Ok((s.q.to_array(), s.v.to_array(), rhs, jac, max_de, n))
}

/// lagrange's adaptive methods.
#[derive(Clone, Copy, Debug)]
enum Adaptive {
    Dopri5,
    Dop853,
    Radau5,
}

impl Adaptive {
    fn name(self) -> &'static str {
        match self {
            Adaptive::Dopri5 => "Dopri5",
            Adaptive::Dop853 => "Dop853",
            Adaptive::Radau5 => "Radau5",
        }
    }
}

fn run_adaptive<M: Mechanism<N>, const N: usize>(
    setup: &Setup<M, N>,
    method: Adaptive,
    tol: f64,
    track: bool,
) -> RunResult<N> {
    let m = &setup.mechanism;
    let mut s = in_coordinates::<M, N>(&setup.start);
    let e0 = m.energy(&s).map_err(|e| e.to_string())?;
    let mut max_de = if track { 0.0f64 } else { f64::NAN };
    let observe = |o: lagrange_core::integrate::Observation<'_, M::Coords, N>| {
        if track {
            if let lagrange_core::integrate::Observation::Step { state, .. } = o {
                if let Ok(e) = m.energy(state) {
                    max_de = max_de.max((e - e0).abs());
                }
            }
        }
    };
    // Dop853 without its dense output (no events here; the peer's sparse output skips it too).
    let t_end = setup.t_end;
    let out = match method {
        Adaptive::Dop853 => {
            let settings = Dop853 {
                dense: false,
                ..Dop853::new(tol, tol)
            };
            Stepper::new(m, settings, &s).and_then(|mut r| r.integrate(t_end, &mut [], observe))
        }
        Adaptive::Dopri5 => Stepper::new(m, Dopri5::new(tol, tol), &s)
            .and_then(|mut r| r.integrate(t_end, &mut [], observe)),
        Adaptive::Radau5 => Stepper::new(m, Radau5::new(tol, tol), &s)
            .and_then(|mut r| r.integrate(t_end, &mut [], observe)),
    }
    .map_err(|e| e.to_string())?;
    s = out.state;
    Ok((
        s.q.to_array(),
        s.v.to_array(),
        out.stats.evaluations,
        out.stats.jacobians,
        max_de,
        out.stats.accepted,
    ))
}

/// The peer: `ode_solvers` Dopri5 / Dop853 on y = (q, v) with the hand-written accelerations.
struct Peer<const N: usize, const N2: usize> {
    rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
}

impl<const N: usize, const N2: usize> ode_solvers::System<f64, ode_solvers::SVector<f64, N2>>
    for Peer<N, N2>
{
    fn system(
        &self,
        t: f64,
        y: &ode_solvers::SVector<f64, N2>,
        dy: &mut ode_solvers::SVector<f64, N2>,
    ) {
        let q: [f64; N] = std::array::from_fn(|i| y[i]);
        let v: [f64; N] = std::array::from_fn(|i| y[N + i]);
        let a = (self.rhs)(t, &q, &v);
        for i in 0..N {
            dy[i] = v[i];
            dy[N + i] = a[i];
        }
    }
}

fn run_peer<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N>,
    dop853: bool,
    tol: f64,
    track: bool,
) -> RunResult<N> {
    assert_eq!(N2, 2 * N);
    let y0 = ode_solvers::SVector::<f64, N2>::from_fn(|i, _| {
        if i < N {
            setup.start.q[i]
        } else {
            setup.start.v[i - N]
        }
    });
    let (t0, t1) = (setup.start.t, setup.t_end);
    let peer = Peer::<N, N2> { rhs: setup.rhs };
    // The peer's own default controller constants (those of its `new`, Hairer's: Dopri5 safety 0.9,
    // β = 0.04, factors 0.2…10; Dop853 safety 0.9, β = 0, factors 0.333…6), automatic initial step,
    // step limit raised to 10⁷. Sparse output: the solution at every accepted step, so the end
    // point is the solver's own last step (its dense output was measured to be less accurate than
    // its steps at tight tolerances: with dense output at t_end alone its Dopri5 stalls near 1e-7).
    macro_rules! go {
        ($solver:ident, $beta:expr, $fac_min:expr, $fac_max:expr) => {{
            let mut solver = ode_solvers::$solver::from_param(
                peer,
                t0,
                t1,
                t1 - t0,
                y0,
                tol,
                tol,
                0.9,
                $beta,
                $fac_min,
                $fac_max,
                t1 - t0,
                0.0,
                10_000_000,
                1000,
                ode_solvers::OutputType::Sparse,
            );
            let stats = solver.integrate().map_err(|e| e.to_string())?;
            let ys = solver.y_out();
            let kept = if track {
                ys.clone()
            } else {
                ys.last().cloned().into_iter().collect()
            };
            (stats, kept)
        }};
    }
    let (stats, ys) = if dop853 {
        go!(Dop853, 0.0, 0.333, 6.0)
    } else {
        go!(Dopri5, 0.04, 0.2, 10.0)
    };
    let y = ys.last().ok_or("no output")?;
    let split = |y: &ode_solvers::SVector<f64, N2>| -> ([f64; N], [f64; N]) {
        (
            std::array::from_fn(|i| y[i]),
            std::array::from_fn(|i| y[N + i]),
        )
    };
    let (q, v) = split(y);
    let mut max_de = f64::NAN;
    if track {
        let m = &setup.mechanism;
        let e0 = m
            .energy(&in_coordinates::<M, N>(&setup.start))
            .map_err(|e| e.to_string())?;
        max_de = 0.0;
        for y in &ys {
            let (q, v) = split(y);
            if let Ok(e) = m.energy(&State::new(
                0.0,
                M::Coords::from_array(q),
                M::Coords::from_array(v),
            )) {
                max_de = max_de.max((e - e0).abs());
            }
        }
    }
    Ok((
        q,
        v,
        stats.num_eval as usize,
        0,
        max_de,
        stats.accepted_steps as usize,
    ))
}

fn record<const N: usize>(
    rows: &mut Vec<Row>,
    problem: &'static str,
    method: &str,
    setting: String,
    setting_value: f64,
    reference: &([f64; N], [f64; N]),
    (result, seconds): (RunResult<N>, f64),
) {
    let row = match result {
        Ok((q, v, rhs, jac, de, steps)) => Row {
            problem,
            method: method.to_string(),
            setting,
            setting_value,
            steps,
            rhs_evals: rhs,
            jacobian_evals: jac,
            seconds,
            end_error: distance(&q, &v, reference),
            max_energy_error: de,
            status: "ok".into(),
        },
        Err(e) => Row {
            problem,
            method: method.to_string(),
            setting,
            setting_value,
            steps: 0,
            rhs_evals: 0,
            jacobian_evals: 0,
            seconds,
            end_error: f64::NAN,
            max_energy_error: f64::NAN,
            status: e.replace(',', ";"),
        },
    };
    rows.push(row);
}

fn count_runs<M, const N: usize>(s: &Setup<M, N>) -> usize {
    let fixed = if s.constrained {
        3
    } else if s.verlet {
        5
    } else {
        4
    };
    let adaptive = if s.jacobian_times.is_some() { 7 } else { 5 };
    fixed * s.steps.len() + adaptive * s.tolerances.len()
}

/// One run of diffsol's `method` at `tol`; the energy along the way is not tracked (NaN).
fn run_diffsol<M: Mechanism<N>, const N: usize>(
    setup: &Setup<M, N>,
    method: diffsol_peer::Method,
    tol: f64,
) -> RunResult<N> {
    let jac = setup.jacobian_times.ok_or("no Jacobian-vector product")?;
    let s = &setup.start;
    let (q, v, evals, products, steps) =
        diffsol_peer::run(method, setup.rhs, jac, s.t, s.q, s.v, setup.t_end, tol)?;
    Ok((q, v, evals, products, f64::NAN, steps))
}

/// Whether a method is a peer's.
fn is_peer(method: &str) -> bool {
    method.starts_with("ode_solvers") || method.starts_with("diffsol")
}

/// Before any timing: each peer and lagrange's Dopri5 and Radau5 at tol 1e-8 from the same start,
/// their end states compared with each other (max-norm distance to lagrange's Radau5) and with
/// the reference. A peer that computed another problem would stand out by orders of magnitude.
fn peer_agreement<M: Mechanism<N>, const N: usize, const N2: usize>(setup: &Setup<M, N>) -> String {
    let tol = 1e-8;
    let ours = run_adaptive(setup, Adaptive::Radau5, tol, false);
    let Ok((q0, v0, ..)) = ours else {
        return format!("{}: lagrange Radau5 failed at tol 1e-8", setup.name);
    };
    let mut runs: Vec<(&str, RunResult<N>)> = vec![
        ("Dopri5", run_adaptive(setup, Adaptive::Dopri5, tol, false)),
        (
            "ode_solvers Dopri5",
            run_peer::<M, N, N2>(setup, false, tol, false),
        ),
        (
            "ode_solvers Dop853",
            run_peer::<M, N, N2>(setup, true, tol, false),
        ),
    ];
    if setup.jacobian_times.is_some() {
        for m in [diffsol_peer::Method::Bdf, diffsol_peer::Method::Esdirk34] {
            runs.push((m.name(), run_diffsol(setup, m, tol)));
        }
    }
    let mut s = format!(
        "{}: at tol 1e-8, lagrange Radau5 ends {:.1e} from the reference; ",
        setup.name,
        distance(&q0, &v0, &setup.reference)
    );
    let parts: Vec<String> = runs
        .into_iter()
        .map(|(name, r)| match r {
            Ok((q, v, ..)) => format!(
                "{name} {:.1e} from Radau5 ({:.1e} from the reference)",
                distance(&q, &v, &(q0, v0)),
                distance(&q, &v, &setup.reference)
            ),
            Err(e) => format!("{name} failed ({e})"),
        })
        .collect();
    s.push_str(&parts.join(", "));
    s.push('.');
    s
}

fn run_setup<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N>,
    quick: bool,
    rows: &mut Vec<Row>,
    progress: &mut Progress,
) {
    let mut methods = vec![Fixed::Rk4, Fixed::Midpoint, Fixed::Gauss];
    if !setup.constrained {
        methods.push(Fixed::Variational);
        if setup.verlet {
            methods.push(Fixed::Verlet);
        }
    }
    for method in &methods {
        for &n in &setup.steps {
            progress.tick(&format!("{} / {} / n = {n}", setup.name, method.name()));
            let h = (setup.t_end - setup.start.t) / n as f64;
            let r = measure(quick, |track| run_fixed(setup, method, n, track));
            record(
                rows,
                setup.name,
                method.name(),
                format!("h = {h:.3e}"),
                h,
                &setup.reference,
                r,
            );
        }
    }
    for &tol in &setup.tolerances {
        for method in [Adaptive::Dopri5, Adaptive::Dop853, Adaptive::Radau5] {
            let name = method.name();
            progress.tick(&format!("{} / {name} / tol = {tol:.1e}", setup.name));
            let r = measure(quick, |track| run_adaptive(setup, method, tol, track));
            record(
                rows,
                setup.name,
                name,
                format!("tol = {tol:.1e}"),
                tol,
                &setup.reference,
                r,
            );
        }
        for (dop853, name) in [(false, "ode_solvers Dopri5"), (true, "ode_solvers Dop853")] {
            progress.tick(&format!("{} / {name} / tol = {tol:.1e}", setup.name));
            let r = measure(quick, |track| {
                run_peer::<M, N, N2>(setup, dop853, tol, track)
            });
            record(
                rows,
                setup.name,
                name,
                format!("tol = {tol:.1e}"),
                tol,
                &setup.reference,
                r,
            );
        }
        if setup.jacobian_times.is_some() {
            for method in [diffsol_peer::Method::Bdf, diffsol_peer::Method::Esdirk34] {
                let name = method.name();
                progress.tick(&format!("{} / {name} / tol = {tol:.1e}", setup.name));
                let r = measure(quick, |_| run_diffsol(setup, method, tol));
                record(
                    rows,
                    setup.name,
                    name,
                    format!("tol = {tol:.1e}"),
                    tol,
                    &setup.reference,
                    r,
                );
            }
        }
    }
}

fn ladder(start: usize, count: usize) -> Vec<usize> {
    (0..count).map(|k| start << k).collect()
}

/// The adaptive methods' tolerances, the same for every method and peer: half-decades from 1e-3
/// to 1e-13 (so that the cheapest run reaching an accuracy is not decided by where a decade grid
/// falls for each method), or four decades with `--quick`.
fn tolerances(quick: bool) -> Vec<f64> {
    if quick {
        return [4, 7, 10, 13].map(|e| 10f64.powi(-e)).to_vec();
    }
    // 10^(−k/2): the decades as 10^(−k/2) by powi, the half-decades those divided by √10.
    (6..=26)
        .map(|k: i32| {
            let decade = 10f64.powi(-(k / 2));
            if k % 2 == 0 {
                decade
            } else {
                decade / 10f64.sqrt()
            }
        })
        .collect()
}

fn main() {
    let Args {
        quick,
        out,
        dop853_steps,
    } = Args::parse();
    let out_dir = out;
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let n_ladder = if quick { 4 } else { 8 };

    // 1. Large-amplitude pendulum over one period 4K(k).
    let period = 4.0 * elliptic_k(PENDULUM_K);
    let pendulum = Setup {
        name: "pendulum k=0.999",
        mechanism: PENDULUM.validated().expect("valid parameters"),
        start: State::new(0.0, [0.0], [2.0 * PENDULUM_K]),
        t_end: period,
        reference: pendulum_exact(period),
        rhs: pendulum_rhs,
        steps: ladder(200, n_ladder),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
    };
    // 2. Kepler e = 0.6 over 5 periods.
    let kepler = Setup {
        name: "Kepler e=0.6",
        mechanism: kepler::KEPLER.validated().expect("valid parameters"),
        start: kepler_start(),
        t_end: 10.0 * std::f64::consts::PI,
        reference: kepler_exact(10.0 * std::f64::consts::PI),
        rhs: kepler_rhs,
        steps: ladder(250, n_ladder + 1),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
    };
    // 3. Double pendulum, both arms horizontal at rest, to t = 10; reference by two methods.
    let dp_start = State::new(0.0, [std::f64::consts::FRAC_PI_2; 2], [0.0; 2]);
    let dp_t = 10.0;
    let ref_a = Stepper::new(
        &DOUBLE_PENDULUM,
        Dopri5::new(1e-14, 1e-14),
        &in_coordinates::<double_pendulum::DoublePendulum, 2>(&dp_start),
    )
    .and_then(|mut r| r.integrate(dp_t, &mut [], |_| {}))
    .expect("reference")
    .state;
    let mut ref_b = in_coordinates::<double_pendulum::DoublePendulum, 2>(&dp_start);
    let n_ref = 1 << 17;
    for _ in 0..n_ref {
        DOUBLE_PENDULUM
            .step::<GaussLegendre2>(&mut ref_b, dp_t / n_ref as f64)
            .expect("reference");
    }
    let (ref_a, ref_b) = (
        (ref_a.q.to_array(), ref_a.v.to_array()),
        (ref_b.q.to_array(), ref_b.v.to_array()),
    );
    let reference_agreement = distance(&ref_a.0, &ref_a.1, &ref_b);
    let double = Setup {
        name: "double pendulum",
        mechanism: DOUBLE_PENDULUM.validated().expect("valid parameters"),
        start: dp_start,
        t_end: dp_t,
        reference: ref_a,
        rhs: double_pendulum_rhs,
        steps: ladder(250, n_ladder),
        tolerances: tolerances(quick),
        verlet: false,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
    };
    // 4. FPU chain to t = 10 (hω = 2 at n = 250); reference Dopri5 1e-14, checked by GL2.
    let fpu_t = 10.0;
    let fpu_ref = Stepper::new(
        &FPU,
        Dopri5::new(1e-14, 1e-14),
        &in_coordinates::<fpu_chain::Fpu, 6>(&fpu_start()),
    )
    .and_then(|mut r| r.integrate(fpu_t, &mut [], |_| {}))
    .expect("reference")
    .state;
    let mut fpu_ref_b = in_coordinates::<fpu_chain::Fpu, 6>(&fpu_start());
    for _ in 0..n_ref {
        FPU.step::<GaussLegendre2>(&mut fpu_ref_b, fpu_t / n_ref as f64)
            .expect("reference");
    }
    let (fpu_ref, fpu_ref_b) = (
        (fpu_ref.q.to_array(), fpu_ref.v.to_array()),
        (fpu_ref_b.q.to_array(), fpu_ref_b.v.to_array()),
    );
    let fpu_agreement = distance(&fpu_ref.0, &fpu_ref.1, &fpu_ref_b);
    let fpu = Setup {
        name: "FPU chain w=50",
        mechanism: FPU.validated().expect("valid parameters"),
        start: fpu_start(),
        t_end: fpu_t,
        reference: fpu_ref,
        rhs: fpu_rhs,
        steps: ladder(100, n_ladder + 1),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 1.0,
    };
    // 5. Wedge and block until shortly before the block reaches the floor.
    let wedge_t = 0.9 * wedge_floor_time();
    let wedge = Setup {
        name: "wedge and block",
        mechanism: WedgeBlock.validated().expect("valid parameters"),
        start: State::new(0.0, [0.0, 0.0], [0.0, 0.0]),
        t_end: wedge_t,
        reference: wedge_exact(wedge_t),
        rhs: wedge_rhs,
        steps: ladder(10, if quick { 3 } else { 5 }),
        tolerances: tolerances(true),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
    };

    // 6. Stiff chain (ω up to 2613) along its slow mode to t = 10: closed form.
    let chain_t = 10.0;
    let chain = Setup {
        name: "stiff chain w=2613",
        mechanism: CHAIN.validated().expect("valid parameters"),
        start: chain_start(),
        t_end: chain_t,
        reference: chain_exact(chain_t),
        rhs: chain_rhs,
        steps: ladder(25, n_ladder + 2),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: Some(chain_jacobian_times),
        unstable_energy: 10.0,
    };
    // 7. Cartesian pendulum (one constraint) over one period 4K(k): closed form.
    let cartesian = Setup {
        name: "Cartesian pendulum k=0.999",
        mechanism: ROD.validated().expect("valid parameters"),
        start: cartesian_start(),
        t_end: period,
        reference: cartesian_exact(period),
        rhs: cartesian_rhs,
        steps: ladder(200, n_ladder),
        tolerances: tolerances(quick),
        verlet: false,
        constrained: true,
        jacobian_times: None,
        unstable_energy: 10.0,
    };

    if dop853_steps {
        let parts = [
            dop853_steps::table::<_, 1, 2>(&pendulum),
            dop853_steps::table::<_, 2, 4>(&kepler),
            dop853_steps::table::<_, 2, 4>(&double),
            dop853_steps::table::<_, 6, 12>(&fpu),
            dop853_steps::table::<_, 2, 4>(&wedge),
            dop853_steps::table::<_, 4, 8>(&chain),
            dop853_steps::table::<_, 2, 4>(&cartesian),
        ];
        print!("{}", dop853_steps::HEADER);
        for (rows, _) in &parts {
            print!("{rows}");
        }
        println!(
            "\nFewest evaluations of a run reaching the accuracy ({}):\n",
            dop853_steps::VARIANTS.join(" / ")
        );
        println!("| problem | ≤ 1e-6 | ≤ 1e-10 |\n|---|---|---|");
        let show = |c: [Option<usize>; 3]| {
            c.map(|e| e.map_or("–".to_string(), |e| e.to_string()))
                .join(" / ")
        };
        for ((_, cheapest), name) in parts.iter().zip([
            pendulum.name,
            kepler.name,
            double.name,
            fpu.name,
            wedge.name,
            chain.name,
            cartesian.name,
        ]) {
            let at = |k: usize| show([cheapest[0][k], cheapest[1][k], cheapest[2][k]]);
            println!("| {name} | {} | {} |", at(0), at(1));
        }
        return;
    }
    let load_before = load_average();
    let agreement = [
        peer_agreement::<_, 2, 4>(&kepler),
        peer_agreement::<_, 2, 4>(&double),
        peer_agreement::<_, 6, 12>(&fpu),
        peer_agreement::<_, 4, 8>(&chain),
        peer_agreement::<_, 2, 4>(&cartesian),
    ];
    let total = count_runs(&pendulum)
        + count_runs(&kepler)
        + count_runs(&double)
        + count_runs(&fpu)
        + count_runs(&wedge)
        + count_runs(&chain)
        + count_runs(&cartesian);
    let mut progress = Progress::new(total);
    let mut rows = Vec::new();
    run_setup::<_, 1, 2>(&pendulum, quick, &mut rows, &mut progress);
    run_setup::<_, 2, 4>(&kepler, quick, &mut rows, &mut progress);
    run_setup::<_, 2, 4>(&double, quick, &mut rows, &mut progress);
    run_setup::<_, 6, 12>(&fpu, quick, &mut rows, &mut progress);
    run_setup::<_, 2, 4>(&wedge, quick, &mut rows, &mut progress);
    run_setup::<_, 4, 8>(&chain, quick, &mut rows, &mut progress);
    run_setup::<_, 2, 4>(&cartesian, quick, &mut rows, &mut progress);
    progress.finish();
    let load_after = load_average();

    // Long run: energy error against time on Kepler over 1000 periods.
    eprintln!("long run: Kepler energy over 1000 periods");
    let long = plot::kepler_long_run(if quick { 100 } else { 1000 });

    write_csv(&out_dir, &rows);
    let (omega, _) = chain_modes();
    let notes = format!(
        "Machine load (`uptime`'s load averages over 1, 5 and 15 minutes) before the runs: {load_before}; \
         after: {load_after}.\n\n\
         Double-pendulum reference: Dopri5 at tol 1e-14 and Gauss–Legendre 2 with 2^17 steps agree to \
         {reference_agreement:.1e} at t = 10. FPU reference: the same two methods agree to {fpu_agreement:.1e}. \
         Stiff chain: four unit masses, the first on a soft spring (k = 1) to a wall, neighbours joined by \
         stiff springs (k = 2e6): mode frequencies {:.3}, {:.0}, {:.0}, {:.0}; started along the slow mode, \
         closed form x(t) = φ(cos ωt + sin ωt). Cartesian pendulum: (x, y) with |r| = 1 as a constraint \
         (its force in q̈; every step projected), closed form from the angle's Jacobi-elliptic solution.\n\n\
         Same answers before timing:\n\n- {}\n",
        omega[0],
        omega[1],
        omega[2],
        omega[3],
        agreement.join("\n- ")
    );
    write_markdown(&out_dir, &rows, &notes, quick);
    for problem in [
        "pendulum k=0.999",
        "Kepler e=0.6",
        "double pendulum",
        "FPU chain w=50",
        "wedge and block",
        "stiff chain w=2613",
        "Cartesian pendulum k=0.999",
    ] {
        plot::work_precision(&out_dir, problem, &rows);
    }
    plot::energy_long_run(&out_dir, &long);
    eprintln!("wrote {}", out_dir.display());
}

/// A ratio with two decimals, or two significant digits below 0.1.
fn factor(x: f64) -> String {
    if x < 0.1 {
        format!("{x:.1e}")
    } else {
        format!("{x:.2}")
    }
}

/// The load averages, or "unknown".
fn load_average() -> String {
    load::load_averages(", ").unwrap_or_else(|| "unknown".into())
}

/// `results.csv`: one record per run. Fields are quoted where they need it (a failed run's status
/// is an error message, which may hold commas and quotes).
fn write_csv(dir: &std::path::Path, rows: &[Row]) {
    let mut w = csv::Writer::from_path(dir.join("results.csv")).expect("create results.csv");
    w.write_record([
        "problem",
        "method",
        "setting",
        "steps",
        "rhs_evals",
        "jacobian_evals",
        "seconds",
        "end_error",
        "max_energy_error",
        "status",
    ])
    .expect("write csv");
    for r in rows {
        w.write_record([
            r.problem.to_string(),
            r.method.clone(),
            r.setting.clone(),
            r.steps.to_string(),
            r.rhs_evals.to_string(),
            r.jacobian_evals.to_string(),
            format!("{:.6e}", r.seconds),
            format!("{:.3e}", r.end_error),
            format!("{:.3e}", r.max_energy_error),
            r.status.clone(),
        ])
        .expect("write csv");
    }
    w.flush().expect("write csv");
}

/// The cheapest (fastest) run reaching `target` end-point error on `problem`.
/// Which runs a summary cell chooses from.
#[derive(Clone, Copy, PartialEq)]
enum Among {
    All,
    Ours,
    Peers,
}

/// The cheapest (fastest) run reaching `target` end-point error on `problem` among `among`.
fn cheapest<'a>(rows: &'a [Row], problem: &str, target: f64, among: Among) -> Option<&'a Row> {
    rows.iter()
        .filter(|r| r.problem == problem && r.status == "ok" && r.end_error <= target)
        .filter(|r| match among {
            Among::All => true,
            Among::Ours => !is_peer(&r.method),
            Among::Peers => is_peer(&r.method),
        })
        .min_by(|a, b| a.seconds.total_cmp(&b.seconds))
}

fn write_markdown(dir: &std::path::Path, rows: &[Row], notes: &str, quick: bool) {
    let mut s = String::from("# Work-precision report\n\n");
    let _ = writeln!(
        s,
        "Generated by `cargo run --release -p lagrange-bench --bin work-precision{}`. Errors are max-norm \
         over (q, v) at the end time; energy errors are max |E − E₀| over the steps of the run; times are the \
         minimum wall time over repeats after a warm-up. Rows with a status other than `ok` failed (the error is \
         given). lagrange's methods run on validated handles (`mechanism.validated()`), as a simulation \
         would: the parameters are checked once, and the problems whose positions are affine in q (the \
         FPU chain, the wedge, the stiff chain) have J and the factors of their constant mass matrix \
         prepared once. The pendulum, Kepler, the double pendulum, the FPU chain, the stiff chain and \
         the Cartesian pendulum are `#[mechanism]` declarations (the pendulums' equations derived by the \
         macro in closed form, their constant factors prepared once; the potentials' gradients of Kepler, \
         the FPU chain (its seven springs each a potential of its own) and the stiff chain derived by the \
         macro on their expression trees); the wedge is a hand-written `Model`. The adaptive methods, \
         lagrange's and the peers' alike, run at rtol = atol = tol over the same grid of tolerances, \
         half-decades from 1e-3 to 1e-13 (four decades with `--quick`).\n",
        if quick { " -- --quick" } else { "" }
    );
    let _ = writeln!(s, "{notes}\n");
    s.push_str(
        "## Cheapest method per accuracy\n\nFastest run reaching the end-point error, among all methods (peers \
         included) and among lagrange's own (with its right-hand-side evaluations and, for the implicit \
         methods, Jacobian evaluations), and the ratio of lagrange's cheapest time to the cheapest peer's \
         (below 1: lagrange is faster; above 1: the peer is, by that factor), split into the ratio of their \
         right-hand-side evaluations and the ratio of their times per evaluation. With 2 cores shared with \
         other work (the load averages above), single timings can be off by a factor of a few; the evaluation \
         counts are exact.\n\n| problem | accuracy | \
         cheapest overall | lagrange's cheapest | lagrange / best peer |\n|---|---|---|---|---|\n",
    );
    let problems: Vec<&str> = {
        let mut p: Vec<&str> = Vec::new();
        for r in rows {
            if !p.contains(&r.problem) {
                p.push(r.problem);
            }
        }
        p
    };
    for p in &problems {
        let cell = |target, among| match cheapest(rows, p, target, among) {
            Some(r) => format!(
                "{} ({}), {:.2e} s, {} evaluations{}",
                r.method,
                r.setting,
                r.seconds,
                r.rhs_evals,
                if r.jacobian_evals > 0 {
                    format!(" + {} Jacobians", r.jacobian_evals)
                } else {
                    String::new()
                }
            ),
            None => "none reached it".into(),
        };
        for target in [1e-6, 1e-10] {
            let ratio = match (
                cheapest(rows, p, target, Among::Ours),
                cheapest(rows, p, target, Among::Peers),
            ) {
                (Some(ours), Some(peer)) => {
                    let r = ours.seconds / peer.seconds;
                    // Why: the ratio of evaluations and the ratio of time per evaluation (Jacobian
                    // evaluations of the implicit methods not counted), whose product is r.
                    let evals = ours.rhs_evals as f64 / peer.rhs_evals as f64;
                    let why = format!(
                        "evaluations ×{}, time per evaluation ×{}",
                        factor(evals),
                        factor(r / evals)
                    );
                    if r <= 1.0 {
                        format!("{r:.2} ({why})")
                    } else {
                        format!("**{r:.2}**: the peer is {r:.2}× faster ({why})")
                    }
                }
                (Some(_), None) => "no peer reached it".into(),
                _ => "—".into(),
            };
            let _ = writeln!(
                s,
                "| {p} | ≤ {target:.0e} | {} | {} | {ratio} |",
                cell(target, Among::All),
                cell(target, Among::Ours),
            );
        }
    }
    // Our Dopri5 against the peer's at rtol 1e-8 on the double pendulum.
    let find = |m: &str| {
        rows.iter().find(|r| {
            r.problem == "double pendulum"
                && r.method == m
                && (r.setting_value - 1e-8).abs() < 1e-20
        })
    };
    if let (Some(a), Some(b)) = (find("Dopri5"), find("ode_solvers Dopri5")) {
        let _ = writeln!(
            s,
            "\nDouble pendulum, tol 1e-8: lagrange Dopri5 {:.3e} s (error {:.2e}, {} evaluations) vs ode_solvers \
             Dopri5 {:.3e} s (error {:.2e}, {} evaluations): time ratio {:.2}, error ratio {:.2}.\n",
            a.seconds,
            a.end_error,
            a.rhs_evals,
            b.seconds,
            b.end_error,
            b.rhs_evals,
            a.seconds / b.seconds,
            a.end_error / b.end_error
        );
    }
    for p in &problems {
        let _ = writeln!(
            s,
            "\n## {p}\n\n![work-precision](./{}.svg)\n",
            plot::slug(p)
        );
        s.push_str("| method | setting | steps | rhs evals | Jacobian evals | time [s] | end error | max energy error | status |\n|---|---|---|---|---|---|---|---|---|\n");
        for r in rows.iter().filter(|r| r.problem == *p) {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {:.3e} | {:.2e} | {:.2e} | {} |",
                r.method,
                r.setting,
                r.steps,
                r.rhs_evals,
                r.jacobian_evals,
                r.seconds,
                r.end_error,
                r.max_energy_error,
                r.status
            );
        }
    }
    s.push_str("\n## Long run\n\n![energy](./kepler-energy-long-run.svg)\n");
    std::fs::write(dir.join("report.md"), s).expect("write markdown");
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

    #[test]
    fn csv_fields_with_commas_and_quotes_round_trip() {
        let row = |status: &str| Row {
            problem: "Kepler e=0.6",
            method: "Dopri5".into(),
            setting: "tol = 1e-6".into(),
            setting_value: 1e-6,
            steps: 12,
            rhs_evals: 80,
            jacobian_evals: 0,
            seconds: 1.5e-4,
            end_error: 2.5e-7,
            max_energy_error: f64::NAN,
            status: status.into(),
        };
        let failed = "step size underflow at t = 1, h = 1e-300: \"singular\"";
        let dir = std::env::temp_dir().join(format!("lagrange-bench-csv-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        write_csv(&dir, &[row("ok"), row(failed)]);
        let mut reader = csv::Reader::from_path(dir.join("results.csv")).unwrap();
        assert_eq!(reader.headers().unwrap().len(), 10);
        let records: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
        assert_eq!(records.len(), 2);
        assert_eq!(&records[0][9], "ok");
        assert_eq!(&records[1][9], failed);
        assert_eq!(&records[1][2], "tol = 1e-6");
        assert_eq!(records[1][7].parse::<f64>().unwrap(), 2.5e-7);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
