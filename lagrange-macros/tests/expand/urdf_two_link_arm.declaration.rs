pub mod m {
    const _: &[u8] = include_bytes!(
        "tests/urdf/two_link_arm.urdf"
    );
    pub struct Coords {
        pub shoulder: f64,
        pub elbow: f64,
    }
    ///Parameters of the model: `g`, gravity's magnitude along −z, and each joint's `<dynamics>` coefficients. `M::default()` holds the file's values (g = 9.81).
    pub struct M {
        pub g: f64,
        pub shoulder_damping: f64,
        pub elbow_damping: f64,
    }
    impl ::core::default::Default for M {
        fn default() -> Self {
            Self {
                g: 9.81,
                shoulder_damping: 0.3,
                elbow_damping: 0.1,
            }
        }
    }
    ///Link `upper`, moved by joint `shoulder`.
    #[rigid_body(
        mass = 2.0,
        com = vec3(0.3, 0.0, 0.0),
        inertia = [[0.01,
        0.002,
        0.001],
        [0.002,
        0.06,
        -0.001],
        [0.001,
        -0.001,
        0.055]]
    )]
    fn upper() -> Spatial {
        spatial(vec3(0.0, 0.0, 1.0), rot_y(-shoulder))
    }
    ///Link `fore`, moved by joint `elbow`.
    #[rigid_body(
        mass = 1.5,
        com = vec3(0.25, 0.05, 0.0),
        inertia = [[0.004,
        -0.001,
        0.0005],
        [-0.001,
        0.03,
        0.0],
        [0.0005,
        0.0,
        0.028]]
    )]
    fn fore() -> Spatial {
        upper.joint(vec3(0.6, 0.0, 0.0), rot_y(-elbow))
    }
    /// Gravity along −z.
    #[gravity]
    fn gravity() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
    /// Viscous joint damping, −c q̇ (`<dynamics damping>`).
    #[generalized_force(on = shoulder)]
    fn shoulder_damping_force() -> f64 {
        -shoulder_damping * shoulder_dot
    }
    /// Viscous joint damping, −c q̇ (`<dynamics damping>`).
    #[generalized_force(on = elbow)]
    fn elbow_damping_force() -> f64 {
        -elbow_damping * elbow_dot
    }
}
