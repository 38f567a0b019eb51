//! Integrators against exact solutions: observed orders of convergence, Dopri5's error control,
//! dense output and event location, long-time energy behaviour, and errors that leave the state
//! alone. Models are written by hand at the end of this file.

use lagrange_core::constraints;
use lagrange_core::integrate::{Direction, Event, Fixed, Observation, Stepper, StopReason};
use lagrange_core::{vec2, Model, Scalar};
use lagrange_core::{
    Dopri5, Error, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Rk4, State,
    StormerVerlet, Variational,
};
use std::f64::consts::PI;

mod support;
use support::BlowUp;

const E: f64 = 0.6;

/// Max-norm distance between two states' (q, v).
fn distance<const N: usize>(q: &[f64; N], v: &[f64; N], q_ref: &[f64; N], v_ref: &[f64; N]) -> f64 {
    q.iter()
        .zip(q_ref)
        .chain(v.iter().zip(v_ref))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

/// End-point error after one period of the e = 0.6 Kepler orbit with n fixed steps.
fn kepler_error<I: Integrator>(n: usize) -> f64 {
    let mut s = kepler_start(E);
    let h = 2.0 * PI / n as f64;
    for _ in 0..n {
        Kepler.step::<I>(&mut s, h).unwrap();
    }
    let (q, v) = kepler_exact(E, s.t);
    distance(&s.q, &s.v, &q, &v)
}

/// Dopri5 used as a fixed-step method (h_init = h_max = h, tolerances so loose that no step is
/// rejected), to observe the order of its 5th-order solution.
fn dopri5_fixed(h: f64) -> Dopri5 {
    Dopri5 {
        rtol: 1e10,
        atol: 1e10,
        h_init: Some(h),
        h_max: h,
        ..Dopri5::default()
    }
}

fn kepler_error_dopri5(n: usize) -> f64 {
    let mut s = kepler_start(E);
    let h = 2.0 * PI / n as f64;
    let out = Kepler
        .integrate(dopri5_fixed(h), &mut s, 2.0 * PI, &mut [], |_| {})
        .unwrap();
    assert_eq!(out.stats.accepted, n);
    let (q, v) = kepler_exact(E, s.t);
    distance(&s.q, &s.v, &q, &v)
}

/// Observed order log₂(err(h)/err(h/2)) from the errors at n, 2n and 4n steps (the last pair,
/// closest to the asymptotic regime; the first pair is printed for the record).
fn observed_order(name: &str, err: impl Fn(usize) -> f64, n: usize) -> f64 {
    let (e1, e2, e3) = (err(n), err(2 * n), err(4 * n));
    let (p1, p2) = ((e1 / e2).log2(), (e2 / e3).log2());
    eprintln!(
        "{name}: errors {e1:.3e} {e2:.3e} {e3:.3e} (n = {n}, {}, {}), orders {p1:.3} {p2:.3}",
        2 * n,
        4 * n
    );
    p2
}

// Convergence orders on one period of the e = 0.6 Kepler orbit (nonlinear, speeds from 0.5 to 2).
// The step counts put the errors well inside the asymptotic regime (error ratio stable between
// successive halvings) and far above round-off (≥ 1e-11 against ~1e-15·n accumulated rounding), so
// the observed order is the theoretical one up to the O(h) correction of the next error term; ±0.3
// leaves room for that correction (measured deviations are printed with `--nocapture`).

#[test]
fn rk4_is_fourth_order() {
    let p = observed_order("RK4", kepler_error::<Rk4>, 400);
    assert!((p - 4.0).abs() < 0.3, "observed order {p}");
}

#[test]
fn dopri5_is_fifth_order() {
    let p = observed_order("Dopri5", kepler_error_dopri5, 400);
    assert!((p - 5.0).abs() < 0.3, "observed order {p}");
}

#[test]
fn implicit_midpoint_is_second_order() {
    let p = observed_order("implicit midpoint", kepler_error::<ImplicitMidpoint>, 1000);
    assert!((p - 2.0).abs() < 0.3, "observed order {p}");
}

#[test]
fn gauss_legendre_is_fourth_order() {
    let p = observed_order("Gauss-Legendre 2", kepler_error::<GaussLegendre2>, 200);
    assert!((p - 4.0).abs() < 0.3, "observed order {p}");
}

#[test]
fn variational_is_second_order() {
    let p = observed_order("variational", kepler_error::<Variational>, 1000);
    assert!((p - 2.0).abs() < 0.3, "observed order {p}");
}

#[test]
fn stormer_verlet_is_second_order() {
    let p = observed_order("Stormer-Verlet", kepler_error::<StormerVerlet>, 1000);
    assert!((p - 2.0).abs() < 0.3, "observed order {p}");
}

// Dopri5: error control, dense output, events.

#[test]
fn dopri5_meets_its_tolerance_on_the_oscillator() {
    // q̈ = −q from (1, 0): q = cos t, v = −sin t. With rtol = atol = tol the local error of every
    // step is held below tol (scaled per component); the oscillator neither amplifies nor damps
    // errors, so after 10 time units the global error is the sum of ~n local errors, and local
    // extrapolation (the step is advanced with the 5th-order solution while the 4th-order estimate
    // is controlled) keeps the sum of the order of tol. Bound: 10·tol (measured ratios ≈ 3).
    for tol in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
        let mut s = State::new(0.0, [1.0], [0.0]);
        let out = Oscillator { damping: 0.0 }
            .integrate(Dopri5::new(tol, tol), &mut s, 10.0, &mut [], |_| {})
            .unwrap();
        assert_eq!(out.reason, StopReason::Reached);
        assert_eq!(s.t, 10.0);
        let err = distance(&s.q, &s.v, &[10f64.cos()], &[-10f64.sin()]);
        eprintln!("Dopri5 tol {tol:e}: error {err:.3e}, {:?}", out.stats);
        assert!(err <= 10.0 * tol, "tol {tol}: error {err}");
        // FSAL: 6 evaluations per attempted step, plus the first evaluation and the initial-step
        // estimate.
        let attempts = out.stats.accepted + out.stats.rejected;
        assert_eq!(out.stats.evaluations, 6 * attempts + 2);
    }
}

#[test]
fn dopri5_dense_output_is_accurate_inside_steps() {
    let tol = 1e-9;
    let mut stepper = Stepper::new(
        &Oscillator { damping: 0.0 },
        Dopri5::new(tol, tol),
        &State::new(0.0, [1.0], [0.0]),
    )
    .unwrap();
    let mut worst = 0.0f64;
    while stepper.t() < 6.0 {
        stepper.step(6.0).unwrap();
        let dense = stepper.dense();
        for k in 1..8 {
            let t = dense.t_start() + (dense.t_end() - dense.t_start()) * k as f64 / 8.0;
            let (q, v) = dense.eval(t);
            worst = worst.max(distance(&q, &v, &[t.cos()], &[-t.sin()]));
        }
    }
    // The continuous extension is of order 4 (one less than the step): its error inside a step is
    // of the size of the local error estimate, ≲ tol, plus the global error carried in, ≲ tol.
    eprintln!("dense output worst error {worst:.3e}");
    assert!(worst <= 20.0 * tol, "{worst}");
    assert_eq!(stepper.t(), 6.0);
}

#[test]
fn dopri5_events_on_the_oscillator() {
    // q = cos t crosses 0 falling at π/2 and rising at 3π/2; the rising one is terminal.
    let g = |s: &State<[f64; 1]>| s.q[0];
    let mut events = [
        Event::new(&g).direction(Direction::Falling),
        Event::new(&g).direction(Direction::Rising).terminal(),
    ];
    let mut seen = Vec::new();
    let mut s = State::new(0.0, [1.0], [0.0]);
    let tol = 1e-10;
    let out = Oscillator { damping: 0.0 }
        .integrate(Dopri5::new(tol, tol), &mut s, 10.0, &mut events, |o| {
            if let Observation::Event(hit) = o {
                seen.push(*hit)
            }
        })
        .unwrap();
    assert_eq!(seen.len(), 2, "{seen:?}");
    assert_eq!(
        (seen[0].index, seen[0].rising, seen[0].terminal),
        (0, false, false)
    );
    assert_eq!(
        (seen[1].index, seen[1].rising, seen[1].terminal),
        (1, true, true)
    );
    // Event times are those of the numerical solution, which is within ~tol of the exact one;
    // |q̇| = 1 at the crossings, so the time error is ~tol too. Bound 10·tol.
    assert!(
        (seen[0].state.t - PI / 2.0).abs() < 10.0 * tol,
        "{}",
        seen[0].state.t - PI / 2.0
    );
    assert!(
        (seen[1].state.t - 1.5 * PI).abs() < 10.0 * tol,
        "{}",
        seen[1].state.t - 1.5 * PI
    );
    match out.reason {
        StopReason::Event(hit) => assert_eq!(hit, seen[1]),
        other => panic!("{other:?}"),
    }
    assert_eq!(s, seen[1].state);
}

/// Complete elliptic integral of the first kind K(k) = π / (2 AGM(1, √(1 − k²))) (Abramowitz &
/// Stegun 17.6).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        let (a1, b1) = (0.5 * (a + b), (a * b).sqrt());
        a = a1;
        b = b1;
    }
    PI / (2.0 * a)
}

#[test]
fn dopri5_locates_the_pendulum_quarter_period() {
    // Released from rest at θ₀ = 2 rad (115°), the pendulum θ̈ = −sin θ first reaches θ = 0 after a
    // quarter period K(k), k = sin(θ₀/2) (Landau & Lifshitz, Mechanics §11, problem 1).
    let theta0 = 2.0f64;
    let exact = elliptic_k((theta0 / 2.0).sin());
    let g = |s: &State<[f64; 1]>| s.q[0];
    let mut events = [Event::new(&g).direction(Direction::Falling).terminal()];
    let mut s = State::new(0.0, [theta0], [0.0]);
    let tol = 1e-12;
    let out = Pendulum
        .integrate(Dopri5::new(tol, tol), &mut s, 10.0, &mut events, |_| {})
        .unwrap();
    assert!(matches!(out.reason, StopReason::Event(_)));
    // The root of the dense output is bracketed to 1e-13 s, so |θ| there is ≤ 1e-13·|θ̇| ≈ 2e-13
    // (θ̇ = −2k ≈ −1.68 at the crossing), plus round-off.
    assert!(s.q[0].abs() <= 1e-12, "θ at the event {}", s.q[0]);
    // The dense solution itself is within ~tol·(number of steps) of the exact one; divided by
    // |θ̇| ≈ 1.68 that is the time error. Bound 1e-10 (measured ~1e-12).
    eprintln!(
        "quarter period: located {} exact {exact} difference {:.3e}",
        s.t,
        s.t - exact
    );
    assert!((s.t - exact).abs() < 1e-10, "{} vs {exact}", s.t);
}

// Long-time energy behaviour on the Kepler orbit e = 0.6.

/// Least-squares slope of y against x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    sxy / sxx
}

/// Energy error H − H₀ over `periods` periods with `per_period` steps each, sampled every step:
/// returns (linear drift over the run from a least-squares fit, max |H − H₀|).
fn kepler_energy_drift<I: Integrator>(periods: usize, per_period: usize) -> (f64, f64) {
    let mut s = kepler_start(E);
    let e0 = Kepler.energy(&s).unwrap();
    let h = 2.0 * PI / per_period as f64;
    let (mut ts, mut es) = (Vec::new(), Vec::new());
    for _ in 0..periods * per_period {
        Kepler.step::<I>(&mut s, h).unwrap();
        ts.push(s.t);
        es.push(Kepler.energy(&s).unwrap() - e0);
    }
    let max = es.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    (slope(&ts, &es) * s.t, max)
}

#[test]
fn symplectic_methods_keep_kepler_energy_bounded_while_rk4_drifts() {
    // 100 periods of the e = 0.6 orbit. A symplectic method (constant mass matrix here) conserves a
    // modified energy O(hᵖ)-close to H, so H − H₀ oscillates with the orbit and shows no trend: the
    // least-squares drift over the run is a small fraction of the oscillation (the fit of a
    // periodic signal over 100 periods leaves ≲ 1/100 of its amplitude, bound 0.05). RK4 is not
    // symplectic and dissipates energy at a constant rate per period: its error is a trend, so the
    // drift is comparable to the maximum error (ratio near 1, bound > 0.5).
    let (periods, per_period) = (100, 100);
    let rk4 = kepler_energy_drift::<Rk4>(periods, per_period);
    eprintln!("RK4: drift {:.3e}, max {:.3e}", rk4.0, rk4.1);
    assert!(rk4.0.abs() > 0.5 * rk4.1, "{rk4:?}");
    for (name, (drift, max)) in [
        (
            "implicit midpoint",
            kepler_energy_drift::<ImplicitMidpoint>(periods, per_period),
        ),
        (
            "Gauss-Legendre 2",
            kepler_energy_drift::<GaussLegendre2>(periods, per_period),
        ),
        (
            "variational",
            kepler_energy_drift::<Variational>(periods, per_period),
        ),
        (
            "Stormer-Verlet",
            kepler_energy_drift::<StormerVerlet>(periods, per_period),
        ),
    ] {
        eprintln!("{name}: drift {drift:.3e}, max {max:.3e}");
        assert!(
            drift.abs() < 0.05 * max,
            "{name}: drift {drift:e}, max {max:e}"
        );
    }
}

// The variational integrator beyond constant mass matrices, and with forcing.

#[test]
fn variational_is_second_order_with_forcing() {
    // Damped oscillator q̈ + c q̇ + q = 0, c = 0.3, from (1, 0): the damping enters through the
    // discrete Lagrange–d'Alembert principle. Exact: q = e^{−ct/2}(cos ωt + (c/2ω) sin ωt),
    // ω = √(1 − c²/4).
    let c = 0.3f64;
    let w = (1.0 - c * c / 4.0).sqrt();
    let exact = |t: f64| {
        let e = (-c * t / 2.0).exp();
        let q = e * ((w * t).cos() + c / (2.0 * w) * (w * t).sin());
        let v = -e * (1.0 + c * c / (4.0 * w * w)) * w * (w * t).sin();
        (q, v)
    };
    let err = |n: usize| {
        let mut s = State::new(0.0, [1.0], [0.0]);
        let h = 5.0 / n as f64;
        for _ in 0..n {
            Oscillator { damping: c }
                .step::<Variational>(&mut s, h)
                .unwrap();
        }
        let (q, v) = exact(s.t);
        distance(&s.q, &s.v, &[q], &[v])
    };
    let p = observed_order("variational, damped oscillator", err, 100);
    assert!((p - 2.0).abs() < 0.3, "{p}");
}

#[test]
fn variational_and_gauss_converge_on_the_double_pendulum() {
    // A mass matrix that depends on q. Reference: Dopri5 at rtol = atol = 1e-13 (its error ~1e-12
    // is far below the errors measured, ≥ 1e-9).
    let start = State::new(0.0, [1.0, -0.5], [0.0, 0.0]);
    let t_end = 2.0;
    let mut reference = start;
    DoublePendulum
        .integrate(
            Dopri5::new(1e-13, 1e-13),
            &mut reference,
            t_end,
            &mut [],
            |_| {},
        )
        .unwrap();
    fn run<I: Integrator>(
        start: State<[f64; 2]>,
        t_end: f64,
        n: usize,
        r: &State<[f64; 2]>,
    ) -> f64 {
        let mut s = start;
        for _ in 0..n {
            DoublePendulum.step::<I>(&mut s, t_end / n as f64).unwrap();
        }
        distance(&s.q, &s.v, &r.q, &r.v)
    }
    let p = observed_order(
        "variational, double pendulum",
        |n| run::<Variational>(start, t_end, n, &reference),
        100,
    );
    assert!((p - 2.0).abs() < 0.3, "{p}");
    let p = observed_order(
        "Gauss-Legendre 2, double pendulum",
        |n| run::<GaussLegendre2>(start, t_end, n, &reference),
        25,
    );
    assert!((p - 4.0).abs() < 0.3, "{p}");
    let p = observed_order(
        "implicit midpoint, double pendulum",
        |n| run::<ImplicitMidpoint>(start, t_end, n, &reference),
        100,
    );
    assert!((p - 2.0).abs() < 0.3, "{p}");
}

#[test]
fn variational_keeps_double_pendulum_energy_bounded() {
    // Symplectic in (q, p) for this q-dependent mass matrix: the energy error stays at its O(h²)
    // level without a trend over 20 000 steps (the chaotic motion makes the oscillation irregular,
    // hence the looser drift bound than on Kepler).
    let mut s = State::new(0.0, [1.0, -0.5], [0.0, 0.0]);
    let e0 = DoublePendulum.energy(&s).unwrap();
    let (mut ts, mut es) = (Vec::new(), Vec::new());
    for _ in 0..20_000 {
        DoublePendulum.step::<Variational>(&mut s, 0.01).unwrap();
        ts.push(s.t);
        es.push(DoublePendulum.energy(&s).unwrap() - e0);
    }
    let max = es.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let drift = slope(&ts, &es) * s.t;
    eprintln!("variational double pendulum: drift {drift:.3e}, max {max:.3e}");
    // (hω)² with ω ~ 2: ~4e-4 relative to |E| ~ 2.
    assert!(max < 1e-2, "{max}");
    assert!(drift.abs() < 0.2 * max, "{drift} vs {max}");
}

// Symplecticity of the step maps in (q, p) on a configuration-dependent mass matrix.

/// The Jacobian Φ of one step map (q₀, p₀) ↦ (q₁, p₁) of `I` on the double pendulum at t = 0, by
/// central differences of step δ on each of the four inputs. The map goes through the public (q, v)
/// interface: v₀ from p₀ by the inverse Legendre transform (exact to round-off for this quadratic
/// Lagrangian), one step, p₁ = ∂L/∂q̇ at the end. Columns and rows ordered (q₁, q₂, p₁, p₂).
fn step_map_jacobian<I: Integrator>(
    q0: [f64; 2],
    p0: [f64; 2],
    h: f64,
    delta: f64,
) -> [[f64; 4]; 4] {
    let map = |y: [f64; 4]| -> [f64; 4] {
        let (q, p) = ([y[0], y[1]], [y[2], y[3]]);
        let (v, _) =
            Variational::velocities_from_momenta(&DoublePendulum, 0.0, &q, &p, &[0.0; 2]).unwrap();
        let mut s = State::new(0.0, q, v);
        DoublePendulum.step::<I>(&mut s, h).unwrap();
        let p1 = DoublePendulum.momenta(&s).unwrap();
        [s.q[0], s.q[1], p1[0], p1[1]]
    };
    let y0 = [q0[0], q0[1], p0[0], p0[1]];
    let mut phi = [[0.0; 4]; 4];
    for k in 0..4 {
        let (mut yp, mut ym) = (y0, y0);
        yp[k] += delta;
        ym[k] -= delta;
        let (fp, fm) = (map(yp), map(ym));
        for i in 0..4 {
            phi[i][k] = (fp[i] - fm[i]) / (2.0 * delta);
        }
    }
    phi
}

/// max |ΦᵀΩΦ − Ω| with Ω = [[0, I], [−I, 0]] (the symplecticity defect of the map).
fn symplecticity_defect(phi: &[[f64; 4]; 4]) -> f64 {
    let omega = |i: usize, j: usize| -> f64 {
        match (i, j) {
            (0, 2) | (1, 3) => 1.0,
            (2, 0) | (3, 1) => -1.0,
            _ => 0.0,
        }
    };
    let mut worst = 0.0f64;
    for a in 0..4 {
        for b in 0..4 {
            let mut x = 0.0;
            for i in 0..4 {
                for j in 0..4 {
                    x += phi[i][a] * omega(i, j) * phi[j][b];
                }
            }
            worst = worst.max((x - omega(a, b)).abs());
        }
    }
    worst
}

#[test]
fn step_maps_are_symplectic_in_q_p_on_the_double_pendulum() {
    // The double pendulum's mass matrix depends on q (M₁₂ = cos(q₁ − q₂)), the case in which Gauss
    // methods applied to (q, q̇) are not symplectic but applied to (q, p) are (Hairer, Lubich &
    // Wanner, Geometric Numerical Integration, Thm VI.4.2), as is the variational integrator
    // (Marsden & West 2001, §1.2). A moving, strongly coupled state and a large step h = 0.2
    // (hω ≲ 0.4) make a non-symplectic method's defect visible: RK4's is O(h⁵) per step. (The same
    // two Gauss methods applied to (q, q̇), as this crate did before, measured 1.2e-3 and 1.1e-5.)
    //
    // Tolerance. Φ by central differences of step δ has truncation error δ²/6·|∂³Φ| and
    // cancellation error ~ η/δ, where η is the noise of one evaluation of the map: the Newton
    // iterations stop at the round-off floor of their increments (4ε relative, or stagnation
    // below 1e-10 relative), which leaves η ~ 1e-15 on O(1) values. With δ = 1e-5 (near the
    // optimum (3η/|∂³Φ|)^{1/3} for |∂³Φ| = O(1)): 1e-10/6 + 1e-10 ≈ 2e-10 per entry of Φ, and
    // ΦᵀΩΦ sums 16 products of entries of size ≲ 2, so its error is ≲ 16·2·2·2e-10 ≈ 1e-8. The
    // bound 1e-7 leaves a further factor 10; a method that is not symplectic must exceed it by far.
    let (q0, v0, h, delta) = ([1.0, -0.5], [0.8, -0.6], 0.2, 1e-5);
    let p0 = DoublePendulum.momenta(&State::new(0.0, q0, v0)).unwrap();
    let tolerance = 1e-7;
    let mut defects = Vec::new();
    for (name, defect) in [
        (
            "implicit midpoint",
            symplecticity_defect(&step_map_jacobian::<ImplicitMidpoint>(q0, p0, h, delta)),
        ),
        (
            "Gauss-Legendre 2",
            symplecticity_defect(&step_map_jacobian::<GaussLegendre2>(q0, p0, h, delta)),
        ),
        (
            "variational",
            symplecticity_defect(&step_map_jacobian::<Variational>(q0, p0, h, delta)),
        ),
    ] {
        eprintln!("{name}: max |ΦᵀΩΦ − Ω| = {defect:.3e}");
        assert!(defect < tolerance, "{name}: {defect:e}");
        defects.push(defect);
    }
    // RK4 is not symplectic: its defect is the O(h⁵) local one, orders of magnitude above the
    // finite-difference noise floor of the symplectic methods (required: 100× the tolerance).
    let rk4 = symplecticity_defect(&step_map_jacobian::<Rk4>(q0, p0, h, delta));
    eprintln!("RK4: max |ΦᵀΩΦ − Ω| = {rk4:.3e}");
    assert!(rk4 > 100.0 * tolerance, "RK4: {rk4:e}");
}

#[test]
fn implicit_midpoint_on_q_p_is_the_midpoint_variational_integrator() {
    // Both solve p(t_m, Q, V) = p₀ + (h/2) G(t_m, Q, V), Q = q₀ + (h/2) V, then q₁ = q₀ + hV,
    // p₁ = p₀ + h G: the same map, here with a q-dependent mass matrix and with forcing (the damped
    // oscillator). They agree to the Newton round-off floor (bound 1e-12 after 100 steps).
    let mut a = State::new(0.0, [1.0, -0.5], [0.8, -0.6]);
    let mut b = a;
    for _ in 0..100 {
        DoublePendulum
            .step::<ImplicitMidpoint>(&mut a, 0.05)
            .unwrap();
        DoublePendulum.step::<Variational>(&mut b, 0.05).unwrap();
    }
    let d = distance(&a.q, &a.v, &b.q, &b.v);
    eprintln!("double pendulum, midpoint vs variational after 100 steps: {d:.3e}");
    assert!(d < 1e-12, "{d}");
    let (mut a, mut b) = (State::new(0.0, [1.0], [0.0]), State::new(0.0, [1.0], [0.0]));
    let damped = Oscillator { damping: 0.3 };
    for _ in 0..100 {
        damped.step::<ImplicitMidpoint>(&mut a, 0.05).unwrap();
        damped.step::<Variational>(&mut b, 0.05).unwrap();
    }
    let d = distance(&a.q, &a.v, &b.q, &b.v);
    eprintln!("damped oscillator, midpoint vs variational after 100 steps: {d:.3e}");
    assert!(d < 1e-12, "{d}");
}

// Störmer–Verlet and the constant-mass-matrix check.

#[test]
fn stormer_verlet_refuses_a_varying_mass_matrix() {
    let mut s = State::new(0.0, [1.0, -0.5], [0.3, 0.0]);
    let before = s;
    let err = DoublePendulum
        .step::<StormerVerlet>(&mut s, 0.01)
        .unwrap_err();
    assert!(
        matches!(
            err,
            Error::UnsuitableMethod {
                method: "Stormer-Verlet",
                ..
            }
        ),
        "{err}"
    );
    assert!(
        err.to_string().contains("mass matrix is not constant"),
        "{err}"
    );
    assert_eq!(s, before);
    // The pendulum's mass matrix sin² + cos² is constant up to round-off: accepted.
    let mut s = State::new(0.0, [2.0], [0.0]);
    for _ in 0..1000 {
        Pendulum.step::<StormerVerlet>(&mut s, 0.01).unwrap();
    }
}

// Errors leave the state alone.

fn assert_unchanged_on_error<I: Integrator>(h: f64) {
    // q̈ = q² blows up at t = √6; keep stepping until the method reports it.
    let mut s = State::new(0.0, [1.0], [(2.0f64 / 3.0).sqrt()]);
    for _ in 0..10_000 {
        let before = s;
        match BlowUp.step::<I>(&mut s, h) {
            Ok(()) => continue,
            Err(e) => {
                assert!(
                    matches!(
                        e,
                        Error::NonFiniteState { .. }
                            | Error::NonFiniteDynamics { .. }
                            | Error::NewtonDiverged { .. }
                    ),
                    "{}: {e}",
                    I::NAME
                );
                assert_eq!(s, before, "{}", I::NAME);
                assert!(s.q[0].is_finite() && s.v[0].is_finite());
                return;
            }
        }
    }
    panic!("{} never failed", I::NAME);
}

#[test]
fn non_finite_results_are_errors_and_leave_the_state_alone() {
    assert_unchanged_on_error::<Rk4>(0.05);
    assert_unchanged_on_error::<ImplicitMidpoint>(0.05);
    assert_unchanged_on_error::<GaussLegendre2>(0.05);
    assert_unchanged_on_error::<Variational>(0.05);
    assert_unchanged_on_error::<StormerVerlet>(0.05);
    // Non-finite input.
    fn nan_input<I: Integrator>() {
        let mut s = State::new(0.0, [1.0, f64::NAN], [0.0, 0.0]);
        let before = s;
        assert!(matches!(
            Kepler.step::<I>(&mut s, 0.1),
            Err(Error::NonFiniteState { .. })
        ));
        assert_eq!(format!("{s:?}"), format!("{before:?}"));
        let mut s = kepler_start(E);
        assert!(matches!(
            Kepler.step::<I>(&mut s, -0.1),
            Err(Error::InvalidStep { .. })
        ));
        assert_eq!(s, kepler_start(E));
    }
    nan_input::<ImplicitMidpoint>();
    nan_input::<GaussLegendre2>();
    nan_input::<Variational>();
    nan_input::<StormerVerlet>();
}

#[test]
fn dopri5_blow_up_is_an_error_and_leaves_the_state_alone() {
    let start = State::new(0.0, [1.0], [(2.0f64 / 3.0).sqrt()]);
    let mut s = start;
    let mut last_t = 0.0;
    let err = BlowUp
        .integrate(Dopri5::new(1e-8, 1e-8), &mut s, 5.0, &mut [], |o| {
            if let Observation::Step { state, .. } = o {
                last_t = state.t
            }
        })
        .unwrap_err();
    eprintln!(
        "Dopri5 on the blow-up: {err} (last accepted t = {last_t}, blow-up at √6 = {})",
        6f64.sqrt()
    );
    assert!(matches!(
        err,
        Error::NonFiniteState { .. }
            | Error::NonFiniteDynamics { .. }
            | Error::StepSizeUnderflow { .. }
    ));
    // It got close to the singularity before giving up, and the caller's state is untouched.
    assert!((last_t - 6f64.sqrt()).abs() < 1e-3, "{last_t}");
    assert_eq!(s, start);
    // Bad settings and a backwards end time are errors too.
    assert!(matches!(
        BlowUp.integrate(Dopri5::new(-1.0, 1e-6), &mut s, 1.0, &mut [], |_| {}),
        Err(Error::InvalidSetting {
            setting: "rtol",
            ..
        })
    ));
    assert!(matches!(
        BlowUp.integrate(Dopri5::default(), &mut s, -1.0, &mut [], |_| {}),
        Err(Error::InvalidEndTime { .. })
    ));
    assert_eq!(s, start);
}

#[test]
fn newton_without_a_solution_is_an_error() {
    // q̈ = q² from (1, √(2/3)) with h = 2: the midpoint equation V = v₀ + (1 + V)² has no real
    // root, so Newton cannot converge; the same holds for the variational step (p = v here).
    fn diverges<I: Integrator>() {
        let mut s = State::new(0.0, [1.0], [(2.0f64 / 3.0).sqrt()]);
        let before = s;
        let err = BlowUp.step::<I>(&mut s, 2.0).unwrap_err();
        assert!(
            matches!(err, Error::NewtonDiverged { .. }),
            "{}: {err}",
            I::NAME
        );
        assert_eq!(s, before);
    }
    diverges::<ImplicitMidpoint>();
    diverges::<GaussLegendre2>();
    diverges::<Variational>();
}

// Stiff spring chain and the long runs.

#[test]
fn implicit_midpoint_stays_bounded_on_the_stiff_chain_at_large_h_omega() {
    // FPU chain with ω = 50 (HLW §I.5.1) at h = 0.1, hω = 5: far beyond the stability limits of
    // the explicit methods (Störmer–Verlet hω < 2, RK4 hω < 2.83), which blow up, while the
    // A-stable implicit midpoint rule keeps the energy error bounded (it conserves the quadratic
    // stiff energy exactly for the linear part; the soft quartic springs perturb it by O(h²)).
    let h = 0.1;
    let mut s = fpu_start();
    let e0 = Fpu.energy(&s).unwrap();
    let mut worst = 0.0f64;
    for _ in 0..300 {
        ImplicitMidpoint::step_with_stats(&Fpu, &mut s, h).unwrap();
        worst = worst.max((Fpu.energy(&s).unwrap() - e0).abs());
    }
    eprintln!("FPU, implicit midpoint hω = 5: max energy error {worst:.3e} of E0 = {e0:.3}");
    assert!(worst < 0.1 * e0, "{worst} vs {e0}");
    for (name, blew_up) in [
        ("RK4", explicit_blows_up::<Rk4>(h)),
        ("Stormer-Verlet", explicit_blows_up::<StormerVerlet>(h)),
    ] {
        assert!(blew_up, "{name} should be unstable at hω = 5");
    }
}

fn explicit_blows_up<I: Integrator>(h: f64) -> bool {
    let mut s = fpu_start();
    let e0 = Fpu.energy(&s).unwrap();
    for _ in 0..1000 {
        if Fpu.step::<I>(&mut s, h).is_err() {
            return true;
        }
        if (Fpu.energy(&s).unwrap() - e0).abs() > 100.0 * e0 {
            return true;
        }
    }
    false
}

#[test]
#[ignore = "long run (10⁶ steps per method): cargo test --release -p lagrange-core --test integrators -- --ignored"]
fn kepler_energy_bounded_over_ten_thousand_periods() {
    // As the 100-period test, over 10⁴ periods with 100 steps per period.
    let (periods, per_period) = (10_000, 100);
    let rk4 = kepler_energy_drift::<Rk4>(periods, per_period);
    eprintln!("RK4: drift {:.3e}, max {:.3e}", rk4.0, rk4.1);
    assert!(rk4.0.abs() > 0.5 * rk4.1, "{rk4:?}");
    for (name, (drift, max)) in [
        (
            "implicit midpoint",
            kepler_energy_drift::<ImplicitMidpoint>(periods, per_period),
        ),
        (
            "Gauss-Legendre 2",
            kepler_energy_drift::<GaussLegendre2>(periods, per_period),
        ),
        (
            "variational",
            kepler_energy_drift::<Variational>(periods, per_period),
        ),
        (
            "Stormer-Verlet",
            kepler_energy_drift::<StormerVerlet>(periods, per_period),
        ),
    ] {
        eprintln!("{name}: drift {drift:.3e}, max {max:.3e}");
        assert!(
            drift.abs() < 0.05 * max,
            "{name}: drift {drift:e}, max {max:e}"
        );
    }
}

#[test]
#[ignore = "long run (10⁶ steps): cargo test --release -p lagrange-core --test integrators -- --ignored"]
fn variational_double_pendulum_energy_bounded_over_a_million_steps() {
    let mut s = State::new(0.0, [1.0, -0.5], [0.0, 0.0]);
    let e0 = DoublePendulum.energy(&s).unwrap();
    let (mut ts, mut es) = (Vec::new(), Vec::new());
    for k in 0..1_000_000 {
        DoublePendulum.step::<Variational>(&mut s, 0.01).unwrap();
        if k % 100 == 0 {
            ts.push(s.t);
            es.push(DoublePendulum.energy(&s).unwrap() - e0);
        }
    }
    let max = es.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let drift = slope(&ts, &es) * s.t;
    eprintln!("variational double pendulum, 10⁶ steps: drift {drift:.3e}, max {max:.3e}");
    assert!(max < 1e-2, "{max}");
    assert!(drift.abs() < 0.2 * max, "{drift} vs {max}");
}

// Constrained mechanisms: RK4, Dopri5, implicit midpoint and Gauss–Legendre integrate the
// constrained accelerations and project after every step; the variational integrator and
// Störmer–Verlet enforce holonomic constraints by RATTLE.

/// A pendulum in Cartesian coordinates with the rod |r| = L as a holonomic constraint (the pattern
/// of `tests/constraints.rs`: the glue a `#[constraint]` declaration generates).
#[derive(Clone, Copy)]
struct CartesianPendulum;

impl Model<2, 2> for CartesianPendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1]
    }
}

impl constraints::Constraints<2, 2, 1> for CartesianPendulum {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [constraints::ConstraintKind; 1] = [constraints::ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - 1.0]
    }
}

lagrange_core::impl_mechanism!(CartesianPendulum, 2, 2, constraints);

#[test]
fn constrained_pendulum_with_implicit_methods_and_dopri5() {
    // Released from rest at 2 rad from the bottom: (x, y) = (sin 2, −cos 2). The angle θ = atan2(x, −y)
    // must follow the angle-form pendulum θ̈ = −sin θ, which reaches θ = 0 after the quarter period
    // K(sin 1) (see `dopri5_locates_the_pendulum_quarter_period`), and |r| stays 1 (projection after
    // every step keeps it at round-off).
    let theta0 = 2.0f64;
    let quarter = elliptic_k((theta0 / 2.0).sin());
    let start = State::new(0.0, [theta0.sin(), -theta0.cos()], [0.0, 0.0]);
    let angle = |s: &State<[f64; 2]>| s.q[0].atan2(-s.q[1]);
    let radius = |s: &State<[f64; 2]>| (s.q[0] * s.q[0] + s.q[1] * s.q[1]).sqrt();
    fn run<I: Integrator>(start: State<[f64; 2]>, t_end: f64, n: usize) -> State<[f64; 2]> {
        let mut s = start;
        for _ in 0..n {
            CartesianPendulum
                .step::<I>(&mut s, t_end / n as f64)
                .unwrap();
            assert!(
                ((s.q[0] * s.q[0] + s.q[1] * s.q[1]).sqrt() - 1.0).abs() < 1e-12,
                "{s:?}"
            );
        }
        s
    }
    // θ(K) = 0 exactly. Global errors: midpoint O(h²) ≈ 0.1·(K/400)² ≈ 3e-6, Gauss O(h⁴) ≲ 1e-9.
    let s = run::<ImplicitMidpoint>(start, quarter, 400);
    assert!(angle(&s).abs() < 1e-4, "midpoint θ(K) = {}", angle(&s));
    let s = run::<GaussLegendre2>(start, quarter, 400);
    assert!(angle(&s).abs() < 1e-7, "Gauss θ(K) = {}", angle(&s));
    // Dopri5 with an event at θ = 0 locates the quarter period.
    let g = |s: &State<[f64; 2]>| s.q[0];
    let mut events = [Event::new(&g).direction(Direction::Falling).terminal()];
    let mut s = start;
    let tol = 1e-10;
    CartesianPendulum
        .integrate(Dopri5::new(tol, tol), &mut s, 10.0, &mut events, |_| {})
        .unwrap();
    assert!((radius(&s) - 1.0).abs() < 1e-9, "{s:?}");
    assert!((s.t - quarter).abs() < 1e-8, "{} vs {quarter}", s.t);
    // The variational integrator and Störmer–Verlet enforce the rod by RATTLE (order 2: the same
    // O(h²) bound as the midpoint rule).
    let s = run::<Variational>(start, quarter, 400);
    assert!(angle(&s).abs() < 1e-4, "variational θ(K) = {}", angle(&s));
    let s = run::<StormerVerlet>(start, quarter, 400);
    assert!(
        angle(&s).abs() < 1e-4,
        "Störmer–Verlet θ(K) = {}",
        angle(&s)
    );
}

// ---------------------------------------------------------------------------------------------
// Hand-written models (the pattern of `hand_written_model.rs`: what `#[mechanism]` generates).

/// Harmonic oscillator q̈ = −q (unit mass, K = 1); with `damping` c > 0 a generalized force −c q̇
/// (non-conservative), q̈ = −q − c q̇.
pub struct Oscillator {
    pub damping: f64,
}

impl Model<1, 1> for Oscillator {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 1] {
        [1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] {
        [q[0]]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D {
        x[0] * x[0] * 0.5
    }
    fn applied_forces<S: Scalar>(
        &self,
        _t: S,
        _q: &[S; 1],
        v: &[S; 1],
        _x: &[S; 1],
        _x_dot: &[S; 1],
        _cartesian_force: &mut [S; 1],
        generalized_force: &mut [S; 1],
    ) {
        generalized_force[0] -= v[0] * self.damping;
    }
}
lagrange_core::impl_mechanism!(Oscillator, 1, 1);

/// Mathematical pendulum, unit mass and length, g = 1: q̈ = −sin q. Its mass matrix is
/// sin² + cos² = 1, constant up to round-off.
pub struct Pendulum;

impl Model<1, 2> for Pendulum {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
        let bob = vec2(q[0].sin(), -q[0].cos());
        [bob.x, bob.y]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D {
        x[1]
    }
}
lagrange_core::impl_mechanism!(Pendulum, 1, 2);

/// Kepler problem in Cartesian coordinates, GM = 1, unit mass: V = −1/r.
pub struct Kepler;

impl Model<2, 2> for Kepler {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        -(x[0] * x[0] + x[1] * x[1]).sqrt().recip()
    }
}
lagrange_core::impl_mechanism!(Kepler, 2, 2);

/// Double pendulum, unit masses and lengths, g = 1: a mass matrix that depends on q.
pub struct DoublePendulum;

impl Model<2, 4> for DoublePendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 4] {
        [1.0; 4]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let bob1 = vec2(q[0].sin(), -q[0].cos());
        let bob2 = bob1 + vec2(q[1].sin(), -q[1].cos());
        [bob1.x, bob1.y, bob2.x, bob2.y]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        x[1] + x[3]
    }
}
lagrange_core::impl_mechanism!(DoublePendulum, 2, 4);

/// Exact Kepler orbit with a = 1, GM = 1 (period 2π) starting at periapsis of eccentricity e:
/// q₀ = (1 − e, 0), v₀ = (0, √((1 + e)/(1 − e))). Position and velocity at time t from Kepler's
/// equation E − e sin E = t, solved by Newton's method.
pub fn kepler_exact(e: f64, t: f64) -> ([f64; 2], [f64; 2]) {
    let m = t.rem_euclid(2.0 * std::f64::consts::PI);
    let mut big_e = if e < 0.8 { m } else { std::f64::consts::PI };
    for _ in 0..50 {
        let d = (big_e - e * big_e.sin() - m) / (1.0 - e * big_e.cos());
        big_e -= d;
        if d.abs() < 1e-16 {
            break;
        }
    }
    let (s, c) = big_e.sin_cos();
    let b = (1.0 - e * e).sqrt();
    let den = 1.0 - e * c;
    ([c - e, b * s], [-s / den, b * c / den])
}

/// Initial state of [`kepler_exact`].
fn kepler_start(e: f64) -> lagrange_core::State<[f64; 2]> {
    lagrange_core::State::new(0.0, [1.0 - e, 0.0], [0.0, ((1.0 + e) / (1.0 - e)).sqrt()])
}

/// Fermi–Pasta–Ulam chain (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.5.1):
/// six unit masses between walls, alternately joined by stiff linear springs (ω²/4 (Δq)², ω = 50)
/// and soft quartic ones ((Δq)⁴).
pub struct Fpu;

const FPU_OMEGA: f64 = 50.0;

impl Model<6, 6> for Fpu {
    type Coords = [f64; 6];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 6] {
        [1.0; 6]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 6]) -> [D; 6] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 6], x: &[D; 6]) -> D {
        let mut v = D::zero();
        for i in 0..3 {
            let d = x[2 * i + 1] - x[2 * i];
            v += d * d * (FPU_OMEGA * FPU_OMEGA / 4.0);
        }
        let soft = |d: D| (d * d) * (d * d);
        v + soft(x[0]) + soft(x[2] - x[1]) + soft(x[4] - x[3]) + soft(x[5])
    }
}
lagrange_core::impl_mechanism!(Fpu, 6, 6);

/// HLW's initial values: the first stiff spring stretched by 1/ω and moving, all else at rest.
fn fpu_start() -> State<[f64; 6]> {
    let (w, r) = (FPU_OMEGA, std::f64::consts::FRAC_1_SQRT_2);
    State::new(
        0.0,
        [(1.0 - 1.0 / w) * r, (1.0 + 1.0 / w) * r, 0.0, 0.0, 0.0, 0.0],
        [0.0, 2f64.sqrt(), 0.0, 0.0, 0.0, 0.0],
    )
}

// Errors that name their cause.

/// A particle in polar coordinates (r, φ) under gravity: M = diag(1, r²), which overflows to ∞ for
/// r ≳ 1e154.
pub struct Polar;

impl Model<2, 2> for Polar {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        let p = vec2(q[1].cos(), q[1].sin()) * q[0];
        [p.x, p.y]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * 9.81
    }
}
lagrange_core::impl_mechanism!(Polar, 2, 2);

#[test]
fn step_that_does_not_advance_time_is_refused() {
    fn refused<I: Integrator>() {
        let start = State::new(1.0, [0.3], [0.1]);
        let mut s = start;
        // 5e-324 is the smallest subnormal: 1 + 5e-324 == 1.
        let err = Pendulum.step::<I>(&mut s, 5e-324).unwrap_err();
        assert!(
            matches!(err, Error::StepDoesNotAdvance { t, h } if t == 1.0 && h == 5e-324),
            "{}: {err}",
            I::NAME
        );
        assert_eq!(s, start);
        // At t = 0 the same step does advance time.
        let mut s = State::new(0.0, [0.3], [0.1]);
        Pendulum.step::<I>(&mut s, 5e-324).unwrap();
        assert_eq!(s.t, 5e-324);
    }
    refused::<Rk4>();
    refused::<ImplicitMidpoint>();
    refused::<GaussLegendre2>();
    refused::<Variational>();
    refused::<StormerVerlet>();
}

#[test]
fn dopri5_tolerance_below_round_off_is_a_step_size_underflow() {
    // At t = 1 a step below ~1e-16 no longer advances time, long before an error estimate against
    // tolerances of 1e-300 can be met: the controller must run out of step size, at a finite
    // configuration where the dynamics are fine.
    let start = State::new(1.0, [1.0], [0.0]);
    let mut s = start;
    let err = Oscillator { damping: 0.0 }
        .integrate(Dopri5::new(1e-300, 1e-300), &mut s, 2.0, &mut [], |_| {})
        .unwrap_err();
    assert!(
        matches!(err, Error::StepSizeUnderflow { t, .. } if t == 1.0),
        "{err}"
    );
    assert_eq!(s, start);
}

#[test]
fn implicit_step_far_too_large_names_the_breakdown_and_the_step() {
    fn breaks_down<I: Integrator>() {
        for start in [State::new(0.0, [0.3], [0.0]), State::new(0.0, [0.3], [0.2])] {
            let mut s = start;
            let err = Pendulum.step::<I>(&mut s, 1e300).unwrap_err();
            assert!(
                matches!(err, Error::NewtonBreakdown { h, .. } if h == 1e300),
                "{}: {err}",
                I::NAME
            );
            assert_eq!(s, start);
        }
    }
    breaks_down::<ImplicitMidpoint>();
    breaks_down::<GaussLegendre2>();
    breaks_down::<Variational>();
}

#[test]
fn overflowing_mass_matrix_is_non_finite_dynamics_not_a_singular_one() {
    // r = 1e300: M = diag(1, ∞). Not a singular mass matrix with "pivot 1".
    let err = Polar
        .accelerations(&State::new(0.0, [1e300, 0.3], [0.0, 0.0]))
        .unwrap_err();
    assert!(matches!(err, Error::NonFiniteDynamics { .. }), "{err}");
    // RK4 with h = 1e300: the second stage sits at r ≈ 2.5e299.
    let start = State::new(0.0, [1.0, 0.3], [0.5, 0.2]);
    let mut s = start;
    let err = Polar.step::<Rk4>(&mut s, 1e300).unwrap_err();
    assert!(
        matches!(err, Error::NonFiniteDynamics { t, .. } if t == 5e299),
        "{err}"
    );
    assert_eq!(s, start);
}

#[test]
fn dopri5_end_time_before_the_start_is_named_as_such() {
    let start = State::new(1.0, [1.0], [0.0]);
    for t_end in [0.5, f64::NAN, f64::INFINITY] {
        let mut s = start;
        let err = Oscillator { damping: 0.0 }
            .integrate(Dopri5::default(), &mut s, t_end, &mut [], |_| {})
            .unwrap_err();
        assert!(
            matches!(err, Error::InvalidEndTime { t, t_end: end } if t == 1.0 && end.to_bits() == t_end.to_bits()),
            "{err}"
        );
        assert_eq!(s, start);
    }
    let mut stepper =
        Stepper::new(&Oscillator { damping: 0.0 }, Dopri5::default(), &start).unwrap();
    assert!(matches!(
        stepper.step(1.0),
        Err(Error::InvalidEndTime { t_end, .. }) if t_end == 1.0
    ));
}

// The common stepping interface.

/// End-point error after one Kepler period with n steps of a solver that keeps its working
/// memory (the implicit methods' Newton matrix) from step to step; also the Jacobians per step.
fn kepler_error_solver<I: Integrator>(n: usize) -> (f64, f64) {
    let start = kepler_start(E);
    let h = 2.0 * PI / n as f64;
    let mut solver = Stepper::new(&Kepler, Fixed::<I>::new(h), &start).unwrap();
    let out = solver.integrate(2.0 * PI, &mut [], |_| {}).unwrap();
    assert_eq!(out.stats.accepted, n);
    let s = solver.state();
    let (q, v) = kepler_exact(E, s.t);
    (
        distance(&s.q, &s.v, &q, &v),
        out.stats.jacobians as f64 / n as f64,
    )
}

#[test]
fn implicit_solvers_reuse_the_jacobian_and_keep_their_order() {
    // The simplified Newton iteration is iterated to round-off like the exact one, so reusing the
    // Newton matrix changes the result only at round-off level (≪ the 1e-7…1e-3 errors here): the
    // orders must be those of the methods, 4 and 2. At these step counts the leading error term
    // dominates: the fresh-memory runs above measure 3.997 and 2.000, so ±0.1 leaves room for the
    // next term only. The Jacobian must actually be reused: on this smooth orbit a refresh is due
    // only when the contraction factor passes 0.1, far less than once per step (< 0.2 asserted).
    for (name, err, n, order) in [
        (
            "Gauss-Legendre 2 solver",
            kepler_error_solver::<GaussLegendre2> as fn(usize) -> (f64, f64),
            200,
            4.0,
        ),
        (
            "implicit midpoint solver",
            kepler_error_solver::<ImplicitMidpoint>,
            1000,
            2.0,
        ),
    ] {
        let p = observed_order(name, |n| err(n).0, n);
        assert!((p - order).abs() < 0.1, "{name}: observed order {p}");
        let (_, jacobians) = err(4 * n);
        eprintln!("{name}: {jacobians:.3} Jacobians per step");
        assert!(jacobians < 0.2, "{name}: {jacobians} Jacobians per step");
        // Same method with fresh memory every step (`sys.step::<I>`): same result to round-off.
        let fresh = if order == 4.0 {
            kepler_error::<GaussLegendre2>(n)
        } else {
            kepler_error::<ImplicitMidpoint>(n)
        };
        let kept = err(n).0;
        assert!(
            (fresh - kept).abs() < 1e-9 * fresh.max(1.0),
            "{name}: {fresh} vs {kept}"
        );
    }
}

#[test]
fn dopri5_as_a_type_parameter_advances_by_h() {
    // `sys.step::<Dopri5>(&mut s, h)` integrates over [t, t + h] with the default tolerances
    // (rtol 1e-6, atol 1e-9): after 10 such calls of h = 2π/10 the state is at t = 2π exactly
    // (steps land on t + h) and the error is that of a tolerance-1e-6 integration over a period:
    // about 140 steps (measured) each allowed a local error of 1e-6 relative, accumulated and
    // amplified by the orbit's error growth near perihelion (speed 2): < 1e-3 (measured 1.6e-4).
    let mut s = kepler_start(E);
    for _ in 0..10 {
        Kepler.step::<Dopri5>(&mut s, 2.0 * PI / 10.0).unwrap();
    }
    assert!((s.t - 2.0 * PI).abs() < 1e-14);
    let (q, v) = kepler_exact(E, s.t);
    let err = distance(&s.q, &s.v, &q, &v);
    assert!(err < 1e-3 && err > 0.0, "error {err}");
}

#[test]
fn every_solver_integrates_with_events_through_the_same_interface() {
    use lagrange_core::integrate::Method;
    // Kepler from perihelion: the radial velocity r·ṙ = x·ẋ crosses zero (rising → falling) at
    // aphelion, t = π exactly (half the period 2π for a = 1). Each solver locates it on its dense
    // output: Dopri5's of order 4 at rtol 1e-10, GL2 at h = 2π/2000 with the cubic Hermite
    // interpolant (error O(h⁴) ≈ 1e-12, plus the method's O(h⁴) ≈ 1e-11 global error in the phase):
    // both well within 1e-8 of π.
    fn run<Me: Method<2>>(name: &str, solver: &mut Stepper<'_, Kepler, Me, 2>) {
        let radial = |s: &State<[f64; 2]>| s.q[0] * s.v[0] + s.q[1] * s.v[1];
        let mut events = [Event::new(&radial).direction(Direction::Falling).terminal()];
        let out = solver.integrate(5.0, &mut events, |_| {}).unwrap();
        let StopReason::Event(hit) = out.reason else {
            panic!("{name}: no event")
        };
        eprintln!("{name}: aphelion at {:.15}, {:?}", hit.state.t, out.stats);
        assert!((hit.state.t - PI).abs() < 1e-8, "{name}: {}", hit.state.t);
        assert!(out.stats.accepted > 0 && out.stats.evaluations > 0);
    }
    let start = kepler_start(E);
    run(
        "Dopri5",
        &mut Stepper::new(&Kepler, Dopri5::new(1e-10, 1e-12), &start).unwrap(),
    );
    run(
        "Gauss-Legendre 2",
        &mut Stepper::new(
            &Kepler,
            Fixed::<GaussLegendre2>::new(2.0 * PI / 2000.0),
            &start,
        )
        .unwrap(),
    );
    run(
        "RK4",
        &mut Stepper::new(&Kepler, Fixed::<Rk4>::new(2.0 * PI / 2000.0), &start).unwrap(),
    );
}

// Dop853.

/// End-point error after one period of the Kepler orbit of eccentricity `e` with n Dop853 steps.
fn kepler_error_dop853(e: f64, n: usize) -> f64 {
    use lagrange_core::integrate::Dop853;
    // Used as a fixed-step method (tolerances so loose that no step is rejected) to observe the
    // order of its 8th-order solution.
    let settings = Dop853 {
        rtol: 1e10,
        atol: 1e10,
        h_init: Some(2.0 * PI / n as f64),
        h_max: 2.0 * PI / n as f64,
        dense: false,
        ..Dop853::default()
    };
    let mut s = kepler_start(e);
    let out = Kepler
        .integrate(settings, &mut s, 2.0 * PI, &mut [], |_| {})
        .unwrap();
    assert_eq!(out.stats.accepted, n);
    let (q, v) = kepler_exact(e, s.t);
    distance(&s.q, &s.v, &q, &v)
}

#[test]
fn dop853_is_eighth_order() {
    // An 8th-order method has a narrow window between its pre-asymptotic regime and round-off in
    // double precision. On Kepler orbits (printed for the record) the observed order is still 7.7
    // at e = 0.2 (40 → 80 steps) where the next halving already meets round-off (≈ 5e-14), and 7.95
    // at e = 0.6 (200 → 400 steps) with round-off (≈ 7e-13) in the finer error. On the harmonic
    // oscillator q̈ = −q over ten periods the window is wide: with 8, 16 and 32 steps per period the
    // errors (≈ 6e-7, 2e-9, 9e-12) are far above round-off and hω ≤ 0.8 is small enough for the
    // leading term to dominate: the measured order is 8.02, and ±0.1 leaves room for the next term.
    observed_order(
        "Dop853 on Kepler e = 0.2",
        |n| kepler_error_dop853(0.2, n),
        20,
    );
    let oscillator = |n: usize| {
        use lagrange_core::integrate::Dop853;
        let h = 2.0 * PI / n as f64;
        let settings = Dop853 {
            rtol: 1e10,
            atol: 1e10,
            h_init: Some(h),
            h_max: h,
            dense: false,
            ..Dop853::default()
        };
        let mut s = State::new(0.0, [1.0], [0.0]);
        let t_end = 20.0 * PI;
        let out = Oscillator { damping: 0.0 }
            .integrate(settings, &mut s, t_end, &mut [], |_| {})
            .unwrap();
        assert_eq!(out.stats.accepted, 10 * n);
        (s.q[0] - t_end.cos())
            .abs()
            .max((s.v[0] + t_end.sin()).abs())
    };
    let p = observed_order("Dop853 on the oscillator", oscillator, 8);
    assert!((p - 8.0).abs() < 0.1, "observed order {p}");
}

#[test]
fn dop853_locates_aphelion_to_1e_12_and_agrees_with_dopri5() {
    use lagrange_core::integrate::Dop853;
    // Kepler from perihelion: r·ṙ falls through zero at aphelion, t = π exactly (a = 1). At
    // rtol 1e-13 the solution's phase error is ≈ 1e-12 at most (measured end-point error below);
    // the event is located on the 7th-order dense output to EVENT_TIME_TOLERANCE = 1e-13; so the
    // event time is within 1e-12 of π.
    let radial = |s: &State<[f64; 2]>| s.q[0] * s.v[0] + s.q[1] * s.v[1];
    let mut s = kepler_start(E);
    let mut events = [Event::new(&radial).direction(Direction::Falling)];
    let mut hits = Vec::new();
    let out = Kepler
        .integrate(
            Dop853::new(1e-13, 1e-15),
            &mut s,
            2.0 * PI,
            &mut events,
            |o| {
                if let Observation::Event(hit) = o {
                    hits.push(hit.state.t);
                }
            },
        )
        .unwrap();
    assert_eq!(hits.len(), 1);
    eprintln!(
        "Dop853 aphelion: {:.3e} from π, {:?}",
        hits[0] - PI,
        out.stats
    );
    assert!((hits[0] - PI).abs() < 1e-12, "{}", hits[0] - PI);
    let (q, v) = kepler_exact(E, s.t);
    let err853 = distance(&s.q, &s.v, &q, &v);
    // Dopri5 at the same tolerance reaches the same end point: both within 1e-10 of the exact
    // orbit (the tolerance is local; the global error of ≈ 1e3 steps is a few hundred times it), so
    // within 2e-10 of each other — and Dop853 takes fewer evaluations.
    let mut s5 = kepler_start(E);
    let out5 = Kepler
        .integrate(
            Dopri5::new(1e-13, 1e-15),
            &mut s5,
            2.0 * PI,
            &mut [],
            |_| {},
        )
        .unwrap();
    let err5 = distance(&s5.q, &s5.v, &q, &v);
    let between = distance(&s.q, &s.v, &s5.q, &s5.v);
    eprintln!(
        "end-point errors: Dop853 {err853:.2e} ({} evaluations), Dopri5 {err5:.2e} ({}), between {between:.2e}",
        out.stats.evaluations, out5.stats.evaluations
    );
    assert!(err853 < 1e-10 && err5 < 1e-10 && between < 2e-10);
    assert!(out.stats.evaluations < out5.stats.evaluations);
}

#[test]
fn dop853_dense_output_is_seventh_order_accurate_inside_steps() {
    use lagrange_core::integrate::Dop853;
    // Inside each step of a Dop853 run at rtol 1e-11 the dense output is compared with the exact
    // orbit at the step's midpoint: the continuous extension of order 7 adds an O(h⁸) error of the
    // size of the step's local error, so it stays within 1e-8 (≫ the measured ≈ 1e-10, ≪ the
    // ≈ 1e-4 that a cubic Hermite interpolant would leave at these step sizes).
    let start = kepler_start(E);
    let mut stepper = Stepper::new(&Kepler, Dop853::new(1e-11, 1e-13), &start).unwrap();
    let mut worst = 0.0f64;
    while Stepper::t(&stepper) < 2.0 * PI {
        stepper.step(2.0 * PI).unwrap();
        let d = Stepper::dense(&stepper);
        let tm = 0.5 * (d.t_start() + d.t_end());
        let (q, v) = d.eval(tm);
        let (qe, ve) = kepler_exact(E, tm);
        worst = worst.max(distance(&q, &v, &qe, &ve));
    }
    eprintln!("Dop853 dense output: worst midpoint error {worst:.2e}");
    assert!(worst < 1e-8 && worst > 0.0, "{worst}");
}

#[test]
fn constrained_or_not_is_decided_by_the_declaration_not_by_lambda() {
    // `impl_mechanism!` declares the constraint rows by kind.
    assert_eq!(
        <CartesianPendulum as lagrange_core::mechanism::Dynamics<2>>::CONSTRAINTS,
        Some(1)
    );
    assert_eq!(
        <CartesianPendulum as lagrange_core::mechanism::Dynamics<2>>::CONSTRAINT_COUNTS
            .map(|c| c.holonomic),
        Some(1)
    );
    assert_eq!(
        <Kepler as lagrange_core::mechanism::Dynamics<2>>::CONSTRAINTS,
        Some(0)
    );
    // Released horizontally at rest the rod's tension m(g cos θ + L θ̇²) is zero: λ = 0 at the
    // first step. A decision from λ would take that step unconstrained and refuse the next one; the
    // declaration makes every step RATTLE, which keeps the rod.
    let horizontal = State::new(0.0, [1.0, 0.0], [0.0, 0.0]);
    for (name, end) in [
        ("variational", {
            let mut s = horizontal;
            for _ in 0..2 {
                CartesianPendulum.step::<Variational>(&mut s, 0.01).unwrap();
            }
            s
        }),
        ("Störmer–Verlet", {
            let mut s = horizontal;
            for _ in 0..2 {
                CartesianPendulum
                    .step::<StormerVerlet>(&mut s, 0.01)
                    .unwrap();
            }
            s
        }),
    ] {
        let r = (end.q[0] * end.q[0] + end.q[1] * end.q[1]).sqrt();
        assert!((r - 1.0).abs() < 1e-14 && end.q[1] < 0.0, "{name}: {end:?}");
    }
}
