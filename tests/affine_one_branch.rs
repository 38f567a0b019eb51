//! Affine mechanisms whose q̈ from the prepared constants is straight-line code (no force, no
//! constraint, every potential's gradient derived on its expression tree): through a validated
//! handle `accelerations` checks a call in one branch, and the integrators' hook solves with the
//! prepared factors of −M. Both must agree with the mechanism's own evaluation, and refuse a
//! non-finite state, or name non-finite dynamics, with the same errors as the checked path.

use lagrange::__private::{Dynamics, Prepare};
use lagrange::evaluation::Evaluate;
use lagrange::prelude::*;

/// A planet about a fixed centre (Kepler's problem): M = m I, diagonal; a potential the only force.
#[mechanism]
pub mod planet {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Planet {
        pub m: f64,
        pub mu: f64,
    }
    #[particle(mass = m)]
    fn body() -> Vec2 {
        vec2(x, y)
    }
    #[potential]
    fn gravitation() -> f64 {
        -mu * m / body.norm()
    }
}

/// Three masses on a line between walls, joined by a stiff and a soft spring and tied to the walls
/// (a short Fermi–Pasta–Ulam chain): M diagonal, one potential per spring.
#[mechanism]
pub mod chain {
    pub const MASSES: usize = 3;
    pub struct Coords {
        pub q: [f64; MASSES],
    }
    pub struct Chain {
        pub m: f64,
        pub omega: f64,
    }
    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(q[i], 0.0)
    }
    #[potential]
    fn stiff() -> f64 {
        omega * omega / 4.0 * (q[1] - q[0]).powi(2)
    }
    #[potential]
    fn soft() -> f64 {
        (q[2] - q[1]).powi(4)
    }
    #[potential]
    fn walls() -> f64 {
        q[0].powi(4) + q[2].powi(4)
    }
}

/// A block on the face of a wedge that slides on the floor, tied to a wall by a spring, under
/// gravity: M not diagonal (the block couples x and d), a uniform field and a potential.
#[mechanism]
pub mod tied_wedge {
    pub struct Coords {
        pub x: f64,
        pub d: f64,
    }
    pub struct TiedWedge {
        pub big_m: f64,
        pub m: f64,
        pub alpha: f64,
        pub k: f64,
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
    #[potential]
    fn spring() -> f64 {
        k * wedge.x * wedge.x / 2.0
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The lecture's wedge and block, gravity the only force: the plain mechanism's call is the
/// closed form's one branch, the handle's the prepared constants' one branch.
#[mechanism]
pub mod wedge {
    pub struct Coords {
        pub x: f64,
        pub d: f64,
    }
    pub struct Wedge {
        pub big_m: f64,
        pub m: f64,
        pub alpha: f64,
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
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

const PLANET: planet::Planet = planet::Planet { m: 1.3, mu: 0.8 };
const CHAIN: chain::Chain = chain::Chain {
    m: 0.9,
    omega: 50.0,
};
const TIED_WEDGE: tied_wedge::TiedWedge = tied_wedge::TiedWedge {
    big_m: 3.0,
    m: 1.0,
    alpha: 0.5,
    k: 40.0,
    g: 9.81,
};

const WEDGE: wedge::Wedge = wedge::Wedge {
    big_m: 3.0,
    m: 1.0,
    alpha: 0.5,
    g: 9.81,
};

#[test]
fn the_declarations_take_the_one_branch_path_through_the_handle() {
    // Checked when the test compiles: otherwise the comparisons below would compare the checked
    // path with itself.
    const { assert!(<planet::Planet as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<chain::Chain as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<tied_wedge::TiedWedge as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<wedge::Wedge as Prepare>::PREPARED_IN_ONE_BRANCH) };
    const { assert!(<Validated<planet::Planet> as Evaluate<2>>::ONE_BRANCH) };
    // The parameters' struct has no constants to solve with: it keeps the checked path.
    const { assert!(!<planet::Planet as Dynamics<2>>::CLOSED_FORM) };
}

/// Thirty states spread over a box of half-width `size` around `centre`, velocities of both signs.
fn states<const N: usize>(centre: f64, size: f64) -> impl Iterator<Item = ([f64; N], [f64; N])> {
    (0..30).map(move |i| {
        let f = i as f64;
        (
            std::array::from_fn(|j| centre + size * (0.9 * f + 1.7 * j as f64).sin()),
            std::array::from_fn(|j| 2.0 * (1.3 * f - 0.6 * j as f64).cos()),
        )
    })
}

/// Through the handle: `accelerations` (one branch) equals the integrators' hook bit for bit (the
/// same evaluation with the prepared constants), and agrees with the parameters' checked path to
/// `tolerance` relative to the largest acceleration.
fn agrees<M: Dynamics<N>, const N: usize>(
    sys: M,
    states: impl Iterator<Item = ([f64; N], [f64; N])>,
    tolerance: f64,
) {
    let handle = sys.validated().unwrap();
    for (i, (q, v)) in states.enumerate() {
        let s = State::new(
            0.1 * i as f64,
            M::Coords::from_array(q),
            M::Coords::from_array(v),
        );
        let one_branch = handle.accelerations(&s).unwrap().to_array();
        let hook = handle.accelerations_at(s.t, &q, &v).unwrap();
        assert_eq!(one_branch, hook, "at {s:?}");
        let checked = handle.get().accelerations(&s).unwrap().to_array();
        let scale = checked.iter().fold(1.0f64, |m, a| m.max(a.abs()));
        for j in 0..N {
            assert!(
                (one_branch[j] - checked[j]).abs() <= tolerance * scale,
                "coordinate {j} at {s:?}: {} vs {}",
                one_branch[j],
                checked[j]
            );
        }
    }
}

#[test]
fn one_branch_accelerations_agree_with_the_checked_path() {
    // Diagonal M: the same factors, once with the prepared −1/Mⱼⱼ joined to the gradient's
    // constant factors and once by the factorisation of M assembled at the state. Each side
    // rounds at most four times (the reciprocal, the constants' product, the products with the
    // state, the division or the solve), each by at most u = ε/2: at most 8u = 4ε apart.
    agrees(PLANET, states::<2>(0.0, 1.5), 4.0 * f64::EPSILON);
    agrees(CHAIN, states::<3>(0.0, 0.5), 4.0 * f64::EPSILON);
    // A 2×2 SPD system (condition ≈ 8 at α = 0.5) solved in a different order of operations, with
    // the field's and the spring's forces summed before or after: a few ulps of the largest q̈.
    agrees(TIED_WEDGE, states::<2>(0.0, 2.0), 1e-14);
    // The prepared M⁻¹ Aᵀ w against the plain call's closed form: the same 2×2 system, solved
    // once by the factors and once by the closed form's division by the determinant.
    agrees(WEDGE, states::<2>(0.0, 2.0), 1e-14);
}

/// Every non-finite entry of (t, q, q̇) in turn: the handle refuses it with the error the checked
/// path gives, naming the same state.
fn refuses_like_the_checked_path<M: Dynamics<N>, const N: usize>(sys: M, q: [f64; N], v: [f64; N]) {
    let handle = sys.validated().unwrap();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for slot in 0..(2 * N + 1) {
            let (mut t, mut q, mut v) = (0.25, q, v);
            match slot {
                0 => t = bad,
                s if s <= N => q[s - 1] = bad,
                s => v[s - N - 1] = bad,
            }
            let s = State::new(t, M::Coords::from_array(q), M::Coords::from_array(v));
            let one_branch = handle.accelerations(&s).unwrap_err();
            assert!(
                matches!(one_branch, Error::NonFiniteState { .. }),
                "{bad} in slot {slot}: {one_branch:?}"
            );
            assert_eq!(one_branch, handle.get().accelerations(&s).unwrap_err());
        }
    }
}

#[test]
fn non_finite_states_are_refused_with_the_same_errors() {
    refuses_like_the_checked_path(PLANET, [0.6, -0.8], [0.1, 1.2]);
    refuses_like_the_checked_path(CHAIN, [0.1, -0.2, 0.3], [0.5, 0.0, -1.0]);
    refuses_like_the_checked_path(TIED_WEDGE, [0.1, 0.4], [-0.3, 0.2]);
    refuses_like_the_checked_path(WEDGE, [0.1, 0.4], [-0.3, 0.2]);
}

#[test]
fn non_finite_dynamics_at_a_finite_state_are_named_like_the_checked_path() {
    // The planet at the centre: ∇V = μ m r/|r|³ is 0/0.
    let s = planet::State::at_rest(planet::Coords { x: 0.0, y: 0.0 });
    let handle = PLANET.validated().unwrap();
    let err = handle.accelerations(&s).unwrap_err();
    assert!(matches!(err, Error::NonFiniteDynamics { .. }), "{err:?}");
    assert_eq!(err, PLANET.accelerations(&s).unwrap_err());
    // The integrators' hook names it too.
    assert_eq!(
        handle.accelerations_at(0.0, &[0.0, 0.0], &[0.0, 0.0]),
        Err(err)
    );
    // The chain stretched so far that the soft spring's force 4 Δ³ overflows.
    let s = chain::State::at_rest(chain::Coords {
        q: [0.0, -1e103, 1e103],
    });
    let err = CHAIN.validated().unwrap().accelerations(&s).unwrap_err();
    assert!(matches!(err, Error::NonFiniteDynamics { .. }), "{err:?}");
    assert_eq!(err, CHAIN.accelerations(&s).unwrap_err());
}

#[test]
fn a_finite_state_whose_sum_overflows_is_not_refused() {
    // Every value finite, their sum not: the one branch fails, the checked path (whose state check
    // sums too, then looks value by value) accepts the state and returns the same q̈ — here the
    // planet so far out that the attraction underflows to zero.
    let huge = f64::MAX / 2.0;
    let s = planet::State::new(
        0.0,
        planet::Coords { x: huge, y: huge },
        planet::Coords { x: huge, y: huge },
    );
    let handle = PLANET.validated().unwrap();
    let a = handle.accelerations(&s).unwrap().to_array();
    assert_eq!(a.map(f64::abs), [0.0, 0.0]);
    assert_eq!(
        a.map(f64::abs),
        PLANET.accelerations(&s).unwrap().to_array().map(f64::abs)
    );
}
