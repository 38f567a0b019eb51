//! The lecture's example 2: a bead of mass m slides without friction on a vertical elliptical wire
//! whose semi-axes a(t) = a₀(1 + ε sin Ωt), b(t) = b₀(1 + ε cos Ωt) are prescribed. The wire does
//! work on the bead, so T + V is not conserved. What holds instead is the energy-function theorem:
//! h = Σ pₖq̇ₖ − L obeys dh/dt = −∂L/∂t along the motion (Goldstein, *Classical Mechanics*, 3rd ed.,
//! eq. 2.55), so h(t) = h(0) − ∫₀ᵗ ∂L/∂t dt.
//!
//! ```text
//! cargo run --release --example breathing_ellipse
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::breathing_ellipse` checks h(6 s) − h(0) against
//! −∫ ∂L/∂t dt.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::breathing_ellipse::breathing_ellipse;

fn main() -> Result<(), lagrange::Error> {
    use breathing_ellipse::{BreathingEllipse, Coords, State};
    let sys = BreathingEllipse {
        m: 0.5,
        a0: 1.0,
        b0: 0.7,
        eps: 0.2,
        omega: 3.0,
        g: 9.81,
    };
    let h = 1e-3;
    let mut s = State::new(0.0, Coords { phi: 1.0 }, Coords { phi: 0.0 });
    let h0 = sys.energy_function(&s)?;
    // ∫ ∂L/∂t dt by Simpson's rule over pairs of steps: (h/3)(f₀ + 4f₁ + f₂).
    let mut rates = [sys.lagrangian_time_derivative(&s)?, 0.0];
    let mut integral = 0.0;
    println!("   t (s)    T + V (J)   h = Σpq̇ − L (J)   h(0) − ∫∂L/∂t dt (J)");
    let (mut energy, mut jacobi) = (Vec::new(), Vec::new());
    for pair in 1..=3000 {
        sys.step::<Rk4>(&mut s, h)?;
        rates[1] = sys.lagrangian_time_derivative(&s)?;
        sys.step::<Rk4>(&mut s, h)?;
        let end = sys.lagrangian_time_derivative(&s)?;
        integral += h / 3.0 * (rates[0] + 4.0 * rates[1] + end);
        rates[0] = end;
        energy.push((s.t, sys.energy(&s)?));
        jacobi.push((s.t, sys.energy_function(&s)?));
        if pair % 500 == 0 {
            println!(
                "{:8.2} {:12.6} {:17.9} {:22.9}",
                s.t,
                sys.energy(&s)?,
                sys.energy_function(&s)?,
                h0 - integral
            );
        }
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("breathing_ellipse_example.svg"),
        "Bead on a breathing ellipse: T + V and h = Σpq̇ − L",
        "t",
        "J",
        &[Series::new("T + V", energy), Series::new("h", jacobi)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
