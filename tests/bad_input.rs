//! The bad-input matrix: every public entry point of four mechanisms (unconstrained, holonomic,
//! unilateral, unilateral with friction), with one input at a time replaced by NaN, ±∞, ±1e300, 0,
//! −1 or the smallest subnormal — each state component, each parameter, the step size and each
//! option. Every case must be a typed error or an `Ok` whose numbers are all finite, never a panic,
//! and an error must leave the caller's state bit for bit as it was. The table of counts is printed
//! (`cargo test --test bad_input -- --nocapture`).

use lagrange::analysis::{
    constrained_equilibrium, equilibrium, linearize, normal_modes, stability, unbalanced_forces,
    EquilibriumOptions,
};
use lagrange::constraints::{
    consistent_state, consistent_state_holding, constraint_forces, Constraints, ContactOptions,
};
use lagrange::integrate::Method;
use lagrange::model::Model;
use lagrange::prelude::*;
use lagrange::{Dopri5, GaussLegendre2, ImplicitMidpoint, StormerVerlet, Variational};
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum;
use lagrange_gallery::scenes::double_pendulum::double_pendulum;
use lagrange_gallery::scenes::rough_ramp::rough_ramp;
use lagrange_gallery::scenes::sphere_release::sphere_release as sphere;
use std::fmt::Debug;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Mutex;

/// The bad values: NaN, ±∞, huge of both signs, zero, a plain negative, the smallest subnormal.
const BAD: [f64; 8] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e300,
    -1e300,
    0.0,
    -1.0,
    5e-324,
];

/// A parameter of a mechanism: its name and where it lives in the parameter struct.
type Parameter<P> = (&'static str, fn(&mut P) -> &mut f64);

/// What one case did.
enum Outcome {
    /// A typed error; whether the caller's state changed.
    Error { state_changed: bool },
    /// `Ok`; whether every number in it (and in the state it wrote) is finite.
    Ok { finite: bool },
}

#[derive(Default)]
struct Tally {
    cases: usize,
    typed_errors: usize,
    finite_ok: usize,
    panics: usize,
    silent_non_finite: usize,
    state_changed: usize,
    failures: Vec<String>,
}

/// Panic messages caught by `catch_unwind`, recorded by the panic hook.
static PANICS: Mutex<Vec<String>> = Mutex::new(Vec::new());

impl Tally {
    fn run(&mut self, label: impl Fn() -> String, case: impl FnOnce() -> Outcome) {
        self.cases += 1;
        match catch_unwind(AssertUnwindSafe(case)) {
            Err(_) => {
                self.panics += 1;
                let message = PANICS.lock().unwrap().pop().unwrap_or_default();
                self.failures.push(format!("PANIC {}: {message}", label()));
            }
            Ok(Outcome::Error { state_changed }) => {
                self.typed_errors += 1;
                if state_changed {
                    self.state_changed += 1;
                    self.failures.push(format!("STATE CHANGED {}", label()));
                }
            }
            Ok(Outcome::Ok { finite }) => {
                if finite {
                    self.finite_ok += 1;
                } else {
                    self.silent_non_finite += 1;
                    self.failures.push(format!("NON-FINITE OK {}", label()));
                }
            }
        }
    }
}

/// Whether a `Debug` rendering holds no NaN or infinity (every float of the value is printed).
fn all_finite(value: &impl Debug) -> bool {
    let text = format!("{value:?}");
    !text
        .split(|c: char| !c.is_ascii_alphanumeric())
        .any(|token| token == "NaN" || token == "inf")
}

/// An `Ok` judged by [`all_finite`], or an error with the state unchanged (for entry points that
/// do not write a state).
fn pure<T: Debug>(result: lagrange::Result<T>) -> Outcome {
    match result {
        Ok(value) => Outcome::Ok {
            finite: all_finite(&value),
        },
        Err(_) => Outcome::Error {
            state_changed: false,
        },
    }
}

fn bits<C: Coordinates<N>, const N: usize>(s: &State<C>) -> Vec<u64> {
    std::iter::once(s.t)
        .chain(s.q.to_array())
        .chain(s.v.to_array())
        .map(f64::to_bits)
        .collect()
}

/// Runs `step` on a copy of `state`: an `Ok` must leave a finite state that moved forward in
/// time, an error the state bit for bit as it was.
fn stepping<C: Coordinates<N>, const N: usize, T>(
    state: &State<C>,
    step: impl FnOnce(&mut State<C>) -> lagrange::Result<T>,
) -> Outcome {
    let mut s = *state;
    let before = bits(&s);
    match step(&mut s) {
        Ok(_) => Outcome::Ok {
            finite: all_finite(&s) && (s.t > state.t || s.t == state.t && bits(&s) == before),
        },
        Err(_) => Outcome::Error {
            state_changed: bits(&s) != before,
        },
    }
}

/// The settings under test, one of which may be bad.
#[derive(Clone, Copy, Debug)]
struct Settings {
    h: f64,
    dopri5: Dopri5,
    radau5: Radau5,
    equilibrium: EquilibriumOptions,
    contact: ContactOptions,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            h: 1e-3,
            // A short budget: some bad cases (tolerances of 5e-324) would otherwise take the default
            // million steps in a debug build.
            dopri5: Dopri5 {
                max_steps: 40,
                ..Dopri5::default()
            },
            radau5: Radau5 {
                max_steps: 40,
                ..Radau5::default()
            },
            equilibrium: EquilibriumOptions::default(),
            contact: ContactOptions::default(),
        }
    }
}

/// Every entry point of any mechanism.
fn mechanism_cases<M: Mechanism<N> + Debug, const N: usize>(
    tally: &mut Tally,
    what: &dyn Fn() -> String,
    sys: &M,
    s: &State<M::Coords>,
    set: &Settings,
) {
    let label = |entry: &str| format!("{} / {entry}", what());
    tally.run(|| label("accelerations"), || pure(sys.accelerations(s)));
    tally.run(|| label("energy"), || pure(sys.energy(s)));
    tally.run(|| label("kinetic_energy"), || pure(sys.kinetic_energy(s)));
    tally.run(
        || label("potential_energy"),
        || pure(sys.potential_energy(s)),
    );
    tally.run(|| label("momenta"), || pure(sys.momenta(s)));
    tally.run(|| label("mass_matrix"), || pure(sys.mass_matrix(s)));
    tally.run(
        || label("generalized_forces"),
        || pure(sys.generalized_forces(s)),
    );
    tally.run(|| label("energy_function"), || pure(sys.energy_function(s)));
    tally.run(
        || label("lagrangian_time_derivative"),
        || pure(sys.lagrangian_time_derivative(s)),
    );
    let h = set.h;
    tally.run(
        || label("step Rk4"),
        || stepping(s, |s| sys.step::<Rk4>(s, h)),
    );
    tally.run(
        || label("step ImplicitMidpoint"),
        || stepping(s, |s| sys.step::<ImplicitMidpoint>(s, h)),
    );
    tally.run(
        || label("step GaussLegendre2"),
        || stepping(s, |s| sys.step::<GaussLegendre2>(s, h)),
    );
    tally.run(
        || label("step Variational"),
        || stepping(s, |s| sys.step::<Variational>(s, h)),
    );
    tally.run(
        || label("step StormerVerlet"),
        || stepping(s, |s| sys.step::<StormerVerlet>(s, h)),
    );
    tally.run(
        || label("Dopri5 integrate"),
        || {
            stepping(s, |state| {
                let t_end = state.t + 10.0 * h;
                sys.integrate(set.dopri5, state, t_end, &mut [], |_| {})
            })
        },
    );
    tally.run(
        || label("Radau5 integrate"),
        || {
            stepping(s, |state| {
                let t_end = state.t + 10.0 * h;
                sys.integrate(set.radau5, state, t_end, &mut [], |_| {})
            })
        },
    );
    tally.run(
        || label("equilibrium"),
        || pure(equilibrium(sys, s.t, &s.q, &set.equilibrium)),
    );
    tally.run(|| label("stability"), || pure(stability(sys, s.t, &s.q)));
    tally.run(
        || label("normal_modes"),
        || pure(normal_modes(sys, s.t, &s.q)),
    );
    tally.run(|| label("linearize"), || pure(linearize(sys, s)));
    tally.run(
        || label("unbalanced_forces"),
        || pure(unbalanced_forces(sys, s.t, &s.q)),
    );
}

/// The entry points of a mechanism with constraints, on top of [`mechanism_cases`]: the contact
/// options and the solvers that hold a contact mode.
fn constrained_cases<M, const N: usize, const K: usize, const C: usize>(
    tally: &mut Tally,
    what: &dyn Fn() -> String,
    sys: &M,
    s: &State<<M as Model<N, K>>::Coords>,
    set: &Settings,
) where
    M: Constraints<N, K, C> + Mechanism<N, Coords = <M as Model<N, K>>::Coords> + Debug,
{
    mechanism_cases(tally, what, sys, s, set);
    let label = |entry: &str| format!("{} / {entry}", what());
    tally.run(
        || label("consistent_state"),
        || pure(consistent_state(sys, s)),
    );
    // Holding the first coordinate and its velocity (the crank of a linkage).
    let first = [<M as Model<N, K>>::Coords::NAMES[0]];
    tally.run(
        || label("consistent_state_holding"),
        || pure(consistent_state_holding(sys, s, &first, &first)),
    );
    tally.run(
        || label("constraint_forces"),
        || pure(constraint_forces(sys, s)),
    );
    tally.run(
        || label("constrained_equilibrium"),
        || pure(constrained_equilibrium(sys, s.t, &s.q, &set.equilibrium)),
    );
    tally.run(
        || label("Stepper::new with contact options"),
        || {
            let solver = Stepper::new(sys, Rk4::with_step(set.h), s);
            let solver = solver.and_then(|solver| solver.with_contact_options(set.contact));
            pure(solver.map(|solver| *solver.contacts()))
        },
    );
    tally.run(
        || label("Stepper step holding contacts, RK4"),
        || {
            stepping(s, |state| {
                step_holding(sys, Rk4::with_step(set.h), set.contact, state)
            })
        },
    );
    tally.run(
        || label("Stepper step holding contacts, GaussLegendre2"),
        || {
            let method = GaussLegendre2::with_step(set.h);
            stepping(s, |state| step_holding(sys, method, set.contact, state))
        },
    );
    tally.run(
        || label("Stepper integrate holding contacts, Dopri5"),
        || {
            let t_end = s.t + set.h;
            stepping(s, |state| {
                integrate_holding(sys, set.dopri5, set.contact, state, t_end)
            })
        },
    );
    tally.run(
        || label("Stepper integrate holding contacts, Radau5"),
        || {
            let t_end = s.t + set.h;
            stepping(s, |state| {
                integrate_holding(sys, set.radau5, set.contact, state, t_end)
            })
        },
    );
}

/// One step of a solver made at `state` with the contact options given, `state` moved to its end.
fn step_holding<M: Mechanism<N>, Me: Method<N>, const N: usize>(
    sys: &M,
    method: Me,
    options: ContactOptions,
    state: &mut State<M::Coords>,
) -> lagrange::Result<()> {
    let mut solver = Stepper::new(sys, method, state)?.with_contact_options(options)?;
    solver.step(f64::INFINITY)?;
    *state = solver.state();
    Ok(())
}

/// An integration to `t_end` by a solver made at `state` with the contact options given, `state`
/// moved to its end.
fn integrate_holding<M: Mechanism<N>, Me: Method<N>, const N: usize>(
    sys: &M,
    method: Me,
    options: ContactOptions,
    state: &mut State<M::Coords>,
    t_end: f64,
) -> lagrange::Result<()> {
    let mut solver = Stepper::new(sys, method, state)?.with_contact_options(options)?;
    *state = solver.integrate(t_end, &mut [], |_| {})?.state;
    Ok(())
}

/// Replaces one input at a time by each bad value: state components, parameters, step size and
/// options, calling `cases` with (description, mechanism, state, settings).
fn matrix<P: Copy + Debug, C: Coordinates<N>, const N: usize>(
    name: &str,
    params: &[Parameter<P>],
    base: P,
    state: State<C>,
    mut cases: impl FnMut(&dyn Fn() -> String, &P, &State<C>, &Settings),
) {
    let set = Settings::default();
    for bad in BAD {
        for component in 0..=2 * N {
            let mut s = state;
            let what = if component == 0 {
                s.t = bad;
                "t".to_string()
            } else if component <= N {
                let mut q = s.q.to_array();
                q[component - 1] = bad;
                s.q = C::from_array(q);
                format!("q.{}", C::NAMES[component - 1])
            } else {
                let mut v = s.v.to_array();
                v[component - 1 - N] = bad;
                s.v = C::from_array(v);
                format!("v.{}", C::NAMES[component - 1 - N])
            };
            cases(&|| format!("{name}: {what} = {bad:e}"), &base, &s, &set);
        }
        for (param, field) in params {
            let mut p = base;
            *field(&mut p) = bad;
            cases(&|| format!("{name}: {param} = {bad:e}"), &p, &state, &set);
        }
        let mut settings: Vec<(&str, Settings)> = Vec::new();
        let mut with = |setting: &'static str, change: &dyn Fn(&mut Settings)| {
            let mut s = set;
            change(&mut s);
            settings.push((setting, s));
        };
        with("h", &|s| s.h = bad);
        with("Dopri5.rtol", &|s| s.dopri5.rtol = bad);
        with("Dopri5.atol", &|s| s.dopri5.atol = bad);
        with("Dopri5.h_init", &|s| s.dopri5.h_init = Some(bad));
        with("Dopri5.h_max", &|s| s.dopri5.h_max = bad);
        with("Dopri5.safety", &|s| s.dopri5.safety = bad);
        with("Dopri5.fac_min", &|s| s.dopri5.fac_min = bad);
        with("Dopri5.fac_max", &|s| s.dopri5.fac_max = bad);
        with("Dopri5.beta", &|s| s.dopri5.beta = bad);
        with("Radau5.rtol", &|s| s.radau5.rtol = bad);
        with("Radau5.atol", &|s| s.radau5.atol = bad);
        with("Radau5.h_init", &|s| s.radau5.h_init = Some(bad));
        with("Radau5.h_max", &|s| s.radau5.h_max = bad);
        with("EquilibriumOptions.residual_tolerance", &|s| {
            s.equilibrium.residual_tolerance = bad
        });
        with("EquilibriumOptions.step_tolerance", &|s| {
            s.equilibrium.step_tolerance = bad
        });
        with("ContactOptions.restitution", &|s| {
            s.contact.restitution = bad
        });
        with("ContactOptions.event_tolerance", &|s| {
            s.contact.event_tolerance = bad
        });
        for (setting, s) in settings {
            cases(
                &|| format!("{name}: {setting} = {bad:e}"),
                &base,
                &state,
                &s,
            );
        }
    }
    // The counts of the options are bad only at zero.
    let mut set0 = set;
    set0.dopri5.max_steps = 0;
    set0.radau5.max_steps = 0;
    set0.equilibrium.max_iterations = 0;
    set0.contact.max_events_per_step = 0;
    cases(
        &|| format!("{name}: max_steps = max_iterations = max_events_per_step = 0"),
        &base,
        &state,
        &set0,
    );
}

#[test]
fn bad_input_matrix() {
    std::panic::set_hook(Box::new(|info| {
        PANICS.lock().unwrap().push(info.to_string());
    }));
    let mut tally = Tally::default();

    {
        use double_pendulum::{Coords, DoublePendulum, State};
        let base = DoublePendulum {
            m1: 1.0,
            m2: 1.5,
            l1: 1.0,
            l2: 0.7,
            g: 9.81,
        };
        let state = State::new(
            0.5,
            Coords {
                theta1: 0.4,
                theta2: -0.3,
            },
            Coords {
                theta1: 0.2,
                theta2: 0.1,
            },
        );
        let params: [Parameter<DoublePendulum>; 5] = [
            ("m1", |p| &mut p.m1),
            ("m2", |p| &mut p.m2),
            ("l1", |p| &mut p.l1),
            ("l2", |p| &mut p.l2),
            ("g", |p| &mut p.g),
        ];
        matrix(
            "double pendulum",
            &params,
            base,
            state,
            |what, p, s, set| mechanism_cases(&mut tally, what, p, s, set),
        );
    }
    {
        use cartesian_pendulum::{CartesianPendulum, Coords, State};
        let base = CartesianPendulum {
            m: 1.0,
            l: 1.0,
            g: 9.81,
        };
        // On the circle, moving along it.
        let good = State::new(0.5, Coords { x: 0.6, y: -0.8 }, Coords { x: 0.8, y: 0.6 });
        let params: [Parameter<CartesianPendulum>; 3] = [
            ("m", |p| &mut p.m),
            ("l", |p| &mut p.l),
            ("g", |p| &mut p.g),
        ];
        matrix(
            "cartesian pendulum",
            &params,
            base,
            good,
            |what, p, s, set| constrained_cases(&mut tally, what, p, s, set),
        );
    }
    {
        use sphere::{Coords, SphereRelease as Sphere, State};
        let base = Sphere {
            m: 1.0,
            r: 1.0,
            g: 9.81,
        };
        // On top of the sphere, in contact, sliding off.
        let good = State::new(0.5, Coords { x: 0.0, y: 1.0 }, Coords { x: 0.5, y: 0.0 });
        let params: [Parameter<Sphere>; 3] = [
            ("m", |p| &mut p.m),
            ("r", |p| &mut p.r),
            ("g", |p| &mut p.g),
        ];
        matrix(
            "sphere (unilateral)",
            &params,
            base,
            good,
            |what, p, s, set| constrained_cases(&mut tally, what, p, s, set),
        );
    }
    {
        use rough_ramp::{Coords, RoughRamp, State};
        let base = RoughRamp {
            m: 2.0,
            alpha: 0.5,
            g: 9.81,
            mu_k: 0.3,
            mu_s: 0.4,
        };
        // On the ramp, sliding down it.
        let (sin, cos) = base.alpha.sin_cos();
        let good = State::new(
            0.5,
            Coords { x: cos, y: sin },
            Coords {
                x: -0.5 * cos,
                y: -0.5 * sin,
            },
        );
        let params: [Parameter<RoughRamp>; 5] = [
            ("m", |p| &mut p.m),
            ("alpha", |p| &mut p.alpha),
            ("g", |p| &mut p.g),
            ("mu_k", |p| &mut p.mu_k),
            ("mu_s", |p| &mut p.mu_s),
        ];
        matrix(
            "rough ramp (friction)",
            &params,
            base,
            good,
            |what, p, s, set| constrained_cases(&mut tally, what, p, s, set),
        );
    }
    let _ = std::panic::take_hook();

    println!("bad-input matrix:");
    println!("| cases | typed errors | finite Ok | panics | silent non-finite | state changed after error |");
    println!("|---|---|---|---|---|---|");
    println!(
        "| {} | {} | {} | {} | {} | {} |",
        tally.cases,
        tally.typed_errors,
        tally.finite_ok,
        tally.panics,
        tally.silent_non_finite,
        tally.state_changed
    );
    for failure in tally.failures.iter().take(40) {
        println!("{failure}");
    }
    assert_eq!(
        tally.cases,
        tally.typed_errors + tally.finite_ok + tally.panics + tally.silent_non_finite
    );
    assert!(
        tally.cases > 5000,
        "the matrix shrank: {} cases",
        tally.cases
    );
    assert_eq!(tally.panics, 0, "panics");
    assert_eq!(tally.silent_non_finite, 0, "Ok with non-finite numbers");
    assert_eq!(tally.state_changed, 0, "state changed after an error");
}
