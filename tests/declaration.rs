//! Each item kind of the declaration, checked numerically against a closed form derived by hand.
//!
//! Tolerances: unless said otherwise a comparison is between the generated accelerations (dual-number
//! derivatives, a small Cholesky solve) and a closed form of a few dozen flops from the same inputs;
//! both are accurate to a few ulps of the largest intermediate term, so they must agree to 1e-12
//! relative to the scale of the terms (which are O(10) here).

use lagrange::model::Model;
use lagrange::prelude::*;

/// |a − b| ≤ 1e-12 · (1 + |b|): see the module docs.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + b.abs())
}

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
pub mod physical_pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct PhysicalPendulum {
        pub m: f64,
        pub i: f64,
        pub d: f64,
        pub g: f64,
        pub tau: f64,
    }

    /// A bar pivoted at the origin, centre of mass at distance d.
    #[rigid_body(mass = m, inertia = i)]
    fn bar() -> Planar {
        planar(vec2(theta.sin(), -theta.cos()) * d, theta)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[torque(on = bar)]
    fn motor() -> f64 {
        tau
    }
}

#[test]
fn planar_rigid_body_is_a_physical_pendulum() {
    use physical_pendulum::{Coords, PhysicalPendulum, State};
    for tau in [0.0, 0.8] {
        let p = PhysicalPendulum {
            m: 2.0,
            i: 0.3,
            d: 0.4,
            g: 9.81,
            tau,
        };
        for (theta, omega) in [(0.0, 1.0), (0.7, -2.0), (2.5, 0.3)] {
            let s = State::new(0.0, Coords { theta }, Coords { theta: omega });
            let got = p.accelerations(&s).unwrap().theta;
            // (I + m d²) θ̈ = τ − m g d sin θ: the period-consistent compound pendulum.
            let want = (tau - p.m * p.g * p.d * theta.sin()) / (p.i + p.m * p.d * p.d);
            assert!(close(got, want), "{got} vs {want}");
            // The planar body's velocity: centre of mass d θ̇ (cos θ, sin θ), angular velocity θ̇.
            let bar = p.body_velocities(&s).bar;
            assert!(close(bar.angle, omega) && close(bar.position.x, p.d * omega * theta.cos()));
            let t = 0.5 * (p.i + p.m * p.d * p.d) * omega * omega;
            assert!(close(p.kinetic_energy(&s).unwrap(), t));
        }
    }
}

#[mechanism]
pub mod free_body {
    pub struct Coords {
        pub yaw: f64,
        pub pitch: f64,
        pub roll: f64,
    }

    pub struct FreeBody {
        pub m: f64,
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }

    /// Fixed centre of mass; orientation by z-y-x angles (roll innermost: about the body x axis).
    #[rigid_body(mass = m, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(yaw) * rot_y(pitch) * rot_x(roll))
    }
}

#[test]
fn spatial_body_spinning_about_a_principal_axis_keeps_its_angular_velocity() {
    use free_body::{Coords, FreeBody, State};
    let p = FreeBody {
        m: 1.0,
        i1: 1.0,
        i2: 2.0,
        i3: 2.5,
    };
    let omega = 3.0;
    // Rolling only: the body's angular velocity is ω along its own x axis, a principal axis, so by
    // Euler's equations it stays constant: q̈ = 0 at every orientation.
    let mut s = State::new(
        0.0,
        Coords {
            yaw: 0.4,
            pitch: -0.3,
            roll: 1.1,
        },
        Coords {
            yaw: 0.0,
            pitch: 0.0,
            roll: omega,
        },
    );
    let qdd = p.accelerations(&s).unwrap();
    // M and b are O(1)–O(10): a zero acceleration comes out as round-off of that size.
    assert!(
        qdd.yaw.abs() < 1e-12 && qdd.pitch.abs() < 1e-12 && qdd.roll.abs() < 1e-12,
        "{qdd:?}"
    );
    // T = ½ I₁ ω².
    assert!(close(
        p.kinetic_energy(&s).unwrap(),
        0.5 * p.i1 * omega * omega
    ));
    for _ in 0..500 {
        p.step::<Rk4>(&mut s, 1e-2).unwrap();
    }
    // The exact motion has q̈ = 0, which RK4 reproduces up to round-off per step (500 steps).
    assert!(
        (s.v.roll - omega).abs() < 1e-10 && s.v.yaw.abs() < 1e-10 && s.v.pitch.abs() < 1e-10,
        "{:?}",
        s.v
    );
    assert!((s.q.roll - (1.1 + 5.0 * omega)).abs() < 1e-9);
    // The centre of mass does not move, and the body turns at ω about its own x axis.
    let velocity = p.body_velocities(&s).body;
    assert!(velocity.linear.norm() < 1e-15);
    // ½ Σ rₖ × ṙₖ after 5 s of RK4 on a rotation: a few ulps of ω times the angles' drift above.
    assert!((velocity.angular.norm() - omega).abs() < 1e-9);
}

#[mechanism]
pub mod spatial_pendulum {
    pub struct Coords {
        pub theta: f64,
        pub phi: f64,
    }

    pub struct SpatialPendulum {
        pub m: f64,
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
        pub d: f64,
        pub g: f64,
    }

    /// Hung from the origin: tilted by θ about x, then swung by φ about the vertical; the centre of
    /// mass is at distance d down the body's z axis.
    #[rigid_body(mass = m, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        let rotation = rot_z(phi) * rot_x(theta);
        spatial(rotation * vec3(0.0, 0.0, -d), rotation)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

#[test]
fn spatial_pendulum_matches_closed_form() {
    use spatial_pendulum::{Coords, SpatialPendulum, State};
    let p = SpatialPendulum {
        m: 1.5,
        i1: 0.2,
        i2: 0.3,
        i3: 0.4,
        d: 0.8,
        g: 9.81,
    };
    // Body angular velocity (θ̇, φ̇ sin θ, φ̇ cos θ), |ċ|² = d²(θ̇² + φ̇² sin²θ), V = −m g d cos θ:
    // (I₁ + m d²) θ̈ = (I₂' − I₃) sin θ cos θ φ̇² − m g d sin θ,  I₂' = I₂ + m d²;
    // (I₂' sin²θ + I₃ cos²θ) φ̈ = −2 (I₂' − I₃) sin θ cos θ θ̇ φ̇.
    for (q, v) in [([0.6, 0.2], [0.5, 1.5]), ([2.0, -1.0], [-1.0, 0.7])] {
        let s = State::new(
            0.0,
            Coords {
                theta: q[0],
                phi: q[1],
            },
            Coords {
                theta: v[0],
                phi: v[1],
            },
        );
        let got = p.accelerations(&s).unwrap();
        let (sin, cos) = q[0].sin_cos();
        let i2 = p.i2 + p.m * p.d * p.d;
        let theta_dd = ((i2 - p.i3) * sin * cos * v[1] * v[1] - p.m * p.g * p.d * sin)
            / (p.i1 + p.m * p.d * p.d);
        let phi_dd =
            -2.0 * (i2 - p.i3) * sin * cos * v[0] * v[1] / (i2 * sin * sin + p.i3 * cos * cos);
        assert!(
            close(got.theta, theta_dd) && close(got.phi, phi_dd),
            "{got:?} vs {theta_dd}, {phi_dd}"
        );
    }
}

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

#[test]
fn parameters_are_validated() {
    use lagrange::Error;
    let s = double_pendulum::State::at_rest(double_pendulum::Coords {
        theta1: 0.1,
        theta2: 0.2,
    });
    let good = double_pendulum::DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let nan_g = double_pendulum::DoublePendulum {
        g: f64::NAN,
        ..good
    };
    assert!(matches!(
        nan_g.accelerations(&s),
        Err(Error::NonFiniteParameter { name: "g", .. })
    ));
    let negative_mass = double_pendulum::DoublePendulum { m2: -1.0, ..good };
    assert!(matches!(
        negative_mass.energy(&s),
        Err(Error::InvalidInertia { body: "bob2", .. })
    ));

    let s = physical_pendulum::State::at_rest(physical_pendulum::Coords { theta: 0.1 });
    let flat = physical_pendulum::PhysicalPendulum {
        m: 1.0,
        i: 0.0,
        d: 0.5,
        g: 9.81,
        tau: 0.0,
    };
    assert!(matches!(
        flat.accelerations(&s),
        Err(Error::InvalidInertia { body: "bar", .. })
    ));

    let s = free_body::State::at_rest(free_body::Coords::default());
    let impossible = free_body::FreeBody {
        m: 1.0,
        i1: 1.0,
        i2: 1.0,
        i3: 3.0,
    };
    let err = impossible.accelerations(&s).unwrap_err();
    assert!(
        matches!(&err, Error::InvalidInertia { body: "body", reason } if reason.contains("triangle")),
        "{err}"
    );
    // A flat plate (I₃ = I₁ + I₂) is allowed.
    let plate = free_body::FreeBody {
        m: 1.0,
        i1: 1.0,
        i2: 2.0,
        i3: 3.0,
    };
    assert!(plate.energy(&s).is_ok());
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
