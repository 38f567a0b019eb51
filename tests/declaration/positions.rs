//! Particles and positions: the double pendulum of the README, positions that name `t`, and
//! vectors scaled from the left.

use super::close;
use lagrange::model::Model;
use lagrange::prelude::*;

#[mechanism]
pub mod double_pendulum {
    /// Generalized coordinates: one field per degree of freedom.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    /// Parameters, fixed for one simulation.
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn readme() -> Result<(), lagrange::Error> {
    use double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let mut s = State::at_rest(Coords {
        theta1: 1.0,
        theta2: 0.5,
    });
    let qdd = sys.accelerations(&s)?;
    let e0 = sys.energy(&s)?;
    for _ in 0..1000 {
        sys.step::<Rk4>(&mut s, 1e-3)?;
    }
    // RK4, h = 1e-3, frequencies ~3/s: energy error ≲ 1e-9 over 1000 steps.
    assert!((sys.energy(&s)? - e0).abs() < 1e-8);
    assert!(qdd.theta1 < 0.0);
    Ok(())
}

#[test]
fn double_pendulum_matches_closed_form_and_bodies_are_named() {
    use double_pendulum::{Coords, DoublePendulum, State};
    let p = DoublePendulum {
        m1: 1.3,
        m2: 0.7,
        l1: 1.1,
        l2: 0.9,
        g: 9.81,
    };
    let (q, v) = ([0.3, -1.2], [0.5, 2.0]);
    let s = State::new(
        0.0,
        Coords {
            theta1: q[0],
            theta2: q[1],
        },
        Coords {
            theta1: v[0],
            theta2: v[1],
        },
    );
    let got = p.accelerations(&s).unwrap();
    // Closed form (myphysicslab's double pendulum).
    let d = q[0] - q[1];
    let den = p.m1 + p.m2 * d.sin().powi(2);
    let a1 = (p.m2 * p.g * q[1].sin() * d.cos()
        - p.m2 * d.sin() * (p.l1 * v[0] * v[0] * d.cos() + p.l2 * v[1] * v[1])
        - (p.m1 + p.m2) * p.g * q[0].sin())
        / (p.l1 * den);
    let a2 = ((p.m1 + p.m2)
        * (p.l1 * v[0] * v[0] * d.sin() - p.g * q[1].sin() + p.g * q[0].sin() * d.cos())
        + p.m2 * p.l2 * v[1] * v[1] * d.sin() * d.cos())
        / (p.l2 * den);
    assert!(
        close(got.theta1, a1) && close(got.theta2, a2),
        "{got:?} vs {a1}, {a2}"
    );

    let bodies = p.bodies(&s);
    assert!(close(bodies.bob1.x, p.l1 * q[0].sin()) && close(bodies.bob1.y, -p.l1 * q[0].cos()));
    let velocities = p.body_velocities(&s);
    // ṙ₁ = l₁ θ̇₁ (cos θ₁, sin θ₁).
    assert!(
        close(velocities.bob1.x, p.l1 * v[0] * q[0].cos())
            && close(velocities.bob1.y, p.l1 * v[0] * q[0].sin())
    );
    assert_eq!(double_pendulum::DOF, 2);
    const { assert!(!<DoublePendulum as Model<2, 4>>::RHEONOMIC) };
}

#[mechanism]
pub mod shaken_pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct ShakenPendulum {
        pub m: f64,
        pub l: f64,
        pub a: f64,
        pub w: f64,
        pub g: f64,
    }

    /// The support moves as a cos(w t) along x.
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(a * (w * t).cos() + l * theta.sin(), -l * theta.cos())
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn rheonomic_position_with_t() {
    use shaken_pendulum::{Coords, ShakenPendulum, State};
    let p = ShakenPendulum {
        m: 1.0,
        l: 0.9,
        a: 0.1,
        w: 7.0,
        g: 9.81,
    };
    const { assert!(<ShakenPendulum as Model<1, 2>>::RHEONOMIC) };
    for (t, theta, omega) in [(0.0, 0.3, 1.0), (0.7, -1.0, 0.4), (2.2, 2.0, -3.0)] {
        let s = State::new(t, Coords { theta }, Coords { theta: omega });
        // l θ̈ = a w² cos(w t) cos θ − g sin θ (independent of θ̇).
        let want = (p.a * p.w * p.w * (p.w * t).cos() * theta.cos() - p.g * theta.sin()) / p.l;
        let got = p.accelerations(&s).unwrap().theta;
        assert!(close(got, want), "{got} vs {want}");
    }
}

/// The double pendulum with every vector scaled from the left: a parameter (`l1 * v`), a float
/// literal times a parameter (`0.5 * l2 * v`, lifted like any literal), a scalar computed in the
/// function, and in space (`l1 * vec3(..)`).
#[mechanism]
pub mod left_scalars {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct LeftScalars {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        l1 * vec2(theta1.sin(), -theta1.cos())
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        let half = 0.5 * l2;
        bob1 + 2.0 * half * vec2(theta2.sin(), -theta2.cos())
    }

    #[point]
    fn shadow() -> Vec3 {
        l1 * vec3(theta1.sin(), 0.0, -theta1.cos())
    }

    #[gravity]
    fn down() -> Vec2 {
        g * vec2(0.0, -1.0)
    }
}

#[test]
fn scalars_multiply_vectors_from_the_left_in_declarations() {
    let left = left_scalars::LeftScalars {
        m1: 1.3,
        m2: 0.7,
        l1: 1.1,
        l2: 0.9,
        g: 9.81,
    };
    let right = double_pendulum::DoublePendulum {
        m1: left.m1,
        m2: left.m2,
        l1: left.l1,
        l2: left.l2,
        g: left.g,
    };
    let (q, v) = ([0.4, -1.2], [0.3, 2.1]);
    let sl = left_scalars::State::new(
        0.0,
        left_scalars::Coords::from_array(q),
        left_scalars::Coords::from_array(v),
    );
    let sr = double_pendulum::State::new(
        0.0,
        double_pendulum::Coords::from_array(q),
        double_pendulum::Coords::from_array(v),
    );
    let (al, ar) = (
        left.accelerations(&sl).unwrap().to_array(),
        right.accelerations(&sr).unwrap().to_array(),
    );
    for k in 0..2 {
        assert!(close(al[k], ar[k]), "{al:?} vs {ar:?}");
    }
    let shadow = left.bodies(&sl).shadow;
    assert!(close(shadow.x, left.l1 * q[0].sin()) && close(shadow.z, -left.l1 * q[0].cos()));
}
