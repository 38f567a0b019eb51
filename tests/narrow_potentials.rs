//! Potentials declared one by one, or a potential written as a sum, have their gradients taken
//! part by part (`Model::potential_gradient`): derived on the expression tree where the macro reads
//! it, otherwise on dual numbers seeded on each part's own coordinates. The same physics written as
//! one potential over every coordinate, passed through a function (which the macro reads neither
//! as a tree nor term by term), takes the dense gradient: they must agree to round-off — on the dense
//! pass, on the prepared pass of an affine mechanism, on the tree pass, and through the dual
//! numbers of Radau5's Newton matrix.

use lagrange::prelude::*;

/// Four masses on a line, the first tied to a wall, neighbours by springs, the last one in a
/// quartic well: each spring a potential of its own, naming elements of the array coordinate.
#[mechanism]
pub mod springs_apart {
    pub const MASSES: usize = 4;
    pub struct Coords {
        pub x: [f64; MASSES],
    }
    pub struct Chain {
        pub m: f64,
        pub k: f64,
        pub k_wall: f64,
        pub a: f64,
    }
    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(x[i], 0.0)
    }
    #[potential]
    fn wall() -> f64 {
        k_wall * x[0] * x[0] / 2.0
    }
    #[potential]
    fn first() -> f64 {
        k * (x[1] - x[0]).powi(2) / 2.0
    }
    #[potential]
    fn second() -> f64 {
        k * (x[2] - x[1]).powi(2) / 2.0
    }
    #[potential]
    fn third() -> f64 {
        k * (x[3] - x[2]).powi(2) / 2.0
    }
    #[potential]
    fn well() -> f64 {
        a * x[3].powi(4)
    }
}

/// The same, one potential.
#[mechanism]
pub mod springs_together {
    pub const MASSES: usize = 4;
    pub struct Coords {
        pub x: [f64; MASSES],
    }
    pub struct Chain {
        pub m: f64,
        pub k: f64,
        pub k_wall: f64,
        pub a: f64,
    }
    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(x[i], 0.0)
    }
    #[potential]
    fn springs() -> f64 {
        // Through a function: one term, not read, on every coordinate (the dense gradient, for
        // reference).
        let total = k_wall * x[0] * x[0] / 2.0
            + k * (x[1] - x[0]).powi(2) / 2.0
            + k * (x[2] - x[1]).powi(2) / 2.0
            + k * (x[3] - x[2]).powi(2) / 2.0
            + a * x[3].powi(4);
        std::convert::identity(total)
    }
}

/// The same, one potential written as a sum with constant factors around inner sums: read term by
/// term (k/2 and the division distributed over the springs), each term on its own coordinates.
#[mechanism]
pub mod springs_summed {
    pub const MASSES: usize = 4;
    pub struct Coords {
        pub x: [f64; MASSES],
    }
    pub struct Chain {
        pub m: f64,
        pub k: f64,
        pub k_wall: f64,
        pub a: f64,
    }
    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(x[i], 0.0)
    }
    #[potential]
    fn springs() -> f64 {
        let (d1, d2) = (x[1] - x[0], x[2] - x[1]);
        let d3 = x[3] - x[2];
        k_wall * x[0] * x[0] / 2.0 + k * (d1 * d1 + d2 * d2 + d3 * d3) / 2.0 - a * -x[3].powi(4)
    }
}

/// A double pendulum with a torsion spring at each joint: a tree of translations, each spring a
/// potential in one angle.
#[mechanism]
pub mod sprung_apart {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct Sprung {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c1: f64,
        pub c2: f64,
    }
    #[particle(mass = m)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l
    }
    #[particle(mass = m)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[potential]
    fn shoulder() -> f64 {
        c1 * theta1 * theta1 / 2.0
    }
    #[potential]
    fn elbow() -> f64 {
        c2 * (theta2 - 0.3).powi(2) / 2.0
    }
}

/// The same, one potential.
#[mechanism]
pub mod sprung_together {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct Sprung {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c1: f64,
        pub c2: f64,
    }
    #[particle(mass = m)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l
    }
    #[particle(mass = m)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[potential]
    fn springs() -> f64 {
        let total = c1 * theta1 * theta1 / 2.0 + c2 * (theta2 - 0.3).powi(2) / 2.0;
        std::convert::identity(total)
    }
}

/// A cart on a rail carrying a swinging bar (a rigid body: the dense pass), and a slider on a
/// second rail tied to the cart by a spring written between the two bodies; a torsion spring on
/// the bar.
#[mechanism]
pub mod cart_apart {
    pub struct Coords {
        pub x: f64,
        pub theta: f64,
        pub s: f64,
    }
    pub struct Cart {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub k: f64,
        pub c: f64,
    }
    #[particle(mass = m)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn bar() -> Planar {
        planar(cart + vec2(theta.sin(), -theta.cos()) * (l / 2.0), theta)
    }
    #[particle(mass = m)]
    fn slider() -> Vec2 {
        vec2(s, 1.0)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[potential]
    fn tie() -> f64 {
        k * (slider.x - cart.x - 0.5).powi(2) / 2.0
    }
    #[potential]
    fn torsion() -> f64 {
        c * theta * theta / 2.0
    }
}

/// The same, one potential.
#[mechanism]
pub mod cart_together {
    pub struct Coords {
        pub x: f64,
        pub theta: f64,
        pub s: f64,
    }
    pub struct Cart {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub k: f64,
        pub c: f64,
    }
    #[particle(mass = m)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn bar() -> Planar {
        planar(cart + vec2(theta.sin(), -theta.cos()) * (l / 2.0), theta)
    }
    #[particle(mass = m)]
    fn slider() -> Vec2 {
        vec2(s, 1.0)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[potential]
    fn springs() -> f64 {
        let total = k * (slider.x - cart.x - 0.5).powi(2) / 2.0 + c * theta * theta / 2.0;
        std::convert::identity(total)
    }
}

/// Whether `M` takes its potential's gradient potential by potential (`Some`) — otherwise the
/// comparisons below would compare the dense gradient with itself.
fn narrow<M: lagrange::__private::Model<N, K>, const N: usize, const K: usize>(sys: &M) -> bool {
    let rows = [Some(nalgebra::SVector::<f64, N>::zeros()); K];
    sys.potential_gradient(0.0, &[0.0; N], &[0.0; K], &rows)
        .is_some()
}

/// Agreement to round-off: the same sums in a different order, relative to the largest entry
/// (the accelerations here are O(1–100); 1e-13 of it is a few hundred ulps).
fn assert_close(a: &[f64], b: &[f64], what: &str) {
    let scale = a.iter().chain(b).fold(1.0f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-13 * scale, "{what}: {a:?} vs {b:?}");
    }
}

fn chain_state(i: usize) -> [[f64; 4]; 2] {
    let f = i as f64;
    [
        [
            0.3 * (0.7 * f).sin(),
            1.0 + 0.2 * f.cos(),
            2.1 - 0.1 * f,
            3.0 + (1.1 * f).sin(),
        ],
        [(0.9 * f).cos(), 0.1 * f, -0.2, (2.0 * f).sin()],
    ]
}

fn apart_params() -> springs_apart::Chain {
    springs_apart::Chain {
        m: 0.5,
        k: 30.0,
        k_wall: 2.0,
        a: 0.7,
    }
}

#[test]
fn separate_springs_agree_with_one_potential() {
    let apart = apart_params();
    let together = springs_together::Chain {
        m: 0.5,
        k: 30.0,
        k_wall: 2.0,
        a: 0.7,
    };
    assert!(narrow(&apart) && !narrow(&together));
    assert!(narrow(&springs_summed::Chain {
        m: 0.5,
        k: 30.0,
        k_wall: 2.0,
        a: 0.7
    }));
    for i in 0..10 {
        let [q, v] = chain_state(i);
        let a = apart
            .accelerations(&springs_apart::State::new(
                0.0,
                springs_apart::Coords { x: q },
                springs_apart::Coords { x: v },
            ))
            .unwrap();
        let b = together
            .accelerations(&springs_together::State::new(
                0.0,
                springs_together::Coords { x: q },
                springs_together::Coords { x: v },
            ))
            .unwrap();
        assert_close(&a.x, &b.x, "dense pass");
        // The chain is affine: through a validated handle, the prepared pass.
        let handle = apart_params().validated().unwrap();
        let a = handle
            .accelerations(&springs_apart::State::new(
                0.0,
                springs_apart::Coords { x: q },
                springs_apart::Coords { x: v },
            ))
            .unwrap();
        assert_close(&a.x, &b.x, "prepared pass");
        let summed = springs_summed::Chain {
            m: 0.5,
            k: 30.0,
            k_wall: 2.0,
            a: 0.7,
        };
        let c = summed
            .accelerations(&springs_summed::State::new(
                0.0,
                springs_summed::Coords { x: q },
                springs_summed::Coords { x: v },
            ))
            .unwrap();
        assert_close(&c.x, &b.x, "one potential read term by term");
    }
}

#[test]
fn separate_joint_springs_agree_with_one_potential_on_the_tree() {
    let apart = sprung_apart::Sprung {
        m: 1.0,
        l: 0.8,
        g: 9.81,
        c1: 3.0,
        c2: 5.0,
    };
    let together = sprung_together::Sprung {
        m: 1.0,
        l: 0.8,
        g: 9.81,
        c1: 3.0,
        c2: 5.0,
    };
    assert!(narrow(&apart) && !narrow(&together));
    for i in 0..10 {
        let f = i as f64;
        let (q, v) = ([0.3 * f - 1.0, 0.7 * f.sin()], [f.cos(), -0.5 + 0.1 * f]);
        let a = apart
            .accelerations(&sprung_apart::State::new(
                0.0,
                sprung_apart::Coords {
                    theta1: q[0],
                    theta2: q[1],
                },
                sprung_apart::Coords {
                    theta1: v[0],
                    theta2: v[1],
                },
            ))
            .unwrap();
        let b = together
            .accelerations(&sprung_together::State::new(
                0.0,
                sprung_together::Coords {
                    theta1: q[0],
                    theta2: q[1],
                },
                sprung_together::Coords {
                    theta1: v[0],
                    theta2: v[1],
                },
            ))
            .unwrap();
        assert_close(&[a.theta1, a.theta2], &[b.theta1, b.theta2], "tree pass");
    }
}

#[test]
fn separate_springs_differentiate_like_one_potential() {
    // Radau5's Newton matrix differentiates q̈ with dual numbers, so the narrow gradients run on
    // duals of duals. Same settings, the same steps up to round-off: the end states agree far
    // below the tolerance.
    let apart = springs_apart::Chain {
        m: 0.5,
        k: 30.0,
        k_wall: 2.0,
        a: 0.7,
    };
    let together = springs_together::Chain {
        m: 0.5,
        k: 30.0,
        k_wall: 2.0,
        a: 0.7,
    };
    let [q, v] = chain_state(3);
    let mut a = springs_apart::State::new(
        0.0,
        springs_apart::Coords { x: q },
        springs_apart::Coords { x: v },
    );
    let mut b = springs_together::State::new(
        0.0,
        springs_together::Coords { x: q },
        springs_together::Coords { x: v },
    );
    let settings = Radau5::new(1e-9, 1e-9);
    apart
        .integrate(settings, &mut a, 1.0, &mut [], |_| {})
        .unwrap();
    together
        .integrate(settings, &mut b, 1.0, &mut [], |_| {})
        .unwrap();
    for j in 0..4 {
        assert!((a.q.x[j] - b.q.x[j]).abs() < 1e-10, "{a:?} vs {b:?}");
    }
}

#[test]
fn a_spring_between_bodies_agrees_with_one_potential() {
    let apart = cart_apart::Cart {
        m: 1.0,
        l: 0.6,
        g: 9.81,
        k: 12.0,
        c: 2.0,
    };
    let together = cart_together::Cart {
        m: 1.0,
        l: 0.6,
        g: 9.81,
        k: 12.0,
        c: 2.0,
    };
    assert!(narrow(&apart) && !narrow(&together));
    for i in 0..10 {
        let f = i as f64;
        let (q, v) = (
            [0.2 * f - 1.0, 0.7 * f.sin(), 1.5 - 0.1 * f],
            [f.cos(), -0.5 + 0.1 * f, 0.3],
        );
        let a = apart
            .accelerations(&cart_apart::State::new(
                0.0,
                cart_apart::Coords {
                    x: q[0],
                    theta: q[1],
                    s: q[2],
                },
                cart_apart::Coords {
                    x: v[0],
                    theta: v[1],
                    s: v[2],
                },
            ))
            .unwrap();
        let b = together
            .accelerations(&cart_together::State::new(
                0.0,
                cart_together::Coords {
                    x: q[0],
                    theta: q[1],
                    s: q[2],
                },
                cart_together::Coords {
                    x: v[0],
                    theta: v[1],
                    s: v[2],
                },
            ))
            .unwrap();
        assert_close(&[a.x, a.theta, a.s], &[b.x, b.theta, b.s], "bodies named");
    }
}
