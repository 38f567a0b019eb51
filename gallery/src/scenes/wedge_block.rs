//! The lecture's frictionless wedge and block: a block of mass m slides down the incline (angle α)
//! of a wedge of mass M that is itself free to slide on a frictionless floor. Generalized
//! coordinates: the wedge's position X and the block's distance d down the incline.
//!
//! Closed form (solve the two Lagrange equations; e.g. Kleppner & Kolenkow, problem 2.x, or the
//! lecture's generalized forces 𝓕_X = 0, 𝓕_d = m g sin α):
//!   Ẍ = −m g sin α cos α / (M + m sin²α),   d̈ = (M + m) g sin α / (M + m sin²α),
//! both constant, so X(t) = ½ Ẍ t², d(t) = ½ d̈ t² until the block reaches the floor. Note that
//! 𝓕_X = 0 does not mean Ẍ = 0 (the lecture's footnote): the momentum conjugate to X is conserved
//! instead, and it is zero when starting from rest.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod wedge_block {
    /// X: wedge position; d: block's distance down the incline.
    pub struct Coords {
        pub x: f64,
        pub d: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WedgeBlock {
        pub wedge_mass: f64,
        pub block_mass: f64,
        pub alpha: f64,
        pub h: f64,
        pub g: f64,
    }

    #[particle(mass = wedge_mass)]
    fn wedge() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = block_mass)]
    fn block() -> Vec2 {
        vec2(x + d * alpha.cos(), h - d * alpha.sin())
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

const SCENE: &str = "wedge and block";

pub fn run(plots: &Path) -> Vec<Check> {
    use wedge_block::{Coords, State, WedgeBlock};
    let sys = WedgeBlock {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
    };
    let (big_m, m, a, g) = (sys.wedge_mass, sys.block_mass, sys.alpha, sys.g);
    let den = big_m + m * a.sin().powi(2);
    let x_acc = -m * g * a.sin() * a.cos() / den;
    let d_acc = (big_m + m) * g * a.sin() / den;

    let mut s = State::at_rest(Coords { x: 0.0, d: 0.0 });
    let qdd = sys.accelerations(&s).expect("accelerations");
    let (h, steps) = (1e-3, 400);
    let mut trace = (Vec::new(), Vec::new());
    let mut worst_momentum = 0.0f64;
    // The wedge is a particle at its lower back corner: its outline, drawn as marks it carries.
    let mut film = Recorder::new(&sys).title(SCENE);
    film.mark("top", "wedge", &[0.0, sys.h])
        .and_then(|f| f.mark("toe", "wedge", &[sys.h / a.tan(), 0.0]))
        .and_then(|f| f.link("top", "toe")?.link("toe", "wedge"))
        .expect("the wedge's outline");
    film.push(&sys, &s).expect("a finite state");
    sys.simulate::<Rk4>(&mut s, h, steps, |s| {
        film.push(&sys, s).expect("a finite state");
        let bodies = sys.bodies(s);
        trace.0.push((bodies.wedge.x, bodies.wedge.y));
        trace.1.push((bodies.block.x, bodies.block.y));
        worst_momentum = worst_momentum.max(sys.momenta(s).expect("momenta").x.abs());
    })
    .expect("simulation");
    let t = s.t;
    let _ = film.write_html(plots.join("wedge_block.html"));
    let _ = plot::lines(
        &plots.join("wedge_block.svg"),
        "Wedge and block: paths from rest",
        "x",
        "y",
        &[Series::new("wedge", trace.0), Series::new("block", trace.1)],
    );
    // Accelerations: a few dozen flops from the same inputs, so agreement to ~1e-15 relative;
    // 1e-13 leaves room for the different order of operations.
    // Positions: the exact motion is quadratic in t, which RK4 integrates exactly; what remains is
    // round-off accumulated over 400 steps (≲ 400·ε ≈ 1e-13).
    vec![
        Check::new(SCENE, "wedge acceleration Ẍ", qdd.x, x_acc, 1e-13),
        Check::new(
            SCENE,
            "block acceleration d̈ along incline",
            qdd.d,
            d_acc,
            1e-13,
        ),
        Check::new(
            SCENE,
            format!("wedge position X(t = {t:.1})"),
            s.q.x,
            0.5 * x_acc * t * t,
            1e-12,
        ),
        Check::new(
            SCENE,
            format!("block distance d(t = {t:.1})"),
            s.q.d,
            0.5 * d_acc * t * t,
            1e-12,
        ),
        // p_X = ∂L/∂Ẋ is conserved (X is cyclic) and zero from rest: checked as an absolute error
        // against the momentum scale m·ḋ ≈ 2.6, round-off level.
        Check::new(
            SCENE,
            "max |p_X| over the run (conserved, 0)",
            worst_momentum,
            0.0,
            1e-12,
        ),
    ]
}
