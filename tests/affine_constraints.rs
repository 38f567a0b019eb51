//! Constrained mechanisms whose positions are affine in the coordinates: through a validated
//! handle their constrained q̈ starts from the constants prepared once (the factors of the constant
//! mass matrix, M⁻¹Aᵀw), and the Schur solve is the one of the general path. It must agree with
//! the mechanism's own evaluation — holonomic, unilateral and friction rows, with potentials and
//! forces, on `f64` and on dual numbers — and refuse bad states the same way.

use lagrange::__private::{Dynamics, Prepare};
use lagrange::evaluation::Evaluate;
use lagrange::prelude::*;
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum::{self, CartesianPendulum};
use lagrange_gallery::scenes::rough_plane::rough_plane::{self, RoughPlane};
use lagrange_gallery::scenes::rough_ramp::rough_ramp::{self, RoughRamp};
use lagrange_gallery::scenes::sphere_release::sphere_release::{self, SphereRelease};
use num_dual::Dual64;

/// A bead on a circular wire of radius `l`, pulled by a spring towards an anchor off the centre
/// and slowed by drag: a potential, a velocity-dependent force and a constraint on affine positions.
#[mechanism]
pub mod sprung_bead {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct SprungBead {
        pub m: f64,
        pub l: f64,
        pub k: f64,
        pub ax: f64,
        pub ay: f64,
        pub c: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(x, y)
    }

    #[potential]
    fn spring() -> f64 {
        let (dx, dy) = (bead.x - ax, bead.y - ay);
        k * (dx * dx + dy * dy) / 2.0
    }

    #[force(on = bead)]
    fn drag() -> Vec2 {
        -bead_dot * c
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[constraint]
    fn wire() -> f64 {
        bead.norm() - l
    }
}

const BEAD: sprung_bead::SprungBead = sprung_bead::SprungBead {
    m: 0.7,
    l: 1.3,
    k: 5.0,
    ax: 0.4,
    ay: 0.9,
    c: 0.2,
    g: 9.81,
};

/// The size of what a mechanism prepares when validated (zero: nothing).
fn prepared_size<M: Prepare>() -> usize {
    std::mem::size_of::<M::Prepared>()
}

/// q̈ of `plain` and of its validated handle agree at `state` to a few ulps of the largest entry:
/// the same Schur solve, with M factorised and M⁻¹Aᵀw formed once instead of at every call (for
/// these diagonal M the same operations, for the others a different order of summation).
fn assert_agree<M: Dynamics<N> + Copy + std::fmt::Debug, const N: usize>(
    plain: M,
    state: &State<M::Coords>,
) {
    let validated = plain.validated().unwrap();
    let a = plain.accelerations(state).unwrap().to_array();
    let b = validated.accelerations(state).unwrap().to_array();
    let scale = a.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    for j in 0..N {
        assert!(
            (a[j] - b[j]).abs() <= 1e-14 * scale,
            "{plain:?}, coordinate {j} at {state:?}: {} vs {}",
            a[j],
            b[j]
        );
    }
}

/// (cos, sin) of `k` angles spread over the circle.
fn angles(k: usize) -> impl Iterator<Item = (f64, f64)> {
    (0..k).map(move |i| {
        let a = 0.3 + std::f64::consts::TAU * i as f64 / k as f64;
        (a.cos(), a.sin())
    })
}

#[test]
fn the_constrained_declarations_are_read_as_affine() {
    // Otherwise the comparisons below would compare the general path with itself.
    assert!(prepared_size::<CartesianPendulum>() > 0);
    assert!(prepared_size::<SphereRelease>() > 0);
    assert!(prepared_size::<RoughRamp>() > 0);
    assert!(prepared_size::<RoughPlane>() > 0);
    assert!(prepared_size::<sprung_bead::SprungBead>() > 0);
}

#[test]
fn holonomic_rows_agree_with_the_general_path() {
    let pendulum = CartesianPendulum {
        m: 1.3,
        l: 0.8,
        g: 9.81,
    };
    for (c, s) in angles(12) {
        // On the circle, moving along it.
        let state = cartesian_pendulum::State::new(
            0.0,
            cartesian_pendulum::Coords {
                x: 0.8 * s,
                y: -0.8 * c,
            },
            cartesian_pendulum::Coords {
                x: 1.7 * c,
                y: 1.7 * s,
            },
        );
        assert_agree(pendulum, &state);
        let state = sprung_bead::State::new(
            0.0,
            sprung_bead::Coords {
                x: 1.3 * c,
                y: 1.3 * s,
            },
            sprung_bead::Coords {
                x: -0.9 * s,
                y: 0.9 * c,
            },
        );
        assert_agree(BEAD, &state);
    }
}

#[test]
fn contact_and_friction_rows_agree_with_the_general_path() {
    let sphere = SphereRelease {
        m: 0.7,
        r: 1.5,
        g: 9.81,
    };
    for (c, s) in angles(8) {
        // In contact (on the sphere, moving along it) and separated (outside, moving away).
        let on = sphere_release::State::new(
            0.0,
            sphere_release::Coords {
                x: 1.5 * s,
                y: 1.5 * c,
            },
            sphere_release::Coords {
                x: 0.4 * c,
                y: -0.4 * s,
            },
        );
        assert_agree(sphere, &on);
        let off = sphere_release::State::new(
            0.0,
            sphere_release::Coords {
                x: 2.0 * s,
                y: 2.0 * c,
            },
            sphere_release::Coords { x: s, y: c },
        );
        assert_agree(sphere, &off);
    }
    // A block on a rough ramp: sliding down, sliding up, at rest (sticking).
    let ramp = RoughRamp {
        m: 1.2,
        alpha: 0.5,
        g: 9.81,
        mu_k: 0.2,
        mu_s: 0.3,
    };
    let (ca, sa) = (0.5f64.cos(), 0.5f64.sin());
    for speed in [-1.5, 0.8, 0.0] {
        let state = rough_ramp::State::new(
            0.0,
            rough_ramp::Coords {
                x: 2.0 * ca,
                y: 2.0 * sa,
            },
            rough_ramp::Coords {
                x: speed * ca,
                y: speed * sa,
            },
        );
        assert_agree(ramp, &state);
    }
    // A puck on a rough plane, pushed sideways: sliding in the plane (the friction cone) and at rest.
    let plane = RoughPlane {
        m: 0.5,
        g: 9.81,
        mu_k: 0.3,
        mu_s: 0.4,
        push: 0.8,
    };
    for (vx, vy) in [(1.0, 0.5), (-0.2, 0.7), (0.0, 0.0)] {
        let state = rough_plane::State::new(
            0.0,
            rough_plane::Coords {
                x: 0.3,
                y: -0.2,
                z: 0.0,
            },
            rough_plane::Coords {
                x: vx,
                y: vy,
                z: 0.0,
            },
        );
        assert_agree(plane, &state);
    }
}

#[test]
fn prepared_accelerations_differentiate_like_the_general_path() {
    // The implicit methods and the sensitivities differentiate q̈ with dual numbers: through the
    // handle these are the prepared path's. Both values and derivatives agree to a few ulps of
    // their scale (the same operations on the derivative parts as on the values).
    let validated = BEAD.validated().unwrap();
    for (c, s) in angles(6) {
        let direction = [0.3 - s, 0.8 + c];
        let q = [
            Dual64::new(1.3 * c, direction[0]),
            Dual64::new(1.3 * s, direction[1]),
        ];
        let v = [Dual64::from(-0.9 * s), Dual64::from(0.9 * c)];
        let t = Dual64::from(0.0);
        let a = Evaluate::accelerations_at(&BEAD, t, &q, &v).unwrap();
        let b = Evaluate::accelerations_at(&validated, t, &q, &v).unwrap();
        let scale = a
            .iter()
            .fold(1.0f64, |m, x| m.max(x.re.abs()).max(x.eps.abs()));
        for j in 0..2 {
            assert!((a[j].re - b[j].re).abs() <= 1e-14 * scale, "{a:?} vs {b:?}");
            assert!(
                (a[j].eps - b[j].eps).abs() <= 1e-14 * scale,
                "{a:?} vs {b:?}"
            );
        }
    }
}

#[test]
fn bad_states_are_refused_through_the_handle_as_without_it() {
    let pendulum = CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let validated = pendulum.validated().unwrap();
    let at = |x: f64, y: f64, vx: f64| {
        cartesian_pendulum::State::new(
            0.0,
            cartesian_pendulum::Coords { x, y },
            cartesian_pendulum::Coords { x: vx, y: 0.0 },
        )
    };
    // Non-finite entries, and the pivot, where the rod's direction (its row) is undefined.
    for state in [
        at(f64::NAN, -1.0, 0.0),
        at(0.0, f64::INFINITY, 0.0),
        at(0.0, -1.0, f64::NEG_INFINITY),
        at(0.0, 0.0, 1.0),
        at(1e300, -1e300, 1e300),
    ] {
        let plain = pendulum.accelerations(&state).unwrap_err();
        let handle = validated.accelerations(&state).unwrap_err();
        assert_eq!(
            std::mem::discriminant(&plain),
            std::mem::discriminant(&handle),
            "{plain:?} vs {handle:?} at {state:?}"
        );
        // A step refuses it too and leaves the state as it was.
        let mut stepped = state;
        assert!(validated.step::<Rk4>(&mut stepped, 1e-3).is_err());
        assert_eq!(format!("{stepped:?}"), format!("{state:?}"));
    }
}
