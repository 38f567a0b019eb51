//! [`Validated`]: a mechanism whose parameters were checked once, so the calls of a simulation
//! check only what changes — the state.

use crate::dynamics::EquationsOfMotion;
use crate::error::Result;
use crate::geometry::Scalar;
use crate::mechanism::{Dynamics, Mechanism, Prepare};
use crate::model::Model;
use crate::parameters::Parametrized;

/// A mechanism whose parameters (finite, masses and inertias positive, constraint declarations
/// well formed) were checked when it was made. Parameters do not change during a simulation, so
/// every call through the handle skips that check and validates only its state.
///
/// What the parameters alone decide is computed once, when the handle is made
/// ([`crate::mechanism::Prepare`]): for a mechanism whose positions are affine in the
/// coordinates (a block on a wedge, particles in Cartesian coordinates, see [`crate::affine`]) the
/// Jacobian and the factorisation of the constant mass matrix, so an evaluation of q̈ forms
/// neither; its results agree with the mechanism's own to round-off. For any other mechanism
/// nothing is prepared and the results are the same as the mechanism's own, bit for bit.
///
/// The handle owns a copy of the parameters and gives them out read-only ([`Validated::get`]), so
/// they cannot become invalid after the check. Every integrator and analysis that takes a
/// [`Mechanism`] takes the handle.
///
/// ```
/// use lagrange_core::{impl_mechanism, vec2, Mechanism, Model, Rk4, Scalar, State};
///
/// /// A pendulum of mass `m` on a unit rod, written by hand (`#[mechanism]` writes the same).
/// struct Pendulum { m: f64 }
///
/// impl Model<1, 2> for Pendulum {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> {
///         match self.m > 0.0 {
///             true => Ok(()),
///             false => Err(lagrange_core::Error::InvalidInertia {
///                 body: "bob",
///                 reason: format!("mass must be positive, got {}", self.m),
///             }),
///         }
///     }
///     fn masses(&self) -> [f64; 2] { [self.m, self.m] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
///         vec2(q[0].sin(), -q[0].cos()).to_array()
///     }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * (9.81 * self.m) }
/// }
/// impl_mechanism!(Pendulum, 1, 2);
///
/// # fn main() -> lagrange_core::Result<()> {
/// let sys = Pendulum { m: 1.0 }.validated()?;
/// let mut s = State::at_rest([0.5]);
/// sys.step::<Rk4>(&mut s, 1e-3)?;
/// assert!(sys.accelerations(&s)?[0] < 0.0);
///
/// // Invalid parameters are refused once, up front.
/// assert!(Pendulum { m: -1.0 }.validated().is_err());
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Validated<M: Prepare>(M, M::Prepared);

impl<M: Prepare> Validated<M> {
    /// The parameters.
    pub fn get(&self) -> &M {
        &self.0
    }

    /// The parameters, to change them (and check them again with
    /// [`Mechanism::validated`]).
    pub fn into_inner(self) -> M {
        self.0
    }
}

impl<M: Prepare> std::ops::Deref for Validated<M> {
    type Target = M;
    fn deref(&self) -> &M {
        &self.0
    }
}

/// Checks `mechanism`'s parameters, prepares what they alone decide, and wraps both.
pub(crate) fn validate<M: Mechanism<N>, const N: usize>(mechanism: M) -> Result<Validated<M>> {
    mechanism.validate()?;
    let prepared = mechanism.prepare()?;
    Ok(Validated(mechanism, prepared))
}

/// The handle has prepared its mechanism's constants already.
impl<M: Prepare> Prepare for Validated<M> {
    type Prepared = ();
    #[inline(always)]
    fn prepare(&self) -> Result<()> {
        Ok(())
    }
}

impl<M: Dynamics<N>, const N: usize> Dynamics<N> for Validated<M> {
    type Coords = M::Coords;
    const CONSTRAINTS: Option<usize> = M::CONSTRAINTS;
    const SCLERONOMIC: bool = M::SCLERONOMIC;
    const CONSTRAINT_COUNTS: Option<crate::constraints::ConstraintCounts> = M::CONSTRAINT_COUNTS;
    /// The closed form, or a mechanism whose q̈ is straight-line code with the prepared constants
    /// ([`Prepare::PREPARED_IN_ONE_BRANCH`]): through the handle, both are checked in one branch.
    const CLOSED_FORM: bool = M::CLOSED_FORM || M::PREPARED_IN_ONE_BRANCH;

    /// Checked when the handle was made.
    #[inline(always)]
    fn check_parameters(&self) -> Result<()> {
        Ok(())
    }
    #[inline(always)]
    fn equations_of_motion_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> EquationsOfMotion<S, N> {
        self.0.equations_of_motion_at(t, q, v)
    }
    #[inline(always)]
    fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> S {
        self.0.kinetic_energy_at(t, q, v)
    }
    #[inline(always)]
    fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; N]) -> S {
        self.0.potential_energy_at(t, q)
    }
    #[inline(always)]
    fn momenta_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [S; N] {
        self.0.momenta_at(t, q, v)
    }
    #[inline(always)]
    fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> f64 {
        self.0.lagrangian_time_derivative_at(t, q, v)
    }
    #[inline(always)]
    fn canonical_field_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> ([S; N], [S; N]) {
        self.0.canonical_field_prepared_at(&self.1, t, q, v)
    }
    #[inline(always)]
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> Result<[S; N]> {
        self.0.accelerations_prepared_at(&self.1, t, q, v)
    }
    #[inline(always)]
    fn inverse_dynamics_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N], qdd: &[S; N]) -> [S; N] {
        self.0.inverse_dynamics_prepared_at(&self.1, t, q, v, qdd)
    }
    #[inline(always)]
    fn regular_accelerations_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Option<[f64; N]> {
        self.0.regular_accelerations_prepared_at(&self.1, t, q, v)
    }
    #[inline(always)]
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        self.0.holonomic_constraints_at(t, q)
    }
    #[inline(always)]
    fn project(&self, t: f64, q: &mut [f64; N], v: &mut [f64; N]) -> Result<()> {
        self.0.project_prepared(&self.1, t, q, v)
    }
    #[inline(always)]
    fn check_declaration_at(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        self.0.check_declaration_at(t, q, v)
    }
    #[inline(always)]
    fn check_constraints(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<()> {
        self.0.check_constraints(t, q, v)
    }
    #[inline(always)]
    fn step_contacts<I: crate::integrate::Integrator>(
        &self,
        state: &mut crate::model::State<Self::Coords>,
        h: f64,
    ) -> Option<Result<()>> {
        self.0.step_contacts::<I>(state, h)
    }
    #[inline(always)]
    fn integrate_contacts<P, O>(
        &self,
        method: P,
        state: &mut crate::model::State<Self::Coords>,
        t_end: f64,
        events: &mut [crate::integrate::Event<'_, Self::Coords>],
        observer: O,
    ) -> Option<Result<crate::integrate::Outcome<Self::Coords>>>
    where
        P: crate::integrate::EmbeddedPair,
        O: FnMut(crate::integrate::Observation<'_, Self::Coords, N>),
    {
        self.0
            .integrate_contacts(method, state, t_end, events, observer)
    }
}

/// The model behind the handle, for the generic code that works on a [`Model`] (the parameter
/// sensitivities lift it; see [`crate::parameters`]).
impl<M: Model<N, K> + Prepare, const N: usize, const K: usize> Model<N, K> for Validated<M> {
    type Coords = M::Coords;
    const INERTIAL: usize = M::INERTIAL;
    const RHEONOMIC: bool = M::RHEONOMIC;
    const HAS_POTENTIAL: bool = M::HAS_POTENTIAL;
    const HAS_FORCES: bool = M::HAS_FORCES;
    const DEPENDS: [[bool; N]; K] = M::DEPENDS;
    const HAS_GRAVITY: bool = M::HAS_GRAVITY;

    /// Checked when the handle was made.
    #[inline(always)]
    fn validate(&self) -> Result<()> {
        Ok(())
    }
    #[inline(always)]
    fn masses(&self) -> [f64; K] {
        self.0.masses()
    }
    #[inline(always)]
    fn weights(&self) -> [f64; K] {
        self.0.weights()
    }
    #[inline(always)]
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; N]) -> [D; K] {
        self.0.cartesian(t, q)
    }
    #[inline(always)]
    fn potential<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> D {
        self.0.potential(t, q, x)
    }
    #[inline(always)]
    fn potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<nalgebra::SVector<S, N>>; K],
    ) -> Option<nalgebra::SVector<S, N>> {
        self.0.potential_gradient(t, q, x, rows)
    }
    #[inline(always)]
    fn applied_forces<D: Scalar>(
        &self,
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
        cartesian_force: &mut [D; K],
        generalized_force: &mut [D; N],
    ) {
        self.0
            .applied_forces(t, q, v, x, x_dot, cartesian_force, generalized_force)
    }
}

impl<M, const N: usize, const K: usize, const NP: usize> Parametrized<N, K, NP> for Validated<M>
where
    M: Parametrized<N, K, NP> + Prepare,
{
    const PARAMETER_NAMES: [&'static str; NP] = M::PARAMETER_NAMES;
    const SEEDABLE: [bool; NP] = M::SEEDABLE;
    #[inline(always)]
    fn parameters(&self) -> [f64; NP] {
        self.0.parameters()
    }
    #[inline(always)]
    fn cartesian_with<S: Scalar, D: Scalar>(&self, p: &[S; NP], t: D, q: &[D; N]) -> [D; K] {
        self.0.cartesian_with(p, t, q)
    }
    #[inline(always)]
    fn potential_with<S: Scalar, D: Scalar>(&self, p: &[S; NP], t: D, q: &[D; N], x: &[D; K]) -> D {
        self.0.potential_with(p, t, q, x)
    }
    #[inline(always)]
    fn applied_forces_with<S: Scalar, D: Scalar>(
        &self,
        p: &[S; NP],
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
        cartesian_force: &mut [D; K],
        generalized_force: &mut [D; N],
    ) {
        self.0
            .applied_forces_with(p, t, q, v, x, x_dot, cartesian_force, generalized_force)
    }
}
