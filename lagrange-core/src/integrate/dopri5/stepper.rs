//! One Dormand–Prince 5(4) step: the stages, the trial step with its error norm, and the
//! [`Dopri5Stepper`] that strings accepted steps together.

use super::control::{adaptive_step, initial_step, project_accepted, ratio, Controller};
use super::dense::{dense_output, DenseOutput};
use super::tableau::*;
use super::{Dopri5, Dopri5Stats};
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::integrate::solver::{Stats, Stepper};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};

/// Step-by-step use of [`Dopri5`]: holds the current state, the proposed next step and the dense
/// output of the last accepted step.
///
/// ```
/// # use lagrange_core::integrate::{Dopri5, Dopri5Stepper};
/// # fn demo<M: lagrange_core::Mechanism<2, Coords = [f64; 2]>>(m: &M) -> lagrange_core::Result<()> {
/// let start = lagrange_core::State::new(0.0, [0.1, 0.0], [0.0, 0.0]);
/// let mut stepper = Dopri5Stepper::new(m, Dopri5::new(1e-8, 1e-10), &start)?;
/// while stepper.t() < 10.0 {
///     stepper.step(10.0)?; // one accepted step, never past 10
///     let (q_mid, _v_mid) = stepper.dense().eval(stepper.t() - 0.5 * stepper.last_step());
/// }
/// # Ok(()) }
/// ```
pub struct Dopri5Stepper<'m, M: Mechanism<N>, const N: usize> {
    mechanism: &'m M,
    settings: Dopri5,
    pub(super) t: f64,
    pub(super) q: [f64; N],
    pub(super) v: [f64; N],
    a: [f64; N],
    h: f64,
    fac_old: f64,
    dense: DenseOutput<N>,
    pub(super) stats: Dopri5Stats,
}

/// y + h Σⱼ coefⱼ kⱼ, componentwise, on any scalar (the f64 operations in the same order).
#[inline(always)]
pub(crate) fn combo<T: Scalar, const N: usize, const S: usize>(
    y: &[T; N],
    h: f64,
    coef: [f64; S],
    k: [&[T; N]; S],
) -> [T; N] {
    std::array::from_fn(|i| {
        let mut s = T::zero();
        for j in 0..S {
            s += k[j][i] * coef[j];
        }
        y[i] + s * h
    })
}

/// The stages of one Dormand–Prince step of size h from (t, q, v) with q̈ = `a1` there: the new
/// (q₁, v₁) and the stage velocities kq and accelerations ka of stages 1…6 (stage 7, FSAL, is q̈ at
/// the new point). On any scalar: the f64 step, and the trajectory sensitivities on dual numbers.
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(crate) fn stages<T: Scalar, const N: usize>(
    t: f64,
    q: &[T; N],
    v: &[T; N],
    a1: [T; N],
    h: f64,
    mut acc: impl FnMut(f64, &[T; N], &[T; N]) -> Result<[T; N]>,
) -> Result<([T; N], [T; N], [[T; N]; 6], [[T; N]; 6])> {
    let (kq1, ka1) = (*v, a1);
    // Stage i: position increments use the stage velocities kqⱼ, velocity increments the stage
    // accelerations kaⱼ.
    let (q2, v2) = (combo(q, h, [A21], [&kq1]), combo(v, h, [A21], [&ka1]));
    let ka2 = acc(t + C2 * h, &q2, &v2)?;
    let kq2 = v2;
    let (q3, v3) = (
        combo(q, h, [A31, A32], [&kq1, &kq2]),
        combo(v, h, [A31, A32], [&ka1, &ka2]),
    );
    let ka3 = acc(t + C3 * h, &q3, &v3)?;
    let kq3 = v3;
    let (q4, v4) = (
        combo(q, h, [A41, A42, A43], [&kq1, &kq2, &kq3]),
        combo(v, h, [A41, A42, A43], [&ka1, &ka2, &ka3]),
    );
    let ka4 = acc(t + C4 * h, &q4, &v4)?;
    let kq4 = v4;
    let (q5, v5) = (
        combo(q, h, [A51, A52, A53, A54], [&kq1, &kq2, &kq3, &kq4]),
        combo(v, h, [A51, A52, A53, A54], [&ka1, &ka2, &ka3, &ka4]),
    );
    let ka5 = acc(t + C5 * h, &q5, &v5)?;
    let kq5 = v5;
    let (q6, v6) = (
        combo(
            q,
            h,
            [A61, A62, A63, A64, A65],
            [&kq1, &kq2, &kq3, &kq4, &kq5],
        ),
        combo(
            v,
            h,
            [A61, A62, A63, A64, A65],
            [&ka1, &ka2, &ka3, &ka4, &ka5],
        ),
    );
    let ka6 = acc(t + h, &q6, &v6)?;
    let kq6 = v6;
    let q1 = combo(
        q,
        h,
        [A71, A73, A74, A75, A76],
        [&kq1, &kq3, &kq4, &kq5, &kq6],
    );
    let v1 = combo(
        v,
        h,
        [A71, A73, A74, A75, A76],
        [&ka1, &ka3, &ka4, &ka5, &ka6],
    );
    Ok((
        q1,
        v1,
        [kq1, kq2, kq3, kq4, kq5, kq6],
        [ka1, ka2, ka3, ka4, ka5, ka6],
    ))
}

impl<'m, M: Mechanism<N>, const N: usize> Dopri5Stepper<'m, M, N> {
    /// Starts at `state`: validates settings, mechanism and state, evaluates q̈ and chooses the
    /// first step.
    pub fn new(mechanism: &'m M, settings: Dopri5, state: &State<M::Coords>) -> Result<Self> {
        settings.validate()?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        Self::start(mechanism, settings, state.t, q, v)
    }

    /// Starts at (t, q, v), already checked.
    pub(super) fn start(
        mechanism: &'m M,
        settings: Dopri5,
        t: f64,
        q: [f64; N],
        v: [f64; N],
    ) -> Result<Self> {
        let a = mechanism
            .accelerations_at(t, &q, &v)
            .map_err(|e| diagnose(mechanism, t, &q, &v, e))?;
        let state = State::<M::Coords>::new(t, M::Coords::from_array(q), M::Coords::from_array(v));
        let mut s = Dopri5Stepper {
            mechanism,
            settings,
            t: state.t,
            q,
            v,
            a,
            h: 0.0,
            fac_old: 1e-4,
            dense: DenseOutput::constant(state.t, &q, &v),
            stats: Dopri5Stats {
                evaluations: 1,
                ..Dopri5Stats::default()
            },
        };
        s.h = match settings.h_init {
            Some(h) => h.min(settings.h_max),
            None => s.initial_step(),
        };
        Ok(s)
    }

    /// HNW I §II.4, "Starting step size" (Hairer's HINIT, order 5).
    fn initial_step(&mut self) -> f64 {
        initial_step(
            self.mechanism,
            &self.settings,
            (self.t, &self.q, &self.v, &self.a),
            5,
            &mut self.stats,
        )
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.q),
            M::Coords::from_array(self.v),
        )
    }

    /// Dense output of the last accepted step (a constant before the first step).
    pub fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }

    /// Length of the last accepted step.
    pub fn last_step(&self) -> f64 {
        self.dense.h
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.h
    }

    /// Cost so far.
    pub fn stats(&self) -> Dopri5Stats {
        self.stats
    }

    /// Takes one accepted step, not past `t_limit` (> current time), rejecting and shrinking as
    /// needed. A stage that fails (singular mass matrix, non-finite dynamics) counts as a rejection
    /// with the step cut by `fac_min`; when the step can no longer shrink (0.1·h below round-off of t)
    /// the last failure is returned ([`Error::StepSizeUnderflow`] if steps were rejected only for
    /// accuracy). On error the accepted state is unchanged.
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        let mut control = Controller {
            h: self.h,
            fac_old: self.fac_old,
        };
        let mut stats = self.stats;
        let this = &*self;
        let ((q1, v1, a1, k), h, t_new) = adaptive_step(
            "Dopri5",
            &self.settings,
            (0.2, 0.75),
            self.t,
            t_limit,
            &mut control,
            &mut stats,
            |h, stats| {
                this.attempt(h, stats)
                    .map(|(q1, v1, a1, err, k)| ((q1, v1, a1, k), err))
            },
        )?;
        // Accepted. The dense output interpolates the step as computed; the state is then projected
        // onto the constraints (a no-op without any), and the FSAL acceleration is kept (see
        // `project_accepted`).
        let (qp, vp) = project_accepted(self.mechanism, t_new, (q1, v1))?;
        self.dense = self.build_dense(h, &q1, &v1, &a1, &k);
        (self.t, self.q, self.v, self.a) = (t_new, qp, vp, a1);
        (self.h, self.fac_old, self.stats) = (control.h, control.fac_old, stats);
        Ok(())
    }

    /// One trial step of size h ([`trial`] on the mechanism's accelerations).
    #[allow(clippy::type_complexity)]
    fn attempt(
        &self,
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N], [f64; N], f64, [[f64; N]; 8])> {
        let m = self.mechanism;
        trial::<M::Coords, N>(
            &self.settings,
            (self.t, &self.q, &self.v, &self.a),
            h,
            stats,
            |t, q, v| {
                m.accelerations_at(t, q, v)
                    .map_err(|e| diagnose(m, t, q, v, e))
            },
        )
    }

    fn build_dense(
        &self,
        h: f64,
        q1: &[f64; N],
        v1: &[f64; N],
        _a1: &[f64; N],
        k: &[[f64; N]; 8],
    ) -> DenseOutput<N> {
        dense_output(self.t, h, (&self.q, &self.v), (q1, v1), k)
    }
}

/// One trial step of Dormand–Prince 5(4) of size h from (t, q, v) with q̈ = `a` there, on the
/// accelerations `acc`: (q₁, v₁, q̈₁, err, stage data for [`dense_output`]). What [`Dopri5Stepper`]
/// attempts on a mechanism's accelerations, and the contact solver on the accelerations of a frozen
/// constraint mode. Adds its evaluations of `acc` to `stats`.
#[allow(clippy::type_complexity)]
pub(crate) fn trial<C: Coordinates<N>, const N: usize>(
    st: &Dopri5,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
    mut acc: impl FnMut(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<([f64; N], [f64; N], [f64; N], f64, [[f64; N]; 8])> {
    let (q1, v1, kq, ka) = stages(t, q, v, *a, h, |t, q, v| {
        stats.evaluations += 1;
        acc(t, q, v)
    })?;
    let [kq1, _, kq3, kq4, kq5, kq6] = kq;
    let [ka1, _, ka3, ka4, ka5, ka6] = ka;
    check_state(&C::NAMES, t + h, &q1, &v1)?;
    stats.evaluations += 1;
    let ka7 = acc(t + h, &q1, &v1)?;
    let kq7 = v1;
    let mut sum = 0.0;
    for i in 0..N {
        let eq =
            h * (E1 * kq1[i] + E3 * kq3[i] + E4 * kq4[i] + E5 * kq5[i] + E6 * kq6[i] + E7 * kq7[i]);
        let ev =
            h * (E1 * ka1[i] + E3 * ka3[i] + E4 * ka4[i] + E5 * ka5[i] + E6 * ka6[i] + E7 * ka7[i]);
        let sq = st.atol + st.rtol * q[i].abs().max(q1[i].abs());
        let sv = st.atol + st.rtol * v[i].abs().max(v1[i].abs());
        sum += ratio(eq, sq).powi(2) + ratio(ev, sv).powi(2);
    }
    // Every stage is finite here (checked above), so an infinite error norm is an error far
    // above a tolerance near the bottom of the floating-point range (rtol = atol = 1e-300):
    // a rejection like any other, which ends in a step-size underflow if it persists.
    let err = (sum / (2 * N) as f64).sqrt();
    if err.is_nan() {
        return Err(Error::NonFiniteDynamics {
            t: t + h,
            configuration: crate::error::describe_configuration(&C::NAMES, &q1),
        });
    }
    // The dense output needs d-weighted sums of the stages for q and v.
    let dq = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&kq1, &kq3, &kq4, &kq5, &kq6, &kq7],
    );
    let dv = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&ka1, &ka3, &ka4, &ka5, &ka6, &ka7],
    );
    Ok((
        q1,
        v1,
        ka7,
        err,
        [kq1, ka1, kq7, ka7, dq, dv, [0.0; N], [0.0; N]],
    ))
}

impl<M: Mechanism<N>, const N: usize> Stepper<M::Coords, N> for Dopri5Stepper<'_, M, N> {
    fn name(&self) -> &'static str {
        "Dopri5"
    }
    fn t(&self) -> f64 {
        self.t
    }
    fn state(&self) -> State<M::Coords> {
        Dopri5Stepper::state(self)
    }
    fn step(&mut self, t_limit: f64) -> Result<()> {
        Dopri5Stepper::step(self, t_limit)
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
