use lagrange::prelude::*;

// `#[angular_velocity]` marks coordinates, not a parameter.
#[mechanism]
pub mod top {
    pub struct Coords {
        pub attitude: [f64; 3],
    }

    pub struct Top {
        #[angular_velocity]
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(attitude[0], attitude[1], attitude[2])))
    }
}

fn main() {}
