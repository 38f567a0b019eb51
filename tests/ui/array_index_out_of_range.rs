use lagrange::prelude::*;

#[mechanism]
pub mod chain {
    pub const LINKS: usize = 2;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m)]
    fn first() -> Vec2 {
        vec2(theta[0].sin(), -theta[0].cos()) * l
    }

    #[particle(mass = m)]
    fn second() -> Vec2 {
        first + vec2(theta[2].sin(), -theta[1].cos()) * l
    }
}

fn main() {}
