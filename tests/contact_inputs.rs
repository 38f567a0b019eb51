//! Inputs on a mechanism with contact rows: the contact mode held over a step — inferred at the
//! start, its accelerations stepped, projected onto, its events located and switched — evaluates
//! with the inputs the driven mechanism holds, in the fixed-step loop (`sys.driven(&u).step`, a
//! fixed-step `Stepper`) and the adaptive one (a Dopri5 `Stepper`), on the plain mechanism and
//! its validated handle (which prepares the affine constants).
//!
//! The scene: a block (a point mass m) on a rough table y ≥ 0 with Coulomb friction (stiction
//! μₛ, kinetic μₖ), pushed by an input force (fx, fy) held over each step. Closed forms (Coulomb's
//! law for a point contact; Stewart, "Rigid-body dynamics with friction and impact", SIAM Review
//! 42(1), 2000): at rest on the table with normal force N = m g − fy,
//! - |fx| ≤ μₛ N: the block sticks;
//! - |fx| > μₛ N: it slides from rest with ẍ = (fx − μₖ N sgn fx)/m;
//! - dropped from height y₀ with fy < 0 it lands at t* = √(2 y₀ / (g − fy/m)) and rests there on
//!   N = m g − fy (statics).
//!
//! Tolerances: between events the block's motion is a polynomial of degree 2 in t, which RK4 and
//! Dopri5 integrate exactly (both are exact on polynomials of degree ≤ 4); what is left is the
//! rounding of the steps (~1e-16 relative per step, ~1e-13 over 10³ steps) and the event location
//! (to 1e-13·(|t| + h) in the fixed-step loop, `EVENT_TIME_TOLERANCE` = 1e-13 on the adaptive
//! dense output). Each bound below is ~10² over that.

use lagrange::constraints::{constraint_forces, RowMode};
use lagrange::inputs::WithInputs;
use lagrange::prelude::*;
use lagrange::Fixed;

#[mechanism]
pub mod block {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Block {
        pub m: f64,
        pub g: f64,
        pub mu_k: f64,
        pub mu_s: f64,
    }

    /// The push on the block.
    #[inputs]
    pub struct Push {
        pub f: [f64; 2],
    }

    #[particle(mass = m)]
    fn body() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = body)]
    fn push() -> Vec2 {
        vec2(f[0], f[1])
    }

    /// The table pushes up and cannot pull.
    #[unilateral]
    fn table() -> f64 {
        body.y
    }

    #[friction(on = table, kinetic = mu_k, stiction = mu_s)]
    fn rub() -> f64 {
        body_dot.x
    }
}

use block::{Block, Coords, Push, State};

const BLOCK: Block = Block {
    m: 2.0,
    g: 9.81,
    mu_k: 0.4,
    mu_s: 0.5,
};
const H: f64 = 1e-3;

/// The weight m g.
fn weight() -> f64 {
    BLOCK.m * BLOCK.g
}

fn at_rest(x: f64, y: f64) -> State {
    State::at_rest(Coords { x, y })
}

fn push(fx: f64, fy: f64) -> Push {
    Push { f: [fx, fy] }
}

/// How the block is stepped with inputs held: `sys.step::<Rk4>` (the mode inferred at every
/// call), a fixed-step RK4 and Gauss–Legendre 2 `Stepper` (the latter on (q, p), through the
/// momenta and the canonical field of the held mode) and a Dopri5 `Stepper` (the mode held across
/// steps).
#[derive(Clone, Copy, Debug)]
enum Loop {
    Step,
    FixedStepper,
    GaussLegendre,
    Adaptive,
}

const LOOPS: [Loop; 4] = [
    Loop::Step,
    Loop::FixedStepper,
    Loop::GaussLegendre,
    Loop::Adaptive,
];

/// `s` advanced to `t_end` on `sys` driven by `u`, and the mode changes a solver recorded.
fn run<E: Mechanism<2, Coords = Coords>>(
    how: Loop,
    sys: &E,
    s: &mut State,
    t_end: f64,
) -> Vec<lagrange::constraints::ModeChange> {
    match how {
        Loop::Step => {
            while s.t < t_end - 0.5 * H {
                sys.step::<Rk4>(s, H).expect("step");
            }
            Vec::new()
        }
        Loop::FixedStepper => stepped(Stepper::new(sys, Fixed::<Rk4>::new(H), s), s, t_end),
        Loop::GaussLegendre => {
            let method = Fixed::<GaussLegendre2>::new(H);
            stepped(Stepper::new(sys, method, s), s, t_end)
        }
        Loop::Adaptive => stepped(Stepper::new(sys, Dopri5::default(), s), s, t_end),
    }
}

fn stepped<E: Mechanism<2, Coords = Coords>, Me: lagrange::integrate::Method<2>>(
    stepper: lagrange::Result<Stepper<'_, E, Me, 2>>,
    s: &mut State,
    t_end: f64,
) -> Vec<lagrange::constraints::ModeChange> {
    let mut stepper = stepper.expect("stepper");
    while stepper.t() < t_end {
        stepper.step(t_end).expect("step");
    }
    *s = stepper.state();
    stepper.mode_changes().to_vec()
}

/// Every loop, on the plain mechanism and on its validated handle, driven by `u`, from `start` to
/// `t_end`: the end states and mode changes, labelled.
fn every_run(
    u: &Push,
    start: State,
    t_end: f64,
) -> Vec<(String, State, Vec<lagrange::constraints::ModeChange>)> {
    let validated = BLOCK.validated().expect("valid");
    let mut out = Vec::new();
    for how in LOOPS {
        let mut s = start;
        let changes = run(how, &BLOCK.driven(u), &mut s, t_end);
        out.push((format!("{how:?}, plain"), s, changes));
        let mut s = start;
        let changes = run(how, &validated.driven(u), &mut s, t_end);
        out.push((format!("{how:?}, validated"), s, changes));
    }
    out
}

#[test]
fn a_push_below_static_friction_leaves_the_block_at_rest() {
    // |fx| = 0.9 μₛ m g: below stiction, above kinetic friction (μₖ m g = 0.8 μₛ m g), so a
    // block stepped without its inputs and one that slid would both be told apart from one that
    // sticks only by the static force balance. Stuck, q̈ = 0 solves the held mode's KKT system
    // to rounding (~1e-15 per step): |ẋ| < 1e-12 after 10³ steps.
    for fx in [0.9, -0.9].map(|k| k * BLOCK.mu_s * weight()) {
        for (label, s, changes) in every_run(&push(fx, 0.0), at_rest(0.0, 0.0), 1.0) {
            let moved = s.q.x.abs().max(s.q.y.abs());
            assert!(s.v.x.abs() < 1e-12 && moved < 1e-12, "{label}: {s:?}");
            assert!(changes.is_empty(), "{label}: {changes:?}");
        }
    }
}

#[test]
fn a_push_above_static_friction_slides_the_block_at_the_closed_form_acceleration() {
    // ẍ = (fx − μₖ m g sgn fx)/m from rest: x(1) = ẍ/2, ẋ(1) = ẍ, exact for RK4 and Dopri5 (a
    // quadratic in t) but for rounding: 1e-11 relative.
    let t_end = 1.0;
    for fx in [1.2, -1.2].map(|k| k * BLOCK.mu_s * weight()) {
        let a = (fx - BLOCK.mu_k * weight() * fx.signum()) / BLOCK.m;
        for (label, s, _) in every_run(&push(fx, 0.0), at_rest(0.0, 0.0), t_end) {
            let (x, v) = (0.5 * a * t_end * t_end, a * t_end);
            assert!(
                (s.q.x - x).abs() < 1e-11 * x.abs(),
                "{label}: {} against {x}",
                s.q.x
            );
            assert!(
                (s.v.x - v).abs() < 1e-11 * v.abs(),
                "{label}: {} against {v}",
                s.v.x
            );
            assert!(
                s.q.y.abs() < 1e-12,
                "{label}: the block left the table: {s:?}"
            );
        }
    }
}

#[test]
fn a_block_pushed_down_lands_at_the_closed_form_time_and_rests_on_the_statics_force() {
    // Dropped from y₀ with fy = −m g (twice the weight down): t* = √(2 y₀ / (g − fy/m)), the
    // event located to ≤ 1e-12 (see the module docs); without the input it would land at
    // √(2 y₀ / g), 0.41 times later.
    let (y0, fy) = (0.5, -weight());
    let t_star = (2.0 * y0 / (BLOCK.g - fy / BLOCK.m)).sqrt();
    let u = push(0.0, fy);
    for (label, s, changes) in every_run(&u, at_rest(0.0, y0), 1.0) {
        assert!(s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12, "{label}: {s:?}");
        if changes.is_empty() {
            // `sys.step` records no changes: only the rest on the table is checked.
            continue;
        }
        let landing = changes[0];
        assert_eq!(
            (landing.constraint, landing.from, landing.to),
            ("table", RowMode::Inactive, RowMode::Active),
            "{label}"
        );
        assert!(
            (landing.t - t_star).abs() < 1e-11,
            "{label}: landed at {} against {t_star}",
            landing.t
        );
    }
    // At rest, the table carries the weight and the push: N = m g − fy.
    let at_rest_there = at_rest(0.0, 0.0);
    let forces = constraint_forces(&WithInputs::new(&BLOCK, u.f), &at_rest_there).expect("forces");
    let normal = forces.cartesian[0][1];
    assert!(
        (normal - (weight() - fy)).abs() < 1e-12 * weight(),
        "N = {normal}"
    );
}

#[test]
fn a_push_lifting_more_than_the_weight_takes_the_block_off_the_table() {
    // fy = 1.5 m g up: the table would have to pull (N = m g − fy < 0), so the contact releases
    // at the start and the block rises at ÿ = (fy − m g)/m, a quadratic in t (exact to rounding).
    let fy = 1.5 * weight();
    let a = (fy - weight()) / BLOCK.m;
    for (label, s, _) in every_run(&push(0.0, fy), at_rest(0.0, 0.0), 0.5) {
        let y = 0.5 * a * 0.25;
        assert!(
            (s.q.y - y).abs() < 1e-11 * y,
            "{label}: {} against {y}",
            s.q.y
        );
    }
}

/// The block pushed with `fx` for t < t₁, then left alone, to `t_end`: a control loop making a
/// new driven mechanism at every step (`sys.step`), or a solver per held input.
fn push_then_release(how: Loop, fx: f64, t1: f64, t_end: f64) -> State {
    let sys = BLOCK.validated().expect("valid");
    let mut s = at_rest(0.0, 0.0);
    match how {
        Loop::Step => {
            while s.t < t_end - 0.5 * H {
                let u = if s.t < t1 - 0.5 * H { fx } else { 0.0 };
                sys.driven(&push(u, 0.0))
                    .step::<Rk4>(&mut s, H)
                    .expect("step");
            }
        }
        _ => {
            run(how, &sys.driven(&push(fx, 0.0)), &mut s, t1);
            run(how, &sys.driven(&push(0.0, 0.0)), &mut s, t_end);
        }
    }
    s
}

#[test]
fn inputs_changed_between_steps_are_held_over_each_and_change_the_motion() {
    // Pushed with fx = 1.2 μₛ m g for t₁ = 0.5, then released: it slides at a₁ = (fx − μₖ m g)/m
    // to ẋ₁ = a₁ t₁, decelerates at μₖ g to rest at t₁ + ẋ₁/(μₖ g) (inside the run), then sticks
    // (no push). x = a₁ t₁²/2 + ẋ₁²/(2 μₖ g). Each piece is a quadratic in t (exact but for
    // rounding); the stop is located to ≤ 1e-12 in time, where ẋ ≈ 0, so x is off by ≪ 1e-12:
    // 1e-10 relative.
    let (fx, t1, t_end) = (1.2 * BLOCK.mu_s * weight(), 0.5, 2.0);
    let a1 = (fx - BLOCK.mu_k * weight()) / BLOCK.m;
    let v1 = a1 * t1;
    let t_stop = t1 + v1 / (BLOCK.mu_k * BLOCK.g);
    assert!(t_stop < t_end - 0.1);
    let x = 0.5 * a1 * t1 * t1 + v1 * v1 / (2.0 * BLOCK.mu_k * BLOCK.g);
    for how in LOOPS {
        let s = push_then_release(how, fx, t1, t_end);
        assert!(
            (s.q.x - x).abs() < 1e-10 * x,
            "{how:?}: {} against {x}",
            s.q.x
        );
        assert!(s.v.x.abs() < 1e-12, "{how:?}: still moving, {s:?}");
    }
    // Held to the end instead, the block keeps sliding: the inputs set at each step are the ones
    // that act.
    let held = push_then_release(Loop::Step, fx, t_end + 1.0, t_end);
    assert!(
        (held.v.x - a1 * t_end).abs() < 1e-11 * a1 * t_end,
        "{held:?}"
    );
}

/// A ball on a frictionless floor, pushed down by an input: what RATTLE steps (it enforces
/// position rows only, so no friction row).
#[mechanism]
pub mod ball {
    pub struct Coords {
        pub y: f64,
    }

    pub struct Ball {
        pub m: f64,
        pub g: f64,
    }

    #[inputs]
    pub struct Push {
        pub f: f64,
    }

    #[particle(mass = m)]
    fn body() -> Vec2 {
        vec2(0.0, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = body)]
    fn push() -> Vec2 {
        vec2(0.0, f)
    }

    #[unilateral]
    fn floor() -> f64 {
        body.y
    }
}

/// The landing time of the ball dropped from y₀ with the push `f`, stepped by `I` with step `H`
/// on the validated handle driven by `f`.
fn landing<I: lagrange::Integrator>(y0: f64, f: f64) -> f64 {
    let sys = ball::Ball { m: 0.5, g: 9.81 }.validated().expect("valid");
    let driven = sys.driven(&ball::Push { f });
    let s = ball::State::at_rest(ball::Coords { y: y0 });
    let mut stepper = Stepper::new(&driven, Fixed::<I>::new(H), &s).expect("stepper");
    while stepper.mode_changes().is_empty() {
        stepper.step(f64::INFINITY).expect("step");
    }
    stepper.mode_changes()[0].t
}

#[test]
fn rattle_steps_a_contact_with_the_inputs_held() {
    // Störmer–Verlet and the variational integrator evaluate the forces through the equations of
    // motion and the momentum rate of the held mode (not its accelerations): with f = −2 m g the
    // ball lands at t* = √(2 y₀ / (g − f/m)) = √(2 y₀ / 3g). Both are exact on a trajectory
    // quadratic in t (velocity Verlet's updates are Taylor's to second order; the variational
    // integrator's midpoint quadrature of a constant force is exact), so the landing is off by
    // the event location alone (≤ 1e-12, see the module docs).
    let (y0, f): (f64, f64) = (0.5, -2.0 * 0.5 * 9.81);
    let t_star = (2.0 * y0 / (9.81 - f / 0.5)).sqrt();
    let verlet = landing::<StormerVerlet>(y0, f);
    let variational = landing::<Variational>(y0, f);
    for (name, t) in [("Störmer–Verlet", verlet), ("variational", variational)] {
        assert!(
            (t - t_star).abs() < 1e-11,
            "{name}: landed at {t} against {t_star}"
        );
    }
}
