//! The constraint rows and the Jacobians of x by automatic differentiation: [`ConstraintRows`],
//! [`constraint_rows`] and the passes the solve and the projection build on.

use super::kinds::{has_position_on_duals, has_velocity, has_written_derivatives, on_duals};
use super::{quasi, ConstraintKind, Constraints};
use crate::dynamics;
use crate::geometry::Scalar;
use nalgebra::SVector;
use num_dual::{Derivative, Dual, Dual2, DualSVec, DualVec, HyperDualVec};

/// The constraint rows at one state (see the [module docs](super) for the notation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstraintRows<S: Scalar, const N: usize, const C: usize> {
    /// rᵢ: ∂g/∂q for position rows, ∂h/∂q̇ for velocity and friction rows.
    pub rows: [SVector<S, N>; C],
    /// βᵢ: rᵢ·q̈ + βᵢ is the second time derivative of g (position rows) or the first of h (velocity rows).
    pub bias: [S; C],
    /// The declared function's value: g or c (position rows), h or s (velocity rows).
    pub value: [S; C],
    /// Its velocity-level value rᵢ·q̇ + ∂/∂t: ġ (position rows), h or s itself (velocity rows).
    pub rate: [S; C],
}

impl<S: Scalar, const N: usize, const C: usize> ConstraintRows<S, N, C> {
    pub(super) fn zero() -> Self {
        Self {
            rows: [SVector::zeros(); C],
            bias: [S::zero(); C],
            value: [S::zero(); C],
            rate: [S::zero(); C],
        }
    }
}

#[inline(always)]
pub(super) fn gradient<S: Scalar, const N: usize>(x: &DualSVec<S, N>) -> SVector<S, N> {
    x.eps.0.unwrap_or_else(SVector::zeros)
}

/// The rows and the Jacobian rows of x (for the mass matrix), at (t, q, q̇).
///
/// Two evaluations of x and g: (1) q seeded as a gradient dual: x, J and G; (2) (q, t) along
/// (q̇, 1) as a second-order dual: ẋ, the q̈ = 0 accelerations of x, ġ and β of position rows. Velocity rows
/// then take two first-order passes of their own ([`velocity_rows`]). Where the hyper-dual pass of
/// the equations of motion is at hand, [`rows_from_pass`] builds the same duals from it instead.
#[allow(clippy::type_complexity)]
fn rows_and_jacobian<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> (ConstraintRows<S, N, C>, [SVector<S, N>; K]) {
    let td = DualSVec::from_re(t);
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let x1 = model.cartesian(td, &qd);
    let t2 = if M::RHEONOMIC {
        Dual2::new(t, S::one(), S::zero())
    } else {
        Dual2::from_re(t)
    };
    let q2: [Dual2<S>; N] = std::array::from_fn(|j| Dual2::new(q[j], v[j], S::zero()));
    let x2 = model.cartesian(t2, &q2);
    let mut out = ConstraintRows::zero();
    let motion = CartesianMotion {
        x: std::array::from_fn(|i| x2[i].re),
        x_dot: std::array::from_fn(|i| x2[i].v1),
        x_accel: std::array::from_fn(|i| x2[i].v2),
        jacobian: std::array::from_fn(|i| gradient(&x1[i])),
    };
    if has_position_on_duals::<M, N, K, C>() {
        let g1 = model.position_constraints(td, &qd, &x1);
        let g2 = model.position_constraints(t2, &q2, &x2);
        for i in 0..C {
            if on_duals::<M, N, K, C>(i) {
                out.rows[i] = gradient(&g1[i]);
                out.value[i] = g1[i].re;
                out.rate[i] = g2[i].v1;
                out.bias[i] = g2[i].v2;
            }
        }
    }
    if has_written_derivatives::<M, N, K, C>() {
        model.position_constraint_derivatives(t, q, v, &motion, &mut out);
    }
    velocity_rows(model, t, q, v, &motion, &mut out);
    (out, motion.jacobian)
}

/// [`rows_and_jacobian`] of a scleronomic mechanism from the hyper-dual pass of its equations of
/// motion. The position rows are evaluated once, on the pass's own seeds and its x: g's ε₁ part is
/// G, its ε₂ part ġ = G q̇, and β = (∂ġ/∂q) q̇ from its ε₁ε₂ part, as for x itself — so G, ġ and β
/// come from one evaluation of g, and x(q) (with the rotations of its bodies) is not evaluated
/// again. Rows whose derivatives the model writes out ([`Constraints::POSITION_DERIVATIVES`]) take
/// them instead, from x, ẋ, a and J read off the same pass; velocity rows take those too.
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(crate) fn rows_from_pass<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    pass: &dynamics::MotionPass<S, N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> (ConstraintRows<S, N, C>, [SVector<S, N>; K]) {
    let mut out = ConstraintRows::zero();
    let jac: [SVector<S, N>; K] =
        std::array::from_fn(|i| pass.x[i].eps1.0.unwrap_or_else(SVector::zeros));
    if has_position_on_duals::<M, N, K, C>() {
        let seeds = dynamics::motion_seeds(q, v);
        let g = model.position_constraints(HyperDualVec::from_re(t), &seeds, &pass.x);
        for i in 0..C {
            if on_duals::<M, N, K, C>(i) {
                out.rows[i] = g[i].eps1.0.unwrap_or_else(SVector::zeros);
                out.value[i] = g[i].re;
                out.rate[i] = g[i].eps2.0.map_or(S::zero(), |d| d[0]);
                out.bias[i] = dynamics::along_motion(&g[i], v, &[true; N]).unwrap_or(S::zero());
            }
        }
    }
    if has_velocity::<M, N, K, C>() || has_written_derivatives::<M, N, K, C>() {
        let motion = CartesianMotion {
            x: std::array::from_fn(|i| pass.x[i].re),
            x_dot: std::array::from_fn(|i| pass.x[i].eps2.0.map_or(S::zero(), |d| d[0])),
            x_accel: std::array::from_fn(|i| {
                dynamics::along_motion(&pass.x[i], v, &M::DEPENDS[i]).unwrap_or(S::zero())
            }),
            jacobian: jac,
        };
        if has_written_derivatives::<M, N, K, C>() {
            model.position_constraint_derivatives(t, q, v, &motion, &mut out);
        }
        velocity_rows(model, t, q, v, &motion, &mut out);
    }
    (out, jac)
}

/// x(q, t) along the motion at one state, at q̈ = 0: what position rows written on bodies are
/// differentiated through ([`Constraints::position_constraint_derivatives`]) and velocity rows are
/// evaluated on.
///
/// ```
/// use lagrange_core::constraints::CartesianMotion;
/// use nalgebra::SVector;
/// // A bob at angle θ on an arm of length 2, x = (2 sin θ, −2 cos θ), swinging at θ̇ = 1.5:
/// // ẋ = J θ̇, and at θ̈ = 0 its acceleration is centripetal, −θ̇² x.
/// let (theta, rate) = (0.3f64, 1.5);
/// let (s, c) = theta.sin_cos();
/// let jacobian = [SVector::from([2.0 * c]), SVector::from([2.0 * s])];
/// let motion = CartesianMotion {
///     x: [2.0 * s, -2.0 * c],
///     x_dot: [jacobian[0][0] * rate, jacobian[1][0] * rate],
///     x_accel: [-rate * rate * 2.0 * s, rate * rate * 2.0 * c],
///     jacobian,
/// };
/// let radial = motion.x[0] * motion.x_accel[0] + motion.x[1] * motion.x_accel[1];
/// assert!((radial + rate * rate * 4.0).abs() < 1e-12); // x·a = −θ̇² |x|²
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CartesianMotion<S: Scalar, const N: usize, const K: usize> {
    /// x.
    pub x: [S; K],
    /// ẋ = J q̇ + ∂x/∂t.
    pub x_dot: [S; K],
    /// d²/ds² x(q + s q̇, t + s)│₀: the accelerations of x at q̈ = 0.
    pub x_accel: [S; K],
    /// J's rows, ∂xᵢ/∂q.
    pub jacobian: [SVector<S, N>; K],
}

/// The velocity rows h(q, q̇, t) into `out`: (3) along the motion as a first-order dual (value and
/// β), with x and ẋ advanced along it by ẋ and the q̈ = 0 accelerations; (4) with q̇ seeded as a
/// gradient dual (A), ẋ's gradient in q̇ being J.
fn velocity_rows<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    motion: &CartesianMotion<S, N, K>,
    out: &mut ConstraintRows<S, N, C>,
) {
    if !has_velocity::<M, N, K, C>() {
        return;
    }
    // Pass 3: h(q + s q̇, q̇, t + s): value and β.
    let tq = if M::RHEONOMIC {
        Dual::new(t, S::one())
    } else {
        Dual::from_re(t)
    };
    let qq: [Dual<S>; N] = std::array::from_fn(|j| Dual::new(q[j], v[j]));
    let vq: [Dual<S>; N] = std::array::from_fn(|j| Dual::from_re(v[j]));
    let xq: [Dual<S>; K] = std::array::from_fn(|i| Dual::new(motion.x[i], motion.x_dot[i]));
    let xdq: [Dual<S>; K] = std::array::from_fn(|i| Dual::new(motion.x_dot[i], motion.x_accel[i]));
    let h = model.velocity_constraints(tq, &qq, &vq, &xq, &xdq);
    // Pass 4: A = ∂h/∂q̇, with ∂ẋ/∂q̇ = J.
    let tv = DualSVec::from_re(t);
    let qv: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let vv: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]).derivative(j));
    let xv: [DualSVec<S, N>; K] = std::array::from_fn(|i| DualSVec::from_re(motion.x[i]));
    let xdv: [DualSVec<S, N>; K] = std::array::from_fn(|i| {
        DualVec::new(motion.x_dot[i], Derivative::some(motion.jacobian[i]))
    });
    let hv = model.velocity_constraints(tv, &qv, &vv, &xv, &xdv);
    for i in 0..C {
        if M::KINDS[i].is_velocity() {
            out.value[i] = h[i].re;
            out.rate[i] = h[i].re;
            out.bias[i] = h[i].eps;
            out.rows[i] = gradient(&hv[i]);
        }
    }
}

/// Pass 1 alone, on f64: position rows G, their values g and the Jacobian rows of x.
#[allow(clippy::type_complexity)]
pub(super) fn position_rows_and_jacobian<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
) -> ([SVector<f64, N>; C], [f64; C], [SVector<f64, N>; K]) {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let td = DualSVec::from_re(t);
    let x1 = model.cartesian(td, &qd);
    let jac: [SVector<f64, N>; K] = std::array::from_fn(|i| gradient(&x1[i]));
    let mut out = ConstraintRows::zero();
    if has_position_on_duals::<M, N, K, C>() {
        let g1 = model.position_constraints(td, &qd, &x1);
        for i in 0..C {
            if on_duals::<M, N, K, C>(i) {
                out.rows[i] = gradient(&g1[i]);
                out.value[i] = g1[i].re;
            }
        }
    }
    if has_written_derivatives::<M, N, K, C>() {
        // At rest: only G and g are read.
        let motion = CartesianMotion {
            x: std::array::from_fn(|i| x1[i].re),
            x_dot: [0.0; K],
            x_accel: [0.0; K],
            jacobian: jac,
        };
        model.position_constraint_derivatives(t, q, &[0.0; N], &motion, &mut out);
    }
    (out.rows, out.value, jac)
}

/// The rows and their velocity-level values (rates) without the biases β, on f64: for position
/// rows ġ = G q̇ + ∂g/∂t, for velocity rows h itself, with ẋ = J q̇ + ∂x/∂t. One gradient pass
/// (plus one first-order pass in t for a rheonomic mechanism), against the two of
/// [`constraint_rows`]: what the velocity projection needs.
#[allow(clippy::type_complexity)]
pub(super) fn velocity_rows_and_jacobian<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> ([SVector<f64, N>; C], [f64; C], [SVector<f64, N>; K]) {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let td = DualSVec::from_re(t);
    let x1 = model.cartesian(td, &qd);
    let jac: [SVector<f64, N>; K] = std::array::from_fn(|i| gradient(&x1[i]));
    let vv = SVector::from(*v);
    let mut rows = [SVector::zeros(); C];
    let mut rate = [0.0; C];
    // ∂x/∂t and ∂g/∂t at fixed q.
    let (x_t, g_t) = if M::RHEONOMIC {
        let tt = Dual::new(t, 1.0);
        let qt: [Dual<f64>; N] = std::array::from_fn(|j| Dual::from_re(q[j]));
        let xt = model.cartesian(tt, &qt);
        let gt = if has_position_on_duals::<M, N, K, C>() {
            let g = model.position_constraints(tt, &qt, &xt);
            std::array::from_fn(|i| g[i].eps)
        } else {
            [0.0; C]
        };
        (std::array::from_fn(|i| xt[i].eps), gt)
    } else {
        ([0.0; K], [0.0; C])
    };
    if has_position_on_duals::<M, N, K, C>() {
        let g1 = model.position_constraints(td, &qd, &x1);
        for i in 0..C {
            if on_duals::<M, N, K, C>(i) {
                rows[i] = gradient(&g1[i]);
                rate[i] = rows[i].dot(&vv) + g_t[i];
            }
        }
    }
    if has_written_derivatives::<M, N, K, C>() {
        // ġ from ẋ = J q̇ + ∂x/∂t; the biases, from a = 0, are not read.
        let motion = CartesianMotion {
            x: std::array::from_fn(|i| x1[i].re),
            x_dot: std::array::from_fn(|i| jac[i].dot(&vv) + x_t[i]),
            x_accel: [0.0; K],
            jacobian: jac,
        };
        let mut out = ConstraintRows::zero();
        model.position_constraint_derivatives(t, q, v, &motion, &mut out);
        for i in 0..C {
            if M::POSITION_DERIVATIVES[i] {
                rows[i] = out.rows[i];
                rate[i] = out.rate[i];
            }
        }
    }
    if has_velocity::<M, N, K, C>() {
        let tv = DualSVec::from_re(t);
        let qv: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
        let vs: [DualSVec<f64, N>; N] =
            std::array::from_fn(|j| DualSVec::from_re(v[j]).derivative(j));
        let xv: [DualSVec<f64, N>; K] = std::array::from_fn(|i| DualSVec::from_re(x1[i].re));
        let xdv: [DualSVec<f64, N>; K] = std::array::from_fn(|i| {
            DualVec::new(jac[i].dot(&vv) + x_t[i], Derivative::some(jac[i]))
        });
        let h = model.velocity_constraints(tv, &qv, &vs, &xv, &xdv);
        for i in 0..C {
            if M::KINDS[i].is_velocity() {
                rows[i] = gradient(&h[i]);
                rate[i] = h[i].re;
            }
        }
    }
    (rows, rate, jac)
}

/// The constraint rows rᵢ, biases βᵢ, values and rates at (t, q, v), for any scalar. With
/// quasi-velocities ([`Constraints::QUASI_VELOCITY_JOINTS`], q̇ = G v) the rows and biases are
/// those of the velocities: from rᵢ·q̈ + βᵢ with q̈ = G (v̇ − Ḃ q̇), the row Gᵀ rᵢ and the bias
/// βᵢ − (Gᵀ rᵢ)·(Ḃ q̇); values and rates are the same.
pub fn constraint_rows<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> ConstraintRows<S, N, C> {
    let rates = quasi::rates::<M, S, N, K, C>(q, v);
    let mut rows = constraint_rows_in_rates(model, t, q, &rates);
    if quasi::quasi::<M, N, K, C>() {
        let bias = SVector::from(quasi::velocity_bias::<M, S, N, K, C>(q, &rates));
        for i in 0..C {
            let row = quasi::forces::<M, S, N, K, C>(q, &rows.rows[i].into());
            rows.rows[i] = SVector::from(row);
            rows.bias[i] -= rows.rows[i].dot(&bias);
        }
    }
    rows
}

/// [`constraint_rows`] at (q, q̇), the coordinates' rates.
pub(crate) fn constraint_rows_in_rates<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> ConstraintRows<S, N, C> {
    rows_and_jacobian(model, t, q, v).0
}

/// [`constraint_rows`] at a real state with the sizes its residuals are measured against (see
/// [`RowScales`](super::consistency::RowScales)), from the same pass: the mass matrix's diagonal
/// from the Cartesian Jacobian that pass computes.
pub(crate) fn rows_and_scales<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> (ConstraintRows<f64, N, C>, super::consistency::RowScales<C>) {
    let (cr, jac) = rows_and_jacobian(model, t, q, v);
    let scales = super::consistency::RowScales::new(&cr, &mass_diagonal(model, &jac), q, v);
    (cr, scales)
}

/// Mⱼⱼ = Σₖ μₖ (∂xₖ/∂qⱼ)², the mass matrix's diagonal from the Cartesian Jacobian (the inertial
/// components only).
pub(super) fn mass_diagonal<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    jac: &[SVector<f64, N>; K],
) -> [f64; N] {
    let masses = model.masses();
    std::array::from_fn(|j| {
        (0..M::INERTIAL).fold(0.0, |m, k| m + masses[k] * jac[k][j] * jac[k][j])
    })
}

pub(super) fn real<S: Scalar, const N: usize>(q: &[S; N]) -> [f64; N] {
    std::array::from_fn(|j| q[j].re())
}

/// The holonomic rows' values g(q, t) at (t, q), for any scalar, in declaration order (other kinds
/// of row skipped) and padded with zeros to N entries: what
/// `Dynamics::holonomic_constraints_at` forwards to,
/// so integrators generic over `Mechanism<N>` (which cannot name C) can differentiate them.
/// Independent holonomic rows number at most N; rows beyond the N-th are not returned (the
/// integrators refuse such a declaration from
/// `Dynamics::CONSTRAINT_COUNTS` before calling this).
///
/// ```
/// use lagrange_core::constraints::{holonomic_values, ConstraintKind, Constraints};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Bead;
/// # impl Model<2, 2> for Bead {
/// #     type Coords = [f64; 2];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = false;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D { D::zero() }
/// # }
/// // A bead on the unit circle, with a velocity row declared first: only the circle is returned.
/// impl Constraints<2, 2, 2> for Bead {
///     const NAMES: [&'static str; 2] = ["drive", "circle"];
///     const KINDS: [ConstraintKind; 2] = [ConstraintKind::Velocity, ConstraintKind::Holonomic];
///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 2] {
///         [D::zero(), vec2(x[0], x[1]).norm() - D::from(1.0)]
///     }
/// }
/// assert_eq!(holonomic_values(&Bead, 0.0, &[3.0, 4.0]), [4.0, 0.0]);
/// ```
pub fn holonomic_values<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
) -> [S; N] {
    let mut out = [S::zero(); N];
    if !M::KINDS
        .iter()
        .any(|k| matches!(k, ConstraintKind::Holonomic))
    {
        return out;
    }
    let x = model.cartesian(t, q);
    let g = model.position_constraints(t, q, &x);
    let mut slot = 0;
    for i in 0..C {
        if matches!(M::KINDS[i], ConstraintKind::Holonomic) && slot < N {
            out[slot] = g[i];
            slot += 1;
        }
    }
    out
}
