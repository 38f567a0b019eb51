//! What several test files share.

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
