//! The Schur-complement solve of the KKT system in a mode: [`ConstrainedAccelerations`] and
//! [`accelerations_in_mode`] (sliding friction included).

use super::quasi;
use super::rows::{constraint_rows_in_rates, real, rows_from_pass, ConstraintRows};
use super::sliding::{slip_sign, SlidingSystem};
use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::affine::{self, AffineConstants};
use crate::dynamics::{self, EquationsOfMotion};
use crate::error::{describe_configuration, Error, Result};
use crate::geometry::Scalar;
use crate::linalg::{factor_pattern, mass_pattern, Ldlt, NotPositiveDefinite, SINGULAR_PIVOT};
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

/// The accelerations of a constrained mechanism and the multipliers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstrainedAccelerations<S: Scalar, const N: usize, const C: usize> {
    /// q̈.
    pub accelerations: [S; N],
    /// λᵢ: the generalized constraint force of row i is λᵢ·rᵢ. For a friction row, the tangential
    /// force along its slip direction (−μₖ·sign(s)·|λₙ| while sliding, the stick multiplier while
    /// sticking; for a cone's row, −μₖ|λₙ|ŝᵢ while sliding); zero for rows not enforced.
    pub multipliers: [S; C],
}

/// The error for a singular Schur matrix S = R M⁻¹ Rᵀ whose factorisation stopped at row
/// p: row p is (numerically) a combination of earlier rows k, S[p, ·] ≈ Σ cₖ S[k, ·] with
/// S₁₁ c = S[0..p, p]. The rows with a coefficient that matters are named with p.
pub(super) fn singular_constraints<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    e: NotPositiveDefinite,
    schur: &SMatrix<S, C, C>,
    enforced: &[bool; C],
    t: S,
    q: &[S; N],
) -> Error {
    let p = e.index;
    let s: SMatrix<f64, C, C> = schur.map(|x| x.re());
    // Dense solve of the leading p×p block by Gaussian elimination (p < C, tiny).
    let mut a = s;
    let mut b = SVector::<f64, C>::zeros();
    for k in 0..p {
        b[k] = s[(k, p)];
    }
    let mut c = [0.0f64; C];
    let mut ok = true;
    for col in 0..p {
        let mut piv = col;
        for r in col + 1..p {
            if a[(r, col)].abs() > a[(piv, col)].abs() {
                piv = r;
            }
        }
        if a[(piv, col)] == 0.0 {
            ok = false;
            break;
        }
        a.swap_rows(piv, col);
        b.swap_rows(piv, col);
        for r in col + 1..p {
            let f = a[(r, col)] / a[(col, col)];
            for k in col..p {
                a[(r, k)] -= f * a[(col, k)];
            }
            b[r] -= f * b[col];
        }
    }
    if ok {
        for r in (0..p).rev() {
            let mut acc = b[r];
            for k in r + 1..p {
                acc -= a[(r, k)] * c[k];
            }
            c[r] = acc / a[(r, r)];
        }
    }
    // cₖ carries the units of row p over those of row k: weighted by √Sₖₖ, the coefficients compare
    // rows whatever each is written in.
    let weight = |k: usize| c[k].abs() * s[(k, k)].abs().sqrt();
    let largest = (0..p).fold(0.0f64, |m, k| m.max(weight(k)));
    let mut names: Vec<&str> = (0..p)
        .filter(|&k| enforced[k] && ok && weight(k) > 1e-6 * largest.max(f64::MIN_POSITIVE))
        .map(|k| M::NAMES[k])
        .collect();
    names.push(M::NAMES[p]);
    Error::SingularConstraints {
        t: t.re(),
        configuration: describe_configuration(&<M::Coords as Coordinates<N>>::NAMES, &real(q)),
        constraints: names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
        pivot: e.pivot,
    }
}

/// λ from (R M⁻¹ Rᵀ) λ = rhs by LDLᵀ, with its relative pivot test. One row (C is a constant of the
/// declaration) is one division: the 1×1 factorisation's test, s > SINGULAR_PIVOT·|s|, then rhs/s.
#[inline(always)]
fn schur_solve<S: Scalar, const C: usize>(
    schur: &SMatrix<S, C, C>,
    rhs: &SVector<S, C>,
) -> std::result::Result<SVector<S, C>, NotPositiveDefinite> {
    if C == 1 {
        let s = schur[(0, 0)];
        if !(s.re() > SINGULAR_PIVOT * s.re().abs()) {
            return Err(NotPositiveDefinite {
                index: 0,
                pivot: s.re(),
            });
        }
        return Ok(rhs / s);
    }
    Ok(Ldlt::new(schur)?.solve(rhs))
}

/// q̈ and λ in a given [`Mode`], for any scalar: the Schur-complement solve of the KKT system (see the
/// [module docs](super)).
///
/// Errors: singular mass matrix, singular R M⁻¹ Rᵀ (naming the rows), indeterminate sliding
/// friction (the friction-coupled Schur matrix is singular: Painlevé's paradox), non-finite results.
#[inline(always)]
pub fn accelerations_in_mode<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    mode: &Mode<C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let rates = quasi::rates::<M, S, N, K, C>(q, v);
    let solved = accelerations_in_mode_in_rates(model, t, q, &rates, mode)?;
    Ok(ConstrainedAccelerations {
        accelerations: quasi::accelerations::<M, S, N, K, C>(q, &rates, &solved.accelerations),
        multipliers: solved.multipliers,
    })
}

/// [`accelerations_in_mode`] at (q, q̇), the coordinates' rates: q̈ and λ.
#[inline(always)]
pub(crate) fn accelerations_in_mode_in_rates<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    mode: &Mode<C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    // A rigid tree's recursions give M, 𝓕 and b where the declaration has them (the rows then
    // from a Cartesian pass of their own); otherwise the Cartesian pass gives both.
    match model.tree_equations(model, t, q, v) {
        Some(eom) => on_equations(model, t, q, v, mode, &eom),
        None => on_cartesian_pass(model, t, q, v, mode),
    }
}

// Each path of the solve is its own function in a build without optimisation, where frames are
// not shared: a rigid tree's solve then does not carry the Cartesian pass's large locals on the
// stack. Optimised, both are inlined and the path not taken is removed.

/// The solve on M, 𝓕 and b given (a rigid tree's), the rows by their own Cartesian pass.
#[cfg_attr(debug_assertions, inline(never))]
#[cfg_attr(not(debug_assertions), inline(always))]
fn on_equations<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    mode: &Mode<C>,
    eom: &EquationsOfMotion<S, N>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let (l, u) = factorised::<M, S, N, K, C>(eom, t, q)?;
    let rows = || constraint_rows_in_rates(model, t, q, v);
    solve_kkt(model, t, q, mode, |b| l.solve(b), u, rows)
}

/// The solve with M, 𝓕, b and the rows from one Cartesian pass (a scleronomic mechanism
/// evaluates x(q) once for all of them).
#[cfg_attr(debug_assertions, inline(never))]
#[cfg_attr(not(debug_assertions), inline(always))]
fn on_cartesian_pass<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    mode: &Mode<C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let pass = (!M::RHEONOMIC).then(|| dynamics::motion_pass(model, t, q, v));
    let eom = match &pass {
        Some(pass) => dynamics::equations_of_motion_from_pass(model, pass, t, q, v),
        None => dynamics::equations_of_motion(model, t, q, v),
    };
    let (l, u) = factorised::<M, S, N, K, C>(&eom, t, q)?;
    let rows = || match &pass {
        Some(pass) => rows_from_pass(model, pass, t, q, v).0,
        None => constraint_rows_in_rates(model, t, q, v),
    };
    solve_kkt(model, t, q, mode, |b| l.solve(b), u, rows)
}

/// The factors of M and u = M⁻¹(𝓕 − b).
type Factorised<S, const N: usize> = (Ldlt<S, N, [[bool; N]; N]>, SVector<S, N>);

/// M = LDLᵀ and u = M⁻¹(𝓕 − b). LDLᵀ with reciprocal pivots: no square roots, no divisions in
/// the solves (see `Ldlt`). The entries of L that the declaration rules out (coordinates no
/// massive row couples, and no elimination fills in) are constants: never formed, in the
/// factorisation or the C + 1 solves.
#[inline(always)]
fn factorised<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    eom: &EquationsOfMotion<S, N>,
    t: S,
    q: &[S; N],
) -> Result<Factorised<S, N>> {
    let pattern = const { factor_pattern(&mass_pattern(&M::DEPENDS, M::INERTIAL)) };
    let l = Ldlt::with_pattern(&eom.mass_matrix, pattern)
        .map_err(|e| dynamics::mass_matrix_failure::<M::Coords, S, N>(&eom.mass_matrix, e, t, q))?;
    let u = l.solve(&(eom.generalized_forces - eom.inertial_terms));
    Ok((l, u))
}

/// [`accelerations_in_mode`] of a mechanism whose positions are affine in the coordinates, with
/// the constants a validated handle prepared ([`crate::affine`]): M is factorised once, b = 0, and
/// M⁻¹𝓕 is a constant where a uniform field is the only force. The constraint rows take one
/// hyper-dual evaluation of g on x(q), which for affine x costs its products with the seeds and no
/// more. The Schur solve is the same.
#[inline(always)]
pub(crate) fn accelerations_in_mode_prepared<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    constants: &AffineConstants<N, K>,
    t: S,
    q: &[S; N],
    v: &[S; N],
    mode: &Mode<C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let u = affine::free_accelerations(model, constants, t, q, v);
    let rows = || match M::RHEONOMIC {
        // Constraints that read t (x itself cannot, to be affine): ∂/∂t seeded as well.
        true => constraint_rows_in_rates(model, t, q, v),
        false => rows_from_pass(model, &dynamics::motion_pass(model, t, q, v), t, q, v).0,
    };
    solve_kkt(
        model,
        t,
        q,
        mode,
        |b| constants.solve_mass::<M, S>(b),
        u,
        rows,
    )
}

/// The Schur-complement solve shared by [`accelerations_in_mode`] and
/// [`accelerations_in_mode_prepared`], from u = M⁻¹(𝓕 − b), M⁻¹ as `solve_mass`, and the
/// constraint rows (formed only when some row is enforced).
#[inline(always)]
fn solve_kkt<M: Constraints<N, K, C>, S: Scalar, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    mode: &Mode<C>,
    solve_mass: impl Fn(&SVector<S, N>) -> SVector<S, N>,
    u: SVector<S, N>,
    rows: impl FnOnce() -> ConstraintRows<S, N, C>,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    let sliding = sliding_rows::<M, N, K, C>(mode, &enforced);
    let mut multipliers = [S::zero(); C];
    if !enforced.iter().any(|&e| e) {
        // No row enforced: every λ is zero.
        return finish::<M, S, N, K, C>(u, multipliers, t, q, true);
    }
    let cr = rows();
    // A loop, not `array::from_fn`, whose closure the compiler does not always inline here
    // (BENCHMARKS.md, §4).
    let mut y = [SVector::<S, N>::zeros(); C];
    for i in 0..C {
        if enforced[i] || sliding[i] {
            y[i] = solve_mass(&cr.rows[i]);
        }
    }
    let (schur, rhs, filler) = schur_complement(&cr, &y, &u, &enforced);
    let lambda = schur_solve(&schur, &rhs)
        .map_err(|e| singular_constraints::<M, S, N, K, C>(e, &schur, &enforced, t, q))?;
    if !sliding.iter().any(|&s| s) {
        let mut qdd = u;
        for k in 0..C {
            if enforced[k] {
                qdd += y[k] * lambda[k];
                multipliers[k] = lambda[k];
            }
        }
        // Each λₖ entered q̈ through M⁻¹rₖ·λₖ, every entry of which is non-finite with λₖ (0·∞ is
        // NaN): q̈ finite implies λ finite, so q̈ alone is checked.
        return finish::<M, S, N, K, C>(qdd, multipliers, t, q, true);
    }
    let system = SlidingSystem {
        rows: &cr,
        y: &y,
        rhs,
        filler,
        enforced,
        sliding,
    };
    let (qdd, multipliers) = system.solve(model, t, q, mode, u, lambda)?;
    finish::<M, S, N, K, C>(qdd, multipliers, t, q, false)
}

/// Which rows slide and act: a sliding friction row (planar or cone) whose contact is enforced.
#[inline(always)]
fn sliding_rows<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    mode: &Mode<C>,
    enforced: &[bool; C],
) -> [bool; C] {
    std::array::from_fn(|j| match M::KINDS[j] {
        ConstraintKind::Friction { normal } => slip_sign(mode.rows[j]) != 0.0 && enforced[normal],
        ConstraintKind::FrictionCone { normal, .. } => {
            mode.rows[j] == RowMode::Sliding && enforced[normal]
        }
        _ => false,
    })
}

/// The Schur complement S = R M⁻¹ Rᵀ of the enforced rows R (with `y`ₖ = M⁻¹rₖ) and its
/// right-hand side −β − R u, S λ = −β − R u; the rows not enforced get λ = 0 from an identity row
/// at the scale of the others (`filler`, the largest diagonal entry, so the relative singularity
/// test of the factorisation is not distorted).
#[inline(always)]
fn schur_complement<S: Scalar, const N: usize, const C: usize>(
    cr: &ConstraintRows<S, N, C>,
    y: &[SVector<S, N>; C],
    u: &SVector<S, N>,
    enforced: &[bool; C],
) -> (SMatrix<S, C, C>, SVector<S, C>, f64) {
    let mut schur = SMatrix::<S, C, C>::zeros();
    let mut rhs = SVector::<S, C>::zeros();
    let mut diagonal = 0.0f64;
    for i in 0..C {
        if enforced[i] {
            for k in 0..C {
                if enforced[k] {
                    schur[(i, k)] = cr.rows[i].dot(&y[k]);
                }
            }
            rhs[i] = -cr.bias[i] - cr.rows[i].dot(u);
            diagonal = diagonal.max(schur[(i, i)].re().abs());
        }
    }
    let filler = if diagonal > 0.0 { diagonal } else { 1.0 };
    for i in 0..C {
        if !enforced[i] {
            schur[(i, i)] = S::from(filler);
        }
    }
    (schur, rhs, filler)
}

/// q̈ and λ when they are finite, otherwise [`Error::NonFiniteDynamics`]; `implied` when λ is finite
/// whenever q̈ is (then q̈ alone is checked).
pub(super) fn finish<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    qdd: SVector<S, N>,
    multipliers: [S; C],
    t: S,
    q: &[S; N],
    implied: bool,
) -> Result<ConstrainedAccelerations<S, N, C>> {
    // Branch-free on the common path (as `check_state`): x·0 is 0 exactly when x is finite.
    let mut zero = 0.0f64;
    for i in 0..N {
        zero += qdd[i].re() * 0.0;
    }
    if !implied {
        for multiplier in &multipliers {
            zero += multiplier.re() * 0.0;
        }
    }
    if zero == 0.0 {
        Ok(ConstrainedAccelerations {
            accelerations: qdd.into(),
            multipliers,
        })
    } else {
        Err(dynamics::non_finite_dynamics::<M::Coords, S, N>(t, q))
    }
}
