//! What a row declares ([`ConstraintKind`]), how many rows of each kind a declaration has, the
//! check of the declaration, and what the constant [`Constraints::KINDS`] and
//! [`Constraints::POSITION_DERIVATIVES`] decide: predicates evaluated in `const` blocks, so the
//! branches they guard fold away.

use super::Constraints;

/// What one constraint row declares. See the [module docs](super) for the equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConstraintKind {
    /// g(q, t, x) = 0, from [`Constraints::position_constraints`].
    Holonomic,
    /// h(q, q̇, t, x, ẋ) = A(q, t) q̇ + a(q, t) = 0, from [`Constraints::velocity_constraints`].
    Velocity,
    /// c(q, t, x) ≥ 0, from [`Constraints::position_constraints`]; the force can only push (λ ≥ 0).
    Unilateral,
    /// Coulomb friction at the contact of row `normal` (a holonomic, velocity or unilateral row,
    /// not a friction row): the slip velocity s(q, q̇, t, x, ẋ), linear in q̇, comes from
    /// [`Constraints::velocity_constraints`]; coefficients from [`Constraints::friction_coefficients`].
    Friction {
        /// Index of the row whose multiplier is the normal force.
        normal: usize,
    },
    /// One of the two rows of isotropic Coulomb friction in a tangent plane (the friction cone) at
    /// the contact of row `normal`: its slip velocity is the component of the tangential relative
    /// velocity along one of two orthonormal tangent directions, `partner` the row of the other.
    /// The friction force (f₁, f₂) on the pair obeys |f| ≤ μ|λₙ| and opposes the slip direction
    /// while sliding; see the [module docs](super).
    FrictionCone {
        /// Index of the row whose multiplier is the normal force.
        normal: usize,
        /// Index of the other tangent row of the same contact.
        partner: usize,
    },
}

impl ConstraintKind {
    /// Whether the row is declared by a position-level function (holonomic or unilateral).
    pub const fn is_position(self) -> bool {
        matches!(self, ConstraintKind::Holonomic | ConstraintKind::Unilateral)
    }
    /// Whether the row is declared by a velocity-level function (velocity constraint or slip).
    pub const fn is_velocity(self) -> bool {
        matches!(
            self,
            ConstraintKind::Velocity
                | ConstraintKind::Friction { .. }
                | ConstraintKind::FrictionCone { .. }
        )
    }
    /// The normal row of a friction row (planar or cone), `None` for other kinds.
    ///
    /// ```
    /// use lagrange_core::constraints::ConstraintKind;
    /// let cone = ConstraintKind::FrictionCone { normal: 0, partner: 2 };
    /// assert_eq!(cone.friction_normal(), Some(0));
    /// assert_eq!(ConstraintKind::Unilateral.friction_normal(), None);
    /// ```
    pub const fn friction_normal(self) -> Option<usize> {
        match self {
            ConstraintKind::Friction { normal } | ConstraintKind::FrictionCone { normal, .. } => {
                Some(normal)
            }
            _ => None,
        }
    }
}

/// How many rows of each [`ConstraintKind`] a declaration has: what
/// `Dynamics::CONSTRAINT_COUNTS` declares, so integrators
/// decide from constants which constraints they can enforce.
///
/// ```
/// use lagrange_core::constraints::{ConstraintCounts, ConstraintKind};
/// let kinds = [ConstraintKind::Holonomic, ConstraintKind::Unilateral, ConstraintKind::Friction { normal: 1 }];
/// const NONE: ConstraintCounts = ConstraintCounts::NONE;
/// let counts = ConstraintCounts::of(&kinds);
/// assert_eq!((counts.holonomic, counts.unilateral, counts.friction, counts.rows()), (1, 1, 1, 3));
/// assert!(!counts.only_holonomic() && NONE.only_holonomic() && NONE.rows() == 0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ConstraintCounts {
    /// Holonomic rows g(q, t) = 0.
    pub holonomic: usize,
    /// Velocity rows A(q, t) q̇ + a(q, t) = 0.
    pub velocity: usize,
    /// Unilateral rows c(q, t) ≥ 0.
    pub unilateral: usize,
    /// Friction rows (a friction cone counts its two tangent rows).
    pub friction: usize,
}

impl ConstraintCounts {
    /// No constraint rows.
    pub const NONE: ConstraintCounts = ConstraintCounts {
        holonomic: 0,
        velocity: 0,
        unilateral: 0,
        friction: 0,
    };

    /// The counts of a declaration's [`Constraints::KINDS`].
    pub const fn of(kinds: &[ConstraintKind]) -> Self {
        let mut counts = Self::NONE;
        let mut i = 0;
        while i < kinds.len() {
            match kinds[i] {
                ConstraintKind::Holonomic => counts.holonomic += 1,
                ConstraintKind::Velocity => counts.velocity += 1,
                ConstraintKind::Unilateral => counts.unilateral += 1,
                ConstraintKind::Friction { .. } | ConstraintKind::FrictionCone { .. } => {
                    counts.friction += 1
                }
            }
            i += 1;
        }
        counts
    }

    /// Every row.
    pub const fn rows(self) -> usize {
        self.holonomic + self.velocity + self.unilateral + self.friction
    }

    /// Whether every row (if any) is holonomic: equality constraints on the configuration alone.
    pub const fn only_holonomic(self) -> bool {
        self.velocity == 0 && self.unilateral == 0 && self.friction == 0
    }
}

/// Checks [`Constraints::KINDS`]: each friction row points at a non-friction row.
pub fn check_declaration<
    M: Constraints<N, K, C> + ?Sized,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> crate::Result<()> {
    for (i, kind) in M::KINDS.iter().enumerate() {
        if let Some(normal) = kind.friction_normal() {
            if normal >= C || M::KINDS[normal].friction_normal().is_some() {
                return Err(crate::Error::InvalidConstraintDeclaration {
                    constraint: M::NAMES[i],
                    reason: format!("friction must point at a contact row, got row {normal}"),
                });
            }
        }
        if let ConstraintKind::FrictionCone { normal, partner } = *kind {
            let paired = partner < C
                && partner != i
                && M::KINDS[partner] == (ConstraintKind::FrictionCone { normal, partner: i });
            if !paired {
                return Err(crate::Error::InvalidConstraintDeclaration {
                    constraint: M::NAMES[i],
                    reason: format!(
                        "a friction cone row needs a partner row on the same contact pointing back, got row {partner}"
                    ),
                });
            }
        }
    }
    Ok(())
}

/// What [`any_kind`] asks of a row.
#[derive(Clone, Copy)]
enum KindTest {
    Position,
    Velocity,
    /// Enforced only in some modes: unilateral and friction rows.
    ModeDependent,
}

/// Whether any row of `kinds` passes `test`, as a `const fn` (a loop: iterators and calls through
/// function pointers are not `const`).
const fn any_kind(kinds: &[ConstraintKind], test: KindTest) -> bool {
    let mut i = 0;
    while i < kinds.len() {
        let k = kinds[i];
        let pass = match test {
            KindTest::Position => k.is_position(),
            KindTest::Velocity => k.is_velocity(),
            KindTest::ModeDependent => {
                !matches!(k, ConstraintKind::Holonomic | ConstraintKind::Velocity)
            }
        };
        if pass {
            return true;
        }
        i += 1;
    }
    false
}

/// Whether some position row of `kinds` has `written[i] == want` (a `const fn`, like [`any_kind`]).
const fn any_position_row(kinds: &[ConstraintKind], written: &[bool], want: bool) -> bool {
    let mut i = 0;
    while i < kinds.len() {
        if kinds[i].is_position() && written[i] == want {
            return true;
        }
        i += 1;
    }
    false
}

// The predicates below are evaluated in `const` blocks: a constant of the declaration, so the
// branches they guard fold away (as a runtime loop over `KINDS` they were not: measured with
// scripts/callgrind, the loop ran on every call).

#[inline(always)]
pub(super) fn has_position<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const { any_kind(&M::KINDS, KindTest::Position) }
}

#[inline(always)]
pub(super) fn has_velocity<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const { any_kind(&M::KINDS, KindTest::Velocity) }
}

/// Whether some position row is differentiated on dual numbers: one the model does not write the
/// derivatives of ([`Constraints::POSITION_DERIVATIVES`]).
#[inline(always)]
pub(super) fn has_position_on_duals<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const { any_position_row(&M::KINDS, &M::POSITION_DERIVATIVES, false) }
}

/// Whether the model writes the derivatives of some position row.
#[inline(always)]
pub(super) fn has_written_derivatives<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const { any_position_row(&M::KINDS, &M::POSITION_DERIVATIVES, true) }
}

/// Whether row `i` is a position row differentiated on dual numbers.
#[inline(always)]
pub(super) fn on_duals<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    i: usize,
) -> bool {
    M::KINDS[i].is_position() && !M::POSITION_DERIVATIVES[i]
}

/// Whether every row is always enforced (no unilateral, no friction rows): then no mode logic.
#[inline(always)]
pub(super) fn always_active<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const { !any_kind(&M::KINDS, KindTest::ModeDependent) }
}

/// Whether every row is holonomic with its derivatives written out
/// ([`Constraints::POSITION_DERIVATIVES`]) and the mechanism scleronomic: then the rows at a state
/// are straight-line code on x, ẋ and J alone, and every row is always enforced.
#[inline(always)]
pub(super) fn written_holonomic<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    const {
        !M::RHEONOMIC
            && !any_kind(&M::KINDS, KindTest::ModeDependent)
            && !any_kind(&M::KINDS, KindTest::Velocity)
            && !any_position_row(&M::KINDS, &M::POSITION_DERIVATIVES, false)
    }
}
