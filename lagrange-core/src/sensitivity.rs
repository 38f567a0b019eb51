//! Trajectory sensitivities by forward-mode differentiation through the integrator: the whole
//! simulation runs on dual numbers (`num_dual::DualSVec`) seeded on chosen initial values or
//! parameters, so the end state carries ∂q(T)/∂q₀, ∂q(T)/∂p and the same for q̇ exactly — the
//! derivatives of the numerical solution (the discrete map the integrator computes), not of an
//! approximation of it.
//!
//! Seeded on initial values only, every evaluation is the mechanism's own scalar-generic
//! `Dynamics::accelerations_at`. Seeded on a parameter, the parameters are dual numbers too
//! ([`crate::parameters::Lifted`]) and the accelerations come from the generic dynamics of
//! [`crate::dynamics`] on the lifted model. Every step is the integrator's own code on the dual
//! type (the stages [`Rk4`](crate::Rk4) and [`Dopri5`] take), so the real parts are the plain f64
//! run up to the order of the floating-point operations (bit for bit on initial values alone). A
//! step with `P` seeds costs one pass of the accelerations on duals of width `P`.
//!
//! ```
//! use lagrange_core::sensitivity::{Seed, Tangent};
//! # use lagrange_core::{impl_mechanism, vec2, Model, Scalar, State};
//! # struct Pendulum;
//! # impl Model<1, 2> for Pendulum {
//! #     type Coords = [f64; 1];
//! #     const RHEONOMIC: bool = false;
//! #     const HAS_POTENTIAL: bool = true;
//! #     const HAS_FORCES: bool = false;
//! #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//! #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//! #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
//! #         vec2(q[0].sin(), -q[0].cos()).to_array()
//! #     }
//! #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
//! # }
//! # impl_mechanism!(Pendulum, 1, 2);
//! // A unit pendulum (g = 9.81) released at rest from 0.01 rad: ∂θ(t)/∂θ₀ = cos(ωt) for the
//! // linearised motion; the amplitude's frequency shift ω θ₀²/16 moves it by ~2e-5 at t = 1.
//! let s0 = State::at_rest([0.01]);
//! let mut run = Tangent::new(&Pendulum, &s0, [Seed::Coordinate("q0")])?;
//! for _ in 0..1000 {
//!     run.rk4_step(1e-3)?;
//! }
//! let by_theta0 = run.sensitivities().dq[0];
//! assert!((by_theta0[0] - (9.81f64.sqrt() * 1.0).cos()).abs() < 1e-4);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

use crate::dynamics::accelerations_generic;
use crate::error::{Error, Result};
use crate::integrate::dopri5::stages;
use crate::integrate::rk4::rk4_step;
use crate::integrate::{check_step_at, Dopri5, Dopri5Stepper};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};
use crate::parameters::{Lifted, Parametrized};
use num_dual::DualSVec;

/// What to differentiate by: an initial value, named by its coordinate, or a parameter, named by
/// its field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seed {
    /// The initial value of the coordinate (q₀).
    Coordinate(&'static str),
    /// The initial value of the coordinate's velocity (q̇₀).
    Velocity(&'static str),
    /// A parameter (a field of the parameter struct) that enters the positions, the potential or
    /// the forces; not a mass, a moment of inertia or a uniform field's strength
    /// ([`Error::UnseedableParameter`]).
    Parameter(&'static str),
}

impl Seed {
    /// `theta1(0)`, `theta1_dot(0)` or `l`.
    pub fn label(&self) -> String {
        match self {
            Seed::Coordinate(name) => format!("{name}(0)"),
            Seed::Velocity(name) => format!("{name}_dot(0)"),
            Seed::Parameter(name) => name.to_string(),
        }
    }
}

/// The state and its derivatives with respect to each seed, named like the coordinates:
/// `dq[j].theta1` is ∂θ₁/∂(seed j), `dv[j].theta1` is ∂θ̇₁/∂(seed j).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sensitivities<C, const P: usize> {
    /// The state (the plain run's, bit for bit).
    pub state: State<C>,
    /// The seeds, in the order of `dq` and `dv`.
    pub seeds: [Seed; P],
    /// ∂q/∂(seed j), one set of coordinates per seed.
    pub dq: [C; P],
    /// ∂q̇/∂(seed j), one set of coordinates per seed.
    pub dv: [C; P],
}

/// A simulation carried on dual numbers seeded on initial values or parameters: the tangent of the
/// trajectory. `K` and `NP` are the mechanism's Cartesian rows and parameters (inferred from its
/// [`Parametrized`] implementation). Cloning it is cheap (a reference and the dual state), which is
/// how a step can be tried and kept or dropped (locating a crossing).
pub struct Tangent<'m, M, const N: usize, const K: usize, const NP: usize, const P: usize> {
    lifted: Lifted<'m, M, DualSVec<f64, P>, K, NP>,
    /// Whether a parameter is seeded: then the accelerations come from the lifted model.
    by_parameter: bool,
    seeds: [Seed; P],
    t: f64,
    q: [DualSVec<f64, P>; N],
    v: [DualSVec<f64, P>; N],
}

impl<M, const N: usize, const K: usize, const NP: usize, const P: usize> Clone
    for Tangent<'_, M, N, K, NP, P>
{
    fn clone(&self) -> Self {
        Tangent { ..*self }
    }
}

impl<M, const N: usize, const K: usize, const NP: usize, const P: usize> std::fmt::Debug
    for Tangent<'_, M, N, K, NP, P>
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tangent")
            .field("seeds", &self.seeds)
            .field("parameters", self.lifted.parameters())
            .field("t", &self.t)
            .field("q", &self.q)
            .field("v", &self.v)
            .finish()
    }
}

/// Index of `name` among the coordinates, or [`Error::UnknownCoordinate`].
fn coordinate<C: Coordinates<N>, const N: usize>(name: &str) -> Result<usize> {
    C::NAMES
        .iter()
        .position(|n| *n == name)
        .ok_or_else(|| Error::UnknownCoordinate {
            name: name.to_string(),
            known: C::NAMES.join(", "),
        })
}

/// Index of `name` among the parameters: [`Error::UnknownParameter`] when there is none,
/// [`Error::UnseedableParameter`] when it enters the dynamics as a plain number.
fn parameter<M: Parametrized<N, K, NP>, const N: usize, const K: usize, const NP: usize>(
    name: &str,
) -> Result<usize> {
    let known = || {
        let names = M::PARAMETER_NAMES.map(|n| format!("`{n}`"));
        match names.len() {
            0 => "none".to_string(),
            _ => names.join(", "),
        }
    };
    let i = M::PARAMETER_NAMES
        .iter()
        .position(|n| *n == name)
        .ok_or_else(|| Error::UnknownParameter {
            name: name.to_string(),
            known: known(),
        })?;
    if !M::SEEDABLE[i] {
        return Err(Error::UnseedableParameter {
            name: M::PARAMETER_NAMES[i],
        });
    }
    Ok(i)
}

impl<'m, M, const N: usize, const K: usize, const NP: usize, const P: usize>
    Tangent<'m, M, N, K, NP, P>
where
    M: Mechanism<N> + Parametrized<N, K, NP>,
{
    /// Starts at `state` with derivative 1 along each seed. Errors: invalid parameters or state, a
    /// seed naming no coordinate ([`Error::UnknownCoordinate`]) or no parameter
    /// ([`Error::UnknownParameter`]), a parameter that carries no derivative
    /// ([`Error::UnseedableParameter`]), a mechanism that declares constraints or does not say
    /// ([`Error::UnsuitableMethod`]: the projection onto the constraints is not differentiated).
    pub fn new(
        mechanism: &'m M,
        state: &State<<M as crate::mechanism::Dynamics<N>>::Coords>,
        seeds: [Seed; P],
    ) -> Result<Self> {
        let (q0, v0) = mechanism.check(state)?;
        // Decided by the declaration alone, as the integrators decide.
        if <M as crate::mechanism::Dynamics<N>>::CONSTRAINTS != Some(0) {
            return Err(constrained());
        }
        let mut q: [DualSVec<f64, P>; N] = std::array::from_fn(|i| DualSVec::from_re(q0[i]));
        let mut v: [DualSVec<f64, P>; N] = std::array::from_fn(|i| DualSVec::from_re(v0[i]));
        let mut p: [DualSVec<f64, P>; NP] = mechanism.parameters().map(DualSVec::from_re);
        let mut by_parameter = false;
        for (j, seed) in seeds.iter().enumerate() {
            match seed {
                Seed::Coordinate(name) => {
                    let i = coordinate::<<M as crate::mechanism::Dynamics<N>>::Coords, N>(name)?;
                    q[i] = q[i].derivative(j);
                }
                Seed::Velocity(name) => {
                    let i = coordinate::<<M as crate::mechanism::Dynamics<N>>::Coords, N>(name)?;
                    v[i] = v[i].derivative(j);
                }
                Seed::Parameter(name) => {
                    let i = parameter::<M, N, K, NP>(name)?;
                    p[i] = p[i].derivative(j);
                    by_parameter = true;
                }
            }
        }
        Ok(Tangent {
            lifted: Lifted::new(mechanism, p),
            by_parameter,
            seeds,
            t: state.t,
            q,
            v,
        })
    }

    /// q̈ on the duals: the mechanism's own accelerations, or the lifted model's when a parameter
    /// is seeded.
    fn accelerations(
        &self,
        t: f64,
        q: &[DualSVec<f64, P>; N],
        v: &[DualSVec<f64, P>; N],
    ) -> Result<[DualSVec<f64, P>; N]> {
        let m = self.lifted.model();
        let t_dual = DualSVec::from_re(t);
        let a = if self.by_parameter {
            accelerations_generic(&self.lifted, t_dual, q, v)
        } else {
            m.accelerations_at(t_dual, q, v)
        };
        a.map_err(|e| {
            let (qr, vr) = (q.map(|x| x.re), v.map(|x| x.re));
            diagnose(m, t, &qr, &vr, e)
        })
    }

    /// One RK4 step of size `h`, on the duals. On error nothing changes.
    pub fn rk4_step(&mut self, h: f64) -> Result<()> {
        check_step_at(self.t, h)?;
        let (q, v) = rk4_step(self.t, &self.q, &self.v, h, |t, q, v| {
            self.accelerations(t, q, v)
        })?;
        self.accept(h, q, v)
    }

    /// One Dormand–Prince 5(4) step of size `h` (fixed: no error control), on the duals, with the
    /// method's own stages. On error nothing changes.
    pub fn dopri5_step(&mut self, h: f64) -> Result<()> {
        check_step_at(self.t, h)?;
        let acc = |t: f64, q: &[DualSVec<f64, P>; N], v: &[DualSVec<f64, P>; N]| {
            self.accelerations(t, q, v)
        };
        let a = acc(self.t, &self.q, &self.v)?;
        let (q, v, _, _) = stages(self.t, &self.q, &self.v, a, h, acc)?;
        self.accept(h, q, v)
    }

    /// Moves to the end of a step of size `h` once its state is checked finite.
    fn accept(&mut self, h: f64, q: [DualSVec<f64, P>; N], v: [DualSVec<f64, P>; N]) -> Result<()> {
        let (qr, vr) = (q.map(|x| x.re), v.map(|x| x.re));
        check_state(
            &<M as crate::mechanism::Dynamics<N>>::Coords::NAMES,
            self.t + h,
            &qr,
            &vr,
        )?;
        (self.t, self.q, self.v) = (self.t + h, q, v);
        Ok(())
    }

    /// The current state (real parts).
    pub fn state(&self) -> State<<M as crate::mechanism::Dynamics<N>>::Coords> {
        State::new(
            self.t,
            <M as crate::mechanism::Dynamics<N>>::Coords::from_array(self.q.map(|x| x.re)),
            <M as crate::mechanism::Dynamics<N>>::Coords::from_array(self.v.map(|x| x.re)),
        )
    }

    /// The state and its derivatives along every seed.
    pub fn sensitivities(&self) -> Sensitivities<<M as crate::mechanism::Dynamics<N>>::Coords, P> {
        let along =
            |x: &[DualSVec<f64, P>; N], j: usize| -> <M as crate::mechanism::Dynamics<N>>::Coords {
                <M as crate::mechanism::Dynamics<N>>::Coords::from_array(std::array::from_fn(|i| {
                    x[i].eps.0.as_ref().map_or(0.0, |d| d[j])
                }))
            };
        Sensitivities {
            state: self.state(),
            seeds: self.seeds,
            dq: std::array::from_fn(|j| along(&self.q, j)),
            dv: std::array::from_fn(|j| along(&self.v, j)),
        }
    }
}

/// Sensitivities of an adaptive Dormand–Prince 5(4) run from `state` to `t_end` with `settings`:
/// the plain run chooses its steps, then they are replayed on dual numbers with the step sizes
/// frozen. The result is the derivative of the map the plain run computed with its step sizes held
/// fixed (how the controller's choices depend on the initial values is not differentiated, which
/// changes the result by about the tolerance); its real parts are the plain run's, bit for bit.
///
/// Errors: those of [`Tangent::new`] and of the plain run ([`Dopri5::integrate`]); more than
/// `settings.max_steps` accepted steps is [`Error::StepSizeUnderflow`] at the time reached.
///
/// ```
/// use lagrange_core::sensitivity::{integrate_dopri5, Seed};
/// use lagrange_core::Dopri5;
/// # use lagrange_core::{impl_mechanism, vec2, Model, Scalar, State};
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
/// # impl_mechanism!(Pendulum, 1, 2);
/// let s0 = State::at_rest([0.01]);
/// let out = integrate_dopri5(&Pendulum, &s0, [Seed::Velocity("q0")], Dopri5::new(1e-10, 1e-12), 1.0)?;
/// // Linearised: ∂θ(t)/∂θ̇₀ = sin(ωt)/ω, to O(θ₀²).
/// let omega = 9.81f64.sqrt();
/// assert!((out.dq[0][0] - omega.sin() / omega).abs() < 1e-4);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn integrate_dopri5<
    M: Mechanism<N> + Parametrized<N, K, NP>,
    const N: usize,
    const K: usize,
    const NP: usize,
    const P: usize,
>(
    mechanism: &M,
    state: &State<<M as crate::mechanism::Dynamics<N>>::Coords>,
    seeds: [Seed; P],
    settings: Dopri5,
    t_end: f64,
) -> Result<Sensitivities<<M as crate::mechanism::Dynamics<N>>::Coords, P>> {
    let mut run = Tangent::new(mechanism, state, seeds)?;
    if !(t_end.is_finite() && t_end >= state.t) {
        return Err(Error::InvalidEndTime { t: state.t, t_end });
    }
    let mut plain = Dopri5Stepper::new(mechanism, settings, state)?;
    let mut accepted = 0;
    while plain.t() < t_end {
        if accepted == settings.max_steps {
            return Err(Error::StepSizeUnderflow {
                method: "Dopri5",
                t: plain.t(),
                h: plain.proposed_step(),
            });
        }
        plain.step(t_end)?;
        accepted += 1;
        run.dopri5_step(plain.last_step())?;
        // The last step lands on t_end exactly, which t + h need not.
        run.t = plain.t();
    }
    Ok(run.sensitivities())
}

fn constrained() -> Error {
    Error::UnsuitableMethod {
        method: "sensitivities",
        reason: "the mechanism declares constraints (or does not declare whether it has any), and \
                 the projection onto them after each step is not differentiated"
            .to_string(),
    }
}
