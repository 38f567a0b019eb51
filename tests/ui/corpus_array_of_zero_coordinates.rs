use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub theta: [f64; 0],
    }

    pub struct P {
        pub m: f64,
    }
}

fn main() {}
