//! Bad input at run time is a typed error, and the caller's state is left as it was.

use lagrange::prelude::*;

#[mechanism]
pub mod spherical_pendulum {
    /// Polar angle from the downward vertical and azimuth: singular at the pole θ = 0, where φ
    /// moves nothing.
    pub struct Coords {
        pub theta: f64,
        pub phi: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct SphericalPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec3 {
        vec3(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            -theta.cos(),
        ) * l
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

use spherical_pendulum::{Coords, SphericalPendulum, State};

const SYS: SphericalPendulum = SphericalPendulum {
    m: 1.0,
    l: 1.0,
    g: 9.81,
};

fn moving() -> State {
    State::new(
        0.0,
        Coords {
            theta: 0.5,
            phi: 0.1,
        },
        Coords {
            theta: 0.2,
            phi: 1.0,
        },
    )
}

#[test]
fn non_finite_state_is_rejected_and_state_kept() {
    for bad in [
        State::new(
            0.0,
            Coords {
                theta: f64::NAN,
                phi: 0.0,
            },
            Coords::default(),
        ),
        State::new(
            0.0,
            Coords {
                theta: 0.5,
                phi: 0.0,
            },
            Coords {
                theta: f64::INFINITY,
                phi: 0.0,
            },
        ),
        State::new(
            f64::NAN,
            Coords {
                theta: 0.5,
                phi: 0.0,
            },
            Coords::default(),
        ),
    ] {
        let mut s = bad;
        let err = SYS.step::<Rk4>(&mut s, 1e-3).unwrap_err();
        assert!(matches!(err, Error::NonFiniteState { .. }), "{err}");
        assert_eq!(
            format!("{s:?}"),
            format!("{bad:?}"),
            "state must be unchanged"
        );
        assert!(matches!(
            SYS.accelerations(&bad),
            Err(Error::NonFiniteState { .. })
        ));
    }
}

#[test]
fn non_finite_parameter_is_named() {
    let sys = SphericalPendulum { l: f64::NAN, ..SYS };
    let mut s = moving();
    let err = sys.step::<Rk4>(&mut s, 1e-3).unwrap_err();
    assert!(
        matches!(err, Error::NonFiniteParameter { name: "l", .. }),
        "{err}"
    );
    assert_eq!(s, moving());
}

#[test]
fn non_positive_mass_is_rejected() {
    let sys = SphericalPendulum { m: -1.0, ..SYS };
    let err = sys.accelerations(&moving()).unwrap_err();
    assert!(
        matches!(err, Error::InvalidInertia { body: "bob", .. }),
        "{err}"
    );
}

#[test]
fn bad_step_is_rejected() {
    for h in [0.0, -1e-3, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut s = moving();
        assert!(
            matches!(SYS.step::<Rk4>(&mut s, h), Err(Error::InvalidStep { .. })),
            "h = {h}"
        );
        assert_eq!(s, moving());
    }
}

#[test]
fn singular_mass_matrix_names_the_configuration() {
    // At the pole the azimuth does not move the bob: M = diag(m l², m l² sin²θ) is singular.
    let at_pole = State::new(
        0.0,
        Coords {
            theta: 0.0,
            phi: 0.3,
        },
        Coords {
            theta: 0.1,
            phi: 0.0,
        },
    );
    let err = SYS.accelerations(&at_pole).unwrap_err();
    match &err {
        Error::SingularMassMatrix {
            configuration,
            coordinate,
            ..
        } => {
            assert_eq!(*coordinate, "phi");
            assert!(
                configuration.contains("theta = 0") && configuration.contains("phi = 0.3"),
                "{configuration}"
            );
        }
        other => panic!("expected a singular mass matrix, got {other}"),
    }
    let mut s = at_pole;
    assert!(SYS.step::<Rk4>(&mut s, 1e-3).is_err());
    assert_eq!(s, at_pole);
    // Near the pole but not at it, the accelerations are finite.
    let near = State::new(
        0.0,
        Coords {
            theta: 1e-3,
            phi: 0.3,
        },
        Coords {
            theta: 0.1,
            phi: 0.0,
        },
    );
    let a = SYS.accelerations(&near).unwrap();
    assert!(a.theta.is_finite() && a.phi.is_finite());
}

#[test]
fn huge_velocity_is_an_error_for_the_energies_as_for_the_accelerations() {
    // φ̇ = 1e300: T = ½ m l² (θ̇² + sin²θ φ̇²) and the centripetal term of b overflow to ∞.
    let fast = State::new(
        0.0,
        Coords {
            theta: 0.5,
            phi: 0.1,
        },
        Coords {
            theta: 0.2,
            phi: 1e300,
        },
    );
    assert!(matches!(
        SYS.accelerations(&fast),
        Err(Error::NonFiniteDynamics { .. })
    ));
    for (what, result) in [
        ("energy", SYS.energy(&fast)),
        ("kinetic energy", SYS.kinetic_energy(&fast)),
        ("energy function", SYS.energy_function(&fast)),
    ] {
        assert!(
            matches!(result, Err(Error::NonFiniteDynamics { .. })),
            "{what}: {result:?}"
        );
    }
    // The potential energy does not depend on the velocities: finite.
    assert!(SYS.potential_energy(&fast).unwrap().is_finite());
}

/// A bead in polar coordinates held on a ray by a constraint: M = diag(m, m r²) overflows at
/// r = 10³⁰⁰.
#[mechanism]
pub mod bead_on_ray {
    pub struct Coords {
        pub r: f64,
        pub theta: f64,
    }

    pub struct Bead {
        pub m: f64,
        pub angle: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(theta.cos(), theta.sin()) * r
    }

    #[constraint]
    fn ray() -> f64 {
        theta - angle
    }
}

#[test]
fn an_overflowing_mass_matrix_in_the_constrained_solve_is_non_finite_dynamics() {
    let p = bead_on_ray::Bead { m: 1.0, angle: 0.3 };
    let (q, v) = ([1e300, 0.3], [0.0, 0.0]);
    // The constrained solve itself, not only the user-facing call: not "singular, pivot 1".
    let err = lagrange::constraints::accelerations(&p, 0.0, &q, &v).unwrap_err();
    assert!(
        matches!(err, lagrange::Error::NonFiniteDynamics { .. }),
        "{err}"
    );
    let s = bead_on_ray::State::new(
        0.0,
        bead_on_ray::Coords {
            r: q[0],
            theta: q[1],
        },
        bead_on_ray::Coords::default(),
    );
    let err = p.accelerations(&s).unwrap_err();
    assert!(
        matches!(err, lagrange::Error::NonFiniteDynamics { .. }),
        "{err}"
    );
}
