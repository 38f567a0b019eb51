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
    fn block() -> Vec2 {
        vec2(x, y)
    }

    #[unilateral]
    fn floor() -> f64 {
        y
    }

    #[friction(on = floor)]
    fn slip() -> f64 {
        x_dot
    }
}

fn main() {}
