//! [`Declaration`]: what a `#[mechanism]` declaration names — its parameters, its degrees of
//! freedom, its inputs, its constraint rows — for code that is generic over declarations and talks to the
//! world in flat arrays of numbers (the C export of `lagrange::export_c!`).

use crate::constraints::{constraint_forces, Constraints};
use crate::error::{Error, Result};
use crate::model::{Coordinates, State};

/// The names and flat values of a declaration, implemented by `#[mechanism]` for the parameter
/// struct. Everything here is in declaration order.
///
/// ```
/// use lagrange_core::declaration::Declaration;
/// # use lagrange_core::{impl_mechanism, vec2, Model, Scalar};
/// # #[derive(Debug, PartialEq)]
/// # struct Pendulum { l: f64, g: f64 }
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         (vec2(q[0].sin(), -q[0].cos()) * D::from(self.l)).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * self.g }
/// # }
/// # impl_mechanism!(Pendulum, 1, 2);
/// # impl Declaration for Pendulum {
/// #     const DOF: usize = 1;
/// #     const PARAMETERS: &'static [&'static str] = &["l", "g"];
/// #     fn from_parameters(values: &[f64]) -> Option<Self> {
/// #         match *values { [l, g] => Some(Pendulum { l, g }), _ => None }
/// #     }
/// #     fn parameters(&self) -> Vec<f64> { vec![self.l, self.g] }
/// # }
/// // `#[mechanism]` writes this impl for every declaration; here a hand-written pendulum.
/// assert_eq!(Pendulum::PARAMETERS, ["l", "g"]);
/// let p = Pendulum::from_parameters(&[2.0, 9.81]).unwrap();
/// assert_eq!(p, Pendulum { l: 2.0, g: 9.81 });
/// assert_eq!(p.parameters(), [2.0, 9.81]);
/// assert!(Pendulum::from_parameters(&[2.0]).is_none());
/// // No constraints: no rows, no forces.
/// assert!(p.constraint_forces(&[], 0.0, &[0.1], &[0.0])?.multipliers.is_empty());
/// // No `#[inputs]`: no input names.
/// assert!(Pendulum::INPUTS.is_empty());
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub trait Declaration: Sized {
    /// Degrees of freedom (the `N` of the mechanism's `Mechanism<N>` impl), so code generic over
    /// declarations can name the impl of a concrete type: `Mechanism<{ <T as Declaration>::DOF }>`.
    const DOF: usize;
    /// The parameters' names (the parameter struct's fields).
    const PARAMETERS: &'static [&'static str];
    /// The inputs' names, flat (`tau[0]`, `tau[1]` for an array field; the `#[inputs]` struct's
    /// [`Inputs::NAMES`](crate::inputs::Inputs::NAMES)), empty without `#[inputs]`.
    const INPUTS: &'static [&'static str] = &[];
    /// The constraint rows' names (empty without constraints).
    const CONSTRAINT_ROWS: &'static [&'static str] = &[];

    /// The parameter struct from its values; `None` unless there is exactly one value per
    /// parameter. Values are not checked here (that is `Mechanism::validate`).
    fn from_parameters(values: &[f64]) -> Option<Self>;

    /// The parameters' values.
    fn parameters(&self) -> Vec<f64>;

    /// The multipliers λ of the constraint rows and their generalized forces λᵢ·rᵢ (row-major,
    /// one row of `DOF` values per constraint) at (t, q, q̇) with `inputs` held (flat, in the
    /// order of [`INPUTS`](Declaration::INPUTS); zeros where it has none), as
    /// [`constraint_forces`] computes them; empty without constraints.
    ///
    /// Errors: `q` or `v` not of length `DOF` ([`Error::InvalidSetting`]), and those of
    /// [`constraint_forces`].
    fn constraint_forces(
        &self,
        inputs: &[f64],
        t: f64,
        q: &[f64],
        v: &[f64],
    ) -> Result<FlatConstraintForces> {
        let _ = (inputs, t);
        check_len("q", q, Self::DOF)?;
        check_len("v", v, Self::DOF)?;
        Ok(FlatConstraintForces::default())
    }
}

/// Constraint forces as flat arrays (see [`Declaration::constraint_forces`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlatConstraintForces {
    /// λᵢ, one per constraint row.
    pub multipliers: Vec<f64>,
    /// λᵢ·rᵢ, row-major: `DOF` values per constraint row.
    pub generalized: Vec<f64>,
}

/// [`Declaration::constraint_forces`] of a mechanism with constraints: what `#[mechanism]` writes
/// into the impl of a constrained declaration, `model` being the declaration (or, for one with
/// `#[inputs]`, the declaration with its inputs held,
/// [`WithInputs::held`](crate::inputs::WithInputs::held)).
pub fn flat_constraint_forces<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64],
    v: &[f64],
) -> Result<FlatConstraintForces> {
    let (mut qa, mut va) = ([0.0; N], [0.0; N]);
    qa.copy_from_slice(check_len("q", q, N)?);
    va.copy_from_slice(check_len("v", v, N)?);
    let state = State::new(
        t,
        <M::Coords as Coordinates<N>>::from_array(qa),
        <M::Coords as Coordinates<N>>::from_array(va),
    );
    let forces = constraint_forces(model, &state)?;
    Ok(FlatConstraintForces {
        multipliers: forces.multipliers.to_vec(),
        generalized: forces.generalized.iter().flatten().copied().collect(),
    })
}

/// `values` when it has `len` entries, otherwise [`Error::InvalidSetting`] naming it.
fn check_len<'a>(name: &'static str, values: &'a [f64], len: usize) -> Result<&'a [f64]> {
    if values.len() == len {
        Ok(values)
    } else {
        Err(Error::InvalidSetting {
            method: "constraint_forces",
            setting: name,
            value: values.len() as f64,
            requirement: "of length the degrees of freedom",
        })
    }
}
