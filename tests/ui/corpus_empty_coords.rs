use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {}

    pub struct P {
        pub m: f64,
    }
}

fn main() {}
