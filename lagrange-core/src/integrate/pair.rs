//! [`EmbeddedPair`]: the adaptive methods with an embedded error estimate and a dense output — the
//! explicit Runge–Kutta pairs [`Dopri5`] and [`Dop853`](super::Dop853) and the implicit
//! [`Radau5`](super::Radau5) — as one interface that takes accepted steps on any
//! [`AccelerationField`]: a mechanism's own accelerations, or those of a contact mode the adaptive
//! loop ([`Stepper`](super::Stepper)) holds over a step.

use super::control::{adaptive_step, initial_step_on, Controller};
use super::dense::DenseOutput;
use super::dopri5::settings::Dopri5;
use super::newton::acceleration_jacobians;
use super::Stats;
use crate::error::{Error, Result};
use crate::evaluation::{diagnose, Dynamics, Evaluate};
use crate::geometry::Scalar;
use crate::model::Coordinates;
use crate::tree::rigid::Joint;
use nalgebra::SMatrix;

/// The methods that are [`EmbeddedPair`]s (each marks itself where it is defined).
pub(crate) mod sealed {
    pub trait Sealed {}
}

/// The right-hand side a step of an [`EmbeddedPair`] integrates: the accelerations q̈(t, q, q̇) of
/// the first-order system y = (q, q̇), y' = (q̇, q̈), and their exact Jacobians for the Newton
/// iteration of an implicit method. A mechanism's own accelerations are one; the accelerations of a
/// constrained mechanism with its contact mode held fixed
/// ([`ContactModel::accelerations`](crate::constraints::ContactModel::accelerations)) are another.
///
/// ```
/// use lagrange_core::integrate::{AccelerationField, DenseOutput, EmbeddedPair, Radau5, Stats};
/// use nalgebra::SMatrix;
///
/// /// The harmonic oscillator q̈ = −q.
/// struct Oscillator;
/// impl AccelerationField<1> for Oscillator {
///     fn accelerations(&self, _t: f64, q: &[f64; 1], _v: &[f64; 1]) -> lagrange_core::Result<[f64; 1]> {
///         Ok([-q[0]])
///     }
///     fn jacobians(
///         &self, _t: f64, _q: &[f64; 1], _v: &[f64; 1],
///     ) -> lagrange_core::Result<(SMatrix<f64, 1, 1>, SMatrix<f64, 1, 1>)> {
///         Ok((SMatrix::from([[-1.0]]), SMatrix::zeros()))
///     }
/// }
///
/// // Radau5 steps on it from q = 1 at rest up to t = 1, where q = cos 1.
/// let method = Radau5::new(1e-10, 1e-10);
/// let mut stats = Stats::default();
/// let (mut t, mut q, mut v, mut a) = (0.0, [1.0], [0.0], [-1.0]);
/// let mut memory = method.start(&Oscillator, (t, &q, &v, &a), &mut stats);
/// let (mut scratch, mut dense) = (Radau5::scratch::<1>(), DenseOutput::constant(t, &q, &v));
/// while t < 1.0 {
///     let start = (t, &q, &v, &a);
///     let step = method.step::<[f64; 1], 1>(&mut memory, &mut scratch, &Oscillator, start, 1.0, &mut stats, &mut dense)?;
///     (t, q, v) = (step.t, step.q, step.v);
///     a = step.a.unwrap_or(Oscillator.accelerations(t, &q, &v)?);
/// }
/// assert!((q[0] - 1f64.cos()).abs() < 1e-9 && t == 1.0);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub trait AccelerationField<const N: usize> {
    /// q̈ at (t, q, q̇) (v̇ at (t, q, v) where the velocities are quasi-velocities).
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<[f64; N]>;

    /// q̇ = G(q) v (see [`Evaluate::position_rates_at`]): v itself, the default.
    #[inline(always)]
    fn position_rates(&self, q: &[f64; N], v: &[f64; N]) -> [f64; N] {
        let _ = q;
        *v
    }

    /// Whether the velocities are quasi-velocities (q̇ = G(q) v, not v), which the methods whose
    /// Newton iteration takes q̇ = v step in the coordinates' rates (Radau5); `false`, the default.
    #[inline(always)]
    fn quasi_velocities(&self) -> bool {
        false
    }

    /// The joints whose velocities are angular velocities, by whose maps G and B the velocities
    /// and the rates convert (`Dynamics::QUASI_VELOCITY_JOINTS`); none, the default.
    #[inline(always)]
    fn quasi_joints(&self) -> &'static [Joint] {
        &[]
    }

    /// The exact Jacobians ∂q̈/∂q and ∂q̈/∂q̇ at (t, q, q̇).
    #[allow(clippy::type_complexity)]
    fn jacobians(
        &self,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)>;
}

/// A mechanism's own accelerations (with the constraint forces of a constrained one), failures
/// diagnosed; Jacobians by dual numbers ([`acceleration_jacobians`]).
pub(crate) struct OfMechanism<'m, M>(pub(crate) &'m M);

impl<M: Evaluate<N>, const N: usize> AccelerationField<N> for OfMechanism<'_, M> {
    #[inline]
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<[f64; N]> {
        let m = self.0;
        m.accelerations_at(t, q, v)
            .map_err(|e| diagnose(m, t, q, v, e))
    }

    #[inline(always)]
    fn position_rates(&self, q: &[f64; N], v: &[f64; N]) -> [f64; N] {
        self.0.position_rates_at(q, v)
    }

    #[inline(always)]
    fn quasi_velocities(&self) -> bool {
        M::QUASI_VELOCITIES
    }

    #[inline(always)]
    fn quasi_joints(&self) -> &'static [Joint] {
        <M::Model as Dynamics<N>>::QUASI_VELOCITY_JOINTS
    }

    fn jacobians(
        &self,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        let m = self.0;
        let (_, by_q, by_v) =
            acceleration_jacobians(m, t, q, v).map_err(|e| diagnose(m, t, q, v, e))?;
        Ok((by_q, by_v))
    }
}

/// The start of a step: (t, q, q̇, q̈).
pub type StepStart<'a, const N: usize> = (f64, &'a [f64; N], &'a [f64; N], &'a [f64; N]);

/// One accepted step of an [`EmbeddedPair`] (its dense output is written where the caller keeps
/// it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accepted<const N: usize> {
    /// Its end time.
    pub t: f64,
    /// q at its end.
    pub q: [f64; N],
    /// q̇ at its end.
    pub v: [f64; N],
    /// q̈ at its end when the method evaluated it anyway (the explicit pairs: first stage of the
    /// next step), `None` when it did not (Radau5).
    pub a: Option<[f64; N]>,
}

/// An adaptive method with an embedded error estimate and a dense output: [`Dopri5`], [`Dop853`](super::Dop853)
/// or [`Radau5`](super::Radau5) (sealed). Its steps are taken on any [`AccelerationField`] and
/// accepted by its own error control; what it keeps from one step to the next (its step-size
/// controller, and Radau5's Jacobian, factorisation and last collocation polynomial) is its
/// [`Memory`](Self::Memory), the stages a step computes in place its
/// [`Scratch`](Self::Scratch).
pub trait EmbeddedPair: Copy + sealed::Sealed {
    /// The method's name.
    const NAME: &'static str;
    /// Whether an accepted step can be taken again on dual numbers with its step size
    /// ([`replay`](Self::replay)): what trajectory sensitivities need (Dopri5).
    const REPLAYS_ON_DUALS: bool = false;
    /// What the method keeps from one step to the next.
    type Memory<const N: usize>: Copy;
    /// The work space of a step (its stages), kept from step to step so it is not cleared each
    /// time; what it holds between steps is never read.
    type Scratch<const N: usize>: Clone;

    /// Checks the settings ([`Dopri5::validate`], [`Dop853::validate`](super::Dop853::validate),
    /// [`Radau5::validate`](super::Radau5::validate)).
    fn validate(&self) -> Result<()>;

    /// Most step attempts of one integration.
    fn max_steps(&self) -> usize;

    /// The settings `sys.step::<Self>(&mut state, h)` integrates over h with: the defaults (for
    /// Dop853 without the dense output, which the step does not need).
    fn one_step_settings() -> Self;

    /// The settings for an integration over an interval of this length (Dop853 bounds an
    /// infinite largest step by it, as `dop853.f` does); unchanged by default.
    fn bounded_to(&self, interval: f64) -> Self {
        let _ = interval;
        *self
    }

    /// A work space for its steps.
    fn scratch<const N: usize>() -> Self::Scratch<N>;

    /// The memory at the start (t, q, q̇) with q̈ = `a` there: the first step chosen (HNW I §II.4)
    /// unless the settings give it. Adds its evaluations to `stats`.
    fn start<const N: usize>(
        &self,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        stats: &mut Stats,
    ) -> Self::Memory<N>;

    /// The step the controller proposes next.
    fn proposed_step<const N: usize>(memory: &Self::Memory<N>) -> f64;

    /// One accepted step from `start` on `field`, not past `t_limit` (> t), rejecting and shrinking
    /// as the method's error control requires; a step within 1 % of `t_limit` lands on it. Its
    /// dense output is written into `dense` once complete (an error before leaves `dense` as it
    /// was). The end point is checked to be finite; it is not projected onto constraints. Adds its
    /// cost to `stats`. On error the memory may have changed (a smaller step proposed), nothing
    /// else.
    #[allow(clippy::too_many_arguments)]
    fn step<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Self::Memory<N>,
        scratch: &mut Self::Scratch<N>,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        t_limit: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>>;

    /// The step just accepted from `start`, recomputed as one step of the shorter length `h` (the
    /// step cut at an event): its local error is within the tolerance as the longer one's was. The
    /// controller's proposal for the next step is kept.
    #[allow(clippy::too_many_arguments)]
    fn shorten<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Self::Memory<N>,
        scratch: &mut Self::Scratch<N>,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        h: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>>;

    /// The field changes at the current point (a contact mode switched): forgets what was
    /// computed on the old one (Radau5's Jacobian, factorisation and the polynomial its Newton
    /// iteration extrapolates); keeps the proposed step.
    fn field_changed<const N: usize>(memory: &mut Self::Memory<N>);

    /// An accepted step of length `h` from (t, q, v) taken again, without error control, on any
    /// scalar (dual numbers carrying sensitivities) with the position rates `rates` (q̇ = G(q) v)
    /// and the accelerations `acc`: (q, v) at t + h. [`Error::UnsuitableMethod`] unless
    /// [`REPLAYS_ON_DUALS`](Self::REPLAYS_ON_DUALS).
    fn replay<S: Scalar, const N: usize>(
        &self,
        t: f64,
        y: (&[S; N], &[S; N]),
        h: f64,
        rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
        acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
    ) -> Result<([S; N], [S; N])> {
        let _ = (t, y, h, rates, acc);
        Err(not_replayed(Self::NAME))
    }
}

/// [`EmbeddedPair::replay`] of a method whose steps are not taken again on dual numbers.
pub(crate) fn not_replayed(method: &'static str) -> Error {
    Error::UnsuitableMethod {
        method,
        reason: "its steps are not taken again on dual numbers: sensitivities of an adaptive run \
                 are Dopri5's"
            .to_string(),
    }
}

/// What the explicit pairs differ in, below [`EmbeddedPair`]: their trials and dense outputs.
pub(crate) trait ExplicitPair: Copy {
    const NAME: &'static str;
    /// The order of the propagated solution, for the choice of the first step (HNW I §II.4).
    const ORDER: i32;
    /// The controller's exponents (p, w): err^(p − β·w) (see [`adaptive_step`]).
    const EXPONENTS: (f64, f64);
    /// [`EmbeddedPair::REPLAYS_ON_DUALS`].
    const REPLAYS_ON_DUALS: bool = false;
    /// The stages of one step, which its attempts fill in place and its completion reads.
    type Stages<const N: usize>: Clone;

    /// The step-control settings, in the form both methods share.
    fn controls(&self) -> Dopri5;

    /// [`EmbeddedPair::one_step_settings`].
    fn one_step_settings() -> Self;

    /// [`EmbeddedPair::bounded_to`].
    fn bounded_to(&self, interval: f64) -> Self {
        let _ = interval;
        *self
    }

    /// [`EmbeddedPair::replay`], `None` where it is not supported.
    fn replay<S: Scalar, const N: usize>(
        t: f64,
        y: (&[S; N], &[S; N]),
        h: f64,
        rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
        acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
    ) -> Option<Result<([S; N], [S; N])>> {
        let _ = (t, y, h, rates, acc);
        None
    }

    /// A stage buffer for one step.
    fn stages<const N: usize>() -> Self::Stages<N>;

    /// One trial step of size h, its stages into `stages`: (q₁, q̇₁) and the error norm.
    #[allow(clippy::type_complexity)]
    fn attempt<C: Coordinates<N>, const N: usize>(
        &self,
        start: StepStart<'_, N>,
        h: f64,
        stages: &mut Self::Stages<N>,
        stats: &mut Stats,
        field: &impl AccelerationField<N>,
    ) -> Result<([f64; N], [f64; N], f64)>;

    /// Completes the accepted attempt ending at `end` = (q₁, q̇₁) whose stages are in `stages`:
    /// q̈₁ at the new point, and the step's dense output written into `dense` once every
    /// evaluation has succeeded (on error `dense` is untouched). In place, because a dense output
    /// is 16 vectors of N: returned by value it was copied two or three times a step.
    #[allow(clippy::too_many_arguments)]
    fn accept<const N: usize>(
        &self,
        start: StepStart<'_, N>,
        h: f64,
        end: (&[f64; N], &[f64; N]),
        stages: &mut Self::Stages<N>,
        stats: &mut Stats,
        field: &impl AccelerationField<N>,
        dense: &mut DenseOutput<N>,
    ) -> Result<[f64; N]>;
}

/// [`EmbeddedPair::start`] of an explicit pair: the controller at the first step.
pub(crate) fn explicit_start<P: ExplicitPair, const N: usize>(
    method: &P,
    field: &impl AccelerationField<N>,
    start: StepStart<'_, N>,
    stats: &mut Stats,
) -> Controller {
    let settings = method.controls();
    let h = match settings.h_init {
        Some(h) => h.min(settings.h_max),
        None => initial_step_on(
            |t, q, v| field.accelerations(t, q, v),
            &settings,
            start,
            &field.position_rates(start.1, start.2),
            P::ORDER,
            stats,
        ),
    };
    Controller { h, fac_old: 1e-4 }
}

/// An accepted step of an explicit pair: its end time and (q, q̇, q̈) there.
pub(crate) type ExplicitStep<const N: usize> = (f64, [f64; N], [f64; N], [f64; N]);

/// One accepted step of an explicit pair on `field`: the shared step loop and PI controller
/// ([`adaptive_step`]) over its trials, whose stages are computed in place in `stages`, then
/// its completion (FSAL evaluation, and the dense output written into `dense`, which an error leaves
/// untouched). What [`EmbeddedPair::step`] of both explicit pairs takes.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn explicit_step<P: ExplicitPair, C: Coordinates<N>, const N: usize>(
    method: &P,
    control: &mut Controller,
    stages: &mut P::Stages<N>,
    field: &impl AccelerationField<N>,
    start: StepStart<'_, N>,
    t_limit: f64,
    stats: &mut Stats,
    dense: &mut DenseOutput<N>,
) -> Result<ExplicitStep<N>> {
    let ((q, v), h, t) = adaptive_step(
        P::NAME,
        &method.controls(),
        P::EXPONENTS,
        start.0,
        t_limit,
        control,
        stats,
        |h, stats| {
            method
                .attempt::<C, N>(start, h, stages, stats, field)
                .map(|(q1, v1, err)| ((q1, v1), err))
        },
    )?;
    let a = method.accept(start, h, (&q, &v), stages, stats, field, dense)?;
    Ok((t, q, v, a))
}

/// [`EmbeddedPair::shorten`] of an explicit pair: one trial of length h, accepted.
pub(crate) fn explicit_shorten<P: ExplicitPair, C: Coordinates<N>, const N: usize>(
    method: &P,
    stages: &mut P::Stages<N>,
    field: &impl AccelerationField<N>,
    start: StepStart<'_, N>,
    h: f64,
    (stats, dense): (&mut Stats, &mut DenseOutput<N>),
) -> Result<Accepted<N>> {
    let (q, v, _) = method.attempt::<C, N>(start, h, stages, stats, field)?;
    let a = method.accept(start, h, (&q, &v), stages, stats, field, dense)?;
    Ok(Accepted {
        t: start.0 + h,
        q,
        v,
        a: Some(a),
    })
}

/// The [`EmbeddedPair`] implementation of an explicit pair (the same for both), invoked where each
/// is defined.
macro_rules! explicit_embedded_pair {
    ($method:ty, $stages:ty) => {
        impl $crate::integrate::pair::EmbeddedPair for $method {
            const NAME: &'static str = <$method as $crate::integrate::pair::ExplicitPair>::NAME;
            const REPLAYS_ON_DUALS: bool =
                <$method as $crate::integrate::pair::ExplicitPair>::REPLAYS_ON_DUALS;
            type Memory<const N: usize> = $crate::integrate::control::Controller;
            type Scratch<const N: usize> = $stages;

            fn validate(&self) -> $crate::error::Result<()> {
                <$method>::validate(self)
            }

            fn max_steps(&self) -> usize {
                self.controls().max_steps
            }

            fn one_step_settings() -> Self {
                <$method as $crate::integrate::pair::ExplicitPair>::one_step_settings()
            }

            fn bounded_to(&self, interval: f64) -> Self {
                <$method as $crate::integrate::pair::ExplicitPair>::bounded_to(self, interval)
            }

            fn scratch<const N: usize>() -> Self::Scratch<N> {
                <$method as $crate::integrate::pair::ExplicitPair>::stages()
            }

            fn start<const N: usize>(
                &self,
                field: &impl $crate::integrate::pair::AccelerationField<N>,
                start: $crate::integrate::pair::StepStart<'_, N>,
                stats: &mut $crate::integrate::Stats,
            ) -> $crate::integrate::control::Controller {
                $crate::integrate::pair::explicit_start(self, field, start, stats)
            }

            fn proposed_step<const N: usize>(
                memory: &$crate::integrate::control::Controller,
            ) -> f64 {
                memory.h
            }

            #[inline(always)]
            fn step<C: $crate::model::Coordinates<N>, const N: usize>(
                &self,
                memory: &mut $crate::integrate::control::Controller,
                scratch: &mut Self::Scratch<N>,
                field: &impl $crate::integrate::pair::AccelerationField<N>,
                start: $crate::integrate::pair::StepStart<'_, N>,
                t_limit: f64,
                stats: &mut $crate::integrate::Stats,
                dense: &mut $crate::integrate::DenseOutput<N>,
            ) -> $crate::error::Result<$crate::integrate::pair::Accepted<N>> {
                let (t, q, v, a) = $crate::integrate::pair::explicit_step::<Self, C, N>(
                    self, memory, scratch, field, start, t_limit, stats, dense,
                )?;
                Ok($crate::integrate::pair::Accepted {
                    t,
                    q,
                    v,
                    a: Some(a),
                })
            }

            fn shorten<C: $crate::model::Coordinates<N>, const N: usize>(
                &self,
                _memory: &mut $crate::integrate::control::Controller,
                scratch: &mut Self::Scratch<N>,
                field: &impl $crate::integrate::pair::AccelerationField<N>,
                start: $crate::integrate::pair::StepStart<'_, N>,
                h: f64,
                stats: &mut $crate::integrate::Stats,
                dense: &mut $crate::integrate::DenseOutput<N>,
            ) -> $crate::error::Result<$crate::integrate::pair::Accepted<N>> {
                $crate::integrate::pair::explicit_shorten::<Self, C, N>(
                    self,
                    scratch,
                    field,
                    start,
                    h,
                    (stats, dense),
                )
            }

            fn field_changed<const N: usize>(_memory: &mut $crate::integrate::control::Controller) {
            }

            fn replay<S: $crate::geometry::Scalar, const N: usize>(
                &self,
                t: f64,
                y: (&[S; N], &[S; N]),
                h: f64,
                rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
                acc: impl FnMut(f64, &[S; N], &[S; N]) -> $crate::error::Result<[S; N]>,
            ) -> $crate::error::Result<([S; N], [S; N])> {
                <$method as $crate::integrate::pair::ExplicitPair>::replay(t, y, h, rates, acc)
                    .unwrap_or_else(|| {
                        Err($crate::integrate::pair::not_replayed(
                            <$method as $crate::integrate::pair::ExplicitPair>::NAME,
                        ))
                    })
            }
        }
    };
}
pub(crate) use explicit_embedded_pair;
