//! Each item kind of the declaration, checked numerically against a closed form derived by hand.
//!
//! Tolerances: unless said otherwise a comparison is between the generated accelerations (dual-number
//! derivatives, a small Cholesky solve) and a closed form of a few dozen flops from the same inputs;
//! both are accurate to a few ulps of the largest intermediate term, so they must agree to 1e-12
//! relative to the scale of the terms (which are O(10) here).

mod constraints;
mod forces;
mod parameters;
mod positions;
mod rigid_bodies;

/// |a − b| ≤ 1e-12 · (1 + |b|): see the module docs.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + b.abs())
}
