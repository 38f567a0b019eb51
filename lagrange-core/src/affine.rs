//! Mechanisms whose positions are affine in the coordinates: x(q) = A q + c, with A and c
//! functions of the parameters alone (a block sliding on a wedge, an Atwood machine, particles in
//! Cartesian coordinates with springs between them).
//!
//! Then, in the notation of [`crate::dynamics`], J = A is constant, so is
//! M = Aᵀ diag(μ) A, the velocity-product terms b = Aᵀ diag(μ) ẍ|_{q̈=0} vanish, and a uniform
//! field's generalized force Aᵀ w is constant too. What is left of M q̈ = 𝓕 − b at a state is
//!
//! ```text
//! q̈ = M⁻¹ (Aᵀ w − ∇V + Aᵀ F + Q),
//! ```
//!
//! with M⁻¹ applied by its LDLᵀ factors. [`AffineConstants`] holds A, the factors and Aᵀ w,
//! computed once when the mechanism is validated ([`crate::Validated`], through
//! [`Prepare`](crate::evaluation::Prepare)); [`accelerations`] is an evaluation with them: x(q)
//! in plain arithmetic when a potential or a force needs it, ∇V on gradient duals, no pass of
//! second derivatives, no assembly and no factorisation. `#[mechanism]` decides affinity from the
//! declaration's expressions, at compile time.
//!
//! A constrained mechanism with affine positions (a particle in Cartesian coordinates on a rod, a
//! sphere or a rough plane) starts its Schur-complement solve from the same constants
//! ([`crate::constraints::accelerations_prepared`]): u = M⁻¹𝓕, then M⁻¹rᵢ for each constraint row by
//! the prepared factors. With a uniform field as the only force u = M⁻¹Aᵀw is itself prepared.

use crate::dynamics::{
    accumulate, add_row, assemble_mass_matrix, cartesian_with_jacobian, finite_accelerations,
    gradient, mass_matrix_failure, potential_gradient,
};
use crate::error::Result;
use crate::geometry::Scalar;
use crate::linalg::{factor_pattern, mass_pattern, Ldlt};
use crate::model::{state_and_accelerations_finite, Model, GRADIENT_COEFFICIENTS};
use nalgebra::SVector;

/// The constants of an affine mechanism's equations of motion (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AffineConstants<const N: usize, const K: usize> {
    /// Row i of A = J (zero where row i of x is constant).
    jacobian: [SVector<f64, N>; K],
    /// M = Aᵀ diag(μ) A, factorised.
    mass_matrix: Ldlt<f64, N>,
    /// The factors of −M: q̈ = (−M)⁻¹ ∇V without negating ∇V (a potential the only force).
    negated_mass_matrix: Ldlt<f64, N>,
    /// Aᵀ w, the generalized force of a uniform field (zero without one).
    field_forces: SVector<f64, N>,
    /// M⁻¹ Aᵀ w: q̈ of a mechanism on which the field is the only force.
    field_accelerations: SVector<f64, N>,
    /// (−M)⁻¹ 1 = −1/Mⱼⱼ for each j where M is diagonal by its pattern (each coordinate moves
    /// particle coordinates no other moves): the scales of
    /// [`Model::scaled_potential_gradient`]. Meaningless for any other M, and not used.
    negated_inverse_diagonal: [f64; N],
    /// The constant factors of the scaled gradient with those scales
    /// ([`Model::gradient_coefficients`]).
    gradient_coefficients: [f64; GRADIENT_COEFFICIENTS],
}

impl<const N: usize, const K: usize> AffineConstants<N, K> {
    /// A, the factors of M and Aᵀ w of `model`, whose x must be affine in q and independent of t
    /// (`#[mechanism]` decides it from the declaration; checked in debug builds).
    ///
    /// Fails with [`Error::SingularMassMatrix`](crate::Error::SingularMassMatrix) when the
    /// constant mass matrix is not positive definite (a coordinate that moves no mass), naming
    /// the configuration q = 0.
    pub fn of<M: Model<N, K>>(model: &M) -> Result<Self> {
        let rows = jacobian_at(model, &[0.0; N]);
        debug_assert!(
            rows == jacobian_at(model, &std::array::from_fn(|j| 0.5 + 0.25 * j as f64)),
            "a mechanism prepared as affine has a Jacobian that changes with q"
        );
        let masses = model.masses();
        let mass_matrix = assemble_mass_matrix::<M, f64, N, K>(&masses, &rows);
        let factors = Ldlt::new(&mass_matrix).map_err(|e| {
            mass_matrix_failure::<M::Coords, f64, N>(&mass_matrix, e, 0.0, &[0.0; N])
        })?;
        let mut field_forces = None;
        if M::HAS_GRAVITY {
            let weights = model.weights();
            for (i, row) in rows.iter().enumerate() {
                if let Some(row) = row {
                    add_row::<M, f64, N, K>(&mut field_forces, i, row, weights[i]);
                }
            }
        }
        let field_forces = field_forces.unwrap_or_else(SVector::zeros);
        let negated_inverse_diagonal: [f64; N] =
            factors.negated().solve(&SVector::repeat(1.0)).into();
        Ok(AffineConstants {
            jacobian: rows.map(|row| row.unwrap_or_else(SVector::zeros)),
            mass_matrix: factors,
            negated_mass_matrix: factors.negated(),
            field_forces,
            field_accelerations: factors.solve(&field_forces),
            negated_inverse_diagonal,
            gradient_coefficients: model.gradient_coefficients(&negated_inverse_diagonal),
        })
    }

    /// The rows of A = J (zero where a row of x is constant).
    #[inline(always)]
    pub(crate) fn jacobian(&self) -> &[SVector<f64, N>; K] {
        &self.jacobian
    }

    /// Mⱼⱼ = Σᵢ μᵢ Aᵢⱼ², the mass matrix's diagonal, from the rows' masses `masses` (zero for rows
    /// that carry none).
    pub(crate) fn mass_diagonal(&self, masses: &[f64; K]) -> [f64; N] {
        std::array::from_fn(|j| {
            (0..K).fold(0.0, |m, k| {
                m + masses[k] * self.jacobian[k][j] * self.jacobian[k][j]
            })
        })
    }

    /// M⁻¹ b by the prepared factors, for any scalar, skipping the couplings `M` rules out by
    /// its declaration ([`Model::DEPENDS`]).
    #[inline(always)]
    pub(crate) fn solve_mass<M: Model<N, K>, S: Scalar>(&self, b: &SVector<S, N>) -> SVector<S, N> {
        let pattern = const { factor_pattern(&mass_pattern(&M::DEPENDS, M::INERTIAL)) };
        self.mass_matrix.solve_in(b, pattern)
    }

    /// −M⁻¹ b by the prepared factors of −M, as [`solve_mass`](Self::solve_mass) (and bit for
    /// bit the negation of its result, see [`Ldlt::negated`]).
    #[inline(always)]
    fn solve_negated_mass<M: Model<N, K>, S: Scalar>(&self, b: &SVector<S, N>) -> SVector<S, N> {
        let pattern = const { factor_pattern(&mass_pattern(&M::DEPENDS, M::INERTIAL)) };
        self.negated_mass_matrix.solve_in(b, pattern)
    }
}

/// Whether a pattern of M has no entry off its diagonal.
const fn is_diagonal<const N: usize>(pattern: &[[bool; N]; N]) -> bool {
    let mut i = 0;
    while i < N {
        let mut j = 0;
        while j < N {
            if i != j && pattern[i][j] {
                return false;
            }
            j += 1;
        }
        i += 1;
    }
    true
}

/// Whether row i of x may depend on q at all, by the declaration.
const fn moving_rows<const N: usize, const K: usize>(depends: &[[bool; N]; K]) -> [bool; K] {
    let mut moving = [false; K];
    let mut i = 0;
    while i < K {
        let mut j = 0;
        while j < N {
            moving[i] |= depends[i][j];
            j += 1;
        }
        i += 1;
    }
    moving
}

/// J at (t = 0, q) by one gradient pass; `None` for the rows that do not depend on q.
fn jacobian_at<M: Model<N, K>, const N: usize, const K: usize>(
    model: &M,
    q: &[f64; N],
) -> [Option<SVector<f64, N>>; K] {
    let (x, _, _) = cartesian_with_jacobian(model, 0.0, q);
    std::array::from_fn(|i| x[i].eps.0.map(|_| gradient(&x[i])))
}

/// q̈ of an affine mechanism at (t, q, q̇) from its prepared constants, for any scalar (see the
/// [module docs](self)).
///
/// ```
/// use lagrange_core::{affine, impl_mechanism, Mechanism, Model, Scalar, State};
///
/// /// A unit mass on a spring of stiffness 4 along a line, written by hand: x = q.
/// struct Spring;
/// impl Model<1, 1> for Spring {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 1] { [1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * x[0] * 2.0 }
/// }
/// impl_mechanism!(Spring, 1, 1, affine);
///
/// let constants = affine::AffineConstants::of(&Spring)?;
/// let a = affine::accelerations(&Spring, &constants, 0.0, &[0.5], &[0.0])?;
/// assert_eq!(a, [-2.0]);
/// // The validated handle evaluates the same way, with the constants it prepared.
/// let sys = Spring.validated()?;
/// assert_eq!(sys.accelerations(&State::at_rest([0.5]))?, [-2.0]);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[inline]
pub fn accelerations<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    // One branch, on q̈ alone: this is the integrators' hook, whose callers check the state (once
    // per step); what is left to check is what the evaluation made of it. M⁻¹ is prepared from
    // valid parameters and regular (`AffineConstants::of` refused it otherwise), so no pivot is
    // tested either: q̈ is non-finite only where 𝓕, or its solve, overflowed or was undefined.
    let qdd = free_accelerations(model, constants, t, q, v);
    finite_accelerations::<M::Coords, S, N>(qdd, t, q)
}

/// q̈ of an affine mechanism at (t, q, q̇) with every check of a call in one branch: `Some(q̈)`
/// when t, q, q̇ and q̈ are all finite, `None` otherwise — the caller then takes the checked path,
/// which says what failed (the state, or q̈ at a finite state). The prepared M is regular, so no
/// pivot is tested.
///
/// For a mechanism whose q̈ from the prepared constants is straight-line arithmetic that runs no
/// user code — `#[mechanism]` uses it when the positions are affine, no force is declared and
/// every potential's gradient is derived on its expression tree — so evaluating it at a state that
/// turns out non-finite costs only the wasted arithmetic: nothing can panic or loop, and the state
/// check that would have refused the state first is the same sum's test.
///
/// ```
/// use lagrange_core::{affine, impl_mechanism, Model, Scalar};
///
/// /// A unit mass on a spring of stiffness 4 along a line, written by hand: x = q.
/// struct Spring;
/// impl Model<1, 1> for Spring {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 1] { [1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * x[0] * 2.0 }
/// }
/// impl_mechanism!(Spring, 1, 1, affine);
///
/// let constants = affine::AffineConstants::of(&Spring)?;
/// assert_eq!(affine::regular_accelerations(&Spring, &constants, 0.0, &[0.5], &[0.0]), Some([-2.0]));
/// assert_eq!(affine::regular_accelerations(&Spring, &constants, 0.0, &[0.5], &[f64::NAN]), None);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[inline(always)]
pub fn regular_accelerations<M: Model<N, K>, const N: usize, const K: usize>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Option<[f64; N]> {
    let qdd: [f64; N] = free_accelerations(model, constants, t, q, v).into();
    state_and_accelerations_finite(t, q, v, &qdd).then_some(qdd)
}

/// M⁻¹ 𝓕 at (t, q, q̇) from the prepared constants (b = 0), unchecked: q̈ of the mechanism without
/// its constraints, which the constrained solve starts from. With a uniform field as the only force
/// it is the prepared M⁻¹ Aᵀ w, a constant; with a potential as the only one, (−M)⁻¹ ∇V by the
/// prepared factors of −M; where M is diagonal by its pattern (each coordinate moves particle
/// coordinates no other moves), the model's own ∇V with each slot's prepared −1/Mⱼⱼ joined to its
/// constant factors ([`Model::scaled_potential_gradient`]) when it writes one, otherwise ∇V times
/// those −1/Mⱼⱼ (the pattern of M leaving out every other term of the solve).
#[inline(always)]
pub(crate) fn free_accelerations<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> SVector<S, N> {
    if !(M::HAS_POTENTIAL || M::HAS_FORCES) {
        return constants.field_accelerations.map(S::from);
    }
    // Which rows move is a constant of the declaration, so the compiler knows every row's
    // presence (stored `Option`s would be branched on in every dual operation).
    let moving = const { moving_rows(&M::DEPENDS) };
    let rows: [Option<SVector<S, N>>; K] =
        std::array::from_fn(|i| moving[i].then(|| constants.jacobian[i].map(S::from)));
    let x = model.cartesian(t, q);
    let diagonal = const { is_diagonal(&mass_pattern(&M::DEPENDS, M::INERTIAL)) };
    if M::HAS_POTENTIAL && !(M::HAS_GRAVITY || M::HAS_FORCES) && diagonal {
        let (scale, prepared) = (
            &constants.negated_inverse_diagonal,
            &constants.gradient_coefficients,
        );
        if let Some(accelerations) =
            model.scaled_potential_gradient(t, q, &x, &rows, scale, prepared)
        {
            return accelerations;
        }
    }
    let potential_gradient = potential_gradient(model, t, q, &x, &rows);
    if !(M::HAS_GRAVITY || M::HAS_FORCES) {
        if let Some(gradient) = potential_gradient {
            return constants.solve_negated_mass::<M, S>(&gradient);
        }
    }
    let mut forces: Option<SVector<S, N>> = None;
    if M::HAS_GRAVITY {
        forces = Some(constants.field_forces.map(S::from));
    }
    if let Some(gradient) = potential_gradient {
        match &mut forces {
            Some(forces) => *forces -= gradient,
            None => forces = Some(-gradient),
        }
    }
    if M::HAS_FORCES {
        // ẋ = A q̇; then 𝓕 += Aᵀ F + Q by virtual work.
        let velocity = SVector::from(*v);
        let x_dot: [S; K] =
            std::array::from_fn(|i| rows[i].map_or(S::zero(), |row| row.dot(&velocity)));
        let mut cartesian_force = [S::zero(); K];
        let mut direct = [S::zero(); N];
        model.applied_forces(t, q, v, &x, &x_dot, &mut cartesian_force, &mut direct);
        for (i, row) in rows.iter().enumerate() {
            if let Some(row) = row {
                add_row::<M, S, N, K>(&mut forces, i, row, cartesian_force[i]);
            }
        }
        accumulate(&mut forces, SVector::from(direct));
    }
    constants.solve_mass::<M, S>(&forces.unwrap_or_else(SVector::zeros))
}
