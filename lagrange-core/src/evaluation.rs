//! What a state implies, evaluated: the trait a declaration implements ([`Dynamics`], with the
//! constants of [`Prepare`]) and the one every integrator, analysis and user call evaluates
//! through ([`Evaluate`]), which a mechanism, a [`Validated`](crate::Validated) handle and a
//! contact mode held over a step implement without restating the equations.
//!
//! Evaluation knows nothing of time stepping: nothing here imports [`crate::integrate`].

mod constants;
mod diagnosis;
pub(crate) mod rates;
pub use constants::{Constants, Prepare};
pub use diagnosis::diagnose;
pub(crate) use diagnosis::non_finite_at;

use crate::constraints::{ConstraintCounts, ContactModel};
use crate::dynamics::{solve_accelerations, EquationsOfMotion};
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::model::{check_state, Coordinates, State};
use crate::tree::rigid::{free, Joint};
use nalgebra::SMatrix;
use num_dual::DualSVec;

/// The equations of a mechanism with `N` degrees of freedom, evaluated at a state: what
/// `#[mechanism]` generates for a declaration (and [`impl_mechanism!`](crate::impl_mechanism) for a
/// hand-written [`Model`](crate::Model)), forwarding to the generic functions of
/// [`crate::dynamics`], [`crate::tree`], [`crate::affine`] and [`crate::constraints`].
///
/// Its shape:
///
/// | item | what |
/// |---|---|
/// | `type Coords` | the named coordinates |
/// | `type Contacts` | the contact modes of its rows ([`NoContacts`](crate::constraints::NoContacts), or [`ContactState`](crate::constraints::ContactState) with unilateral or friction rows, [`DrivenContacts`](crate::inputs::DrivenContacts) with inputs too): what a time loop holds over a step |
/// | `CONSTRAINT_COUNTS`, `CONSTRAINTS`, `SCLERONOMIC`, `CLOSED_FORM` | what the declaration states |
/// | `QUASI_VELOCITY_JOINTS`, `position_rates_at(q, v)` | which velocities are angular velocities, and q̇ = G(q) v (q̇ = v by default) |
/// | `check_parameters` | finite parameters, positive masses and inertias |
/// | `equations_of_motion_at(prepared, t, q, q̇)` | M, 𝓕 and b |
/// | `mass_matrix_at(prepared, t, q)` | M alone (by default from the equations of motion) |
/// | `accelerations_at(prepared, t, q, q̇)` | q̈ (by default M q̈ = 𝓕 − b solved) |
/// | `regular_accelerations_at(prepared, t, q, q̇)` | q̈ with every check in one branch, where the equations are straight-line code |
/// | `inverse_dynamics_at(prepared, t, q, q̇, q̈)` | τ = M q̈ + b − 𝓕 (by default from the equations of motion) |
/// | `kinetic_energy_at`, `potential_energy_at`, `momenta_at`, `lagrangian_time_derivative_at` | T, V, p = ∂L/∂q̇, ∂L/∂t |
/// | `canonical_field_at(prepared, t, q, q̇)` | (p, ṗ) for the methods on (q, p) |
/// | `holonomic_constraints_at`, `project(prepared, …)`, `check_constraints`, `check_declaration_at` | the constraint rows' values, the projection onto them, the consistency and declaration checks (no-ops without constraints) |
///
/// Every evaluation method takes the constants [`Prepare::prepare`] computed, `Some` through a
/// [`Validated`](crate::Validated) handle and `None` on the plain mechanism (which then evaluates
/// without them, or computes what it needs on the fly): one method per quantity, no twin for the
/// prepared path. The trait is evaluation only — no method steps time — and it is implemented
/// once per declaration: what wraps a mechanism and changes what is evaluated (a validated
/// handle's constants, a contact mode held over a step, the parameters lifted for sensitivities)
/// implements [`Evaluate`] or the [`Model`](crate::Model) beneath, overriding only what it changes.
/// The contact modes are a type the declaration names, with their evaluation (accelerations,
/// projection, event functions and switches in a mode, [`ContactModel`]); the loops that hold a
/// mode over a step, locate its events and switch it are [`crate::integrate`]'s.
#[doc(hidden)]
pub trait Dynamics<const N: usize>: Prepare + Sized {
    /// The named generalized coordinates (`Coords` of the declaration).
    type Coords: Coordinates<N>;

    /// The contact modes of the declaration's constraint rows and their evaluation:
    /// [`NoContacts`](crate::constraints::NoContacts) without unilateral or friction rows,
    /// [`ContactState`](crate::constraints::ContactState) with them (or with any constraint rows,
    /// its `SWITCHES` then false), [`DrivenContacts`](crate::inputs::DrivenContacts) for a
    /// declaration with inputs (the same modes, evaluated with the inputs of the call holding
    /// them).
    type Contacts: ContactModel<Self, N>;

    /// The constraint rows the declaration has, by kind (`Some(ConstraintCounts::NONE)` for none),
    /// or `None` when the implementation does not say. [`impl_mechanism!`](crate::impl_mechanism)
    /// and `#[mechanism]` declare it. Integrators decide from it alone — never from the state, so a
    /// constraint whose force happens to vanish (λ = 0) is treated as what it is:
    /// Störmer–Verlet and the variational integrator enforce holonomic rows by RATTLE and refuse
    /// velocity, unilateral and friction rows, and an undeclared implementation; implicit midpoint
    /// and Gauss–Legendre add Jᵀλ at every stage unless the mechanism declares no rows.
    const CONSTRAINT_COUNTS: Option<ConstraintCounts> = None;

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
    const SCLERONOMIC: bool = false;

    /// Whether `#[mechanism]` derived M, 𝓕 and b in closed form (straight-line code from the
    /// positions read as polynomials in the coordinates, their sines and cosines) rather than by
    /// the dual-number passes of [`crate::dynamics`].
    const CLOSED_FORM: bool = false;

    /// The joints whose free and ball members with
    /// [`Velocities::AngularVelocity`](crate::tree::rigid::Velocities::AngularVelocity) (declared
    /// `#[angular_velocity]`) have the body's angular velocity ω_b for velocities, not their
    /// chart's rates: a rigid tree's joints, or none, the default, where every velocity is its
    /// coordinate's rate. With such a joint the velocities are quasi-velocities, q̇ = G(q) v
    /// ([`position_rates_at`](Dynamics::position_rates_at), the maps of
    /// [`crate::tree::rigid::free`]), and every method below reads v and returns v̇, and
    /// generalized forces and momenta dual to v — but `canonical_field_at`, which reads its
    /// velocities as the coordinates' rates q̇ (the methods on (q, p) step such a mechanism in its
    /// rates through an adapter with its own canonical field, and never call it).
    const QUASI_VELOCITY_JOINTS: &'static [Joint] = &[];

    /// Whether the velocities are quasi-velocities (some joint of
    /// [`QUASI_VELOCITY_JOINTS`](Dynamics::QUASI_VELOCITY_JOINTS) has the angular velocity). The
    /// explicit Runge–Kutta methods step them; the methods on momenta conjugate to q̇ and Radau5
    /// step the coordinates' rates between conversions; Störmer–Verlet refuses them
    /// ([`Error::UnsuitableMethod`]).
    const QUASI_VELOCITIES: bool = free::has_angular_velocities(Self::QUASI_VELOCITY_JOINTS);

    /// q̇ = G(q) v: the coordinates' rates at velocities v (v itself unless
    /// [`QUASI_VELOCITIES`](Dynamics::QUASI_VELOCITIES)), for any scalar.
    #[inline(always)]
    fn position_rates_at<S: Scalar>(&self, q: &[S; N], v: &[S; N]) -> [S; N] {
        match Self::QUASI_VELOCITIES {
            false => *v,
            true => free::position_rates(Self::QUASI_VELOCITY_JOINTS, q, v),
        }
    }

    /// Checks the parameters: finite, masses and inertias positive (what `Mechanism::validate`
    /// calls).
    fn check_parameters(&self) -> Result<()>;

    /// M, 𝓕 and b at (t, q, q̇), for any scalar.
    fn equations_of_motion_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> EquationsOfMotion<S, N>;

    /// M(q, t) alone, for any scalar. By default the equations of motion's (evaluated at q̇ = 0,
    /// on which M does not depend); a rigid tree forms it by the composite-rigid-body algorithm
    /// without the Newton–Euler sweep and the forces the equations of motion also compute.
    #[inline]
    fn mass_matrix_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
    ) -> SMatrix<S, N, N> {
        Dynamics::equations_of_motion_at(self, prepared, t, q, &[S::zero(); N]).mass_matrix
    }

    /// q̈ at (t, q, q̇) for any scalar: solves M q̈ = 𝓕 − b (with the constraint forces of a
    /// constrained mechanism). No validation (the hot path of integrators, which validate once
    /// per step).
    #[inline]
    fn accelerations_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]> {
        let eom = Dynamics::equations_of_motion_at(self, prepared, t, q, v);
        solve_accelerations::<Self::Coords, S, N>(&eom, t, q)
    }

    /// q̈ at (t, q, q̇) with every check in one branch, for equations that are straight-line code
    /// ([`CLOSED_FORM`](Dynamics::CLOSED_FORM), or [`Prepare::PREPARED_IN_ONE_BRANCH`] with the
    /// constants; see [`crate::dynamics::regular_accelerations`]): `Some(q̈)` when the parameters
    /// pass their checks, the state and q̈ are finite and M is regular, `None` otherwise — and
    /// always `None` (the default) for equations that run user code, which is never evaluated at a
    /// state before the state is checked.
    #[inline(always)]
    fn regular_accelerations_at(
        &self,
        prepared: Constants<'_, Self>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Option<[f64; N]> {
        let _ = (prepared, t, q, v);
        None
    }

    /// The generalized forces τ = M q̈ + b − 𝓕 that make the mechanism move with accelerations
    /// `a` at (t, q, q̇) (inverse dynamics), for any scalar; by default from the equations of
    /// motion.
    #[inline]
    fn inverse_dynamics_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
        a: &[S; N],
    ) -> [S; N] {
        let eom = Dynamics::equations_of_motion_at(self, prepared, t, q, v);
        let tau = eom.mass_matrix * nalgebra::SVector::from(*a) + eom.inertial_terms
            - eom.generalized_forces;
        tau.into()
    }

    /// T at (t, q, q̇), for any scalar.
    fn kinetic_energy_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> S;

    /// V at (t, q), for any scalar.
    fn potential_energy_at<S: Scalar>(&self, prepared: Constants<'_, Self>, t: S, q: &[S; N]) -> S;

    /// p = ∂L/∂q̇ at (t, q, q̇), for any scalar.
    fn momenta_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> [S; N];

    /// ∂L/∂t at fixed (q, q̇) (zero for a scleronomic mechanism).
    fn lagrangian_time_derivative_at(
        &self,
        prepared: Constants<'_, Self>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> f64;

    /// The canonical field (p, ṗ) = (∂L/∂q̇, ∂L/∂q + F_nc) at (t, q, q̇), for any scalar: what the
    /// methods on (q, p) evaluate. By default from the momenta and a gradient of T of their own
    /// ([`momentum_rate`], on the mechanism without its constants); `#[mechanism]` computes a
    /// scleronomic mechanism's from one hyper-dual pass ([`crate::dynamics::canonical_field`]),
    /// or as straight-line code where it derives the equations in closed form
    /// ([`CLOSED_FORM`](Dynamics::CLOSED_FORM)), then with the prepared coefficients.
    #[inline]
    fn canonical_field_at<S: Scalar>(
        &self,
        prepared: Constants<'_, Self>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> ([S; N], [S; N]) {
        // Without the prepared constants, with the inputs.
        let plain = WithConstants {
            model: self,
            constants: Constants::NONE.with_inputs(prepared.inputs),
        };
        (plain.momenta_at(t, q, v), momentum_rate(&plain, t, q, v))
    }

    /// The declaration's inputs' names, flat (its `#[inputs]` struct's
    /// [`Inputs::NAMES`](crate::inputs::Inputs::NAMES)), empty without `#[inputs]`: what a
    /// sensitivity seed on an input is named by.
    const INPUT_NAMES: &'static [&'static str] = &[];

    /// q̈ at (t, q, q̇) with the inputs `inputs` (flat, in the order of
    /// [`INPUT_NAMES`](Dynamics::INPUT_NAMES), zeros where it has fewer) of the same scalar as the
    /// state, so dual numbers seeded on inputs carry ∂q̈/∂u: the declaration's forces read them
    /// through [`WithInputs`](crate::inputs::WithInputs) on that scalar, and q̈ is the generic
    /// solve of [`crate::dynamics`] (of [`crate::constraints`] with constraint rows, in the mode
    /// inferred from the state). `#[mechanism]` writes it for a declaration with `#[inputs]`; the
    /// default refuses ([`Error::UnsuitableMethod`]: no inputs to read).
    #[inline]
    fn accelerations_with_inputs_at<S: Scalar>(
        &self,
        inputs: &[S],
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]> {
        let _ = (inputs, t, q, v);
        Err(Error::UnsuitableMethod {
            method: "accelerations_with_inputs_at",
            reason: "the mechanism declares no inputs".to_string(),
        })
    }

    /// Mechanisms with holonomic constraints: their values g(q, t) at (t, q), for any scalar, in
    /// declaration order and padded with zeros to N entries (see
    /// [`crate::constraints::holonomic_values`]); `None` (the default) when the implementation
    /// does not provide them. RATTLE (Störmer–Verlet, the variational integrator) differentiates
    /// them with dual numbers.
    #[inline]
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        let _ = (t, q);
        None
    }

    /// Mechanisms with constraints: projects (q, q̇) at time `t` back onto them (see
    /// [`crate::constraints::project`]). Integrators call it after every step; the default does
    /// nothing. On error `q` and `v` are unchanged.
    #[inline]
    fn project(
        &self,
        prepared: Constants<'_, Self>,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
    ) -> Result<()> {
        let _ = (prepared, t, q, v);
        Ok(())
    }

    /// Mechanisms whose rotations are written in a chart of three coordinates (`rot_vector`,
    /// `rot_mrp`): keeps every chart regular by [`crate::geometry::switch_chart`] — past a
    /// rotation angle of π its coordinates and rates move to the equivalent point of the chart —
    /// and says whether one moved. Integrators call it after every accepted step, after the
    /// projection and after the step's dense output is written (which stays in the chart the
    /// step was taken in); the default does nothing.
    #[inline]
    fn switch_charts<S: Scalar>(&self, q: &mut [S; N], v: &mut [S; N]) -> bool {
        let _ = (q, v);
        false
    }

    /// Mechanisms with constraints: checks that (t, q, q̇) satisfies them within tolerance (see
    /// [`crate::constraints::check_consistent`]), so a state violating them is refused rather
    /// than silently projected. Integrators call it before a run; the default accepts.
    #[inline]
    fn check_constraints(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        let _ = (t, q, v);
        Ok(())
    }

    /// Mechanisms with constraints: checks what the declaration promises but only a state can
    /// show — that every velocity row is affine in q̇ (see
    /// [`crate::constraints::check_velocity_rows_affine`]) — so every entry point refuses the same
    /// declarations. The default accepts.
    #[inline]
    fn check_declaration_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        let _ = (t, q, v);
        Ok(())
    }
}

/// What the integrators, the analyses and the user calls evaluate: a mechanism's [`Dynamics`]
/// with the constants that go with it, each method the [`Dynamics`] method of the same name
/// without the constants argument. Implemented by every mechanism (no constants), by a
/// [`Validated`](crate::Validated) handle (its prepared constants) and by a contact mode held over
/// a step (which overrides the accelerations, the projection and the position rows): each
/// implementation gives [`model`](Evaluate::model) and [`prepared`](Evaluate::prepared) and
/// overrides only what it changes.
#[doc(hidden)]
pub trait Evaluate<const N: usize>: Sized {
    /// The declaration evaluated.
    type Model: Dynamics<N>;
    /// Its named coordinates (the model's).
    type Coords: Coordinates<N>;

    /// The constraint rows, by kind, as the integrators are to treat them (the model's).
    const CONSTRAINT_COUNTS: Option<ConstraintCounts> =
        <Self::Model as Dynamics<N>>::CONSTRAINT_COUNTS;
    /// The number of constraint rows (the model's).
    const CONSTRAINTS: Option<usize> = <Self::Model as Dynamics<N>>::CONSTRAINTS;
    /// Whether x does not depend on time (the model's).
    const SCLERONOMIC: bool = <Self::Model as Dynamics<N>>::SCLERONOMIC;
    /// Whether some velocities are quasi-velocities, q̇ = G(q) v (the model's).
    const QUASI_VELOCITIES: bool = <Self::Model as Dynamics<N>>::QUASI_VELOCITIES;
    /// Whether [`regular_accelerations_at`](Evaluate::regular_accelerations_at) checks a call in
    /// one branch: the closed form, and through a handle the prepared straight-line code.
    const ONE_BRANCH: bool = <Self::Model as Dynamics<N>>::CLOSED_FORM;

    /// The declaration.
    fn model(&self) -> &Self::Model;
    /// Its prepared constants, if any.
    fn prepared(&self) -> Constants<'_, Self::Model>;
    /// Checks the parameters (nothing through a validated handle, which checked them once).
    #[inline]
    fn check_parameters(&self) -> Result<()> {
        Dynamics::check_parameters(self.model())
    }

    /// [`Dynamics::position_rates_at`]: q̇ = G(q) v.
    #[inline(always)]
    fn position_rates_at<S: Scalar>(&self, q: &[S; N], v: &[S; N]) -> [S; N] {
        Dynamics::position_rates_at(self.model(), q, v)
    }
    /// [`Dynamics::equations_of_motion_at`].
    #[inline(always)]
    fn equations_of_motion_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> EquationsOfMotion<S, N> {
        Dynamics::equations_of_motion_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::mass_matrix_at`].
    #[inline(always)]
    fn mass_matrix_at<S: Scalar>(&self, t: S, q: &[S; N]) -> SMatrix<S, N, N> {
        Dynamics::mass_matrix_at(self.model(), self.prepared(), t, q)
    }
    /// [`Dynamics::accelerations_at`].
    #[inline(always)]
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> Result<[S; N]> {
        Dynamics::accelerations_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::regular_accelerations_at`].
    #[inline(always)]
    fn regular_accelerations_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Option<[f64; N]> {
        Dynamics::regular_accelerations_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::inverse_dynamics_at`].
    #[inline(always)]
    fn inverse_dynamics_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N], a: &[S; N]) -> [S; N] {
        Dynamics::inverse_dynamics_at(self.model(), self.prepared(), t, q, v, a)
    }
    /// [`Dynamics::kinetic_energy_at`].
    #[inline(always)]
    fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> S {
        Dynamics::kinetic_energy_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::potential_energy_at`].
    #[inline(always)]
    fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; N]) -> S {
        Dynamics::potential_energy_at(self.model(), self.prepared(), t, q)
    }
    /// [`Dynamics::momenta_at`].
    #[inline(always)]
    fn momenta_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [S; N] {
        Dynamics::momenta_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::lagrangian_time_derivative_at`].
    #[inline(always)]
    fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> f64 {
        Dynamics::lagrangian_time_derivative_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::canonical_field_at`].
    #[inline(always)]
    fn canonical_field_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> ([S; N], [S; N]) {
        Dynamics::canonical_field_at(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::holonomic_constraints_at`]: the position rows RATTLE enforces.
    #[inline(always)]
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        Dynamics::holonomic_constraints_at(self.model(), t, q)
    }
    /// How many leading entries of [`holonomic_constraints_at`](Evaluate::holonomic_constraints_at)
    /// are enforced: `None` (the default), every holonomic row
    /// [`CONSTRAINT_COUNTS`](Evaluate::CONSTRAINT_COUNTS) declares; a contact mode held over a step
    /// says how many position rows it holds (its holonomic rows and its closed contacts).
    ///
    /// ```
    /// use lagrange_core::evaluation::Evaluate;
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
    /// // A declared mechanism holds no mode, and the pendulum in its angle has no rows.
    /// assert_eq!(Pendulum.enforced_holonomic_rows(), None);
    /// assert_eq!(Pendulum.holonomic_constraints_at(0.0, &[0.3]), None);
    /// ```
    #[inline]
    fn enforced_holonomic_rows(&self) -> Option<usize> {
        None
    }
    /// [`Dynamics::project`].
    #[inline(always)]
    fn project(&self, t: f64, q: &mut [f64; N], v: &mut [f64; N]) -> Result<()> {
        Dynamics::project(self.model(), self.prepared(), t, q, v)
    }
    /// [`Dynamics::switch_charts`].
    #[inline(always)]
    fn switch_charts<S: Scalar>(&self, q: &mut [S; N], v: &mut [S; N]) -> bool {
        Dynamics::switch_charts(self.model(), q, v)
    }
    /// [`Dynamics::check_constraints`].
    #[inline(always)]
    fn check_constraints(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        Dynamics::check_constraints(self.model(), t, q, v)
    }
    /// [`Dynamics::check_declaration_at`].
    #[inline(always)]
    fn check_declaration_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        Dynamics::check_declaration_at(self.model(), t, q, v)
    }
    /// Checks parameters and state; what every user-facing call does first.
    #[inline]
    fn check(&self, state: &State<Self::Coords>) -> Result<([f64; N], [f64; N])> {
        self.check_parameters()?;
        let (q, v) = (state.q.to_array(), state.v.to_array());
        check_state(&Self::Coords::NAMES, state.t, &q, &v)?;
        Ok((q, v))
    }
}

/// A model evaluated with the constants a [`Dynamics`] method was handed: what a default method
/// evaluates the model's other quantities through.
struct WithConstants<'a, M: Prepare> {
    model: &'a M,
    constants: Constants<'a, M>,
}

impl<M: Dynamics<N>, const N: usize> Evaluate<N> for WithConstants<'_, M> {
    type Model = M;
    type Coords = M::Coords;
    #[inline(always)]
    fn model(&self) -> &M {
        self.model
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, M> {
        self.constants
    }
}

/// Every mechanism evaluates itself, without prepared constants.
impl<M: Dynamics<N>, const N: usize> Evaluate<N> for M {
    type Model = M;
    type Coords = M::Coords;
    #[inline(always)]
    fn model(&self) -> &M {
        self
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, M> {
        Constants::NONE
    }
}

/// G = ∂T/∂q + 𝓕 = ∂L/∂q + F_nc at (t, q, v), for any scalar: the right-hand side of ṗ = G (the
/// Euler–Lagrange equations in (q, p); see `integrate::canonical`). ∂T/∂q from one gradient dual
/// pass over q at fixed q̇; 𝓕 already contains −∇V and the non-conservative forces.
pub fn momentum_rate<M: Evaluate<N>, S: Scalar, const N: usize>(
    mechanism: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    let td = DualSVec::<S, N>::from_re(t);
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let vd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
    let kinetic = mechanism.kinetic_energy_at(td, &qd, &vd);
    let forces = mechanism.equations_of_motion_at(t, q, v).generalized_forces;
    match kinetic.eps.0 {
        Some(grad) => std::array::from_fn(|k| grad[k] + forces[k]),
        None => forces.into(),
    }
}
