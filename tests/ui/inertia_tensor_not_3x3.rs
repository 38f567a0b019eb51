use lagrange::prelude::*;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct P {
        pub m: f64,
        pub ixx: f64,
        pub iyy: f64,
    }

    #[rigid_body(mass = m, inertia = [[ixx, 0.0], [0.0, iyy]])]
    fn link() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_x(theta))
    }
}

fn main() {}
