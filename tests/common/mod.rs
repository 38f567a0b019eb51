//! What several test files share: the gallery's simple pendulum, its first passage through the
//! bottom carried with its sensitivities, the plain RK4 run a tangent is compared with, and the
//! check of sensitivities against finite differences.

use lagrange::evaluation::Evaluate;
use lagrange::integrate::Fixed;
use lagrange::parameters::Parametrized;
use lagrange::prelude::*;
use lagrange::sensitivity::{Seed, SeededTangent, Sensitivities};
pub use lagrange_gallery::scenes::pendulum::pendulum;

/// A solver of the mechanism (or handle) `M` with RK4 steps carrying the tangent of its trajectory.
pub type Tangent<'m, M, const N: usize, const K: usize, const NP: usize, const P: usize> =
    Stepper<'m, M, Fixed<Rk4>, N, SeededTangent<'m, <M as Evaluate<N>>::Model, N, K, NP, P>>;

/// RK4 steps of `h` from `s0` carried with the sensitivities along `seeds` (no dense output).
pub fn rk4_tangent<'m, M, const N: usize, const K: usize, const NP: usize, const P: usize>(
    sys: &'m M,
    s0: &State<<M as Evaluate<N>>::Coords>,
    seeds: [Seed; P],
    h: f64,
) -> lagrange::Result<Tangent<'m, M, N, K, NP, P>>
where
    M: Evaluate<N>,
    M::Model: Parametrized<N, K, NP>,
{
    Stepper::new(sys, Fixed::<Rk4>::new(h).without_dense(), s0)?.with_sensitivities(seeds)
}

/// Carries `run`, a tangent of the pendulum `sys` started at θ > 0, to its first passage through
/// θ = 0: whole RK4 steps of `h` while θ stays positive, then the partial step τ that lands on
/// θ = 0, found by the secant method on the plain RK4 step (θ(τ) is smooth in τ). Returns the
/// sensitivities there.
pub fn first_passage<'m, M, const K: usize, const NP: usize, const P: usize>(
    sys: &'m M,
    mut run: Tangent<'m, M, 1, K, NP, P>,
    h: f64,
) -> Sensitivities<pendulum::Coords, P>
where
    M: Evaluate<1, Coords = pendulum::Coords>,
    M::Model: Parametrized<1, K, NP>,
{
    loop {
        let mut next = run.clone();
        next.step(f64::INFINITY).unwrap();
        if next.state().q.theta <= 0.0 {
            break;
        }
        run = next;
    }
    let theta_after = |tau: f64| {
        let mut s = run.state();
        sys.step::<Rk4>(&mut s, tau).unwrap();
        s.q.theta
    };
    let (mut a, mut b): (f64, f64) = (0.5 * h, h);
    let (mut fa, mut fb) = (theta_after(a), theta_after(b));
    for _ in 0..50 {
        if fb == 0.0 || (b - a).abs() < 1e-16 {
            break;
        }
        let c = b - fb * (b - a) / (fb - fa);
        (a, fa) = (b, fb);
        (b, fb) = (c, theta_after(c));
    }
    run.step(run.t() + b).unwrap();
    run.sensitivities()
}

/// The tangent of the two-coordinate `sys` from `s0`, seeded on `seeds`, after `steps` RK4 steps
/// of `h`: its real parts x = (q₁, q₂, q̇₁, q̇₂) and, per seed j, their derivatives ∂x/∂(seed j).
pub fn rk4_tangent_end<M, const K: usize, const NP: usize, const P: usize>(
    sys: &M,
    s0: State<<M as Evaluate<2>>::Coords>,
    seeds: [Seed; P],
    h: f64,
    steps: usize,
) -> ([f64; 4], Vec<[f64; 4]>)
where
    M: Evaluate<2>,
    M::Model: Parametrized<2, K, NP>,
{
    let mut run = rk4_tangent(sys, &s0, seeds, h).unwrap();
    for _ in 0..steps {
        run.step(f64::INFINITY).unwrap();
    }
    let ad = run.sensitivities();
    let row = |q: <M as Evaluate<2>>::Coords, v: <M as Evaluate<2>>::Coords| {
        let ([q1, q2], [v1, v2]) = (q.to_array(), v.to_array());
        [q1, q2, v1, v2]
    };
    let jacobian = (0..P).map(|j| row(ad.dq[j], ad.dv[j])).collect();
    (row(ad.state.q, ad.state.v), jacobian)
}

/// The plain RK4 run of the two-coordinate `sys` from `s0`: (q₁, q₂, q̇₁, q̇₂) after `steps` steps
/// of `h`.
pub fn rk4_end<M: Evaluate<2>>(
    sys: &M,
    s0: State<<M as Evaluate<2>>::Coords>,
    h: f64,
    steps: usize,
) -> [f64; 4] {
    let mut s = s0;
    sys.simulate::<Rk4>(&mut s, h, steps, |_| {}).unwrap();
    let ([q1, q2], [v1, v2]) = (s.q.to_array(), s.v.to_array());
    [q1, q2, v1, v2]
}

/// Checks forward-mode sensitivities of an end state against finite differences of the same
/// discrete map, to the differences' own error, and returns the worst ratio of the difference to
/// that error estimate (printed by the callers).
///
/// `jacobian[j][i]` is ∂xᵢ/∂(seed j) by dual numbers, `plain` the end state x of the plain run of
/// `steps` steps, `central(j, δ)` the central difference (x(+δ) − x(−δ))/(2δ) along seed j, and
/// `labels[j]` names seed j in messages. The error estimate:
/// - truncation: the central difference D(δ) has error c₂δ² + c₄δ⁴ + …; the Richardson combination
///   R(δ) = (4 D(δ/2) − D(δ))/3 removes c₂, so R(δ/2) is off by about |R(δ) − R(δ/2)|/15;
/// - round-off: each of the n steps rounds the state at relative ε; such an error propagates like a
///   perturbation of the initial value, amplified at most by 1 + the largest sensitivity, and n of
///   them add like a random walk: ε max(|x|, 1)(1 + |J|max)√n in each end value, divided by the
///   increment δ/4 and amplified 5/3 by the Richardson combination.
///
/// Each derivative must lie within 3 estimates of R(δ/2), δ = 1e-3.
pub fn check_against_finite_differences<const X: usize>(
    jacobian: &[[f64; X]],
    labels: &[String],
    plain: [f64; X],
    steps: usize,
    central: impl Fn(usize, f64) -> [f64; X],
) -> f64 {
    let largest = jacobian
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let delta = 1e-3;
    let mut worst: f64 = 0.0;
    for (j, row) in jacobian.iter().enumerate() {
        let d = [
            central(j, delta),
            central(j, delta / 2.0),
            central(j, delta / 4.0),
        ];
        for i in 0..X {
            let coarse = (4.0 * d[1][i] - d[0][i]) / 3.0;
            let fine = (4.0 * d[2][i] - d[1][i]) / 3.0;
            let truncation = (coarse - fine).abs() / 15.0;
            let round_off =
                f64::EPSILON * plain[i].abs().max(1.0) * (1.0 + largest) * (steps as f64).sqrt()
                    / (delta / 4.0)
                    * (5.0 / 3.0);
            let estimate = truncation + round_off;
            let error = (row[i] - fine).abs();
            worst = worst.max(error / estimate);
            assert!(
                error <= 3.0 * estimate,
                "∂x{i}/∂{}: AD {:e}, FD {fine:e}, differs by {error:e} > 3 × the FD error estimate {estimate:e}",
                labels[j],
                row[i],
            );
        }
    }
    eprintln!("largest sensitivity {largest:.2}; worst |AD − FD| / FD error estimate: {worst:.3}");
    worst
}
