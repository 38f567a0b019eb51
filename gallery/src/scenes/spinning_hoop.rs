//! A bead on a circular hoop of radius R spun about its vertical diameter at a constant rate ω
//! (a rheonomic constraint written into the position: the hoop's azimuth is ωt). One coordinate, the
//! bead's angle θ from the bottom.
//!
//! For ω² > g/R the bottom is unstable and the bead rests at cos θ* = g/(ω²R) (Goldstein, 3rd ed.,
//! §2.6 exercise; Taylor, *Classical Mechanics*, §7.6). The hoop's motor does work, so T + V is not
//! conserved; the Jacobi integral h = ½mR²θ̇² − ½mR²ω²sin²θ − mgR cos θ is, because L has no explicit
//! t dependence once written in θ.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod spinning_hoop {
    /// The bead's angle from the bottom of the hoop.
    pub struct Coords {
        pub theta: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct SpinningHoop {
        pub m: f64,
        pub r: f64,
        pub omega: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec3 {
        let azimuth = omega * t;
        vec3(
            theta.sin() * azimuth.cos(),
            theta.sin() * azimuth.sin(),
            -theta.cos(),
        ) * r
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

const SCENE: &str = "bead on a spinning hoop";

/// A recorder of the hoop titled `title`: the vertical axis it turns about, through its top and
/// bottom, and the bead's path.
pub fn recorder(
    sys: &spinning_hoop::SpinningHoop,
    title: &str,
) -> Recorder<spinning_hoop::SpinningHoop, 1> {
    let mut film = Recorder::new(sys).title(title);
    film.fixed_point("top", &[0.0, 0.0, sys.r])
        .and_then(|f| {
            f.fixed_point("bottom", &[0.0, 0.0, -sys.r])?
                .link("top", "bottom")?
                .trail("bead")
        })
        .expect("the hoop's axis");
    film
}

pub fn run(plots: &Path) -> Vec<Check> {
    use spinning_hoop::{Coords, SpinningHoop, State};
    let sys = SpinningHoop {
        m: 0.2,
        r: 1.0,
        omega: 5.0,
        g: 9.81,
    };
    let (m, r, w, g) = (sys.m, sys.r, sys.omega, sys.g);
    let theta_star = (g / (w * w * r)).acos();

    // At rest at θ*: no acceleration, and the bead stays.
    let mut at_star = State::at_rest(Coords { theta: theta_star });
    let acc_star = sys.accelerations(&at_star).expect("accelerations").theta;
    sys.simulate::<Rk4>(&mut at_star, 1e-3, 2000, |_| {})
        .expect("simulation");

    // Released off the equilibrium: h conserved, T + V not.
    let jacobi = |theta: f64, theta_dot: f64| {
        0.5 * m * r * r * theta_dot * theta_dot
            - 0.5 * m * r * r * w * w * theta.sin().powi(2)
            - m * g * r * theta.cos()
    };
    let mut s = State::at_rest(Coords {
        theta: theta_star + 0.4,
    });
    let h0 = sys.energy_function(&s).expect("h");
    let h0_exact = jacobi(s.q.theta, s.v.theta);
    let (mut h_trace, mut e_trace, mut theta_trace) = (Vec::new(), Vec::new(), Vec::new());
    let mut film = recorder(&sys, SCENE);
    film.push(&sys, &s).expect("a finite state");
    sys.simulate::<Rk4>(&mut s, 1e-3, 10_000, |s| {
        film.push(&sys, s).expect("a finite state");
        h_trace.push((s.t, sys.energy_function(s).expect("h")));
        e_trace.push((s.t, sys.energy(s).expect("T + V")));
        theta_trace.push((s.t, s.q.theta));
    })
    .expect("simulation");
    let _ = film.write_html(plots.join("spinning_hoop.html"));
    let (e_min, e_max) = e_trace
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &(_, e)| (a.min(e), b.max(e)));
    println!("{SCENE}: T + V ranges over [{e_min:.4}, {e_max:.4}] J while h stays at {h0:.12} J");
    let _ = plot::lines(
        &plots.join("spinning_hoop_energy.svg"),
        "Bead on a spinning hoop: Jacobi integral h conserved, T + V not",
        "t",
        "J",
        &[Series::new("T + V", e_trace), Series::new("h", h_trace)],
    );
    let _ = plot::lines(
        &plots.join("spinning_hoop_theta.svg"),
        "Bead on a spinning hoop: oscillation about θ* = arccos(g/ω²R)",
        "t",
        "θ",
        &[
            Series::new("θ(t)", theta_trace),
            Series::new("θ*", vec![(0.0, theta_star), (10.0, theta_star)]),
        ],
    );
    vec![
        // θ̈(θ*) = sinθ*(ω² cosθ* − g/R) = 0 up to the round-off of cos(arccos(·)), ~1e-16·ω².
        Check::new(SCENE, "θ̈ at rest at θ* (absolute)", acc_star, 0.0, 1e-13),
        // Started exactly at equilibrium, RK4 stays there to round-off.
        Check::new(
            SCENE,
            "θ after 2 s at rest at θ* = arccos(g/ω²R)",
            at_star.q.theta,
            theta_star,
            1e-12,
        ),
        // The generated energy function against the closed form: same formula, round-off apart.
        Check::new(
            SCENE,
            "Jacobi integral h(0) against ½mR²θ̇² − ½mR²ω²sin²θ − mgR cosθ",
            h0,
            h0_exact,
            1e-14,
        ),
        // RK4 (h = 1e-3, oscillation frequency ≈ ω sinθ* ≈ 4.6/s) loses energy at a relative rate
        // ~ (hω)⁴ per unit time ≈ 5e-10/s; over 10 s that is ≲ 1e-8.
        Check::new(
            SCENE,
            "Jacobi integral h after 10 s (conserved)",
            sys.energy_function(&s).expect("h"),
            h0,
            1e-8,
        ),
    ]
}
