//! Constraints the generalized coordinates do not absorb: closed loops, rheonomic guides, rolling
//! without slipping, contacts that can separate, and Coulomb friction.
//!
//! # Physics
//!
//! A mechanism with `C` constraint rows adds to M q̈ = 𝓕 − b (see [`crate::dynamics`]) one
//! generalized constraint force per row, λᵢ·rᵢ, where rᵢ ∈ ℝᴺ is the row's Jacobian:
//!
//! ```text
//! M q̈ = 𝓕 − b + Σᵢ λᵢ rᵢ,           rᵢ · q̈ = −βᵢ   for every active row i.
//! ```
//!
//! | kind | declared function | row rᵢ | βᵢ (acceleration-level bias) | multiplier |
//! |---|---|---|---|---|
//! | [`Holonomic`](ConstraintKind::Holonomic) | g(q, t, x) = 0 | ∂g/∂q (through x too) | d²/ds² g(q + s q̇, t + s)│₀ | free sign |
//! | [`Velocity`](ConstraintKind::Velocity) | h = A(q, t) q̇ + a(q, t) = 0 | ∂h/∂q̇ = A | d/ds h(q + s q̇, q̇, t + s)│₀ | free sign |
//! | [`Unilateral`](ConstraintKind::Unilateral) | c(q, t, x) ≥ 0 | ∂c/∂q | as holonomic, while in contact | λ ≥ 0 (pushes only) |
//! | [`Friction`](ConstraintKind::Friction) | slip velocity s = S(q, t) q̇ + s₀(q, t) | S = ∂s/∂q̇ | as velocity, while sticking | see below |
//!
//! This is the KKT system [M −Rᵀ; R 0][q̈; λ] = [𝓕 − b; −β], the index-1 form of
//! the equations of motion of a constrained mechanical system (Hairer & Wanner, *Solving Ordinary
//! Differential Equations II*, 2nd ed., §VII.1, eq. (1.46); Lagrange multipliers for
//! nonholonomic constraints linear in the velocities: Goldstein, Poole & Safko, *Classical
//! Mechanics*, 3rd ed., §2.4). It is solved by the Schur complement: with M = LDLᵀ,
//! (R M⁻¹ Rᵀ) λ = −β − R M⁻¹(𝓕 − b), then q̈ = M⁻¹(𝓕 − b + Rᵀλ). Every matrix stays N×N or C×C, so
//! sizes are const generics on stable Rust. **M must be positive definite** (the generalized
//! coordinates independent before the constraints are imposed); a singular M is
//! [`Error::SingularMassMatrix`](crate::Error::SingularMassMatrix) as without constraints. A
//! singular R M⁻¹ Rᵀ (redundant or contradictory constraints at this configuration) is
//! [`Error::SingularConstraints`](crate::Error::SingularConstraints), naming the rows involved.
//!
//! **Friction** follows the lecture's model (Cross, Caltech Ph106 Lecture 4, "Constraints"): the
//! contact constraint is holonomic (or unilateral) and the friction force is part of the constraint
//! force; unlike the normal force it does virtual work, so it stays in the equations. A friction
//! row j attached to normal row n has a slip velocity sⱼ, linear in q̇ (the tangential relative
//! velocity at the contact, written with ẋ). Its generalized force is fⱼ·Sⱼ, fⱼ being the tangential
//! force along the slip direction:
//! - **sliding** (sⱼ ≠ 0): fⱼ = −μₖ·sign(sⱼ)·|λₙ| (Coulomb's law; the friction force opposes the slip and
//!   its magnitude is proportional to the normal force, which itself depends on q̈, so the two are
//!   solved together: the Schur matrix R M⁻¹ Wᵀ is then not symmetric and is solved by LU);
//! - **sticking** (sⱼ = 0): the row is an active velocity constraint sⱼ = 0 and fⱼ = λⱼ is its
//!   multiplier, admissible while |λⱼ| ≤ μₛ|λₙ|.
//!
//! A [`Friction`](ConstraintKind::Friction) row is planar: one scalar slip velocity. Two such rows on
//! one contact give the *anisotropic* (box) law, each component bounded on its own.
//!
//! **Friction in a tangent plane** (the isotropic Coulomb cone, declared with a `Vec2` slip
//! velocity): a [`FrictionCone`](ConstraintKind::FrictionCone) pair of rows (j, k) carries the slip
//! velocity s = (sⱼ, sₖ), its components along two orthonormal tangent directions at the contact, and
//! the tangential force f = (fⱼ, fₖ) with generalized force fⱼSⱼ + fₖSₖ. Coulomb's law in its cone
//! form (Stewart, "Rigid-body dynamics with friction and impact", SIAM Review 42(1), 2000,
//! pp. 3–39: |F_t| ≤ μN, and F_t = −μN v_t/|v_t| while sliding):
//! - **sliding** (|s| > 0): f = −μₖ|λₙ| ŝ, ŝ = s/|s|. The direction depends on the state, not only on
//!   the mode, so unlike the planar row the coefficient of each tangent row in the Schur system is
//!   −μₖŝⱼ (still solved together with λₙ by LU);
//! - **sticking** (s = 0): both rows are active velocity constraints with multipliers fⱼ, fₖ,
//!   admissible while |f| = √(fⱼ² + fₖ²) ≤ μₛ|λₙ|; beyond it the contact starts sliding with ŝ
//!   opposite to the force static friction would have had to supply (exact when the tangential
//!   inverse inertia is isotropic, a particle or a body sliding without rolling).
//!
//! # Modes and events
//!
//! Which rows are enforced is the [`Mode`]: unilateral rows are in contact or separated, friction
//! rows stick or slide in one direction. [`infer_mode`] reads it from a state by complementarity
//! (a contact with c ≈ 0 and ċ ≈ 0 is active if its λ ≥ 0; a slip velocity ≈ 0 sticks if static
//! friction can hold it). A time loop ([`crate::integrate::Stepper`]) holds the mode over a step
//! ([`ContactModel`]: a declaration's `Dynamics::Contacts`) and locates the instant a mode
//! changes — contact, release (λ = 0), slip velocity reaching 0, static friction exceeded — by the
//! Illinois method (on the step length with a fixed step, to 1e-12 relative; on the dense output
//! of an adaptive step), so mode changes happen exactly once and never chatter. A sliding cone has no sign to fix during a step, so its slip
//! direction at the step's start, [`Mode::reference`], plays that part: the force opposes
//! ŝ·sign(ŝ·ŝ_ref), which continues smoothly through the instant the slip stops, and that instant is
//! the zero of s·ŝ_ref.
//!
//! **Impact law**: when a separated unilateral contact closes (c reaches 0 with ċ < 0), the
//! velocities jump by an impulse along the contact row (and the other active rows, which stay
//! satisfied): q̇⁺ = q̇⁻ + M⁻¹Rᵀp with ċ⁺ = −e·ċ⁻, e the [`ContactOptions::restitution`] (Newton's
//! restitution law; e = 0, the default, is a plastic impact after which the contact is active). The
//! impulse is frictionless (no tangential impulse). For a single contact row r the kinetic energy
//! lost (scleronomic contact) is ½(1 − e²)·(ċ⁻)²/(r M⁻¹ rᵀ): the impulse is p = −(1 + e)ċ⁻/(r M⁻¹ rᵀ)
//! and ΔT = p ċ⁻ + ½p²·r M⁻¹ rᵀ.
//!
//! # Drift
//!
//! Integrating the acceleration-level equations lets g and ġ drift (Hairer & Wanner II, §VII.2).
//! After each step, [`project`] moves q back onto the active position constraints by the
//! mass-weighted least-norm Newton correction q ← q − M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹g (iterated to round-off), then
//! q̇ onto the active velocity-level constraints, q̇ ← q̇ − M⁻¹Rᵀ(RM⁻¹Rᵀ)⁻¹(Rq̇ + r_t), which is exact
//! because they are linear in q̇ (the "coordinate projection" of Hairer & Wanner II, §VII.2,
//! eq. (2.19) ff., in the metric of M, so the correction removes the least kinetic energy).
//!
//! # Integrators
//!
//! Every integrator calls `Dynamics::check_constraints` on the state before a run (refusing a state
//! that violates the constraints) and `Dynamics::project` on the new (q, q̇) after every step,
//! before writing it back; both default to no-ops, so unconstrained mechanisms pay nothing. On a
//! declaration with unilateral contacts or friction every time loop holds the contact mode over a
//! step ([`ContactModel`]) and locates its changes; evaluated on its own, [`accelerations`] re-infers
//! the mode from the state at every call, which is right between events but would put each event
//! somewhere inside a step (an adaptive method would reject and shrink its steps around every
//! switch, and a contact drifting by round-off would chatter between modes).
//!
//! # Cost
//!
//! What a constraint adds to an evaluation of q̈ (the measured ratios are in the repository's
//! BENCHMARKS.md; reproduce them with
//! `cargo test --release -p lagrange-core --test constraints -- --ignored --nocapture`): for a
//! scleronomic mechanism, the position rows are evaluated once on the hyper-dual numbers that
//! already carry x(q) for M, 𝓕 and b, so G, ġ and β come with no second evaluation of x (or,
//! for rows `#[mechanism]` reads as expression trees, from their derivatives written out as
//! straight-line code, [`Constraints::position_constraint_derivatives`]); then
//! one LDLᵀ factorisation of M reused for M⁻¹(𝓕 − b) and M⁻¹Rᵀ, and one of the C×C Schur matrix.
//! A rheonomic mechanism evaluates x and g twice more (gradient, then along the motion). Through a
//! validated handle, a mechanism whose positions are affine in q (x = A q + c) has M factorised
//! once and no b ([`crate::affine`], [`accelerations_prepared`]); where its rows are all holonomic
//! and written out, they are straight-line code on x, A q̇ and A, q̈ is checked in one branch
//! ([`regular_accelerations_prepared`]) and the projection uses the same factors
//! ([`project_prepared`]). Each step
//! adds the projection (one or two Newton corrections and one velocity correction) and the
//! consistency check.
//!
//! # Quasi-velocities
//!
//! A rigid tree whose free or ball joints have the body's angular velocity for velocities
//! (`#[angular_velocity]`, [`Constraints::QUASI_VELOCITY_JOINTS`]) carries v with q̇ = G(q) v. The
//! rows are written on the coordinates' rates, and everything above is said of (q, q̇); the
//! public functions that take a state's velocities convert at their entry (q̇ = G v) and exit
//! (v̇ = B q̈ + Ḃ q̇, rows and generalized forces dual to v by Gᵀ). Each statement is unchanged by
//! the change of velocities at fixed q: the multipliers are the same, and the velocity projection
//! in the metric of M = Bᵀ M_v B onto R q̇ = r is the projection in the metric of M_v onto
//! (R G) v = r, so the impact law and the projection are those of v. `consistent_state_holding`
//! refuses to hold a component of an angular velocity (ω = B(q) ċ moves with q where ċ is held).
//!
//! # Only what is declared
//!
//! Every branch on [`Constraints::KINDS`] is on a constant, so a mechanism with only holonomic rows
//! carries no velocity-row, contact or friction code after monomorphization, and a mechanism without
//! constraints does not implement [`Constraints`] at all (no KKT solve).

//! # Example: what a declaration with a `#[constraint]` expands to
//!
//! A planar pendulum in Cartesian coordinates: the bob (x, y) is kept at distance L from the pivot
//! by a holonomic constraint written on the bob's position. The impls are the shape the
//! `#[mechanism]` attribute generates; the constraint overrides of `Dynamics` (the glue beneath
//! `Mechanism`) are what makes every integrator enforce the constraints.
//!
//! ```
//! use lagrange_core::constraints::{self, ConstraintKind, Constraints, CONSISTENCY_TOLERANCE};
//! use lagrange_core::dynamics::{self, EquationsOfMotion};
//! use lagrange_core::evaluation::{Constants, Dynamics, Prepare};
//! use lagrange_core::{vec2, Mechanism, Model, Rk4, Scalar, State};
//!
//! struct Pendulum { m: f64, l: f64, g: f64 }
//!
//! impl Model<2, 2> for Pendulum {
//!     type Coords = [f64; 2];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [self.m, self.m] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D { x[1] * (self.m * self.g) }
//! }
//!
//! impl Constraints<2, 2, 1> for Pendulum {
//!     const NAMES: [&'static str; 1] = ["rod"];
//!     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
//!     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
//!         [vec2(x[0], x[1]).norm() - self.l]
//!     }
//! }
//!
//! // Nothing to prepare once from the parameters (see `Prepare`).
//! impl Prepare for Pendulum {
//!     type Prepared = ();
//!     fn prepare(&self) -> lagrange_core::Result<()> { Ok(()) }
//! }
//!
//! impl Dynamics<2> for Pendulum {
//!     type Coords = [f64; 2];
//!     // Its contact modes: none switch (a holonomic row is always enforced).
//!     type Contacts = constraints::ContactState<2, 1>;
//!     fn check_parameters(&self) -> lagrange_core::Result<()> { Model::validate(self) }
//!     fn equations_of_motion_at<S: Scalar>(&self, _: Constants<'_, Self>, t: S, q: &[S; 2], v: &[S; 2]) -> EquationsOfMotion<S, 2> {
//!         dynamics::equations_of_motion(self, t, q, v)
//!     }
//!     fn kinetic_energy_at<S: Scalar>(&self, _: Constants<'_, Self>, t: S, q: &[S; 2], v: &[S; 2]) -> S {
//!         dynamics::kinetic_energy(self, t, q, v)
//!     }
//!     fn potential_energy_at<S: Scalar>(&self, _: Constants<'_, Self>, t: S, q: &[S; 2]) -> S {
//!         dynamics::potential_energy(self, t, q)
//!     }
//!     fn momenta_at<S: Scalar>(&self, _: Constants<'_, Self>, t: S, q: &[S; 2], v: &[S; 2]) -> [S; 2] {
//!         dynamics::momenta(self, t, q, v)
//!     }
//!     fn lagrangian_time_derivative_at(&self, _: Constants<'_, Self>, t: f64, q: &[f64; 2], v: &[f64; 2]) -> f64 {
//!         dynamics::lagrangian_time_derivative(self, t, q, v)
//!     }
//!     // The three overrides of a constrained mechanism:
//!     fn accelerations_at<S: Scalar>(&self, _: Constants<'_, Self>, t: S, q: &[S; 2], v: &[S; 2]) -> lagrange_core::Result<[S; 2]> {
//!         constraints::accelerations(self, t, q, v)
//!     }
//!     fn project(&self, _: Constants<'_, Self>, t: f64, q: &mut [f64; 2], v: &mut [f64; 2]) -> lagrange_core::Result<()> {
//!         let mode = constraints::infer_mode(self, t, q, v)?;
//!         constraints::project(self, t, q, v, &mode)
//!     }
//!     fn check_constraints(&self, t: f64, q: &[f64; 2], v: &[f64; 2]) -> lagrange_core::Result<()> {
//!         constraints::check_consistent(self, t, q, v, CONSISTENCY_TOLERANCE)
//!     }
//! }
//!
//! let p = Pendulum { m: 1.0, l: 2.0, g: 9.81 };
//! // A guess off the circle is refused by the integrator, and projected on request.
//! let guess = State::new(0.0, [1.0, -1.5], [1.0, 0.0]);
//! assert!(p.step::<Rk4>(&mut guess.clone(), 1e-3).is_err());
//! let mut s = constraints::consistent_state(&p, &guess)?;
//! for _ in 0..1000 {
//!     p.step::<Rk4>(&mut s, 1e-3)?;
//! }
//! let [x, y] = s.q;
//! assert!(((x * x + y * y).sqrt() - 2.0).abs() < 1e-14);
//! // The multiplier of |r| − L is minus the rod tension m(g cos θ + L θ̇²).
//! let forces = constraints::constraint_forces(&p, &s)?;
//! let (cos, speed2) = (-y / 2.0, s.v[0] * s.v[0] + s.v[1] * s.v[1]);
//! assert!((-forces.multipliers[0] - (9.81 * cos + speed2 / 2.0)).abs() < 1e-10);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

// Index loops run over several fixed-size arrays in parallel (rows, kinds, modes, multipliers), and
// `!(x > tol)` is deliberate: it also rejects NaN.
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

mod cone;
mod consistency;
mod contact;
mod events;
mod forces;
mod kinds;
mod mode;
mod prepared;
mod projection;
mod quasi;
mod rows;
mod sliding;
mod solve;
mod switch;

pub use consistency::{
    check_consistent, check_velocity_rows_affine, consistent_state, consistent_state_holding,
    CONSISTENCY_TOLERANCE,
};
pub use contact::{row_count, ContactModel, ContactOptions, ContactState, ModeChange, NoContacts};
pub use forces::{constraint_forces, ConstraintForces};
pub use kinds::{check_declaration, ConstraintCounts, ConstraintKind};
pub use mode::{accelerations, infer_mode};
pub use prepared::{accelerations_prepared, project_prepared, regular_accelerations_prepared};
pub use projection::project;
pub(crate) use rows::rows_and_scales;
pub use rows::{constraint_rows, holonomic_values, CartesianMotion, ConstraintRows};
pub use solve::{accelerations_in_mode, ConstrainedAccelerations};

use crate::dynamics::EquationsOfMotion;
use crate::geometry::Scalar;
use crate::model::Model;
use crate::tree::rigid::Joint;

/// Coulomb friction coefficients of a friction row.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Coulomb {
    /// μₖ: sliding friction, |f| = μₖ|λₙ| while slipping.
    pub kinetic: f64,
    /// μₛ ≥ μₖ: sticking holds while |f| ≤ μₛ|λₙ|.
    pub stiction: f64,
}

/// The state of one constraint row in a [`Mode`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowMode {
    /// Enforced (holonomic and velocity rows always; a unilateral row in contact).
    Active,
    /// Not enforced: a separated unilateral row, or a friction row whose contact is separated.
    Inactive,
    /// A friction row with zero slip, enforced as s = 0.
    Stick,
    /// A friction row sliding with s > 0.
    SlipPositive,
    /// A friction row sliding with s < 0.
    SlipNegative,
    /// Both rows of a friction cone sliding: the friction force is −μₖ|λₙ| times the unit slip
    /// direction in the tangent plane (continued through [`Mode::reference`] within a step).
    Sliding,
}

/// Which constraint rows are enforced, and how friction rows act.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mode<const C: usize> {
    /// One entry per row, in declaration order.
    pub rows: [RowMode; C],
    /// For the two rows of a sliding friction cone: the unit slip direction (its components along
    /// the two tangent rows) at the start of the current step. The friction force opposes ŝ·sign(ŝ·ŝ_ref):
    /// the slip direction, continued smoothly past an instant where the slip stops, so that the
    /// event "slip stopped" (s·ŝ_ref = 0) can be located instead of the force flipping inside a step.
    /// Zero for every other row.
    pub reference: [f64; C],
    /// For the rows of a sliding friction cone whose slip is predicted to stop within the current
    /// step: the force is held at −μₖ|λₙ| ŝ_ref for the step. Near a stop the slip direction turns
    /// without bound (ŝ is not smooth at s = 0), and a step through it would swing s around the
    /// origin instead of through it; held, s crosses zero along a line and the stop is located.
    pub stopping: [bool; C],
}

impl<const C: usize> Mode<C> {
    /// Every row enforced: holonomic, velocity and unilateral rows active, friction rows sticking.
    pub fn all_active<M: Constraints<N, K, C>, const N: usize, const K: usize>() -> Self {
        Mode {
            rows: std::array::from_fn(|i| match M::KINDS[i] {
                ConstraintKind::Friction { .. } | ConstraintKind::FrictionCone { .. } => {
                    RowMode::Stick
                }
                _ => RowMode::Active,
            }),
            reference: [0.0; C],
            stopping: [false; C],
        }
    }
    /// Whether row `i` is enforced as a constraint (contributes a row to the KKT system).
    pub fn enforced(&self, i: usize) -> bool {
        matches!(self.rows[i], RowMode::Active | RowMode::Stick)
    }
}

/// The constraints of a mechanism: what `#[constraint]`, `#[velocity_constraint]`, `#[unilateral]`
/// and `#[friction]` items compile to, on top of its [`Model`].
///
/// # Contract for implementors (the `#[mechanism]` expansion)
///
/// `C` is the number of rows, in declaration order; each declaration item is one row (a friction
/// item is its own row, after or before its contact row, pointing at it by index).
///
/// - [`NAMES`](Self::NAMES): the item names, used in error messages.
/// - [`KINDS`](Self::KINDS): one [`ConstraintKind`] per row. For `Friction { normal }`, `normal`
///   must index a row of another kind. Checked by [`check_declaration`].
/// - [`position_constraints`](Self::position_constraints) returns one value per row: g(q, t, x)
///   for holonomic rows, c(q, t, x) for unilateral rows (≥ 0 means admissible, the force pushes
///   towards increasing c) and **zero for every other row**. `x` is [`Model::cartesian`] at the
///   same (t, q), so constraints can be written on body positions. It must not read velocities.
///   It is evaluated on `f64`, gradient duals (for ∂/∂q), second-order duals (for β) and nested duals,
///   so it must be written generically, like `cartesian`.
/// - [`velocity_constraints`](Self::velocity_constraints) returns one value per row: h for
///   velocity rows, the slip velocity s for friction rows (its sign defines the slip direction; the
///   friction force opposes it) and **zero for every other row**. `x_dot` is ẋ = J q̇ + ∂x/∂t at the
///   same state. The function must be affine in `v` (and in `x_dot`, which is affine in `v`):
///   h(q, v) = A(q, t) v + a(q, t). This is checked at run time by [`check_consistent`]
///   ([`Error::NonlinearVelocityConstraint`](crate::Error::NonlinearVelocityConstraint)).
/// - Explicit time dependence: if any constraint reads `t`, [`Model::RHEONOMIC`] must be `true`
///   (otherwise the time derivatives are not seeded and the constraint is treated as frozen in time).
/// - [`friction_coefficients`](Self::friction_coefficients)`(i)` for each friction row `i`
///   (parameters of the mechanism, so a method, not a constant); [`validate_constraints`](Self::validate_constraints)
///   checks them (finite, 0 ≤ μₖ ≤ μₛ) and is called by the steppers.
///
/// The generated `Mechanism` impl then overrides
/// `Dynamics::accelerations_at` with [`accelerations`],
/// `Dynamics::project` with [`project`] in the [`infer_mode`]d mode, and
/// `Dynamics::check_constraints` with [`check_consistent`],
/// so every integrator that calls the hooks enforces the constraints, and names its contact modes
/// `Dynamics::Contacts` = [`ContactState`], which the time loops hold over a step to locate mode
/// changes; the [module example](self) shows the exact code.
pub trait Constraints<const N: usize, const K: usize, const C: usize>: Model<N, K> {
    /// Row names, in declaration order.
    const NAMES: [&'static str; C];
    /// Row kinds, in declaration order.
    const KINDS: [ConstraintKind; C];

    /// The rigid tree's joints when some of its free or ball joints have the body's angular
    /// velocity for velocities (`#[angular_velocity]`, `Dynamics::QUASI_VELOCITY_JOINTS`); none
    /// (the default) where every velocity is its coordinate's rate. The rows, the solve and the
    /// projection work on the coordinates' rates q̇ = G(q) v; the functions of this module that
    /// take a state's velocities convert at their entry and exit (see
    /// [the module's docs](crate::constraints#quasi-velocities)).
    const QUASI_VELOCITY_JOINTS: &'static [Joint] = &[];

    /// g or c for position rows (holonomic, unilateral); zero for the others.
    fn position_constraints<D: Scalar>(&self, t: D, q: &[D; N], x: &[D; K]) -> [D; C];

    /// M, 𝓕 and b at (t, q, q̇), q̇ the coordinates' rates, with the forces of `forces` (the
    /// declaration, or the declaration with its inputs held), formed otherwise than by the
    /// Cartesian pass: `#[mechanism]` writes it for a declaration the rigid tree pass takes (the
    /// composite-rigid-body algorithm and Newton–Euler,
    /// [`equations_of_motion_in_rates`](crate::tree::rigid::equations_of_motion_in_rates)), and
    /// the constrained solve then takes them, the Cartesian pass forming the rows alone. `None`
    /// (the default): the solve forms M, 𝓕 and b from the same Cartesian pass as the rows.
    #[inline(always)]
    fn tree_equations<F: Model<N, K>, S: Scalar>(
        &self,
        forces: &F,
        t: S,
        q: &[S; N],
        rates: &[S; N],
    ) -> Option<EquationsOfMotion<S, N>> {
        let _ = (forces, t, q, rates);
        None
    }

    /// The position rows whose derivatives [`position_constraint_derivatives`](Self::position_constraint_derivatives)
    /// writes out; the others are differentiated on dual numbers through
    /// [`position_constraints`](Self::position_constraints). None by default.
    const POSITION_DERIVATIVES: [bool; C] = [false; C];

    /// For each row of [`POSITION_DERIVATIVES`](Self::POSITION_DERIVATIVES), written into `rows`:
    /// its value g, its row G = ∂g/∂q + Σᵣ (∂g/∂xᵣ) Jᵣ (through x, whose rows J, ẋ and
    /// accelerations at q̈ = 0 `motion` gives), its rate ġ = d/ds g(q + s q̇, t + s)│₀ and its bias
    /// β = d²/ds² g(q + s q̇, t + s)│₀ (the table of the [module docs](self)).
    /// Every other entry is left as it is. What the dual numbers would give, to round-off; the
    /// `#[mechanism]` attribute writes it for the rows whose bodies it reads as expression trees,
    /// as straight-line code (the cost of the rows is then that of the formulas, not of dual
    /// arithmetic). The default writes nothing.
    ///
    /// ```
    /// use lagrange_core::constraints::{
    ///     constraint_rows, CartesianMotion, ConstraintKind, ConstraintRows, Constraints,
    /// };
    /// # use lagrange_core::{vec2, Model, Scalar};
    /// # use nalgebra::SVector;
    /// # struct Bead;
    /// # impl Model<2, 2> for Bead {
    /// #     type Coords = [f64; 2];
    /// #     const RHEONOMIC: bool = false;
    /// #     const HAS_POTENTIAL: bool = false;
    /// #     const HAS_FORCES: bool = false;
    /// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    /// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
    /// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
    /// # }
    /// // A bead on the unit circle, g = |r| − 1: G = r̂, ġ = r̂·q̇, β = (|q̇|² − ġ²)/|r|.
    /// impl Constraints<2, 2, 1> for Bead {
    ///     const NAMES: [&'static str; 1] = ["circle"];
    ///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    ///     const POSITION_DERIVATIVES: [bool; 1] = [true];
    ///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
    ///         [vec2(x[0], x[1]).norm() - D::from(1.0)]
    ///     }
    ///     fn position_constraint_derivatives<S: Scalar>(
    ///         &self, _t: S, q: &[S; 2], v: &[S; 2],
    ///         _motion: &CartesianMotion<S, 2, 2>, rows: &mut ConstraintRows<S, 2, 1>,
    ///     ) {
    ///         let r = (q[0] * q[0] + q[1] * q[1]).sqrt();
    ///         let n = SVector::from([q[0] / r, q[1] / r]);
    ///         let rate = n[0] * v[0] + n[1] * v[1];
    ///         rows.value[0] = r - S::one();
    ///         rows.rows[0] = n;
    ///         rows.rate[0] = rate;
    ///         rows.bias[0] = (v[0] * v[0] + v[1] * v[1] - rate * rate) / r;
    ///     }
    /// }
    /// let cr = constraint_rows(&Bead, 0.0, &[0.6, 0.8], &[-0.8, 0.6]);
    /// assert!((cr.bias[0] - 1.0).abs() < 1e-15); // |q̇|²/|r| on the circle
    /// ```
    #[inline(always)]
    fn position_constraint_derivatives<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        v: &[S; N],
        motion: &CartesianMotion<S, N, K>,
        rows: &mut ConstraintRows<S, N, C>,
    ) {
        let _ = (t, q, v, motion, rows);
    }

    /// h for velocity rows, the slip velocity for friction rows; zero for the others. Affine in `v`.
    fn velocity_constraints<D: Scalar>(
        &self,
        t: D,
        q: &[D; N],
        v: &[D; N],
        x: &[D; K],
        x_dot: &[D; K],
    ) -> [D; C] {
        let _ = (t, q, v, x, x_dot);
        [D::zero(); C]
    }

    /// Coulomb coefficients of friction row `row` (ignored for other rows).
    fn friction_coefficients(&self, row: usize) -> Coulomb {
        let _ = row;
        Coulomb::default()
    }

    /// Checks the friction coefficients: finite and 0 ≤ μₖ ≤ μₛ. (μₖ > μₛ would let a stuck contact
    /// start sliding against the direction static friction resists, an inconsistent mode.)
    fn validate_constraints(&self) -> crate::Result<()> {
        check_declaration::<Self, N, K, C>()?;
        for (i, kind) in Self::KINDS.iter().enumerate() {
            if kind.friction_normal().is_some() {
                let Coulomb { kinetic, stiction } = self.friction_coefficients(i);
                if !(kinetic.is_finite()
                    && stiction.is_finite()
                    && 0.0 <= kinetic
                    && kinetic <= stiction)
                {
                    return Err(crate::Error::InvalidFriction {
                        constraint: Self::NAMES[i],
                        kinetic,
                        stiction,
                    });
                }
            }
        }
        Ok(())
    }
}
