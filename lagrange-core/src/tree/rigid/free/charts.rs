//! A free joint's orientation in one of the two rotation charts
//! ([`RotationChart`](crate::geometry::RotationChart)), and the maps between its coordinates'
//! rates ċ and the body's angular velocity ω_b = B(c) ċ (in the body's frame) that the joint's
//! motion subspace is made of.
//!
//! - Modified Rodrigues parameters σ, s = |σ|²: B = 4/(1+s)² A₋(σ), B⁻¹ = A₊(σ)/4 with
//!   A±(σ) x = (1 − s) x ± 2 σ × x + 2 σ (σ·x) (Schaub & Junkins, *Analytical Mechanics of Space
//!   Systems*, 2nd ed., 2009, §3.8, eq. 3.155), and Ḃ σ̇ = 8 |σ̇|² σ/(1+s)² − 4 (σ·σ̇) ω_b/(1+s)
//!   (d/dt of B σ̇ with σ̈ held, derived for this module).
//! - The rotation vector φ, θ = |φ|: B is the right Jacobian of the exponential map,
//!   B x = x − a φ × x + b φ × (φ × x) with a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³, and
//!   B⁻¹ x = x + ½ φ × x + c φ × (φ × x) with c = (1 − (θ/2) cot(θ/2))/θ² (Chirikjian,
//!   *Stochastic Models, Information Theory, and Lie Groups*, vol. 2, 2012, §10.2; Barfoot,
//!   *State Estimation for Robotics*, 2017, §7.1, gives the left Jacobian J(φ) and its inverse,
//!   and B(φ) = J(−φ)). With φ̈ held,
//!   Ḃ φ̇ = −ȧ φ × φ̇ + ḃ φ × (φ × φ̇) + b φ̇ × (φ × φ̇), ȧ = 2 a′ (φ·φ̇), ḃ = 2 b′ (φ·φ̇), a′ and b′
//!   the derivatives in θ² (derived for this module: φ̇ × φ̇ = 0 removes the other terms).
//!
//! Bᵀ and B⁻ᵀ follow by flipping the sign of the cross product's term (φ×, σ× are skew; the
//! double cross product is symmetric). The unit tests check every map against
//! [`body_angular_velocity`](crate::geometry::body_angular_velocity) and dual-number derivatives.

use super::super::spatial::{add3, cross, dot3, scale3, sub3, M3, V3};
use super::super::Velocities;
use crate::geometry::charts::{series, VERSINE_SERIES};
use crate::geometry::{rot_mrp, rot_vector, vec3, RotationChart, Scalar};

/// A free joint's orientation: its chart and its three coordinates in it, with what every map
/// needs formed once: R(c) and, for the rotation vector, its coefficients. On a joint whose
/// velocities are the angular velocity ω_b ([`Velocities::AngularVelocity`]) the maps between
/// "rates" and ω_b are the identity and the bias zero: its velocities enter the body as they are.
#[derive(Clone, Copy, Debug)]
pub struct Orientation<S> {
    pub chart: RotationChart,
    pub c: V3<S>,
    r: M3<S>,
    k: [S; 5],
    angular: bool,
}

/// x + k₁ c × x + k₂ c × (c × x): the shape every map of the rotation vector takes.
#[inline(always)]
fn turned<S: Scalar>(c: V3<S>, x: V3<S>, k1: S, k2: S) -> V3<S> {
    let once = cross(c, x);
    add3(add3(x, scale3(once, k1)), scale3(cross(c, once), k2))
}

/// A±(σ) x = (1 − s) x ± 2 σ × x + 2 σ (σ·x).
#[inline(always)]
fn a_map<S: Scalar>(sigma: V3<S>, x: V3<S>, plus: bool) -> V3<S> {
    let s = dot3(sigma, sigma);
    let turn = scale3(cross(sigma, x), if plus { 2.0 } else { -2.0 }.into());
    let along = scale3(sigma, dot3(sigma, x) * 2.0);
    add3(add3(scale3(x, S::one() - s), turn), along)
}

/// 4/(1+s)², the factor of B and Bᵀ for the modified Rodrigues parameters.
#[inline(always)]
fn b_factor<S: Scalar>(sigma: V3<S>) -> S {
    let d = S::one() + dot3(sigma, sigma);
    (d * d).recip() * 4.0
}

/// The rotation vector's coefficients at t = θ²: [a, b, c, a′, b′] (see the module docs; a′, b′
/// the derivatives in t). Below t = 10⁻² each is its Taylor series in t (truncated where the next
/// term is below 10⁻¹⁷ relative), so the maps and their derivatives are smooth through φ = 0.
#[inline(always)]
fn vector_coefficients<S: Scalar>(t: S) -> [S; 5] {
    if t.re() < 1e-2 {
        return [
            series(t, VERSINE_SERIES),
            series(
                t,
                [
                    1.0 / 6.0,
                    -1.0 / 120.0,
                    1.0 / 5040.0,
                    -1.0 / 362880.0,
                    1.0 / 39916800.0,
                ],
            ),
            series(
                t,
                [
                    1.0 / 12.0,
                    1.0 / 720.0,
                    1.0 / 30240.0,
                    1.0 / 1209600.0,
                    1.0 / 47900160.0,
                ],
            ),
            series(
                t,
                [
                    -1.0 / 24.0,
                    1.0 / 360.0,
                    -1.0 / 13440.0,
                    1.0 / 907200.0,
                    -1.0 / 95800320.0,
                ],
            ),
            series(
                t,
                [
                    -1.0 / 120.0,
                    1.0 / 2520.0,
                    -1.0 / 120960.0,
                    1.0 / 9979200.0,
                    -1.0 / 1245404160.0,
                ],
            ),
        ];
    }
    let theta = t.sqrt();
    let sin = theta.sin();
    let half = (theta * 0.5).sin();
    // 1 − cos θ = 2 sin²(θ/2), without the cancellation.
    let versine = half * half * 2.0;
    let (t2, t3) = (t * t, t * theta);
    let a = versine / t;
    let b = (theta - sin) / t3;
    // (θ/2) cot(θ/2) = (θ/2) cos(θ/2)/sin(θ/2): regular at θ = π, where sin θ is not.
    let c = (S::one() - theta * 0.5 * (theta * 0.5).cos() / half) / t;
    let a_prime = (theta * sin - versine * 2.0) / (t2 * 2.0);
    let b_prime = (versine * theta - (theta - sin) * 3.0) / (t2 * theta * 2.0);
    [a, b, c, a_prime, b_prime]
}

impl<S: Scalar> Orientation<S> {
    /// The orientation at the coordinates `c` of `chart`, its maps those between the chart's
    /// rates and the angular velocity.
    #[inline(always)]
    pub fn new(chart: RotationChart, c: V3<S>) -> Self {
        Self::of(chart, Velocities::ChartRates, c)
    }

    /// The orientation at the coordinates `c` of `chart` of a joint with `velocities`.
    #[inline(always)]
    pub fn of(chart: RotationChart, velocities: Velocities, c: V3<S>) -> Self {
        let v = vec3(c[0], c[1], c[2]);
        let angular = velocities == Velocities::AngularVelocity;
        let (r, k) = match chart {
            RotationChart::Mrp => (rot_mrp(v).rows, [S::zero(); 5]),
            // The coefficients serve the maps alone, which the angular velocity does not take.
            RotationChart::Vector if angular => (rot_vector(v).rows, [S::zero(); 5]),
            RotationChart::Vector => (rot_vector(v).rows, vector_coefficients(dot3(c, c))),
        };
        Orientation {
            chart,
            c,
            r,
            k,
            angular,
        }
    }

    /// R(c), by rows: the body's axes in the world by columns.
    #[inline(always)]
    pub fn rotation(&self) -> M3<S> {
        self.r
    }

    /// ω_b = B ċ: the body's angular velocity from the coordinates' rates.
    #[inline(always)]
    pub fn angular_velocity(&self, rates: V3<S>) -> V3<S> {
        if self.angular {
            return rates;
        }
        let c = self.c;
        match self.chart {
            RotationChart::Mrp => scale3(a_map(c, rates, false), b_factor(c)),
            RotationChart::Vector => {
                let [a, b, ..] = self.k;
                turned(c, rates, -a, b)
            }
        }
    }

    /// Bᵀ n: the generalized forces of a moment n (body frame) on the coordinates.
    #[inline(always)]
    pub fn generalized_moment(&self, n: V3<S>) -> V3<S> {
        if self.angular {
            return n;
        }
        let c = self.c;
        match self.chart {
            RotationChart::Mrp => scale3(a_map(c, n, true), b_factor(c)),
            RotationChart::Vector => {
                let [a, b, ..] = self.k;
                turned(c, n, a, b)
            }
        }
    }

    /// B⁻¹ ω: the rates whose angular velocity is ω.
    #[inline(always)]
    pub fn rates_of(&self, omega: V3<S>) -> V3<S> {
        if self.angular {
            return omega;
        }
        let c = self.c;
        match self.chart {
            RotationChart::Mrp => scale3(a_map(c, omega, true), S::from(0.25)),
            RotationChart::Vector => {
                let [_, _, k, ..] = self.k;
                turned(c, omega, S::from(0.5), k)
            }
        }
    }

    /// B⁻ᵀ τ: the moment whose generalized forces on the coordinates are τ.
    #[inline(always)]
    pub fn moment_of(&self, tau: V3<S>) -> V3<S> {
        if self.angular {
            return tau;
        }
        let c = self.c;
        match self.chart {
            RotationChart::Mrp => scale3(a_map(c, tau, false), S::from(0.25)),
            RotationChart::Vector => {
                let [_, _, k, ..] = self.k;
                turned(c, tau, S::from(-0.5), k)
            }
        }
    }

    /// Ḃ ċ with c̈ held, given ω_b = B ċ: the angular part of the joint's bias acceleration.
    #[inline(always)]
    pub fn angular_bias(&self, rates: V3<S>, omega: V3<S>) -> V3<S> {
        if self.angular {
            return [S::zero(); 3];
        }
        let c = self.c;
        let along = dot3(c, rates);
        match self.chart {
            RotationChart::Mrp => {
                let d = S::one() + dot3(c, c);
                sub3(
                    scale3(c, dot3(rates, rates) * 8.0 / (d * d)),
                    scale3(omega, along * 4.0 / d),
                )
            }
            RotationChart::Vector => {
                let [_, b, _, a_prime, b_prime] = self.k;
                let once = cross(c, rates);
                let (a_dot, b_dot) = (a_prime * along * 2.0, b_prime * along * 2.0);
                add3(
                    sub3(scale3(cross(c, once), b_dot), scale3(once, a_dot)),
                    scale3(cross(rates, once), b),
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::vector_coefficients;
    use num_dual::Dual64;

    /// a′ and b′ are the derivatives of a and b in t = θ², in the series (t = 10⁻³, and
    /// 9·10⁻³ where its last terms weigh most) and in the closed forms (t = 0.5, 3): a and b on a
    /// dual number give theirs. Both are formulas of a few
    /// operations on numbers of order one (the closed forms' cancellation is small away from the
    /// threshold), so they agree to a few hundred rounding units.
    #[test]
    fn the_derivatives_are_the_coefficients() {
        for t in [1e-3, 9e-3, 0.5, 3.0] {
            let k = vector_coefficients(Dual64::new(t, 1.0));
            for (derivative, of) in [(k[3], k[0]), (k[4], k[1])] {
                let scale = derivative.re.abs();
                assert!((of.eps - derivative.re).abs() < 1e-13 * scale, "t = {t}");
            }
        }
    }

    /// Just below and just above the threshold t = 10⁻² every coefficient agrees: the series are
    /// truncated below 10⁻¹⁸ relative, and the closed forms cancel — b′ worst, terms of order θ³
    /// leaving one of order θ⁵, a relative rounding error of order 10⁻¹⁶/θ² · 10 ≈ 10⁻¹³…10⁻¹⁰.
    #[test]
    fn the_series_meet_the_closed_forms_at_the_threshold() {
        let below = vector_coefficients(1e-2 * (1.0 - 1e-12));
        let above = vector_coefficients(1e-2 * (1.0 + 1e-12));
        for (x, y) in below.iter().zip(above) {
            assert!(
                (x - y).abs() < 1e-9 * y.abs(),
                "{below:?} against {above:?}"
            );
        }
    }
}
