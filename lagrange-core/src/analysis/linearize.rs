//! Linearization of the equations of motion about any state.

use super::to_dmatrix;
use crate::error::{Error, Result};
use crate::inputs::{Actuated, Inputs as _};
use crate::mechanism::Mechanism;
use crate::model::State;
use nalgebra::{DMatrix, SMatrix};
use num_dual::DualSVec;

/// The first-order system linearized about a state x₀ = (q₀, v₀) at time t:
///
/// ```text
/// d/dt δx = ẋ₀ + A δx + B u,   δx = (δq, δv),
/// A = [ ∂q̇/∂q  ∂q̇/∂v ]  =  [ 0       I      ]      B = [ 0   ]
///     [ ∂q̈/∂q  ∂q̈/∂v ]     [ ∂q̈/∂q   ∂q̈/∂v ]          [ M⁻¹ ]
/// ```
///
/// — the top row [0, I] where the velocities are the coordinates' rates. Where some are
/// quasi-velocities (a free or ball joint's angular velocity, `Dynamics::QUASI_VELOCITIES`),
/// q̇ = G(q) v and the top row is [∂(G v)/∂q, G] ([`dqd_dq`](Linearization::dqd_dq),
/// [`dqd_dv`](Linearization::dqd_dv)); the bottom row is then v̇'s, and M the mass matrix on v.
///
/// ẋ₀ = (G v₀, v̇₀) (= (v₀, q̈₀) where the velocities are the rates) is zero about an equilibrium at
/// rest. A is 2N × 2N, which a fixed-size nalgebra type cannot spell on stable Rust
/// (`SMatrix<f64, {2 * N}, {2 * N}>` needs `generic_const_exprs`), so its four N × N blocks are
/// stored and [`Linearization::a_matrix`] assembles a `DMatrix`.
///
/// **Inputs.** `u` is a vector of additional generalized forces, one per coordinate, entering as
/// M q̈ = 𝓕 − b + u; hence B = [0; M⁻¹] ([`Linearization::b_matrix`]). A declared input acting as a
/// direct generalized force on coordinate k is column k of B. An input that is a Cartesian force
/// F on a point with Jacobian Jₚ = ∂rₚ/∂q enters as u = Jₚᵀ F, so its B is [0; M⁻¹Jₚᵀ]; inputs that
/// enter the forces non-linearly need their own derivative: for a declaration's `#[inputs]`,
/// [`linearize_driven`] gives B for the inputs themselves.
///
/// ```
/// use lagrange_core::analysis::linearize;
/// use lagrange_core::State;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// // A swinging pendulum: ∂θ̈/∂θ = −(g/l) cos θ, no velocity dependence.
/// let lin = linearize(&Pendulum { m: 1.0, l: 1.0, g: 9.81 }, &State::new(0.0, [0.2], [1.5]))?;
/// assert!((lin.dqdd_dq[(0, 0)] + 9.81 * 0.2f64.cos()).abs() < 1e-12);
/// assert_eq!(lin.dqdd_dv[(0, 0)], 0.0);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Linearization<const N: usize> {
    /// Time of the state linearized about.
    pub t: f64,
    /// q₀.
    pub q: [f64; N],
    /// v₀ (q̇₀ unless the velocities are quasi-velocities).
    pub v: [f64; N],
    /// q̈₀: the accelerations at the state (zero at an equilibrium).
    pub accelerations: [f64; N],
    /// ∂q̈/∂q: the lower-left block of A (−M⁻¹K at an equilibrium at rest).
    pub dqdd_dq: SMatrix<f64, N, N>,
    /// ∂q̈/∂v: the lower-right block of A (−M⁻¹D at an equilibrium at rest: damping, gyroscopic
    /// and Coriolis terms).
    pub dqdd_dv: SMatrix<f64, N, N>,
    /// ∂q̈/∂u = M⁻¹: the lower block of B for generalized-force inputs.
    pub dqdd_du: SMatrix<f64, N, N>,
    /// ∂q̇/∂q: the upper-left block of A (zero unless the velocities are quasi-velocities).
    pub dqd_dq: SMatrix<f64, N, N>,
    /// ∂q̇/∂v: the upper-right block of A (the identity unless the velocities are
    /// quasi-velocities, then G(q₀)).
    pub dqd_dv: SMatrix<f64, N, N>,
}

impl<const N: usize> Linearization<N> {
    /// The four N × N blocks of A, row-major: `[[∂q̇/∂q, ∂q̇/∂v], [∂q̈/∂q, ∂q̈/∂v]]` =
    /// `[[dqd_dq, dqd_dv], [dqdd_dq, dqdd_dv]]` (`[[0, I], …]` where the velocities are rates).
    ///
    /// ```
    /// use lagrange_core::analysis::linearize;
    /// # use lagrange_core::analysis::doc_models::Pendulum;
    /// use lagrange_core::State;
    /// let lin = linearize(&Pendulum { m: 1.0, l: 1.0, g: 9.81 }, &State::at_rest([0.0]))?;
    /// let [[_, identity], [stiff, _]] = lin.blocks();
    /// assert_eq!(identity[(0, 0)], 1.0);
    /// assert!((stiff[(0, 0)] + 9.81).abs() < 1e-12);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn blocks(&self) -> [[SMatrix<f64, N, N>; 2]; 2] {
        [[self.dqd_dq, self.dqd_dv], [self.dqdd_dq, self.dqdd_dv]]
    }

    /// The full 2N × 2N matrix A of d/dt(δq, δv) = A (δq, δv), rows and columns ordered
    /// (q₀ … q_{N−1}, v₀ … v_{N−1}).
    ///
    /// ```
    /// use lagrange_core::analysis::linearize;
    /// # use lagrange_core::analysis::doc_models::Pendulum;
    /// use lagrange_core::State;
    /// let lin = linearize(&Pendulum { m: 1.0, l: 1.0, g: 9.81 }, &State::at_rest([0.0]))?;
    /// let a = lin.a_matrix();
    /// assert_eq!(a.shape(), (2, 2));
    /// // Eigenvalues ±i√(g/l): tr A = 0, det A = g/l.
    /// assert!((a.determinant() - 9.81).abs() < 1e-12 && a.trace().abs() < 1e-15);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn a_matrix(&self) -> DMatrix<f64> {
        let mut a = DMatrix::zeros(2 * N, 2 * N);
        a.view_mut((0, 0), (N, N))
            .copy_from(&to_dmatrix(&self.dqd_dq));
        a.view_mut((0, N), (N, N))
            .copy_from(&to_dmatrix(&self.dqd_dv));
        a.view_mut((N, 0), (N, N))
            .copy_from(&to_dmatrix(&self.dqdd_dq));
        a.view_mut((N, N), (N, N))
            .copy_from(&to_dmatrix(&self.dqdd_dv));
        a
    }

    /// The 2N × N matrix B = [0; M⁻¹] for generalized-force inputs (see the type's docs).
    ///
    /// ```
    /// use lagrange_core::analysis::linearize;
    /// # use lagrange_core::analysis::doc_models::Pendulum;
    /// use lagrange_core::State;
    /// // A torque u on a pendulum (m = 2, l = 3) gives θ̈ = u / (m l²).
    /// let lin = linearize(&Pendulum { m: 2.0, l: 3.0, g: 9.81 }, &State::at_rest([0.0]))?;
    /// assert!((lin.b_matrix()[(1, 0)] - 1.0 / 18.0).abs() < 1e-15);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn b_matrix(&self) -> DMatrix<f64> {
        let mut b = DMatrix::zeros(2 * N, N);
        b.view_mut((N, 0), (N, N))
            .copy_from(&to_dmatrix(&self.dqdd_du));
        b
    }
}

/// Linearizes the equations of motion about `state` (any state, not only an equilibrium): the
/// Jacobians of q̈(t, q, q̇) with respect to q and q̇, exact, by evaluating
/// `Dynamics::accelerations_at` on gradient dual numbers (one pass seeded on q, one on q̇; the
/// Cholesky solve of M q̈ = 𝓕 − b is differentiated along). See [`Linearization`] for the layout.
///
/// Errors: non-finite parameters or state, a singular mass matrix at the state, non-finite
/// derivatives. The state is not modified.
///
/// ```
/// use lagrange_core::analysis::linearize;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// use lagrange_core::State;
/// let p = Pendulum { m: 1.0, l: 2.0, g: 9.81 };
/// // About θ = 0.3 at rest: θ̈ ≈ −(g/l) sin 0.3 − (g/l) cos 0.3 δθ.
/// let lin = linearize(&p, &State::at_rest([0.3]))?;
/// assert!((lin.accelerations[0] + 9.81 / 2.0 * 0.3f64.sin()).abs() < 1e-12);
/// assert!((lin.dqdd_dq[(0, 0)] + 9.81 / 2.0 * 0.3f64.cos()).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn linearize<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    state: &State<M::Coords>,
) -> Result<Linearization<N>> {
    let (q, v) = mechanism.check(state)?;
    let t = state.t;
    let td = DualSVec::<f64, N>::from_re(t);
    let seeded = |x: &[f64; N]| -> [DualSVec<f64, N>; N] {
        std::array::from_fn(|j| DualSVec::from_re(x[j]).derivative(j))
    };
    let plain = |x: &[f64; N]| -> [DualSVec<f64, N>; N] {
        std::array::from_fn(|j| DualSVec::from_re(x[j]))
    };

    let by_q = mechanism.accelerations_at(td, &seeded(&q), &plain(&v))?;
    let by_v = mechanism.accelerations_at(td, &plain(&q), &seeded(&v))?;
    let mut dqdd_dq = SMatrix::<f64, N, N>::zeros();
    let mut dqdd_dv = SMatrix::<f64, N, N>::zeros();
    for i in 0..N {
        dqdd_dq.set_row(i, &super::gradient(&by_q[i]).transpose());
        dqdd_dv.set_row(i, &super::gradient(&by_v[i]).transpose());
    }
    let accelerations: [f64; N] = std::array::from_fn(|i| by_q[i].re);
    let (dqd_dq, dqd_dv) = position_rate_jacobians(mechanism, &q, &v);

    // ∂q̈/∂u = M⁻¹, column by column from the Cholesky factor.
    let mass_matrix = mechanism.equations_of_motion_at(t, &q, &v).mass_matrix;
    let l = super::mass_cholesky::<M, N>(&mass_matrix, t, &q)?;
    let mut dqdd_du = SMatrix::<f64, N, N>::zeros();
    for j in 0..N {
        let e = SMatrix::<f64, N, 1>::from_fn(|i, _| if i == j { 1.0 } else { 0.0 });
        dqdd_du.set_column(j, &crate::linalg::cholesky_substitute(&l, &e));
    }

    let finite = dqdd_dq
        .iter()
        .chain(dqdd_dv.iter())
        .chain(dqdd_du.iter())
        .chain(dqd_dq.iter())
        .chain(dqd_dv.iter())
        .chain(accelerations.iter())
        .all(|x| x.is_finite());
    if !finite {
        return Err(Error::NonFiniteDynamics {
            t,
            configuration: super::describe::<M, N>(&q),
        });
    }
    Ok(Linearization {
        t,
        q,
        v,
        accelerations,
        dqdd_dq,
        dqdd_dv,
        dqdd_du,
        dqd_dq,
        dqd_dv,
    })
}

/// (∂q̇/∂q, ∂q̇/∂v) of q̇ = G(q) v at (q, v): (0, I) where the velocities are the rates, else two
/// dual passes through `Dynamics::position_rates_at`.
fn position_rate_jacobians<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    q: &[f64; N],
    v: &[f64; N],
) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
    if !M::QUASI_VELOCITIES {
        return (SMatrix::zeros(), SMatrix::identity());
    }
    let seeded = |x: &[f64; N]| -> [DualSVec<f64, N>; N] {
        std::array::from_fn(|j| DualSVec::from_re(x[j]).derivative(j))
    };
    let plain = |x: &[f64; N]| x.map(DualSVec::<f64, N>::from_re);
    let by_q = mechanism.position_rates_at(&seeded(q), &plain(v));
    let by_v = mechanism.position_rates_at(&plain(q), &seeded(v));
    let rows =
        |x: [DualSVec<f64, N>; N]| SMatrix::<f64, N, N>::from_fn(|i, j| super::gradient(&x[i])[j]);
    (rows(by_q), rows(by_v))
}

/// The linearization of a mechanism driven by its declared inputs `u₀` about a state: A at the
/// driven state, and the input matrix of the inputs themselves,
///
/// ```text
/// d/dt δx = ẋ₀ + A δx + B δu,   B = [ 0       ]  (2N × NU),
///                                   [ ∂q̈/∂u ]
/// ```
///
/// δu the change of the inputs from `u₀`, in the order of
/// [`Inputs::NAMES`](crate::inputs::Inputs::NAMES). What [`linearize_driven`] returns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrivenLinearization<const N: usize, const NU: usize> {
    /// The linearization of the driven mechanism (its `dqdd_du` is M⁻¹, for generalized forces
    /// on every coordinate; the declared inputs' are
    /// [`dqdd_dinputs`](DrivenLinearization::dqdd_dinputs)).
    pub linearization: Linearization<N>,
    /// The inputs linearized about, flat.
    pub inputs: [f64; NU],
    /// ∂q̈/∂u: column j for input j.
    pub dqdd_dinputs: SMatrix<f64, N, NU>,
}

impl<const N: usize, const NU: usize> DrivenLinearization<N, NU> {
    /// A, 2N × 2N (see [`Linearization::a_matrix`]).
    pub fn a_matrix(&self) -> DMatrix<f64> {
        self.linearization.a_matrix()
    }

    /// B = [0; ∂q̈/∂u], 2N × NU: rows (q₀ … q_{N−1}, v₀ … v_{N−1}), a column per input.
    pub fn b_matrix(&self) -> DMatrix<f64> {
        let mut b = DMatrix::zeros(2 * N, NU);
        b.view_mut((N, 0), (N, NU))
            .copy_from(&to_dmatrix(&self.dqdd_dinputs));
        b
    }
}

/// Linearizes a mechanism with `#[inputs]` about `state` with the inputs `inputs` held:
/// [`linearize`] of `mechanism.driven(inputs)`, and ∂q̈/∂u for the declared inputs
/// ([`input_matrix`](crate::inputs::input_matrix): q̈ on dual numbers seeded on the inputs,
/// through the constrained solve where the mechanism has constraint rows). Exact.
///
/// Errors: those of [`linearize`] and of [`input_matrix`](crate::inputs::input_matrix). The state
/// is not modified.
///
/// ```
/// use lagrange_core::analysis::linearize_driven;
/// # use lagrange_core::analysis::doc_models::{DrivenPendulum, Pendulum, Torque};
/// use lagrange_core::State;
/// // A pendulum (m = 2, l = 3, g = 9.81) driven by a torque τ at its pivot:
/// // m l² θ̈ = τ − m g l sin θ.
/// let sys = DrivenPendulum(Pendulum { m: 2.0, l: 3.0, g: 9.81 });
/// let lin = linearize_driven(&sys, &State::at_rest([0.0]), &Torque { tau: 1.0 })?;
/// assert!((lin.linearization.accelerations[0] - 1.0 / 18.0).abs() < 1e-15);
/// assert!((lin.dqdd_dinputs[(0, 0)] - 1.0 / 18.0).abs() < 1e-15);
/// // B = [0; 1/(m l²)], beside A = [[0, 1], [−g/l, 0]].
/// assert_eq!(lin.b_matrix().shape(), (2, 1));
/// assert!((lin.b_matrix()[(1, 0)] - 1.0 / 18.0).abs() < 1e-15);
/// assert!((lin.a_matrix()[(1, 0)] + 9.81 / 3.0).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn linearize_driven<E, const N: usize, const NU: usize>(
    mechanism: &E,
    state: &State<E::Coords>,
    inputs: &<E::Model as Actuated<NU>>::Inputs,
) -> Result<DrivenLinearization<N, NU>>
where
    E: Mechanism<N>,
    E::Model: Actuated<NU>,
{
    let linearization = linearize(&mechanism.driven(inputs), state)?;
    let dqdd_dinputs = crate::inputs::input_matrix(mechanism, inputs, state)?;
    Ok(DrivenLinearization {
        linearization,
        inputs: inputs.to_array(),
        dqdd_dinputs,
    })
}
