use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum(pub f64, pub f64);

    #[particle(mass = 1.0)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos())
    }
}

fn main() {
    let _ = pendulum::State::at_rest(pendulum::Coords { theta: 0.1 });
}
