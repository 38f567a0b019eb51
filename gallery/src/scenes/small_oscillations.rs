//! Small oscillations of the double pendulum (equal masses m and lengths l, the mechanism of
//! `double_pendulum.rs`) about its stable equilibrium: the normal modes from K v = ω² M v with M and
//! K from dual numbers. Closed form (Goldstein, 3rd ed., §6.4; Landau & Lifshitz §23, problem 1):
//! ω² = (2 ± √2) g/l, with mode shapes θ₂/θ₁ = ±√2 (in phase for the slow mode).

pub use super::double_pendulum as scene;

use crate::Check;
use lagrange::analysis::{equilibrium, normal_modes, EquilibriumOptions};
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use scene::double_pendulum::{Coords, DoublePendulum, State};
use std::path::Path;

const SCENE: &str = "double pendulum, normal modes";

pub fn run(plots: &Path) -> Vec<Check> {
    let (m, l, g): (f64, f64, f64) = (0.7, 1.3, 9.81);
    let sys = DoublePendulum {
        m1: m,
        m2: m,
        l1: l,
        l2: l,
        g,
    };
    // The equilibrium from a guess off it, by virtual work: every generalized force zero.
    let rest = equilibrium(
        &sys,
        0.0,
        &Coords {
            theta1: 0.3,
            theta2: -0.2,
        },
        &EquilibriumOptions::default(),
    )
    .map(|e| e.q)
    .unwrap_or(Coords {
        theta1: f64::NAN,
        theta2: f64::NAN,
    });
    let modes = normal_modes(&sys, 0.0, &rest).ok();
    let frequency = |j: usize| modes.as_ref().map_or(f64::NAN, |m| m.frequencies[j]);
    let shape = |j: usize| {
        modes
            .as_ref()
            .map_or(f64::NAN, |m| m.shapes[(1, j)] / m.shapes[(0, j)])
    };
    let root2 = std::f64::consts::SQRT_2;
    // The animation: the fast mode, released from its shape at 0.1 rad, for 4 s.
    if let Some(modes) = &modes {
        let amplitude = 0.1 / modes.shapes[(0, 1)];
        let mut s = State::at_rest(Coords {
            theta1: rest.theta1 + amplitude * modes.shapes[(0, 1)],
            theta2: rest.theta2 + amplitude * modes.shapes[(1, 1)],
        });
        let mut film = Recorder::new(&sys).title(SCENE);
        film.fixed_point("pivot", &[0.0, 0.0])
            .and_then(|f| f.link("pivot", "bob1")?.trail("bob2"))
            .expect("the pivot");
        if film.push(&sys, &s).is_ok()
            && sys
                .simulate::<Rk4>(&mut s, 1e-3, 4000, film.observer(&sys))
                .is_ok()
        {
            let _ = film.write_html(plots.join("small_oscillations.html"));
        }
    }
    // All four are exact algebra on M and K assembled from dual numbers: agreement to round-off of a
    // 2×2 symmetric eigenproblem (~1e-15 relative); 1e-12 leaves room for the Cholesky transform.
    vec![
        Check::new(SCENE, "equilibrium θ₁ (absolute)", rest.theta1, 0.0, 1e-12),
        Check::new(
            SCENE,
            "slow mode √(2 − √2)·√(g/l)",
            frequency(0),
            ((2.0 - root2) * g / l).sqrt(),
            1e-12,
        ),
        Check::new(
            SCENE,
            "fast mode √(2 + √2)·√(g/l)",
            frequency(1),
            ((2.0 + root2) * g / l).sqrt(),
            1e-12,
        ),
        Check::new(SCENE, "slow mode shape θ₂/θ₁ = √2", shape(0), root2, 1e-12),
        Check::new(
            SCENE,
            "fast mode shape θ₂/θ₁ = −√2",
            shape(1),
            -root2,
            1e-12,
        ),
    ]
}
