//! Statics of the bead on a spinning hoop (the mechanism of `spinning_hoop.rs`): equilibria by the
//! principle of virtual work (all generalized forces zero at rest, the lecture's eq. 5), their
//! stability and small-oscillation frequencies, traced over the spin rate ω.
//!
//! Closed forms (Taylor, *Classical Mechanics*, §7.6; Goldstein §2.6): with ω_c² = g/R,
//! - for ω < ω_c the bottom θ = 0 is the only equilibrium, stable, with ω₀² = g/R − ω²;
//! - for ω > ω_c the bottom is unstable and the bead rests at cos θ* = g/(ω²R), oscillating about it
//!   with frequency² = ω² sin²θ* = ω² − g²/(ω²R²): a supercritical pitchfork bifurcation at ω_c.

pub use super::spinning_hoop as scene;

use crate::plot::{self, Series};
use crate::Check;
use lagrange::analysis::{
    continuation, normal_modes, stability, Branch, EquilibriumOptions, Stability,
};
use lagrange::prelude::*;
use scene::spinning_hoop::{Coords, SpinningHoop};
use std::path::Path;

const SCENE: &str = "hoop bifurcation";

type HoopBranch = Branch<Coords, 1>;

/// The hoop's parameters.
const M: f64 = 0.2;
const R: f64 = 1.0;
const G: f64 = 9.81;

fn hoop(omega: f64) -> SpinningHoop {
    SpinningHoop {
        m: M,
        r: R,
        omega,
        g: G,
    }
}

pub fn run(plots: &Path) -> Vec<Check> {
    let critical = (G / R).sqrt();
    let options = EquilibriumOptions::default();
    let ratios: Vec<f64> = (0..=80).map(|i| 0.4 + 2.1 * i as f64 / 80.0).collect();
    let spins: Vec<f64> = ratios.iter().map(|x| x * critical).collect();

    // The bottom branch, over every spin; the off-bottom branch, from fast spins down towards ω_c.
    let bottom = continuation(hoop, &spins, 0.0, &Coords { theta: 0.0 }, &options);
    let fast: Vec<f64> = spins
        .iter()
        .rev()
        .copied()
        .filter(|&w| w > 1.02 * critical)
        .collect();
    let off = continuation(hoop, &fast, 0.0, &Coords { theta: 1.2 }, &options);
    let wrong = wrong_verdicts(&bottom, &off, critical);

    // Off-bottom equilibrium at ω = 2ω_c (the branch's point nearest it).
    let omega = 2.0 * critical;
    let at_two = off.points.iter().min_by(|a, b| {
        (a.parameter - omega)
            .abs()
            .total_cmp(&(b.parameter - omega).abs())
    });
    let (theta_star, omega_found) =
        at_two.map_or((f64::NAN, omega), |p| (p.equilibrium.q.theta, p.parameter));
    animate(plots, omega_found, theta_star);
    plot_branches(plots, &ratios, critical, &bottom, &off);
    println!(
        "{SCENE}: {} bottom and {} off-bottom equilibria traced; plot hoop_bifurcation.svg",
        bottom.points.len(),
        off.points.len()
    );
    checks((omega, omega_found), theta_star, critical, wrong)
}

/// Stability verdicts contradicting the closed form: the bottom stable below ω_c and unstable
/// above (away from ω_c itself, where the test is marginal), the off-bottom branch stable.
fn wrong_verdicts(bottom: &HoopBranch, off: &HoopBranch, critical: f64) -> usize {
    let mut wrong = 0;
    for p in &bottom.points {
        let expected = if p.parameter < critical {
            Stability::Stable
        } else {
            Stability::Unstable
        };
        if (p.parameter - critical).abs() > 1e-9 && p.stability != expected {
            wrong += 1;
        }
    }
    wrong
        + off
            .points
            .iter()
            .filter(|p| p.stability != Stability::Stable)
            .count()
}

/// The animation: the bead released 0.15 rad below θ*, oscillating about it for 4 s.
fn animate(plots: &Path, omega: f64, theta_star: f64) {
    let spun = hoop(omega);
    let mut s = scene::spinning_hoop::State::at_rest(Coords {
        theta: theta_star - 0.15,
    });
    let mut film = scene::recorder(&spun, SCENE);
    if film.push(&spun, &s).is_ok()
        && spun
            .simulate::<Rk4>(&mut s, 1e-3, 4000, film.observer(&spun))
            .is_ok()
    {
        let _ = film.write_html(plots.join("hoop_bifurcation.html"));
    }
}

/// The equilibria against ω/ω_c: the bottom, stable and unstable, the two off-bottom branches and
/// arccos(g/ω²R).
fn plot_branches(
    plots: &Path,
    ratios: &[f64],
    critical: f64,
    bottom: &HoopBranch,
    off: &HoopBranch,
) {
    let on_bottom = |verdict: Stability| -> Vec<(f64, f64)> {
        bottom
            .points
            .iter()
            .filter(|p| p.stability == verdict)
            .map(|p| (p.parameter / critical, 0.0))
            .collect()
    };
    let mut upper: Vec<(f64, f64)> = off
        .points
        .iter()
        .map(|p| (p.parameter / critical, p.equilibrium.q.theta))
        .collect();
    upper.reverse();
    let lower: Vec<(f64, f64)> = upper.iter().map(|&(x, y)| (x, -y)).collect();
    let exact: Vec<(f64, f64)> = ratios
        .iter()
        .filter(|&&x| x > 1.0)
        .map(|&x| (x, (1.0 / (x * x)).acos()))
        .collect();
    let _ = plot::lines(
        &plots.join("hoop_bifurcation.svg"),
        "Bead on a spinning hoop: equilibria θ* against ω/√(g/R)",
        "ω / √(g/R)",
        "θ*",
        &[
            Series::new("bottom, stable", on_bottom(Stability::Stable)),
            Series::new("bottom, unstable", on_bottom(Stability::Unstable)),
            Series::new("θ* > 0, stable", upper),
            Series::new("θ* < 0, stable", lower),
            Series::new("arccos(g/ω²R)", exact),
        ],
    );
}

/// The checks: θ* and the frequency about it at ω = 2ω_c (`omega`, the branch's point at
/// `omega_found`), the bottom's frequency at ω_c/2 and its instability at 2ω_c, and the verdicts.
fn checks(
    (omega, omega_found): (f64, f64),
    theta_star: f64,
    critical: f64,
    wrong_verdicts: usize,
) -> Vec<Check> {
    let modes = normal_modes(&hoop(omega_found), 0.0, &Coords { theta: theta_star })
        .map(|m| m.frequencies[0]);
    let frequency_exact = (omega_found.powi(2) - G * G / (omega_found.powi(2) * R * R)).sqrt();
    let slow = 0.5 * critical;
    let bottom_frequency =
        normal_modes(&hoop(slow), 0.0, &Coords { theta: 0.0 }).map(|m| m.frequencies[0]);
    let unstable_bottom = stability(&hoop(omega), 0.0, &Coords { theta: 0.0 }).map(|s| s.stability);
    vec![
        // Newton stops at a residual of ~1e-14 of the force scale m g; with stiffness
        // K = m R² ω² sin²θ* ≈ 2.2, θ* is then known to ~1e-14.
        Check::new(
            SCENE,
            "θ* at ω = 2√(g/R), arccos(g/ω²R)",
            theta_star,
            (G / (omega_found.powi(2) * R)).acos(),
            1e-12,
        ),
        // Frequencies from a 1×1 generalized eigenproblem with exact dual-number K and M.
        Check::new(
            SCENE,
            "oscillation about θ*, √(ω² − g²/ω²R²)",
            modes.unwrap_or(f64::NAN),
            frequency_exact,
            1e-12,
        ),
        Check::new(
            SCENE,
            "oscillation about the bottom at ω = ½√(g/R), √(g/R − ω²)",
            bottom_frequency.unwrap_or(f64::NAN),
            (G / R - slow * slow).sqrt(),
            1e-12,
        ),
        Check::new(
            SCENE,
            "bottom unstable at ω = 2√(g/R) (1 = yes)",
            f64::from(u8::from(unstable_bottom == Ok(Stability::Unstable))),
            1.0,
            0.0,
        ),
        Check::new(
            SCENE,
            "stability verdicts contradicting the closed form",
            wrong_verdicts as f64,
            0.0,
            0.0,
        ),
    ]
}
