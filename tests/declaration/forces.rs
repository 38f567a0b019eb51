//! Points and forces on them, generalized forces, potentials, and gravity fields in the plane and
//! in space.

use super::close;
use lagrange::model::Model;
use lagrange::prelude::*;

#[mechanism]
pub mod bar_on_spring {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct BarOnSpring {
        pub m: f64,
        pub i: f64,
        pub d: f64,
        pub k: f64,
        pub wall: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m, inertia = i)]
    fn bar() -> Planar {
        planar(vec2(theta.sin(), -theta.cos()) * d, theta)
    }

    /// The bar's far end, at 2d from the pivot.
    #[point]
    fn tip() -> Vec2 {
        bar.point(vec2(0.0, -d))
    }

    /// A horizontal spring from the tip to a wall at x = wall.
    #[force(on = tip)]
    fn spring() -> Vec2 {
        vec2((wall - tip.x) * k, 0.0)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn point_and_force_make_a_spring_to_a_wall() {
    use bar_on_spring::{BarOnSpring, Coords, State};
    let p = BarOnSpring {
        m: 1.0,
        i: 0.1,
        d: 0.5,
        k: 20.0,
        wall: 0.3,
        g: 9.81,
    };
    for theta in [-0.4, 0.2, 1.0] {
        let s = State::new(0.0, Coords { theta }, Coords { theta: 0.5 });
        let tip = p.bodies(&s).tip;
        assert!(close(tip.x, 2.0 * p.d * theta.sin()) && close(tip.y, -2.0 * p.d * theta.cos()));
        // Virtual work of F = k (wall − x_tip) x̂ at the tip, x_tip = 2d sin θ: Q = F · 2d cos θ.
        let q_spring = p.k * (p.wall - 2.0 * p.d * theta.sin()) * 2.0 * p.d * theta.cos();
        let want = (q_spring - p.m * p.g * p.d * theta.sin()) / (p.i + p.m * p.d * p.d);
        let got = p.accelerations(&s).unwrap().theta;
        assert!(close(got, want), "{got} vs {want}");
    }
}

#[mechanism]
pub mod damped_pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct DampedPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// Joint damping.
    #[generalized_force(on = theta)]
    fn damping() -> f64 {
        -c * theta_dot
    }
}

#[test]
fn generalized_force_damping_removes_energy_at_rate_c_theta_dot_squared() {
    use damped_pendulum::{Coords, DampedPendulum, State};
    let p = DampedPendulum {
        m: 1.0,
        l: 1.2,
        g: 9.81,
        c: 0.4,
    };
    let mut s = State::new(0.0, Coords { theta: 1.0 }, Coords { theta: 0.5 });
    // Instantaneously: dE/dt = m l² θ̇ θ̈ + m g l sin θ θ̇ = −c θ̇².
    let qdd = p.accelerations(&s).unwrap().theta;
    let (theta, omega) = (s.q.theta, s.v.theta);
    let rate = p.m * p.l * p.l * omega * qdd + p.m * p.g * p.l * theta.sin() * omega;
    assert!(close(rate, -p.c * omega * omega), "{rate}");
    // Over a run: E(T) − E(0) = −∫ c θ̇² dt, the integral by the trapezoid rule.
    let (h, steps) = (1e-3, 2000);
    let e0 = p.energy(&s).unwrap();
    let mut dissipated = 0.0;
    for _ in 0..steps {
        let before = p.c * s.v.theta * s.v.theta;
        p.step::<Rk4>(&mut s, h).unwrap();
        dissipated += 0.5 * h * (before + p.c * s.v.theta * s.v.theta);
    }
    let lost = e0 - p.energy(&s).unwrap();
    // Trapezoid error ≈ T h² max|d²(cθ̇²)/dt²| / 12 ≈ 2 · 1e-6 · 100 / 12 ≈ 2e-5; RK4's is far smaller.
    assert!(
        lost > 0.0 && (lost - dissipated).abs() < 5e-5,
        "lost {lost}, dissipated {dissipated}"
    );
}

#[mechanism]
pub mod anharmonic {
    pub struct Coords {
        pub x: f64,
    }

    pub struct Anharmonic {
        pub m: f64,
        pub k: f64,
        pub k4: f64,
    }

    #[particle(mass = m)]
    fn mass() -> Vec2 {
        vec2(x, 0.0)
    }

    #[potential]
    fn spring() -> f64 {
        k * x * x * 0.5
    }

    /// A quartic term; `powf`'s exponent stays an `f64`.
    #[potential]
    fn stiffening() -> f64 {
        k4 * x.powf(4.0) * 0.25
    }
}

#[test]
fn potentials_add_up() {
    use anharmonic::{Anharmonic, Coords, State};
    let p = Anharmonic {
        m: 2.0,
        k: 3.0,
        k4: 5.0,
    };
    let x = 0.7;
    let s = State::at_rest(Coords { x });
    let v = 0.5 * p.k * x * x + 0.25 * p.k4 * x.powi(4);
    assert!(close(p.potential_energy(&s).unwrap(), v));
    let want = -(p.k * x + p.k4 * x.powi(3)) / p.m;
    assert!(close(p.accelerations(&s).unwrap().x, want));
}

#[mechanism]
pub mod dragged_pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct DraggedPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// Linear drag on the bob.
    #[force(on = bob)]
    fn drag() -> Vec2 {
        bob_dot * (-c)
    }
}

#[test]
fn force_reading_body_velocity_is_linear_drag() {
    use dragged_pendulum::{Coords, DraggedPendulum, State};
    let p = DraggedPendulum {
        m: 0.5,
        l: 1.1,
        g: 9.81,
        c: 0.3,
    };
    for (theta, omega) in [(0.2, 1.5), (-1.3, -0.4)] {
        let s = State::new(0.0, Coords { theta }, Coords { theta: omega });
        // F = −c ṙ, ṙ = l θ̇ (cos θ, sin θ): Q = F · ∂r/∂θ = −c l² θ̇; m l² θ̈ = −m g l sin θ − c l² θ̇.
        let want = -p.g / p.l * theta.sin() - p.c / p.m * omega;
        let got = p.accelerations(&s).unwrap().theta;
        assert!(close(got, want), "{got} vs {want}");
    }
}

#[mechanism]
pub mod mixed_dimensions {
    pub struct Coords {
        pub y: f64,
        pub z: f64,
    }

    pub struct MixedDimensions {
        pub m: f64,
        pub g2: f64,
        pub g3: f64,
        pub f0: f64,
        pub w: f64,
    }

    /// Moves in the plane.
    #[particle(mass = m)]
    fn flat() -> Vec2 {
        vec2(0.0, y)
    }

    /// Moves in space.
    #[particle(mass = m * 2.0)]
    fn bead() -> Vec3 {
        vec3(0.0, 0.0, z)
    }

    #[gravity]
    fn plane_down() -> Vec2 {
        vec2(0.0, -g2)
    }

    #[gravity]
    fn space_down() -> Vec3 {
        vec3(0.0, 0.0, -g3)
    }

    /// A driving force; naming `t` in a force does not make the positions time-dependent.
    #[force(on = bead)]
    fn drive() -> Vec3 {
        vec3(0.0, 0.0, (w * t).cos() * f0)
    }
}

#[test]
fn planar_and_spatial_bodies_mix_and_each_field_acts_on_its_own() {
    use mixed_dimensions::{Coords, MixedDimensions, State};
    let p = MixedDimensions {
        m: 0.5,
        g2: 9.81,
        g3: 1.62,
        f0: 0.7,
        w: 3.0,
    };
    const { assert!(!<MixedDimensions as Model<2, 5>>::RHEONOMIC) };
    let t = 0.4;
    let s = State::new(t, Coords { y: 1.0, z: -2.0 }, Coords { y: 0.3, z: 0.1 });
    let qdd = p.accelerations(&s).unwrap();
    // ÿ = −g₂; z̈ = −g₃ + f₀ cos(w t) / (2m).
    assert!(close(qdd.y, -p.g2), "{qdd:?}");
    assert!(
        close(qdd.z, -p.g3 + p.f0 * (p.w * t).cos() / (2.0 * p.m)),
        "{qdd:?}"
    );
    // V = m g₂ y + 2m g₃ z.
    assert!(close(
        p.potential_energy(&s).unwrap(),
        p.m * p.g2 * 1.0 + 2.0 * p.m * p.g3 * -2.0
    ));
}
