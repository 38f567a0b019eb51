pub mod springs {
    pub struct Springs {
        pub m: f64,
        pub omega: f64,
        pub mu: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    pub struct Coords<T = f64> {
        pub q: [T; 2],
        pub x: T,
        pub y: T,
    }
    impl<
        T: ::lagrange::__private::core::default::Default,
    > ::lagrange::__private::core::default::Default for Coords<T> {
        fn default() -> Self {
            Coords {
                q: ::lagrange::__private::core::array::from_fn(|_| T::default()),
                x: T::default(),
                y: T::default(),
            }
        }
    }
    impl ::lagrange::__private::Coordinates<4> for Coords<f64> {
        const NAMES: [&'static str; 4] = ["q[0]", "q[1]", "x", "y"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 4] {
            [self.q[0], self.q[1], self.x, self.y]
        }
        #[inline(always)]
        fn from_array(values: [f64; 4]) -> Self {
            Coords {
                q: [values[0], values[1]],
                x: values[2],
                y: values[3],
            }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 4;
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
        pub mass: [::lagrange::__private::geometry::Vec2<T>; 2],
        pub planet: ::lagrange::__private::geometry::Vec2<T>,
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
        pub mass: [::lagrange::__private::geometry::Vec2<T>; 2],
        pub planet: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl Springs {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                4,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                4,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                4,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                4,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                4,
                6,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 4],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let q = [__q[0], __q[1]];
            let x = __q[2];
            let y = __q[3];
            let mass: [::lagrange::__private::geometry::Vec2<__D>; 2] = {
                let mut mass: [::lagrange::__private::geometry::Vec2<__D>; 2] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..2 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        vec2(q[i], <__D>::from(0.0))
                    };
                    mass[i] = __member;
                }
                mass
            };
            let planet: ::lagrange::__private::geometry::Vec2<__D> = { vec2(x, y) };
            Bodies { mass, planet }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 6],
        ) -> Bodies<__D> {
            Bodies {
                mass: [
                    ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
                    ::lagrange::__private::geometry::vec2(__x[2], __x[3]),
                ],
                planet: ::lagrange::__private::geometry::vec2(__x[4], __x[5]),
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 6],
            __x_dot: &[__D; 6],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                mass: [
                    ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                    ::lagrange::__private::geometry::vec2(__x_dot[2], __x_dot[3]),
                ],
                planet: ::lagrange::__private::geometry::vec2(__x_dot[4], __x_dot[5]),
            }
        }
    }
    impl Springs {}
    impl ::lagrange::__private::Model<4, 6> for Springs {
        type Coords = Coords;
        const INERTIAL: usize = 6;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 4]; 6] = [
            [true, false, false, false],
            [true, false, false, false],
            [false, true, false, false],
            [false, true, false, false],
            [false, false, true, false],
            [false, false, false, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m: f64 = self.m;
            let omega: f64 = self.omega;
            let mu: f64 = self.mu;
            let __mass_mass: f64 = m;
            let __mass_planet: f64 = m;
            ((0.0 + self.m + self.omega + self.mu + __mass_mass + __mass_planet) * 0.0
                == 0.0) & (__mass_mass > 0.0) & (__mass_planet > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<4, 6>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.omega.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "omega",
                    value: self.omega,
                });
            }
            if !self.mu.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "mu",
                    value: self.mu,
                });
            }
            let m: f64 = self.m;
            let omega: f64 = self.omega;
            let mu: f64 = self.mu;
            let __mass_mass: f64 = m;
            let __mass_planet: f64 = m;
            if !(__mass_mass.is_finite() && __mass_mass > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "mass",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_mass
                    ),
                });
            }
            if !(__mass_planet.is_finite() && __mass_planet > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "planet",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_planet
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 6] {
            let m: f64 = self.m;
            let omega: f64 = self.omega;
            let mu: f64 = self.mu;
            let __mass_mass: f64 = m;
            let __mass_planet: f64 = m;
            [
                __mass_mass,
                __mass_mass,
                __mass_mass,
                __mass_mass,
                __mass_planet,
                __mass_planet,
            ]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 4],
        ) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.mass[0].x,
                __bodies.mass[0].y,
                __bodies.mass[1].x,
                __bodies.mass[1].y,
                __bodies.planet.x,
                __bodies.planet.y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 4],
            __x: &[__D; 6],
        ) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let q = [__q[0], __q[1]];
            let x = __q[2];
            let y = __q[3];
            let m = <__D>::from(self.m);
            let omega = <__D>::from(self.omega);
            let mu = <__D>::from(self.mu);
            let __param_0: __D = <__D>::from({
                let omega: f64 = self.omega;
                omega * omega / 4.0
            });
            let __param_1: __D = <__D>::from({
                let m: f64 = self.m;
                let mu: f64 = self.mu;
                -mu * m
            });
            let Bodies { mass, planet } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_stiff: __D = { __param_0 * (q[1] - q[0]).powi(2) };
            __potential += __potential_stiff;
            let __potential_gravitation: __D = { __param_1 / planet.norm() };
            __potential += __potential_gravitation;
            __potential
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 4],
            __x: &[__S; 6],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 4>,
            >; 6],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 4>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                4,
            >::repeat(<__S>::from(-0.0));
            {
                let m: f64 = self.m;
                let omega: f64 = self.omega;
                let mu: f64 = self.mu;
                let __e6: __S = __q[2];
                let __e7: __S = __q[3];
                let __e8: f64 = omega;
                let __e9: f64 = __e8 * __e8;
                let __e11: f64 = __e9 / 4.0;
                let __e12: __S = __q[1];
                let __e13: __S = __q[0];
                let __e14: __S = __e12 - __e13;
                let __e23: f64 = __e11 * 2.0;
                let __e24: __S = __e14 * __e23;
                let __e36: f64 = mu;
                let __e38: f64 = m;
                let __e39: f64 = __e36 * __e38;
                let __e41: __S = __e6 * __e6;
                let __e42: __S = __e7 * __e7;
                let __e43: __S = __e41 + __e42;
                let __e44: __S = __e43.sqrt();
                let __e57: __S = __e43 * __e44;
                let __e59: __S = __e6 * __e39;
                let __e60: __S = __e59 / __e57;
                let __e69: __S = __e7 * __e39;
                let __e70: __S = __e69 / __e57;
                __gradient[0] -= __e24;
                __gradient[1] += __e24;
                __gradient[2] += __e60;
                __gradient[3] += __e70;
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn gradient_coefficients(
            &self,
            __scale: &[f64; 4],
        ) -> [f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS] {
            let mut __coefficients = [0.0; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS];
            let m: f64 = self.m;
            let omega: f64 = self.omega;
            let mu: f64 = self.mu;
            let __e8: f64 = omega;
            let __e9: f64 = __e8 * __e8;
            let __e11: f64 = __e9 / 4.0;
            let __e23: f64 = __e11 * 2.0;
            let __e36: f64 = mu;
            let __e38: f64 = m;
            let __e39: f64 = __e36 * __e38;
            let __e53: f64 = __scale[2];
            let __e55: f64 = __e53 * __e39;
            let __e64: f64 = __scale[3];
            let __e66: f64 = __e64 * __e39;
            __coefficients[0] = <f64>::from(__e23);
            __coefficients[1] = <f64>::from(__e55);
            __coefficients[2] = <f64>::from(__e66);
            __coefficients
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn scaled_potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 4],
            __x: &[__S; 6],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 4>,
            >; 6],
            __scale: &[f64; 4],
            __prepared: &[f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 4>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                4,
            >::repeat(<__S>::from(-0.0));
            {
                let m: f64 = self.m;
                let omega: f64 = self.omega;
                let mu: f64 = self.mu;
                let __e6: __S = __q[2];
                let __e7: __S = __q[3];
                let __e12: __S = __q[1];
                let __e13: __S = __q[0];
                let __e14: __S = __e12 - __e13;
                let __e23: f64 = __prepared[0];
                let __e24: __S = __e14 * __e23;
                let __e41: __S = __e6 * __e6;
                let __e42: __S = __e7 * __e7;
                let __e43: __S = __e41 + __e42;
                let __e44: __S = __e43.sqrt();
                let __e55: f64 = __prepared[1];
                let __e56: __S = __e6 * __e55;
                let __e57: __S = __e43 * __e44;
                let __e58: __S = __e56 / __e57;
                let __e66: f64 = __prepared[2];
                let __e67: __S = __e7 * __e66;
                let __e68: __S = __e67 / __e57;
                __gradient[0] -= __e24;
                __gradient[1] += __e24;
                __gradient[2] += __e58;
                __gradient[3] += __e68;
                __gradient[0] *= __scale[0];
                __gradient[1] *= __scale[1];
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
    }
    impl Springs {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_mass_0<__D: ::lagrange::__private::Scalar>(
            &self,
            i: usize,
            __t: __D,
            __q_at_i: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            { vec2(__q_at_i, <__D>::from(0.0)) }
        }
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_planet<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            x: __D,
            y: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            { vec2(x, y) }
        }
    }
    impl ::lagrange::__private::tree::Tree<4, 6, 2, 3> for Springs {
        const BODIES: [::lagrange::__private::tree::Body<2>; 3] = [
            ::lagrange::__private::tree::Body {
                row: 0,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [
                    ::lagrange::__private::tree::Seed::Coordinate(0),
                    ::lagrange::__private::tree::Seed::Unused,
                ],
            },
            ::lagrange::__private::tree::Body {
                row: 2,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [
                    ::lagrange::__private::tree::Seed::Coordinate(1),
                    ::lagrange::__private::tree::Seed::Unused,
                ],
            },
            ::lagrange::__private::tree::Body {
                row: 4,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [
                    ::lagrange::__private::tree::Seed::Coordinate(2),
                    ::lagrange::__private::tree::Seed::Coordinate(3),
                ],
            },
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn displacements<S: ::lagrange::__private::Scalar>(
            &self,
            __t: S,
            __q: &[S; 4],
            __v: &[S; 4],
        ) -> [::lagrange::__private::tree::Seeded<S, 2>; 6] {
            let __body_0 = self
                .__lagrange_displacement_mass_0(
                    0,
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[0], __v[0], 0),
                );
            let __body_1 = self
                .__lagrange_displacement_mass_0(
                    1,
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[1], __v[1], 0),
                );
            let __body_2 = self
                .__lagrange_displacement_planet(
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[2], __v[2], 0),
                    ::lagrange::__private::tree::seed(__q[3], __v[3], 1),
                );
            [__body_0.x, __body_0.y, __body_1.x, __body_1.y, __body_2.x, __body_2.y]
        }
        #[inline(always)]
        fn mass_matrix<S: ::lagrange::__private::Scalar>(
            __jacobian: &::lagrange::__private::tree::BodyJacobians<S, 2, 3>,
            __composite: &[f64; 3],
        ) -> ::lagrange::__private::nalgebra::SMatrix<S, 4, 4> {
            let mut __m = ::lagrange::__private::nalgebra::SMatrix::<S, 4, 4>::zeros();
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                4,
                6,
                2,
                3,
            >(&mut __m, __jacobian, __composite, 0, 0);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                4,
                6,
                2,
                3,
            >(&mut __m, __jacobian, __composite, 1, 1);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                4,
                6,
                2,
                3,
            >(&mut __m, __jacobian, __composite, 2, 2);
            __m
        }
    }
    impl ::lagrange::__private::Prepare for Springs {
        type Prepared = ::lagrange::__private::lagrange_core::affine::AffineConstants<
            4,
            6,
        >;
        const PREPARED_IN_ONE_BRANCH: bool = true;
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::lagrange_core::affine::AffineConstants::of::<
                Self,
            >(self)
        }
    }
    impl ::lagrange::__private::Dynamics<4> for Springs {
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
            <Self as ::lagrange::__private::Model<4, 6>>::validate(self)?;
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
            q: &[S; 4],
            v: &[S; 4],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 4> {
            let _prepared = __constants.prepared;
            ::lagrange::__private::tree::equations_of_motion::<
                Self,
                S,
                4,
                6,
                2,
                3,
            >(self, t, q, v)
        }
        #[inline]
        fn accelerations_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 4],
            v: &[S; 4],
        ) -> ::lagrange::__private::Result<[S; 4]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::accelerations::<
                        Self,
                        S,
                        4,
                        6,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    ::lagrange::__private::tree::accelerations::<
                        Self,
                        S,
                        4,
                        6,
                        2,
                        3,
                    >(self, t, q, v)
                }
            }
        }
        #[inline(always)]
        fn regular_accelerations_at(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: f64,
            q: &[f64; 4],
            v: &[f64; 4],
        ) -> ::lagrange::__private::core::option::Option<[f64; 4]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::regular_accelerations::<
                        Self,
                        4,
                        6,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    ::lagrange::__private::core::option::Option::None
                }
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
            q: &[S; 4],
            v: &[S; 4],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::kinetic_energy::<
                Self,
                S,
                4,
                6,
            >(self, t, q, v)
        }
        #[inline]
        fn potential_energy_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 4],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                4,
                6,
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
            q: &[f64; 4],
            v: &[f64; 4],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                4,
                6,
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
            q: &[S; 4],
            v: &[S; 4],
        ) -> [S; 4] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 4, 6>(self, t, q, v)
        }
        #[inline]
        fn canonical_field_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 4],
            v: &[S; 4],
        ) -> ([S; 4], [S; 4]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    Self,
                    S,
                    4,
                    6,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Springs {
        const DOF: usize = 4;
        const PARAMETERS: &'static [&'static str] = &["m", "omega", "mu"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Springs {
                m: values[0],
                omega: values[1],
                mu: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.omega, self.mu]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<4> for Springs {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "mass",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::Some(2),
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "planet",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 4,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 4],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[
                    __bodies.mass[0].x,
                    __bodies.mass[0].y,
                    __bodies.mass[1].x,
                    __bodies.mass[1].y,
                    __bodies.planet.x,
                    __bodies.planet.y,
                ],
            );
        }
    }
    impl Springs {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 4]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let q = [__q[0], __q[1]];
            let x = __q[2];
            let y = __q[3];
            let mass: [::lagrange::__private::geometry::Vec2<__D>; 2] = {
                let mut mass: [::lagrange::__private::geometry::Vec2<__D>; 2] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..2 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        vec2(q[i], <__D>::from(0.0))
                    };
                    mass[i] = __member;
                }
                mass
            };
            let planet: ::lagrange::__private::geometry::Vec2<__D> = { vec2(x, y) };
            Bodies { mass, planet }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<4, 6, 3> for Springs {
        const PARAMETER_NAMES: [&'static str; 3] = ["m", "omega", "mu"];
        const SEEDABLE: [bool; 3] = [false, true, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m, self.omega, self.mu]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 4]) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.mass[0].x,
                __bodies.mass[0].y,
                __bodies.mass[1].x,
                __bodies.mass[1].y,
                __bodies.planet.x,
                __bodies.planet.y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 4], __x: &[__D; 6]) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let q = [__q[0], __q[1]];
            let x = __q[2];
            let y = __q[3];
            let m: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[0]);
            let omega: __D = ::lagrange::__private::parameters::lift::<
                __S,
                __D,
            >(&__p[1]);
            let mu: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[2]);
            let Bodies { mass, planet } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_stiff: __D = {
                omega * omega / <__D>::from(4.0) * (q[1] - q[0]).powi(2)
            };
            __potential += __potential_stiff;
            let __potential_gravitation: __D = { -mu * m / planet.norm() };
            __potential += __potential_gravitation;
            __potential
        }
    }
}
