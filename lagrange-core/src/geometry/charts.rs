//! Orientations with no singularity: a free body's rotation written in three coordinates that
//! switch chart before they reach one.
//!
//! No three coordinates cover the rotations without a singularity (Euler angles lose a degree of
//! freedom at gimbal lock). Two charts are given, each regular on a ball of rotation angles
//! θ ≤ π with margin, and a switch to an equivalent point of the same chart when a trajectory
//! leaves the ball ([`switch_chart`]): the integrators call it after every accepted step
//! ([`Dynamics::switch_charts`](crate::evaluation::Dynamics::switch_charts)), so within a step
//! the coordinates are ordinary Lagrangian coordinates and between steps they stay where the
//! chart is regular.
//!
//! - [`rot_vector`]: the rotation vector φ (exponential coordinates), R = exp(\[φ\]×), the
//!   rotation by θ = |φ| about φ/θ. Singular at θ = 2π; past θ = π the equivalent
//!   φ (1 − 2π/θ) (angle 2π − θ about −φ/θ) is taken. At φ = 0 the rates φ̇ are the angular
//!   velocity.
//! - [`rot_mrp`]: modified Rodrigues parameters σ = n tan(θ/4), R rational in σ. Singular at
//!   θ = 2π (|σ| → ∞); past |σ| = 1 (θ = π) the shadow set −σ/|σ|² is taken (Schaub & Junkins,
//!   *Analytical Mechanics of Space Systems*, 2nd ed., 2009, §3.8). At σ = 0 the rates σ̇ are a
//!   quarter of the angular velocity.
//!
//! A switch maps the rates with the switch's Jacobian, so the rotation and the angular velocity
//! are unchanged: only their coordinates are.

use super::{Rot3, Scalar, Vec3};

/// A rotation chart of three coordinates, and the switch that keeps it regular.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RotationChart {
    /// The rotation vector, [`rot_vector`].
    Vector,
    /// Modified Rodrigues parameters, [`rot_mrp`].
    Mrp,
}

/// \[a\]× b + c I + d a aᵀ as a rotation's rows: the shape both charts' matrices take.
#[inline(always)]
fn rotation_from<D: Scalar>(a: Vec3<D>, skew: D, identity: D, outer: D) -> Rot3<D> {
    let [x, y, z] = [a.x, a.y, a.z];
    Rot3 {
        rows: [
            [
                identity + outer * x * x,
                outer * x * y - skew * z,
                outer * x * z + skew * y,
            ],
            [
                outer * y * x + skew * z,
                identity + outer * y * y,
                outer * y * z - skew * x,
            ],
            [
                outer * z * x - skew * y,
                outer * z * y + skew * x,
                identity + outer * z * z,
            ],
        ],
    }
}

/// (1 − cos θ)/θ² = Σₖ (−θ²)ᵏ/(2k + 2)!, to θ⁸.
pub(crate) const VERSINE_SERIES: [f64; 5] = [
    0.5,
    -1.0 / 24.0,
    1.0 / 720.0,
    -1.0 / 40320.0,
    1.0 / 3628800.0,
];

/// c₀ + c₁ t + … + c₄ t⁴ by Horner's rule: the charts' coefficients by their series in t = θ².
#[inline(always)]
pub(crate) fn series<D: Scalar>(t: D, c: [f64; 5]) -> D {
    D::from(c[0]) + t * (D::from(c[1]) + t * (D::from(c[2]) + t * (D::from(c[3]) + t * c[4])))
}

/// The rotation with rotation vector `phi`: R = exp(\[φ\]×) = I + a \[φ\]× + b \[φ\]×², with
/// a = sin θ/θ, b = (1 − cos θ)/θ², θ = |φ| (Rodrigues' formula; Murray, Li & Sastry, *A
/// Mathematical Introduction to Robotic Manipulation*, 1994, eq. (2.14)), and \[φ\]×² = φφᵀ − θ² I.
/// Below θ² = 10⁻² the two coefficients are their Taylor series in θ² to θ⁸ (the next terms are
/// below 3·10⁻¹⁸), so the function and its derivatives of every order are smooth through φ = 0.
///
/// ```
/// use lagrange_core::geometry::{rot_axis, rot_vector, vec3};
/// let r = rot_vector(vec3(0.3, -0.2, 0.6_f64));
/// let about = rot_axis(vec3(0.3, -0.2, 0.6), 0.7);
/// for (row, expected) in r.rows.iter().zip(about.rows) {
///     for (a, b) in row.iter().zip(expected) {
///         assert!((a - b).abs() < 1e-15);
///     }
/// }
/// ```
pub fn rot_vector<D: Scalar>(phi: Vec3<D>) -> Rot3<D> {
    let theta2 = phi.x * phi.x + phi.y * phi.y + phi.z * phi.z;
    let (sinc, versine) = if theta2.re() < 1e-2 {
        // sin θ/θ and (1 − cos θ)/θ² by their series in θ².
        (
            series(
                theta2,
                [1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0],
            ),
            series(theta2, VERSINE_SERIES),
        )
    } else {
        let theta = theta2.sqrt();
        let half = (theta * 0.5).sin() / theta;
        // 1 − cos θ = 2 sin²(θ/2), without the cancellation.
        (theta.sin() / theta, half * half * 2.0)
    };
    rotation_from(phi, sinc, D::one() - versine * theta2, versine)
}

/// The rotation with modified Rodrigues parameters `sigma` (σ = n tan(θ/4) for the rotation by θ
/// about the unit vector n): R = I + (8 \[σ\]×² + 4 (1 − s) \[σ\]×)/(1 + s)², s = |σ|² (the
/// transpose of the direction cosine matrix of Schaub & Junkins, *Analytical Mechanics of Space
/// Systems*, 2nd ed., 2009, §3.8, which maps the other way). Rational in σ: no branch and
/// no trigonometry.
///
/// ```
/// use lagrange_core::geometry::{rot_axis, rot_mrp, vec3};
/// let (n, theta) = (vec3(0.0, 0.6, 0.8_f64), 2.5_f64);
/// let r = rot_mrp(n * (theta / 4.0).tan());
/// for (row, expected) in r.rows.iter().zip(rot_axis(n, theta).rows) {
///     for (a, b) in row.iter().zip(expected) {
///         assert!((a - b).abs() < 1e-15);
///     }
/// }
/// ```
pub fn rot_mrp<D: Scalar>(sigma: Vec3<D>) -> Rot3<D> {
    let s = sigma.x * sigma.x + sigma.y * sigma.y + sigma.z * sigma.z;
    let d = (D::one() + s).powi(2).recip();
    // 8 [σ]×² = 8 (σσᵀ − s I).
    let eight = d * 8.0;
    rotation_from(sigma, d * (D::one() - s) * 4.0, D::one() - eight * s, eight)
}

/// Keeps the chart's coordinates `q[at]` regular: past θ = π, moves them and their rates
/// `v[at]` to the equivalent point (the same rotation, the same angular velocity) of the chart,
/// and says whether it did. The decision is taken on the real parts; on dual numbers the move is
/// differentiated along (the switch is smooth where it is taken).
///
/// - Rotation vector, θ = |φ| > π: φ′ = φ (1 − 2π/θ), φ̇′ = φ̇ − (2π/θ)(φ̇ − n (n·φ̇)), n = φ/θ.
/// - Modified Rodrigues parameters, s = |σ|² > 1: σ′ = −σ/s, σ̇′ = −σ̇/s + 2σ (σ·σ̇)/s²
///   (Schaub & Junkins, §3.8, the shadow set; its rates by differentiating σ′ = −σ/s).
///
/// ```
/// use lagrange_core::geometry::{rot_vector, switch_chart, vec3, RotationChart};
/// let (mut q, mut v) = ([3.5, 0.0, 0.0], [1.0, 0.5, 0.0]);
/// assert!(switch_chart(RotationChart::Vector, [0, 1, 2], &mut q, &mut v));
/// // The same rotation: by 2π − 3.5 the other way about x.
/// assert!((q[0] - (3.5 - 2.0 * std::f64::consts::PI)).abs() < 1e-15);
/// assert!(!switch_chart(RotationChart::Vector, [0, 1, 2], &mut q, &mut v));
/// ```
pub fn switch_chart<S: Scalar, const N: usize>(
    chart: RotationChart,
    at: [usize; 3],
    q: &mut [S; N],
    v: &mut [S; N],
) -> bool {
    let p = at.map(|i| q[i]);
    let r = at.map(|i| v[i]);
    let s = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    let dot = p[0] * r[0] + p[1] * r[1] + p[2] * r[2];
    let (p1, r1): ([S; 3], [S; 3]) = match chart {
        RotationChart::Vector if s.re() > std::f64::consts::PI.powi(2) => {
            let theta = s.sqrt();
            let k = theta.recip() * std::f64::consts::TAU;
            let along = dot / s;
            (
                p.map(|x| x * (S::one() - k)),
                std::array::from_fn(|j| r[j] - k * (r[j] - p[j] * along)),
            )
        }
        RotationChart::Mrp if s.re() > 1.0 => {
            let inv = s.recip();
            let along = dot * inv * inv * 2.0;
            (
                p.map(|x| -x * inv),
                std::array::from_fn(|j| p[j] * along - r[j] * inv),
            )
        }
        _ => return false,
    };
    for j in 0..3 {
        (q[at[j]], v[at[j]]) = (p1[j], r1[j]);
    }
    true
}

/// [`switch_chart`] for coordinates whose velocities are not their rates but the body's angular
/// velocity ω_b (a free or ball joint with
/// [`Velocities::AngularVelocity`](crate::tree::rigid::Velocities::AngularVelocity)): the
/// coordinates move to the equivalent point, the velocities stay (ω_b is the rotation's, not the
/// chart's).
///
/// ```
/// use lagrange_core::geometry::{switch_orientation, RotationChart};
/// let mut q = [0.0, 1.2, 0.5, 0.0];
/// assert!(switch_orientation(RotationChart::Mrp, [1, 2, 3], &mut q));
/// // The shadow set: −σ/|σ|².
/// assert!((q[1] + 1.2 / 1.69).abs() < 1e-15 && (q[2] + 0.5 / 1.69).abs() < 1e-15);
/// ```
pub fn switch_orientation<S: Scalar, const N: usize>(
    chart: RotationChart,
    at: [usize; 3],
    q: &mut [S; N],
) -> bool {
    let mut rates = [S::zero(); N];
    switch_chart(chart, at, q, &mut rates)
}

/// The rotation a chart's coordinates give.
pub fn rotation<D: Scalar>(chart: RotationChart, coordinates: Vec3<D>) -> Rot3<D> {
    match chart {
        RotationChart::Vector => rot_vector(coordinates),
        RotationChart::Mrp => rot_mrp(coordinates),
    }
}

/// The body-frame angular velocity ω = vee(RᵀṘ) of the chart's rotation at `coordinates` moving
/// at `rates` (one pass of dual numbers): what a free body's state means as a spin.
///
/// ```
/// use lagrange_core::geometry::{body_angular_velocity, RotationChart};
/// // At the origin the rotation vector's rates are ω, the parameters' a quarter of it.
/// let w = body_angular_velocity(RotationChart::Mrp, [0.0; 3], [0.25, 0.0, -0.5]);
/// assert!((w[0] - 1.0).abs() < 1e-15 && (w[2] + 2.0).abs() < 1e-15);
/// ```
pub fn body_angular_velocity(
    chart: RotationChart,
    coordinates: [f64; 3],
    rates: [f64; 3],
) -> [f64; 3] {
    let d = |k: usize| num_dual::Dual64::new(coordinates[k], rates[k]);
    let r = rotation(chart, super::vec3(d(0), d(1), d(2)));
    // (RᵀṘ)ᵢⱼ = Σₖ Rₖᵢ Ṙₖⱼ, skew: ω = ((RᵀṘ)₃₂, (RᵀṘ)₁₃, (RᵀṘ)₂₁).
    let entry = |i: usize, j: usize| (0..3).map(|k| r.rows[k][i].re * r.rows[k][j].eps).sum();
    [entry(2, 1), entry(0, 2), entry(1, 0)]
}

/// The chart's rates that give the body-frame angular velocity `omega` at `coordinates`: the
/// inverse of [`body_angular_velocity`], which is linear in the rates (its 3 × 3 matrix from
/// three dual passes, solved by LU). `None` where the chart is singular (a turn of 2π). How a
/// free body's state is set from a spin:
///
/// ```
/// use lagrange_core::geometry::{body_angular_velocity, chart_rates, RotationChart};
/// let (sigma, omega) = ([0.3, -0.5, 0.4], [1.0, 2.0, -0.5]);
/// let rates = chart_rates(RotationChart::Mrp, sigma, omega).unwrap();
/// let back = body_angular_velocity(RotationChart::Mrp, sigma, rates);
/// assert!((0..3).all(|k| (back[k] - omega[k]).abs() < 1e-14));
/// ```
pub fn chart_rates(
    chart: RotationChart,
    coordinates: [f64; 3],
    omega: [f64; 3],
) -> Option<[f64; 3]> {
    let unit = |k: usize| std::array::from_fn(|j| if j == k { 1.0 } else { 0.0 });
    let columns = [0, 1, 2].map(|k| body_angular_velocity(chart, coordinates, unit(k)));
    let matrix = nalgebra::Matrix3::from_fn(|i, j| columns[j][i]);
    let rates = matrix.lu().solve(&nalgebra::Vector3::from(omega))?;
    rates
        .iter()
        .all(|x| x.is_finite())
        .then(|| [rates[0], rates[1], rates[2]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{rot_axis, vec3};
    use num_dual::Dual64;

    fn close(a: Rot3<f64>, b: Rot3<f64>, tolerance: f64) -> bool {
        (0..3).all(|i| (0..3).all(|j| (a.rows[i][j] - b.rows[i][j]).abs() < tolerance))
    }

    /// The world-frame angular velocity of R(c(t)) at c with rates ċ, by one dual pass:
    /// \[ω\]× = Ṙ Rᵀ.
    fn omega(chart: RotationChart, c: [f64; 3], rates: [f64; 3]) -> [f64; 3] {
        let d = |k: usize| Dual64::new(c[k], rates[k]);
        let r = rotation(chart, vec3(d(0), d(1), d(2)));
        let re = Rot3 {
            rows: r.rows.map(|row| row.map(|x| x.re)),
        };
        let dot = Rot3 {
            rows: r.rows.map(|row| row.map(|x| x.eps)),
        };
        let w = dot * re.transpose();
        [w.rows[2][1], w.rows[0][2], w.rows[1][0]]
    }

    /// Both charts give the rotation by θ about n: the rotation vector θ n, the modified Rodrigues
    /// parameters tan(θ/4) n, for angles through 0, small, π and beyond.
    #[test]
    fn charts_give_the_rotation_about_their_axis() {
        let n = vec3(0.48, -0.6, 0.64);
        for theta in [0.0, 1e-9, 0.05, 0.0999, 0.1001, 1.0, 3.0, 3.2, 5.0] {
            let about = rot_axis(n, theta);
            assert!(close(rot_vector(n * theta), about, 1e-15));
            assert!(close(rot_mrp(n * (theta / 4.0).tan()), about, 1e-14));
        }
    }

    /// The rotation vector's series branch and its closed form meet at θ² = 10⁻² in value and in
    /// first derivative (dual numbers), to rounding.
    #[test]
    fn rotation_vector_is_smooth_across_its_series() {
        let n = [0.48, -0.6, 0.64];
        let at = |theta: f64| {
            let d = |k: usize| Dual64::new(n[k] * theta, n[k]);
            rot_vector(vec3(d(0), d(1), d(2)))
        };
        // The two points are 2·10⁻¹² apart and the entries and their first derivatives change at
        // rates of order 1 there: branches that disagreed by more than 10⁻¹¹ would show.
        let (below, above) = (at(0.1 - 1e-12), at(0.1 + 1e-12));
        for i in 0..3 {
            for j in 0..3 {
                assert!((below.rows[i][j].re - above.rows[i][j].re).abs() < 1e-11);
                assert!((below.rows[i][j].eps - above.rows[i][j].eps).abs() < 1e-11);
            }
        }
        // Through φ = 0 the derivative is [n]× (R ≈ I + [φ]×), with no 0/0.
        let zero = at(0.0);
        assert!((zero.rows[1][0].eps - n[2]).abs() < 1e-15);
        assert!(zero.rows.iter().flatten().all(|x| x.eps.is_finite()));
    }

    /// A switch keeps the rotation and the angular velocity; it moves past θ = π only, and lands
    /// inside the ball θ ≤ π; on dual numbers it carries the tangent with its Jacobian (checked
    /// against central differences of the switch).
    #[test]
    fn a_switch_keeps_rotation_and_angular_velocity() {
        let n = [0.48, -0.6, 0.64];
        let rates = [0.3, -1.1, 0.7];
        for (chart, past) in [
            (RotationChart::Vector, 3.3),
            (RotationChart::Mrp, (3.3f64 / 4.0).tan()),
        ] {
            let (mut q, mut v) = (n.map(|x| x * past), rates);
            let (q0, v0) = (q, v);
            assert!(switch_chart(chart, [0, 1, 2], &mut q, &mut v));
            let r = |c: [f64; 3]| rotation(chart, vec3(c[0], c[1], c[2]));
            assert!(close(r(q), r(q0), 1e-14));
            let (w, w0) = (omega(chart, q, v), omega(chart, q0, v0));
            assert!((0..3).all(|k| (w[k] - w0[k]).abs() < 1e-13), "{w:?} {w0:?}");
            // Now inside: no second switch.
            assert!(!switch_chart(chart, [0, 1, 2], &mut q, &mut v));
            // The tangent: d q′/d q₀ along e₀ by duals and by differences.
            let mut qd =
                std::array::from_fn(|k| Dual64::new(q0[k], if k == 0 { 1.0 } else { 0.0 }));
            let mut vd = v0.map(Dual64::from_re);
            switch_chart(chart, [0, 1, 2], &mut qd, &mut vd);
            let h = 1e-6;
            let moved = |dx: f64| {
                let (mut q, mut v) = (q0, v0);
                q[0] += dx;
                switch_chart(chart, [0, 1, 2], &mut q, &mut v);
                (q, v)
            };
            let ((qp, vp), (qm, vm)) = (moved(h), moved(-h));
            for k in 0..3 {
                // Central differences: truncation ~h² ≈ 1e-12, rounding ~1e-16/h ≈ 1e-10.
                assert!((qd[k].eps - (qp[k] - qm[k]) / (2.0 * h)).abs() < 1e-8);
                assert!((vd[k].eps - (vp[k] - vm[k]) / (2.0 * h)).abs() < 1e-8);
            }
        }
        // Inside the ball nothing moves.
        let (mut q, mut v) = ([1.0, 2.0, 0.5], [1.0; 3]);
        assert!(!switch_chart(
            RotationChart::Vector,
            [0, 1, 2],
            &mut q,
            &mut v
        ));
        assert_eq!(q, [1.0, 2.0, 0.5]);
    }
}
