// Written by scripts/peers/robots.py; do not edit. The robot `arm7`: 7 revolute joints,
// the same numbers as scripts/peers/robots/arm7.urdf (fixed base `base`).
#[lagrange::mechanism]
pub mod arm7 {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
        pub q4: f64,
        pub q5: f64,
        pub q6: f64,
        pub q7: f64,
    }
    pub struct Arm7 {
        pub g: f64,
    }

    // arm, joint 1 of 7
    #[rigid_body(mass = 3.995, com = vec3(-0.0087, 0.0143, 0.0606),
                 inertia = [[0.0238623, 0.0018166, 0.0010764],
                            [0.0018166, 0.0258265, 0.001738],
                            [0.0010764, 0.001738, 0.0240714]])]
    fn link1() -> Spatial {
        spatial(
            vec3(0.0335, -0.1106, 0.1902),
            rpy(0.8041, -0.124, -0.3381) * rot_z(q1),
        )
    }

    // arm, joint 2 of 7
    #[rigid_body(mass = 3.957, com = vec3(0.0574, 0.0152, 0.0238),
                 inertia = [[0.0273397, -0.0035306, -0.0051068],
                            [-0.0035306, 0.0337213, 0.0067301],
                            [-0.0051068, 0.0067301, 0.0250472]])]
    fn link2() -> Spatial {
        link1.joint(
            vec3(-0.2228, -0.0984, -0.1518),
            rpy(-0.9537, -0.6185, -0.0413) * rot_y(q2),
        )
    }

    // arm, joint 3 of 7
    #[rigid_body(mass = 2.699, com = vec3(-0.0729, 0.052, -0.0054),
                 inertia = [[0.0128819, 0.0003918, 0.0032776],
                            [0.0003918, 0.0146073, -0.0009942],
                            [0.0032776, -0.0009942, 0.0072465]])]
    fn link3() -> Spatial {
        link2.joint(
            vec3(0.1415, -0.2007, -0.1105),
            rpy(1.0533, -0.7222, -0.3107) * rot_z(q3),
        )
    }

    // arm, joint 4 of 7
    #[rigid_body(mass = 2.429, com = vec3(-0.0212, 0.0318, -0.0324),
                 inertia = [[0.0024234, -0.0001958, 0.0001382],
                            [-0.0001958, 0.0026472, -0.0001752],
                            [0.0001382, -0.0001752, 0.0023889]])]
    fn link4() -> Spatial {
        link3.joint(
            vec3(0.0901, -0.0467, 0.0067),
            rpy(0.8834, -0.0933, 0.8839) * rot_y(q4),
        )
    }

    // arm, joint 5 of 7
    #[rigid_body(mass = 1.694, com = vec3(-0.0393, -0.0754, 0.0637),
                 inertia = [[0.0041211, -0.0000566, -0.000031],
                            [-0.0000566, 0.0044258, -0.0004601],
                            [-0.000031, -0.0004601, 0.0031032]])]
    fn link5() -> Spatial {
        link4.joint(
            vec3(-0.0075, 0.1619, -0.159),
            rpy(-0.2352, 0.1078, -1.1339) * rot_z(q5),
        )
    }

    // arm, joint 6 of 7
    #[rigid_body(mass = 1.343, com = vec3(-0.064, 0.0781, -0.0249),
                 inertia = [[0.0014199, 0.000012, -0.0000318],
                            [0.000012, 0.001361, 0.000049],
                            [-0.0000318, 0.000049, 0.0013344]])]
    fn link6() -> Spatial {
        link5.joint(
            vec3(-0.0373, 0.0462, -0.2378),
            rpy(-0.3491, 1.0152, 0.1502) * rot_y(q6),
        )
    }

    // arm, joint 7 of 7
    #[rigid_body(mass = 0.617, com = vec3(0.0404, -0.013, -0.025),
                 inertia = [[0.0027432, -0.0001345, -0.0009652],
                            [-0.0001345, 0.005038, -0.0000114],
                            [-0.0009652, -0.0000114, 0.0044378]])]
    fn link7() -> Spatial {
        link6.joint(
            vec3(-0.0701, -0.251, -0.0818),
            rpy(0.095, -0.4715, 0.7381) * rot_z(q7),
        )
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
