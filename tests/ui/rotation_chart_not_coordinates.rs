use lagrange::prelude::*;

// A rotation chart's vector is three coordinates: the generated code switches them to an
// equivalent rotation past an angle of π, which it cannot do to an expression.
#[mechanism]
pub mod top {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }

    pub struct Top {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_vector(vec3(a, b, 0.5 * c)))
    }
}

fn main() {}
