//! Adaptive Dormand–Prince 8(5,3) — Hairer's DOP853 — with its continuous extension of order 7
//! and event location.
//!
//! - Method: Prince & Dormand, *High order embedded Runge–Kutta formulae*, J. Comput. Appl. Math. 7
//!   (1981); Hairer, Nørsett & Wanner, *Solving ODEs I* (HNW I), §II.10 (Table 10.3 and the
//!   surrounding text). The coefficients below are those of Hairer's published Fortran code
//!   `dop853.f` (E. Hairer and G. Wanner, Université de Genève, version of 2004, distributed with
//!   HNW I), to the digits printed there. Twelve stages; the FSAL evaluation at the new point is
//!   the next step's first stage, so an accepted step costs 12 evaluations (plus 3 for the dense
//!   output).
//! - Error estimate (HNW I §II.10, and `dop853.f`): the 5th-order estimate err₅ and the 3rd-order
//!   estimate err₃ are combined as err = err₅² / √(err₅² + 0.01·err₃²) (norms as in
//!   [`Dopri5`], over all q and v components), which behaves like O(h⁸).
//! - Step-size control: the PI controller of HNW I §II.4 / Hairer & Wanner, *Solving ODEs II*,
//!   §IV.2 (Gustafsson), h_new = h·min(fac_max, max(fac_min, err^(−1/8 + 0.2β)·err_old^β / safety)),
//!   the form of `dop853.f`; β = 0.04 here by default (Hairer's code defaults to β = 0, the classical
//!   controller, which `beta: 0.0` selects).
//! - Dense output: the continuous extension of order 7 of `dop853.f` (CONTD8), three more
//!   evaluations per accepted step (`dense: false` skips them and interpolates by cubic Hermite
//!   instead, order 3).
//! - Events, the observer and the statistics are those of every solver ([`Stepper::integrate`]).
//! - Constraints: as [`Dopri5`], the start state must satisfy them and every
//!   accepted step is projected onto them.
//!
//! Integration is forward in time only.

// Coefficients carry the digits printed in dop853.f; stage loops index several arrays;
// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(
    clippy::excessive_precision,
    clippy::needless_range_loop,
    clippy::neg_cmp_op_on_partial_ord,
    clippy::unreadable_literal
)]

use super::dopri5::{
    adaptive_step, initial_step, project_accepted, ratio, Controller, DenseOutput, Dopri5,
};
use super::solver::{Event, Observation, Outcome, Stats, Stepper, StopReason};
use super::Integrator;
use crate::error::{Error, Result};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};

/// aᵢⱼ: row i − 1 is stage i (1-based; stage 1 has none, stage 13 is unused: the FSAL
/// evaluation at the new point takes its place).
const A: [[f64; 15]; 16] = [
    [0.0; 15],
    [
        5.26001519587677318785587544488e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        1.97250569845378994544595329183e-2,
        5.91751709536136983633785987549e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        2.95875854768068491816892993775e-2,
        0.0,
        8.87627564304205475450678981324e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        2.41365134159266685502369798665e-1,
        0.0,
        -8.84549479328286085344864962717e-1,
        9.24834003261792003115737966543e-1,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.7037037037037037037037037037e-2,
        0.0,
        0.0,
        1.70828608729473871279604482173e-1,
        1.25467687566822425016691814123e-1,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.7109375e-2,
        0.0,
        0.0,
        1.70252211019544039314978060272e-1,
        6.02165389804559606850219397283e-2,
        -1.7578125e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.70920001185047927108779319836e-2,
        0.0,
        0.0,
        1.70383925712239993810214054705e-1,
        1.07262030446373284651809199168e-1,
        -1.53194377486244017527936158236e-2,
        8.27378916381402288758473766002e-3,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        6.24110958716075717114429577812e-1,
        0.0,
        0.0,
        -3.36089262944694129406857109825e0,
        -8.68219346841726006818189891453e-1,
        2.75920996994467083049415600797e1,
        2.01540675504778934086186788979e1,
        -4.34898841810699588477366255144e1,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        4.77662536438264365890433908527e-1,
        0.0,
        0.0,
        -2.48811461997166764192642586468e0,
        -5.90290826836842996371446475743e-1,
        2.12300514481811942347288949897e1,
        1.52792336328824235832596922938e1,
        -3.32882109689848629194453265587e1,
        -2.03312017085086261358222928593e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        -9.3714243008598732571704021658e-1,
        0.0,
        0.0,
        5.18637242884406370830023853209e0,
        1.09143734899672957818500254654e0,
        -8.14978701074692612513997267357e0,
        -1.85200656599969598641566180701e1,
        2.27394870993505042818970056734e1,
        2.49360555267965238987089396762e0,
        -3.0467644718982195003823669022e0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        2.27331014751653820792359768449e0,
        0.0,
        0.0,
        -1.05344954667372501984066689879e1,
        -2.00087205822486249909675718444e0,
        -1.79589318631187989172765950534e1,
        2.79488845294199600508499808837e1,
        -2.85899827713502369474065508674e0,
        -8.87285693353062954433549289258e0,
        1.23605671757943030647266201528e1,
        6.43392746015763530355970484046e-1,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    ],
    [
        5.61675022830479523392909219681e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        2.53500210216624811088794765333e-1,
        -2.46239037470802489917441475441e-1,
        -1.24191423263816360469010140626e-1,
        1.5329179827876569731206322685e-1,
        8.20105229563468988491666602057e-3,
        7.56789766054569976138603589584e-3,
        -8.298e-3,
        0.0,
        0.0,
    ],
    [
        3.18346481635021405060768473261e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        2.83009096723667755288322961402e-2,
        5.35419883074385676223797384372e-2,
        -5.49237485713909884646569340306e-2,
        0.0,
        0.0,
        -1.08347328697249322858509316994e-4,
        3.82571090835658412954920192323e-4,
        -3.40465008687404560802977114492e-4,
        1.41312443674632500278074618366e-1,
        0.0,
    ],
    [
        -4.28896301583791923408573538692e-1,
        0.0,
        0.0,
        0.0,
        0.0,
        -4.69762141536116384314449447206e0,
        7.68342119606259904184240953878e0,
        4.06898981839711007970213554331e0,
        3.56727187455281109270669543021e-1,
        0.0,
        0.0,
        0.0,
        -1.39902416515901462129418009734e-3,
        2.9475147891527723389556272149e0,
        -9.15095847217987001081870187138e0,
    ],
];
/// bᵢ of the 8th-order solution (stages 1…12).
const B: [f64; 12] = [
    5.42937341165687622380535766363e-2,
    0.0,
    0.0,
    0.0,
    0.0,
    4.45031289275240888144113950566e0,
    1.89151789931450038304281599044e0,
    -5.8012039600105847814672114227e0,
    3.1116436695781989440891606237e-1,
    -1.52160949662516078556178806805e-1,
    2.01365400804030348374776537501e-1,
    4.47106157277725905176885569043e-2,
];
/// Weights of the 3rd-order estimate on stages 1, 9 and 12.
const BHH: [f64; 3] = [
    0.244094488188976377952755905512e+00,
    0.733846688281611857341361741547e+00,
    0.220588235294117647058823529412e-01,
];
/// cᵢ (c₁₂ = c₁₃ = 1: stage 12 and the FSAL evaluation are at the new point).
const C: [f64; 16] = [
    0.0,
    0.526001519587677318785587544488e-01,
    0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510e+00,
    0.281649658092772603273242802490e+00,
    0.333333333333333333333333333333e+00,
    0.25e+00,
    0.307692307692307692307692307692e+00,
    0.651282051282051282051282051282e+00,
    0.6e+00,
    0.857142857142857142857142857142e+00,
    1.0,
    1.0,
    0.1e+00,
    0.2e+00,
    0.777777777777777777777777777778e+00,
];
/// Weights of the 5th-order error estimate (stages 1…12; the rest zero).
const E: [f64; 16] = [
    0.1312004499419488073250102996e-01,
    0.0,
    0.0,
    0.0,
    0.0,
    -0.1225156446376204440720569753e+01,
    -0.4957589496572501915214079952e+00,
    0.1664377182454986536961530415e+01,
    -0.3503288487499736816886487290e+00,
    0.3341791187130174790297318841e+00,
    0.8192320648511571246570742613e-01,
    -0.2235530786388629525884427845e-01,
    0.0,
    0.0,
    0.0,
    0.0,
];
/// d₄…d₇ of the continuous extension (CONTD8), over stages 1…16.
const D: [[f64; 16]; 4] = [
    [
        -0.84289382761090128651353491142e+01,
        0.0,
        0.0,
        0.0,
        0.0,
        0.56671495351937776962531783590e+00,
        -0.30689499459498916912797304727e+01,
        0.23846676565120698287728149680e+01,
        0.21170345824450282767155149946e+01,
        -0.87139158377797299206789907490e+00,
        0.22404374302607882758541771650e+01,
        0.63157877876946881815570249290e+00,
        -0.88990336451333310820698117400e-01,
        0.18148505520854727256656404962e+02,
        -0.91946323924783554000451984436e+01,
        -0.44360363875948939664310572000e+01,
    ],
    [
        0.10427508642579134603413151009e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        0.24228349177525818288430175319e+03,
        0.16520045171727028198505394887e+03,
        -0.37454675472269020279518312152e+03,
        -0.22113666853125306036270938578e+02,
        0.77334326684722638389603898808e+01,
        -0.30674084731089398182061213626e+02,
        -0.93321305264302278729567221706e+01,
        0.15697238121770843886131091075e+02,
        -0.31139403219565177677282850411e+02,
        -0.93529243588444783865713862664e+01,
        0.35816841486394083752465898540e+02,
    ],
    [
        0.19985053242002433820987653617e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.38703730874935176555105901742e+03,
        -0.18917813819516756882830838328e+03,
        0.52780815920542364900561016686e+03,
        -0.11573902539959630126141871134e+02,
        0.68812326946963000169666922661e+01,
        -0.10006050966910838403183860980e+01,
        0.77771377980534432092869265740e+00,
        -0.27782057523535084065932004339e+01,
        -0.60196695231264120758267380846e+02,
        0.84320405506677161018159903784e+02,
        0.11992291136182789328035130030e+02,
    ],
    [
        -0.25693933462703749003312586129e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.15418974869023643374053993627e+03,
        -0.23152937917604549567536039109e+03,
        0.35763911791061412378285349910e+03,
        0.93405324183624310003907691704e+02,
        -0.37458323136451633156875139351e+02,
        0.10409964950896230045147246184e+03,
        0.29840293426660503123344363579e+02,
        -0.43533456590011143754432175058e+02,
        0.96324553959188282948394950600e+02,
        -0.39177261675615439165231486172e+02,
        -0.14972683625798562581422125276e+03,
    ],
];

/// Settings of the adaptive Dormand–Prince 8(5,3) method (see the [module docs](self)).
///
/// ```
/// use lagrange_core::integrate::Dop853;
/// use lagrange_core::{Mechanism, State};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Pendulum;
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         vec2(q[0].sin(), -q[0].cos()).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// # }
/// # lagrange_core::impl_mechanism!(Pendulum, 1, 2);
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// let out = Dop853::new(1e-12, 1e-14).integrate(&Pendulum, &mut s, 10.0, &mut [], |_| {})?;
/// // Tolerance 1e-12 per step over ≈ 100 steps: the energy (4.3 J) is kept to ≈ 1e-10 relative.
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-9);
/// assert!(out.stats.accepted < 300);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dop853 {
    /// Relative tolerance (per component, against max(|y₀|, |y₁|)).
    pub rtol: f64,
    /// Absolute tolerance (per component).
    pub atol: f64,
    /// First step; `None` chooses it (HNW I §II.4).
    pub h_init: Option<f64>,
    /// Largest step.
    pub h_max: f64,
    /// Most step attempts (accepted + rejected) of one [`Dop853::integrate`] call.
    pub max_steps: usize,
    /// Safety factor of the step-size controller.
    pub safety: f64,
    /// Smallest factor by which a step may shrink.
    pub fac_min: f64,
    /// Largest factor by which a step may grow.
    pub fac_max: f64,
    /// PI stabilisation exponent β (0: classical controller).
    pub beta: f64,
    /// Whether accepted steps build the 7th-order dense output (three more evaluations each);
    /// otherwise the dense output is the cubic Hermite interpolant.
    pub dense: bool,
}

impl Default for Dop853 {
    /// rtol = 1e-6, atol = 1e-9, `dop853.f`'s controller constants (safety 0.9, factors 1/3…6) with
    /// β = 0.04, dense output on.
    fn default() -> Self {
        Dop853 {
            rtol: 1e-6,
            atol: 1e-9,
            h_init: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            safety: 0.9,
            fac_min: 1.0 / 3.0,
            fac_max: 6.0,
            beta: 0.04,
            dense: true,
        }
    }
}

impl Dop853 {
    /// The default settings with these tolerances.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Dop853 {
            rtol,
            atol,
            ..Dop853::default()
        }
    }

    /// The settings as the shared embedded-pair settings.
    pub(crate) fn shared(&self) -> Dopri5 {
        Dopri5 {
            rtol: self.rtol,
            atol: self.atol,
            h_init: self.h_init,
            h_max: self.h_max,
            max_steps: self.max_steps,
            safety: self.safety,
            fac_min: self.fac_min,
            fac_max: self.fac_max,
            beta: self.beta,
        }
    }

    /// Checks the settings as [`Dopri5::validate`] does.
    pub fn validate(&self) -> Result<()> {
        self.shared().validate_as("Dop853")
    }

    /// Integrates from `state` to `t_end` (≥ state.t) with events and an observer, as
    /// [`Dopri5::integrate`]. On success `state` is the final state (at t_end, at the terminal event,
    /// or the last accepted one); on error `state` is unchanged. No allocation.
    pub fn integrate<M: Mechanism<N>, const N: usize>(
        &self,
        mechanism: &M,
        state: &mut State<M::Coords>,
        t_end: f64,
        events: &mut [Event<'_, M::Coords>],
        mut observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<Outcome<M::Coords>> {
        if !(t_end.is_finite() && t_end >= state.t) {
            return Err(Error::InvalidEndTime { t: state.t, t_end });
        }
        // Unilateral and friction rows: the mode held per step, its switches located.
        if let Some(outcome) =
            mechanism.integrate_contacts(*self, state, t_end, events, &mut observer)
        {
            return outcome;
        }
        let mut stepper = Dop853Stepper::new(mechanism, *self, state)?;
        let outcome = stepper.integrate(t_end, events, observer)?;
        *state = match outcome.reason {
            StopReason::Event(hit) => hit.state,
            _ => Stepper::state(&stepper),
        };
        Ok(outcome)
    }
}

/// Step-by-step use of [`Dop853`]: holds the current state, the proposed next step and the dense
/// output of the last accepted step; implements [`Stepper`].
pub struct Dop853Stepper<'m, M: Mechanism<N>, const N: usize> {
    mechanism: &'m M,
    settings: Dop853,
    t: f64,
    q: [f64; N],
    v: [f64; N],
    a: [f64; N],
    h: f64,
    fac_old: f64,
    dense: DenseOutput<N>,
    stats: Stats,
}

/// One trial step of [`Dop853`]: the new (q, v), the error norm and the stages (position and
/// velocity parts).
#[derive(Clone, Copy, Debug)]
pub struct Trial<const N: usize> {
    pub(crate) q1: [f64; N],
    pub(crate) v1: [f64; N],
    pub(crate) err: f64,
    pub(crate) kq: [[f64; N]; 16],
    pub(crate) ka: [[f64; N]; 16],
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
            h,
            fac_old: 1e-4,
            dense: DenseOutput::constant(t, &q, &v),
            stats,
        })
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.h
    }

    /// Length of the last accepted step.
    pub fn last_step(&self) -> f64 {
        self.dense.t_end() - self.dense.t_start()
    }

    /// Takes one accepted step, not past `t_limit` (> current time), rejecting and shrinking as
    /// needed, as [`Dopri5Stepper::step`](super::Dopri5Stepper::step) does. On error the accepted
    /// state is unchanged.
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        let mut control = Controller {
            h: self.h,
            fac_old: self.fac_old,
        };
        let mut stats = self.stats;
        let acc = mechanism_accelerations(self.mechanism);
        let start = (self.t, &self.q, &self.v, &self.a);
        let settings = self.settings;
        let (mut trial, h, t_new) = adaptive_step(
            "Dop853",
            &settings.shared(),
            (1.0 / 8.0, 0.2),
            self.t,
            t_limit,
            &mut control,
            &mut stats,
            |h, stats| {
                attempt::<M::Coords, N>(&settings, start, h, stats, &acc).map(|trial| {
                    let err = trial.err;
                    (trial, err)
                })
            },
        )?;
        // FSAL: q̈ at the new point (stage 13), then the dense output, then the projection.
        let (a1, dense) = accept(&settings, start, h, &mut trial, &mut stats, &acc)?;
        let (qp, vp, ap) =
            project_accepted(self.mechanism, t_new, (trial.q1, trial.v1, a1), &mut stats)?;
        self.dense = dense;
        (self.t, self.q, self.v, self.a) = (t_new, qp, vp, ap);
        (self.h, self.fac_old, self.stats) = (control.h, control.fac_old, stats);
        Ok(())
    }
}

/// q̈ of a mechanism, as the stages evaluate it.
fn mechanism_accelerations<M: Mechanism<N>, const N: usize>(
    m: &M,
) -> impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]> + '_ {
    move |t, q, v| {
        m.accelerations_at(t, q, v)
            .map_err(|e| diagnose(m, t, q, v, e))
    }
}

/// (q, v) at stage i (0-based) from the stages before it: y + h Σⱼ aᵢⱼ kⱼ.
fn stage_point<const N: usize>(
    (q0, v0): (&[f64; N], &[f64; N]),
    h: f64,
    i: usize,
    kq: &[[f64; N]; 16],
    ka: &[[f64; N]; 16],
) -> ([f64; N], [f64; N]) {
    let mut q = *q0;
    let mut v = *v0;
    for j in 0..i {
        let a = A[i][j];
        if a != 0.0 {
            for n in 0..N {
                q[n] += h * a * kq[j][n];
                v[n] += h * a * ka[j][n];
            }
        }
    }
    (q, v)
}

/// Evaluates stage i (0-based) of a step of size h from (t, q, v) into kq[i], ka[i].
#[allow(clippy::too_many_arguments)]
fn evaluate_stage<const N: usize>(
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    h: f64,
    i: usize,
    kq: &mut [[f64; N]; 16],
    ka: &mut [[f64; N]; 16],
    stats: &mut Stats,
    acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<()> {
    let (qi, vi) = stage_point((q, v), h, i, kq, ka);
    stats.evaluations += 1;
    ka[i] = acc(t + C[i] * h, &qi, &vi)?;
    kq[i] = vi;
    Ok(())
}

/// One trial step of size h from (t, q, v) with q̈ = `a` there, on the accelerations `acc`
/// (stages 1…12, the 8th-order solution and the error norm): what [`Dop853Stepper`] attempts on a
/// mechanism's accelerations, and the contact solver on those of a frozen constraint mode.
pub(crate) fn attempt<Q: Coordinates<N>, const N: usize>(
    st: &Dop853,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
    acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<Trial<N>> {
    let mut kq = [[0.0; N]; 16];
    let mut ka = [[0.0; N]; 16];
    kq[0] = *v;
    ka[0] = *a;
    for i in 1..12 {
        evaluate_stage((t, q, v), h, i, &mut kq, &mut ka, stats, acc)?;
    }
    let mut q1 = *q;
    let mut v1 = *v;
    for j in 0..12 {
        if B[j] != 0.0 {
            for n in 0..N {
                q1[n] += h * B[j] * kq[j][n];
                v1[n] += h * B[j] * ka[j][n];
            }
        }
    }
    check_state(&Q::NAMES, t + h, &q1, &v1)?;
    let (mut err5, mut err3) = (0.0, 0.0);
    let mut component = |e5: f64, e3: f64, y0: f64, y1: f64| {
        let sc = st.atol + st.rtol * y0.abs().max(y1.abs());
        err5 += ratio(e5, sc).powi(2);
        err3 += ratio(e3, sc).powi(2);
    };
    for n in 0..N {
        for (k, y0, y1) in [(&kq, q[n], q1[n]), (&ka, v[n], v1[n])] {
            let mut e5 = 0.0;
            let mut bsum = 0.0;
            for j in 0..12 {
                e5 += E[j] * k[j][n];
                bsum += B[j] * k[j][n];
            }
            let e3 = bsum - BHH[0] * k[0][n] - BHH[1] * k[8][n] - BHH[2] * k[11][n];
            component(e5, e3, y0, y1);
        }
    }
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
    Ok(Trial {
        q1,
        v1,
        err,
        kq,
        ka,
    })
}

/// Completes an accepted [`attempt`] of size h from (t, q, v, q̈): the FSAL evaluation q̈₁ at the
/// new point (stage 13), and the dense output — the 7th-order continuous extension of `dop853.f`
/// (CONTD8, stages 14–16 evaluated here), or the cubic Hermite interpolant with `dense: false`.
pub(crate) fn accept<const N: usize>(
    st: &Dop853,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    trial: &mut Trial<N>,
    stats: &mut Stats,
    acc: &impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<([f64; N], DenseOutput<N>)> {
    stats.evaluations += 1;
    let a1 = acc(t + h, &trial.q1, &trial.v1)?;
    trial.kq[12] = trial.v1;
    trial.ka[12] = a1;
    if !st.dense {
        let dense = DenseOutput::hermite(t, h, (q, v, a), (&trial.q1, &trial.v1, &a1));
        return Ok((a1, dense));
    }
    for i in 13..16 {
        evaluate_stage((t, q, v), h, i, &mut trial.kq, &mut trial.ka, stats, acc)?;
    }
    let make = |y0: &[f64; N], y1: &[f64; N], k: &[[f64; N]; 16]| {
        let mut r = [[0.0; N]; 8];
        for n in 0..N {
            let diff = y1[n] - y0[n];
            let bspl = h * k[0][n] - diff;
            r[0][n] = y0[n];
            r[1][n] = diff;
            r[2][n] = bspl;
            r[3][n] = diff - h * k[12][n] - bspl;
            for (row, d) in D.iter().enumerate() {
                let mut s = 0.0;
                for j in 0..16 {
                    s += d[j] * k[j][n];
                }
                r[4 + row][n] = h * s;
            }
        }
        r
    };
    let dense = DenseOutput::from_coefficients(
        t,
        h,
        make(q, &trial.q1, &trial.kq),
        make(v, &trial.v1, &trial.ka),
    );
    Ok((a1, dense))
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

/// `sys.step::<Dop853>(&mut state, h)`: integrates over [t, t + h] with the
/// [default](Dop853::default) tolerances, landing exactly on t + h (as `Dopri5` does).
impl Integrator for Dop853 {
    const NAME: &'static str = "Dop853";
    type Memory<const N: usize> = ();

    fn advance<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        _memory: &mut (),
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        let start = State::new(t, M::Coords::from_array(*q), M::Coords::from_array(*v));
        let settings = Dop853 {
            dense: false,
            ..Dop853::default()
        };
        let mut stepper = Dop853Stepper::new(mechanism, settings, &start)?;
        let t_end = t + h;
        let result = (|| {
            while stepper.t < t_end {
                stepper.step(t_end)?;
            }
            Ok((stepper.q, stepper.v))
        })();
        *stats += stepper.stats;
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tableau_is_consistent() {
        // Row sums of A are the nodes (HNW I (1.9)) for every stage used (13 is the FSAL point,
        // whose row is empty: it is not a stage of the step); the weights sum to 1; the error
        // weights to 0 (both solutions are consistent). Printed to 30 digits: 1e-14 is round-off
        // of summing up to 15 terms of size ≤ 60.
        for i in 1..16 {
            if i == 12 {
                continue;
            }
            let s: f64 = A[i].iter().sum();
            assert!((s - C[i]).abs() < 1e-14, "row {}: {s} vs {}", i + 1, C[i]);
        }
        assert!((B.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        assert!(E.iter().sum::<f64>().abs() < 1e-14);
        assert!((BHH.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
}
