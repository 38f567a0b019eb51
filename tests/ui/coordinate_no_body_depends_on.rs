use lagrange::mechanism;

#[mechanism]
pub mod cart {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Cart {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }
}

fn main() {}
