use lagrange::prelude::*;

/// A helper outside the declaration's module, taking `f64`.
pub fn my_sin(a: f64) -> f64 {
    a.sin()
}

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(super::my_sin(theta), -theta.cos()) * l
    }
}

fn main() {}
