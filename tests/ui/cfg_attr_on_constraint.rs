use lagrange::mechanism;

#[mechanism]
pub mod bead {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Bead {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec2 {
        vec2(x, y)
    }

    #[cfg_attr(test, allow(unused))]
    #[constraint]
    fn wire() -> f64 {
        y - x * x
    }
}

fn main() {}
