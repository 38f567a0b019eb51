//! A free asymmetric rigid body tumbling for 10⁴ s: its orientation the rotation vector φ
//! (`rot_vector`), which the integrators move to the equivalent rotation each time the body has
//! turned by more than π — thousands of times over the run — so no orientation is singular.
//!
//! Closed form (Landau & Lifshitz, *Mechanics*, 3rd ed., §37, eqs. 37.10): for principal moments
//! I₁ < I₂ < I₃ and an angular velocity with |L|² > 2 E I₂, the body-frame angular velocity is
//! ω₁ = A cn τ, ω₂ = B sn τ, ω₃ = C dn τ, τ = t √((I₃ − I₂)(L² − 2EI₁)/(I₁I₂I₃)), of parameter
//! k² = (I₂ − I₁)(2EI₃ − L²)/((I₃ − I₂)(L² − 2EI₁)), with A² = (2EI₃ − L²)/(I₁(I₃ − I₁)),
//! B² = (2EI₃ − L²)/(I₂(I₃ − I₂)), C² = (L² − 2EI₁)/(I₃(I₃ − I₁)); starting from ω(0) = (A, 0, C)
//! the signs follow Euler's equations at t = 0 (I₂ ω̇₂ = (I₃ − I₁) ω₃ ω₁ > 0). The energy E and
//! the angular momentum L = R I ω in the world frame are constant.

use crate::plot::{self, Series};
use crate::{jacobi_elliptic, Check};
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod tumbling {
    pub struct Coords {
        /// The rotation vector: the body is turned by |φ| about φ/|φ|.
        pub phi: [f64; 3],
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Tumbling {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(
            vec3(0.0, 0.0, 0.0),
            rot_vector(vec3(phi[0], phi[1], phi[2])),
        )
    }
}

use tumbling::{Coords, State, Tumbling};

const SCENE: &str = "torque-free tumbling body";

/// The body of the scene and the tests: moments (1, 2, 3).
pub const BODY: Tumbling = Tumbling {
    i1: 1.0,
    i2: 2.0,
    i3: 3.0,
};
/// The body-frame angular velocity at t = 0: about the first and third axes, |L|² > 2 E I₂.
pub const OMEGA0: [f64; 3] = [1.0, 0.0, 2.0];
/// How long the scene runs.
pub const DURATION: f64 = 1e4;

/// The start: at φ = 0 the rates φ̇ are the body-frame angular velocity.
pub fn start() -> State {
    State::new(0.0, Coords { phi: [0.0; 3] }, Coords { phi: OMEGA0 })
}

/// The closed form's body-frame angular velocity at `t` (see the module docs).
pub fn closed_form(t: f64) -> [f64; 3] {
    let Tumbling { i1, i2, i3 } = BODY;
    let [w1, _, w3] = OMEGA0;
    let two_e = i1 * w1 * w1 + i3 * w3 * w3;
    let l2 = (i1 * w1).powi(2) + (i3 * w3).powi(2);
    let a = ((two_e * i3 - l2) / (i1 * (i3 - i1))).sqrt();
    let b = ((two_e * i3 - l2) / (i2 * (i3 - i2))).sqrt();
    let c = ((l2 - two_e * i1) / (i3 * (i3 - i1))).sqrt();
    let rate = ((i3 - i2) * (l2 - two_e * i1) / (i1 * i2 * i3)).sqrt();
    let m = (i2 - i1) * (two_e * i3 - l2) / ((i3 - i2) * (l2 - two_e * i1));
    let (sn, cn, dn) = jacobi_elliptic(rate * t, m);
    [a * cn, b * sn, c * dn]
}

/// The body-frame angular velocity Rᵀ ω at a state.
pub fn angular_velocity(s: &State) -> [f64; 3] {
    let r = BODY.bodies(s).body.rotation;
    let w = r.transpose() * BODY.body_velocities(s).body.angular;
    [w.x, w.y, w.z]
}

/// The world-frame angular momentum L = R I ω.
pub fn angular_momentum(s: &State) -> [f64; 3] {
    let r = BODY.bodies(s).body.rotation;
    let w = angular_velocity(s);
    let l = r * vec3(BODY.i1 * w[0], BODY.i2 * w[1], BODY.i3 * w[2]);
    [l.x, l.y, l.z]
}

/// What a run measured.
pub struct Tumble {
    /// max over the run of max_k |ω_k − ω_k(closed form)|.
    pub omega_error: f64,
    /// max |E − E₀| / E₀.
    pub energy_error: f64,
    /// max_k |L_k − L_k(0)| / |L(0)|.
    pub momentum_error: f64,
    /// max over the run of the entries of RᵀR − I.
    pub orthonormality: f64,
    /// How often the chart switched.
    pub switches: usize,
    /// (t, ω_k − ω_k(closed form)) every second, per component.
    pub departure: [Vec<(f64, f64)>; 3],
}

/// Runs the body for `duration` with steps of `h` of the method `I`, measuring as it goes.
pub fn tumble<I: Integrator>(h: f64, duration: f64) -> lagrange::Result<Tumble> {
    let mut s = start();
    let (e0, l0) = (BODY.energy(&s)?, angular_momentum(&s));
    let l0_norm = l0.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut run = Tumble {
        omega_error: 0.0,
        energy_error: 0.0,
        momentum_error: 0.0,
        orthonormality: 0.0,
        switches: 0,
        departure: Default::default(),
    };
    let per_second = (1.0 / h).round() as usize;
    let steps = (duration / h).round() as usize;
    for step in 1..=steps {
        let before = s.q.phi;
        BODY.step::<I>(&mut s, h)?;
        // A switch turns φ about: the new vector points against the old.
        run.switches += usize::from((0..3).map(|k| s.q.phi[k] * before[k]).sum::<f64>() < 0.0);
        if step % per_second != 0 {
            continue;
        }
        let (w, exact) = (angular_velocity(&s), closed_form(s.t));
        for k in 0..3 {
            run.omega_error = run.omega_error.max((w[k] - exact[k]).abs());
            run.departure[k].push((s.t, w[k] - exact[k]));
        }
        run.energy_error = run.energy_error.max((BODY.energy(&s)? - e0).abs() / e0);
        let l = angular_momentum(&s);
        for k in 0..3 {
            run.momentum_error = run.momentum_error.max((l[k] - l0[k]).abs() / l0_norm);
        }
        let r = BODY.bodies(&s).body.rotation;
        let rtr = r.transpose() * r;
        for i in 0..3 {
            for j in 0..3 {
                let identity = if i == j { 1.0 } else { 0.0 };
                run.orthonormality = run.orthonormality.max((rtr.rows[i][j] - identity).abs());
            }
        }
    }
    Ok(run)
}

/// The steps: RK4 at h = 2.5 ms for the trajectory, Gauss–Legendre (symplectic, order 4) at
/// h = 10 ms for the invariants.
const RK4_STEP: f64 = 2.5e-3;
const GL2_STEP: f64 = 1e-2;

pub fn run(plots: &Path) -> Vec<Check> {
    let rk4 = tumble::<Rk4>(RK4_STEP, DURATION).expect("RK4 run");
    let gl2 = tumble::<GaussLegendre2>(GL2_STEP, DURATION).expect("Gauss–Legendre run");
    let series: Vec<Series> = (0..3)
        .map(|k| {
            Series::new(
                format!("ω{} − closed form", k + 1),
                rk4.departure[k].clone(),
            )
        })
        .collect();
    let _ = plot::lines(
        &plots.join("tumbling_body.svg"),
        "torque-free body: RK4 (h = 2.5 ms) against Euler's closed form",
        "t (s)",
        "ω − ω_cf (rad/s)",
        &series,
    );
    vec![
        // RK4's energy error drifts linearly in t, and the frequency with it, so its error in ω
        // grows like h⁴ t²: from 7.8e-8 at h = 5 ms over 100 s (this run, shortened) to
        // (1/2)⁴ × 100² × 7.8e-8 ≈ 5e-5 at h = 2.5 ms over 10⁴ s.
        Check::new(
            SCENE,
            format!(
                "max |ω − ω_cf| over {DURATION:.0} s, RK4, {} chart switches",
                rk4.switches
            ),
            rk4.omega_error,
            0.0,
            5e-5,
        ),
        // The rotation is built orthonormal from φ: RᵀR = I to rounding at every step, with no
        // norm to drift.
        Check::new(
            SCENE,
            "max |RᵀR − I| over the run",
            rk4.orthonormality,
            0.0,
            1e-14,
        ),
        // Symplectic within a chart, Gauss–Legendre keeps E and L to its error; across the chart
        // switches (the coordinates it is symplectic in change) they drift slowly with the run,
        // growing in proportion to t and falling with h at about the fifth power: 5.4e-8 and
        // 4.1e-7 at h = 20 ms over 10⁴ s, so at h = 10 ms about 2e-9 and 2e-8.
        Check::new(
            SCENE,
            format!("max |E − E₀|/E₀, Gauss–Legendre, {DURATION:.0} s"),
            gl2.energy_error,
            0.0,
            1e-8,
        ),
        Check::new(
            SCENE,
            format!("max |L − L₀|/|L₀|, Gauss–Legendre, {DURATION:.0} s"),
            gl2.momentum_error,
            0.0,
            1e-7,
        ),
    ]
}
