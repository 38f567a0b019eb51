//! Identifying a pendulum from a measurement: its length L and the viscous friction c in its pivot
//! are fitted to sampled angles θ(tᵢ) by Gauss–Newton. The Jacobian ∂θ(tᵢ)/∂(L, c) comes from one
//! sensitivity run per iteration (`lagrange::sensitivity`, `Seed::Parameter`: the run is carried on
//! dual numbers seeded on the fields `l` and `c`) instead of finite differences. The measurement is
//! a simulation at known parameters, so the fit must recover them.
//!
//! Gauss–Newton (Nocedal & Wright, *Numerical Optimization*, 2nd ed., §10.3): with residuals
//! rᵢ(p) = θ(tᵢ; p) − θᵢ and J = ∂r/∂p, the step solves JᵀJ Δp = −Jᵀr; on a zero-residual problem
//! it converges quadratically near the solution.
//!
//! ```text
//! cargo run --release --example identify_pendulum
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::identify_pendulum` checks that the fit recovers
//! the true L and c.

use lagrange::prelude::*;
use lagrange::sensitivity::Seed;
use lagrange::Fixed;
use nalgebra::{Matrix2, Vector2};

use lagrange_gallery::scenes::identify_pendulum::damped_pendulum;

use damped_pendulum::{Coords, DampedPendulum, State};

/// θ every 0.05 s for 3 s, with ∂θ/∂L and ∂θ/∂c, from one RK4 run (h = 1e-3) on dual numbers.
fn samples(sys: &DampedPendulum, s0: &State) -> Result<Vec<(f64, Vector2<f64>)>, lagrange::Error> {
    let seeds = [Seed::Parameter("l"), Seed::Parameter("c")];
    let rk4 = Fixed::<Rk4>::new(1e-3).without_dense();
    let mut run = Stepper::new(sys, rk4, s0)?.with_sensitivities(seeds)?;
    let mut out = Vec::new();
    for _ in 0..60 {
        for _ in 0..50 {
            run.step(f64::INFINITY)?;
        }
        let at = run.sensitivities();
        out.push((
            at.state.q.theta,
            Vector2::new(at.dq[0].theta, at.dq[1].theta),
        ));
    }
    Ok(out)
}

fn main() -> Result<(), lagrange::Error> {
    let truth = DampedPendulum {
        m: 0.5,
        l: 0.75,
        g: 9.81,
        c: 0.04,
    };
    let s0 = State::at_rest(Coords { theta: 1.0 });
    let measured: Vec<f64> = samples(&truth, &s0)?
        .into_iter()
        .map(|(theta, _)| theta)
        .collect();

    // Gauss–Newton from a poor guess.
    let mut sys = DampedPendulum {
        l: 1.0,
        c: 0.1,
        ..truth
    };
    println!("iteration   L (m)            c (N·m·s)        Σ rᵢ² (rad²)");
    for k in 0..20 {
        let (mut normal, mut gradient, mut sum) = (Matrix2::zeros(), Vector2::zeros(), 0.0);
        for ((theta, j), target) in samples(&sys, &s0)?.into_iter().zip(&measured) {
            normal += j * j.transpose();
            gradient += j * (theta - target);
            sum += (theta - target).powi(2);
        }
        println!("{k:9}   {:.12}   {:.12}   {sum:.3e}", sys.l, sys.c);
        let step = normal
            .lu()
            .solve(&(-gradient))
            .ok_or(lagrange::Error::UnsuitableMethod {
                method: "Gauss–Newton",
                reason: "the samples do not determine both parameters (JᵀJ is singular)"
                    .to_string(),
            })?;
        sys.l += step[0];
        sys.c += step[1];
        if step[0].abs() <= 1e-13 * sys.l && step[1].abs() <= 1e-13 * sys.c.abs() {
            break;
        }
    }
    println!(
        "fitted L = {:.12} m (true {}), c = {:.12} N·m·s (true {})",
        sys.l, truth.l, sys.c, truth.c
    );
    Ok(())
}
