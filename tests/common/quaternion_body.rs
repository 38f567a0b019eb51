//! A free body's orientation as a unit quaternion e = (w, x, y, z): four coordinates, the rotation
//! homogeneous of degree two in e (the transpose of Shuster's attitude matrix, which maps the other
//! way: "A survey of attitude representations", *J. Astronautical Sciences* 41(4), 1993, eq. 161,
//! times |e|²) and the norm a holonomic constraint. Declared once for `tests/quaternion_body.rs` and
//! the instruction counts of `scripts/callgrind` (`charts`).

use lagrange::prelude::*;

#[mechanism]
pub mod quaternion_body {
    pub struct Coords {
        /// (w, x, y, z): the body is turned by 2 acos w about (x, y, z).
        pub e: [f64; 4],
    }
    pub struct QuaternionBody {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }
    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        let (w, x, y, z) = (e[0], e[1], e[2], e[3]);
        spatial(
            vec3(0.0, 0.0, 0.0),
            rot3([
                [
                    w * w + x * x - y * y - z * z,
                    2.0 * (x * y - w * z),
                    2.0 * (x * z + w * y),
                ],
                [
                    2.0 * (x * y + w * z),
                    w * w - x * x + y * y - z * z,
                    2.0 * (y * z - w * x),
                ],
                [
                    2.0 * (x * z - w * y),
                    2.0 * (y * z + w * x),
                    w * w - x * x - y * y + z * z,
                ],
            ]),
        )
    }
    #[constraint]
    fn unit() -> f64 {
        e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3] - 1.0
    }
}
