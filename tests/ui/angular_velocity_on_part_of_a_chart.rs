use lagrange::prelude::*;

// The angular velocity has three components: `c`, in the same chart, is not marked.
#[mechanism]
pub mod top {
    pub struct Coords {
        #[angular_velocity]
        pub a: f64,
        #[angular_velocity]
        pub b: f64,
        pub c: f64,
    }

    pub struct Top {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(a, b, c)))
    }
}

fn main() {}
