//! Adaptive Dormand–Prince 5(4) with dense output and event location.
//!
//! - Method: Dormand & Prince, *A family of embedded Runge–Kutta formulae*, J. Comput. Appl. Math. 6
//!   (1980); coefficients as in Hairer, Nørsett & Wanner, *Solving ODEs I* (HNW I), §II.5,
//!   Table 5.2, and Hairer's code DOPRI5. Seven stages, the last evaluated at the new solution and
//!   reused as the first stage of the next step (FSAL), so an accepted step costs 6 evaluations.
//! - Error control (HNW I §II.4, (4.10)–(4.13)): err = √(1/n Σ (eᵢ/scᵢ)²) with
//!   scᵢ = atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|) over all q and v components; the step is accepted when
//!   err ≤ 1 and the new step is h·min(fac_max, max(fac_min, safety·err^(−1/5)·PI)). The optional PI
//!   factor err_old^β with exponent 1/5 − 0.75β is Gustafsson's stabilisation as in DOPRI5 (HNW II
//!   §IV.2 / HNW I §II.4, β = 0.04 by default, β = 0 gives the classical controller). After a rejection
//!   the step does not grow.
//! - Initial step: HNW I §II.4, "Starting step size" (Hairer's routine HINIT), one extra evaluation.
//! - Dense output: the continuous extension of order 4 of DOPRI5 (HNW I §II.6, (6.12) and the
//!   coefficients d₁…d₇ of Hairer's DOPRI5/CONTD5), no extra evaluation:
//!   y(t₀ + θh) = r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ) r₅))).
//! - Events: after each accepted step every event function g(state) is evaluated at the new point;
//!   a sign change in the event's direction is located on the dense output by the Illinois variant of
//!   regula falsi (Dowell & Jarratt, BIT 11 (1971)), which keeps a bracket, until the bracket is
//!   shorter than max(1e-13, 4ε|t|) (so within 1e-12 of the root of g on the dense output; the
//!   distance to the exact root is then that of the dense solution, O(tolerance)). Events in one step
//!   are reported in time order; a terminal event ends the integration at its time, with the state
//!   taken from the dense output. An event function with two roots inside one step shows no sign
//!   change and is missed: bound `h_max` if that matters.
//!
//! - Constraints: the start state must satisfy the mechanism's constraints
//!   (`Dynamics::check_constraints`); every accepted step is projected onto them
//!   (`Dynamics::project`, a no-op without constraints). The dense output interpolates the step
//!   before projection, which moves the end point by about the local error.
//!
//! Integration is forward in time only.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::solver::{check_step, Stepper};
pub use super::solver::{Direction, Event, EventHit, Observation, Outcome, Stats, StopReason};
use super::Integrator;
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};

// Nodes and coefficients: HNW I, Table 5.2 (DOPRI5).
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Error estimate coefficients eᵢ = bᵢ − b̂ᵢ (Hairer's DOPRI5).
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output (Hairer's DOPRI5, CONTD5; HNW I §II.6).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Width under which an event's bracket counts as located (absolute, in time units; widened to
/// 4 ulp of t for large t).
pub const EVENT_TIME_TOLERANCE: f64 = 1e-13;

/// Settings of the adaptive Dormand–Prince 5(4) method (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dopri5 {
    /// Relative tolerance (per component, against max(|y₀|, |y₁|)).
    pub rtol: f64,
    /// Absolute tolerance (per component).
    pub atol: f64,
    /// First step; `None` chooses it (HNW I §II.4).
    pub h_init: Option<f64>,
    /// Largest step.
    pub h_max: f64,
    /// Most step attempts (accepted + rejected) of one [`Dopri5::integrate`] call.
    pub max_steps: usize,
    /// Safety factor of the step-size controller.
    pub safety: f64,
    /// Smallest factor by which a step may shrink.
    pub fac_min: f64,
    /// Largest factor by which a step may grow.
    pub fac_max: f64,
    /// PI stabilisation exponent β (0: classical controller).
    pub beta: f64,
}

impl Default for Dopri5 {
    /// rtol = 1e-6, atol = 1e-9, DOPRI5's controller constants (safety 0.9, factors 0.2…10, β = 0.04).
    fn default() -> Self {
        Dopri5 {
            rtol: 1e-6,
            atol: 1e-9,
            h_init: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            safety: 0.9,
            fac_min: 0.2,
            fac_max: 10.0,
            beta: 0.04,
        }
    }
}

/// What a Dormand–Prince integration cost (the statistics every solver keeps).
pub type Dopri5Stats = Stats;

/// The result of [`Dopri5::integrate`].
pub type Dopri5Outcome<C> = Outcome<C>;

/// The dense output of one step: a polynomial in time for q and v over [t₀, t₀ + h], in the form
/// of Hairer's CONTD5, y(t₀ + θh) = r₁ + θ(r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ) r₅))): of order 4 for
/// Dopri5, and the cubic Hermite interpolant (r₅ = 0) of the end values and derivatives for the
/// other methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseOutput<const N: usize> {
    t0: f64,
    h: f64,
    q: [[f64; N]; 8],
    v: [[f64; N]; 8],
    /// Coefficients in use: 5 (Dopri5, Hermite) or 8 (Dop853).
    terms: usize,
}

impl<const N: usize> DenseOutput<N> {
    pub(crate) fn constant(t: f64, q: &[f64; N], v: &[f64; N]) -> Self {
        let mut d = DenseOutput {
            t0: t,
            h: 0.0,
            q: [[0.0; N]; 8],
            v: [[0.0; N]; 8],
            terms: 5,
        };
        d.q[0] = *q;
        d.v[0] = *v;
        d
    }

    /// The cubic Hermite interpolant over [t₀, t₀ + h] of (q, v) with derivatives (v, q̈) at both
    /// ends (`start` and `end` are (q, v, q̈)): order 3 (HNW I §II.6, (6.7)).
    pub(crate) fn hermite(
        t0: f64,
        h: f64,
        start: (&[f64; N], &[f64; N], &[f64; N]),
        end: (&[f64; N], &[f64; N], &[f64; N]),
    ) -> Self {
        let make = |y0: &[f64; N], y1: &[f64; N], d0: &[f64; N], d1: &[f64; N]| {
            let mut r = [[0.0; N]; 8];
            for i in 0..N {
                let diff = y1[i] - y0[i];
                let bspl = h * d0[i] - diff;
                r[0][i] = y0[i];
                r[1][i] = diff;
                r[2][i] = bspl;
                r[3][i] = diff - h * d1[i] - bspl;
            }
            r
        };
        DenseOutput {
            t0,
            h,
            q: make(start.0, end.0, start.1, end.1),
            v: make(start.1, end.1, start.2, end.2),
            terms: 5,
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

impl Dopri5 {
    /// The default settings with these tolerances.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Dopri5 {
            rtol,
            atol,
            ..Dopri5::default()
        }
    }

    /// Checks the settings: tolerances finite, non-negative and not both zero, step-control
    /// factors in their ranges, `max_steps` at least 1 ([`Error::InvalidSetting`] naming the
    /// setting), the initial step positive and finite ([`Error::InvalidStep`]).
    pub fn validate(&self) -> Result<()> {
        self.validate_as("Dopri5")
    }

    /// [`validate`](Self::validate), naming `method` in the errors (the settings are shared with
    /// [`Dop853`](super::Dop853)).
    pub(crate) fn validate_as(&self, method: &'static str) -> Result<()> {
        let invalid = |setting, value, requirement| {
            Err(Error::InvalidSetting {
                method,
                setting,
                value,
                requirement,
            })
        };
        for (name, value) in [("rtol", self.rtol), ("atol", self.atol)] {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(name, value, "finite and non-negative");
            }
        }
        if self.rtol == 0.0 && self.atol == 0.0 {
            return invalid("rtol", 0.0, "positive when atol is zero");
        }
        for (name, value, ok, requirement) in [
            (
                "safety",
                self.safety,
                self.safety > 0.0 && self.safety <= 1.0,
                "in (0, 1]",
            ),
            (
                "fac_min",
                self.fac_min,
                self.fac_min > 0.0 && self.fac_min <= 1.0,
                "in (0, 1]",
            ),
            (
                "fac_max",
                self.fac_max,
                self.fac_max >= 1.0 && self.fac_max.is_finite(),
                "finite and at least 1",
            ),
            (
                "beta",
                self.beta,
                (0.0..0.2).contains(&self.beta),
                "in [0, 0.2)",
            ),
        ] {
            if !ok {
                return invalid(name, value, requirement);
            }
        }
        if !(self.h_max > 0.0) {
            return invalid("h_max", self.h_max, "positive");
        }
        if self.max_steps == 0 {
            return invalid("max_steps", 0.0, "at least 1");
        }
        if let Some(h) = self.h_init {
            check_step(h)?;
        }
        Ok(())
    }

    /// Integrates from `state` to `t_end` (≥ state.t), calling `observer` after every accepted
    /// step and for every located event, and stopping early at a terminal event or after
    /// `max_steps` attempts. On success `state` is the final state (at t_end, at the terminal event,
    /// or the last accepted one); on error `state` is unchanged. No allocation.
    ///
    /// A mechanism with unilateral contacts or friction is integrated here with its mode re-inferred
    /// at every evaluation, so each mode switch falls inside a step and costs many rejected steps:
    /// use [`integrate_contacts`](Self::integrate_contacts) for it, which fixes the mode over a
    /// step and locates the switches.
    pub fn integrate<M: Mechanism<N>, const N: usize>(
        &self,
        mechanism: &M,
        state: &mut State<M::Coords>,
        t_end: f64,
        events: &mut [Event<'_, M::Coords>],
        mut observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<Dopri5Outcome<M::Coords>> {
        if !(t_end.is_finite() && t_end >= state.t) {
            return Err(Error::InvalidEndTime { t: state.t, t_end });
        }
        // Unilateral and friction rows: the mode held per step, its switches located.
        if let Some(outcome) =
            mechanism.integrate_contacts(*self, state, t_end, events, &mut observer)
        {
            return outcome;
        }
        let mut stepper = Dopri5Stepper::new(mechanism, *self, state)?;
        let outcome = stepper.integrate(t_end, events, observer)?;
        *state = match outcome.reason {
            StopReason::Event(hit) => hit.state,
            _ => stepper.state(),
        };
        Ok(outcome)
    }
}

/// The starting step of an embedded pair of order `order` (HNW I §II.4, "Starting step size";
/// Hairer's HINIT): one extra evaluation of q̈.
pub(crate) fn initial_step<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    st: &Dopri5,
    start: (f64, &[f64; N], &[f64; N], &[f64; N]),
    order: i32,
    stats: &mut Stats,
) -> f64 {
    initial_step_on(
        |t, q, v| mechanism.accelerations_at(t, q, v),
        st,
        start,
        order,
        stats,
    )
}

/// [`initial_step`] on the accelerations `acc` (those of a frozen constraint mode, say).
pub(crate) fn initial_step_on<const N: usize>(
    acc: impl FnOnce(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    st: &Dopri5,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    order: i32,
    stats: &mut Stats,
) -> f64 {
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..N {
        let sq = st.atol + st.rtol * q[i].abs();
        let sv = st.atol + st.rtol * v[i].abs();
        dnf += (v[i] / sq).powi(2) + (a[i] / sv).powi(2);
        dny += (q[i] / sq).powi(2) + (v[i] / sv).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(st.h_max);
    let q1: [f64; N] = std::array::from_fn(|i| q[i] + h * v[i]);
    let v1: [f64; N] = std::array::from_fn(|i| v[i] + h * a[i]);
    stats.evaluations += 1;
    let Ok(a1) = acc(t + h, &q1, &v1) else {
        return h;
    };
    let mut der2 = 0.0;
    for i in 0..N {
        let sq = st.atol + st.rtol * q[i].abs();
        let sv = st.atol + st.rtol * v[i].abs();
        der2 += ((v1[i] - v[i]) / sq).powi(2) + ((a1[i] - a[i]) / sv).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / order as f64)
    };
    let h = (100.0 * h).min(h1).min(st.h_max);
    if h.is_finite() && h > 0.0 {
        h
    } else {
        1e-6
    }
}

/// The step size and the previous error of an explicit embedded pair's controller: the memory
/// ([`EmbeddedPair::Memory`](super::EmbeddedPair::Memory)) of [`Dopri5`] and
/// [`Dop853`](super::Dop853) from one step to the next.
#[derive(Clone, Copy, Debug)]
pub struct Controller {
    pub(crate) h: f64,
    pub(crate) fac_old: f64,
}

/// The step loop and PI step-size controller shared by the embedded pairs (Dopri5, Dop853):
/// attempts steps of the controller's size (the last one shortened to land on `t_limit`, and
/// steps within 1 % of it stretched to it), rejecting and shrinking until `attempt` reports an
/// error norm ≤ 1, and returns the accepted trial, its h and its end time. The controller is
/// h_new = h·min(1/fac_min, max(1/fac_max, safety⁻¹·err^(p − β·w)·err_old^(−β)))⁻¹ with
/// (p, w) = `exponents` = (1/5, 0.75) for Dopri5 and (1/8, 0.2) for Dop853 (HNW I §II.4;
/// Hairer & Wanner, *Solving ODEs II*, §IV.2; the forms of Hairer's DOPRI5 and DOP853); after a
/// rejection the step does not grow. A failing attempt (singular mass matrix, non-finite
/// dynamics) counts as a rejection with the step cut by `fac_min`; when the step can no longer
/// shrink (0.1·h below round-off of t) the last failure is returned
/// ([`Error::StepSizeUnderflow`] if steps were rejected only for accuracy).
#[allow(clippy::too_many_arguments)]
pub(crate) fn adaptive_step<T>(
    method: &'static str,
    st: &Dopri5,
    (exponent, weight): (f64, f64),
    t: f64,
    t_limit: f64,
    control: &mut Controller,
    stats: &mut Stats,
    mut attempt: impl FnMut(f64, &mut Stats) -> Result<(T, f64)>,
) -> Result<(T, f64, f64)> {
    if !(t_limit > t) || !t_limit.is_finite() {
        return Err(Error::InvalidEndTime { t, t_end: t_limit });
    }
    let expo1 = exponent - st.beta * weight;
    let mut last_rejected = false;
    let mut last_error: Option<Error> = None;
    loop {
        let mut h = control.h.min(st.h_max);
        let last = t + 1.01 * h >= t_limit;
        if last {
            h = t_limit - t;
        }
        if !(t + 0.1 * h > t) {
            return Err(last_error.unwrap_or(Error::StepSizeUnderflow { method, t, h }));
        }
        match attempt(h, stats) {
            Ok((trial, err)) => {
                let fac11 = err.powf(expo1);
                if err <= 1.0 {
                    let fac = (fac11 / control.fac_old.powf(st.beta) / st.safety)
                        .clamp(1.0 / st.fac_max, 1.0 / st.fac_min);
                    let mut h_new = h / fac;
                    if last_rejected {
                        h_new = h_new.min(h);
                    }
                    control.fac_old = err.max(1e-4);
                    control.h = h_new;
                    stats.accepted += 1;
                    let t_new = if last { t_limit } else { t + h };
                    return Ok((trial, h, t_new));
                }
                control.h = h / (1.0 / st.fac_min).min(fac11 / st.safety);
            }
            Err(e) => {
                control.h = h * st.fac_min;
                last_error = Some(e);
            }
        }
        last_rejected = true;
        stats.rejected += 1;
    }
}

/// Projects an accepted step's end onto the constraints (a no-op without any); if that moved it,
/// checks it and re-evaluates q̈ there. Returns (q, v, q̈) at the projected state.
#[allow(clippy::type_complexity)]
pub(crate) fn project_accepted<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    (q1, v1, a1): ([f64; N], [f64; N], [f64; N]),
    stats: &mut Stats,
) -> Result<([f64; N], [f64; N], [f64; N])> {
    let (mut qp, mut vp, mut ap) = (q1, v1, a1);
    mechanism.project(t, &mut qp, &mut vp)?;
    if qp != q1 || vp != v1 {
        check_state(&M::Coords::NAMES, t, &qp, &vp)?;
        stats.evaluations += 1;
        ap = mechanism
            .accelerations_at(t, &qp, &vp)
            .map_err(|e| diagnose(mechanism, t, &qp, &vp, e))?;
    }
    Ok((qp, vp, ap))
}

/// Step-by-step use of [`Dopri5`]: holds the current state, the proposed next step and the dense
/// output of the last accepted step.
///
/// ```
/// # use lagrange_core::integrate::{Dopri5, Dopri5Stepper};
/// # fn demo<M: lagrange_core::Mechanism<2, Coords = [f64; 2]>>(m: &M) -> lagrange_core::Result<()> {
/// let start = lagrange_core::State::new(0.0, [0.1, 0.0], [0.0, 0.0]);
/// let mut stepper = Dopri5Stepper::new(m, Dopri5::new(1e-8, 1e-10), &start)?;
/// while stepper.t() < 10.0 {
///     stepper.step(10.0)?; // one accepted step, never past 10
///     let (q_mid, _v_mid) = stepper.dense().eval(stepper.t() - 0.5 * stepper.last_step());
/// }
/// # Ok(()) }
/// ```
pub struct Dopri5Stepper<'m, M: Mechanism<N>, const N: usize> {
    mechanism: &'m M,
    settings: Dopri5,
    t: f64,
    q: [f64; N],
    v: [f64; N],
    a: [f64; N],
    h: f64,
    fac_old: f64,
    dense: DenseOutput<N>,
    stats: Dopri5Stats,
}

/// e/sc of the error norm, with 0/0 = 0 (an exact component with a zero scale, possible when
/// atol = 0) and e/0 = ∞ otherwise.
#[inline(always)]
pub(crate) fn ratio(e: f64, scale: f64) -> f64 {
    if e == 0.0 {
        0.0
    } else {
        e / scale
    }
}

/// y + h Σⱼ coefⱼ kⱼ, componentwise, on any scalar (the f64 operations in the same order).
#[inline(always)]
pub(crate) fn combo<T: Scalar, const N: usize, const S: usize>(
    y: &[T; N],
    h: f64,
    coef: [f64; S],
    k: [&[T; N]; S],
) -> [T; N] {
    std::array::from_fn(|i| {
        let mut s = T::zero();
        for j in 0..S {
            s += k[j][i] * coef[j];
        }
        y[i] + s * h
    })
}

/// The stages of one Dormand–Prince step of size h from (t, q, v) with q̈ = `a1` there: the new
/// (q₁, v₁) and the stage velocities kq and accelerations ka of stages 1…6 (stage 7, FSAL, is q̈ at
/// the new point). On any scalar: the f64 step, and the trajectory sensitivities on dual numbers.
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(crate) fn stages<T: Scalar, const N: usize>(
    t: f64,
    q: &[T; N],
    v: &[T; N],
    a1: [T; N],
    h: f64,
    mut acc: impl FnMut(f64, &[T; N], &[T; N]) -> Result<[T; N]>,
) -> Result<([T; N], [T; N], [[T; N]; 6], [[T; N]; 6])> {
    let (kq1, ka1) = (*v, a1);
    // Stage i: position increments use the stage velocities kqⱼ, velocity increments the stage
    // accelerations kaⱼ.
    let (q2, v2) = (combo(q, h, [A21], [&kq1]), combo(v, h, [A21], [&ka1]));
    let ka2 = acc(t + C2 * h, &q2, &v2)?;
    let kq2 = v2;
    let (q3, v3) = (
        combo(q, h, [A31, A32], [&kq1, &kq2]),
        combo(v, h, [A31, A32], [&ka1, &ka2]),
    );
    let ka3 = acc(t + C3 * h, &q3, &v3)?;
    let kq3 = v3;
    let (q4, v4) = (
        combo(q, h, [A41, A42, A43], [&kq1, &kq2, &kq3]),
        combo(v, h, [A41, A42, A43], [&ka1, &ka2, &ka3]),
    );
    let ka4 = acc(t + C4 * h, &q4, &v4)?;
    let kq4 = v4;
    let (q5, v5) = (
        combo(q, h, [A51, A52, A53, A54], [&kq1, &kq2, &kq3, &kq4]),
        combo(v, h, [A51, A52, A53, A54], [&ka1, &ka2, &ka3, &ka4]),
    );
    let ka5 = acc(t + C5 * h, &q5, &v5)?;
    let kq5 = v5;
    let (q6, v6) = (
        combo(
            q,
            h,
            [A61, A62, A63, A64, A65],
            [&kq1, &kq2, &kq3, &kq4, &kq5],
        ),
        combo(
            v,
            h,
            [A61, A62, A63, A64, A65],
            [&ka1, &ka2, &ka3, &ka4, &ka5],
        ),
    );
    let ka6 = acc(t + h, &q6, &v6)?;
    let kq6 = v6;
    let q1 = combo(
        q,
        h,
        [A71, A73, A74, A75, A76],
        [&kq1, &kq3, &kq4, &kq5, &kq6],
    );
    let v1 = combo(
        v,
        h,
        [A71, A73, A74, A75, A76],
        [&ka1, &ka3, &ka4, &ka5, &ka6],
    );
    Ok((
        q1,
        v1,
        [kq1, kq2, kq3, kq4, kq5, kq6],
        [ka1, ka2, ka3, ka4, ka5, ka6],
    ))
}

impl<'m, M: Mechanism<N>, const N: usize> Dopri5Stepper<'m, M, N> {
    /// Starts at `state`: validates settings, mechanism and state, evaluates q̈ and chooses the
    /// first step.
    pub fn new(mechanism: &'m M, settings: Dopri5, state: &State<M::Coords>) -> Result<Self> {
        settings.validate()?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        Self::start(mechanism, settings, state.t, q, v)
    }

    /// Starts at (t, q, v), already checked.
    fn start(mechanism: &'m M, settings: Dopri5, t: f64, q: [f64; N], v: [f64; N]) -> Result<Self> {
        let a = mechanism
            .accelerations_at(t, &q, &v)
            .map_err(|e| diagnose(mechanism, t, &q, &v, e))?;
        let state = State::<M::Coords>::new(t, M::Coords::from_array(q), M::Coords::from_array(v));
        let mut s = Dopri5Stepper {
            mechanism,
            settings,
            t: state.t,
            q,
            v,
            a,
            h: 0.0,
            fac_old: 1e-4,
            dense: DenseOutput::constant(state.t, &q, &v),
            stats: Dopri5Stats {
                evaluations: 1,
                ..Dopri5Stats::default()
            },
        };
        s.h = match settings.h_init {
            Some(h) => h.min(settings.h_max),
            None => s.initial_step(),
        };
        Ok(s)
    }

    /// HNW I §II.4, "Starting step size" (Hairer's HINIT, order 5).
    fn initial_step(&mut self) -> f64 {
        initial_step(
            self.mechanism,
            &self.settings,
            (self.t, &self.q, &self.v, &self.a),
            5,
            &mut self.stats,
        )
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.q),
            M::Coords::from_array(self.v),
        )
    }

    /// Dense output of the last accepted step (a constant before the first step).
    pub fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }

    /// Length of the last accepted step.
    pub fn last_step(&self) -> f64 {
        self.dense.h
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.h
    }

    /// Cost so far.
    pub fn stats(&self) -> Dopri5Stats {
        self.stats
    }

    /// Takes one accepted step, not past `t_limit` (> current time), rejecting and shrinking as
    /// needed. A stage that fails (singular mass matrix, non-finite dynamics) counts as a rejection
    /// with the step cut by `fac_min`; when the step can no longer shrink (0.1·h below round-off of t)
    /// the last failure is returned ([`Error::StepSizeUnderflow`] if steps were rejected only for
    /// accuracy). On error the accepted state is unchanged.
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        let mut control = Controller {
            h: self.h,
            fac_old: self.fac_old,
        };
        let mut stats = self.stats;
        let this = &*self;
        let ((q1, v1, a1, k), h, t_new) = adaptive_step(
            "Dopri5",
            &self.settings,
            (0.2, 0.75),
            self.t,
            t_limit,
            &mut control,
            &mut stats,
            |h, stats| {
                this.attempt(h, stats)
                    .map(|(q1, v1, a1, err, k)| ((q1, v1, a1, k), err))
            },
        )?;
        // Accepted. The dense output interpolates the step as computed; the state is then projected
        // onto the constraints (a no-op without any: then nothing changes and nothing is
        // re-evaluated). If the projection moved it, the FSAL acceleration is re-evaluated at the
        // projected state.
        let (qp, vp, ap) = project_accepted(self.mechanism, t_new, (q1, v1, a1), &mut stats)?;
        self.dense = self.build_dense(h, &q1, &v1, &a1, &k);
        (self.t, self.q, self.v, self.a) = (t_new, qp, vp, ap);
        (self.h, self.fac_old, self.stats) = (control.h, control.fac_old, stats);
        Ok(())
    }

    /// One trial step of size h ([`trial`] on the mechanism's accelerations).
    #[allow(clippy::type_complexity)]
    fn attempt(
        &self,
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N], [f64; N], f64, [[f64; N]; 8])> {
        let m = self.mechanism;
        trial::<M::Coords, N>(
            &self.settings,
            (self.t, &self.q, &self.v, &self.a),
            h,
            stats,
            |t, q, v| {
                m.accelerations_at(t, q, v)
                    .map_err(|e| diagnose(m, t, q, v, e))
            },
        )
    }

    fn build_dense(
        &self,
        h: f64,
        q1: &[f64; N],
        v1: &[f64; N],
        _a1: &[f64; N],
        k: &[[f64; N]; 8],
    ) -> DenseOutput<N> {
        dense_output(self.t, h, (&self.q, &self.v), (q1, v1), k)
    }
}

/// One trial step of Dormand–Prince 5(4) of size h from (t, q, v) with q̈ = `a` there, on the
/// accelerations `acc`: (q₁, v₁, q̈₁, err, stage data for [`dense_output`]). What [`Dopri5Stepper`]
/// attempts on a mechanism's accelerations, and the contact solver on the accelerations of a frozen
/// constraint mode. Adds its evaluations of `acc` to `stats`.
#[allow(clippy::type_complexity)]
pub(crate) fn trial<C: Coordinates<N>, const N: usize>(
    st: &Dopri5,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
    mut acc: impl FnMut(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<([f64; N], [f64; N], [f64; N], f64, [[f64; N]; 8])> {
    let (q1, v1, kq, ka) = stages(t, q, v, *a, h, |t, q, v| {
        stats.evaluations += 1;
        acc(t, q, v)
    })?;
    let [kq1, _, kq3, kq4, kq5, kq6] = kq;
    let [ka1, _, ka3, ka4, ka5, ka6] = ka;
    check_state(&C::NAMES, t + h, &q1, &v1)?;
    stats.evaluations += 1;
    let ka7 = acc(t + h, &q1, &v1)?;
    let kq7 = v1;
    let mut sum = 0.0;
    for i in 0..N {
        let eq =
            h * (E1 * kq1[i] + E3 * kq3[i] + E4 * kq4[i] + E5 * kq5[i] + E6 * kq6[i] + E7 * kq7[i]);
        let ev =
            h * (E1 * ka1[i] + E3 * ka3[i] + E4 * ka4[i] + E5 * ka5[i] + E6 * ka6[i] + E7 * ka7[i]);
        let sq = st.atol + st.rtol * q[i].abs().max(q1[i].abs());
        let sv = st.atol + st.rtol * v[i].abs().max(v1[i].abs());
        sum += ratio(eq, sq).powi(2) + ratio(ev, sv).powi(2);
    }
    // Every stage is finite here (checked above), so an infinite error norm is an error far
    // above a tolerance near the bottom of the floating-point range (rtol = atol = 1e-300):
    // a rejection like any other, which ends in a step-size underflow if it persists.
    let err = (sum / (2 * N) as f64).sqrt();
    if err.is_nan() {
        return Err(Error::NonFiniteDynamics {
            t: t + h,
            configuration: crate::error::describe_configuration(&C::NAMES, &q1),
        });
    }
    // The dense output needs d-weighted sums of the stages for q and v.
    let dq = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&kq1, &kq3, &kq4, &kq5, &kq6, &kq7],
    );
    let dv = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&ka1, &ka3, &ka4, &ka5, &ka6, &ka7],
    );
    Ok((
        q1,
        v1,
        ka7,
        err,
        [kq1, ka1, kq7, ka7, dq, dv, [0.0; N], [0.0; N]],
    ))
}

/// The dense output of an accepted [`trial`] of size h from (t₀, q₀, v₀) to (q₁, v₁): Hairer's
/// CONTD5 (HNW I §II.6), order 4, no extra evaluation.
pub(crate) fn dense_output<const N: usize>(
    t0: f64,
    h: f64,
    (q0, v0): (&[f64; N], &[f64; N]),
    (q1, v1): (&[f64; N], &[f64; N]),
    k: &[[f64; N]; 8],
) -> DenseOutput<N> {
    let [kq1, ka1, kq7, ka7, dq, dv, _, _] = k;
    let make = |y0: &[f64; N],
                y1: &[f64; N],
                k1: &[f64; N],
                k7: &[f64; N],
                d: &[f64; N]|
     -> [[f64; N]; 8] {
        let mut r = [[0.0; N]; 8];
        for i in 0..N {
            let diff = y1[i] - y0[i];
            let bspl = h * k1[i] - diff;
            r[0][i] = y0[i];
            r[1][i] = diff;
            r[2][i] = bspl;
            r[3][i] = diff - h * k7[i] - bspl;
            r[4][i] = h * d[i];
        }
        r
    };
    DenseOutput {
        t0,
        h,
        q: make(q0, q1, kq1, kq7, dq),
        v: make(v0, v1, ka1, ka7, dv),
        terms: 5,
    }
}

impl<M: Mechanism<N>, const N: usize> Stepper<M::Coords, N> for Dopri5Stepper<'_, M, N> {
    fn name(&self) -> &'static str {
        "Dopri5"
    }
    fn t(&self) -> f64 {
        self.t
    }
    fn state(&self) -> State<M::Coords> {
        Dopri5Stepper::state(self)
    }
    fn step(&mut self, t_limit: f64) -> Result<()> {
        Dopri5Stepper::step(self, t_limit)
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

/// `sys.step::<Dopri5>(&mut state, h)`: integrates over [t, t + h] with the
/// [default](Dopri5::default) tolerances (rtol 1e-6, atol 1e-9), as many adaptive steps as that
/// takes, landing exactly on t + h — the state advances by h, as with every fixed-step method.
/// For other tolerances, dense output or events use [`Dopri5::integrate`] or a [`Dopri5Stepper`].
///
/// ```
/// use lagrange_core::{Dopri5, Mechanism, State};
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
/// Pendulum.step::<Dopri5>(&mut s, 0.5)?;
/// assert_eq!(s.t, 0.5);
/// // rtol 1e-6 per step: the energy moves by about that much of its size (4.3 J).
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-5);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
impl Integrator for Dopri5 {
    const NAME: &'static str = "Dopri5";
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
        let mut stepper = Dopri5Stepper::start(mechanism, Dopri5::default(), t, *q, *v)?;
        let t_end = t + h;
        let result = (|| {
            while stepper.t < t_end {
                stepper.step(t_end)?;
            }
            Ok((stepper.q, stepper.v))
        })();
        *stats += stepper.stats;
        result
    }
}
