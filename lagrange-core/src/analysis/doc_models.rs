//! Small hand-written mechanisms for the examples in this module's documentation (what
//! `#[mechanism]` would generate for them). Not part of the public API.

use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::impl_mechanism;
use crate::model::Model;

fn finite(parameters: &[(&'static str, f64)]) -> Result<()> {
    for &(name, value) in parameters {
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name, value });
        }
    }
    Ok(())
}

/// A plane pendulum: bob of mass `m` on a massless rod of length `l`, angle θ from the downward
/// vertical, gravity `g`.
#[derive(Clone, Copy, Debug)]
pub struct Pendulum {
    /// Bob mass.
    pub m: f64,
    /// Rod length.
    pub l: f64,
    /// Gravitational acceleration.
    pub g: f64,
}

impl Model<1, 2> for Pendulum {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> Result<()> {
        finite(&[("m", self.m), ("l", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m; 2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
        [q[0].sin() * self.l, -q[0].cos() * self.l]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}
impl_mechanism!(Pendulum, 1, 2);

/// A bead of mass `m` on a hoop of radius `r` spun about its vertical diameter at the constant rate
/// `omega`; θ is measured from the bottom. Rheonomic: x = R sin θ cos ωt, y = R sin θ sin ωt,
/// z = −R cos θ.
#[derive(Clone, Copy, Debug)]
pub struct SpinningHoop {
    /// Bead mass.
    pub m: f64,
    /// Hoop radius.
    pub r: f64,
    /// Gravitational acceleration.
    pub g: f64,
    /// Constant spin rate of the hoop about its vertical diameter.
    pub omega: f64,
}

impl Model<1, 3> for SpinningHoop {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> Result<()> {
        finite(&[
            ("m", self.m),
            ("r", self.r),
            ("g", self.g),
            ("omega", self.omega),
        ])
    }
    fn masses(&self) -> [f64; 3] {
        [self.m; 3]
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 3] {
        let spin = t * self.omega;
        let rho = q[0].sin() * self.r;
        [rho * spin.cos(), rho * spin.sin(), -q[0].cos() * self.r]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 3]) -> D {
        x[2] * (self.m * self.g)
    }
}
impl_mechanism!(SpinningHoop, 1, 3);

/// A plane pendulum in Cartesian coordinates (x, y) of the bob (mass `m`), the rod written as the
/// holonomic constraint `rod`: √(x² + y²) − `l` = 0; gravity `g` along −y.
#[derive(Clone, Copy, Debug)]
pub struct CartesianPendulum {
    /// Bob mass.
    pub m: f64,
    /// Rod length.
    pub l: f64,
    /// Gravitational acceleration, along −y.
    pub g: f64,
}

impl Model<2, 2> for CartesianPendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> Result<()> {
        finite(&[("m", self.m), ("l", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m; 2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl crate::constraints::Constraints<2, 2, 1> for CartesianPendulum {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [crate::constraints::ConstraintKind; 1] =
        [crate::constraints::ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [(x[0] * x[0] + x[1] * x[1]).sqrt() - self.l]
    }
}
impl_mechanism!(CartesianPendulum, 2, 2, constraints);

/// [`Pendulum`] driven by a torque τ at its pivot (the one input, [`Torque`]):
/// m l² θ̈ = τ − m g l sin θ.
#[derive(Clone, Copy, Debug)]
pub struct DrivenPendulum(pub Pendulum);

/// The input of [`DrivenPendulum`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Torque {
    /// The torque at the pivot.
    pub tau: f64,
}

impl crate::inputs::Inputs<1> for Torque {
    const NAMES: [&'static str; 1] = ["tau"];
    fn to_array(&self) -> [f64; 1] {
        [self.tau]
    }
    fn from_array([tau]: [f64; 1]) -> Self {
        Torque { tau }
    }
}

impl crate::inputs::Actuated<1> for DrivenPendulum {
    type Inputs = Torque;
}

impl Model<1, 2> for DrivenPendulum {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> Result<()> {
        self.0.validate()
    }
    fn masses(&self) -> [f64; 2] {
        self.0.masses()
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 2] {
        self.0.cartesian(t, q)
    }
    fn potential<D: Scalar>(&self, t: D, q: &[D; 1], x: &[D; 2]) -> D {
        self.0.potential(t, q, x)
    }
    #[allow(clippy::too_many_arguments)]
    fn applied_forces<S: Scalar>(
        &self,
        t: S,
        q: &[S; 1],
        v: &[S; 1],
        x: &[S; 2],
        x_dot: &[S; 2],
        cartesian_force: &mut [S; 2],
        generalized_force: &mut [S; 1],
    ) {
        use crate::inputs::ActuatedModel;
        let zero = [0.0];
        self.applied_forces_with_inputs(
            &zero,
            t,
            q,
            v,
            x,
            x_dot,
            cartesian_force,
            generalized_force,
        )
    }
}

impl crate::inputs::ActuatedModel<1, 2, 1> for DrivenPendulum {
    fn applied_forces_with_inputs<S: Scalar, U: Scalar>(
        &self,
        u: &[U; 1],
        _t: S,
        _q: &[S; 1],
        _v: &[S; 1],
        _x: &[S; 2],
        _x_dot: &[S; 2],
        _cartesian_force: &mut [S; 2],
        generalized_force: &mut [S; 1],
    ) {
        generalized_force[0] += crate::inputs::input::<U, S>(&u[0]);
    }
}
impl_mechanism!(DrivenPendulum, 1, 2, inputs 1);
