use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub t: f64,
    }

    pub struct P {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(t, 0.0)
    }
}

fn main() {}
