//! `work-precision --dop853-steps`: the steps of lagrange's `Dop853` under two controllers against
//! the `ode_solvers` peer's, on every problem and tolerance of the report — exact counts, no timing.
//!
//! Per run: accepted steps / rejected attempts / evaluations, and the end-point error (max norm over
//! q and v against the reference), of lagrange's `Dop853` without dense output (as in the report)
//! with β = 0.04 (a PI controller) and β = 0 (the classical controller, `dop853.f`'s default), then
//! the peer's (the report's settings, `dop853.f`'s defaults). The peer counts one evaluation more
//! than lagrange for the same steps (its initial-step routine evaluates f(t₀, y₀) once more), and
//! like `dop853.f` it does not count rejections before the first accepted step. Then, per problem
//! and accuracy, the fewest evaluations of a run reaching it (the report's "cheapest" criterion).

use crate::peer::PeerMethod;
use crate::setup::{distance, in_coordinates, split_qv, Problem, Rhs, Setup};
use lagrange_core::integrate::{Dop853, Stats, Stepper};
use lagrange_core::{Coordinates, Mechanism, State};
use std::fmt::Write as _;

/// (accepted, rejected, evaluations) and the end state (q, q̇) of one run, or why it failed.
type Run<const N: usize> = Result<((usize, usize, usize), ([f64; N], [f64; N])), String>;

/// lagrange's Dop853 with `settings` from `start` to `t_end`: its counts and end state.
fn ours<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    start: &State<[f64; N]>,
    t_end: f64,
    settings: Dop853,
) -> Run<N> {
    let start = in_coordinates::<M, N>(start);
    let out = Stepper::new(mechanism, settings, &start)
        .and_then(|mut solver| solver.integrate(t_end, &mut [], |_| {}))
        .map_err(|e| e.to_string())?;
    let state = out.state;
    let Stats {
        accepted,
        rejected,
        evaluations,
        ..
    } = out.stats;
    Ok((
        (accepted, rejected, evaluations),
        (state.q.to_array(), state.v.to_array()),
    ))
}

/// The `ode_solvers` Dop853 on the hand-written `rhs` at rtol = atol = `tol` with the report's
/// settings (`dop853.f`'s defaults): its counts and end state.
fn peer<const N: usize, const N2: usize>(
    rhs: Rhs<N>,
    start: &State<[f64; N]>,
    t_end: f64,
    tol: f64,
) -> Run<N> {
    let (stats, ys) =
        crate::peer::solve::<N, N2>(rhs, start, t_end, tol, PeerMethod::Dop853, false)?;
    let y = ys.last().ok_or("no output")?;
    Ok((
        (
            stats.accepted_steps as usize,
            stats.rejected_steps as usize,
            stats.num_eval as usize,
        ),
        split_qv(y.as_slice()),
    ))
}

fn cell<const N: usize>(run: &Run<N>, reference: &([f64; N], [f64; N])) -> String {
    match run {
        Ok(((a, r, e), (q, v))) => format!("{a} / {r} / {e}, {:.1e}", distance(q, v, reference)),
        Err(e) => format!("failed ({})", e.chars().take(40).collect::<String>()),
    }
}

/// The variants compared, in the columns' order.
const VARIANTS: [&str; 3] = ["Dop853 β = 0.04", "Dop853 β = 0", "ode_solvers Dop853"];

/// The table of one problem, as markdown rows, and per variant the fewest evaluations of a run
/// reaching an end error ≤ 1e-6 and ≤ 1e-10 (`None`: no run did).
pub fn table<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
) -> (String, [[Option<usize>; 2]; 3]) {
    let mut rows = String::new();
    let mut cheapest = [[None; 2]; 3];
    for &tol in &setup.tolerances {
        let base = Dop853 {
            dense: false,
            ..Dop853::new(tol, tol)
        };
        let (start, t_end) = (&setup.start, setup.t_end);
        let runs = [
            ours(
                &setup.mechanism,
                start,
                t_end,
                Dop853 { beta: 0.04, ..base },
            ),
            ours(&setup.mechanism, start, t_end, Dop853 { beta: 0.0, ..base }),
            peer::<N, N2>(setup.rhs, start, t_end, tol),
        ];
        let _ = write!(rows, "| {} | {tol:.1e} |", setup.name);
        for (run, best) in runs.iter().zip(&mut cheapest) {
            let _ = write!(rows, " {} |", cell(run, &setup.reference));
            if let Ok(((_, _, evaluations), (q, v))) = run {
                let err = distance(q, v, &setup.reference);
                for (accuracy, best) in [1e-6, 1e-10].into_iter().zip(best.iter_mut()) {
                    if err <= accuracy && best.is_none_or(|b| *evaluations < b) {
                        *best = Some(*evaluations);
                    }
                }
            }
        }
        rows.push('\n');
    }
    (rows, cheapest)
}

/// The header of [`table`]'s rows.
const HEADER: &str = "| problem | tol | Dop853 β = 0.04: accepted / rejected / evaluations, \
                          end error | Dop853 β = 0 | ode_solvers Dop853 |\n|---|---|---|---|---|\n";

/// The `--dop853-steps` output: every problem's table, then per problem and accuracy the fewest
/// evaluations of each variant.
pub fn print(problems: &[Box<dyn Problem>]) {
    let parts: Vec<_> = problems.iter().map(|p| p.dop853_steps()).collect();
    print!("{HEADER}");
    for (rows, _) in &parts {
        print!("{rows}");
    }
    println!(
        "\nFewest evaluations of a run reaching the accuracy ({}):\n",
        VARIANTS.join(" / ")
    );
    println!("| problem | ≤ 1e-6 | ≤ 1e-10 |\n|---|---|---|");
    let show = |c: [Option<usize>; 3]| {
        c.map(|e| e.map_or("–".to_string(), |e| e.to_string()))
            .join(" / ")
    };
    for ((_, cheapest), problem) in parts.iter().zip(problems) {
        let at = |k: usize| show([cheapest[0][k], cheapest[1][k], cheapest[2][k]]);
        println!("| {} | {} | {} |", problem.name(), at(0), at(1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pendulums::DOUBLE_PENDULUM;
    use crate::problems::{double_pendulum_rhs, kepler_rhs, kepler_start};

    /// lagrange's Dop853 with its default controller (`dop853.f`'s) on the report's declaration,
    /// and the peer with `dop853.f`'s defaults on the hand-written equations: the same accepted
    /// and rejected steps at every tolerance, and one evaluation fewer (the peer evaluates
    /// f(t₀, y₀) twice). The end states differ by round-off only: the two right-hand sides
    /// round differently, the steps are the same.
    fn same_steps_as_the_peer<M: Mechanism<N>, const N: usize, const N2: usize>(
        mechanism: &M,
        rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
        start: &State<[f64; N]>,
        t_end: f64,
    ) {
        for tol in [1e-4, 1e-7, 1e-10, 1e-13] {
            let settings = Dop853 {
                dense: false,
                ..Dop853::new(tol, tol)
            };
            let ((a, r, e), (q, v)) = ours(mechanism, start, t_end, settings).unwrap();
            let ((pa, pr, pe), end) = peer::<N, N2>(rhs, start, t_end, tol).unwrap();
            assert_eq!((a, r, e + 1), (pa, pr, pe), "tol {tol:.0e}");
            let d = distance(&q, &v, &end);
            // Round-off (≈ 1e-16 per evaluation, over up to 3000 of them) grown by the flow's
            // sensitivity over the run, not the method's error (≈ tol).
            assert!(d < 1e-9, "tol {tol:.0e}: end states {d:.1e} apart");
        }
    }

    #[test]
    fn double_pendulum_takes_the_peers_steps() {
        let start = State::new(0.0, [std::f64::consts::FRAC_PI_2; 2], [0.0; 2]);
        let sys = DOUBLE_PENDULUM.validated().unwrap();
        same_steps_as_the_peer::<_, 2, 4>(&sys, double_pendulum_rhs, &start, 10.0);
    }

    #[test]
    fn kepler_takes_the_peers_steps() {
        let sys = crate::kepler::KEPLER.validated().unwrap();
        let t_end = 10.0 * std::f64::consts::PI;
        same_steps_as_the_peer::<_, 2, 4>(&sys, kepler_rhs, &kepler_start(), t_end);
    }
}
