//! [`Mechanism`]: what every generated mechanism offers its user, over [`Dynamics`], the glue
//! `#[mechanism]` generates.

use crate::dynamics::EquationsOfMotion;
use crate::error::{describe_configuration, Error, Result};
use crate::geometry::Scalar;
use crate::integrate::Integrator;
use crate::model::{check_state, Coordinates, State};
use nalgebra::SMatrix;

/// A mechanism with `N` degrees of freedom, as `#[mechanism]` generates it: what a user calls.
///
/// [`accelerations`](Mechanism::accelerations), the energies and momenta,
/// [`step`](Mechanism::step) and [`simulate`](Mechanism::simulate), [`validated`](Mechanism::validated),
/// with named coordinates in and out and typed errors. Every type that implements the generated
/// glue ([`Dynamics`], hidden from these docs) is a `Mechanism`.
pub trait Mechanism<const N: usize>: Dynamics<N> {
    /// Checks the parameters: finite, masses and inertias positive. Every call on a state does it
    /// first; [`validated`](Mechanism::validated) does it once.
    fn validate(&self) -> Result<()> {
        self.check_parameters()
    }

    /// Checks the parameters once and returns a handle whose calls check only the state (see
    /// [`Validated`](crate::validated::Validated)): the form for a simulation, where parameters do
    /// not change.
    fn validated(self) -> Result<crate::validated::Validated<Self>> {
        crate::validated::validate(self)
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
        if Self::CLOSED_FORM {
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
        let (q, v) = self.check(state)?;
        let m = self.equations_of_motion_at(state.t, &q, &v).mass_matrix;
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

    /// p = ∂L/∂q̇, by name.
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
    /// ([`Dopri5`](crate::integrate::Dopri5), [`Dop853`](crate::integrate::Dop853)) it integrates
    /// over [t, t + h] with their default tolerances, so the state advances by h as well. For many
    /// steps, dense output, events or statistics use a solver
    /// ([`Stepper`](crate::integrate::Stepper)). On error the state is unchanged.
    fn step<I: Integrator>(&self, state: &mut State<Self::Coords>, h: f64) -> Result<()> {
        I::step(self, state, h)
    }

    /// Advances `state` by `steps` steps of size `h`, calling `observe` after each. Stops at the first
    /// error, leaving the state after the last successful step.
    fn simulate<I: Integrator>(
        &self,
        state: &mut State<Self::Coords>,
        h: f64,
        steps: usize,
        mut observe: impl FnMut(&State<Self::Coords>),
    ) -> Result<()> {
        for _ in 0..steps {
            I::step(self, state, h)?;
            observe(state);
        }
        Ok(())
    }
}

impl<T: Dynamics<N>, const N: usize> Mechanism<N> for T {}

/// What a mechanism computes once from its parameters, when it is validated, so that every
/// evaluation of a simulation reuses it: [`Validated`](crate::Validated) stores it next to the
/// parameters (which cannot change while the handle exists) and passes it to
/// [`Dynamics::accelerations_prepared_at`].
///
/// `#[mechanism]` prepares the constants of a declaration whose positions are affine in the
/// coordinates (x = A q + c: J = A and M = Aᵀ diag(μ) A constant, see [`crate::affine`]) and
/// nothing, `()`, for any other; [`impl_mechanism!`](crate::impl_mechanism) likewise
/// (`affine` for the former).
#[doc(hidden)]
pub trait Prepare {
    /// The constants (`()` when there are none).
    type Prepared: Copy + std::fmt::Debug + PartialEq;
    /// Whether [`Dynamics::regular_accelerations_prepared_at`] evaluates q̈ with the constants as
    /// straight-line code that runs no user code, every check in one branch (an affine mechanism
    /// whose potentials' gradients `#[mechanism]` derived and that declares no force, see
    /// [`crate::affine::regular_accelerations`]): a validated handle then takes
    /// [`Mechanism::accelerations`]' one-branch path, as the closed form does.
    const PREPARED_IN_ONE_BRANCH: bool = false;
    /// Computes them from valid parameters. Fails only where the parameters alone decide the
    /// equations of motion are singular (a constant mass matrix that is not positive definite).
    fn prepare(&self) -> Result<Self::Prepared>;
}

/// The glue `#[mechanism]` generates beneath [`Mechanism`]: the named coordinates, what the
/// declaration states (its constraint rows, whether it is scleronomic), and scalar-generic hooks on
/// raw arrays that forward to the generic functions of [`crate::dynamics`], [`crate::tree`] and
/// [`crate::constraints`], and that the integrators, the analyses and the sensitivities call.
/// [`impl_mechanism!`](crate::impl_mechanism) writes it for a hand-written [`Model`](crate::Model).
#[doc(hidden)]
pub trait Dynamics<const N: usize>: Prepare + Sized {
    /// The named generalized coordinates (`Coords` of the declaration).
    type Coords: Coordinates<N>;

    /// The constraint rows the declaration has, by kind (`Some(ConstraintCounts::NONE)` for none),
    /// or `None` when the implementation does not say. [`impl_mechanism!`](crate::impl_mechanism)
    /// and `#[mechanism]` declare it. Integrators decide from it alone — never from the state, so a
    /// constraint whose force happens to vanish (λ = 0) is treated as what it is:
    /// Störmer–Verlet and the variational integrator enforce holonomic rows by RATTLE and refuse
    /// velocity, unilateral and friction rows, and an undeclared implementation; implicit midpoint
    /// and Gauss–Legendre add Jᵀλ at every stage unless the mechanism declares no rows.
    ///
    /// [`ConstraintCounts`]: crate::constraints::ConstraintCounts
    const CONSTRAINT_COUNTS: Option<crate::constraints::ConstraintCounts> = None;

    /// The number of constraint rows the declaration has (`Some(0)` for none), or `None` when the
    /// implementation does not say; by default the total of
    /// [`CONSTRAINT_COUNTS`](Dynamics::CONSTRAINT_COUNTS).
    const CONSTRAINTS: Option<usize> = match Self::CONSTRAINT_COUNTS {
        Some(counts) => Some(counts.rows()),
        None => None,
    };

    /// Whether x does not depend on time (`#[mechanism]` declares it; `false`, the safe default,
    /// for an implementation that does not say). Then p = M(q) q̇ exactly, and the methods on (q, p)
    /// recover q̇ from p by one solve with M instead of a Newton iteration.
    #[doc(hidden)]
    const SCLERONOMIC: bool = false;

    /// Whether `#[mechanism]` derived M, 𝓕 and b in closed form (straight-line code from the
    /// positions read as polynomials in the coordinates, their sines and cosines) rather than by
    /// the dual-number passes of [`crate::dynamics`].
    #[doc(hidden)]
    const CLOSED_FORM: bool = false;

    /// Checks the parameters: finite, masses and inertias positive (what
    /// [`Mechanism::validate`] calls).
    fn check_parameters(&self) -> Result<()>;

    #[doc(hidden)]
    /// M, 𝓕 and b at (t, q, q̇), for any scalar.
    fn equations_of_motion_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> EquationsOfMotion<S, N>;

    #[doc(hidden)]
    /// T at (t, q, q̇), for any scalar.
    fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> S;

    #[doc(hidden)]
    /// V at (t, q), for any scalar.
    fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; N]) -> S;

    #[doc(hidden)]
    /// p = ∂L/∂q̇ at (t, q, q̇), for any scalar.
    fn momenta_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [S; N];

    #[doc(hidden)]
    /// ∂L/∂t at fixed (q, q̇) (zero for a scleronomic mechanism).
    fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> f64;

    /// The canonical field (p, ṗ) = (∂L/∂q̇, ∂L/∂q + F_nc) at (t, q, q̇), for any scalar: what the
    /// methods on (q, p) evaluate (see `integrate::canonical`). By default from the momenta and a
    /// gradient of T of their own; `#[mechanism]` computes a scleronomic mechanism's from one
    /// hyper-dual pass ([`crate::dynamics::canonical_field`]), or as straight-line code where it
    /// derives the equations in closed form ([`CLOSED_FORM`](Dynamics::CLOSED_FORM)).
    #[doc(hidden)]
    #[inline]
    fn canonical_field_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> ([S; N], [S; N]) {
        (
            self.momenta_at(t, q, v),
            crate::integrate::momentum_rate(self, t, q, v),
        )
    }

    /// [`canonical_field_at`](Dynamics::canonical_field_at) with the constants
    /// [`Prepare::prepare`] computed when the mechanism was validated: what a
    /// [`Validated`](crate::Validated) handle calls (`#[mechanism]`'s closed form evaluates its
    /// prepared coefficients). By default the constants are not used.
    #[doc(hidden)]
    #[inline(always)]
    fn canonical_field_prepared_at<S: Scalar>(
        &self,
        prepared: &Self::Prepared,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> ([S; N], [S; N]) {
        let _ = prepared;
        self.canonical_field_at(t, q, v)
    }

    #[doc(hidden)]
    /// q̈ at (t, q, q̇) for any scalar: solves M q̈ = 𝓕 − b. No validation (the hot path of
    /// integrators, which validate once per step).
    #[inline]
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> Result<[S; N]> {
        let eom = self.equations_of_motion_at(t, q, v);
        crate::dynamics::solve_accelerations::<Self::Coords, S, N>(&eom, t, q)
    }

    #[doc(hidden)]
    /// q̈ as [`accelerations_at`](Dynamics::accelerations_at), with the constants
    /// [`Prepare::prepare`] computed when the mechanism was validated: what a
    /// [`Validated`](crate::Validated) handle calls. By default the constants are not used.
    #[inline]
    fn accelerations_prepared_at<S: Scalar>(
        &self,
        prepared: &Self::Prepared,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]> {
        let _ = prepared;
        self.accelerations_at(t, q, v)
    }

    #[doc(hidden)]
    /// τ = M q̈ + b − 𝓕 at (t, q, q̇, q̈), for any scalar: inverse dynamics. By default from
    /// [`equations_of_motion_at`](Dynamics::equations_of_motion_at); a kinematic tree of rigid
    /// bodies takes the recursive Newton–Euler algorithm.
    #[inline]
    fn inverse_dynamics_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N], qdd: &[S; N]) -> [S; N] {
        let eom = self.equations_of_motion_at(t, q, v);
        let qdd = nalgebra::SVector::from(*qdd);
        (eom.mass_matrix * qdd + eom.inertial_terms - eom.generalized_forces).into()
    }

    #[doc(hidden)]
    /// [`inverse_dynamics_at`](Dynamics::inverse_dynamics_at) with the constants
    /// [`Prepare::prepare`] computed when the mechanism was validated: what a
    /// [`Validated`](crate::Validated) handle calls. By default the constants are not used.
    #[inline]
    fn inverse_dynamics_prepared_at<S: Scalar>(
        &self,
        prepared: &Self::Prepared,
        t: S,
        q: &[S; N],
        v: &[S; N],
        qdd: &[S; N],
    ) -> [S; N] {
        let _ = prepared;
        self.inverse_dynamics_at(t, q, v, qdd)
    }

    #[doc(hidden)]
    /// q̈ at (t, q, q̇) with every check in one branch, for equations that are straight-line code
    /// ([`CLOSED_FORM`](Dynamics::CLOSED_FORM), see [`crate::dynamics::regular_accelerations`]):
    /// `Some(q̈)` when the parameters pass their checks, the state and q̈ are finite and M is
    /// regular, `None` otherwise — and
    /// always `None` (the default) for equations that run user code, which is never evaluated at
    /// a state before the state is checked.
    #[inline(always)]
    fn regular_accelerations_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Option<[f64; N]> {
        let _ = (t, q, v);
        None
    }

    #[doc(hidden)]
    /// [`regular_accelerations_at`](Dynamics::regular_accelerations_at) with the constants
    /// [`Prepare::prepare`] computed when the mechanism was validated: what a
    /// [`Validated`](crate::Validated) handle calls.
    #[inline(always)]
    fn regular_accelerations_prepared_at(
        &self,
        prepared: &Self::Prepared,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Option<[f64; N]> {
        let _ = prepared;
        self.regular_accelerations_at(t, q, v)
    }

    #[doc(hidden)]
    /// Hook for mechanisms with holonomic constraints: their values g(q, t) at (t, q), for any
    /// scalar, in declaration order and padded with zeros to N entries (see
    /// [`crate::constraints::holonomic_values`]); `None` (the default) when the implementation
    /// does not provide them. RATTLE ([`StormerVerlet`](crate::StormerVerlet),
    /// [`Variational`](crate::Variational)) differentiates them with dual numbers.
    ///
    /// ```
    /// use lagrange_core::mechanism::Dynamics;
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
    /// // The pendulum in its angle has no constraint rows to provide.
    /// assert_eq!(Pendulum.holonomic_constraints_at(0.0, &[0.3]), None);
    /// ```
    #[inline]
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        let _ = (t, q);
        None
    }

    #[doc(hidden)]
    /// Hook for a mechanism that holds a contact mode over a step (the contact loop's held mode):
    /// how many leading rows of [`holonomic_constraints_at`](Dynamics::holonomic_constraints_at)
    /// are enforced over it — its holonomic rows and its closed unilateral contacts, which RATTLE
    /// enforces as holonomic rows while the mode is held. `None` (the default): every holonomic
    /// row [`CONSTRAINT_COUNTS`](Dynamics::CONSTRAINT_COUNTS) declares.
    ///
    /// ```
    /// use lagrange_core::mechanism::Dynamics;
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
    /// // A declared mechanism holds no mode: its declaration says which rows are enforced.
    /// assert_eq!(Pendulum.enforced_holonomic_rows(), None);
    /// ```
    #[inline]
    fn enforced_holonomic_rows(&self) -> Option<usize> {
        None
    }

    #[doc(hidden)]
    /// Hook for mechanisms with unilateral or friction rows: one step of `h` with the fixed-step
    /// method `I`, the contact mode held over it and its switches located and applied
    /// ([`ContactRk4::step_with`](crate::constraints::ContactRk4::step_with)), as
    /// `sys.step::<ImplicitMidpoint>` and `sys.step::<GaussLegendre2>` promise (those
    /// [`Integrator::HOLDS_CONTACT_MODE`](crate::integrate::Integrator::HOLDS_CONTACT_MODE)).
    /// `None` (the default) when the declaration has no such rows.
    #[inline]
    fn step_contacts<I: crate::integrate::Integrator>(
        &self,
        state: &mut State<Self::Coords>,
        h: f64,
    ) -> Option<Result<()>> {
        let _ = (state, h);
        None
    }

    #[doc(hidden)]
    /// Hook for mechanisms with unilateral or friction rows: integrates from `state` to `t_end`
    /// with the adaptive method `method` (Dopri5, Dop853 or Radau5), the contact mode held within
    /// each step and its switches located ([`crate::constraints::ContactAdaptive`]), as
    /// `Dopri5::integrate`, `Dop853::integrate` and `Radau5::integrate` promise. `None` (the
    /// default) when the declaration has no such rows: the method then integrates the smooth
    /// system itself.
    #[inline]
    fn integrate_contacts<P, O>(
        &self,
        method: P,
        state: &mut State<Self::Coords>,
        t_end: f64,
        events: &mut [crate::integrate::Event<'_, Self::Coords>],
        observer: O,
    ) -> Option<Result<crate::integrate::Outcome<Self::Coords>>>
    where
        P: crate::integrate::EmbeddedPair,
        O: FnMut(crate::integrate::Observation<'_, Self::Coords, N>),
    {
        let _ = (method, state, t_end, events, observer);
        None
    }

    #[doc(hidden)]
    /// Hook for mechanisms with constraints: projects (q, q̇) at time `t` back onto the constraints
    /// (see [`crate::constraints::project`]). Integrators call it after every step; the default does
    /// nothing. On error `q` and `v` are unchanged.
    #[inline]
    fn project(&self, t: f64, q: &mut [f64; N], v: &mut [f64; N]) -> Result<()> {
        let _ = (t, q, v);
        Ok(())
    }

    #[doc(hidden)]
    /// [`project`](Dynamics::project) with the constants [`Prepare::prepare`] computed when the
    /// mechanism was validated (see [`crate::constraints::project_prepared`]): what a
    /// [`Validated`](crate::Validated) handle calls. By default the constants are not used.
    #[inline]
    fn project_prepared(
        &self,
        prepared: &Self::Prepared,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
    ) -> Result<()> {
        let _ = prepared;
        self.project(t, q, v)
    }

    #[doc(hidden)]
    /// Hook for mechanisms with constraints: checks that (t, q, q̇) satisfies them within tolerance
    /// (see [`crate::constraints::check_consistent`]), so a state violating them is refused rather
    /// than silently projected. Integrators call it before every step; the default accepts.
    #[inline]
    fn check_constraints(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        let _ = (t, q, v);
        Ok(())
    }

    #[doc(hidden)]
    /// Hook for mechanisms with constraints: checks what the declaration promises but only a state
    /// can show — that every velocity row is affine in q̇ (see
    /// [`crate::constraints::check_velocity_rows_affine`]) — so every entry point refuses the same
    /// declarations. The default accepts.
    #[inline]
    fn check_declaration_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        let _ = (t, q, v);
        Ok(())
    }

    #[doc(hidden)]
    /// Checks parameters and state; what every user-facing call does first.
    fn check(&self, state: &State<Self::Coords>) -> Result<([f64; N], [f64; N])> {
        self.check_parameters()?;
        let (q, v) = (state.q.to_array(), state.v.to_array());
        check_state(&Self::Coords::NAMES, state.t, &q, &v)?;
        Ok((q, v))
    }
}

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

#[cold]
#[inline(never)]
fn non_finite_at<C: crate::model::Coordinates<N>, const N: usize>(
    t: f64,
    q: &[f64; N],
    v: Option<&[f64; N]>,
) -> Error {
    let mut configuration = describe_configuration(&C::NAMES, q);
    if let Some(v) = v {
        configuration = format!(
            "{configuration}, velocities ({})",
            describe_configuration(&C::NAMES, v)
        );
    }
    Error::NonFiniteDynamics { t, configuration }
}

/// Re-examines an error of the accelerations at (t, q, q̇) for its real cause: a mass matrix
/// reported singular because one of its entries overflowed (a coordinate of 1e300 in a mass
/// matrix that grows like its square, or the stage of a step that blew up) is
/// [`Error::NonFiniteDynamics`] at that state, not a singular matrix with a meaningless pivot. Other
/// errors pass unchanged. Only called on the error path.
#[cold]
#[inline(never)]
pub fn diagnose<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    error: Error,
) -> Error {
    if let Error::SingularMassMatrix { .. } = error {
        let m = mechanism.equations_of_motion_at(t, q, v).mass_matrix;
        if !m.iter().all(|x| x.is_finite()) {
            return non_finite_at::<M::Coords, N>(t, q, Some(v));
        }
    }
    error
}

/// Implements [`Mechanism`] for a hand-written [`Model`](crate::Model) with `N` coordinates and `K`
/// Cartesian coordinates, forwarding every method to [`crate::dynamics`]: the same glue
/// `#[mechanism]` generates, for models written by hand (tests, benchmarks, peers).
///
/// ```
/// use lagrange_core::{impl_mechanism, vec2, Mechanism, Model, Scalar, State};
///
/// /// A pendulum of unit mass and length, written by hand.
/// struct Pendulum;
///
/// impl Model<1, 2> for Pendulum {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
///         vec2(q[0].sin(), -q[0].cos()).to_array()
///     }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// }
/// impl_mechanism!(Pendulum, 1, 2);
///
/// let a = Pendulum.accelerations(&State::at_rest([0.5])).unwrap();
/// assert!((a[0] + 9.81 * 0.5f64.sin()).abs() < 1e-14);
/// ```
///
/// `impl_mechanism!(Type, N, K, constraints)` is the same for a model that also implements
/// [`Constraints`](crate::constraints::Constraints): accelerations solve the constrained system,
/// integrators project after every step and refuse inconsistent states.
///
/// `impl_mechanism!(Type, N, K, affine)` is for a model without constraints whose x is affine in
/// q with constant coefficients and independent of t (x = A q + c; [`crate::affine`]): its
/// [`Validated`](crate::Validated) handle computes J = A and the factorisation of the constant
/// mass matrix once. The model promises it; a position that is not affine gives wrong
/// accelerations through the handle.
#[macro_export]
macro_rules! impl_mechanism {
    ($ty:ty, $n:tt, $k:tt, constraints) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, {
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> = {
                use $crate::constraints::Constraints as _;
                Some($crate::constraints::ConstraintCounts::of(&<$ty>::KINDS))
            };
            fn holonomic_constraints_at<S: $crate::Scalar>(&self, t: S, q: &[S; $n]) -> Option<[S; $n]> {
                Some($crate::constraints::holonomic_values(self, t, q))
            }
            fn accelerations_at<S: $crate::Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> $crate::Result<[S; $n]> {
                $crate::constraints::accelerations(self, t, q, v)
            }
            fn project(&self, t: f64, q: &mut [f64; $n], v: &mut [f64; $n]) -> $crate::Result<()> {
                let mode = $crate::constraints::infer_mode(self, t, q, v)?;
                $crate::constraints::project(self, t, q, v, &mode)
            }
            fn check_declaration_at(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> $crate::Result<()> {
                $crate::constraints::check_velocity_rows_affine(self, t, q, v)
            }
            fn check_constraints(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> $crate::Result<()> {
                $crate::constraints::check_consistent(
                    self,
                    t,
                    q,
                    v,
                    $crate::constraints::CONSISTENCY_TOLERANCE,
                )
            }
            fn step_contacts<I: $crate::integrate::Integrator>(
                &self,
                state: &mut $crate::State<Self::Coords>,
                h: f64,
            ) -> Option<$crate::Result<()>> {
                $crate::constraints::step_declared_contacts::<I, Self, $n, $k, _>(self, state, h)
            }
            fn integrate_contacts<P, O>(
                &self,
                method: P,
                state: &mut $crate::State<Self::Coords>,
                t_end: f64,
                events: &mut [$crate::integrate::Event<'_, Self::Coords>],
                observer: O,
            ) -> Option<$crate::Result<$crate::integrate::Outcome<Self::Coords>>>
            where
                P: $crate::integrate::EmbeddedPair,
                O: FnMut($crate::integrate::Observation<'_, Self::Coords, $n>),
            {
                $crate::constraints::integrate_declared_contacts(method, self, state, t_end, events, observer)
            }
        });
        $crate::impl_mechanism!(@prepare_nothing $ty);
    };
    ($ty:ty, $n:tt, $k:tt, affine) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, {
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> =
                Some($crate::constraints::ConstraintCounts::NONE);
            fn accelerations_prepared_at<S: $crate::Scalar>(
                &self,
                prepared: &Self::Prepared,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> $crate::Result<[S; $n]> {
                $crate::affine::accelerations::<$ty, S, $n, $k>(self, prepared, t, q, v)
            }
        });
        impl $crate::mechanism::Prepare for $ty {
            type Prepared = $crate::affine::AffineConstants<$n, $k>;
            fn prepare(&self) -> $crate::Result<Self::Prepared> {
                $crate::affine::AffineConstants::of::<$ty>(self)
            }
        }
    };
    ($ty:ty, $n:tt, $k:tt) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, {
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> =
                Some($crate::constraints::ConstraintCounts::NONE);
        });
        $crate::impl_mechanism!(@prepare_nothing $ty);
    };
    (@prepare_nothing $ty:ty) => {
        impl $crate::mechanism::Prepare for $ty {
            type Prepared = ();
            fn prepare(&self) -> $crate::Result<()> {
                Ok(())
            }
        }
    };
    (@impl $ty:ty, $n:tt, $k:tt, { $($extra:tt)* }) => {
        // A hand-written model reads no parameter through an array: there is nothing to seed.
        impl $crate::parameters::Parametrized<$n, $k, 0> for $ty {
            const PARAMETER_NAMES: [&'static str; 0] = [];
            const SEEDABLE: [bool; 0] = [];
            fn parameters(&self) -> [f64; 0] {
                []
            }
            fn cartesian_with<S: $crate::Scalar, D: $crate::Scalar>(
                &self,
                _p: &[S; 0],
                t: D,
                q: &[D; $n],
            ) -> [D; $k] {
                <$ty as $crate::Model<$n, $k>>::cartesian(self, t, q)
            }
        }
        impl $crate::mechanism::Dynamics<$n> for $ty {
            type Coords = <$ty as $crate::Model<$n, $k>>::Coords;
            fn check_parameters(&self) -> $crate::Result<()> {
                <$ty as $crate::Model<$n, $k>>::validate(self)
            }
            fn equations_of_motion_at<S: $crate::Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> $crate::dynamics::EquationsOfMotion<S, $n> {
                $crate::dynamics::equations_of_motion::<$ty, S, $n, $k>(self, t, q, v)
            }
            fn kinetic_energy_at<S: $crate::Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> S {
                $crate::dynamics::kinetic_energy::<$ty, S, $n, $k>(self, t, q, v)
            }
            fn potential_energy_at<S: $crate::Scalar>(&self, t: S, q: &[S; $n]) -> S {
                $crate::dynamics::potential_energy::<$ty, S, $n, $k>(self, t, q)
            }
            fn momenta_at<S: $crate::Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> [S; $n] {
                $crate::dynamics::momenta::<$ty, S, $n, $k>(self, t, q, v)
            }
            fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> f64 {
                $crate::dynamics::lagrangian_time_derivative::<$ty, $n, $k>(self, t, q, v)
            }
            $($extra)*
        }
    };
}
