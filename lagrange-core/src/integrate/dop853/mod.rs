//! Adaptive Dormand–Prince 8(5,3) — Hairer's DOP853 — with its continuous extension of order 7
//! and event location.
//!
//! - Method: Prince & Dormand, *High order embedded Runge–Kutta formulae*, J. Comput. Appl. Math. 7
//!   (1981); Hairer, Nørsett & Wanner, *Solving ODEs I* (HNW I), §II.10 (Table 10.3 and the
//!   surrounding text). The coefficients below are those of Hairer's published Fortran code
//!   `dop853.f` (E. Hairer and G. Wanner, Université de Genève, version of 2004, distributed with
//!   HNW I), to the digits printed there. Twelve stages; the FSAL evaluation at the new point is
//!   the next step's first stage, so an accepted step costs 12 evaluations (plus 3 for the dense
//!   output).
//! - Error estimate (HNW I §II.10, and `dop853.f`): the 5th-order estimate err₅ and the 3rd-order
//!   estimate err₃ are combined as err = err₅² / √(err₅² + 0.01·err₃²) (norms as in
//!   [`Dopri5`], over all q and v components), which behaves like O(h⁸).
//! - Step-size control: the PI controller of HNW I §II.4 / Hairer & Wanner, *Solving ODEs II*,
//!   §IV.2 (Gustafsson), h_new = h·min(fac_max, max(fac_min, err^(−1/8 + 0.2β)·err_old^β / safety)),
//!   the form of `dop853.f`, with its defaults: β = 0 (the classical controller h_new =
//!   h·min(6, max(0.333, safety·err^(−1/8)))), safety 0.9, fac_min = 0.333, fac_max = 6. With these
//!   the steps are those of `dop853.f` (a test reproduces its driver's counts on Van der Pol's
//!   equation). `beta` stays a setting: β = 0.04 (DOPRI5's default) damps the step-size
//!   oscillations where stability limits the step, at the price of more accepted steps where
//!   accuracy does (BENCHMARKS.md §13 has the counts on the work-precision problems).
//! - Largest step: by default (`h_max` infinite) an integration
//!   ([`Stepper::integrate`](super::Stepper::integrate) from a fresh solver) bounds it by its
//!   interval t_end − t₀, as `dop853.f` does (it also bounds the first step's probe).
//! - Dense output: the continuous extension of order 7 of `dop853.f` (CONTD8), three more
//!   evaluations per accepted step (`dense: false` skips them and interpolates by cubic Hermite
//!   instead, order 3).
//! - Events, the observer, the statistics and the contact mode are those of every solver
//!   ([`Stepper`](super::Stepper)).
//! - Constraints: as [`Dopri5`], the start state must satisfy them and every
//!   accepted step is projected onto them.
//!
//! Integration is forward in time only.

// Coefficients carry the digits printed in dop853.f; stage loops index several arrays;
// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(
    clippy::excessive_precision,
    clippy::needless_range_loop,
    clippy::neg_cmp_op_on_partial_ord,
    clippy::unreadable_literal
)]

use super::dense::DenseOutput;
use super::dopri5::settings::Dopri5;
use super::pair::{explicit_embedded_pair, sealed, AccelerationField, ExplicitPair, StepStart};
use super::Stats;
use crate::error::Result;
use crate::model::Coordinates;

mod attempt;
mod dense;
mod tableau;

pub(crate) use attempt::attempt;
pub use attempt::Stages;
pub(crate) use dense::accept;

/// Settings of the adaptive Dormand–Prince 8(5,3) method (see the [module docs](self)).
///
/// One step: `sys.step::<Dop853>(&mut state, h)` integrates over [t, t + h] with the
/// [default](Dop853::default) tolerances, without the dense output (the step does not need it),
/// landing exactly on t + h (as [`Dopri5`] does).
///
/// ```
/// use lagrange_core::integrate::{Dop853, Stepper};
/// use lagrange_core::{Mechanism, State};
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
/// let s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// let out = Stepper::new(&Pendulum, Dop853::new(1e-12, 1e-14), &s)?.integrate(10.0, &mut [], |_| {})?;
/// // Tolerance 1e-12 per step over ≈ 100 steps: the energy (4.3 J) is kept to ≈ 1e-10 relative.
/// assert!((Pendulum.energy(&out.state)? - e0).abs() < 1e-9);
/// assert!(out.stats.accepted < 300);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dop853 {
    /// Relative tolerance (per component, against max(|y₀|, |y₁|)).
    pub rtol: f64,
    /// Absolute tolerance (per component).
    pub atol: f64,
    /// First step; `None` chooses it (HNW I §II.4).
    pub h_init: Option<f64>,
    /// Largest step; infinite (the default): the interval of an integration from a fresh solver.
    pub h_max: f64,
    /// Most step attempts (accepted + rejected) of one integration.
    pub max_steps: usize,
    /// Safety factor of the step-size controller.
    pub safety: f64,
    /// Smallest factor by which a step may shrink.
    pub fac_min: f64,
    /// Largest factor by which a step may grow.
    pub fac_max: f64,
    /// PI stabilisation exponent β (0: classical controller).
    pub beta: f64,
    /// Whether accepted steps build the 7th-order dense output (three more evaluations each);
    /// otherwise the dense output is the cubic Hermite interpolant.
    pub dense: bool,
}

impl Default for Dop853 {
    /// rtol = 1e-6, atol = 1e-9, `dop853.f`'s controller constants (safety 0.9, factors 0.333…6,
    /// β = 0: the classical controller), dense output on.
    fn default() -> Self {
        Dop853 {
            rtol: 1e-6,
            atol: 1e-9,
            h_init: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            safety: 0.9,
            fac_min: 0.333,
            fac_max: 6.0,
            beta: 0.0,
            dense: true,
        }
    }
}

impl Dop853 {
    /// The default settings with these tolerances.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Dop853 {
            rtol,
            atol,
            ..Dop853::default()
        }
    }

    /// The settings as the shared embedded-pair settings.
    pub(crate) fn shared(&self) -> Dopri5 {
        Dopri5 {
            rtol: self.rtol,
            atol: self.atol,
            h_init: self.h_init,
            h_max: self.h_max,
            max_steps: self.max_steps,
            safety: self.safety,
            fac_min: self.fac_min,
            fac_max: self.fac_max,
            beta: self.beta,
        }
    }

    /// Checks the settings as [`Dopri5::validate`] does.
    pub fn validate(&self) -> Result<()> {
        self.shared().validate_as("Dop853")
    }

    /// The settings for an integration over [t₀, t_end]: an infinite `h_max` becomes the interval
    /// t_end − t₀, as `dop853.f` bounds it (HMAX = XEND − X unless given).
    pub(crate) fn bounded_to(&self, interval: f64) -> Self {
        if self.h_max == f64::INFINITY && interval > 0.0 {
            Dop853 {
                h_max: interval,
                ..*self
            }
        } else {
            *self
        }
    }
}

impl sealed::Sealed for Dop853 {}

impl ExplicitPair for Dop853 {
    const NAME: &'static str = "Dop853";
    const ORDER: i32 = 8;
    const EXPONENTS: (f64, f64) = (1.0 / 8.0, 0.2);
    type Stages<const N: usize> = Stages<N>;

    fn controls(&self) -> Dopri5 {
        self.shared()
    }

    fn one_step_settings() -> Self {
        Dop853 {
            dense: false,
            ..Dop853::default()
        }
    }

    fn bounded_to(&self, interval: f64) -> Self {
        Dop853::bounded_to(self, interval)
    }

    fn stages<const N: usize>() -> Self::Stages<N> {
        Stages::new()
    }

    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: StepStart<'_, N>,
        h: f64,
        stages: &mut Self::Stages<N>,
        stats: &mut Stats,
        field: &impl AccelerationField<N>,
    ) -> Result<([f64; N], [f64; N], f64)> {
        attempt::<C, N>(self, start, h, stages, stats, field)
    }

    fn accept<const N: usize>(
        &self,
        start: StepStart<'_, N>,
        h: f64,
        end: (&[f64; N], &[f64; N]),
        stages: &mut Self::Stages<N>,
        stats: &mut Stats,
        field: &impl AccelerationField<N>,
        dense: &mut DenseOutput<N>,
    ) -> Result<[f64; N]> {
        accept(self, start, h, end, stages, stats, field, dense)
    }
}

explicit_embedded_pair!(Dop853, Stages<N>);
