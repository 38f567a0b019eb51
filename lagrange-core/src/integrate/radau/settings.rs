//! The settings of [`Radau5`](super::Radau5).

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::error::Result;
use crate::integrate::{check_step, check_step_bounds, check_tolerances, invalid_setting};

/// Settings of the adaptive Radau IIA method of order 5 (see the [module docs](super)).
///
/// One step: `sys.step::<Radau5>(&mut state, h)` integrates over [t, t + h] with the
/// [default](Radau5::default) tolerances, as many adaptive steps as that takes, landing exactly on
/// t + h (as [`Dopri5`](crate::integrate::Dopri5) does).
///
/// ```
/// use lagrange_core::{Mechanism, Radau5, State};
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
/// Pendulum.step::<Radau5>(&mut s, 0.5)?;
/// assert_eq!(s.t, 0.5);
/// // rtol 1e-6: the energy (4.3 J) moves by about that much of its size.
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-4);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radau5 {
    /// Relative tolerance (per component; converted as in `radau5.f`, see the module docs).
    pub rtol: f64,
    /// Absolute tolerance (per component).
    pub atol: f64,
    /// First step; `None` chooses it (HNW I §II.4, as for Dopri5).
    pub h_init: Option<f64>,
    /// Largest step.
    pub h_max: f64,
    /// Most step attempts (accepted + rejected) of one integration
    /// ([`Stepper::integrate`](crate::integrate::Stepper::integrate)).
    pub max_steps: usize,
    /// Most Newton iterations per step attempt (`radau5.f`: 7).
    pub max_newton_iterations: usize,
    /// The Jacobian is kept for the next step while the Newton contraction rate θ is at most this
    /// (`radau5.f`'s THET: 0.001; a cheap-to-evaluate Jacobian favours a smaller value).
    pub jacobian_theta: f64,
    /// The step (and its factorisation) is kept while the controller's proposal h_new/h lies in
    /// this range (`radau5.f`'s QUOT1, QUOT2: 1 and 1.2).
    pub keep_step: (f64, f64),
    /// The Newton iteration's stopping tolerance κ·tol on the scaled increments; `None` takes
    /// `radau5.f`'s default max(10ε/rtol′, min(0.03, √rtol′)) (its WORK(4)). Smaller is slower and
    /// safer: a fixed-step run iterates to round-off with a tiny value.
    pub newton_tolerance: Option<f64>,
}

impl Default for Radau5 {
    /// rtol = 1e-6, atol = 1e-9 and the constants of `radau5.f`.
    fn default() -> Self {
        Radau5 {
            rtol: 1e-6,
            atol: 1e-9,
            h_init: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            max_newton_iterations: 7,
            jacobian_theta: 0.001,
            keep_step: (1.0, 1.2),
            newton_tolerance: None,
        }
    }
}

impl Radau5 {
    /// The default settings with these tolerances.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Radau5 {
            rtol,
            atol,
            ..Radau5::default()
        }
    }

    /// Checks the settings ([`Error::InvalidSetting`](crate::Error::InvalidSetting) naming the
    /// setting; [`Error::InvalidStep`](crate::Error::InvalidStep) for a bad `h_init`).
    pub fn validate(&self) -> Result<()> {
        let invalid = |setting, value, requirement| {
            Err(invalid_setting("Radau5", setting, value, requirement))
        };
        check_tolerances("Radau5", self.rtol, self.atol)?;
        // Both positive: the error and Newton norms divide by atol′ + rtol′·|yᵢ|, which a
        // component at zero would make 0 with atol = 0.
        if !(self.rtol > 0.0) {
            return invalid("rtol", self.rtol, "positive");
        }
        if !(self.atol > 0.0) {
            return invalid("atol", self.atol, "positive");
        }
        check_step_bounds("Radau5", self.h_max, self.max_steps)?;
        if !(2..=50).contains(&self.max_newton_iterations) {
            let n = self.max_newton_iterations as f64;
            return invalid("max_newton_iterations", n, "between 2 and 50");
        }
        if !(self.jacobian_theta >= 0.0 && self.jacobian_theta < 1.0) {
            return invalid("jacobian_theta", self.jacobian_theta, "in [0, 1)");
        }
        let (lo, hi) = self.keep_step;
        if !(lo > 0.0 && lo <= 1.0) {
            return invalid("keep_step.0", lo, "in (0, 1]");
        }
        if !(hi >= 1.0 && hi.is_finite()) {
            return invalid("keep_step.1", hi, "finite and at least 1");
        }
        if let Some(tol) = self.newton_tolerance {
            if !(tol > 0.0 && tol < 1.0) {
                return invalid("newton_tolerance", tol, "in (0, 1)");
            }
        }
        if let Some(h) = self.h_init {
            check_step(h)?;
        }
        Ok(())
    }
}
