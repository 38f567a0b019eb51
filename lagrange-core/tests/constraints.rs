//! Constrained mechanisms written by hand (what `#[mechanism]` generates for `#[constraint]`,
//! `#[velocity_constraint]`, `#[unilateral]` and `#[friction]` items), checked against closed forms.
//! The scenes: particle leaving a sphere, rolling wheel, four-bar linkage, Cartesian
//! pendulum, block on a rough ramp, wedge and block with friction.
//!
//! Tolerances: classical RK4 has local error O(h⁵) and global error O(h⁴) (Hairer, Nørsett &
//! Wanner I, §II.3); with h = 1e-3 and the scenes' frequencies ω ≲ 4/s, (hω)⁴ ≈ 3e-10 per unit
//! time at most, so trajectories agree with closed forms to ~1e-9 over tens of seconds. Projection
//! after every step keeps constraint residuals at round-off, independently of h.

#![allow(clippy::needless_range_loop)] // index loops over parallel arrays of q, exact values, events

use lagrange_core::constraints::{
    self, consistent_state, consistent_state_holding, constraint_forces, ConstraintKind,
    Constraints, ContactOptions, Coulomb, RowMode, CONSISTENCY_TOLERANCE,
};
#[macro_use]
mod support;

use lagrange_core::impl_mechanism;
use lagrange_core::{
    vec2, Error, GaussLegendre2, Integrator, Mechanism, Model, Rk4, Scalar, State, Stepper,
};

/// Steps of the long runs (scenes 2–4): 10⁵ in optimized builds
/// (`cargo test --release`, ~1 s each); 10⁴ in debug builds, where 10⁵ would take minutes. The
/// projection after every step keeps the constraint error at round-off independently of the run
/// length, so the shorter run checks the same property; the figures quoted in the docs are from
/// release runs.
const LONG_RUN: usize = if cfg!(debug_assertions) {
    10_000
} else {
    100_000
};

fn finite(params: &[(&'static str, f64)]) -> lagrange_core::Result<()> {
    for &(name, value) in params {
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name, value });
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Scene 4: planar pendulum in Cartesian coordinates, |r| − L = 0.

#[derive(Clone, Copy)]
struct CartesianPendulum {
    m: f64,
    l: f64,
    g: f64,
}

impl Model<2, 2> for CartesianPendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("l", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 1> for CartesianPendulum {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - self.l]
    }
}
impl_mechanism!(CartesianPendulum, 2, 2, constraints);

/// RK4 on θ̈ = −(g/L) sin θ: the angle form of the same pendulum.
fn angle_pendulum_step(p: &CartesianPendulum, th: f64, w: f64, h: f64) -> (f64, f64) {
    let f = |th: f64| -(p.g / p.l) * th.sin();
    let (k1q, k1v) = (w, f(th));
    let (k2q, k2v) = (w + 0.5 * h * k1v, f(th + 0.5 * h * k1q));
    let (k3q, k3v) = (w + 0.5 * h * k2v, f(th + 0.5 * h * k2q));
    let (k4q, k4v) = (w + h * k3v, f(th + h * k3q));
    (
        th + h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q),
        w + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
    )
}

#[test]
fn cartesian_pendulum_matches_angle_form_and_rod_tension() {
    let p = CartesianPendulum {
        m: 1.3,
        l: 0.8,
        g: 9.81,
    };
    let (th0, w0) = (1.2f64, 0.5f64);
    let mut s = State::new(
        0.0,
        [p.l * th0.sin(), -p.l * th0.cos()],
        [p.l * w0 * th0.cos(), p.l * w0 * th0.sin()],
    );
    let (mut th, mut w) = (th0, w0);
    let h = 1e-3;
    let (mut worst_position, mut worst_tension, mut worst_g, mut worst_gdot) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let e0 = p.energy(&s).unwrap();
    let mut worst_energy = 0.0f64;
    for step in 1..=LONG_RUN {
        p.step::<Rk4>(&mut s, h).unwrap();
        (th, w) = angle_pendulum_step(&p, th, w, h);
        let [x, y] = s.q;
        let [vx, vy] = s.v;
        worst_g = worst_g.max(((x * x + y * y).sqrt() - p.l).abs());
        worst_gdot = worst_gdot.max((x * vx + y * vy).abs() / p.l);
        worst_energy = worst_energy.max((p.energy(&s).unwrap() - e0).abs());
        if step <= 10_000 {
            worst_position = worst_position
                .max((x - p.l * th.sin()).abs())
                .max((y + p.l * th.cos()).abs());
        }
        if step % 1000 == 0 {
            // λ is the multiplier of |r| − L, whose gradient is the outward unit vector: the rod
            // tension (pulling inward) is T = −λ. Closed form: the radial component of Newton's
            // law for the bob, m L θ̇² = T − m g cos θ (θ from the downward vertical).
            let f = constraint_forces(&p, &s).unwrap();
            let theta = x.atan2(-y);
            let theta_dot = (x * vy - y * vx) / (p.l * p.l);
            let tension = p.m * (p.g * theta.cos() + p.l * theta_dot * theta_dot);
            worst_tension =
                worst_tension.max((-f.multipliers[0] - tension).abs() / tension.abs().max(1.0));
            // The Cartesian force of the rod on the bob is λ ∂g/∂x = −T r̂.
            let fx = f.cartesian[0][0];
            assert!((fx + tension * x / p.l).abs() < 1e-9 * tension.abs().max(1.0));
        }
    }
    println!(
        "cartesian pendulum, {LONG_RUN} RK4 steps h = 1e-3: |g| ≤ {worst_g:.2e}, |ġ| ≤ {worst_gdot:.2e}, energy drift {worst_energy:.2e}, \
         position vs angle form (1e4 steps) {worst_position:.2e}, tension rel. error {worst_tension:.2e}"
    );
    // Two RK4 solutions of the same motion, each O(h⁴) accurate: ≲ 1e-9 over 10 s (ω ≈ 3.5/s).
    assert!(
        worst_position < 1e-8,
        "position vs angle form {worst_position}"
    );
    // The tension identity holds at every state of the constrained solution up to round-off.
    assert!(worst_tension < 1e-10, "tension {worst_tension}");
    assert!(
        worst_g <= 1e-10 && worst_gdot <= 1e-10,
        "constraint error {worst_g} {worst_gdot}"
    );
    // Energy: RK4 error accumulates linearly, ~ 1e5 steps × (hω)⁵·E ≈ 1e-8·E at worst.
    assert!(
        worst_energy < 1e-7 * e0.abs().max(1.0),
        "energy {worst_energy}"
    );
}

#[test]
fn inconsistent_initial_state_is_refused_and_can_be_projected() {
    let p = CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let guess = State::new(0.0, [0.6, -0.9], [1.0, 0.3]);
    let mut s = guess;
    let err = p.step::<Rk4>(&mut s, 1e-3).unwrap_err();
    assert!(matches!(err, Error::ConstraintViolation { .. }), "{err}");
    assert!(err.to_string().contains("`rod`"), "{err}");
    assert_eq!(s, guess, "state unchanged on error");
    let fixed = consistent_state(&p, &guess).unwrap();
    let [x, y] = fixed.q;
    assert!(((x * x + y * y).sqrt() - 1.0).abs() < 1e-15);
    assert!((x * fixed.v[0] + y * fixed.v[1]).abs() < 1e-15);
    // Mass-weighted least-norm: the projection moves along the gradient (radially here).
    assert!((x / y - 0.6 / -0.9).abs() < 1e-12);
    let mut s = fixed;
    p.step::<Rk4>(&mut s, 1e-3).unwrap();
    // A constraint no configuration satisfies (|r| = −1): Newton stalls; an error with the residual.
    let impossible = CartesianPendulum { l: -1.0, ..p };
    let err = consistent_state(&impossible, &guess).unwrap_err();
    assert!(
        matches!(err, Error::ProjectionFailed { residual, .. } if residual > 1.0),
        "{err}"
    );
    // A guess at the pivot has no gradient direction to project along: an error, not NaN.
    let bad = State::new(0.0, [0.0, 0.0], [0.0, 0.0]);
    assert!(consistent_state(&p, &bad).is_err());
}

// ---------------------------------------------------------------------------------------------
// Redundant constraints: the same rod twice.

struct DoubleRod(CartesianPendulum);
delegate_model!(DoubleRod, CartesianPendulum, 2, 2);
impl Constraints<2, 2, 3> for DoubleRod {
    const NAMES: [&'static str; 3] = ["rod", "floor_guide", "second_rod"];
    const KINDS: [ConstraintKind; 3] = [
        ConstraintKind::Holonomic,
        ConstraintKind::Velocity,
        ConstraintKind::Holonomic,
    ];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 3] {
        let r = vec2(x[0], x[1]).norm();
        [r - self.0.l, D::zero(), (r - self.0.l) * 2.0]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        v: &[D; 2],
        _x: &[D; 2],
        _xd: &[D; 2],
    ) -> [D; 3] {
        // A horizontal velocity guide, independent of the rods.
        [D::zero(), v[1], D::zero()]
    }
}

#[test]
fn redundant_constraints_are_an_error_naming_them() {
    let p = DoubleRod(CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    });
    // Not at the bottom, where the rod's gradient would be vertical like the guide's.
    let q = [0.6, -0.8];
    let err = constraints::accelerations(&p, 0.0, &q, &[0.0, 0.0]).unwrap_err();
    assert!(matches!(err, Error::SingularConstraints { .. }), "{err}");
    let msg = err.to_string();
    assert!(
        msg.contains("`rod`") && msg.contains("`second_rod`") && !msg.contains("floor_guide"),
        "{msg}"
    );
}

/// A "velocity constraint" that is quadratic in the velocities.
struct NotLinear(CartesianPendulum);
impl Model<2, 2> for NotLinear {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = false;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        self.0.masses()
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 2]) -> [D; 2] {
        self.0.cartesian(t, q)
    }
}
impl Constraints<2, 2, 1> for NotLinear {
    const NAMES: [&'static str; 1] = ["speed_limit"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Velocity];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> [D; 1] {
        [D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        v: &[D; 2],
        _x: &[D; 2],
        _xd: &[D; 2],
    ) -> [D; 1] {
        [v[0] * v[0] + v[1] * v[1] - 1.0]
    }
}

#[test]
fn nonlinear_velocity_constraint_is_an_error() {
    let p = NotLinear(CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 0.0,
    });
    let err =
        constraints::check_consistent(&p, 0.0, &[0.0, 0.0], &[1.0, 0.0], CONSISTENCY_TOLERANCE)
            .unwrap_err();
    assert!(
        matches!(
            err,
            Error::NonlinearVelocityConstraint {
                constraint: "speed_limit",
                ..
            }
        ),
        "{err}"
    );
}

// ---------------------------------------------------------------------------------------------
// Scene 2: the lecture's vertical wheel rolling on a plane (Hand & Finch, Appendix 1A): q = (x, y,
// φ heading, θ rolling angle), two velocity constraints ẋ = R θ̇ cos φ, ẏ = R θ̇ sin φ.

#[derive(Clone, Copy)]
struct RollingWheel {
    m: f64,
    r: f64,
}

impl RollingWheel {
    /// Uniform disk: moment about the axle ½mR², about a diameter ¼mR².
    fn inertias(&self) -> (f64, f64) {
        (
            0.5 * self.m * self.r * self.r,
            0.25 * self.m * self.r * self.r,
        )
    }
}

impl Model<4, 4> for RollingWheel {
    type Coords = [f64; 4];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = false;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("r", self.r)])
    }
    fn masses(&self) -> [f64; 4] {
        let (axle, diameter) = self.inertias();
        [self.m, self.m, diameter, axle]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 4]) -> [D; 4] {
        // Centre (x, y); heading φ with the diametral moment, rolling angle θ with the axial one.
        *q
    }
}

impl Constraints<4, 4, 2> for RollingWheel {
    const NAMES: [&'static str; 2] = ["roll_x", "roll_y"];
    const KINDS: [ConstraintKind; 2] = [ConstraintKind::Velocity, ConstraintKind::Velocity];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 4], _x: &[D; 4]) -> [D; 2] {
        [D::zero(); 2]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        q: &[D; 4],
        v: &[D; 4],
        _x: &[D; 4],
        x_dot: &[D; 4],
    ) -> [D; 2] {
        let rolling = v[3] * self.r;
        [
            x_dot[0] - rolling * q[2].cos(),
            x_dot[1] - rolling * q[2].sin(),
        ]
    }
}
impl_mechanism!(RollingWheel, 4, 4, constraints);

/// Free rolling: with the constraint forces λ₁, λ₂ on x, y, the equations are m ẍ = λ₁, m ÿ = λ₂,
/// I_d φ̈ = 0, I_a θ̈ = −R(λ₁ cos φ + λ₂ sin φ); differentiating the constraints gives
/// (I_a + mR²) θ̈ = 0 (Greenwood, *Advanced Dynamics*, 2003, §3.4 "rolling disk", vertical case).
/// So φ = φ₀ + ωt, θ̇ = Ω and the centre moves on a circle of radius RΩ/ω (a line when ω = 0).
fn wheel_closed_form(
    w: &RollingWheel,
    q0: [f64; 4],
    omega: f64,
    big_omega: f64,
    t: f64,
) -> [f64; 4] {
    let phi = q0[2] + omega * t;
    let theta = q0[3] + big_omega * t;
    if omega == 0.0 {
        let s = w.r * big_omega * t;
        [q0[0] + s * q0[2].cos(), q0[1] + s * q0[2].sin(), phi, theta]
    } else {
        let rho = w.r * big_omega / omega;
        [
            q0[0] + rho * (phi.sin() - q0[2].sin()),
            q0[1] - rho * (phi.cos() - q0[2].cos()),
            phi,
            theta,
        ]
    }
}

fn run_wheel(omega: f64) -> (f64, f64, f64) {
    let w = RollingWheel { m: 2.0, r: 0.3 };
    let (big_omega, phi0) = (5.0f64, 0.4f64);
    let q0 = [0.1, -0.2, phi0, 0.0];
    let v0 = [
        w.r * big_omega * phi0.cos(),
        w.r * big_omega * phi0.sin(),
        omega,
        big_omega,
    ];
    let mut s = State::new(0.0, q0, v0);
    let e0 = w.energy(&s).unwrap();
    let h = 1e-3;
    let (mut slip, mut worst) = (0.0f64, 0.0f64);
    for _ in 0..LONG_RUN {
        w.step::<Rk4>(&mut s, h).unwrap();
        let [_, _, phi, _] = s.q;
        let [vx, vy, _, th_dot] = s.v;
        slip = slip
            .max((vx - w.r * th_dot * phi.cos()).abs())
            .max((vy - w.r * th_dot * phi.sin()).abs());
    }
    let exact = wheel_closed_form(&w, q0, omega, big_omega, s.t);
    for k in 0..4 {
        worst = worst.max((s.q[k] - exact[k]).abs());
    }
    let energy = (w.energy(&s).unwrap() - e0).abs() / e0;
    (slip, worst, energy)
}

#[test]
fn rolling_wheel_keeps_no_slip_and_follows_line_and_circle() {
    for (omega, label) in [(0.0, "straight"), (0.7, "circle")] {
        let (slip, worst, energy) = run_wheel(omega);
        let t_end = LONG_RUN as f64 * 1e-3;
        println!(
            "rolling wheel ({label}), {LONG_RUN} RK4 steps h = 1e-3: no-slip residual {slip:.2e}, \
             |q − closed form| {worst:.2e} at t = {t_end}, relative energy change {energy:.2e}"
        );
        // Velocities are projected onto A v = 0 after every step: residual at round-off of the
        // velocities (|v| ~ 5).
        assert!(slip < 1e-13, "slip {slip}");
        // θ̇, φ̇ are constant along the exact motion, so RK4 integrates φ and θ exactly and the
        // centre to O(h⁴ ω⁴) per unit time (≪ 1e-10 over 100 s); what remains is the round-off of
        // 1e5 additions to θ, which reaches 500 rad: ≲ 1e5·ε·|θ| ≈ 1e-8, measured ~1e-9.
        assert!(worst < 1e-11 * 500.0, "{label}: {worst}");
        assert!(energy < 1e-12, "{label}: energy {energy}");
    }
}

// ---------------------------------------------------------------------------------------------
// Scene 3: four-bar linkage under gravity. Crank (length l1) pivoted at O = (0, 0), rocker (l3)
// pivoted at D = (d, 0), coupler (l2) joining their tips; q = (θ1, θ2, θ3), absolute angles of the
// three bars; each bar a uniform rod (I = ml²/12 about its centre). Closing the loop: two holonomic
// constraints, written on the bars' Cartesian coordinates (the coupler's far end equals the
// rocker's tip).

#[derive(Clone, Copy)]
struct FourBar {
    l: [f64; 3],
    m: [f64; 3],
    d: f64,
    g: f64,
}

impl Model<3, 9> for FourBar {
    type Coords = [f64; 3];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("d", self.d), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 9] {
        let i = |k: usize| self.m[k] * self.l[k] * self.l[k] / 12.0;
        [
            self.m[0],
            self.m[0],
            i(0),
            self.m[1],
            self.m[1],
            i(1),
            self.m[2],
            self.m[2],
            i(2),
        ]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 3]) -> [D; 9] {
        let e = |a: D| vec2(a.cos(), a.sin());
        let tip_a = e(q[0]) * D::from(self.l[0]);
        let c1 = e(q[0]) * D::from(0.5 * self.l[0]);
        let c2 = tip_a + e(q[1]) * D::from(0.5 * self.l[1]);
        let c3 = vec2(D::from(self.d), D::zero()) + e(q[2]) * D::from(0.5 * self.l[2]);
        [c1.x, c1.y, q[0], c2.x, c2.y, q[1], c3.x, c3.y, q[2]]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 9]) -> D {
        (x[1] * self.m[0] + x[4] * self.m[1] + x[7] * self.m[2]) * self.g
    }
}

impl Constraints<3, 9, 2> for FourBar {
    const NAMES: [&'static str; 2] = ["joint_b_x", "joint_b_y"];
    const KINDS: [ConstraintKind; 2] = [ConstraintKind::Holonomic, ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 9]) -> [D; 2] {
        // End B of the coupler (centre + half length along its angle) = tip of the rocker.
        let coupler_end =
            vec2(x[3], x[4]) + vec2(x[5].cos(), x[5].sin()) * D::from(0.5 * self.l[1]);
        let rocker_tip = vec2(x[6], x[7]) + vec2(x[8].cos(), x[8].sin()) * D::from(0.5 * self.l[2]);
        [coupler_end.x - rocker_tip.x, coupler_end.y - rocker_tip.y]
    }
}
impl_mechanism!(FourBar, 3, 9, constraints);

#[test]
fn four_bar_starts_at_the_held_crank_angle_and_rate() {
    let p = FourBar {
        l: [1.0, 3.0, 2.0],
        m: [1.0, 2.0, 1.5],
        d: 3.0,
        g: 9.81,
    };
    let (theta1, rate1) = (0.3, 2.0);
    let guess = State::new(0.0, [theta1, 0.2, 1.6], [rate1, 0.0, 0.0]);
    // Without holding, the least-norm projection moves the crank too.
    let moved = consistent_state(&p, &guess).unwrap();
    assert!((moved.q[0] - theta1).abs() > 1e-3, "{:?}", moved.q);
    assert!((moved.v[0] - rate1).abs() > 1e-3, "{:?}", moved.v);

    let s = consistent_state_holding(&p, &guess, &["q0"], &["q0"]).unwrap();
    assert_eq!(s.q[0], theta1, "the held angle is kept bit for bit");
    assert_eq!(s.v[0], rate1, "the held rate is kept bit for bit");
    // Closed form: B is where the circles |B − A| = l2 about the crank tip A and |B − D| = l3 about
    // the rocker pivot D meet, on the side of the guess (above the line AD).
    let [l1, l2, l3] = p.l;
    let a = vec2(theta1.cos(), theta1.sin()) * l1;
    let dd = vec2(p.d, 0.0);
    let ad = dd - a;
    let r = ad.norm();
    let along = (l2 * l2 - l3 * l3 + r * r) / (2.0 * r);
    let across = (l2 * l2 - along * along).sqrt();
    let b = a + ad * (along / r) + vec2(-ad.y, ad.x) * (across / r);
    let theta2 = (b.y - a.y).atan2(b.x - a.x);
    let theta3 = (b.y - dd.y).atan2(b.x - dd.x);
    assert!((s.q[1] - theta2).abs() < 1e-13, "{} vs {theta2}", s.q[1]);
    assert!((s.q[2] - theta3).abs() < 1e-13, "{} vs {theta3}", s.q[2]);
    // Velocities: l1 θ̇1 e⊥(θ1) + l2 θ̇2 e⊥(θ2) = l3 θ̇3 e⊥(θ3), dotted with e(θ3) and e(θ2).
    let rate2 = -rate1 * l1 * (theta3 - theta1).sin() / (l2 * (theta3 - theta2).sin());
    let rate3 = rate1 * l1 * (theta2 - theta1).sin() / (l3 * (theta2 - theta3).sin());
    assert!((s.v[1] - rate2).abs() < 1e-12, "{} vs {rate2}", s.v[1]);
    assert!((s.v[2] - rate3).abs() < 1e-12, "{} vs {rate3}", s.v[2]);
    // And it is a state the integrators accept.
    let mut next = s;
    p.step::<Rk4>(&mut next, 1e-3).unwrap();

    // Positions and velocities are held independently.
    let only_angle = consistent_state_holding(&p, &guess, &["q0"], &[]).unwrap();
    assert_eq!(only_angle.q[0], theta1);
    assert!((only_angle.v[0] - rate1).abs() > 1e-3);

    // Typed errors: a name that is not a coordinate, and too few free coordinates for two rows.
    let err = consistent_state_holding(&p, &guess, &["crank"], &[]).unwrap_err();
    assert!(
        matches!(&err, Error::UnknownCoordinate { name, known } if name == "crank" && known.contains("`q2`")),
        "{err}"
    );
    let err = consistent_state_holding(&p, &guess, &["q0", "q1"], &[]).unwrap_err();
    assert!(
        matches!(
            &err,
            Error::TooFewFreeCoordinates {
                what: "coordinates",
                free: 1,
                rows: 2,
                max: 1,
                ..
            }
        ),
        "{err}"
    );
    let err = consistent_state_holding(&p, &guess, &[], &["q0", "q1", "q2"]).unwrap_err();
    assert!(
        matches!(
            &err,
            Error::TooFewFreeCoordinates {
                what: "velocities",
                free: 0,
                ..
            }
        ),
        "{err}"
    );
    assert!(consistent_state_holding(&p, &guess, &[], &["q2"]).is_ok());
}

#[test]
fn four_bar_linkage_keeps_energy_and_closure() {
    // Grashof crank–rocker (s + l = 1 + 3 ≤ p + q = 2 + 3): the crank turns fully, and the
    // transmission angle stays within [41°, 104°], far from the toggle (singular) positions.
    let p = FourBar {
        l: [1.0, 3.0, 2.0],
        m: [1.0, 2.0, 1.5],
        d: 3.0,
        g: 9.81,
    };
    // A rough guess; consistent_state closes the loop and removes the inconsistent velocities.
    let guess = State::new(0.0, [1.0, 0.2, 1.6], [3.0, 0.0, 0.0]);
    let s0 = consistent_state(&p, &guess).unwrap();
    let mut s = s0;
    let e0 = p.energy(&s).unwrap();
    let h = 1e-3;
    let (mut closure, mut closure_rate, mut energy) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..LONG_RUN {
        p.step::<Rk4>(&mut s, h).unwrap();
        let rows = constraints::constraint_rows(&p, s.t, &s.q, &s.v);
        for i in 0..2 {
            closure = closure.max(rows.value[i].abs());
            closure_rate = closure_rate.max(rows.rate[i].abs());
        }
        energy = energy.max((p.energy(&s).unwrap() - e0).abs());
    }
    println!(
        "four-bar, {LONG_RUN} RK4 steps h = 1e-3: loop closure |g| ≤ {closure:.2e}, |ġ| ≤ {closure_rate:.2e}, \
         energy drift {energy:.2e} (E = {e0:.3})"
    );
    assert!(
        closure <= 1e-10 && closure_rate <= 1e-10,
        "closure {closure} {closure_rate}"
    );
    // RK4 energy error per step ~ (hω)⁵·E with ω ≲ 6/s; the projection removes the kinetic energy of
    // the velocity drift, O(h⁵) per step too: ≲ 1e-7·|E| over 1e5 steps.
    assert!(energy < 1e-7 * e0.abs().max(1.0), "energy {energy}");
    // The joint force on the coupler and the rocker are equal and opposite (Newton's third law
    // through virtual work of a constraint written on both bodies).
    let f = constraint_forces(&p, &s).unwrap();
    for i in 0..2 {
        let on_coupler = f.cartesian[i][3 + i];
        let on_rocker = f.cartesian[i][6 + i];
        assert!((on_coupler + on_rocker).abs() < 1e-12 * on_coupler.abs().max(1.0));
    }
}

// ---------------------------------------------------------------------------------------------
// Scene 1: a particle on the outside of a frictionless sphere (a great circle of it: the motion is
// planar), started at the top with speed v₀. Unilateral contact |r| − R ≥ 0.

#[derive(Clone, Copy)]
struct SphereParticle {
    m: f64,
    r: f64,
    g: f64,
}

impl Model<2, 2> for SphereParticle {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("r", self.r), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 1> for SphereParticle {
    const NAMES: [&'static str; 1] = ["surface"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - self.r]
    }
}
impl_mechanism!(SphereParticle, 2, 2, constraints);

/// ∫ₐᵇ f by composite 5-point Gauss–Legendre (Abramowitz & Stegun, Table 25.4), exact for
/// polynomials of degree 9 per panel: for an analytic integrand the error with 400 panels is far
/// below round-off.
fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const X: [f64; 5] = [
        0.0,
        -0.538_469_310_105_683_1,
        0.538_469_310_105_683_1,
        -0.906_179_845_938_664,
        0.906_179_845_938_664,
    ];
    const W: [f64; 5] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let width = (b - a) / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let mid = a + (p as f64 + 0.5) * width;
        for k in 0..5 {
            sum += W[k] * f(mid + 0.5 * width * X[k]);
        }
    }
    0.5 * width * sum
}

#[test]
fn particle_leaves_the_sphere_where_the_normal_force_vanishes() {
    let p = SphereParticle {
        m: 0.7,
        r: 1.5,
        g: 9.81,
    };
    let v0 = 1.2f64;
    // Energy: v² = v₀² + 2gR(1 − cos θ); radial Newton: m v²/R = m g cos θ − N, so
    // N = m g (3 cos θ − 2) − m v₀²/R, zero at cos θ* = (2 + v₀²/(gR))/3.
    let cos_star = (2.0 + v0 * v0 / (p.g * p.r)) / 3.0;
    let theta_star = cos_star.acos();
    let speed = |th: f64| (v0 * v0 + 2.0 * p.g * p.r * (1.0 - th.cos())).sqrt();
    // Release time: t* = ∫₀^θ* R dθ / v(θ) (θ̇ = v/R), a smooth integrand since v ≥ v₀ > 0.
    let t_star = gauss_legendre(|th| p.r / speed(th), 0.0, theta_star, 400);

    let s0 = State::new(0.0, [0.0, p.r], [v0, 0.0]);
    let h = 1e-3;
    let mut stepper = Stepper::new(&p, Rk4::with_step(h), &s0).unwrap();
    assert_eq!(stepper.contacts().mode().rows, [RowMode::Active]);
    let mut s = s0;
    let mut worst_normal = 0.0f64;
    while stepper.mode_changes().is_empty() {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
        if stepper.mode_changes().is_empty() {
            let f = constraint_forces(&p, &s).unwrap();
            let cos = s.q[1] / p.r;
            let normal = p.m * p.g * (3.0 * cos - 2.0) - p.m * v0 * v0 / p.r;
            worst_normal = worst_normal.max((f.multipliers[0] - normal).abs());
        }
    }
    let release = stepper.mode_changes()[0];
    assert_eq!(
        (release.from, release.to),
        (RowMode::Active, RowMode::Inactive)
    );
    let release_error = (release.t - t_star).abs() / t_star;
    println!(
        "sphere: release at t = {:.15} vs {t_star:.15} by quadrature (rel. error {release_error:.1e}); \
         normal force vs closed form ≤ {worst_normal:.1e}",
        release.t
    );
    // Located to 1e-13 relative; the RK4 error of the contact phase (0.5 s, h = 1e-3) dominates.
    assert!(release_error < 1e-9, "release time error {release_error}");
    // N from the KKT solve at the RK4 state vs the closed form at the same θ: the closed form uses
    // the exact energy integral, so they differ by the RK4 energy error (≪ 1e-9·mg).
    assert!(
        worst_normal < 1e-9 * p.m * p.g,
        "normal force {worst_normal}"
    );

    // After release: free fall from the release state, a parabola (which RK4 integrates exactly,
    // so only the release-state error remains), staying outside the sphere.
    let r_star = [p.r * theta_star.sin(), p.r * cos_star];
    let v_star = [
        speed(theta_star) * cos_star,
        -speed(theta_star) * theta_star.sin(),
    ];
    let mut worst_parabola = 0.0f64;
    while s.t < t_star + 0.4 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
        let tau = s.t - t_star;
        let x = r_star[0] + v_star[0] * tau;
        let y = r_star[1] + v_star[1] * tau - 0.5 * p.g * tau * tau;
        worst_parabola = worst_parabola
            .max((s.q[0] - x).abs())
            .max((s.q[1] - y).abs());
        assert!(s.q[0].hypot(s.q[1]) > p.r);
    }
    println!("sphere: parabola after release within {worst_parabola:.1e}");
    assert!(worst_parabola < 1e-8, "parabola {worst_parabola}");
    assert_eq!(
        stepper.mode_changes().len(),
        1,
        "one mode change: {:?}",
        stepper.mode_changes()
    );
}

// ---------------------------------------------------------------------------------------------
// Scene 5: a block (point mass) on a rough fixed ramp through the origin at angle α. Contact
// c = n·r ≥ 0 with n = (−sin α, cos α); friction on it with slip s = t̂·ṙ, t̂ = (cos α, sin α)
// (positive up the ramp).

#[derive(Clone, Copy)]
struct RoughRamp {
    m: f64,
    alpha: f64,
    g: f64,
    friction: Coulomb,
}

impl Model<2, 2> for RoughRamp {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("alpha", self.alpha), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 2> for RoughRamp {
    const NAMES: [&'static str; 2] = ["ramp", "ramp_friction"];
    const KINDS: [ConstraintKind; 2] = [
        ConstraintKind::Unilateral,
        ConstraintKind::Friction { normal: 0 },
    ];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 2] {
        let (s, c) = self.alpha.sin_cos();
        [x[1] * c - x[0] * s, D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        _v: &[D; 2],
        _x: &[D; 2],
        xd: &[D; 2],
    ) -> [D; 2] {
        let (s, c) = self.alpha.sin_cos();
        [D::zero(), xd[0] * c + xd[1] * s]
    }
    fn friction_coefficients(&self, _row: usize) -> Coulomb {
        self.friction
    }
}
impl_mechanism!(RoughRamp, 2, 2, constraints);

/// Distance up the ramp and its rate.
fn along(p: &RoughRamp, s: &State<[f64; 2]>) -> (f64, f64) {
    let (sn, cs) = p.alpha.sin_cos();
    (s.q[0] * cs + s.q[1] * sn, s.v[0] * cs + s.v[1] * sn)
}

#[test]
fn block_on_rough_ramp_slides_sticks_or_slides_back_without_chattering() {
    let g = 9.81;
    let alpha = 0.5f64; // tan α = 0.546
    let h = 1e-3;
    // Sliding down from rest (tan α > μₛ): a = g(sin α − μₖ cos α) down the ramp.
    let p = RoughRamp {
        m: 2.0,
        alpha,
        g,
        friction: Coulomb {
            kinetic: 0.3,
            stiction: 0.4,
        },
    };
    let mut s = State::at_rest([0.0, 0.0]);
    let mut stepper = Stepper::new(&p, Rk4::with_step(h), &s).unwrap();
    assert_eq!(
        stepper.contacts().mode().rows,
        [RowMode::Active, RowMode::SlipNegative]
    );
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
    }
    let a = g * (alpha.sin() - 0.3 * alpha.cos());
    let (d, rate) = along(&p, &s);
    assert!(
        (d + 0.5 * a * s.t * s.t).abs() < 1e-12 && (rate + a * s.t).abs() < 1e-12,
        "{d} {rate}"
    );
    let f = constraint_forces(&p, &s).unwrap();
    let normal = p.m * g * alpha.cos();
    assert!((f.multipliers[0] - normal).abs() < 1e-12 * normal);
    assert!(
        (f.multipliers[1] - 0.3 * normal).abs() < 1e-12 * normal,
        "friction acts up the ramp"
    );
    assert!(stepper.mode_changes().is_empty());

    // At rest when tan α ≤ μₛ: no motion, no events.
    let p = RoughRamp {
        friction: Coulomb {
            kinetic: 0.5,
            stiction: 0.6,
        },
        ..p
    };
    let mut s = State::at_rest([0.0, 0.0]);
    let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s).unwrap();
    assert_eq!(
        stepper.contacts().mode().rows,
        [RowMode::Active, RowMode::Stick]
    );
    for _ in 0..2000 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
    }
    assert!(
        s.q[0].abs() < 1e-15 && s.q[1].abs() < 1e-15 && stepper.mode_changes().is_empty(),
        "{s:?}"
    );

    // Started sliding up with speed u: decelerates at g(sin α + μₖ cos α), stops at
    // t_s = u/(g(sin α + μₖ cos α)) after d_s = u²/(2g(sin α + μₖ cos α)); then sticks if
    // tan α ≤ μₛ, else slides back at g(sin α − μₖ cos α). Exactly one mode change either way.
    let u = 2.0;
    for (friction, sticks) in [
        (
            Coulomb {
                kinetic: 0.5,
                stiction: 0.6,
            },
            true,
        ),
        (
            Coulomb {
                kinetic: 0.2,
                stiction: 0.3,
            },
            false,
        ),
    ] {
        let p = RoughRamp { friction, ..p };
        let (sn, cs) = alpha.sin_cos();
        let mut s = State::new(0.0, [0.0, 0.0], [u * cs, u * sn]);
        let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s).unwrap();
        assert_eq!(
            stepper.contacts().mode().rows,
            [RowMode::Active, RowMode::SlipPositive]
        );
        let up = g * (sn + friction.kinetic * cs);
        let down = g * (sn - friction.kinetic * cs);
        let (t_stop, d_stop) = (u / up, u * u / (2.0 * up));
        let mut worst = 0.0f64;
        for _ in 0..3000 {
            stepper.step(f64::INFINITY).unwrap();
            s = stepper.state();
            let (d, _) = along(&p, &s);
            let exact = if s.t <= t_stop {
                u * s.t - 0.5 * up * s.t * s.t
            } else if sticks {
                d_stop
            } else {
                d_stop - 0.5 * down * (s.t - t_stop).powi(2)
            };
            worst = worst.max((d - exact).abs());
        }
        let ev = stepper.mode_changes();
        println!(
            "ramp (μₛ = {}): {} mode change(s) in 3000 steps, stop at t = {:.15} (exact {t_stop:.15}), |d − exact| ≤ {worst:.1e}",
            friction.stiction,
            ev.len(),
            ev[0].t
        );
        assert_eq!(ev.len(), 1, "no chattering: {ev:?}");
        assert_eq!(
            ev[0].to,
            if sticks {
                RowMode::Stick
            } else {
                RowMode::SlipNegative
            }
        );
        assert!(
            (ev[0].t - t_stop).abs() < 1e-12 * t_stop,
            "stop time {} vs {t_stop}",
            ev[0].t
        );
        // Piecewise quadratic motion: RK4 is exact on each piece, the event is located to 1e-13.
        assert!(worst < 1e-11, "{worst}");
    }
}

// ---------------------------------------------------------------------------------------------
// Scene 6: the lecture's wedge and block (Cross, Ph106 Lecture 4, eqs. (27)–(32)), now with friction
// between them; the wedge slides freely on a frictionless floor. q = (X, bx, by): wedge position
// and block position; the face passes through (X, h) sloping down at angle α. Contact
// c = n·(r_b − (X, h)) ≥ 0 with n = (sin α, cos α); slip s = t̂·(ṙ_b − (Ẋ, 0)) with
// t̂ = (cos α, −sin α) (positive when the block slides down the face).

#[derive(Clone, Copy)]
struct WedgeBlock {
    wedge: f64,
    block: f64,
    alpha: f64,
    h: f64,
    g: f64,
    friction: Coulomb,
}

impl Model<3, 4> for WedgeBlock {
    type Coords = [f64; 3];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("wedge", self.wedge),
            ("block", self.block),
            ("alpha", self.alpha),
            ("h", self.h),
            ("g", self.g),
        ])
    }
    fn masses(&self) -> [f64; 4] {
        [self.wedge, self.wedge, self.block, self.block]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 3]) -> [D; 4] {
        [q[0], D::zero(), q[1], q[2]]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 4]) -> D {
        x[3] * (self.block * self.g)
    }
}

impl Constraints<3, 4, 2> for WedgeBlock {
    const NAMES: [&'static str; 2] = ["face", "face_friction"];
    const KINDS: [ConstraintKind; 2] = [
        ConstraintKind::Unilateral,
        ConstraintKind::Friction { normal: 0 },
    ];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 4]) -> [D; 2] {
        let (s, c) = self.alpha.sin_cos();
        [(x[2] - x[0]) * s + (x[3] - x[1] - self.h) * c, D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 3],
        _v: &[D; 3],
        _x: &[D; 4],
        xd: &[D; 4],
    ) -> [D; 2] {
        let (s, c) = self.alpha.sin_cos();
        [D::zero(), (xd[2] - xd[0]) * c - (xd[3] - xd[1]) * s]
    }
    fn friction_coefficients(&self, _row: usize) -> Coulomb {
        self.friction
    }
}
impl_mechanism!(WedgeBlock, 3, 4, constraints);

#[test]
fn wedge_and_block_with_friction_match_closed_form() {
    let p = WedgeBlock {
        wedge: 3.0,
        block: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
        friction: Coulomb {
            kinetic: 0.2,
            stiction: 0.3,
        },
    };
    let (m, big_m, mu, g) = (p.block, p.wedge, p.friction.kinetic, p.g);
    let (sn, cs) = p.alpha.sin_cos();
    // Closed form while the block slides down the face (derived here; at μ = 0 it reduces to the
    // textbook frictionless result A = −m g sin α cos α/(M + m sin²α)). With the wedge's
    // acceleration A (horizontal), the block's acceleration relative to the face a_r (down the
    // face), normal force N and friction μN up the face on the block (down on the wedge):
    //   block along n:  m A sin α = N − m g cos α
    //   block along t̂:  m (A cos α + a_r) = m g sin α − μ N
    //   wedge, x:        M A = −N (sin α − μ cos α)
    // ⇒ A = −m g cos α (sin α − μ cos α) / (M + m sin α (sin α − μ cos α)),
    //   N = m (g cos α + A sin α),  a_r = g (sin α − μ cos α) − A (cos α + μ sin α).
    let k = sn - mu * cs;
    let big_a = -m * g * cs * k / (big_m + m * sn * k);
    let normal = m * (g * cs + big_a * sn);
    let a_r = g * k - big_a * (cs + mu * sn);
    let d0 = 0.3;
    let s0 = State::new(0.0, [0.0, d0 * cs, p.h - d0 * sn], [0.0; 3]);
    let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s0).unwrap();
    assert_eq!(
        stepper.contacts().mode().rows,
        [RowMode::Active, RowMode::SlipPositive]
    );
    let mut s = s0;
    let mut worst = 0.0f64;
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
        let t = s.t;
        let x_wedge = 0.5 * big_a * t * t;
        let d = d0 + 0.5 * a_r * t * t;
        let exact = [x_wedge, x_wedge + d * cs, p.h - d * sn];
        for i in 0..3 {
            worst = worst.max((s.q[i] - exact[i]).abs());
        }
    }
    let f = constraint_forces(&p, &s).unwrap();
    println!(
        "wedge and block: A = {big_a:.6}, a_r = {a_r:.6}, N = {normal:.6}; |q − closed form| ≤ {worst:.1e}, \
         λ = {:?}",
        f.multipliers
    );
    // Constant accelerations: RK4 is exact up to round-off.
    assert!(worst < 1e-12, "{worst}");
    assert!((f.multipliers[0] - normal).abs() < 1e-12 * normal);
    assert!((f.multipliers[1] + mu * normal).abs() < 1e-12 * normal);
    // Newton's third law through the virtual work of the friction row: the tangential forces on
    // wedge and block along x are opposite.
    assert!((f.cartesian[1][0] + f.cartesian[1][2]).abs() < 1e-12);
    assert!(stepper.mode_changes().is_empty());
    // With μₛ ≥ tan α the block sticks and nothing moves (no horizontal external force).
    let p = WedgeBlock {
        friction: Coulomb {
            kinetic: 0.5,
            stiction: 0.6,
        },
        ..p
    };
    let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s0).unwrap();
    let mut s = s0;
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
    }
    assert!(
        (0..3).all(|i| (s.q[i] - s0.q[i]).abs() < 1e-14) && stepper.mode_changes().is_empty(),
        "{s:?}"
    );
}

// ---------------------------------------------------------------------------------------------
// Impacts: a particle dropped on a floor y ≥ 0, plastic (e = 0) and with restitution e = 0.5.

#[derive(Clone, Copy)]
struct Floor {
    m: f64,
    g: f64,
}

impl Model<2, 2> for Floor {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 1> for Floor {
    const NAMES: [&'static str; 1] = ["floor"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [x[1]]
    }
}
impl_mechanism!(Floor, 2, 2, constraints);

#[test]
fn contact_is_re_established_by_plastic_or_restitution_impact() {
    let p = Floor { m: 1.5, g: 9.81 };
    let (height, u) = (1.0, 0.7);
    let t_hit = (2.0 * height / p.g).sqrt();
    let v_hit = p.g * t_hit;
    let s0 = State::new(0.0, [0.0, height], [u, 0.0]);
    // Plastic: the vertical velocity is lost at t_hit, then the particle slides on the floor
    // (frictionless) with λ = m g.
    let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s0).unwrap();
    assert_eq!(stepper.contacts().mode().rows, [RowMode::Inactive]);
    let mut s = s0;
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
    }
    assert_eq!(
        stepper.mode_changes().len(),
        1,
        "{:?}",
        stepper.mode_changes()
    );
    let contact = stepper.mode_changes()[0];
    assert_eq!(
        (contact.from, contact.to),
        (RowMode::Inactive, RowMode::Active)
    );
    assert!(
        (contact.t - t_hit).abs() < 1e-12 * t_hit,
        "{} vs {t_hit}",
        contact.t
    );
    assert!(s.q[1].abs() < 1e-15 && s.v[1].abs() < 1e-15);
    assert!((s.q[0] - u * s.t).abs() < 1e-12);
    let f = constraint_forces(&p, &s).unwrap();
    assert!((f.multipliers[0] - p.m * p.g).abs() < 1e-12);

    // Restitution e: rebounds with e·v, flight times 2 e^k v/g; the contact closes each time.
    let e = 0.5;
    let options = ContactOptions {
        restitution: e,
        ..ContactOptions::default()
    };
    let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s0)
        .and_then(|solver| solver.with_contact_options(options))
        .unwrap();
    let mut s = s0;
    let mut expected = vec![t_hit];
    let mut speed = v_hit;
    for _ in 0..3 {
        speed *= e;
        expected.push(expected.last().unwrap() + 2.0 * speed / p.g);
    }
    while s.t < expected[3] + 0.01 {
        stepper.step(f64::INFINITY).unwrap();
        s = stepper.state();
        assert!(s.q[1] > -1e-12, "no penetration: {s:?}");
    }
    assert!(stepper.mode_changes().len() >= 4);
    for k in 0..4 {
        let got = stepper.mode_changes()[k].t;
        // Each impact is located to 1e-13; the flight between them is a parabola RK4 integrates
        // exactly, so the times agree to round-off.
        assert!(
            (got - expected[k]).abs() < 1e-11,
            "impact {k}: {got} vs {}",
            expected[k]
        );
    }
}

// ---------------------------------------------------------------------------------------------
// A rheonomic guide: a particle on a horizontal rail that oscillates vertically,
// y = A sin ωt. The rail's force is λ = m (g − A ω² sin ωt) (Newton in y).

#[derive(Clone, Copy)]
struct ShakenRail {
    m: f64,
    g: f64,
    amplitude: f64,
    omega: f64,
}

impl Model<2, 2> for ShakenRail {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 1> for ShakenRail {
    const NAMES: [&'static str; 1] = ["rail"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [x[1] - (t * self.omega).sin() * self.amplitude]
    }
}
impl_mechanism!(ShakenRail, 2, 2, constraints);

#[test]
fn rheonomic_guide_gives_time_dependent_force() {
    let p = ShakenRail {
        m: 0.5,
        g: 9.81,
        amplitude: 0.2,
        omega: 3.0,
    };
    let mut s = State::new(0.0, [0.0, 0.0], [1.0, p.amplitude * p.omega]);
    for _ in 0..5000 {
        p.step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    let t = s.t;
    assert!((s.q[1] - p.amplitude * (p.omega * t).sin()).abs() < 1e-14);
    assert!((s.v[1] - p.amplitude * p.omega * (p.omega * t).cos()).abs() < 1e-13);
    assert!((s.q[0] - t).abs() < 1e-12);
    let f = constraint_forces(&p, &s).unwrap();
    let want = p.m * (p.g - p.amplitude * p.omega * p.omega * (p.omega * t).sin());
    assert!(
        (f.multipliers[0] - want).abs() < 1e-12,
        "{} vs {want}",
        f.multipliers[0]
    );
}

#[test]
fn constrained_accelerations_differentiate_through_dual_numbers() {
    // Implicit integrators differentiate q̈(q, v) with dual numbers: compare with central differences.
    use num_dual::Dual64;
    let p = FourBar {
        l: [1.0, 3.0, 2.0],
        m: [1.0, 2.0, 1.5],
        d: 3.0,
        g: 9.81,
    };
    let s = consistent_state(&p, &State::new(0.0, [1.0, 0.2, 1.6], [3.0, 0.0, 0.0])).unwrap();
    for k in 0..3 {
        let qd: [Dual64; 3] = std::array::from_fn(|j| Dual64::from_re(s.q[j]));
        let mut qd = qd;
        qd[k] = qd[k].derivative();
        let vd: [Dual64; 3] = std::array::from_fn(|j| Dual64::from_re(s.v[j]));
        let a = constraints::accelerations(&p, Dual64::from_re(0.0), &qd, &vd).unwrap();
        let eps = 1e-6;
        let (mut qp, mut qm) = (s.q, s.q);
        qp[k] += eps;
        qm[k] -= eps;
        let ap = constraints::accelerations(&p, 0.0, &qp, &s.v).unwrap();
        let am = constraints::accelerations(&p, 0.0, &qm, &s.v).unwrap();
        for i in 0..3 {
            let fd = (ap[i] - am[i]) / (2.0 * eps);
            // Central differences: truncation O(eps²)·|q⃛| plus round-off ε|q̈|/eps ≈ 1e-9.
            assert!(
                (a[i].eps - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                "∂q̈{i}/∂q{k}: {} vs {fd}",
                a[i].eps
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Cost per step of each constraint kind relative to the same mechanism without it. Printed, never
// asserted: run with `cargo test --release -p lagrange-core --test constraints -- --ignored --nocapture`.

/// The same model with its constraints dropped.
struct Free<T>(T);

macro_rules! free_mechanism {
    ($inner:ty, $n:literal, $k:literal) => {
        delegate_model!(Free<$inner>, $inner, $n, $k);
        impl_mechanism!(Free<$inner>, $n, $k);
    };
}
free_mechanism!(CartesianPendulum, 2, 2);
free_mechanism!(RollingWheel, 4, 4);
free_mechanism!(FourBar, 3, 9);
free_mechanism!(SphereParticle, 2, 2);

/// The rough ramp with its friction row dropped (contact only).
struct SmoothRamp(RoughRamp);
delegate_model!(SmoothRamp, RoughRamp, 2, 2);
impl Constraints<2, 2, 1> for SmoothRamp {
    const NAMES: [&'static str; 1] = ["ramp"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    fn position_constraints<D: Scalar>(&self, t: D, q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [self.0.position_constraints(t, q, x)[0]]
    }
}
impl_mechanism!(SmoothRamp, 2, 2, constraints);

/// Nanoseconds per step of two runs, measured alternately (so both see the same machine load):
/// minimum over 25 repeats of `steps` steps each, after a warm-up.
fn time_pair(steps: usize, mut a: impl FnMut(usize), mut b: impl FnMut(usize)) -> (f64, f64) {
    a(steps);
    b(steps);
    let mut best = (f64::INFINITY, f64::INFINITY);
    for _ in 0..25 {
        let start = std::time::Instant::now();
        a(steps);
        best.0 = best.0.min(start.elapsed().as_nanos() as f64 / steps as f64);
        let start = std::time::Instant::now();
        b(steps);
        best.1 = best.1.min(start.elapsed().as_nanos() as f64 / steps as f64);
    }
    best
}

fn rk4_run<M: Mechanism<N, Coords = [f64; N]>, const N: usize>(
    m: &M,
    s0: State<[f64; N]>,
) -> impl FnMut(usize) + '_ {
    move |n| {
        let mut s = s0;
        for _ in 0..n {
            m.step::<Rk4>(&mut s, 1e-4).unwrap();
        }
        std::hint::black_box(s);
    }
}

fn contact_run<
    M: Constraints<N, K, C, Coords = [f64; N]>
        + lagrange_core::evaluation::Dynamics<N, Coords = [f64; N]>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    m: &M,
    s0: State<[f64; N]>,
) -> impl FnMut(usize) + '_ {
    move |n| {
        let mut s = s0;
        let mut stepper = Stepper::new(m, Rk4::with_step(1e-5), &s).unwrap();
        for _ in 0..n {
            stepper.step(f64::INFINITY).unwrap();
            s = stepper.state();
        }
        std::hint::black_box(s);
    }
}

#[test]
#[ignore = "timing report, run in release with --ignored --nocapture"]
fn cost_per_step_of_each_constraint_kind() {
    const STEPS: usize = 4000;
    let report = |label: &str, (with, without): (f64, f64), base: &str| {
        println!(
            "{label}: {with:.0} ns/step vs {without:.0} {base}: ×{:.1}",
            with / without
        );
    };
    let pendulum = CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let s = State::new(0.0, [0.6, -0.8], [0.8, 0.6]);
    let free = Free(pendulum);
    report(
        "holonomic (Cartesian pendulum, 1 row, RK4 + projection)",
        time_pair(STEPS, rk4_run(&pendulum, s), rk4_run(&free, s)),
        "free",
    );

    let four_bar = FourBar {
        l: [1.0, 3.0, 2.0],
        m: [1.0, 2.0, 1.5],
        d: 3.0,
        g: 9.81,
    };
    let s = consistent_state(
        &four_bar,
        &State::new(0.0, [1.0, 0.2, 1.6], [3.0, 0.0, 0.0]),
    )
    .unwrap();
    let free = Free(four_bar);
    report(
        "holonomic (four-bar, 2 rows, RK4 + projection)",
        time_pair(STEPS, rk4_run(&four_bar, s), rk4_run(&free, s)),
        "free",
    );

    let wheel = RollingWheel { m: 2.0, r: 0.3 };
    let s = State::new(
        0.0,
        [0.0, 0.0, 0.4, 0.0],
        [0.3 * 5.0 * 0.4f64.cos(), 0.3 * 5.0 * 0.4f64.sin(), 0.7, 5.0],
    );
    let free = Free(wheel);
    report(
        "velocity (rolling wheel, 2 rows, RK4 + projection)",
        time_pair(STEPS, rk4_run(&wheel, s), rk4_run(&free, s)),
        "free",
    );

    let sphere = SphereParticle {
        m: 1.0,
        r: 1.0,
        g: 9.81,
    };
    let s = State::new(0.0, [0.0, 1.0], [0.5, 0.0]);
    let free = Free(sphere);
    report(
        "unilateral in contact (sphere, ContactRk4)",
        time_pair(STEPS, contact_run(&sphere, s), rk4_run(&free, s)),
        "free RK4",
    );
    let high = State::new(0.0, [0.0, 2.0], [0.5, 0.0]);
    report(
        "unilateral separated (sphere, ContactRk4)",
        time_pair(STEPS, contact_run(&sphere, high), rk4_run(&free, high)),
        "free RK4",
    );

    let ramp = RoughRamp {
        m: 1.0,
        alpha: 0.5,
        g: 9.81,
        friction: Coulomb {
            kinetic: 0.3,
            stiction: 0.4,
        },
    };
    let s = State::at_rest([0.0, 0.0]);
    let smooth = SmoothRamp(ramp);
    report(
        "friction sliding (ramp, ContactRk4)",
        time_pair(STEPS, contact_run(&ramp, s), contact_run(&smooth, s)),
        "contact only",
    );
    let sticky = RoughRamp {
        friction: Coulomb {
            kinetic: 0.5,
            stiction: 0.6,
        },
        ..ramp
    };
    report(
        "friction sticking (ramp, ContactRk4)",
        time_pair(STEPS, contact_run(&sticky, s), contact_run(&smooth, s)),
        "contact only (sliding)",
    );
}

// ---------------------------------------------------------------------------------------------
// Stick breaking: a bead on a rough horizontal wire (a bilateral contact y = 0), pulled along it by
// a force k t that grows with time and lifted by a constant force. It sticks until
// k t_b = μₛ|N|, then slides with m ẍ = k t − μₖ|N|. With a lift of 2 m g the normal force
// N = m g − lift changes sign, and friction (∝ |N|) must not.

#[derive(Clone, Copy)]
struct PulledBead {
    m: f64,
    g: f64,
    k: f64,
    lift: f64,
    friction: Coulomb,
}

impl Model<2, 2> for PulledBead {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("m", self.m),
            ("g", self.g),
            ("k", self.k),
            ("lift", self.lift),
        ])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
    fn applied_forces<S: Scalar>(
        &self,
        t: S,
        _q: &[S; 2],
        _v: &[S; 2],
        _x: &[S; 2],
        _x_dot: &[S; 2],
        cartesian_force: &mut [S; 2],
        _generalized_force: &mut [S; 2],
    ) {
        cartesian_force[0] += t * self.k;
        cartesian_force[1] += S::from(self.lift);
    }
}

impl Constraints<2, 2, 2> for PulledBead {
    const NAMES: [&'static str; 2] = ["wire", "wire_friction"];
    const KINDS: [ConstraintKind; 2] = [
        ConstraintKind::Holonomic,
        ConstraintKind::Friction { normal: 0 },
    ];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 2] {
        [x[1], D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        _v: &[D; 2],
        _x: &[D; 2],
        xd: &[D; 2],
    ) -> [D; 2] {
        [D::zero(), xd[0]]
    }
    fn friction_coefficients(&self, _row: usize) -> Coulomb {
        self.friction
    }
}
impl_mechanism!(PulledBead, 2, 2, constraints);

#[test]
fn stick_breaks_when_static_friction_is_exceeded_whatever_the_normal_force_sign() {
    for lift_factor in [0.0, 2.0] {
        let (m, g, k) = (1.5, 9.81, 4.0);
        let friction = Coulomb {
            kinetic: 0.25,
            stiction: 0.4,
        };
        let p = PulledBead {
            m,
            g,
            k,
            lift: lift_factor * m * g,
            friction,
        };
        let normal = (m * g - p.lift).abs();
        let t_b = friction.stiction * normal / k;
        let mut s = State::at_rest([0.0, 0.0]);
        let mut stepper = Stepper::new(&p, Rk4::with_step(1e-3), &s).unwrap();
        assert_eq!(
            stepper.contacts().mode().rows,
            [RowMode::Active, RowMode::Stick]
        );
        let mut worst = 0.0f64;
        for _ in 0..3000 {
            stepper.step(f64::INFINITY).unwrap();
            s = stepper.state();
            let t = s.t;
            // After the break: v = (k/2m)(t² − t_b²) − μₖ|N|(t − t_b)/m, x its integral.
            let exact = if t <= t_b {
                0.0
            } else {
                let dt = t - t_b;
                k / (6.0 * m) * (t.powi(3) - t_b.powi(3))
                    - k / (2.0 * m) * t_b * t_b * dt
                    - 0.5 * friction.kinetic * normal / m * dt * dt
            };
            worst = worst.max((s.q[0] - exact).abs());
            assert!(s.q[1].abs() < 1e-15);
        }
        let ev = stepper.mode_changes();
        println!(
            "pulled bead (lift {lift_factor} mg): {} mode change(s), stick breaks at t = {:.15} (exact {t_b:.15}), \
             |x − exact| ≤ {worst:.1e}",
            ev.len(),
            ev[0].t
        );
        assert_eq!(ev.len(), 1, "{ev:?}");
        assert_eq!(
            (ev[0].from, ev[0].to),
            (RowMode::Stick, RowMode::SlipPositive)
        );
        assert!((ev[0].t - t_b).abs() < 1e-12 * t_b);
        // Piecewise polynomial motion (x cubic in t) that RK4 integrates exactly: round-off only.
        assert!(worst < 1e-11, "{worst}");
        let f = constraint_forces(&p, &s).unwrap();
        assert!((f.multipliers[0] - (m * g - p.lift)).abs() < 1e-12 * m * g);
        assert!((f.multipliers[1] + friction.kinetic * normal).abs() < 1e-12 * m * g);
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input to the constrained entry points: typed errors, the caller's state left alone.

impl_mechanism!(NotLinear, 2, 2, constraints);

#[test]
fn nonlinear_velocity_constraint_is_refused_by_every_entry_point() {
    let p = NotLinear(CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 0.0,
    });
    // On the constraint (|v| = 1) and off it: the row is refused either way, as a declaration
    // error, before any question of consistency.
    for v in [[1.0, 0.0], [0.3, 0.2]] {
        let state = State::new(0.0, [0.0, 0.0], v);
        let is_nonlinear = |r: lagrange_core::Result<()>| {
            matches!(
                r,
                Err(Error::NonlinearVelocityConstraint {
                    constraint: "speed_limit",
                    ..
                })
            )
        };
        assert!(is_nonlinear(p.accelerations(&state).map(|_| ())), "{v:?}");
        assert!(is_nonlinear(constraint_forces(&p, &state).map(|_| ())));
        assert!(is_nonlinear(consistent_state(&p, &state).map(|_| ())));
        let mut s = state;
        assert!(is_nonlinear(p.step::<Rk4>(&mut s, 1e-3)));
        assert_eq!(s, state);
    }
}

#[test]
fn contact_stepper_refuses_a_state_that_violates_the_constraints() {
    // A bob at twice the rod length, as the plain steppers see it.
    let rod = CartesianPendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let stretched = State::new(0.0, [1.2, -1.6], [0.8, 0.6]);
    let mut s = stretched;
    assert!(matches!(
        rod.step::<Rk4>(&mut s, 1e-3),
        Err(Error::ConstraintViolation { .. })
    ));
    let err = Stepper::new(&rod, Rk4::with_step(1e-3), &stretched)
        .map(|_| ())
        .unwrap_err();
    assert!(
        matches!(err, Error::ConstraintViolation { ref residuals, .. } if residuals.contains("`rod`")),
        "{err}"
    );
    assert_eq!(s, stretched);
    // A particle half a radius inside the sphere.
    let sphere = SphereParticle {
        m: 1.0,
        r: 1.0,
        g: 9.81,
    };
    let inside = State::new(0.0, [0.0, 0.5], [0.5, 0.0]);
    let mut s = inside;
    let err = Stepper::new(&sphere, Rk4::with_step(1e-3), &inside)
        .map(|_| ())
        .unwrap_err();
    assert!(matches!(err, Error::ConstraintViolation { .. }), "{err}");
    let err = sphere.step::<GaussLegendre2>(&mut s, 1e-3).unwrap_err();
    assert!(matches!(err, Error::ConstraintViolation { .. }), "{err}");
    assert_eq!(s, inside);
}

#[test]
fn contact_options_are_validated() {
    let sphere = SphereParticle {
        m: 1.0,
        r: 1.0,
        g: 9.81,
    };
    let top = State::new(0.0, [0.0, 1.0], [0.5, 0.0]);
    let defaults = ContactOptions::default();
    let bad = [
        (
            "restitution",
            ContactOptions {
                restitution: f64::NAN,
                ..defaults
            },
        ),
        (
            "restitution",
            ContactOptions {
                restitution: -0.1,
                ..defaults
            },
        ),
        (
            "restitution",
            ContactOptions {
                restitution: 1.5,
                ..defaults
            },
        ),
        (
            "event_tolerance",
            ContactOptions {
                event_tolerance: f64::NAN,
                ..defaults
            },
        ),
        (
            "event_tolerance",
            ContactOptions {
                event_tolerance: 0.0,
                ..defaults
            },
        ),
        (
            "event_tolerance",
            ContactOptions {
                event_tolerance: -1.0,
                ..defaults
            },
        ),
        (
            "event_tolerance",
            ContactOptions {
                event_tolerance: f64::INFINITY,
                ..defaults
            },
        ),
        (
            "event_tolerance",
            ContactOptions {
                event_tolerance: 1.0,
                ..defaults
            },
        ),
        (
            "max_events_per_step",
            ContactOptions {
                max_events_per_step: 0,
                ..defaults
            },
        ),
    ];
    for (name, options) in bad {
        let is_invalid = |r: lagrange_core::Result<()>| matches!(r, Err(Error::InvalidSetting { setting, .. }) if setting == name);
        let solver = Stepper::new(&sphere, Rk4::with_step(1e-3), &top).unwrap();
        assert!(
            is_invalid(solver.with_contact_options(options).map(|_| ())),
            "{options:?}"
        );
    }
}

#[test]
fn contact_step_that_does_not_advance_time_is_refused() {
    let sphere = SphereParticle {
        m: 1.0,
        r: 1.0,
        g: 9.81,
    };
    let top = State::new(1.0, [0.0, 1.0], [0.5, 0.0]);
    // 5e-324 is the smallest subnormal: 1 + 5e-324 == 1.
    let err = Stepper::new(&sphere, Rk4::with_step(5e-324), &top)
        .map(|_| ())
        .unwrap_err();
    assert!(
        matches!(err, Error::StepDoesNotAdvance { t, h } if t == 1.0 && h == 5e-324),
        "{err}"
    );
    let mut s = top;
    let err = sphere.step::<Rk4>(&mut s, 5e-324).unwrap_err();
    assert!(
        matches!(err, Error::StepDoesNotAdvance { t, h } if t == 1.0 && h == 5e-324),
        "{err}"
    );
    assert_eq!(s, top);
}

/// A block on a bilateral horizontal wire whose friction row measures the slip as ẋ + ẏ, so the
/// friction force has a component along the normal row (r M⁻¹ Sᵀ ≠ 0). With μₖ = 2, sliding with
/// s > 0 under gravity, the normal force must satisfy λ (1 − 2 sₙ)/m = g with sₙ = sign(λ): for
/// sₙ = +1 that gives λ = −m g < 0, for sₙ = −1 λ = m g/3 > 0. Neither sign is consistent: the
/// contact forces are indeterminate (Painlevé's paradox in its simplest form).
struct SkewSlip(PulledBead);
delegate_model!(SkewSlip, PulledBead, 2, 2);
impl Constraints<2, 2, 2> for SkewSlip {
    const NAMES: [&'static str; 2] = ["wire", "skew_friction"];
    const KINDS: [ConstraintKind; 2] = [
        ConstraintKind::Holonomic,
        ConstraintKind::Friction { normal: 0 },
    ];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 2] {
        [x[1], D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        _v: &[D; 2],
        _x: &[D; 2],
        xd: &[D; 2],
    ) -> [D; 2] {
        [D::zero(), xd[0] + xd[1]]
    }
    fn friction_coefficients(&self, _row: usize) -> Coulomb {
        Coulomb {
            kinetic: 2.0,
            stiction: 2.0,
        }
    }
}
impl_mechanism!(SkewSlip, 2, 2, constraints);

#[test]
fn friction_sign_iteration_without_a_consistent_sign_is_an_error() {
    let p = SkewSlip(PulledBead {
        m: 1.5,
        g: 9.81,
        k: 0.0,
        lift: 0.0,
        friction: Coulomb::default(),
    });
    let err = constraints::accelerations(&p, 0.0, &[0.0, 0.0], &[1.0, 0.0]).unwrap_err();
    assert!(
        matches!(err, Error::FrictionIndeterminate { ref constraints, .. } if constraints.contains("`skew_friction`")),
        "{err}"
    );
}
