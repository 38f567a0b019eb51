//! Parameters as values of any scalar: what lets a simulation be differentiated with respect to a
//! mechanism's parameters ([`crate::sensitivity`], `Seed::Parameter`).
//!
//! A [`Model`] reads its parameters as `f64` fields. [`Parametrized`] is the same model with the
//! parameters passed in as an array of any scalar `S`: x(q, t; p), V(q, t; p) and the applied forces
//! F(q, q̇, t; p). [`Lifted`] binds such an array (dual numbers seeded on some parameters) to a
//! mechanism and is a [`Model`] again, so every generic function of [`crate::dynamics`] — the mass
//! matrix, the inertial terms, the generalized forces — carries ∂/∂p along without knowing about it.
//!
//! Masses, moments of inertia and the strength of a uniform field enter the dynamics as `f64`
//! ([`Model::masses`], [`Model::weights`]); a parameter that appears in one of them is not
//! [`SEEDABLE`](Parametrized::SEEDABLE).

use crate::geometry::Scalar;
use crate::model::Model;
use num_dual::DualNum;
use std::any::Any;

/// A [`Model`] whose position, potential and force functions take their parameters as an array of
/// any scalar. `#[mechanism]` implements it for every declaration (the parameters in the order of
/// the parameter struct's fields); [`impl_mechanism!`](crate::impl_mechanism) implements it with no
/// parameters (`NP = 0`) for hand-written models.
pub trait Parametrized<const N: usize, const K: usize, const NP: usize>: Model<N, K> {
    /// The parameters' names (the parameter struct's fields, in declaration order).
    const PARAMETER_NAMES: [&'static str; NP];

    /// Whether each parameter enters only x, V and the applied forces — the functions evaluated on
    /// any scalar — and so can carry a derivative. `false` for a parameter named in a mass, a
    /// moment of inertia or a uniform field (these are `f64` in the dynamics).
    const SEEDABLE: [bool; NP];

    /// The parameters' values, in the order of [`PARAMETER_NAMES`](Parametrized::PARAMETER_NAMES).
    fn parameters(&self) -> [f64; NP];

    /// x(q, t) with the parameters `p` in place of the fields (see [`Model::cartesian`]).
    fn cartesian_with<S: Scalar, D: Scalar>(&self, p: &[S; NP], t: D, q: &[D; N]) -> [D; K];

    /// V(q, t) with the parameters `p` (see [`Model::potential`]). The default is
    /// [`Model::potential`], right for a model whose potential reads no parameter.
    fn potential_with<S: Scalar, D: Scalar>(&self, p: &[S; NP], t: D, q: &[D; N], x: &[D; K]) -> D {
        let _ = p;
        self.potential(t, q, x)
    }

    /// The applied forces with the parameters `p` (see [`Model::applied_forces`]). The default is
    /// [`Model::applied_forces`], right for a model whose forces read no parameter.
    #[allow(clippy::too_many_arguments)]
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
        let _ = p;
        self.applied_forces(t, q, v, x, x_dot, cartesian_force, generalized_force)
    }

    /// The applied forces with the parameters `p` and the inputs `inputs` held (a declaration's
    /// `#[inputs]`, flat, zeros past the end of `inputs`): what a mechanism driven by inputs
    /// ([`crate::inputs::Driven`]) evaluates with its parameters lifted. The default is
    /// [`applied_forces_with`](Parametrized::applied_forces_with), right for a model whose forces
    /// read no inputs; `#[mechanism]` writes it for a declaration with `#[inputs]`.
    #[allow(clippy::too_many_arguments)]
    fn applied_forces_with_inputs_held<S: Scalar, D: Scalar>(
        &self,
        p: &[S; NP],
        inputs: &[f64],
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
        cartesian_force: &mut [D; K],
        generalized_force: &mut [D; N],
    ) {
        let _ = inputs;
        self.applied_forces_with(p, t, q, v, x, x_dot, cartesian_force, generalized_force)
    }
}

/// A parameter's value `s` as the scalar `D` a generated function evaluates on: `s` itself when
/// `D` is `S`, `s` as the real part of each nesting level when `D` is a dual number built on `S`
/// (the hyper-dual numbers of [`crate::dynamics`] built on a sensitivity run's duals), and the value
/// alone when `D` is `f64` (a plain evaluation needs no derivative). With `S = f64` it is
/// `D::from(s)`: the type tests are constants, so the plain path compiles to what it was.
///
/// ```
/// use lagrange_core::parameters::lift;
/// use num_dual::{Dual64, HyperDual64};
///
/// let l = Dual64::new(2.0, 1.0); // ∂l/∂l = 1
/// let on_hyper: num_dual::HyperDual<Dual64> = lift(&l);
/// assert_eq!(on_hyper.re, l);
/// assert_eq!(lift::<Dual64, Dual64>(&l), l);
/// assert_eq!(lift::<Dual64, f64>(&l), 2.0);
/// let plain: HyperDual64 = lift(&2.0);
/// assert_eq!(plain, HyperDual64::from(2.0));
/// ```
#[inline(always)]
pub fn lift<S: Scalar, D: Scalar>(s: &S) -> D {
    lift_into(s)
}

/// [`lift`] for any level of nesting (the real part of a dual number on `f64` is a dual number on
/// `f64` again, which `DualNum` alone does not state).
#[inline(always)]
fn lift_into<S: Scalar, D: DualNum>(s: &S) -> D {
    // The type tests are constants after monomorphisation: one branch is left.
    if let Some(same) = (s as &dyn Any).downcast_ref::<D>() {
        return same.clone();
    }
    let value: f64 = s.re();
    if let Some(real) = (&value as &dyn Any).downcast_ref::<D>() {
        return real.clone();
    }
    // D is a dual number whose parts are `D::InnerDual` (every scalar here has `f64` at the
    // bottom, where the recursion stops).
    D::from_re(lift_into::<S, D::InnerDual>(s))
}

/// A mechanism with its parameters replaced by values of the scalar `S` (dual numbers seeded on some
/// of them): a [`Model`] whose functions forward to the `*_with` functions of [`Parametrized`].
/// The inputs of a driven mechanism are held beside them ([`Lifted::with_inputs`]); none by
/// default (all zero).
///
/// ```
/// use lagrange_core::parameters::{Lifted, Parametrized};
/// use lagrange_core::{dynamics, impl_mechanism, vec2, Model, Scalar};
/// use num_dual::Dual64;
///
/// /// A pendulum of length l (the one parameter), unit mass, g = 1.
/// struct Pendulum { l: f64 }
/// impl Model<1, 2> for Pendulum {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 2] {
///         self.cartesian_with(&[self.l], t, q)
///     }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] }
/// }
/// impl Parametrized<1, 2, 1> for Pendulum {
///     const PARAMETER_NAMES: [&'static str; 1] = ["l"];
///     const SEEDABLE: [bool; 1] = [true];
///     fn parameters(&self) -> [f64; 1] { [self.l] }
///     fn cartesian_with<S: Scalar, D: Scalar>(&self, p: &[S; 1], _t: D, q: &[D; 1]) -> [D; 2] {
///         let l: D = lagrange_core::parameters::lift(&p[0]);
///         (vec2(q[0].sin(), -q[0].cos()) * l).to_array()
///     }
/// }
///
/// // θ̈ = −(g/l) sin θ, so ∂θ̈/∂l = (g/l²) sin θ.
/// let sys = Pendulum { l: 2.0 };
/// let lifted = Lifted::new(&sys, [Dual64::new(2.0, 1.0)]);
/// let theta = Dual64::from(0.5);
/// let a = dynamics::accelerations_generic(&lifted, Dual64::from(0.0), &[theta], &[Dual64::from(0.0)])?;
/// assert!((a[0].re + 0.5f64.sin() / 2.0).abs() < 1e-15);
/// assert!((a[0].eps - 0.5f64.sin() / 4.0).abs() < 1e-15);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub struct Lifted<'m, M, S, const K: usize, const NP: usize> {
    model: &'m M,
    parameters: [S; NP],
    inputs: &'m [f64],
}

impl<'m, M, S: Copy, const K: usize, const NP: usize> Lifted<'m, M, S, K, NP> {
    /// `model` with its parameters replaced by `parameters`.
    pub fn new(model: &'m M, parameters: [S; NP]) -> Self {
        Lifted {
            model,
            parameters,
            inputs: &[],
        }
    }

    /// The same with the inputs `inputs` held (flat, as [`crate::evaluation::Constants::inputs`]
    /// holds them), which its forces read.
    pub fn with_inputs(self, inputs: &'m [f64]) -> Self {
        Lifted { inputs, ..self }
    }

    /// The mechanism whose parameters are replaced.
    pub fn model(&self) -> &'m M {
        self.model
    }

    /// The parameters, as the scalar `S`.
    pub fn parameters(&self) -> &[S; NP] {
        &self.parameters
    }
}

impl<M, S: Copy, const K: usize, const NP: usize> Clone for Lifted<'_, M, S, K, NP> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<M, S: Copy, const K: usize, const NP: usize> Copy for Lifted<'_, M, S, K, NP> {}

impl<M, S: Scalar, const N: usize, const K: usize, const NP: usize> Model<N, K>
    for Lifted<'_, M, S, K, NP>
where
    M: Parametrized<N, K, NP>,
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

    fn masses(&self) -> [f64; K] {
        self.model.masses()
    }

    fn weights(&self) -> [f64; K] {
        self.model.weights()
    }

    #[inline(always)]
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; N]) -> [D; K] {
        self.model.cartesian_with(&self.parameters, t, q)
    }

    #[inline(always)]
    fn potential<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> D {
        self.model.potential_with(&self.parameters, t, q, x)
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
        self.model.applied_forces_with_inputs_held(
            &self.parameters,
            self.inputs,
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

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::{Dual64, DualSVec, HyperDualVec};

    #[test]
    fn lift_keeps_the_value_and_the_derivatives_at_every_level() {
        let s = DualSVec::<f64, 2>::new(
            1.5,
            num_dual::Derivative::some(nalgebra::SVector::from([0.25, -2.0])),
        );
        // The same type: a copy.
        assert_eq!(lift::<_, DualSVec<f64, 2>>(&s), s);
        // One level up: s is the real part, the new directions are zero.
        let h: HyperDualVec<DualSVec<f64, 2>, nalgebra::Const<3>, nalgebra::Const<3>> = lift(&s);
        assert_eq!(h.re, s);
        assert_eq!(h.eps1, num_dual::Derivative::none());
        // Two levels up.
        let d: Dual64 = lift(&2.0);
        assert_eq!(d, Dual64::from(2.0));
        let dd: num_dual::Dual<num_dual::Dual<DualSVec<f64, 2>>> = lift(&s);
        assert_eq!(dd.re.re, s);
        // Down to f64: the value alone.
        assert_eq!(lift::<_, f64>(&s), 1.5);
    }
}
