//! One Dormand–Prince 8(5,3) step: the stages, the trial step with its error norm, and the
//! [`Dop853Stepper`] that strings accepted steps together.

use super::tableau::{A, B, BHH, C, E};
use super::Dop853;
use crate::error::{Error, Result};
use crate::integrate::dopri5::{initial_step, project_accepted, ratio, Controller, DenseOutput};
use crate::integrate::pair::{explicit_step, OfMechanism};
use crate::integrate::solver::{Stats, Stepper};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};

/// Step-by-step use of [`Dop853`]: holds the current state, the proposed next step and the dense
/// output of the last accepted step; implements [`Stepper`].
pub struct Dop853Stepper<'m, M: Mechanism<N>, const N: usize> {
    mechanism: &'m M,
    settings: Dop853,
    pub(super) t: f64,
    pub(super) q: [f64; N],
    pub(super) v: [f64; N],
    a: [f64; N],
    control: Controller,
    /// The stages of the step being taken, kept from step to step (so not cleared each time).
    stages: Stages<N>,
    dense: DenseOutput<N>,
    pub(super) stats: Stats,
}

/// The stages of one [`Dop853`] step, position parts kq (the stage velocities) and velocity parts
/// ka (the stage accelerations): stages 1…12 of the trial, 13 the FSAL evaluation at the new point,
/// 14…16 those of the dense output. A step computes them in place, without copying them around.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stages<const N: usize> {
    pub(crate) kq: [[f64; N]; 16],
    pub(crate) ka: [[f64; N]; 16],
}

impl<const N: usize> Stages<N> {
    /// All stages zero, to be filled by [`attempt`] and [`accept`].
    pub(crate) fn new() -> Self {
        Stages {
            kq: [[0.0; N]; 16],
            ka: [[0.0; N]; 16],
        }
    }
}

impl<'m, M: Mechanism<N>, const N: usize> Dop853Stepper<'m, M, N> {
    /// Starts at `state`: validates settings, mechanism and state, evaluates q̈ and chooses the
    /// first step.
    pub fn new(mechanism: &'m M, settings: Dop853, state: &State<M::Coords>) -> Result<Self> {
        settings.validate()?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        let t = state.t;
        let a = mechanism
            .accelerations_at(t, &q, &v)
            .map_err(|e| diagnose(mechanism, t, &q, &v, e))?;
        let mut stats = Stats {
            evaluations: 1,
            ..Stats::default()
        };
        let h = match settings.h_init {
            Some(h) => h.min(settings.h_max),
            None => initial_step(
                mechanism,
                &settings.shared(),
                (t, &q, &v, &a),
                8,
                &mut stats,
            ),
        };
        Ok(Dop853Stepper {
            mechanism,
            settings,
            t,
            q,
            v,
            a,
            control: Controller { h, fac_old: 1e-4 },
            stages: Stages::new(),
            dense: DenseOutput::constant(t, &q, &v),
            stats,
        })
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.control.h
    }

    /// Length of the last accepted step.
    pub fn last_step(&self) -> f64 {
        self.dense.t_end() - self.dense.t_start()
    }

    /// Takes one accepted step, not past `t_limit` (> current time), rejecting and shrinking as
    /// needed, as [`Dopri5Stepper::step`](crate::integrate::Dopri5Stepper::step) does. On error
    /// the accepted state is unchanged (and when the projection after the step failed, the dense
    /// output is the constant at that state).
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        let (mut control, mut stats) = (self.control, self.stats);
        let start = (self.t, &self.q, &self.v, &self.a);
        // The dense output is written in place: an error before it is complete leaves it as it was.
        let (t_new, q1, v1, a1) = explicit_step::<Dop853, M::Coords, N>(
            &self.settings,
            &mut control,
            &mut self.stages,
            &OfMechanism(self.mechanism),
            start,
            t_limit,
            &mut stats,
            &mut self.dense,
        )?;
        // Onto the constraints, the FSAL acceleration kept (see `project_accepted`).
        let (qp, vp) = match project_accepted(self.mechanism, t_new, (q1, v1)) {
            Ok(projected) => projected,
            Err(e) => {
                self.dense = DenseOutput::constant(self.t, &self.q, &self.v);
                return Err(e);
            }
        };
        (self.t, self.q, self.v, self.a) = (t_new, qp, vp, a1);
        (self.control, self.stats) = (control, stats);
        Ok(())
    }
}

/// Evaluates stage I (0-based) of a step of size h from (t, q, v) into kq[I], ka[I]: the stage
/// point (q, v) + h Σ_{j<I} a_Ij (kqⱼ, kaⱼ), its velocity and q̈ there. The stage is a constant,
/// so the sum is unrolled over its nonzero aᵢⱼ alone.
#[inline(always)]
pub(super) fn evaluate_stage<const I: usize, const N: usize>(
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    h: f64,
    k: &mut Stages<N>,
    stats: &mut Stats,
    acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<()> {
    let (mut qi, mut vi) = (*q, *v);
    for j in 0..I {
        let a = A[I][j];
        if a != 0.0 {
            for n in 0..N {
                qi[n] += h * a * k.kq[j][n];
                vi[n] += h * a * k.ka[j][n];
            }
        }
    }
    stats.evaluations += 1;
    k.ka[I] = acc(t + C[I] * h, &qi, &vi)?;
    k.kq[I] = vi;
    Ok(())
}

/// Σⱼ wⱼ kⱼ over stages 1…12 (0-based 0…11), componentwise, the zero weights skipped (the weights
/// are constants: the loop unrolls over the nonzero ones, each a sweep over the N components).
#[inline(always)]
fn weighted<const N: usize>(w: &[f64; 12], k: &[[f64; N]; 16]) -> [f64; N] {
    let mut s = [0.0; N];
    for j in 0..12 {
        if w[j] != 0.0 {
            for n in 0..N {
                s[n] += w[j] * k[j][n];
            }
        }
    }
    s
}

/// One trial step of size h from (t, q, v) with q̈ = `a` there, on the accelerations `acc`: stages
/// 1…12 into `k`, the 8th-order solution (q₁, q̇₁) and the error norm. What every Dop853 step
/// attempts ([`explicit_step`]), on a mechanism's accelerations or any other field.
pub(crate) fn attempt<Q: Coordinates<N>, const N: usize>(
    st: &Dop853,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    k: &mut Stages<N>,
    stats: &mut Stats,
    acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<([f64; N], [f64; N], f64)> {
    k.kq[0] = *v;
    k.ka[0] = *a;
    let y = (t, q, v);
    evaluate_stage::<1, N>(y, h, k, stats, acc)?;
    evaluate_stage::<2, N>(y, h, k, stats, acc)?;
    evaluate_stage::<3, N>(y, h, k, stats, acc)?;
    evaluate_stage::<4, N>(y, h, k, stats, acc)?;
    evaluate_stage::<5, N>(y, h, k, stats, acc)?;
    evaluate_stage::<6, N>(y, h, k, stats, acc)?;
    evaluate_stage::<7, N>(y, h, k, stats, acc)?;
    evaluate_stage::<8, N>(y, h, k, stats, acc)?;
    evaluate_stage::<9, N>(y, h, k, stats, acc)?;
    evaluate_stage::<10, N>(y, h, k, stats, acc)?;
    evaluate_stage::<11, N>(y, h, k, stats, acc)?;
    // dop853.f: k₄ = Σⱼ bⱼ kⱼ and y₁ = y₀ + h·k₄; the 5th-order error h·Σⱼ eⱼ kⱼ and the 3rd-order
    // one h·(k₄ − bhh₁k₁ − bhh₂k₉ − bhh₃k₁₂) (the factor h is applied to the norm below).
    // The sums of squares run over y = (q, q̇) in this order, as over dop853.f's y.
    let (mut q1, mut v1) = ([0.0; N], [0.0; N]);
    let (mut err5, mut err3) = (0.0, 0.0);
    for (kx, y0, y1) in [(&k.kq, q, &mut q1), (&k.ka, v, &mut v1)] {
        let (bsum, e5) = (weighted(&B, kx), weighted(&E, kx));
        for n in 0..N {
            y1[n] = y0[n] + h * bsum[n];
            let e3 = bsum[n] - BHH[0] * kx[0][n] - BHH[1] * kx[8][n] - BHH[2] * kx[11][n];
            let sc = st.atol + st.rtol * y0[n].abs().max(y1[n].abs());
            err5 += ratio(e5[n], sc).powi(2);
            err3 += ratio(e3, sc).powi(2);
        }
    }
    check_state(&Q::NAMES, t + h, &q1, &v1)?;
    // dop853.f: err = |h|·err₅² / √(n·(err₅² + 0.01·err₃²)), with sums of squares.
    let mut deno = err5 + 0.01 * err3;
    if !(deno > 0.0) {
        deno = 1.0;
    }
    let err = h.abs() * err5 * (1.0 / (deno * (2 * N) as f64)).sqrt();
    if err.is_nan() {
        return Err(Error::NonFiniteDynamics {
            t: t + h,
            configuration: crate::error::describe_configuration(&Q::NAMES, &q1),
        });
    }
    Ok((q1, v1, err))
}

impl<M: Mechanism<N>, const N: usize> Stepper<M::Coords, N> for Dop853Stepper<'_, M, N> {
    fn name(&self) -> &'static str {
        "Dop853"
    }
    fn t(&self) -> f64 {
        self.t
    }
    fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.q),
            M::Coords::from_array(self.v),
        )
    }
    fn step(&mut self, t_limit: f64) -> Result<()> {
        Dop853Stepper::step(self, t_limit)
    }
    fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }
    fn stats(&self) -> Stats {
        self.stats
    }
    fn count_event_evaluations(&mut self, n: usize) {
        self.stats.event_evaluations += n;
    }
    fn max_steps(&self) -> usize {
        self.settings.max_steps
    }
}
