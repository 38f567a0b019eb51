use lagrange::mechanism;

#[mechanism]
pub mod mixed {
    pub struct Coords {
        pub theta: f64,
        pub z: f64,
    }

    pub struct Mixed {
        pub m: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos())
    }

    // A `Vec2` field would not act on this particle.
    #[particle(mass = m)]
    fn bead() -> Vec3 {
        vec3(0.0, 0.0, z)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

fn main() {}
