use lagrange::prelude::*;

// The marker says everything: it takes no arguments.
#[mechanism]
pub mod top {
    pub struct Coords {
        #[angular_velocity(body)]
        pub attitude: [f64; 3],
    }

    pub struct Top {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(attitude[0], attitude[1], attitude[2])))
    }
}

fn main() {}
