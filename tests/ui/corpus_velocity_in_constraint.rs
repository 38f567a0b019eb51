use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct P {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }

    #[constraint]
    fn rail() -> f64 {
        y - x_dot
    }
}

fn main() {}
