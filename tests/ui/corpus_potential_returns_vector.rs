use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub x: f64,
    }

    pub struct P {
        pub m: f64,
        pub k: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, 0.0)
    }

    #[potential]
    fn spring() -> Vec2 {
        vec2(k * x, 0.0)
    }
}

fn main() {}
