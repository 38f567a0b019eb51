//! What a mechanism declaration compiles to, and the state it is simulated in.
//!
//! A declaration is reduced to one idea: the **Cartesian coordinates** x(q, t) ∈ ℝᴷ of everything
//! that carries mass, each with a constant mass μᵢ, so that the kinetic energy is
//!
//! ```text
//! T = ½ Σᵢ μᵢ ẋᵢ²,        ẋ = J(q,t) q̇ + ∂x/∂t,   J = ∂x/∂q.
//! ```
//!
//! A particle contributes its 2 or 3 position components (μ = its mass). A planar rigid body
//! contributes its centre of mass (μ = m) and its angle (μ = I, since ½Iθ̇² has the same form).
//! A spatial rigid body with principal moments I₁, I₂, I₃ contributes its centre of mass and the
//! three columns of its rotation matrix R, column k with μ = Jₖ = (I₁ + I₂ + I₃)/2 − Iₖ, because
//! ½ ωᵀ I ω = ½ tr(Ṙ diag(J) Ṙᵀ) (Lee, Leok & McClamroch, *Global Formulations of Lagrangian and
//! Hamiltonian Dynamics on Manifolds*, 2018, eq. (6.34)). Points where forces act but that carry no
//! mass come last, with μ = 0, so their Jacobians are available for the virtual work of forces.
//!
//! Everything else — mass matrix, inertial terms, generalized forces — follows from x(q, t) by
//! automatic differentiation in [`crate::dynamics`]. The `#[mechanism]` attribute writes an
//! implementation of [`Model`]; users never implement it by hand (but can).

use crate::error::{Error, Result};
use crate::geometry::Scalar;

/// A named set of generalized coordinates (or velocities) of a mechanism with `N` degrees of
/// freedom. The `#[mechanism]` attribute implements it for the generated `Coords` struct.
pub trait Coordinates<const N: usize>: Copy + Default + std::fmt::Debug {
    /// The coordinates' names, in declaration order.
    const NAMES: [&'static str; N];
    /// The values in declaration order.
    fn to_array(&self) -> [f64; N];
    /// Builds the named struct from values in declaration order.
    fn from_array(values: [f64; N]) -> Self;
    /// The values in declaration order as a nalgebra column vector, for linear algebra on a
    /// state or a result (accelerations, momenta, an equilibrium).
    ///
    /// ```
    /// use lagrange_core::Coordinates;
    /// use nalgebra::SVector;
    /// let q = [1.0, 2.0];
    /// assert_eq!(q.to_vector(), SVector::<f64, 2>::new(1.0, 2.0));
    /// assert_eq!(<[f64; 2]>::from_vector(SVector::<f64, 2>::new(3.0, 4.0)), [3.0, 4.0]);
    /// ```
    fn to_vector(&self) -> nalgebra::SVector<f64, N> {
        nalgebra::SVector::from(self.to_array())
    }
    /// Builds the named struct from a nalgebra column vector in declaration order.
    fn from_vector(values: nalgebra::SVector<f64, N>) -> Self {
        Self::from_array(values.into())
    }
}

/// Plain arrays are coordinates too (named q0, q1, … in messages); useful for hand-written models.
impl<const N: usize> Coordinates<N> for [f64; N]
where
    [f64; N]: Default,
{
    const NAMES: [&'static str; N] = {
        const NAMES: [&str; 32] = [
            "q0", "q1", "q2", "q3", "q4", "q5", "q6", "q7", "q8", "q9", "q10", "q11", "q12", "q13",
            "q14", "q15", "q16", "q17", "q18", "q19", "q20", "q21", "q22", "q23", "q24", "q25",
            "q26", "q27", "q28", "q29", "q30", "q31",
        ];
        let mut out = ["q"; N];
        let mut i = 0;
        while i < N && i < 32 {
            out[i] = NAMES[i];
            i += 1;
        }
        out
    };
    fn to_array(&self) -> [f64; N] {
        *self
    }
    fn from_array(values: [f64; N]) -> Self {
        values
    }
}

/// The state of a mechanism: time, generalized coordinates q and generalized velocities v = q̇.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct State<C> {
    /// Time.
    pub t: f64,
    /// Generalized coordinates q.
    pub q: C,
    /// Generalized velocities q̇.
    pub v: C,
}

impl<C: Default> State<C> {
    /// At rest at `q`, at t = 0.
    pub fn at_rest(q: C) -> Self {
        State {
            t: 0.0,
            q,
            v: C::default(),
        }
    }
}

impl<C> State<C> {
    /// At `q` with velocities `v`, at time `t`.
    pub fn new(t: f64, q: C, v: C) -> Self {
        State { t, q, v }
    }

    /// The generalized coordinates q as a nalgebra column vector, in declaration order.
    ///
    /// ```
    /// use lagrange_core::State;
    /// use nalgebra::SVector;
    ///
    /// let s = State::new(0.5, [1.0, 2.0], [-3.0, 4.0]);
    /// assert_eq!(s.q_vector(), SVector::<f64, 2>::new(1.0, 2.0));
    /// assert_eq!(s.v_vector(), SVector::<f64, 2>::new(-3.0, 4.0));
    /// let back = State::<[f64; 2]>::from_vectors(s.t, s.q_vector(), s.v_vector());
    /// assert_eq!(back, s);
    /// ```
    pub fn q_vector<const N: usize>(&self) -> nalgebra::SVector<f64, N>
    where
        C: Coordinates<N>,
    {
        self.q.to_vector()
    }

    /// The generalized velocities q̇ as a nalgebra column vector, in declaration order.
    pub fn v_vector<const N: usize>(&self) -> nalgebra::SVector<f64, N>
    where
        C: Coordinates<N>,
    {
        self.v.to_vector()
    }

    /// A state at time `t` from q and q̇ as nalgebra column vectors, in declaration order.
    pub fn from_vectors<const N: usize>(
        t: f64,
        q: nalgebra::SVector<f64, N>,
        v: nalgebra::SVector<f64, N>,
    ) -> Self
    where
        C: Coordinates<N>,
    {
        State {
            t,
            q: C::from_vector(q),
            v: C::from_vector(v),
        }
    }
}

/// How many constant factors of a potential's gradient a prepared handle computes once
/// ([`Model::gradient_coefficients`]); a gradient with more computes the others where it uses them.
pub const GRADIENT_COEFFICIENTS: usize = 16;

/// The generated description of a mechanism: `N` generalized coordinates, `K` Cartesian coordinates
/// (see the [module docs](self)). Implemented by `#[mechanism]`; the numerical work on it lives in
/// [`crate::dynamics`].
pub trait Model<const N: usize, const K: usize> {
    /// The named coordinates.
    type Coords: Coordinates<N>;

    /// Rows `0..INERTIAL` of x carry mass; rows `INERTIAL..K` are massless points forces act at.
    const INERTIAL: usize = K;
    /// Whether x or V depend on time explicitly (a rheonomic mechanism). When false no time
    /// derivative is seeded and momenta need no ∂x/∂t term.
    const RHEONOMIC: bool;
    /// Whether a potential V(q, t) is declared (gravity, springs, …).
    const HAS_POTENTIAL: bool;
    /// Whether applied Cartesian or generalized forces are declared.
    const HAS_FORCES: bool;
    /// Whether every applied force is a generalized force on a coordinate that reads no body's
    /// position or velocity (a motor, joint damping): [`applied_forces`](Model::applied_forces)
    /// then reads neither `x` nor `x_dot`, and a rigid tree evaluates it without forming x or
    /// its Jacobian. `false`, the safe default, for an implementation that does not say.
    const GENERALIZED_FORCES_ONLY: bool = false;

    /// Adds the applied forces of a model whose forces are all generalized forces that read no
    /// body ([`GENERALIZED_FORCES_ONLY`](Model::GENERALIZED_FORCES_ONLY)) to `generalized_force`,
    /// without x. By default [`applied_forces`](Model::applied_forces) with x and ẋ zero (which
    /// such forces do not read); `#[mechanism]` writes it without them.
    #[inline(always)]
    fn coordinate_forces<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        generalized_force: &mut [S; N],
    ) {
        let unread = [S::zero(); K];
        let mut cartesian = [S::zero(); K];
        self.applied_forces(t, q, v, &unread, &unread, &mut cartesian, generalized_force);
    }

    /// `DEPENDS[i][j]`: row i of x may depend on coordinate j. `false` only where the declaration
    /// shows it cannot (row i's body, and the bodies it is placed from, never name coordinate j; or
    /// the body writes its components out and row i's component does not): a structural zero of
    /// the Jacobian, whose products the dense assembly of M, b and 𝓕 skips, and whose couplings the
    /// constrained solve's factorisation of M leaves out ([`crate::linalg::mass_pattern`]).
    /// By default every row may depend on every coordinate.
    const DEPENDS: [[bool; N]; K] = [[true; N]; K];

    /// Checks the parameters: finite, masses and inertias positive.
    fn validate(&self) -> Result<()>;

    /// Whether [`validate`](Model::validate) passes, as one test without a branch per parameter:
    /// what a call of equations in closed form folds into its single check
    /// ([`crate::dynamics::regular_accelerations`]). `#[mechanism]` writes it for declarations
    /// without spatial bodies; by default it is `validate` itself.
    #[doc(hidden)]
    #[inline]
    fn parameters_pass(&self) -> bool {
        self.validate().is_ok()
    }

    /// μᵢ for each Cartesian coordinate (0 for massless force points).
    fn masses(&self) -> [f64; K];

    /// x(q, t).
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; N]) -> [D; K];

    /// Whether a uniform field (gravity) acts, with Cartesian force [`Model::weights`] on each row.
    /// A uniform field needs no differentiation: its generalized force is Jᵀw and its potential
    /// −w·x (for g = (0, −g): V = Σ m g y).
    const HAS_GRAVITY: bool = false;

    /// The weight μᵢgᵢ of each Cartesian row in the uniform field (0 for rows that are not a
    /// position component of a massive point or centre of mass).
    fn weights(&self) -> [f64; K] {
        [0.0; K]
    }

    /// V(q, t); `x` is [`Model::cartesian`] at the same (q, t), passed so bodies are not recomputed.
    fn potential<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> D {
        let _ = (t, q, x);
        D::zero()
    }

    /// ∇V at (t, q) taken potential by potential, each on dual numbers seeded only on the
    /// coordinates it depends on, from x and its Jacobian rows J (already known to the caller);
    /// `None` (the default) when the model does not provide it and ∇V is taken on all N at once.
    /// `#[mechanism]` writes it when every declared potential names fewer than N coordinates (a
    /// spring between two masses of a chain): the cost of the gradient is then proportional to
    /// the potentials' own coordinates, not to N per potential.
    #[inline(always)]
    fn potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<nalgebra::SVector<S, N>>; K],
    ) -> Option<nalgebra::SVector<S, N>> {
        let _ = (t, q, x, rows);
        None
    }

    /// ∇V at (t, q) as [`potential_gradient`](Model::potential_gradient) takes it, each slot j
    /// multiplied by `scale[j]`: with sⱼ = −1/Mⱼⱼ for a constant diagonal M, the accelerations
    /// q̈ = −M⁻¹∇V of a potential the only force, each sⱼ joined to the constant factors of its
    /// slot's derivative (one product fewer after the state's arithmetic). `prepared` is
    /// [`gradient_coefficients`](Model::gradient_coefficients) of the same `scale`, computed
    /// once: the constant factors themselves (μ m sⱼ, ω²/2), so an evaluation does only the
    /// state's arithmetic. `None` (the default) when the model does not provide it. `#[mechanism]`
    /// writes it for affine positions with every potential's gradient derived on its expression
    /// tree; [`crate::affine`] calls it.
    #[doc(hidden)]
    #[inline(always)]
    fn scaled_potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<nalgebra::SVector<S, N>>; K],
        scale: &[f64; N],
        prepared: &[f64; GRADIENT_COEFFICIENTS],
    ) -> Option<nalgebra::SVector<S, N>> {
        let _ = (t, q, x, rows, scale, prepared);
        None
    }

    /// The constant factors [`scaled_potential_gradient`](Model::scaled_potential_gradient)
    /// reads, from the parameters and `scale` (zeros by default).
    #[doc(hidden)]
    fn gradient_coefficients(&self, scale: &[f64; N]) -> [f64; GRADIENT_COEFFICIENTS] {
        let _ = scale;
        [0.0; GRADIENT_COEFFICIENTS]
    }

    /// Adds applied forces at (t, q, q̇): Cartesian components on the rows of x they act on
    /// (`cartesian_force`), and forces directly on coordinates (`generalized_force`).
    /// `x` and `x_dot` are the Cartesian positions and velocities at the same state.
    #[allow(clippy::too_many_arguments)]
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
        let _ = (t, q, v, x, x_dot, cartesian_force, generalized_force);
    }
}

/// Checks that a state is finite; the error names the coordinates.
pub fn check_state<const N: usize>(
    names: &[&'static str; N],
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    // Branch-free on the common path: s·0 is 0 exactly when s is finite, and the sum s of every
    // value is finite when they all are; a sum that overflows although every value is finite is
    // sorted out off the hot path.
    if (t + lane_sum::<N>(|j| q[j] + v[j])) * 0.0 == 0.0 {
        Ok(())
    } else {
        finite_or_non_finite_state(names, t, q, v)
    }
}

/// Σⱼ term(j) over j < N, in two interleaved lanes (even and odd j) added at the end: what the
/// one-branch finiteness tests sum (a sum is finite when every term is, and s·0 = 0 exactly when
/// s is finite). Two lanes are two independent chains the compiler can keep in one vector
/// register; a single chain of additions, which it may not reorder, would be N in series. Each
/// lane starts from −0, the identity of `+`, so nothing is added to a zero.
#[inline(always)]
pub(crate) fn lane_sum<const N: usize>(term: impl Fn(usize) -> f64) -> f64 {
    let mut lanes = [-0.0; 2];
    for j in 0..N {
        lanes[j % 2] += term(j);
    }
    lanes[0] + lanes[1]
}

/// Whether t, q, q̇ and q̈ are all finite, by one sum: the one-branch test of the calls whose
/// q̈ is straight-line code (`dynamics::regular_accelerations`, `affine::regular_accelerations`).
/// A sum that overflows although every value is finite answers `false`, which only sends the
/// caller down its checked path, where the same q̈ is returned.
#[inline(always)]
pub(crate) fn state_and_accelerations_finite<const N: usize>(
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    qdd: &[f64; N],
) -> bool {
    (t + lane_sum::<N>(|j| q[j] + v[j] + qdd[j])) * 0.0 == 0.0
}

/// [`check_state`] when the sum of the values is not finite: `Ok` when every value is (the sum
/// overflowed), otherwise the error naming the state.
#[cold]
#[inline(never)]
fn finite_or_non_finite_state<const N: usize>(
    names: &[&'static str; N],
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    if t.is_finite() && q.iter().chain(v).all(|x| x.is_finite()) {
        Ok(())
    } else {
        non_finite_state(names, t, q, v)
    }
}

#[cold]
#[inline(never)]
fn non_finite_state<const N: usize>(
    names: &[&'static str; N],
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    Err(Error::NonFiniteState {
        state: crate::error::describe_state(names, t, q, v),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::SVector;

    /// Named coordinates whose declaration order (r, phi) is not alphabetical.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct Polar {
        r: f64,
        phi: f64,
    }

    impl Coordinates<2> for Polar {
        const NAMES: [&'static str; 2] = ["r", "phi"];
        fn to_array(&self) -> [f64; 2] {
            [self.r, self.phi]
        }
        fn from_array(values: [f64; 2]) -> Self {
            Polar {
                r: values[0],
                phi: values[1],
            }
        }
    }

    #[test]
    fn vectors_follow_declaration_order() {
        let s = State::new(
            1.25,
            Polar { r: 2.0, phi: 0.5 },
            Polar { r: -0.1, phi: 3.0 },
        );
        assert_eq!(s.q_vector(), SVector::<f64, 2>::new(2.0, 0.5));
        assert_eq!(s.v_vector(), SVector::<f64, 2>::new(-0.1, 3.0));
        let back = State::<Polar>::from_vectors(1.25, s.q_vector(), s.v_vector());
        assert_eq!(back, s);
        let q = Polar::from_vector(SVector::<f64, 2>::new(7.0, -1.0));
        assert_eq!(q, Polar { r: 7.0, phi: -1.0 });
        assert_eq!(q.to_vector()[1], -1.0);
    }
}
