// Written by scripts/peers/robots.py; do not edit. The robot `arm3`: 3 revolute joints,
// the same numbers as scripts/peers/robots/arm3.urdf (fixed base `base`).
#[lagrange::mechanism]
pub mod arm3 {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
    }
    pub struct Arm3 {
        pub g: f64,
    }

    // arm, joint 1 of 3
    #[rigid_body(mass = 2.613, com = vec3(0.0177, -0.0234, 0.0541),
                 inertia = [[0.0068786, -0.0003903, -0.0000346],
                            [-0.0003903, 0.0062602, 0.0005677],
                            [-0.0000346, 0.0005677, 0.0062919]])]
    fn link1() -> Spatial {
        spatial(
            vec3(0.0147, -0.116, 0.0854),
            rpy(-0.3482, 0.6972, 0.9723) * rot_z(q1),
        )
    }

    // arm, joint 2 of 3
    #[rigid_body(mass = 1.768, com = vec3(0.0309, 0.0246, 0.0088),
                 inertia = [[0.0016411, 0.0003609, -0.0003307],
                            [0.0003609, 0.0018011, 0.0000624],
                            [-0.0003307, 0.0000624, 0.0019013]])]
    fn link2() -> Spatial {
        link1.joint(
            vec3(0.0321, 0.0913, -0.0357),
            rpy(0.2277, -0.1552, -0.48) * rot_y(q2),
        )
    }

    // arm, joint 3 of 3
    #[rigid_body(mass = 0.998, com = vec3(-0.0059, 0.0344, 0.0151),
                 inertia = [[0.0051249, -0.0006052, 0.0006181],
                            [-0.0006052, 0.0028628, 0.0007385],
                            [0.0006181, 0.0007385, 0.0037237]])]
    fn link3() -> Spatial {
        link2.joint(
            vec3(0.0723, 0.2193, -0.0819),
            rpy(0.2916, -0.3069, -0.1915) * rot_z(q3),
        )
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
