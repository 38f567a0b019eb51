//! [`Mechanism`]: what every generated mechanism offers its user, over the glue `#[mechanism]`
//! generates ([`Dynamics`], evaluated through [`Evaluate`]; see [`crate::evaluation`]).

use crate::error::{describe_configuration, Error, Result};
use crate::evaluation::non_finite_at;
pub use crate::evaluation::{diagnose, Dynamics, Evaluate, Prepare};
use crate::inputs::{Actuated, Driven, Inputs as _};
use crate::integrate::{Event, Integrator, Method, Observation, Outcome, Stepper};
use crate::model::{Coordinates, State};
use nalgebra::SMatrix;

/// A mechanism with `N` degrees of freedom, as `#[mechanism]` generates it: what a user calls.
///
/// [`accelerations`](Mechanism::accelerations), the energies and momenta,
/// [`step`](Mechanism::step) and [`simulate`](Mechanism::simulate), [`validated`](Mechanism::validated),
/// with named coordinates in and out and typed errors. Every type that implements the generated
/// glue ([`Dynamics`], hidden from these docs) is a `Mechanism`, and so is its
/// [`Validated`](crate::validated::Validated) handle.
pub trait Mechanism<const N: usize>: Evaluate<N> {
    /// Checks the parameters: finite, masses and inertias positive. Every call on a state does it
    /// first; [`validated`](Mechanism::validated) does it once.
    fn validate(&self) -> Result<()> {
        self.check_parameters()
    }

    /// Checks the parameters once and returns a handle whose calls check only the state (see
    /// [`Validated`](crate::validated::Validated)): the form for a simulation, where parameters do
    /// not change.
    fn validated(self) -> Result<crate::validated::Validated<Self>>
    where
        Self: Dynamics<N>,
    {
        crate::validated::validate(self)
    }

    /// The mechanism with the inputs `inputs` held (a declaration with `#[inputs]`): every
    /// evaluation, step and analysis of the result sees them, constant over each step (see
    /// [`Driven`]). Without it the inputs are zero.
    fn driven<const NU: usize>(
        &self,
        inputs: &<Self::Model as Actuated<NU>>::Inputs,
    ) -> Driven<'_, Self, [f64; NU]>
    where
        Self::Model: Actuated<NU>,
    {
        Driven::new(self, inputs.to_array())
    }

    /// The inputs that make the mechanism move with `accelerations` at `state` (computed torque),
    /// for a declaration whose every input is a generalized force on a coordinate of its own
    /// ([`Actuated::COORDINATES`]): the generalized forces τ of
    /// [`inverse_dynamics`](Mechanism::inverse_dynamics) at zero inputs, read on the actuated
    /// coordinates. The unactuated coordinates must need none: τⱼ there is zero to rounding
    /// (|τⱼ| ≤ 1e-12 · (1 + max |τ|)).
    ///
    /// Errors: those of `inverse_dynamics`; inputs that are not one generalized force per
    /// coordinate, or accelerations an unactuated coordinate cannot follow
    /// ([`Error::UnsuitableMethod`], naming the coordinate).
    fn inverse_dynamics_inputs<const NU: usize>(
        &self,
        state: &State<Self::Coords>,
        accelerations: &Self::Coords,
    ) -> Result<<Self::Model as Actuated<NU>>::Inputs>
    where
        Self::Model: Actuated<NU>,
    {
        let Some(coordinates) = <Self::Model as Actuated<NU>>::COORDINATES else {
            return Err(Error::UnsuitableMethod {
                method: "inverse_dynamics_inputs",
                reason: "the inputs are not each one generalized force on a coordinate of its own"
                    .to_string(),
            });
        };
        let tau = self.inverse_dynamics(state, accelerations)?.to_array();
        let scale = 1.0 + tau.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for (j, name) in Self::Coords::NAMES.iter().enumerate() {
            if !coordinates.contains(&j) && tau[j].abs() > 1e-12 * scale {
                return Err(Error::UnsuitableMethod {
                    method: "inverse_dynamics_inputs",
                    reason: format!(
                        "coordinate `{name}` has no input, and the wanted accelerations need a \
                         generalized force of {} on it",
                        tau[j]
                    ),
                });
            }
        }
        Ok(
            <<Self::Model as Actuated<NU>>::Inputs as crate::inputs::Inputs<NU>>::from_array(
                coordinates.map(|j| tau[j]),
            ),
        )
    }

    /// The generalized accelerations q̈, by name.
    ///
    /// Errors: non-finite parameters or state, a singular mass matrix (the error names the
    /// configuration), non-finite dynamics.
    ///
    /// A mechanism with constraints also refuses what its integrators refuse about the declaration
    /// itself (invalid friction coefficients, a velocity row that is not linear in q̇), but
    /// evaluates states off the constraints (see `Dynamics::check_constraints`).
    fn accelerations(&self, state: &State<Self::Coords>) -> Result<Self::Coords> {
        // Equations in closed form are checked in one branch, parameters included (the hook is
        // `None` otherwise); everything else, and a call where that branch fails, goes through the
        // checks one at a time, out of line, which say what failed.
        if Self::ONE_BRANCH {
            let (q, v) = (state.q.to_array(), state.v.to_array());
            if let Some(qdd) = self.regular_accelerations_at(state.t, &q, &v) {
                return Ok(Self::Coords::from_array(qdd));
            }
        }
        checked_accelerations(self, state)
    }

    /// M(q, t): the mass matrix, row and column k for coordinate k in declaration order.
    ///
    /// Errors: non-finite parameters or state, a mass matrix that is not finite here
    /// ([`Error::NonFiniteDynamics`]).
    fn mass_matrix(&self, state: &State<Self::Coords>) -> Result<SMatrix<f64, N, N>> {
        let (q, _) = self.check(state)?;
        let m = self.mass_matrix_at(state.t, &q);
        finite_or_error::<Self::Coords, N>(m.iter(), state.t, &q, None)?;
        Ok(m)
    }

    /// 𝓕: the generalized forces (potentials, applied and direct forces), by name.
    ///
    /// Errors: non-finite parameters or state, forces that are not finite here
    /// ([`Error::NonFiniteDynamics`]).
    fn generalized_forces(&self, state: &State<Self::Coords>) -> Result<Self::Coords> {
        let (q, v) = self.check(state)?;
        let f: [f64; N] = self
            .equations_of_motion_at(state.t, &q, &v)
            .generalized_forces
            .into();
        finite_or_error::<Self::Coords, N>(f.iter(), state.t, &q, Some(&v))?;
        Ok(Self::Coords::from_array(f))
    }

    /// Inverse dynamics: the generalized forces τ that, added to those the declaration states,
    /// make the mechanism move with accelerations `accelerations` at `state`,
    /// τ = M q̈ + b − 𝓕 (for a kinematic tree of rigid bodies, by the recursive Newton–Euler
    /// algorithm: work proportional to the bodies). For a mechanism with constraints, τ includes
    /// what the constraint forces would supply (Gᵀλ): it is the generalized force of everything
    /// not declared.
    ///
    /// ```
    /// use lagrange_core::{impl_mechanism, vec2, Mechanism, Model, Scalar, State};
    ///
    /// /// A pendulum of mass 2 on a rod of length 1/2, written by hand (`#[mechanism]` writes the
    /// /// same).
    /// struct Pendulum;
    /// impl Model<1, 2> for Pendulum {
    ///     type Coords = [f64; 1];
    ///     const RHEONOMIC: bool = false;
    ///     const HAS_POTENTIAL: bool = true;
    ///     const HAS_FORCES: bool = false;
    ///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    ///     fn masses(&self) -> [f64; 2] { [2.0, 2.0] }
    ///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
    ///         (vec2(q[0].sin(), -q[0].cos()) * D::from(0.5)).to_array()
    ///     }
    ///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * (2.0 * 9.81) }
    /// }
    /// impl_mechanism!(Pendulum, 1, 2);
    ///
    /// # fn main() -> lagrange_core::Result<()> {
    /// // The torque that holds the pendulum still at 0.3 rad: m g l sin θ.
    /// let tau = Pendulum.inverse_dynamics(&State::at_rest([0.3]), &[0.0])?;
    /// assert!((tau[0] - 2.0 * 9.81 * 0.5 * 0.3f64.sin()).abs() < 1e-12);
    /// # Ok(())
    /// # }
    /// ```
    ///
    /// Errors: non-finite parameters, state or accelerations, a result that is not finite
    /// ([`Error::NonFiniteDynamics`]).
    fn inverse_dynamics(
        &self,
        state: &State<Self::Coords>,
        accelerations: &Self::Coords,
    ) -> Result<Self::Coords> {
        let (q, v) = self.check(state)?;
        let qdd = accelerations.to_array();
        if !qdd.iter().all(|a| a.is_finite()) {
            return Err(Error::NonFiniteState {
                state: format!(
                    "accelerations ({})",
                    describe_configuration(&Self::Coords::NAMES, &qdd)
                ),
            });
        }
        let tau = self.inverse_dynamics_at(state.t, &q, &v, &qdd);
        finite_or_error::<Self::Coords, N>(tau.iter(), state.t, &q, Some(&v))?;
        Ok(Self::Coords::from_array(tau))
    }

    /// T: kinetic energy.
    ///
    /// Errors: non-finite parameters or state, a kinetic energy that overflows
    /// ([`Error::NonFiniteDynamics`], as [`accelerations`](Self::accelerations) reports for a state
    /// whose inertial terms overflow).
    fn kinetic_energy(&self, state: &State<Self::Coords>) -> Result<f64> {
        let (q, v) = self.check(state)?;
        let kinetic = self.kinetic_energy_at(state.t, &q, &v);
        finite_or_error::<Self::Coords, N>([kinetic].iter(), state.t, &q, Some(&v))?;
        Ok(kinetic)
    }

    /// V: potential energy.
    ///
    /// Errors: non-finite parameters or state, a potential that is not finite here
    /// ([`Error::NonFiniteDynamics`]).
    fn potential_energy(&self, state: &State<Self::Coords>) -> Result<f64> {
        let (q, _) = self.check(state)?;
        let potential = self.potential_energy_at(state.t, &q);
        finite_or_error::<Self::Coords, N>([potential].iter(), state.t, &q, None)?;
        Ok(potential)
    }

    /// T + V. Conserved when nothing depends on time and no non-conservative force acts.
    ///
    /// Errors: as [`kinetic_energy`](Self::kinetic_energy) and
    /// [`potential_energy`](Self::potential_energy); a sum that overflows is
    /// [`Error::NonFiniteDynamics`] too.
    fn energy(&self, state: &State<Self::Coords>) -> Result<f64> {
        let (q, v) = self.check(state)?;
        let energy =
            self.kinetic_energy_at(state.t, &q, &v) + self.potential_energy_at(state.t, &q);
        finite_or_error::<Self::Coords, N>([energy].iter(), state.t, &q, Some(&v))?;
        Ok(energy)
    }

    /// p = ∂L/∂q̇, by name (∂L/∂v where the velocities are quasi-velocities, a free or ball
    /// joint's angular velocity: the body's angular momentum in its frame there).
    ///
    /// Errors: non-finite parameters or state, momenta that overflow
    /// ([`Error::NonFiniteDynamics`]).
    fn momenta(&self, state: &State<Self::Coords>) -> Result<Self::Coords> {
        let (q, v) = self.check(state)?;
        let p = self.momenta_at(state.t, &q, &v);
        finite_or_error::<Self::Coords, N>(p.iter(), state.t, &q, Some(&v))?;
        Ok(Self::Coords::from_array(p))
    }

    /// The energy function (Jacobi integral) h = Σ pₖ q̇ₖ − L. Conserved when L does not depend on
    /// t explicitly, even where T + V is not (a bead on a spinning hoop); in general
    /// dh/dt = −∂L/∂t + (power of non-conservative forces).
    ///
    /// Errors: as [`energy`](Self::energy).
    fn energy_function(&self, state: &State<Self::Coords>) -> Result<f64> {
        let (q, v) = self.check(state)?;
        let p = self.momenta_at(state.t, &q, &v);
        let pv: f64 = p.iter().zip(&v).map(|(p, v)| p * v).sum();
        let lagrangian =
            self.kinetic_energy_at(state.t, &q, &v) - self.potential_energy_at(state.t, &q);
        let h = pv - lagrangian;
        finite_or_error::<Self::Coords, N>([h].iter(), state.t, &q, Some(&v))?;
        Ok(h)
    }

    /// ∂L/∂t at the state (zero for a scleronomic mechanism).
    ///
    /// Errors: as [`energy`](Self::energy).
    fn lagrangian_time_derivative(&self, state: &State<Self::Coords>) -> Result<f64> {
        let (q, v) = self.check(state)?;
        let rate = self.lagrangian_time_derivative_at(state.t, &q, &v);
        finite_or_error::<Self::Coords, N>([rate].iter(), state.t, &q, Some(&v))?;
        Ok(rate)
    }

    /// Advances `state` by one step of size `h` with integrator `I` (for example
    /// [`Rk4`](crate::integrate::Rk4)), with fresh working memory. For the adaptive methods
    /// ([`Dopri5`](crate::integrate::Dopri5), [`Dop853`](crate::integrate::Dop853),
    /// [`Radau5`](crate::integrate::Radau5)) it integrates over [t, t + h] with their default
    /// tolerances, so the state advances by h as well. A declaration with unilateral or friction
    /// rows is stepped with the contact mode of the state held over the step, a mode change inside
    /// it located and applied. For many steps, dense output, events or statistics use
    /// [`integrate`](Mechanism::integrate) or a [`Stepper`]. On error the state is unchanged.
    ///
    /// ```
    /// use lagrange_core::{Mechanism, Rk4, State};
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
    /// // A unit pendulum released at rest from 0.5 rad, one RK4 step of 1 ms: it starts to fall,
    /// // θ̇(h) = −g sin θ₀ h + O(h³) (θ⃛ = −g cos θ θ̇ vanishes at rest), the O(h³) term ≈ 7e-9.
    /// let mut s = State::new(0.0, [0.5], [0.0]);
    /// Pendulum.step::<Rk4>(&mut s, 1e-3)?;
    /// assert_eq!(s.t, 1e-3);
    /// assert!((s.v[0] + 9.81 * 0.5f64.sin() * 1e-3).abs() < 1e-7);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    fn step<I: Integrator>(&self, state: &mut State<Self::Coords>, h: f64) -> Result<()> {
        I::step(self, state, h)
    }

    /// Integrates `state` to `t_end` with `method` — a one-step method with its step
    /// (`Rk4::with_step(1e-3)`, see [`Integrator::with_step`]) or an adaptive method's settings
    /// ([`Dopri5`](crate::integrate::Dopri5), [`Dop853`](crate::integrate::Dop853),
    /// [`Radau5`](crate::integrate::Radau5)) — calling `observer` after every step and for every
    /// located event, and stopping early at a terminal event or after the method's `max_steps`:
    /// [`Stepper::integrate`] from `state`, which is then moved to where the integration ended
    /// ([`Outcome::state`]). On error the state is unchanged. For step-by-step control, dense
    /// output, contact options or sensitivities keep the [`Stepper`].
    ///
    /// ```
    /// use lagrange_core::integrate::{Direction, Event, StopReason};
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
    /// // A unit pendulum released at rest from 0.5 rad, stopped where it first passes the bottom.
    /// let mut s = State::new(0.0, [0.5], [0.0]);
    /// let bottom = |s: &State<[f64; 1]>| s.q[0];
    /// let mut events = [Event::new(&bottom).direction(Direction::Falling).terminal()];
    /// let outcome = Pendulum.integrate(Dopri5::new(1e-10, 1e-12), &mut s, 10.0, &mut events, |_| {})?;
    /// assert!(matches!(outcome.reason, StopReason::Event(_)));
    /// // A quarter period K(sin ¼)·√(l/g) = 0.50946697879 s, located on the dense output.
    /// assert!((s.t - 0.509_466_978_79).abs() < 1e-9 && s.q[0].abs() < 1e-9);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    fn integrate<Me: Method<N>>(
        &self,
        method: Me,
        state: &mut State<Self::Coords>,
        t_end: f64,
        events: &mut [Event<'_, Self::Coords>],
        observer: impl FnMut(Observation<'_, Self::Coords, N>),
    ) -> Result<Outcome<Self::Coords>> {
        let outcome = Stepper::new(self, method, state)?.integrate(t_end, events, observer)?;
        *state = outcome.state;
        Ok(outcome)
    }

    /// Advances `state` by `steps` steps of size `h`, calling `observe` after each. Stops at the first
    /// error, leaving the state after the last successful step. Each step is
    /// [`step`](Self::step)'s, with the method's working memory kept from one to the next, as a
    /// [`Stepper`] keeps it: the implicit methods reuse their Jacobians and factorised Newton
    /// matrix while they contract, where a single `step` must form them.
    ///
    /// ```
    /// use lagrange_core::{Mechanism, Rk4, State};
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
    /// // A second of a unit pendulum from 0.5 rad in 1000 RK4 steps: the energy drifts by the method's
    /// // error, O((hω)⁴) relative over the run (ω = √g ≈ 3.1, so ~1e-10), far below 1e-8.
    /// let mut s = State::new(0.0, [0.5], [0.0]);
    /// let e0 = Pendulum.energy(&s)?;
    /// let mut drift = 0.0f64;
    /// Pendulum.simulate::<Rk4>(&mut s, 1e-3, 1000, |s| {
    ///     drift = drift.max((Pendulum.energy(s).unwrap() - e0).abs());
    /// })?;
    /// assert!((s.t - 1.0).abs() < 1e-12 && drift < 1e-8);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    fn simulate<I: Integrator>(
        &self,
        state: &mut State<Self::Coords>,
        h: f64,
        steps: usize,
        mut observe: impl FnMut(&State<Self::Coords>),
    ) -> Result<()> {
        let mut memory = I::Memory::<N>::default();
        for _ in 0..steps {
            crate::integrate::step_keeping_memory::<I, Self, N>(self, &mut memory, state, h)?;
            observe(state);
        }
        Ok(())
    }
}

impl<T: Evaluate<N>, const N: usize> Mechanism<N> for T {}

/// [`Mechanism::accelerations`] with one check at a time: parameters, state, the declaration, then
/// the solve, whose failure is diagnosed against the declaration.
#[inline(never)]
fn checked_accelerations<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    state: &State<M::Coords>,
) -> Result<M::Coords> {
    let (q, v) = mechanism.check(state)?;
    mechanism.check_declaration_at(state.t, &q, &v)?;
    mechanism
        .accelerations_at(state.t, &q, &v)
        .map(M::Coords::from_array)
        .map_err(|e| diagnose(mechanism, state.t, &q, &v, e))
}

/// `Ok` when every value is finite, otherwise [`Error::NonFiniteDynamics`] at (t, q), naming the
/// velocities too when they were an input (a huge velocity overflows T while q is harmless).
#[inline]
fn finite_or_error<'a, C: crate::model::Coordinates<N>, const N: usize>(
    values: impl Iterator<Item = &'a f64>,
    t: f64,
    q: &[f64; N],
    v: Option<&[f64; N]>,
) -> Result<()> {
    let mut zero = 0.0;
    for x in values {
        zero += x * 0.0;
    }
    if zero == 0.0 {
        Ok(())
    } else {
        Err(non_finite_at::<C, N>(t, q, v))
    }
}
