//! RATTLE on declared mechanisms: the variational integrator on the four-bar linkage (two
//! `#[constraint]` loop closures on rigid bodies in angles, so a mass matrix that varies with q),
//! and the kinds of constraint rows `#[mechanism]` declares deciding which methods apply.

use lagrange_gallery::scenes::four_bar;

use lagrange::constraints::constraint_rows;
use lagrange::prelude::*;
use lagrange::Variational;

#[test]
fn variational_rattle_keeps_the_four_bar_closed_and_its_energy_bounded() {
    let (sys, mut s) = four_bar::linkage();
    let e0 = sys.energy(&s).unwrap();
    let h = 1e-3;
    let (mut closure, mut closure_rate, mut energy) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..2000 {
        sys.step::<Variational>(&mut s, h).unwrap();
        let rows = constraint_rows(&sys, s.t, &s.q.to_array(), &s.v.to_array());
        for i in 0..2 {
            closure = closure.max(rows.value[i].abs());
            closure_rate = closure_rate.max(rows.rate[i].abs());
        }
        energy = energy.max((sys.energy(&s).unwrap() - e0).abs());
    }
    eprintln!(
        "four-bar, 2000 variational steps of h = {h}: |g| ≤ {closure:.2e} m, |ġ| ≤ {closure_rate:.2e} m/s, \
         |E − E₀| ≤ {energy:.2e} J (E₀ = {e0:.4} J)"
    );
    // The position stage solves g(q₁) = 0 with the step by Newton to round-off, the velocity stage
    // projects q̇₁ exactly onto ġ = 0: both at round-off of lengths ~3 m, at every step.
    assert!(
        closure < 1e-10 && closure_rate < 1e-10,
        "{closure:e}, {closure_rate:e}"
    );
    // Symplectic, order 2: the energy error stays O((hΩ)²)·T with Ω ≲ 10 rad/s the fastest bar rate
    // and T ≲ 50 J the kinetic energy along this run: ≲ 5e-3 J at h = 1e-3.
    assert!(energy < 5e-3, "{energy:e}");
}

#[mechanism]
pub mod rail {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Rail {
        pub m: f64,
    }
    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(x, y)
    }
    /// Moves along x only, as a velocity constraint.
    #[velocity_constraint]
    fn along_x() -> f64 {
        bead_dot.y
    }
}

#[mechanism]
pub mod floor {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Floor {
        pub m: f64,
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
    #[unilateral]
    fn above() -> f64 {
        y
    }
}

#[test]
fn the_declared_kinds_decide_which_constraints_rattle_refuses() {
    use lagrange::constraints::ConstraintCounts;
    // What #[mechanism] declares: the four-bar's two holonomic rows, the rail's velocity row, the
    // floor's unilateral row.
    let counts = |holonomic, velocity, unilateral| ConstraintCounts {
        holonomic,
        velocity,
        unilateral,
        friction: 0,
    };
    assert_eq!(
        <four_bar::four_bar::FourBar as lagrange::mechanism::Dynamics<3>>::CONSTRAINT_COUNTS,
        Some(counts(2, 0, 0))
    );
    assert_eq!(
        <rail::Rail as lagrange::mechanism::Dynamics<2>>::CONSTRAINT_COUNTS,
        Some(counts(0, 1, 0))
    );
    assert_eq!(
        <floor::Floor as lagrange::mechanism::Dynamics<2>>::CONSTRAINT_COUNTS,
        Some(counts(0, 0, 1))
    );
    // Refused at once, the state left alone; RK4 takes the same steps.
    let start = rail::State::new(
        0.0,
        rail::Coords { x: 0.0, y: 0.0 },
        rail::Coords { x: 1.0, y: 0.0 },
    );
    for err in [
        rail::Rail { m: 1.0 }.step::<StormerVerlet>(&mut start.clone(), 0.01),
        rail::Rail { m: 1.0 }.step::<Variational>(&mut start.clone(), 0.01),
    ]
    .map(|r| r.unwrap_err())
    {
        assert!(err.to_string().contains("1 velocity"), "{err}");
    }
    rail::Rail { m: 1.0 }
        .step::<Rk4>(&mut start.clone(), 0.01)
        .unwrap();
    // The floor's unilateral row: a single step goes through the contact loop, which holds the
    // contact mode over the step (the closed contact a RATTLE row for it): resting on the floor
    // (λ = m g > 0) the ball stays, y and ẏ at round-off.
    let resting = floor::State::new(
        0.0,
        floor::Coords { x: 0.0, y: 0.0 },
        floor::Coords { x: 0.0, y: 0.0 },
    );
    let sys = floor::Floor { m: 1.0, g: 9.81 };
    for step in [
        (|sys, s| sys.step::<StormerVerlet>(s, 0.01)) as fn(&floor::Floor, &mut floor::State) -> _,
        |sys, s| sys.step::<Variational>(s, 0.01),
    ] {
        let mut s = resting;
        for _ in 0..10 {
            step(&sys, &mut s).unwrap();
        }
        assert!(
            (s.t - 0.1).abs() < 1e-15 && s.q.y.abs() < 1e-15 && s.v.y.abs() < 1e-15,
            "{s:?}"
        );
    }
    // A stepper carries the same contact mode from step to step: the ball stays at rest.
    use lagrange::integrate::Fixed;
    let rests = |s: floor::State| {
        assert!(
            (s.t - 0.1).abs() < 1e-15 && s.q.y.abs() < 1e-15 && s.v.y.abs() < 1e-15,
            "{s:?}"
        )
    };
    let mut verlet = Stepper::new(&sys, Fixed::<StormerVerlet>::new(0.01), &resting).unwrap();
    rests(verlet.integrate(0.1, &mut [], |_| {}).unwrap().state);
    let mut variational = Stepper::new(&sys, Fixed::<Variational>::new(0.01), &resting).unwrap();
    rests(variational.integrate(0.1, &mut [], |_| {}).unwrap().state);
}
