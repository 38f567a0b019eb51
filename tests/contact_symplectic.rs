//! Unilateral contacts with the symplectic methods, Störmer–Verlet and the variational integrator,
//! in the contact stepper's event loop (`ContactRk4::step_with`, and a single `sys.step`): with the
//! contact mode held over a step, a closed contact is a holonomic row that RATTLE enforces; the
//! loop releases it where its multiplier crosses 0 and closes it where its gap does.
//!
//! - A particle sliding off a sphere declared `#[unilateral]` (the gallery's `sphere_release`):
//!   its release time against the closed form (Goldstein, Poole & Safko, *Classical Mechanics*,
//!   3rd ed., §2.4) at the methods' order 2, against the same sphere declared `#[constraint]`
//!   stepped by the same method with an event on its multiplier (position, cost), and its energy
//!   while in contact.
//! - A pendulum on a string (a `#[unilateral]` taut length) swinging for many periods: the string
//!   stays taut and the energy error stays bounded, as on a bilateral constraint.
//! - A ball dropped on a `#[unilateral]` floor: impact at √(2h/g).
//! - Friction is refused, naming what integrates it, and the state is left as it was.

use lagrange::constraints::{constraint_forces, ContactOptions, RowMode};
use lagrange::integrate::{Direction, Event, Fixed, Stats, Stepper, StopReason};
use lagrange::prelude::*;
use lagrange::{Integrator, StormerVerlet, Variational};
use lagrange_gallery::scenes::rough_ramp::rough_ramp;
use lagrange_gallery::scenes::sphere_release::{sphere_release as unilateral, Release};

mod contact_scenes;
use contact_scenes::{ball, bilateral};

const M: f64 = 0.7;
const R: f64 = 1.5;
const G: f64 = 9.81;

/// Released at rest near the top (cos θ* = ⅔ cos θ₀), and from the top at two speeds.
const STARTS: [Release; 3] = [
    Release {
        r: R,
        g: G,
        theta0: 0.1,
        v0: 0.0,
    },
    Release {
        r: R,
        g: G,
        theta0: 0.0,
        v0: 0.5,
    },
    Release {
        r: R,
        g: G,
        theta0: 0.0,
        v0: 1.2,
    },
];

/// The unilateral sphere stepped by `I` in the contact loop with step h up to its release: the
/// release time, the cost, and the largest energy error |E − E₀| at the steps before it.
fn unilateral_release<I: Integrator>(start: Release, h: f64) -> (f64, Stats, f64) {
    use unilateral::{Coords, SphereRelease, State};
    let sys = SphereRelease { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let s = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let e0 = sys.energy(&s).expect("energy");
    let mut contact = Stepper::new(&sys, I::with_step(h), &s).expect("stepper");
    assert_eq!(contact.contacts().mode().rows, [RowMode::Active]);
    let mut energy = 0.0f64;
    loop {
        contact.step(f64::INFINITY).expect("step");
        if !contact.mode_changes().is_empty() {
            break;
        }
        let s = contact.state();
        energy = energy.max((sys.energy(&s).expect("energy") - e0).abs());
    }
    let change = contact.mode_changes()[0];
    assert_eq!(
        (change.constraint, change.from, change.to),
        ("surface", RowMode::Active, RowMode::Inactive)
    );
    (change.t, contact.stats(), energy)
}

/// The bilateral sphere stepped by `I` ([`FixedStepper`], step h), stopped where its multiplier
/// falls through 0 (an event located on the cubic Hermite dense output): the time and the cost.
fn bilateral_release<I: Integrator>(start: Release, h: f64) -> (f64, Stats) {
    use bilateral::{Coords, Sphere, State};
    let sys = Sphere { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let s = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let normal = |s: &State| constraint_forces(&sys, s).expect("forces").multipliers[0];
    let mut events = [Event::new(&normal).direction(Direction::Falling).terminal()];
    let mut solver = Stepper::new(&sys, Fixed::<I>::new(h), &s).expect("solver");
    let outcome = solver
        .integrate(10.0, &mut events, |_| {})
        .expect("integration");
    let StopReason::Event(hit) = outcome.reason else {
        panic!("the particle did not leave: {:?}", outcome.reason)
    };
    (hit.state.t, outcome.stats)
}

/// The methods, for the loops below: name, unilateral run, bilateral run.
type UnilateralRun = fn(Release, f64) -> (f64, Stats, f64);
type BilateralRun = fn(Release, f64) -> (f64, Stats);
const METHODS: [(&str, UnilateralRun, BilateralRun); 2] = [
    (
        "Stormer-Verlet",
        unilateral_release::<StormerVerlet>,
        bilateral_release::<StormerVerlet>,
    ),
    (
        "variational",
        unilateral_release::<Variational>,
        bilateral_release::<Variational>,
    ),
];

#[test]
fn unilateral_sphere_with_verlet_and_variational_releases_at_second_order() {
    for start in STARTS {
        let (t_star, _) = start.release();
        for (name, unilateral, _) in METHODS {
            // The release time's error is the method's global error carried to λ (its event is
            // located on the method's own steps, to the event tolerance 1e-13·(|t| + h)): O(h²) for
            // both methods. Checked: halving h from 1e-2 divides the error by 2² (within [0.9, 1.1]
            // of it: the next term of the expansion is O(h⁴), ~1e-4 relative at these h), and at
            // h = 1e-3 the error is what h = 1e-2's predicts, scaled by 10⁻², within 10 %, plus
            // the event tolerance (2.2e-13).
            let [e1, e2, e3] = [1e-2, 5e-3, 1e-3].map(|h| unilateral(start, h).0 - t_star);
            let ratio = e1 / e2;
            eprintln!(
                "{name}, {start:?}: release error {e1:+.3e} (h = 1e-2), {e2:+.3e} (5e-3), \
                 {e3:+.3e} (1e-3); ratio {ratio:.3} (2² = 4)"
            );
            assert!(
                ratio > 0.9 * 4.0 && ratio < 1.1 * 4.0,
                "{name}: ratio {ratio}"
            );
            let predicted = 1.1 * e1.abs() * 1e-2 + 2.2e-13;
            assert!(e3.abs() < predicted, "{name}: {e3:e} against {predicted:e}");
        }
    }
}

#[test]
fn unilateral_sphere_releases_where_the_bilateral_multiplier_vanishes_at_the_same_cost() {
    // ω = √(g/R), the rate of the motion near the top; m g R the energy scale.
    let omega = (G / R).sqrt();
    let energy_scale = M * G * R;
    for start in STARTS {
        for (name, unilateral, bilateral) in METHODS {
            let mut energy_errors = [0.0; 2];
            for (k, h) in [1e-2, 1e-3].into_iter().enumerate() {
                let (tu, su, energy) = unilateral(start, h);
                let (tb, sb) = bilateral(start, h);
                eprintln!(
                    "{name}, h = {h}, {start:?}: unilateral release at {tu:.12} ({} steps, {} \
                     evaluations, {} Newton iterations), bilateral λ = 0 at {tb:.12} ({} steps, {} \
                     evaluations, {} Newton iterations, {} event evaluations); |E − E₀| ≤ \
                     {energy:.2e} J in contact",
                    su.accepted,
                    su.evaluations,
                    su.newton_iterations,
                    sb.accepted,
                    sb.evaluations,
                    sb.newton_iterations,
                    sb.event_evaluations
                );
                // In contact the held mode is the bilateral sphere: both take the same steps
                // (RATTLE on the same row), to round-off. They differ in where λ's zero is sought
                // within the last step: on the method's step of length τ from its start
                // (unilateral) and on the cubic Hermite interpolant of its ends (bilateral). Both
                // curves are the exact flow from the step's start up to the local error of an order
                // 2 method, ≲ h³|q⃛|/6 with |q⃛| ≲ g v/R ≈ 20 m/s³ here (v ≲ 3.2 m/s): ≲ 3.4 h³;
                // carried to λ's zero by |∂λ/∂(q, q̇)|₁/|λ̇| ≈ 7.6/32 (see tests/sphere_event.rs):
                // ≲ 0.8 h³. Asserted within h³.
                assert!((tu - tb).abs() < h * h * h, "{name}: {tu} against {tb}");
                // The cost: the bilateral declaration's steps, one more sub-step for the step cut
                // at the release, and the event location's trial steps (in the last step only).
                // Required within 2× of the bilateral run, its dense output and event location
                // included.
                assert!(su.accepted <= 2 * sb.accepted, "{name}: {su:?} {sb:?}");
                assert!(
                    su.evaluations + su.newton_iterations
                        <= 2 * (sb.evaluations + sb.newton_iterations + sb.event_evaluations),
                    "{name}: {su:?} {sb:?}"
                );
                // Symplectic on the constraint manifold, order 2: the energy error in contact
                // oscillates with an amplitude O((hω)²)·E, without drift. Asserted: below (hω)²·mgR
                // (constant 1 on the leading term), and falling as h² (×10⁻² from h = 1e-2 to
                // 1e-3, within [0.6, 1.6] of it: the next term of the error expansion).
                let bound = (h * omega).powi(2) * energy_scale;
                assert!(energy < bound, "{name}: {energy:e} against {bound:e}");
                energy_errors[k] = energy;
            }
            let ratio = energy_errors[0] / energy_errors[1];
            assert!(ratio > 60.0 && ratio < 160.0, "{name}: ratio {ratio}");
        }
    }
}

/// A pendulum on a string: the particle is held at most l from the pivot, a `#[unilateral]` row
/// that stays closed while the string is taut.
#[mechanism]
pub mod string_pendulum {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct StringPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The string can only pull.
    #[unilateral]
    fn string() -> f64 {
        l - bob.norm()
    }
}

#[test]
fn a_taut_string_keeps_the_energy_bounded_over_many_periods() {
    use string_pendulum::{Coords, State, StringPendulum};
    // Released at rest 1 rad from the bottom: the tension m(g cos θ + v²/l) stays above
    // m g cos 1 > 0, so the string stays taut and the held mode is the bilateral pendulum
    // throughout: RATTLE's map, symplectic on the circle.
    let (l, theta0, h) = (1.0, 1.0f64, 1e-2);
    let sys = StringPendulum { m: 0.5, l, g: G };
    let s = State::new(
        0.0,
        Coords {
            x: l * theta0.sin(),
            y: -l * theta0.cos(),
        },
        Coords { x: 0.0, y: 0.0 },
    );
    let e0 = sys.energy(&s).unwrap();
    for (name, step) in [
        (
            "Stormer-Verlet",
            (|sys, s, h| sys.step::<StormerVerlet>(s, h))
                as fn(&StringPendulum, &mut State, f64) -> _,
        ),
        ("variational", |sys, s, h| sys.step::<Variational>(s, h)),
    ] {
        let mut state = s;
        // 20 000 steps, 200 s: ~ 95 periods of 2.1 s.
        let mut worst = [0.0f64; 2];
        for k in 0..20_000 {
            step(&sys, &mut state, h).unwrap();
            let half = k / 10_000;
            worst[half] = worst[half].max((sys.energy(&state).unwrap() - e0).abs());
            // Taut: RATTLE solves |x| = l with the step by Newton to round-off, every step.
            let r = state.q.x.hypot(state.q.y);
            assert!(
                (r - l).abs() < 1e-12,
                "{name}: slack string at t = {}",
                state.t
            );
        }
        eprintln!(
            "{name}: |E − E₀| ≤ {:.3e} J over the first 100 s, {:.3e} J over the next (E₀ = {e0:.3} J)",
            worst[0], worst[1]
        );
        // Symplectic, order 2: the error oscillates with an amplitude O((hω)²)·E (ω = √(g/l)),
        // without drift; both halves of the run reach the same amplitude (to 10 %: the
        // oscillation's sampling), which a drift of even 1e-3 of it per period would exceed.
        let bound = h * h * G / l * sys.m * G * l;
        assert!(
            worst[0] < bound && worst[1] < 1.1 * worst[0],
            "{name}: {worst:?} against {bound:e}"
        );
    }
}

#[test]
fn ball_lands_on_time_with_verlet_and_variational() {
    // Constant accelerations between events: q is quadratic in t, which both methods integrate
    // exactly (Störmer–Verlet's q₁ = q₀ + h q̇₀ + (h²/2) q̈ and the midpoint discrete Euler–Lagrange
    // equations are exact for a constant force); the events are located to the event tolerance
    // 1e-13·(|t| + h) on exact steps. Asserted to 1e-12 (landing times, positions).
    fn ball_run<I: Integrator>(restitution: f64) -> (Vec<f64>, ball::State) {
        use ball::{Ball, Coords, State};
        let sys = Ball { m: 0.3, g: G };
        let s = State::new(0.0, Coords { x: 0.2, y: 1.3 }, Coords { x: 0.5, y: 0.0 });
        let options = ContactOptions {
            restitution,
            ..Default::default()
        };
        let mut contact = Stepper::new(&sys, I::with_step(1e-2), &s)
            .and_then(|solver| solver.with_contact_options(options))
            .expect("stepper");
        for _ in 0..150 {
            contact.step(f64::INFINITY).expect("step");
        }
        let landings = contact.mode_changes().iter().map(|c| c.t).collect();
        (landings, contact.state())
    }
    /// 150 single steps `sys.step::<I>` (each one contact-loop step from the state's own mode).
    fn ball_steps<I: Integrator>() -> ball::State {
        use ball::{Ball, Coords, State};
        let sys = Ball { m: 0.3, g: G };
        let mut s = State::new(0.0, Coords { x: 0.2, y: 1.3 }, Coords { x: 0.5, y: 0.0 });
        for _ in 0..150 {
            sys.step::<I>(&mut s, 1e-2).expect("step");
        }
        s
    }
    // The impact at √(2h/g) from h = 1.3 m.
    let t1 = (2.0 * 1.3 / G).sqrt();
    type Run = fn(f64) -> (Vec<f64>, ball::State);
    type Steps = fn() -> ball::State;
    let methods: [(&str, Run, Steps); 2] = [
        (
            "Stormer-Verlet",
            ball_run::<StormerVerlet>,
            ball_steps::<StormerVerlet>,
        ),
        (
            "variational",
            ball_run::<Variational>,
            ball_steps::<Variational>,
        ),
    ];
    for (name, run, steps) in methods {
        let (landings, s) = run(0.0);
        eprintln!("{name}: landed at {:?} (√(2h/g) = {t1:.15})", landings);
        assert_eq!(landings.len(), 1, "{name}: {landings:?}");
        assert!((landings[0] - t1).abs() < 1e-12, "{name}: {landings:?}");
        // Plastic: it stays on the floor, RATTLE holding y = 0 while x moves on.
        assert!(s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12 && (s.q.x - 0.95).abs() < 1e-12);
        // Bounces with e = 0.6: landings at t₁(1 + 2e + … + 2eᵏ⁻¹), two of them within 1.5 s.
        let (landings, _) = run(0.6);
        assert_eq!(landings.len(), 2, "{name}: {landings:?}");
        let (mut landing, mut flight) = (t1, 1.2 * t1);
        for t in &landings {
            assert!((t - landing).abs() < 1e-12, "{name}: {t} against {landing}");
            landing += flight;
            flight *= 0.6;
        }
        // A single sys.step takes the same route: at 1.5 s it rests where the stepper's run did.
        let s = steps();
        assert!((s.t - 1.5).abs() < 1e-12, "{name}: t = {}", s.t);
        assert!(
            s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12 && (s.q.x - 0.95).abs() < 1e-12,
            "{name}: {s:?}"
        );
    }
}

#[test]
fn friction_is_refused_by_the_symplectic_methods_naming_what_integrates_it() {
    use rough_ramp::{Coords, RoughRamp, State};
    let (alpha, u) = (0.5f64, 2.0);
    let sys = RoughRamp {
        m: 2.0,
        alpha,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
    };
    let start = State::new(
        0.0,
        Coords { x: 0.0, y: 0.0 },
        Coords {
            x: u * alpha.cos(),
            y: u * alpha.sin(),
        },
    );
    let check = |name: &str, result: lagrange::Result<()>, s: &State| {
        let err = result.expect_err(name);
        let text = err.to_string();
        eprintln!("{name}: {text}");
        assert!(
            matches!(err, Error::UnsuitableMethod { .. }),
            "{name}: {err:?}"
        );
        assert!(
            text.contains("1 friction") && text.contains("GaussLegendre2"),
            "{name}: {text}"
        );
        assert_eq!(*s, start, "{name}: the state changed");
    };
    let mut s = start;
    check(
        "sys.step::<StormerVerlet>",
        sys.step::<StormerVerlet>(&mut s, 1e-2),
        &s,
    );
    check(
        "sys.step::<Variational>",
        sys.step::<Variational>(&mut s, 1e-2),
        &s,
    );
    let result = Stepper::new(&sys, StormerVerlet::with_step(1e-2), &start)
        .and_then(|mut solver| solver.step(f64::INFINITY));
    check("a Störmer–Verlet solver", result, &s);
    // What the error names integrates it: Gauss–Legendre in the same loop.
    let mut solver = Stepper::new(&sys, GaussLegendre2::with_step(1e-2), &start).expect("solver");
    solver.step(f64::INFINITY).expect("Gauss-Legendre");
}

/// A ball in a box [0, a] × [0, b] under a tilted gravity (gₓ, −g_y): four unilateral walls, more
/// rows than coordinates, of which at most two close at once (a corner).
#[mechanism]
pub mod tilted_box {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct TiltedBox {
        pub m: f64,
        pub a: f64,
        pub b: f64,
        pub gx: f64,
        pub gy: f64,
    }

    #[particle(mass = m)]
    fn ball() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(gx, -gy)
    }

    #[unilateral]
    fn left() -> f64 {
        x
    }

    #[unilateral]
    fn right() -> f64 {
        a - x
    }

    #[unilateral]
    fn floor() -> f64 {
        y
    }

    #[unilateral]
    fn ceiling() -> f64 {
        b - y
    }
}

#[test]
fn ball_in_a_box_settles_in_the_corner_with_two_contacts_held_by_rattle() {
    use tilted_box::{Coords, State, TiltedBox};
    // From rest at (x₀, y₀): it lands on the floor at √(2y₀/g_y), plastic (only ẏ is lost: the
    // walls are frictionless), slides on, x = x₀ + gₓt²/2 all along, into the right wall at
    // √(2(a − x₀)/gₓ) = 1 s, and rests in the corner, both contacts closed: RATTLE's two rows fix
    // q there. The motion is quadratic in t between events, which both methods integrate exactly;
    // the events are located to 1e-13·(|t| + h): asserted to 1e-12.
    let sys = TiltedBox {
        m: 0.4,
        a: 2.0,
        b: 1.0,
        gx: 3.0,
        gy: G,
    };
    let (x0, y0) = (0.5, 0.8);
    let landing = (2.0 * y0 / G).sqrt();
    let against_wall = (2.0 * (sys.a - x0) / sys.gx).sqrt();
    fn run<I: Integrator>(sys: &TiltedBox, x0: f64, y0: f64) -> (Vec<(f64, &'static str)>, State) {
        let s = State::new(0.0, Coords { x: x0, y: y0 }, Coords { x: 0.0, y: 0.0 });
        let mut contact = Stepper::new(sys, I::with_step(1e-2), &s).expect("stepper");
        for _ in 0..150 {
            contact.step(f64::INFINITY).expect("step");
        }
        // The right wall and the floor closed, the others open.
        use RowMode::{Active, Inactive};
        assert_eq!(
            contact.contacts().mode().rows,
            [Inactive, Active, Active, Inactive]
        );
        (
            contact
                .mode_changes()
                .iter()
                .map(|c| (c.t, c.constraint))
                .collect(),
            contact.state(),
        )
    }
    for (name, (events, s)) in [
        ("Stormer-Verlet", run::<StormerVerlet>(&sys, x0, y0)),
        ("variational", run::<Variational>(&sys, x0, y0)),
    ] {
        eprintln!("{name}: {events:?}, at t = {}: {:?}", s.t, s.q);
        assert_eq!(events.len(), 2, "{name}: {events:?}");
        assert_eq!((events[0].1, events[1].1), ("floor", "right"));
        assert!((events[0].0 - landing).abs() < 1e-12, "{name}: {events:?}");
        assert!(
            (events[1].0 - against_wall).abs() < 1e-12,
            "{name}: {events:?}"
        );
        assert!(
            (s.q.x - sys.a).abs() < 1e-12
                && s.q.y.abs() < 1e-12
                && s.v.x.abs() < 1e-12
                && s.v.y.abs() < 1e-12,
            "{name}: {s:?}"
        );
    }
}
