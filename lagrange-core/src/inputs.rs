//! Inputs: what a program driving a mechanism sets between steps — a motor's torque, a thruster's
//! thrust, a steering angle — held constant over every evaluation of a step (a zero-order hold).
//!
//! A declaration names its inputs in an `#[inputs]` struct of `f64` fields, and its forces,
//! torques and generalized forces read them by name. [`Mechanism::driven`](crate::Mechanism::driven)
//! gives the mechanism with inputs `u` held, [`Driven`]: every evaluation, step, solver and analysis
//! of [`Mechanism`](crate::Mechanism) works on it and sees `u`. The mechanism itself (or its
//! validated handle) evaluated without inputs sees them all zero. A mechanism that declares no
//! inputs has no `driven` and pays nothing: its generated code is what it was.
//!
//! Inside, the inputs travel as data beside the prepared constants ([`Constants::inputs`]), so
//! no evaluation signature depends on whether a declaration has inputs. Where the generated
//! equations evaluate the forces they hand the generic functions of [`crate::dynamics`],
//! [`crate::tree::rigid`] and [`crate::constraints`] the model with its inputs, [`WithInputs`]:
//! a [`Model`] (and [`RigidTree`], [`Constraints`]) that is the declaration's in everything but its
//! applied forces, which read the inputs. With inputs of a dual-number type, the same functions
//! give ∂q̈/∂u ([`input_matrix`]).

mod contacts;
pub use contacts::DrivenContacts;

use crate::constraints::{CartesianMotion, ConstraintKind, ConstraintRows, Constraints, Coulomb};
use crate::dynamics::EquationsOfMotion;
use crate::evaluation::{Constants, Evaluate, Prepare};
use crate::geometry::Scalar;
use crate::model::{Model, GRADIENT_COEFFICIENTS};
use crate::parameters::lift;
use crate::tree::rigid::{Joint, RigidTree};
use nalgebra::SVector;

/// A declaration's inputs, by name: the `#[inputs]` struct (`#[mechanism]` implements it), its
/// fields flat in declaration order.
pub trait Inputs<const NU: usize>: Copy + Default + std::fmt::Debug {
    /// The inputs' names, flat (`tau[0]`, `tau[1]` for an array field).
    const NAMES: [&'static str; NU];
    /// The values, flat, in the order of [`NAMES`](Inputs::NAMES).
    fn to_array(&self) -> [f64; NU];
    /// The inputs from flat values.
    fn from_array(values: [f64; NU]) -> Self;
}

/// A mechanism whose declaration names inputs: which struct holds them.
pub trait Actuated<const NU: usize> {
    /// The `#[inputs]` struct.
    type Inputs: Inputs<NU>;
    /// Where every input is a generalized force on a coordinate of its own — declared as
    /// `#[generalized_force(on = q)] fn motor() -> f64 { u }` (or `{ tau[2] }`), read nowhere
    /// else — the coordinate each input acts on, in input order: then the inputs that give wanted
    /// accelerations are read off inverse dynamics
    /// ([`Mechanism::inverse_dynamics_inputs`](crate::Mechanism::inverse_dynamics_inputs)).
    /// `None` otherwise.
    const COORDINATES: Option<[usize; NU]> = None;
}

/// A [`Model`] whose applied forces read inputs: `#[mechanism]` implements it for a declaration
/// with `#[inputs]`, [`Model::applied_forces`] being these forces at zero inputs.
pub trait ActuatedModel<const N: usize, const K: usize, const NU: usize>: Model<N, K> {
    /// The applied forces at (t, q, q̇) with the inputs `u`, of any scalar (see
    /// [`Model::applied_forces`]).
    #[allow(clippy::too_many_arguments)]
    fn applied_forces_with_inputs<S: Scalar, U: Scalar>(
        &self,
        u: &[U; NU],
        t: S,
        q: &[S; N],
        v: &[S; N],
        x: &[S; K],
        x_dot: &[S; K],
        cartesian_force: &mut [S; K],
        generalized_force: &mut [S; N],
    );

    /// [`Model::coordinate_forces`] with the inputs `u`: by default the applied forces with x
    /// and ẋ zero (which forces on coordinates alone do not read).
    #[inline(always)]
    fn coordinate_forces_with_inputs<S: Scalar, U: Scalar>(
        &self,
        u: &[U; NU],
        t: S,
        q: &[S; N],
        v: &[S; N],
        generalized_force: &mut [S; N],
    ) {
        let unread = [S::zero(); K];
        let mut cartesian = [S::zero(); K];
        self.applied_forces_with_inputs(
            u,
            t,
            q,
            v,
            &unread,
            &unread,
            &mut cartesian,
            generalized_force,
        );
    }
}

/// An input's value `u` as the scalar `S` a force function evaluates on (see [`lift`]).
#[inline(always)]
pub fn input<U: Scalar, S: Scalar>(u: &U) -> S {
    lift(u)
}

/// The model of a declaration with its inputs held: the declaration in everything but its
/// applied forces, which read `inputs` ([`ActuatedModel::applied_forces_with_inputs`]). `U` is
/// `f64` for an evaluation, a dual number for ∂q̈/∂u.
pub struct WithInputs<'m, M, U, const NU: usize> {
    model: &'m M,
    inputs: [U; NU],
}

impl<'m, M, U: Scalar, const NU: usize> WithInputs<'m, M, U, NU> {
    /// `model` with the inputs held flat — those a [`Constants`] holds, or dual numbers seeded on
    /// some of them ([`Dynamics::accelerations_with_inputs_at`](crate::evaluation::Dynamics::accelerations_with_inputs_at)):
    /// `inputs` in order, zeros where it has none (a mechanism evaluated without inputs).
    #[inline(always)]
    pub fn held(model: &'m M, inputs: &[U]) -> Self {
        WithInputs {
            model,
            inputs: std::array::from_fn(|i| inputs.get(i).copied().unwrap_or(U::zero())),
        }
    }
}

impl<'m, M, U, const NU: usize> WithInputs<'m, M, U, NU> {
    /// `model` with `inputs`.
    #[inline(always)]
    pub fn new(model: &'m M, inputs: [U; NU]) -> Self {
        WithInputs { model, inputs }
    }

    /// The declaration.
    #[inline(always)]
    pub fn model(&self) -> &'m M {
        self.model
    }
}

impl<M, U: Scalar, const N: usize, const K: usize, const NU: usize> Model<N, K>
    for WithInputs<'_, M, U, NU>
where
    M: ActuatedModel<N, K, NU>,
{
    type Coords = M::Coords;
    const INERTIAL: usize = M::INERTIAL;
    const RHEONOMIC: bool = M::RHEONOMIC;
    const HAS_POTENTIAL: bool = M::HAS_POTENTIAL;
    const HAS_FORCES: bool = M::HAS_FORCES;
    const GENERALIZED_FORCES_ONLY: bool = M::GENERALIZED_FORCES_ONLY;
    const DEPENDS: [[bool; N]; K] = M::DEPENDS;
    const HAS_GRAVITY: bool = M::HAS_GRAVITY;

    fn validate(&self) -> crate::Result<()> {
        self.model.validate()
    }
    #[inline(always)]
    fn parameters_pass(&self) -> bool {
        self.model.parameters_pass()
    }
    #[inline(always)]
    fn masses(&self) -> [f64; K] {
        self.model.masses()
    }
    #[inline(always)]
    fn weights(&self) -> [f64; K] {
        self.model.weights()
    }
    #[inline(always)]
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; N]) -> [D; K] {
        self.model.cartesian(t, q)
    }
    #[inline(always)]
    fn potential<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> D {
        self.model.potential(t, q, x)
    }
    #[inline(always)]
    fn potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<SVector<S, N>>; K],
    ) -> Option<SVector<S, N>> {
        self.model.potential_gradient(t, q, x, rows)
    }
    #[inline(always)]
    fn scaled_potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<SVector<S, N>>; K],
        scale: &[f64; N],
        prepared: &[f64; GRADIENT_COEFFICIENTS],
    ) -> Option<SVector<S, N>> {
        self.model
            .scaled_potential_gradient(t, q, x, rows, scale, prepared)
    }
    fn gradient_coefficients(&self, scale: &[f64; N]) -> [f64; GRADIENT_COEFFICIENTS] {
        self.model.gradient_coefficients(scale)
    }
    #[inline(always)]
    fn coordinate_forces<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        generalized_force: &mut [S; N],
    ) {
        self.model
            .coordinate_forces_with_inputs(&self.inputs, t, q, v, generalized_force)
    }
    #[inline(always)]
    fn applied_forces<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        x: &[S; K],
        x_dot: &[S; K],
        cartesian_force: &mut [S; K],
        generalized_force: &mut [S; N],
    ) {
        self.model.applied_forces_with_inputs(
            &self.inputs,
            t,
            q,
            v,
            x,
            x_dot,
            cartesian_force,
            generalized_force,
        )
    }
}

/// The declaration's constants: holding inputs changes no parameter.
impl<M: Prepare, U, const NU: usize> Prepare for WithInputs<'_, M, U, NU> {
    type Prepared = M::Prepared;
    const PREPARED_IN_ONE_BRANCH: bool = M::PREPARED_IN_ONE_BRANCH;
    fn prepare(&self) -> crate::Result<M::Prepared> {
        self.model.prepare()
    }
}

impl<M: RigidTree<N, B>, U, const N: usize, const B: usize, const NU: usize> RigidTree<N, B>
    for WithInputs<'_, M, U, NU>
{
    const JOINTS: [Joint; B] = M::JOINTS;
}

impl<M, U: Scalar, const N: usize, const K: usize, const C: usize, const NU: usize>
    Constraints<N, K, C> for WithInputs<'_, M, U, NU>
where
    M: ActuatedModel<N, K, NU> + Constraints<N, K, C>,
{
    const NAMES: [&'static str; C] = <M as Constraints<N, K, C>>::NAMES;
    const KINDS: [ConstraintKind; C] = M::KINDS;
    const QUASI_VELOCITY_JOINTS: &'static [Joint] =
        <M as Constraints<N, K, C>>::QUASI_VELOCITY_JOINTS;
    const POSITION_DERIVATIVES: [bool; C] = M::POSITION_DERIVATIVES;

    #[inline(always)]
    fn position_constraints<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> [D; C] {
        self.model.position_constraints(t, q, x)
    }
    #[inline(always)]
    fn tree_equations<F: Model<N, K>, S: Scalar>(
        &self,
        forces: &F,
        t: S,
        q: &[S; N],
        rates: &[S; N],
    ) -> Option<EquationsOfMotion<S, N>> {
        self.model.tree_equations(forces, t, q, rates)
    }
    #[inline(always)]
    fn position_constraint_derivatives<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        motion: &CartesianMotion<S, N, K>,
        rows: &mut ConstraintRows<S, N, C>,
    ) {
        self.model
            .position_constraint_derivatives(t, q, v, motion, rows)
    }
    #[inline(always)]
    fn velocity_constraints<D: Scalar>(
        &self,
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
    ) -> [D; C] {
        self.model.velocity_constraints(t, q, v, x, x_dot)
    }
    fn friction_coefficients(&self, row: usize) -> Coulomb {
        self.model.friction_coefficients(row)
    }
    fn validate_constraints(&self) -> crate::Result<()> {
        self.model.validate_constraints()
    }
}

/// A mechanism with its inputs held: what [`Mechanism::driven`](crate::Mechanism::driven) returns
/// (the inputs an array of the declaration's `NU`), or, for code that knows the number of inputs
/// only as a length (the C export), a slice (`Driven::new(&sys, &inputs[..])`). It is a
/// mechanism again — every evaluation, step, solver ([`Stepper`](crate::Stepper)) and analysis
/// takes it — and every one of them sees the inputs, constant over each step (a zero-order hold):
/// a controller sets new inputs between steps by making a new `Driven`. The inputs travel in
/// [`Constants::inputs`], which the generated forces read (zeros where they are fewer than the
/// declaration's); everything else is the mechanism's. The README's "Inputs" section shows one
/// in use.
pub struct Driven<'m, E, I> {
    mechanism: &'m E,
    inputs: I,
}

impl<'m, E, I: AsRef<[f64]>> Driven<'m, E, I> {
    /// `mechanism` with `inputs` (flat, in declaration order) held.
    pub fn new(mechanism: &'m E, inputs: I) -> Self {
        Driven { mechanism, inputs }
    }

    /// The inputs held, flat.
    pub fn inputs(&self) -> &[f64] {
        self.inputs.as_ref()
    }

    /// The mechanism driven.
    pub fn mechanism(&self) -> &'m E {
        self.mechanism
    }
}

impl<E, I: Copy> Clone for Driven<'_, E, I> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<E, I: Copy> Copy for Driven<'_, E, I> {}

impl<E: Evaluate<N>, I: AsRef<[f64]>, const N: usize> Evaluate<N> for Driven<'_, E, I> {
    type Model = E::Model;
    type Coords = E::Coords;
    const CONSTRAINT_COUNTS: Option<crate::constraints::ConstraintCounts> = E::CONSTRAINT_COUNTS;
    const CONSTRAINTS: Option<usize> = E::CONSTRAINTS;
    const SCLERONOMIC: bool = E::SCLERONOMIC;
    const ONE_BRANCH: bool = E::ONE_BRANCH;

    #[inline(always)]
    fn model(&self) -> &E::Model {
        self.mechanism.model()
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, E::Model> {
        self.mechanism.prepared().with_inputs(self.inputs.as_ref())
    }
    #[inline(always)]
    fn check_parameters(&self) -> crate::Result<()> {
        self.mechanism.check_parameters()
    }
}

/// ∂q̈/∂u: how the accelerations of a mechanism change with its inputs at a state, the inputs at
/// `inputs` — the input matrix B of the linearized system d/dt (δq, δq̇) = A (δq, δq̇) + [0; B] δu
/// beside [`linearize`](crate::analysis::linearize)'s A (both at once:
/// [`linearize_driven`](crate::analysis::linearize_driven)). One evaluation of q̈ on dual numbers
/// seeded on the inputs
/// ([`Dynamics::accelerations_with_inputs_at`](crate::evaluation::Dynamics::accelerations_with_inputs_at)):
/// without constraint rows B = M⁻¹ ∂𝓕/∂u, differentiated through the solve of M q̈ = 𝓕 − b;
/// with them, through the constrained solve too, in the contact mode the state implies (which
/// holds for a small enough δu away from a mode change). Exact for inputs that enter the forces
/// non-linearly too.
///
/// Errors: those of [`Mechanism::accelerations`](crate::Mechanism::accelerations) of the driven
/// mechanism at the state; non-finite derivatives
/// ([`Error::NonFiniteDynamics`](crate::Error::NonFiniteDynamics)).
pub fn input_matrix<E, const N: usize, const NU: usize>(
    mechanism: &E,
    inputs: &<E::Model as Actuated<NU>>::Inputs,
    state: &crate::State<E::Coords>,
) -> crate::Result<nalgebra::SMatrix<f64, N, NU>>
where
    E: Evaluate<N>,
    E::Model: Actuated<NU>,
{
    use crate::evaluation::Dynamics;
    use crate::Mechanism;
    use num_dual::DualSVec;
    let u = inputs.to_array();
    let driven = Driven::new(mechanism, u);
    let (q, v) = driven.check(state)?;
    driven.accelerations(state)?;
    let seeded: [DualSVec<f64, NU>; NU] =
        std::array::from_fn(|j| DualSVec::from_re(u[j]).derivative(j));
    let constant = |x: &[f64; N]| x.map(DualSVec::<f64, NU>::from_re);
    let t = DualSVec::from_re(state.t);
    let qdd =
        mechanism
            .model()
            .accelerations_with_inputs_at(&seeded, t, &constant(&q), &constant(&v))?;
    let b = nalgebra::SMatrix::<f64, N, NU>::from_fn(|i, j| qdd[i].eps.0.map_or(0.0, |d| d[j]));
    if !b.iter().all(|x| x.is_finite()) {
        return Err(crate::Error::NonFiniteDynamics {
            t: state.t,
            configuration: crate::error::describe_configuration(
                &<E::Coords as crate::model::Coordinates<N>>::NAMES,
                &q,
            ),
        });
    }
    Ok(b)
}
