use lagrange::mechanism;

#[mechanism]
pub mod double_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
    }

    #[particle]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l3
    }
}

fn main() {}
