//! Mechanisms whose positions are affine in the coordinates: through a validated handle their q̈
//! comes from the constants prepared once (J, the factors of the constant mass matrix, Aᵀw); it
//! must agree with the mechanism's own evaluation, on `f64` and on dual numbers, and a constant
//! mass matrix that is singular must be refused when the handle is made.

use lagrange::prelude::*;

/// A wedge of mass `big_m` sliding on the floor, a block on its face at distance `d` down the
/// slope, a second block on the floor tied to the wedge by a spring, pushed by a force through a
/// massless handle at a fixed offset, with drag: every row is a coordinate times a constant.
#[mechanism]
pub mod sliders {
    pub struct Coords {
        pub x: f64,
        pub d: f64,
        pub s: f64,
    }

    pub struct Sliders {
        pub big_m: f64,
        pub m: f64,
        pub m2: f64,
        pub alpha: f64,
        pub k: f64,
        pub rest: f64,
        pub c: f64,
        pub push: f64,
        pub g: f64,
    }

    #[particle(mass = big_m)]
    fn wedge() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = m)]
    fn block() -> Vec2 {
        wedge + vec2(d * alpha.cos(), -d * alpha.sin())
    }

    #[particle(mass = m2)]
    fn follower() -> Vec2 {
        vec2(s, 0.0)
    }

    #[point]
    fn handle() -> Vec2 {
        follower + vec2(0.5, 0.25)
    }

    #[potential]
    fn spring() -> f64 {
        let stretch = follower.x - wedge.x - rest;
        k * stretch * stretch / 2.0
    }

    #[force(on = handle)]
    fn pushing() -> Vec2 {
        vec2(push, 0.0) - handle_dot * c
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// A coordinate that moves only a massless point: the constant mass matrix is singular.
#[mechanism]
pub mod idle {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Idle {
        pub m: f64,
    }
    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(x, 0.0)
    }
    #[point]
    fn marker() -> Vec2 {
        vec2(x, y)
    }
}

fn sliders() -> sliders::Sliders {
    sliders::Sliders {
        big_m: 3.0,
        m: 1.0,
        m2: 0.7,
        alpha: 0.5,
        k: 40.0,
        rest: 1.5,
        c: 0.3,
        push: 2.0,
        g: 9.81,
    }
}

/// States spread over the configuration space (the positions are affine, so no region is special).
fn states() -> impl Iterator<Item = sliders::State> {
    (0..20).map(|i| {
        let f = i as f64;
        sliders::State::new(
            0.1 * f,
            sliders::Coords {
                x: (0.7 * f).sin(),
                d: 0.3 + (1.3 * f).cos(),
                s: 2.0 + (0.4 * f).sin(),
            },
            sliders::Coords {
                x: (0.9 * f).cos(),
                d: -0.5 + 0.1 * f,
                s: (2.1 * f).sin(),
            },
        )
    })
}

/// The size of what a mechanism prepares when validated (zero: nothing).
fn prepared_size<M: lagrange::__private::Prepare>() -> usize {
    std::mem::size_of::<M::Prepared>()
}

#[test]
fn the_declarations_are_read_as_affine() {
    // Otherwise the comparisons below would compare the general path with itself.
    assert!(prepared_size::<sliders::Sliders>() > 0);
    assert!(prepared_size::<idle::Idle>() > 0);
}

#[test]
fn prepared_accelerations_agree_with_the_general_path() {
    let plain = sliders();
    let validated = sliders().validated().unwrap();
    for s in states() {
        let a = plain.accelerations(&s).unwrap().to_array();
        let b = validated.accelerations(&s).unwrap().to_array();
        // The same 3×3 SPD system (condition ≈ 20) solved in a different order of operations:
        // agreement to a few ulps of the largest acceleration.
        let scale = a.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for j in 0..3 {
            assert!(
                (a[j] - b[j]).abs() <= 1e-14 * scale,
                "coordinate {j} at {s:?}: {} vs {}",
                a[j],
                b[j]
            );
        }
    }
}

#[test]
fn prepared_accelerations_differentiate_like_the_general_path() {
    // Radau5 differentiates q̈ with dual numbers for its Newton matrix: through the handle these
    // are the prepared path's duals. Same settings, same steps up to round-off: the end states
    // agree far below the tolerance.
    let plain = sliders();
    let validated = sliders().validated().unwrap();
    let start = states().nth(3).unwrap();
    let (mut a, mut b) = (start, start);
    let settings = Radau5::new(1e-9, 1e-9);
    plain
        .integrate(settings, &mut a, 2.0, &mut [], |_| {})
        .unwrap();
    validated
        .integrate(settings, &mut b, 2.0, &mut [], |_| {})
        .unwrap();
    let (qa, qb) = (a.q.to_array(), b.q.to_array());
    for j in 0..3 {
        assert!((qa[j] - qb[j]).abs() < 1e-11, "{qa:?} vs {qb:?}");
    }
}

#[test]
fn a_singular_constant_mass_matrix_is_refused_when_validated() {
    let Err(err) = idle::Idle { m: 1.0 }.validated() else {
        panic!("a singular constant mass matrix was accepted");
    };
    match err {
        Error::SingularMassMatrix { coordinate, .. } => assert_eq!(coordinate, "y"),
        other => panic!("expected a singular mass matrix naming `y`, got {other:?}"),
    }
    // The unvalidated mechanism reports the same at any state.
    let s = idle::State::at_rest(idle::Coords { x: 0.0, y: 0.0 });
    assert!(matches!(
        idle::Idle { m: 1.0 }.accelerations(&s),
        Err(Error::SingularMassMatrix { .. })
    ));
}
