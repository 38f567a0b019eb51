use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum<T> {
        pub m: T,
        pub l: T,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }
}

fn main() {
    let _ = pendulum::Pendulum { m: 1.0, l: 1.0 };
}
