//! The errors a simulation can return. Nothing in the runtime panics on user input: a bad
//! parameter, a bad state, a bad step or a configuration where the equations of motion cannot be
//! solved is one of these, and the state the caller passed in is left as it was.

/// Everything that can go wrong while evaluating or stepping a mechanism.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter of the mechanism is NaN or infinite.
    #[error("parameter `{name}` is not finite ({value})")]
    NonFiniteParameter { name: &'static str, value: f64 },

    /// A mass or moment of inertia is not positive, or an inertia tensor violates the triangle
    /// inequality (I₁ + I₂ ≥ I₃ and permutations).
    #[error("body `{body}`: {reason}")]
    InvalidInertia { body: &'static str, reason: String },

    /// The time, a coordinate or a velocity of the state is NaN or infinite.
    #[error("state is not finite: {state}")]
    NonFiniteState { state: String },

    /// The step size is zero, negative, NaN or infinite.
    #[error("step size must be positive and finite, got {h}")]
    InvalidStep { h: f64 },

    /// The step size is positive but so small against the time that t + h == t in floating point
    /// (for example a subnormal h at t = 1): the step would not advance time.
    #[error("step size h = {h:e} does not advance t = {t} (t + h == t in floating point)")]
    StepDoesNotAdvance { t: f64, h: f64 },

    /// The end time of an integration is NaN, infinite or before the state's time (integration is
    /// forward in time only).
    #[error("end time {t_end} is not a finite time after the state's time t = {t}")]
    InvalidEndTime { t: f64, t_end: f64 },

    /// The mass matrix M(q, t) is singular (or not positive definite) at this configuration, so
    /// the accelerations are not determined — for example spherical coordinates at a pole.
    #[error("mass matrix is singular at t = {t}, {configuration} (pivot {pivot:e} of coordinate `{coordinate}`)")]
    SingularMassMatrix {
        t: f64,
        configuration: String,
        coordinate: &'static str,
        pivot: f64,
    },

    /// The equations of motion produced a NaN or an infinity (for example a position function
    /// that divides by zero at this configuration).
    #[error("equations of motion are not finite at t = {t}, {configuration}")]
    NonFiniteDynamics { t: f64, configuration: String },

    /// A Newton iteration of an implicit method did not converge.
    #[error("Newton iteration did not converge in {iterations} iterations at t = {t} (residual {residual:e})")]
    NewtonDiverged {
        t: f64,
        iterations: usize,
        residual: f64,
    },

    /// The Newton iteration of an implicit step broke down before it could converge: its matrix is
    /// not finite or singular, or its residual is not finite. Usually a step far too large for the
    /// mechanism's time scales (h² overflowing, stages far from the solution); `reason` says which.
    #[error("{method}: Newton iteration broke down at iteration {iteration} of the step from t = {t} with h = {h:e}: {reason}")]
    NewtonBreakdown {
        method: &'static str,
        t: f64,
        h: f64,
        iteration: usize,
        reason: String,
    },

    /// The method refuses this mechanism (for example Störmer–Verlet on a mass matrix that depends
    /// on the configuration).
    #[error("{method} cannot integrate this mechanism: {reason}")]
    UnsuitableMethod {
        method: &'static str,
        reason: String,
    },

    /// A setting of an integrator or of an options struct is out of its range (a negative
    /// tolerance, a safety factor above one, a restitution above one, …): see `Dopri5::validate`,
    /// `EquilibriumOptions::validate`, `ContactOptions::validate`.
    #[error("{method}: setting `{setting}` = {value} is invalid: it must be {requirement}")]
    InvalidSetting {
        method: &'static str,
        setting: &'static str,
        value: f64,
        requirement: &'static str,
    },

    /// An adaptive method needed a step too small to advance time in floating point (a
    /// singularity of the solution, or a tolerance below round-off).
    #[error("{method}: step size underflow at t = {t} (h = {h:e}): the solution is singular there or the tolerance is below round-off")]
    StepSizeUnderflow {
        method: &'static str,
        t: f64,
        h: f64,
    },

    /// The search for an equilibrium (all generalized forces balanced at rest) did not converge:
    /// too many iterations, or the line search stalled at a point that is not a root.
    #[error("no equilibrium found at t = {t} after {iterations} iterations: residual {residual:e} at {configuration}")]
    EquilibriumNotFound {
        t: f64,
        iterations: usize,
        residual: f64,
        configuration: String,
    },

    /// A configuration passed as an equilibrium is not one: the generalized forces at rest do not
    /// balance there.
    #[error(
        "not an equilibrium at t = {t}, {configuration}: unbalanced generalized force {residual:e}"
    )]
    NotAnEquilibrium {
        t: f64,
        configuration: String,
        residual: f64,
    },

    /// Normal modes were asked for where they do not exist (an equilibrium that is not stable, or
    /// circulatory forces).
    #[error("no normal modes at t = {t}, {configuration}: {reason}")]
    NoNormalModes {
        t: f64,
        configuration: String,
        reason: String,
    },

    /// An eigenvalue iteration did not converge.
    #[error("eigenvalue iteration did not converge at t = {t}, {configuration}")]
    EigenvalueFailure { t: f64, configuration: String },

    /// The constraints enforced at this configuration are redundant or contradictory: the matrix
    /// G M⁻¹ Gᵀ of their rows is singular. Names the rows involved.
    #[error("constraints {constraints} are redundant or contradictory at t = {t}, {configuration} (pivot {pivot:e})")]
    SingularConstraints {
        t: f64,
        configuration: String,
        constraints: String,
        pivot: f64,
    },

    /// A state violates the constraints beyond tolerance (and projection was not asked for).
    #[error("state violates the constraints at t = {t}: {residuals} (largest {residual:e}); make it consistent with `consistent_state` first")]
    ConstraintViolation {
        t: f64,
        residual: f64,
        residuals: String,
    },

    /// Projecting a state onto the constraints did not converge (the guess is too far from the
    /// constraint manifold, or the constraints cannot be satisfied there).
    #[error("projection onto the constraints failed after {iterations} iterations (residual {residual:e}) from {state}")]
    ProjectionFailed {
        t: f64,
        iterations: usize,
        residual: f64,
        state: String,
    },

    /// A velocity constraint or slip velocity is not linear in the generalized velocities.
    #[error("velocity constraint `{constraint}` is not linear in the velocities at t = {t}, {configuration} (deviation {deviation:e})")]
    NonlinearVelocityConstraint {
        constraint: &'static str,
        t: f64,
        configuration: String,
        deviation: f64,
    },

    /// Sliding friction makes the contact forces indeterminate (or inconsistent): the
    /// friction-coupled constraint matrix is singular (Painlevé's paradox).
    #[error("sliding friction of {constraints} makes the contact forces indeterminate at t = {t}, {configuration}")]
    FrictionIndeterminate {
        t: f64,
        configuration: String,
        constraints: String,
    },

    /// Friction coefficients that are not finite or not 0 ≤ μₖ ≤ μₛ.
    #[error("friction `{constraint}`: coefficients must satisfy 0 <= kinetic <= static, got kinetic {kinetic}, static {stiction}")]
    InvalidFriction {
        constraint: &'static str,
        kinetic: f64,
        stiction: f64,
    },

    /// A constraint declaration that does not make sense (for example friction pointing at a row
    /// that is not a contact).
    #[error("constraint `{constraint}`: {reason}")]
    InvalidConstraintDeclaration {
        constraint: &'static str,
        reason: String,
    },

    /// More mode changes (contacts, releases, stick/slip switches) within one step than allowed.
    #[error("{events} mode changes within one step at t = {t} (Zeno behaviour or an inconsistent contact mode)")]
    TooManyEvents { t: f64, events: usize },

    /// A coordinate named to be held (by
    /// [`consistent_state_holding`](crate::constraints::consistent_state_holding)) is not one of
    /// the mechanism's coordinates.
    #[error("no coordinate named `{name}` to hold; the coordinates are {known}")]
    UnknownCoordinate {
        /// The name given.
        name: String,
        /// The mechanism's coordinates, in declaration order.
        known: String,
    },

    /// Holding the named coordinates (or velocities) leaves fewer free ones than there are
    /// constraint rows to satisfy with them, so the constraints cannot be solved for the rest.
    #[error(
        "holding {held} leaves {free} free {what} for {rows} constraint rows: hold at most {max}"
    )]
    TooFewFreeCoordinates {
        /// `"coordinates"` (position rows) or `"velocities"` (velocity-level rows).
        what: &'static str,
        /// The held names.
        held: String,
        /// How many are left free.
        free: usize,
        /// How many constraint rows they must satisfy.
        rows: usize,
        /// The most that can be held.
        max: usize,
    },
}

/// Shorthand for results of this crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// "theta1 = 0.1, theta2 = -3": a configuration named by its coordinates, for error messages.
pub fn describe_configuration<const N: usize>(names: &[&'static str; N], q: &[f64; N]) -> String {
    let parts: Vec<String> = names
        .iter()
        .zip(q)
        .map(|(n, v)| format!("{n} = {v}"))
        .collect();
    parts.join(", ")
}

/// "t = 0, q = (x = 1, y = NaN), v = (...)": a whole state, for error messages.
pub fn describe_state<const N: usize>(
    names: &[&'static str; N],
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> String {
    format!(
        "t = {t}, q = ({}), v = ({})",
        describe_configuration(names, q),
        describe_configuration(names, v)
    )
}
