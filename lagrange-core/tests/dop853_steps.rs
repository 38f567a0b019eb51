//! Dop853 takes the steps of Hairer's `dop853.f` (E. Hairer and G. Wanner, the code distributed
//! with *Solving ODEs I*): its driver `dr_dop853.f` on Van der Pol's equation, whose published
//! counts this reproduces, and the defaults of its controller.

use lagrange_core::integrate::{
    AccelerationField, DenseOutput, Dop853, EmbeddedPair, Observation, Stats, Stepper,
};
use lagrange_core::{Error, Mechanism, State};
use nalgebra::SMatrix;

mod support;
use support::BlowUp;

/// Van der Pol's equation as `dr_dop853.f` writes it, y₁' = y₂, y₂' = ((1 − y₁²) y₂ − y₁)/ε: a
/// second-order equation q̈ = ((1 − q²) q̇ − q)/ε in q = y₁, so (q, q̇) is the first-order state
/// of `dop853.f` in its order.
struct VanDerPol {
    eps: f64,
}

impl AccelerationField<1> for VanDerPol {
    fn accelerations(
        &self,
        _t: f64,
        q: &[f64; 1],
        v: &[f64; 1],
    ) -> lagrange_core::Result<[f64; 1]> {
        Ok([((1.0 - q[0] * q[0]) * v[0] - q[0]) / self.eps])
    }

    fn jacobians(
        &self,
        _t: f64,
        q: &[f64; 1],
        v: &[f64; 1],
    ) -> lagrange_core::Result<(SMatrix<f64, 1, 1>, SMatrix<f64, 1, 1>)> {
        Ok((
            SMatrix::from([[(-2.0 * q[0] * v[0] - 1.0) / self.eps]]),
            SMatrix::from([[(1.0 - q[0] * q[0]) / self.eps]]),
        ))
    }
}

#[test]
fn defaults_are_those_of_dop853_f() {
    // dop853.f: SAFE = 0.9, FAC1 = 0.333, FAC2 = 6, BETA = 0 unless WORK(2…5) give them.
    let d = Dop853::default();
    assert_eq!(
        (d.safety, d.fac_min, d.fac_max, d.beta),
        (0.9, 0.333, 6.0, 0.0)
    );
}

/// `dr_dop853.f`: ε = 1e-3, y(0) = (2, 0), x_end = 2, RTOL = ATOL = 1e-9, dense output on (IOUT = 2),
/// with the first step given as 1e-6 (WORK(7)); `dop853.f` (version of 2004) prints 1348 accepted
/// and 121 rejected steps, 21553 evaluations (its count adds 2 at the start, one of them for the
/// initial-step routine it skips when WORK(7) is given), y(2) = (1.763234540172087,
/// −0.835688681930191) and a proposed next step of 8.656983588595286e-4 (the output of Hairer's
/// Fortran sources compiled as they are, published with the test data of the `russell` ODE crate).
#[test]
fn van_der_pol_takes_the_steps_of_dr_dop853() {
    let field = VanDerPol { eps: 1e-3 };
    let method = Dop853 {
        h_init: Some(1e-6),
        ..Dop853::new(1e-9, 1e-9)
    };
    let mut stats = Stats::default();
    let (mut t, mut q, mut v) = (0.0, [2.0], [0.0]);
    let mut a = field.accelerations(t, &q, &v).unwrap();
    stats.evaluations += 1;
    let mut memory = method.start(&field, (t, &q, &v, &a), &mut stats);
    let (mut stages, mut dense) = (Dop853::scratch::<1>(), DenseOutput::constant(t, &q, &v));
    let t_end = 2.0;
    while t < t_end {
        let start = (t, &q, &v, &a);
        let step = method
            .step::<[f64; 1], 1>(
                &mut memory,
                &mut stages,
                &field,
                start,
                t_end,
                &mut stats,
                &mut dense,
            )
            .unwrap();
        (t, q, v, a) = (step.t, step.q, step.v, step.a.unwrap());
    }
    assert_eq!(t, t_end);
    assert_eq!((stats.accepted, stats.rejected), (1348, 121), "{stats:?}");
    // One evaluation at the start, 11 per attempt, 1 (FSAL) + 3 (dense output) per accepted step.
    assert_eq!(stats.evaluations, 1 + 11 * (1348 + 121) + 4 * 1348);
    assert_eq!(stats.evaluations + 1, 21553);
    // The same steps with the sums in another order: the end points differ by round-off
    // (ε ≈ 2e-16 per operation) carried along 1348 steps — far below the tolerance of 1e-9 that
    // a different step sequence would show; q̇ ≈ −0.84 comes from a relaxation term of size
    // 1/ε = 1e3 and so carries 1e3 times q's round-off.
    let (y1, y2) = (1.763234540172087, -0.835688681930191);
    assert!(
        (q[0] - y1).abs() < 1e-13 && (v[0] - y2).abs() < 1e-11,
        "{q:?} {v:?}"
    );
    eprintln!(
        "end point {:.2e}, {:.2e} from the Fortran's",
        q[0] - y1,
        v[0] - y2
    );
    // The proposed next step is h·(err/safety)^(−1/8) with err the last step's error estimate, a
    // sum of stage values that cancel to ≈ 1e-9 of their size: its last digits, and so the
    // next step's, depend on the order of the sums (a relative difference of 1e-3 in err moves
    // the step by 1.3e-4).
    let h_next = <Dop853 as EmbeddedPair>::proposed_step::<1>(&memory);
    assert!(
        (h_next / 8.656983588595286e-4 - 1.0).abs() < 1e-3,
        "{h_next}"
    );
}

/// Every step is checked: the blow-up ends the integration with a named error close to the
/// singularity, and the caller's state is left as it was; a non-finite start is refused.
#[test]
fn blow_up_and_non_finite_states_are_named_errors() {
    let start = State::new(0.0, [1.0], [(2.0f64 / 3.0).sqrt()]);
    let mut solver = Stepper::new(&BlowUp, Dop853::new(1e-8, 1e-8), &start).unwrap();
    let mut last_t = 0.0;
    let err = solver
        .integrate(5.0, &mut [], |o| {
            if let Observation::Step { state, .. } = o {
                last_t = state.t
            }
        })
        .unwrap_err();
    assert!(
        matches!(
            err,
            Error::NonFiniteState { .. }
                | Error::NonFiniteDynamics { .. }
                | Error::StepSizeUnderflow { .. }
        ),
        "{err}"
    );
    // q = 6/(t − √6)² reaches 1e8 (the tolerance's reciprocal) 2.4e-4 before the singularity;
    // the steps then shrink below round-off of t.
    assert!((last_t - 6f64.sqrt()).abs() < 1e-3, "{last_t}");
    // The solver stays at the last step it took.
    assert_eq!(solver.state().t, last_t);

    let mut s = State::new(0.0, [f64::NAN], [0.0]);
    let err = BlowUp.step::<Dop853>(&mut s, 0.1).unwrap_err();
    assert!(matches!(err, Error::NonFiniteState { .. }), "{err}");
    assert!(s.q[0].is_nan() && s.v[0] == 0.0);
}

/// A right-hand side that turns non-finite within a step: the trial's new point is refused
/// (`NonFiniteState`) and the step shrinks towards it until it cannot, then reports that error.
#[test]
fn a_non_finite_right_hand_side_is_refused_at_every_step() {
    /// q̈ = 1 for q < 1, NaN beyond.
    struct Cliff;
    impl AccelerationField<1> for Cliff {
        fn accelerations(
            &self,
            _t: f64,
            q: &[f64; 1],
            _v: &[f64; 1],
        ) -> lagrange_core::Result<[f64; 1]> {
            Ok([if q[0] < 1.0 { 1.0 } else { f64::NAN }])
        }
        fn jacobians(
            &self,
            _t: f64,
            _q: &[f64; 1],
            _v: &[f64; 1],
        ) -> lagrange_core::Result<(SMatrix<f64, 1, 1>, SMatrix<f64, 1, 1>)> {
            Ok((SMatrix::zeros(), SMatrix::zeros()))
        }
    }
    let method = Dop853::new(1e-8, 1e-8);
    let mut stats = Stats::default();
    let (mut t, mut q, mut v, mut a) = (0.0, [0.0], [0.0], [1.0]);
    let mut memory = method.start(&Cliff, (t, &q, &v, &a), &mut stats);
    let (mut stages, mut dense) = (Dop853::scratch::<1>(), DenseOutput::constant(t, &q, &v));
    let err = loop {
        let start = (t, &q, &v, &a);
        match method.step::<[f64; 1], 1>(
            &mut memory,
            &mut stages,
            &Cliff,
            start,
            10.0,
            &mut stats,
            &mut dense,
        ) {
            Ok(step) => {
                assert!(step.q[0] < 1.0 && step.q[0].is_finite(), "{step:?}");
                (t, q, v, a) = (step.t, step.q, step.v, step.a.unwrap());
            }
            Err(e) => break e,
        }
    };
    assert!(
        matches!(
            err,
            Error::NonFiniteState { .. } | Error::StepSizeUnderflow { .. }
        ),
        "{err}"
    );
    // q = t²/2 reaches 1 at t = √2; the last accepted point is just before it.
    assert!(t < 2f64.sqrt() && t > 1.3, "{t}");
}
