//! Answers that do not depend on the units a mechanism is written in: every pivot test compares a
//! pivot with a quantity of its own unit, and every Newton iteration measures its increments
//! against quantities of their own units. The cases here are the ones that were refused or failed
//! before; `tests/scale_matrix` runs every entry point over many systems of units.

#[path = "common/squeezer.rs"]
mod squeezer_model;
#[path = "common/units.rs"]
#[allow(dead_code)]
mod units;

use lagrange::integrate::{Method, Stepper};
use lagrange::prelude::*;
use lagrange::{GaussLegendre2, ImplicitMidpoint, StormerVerlet, Variational};
use lagrange_gallery::scenes::{cartesian_pendulum, four_bar, spinning_hoop};
use squeezer_model::{andrews_in, squeezer, START};
use units::Units;

#[mechanism]
pub mod kepler_polar {
    pub struct Coords {
        pub r: f64,
        pub phi: f64,
    }

    #[derive(Clone, Copy, Debug)]
    pub struct KeplerPolar {
        pub m: f64,
        /// The centre's gravitational parameter GM.
        pub gm: f64,
    }

    #[particle(mass = m)]
    fn planet() -> Vec2 {
        vec2(phi.cos(), phi.sin()) * r
    }

    #[potential]
    fn gravitation() -> f64 {
        -gm * m / r
    }
}

/// The Earth's GM, m³/s² (IERS Conventions 2010, Technical Note 36, Table 1.1).
const GM_EARTH: f64 = 3.986004418e14;

/// A 1000 kg satellite at radius r (m), on a slightly eccentric orbit: ṙ = 120 m/s, φ̇ 1.1 times
/// the circular rate.
fn satellite(r: f64) -> (kepler_polar::KeplerPolar, kepler_polar::State) {
    use kepler_polar::{Coords, KeplerPolar, State};
    let sys = KeplerPolar {
        m: 1000.0,
        gm: GM_EARTH,
    };
    let rate = 1.1 * (GM_EARTH / (r * r * r)).sqrt();
    let s = State::new(
        0.0,
        Coords { r, phi: 0.3 },
        Coords {
            r: 120.0,
            phi: rate,
        },
    );
    (sys, s)
}

#[test]
fn a_planet_in_si_units_is_not_refused() {
    // M = diag(m, m r²) = diag(1e3 kg, 4.9e16 kg m²) at r = 7e6 m: perfectly conditioned per
    // coordinate, refused while the pivot test compared the radial pivot (kg) with the angular
    // diagonal entry (kg m²). In polar coordinates r̈ = r φ̇² − GM/r², φ̈ = −2 ṙ φ̇ / r.
    for r in [3e6, 7e6, 4.2164e7, 1e9] {
        let (sys, s) = satellite(r);
        let a = sys.accelerations(&s).expect("a planet in SI units");
        let (v, rate) = (s.v.r, s.v.phi);
        let (r_dd, phi_dd) = (r * rate * rate - GM_EARTH / (r * r), -2.0 * v * rate / r);
        // Each a difference of two terms of similar size (r φ̇² is 1.21 GM/r²): a few ulps of
        // those terms, ≲ 1e-14 of the result.
        assert!((a.r - r_dd).abs() <= 1e-14 * r_dd.abs(), "r = {r}: {a:?}");
        assert!(
            (a.phi - phi_dd).abs() <= 1e-14 * phi_dd.abs(),
            "r = {r}: {a:?}"
        );
        let validated = sys.validated().unwrap();
        assert_eq!(validated.accelerations(&s).unwrap(), a);
    }
}

/// The satellite at 7e6 m in units where GM = 1, the radius of the Earth's surface is 1 and the
/// satellite's mass is 1: lengths in 6.371e6 m, masses in 1000 kg, times in √(R³/GM) ≈ 806.8 s.
fn earth_units() -> Units {
    let length = 6.371e6;
    Units {
        length,
        mass: 1000.0,
        time: (length * length * length / GM_EARTH).sqrt(),
    }
}

/// `s` (SI) in `units`.
fn satellite_in(
    units: &Units,
    s: &kepler_polar::State,
) -> (kepler_polar::KeplerPolar, kepler_polar::State) {
    use kepler_polar::{Coords, KeplerPolar, State};
    use units::{dim, LENGTH, MASS, ONE, RATE};
    let (sys, _) = satellite(7e6);
    let scaled = KeplerPolar {
        m: units.express(sys.m, MASS),
        gm: units.express(sys.gm, dim(3, 0, -2)),
    };
    let q = Coords {
        r: units.express(s.q.r, LENGTH),
        phi: units.express(s.q.phi, ONE),
    };
    let v = Coords {
        r: units.express(s.v.r, dim(1, 0, -1)),
        phi: units.express(s.v.phi, RATE),
    };
    (scaled, State::new(units.express(s.t, units::TIME), q, v))
}

#[test]
fn the_implicit_methods_step_a_planet_in_si_units_as_in_natural_units() {
    // The Newton matrices of Gauss–Legendre, implicit midpoint, the variational integrator and
    // Radau5 carry the units of M (kg against kg m²): their LU pivots were tested against the
    // largest entry, so the SI declaration was refused where the natural one was not. Now both
    // take the same iterations and agree, rescaled, to round-off (a 60 s step, 1/100 of the
    // orbit's period: each method's own error, ~1e-8 to 1e-4 of the state, is far above that).
    let (sys, s) = satellite(7e6);
    let units = earth_units();
    let (natural, s_natural) = satellite_in(&units, &s);
    let h = 60.0;
    let h_natural = units.express(h, units::TIME);
    let close = |a: &kepler_polar::State, b: &kepler_polar::State| {
        let (_, b_si) = satellite_in(
            &Units {
                length: 1.0 / units.length,
                mass: 1.0 / units.mass,
                time: 1.0 / units.time,
            },
            b,
        );
        // Each component to 1e-12 relative: rescaling rounds every input once (ε), and the step
        // amplifies that by its condition, a few orders at most over one step.
        let rel = |x: f64, y: f64| (x - y).abs() / x.abs().max(1e-300);
        assert!(
            rel(a.q.r, b_si.q.r) < 1e-12 && rel(a.q.phi, b_si.q.phi) < 1e-12,
            "{a:?} vs {b_si:?}"
        );
        assert!(
            rel(a.v.r, b_si.v.r) < 1e-12 && rel(a.v.phi, b_si.v.phi) < 1e-12,
            "{a:?} vs {b_si:?}"
        );
    };
    macro_rules! both {
        ($method:ty) => {{
            let (mut a, mut b) = (s, s_natural);
            let ca = <$method>::step_with_stats(&sys, &mut a, h).expect(stringify!($method));
            let cb = <$method>::step_with_stats(&natural, &mut b, h_natural).unwrap();
            assert_eq!(ca, cb, stringify!($method));
            close(&a, &b);
        }};
    }
    both!(GaussLegendre2);
    both!(ImplicitMidpoint);
    both!(Variational);
    let settings = |h0: f64| Radau5 {
        h_init: Some(h0),
        ..Radau5::new(1e-8, 1e-300)
    };
    let mut a = Stepper::new(&sys, settings(h), &s).expect("Radau5 in SI units");
    let mut b = Stepper::new(&natural, settings(h_natural), &s_natural).unwrap();
    a.integrate(20.0 * h, &mut [], |_| {}).unwrap();
    b.integrate(20.0 * h_natural, &mut [], |_| {}).unwrap();
    assert_eq!(a.stats(), b.stats());
    close(&a.state(), &b.state());
}

/// The gallery's four-bar with its second closure row written in another unit (a factor `unit`):
/// the same constraint, g_y·unit = 0.
#[mechanism]
pub mod four_bar_mixed {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
        pub theta3: f64,
    }

    pub struct FourBar {
        pub l1: f64,
        pub l2: f64,
        pub l3: f64,
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub d: f64,
        pub g: f64,
        pub unit: f64,
    }

    #[rigid_body(mass = m1, inertia = m1 * l1 * l1 / 12.0)]
    fn crank() -> Planar {
        planar(vec2(theta1.cos(), theta1.sin()) * (0.5 * l1), theta1)
    }

    #[rigid_body(mass = m2, inertia = m2 * l2 * l2 / 12.0)]
    fn coupler() -> Planar {
        let tip = vec2(theta1.cos(), theta1.sin()) * l1;
        planar(tip + vec2(theta2.cos(), theta2.sin()) * (0.5 * l2), theta2)
    }

    #[rigid_body(mass = m3, inertia = m3 * l3 * l3 / 12.0)]
    fn rocker() -> Planar {
        planar(
            vec2(d, 0.0) + vec2(theta3.cos(), theta3.sin()) * (0.5 * l3),
            theta3,
        )
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[constraint]
    fn joint_b_x() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).x - rocker.point(vec2(0.5 * l3, 0.0)).x
    }

    #[constraint]
    fn joint_b_y() -> f64 {
        (coupler.point(vec2(0.5 * l2, 0.0)).y - rocker.point(vec2(0.5 * l3, 0.0)).y) * unit
    }
}

#[test]
fn the_schur_complement_of_constraints_in_different_units_is_not_refused() {
    // R M⁻¹ Rᵀ with one row scaled by 1e-9 (and 1e9): its diagonal entries 1e18 apart, refused while
    // the pivots were compared with the largest diagonal entry. The constraint is the same, so are
    // q̈, the constraint forces and the projection.
    let (plain, s) = four_bar::linkage();
    let reference = plain.accelerations(&s).unwrap().to_array();
    for unit in [1e-9, 1e9] {
        let sys = four_bar_mixed::FourBar {
            l1: plain.l1,
            l2: plain.l2,
            l3: plain.l3,
            m1: plain.m1,
            m2: plain.m2,
            m3: plain.m3,
            d: plain.d,
            g: plain.g,
            unit,
        };
        let q = four_bar_mixed::Coords::from_array(s.q.to_array());
        let v = four_bar_mixed::Coords::from_array(s.v.to_array());
        let state = four_bar_mixed::State::new(s.t, q, v);
        let a = sys
            .accelerations(&state)
            .expect("rows in other units")
            .to_array();
        for k in 0..3 {
            // The KKT solve's round-off, κ(R M⁻¹ Rᵀ) ε relative after the rows are equilibrated.
            assert!(
                (a[k] - reference[k]).abs() <= 1e-12 * reference[k].abs().max(1.0),
                "{a:?} vs {reference:?}"
            );
        }
        // The projection after a step solves with the same Schur matrix.
        let mut stepped = state;
        sys.step::<Rk4>(&mut stepped, 1e-3).expect("projected step");
    }
}

#[mechanism]
pub mod chain_micro {
    pub const LINKS: usize = 16;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        /// The unit of the odd links' angles, in radians.
        pub unit: f64,
    }

    /// Link i hangs from link i − 1; the odd links' angles are measured in `unit`.
    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let angle = if i % 2 == 0 {
            theta[i]
        } else {
            theta[i] * unit
        };
        let link = vec2(angle.sin(), -angle.cos()) * l;
        if i == 0 {
            link
        } else {
            bob[i - 1] + link
        }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn the_tree_recursion_takes_coordinates_in_any_units() {
    // A 16-link chain, whose q̈ comes from the articulated-body recursion: with the odd links'
    // angles in microradians their diagonal entries of M are 1e-12 of the even ones' (and 16
    // times less at the tip), refused while each pivot was compared with M's largest diagonal
    // entry. q̈ is the radian chain's, rescaled.
    use chain_micro::{Chain, Coords, State};
    let unit = 1e-6;
    let radians = Chain {
        m: 0.5,
        l: 0.3,
        g: 9.81,
        unit: 1.0,
    };
    let micro = Chain { unit, ..radians };
    let angles: [f64; 16] = std::array::from_fn(|i| 0.4 * (i as f64 * 0.7).sin());
    let rates: [f64; 16] = std::array::from_fn(|i| 0.2 * (i as f64 * 1.3).cos());
    let in_unit = |x: [f64; 16]| -> [f64; 16] {
        std::array::from_fn(|i| if i % 2 == 1 { x[i] / unit } else { x[i] })
    };
    let s = State::new(0.0, Coords { theta: angles }, Coords { theta: rates });
    let s_micro = State::new(
        0.0,
        Coords {
            theta: in_unit(angles),
        },
        Coords {
            theta: in_unit(rates),
        },
    );
    let a = radians.accelerations(&s).unwrap().theta;
    let b = micro
        .accelerations(&s_micro)
        .expect("microradians refused")
        .theta;
    let b_radians: [f64; 16] = std::array::from_fn(|i| if i % 2 == 1 { b[i] * unit } else { b[i] });
    let size = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..16 {
        // The recursion's round-off over 16 bodies against the rescaling's rounding: 1e-11 of the
        // largest entry.
        assert!(
            (a[i] - b_radians[i]).abs() <= 1e-11 * size,
            "{i}: {} vs {}",
            a[i],
            b_radians[i]
        );
    }
}

/// The squeezer in `units`, at rest at Hairer & Wanner's start.
fn squeezer_in(units: &Units) -> (squeezer::Squeezer, squeezer::State) {
    let sys = andrews_in(|value, [l, m, t]| units.express(value, units::dim(l, m, t)));
    (sys, squeezer_model::start())
}

#[test]
fn the_variational_integrator_steps_the_squeezer_at_small_steps() {
    // At h = 1e-6 s the position rows g(q₁)/h of the discrete Euler–Lagrange system are resolved to
    // about ε·|x|/h ≈ 1e-11: a Newton iteration whose increments had to fall below 4ε·max(1, |x|)
    // in absolute terms never got there (NewtonDiverged with a residual of 1e-11). Measured
    // against the positions' own size over h, it converges in two or three iterations at every h;
    // so do the collocation methods.
    let (sys, s) = squeezer_in(&units::SI);
    for h in [1e-7, 1e-6, 1e-5, 1e-4] {
        let mut v = s;
        let counts = Variational::step_with_stats(&sys, &mut v, h).expect("variational step");
        assert!(counts.iterations <= 4, "h = {h}: {counts:?}");
        for mut state in [s, s] {
            GaussLegendre2::step_with_stats(&sys, &mut state, h).expect("Gauss-Legendre step");
        }
        let mut m = s;
        ImplicitMidpoint::step_with_stats(&sys, &mut m, h).expect("midpoint step");
        // The crank turns by ½ β̈ h² in the first step (β̈(0) = 14222.44 rad/s², Hairer & Wanner).
        let turned = v.q.beta - START[0];
        assert!(
            (turned / (0.5 * 14222.443919954 * h * h) - 1.0).abs() < 1e-2,
            "h = {h}: {turned}"
        );
    }
}

/// The systems of units every Newton driver is checked in: time alone over fifteen orders, and
/// length and mass with it.
fn rescalings() -> Vec<Units> {
    let mut all = Vec::new();
    for k in [-6, -3, 3, 6, 9] {
        let x = 10f64.powi(k);
        all.push(Units {
            time: x,
            ..units::SI
        });
        all.push(Units {
            length: x,
            ..units::SI
        });
        all.push(Units {
            mass: x,
            ..units::SI
        });
    }
    all.push(Units {
        length: 1e-3,
        mass: 1e3,
        time: 1e-3,
    });
    all.push(Units {
        length: 1e6,
        mass: 1e-6,
        time: 1e9,
    });
    all
}

#[test]
fn every_newton_driver_takes_the_same_iterations_in_any_units() {
    // The squeezer (constrained, 7 + 6) through the variational integrator (RATTLE on its discrete
    // Euler-Lagrange equations), Gauss–Legendre 2 and implicit midpoint (the simplified Newton
    // iteration with its kept matrix, and the velocity recovery) and Radau5, 10 steps of 2e-5 s
    // from the start; the Cartesian pendulum through Störmer–Verlet's RATTLE position stage; the
    // spinning hoop (rheonomic: its velocity recovery is a Newton iteration) through
    // Gauss–Legendre 2. Every count is the same in every system of units.
    let h = 2e-5;
    let reference = squeezer_counts(&units::SI, h);
    let (pendulum, hoop) = (pendulum_counts(&units::SI), hoop_counts(&units::SI));
    for u in rescalings() {
        assert_eq!(squeezer_counts(&u, h), reference, "{}", u.label());
        assert_eq!(pendulum_counts(&u), pendulum, "{}", u.label());
        assert_eq!(hoop_counts(&u), hoop, "{}", u.label());
    }
}

/// `n` steps of the solver's h each (never shortened to land on an end time: whether t₀ + k·h
/// rounds to the same end in every system of units is no question for the methods).
fn steps<M: Mechanism<N>, Me: Method<N>, const N: usize>(solver: &mut Stepper<M, Me, N>, n: usize) {
    for _ in 0..n {
        solver.step(f64::MAX).expect("step");
    }
}

/// Newton iterations, Jacobians and factorisations of each method over 10 steps of the squeezer.
fn squeezer_counts(u: &Units, h_si: f64) -> Vec<(usize, usize, usize)> {
    let (sys, s) = squeezer_in(u);
    let h = u.express(h_si, units::TIME);
    let end = 10.0 * h;
    let mut counts = Vec::new();
    macro_rules! fixed {
        ($method:ty) => {{
            let mut solver = Stepper::new(&sys, <$method>::with_step(h), &s).unwrap();
            steps(&mut solver, 10);
            let st = solver.stats();
            counts.push((st.newton_iterations, st.jacobians, st.factorizations));
        }};
    }
    fixed!(Variational);
    fixed!(GaussLegendre2);
    fixed!(ImplicitMidpoint);
    // Radau5 from the state 10 steps on, where every velocity is nonzero: its error is measured
    // against atol + rtol·|y|, and only with atol negligible (1e-300) beside every |y| is that
    // measure the same in every system of units (a scalar atol has no single unit when the
    // components have several); at rest it would be atol alone for the velocities.
    let mut moving = s;
    for _ in 0..10 {
        sys.step::<GaussLegendre2>(&mut moving, h).unwrap();
    }
    let settings = Radau5 {
        h_init: Some(h),
        ..Radau5::new(1e-8, 1e-300)
    };
    let mut radau = Stepper::new(&sys, settings, &moving).unwrap();
    let end = moving.t + end;
    radau.integrate(end, &mut [], |_| {}).expect("Radau5");
    let st = radau.stats();
    counts.push((st.newton_iterations, st.jacobians, st.factorizations));
    counts.push((st.accepted, st.rejected, st.evaluations));
    counts
}

/// Störmer–Verlet's counts over 50 steps of the gallery's Cartesian pendulum in `u`.
fn pendulum_counts(u: &Units) -> (usize, usize, usize) {
    use cartesian_pendulum::cartesian_pendulum::{CartesianPendulum, Coords, State};
    use units::{ACCELERATION, LENGTH, MASS};
    let sys = CartesianPendulum {
        m: u.express(1.5, MASS),
        l: u.express(0.8, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let (x, y) = (0.8 * 0.6, -0.8 * 0.8);
    let speed = u.express(1.0, units::dim(1, 0, -1));
    let s = State::new(
        0.0,
        Coords {
            x: u.express(x, LENGTH),
            y: u.express(y, LENGTH),
        },
        Coords {
            x: speed * 0.8,
            y: speed * 0.6,
        },
    );
    let h = u.express(1e-3, units::TIME);
    let mut solver = Stepper::new(&sys, StormerVerlet::with_step(h), &s).unwrap();
    steps(&mut solver, 50);
    let st = solver.stats();
    (st.newton_iterations, st.jacobians, st.factorizations)
}

/// Gauss–Legendre 2's counts over 50 steps of the gallery's spinning hoop in `u`.
fn hoop_counts(u: &Units) -> (usize, usize, usize) {
    use spinning_hoop::spinning_hoop::{Coords, SpinningHoop, State};
    use units::{ACCELERATION, LENGTH, MASS, RATE};
    let sys = SpinningHoop {
        m: u.express(0.2, MASS),
        r: u.express(0.5, LENGTH),
        omega: u.express(7.0, RATE),
        g: u.express(9.81, ACCELERATION),
    };
    let s = State::new(
        0.0,
        Coords { theta: 0.4 },
        Coords {
            theta: u.express(0.3, RATE),
        },
    );
    let h = u.express(1e-3, units::TIME);
    let mut solver = Stepper::new(&sys, GaussLegendre2::with_step(h), &s).unwrap();
    steps(&mut solver, 50);
    let st = solver.stats();
    (st.newton_iterations, st.jacobians, st.evaluations)
}
