//! [`HeldInputs`]: a mechanism evaluated with a slice of inputs held, for code that knows the
//! number of inputs only as a length ([`Declaration::INPUTS`](lagrange_core::declaration::Declaration::INPUTS)),
//! not as a type-level `NU`, as the C export does.

use lagrange_core::evaluation::{Constants, Evaluate};

/// `mechanism` with `inputs` (flat, in declaration order) held over every evaluation, step and
/// analysis made through it: the slice counterpart of
/// [`Driven`](lagrange_core::inputs::Driven), which holds an array of the declaration's `NU`
/// inputs. The inputs travel in [`Constants::inputs`], which the generated forces read (zeros
/// where the slice is shorter, none for a mechanism without inputs); everything else is
/// `mechanism`'s.
///
/// ```
/// use lagrange::prelude::*;
/// use lagrange::ffi::HeldInputs;
///
/// #[mechanism]
/// pub mod motor {
///     pub struct Coords {
///         pub theta: f64,
///     }
///     pub struct Motor {
///         pub j: f64,
///     }
///     #[inputs]
///     pub struct Torque {
///         pub tau: f64,
///     }
///     #[rigid_body(mass = 1.0, inertia = j)]
///     fn disc() -> Planar {
///         planar(vec2(0.0, 0.0), theta)
///     }
///     #[generalized_force(on = theta)]
///     fn drive() -> f64 {
///         tau
///     }
/// }
///
/// let sys = motor::Motor { j: 2.0 }.validated()?;
/// let state = motor::State::at_rest(motor::Coords { theta: 0.0 });
/// // j θ̈ = τ: θ̈ = 3 / 2.
/// let held = HeldInputs::new(&sys, &[3.0]);
/// assert_eq!(held.accelerations(&state)?.theta, 1.5);
/// assert_eq!(held.accelerations(&state)?, sys.driven(&motor::Torque { tau: 3.0 }).accelerations(&state)?);
/// # Ok::<(), lagrange::Error>(())
/// ```
pub struct HeldInputs<'a, E> {
    mechanism: &'a E,
    inputs: &'a [f64],
}

impl<'a, E> HeldInputs<'a, E> {
    /// `mechanism` with `inputs` held.
    pub fn new(mechanism: &'a E, inputs: &'a [f64]) -> Self {
        HeldInputs { mechanism, inputs }
    }
}

impl<E: Evaluate<N>, const N: usize> Evaluate<N> for HeldInputs<'_, E> {
    type Model = E::Model;
    type Coords = E::Coords;
    const CONSTRAINT_COUNTS: Option<lagrange_core::constraints::ConstraintCounts> =
        E::CONSTRAINT_COUNTS;
    const CONSTRAINTS: Option<usize> = E::CONSTRAINTS;
    const SCLERONOMIC: bool = E::SCLERONOMIC;
    const ONE_BRANCH: bool = E::ONE_BRANCH;

    #[inline(always)]
    fn model(&self) -> &E::Model {
        self.mechanism.model()
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, E::Model> {
        self.mechanism.prepared().with_inputs(self.inputs)
    }
    #[inline(always)]
    fn check_parameters(&self) -> lagrange_core::Result<()> {
        self.mechanism.check_parameters()
    }
}
