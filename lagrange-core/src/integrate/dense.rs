//! The dense output of one step ([`DenseOutput`]): a polynomial in time for (q, q̇) over the step,
//! what events are located on, and the cubic Hermite interpolant every method without a
//! continuous extension of its own uses.

use crate::tree::rigid::{free, Joint};

/// Width under which an event's bracket counts as located (absolute, in time units; widened to
/// 4 ulp of t for large t).
pub const EVENT_TIME_TOLERANCE: f64 = 1e-13;

/// The dense output of one step: a polynomial in time for q and v over [t₀, t₀ + h], in the form
/// of Hairer's CONTD5, y(t₀ + θh) = r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ) r₅))): of order 4 for
/// Dopri5, of order 7 for Dop853 (eight coefficients), the collocation polynomial for Radau5, and
/// the cubic Hermite interpolant (r₅ = 0) of the end values and derivatives for the other methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseOutput<const N: usize> {
    t0: f64,
    pub(crate) h: f64,
    q: [[f64; N]; 8],
    v: [[f64; N]; 8],
    /// Coefficients in use: 5 (Dopri5, Hermite) or 8 (Dop853).
    terms: usize,
    /// Where the polynomial in v is one in the coordinates' rates q̇ of a mechanism whose
    /// velocities are quasi-velocities (Radau5 steps the rates): its joints, by whose map
    /// v = B(q) q̇ [`eval`](Self::eval) turns the rates into the velocities; none elsewhere.
    rates_of: &'static [Joint],
}

impl<const N: usize> DenseOutput<N> {
    /// The constant (q, q̇) at t: the dense output before a first step.
    pub fn constant(t: f64, q: &[f64; N], v: &[f64; N]) -> Self {
        let mut d = DenseOutput {
            t0: t,
            h: 0.0,
            q: [[0.0; N]; 8],
            v: [[0.0; N]; 8],
            terms: 5,
            rates_of: &[],
        };
        d.q[0] = *q;
        d.v[0] = *v;
        d
    }

    /// The cubic Hermite interpolant over [t₀, t₀ + h] of (q, v) with derivatives (q̇, v̇) at both
    /// ends (`start` and `end` are (q, v, v̇), `rates` q̇ = G(q) v at both, v itself unless the
    /// velocities are quasi-velocities): order 3 (HNW I §II.6, (6.7)), written over `self` in
    /// place (the rows it does not use are left as they are): what an integrator that keeps its
    /// dense output does after every step.
    #[inline]
    pub(crate) fn set_hermite(
        &mut self,
        t0: f64,
        h: f64,
        start: (&[f64; N], &[f64; N], &[f64; N]),
        end: (&[f64; N], &[f64; N], &[f64; N]),
        (r0, r1): (&[f64; N], &[f64; N]),
    ) {
        hermite_rows(&mut self.q, h, start.0, end.0, r0, r1);
        hermite_rows(&mut self.v, h, start.1, end.1, start.2, end.2);
        self.q[4] = [0.0; N];
        self.v[4] = [0.0; N];
        (self.t0, self.h, self.terms) = (t0, h, 5);
    }

    /// Without v̇ at the ends: the cubic Hermite interpolant of q (from q and q̇ = `rates` at both
    /// ends) and the straight line between the two v — what a fixed-step solver without dense
    /// output keeps, written over `self` in place.
    #[inline]
    pub(crate) fn set_hermite_positions(
        &mut self,
        t0: f64,
        h: f64,
        (q0, v0): (&[f64; N], &[f64; N]),
        (q1, v1): (&[f64; N], &[f64; N]),
        (r0, r1): (&[f64; N], &[f64; N]),
    ) {
        hermite_rows(&mut self.q, h, q0, q1, r0, r1);
        for i in 0..N {
            self.v[0][i] = v0[i];
            self.v[1][i] = v1[i] - v0[i];
            self.v[2][i] = 0.0;
            self.v[3][i] = 0.0;
        }
        self.q[4] = [0.0; N];
        self.v[4] = [0.0; N];
        (self.t0, self.h, self.terms) = (t0, h, 5);
    }

    /// A continuous extension from its coefficients r₁…r₅ (Dopri5's CONTD5, the collocation
    /// polynomial of Radau5) for q and for v.
    pub(crate) fn from_five(t0: f64, h: f64, q: [[f64; N]; 8], v: [[f64; N]; 8]) -> Self {
        DenseOutput {
            t0,
            h,
            q,
            v,
            terms: 5,
            rates_of: &[],
        }
    }

    /// Dop853's continuous extension of order 7 (Hairer's CONTD8): r₁…r₈ for q and for v.
    pub(crate) fn from_coefficients(t0: f64, h: f64, q: [[f64; N]; 8], v: [[f64; N]; 8]) -> Self {
        DenseOutput {
            t0,
            h,
            q,
            v,
            terms: 8,
            rates_of: &[],
        }
    }

    /// Start of the step.
    pub fn t_start(&self) -> f64 {
        self.t0
    }

    /// End of the step.
    pub fn t_end(&self) -> f64 {
        self.t0 + self.h
    }

    /// (q, v) at time t (meant for t in the step; outside it this extrapolates).
    pub fn eval(&self, t: f64) -> ([f64; N], [f64; N]) {
        let (q, v) = self.polynomials(t);
        match self.rates_of.is_empty() {
            true => (q, v),
            false => {
                let v = free::velocities_from_rates(self.rates_of, &q, &v);
                (q, v)
            }
        }
    }

    /// The two polynomials at t.
    fn polynomials(&self, t: f64) -> ([f64; N], [f64; N]) {
        if self.h == 0.0 {
            return (self.q[0], self.v[0]);
        }
        let th = (t - self.t0) / self.h;
        let th1 = 1.0 - th;
        let terms = self.terms;
        let f = |r: &[[f64; N]; 8]| -> [f64; N] {
            std::array::from_fn(|i| {
                // r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ)(r₅ + θ(r₆ + (1−θ)(r₇ + θ r₈)))))), from the
                // innermost term out, alternating the factors θ and 1 − θ.
                let mut acc = 0.0;
                for k in (1..terms).rev() {
                    acc = (r[k][i] + acc) * if k % 2 == 1 { th } else { th1 };
                }
                r[0][i] + acc
            })
        };
        (f(&self.q), f(&self.v))
    }

    /// Marks the polynomial in v as one in the rates q̇ of the quasi-velocities of `joints`, which
    /// [`eval`](Self::eval) then converts (v = B(q) q̇).
    pub(crate) fn evaluate_velocities(&mut self, joints: &'static [Joint]) {
        self.rates_of = joints;
    }

    /// The root in (t_start, t_end] of g(t, q(t), v(t)) given its values at both ends (of opposite
    /// signs, or zero at the end), by the Illinois method to within [`EVENT_TIME_TOLERANCE`]. The
    /// returned time is on the far side of the bracket (g has its end-of-step sign there or is zero).
    /// Also returns the number of evaluations of g.
    pub fn find_root(
        &self,
        g: impl FnMut(f64, &[f64; N], &[f64; N]) -> f64,
        g_start: f64,
        g_end: f64,
    ) -> (f64, usize) {
        self.find_root_between(g, (self.t0, g_start), (self.t_end(), g_end))
    }

    /// [`find_root`](Self::find_root) on a bracket [a, b] inside the step, given g there.
    pub(crate) fn find_root_between(
        &self,
        mut g: impl FnMut(f64, &[f64; N], &[f64; N]) -> f64,
        (mut a, mut fa): (f64, f64),
        (mut b, mut fb): (f64, f64),
    ) -> (f64, usize) {
        if fb == 0.0 {
            return (b, 0);
        }
        let tol = EVENT_TIME_TOLERANCE.max(4.0 * f64::EPSILON * b.abs());
        let mut side = 0i8;
        let mut evaluations = 0;
        for _ in 0..200 {
            if (b - a).abs() <= tol {
                break;
            }
            let mut c = (a * fb - b * fa) / (fb - fa);
            if !(c > a.min(b) && c < a.max(b)) {
                c = 0.5 * (a + b);
            }
            let (q, v) = self.eval(c);
            let fc = g(c, &q, &v);
            evaluations += 1;
            if fc == 0.0 {
                return (c, evaluations);
            }
            if !fc.is_finite() {
                // Cannot judge the sign: bisect towards the start, keeping the bracket.
                b = c;
                continue;
            }
            if (fc > 0.0) == (fb > 0.0) {
                b = c;
                fb = fc;
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                a = c;
                fa = fc;
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        (b, evaluations)
    }
}

/// Rows 0–3 of a dense output's coefficients over a step of size h from y₀ to y₁, with
/// derivatives d₀ = y'(t₀) and d₁ = y'(t₀ + h) (rows 4–7 are left as they are):
///
/// ```text
/// r₀ = y₀,   r₁ = y₁ − y₀,   r₂ = h d₀ − r₁,   r₃ = r₁ − h d₁ − r₂.
/// ```
///
/// The start of the continuous extensions of DOPRI5 and DOP853 (Hairer, Nørsett & Wanner,
/// *Solving Ordinary Differential Equations I*, 2nd ed., 1993, §II.6; `rcont1`…`rcont4` of
/// `contd5` in dopri5.f and of `contd8` in dop853.f; r₁…r₄ in the 1-based form of
/// [`DenseOutput`]). Alone (the higher rows zero) they are the cubic Hermite interpolant
/// y₀ + θ(r₁ + (1−θ)(r₂ + θ r₃)), θ = (t − t₀)/h, of the end values and derivatives: its
/// θ-derivative is r₁ + r₂ = h d₀ at θ = 0 and r₁ − r₂ − r₃ = h d₁ at θ = 1.
#[inline(always)]
pub(crate) fn hermite_rows<const N: usize>(
    r: &mut [[f64; N]; 8],
    h: f64,
    y0: &[f64; N],
    y1: &[f64; N],
    d0: &[f64; N],
    d1: &[f64; N],
) {
    for i in 0..N {
        let diff = y1[i] - y0[i];
        let bspl = h * d0[i] - diff;
        r[0][i] = y0[i];
        r[1][i] = diff;
        r[2][i] = bspl;
        r[3][i] = diff - h * d1[i] - bspl;
    }
}
