//! A generic helper function called from a body (one in the module, one outside it by a path), a
//! helper taking `f64` in an attribute, and a vector divided by a scalar.
use lagrange::prelude::*;

/// Outside the module, generic over the scalar: called as `super::half(..)`.
pub fn half<D: lagrange::Scalar>(x: D) -> D {
    x * 0.5
}

#[mechanism]
pub mod helpers {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Helpers {
        pub m: f64,
        pub l: f64,
    }

    fn arm<D: lagrange::Scalar>(angle: D) -> D {
        angle.sin()
    }

    fn doubled(x: f64) -> f64 {
        2.0 * x
    }

    #[particle(mass = doubled(m) / 2.0)]
    fn bob() -> Vec2 {
        vec2(arm(theta), -theta.cos()) * super::half(l) * 4.0 / 2.0
    }
}

fn main() {
    let p = helpers::Helpers { m: 1.0, l: 1.0 };
    let s = helpers::State::at_rest(helpers::Coords { theta: 0.3 });
    let a = p.accelerations(&s).unwrap().theta;
    // θ̈ = −(g/l) sin θ with no gravity declared: the pendulum at rest does not move.
    assert_eq!(a, 0.0);
}
