//! Rigid bodies in the plane and in space.

use super::close;
use lagrange::prelude::*;

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
