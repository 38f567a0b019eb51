//! Sensitivities by parameters (`Seed::Parameter`): the pendulum's period against its closed form,
//! a damped double pendulum against finite differences, and the parameters that cannot be seeded.

use lagrange::prelude::*;
use lagrange::sensitivity::Seed;

mod common;
use common::pendulum;

/// A double pendulum with viscous friction c in both joints (the relative rate of the second).
#[mechanism]
pub mod damped {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct Damped {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
        pub c: f64,
    }
    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }
    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[generalized_force(on = theta1)]
    fn friction1() -> f64 {
        -c * theta1_dot + c * (theta2_dot - theta1_dot)
    }
    #[generalized_force(on = theta2)]
    fn friction2() -> f64 {
        -c * (theta2_dot - theta1_dot)
    }
}

const G: f64 = 9.81;

/// The first passage through θ = 0 of a pendulum of length `l` released at rest from `theta0`
/// (RK4 steps of `h`, [`common::first_passage`]), carried with the sensitivity by `l`: (t*, ∂θ/∂l
/// and θ̇ at t*).
fn first_passage(l: f64, theta0: f64, h: f64) -> (f64, f64, f64) {
    let sys = pendulum::Pendulum { m: 1.0, l, g: G };
    let s0 = pendulum::State::at_rest(pendulum::Coords { theta: theta0 });
    let run = common::rk4_tangent(&sys, &s0, [Seed::Parameter("l")], h).unwrap();
    let out = common::first_passage(&sys, run, h);
    (out.state.t, out.dq[0].theta, out.state.v.theta)
}

/// T = 4 √(L/g) K(sin(θ₀/2)) at any amplitude (Landau & Lifshitz, *Mechanics*, §11, problem 1), so
/// dT/dL = T/(2L) exactly; at small amplitude T → 2π√(L/g) and dT/dL → π/√(gL). The simulation
/// gets dT/dL from the sensitivity by L at the quarter period t*: θ(t*; L) = 0, so
/// dt*/dL = −(∂θ/∂L)/θ̇. RK4 at h = 1e-3 (ωh ≤ 3e-3) is accurate to ~1e-12 in θ and in its
/// derivative (the derivative is the same discrete map, differentiated), so 1e-8 relative bounds
/// both, the closed form being exact.
#[test]
fn period_derivative_by_length_matches_the_closed_form() {
    for (l, theta0) in [(1.5, 2.0), (0.8, 1e-3)] {
        let (quarter, dtheta_dl, rate) = first_passage(l, theta0, 1e-3);
        let period = 4.0 * (l / G).sqrt() * lagrange_gallery::elliptic_k((theta0 / 2.0).sin());
        let dperiod = 4.0 * (-dtheta_dl / rate);
        eprintln!(
            "L = {l}, θ₀ = {theta0}: T = {:.12} (closed form {period:.12}), dT/dL = {dperiod:.12} \
             (closed form {:.12}; small-amplitude π/√(gL) = {:.12})",
            4.0 * quarter,
            period / (2.0 * l),
            std::f64::consts::PI / (G * l).sqrt()
        );
        assert!(((4.0 * quarter - period) / period).abs() < 1e-8);
        let exact = period / (2.0 * l);
        assert!(
            ((dperiod - exact) / exact).abs() < 1e-8,
            "dT/dL = {dperiod}, closed form {exact}"
        );
    }
}

fn damped() -> damped::Damped {
    damped::Damped {
        m1: 1.0,
        m2: 0.7,
        l1: 1.1,
        l2: 0.9,
        g: G,
        c: 0.3,
    }
}

/// On the damped double pendulum (2 s of RK4, h = 1e-3) the derivatives of the end state by the
/// lengths (in the positions) and by the friction coefficient (in the forces) agree with finite
/// differences of the same discrete map, to the differences' own error (estimated in
/// `common::check_against_finite_differences`; the real parts of the two runs, the lifted model's
/// dynamics and the generated ones, differ by rounding of the same order).
#[test]
fn damped_double_pendulum_by_parameters_matches_finite_differences() {
    let sys = damped();
    let s0 = damped::State::new(
        0.0,
        damped::Coords {
            theta1: 1.2,
            theta2: -0.4,
        },
        damped::Coords {
            theta1: 0.3,
            theta2: 0.1,
        },
    );
    let seeds = [
        Seed::Parameter("l1"),
        Seed::Parameter("l2"),
        Seed::Parameter("c"),
    ];
    let (h, steps) = (1e-3, 2000);
    let (real, jacobian) = common::rk4_tangent_end(&sys, s0, seeds, h, steps);
    let plain = common::rk4_end(&sys, s0, h, steps);
    for i in 0..4 {
        // Rounding only: the same steps through two orderings of the same arithmetic.
        assert!(
            (real[i] - plain[i]).abs() < 1e-11,
            "real part {i}: {} against the plain run's {}",
            real[i],
            plain[i]
        );
    }
    let central = |seed: usize, delta: f64| -> [f64; 4] {
        let shifted = |sign: f64| {
            let mut p = damped();
            let d = sign * delta;
            match seed {
                0 => p.l1 += d,
                1 => p.l2 += d,
                _ => p.c += d,
            }
            common::rk4_end(&p, s0, h, steps)
        };
        let (plus, minus) = (shifted(1.0), shifted(-1.0));
        std::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * delta))
    };
    let labels: Vec<String> = seeds.iter().map(Seed::label).collect();
    common::check_against_finite_differences(&jacobian, &labels, plain, steps, central);
    // The friction's sensitivity is not trivially zero: c takes energy out.
    assert!(jacobian[2].iter().any(|x| x.abs() > 1e-2));
}

/// Initial values and parameters seeded together: each column is what it is when seeded alone
/// (forward mode carries the directions independently).
#[test]
fn mixed_seeds_are_independent_columns() {
    let sys = damped().validated().unwrap();
    let s0 = damped::State::at_rest(damped::Coords {
        theta1: 0.7,
        theta2: 0.2,
    });
    let run_with = |seeds: &[Seed]| {
        let mut out = Vec::new();
        for &seed in seeds {
            let mut run = common::rk4_tangent(&sys, &s0, [seed], 2e-3).unwrap();
            for _ in 0..500 {
                run.step(f64::INFINITY).unwrap();
            }
            out.push(run.sensitivities().dq[0]);
        }
        out
    };
    let alone = run_with(&[Seed::Coordinate("theta2"), Seed::Parameter("l2")]);
    let seeds = [Seed::Coordinate("theta2"), Seed::Parameter("l2")];
    let mut run = common::rk4_tangent(&sys, &s0, seeds, 2e-3).unwrap();
    for _ in 0..500 {
        run.step(f64::INFINITY).unwrap();
    }
    let together = run.sensitivities();
    for (column, alone) in together.dq.iter().zip(&alone) {
        // Same arithmetic on each direction; only the real parts' path may differ (the initial
        // value alone takes the generated dynamics): rounding.
        assert!((column.theta1 - alone.theta1).abs() < 1e-11);
        assert!((column.theta2 - alone.theta2).abs() < 1e-11);
    }
}

/// Dopri5 with its step sizes frozen from the plain run differentiates by a parameter too, and
/// agrees with RK4 at h = 1e-3 to the adaptive run's tolerance (rtol 1e-11 over ~1000 steps,
/// amplified by sensitivities of order 1: ≤ 1e-7).
#[test]
fn dopri5_by_a_parameter_matches_rk4() {
    let sys = damped();
    let s0 = damped::State::at_rest(damped::Coords {
        theta1: 1.0,
        theta2: 0.5,
    });
    let seeds = [Seed::Parameter("l2"), Seed::Parameter("c")];
    let mut run = Stepper::new(&sys, Dopri5::new(1e-11, 1e-13), &s0)
        .unwrap()
        .with_sensitivities(seeds)
        .unwrap();
    run.integrate(2.0, &mut [], |_| {}).unwrap();
    let adaptive = run.sensitivities();
    let mut run = common::rk4_tangent(&sys, &s0, seeds, 1e-3).unwrap();
    for _ in 0..2000 {
        run.step(f64::INFINITY).unwrap();
    }
    let fixed = run.sensitivities();
    for (j, seed) in seeds.iter().enumerate() {
        let diff = (adaptive.dq[j].theta1 - fixed.dq[j].theta1)
            .abs()
            .max((adaptive.dq[j].theta2 - fixed.dq[j].theta2).abs())
            .max((adaptive.dv[j].theta2 - fixed.dv[j].theta2).abs());
        assert!(
            diff < 1e-7,
            "{}: Dopri5 and RK4 differ by {diff:e}",
            seed.label()
        );
    }
}

/// Masses and a uniform field's strength enter the dynamics as plain numbers: refused by name, as is
/// a parameter the mechanism does not have.
#[test]
fn parameters_that_carry_no_derivative_are_refused() {
    let sys = damped();
    let s0 = damped::State::at_rest(damped::Coords {
        theta1: 0.1,
        theta2: 0.0,
    });
    for name in ["m2", "g"] {
        let err = common::rk4_tangent(&sys, &s0, [Seed::Parameter(name)], 1e-3)
            .map(|_| ())
            .unwrap_err();
        assert!(
            matches!(err, lagrange::Error::UnseedableParameter { name: n } if n == name),
            "{name}: {err}"
        );
    }
    let err = common::rk4_tangent(&sys, &s0, [Seed::Parameter("length")], 1e-3)
        .map(|_| ())
        .unwrap_err();
    assert!(
        matches!(&err, lagrange::Error::UnknownParameter { name, known } if name == "length" && known.contains("`l2`")),
        "{err}"
    );
}
