//! The cost tables of BENCHMARKS.md.

use super::contact_scenes::on_sphere;
use super::sphere::{bilateral_release, unilateral_release};
use super::stiff_lander::{lander, LANDER};
use lagrange::integrate::Stats;
use lagrange::prelude::*;

/// The figures of BENCHMARKS.md: steps, Newton iterations and evaluations in contact, up to the
/// release, for the sphere declared unilateral ([`ContactRadau5`]) and bilateral (Radau5 with an
/// event on its multiplier); and the stiff lander in ContactRadau5 and ContactDopri5.
/// `cargo test --release --test contact_implicit -- --ignored --nocapture`
#[test]
#[ignore = "prints the cost tables of BENCHMARKS.md"]
fn cost_in_contact_table() {
    let show = |s: Stats| {
        format!(
            "{} + {} | {} | {} | {} / {}",
            s.accepted,
            s.rejected,
            s.newton_iterations,
            s.evaluations,
            s.jacobians,
            s.factorizations
        )
    };
    println!("| tol | declaration | steps (acc. + rej.) | Newton iterations | evaluations | Jacobians / factorisations |");
    println!("|---|---|---|---|---|---|");
    let start = on_sphere(0.0, 0.5);
    for tol in [1e-6, 1e-10, 1e-13] {
        let (_, uni, _) = unilateral_release(start, tol);
        let (_, bil) = bilateral_release(start, tol);
        println!("| {tol:.0e} | unilateral, ContactRadau5 | {} |", show(uni));
        println!("| {tol:.0e} | bilateral, Radau5 | {} |", show(bil));
    }
    println!();
    println!("| tol | lander to t = 1 s | steps (acc. + rej.) | Newton iterations | evaluations | Jacobians / factorisations |");
    println!("|---|---|---|---|---|---|");
    let sys = LANDER;
    let start = lander::State::new(
        0.0,
        lander::Coords {
            foot: 0.4,
            top: 0.9,
        },
        lander::Coords {
            foot: 0.0,
            top: 0.0,
        },
    );
    for tol in [1e-6, 1e-8, 1e-10] {
        let mut r = Stepper::new(&sys, Radau5::new(tol, tol), &start).expect("solver");
        r.integrate(1.0, &mut [], |_| {}).expect("Radau5");
        let mut d = Stepper::new(&sys, Dopri5::new(tol, tol), &start).expect("solver");
        d.integrate(1.0, &mut [], |_| {}).expect("Dopri5");
        println!("| {tol:.0e} | ContactRadau5 | {} |", show(r.stats()));
        println!("| {tol:.0e} | ContactDopri5 | {} |", show(d.stats()));
    }
}
