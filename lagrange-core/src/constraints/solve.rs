//! The Schur-complement solve of the KKT system in a mode: [`ConstrainedAccelerations`],
//! [`accelerations_in_mode`] (sliding friction included) and [`accelerations`].

use super::cone;
use super::kinds::{always_active, written_holonomic};
use super::prepared::holonomic_accelerations_prepared;
use super::rows::{constraint_rows, real, rows_from_pass, ConstraintRows};
use super::{infer_mode, ConstraintKind, Constraints, Mode, RowMode};
use crate::affine::{self, AffineConstants};
use crate::dynamics;
use crate::error::{describe_configuration, Error, Result};
use crate::geometry::Scalar;
use crate::linalg::{factor_pattern, mass_pattern, Ldlt, NotPositiveDefinite, SINGULAR_PIVOT};
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

// `contact.rs` imports `worst_violation` from here, where it was before the split.
pub(crate) use super::mode::worst_violation;

/// Solves with sliding friction tried before the signs of the bilateral normal forces are declared
/// inconsistent ([`Error::FrictionIndeterminate`]): two decide one normal row, the rest allow for
/// a flip of a second row.
const SIGN_ATTEMPTS: usize = 4;

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

fn slip_sign(mode: RowMode) -> f64 {
    match mode {
        RowMode::SlipPositive => 1.0,
        RowMode::SlipNegative => -1.0,
        _ => 0.0,
    }
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
    // A scleronomic mechanism evaluates x(q) once, for M, 𝓕, b and the constraint rows alike.
    let pass = (!M::RHEONOMIC).then(|| dynamics::motion_pass(model, t, q, v));
    let eom = match &pass {
        Some(pass) => dynamics::equations_of_motion_from_pass(model, pass, t, q, v),
        None => dynamics::equations_of_motion(model, t, q, v),
    };
    // LDLᵀ with reciprocal pivots: no square roots, no divisions in the solves (see `Ldlt`). The
    // entries of L that the declaration rules out (coordinates no massive row couples, and no
    // elimination fills in) are constants: never formed, in the factorisation or the C + 1 solves.
    let pattern = const { factor_pattern(&mass_pattern(&M::DEPENDS, M::INERTIAL)) };
    let l = Ldlt::with_pattern(&eom.mass_matrix, pattern)
        .map_err(|e| dynamics::mass_matrix_failure::<M::Coords, S, N>(&eom.mass_matrix, e, t, q))?;
    let u = l.solve(&(eom.generalized_forces - eom.inertial_terms));
    let rows = || match &pass {
        Some(pass) => rows_from_pass(model, pass, t, q, v).0,
        None => constraint_rows(model, t, q, v),
    };
    solve_kkt(model, t, q, mode, |b| l.solve(b), u, rows)
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
        true => constraint_rows(model, t, q, v),
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
    // A sliding row acts when its contact is enforced.
    let sliding: [bool; C] = std::array::from_fn(|j| match M::KINDS[j] {
        ConstraintKind::Friction { normal } => slip_sign(mode.rows[j]) != 0.0 && enforced[normal],
        ConstraintKind::FrictionCone { normal, .. } => {
            mode.rows[j] == RowMode::Sliding && enforced[normal]
        }
        _ => false,
    });
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
            rhs[i] = -cr.bias[i] - cr.rows[i].dot(&u);
            diagonal = diagonal.max(schur[(i, i)].re().abs());
        }
    }
    // Rows not enforced get λ = 0 from an identity row at the scale of the others (so the relative
    // singularity test of the factorisation is not distorted).
    let filler = if diagonal > 0.0 { diagonal } else { 1.0 };
    for i in 0..C {
        if !enforced[i] {
            schur[(i, i)] = S::from(filler);
        }
    }
    let mut lambda = schur_solve(&schur, &rhs)
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
    // Sliding friction: the generalized force of normal row n becomes λₙ(rₙ − Σⱼ μₖ σⱼ sₙ Sⱼ), with
    // sₙ = sign(λₙ) (+1 for a unilateral contact, whose λ ≥ 0 while active). The sign of a bilateral
    // normal force is taken from the frictionless solve and re-checked. σⱼ is the slip sign of a
    // planar row, and the component ŝⱼ of the unit slip direction of a cone's row.
    let direction: [S; C] = std::array::from_fn(|j| match M::KINDS[j] {
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
    });
    let mut sign_n: [f64; C] = std::array::from_fn(|n| match M::KINDS[n] {
        ConstraintKind::Unilateral => 1.0,
        _ => {
            if lambda[n].re() < 0.0 {
                -1.0
            } else {
                1.0
            }
        }
    });
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
    // Each attempt solves with the current signs and flips those the solution contradicts. With
    // one bilateral normal row two attempts decide: if both signs contradict themselves, no normal
    // force is consistent with sliding friction (Painlevé's inconsistent case). Several normal rows
    // get a few more attempts; signs still inconsistent after them are the same error, never a
    // solution computed with a sign its own normal force contradicts.
    let mut consistent = false;
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
                a[(i, i)] = S::from(filler);
            }
        }
        lambda = lu_solve_generic(&a, &rhs).ok_or_else(indeterminate)?;
        consistent = true;
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
            break;
        }
    }
    if !consistent {
        return Err(indeterminate());
    }
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
    finish::<M, S, N, K, C>(qdd, multipliers, t, q, false)
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

/// q̈ at (t, q, q̇) with the mode read from the state ([`infer_mode`]); with only holonomic and
/// velocity rows, every row is enforced and no inference runs. What a constrained mechanism's
/// `Dynamics::accelerations_at` forwards to.
pub fn accelerations<
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
) -> Result<[S; N]> {
    let mode = if always_active::<M, N, K, C>() {
        Mode::all_active::<M, N, K>()
    } else {
        infer_mode(model, t.re(), &real(q), &real(v))?
    };
    accelerations_in_mode(model, t, q, v, &mode).map(|a| a.accelerations)
}

/// [`accelerations`] of a mechanism whose positions are affine in the coordinates (x = A q + c,
/// see [`crate::affine`]), with the constants prepared once from its parameters: what a
/// constrained affine mechanism's validated handle evaluates. Agrees with [`accelerations`] to
/// round-off.
///
/// ```
/// use lagrange_core::affine::AffineConstants;
/// use lagrange_core::constraints::{self, ConstraintKind, Constraints};
/// use lagrange_core::{vec2, Model, Scalar};
///
/// /// A pendulum in Cartesian coordinates: x = q, affine; the rod |x| = 2 a constraint.
/// struct Pendulum;
/// impl Model<2, 2> for Pendulum {
///     type Coords = [f64; 2];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = false;
///     const HAS_FORCES: bool = false;
///     const HAS_GRAVITY: bool = true;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.5, 1.5] }
///     fn weights(&self) -> [f64; 2] { [0.0, -1.5 * 9.81] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] { *q }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D { D::zero() }
/// }
/// impl Constraints<2, 2, 1> for Pendulum {
///     const NAMES: [&'static str; 1] = ["rod"];
///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
///     fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
///         [vec2(x[0], x[1]).norm() - 2.0]
///     }
/// }
///
/// let constants = AffineConstants::of(&Pendulum)?;
/// let (q, v) = ([1.2, -1.6], [0.8, 0.6]);
/// let prepared = constraints::accelerations_prepared(&Pendulum, &constants, 0.0, &q, &v)?;
/// let direct = constraints::accelerations(&Pendulum, 0.0, &q, &v)?;
/// assert!((prepared[0] - direct[0]).abs() < 1e-14 && (prepared[1] - direct[1]).abs() < 1e-14);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[inline]
pub fn accelerations_prepared<
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
) -> Result<[S; N]> {
    // Holonomic rows written out: the Schur complement from the prepared constants alone.
    if written_holonomic::<M, N, K, C>() {
        return holonomic_accelerations_prepared(model, constants, t, q, v)
            .map(|a| a.accelerations);
    }
    let mode = if always_active::<M, N, K, C>() {
        Mode::all_active::<M, N, K>()
    } else {
        infer_mode(model, t.re(), &real(q), &real(v))?
    };
    accelerations_in_mode_prepared(model, constants, t, q, v, &mode).map(|a| a.accelerations)
}
