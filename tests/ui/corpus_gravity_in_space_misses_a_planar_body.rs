use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub x: f64,
        pub z: f64,
    }

    pub struct P {
        pub m: f64,
        pub i: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec3 {
        vec3(0.0, 0.0, z)
    }

    #[rigid_body(mass = m, inertia = i)]
    fn bar() -> Planar {
        planar(vec2(x, 0.0), x)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -9.81)
    }
}

fn main() {}
