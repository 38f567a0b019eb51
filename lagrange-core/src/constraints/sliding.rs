//! Sliding friction in the KKT solve: the generalized force of a contact's normal row becomes
//! λₙ(rₙ − Σⱼ μₖ σⱼ sₙ Sⱼ), with the signs sₙ of bilateral normal forces found by re-solving.

use super::cone;
use super::rows::{real, ConstraintRows};
use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::error::{describe_configuration, Error, Result};
use crate::geometry::Scalar;
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

/// Solves with sliding friction tried before the signs of the bilateral normal forces are declared
/// inconsistent ([`Error::FrictionIndeterminate`]): two decide one normal row, the rest allow for
/// a flip of a second row.
const SIGN_ATTEMPTS: usize = 4;

/// σ of a planar friction row: +1 sliding with s > 0, −1 with s < 0, 0 otherwise.
pub(super) fn slip_sign(mode: RowMode) -> f64 {
    match mode {
        RowMode::SlipPositive => 1.0,
        RowMode::SlipNegative => -1.0,
        _ => 0.0,
    }
}

/// The frictionless system a sliding solve starts from: the constraint rows, yₖ = M⁻¹rₖ, the
/// right-hand side −β − R u of the Schur complement, the diagonal `filler` of the rows not
/// enforced, and which rows are enforced and which slide.
pub(super) struct SlidingSystem<'a, S: Scalar, const N: usize, const C: usize> {
    pub(super) rows: &'a ConstraintRows<S, N, C>,
    pub(super) y: &'a [SVector<S, N>; C],
    pub(super) rhs: SVector<S, C>,
    pub(super) filler: f64,
    pub(super) enforced: [bool; C],
    pub(super) sliding: [bool; C],
}

impl<S: Scalar, const N: usize, const C: usize> SlidingSystem<'_, S, N, C> {
    /// q̈ and λ with sliding friction, from u = M⁻¹(𝓕 − b) and the frictionless multipliers `lambda`
    /// (whose signs start the bilateral normal forces' signs), not yet checked finite.
    #[inline(always)]
    pub(super) fn solve<M: Constraints<N, K, C>, const K: usize>(
        &self,
        model: &M,
        t: S,
        q: &[S; N],
        mode: &Mode<C>,
        u: SVector<S, N>,
        lambda: SVector<S, C>,
    ) -> Result<(SVector<S, N>, [S; C])> {
        let (enforced, sliding) = (&self.enforced, &self.sliding);
        let direction = self.slip_directions::<M, K>(mode);
        let sign_n: [f64; C] = std::array::from_fn(|n| match M::KINDS[n] {
            ConstraintKind::Unilateral => 1.0,
            _ => {
                if lambda[n].re() < 0.0 {
                    -1.0
                } else {
                    1.0
                }
            }
        });
        let (columns, lambda, sign_n) = self.consistent_signs(model, t, q, &direction, sign_n)?;
        let mut multipliers = [S::zero(); C];
        let mut qdd = u;
        for k in 0..C {
            if enforced[k] {
                qdd += columns[k] * lambda[k];
                multipliers[k] = lambda[k];
            }
        }
        for j in 0..C {
            if let (true, Some(normal)) = (sliding[j], M::KINDS[j].friction_normal()) {
                let mu = model.friction_coefficients(j).kinetic;
                multipliers[j] = lambda[normal] * direction[j] * S::from(-mu * sign_n[normal]);
            }
        }
        Ok((qdd, multipliers))
    }

    /// σⱼ of each sliding row: the slip sign of a planar row, the component ŝⱼ of the unit slip
    /// direction of a cone's row (held at the reference while the slip is stopping).
    #[inline(always)]
    fn slip_directions<M: Constraints<N, K, C>, const K: usize>(&self, mode: &Mode<C>) -> [S; C] {
        let (cr, sliding) = (self.rows, &self.sliding);
        std::array::from_fn(|j| match M::KINDS[j] {
            ConstraintKind::FrictionCone { .. } if sliding[j] && mode.stopping[j] => {
                S::from(mode.reference[j])
            }
            ConstraintKind::FrictionCone { partner, .. } if sliding[j] => cone::sliding_direction(
                cr.value[j],
                cr.value[partner],
                mode.reference[j],
                mode.reference[partner],
            ),
            _ => S::from(slip_sign(mode.rows[j])),
        })
    }

    /// The columns λₙ multiplies (M⁻¹ times the generalized force per unit λ), λ and the signs of the
    /// normal forces, solved until the signs agree with the solution they give.
    ///
    /// Each attempt solves with the current signs and flips those the solution contradicts. With
    /// one bilateral normal row two attempts decide: if both signs contradict themselves, no normal
    /// force is consistent with sliding friction (Painlevé's inconsistent case). Several normal rows
    /// get a few more attempts; signs still inconsistent after them are the same error, never a
    /// solution computed with a sign its own normal force contradicts.
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    fn consistent_signs<M: Constraints<N, K, C>, const K: usize>(
        &self,
        model: &M,
        t: S,
        q: &[S; N],
        direction: &[S; C],
        mut sign_n: [f64; C],
    ) -> Result<([SVector<S, N>; C], SVector<S, C>, [f64; C])> {
        let (cr, y, enforced, sliding) = (self.rows, self.y, &self.enforced, &self.sliding);
        let mut columns = [SVector::<S, N>::zeros(); C];
        let indeterminate = || Error::FrictionIndeterminate {
            t: t.re(),
            configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, &real(q)),
            constraints: (0..C)
                .filter(|&j| sliding[j])
                .map(|j| format!("`{}`", M::NAMES[j]))
                .collect::<Vec<_>>()
                .join(", "),
        };
        for _attempt in 0..SIGN_ATTEMPTS {
            for k in 0..C {
                if enforced[k] {
                    columns[k] = y[k];
                }
            }
            for j in 0..C {
                if let (true, Some(normal)) = (sliding[j], M::KINDS[j].friction_normal()) {
                    let mu = model.friction_coefficients(j).kinetic;
                    columns[normal] -= y[j] * direction[j] * S::from(mu * sign_n[normal]);
                }
            }
            let mut a = SMatrix::<S, C, C>::zeros();
            for i in 0..C {
                if enforced[i] {
                    for k in 0..C {
                        if enforced[k] {
                            a[(i, k)] = cr.rows[i].dot(&columns[k]);
                        }
                    }
                } else {
                    a[(i, i)] = S::from(self.filler);
                }
            }
            let lambda = lu_solve_generic(&a, &self.rhs).ok_or_else(indeterminate)?;
            let mut consistent = true;
            for n in 0..C {
                if enforced[n]
                    && !matches!(M::KINDS[n], ConstraintKind::Unilateral)
                    && lambda[n].re() * sign_n[n] < 0.0
                {
                    sign_n[n] = -sign_n[n];
                    consistent = false;
                }
            }
            if consistent {
                return Ok((columns, lambda, sign_n));
            }
        }
        Err(indeterminate())
    }
}

/// Solves A x = b (general square, fixed size) by LU with scaled partial pivoting on the real parts
/// (pivots chosen and tested on the equilibrated matrix, as [`crate::linalg::BlockLu`]'s: a test
/// that rescaling a constraint row does not change); generic over the scalar so it differentiates
/// through dual numbers. `None` for a vanishing pivot or an entry that is not finite.
fn lu_solve_generic<S: Scalar, const C: usize>(
    a: &SMatrix<S, C, C>,
    b: &SVector<S, C>,
) -> Option<SVector<S, C>> {
    let mut a = *a;
    let mut x = *b;
    let magnitude = a.map(|v| v.re().abs());
    if !magnitude.iter().all(|v| v.is_finite()) {
        return None;
    }
    let columns: [f64; C] = std::array::from_fn(|c| 1.0 / magnitude.column(c).max());
    let mut rows: [f64; C] = std::array::from_fn(|r| {
        1.0 / (0..C).fold(0.0f64, |m, c| m.max(magnitude[(r, c)] * columns[c]))
    });
    if !columns.iter().chain(&rows).all(|s| s.is_finite()) {
        return None;
    }
    for c in 0..C {
        let mut p = c;
        for r in (c + 1)..C {
            if a[(r, c)].re().abs() * rows[r] > a[(p, c)].re().abs() * rows[p] {
                p = r;
            }
        }
        if !(a[(p, c)].re().abs() * rows[p] * columns[c] > crate::linalg::SINGULAR_PIVOT) {
            return None;
        }
        if p != c {
            a.swap_rows(p, c);
            x.swap_rows(p, c);
            rows.swap(p, c);
        }
        let inv = a[(c, c)].recip();
        for r in (c + 1)..C {
            let f = a[(r, c)] * inv;
            for k in c..C {
                let v = a[(c, k)];
                a[(r, k)] -= f * v;
            }
            let xc = x[c];
            x[r] -= f * xc;
        }
    }
    for r in (0..C).rev() {
        let mut s = x[r];
        for k in (r + 1)..C {
            s -= a[(r, k)] * x[k];
        }
        x[r] = s / a[(r, r)];
    }
    Some(x)
}
