use lagrange::prelude::*;

// Inputs are numbers the forces read as the scalar of the evaluation.
#[mechanism]
pub mod cart {
    pub struct Coords {
        pub x: f64,
    }

    pub struct Cart {
        pub m: f64,
    }

    #[inputs]
    pub struct Push {
        pub f: f32,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, 0.0)
    }

    #[generalized_force(on = x)]
    fn drive() -> f64 {
        f
    }
}

fn main() {}
