//! Spatial inertias in block form, I = [A B; Bᵀ C] with A and C symmetric (see
//! [`super::spatial`]): a rigid body's, a composite of bodies, or an articulated body's. The
//! symmetric blocks are stored by their six distinct entries and every routine forms only those:
//! the frame changes of the backward sweeps are most of the recursions' work.

use super::spatial::{Axis, Force, Motion, RigidInertia, M3, V3};
use crate::geometry::Scalar;

/// [f(0), f(1), f(2)], written out (in the per-body steps, where `std::array::from_fn` is left
/// as a call).
#[inline(always)]
fn map3<T>(f: impl Fn(usize) -> T) -> [T; 3] {
    [f(0), f(1), f(2)]
}

/// A symmetric 3×3 matrix by its distinct entries: (xx, yy, zz, xy, xz, yz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sym3<S>(pub [S; 6]);

/// The index in [`Sym3`] of entry (i, j).
#[inline(always)]
const fn sym(i: usize, j: usize) -> usize {
    match (i, j) {
        (0, 0) => 0,
        (1, 1) => 1,
        (2, 2) => 2,
        (0, 1) | (1, 0) => 3,
        (0, 2) | (2, 0) => 4,
        _ => 5,
    }
}

impl<S: Scalar> Sym3<S> {
    /// Entry (i, j).
    #[inline(always)]
    pub fn at(&self, i: usize, j: usize) -> S {
        self.0[sym(i, j)]
    }

    #[inline(always)]
    fn set(&mut self, i: usize, j: usize, x: S) {
        self.0[sym(i, j)] = x;
    }

    /// From a matrix known to be symmetric (its upper triangle).
    #[inline(always)]
    pub fn from_upper(m: &M3<S>) -> Self {
        Sym3([m[0][0], m[1][1], m[2][2], m[0][1], m[0][2], m[1][2]])
    }

    /// M x.
    #[inline(always)]
    fn apply(&self, x: V3<S>) -> V3<S> {
        map3(|i| self.at(i, 0) * x[0] + self.at(i, 1) * x[1] + self.at(i, 2) * x[2])
    }

    /// R M Rᵀ for R the rotation by (cos θ, sin θ) about `axis`: with (u, v) the plane it turns,
    /// the uu, uv, vv entries by the double angle, the ua, va entries as a vector, aa unchanged.
    #[inline(always)]
    fn turn(&mut self, axis: Axis, (c, s): (S, S), double: (S, S)) {
        let (a, u, v) = axis.indices();
        let (c2, s2) = double;
        let (uu, vv, uv) = (self.at(u, u), self.at(v, v), self.at(u, v));
        let half_sum = (uu + vv) * 0.5;
        let half_diff = (uu - vv) * 0.5;
        let along = c2 * half_diff - s2 * uv;
        self.set(u, u, half_sum + along);
        self.set(v, v, half_sum - along);
        self.set(u, v, s2 * half_diff + c2 * uv);
        let (ua, va) = (self.at(u, a), self.at(v, a));
        self.set(u, a, c * ua - s * va);
        self.set(v, a, s * ua + c * va);
    }

    /// Q M Qᵀ for a constant Q: G = Q M, then the six entries of G Qᵀ.
    #[inline(always)]
    fn rotate(&self, q: &M3<f64>) -> Self {
        let g: M3<S> = map3(|i| {
            map3(|j| self.at(0, j) * q[i][0] + self.at(1, j) * q[i][1] + self.at(2, j) * q[i][2])
        });
        let entry = |i: usize, j: usize| g[i][0] * q[j][0] + g[i][1] * q[j][1] + g[i][2] * q[j][2];
        Sym3([
            entry(0, 0),
            entry(1, 1),
            entry(2, 2),
            entry(0, 1),
            entry(0, 2),
            entry(1, 2),
        ])
    }
}

/// A spatial inertia (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia<S> {
    /// A: the angular–angular block.
    pub a: Sym3<S>,
    /// B: the angular–linear block, by rows.
    pub b: M3<S>,
    /// C: the linear–linear block.
    pub c: Sym3<S>,
}

impl<S: Scalar> Inertia<S> {
    /// Zero.
    #[inline(always)]
    pub fn zero() -> Self {
        Inertia {
            a: Sym3([S::zero(); 6]),
            b: [[S::zero(); 3]; 3],
            c: Sym3([S::zero(); 6]),
        }
    }

    /// I += o.
    #[inline(always)]
    pub fn add(&mut self, o: &Self) {
        for k in 0..6 {
            self.a.0[k] += o.a.0[k];
            self.c.0[k] += o.c.0[k];
        }
        for i in 0..3 {
            for j in 0..3 {
                self.b[i][j] += o.b[i][j];
            }
        }
    }

    /// I m.
    #[inline(always)]
    pub fn apply(&self, m: &Motion<S>) -> Force<S> {
        let (w, v) = (m.angular, m.linear);
        let (aw, cv) = (self.a.apply(w), self.c.apply(v));
        let b = &self.b;
        Force {
            moment: map3(|i| aw[i] + b[i][0] * v[0] + b[i][1] * v[1] + b[i][2] * v[2]),
            force: map3(|i| cv[i] + b[0][i] * w[0] + b[1][i] * w[1] + b[2][i] * w[2]),
        }
    }

    /// The 6 × 6 matrix [A B; Bᵀ C] (angular rows and columns first).
    #[inline(always)]
    pub fn matrix(&self) -> nalgebra::SMatrix<S, 6, 6> {
        nalgebra::SMatrix::<S, 6, 6>::from_fn(|i, j| match (i < 3, j < 3) {
            (true, true) => self.a.at(i, j),
            (true, false) => self.b[i][j - 3],
            (false, true) => self.b[j][i - 3],
            (false, false) => self.c.at(i - 3, j - 3),
        })
    }

    /// I (e_axis; 0): the angular column for `axis` (a revolute joint's U).
    #[inline(always)]
    pub fn angular_column(&self, axis: Axis) -> Force<S> {
        let (a, _, _) = axis.indices();
        Force {
            moment: map3(|i| self.a.at(i, a)),
            force: self.b[a],
        }
    }

    /// I (0; e_axis): the linear column for `axis` (a prismatic joint's U).
    #[inline(always)]
    pub fn linear_column(&self, axis: Axis) -> Force<S> {
        let (a, _, _) = axis.indices();
        Force {
            moment: map3(|i| self.b[i][a]),
            force: map3(|i| self.c.at(i, a)),
        }
    }

    /// The largest diagonal entry of A (angular) or C (linear), real part: the scale a revolute or
    /// prismatic joint's pivot is tested against, in its own units.
    #[inline(always)]
    pub fn diagonal_scale(&self, angular: bool) -> f64 {
        let d = if angular { &self.a } else { &self.c };
        d.0[0].re().max(d.0[1].re()).max(d.0[2].re())
    }

    /// I − U Uᵀ / d for U = (n; f): the articulated inertia a joint passes to its parent
    /// (Featherstone eq. 7.38).
    #[inline(always)]
    pub fn sub_outer(&mut self, u: &Force<S>, inverse_d: S) {
        let (n, f) = (u.moment, u.force);
        let ns: V3<S> = map3(|i| n[i] * inverse_d);
        let fs: V3<S> = map3(|i| f[i] * inverse_d);
        for (k, (i, j)) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
            .into_iter()
            .enumerate()
        {
            self.a.0[k] -= ns[i] * n[j];
            self.c.0[k] -= fs[i] * f[j];
        }
        for i in 0..3 {
            for j in 0..3 {
                self.b[i][j] -= ns[i] * f[j];
            }
        }
    }

    /// The rotation about `axis` by (cos θ, sin θ) applied on both sides, R (A, B, C) Rᵀ: the
    /// joint's own rotation taking a child-frame inertia to the joint's fixed frame.
    #[inline(always)]
    pub fn turn(&mut self, axis: Axis, (c, s): (S, S)) {
        let double = (c * c - s * s, (c * s) * 2.0);
        self.a.turn(axis, (c, s), double);
        self.c.turn(axis, (c, s), double);
        let (_, u, v) = axis.indices();
        let b = &mut self.b;
        for j in 0..3 {
            let (bu, bv) = (b[u][j], b[v][j]);
            b[u][j] = c * bu - s * bv;
            b[v][j] = s * bu + c * bv;
        }
        for row in b.iter_mut() {
            let (bu, bv) = (row[u], row[v]);
            row[u] = c * bu - s * bv;
            row[v] = s * bu + c * bv;
        }
    }

    /// Q (A, B, C) Qᵀ for a constant rotation Q.
    #[inline(always)]
    pub fn rotate(&mut self, q: &M3<f64>) {
        self.a = self.a.rotate(q);
        self.c = self.c.rotate(q);
        let b = &self.b;
        let g: M3<S> =
            map3(|i| map3(|j| b[0][j] * q[i][0] + b[1][j] * q[i][1] + b[2][j] * q[i][2]));
        self.b = map3(|i| map3(|j| g[i][0] * q[j][0] + g[i][1] * q[j][1] + g[i][2] * q[j][2]));
    }

    /// The change of origin by r (the child's origin in the parent's coordinates, both frames
    /// with the same axes): C stays, B += r× C, A −= T + Tᵀ + r× C r× with T = B r×. Components
    /// of r that are structurally zero (`mask[k]` false) are left out.
    #[inline(always)]
    pub fn shift<R: Copy + Into<S>>(&mut self, r: [R; 3], mask: [bool; 3]) {
        let r: V3<S> = r.map(Into::into);
        let cross = |x: V3<S>| cross_masked(&r, mask, x);
        // W = r× C by columns: column j is r × (column j of C).
        let w_cols: [V3<S>; 3] =
            map3(|j| cross([self.c.at(0, j), self.c.at(1, j), self.c.at(2, j)]));
        // Row i of T = B r× is row_i(B) × r = −(r × row_i(B)).
        let t: [V3<S>; 3] = map3(|i| cross(self.b[i]));
        // Row i of W r× is −(r × row_i(W)): the rows of W from its columns.
        let w_row = |i: usize| [w_cols[0][i], w_cols[1][i], w_cols[2][i]];
        let wr: [V3<S>; 3] = map3(|i| cross(w_row(i)));
        // A −= T + Tᵀ + r× C r×, i.e. A += (r × bᵢ)_j + (r × bⱼ)_i + (r × wᵢ)_j.
        for (k, (i, j)) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
            .into_iter()
            .enumerate()
        {
            self.a.0[k] += t[i][j] + t[j][i] + wr[i][j];
        }
        for i in 0..3 {
            for j in 0..3 {
                self.b[i][j] += w_cols[j][i];
            }
        }
    }
}

/// r × x with the components of r that are structurally zero (`mask[k]` false) left out.
#[inline(always)]
fn cross_masked<S: Scalar>(r: &V3<S>, mask: [bool; 3], x: V3<S>) -> V3<S> {
    let term = |k: usize, y: S| if mask[k] { Some(r[k] * y) } else { None };
    let diff = |a: Option<S>, b: Option<S>| match (a, b) {
        (Some(a), Some(b)) => a - b,
        (Some(a), None) => a,
        (None, Some(b)) => -b,
        (None, None) => S::zero(),
    };
    [
        diff(term(1, x[2]), term(2, x[1])),
        diff(term(2, x[0]), term(0, x[2])),
        diff(term(0, x[1]), term(1, x[0])),
    ]
}

impl RigidInertia {
    /// The body's spatial inertia in block form (where the articulated-body and composite-body
    /// recursions start from).
    #[inline(always)]
    pub fn as_inertia<S: Scalar>(&self) -> Inertia<S> {
        let lift = |m: &M3<f64>| m.map(|row| row.map(S::from));
        let h = &self.first_moment;
        let z = 0.0;
        // h× by rows.
        let hx = [[z, -h[2], h[1]], [h[2], z, -h[0]], [-h[1], h[0], z]];
        let m = S::from(self.mass);
        Inertia {
            a: Sym3::from_upper(&lift(&self.rotational)),
            b: lift(&hx),
            c: Sym3([m, m, m, S::zero(), S::zero(), S::zero()]),
        }
    }
}
