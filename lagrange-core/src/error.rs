//! The errors a simulation can return. Nothing in the runtime panics on user input: a bad
//! parameter, a bad state, a bad step or a configuration where the equations of motion cannot be
//! solved is one of these, and the state the caller passed in is left as it was.

/// Everything that can go wrong while evaluating or stepping a mechanism.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter of the mechanism is NaN or infinite.
    #[error("parameter `{name}` is not finite ({value})")]
    NonFiniteParameter {
        /// The parameter, by its declared name.
        name: &'static str,
        /// Its value.
        value: f64,
    },

    /// A mass or moment of inertia is not positive, principal moments violate the triangle
    /// inequality (I₁ + I₂ ≥ I₃ and permutations), a full inertia tensor is not finite, symmetric
    /// and positive definite, or a centre of mass offset is not finite.
    #[error("body `{body}`: {reason}")]
    InvalidInertia {
        /// The body, by its declared name.
        body: &'static str,
        /// Which mass or moment is wrong, and how.
        reason: String,
    },

    /// A rotation a declaration writes from constants (parameters and literals) is not one: a
    /// `rot3` matrix that is not orthonormal with determinant +1, or a `rot_axis` axis without a
    /// direction (zero length, or not finite).
    #[error("`{body}`: {reason}")]
    InvalidRotation {
        /// The body (or other declared function) whose expression writes it, by its declared name.
        body: &'static str,
        /// What is wrong with it.
        reason: String,
    },

    /// The time, a coordinate or a velocity of the state is NaN or infinite.
    #[error("state is not finite: {state}")]
    NonFiniteState {
        /// The state, coordinate by coordinate.
        state: String,
    },

    /// The step size is zero, negative, NaN or infinite.
    #[error("step size must be positive and finite, got {h}")]
    InvalidStep {
        /// The step size given.
        h: f64,
    },

    /// The step size is positive but so small against the time that t + h == t in floating point
    /// (for example a subnormal h at t = 1): the step would not advance time.
    #[error("step size h = {h:e} does not advance t = {t} (t + h == t in floating point)")]
    StepDoesNotAdvance {
        /// The state's time.
        t: f64,
        /// The step size given.
        h: f64,
    },

    /// The end time of an integration is NaN, infinite or before the state's time (integration is
    /// forward in time only).
    #[error("end time {t_end} is not a finite time after the state's time t = {t}")]
    InvalidEndTime {
        /// The state's time.
        t: f64,
        /// The end time given.
        t_end: f64,
    },

    /// The mass matrix M(q, t) is singular (or not positive definite) at this configuration, so
    /// the accelerations are not determined — for example spherical coordinates at a pole.
    #[error("mass matrix is singular at t = {t}, {configuration} (pivot {pivot:e} of coordinate `{coordinate}`)")]
    SingularMassMatrix {
        /// The time at which it happened.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// The coordinate whose Cholesky pivot vanished.
        coordinate: &'static str,
        /// That pivot's value.
        pivot: f64,
    },

    /// The equations of motion produced a NaN or an infinity (for example a position function
    /// that divides by zero at this configuration).
    #[error("equations of motion are not finite at t = {t}, {configuration}")]
    NonFiniteDynamics {
        /// The time at which it happened.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
    },

    /// A Newton iteration of an implicit method did not converge.
    #[error("Newton iteration did not converge in {iterations} iterations at t = {t} (residual {residual:e})")]
    NewtonDiverged {
        /// The time at the start of the step.
        t: f64,
        /// Iterations done.
        iterations: usize,
        /// The largest residual left.
        residual: f64,
    },

    /// The Newton iteration of an implicit step broke down before it could converge: its matrix is
    /// not finite or singular, or its residual is not finite. Usually a step far too large for the
    /// mechanism's time scales (h² overflowing, stages far from the solution); `reason` says which.
    #[error("{method}: Newton iteration broke down at iteration {iteration} of the step from t = {t} with h = {h:e}: {reason}")]
    NewtonBreakdown {
        /// The method or options struct that reports it.
        method: &'static str,
        /// The time at the start of the step.
        t: f64,
        /// The step size.
        h: f64,
        /// The Newton iteration at which it broke down (from 1).
        iteration: usize,
        /// What broke down: a non-finite or singular matrix, or a non-finite residual.
        reason: String,
    },

    /// The method refuses this mechanism (for example Störmer–Verlet on a mass matrix that depends
    /// on the configuration).
    #[error("{method} cannot integrate this mechanism: {reason}")]
    UnsuitableMethod {
        /// The method or options struct that reports it.
        method: &'static str,
        /// What about the mechanism the method cannot handle.
        reason: String,
    },

    /// A setting of an integrator or of an options struct is out of its range (a negative
    /// tolerance, a safety factor above one, a restitution above one, …): see `Dopri5::validate`,
    /// `EquilibriumOptions::validate`, `ContactOptions::validate`.
    #[error("{method}: setting `{setting}` = {value} is invalid: it must be {requirement}")]
    InvalidSetting {
        /// The method or options struct that reports it.
        method: &'static str,
        /// The setting, by its field name.
        setting: &'static str,
        /// Its value.
        value: f64,
        /// What it must satisfy, in words.
        requirement: &'static str,
    },

    /// An adaptive method needed a step too small to advance time in floating point (a
    /// singularity of the solution, or a tolerance below round-off).
    #[error("{method}: step size underflow at t = {t} (h = {h:e}): the solution is singular there or the tolerance is below round-off")]
    StepSizeUnderflow {
        /// The method or options struct that reports it.
        method: &'static str,
        /// The time reached.
        t: f64,
        /// The step size that no longer advances time.
        h: f64,
    },

    /// The search for an equilibrium (all generalized forces balanced at rest) did not converge:
    /// too many iterations, or the line search stalled at a point that is not a root.
    #[error("no equilibrium found at t = {t} after {iterations} iterations: residual {residual:e} at {configuration}")]
    EquilibriumNotFound {
        /// The time the equilibrium is sought at.
        t: f64,
        /// Iterations done.
        iterations: usize,
        /// The largest unbalanced generalized force left.
        residual: f64,
        /// The last iterate, coordinate by coordinate.
        configuration: String,
    },

    /// A configuration passed as an equilibrium is not one: the generalized forces at rest do not
    /// balance there.
    #[error(
        "not an equilibrium at t = {t}, {configuration}: unbalanced generalized force {residual:e}"
    )]
    NotAnEquilibrium {
        /// The time the equilibrium is claimed at.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// The largest unbalanced generalized force.
        residual: f64,
    },

    /// Normal modes were asked for where they do not exist (an equilibrium that is not stable, or
    /// circulatory forces).
    #[error("no normal modes at t = {t}, {configuration}: {reason}")]
    NoNormalModes {
        /// The time of the configuration.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// Why, in words.
        reason: String,
    },

    /// An eigenvalue iteration did not converge.
    #[error("eigenvalue iteration did not converge at t = {t}, {configuration}")]
    EigenvalueFailure {
        /// The time of the configuration.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
    },

    /// The constraints enforced at this configuration are redundant or contradictory: the matrix
    /// G M⁻¹ Gᵀ of their rows is singular. Names the rows involved.
    #[error("constraints {constraints} are redundant or contradictory at t = {t}, {configuration} (pivot {pivot:e})")]
    SingularConstraints {
        /// The time at which it happened.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// The constraint rows involved, by their declared names.
        constraints: String,
        /// The vanishing pivot of the rows' matrix.
        pivot: f64,
    },

    /// A state violates the constraints beyond tolerance (and projection was not asked for).
    #[error("state violates the constraints at t = {t}: {residuals} (largest {residual:e}); make it consistent with `consistent_state` first")]
    ConstraintViolation {
        /// The time at which it happened.
        t: f64,
        /// The largest residual among the violated rows.
        residual: f64,
        /// Each violated row with its residual ("`rod` off by 1e-3").
        residuals: String,
    },

    /// Projecting a state onto the constraints did not converge (the guess is too far from the
    /// constraint manifold, or the constraints cannot be satisfied there).
    #[error("projection onto the constraints failed after {iterations} iterations (residual {residual:e}) from {state}")]
    ProjectionFailed {
        /// The time of the state.
        t: f64,
        /// Iterations done.
        iterations: usize,
        /// The largest position residual left.
        residual: f64,
        /// The state that was projected, coordinate by coordinate.
        state: String,
    },

    /// A velocity constraint or slip velocity is not linear in the generalized velocities.
    #[error("velocity constraint `{constraint}` is not linear in the velocities at t = {t}, {configuration} (deviation {deviation:e})")]
    NonlinearVelocityConstraint {
        /// The constraint row, by its declared name.
        constraint: &'static str,
        /// The time at which it happened.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// The quadratic term found along a test direction of the velocities.
        deviation: f64,
    },

    /// Sliding friction makes the contact forces indeterminate (or inconsistent): the
    /// friction-coupled constraint matrix is singular (Painlevé's paradox).
    #[error("sliding friction of {constraints} makes the contact forces indeterminate at t = {t}, {configuration}")]
    FrictionIndeterminate {
        /// The time at which it happened.
        t: f64,
        /// The configuration, coordinate by coordinate ("theta1 = 0.1, theta2 = -3").
        configuration: String,
        /// The constraint rows involved, by their declared names.
        constraints: String,
    },

    /// Friction coefficients that are not finite or not 0 ≤ μₖ ≤ μₛ.
    #[error("friction `{constraint}`: coefficients must satisfy 0 <= kinetic <= static, got kinetic {kinetic}, static {stiction}")]
    InvalidFriction {
        /// The constraint row, by its declared name.
        constraint: &'static str,
        /// The kinetic coefficient μₖ given.
        kinetic: f64,
        /// The static coefficient μₛ given.
        stiction: f64,
    },

    /// A constraint declaration that does not make sense (for example friction pointing at a row
    /// that is not a contact).
    #[error("constraint `{constraint}`: {reason}")]
    InvalidConstraintDeclaration {
        /// The constraint row, by its declared name.
        constraint: &'static str,
        /// What is wrong with it.
        reason: String,
    },

    /// More mode changes (contacts, releases, stick/slip switches) within one step than allowed.
    #[error("{events} mode changes within one step at t = {t} (Zeno behaviour or an inconsistent contact mode)")]
    TooManyEvents {
        /// The time at the start of the step.
        t: f64,
        /// How many mode changes were located in the step.
        events: usize,
    },

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

    /// A sensitivity seed names no parameter of the mechanism.
    #[error("no parameter named `{name}` to differentiate by; the parameters are {known}")]
    UnknownParameter {
        /// The name given.
        name: String,
        /// The mechanism's parameters, in declaration order.
        known: String,
    },

    /// A sensitivity seed names no input of the mechanism (or the mechanism declares no
    /// `#[inputs]`).
    #[error("no input named `{name}` to differentiate by; the inputs are {known}")]
    UnknownInput {
        /// The name given.
        name: String,
        /// The mechanism's inputs, flat, in declaration order.
        known: String,
    },

    /// A sensitivity seed names a parameter that enters the dynamics as a plain number (a mass, a
    /// moment of inertia or a uniform field's strength), which carries no derivative.
    #[error(
        "parameter `{name}` is a mass, a moment of inertia or the strength of a uniform field, \
         which the dynamics take as plain numbers: it cannot be differentiated by (positions, \
         potentials and forces can)"
    )]
    UnseedableParameter {
        /// The parameter's name.
        name: &'static str,
    },

    /// A sensitivity seed names a parameter beside a seed on an input: the forces read either
    /// parameters or inputs on dual numbers, not both (seeded on parameters alone, a driven
    /// mechanism's forces read the inputs it holds).
    #[error(
        "parameter `{name}` cannot be differentiated by in the same run as an input: seed the \
         parameters and the inputs in two runs, or declare the input as a parameter"
    )]
    ParameterSeedWithInputs {
        /// The parameter's name.
        name: &'static str,
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
