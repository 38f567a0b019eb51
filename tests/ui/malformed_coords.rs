use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords(f64);

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(0.0, -l)
    }
}

fn main() {
    let _ = pendulum::Pendulum { m: 1.0, l: 1.0 };
}
