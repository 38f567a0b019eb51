//! Adaptive Radau IIA of order 5 — Hairer's RADAU5 — for stiff mechanisms.
//!
//! - Method: the 3-stage Radau IIA collocation method (nodes c = (4 − √6)/10, (4 + √6)/10, 1),
//!   order 5, L-stable, stiffly accurate (Hairer & Wanner, *Solving ODEs II* (HW II), §IV.5,
//!   Table 5.6; the implementation follows §IV.8 and Hairer's code `radau5.f`, version of 1996–2002).
//!   It is applied to the first-order system y = (q, v), y' = f(t, y) = (v, q̈(t, q, v)), with q̈
//!   the mechanism's accelerations (on a constrained mechanism these include the constraint forces,
//!   as for [`Dopri5`]).
//! - Stage equations: for Z = (Z₁, Z₂, Z₃), Zᵢ = yᵢ − y₀, the collocation equations
//!   Zᵢ = h Σⱼ aᵢⱼ f(t₀ + cⱼh, y₀ + Zⱼ) are solved by the **simplified Newton iteration** of HW II
//!   §IV.8, (8.5)–(8.17): with W = T⁻¹Z (T the eigenvector matrix of A⁻¹, eigenvalues γ̂ and
//!   α̂ ± iβ̂), the 6N-dimensional linear system splits into a real system with matrix
//!   γ̂/h·I − J and a complex one with (α̂ + iβ̂)/h·I − J, J = ∂f/∂y at (t₀, y₀).
//! - Second-order structure: J = [[0, I], [∂q̈/∂q, ∂q̈/∂v]], so (σI − J)(x, y) = (r₁, r₂) reduces to
//!   (σ²I − σ∂q̈/∂v − ∂q̈/∂q) x = r₂ + (σI − ∂q̈/∂v) r₁, y = σx − r₁: an N-square system (the
//!   reduction `radau5.f` makes for problems with the special structure y'ᵢ = y_{i+M2}, its options
//!   M1, M2). The real matrix is factorised as an N-square block LU (the one the Gauss methods use), the complex one in its real
//!   form [[Re K, −Im K], [Im K, Re K]] as a 2N-square one: about 3N³ flops per
//!   factorisation against (6N)³/3 = 72N³ for the unsplit system.
//! - Reuse: the Jacobians ∂q̈/∂q, ∂q̈/∂v (exact, by dual numbers, [`acceleration_jacobians`]) are
//!   kept across iterations and steps while the Newton contraction rate θ stays below
//!   [`Radau5::jacobian_theta`], and the factorisation too while moreover the proposed step changes
//!   by less than the factors in [`Radau5::keep_step`] (then the step is kept as it is);
//!   otherwise the Jacobian (θ large) or the factorisation (h changed) is recomputed (`radau5.f`,
//!   THET, QUOT1, QUOT2).
//! - Newton stopping: the iteration stops when η‖ΔW‖ ≤ κ·tol with η = θ/(1 − θ) (HW II (8.10),
//!   (8.13); κ·tol = max(10ε/rtol′, min(0.03, √rtol′)) as in `radau5.f`); it is abandoned (the
//!   step rejected and shrunk as in `radau5.f`) when θ ≥ 0.99, when the predicted error after
//!   the remaining iterations is too large, or after [`Radau5::max_newton_iterations`]. Starting
//!   values extrapolate the previous step's collocation polynomial (HW II (8.16)).
//! - Error estimate: err = (γ₀h)⁻¹·(γ̂/h·I − J)⁻¹ applied to γ₀h f(y₀) + Σ eᵢZᵢ, as in `radau5.f`
//!   (HW II (8.19)–(8.20)), re-filtered through one more evaluation after a rejection or on the
//!   first step (8.21). Norm: √(1/(2N) Σ (errᵢ/scᵢ)²), scᵢ = atol′ + rtol′·|y₀ᵢ|.
//! - Tolerances: `radau5.f` replaces the user's (rtol, atol) with rtol′ = 0.1·rtol^(2/3),
//!   atol′ = rtol′·atol/rtol, so that the achieved error is roughly proportional to rtol; the same
//!   is done here.
//! - Step-size control: h_new = h·fac·err^(−1/4), fac = min(0.9, 0.9·(1 + 2k_max)/(k + 2k_max))
//!   (k Newton iterations), with Gustafsson's predictive controller (HW II (8.25)), h_new/h in
//!   [0.2, 8]; after a rejection the step does not grow.
//! - Dense output: the collocation polynomial (cubic; order 3 uniformly, the stage order), as
//!   `radau5.f`'s CONTR5.
//! - Events, the observer and the statistics are those of every solver ([`Stepper::integrate`]).
//!   [`Stats::factorizations`] counts one per refactorisation (the real and the complex matrix
//!   together, as `radau5.f`'s NDEC).
//! - Constraints: as [`Dopri5`], the start state must satisfy them and every
//!   accepted step is projected onto them; the dense output interpolates the step before
//!   projection.
//!
//! Integration is forward in time only.
//!
//! ```
//! use lagrange_core::integrate::{Radau5, Radau5Stepper, Stepper};
//! use lagrange_core::{Model, Scalar, State};
//!
//! /// A stiff spring (ω = 1000) carrying a slow one (ω = 1), written by hand: two unit masses on
//! /// a line, x₁ tied to the wall by a spring of stiffness 1, x₂ tied to x₁ by one of 10⁶.
//! struct StiffPair;
//! impl Model<2, 2> for StiffPair {
//!     type Coords = [f64; 2];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
//!         x[0] * x[0] * 0.5 + (x[1] - x[0]) * (x[1] - x[0]) * 5e5
//!     }
//! }
//! lagrange_core::impl_mechanism!(StiffPair, 2, 2);
//!
//! // Released at rest along the slow normal mode, x₂/x₁ = 1 + (1 − λ)/10⁶ with λ ≈ 1/2 (both
//! // masses on the soft spring): the stiff mode is not excited (to O(10⁻¹²)), and
//! // x₁ = cos(√λ t) with λ = 1/2 up to 10⁻⁶.
//! let start = State::new(0.0, [1.0, 1.0 + 0.5e-6], [0.0, 0.0]);
//! let mut solver = Radau5Stepper::new(&StiffPair, Radau5::new(1e-8, 1e-8), &start)?;
//! let outcome = solver.integrate(10.0, &mut [], |_| {})?;
//! let exact = (0.5f64.sqrt() * 10.0).cos();
//! assert!((solver.state().q[0] - exact).abs() < 1e-5);
//! // An explicit method would need hω < 3.3, over 3000 steps; Radau5 follows the slow motion.
//! assert!(outcome.stats.accepted < 300, "{:?}", outcome.stats);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays;
// the coefficients carry the digits of `radau5.f`.
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    clippy::needless_range_loop,
    clippy::excessive_precision
)]

mod algebra;
mod settings;

use super::dopri5::{initial_step, DenseOutput, Dopri5};
use super::newton::acceleration_jacobians;
use super::solver::Stepper;
pub use super::solver::{Event, Observation, Outcome, Stats, StopReason};
use super::Integrator;
use crate::error::{Error, Result};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};
use algebra::*;
use nalgebra::SVector;
pub use settings::Radau5;

/// How a Newton iteration of a step attempt ended.
enum Attempt<const N: usize> {
    /// Converged: the stages Zᵢ, the iterations taken.
    Converged([Pair<N>; 3], usize),
    /// Abandoned: retry with h times this factor (and a fresh Jacobian if the current one is old);
    /// the error, if an evaluation failed.
    Failed(f64, Option<Error>),
}

/// Step-by-step use of [`Radau5`]: holds the current state, the Jacobian and factorisation being
/// reused, the proposed next step and the dense output of the last accepted step; implements
/// [`Stepper`].
pub struct Radau5Stepper<'m, M: Mechanism<N>, const N: usize> {
    mechanism: &'m M,
    settings: Radau5,
    /// The converted tolerances (rtol′, atol′) and the Newton tolerance κ·tol.
    rtol: f64,
    atol: f64,
    newton_tol: f64,
    t: f64,
    y: Pair<N>,
    /// f(t, y) = (v, q̈).
    f0: Pair<N>,
    h: f64,
    jacobians: Option<Jacobians<N>>,
    /// Whether the Jacobian was evaluated at the current point (no accepted step since).
    jacobian_current: bool,
    factors: Option<Factors<N>>,
    /// Contraction rate of the last Newton iteration, and η of HW II (8.10).
    theta: f64,
    faccon: f64,
    first: bool,
    /// Gustafsson's controller: the last accepted step and its error.
    h_acc: f64,
    err_acc: f64,
    dense: DenseOutput<N>,
    stats: Stats,
}

impl<'m, M: Mechanism<N>, const N: usize> Radau5Stepper<'m, M, N> {
    /// Starts at `state`: validates settings, mechanism, state and constraints, evaluates q̈ and
    /// chooses the first step.
    pub fn new(mechanism: &'m M, settings: Radau5, state: &State<M::Coords>) -> Result<Self> {
        settings.validate()?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        Self::start(mechanism, settings, state.t, q, v)
    }

    fn start(mechanism: &'m M, settings: Radau5, t: f64, q: [f64; N], v: [f64; N]) -> Result<Self> {
        crate::integrate::newton::refuse_contacts::<M, N>("Radau5")?;
        let a = mechanism
            .accelerations_at(t, &q, &v)
            .map_err(|e| diagnose(mechanism, t, &q, &v, e))?;
        // `radau5.f`: rtol′ = 0.1·rtol^(2/3), atol′ = rtol′·atol/rtol; the Newton tolerance.
        let rtol = 0.1 * settings.rtol.powf(2.0 / 3.0);
        let atol = rtol * (settings.atol / settings.rtol);
        let newton_tol = settings
            .newton_tolerance
            .unwrap_or((10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt())));
        let mut stats = Stats {
            evaluations: 1,
            ..Stats::default()
        };
        let h = match settings.h_init {
            Some(h) => h.min(settings.h_max),
            None => {
                let dopri = Dopri5 {
                    rtol,
                    atol,
                    h_max: settings.h_max,
                    ..Dopri5::default()
                };
                initial_step(mechanism, &dopri, (t, &q, &v, &a), 5, &mut stats)
            }
        };
        let (qv, vv) = (SVector::from(q), SVector::from(v));
        Ok(Radau5Stepper {
            mechanism,
            settings,
            rtol,
            atol,
            newton_tol,
            t,
            y: Pair { q: qv, v: vv },
            f0: Pair {
                q: vv,
                v: SVector::from(a),
            },
            h,
            jacobians: None,
            jacobian_current: false,
            factors: None,
            theta: settings.jacobian_theta,
            faccon: 1.0,
            first: true,
            h_acc: h,
            err_acc: 1e-2,
            dense: DenseOutput::constant(t, &q, &v),
            stats,
        })
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.h
    }

    /// f(t, y₀ + z) = (v₀ + z_v, q̈) at time t, counted.
    fn field(&self, t: f64, z: &Pair<N>, stats: &mut Stats) -> Result<Pair<N>> {
        let q: [f64; N] = (self.y.q + z.q).into();
        let v: [f64; N] = (self.y.v + z.v).into();
        stats.evaluations += 1;
        let m = self.mechanism;
        let a = m
            .accelerations_at(t, &q, &v)
            .map_err(|e| diagnose(m, t, &q, &v, e))?;
        Ok(Pair {
            q: SVector::from(v),
            v: SVector::from(a),
        })
    }

    /// The simplified Newton iteration of one step attempt with step h (HW II §IV.8; `radau5.f`,
    /// the loop at label 40).
    fn newton(
        &mut self,
        h: f64,
        jac: &Jacobians<N>,
        f: &Factors<N>,
        stats: &mut Stats,
    ) -> Attempt<N> {
        let nit = self.settings.max_newton_iterations;
        let scale = self.scale();
        // Starting values: the last step's collocation polynomial extrapolated (HW II (8.16)), or 0.
        let mut z = [Pair::zero(); 3];
        if !self.first && self.dense.t_end() > self.dense.t_start() {
            let (q1, v1) = self.dense.eval(self.t);
            for (i, c) in [C1, C2, 1.0].into_iter().enumerate() {
                let (q, v) = self.dense.eval(self.t + c * h);
                z[i] = Pair {
                    q: SVector::from(q) - SVector::from(q1),
                    v: SVector::from(v) - SVector::from(v1),
                };
            }
        }
        let to_w = |z: &[Pair<N>; 3]| {
            [
                Pair::combine([TI11, TI12, TI13], [&z[0], &z[1], &z[2]]),
                Pair::combine([TI21, TI22, TI23], [&z[0], &z[1], &z[2]]),
                Pair::combine([TI31, TI32, TI33], [&z[0], &z[1], &z[2]]),
            ]
        };
        let mut w = to_w(&z);
        self.faccon = self.faccon.max(f64::EPSILON).powf(0.8);
        self.theta = self.settings.jacobian_theta;
        let (mut dyno_old, mut thq_old) = (1.0, 1.0);
        let fac1 = U1 / h;
        let (alphn, betan) = (ALPH / h, BETA / h);
        for newt in 1..=nit {
            let mut fz = [Pair::zero(); 3];
            for (i, c) in [C1, C2, 1.0].into_iter().enumerate() {
                match self.field(self.t + c * h, &z[i], stats) {
                    Ok(v) => fz[i] = v,
                    Err(e) => return Attempt::Failed(0.5, Some(e)),
                }
            }
            stats.newton_iterations += 1;
            // The residual in W: T⁻¹F(Z) − Λ W, Λ = diag(γ̂, [[α̂, −β̂], [β̂, α̂]])/h; solved blockwise.
            let g = to_w(&fz);
            let r1 = Pair::combine([1.0, -fac1], [&g[0], &w[0]]);
            let r2 = Pair::combine([1.0, -alphn, betan], [&g[1], &w[1], &w[2]]);
            let r3 = Pair::combine([1.0, -alphn, -betan], [&g[2], &w[2], &w[1]]);
            let d1 = jac.solve_real(f, &r1);
            let (d2, d3) = jac.solve_complex(f, &r2, &r3);
            let dyno = ((d1.scaled_sum(&scale) + d2.scaled_sum(&scale) + d3.scaled_sum(&scale))
                / (6 * N) as f64)
                .sqrt();
            if !dyno.is_finite() {
                return Attempt::Failed(0.5, None);
            }
            if newt > 1 && newt < nit {
                let thq = dyno / dyno_old;
                self.theta = if newt == 2 {
                    thq
                } else {
                    (thq * thq_old).sqrt()
                };
                thq_old = thq;
                if self.theta < 0.99 {
                    self.faccon = self.theta / (1.0 - self.theta);
                    let remaining = (nit - 1 - newt) as i32;
                    let predicted =
                        self.faccon * dyno * self.theta.powi(remaining) / self.newton_tol;
                    if predicted >= 1.0 {
                        let q = predicted.clamp(1e-4, 20.0);
                        return Attempt::Failed(
                            0.8 * q.powf(-1.0 / (4.0 + remaining as f64)),
                            None,
                        );
                    }
                } else {
                    return Attempt::Failed(0.5, None);
                }
            }
            dyno_old = dyno.max(f64::EPSILON);
            for (wi, di) in w.iter_mut().zip([&d1, &d2, &d3]) {
                wi.q += di.q;
                wi.v += di.v;
            }
            z = [
                Pair::combine([T11, T12, T13], [&w[0], &w[1], &w[2]]),
                Pair::combine([T21, T22, T23], [&w[0], &w[1], &w[2]]),
                Pair::combine([T31, 1.0], [&w[0], &w[1]]),
            ];
            if self.faccon * dyno <= self.newton_tol {
                return Attempt::Converged(z, newt);
            }
        }
        Attempt::Failed(0.5, None)
    }

    /// scᵢ = atol′ + rtol′·|y₀ᵢ|.
    fn scale(&self) -> Pair<N> {
        Pair {
            q: self.y.q.map(|x| self.atol + self.rtol * x.abs()),
            v: self.y.v.map(|x| self.atol + self.rtol * x.abs()),
        }
    }

    /// The error estimate of HW II (8.19)–(8.21), `radau5.f`'s ESTRAD.
    fn error(
        &self,
        h: f64,
        z: &[Pair<N>; 3],
        jac: &Jacobians<N>,
        f: &Factors<N>,
        refine: bool,
        stats: &mut Stats,
    ) -> f64 {
        let scale = self.scale();
        let f2 = Pair::combine([DD1 / h, DD2 / h, DD3 / h], [&z[0], &z[1], &z[2]]);
        let mut e = jac.solve_real(f, &Pair::combine([1.0, 1.0], [&f2, &self.f0]));
        let mut err = (e.scaled_sum(&scale) / (2 * N) as f64).sqrt().max(1e-10);
        if err >= 1.0 && refine {
            match self.field(self.t, &e, stats) {
                Ok(fe) => {
                    e = jac.solve_real(f, &Pair::combine([1.0, 1.0], [&fe, &f2]));
                    err = (e.scaled_sum(&scale) / (2 * N) as f64).sqrt().max(1e-10);
                }
                Err(_) => return f64::INFINITY,
            }
        }
        if err.is_nan() {
            f64::INFINITY
        } else {
            err
        }
    }

    /// Takes one accepted step, not past `t_limit` (> the current time), rejecting and shrinking
    /// as needed (`radau5.f`'s RADCOR). When the step can no longer shrink (0.1·h below round-off
    /// of t) the last failure is returned ([`Error::StepSizeUnderflow`] if steps were rejected only
    /// for accuracy or slow Newton convergence). On error the accepted state is unchanged.
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        if !(t_limit > self.t) || !t_limit.is_finite() {
            return Err(Error::InvalidEndTime {
                t: self.t,
                t_end: t_limit,
            });
        }
        let mut stats = self.stats;
        let mut reject = false;
        let mut last_error: Option<Error> = None;
        let nit = self.settings.max_newton_iterations as f64;
        loop {
            let mut h = self.h.min(self.settings.h_max);
            let last = self.t + 1.01 * h >= t_limit;
            if last {
                h = t_limit - self.t;
            }
            if !(self.t + 0.1 * h > self.t) {
                self.stats = stats;
                return Err(last_error.unwrap_or(Error::StepSizeUnderflow {
                    method: "Radau5",
                    t: self.t,
                    h,
                }));
            }
            if self.jacobians.is_none() {
                let (t, q, v) = (self.t, self.y.q.into(), self.y.v.into());
                stats.jacobians += 1;
                let m = self.mechanism;
                let (_, by_q, by_v) =
                    acceleration_jacobians(m, t, &q, &v).map_err(|e| diagnose(m, t, &q, &v, e))?;
                self.jacobians = Some(Jacobians { by_q, by_v });
                self.jacobian_current = true;
                self.factors = None;
            }
            let jac = self.jacobians.expect("evaluated above");
            let factors = match self.factors {
                Some(f) if f.h == h => Some(f),
                _ => {
                    stats.factorizations += 1;
                    jac.factor(h)
                }
            };
            self.factors = factors;
            let attempt = match factors {
                Some(f) => self.newton(h, &jac, &f, &mut stats),
                None => Attempt::Failed(
                    0.5,
                    Some(Error::NewtonBreakdown {
                        method: "Radau5",
                        t: self.t,
                        h,
                        iteration: 0,
                        reason: "the Newton matrix is singular or not finite".to_string(),
                    }),
                ),
            };
            let (z, newt) = match attempt {
                Attempt::Converged(z, newt) => (z, newt),
                Attempt::Failed(factor, error) => {
                    // `radau5.f` label 78 / the slow-convergence exit: shrink, refresh an old Jacobian.
                    last_error = error.or(last_error);
                    self.h = h * factor;
                    self.renew_jacobian_if_old();
                    reject = true;
                    stats.rejected += 1;
                    continue;
                }
            };
            let f = factors.expect("converged with a factorisation");
            let err = self.error(h, &z, &jac, &f, self.first || reject, &mut stats);
            // h_new = h·fac·err^(−1/4) (`radau5.f`): fac falls with the Newton iterations taken.
            let fac = SAFETY.min(SAFETY * (1.0 + 2.0 * nit) / (newt as f64 + 2.0 * nit));
            let mut quot = (err.powf(0.25) / fac).clamp(0.125, 5.0);
            if !(err < 1.0) {
                self.h = if self.first { 0.1 * h } else { h / quot };
                self.renew_jacobian_if_old();
                reject = true;
                stats.rejected += 1;
                continue;
            }
            // Accepted. Gustafsson's predictive controller (HW II (8.25)).
            if stats.accepted > 0 {
                let gus = ((self.h_acc / h) * (err * err / self.err_acc).powf(0.25) / SAFETY)
                    .clamp(0.125, 5.0);
                quot = quot.max(gus);
            }
            self.h_acc = h;
            self.err_acc = err.max(1e-2);
            let t_new = if last { t_limit } else { self.t + h };
            let y1 = Pair::combine([1.0, 1.0], [&self.y, &z[2]]);
            let (q1, v1): ([f64; N], [f64; N]) = (y1.q.into(), y1.v.into());
            check_state(&M::Coords::NAMES, t_new, &q1, &v1)?;
            let (mut qp, mut vp) = (q1, v1);
            let m = self.mechanism;
            m.project(t_new, &mut qp, &mut vp)?;
            if qp != q1 || vp != v1 {
                check_state(&M::Coords::NAMES, t_new, &qp, &vp)?;
            }
            stats.evaluations += 1;
            let a1 = m
                .accelerations_at(t_new, &qp, &vp)
                .map_err(|e| diagnose(m, t_new, &qp, &vp, e))?;
            stats.accepted += 1;
            self.dense = self.collocation_polynomial(h, &z);
            self.t = t_new;
            self.y = Pair {
                q: SVector::from(qp),
                v: SVector::from(vp),
            };
            self.f0 = Pair {
                q: self.y.v,
                v: SVector::from(a1),
            };
            self.first = false;
            self.jacobian_current = false;
            // The next step: keep h and the factorisation when the proposal is within keep_step and
            // the Newton iteration converged fast; keep the Jacobian when it converged fast.
            let mut h_new = (h / quot).min(self.settings.h_max);
            if reject {
                h_new = h_new.min(h);
            }
            let fast = self.theta <= self.settings.jacobian_theta;
            let (lo, hi) = self.settings.keep_step;
            let ratio = h_new / h;
            self.h = if fast && ratio >= lo && ratio <= hi && !last {
                h
            } else {
                h_new
            };
            if !fast {
                self.jacobians = None;
            }
            self.stats = stats;
            return Ok(());
        }
    }

    /// After a failed attempt: a Jacobian not evaluated at the current point is evaluated anew.
    fn renew_jacobian_if_old(&mut self) {
        if !self.jacobian_current {
            self.jacobians = None;
        }
    }

    /// The collocation polynomial through (0, y₀), (cᵢ, y₀ + Zᵢ) as a dense output, in the form
    /// y₀ + θ r₂ + θ(1−θ) r₃ + θ²(1−θ) r₄: r₂ = Z₃, and with gᵢ = (Zᵢ − cᵢZ₃)/(cᵢ(1 − cᵢ)) = r₃ + cᵢr₄
    /// (i = 1, 2), r₄ = (g₂ − g₁)/(c₂ − c₁), r₃ = g₁ − c₁r₄.
    fn collocation_polynomial(&self, h: f64, z: &[Pair<N>; 3]) -> DenseOutput<N> {
        let make = |y0: &SVector<f64, N>, z: [&SVector<f64, N>; 3]| {
            let mut r = [[0.0; N]; 8];
            for i in 0..N {
                let g1 = (z[0][i] - C1 * z[2][i]) / (C1 * (1.0 - C1));
                let g2 = (z[1][i] - C2 * z[2][i]) / (C2 * (1.0 - C2));
                let r4 = (g2 - g1) / (C2 - C1);
                r[0][i] = y0[i];
                r[1][i] = z[2][i];
                r[2][i] = g1 - C1 * r4;
                r[3][i] = r4;
            }
            r
        };
        DenseOutput::from_coefficients(
            self.t,
            h,
            make(&self.y.q, [&z[0].q, &z[1].q, &z[2].q]),
            make(&self.y.v, [&z[0].v, &z[1].v, &z[2].v]),
        )
    }
}

impl<M: Mechanism<N>, const N: usize> Stepper<M::Coords, N> for Radau5Stepper<'_, M, N> {
    fn name(&self) -> &'static str {
        "Radau5"
    }
    fn t(&self) -> f64 {
        self.t
    }
    fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.y.q.into()),
            M::Coords::from_array(self.y.v.into()),
        )
    }
    fn step(&mut self, t_limit: f64) -> Result<()> {
        Radau5Stepper::step(self, t_limit)
    }
    fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }
    fn stats(&self) -> Stats {
        self.stats
    }
    fn count_event_evaluations(&mut self, n: usize) {
        self.stats.event_evaluations += n;
    }
    fn max_steps(&self) -> usize {
        self.settings.max_steps
    }
}

/// `sys.step::<Radau5>(&mut state, h)`: integrates over [t, t + h] with the
/// [default](Radau5::default) tolerances, as many adaptive steps as that takes, landing exactly on
/// t + h (as [`Dopri5`](super::Dopri5) does).
///
/// ```
/// use lagrange_core::{Mechanism, Radau5, State};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Pendulum;
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         vec2(q[0].sin(), -q[0].cos()).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// # }
/// # lagrange_core::impl_mechanism!(Pendulum, 1, 2);
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// Pendulum.step::<Radau5>(&mut s, 0.5)?;
/// assert_eq!(s.t, 0.5);
/// // rtol 1e-6: the energy (4.3 J) moves by about that much of its size.
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-4);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
impl Integrator for Radau5 {
    const NAME: &'static str = "Radau5";
    type Memory<const N: usize> = ();

    fn advance<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        _memory: &mut (),
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        let mut stepper = Radau5Stepper::start(mechanism, Radau5::default(), t, *q, *v)?;
        let t_end = t + h;
        let result = (|| {
            while stepper.t < t_end {
                stepper.step(t_end)?;
            }
            Ok((stepper.y.q.into(), stepper.y.v.into()))
        })();
        *stats += stepper.stats;
        result
    }
}
