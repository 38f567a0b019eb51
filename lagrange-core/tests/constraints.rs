//! Constrained mechanisms written by hand (what `#[mechanism]` generates for `#[constraint]`,
//! `#[velocity_constraint]`, `#[unilateral]` and `#[friction]` items), checked against closed forms.
//! The scenes are issue 3's: particle leaving a sphere, rolling wheel, four-bar linkage, Cartesian
//! pendulum, block on a rough ramp, wedge and block with friction.
//!
//! Tolerances: classical RK4 has local error O(h⁵) and global error O(h⁴) (Hairer, Nørsett &
//! Wanner I, §II.3); with h = 1e-3 and the scenes' frequencies ω ≲ 4/s, (hω)⁴ ≈ 3e-10 per unit
//! time at most, so trajectories agree with closed forms to ~1e-9 over tens of seconds. Projection
//! after every step keeps constraint residuals at round-off, independently of h.

use lagrange_core::constraints::{
    self, consistent_state, constraint_forces, ConstraintKind, Constraints, ContactOptions,
    ContactRk4, Coulomb, RowMode, CONSISTENCY_TOLERANCE,
};
use lagrange_core::dynamics::{self, EquationsOfMotion};
use lagrange_core::{vec2, Error, Mechanism, Model, Rk4, Scalar, State};

/// The `Mechanism` glue a constrained declaration generates: as for an unconstrained one, plus the
/// three overrides that make every integrator enforce the constraints.
macro_rules! constrained_mechanism {
    ($ty:ty, $n:literal) => {
        impl Mechanism<$n> for $ty {
            type Coords = [f64; $n];
            fn validate(&self) -> lagrange_core::Result<()> {
                Model::validate(self)
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
            fn accelerations_at<S: Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> lagrange_core::Result<[S; $n]> {
                constraints::accelerations(self, t, q, v)
            }
            fn project(
                &self,
                t: f64,
                q: &mut [f64; $n],
                v: &mut [f64; $n],
            ) -> lagrange_core::Result<()> {
                let mode = constraints::infer_mode(self, t, q, v)?;
                constraints::project(self, t, q, v, &mode)
            }
            fn check_constraints(
                &self,
                t: f64,
                q: &[f64; $n],
                v: &[f64; $n],
            ) -> lagrange_core::Result<()> {
                constraints::check_consistent(self, t, q, v, CONSISTENCY_TOLERANCE)
            }
        }
    };
}

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
constrained_mechanism!(CartesianPendulum, 2);

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
    for step in 1..=100_000 {
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
        "cartesian pendulum, 1e5 RK4 steps h = 1e-3: |g| ≤ {worst_g:.2e}, |ġ| ≤ {worst_gdot:.2e}, energy drift {worst_energy:.2e}, \
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
    // A guess at the pivot has no gradient direction to project along: an error, not NaN.
    let bad = State::new(0.0, [0.0, 0.0], [0.0, 0.0]);
    assert!(consistent_state(&p, &bad).is_err());
}

// ---------------------------------------------------------------------------------------------
// Redundant constraints: the same rod twice.

struct DoubleRod(CartesianPendulum);
impl Model<2, 2> for DoubleRod {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Model::validate(&self.0)
    }
    fn masses(&self) -> [f64; 2] {
        self.0.masses()
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 2]) -> [D; 2] {
        self.0.cartesian(t, q)
    }
    fn potential<D: Scalar>(&self, t: D, q: &[D; 2], x: &[D; 2]) -> D {
        self.0.potential(t, q, x)
    }
}
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
