//! `export_c!` on mechanisms with `#[inputs]`, called through their exported C symbols: the header
//! names the inputs, `PREFIX_set_inputs` holds them over every later call (a zero-order hold) and
//! the runs equal `driven(&u)` in Rust to the last bit, bad inputs are refused with the handle
//! unchanged, and a mechanism without inputs takes none.

use lagrange::ffi::{Export, Method, Status};
use lagrange::prelude::*;
use std::ffi::{c_char, CStr};
use std::ptr::{null, null_mut};

/// Two point masses on rods, a motor at each joint: the inputs as an array.
#[mechanism]
pub mod driven_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct DrivenPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[inputs]
    pub struct Motors {
        pub tau: [f64; 2],
    }
    #[particle(mass = m)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l
    }
    #[particle(mass = m)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[generalized_force(on = theta1)]
    fn shoulder() -> f64 {
        tau[0]
    }
    #[generalized_force(on = theta2)]
    fn elbow() -> f64 {
        tau[1]
    }
}

/// A bob on a rod (a constraint row) pushed sideways by an input force.
#[mechanism]
pub mod pushed_pendulum {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct PushedPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[inputs]
    pub struct Push {
        pub f: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[force(on = bob)]
    fn push() -> Vec2 {
        vec2(f, 0.0)
    }
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

/// A pendulum without inputs.
#[mechanism]
pub mod free_pendulum {
    pub struct Coords {
        pub theta: f64,
    }
    pub struct FreePendulum {
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = 1.0)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

lagrange::export_c!(driven_pendulum::DrivenPendulum, prefix = dpi);
lagrange::export_c!(pushed_pendulum::PushedPendulum, prefix = ppi);
lagrange::export_c!(free_pendulum::FreePendulum, prefix = fpi);

/// An opaque handle, as C sees it.
#[repr(C)]
struct Handle {
    _opaque: [u8; 0],
}

// The functions `export_c!` wrote, declared as a C program declares them from the header.
extern "C" {
    fn dpi_create(params: *const f64, len: usize, out: *mut *mut Handle) -> Status;
    fn dpi_set_state(sim: *mut Handle, t: f64, q: *const f64, v: *const f64, dof: usize) -> Status;
    fn dpi_get_state(
        sim: *const Handle,
        t: *mut f64,
        q: *mut f64,
        v: *mut f64,
        dof: usize,
    ) -> Status;
    fn dpi_set_inputs(sim: *mut Handle, u: *const f64, len: usize) -> Status;
    fn dpi_get_inputs(sim: *const Handle, u: *mut f64, len: usize) -> Status;
    fn dpi_step(sim: *mut Handle, method: u32, h: f64) -> Status;
    fn dpi_steps(sim: *mut Handle, method: u32, h: f64, count: usize) -> Status;
    fn dpi_integrate_dopri5(
        sim: *mut Handle,
        t_end: f64,
        rtol: f64,
        atol: f64,
        accepted: *mut usize,
    ) -> Status;
    fn dpi_accelerations(sim: *const Handle, qdd: *mut f64, dof: usize) -> Status;
    fn dpi_last_error() -> *const c_char;
    fn dpi_free(sim: *mut Handle);

    fn ppi_create(params: *const f64, len: usize, out: *mut *mut Handle) -> Status;
    fn ppi_set_state(sim: *mut Handle, t: f64, q: *const f64, v: *const f64, dof: usize) -> Status;
    fn ppi_set_inputs(sim: *mut Handle, u: *const f64, len: usize) -> Status;
    fn ppi_constraint_forces(
        sim: *const Handle,
        multipliers: *mut f64,
        rows: usize,
        generalized: *mut f64,
        len: usize,
    ) -> Status;
    fn ppi_free(sim: *mut Handle);

    fn fpi_create(params: *const f64, len: usize, out: *mut *mut Handle) -> Status;
    fn fpi_set_inputs(sim: *mut Handle, u: *const f64, len: usize) -> Status;
    fn fpi_get_inputs(sim: *const Handle, u: *mut f64, len: usize) -> Status;
    fn fpi_step(sim: *mut Handle, method: u32, h: f64) -> Status;
    fn fpi_free(sim: *mut Handle);
}

fn last_error() -> String {
    unsafe { CStr::from_ptr(dpi_last_error()) }
        .to_string_lossy()
        .into_owned()
}

const PARAMS: [f64; 3] = [1.0, 0.8, 9.81];
const Q0: [f64; 2] = [0.4, -0.3];
const V0: [f64; 2] = [0.2, 0.1];

/// A driven pendulum handle at (Q0, V0), t = 0.
fn handle() -> *mut Handle {
    let mut sim = null_mut();
    unsafe {
        assert_eq!(dpi_create(PARAMS.as_ptr(), 3, &mut sim), Status::Ok);
        assert_eq!(
            dpi_set_state(sim, 0.0, Q0.as_ptr(), V0.as_ptr(), 2),
            Status::Ok
        );
    }
    sim
}

/// (t, q, v) of a handle.
fn state_of(sim: *const Handle) -> (f64, [f64; 2], [f64; 2]) {
    let (mut t, mut q, mut v) = (0.0, [0.0; 2], [0.0; 2]);
    let status = unsafe { dpi_get_state(sim, &mut t, q.as_mut_ptr(), v.as_mut_ptr(), 2) };
    assert_eq!(status, Status::Ok);
    (t, q, v)
}

fn inputs_of(sim: *const Handle) -> [f64; 2] {
    let mut u = [f64::NAN; 2];
    assert_eq!(
        unsafe { dpi_get_inputs(sim, u.as_mut_ptr(), 2) },
        Status::Ok
    );
    u
}

/// The same mechanism and state in Rust.
fn rust_scene() -> (
    lagrange::Validated<driven_pendulum::DrivenPendulum>,
    driven_pendulum::State,
) {
    let [m, l, g] = PARAMS;
    let sys = driven_pendulum::DrivenPendulum { m, l, g }
        .validated()
        .unwrap();
    let c = |a: [f64; 2]| driven_pendulum::Coords {
        theta1: a[0],
        theta2: a[1],
    };
    (sys, driven_pendulum::State::new(0.0, c(Q0), c(V0)))
}

fn motors(tau: [f64; 2]) -> driven_pendulum::Motors {
    driven_pendulum::Motors { tau }
}

fn rust_state(s: &driven_pendulum::State) -> (f64, [f64; 2], [f64; 2]) {
    (s.t, s.q.to_array(), s.v.to_array())
}

#[test]
fn the_header_names_the_inputs() {
    let header = dpi::header();
    assert!(header.contains("#define DPI_INPUT_COUNT 2\n"), "{header}");
    assert!(header.contains("#define DPI_INPUT_TAU_0 0\n#define DPI_INPUT_TAU_1 1\n"));
    assert!(header.contains(
        "lagrange_status dpi_set_inputs(dpi_simulation *sim, const double *u, size_t len);"
    ));
    assert!(header.contains(
        "lagrange_status dpi_get_inputs(const dpi_simulation *sim, double *u, size_t len);"
    ));
    assert!(header.contains("DPI_INPUT_COUNT finite values, indexed by\n * DPI_INPUT_*"));
    let header = ppi::header();
    assert!(header.contains("#define PPI_INPUT_COUNT 1\n"));
    assert!(header.contains("#define PPI_INPUT_F 0\n"));
    let header = fpi::header();
    assert!(header.contains("#define FPI_INPUT_COUNT 0\n"));
    let input_lines = header
        .lines()
        .filter(|l| l.starts_with("#define FPI_INPUT_"));
    assert_eq!(input_lines.count(), 1, "only the count: {header}");
}

/// Inputs set from C and held over the steps, changed between them, give the run `driven(&u)`
/// gives in Rust, bit for bit: the same compiled functions on the same numbers.
#[test]
fn set_inputs_then_step_is_the_driven_run() {
    let sim = handle();
    assert_eq!(inputs_of(sim), [0.0, 0.0], "inputs are zero at creation");
    let (sys, mut s) = rust_scene();
    let schedule = [[1.5, -0.4], [-2.0, 0.7], [0.0, 3.0]];
    unsafe {
        for (k, u) in schedule.iter().enumerate() {
            assert_eq!(dpi_set_inputs(sim, u.as_ptr(), 2), Status::Ok);
            assert_eq!(inputs_of(sim), *u);
            let driven = sys.driven(&motors(*u));
            let mut qdd = [0.0; 2];
            assert_eq!(dpi_accelerations(sim, qdd.as_mut_ptr(), 2), Status::Ok);
            assert_eq!(qdd, driven.accelerations(&s).unwrap().to_array());
            // Every method, one call per step, then many steps in one call.
            for method in Method::ALL {
                let status = dpi_step(sim, method as u32, 1e-3);
                let rust = driven.step_with(method, &mut s, 1e-3);
                assert_eq!(status == Status::Ok, rust.is_ok(), "{method:?}");
                // Störmer–Verlet needs a constant mass matrix; every other method steps.
                let refused = method == Method::StormerVerlet;
                assert_eq!(status == Status::Unsupported, refused, "{method:?}");
            }
            assert_eq!(dpi_steps(sim, 0, 2e-3, 25), Status::Ok);
            for _ in 0..25 {
                driven.step::<Rk4>(&mut s, 2e-3).unwrap();
            }
            assert_eq!(state_of(sim), rust_state(&s), "after input set {k}");
        }
        // Adaptive to an end time, with the last inputs held.
        let mut accepted = 0;
        let status = dpi_integrate_dopri5(sim, 1.0, 1e-9, 1e-12, &mut accepted);
        assert_eq!(status, Status::Ok, "{}", last_error());
        let outcome = sys
            .driven(&motors(schedule[2]))
            .integrate(Dopri5::new(1e-9, 1e-12), &mut s, 1.0, &mut [], |_| {})
            .unwrap();
        assert_eq!(accepted, outcome.stats.accepted);
        assert_eq!(state_of(sim), rust_state(&s));
        // The inputs act: the same run undriven ends elsewhere.
        let (undriven, mut s0) = rust_scene();
        undriven
            .integrate(Dopri5::new(1e-9, 1e-12), &mut s0, s.t, &mut [], |_| {})
            .unwrap();
        assert!((s0.q.theta2 - s.q.theta2).abs() > 1e-2);
        dpi_free(sim);
    }
}

/// The methods a C caller picks by code, stepped in Rust.
trait StepWith {
    fn step_with(
        &self,
        method: Method,
        s: &mut driven_pendulum::State,
        h: f64,
    ) -> Result<(), lagrange::Error>;
}

impl<M: Mechanism<2, Coords = driven_pendulum::Coords>> StepWith for M {
    fn step_with(
        &self,
        method: Method,
        s: &mut driven_pendulum::State,
        h: f64,
    ) -> Result<(), lagrange::Error> {
        match method {
            Method::Rk4 => self.step::<Rk4>(s, h),
            Method::Dopri5 => self.step::<Dopri5>(s, h),
            Method::Dop853 => self.step::<Dop853>(s, h),
            Method::ImplicitMidpoint => self.step::<ImplicitMidpoint>(s, h),
            Method::GaussLegendre2 => self.step::<GaussLegendre2>(s, h),
            Method::Variational => self.step::<Variational>(s, h),
            Method::StormerVerlet => self.step::<StormerVerlet>(s, h),
        }
    }
}

/// NULL, a wrong length, a NaN or an infinity: an error status and message, and the handle —
/// inputs and state — as it was.
#[test]
fn refused_inputs_leave_the_handle_unchanged() {
    let sim = handle();
    let u = [0.5, -0.25];
    unsafe {
        assert_eq!(dpi_set_inputs(sim, u.as_ptr(), 2), Status::Ok);
        let before = (state_of(sim), inputs_of(sim));
        let (nan, inf, minus_inf) = (
            [f64::NAN, 1.0],
            [1.0, f64::INFINITY],
            [1.0, f64::NEG_INFINITY],
        );
        let refusals: [(*mut Handle, *const f64, usize, Status, &str); 7] = [
            (
                null_mut(),
                u.as_ptr(),
                2,
                Status::NullPointer,
                "`sim` is NULL",
            ),
            (sim, null(), 2, Status::NullPointer, "`u` is NULL"),
            (
                sim,
                u.as_ptr(),
                1,
                Status::InvalidArgument,
                "`u` has length 1, this mechanism needs 2",
            ),
            (
                sim,
                u.as_ptr(),
                3,
                Status::InvalidArgument,
                "`u` has length 3",
            ),
            (
                sim,
                nan.as_ptr(),
                2,
                Status::InvalidArgument,
                "input `tau[0]` is not finite (NaN)",
            ),
            (
                sim,
                inf.as_ptr(),
                2,
                Status::InvalidArgument,
                "input `tau[1]` is not finite (inf)",
            ),
            (
                sim,
                minus_inf.as_ptr(),
                2,
                Status::InvalidArgument,
                "input `tau[1]` is not finite (-inf)",
            ),
        ];
        for (handle, values, len, status, message) in refusals {
            assert_eq!(dpi_set_inputs(handle, values, len), status, "{message}");
            assert!(
                last_error().contains(message),
                "{} against {message}",
                last_error()
            );
            assert_eq!((state_of(sim), inputs_of(sim)), before, "{message}");
        }
        // Reading: a wrong length or NULL is refused too, and nothing is written.
        let mut out = [7.0; 3];
        assert_eq!(
            dpi_get_inputs(sim, out.as_mut_ptr(), 3),
            Status::InvalidArgument
        );
        assert_eq!(out, [7.0; 3]);
        assert_eq!(dpi_get_inputs(sim, null_mut(), 2), Status::NullPointer);
        assert_eq!(
            dpi_get_inputs(null(), out.as_mut_ptr(), 2),
            Status::NullPointer
        );
        // A failed step leaves the inputs held too.
        assert_eq!(dpi_step(sim, 0, -1.0), Status::InvalidStep);
        assert_eq!((state_of(sim), inputs_of(sim)), before);
        dpi_free(sim);
    }
}

/// The rod's multiplier sees the push. At rest at angle θ from the downward vertical, the bob's
/// acceleration is tangential, so the rod balances the radial part of the applied forces along the
/// outward unit vector e = (sin θ, −cos θ): T = m g cos θ + f sin θ, λ = −T (the sign convention
/// of `tests/constrained.rs`).
#[test]
fn constraint_forces_see_the_inputs() {
    let (m, l, g, f) = (2.0, 1.5, 9.81, 4.0);
    let theta = 0.7f64;
    let q = [l * theta.sin(), -l * theta.cos()];
    let mut sim = null_mut();
    unsafe {
        assert_eq!(ppi_create([m, l, g].as_ptr(), 3, &mut sim), Status::Ok);
        assert_eq!(
            ppi_set_state(sim, 0.0, q.as_ptr(), [0.0; 2].as_ptr(), 2),
            Status::Ok
        );
        let mut lambda = [0.0];
        for push in [0.0, f] {
            assert_eq!(ppi_set_inputs(sim, [push].as_ptr(), 1), Status::Ok);
            let status = ppi_constraint_forces(sim, lambda.as_mut_ptr(), 1, null_mut(), 0);
            assert_eq!(status, Status::Ok);
            let tension = m * g * theta.cos() + push * theta.sin();
            // One Schur-complement solve in f64 on quantities of order 20: round-off ~1e-14.
            assert!(
                (lambda[0] + tension).abs() < 1e-12,
                "push {push}: λ = {} against −T = {}",
                lambda[0],
                -tension
            );
        }
        ppi_free(sim);
    }
}

/// No `#[inputs]`: zero inputs, an empty `set_inputs` accepted, any other refused.
#[test]
fn a_mechanism_without_inputs_takes_none() {
    let mut sim = null_mut();
    unsafe {
        assert_eq!(fpi_create([1.0, 9.81].as_ptr(), 2, &mut sim), Status::Ok);
        assert_eq!(fpi_set_inputs(sim, null(), 0), Status::Ok);
        assert_eq!(fpi_get_inputs(sim, null_mut(), 0), Status::Ok);
        assert_eq!(
            fpi_set_inputs(sim, [1.0].as_ptr(), 1),
            Status::InvalidArgument
        );
        assert!(last_error().contains("`u` has length 1, this mechanism needs 0"));
        assert_eq!(fpi_step(sim, 0, 1e-3), Status::Ok);
        fpi_free(sim);
    }
}
