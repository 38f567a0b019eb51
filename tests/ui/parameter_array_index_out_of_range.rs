use lagrange::prelude::*;

// Two lengths, indexed by a literal past the end; and an empty array of parameters.
#[mechanism]
pub mod arm {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
    }

    pub struct Arm {
        pub m: f64,
        pub l: [f64; 2],
        pub unused: [f64; 0],
    }

    #[particle(mass = m)]
    fn first() -> Vec2 {
        vec2(a.sin(), -a.cos()) * l[0]
    }

    #[particle(mass = m)]
    fn second() -> Vec2 {
        first + vec2(b.sin(), -b.cos()) * l[2]
    }
}

fn main() {}
