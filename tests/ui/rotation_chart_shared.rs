use lagrange::prelude::*;

// Each coordinate writes one rotation, in one chart: `c` cannot be in both.
#[mechanism]
pub mod pair {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
        pub d: f64,
        pub e: f64,
    }

    pub struct Pair {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn first() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_vector(vec3(a, b, c)))
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn second() -> Spatial {
        spatial(vec3(1.0, 0.0, 0.0), rot_mrp(vec3(c, d, e)))
    }
}

fn main() {}
