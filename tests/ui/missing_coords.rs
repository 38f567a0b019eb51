use lagrange::prelude::*;

#[mechanism]
pub mod pendulum {
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
    let p = pendulum::Pendulum { m: 1.0, l: 1.0 };
    let _ = p.validate();
}
