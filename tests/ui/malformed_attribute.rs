use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub length: f64,
    }

    #[particle(mass)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * length
    }
}

fn main() {}
