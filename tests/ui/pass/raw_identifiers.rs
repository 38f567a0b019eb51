//! Raw identifiers as coordinate, parameter and body names: `r#type` is read as written, and its
//! velocity is `type_dot`.
use lagrange::prelude::*;

#[mechanism]
pub mod raw {
    pub struct Coords {
        pub r#type: f64,
        pub r#match: f64,
    }

    pub struct Raw {
        pub m: f64,
        pub r#loop: f64,
        pub c: f64,
    }

    #[particle(mass = m)]
    fn r#box() -> Vec2 {
        vec2(r#type.sin(), -r#type.cos()) * r#loop
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        r#box + vec2(r#match.sin(), -r#match.cos()) * r#loop
    }

    #[generalized_force(on = r#type)]
    fn damping() -> f64 {
        -c * type_dot
    }

    #[force(on = bob)]
    fn drag() -> Vec2 {
        box_dot * (-c)
    }
}

fn main() {
    let sys = raw::Raw { m: 1.0, r#loop: 1.0, c: 0.1 };
    let s = raw::State::at_rest(raw::Coords { r#type: 0.3, r#match: 0.1 });
    let qdd = sys.accelerations(&s).unwrap();
    assert!(qdd.r#type.is_finite() && qdd.r#match.is_finite());
}
