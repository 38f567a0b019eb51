use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coordinates {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }
}

fn main() {
    let _ = pendulum::Pendulum { m: 1.0, l: 1.0 };
}
