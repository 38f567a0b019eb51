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
        // Naming `y` in a binding the position never uses does not make the body depend on it.
        let _unused = y;
        vec2(x, 0.0)
    }
}

fn main() {}
