use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub theta: [f64; 2],
    }

    pub struct P {
        pub m: f64,
    }

    #[particle(mass = m, count = 2)]
    fn bob(i: usize) -> Vec2 {
        vec2(theta[i], 0.0)
    }

    #[generalized_force(on = theta)]
    fn push() -> f64 {
        1.0
    }
}

fn main() {}
