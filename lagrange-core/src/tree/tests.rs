use super::*;
use crate::dynamics;
use crate::test_models::test_model_items;

/// Body of `dim` rows from row `row` of x, below `parent`, displaced by the slots `seeds`.
const fn body<const W: usize>(
    row: usize,
    dim: usize,
    parent: Option<usize>,
    seeds: [Seed; W],
) -> Body<W> {
    Body {
        row,
        dim,
        parent,
        seeds,
    }
}
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
    test_model_items!(3; rheonomic: true, potential: true, forces: true, gravity: true);
    const INERTIAL: usize = 4;
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
        body(0, 2, None, [Seed::Coordinate(0), Seed::Time]),
        body(2, 2, Some(0), [Seed::Coordinate(1), Seed::Coordinate(2)]),
        body(4, 2, Some(1), [Seed::Coordinate(0), Seed::Unused]),
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
    test_model_items!(5; rheonomic: true, potential: true, forces: true, gravity: true);
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
        body(0, 3, None, [Seed::Coordinate(0), Seed::Time]),
        body(3, 3, Some(0), [Seed::Coordinate(1), Seed::Coordinate(2)]),
        body(6, 3, Some(1), [Seed::Coordinate(3), Seed::Unused]),
        body(9, 3, Some(0), [Seed::Unused, Seed::Coordinate(4)]),
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
