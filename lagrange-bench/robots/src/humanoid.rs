// Written by scripts/peers/robots.py; do not edit. The robot `humanoid`: 30 revolute joints,
// the same numbers as scripts/peers/robots/humanoid.urdf (fixed base `pelvis`).
#[lagrange::mechanism]
pub mod humanoid {
    pub struct Coords {
        pub q_lleg1: f64,
        pub q_lleg2: f64,
        pub q_lleg3: f64,
        pub q_lleg4: f64,
        pub q_lleg5: f64,
        pub q_lleg6: f64,
        pub q_rleg1: f64,
        pub q_rleg2: f64,
        pub q_rleg3: f64,
        pub q_rleg4: f64,
        pub q_rleg5: f64,
        pub q_rleg6: f64,
        pub q_waist1: f64,
        pub q_waist2: f64,
        pub q_larm1: f64,
        pub q_larm2: f64,
        pub q_larm3: f64,
        pub q_larm4: f64,
        pub q_larm5: f64,
        pub q_larm6: f64,
        pub q_larm7: f64,
        pub q_rarm1: f64,
        pub q_rarm2: f64,
        pub q_rarm3: f64,
        pub q_rarm4: f64,
        pub q_rarm5: f64,
        pub q_rarm6: f64,
        pub q_rarm7: f64,
        pub q_head1: f64,
        pub q_head2: f64,
    }
    pub struct Humanoid {
        pub g: f64,
    }

    // left leg, joint 1 of 6
    #[rigid_body(mass = 1.262, com = vec3(-0.0287, -0.0125, -0.0244),
                 inertia = [[0.0009112, 0.0000585, -0.0000908],
                            [0.0000585, 0.0009456, -0.0001418],
                            [-0.0000908, -0.0001418, 0.0010466]])]
    fn lleg1() -> Spatial {
        spatial(vec3(0.0178, 0.0817, -0.0832), rpy(0.6992, 0.0258, 1.1954) * rot_z(q_lleg1))
    }

    // left leg, joint 2 of 6
    #[rigid_body(mass = 1.553, com = vec3(-0.0309, 0.0159, 0.0157),
                 inertia = [[0.0014362, -0.0001424, -0.0001232],
                            [-0.0001424, 0.0012861, 0.0000832],
                            [-0.0001232, 0.0000832, 0.0013066]])]
    fn lleg2() -> Spatial {
        lleg1.joint(vec3(0.0044, 0.0413, 0.0684), rpy(0.0484, 0.6277, 0.2474) * rot_x(q_lleg2))
    }

    // left leg, joint 3 of 6
    #[rigid_body(mass = 4.362, com = vec3(-0.1355, -0.0647, -0.0921),
                 inertia = [[0.0799186, -0.0201218, -0.0009259],
                            [-0.0201218, 0.0735948, 0.0005298],
                            [-0.0009259, 0.0005298, 0.0567356]])]
    fn lleg3() -> Spatial {
        lleg2.joint(vec3(0.2014, 0.3212, -0.1276), rpy(-0.5694, 1.1419, -0.0088) * rot_y(q_lleg3))
    }

    // left leg, joint 4 of 6
    #[rigid_body(mass = 3.535, com = vec3(0.0005, 0.0814, 0.073),
                 inertia = [[0.0678507, -0.0019857, -0.0019456],
                            [-0.0019857, 0.0606273, 0.0034216],
                            [-0.0019456, 0.0034216, 0.0586695]])]
    fn lleg4() -> Spatial {
        lleg3.joint(vec3(0.343, 0.1966, 0.0607), rpy(0.7297, -0.5386, -0.7142) * rot_y(q_lleg4))
    }

    // left leg, joint 5 of 6
    #[rigid_body(mass = 0.839, com = vec3(-0.0103, 0.0123, -0.0295),
                 inertia = [[0.0005128, -0.0000619, 0.0000649],
                            [-0.0000619, 0.0004674, -0.000045],
                            [0.0000649, -0.000045, 0.0004489]])]
    fn lleg5() -> Spatial {
        lleg4.joint(vec3(0.007, 0.0797, 0.0023), rpy(1.0793, 0.932, -0.5662) * rot_y(q_lleg5))
    }

    // left leg, joint 6 of 6
    #[rigid_body(mass = 0.875, com = vec3(0.0335, -0.0074, 0.0278),
                 inertia = [[0.0011424, 0.0000645, 0.0000443],
                            [0.0000645, 0.00112, -0.0000463],
                            [0.0000443, -0.0000463, 0.0011614]])]
    fn lleg6() -> Spatial {
        lleg5.joint(vec3(-0.0362, -0.0888, -0.0283), rpy(-1.0881, 0.6541, -1.0938) * rot_x(q_lleg6))
    }

    // right leg, joint 1 of 6
    #[rigid_body(mass = 1.567, com = vec3(0.0273, 0.0032, 0.0091),
                 inertia = [[0.0005426, 0.0000539, -0.000053],
                            [0.0000539, 0.0003271, -0.000058],
                            [-0.000053, -0.000058, 0.000464]])]
    fn rleg1() -> Spatial {
        spatial(vec3(0.0025, -0.096, -0.0853), rpy(-0.6224, 0.2575, 0.3649) * rot_z(q_rleg1))
    }

    // right leg, joint 2 of 6
    #[rigid_body(mass = 1.307, com = vec3(-0.0145, -0.021, 0.0287),
                 inertia = [[0.0009903, 0.0000031, -0.0000141],
                            [0.0000031, 0.0009933, 0.0000152],
                            [-0.0000141, 0.0000152, 0.0011368]])]
    fn rleg2() -> Spatial {
        rleg1.joint(vec3(-0.0077, -0.0779, -0.0164), rpy(0.4321, -0.8404, -0.647) * rot_x(q_rleg2))
    }

    // right leg, joint 3 of 6
    #[rigid_body(mass = 4.535, com = vec3(0.089, 0.063, -0.0427),
                 inertia = [[0.0375971, -0.0085476, -0.0045653],
                            [-0.0085476, 0.0447688, -0.004495],
                            [-0.0045653, -0.004495, 0.0480866]])]
    fn rleg3() -> Spatial {
        rleg2.joint(vec3(0.0055, -0.3907, -0.0858), rpy(0.8894, -0.0098, -0.814) * rot_y(q_rleg3))
    }

    // right leg, joint 4 of 6
    #[rigid_body(mass = 2.802, com = vec3(-0.1059, -0.1187, 0.0889),
                 inertia = [[0.037152, -0.002168, -0.0046672],
                            [-0.002168, 0.0403341, -0.0045071],
                            [-0.0046672, -0.0045071, 0.0130959]])]
    fn rleg4() -> Spatial {
        rleg3.joint(vec3(0.1206, -0.0713, 0.3747), rpy(0.127, 0.0392, -0.0125) * rot_y(q_rleg4))
    }

    // right leg, joint 5 of 6
    #[rigid_body(mass = 0.879, com = vec3(0.0152, 0.0073, 0.0063),
                 inertia = [[0.0003522, -0.0000201, -0.0000739],
                            [-0.0000201, 0.0003792, 0.0000269],
                            [-0.0000739, 0.0000269, 0.0002685]])]
    fn rleg5() -> Spatial {
        rleg4.joint(vec3(0.0315, -0.0212, 0.0704), rpy(0.9512, 0.7114, -0.1178) * rot_y(q_rleg5))
    }

    // right leg, joint 6 of 6
    #[rigid_body(mass = 0.944, com = vec3(0.0178, 0.0155, -0.0293),
                 inertia = [[0.0006993, 0.0000554, -0.0001975],
                            [0.0000554, 0.000782, 0.0000863],
                            [-0.0001975, 0.0000863, 0.0003531]])]
    fn rleg6() -> Spatial {
        rleg5.joint(vec3(-0.0713, -0.0683, -0.0162), rpy(-1.0988, -0.4628, 0.3045) * rot_x(q_rleg6))
    }

    // waist, joint 1 of 2
    #[rigid_body(mass = 1.648, com = vec3(0.0179, -0.0347, -0.0136),
                 inertia = [[0.001593, -0.0000581, 0.000183],
                            [-0.0000581, 0.0019539, -0.0000015],
                            [0.000183, -0.0000015, 0.002179]])]
    fn waist1() -> Spatial {
        spatial(vec3(0.0004, -0.0049, 0.151), rpy(0.8297, -0.832, 0.7184) * rot_z(q_waist1))
    }

    // waist, joint 2 of 2
    #[rigid_body(mass = 13.641, com = vec3(-0.0167, -0.1045, -0.0806),
                 inertia = [[0.0578364, -0.0133691, 0.0019965],
                            [-0.0133691, 0.0675568, -0.0137859],
                            [0.0019965, -0.0137859, 0.0786111]])]
    fn waist2() -> Spatial {
        waist1.joint(vec3(0.2006, 0.2119, 0.0696), rpy(0.2784, -0.6216, -0.2334) * rot_y(q_waist2))
    }

    // left arm, joint 1 of 7
    #[rigid_body(mass = 1.578, com = vec3(-0.013, 0.0131, 0.0082),
                 inertia = [[0.0008332, 0.0000992, 0.0001327],
                            [0.0000992, 0.0013179, 0.0000329],
                            [0.0001327, 0.0000329, 0.0008432]])]
    fn larm1() -> Spatial {
        waist2.joint(vec3(0.0099, 0.2138, 0.3388), rpy(-0.7342, -0.1101, -0.4312) * rot_y(q_larm1))
    }

    // left arm, joint 2 of 7
    #[rigid_body(mass = 1.6, com = vec3(0.0315, 0.0086, -0.0234),
                 inertia = [[0.0009256, -0.0000373, -0.0001488],
                            [-0.0000373, 0.0006797, -0.0001759],
                            [-0.0001488, -0.0001759, 0.0009635]])]
    fn larm2() -> Spatial {
        larm1.joint(vec3(0.0607, -0.0505, 0.0128), rpy(-0.8588, 1.0386, -0.3658) * rot_x(q_larm2))
    }

    // left arm, joint 3 of 7
    #[rigid_body(mass = 1.668, com = vec3(-0.089, -0.0951, -0.0075),
                 inertia = [[0.0099589, 0.0005449, -0.0008918],
                            [0.0005449, 0.0080905, 0.0015417],
                            [-0.0008918, 0.0015417, 0.0061729]])]
    fn larm3() -> Spatial {
        larm2.joint(vec3(0.2681, -0.077, -0.0239), rpy(-0.0985, -0.3195, 0.4919) * rot_z(q_larm3))
    }

    // left arm, joint 4 of 7
    #[rigid_body(mass = 1.385, com = vec3(0.0092, -0.0127, -0.015),
                 inertia = [[0.0006005, 0.0000713, -0.0001203],
                            [0.0000713, 0.0006974, 0.0000059],
                            [-0.0001203, 0.0000059, 0.0006153]])]
    fn larm4() -> Spatial {
        larm3.joint(vec3(-0.0021, -0.0795, -0.0087), rpy(-0.8226, -0.5486, 0.4629) * rot_y(q_larm4))
    }

    // left arm, joint 5 of 7
    #[rigid_body(mass = 0.91, com = vec3(0.0253, -0.1009, -0.0259),
                 inertia = [[0.0057432, -0.000084, -0.0005388],
                            [-0.000084, 0.0054047, -0.0004972],
                            [-0.0005388, -0.0004972, 0.0039277]])]
    fn larm5() -> Spatial {
        larm4.joint(vec3(0.1281, 0.1582, -0.1617), rpy(0.4387, -1.1749, 0.7918) * rot_z(q_larm5))
    }

    // left arm, joint 6 of 7
    #[rigid_body(mass = 0.573, com = vec3(0.0017, 0.0177, -0.0014),
                 inertia = [[0.0000719, 0.0000091, 0.0000008],
                            [0.0000091, 0.000071, 0.0000022],
                            [0.0000008, 0.0000022, 0.0000679]])]
    fn larm6() -> Spatial {
        larm5.joint(vec3(-0.0327, 0.0006, 0.0503), rpy(-1.1848, 1.132, -0.9573) * rot_y(q_larm6))
    }

    // left arm, joint 7 of 7
    #[rigid_body(mass = 0.417, com = vec3(0.0238, 0.0313, 0.009),
                 inertia = [[0.0003086, 0.0000103, -0.0000322],
                            [0.0000103, 0.0002228, -0.0000217],
                            [-0.0000322, -0.0000217, 0.0002295]])]
    fn larm7() -> Spatial {
        larm6.joint(vec3(0.0722, -0.0345, -0.0017), rpy(-0.3419, -0.8925, 0.483) * rot_x(q_larm7))
    }

    // right arm, joint 1 of 7
    #[rigid_body(mass = 1.476, com = vec3(-0.0097, -0.0021, 0.0198),
                 inertia = [[0.0010369, -0.0000954, 0.0000995],
                            [-0.0000954, 0.0011149, -0.0001822],
                            [0.0000995, -0.0001822, 0.001213]])]
    fn rarm1() -> Spatial {
        waist2.joint(vec3(-0.0054, -0.2147, 0.3522), rpy(-0.4316, -1.0139, 0.7553) * rot_y(q_rarm1))
    }

    // right arm, joint 2 of 7
    #[rigid_body(mass = 1.483, com = vec3(0.0146, 0.0192, 0.0111),
                 inertia = [[0.0008046, -0.0000564, 0.0001055],
                            [-0.0000564, 0.0008131, 0.0002111],
                            [0.0001055, 0.0002111, 0.0005314]])]
    fn rarm2() -> Spatial {
        rarm1.joint(vec3(-0.0351, -0.0713, 0.0091), rpy(0.8294, -0.189, 0.7932) * rot_x(q_rarm2))
    }

    // right arm, joint 3 of 7
    #[rigid_body(mass = 1.821, com = vec3(-0.0289, 0.0304, -0.0708),
                 inertia = [[0.0132843, -0.000184, -0.0013685],
                            [-0.000184, 0.0107408, -0.0003268],
                            [-0.0013685, -0.0003268, 0.0065979]])]
    fn rarm3() -> Spatial {
        rarm2.joint(vec3(-0.2076, -0.0149, 0.1873), rpy(-0.8767, 0.843, 0.2728) * rot_z(q_rarm3))
    }

    // right arm, joint 4 of 7
    #[rigid_body(mass = 1.431, com = vec3(0.0231, 0.0026, -0.0144),
                 inertia = [[0.0010486, -0.0000085, 0.0000336],
                            [-0.0000085, 0.0011048, -0.0000126],
                            [0.0000336, -0.0000126, 0.0009695]])]
    fn rarm4() -> Spatial {
        rarm3.joint(vec3(0.0437, -0.0186, 0.0644), rpy(0.1877, 0.1448, -1.1822) * rot_y(q_rarm4))
    }

    // right arm, joint 5 of 7
    #[rigid_body(mass = 1.007, com = vec3(-0.0936, -0.0872, -0.0405),
                 inertia = [[0.0049918, -0.0003157, 0.0007607],
                            [-0.0003157, 0.0050149, -0.0004215],
                            [0.0007607, -0.0004215, 0.0060139]])]
    fn rarm5() -> Spatial {
        rarm4.joint(vec3(-0.1524, 0.1974, -0.0734), rpy(-0.9891, -0.408, -1.0778) * rot_z(q_rarm5))
    }

    // right arm, joint 6 of 7
    #[rigid_body(mass = 0.538, com = vec3(-0.0158, -0.0099, -0.0182),
                 inertia = [[0.0001388, -0.0000073, -0.000017],
                            [-0.0000073, 0.00016, 0.0000489],
                            [-0.000017, 0.0000489, 0.0001537]])]
    fn rarm6() -> Spatial {
        rarm5.joint(vec3(0.0508, 0.0202, -0.0248), rpy(0.2678, 1.0371, -0.3176) * rot_y(q_rarm6))
    }

    // right arm, joint 7 of 7
    #[rigid_body(mass = 0.336, com = vec3(0.0078, -0.0282, -0.0015),
                 inertia = [[0.000119, -0.0000218, -0.0000471],
                            [-0.0000218, 0.0001471, 0.0000026],
                            [-0.0000471, 0.0000026, 0.0001451]])]
    fn rarm7() -> Spatial {
        rarm6.joint(vec3(-0.0757, 0.0192, -0.0173), rpy(0.024, 0.5826, 0.8657) * rot_x(q_rarm7))
    }

    // head, joint 1 of 2
    #[rigid_body(mass = 0.546, com = vec3(0.0161, -0.0097, 0.0092),
                 inertia = [[0.0001122, -0.000027, 0.0000023],
                            [-0.000027, 0.0001359, -0.0000041],
                            [0.0000023, -0.0000041, 0.0000969]])]
    fn head1() -> Spatial {
        waist2.joint(vec3(0.0173, 0.0085, 0.453), rpy(-0.0267, -0.1368, 1.1754) * rot_z(q_head1))
    }

    // head, joint 2 of 2
    #[rigid_body(mass = 3.33, com = vec3(-0.0526, 0.0157, -0.0429),
                 inertia = [[0.0023951, -0.0005027, -0.0001278],
                            [-0.0005027, 0.0031979, 0.0001542],
                            [-0.0001278, 0.0001542, 0.0032139]])]
    fn head2() -> Spatial {
        head1.joint(vec3(0.0536, -0.0185, 0.1389), rpy(-0.0721, 0.6812, 0.9963) * rot_y(q_head2))
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
