//! What the constant [`Constraints::KINDS`] and [`Constraints::POSITION_DERIVATIVES`] of a
//! declaration decide: predicates evaluated in `const` blocks, so the branches they guard fold
//! away.

use super::{ConstraintKind, Constraints};

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
