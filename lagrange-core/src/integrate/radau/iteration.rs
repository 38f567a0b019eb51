//! Radau5's simplified Newton iteration (HW II §IV.8; `radau5.f`, the loop at label 40), its error
//! estimate (HW II (8.19)–(8.21)) and the Newton matrices it reuses, on any
//! [`AccelerationField`]: what [`step`](super::step) attempts.

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::algebra::*;
use super::memory::Radau5Memory;
use super::Radau5;
use crate::error::{Error, Result};
use crate::integrate::pair::{AccelerationField, StepStart};
use crate::integrate::Stats;
use nalgebra::SVector;

/// How a Newton iteration of a step attempt ended.
pub(super) enum Attempt<const N: usize> {
    /// Converged: the stages Zᵢ, the iterations taken.
    Converged([Pair<N>; 3], usize),
    /// Abandoned: retry with h times this factor (and a fresh Jacobian if the current one is old);
    /// the error, if an evaluation failed.
    Failed(f64, Option<Error>),
}

/// f(t, y₀ + z) = (v₀ + z_v, q̈), counted.
fn stage_field<const N: usize>(
    field: &impl AccelerationField<N>,
    t: f64,
    y0: &Pair<N>,
    z: &Pair<N>,
    stats: &mut Stats,
) -> Result<Pair<N>> {
    let q: [f64; N] = (y0.q + z.q).into();
    let v: [f64; N] = (y0.v + z.v).into();
    stats.evaluations += 1;
    let a = field.accelerations(t, &q, &v)?;
    Ok(Pair {
        q: SVector::from(v),
        v: SVector::from(a),
    })
}

/// W = T⁻¹Z: the stages in the coordinates that block-diagonalise A⁻¹ (HW II (8.7)).
fn to_w<const N: usize>(z: &[Pair<N>; 3]) -> [Pair<N>; 3] {
    [
        Pair::combine([TI11, TI12, TI13], [&z[0], &z[1], &z[2]]),
        Pair::combine([TI21, TI22, TI23], [&z[0], &z[1], &z[2]]),
        Pair::combine([TI31, TI32, TI33], [&z[0], &z[1], &z[2]]),
    ]
}

/// Z = TW, back from the block-diagonal coordinates (T's last row is (T31, 1, 0)).
fn from_w<const N: usize>(w: &[Pair<N>; 3]) -> [Pair<N>; 3] {
    [
        Pair::combine([T11, T12, T13], [&w[0], &w[1], &w[2]]),
        Pair::combine([T21, T22, T23], [&w[0], &w[1], &w[2]]),
        Pair::combine([T31, 1.0], [&w[0], &w[1]]),
    ]
}

/// The Newton iteration's starting values at a step of h from t: the last step's collocation
/// polynomial extrapolated to the nodes, Zᵢ = u(t + cᵢh) − u(t) (HW II (8.16)), or 0 without one.
fn starting_values<const N: usize>(memory: &Radau5Memory<N>, t: f64, h: f64) -> [Pair<N>; 3] {
    let mut z = [Pair::zero(); 3];
    if let Some(dense) = memory.last {
        let (q1, v1) = dense.eval(t);
        for (i, c) in [C1, C2, 1.0].into_iter().enumerate() {
            let (q, v) = dense.eval(t + c * h);
            z[i] = Pair {
                q: SVector::from(q) - SVector::from(q1),
                v: SVector::from(v) - SVector::from(v1),
            };
        }
    }
    z
}

/// One simplified Newton increment ΔW from the stage derivatives F(Z) = `fz` at W = `w`: the
/// residual T⁻¹F(Z) − Λ W, Λ = diag(γ̂, [[α̂, −β̂], [β̂, α̂]])/h, solved blockwise with the real and
/// the complex factorisation; and its scaled norm ‖ΔW‖ = √(1/(6N) Σ (ΔWᵢ/scᵢ)²).
fn newton_increment<const N: usize>(
    (jac, f): (&Jacobians<N>, &Factors<N>),
    fz: &[Pair<N>; 3],
    w: &[Pair<N>; 3],
    h: f64,
    scale: &Pair<N>,
) -> ([Pair<N>; 3], f64) {
    let fac1 = U1 / h;
    let (alphn, betan) = (ALPH / h, BETA / h);
    let g = to_w(fz);
    let r1 = Pair::combine([1.0, -fac1], [&g[0], &w[0]]);
    let r2 = Pair::combine([1.0, -alphn, betan], [&g[1], &w[1], &w[2]]);
    let r3 = Pair::combine([1.0, -alphn, -betan], [&g[2], &w[2], &w[1]]);
    let d1 = jac.solve_real(f, &r1);
    let (d2, d3) = jac.solve_complex(f, &r2, &r3);
    let dyno = ((d1.scaled_sum(scale) + d2.scaled_sum(scale) + d3.scaled_sum(scale))
        / (6 * N) as f64)
        .sqrt();
    ([d1, d2, d3], dyno)
}

impl Radau5 {
    /// The simplified Newton iteration of one step attempt with step h from (t, y₀) (HW II §IV.8;
    /// `radau5.f`, the loop at label 40).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn newton<const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        (t, y0): (f64, &Pair<N>),
        h: f64,
        jac: &Jacobians<N>,
        f: &Factors<N>,
        stats: &mut Stats,
    ) -> Attempt<N> {
        let nit = self.max_newton_iterations;
        let scale = memory.scale(y0);
        let mut z = starting_values(memory, t, h);
        let mut w = to_w(&z);
        memory.faccon = memory.faccon.max(f64::EPSILON).powf(0.8);
        memory.theta = self.jacobian_theta;
        let mut rates = (1.0, 1.0);
        for newt in 1..=nit {
            let mut fz = [Pair::zero(); 3];
            for (i, c) in [C1, C2, 1.0].into_iter().enumerate() {
                match stage_field(field, t + c * h, y0, &z[i], stats) {
                    Ok(v) => fz[i] = v,
                    Err(e) => return Attempt::Failed(0.5, Some(e)),
                }
            }
            stats.newton_iterations += 1;
            let (d, dyno) = newton_increment((jac, f), &fz, &w, h, &scale);
            if !dyno.is_finite() {
                return Attempt::Failed(0.5, None);
            }
            if newt > 1 && newt < nit {
                if let Some(shrink) = self.contraction(memory, newt, dyno, &mut rates) {
                    return Attempt::Failed(shrink, None);
                }
            }
            rates.0 = dyno.max(f64::EPSILON);
            for (wi, di) in w.iter_mut().zip(&d) {
                wi.q += di.q;
                wi.v += di.v;
            }
            z = from_w(&w);
            if memory.faccon * dyno <= memory.newton_tol {
                return Attempt::Converged(z, newt);
            }
        }
        Attempt::Failed(0.5, None)
    }

    /// The contraction rate θ of iteration `newt` (from its increment's norm `dyno` and the
    /// previous one's, `rates` = (‖ΔW‖ before, θ before)), and η = θ/(1 − θ) of HW II (8.10) into
    /// the memory; the factor to shrink h by when the iteration is abandoned: θ ≥ 0.99, or the
    /// error predicted after the remaining iterations, η‖ΔW‖θ^(k_max−1−k), above the tolerance
    /// (`radau5.f`).
    fn contraction<const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        newt: usize,
        dyno: f64,
        (dyno_old, thq_old): &mut (f64, f64),
    ) -> Option<f64> {
        let thq = dyno / *dyno_old;
        memory.theta = if newt == 2 {
            thq
        } else {
            (thq * *thq_old).sqrt()
        };
        *thq_old = thq;
        if !(memory.theta < 0.99) {
            return Some(0.5);
        }
        memory.faccon = memory.theta / (1.0 - memory.theta);
        let remaining = (self.max_newton_iterations - 1 - newt) as i32;
        let predicted = memory.faccon * dyno * memory.theta.powi(remaining) / memory.newton_tol;
        if predicted >= 1.0 {
            let q = predicted.clamp(1e-4, 20.0);
            return Some(0.8 * q.powf(-1.0 / (4.0 + remaining as f64)));
        }
        None
    }

    /// The error estimate of HW II (8.19)–(8.21), `radau5.f`'s ESTRAD, for a step of h from
    /// (t, y₀) with f(y₀) = `f0`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn error<const N: usize>(
        memory: &Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        (t, y0, f0): (f64, &Pair<N>, &Pair<N>),
        h: f64,
        z: &[Pair<N>; 3],
        (jac, f): (&Jacobians<N>, &Factors<N>),
        refine: bool,
        stats: &mut Stats,
    ) -> f64 {
        let scale = memory.scale(y0);
        let f2 = Pair::combine([DD1 / h, DD2 / h, DD3 / h], [&z[0], &z[1], &z[2]]);
        let mut e = jac.solve_real(f, &Pair::combine([1.0, 1.0], [&f2, f0]));
        let mut err = (e.scaled_sum(&scale) / (2 * N) as f64).sqrt().max(1e-10);
        if err >= 1.0 && refine {
            match stage_field(field, t, y0, &e, stats) {
                Ok(fe) => {
                    e = jac.solve_real(f, &Pair::combine([1.0, 1.0], [&fe, &f2]));
                    err = (e.scaled_sum(&scale) / (2 * N) as f64).sqrt().max(1e-10);
                }
                Err(_) => return f64::INFINITY,
            }
        }
        if err.is_nan() {
            f64::INFINITY
        } else {
            err
        }
    }

    /// The Jacobians at the start of a step, evaluated if the memory has none (counted), and
    /// the factorisation for h, refactorised if it was for another h (counted).
    #[allow(clippy::type_complexity)]
    pub(super) fn newton_matrices<const N: usize>(
        memory: &mut Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        (t, q, v, _): StepStart<'_, N>,
        h: f64,
        stats: &mut Stats,
    ) -> Result<(Jacobians<N>, Option<Factors<N>>)> {
        let jac = match memory.jacobians {
            Some(jac) => jac,
            None => {
                stats.jacobians += 1;
                let (by_q, by_v) = field.jacobians(t, q, v)?;
                let jac = Jacobians { by_q, by_v };
                memory.jacobians = Some(jac);
                memory.jacobian_current = true;
                memory.factors = None;
                jac
            }
        };
        let factors = match memory.factors {
            Some(f) if f.h == h => Some(f),
            _ => {
                stats.factorizations += 1;
                jac.factor(h)
            }
        };
        Ok((jac, factors))
    }
}
