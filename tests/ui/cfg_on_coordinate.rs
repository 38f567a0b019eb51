use lagrange::mechanism;

#[mechanism]
pub mod cart {
    pub struct Coords {
        pub x: f64,
        #[cfg(any())]
        pub y: f64,
    }

    pub struct Cart {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn cart() -> Vec2 {
        vec2(x, y)
    }
}

fn main() {}
