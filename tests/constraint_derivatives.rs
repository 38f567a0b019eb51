//! Constraint rows whose derivatives the macro writes out from the expression tree
//! (`Constraints::position_constraint_derivatives`) against the same declaration differentiated on
//! dual numbers: a wrapper forwards every item of `Model` and `Constraints` but the hook, so the
//! rows, q̈ and the projection are compared between the two paths on one declaration. The shapes:
//! a norm (the Cartesian pendulum), a polynomial, a loop closure in sines and cosines, a
//! constraint that reads time, one written on rows of x that are not coordinates, and one the
//! tree reader does not read beside one it does.

use lagrange::__private::{Model, Scalar};
use lagrange::constraints::{self, constraint_rows, ConstraintKind, ConstraintRows, Constraints};
use lagrange::prelude::*;
use nalgebra::SVector;

/// `M` with its constraint rows differentiated on dual numbers: every item forwarded but
/// `position_constraint_derivatives` (left to its default, which writes nothing).
struct OnDuals<M>(M);

impl<M: Model<N, K>, const N: usize, const K: usize> Model<N, K> for OnDuals<M> {
    type Coords = M::Coords;
    const INERTIAL: usize = M::INERTIAL;
    const RHEONOMIC: bool = M::RHEONOMIC;
    const HAS_POTENTIAL: bool = M::HAS_POTENTIAL;
    const HAS_FORCES: bool = M::HAS_FORCES;
    const DEPENDS: [[bool; N]; K] = M::DEPENDS;
    const HAS_GRAVITY: bool = M::HAS_GRAVITY;
    fn validate(&self) -> lagrange::Result<()> {
        self.0.validate()
    }
    fn masses(&self) -> [f64; K] {
        self.0.masses()
    }
    fn weights(&self) -> [f64; K] {
        self.0.weights()
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; N]) -> [D; K] {
        self.0.cartesian(t, q)
    }
    fn potential<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> D {
        self.0.potential(t, q, x)
    }
    fn potential_gradient<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        x: &[S; K],
        rows: &[Option<SVector<S, N>>; K],
    ) -> Option<SVector<S, N>> {
        self.0.potential_gradient(t, q, x, rows)
    }
    fn applied_forces<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        x: &[S; K],
        x_dot: &[S; K],
        cartesian_force: &mut [S; K],
        generalized_force: &mut [S; N],
    ) {
        self.0
            .applied_forces(t, q, v, x, x_dot, cartesian_force, generalized_force)
    }
}

impl<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize> Constraints<N, K, C>
    for OnDuals<M>
{
    const NAMES: [&'static str; C] = M::NAMES;
    const KINDS: [ConstraintKind; C] = M::KINDS;
    fn position_constraints<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> [D; C] {
        self.0.position_constraints(t, q, x)
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
    ) -> [D; C] {
        self.0.velocity_constraints(t, q, v, x, x_dot)
    }
    fn friction_coefficients(&self, row: usize) -> constraints::Coulomb {
        self.0.friction_coefficients(row)
    }
}

#[mechanism]
pub mod norm {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Norm {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

/// A bead on the cubic x² y + y³/3 = c (a polynomial of the coordinates, with a product).
#[mechanism]
pub mod polynomial {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Polynomial {
        pub m: f64,
        pub c: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(x, y)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn wire() -> f64 {
        x * x * y + y.powi(3) / 3.0 - c
    }
}

/// Two cranks whose tips are joined by a rod along x: the loop closure in sines and cosines.
#[mechanism]
pub mod cranks {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
    }
    pub struct Cranks {
        pub m: f64,
        pub i: f64,
        pub l1: f64,
        pub l2: f64,
        pub d: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = i)]
    fn left() -> Planar {
        planar(vec2(a.cos(), a.sin()) * (0.5 * l1), a)
    }
    #[rigid_body(mass = m, inertia = i)]
    fn right() -> Planar {
        planar(vec2(d + b.cos() * (0.5 * l2), b.sin() * (0.5 * l2)), b)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn level() -> f64 {
        l1 * a.sin() - l2 * b.sin()
    }
}

/// A particle on a rod whose length is driven, L(t) = l (1 + e sin ωt): g reads t.
#[mechanism]
pub mod driven {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Driven {
        pub m: f64,
        pub l: f64,
        pub e: f64,
        pub w: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l * (1.0 + e * (w * t).sin())
    }
}

/// A pendulum with a sliding bead on its arm: the constraint reads the bead's rows of x (not
/// coordinates), through x's Jacobian and accelerations, and a row the tree reader does not read
/// (`abs`) stays on dual numbers beside it.
#[mechanism]
pub mod slider {
    pub struct Coords {
        pub theta: f64,
        pub s: f64,
    }
    pub struct Slider {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * s
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn reach() -> f64 {
        (bead - vec2(0.3, 0.0)).norm_squared() - l * l
    }
    #[unilateral]
    fn wall() -> f64 {
        (bead.x - 2.0).abs()
    }
}

/// Agreement to round-off: the tree and the dual numbers evaluate the same chain rule in another
/// order, each entry to a few ulps of the largest term it sums (values O(1)–O(100) here), so
/// 1e-13 relative to 1 + |value|.
fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-13 * (1.0 + a.abs().max(b.abs())),
        "{what}: {a} vs {b}"
    );
}

fn same_rows<const N: usize, const C: usize>(
    a: &ConstraintRows<f64, N, C>,
    b: &ConstraintRows<f64, N, C>,
) {
    for i in 0..C {
        close(a.value[i], b.value[i], "g");
        close(a.rate[i], b.rate[i], "ġ");
        close(a.bias[i], b.bias[i], "β");
        for j in 0..N {
            close(a.rows[i][j], b.rows[i][j], "G");
        }
    }
}

/// States off the constraints, moving, at several times.
fn states<const N: usize>() -> impl Iterator<Item = (f64, [f64; N], [f64; N])> {
    (0..10).map(|i| {
        let k = i as f64;
        (
            0.41 * k,
            std::array::from_fn(|j| 0.3 + 0.45 * k - 0.8 * j as f64 + 0.1 * (k * j as f64)),
            std::array::from_fn(|j| 1.2 - 0.35 * k + 0.5 * j as f64),
        )
    })
}

/// The rows (general path), q̈ with every row enforced (the scleronomic hyper-dual pass, or the
/// rheonomic passes), and λ agree between the two paths.
fn agree<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(model: M) {
    let duals = OnDuals(model);
    let model = &duals.0;
    let all = constraints::Mode::all_active::<M, N, K>();
    let mut solved = 0;
    for (t, q, v) in states::<N>() {
        same_rows(
            &constraint_rows(model, t, &q, &v),
            &constraint_rows(&duals, t, &q, &v),
        );
        let a = constraints::accelerations_in_mode(model, t, &q, &v, &all);
        let b = constraints::accelerations_in_mode(&duals, t, &q, &v, &all);
        match (a, b) {
            (Ok(a), Ok(b)) => {
                solved += 1;
                for j in 0..N {
                    close(a.accelerations[j], b.accelerations[j], "q̈");
                }
                for i in 0..C {
                    close(a.multipliers[i], b.multipliers[i], "λ");
                }
            }
            (a, b) => assert_eq!(a.is_err(), b.is_err(), "{a:?} vs {b:?}"),
        }
    }
    // Singular rows (G = 0) at a few states at most: q̈ is compared at most of them.
    assert!(solved >= 8, "q̈ compared at {solved} states of 10");
}

#[test]
fn a_norm() {
    assert_eq!(norm::Norm::POSITION_DERIVATIVES, [true]);
    agree(norm::Norm {
        m: 1.3,
        l: 1.7,
        g: 9.81,
    });
}

#[test]
fn a_polynomial() {
    assert_eq!(polynomial::Polynomial::POSITION_DERIVATIVES, [true]);
    agree(polynomial::Polynomial {
        m: 0.7,
        c: 0.4,
        g: 9.81,
    });
}

#[test]
fn sines_and_cosines() {
    assert_eq!(cranks::Cranks::POSITION_DERIVATIVES, [true]);
    agree(cranks::Cranks {
        m: 0.9,
        i: 0.1,
        l1: 1.0,
        l2: 1.4,
        d: 2.0,
        g: 9.81,
    });
}

#[test]
fn time() {
    assert_eq!(driven::Driven::POSITION_DERIVATIVES, [true]);
    agree(driven::Driven {
        m: 1.1,
        l: 1.5,
        e: 0.2,
        w: 3.0,
        g: 9.81,
    });
}

#[test]
fn rows_of_x_and_a_row_not_read() {
    assert_eq!(slider::Slider::POSITION_DERIVATIVES, [true, false]);
    agree(slider::Slider {
        m: 0.8,
        l: 1.2,
        g: 9.81,
    });
}

#[test]
fn the_validated_handle_agrees() {
    // The Cartesian pendulum through a validated handle: affine positions, the prepared solve.
    let p = norm::Norm {
        m: 1.3,
        l: 1.7,
        g: 9.81,
    };
    let duals = OnDuals(norm::Norm { ..p });
    let sys = p.validated().unwrap();
    for (t, q, v) in states::<2>() {
        let s = State::new(
            t,
            norm::Coords { x: q[0], y: q[1] },
            norm::Coords { x: v[0], y: v[1] },
        );
        let a = sys.accelerations(&s).unwrap();
        let b = constraints::accelerations(&duals, t, &q, &v).unwrap();
        close(a.x, b[0], "q̈ₓ");
        close(a.y, b[1], "q̈ᵧ");
    }
}

#[test]
fn the_gallery_four_bar_through_body_points() {
    // Loop closures written with `Planar::point`: rows of x (centres and angles) through J and a.
    use lagrange_gallery::scenes::four_bar::{four_bar::FourBar, linkage};
    assert_eq!(FourBar::POSITION_DERIVATIVES, [true, true]);
    agree(linkage().0);
}
