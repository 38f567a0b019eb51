use lagrange::mechanism;

#[mechanism]
pub mod puck {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    pub struct Puck {
        pub m: f64,
        pub mu: f64,
    }

    #[particle(mass = m)]
    fn puck() -> Vec3 {
        vec3(x, y, z)
    }

    #[unilateral]
    fn floor() -> f64 {
        puck.z
    }

    // The slip velocity lies in the tangent plane: two components, not three.
    #[friction(on = floor, kinetic = mu)]
    fn rub() -> Vec3 {
        puck_dot
    }
}

fn main() {}
