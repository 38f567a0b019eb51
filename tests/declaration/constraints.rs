//! Holonomic, velocity, unilateral and time-dependent constraints, and Coulomb friction.

use super::close;
use lagrange::model::Model;
use lagrange::prelude::*;

#[mechanism]
pub mod cartesian_pendulum {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct CartesianPendulum {
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

    /// The rod keeps the bob at distance l from the pivot.
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

#[test]
fn holonomic_constraint_is_a_pendulum_in_cartesian_coordinates() {
    use cartesian_pendulum::{CartesianPendulum, Coords, State};
    let p = CartesianPendulum {
        m: 0.8,
        l: 1.5,
        g: 9.81,
    };
    let (theta, omega) = (0.5_f64, 1.3);
    let (sin, cos) = theta.sin_cos();
    let q = Coords {
        x: p.l * sin,
        y: -p.l * cos,
    };
    let v = Coords {
        x: p.l * omega * cos,
        y: p.l * omega * sin,
    };
    let mut s = State::new(0.0, q, v);
    // r̈ = l θ̈ (cos θ, sin θ) + l θ̇² (−sin θ, cos θ), θ̈ = −(g/l) sin θ. The KKT solve adds a
    // Schur complement to the few flops of the unconstrained case: still a few ulps of |r̈| ~ 10.
    let a = p.accelerations(&s).unwrap();
    let theta_dd = -p.g / p.l * sin;
    let want = [
        p.l * (theta_dd * cos - omega * omega * sin),
        p.l * (theta_dd * sin + omega * omega * cos),
    ];
    assert!(
        close(a.x, want[0]) && close(a.y, want[1]),
        "{a:?} vs {want:?}"
    );
    for _ in 0..1000 {
        p.step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    // Projected after every step: on the circle to round-off.
    assert!(((s.q.x * s.q.x + s.q.y * s.q.y).sqrt() - p.l).abs() < 1e-12);
}

#[mechanism]
pub mod rail {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Rail {
        pub m: f64,
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

    /// The bead may only move along (1, 1).
    #[velocity_constraint]
    fn diagonal() -> f64 {
        x_dot - y_dot
    }
}

#[test]
fn velocity_constraint_guides_the_motion() {
    use rail::{Coords, Rail, State};
    let p = Rail { m: 2.0, g: 9.81 };
    let s = State::new(0.0, Coords { x: 0.3, y: -0.2 }, Coords { x: 0.7, y: 0.7 });
    // Along (1, 1)/√2 gravity's component is −g/√2: ẍ = ÿ = −g/2.
    let a = p.accelerations(&s).unwrap();
    assert!(close(a.x, -p.g / 2.0) && close(a.y, -p.g / 2.0), "{a:?}");
}

#[mechanism]
pub mod sliding_block {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct SlidingBlock {
        pub m: f64,
        pub g: f64,
        pub mu: f64,
    }

    #[particle(mass = m)]
    fn block() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The floor can only push up.
    #[unilateral]
    fn floor() -> f64 {
        block.y
    }

    /// Coulomb friction at the floor contact.
    #[friction(on = floor, kinetic = mu, stiction = mu * 1.5)]
    fn slide() -> f64 {
        block_dot.x
    }
}

#[test]
fn unilateral_contact_with_coulomb_friction() {
    use sliding_block::{Coords, SlidingBlock, State};
    let p = SlidingBlock {
        m: 1.2,
        g: 9.81,
        mu: 0.3,
    };
    // Sliding to the right on the floor: ẍ = −μ g, ÿ = 0 (normal force m g).
    let s = State::new(0.0, Coords { x: 0.0, y: 0.0 }, Coords { x: 2.0, y: 0.0 });
    let a = p.accelerations(&s).unwrap();
    assert!(close(a.x, -p.mu * p.g) && close(a.y, 0.0), "{a:?}");
    // At rest on the floor: static friction holds, nothing moves.
    let a = p
        .accelerations(&State::at_rest(Coords { x: 0.0, y: 0.0 }))
        .unwrap();
    assert!(close(a.x, 0.0) && close(a.y, 0.0), "{a:?}");
    // Above the floor: free fall.
    let a = p
        .accelerations(&State::at_rest(Coords { x: 0.0, y: 1.0 }))
        .unwrap();
    assert!(close(a.x, 0.0) && close(a.y, -p.g), "{a:?}");
    let bad = SlidingBlock { mu: -0.1, ..p };
    assert!(bad.accelerations(&s).is_err());
}

#[mechanism]
pub mod driven_guide {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct DrivenGuide {
        pub m: f64,
        pub a: f64,
        pub w: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn ball() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// A vertical guide moved as a sin(w t): a rheonomic constraint.
    #[constraint]
    fn guide() -> f64 {
        x - a * (w * t).sin()
    }
}

#[test]
fn rheonomic_constraint_with_t() {
    use driven_guide::{Coords, DrivenGuide, State};
    let p = DrivenGuide {
        m: 1.0,
        a: 0.2,
        w: 5.0,
        g: 9.81,
    };
    const { assert!(<DrivenGuide as Model<2, 2>>::RHEONOMIC) };
    let t = 0.3;
    let (x, x_dot) = (p.a * (p.w * t).sin(), p.a * p.w * (p.w * t).cos());
    let s = State::new(t, Coords { x, y: 1.0 }, Coords { x: x_dot, y: -0.5 });
    // ẍ follows the guide, −a w² sin(w t); ÿ = −g.
    let a = p.accelerations(&s).unwrap();
    assert!(
        close(a.x, -p.a * p.w * p.w * (p.w * t).sin()) && close(a.y, -p.g),
        "{a:?}"
    );
}
