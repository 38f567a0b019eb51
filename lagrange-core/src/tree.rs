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
//! (DESIGN §2, "the point-mass form"; the composite-body idea of Featherstone, *Rigid Body Dynamics
//! Algorithms*, 2008, §6.2, for translations):
//!
//! ```text
//! M = Σ_{a, b} m(a, b) Dₐᵀ D_b,           m(a, b) = mass of the rows below both a and b,
//! 𝓕 − b = Σₐ Dₐᵀ Σ_{i below a} (Fᵢ − μᵢ Aᵢ) − ∇V + Q,   Aᵢ = A_p(i) + αᵢ,
//! ```
//!
//! where αᵢ = d²/ds² dᵢ(q + s q̇, t + s)|₀ is a row's own velocity-product (and time) acceleration and
//! Aᵢ the row's whole acceleration at q̈ = 0. "Below a" includes a. When b lies below a,
//! m(a, b) = C_b, the composite mass of b's subtree; rows on different branches do not couple. So
//! M is a walk from every row up through its ancestors (a chain: O(N²) products, one per entry, as
//! in the hand-written form), the forces a backward sweep (O(K)), the accelerations a forward sweep.
//!
//! `#[mechanism]` implements [`Tree`] when it finds this structure in a declaration (see the
//! facade's documentation); other mechanisms use [`crate::dynamics::equations_of_motion`].

use crate::dynamics::EquationsOfMotion;
use crate::geometry::Scalar;
use crate::model::Model;
use nalgebra::{Const, SMatrix, SVector, U1};
use num_dual::{Derivative, DualSVec, HyperDualVec};

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

/// A mechanism whose Cartesian rows form a tree of translations, xᵢ = x_p(i) + dᵢ(q_S(i), t), with
/// at most `W` seeds per row (see the [module docs](self)). Parents come before their children.
pub trait Tree<const N: usize, const K: usize, const W: usize>: Model<N, K> {
    /// The row each row is translated from (`None` for a root). `PARENT[i] < i`.
    const PARENT: [Option<usize>; K];
    /// What each of a row's `W` seeds stands for; the rows of one body share their seeds.
    const SEEDS: [[Seed; W]; K];
    /// dᵢ for every row, each body's expression evaluated on its own seeds ([`seed`], [`time`]).
    fn displacements<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> [Seeded<S, W>; K];
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

/// One row's own terms: value dᵢ, velocity ḋᵢ, acceleration αᵢ at q̈ = 0, and Dᵢ on its seeds.
struct Own<S: Scalar, const W: usize> {
    value: S,
    velocity: S,
    acceleration: Option<S>,
    jacobian: Option<SVector<S, W>>,
}

#[inline(always)]
fn own<S: Scalar, const N: usize, const W: usize>(
    d: &Seeded<S, W>,
    seeds: &[Seed; W],
    v: &[S; N],
) -> Own<S, W> {
    // αᵢ = (∂ḋᵢ/∂(q_S, t)) · (q̇_S, 1): the mixed part along the direction of motion.
    let acceleration = d.eps1eps2.0.map(|h| {
        let mut a = S::zero();
        for (j, seed) in seeds.iter().enumerate() {
            match seed {
                Seed::Coordinate(c) => a += h[j] * v[*c],
                Seed::Time => a += h[j],
                Seed::Unused => {}
            }
        }
        a
    });
    Own {
        value: d.re,
        velocity: d.eps2.0.map_or(S::zero(), |e| e[0]),
        acceleration,
        jacobian: d.eps1.0,
    }
}

/// M, 𝓕 and b at (t, q, q̇) of a [`Tree`] (see the [module docs](self)).
#[inline]
pub fn equations_of_motion<
    M: Tree<N, K, W>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const W: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    let d = model.displacements(t, q, v);
    let masses = model.masses();
    let own: [Own<S, W>; K] = std::array::from_fn(|i| own(&d[i], &M::SEEDS[i], v));

    // Forward sweep, root to leaf: xᵢ, ẋᵢ and Aᵢ = A_p(i) + αᵢ.
    let mut x = [S::zero(); K];
    let mut x_dot = [S::zero(); K];
    let mut acceleration = [S::zero(); K];
    for i in 0..K {
        let (mut xi, mut vi, mut ai) = (own[i].value, own[i].velocity, S::zero());
        if let Some(a) = own[i].acceleration {
            ai = a;
        }
        if let Some(p) = M::PARENT[i] {
            xi += x[p];
            vi += x_dot[p];
            ai += acceleration[p];
        }
        x[i] = xi;
        x_dot[i] = vi;
        acceleration[i] = ai;
    }

    // Cartesian forces on each row: weights of a uniform field and applied forces.
    let mut force = [S::zero(); K];
    if M::HAS_GRAVITY {
        let weights = model.weights();
        for i in 0..K {
            force[i] = S::from(weights[i]);
        }
    }
    let mut direct = [S::zero(); N];
    if M::HAS_FORCES {
        let mut applied = [S::zero(); K];
        model.applied_forces(t, q, v, &x, &x_dot, &mut applied, &mut direct);
        for i in 0..K {
            force[i] += applied[i];
        }
    }

    // Backward sweep, leaf to root: Σ over the rows below each row of Fᵢ, μᵢAᵢ and μᵢ (composite
    // masses).
    let mut inertia = [S::zero(); K];
    let mut composite = masses;
    for i in 0..K {
        inertia[i] = acceleration[i] * masses[i];
    }
    for i in (0..K).rev() {
        if let Some(p) = M::PARENT[i] {
            let (f, b, c) = (force[i], inertia[i], composite[i]);
            force[p] += f;
            inertia[p] += b;
            composite[p] += c;
        }
    }

    // 𝓕 = Σₐ Dₐᵀ (Σ below a Fᵢ) + Q − ∇V and b = Σₐ Dₐᵀ (Σ below a μᵢAᵢ), scattered by the seeds.
    let mut generalized_forces = SVector::<S, N>::from(direct);
    let mut inertial_terms = SVector::<S, N>::zeros();
    for a in 0..K {
        if let Some(da) = &own[a].jacobian {
            for (j, seed) in M::SEEDS[a].iter().enumerate() {
                if let Seed::Coordinate(c) = seed {
                    generalized_forces[*c] += da[j] * force[a];
                    inertial_terms[*c] += da[j] * inertia[a];
                }
            }
        }
    }
    if M::HAS_POTENTIAL {
        generalized_forces -= potential_gradient(model, t, q, &own, &x);
    }

    EquationsOfMotion {
        mass_matrix: mass_matrix::<M, S, N, K, W>(&own, &composite),
        generalized_forces,
        inertial_terms,
    }
}

/// M = Σ_b Σ_{a ancestor of b or b} C_b (Dₐᵀ D_b + D_bᵀ Dₐ) (once for a = b): every row walks up
/// through its ancestors. The lower triangle is summed and mirrored (exactly symmetric).
#[inline(always)]
fn mass_matrix<M: Tree<N, K, W>, S: Scalar, const N: usize, const K: usize, const W: usize>(
    own: &[Own<S, W>; K],
    composite: &[f64; K],
) -> SMatrix<S, N, N> {
    let mut m = SMatrix::<S, N, N>::zeros();
    for b in 0..K {
        let Some(db) = &own[b].jacobian else { continue };
        if composite[b] == 0.0 {
            continue;
        }
        let weighted = db * S::from(composite[b]);
        // a = b: C_b D_bᵀ D_b.
        for (r, row_seed) in M::SEEDS[b].iter().enumerate() {
            let Seed::Coordinate(cr) = *row_seed else { continue };
            for (s, col_seed) in M::SEEDS[b].iter().enumerate() {
                let Seed::Coordinate(cs) = *col_seed else { continue };
                if cr >= cs {
                    m[(cr, cs)] += db[r] * weighted[s];
                }
            }
        }
        // a strictly above b: C_b (Dₐᵀ D_b + D_bᵀ Dₐ).
        let mut ancestor = M::PARENT[b];
        while let Some(a) = ancestor {
            if let Some(da) = &own[a].jacobian {
                for (r, a_seed) in M::SEEDS[a].iter().enumerate() {
                    let Seed::Coordinate(ca) = *a_seed else { continue };
                    for (s, b_seed) in M::SEEDS[b].iter().enumerate() {
                        let Seed::Coordinate(cb) = *b_seed else { continue };
                        let term = da[r] * weighted[s];
                        if ca == cb {
                            m[(ca, ca)] += term + term;
                        } else {
                            m[(ca.max(cb), ca.min(cb))] += term;
                        }
                    }
                }
            }
            ancestor = M::PARENT[a];
        }
    }
    for c in 0..N {
        for r in (c + 1)..N {
            m[(c, r)] = m[(r, c)];
        }
    }
    m
}

/// ∇V, with V evaluated on gradient duals whose rows are assembled along the tree (Jᵢ = J_p(i) + Dᵢ).
#[inline(always)]
fn potential_gradient<M: Tree<N, K, W>, S: Scalar, const N: usize, const K: usize, const W: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    own: &[Own<S, W>; K],
    x: &[S; K],
) -> SVector<S, N> {
    let mut rows: [SVector<S, N>; K] = [SVector::zeros(); K];
    for i in 0..K {
        let mut row = match M::PARENT[i] {
            Some(p) => rows[p],
            None => SVector::zeros(),
        };
        if let Some(d) = &own[i].jacobian {
            for (j, seed) in M::SEEDS[i].iter().enumerate() {
                if let Seed::Coordinate(c) = seed {
                    row[*c] += d[j];
                }
            }
        }
        rows[i] = row;
    }
    let qd: [DualSVec<S, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let xd: [DualSVec<S, N>; K] =
        std::array::from_fn(|i| DualSVec::new(x[i], Derivative::some(rows[i])));
    let v = model.potential(DualSVec::from_re(t), &qd, &xd);
    v.eps.0.unwrap_or_else(SVector::zeros)
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

    const NONE: Seed = Seed::Unused;

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

    impl Tree<3, 6, 2> for Branchy {
        const PARENT: [Option<usize>; 6] = [None, None, Some(0), Some(1), Some(2), Some(3)];
        const SEEDS: [[Seed; 2]; 6] = [
            [Seed::Coordinate(0), Seed::Time],
            [Seed::Time, NONE],
            [Seed::Coordinate(1), Seed::Coordinate(2)],
            [Seed::Coordinate(1), Seed::Coordinate(2)],
            [Seed::Coordinate(0), NONE],
            [Seed::Coordinate(0), NONE],
        ];
        fn displacements<S: Scalar>(&self, t: S, q: &[S; 3], v: &[S; 3]) -> [Seeded<S, 2>; 6] {
            let (q0, t0) = (seed(q[0], v[0], 0), time(t, Some(1)));
            let a = vec2(q0 + t0.sin(), time::<S, 2>(t, Some(0)).cos() * 0.3);
            let (q1, q2) = (seed::<S, 2>(q[1], v[1], 0), seed(q[2], v[2], 1));
            let b = vec2(q1.sin(), -q1.cos()) * (q2 + 1.0);
            let q0 = seed::<S, 2>(q[0], v[0], 0);
            let c = vec2(q0.cos(), q0 * q0);
            [a.x, a.y, b.x, b.y, c.x, c.y]
        }
    }

    #[test]
    fn the_tree_sums_equal_the_dense_assembly() {
        let model = Branchy { k: 3.0, c: 0.4 };
        let (t, q, v) = (0.7, [0.3, -1.1, 0.4], [0.9, -0.2, 1.3]);
        let tree = equations_of_motion::<_, f64, 3, 6, 2>(&model, t, &q, &v);
        let dense = dynamics::equations_of_motion(&model, t, &q, &v);
        // Both sum the same products in a different order: a few ulps of entries of order 1–30.
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-13 * (1.0 + b.abs());
        for r in 0..3 {
            assert!(close(tree.generalized_forces[r], dense.generalized_forces[r]), "F{r}");
            assert!(close(tree.inertial_terms[r], dense.inertial_terms[r]), "b{r}");
            for c in 0..3 {
                assert!(close(tree.mass_matrix[(r, c)], dense.mass_matrix[(r, c)]), "M{r}{c}");
            }
        }
        assert_eq!(tree.mass_matrix, tree.mass_matrix.transpose());
    }
}
