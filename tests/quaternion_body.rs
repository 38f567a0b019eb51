//! A free body's orientation in unit-quaternion coordinates: four coordinates e = (w, x, y, z)
//! held on the unit sphere by a holonomic constraint |e|² = 1, the integrators' projection keeping
//! the norm after every step. The alternative to a rotation chart of three coordinates that
//! switches (`tests/floating.rs`): the same torque-free asymmetric body as the gallery's
//! `tumbling_body`, against Euler's closed form.
//!
//! The rotation is written homogeneous of degree two in e (`common/quaternion_body.rs`): on the
//! sphere it is the rotation of the unit quaternion, and off it R = |e|² R̂, so a velocity along e
//! changes the body's size, costs kinetic energy, and the mass matrix stays regular on the whole
//! space of four coordinates (the Lagrange multiplier of the norm takes that direction out).

use lagrange::prelude::*;
use lagrange_gallery::scenes::tumbling_body::{closed_form, BODY, OMEGA0};

#[path = "common/quaternion_body.rs"]
mod declaration;
use declaration::quaternion_body;

use quaternion_body::{Coords, QuaternionBody, State};

const QUATERNION_BODY: QuaternionBody = QuaternionBody {
    i1: BODY.i1,
    i2: BODY.i2,
    i3: BODY.i3,
};

/// At e = (1, 0, 0, 0) the rates are ė = ½ e ⊗ (0, ω) = (0, ω/2).
fn start() -> State {
    let [a, b, c] = OMEGA0;
    State::new(
        0.0,
        Coords {
            e: [1.0, 0.0, 0.0, 0.0],
        },
        Coords {
            e: [0.0, 0.5 * a, 0.5 * b, 0.5 * c],
        },
    )
}

/// The body-frame angular velocity Rᵀ ω.
fn angular_velocity(s: &State) -> [f64; 3] {
    let r = QUATERNION_BODY.bodies(s).body.rotation;
    let w = r.transpose() * QUATERNION_BODY.body_velocities(s).body.angular;
    [w.x, w.y, w.z]
}

/// What a run measured: the largest departure of ω from the closed form (sampled every second),
/// of |e| from 1 (every step) and of the energy from its start (relative, every second).
struct Run {
    omega_error: f64,
    norm_error: f64,
    energy_error: f64,
}

fn run<I: Integrator>(h: f64, duration: f64) -> Run {
    let mut s = start();
    let e0 = QUATERNION_BODY.energy(&s).unwrap();
    let mut out = Run {
        omega_error: 0.0,
        norm_error: 0.0,
        energy_error: 0.0,
    };
    let per_second = (1.0 / h).round() as usize;
    for step in 1..=(duration / h).round() as usize {
        QUATERNION_BODY.step::<I>(&mut s, h).unwrap();
        let norm = s.q.e.iter().map(|x| x * x).sum::<f64>().sqrt();
        out.norm_error = out.norm_error.max((norm - 1.0).abs());
        if step % per_second == 0 {
            let (w, exact) = (angular_velocity(&s), closed_form(s.t));
            for k in 0..3 {
                out.omega_error = out.omega_error.max((w[k] - exact[k]).abs());
            }
            let e = QUATERNION_BODY.energy(&s).unwrap();
            out.energy_error = out.energy_error.max((e - e0).abs() / e0);
        }
    }
    out
}

/// Through 40 s RK4 follows Euler's closed form with the error of a fourth-order method: halving
/// the step divides it by 16 (12 to 20 allowed, as for the charts in `tests/floating.rs`: the h⁵
/// term still shifts the ratio at h = 0.01). The projection after each step puts |e| back on 1 to
/// its Newton tolerance.
#[test]
fn rk4_follows_eulers_closed_form_with_the_norm_kept() {
    let coarse = run::<Rk4>(0.01, 40.0);
    let fine = run::<Rk4>(0.005, 40.0);
    let ratio = coarse.omega_error / fine.omega_error;
    // RK4's local error, (h|ω|)⁵/5! ≈ 5·10⁻¹¹ per step at |ω| ≈ 2.2, over 4 000 steps: ≈ 2·10⁻⁷
    // of |ω|, times the growth of a phase error along the elliptic functions over a few periods.
    assert!(coarse.omega_error < 1e-5, "{:e}", coarse.omega_error);
    assert!((12.0..20.0).contains(&ratio), "ratio {ratio}");
    assert!(coarse.norm_error < 1e-12, "{:e}", coarse.norm_error);
    println!(
        "quaternion, RK4 40 s: ω error {:e} (h = 0.01), {:e} (h = 0.005); |e| − 1 {:e}; energy {:e}",
        coarse.omega_error, fine.omega_error, coarse.norm_error, coarse.energy_error
    );
}

/// The variational integrator (the discrete Lagrangian's RATTLE for a general mass matrix,
/// symplectic, order 2): ω follows the closed form with a second-order error (halving the step
/// divides it by about 4; 3 to 5 allowed), the energy stays within the method's O(h²) error,
/// (h |ω|)² = 5·10⁻⁴ at h = 0.01, with no drift, and the norm is kept by the method's own
/// constraint solve.
#[test]
fn the_variational_integrator_keeps_the_energy_and_the_norm() {
    let coarse = run::<Variational>(0.01, 20.0);
    let fine = run::<Variational>(0.005, 20.0);
    let ratio = coarse.omega_error / fine.omega_error;
    assert!((3.0..5.0).contains(&ratio), "ratio {ratio}");
    assert!(coarse.energy_error < 5e-4, "{:e}", coarse.energy_error);
    assert!(coarse.norm_error < 1e-12, "{:e}", coarse.norm_error);
}
