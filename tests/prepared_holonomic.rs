//! Holonomic rows read as expression trees on affine positions: through a validated handle, q̈ is
//! the Schur complement S = G M⁻¹ Gᵀ from the prepared constants (one branch for every check of
//! a call) and the projection after a step uses the same constants. Both must agree with the
//! general path of the plain mechanism — the dual-number pass, M factorised at every call — and
//! refuse what it refuses, with the same errors.

use lagrange::__private::{Dynamics, Prepare};
use lagrange::constraints::Constraints;
use lagrange::evaluation::Evaluate;
use lagrange::integrate::Dop853;
use lagrange::prelude::*;
use lagrange::{Error, Validated};
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum::{self, CartesianPendulum};

/// A bead on a circle of latitude: a particle in space held on a sphere of radius `l` and on the
/// plane z = h, under gravity and a spring to the origin. Two holonomic rows; at the sphere's pole
/// (x = y = 0) their gradients r̂ and e_z are parallel, so S is singular there.
#[mechanism]
pub mod latitude_bead {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct LatitudeBead {
        pub m: f64,
        pub l: f64,
        pub h: f64,
        pub k: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec3 {
        vec3(x, y, z)
    }

    #[potential]
    fn spring() -> f64 {
        k * bead.norm_squared() / 2.0
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[constraint]
    fn sphere() -> f64 {
        bead.norm() - l
    }

    #[constraint]
    fn plane() -> f64 {
        bead.z - h
    }
}

use latitude_bead::LatitudeBead;

const BEAD: LatitudeBead = LatitudeBead {
    m: 1.3,
    l: 2.0,
    h: 0.5,
    k: 0.7,
    g: 9.81,
};

const PENDULUM: CartesianPendulum = CartesianPendulum {
    m: 1.0,
    l: 0.8,
    g: 9.81,
};

/// States on and off the circle of latitude, moving in every direction.
fn bead_states() -> impl Iterator<Item = ([f64; 3], [f64; 3])> {
    (0..12).map(|i| {
        let phi = 0.55 * i as f64;
        let rho = (BEAD.l * BEAD.l - BEAD.h * BEAD.h).sqrt() * (1.0 + 0.01 * (i % 3) as f64);
        let q = [
            rho * phi.cos(),
            rho * phi.sin(),
            BEAD.h - 0.02 * (i % 2) as f64,
        ];
        let v = [-1.1 * phi.sin(), 0.9 * phi.cos(), 0.3 - 0.05 * i as f64];
        (q, v)
    })
}

/// The pendulum on and off its circle.
fn pendulum_states() -> impl Iterator<Item = ([f64; 2], [f64; 2])> {
    (0..12).map(|i| {
        let th = -2.9 + 0.5 * i as f64;
        let r = PENDULUM.l * (1.0 + 0.02 * (i % 3) as f64 - 0.02);
        let w = 2.5 - 0.4 * i as f64;
        (
            [r * th.sin(), -r * th.cos()],
            [r * w * th.cos() + 0.01 * i as f64, r * w * th.sin()],
        )
    })
}

#[test]
fn the_declarations_take_the_prepared_holonomic_path() {
    // Rows written out on their trees, and q̈ in one branch through the handle.
    assert_eq!(
        <LatitudeBead as Constraints<3, 3, 2>>::POSITION_DERIVATIVES,
        [true, true]
    );
    // Checked when the test compiles: otherwise the comparisons below would compare the general
    // path with itself.
    const { assert!(<LatitudeBead as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<CartesianPendulum as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<Validated<CartesianPendulum> as Evaluate<2>>::ONE_BRANCH) };
}

/// q̈ of the plain mechanism (general path), of the handle's one branch (`accelerations`) and of
/// the handle's checked path (`accelerations_at`): one KKT system solved three ways.
fn assert_agree<M: Dynamics<N> + Copy, const N: usize>(plain: &M, q: [f64; N], v: [f64; N]) {
    let handle = (*plain).validated().unwrap();
    let state = State::new(0.0, M::Coords::from_array(q), M::Coords::from_array(v));
    let general = plain.accelerations(&state).unwrap().to_array();
    let one_branch = handle.accelerations(&state).unwrap().to_array();
    let checked = handle.accelerations_at(0.0, &q, &v).unwrap();
    // The same solve in another order (M⁻¹ by prepared factors against a fresh LDLᵀ, S formed
    // symmetric): the difference is a few ulps of |q̈| times the conditioning of M and S, which
    // is O(1) to O(10) at these states, so 1e-12 relative leaves a margin of 10³.
    let scale = general.iter().fold(1.0f64, |m, a| m.max(a.abs()));
    for j in 0..N {
        assert!(
            (general[j] - one_branch[j]).abs() <= 1e-12 * scale,
            "{general:?} vs {one_branch:?} at q = {q:?}, v = {v:?}"
        );
        assert_eq!(
            one_branch[j].to_bits(),
            checked[j].to_bits(),
            "one branch vs checked"
        );
    }
}

#[test]
fn accelerations_agree_with_the_general_path() {
    for (q, v) in bead_states() {
        assert_agree(&BEAD, q, v);
    }
    for (q, v) in pendulum_states() {
        assert_agree(&PENDULUM, q, v);
    }
}

#[test]
fn dependent_rows_are_named_through_the_handle_as_without_it() {
    let handle = BEAD.validated().unwrap();
    // At the pole the sphere's row r̂ = e_z is the plane's: S = [[1/m, 1/m], [1/m, 1/m]]/… is
    // singular, and both rows are named.
    let state = latitude_bead::State::new(
        0.0,
        latitude_bead::Coords {
            x: 0.0,
            y: 0.0,
            z: 1.5,
        },
        latitude_bead::Coords {
            x: 0.3,
            y: 0.0,
            z: 0.0,
        },
    );
    let plain = BEAD.accelerations(&state).unwrap_err();
    let through = handle.accelerations(&state).unwrap_err();
    for e in [&plain, &through] {
        match e {
            Error::SingularConstraints { constraints, .. } => {
                assert_eq!(constraints, "`sphere`, `plane`", "{e:?}")
            }
            other => panic!("expected singular constraints, got {other:?}"),
        }
    }
    // The pendulum's pivot, where the rod's direction is undefined, and non-finite states.
    let pendulum = PENDULUM.validated().unwrap();
    for (q, v) in [
        ([0.0, 0.0], [1.0, 0.0]),
        ([f64::NAN, -0.8], [0.0, 0.0]),
        ([0.0, -0.8], [f64::INFINITY, 0.0]),
        ([1e300, -1e300], [1e300, 0.0]),
    ] {
        let state = cartesian_pendulum::State::new(
            0.0,
            cartesian_pendulum::Coords::from_array(q),
            cartesian_pendulum::Coords::from_array(v),
        );
        let plain = PENDULUM.accelerations(&state).unwrap_err();
        let through = pendulum.accelerations(&state).unwrap_err();
        assert_eq!(format!("{plain:?}"), format!("{through:?}"));
    }
}

#[test]
fn the_prepared_projection_agrees_with_the_general_one() {
    let handle = BEAD.validated().unwrap();
    for (q0, v0) in bead_states() {
        let (mut q1, mut v1) = (q0, v0);
        let (mut q2, mut v2) = (q0, v0);
        Evaluate::project(&BEAD, 0.0, &mut q1, &mut v1).unwrap();
        handle.project(0.0, &mut q2, &mut v2).unwrap();
        // The same Newton iterates (the mass-weighted least-norm step, M⁻¹ by prepared factors
        // instead of a fresh Cholesky), each converged to round-off: they agree to a few ulps of
        // |q| ≈ 2 and |q̇| ≈ 1.5, amplified by S's conditioning (O(10) here).
        for j in 0..3 {
            assert!((q1[j] - q2[j]).abs() < 1e-13, "{q1:?} vs {q2:?}");
            assert!((v1[j] - v2[j]).abs() < 1e-13, "{v1:?} vs {v2:?}");
        }
        // On both constraints to round-off, and moving along them.
        let r = (q2[0] * q2[0] + q2[1] * q2[1] + q2[2] * q2[2]).sqrt();
        assert!((r - BEAD.l).abs() < 1e-14 && (q2[2] - BEAD.h).abs() < 1e-15);
        let radial = (q2[0] * v2[0] + q2[1] * v2[1] + q2[2] * v2[2]) / r;
        assert!(radial.abs() < 1e-14 && v2[2].abs() < 1e-14, "{v2:?}");
    }
    // A state the projection cannot reach is refused the same way, and left as it was.
    for (q0, v0) in [
        ([0.0; 3], [1.0, 0.0, 0.0]),
        ([f64::NAN, 1.0, 0.5], [0.0; 3]),
    ] {
        let (mut q1, mut v1) = (q0, v0);
        let (mut q2, mut v2) = (q0, v0);
        let plain = Evaluate::project(&BEAD, 0.0, &mut q1, &mut v1).unwrap_err();
        let through = handle.project(0.0, &mut q2, &mut v2).unwrap_err();
        assert_eq!(
            std::mem::discriminant(&plain),
            std::mem::discriminant(&through),
            "{plain:?} vs {through:?}"
        );
        assert_eq!(format!("{q0:?}{v0:?}"), format!("{q2:?}{v2:?}"));
    }
}

#[test]
fn an_adaptive_run_through_the_handle_follows_the_plain_one() {
    // One period's worth of the pendulum at tolerance 1e-10, on the plain mechanism (general path)
    // and through the handle (prepared path). Every evaluation and projection agrees to round-off,
    // so both runs accept the same steps and end within round-off growth of each other — far
    // below the tolerance, whose size bounds the error of either run.
    let start = cartesian_pendulum::State::new(
        0.0,
        cartesian_pendulum::Coords { x: 0.0, y: -0.8 },
        cartesian_pendulum::Coords { x: 5.0, y: 0.0 },
    );
    let method = Dop853 {
        dense: false,
        ..Dop853::new(1e-10, 1e-10)
    };
    let (mut plain, mut through) = (start, start);
    let a = PENDULUM
        .integrate(method, &mut plain, 2.0, &mut [], |_| {})
        .unwrap();
    let b = PENDULUM
        .validated()
        .unwrap()
        .integrate(method, &mut through, 2.0, &mut [], |_| {})
        .unwrap();
    assert_eq!(a.stats.accepted, b.stats.accepted);
    let (p, t) = (plain.q.to_array(), through.q.to_array());
    assert!((p[0] - t[0]).abs() < 1e-11 && (p[1] - t[1]).abs() < 1e-11);
    let r = (t[0] * t[0] + t[1] * t[1]).sqrt();
    assert!((r - PENDULUM.l).abs() < 1e-15, "{r}");
}
