use lagrange::prelude::*;

// `i` is a family's own index: a single body has none to name in its mass.
#[mechanism]
pub mod arm {
    pub struct Coords {
        pub a: f64,
    }

    pub struct Arm {
        pub m: [f64; 2],
        pub l: f64,
    }

    #[particle(mass = m[i])]
    fn bob() -> Vec2 {
        vec2(a.sin(), -a.cos()) * l
    }
}

fn main() {}
