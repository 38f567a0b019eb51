//! Contacts with any one-step method: a constrained mechanism with its contact mode held is a
//! mechanism of its own ([`HeldMode`]), which every [`Integrator`] steps, so [`ContactRk4`]'s
//! event loop runs with implicit midpoint or Gauss–Legendre as well, and with Störmer–Verlet or
//! the variational integrator, whose RATTLE takes the mode's closed contacts as holonomic rows
//! ([`ContactRk4::step_with`]).

use super::{accelerations_in_mode, project, ConstraintCounts, Constraints, ContactRk4, Mode};
use crate::dynamics::EquationsOfMotion;
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::integrate::{Integrator, Stats};
use crate::mechanism::{Dynamics, Mechanism};
use crate::model::{Model, State};

/// A constrained mechanism whose contact mode is held: its accelerations are those of the mode
/// ([`accelerations_in_mode`]: the mode's rows enforced as equalities, its sliding friction a
/// known force), everything else is the mechanism's. While the mode is held its enforced rows are
/// bilateral, which is what it declares to the integrators: constraint rows that every stage
/// carries the force of (never unilateral or friction rows, which they would refuse) — its
/// holonomic and unilateral rows as holonomic rows, its velocity and friction rows as velocity
/// rows. To RATTLE ([`StormerVerlet`](crate::StormerVerlet), [`Variational`](crate::Variational))
/// it hands the position rows the mode enforces: the holonomic rows and the closed contacts, in
/// declaration order, first among `holonomic_constraints_at`'s entries, their number from
/// `enforced_holonomic_rows`.
struct HeldMode<'m, M, const K: usize, const C: usize> {
    model: &'m M,
    mode: Mode<C>,
}

/// Nothing is prepared: a held mode lives for one step.
impl<M, const K: usize, const C: usize> crate::mechanism::Prepare for HeldMode<'_, M, K, C> {
    type Prepared = ();
    fn prepare(&self) -> Result<()> {
        Ok(())
    }
}

impl<M, const N: usize, const K: usize, const C: usize> Dynamics<N> for HeldMode<'_, M, K, C>
where
    M: Dynamics<N> + Constraints<N, K, C>,
{
    type Coords = <M as Dynamics<N>>::Coords;
    const CONSTRAINT_COUNTS: Option<ConstraintCounts> = {
        let declared = ConstraintCounts::of(&<M as Constraints<N, K, C>>::KINDS);
        Some(ConstraintCounts {
            holonomic: declared.holonomic + declared.unilateral,
            velocity: declared.velocity + declared.friction,
            ..ConstraintCounts::NONE
        })
    };
    const SCLERONOMIC: bool = <M as Dynamics<N>>::SCLERONOMIC;

    fn check_parameters(&self) -> Result<()> {
        Dynamics::check_parameters(self.model)
    }
    #[inline]
    fn equations_of_motion_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> EquationsOfMotion<S, N> {
        self.model.equations_of_motion_at(t, q, v)
    }
    #[inline]
    fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> S {
        self.model.kinetic_energy_at(t, q, v)
    }
    #[inline]
    fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; N]) -> S {
        self.model.potential_energy_at(t, q)
    }
    #[inline]
    fn momenta_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [S; N] {
        self.model.momenta_at(t, q, v)
    }
    fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> f64 {
        self.model.lagrangian_time_derivative_at(t, q, v)
    }
    #[inline]
    fn canonical_field_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> ([S; N], [S; N]) {
        self.model.canonical_field_at(t, q, v)
    }
    #[inline]
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> Result<[S; N]> {
        Ok(accelerations_in_mode(self.model, t, q, v, &self.mode)?.accelerations)
    }
    fn project(&self, t: f64, q: &mut [f64; N], v: &mut [f64; N]) -> Result<()> {
        project(self.model, t, q, v, &self.mode)
    }
    /// g of the position rows the mode enforces (holonomic rows and closed contacts), in
    /// declaration order, padded with zeros to N entries.
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        let x = self.model.cartesian(t, q);
        let g = self.model.position_constraints(t, q, &x);
        let mut out = [S::zero(); N];
        for (slot, i) in position_rows::<M, N, K, C>(&self.mode).take(N).enumerate() {
            out[slot] = g[i];
        }
        Some(out)
    }
    fn enforced_holonomic_rows(&self) -> Option<usize> {
        Some(position_rows::<M, N, K, C>(&self.mode).count())
    }
}

/// The position rows (holonomic, unilateral) `mode` enforces, in declaration order.
fn position_rows<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    mode: &Mode<C>,
) -> impl Iterator<Item = usize> + '_ {
    (0..C).filter(|&i| M::KINDS[i].is_position() && mode.enforced(i))
}

impl<const C: usize> ContactRk4<C> {
    /// [`step`](Self::step) with the one-step method `I` in place of RK4: every (sub)step, and every
    /// trial step of the event location, is one step of `I` (with fresh working memory) on the
    /// mechanism with the step's mode held, projected onto the mode's rows; a step is cut at a
    /// located event, the mode switched, and the rest of h taken as a shorter step in the new mode.
    /// This is how implicit midpoint and Gauss–Legendre integrate unilateral contacts and friction,
    /// and Störmer–Verlet and the variational integrator unilateral contacts (a single
    /// `sys.step::<GaussLegendre2>` or `sys.step::<StormerVerlet>` on such a declaration is one of
    /// these steps from the state's own mode; their steppers that keep working memory refuse it).
    /// The methods on (q, p) stay symmetric within a held mode only up to the projection, as on
    /// any constrained mechanism.
    ///
    /// With Störmer–Verlet and the variational integrator, RATTLE enforces the mode's closed
    /// contacts as holonomic rows over the step (c(q, t) = 0 at its end, ċ = 0 by the velocity
    /// projection), so within a mode the step map is that of the mechanism with those rows
    /// bilateral — symplectic on its constraint manifold (the loop's projection after the step
    /// moves a RATTLE step by round-off only). A contact is released where its
    /// multiplier, evaluated on the method's steps, crosses 0. Friction and velocity rows constrain
    /// q̇, not q, and cannot be RATTLE rows: a declaration with them is refused with
    /// [`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod) before anything is computed.
    ///
    /// ```
    /// use lagrange_core::constraints::{ConstraintKind, ContactOptions, ContactRk4, Constraints};
    /// use lagrange_core::{GaussLegendre2, Model, Scalar, State, StormerVerlet};
    ///
    /// /// A unit mass falling onto the floor y ≥ 0.
    /// struct Ball;
    /// impl Model<1, 1> for Ball {
    ///     type Coords = [f64; 1];
    ///     const RHEONOMIC: bool = false;
    ///     const HAS_POTENTIAL: bool = true;
    ///     const HAS_FORCES: bool = false;
    ///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    ///     fn masses(&self) -> [f64; 1] { [1.0] }
    ///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
    ///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * 9.81 }
    /// }
    /// impl Constraints<1, 1, 1> for Ball {
    ///     const NAMES: [&'static str; 1] = ["floor"];
    ///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    ///     fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 1], _x: &[D; 1]) -> [D; 1] { [q[0]] }
    /// }
    /// lagrange_core::impl_mechanism!(Ball, 1, 1, constraints);
    ///
    /// let mut s = State::new(0.0, [1.0], [0.0]);
    /// let mut contact = ContactRk4::new(&Ball, &s, ContactOptions::default())?;
    /// for _ in 0..100 {
    ///     contact.step_with::<GaussLegendre2, _, 1, 1>(&Ball, &mut s, 1e-2)?;
    /// }
    /// // It lands at √(2/g) = 0.4515 s and stays on the floor; the fall is a quadratic, which the
    /// // Gauss method integrates exactly: the landing is located to the event tolerance.
    /// assert!((contact.events[0].t - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
    /// assert!(s.q[0].abs() < 1e-12 && (s.t - 1.0).abs() < 1e-12);
    ///
    /// // Störmer–Verlet too (exact on the quadratic), the floor a RATTLE row once closed.
    /// let mut s = State::new(0.0, [1.0], [0.0]);
    /// let mut contact = ContactRk4::new(&Ball, &s, ContactOptions::default())?;
    /// for _ in 0..100 {
    ///     contact.step_with::<StormerVerlet, _, 1, 1>(&Ball, &mut s, 1e-2)?;
    /// }
    /// assert!((contact.events[0].t - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
    /// assert!(s.q[0].abs() < 1e-12 && s.v[0].abs() < 1e-12);
    /// // 100 steps and the one cut at the landing.
    /// assert_eq!(contact.stats().accepted, 101);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn step_with<I, M, const N: usize, const K: usize>(
        &mut self,
        model: &M,
        state: &mut State<<M as Model<N, K>>::Coords>,
        h: f64,
    ) -> Result<()>
    where
        I: Integrator,
        M: Constraints<N, K, C> + Mechanism<N>,
    {
        refuse_velocity_rows::<I, M, N, K, C>()?;
        let cost = std::cell::Cell::new(Stats::default());
        self.step_by(model, state, h, &|t, q, v, tau, mode| {
            let held = HeldMode { model, mode: *mode };
            let mut memory = I::Memory::<N>::default();
            let mut stats = cost.get();
            let result = I::advance(&held, &mut memory, t, q, v, tau, &mut stats);
            cost.set(stats);
            let (mut q1, mut v1) = result?;
            project(model, t + tau, &mut q1, &mut v1, mode)?;
            Ok((q1, v1))
        })?;
        // `accepted` is counted by the event loop.
        self.stats += Stats {
            accepted: 0,
            ..cost.get()
        };
        Ok(())
    }
}

/// Refuses, for a method that enforces only position rows (RATTLE:
/// [`Integrator::POSITION_ROWS_ONLY`]), a declaration with velocity or friction rows: decided by
/// the declaration (`Constraints::KINDS`), never by a state.
fn refuse_velocity_rows<I, M, const N: usize, const K: usize, const C: usize>() -> Result<()>
where
    I: Integrator,
    M: Constraints<N, K, C>,
{
    let counts = ConstraintCounts::of(&M::KINDS);
    if !I::POSITION_ROWS_ONLY || counts.velocity + counts.friction == 0 {
        return Ok(());
    }
    Err(Error::UnsuitableMethod {
        method: I::NAME,
        reason: format!(
            "the declaration has {} velocity and {} friction rows, which constrain the velocities, not \
             the positions: RATTLE enforces only rows g(q, t) = 0 (holonomic rows, and the closed \
             unilateral contacts while the contact mode is held); integrate friction with \
             ContactRk4::step_with::<GaussLegendre2> or ::<ImplicitMidpoint> (symplectic methods on \
             (q, p), the mode held over each step; what a single sys.step with either does), \
             ContactRk4, or Dopri5, Dop853 or Radau5 (their integrate holds the mode per step)",
            counts.velocity, counts.friction
        ),
    })
}
