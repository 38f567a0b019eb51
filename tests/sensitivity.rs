//! Trajectory sensitivities (`lagrange::sensitivity`) against closed forms and finite differences.

use lagrange::prelude::*;
use lagrange::sensitivity::Seed;

mod common;
use common::pendulum;
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum;
use lagrange_gallery::scenes::double_pendulum::double_pendulum;

const G: f64 = 9.81;

fn double_pendulum() -> lagrange::Validated<double_pendulum::DoublePendulum> {
    double_pendulum::DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: G,
    }
    .validated()
    .unwrap()
}

/// On the double pendulum (2 s of RK4, h = 1e-3, released with velocity; sensitivities up to ~4)
/// every derivative of the end state by every initial value agrees with finite differences of the
/// same discrete map, to the differences' own error (estimated in
/// `common::check_against_finite_differences`).
#[test]
fn double_pendulum_matches_finite_differences() {
    let sys = double_pendulum();
    let s0 = double_pendulum::State::new(
        0.0,
        double_pendulum::Coords {
            theta1: 1.2,
            theta2: -0.4,
        },
        double_pendulum::Coords {
            theta1: 0.3,
            theta2: 0.1,
        },
    );
    let seeds = [
        Seed::Coordinate("theta1"),
        Seed::Coordinate("theta2"),
        Seed::Velocity("theta1"),
        Seed::Velocity("theta2"),
    ];
    let (h, steps) = (1e-3, 2000);
    let (real, jacobian) = common::rk4_tangent_end(&sys, s0, seeds, h, steps);
    // The real parts are the plain run, bit for bit.
    let plain = common::rk4_end(&sys, s0, h, steps);
    assert_eq!(real, plain);
    let central = |seed: usize, delta: f64| -> [f64; 4] {
        let shifted = |sign: f64| {
            let mut s = s0;
            let d = sign * delta;
            match seed {
                0 => s.q.theta1 += d,
                1 => s.q.theta2 += d,
                2 => s.v.theta1 += d,
                _ => s.v.theta2 += d,
            }
            common::rk4_end(&sys, s, h, steps)
        };
        let (plus, minus) = (shifted(1.0), shifted(-1.0));
        std::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * delta))
    };
    let labels: Vec<String> = seeds.iter().map(Seed::label).collect();
    common::check_against_finite_differences(&jacobian, &labels, plain, steps, central);
}

/// Small oscillations: θ(t) = θ₀ cos ωt + (θ̇₀/ω) sin ωt, so ∂θ/∂θ₀ = cos ωt and ∂θ/∂θ̇₀ =
/// sin(ωt)/ω, ω = √(g/L). At θ₀ = 1e-4 the nonlinearity shifts the frequency by ω θ₀²/16
/// (Landau & Lifshitz, *Mechanics*, §28), 2e-9 relative, so over t = 5 the linear forms hold to
/// ~1e-8; RK4 at h = 1e-3 adds (ωh)⁴ ω t / 120 ≈ 1e-11.
#[test]
fn small_oscillations_have_the_linear_sensitivities() {
    let sys = pendulum::Pendulum {
        m: 1.0,
        l: 2.0,
        g: G,
    }
    .validated()
    .unwrap();
    let s0 = pendulum::State::at_rest(pendulum::Coords { theta: 1e-4 });
    let seeds = [Seed::Coordinate("theta"), Seed::Velocity("theta")];
    let mut run = common::rk4_tangent(&sys, &s0, seeds, 1e-3).unwrap();
    for _ in 0..5000 {
        run.step(f64::INFINITY).unwrap();
    }
    let out = run.sensitivities();
    let (omega, t) = ((G / 2.0).sqrt(), out.state.t);
    assert!((out.dq[0].theta - (omega * t).cos()).abs() < 1e-7);
    assert!((out.dq[1].theta - (omega * t).sin() / omega).abs() < 1e-7);
    assert!((out.dv[0].theta + omega * (omega * t).sin()).abs() < 1e-7);
}

/// K(k) and E(k) by the arithmetic–geometric mean (Abramowitz & Stegun 17.6.1–17.6.4):
/// K = π / (2 a_∞), E = K (1 − Σₙ 2ⁿ⁻¹ cₙ²) with c₀ = k, cₙ = (aₙ₋₁ − bₙ₋₁)/2.
fn elliptic_k_e(k: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    let (mut sum, mut power) = (0.5 * k * k, 0.5);
    for _ in 0..64 {
        let c = 0.5 * (a - b);
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
        power *= 2.0;
        sum += power * c * c;
        if c.abs() <= 1e-17 {
            break;
        }
    }
    let big_k = std::f64::consts::PI / (2.0 * a);
    (big_k, big_k * (1.0 - sum))
}

/// The large-amplitude period T(θ₀) = 4 √(L/g) K(sin(θ₀/2)) (Abramowitz & Stegun 17.3; the
/// pendulum's period, Landau & Lifshitz §11) has dT/dθ₀ = 4 √(L/g) K'(k) cos(θ₀/2)/2 with
/// K'(k) = (E − (1 − k²) K) / (k (1 − k²)) (NIST DLMF 19.4.1). The simulation gets it from the
/// sensitivity of the first passage through θ = 0 (a quarter period): at that time t*,
/// θ(t*; θ₀) = 0, so dt*/dθ₀ = −(∂θ/∂θ₀)/θ̇. RK4 at h = 1e-3 (ωh ≈ 3e-3) is accurate to ~1e-12
/// in θ and its derivative, so 1e-8 relative is the bound, the closed form being exact.
#[test]
fn large_amplitude_period_derivative_matches_elliptic_integrals() {
    let (l, theta0) = (1.5, 2.0);
    let sys = pendulum::Pendulum { m: 1.0, l, g: G }.validated().unwrap();
    let s0 = pendulum::State::at_rest(pendulum::Coords { theta: theta0 });
    let run = common::rk4_tangent(&sys, &s0, [Seed::Coordinate("theta")], 1e-3).unwrap();
    // The first passage through θ = 0, RK4 steps of h = 1e-3.
    let at_bottom = common::first_passage(&sys, run, 1e-3);
    let quarter = at_bottom.state.t;
    let dquarter = -at_bottom.dq[0].theta / at_bottom.state.v.theta;

    let k = (theta0 / 2.0).sin();
    let (big_k, big_e) = elliptic_k_e(k);
    let scale = 4.0 * (l / G).sqrt();
    let period = scale * big_k;
    let dk_dk = (big_e - (1.0 - k * k) * big_k) / (k * (1.0 - k * k));
    let dperiod = scale * dk_dk * 0.5 * (theta0 / 2.0).cos();
    assert!(
        ((4.0 * quarter - period) / period).abs() < 1e-8,
        "T: {} against {period}",
        4.0 * quarter
    );
    assert!(
        ((4.0 * dquarter - dperiod) / dperiod).abs() < 1e-8,
        "dT/dθ₀: {} against {dperiod}",
        4.0 * dquarter
    );
}

#[test]
fn unknown_coordinates_are_named() {
    let sys = double_pendulum();
    let s0 = double_pendulum::State::at_rest(double_pendulum::Coords {
        theta1: 0.1,
        theta2: 0.0,
    });
    let err = common::rk4_tangent(&sys, &s0, [Seed::Velocity("theta3")], 1e-3)
        .map(|_| ())
        .unwrap_err();
    assert!(matches!(err, lagrange::Error::UnknownCoordinate { ref name, .. } if name == "theta3"));
    let err = common::rk4_tangent(&sys, &s0, [Seed::Coordinate("theta1")], -1.0)
        .map(|_| ())
        .unwrap_err();
    assert!(matches!(err, lagrange::Error::InvalidStep { .. }), "{err}");
    // A step before the solver's time is refused and changes nothing.
    let mut run = common::rk4_tangent(&sys, &s0, [Seed::Coordinate("theta1")], 1e-3).unwrap();
    assert!(matches!(
        run.step(-1.0),
        Err(lagrange::Error::InvalidEndTime { .. })
    ));
    assert_eq!(run.state(), s0, "a refused step changes nothing");
}

/// Dopri5 with its step sizes frozen from the plain run: the state is that run bit for bit, and
/// the derivatives agree with RK4's (h = 1e-3) on the double pendulum. Both approximate the
/// exact sensitivities: RK4's error is that of its solution, O(h⁴) ≈ 1e-11 here (the
/// finite-difference test above holds it to 1e-10); Dopri5's is governed by rtol = 1e-11 on the
/// state, amplified by at most the largest sensitivity (≈ 4) over its ~1000 steps: ≤ 1e-7 at
/// worst, so 1e-7 is the bound (measured: printed).
#[test]
fn dopri5_with_frozen_steps_matches_rk4() {
    let sys = double_pendulum();
    let s0 = double_pendulum::State::new(
        0.0,
        double_pendulum::Coords {
            theta1: 1.2,
            theta2: -0.4,
        },
        double_pendulum::Coords {
            theta1: 0.3,
            theta2: 0.1,
        },
    );
    let seeds = [Seed::Coordinate("theta1"), Seed::Velocity("theta2")];
    let settings = Dopri5::new(1e-11, 1e-13);
    let mut run = Stepper::new(&sys, settings, &s0)
        .unwrap()
        .with_sensitivities(seeds)
        .unwrap();
    run.integrate(2.0, &mut [], |_| {}).unwrap();
    let adaptive = run.sensitivities();
    let mut plain = s0;
    sys.integrate(settings, &mut plain, 2.0, &mut [], |_| {})
        .unwrap();
    assert_eq!(adaptive.state, plain, "the state is the plain run's");

    let mut run = common::rk4_tangent(&sys, &s0, seeds, 1e-3).unwrap();
    for _ in 0..2000 {
        run.step(f64::INFINITY).unwrap();
    }
    let fixed = run.sensitivities();
    let mut worst: f64 = 0.0;
    for j in 0..2 {
        let a = [
            adaptive.dq[j].theta1,
            adaptive.dq[j].theta2,
            adaptive.dv[j].theta1,
            adaptive.dv[j].theta2,
        ];
        let b = [
            fixed.dq[j].theta1,
            fixed.dq[j].theta2,
            fixed.dv[j].theta1,
            fixed.dv[j].theta2,
        ];
        for i in 0..4 {
            worst = worst.max((a[i] - b[i]).abs());
        }
    }
    eprintln!("largest |Dopri5 − RK4| sensitivity difference: {worst:e}");
    assert!(worst < 1e-7);
}

/// The projection onto constraints after each step is not differentiated: refused up front.
#[test]
fn constrained_mechanisms_are_refused() {
    let sys = cartesian_pendulum::CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: G,
    };
    let s0 = cartesian_pendulum::State::at_rest(cartesian_pendulum::Coords { x: 0.6, y: -0.8 });
    let err = common::rk4_tangent(&sys, &s0, [Seed::Coordinate("x")], 1e-3)
        .map(|_| ())
        .unwrap_err();
    assert!(matches!(
        err,
        lagrange::Error::UnsuitableMethod {
            method: "sensitivities",
            ..
        }
    ));
}
