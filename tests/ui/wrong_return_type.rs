use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m)]
    fn bob() -> f64 {
        theta * l
    }
}

fn main() {}
