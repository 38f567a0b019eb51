pub mod legs {
    pub struct Legs {
        pub m: f64,
        pub w: f64,
        pub g: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq,
        ::lagrange::__private::core::default::Default
    )]
    pub struct Coords<T = f64> {
        pub yaw: T,
        pub left: T,
        pub right: T,
    }
    impl ::lagrange::__private::Coordinates<3> for Coords<f64> {
        const NAMES: [&'static str; 3] = ["yaw", "left", "right"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 3] {
            [self.yaw, self.left, self.right]
        }
        #[inline(always)]
        fn from_array(values: [f64; 3]) -> Self {
            Coords {
                yaw: values[0],
                left: values[1],
                right: values[2],
            }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 3;
    /// The state of this mechanism: time, coordinates, velocities.
    #[allow(dead_code)]
    pub type State = ::lagrange::__private::State<Coords>;
    /// Every body and point of the mechanism, by name: a particle or point's position, a rigid
    /// body's pose as its function returns it (its centre of mass and orientation, or, for a
    /// body declared with its `com`, its frame).
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    #[allow(dead_code)]
    pub struct Bodies<T = f64> {
        pub torso: ::lagrange::__private::geometry::Spatial<T>,
        pub left_leg: ::lagrange::__private::geometry::Spatial<T>,
        pub right_leg: ::lagrange::__private::geometry::Spatial<T>,
    }
    /// The velocity of every body and point, by name: a particle or point's velocity; for a
    /// planar body, its centre-of-mass velocity and angular velocity (as a `Planar`); for a
    /// spatial body, a `SpatialVelocity` (centre-of-mass and angular velocity, world frame).
    /// For a body declared with its `com`, the velocity of its frame's origin in place of the
    /// centre of mass's.
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    #[allow(dead_code)]
    pub struct BodyVelocities<T = f64> {
        pub torso: ::lagrange::__private::geometry::SpatialVelocity<T>,
        pub left_leg: ::lagrange::__private::geometry::SpatialVelocity<T>,
        pub right_leg: ::lagrange::__private::geometry::SpatialVelocity<T>,
    }
    impl Legs {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                3,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                3,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                3,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                3,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                3,
                36,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 3],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [yaw, left, right] = *__q;
            let w = <__D>::from(self.w);
            let __param_0: __D = <__D>::from({
                let w: f64 = self.w;
                -w
            });
            let torso: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(<__D>::from(0.0), <__D>::from(0.0), <__D>::from(1.0)),
                    rot_z(yaw),
                )
            };
            let left_leg: ::lagrange::__private::geometry::Spatial<__D> = {
                let r = torso.rotation * rot_x(left);
                spatial(
                    torso.point(vec3(w, <__D>::from(0.0), -<__D>::from(0.3)))
                        + r
                            * vec3(
                                <__D>::from(0.0),
                                <__D>::from(0.0),
                                -<__D>::from(0.2),
                            ),
                    r,
                )
            };
            let right_leg: ::lagrange::__private::geometry::Spatial<__D> = {
                let r = torso.rotation * rot_x(right);
                spatial(
                    torso.point(vec3(__param_0, <__D>::from(0.0), -<__D>::from(0.3)))
                        + r
                            * vec3(
                                <__D>::from(0.0),
                                <__D>::from(0.0),
                                -<__D>::from(0.2),
                            ),
                    r,
                )
            };
            Bodies {
                torso,
                left_leg,
                right_leg,
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 36],
            __x_dot: &[__D; 36],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                torso: ::lagrange::__private::geometry::SpatialVelocity {
                    linear: ::lagrange::__private::geometry::vec3(
                        __x_dot[0],
                        __x_dot[1],
                        __x_dot[2],
                    ),
                    angular: ::lagrange::__private::geometry::angular_velocity(
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x[3],
                                __x[4],
                                __x[5],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[6],
                                __x[7],
                                __x[8],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[9],
                                __x[10],
                                __x[11],
                            ),
                        ],
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[3],
                                __x_dot[4],
                                __x_dot[5],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[6],
                                __x_dot[7],
                                __x_dot[8],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[9],
                                __x_dot[10],
                                __x_dot[11],
                            ),
                        ],
                    ),
                },
                left_leg: ::lagrange::__private::geometry::SpatialVelocity {
                    linear: ::lagrange::__private::geometry::vec3(
                        __x_dot[12],
                        __x_dot[13],
                        __x_dot[14],
                    ),
                    angular: ::lagrange::__private::geometry::angular_velocity(
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x[15],
                                __x[16],
                                __x[17],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[18],
                                __x[19],
                                __x[20],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[21],
                                __x[22],
                                __x[23],
                            ),
                        ],
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[15],
                                __x_dot[16],
                                __x_dot[17],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[18],
                                __x_dot[19],
                                __x_dot[20],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[21],
                                __x_dot[22],
                                __x_dot[23],
                            ),
                        ],
                    ),
                },
                right_leg: ::lagrange::__private::geometry::SpatialVelocity {
                    linear: ::lagrange::__private::geometry::vec3(
                        __x_dot[24],
                        __x_dot[25],
                        __x_dot[26],
                    ),
                    angular: ::lagrange::__private::geometry::angular_velocity(
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x[27],
                                __x[28],
                                __x[29],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[30],
                                __x[31],
                                __x[32],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x[33],
                                __x[34],
                                __x[35],
                            ),
                        ],
                        [
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[27],
                                __x_dot[28],
                                __x_dot[29],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[30],
                                __x_dot[31],
                                __x_dot[32],
                            ),
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[33],
                                __x_dot[34],
                                __x_dot[35],
                            ),
                        ],
                    ),
                },
            }
        }
    }
    impl ::lagrange::__private::Model<3, 36> for Legs {
        type Coords = Coords;
        const INERTIAL: usize = 36;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 3]; 36] = [
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, false, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, true, false],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
            [true, false, true],
        ];
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.w.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "w",
                    value: self.w,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let m: f64 = self.m;
            let w: f64 = self.w;
            let g: f64 = self.g;
            let __mass_torso: f64 = m;
            let __inertia_torso: [f64; 3] = [0.2, 0.15, 0.1];
            let __mass_left_leg: f64 = m;
            let __inertia_left_leg: [f64; 3] = [0.05, 0.05, 0.01];
            let __mass_right_leg: f64 = m;
            let __inertia_right_leg: [f64; 3] = [0.05, 0.05, 0.01];
            if !(__mass_torso.is_finite() && __mass_torso > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "torso",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_torso
                    ),
                });
            }
            let __sum: f64 = __inertia_torso[0] + __inertia_torso[1]
                + __inertia_torso[2];
            for (__k, __moment) in __inertia_torso.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "torso",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "torso",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_torso, __k + 1
                        ),
                    });
                }
            }
            if !(__mass_left_leg.is_finite() && __mass_left_leg > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "left_leg",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_left_leg
                    ),
                });
            }
            let __sum: f64 = __inertia_left_leg[0] + __inertia_left_leg[1]
                + __inertia_left_leg[2];
            for (__k, __moment) in __inertia_left_leg.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "left_leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "left_leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_left_leg, __k + 1
                        ),
                    });
                }
            }
            if !(__mass_right_leg.is_finite() && __mass_right_leg > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "right_leg",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_right_leg
                    ),
                });
            }
            let __sum: f64 = __inertia_right_leg[0] + __inertia_right_leg[1]
                + __inertia_right_leg[2];
            for (__k, __moment) in __inertia_right_leg.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "right_leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "right_leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_right_leg, __k + 1
                        ),
                    });
                }
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 36] {
            let m: f64 = self.m;
            let w: f64 = self.w;
            let g: f64 = self.g;
            let __mass_torso: f64 = m;
            let __inertia_torso: [f64; 3] = [0.2, 0.15, 0.1];
            let __mass_left_leg: f64 = m;
            let __inertia_left_leg: [f64; 3] = [0.05, 0.05, 0.01];
            let __mass_right_leg: f64 = m;
            let __inertia_right_leg: [f64; 3] = [0.05, 0.05, 0.01];
            [
                __mass_torso,
                __mass_torso,
                __mass_torso,
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[0usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[0usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[0usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[1usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[1usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[1usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[2usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[2usize]),
                ((__inertia_torso[0] + __inertia_torso[1] + __inertia_torso[2]) * 0.5
                    - __inertia_torso[2usize]),
                __mass_left_leg,
                __mass_left_leg,
                __mass_left_leg,
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[0usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[0usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[0usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[1usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[1usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[1usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[2usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[2usize]),
                ((__inertia_left_leg[0] + __inertia_left_leg[1] + __inertia_left_leg[2])
                    * 0.5 - __inertia_left_leg[2usize]),
                __mass_right_leg,
                __mass_right_leg,
                __mass_right_leg,
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[0usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[0usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[0usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[1usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[1usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[1usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[2usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[2usize]),
                ((__inertia_right_leg[0] + __inertia_right_leg[1]
                    + __inertia_right_leg[2]) * 0.5 - __inertia_right_leg[2usize]),
            ]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 3],
        ) -> [__D; 36] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.torso.position.x,
                __bodies.torso.position.y,
                __bodies.torso.position.z,
                __bodies.torso.rotation.rows[0][0],
                __bodies.torso.rotation.rows[1][0],
                __bodies.torso.rotation.rows[2][0],
                __bodies.torso.rotation.rows[0][1],
                __bodies.torso.rotation.rows[1][1],
                __bodies.torso.rotation.rows[2][1],
                __bodies.torso.rotation.rows[0][2],
                __bodies.torso.rotation.rows[1][2],
                __bodies.torso.rotation.rows[2][2],
                __bodies.left_leg.position.x,
                __bodies.left_leg.position.y,
                __bodies.left_leg.position.z,
                __bodies.left_leg.rotation.rows[0][0],
                __bodies.left_leg.rotation.rows[1][0],
                __bodies.left_leg.rotation.rows[2][0],
                __bodies.left_leg.rotation.rows[0][1],
                __bodies.left_leg.rotation.rows[1][1],
                __bodies.left_leg.rotation.rows[2][1],
                __bodies.left_leg.rotation.rows[0][2],
                __bodies.left_leg.rotation.rows[1][2],
                __bodies.left_leg.rotation.rows[2][2],
                __bodies.right_leg.position.x,
                __bodies.right_leg.position.y,
                __bodies.right_leg.position.z,
                __bodies.right_leg.rotation.rows[0][0],
                __bodies.right_leg.rotation.rows[1][0],
                __bodies.right_leg.rotation.rows[2][0],
                __bodies.right_leg.rotation.rows[0][1],
                __bodies.right_leg.rotation.rows[1][1],
                __bodies.right_leg.rotation.rows[2][1],
                __bodies.right_leg.rotation.rows[0][2],
                __bodies.right_leg.rotation.rows[1][2],
                __bodies.right_leg.rotation.rows[2][2],
            ]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 36] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<3, 36>>::masses(self);
            let mut __weights = [0.0; 36];
            let __gravity_down: ::lagrange::__private::geometry::Vec3<f64> = {
                vec3(0.0, 0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights[2] += __gravity_down.z * __masses[2];
            __weights[12] += __gravity_down.x * __masses[12];
            __weights[13] += __gravity_down.y * __masses[13];
            __weights[14] += __gravity_down.z * __masses[14];
            __weights[24] += __gravity_down.x * __masses[24];
            __weights[25] += __gravity_down.y * __masses[25];
            __weights[26] += __gravity_down.z * __masses[26];
            __weights
        }
    }
    impl ::lagrange::__private::tree::rigid::RigidTree<3, 3> for Legs {
        const JOINTS: [::lagrange::__private::tree::rigid::Joint; 3] = [
            ::lagrange::__private::tree::rigid::Joint {
                parent: ::lagrange::__private::core::option::Option::None,
                kind: ::lagrange::__private::tree::rigid::JointKind::Revolute(
                    ::lagrange::__private::tree::rigid::spatial::Axis::Z,
                ),
                coordinate: 0,
                rotated: false,
                offset: [false, false, true],
            },
            ::lagrange::__private::tree::rigid::Joint {
                parent: ::lagrange::__private::core::option::Option::Some(0),
                kind: ::lagrange::__private::tree::rigid::JointKind::Revolute(
                    ::lagrange::__private::tree::rigid::spatial::Axis::X,
                ),
                coordinate: 1,
                rotated: false,
                offset: [true, false, true],
            },
            ::lagrange::__private::tree::rigid::Joint {
                parent: ::lagrange::__private::core::option::Option::Some(0),
                kind: ::lagrange::__private::tree::rigid::JointKind::Revolute(
                    ::lagrange::__private::tree::rigid::spatial::Axis::X,
                ),
                coordinate: 2,
                rotated: false,
                offset: [true, false, true],
            },
        ];
    }
    impl Legs {
        #[allow(unused_variables, unused_parens, clippy::all)]
        fn __lagrange_rigid_constants(
            &self,
        ) -> ::lagrange::__private::tree::rigid::RigidConstants<3> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let m: f64 = self.m;
            let w: f64 = self.w;
            let g: f64 = self.g;
            let __after_0: Rot3<f64> = (Rot3::<f64>::identity());
            let __own_0: Vec3<f64> = (Vec3::<f64>::zero());
            let __body_0 = {
                let __rotation: Rot3<f64> = Rot3::<f64>::identity()
                    * (Rot3::<f64>::identity());
                let __offset: Vec3<f64> = Rot3::<f64>::identity()
                    * (Vec3::<f64>::zero()
                        + (Rot3::<f64>::identity()) * vec3((0.0), (0.0), (1.0)));
                let __mass: f64 = m;
                let __tensor: [[f64; 3]; 3] = ::lagrange::__private::tree::rigid::turned_tensor(
                    &__after_0,
                    ::lagrange::__private::tree::rigid::diagonal([0.2, 0.15, 0.1]),
                );
                let __centre: Vec3<f64> = __own_0 + __after_0 * Vec3::<f64>::zero();
                ::lagrange::__private::tree::rigid::body_constants(
                    __rotation,
                    __offset,
                    __mass,
                    __centre,
                    __tensor,
                )
            };
            let __after_1: Rot3<f64> = (Rot3::<f64>::identity());
            let __own_1: Vec3<f64> = (Vec3::<f64>::zero()
                + (Rot3::<f64>::identity()) * vec3((0.0), (0.0), (-(0.2))));
            let __body_1 = {
                let __rotation: Rot3<f64> = __after_0 * (Rot3::<f64>::identity());
                let __offset: Vec3<f64> = __own_0
                    + __after_0
                        * (Vec3::<f64>::zero()
                            + (Rot3::<f64>::identity()) * vec3((w), (0.0), (-(0.3))));
                let __mass: f64 = m;
                let __tensor: [[f64; 3]; 3] = ::lagrange::__private::tree::rigid::turned_tensor(
                    &__after_1,
                    ::lagrange::__private::tree::rigid::diagonal([0.05, 0.05, 0.01]),
                );
                let __centre: Vec3<f64> = __own_1 + __after_1 * Vec3::<f64>::zero();
                ::lagrange::__private::tree::rigid::body_constants(
                    __rotation,
                    __offset,
                    __mass,
                    __centre,
                    __tensor,
                )
            };
            let __after_2: Rot3<f64> = (Rot3::<f64>::identity());
            let __own_2: Vec3<f64> = (Vec3::<f64>::zero()
                + (Rot3::<f64>::identity()) * vec3((0.0), (0.0), (-(0.2))));
            let __body_2 = {
                let __rotation: Rot3<f64> = __after_0 * (Rot3::<f64>::identity());
                let __offset: Vec3<f64> = __own_0
                    + __after_0
                        * (Vec3::<f64>::zero()
                            + (Rot3::<f64>::identity()) * vec3((-(w)), (0.0), (-(0.3))));
                let __mass: f64 = m;
                let __tensor: [[f64; 3]; 3] = ::lagrange::__private::tree::rigid::turned_tensor(
                    &__after_2,
                    ::lagrange::__private::tree::rigid::diagonal([0.05, 0.05, 0.01]),
                );
                let __centre: Vec3<f64> = __own_2 + __after_2 * Vec3::<f64>::zero();
                ::lagrange::__private::tree::rigid::body_constants(
                    __rotation,
                    __offset,
                    __mass,
                    __centre,
                    __tensor,
                )
            };
            ::lagrange::__private::tree::rigid::RigidConstants {
                bodies: [__body_0, __body_1, __body_2],
                gravity: ((Vec3::<f64>::zero()
                    + {
                        let __g: Vec3<f64> = { vec3(0.0, 0.0, -g) };
                        __g
                    }))
                    .to_array(),
            }
        }
        #[inline(always)]
        #[allow(clippy::all)]
        fn __lagrange_rigid_sweeps<S: ::lagrange::__private::Scalar>(
            &self,
            __ws: &mut ::lagrange::__private::tree::rigid::Articulated<S, 3>,
            __joints: &[::lagrange::__private::tree::rigid::Joint; 3],
            __k: &::lagrange::__private::tree::rigid::RigidConstants<3>,
            (__q, __v, __tau): (&[S; 3], &[S; 3], &[S; 3]),
            __qdd: &mut [S; 3],
        ) -> ::lagrange::__private::core::result::Result<
            (),
            ::lagrange::__private::tree::rigid::Pivot,
        > {
            __ws.velocity::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[0]
                            .code()
                    },
                    3,
                >(__joints, __k, __q, __v, 0);
            __ws.velocity::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[1]
                            .code()
                    },
                    3,
                >(__joints, __k, __q, __v, 1);
            __ws.velocity::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[2]
                            .code()
                    },
                    3,
                >(__joints, __k, __q, __v, 2);
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws
                .articulate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[2]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 2)
            {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws
                .articulate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[1]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 1)
            {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws
                .articulate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[0]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 0)
            {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
            __ws.accelerate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[0]
                            .code()
                    },
                    3,
                >(__joints, __k, __qdd, 0);
            __ws.accelerate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[1]
                            .code()
                    },
                    3,
                >(__joints, __k, __qdd, 1);
            __ws.accelerate::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[2]
                            .code()
                    },
                    3,
                >(__joints, __k, __qdd, 2);
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_accelerations<
            S: ::lagrange::__private::Scalar,
            __F: ::lagrange::__private::Model<3, 36>,
        >(
            &self,
            __forces: &__F,
            __k: &::lagrange::__private::tree::rigid::RigidConstants<3>,
            __t: S,
            __q: &[S; 3],
            __v: &[S; 3],
        ) -> ::lagrange::__private::Result<[S; 3]> {
            let __joints = &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                3,
                3,
            >>::JOINTS;
            let __tau: [S; 3] = ::lagrange::__private::tree::rigid::other_generalized_forces::<
                __F,
                S,
                3,
                36,
                3,
            >(__forces, __joints, __t, __q, __v)
                .into();
            let mut __ws = ::lagrange::__private::tree::rigid::Articulated::<
                S,
                3,
            >::new();
            let mut __qdd = [<S as ::lagrange::__private::core::convert::From<
                f64,
            >>::from(0.0); 3];
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = self
                .__lagrange_rigid_sweeps(
                    &mut __ws,
                    __joints,
                    __k,
                    (__q, __v, &__tau),
                    &mut __qdd,
                )
            {
                return ::lagrange::__private::core::result::Result::Err(
                    ::lagrange::__private::tree::rigid::singular::<
                        Coords,
                        S,
                        3,
                        3,
                    >(__joints, __pivot, __t, __q),
                );
            }
            ::lagrange::__private::tree::rigid::finished::<Coords, S, 3>(__qdd, __t, __q)
        }
        /// The two sweeps; neither fails (the chunks' `Result` is for the sweeps that can).
        #[inline(always)]
        #[allow(clippy::all)]
        fn __lagrange_rigid_newton_euler<S: ::lagrange::__private::Scalar>(
            &self,
            __ws: &mut ::lagrange::__private::tree::rigid::NewtonEuler<S, 3>,
            __joints: &[::lagrange::__private::tree::rigid::Joint; 3],
            __k: &::lagrange::__private::tree::rigid::RigidConstants<3>,
            __state: (&[S; 3], &[S; 3], &[S; 3]),
            __tau: &mut [S; 3],
        ) -> ::lagrange::__private::core::result::Result<
            (),
            ::lagrange::__private::tree::rigid::Pivot,
        > {
            __ws.forward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[0]
                            .code()
                    },
                    3,
                >(__joints, __k, __state, 0);
            __ws.forward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[1]
                            .code()
                    },
                    3,
                >(__joints, __k, __state, 1);
            __ws.forward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[2]
                            .code()
                    },
                    3,
                >(__joints, __k, __state, 2);
            __ws.backward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[2]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 2);
            __ws.backward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[1]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 1);
            __ws.backward::<
                    {
                        <Legs as ::lagrange::__private::tree::rigid::RigidTree<
                            3,
                            3,
                        >>::JOINTS[0]
                            .code()
                    },
                    3,
                >(__joints, __k, __tau, 0);
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_inverse_dynamics<
            S: ::lagrange::__private::Scalar,
            __F: ::lagrange::__private::Model<3, 36>,
        >(
            &self,
            __forces: &__F,
            __k: &::lagrange::__private::tree::rigid::RigidConstants<3>,
            __t: S,
            __q: &[S; 3],
            __v: &[S; 3],
            __qdd: &[S; 3],
        ) -> [S; 3] {
            let __joints = &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                3,
                3,
            >>::JOINTS;
            let mut __ws = ::lagrange::__private::tree::rigid::NewtonEuler::<
                S,
                3,
            >::new();
            let mut __tau = [<S as ::lagrange::__private::core::convert::From<
                f64,
            >>::from(0.0); 3];
            let _ = self
                .__lagrange_rigid_newton_euler(
                    &mut __ws,
                    __joints,
                    __k,
                    (__q, __v, __qdd),
                    &mut __tau,
                );
            ::lagrange::__private::tree::rigid::less_other_forces::<
                __F,
                S,
                3,
                36,
                3,
            >(__forces, __joints, __tau, __t, __q, __v)
        }
    }
    impl ::lagrange::__private::Prepare for Legs {
        type Prepared = ::lagrange::__private::tree::rigid::RigidConstants<3>;
        #[inline]
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::core::result::Result::Ok(
                self.__lagrange_rigid_constants(),
            )
        }
    }
    impl ::lagrange::__private::Dynamics<3> for Legs {
        type Coords = Coords;
        type Contacts = ::lagrange::__private::lagrange_core::constraints::NoContacts;
        const CONSTRAINT_COUNTS: ::lagrange::__private::core::option::Option<
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts,
        > = ::lagrange::__private::core::option::Option::Some(
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts::NONE,
        );
        const SCLERONOMIC: bool = true;
        const CLOSED_FORM: bool = false;
        #[inline]
        fn check_parameters(&self) -> ::lagrange::__private::Result<()> {
            <Self as ::lagrange::__private::Model<3, 36>>::validate(self)?;
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn equations_of_motion_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 3> {
            let prepared = __constants.prepared;
            {
                let __owned;
                let __k = match prepared {
                    ::lagrange::__private::core::option::Option::Some(__k) => __k,
                    ::lagrange::__private::core::option::Option::None => {
                        __owned = self.__lagrange_rigid_constants();
                        &__owned
                    }
                };
                ::lagrange::__private::tree::rigid::equations_of_motion::<
                    Self,
                    S,
                    3,
                    36,
                    3,
                >(self, __k, t, q, v)
            }
        }
        #[inline]
        fn mass_matrix_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            _t: S,
            q: &[S; 3],
        ) -> ::lagrange::__private::nalgebra::SMatrix<S, 3, 3> {
            let prepared = __constants.prepared;
            {
                let __owned;
                let __k = match prepared {
                    ::lagrange::__private::core::option::Option::Some(__k) => __k,
                    ::lagrange::__private::core::option::Option::None => {
                        __owned = self.__lagrange_rigid_constants();
                        &__owned
                    }
                };
                ::lagrange::__private::tree::rigid::mass_matrix::<
                    S,
                    3,
                    3,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        3,
                        3,
                    >>::JOINTS,
                    __k,
                    q,
                )
            }
        }
        #[inline]
        fn accelerations_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
        ) -> ::lagrange::__private::Result<[S; 3]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    self.__lagrange_rigid_accelerations(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    self.__lagrange_rigid_accelerations(
                        self,
                        &self.__lagrange_rigid_constants(),
                        t,
                        q,
                        v,
                    )
                }
            }
        }
        #[inline]
        fn inverse_dynamics_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
            a: &[S; 3],
        ) -> [S; 3] {
            let prepared = __constants.prepared;
            {
                let __owned;
                let __k = match prepared {
                    ::lagrange::__private::core::option::Option::Some(__k) => __k,
                    ::lagrange::__private::core::option::Option::None => {
                        __owned = self.__lagrange_rigid_constants();
                        &__owned
                    }
                };
                self.__lagrange_rigid_inverse_dynamics(self, __k, t, q, v, a)
            }
        }
        #[inline]
        fn kinetic_energy_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
        ) -> S {
            let prepared = __constants.prepared;
            {
                let __owned;
                let __k = match prepared {
                    ::lagrange::__private::core::option::Option::Some(__k) => __k,
                    ::lagrange::__private::core::option::Option::None => {
                        __owned = self.__lagrange_rigid_constants();
                        &__owned
                    }
                };
                ::lagrange::__private::tree::rigid::kinetic_energy::<
                    S,
                    3,
                    3,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        3,
                        3,
                    >>::JOINTS,
                    __k,
                    q,
                    v,
                )
            }
        }
        #[inline]
        fn potential_energy_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                3,
                36,
            >(self, t, q)
        }
        #[inline]
        fn lagrangian_time_derivative_at(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: f64,
            q: &[f64; 3],
            v: &[f64; 3],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                3,
                36,
            >(self, t, q, v)
        }
        #[inline]
        fn momenta_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
        ) -> [S; 3] {
            let prepared = __constants.prepared;
            {
                let __owned;
                let __k = match prepared {
                    ::lagrange::__private::core::option::Option::Some(__k) => __k,
                    ::lagrange::__private::core::option::Option::None => {
                        __owned = self.__lagrange_rigid_constants();
                        &__owned
                    }
                };
                ::lagrange::__private::tree::rigid::momenta::<
                    S,
                    3,
                    3,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        3,
                        3,
                    >>::JOINTS,
                    __k,
                    q,
                    v,
                )
            }
        }
        #[inline]
        fn canonical_field_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 3],
            v: &[S; 3],
        ) -> ([S; 3], [S; 3]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    Self,
                    S,
                    3,
                    36,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Legs {
        const DOF: usize = 3;
        const PARAMETERS: &'static [&'static str] = &["m", "w", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Legs {
                m: values[0],
                w: values[1],
                g: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.w, self.g]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<3> for Legs {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "torso",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "left_leg",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 12,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "right_leg",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 24,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[
            ::lagrange::__private::lagrange_core::animation::Link {
                from: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 1,
                    member: 0,
                },
                to: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 0,
                },
            },
            ::lagrange::__private::lagrange_core::animation::Link {
                from: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 2,
                    member: 0,
                },
                to: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 0,
                },
            },
        ];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 3],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[
                    __bodies.torso.position.x,
                    __bodies.torso.position.y,
                    __bodies.torso.position.z,
                    __bodies.torso.rotation.rows[0][0],
                    __bodies.torso.rotation.rows[1][0],
                    __bodies.torso.rotation.rows[2][0],
                    __bodies.torso.rotation.rows[0][1],
                    __bodies.torso.rotation.rows[1][1],
                    __bodies.torso.rotation.rows[2][1],
                    __bodies.torso.rotation.rows[0][2],
                    __bodies.torso.rotation.rows[1][2],
                    __bodies.torso.rotation.rows[2][2],
                    __bodies.left_leg.position.x,
                    __bodies.left_leg.position.y,
                    __bodies.left_leg.position.z,
                    __bodies.left_leg.rotation.rows[0][0],
                    __bodies.left_leg.rotation.rows[1][0],
                    __bodies.left_leg.rotation.rows[2][0],
                    __bodies.left_leg.rotation.rows[0][1],
                    __bodies.left_leg.rotation.rows[1][1],
                    __bodies.left_leg.rotation.rows[2][1],
                    __bodies.left_leg.rotation.rows[0][2],
                    __bodies.left_leg.rotation.rows[1][2],
                    __bodies.left_leg.rotation.rows[2][2],
                    __bodies.right_leg.position.x,
                    __bodies.right_leg.position.y,
                    __bodies.right_leg.position.z,
                    __bodies.right_leg.rotation.rows[0][0],
                    __bodies.right_leg.rotation.rows[1][0],
                    __bodies.right_leg.rotation.rows[2][0],
                    __bodies.right_leg.rotation.rows[0][1],
                    __bodies.right_leg.rotation.rows[1][1],
                    __bodies.right_leg.rotation.rows[2][1],
                    __bodies.right_leg.rotation.rows[0][2],
                    __bodies.right_leg.rotation.rows[1][2],
                    __bodies.right_leg.rotation.rows[2][2],
                ],
            );
        }
    }
    impl Legs {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 3]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [yaw, left, right] = *__q;
            let w: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[1]);
            let torso: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(<__D>::from(0.0), <__D>::from(0.0), <__D>::from(1.0)),
                    rot_z(yaw),
                )
            };
            let left_leg: ::lagrange::__private::geometry::Spatial<__D> = {
                let r = torso.rotation * rot_x(left);
                spatial(
                    torso.point(vec3(w, <__D>::from(0.0), -<__D>::from(0.3)))
                        + r
                            * vec3(
                                <__D>::from(0.0),
                                <__D>::from(0.0),
                                -<__D>::from(0.2),
                            ),
                    r,
                )
            };
            let right_leg: ::lagrange::__private::geometry::Spatial<__D> = {
                let r = torso.rotation * rot_x(right);
                spatial(
                    torso.point(vec3(-w, <__D>::from(0.0), -<__D>::from(0.3)))
                        + r
                            * vec3(
                                <__D>::from(0.0),
                                <__D>::from(0.0),
                                -<__D>::from(0.2),
                            ),
                    r,
                )
            };
            Bodies {
                torso,
                left_leg,
                right_leg,
            }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<3, 36, 3> for Legs {
        const PARAMETER_NAMES: [&'static str; 3] = ["m", "w", "g"];
        const SEEDABLE: [bool; 3] = [false, true, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m, self.w, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 3]) -> [__D; 36] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.torso.position.x,
                __bodies.torso.position.y,
                __bodies.torso.position.z,
                __bodies.torso.rotation.rows[0][0],
                __bodies.torso.rotation.rows[1][0],
                __bodies.torso.rotation.rows[2][0],
                __bodies.torso.rotation.rows[0][1],
                __bodies.torso.rotation.rows[1][1],
                __bodies.torso.rotation.rows[2][1],
                __bodies.torso.rotation.rows[0][2],
                __bodies.torso.rotation.rows[1][2],
                __bodies.torso.rotation.rows[2][2],
                __bodies.left_leg.position.x,
                __bodies.left_leg.position.y,
                __bodies.left_leg.position.z,
                __bodies.left_leg.rotation.rows[0][0],
                __bodies.left_leg.rotation.rows[1][0],
                __bodies.left_leg.rotation.rows[2][0],
                __bodies.left_leg.rotation.rows[0][1],
                __bodies.left_leg.rotation.rows[1][1],
                __bodies.left_leg.rotation.rows[2][1],
                __bodies.left_leg.rotation.rows[0][2],
                __bodies.left_leg.rotation.rows[1][2],
                __bodies.left_leg.rotation.rows[2][2],
                __bodies.right_leg.position.x,
                __bodies.right_leg.position.y,
                __bodies.right_leg.position.z,
                __bodies.right_leg.rotation.rows[0][0],
                __bodies.right_leg.rotation.rows[1][0],
                __bodies.right_leg.rotation.rows[2][0],
                __bodies.right_leg.rotation.rows[0][1],
                __bodies.right_leg.rotation.rows[1][1],
                __bodies.right_leg.rotation.rows[2][1],
                __bodies.right_leg.rotation.rows[0][2],
                __bodies.right_leg.rotation.rows[1][2],
                __bodies.right_leg.rotation.rows[2][2],
            ]
        }
    }
}
