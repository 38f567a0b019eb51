//! The integrators' hook (`Evaluate::accelerations_at` on a validated handle) of the report's
//! Kepler and FPU chain, and the peers' hand-written right-hand sides, each monomorphised in a
//! function of its own (`#[inline(never)]`), for reading the machine code: `objdump -d` of
//! `hooks::kepler` etc., or `mca.sh` (llvm-mca's cycles for one pass). Running it evaluates each
//! once at a fixed state and prints the results.

use lagrange::evaluation::Evaluate;
use lagrange::prelude::*;
use std::hint::black_box;

#[path = "../../../../lagrange-bench/src/fpu.rs"]
#[allow(dead_code)]
mod fpu;
#[path = "../../../../lagrange-bench/src/kepler.rs"]
#[allow(dead_code)]
mod kepler;

/// Kepler's q̈ through the validated handle's hook.
#[inline(never)]
pub fn kepler(sys: &Validated<kepler::kepler::Kepler>, q: &[f64; 2], v: &[f64; 2]) -> [f64; 2] {
    sys.accelerations_at(0.0, q, v).unwrap()
}

/// Kepler's q̈ by hand (the peers' right-hand side).
#[inline(never)]
pub fn hw_kepler(q: &[f64; 2], v: &[f64; 2]) -> [f64; 2] {
    kepler::kepler_rhs(0.0, q, v)
}

/// The FPU chain's q̈ through the validated handle's hook.
#[inline(never)]
pub fn fpu(sys: &Validated<fpu::fpu_chain::Fpu>, q: &[f64; 6], v: &[f64; 6]) -> [f64; 6] {
    sys.accelerations_at(0.0, q, v).unwrap()
}

/// The FPU chain's forces by hand (unit masses: its q̈).
#[inline(never)]
pub fn hw_fpu(q: &[f64; 6]) -> [f64; 6] {
    fpu::fpu_forces(50.0, q)
}

fn main() {
    let k = kepler::KEPLER.validated().unwrap();
    let f = fpu::fpu_chain::Fpu {
        m: 1.0,
        omega: 50.0,
    }
    .validated()
    .unwrap();
    let (q, q6) = (
        black_box([0.5, 0.3]),
        black_box([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]),
    );
    println!("{:?} {:?}", kepler(&k, &q, &q), hw_kepler(&q, &q));
    println!("{:?} {:?}", fpu(&f, &q6, &q6), hw_fpu(&q6));
}
