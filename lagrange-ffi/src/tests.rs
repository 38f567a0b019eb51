//! The generic glue on a hand-written pendulum: statuses, messages, marshalling, the panic guard.

use crate::simulation::{self, Method, Simulation};
use crate::status::{guard, last_error, set_last_error, status_of, Failure, Status};
use lagrange_core::declaration::Declaration;
use lagrange_core::{impl_mechanism, vec2, Error, Mechanism, Model, Scalar};
use std::ffi::CStr;
use std::ptr::{null, null_mut};

/// A pendulum of mass `m` and length `l` under gravity `g`.
#[derive(Debug)]
struct Pendulum {
    m: f64,
    l: f64,
    g: f64,
}

impl Model<1, 2> for Pendulum {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        for (name, value) in [("m", self.m), ("l", self.l), ("g", self.g)] {
            if !value.is_finite() {
                return Err(Error::NonFiniteParameter { name, value });
            }
        }
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
        (vec2(q[0].sin(), -q[0].cos()) * D::from(self.l)).to_array()
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}
impl_mechanism!(Pendulum, 1, 2);

impl Declaration for Pendulum {
    const DOF: usize = 1;
    const PARAMETERS: &'static [&'static str] = &["m", "l", "g"];
    fn from_parameters(values: &[f64]) -> Option<Self> {
        match *values {
            [m, l, g] => Some(Pendulum { m, l, g }),
            _ => None,
        }
    }
    fn parameters(&self) -> Vec<f64> {
        vec![self.m, self.l, self.g]
    }
}

type Sim = Simulation<Pendulum, 1>;

fn message() -> String {
    // SAFETY: `last_error` is a NUL-terminated string owned by this thread's storage.
    unsafe { CStr::from_ptr(last_error()) }
        .to_str()
        .unwrap()
        .to_string()
}

/// A simulation of the unit pendulum at θ = 0.5, at rest.
fn pendulum() -> *mut Sim {
    let mut sim: *mut Sim = null_mut();
    let params = [1.0, 1.0, 9.81];
    unsafe {
        assert_eq!(simulation::create(params.as_ptr(), 3, &mut sim), Status::Ok);
        assert_eq!(
            simulation::set_state(sim, 0.0, [0.5].as_ptr(), [0.0].as_ptr(), 1),
            Status::Ok
        );
    }
    sim
}

fn state(sim: *const Sim) -> (f64, f64, f64) {
    let (mut t, mut q, mut v) = (0.0, [0.0], [0.0]);
    let status = unsafe { simulation::get_state(sim, &mut t, q.as_mut_ptr(), v.as_mut_ptr(), 1) };
    assert_eq!(status, Status::Ok);
    (t, q[0], v[0])
}

#[test]
fn status_codes_are_their_position() {
    for (i, s) in Status::ALL.iter().enumerate() {
        assert_eq!(*s as usize, i);
    }
    for (i, m) in Method::ALL.iter().enumerate() {
        assert_eq!(*m as usize, i);
        assert_eq!(Method::from_code(i as u32), Some(*m));
    }
    assert_eq!(Method::from_code(Method::ALL.len() as u32), None);
}

#[test]
fn errors_map_to_their_kind() {
    let nan = Error::NonFiniteParameter {
        name: "l",
        value: f64::NAN,
    };
    assert_eq!(status_of(&nan), Status::InvalidParameter);
    assert_eq!(
        status_of(&Error::InvalidStep { h: -1.0 }),
        Status::InvalidStep
    );
    let state = Error::NonFiniteState {
        state: String::new(),
    };
    assert_eq!(status_of(&state), Status::InvalidState);
    assert_eq!(Failure::Null("sim").status(), Status::NullPointer);
    assert_eq!(Failure::Null("sim").message(), "`sim` is NULL");
}

#[test]
fn the_last_error_is_per_thread_and_survives_success() {
    std::thread::spawn(|| {
        assert_eq!(message(), "", "empty before the first failure");
        set_last_error("bad\0byte");
        assert_eq!(
            message(),
            "bad\u{fffd}byte",
            "an interior NUL cannot end the C string"
        );
        assert_eq!(guard(|| Ok(())), Status::Ok);
        assert_eq!(message(), "bad\u{fffd}byte");
    })
    .join()
    .unwrap();
}

#[test]
fn a_panic_is_caught_at_the_boundary() {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let status = guard(|| panic!("an index out of bounds"));
    std::panic::set_hook(hook);
    assert_eq!(status, Status::Panic);
    assert!(
        message().contains("an index out of bounds"),
        "{}",
        message()
    );
}

#[test]
fn create_refuses_bad_parameters_cleanly() {
    let mut sim: *mut Sim = null_mut();
    let nan = [1.0, f64::NAN, 9.81];
    unsafe {
        assert_eq!(
            simulation::create(nan.as_ptr(), 3, &mut sim),
            Status::InvalidParameter
        );
        assert!(sim.is_null());
        assert_eq!(message(), "parameter `l` is not finite (NaN)");
        assert_eq!(
            simulation::create(nan.as_ptr(), 2, &mut sim),
            Status::InvalidArgument
        );
        assert_eq!(message(), "`params` has length 2, this mechanism needs 3");
        assert_eq!(simulation::create(null(), 3, &mut sim), Status::NullPointer);
        assert_eq!(
            simulation::create(nan.as_ptr(), 3, null_mut::<*mut Sim>()),
            Status::NullPointer
        );
    }
}

#[test]
fn every_method_steps_and_rk4_matches_rust() {
    let sys = Pendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    for method in Method::ALL {
        let sim = pendulum();
        let status = unsafe { simulation::step(sim, method as u32, 1e-3) };
        assert_eq!(status, Status::Ok, "{method:?}: {}", message());
        let (t, q, v) = state(sim);
        assert!((t - 1e-3).abs() < 1e-15 && q < 0.5 && v < 0.0, "{method:?}");
        unsafe { simulation::free(sim) };
    }
    let sim = pendulum();
    assert_eq!(unsafe { simulation::steps(sim, 0, 1e-3, 100) }, Status::Ok);
    let mut s = lagrange_core::State::new(0.0, [0.5], [0.0]);
    sys.simulate::<lagrange_core::Rk4>(&mut s, 1e-3, 100, |_| {})
        .unwrap();
    assert_eq!(
        state(sim),
        (s.t, s.q[0], s.v[0]),
        "the same operations, bit for bit"
    );
    unsafe { simulation::free(sim) };
}

#[test]
fn refused_calls_leave_the_state_unchanged() {
    let sim = pendulum();
    let before = state(sim);
    unsafe {
        let nan = [f64::NAN];
        assert_eq!(
            simulation::set_state(sim, 0.0, nan.as_ptr(), [0.0].as_ptr(), 1),
            Status::InvalidState
        );
        assert!(message().contains("q0 = NaN"), "{}", message());
        assert_eq!(
            simulation::set_state(sim, 0.0, [0.1].as_ptr(), [0.0].as_ptr(), 2),
            Status::InvalidArgument
        );
        assert_eq!(simulation::step(sim, 0, -1.0), Status::InvalidStep);
        assert_eq!(simulation::step(sim, 42, 1e-3), Status::InvalidArgument);
        assert!(message().contains("unknown method 42"));
        assert_eq!(
            simulation::integrate_dopri5(sim, -1.0, 1e-8, 1e-8, null_mut()),
            Status::InvalidStep
        );
        assert_eq!(
            simulation::integrate_dopri5(sim, 1.0, f64::NAN, 1e-8, null_mut()),
            Status::InvalidStep
        );
        assert_eq!(
            simulation::step(null_mut::<Sim>(), 0, 1e-3),
            Status::NullPointer
        );
        let mut q = [0.0; 2];
        assert_eq!(
            simulation::get_state(sim, null_mut(), q.as_mut_ptr(), null_mut(), 2),
            Status::InvalidArgument
        );
    }
    assert_eq!(state(sim), before);
    unsafe { simulation::free(sim) };
}

#[test]
fn dopri5_integrates_to_the_end_time_and_energies_are_read() {
    let sim = pendulum();
    let mut accepted = 0usize;
    let status = unsafe { simulation::integrate_dopri5(sim, 2.0, 1e-10, 1e-12, &mut accepted) };
    assert_eq!(status, Status::Ok);
    assert!(accepted > 10);
    assert_eq!(state(sim).0, 2.0);
    let (mut kinetic, mut potential) = (f64::NAN, f64::NAN);
    unsafe {
        assert_eq!(
            simulation::energies(sim, &mut kinetic, &mut potential),
            Status::Ok
        );
        assert_eq!(
            simulation::energies(sim, null_mut(), null_mut()),
            Status::Ok
        );
    }
    // E = −m g l cos θ₀ at release; tolerances 1e-10 keep it to ~1e-9 over 2 s.
    assert!((kinetic + potential + 9.81 * 0.5f64.cos()).abs() < 1e-8);
    let mut qdd = [0.0];
    unsafe {
        assert_eq!(
            simulation::accelerations(sim, qdd.as_mut_ptr(), 1),
            Status::Ok
        );
        assert_eq!(
            simulation::accelerations(sim, null_mut(), 1),
            Status::NullPointer
        );
        // No constraints: zero rows, and asking for one is a wrong length.
        assert_eq!(
            simulation::constraint_forces(sim, null_mut(), 0, null_mut(), 0),
            Status::Ok
        );
        let mut row = [0.0];
        assert_eq!(
            simulation::constraint_forces(sim, row.as_mut_ptr(), 1, null_mut(), 0),
            Status::InvalidArgument
        );
        simulation::free(sim);
        simulation::free(null_mut::<Sim>());
    }
}
