//! Every integrator step is allocation-free: a counting global allocator records the allocations
//! made by this thread while stepping, and there must be none.

use lagrange_core::integrate::{Direction, Event, Observation, Radau5, Stepper};
use lagrange_core::{
    vec2, Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Model, Rk4, Scalar,
    State, StormerVerlet, Variational,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = COUNTING.try_with(|c| {
            if c.get() {
                let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
            }
        });
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = COUNTING.try_with(|c| {
            if c.get() {
                let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
            }
        });
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations made by this thread while running `f`.
fn allocations(f: impl FnOnce()) -> usize {
    ALLOCATIONS.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.with(|n| n.get())
}

/// Kepler problem, V = −1/r (constant mass matrix: every method applies).
struct Kepler;

impl Model<2, 2> for Kepler {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        -(x[0] * x[0] + x[1] * x[1]).sqrt().recip()
    }
}
lagrange_core::impl_mechanism!(Kepler, 2, 2);

/// Double pendulum with joint damping (a q-dependent mass matrix and a non-conservative force).
struct DampedDoublePendulum;

impl Model<2, 4> for DampedDoublePendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 4] {
        [1.0; 4]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let bob1 = vec2(q[0].sin(), -q[0].cos());
        let bob2 = bob1 + vec2(q[1].sin(), -q[1].cos());
        [bob1.x, bob1.y, bob2.x, bob2.y]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        x[1] + x[3]
    }
    fn applied_forces<S: Scalar>(
        &self,
        _t: S,
        _q: &[S; 2],
        v: &[S; 2],
        _x: &[S; 4],
        _x_dot: &[S; 4],
        _cartesian_force: &mut [S; 4],
        generalized_force: &mut [S; 2],
    ) {
        generalized_force[0] -= v[0] * 0.1;
        generalized_force[1] -= v[1] * 0.1;
    }
}
lagrange_core::impl_mechanism!(DampedDoublePendulum, 2, 4);

/// The pendulum in Cartesian coordinates with its rod as a holonomic constraint: RATTLE.
struct CartesianPendulum;

impl Model<2, 2> for CartesianPendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * D::from(9.81)
    }
}

impl lagrange_core::constraints::Constraints<2, 2, 1> for CartesianPendulum {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [lagrange_core::constraints::ConstraintKind; 1] =
        [lagrange_core::constraints::ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - D::from(1.0)]
    }
}
lagrange_core::impl_mechanism!(CartesianPendulum, 2, 2, constraints);

fn steps_without_allocating<I: Integrator, M: Mechanism<N, Coords = [f64; N]>, const N: usize>(
    m: &M,
    start: State<[f64; N]>,
) {
    let mut s = start;
    I::step(m, &mut s, 1e-2).unwrap(); // warm-up
    let n = allocations(|| {
        for _ in 0..200 {
            I::step(m, &mut s, 1e-2).unwrap();
        }
    });
    assert_eq!(n, 0, "{} allocated {n} times in 200 steps", I::NAME);
}

#[test]
fn every_integrator_steps_without_allocating() {
    // Sanity check of the counter itself.
    assert!(allocations(|| drop(std::hint::black_box(vec![1u8; 16]))) >= 1);

    let kepler = State::new(0.0, [0.4, 0.0], [0.0, 2.0]);
    let pendulum = State::new(0.0, [1.0, -0.5], [0.0, 0.0]);
    steps_without_allocating::<Rk4, _, 2>(&Kepler, kepler);
    steps_without_allocating::<ImplicitMidpoint, _, 2>(&Kepler, kepler);
    steps_without_allocating::<GaussLegendre2, _, 2>(&Kepler, kepler);
    steps_without_allocating::<Variational, _, 2>(&Kepler, kepler);
    steps_without_allocating::<StormerVerlet, _, 2>(&Kepler, kepler);
    steps_without_allocating::<Rk4, _, 2>(&DampedDoublePendulum, pendulum);
    steps_without_allocating::<ImplicitMidpoint, _, 2>(&DampedDoublePendulum, pendulum);
    steps_without_allocating::<GaussLegendre2, _, 2>(&DampedDoublePendulum, pendulum);
    steps_without_allocating::<Variational, _, 2>(&DampedDoublePendulum, pendulum);
    // RATTLE: the position stage's Newton iteration and the velocity projection.
    let on_rod = State::new(0.0, [0.6, -0.8], [0.8, 0.6]);
    steps_without_allocating::<StormerVerlet, _, 2>(&CartesianPendulum, on_rod);
    steps_without_allocating::<Variational, _, 2>(&CartesianPendulum, on_rod);
    steps_without_allocating::<GaussLegendre2, _, 2>(&CartesianPendulum, on_rod);

    // Dopri5: a whole integration with events (one terminal) and an observer.
    let settings = Dopri5::new(1e-9, 1e-9);
    let g_cross = |s: &State<[f64; 2]>| s.q[1];
    let g_late = |s: &State<[f64; 2]>| s.t - 15.0;
    let mut observed = 0usize;
    let mut hits = 0usize;
    let mut s = kepler;
    let n = allocations(|| {
        let mut events = [
            Event::new(&g_cross),
            Event::new(&g_late).direction(Direction::Rising).terminal(),
        ];
        let out = Stepper::new(&Kepler, settings, &s)
            .unwrap()
            .integrate(20.0, &mut events, |o| match o {
                Observation::Step { .. } => observed += 1,
                Observation::Event(_) => hits += 1,
            })
            .unwrap();
        s = out.state;
    });
    assert_eq!(n, 0, "a Dopri5 integration allocated {n} times");
    assert!(
        observed > 10 && hits == 5,
        "{observed} steps, {hits} events"
    );

    // Dopri5 step by step, with dense output.
    let mut stepper = Stepper::new(&DampedDoublePendulum, settings, &pendulum).unwrap();
    stepper.step(10.0).unwrap();
    let n = allocations(|| {
        while stepper.t() < 10.0 {
            stepper.step(10.0).unwrap();
            std::hint::black_box(
                stepper
                    .dense()
                    .eval(stepper.t() - 0.5 * stepper.last_step()),
            );
        }
    });
    assert_eq!(n, 0, "a Dopri5 step allocated {n} times");

    // Radau5 step by step (Jacobian, factorisations, Newton iterations) and a whole integration
    // with an event.
    let mut stepper =
        Stepper::new(&DampedDoublePendulum, Radau5::new(1e-8, 1e-8), &pendulum).unwrap();
    stepper.step(10.0).unwrap();
    let n = allocations(|| {
        while stepper.t() < 10.0 {
            stepper.step(10.0).unwrap();
            std::hint::black_box(stepper.dense().eval(stepper.t()));
        }
    });
    assert_eq!(n, 0, "a Radau5 step allocated {n} times");
    assert!(stepper.stats().factorizations > 1 && stepper.stats().jacobians >= 1);
    let mut s = kepler;
    let n = allocations(|| {
        let mut events = [Event::new(&g_cross)];
        let out = Stepper::new(&Kepler, Radau5::new(1e-8, 1e-8), &s)
            .unwrap()
            .integrate(20.0, &mut events, |_| {})
            .unwrap();
        s = out.state;
    });
    assert_eq!(n, 0, "a Radau5 integration allocated {n} times");
}

/// A particle sliding on a floor y ≥ 0 that can only push.
struct SlidingOnFloor;

impl Model<2, 2> for SlidingOnFloor {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * D::from(9.81) + x[0] * x[0] * D::from(0.5)
    }
}

impl lagrange_core::constraints::Constraints<2, 2, 1> for SlidingOnFloor {
    const NAMES: [&'static str; 1] = ["floor"];
    const KINDS: [lagrange_core::constraints::ConstraintKind; 1] =
        [lagrange_core::constraints::ConstraintKind::Unilateral];
    fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 2], _x: &[D; 2]) -> [D; 1] {
        [q[1]]
    }
}
lagrange_core::impl_mechanism!(SlidingOnFloor, 2, 2, constraints);

#[test]
fn the_adaptive_contact_solver_steps_without_allocating() {
    // In contact (λ = g > 0) and oscillating along the floor on a spring: steps without a mode
    // change, each with its event functions, the projection and the dense output.
    let start = State::new(0.0, [1.0, 0.0], [0.0, 0.0]);
    let settings = Dopri5::new(1e-9, 1e-9);
    let mut solver = Stepper::new(&SlidingOnFloor, settings, &start).unwrap();
    solver.step(10.0).unwrap();
    let n = allocations(|| {
        while solver.t() < 10.0 {
            solver.step(10.0).unwrap();
            std::hint::black_box(solver.dense().eval(solver.t()));
        }
    });
    assert_eq!(n, 0, "a Dopri5 step holding a contact allocated {n} times");
    assert!(solver.mode_changes().is_empty() && solver.stats().accepted > 10);
}

#[test]
fn the_implicit_contact_solver_steps_without_allocating() {
    // The same run in Radau5: Jacobians of the mode's accelerations by dual numbers,
    // factorisations and Newton iterations, the event functions and the projection.
    let start = State::new(0.0, [1.0, 0.0], [0.0, 0.0]);
    let settings = Radau5::new(1e-9, 1e-9);
    let mut solver = Stepper::new(&SlidingOnFloor, settings, &start).unwrap();
    solver.step(10.0).unwrap();
    let n = allocations(|| {
        while solver.t() < 10.0 {
            solver.step(10.0).unwrap();
            std::hint::black_box(solver.dense().eval(solver.t()));
        }
    });
    assert_eq!(n, 0, "a Radau5 step holding a contact allocated {n} times");
    assert!(solver.mode_changes().is_empty() && solver.stats().accepted > 10);
}
