//! The equations of motion of a mechanism whose bodies form a **tree of translations**, with
//! derivative work proportional to the structural non-zeros.
//!
//! Most declarations place a body relative to one it names: a chain's link k is link k − 1 plus a
//! rod, the double pendulum's second bob is the first plus its own arm. When every row of x is
//! written that way,
//!
//! ```text
//! xᵢ = x_p(i) + dᵢ(q_S(i), t),      Jᵢ = J_p(i) + Dᵢ,      Dᵢ = ∂dᵢ/∂q  (non-zero only in columns S(i)),
//! ```
//!
//! so each row's own displacement dᵢ needs dual numbers seeded only on the few coordinates S(i) it
//! names (a chain link: one), never on all N. Summing Lagrange's terms over the tree
//! (the composite-rigid-body idea of Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §6.2,
//! for bodies that only translate relative to their parents):
//!
//! ```text
//! M = Σ_{a, b} m(a, b) Dₐᵀ D_b,           m(a, b) = mass of the rows below both a and b,
//! 𝓕 − b = Σₐ Dₐᵀ Σ_{i below a} (Fᵢ − μᵢ Aᵢ) − ∇V + Q,   Aᵢ = A_p(i) + αᵢ,
//! ```
//!
//! where αᵢ = d²/ds² dᵢ(q + s q̇, t + s)|₀ is a row's own velocity-product (and time) acceleration and
//! Aᵢ the row's whole acceleration at q̈ = 0. "Below a" includes a. When b lies below a,
//! m(a, b) = C_b, the composite mass of b's subtree; rows on different branches do not couple. So
//! M pairs every body with each of its ancestors (a chain: O(N²) products, one per entry, as
//! in the hand-written form), the forces a backward sweep (O(K)), the accelerations a forward sweep.
//!
//! `#[mechanism]` implements [`Tree`] when it finds this structure in a declaration (see the
//! facade's documentation); other mechanisms use [`crate::dynamics::equations_of_motion`].

use crate::dynamics::EquationsOfMotion;
use crate::error::Result;
use crate::geometry::Scalar;
use crate::model::Model;
use nalgebra::{Const, SMatrix, SVector, U1};
use num_dual::{Derivative, HyperDualVec};

mod articulated;
pub mod rigid;
pub use articulated::each_coordinate_moves_one_body;

/// A hyper-dual number with a `W`-wide first part (the seeded coordinates of one body) and a scalar
/// second part (the direction of motion (q̇, 1)).
pub type Seeded<S, const W: usize> = HyperDualVec<S, Const<W>, U1>;

/// What slot j of a row's seeds stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seed {
    /// Not used by this row.
    Unused,
    /// Generalized coordinate q_c (direction q̇_c).
    Coordinate(usize),
    /// Time (direction 1): the row depends on t explicitly.
    Time,
}

/// A body of a [`Tree`]: a point whose 2 or 3 rows of x are translated from its parent's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Body<const W: usize> {
    /// Its first row of x.
    pub row: usize,
    /// Its rows: 2 in the plane, 3 in space.
    pub dim: usize,
    /// The body it is translated from (an earlier one), if any.
    pub parent: Option<usize>,
    /// What each of its `W` seeds stands for.
    pub seeds: [Seed; W],
}

/// A mechanism whose bodies form a tree of translations, x_b = x_p(b) + d_b(q_S(b), t), with at most
/// `W` seeds per body and `B` bodies (see the [module docs](self)). Parents come before their
/// children, in the list and in x.
pub trait Tree<const N: usize, const K: usize, const W: usize, const B: usize>:
    Model<N, K>
{
    /// The bodies, in declaration order.
    const BODIES: [Body<W>; B];
    /// `ANCESTORS[b][a]`: body a lies above body b (b is translated, directly or through others,
    /// from a). Computed from [`Tree::BODIES`] at compile time, so the mass matrix's loop over pairs
    /// has a fixed shape instead of a walk whose length varies from body to body.
    const ANCESTORS: [[bool; B]; B] = ancestors(&Self::BODIES);
    /// Whether every coordinate moves exactly one body (is a seed of one body only): then
    /// [`accelerations`] takes the articulated-body recursion instead of solving with M.
    const JOINTS: bool = each_coordinate_moves_one_body(&Self::BODIES, N);
    /// d for every row of x, each body's expression evaluated on its own seeds ([`seed`], [`time`]).
    fn displacements<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [Seeded<S, W>; K];
    /// M from each body's D and composite mass: by default a loop over the pairs
    /// ([`mass_matrix_by_ancestors`]); `#[mechanism]` writes the pairs out, one [`couple`] each.
    #[inline(always)]
    fn mass_matrix<S: Scalar>(
        jacobian: &BodyJacobians<S, W, B>,
        composite: &[f64; B],
    ) -> SMatrix<S, N, N>
    where
        Self: Sized,
    {
        mass_matrix_by_ancestors::<Self, S, N, K, W, B>(jacobian, composite)
    }
}

/// The ancestor table of a list of bodies whose parents come first (see [`Tree::ANCESTORS`]).
pub const fn ancestors<const W: usize, const B: usize>(bodies: &[Body<W>; B]) -> [[bool; B]; B] {
    let mut table = [[false; B]; B];
    let mut b = 0;
    while b < B {
        let mut above = bodies[b].parent;
        while let Some(a) = above {
            table[b][a] = true;
            above = bodies[a].parent;
        }
        b += 1;
    }
    table
}

/// Coordinate value `q` seeded in `slot` with direction `q̇`: ε₁ = e_slot, ε₂ = q̇.
#[inline(always)]
pub fn seed<S: Scalar, const W: usize>(q: S, q_dot: S, slot: usize) -> Seeded<S, W> {
    HyperDualVec::new(
        q,
        Derivative::derivative_generic(Const::<W>, U1, slot),
        Derivative::some(SMatrix::<S, 1, 1>::new(q_dot)),
        Derivative::none(),
    )
}

/// Time seeded in `slot` with direction 1 (a row that names t), or unseeded (`slot = None`).
#[inline(always)]
pub fn time<S: Scalar, const W: usize>(t: S, slot: Option<usize>) -> Seeded<S, W> {
    match slot {
        Some(slot) => seed(t, S::one(), slot),
        None => HyperDualVec::from_re(t),
    }
}

/// αᵢ = (∂ḋᵢ/∂(q_S, t)) · (q̇_S, 1): the mixed part of a row's displacement along the direction of
/// motion (zero when the row is at most linear in its seeds).
#[inline(always)]
fn own_acceleration_of<S: Scalar, const N: usize, const W: usize>(
    d: &Seeded<S, W>,
    seeds: &[Seed; W],
    v: &[S; N],
) -> S {
    let mut a = S::zero();
    if let Some(h) = &d.eps1eps2.0 {
        for (j, seed) in seeds.iter().enumerate() {
            match seed {
                Seed::Coordinate(c) => a += h[j] * v[*c],
                Seed::Time => a += h[j],
                Seed::Unused => {}
            }
        }
    }
    a
}

/// M, 𝓕 and b at (t, q, q̇) of a [`Tree`] (see the [module docs](self)).
#[inline]
pub fn equations_of_motion<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    let d = model.displacements(t, q, v);
    let masses = model.masses();
    let Rows {
        own_acceleration,
        mut force,
        mut generalized_forces,
    } = rows::<M, S, N, K, W, B>(model, t, q, v, &d);
    let mut inertia = accelerations_at_rest::<M, S, N, K, W, B>(own_acceleration);
    for i in 0..K {
        inertia[i] *= masses[i];
    }

    // Backward sweep, leaf to root: each body's subtree sums of Fᵢ and μᵢAᵢ (row by row) and of
    // the masses (C_b); a body's sums are complete when it is reached.
    let mut composite = [0.0; B];
    let mut inertial_terms = SVector::<S, N>::zeros();
    for b in (0..B).rev() {
        let body = &M::BODIES[b];
        composite[b] += masses[body.row];
        for k in 0..3 {
            if k >= body.dim {
                break;
            }
            let i = body.row + k;
            if let Some(db) = &d[i].eps1.0 {
                for (j, seed) in body.seeds.iter().enumerate() {
                    if let Seed::Coordinate(c) = *seed {
                        generalized_forces[c] += db[j] * force[i];
                        inertial_terms[c] += db[j] * inertia[i];
                    }
                }
            }
            if let Some(p) = body.parent {
                let ip = M::BODIES[p].row + k;
                let (row_force, row_inertia) = (force[i], inertia[i]);
                force[ip] += row_force;
                inertia[ip] += row_inertia;
            }
        }
        if let Some(p) = body.parent {
            composite[p] += composite[b];
        }
    }

    let jacobian = body_jacobians::<M, S, N, K, W, B>(&d);
    EquationsOfMotion {
        mass_matrix: M::mass_matrix(&jacobian, &composite),
        generalized_forces,
        inertial_terms,
    }
}

/// Aᵢ = A_p(i) + αᵢ, root to leaf: each row's acceleration at q̈ = 0, its parent's included.
#[inline(always)]
fn accelerations_at_rest<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    own_acceleration: [S; K],
) -> [S; K] {
    let mut acceleration = own_acceleration;
    for body in &M::BODIES {
        if let Some(p) = body.parent {
            for k in 0..3 {
                if k >= body.dim {
                    break;
                }
                let (i, ip) = (body.row + k, M::BODIES[p].row + k);
                acceleration[i] += acceleration[ip];
            }
        }
    }
    acceleration
}

/// D of each body, row by row (zero where a row does not depend on the seeds).
#[inline(always)]
fn body_jacobians<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    d: &[Seeded<S, W>; K],
) -> BodyJacobians<S, W, B> {
    std::array::from_fn(|b| {
        let body = &M::BODIES[b];
        std::array::from_fn(|k| match k < body.dim {
            true => d[body.row + k].eps1.0.unwrap_or_else(SVector::zeros),
            false => SVector::zeros(),
        })
    })
}

/// What M, 𝓕 and b and the articulated-body recursion both start from, row by row of x.
pub(crate) struct Rows<S, const N: usize, const K: usize> {
    /// αᵢ: the row's own acceleration at q̈ = 0 (not its parent's).
    pub own_acceleration: [S; K],
    /// The Cartesian forces on the row: the uniform field's weight and applied forces.
    pub force: [S; K],
    /// The generalized forces that act on the coordinates directly: direct forces and −∇V.
    pub generalized_forces: SVector<S, N>,
}

/// [`Rows`] at (t, q, q̇) from the bodies' displacements `d`: x and ẋ (what applied forces and
/// potentials read) by a forward sweep, root to leaf, then the forces.
#[inline(always)]
pub(crate) fn rows<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    d: &[Seeded<S, W>; K],
) -> Rows<S, N, K> {
    let mut x = [S::zero(); K];
    let mut x_dot = [S::zero(); K];
    let mut own_acceleration = [S::zero(); K];
    for body in &M::BODIES {
        // Over the constant range 0..3 (unrolled by the compiler), not 0..dim.
        for k in 0..3 {
            if k >= body.dim {
                break;
            }
            let i = body.row + k;
            let mut xi = d[i].re;
            let mut vi = d[i].eps2.0.map_or(S::zero(), |e| e[0]);
            if let Some(p) = body.parent {
                let ip = M::BODIES[p].row + k;
                xi += x[ip];
                vi += x_dot[ip];
            }
            x[i] = xi;
            x_dot[i] = vi;
            own_acceleration[i] = own_acceleration_of(&d[i], &body.seeds, v);
        }
    }
    let mut force = [S::zero(); K];
    if M::HAS_GRAVITY {
        let weights = model.weights();
        for i in 0..K {
            force[i] = S::from(weights[i]);
        }
    }
    let mut generalized_forces = SVector::<S, N>::zeros();
    if M::HAS_FORCES {
        let mut applied = [S::zero(); K];
        let mut direct = [S::zero(); N];
        model.applied_forces(t, q, v, &x, &x_dot, &mut applied, &mut direct);
        for i in 0..K {
            force[i] += applied[i];
        }
        generalized_forces = SVector::from(direct);
    }
    if M::HAS_POTENTIAL {
        generalized_forces -= potential_gradient(model, t, q, d, &x);
    }
    Rows {
        own_acceleration,
        force,
        generalized_forces,
    }
}

/// q̈ at (t, q, q̇) of a [`Tree`]: by the articulated-body recursion when each coordinate moves one
/// body ([`Tree::JOINTS`]; work proportional to the bodies), otherwise by solving
/// M q̈ = 𝓕 − b with [`equations_of_motion`].
#[inline]
pub fn accelerations<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    if !M::JOINTS {
        let eom = equations_of_motion(model, t, q, v);
        return crate::dynamics::solve_accelerations::<M::Coords, S, N>(&eom, t, q);
    }
    // Every body planar: 2 rows each; otherwise 3, a planar body's third left empty.
    if K == 2 * B {
        articulated::accelerations::<M, S, N, K, W, B, 2>(model, t, q, v)
    } else {
        articulated::accelerations::<M, S, N, K, W, B, 3>(model, t, q, v)
    }
}

/// The rows of D of each body (zero where a row does not depend on the seeds): what
/// [`Tree::mass_matrix`] pairs.
pub type BodyJacobians<S, const W: usize, const B: usize> = [[SVector<S, W>; 3]; B];

/// M = Σ_b C_b (D_bᵀ D_b + Σ_{a above b} (Dₐᵀ D_b + D_bᵀ Dₐ)) by a loop over the pairs
/// [`Tree::ANCESTORS`] lists, one [`couple`] each: the default of [`Tree::mass_matrix`].
#[inline(always)]
pub fn mass_matrix_by_ancestors<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    jacobian: &BodyJacobians<S, W, B>,
    composite: &[f64; B],
) -> SMatrix<S, N, N> {
    let mut m = SMatrix::<S, N, N>::zeros();
    for b in 0..B {
        // A subtree of massless points adds nothing.
        if composite[b] == 0.0 {
            continue;
        }
        couple::<M, S, N, K, W, B>(&mut m, jacobian, composite, b, b);
        for a in 0..b {
            if M::ANCESTORS[b][a] {
                couple::<M, S, N, K, W, B>(&mut m, jacobian, composite, b, a);
            }
        }
    }
    m
}

/// Adds to M the terms that pair body `b` with body `a` — `a = b` (C_b D_bᵀ D_b), or `a` above `b`
/// (C_b (Dₐᵀ D_b + D_bᵀ Dₐ)) — one dot product over b's rows per pair of seeds. Mirrored entries
/// receive the same terms in the same order, so M is exactly symmetric. Called with constant
/// `b` and `a` (as the `#[mechanism]` expansion does, pair by pair, leaving out the bodies below
/// which nothing carries mass), every index and seed is known where it is compiled: straight-line
/// code with no loop, branch or bounds check left.
#[inline(always)]
pub fn couple<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    m: &mut SMatrix<S, N, N>,
    jacobian: &BodyJacobians<S, W, B>,
    composite: &[f64; B],
    b: usize,
    a: usize,
) {
    let (body, above) = (&M::BODIES[b], &M::BODIES[a]);
    let weight = S::from(composite[b]);
    let (da, db) = (&jacobian[a], &jacobian[b]);
    // Σ over the body's rows of Dₐ[r] D_b[s].
    let dot = |r: usize, s: usize| {
        let mut sum = da[0][r] * db[0][s];
        for k in 1..body.dim {
            sum += da[k][r] * db[k][s];
        }
        sum * weight
    };
    for (s, seed_s) in body.seeds.iter().enumerate() {
        let Seed::Coordinate(cs) = *seed_s else {
            continue;
        };
        for (r, seed_r) in above.seeds.iter().enumerate() {
            let Seed::Coordinate(cr) = *seed_r else {
                continue;
            };
            let term = dot(r, s);
            if a == b {
                // Every entry of D_bᵀ D_b: the (r, s) and (s, r) products are equal.
                m[(cr, cs)] += term;
            } else {
                // The same term into both mirrored entries (twice into a diagonal one).
                m[(cr, cs)] += term;
                m[(cs, cr)] += term;
            }
        }
    }
}

#[inline(always)]
fn potential_gradient<
    M: Tree<N, K, W, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
    const B: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    d: &[Seeded<S, W>; K],
    x: &[S; K],
) -> SVector<S, N> {
    let mut rows: [SVector<S, N>; K] = [SVector::zeros(); K];
    for body in &M::BODIES {
        for k in 0..body.dim {
            let i = body.row + k;
            let mut row = match body.parent {
                Some(p) => rows[M::BODIES[p].row + k],
                None => SVector::zeros(),
            };
            if let Some(di) = &d[i].eps1.0 {
                for (j, seed) in body.seeds.iter().enumerate() {
                    if let Seed::Coordinate(c) = seed {
                        row[*c] += di[j];
                    }
                }
            }
            rows[i] = row;
        }
    }
    let rows: [Option<SVector<S, N>>; K] = rows.map(Some);
    crate::dynamics::potential_forces(model, t, q, x, &rows).map_or_else(SVector::zeros, |f| -f)
}

#[cfg(test)]
mod tests;
