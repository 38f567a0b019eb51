//! `#[angular_velocity]` with constraint rows: the rows are written on the coordinates' rates, and
//! every function of `lagrange::constraints` that takes a state converts (q̇ = G v at its entry,
//! v̇ = B q̈ + Ḃ q̇ and forces dual to v at its exit; the projection in the rates with M = Bᵀ M_v B
//! is the projection in v with M_v). So a body whose velocities are its angular velocity moves
//! as the same declaration written with the chart's rates moves: checked here quantity by
//! quantity (q̈, λ, the constraint forces, the projection, a consistent start), over trajectories
//! (RK4 with a rod, Dopri5 through an impact on a floor, the collocation and variational steps),
//! and on a URDF quadruped with a foot contact, whose floating base has ω for velocities.

use lagrange::constraints::{
    consistent_state, consistent_state_holding, constraint_forces, ModeChange, RowMode,
};
use lagrange::geometry::RotationChart;
use lagrange::integrate::EmbeddedPair;
use lagrange::prelude::*;
use lagrange::tree::rigid::free::{position_rates, velocities_from_rates, velocity_bias};
use lagrange::tree::rigid::{JointKind, RigidTree, Velocities};

/// A body on a rod from the origin to one of its corners, over a floor another corner cannot go
/// below, with a drag on its turning: written twice, its orientation's velocities the angular
/// velocity and the chart's rates.
macro_rules! tethered {
    ($module:ident $(, #[$marker:ident])?) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                pub position: [f64; 3],
                $(#[$marker])?
                pub attitude: [f64; 3],
            }
            pub struct Tethered {
                pub m: f64,
                pub g: f64,
                pub length: f64,
                pub floor: f64,
            }
            #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.12])]
            fn base() -> Spatial {
                let r = rot_mrp(vec3(attitude[0], attitude[1], attitude[2]));
                spatial(vec3(position[0], position[1], position[2]), r)
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
            #[torque(on = base)]
            fn drag() -> Vec3 {
                base_dot.angular * (-0.05)
            }
            #[constraint]
            fn rod() -> f64 {
                base.point(vec3(0.2, 0.1, 0.3)).norm() - length
            }
            #[unilateral]
            fn ground() -> f64 {
                base.point(vec3(-0.2, 0.0, -0.1)).z - floor
            }
        }
    };
}

tethered!(quasi, #[angular_velocity]);
tethered!(rates);

const N: usize = 6;

fn bodies() -> (quasi::Tethered, rates::Tethered) {
    // The floor far below: the rod alone acts (the contact separated) unless a test raises it.
    let (m, g, length, floor) = (1.3, 9.81, 1.0, -10.0);
    (
        quasi::Tethered {
            m,
            g,
            length,
            floor,
        },
        rates::Tethered {
            m,
            g,
            length,
            floor,
        },
    )
}

fn joints() -> [lagrange::tree::rigid::Joint; 1] {
    <quasi::Tethered as RigidTree<N, 1>>::JOINTS
}

/// q̇ = G v, v = B q̇ and Ḃ q̇ of the quasi body's joint (the maps `tree::rigid::free` tests).
fn rates_of(q: &[f64; N], v: &[f64; N]) -> [f64; N] {
    position_rates(&joints(), q, v)
}
fn velocities_of(q: &[f64; N], rates: &[f64; N]) -> [f64; N] {
    velocities_from_rates(&joints(), q, rates)
}

/// Within `tolerance` relative to 1 + the size of `b`.
fn agree(a: &[f64], b: &[f64], tolerance: f64, what: &str) {
    let size = b.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    let worst = a
        .iter()
        .zip(b)
        .fold(0.0f64, |w, (x, y)| w.max((x - y).abs()));
    assert!(
        worst <= tolerance * size,
        "{what}: {a:?} against {b:?} ({worst:e})"
    );
}

/// Consistent states of the rates body from a few guesses (on the rod, off the floor), with
/// orientations up to π + 0.3 (past the chart's switch) and their angular velocities.
fn states() -> Vec<([f64; N], [f64; N])> {
    let (_, rates_body) = bodies();
    [0.3, 1.1, 0.95, 1.05]
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            let phase = i as f64;
            let axis = [0.6, -0.48, 0.64];
            let q = [
                0.1,
                0.5 - 0.2 * phase,
                -0.6,
                n * axis[0],
                n * axis[1],
                n * axis[2],
            ];
            let v = [0.4, -0.3, 0.2, 0.7 + 0.2 * phase, -0.5, 0.9];
            let guess = rates::State::new(
                0.0,
                rates::Coords::from_array(q),
                rates::Coords::from_array(v),
            );
            let s = consistent_state(&rates_body, &guess).expect("a consistent guess");
            (s.q.to_array(), s.v.to_array())
        })
        .collect()
}

/// At the same motion (v = B q̇): v̇ = B q̈ + Ḃ q̇, the same multipliers, constraint forces dual
/// to v (Gᵀ rᵢ λᵢ) and rows Gᵀ rᵢ. Exact formulas on one solve each: 1e-11.
#[test]
fn the_constrained_solve_is_the_rates_solve_converted() {
    let (quasi_body, rates_body) = bodies();
    for (q, q_dot) in states() {
        let v = velocities_of(&q, &q_dot);
        let qs = quasi::State::new(
            0.0,
            quasi::Coords::from_array(q),
            quasi::Coords::from_array(v),
        );
        let rs = rates::State::new(
            0.0,
            rates::Coords::from_array(q),
            rates::Coords::from_array(q_dot),
        );
        let a_rates = rates_body.accelerations(&rs).unwrap().to_array();
        let a_quasi = quasi_body.accelerations(&qs).unwrap().to_array();
        let b_qdd = velocities_of(&q, &a_rates);
        let bias = velocity_bias(&joints(), &q, &q_dot);
        let expected: [f64; N] = std::array::from_fn(|i| b_qdd[i] + bias[i]);
        agree(&a_quasi, &expected, 1e-11, "v̇ = B q̈ + Ḃ q̇");

        let fq = constraint_forces(&quasi_body, &qs).unwrap();
        let fr = constraint_forces(&rates_body, &rs).unwrap();
        agree(&fq.multipliers, &fr.multipliers, 1e-11, "multipliers");
        agree(
            &fq.accelerations,
            &expected,
            1e-11,
            "the forces' accelerations",
        );
        for (row_q, row_r) in fq.generalized.iter().zip(&fr.generalized) {
            let dual = lagrange::tree::rigid::free::velocity_forces(&joints(), &q, row_r);
            agree(row_q, &dual, 1e-11, "generalized constraint force Gᵀ r λ");
            // Power is the same: the force's power on v is its power on q̇.
            let (pq, pr) = (dot(row_q, &v), dot(row_r, &q_dot));
            agree(&[pq], &[pr], 1e-11, "constraint power");
        }
        agree(
            &fq.cartesian.concat(),
            &fr.cartesian.concat(),
            1e-11,
            "Cartesian forces",
        );
    }
}

fn dot(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// A guess projected onto the rod: the quasi body's consistent state is the rates body's from
/// the converted guess, converted (the projection in v with M_v is the projection in q̇ with M:
/// the same computation, to round-off). Holding an angular velocity's component is refused.
#[test]
fn a_consistent_start_is_the_rates_start_converted() {
    let (quasi_body, rates_body) = bodies();
    let (q, v) = (
        [0.1, 0.9, -0.7, 0.2, 0.3, -0.4],
        [0.4, -0.3, 0.2, 0.7, -0.5, 0.9],
    );
    let q_dot = rates_of(&q, &v);
    let guess_q = quasi::State::new(
        0.0,
        quasi::Coords::from_array(q),
        quasi::Coords::from_array(v),
    );
    let guess_r = rates::State::new(
        0.0,
        rates::Coords::from_array(q),
        rates::Coords::from_array(q_dot),
    );
    let sq = consistent_state(&quasi_body, &guess_q).unwrap();
    let sr = consistent_state(&rates_body, &guess_r).unwrap();
    agree(
        &sq.q.to_array(),
        &sr.q.to_array(),
        1e-13,
        "projected positions",
    );
    let converted = velocities_of(&sr.q.to_array(), &sr.v.to_array());
    agree(&sq.v.to_array(), &converted, 1e-12, "projected velocities");
    // A translation's velocity can be held; an angular velocity's component cannot.
    let held = consistent_state_holding(&quasi_body, &guess_q, &[], &["position[0]"]).unwrap();
    assert_eq!(held.v.position[0], v[0]);
    let refused = consistent_state_holding(&quasi_body, &guess_q, &[], &["attitude[1]"]);
    assert!(
        matches!(refused, Err(Error::UnsuitableMethod { .. })),
        "{refused:?}"
    );
}

fn quasi_state(q: [f64; N], v: [f64; N]) -> quasi::State {
    quasi::State::new(
        0.0,
        quasi::Coords::from_array(q),
        quasi::Coords::from_array(v),
    )
}
fn rates_state(q: [f64; N], q_dot: [f64; N]) -> rates::State {
    rates::State::new(
        0.0,
        rates::Coords::from_array(q),
        rates::Coords::from_array(q_dot),
    )
}

/// A state as the body's position, two of its axes in the world and ω_b: what two runs whose
/// charts may have switched at different steps are compared by.
fn motion(q: &[f64; N], v: &[f64; N]) -> [f64; 12] {
    let r = rot_mrp(vec3(q[3], q[4], q[5]));
    let (a, b) = (r * vec3(1.0, 0.0, 0.0), r * vec3(0.0, 1.0, 0.0));
    [
        q[0], q[1], q[2], a.x, a.y, a.z, b.x, b.y, b.z, v[3], v[4], v[5],
    ]
}

/// The largest difference between the two motions.
fn apart(a: &[f64; 12], b: &[f64; 12]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0f64, |w, (x, y)| w.max((x - y).abs()))
}

/// 1 s of RK4 on the rod at step `h`, both bodies from the same motion: how far apart they end.
fn rk4_apart(h: f64) -> f64 {
    let (quasi_body, rates_body) = bodies();
    let (q, q_dot) = states()[1];
    let (mut sq, mut sr) = (
        quasi_state(q, velocities_of(&q, &q_dot)),
        rates_state(q, q_dot),
    );
    for _ in 0..(1.0 / h).round() as usize {
        quasi_body.step::<Rk4>(&mut sq, h).unwrap();
        rates_body.step::<Rk4>(&mut sr, h).unwrap();
    }
    let (qr, vr) = (sr.q.to_array(), sr.v.to_array());
    let a = motion(&sq.q.to_array(), &sq.v.to_array());
    apart(&a, &motion(&qr, &velocities_of(&qr, &vr)))
}

/// RK4 steps the angular velocity and the rates body its rates: two discretizations of one
/// motion, each fourth order, so they differ by O(h⁴) — the difference falls about 16 times when
/// h halves (≥ 10 asked: the ratio of two fourth-order errors' leading terms). A conversion
/// wrong anywhere (the solve, the projection after each step) would leave an O(1) gap instead.
#[test]
fn rk4_on_the_rod_converges_to_the_rates_motion() {
    let (coarse, fine) = (rk4_apart(0.02), rk4_apart(0.01));
    assert!(
        coarse < 1e-3 && coarse / fine > 10.0,
        "{coarse:e} then {fine:e}"
    );
}

/// Mode changes as (time, row, new mode).
type Changes = Vec<(f64, usize, RowMode)>;

/// The floor raised under the swinging body: Dopri5 at `tol` from the same motion for 2 s; each
/// body's mode changes (time, row, new mode) and how far apart the two end.
fn impact_run(tol: f64) -> (Changes, Changes, f64) {
    impact_run_in(Dopri5::new(tol, tol))
}

/// [`impact_run`] in `method`.
fn impact_run_in<P: EmbeddedPair + Copy>(method: P) -> (Changes, Changes, f64) {
    let (mut quasi_body, mut rates_body) = bodies();
    (quasi_body.floor, rates_body.floor) = (FLOOR, FLOOR);
    let (q, q_dot) = states()[1];
    let changes = |c: &[ModeChange]| c.iter().map(|c| (c.t, c.row, c.to)).collect::<Vec<_>>();
    let start = quasi_state(q, velocities_of(&q, &q_dot));
    let mut solver = Stepper::new(&quasi_body, method, &start).unwrap();
    let sq = solver.integrate(2.0, &mut [], |_| {}).unwrap().state;
    let changes_q = changes(solver.mode_changes());
    let start = rates_state(q, q_dot);
    let mut solver = Stepper::new(&rates_body, method, &start).unwrap();
    let sr = solver.integrate(2.0, &mut [], |_| {}).unwrap().state;
    let changes_r = changes(solver.mode_changes());
    let (qr, vr) = (sr.q.to_array(), sr.v.to_array());
    let a = motion(&sq.q.to_array(), &sq.v.to_array());
    (
        changes_q,
        changes_r,
        apart(&a, &motion(&qr, &velocities_of(&qr, &vr))),
    )
}

const FLOOR: f64 = -1.15;

/// The body swings down onto the floor: both land on the same corner at the same instant, the
/// contact closes (plastic impact) and holds, and the two motions agree to the solver's error.
/// A tolerance-`tol` run is off the exact motion by a few tol here (about 7 tol apart at 1e-10
/// and 1e-12), so each pair is asked to be within 100 tol, and the gap to fall with the
/// tolerance; a wrong conversion in the impact or the held mode would leave an O(1) gap.
#[test]
fn dopri5_lands_on_the_floor_as_the_rates_body() {
    let mut gaps = Vec::new();
    for tol in [1e-10, 1e-12] {
        let (changes_q, changes_r, gap) = impact_run(tol);
        assert_eq!(changes_q.len(), 1, "{changes_q:?}");
        assert_eq!(changes_r.len(), 1, "{changes_r:?}");
        let ((tq, row_q, to_q), (tr, row_r, to_r)) = (changes_q[0], changes_r[0]);
        assert_eq!((row_q, to_q), (1, RowMode::Active));
        assert_eq!((row_r, to_r), (1, RowMode::Active));
        assert!((tq - tr).abs() <= 100.0 * tol, "impact at {tq} and {tr}");
        assert!(gap <= 100.0 * tol, "{gap:e} apart at tol {tol:e}");
        gaps.push(gap);
    }
    assert!(gaps[1] < gaps[0], "{gaps:?}");
}

/// Radau5 steps the rates between conversions (its stage equations are written for q' = q̇), so
/// on the swinging body it takes the rates body's very steps: it lands on the floor at the same
/// instant (located on the dense output, whose velocities are converted) and the two end
/// together, to the conversions' rounding carried through the run (6e-15 seen; 1e-12 and 1e-11
/// asked).
#[test]
fn radau5_lands_on_the_floor_as_the_rates_body() {
    let (changes_q, changes_r, gap) = impact_run_in(Radau5::new(1e-10, 1e-10));
    assert_eq!(changes_q.len(), 1, "{changes_q:?}");
    assert_eq!(changes_r.len(), 1, "{changes_r:?}");
    let ((tq, row_q, to_q), (tr, ..)) = (changes_q[0], changes_r[0]);
    eprintln!("Radau5: impact at {tq} and {tr}, {gap:e} apart");
    assert_eq!((row_q, to_q), (1, RowMode::Active));
    assert!((tq - tr).abs() <= 1e-12, "impact at {tq} and {tr}");
    assert!(gap <= 1e-11, "{gap:e} apart");
}

/// The methods on momenta conjugate to q̇ step the rates between conversions: on the rod (the
/// floor far below, its contact separated) they take the rates body's steps, to round-off
/// (1e-11 over 100 steps) — the projection after each step included.
macro_rules! steps_as_the_rates {
    ($name:ident, $method:ty) => {
        #[test]
        fn $name() {
            let (quasi_body, rates_body) = bodies();
            let (q, q_dot) = states()[2];
            let mut sq = quasi_state(q, velocities_of(&q, &q_dot));
            let mut sr = rates_state(q, q_dot);
            for _ in 0..100 {
                quasi_body.step::<$method>(&mut sq, 0.01).unwrap();
                rates_body.step::<$method>(&mut sr, 0.01).unwrap();
            }
            let (q1, v1) = (sq.q.to_array(), sq.v.to_array());
            agree(&q1, &sr.q.to_array(), 1e-11, "q");
            agree(&rates_of(&q1, &v1), &sr.v.to_array(), 1e-11, "q̇");
            // Still on the rod.
            let rod = constraint_forces(&quasi_body, &sq).unwrap();
            assert!(rod.multipliers[0] != 0.0);
        }
    };
}

steps_as_the_rates!(gauss_legendre_steps_as_the_rates, GaussLegendre2);
steps_as_the_rates!(implicit_midpoint_steps_as_the_rates, ImplicitMidpoint);
steps_as_the_rates!(variational_steps_as_the_rates, Variational);

/// A floating URDF base whose module adds a contact row: the base has ω for velocities.
#[lagrange::urdf("tests/urdf/quadruped.urdf", floating)]
pub mod standing_quadruped {
    #[unilateral]
    fn above_ground() -> f64 {
        base_position[2]
    }
}

/// Dropped from rest, the quadruped falls rigidly (no joint moves: every body has the same
/// acceleration g), so its base's origin reaches the ground at t* = √(2 z₀ / g) exactly; Dopri5
/// at 1e-12 locates the contact there to the event location's accuracy (1e-9 asked), and the
/// contact holds it on the ground after the plastic impact.
#[test]
fn a_floating_urdf_base_with_contacts_has_angular_velocities() {
    use standing_quadruped::{StandingQuadruped as Robot, DOF};
    let joints = <Robot as RigidTree<DOF, 13>>::JOINTS;
    let kind = JointKind::Free(RotationChart::Mrp, Velocities::AngularVelocity);
    assert_eq!(joints[0].kind, kind);
    let robot = Robot::default();
    let z0 = 0.3;
    let mut q = [0.0; DOF];
    q[2] = z0;
    q[3..6].copy_from_slice(&[0.1, -0.2, 0.15]);
    let start = standing_quadruped::State::new(
        0.0,
        standing_quadruped::Coords::from_array(q),
        standing_quadruped::Coords::from_array([0.0; DOF]),
    );
    let mut solver = Stepper::new(&robot, Dopri5::new(1e-12, 1e-12), &start).unwrap();
    let end = solver.integrate(0.5, &mut [], |_| {}).unwrap().state;
    let landing = (2.0 * z0 / robot.g).sqrt();
    let changes = solver.mode_changes();
    assert_eq!(changes.len(), 1, "{changes:?}");
    assert!(
        (changes[0].t - landing).abs() < 1e-9,
        "{} against {landing}",
        changes[0].t
    );
    assert!(
        end.q.base_position[2].abs() < 1e-9,
        "{:?}",
        end.q.base_position
    );
}

/// The quadruped standing on its base's contact (closed, pressed down by its weight), its joints
/// driven: q̈ of the constrained solve, whose M, 𝓕 and b come from the tree's recursions, against
/// the KKT system solved here on the dense Cartesian pass (`lagrange::dynamics`, which shares no
/// code with the recursions) of the declaration with the same inputs held, in the rates and
/// converted to ω̇. Both are exact formulas in double precision: 1e-10 relative.
#[test]
fn a_driven_standing_quadruped_is_the_dense_kkt_system() {
    use lagrange::inputs::{Inputs, WithInputs};
    use standing_quadruped::{Efforts, StandingQuadruped as Robot, DOF};
    const NU: usize = DOF - 6;
    let robot = Robot::default();
    let joints = <Robot as RigidTree<DOF, 13>>::JOINTS;
    let efforts: [f64; NU] = std::array::from_fn(|i| 0.8 * ((i as f64) * 1.7).sin());
    let mut q: [f64; DOF] = std::array::from_fn(|k| 0.3 * ((k as f64) * 0.7).sin());
    let mut v: [f64; DOF] = std::array::from_fn(|k| 0.5 * ((k as f64) * 1.3).cos());
    // On the ground, not moving through it.
    (q[2], v[2]) = (0.0, 0.0);
    let state = standing_quadruped::State::new(
        0.0,
        standing_quadruped::Coords::from_array(q),
        standing_quadruped::Coords::from_array(v),
    );
    let inputs = Efforts::from_array(efforts);
    let solved = robot
        .driven(&inputs)
        .accelerations(&state)
        .unwrap()
        .to_array();

    let held = WithInputs::<Robot, f64, NU>::new(&robot, efforts);
    let rates = position_rates(&joints, &q, &v);
    let eom = lagrange::dynamics::equations_of_motion(&held, 0.0, &q, &rates);
    // The ground row on the rates: g = z, r = e₂, β = 0 (z is a coordinate).
    let mut kkt = nalgebra::SMatrix::<f64, 19, 19>::zeros();
    kkt.fixed_view_mut::<DOF, DOF>(0, 0)
        .copy_from(&eom.mass_matrix);
    (kkt[(2, DOF)], kkt[(DOF, 2)]) = (-1.0, 1.0);
    let mut rhs = nalgebra::SVector::<f64, 19>::zeros();
    rhs.fixed_rows_mut::<DOF>(0)
        .copy_from(&(eom.generalized_forces - eom.inertial_terms));
    let x = kkt.lu().solve(&rhs).unwrap();
    let qdd: [f64; DOF] = std::array::from_fn(|i| x[i]);
    assert!(x[DOF] > 0.0, "the ground pushes: λ = {}", x[DOF]);
    let b_qdd = velocities_from_rates(&joints, &q, &qdd);
    let bias = velocity_bias(&joints, &q, &rates);
    let expected: [f64; DOF] = std::array::from_fn(|i| b_qdd[i] + bias[i]);
    agree(&solved, &expected, 1e-10, "ω̇ and q̈ of the joints");
}
