use lagrange::prelude::*;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct P {
        pub m: f64,
        pub l: f64,
    }

    #[rigid_body(mass = m, inertia = [0.1, 0.1, 0.02], com = vec3(0.0, 0.0, l * theta))]
    fn link() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_x(theta))
    }
}

fn main() {}
