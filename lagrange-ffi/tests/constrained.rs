//! `export_c!` on a mechanism with a constraint, called through its exported C symbols: the rod
//! tension of the Cartesian pendulum comes out of `cp_constraint_forces`.
//!
//! Closed form: for the bob on a rod of length L at angle θ from the downward vertical, moving at
//! θ̇, the rod tension is T = m (g cos θ + L θ̇²) (Taylor, *Classical Mechanics*, 2005, §7.10,
//! example 7.9). The constraint |r| − L = 0 has the outward unit vector as its gradient, so its
//! multiplier is λ = −T and its generalized force λ·r/|r|.

use lagrange::ffi::{Export, Status};
use lagrange::prelude::*;
use std::ffi::{c_char, CStr};

#[mechanism]
pub mod cartesian_pendulum {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct CartesianPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

lagrange::export_c!(cartesian_pendulum::CartesianPendulum, prefix = cp);

/// The opaque handle, as C sees it.
#[repr(C)]
struct CpSimulation {
    _opaque: [u8; 0],
}

// The functions `export_c!` wrote, declared as a C program declares them from the header.
extern "C" {
    fn cp_create(params: *const f64, len: usize, out: *mut *mut CpSimulation) -> Status;
    fn cp_set_state(
        sim: *mut CpSimulation,
        t: f64,
        q: *const f64,
        v: *const f64,
        dof: usize,
    ) -> Status;
    fn cp_step(sim: *mut CpSimulation, method: u32, h: f64) -> Status;
    fn cp_constraint_forces(
        sim: *const CpSimulation,
        multipliers: *mut f64,
        rows: usize,
        generalized: *mut f64,
        len: usize,
    ) -> Status;
    fn cp_last_error() -> *const c_char;
    fn cp_free(sim: *mut CpSimulation);
}

fn last_error() -> String {
    unsafe { CStr::from_ptr(cp_last_error()) }
        .to_string_lossy()
        .into_owned()
}

#[test]
fn the_header_names_the_constraint_row() {
    let header = cp::header();
    assert!(header.contains("#define CP_CONSTRAINT_COUNT 1"));
    assert!(header.contains("#define CP_CONSTRAINT_ROD 0"));
    assert!(header.contains("#define CP_X 0\n#define CP_Y 1"));
}

#[test]
fn rod_tension_through_the_c_interface() {
    let (m, l, g) = (2.0, 1.5, 9.81);
    let (theta, omega) = (0.7f64, 1.3f64);
    // On the circle, moving along it: r = L (sin θ, −cos θ), ṙ = L θ̇ (cos θ, sin θ).
    let q = [l * theta.sin(), -l * theta.cos()];
    let v = [l * omega * theta.cos(), l * omega * theta.sin()];
    let mut sim = std::ptr::null_mut();
    unsafe {
        assert_eq!(cp_create([m, l, g].as_ptr(), 3, &mut sim), Status::Ok);
        assert_eq!(
            cp_set_state(sim, 0.0, q.as_ptr(), v.as_ptr(), 2),
            Status::Ok
        );
        let (mut lambda, mut generalized) = ([0.0], [0.0; 2]);
        let status = cp_constraint_forces(sim, lambda.as_mut_ptr(), 1, generalized.as_mut_ptr(), 2);
        assert_eq!(status, Status::Ok, "{}", last_error());
        let tension = m * (g * theta.cos() + l * omega * omega);
        // One Schur-complement solve in f64 on quantities of order 30: round-off ~1e-14.
        assert!(
            (lambda[0] + tension).abs() < 1e-12,
            "λ = {} against −T = {}",
            lambda[0],
            -tension
        );
        // λ times the outward unit vector r/L.
        assert!((generalized[0] - lambda[0] * q[0] / l).abs() < 1e-12);
        assert!((generalized[1] - lambda[0] * q[1] / l).abs() < 1e-12);

        // Off the circle, a step is refused with a message naming the row.
        assert_eq!(
            cp_set_state(sim, 0.0, [l, l].as_ptr(), [0.0, 0.0].as_ptr(), 2),
            Status::Ok
        );
        assert_eq!(cp_step(sim, 0, 1e-3), Status::InvalidState);
        assert!(last_error().contains("`rod`"), "{}", last_error());
        // A wrong number of rows is a wrong argument, not a write past the array.
        let status = cp_constraint_forces(sim, lambda.as_mut_ptr(), 2, std::ptr::null_mut(), 0);
        assert_eq!(status, Status::InvalidArgument);
        cp_free(sim);
    }
}
