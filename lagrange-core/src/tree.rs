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
    // Aᵢ = A_p(i) + αᵢ, root to leaf.
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
    let mut inertia = acceleration;
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

    // D of each body, row by row (zero where a row does not depend on the seeds).
    let jacobian: BodyJacobians<S, W, B> = std::array::from_fn(|b| {
        let body = &M::BODIES[b];
        std::array::from_fn(|k| match k < body.dim {
            true => d[body.row + k].eps1.0.unwrap_or_else(SVector::zeros),
            false => SVector::zeros(),
        })
    });
    EquationsOfMotion {
        mass_matrix: M::mass_matrix(&jacobian, &composite),
        generalized_forces,
        inertial_terms,
    }
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
mod tests {
    use super::*;
    use crate::dynamics;
    use crate::error::Result;
    use crate::geometry::vec2;
    use num_dual::DualNum;

    /// Three bodies written by hand as a tree: A on a support moving in time, B translated from A by
    /// an arm that depends on two coordinates (W = 2), and a massless point C translated from B;
    /// a spring potential, drag on B and a direct force. The same `Model` evaluated densely
    /// ([`dynamics::equations_of_motion`]) is the reference.
    struct Branchy {
        k: f64,
        c: f64,
    }

    impl Model<3, 6> for Branchy {
        type Coords = [f64; 3];
        const INERTIAL: usize = 4;
        const RHEONOMIC: bool = true;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = true;
        const HAS_GRAVITY: bool = true;
        fn validate(&self) -> Result<()> {
            Ok(())
        }
        fn masses(&self) -> [f64; 6] {
            [2.0, 2.0, 0.5, 0.5, 0.0, 0.0]
        }
        fn weights(&self) -> [f64; 6] {
            [0.0, -2.0 * 9.81, 0.0, -0.5 * 9.81, 0.0, 0.0]
        }
        fn cartesian<D: Scalar>(&self, t: D, q: &[D; 3]) -> [D; 6] {
            let a = vec2(q[0] + t.sin(), t.cos() * 0.3);
            let b = a + vec2(q[1].sin(), -q[1].cos()) * (q[2] + 1.0);
            let c = b + vec2(q[0].cos(), q[0] * q[0]);
            [a.x, a.y, b.x, b.y, c.x, c.y]
        }
        fn potential<D: Scalar>(&self, _t: D, q: &[D; 3], x: &[D; 6]) -> D {
            (x[2] * x[2] + x[3] * x[3]) * (self.k * 0.5) + q[2] * q[2] * 3.0
        }
        fn applied_forces<S: Scalar>(
            &self,
            _t: S,
            _q: &[S; 3],
            v: &[S; 3],
            x: &[S; 6],
            x_dot: &[S; 6],
            cartesian_force: &mut [S; 6],
            generalized_force: &mut [S; 3],
        ) {
            cartesian_force[2] += x_dot[2] * (-self.c);
            cartesian_force[3] += x_dot[3] * (-self.c);
            cartesian_force[4] += x[5];
            generalized_force[1] += v[1] * 0.7;
        }
    }

    impl Tree<3, 6, 2, 3> for Branchy {
        const BODIES: [Body<2>; 3] = [
            Body {
                row: 0,
                dim: 2,
                parent: None,
                seeds: [Seed::Coordinate(0), Seed::Time],
            },
            Body {
                row: 2,
                dim: 2,
                parent: Some(0),
                seeds: [Seed::Coordinate(1), Seed::Coordinate(2)],
            },
            Body {
                row: 4,
                dim: 2,
                parent: Some(1),
                seeds: [Seed::Coordinate(0), Seed::Unused],
            },
        ];
        fn displacements<S: Scalar>(&self, t: S, q: &[S; 3], v: &[S; 3]) -> [Seeded<S, 2>; 6] {
            let (q0, t0) = (seed(q[0], v[0], 0), time(t, Some(1)));
            let a = vec2(q0 + t0.sin(), t0.cos() * 0.3);
            let (q1, q2) = (seed::<S, 2>(q[1], v[1], 0), seed(q[2], v[2], 1));
            let b = vec2(q1.sin(), -q1.cos()) * (q2 + 1.0);
            let q0 = seed::<S, 2>(q[0], v[0], 0);
            let c = vec2(q0.cos(), q0 * q0);
            [a.x, a.y, b.x, b.y, c.x, c.y]
        }
    }

    /// A tree whose coordinates each move one body: A on a support moving in time (q0), B from A
    /// on an arm of two coordinates (q1 angle, q2 length), C from B on a rod (q3), and D from A on
    /// a branch of its own (q4, in 3 dimensions as every body here); gravity, a spring, drag and a
    /// direct force.
    struct Joints;

    impl Model<5, 12> for Joints {
        type Coords = [f64; 5];
        const INERTIAL: usize = 12;
        const RHEONOMIC: bool = true;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = true;
        const HAS_GRAVITY: bool = true;
        fn validate(&self) -> Result<()> {
            Ok(())
        }
        fn masses(&self) -> [f64; 12] {
            [2.0, 2.0, 2.0, 0.5, 0.5, 0.5, 0.8, 0.8, 0.8, 1.1, 1.1, 1.1]
        }
        fn weights(&self) -> [f64; 12] {
            let g = -9.81;
            [
                0.0,
                0.0,
                2.0 * g,
                0.0,
                0.0,
                0.5 * g,
                0.0,
                0.0,
                0.8 * g,
                0.0,
                0.0,
                1.1 * g,
            ]
        }
        fn cartesian<D: Scalar>(&self, t: D, q: &[D; 5]) -> [D; 12] {
            let [a, b, c, d] = self.parts(t, q);
            let b = a + b;
            let c = b + c;
            let d = a + d;
            [a, b, c, d]
                .map(|p| p.to_array())
                .concat()
                .try_into()
                .unwrap()
        }
        fn potential<D: Scalar>(&self, _t: D, q: &[D; 5], x: &[D; 12]) -> D {
            (x[3] * x[3] + x[4] * x[4]) * 1.5 + q[2] * q[2] * 3.0
        }
        fn applied_forces<S: Scalar>(
            &self,
            _t: S,
            _q: &[S; 5],
            v: &[S; 5],
            _x: &[S; 12],
            x_dot: &[S; 12],
            cartesian_force: &mut [S; 12],
            generalized_force: &mut [S; 5],
        ) {
            for i in 6..9 {
                cartesian_force[i] += x_dot[i] * (-0.4);
            }
            generalized_force[4] += v[4] * 0.7;
        }
    }

    impl Joints {
        /// A's position and the displacements of B, C and D.
        fn parts<D: Scalar>(&self, t: D, q: &[D; 5]) -> [crate::geometry::Vec3<D>; 4] {
            use crate::geometry::vec3;
            [
                vec3(q[0] + t.sin(), t.cos() * 0.3, D::zero()),
                (q[2] + 1.0) * vec3(q[1].sin(), D::zero(), -q[1].cos()),
                D::from(0.7) * vec3(q[3].cos(), q[3].sin(), q[3] * 0.2),
                D::from(0.9) * vec3(D::zero(), q[4].sin(), -q[4].cos()),
            ]
        }
    }

    impl Tree<5, 12, 2, 4> for Joints {
        const BODIES: [Body<2>; 4] = [
            Body {
                row: 0,
                dim: 3,
                parent: None,
                seeds: [Seed::Coordinate(0), Seed::Time],
            },
            Body {
                row: 3,
                dim: 3,
                parent: Some(0),
                seeds: [Seed::Coordinate(1), Seed::Coordinate(2)],
            },
            Body {
                row: 6,
                dim: 3,
                parent: Some(1),
                seeds: [Seed::Coordinate(3), Seed::Unused],
            },
            Body {
                row: 9,
                dim: 3,
                parent: Some(0),
                seeds: [Seed::Unused, Seed::Coordinate(4)],
            },
        ];
        fn displacements<S: Scalar>(&self, t: S, q: &[S; 5], v: &[S; 5]) -> [Seeded<S, 2>; 12] {
            let t_seeded = time(t, Some(1));
            let seeded: [Seeded<S, 2>; 5] = [
                seed(q[0], v[0], 0),
                seed(q[1], v[1], 0),
                seed(q[2], v[2], 1),
                seed(q[3], v[3], 0),
                seed(q[4], v[4], 1),
            ];
            let [a, b, c, d] = self.parts(t_seeded, &seeded);
            [a, b, c, d]
                .map(|p| p.to_array())
                .concat()
                .try_into()
                .unwrap()
        }
    }

    #[test]
    fn the_articulated_recursion_solves_what_the_dense_assembly_gives() {
        const { assert!(Joints::JOINTS && !Branchy::JOINTS) };
        for (t, q, v) in [
            (
                0.7,
                [0.3, -1.1, 0.4, 2.0, -0.6],
                [0.9, -0.2, 1.3, 0.5, -1.7],
            ),
            (
                -2.0,
                [1.5, 0.2, -0.3, -1.0, 2.5],
                [-0.4, 2.2, 0.1, -1.5, 0.3],
            ),
        ] {
            let recursion = accelerations::<_, f64, 5, 12, 2, 4>(&Joints, t, &q, &v).unwrap();
            let dense = dynamics::equations_of_motion(&Joints, t, &q, &v);
            let solved = dynamics::solve_accelerations::<[f64; 5], f64, 5>(&dense, t, &q).unwrap();
            // Two backward-stable solves of a well-conditioned system (κ(M) < 10³ here), each
            // within a few ulps of q̈ ~ 10: agreement to 1e-12.
            for j in 0..5 {
                assert!(
                    (recursion[j] - solved[j]).abs() <= 1e-12 * (1.0 + solved[j].abs()),
                    "q̈{j} at {q:?}: {} vs {}",
                    recursion[j],
                    solved[j]
                );
            }
        }
        // On the other tree (a coordinate moves two bodies), the same function solves with M.
        let (t, q, v) = (0.7, [0.3, -1.1, 0.4], [0.9, -0.2, 1.3]);
        let eom = equations_of_motion::<_, f64, 3, 6, 2, 3>(&Branchy { k: 3.0, c: 0.4 }, t, &q, &v);
        assert_eq!(
            accelerations::<_, f64, 3, 6, 2, 3>(&Branchy { k: 3.0, c: 0.4 }, t, &q, &v).unwrap(),
            dynamics::solve_accelerations::<[f64; 3], f64, 3>(&eom, t, &q).unwrap()
        );
    }

    #[test]
    fn the_articulated_recursion_reports_a_singular_joint() {
        // With the arm of length zero (q2 = −1), its angle q1 moves nothing: M is singular there.
        let (t, q, v) = (
            0.7,
            [0.3, -1.1, -1.0, 2.0, -0.6],
            [0.9, -0.2, 1.3, 0.5, -1.7],
        );
        match accelerations::<_, f64, 5, 12, 2, 4>(&Joints, t, &q, &v) {
            Err(crate::Error::SingularMassMatrix { coordinate, .. }) => {
                assert_eq!(coordinate, "q1")
            }
            other => panic!("expected a singular mass matrix, got {other:?}"),
        }
    }

    #[test]
    fn the_tree_sums_equal_the_dense_assembly() {
        let model = Branchy { k: 3.0, c: 0.4 };
        let (t, q, v) = (0.7, [0.3, -1.1, 0.4], [0.9, -0.2, 1.3]);
        let tree = equations_of_motion::<_, f64, 3, 6, 2, 3>(&model, t, &q, &v);
        let dense = dynamics::equations_of_motion(&model, t, &q, &v);
        // Both sum the same products in a different order: a few ulps of entries of order 1–30.
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-13 * (1.0 + b.abs());
        for r in 0..3 {
            assert!(
                close(tree.generalized_forces[r], dense.generalized_forces[r]),
                "F{r}"
            );
            assert!(
                close(tree.inertial_terms[r], dense.inertial_terms[r]),
                "b{r}"
            );
            for c in 0..3 {
                assert!(
                    close(tree.mass_matrix[(r, c)], dense.mass_matrix[(r, c)]),
                    "M{r}{c}"
                );
            }
        }
        assert_eq!(tree.mass_matrix, tree.mass_matrix.transpose());
    }
}
