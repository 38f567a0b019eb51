//! Radau IIA of order 5 against exact solutions: its observed order with fixed steps, its advantage
//! over Dopri5 on a stiff chain (checked against the closed form), the reuse of its Jacobian and
//! factorisation, dense output and events, constraints, and errors that leave the state alone.

use lagrange_core::constraints::{ConstraintKind, Constraints};
use lagrange_core::integrate::{Direction, Event, Observation, Stepper, StopReason};
use lagrange_core::{vec2, Dopri5, Error, Mechanism, Model, Radau5, Scalar, State};
use std::f64::consts::PI;

/// Max-norm distance between two states' (q, v).
fn distance<const N: usize>(q: &[f64; N], v: &[f64; N], q_ref: &[f64; N], v_ref: &[f64; N]) -> f64 {
    q.iter()
        .zip(q_ref)
        .chain(v.iter().zip(v_ref))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

/// Radau5 as a fixed-step method: h_init = h_max = h, tolerances so loose that no step is rejected,
/// and the Newton iteration run to round-off (a tiny κ·tol, up to 50 iterations), so that the error
/// is the method's own.
fn radau5_fixed(h: f64) -> Radau5 {
    Radau5 {
        rtol: 1e10,
        atol: 1e10,
        h_init: Some(h),
        h_max: h,
        max_newton_iterations: 50,
        newton_tolerance: Some(1e-30),
        ..Radau5::default()
    }
}

/// End-point error after one period of the e = 0.6 Kepler orbit with n steps of Radau5.
fn kepler_error(n: usize) -> f64 {
    let e: f64 = 0.6;
    let mut s = State::new(0.0, [1.0 - e, 0.0], [0.0, ((1.0 + e) / (1.0 - e)).sqrt()]);
    let out = Kepler
        .integrate(
            radau5_fixed(2.0 * PI / n as f64),
            &mut s,
            2.0 * PI,
            &mut [],
            |_| {},
        )
        .unwrap();
    assert_eq!((out.stats.accepted, out.stats.rejected), (n, 0));
    let (q, v) = kepler_exact(e, s.t);
    distance(&s.q, &s.v, &q, &v)
}

#[test]
fn radau5_is_fifth_order() {
    // Radau IIA with 3 stages has classical order 2s − 1 = 5 (HW II, §IV.5, Theorem 5.3). The step
    // counts put the errors in the asymptotic regime (the ratio of successive errors is stable)
    // and far above round-off (≥ 1e-10 against ~1e-15·n accumulated rounding); the next error term
    // changes the observed order by O(h), measured below 0.05 at these step counts.
    let n = 400;
    let (e1, e2, e3) = (kepler_error(n), kepler_error(2 * n), kepler_error(4 * n));
    let (p1, p2) = ((e1 / e2).log2(), (e2 / e3).log2());
    eprintln!("Radau5: errors {e1:.3e} {e2:.3e} {e3:.3e}, orders {p1:.3} {p2:.3}");
    assert!((p2 - 5.0).abs() < 0.1, "observed order {p2}");
}

/// The stiff pair's fast angular frequency: the larger eigenvalue of K is tr − λ_slow.
fn omega_stiff() -> f64 {
    let (slow, _) = stiff_pair_slow_mode();
    (1.0 + 2.0 * STIFF_K - slow * slow).sqrt()
}

/// The slow normal mode of the stiff pair (ω_slow, and x₂/x₁ along it).
fn stiff_pair_slow_mode() -> (f64, f64) {
    // K = [[k₁ + k₂, −k₂], [−k₂, k₂]] with unit masses: the smaller eigenvalue and its eigenvector.
    let (k1, k2) = (1.0, STIFF_K);
    let (tr, det) = (k1 + 2.0 * k2, k1 * k2);
    let lambda = det / (0.5 * tr + (0.25 * tr * tr - det).sqrt()); // the small root, without cancellation
    (lambda.sqrt(), (k1 + k2 - lambda) / k2)
}

#[test]
fn radau5_takes_far_fewer_steps_than_dopri5_on_a_stiff_chain() {
    // Two unit masses: the first tied to the wall by a soft spring (k = 1), the second tied to
    // the first by a stiff one (k = 10⁶, ω ≈ 1414). Released at rest along the slow normal mode,
    // the exact motion is x(t) = x(0)·cos(ω_slow t). Dopri5's stability region forces hω ≲ 3.3 on
    // the stiff mode whatever the tolerance; the L-stable Radau5 follows the slow motion only.
    let (omega, ratio) = stiff_pair_slow_mode();
    let start = State::new(0.0, [1.0, ratio], [0.0, 0.0]);
    let t_end = 10.0;
    let (rtol, atol) = (1e-6, 1e-8);
    let mut radau = start;
    let r = StiffPair
        .integrate(Radau5::new(rtol, atol), &mut radau, t_end, &mut [], |_| {})
        .unwrap();
    let mut dopri = start;
    let d = StiffPair
        .integrate(Dopri5::new(rtol, atol), &mut dopri, t_end, &mut [], |_| {})
        .unwrap();
    let c = (omega * t_end).cos();
    let s = (omega * t_end).sin();
    let exact_q = [c, ratio * c];
    let exact_v = [-omega * s, -ratio * omega * s];
    let err_radau = distance(&radau.q, &radau.v, &exact_q, &exact_v);
    let err_dopri = distance(&dopri.q, &dopri.v, &exact_q, &exact_v);
    eprintln!("stiff pair: Radau5 {:?} error {err_radau:.2e}", r.stats);
    eprintln!("stiff pair: Dopri5 {:?} error {err_dopri:.2e}", d.stats);
    // Radau5 meets the tolerance in the global error up to the usual factor of tolerance
    // proportionality (ten times rtol on a solution of size 1). Dopri5, held at its stability
    // boundary on the stiff mode, lets that mode carry noise of about the tolerance in position,
    // which shows ω ≈ 1414 times larger in the velocity: its error is bounded by ω·rtol.
    assert!(err_radau < 10.0 * rtol, "{err_radau}");
    assert!(err_dopri < omega_stiff() * rtol, "{err_dopri}");
    // The stability bound alone costs Dopri5 t_end·ω/3.3 ≈ 4300 steps; Radau5 needs a few dozen.
    assert!(d.stats.accepted > 4000, "{:?}", d.stats);
    assert!(r.stats.accepted * 20 < d.stats.accepted, "{:?}", r.stats);
    assert!(r.stats.evaluations * 10 < d.stats.evaluations);
    // The Jacobian and its factorisation are reused across steps.
    assert!(r.stats.jacobians < r.stats.accepted, "{:?}", r.stats);
    assert!(r.stats.factorizations <= r.stats.accepted + r.stats.rejected);
}

#[test]
fn radau5_meets_its_tolerance_on_the_stiff_chain_at_tight_tolerance() {
    // At rtol = 1e-10 the global error after ~1.5 slow periods stays within 100·rtol (the
    // tolerance is per step; radau5.f's conversion rtol′ = 0.1·rtol^(2/3) aims the global error
    // near rtol), and falls with the tolerance.
    let (omega, ratio) = stiff_pair_slow_mode();
    let start = State::new(0.0, [1.0, ratio], [0.0, 0.0]);
    let t_end = 10.0;
    let exact_q = [(omega * t_end).cos(), ratio * (omega * t_end).cos()];
    let exact_v = [
        -omega * (omega * t_end).sin(),
        -ratio * omega * (omega * t_end).sin(),
    ];
    let mut errors = vec![];
    for tol in [1e-6, 1e-8, 1e-10] {
        let mut s = start;
        let out = StiffPair
            .integrate(Radau5::new(tol, tol), &mut s, t_end, &mut [], |_| {})
            .unwrap();
        let err = distance(&s.q, &s.v, &exact_q, &exact_v);
        eprintln!("tol {tol:e}: error {err:.2e}, {:?}", out.stats);
        errors.push(err);
    }
    assert!(errors[2] < 1e-8, "{errors:?}");
    assert!(errors[0] > errors[1] && errors[1] > errors[2], "{errors:?}");
}

#[test]
fn radau5_dense_output_and_events_on_the_oscillator() {
    // x'' = −x from x = 1: the zeros of x at π/2 + kπ. The collocation polynomial is a dense
    // output of order 3 (the stage order): at rtol = 1e-9 its error inside a step is
    // O(h⁴)·|x⁽⁴⁾| with the h that rtol′ ≈ 1e-7 allows, well below 1e-5.
    let start = State::new(0.0, [1.0], [0.0]);
    let mut solver = Stepper::new(&Oscillator, Radau5::new(1e-9, 1e-9), &start).unwrap();
    let g = |s: &State<[f64; 1]>| s.q[0];
    let mut events = [Event::new(&g).direction(Direction::Either)];
    let mut hits = vec![];
    let mut worst_dense = 0.0f64;
    let out = solver
        .integrate(10.0, &mut events, |o| match o {
            Observation::Event(hit) => hits.push(hit.state.t),
            Observation::Step { dense, .. } => {
                let t = 0.5 * (dense.t_start() + dense.t_end());
                let (q, v) = dense.eval(t);
                worst_dense = worst_dense.max((q[0] - t.cos()).abs().max((v[0] + t.sin()).abs()));
            }
        })
        .unwrap();
    assert_eq!(out.reason, StopReason::Reached);
    assert_eq!(hits.len(), 3, "{hits:?}");
    for (k, t) in hits.iter().enumerate() {
        assert!((t - (PI / 2.0 + k as f64 * PI)).abs() < 1e-6, "{t}");
    }
    assert!(worst_dense < 1e-5, "{worst_dense}");
    assert!((solver.state().q[0] - 10f64.cos()).abs() < 1e-6);
}

#[test]
fn radau5_keeps_the_constrained_pendulum_on_its_circle() {
    // A particle in the plane on a rod of length 1 (one holonomic constraint, its force in q̈):
    // as with Dopri5, every accepted step is projected onto the constraint, and the motion agrees
    // with Dopri5's at tight tolerances to within both tolerances' global errors.
    let start = State::new(0.0, [1.0, 0.0], [0.0, 0.0]);
    let mut radau = start;
    Rod.integrate(Radau5::new(1e-9, 1e-9), &mut radau, 3.0, &mut [], |_| {})
        .unwrap();
    let mut dopri = start;
    Rod.integrate(Dopri5::new(1e-11, 1e-11), &mut dopri, 3.0, &mut [], |_| {})
        .unwrap();
    let r = (radau.q[0].powi(2) + radau.q[1].powi(2)).sqrt();
    assert!((r - 1.0).abs() < 1e-12, "{r}");
    let d = distance(&radau.q, &radau.v, &dopri.q, &dopri.v);
    assert!(d < 1e-6, "{d}");
}

#[test]
fn radau5_errors_name_their_cause_and_leave_the_state_alone() {
    let start = State::new(0.0, [1.0], [0.0]);
    let bad = Radau5 {
        rtol: -1.0,
        ..Radau5::default()
    };
    assert!(matches!(
        Stepper::new(&Oscillator, bad, &start),
        Err(Error::InvalidSetting {
            setting: "rtol",
            ..
        })
    ));
    let no_atol = Radau5::new(1e-6, 0.0);
    assert!(matches!(
        Stepper::new(&Oscillator, no_atol, &start),
        Err(Error::InvalidSetting {
            setting: "atol",
            ..
        })
    ));
    // q̈ = q² from q = 1, q̇ = √(2/3) blows up at t = √6: the integration to 3 fails and the state
    // stays where it was.
    let mut s = State::new(0.0, [1.0], [(2.0f64 / 3.0).sqrt()]);
    let before = s;
    let r = BlowUp.integrate(Radau5::new(1e-8, 1e-8), &mut s, 3.0, &mut [], |_| {});
    assert!(r.is_err(), "{r:?}");
    assert_eq!(s, before);
    // An end time before the start.
    let mut solver = Stepper::new(&Oscillator, Radau5::default(), &start).unwrap();
    assert!(matches!(
        solver.integrate(-1.0, &mut [], |_| {}),
        Err(Error::InvalidEndTime { .. })
    ));
    // One validated step through the Integrator interface.
    let mut s = start;
    Oscillator.step::<Radau5>(&mut s, 0.5).unwrap();
    assert_eq!(s.t, 0.5);
    assert!((s.q[0] - 0.5f64.cos()).abs() < 1e-5);
}

// Models, written by hand.

/// Stiffness of the stiff spring of [`StiffPair`] (ω ≈ √(2k) ≈ 1414).
const STIFF_K: f64 = 1e6;

/// Two unit masses on a line: x₁ tied to the wall by a spring of stiffness 1, x₂ to x₁ by one of
/// stiffness [`STIFF_K`].
struct StiffPair;

impl Model<2, 2> for StiffPair {
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
        let d = x[1] - x[0];
        x[0] * x[0] * 0.5 + d * d * (0.5 * STIFF_K)
    }
}
lagrange_core::impl_mechanism!(StiffPair, 2, 2);

/// A unit mass in the plane on a rod of length 1 from the origin, under gravity g = 9.81.
struct Rod;

impl Model<2, 2> for Rod {
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
        x[1] * 9.81
    }
}

impl Constraints<2, 2, 1> for Rod {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - 1.0]
    }
}
lagrange_core::impl_mechanism!(Rod, 2, 2, constraints);

/// x'' = −x.
struct Oscillator;

impl Model<1, 1> for Oscillator {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 1] {
        [1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D {
        x[0] * x[0] * 0.5
    }
}
lagrange_core::impl_mechanism!(Oscillator, 1, 1);

/// q̈ = q² (V = −q³/3).
struct BlowUp;

impl Model<1, 1> for BlowUp {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 1] {
        [1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D {
        -(x[0] * x[0] * x[0]) / 3.0
    }
}
lagrange_core::impl_mechanism!(BlowUp, 1, 1);

/// Kepler problem, GM = 1.
struct Kepler;

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

/// Exact Kepler orbit with a = 1, GM = 1 (period 2π) from periapsis of eccentricity e, by Kepler's
/// equation E − e sin E = t solved by Newton's method.
fn kepler_exact(e: f64, t: f64) -> ([f64; 2], [f64; 2]) {
    let m = t.rem_euclid(2.0 * PI);
    let mut big_e = m;
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
