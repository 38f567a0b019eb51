//! Mechanisms whose positions are polynomials in the coordinates and their sines and cosines get
//! M, 𝓕 and b in closed form, derived by the macro; they must agree with the dual-number passes
//! (`dynamics::equations_of_motion`) at every state, on `f64` and through an integrator that
//! differentiates q̈ with dual numbers.

use lagrange::__private::{dynamics, Dynamics, Model};
use lagrange::evaluation::Evaluate;
use lagrange::prelude::*;

/// A two-link arm in relative angles with a rod as a planar body, a marker point at its tip and a
/// field at an angle `tilt` (written as `tilt.sin()`: a constant as written).
#[mechanism]
pub mod arm {
    pub struct Coords {
        pub shoulder: f64,
        pub elbow: f64,
    }
    pub struct Arm {
        pub m: f64,
        pub inertia: f64,
        pub l: f64,
        pub g: f64,
        pub tilt: f64,
    }
    #[rigid_body(mass = m, inertia = inertia)]
    fn upper() -> Planar {
        planar(vec2(shoulder.cos(), shoulder.sin()) * (l / 2.0), shoulder)
    }
    #[particle(mass = m)]
    fn hand() -> Vec2 {
        let elbow_at = upper.position * 2.0;
        elbow_at + vec2((shoulder + elbow).cos(), (shoulder + elbow).sin()) * l
    }
    #[point]
    fn tip() -> Vec2 {
        hand + vec2((shoulder + 2.0 * elbow).cos(), 0.0) * 0.1
    }
    #[gravity]
    fn field() -> Vec2 {
        vec2(g * tilt.sin(), -g * tilt.cos())
    }
}

// The cart-pendulum and the spherical pendulum, declared once for this file and another.
#[path = "common/closed_form_mechanisms.rs"]
mod closed_form_mechanisms;
use closed_form_mechanisms::{cart_pendulum, spherical, states};

fn cart_pendulum() -> cart_pendulum::CartPendulum {
    cart_pendulum::CartPendulum {
        cart_mass: 2.0,
        m: 0.5,
        l: 0.8,
        g: 9.81,
    }
}

fn arm() -> arm::Arm {
    arm::Arm {
        m: 1.3,
        inertia: 0.07,
        l: 0.6,
        g: 9.81,
        tilt: 0.2,
    }
}

fn spherical() -> spherical::Spherical {
    spherical::Spherical {
        m: 0.9,
        m2: 1.7,
        l: 1.1,
        g: 9.81,
    }
}

/// The closed form against the dual-number passes at every state: M, 𝓕 and b entry by entry.
fn agrees_with_the_dual_passes<M: Model<N, K> + Dynamics<N>, const N: usize, const K: usize>(
    sys: &M,
) {
    assert!(
        M::CLOSED_FORM,
        "the declaration is not derived in closed form"
    );
    for (q, v) in states::<N>() {
        let closed = Evaluate::equations_of_motion_at(sys, 0.0, &q, &v);
        let dual = dynamics::equations_of_motion::<M, f64, N, K>(sys, 0.0, &q, &v);
        // The same sums of products in another order (the closed form simplified by
        // sin² + cos² = 1 before evaluating): agreement to a few ulps of each term's scale.
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-13 * scale.max(1.0);
        let m_scale = dual.mass_matrix.amax();
        for (a, b) in closed.mass_matrix.iter().zip(dual.mass_matrix.iter()) {
            assert!(close(*a, *b, m_scale), "M at {q:?}: {a} vs {b}");
        }
        let f_scale = dual.generalized_forces.amax();
        for (a, b) in closed
            .generalized_forces
            .iter()
            .zip(dual.generalized_forces.iter())
        {
            assert!(close(*a, *b, f_scale), "𝓕 at {q:?}: {a} vs {b}");
        }
        let b_scale = dual.inertial_terms.amax();
        for (a, b) in closed.inertial_terms.iter().zip(dual.inertial_terms.iter()) {
            assert!(close(*a, *b, b_scale), "b at {q:?}, {v:?}: {a} vs {b}");
        }
    }
}

#[test]
fn a_cart_pendulum_agrees_with_the_dual_passes() {
    agrees_with_the_dual_passes(&cart_pendulum());
}

#[test]
fn a_planar_arm_with_angle_sums_agrees_with_the_dual_passes() {
    agrees_with_the_dual_passes(&arm());
}

#[test]
fn a_spherical_pendulum_and_polar_coordinates_agree_with_the_dual_passes() {
    agrees_with_the_dual_passes(&spherical());
}

/// Affine positions in a uniform field: the plain mechanism's call takes the closed form (nothing
/// prepared), the validated handle the constants it prepared (J and M's factors); both give the
/// dual passes' q̈.
#[test]
fn an_affine_declaration_in_closed_form_keeps_its_prepared_handle() {
    use lagrange_gallery::scenes::wedge_block::wedge_block::{Coords, State, WedgeBlock};
    let sys = WedgeBlock {
        wedge_mass: 3.0,
        block_mass: 1.2,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
    };
    agrees_with_the_dual_passes(&sys);
    let handle = sys.validated().unwrap();
    for (q, v) in states::<2>() {
        let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
        let dual = dynamics::accelerations_generic::<_, f64, 2, 4>(&sys, 0.0, &q, &v).unwrap();
        for qdd in [sys.accelerations(&s), handle.accelerations(&s)] {
            let qdd = qdd.unwrap().to_array();
            // The same formula rounded three ways (closed form, prepared factors, dual passes).
            for j in 0..2 {
                assert!(
                    (qdd[j] - dual[j]).abs() <= 1e-13 * dual[j].abs().max(1.0),
                    "{qdd:?} vs {dual:?}"
                );
            }
        }
    }
    let bad = State::new(0.0, Coords::from_array([f64::NAN, 0.1]), Coords::default());
    for result in [sys.accelerations(&bad), handle.accelerations(&bad)] {
        assert!(
            matches!(result, Err(Error::NonFiniteState { .. })),
            "{result:?}"
        );
    }
}

#[test]
fn the_gallery_pendulums_are_derived_in_closed_form() {
    use lagrange_gallery::scenes::double_pendulum::double_pendulum;
    use lagrange_gallery::scenes::pendulum::pendulum;
    // Checked when the test compiles.
    const { assert!(<pendulum::Pendulum as Dynamics<1>>::CLOSED_FORM) };
    const { assert!(<double_pendulum::DoublePendulum as Dynamics<2>>::CLOSED_FORM) };
}

#[test]
fn closed_form_accelerations_differentiate_like_the_dual_passes() {
    // Radau5 differentiates q̈ with dual numbers for its Newton matrix: the closed form's
    // straight-line code on duals. Integrated against RK4 on a fine step (error ≈ h⁴ ≈ 1e-12 over
    // the run) from the same start, the end states agree to Radau5's tolerance.
    let sys = cart_pendulum();
    let start = cart_pendulum::State::new(
        0.0,
        cart_pendulum::Coords { x: 0.1, theta: 2.5 },
        cart_pendulum::Coords {
            x: -0.4,
            theta: 1.0,
        },
    );
    let mut implicit = start;
    sys.integrate(
        Radau5::new(1e-10, 1e-10),
        &mut implicit,
        2.0,
        &mut [],
        |_| {},
    )
    .unwrap();
    let mut reference = start;
    for _ in 0..2000 {
        sys.step::<Rk4>(&mut reference, 1e-3).unwrap();
    }
    let (a, b) = (implicit.q.to_array(), reference.q.to_array());
    for j in 0..2 {
        assert!((a[j] - b[j]).abs() < 1e-7, "{a:?} vs {b:?}");
    }
}

#[test]
fn a_validated_handle_prepares_the_coefficients_once() {
    // The handle computes the closed form's constant factors when it is made and evaluates the
    // same expressions with them: the same operations in the same order, so the same bits.
    fn same<M: Dynamics<N>, const N: usize>(
        sys: M,
        states: impl Iterator<Item = State<M::Coords>>,
    ) {
        assert!(std::mem::size_of::<<M as lagrange::__private::Prepare>::Prepared>() > 0);
        let validated = sys.validated().unwrap();
        for s in states {
            let plain = validated.get().accelerations(&s).unwrap().to_array();
            let prepared = validated.accelerations(&s).unwrap().to_array();
            assert_eq!(plain, prepared, "at {s:?}");
        }
    }
    let at = |(q, v): ([f64; 2], [f64; 2])| {
        arm::State::new(0.0, arm::Coords::from_array(q), arm::Coords::from_array(v))
    };
    same(arm(), states::<2>().map(at));
    let at = |(q, v): ([f64; 4], [f64; 4])| {
        let q = [q[0], q[1], 1.0 + q[2].abs(), q[3]];
        spherical::State::new(
            0.0,
            spherical::Coords::from_array(q),
            spherical::Coords::from_array(v),
        )
    };
    same(spherical(), states::<4>().map(at));
}

/// The double pendulum with its angles as an array coordinate, read element by element.
#[mechanism]
pub mod array_pendulum {
    pub struct Coords {
        pub theta: [f64; 2],
    }
    pub struct ArrayPendulum {
        pub m1: f64,
        pub m2: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m1)]
    fn upper() -> Vec2 {
        vec2(theta[0].sin(), -theta[0].cos()) * l
    }
    #[particle(mass = m2)]
    fn lower() -> Vec2 {
        upper + vec2(theta[1].sin(), -theta[1].cos()) * (0.5 * l)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn array_coordinates_read_by_literal_index_agree_with_the_dual_passes() {
    agrees_with_the_dual_passes(&array_pendulum::ArrayPendulum {
        m1: 1.2,
        m2: 0.8,
        l: 0.9,
        g: 9.81,
    });
}

/// The closed form checks a call in one branch; where it fails, the checks one at a time must say
/// what failed, exactly as for equations that are not in closed form, through the plain mechanism
/// and through a validated handle alike.
#[test]
fn one_branch_checks_fall_back_to_errors_that_name_the_failure() {
    use spherical::{Coords, State};
    let sys = spherical();
    let handle = spherical().validated().unwrap();
    let at =
        |q: [f64; 4], v: [f64; 4]| State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    for bad in [
        at([0.5, 0.1, f64::NAN, 0.0], [0.0; 4]),
        at([0.5, 0.1, 1.0, 0.0], [0.0, f64::INFINITY, 0.0, 0.0]),
        State::new(
            f64::NAN,
            Coords::from_array([0.5, 0.1, 1.0, 0.0]),
            Coords::default(),
        ),
    ] {
        for result in [sys.accelerations(&bad), handle.accelerations(&bad)] {
            assert!(
                matches!(result, Err(Error::NonFiniteState { .. })),
                "{result:?}"
            );
        }
    }
    // At the pole the azimuth does not move the bob, M = diag(m l², m l² sin² θ, …) is singular.
    let pole = at([0.0, 0.3, 1.0, 0.0], [0.1, 0.0, 0.0, 0.0]);
    for result in [sys.accelerations(&pole), handle.accelerations(&pole)] {
        match result {
            Err(Error::SingularMassMatrix { coordinate, .. }) => assert_eq!(coordinate, "phi"),
            other => panic!("expected a singular mass matrix, got {other:?}"),
        }
    }
    // A negative mass makes M indefinite, but the parameters are refused first.
    let negative = spherical::Spherical {
        m: -1.0,
        ..spherical()
    };
    assert!(matches!(
        negative.accelerations(&at([0.5, 0.1, 1.0, 0.0], [0.0; 4])),
        Err(Error::InvalidInertia { .. })
    ));
    // The parameters' test is part of the one branch: a non-finite or zero parameter fails it,
    // and the checks one at a time name the parameter or the body.
    let state = at([0.5, 0.1, 1.0, 0.0], [0.2, -0.3, 0.1, 0.4]);
    let no_gravity = spherical::Spherical {
        g: f64::NAN,
        ..spherical()
    };
    match no_gravity.accelerations(&state) {
        Err(Error::NonFiniteParameter { name, .. }) => assert_eq!(name, "g"),
        other => panic!("expected a non-finite parameter, got {other:?}"),
    }
    let massless = spherical::Spherical {
        m2: 0.0,
        ..spherical()
    };
    match massless.accelerations(&state) {
        Err(Error::InvalidInertia { body, .. }) => assert_eq!(body, "orbiter"),
        other => panic!("expected an invalid inertia, got {other:?}"),
    }
    // A negative cart mass the bob outweighs: M = [[M + m, m l cos θ], [m l cos θ, m l²]] has
    // det = m l² (M + m sin² θ) > 0 at θ = 1.2, so q̈ is finite and M's pivots pass; only the
    // parameters' test refuses the call.
    let light_cart = cart_pendulum::CartPendulum {
        cart_mass: -0.1,
        ..cart_pendulum()
    };
    let tilted = cart_pendulum::State::new(
        0.0,
        cart_pendulum::Coords::from_array([0.0, 1.2]),
        cart_pendulum::Coords::from_array([0.3, -0.2]),
    );
    match light_cart.accelerations(&tilted) {
        Err(Error::InvalidInertia { body, .. }) => assert_eq!(body, "cart"),
        other => panic!("expected an invalid inertia, got {other:?}"),
    }
}

/// Finite parameters whose sum overflows fail the one branch's test too; the checks one at a time
/// then accept them and return q̈ as the dual passes give it.
#[test]
fn finite_parameters_whose_sum_overflows_are_accepted() {
    // Each mass counted twice (as a parameter and as its body's mass): 4 × 6e307 overflows the
    // sum, while M, 𝓕 and b stay finite and q̈ does not depend on the masses' common scale.
    let sys = spherical::Spherical {
        m: 6e307,
        m2: 6e307,
        l: 1.0,
        g: 1.0,
    };
    let (q, v) = ([0.5, 0.1, 0.5, 0.3], [0.2, -0.3, 0.1, 0.4]);
    let s = spherical::State::new(
        0.0,
        spherical::Coords::from_array(q),
        spherical::Coords::from_array(v),
    );
    let dual = dynamics::accelerations_generic::<_, f64, 4, 6>(&sys, 0.0, &q, &v).unwrap();
    let qdd = sys.accelerations(&s).unwrap().to_array();
    // The closed form and the dual passes round the same formula differently: a few ulps.
    for j in 0..4 {
        assert!(
            (qdd[j] - dual[j]).abs() <= 1e-13 * dual[j].abs().max(1.0),
            "{qdd:?} vs {dual:?}"
        );
    }
}

/// The one branch tests the sum of the state and q̈: finite values whose sum overflows take the
/// checked path, which returns q̈ as the dual passes give it (the cart's position and speed do not
/// enter q̈).
#[test]
fn a_finite_state_whose_sum_overflows_is_accepted() {
    use cart_pendulum::{Coords, State};
    let sys = cart_pendulum();
    let (q, v) = ([1.5e308, 0.7], [1.5e308, -1.1]);
    let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    let dual = dynamics::accelerations_generic::<_, f64, 2, 4>(&sys, 0.0, &q, &v).unwrap();
    for qdd in [
        sys.accelerations(&s),
        cart_pendulum().validated().unwrap().accelerations(&s),
    ] {
        let qdd = qdd.unwrap().to_array();
        // The closed form and the dual passes round the same formula differently: a few ulps.
        for j in 0..2 {
            assert!(
                (qdd[j] - dual[j]).abs() <= 1e-13 * dual[j].abs().max(1.0),
                "{qdd:?} vs {dual:?}"
            );
        }
    }
}
