//! q̈ of a tree of translations by the articulated-body recursion: work proportional to the
//! bodies, no mass matrix formed or factorised.
//!
//! When every coordinate moves exactly one body relative to its parent (a chain's angle moves its
//! own link; a body may have several coordinates), Newton's equations of the bodies and Lagrange's
//! equation of each coordinate, D_cᵀ F_c = Q_c — the force F_c that enters c's subtree through c's
//! coordinates, projected on them, equals the generalized forces that act on them directly — are
//! solved leaf to root, then root to leaf (Featherstone, *Rigid Body Dynamics Algorithms*, 2008,
//! §7.3, the articulated-body algorithm; here the bodies are points that translate):
//!
//! ```text
//! F_c = I_c ẍ_c + p_c                                     (c's articulated inertia and bias)
//! I_b = m_b 1 + Σ_c (I_c − U_c H_c⁻¹ U_cᵀ)                 (c over b's children)
//! p_b = −f_b + Σ_c (I_c α_c + p_c + U_c H_c⁻¹ u_c)
//! U_c = I_c D_c,   H_c = D_cᵀ U_c,   u_c = Q_c − D_cᵀ (I_c α_c + p_c)
//! q̈_c = H_c⁻¹ (u_c − U_cᵀ ẍ_b),   ẍ_c = ẍ_b + D_c q̈_c + α_c   (ẍ = 0 above a root)
//! ```
//!
//! with f_b the Cartesian forces on b (weights, applied forces), D_c = ∂d_c/∂q_c the body's own
//! Jacobian, α_c its own acceleration at q̈ = 0 and Q_c the direct generalized forces and −∇V on
//! its coordinates — the same terms [`super::equations_of_motion`] assembles into M, 𝓕 and b.
//!
//! The H_c are the pivots of a factorisation of M taken leaves first, so M is singular exactly
//! where one of them is; each pivot is tested against M's diagonal entry for its coordinate,
//! C_c |D_c eⱼ|² (C_c the mass of c's subtree), as [`crate::linalg::Ldlt`] tests M's own pivots
//! against their own diagonal entries: a test that rescaling a coordinate does not change.

use super::{Seed, Seeded, Tree};
use crate::dynamics::{finite_accelerations, non_finite_dynamics, singular_mass_matrix};
use crate::error::Result;
use crate::geometry::Scalar;
use crate::linalg::{Dense, Ldlt, NotPositiveDefinite};
use nalgebra::{SMatrix, SVector};
use std::marker::PhantomData;

/// Whether every coordinate 0..N is a seed of exactly one body: the condition of the recursion.
pub const fn each_coordinate_moves_one_body<const W: usize, const B: usize>(
    bodies: &[super::Body<W>; B],
    n: usize,
) -> bool {
    let mut c = 0;
    while c < n {
        let mut owners = 0;
        let mut b = 0;
        while b < B {
            let mut j = 0;
            while j < W {
                if let Seed::Coordinate(seeded) = bodies[b].seeds[j] {
                    if seeded == c {
                        owners += 1;
                    }
                }
                j += 1;
            }
            b += 1;
        }
        if owners != 1 {
            return false;
        }
        c += 1;
    }
    true
}

/// q̈ at (t, q, q̇) of a tree whose coordinates each move one body ([`Tree::JOINTS`]), in `DIM`
/// dimensions (2 when every body is planar; 3 otherwise, a planar body's third row left empty).
#[inline]
pub(super) fn accelerations<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
    const DIM: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    let d = model.displacements(t, q, v);
    let masses = model.masses();
    let rows = super::rows::<M, S, N, K, W, B>(model, t, q, v, &d);
    let (jacobian, own) = Recursion::<M, S, N, K, W, B, DIM>::own_terms(&d, &rows.own_acceleration);
    let diagonal = Recursion::<M, S, N, K, W, B, DIM>::diagonal_entries(&jacobian, &masses);
    let (free, coupling) = Recursion::<M, S, N, K, W, B, DIM>::leaf_to_root(
        t, q, &rows, &masses, &jacobian, &own, &diagonal,
    )?;
    let qdd = Recursion::<M, S, N, K, W, B, DIM>::root_to_leaf(&jacobian, &own, &free, &coupling);
    finite_accelerations::<M::Coords, S, N>(qdd, t, q)
}

/// The sweeps of the recursion for trees of type `M` in `DIM` dimensions, at scalar `S`.
struct Recursion<
    M,
    S,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
    const DIM: usize,
>(PhantomData<(M, S)>);

impl<
        M: Tree<N, K, W, B>,
        S: Scalar,
        const N: usize,
        const K: usize,
        const W: usize,
        const B: usize,
        const DIM: usize,
    > Recursion<M, S, N, K, W, B, DIM>
{
    /// Each body's own D (only its coordinates' columns) and α, in `DIM` rows.
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    fn own_terms(
        d: &[Seeded<S, W>; K],
        own_acceleration: &[S; K],
    ) -> ([SMatrix<S, DIM, W>; B], [SVector<S, DIM>; B]) {
        let zero = S::zero();
        let jacobian: [SMatrix<S, DIM, W>; B] = std::array::from_fn(|b| {
            let body = &M::BODIES[b];
            SMatrix::from_fn(|k, j| match (k < body.dim, body.seeds[j]) {
                (true, Seed::Coordinate(_)) => d[body.row + k].eps1.0.map_or(zero, |e| e[j]),
                _ => zero,
            })
        });
        let own: [SVector<S, DIM>; B] = std::array::from_fn(|b| {
            let body = &M::BODIES[b];
            SVector::from_fn(|k, _| match k < body.dim {
                true => own_acceleration[body.row + k],
                false => zero,
            })
        });
        (jacobian, own)
    }

    /// M's diagonal entry per body and slot, C_b |D_b eⱼ|² (C_b the mass of b's subtree), what
    /// each pivot is tested against; 1 for a slot that is not a coordinate (its pivot is 1).
    #[inline(always)]
    fn diagonal_entries(jacobian: &[SMatrix<S, DIM, W>; B], masses: &[f64; K]) -> [[f64; W]; B] {
        let mut composite = [0.0; B];
        let mut diagonal = [[1.0f64; W]; B];
        for b in (0..B).rev() {
            composite[b] += masses[M::BODIES[b].row];
            for (j, entry) in diagonal[b].iter_mut().enumerate() {
                if !matches!(M::BODIES[b].seeds[j], Seed::Coordinate(_)) {
                    continue;
                }
                let column = jacobian[b].column(j);
                let mut norm = 0.0;
                for k in 0..DIM {
                    norm += column[k].re() * column[k].re();
                }
                *entry = composite[b] * norm;
            }
            if let Some(p) = M::BODIES[b].parent {
                composite[p] += composite[b];
            }
        }
        diagonal
    }

    /// Leaf to root: I_b and p_b, and per body H⁻¹u and H⁻¹Uᵀ for the way back.
    #[inline(always)]
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    fn leaf_to_root(
        t: S,
        q: &[S; N],
        rows: &super::Rows<S, N, K>,
        masses: &[f64; K],
        jacobian: &[SMatrix<S, DIM, W>; B],
        own: &[SVector<S, DIM>; B],
        diagonal: &[[f64; W]; B],
    ) -> Result<([SVector<S, W>; B], [SMatrix<S, W, DIM>; B])> {
        let mut inertia = [SMatrix::<S, DIM, DIM>::zeros(); B];
        let mut bias = [SVector::<S, DIM>::zeros(); B];
        let mut free = [SVector::<S, W>::zeros(); B];
        let mut coupling = [SMatrix::<S, W, DIM>::zeros(); B];
        for b in (0..B).rev() {
            let body = &M::BODIES[b];
            for k in 0..body.dim.min(DIM) {
                inertia[b][(k, k)] += S::from(masses[body.row + k]);
                bias[b][k] -= rows.force[body.row + k];
            }
            let (i_b, dj) = (inertia[b], &jacobian[b]);
            // I α + p, what the subtree needs at ẍ_b = 0 and q̈_b = 0.
            let mut at_rest = bias[b];
            for r in 0..DIM {
                for k in 0..DIM {
                    at_rest[r] += i_b[(r, k)] * own[b][k];
                }
            }
            let (u_mat, h, u) = Self::joint_terms(&i_b, dj, &at_rest, &body.seeds, rows);
            let factors = match Ldlt::with_scales(&h, Dense, &diagonal[b]) {
                Ok(factors) => factors,
                Err(e) => {
                    return Err(failure::<M, S, N, K, W, B>(
                        body.seeds,
                        e,
                        &diagonal[b],
                        t,
                        q,
                    ))
                }
            };
            free[b] = factors.solve(&u);
            for r in 0..DIM {
                let column = factors.solve(&SVector::from_fn(|j, _| u_mat[(r, j)]));
                for j in 0..W {
                    coupling[b][(j, r)] = column[j];
                }
            }
            if let Some(p) = body.parent {
                // I − U H⁻¹Uᵀ and I α + p + U H⁻¹u into the parent's.
                for r in 0..DIM {
                    let mut pushed = at_rest[r];
                    for j in 0..W {
                        pushed += u_mat[(r, j)] * free[b][j];
                    }
                    bias[p][r] += pushed;
                    for k in 0..DIM {
                        let mut reduced = i_b[(r, k)];
                        for j in 0..W {
                            reduced -= u_mat[(r, j)] * coupling[b][(j, k)];
                        }
                        inertia[p][(r, k)] += reduced;
                    }
                }
            }
        }
        Ok((free, coupling))
    }

    /// U = I D, H = Dᵀ U and u = Q − Dᵀ (I α + p) of a body with articulated inertia `i_b`, own
    /// Jacobian `dj` and I α + p = `at_rest`; slots that are not coordinates get H = 1, a pivot
    /// tested against 1.
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    fn joint_terms(
        i_b: &SMatrix<S, DIM, DIM>,
        dj: &SMatrix<S, DIM, W>,
        at_rest: &SVector<S, DIM>,
        seeds: &[Seed; W],
        rows: &super::Rows<S, N, K>,
    ) -> (SMatrix<S, DIM, W>, SMatrix<S, W, W>, SVector<S, W>) {
        let mut u_mat = SMatrix::<S, DIM, W>::zeros();
        for r in 0..DIM {
            for j in 0..W {
                for k in 0..DIM {
                    u_mat[(r, j)] += i_b[(r, k)] * dj[(k, j)];
                }
            }
        }
        let mut h = SMatrix::<S, W, W>::zeros();
        let mut u = SVector::<S, W>::zeros();
        for (i, seed) in seeds.iter().enumerate() {
            let Seed::Coordinate(c) = *seed else {
                h[(i, i)] = S::one();
                continue;
            };
            for j in 0..W {
                for k in 0..DIM {
                    h[(i, j)] += dj[(k, i)] * u_mat[(k, j)];
                }
            }
            u[i] = rows.generalized_forces[c];
            for k in 0..DIM {
                u[i] -= dj[(k, i)] * at_rest[k];
            }
        }
        (u_mat, h, u)
    }

    /// Root to leaf: q̈ of each body's coordinates from its parent's ẍ, then its own ẍ.
    #[inline(always)]
    fn root_to_leaf(
        jacobian: &[SMatrix<S, DIM, W>; B],
        own: &[SVector<S, DIM>; B],
        free: &[SVector<S, W>; B],
        coupling: &[SMatrix<S, W, DIM>; B],
    ) -> SVector<S, N> {
        let mut qdd = SVector::<S, N>::zeros();
        let mut body_acceleration = [SVector::<S, DIM>::zeros(); B];
        for b in 0..B {
            let body = &M::BODIES[b];
            let above = match body.parent {
                Some(p) => body_acceleration[p],
                None => SVector::zeros(),
            };
            let mut slots = free[b];
            for j in 0..W {
                for k in 0..DIM {
                    slots[j] -= coupling[b][(j, k)] * above[k];
                }
            }
            let mut acceleration = above + own[b];
            for k in 0..DIM {
                for j in 0..W {
                    acceleration[k] += jacobian[b][(k, j)] * slots[j];
                }
            }
            body_acceleration[b] = acceleration;
            for (j, seed) in body.seeds.iter().enumerate() {
                if let Seed::Coordinate(c) = *seed {
                    qdd[c] = slots[j];
                }
            }
        }
        qdd
    }
}

/// The error for a pivot that failed: non-finite dynamics when the pivot or a diagonal entry
/// overflowed, otherwise a singular mass matrix named by the pivot's coordinate (the body's first
/// coordinate when the failing slot is not one).
#[cold]
#[inline(never)]
fn failure<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    seeds: [Seed; W],
    e: NotPositiveDefinite,
    scales: &[f64; W],
    t: S,
    q: &[S; N],
) -> crate::error::Error {
    if !e.pivot.is_finite() || scales.iter().any(|s| !s.is_finite()) {
        return non_finite_dynamics::<M::Coords, S, N>(t, q);
    }
    let coordinate = |seed: Seed| match seed {
        Seed::Coordinate(c) => Some(c),
        _ => None,
    };
    let index = coordinate(seeds[e.index])
        .or_else(|| seeds.iter().find_map(|s| coordinate(*s)))
        .unwrap_or(0);
    singular_mass_matrix::<M::Coords, S, N>(
        NotPositiveDefinite {
            index,
            pivot: e.pivot,
        },
        t,
        q,
    )
}
