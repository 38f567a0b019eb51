//! Integrators against exact solutions: observed orders of convergence, Dopri5's error control,
//! dense output and event location, long-time energy behaviour, and errors that leave the state
//! alone. Models are written by hand at the end of this file.

use lagrange_core::dynamics::{self, EquationsOfMotion};
use lagrange_core::integrate::{Direction, Dopri5Stepper, Event, Observation, StopReason};
use lagrange_core::{vec2, Model, Scalar};
use lagrange_core::{
    Dopri5, Error, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Rk4, State,
    StormerVerlet, Variational,
};
use std::f64::consts::PI;

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
    let out = dopri5_fixed(h)
        .integrate(&Kepler, &mut s, 2.0 * PI, &mut [], |_| {})
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

// ---------------------------------------------------------------------------------------------
// Hand-written models (the pattern of `hand_written_model.rs`: what `#[mechanism]` generates).

/// Implements `Mechanism<N>` for a `Model<N, K>` by forwarding to `lagrange_core::dynamics`, as the
/// generated glue does.
macro_rules! mechanism_from_model {
    ($ty:ty, $n:literal) => {
        impl Mechanism<$n> for $ty {
            type Coords = [f64; $n];
            fn validate(&self) -> lagrange_core::Result<()> {
                Ok(())
            }
            fn equations_of_motion_at<S: Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> EquationsOfMotion<S, $n> {
                dynamics::equations_of_motion(self, t, q, v)
            }
            fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> S {
                dynamics::kinetic_energy(self, t, q, v)
            }
            fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; $n]) -> S {
                dynamics::potential_energy(self, t, q)
            }
            fn momenta_at<S: Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> [S; $n] {
                dynamics::momenta(self, t, q, v)
            }
            fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> f64 {
                dynamics::lagrangian_time_derivative(self, t, q, v)
            }
        }
    };
}

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
mechanism_from_model!(Oscillator, 1);

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
mechanism_from_model!(Pendulum, 1);

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
mechanism_from_model!(Kepler, 2);

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
mechanism_from_model!(DoublePendulum, 2);

/// q̈ = q² (V = −q³/3): from q = 1, q̇ = √(2/3) (zero energy) the solution q = 4/(2 − √(2/3) t)²
/// blows up at t = √6.
pub struct BlowUp;

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
        [q[0]]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D {
        -(x[0] * x[0] * x[0]) / 3.0
    }
}
mechanism_from_model!(BlowUp, 1);

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
pub fn kepler_start(e: f64) -> lagrange_core::State<[f64; 2]> {
    lagrange_core::State::new(0.0, [1.0 - e, 0.0], [0.0, ((1.0 + e) / (1.0 - e)).sqrt()])
}
