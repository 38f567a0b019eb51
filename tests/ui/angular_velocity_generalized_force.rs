use lagrange::prelude::*;

// A generalized force on a chart's coordinate is dual to its rate, not to the angular velocity.
#[mechanism]
pub mod top {
    pub struct Coords {
        #[angular_velocity]
        pub a: f64,
        #[angular_velocity]
        pub b: f64,
        #[angular_velocity]
        pub c: f64,
    }

    pub struct Top {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(a, b, c)))
    }

    #[generalized_force(on = c)]
    fn spin() -> f64 {
        0.1
    }
}

fn main() {}
