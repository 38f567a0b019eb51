//! The settings of [`Dopri5`](super::Dopri5), which are also the step-control settings every
//! explicit pair shares ([`Dop853`](crate::integrate::Dop853)'s convert to them).

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::error::Result;
use crate::integrate::{check_step, check_step_bounds, check_tolerances, invalid_setting};

/// Settings of the adaptive Dormand–Prince 5(4) method (see the [module docs](super)).
///
/// One step: `sys.step::<Dopri5>(&mut state, h)` integrates over [t, t + h] with the
/// [default](Dopri5::default) tolerances (rtol 1e-6, atol 1e-9), as many adaptive steps as that
/// takes, landing exactly on t + h — the state advances by h, as with every fixed-step method.
/// For other tolerances, dense output or events use a [`Stepper`](crate::integrate::Stepper).
///
/// ```
/// use lagrange_core::{Dopri5, Mechanism, State};
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
/// Pendulum.step::<Dopri5>(&mut s, 0.5)?;
/// assert_eq!(s.t, 0.5);
/// // rtol 1e-6 per step: the energy moves by about that much of its size (4.3 J).
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-5);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dopri5 {
    /// Relative tolerance (per component, against max(|y₀|, |y₁|)).
    pub rtol: f64,
    /// Absolute tolerance (per component).
    pub atol: f64,
    /// First step; `None` chooses it (HNW I §II.4).
    pub h_init: Option<f64>,
    /// Largest step.
    pub h_max: f64,
    /// Most step attempts (accepted + rejected) of one integration ([`Stepper::integrate`](crate::integrate::Stepper::integrate)).
    pub max_steps: usize,
    /// Safety factor of the step-size controller.
    pub safety: f64,
    /// Smallest factor by which a step may shrink.
    pub fac_min: f64,
    /// Largest factor by which a step may grow.
    pub fac_max: f64,
    /// PI stabilisation exponent β (0: classical controller).
    pub beta: f64,
}

impl Default for Dopri5 {
    /// rtol = 1e-6, atol = 1e-9, DOPRI5's controller constants (safety 0.9, factors 0.2…10, β = 0.04).
    fn default() -> Self {
        Dopri5 {
            rtol: 1e-6,
            atol: 1e-9,
            h_init: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            safety: 0.9,
            fac_min: 0.2,
            fac_max: 10.0,
            beta: 0.04,
        }
    }
}

impl Dopri5 {
    /// The default settings with these tolerances.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Dopri5 {
            rtol,
            atol,
            ..Dopri5::default()
        }
    }

    /// Checks the settings: tolerances finite, non-negative and not both zero, step-control factors
    /// in their ranges, `max_steps` at least 1
    /// ([`Error::InvalidSetting`](crate::Error::InvalidSetting) naming the setting), the initial
    /// step positive and finite ([`Error::InvalidStep`](crate::Error::InvalidStep)).
    pub fn validate(&self) -> Result<()> {
        self.validate_as("Dopri5")
    }

    /// [`validate`](Self::validate), naming `method` in the errors (the settings are shared with
    /// [`Dop853`](super::Dop853)).
    pub(crate) fn validate_as(&self, method: &'static str) -> Result<()> {
        let invalid =
            |setting, value, requirement| Err(invalid_setting(method, setting, value, requirement));
        check_tolerances(method, self.rtol, self.atol)?;
        if self.rtol == 0.0 && self.atol == 0.0 {
            return invalid("rtol", 0.0, "positive when atol is zero");
        }
        for (name, value, ok, requirement) in [
            (
                "safety",
                self.safety,
                self.safety > 0.0 && self.safety <= 1.0,
                "in (0, 1]",
            ),
            (
                "fac_min",
                self.fac_min,
                self.fac_min > 0.0 && self.fac_min <= 1.0,
                "in (0, 1]",
            ),
            (
                "fac_max",
                self.fac_max,
                self.fac_max >= 1.0 && self.fac_max.is_finite(),
                "finite and at least 1",
            ),
            (
                "beta",
                self.beta,
                (0.0..0.2).contains(&self.beta),
                "in [0, 0.2)",
            ),
        ] {
            if !ok {
                return invalid(name, value, requirement);
            }
        }
        check_step_bounds(method, self.h_max, self.max_steps)?;
        if let Some(h) = self.h_init {
            check_step(h)?;
        }
        Ok(())
    }
}
