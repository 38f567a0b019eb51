//! Identifying a pendulum from a measurement: its length L and the viscous friction c in its pivot
//! are fitted to sampled angles θ(tᵢ) by Gauss–Newton, with the Jacobian ∂θ(tᵢ)/∂(L, c) taken from
//! one sensitivity run per iteration (`lagrange::sensitivity`, `Seed::Parameter`) instead of finite
//! differences. The measurement is a simulation at known parameters, so the fit must recover them.
//!
//! Gauss–Newton (Nocedal & Wright, *Numerical Optimization*, 2nd ed., §10.3): with residuals
//! rᵢ(p) = θ(tᵢ; p) − θᵢ and J = ∂r/∂p, the step solves JᵀJ Δp = −Jᵀr. On a zero-residual problem
//! it converges quadratically near the solution.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use lagrange::sensitivity::Seed;
use lagrange::Fixed;
use nalgebra::{Matrix2, Vector2};
use std::path::Path;

#[mechanism]
pub mod damped_pendulum {
    /// Angle from the downward vertical.
    pub struct Coords {
        pub theta: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct DampedPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        /// Viscous friction in the pivot (torque −c θ̇).
        pub c: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[generalized_force(on = theta)]
    fn friction() -> f64 {
        -c * theta_dot
    }
}

use damped_pendulum::{Coords, DampedPendulum, State};

const SCENE: &str = "identify a pendulum's length and friction";
/// RK4 step of the simulation and of the measurement.
const H: f64 = 1e-3;
/// Steps between samples (a sample every 0.05 s) and samples (3 s).
const STRIDE: usize = 50;
const SAMPLES: usize = 60;

/// θ(tᵢ) at every sample, and ∂θ(tᵢ)/∂(L, c), from one RK4 run carried on dual numbers.
pub fn trajectory(sys: &DampedPendulum, s0: &State) -> lagrange::Result<(Vec<f64>, Vec<[f64; 2]>)> {
    let seeds = [Seed::Parameter("l"), Seed::Parameter("c")];
    let rk4 = Fixed::<Rk4>::new(H).without_dense();
    let mut run = Stepper::new(sys, rk4, s0)?.with_sensitivities(seeds)?;
    let (mut theta, mut jacobian) = (Vec::new(), Vec::new());
    for _ in 0..SAMPLES {
        for _ in 0..STRIDE {
            run.step(f64::INFINITY)?;
        }
        let out = run.sensitivities();
        theta.push(out.state.q.theta);
        jacobian.push([out.dq[0].theta, out.dq[1].theta]);
    }
    Ok((theta, jacobian))
}

/// The fit: the parameters after each Gauss–Newton iteration (the first entry is the guess).
#[derive(Clone, Debug)]
pub struct Fit {
    /// (L, c) after each iteration.
    pub history: Vec<[f64; 2]>,
}

impl Fit {
    /// The fitted (L, c).
    pub fn parameters(&self) -> [f64; 2] {
        *self.history.last().expect("the guess is the first entry")
    }

    /// Gauss–Newton iterations taken.
    pub fn iterations(&self) -> usize {
        self.history.len() - 1
    }
}

/// Fits (L, c) of `sys` to `measured` angles from `s0`, starting at `sys`'s values; stops when a
/// step changes both by less than 1e-13 relative, or after 20 iterations.
pub fn identify(sys: DampedPendulum, s0: &State, measured: &[f64]) -> lagrange::Result<Fit> {
    let mut p = Vector2::new(sys.l, sys.c);
    let mut history = vec![[p[0], p[1]]];
    for _ in 0..20 {
        let guess = DampedPendulum {
            l: p[0],
            c: p[1],
            ..sys
        };
        let (theta, jacobian) = trajectory(&guess, s0)?;
        let (mut normal, mut gradient) = (Matrix2::zeros(), Vector2::zeros());
        for ((&th, &target), row) in theta.iter().zip(measured).zip(&jacobian) {
            let j = Vector2::new(row[0], row[1]);
            normal += j * j.transpose();
            gradient += j * (th - target);
        }
        let step = normal
            .lu()
            .solve(&(-gradient))
            .ok_or(lagrange::Error::UnsuitableMethod {
                method: "Gauss–Newton",
                reason: "the samples do not determine both parameters (JᵀJ is singular)"
                    .to_string(),
            })?;
        p += step;
        history.push([p[0], p[1]]);
        if step[0].abs() <= 1e-13 * p[0].abs() && step[1].abs() <= 1e-13 * p[1].abs() {
            break;
        }
    }
    Ok(Fit { history })
}

pub fn run(plots: &Path) -> Vec<Check> {
    let truth = DampedPendulum {
        m: 0.5,
        l: 0.75,
        g: 9.81,
        c: 0.04,
    };
    let s0 = State::at_rest(Coords { theta: 1.0 });
    let (measured, _) = trajectory(&truth, &s0).expect("measurement");
    let guess = DampedPendulum {
        l: 1.0,
        c: 0.1,
        ..truth
    };
    let fit = identify(guess, &s0, &measured).expect("fit");
    let [l, c] = fit.parameters();
    println!(
        "{SCENE}: from L = {:.3} m, c = {:.3} N·m·s to L = {l:.12} m, c = {c:.12} N·m·s in {} \
         Gauss–Newton iterations (each one sensitivity run)",
        guess.l,
        guess.c,
        fit.iterations()
    );
    for (k, [l, c]) in fit.history.iter().enumerate() {
        println!(
            "    iteration {k}: L − L_true = {:+.3e}, c − c_true = {:+.3e}",
            l - truth.l,
            c - truth.c
        );
    }
    // The animation: the fitted pendulum over the measured 3 s.
    let fitted = DampedPendulum { l, c, ..truth };
    let mut film = Recorder::new(&fitted).title(format!("{SCENE}: the fitted pendulum"));
    film.fixed_point("pivot", &[0.0, 0.0])
        .and_then(|f| f.link("pivot", "bob")?.trail("bob"))
        .expect("the pivot");
    let mut s = s0;
    if film.push(&fitted, &s).is_ok()
        && fitted
            .simulate::<Rk4>(&mut s, H, SAMPLES * STRIDE, film.observer(&fitted))
            .is_ok()
    {
        let _ = film.write_html(plots.join("identify_pendulum.html"));
    }
    let times: Vec<f64> = (1..=SAMPLES).map(|i| (i * STRIDE) as f64 * H).collect();
    let (at_guess, _) = trajectory(&guess, &s0).expect("guess");
    let series = |label: &str, values: &[f64]| {
        Series::new(
            label,
            times.iter().copied().zip(values.iter().copied()).collect(),
        )
    };
    let _ = plot::lines(
        &plots.join("identify_pendulum.svg"),
        "Fitting L and c to sampled angles",
        "t",
        "θ",
        &[
            series("measured θ(tᵢ)", &measured),
            series("initial guess", &at_guess),
        ],
    );
    // The measurement is the same discrete map (RK4, h = 1e-3) at the true parameters, so the
    // least-squares minimum is the truth with zero residual; the fit stops at rounding: residuals
    // of ~1e-16 in θ move the parameters by ~1e-16 / (smallest singular value of J ≈ 1e-2), far
    // below the 1e-9 asserted.
    vec![
        Check::new(
            SCENE,
            "length L recovered by Gauss–Newton",
            l,
            truth.l,
            1e-9,
        ),
        Check::new(
            SCENE,
            "friction c recovered by Gauss–Newton",
            c,
            truth.c,
            1e-9,
        ),
    ]
}
