//! Free-flying bodies: orientations written in a chart of three coordinates that switches before
//! it turns singular (`rot_vector`, `rot_mrp`). The gallery's torque-free asymmetric body
//! (`lagrange_gallery::scenes::tumbling_body`, which runs it for 10⁴ s) against the closed form of
//! Euler's equations through many chart switches, shortened here to keep the debug run short; a
//! thrown body whose centre of mass falls freely; a quadruped from URDF with a floating base.

use lagrange::prelude::*;
use lagrange::Seed;
use lagrange_gallery::scenes::tumbling_body::{
    angular_velocity, closed_form, start, tumble, tumbling, Tumble, BODY, OMEGA0,
};

/// The same body, its orientation in modified Rodrigues parameters σ.
#[mechanism]
pub mod tumbling_mrp {
    pub struct Coords {
        pub s1: f64,
        pub s2: f64,
        pub s3: f64,
    }
    pub struct TumblingMrp {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }
    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(s1, s2, s3)))
    }
}

/// A body thrown in a uniform field: its centre of mass (x, y, z), its orientation (φ).
#[mechanism]
pub mod thrown {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
        pub phi: [f64; 3],
    }
    pub struct Thrown {
        pub m: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = [0.02, 0.05, 0.06])]
    fn body() -> Spatial {
        spatial(vec3(x, y, z), rot_vector(vec3(phi[0], phi[1], phi[2])))
    }
    #[gravity]
    fn field() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

const I: [f64; 3] = [BODY.i1, BODY.i2, BODY.i3];

/// The body-frame angular velocity Rᵀ ω from a pose and its velocity.
fn body_frame(rotation: Rot3<f64>, omega: Vec3<f64>) -> [f64; 3] {
    let w = rotation.transpose() * omega;
    [w.x, w.y, w.z]
}

fn tumbling_start() -> (tumbling::Tumbling, tumbling::State) {
    (BODY, start())
}

fn max_error(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
}

/// Through 40 s (about 13 switches of the chart, each after a rotation by π) RK4 follows Euler's
/// closed form with the error of a fourth-order method: halving the step divides it by 16 (12 to
/// 20 allowed: the h⁵ term still shifts the ratio at h = 0.01), sampled every second.
#[test]
fn torque_free_body_follows_eulers_closed_form() {
    let coarse = tumble::<Rk4>(0.01, 40.0).unwrap();
    let fine = tumble::<Rk4>(0.005, 40.0).unwrap();
    assert!(coarse.switches >= 10, "{} chart switches", coarse.switches);
    let ratio = coarse.omega_error / fine.omega_error;
    assert!((12.0..20.0).contains(&ratio), "ratio {ratio}");
    // |ω| ≈ 2 and the motion's period a few seconds: RK4's h⁴ error over 40 s stays below 1e-6.
    assert!(coarse.omega_error < 1e-5, "{:e}", coarse.omega_error);
    // Built from φ, the rotation is orthonormal to rounding whatever the steps did.
    assert!(coarse.orthonormality < 1e-14);
}

/// Modified Rodrigues parameters give the same motion as the rotation vector (both to RK4's
/// error: the two charts are different coordinates, so the numerical solutions differ by the
/// method's error, below 1e-6 at h = 0.01 over 20 s by the previous test).
#[test]
fn both_charts_give_the_same_motion() {
    let (sys, mut s) = tumbling_start();
    let mrp = tumbling_mrp::TumblingMrp {
        i1: I[0],
        i2: I[1],
        i3: I[2],
    };
    // At σ = 0 the rates σ̇ are a quarter of the body-frame angular velocity.
    let quarter = OMEGA0.map(|w| w / 4.0);
    let mut r = tumbling_mrp::State::new(
        0.0,
        tumbling_mrp::Coords {
            s1: 0.0,
            s2: 0.0,
            s3: 0.0,
        },
        tumbling_mrp::Coords {
            s1: quarter[0],
            s2: quarter[1],
            s3: quarter[2],
        },
    );
    for _ in 0..2000 {
        sys.step::<Rk4>(&mut s, 0.01).unwrap();
        mrp.step::<Rk4>(&mut r, 0.01).unwrap();
    }
    let a = sys.bodies(&s).body.rotation;
    let b = mrp.bodies(&r).body.rotation;
    for i in 0..3 {
        for j in 0..3 {
            assert!((a.rows[i][j] - b.rows[i][j]).abs() < 1e-5);
        }
    }
    let w = body_frame(b, mrp.body_velocities(&r).body.angular);
    assert!(max_error(w, angular_velocity(&s)) < 1e-5);
    assert!(max_error(w, closed_form(r.t)) < 1e-5);
}

/// A quadruped from a URDF file the repository writes, its root link flying free: 6 coordinates of
/// the base (position, modified Rodrigues parameters, whose velocities are the base's angular
/// velocity) and 12 joints; the rigid tree pass with a free root.
#[lagrange::urdf("tests/urdf/quadruped.urdf", floating)]
pub mod quadruped {}

/// The file's links' masses: trunk 6, IMU 0.1, and per leg 0.5 + 0.8 + 0.3 + 0.05.
const QUADRUPED_MASS: f64 = 12.7;

/// Deterministic states spread over the configuration space: the base anywhere, turned by up to a
/// rotation of π, the joints over ±1.5 rad, every velocity up to 2 (rad/s, m/s).
fn quadruped_states() -> Vec<quadruped::State> {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut uniform = move |a: f64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        a * (2.0 * (seed >> 11) as f64 / (1u64 << 53) as f64 - 1.0)
    };
    (0..6)
        .map(|_| {
            let mut q = [0.0; quadruped::DOF].map(|_| uniform(1.5));
            let v = [0.0; quadruped::DOF].map(|_| uniform(2.0));
            q[3..6].iter_mut().for_each(|p| *p *= 1.8);
            quadruped::State::new(0.0, Coordinates::from_array(q), Coordinates::from_array(v))
        })
        .collect()
}

/// The base's three translation coordinates move every body rigidly, so their momenta are the
/// total linear momentum P, and P's rate is the total external force, M g: the centre of mass
/// falls freely whatever the legs do. Checked at each state to rounding: Ṗ from the momenta on
/// dual numbers along (q̇, q̈), q̈ the generated accelerations. The tolerance is rounding: the
/// 18 × 18 solve's relative error, 10⁻¹⁶ times the condition number of M (below 10⁴ at these
/// states), on a force of M g.
#[test]
fn quadruped_centre_of_mass_falls_freely() {
    use lagrange::evaluation::Evaluate;
    use num_dual::Dual64;
    let sys = quadruped::Quadruped::default();
    for s in quadruped_states() {
        let a = sys.accelerations(&s).unwrap().to_array();
        let (q, v) = (s.q.to_array(), s.v.to_array());
        let along = |x: [f64; quadruped::DOF], dx: [f64; quadruped::DOF]| {
            std::array::from_fn(|i| Dual64::new(x[i], dx[i]))
        };
        // Along the motion: q moves by its rates q̇ = G(q) v (the base's velocities are its
        // angular velocity), v by v̇.
        let rates = sys.position_rates_at(&q, &v);
        let p = sys.momenta_at(Dual64::new(0.0, 1.0), &along(q, rates), &along(v, a));
        let weight = QUADRUPED_MASS * sys.g;
        let rate = [p[0].eps, p[1].eps, p[2].eps + weight];
        assert!(rate.iter().all(|r| r.abs() < 1e-12 * weight), "{rate:?}");
    }
    // At rest but for a translation of the base, P = M v: the total mass is the file's.
    let mut s = quadruped_states()[0];
    s.v = Coordinates::from_array([0.0; quadruped::DOF]);
    s.v.base_position = [0.3, -0.2, 0.5];
    let p = sys.momenta(&s).unwrap();
    for k in 0..3 {
        assert!((p.base_position[k] - QUADRUPED_MASS * s.v.base_position[k]).abs() < 1e-12);
    }
}

/// A body thrown spinning: its centre of mass is three of its coordinates, on which the uniform
/// field acts alone, so RK4 (exact for a quadratic in t) follows the parabola to rounding, while
/// the orientation switches chart every half turn.
#[test]
fn thrown_body_centre_of_mass_follows_the_parabola() {
    let sys = thrown::Thrown { m: 0.4, g: 9.81 };
    let mut s = thrown::State::new(
        0.0,
        thrown::Coords {
            x: 0.0,
            y: 0.0,
            z: 1.0,
            phi: [0.0; 3],
        },
        thrown::Coords {
            x: 2.0,
            y: -1.0,
            z: 6.0,
            phi: [0.5, 0.1, 12.0],
        },
    );
    let mut switches = 0;
    for _ in 0..200 {
        let before = s.q.phi;
        sys.step::<Rk4>(&mut s, 0.01).unwrap();
        switches += usize::from((0..3).map(|i| s.q.phi[i] * before[i]).sum::<f64>() < 0.0);
    }
    let t = s.t;
    assert!(switches >= 5, "{switches}");
    assert!((s.q.x - 2.0 * t).abs() < 1e-12 && (s.q.y + t).abs() < 1e-12);
    assert!((s.q.z - (1.0 + 6.0 * t - 9.81 * t * t / 2.0)).abs() < 1e-12);
    assert!((s.v.z - (6.0 - 9.81 * t)).abs() < 1e-12);
}

/// Dopri5 through the chart switches: after a switch the end of the step is in other coordinates,
/// so the method's last evaluation (its first stage of the next step) must be taken again there.
/// At rtol 1e-10 the error is governed by the tolerance: ω within 2e-8 of the closed form over
/// 30 s (a few hundred steps, each of local error about 1e-10); a stale first stage after a switch
/// costs more than ten times that.
#[test]
fn adaptive_steps_cross_the_switches() {
    let (sys, start) = tumbling_start();
    let mut run = Stepper::new(&sys, Dopri5::new(1e-10, 1e-12), &start).unwrap();
    let mut worst = 0.0f64;
    while run.state().t < 30.0 {
        run.step(30.0).unwrap();
        let s = run.state();
        worst = worst.max(max_error(angular_velocity(&s), closed_form(s.t)));
    }
    assert!(worst < 2e-8, "{worst:e}");
}

/// Sensitivities carried through the switches: ∂φ(T)/∂φ̇₀ from the tangent against central
/// differences of two runs (δ = 1e-6: truncation ~δ² |∂³φ| ≈ 1e-12, rounding ~1e-16/δ = 1e-10),
/// over 10 s and several switches.
#[test]
fn sensitivities_cross_the_switches() {
    let (sys, start) = tumbling_start();
    let t_end = 10.0;
    let mut run = Stepper::new(&sys, Rk4::with_step(0.01), &start)
        .unwrap()
        .with_sensitivities([Seed::Velocity("phi[0]")])
        .unwrap();
    run.integrate(t_end, &mut [], |_| {}).unwrap();
    let tangent = run.sensitivities().dq[0].phi;
    let end = |delta: f64| {
        let mut s = start;
        s.v.phi[0] += delta;
        while s.t < t_end - 1e-9 {
            sys.step::<Rk4>(&mut s, 0.01).unwrap();
        }
        s.q.phi
    };
    let (plus, minus) = (end(1e-6), end(-1e-6));
    for k in 0..3 {
        let difference = (plus[k] - minus[k]) / 2e-6;
        assert!((tangent[k] - difference).abs() < 1e-7 * (1.0 + difference.abs()));
    }
}

/// Gauss–Legendre (symplectic, order 4) through 20 s of switches: the energy and the world-frame
/// angular momentum L = R I ω stay at their initial values to the method's error — halving the
/// step divides the largest deviation by about 2⁴ (10 to 24 allowed). (Across the switches the
/// coordinates it is symplectic in change, so over 10⁴ s the deviations grow slowly with the run;
/// the gallery's scene measures them.)
#[test]
fn energy_and_angular_momentum_are_kept() {
    let coarse = tumble::<GaussLegendre2>(0.05, 20.0).unwrap();
    let fine = tumble::<GaussLegendre2>(0.025, 20.0).unwrap();
    let deviation = |t: &Tumble| t.energy_error.max(t.momentum_error);
    let ratio = deviation(&coarse) / deviation(&fine);
    assert!(deviation(&coarse) < 1e-5, "{:e}", deviation(&coarse));
    assert!((10.0..24.0).contains(&ratio), "ratio {ratio}");
}

/// The quadruped dropped tumbling, its legs swinging: along an RK4 run the total linear momentum
/// (the base translation's momenta) stays on P(0) − M g t, to RK4's error in the state — halving
/// the step divides the departure by about 16 (10 to 24 allowed) — while the base's chart
/// switches (it turns by several π).
#[test]
fn quadruped_dropped_falls_freely() {
    let sys = quadruped::Quadruped::default();
    let weight = QUADRUPED_MASS * sys.g;
    let mut start = quadruped_states()[1];
    start.q.base_rotation = [0.0; 3];
    // The base's angular velocity: about 24 rad/s about a tilted axis, a turn of π in 0.13 s.
    start.v.base_rotation = [6.4, -12.0, 19.2];
    let p0 = sys.momenta(&start).unwrap().base_position;
    let departure = |h: f64| {
        let mut s = start;
        let (mut worst, mut switches) = (0.0f64, 0);
        for _ in 0..(0.2 / h).round() as usize {
            let before = s.q.base_rotation;
            sys.step::<Rk4>(&mut s, h).unwrap();
            let after = s.q.base_rotation;
            switches += usize::from((0..3).map(|k| before[k] * after[k]).sum::<f64>() < 0.0);
            let p = sys.momenta(&s).unwrap().base_position;
            let exact = [p0[0], p0[1], p0[2] - weight * s.t];
            worst = worst.max((0..3).map(|k| (p[k] - exact[k]).abs()).fold(0.0, f64::max));
        }
        (worst, switches)
    };
    let ((coarse, switches), (fine, _)) = (departure(2e-3), departure(1e-3));
    assert!(switches >= 1, "{switches}");
    let ratio = coarse / fine;
    assert!(
        (10.0..24.0).contains(&ratio),
        "{coarse:e} → {fine:e}: {ratio}"
    );
    // RK4 at ω h ≈ 0.05 (the fastest rate, the base's spin): a relative error of order 1e-5 on
    // momenta of tens of N s.
    let scale = p0.iter().map(|p| p * p).sum::<f64>().sqrt() + weight * 0.2;
    assert!(coarse < 1e-4 * scale, "{coarse:e}");
}
