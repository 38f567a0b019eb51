//! Consistency of a state with the constraints: [`check_consistent`], [`check_velocity_rows_affine`],
//! [`CONSISTENCY_TOLERANCE`], and consistent states from a guess ([`consistent_state`],
//! [`consistent_state_holding`]).

use super::kinds::has_velocity;
use super::mode::friction_rows_follow;
use super::projection::project_holding;
use super::quasi;
use super::rows::rows_and_scales;
#[cfg(doc)]
use super::{infer_mode, project};
use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::dynamics;
use crate::error::{describe_configuration, Error, Result};
use crate::model::{Coordinates, State};
use num_dual::{Dual, Dual2};

/// Relative tolerance under which [`check_consistent`] accepts a state, [`infer_mode`] counts a
/// contact as closed or a slip velocity as zero, and [`project`] is done: each row's residual is
/// measured against its own size at the state (`RowScales`: the change of the row over a motion
/// of the configuration's own size, or at its velocity), so the test is the same in every system
/// of units and for a row written in any unit. States produced by [`project`] are at round-off,
/// far below it.
pub const CONSISTENCY_TOLERANCE: f64 = 1e-8;

/// √|Mⱼⱼ|: the weights that give the coordinates (and their rates) one unit.
pub(crate) fn mass_weights<const N: usize>(diagonal: &[f64; N]) -> [f64; N] {
    std::array::from_fn(|j| diagonal[j].abs().sqrt())
}

/// The rounding of a row's value at a state that gives it no size of its own (at rest, or at
/// the origin of every coordinate): 64ε·maxⱼ |rᵢⱼ|, each coordinate (or rate) moved by a rounding
/// of one of its units. Such a state has no length or time of its own to measure a residual
/// against (the step's would be one), so this floor is in the declaration's units; it only
/// decides residuals at round-off.
const ROUNDING_FLOOR: f64 = 64.0 * f64::EPSILON;

/// ‖rᵢ‖·‖x‖ for each row rᵢ (see [`RowScales`]): maxⱼ |rᵢⱼ|/wⱼ · maxⱼ wⱼ|xⱼ|, the change of the row
/// along the largest component of x in the kinetic metric; at least [`ROUNDING_FLOOR`] over
/// [`CONSISTENCY_TOLERANCE`] of the row's coefficients, so that a residual at round-off passes
/// where x = 0.
pub(crate) fn row_sizes<const N: usize, const C: usize>(
    rows: &[nalgebra::SVector<f64, N>; C],
    w: &[f64; N],
    x: &[f64; N],
) -> [f64; C] {
    let size = (0..N).fold(0.0f64, |m, j| m.max(w[j] * x[j].abs()));
    std::array::from_fn(|i| {
        let gradient = (0..N)
            .filter(|&j| w[j] > 0.0)
            .fold(0.0f64, |m, j| m.max(rows[i][j].abs() / w[j]));
        let floor = ROUNDING_FLOOR / CONSISTENCY_TOLERANCE * rows[i].amax();
        (gradient * size).max(floor)
    })
}

/// What each constraint row's residuals are measured against: its position-level value (g, c)
/// against ‖rᵢ‖·‖q‖, its velocity-level value (ġ, h, the slip s) against ‖rᵢ‖·‖q̇‖ + |rᵢ·q̇ − ṙateᵢ|,
/// with the norms weighted by the mass matrix's diagonal, ‖rᵢ‖ = maxⱼ |rᵢⱼ|/√Mⱼⱼ and
/// ‖q‖ = maxⱼ √Mⱼⱼ |qⱼ|: the change of the row along the largest motion of the configuration (of the
/// velocities) by the kinetic metric, plus the row's explicit time rate. Each is a size in the
/// row's own unit, whatever the units of the coordinates and the row, so a tolerance relative to
/// it is the same in every system of units (`tests/scale_matrix`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RowScales<const C: usize> {
    /// Per row, the size of its position-level value.
    pub position: [f64; C],
    /// Per row, the size of its velocity-level value.
    pub velocity: [f64; C],
}

impl<const C: usize> RowScales<C> {
    /// The scales of `rows` at (q, q̇), with Mⱼⱼ the mass matrix's diagonal.
    pub(crate) fn new<const N: usize>(
        rows: &super::rows::ConstraintRows<f64, N, C>,
        diagonal: &[f64; N],
        q: &[f64; N],
        v: &[f64; N],
    ) -> Self {
        let w = mass_weights(diagonal);
        let mut scales = RowScales {
            position: row_sizes(&rows.rows, &w, q),
            velocity: row_sizes(&rows.rows, &w, v),
        };
        for i in 0..C {
            // The part of the rate that is not r·q̇: ∂g/∂t, or a velocity row's a(q, t).
            let explicit = (rows.rate[i] - rows.rows[i].dot(&nalgebra::SVector::from(*v))).abs();
            scales.velocity[i] += explicit;
        }
        scales
    }

    /// Per row, the slip speed under which a friction row counts as sticking:
    /// [`CONSISTENCY_TOLERANCE`] of its velocity-level size.
    pub(crate) fn stick(&self) -> [f64; C] {
        self.velocity.map(|s| CONSISTENCY_TOLERANCE * s)
    }
}

/// Checks a state against the constraints: holonomic |g| and |ġ|, velocity |h|, unilateral c ≥ −tol
/// (and ċ ≥ −tol where c ≤ tol), each within `tol` (use [`CONSISTENCY_TOLERANCE`]) relative to
/// the row's own size at the state (see [`CONSISTENCY_TOLERANCE`]); and that every velocity and
/// friction row is affine in q̇: its second derivative along w = q̇ + (1, …, 1),
/// d²/ds² h(q, q̇ + s w), must vanish (exactly zero for affine code; allowed 1e-9 relative).
///
/// Cost: one pass over x with gradient and second-order duals (the rows, their rates and the mass
/// matrix's diagonal that sizes them), and for velocity rows one more dual pass for J w and one
/// second-order evaluation of h; cheap enough to run before every step
/// (`Dynamics::check_constraints`).
///
/// Errors, in this order: invalid friction coefficients, [`Error::NonlinearVelocityConstraint`]
/// (a property of the declaration, reported whether or not the state satisfies the rows),
/// [`Error::ConstraintViolation`] listing the violated rows and residuals.
pub fn check_consistent<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    tol: f64,
) -> Result<()> {
    check_consistent_in_rates(model, t, q, &quasi::rates::<M, f64, N, K, C>(q, v), tol)
}

/// [`check_consistent`] at (q, q̇), the coordinates' rates.
pub(crate) fn check_consistent_in_rates<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    tol: f64,
) -> Result<()> {
    model.validate_constraints()?;
    // The declaration first: a velocity row that is not affine in q̇ is refused whatever the state.
    check_velocity_rows_affine(model, t, q, v)?;
    let (cr, scales) = rows_and_scales(model, t, q, v);
    let (value, rate) = (cr.value, cr.rate);
    let mut violated = Vec::new();
    for i in 0..C {
        let (at_position, at_velocity) = (tol * scales.position[i], tol * scales.velocity[i]);
        // The residuals and whether each is within its row's tolerance.
        let (r, within) = match M::KINDS[i] {
            ConstraintKind::Holonomic => (
                value[i].abs().max(rate[i].abs()),
                value[i].abs() <= at_position && rate[i].abs() <= at_velocity,
            ),
            ConstraintKind::Velocity => (value[i].abs(), value[i].abs() <= at_velocity),
            ConstraintKind::Unilateral => {
                let pen = (-value[i]).max(0.0);
                if value[i] <= at_position {
                    let approach = (-rate[i]).max(0.0);
                    (
                        pen.max(approach),
                        pen <= at_position && approach <= at_velocity,
                    )
                } else {
                    (pen, true)
                }
            }
            ConstraintKind::Friction { .. } | ConstraintKind::FrictionCone { .. } => (0.0, true),
        };
        // `!within` with `r` NaN: a NaN residual fails both comparisons.
        if !within || r.is_nan() {
            violated.push((i, r));
        }
    }
    if !violated.is_empty() {
        let residual = violated.iter().fold(0.0f64, |m, x| m.max(x.1));
        return Err(Error::ConstraintViolation {
            t,
            residual,
            residuals: violated
                .iter()
                .map(|(i, r)| format!("`{}` off by {r:e}", M::NAMES[*i]))
                .collect::<Vec<_>>()
                .join(", "),
        });
    }
    Ok(())
}

/// Checks that every velocity row is affine in q̇ at (t, q, q̇) — what the declaration promises and
/// the solve relies on — as every entry point does, whatever the state's consistency. A mechanism
/// without velocity rows has nothing to check.
///
/// Errors: [`Error::NonlinearVelocityConstraint`], naming the row and its quadratic part.
pub fn check_velocity_rows_affine<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    if !has_velocity::<M, N, K, C>() {
        return Ok(());
    }
    let (x, x_dot) = dynamics::cartesian_velocities(model, t, q, v);
    velocity_rows_affine_at(model, t, q, v, &x, &x_dot)
}

/// [`check_velocity_rows_affine`] with x and ẋ at the state already evaluated.
fn velocity_rows_affine_at<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    x: &[f64; K],
    x_dot: &[f64; K],
) -> Result<()> {
    if !has_velocity::<M, N, K, C>() {
        return Ok(());
    }
    // Affine in q̇ ⇔ zero second derivative along any direction w; ẋ(q̇ + s w) = ẋ + s J w.
    let w: [f64; N] = std::array::from_fn(|j| v[j] + 1.0);
    let qw: [Dual<f64>; N] = std::array::from_fn(|j| Dual::new(q[j], w[j]));
    let jw = model.cartesian(Dual::from_re(t), &qw);
    let t2 = Dual2::from_re(t);
    let q2: [Dual2<f64>; N] = std::array::from_fn(|j| Dual2::from_re(q[j]));
    let v2: [Dual2<f64>; N] = std::array::from_fn(|j| Dual2::new(v[j], w[j], 0.0));
    let x2: [Dual2<f64>; K] = std::array::from_fn(|i| Dual2::from_re(x[i]));
    let xd2: [Dual2<f64>; K] = std::array::from_fn(|i| Dual2::new(x_dot[i], jw[i].eps, 0.0));
    let h = model.velocity_constraints(t2, &q2, &v2, &x2, &xd2);
    for i in 0..C {
        if !M::KINDS[i].is_velocity() {
            continue;
        }
        // The quadratic term at s = 1 against the size of the affine part there.
        let deviation = 0.5 * h[i].v2.abs();
        let size = h[i].re.abs() + h[i].v1.abs();
        if !(deviation <= 1e-9 * size) && deviation > 0.0 || !deviation.is_finite() {
            return Err(Error::NonlinearVelocityConstraint {
                constraint: M::NAMES[i],
                t,
                configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, q),
                deviation,
            });
        }
    }
    Ok(())
}

/// A state consistent with the constraints, from a guess: holonomic rows and unilateral rows with
/// c ≤ [`CONSISTENCY_TOLERANCE`] (touching or penetrating) are projected to g = 0, then velocities
/// onto every enforced row (friction rows whose slip is within tolerance are set to stick). The
/// result passes [`check_consistent`].
///
/// Errors: the projection fails ([`Error::ProjectionFailed`], with the residual), or the result still
/// violates the constraints ([`Error::ConstraintViolation`]).
pub fn consistent_state<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    guess: &State<M::Coords>,
) -> Result<State<M::Coords>> {
    consistent_state_holding(model, guess, &[], &[])
}

/// [`consistent_state`] that keeps the named coordinates and velocities exactly as in the guess
/// and solves the constraints for the others: start a four-bar or a slider-crank at a crank angle
/// of exactly 0.3 and crank rate exactly 2, and let the loop closure place the rest.
///
/// `hold_q` names coordinates whose values are kept, `hold_v` coordinates whose velocities are
/// kept (by the names of [`Coordinates::NAMES`]: `"phi"`, or `"theta[2]"` for an array
/// coordinate). Positions are projected with the held coordinates fixed, the mass-weighted
/// least-norm correction spread over the free ones; velocities likewise.
///
/// Errors, besides those of [`consistent_state`]: [`Error::UnknownCoordinate`] for a name that is
/// not a coordinate; [`Error::TooFewFreeCoordinates`] when fewer coordinates (velocities) are left
/// free than there are position (velocity-level) rows to satisfy. Holding a set that the
/// constraints cannot be solved around — a crank held at an angle the loop cannot close at, or
/// every free coordinate absent from a row — is [`Error::SingularConstraints`] or
/// [`Error::ProjectionFailed`], as for an impossible guess.
///
/// ```
/// use lagrange_core::analysis::doc_models::CartesianPendulum;
/// use lagrange_core::constraints::consistent_state_holding;
/// use lagrange_core::State;
///
/// // The bob on a rod of length 1: hold x = 0.6, solve for y (from a guess below the pivot).
/// let p = CartesianPendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let guess = State::new(0.0, [0.6, -0.5], [1.6, 0.0]);
/// let s = consistent_state_holding(&p, &guess, &["q0"], &["q0"])?;
/// assert_eq!(s.q[0], 0.6);
/// assert!((s.q[1] + 0.8).abs() < 1e-14);
/// // The rod is rigid: ẋ x + ẏ y = 0 with ẋ held at 1.6 gives ẏ = 1.2.
/// assert_eq!(s.v[0], 1.6);
/// assert!((s.v[1] - 1.2).abs() < 1e-14);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn consistent_state_holding<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    guess: &State<M::Coords>,
    hold_q: &[&str],
    hold_v: &[&str],
) -> Result<State<M::Coords>> {
    model.validate()?;
    let free_q = free_mask::<N>(&<M::Coords as Coordinates<N>>::NAMES, hold_q)?;
    let free_v = free_mask::<N>(&<M::Coords as Coordinates<N>>::NAMES, hold_v)?;
    let (mut q, v) = (guess.q.to_array(), guess.v.to_array());
    crate::model::check_state(&<M::Coords as Coordinates<N>>::NAMES, guess.t, &q, &v)?;
    refuse_held_angular_velocities::<M, N, K, C>(&free_v)?;
    // Projected in the coordinates' rates, the velocities converted back at the end.
    let mut v = quasi::rates::<M, f64, N, K, C>(&q, &v);
    // The declaration is checked before projecting (friction coefficients, velocity rows linear
    // in q̇); the guess itself may violate the rows.
    match check_consistent_in_rates(model, guess.t, &q, &v, CONSISTENCY_TOLERANCE) {
        Ok(()) | Err(Error::ConstraintViolation { .. }) => {}
        Err(e) => return Err(e),
    }
    let (cr, scales) = rows_and_scales(model, guess.t, &q, &v);
    let mut mode = Mode::all_active::<M, N, K>();
    for i in 0..C {
        if let ConstraintKind::Unilateral = M::KINDS[i] {
            if cr.value[i] > CONSISTENCY_TOLERANCE * scales.position[i] {
                mode.rows[i] = RowMode::Inactive;
            }
        }
    }
    friction_rows_follow(&M::KINDS, &mut mode, &cr.value, None, &scales.stick());
    let position_rows = (0..C)
        .filter(|&i| mode.enforced(i) && M::KINDS[i].is_position())
        .count();
    let velocity_rows = (0..C).filter(|&i| mode.enforced(i)).count();
    enough_free("coordinates", hold_q, &free_q, position_rows)?;
    enough_free("velocities", hold_v, &free_v, velocity_rows)?;
    project_holding(model, guess.t, &mut q, &mut v, &mode, &free_q, &free_v)?;
    check_consistent_in_rates(model, guess.t, &q, &v, CONSISTENCY_TOLERANCE)?;
    let v = quasi::velocities::<M, f64, N, K, C>(&q, &v);
    Ok(State::new(
        guess.t,
        M::Coords::from_array(q),
        M::Coords::from_array(v),
    ))
}

/// [`Error::UnsuitableMethod`] when a held velocity (`free_v` unset) is a component of an angular
/// velocity ([`Constraints::QUASI_VELOCITY_JOINTS`]): the velocities are projected as the
/// coordinates' rates, and ω = B(q) ċ moves with q even where ċ is held.
fn refuse_held_angular_velocities<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    free_v: &[bool; N],
) -> Result<()> {
    let angular = crate::tree::rigid::free::angular_velocity_slots(M::QUASI_VELOCITY_JOINTS);
    match (0..N).find(|&j| !free_v[j] && angular.contains(&j)) {
        None => Ok(()),
        Some(j) => Err(Error::UnsuitableMethod {
            method: "consistent_state_holding",
            reason: format!(
                "the velocity of `{}` is a component of an angular velocity \
                 (`#[angular_velocity]`), which the projection cannot hold: hold other \
                 velocities only",
                <M::Coords as Coordinates<N>>::NAMES[j]
            ),
        }),
    }
}

/// Which coordinates are free: all but the named ones; a name that is not a coordinate is
/// [`Error::UnknownCoordinate`].
fn free_mask<const N: usize>(names: &[&'static str; N], held: &[&str]) -> Result<[bool; N]> {
    let mut free = [true; N];
    for name in held {
        match names.iter().position(|n| n == name) {
            Some(j) => free[j] = false,
            None => {
                return Err(Error::UnknownCoordinate {
                    name: (*name).to_string(),
                    known: names
                        .iter()
                        .map(|n| format!("`{n}`"))
                        .collect::<Vec<_>>()
                        .join(", "),
                })
            }
        }
    }
    Ok(free)
}

/// [`Error::TooFewFreeCoordinates`] unless at least `rows` entries of `free` are set.
fn enough_free<const N: usize>(
    what: &'static str,
    held: &[&str],
    free: &[bool; N],
    rows: usize,
) -> Result<()> {
    let n_free = free.iter().filter(|&&f| f).count();
    if n_free >= rows {
        return Ok(());
    }
    Err(Error::TooFewFreeCoordinates {
        what,
        held: held
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
        free: n_free,
        rows,
        max: N - rows,
    })
}
