//! [`Status`]: what every exported C function returns, and the last error's message on this
//! thread ([`last_error`]), with the guard that turns a Rust result or panic into both.

use lagrange_core::Error;
use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The result of an exported C function: `LAGRANGE_OK` (0) or the kind of failure. The message
/// of a failure is `PREFIX_last_error()`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Success.
    Ok = 0,
    /// A required pointer argument is NULL.
    NullPointer = 1,
    /// An argument is malformed: an array length that does not match the mechanism, an unknown
    /// method.
    InvalidArgument = 2,
    /// A parameter is not finite, a mass or inertia not positive, a constraint declaration invalid.
    InvalidParameter = 3,
    /// The state is not finite or violates the constraints.
    InvalidState = 4,
    /// A step size, end time or tolerance is out of range.
    InvalidStep = 5,
    /// The mass matrix or the constraints are singular at this configuration.
    Singular = 6,
    /// The equations of motion are not finite at this state.
    NonFiniteDynamics = 7,
    /// An iteration of the method failed: Newton, step-size underflow, projection.
    SolverFailed = 8,
    /// The method cannot integrate this mechanism (Störmer–Verlet on a varying mass matrix).
    Unsupported = 9,
    /// An internal error of the library (a Rust panic, caught at the boundary). Please report it.
    Panic = 10,
    /// Any other error of the library.
    Other = 11,
}

impl Status {
    /// Every status, in order of value.
    pub const ALL: [Status; 12] = [
        Status::Ok,
        Status::NullPointer,
        Status::InvalidArgument,
        Status::InvalidParameter,
        Status::InvalidState,
        Status::InvalidStep,
        Status::Singular,
        Status::NonFiniteDynamics,
        Status::SolverFailed,
        Status::Unsupported,
        Status::Panic,
        Status::Other,
    ];

    /// The C name of the value (`LAGRANGE_INVALID_STEP`) and its one-line meaning, for the header.
    pub fn c_definition(self) -> (&'static str, &'static str) {
        match self {
            Status::Ok => ("LAGRANGE_OK", "success"),
            Status::NullPointer => (
                "LAGRANGE_NULL_POINTER",
                "a required pointer argument is NULL",
            ),
            Status::InvalidArgument => (
                "LAGRANGE_INVALID_ARGUMENT",
                "an array length that does not match the mechanism, an unknown method, or a non-finite input",
            ),
            Status::InvalidParameter => (
                "LAGRANGE_INVALID_PARAMETER",
                "a parameter is not finite, a mass or inertia not positive",
            ),
            Status::InvalidState => (
                "LAGRANGE_INVALID_STATE",
                "the state is not finite or violates the constraints",
            ),
            Status::InvalidStep => (
                "LAGRANGE_INVALID_STEP",
                "a step size, end time or tolerance is out of range",
            ),
            Status::Singular => (
                "LAGRANGE_SINGULAR",
                "the mass matrix or the constraints are singular here",
            ),
            Status::NonFiniteDynamics => (
                "LAGRANGE_NON_FINITE_DYNAMICS",
                "the equations of motion are not finite at this state",
            ),
            Status::SolverFailed => (
                "LAGRANGE_SOLVER_FAILED",
                "an iteration of the method failed (Newton, step size, projection)",
            ),
            Status::Unsupported => (
                "LAGRANGE_UNSUPPORTED",
                "the method cannot integrate this mechanism",
            ),
            Status::Panic => (
                "LAGRANGE_PANIC",
                "an internal error of the library, caught at the boundary",
            ),
            Status::Other => ("LAGRANGE_OTHER", "any other error"),
        }
    }
}

/// A failure at the C boundary: the library's own [`Error`], or misuse the C caller can make and
/// Rust cannot (a NULL pointer, a wrong length, an unknown method code).
#[derive(Debug, Clone, PartialEq)]
pub enum Failure {
    /// An error of the library.
    Error(Error),
    /// A NULL pointer where one is required; the argument's name.
    Null(&'static str),
    /// A malformed argument, in words.
    Argument(String),
    /// A solver that stopped before its goal without an error of its own, in words.
    Solver(String),
    /// A panic caught at the boundary, with its message.
    Panic(String),
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Error(e)
    }
}

impl Failure {
    /// The status a C caller sees.
    pub fn status(&self) -> Status {
        match self {
            Failure::Null(_) => Status::NullPointer,
            Failure::Argument(_) => Status::InvalidArgument,
            Failure::Solver(_) => Status::SolverFailed,
            Failure::Panic(_) => Status::Panic,
            Failure::Error(e) => status_of(e),
        }
    }

    /// The message `PREFIX_last_error()` returns.
    pub fn message(&self) -> String {
        match self {
            Failure::Null(name) => format!("`{name}` is NULL"),
            Failure::Argument(what) | Failure::Solver(what) => what.clone(),
            Failure::Panic(what) => {
                format!("internal error (a bug of lagrange, please report it): {what}")
            }
            Failure::Error(e) => e.to_string(),
        }
    }
}

/// The status of each error of the library.
pub fn status_of(e: &Error) -> Status {
    match e {
        Error::NonFiniteParameter { .. }
        | Error::InvalidInertia { .. }
        | Error::InvalidRotation { .. }
        | Error::InvalidFriction { .. }
        | Error::InvalidConstraintDeclaration { .. } => Status::InvalidParameter,
        Error::NonFiniteState { .. } | Error::ConstraintViolation { .. } => Status::InvalidState,
        Error::InvalidStep { .. }
        | Error::StepDoesNotAdvance { .. }
        | Error::InvalidEndTime { .. }
        | Error::InvalidSetting { .. } => Status::InvalidStep,
        Error::SingularMassMatrix { .. }
        | Error::SingularConstraints { .. }
        | Error::FrictionIndeterminate { .. } => Status::Singular,
        Error::NonFiniteDynamics { .. } => Status::NonFiniteDynamics,
        Error::NewtonDiverged { .. }
        | Error::NewtonBreakdown { .. }
        | Error::StepSizeUnderflow { .. }
        | Error::ProjectionFailed { .. }
        | Error::TooManyEvents { .. } => Status::SolverFailed,
        Error::UnsuitableMethod { .. } | Error::NonlinearVelocityConstraint { .. } => {
            Status::Unsupported
        }
        _ => Status::Other,
    }
}

thread_local! {
    /// The message of the last failure on this thread (empty before the first).
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Stores `message` as this thread's last error (an interior NUL, which C cannot represent,
/// becomes U+FFFD).
pub fn set_last_error(message: &str) {
    let text = CString::new(message.replace('\0', "\u{fffd}")).unwrap_or_default();
    // `try_with`: during the thread's teardown (a call from a thread-exit destructor) the storage
    // is gone; the message is then dropped rather than panicking.
    let _ = LAST_ERROR.try_with(|cell| *cell.borrow_mut() = text);
}

/// The message of the last failure of a call on this thread, as a NUL-terminated UTF-8 string
/// owned by the library: valid until the next call into the library on this thread, never to be
/// freed by the caller. Empty (`""`) before the first failure. A success does not clear it.
pub fn last_error() -> *const c_char {
    LAST_ERROR
        .try_with(|cell| cell.borrow().as_ptr())
        .unwrap_or(c"".as_ptr())
}

/// Runs `body` at the C boundary: `Ok` is [`Status::Ok`]; a failure stores its message and returns
/// its status; a panic (a bug of the library, never bad input) is caught here, as a last guard,
/// and reported as [`Status::Panic`] with its message, so no unwinding crosses into C. (A library
/// built with `panic = "abort"` aborts instead: keep the default `unwind` profile for it.)
pub fn guard(body: impl FnOnce() -> Result<(), Failure>) -> Status {
    let outcome = catch_unwind(AssertUnwindSafe(body)).unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_string());
        Err(Failure::Panic(what))
    });
    match outcome {
        Ok(()) => Status::Ok,
        Err(f) => {
            set_last_error(&f.message());
            f.status()
        }
    }
}
