//! A spatial arm of three rigid links, declared as the README writes robots — each link placed
//! from the one before by a joint and constant offsets — which the macro reads as a kinematic tree
//! and simulates by the articulated-body algorithm. Two closed-form facts check it:
//!
//! - **Swinging free**, the arm conserves its energy, and, since its first joint turns about the
//!   vertical, along which gravity acts, the momentum conjugate to that joint's angle: q₁ is
//!   cyclic (neither T nor V depends on it), so p₁ = ∂L/∂q̇₁, the arm's angular momentum about the
//!   vertical, is constant (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §2.6).
//! - **One link hinged about a horizontal axis** is a physical pendulum: released at rest from θ₀,
//!   its period is T = 4 K(sin(θ₀/2)) √(I_O / (m g d)), with I_O its moment of inertia about the
//!   hinge and d the distance from the hinge to its centre of mass (Landau & Lifshitz, *Mechanics*,
//!   §11 problem 1, with the pendulum's length replaced by I_O/(m d)).

use crate::plot::{self, Series};
use crate::{elliptic_k, Check};
use lagrange::animation::Recorder;
use lagrange::integrate::{Direction, Event, Observation, StopReason};
use lagrange::prelude::*;
use lagrange::Dop853;
use std::path::Path;

#[mechanism]
pub mod arm {
    /// The joints: the base about the vertical, shoulder and elbow about the links' y axes.
    pub struct Coords {
        pub base: f64,
        pub shoulder: f64,
        pub elbow: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Arm {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub d1: f64,
        pub d2: f64,
        pub d3: f64,
        /// The elbow's offset across the upper arm.
        pub e: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m1, inertia = [0.04, 0.04, 0.01])]
    fn column() -> Spatial {
        let r = rot_z(base);
        spatial(r * vec3(0.0, 0.0, 0.5 * d1), r)
    }

    #[rigid_body(mass = m2, inertia = [0.03, 0.03, 0.004])]
    fn upper() -> Spatial {
        let r = column.rotation * rot_y(shoulder);
        let joint = column.point(vec3(0.0, 0.0, 0.5 * d1));
        spatial(joint + r * vec3(0.0, 0.0, 0.5 * d2), r)
    }

    #[rigid_body(mass = m3, inertia = [0.02, 0.018, 0.003])]
    fn fore() -> Spatial {
        let r = upper.rotation * rot_y(elbow);
        let joint = upper.point(vec3(e, 0.0, 0.5 * d2));
        spatial(joint + r * vec3(0.0, 0.0, 0.5 * d3), r)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

#[mechanism]
pub mod hinged_link {
    pub struct Coords {
        pub theta: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct HingedLink {
        pub m: f64,
        pub d: f64,
        /// Principal moments about the centre of mass: about the hinge's axis first.
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
        pub g: f64,
    }

    /// Hinged about the world x axis at the origin, its centre of mass a distance d below.
    #[rigid_body(mass = m, inertia = [i1, i2, i3])]
    fn link() -> Spatial {
        let r = rot_x(theta);
        spatial(r * vec3(0.0, 0.0, -d), r)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

const SCENE: &str = "spatial arm (kinematic tree)";

pub fn run(plots: &Path) -> Vec<Check> {
    let mut checks = free_swing(plots);
    checks.extend(physical_pendulum());
    checks
}

/// The arm released with its base turning: energy and p₁ along the run.
fn free_swing(plots: &Path) -> Vec<Check> {
    use arm::{Arm, Coords, State};
    let sys = Arm {
        m1: 3.0,
        m2: 2.0,
        m3: 1.2,
        d1: 0.4,
        d2: 0.5,
        d3: 0.4,
        e: 0.06,
        g: 9.81,
    }
    .validated()
    .expect("valid parameters");
    let mut s = State::new(
        0.0,
        Coords {
            base: 0.0,
            shoulder: 1.1,
            elbow: -0.6,
        },
        Coords {
            base: 2.0,
            shoulder: 0.0,
            elbow: 0.5,
        },
    );
    let (e0, p0) = (
        sys.energy(&s).expect("energy"),
        sys.momenta(&s).expect("momenta").base,
    );
    let (mut times, mut drift) = (Vec::new(), Vec::new());
    // The base on the floor and the hand (the forearm's far end), whose path is drawn.
    let mut film = Recorder::new(&sys).title(SCENE);
    film.fixed_point("base", &[0.0, 0.0, 0.0])
        .and_then(|f| {
            f.link("base", "column")?
                .mark("hand", "fore", &[0.0, 0.0, 0.5 * sys.d3])
        })
        .and_then(|f| f.trail("hand"))
        .expect("the base and the hand");
    film.push(&sys, &s).expect("a finite state");
    let mut events = [];
    let t_end = 10.0;
    sys.integrate(Dop853::new(1e-12, 1e-12), &mut s, t_end, &mut events, |o| {
        if let Observation::Step { state, .. } = o {
            film.push(&sys, state).expect("a finite state");
            if let Ok(e) = sys.energy(state) {
                times.push(state.t);
                drift.push((e - e0) / e0.abs());
            }
        }
    })
    .expect("simulation");
    let _ = film.write_html(plots.join("spatial_arm.html"));
    let _ = plot::lines(
        &plots.join("spatial_arm_energy.svg"),
        "Spatial arm swinging free: relative energy error (Dop853, tol 1e-12)",
        "t",
        "(E − E₀)/|E₀|",
        &[Series::new(
            "energy error",
            times.iter().copied().zip(drift).collect(),
        )],
    );
    let (e, p) = (
        sys.energy(&s).expect("energy"),
        sys.momenta(&s).expect("momenta").base,
    );
    // Dop853 at tolerance 1e-12: the local errors are ~1e-12 of the state's scale per step and
    // accumulate over a few thousand steps to ~1e-10 relative; 1e-8 leaves a margin of 100.
    vec![
        Check::new(
            SCENE,
            format!("energy after {t_end} s swinging free"),
            e,
            e0,
            1e-8,
        ),
        Check::new(
            SCENE,
            "p₁ (momentum about the vertical) conserved",
            p,
            p0,
            1e-8,
        ),
    ]
}

/// One link hinged about a horizontal axis: its half period against 4K√(I_O/(m g d)) / 2.
fn physical_pendulum() -> Vec<Check> {
    use hinged_link::{Coords, HingedLink, State};
    let sys = HingedLink {
        m: 1.5,
        d: 0.35,
        i1: 0.02,
        i2: 0.025,
        i3: 0.01,
        g: 9.81,
    };
    let theta0 = 2.0_f64;
    let hinge_inertia = sys.i1 + sys.m * sys.d * sys.d;
    let period =
        4.0 * elliptic_k((theta0 / 2.0).sin()) * (hinge_inertia / (sys.m * sys.g * sys.d)).sqrt();
    let mut s = State::at_rest(Coords { theta: theta0 });
    // Half a period later the link stops at −θ₀: θ̇ rises through zero.
    let rate = |s: &State| s.v.theta;
    let mut events = [Event::new(&rate).direction(Direction::Rising).terminal()];
    let outcome = sys
        .integrate(
            Dop853::new(1e-12, 1e-12),
            &mut s,
            period,
            &mut events,
            |_| {},
        )
        .expect("simulation");
    let located = matches!(outcome.reason, StopReason::Event(_));
    // The event is located on Dop853's dense output (order 7) to the tolerance, ~1e-12 of the
    // period; 1e-9 leaves the margin of a few ulps of the elliptic integral and the root finder.
    vec![
        Check::new(
            SCENE,
            "hinged link: half period 2K(sin(θ₀/2))√(I_O/(m g d))",
            if located { s.t } else { f64::NAN },
            period / 2.0,
            1e-9,
        ),
        Check::new(
            SCENE,
            "hinged link: turns back at −θ₀",
            s.q.theta,
            -theta0,
            1e-9,
        ),
    ]
}
