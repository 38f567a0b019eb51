pub mod m {
    const _: &[u8] = include_bytes!(
        "tests/urdf/every_joint.urdf"
    );
    pub struct Coords {
        pub yaw: f64,
        pub reach: f64,
        pub spin: f64,
        pub slide: f64,
        pub tilt: f64,
    }
    ///Parameters of the model: `g`, gravity's magnitude along −z, and each joint's `<dynamics>` coefficients. `M::default()` holds the file's values (g = 9.81).
    pub struct M {
        pub g: f64,
        pub slide_damping: f64,
        pub slide_friction: f64,
        pub tilt_damping: f64,
    }
    impl ::core::default::Default for M {
        fn default() -> Self {
            Self {
                g: 9.81,
                slide_damping: 0.4,
                slide_friction: 0.05,
                tilt_damping: 0.02,
            }
        }
    }
    ///Link `turret`, moved by joint `yaw`.
    #[rigid_body(
        mass = 3.3,
        com = vec3(0.048852624160343895, 0.008031160645728098, 0.10595621348874125),
        inertia = [[0.04131273832670693,
        0.001316558358133363,
        -0.009059962402968823],
        [0.001316558358133363,
        0.0474723001253911,
        0.0033109180892578385],
        [-0.009059962402968823,
        0.0033109180892578385,
        0.03236026395069286]]
    )]
    fn turret() -> Spatial {
        spatial(
            vec3(0.1, 0.0, 0.25),
            rpy(0.0, 0.0, 0.7) * rpy(0.05, -0.03, 0.0) * rot_z(yaw),
        )
    }
    ///Link `carriage`, moved by joint `reach`.
    #[rigid_body(
        mass = 1.2,
        com = vec3(0.0, 0.03, 0.0),
        inertia = [[0.006,
        0.0,
        0.0],
        [0.0,
        0.004,
        0.0002],
        [0.0,
        0.0002,
        0.005]]
    )]
    fn carriage() -> Spatial {
        let frame = turret
            .joint(
                vec3(0.13908339297798628, 0.0274179345752589, 0.17491475982134114),
                rpy(0.3, -0.4, 0.2) * rpy(0.0, 0.0, 0.25)
                    * rot_axis(vec3(-1.0, 0.0, 0.0), 0.6435011087932844),
            );
        spatial(
            frame.point(vec3(0.0, 0.0, reach)),
            frame.rotation * rot_axis(vec3(-1.0, 0.0, 0.0), -0.6435011087932844),
        )
    }
    ///Link `wheel`, moved by joint `spin`.
    #[rigid_body(
        mass = 0.8999999999999999,
        com = vec3(0.01, 0.0, 0.02666666666666667),
        inertia = [[0.0029586141827985858,
        -0.000029602127248918097,
        -0.000010847158348612786],
        [-0.000029602127248918097,
        0.003094950066619069,
        -0.00014603187836574393],
        [-0.000010847158348612786,
        -0.00014603187836574393,
        0.0038064357505823458]]
    )]
    fn wheel() -> Spatial {
        carriage
            .joint(
                vec3(0.0, 0.1, 0.05),
                rpy(0.0, 0.2, 0.0)
                    * rot_axis(
                        vec3(0.5773502691896258, 0.5773502691896258, 0.5773502691896258),
                        spin,
                    ),
            )
    }
    ///Link `slider`, moved by joint `slide`.
    #[rigid_body(
        mass = 0.9,
        com = vec3(0.02, 0.0, 0.0),
        inertia = [[0.001,
        0.0,
        0.0],
        [0.0,
        0.003,
        0.0],
        [0.0,
        0.0,
        0.003]]
    )]
    fn slider() -> Spatial {
        let frame = turret.joint(vec3(-0.1, 0.0, 0.1), rot_z(0.0));
        spatial(frame.point(vec3(-slide, 0.0, 0.0)), frame.rotation)
    }
    ///Link `flap`, moved by joint `tilt`.
    #[rigid_body(
        mass = 0.4,
        com = vec3(0.04, 0.0, 0.0),
        inertia = [[0.0003,
        0.0,
        0.0],
        [0.0,
        0.0008,
        0.0],
        [0.0,
        0.0,
        0.0009]]
    )]
    fn flap() -> Spatial {
        slider.joint(vec3(0.05, 0.0, 0.0), rpy(1.2, 0.0, 0.0) * rot_z(-tilt))
    }
    /// Gravity along −z.
    #[gravity]
    fn gravity() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
    /// Viscous joint damping, −c q̇ (`<dynamics damping>`).
    #[generalized_force(on = slide)]
    fn slide_damping_force() -> f64 {
        -slide_damping * slide_dot
    }
    /// Coulomb friction of constant magnitude opposing the joint's motion,
    /// −f sgn(q̇), zero at rest (`<dynamics friction>`; no sticking):
    /// sgn(q̇) = q̇ / max(|q̇|, the least normal f64), exactly ±1 for every normal
    /// q̇, 0 at 0, with zero derivative.
    #[generalized_force(on = slide)]
    fn slide_friction_force() -> f64 {
        -slide_friction * (slide_dot / slide_dot.abs().max(2.2250738585072014e-308))
    }
    /// Viscous joint damping, −c q̇ (`<dynamics damping>`).
    #[generalized_force(on = tilt)]
    fn tilt_damping_force() -> f64 {
        -tilt_damping * tilt_dot
    }
}
