//! Trajectory sensitivities by forward-mode differentiation through the integrator: a solver
//! ([`Stepper`]) that carries the tangent of its trajectory — the state on dual numbers
//! (`num_dual::DualSVec`) seeded on chosen initial values or parameters
//! ([`Stepper::with_sensitivities`]) — so the state carries ∂q(t)/∂q₀, ∂q(t)/∂p and the same for
//! q̇ exactly: the derivatives of the numerical solution (the discrete map the integrator
//! computes), not of an approximation of it.
//!
//! Seeded on initial values only, every evaluation is the mechanism's own scalar-generic
//! accelerations. Seeded on a parameter, the parameters are dual numbers too
//! ([`crate::parameters::Lifted`]) and the accelerations come from the generic dynamics of
//! [`crate::dynamics`] on the lifted model (whose forces read the inputs a driven mechanism
//! holds). Seeded on an input of a driven mechanism ([`crate::inputs::Driven`]), the inputs are
//! dual numbers held over the whole run and the forces read them through
//! [`crate::inputs::WithInputs`] on the seeds' dual type
//! ([`Dynamics::accelerations_with_inputs_at`]). Every step is the method's own code on the dual
//! type: with a fixed step, RK4's step on the duals is the step (the state is its real parts, the
//! plain run bit for bit on initial values alone); with Dopri5 the plain step chooses its size and
//! is taken again on the duals with that size frozen (how the controller's choices depend on the
//! seeds is not differentiated, which changes the result by about the tolerance). A step with `P`
//! seeds costs one pass of the accelerations on duals of width `P` per stage. The example is on
//! [`Stepper::with_sensitivities`].

use crate::dynamics::accelerations_generic;
use crate::error::{Error, Result};
use crate::evaluation::{diagnose, Dynamics, Evaluate};
use crate::integrate::{EmbeddedPair, Integrator, Method, Stats, Stepper, Tangent};
use crate::model::{Coordinates, State};
use crate::parameters::{Lifted, Parametrized};
use num_dual::DualSVec;

/// What to differentiate by: an initial value, named by its coordinate, a parameter, named by its
/// field, or an input, named by its field.
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
    /// An input of the mechanism's `#[inputs]`, named as in
    /// [`Inputs::NAMES`](crate::inputs::Inputs::NAMES) (`tau[1]` for an element of an array
    /// field), held at its value over the whole run: on `sys.driven(&u)` the derivative is by
    /// that input of `u` held constant from now on.
    ///
    /// ```
    /// use lagrange_core::integrate::Stepper;
    /// use lagrange_core::sensitivity::Seed;
    /// # use lagrange_core::analysis::doc_models::{DrivenPendulum, Pendulum, Torque};
    /// use lagrange_core::{Integrator, Mechanism, Rk4, State};
    /// // A pendulum (m = 2, l = 1, g = 9.81) at rest, a torque τ = 0 held at its pivot: the
    /// // tangent follows m l² δθ̈ = δτ − m g l δθ, so ∂θ(t)/∂τ = (1 − cos ωt) / (m g l), ω² = g/l.
    /// let sys = DrivenPendulum(Pendulum { m: 2.0, l: 1.0, g: 9.81 });
    /// let driven = sys.driven(&Torque { tau: 0.0 });
    /// let mut run = Stepper::new(&driven, Rk4::with_step(1e-3), &State::at_rest([0.0]))?
    ///     .with_sensitivities([Seed::Input("tau")])?;
    /// run.integrate(1.0, &mut [], |_| {})?;
    /// let by_tau = run.sensitivities().dq[0][0];
    /// // RK4's error over the run, ~(ωh)⁴ ωt, is ~1e-11.
    /// assert!((by_tau - (1.0 - 9.81f64.sqrt().cos()) / (2.0 * 9.81)).abs() < 1e-9);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    Input(&'static str),
}

impl Seed {
    /// `theta1(0)`, `theta1_dot(0)` or `l`.
    pub fn label(&self) -> String {
        match self {
            Seed::Coordinate(name) => format!("{name}(0)"),
            Seed::Velocity(name) => format!("{name}_dot(0)"),
            Seed::Parameter(name) | Seed::Input(name) => name.to_string(),
        }
    }
}

/// The state and its derivatives with respect to each seed, named like the coordinates:
/// `dq[j].theta1` is ∂θ₁/∂(seed j), `dv[j].theta1` is ∂θ̇₁/∂(seed j).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sensitivities<C, const P: usize> {
    /// The state (the solver's).
    pub state: State<C>,
    /// The seeds, in the order of `dq` and `dv`.
    pub seeds: [Seed; P],
    /// ∂q/∂(seed j), one set of coordinates per seed.
    pub dq: [C; P],
    /// ∂q̇/∂(seed j), one set of coordinates per seed.
    pub dv: [C; P],
}

/// The tangent of a trajectory a [`Stepper`] carries ([`Stepper::with_sensitivities`]): the
/// state on dual numbers of width `P`, one per seed, the parameters lifted to them where a
/// parameter is seeded and the inputs where an input is. `K` and `NP` are the model's Cartesian
/// rows and parameters (inferred from its [`Parametrized`] implementation).
pub struct SeededTangent<'m, L, const N: usize, const K: usize, const NP: usize, const P: usize> {
    lifted: Lifted<'m, L, DualSVec<f64, P>, K, NP>,
    /// Where the accelerations on the duals come from.
    by: SeededOn,
    /// The inputs held over the run, flat, on the duals (seeded where an input is); empty unless
    /// an input is seeded.
    inputs: Vec<DualSVec<f64, P>>,
    seeds: [Seed; P],
    q: [DualSVec<f64, P>; N],
    v: [DualSVec<f64, P>; N],
}

/// What the seeds of a tangent reach beyond the state, and so which accelerations it evaluates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SeededOn {
    /// Initial values only: the mechanism's own accelerations.
    State,
    /// A parameter: the lifted model's.
    Parameters,
    /// An input: the model's with the inputs on the duals.
    Inputs,
}

impl<L, const N: usize, const K: usize, const NP: usize, const P: usize> Clone
    for SeededTangent<'_, L, N, K, NP, P>
{
    fn clone(&self) -> Self {
        SeededTangent {
            inputs: self.inputs.clone(),
            ..*self
        }
    }
}

impl<L, const N: usize, const K: usize, const NP: usize, const P: usize> std::fmt::Debug
    for SeededTangent<'_, L, N, K, NP, P>
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SeededTangent")
            .field("seeds", &self.seeds)
            .field("parameters", self.lifted.parameters())
            .field("q", &self.q)
            .field("v", &self.v)
            .finish()
    }
}

impl<'m, L, const N: usize, const K: usize, const NP: usize, const P: usize>
    SeededTangent<'m, L, N, K, NP, P>
where
    L: Parametrized<N, K, NP> + Dynamics<N>,
{
    /// q̈ on the duals: the mechanism's own accelerations, the lifted model's when a parameter is
    /// seeded, the model's with the inputs on the duals when an input is.
    fn accelerations<M: Evaluate<N, Model = L>>(
        &self,
        mechanism: &M,
        t: f64,
        q: &[DualSVec<f64, P>; N],
        v: &[DualSVec<f64, P>; N],
    ) -> Result<[DualSVec<f64, P>; N]> {
        let t_dual = DualSVec::from_re(t);
        let a = match self.by {
            SeededOn::State => mechanism.accelerations_at(t_dual, q, v),
            SeededOn::Parameters => accelerations_generic(&self.lifted, t_dual, q, v),
            SeededOn::Inputs => Dynamics::accelerations_with_inputs_at(
                mechanism.model(),
                &self.inputs,
                t_dual,
                q,
                v,
            ),
        };
        a.map_err(|e| {
            let (qr, vr) = (q.map(|x| x.re), v.map(|x| x.re));
            diagnose(mechanism, t, &qr, &vr, e)
        })
    }
}

impl<'m, M, L, const N: usize, const K: usize, const NP: usize, const P: usize> Tangent<M, N>
    for SeededTangent<'m, L, N, K, NP, P>
where
    M: Evaluate<N, Model = L>,
    L: Parametrized<N, K, NP> + Dynamics<N>,
{
    const ACTIVE: bool = true;

    fn step<I: Integrator>(
        &mut self,
        mechanism: &M,
        t: f64,
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        let (q, v) = (self.q, self.v);
        let acc = |t: f64, q: &[DualSVec<f64, P>; N], v: &[DualSVec<f64, P>; N]| {
            self.accelerations(mechanism, t, q, v)
        };
        let rates = |q: &[DualSVec<f64, P>; N], v: &[DualSVec<f64, P>; N]| {
            mechanism.position_rates_at(q, v)
        };
        let (q1, v1) = I::advance_on_duals(t, (&q, &v), h, rates, acc, stats)?;
        (self.q, self.v) = (q1, v1);
        Ok((q1.map(|x| x.re), v1.map(|x| x.re)))
    }

    fn replay<Pair: EmbeddedPair>(
        &mut self,
        mechanism: &M,
        method: &Pair,
        t: f64,
        h: f64,
    ) -> Result<()> {
        let (q, v) = (self.q, self.v);
        let acc = |t: f64, q: &[DualSVec<f64, P>; N], v: &[DualSVec<f64, P>; N]| {
            self.accelerations(mechanism, t, q, v)
        };
        let rates = |q: &[DualSVec<f64, P>; N], v: &[DualSVec<f64, P>; N]| {
            mechanism.position_rates_at(q, v)
        };
        (self.q, self.v) = method.replay(t, (&q, &v), h, rates, acc)?;
        Ok(())
    }

    fn switch_charts(&mut self, mechanism: &M) {
        mechanism.switch_charts(&mut self.q, &mut self.v);
    }
}

impl<'m, M: Evaluate<N>, Me: Method<N>, const N: usize> Stepper<'m, M, Me, N> {
    /// The same solver carrying the tangent of its trajectory from the current state, with
    /// derivative 1 along each seed: after any steps, [`sensitivities`](Stepper::sensitivities)
    /// are the derivatives of the state with respect to the seeds' values now.
    ///
    /// Errors: a seed naming no coordinate ([`Error::UnknownCoordinate`]), no parameter
    /// ([`Error::UnknownParameter`]) or no input ([`Error::UnknownInput`], also on a mechanism
    /// that declares none), a parameter that carries no derivative
    /// ([`Error::UnseedableParameter`]), a parameter seeded beside an input
    /// ([`Error::ParameterSeedWithInputs`]), a mechanism that declares constraints or does not
    /// say (the projection onto the constraints is not differentiated), a method whose steps are
    /// not taken on dual numbers (with a fixed step RK4, adaptively Dopri5)
    /// ([`Error::UnsuitableMethod`]).
    ///
    /// ```
    /// use lagrange_core::integrate::Stepper;
    /// use lagrange_core::sensitivity::Seed;
    /// # use lagrange_core::{impl_mechanism, vec2, Integrator, Model, Rk4, Scalar, State};
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
    /// // A unit pendulum (g = 9.81) released at rest from 0.01 rad: ∂θ(t)/∂θ₀ = cos(ωt) for the
    /// // linearised motion; the amplitude's frequency shift ω θ₀²/16 moves it by ~2e-5 at t = 1.
    /// let s0 = State::at_rest([0.01]);
    /// let mut run = Stepper::new(&Pendulum, Rk4::with_step(1e-3), &s0)?
    ///     .with_sensitivities([Seed::Coordinate("q0")])?;
    /// run.integrate(1.0, &mut [], |_| {})?;
    /// let by_theta0 = run.sensitivities().dq[0];
    /// assert!((by_theta0[0] - (9.81f64.sqrt() * 1.0).cos()).abs() < 1e-4);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn with_sensitivities<const K: usize, const NP: usize, const P: usize>(
        self,
        seeds: [Seed; P],
    ) -> Result<Stepper<'m, M, Me, N, SeededTangent<'m, M::Model, N, K, NP, P>>>
    where
        M::Model: Parametrized<N, K, NP>,
    {
        // Decided by the declaration alone, as the integrators decide.
        if M::CONSTRAINTS != Some(0) {
            return Err(constrained());
        }
        if !Me::TANGENT {
            return Err(Error::UnsuitableMethod {
                method: Me::NAME,
                reason: "its steps are not taken on dual numbers: sensitivities are RK4's with a \
                         fixed step and Dopri5's adaptively"
                    .to_string(),
            });
        }
        let parameter = seeds.iter().find_map(|seed| match seed {
            Seed::Parameter(name) => Some(*name),
            _ => None,
        });
        let held = self.mechanism.prepared().inputs;
        let input_seeded = seeds.iter().any(|seed| matches!(seed, Seed::Input(_)));
        if let (Some(name), true) = (parameter, input_seeded) {
            return Err(Error::ParameterSeedWithInputs { name });
        }
        let tangent = seeded::<M::Coords, _, N, K, NP, P>(
            self.mechanism.model(),
            (&self.q, &self.v),
            held,
            seeds,
        )?;
        Ok(self.carrying(tangent))
    }
}

/// The tangent at (q, q̇) with the inputs `held` (flat, zeros where it has fewer than the
/// declaration) seeded on `seeds`, the coordinates named as `C`.
fn seeded<'m, C, L, const N: usize, const K: usize, const NP: usize, const P: usize>(
    model: &'m L,
    (q0, v0): (&[f64; N], &[f64; N]),
    held: &'m [f64],
    seeds: [Seed; P],
) -> Result<SeededTangent<'m, L, N, K, NP, P>>
where
    C: Coordinates<N>,
    L: Parametrized<N, K, NP> + Dynamics<N>,
{
    let mut q: [DualSVec<f64, P>; N] = std::array::from_fn(|i| DualSVec::from_re(q0[i]));
    let mut v: [DualSVec<f64, P>; N] = std::array::from_fn(|i| DualSVec::from_re(v0[i]));
    let mut p: [DualSVec<f64, P>; NP] = model.parameters().map(DualSVec::from_re);
    let mut inputs: Vec<DualSVec<f64, P>> = (0..L::INPUT_NAMES.len())
        .map(|i| DualSVec::from_re(held.get(i).copied().unwrap_or(0.0)))
        .collect();
    let mut by = SeededOn::State;
    for (j, seed) in seeds.iter().enumerate() {
        match seed {
            Seed::Coordinate(name) => {
                let i = coordinate::<C, N>(name)?;
                q[i] = q[i].derivative(j);
            }
            Seed::Velocity(name) => {
                let i = coordinate::<C, N>(name)?;
                v[i] = v[i].derivative(j);
            }
            Seed::Parameter(name) => {
                let i = parameter::<L, N, K, NP>(name)?;
                p[i] = p[i].derivative(j);
                by = SeededOn::Parameters;
            }
            Seed::Input(name) => {
                let i = input::<L, N>(name)?;
                inputs[i] = inputs[i].derivative(j);
                by = SeededOn::Inputs;
            }
        }
    }
    if by != SeededOn::Inputs {
        inputs.clear();
    }
    Ok(SeededTangent {
        lifted: Lifted::new(model, p).with_inputs(held),
        by,
        inputs,
        seeds,
        q,
        v,
    })
}

impl<'m, M, Me, const N: usize, const K: usize, const NP: usize, const P: usize>
    Stepper<'m, M, Me, N, SeededTangent<'m, M::Model, N, K, NP, P>>
where
    M: Evaluate<N>,
    Me: Method<N>,
    M::Model: Parametrized<N, K, NP>,
{
    /// The state and its derivatives along every seed.
    pub fn sensitivities(&self) -> Sensitivities<M::Coords, P> {
        let tangent = &self.tangent;
        let along = |x: &[DualSVec<f64, P>; N], j: usize| -> M::Coords {
            M::Coords::from_array(std::array::from_fn(|i| {
                x[i].eps.0.as_ref().map_or(0.0, |d| d[j])
            }))
        };
        Sensitivities {
            state: self.state(),
            seeds: tangent.seeds,
            dq: std::array::from_fn(|j| along(&tangent.q, j)),
            dv: std::array::from_fn(|j| along(&tangent.v, j)),
        }
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

/// Index of `name` among the declaration's inputs, or [`Error::UnknownInput`] (a mechanism
/// without `#[inputs]` has none).
fn input<L: Dynamics<N>, const N: usize>(name: &str) -> Result<usize> {
    L::INPUT_NAMES
        .iter()
        .position(|n| *n == name)
        .ok_or_else(|| Error::UnknownInput {
            name: name.to_string(),
            known: match L::INPUT_NAMES {
                [] => "none (the mechanism declares no `#[inputs]`)".to_string(),
                names => names
                    .iter()
                    .map(|n| format!("`{n}`"))
                    .collect::<Vec<_>>()
                    .join(", "),
            },
        })
}

fn constrained() -> Error {
    Error::UnsuitableMethod {
        method: "sensitivities",
        reason: "the mechanism declares constraints (or does not declare whether it has any), and \
                 the projection onto them after each step is not differentiated"
            .to_string(),
    }
}
