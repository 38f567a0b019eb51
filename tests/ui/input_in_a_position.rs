use lagrange::prelude::*;

// An input moves the bob directly: inputs act through forces.
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
        pub f: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x + f, 0.0)
    }

    #[generalized_force(on = x)]
    fn drive() -> f64 {
        f
    }
}

fn main() {}
