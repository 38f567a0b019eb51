//! Holonomic rows of a mechanism whose positions are affine in the coordinates, with the constants
//! a validated handle prepared ([`crate::affine`]): the KKT solve with the Schur complement in
//! closed form ([`regular_accelerations_prepared`], and the checked path of
//! [`accelerations_prepared`](super::accelerations_prepared)) and the projection after a step
//! ([`project_prepared`]), where every row is holonomic with derivatives `#[mechanism]` wrote out
//! ([`Constraints::POSITION_DERIVATIVES`]) and the mechanism is scleronomic.
//!
//! With x = A q + c (A and c constant), J = A, ẋ = A q̇ and x's accelerations at q̈ = 0 vanish, so
//! the rows G, ġ and β at a state are the written straight-line code on (x, A q̇, 0, A): no dual
//! numbers. M is constant and factorised once, and b = 0. With u = M⁻¹𝓕,
//!
//! ```text
//! S = G M⁻¹ Gᵀ (C×C),   S λ = −β − G u,   q̈ = u + M⁻¹ Gᵀ λ,
//! ```
//!
//! the Schur complement of the KKT system (Hairer & Wanner, *Solving Ordinary Differential
//! Equations II*, 2nd ed., §VII.1, eq. (1.46); see the [module docs](super)), S solved in closed
//! form for one or two rows ([`solve_spd_flagged`]). The projection is the same mass-weighted
//! least-norm Newton correction as [`project`](super::project), with M⁻¹ by the prepared factors
//! and G, g and ġ from one evaluation of the rows per iterate: the rows at the accepted iterate
//! give the velocity projection its G and ġ.

use super::kinds::{always_active, written_holonomic};
use super::mode::infer_mode_in_rates;
use super::projection::{
    newton_onto_positions, project_in_rates, projection_failed, relative_residual,
};
use super::rows::{real, CartesianMotion, ConstraintRows};
use super::solve::ConstrainedAccelerations;
use super::solve::{accelerations_in_mode_prepared, finish, singular_constraints};
#[cfg(doc)]
use super::{infer_mode, project};
use super::{Constraints, Mode};
use crate::affine::{self, AffineConstants};
use crate::error::{describe_state, Error, Result};
use crate::geometry::Scalar;
use crate::linalg::{solve_spd, solve_spd_flagged, NotPositiveDefinite};
use crate::model::{lane_sum, state_and_accelerations_finite, Coordinates};
use nalgebra::{SMatrix, SVector};

/// The rows at (t, q, q̇) from x = A q + c: x by the declaration's own positions, ẋ = A q̇ (over the
/// coordinates each row of x depends on), accelerations 0, J = A.
#[inline(always)]
fn affine_rows<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> ConstraintRows<S, N, C> {
    let a = constants.jacobian();
    let jacobian: [SVector<S, N>; K] = std::array::from_fn(|i| a[i].map(S::from));
    let mut x_dot = [S::zero(); K];
    for i in 0..K {
        for j in 0..N {
            if M::DEPENDS[i][j] {
                x_dot[i] += jacobian[i][j] * v[j];
            }
        }
    }
    let motion = CartesianMotion {
        x: model.cartesian(t, q),
        x_dot,
        x_accel: [S::zero(); K],
        jacobian,
    };
    let mut rows = ConstraintRows::zero();
    model.position_constraint_derivatives(t, q, v, &motion, &mut rows);
    rows
}

/// M⁻¹Gᵢᵀ for each row i by the prepared factors, and S = G M⁻¹ Gᵀ (formed symmetric).
#[inline(always)]
fn schur_complement<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    constants: &AffineConstants<N, K>,
    rows: &[SVector<S, N>; C],
) -> ([SVector<S, N>; C], SMatrix<S, C, C>) {
    let mut y = [SVector::<S, N>::zeros(); C];
    for i in 0..C {
        y[i] = constants.solve_mass::<M, S>(&rows[i]);
    }
    let mut schur = SMatrix::<S, C, C>::zeros();
    for i in 0..C {
        for k in 0..=i {
            let s = rows[i].dot(&y[k]);
            schur[(i, k)] = s;
            schur[(k, i)] = s;
        }
    }
    (y, schur)
}

/// q̈ and λ from u = M⁻¹𝓕 and the rows (see the [module docs](self)), with S and whether its
/// pivots passed (q̈ and λ are meaningless when they did not).
#[inline(always)]
#[allow(clippy::type_complexity)]
fn schur_solution<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    constants: &AffineConstants<N, K>,
    u: SVector<S, N>,
    rows: &ConstraintRows<S, N, C>,
) -> (SVector<S, N>, SVector<S, C>, SMatrix<S, C, C>, bool) {
    let (y, schur) = schur_complement::<M, S, N, K, C>(constants, &rows.rows);
    let rhs = SVector::<S, C>::from_fn(|i, _| -rows.bias[i] - rows.rows[i].dot(&u));
    let (lambda, regular) = solve_spd_flagged(&schur, &rhs);
    let mut qdd = u;
    for k in 0..C {
        qdd += y[k] * lambda[k];
    }
    (qdd, lambda, schur, regular)
}

/// q̈ of a constrained mechanism with affine positions (x = A q + c) whose rows are all holonomic
/// and written out ([`Constraints::POSITION_DERIVATIVES`]; then G, ġ and β are that code on x,
/// A q̇ and A, with no dual numbers), from the prepared constants: u = M⁻¹𝓕, S = G M⁻¹ Gᵀ,
/// S λ = −β − G u, q̈ = u + M⁻¹Gᵀλ (the Schur complement of the KKT system, Hairer & Wanner,
/// *Solving Ordinary Differential Equations II*, 2nd ed., §VII.1, eq. (1.46)), with every check of
/// a call in one branch: `Some(q̈)` when t, q, q̇ and q̈ are finite and S = G M⁻¹ Gᵀ passes its pivot tests,
/// `None` otherwise (and for any other declaration) — the caller then takes the checked path,
/// which names the failure. λ is not tested: each λₖ enters q̈ through M⁻¹Gₖᵀλₖ, every entry of
/// which is non-finite with λₖ (0·∞ is NaN), so q̈ finite implies λ finite.
///
/// For a declaration whose q̈ from the prepared constants is straight-line arithmetic that runs no
/// user code, as for [`affine::regular_accelerations`]: `#[mechanism]` uses it when no force is
/// declared and every potential's gradient and every constraint's derivatives are derived on
/// expression trees.
///
/// ```
/// use lagrange_core::affine::AffineConstants;
/// use lagrange_core::constraints::{
///     self, CartesianMotion, ConstraintKind, ConstraintRows, Constraints,
/// };
/// use lagrange_core::{vec2, Model, Scalar};
/// use nalgebra::SVector;
///
/// /// A pendulum in Cartesian coordinates (unit mass, g = 9.81) on a rod of length 2, its
/// /// derivatives written as `#[mechanism]` writes them: G = r̂, ġ = r̂·q̇, β = (|q̇|² − ġ²)/|r|.
/// struct Pendulum;
/// impl Model<2, 2> for Pendulum {
///     type Coords = [f64; 2];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = false;
///     const HAS_FORCES: bool = false;
///     const HAS_GRAVITY: bool = true;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn weights(&self) -> [f64; 2] { [0.0, -9.81] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D { D::zero() }
/// }
/// impl Constraints<2, 2, 1> for Pendulum {
///     const NAMES: [&'static str; 1] = ["rod"];
///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
///     const POSITION_DERIVATIVES: [bool; 1] = [true];
///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
///         [vec2(x[0], x[1]).norm() - 2.0]
///     }
///     fn position_constraint_derivatives<S: Scalar>(
///         &self, _t: S, _q: &[S; 2], _v: &[S; 2],
///         m: &CartesianMotion<S, 2, 2>, rows: &mut ConstraintRows<S, 2, 1>,
///     ) {
///         let r = (m.x[0] * m.x[0] + m.x[1] * m.x[1]).sqrt();
///         let n = [m.x[0] / r, m.x[1] / r];
///         let rate = n[0] * m.x_dot[0] + n[1] * m.x_dot[1];
///         rows.value[0] = r - S::from(2.0);
///         rows.rows[0] = SVector::from([n[0], n[1]]);
///         rows.rate[0] = rate;
///         rows.bias[0] = (m.x_dot[0] * m.x_dot[0] + m.x_dot[1] * m.x_dot[1] - rate * rate) / r;
///     }
/// }
///
/// let constants = AffineConstants::of(&Pendulum)?;
/// let (q, v) = ([1.2, -1.6], [0.8, 0.6]);
/// let regular = constraints::regular_accelerations_prepared(&Pendulum, &constants, 0.0, &q, &v);
/// let direct = constraints::accelerations(&Pendulum, 0.0, &q, &v)?;
/// let regular = regular.expect("a finite state with an independent row");
/// assert!((regular[0] - direct[0]).abs() < 1e-14 && (regular[1] - direct[1]).abs() < 1e-14);
/// // A state that is not finite, or the rod's singular configuration r = 0, fails the one branch.
/// let nan = [f64::NAN, 0.6];
/// assert!(constraints::regular_accelerations_prepared(&Pendulum, &constants, 0.0, &q, &nan).is_none());
/// let at_pivot = constraints::regular_accelerations_prepared(&Pendulum, &constants, 0.0, &[0.0; 2], &v);
/// assert!(at_pivot.is_none());
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[inline(always)]
pub fn regular_accelerations_prepared<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Option<[f64; N]> {
    if !written_holonomic::<M, N, K, C>() {
        return None;
    }
    let u = affine::free_accelerations(model, constants, t, q, v);
    let rows = affine_rows(model, constants, t, q, v);
    let (qdd, _, _, regular) = schur_solution::<M, f64, N, K, C>(constants, u, &rows);
    let qdd: [f64; N] = qdd.into();
    // `&`, not `&&`: one branch for both.
    (regular & state_and_accelerations_finite(t, q, v, &qdd)).then_some(qdd)
}

/// The checked path of [`regular_accelerations_prepared`], for any scalar: q̈ and λ, or the error
/// that names what failed — a singular S (the rows dependent at this configuration, named), or
/// non-finite q̈.
#[inline(always)]
pub(super) fn holonomic_accelerations_prepared<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let u = affine::free_accelerations(model, constants, t, q, v);
    let rows = affine_rows(model, constants, t, q, v);
    let (qdd, lambda, schur, regular) = schur_solution::<M, S, N, K, C>(constants, u, &rows);
    // One branch for S's pivots and q̈'s finiteness (which implies λ's, see
    // `regular_accelerations_prepared`); the failure is named off the common path.
    if regular & (lane_sum::<N>(|j| qdd[j].re()) * 0.0 == 0.0) {
        return Ok(ConstrainedAccelerations {
            accelerations: qdd.into(),
            multipliers: lambda.into(),
        });
    }
    if !regular {
        return Err(schur_failure::<M, S, N, K, C>(&schur, t, q));
    }
    finish::<M, S, N, K, C>(qdd, lambda.into(), t, q, true)
}

/// Why S's pivots failed: the rows, named, that are dependent at this configuration — or whose
/// directions are undefined there (a NaN pivot: a distance's gradient at zero distance), as the
/// general solve names them.
#[cold]
#[inline(never)]
fn schur_failure<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    schur: &SMatrix<S, C, C>,
    t: S,
    q: &[S; N],
) -> Error {
    let e = solve_spd(schur, &SVector::zeros())
        .err()
        .unwrap_or(NotPositiveDefinite {
            index: 0,
            pivot: f64::NAN,
        });
    singular_constraints::<M, S, N, K, C>(e, schur, &[true; C], t, q)
}

/// The mass-weighted least-norm correction δ = −M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹r by the prepared factors.
fn least_norm_correction<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    constants: &AffineConstants<N, K>,
    rows: &[SVector<f64, N>; C],
    residual: &[f64; C],
    t: f64,
    q: &[f64; N],
) -> Result<SVector<f64, N>> {
    let (y, schur) = schur_complement::<M, f64, N, K, C>(constants, rows);
    let mu = solve_spd(&schur, &SVector::from(*residual))
        .map_err(|e| singular_constraints::<M, f64, N, K, C>(e, &schur, &[true; C], t, q))?;
    let mut delta = SVector::<f64, N>::zeros();
    for k in 0..C {
        delta -= y[k] * mu[k];
    }
    Ok(delta)
}

/// [`project`] of a mechanism with affine positions, with the constants a validated handle
/// prepared: where every row is holonomic and written out (as for
/// [`regular_accelerations_prepared`]), the same
/// Newton iteration and velocity projection with M⁻¹ by the prepared factors and one evaluation of
/// the rows per iterate; for any other declaration, [`project`] in the [`infer_mode`]d mode. What
/// a constrained affine mechanism's validated handle projects with.
///
/// Errors as [`project`]; on error `q` and `v` are unchanged.
///
/// ```
/// use lagrange_core::affine::AffineConstants;
/// use lagrange_core::constraints::{
///     self, CartesianMotion, ConstraintKind, ConstraintRows, Constraints, Mode,
/// };
/// use lagrange_core::{vec2, Model, Scalar};
/// use nalgebra::SVector;
///
/// /// A bead on the unit circle, in Cartesian coordinates, its row's derivatives written out:
/// /// G = r̂, ġ = r̂·q̇, β = (|q̇|² − ġ²)/|r|.
/// struct Bead;
/// impl Model<2, 2> for Bead {
///     type Coords = [f64; 2];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = false;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D { D::zero() }
/// }
/// impl Constraints<2, 2, 1> for Bead {
///     const NAMES: [&'static str; 1] = ["circle"];
///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
///     const POSITION_DERIVATIVES: [bool; 1] = [true];
///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
///         [vec2(x[0], x[1]).norm() - 1.0]
///     }
///     fn position_constraint_derivatives<S: Scalar>(
///         &self, _t: S, _q: &[S; 2], _v: &[S; 2],
///         m: &CartesianMotion<S, 2, 2>, rows: &mut ConstraintRows<S, 2, 1>,
///     ) {
///         let r = (m.x[0] * m.x[0] + m.x[1] * m.x[1]).sqrt();
///         let n = [m.x[0] / r, m.x[1] / r];
///         let rate = n[0] * m.x_dot[0] + n[1] * m.x_dot[1];
///         rows.value[0] = r - S::one();
///         rows.rows[0] = SVector::from([n[0], n[1]]);
///         rows.rate[0] = rate;
///         rows.bias[0] = (m.x_dot[0] * m.x_dot[0] + m.x_dot[1] * m.x_dot[1] - rate * rate) / r;
///     }
/// }
///
/// let constants = AffineConstants::of(&Bead)?;
/// let (mut q, mut v) = ([0.6, 0.801], [-0.8, 0.7]);
/// let (mut q_general, mut v_general) = (q, v);
/// constraints::project_prepared(&Bead, &constants, 0.0, &mut q, &mut v)?;
/// assert!(((q[0] * q[0] + q[1] * q[1]).sqrt() - 1.0).abs() < 1e-15);
/// assert!((q[0] * v[0] + q[1] * v[1]).abs() < 1e-15); // ġ = r̂·q̇ = 0
/// // The general projection's iterates, with M factorised at each: the same to round-off.
/// let mode = Mode::all_active::<Bead, 2, 2>();
/// constraints::project(&Bead, 0.0, &mut q_general, &mut v_general, &mode)?;
/// assert!((q[0] - q_general[0]).abs() < 1e-15 && (v[1] - v_general[1]).abs() < 1e-15);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn project_prepared<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
) -> Result<()> {
    if !written_holonomic::<M, N, K, C>() {
        let mode = infer_mode_in_rates(model, t, q, v)?;
        return project_in_rates(model, t, q, v, &mode);
    }
    // Each row's residual against its size at the start (see CONSISTENCY_TOLERANCE).
    let start: ConstraintRows<f64, N, C> = affine_rows(model, constants, t, q, v);
    let weights = super::consistency::mass_weights(&constants.mass_diagonal(&model.masses()));
    let sizes = super::consistency::row_sizes(&start.rows, &weights, q);
    let rows_at = |q: &[f64; N]| {
        let rows: ConstraintRows<f64, N, C> = affine_rows(model, constants, t, q, v);
        (relative_residual(&rows.value, &sizes, |_| true), rows)
    };
    let at_start = (relative_residual(&start.value, &sizes, |_| true), start);
    let (qn, rows, residual, iterations) =
        newton_onto_positions(*q, at_start, &weights, rows_at, |q, rows| {
            least_norm_correction::<M, N, K, C>(constants, &rows.rows, &rows.value, t, q)
        })?;
    if let Some(e) = projection_failed::<M::Coords, N>(t, q, v, iterations, residual) {
        return Err(e);
    }
    // q̇ onto G q̇ = 0 at the projected q: ġ is the rate the last evaluation gave.
    let delta = least_norm_correction::<M, N, K, C>(constants, &rows.rows, &rows.rate, t, &qn)?;
    let vn: [f64; N] = std::array::from_fn(|j| v[j] + delta[j]);
    if !qn.iter().chain(vn.iter()).all(|x| x.is_finite()) {
        return Err(Error::NonFiniteState {
            state: describe_state(&<M::Coords as Coordinates<N>>::NAMES, t, &qn, &vn),
        });
    }
    *q = qn;
    *v = vn;
    Ok(())
}

/// [`accelerations`](super::accelerations) of a mechanism whose positions are affine in the coordinates (x = A q + c,
/// see [`crate::affine`]), with the constants prepared once from its parameters: what a
/// constrained affine mechanism's validated handle evaluates. Agrees with [`accelerations`](super::accelerations) to
/// round-off.
///
/// ```
/// use lagrange_core::affine::AffineConstants;
/// use lagrange_core::constraints::{self, ConstraintKind, Constraints};
/// use lagrange_core::{vec2, Model, Scalar};
///
/// /// A pendulum in Cartesian coordinates: x = q, affine; the rod |x| = 2 a constraint.
/// struct Pendulum;
/// impl Model<2, 2> for Pendulum {
///     type Coords = [f64; 2];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = false;
///     const HAS_FORCES: bool = false;
///     const HAS_GRAVITY: bool = true;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.5, 1.5] }
///     fn weights(&self) -> [f64; 2] { [0.0, -1.5 * 9.81] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D { D::zero() }
/// }
/// impl Constraints<2, 2, 1> for Pendulum {
///     const NAMES: [&'static str; 1] = ["rod"];
///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
///         [vec2(x[0], x[1]).norm() - 2.0]
///     }
/// }
///
/// let constants = AffineConstants::of(&Pendulum)?;
/// let (q, v) = ([1.2, -1.6], [0.8, 0.6]);
/// let prepared = constraints::accelerations_prepared(&Pendulum, &constants, 0.0, &q, &v)?;
/// let direct = constraints::accelerations(&Pendulum, 0.0, &q, &v)?;
/// assert!((prepared[0] - direct[0]).abs() < 1e-14 && (prepared[1] - direct[1]).abs() < 1e-14);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[inline]
pub fn accelerations_prepared<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    // Holonomic rows written out: the Schur complement from the prepared constants alone.
    if written_holonomic::<M, N, K, C>() {
        return holonomic_accelerations_prepared(model, constants, t, q, v)
            .map(|a| a.accelerations);
    }
    let mode = if always_active::<M, N, K, C>() {
        Mode::all_active::<M, N, K>()
    } else {
        infer_mode_in_rates(model, t.re(), &real(q), &real(v))?
    };
    accelerations_in_mode_prepared(model, constants, t, q, v, &mode).map(|a| a.accelerations)
}
