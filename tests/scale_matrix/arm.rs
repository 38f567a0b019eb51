//! The gallery's spatial arm (`scenes::spatial_arm`) with its principal moments of inertia as
//! parameters (the gallery writes them as numbers in kg m²), so that they can be given in any
//! units: three rigid links taking the tree pass (the articulated-body recursion).

use lagrange::prelude::*;

#[mechanism]
pub mod arm {
    pub struct Coords {
        pub base: f64,
        pub shoulder: f64,
        pub elbow: f64,
    }

    pub struct Arm {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub d1: f64,
        pub d2: f64,
        pub d3: f64,
        pub e: f64,
        pub g: f64,
        /// The links' principal moments about their centres of mass.
        pub i1x: f64,
        pub i1y: f64,
        pub i1z: f64,
        pub i2x: f64,
        pub i2y: f64,
        pub i2z: f64,
        pub i3x: f64,
        pub i3y: f64,
        pub i3z: f64,
    }

    #[rigid_body(mass = m1, inertia = [i1x, i1y, i1z])]
    fn column() -> Spatial {
        let r = rot_z(base);
        spatial(r * vec3(0.0, 0.0, 0.5 * d1), r)
    }

    #[rigid_body(mass = m2, inertia = [i2x, i2y, i2z])]
    fn upper() -> Spatial {
        let r = column.rotation * rot_y(shoulder);
        let joint = column.point(vec3(0.0, 0.0, 0.5 * d1));
        spatial(joint + r * vec3(0.0, 0.0, 0.5 * d2), r)
    }

    #[rigid_body(mass = m3, inertia = [i3x, i3y, i3z])]
    fn fore() -> Spatial {
        let r = upper.rotation * rot_y(elbow);
        let joint = upper.point(vec3(e, 0.0, 0.5 * d2));
        spatial(joint + r * vec3(0.0, 0.0, 0.5 * d3), r)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
