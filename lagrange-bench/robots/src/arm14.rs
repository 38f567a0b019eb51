// Written by scripts/peers/robots.py; do not edit. The robot `arm14`: 14 revolute joints,
// the same numbers as scripts/peers/robots/arm14.urdf (fixed base `base`).
#[lagrange::mechanism]
pub mod arm14 {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
        pub q4: f64,
        pub q5: f64,
        pub q6: f64,
        pub q7: f64,
        pub q8: f64,
        pub q9: f64,
        pub q10: f64,
        pub q11: f64,
        pub q12: f64,
        pub q13: f64,
        pub q14: f64,
    }
    pub struct Arm14 {
        pub g: f64,
    }

    // two arms in series, joint 1 of 14
    #[rigid_body(mass = 3.208, com = vec3(0.0038, 0.0159, 0.0352),
                 inertia = [[0.0032303, -0.0001102, -0.0003144],
                            [-0.0001102, 0.0027101, -0.0001015],
                            [-0.0003144, -0.0001015, 0.0043334]])]
    fn link1() -> Spatial {
        spatial(
            vec3(-0.0242, 0.0994, -0.0197),
            rpy(-0.8318, 0.1247, -0.1727) * rot_z(q1),
        )
    }

    // two arms in series, joint 2 of 14
    #[rigid_body(mass = 4.37, com = vec3(-0.0751, 0.0691, 0.0698),
                 inertia = [[0.0172999, -0.0001465, 0.0007242],
                            [-0.0001465, 0.0175041, 0.0003802],
                            [0.0007242, 0.0003802, 0.0161906]])]
    fn link2() -> Spatial {
        link1.joint(
            vec3(-0.0994, -0.1986, -0.0171),
            rpy(-0.0623, -0.0962, -0.1801) * rot_y(q2),
        )
    }

    // two arms in series, joint 3 of 14
    #[rigid_body(mass = 2.895, com = vec3(-0.0249, 0.0431, -0.0114),
                 inertia = [[0.005724, -0.0006632, 0.0004889],
                            [-0.0006632, 0.0048845, -0.0001184],
                            [0.0004889, -0.0001184, 0.0044034]])]
    fn link3() -> Spatial {
        link2.joint(
            vec3(0.0755, -0.0986, 0.0277),
            rpy(0.4348, -0.0458, 0.7154) * rot_z(q3),
        )
    }

    // two arms in series, joint 4 of 14
    #[rigid_body(mass = 2.835, com = vec3(0.0555, 0.008, 0.0636),
                 inertia = [[0.0132204, -0.0007945, 0.0004379],
                            [-0.0007945, 0.0146072, -0.0000616],
                            [0.0004379, -0.0000616, 0.0107472]])]
    fn link4() -> Spatial {
        link3.joint(
            vec3(0.204, 0.2531, 0.079),
            rpy(0.2159, 1.0922, 1.0594) * rot_y(q4),
        )
    }

    // two arms in series, joint 5 of 14
    #[rigid_body(mass = 3.096, com = vec3(-0.0283, 0.0442, 0.0358),
                 inertia = [[0.0065423, 0.0004104, -0.0008767],
                            [0.0004104, 0.0074916, -0.0001827],
                            [-0.0008767, -0.0001827, 0.0071433]])]
    fn link5() -> Spatial {
        link4.joint(
            vec3(0.1455, 0.009, 0.013),
            rpy(1.0381, -0.4525, -0.7603) * rot_z(q5),
        )
    }

    // two arms in series, joint 6 of 14
    #[rigid_body(mass = 2.55, com = vec3(-0.0219, 0.0433, 0.0652),
                 inertia = [[0.011801, -0.0004553, 0.0008248],
                            [-0.0004553, 0.0057254, 0.0012194],
                            [0.0008248, 0.0012194, 0.0100486]])]
    fn link6() -> Spatial {
        link5.joint(
            vec3(0.1307, -0.1009, 0.1499),
            rpy(0.8858, -0.2534, 0.6676) * rot_y(q6),
        )
    }

    // two arms in series, joint 7 of 14
    #[rigid_body(mass = 2.134, com = vec3(-0.0305, 0.0169, 0.0672),
                 inertia = [[0.0115403, -0.0015282, -0.0000946],
                            [-0.0015282, 0.0101005, 0.0003954],
                            [-0.0000946, 0.0003954, 0.0083976]])]
    fn link7() -> Spatial {
        link6.joint(
            vec3(-0.0041, 0.1985, 0.088),
            rpy(0.9745, -0.9224, 1.0368) * rot_z(q7),
        )
    }

    // two arms in series, joint 8 of 14
    #[rigid_body(mass = 1.72, com = vec3(-0.0005, 0.0352, 0.0133),
                 inertia = [[0.0020938, -0.0000683, -0.000012],
                            [-0.0000683, 0.0023197, -0.0003441],
                            [-0.000012, -0.0003441, 0.0024375]])]
    fn link8() -> Spatial {
        link7.joint(
            vec3(-0.0361, 0.0838, 0.0705),
            rpy(-0.0795, -1.0273, 0.6713) * rot_y(q8),
        )
    }

    // two arms in series, joint 9 of 14
    #[rigid_body(mass = 1.597, com = vec3(-0.0622, -0.0641, 0.0399),
                 inertia = [[0.0025621, -0.000341, -0.0003863],
                            [-0.000341, 0.0017989, 0.0002263],
                            [-0.0003863, 0.0002263, 0.0029959]])]
    fn link9() -> Spatial {
        link8.joint(
            vec3(-0.0903, 0.0706, -0.1232),
            rpy(1.0973, 0.4004, 1.1094) * rot_z(q9),
        )
    }

    // two arms in series, joint 10 of 14
    #[rigid_body(mass = 1.6, com = vec3(0.085, 0.0744, -0.0378),
                 inertia = [[0.005489, 0.000615, 0.0007155],
                            [0.000615, 0.0043533, -0.0017047],
                            [0.0007155, -0.0017047, 0.0033368]])]
    fn link10() -> Spatial {
        link9.joint(
            vec3(-0.1441, 0.2039, -0.0298),
            rpy(-0.8354, -1.1261, 1.1935) * rot_y(q10),
        )
    }

    // two arms in series, joint 11 of 14
    #[rigid_body(mass = 1.348, com = vec3(-0.0202, 0.0706, 0.0705),
                 inertia = [[0.0045914, 0.0002806, 0.0007789],
                            [0.0002806, 0.0050599, 0.0003098],
                            [0.0007789, 0.0003098, 0.0043743]])]
    fn link11() -> Spatial {
        link10.joint(
            vec3(-0.1524, -0.0266, -0.1249),
            rpy(-0.8065, 0.0542, 0.3901) * rot_z(q11),
        )
    }

    // two arms in series, joint 12 of 14
    #[rigid_body(mass = 0.953, com = vec3(0.0915, -0.0912, -0.1095),
                 inertia = [[0.0048408, 0.0007287, 0.0006926],
                            [0.0007287, 0.0048426, -0.0005356],
                            [0.0006926, -0.0005356, 0.0049464]])]
    fn link12() -> Spatial {
        link11.joint(
            vec3(0.1127, 0.2918, -0.0591),
            rpy(0.3128, -0.8292, 0.2528) * rot_y(q12),
        )
    }

    // two arms in series, joint 13 of 14
    #[rigid_body(mass = 0.686, com = vec3(-0.0222, 0.0196, -0.0454),
                 inertia = [[0.001127, 0.0000132, 0.0001084],
                            [0.0000132, 0.001014, 0.0000845],
                            [0.0001084, 0.0000845, 0.0005107]])]
    fn link13() -> Spatial {
        link12.joint(
            vec3(-0.0653, 0.0611, -0.1082),
            rpy(0.5416, -0.1343, 0.1026) * rot_z(q13),
        )
    }

    // two arms in series, joint 14 of 14
    #[rigid_body(mass = 0.37, com = vec3(-0.0196, -0.0669, -0.0633),
                 inertia = [[0.0006627, 0.0000024, 0.0000788],
                            [0.0000024, 0.0009084, 0.0000339],
                            [0.0000788, 0.0000339, 0.0005139]])]
    fn link14() -> Spatial {
        link13.joint(
            vec3(0.1159, -0.0838, 0.1168),
            rpy(-0.093, 0.9534, -1.1339) * rot_y(q14),
        )
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
