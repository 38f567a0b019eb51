//! Mechanisms whose bodies are written as an earlier body plus a displacement are assembled as a
//! tree, seeded body by body (`lagrange::tree`); the same mechanisms written so that the macro cannot
//! see the structure (the parent inside a product, `bob1 * 1.0`) take the dense pass. Both must give
//! the same mass matrix, forces and accelerations.

use lagrange::prelude::*;

/// A double pendulum hung from a support that moves in time, with a spring from the second bob to
/// a point carried by the first (a potential naming bodies), drag on the second bob and a motor
/// torque on the first joint; with `$scale` the second bob names the first inside a product.
macro_rules! driven_double_pendulum {
    ($name:ident $(, $scale:literal)?) => {
        #[mechanism]
        pub mod $name {
            pub struct Coords {
                pub theta1: f64,
                pub theta2: f64,
                pub r: f64,
            }
            pub struct Params {
                pub m1: f64,
                pub m2: f64,
                pub l1: f64,
                pub k: f64,
                pub c: f64,
                pub a: f64,
                pub w: f64,
                pub g: f64,
                pub tau: f64,
            }
            #[particle(mass = m1)]
            fn bob1() -> Vec2 {
                vec2(a * (w * t).sin() + l1 * theta1.sin(), -l1 * theta1.cos())
            }
            /// The second arm's length is a coordinate too: two seeds for this body.
            #[particle(mass = m2)]
            fn bob2() -> Vec2 {
                bob1 $(* $scale)? + vec2(theta2.sin(), -theta2.cos()) * r
            }
            #[point]
            fn anchor() -> Vec2 {
                bob1 + vec2(0.0, -0.2)
            }
            #[potential]
            fn spring() -> f64 {
                (bob2 - anchor).norm_squared() * (0.5 * k) + (r - 1.0) * (r - 1.0) * k
            }
            #[gravity]
            fn down() -> Vec2 {
                vec2(0.0, -g)
            }
            #[force(on = bob2)]
            fn drag() -> Vec2 {
                bob2_dot * (-c)
            }
            #[generalized_force(on = theta1)]
            fn motor() -> f64 {
                tau - theta1_dot * 0.1
            }
        }
    };
}

driven_double_pendulum!(as_tree);
driven_double_pendulum!(dense, 1.0);

// The tree forms are trees: 3 coordinates, 6 rows, 2 seeds (bob2's angle and arm), 3 bodies; 5
// links seeded one coordinate each.
const _: usize = <as_tree::Params as lagrange::tree::Tree<3, 6, 2, 3>>::BODIES.len();
const _: usize = <family_chain::Chain as lagrange::tree::Tree<5, 10, 1, 5>>::BODIES.len();

/// A chain as a family, against the same chain with every link's parent inside a product.
#[mechanism]
pub mod family_chain {
    pub const LINKS: usize = 5;
    pub struct Coords {
        pub theta: [f64; LINKS],
    }
    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * (l * (1.0 + 0.1 * i as f64));
        if i == 0 {
            link
        } else {
            bob[i - 1] + link
        }
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod dense_chain {
    pub const LINKS: usize = 5;
    pub struct Coords {
        pub theta: [f64; LINKS],
    }
    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * (l * (1.0 + 0.1 * i as f64));
        if i == 0 {
            link
        } else {
            bob[i - 1] * 1.0 + link
        }
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// States spread over the configuration space.
fn states<const N: usize>() -> impl Iterator<Item = (f64, [f64; N], [f64; N])> {
    (0..7).map(|k| {
        let k = k as f64;
        (
            0.3 * k,
            std::array::from_fn(|j| 0.4 + 0.9 * (1.7 * k + j as f64).sin()),
            std::array::from_fn(|j| 1.3 * (0.8 * k - 2.0 * j as f64).cos()),
        )
    })
}

/// Entries of order 1–30 summed in a different order by the two assemblies: a few ulps.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + b.abs())
}

#[test]
fn a_rheonomic_tree_with_potentials_forces_and_a_point_equals_the_dense_assembly() {
    let [m1, m2, l1, k, c, a, w, g, tau] = [1.0, 0.7, 1.1, 3.0, 0.4, 0.3, 2.0, 9.81, 0.5];
    let tree = as_tree::Params {
        m1,
        m2,
        l1,
        k,
        c,
        a,
        w,
        g,
        tau,
    };
    let dense = dense::Params {
        m1,
        m2,
        l1,
        k,
        c,
        a,
        w,
        g,
        tau,
    };
    for (t, q, v) in states::<3>() {
        let s1 = as_tree::State::new(
            t,
            as_tree::Coords::from_array(q),
            as_tree::Coords::from_array(v),
        );
        let s2 = dense::State::new(
            t,
            dense::Coords::from_array(q),
            dense::Coords::from_array(v),
        );
        let (m_tree, m_dense) = (
            tree.mass_matrix(&s1).unwrap(),
            dense.mass_matrix(&s2).unwrap(),
        );
        for (x, y) in m_tree.iter().zip(m_dense.iter()) {
            assert!(close(*x, *y), "M: {m_tree} vs {m_dense}");
        }
        let (f_tree, f_dense) = (
            tree.generalized_forces(&s1).unwrap().to_array(),
            dense.generalized_forces(&s2).unwrap().to_array(),
        );
        let (a_tree, a_dense) = (
            tree.accelerations(&s1).unwrap().to_array(),
            dense.accelerations(&s2).unwrap().to_array(),
        );
        for j in 0..3 {
            assert!(close(f_tree[j], f_dense[j]), "F: {f_tree:?} vs {f_dense:?}");
            // Through the solve: the mass matrix's condition number (below 100 here) times the
            // entries' rounding.
            assert!((a_tree[j] - a_dense[j]).abs() <= 1e-10 * (1.0 + a_dense[j].abs()));
        }
    }
}

/// The trees above move each body by coordinates of its own, so their `accelerations` come from
/// the articulated-body recursion (`lagrange::tree::accelerations`), not from a solve with M: the
/// comparisons with the dense pass test the recursion.
#[test]
fn these_trees_take_the_articulated_recursion() {
    use lagrange::tree::Tree;
    const {
        assert!(<family_chain::Chain as Tree<5, 10, 1, 5>>::JOINTS);
        assert!(<as_tree::Params as Tree<3, 6, 2, 3>>::JOINTS);
    }
}

#[test]
fn a_family_read_member_by_member_equals_the_dense_assembly() {
    let (m, l, g) = (1.0, 0.5, 9.81);
    let tree = family_chain::Chain { m, l, g };
    let dense = dense_chain::Chain { m, l, g };
    for (t, q, v) in states::<5>() {
        let s1 = family_chain::State::new(
            t,
            family_chain::Coords { theta: q },
            family_chain::Coords { theta: v },
        );
        let s2 = dense_chain::State::new(
            t,
            dense_chain::Coords { theta: q },
            dense_chain::Coords { theta: v },
        );
        let (m_tree, m_dense) = (
            tree.mass_matrix(&s1).unwrap(),
            dense.mass_matrix(&s2).unwrap(),
        );
        for (x, y) in m_tree.iter().zip(m_dense.iter()) {
            assert!(close(*x, *y), "M: {m_tree} vs {m_dense}");
        }
        let (a_tree, a_dense) = (
            tree.accelerations(&s1).unwrap().theta,
            dense.accelerations(&s2).unwrap().theta,
        );
        for j in 0..5 {
            // A 5-link chain's mass matrix has condition number ≈ 10³ at these states.
            assert!((a_tree[j] - a_dense[j]).abs() <= 1e-9 * (1.0 + a_dense[j].abs()));
        }
    }
}

/// A branching tree in space: a hub on a plane, two arms hung from it (one with a second link) and
/// drag on the last, so bodies have siblings and pairs of bodies on different branches do not
/// couple. (The drag is a force: without one, these positions would be derived in closed form.)
macro_rules! branching {
    ($name:ident $(, $scale:literal)?) => {
        #[mechanism]
        pub mod $name {
            pub struct Coords {
                pub x: f64,
                pub y: f64,
                pub a: f64,
                pub b: f64,
                pub c: f64,
            }
            pub struct Params {
                pub m: f64,
                pub l: f64,
                pub g: f64,
                pub k: f64,
            }
            #[particle(mass = m * 3.0)]
            fn hub() -> Vec3 {
                vec3(x, y, 0.0)
            }
            #[force(on = tip)]
            fn drag() -> Vec3 {
                -tip_dot * k
            }
            #[particle(mass = m)]
            fn left() -> Vec3 {
                hub $(* $scale)? + vec3(a.sin(), 0.0, -a.cos()) * l
            }
            #[particle(mass = m * 0.5)]
            fn right() -> Vec3 {
                hub + vec3(0.0, b.sin(), -b.cos()) * l
            }
            #[particle(mass = m * 2.0)]
            fn tip() -> Vec3 {
                vec3(c.sin() * c.cos(), c.cos(), -c.sin()) * (0.5 * l) + left
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
        }
    };
}

branching!(branching_tree);
branching!(branching_dense, 1.0);

// Five coordinates, twelve rows, two seeds (the hub), four bodies.
const _: usize = <branching_tree::Params as lagrange::tree::Tree<5, 12, 2, 4>>::BODIES.len();

#[test]
fn a_branching_tree_in_space_equals_the_dense_assembly() {
    let (m, l, g, k) = (1.0, 0.7, 9.81, 0.3);
    let tree = branching_tree::Params { m, l, g, k };
    let dense = branching_dense::Params { m, l, g, k };
    for (t, q, v) in states::<5>() {
        let s1 = branching_tree::State::new(
            t,
            branching_tree::Coords::from_array(q),
            branching_tree::Coords::from_array(v),
        );
        let s2 = branching_dense::State::new(
            t,
            branching_dense::Coords::from_array(q),
            branching_dense::Coords::from_array(v),
        );
        let (m_tree, m_dense) = (
            tree.mass_matrix(&s1).unwrap(),
            dense.mass_matrix(&s2).unwrap(),
        );
        for (x, y) in m_tree.iter().zip(m_dense.iter()) {
            assert!(close(*x, *y), "M: {m_tree} vs {m_dense}");
        }
        // The two arms are on different branches: their angles do not couple.
        assert_eq!(m_tree[(2, 3)], 0.0);
        let (a_tree, a_dense) = (
            tree.accelerations(&s1).unwrap().to_array(),
            dense.accelerations(&s2).unwrap().to_array(),
        );
        for j in 0..5 {
            // Condition number of M below 10³ at these states.
            assert!((a_tree[j] - a_dense[j]).abs() <= 1e-10 * (1.0 + a_dense[j].abs()));
        }
    }
}
