//! Constraint rows by automatic differentiation, the Schur-complement solve of the KKT system,
//! mode inference, projection onto the constraints and consistency checks.

use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::dynamics;
use crate::error::{describe_configuration, describe_state, Error, Result};
use crate::geometry::Scalar;
use crate::linalg::{cholesky, cholesky_substitute, NotPositiveDefinite};
use crate::model::{Coordinates, State};
use nalgebra::{SMatrix, SVector};
use num_dual::{Derivative, Dual, Dual2, DualSVec, DualVec};

/// Absolute tolerance (in the units of each row: length for g and c, velocity for h and s) under
/// which [`check_consistent`] accepts a state and [`infer_mode`] counts a contact as closed or a
/// slip velocity as zero. States produced by [`project`] are at round-off, far below it.
pub const CONSISTENCY_TOLERANCE: f64 = 1e-8;

/// Solves with sliding friction tried before the signs of the bilateral normal forces are declared
/// inconsistent ([`Error::FrictionIndeterminate`]): two decide one normal row, the rest allow for
/// a flip of a second row.
const SIGN_ATTEMPTS: usize = 4;

/// Iterations of the Newton projection of positions before giving up.
const MAX_PROJECTION_ITERATIONS: usize = 12;

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

/// The accelerations of a constrained mechanism and the multipliers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstrainedAccelerations<S: Scalar, const N: usize, const C: usize> {
    /// q̈.
    pub accelerations: [S; N],
    /// λᵢ: the generalized constraint force of row i is λᵢ·rᵢ. For a friction row, the tangential
    /// force along its slip direction (−μₖ·sign(s)·|λₙ| while sliding, the stick multiplier while
    /// sticking); zero for rows not enforced.
    pub multipliers: [S; C],
}

/// What each constraint does at a state: multipliers, generalized and Cartesian forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstraintForces<const N: usize, const K: usize, const C: usize> {
    /// The mode the forces were computed in ([`infer_mode`]).
    pub mode: Mode<C>,
    /// q̈.
    pub accelerations: [f64; N],
    /// λᵢ (see [`ConstrainedAccelerations::multipliers`]).
    pub multipliers: [f64; C],
    /// λᵢ·rᵢ: the generalized force of each row.
    pub generalized: [[f64; N]; C],
    /// λᵢ·∂fᵢ/∂xₖ (position rows) or λᵢ·∂fᵢ/∂ẋₖ (velocity and friction rows): the force row i applies
    /// to Cartesian coordinate k, with x treated as independent of q. This is the physical force on a
    /// body when the constraint is written on the bodies' Cartesian coordinates (as the declaration
    /// syntax encourages); parts written directly on q appear only in `generalized`.
    pub cartesian: [[f64; K]; C],
}

#[inline(always)]
fn gradient<S: Scalar, const N: usize>(x: &DualSVec<S, N>) -> SVector<S, N> {
    x.eps.0.unwrap_or_else(SVector::zeros)
}

fn has_position<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>() -> bool {
    M::KINDS.iter().any(|k| k.is_position())
}

fn has_velocity<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>() -> bool {
    M::KINDS.iter().any(|k| k.is_velocity())
}

/// Whether every row is always enforced (no unilateral, no friction rows): then no mode logic.
fn always_active<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>() -> bool
{
    M::KINDS
        .iter()
        .all(|k| matches!(k, ConstraintKind::Holonomic | ConstraintKind::Velocity))
}

/// The rows and the Jacobian rows of x (for the mass matrix), at (t, q, q̇).
///
/// Two evaluations of x: (1) q seeded as a gradient dual: x, J and G; (2) (q, t) along (q̇, 1) as
/// a second-order dual: ẋ, the q̈ = 0 accelerations of x, ġ and β of position rows. Velocity rows
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
    rows_on(model, t, q, v, (td, &qd, &x1), (t2, &q2, &x2))
}

/// [`rows_and_jacobian`] of a scleronomic mechanism from the hyper-dual pass of its equations of
/// motion: x as a gradient dual is (re, ε₁) of the pass, and x along the motion is (re, ε₂, a) with
/// a = (∂ẋ/∂q) q̇ from ε₁ε₂ — the same numbers the two evaluations of [`rows_and_jacobian`] would
/// give, without evaluating x(q) again.
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
    let td = DualSVec::from_re(t);
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let x1: [DualSVec<S, N>; K] =
        std::array::from_fn(|i| DualSVec::new(pass.x[i].re, Derivative::new(pass.x[i].eps1.0)));
    let t2 = Dual2::from_re(t);
    let q2: [Dual2<S>; N] = std::array::from_fn(|j| Dual2::new(q[j], v[j], S::zero()));
    let x2: [Dual2<S>; K] = std::array::from_fn(|i| {
        Dual2::new(
            pass.x[i].re,
            pass.x[i].eps2.0.map_or(S::zero(), |d| d[0]),
            dynamics::along_motion(&pass.x[i], v).unwrap_or(S::zero()),
        )
    });
    rows_on(model, t, q, v, (td, &qd, &x1), (t2, &q2, &x2))
}

/// The rows from x as a gradient dual (J, G) and x along the motion (ẋ, a; ġ, β of position
/// rows), then the velocity rows ([`velocity_rows`]).
#[allow(clippy::type_complexity)]
#[inline(always)]
fn rows_on<M: Constraints<N, K, C>, S: Scalar, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    (td, qd, x1): (DualSVec<S, N>, &[DualSVec<S, N>; N], &[DualSVec<S, N>; K]),
    (t2, q2, x2): (Dual2<S>, &[Dual2<S>; N], &[Dual2<S>; K]),
) -> (ConstraintRows<S, N, C>, [SVector<S, N>; K]) {
    let mut out = ConstraintRows {
        rows: [SVector::zeros(); C],
        bias: [S::zero(); C],
        value: [S::zero(); C],
        rate: [S::zero(); C],
    };
    let jac: [SVector<S, N>; K] = std::array::from_fn(|i| gradient(&x1[i]));
    if has_position::<M, N, K, C>() {
        let g1 = model.position_constraints(td, qd, x1);
        let g2 = model.position_constraints(t2, q2, x2);
        for i in 0..C {
            if M::KINDS[i].is_position() {
                out.rows[i] = gradient(&g1[i]);
                out.value[i] = g1[i].re;
                out.rate[i] = g2[i].v1;
                out.bias[i] = g2[i].v2;
            }
        }
    }
    let motion = CartesianMotion {
        x: std::array::from_fn(|i| x2[i].re),
        x_dot: std::array::from_fn(|i| x2[i].v1),
        x_accel: std::array::from_fn(|i| x2[i].v2),
    };
    velocity_rows(model, t, q, v, &motion, &jac, &mut out);
    (out, jac)
}

/// x, ẋ and the q̈ = 0 accelerations of x at one state: what velocity rows are evaluated on.
struct CartesianMotion<S: Scalar, const K: usize> {
    x: [S; K],
    x_dot: [S; K],
    x_accel: [S; K],
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
    motion: &CartesianMotion<S, K>,
    jac: &[SVector<S, N>; K],
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
    let xdv: [DualSVec<S, N>; K] =
        std::array::from_fn(|i| DualVec::new(motion.x_dot[i], Derivative::some(jac[i])));
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
fn position_rows_and_jacobian<
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
    let g1 = model.position_constraints(td, &qd, &x1);
    let mut rows = [SVector::zeros(); C];
    let mut value = [0.0; C];
    for i in 0..C {
        if M::KINDS[i].is_position() {
            rows[i] = gradient(&g1[i]);
            value[i] = g1[i].re;
        }
    }
    (rows, value, jac)
}

/// The rows and their velocity-level values (rates) without the biases β, on f64: for position
/// rows ġ = G q̇ + ∂g/∂t, for velocity rows h itself, with ẋ = J q̇ + ∂x/∂t. One gradient pass
/// (plus one first-order pass in t for a rheonomic mechanism), against the two of
/// [`constraint_rows`]: what the velocity projection needs.
#[allow(clippy::type_complexity)]
fn velocity_rows_and_jacobian<
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
        let gt = if has_position::<M, N, K, C>() {
            let g = model.position_constraints(tt, &qt, &xt);
            std::array::from_fn(|i| g[i].eps)
        } else {
            [0.0; C]
        };
        (std::array::from_fn(|i| xt[i].eps), gt)
    } else {
        ([0.0; K], [0.0; C])
    };
    if has_position::<M, N, K, C>() {
        let g1 = model.position_constraints(td, &qd, &x1);
        for i in 0..C {
            if M::KINDS[i].is_position() {
                rows[i] = gradient(&g1[i]);
                rate[i] = rows[i].dot(&vv) + g_t[i];
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

/// The constraint rows rᵢ, biases βᵢ, values and rates at (t, q, q̇), for any scalar.
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
    rows_and_jacobian(model, t, q, v).0
}

fn real<S: Scalar, const N: usize>(q: &[S; N]) -> [f64; N] {
    std::array::from_fn(|j| q[j].re())
}

/// The error for a singular Schur matrix S = R M⁻¹ Rᵀ whose Cholesky factorisation stopped at row
/// p: row p is (numerically) a combination of earlier rows k, S[p, ·] ≈ Σ cₖ S[k, ·] with
/// S₁₁ c = S[0..p, p]. The rows with a coefficient that matters are named with p.
fn singular_constraints<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    e: NotPositiveDefinite,
    schur: &SMatrix<S, C, C>,
    enforced: &[bool; C],
    t: S,
    q: &[S; N],
) -> Error {
    let p = e.index;
    let s: SMatrix<f64, C, C> = schur.map(|x| x.re());
    // Dense solve of the leading p×p block by Gaussian elimination (p < C, tiny).
    let mut a = s;
    let mut b = SVector::<f64, C>::zeros();
    for k in 0..p {
        b[k] = s[(k, p)];
    }
    let mut c = [0.0f64; C];
    let mut ok = true;
    for col in 0..p {
        let mut piv = col;
        for r in col + 1..p {
            if a[(r, col)].abs() > a[(piv, col)].abs() {
                piv = r;
            }
        }
        if a[(piv, col)] == 0.0 {
            ok = false;
            break;
        }
        a.swap_rows(piv, col);
        b.swap_rows(piv, col);
        for r in col + 1..p {
            let f = a[(r, col)] / a[(col, col)];
            for k in col..p {
                a[(r, k)] -= f * a[(col, k)];
            }
            b[r] -= f * b[col];
        }
    }
    if ok {
        for r in (0..p).rev() {
            let mut acc = b[r];
            for k in r + 1..p {
                acc -= a[(r, k)] * c[k];
            }
            c[r] = acc / a[(r, r)];
        }
    }
    let largest = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut names: Vec<&str> = (0..p)
        .filter(|&k| enforced[k] && ok && c[k].abs() > 1e-6 * largest.max(f64::MIN_POSITIVE))
        .map(|k| M::NAMES[k])
        .collect();
    names.push(M::NAMES[p]);
    Error::SingularConstraints {
        t: t.re(),
        configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, &real(q)),
        constraints: names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
        pivot: e.pivot,
    }
}

/// Solves A x = b (general square, fixed size) by LU with partial pivoting on the real parts;
/// generic over the scalar so it differentiates through dual numbers. `None` for a vanishing pivot.
fn lu_solve_generic<S: Scalar, const C: usize>(
    a: &SMatrix<S, C, C>,
    b: &SVector<S, C>,
) -> Option<SVector<S, C>> {
    let mut a = *a;
    let mut x = *b;
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.re().abs()));
    let tol = crate::linalg::SINGULAR_PIVOT * scale;
    for c in 0..C {
        let mut p = c;
        for r in (c + 1)..C {
            if a[(r, c)].re().abs() > a[(p, c)].re().abs() {
                p = r;
            }
        }
        if !(a[(p, c)].re().abs() > tol) {
            return None;
        }
        if p != c {
            a.swap_rows(p, c);
            x.swap_rows(p, c);
        }
        let inv = a[(c, c)].recip();
        for r in (c + 1)..C {
            let f = a[(r, c)] * inv;
            for k in c..C {
                let v = a[(c, k)];
                a[(r, k)] -= f * v;
            }
            let xc = x[c];
            x[r] -= f * xc;
        }
    }
    for r in (0..C).rev() {
        let mut s = x[r];
        for k in (r + 1)..C {
            s -= a[(r, k)] * x[k];
        }
        x[r] = s / a[(r, r)];
    }
    Some(x)
}

fn slip_sign(mode: RowMode) -> f64 {
    match mode {
        RowMode::SlipPositive => 1.0,
        RowMode::SlipNegative => -1.0,
        _ => 0.0,
    }
}

/// q̈ and λ in a given [`Mode`], for any scalar: the Schur-complement solve of the KKT system (see the
/// [module docs](super)).
///
/// Errors: singular mass matrix, singular R M⁻¹ Rᵀ (naming the rows), indeterminate sliding
/// friction (the friction-coupled Schur matrix is singular: Painlevé's paradox), non-finite results.
pub fn accelerations_in_mode<
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
    mode: &Mode<C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    // A scleronomic mechanism evaluates x(q) once, for M, 𝓕, b and the constraint rows alike.
    let pass = (!M::RHEONOMIC).then(|| dynamics::motion_pass(model, t, q, v));
    let eom = match &pass {
        Some(pass) => dynamics::equations_of_motion_from_pass(model, pass, t, q, v),
        None => dynamics::equations_of_motion(model, t, q, v),
    };
    let l = cholesky(&eom.mass_matrix)
        .map_err(|e| dynamics::singular_mass_matrix::<M::Coords, S, N>(e, t, q))?;
    let u = cholesky_substitute(&l, &(eom.generalized_forces - eom.inertial_terms));
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    // A sliding row acts when its contact is enforced.
    let sliding: [bool; C] = std::array::from_fn(|j| match M::KINDS[j] {
        ConstraintKind::Friction { normal } => slip_sign(mode.rows[j]) != 0.0 && enforced[normal],
        _ => false,
    });
    let mut multipliers = [S::zero(); C];
    if !enforced.iter().any(|&e| e) {
        return finish::<M, S, N, K, C>(u, multipliers, t, q);
    }
    let cr = match &pass {
        Some(pass) => rows_from_pass(model, pass, t, q, v).0,
        None => constraint_rows(model, t, q, v),
    };
    let y: [SVector<S, N>; C] = std::array::from_fn(|i| {
        if enforced[i] || sliding[i] {
            cholesky_substitute(&l, &cr.rows[i])
        } else {
            SVector::zeros()
        }
    });
    let mut schur = SMatrix::<S, C, C>::zeros();
    let mut rhs = SVector::<S, C>::zeros();
    let mut diagonal = 0.0f64;
    for i in 0..C {
        if enforced[i] {
            for k in 0..C {
                if enforced[k] {
                    schur[(i, k)] = cr.rows[i].dot(&y[k]);
                }
            }
            rhs[i] = -cr.bias[i] - cr.rows[i].dot(&u);
            diagonal = diagonal.max(schur[(i, i)].re().abs());
        }
    }
    // Rows not enforced get λ = 0 from an identity row at the scale of the others (so the relative
    // singularity test of the Cholesky factorisation is not distorted).
    let filler = if diagonal > 0.0 { diagonal } else { 1.0 };
    for i in 0..C {
        if !enforced[i] {
            schur[(i, i)] = S::from(filler);
        }
    }
    let ls = cholesky(&schur)
        .map_err(|e| singular_constraints::<M, S, N, K, C>(e, &schur, &enforced, t, q))?;
    let mut lambda = cholesky_substitute(&ls, &rhs);
    if !sliding.iter().any(|&s| s) {
        let mut qdd = u;
        for k in 0..C {
            if enforced[k] {
                qdd += y[k] * lambda[k];
                multipliers[k] = lambda[k];
            }
        }
        return finish::<M, S, N, K, C>(qdd, multipliers, t, q);
    }
    // Sliding friction: the generalized force of normal row n becomes λₙ(rₙ − Σⱼ μₖ σⱼ sₙ Sⱼ), with
    // sₙ = sign(λₙ) (+1 for a unilateral contact, whose λ ≥ 0 while active). The sign of a bilateral
    // normal force is taken from the frictionless solve and re-checked.
    let mut sign_n: [f64; C] = std::array::from_fn(|n| match M::KINDS[n] {
        ConstraintKind::Unilateral => 1.0,
        _ => {
            if lambda[n].re() < 0.0 {
                -1.0
            } else {
                1.0
            }
        }
    });
    let mut columns = [SVector::<S, N>::zeros(); C];
    let indeterminate = || Error::FrictionIndeterminate {
        t: t.re(),
        configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, &real(q)),
        constraints: (0..C)
            .filter(|&j| sliding[j])
            .map(|j| format!("`{}`", M::NAMES[j]))
            .collect::<Vec<_>>()
            .join(", "),
    };
    // Each attempt solves with the current signs and flips those the solution contradicts. With
    // one bilateral normal row two attempts decide: if both signs contradict themselves, no normal
    // force is consistent with sliding friction (Painlevé's inconsistent case). Several normal rows
    // get a few more attempts; signs still inconsistent after them are the same error, never a
    // solution computed with a sign its own normal force contradicts.
    let mut consistent = false;
    for _attempt in 0..SIGN_ATTEMPTS {
        for k in 0..C {
            if enforced[k] {
                columns[k] = y[k];
            }
        }
        for j in 0..C {
            if let (true, ConstraintKind::Friction { normal }) = (sliding[j], M::KINDS[j]) {
                let mu = model.friction_coefficients(j).kinetic;
                columns[normal] -= y[j] * S::from(mu * slip_sign(mode.rows[j]) * sign_n[normal]);
            }
        }
        let mut a = SMatrix::<S, C, C>::zeros();
        for i in 0..C {
            if enforced[i] {
                for k in 0..C {
                    if enforced[k] {
                        a[(i, k)] = cr.rows[i].dot(&columns[k]);
                    }
                }
            } else {
                a[(i, i)] = S::from(filler);
            }
        }
        lambda = lu_solve_generic(&a, &rhs).ok_or_else(indeterminate)?;
        consistent = true;
        for n in 0..C {
            if enforced[n]
                && !matches!(M::KINDS[n], ConstraintKind::Unilateral)
                && lambda[n].re() * sign_n[n] < 0.0
            {
                sign_n[n] = -sign_n[n];
                consistent = false;
            }
        }
        if consistent {
            break;
        }
    }
    if !consistent {
        return Err(indeterminate());
    }
    let mut qdd = u;
    for k in 0..C {
        if enforced[k] {
            qdd += columns[k] * lambda[k];
            multipliers[k] = lambda[k];
        }
    }
    for j in 0..C {
        if let (true, ConstraintKind::Friction { normal }) = (sliding[j], M::KINDS[j]) {
            let mu = model.friction_coefficients(j).kinetic;
            multipliers[j] = lambda[normal] * (-mu * slip_sign(mode.rows[j]) * sign_n[normal]);
        }
    }
    finish::<M, S, N, K, C>(qdd, multipliers, t, q)
}

fn finish<M: Constraints<N, K, C>, S: Scalar, const N: usize, const K: usize, const C: usize>(
    qdd: SVector<S, N>,
    multipliers: [S; C],
    t: S,
    q: &[S; N],
) -> Result<ConstrainedAccelerations<S, N, C>> {
    if qdd
        .iter()
        .chain(multipliers.iter())
        .all(|a| a.re().is_finite())
    {
        Ok(ConstrainedAccelerations {
            accelerations: qdd.into(),
            multipliers,
        })
    } else {
        Err(dynamics::non_finite_dynamics::<M::Coords, S, N>(t, q))
    }
}

/// q̈ at (t, q, q̇) with the mode read from the state ([`infer_mode`]); with only holonomic and
/// velocity rows, every row is enforced and no inference runs. What a constrained mechanism's
/// [`Mechanism::accelerations_at`](crate::Mechanism::accelerations_at) forwards to.
pub fn accelerations<
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
) -> Result<[S; N]> {
    let mode = if always_active::<M, N, K, C>() {
        Mode::all_active::<M, N, K>()
    } else {
        infer_mode(model, t.re(), &real(q), &real(v))?
    };
    Ok(accelerations_in_mode(model, t, q, v, &mode)?.accelerations)
}

/// The mode at a state, by complementarity: a unilateral row with c ≤ tol and ċ ≤ tol is a
/// candidate contact, kept if its λ ≥ 0; a friction row with |s| ≤ tol (tol =
/// [`CONSISTENCY_TOLERANCE`]) on an enforced contact is a candidate stick, kept if
/// |λₜ| ≤ μₛ|λₙ|, otherwise it slides against the force static friction would have had to supply.
/// Candidates are dropped one at a time, the most violated first, until the mode is consistent.
pub fn infer_mode<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<Mode<C>> {
    let mut mode = Mode::all_active::<M, N, K>();
    if always_active::<M, N, K, C>() {
        return Ok(mode);
    }
    let cr = constraint_rows(model, t, q, v);
    let tol = CONSISTENCY_TOLERANCE;
    for i in 0..C {
        if let ConstraintKind::Unilateral = M::KINDS[i] {
            if !(cr.value[i] <= tol && cr.rate[i] <= tol) {
                mode.rows[i] = RowMode::Inactive;
            }
        }
    }
    friction_rows_follow(&M::KINDS, &mut mode, &cr.value);
    for _ in 0..=2 * C {
        if always_active::<M, N, K, C>() {
            break;
        }
        let sol = accelerations_in_mode(model, t, q, v, &mode)?;
        match worst_violation(model, &mode, &sol.multipliers) {
            None => break,
            Some((i, new)) => {
                mode.rows[i] = new;
                if new == RowMode::Inactive {
                    // A separated contact carries no friction.
                    for j in 0..C {
                        if M::KINDS[j] == (ConstraintKind::Friction { normal: i }) {
                            mode.rows[j] = RowMode::Inactive;
                        }
                    }
                }
            }
        }
    }
    Ok(mode)
}

/// Friction rows follow their contact (helper with the model type in scope).
fn friction_rows_follow<const C: usize>(
    kinds: &[ConstraintKind; C],
    mode: &mut Mode<C>,
    slip: &[f64; C],
) {
    for j in 0..C {
        if let ConstraintKind::Friction { normal } = kinds[j] {
            mode.rows[j] = if !mode.enforced(normal) {
                RowMode::Inactive
            } else if slip[j].abs() <= CONSISTENCY_TOLERANCE {
                RowMode::Stick
            } else if slip[j] > 0.0 {
                RowMode::SlipPositive
            } else {
                RowMode::SlipNegative
            };
        }
    }
}

/// The most violated complementarity condition of a solved mode, and the row mode that fixes it:
/// a contact pulling (λ < 0) separates; a stick needing more than μₛ|λₙ| slides against it.
pub(crate) fn worst_violation<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    mode: &Mode<C>,
    lambda: &[f64; C],
) -> Option<(usize, RowMode)> {
    let mut worst: Option<(usize, RowMode, f64)> = None;
    for i in 0..C {
        let (excess, fix) = match (M::KINDS[i], mode.rows[i]) {
            (ConstraintKind::Unilateral, RowMode::Active) => (-lambda[i], RowMode::Inactive),
            (ConstraintKind::Friction { normal }, RowMode::Stick) => {
                let bound = model.friction_coefficients(i).stiction * lambda[normal].abs();
                let fix = if lambda[i] > 0.0 {
                    RowMode::SlipNegative
                } else {
                    RowMode::SlipPositive
                };
                (lambda[i].abs() - bound, fix)
            }
            _ => continue,
        };
        if excess > 0.0 && worst.is_none_or(|w| excess > w.2) {
            worst = Some((i, fix, excess));
        }
    }
    worst.map(|(i, m, _)| (i, m))
}

fn mass_from_jacobian<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    jac: &[SVector<f64, N>; K],
) -> SMatrix<f64, N, N> {
    let masses = model.masses();
    let mut m = SMatrix::<f64, N, N>::zeros();
    for i in 0..M::INERTIAL {
        if masses[i] != 0.0 {
            m += jac[i] * jac[i].transpose() * masses[i];
        }
    }
    m
}

/// Position rows enforced in `mode` and their values at (t, q) (plain f64, no derivatives).
fn position_residual<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    mode: &Mode<C>,
) -> f64 {
    let x = model.cartesian(t, q);
    let g = model.position_constraints(t, q, &x);
    (0..C)
        .filter(|&i| M::KINDS[i].is_position() && mode.enforced(i))
        .fold(0.0f64, |m, i| m.max(g[i].abs()))
}

/// One mass-weighted least-norm correction δ = −M⁻¹Rᵀ(RM⁻¹Rᵀ)⁻¹r over the rows selected by `use_row`,
/// moving only the coordinates marked in `free`: held coordinates are removed from R and M is
/// replaced by its free block (the held rows and columns by the identity), so δ is exactly zero
/// on them and mass-weighted least-norm on the rest.
#[allow(clippy::too_many_arguments)]
fn least_norm_correction<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    jac: &[SVector<f64, N>; K],
    rows: &[SVector<f64, N>; C],
    residual: &[f64; C],
    use_row: &[bool; C],
    free: &[bool; N],
) -> Result<SVector<f64, N>> {
    let mut mass = mass_from_jacobian(model, jac);
    let held_rows: [SVector<f64, N>; C];
    let rows = if free.iter().all(|&f| f) {
        rows
    } else {
        for a in 0..N {
            for b in 0..N {
                if !free[a] || !free[b] {
                    mass[(a, b)] = if a == b { 1.0 } else { 0.0 };
                }
            }
        }
        held_rows = std::array::from_fn(|i| {
            SVector::from_fn(|j, _| if free[j] { rows[i][j] } else { 0.0 })
        });
        &held_rows
    };
    let l = cholesky(&mass)
        .map_err(|e| dynamics::singular_mass_matrix::<M::Coords, f64, N>(e, t, q))?;
    let y: [SVector<f64, N>; C] = std::array::from_fn(|i| {
        if use_row[i] {
            cholesky_substitute(&l, &rows[i])
        } else {
            SVector::zeros()
        }
    });
    let mut schur = SMatrix::<f64, C, C>::zeros();
    let mut rhs = SVector::<f64, C>::zeros();
    let mut diagonal = 0.0f64;
    for i in 0..C {
        if use_row[i] {
            for k in 0..C {
                if use_row[k] {
                    schur[(i, k)] = rows[i].dot(&y[k]);
                }
            }
            rhs[i] = residual[i];
            diagonal = diagonal.max(schur[(i, i)]);
        }
    }
    let filler = if diagonal > 0.0 { diagonal } else { 1.0 };
    for i in 0..C {
        if !use_row[i] {
            schur[(i, i)] = filler;
        }
    }
    let ls = cholesky(&schur)
        .map_err(|e| singular_constraints::<M, f64, N, K, C>(e, &schur, use_row, t, q))?;
    let mu = cholesky_substitute(&ls, &rhs);
    let mut delta = SVector::<f64, N>::zeros();
    for k in 0..C {
        if use_row[k] {
            delta -= y[k] * mu[k];
        }
    }
    Ok(delta)
}

/// Projects (q, q̇) onto the rows enforced in `mode` (see the [module docs](super)): Newton on the
/// position rows with the mass-weighted least-norm step until the residual stops decreasing (round-off),
/// then one exact projection of q̇ onto every enforced row's velocity-level equation.
///
/// Errors: the Newton iteration does not bring the position residual below
/// [`CONSISTENCY_TOLERANCE`] ([`Error::ProjectionFailed`]), singular M or R M⁻¹ Rᵀ. On error `q`
/// and `v` are unchanged.
pub fn project<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
) -> Result<()> {
    project_holding(model, t, q, v, mode, &[true; N], &[true; N])
}

/// [`project`] moving only the coordinates marked in `free_q` and the velocities marked in
/// `free_v`; the others are kept bit for bit.
fn project_holding<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
    free_q: &[bool; N],
    free_v: &[bool; N],
) -> Result<()> {
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    let position_rows: [bool; C] =
        std::array::from_fn(|i| enforced[i] && M::KINDS[i].is_position());
    let mut qn = *q;
    if position_rows.iter().any(|&b| b) {
        let mut residual = position_residual(model, t, &qn, mode);
        let mut iterations = 0;
        while residual > 0.0 {
            if iterations == MAX_PROJECTION_ITERATIONS {
                break;
            }
            iterations += 1;
            let (rows, value, jac) = position_rows_and_jacobian(model, t, &qn);
            let delta =
                least_norm_correction(model, t, &qn, &jac, &rows, &value, &position_rows, free_q)?;
            let trial: [f64; N] = std::array::from_fn(|j| qn[j] + delta[j]);
            let new_residual = position_residual(model, t, &trial, mode);
            if !(new_residual < residual) {
                break; // round-off floor reached: keep the best iterate
            }
            let stalled = new_residual > 0.25 * residual;
            let scale = qn.iter().fold(1.0f64, |m, x| m.max(x.abs()));
            // Newton converges quadratically: after a correction this small the next one would be
            // ≲ |δ|²·(curvature) — below round-off — so it is not computed.
            let converged = delta.amax() <= 1e-8 * scale;
            qn = trial;
            residual = new_residual;
            if converged || (stalled && residual < CONSISTENCY_TOLERANCE * 1e-4) {
                break;
            }
        }
        if !(residual <= CONSISTENCY_TOLERANCE) {
            return Err(Error::ProjectionFailed {
                t,
                iterations,
                residual,
                state: describe_state(&<M::Coords as Coordinates<N>>::NAMES, t, q, v),
            });
        }
    }
    let mut vn = *v;
    if enforced.iter().any(|&b| b) {
        let (rows, rate, jac) = velocity_rows_and_jacobian(model, t, &qn, &vn);
        let delta = least_norm_correction(model, t, &qn, &jac, &rows, &rate, &enforced, free_v)?;
        for j in 0..N {
            vn[j] += delta[j];
        }
    }
    if !qn.iter().chain(vn.iter()).all(|x| x.is_finite()) {
        return Err(Error::NonFiniteState {
            state: describe_state(&<M::Coords as Coordinates<N>>::NAMES, t, &qn, &vn),
        });
    }
    *q = qn;
    *v = vn;
    Ok(())
}

/// Checks a state against the constraints: holonomic |g| and |ġ|, velocity |h|, unilateral c ≥ −tol
/// (and ċ ≥ −tol where c ≤ tol), each within `tol` (use [`CONSISTENCY_TOLERANCE`]); and that every
/// velocity and friction row is affine in q̇: its second derivative along w = q̇ + (1, …, 1),
/// d²/ds² h(q, q̇ + s w), must vanish (exactly zero for affine code; allowed 1e-9 relative).
///
/// Cost: one first-order dual pass over x along (q̇, 1) for the residuals, and for velocity rows one
/// more dual pass for J w and one second-order evaluation of h; cheap enough to run before every
/// step ([`Mechanism::check_constraints`](crate::Mechanism::check_constraints)).
///
/// Errors, in this order: invalid friction coefficients, [`Error::NonlinearVelocityConstraint`]
/// (a property of the declaration, reported whether or not the state satisfies the rows),
/// [`Error::ConstraintViolation`] listing the violated rows and residuals.
pub fn check_consistent<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    tol: f64,
) -> Result<()> {
    model.validate_constraints()?;
    // x, ẋ and ġ from one dual pass along (q̇, 1).
    let td = if M::RHEONOMIC {
        Dual::new(t, 1.0)
    } else {
        Dual::from_re(t)
    };
    let qd: [Dual<f64>; N] = std::array::from_fn(|j| Dual::new(q[j], v[j]));
    let xd = model.cartesian(td, &qd);
    let x: [f64; K] = std::array::from_fn(|i| xd[i].re);
    let x_dot: [f64; K] = std::array::from_fn(|i| xd[i].eps);
    let (mut value, mut rate) = ([0.0; C], [0.0; C]);
    if has_position::<M, N, K, C>() {
        let g = model.position_constraints(td, &qd, &xd);
        for i in 0..C {
            value[i] = g[i].re;
            rate[i] = g[i].eps;
        }
    }
    if has_velocity::<M, N, K, C>() {
        let h = model.velocity_constraints(t, q, v, &x, &x_dot);
        for i in 0..C {
            if M::KINDS[i].is_velocity() {
                value[i] = h[i];
            }
        }
    }
    // The declaration first: a velocity row that is not affine in q̇ is refused whatever the state.
    velocity_rows_affine_at(model, t, q, v, &x, &x_dot)?;
    let mut violated = Vec::new();
    for i in 0..C {
        let r = match M::KINDS[i] {
            ConstraintKind::Holonomic => value[i].abs().max(rate[i].abs()),
            ConstraintKind::Velocity => value[i].abs(),
            ConstraintKind::Unilateral => {
                let pen = (-value[i]).max(0.0);
                if value[i] <= tol {
                    pen.max((-rate[i]).max(0.0))
                } else {
                    pen
                }
            }
            ConstraintKind::Friction { .. } => 0.0,
        };
        if !(r <= tol) {
            violated.push((i, r));
        }
    }
    if !violated.is_empty() {
        let residual = violated.iter().fold(0.0f64, |m, x| m.max(x.1));
        return Err(Error::ConstraintViolation {
            t,
            residual,
            residuals: violated
                .iter()
                .map(|(i, r)| format!("`{}` off by {r:e}", M::NAMES[*i]))
                .collect::<Vec<_>>()
                .join(", "),
        });
    }
    Ok(())
}

/// Checks that every velocity row is affine in q̇ at (t, q, q̇) — what the declaration promises and
/// the solve relies on — as every entry point does, whatever the state's consistency. A mechanism
/// without velocity rows has nothing to check.
///
/// Errors: [`Error::NonlinearVelocityConstraint`], naming the row and its quadratic part.
pub fn check_velocity_rows_affine<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    if !has_velocity::<M, N, K, C>() {
        return Ok(());
    }
    let (x, x_dot) = dynamics::cartesian_velocities(model, t, q, v);
    velocity_rows_affine_at(model, t, q, v, &x, &x_dot)
}

/// [`check_velocity_rows_affine`] with x and ẋ at the state already evaluated.
fn velocity_rows_affine_at<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    x: &[f64; K],
    x_dot: &[f64; K],
) -> Result<()> {
    if !has_velocity::<M, N, K, C>() {
        return Ok(());
    }
    // Affine in q̇ ⇔ zero second derivative along any direction w; ẋ(q̇ + s w) = ẋ + s J w.
    let w: [f64; N] = std::array::from_fn(|j| v[j] + 1.0);
    let qw: [Dual<f64>; N] = std::array::from_fn(|j| Dual::new(q[j], w[j]));
    let jw = model.cartesian(Dual::from_re(t), &qw);
    let t2 = Dual2::from_re(t);
    let q2: [Dual2<f64>; N] = std::array::from_fn(|j| Dual2::from_re(q[j]));
    let v2: [Dual2<f64>; N] = std::array::from_fn(|j| Dual2::new(v[j], w[j], 0.0));
    let x2: [Dual2<f64>; K] = std::array::from_fn(|i| Dual2::from_re(x[i]));
    let xd2: [Dual2<f64>; K] = std::array::from_fn(|i| Dual2::new(x_dot[i], jw[i].eps, 0.0));
    let h = model.velocity_constraints(t2, &q2, &v2, &x2, &xd2);
    for i in 0..C {
        if !M::KINDS[i].is_velocity() {
            continue;
        }
        // The quadratic term at s = 1 against the size of the affine part there.
        let deviation = 0.5 * h[i].v2.abs();
        let size = h[i].re.abs() + h[i].v1.abs();
        if !(deviation <= 1e-9 * size) && deviation > 0.0 || !deviation.is_finite() {
            return Err(Error::NonlinearVelocityConstraint {
                constraint: M::NAMES[i],
                t,
                configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, q),
                deviation,
            });
        }
    }
    Ok(())
}

/// A state consistent with the constraints, from a guess: holonomic rows and unilateral rows with
/// c ≤ [`CONSISTENCY_TOLERANCE`] (touching or penetrating) are projected to g = 0, then velocities
/// onto every enforced row (friction rows whose slip is within tolerance are set to stick). The
/// result passes [`check_consistent`].
///
/// Errors: the projection fails ([`Error::ProjectionFailed`], with the residual), or the result still
/// violates the constraints ([`Error::ConstraintViolation`]).
pub fn consistent_state<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    guess: &State<M::Coords>,
) -> Result<State<M::Coords>> {
    consistent_state_holding(model, guess, &[], &[])
}

/// [`consistent_state`] that keeps the named coordinates and velocities exactly as in the guess
/// and solves the constraints for the others: start a four-bar or a slider-crank at a crank angle
/// of exactly 0.3 and crank rate exactly 2, and let the loop closure place the rest.
///
/// `hold_q` names coordinates whose values are kept, `hold_v` coordinates whose velocities are
/// kept (by the names of [`Coordinates::NAMES`]: `"phi"`, or `"theta[2]"` for an array
/// coordinate). Positions are projected with the held coordinates fixed, the mass-weighted
/// least-norm correction spread over the free ones; velocities likewise.
///
/// Errors, besides those of [`consistent_state`]: [`Error::UnknownCoordinate`] for a name that is
/// not a coordinate; [`Error::TooFewFreeCoordinates`] when fewer coordinates (velocities) are left
/// free than there are position (velocity-level) rows to satisfy. Holding a set that the
/// constraints cannot be solved around — a crank held at an angle the loop cannot close at, or
/// every free coordinate absent from a row — is [`Error::SingularConstraints`] or
/// [`Error::ProjectionFailed`], as for an impossible guess.
///
/// ```
/// use lagrange_core::analysis::doc_models::CartesianPendulum;
/// use lagrange_core::constraints::consistent_state_holding;
/// use lagrange_core::State;
///
/// // The bob on a rod of length 1: hold x = 0.6, solve for y (from a guess below the pivot).
/// let p = CartesianPendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let guess = State::new(0.0, [0.6, -0.5], [1.6, 0.0]);
/// let s = consistent_state_holding(&p, &guess, &["q0"], &["q0"])?;
/// assert_eq!(s.q[0], 0.6);
/// assert!((s.q[1] + 0.8).abs() < 1e-14);
/// // The rod is rigid: ẋ x + ẏ y = 0 with ẋ held at 1.6 gives ẏ = 1.2.
/// assert_eq!(s.v[0], 1.6);
/// assert!((s.v[1] - 1.2).abs() < 1e-14);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn consistent_state_holding<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    guess: &State<M::Coords>,
    hold_q: &[&str],
    hold_v: &[&str],
) -> Result<State<M::Coords>> {
    model.validate()?;
    let free_q = free_mask::<N>(&<M::Coords as Coordinates<N>>::NAMES, hold_q)?;
    let free_v = free_mask::<N>(&<M::Coords as Coordinates<N>>::NAMES, hold_v)?;
    let (mut q, mut v) = (guess.q.to_array(), guess.v.to_array());
    crate::model::check_state(&<M::Coords as Coordinates<N>>::NAMES, guess.t, &q, &v)?;
    // The declaration is checked before projecting (friction coefficients, velocity rows linear
    // in q̇); the guess itself may violate the rows.
    match check_consistent(model, guess.t, &q, &v, CONSISTENCY_TOLERANCE) {
        Ok(()) | Err(Error::ConstraintViolation { .. }) => {}
        Err(e) => return Err(e),
    }
    let cr = constraint_rows(model, guess.t, &q, &v);
    let mut mode = Mode::all_active::<M, N, K>();
    for i in 0..C {
        if let ConstraintKind::Unilateral = M::KINDS[i] {
            if cr.value[i] > CONSISTENCY_TOLERANCE {
                mode.rows[i] = RowMode::Inactive;
            }
        }
    }
    friction_rows_follow(&M::KINDS, &mut mode, &cr.value);
    let position_rows = (0..C)
        .filter(|&i| mode.enforced(i) && M::KINDS[i].is_position())
        .count();
    let velocity_rows = (0..C).filter(|&i| mode.enforced(i)).count();
    enough_free("coordinates", hold_q, &free_q, position_rows)?;
    enough_free("velocities", hold_v, &free_v, velocity_rows)?;
    project_holding(model, guess.t, &mut q, &mut v, &mode, &free_q, &free_v)?;
    check_consistent(model, guess.t, &q, &v, CONSISTENCY_TOLERANCE)?;
    Ok(State::new(
        guess.t,
        M::Coords::from_array(q),
        M::Coords::from_array(v),
    ))
}

/// Which coordinates are free: all but the named ones; a name that is not a coordinate is
/// [`Error::UnknownCoordinate`].
fn free_mask<const N: usize>(names: &[&'static str; N], held: &[&str]) -> Result<[bool; N]> {
    let mut free = [true; N];
    for name in held {
        match names.iter().position(|n| n == name) {
            Some(j) => free[j] = false,
            None => {
                return Err(Error::UnknownCoordinate {
                    name: (*name).to_string(),
                    known: names
                        .iter()
                        .map(|n| format!("`{n}`"))
                        .collect::<Vec<_>>()
                        .join(", "),
                })
            }
        }
    }
    Ok(free)
}

/// [`Error::TooFewFreeCoordinates`] unless at least `rows` entries of `free` are set.
fn enough_free<const N: usize>(
    what: &'static str,
    held: &[&str],
    free: &[bool; N],
    rows: usize,
) -> Result<()> {
    let n_free = free.iter().filter(|&&f| f).count();
    if n_free >= rows {
        return Ok(());
    }
    Err(Error::TooFewFreeCoordinates {
        what,
        held: held
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
        free: n_free,
        rows,
        max: N - rows,
    })
}

/// Multipliers, generalized and Cartesian forces of every constraint at a state (mode by
/// [`infer_mode`]).
pub fn constraint_forces<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    state: &State<M::Coords>,
) -> Result<ConstraintForces<N, K, C>> {
    model.validate()?;
    let (q, v) = (state.q.to_array(), state.v.to_array());
    crate::model::check_state(&<M::Coords as Coordinates<N>>::NAMES, state.t, &q, &v)?;
    let t = state.t;
    // Refuse what the integrators refuse about the declaration (friction coefficients, velocity
    // rows not linear in q̇), but compute forces at states off the constraints too.
    match check_consistent(model, t, &q, &v, CONSISTENCY_TOLERANCE) {
        Ok(()) | Err(Error::ConstraintViolation { .. }) => {}
        Err(e) => return Err(e),
    }
    let mode = infer_mode(model, t, &q, &v)?;
    forces_in_mode(model, t, &q, &v, &mode)
}

/// [`constraint_forces`] in a given mode.
pub(crate) fn forces_in_mode<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    mode: &Mode<C>,
) -> Result<ConstraintForces<N, K, C>> {
    let sol = accelerations_in_mode(model, t, q, v, mode)?;
    let cr = constraint_rows(model, t, q, v);
    let generalized: [[f64; N]; C] =
        std::array::from_fn(|i| std::array::from_fn(|j| sol.multipliers[i] * cr.rows[i][j]));
    // ∂f/∂x (position rows) and ∂f/∂ẋ (velocity rows), x and ẋ seeded as independent gradient duals.
    let (x, x_dot) = dynamics::cartesian_velocities(model, t, q, v);
    let mut cartesian = [[0.0; K]; C];
    let qs: [DualSVec<f64, K>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let ts = DualSVec::<f64, K>::from_re(t);
    if has_position::<M, N, K, C>() {
        let xs: [DualSVec<f64, K>; K] =
            std::array::from_fn(|i| DualSVec::from_re(x[i]).derivative(i));
        let g = model.position_constraints(ts, &qs, &xs);
        for i in 0..C {
            if M::KINDS[i].is_position() {
                let d = gradient(&g[i]);
                cartesian[i] = std::array::from_fn(|k| sol.multipliers[i] * d[k]);
            }
        }
    }
    if has_velocity::<M, N, K, C>() {
        let vk: [DualSVec<f64, K>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
        let xs: [DualSVec<f64, K>; K] = std::array::from_fn(|i| DualSVec::from_re(x[i]));
        let xds: [DualSVec<f64, K>; K] =
            std::array::from_fn(|i| DualSVec::from_re(x_dot[i]).derivative(i));
        let h = model.velocity_constraints(ts, &qs, &vk, &xs, &xds);
        for i in 0..C {
            if M::KINDS[i].is_velocity() {
                let d = gradient(&h[i]);
                cartesian[i] = std::array::from_fn(|k| sol.multipliers[i] * d[k]);
            }
        }
    }
    // A row without force (not enforced, or λ = 0 exactly) applies none, even where its gradient is
    // not finite (a separated contact at an overflowing or degenerate configuration): 0, not 0·NaN.
    let mut generalized = generalized;
    for i in 0..C {
        if sol.multipliers[i] == 0.0 {
            generalized[i] = [0.0; N];
            cartesian[i] = [0.0; K];
        }
    }
    if !generalized
        .iter()
        .flatten()
        .chain(cartesian.iter().flatten())
        .all(|x| x.is_finite())
    {
        return Err(dynamics::non_finite_dynamics::<M::Coords, f64, N>(t, q));
    }
    Ok(ConstraintForces {
        mode: *mode,
        accelerations: sol.accelerations,
        multipliers: sol.multipliers,
        generalized,
        cartesian,
    })
}
