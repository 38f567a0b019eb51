//! Two small hand-written mechanisms for the examples in this module's documentation (what
//! `#[mechanism]` would generate for them). Not part of the public API.

use crate::dynamics::{self, EquationsOfMotion};
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::mechanism::Mechanism;
use crate::model::Model;

fn finite(parameters: &[(&'static str, f64)]) -> Result<()> {
    for &(name, value) in parameters {
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name, value });
        }
    }
    Ok(())
}

macro_rules! forward_mechanism {
    ($ty:ty, $n:literal) => {
        impl Mechanism<$n> for $ty {
            type Coords = [f64; $n];
            fn validate(&self) -> Result<()> {
                Model::validate(self)
            }
            fn equations_of_motion_at<S: Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> EquationsOfMotion<S, $n> {
                dynamics::equations_of_motion(self, t, q, v)
            }
            fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> S {
                dynamics::kinetic_energy(self, t, q, v)
            }
            fn potential_energy_at<S: Scalar>(&self, t: S, q: &[S; $n]) -> S {
                dynamics::potential_energy(self, t, q)
            }
            fn momenta_at<S: Scalar>(&self, t: S, q: &[S; $n], v: &[S; $n]) -> [S; $n] {
                dynamics::momenta(self, t, q, v)
            }
            fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> f64 {
                dynamics::lagrangian_time_derivative(self, t, q, v)
            }
        }
    };
}

/// A plane pendulum: bob of mass `m` on a massless rod of length `l`, angle θ from the downward
/// vertical, gravity `g`.
#[derive(Clone, Copy, Debug)]
pub struct Pendulum {
    pub m: f64,
    pub l: f64,
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
forward_mechanism!(Pendulum, 1);

/// A bead of mass `m` on a hoop of radius `r` spun about its vertical diameter at the constant rate
/// `omega`; θ is measured from the bottom. Rheonomic: x = R sin θ cos ωt, y = R sin θ sin ωt,
/// z = −R cos θ.
#[derive(Clone, Copy, Debug)]
pub struct SpinningHoop {
    pub m: f64,
    pub r: f64,
    pub g: f64,
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
forward_mechanism!(SpinningHoop, 1);
