//! A stiff case: a lander on a unilateral floor, its leg a stiff, damped spring.

use super::contact_scenes::G;
use lagrange::constraints::RowMode;
use lagrange::prelude::*;

/// A lander: a foot of mass m₁ on the floor (unilateral), a top mass m₂ above it on a spring of
/// stiffness k and rest length l with a damper c between them: a stiff, overdamped leg.
#[mechanism]
pub mod lander {
    pub struct Coords {
        pub foot: f64,
        pub top: f64,
    }

    pub struct Lander {
        pub m1: f64,
        pub m2: f64,
        pub k: f64,
        pub c: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn foot_mass() -> Vec2 {
        vec2(0.0, foot)
    }

    #[particle(mass = m2)]
    fn top_mass() -> Vec2 {
        vec2(0.0, top)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[potential]
    fn leg_spring() -> f64 {
        (top - foot - l) * (top - foot - l) * (0.5 * k)
    }

    /// The damper's force −c·(ṫop − ḟoot) on the top, its reaction on the foot.
    #[generalized_force(on = top)]
    fn damper_on_top() -> f64 {
        (top_dot - foot_dot) * (-c)
    }

    #[generalized_force(on = foot)]
    fn damper_on_foot() -> f64 {
        (top_dot - foot_dot) * c
    }

    #[unilateral]
    fn floor() -> f64 {
        foot
    }
}

/// The lander's parameters: a stiff (k = 10⁶ N/m), heavily overdamped (c = 2·10⁴ N·s/m) leg; its
/// relative motion has the rates s² + (c/μ)s + k/μ = 0 with μ = m₁m₂/(m₁ + m₂) in flight, and
/// s² + (c/m₂)s + k/m₂ = 0 on the floor: s ≈ −2·10⁴ (stiff) and −k/c = −50 s⁻¹.
pub(super) const LANDER: lander::Lander = lander::Lander {
    m1: 1.0,
    m2: 1.0,
    k: 1e6,
    c: 2e4,
    l: 0.5,
    g: G,
};

#[test]
fn stiff_lander_settles_on_a_unilateral_floor_in_radau5() {
    use lander::{Coords, State};
    let sys = LANDER;
    let height = 0.4;
    // Released at rest with the leg at its rest length: in free fall it stays so (both masses
    // accelerate at g), and the foot lands at √(2h/g).
    let start = State::new(
        0.0,
        Coords {
            foot: height,
            top: height + sys.l,
        },
        Coords {
            foot: 0.0,
            top: 0.0,
        },
    );
    let t_end = 1.0;
    let run_radau = |tol: f64| {
        let mut solver = Stepper::new(&sys, Radau5::new(tol, tol), &start).expect("solver");
        solver.integrate(t_end, &mut [], |_| {}).expect("Radau5");
        (
            solver.state(),
            solver.mode_changes().to_vec(),
            solver.stats(),
        )
    };
    let run_dopri = |tol: f64| {
        let mut solver = Stepper::new(&sys, Dopri5::new(tol, tol), &start).expect("solver");
        solver.integrate(t_end, &mut [], |_| {}).expect("Dopri5");
        (
            solver.state(),
            solver.mode_changes().to_vec(),
            solver.stats(),
        )
    };
    let (reference, ref_events, ref_stats) = run_dopri(1e-12);
    let t_land = (2.0 * height / G).sqrt();
    // On the floor the top relaxes to the static compression m₂g/k at the rate k/c = 50 s⁻¹: by
    // t = 1 s (0.55 s after the landing) the deviation is e^{−27.5} ≈ 1e-12 of the ≈ 1.5e-4 m
    // compression reached: at rest to round-off.
    let rest_top = sys.l - sys.m2 * G / sys.k;
    eprintln!(
        "reference ContactDopri5 1e-12: {:?} {ref_stats:?}\n    top {:.15} (rest {rest_top:.15})",
        ref_events, reference.q.top
    );
    assert_eq!(
        ref_events.len(),
        1,
        "the foot lands and stays: {ref_events:?}"
    );
    // The reference at rest at the closed-form equilibrium, to its own tolerance (its deviation
    // from equilibrium decayed to e^{−27.5}·1.5e-4 m ≈ 2e-16 m).
    assert!((reference.q.top - rest_top).abs() < 1e-12 && reference.v.top.abs() < 1e-12);
    for tol in [1e-6, 1e-8, 1e-10] {
        let (s, events, stats) = run_radau(tol);
        let (_, _, dopri) = run_dopri(tol);
        let (dq, dv) = (
            (s.q.top - reference.q.top)
                .abs()
                .max((s.q.foot - reference.q.foot).abs()),
            (s.v.top - reference.v.top)
                .abs()
                .max((s.v.foot - reference.v.foot).abs()),
        );
        eprintln!(
            "tol {tol:.0e}: landed at {:+.1e} from √(2h/g); end state off the reference by \
             {dq:.1e} m, {dv:.1e} m/s\n    ContactRadau5 {stats:?}\n    ContactDopri5 {dopri:?}",
            events[0].t - t_land
        );
        // The fall is a quadratic (the leg at rest length): landing to the root finder's 1e-13.
        assert_eq!(events.len(), 1, "{events:?}");
        assert_eq!(
            (events[0].from, events[0].to),
            (RowMode::Inactive, RowMode::Active)
        );
        assert!((events[0].t - t_land).abs() < 1e-12);
        // At the static equilibrium at t_end (the reference's state, which is there to
        // round-off): Radau5's error control holds each component's error to about
        // tol·(1 + |y|) (|y| ≤ 3 here; HW II §IV.8 for the conversion of the tolerances), and on
        // the floor every error decays with the leg's motion (at 50 s⁻¹ or, for the stiff mode,
        // faster, which the L-stable method damps). Asserted: within 4·tol of the reference in
        // position and velocity, the foot on the floor to the projection's round-off.
        assert!(
            s.q.foot.abs() < 1e-12,
            "the foot on the floor: {}",
            s.q.foot
        );
        assert!(dq < 4.0 * tol && dv < 4.0 * tol, "{dq:e} {dv:e}");
        // The stiff mode (−2·10⁴ s⁻¹) bounds Dopri5's step by its stability, ≈ 3.3/2·10⁴ s,
        // whatever the tolerance; Radau5 follows the slow motion.
        assert!(
            5 * (stats.accepted + stats.rejected) < dopri.accepted + dopri.rejected,
            "Radau5 {stats:?} against Dopri5 {dopri:?}"
        );
    }
}

#[test]
fn stiff_lander_with_a_critically_damped_leg_hops_once_in_radau5() {
    use lander::{Coords, Lander, State};
    // The leg critically damped (c = 2√(k m₂) = 2000 N·s/m) on the floor: as the top rebounds
    // after the landing, the leg pulls the foot up harder than the weights hold it down (the
    // contact force reaches zero), the foot lifts off, flies a few centimetres' worth of time and
    // lands again for good. Three events, each against a ContactDopri5 run at 1e-12: a release
    // during a stiff transient (rates up to 10³ s⁻¹) and two impacts.
    let sys = Lander { c: 2e3, ..LANDER };
    let start = State::new(
        0.0,
        Coords {
            foot: 0.4,
            top: 0.9,
        },
        Coords {
            foot: 0.0,
            top: 0.0,
        },
    );
    let mut reference = Stepper::new(&sys, Dopri5::new(1e-12, 1e-12), &start).expect("solver");
    reference
        .integrate(1.0, &mut [], |_| {})
        .expect("reference");
    let modes = [RowMode::Active, RowMode::Inactive, RowMode::Active];
    let reference_modes: Vec<RowMode> = reference.mode_changes().iter().map(|e| e.to).collect();
    assert_eq!(reference_modes, modes, "{:?}", reference.mode_changes());
    for tol in [1e-6, 1e-8, 1e-10] {
        let mut solver = Stepper::new(&sys, Radau5::new(tol, tol), &start).expect("solver");
        let outcome = solver.integrate(1.0, &mut [], |_| {}).expect("Radau5");
        let events = solver.mode_changes();
        eprintln!(
            "tol {tol:.0e}: events {:?} (reference {:?}); {:?}",
            events.iter().map(|e| e.t).collect::<Vec<_>>(),
            reference
                .mode_changes()
                .iter()
                .map(|e| e.t)
                .collect::<Vec<_>>(),
            outcome.stats
        );
        assert_eq!(events.iter().map(|e| e.to).collect::<Vec<_>>(), modes);
        // Each event time is off by the solution's error at it divided by the event function's
        // rate: for the impacts the gap c = foot, whose error Radau5 holds to about
        // tol·(1 + |y|) ≤ 1.5·tol, over the landing speed (3.1 m/s, then 0.167 m/s for the hop's
        // landing, leg and foot moving together by then); the release's λ moves at the stiff
        // leg's rate, far faster. So ≤ 1.5/0.167·tol < 10·tol, plus the
        // reference's own error at 1e-12 (1e-10 with the same argument).
        for (e, r) in events.iter().zip(reference.mode_changes()) {
            assert!(
                (e.t - r.t).abs() < 10.0 * tol + 1e-10,
                "tol {tol:.0e}: {} against {}",
                e.t,
                r.t
            );
        }
        // At rest at the end, as the reference (see the settling lander above).
        let (s, r) = (solver.state(), reference.state());
        assert!(s.q.foot.abs() < 1e-12);
        assert!((s.q.top - r.q.top).abs() < 4.0 * tol && (s.v.top - r.v.top).abs() < 4.0 * tol);
    }
}
