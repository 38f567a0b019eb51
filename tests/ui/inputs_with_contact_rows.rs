use lagrange::prelude::*;

// A ball pushed along a floor it may leave: contact modes are stepped without inputs.
#[mechanism]
pub mod ball {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Ball {
        pub m: f64,
        pub g: f64,
    }

    #[inputs]
    pub struct Push {
        pub f: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = bob)]
    fn push() -> Vec2 {
        vec2(f, 0.0)
    }

    #[unilateral]
    fn floor() -> f64 {
        y
    }
}

fn main() {}
