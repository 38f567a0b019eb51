use lagrange::prelude::*;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct P {
        pub m: f64,
        pub i: f64,
        pub l: f64,
    }

    #[rigid_body(mass = m, inertia = i, com = vec3(0.5 * l, 0.0, 0.0))]
    fn rod() -> Planar {
        planar(vec2(0.0, 0.0), theta)
    }
}

fn main() {}
