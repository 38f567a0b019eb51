//! Andrews' squeezer mechanism: seven rigid bars in a horizontal plane, joined in three closed
//! loops, driven by a constant torque on the crank against a spring (Hairer & Wanner, *Solving
//! Ordinary Differential Equations II*, 2nd ed., §VII.7; the model of Manning (1981) and Schiehlen
//! (1990); the IVP test set of Mazzia & Magherini, problem "andrews"). Seven angles, six holonomic
//! constraints (the point E where the crank's coupler K2 meets K3, K4 and K6), one degree of freedom.
//!
//! Declared here from the bodies' positions, not from the published equations: the mass matrix the
//! macro derives is Hairer & Wanner's (K1 turns about O by β; K2 about the crank's end P by β + Θ;
//! K3 about B by γ; K5 about A by δ and K4 about K5's end F by Φ + δ; K7 about A by ε and K6 about
//! K7's end G by Ω + ε), and at rest the published initial accelerations follow from it
//! (`tests/andrews_squeezer.rs`). Every parameter is a field, so the same declaration serves any
//! system of units.

use lagrange::prelude::*;

#[mechanism]
pub mod squeezer {
    /// The seven angles, in Hairer & Wanner's order (β, Θ, γ, Φ, δ, Ω, ε).
    pub struct Coords {
        pub beta: f64,
        pub theta: f64,
        pub gamma: f64,
        pub phi: f64,
        pub delta: f64,
        pub omega: f64,
        pub epsilon: f64,
    }

    /// Hairer & Wanner's constants, in their names.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Squeezer {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub m4: f64,
        pub m5: f64,
        pub m6: f64,
        pub m7: f64,
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
        pub i4: f64,
        pub i5: f64,
        pub i6: f64,
        pub i7: f64,
        pub xa: f64,
        pub ya: f64,
        pub xb: f64,
        pub yb: f64,
        pub xc: f64,
        pub yc: f64,
        pub c0: f64,
        pub d: f64,
        pub da: f64,
        pub e: f64,
        pub ea: f64,
        pub rr: f64,
        pub ra: f64,
        pub l0: f64,
        pub ss: f64,
        pub sa: f64,
        pub sb: f64,
        pub sc: f64,
        pub sd: f64,
        pub ta: f64,
        pub tb: f64,
        pub u: f64,
        pub ua: f64,
        pub ub: f64,
        pub zf: f64,
        pub zt: f64,
        pub fa: f64,
        /// The motor's torque on the crank.
        pub mom: f64,
    }

    /// K1, the crank, about O.
    #[rigid_body(mass = m1, inertia = i1)]
    fn k1() -> Planar {
        planar(vec2(beta.cos(), beta.sin()) * ra, beta)
    }

    /// K2, on the crank's end P = rr (cos β, sin β); its far end is E.
    #[rigid_body(mass = m2, inertia = i2)]
    fn k2() -> Planar {
        let turned = beta + theta;
        planar(
            vec2(beta.cos(), beta.sin()) * rr - vec2(turned.cos(), turned.sin()) * da,
            turned,
        )
    }

    /// K3, about B.
    #[rigid_body(mass = m3, inertia = i3)]
    fn k3() -> Planar {
        let (s, c) = (gamma.sin(), gamma.cos());
        planar(vec2(xb + sa * s + sb * c, yb - sa * c + sb * s), gamma)
    }

    /// K5, about A.
    #[rigid_body(mass = m5, inertia = i5)]
    fn k5() -> Planar {
        let (s, c) = (delta.sin(), delta.cos());
        planar(vec2(xa + ta * c - tb * s, ya + ta * s + tb * c), delta)
    }

    /// K4, about K5's end F = A + zt (cos δ, sin δ).
    #[rigid_body(mass = m4, inertia = i4)]
    fn k4() -> Planar {
        let turned = phi + delta;
        let f = vec2(xa + zt * delta.cos(), ya + zt * delta.sin());
        planar(f + vec2(turned.sin(), -turned.cos()) * (e - ea), turned)
    }

    /// K7, about A.
    #[rigid_body(mass = m7, inertia = i7)]
    fn k7() -> Planar {
        let (s, c) = (epsilon.sin(), epsilon.cos());
        planar(vec2(xa + ua * c - ub * s, ya + ua * s + ub * c), epsilon)
    }

    /// K6, about K7's end G = A + u (sin ε, −cos ε).
    #[rigid_body(mass = m6, inertia = i6)]
    fn k6() -> Planar {
        let turned = omega + epsilon;
        let g = vec2(xa + u * epsilon.sin(), ya - u * epsilon.cos());
        planar(g + vec2(turned.cos(), turned.sin()) * (zf - fa), turned)
    }

    /// D, where the spring holds K3.
    #[point]
    fn spring_end() -> Vec2 {
        let (s, c) = (gamma.sin(), gamma.cos());
        vec2(xb + sd * c + sc * s, yb + sd * s - sc * c)
    }

    /// The spring from D to the fixed point C, of stiffness c0 and rest length l0.
    #[potential]
    fn spring() -> f64 {
        let stretch = (spring_end - vec2(xc, yc)).norm() - l0;
        0.5 * c0 * stretch * stretch
    }

    /// The motor's constant torque on the crank.
    #[generalized_force(on = beta)]
    fn motor() -> f64 {
        mom
    }

    /// E, K2's far end, on K3 at distance ss from B (x).
    #[constraint]
    fn e_on_k3_x() -> f64 {
        rr * beta.cos() - d * (beta + theta).cos() - ss * gamma.sin() - xb
    }

    /// E on K3 (y).
    #[constraint]
    fn e_on_k3_y() -> f64 {
        rr * beta.sin() - d * (beta + theta).sin() + ss * gamma.cos() - yb
    }

    /// E on K4, at distance e from F (x).
    #[constraint]
    fn e_on_k4_x() -> f64 {
        rr * beta.cos() - d * (beta + theta).cos() - e * (phi + delta).sin() - zt * delta.cos() - xa
    }

    /// E on K4 (y).
    #[constraint]
    fn e_on_k4_y() -> f64 {
        rr * beta.sin() - d * (beta + theta).sin() + e * (phi + delta).cos() - zt * delta.sin() - ya
    }

    /// E on K6, at distance zf from G (x).
    #[constraint]
    fn e_on_k6_x() -> f64 {
        rr * beta.cos()
            - d * (beta + theta).cos()
            - zf * (omega + epsilon).cos()
            - u * epsilon.sin()
            - xa
    }

    /// E on K6 (y).
    #[constraint]
    fn e_on_k6_y() -> f64 {
        rr * beta.sin() - d * (beta + theta).sin() - zf * (omega + epsilon).sin()
            + u * epsilon.cos()
            - ya
    }
}

/// Hairer & Wanner's constants (SI units: kg, kg m², m, N/m, N m).
pub const ANDREWS: squeezer::Squeezer = squeezer::Squeezer {
    m1: 0.04325,
    m2: 0.00365,
    m3: 0.02373,
    m4: 0.00706,
    m5: 0.07050,
    m6: 0.00706,
    m7: 0.05498,
    i1: 2.194e-6,
    i2: 4.410e-7,
    i3: 5.255e-6,
    i4: 5.667e-7,
    i5: 1.169e-5,
    i6: 5.667e-7,
    i7: 1.912e-5,
    xa: -0.06934,
    ya: -0.00227,
    xb: -0.03635,
    yb: 0.03273,
    xc: 0.014,
    yc: 0.072,
    c0: 4530.0,
    d: 28e-3,
    da: 115e-4,
    e: 2e-2,
    ea: 1421e-5,
    rr: 7e-3,
    ra: 92e-5,
    l0: 7785e-5,
    ss: 35e-3,
    sa: 1874e-5,
    sb: 1043e-5,
    sc: 18e-3,
    sd: 2e-2,
    ta: 2308e-5,
    tb: 916e-5,
    u: 4e-2,
    ua: 1228e-5,
    ub: 449e-5,
    zf: 2e-2,
    zt: 4e-2,
    fa: 1421e-5,
    mom: 33e-3,
};

/// The consistent initial angles of Hairer & Wanner (at rest), with the digits they print.
#[allow(clippy::excessive_precision)]
pub const START: [f64; 7] = [
    -0.061_713_890_014_276_449_635_894_845_800_1,
    0.0,
    0.455_279_819_163_070_380_255_912_382_449,
    0.222_668_390_165_885_884_674_473_185_609,
    0.487_364_979_543_842_550_225_598_953_530,
    -0.222_668_390_165_885_884_674_473_185_609,
    1.230_547_444_549_821_192_497_356_155_68,
];

/// The squeezer at rest at [`START`], t = 0.
pub fn start() -> squeezer::State {
    let q = <squeezer::Coords as Coordinates<7>>::from_array(START);
    squeezer::State::at_rest(q)
}

/// [`ANDREWS`] with every constant passed through `convert(value, [length, mass, time] exponents of
/// its dimension)`: the same squeezer in another system of units.
pub fn andrews_in(convert: impl Fn(f64, [i32; 3]) -> f64) -> squeezer::Squeezer {
    const MASS: [i32; 3] = [0, 1, 0];
    const INERTIA: [i32; 3] = [2, 1, 0];
    const LENGTH: [i32; 3] = [1, 0, 0];
    const STIFFNESS: [i32; 3] = [0, 1, -2];
    const TORQUE: [i32; 3] = [2, 1, -2];
    let a = ANDREWS;
    squeezer::Squeezer {
        m1: convert(a.m1, MASS),
        m2: convert(a.m2, MASS),
        m3: convert(a.m3, MASS),
        m4: convert(a.m4, MASS),
        m5: convert(a.m5, MASS),
        m6: convert(a.m6, MASS),
        m7: convert(a.m7, MASS),
        i1: convert(a.i1, INERTIA),
        i2: convert(a.i2, INERTIA),
        i3: convert(a.i3, INERTIA),
        i4: convert(a.i4, INERTIA),
        i5: convert(a.i5, INERTIA),
        i6: convert(a.i6, INERTIA),
        i7: convert(a.i7, INERTIA),
        xa: convert(a.xa, LENGTH),
        ya: convert(a.ya, LENGTH),
        xb: convert(a.xb, LENGTH),
        yb: convert(a.yb, LENGTH),
        xc: convert(a.xc, LENGTH),
        yc: convert(a.yc, LENGTH),
        c0: convert(a.c0, STIFFNESS),
        d: convert(a.d, LENGTH),
        da: convert(a.da, LENGTH),
        e: convert(a.e, LENGTH),
        ea: convert(a.ea, LENGTH),
        rr: convert(a.rr, LENGTH),
        ra: convert(a.ra, LENGTH),
        l0: convert(a.l0, LENGTH),
        ss: convert(a.ss, LENGTH),
        sa: convert(a.sa, LENGTH),
        sb: convert(a.sb, LENGTH),
        sc: convert(a.sc, LENGTH),
        sd: convert(a.sd, LENGTH),
        ta: convert(a.ta, LENGTH),
        tb: convert(a.tb, LENGTH),
        u: convert(a.u, LENGTH),
        ua: convert(a.ua, LENGTH),
        ub: convert(a.ub, LENGTH),
        zf: convert(a.zf, LENGTH),
        zt: convert(a.zt, LENGTH),
        fa: convert(a.fa, LENGTH),
        mom: convert(a.mom, TORQUE),
    }
}
