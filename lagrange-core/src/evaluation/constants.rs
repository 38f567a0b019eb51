//! The constants a validated handle prepares once ([`Prepare`]) and what every
//! [`Dynamics`](super::Dynamics) method is handed beside the state ([`Constants`]: those constants
//! and the inputs held).

use crate::error::Result;

/// What a mechanism computes once from its parameters, when it is validated, so that every
/// evaluation of a simulation reuses it: [`Validated`](crate::Validated) stores it next to the
/// parameters (which cannot change while the handle exists) and hands it to every
/// [`Dynamics`](super::Dynamics) method.
///
/// `#[mechanism]` prepares the constants of a declaration whose positions are affine in the
/// coordinates (x = A q + c: J = A and M = Aᵀ diag(μ) A constant, see [`crate::affine`]), the
/// coefficients of equations it derives in closed form, and nothing, `()`, for any other;
/// [`impl_mechanism!`](crate::impl_mechanism) likewise (`affine` for the former).
#[doc(hidden)]
pub trait Prepare {
    /// The constants (`()` when there are none).
    type Prepared: Copy + std::fmt::Debug + PartialEq;
    /// Whether [`Dynamics::regular_accelerations_at`](super::Dynamics::regular_accelerations_at) with the constants is straight-line code
    /// that runs no user code, every check in one branch (an affine mechanism whose potentials'
    /// gradients `#[mechanism]` derived and that declares no force, see
    /// [`crate::affine::regular_accelerations`]): a validated handle then takes
    /// `Mechanism::accelerations`' one-branch path, as the closed form does.
    const PREPARED_IN_ONE_BRANCH: bool = false;
    /// Computes them from valid parameters. Fails only where the parameters alone decide the
    /// equations of motion are singular (a constant mass matrix that is not positive definite).
    fn prepare(&self) -> Result<Self::Prepared>;
}

/// What a [`Dynamics`](super::Dynamics) method is handed besides the state: the prepared constants (`Some`
/// through a [`Validated`](crate::Validated) handle, `None` on the plain mechanism) and the
/// inputs held over the evaluation (a declaration's `#[inputs]`, in declaration order; empty
/// where none are set, which the generated force functions read as zeros, see
/// [`crate::inputs`]).
pub struct Constants<'a, M: Prepare + ?Sized> {
    /// The constants [`Prepare::prepare`] computed, if any.
    pub prepared: Option<&'a M::Prepared>,
    /// The inputs, flat (empty when none are set).
    pub inputs: &'a [f64],
}

impl<M: Prepare + ?Sized> Clone for Constants<'_, M> {
    #[inline(always)]
    fn clone(&self) -> Self {
        *self
    }
}

impl<M: Prepare + ?Sized> Copy for Constants<'_, M> {}

impl<'a, M: Prepare + ?Sized> Constants<'a, M> {
    /// Nothing prepared, no inputs: what the plain mechanism evaluates with.
    pub const NONE: Self = Constants {
        prepared: None,
        inputs: &[],
    };

    /// The prepared constants, no inputs: what a validated handle evaluates with.
    #[inline(always)]
    pub fn prepared(prepared: &'a M::Prepared) -> Self {
        Constants {
            prepared: Some(prepared),
            inputs: &[],
        }
    }

    /// The same constants with `inputs` held.
    #[inline(always)]
    pub fn with_inputs(self, inputs: &'a [f64]) -> Self {
        Constants { inputs, ..self }
    }
}
