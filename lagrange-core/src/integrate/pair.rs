//! [`EmbeddedPair`]: the adaptive explicit Runge–Kutta pairs ([`Dopri5`], [`Dop853`]) as one
//! interface over an acceleration closure, for a solver that evaluates its own right-hand side:
//! the contact solver [`ContactAdaptive`](crate::constraints::ContactAdaptive), which freezes the
//! constraint mode over each step.

use super::dop853::{self, Dop853};
use super::dopri5::{self, DenseOutput, Dopri5};
use super::Stats;
use crate::error::Result;
use crate::model::Coordinates;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Dopri5 {}
    impl Sealed for super::Dop853 {}
}

/// An adaptive embedded Runge–Kutta pair with dense output: [`Dopri5`] or [`Dop853`] (sealed).
/// Its step-size control is the shared PI controller of both (their settings), its attempts and
/// dense output are evaluated on any accelerations q̈(t, q, q̇).
pub trait EmbeddedPair: Copy + sealed::Sealed {
    /// The method's name.
    const NAME: &'static str;
    /// The order of the propagated solution, for the choice of the first step (HNW I §II.4).
    const ORDER: i32;
    /// The controller's exponents (p, w): err^(p − β·w) (see the adaptive step loop).
    const EXPONENTS: (f64, f64);
    /// What an attempted step hands to [`accept`](Self::accept): the new point and the stages.
    type Attempt<const N: usize>;

    /// The step-control settings, in the form both methods share.
    fn controls(&self) -> Dopri5;

    /// Checks the settings ([`Dopri5::validate`], [`Dop853::validate`]).
    fn validate(&self) -> Result<()>;

    /// One trial step of size h from (t, q, q̇) with q̈ = `a` there, on `acc`: (q₁, q̇₁), the error
    /// norm, and what [`accept`](Self::accept) needs. Adds its evaluations to `stats`.
    #[allow(clippy::type_complexity)]
    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        stats: &mut Stats,
        acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], [f64; N], f64, Self::Attempt<N>)>;

    /// Completes an accepted attempt: q̈₁ at the new point and the step's dense output.
    fn accept<const N: usize>(
        &self,
        start: (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        attempt: Self::Attempt<N>,
        stats: &mut Stats,
        acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], DenseOutput<N>)>;
}

impl EmbeddedPair for Dopri5 {
    const NAME: &'static str = "Dopri5";
    const ORDER: i32 = 5;
    const EXPONENTS: (f64, f64) = (0.2, 0.75);
    /// (q₁, q̇₁, q̈₁ (FSAL), stage data of the dense output).
    type Attempt<const N: usize> = ([f64; N], [f64; N], [f64; N], [[f64; N]; 8]);

    fn controls(&self) -> Dopri5 {
        *self
    }

    fn validate(&self) -> Result<()> {
        Dopri5::validate(self)
    }

    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        stats: &mut Stats,
        acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], [f64; N], f64, Self::Attempt<N>)> {
        let (q1, v1, a1, err, k) = dopri5::trial::<C, N>(self, start, h, stats, acc)?;
        Ok((q1, v1, err, (q1, v1, a1, k)))
    }

    fn accept<const N: usize>(
        &self,
        (t, q, v, _): (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        (q1, v1, a1, k): Self::Attempt<N>,
        _stats: &mut Stats,
        _acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], DenseOutput<N>)> {
        Ok((a1, dopri5::dense_output(t, h, (q, v), (&q1, &v1), &k)))
    }
}

impl EmbeddedPair for Dop853 {
    const NAME: &'static str = "Dop853";
    const ORDER: i32 = 8;
    const EXPONENTS: (f64, f64) = (1.0 / 8.0, 0.2);
    type Attempt<const N: usize> = dop853::Trial<N>;

    fn controls(&self) -> Dopri5 {
        self.shared()
    }

    fn validate(&self) -> Result<()> {
        Dop853::validate(self)
    }

    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        stats: &mut Stats,
        acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], [f64; N], f64, Self::Attempt<N>)> {
        let trial = dop853::attempt::<C, N>(self, start, h, stats, acc)?;
        Ok((trial.q1, trial.v1, trial.err, trial))
    }

    fn accept<const N: usize>(
        &self,
        start: (f64, &[f64; N], &[f64; N], &[f64; N]),
        h: f64,
        mut attempt: Self::Attempt<N>,
        stats: &mut Stats,
        acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    ) -> Result<([f64; N], DenseOutput<N>)> {
        dop853::accept(self, start, h, &mut attempt, stats, acc)
    }
}
