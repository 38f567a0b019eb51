//! Ordinary `f64` code in declaration functions: `f64` methods dual numbers lack, integer
//! literals, closures and lets typed `f64`, casts, and exponents that are parameters.
use lagrange::prelude::*;

#[mechanism]
pub mod methods {
    pub struct Coords {
        pub theta: f64,
        pub x: f64,
    }

    pub struct Methods {
        pub m: f64,
        pub l: f64,
        pub k: f64,
        pub n: f64,
        pub c: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        let half = |s: f64| s / 2;
        let scale: f64 = 1.0;
        vec2(theta.sin(), -theta.cos().max(-0.5).min(0.9)) * l * scale + vec2(half(x) * 2, 0.0)
    }

    #[particle(mass = m * 2.0)]
    fn cart() -> Vec2 {
        vec2(x.clamp(-10.0, 10.0), x.hypot(1.0) - 1 + theta.atan2(1.0) * 0.0)
    }

    #[potential]
    fn spring() -> f64 {
        k * x.abs().powf(n) / 2 + x.signum() * 0.0 + theta.powi(2) * 0 + x.powf(2.0) * 0.5
    }

    #[generalized_force(on = theta)]
    fn damping() -> f64 {
        -c * theta_dot * (1 as f64)
    }
}

#[mechanism]
pub mod families {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Families {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let k = i * 1;
        let link = vec2(theta[k].sin(), -theta[k].cos()) * l * (i as f64 + 1.0) * 0.5;
        if i == 0 { link } else { bob[i - 1] + link }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

fn main() {
    let sys = methods::Methods { m: 1.0, l: 1.0, k: 2.0, n: 2.0, c: 0.1 };
    let s = methods::State::at_rest(methods::Coords { theta: 0.3, x: 0.2 });
    let qdd = sys.accelerations(&s).unwrap();
    assert!(qdd.theta.is_finite() && qdd.x.is_finite());
    let sys = families::Families { m: 1.0, l: 1.0, g: 9.81 };
    let s = families::State::at_rest(families::Coords { theta: [0.1, 0.2, 0.3] });
    assert!(sys.accelerations(&s).is_ok());
}
