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

    #[friction(on = floor, kinetic = mu)]
    fn rub() -> Vec2 {
        vec2(puck_dot.x, puck_dot.y)
    }

    // The cone already bounds the whole tangential force at `floor`.
    #[friction(on = floor, kinetic = mu)]
    fn drag() -> f64 {
        puck_dot.x
    }
}

fn main() {}
