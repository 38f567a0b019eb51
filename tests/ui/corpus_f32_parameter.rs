use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub x: f64,
    }

    pub struct P {
        pub m: f32,
    }

    #[particle(mass = 1.0)]
    fn bob() -> Vec2 {
        vec2(x, 0.0)
    }
}

fn main() {}
