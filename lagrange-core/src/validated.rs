//! [`Validated`]: a mechanism whose parameters were checked once, so the calls of a simulation
//! check only what changes — the state.

use crate::error::Result;
use crate::evaluation::{Constants, Dynamics, Evaluate, Prepare};

/// A mechanism whose parameters (finite, masses and inertias positive, constraint declarations
/// well formed) were checked when it was made. Parameters do not change during a simulation, so
/// every call through the handle skips that check and validates only its state.
///
/// What the parameters alone decide is computed once, when the handle is made
/// ([`Prepare`]), and handed to every evaluation: for a mechanism whose positions are affine in the
/// coordinates (a block on a wedge, particles in Cartesian coordinates, see [`crate::affine`]) the
/// Jacobian and the factorisation of the constant mass matrix, so an evaluation of q̈ forms
/// neither; its results agree with the mechanism's own to round-off. For any other mechanism
/// nothing is prepared and the results are the same as the mechanism's own, bit for bit.
///
/// The handle owns a copy of the parameters and gives them out read-only ([`Validated::get`]), so
/// they cannot become invalid after the check. Every integrator and analysis that takes a
/// [`Mechanism`](crate::Mechanism) takes the handle: it implements [`Evaluate`], the trait they
/// evaluate through, by giving the parameters and the constants, nothing more.
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
    /// [`Mechanism::validated`](crate::Mechanism::validated)).
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
pub(crate) fn validate<M: Dynamics<N>, const N: usize>(mechanism: M) -> Result<Validated<M>> {
    mechanism.check_parameters()?;
    let prepared = mechanism.prepare()?;
    Ok(Validated(mechanism, prepared))
}

/// The mechanism with its prepared constants; the parameters were checked when the handle was
/// made.
impl<M: Dynamics<N>, const N: usize> Evaluate<N> for Validated<M> {
    type Model = M;
    type Coords = M::Coords;
    /// The closed form, or a mechanism whose q̈ is straight-line code with the prepared constants
    /// ([`Prepare::PREPARED_IN_ONE_BRANCH`]): through the handle, both are checked in one branch.
    const ONE_BRANCH: bool = M::CLOSED_FORM || M::PREPARED_IN_ONE_BRANCH;

    #[inline(always)]
    fn model(&self) -> &M {
        &self.0
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, M> {
        Constants::prepared(&self.1)
    }
    /// Checked when the handle was made.
    #[inline(always)]
    fn check_parameters(&self) -> Result<()> {
        Ok(())
    }
}
