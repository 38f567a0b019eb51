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
//! - Events, the observer, the statistics and the contact mode are those of every solver
//!   ([`Stepper`](super::Stepper)); events are located on the dense output.
//! - Constraints: the start state must satisfy the mechanism's constraints
//!   (`Dynamics::check_constraints`); every accepted step is projected onto them
//!   (`Dynamics::project`, a no-op without constraints). The dense output interpolates the step
//!   before projection, which moves the end point by about the local error; q̈ at the end,
//!   evaluated before the projection, stays the next step's first stage for the same reason.
//!
//! Integration is forward in time only.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::dense::DenseOutput;
use super::pair::{explicit_embedded_pair, sealed, AccelerationField, ExplicitPair, StepStart};
use super::Stats;
use crate::error::Result;
use crate::geometry::Scalar;
use crate::model::Coordinates;

pub(crate) mod settings;
mod stages;
mod tableau;

pub use settings::Dopri5;
pub(crate) use stages::{dense_output, stages, trial, Stages};

impl sealed::Sealed for Dopri5 {}

impl ExplicitPair for Dopri5 {
    const NAME: &'static str = "Dopri5";
    const ORDER: i32 = 5;
    const EXPONENTS: (f64, f64) = (0.2, 0.75);
    const REPLAYS_ON_DUALS: bool = true;
    type Stages<const N: usize> = Stages<N>;

    fn controls(&self) -> Dopri5 {
        *self
    }

    fn one_step_settings() -> Self {
        Dopri5::default()
    }

    /// The method's stages ([`stages`]) on any scalar, from q̈ evaluated at the start.
    fn replay<S: Scalar, const N: usize>(
        t: f64,
        (q, v): (&[S; N], &[S; N]),
        h: f64,
        rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
        mut acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
    ) -> Option<Result<([S; N], [S; N])>> {
        let step = || {
            let a = acc(t, q, v)?;
            let (q1, v1, _, _) = stages(t, (q, v), a, h, rates, acc)?;
            Ok((q1, v1))
        };
        Some(step())
    }

    fn stages<const N: usize>() -> Self::Stages<N> {
        ([0.0; N], [[0.0; N]; 6])
    }

    #[inline(always)]
    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: StepStart<'_, N>,
        h: f64,
        stages: &mut Self::Stages<N>,
        stats: &mut Stats,
        field: &impl AccelerationField<N>,
    ) -> Result<([f64; N], [f64; N], f64)> {
        let rates = |q: &[f64; N], v: &[f64; N]| field.position_rates(q, v);
        trial::<C, N>(self, start, h, stages, stats, rates, |t, q, v| {
            field.accelerations(t, q, v)
        })
    }

    #[inline(always)]
    fn accept<const N: usize>(
        &self,
        (t, q, v, _): StepStart<'_, N>,
        h: f64,
        end: (&[f64; N], &[f64; N]),
        (a1, k): &mut Self::Stages<N>,
        _stats: &mut Stats,
        _field: &impl AccelerationField<N>,
        dense: &mut DenseOutput<N>,
    ) -> Result<[f64; N]> {
        *dense = dense_output(t, h, (q, v), end, k);
        Ok(*a1)
    }
}

explicit_embedded_pair!(Dopri5, Stages<N>);
