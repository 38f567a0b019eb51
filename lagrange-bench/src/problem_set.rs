//! The report's seven problems as [`Setup`]s, in the report's order: start, end time, reference
//! end state (closed form, or two methods at high precision that check each other) and the ladders
//! of step numbers and tolerances.

use crate::kepler::KEPLER;
use crate::pendulums::*;
use crate::problems::*;
use crate::setup::{distance, in_coordinates, Problem, Setup};
use crate::stiff::*;
use lagrange_core::integrate::Stepper;
use lagrange_core::{Coordinates, Dopri5, GaussLegendre2, Mechanism, State};

/// The problems, and how well the references computed by integration agree.
pub struct ProblemSet {
    /// In the report's order.
    pub problems: Vec<Box<dyn Problem>>,
    /// Max-norm distance of the double pendulum's two references at its end time.
    pub double_pendulum_references: f64,
    /// Max-norm distance of the FPU chain's two references at its end time.
    pub fpu_references: f64,
}

/// The problems with the full ladders, or the short ones of `--quick`.
pub fn build(quick: bool) -> ProblemSet {
    let n_ladder = if quick { 4 } else { 8 };
    let pendulum = pendulum(quick, n_ladder);
    let kepler = kepler(quick, n_ladder);
    let (double, double_pendulum_references) = double_pendulum(quick, n_ladder);
    let (fpu, fpu_references) = fpu(quick, n_ladder);
    let wedge = wedge(quick);
    let chain = stiff_chain(quick, n_ladder);
    let cartesian = cartesian_pendulum(quick, n_ladder);
    ProblemSet {
        problems: vec![pendulum, kepler, double, fpu, wedge, chain, cartesian],
        double_pendulum_references,
        fpu_references,
    }
}

/// `count` numbers of steps, doubling from `start`.
fn ladder(start: usize, count: usize) -> Vec<usize> {
    (0..count).map(|k| start << k).collect()
}

/// The adaptive methods' tolerances, the same for every method and peer: half-decades from 1e-3
/// to 1e-13 (so that the cheapest run reaching an accuracy is not decided by where a decade grid
/// falls for each method), or four decades with `--quick`.
fn tolerances(quick: bool) -> Vec<f64> {
    if quick {
        return [4, 7, 10, 13].map(|e| 10f64.powi(-e)).to_vec();
    }
    // 10^(−k/2): the decades as 10^(−k/2) by powi, the half-decades those divided by √10.
    (6..=26)
        .map(|k: i32| {
            let decade = 10f64.powi(-(k / 2));
            if k % 2 == 0 {
                decade
            } else {
                decade / 10f64.sqrt()
            }
        })
        .collect()
}

/// The reference end state at `t_end` by Dopri5 at tol 1e-14, and its max-norm distance from
/// Gauss–Legendre 2's with 2^17 steps (the check of the reference).
fn reference_by_two_methods<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    start: &State<[f64; N]>,
    t_end: f64,
) -> (([f64; N], [f64; N]), f64) {
    let dopri5 = Stepper::new(
        mechanism,
        Dopri5::new(1e-14, 1e-14),
        &in_coordinates::<M, N>(start),
    )
    .and_then(|mut r| r.integrate(t_end, &mut [], |_| {}))
    .expect("reference")
    .state;
    let mut gauss = in_coordinates::<M, N>(start);
    let n = 1 << 17;
    for _ in 0..n {
        mechanism
            .step::<GaussLegendre2>(&mut gauss, t_end / n as f64)
            .expect("reference");
    }
    let dopri5 = (dopri5.q.to_array(), dopri5.v.to_array());
    let gauss = (gauss.q.to_array(), gauss.v.to_array());
    (dopri5, distance(&dopri5.0, &dopri5.1, &gauss))
}

/// One period 4K(k) of the pendulums with modulus k = 0.999.
fn pendulum_period() -> f64 {
    4.0 * elliptic_k(PENDULUM_K)
}

/// Problem 1: large-amplitude pendulum over one period 4K(k).
fn pendulum(quick: bool, n_ladder: usize) -> Box<dyn Problem> {
    let period = pendulum_period();
    Box::new(Setup::<_, 1, 2> {
        name: "pendulum k=0.999",
        mechanism: PENDULUM.validated().expect("valid parameters"),
        start: State::new(0.0, [0.0], [2.0 * PENDULUM_K]),
        t_end: period,
        reference: pendulum_exact(period),
        rhs: pendulum_rhs,
        steps: ladder(200, n_ladder),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
        peers_checked: false,
    })
}

/// Problem 2: Kepler e = 0.6 over 5 periods.
fn kepler(quick: bool, n_ladder: usize) -> Box<dyn Problem> {
    Box::new(Setup::<_, 2, 4> {
        name: "Kepler e=0.6",
        mechanism: KEPLER.validated().expect("valid parameters"),
        start: kepler_start(),
        t_end: 10.0 * std::f64::consts::PI,
        reference: kepler_exact(10.0 * std::f64::consts::PI),
        rhs: kepler_rhs,
        steps: ladder(250, n_ladder + 1),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
        peers_checked: true,
    })
}

/// Problem 3: double pendulum, both arms horizontal at rest, to t = 10; reference by two methods
/// (returned with their distance).
fn double_pendulum(quick: bool, n_ladder: usize) -> (Box<dyn Problem>, f64) {
    let start = State::new(0.0, [std::f64::consts::FRAC_PI_2; 2], [0.0; 2]);
    let t_end = 10.0;
    let (reference, agreement) = reference_by_two_methods(&DOUBLE_PENDULUM, &start, t_end);
    let setup = Setup::<_, 2, 4> {
        name: "double pendulum",
        mechanism: DOUBLE_PENDULUM.validated().expect("valid parameters"),
        start,
        t_end,
        reference,
        rhs: double_pendulum_rhs,
        steps: ladder(250, n_ladder),
        tolerances: tolerances(quick),
        verlet: false,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
        peers_checked: true,
    };
    (Box::new(setup), agreement)
}

/// Problem 4: FPU chain to t = 10 (hω = 2 at n = 250); reference by two methods (returned with
/// their distance).
fn fpu(quick: bool, n_ladder: usize) -> (Box<dyn Problem>, f64) {
    let t_end = 10.0;
    let (reference, agreement) = reference_by_two_methods(&FPU, &fpu_start(), t_end);
    let setup = Setup::<_, 6, 12> {
        name: "FPU chain w=50",
        mechanism: FPU.validated().expect("valid parameters"),
        start: fpu_start(),
        t_end,
        reference,
        rhs: fpu_rhs,
        steps: ladder(100, n_ladder + 1),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 1.0,
        peers_checked: true,
    };
    (Box::new(setup), agreement)
}

/// Problem 5: wedge and block until shortly before the block reaches the floor.
fn wedge(quick: bool) -> Box<dyn Problem> {
    let t_end = 0.9 * wedge_floor_time();
    Box::new(Setup::<_, 2, 4> {
        name: "wedge and block",
        mechanism: WedgeBlock.validated().expect("valid parameters"),
        start: State::new(0.0, [0.0, 0.0], [0.0, 0.0]),
        t_end,
        reference: wedge_exact(t_end),
        rhs: wedge_rhs,
        steps: ladder(10, if quick { 3 } else { 5 }),
        tolerances: tolerances(true),
        verlet: true,
        constrained: false,
        jacobian_times: None,
        unstable_energy: 10.0,
        peers_checked: false,
    })
}

/// Problem 6: stiff chain (ω up to 2613) along its slow mode to t = 10: closed form.
fn stiff_chain(quick: bool, n_ladder: usize) -> Box<dyn Problem> {
    let t_end = 10.0;
    Box::new(Setup::<_, 4, 8> {
        name: "stiff chain w=2613",
        mechanism: CHAIN.validated().expect("valid parameters"),
        start: chain_start(),
        t_end,
        reference: chain_exact(t_end),
        rhs: chain_rhs,
        steps: ladder(25, n_ladder + 2),
        tolerances: tolerances(quick),
        verlet: true,
        constrained: false,
        jacobian_times: Some(chain_jacobian_times),
        unstable_energy: 10.0,
        peers_checked: true,
    })
}

/// Problem 7: Cartesian pendulum (one constraint) over one period 4K(k): closed form.
fn cartesian_pendulum(quick: bool, n_ladder: usize) -> Box<dyn Problem> {
    let period = pendulum_period();
    Box::new(Setup::<_, 2, 4> {
        name: "Cartesian pendulum k=0.999",
        mechanism: ROD.validated().expect("valid parameters"),
        start: cartesian_start(),
        t_end: period,
        reference: cartesian_exact(period),
        rhs: cartesian_rhs,
        steps: ladder(200, n_ladder),
        tolerances: tolerances(quick),
        verlet: false,
        constrained: true,
        jacobian_times: None,
        unstable_energy: 10.0,
        peers_checked: true,
    })
}
