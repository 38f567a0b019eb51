use lagrange::prelude::*;

// `l` holds two lengths: the position needs one of them.
#[mechanism]
pub mod arm {
    pub struct Coords {
        pub a: f64,
    }

    pub struct Arm {
        pub m: f64,
        pub l: [f64; 2],
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(a.sin(), -a.cos()) * l
    }
}

fn main() {}
