//! One accepted step of [`Radau5`] on any [`AccelerationField`] ([`EmbeddedPair`]): the step-size
//! control of the [parent module](super) around the Newton iteration of
//! [`iteration`](super::iteration), on a mechanism's accelerations or those of a held contact mode.

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::algebra::*;
use super::iteration::Attempt;
use super::memory::Radau5Memory;
use super::rates;
use super::Radau5;
use crate::error::{Error, Result};
use crate::integrate::control::{check_limit, initial_step_on, next_attempt};
use crate::integrate::dense::DenseOutput;
use crate::integrate::dopri5::settings::Dopri5;
use crate::integrate::newton::breakdown;
use crate::integrate::pair::{sealed, AccelerationField, Accepted, EmbeddedPair, StepStart};
use crate::integrate::Stats;
use crate::model::{check_state, Coordinates};
use nalgebra::SVector;

impl sealed::Sealed for Radau5 {}

/// The start of a step as first-order vectors: y₀ = (q₀, v₀) and f(y₀) = (v₀, q̈₀).
fn first_order<const N: usize>((_, q, v, a): StepStart<'_, N>) -> (Pair<N>, Pair<N>) {
    let (q, v) = (SVector::from(*q), SVector::from(*v));
    (
        Pair { q, v },
        Pair {
            q: v,
            v: SVector::from(*a),
        },
    )
}

impl Radau5 {
    /// The end of a converged step of h from (t, y₀): y₀ + Z₃, checked, and the collocation
    /// polynomial through (0, y₀), (cᵢ, y₀ + Zᵢ) as the dense output, in the form
    /// y₀ + θ r₂ + θ(1−θ) r₃ + θ²(1−θ) r₄: r₂ = Z₃, and with gᵢ = (Zᵢ − cᵢZ₃)/(cᵢ(1 − cᵢ)) = r₃ + cᵢr₄
    /// (i = 1, 2), r₄ = (g₂ − g₁)/(c₂ − c₁), r₃ = g₁ − c₁r₄ (`radau5.f`'s CONTR5).
    fn accepted<C: Coordinates<N>, const N: usize>(
        (t, y0): (f64, &Pair<N>),
        t_new: f64,
        h: f64,
        z: &[Pair<N>; 3],
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>> {
        let y1 = Pair::combine([1.0, 1.0], [y0, &z[2]]);
        let (q1, v1): ([f64; N], [f64; N]) = (y1.q.into(), y1.v.into());
        check_state(&C::NAMES, t_new, &q1, &v1)?;
        let make = |y0: &SVector<f64, N>, z: [&SVector<f64, N>; 3]| {
            let mut r = [[0.0; N]; 8];
            for i in 0..N {
                let g1 = (z[0][i] - C1 * z[2][i]) / (C1 * (1.0 - C1));
                let g2 = (z[1][i] - C2 * z[2][i]) / (C2 * (1.0 - C2));
                let r4 = (g2 - g1) / (C2 - C1);
                r[0][i] = y0[i];
                r[1][i] = z[2][i];
                r[2][i] = g1 - C1 * r4;
                r[3][i] = r4;
            }
            r
        };
        *dense = DenseOutput::from_coefficients(
            t,
            h,
            make(&y0.q, [&z[0].q, &z[1].q, &z[2].q]),
            make(&y0.v, [&z[0].v, &z[1].v, &z[2].v]),
        );
        Ok(Accepted {
            t: t_new,
            q: q1,
            v: v1,
            a: None,
        })
    }
}

impl Radau5 {
    /// The Jacobians and the factorisation for h ([`newton_matrices`](Self::newton_matrices),
    /// the factorisation kept in the memory) and the Newton iteration on them: the stages Zᵢ, the
    /// iterations taken and the matrices, or the factor to shrink h by and the error that ended
    /// the attempt (a singular or non-finite Newton matrix is [`Error::NewtonBreakdown`]).
    #[allow(clippy::type_complexity)]
    fn solve_stages<const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        y0: &Pair<N>,
        h: f64,
        stats: &mut Stats,
    ) -> Result<StageSolve<N>> {
        let t = start.0;
        let (jac, factors) = Self::newton_matrices(memory, field, start, h, stats)?;
        memory.factors = factors;
        let Some(f) = factors else {
            let singular = "the Newton matrix is singular or not finite";
            return Ok(Err((0.5, Some(breakdown("Radau5", t, h, 0, singular)))));
        };
        Ok(
            match self.newton(memory, field, (t, y0), h, &jac, &f, stats) {
                Attempt::Converged(z, newt) => Ok((z, newt, jac, f)),
                Attempt::Failed(factor, error) => Err((factor, error)),
            },
        )
    }

    /// h/h_new of `radau5.f`'s controller for a step with scaled error `err` whose Newton
    /// iteration took `newt` iterations: h_new = h·fac·err^(−1/4), fac falling with the iterations
    /// taken, the quotient clamped to [1/8, 5].
    fn step_quotient(&self, err: f64, newt: usize) -> f64 {
        let nit = self.max_newton_iterations as f64;
        let fac = SAFETY.min(SAFETY * (1.0 + 2.0 * nit) / (newt as f64 + 2.0 * nit));
        (err.powf(0.25) / fac).clamp(0.125, 5.0)
    }

    /// The quotient of an accepted step after Gustafsson's predictive controller (HW II (8.25)),
    /// from the second accepted step on, and the step and its error remembered for the next.
    fn predictive_quotient<const N: usize>(
        memory: &mut Radau5Memory<N>,
        h: f64,
        err: f64,
        mut quot: f64,
    ) -> f64 {
        if !memory.first {
            let gus = ((memory.h_acc / h) * (err * err / memory.err_acc).powf(0.25) / SAFETY)
                .clamp(0.125, 5.0);
            quot = quot.max(gus);
        }
        memory.h_acc = h;
        memory.err_acc = err.max(1e-2);
        quot
    }

    /// After an accepted step of h: the step proposed next, h/quot (bounded by `h_max`, not
    /// growing after a rejection). h itself and its factorisation are kept when the proposal is
    /// within `keep_step` and the Newton iteration converged fast; the Jacobian is kept when it
    /// converged fast (`radau5.f`'s QUOT1, QUOT2, THET).
    fn propose_next<const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        h: f64,
        quot: f64,
        (last, rejected): (bool, bool),
    ) {
        memory.first = false;
        memory.jacobian_current = false;
        let mut h_new = (h / quot).min(self.h_max);
        if rejected {
            h_new = h_new.min(h);
        }
        let fast = memory.theta <= self.jacobian_theta;
        let (lo, hi) = self.keep_step;
        let ratio = h_new / h;
        memory.h = if fast && ratio >= lo && ratio <= hi && !last {
            h
        } else {
            h_new
        };
        if !fast {
            memory.jacobians = None;
        }
    }
}

impl Radau5 {
    /// [`EmbeddedPair::step`] on a field whose velocities are the coordinates' rates.
    fn step_on<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        t_limit: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>> {
        let t = start.0;
        check_limit(t, t_limit)?;
        let (y0, f0) = first_order(start);
        let mut reject = false;
        let mut last_error: Option<Error> = None;
        loop {
            let limits = (t, t_limit);
            let (h, last) = next_attempt("Radau5", limits, memory.h, self.h_max, &mut last_error)?;
            let (z, newt, jac, f) = match self.solve_stages(memory, field, start, &y0, h, stats)? {
                Ok(converged) => converged,
                Err((factor, error)) => {
                    // `radau5.f` label 78 / the slow-convergence exit: shrink, refresh an old Jacobian.
                    last_error = error.or(last_error);
                    reject_step(memory, h * factor, &mut reject, stats);
                    continue;
                }
            };
            let refine = memory.first || reject;
            let err = Self::error(
                memory,
                field,
                (t, &y0, &f0),
                h,
                &z,
                (&jac, &f),
                refine,
                stats,
            );
            let quot = self.step_quotient(err, newt);
            if !(err < 1.0) {
                let h_retry = if memory.first { 0.1 * h } else { h / quot };
                reject_step(memory, h_retry, &mut reject, stats);
                continue;
            }
            let quot = Self::predictive_quotient(memory, h, err, quot);
            let t_new = if last { t_limit } else { t + h };
            let accepted = Self::accepted::<C, N>((t, &y0), t_new, h, &z, dense)?;
            stats.accepted += 1;
            memory.last = Some(*dense);
            self.propose_next(memory, h, quot, (last, reject));
            return Ok(accepted);
        }
    }

    /// [`EmbeddedPair::shorten`] on a field whose velocities are the coordinates' rates.
    fn shorten_on<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        h: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>> {
        let t = start.0;
        let (y0, _) = first_order(start);
        let mut fresh = memory.jacobians.is_none();
        loop {
            // The factorisation for h is not kept: the next step starts from the proposed one.
            let (jac, factors) = Self::newton_matrices(memory, field, start, h, stats)?;
            let attempt = match factors {
                Some(f) => self.newton(memory, field, (t, &y0), h, &jac, &f, stats),
                None => Attempt::Failed(0.5, None),
            };
            match attempt {
                Attempt::Converged(z, _) => {
                    let accepted = Self::accepted::<C, N>((t, &y0), t + h, h, &z, dense)?;
                    memory.last = Some(*dense);
                    memory.jacobian_current = false;
                    return Ok(accepted);
                }
                Attempt::Failed(_, error) if fresh => {
                    let reason = "the step cut at an event did not converge";
                    let iteration = self.max_newton_iterations;
                    return Err(error.unwrap_or(breakdown("Radau5", t, h, iteration, reason)));
                }
                Attempt::Failed(..) => {
                    memory.jacobians = None;
                    fresh = true;
                }
            }
        }
    }
}

/// The first step's size, chosen as Dopri5 chooses it (HNW I §II.4) at Radau5's tolerances.
fn first_step<const N: usize>(
    field: &impl AccelerationField<N>,
    dopri: &Dopri5,
    start: StepStart<'_, N>,
    stats: &mut Stats,
) -> f64 {
    let acc = |t: f64, q: &[f64; N], v: &[f64; N]| field.accelerations(t, q, v);
    initial_step_on(acc, dopri, start, start.2, 5, stats)
}

/// A rejected attempt: the next one with `h_retry`, a Jacobian not evaluated at the step's start
/// evaluated anew.
fn reject_step<const N: usize>(
    memory: &mut Radau5Memory<N>,
    h_retry: f64,
    rejected: &mut bool,
    stats: &mut Stats,
) {
    memory.h = h_retry;
    memory.renew_jacobian_if_old();
    *rejected = true;
    stats.rejected += 1;
}

/// What the Newton iteration of an attempt gives: the stages Zᵢ, the iterations taken, the
/// Jacobians and factorisation used; or the factor to shrink h by and the failure, if any.
#[allow(clippy::type_complexity)]
type StageSolve<const N: usize> =
    std::result::Result<([Pair<N>; 3], usize, Jacobians<N>, Factors<N>), (f64, Option<Error>)>;

impl EmbeddedPair for Radau5 {
    const NAME: &'static str = "Radau5";
    type Memory<const N: usize> = Radau5Memory<N>;
    /// Nothing: the stages are the Newton iteration's own.
    type Scratch<const N: usize> = ();

    fn validate(&self) -> Result<()> {
        Radau5::validate(self)
    }

    fn max_steps(&self) -> usize {
        self.max_steps
    }

    fn one_step_settings() -> Self {
        Radau5::default()
    }

    fn scratch<const N: usize>() {}

    fn start<const N: usize>(
        &self,
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        stats: &mut Stats,
    ) -> Radau5Memory<N> {
        // `radau5.f`: rtol′ = 0.1·rtol^(2/3), atol′ = rtol′·atol/rtol; the Newton tolerance.
        let rtol = 0.1 * self.rtol.powf(2.0 / 3.0);
        let atol = rtol * (self.atol / self.rtol);
        let newton_tol = self
            .newton_tolerance
            .unwrap_or((10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt())));
        let h = match self.h_init {
            Some(h) => h.min(self.h_max),
            None => {
                let dopri = Dopri5 {
                    rtol,
                    atol,
                    h_max: self.h_max,
                    ..Dopri5::default()
                };
                // In the rates, where the steps are taken, for quasi-velocities.
                match field.quasi_velocities() {
                    false => first_step(field, &dopri, start, stats),
                    true => rates::in_rates(field, start, |field, start| {
                        first_step(field, &dopri, start, stats)
                    }),
                }
            }
        };
        Radau5Memory {
            rtol,
            atol,
            newton_tol,
            h,
            jacobians: None,
            jacobian_current: false,
            factors: None,
            theta: self.jacobian_theta,
            faccon: 1.0,
            first: true,
            h_acc: h,
            err_acc: 1e-2,
            last: None,
        }
    }

    fn proposed_step<const N: usize>(memory: &Radau5Memory<N>) -> f64 {
        memory.h
    }

    /// One accepted step, rejecting and shrinking as needed (`radau5.f`'s RADCOR). When the step
    /// can no longer shrink (0.1·h below round-off of t) the last failure is returned
    /// ([`Error::StepSizeUnderflow`] if steps were rejected only for accuracy or slow Newton
    /// convergence).
    fn step<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        _scratch: &mut (),
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        t_limit: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>> {
        if !field.quasi_velocities() {
            return self.step_on::<C, N>(memory, field, start, t_limit, stats, dense);
        }
        let step = rates::in_rates(field, start, |field, start| {
            self.step_on::<C, N>(memory, field, start, t_limit, stats, dense)
        });
        rates::in_velocities(field.quasi_joints(), step, dense)
    }

    /// The collocation equations solved anew for the shorter h, from the accepted step's
    /// polynomial (excellent starting values: it interpolates there), with the Jacobian kept (or
    /// evaluated at the step's start if none is) and a factorisation for h. Should the iteration
    /// fail with a kept Jacobian, it is retried with one evaluated at the start; a second failure
    /// is [`Error::NewtonBreakdown`].
    fn shorten<C: Coordinates<N>, const N: usize>(
        &self,
        memory: &mut Radau5Memory<N>,
        _scratch: &mut (),
        field: &impl AccelerationField<N>,
        start: StepStart<'_, N>,
        h: f64,
        stats: &mut Stats,
        dense: &mut DenseOutput<N>,
    ) -> Result<Accepted<N>> {
        if !field.quasi_velocities() {
            return self.shorten_on::<C, N>(memory, field, start, h, stats, dense);
        }
        let step = rates::in_rates(field, start, |field, start| {
            self.shorten_on::<C, N>(memory, field, start, h, stats, dense)
        });
        rates::in_velocities(field.quasi_joints(), step, dense)
    }

    fn field_changed<const N: usize>(memory: &mut Radau5Memory<N>) {
        memory.jacobians = None;
        memory.jacobian_current = false;
        memory.factors = None;
        memory.last = None;
    }
}
