// Written by scripts/peers/robots.py; do not edit. The robot `quadruped`: 12 revolute joints,
// the same numbers as scripts/peers/robots/quadruped.urdf (fixed base `torso`).
#[lagrange::mechanism]
pub mod quadruped {
    pub struct Coords {
        pub q_fl1: f64,
        pub q_fl2: f64,
        pub q_fl3: f64,
        pub q_fr1: f64,
        pub q_fr2: f64,
        pub q_fr3: f64,
        pub q_hl1: f64,
        pub q_hl2: f64,
        pub q_hl3: f64,
        pub q_hr1: f64,
        pub q_hr2: f64,
        pub q_hr3: f64,
    }
    pub struct Quadruped {
        pub g: f64,
    }

    // front left leg, joint 1 of 3
    #[rigid_body(mass = 0.847, com = vec3(-0.0191, 0.0068, 0.0144),
                 inertia = [[0.0007605, -0.0000065, 0.0000211],
                            [-0.0000065, 0.0008176, -0.0000015],
                            [0.0000211, -0.0000015, 0.0007807]])]
    fn fl1() -> Spatial {
        spatial(
            vec3(0.2555, 0.1005, -0.0115),
            rpy(-0.8478, 0.3995, 0.4372) * rot_x(q_fl1),
        )
    }

    // front left leg, joint 2 of 3
    #[rigid_body(mass = 1.406, com = vec3(-0.079, 0.0721, -0.053),
                 inertia = [[0.0060965, 0.0005752, -0.0001858],
                            [0.0005752, 0.0063659, 0.0002372],
                            [-0.0001858, 0.0002372, 0.0068596]])]
    fn fl2() -> Spatial {
        fl1.joint(
            vec3(0.068, 0.1984, -0.0665),
            rpy(0.0466, -0.7296, 0.1207) * rot_y(q_fl2),
        )
    }

    // front left leg, joint 3 of 3
    #[rigid_body(mass = 0.368, com = vec3(0.0711, 0.0, -0.0223),
                 inertia = [[0.0010638, 0.0001054, -0.0000264],
                            [0.0001054, 0.0005308, -0.000027],
                            [-0.0000264, -0.000027, 0.0008795]])]
    fn fl3() -> Spatial {
        fl2.joint(
            vec3(0.1275, 0.1791, 0.0079),
            rpy(-0.8181, 0.3957, 0.9901) * rot_y(q_fl3),
        )
    }

    // front right leg, joint 1 of 3
    #[rigid_body(mass = 0.864, com = vec3(-0.0153, -0.0238, -0.0224),
                 inertia = [[0.0003918, -0.000018, 0.0000437],
                            [-0.000018, 0.0003608, -0.0000066],
                            [0.0000437, -0.0000066, 0.0004145]])]
    fn fr1() -> Spatial {
        spatial(
            vec3(0.257, -0.1366, 0.0026),
            rpy(-0.8232, 1.0224, 0.0215) * rot_x(q_fr1),
        )
    }

    // front right leg, joint 2 of 3
    #[rigid_body(mass = 1.797, com = vec3(0.0754, 0.0633, -0.0203),
                 inertia = [[0.0079218, 0.0005624, 0.0003756],
                            [0.0005624, 0.0082544, 0.0023072],
                            [0.0003756, 0.0023072, 0.0085252]])]
    fn fr2() -> Spatial {
        fr1.joint(
            vec3(0.1027, 0.1945, 0.0004),
            rpy(1.1584, 0.0184, -0.3093) * rot_y(q_fr2),
        )
    }

    // front right leg, joint 3 of 3
    #[rigid_body(mass = 0.346, com = vec3(-0.0811, 0.0114, 0.0739),
                 inertia = [[0.0012366, 0.0000214, 0.0000515],
                            [0.0000214, 0.0010409, -0.0000903],
                            [0.0000515, -0.0000903, 0.0010069]])]
    fn fr3() -> Spatial {
        fr2.joint(
            vec3(0.0104, -0.1062, -0.1924),
            rpy(0.5874, -0.3627, 0.3312) * rot_y(q_fr3),
        )
    }

    // hind left leg, joint 1 of 3
    #[rigid_body(mass = 0.82, com = vec3(0.0146, 0.0254, 0.0074),
                 inertia = [[0.000309, -0.0000034, 0.0000144],
                            [-0.0000034, 0.0003247, -0.0000182],
                            [0.0000144, -0.0000182, 0.0003388]])]
    fn hl1() -> Spatial {
        spatial(
            vec3(-0.2394, 0.1016, -0.0102),
            rpy(0.9465, 0.6585, -0.3749) * rot_x(q_hl1),
        )
    }

    // hind left leg, joint 2 of 3
    #[rigid_body(mass = 1.53, com = vec3(0.0828, 0.0805, -0.0225),
                 inertia = [[0.0057778, 0.0000487, -0.0000596],
                            [0.0000487, 0.0056733, -0.0000246],
                            [-0.0000596, -0.0000246, 0.0056974]])]
    fn hl2() -> Spatial {
        hl1.joint(
            vec3(0.1632, 0.1334, -0.0628),
            rpy(-0.053, -0.989, 0.2261) * rot_y(q_hl2),
        )
    }

    // hind left leg, joint 3 of 3
    #[rigid_body(mass = 0.372, com = vec3(0.0701, -0.0326, -0.0877),
                 inertia = [[0.001067, -0.0004191, -0.0002702],
                            [-0.0004191, 0.0010924, -0.000356],
                            [-0.0002702, -0.000356, 0.0013742]])]
    fn hl3() -> Spatial {
        hl2.joint(
            vec3(0.0987, 0.1966, -0.0033),
            rpy(0.7099, 0.954, 0.3086) * rot_y(q_hl3),
        )
    }

    // hind right leg, joint 1 of 3
    #[rigid_body(mass = 0.924, com = vec3(0.03, 0.0129, 0.0264),
                 inertia = [[0.0002356, 0.0000117, -0.0000411],
                            [0.0000117, 0.0003051, -0.0000213],
                            [-0.0000411, -0.0000213, 0.0003219]])]
    fn hr1() -> Spatial {
        spatial(
            vec3(-0.2445, -0.1121, 0.0141),
            rpy(-1.1637, 0.7666, 0.9224) * rot_x(q_hr1),
        )
    }

    // hind right leg, joint 2 of 3
    #[rigid_body(mass = 1.785, com = vec3(0.0392, -0.0151, -0.0032),
                 inertia = [[0.0067402, 0.0001865, 0.0012742],
                            [0.0001865, 0.0061168, -0.0001794],
                            [0.0012742, -0.0001794, 0.0074049]])]
    fn hr2() -> Spatial {
        hr1.joint(
            vec3(-0.213, 0.0181, -0.052),
            rpy(-0.3433, 0.7519, -0.5349) * rot_y(q_hr2),
        )
    }

    // hind right leg, joint 3 of 3
    #[rigid_body(mass = 0.391, com = vec3(-0.0192, -0.02, 0.0318),
                 inertia = [[0.0010359, -0.0001944, -0.0000933],
                            [-0.0001944, 0.0014839, -0.0000323],
                            [-0.0000933, -0.0000323, 0.0015507]])]
    fn hr3() -> Spatial {
        hr2.joint(
            vec3(-0.0797, 0.187, -0.0842),
            rpy(0.7154, -0.4159, 0.3635) * rot_y(q_hr3),
        )
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
