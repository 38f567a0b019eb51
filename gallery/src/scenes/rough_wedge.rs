//! The lecture's wedge and block (Cross, Caltech Ph106, Lecture 4, eqs. (27)–(32); the frictionless
//! version is the `wedge_block` scene), now with Coulomb friction between block and wedge; the wedge
//! (mass M) still slides freely on a frictionless floor. Coordinates: the wedge's position X and the
//! block's position (bₓ, b_y). The wedge's face passes through (X, h) and slopes down at angle α; the
//! block touches it through a unilateral contact c = n·(b − (X, h)) ≥ 0, n = (sin α, cos α), with
//! friction on that contact, slip velocity s = t̂·(ḃ − (Ẋ, 0)), t̂ = (cos α, −sin α) (positive when
//! the block slides down the face).
//!
//! Closed form while the block slides down (derived here; Newton's laws for the two bodies, as in
//! Kleppner & Kolenkow, 2nd ed., problem 3.x for the frictionless case). With A the wedge's
//! (horizontal) acceleration, a_r the block's acceleration down the face relative to the wedge, N the
//! normal force and μₖN the friction on the block (up the face; down the face on the wedge):
//!   block along n:   m A sin α = N − m g cos α
//!   block along t̂:   m (A cos α + a_r) = m g sin α − μₖ N
//!   wedge along x:   M A = −N (sin α − μₖ cos α)
//! so, with k = sin α − μₖ cos α,
//!   A = −m g cos α · k / (M + m sin α · k),   N = m (g cos α + A sin α),
//!   a_r = g k − A (cos α + μₖ sin α),
//! all constant. At μₖ = 0 this is the frictionless A = −m g sin α cos α / (M + m sin²α). Friction
//! is internal: the total horizontal momentum M Ẋ + m ḃₓ stays 0 from rest, while the energy falls by
//! the work of friction, μₖ N times the distance slid, ½ a_r t². With tan α ≤ μₛ the block sticks
//! and, no horizontal external force acting, nothing moves.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::{constraint_forces, ConstraintForces, RowMode};
use lagrange::prelude::*;
use lagrange::Fixed;
use rough_wedge::{Coords, RoughWedge, State};
use std::path::Path;

#[mechanism]
pub mod rough_wedge {
    /// X: the wedge's position on the floor; (bx, by): the block's position.
    pub struct Coords {
        pub x: f64,
        pub bx: f64,
        pub by: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct RoughWedge {
        pub wedge_mass: f64,
        pub block_mass: f64,
        pub alpha: f64,
        /// Height of the face's top edge above the wedge's reference point.
        pub h: f64,
        pub g: f64,
        pub mu_k: f64,
        pub mu_s: f64,
    }

    #[particle(mass = wedge_mass)]
    fn wedge() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = block_mass)]
    fn block() -> Vec2 {
        vec2(bx, by)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The face pushes the block along its normal (sin α, cos α) and cannot pull.
    #[unilateral]
    fn face() -> f64 {
        (block.x - wedge.x) * alpha.sin() + (block.y - wedge.y - h) * alpha.cos()
    }

    /// Coulomb friction between block and face; slip velocity positive down the face.
    #[friction(on = face, kinetic = mu_k, stiction = mu_s)]
    fn face_friction() -> f64 {
        (block_dot.x - wedge_dot.x) * alpha.cos() - (block_dot.y - wedge_dot.y) * alpha.sin()
    }
}

const SCENE: &str = "wedge and block with friction";

/// How far down the face the block starts, at rest (m).
const START_DOWN_FACE: f64 = 0.3;

/// The closed form: (A, a_r, N) for coefficient μₖ.
fn closed_form(sys: &RoughWedge) -> (f64, f64, f64) {
    let (m, big_m, mu, g) = (sys.block_mass, sys.wedge_mass, sys.mu_k, sys.g);
    let (sn, cs) = sys.alpha.sin_cos();
    let k = sn - mu * cs;
    let big_a = -m * g * cs * k / (big_m + m * sn * k);
    let normal = m * (g * cs + big_a * sn);
    let a_r = g * k - big_a * (cs + mu * sn);
    (big_a, a_r, normal)
}

pub fn run(plots: &Path) -> Vec<Check> {
    // tan α = 0.546 > μₛ: the block slides.
    let sys = RoughWedge {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
        mu_k: 0.2,
        mu_s: 0.3,
    };
    let s0 = at_rest_on_face(&sys);
    let mut checks = slides_down(&sys, s0, plots);
    checks.push(frictionless_limit(&sys, s0));
    checks.extend(sticks(
        &RoughWedge {
            mu_k: 0.5,
            mu_s: 0.6,
            ..sys
        },
        s0,
    ));
    checks
}

/// Everything at rest, the block a distance d₀ down the face.
fn at_rest_on_face(sys: &RoughWedge) -> State {
    let (sn, cs) = sys.alpha.sin_cos();
    let d0 = START_DOWN_FACE;
    State::at_rest(Coords {
        x: 0.0,
        bx: d0 * cs,
        by: sys.h - d0 * sn,
    })
}

/// A stepper for `sys` from `s0` with RK4 of step 1 ms.
fn stepper(sys: &RoughWedge, s0: State) -> Stepper<'_, RoughWedge, Fixed<Rk4>, 3> {
    Stepper::new(sys, Rk4::with_step(1e-3), &s0).expect("stepper")
}

/// The film: the wedge is a particle at its lower back corner, its outline drawn as marks it carries.
fn film(sys: &RoughWedge) -> Recorder<RoughWedge, 3> {
    let (sn, cs) = sys.alpha.sin_cos();
    let mut film = Recorder::new(sys).title(SCENE);
    film.mark("top", "wedge", &[0.0, sys.h])
        .and_then(|f| f.mark("toe", "wedge", &[sys.h * cs / sn, 0.0]))
        .and_then(|f| f.link("top", "toe")?.link("toe", "wedge"))
        .expect("the wedge's outline");
    film
}

/// What a sliding run measured against the closed form.
struct Slide {
    end: State,
    starts_sliding: bool,
    mode_changes: usize,
    /// max |q − closed form| over the run.
    worst: f64,
    /// max |M Ẋ + m ḃₓ| over the run.
    worst_momentum: f64,
    /// E(0) − E(end).
    energy_lost: f64,
}

/// Slides the block down from `s0` for 1 s against the closed form, filming it and plotting the
/// two bodies' paths.
fn slide(sys: &RoughWedge, s0: State, plots: &Path) -> Slide {
    let (sn, cs) = sys.alpha.sin_cos();
    let (big_a, a_r, _) = closed_form(sys);
    let d0 = START_DOWN_FACE;
    let exact = |t: f64| {
        let x_wedge = 0.5 * big_a * t * t;
        let d = d0 + 0.5 * a_r * t * t;
        [x_wedge, x_wedge + d * cs, sys.h - d * sn]
    };
    let mut stepper = stepper(sys, s0);
    let starts_sliding = stepper.contacts().mode().rows == [RowMode::Active, RowMode::SlipPositive];
    let mut s = s0;
    let e0 = sys.energy(&s).expect("energy");
    let (mut worst, mut worst_momentum) = (0.0f64, 0.0f64);
    let (mut wedge_path, mut block_path) = (Vec::new(), Vec::new());
    let mut film = film(sys);
    film.push(sys, &s).expect("a finite state");
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).expect("step");
        s = stepper.state();
        film.push(sys, &s).expect("a finite state");
        let q = s.q.to_array();
        let e = exact(s.t);
        worst = (0..3).fold(worst, |acc, i| acc.max((q[i] - e[i]).abs()));
        let p = sys.momenta(&s).expect("momenta");
        worst_momentum = worst_momentum.max((p.x + p.bx).abs());
        let b = sys.bodies(&s);
        wedge_path.push((b.wedge.x, b.wedge.y));
        block_path.push((b.block.x, b.block.y));
    }
    let _ = film.write_html(plots.join("rough_wedge.html"));
    let _ = plot::lines(
        &plots.join("rough_wedge.svg"),
        "Wedge and block with friction (μₖ = 0.2): paths over 1 s from rest",
        "x",
        "y",
        &[
            Series::new("wedge", wedge_path),
            Series::new("block", block_path),
        ],
    );
    Slide {
        end: s,
        starts_sliding,
        mode_changes: stepper.mode_changes().len(),
        worst,
        worst_momentum,
        energy_lost: e0 - sys.energy(&s).expect("energy"),
    }
}

/// Sliding down from rest: positions, multipliers, momentum and energy against the closed form.
fn slides_down(sys: &RoughWedge, s0: State, plots: &Path) -> Vec<Check> {
    let (big_a, a_r, normal) = closed_form(sys);
    let run = slide(sys, s0, plots);
    let t = run.end.t;
    let f = constraint_forces(sys, &run.end).expect("forces");
    let dissipated = run.energy_lost;
    let friction_work = sys.mu_k * normal * 0.5 * a_r * t * t;
    println!(
        "{SCENE}: A = {big_a:.6} m/s², a_r = {a_r:.6} m/s², N = {normal:.6} N; |q − closed form| ≤ {:.1e} m \
         after {t:.0} s; λ = ({:.6}, {:.6}) N; energy lost {dissipated:.6} J vs μₖN·½a_r t² = {friction_work:.6} J",
        run.worst, f.multipliers[0], f.multipliers[1]
    );
    let mut checks = sliding_motion(&run);
    checks.extend(sliding_forces(sys, &f));
    checks.extend(sliding_balances(&run, friction_work));
    checks
}

/// The sliding run's mode and positions.
fn sliding_motion(run: &Slide) -> Vec<Check> {
    let t = run.end.t;
    vec![
        Check::new(
            SCENE,
            "block slides down the face from rest, no mode change (1 = yes)",
            f64::from(u8::from(run.starts_sliding && run.mode_changes == 0)),
            1.0,
            0.0,
        ),
        // Constant accelerations: RK4 integrates the quadratic motion exactly; round-off over 1000
        // steps of positions ~1 m.
        Check::new(
            SCENE,
            format!("max |q − closed form| over {t:.0} s (m)"),
            run.worst,
            0.0,
            1e-12,
        ),
    ]
}

/// The multipliers and the wedge's acceleration at the end of the sliding run.
fn sliding_forces(sys: &RoughWedge, f: &ConstraintForces<3, 4, 2>) -> Vec<Check> {
    let (big_a, _, normal) = closed_form(sys);
    vec![
        // The multipliers from the KKT solve (the friction row's coupled to the normal row's by
        // Coulomb's law, solved by LU) against the closed form: round-off.
        Check::new(
            SCENE,
            "normal force λ = N = m(g cos α + A sin α)",
            f.multipliers[0],
            normal,
            1e-12,
        ),
        Check::new(
            SCENE,
            "friction multiplier −μₖN (opposes the slip)",
            f.multipliers[1],
            -sys.mu_k * normal,
            1e-12,
        ),
        Check::new(
            SCENE,
            "wedge acceleration Ẍ = A",
            f.accelerations[0],
            big_a,
            1e-12,
        ),
    ]
}

/// The sliding run's momentum and energy balances; `friction_work` is μₖN · ½a_r t².
fn sliding_balances(run: &Slide, friction_work: f64) -> Vec<Check> {
    let t = run.end.t;
    vec![
        // Friction is internal and the floor frictionless: M Ẋ + m ḃₓ = 0 from rest; absolute error
        // against momenta ~ m a_r t ≈ 2 kg m/s, round-off.
        Check::new(
            SCENE,
            "max |M Ẋ + m ḃₓ| (horizontal momentum, 0 from rest)",
            run.worst_momentum,
            0.0,
            1e-12,
        ),
        // Energy lost = friction's work μₖN × distance slid: both exact for RK4 on this quadratic
        // motion, round-off of E ~ 10 J.
        Check::new(
            SCENE,
            format!("energy lost after {t:.0} s = μₖN · ½a_r t²"),
            run.energy_lost,
            friction_work,
            1e-11,
        ),
    ]
}

/// μ = 0 reproduces the frictionless textbook result.
fn frictionless_limit(sys: &RoughWedge, s0: State) -> Check {
    let (sn, cs) = sys.alpha.sin_cos();
    let smooth = RoughWedge {
        mu_k: 0.0,
        mu_s: 0.0,
        ..*sys
    };
    let a_smooth = sys.block_mass * sys.g * sn * cs / (sys.wedge_mass + sys.block_mass * sn * sn);
    let smooth_acc = constraint_forces(&smooth, &s0)
        .expect("forces")
        .accelerations[0];
    Check::new(
        SCENE,
        "μ = 0: Ẍ = −m g sin α cos α / (M + m sin²α)",
        smooth_acc,
        -a_smooth,
        1e-13,
    )
}

/// tan α ≤ μₛ: stuck, and with no horizontal external force nothing moves.
fn sticks(sys: &RoughWedge, s0: State) -> Vec<Check> {
    let mut stuck = stepper(sys, s0);
    let starts_stuck = stuck.contacts().mode().rows == [RowMode::Active, RowMode::Stick];
    let mut s_stuck = s0;
    for _ in 0..1000 {
        stuck.step(f64::INFINITY).expect("step");
        s_stuck = stuck.state();
    }
    let (q_end, q_start) = (s_stuck.q.to_array(), s0.q.to_array());
    let moved = (0..3).fold(0.0f64, |acc, i| acc.max((q_end[i] - q_start[i]).abs()));
    vec![
        // Sticking is enforced as a velocity constraint: nothing moves, to round-off.
        Check::new(
            SCENE,
            "tan α ≤ μₛ: max |q − q₀| after 1 s (m)",
            moved,
            0.0,
            1e-14,
        ),
        Check::new(
            SCENE,
            "tan α ≤ μₛ: stuck, no mode change (1 = yes)",
            f64::from(u8::from(starts_stuck && stuck.mode_changes().is_empty())),
            1.0,
            0.0,
        ),
    ]
}
