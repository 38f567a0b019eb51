use lagrange::prelude::*;

#[mechanism]
pub mod chain {
    pub struct Coords {
        pub theta: [f64; 3],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m, count = 4)]
    fn bob(i: usize) -> Vec2 {
        vec2(theta[i].sin(), -theta[i].cos()) * l
    }
}

fn main() {}
