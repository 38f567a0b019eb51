pub mod m {
    const _: &[u8] = include_bytes!(
        "tests/urdf/branched.urdf"
    );
    pub struct Coords {
        pub l_shoulder: f64,
        pub l_elbow: f64,
        pub r_shoulder: f64,
        pub r_elbow: f64,
        pub neck: f64,
    }
    ///Parameters of the model: `g`, gravity's magnitude along −z, and each joint's `<dynamics>` coefficients. `M::default()` holds the file's values (g = 9.81).
    pub struct M {
        pub g: f64,
    }
    impl ::core::default::Default for M {
        fn default() -> Self {
            Self { g: 9.81 }
        }
    }
    ///Link `l_upper`, moved by joint `l_shoulder`.
    #[rigid_body(
        mass = 1.8,
        com = vec3(0.0, 0.0, -0.15),
        inertia = [[0.018557435256518387,
        0.0011198289846681498,
        -0.0037813207588630075],
        [0.0011198289846681498,
        0.021305527147935984,
        0.0023666587331108314],
        [-0.0037813207588630075,
        0.0023666587331108314,
        0.005137037595545632]]
    )]
    fn l_upper() -> Spatial {
        spatial(
            vec3(-0.08060085996777522, 0.2319785886815846, 1.5690827951047521),
            rpy(0.0, 0.0, 0.3) * rpy(0.4, -0.2, 0.1) * rot_x(l_shoulder),
        )
    }
    ///Link `l_fore`, moved by joint `l_elbow`.
    #[rigid_body(
        mass = 1.1,
        com = vec3(0.01, 0.0, -0.12),
        inertia = [[0.011,
        0.0,
        0.001],
        [0.0,
        0.012,
        0.0],
        [0.001,
        0.0,
        0.002]]
    )]
    fn l_fore() -> Spatial {
        l_upper.joint(vec3(0.0, 0.0, -0.3), rpy(0.0, 0.0, 0.2) * rot_y(l_elbow))
    }
    ///Link `r_upper`, moved by joint `r_shoulder`.
    #[rigid_body(
        mass = 1.7,
        com = vec3(0.0, 0.0, -0.15),
        inertia = [[0.019,
        0.0,
        0.0],
        [0.0,
        0.02,
        0.0],
        [0.0,
        0.0,
        0.0035]]
    )]
    fn r_upper() -> Spatial {
        spatial(
            vec3(0.07388005166533489, -0.2388341222814015, 1.5499999999999998),
            rpy(0.0, 0.0, 0.3) * rpy(-0.3, 0.0, 0.0) * rot_y(r_shoulder),
        )
    }
    ///Link `r_fore`, moved by joint `r_elbow`.
    #[rigid_body(
        mass = 1.0,
        com = vec3(0.0, 0.01, -0.12),
        inertia = [[0.008161209223472559,
        0.0,
        -0.0033658839392315862],
        [0.0,
        0.011,
        0.0],
        [-0.0033658839392315862,
        0.0,
        0.0038387907765274412]]
    )]
    fn r_fore() -> Spatial {
        r_upper.joint(vec3(0.0, 0.0, -0.3), rot_x(-r_elbow))
    }
    ///Link `head`, moved by joint `neck`.
    #[rigid_body(
        mass = 2.2,
        com = vec3(0.0, 0.0, 0.1),
        inertia = [[0.012,
        0.0,
        0.0],
        [0.0,
        0.013,
        0.0],
        [0.0,
        0.0,
        0.009]]
    )]
    fn head() -> Spatial {
        spatial(
            vec3(0.0, 0.0, 1.7),
            rpy(0.0, 0.0, 0.3) * rot_axis(vec3(0.0, 0.6, 0.8), neck),
        )
    }
    /// Gravity along −z.
    #[gravity]
    fn gravity() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}
