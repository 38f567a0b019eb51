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

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        return vec2(theta.sin(), -theta.cos()) * length;
    }
}

fn main() {}
