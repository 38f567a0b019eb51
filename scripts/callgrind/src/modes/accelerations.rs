//! `accelerations` of the generated mechanisms without constraints, `n` calls along the path the
//! mode's prefix picks (see `calls`): each mode its mechanism's parameters and a state.

use crate::calls::{calls, Via};
use crate::mechanisms::{
    cart_pendulum, double_pendulum_start, drag, driven, fpu, fpu_chain, kepler, wedge_block,
    CART_PENDULUM, DOUBLE_PENDULUM, KEPLER, PENDULUM, WEDGE_BLOCK,
};
use lagrange::prelude::*;

pub fn pendulum(n: usize, via: Via) -> f64 {
    use crate::mechanisms::pendulum::*;
    let sys = PENDULUM;
    let s = State::new(0.0, Coords { theta: 0.7 }, Coords { theta: 1.1 });
    calls(sys, &s, n, via)
}

pub fn double_pendulum(n: usize, via: Via) -> f64 {
    let sys = DOUBLE_PENDULUM;
    let s = double_pendulum_start();
    calls(sys, &s, n, via)
}

pub fn wedge_block(n: usize, via: Via) -> f64 {
    use wedge_block::*;
    let sys = WEDGE_BLOCK;
    let s = State::new(0.0, Coords { x: 0.1, d: 0.2 }, Coords { x: -0.3, d: 0.5 });
    calls(sys, &s, n, via)
}

pub fn cart_pendulum(n: usize, via: Via) -> f64 {
    use cart_pendulum::*;
    let sys = CART_PENDULUM;
    let s = State::new(
        0.0,
        Coords { x: 0.1, theta: 0.7 },
        Coords {
            x: -0.3,
            theta: 1.1,
        },
    );
    calls(sys, &s, n, via)
}

/// The FPU chain with its potential as one sum (`mechanisms::fpu`).
pub fn fpu(n: usize, via: Via) -> f64 {
    let sys = fpu::Fpu {
        m: 1.0,
        omega: 50.0,
    };
    let s = State::new(
        0.0,
        fpu::Coords {
            q: [0.1, 0.2, -0.3, 0.05, 0.4, -0.1],
        },
        fpu::Coords {
            q: [0.3, -0.2, 0.1, 0.0, 0.5, 0.2],
        },
    );
    calls(sys, &s, n, via)
}

/// The FPU chain of the work-precision report, spring by spring (`fpu_report::fpu_chain`).
pub fn fpu_springs(n: usize, via: Via) -> f64 {
    let sys = fpu_chain::Fpu {
        m: 1.0,
        omega: 50.0,
    };
    let s = State::new(
        0.0,
        fpu_chain::Coords {
            q: [0.1, 0.2, -0.3, 0.05, 0.4, -0.1],
        },
        fpu_chain::Coords {
            q: [0.3, -0.2, 0.1, 0.0, 0.5, 0.2],
        },
    );
    calls(sys, &s, n, via)
}

pub fn kepler(n: usize, via: Via) -> f64 {
    let s = State::new(
        0.0,
        kepler::Coords { x: 0.4, y: 0.3 },
        kepler::Coords { x: -0.2, y: 1.7 },
    );
    calls(KEPLER, &s, n, via)
}

/// The pendulum with a velocity-dependent force (linear drag), against `pendulum`.
pub fn drag(n: usize, via: Via) -> f64 {
    use drag::*;
    let sys = Drag {
        m: 1.0,
        l: 0.8,
        g: 9.81,
        c: 0.3,
    };
    let s = State::new(0.2, Coords { theta: 0.7 }, Coords { theta: 1.1 });
    calls(sys, &s, n, via)
}

/// The pendulum on a moving support (time in the position), against `pendulum`.
pub fn driven(n: usize, via: Via) -> f64 {
    use driven::*;
    let sys = Driven {
        m: 1.0,
        l: 0.8,
        g: 9.81,
        a: 0.1,
        w: 2.0,
    };
    let s = State::new(0.2, Coords { theta: 0.7 }, Coords { theta: 1.1 });
    calls(sys, &s, n, via)
}
