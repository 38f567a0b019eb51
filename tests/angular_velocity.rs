//! `#[angular_velocity]`: a free or ball joint whose velocities are the body's angular velocity ω_b
//! (body frame), not its chart's rates — quasi-velocities, q̇ = G(q) v with G = B(c)⁻¹ on the
//! chart. The state then holds ω_b itself: no conversion to set it, and the chart's switches move
//! the coordinates only. Checked against Euler's closed form (the gallery's torque-free body), and
//! against the same declaration without the attribute, whose velocities are the chart's rates:
//! the two describe one motion, so every quantity of one is the other's converted.

use lagrange::geometry::{body_angular_velocity, chart_rates, RotationChart};
use lagrange::prelude::*;
use lagrange::tree::rigid::{JointKind, RigidTree, Velocities};
use lagrange::Seed;
use lagrange_gallery::scenes::tumbling_body::{closed_form, BODY, OMEGA0};

/// The gallery's tumbling body (moments 1, 2, 3), turned by the chart `$chart` about a fixed point,
/// its velocities the body's angular velocity.
macro_rules! spinning {
    ($module:ident, $chart:ident) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                #[angular_velocity]
                pub attitude: [f64; 3],
            }
            pub struct Spinning {
                pub i1: f64,
                pub i2: f64,
                pub i3: f64,
            }
            #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
            fn body() -> Spatial {
                spatial(
                    vec3(0.0, 0.0, 0.0),
                    $chart(vec3(attitude[0], attitude[1], attitude[2])),
                )
            }
        }
    };
}

spinning!(spinning_vector, rot_vector);
spinning!(spinning_mrp, rot_mrp);

/// A free base with an arm on a hinge, in a uniform field and pushed, written twice: its
/// orientation's velocities the angular velocity, and the chart's rates.
macro_rules! floater {
    ($module:ident, $chart:ident $(, #[$marker:ident])?) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                pub position: [f64; 3],
                $(#[$marker])?
                pub attitude: [f64; 3],
                pub hinge: f64,
            }
            pub struct Floater {
                pub m: f64,
                pub push: f64,
                pub g: f64,
            }
            #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.12])]
            fn base() -> Spatial {
                let r = $chart(vec3(attitude[0], attitude[1], attitude[2]));
                spatial(vec3(position[0], position[1], position[2]), r)
            }
            #[rigid_body(mass = 0.4 * m, inertia = [0.02, 0.02, 0.004])]
            fn arm() -> Spatial {
                let r = base.rotation * rot_z(0.2) * rot_y(hinge);
                spatial(base.point(vec3(0.2, 0.0, 0.1)) + r * vec3(0.0, 0.0, 0.25), r)
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
            #[force(on = arm)]
            fn shove() -> Vec3 {
                vec3(push, 0.0, 0.5 * push)
            }
            #[torque(on = base)]
            fn twist() -> Vec3 {
                vec3(0.0, 0.1 * push, 0.2 * push)
            }
            /// A drag on the base's turning: a force that reads the velocities.
            #[torque(on = base)]
            fn drag() -> Vec3 {
                base_dot.angular * (-0.3 * push)
            }
        }
    };
}

floater!(quasi_mrp, rot_mrp, #[angular_velocity]);
floater!(rates_mrp, rot_mrp);
floater!(quasi_vector, rot_vector, #[angular_velocity]);
floater!(rates_vector, rot_vector);

const VECTOR: spinning_vector::Spinning = spinning_vector::Spinning {
    i1: BODY.i1,
    i2: BODY.i2,
    i3: BODY.i3,
};

fn max_difference(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
}

/// The largest |ω_k − ω_k(closed form)| over `duration` with RK4 steps of `h`, sampled every
/// second, the velocities read straight from the state; and how often the chart switched.
fn vector_error(h: f64, duration: f64) -> (f64, usize) {
    let start = spinning_vector::Coords { attitude: [0.0; 3] };
    let spin = spinning_vector::Coords { attitude: OMEGA0 };
    let mut s = spinning_vector::State::new(0.0, start, spin);
    let (per_second, steps) = ((1.0 / h).round() as usize, (duration / h).round() as usize);
    let (mut error, mut switches) = (0.0f64, 0);
    for step in 1..=steps {
        let before = s.q.attitude;
        VECTOR.step::<Rk4>(&mut s, h).unwrap();
        switches += usize::from((0..3).map(|k| s.q.attitude[k] * before[k]).sum::<f64>() < 0.0);
        if step % per_second == 0 {
            error = error.max(max_difference(s.v.attitude, closed_form(s.t)));
        }
    }
    (error, switches)
}

#[test]
fn the_joints_have_the_angular_velocity_for_velocities() {
    let joints = <spinning_vector::Spinning as RigidTree<3, 1>>::JOINTS;
    let kind = JointKind::Ball(RotationChart::Vector, Velocities::AngularVelocity);
    assert_eq!(joints[0].kind, kind);
    let joints = <quasi_mrp::Floater as RigidTree<7, 2>>::JOINTS;
    let kind = JointKind::Free(RotationChart::Mrp, Velocities::AngularVelocity);
    assert_eq!(joints[0].kind, kind);
    let joints = <rates_mrp::Floater as RigidTree<7, 2>>::JOINTS;
    let kind = JointKind::Free(RotationChart::Mrp, Velocities::ChartRates);
    assert_eq!(joints[0].kind, kind);
}

/// Through 40 s (about 13 switches of the chart) RK4 follows Euler's closed form, the state's
/// velocities compared with ω_b as they are: fourth order, halving the step divides the error by
/// 16 (12 to 20 allowed: the h⁵ term still shifts the ratio at h = 0.01), as with the chart's
/// rates (`tests/floating.rs`).
#[test]
fn the_state_holds_the_angular_velocity_of_eulers_closed_form() {
    let (coarse, switches) = vector_error(0.01, 40.0);
    let (fine, _) = vector_error(0.005, 40.0);
    assert!(switches >= 10, "{switches} chart switches");
    let ratio = coarse / fine;
    assert!((12.0..20.0).contains(&ratio), "ratio {ratio}");
    // |ω| ≈ 2, a period of a few seconds: RK4's h⁴ error over 40 s stays below 1e-6.
    assert!(coarse < 1e-5, "{coarse:e}");
}

/// A chart switch moves the coordinates and leaves the angular velocity: a step across one
/// changes ω_b by the step's change alone (|ω̇| h ≲ 0.05 here), where the chart's rates would
/// jump (by a factor |σ|⁻² ≈ 1 and a reflection for modified Rodrigues parameters).
#[test]
fn a_chart_switch_leaves_the_velocities() {
    let sys = spinning_mrp::Spinning {
        i1: BODY.i1,
        i2: BODY.i2,
        i3: BODY.i3,
    };
    let start = spinning_mrp::Coords { attitude: [0.0; 3] };
    let spin = spinning_mrp::Coords { attitude: OMEGA0 };
    let mut s = spinning_mrp::State::new(0.0, start, spin);
    let mut switched = 0;
    for _ in 0..2000 {
        let (before, velocity) = (s.q.attitude, s.v.attitude);
        sys.step::<Rk4>(&mut s, 0.01).unwrap();
        // A switch to the shadow set turns σ about: the new vector points against the old.
        if (0..3).map(|k| before[k] * s.q.attitude[k]).sum::<f64>() < 0.0 {
            switched += 1;
            let change = (0..3).map(|k| (s.v.attitude[k] - velocity[k]).abs());
            assert!(
                change.fold(0.0, f64::max) < 0.1,
                "{:?} to {:?}",
                velocity,
                s.v.attitude
            );
        }
    }
    assert!(switched >= 5, "{switched} switches");
    // And the velocities still are Euler's (RK4 at h = 0.01 over 20 s).
    let exact = closed_form(s.t);
    assert!((0..3).all(|k| (s.v.attitude[k] - exact[k]).abs() < 1e-5));
}

/// The body's velocities the declaration reports (`body_velocities`) are those the state's ω_b
/// give: Rᵀ ω_world = ω_b.
#[test]
fn body_velocities_read_the_angular_velocity() {
    let q = spinning_vector::Coords {
        attitude: [0.4, -1.3, 2.2],
    };
    let v = spinning_vector::Coords {
        attitude: [0.7, -0.2, 1.5],
    };
    let s = spinning_vector::State::new(0.0, q, v);
    let r = VECTOR.bodies(&s).body.rotation;
    let w = r.transpose() * VECTOR.body_velocities(&s).body.angular;
    let got = [w.x, w.y, w.z];
    assert!(
        (0..3).all(|k| (got[k] - v.attitude[k]).abs() < 1e-14),
        "{got:?}"
    );
}

/// Adaptive steps (Dopri5, its dense output and error control on (q, ω_b)) follow Euler's closed
/// form to the tolerance's order over 20 s of switches.
#[test]
fn dopri5_steps_the_angular_velocity() {
    let start = spinning_vector::Coords { attitude: [0.0; 3] };
    let spin = spinning_vector::Coords { attitude: OMEGA0 };
    let s0 = spinning_vector::State::new(0.0, start, spin);
    let mut run = Stepper::new(&VECTOR, Dopri5::new(1e-10, 1e-12), &s0).unwrap();
    let mut worst = 0.0f64;
    for k in 1..=20 {
        run.integrate(k as f64, &mut [], |_| {}).unwrap();
        let s = run.state();
        worst = worst.max(max_difference(s.v.attitude, closed_form(k as f64)));
    }
    // A local tolerance of 1e-10 accumulates to well below 1e-7 over 20 s of a few periods.
    assert!(worst < 1e-7, "{worst:e}");
}

/// G = B(c)⁻¹ of the chart at c, by columns: ċ = G ω_b.
fn g_matrix(chart: RotationChart, c: [f64; 3]) -> [[f64; 3]; 3] {
    let unit = |k: usize| std::array::from_fn(|j| if j == k { 1.0 } else { 0.0 });
    [0, 1, 2].map(|k| chart_rates(chart, c, unit(k)).unwrap())
}

/// Ḃ(c, ċ) ċ by central differences of B(c) ċ along ċ (step δ = 1e-6: truncation O(δ²) ≈ 1e-12,
/// rounding 1e-16/δ ≈ 1e-10 on quantities of order one).
fn b_dot_rates(chart: RotationChart, c: [f64; 3], rates: [f64; 3]) -> [f64; 3] {
    let delta = 1e-6;
    let moved = |sign: f64| std::array::from_fn(|k| c[k] + sign * delta * rates[k]);
    let plus = body_angular_velocity(chart, moved(1.0), rates);
    let minus = body_angular_velocity(chart, moved(-1.0), rates);
    std::array::from_fn(|k| (plus[k] - minus[k]) / (2.0 * delta))
}

/// The floaters' seven coordinates: position (0..3), orientation (3..6), hinge (6).
const AT: usize = 3;

/// ċ = G ω on the orientation's slots, everything else as it is.
fn rates_of(chart: RotationChart, q: &[f64; 7], v: &[f64; 7]) -> [f64; 7] {
    let c = [q[AT], q[AT + 1], q[AT + 2]];
    let g = g_matrix(chart, c);
    let mut out = *v;
    for k in 0..3 {
        out[AT + k] = (0..3).map(|j| g[j][k] * v[AT + j]).sum();
    }
    out
}

/// Gᵀ x on the orientation's slots: what is dual to ċ made dual to ω.
fn dual_of(chart: RotationChart, q: &[f64; 7], x: &[f64; 7]) -> [f64; 7] {
    let g = g_matrix(chart, [q[AT], q[AT + 1], q[AT + 2]]);
    let mut out = *x;
    for j in 0..3 {
        out[AT + j] = (0..3).map(|k| g[j][k] * x[AT + k]).sum();
    }
    out
}

/// Whether a and b agree to `tolerance` relative to the larger's size (at least 1).
fn agree(a: &[f64], b: &[f64], tolerance: f64, what: &str) {
    let scale = a.iter().chain(b).fold(1.0f64, |m, x| m.max(x.abs()));
    let worst = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(worst < tolerance * scale, "{what}: {a:?} against {b:?}");
}

/// States of the floaters: the orientation at norms from small to past the switch's, the rest
/// moving.
fn floater_states(norms: &[f64]) -> Vec<([f64; 7], [f64; 7])> {
    norms
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            let axis = [0.6, -0.48, 0.64];
            let phase = i as f64;
            let q = [
                0.3,
                -0.2,
                1.1,
                n * axis[0],
                n * axis[1],
                n * axis[2],
                0.4 - 0.3 * phase,
            ];
            let v = [0.2, 1.2, -0.8, 0.7 + 0.1 * phase, -0.4, 1.1, -0.6];
            (q, v)
        })
        .collect()
}

/// Every quantity of the floater with ω_b for velocities is the rates floater's converted, at the
/// same motion (ċ = G ω): T and V equal, p_ω = Gᵀ p_ċ, M_ω = Gᵀ M_ċ G, 𝓕_ω = Gᵀ 𝓕_ċ (the
/// applied force, torque and field), ω̇ = B c̈ + Ḃ ċ, and inverse dynamics τ_ω = Gᵀ τ_ċ. Both are
/// exact formulas in double precision (1e-11 relative), ω̇ but for the difference quotient's
/// 1e-10 (1e-8 allowed).
macro_rules! agrees_converted {
    ($name:ident, $quasi:ident, $rates:ident, $chart:expr, $norms:expr) => {
        #[test]
        fn $name() {
            let quasi = $quasi::Floater {
                m: 1.3,
                push: 0.7,
                g: 9.81,
            };
            let rates = $rates::Floater {
                m: 1.3,
                push: 0.7,
                g: 9.81,
            };
            for (q, v) in floater_states(&$norms) {
                let q_dot = rates_of($chart, &q, &v);
                let c = [q[AT], q[AT + 1], q[AT + 2]];
                let coords = |x: [f64; 7]| $quasi::Coords::from_array(x);
                let s = $quasi::State::new(0.0, coords(q), coords(v));
                let r = $rates::State::new(
                    0.0,
                    $rates::Coords::from_array(q),
                    $rates::Coords::from_array(q_dot),
                );
                let energy = |e: f64, f: f64| agree(&[e], &[f], 1e-11, "energy");
                energy(
                    quasi.kinetic_energy(&s).unwrap(),
                    rates.kinetic_energy(&r).unwrap(),
                );
                energy(quasi.energy(&s).unwrap(), rates.energy(&r).unwrap());
                let p = rates.momenta(&r).unwrap().to_array();
                agree(
                    &quasi.momenta(&s).unwrap().to_array(),
                    &dual_of($chart, &q, &p),
                    1e-11,
                    "p",
                );
                let f = rates.generalized_forces(&r).unwrap().to_array();
                let got = quasi.generalized_forces(&s).unwrap().to_array();
                agree(&got, &dual_of($chart, &q, &f), 1e-11, "forces");
                let (m_quasi, m_rates) = (
                    quasi.mass_matrix(&s).unwrap(),
                    rates.mass_matrix(&r).unwrap(),
                );
                for j in 0..7 {
                    let unit: [f64; 7] = std::array::from_fn(|i| if i == j { 1.0 } else { 0.0 });
                    let column: [f64; 7] =
                        (m_rates * nalgebra::SVector::from(rates_of($chart, &q, &unit))).into();
                    let expected = dual_of($chart, &q, &column);
                    let got: [f64; 7] = m_quasi
                        .column(j)
                        .iter()
                        .copied()
                        .collect::<Vec<_>>()
                        .try_into()
                        .unwrap();
                    agree(&got, &expected, 1e-11, "mass matrix");
                }
                let q_ddot = rates.accelerations(&r).unwrap().to_array();
                let omega_dot =
                    body_angular_velocity($chart, c, [q_ddot[AT], q_ddot[AT + 1], q_ddot[AT + 2]]);
                let bias = b_dot_rates($chart, c, [q_dot[AT], q_dot[AT + 1], q_dot[AT + 2]]);
                let mut expected = q_ddot;
                for k in 0..3 {
                    expected[AT + k] = omega_dot[k] + bias[k];
                }
                let got = quasi.accelerations(&s).unwrap().to_array();
                agree(&got, &expected, 1e-8, "accelerations");
                // Inverse dynamics at other accelerations than the motion's.
                let a: [f64; 7] = std::array::from_fn(|i| 0.3 * i as f64 - 0.8);
                let a_omega = body_angular_velocity($chart, c, [a[AT], a[AT + 1], a[AT + 2]]);
                let mut a_quasi = a;
                for k in 0..3 {
                    a_quasi[AT + k] = a_omega[k] + bias[k];
                }
                let tau_rates = rates
                    .inverse_dynamics(&r, &$rates::Coords::from_array(a))
                    .unwrap()
                    .to_array();
                let tau = quasi
                    .inverse_dynamics(&s, &coords(a_quasi))
                    .unwrap()
                    .to_array();
                agree(
                    &tau,
                    &dual_of($chart, &q, &tau_rates),
                    1e-8,
                    "inverse dynamics",
                );
            }
        }
    };
}

agrees_converted!(
    mrp_floater_is_the_rates_floater_converted,
    quasi_mrp,
    rates_mrp,
    RotationChart::Mrp,
    [0.05, 0.5, 0.95, 1.05]
);
agrees_converted!(
    vector_floater_is_the_rates_floater_converted,
    quasi_vector,
    rates_vector,
    RotationChart::Vector,
    [
        0.05,
        1.5,
        std::f64::consts::PI - 1e-3,
        std::f64::consts::PI + 0.05
    ]
);

/// The MRP floater in both descriptions, and one motion (the first of [`floater_states`] at a
/// rotation of norm 0.8) as each one's state: ω for the one, ċ = G ω for the other.
fn one_motion_twice() -> (
    quasi_mrp::Floater,
    rates_mrp::Floater,
    quasi_mrp::State,
    rates_mrp::State,
) {
    let (m, push, g) = (1.3, 0.7, 9.81);
    let (q, v) = floater_states(&[0.8])[0];
    let s = quasi_mrp::State::new(
        0.0,
        quasi_mrp::Coords::from_array(q),
        quasi_mrp::Coords::from_array(v),
    );
    let r = rates_mrp::State::new(
        0.0,
        rates_mrp::Coords::from_array(q),
        rates_mrp::Coords::from_array(rates_of(RotationChart::Mrp, &q, &v)),
    );
    (
        quasi_mrp::Floater { m, push, g },
        rates_mrp::Floater { m, push, g },
        s,
        r,
    )
}

/// Störmer–Verlet, built on q̇ = v (and a constant mass matrix), refuses such a declaration,
/// decided by the declaration: the state is unchanged. (On q' = G(q) v it would not be
/// symplectic.)
#[test]
fn stormer_verlet_refuses_angular_velocities() {
    let start = spinning_vector::Coords {
        attitude: [0.1, 0.2, 0.3],
    };
    let spin = spinning_vector::Coords { attitude: OMEGA0 };
    let s0 = spinning_vector::State::new(0.0, start, spin);
    let refused = |result: lagrange::Result<()>| {
        let error = result.expect_err("refused");
        assert!(
            matches!(error, lagrange::Error::UnsuitableMethod { .. }),
            "{error}"
        );
        assert!(error.to_string().contains("#[angular_velocity]"), "{error}");
    };
    let mut s = s0;
    refused(VECTOR.step::<StormerVerlet>(&mut s, 0.01));
    assert_eq!(s, s0);
}

/// Radau5 steps the coordinates' rates between conversions (its stage equations are written for
/// q' = q̇), so from one motion in both descriptions it takes the very steps it takes on the
/// declaration written with the rates, through the MRP chart's switch: the same number of steps,
/// the same end to the conversions' rounding (which may stop a Newton iteration one sweep apart,
/// so up to the iteration's tolerance, about 1e-10 at a tolerance of 1e-8: 1e-9 relative asked),
/// and its dense output, evaluated at each step's midpoint,
/// holds the velocities (the rates run's dense output converted).
#[test]
fn radau5_steps_as_the_rates() {
    // Unoptimised, the Jacobians of the tree's recursions on dual numbers take more stack than a
    // test thread's 2 MB (3–4 MB measured): run on a thread with 16 MB.
    let run = std::thread::Builder::new().stack_size(16 << 20);
    run.spawn(radau5_against_the_rates).unwrap().join().unwrap();
}

fn radau5_against_the_rates() {
    let (quasi, rates, s, r) = one_motion_twice();
    let method = Radau5::new(1e-8, 1e-8);
    let mut quasi_run = Stepper::new(&quasi, method, &s).unwrap();
    let mut rates_run = Stepper::new(&rates, method, &r).unwrap();
    let mut switched = false;
    while quasi_run.state().t < 3.0 {
        quasi_run.step(3.0).unwrap();
        rates_run.step(3.0).unwrap();
        let (dq, dr) = (quasi_run.dense(), rates_run.dense());
        let mid = 0.5 * (dq.t_start() + dq.t_end());
        let ((qm, vm), (qr, rr)) = (dq.eval(mid), dr.eval(mid));
        agree(&qm, &qr, 1e-9, "dense q");
        agree(
            &rates_of(RotationChart::Mrp, &qm, &vm),
            &rr,
            1e-9,
            "dense q̇",
        );
        let size: f64 = quasi_run.state().q.attitude.iter().map(|x| x * x).sum();
        switched |= size < 0.5;
    }
    assert!(switched, "the chart switched");
    let (end_q, end_r) = (quasi_run.state(), rates_run.state());
    assert_eq!(end_q.t, end_r.t);
    assert_eq!(quasi_run.stats().accepted, rates_run.stats().accepted);
    let (q1, v1) = (end_q.q.to_array(), end_q.v.to_array());
    agree(&q1, &end_r.q.to_array(), 1e-9, "q");
    agree(
        &rates_of(RotationChart::Mrp, &q1, &v1),
        &end_r.v.to_array(),
        1e-9,
        "q̇",
    );
}

/// The methods on momenta conjugate to q̇ step the coordinates' rates between conversions, so they
/// take the very steps they take on the declaration written with the rates: `$method` from one
/// motion in both descriptions, 300 steps of 10 ms through the MRP chart's switch, ends at the
/// same point. The two runs differ by the conversions' rounding, carried through the Newton
/// iterations and 300 steps (the largest difference seen is 2e-13 on coordinates up to 45): 1e-11
/// relative.
macro_rules! steps_as_the_rates {
    ($name:ident, $method:ty) => {
        #[test]
        fn $name() {
            let (quasi, rates, mut s, mut r) = one_motion_twice();
            let (mut switched, e0) = (false, quasi.energy(&s).unwrap());
            for _ in 0..300 {
                quasi.step::<$method>(&mut s, 0.01).unwrap();
                rates.step::<$method>(&mut r, 0.01).unwrap();
                let size: f64 = s.q.attitude.iter().map(|x| x * x).sum();
                switched |= size < 0.5;
            }
            assert!(switched, "the chart switched");
            let (q1, v1) = (s.q.to_array(), s.v.to_array());
            agree(&q1, &r.q.to_array(), 1e-11, "q");
            agree(
                &rates_of(RotationChart::Mrp, &q1, &v1),
                &r.v.to_array(),
                1e-11,
                "q̇",
            );
            // Pushed, the floater gains energy: it is the rates run's.
            let gained = quasi.energy(&s).unwrap() - e0;
            agree(
                &[gained],
                &[rates.energy(&r).unwrap() - e0],
                1e-11,
                "energy",
            );
        }
    };
}

steps_as_the_rates!(gauss_legendre_steps_as_the_rates, GaussLegendre2);
steps_as_the_rates!(implicit_midpoint_steps_as_the_rates, ImplicitMidpoint);
steps_as_the_rates!(variational_steps_as_the_rates, Variational);

/// The linearization's top row is [∂(G v)/∂q, G] (not [0, I]): G from the chart's inverse map and
/// ∂(G v)/∂q by central differences of G v (step 1e-6: O(δ²) truncation, 1e-10 rounding; 1e-7
/// allowed); the bottom row is v̇'s, checked against central differences of the accelerations.
#[test]
fn linearization_has_the_position_rates_row() {
    use lagrange::analysis::linearize;
    let sys = quasi_mrp::Floater {
        m: 1.3,
        push: 0.7,
        g: 9.81,
    };
    let (q, v) = floater_states(&[0.7])[0];
    let state = |q: [f64; 7], v: [f64; 7]| {
        quasi_mrp::State::new(
            0.0,
            quasi_mrp::Coords::from_array(q),
            quasi_mrp::Coords::from_array(v),
        )
    };
    let lin = linearize(&sys, &state(q, v)).unwrap();
    let delta = 1e-6;
    for j in 0..7 {
        let moved = |sign: f64| -> [f64; 7] {
            std::array::from_fn(|i| if i == j { q[i] + sign * delta } else { q[i] })
        };
        let (plus, minus) = (moved(1.0), moved(-1.0));
        let rates = |x: &[f64; 7]| rates_of(RotationChart::Mrp, x, &v);
        let column: Vec<f64> = (0..7)
            .map(|i| (rates(&plus)[i] - rates(&minus)[i]) / (2.0 * delta))
            .collect();
        let got: Vec<f64> = lin.dqd_dq.column(j).iter().copied().collect();
        agree(&got, &column, 1e-7, "∂(G v)/∂q");
        let unit: [f64; 7] = std::array::from_fn(|i| if i == j { 1.0 } else { 0.0 });
        let column = rates_of(RotationChart::Mrp, &q, &unit);
        let got: Vec<f64> = lin.dqd_dv.column(j).iter().copied().collect();
        agree(&got, &column, 1e-14, "G");
        let acc = |x: [f64; 7]| sys.accelerations(&state(x, v)).unwrap().to_array();
        let (a, b) = (acc(plus), acc(minus));
        let column: Vec<f64> = (0..7).map(|i| (a[i] - b[i]) / (2.0 * delta)).collect();
        let got: Vec<f64> = lin.dqdd_dq.column(j).iter().copied().collect();
        agree(&got, &column, 1e-7, "∂v̇/∂q");
    }
    // The assembled A carries the blocks.
    let a = lin.a_matrix();
    assert_eq!(a[(AT, 7 + AT)], lin.dqd_dv[(AT, AT)]);
    assert_ne!(a[(AT, AT + 1)], 0.0);
}

/// Trajectory sensitivities (RK4 on dual numbers, the position rates along) seeded on ω_b(0):
/// against central differences of two runs (δ = 1e-6; the runs are the same f64 operations, so
/// the quotient's error is O(δ²) and 1e-16/δ, 1e-7 allowed).
#[test]
fn sensitivities_carry_the_position_rates() {
    let start = spinning_vector::Coords {
        attitude: [0.2, -0.1, 0.3],
    };
    let run = |w: f64| {
        let spin = spinning_vector::Coords {
            attitude: [w, 0.0, 2.0],
        };
        let s0 = spinning_vector::State::new(0.0, start, spin);
        let mut run = Stepper::new(&VECTOR, Rk4::with_step(0.01), &s0)
            .unwrap()
            .with_sensitivities([Seed::Velocity("attitude[0]")])
            .unwrap();
        run.integrate(3.0, &mut [], |_| {}).unwrap();
        let s = run.sensitivities();
        (s.state, s.dq[0], s.dv[0])
    };
    let (state, dq, dv) = run(1.0);
    // The tangent's real parts are the plain run's (to rounding: the tree's passes on dual numbers
    // and on f64 are not the same operations everywhere).
    let spin = spinning_vector::Coords {
        attitude: [1.0, 0.0, 2.0],
    };
    let s0 = spinning_vector::State::new(0.0, start, spin);
    let mut plain = Stepper::new(&VECTOR, Rk4::with_step(0.01), &s0).unwrap();
    plain.integrate(3.0, &mut [], |_| {}).unwrap();
    let end = plain.state();
    agree(&state.q.attitude, &end.q.attitude, 1e-12, "q");
    agree(&state.v.attitude, &end.v.attitude, 1e-12, "v");
    let delta = 1e-6;
    let (plus, minus) = (run(1.0 + delta).0, run(1.0 - delta).0);
    let quotient = |a: [f64; 3], b: [f64; 3]| -> Vec<f64> {
        (0..3).map(|k| (a[k] - b[k]) / (2.0 * delta)).collect()
    };
    agree(
        &dq.attitude,
        &quotient(plus.q.attitude, minus.q.attitude),
        1e-7,
        "∂q/∂ω₁(0)",
    );
    agree(
        &dv.attitude,
        &quotient(plus.v.attitude, minus.v.attitude),
        1e-7,
        "∂ω/∂ω₁(0)",
    );
}

/// A floating base with a motor at its hinge, the base's velocities its angular velocity.
#[mechanism]
pub mod driven_floater {
    pub struct Coords {
        pub position: [f64; 3],
        #[angular_velocity]
        pub attitude: [f64; 3],
        pub hinge: f64,
    }
    pub struct Floater {
        pub m: f64,
        pub g: f64,
    }
    #[inputs]
    pub struct Motor {
        pub tau: f64,
    }
    #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.12])]
    fn base() -> Spatial {
        let r = rot_mrp(vec3(attitude[0], attitude[1], attitude[2]));
        spatial(vec3(position[0], position[1], position[2]), r)
    }
    #[rigid_body(mass = 0.4 * m, inertia = [0.02, 0.02, 0.004])]
    fn arm() -> Spatial {
        let r = base.rotation * rot_z(0.2) * rot_y(hinge);
        spatial(
            base.point(vec3(0.2, 0.0, 0.1)) + r * vec3(0.0, 0.0, 0.25),
            r,
        )
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
    #[generalized_force(on = hinge)]
    fn motor() -> f64 {
        tau
    }
}

/// Inputs on a mechanism with angular velocities: the motor's torque reaches v̇ through the
/// tree, and the input matrix ∂v̇/∂τ (dual numbers seeded on the input) is the central difference
/// of the driven accelerations (v̇ is affine in τ: no truncation error, rounding ~1e-16/δ with
/// δ = 1e-4, 1e-9 allowed); the undriven accelerations at τ = 0 are those of the motor's absence.
#[test]
fn inputs_drive_a_base_with_angular_velocities() {
    use lagrange::analysis::linearize_driven;
    let sys = driven_floater::Floater { m: 1.3, g: 9.81 };
    let (q, v) = floater_states(&[0.6])[0];
    let state = driven_floater::State::new(
        0.0,
        driven_floater::Coords::from_array(q),
        driven_floater::Coords::from_array(v),
    );
    let motor = |tau: f64| driven_floater::Motor { tau };
    let driven = |tau: f64| {
        sys.driven(&motor(tau))
            .accelerations(&state)
            .unwrap()
            .to_array()
    };
    agree(
        &driven(0.0),
        &sys.accelerations(&state).unwrap().to_array(),
        1e-14,
        "undriven",
    );
    let lin = linearize_driven(&sys, &state, &motor(0.5)).unwrap();
    let delta = 1e-4;
    let (plus, minus) = (driven(0.5 + delta), driven(0.5 - delta));
    let column: Vec<f64> = (0..7)
        .map(|i| (plus[i] - minus[i]) / (2.0 * delta))
        .collect();
    let got: Vec<f64> = lin.dqdd_dinputs.column(0).iter().copied().collect();
    agree(&got, &column, 1e-9, "∂v̇/∂τ");
    // The motor turns the arm and, reacting, the base: both rows are non-zero.
    assert!(
        got[6].abs() > 0.1 && got[AT..AT + 3].iter().any(|x| x.abs() > 0.1),
        "{got:?}"
    );
}

/// A physical pendulum on a ball joint (its frame at the pivot, the centre of mass at `com`
/// below it), the chart's velocities the angular velocity.
#[mechanism]
pub mod hanging {
    pub struct Coords {
        #[angular_velocity]
        pub attitude: [f64; 3],
    }
    pub struct Hanging {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = [0.02, 0.05, 0.04], com = vec3(0.0, 0.0, -l))]
    fn bob() -> Spatial {
        spatial(
            vec3(0.0, 0.0, 0.0),
            rot_mrp(vec3(attitude[0], attitude[1], attitude[2])),
        )
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

/// The analyses at rest linearize in the coordinates (M δq̈ + K δq = 0, δq̇ = G δv between them):
/// hanging, the pendulum's stiffness eigenvalues relative to M are the physical pendulum's
/// ω² = m g l / (Iₖ + m l²) about x and y, and 0 about the vertical (Landau & Lifshitz, *Mechanics*,
/// §21 for the small oscillations; Steiner's theorem for the pivot's moments). Exact formulas in
/// double precision: 1e-12.
#[test]
fn small_oscillations_are_the_physical_pendulum_s() {
    use lagrange::analysis::stability;
    let sys = hanging::Hanging {
        m: 0.8,
        l: 0.3,
        g: 9.81,
    };
    let rest = hanging::Coords { attitude: [0.0; 3] };
    let analysis = stability(&sys, 0.0, &rest).unwrap();
    let swing = |i: f64| sys.m * sys.g * sys.l / (i + sys.m * sys.l * sys.l);
    let mut expected = [swing(0.02), swing(0.05), 0.0];
    expected.sort_by(f64::total_cmp);
    agree(&analysis.stiffness_eigenvalues, &expected, 1e-12, "ω²");
    // Turned about the vertical (σ = (0, 0, 0.4)), it hangs all the same, and the verdict is the
    // same: marginal (the free turn about the vertical), the swings' eigenvalues unchanged.
    let turned = hanging::Coords {
        attitude: [0.0, 0.0, 0.4],
    };
    let analysis = stability(&sys, 0.0, &turned).unwrap();
    assert_eq!(analysis.stability, lagrange::analysis::Stability::Marginal);
    agree(
        &analysis.stiffness_eigenvalues,
        &expected,
        1e-12,
        "ω² turned",
    );
}

/// Dop853 (its stages and its 7th-order dense output on (q, ω)) follows Euler's closed form to the
/// tolerance's order over 20 s of switches, as Dopri5 does.
#[test]
fn dop853_steps_the_angular_velocity() {
    let start = spinning_vector::Coords { attitude: [0.0; 3] };
    let spin = spinning_vector::Coords { attitude: OMEGA0 };
    let s0 = spinning_vector::State::new(0.0, start, spin);
    let mut run = Stepper::new(&VECTOR, Dop853::new(1e-10, 1e-12), &s0).unwrap();
    let mut worst = 0.0f64;
    for k in 1..=20 {
        run.integrate(k as f64, &mut [], |_| {}).unwrap();
        worst = worst.max(max_difference(
            run.state().v.attitude,
            closed_form(k as f64),
        ));
    }
    // A local tolerance of 1e-10 accumulates to well below 1e-7 over 20 s of a few periods.
    assert!(worst < 1e-7, "{worst:e}");
}

/// A step's dense output moves the positions by their rates G v, not by v: at the middle of a
/// step of the floater (MRP, where G is a quarter of the identity near the origin) it meets an
/// accurate solution (RK4 at a thousandth of the step from the step's start) to the interpolant's
/// order — cubic Hermite O(h⁴), Dopri5's order 4, Dop853's 7: with h ≤ 0.05 and derivatives of
/// order one, below 1e-6 — where interpolating with v would be off by h |v − G v| ≈ 0.03. The
/// velocities to `$v_tolerance`: the same orders, but a straight line between the step's two v
/// without the dense output's end evaluation (off by h²/8 |v̈| ≲ 1e-3).
macro_rules! dense_output_moves_by_the_rates {
    ($name:ident, $method:expr, $v_tolerance:expr) => {
        #[test]
        fn $name() {
            let sys = quasi_mrp::Floater {
                m: 1.3,
                push: 0.7,
                g: 9.81,
            };
            let (q, v) = floater_states(&[0.3])[0];
            let coords = quasi_mrp::Coords::from_array;
            let s0 = quasi_mrp::State::new(0.0, coords(q), coords(v));
            let mut run = Stepper::new(&sys, $method, &s0).unwrap();
            let start = run.state();
            run.step(0.05).unwrap();
            let h = run.last_step();
            let (q_mid, v_mid) = run.dense().eval(0.5 * h);
            let mut exact = start;
            let fine = h / 1000.0;
            for _ in 0..500 {
                sys.step::<Rk4>(&mut exact, fine).unwrap();
            }
            agree(
                &q_mid,
                &exact.q.to_array(),
                1e-6,
                "q at the middle of the step",
            );
            agree(
                &v_mid,
                &exact.v.to_array(),
                $v_tolerance,
                "v at the middle of the step",
            );
        }
    };
}

dense_output_moves_by_the_rates!(
    rk4_dense_output_moves_by_the_rates,
    Rk4::with_step(0.05),
    1e-5
);
dense_output_moves_by_the_rates!(
    rk4_positions_only_dense_output_moves_by_the_rates,
    Rk4::with_step(0.05).without_dense(),
    1e-2
);
dense_output_moves_by_the_rates!(
    dopri5_dense_output_moves_by_the_rates,
    Dopri5::new(1e-8, 1e-10),
    1e-5
);
dense_output_moves_by_the_rates!(
    dop853_dense_output_moves_by_the_rates,
    Dop853::new(1e-8, 1e-10),
    1e-5
);
