//! Bad constants of a body declared by its frame, each a typed error naming the body (or the
//! function that writes the rotation), from `validate`, from `validated`, and from every call that
//! checks the parameters, with the caller's state untouched: an inertia tensor that is not
//! symmetric, not positive definite, or whose principal moments violate the triangle inequality,
//! a tensor or centre of mass that overflows, a `rot3` that is not a rotation, a `rot_axis` about
//! no direction. The valid declaration passes every check.

use lagrange::prelude::*;

/// One link turning about a fixed axis behind a fixed rotation, every constant a parameter so
/// that each can be made wrong: the tensor's lower triangle separately from its upper one.
#[mechanism]
pub mod checked_link {
    pub struct Coords {
        pub q: f64,
    }
    #[derive(Clone, Copy)]
    pub struct CheckedLink {
        pub m: f64,
        pub ixx: f64,
        pub ixy: f64,
        pub ixz: f64,
        pub iyx: f64,
        pub iyy: f64,
        pub iyz: f64,
        pub izx: f64,
        pub izy: f64,
        pub izz: f64,
        pub cz: f64,
        pub r00: f64,
        pub r11: f64,
        pub r22: f64,
        pub ax: f64,
        pub ay: f64,
        pub az: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, com = vec3(0.0, 0.0, cz), inertia = [[ixx, ixy, ixz], [iyx, iyy, iyz], [izx, izy, izz]])]
    fn link() -> Spatial {
        let mount = rot3([[r00, 0.0, 0.0], [0.0, r11, 0.0], [0.0, 0.0, r22]]);
        spatial(vec3(0.0, 0.0, 0.0), mount * rot_axis(vec3(ax, ay, az), q))
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

use checked_link::{CheckedLink, Coords, State};

fn valid() -> CheckedLink {
    CheckedLink {
        m: 1.0,
        ixx: 0.02,
        ixy: 0.001,
        ixz: -0.002,
        iyx: 0.001,
        iyy: 0.03,
        iyz: 0.0005,
        izx: -0.002,
        izy: 0.0005,
        izz: 0.04,
        cz: 0.2,
        r00: 1.0,
        r11: 1.0,
        r22: 1.0,
        ax: 1.0,
        ay: 0.0,
        az: 0.0,
        g: 9.81,
    }
}

/// The error every entry point gives for `sys`, which must be the same, leave the state as it
/// was, and satisfy `expected`.
fn refused(sys: CheckedLink, expected: impl Fn(&Error) -> bool) {
    let error = sys.validate().expect_err("the parameters are refused");
    assert!(expected(&error), "{error:?}");
    assert_eq!(sys.validated().err(), Some(error.clone()));
    let sys = &sys;
    let start = State::new(0.0, Coords { q: 0.4 }, Coords { q: -1.0 });
    let mut s = start;
    assert_eq!(sys.accelerations(&s).err(), Some(error.clone()));
    assert_eq!(sys.mass_matrix(&s).err(), Some(error.clone()));
    assert_eq!(sys.energy(&s).err(), Some(error.clone()));
    assert_eq!(sys.momenta(&s).err(), Some(error.clone()));
    assert_eq!(sys.step::<Rk4>(&mut s, 1e-3).err(), Some(error));
    assert_eq!(s, start, "the state is untouched");
}

fn inertia_of_link(reason: &'static str) -> impl Fn(&Error) -> bool {
    move |e| matches!(e, Error::InvalidInertia { body: "link", reason: r } if r.contains(reason))
}

fn rotation_in_link(reason: &'static str) -> impl Fn(&Error) -> bool {
    move |e| matches!(e, Error::InvalidRotation { body: "link", reason: r } if r.contains(reason))
}

#[test]
fn the_valid_link_passes_and_moves() {
    let sys = valid().validated().unwrap();
    let mut s = State::new(0.0, Coords { q: 0.4 }, Coords { q: -1.0 });
    sys.step::<Rk4>(&mut s, 1e-3).unwrap();
    assert!(s.q.q.is_finite() && s.q.q != 0.4);
}

#[test]
fn an_asymmetric_tensor_is_refused() {
    let mut sys = valid();
    sys.iyx = 0.0011; // ixy = 0.001
    refused(sys, inertia_of_link("not symmetric"));
    // Round-off in a copied product of inertia is not asymmetry.
    let mut sys = valid();
    sys.iyx = 0.001 * (1.0 + 1e-15);
    assert!(sys.validate().is_ok());
}

#[test]
fn a_tensor_that_is_not_positive_definite_is_refused() {
    // Symmetric, but its principal moments are 0.02 ± 0.03: one negative.
    let mut sys = valid();
    (sys.ixx, sys.iyy, sys.izz) = (0.02, 0.02, 0.03);
    (sys.ixy, sys.iyx) = (0.03, 0.03);
    (sys.ixz, sys.izx, sys.iyz, sys.izy) = (0.0, 0.0, 0.0, 0.0);
    refused(sys, inertia_of_link("not positive definite"));
}

#[test]
fn principal_moments_violating_the_triangle_inequality_are_refused() {
    // Positive definite, but I₃ = 0.1 > I₁ + I₂ = 0.05: no mass distribution has it.
    let mut sys = valid();
    (sys.ixx, sys.iyy, sys.izz) = (0.02, 0.03, 0.1);
    (sys.ixy, sys.iyx, sys.ixz, sys.izx, sys.iyz, sys.izy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    refused(sys, inertia_of_link("triangle inequality"));
    // The equality is a flat body, which exists.
    let mut flat = valid();
    (flat.ixx, flat.iyy, flat.izz) = (0.02, 0.03, 0.05);
    (flat.ixy, flat.iyx, flat.ixz, flat.izx, flat.iyz, flat.izy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    assert!(flat.validate().is_ok());
}

#[test]
fn a_non_finite_parameter_is_named_before_the_tensor_is_read() {
    let mut sys = valid();
    sys.ixz = f64::INFINITY;
    refused(sys, |e| {
        matches!(e, Error::NonFiniteParameter { name: "ixz", .. })
    });
}

#[test]
fn a_centre_of_mass_that_is_not_finite_is_refused() {
    // Every parameter finite, the offset they make is not: the body gets the blame.
    let mut sys = valid();
    sys.cz = f64::MAX;
    assert!(sys.validate().is_ok(), "a large offset is an offset");
    #[mechanism]
    pub mod far_link {
        pub struct Coords {
            pub q: f64,
        }
        pub struct FarLink {
            pub m: f64,
            pub i: f64,
            pub d: f64,
        }
        #[rigid_body(mass = m, com = vec3(0.0, 0.0, d * d), inertia = [i, i, i])]
        fn link() -> Spatial {
            spatial(vec3(0.0, 0.0, 0.0), rot_x(q))
        }
    }
    let far = far_link::FarLink {
        m: 1.0,
        i: 0.1,
        d: 1e200,
    };
    let error = far.validate().unwrap_err();
    assert!(inertia_of_link("centre of mass")(&error), "{error:?}");
    let start = far_link::State::new(
        0.0,
        far_link::Coords { q: 0.1 },
        far_link::Coords { q: 1.0 },
    );
    let mut s = start;
    assert_eq!(far.step::<Rk4>(&mut s, 1e-3).err(), Some(error));
    assert_eq!(s, start);
}

#[test]
fn a_rot3_that_is_not_a_rotation_is_refused() {
    // Stretched: not orthonormal.
    let mut sys = valid();
    sys.r11 = 1.1;
    refused(sys, rotation_in_link("not orthonormal"));
    // A mirror: orthonormal, determinant −1.
    let mut sys = valid();
    sys.r22 = -1.0;
    refused(sys, rotation_in_link("reflection"));
    // A turn by π about x, written out, is a rotation.
    let mut sys = valid();
    (sys.r11, sys.r22) = (-1.0, -1.0);
    assert!(sys.validate().is_ok());
}

#[test]
fn a_rot_axis_about_no_direction_is_refused() {
    let mut sys = valid();
    (sys.ax, sys.ay, sys.az) = (0.0, 0.0, 0.0);
    refused(sys, rotation_in_link("no direction"));
    // Any length of axis is a direction.
    let mut sys = valid();
    (sys.ax, sys.ay, sys.az) = (0.0, 3.0, 4.0);
    assert!(sys.validate().is_ok());
}
