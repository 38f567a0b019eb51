pub mod floating {
    pub struct Floating {
        pub m: f64,
        pub g: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    pub struct Coords<T = f64> {
        pub base_position: [T; 3],
        pub base_rotation: [T; 3],
        pub q: T,
    }
    impl<
        T: ::lagrange::__private::core::default::Default,
    > ::lagrange::__private::core::default::Default for Coords<T> {
        fn default() -> Self {
            Coords {
                base_position: ::lagrange::__private::core::array::from_fn(|_| T::default()),
                base_rotation: ::lagrange::__private::core::array::from_fn(|_| T::default()),
                q: T::default(),
            }
        }
    }
    impl ::lagrange::__private::Coordinates<7> for Coords<f64> {
        const NAMES: [&'static str; 7] = [
            "base_position[0]",
            "base_position[1]",
            "base_position[2]",
            "base_rotation[0]",
            "base_rotation[1]",
            "base_rotation[2]",
            "q",
        ];
        #[inline(always)]
        fn to_array(&self) -> [f64; 7] {
            [
                self.base_position[0],
                self.base_position[1],
                self.base_position[2],
                self.base_rotation[0],
                self.base_rotation[1],
                self.base_rotation[2],
                self.q,
            ]
        }
        #[inline(always)]
        fn from_array(values: [f64; 7]) -> Self {
            Coords {
                base_position: [values[0], values[1], values[2]],
                base_rotation: [values[3], values[4], values[5]],
                q: values[6],
            }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 7;
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
        pub base: ::lagrange::__private::geometry::Spatial<T>,
        pub leg: ::lagrange::__private::geometry::Spatial<T>,
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
        pub base: ::lagrange::__private::geometry::SpatialVelocity<T>,
        pub leg: ::lagrange::__private::geometry::SpatialVelocity<T>,
    }
    impl Floating {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                7,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                7,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                7,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                7,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                7,
                24,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 7],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let base_position = [__q[0], __q[1], __q[2]];
            let base_rotation = [__q[3], __q[4], __q[5]];
            let q = __q[6];
            let base: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(base_position[0], base_position[1], base_position[2]),
                    rot_mrp(vec3(base_rotation[0], base_rotation[1], base_rotation[2])),
                )
            };
            let leg: ::lagrange::__private::geometry::Spatial<__D> = {
                base.joint(
                    vec3(<__D>::from(0.2), <__D>::from(0.0), -<__D>::from(0.1)),
                    rot_y(q),
                )
            };
            Bodies { base, leg }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 24],
            __x_dot: &[__D; 24],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                base: ::lagrange::__private::geometry::SpatialVelocity {
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
                leg: ::lagrange::__private::geometry::SpatialVelocity {
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
            }
        }
    }
    impl ::lagrange::__private::Model<7, 24> for Floating {
        type Coords = Coords;
        const INERTIAL: usize = 24;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 7]; 24] = [
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, false],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
            [true, true, true, true, true, true, true],
        ];
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let m: f64 = self.m;
            let g: f64 = self.g;
            let __mass_base: f64 = m;
            let __inertia_base: [f64; 3] = [0.3, 0.2, 0.1];
            let __mass_leg: f64 = 0.5;
            let __inertia_leg: [f64; 3] = [0.01, 0.01, 0.002];
            if !(__mass_base.is_finite() && __mass_base > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "base",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_base
                    ),
                });
            }
            let __sum: f64 = __inertia_base[0] + __inertia_base[1] + __inertia_base[2];
            for (__k, __moment) in __inertia_base.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "base",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "base",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_base, __k + 1
                        ),
                    });
                }
            }
            if !(__mass_leg.is_finite() && __mass_leg > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "leg",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_leg
                    ),
                });
            }
            let __sum: f64 = __inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2];
            for (__k, __moment) in __inertia_leg.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "leg",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_leg, __k + 1
                        ),
                    });
                }
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 24] {
            let m: f64 = self.m;
            let g: f64 = self.g;
            let __mass_base: f64 = m;
            let __inertia_base: [f64; 3] = [0.3, 0.2, 0.1];
            let __mass_leg: f64 = 0.5;
            let __inertia_leg: [f64; 3] = [0.01, 0.01, 0.002];
            [
                __mass_base,
                __mass_base,
                __mass_base,
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[0usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[0usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[0usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[1usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[1usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[1usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[2usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[2usize]),
                ((__inertia_base[0] + __inertia_base[1] + __inertia_base[2]) * 0.5
                    - __inertia_base[2usize]),
                __mass_leg,
                __mass_leg,
                __mass_leg,
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[0usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[0usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[0usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[1usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[1usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[1usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[2usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[2usize]),
                ((__inertia_leg[0] + __inertia_leg[1] + __inertia_leg[2]) * 0.5
                    - __inertia_leg[2usize]),
            ]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 7],
        ) -> [__D; 24] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.base.position.x,
                __bodies.base.position.y,
                __bodies.base.position.z,
                __bodies.base.rotation.rows[0][0],
                __bodies.base.rotation.rows[1][0],
                __bodies.base.rotation.rows[2][0],
                __bodies.base.rotation.rows[0][1],
                __bodies.base.rotation.rows[1][1],
                __bodies.base.rotation.rows[2][1],
                __bodies.base.rotation.rows[0][2],
                __bodies.base.rotation.rows[1][2],
                __bodies.base.rotation.rows[2][2],
                __bodies.leg.position.x,
                __bodies.leg.position.y,
                __bodies.leg.position.z,
                __bodies.leg.rotation.rows[0][0],
                __bodies.leg.rotation.rows[1][0],
                __bodies.leg.rotation.rows[2][0],
                __bodies.leg.rotation.rows[0][1],
                __bodies.leg.rotation.rows[1][1],
                __bodies.leg.rotation.rows[2][1],
                __bodies.leg.rotation.rows[0][2],
                __bodies.leg.rotation.rows[1][2],
                __bodies.leg.rotation.rows[2][2],
            ]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 24] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<7, 24>>::masses(self);
            let mut __weights = [0.0; 24];
            let __gravity_down: ::lagrange::__private::geometry::Vec3<f64> = {
                vec3(0.0, 0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights[2] += __gravity_down.z * __masses[2];
            __weights[12] += __gravity_down.x * __masses[12];
            __weights[13] += __gravity_down.y * __masses[13];
            __weights[14] += __gravity_down.z * __masses[14];
            __weights
        }
    }
    impl ::lagrange::__private::tree::rigid::RigidTree<7, 2> for Floating {
        const JOINTS: [::lagrange::__private::tree::rigid::Joint; 2] = [
            ::lagrange::__private::tree::rigid::Joint {
                parent: ::lagrange::__private::core::option::Option::None,
                kind: ::lagrange::__private::tree::rigid::JointKind::Free(
                    ::lagrange::__private::lagrange_core::geometry::RotationChart::Mrp,
                    ::lagrange::__private::tree::rigid::Velocities::ChartRates,
                ),
                coordinate: 0,
                rotated: false,
                offset: [false, false, false],
            },
            ::lagrange::__private::tree::rigid::Joint {
                parent: ::lagrange::__private::core::option::Option::Some(0),
                kind: ::lagrange::__private::tree::rigid::JointKind::Revolute(
                    ::lagrange::__private::tree::rigid::spatial::Axis::Y,
                ),
                coordinate: 6,
                rotated: false,
                offset: [true, false, true],
            },
        ];
    }
    impl Floating {
        #[allow(unused_variables, unused_parens, clippy::all)]
        fn __lagrange_rigid_constants(
            &self,
        ) -> ::lagrange::__private::tree::rigid::RigidConstants<2> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let m: f64 = self.m;
            let g: f64 = self.g;
            let __after_0: Rot3<f64> = (Rot3::<f64>::identity());
            let __own_0: Vec3<f64> = (Vec3::<f64>::zero());
            let __body_0 = {
                let __rotation: Rot3<f64> = Rot3::<f64>::identity()
                    * (Rot3::<f64>::identity());
                let __offset: Vec3<f64> = Rot3::<f64>::identity()
                    * (Vec3::<f64>::zero());
                let __mass: f64 = m;
                let __tensor: [[f64; 3]; 3] = ::lagrange::__private::tree::rigid::turned_tensor(
                    &__after_0,
                    ::lagrange::__private::tree::rigid::diagonal([0.3, 0.2, 0.1]),
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
            let __own_1: Vec3<f64> = (Vec3::<f64>::zero());
            let __body_1 = {
                let __rotation: Rot3<f64> = __after_0 * (Rot3::<f64>::identity());
                let __offset: Vec3<f64> = __own_0
                    + __after_0
                        * (Vec3::<f64>::zero()
                            + (Rot3::<f64>::identity()) * vec3((0.2), (0.0), (-(0.1))));
                let __mass: f64 = 0.5;
                let __tensor: [[f64; 3]; 3] = ::lagrange::__private::tree::rigid::turned_tensor(
                    &__after_1,
                    ::lagrange::__private::tree::rigid::diagonal([0.01, 0.01, 0.002]),
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
            ::lagrange::__private::tree::rigid::RigidConstants {
                bodies: [__body_0, __body_1],
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
            __ws: &mut ::lagrange::__private::tree::rigid::Articulated<S, 2>,
            __joints: &[::lagrange::__private::tree::rigid::Joint; 2],
            __k: &::lagrange::__private::tree::rigid::RigidConstants<2>,
            (__q, __v, __tau): (&[S; 7], &[S; 7], &[S; 7]),
            __qdd: &mut [S; 7],
        ) -> ::lagrange::__private::core::result::Result<
            (),
            ::lagrange::__private::tree::rigid::Pivot,
        > {
            __ws.velocity::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[0]
                            .code()
                    },
                    7,
                >(__joints, __k, __q, __v, 0);
            __ws.velocity::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[1]
                            .code()
                    },
                    7,
                >(__joints, __k, __q, __v, 1);
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws
                .articulate::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[1]
                            .code()
                    },
                    7,
                >(__joints, __k, __tau, 1)
            {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws
                .articulate::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[0]
                            .code()
                    },
                    7,
                >(__joints, __k, __tau, 0)
            {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
            __ws.accelerate::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[0]
                            .code()
                    },
                    7,
                >(__joints, __k, __qdd, 0);
            __ws.accelerate::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[1]
                            .code()
                    },
                    7,
                >(__joints, __k, __qdd, 1);
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_accelerations<
            S: ::lagrange::__private::Scalar,
            __F: ::lagrange::__private::Model<7, 24>,
        >(
            &self,
            __forces: &__F,
            __k: &::lagrange::__private::tree::rigid::RigidConstants<2>,
            __t: S,
            __q: &[S; 7],
            __v: &[S; 7],
        ) -> ::lagrange::__private::Result<[S; 7]> {
            let __joints = &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                7,
                2,
            >>::JOINTS;
            let __tau: [S; 7] = ::lagrange::__private::tree::rigid::other_generalized_forces::<
                __F,
                S,
                7,
                24,
                2,
            >(__forces, __joints, __t, __q, __v)
                .into();
            let mut __ws = ::lagrange::__private::tree::rigid::Articulated::<
                S,
                2,
            >::new();
            let mut __qdd = [<S as ::lagrange::__private::core::convert::From<
                f64,
            >>::from(0.0); 7];
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
                        7,
                        2,
                    >(__joints, __pivot, __t, __q),
                );
            }
            ::lagrange::__private::tree::rigid::finished::<Coords, S, 7>(__qdd, __t, __q)
        }
        /// The two sweeps; neither fails (the chunks' `Result` is for the sweeps that can).
        #[inline(always)]
        #[allow(clippy::all)]
        fn __lagrange_rigid_newton_euler<S: ::lagrange::__private::Scalar>(
            &self,
            __ws: &mut ::lagrange::__private::tree::rigid::NewtonEuler<S, 2>,
            __joints: &[::lagrange::__private::tree::rigid::Joint; 2],
            __k: &::lagrange::__private::tree::rigid::RigidConstants<2>,
            __state: (&[S; 7], &[S; 7], &[S; 7]),
            __tau: &mut [S; 7],
        ) -> ::lagrange::__private::core::result::Result<
            (),
            ::lagrange::__private::tree::rigid::Pivot,
        > {
            __ws.forward::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[0]
                            .code()
                    },
                    7,
                >(__joints, __k, __state, 0);
            __ws.forward::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[1]
                            .code()
                    },
                    7,
                >(__joints, __k, __state, 1);
            __ws.backward::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[1]
                            .code()
                    },
                    7,
                >(__joints, __k, __tau, 1);
            __ws.backward::<
                    {
                        <Floating as ::lagrange::__private::tree::rigid::RigidTree<
                            7,
                            2,
                        >>::JOINTS[0]
                            .code()
                    },
                    7,
                >(__joints, __k, __tau, 0);
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_inverse_dynamics<
            S: ::lagrange::__private::Scalar,
            __F: ::lagrange::__private::Model<7, 24>,
        >(
            &self,
            __forces: &__F,
            __k: &::lagrange::__private::tree::rigid::RigidConstants<2>,
            __t: S,
            __q: &[S; 7],
            __v: &[S; 7],
            __qdd: &[S; 7],
        ) -> [S; 7] {
            let __joints = &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                7,
                2,
            >>::JOINTS;
            let mut __ws = ::lagrange::__private::tree::rigid::NewtonEuler::<
                S,
                2,
            >::new();
            let mut __tau = [<S as ::lagrange::__private::core::convert::From<
                f64,
            >>::from(0.0); 7];
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
                7,
                24,
                2,
            >(__forces, __joints, __tau, __t, __q, __v)
        }
    }
    impl ::lagrange::__private::Prepare for Floating {
        type Prepared = ::lagrange::__private::tree::rigid::RigidConstants<2>;
        #[inline]
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::core::result::Result::Ok(
                self.__lagrange_rigid_constants(),
            )
        }
    }
    impl ::lagrange::__private::Dynamics<7> for Floating {
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
            <Self as ::lagrange::__private::Model<7, 24>>::validate(self)?;
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
            q: &[S; 7],
            v: &[S; 7],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 7> {
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
                    7,
                    24,
                    2,
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
            q: &[S; 7],
        ) -> ::lagrange::__private::nalgebra::SMatrix<S, 7, 7> {
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
                    7,
                    2,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        7,
                        2,
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
            q: &[S; 7],
            v: &[S; 7],
        ) -> ::lagrange::__private::Result<[S; 7]> {
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
            q: &[S; 7],
            v: &[S; 7],
            a: &[S; 7],
        ) -> [S; 7] {
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
            q: &[S; 7],
            v: &[S; 7],
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
                    7,
                    2,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        7,
                        2,
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
            q: &[S; 7],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                7,
                24,
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
            q: &[f64; 7],
            v: &[f64; 7],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                7,
                24,
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
            q: &[S; 7],
            v: &[S; 7],
        ) -> [S; 7] {
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
                    7,
                    2,
                >(
                    &<Self as ::lagrange::__private::tree::rigid::RigidTree<
                        7,
                        2,
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
            q: &[S; 7],
            v: &[S; 7],
        ) -> ([S; 7], [S; 7]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    Self,
                    S,
                    7,
                    24,
                >(self, t, q, v)
            }
        }
        #[inline]
        fn switch_charts<S: ::lagrange::__private::Scalar>(
            &self,
            q: &mut [S; 7],
            v: &mut [S; 7],
        ) -> bool {
            false
                | ::lagrange::__private::lagrange_core::geometry::switch_chart(
                    ::lagrange::__private::lagrange_core::geometry::RotationChart::Mrp,
                    [3, 4, 5],
                    q,
                    v,
                )
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Floating {
        const DOF: usize = 7;
        const PARAMETERS: &'static [&'static str] = &["m", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Floating {
                m: values[0],
                g: values[1],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.g]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<7> for Floating {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "base",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "leg",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 12,
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
        ];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 7],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[
                    __bodies.base.position.x,
                    __bodies.base.position.y,
                    __bodies.base.position.z,
                    __bodies.base.rotation.rows[0][0],
                    __bodies.base.rotation.rows[1][0],
                    __bodies.base.rotation.rows[2][0],
                    __bodies.base.rotation.rows[0][1],
                    __bodies.base.rotation.rows[1][1],
                    __bodies.base.rotation.rows[2][1],
                    __bodies.base.rotation.rows[0][2],
                    __bodies.base.rotation.rows[1][2],
                    __bodies.base.rotation.rows[2][2],
                    __bodies.leg.position.x,
                    __bodies.leg.position.y,
                    __bodies.leg.position.z,
                    __bodies.leg.rotation.rows[0][0],
                    __bodies.leg.rotation.rows[1][0],
                    __bodies.leg.rotation.rows[2][0],
                    __bodies.leg.rotation.rows[0][1],
                    __bodies.leg.rotation.rows[1][1],
                    __bodies.leg.rotation.rows[2][1],
                    __bodies.leg.rotation.rows[0][2],
                    __bodies.leg.rotation.rows[1][2],
                    __bodies.leg.rotation.rows[2][2],
                ],
            );
        }
    }
    impl Floating {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 2], __t: __D, __q: &[__D; 7]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let base_position = [__q[0], __q[1], __q[2]];
            let base_rotation = [__q[3], __q[4], __q[5]];
            let q = __q[6];
            let base: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(base_position[0], base_position[1], base_position[2]),
                    rot_mrp(vec3(base_rotation[0], base_rotation[1], base_rotation[2])),
                )
            };
            let leg: ::lagrange::__private::geometry::Spatial<__D> = {
                base.joint(
                    vec3(<__D>::from(0.2), <__D>::from(0.0), -<__D>::from(0.1)),
                    rot_y(q),
                )
            };
            Bodies { base, leg }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<7, 24, 2> for Floating {
        const PARAMETER_NAMES: [&'static str; 2] = ["m", "g"];
        const SEEDABLE: [bool; 2] = [false, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 2] {
            [self.m, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 2], __t: __D, __q: &[__D; 7]) -> [__D; 24] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.base.position.x,
                __bodies.base.position.y,
                __bodies.base.position.z,
                __bodies.base.rotation.rows[0][0],
                __bodies.base.rotation.rows[1][0],
                __bodies.base.rotation.rows[2][0],
                __bodies.base.rotation.rows[0][1],
                __bodies.base.rotation.rows[1][1],
                __bodies.base.rotation.rows[2][1],
                __bodies.base.rotation.rows[0][2],
                __bodies.base.rotation.rows[1][2],
                __bodies.base.rotation.rows[2][2],
                __bodies.leg.position.x,
                __bodies.leg.position.y,
                __bodies.leg.position.z,
                __bodies.leg.rotation.rows[0][0],
                __bodies.leg.rotation.rows[1][0],
                __bodies.leg.rotation.rows[2][0],
                __bodies.leg.rotation.rows[0][1],
                __bodies.leg.rotation.rows[1][1],
                __bodies.leg.rotation.rows[2][1],
                __bodies.leg.rotation.rows[0][2],
                __bodies.leg.rotation.rows[1][2],
                __bodies.leg.rotation.rows[2][2],
            ]
        }
    }
}
