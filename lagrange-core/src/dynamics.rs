//! The equations of motion of a [`Model`], by automatic differentiation.
//!
//! With Cartesian coordinates x(q, t), masses μ and Jacobian J = ∂x/∂q (see [`crate::model`]),
//! Lagrange's equations d/dt(∂T/∂q̇ₖ) − ∂T/∂qₖ = 𝓕ₖ become (Goldstein, Poole & Safko,
//! *Classical Mechanics*, 3rd ed., §1.4; Cross, Caltech Ph106 Lecture 4, the "golden rule")
//!
//! ```text
//! M(q,t) q̈ = 𝓕 − b,    M = Jᵀ diag(μ) J,    b = Jᵀ diag(μ) a,    a = d²/ds² x(q + s q̇, t + s)|₀,
//! 𝓕 = Jᵀ F − ∇V + Q    (virtual work of Cartesian forces F, potential V, direct generalized forces Q).
//! ```
//!
//! `a` is the acceleration x would have with q̈ = 0: every velocity-product (Coriolis, centripetal)
//! and time term at once. Two passes of dual numbers give everything:
//! 1. q seeded as a gradient dual (`DualSVec<S, N>`): x and its Jacobian rows, V and ∇V;
//! 2. (q, t) seeded along (q̇, 1) as a second-order dual (`Dual2<S>`): x, ẋ and a.
//!
//! All functions are generic over the outer scalar `S`, so the accelerations themselves can be
//! differentiated (implicit integrators, linearization) by calling them with dual numbers.

use crate::error::Result;
use crate::geometry::Scalar;
use crate::linalg::{solve_spd, solve_spd_flagged};
use crate::model::{state_and_accelerations_finite, Coordinates, Model};
use nalgebra::{Const, U1};
use nalgebra::{SMatrix, SVector};
use num_dual::{Derivative, Dual2, DualSVec, HyperDualVec};

mod energy;
mod failures;

pub use energy::{
    canonical_field, cartesian_velocities, kinetic_energy, lagrangian_time_derivative, momenta,
    potential_energy,
};
pub(crate) use failures::{
    finite_accelerations, mass_matrix_failure, non_finite_dynamics, singular_mass_matrix,
};

/// A hyper-dual number with an N-wide first part and a scalar second part.
pub(crate) type HyperDualSVec<S, const N: usize, const M: usize> =
    HyperDualVec<S, Const<N>, Const<M>>;

/// The terms of M q̈ = 𝓕 − b at one state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EquationsOfMotion<S: Scalar, const N: usize> {
    /// M(q, t), symmetric positive (semi)definite.
    pub mass_matrix: SMatrix<S, N, N>,
    /// 𝓕: generalized forces from potentials, applied forces and direct generalized forces.
    pub generalized_forces: SVector<S, N>,
    /// b: the inertial terms at q̈ = 0 (velocity products and explicit time dependence).
    pub inertial_terms: SVector<S, N>,
}

impl<S: Scalar, const N: usize> EquationsOfMotion<S, N> {
    /// The terms from arrays: M by columns (`mass_matrix[j]` is column j), 𝓕 and b. What the
    /// closed-form equations `#[mechanism]` derives are returned as.
    ///
    /// ```
    /// use lagrange_core::dynamics::EquationsOfMotion;
    /// let eom = EquationsOfMotion::from_columns([[2.0, 1.0], [1.0, 3.0]], [1.0, 0.0], [0.0, 0.5]);
    /// assert_eq!(eom.mass_matrix[(0, 1)], 1.0);
    /// assert_eq!(eom.inertial_terms[1], 0.5);
    /// ```
    #[inline(always)]
    pub fn from_columns(
        mass_matrix: [[S; N]; N],
        generalized_forces: [S; N],
        inertial_terms: [S; N],
    ) -> Self {
        EquationsOfMotion {
            mass_matrix: SMatrix::from(mass_matrix),
            generalized_forces: SVector::from(generalized_forces),
            inertial_terms: SVector::from(inertial_terms),
        }
    }
}

/// Pass 1: x(q, t) seeded as a gradient over q. Returns the values and Jacobian rows.
#[inline(always)]
pub(crate) fn cartesian_with_jacobian<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
) -> ([DualSVec<S, N>; K], [DualSVec<S, N>; N], DualSVec<S, N>) {
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let td = DualSVec::from_re(t);
    (model.cartesian(td, &qd), qd, td)
}

#[inline(always)]
pub(crate) fn gradient<S: Scalar, const N: usize>(x: &DualSVec<S, N>) -> SVector<S, N> {
    x.eps.0.unwrap_or_else(SVector::zeros)
}

/// Pass 2: x along (q̇, 1): values, ẋ and the q̈ = 0 accelerations `a`.
#[inline(always)]
fn cartesian_along_motion<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> [Dual2<S>; K] {
    let q2: [Dual2<S>; N] = std::array::from_fn(|j| Dual2::new(q[j], v[j], S::zero()));
    // A scleronomic mechanism never reads t: seeding it would be wasted work.
    let t2 = if M::RHEONOMIC {
        Dual2::new(t, S::one(), S::zero())
    } else {
        Dual2::from_re(t)
    };
    model.cartesian(t2, &q2)
}

/// M(q, t) = Σᵢ μᵢ Jᵢᵀ Jᵢ over the rows that carry mass and depend on q, by rank-one updates of
/// the lower triangle, mirrored at the end. Only the entries [`Model::DEPENDS`] allows are
/// formed: a row that depends on two of N coordinates costs three products, not N(N + 1)/2.
#[inline(always)]
pub(crate) fn assemble_mass_matrix<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    masses: &[f64; K],
    rows: &[Option<SVector<S, N>>; K],
) -> SMatrix<S, N, N> {
    let mut mass_matrix = SMatrix::<S, N, N>::zeros();
    // Written for the compiler, measured with scripts/callgrind: over the constant range 0..K (not
    // 0..INERTIAL), from a zero matrix, LLVM unrolls this loop for small mechanisms, where otherwise
    // a pendulum's rows stay in memory and are looped over; `DEPENDS` is then known at every entry.
    for i in 0..K {
        if i >= M::INERTIAL {
            break;
        }
        let depends = &M::DEPENDS[i];
        if let Some(row) = &rows[i] {
            let mass = S::from(masses[i]);
            for c in 0..N {
                if !depends[c] {
                    continue;
                }
                let weighted = row[c] * mass;
                for r in c..N {
                    if depends[r] {
                        mass_matrix[(r, c)] += row[r] * weighted;
                    }
                }
            }
        }
    }
    for c in 0..N {
        for r in (c + 1)..N {
            mass_matrix[(c, r)] = mass_matrix[(r, c)];
        }
    }
    mass_matrix
}

/// M, 𝓕 and b at (t, q, q̇).
///
/// A scleronomic mechanism (x independent of t) needs one pass: q seeded as a hyper-dual number
/// with ε₁ = eⱼ (gradient) and ε₂ = q̇ⱼ (direction of motion) gives x, J (ε₁), ẋ (ε₂) and
/// ∂ẋ/∂q (ε₁ε₂), so a = (∂ẋ/∂q) q̇ — every trigonometric function of the positions is evaluated
/// once. A rheonomic one needs ∂ẋ/∂t too, which this pass does not carry; it takes the two passes
/// described in the module docs.
///
/// Sums run over the terms that exist: a row of x that does not depend on q (the wedge's height)
/// has no Jacobian row, a row that is linear in q (a slider) has no `a`, and num-dual records both
/// as absent derivatives, known when this function is compiled for a mechanism — so they cost
/// nothing rather than additions of zeros.
#[inline]
pub fn equations_of_motion<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    let kinematics = if M::RHEONOMIC {
        two_passes(model, t, q, v)
    } else {
        kinematics_of_pass(model, &motion_pass(model, t, q, v), t, q, v)
    };
    assemble(model, &kinematics, t, q, v)
}

/// [`equations_of_motion`] of a scleronomic mechanism from a [`MotionPass`] already made, so a
/// caller that also evaluates constraints on the same seeds (the constrained solve) pays for one
/// evaluation of x(q).
#[inline]
pub(crate) fn equations_of_motion_from_pass<
    M: Model<N, K>,
    S: Scalar,
    const N: usize,
    const K: usize,
>(
    model: &M,
    pass: &MotionPass<S, N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    assemble(model, &kinematics_of_pass(model, pass, t, q, v), t, q, v)
}

/// M, 𝓕 and b from the kinematics of either pass.
#[inline(always)]
fn assemble<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    kinematics: &Kinematics<S, N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    let masses = model.masses();
    let rows = &kinematics.rows;

    let mass_matrix = assemble_mass_matrix::<M, S, N, K>(&masses, rows);
    // b = Σᵢ μᵢ aᵢ Jᵢᵀ.
    let mut inertial_terms: Option<SVector<S, N>> = None;
    for i in 0..M::INERTIAL {
        if let (Some(row), Some(a)) = (&rows[i], kinematics.accelerations[i]) {
            add_row::<M, S, N, K>(&mut inertial_terms, i, row, a * masses[i]);
        }
    }

    let mut generalized_forces = kinematics.potential_forces;
    // A uniform field, by virtual work: 𝓕 += Jᵀ w.
    if M::HAS_GRAVITY {
        let weights = model.weights();
        for i in 0..K {
            if let Some(row) = &rows[i] {
                add_row::<M, S, N, K>(&mut generalized_forces, i, row, S::from(weights[i]));
            }
        }
    }

    // Applied forces, by virtual work: 𝓕 += Jᵀ F + Q.
    if M::HAS_FORCES {
        let mut cartesian_force = [S::zero(); K];
        let mut direct = [S::zero(); N];
        model.applied_forces(
            t,
            q,
            v,
            &kinematics.x,
            &kinematics.x_dot,
            &mut cartesian_force,
            &mut direct,
        );
        for i in 0..K {
            if let Some(row) = &rows[i] {
                if cartesian_force[i] != 0.0 {
                    add_row::<M, S, N, K>(&mut generalized_forces, i, row, cartesian_force[i]);
                }
            }
        }
        accumulate(&mut generalized_forces, SVector::from(direct));
    }
    EquationsOfMotion {
        mass_matrix,
        generalized_forces: generalized_forces.unwrap_or_else(SVector::zeros),
        inertial_terms: inertial_terms.unwrap_or_else(SVector::zeros),
    }
}

/// `sum += s·row` for row i of x: the whole row, or, where [`Model::DEPENDS`] rules entries out,
/// only the others.
#[inline(always)]
pub(crate) fn add_row<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    sum: &mut Option<SVector<S, N>>,
    i: usize,
    row: &SVector<S, N>,
    s: S,
) {
    let depends = &M::DEPENDS[i];
    if depends.iter().all(|&d| d) {
        accumulate(sum, row * s);
    } else {
        let sum = sum.get_or_insert_with(SVector::zeros);
        for j in 0..N {
            if depends[j] {
                sum[j] += row[j] * s;
            }
        }
    }
}

/// `sum += term`, where an absent sum is an exact zero (so the first term is not added to zeros).
#[inline(always)]
pub(crate) fn accumulate<S: Scalar, const N: usize>(
    sum: &mut Option<SVector<S, N>>,
    term: SVector<S, N>,
) {
    match sum {
        Some(s) => *s += term,
        None => *sum = Some(term),
    }
}

/// What the passes produce, row by row of x: the Jacobian row (`None` where the row does not
/// depend on q), the value, the velocity, the acceleration at q̈ = 0 (`None` where it vanishes
/// identically); and −∇V (`None` without a potential).
struct Kinematics<S: Scalar, const N: usize, const K: usize> {
    rows: [Option<SVector<S, N>>; K],
    x: [S; K],
    x_dot: [S; K],
    accelerations: [Option<S>; K],
    potential_forces: Option<SVector<S, N>>,
}

/// One evaluation of x(q) for a scleronomic mechanism, on hyper-dual numbers: q seeded with
/// ε₁ = eⱼ (gradient) and ε₂ = q̇ⱼ (direction of motion), so each row carries xᵢ, its Jacobian row
/// (ε₁), ẋᵢ (ε₂) and ∂ẋᵢ/∂q (ε₁ε₂, see [`along_motion`]). The equations of motion and, in the
/// constrained solve, the constraint rows are read off the same pass.
pub(crate) struct MotionPass<S: Scalar, const N: usize, const K: usize> {
    /// x(q) on the seeds.
    pub x: [HyperDualSVec<S, N, 1>; K],
}

/// d²/ds² f(q + s q̇)|₀ = (∂ḟ/∂q) q̇ of a value f computed on the seeds of a [`MotionPass`]
/// (`None` when f is at most linear in q: the mixed part was never formed), summed over the
/// coordinates f may depend on (`depends`, e.g. a row of [`Model::DEPENDS`]).
#[inline(always)]
pub(crate) fn along_motion<S: Scalar, const N: usize>(
    f: &HyperDualSVec<S, N, 1>,
    v: &[S; N],
    depends: &[bool; N],
) -> Option<S> {
    f.eps1eps2.0.map(|h| {
        let mut a = S::zero();
        for j in 0..N {
            if depends[j] {
                a += h[j] * v[j];
            }
        }
        a
    })
}

/// The hyper-dual pass of a scleronomic mechanism (see [`equations_of_motion`]).
#[inline(always)]
pub(crate) fn motion_pass<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> MotionPass<S, N, K> {
    MotionPass {
        x: model.cartesian(HyperDualSVec::from_re(t), &motion_seeds(q, v)),
    }
}

/// The seeds of a [`MotionPass`]: qⱼ with ε₁ = eⱼ (gradient) and ε₂ = q̇ⱼ (direction of motion).
#[inline(always)]
pub(crate) fn motion_seeds<S: Scalar, const N: usize>(
    q: &[S; N],
    v: &[S; N],
) -> [HyperDualSVec<S, N, 1>; N] {
    std::array::from_fn(|j| {
        HyperDualSVec::new(
            q[j],
            Derivative::derivative_generic(Const::<N>, U1, j),
            Derivative::some(SMatrix::<S, 1, 1>::new(v[j])),
            Derivative::none(),
        )
    })
}

/// J, x, ẋ, a = (∂ẋ/∂q) q̇ and −∇V from a [`MotionPass`].
#[inline(always)]
fn kinematics_of_pass<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    pass: &MotionPass<S, N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Kinematics<S, N, K> {
    let xh = &pass.x;
    let rows: [Option<SVector<S, N>>; K] = std::array::from_fn(|i| xh[i].eps1.0);
    let x = std::array::from_fn(|i| xh[i].re);
    let x_dot = std::array::from_fn(|i| xh[i].eps2.0.map_or(S::zero(), |d| d[0]));
    let accelerations = std::array::from_fn(|i| along_motion(&xh[i], v, &M::DEPENDS[i]));
    let potential_forces = potential_forces(model, t, q, &x, &rows);
    Kinematics {
        rows,
        x,
        x_dot,
        accelerations,
        potential_forces,
    }
}

/// −∇V at (t, q) from the positions x and their Jacobian rows, already known (see
/// [`potential_gradient`]). `None` without a potential.
#[inline(always)]
pub(crate) fn potential_forces<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    x: &[S; K],
    rows: &[Option<SVector<S, N>>; K],
) -> Option<SVector<S, N>> {
    potential_gradient(model, t, q, x, rows).map(|gradient| -gradient)
}

/// ∇V at (t, q) from the positions x and their Jacobian rows, already known: the model's own
/// ([`Model::potential_gradient`]) when it writes one, otherwise V evaluated on gradient duals
/// rebuilt from x and J (q seeded, xᵢ carrying its row), so x(q) is not evaluated again and
/// ∇V = ∂V/∂q + Jᵀ ∂V/∂x by the chain rule. `None` without a potential.
#[inline(always)]
pub(crate) fn potential_gradient<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    x: &[S; K],
    rows: &[Option<SVector<S, N>>; K],
) -> Option<SVector<S, N>> {
    if !M::HAS_POTENTIAL {
        return None;
    }
    if let Some(gradient) = model.potential_gradient(t, q, x, rows) {
        return Some(gradient);
    }
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let xd: [DualSVec<S, N>; K] =
        std::array::from_fn(|i| DualSVec::new(x[i], Derivative::new(rows[i])));
    Some(gradient(&model.potential(DualSVec::from_re(t), &qd, &xd)))
}

/// Rheonomic: a gradient pass for J and ∇V, a second-order pass along (q̇, 1) for ẋ and a.
#[inline(always)]
fn two_passes<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Kinematics<S, N, K> {
    let (x1, qd, td) = cartesian_with_jacobian(model, t, q);
    let potential_forces = if M::HAS_POTENTIAL {
        Some(-gradient(&model.potential(td, &qd, &x1)))
    } else {
        None
    };
    let x2 = cartesian_along_motion(model, t, q, v);
    Kinematics {
        rows: std::array::from_fn(|i| x1[i].eps.0),
        x: std::array::from_fn(|i| x2[i].re),
        x_dot: std::array::from_fn(|i| x2[i].v1),
        accelerations: std::array::from_fn(|i| Some(x2[i].v2)),
        potential_forces,
    }
}

/// q̈ from M q̈ = 𝓕 − b, for any scalar (dual numbers give derivatives of the accelerations).
/// Fails when M is singular at this configuration.
pub fn accelerations_generic<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    let eom = equations_of_motion(model, t, q, v);
    solve_accelerations::<M::Coords, S, N>(&eom, t, q)
}

/// Solves M q̈ = 𝓕 − b, naming the configuration when M is singular.
#[inline(always)]
pub fn solve_accelerations<C: Coordinates<N>, S: Scalar, const N: usize>(
    eom: &EquationsOfMotion<S, N>,
    t: S,
    q: &[S; N],
) -> Result<[S; N]> {
    let rhs = eom.generalized_forces - eom.inertial_terms;
    let qdd = match solve_spd(&eom.mass_matrix, &rhs) {
        Ok(qdd) => qdd,
        Err(e) => return Err(mass_matrix_failure::<C, S, N>(&eom.mass_matrix, e, t, q)),
    };
    finite_accelerations::<C, S, N>(qdd, t, q)
}

/// q̈ from M q̈ = 𝓕 − b with every check of a call in one branch: `Some(q̈)` when the parameters
/// pass (`parameters_pass`: [`Model::parameters_pass`], or `true`
/// where they were checked once), t, q, q̇ and q̈ are all finite and M's pivots pass
/// [`solve_spd`]'s test; `None` otherwise — the caller then takes the checked path (the parameter
/// and state checks, then [`solve_accelerations`]), which says what failed.
///
/// For equations whose evaluation is straight-line arithmetic (the closed form `#[mechanism]`
/// derives), so that evaluating them at a state that turns out non-finite costs nothing but the
/// wasted arithmetic: no user code runs, nothing can panic or loop.
///
/// ```
/// use lagrange_core::dynamics::{regular_accelerations, EquationsOfMotion};
/// use nalgebra::{matrix, vector};
/// let eom = EquationsOfMotion {
///     mass_matrix: matrix![2.0],
///     generalized_forces: vector![-4.0],
///     inertial_terms: vector![0.0],
/// };
/// assert_eq!(regular_accelerations(&eom, 0.0, &[0.1], &[0.0], true), Some([-2.0]));
/// assert_eq!(regular_accelerations(&eom, 0.0, &[0.1], &[f64::NAN], true), None);
/// assert_eq!(regular_accelerations(&eom, 0.0, &[0.1], &[0.0], false), None);
/// ```
#[inline(always)]
pub fn regular_accelerations<const N: usize>(
    eom: &EquationsOfMotion<f64, N>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    parameters_pass: bool,
) -> Option<[f64; N]> {
    let rhs = eom.generalized_forces - eom.inertial_terms;
    let (qdd, pivots_pass) = solve_spd_flagged(&eom.mass_matrix, &rhs);
    let qdd: [f64; N] = qdd.into();
    // `&`, not `&&`: one branch for all three.
    (parameters_pass & pivots_pass & state_and_accelerations_finite(t, q, v, &qdd)).then_some(qdd)
}

/// The mass matrix alone (one gradient pass).
pub fn mass_matrix<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
) -> SMatrix<S, N, N> {
    let (x1, _, _) = cartesian_with_jacobian(model, t, q);
    let rows: [Option<SVector<S, N>>; K] = std::array::from_fn(|i| x1[i].eps.0);
    assemble_mass_matrix::<M, S, N, K>(&model.masses(), &rows)
}

#[cfg(test)]
mod tests;
