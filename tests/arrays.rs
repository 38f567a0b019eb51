//! Array coordinates and families of bodies: an N-link planar pendulum declared in a few lines,
//! against the double pendulum declared body by body (N = 2) and against energy conservation
//! (N = 8); a family of forces against the same forces written one by one.

use lagrange::prelude::*;

#[mechanism]
pub mod chain2 {
    pub const LINKS: usize = 2;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    /// Link i hangs from link i − 1 (from the pivot for i = 0).
    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
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
pub mod chain8 {
    pub const LINKS: usize = 8;

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
        let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
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
pub mod double_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct DoublePendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
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

    #[force(on = bob1)]
    fn drag1() -> Vec2 {
        bob1_dot * (-c)
    }

    #[force(on = bob2)]
    fn drag2() -> Vec2 {
        bob2_dot * (-c)
    }
}

/// A cart (scalar coordinate) carrying a chain of three links (array coordinate), with linear
/// drag on every bob as a family of forces.
#[mechanism]
pub mod cart_chain {
    pub struct Coords {
        pub x: f64,
        pub theta: [f64; 3],
    }

    pub struct CartChain {
        pub cart_mass: f64,
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }

    #[particle(mass = cart_mass)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = m, count = 3)]
    fn bob(i: usize) -> Vec2 {
        let pivot = if i == 0 { cart } else { bob[i - 1] };
        pivot + vec2(theta[i].sin(), -theta[i].cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = bob, count = 3)]
    fn drag(i: usize) -> Vec2 {
        bob_dot[i] * (-c)
    }
}

#[mechanism]
pub mod cart_chain_by_hand {
    pub struct Coords {
        pub x: f64,
        pub theta0: f64,
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct CartChain {
        pub cart_mass: f64,
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }

    #[particle(mass = cart_mass)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = m)]
    fn bob0() -> Vec2 {
        cart + vec2(theta0.sin(), -theta0.cos()) * l
    }

    #[particle(mass = m)]
    fn bob1() -> Vec2 {
        bob0 + vec2(theta1.sin(), -theta1.cos()) * l
    }

    #[particle(mass = m)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = bob0)]
    fn drag0() -> Vec2 {
        bob0_dot * (-c)
    }

    #[force(on = bob1)]
    fn drag1() -> Vec2 {
        bob1_dot * (-c)
    }

    #[force(on = bob2)]
    fn drag2() -> Vec2 {
        bob2_dot * (-c)
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn two_link_chain_is_the_double_pendulum() {
    let (m, l, g) = (1.3, 0.7, 9.81);
    let chain = chain2::Chain { m, l, g };
    let double = double_pendulum::DoublePendulum { m, l, g, c: 0.0 };
    for (q, v) in [
        ([0.7, -1.2], [1.1, -0.4]),
        ([2.5, 0.1], [-3.0, 2.0]),
        ([0.0, 0.0], [0.0, 0.0]),
    ] {
        let s = chain2::State::new(
            0.0,
            chain2::Coords { theta: q },
            chain2::Coords { theta: v },
        );
        let d = double_pendulum::State::new(
            0.0,
            double_pendulum::Coords {
                theta1: q[0],
                theta2: q[1],
            },
            double_pendulum::Coords {
                theta1: v[0],
                theta2: v[1],
            },
        );
        let a = chain.accelerations(&s).unwrap().theta;
        let b = double.accelerations(&d).unwrap();
        assert!(
            close(a[0], b.theta1) && close(a[1], b.theta2),
            "{a:?} vs {b:?}"
        );
        assert!(close(chain.energy(&s).unwrap(), double.energy(&d).unwrap()));
        let bodies = chain.bodies(&s);
        let by_name = double.bodies(&d);
        assert!(close(bodies.bob[1].x, by_name.bob2.x) && close(bodies.bob[1].y, by_name.bob2.y));
    }
    // Names of array elements in messages and the flat order of `to_array`.
    assert_eq!(
        <chain2::Coords as Coordinates<2>>::NAMES,
        ["theta[0]", "theta[1]"]
    );
    assert_eq!(chain2::DOF, 2);
}

#[test]
fn eight_link_chain_conserves_energy() {
    let sys = chain8::Chain {
        m: 1.0,
        l: 0.5,
        g: 9.81,
    };
    let theta: [f64; 8] = std::array::from_fn(|j| 0.4 * ((j as f64) * 0.9).sin());
    let mut s = chain8::State::at_rest(chain8::Coords { theta });
    let e0 = sys.energy(&s).unwrap();
    let mut worst = 0.0f64;
    for _ in 0..2000 {
        sys.step::<Rk4>(&mut s, 1e-3).unwrap();
        worst = worst.max((sys.energy(&s).unwrap() - e0).abs());
    }
    // RK4's energy error over 2 s at h = 1e-3 is O(h⁴) times the motion's time scales
    // (√(l/g) ≈ 0.23 s): about 1e-9 relative here; 1e-7 leaves room without hiding a wrong term
    // (a wrong mass-matrix or velocity-product term drifts at O(1)).
    let scale = e0.abs().max(1.0);
    assert!(worst / scale < 1e-7, "energy drift {worst:e} of {e0}");
    assert!(
        s.q.theta.iter().any(|&a| (a - theta[0]).abs() > 1e-3),
        "it moved"
    );
}

#[test]
fn family_of_forces_equals_forces_written_one_by_one() {
    let (cart_mass, m, l, g, c) = (2.0, 0.5, 0.4, 9.81, 0.3);
    let family = cart_chain::CartChain {
        cart_mass,
        m,
        l,
        g,
        c,
    };
    let by_hand = cart_chain_by_hand::CartChain {
        cart_mass,
        m,
        l,
        g,
        c,
    };
    let (q, v) = ([0.1, 0.4, -0.8, 1.5], [0.3, -1.0, 0.5, 2.0]);
    let s = cart_chain::State::new(
        0.0,
        cart_chain::Coords {
            x: q[0],
            theta: [q[1], q[2], q[3]],
        },
        cart_chain::Coords {
            x: v[0],
            theta: [v[1], v[2], v[3]],
        },
    );
    let h = cart_chain_by_hand::State::new(
        0.0,
        <cart_chain_by_hand::Coords as Coordinates<4>>::from_array(q),
        <cart_chain_by_hand::Coords as Coordinates<4>>::from_array(v),
    );
    let a = family.accelerations(&s).unwrap().to_array();
    let b = by_hand.accelerations(&h).unwrap().to_array();
    for j in 0..4 {
        assert!(close(a[j], b[j]), "{a:?} vs {b:?}");
    }
    assert_eq!(s.q.to_array(), q);
    let velocities = family.body_velocities(&s);
    let by_name = by_hand.body_velocities(&h);
    assert!(close(velocities.bob[2].x, by_name.bob2.x));
}
