use lagrange::prelude::*;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    fn arm(angle: f64) -> f64 {
        angle.sin()
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(arm(theta), -theta.cos()) * l
    }
}

fn main() {}
