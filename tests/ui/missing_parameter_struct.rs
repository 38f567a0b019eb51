use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    #[particle(mass = 1.0)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos())
    }
}

fn main() {}
