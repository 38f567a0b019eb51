//! Systems of units for tests that declare the same physics in several: a unit of length, mass and
//! time (each given in SI), and the factor that converts an SI value of a given dimension into them.

/// A dimension Lᵃ Mᵇ Tᶜ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dim {
    pub length: i32,
    pub mass: i32,
    pub time: i32,
}

/// Lᵃ Mᵇ Tᶜ.
pub const fn dim(length: i32, mass: i32, time: i32) -> Dim {
    Dim { length, mass, time }
}

/// Dimensionless (an angle, a friction coefficient).
pub const ONE: Dim = dim(0, 0, 0);
/// A length.
pub const LENGTH: Dim = dim(1, 0, 0);
/// A mass.
pub const MASS: Dim = dim(0, 1, 0);
/// A time.
pub const TIME: Dim = dim(0, 0, 1);
/// A moment of inertia, M L².
pub const INERTIA: Dim = dim(2, 1, 0);
/// An acceleration, L T⁻², such as g.
pub const ACCELERATION: Dim = dim(1, 0, -2);
/// A rate, T⁻¹ (an angular velocity).
pub const RATE: Dim = dim(0, 0, -1);
/// A stiffness, M T⁻² (force per length).
pub const STIFFNESS: Dim = dim(0, 1, -2);
/// A force, M L T⁻².
pub const FORCE: Dim = dim(1, 1, -2);
/// A torque or an energy, M L² T⁻².
pub const TORQUE: Dim = dim(2, 1, -2);

/// The units: one unit of length is `length` metres, of mass `mass` kilograms, of time `time`
/// seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Units {
    pub length: f64,
    pub mass: f64,
    pub time: f64,
}

/// Metres, kilograms, seconds.
pub const SI: Units = Units {
    length: 1.0,
    mass: 1.0,
    time: 1.0,
};

impl Units {
    /// The size of one unit of `d` in SI: Lᵃ Mᵇ Tᶜ.
    pub fn unit(self, d: Dim) -> f64 {
        self.length.powi(d.length) * self.mass.powi(d.mass) * self.time.powi(d.time)
    }

    /// An SI value of dimension `d` in these units.
    pub fn express(self, value: f64, d: Dim) -> f64 {
        value / self.unit(d)
    }

    /// A value of dimension `d` in these units, in SI.
    pub fn in_si(self, value: f64, d: Dim) -> f64 {
        value * self.unit(d)
    }

    /// A short label: "L 1e-6", "M 1e3 T 1e9", "SI".
    pub fn label(self) -> String {
        let mut parts = Vec::new();
        for (name, x) in [("L", self.length), ("M", self.mass), ("T", self.time)] {
            if x != 1.0 {
                parts.push(format!("{name} {x:e}"));
            }
        }
        if parts.is_empty() {
            "SI".to_string()
        } else {
            parts.join(" ")
        }
    }
}
