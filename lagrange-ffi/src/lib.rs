//! C embedding of `lagrange` mechanisms.
//!
//! [`export_c!`] writes the `extern "C"` functions of a declared mechanism — create it from its
//! parameters, set and read its state, step it with a chosen method, integrate it adaptively to a
//! time, read its energies, accelerations and constraint forces — and its C header
//! ([`Export::header`]). Everything the functions do is generic and lives here once:
//! - [`status`]: the [`Status`] codes every function returns, the last error's message per thread,
//!   and the guard that turns errors and (as a last resort) panics into both;
//! - [`simulation`]: the handle C holds ([`Simulation`]) and the checked marshalling of arrays;
//! - [`header`](mod@header): the header, written from the same tokens as the functions.
//!
//! Bad input — a NULL pointer, a wrong array length, an unknown method code, a NaN parameter,
//! state or input, a bad step — is a status and a message, never a panic; no unwinding crosses into C.

pub mod export;
pub mod header;
pub mod simulation;
pub mod status;

pub use header::{header, CFunction, CType, Export};
pub use simulation::{Method, Simulation};
pub use status::{last_error, status_of, Failure, Status};

/// What `export_c!` names. Not a public API.
#[doc(hidden)]
pub mod __private {
    pub use lagrange_core::declaration::Declaration;
    pub use std::ffi::c_char;
    pub use std::string::String;
    pub use std::vec;
    pub use std::vec::Vec;
}

#[cfg(test)]
mod tests;
