//! Statics of the bead on a spinning hoop (the mechanism of the `spinning_hoop` example): its
//! equilibria by the principle of virtual work (every generalized force zero at rest), their
//! stability and small-oscillation frequencies, traced over the spin rate ω with `continuation`.
//!
//! Closed forms (Taylor, *Classical Mechanics*, §7.6; Goldstein §2.6): with ω_c² = g/R,
//! - for ω < ω_c the bottom θ = 0 is the only equilibrium, stable, with frequency² g/R − ω²;
//! - for ω > ω_c the bottom is unstable and the bead rests at cos θ* = g/(ω²R), oscillating about it
//!   with frequency² ω² − g²/(ω²R²): a supercritical pitchfork bifurcation at ω_c.
//!
//! ```text
//! cargo run --release --example hoop_bifurcation
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::hoop_bifurcation` checks θ*, both frequencies and
//! every stability verdict along the branches against these closed forms.

use lagrange::analysis::{continuation, normal_modes, EquilibriumOptions, Stability};
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::spinning_hoop::spinning_hoop;

fn main() -> Result<(), lagrange::Error> {
    use spinning_hoop::{Coords, SpinningHoop};
    let (m, r, g): (f64, f64, f64) = (0.2, 1.0, 9.81);
    let critical: f64 = (g / r).sqrt();
    let hoop = |omega: f64| SpinningHoop { m, r, omega, g };
    let options = EquilibriumOptions::default();

    // The off-bottom branch, from a fast spin down towards ω_c, warm-started point to point.
    let spins: Vec<f64> = (0..=12)
        .rev()
        .map(|i| (1.1 + 0.1 * i as f64) * critical)
        .collect();
    let off = continuation(hoop, &spins, 0.0, &Coords { theta: 1.2 }, &options);
    println!("ω/ω_c   θ* (rad)     arccos(g/ω²R)   frequency     √(ω² − g²/ω²R²)   stability");
    let mut branch = Vec::new();
    for p in &off.points {
        let (omega, theta) = (p.parameter, p.equilibrium.q.theta);
        let frequency = normal_modes(&hoop(omega), 0.0, &p.equilibrium.q)?.frequencies[0];
        println!(
            "{:5.2}  {theta:.10}  {:.10}    {frequency:.10}  {:.10}      {:?}",
            omega / critical,
            (g / (omega * omega * r)).acos(),
            (omega * omega - g * g / (omega * omega * r * r)).sqrt(),
            p.stability
        );
        branch.push((omega / critical, theta));
    }

    // The bottom, below and above ω_c.
    let bottom = continuation(
        hoop,
        &[0.5 * critical, 2.0 * critical],
        0.0,
        &Coords { theta: 0.0 },
        &options,
    );
    for p in &bottom.points {
        let verdict = p.stability;
        let detail = if verdict == Stability::Stable {
            let frequency = normal_modes(&hoop(p.parameter), 0.0, &p.equilibrium.q)?.frequencies[0];
            format!(
                ", frequency {frequency:.10}, √(g/R − ω²) = {:.10}",
                (g / r - p.parameter.powi(2)).sqrt()
            )
        } else {
            String::new()
        };
        println!(
            "bottom at ω/ω_c = {:.1}: {verdict:?}{detail}",
            p.parameter / critical
        );
    }

    branch.reverse();
    let mirror: Vec<(f64, f64)> = branch.iter().map(|&(x, y)| (x, -y)).collect();
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("hoop_bifurcation_example.svg"),
        "Bead on a spinning hoop: off-bottom equilibria ±θ* against ω/√(g/R)",
        "ω / √(g/R)",
        "θ*",
        &[Series::new("θ* > 0", branch), Series::new("θ* < 0", mirror)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
