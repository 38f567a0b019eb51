//! Adaptive Radau IIA of order 5 — Hairer's RADAU5 — for stiff mechanisms.
//!
//! - Method: the 3-stage Radau IIA collocation method (nodes c = (4 − √6)/10, (4 + √6)/10, 1),
//!   order 5, L-stable, stiffly accurate (Hairer & Wanner, *Solving ODEs II* (HW II), §IV.5,
//!   Table 5.6; the implementation follows §IV.8 and Hairer's code `radau5.f`, version of 1996–2002).
//!   It is applied to the first-order system y = (q, v), y' = f(t, y) = (v, q̈(t, q, v)), with q̈
//!   the mechanism's accelerations (on a constrained mechanism these include the constraint forces,
//!   as for [`Dopri5`](super::Dopri5)).
//! - Stage equations: for Z = (Z₁, Z₂, Z₃), Zᵢ = yᵢ − y₀, the collocation equations
//!   Zᵢ = h Σⱼ aᵢⱼ f(t₀ + cⱼh, y₀ + Zⱼ) are solved by the **simplified Newton iteration** of HW II
//!   §IV.8, (8.5)–(8.17): with W = T⁻¹Z (T the eigenvector matrix of A⁻¹, eigenvalues γ̂ and
//!   α̂ ± iβ̂), the 6N-dimensional linear system splits into a real system with matrix
//!   γ̂/h·I − J and a complex one with (α̂ + iβ̂)/h·I − J, J = ∂f/∂y at (t₀, y₀).
//! - Second-order structure: J = [[0, I], [∂q̈/∂q, ∂q̈/∂v]], so (σI − J)(x, y) = (r₁, r₂) reduces to
//!   (σ²I − σ∂q̈/∂v − ∂q̈/∂q) x = r₂ + (σI − ∂q̈/∂v) r₁, y = σx − r₁: an N-square system (the
//!   reduction `radau5.f` makes for problems with the special structure y'ᵢ = y_{i+M2}, its options
//!   M1, M2). The real matrix is factorised as an N-square block LU (the one the Gauss methods use), the complex one in its real
//!   form [[Re K, −Im K], [Im K, Re K]] as a 2N-square one: about 3N³ flops per
//!   factorisation against (6N)³/3 = 72N³ for the unsplit system.
//! - Reuse: the Jacobians ∂q̈/∂q, ∂q̈/∂v (exact, by dual numbers, [`acceleration_jacobians`](super::acceleration_jacobians)) are
//!   kept across iterations and steps while the Newton contraction rate θ stays below
//!   [`Radau5::jacobian_theta`], and the factorisation too while moreover the proposed step changes
//!   by less than the factors in [`Radau5::keep_step`] (then the step is kept as it is);
//!   otherwise the Jacobian (θ large) or the factorisation (h changed) is recomputed (`radau5.f`,
//!   THET, QUOT1, QUOT2).
//! - Newton stopping: the iteration stops when η‖ΔW‖ ≤ κ·tol with η = θ/(1 − θ) (HW II (8.10),
//!   (8.13); κ·tol = max(10ε/rtol′, min(0.03, √rtol′)) as in `radau5.f`); it is abandoned (the
//!   step rejected and shrunk as in `radau5.f`) when θ ≥ 0.99, when the predicted error after
//!   the remaining iterations is too large, or after [`Radau5::max_newton_iterations`]. Starting
//!   values extrapolate the previous step's collocation polynomial (HW II (8.16)).
//! - Error estimate: err = (γ₀h)⁻¹·(γ̂/h·I − J)⁻¹ applied to γ₀h f(y₀) + Σ eᵢZᵢ, as in `radau5.f`
//!   (HW II (8.19)–(8.20)), re-filtered through one more evaluation after a rejection or on the
//!   first step (8.21). Norm: √(1/(2N) Σ (errᵢ/scᵢ)²), scᵢ = atol′ + rtol′·|y₀ᵢ|.
//! - Tolerances: `radau5.f` replaces the user's (rtol, atol) with rtol′ = 0.1·rtol^(2/3),
//!   atol′ = rtol′·atol/rtol, so that the achieved error is roughly proportional to rtol; the same
//!   is done here.
//! - Step-size control: h_new = h·fac·err^(−1/4), fac = min(0.9, 0.9·(1 + 2k_max)/(k + 2k_max))
//!   (k Newton iterations), with Gustafsson's predictive controller (HW II (8.25)), h_new/h in
//!   [0.2, 8]; after a rejection the step does not grow.
//! - Dense output: the collocation polynomial (cubic; order 3 uniformly, the stage order), as
//!   `radau5.f`'s CONTR5.
//! - Events, the observer, the statistics and the contact mode are those of every solver
//!   ([`Stepper`](super::Stepper)). [`Stats::factorizations`](super::Stats::factorizations) counts one per refactorisation (the
//!   real and the complex matrix together, as `radau5.f`'s NDEC).
//! - Constraints: as [`Dopri5`](super::Dopri5), the start state must satisfy them and every
//!   accepted step is projected onto them; the dense output interpolates the step before
//!   projection.
//!
//! Integration is forward in time only.
//!
//! ```
//! use lagrange_core::integrate::{Radau5, Stepper};
//! use lagrange_core::{Model, Scalar, State};
//!
//! /// A stiff spring (ω = 1000) carrying a slow one (ω = 1), written by hand: two unit masses on
//! /// a line, x₁ tied to the wall by a spring of stiffness 1, x₂ tied to x₁ by one of 10⁶.
//! struct StiffPair;
//! impl Model<2, 2> for StiffPair {
//!     type Coords = [f64; 2];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
//!         x[0] * x[0] * 0.5 + (x[1] - x[0]) * (x[1] - x[0]) * 5e5
//!     }
//! }
//! lagrange_core::impl_mechanism!(StiffPair, 2, 2);
//!
//! // Released at rest along the slow normal mode, x₂/x₁ = 1 + (1 − λ)/10⁶ with λ ≈ 1/2 (both
//! // masses on the soft spring): the stiff mode is not excited (to O(10⁻¹²)), and
//! // x₁ = cos(√λ t) with λ = 1/2 up to 10⁻⁶.
//! let start = State::new(0.0, [1.0, 1.0 + 0.5e-6], [0.0, 0.0]);
//! let mut solver = Stepper::new(&StiffPair, Radau5::new(1e-8, 1e-8), &start)?;
//! let outcome = solver.integrate(10.0, &mut [], |_| {})?;
//! let exact = (0.5f64.sqrt() * 10.0).cos();
//! assert!((solver.state().q[0] - exact).abs() < 1e-5);
//! // An explicit method would need hω < 3.3, over 3000 steps; Radau5 follows the slow motion.
//! assert!(outcome.stats.accepted < 300, "{:?}", outcome.stats);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

// `!(a <= b)` comparisons are deliberate (they also catch NaN); the coefficients carry the digits
// of `radau5.f`.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::excessive_precision)]

mod algebra;
mod iteration;
mod memory;
mod rates;
mod settings;
mod step;

pub use memory::Radau5Memory;
pub use settings::Radau5;
