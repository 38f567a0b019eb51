use lagrange::mechanism;

const fn links() -> usize {
    3
}

#[mechanism]
pub mod chain {
    pub struct Coords {
        pub theta: [f64; super::links()],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m, count = 3)]
    fn bob(i: usize) -> Vec2 {
        vec2(theta[i].sin(), -theta[i].cos()) * l
    }
}

fn main() {
    let s = chain::State::at_rest(chain::Coords { theta: [0.1; 3] });
    let _ = s.q.theta[2];
}
