pub mod stretched {
    pub struct Stretched {
        pub m1: f64,
        pub m2: f64,
        pub k: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq,
        ::lagrange::__private::core::default::Default
    )]
    pub struct Coords<T = f64> {
        pub a: T,
        pub b: T,
    }
    impl ::lagrange::__private::Coordinates<2> for Coords<f64> {
        const NAMES: [&'static str; 2] = ["a", "b"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 2] {
            [self.a, self.b]
        }
        #[inline(always)]
        fn from_array(values: [f64; 2]) -> Self {
            Coords {
                a: values[0],
                b: values[1],
            }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 2;
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
        pub p: ::lagrange::__private::geometry::Vec2<T>,
        pub r: ::lagrange::__private::geometry::Vec2<T>,
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
        pub p: ::lagrange::__private::geometry::Vec2<T>,
        pub r: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl Stretched {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                2,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                2,
                4,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [a, b] = *__q;
            let p: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(<__D>::from(2.0) * a + <__D>::from(0.3), <__D>::from(0.0))
            };
            let r: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(<__D>::from(0.0), <__D>::from(3.0) * b)
            };
            Bodies { p, r }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 4],
        ) -> Bodies<__D> {
            Bodies {
                p: ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
                r: ::lagrange::__private::geometry::vec2(__x[2], __x[3]),
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 4],
            __x_dot: &[__D; 4],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                p: ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                r: ::lagrange::__private::geometry::vec2(__x_dot[2], __x_dot[3]),
            }
        }
    }
    impl Stretched {}
    impl ::lagrange::__private::Model<2, 4> for Stretched {
        type Coords = Coords;
        const INERTIAL: usize = 4;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 2]; 4] = [
            [true, false],
            [false, false],
            [false, false],
            [false, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let k: f64 = self.k;
            let __mass_p: f64 = m1;
            let __mass_r: f64 = m2;
            ((0.0 + self.m1 + self.m2 + self.k + __mass_p + __mass_r) * 0.0 == 0.0)
                & (__mass_p > 0.0) & (__mass_r > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<2, 4>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m1.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m1",
                    value: self.m1,
                });
            }
            if !self.m2.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m2",
                    value: self.m2,
                });
            }
            if !self.k.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "k",
                    value: self.k,
                });
            }
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let k: f64 = self.k;
            let __mass_p: f64 = m1;
            let __mass_r: f64 = m2;
            if !(__mass_p.is_finite() && __mass_p > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "p",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_p
                    ),
                });
            }
            if !(__mass_r.is_finite() && __mass_r > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "r",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_r
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 4] {
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let k: f64 = self.k;
            let __mass_p: f64 = m1;
            let __mass_r: f64 = m2;
            [__mass_p, __mass_p, __mass_r, __mass_r]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.p.x, __bodies.p.y, __bodies.r.x, __bodies.r.y]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __x: &[__D; 4],
        ) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [a, b] = *__q;
            let k = <__D>::from(self.k);
            let Bodies { p, r } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_spring: __D = {
                k * ((p - r).norm() - <__D>::from(1.0)).powi(2)
            };
            __potential += __potential_spring;
            let __potential_pin: __D = { k * a.powi(2) / <__D>::from(3.0) };
            __potential += __potential_pin;
            __potential
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 2],
            __x: &[__S; 4],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 2>,
            >; 4],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 2>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                2,
            >::repeat(<__S>::from(-0.0));
            {
                let m1: f64 = self.m1;
                let m2: f64 = self.m2;
                let k: f64 = self.k;
                let __e0: __S = __x[0];
                let __e3: __S = __x[3];
                let __e5: __S = __q[0];
                let __e13: f64 = k;
                let __e15: __S = __e0 * __e0;
                let __e16: __S = __e3 * __e3;
                let __e18: __S = __e15 + __e16;
                let __e19: __S = __e18.sqrt();
                let __e21: __S = __e19 - 1.0;
                let __e30: f64 = __e13 * 2.0;
                let __e31: __S = __e0 * __e30;
                let __e32: __S = __e31 * __e21;
                let __e33: __S = __e32 / __e19;
                let __e37: __S = __e3 * __e30;
                let __e38: __S = __e37 * __e21;
                let __e39: __S = __e38 / __e19;
                let __e50: f64 = __e30 / 3.0;
                let __e51: __S = __e5 * __e50;
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e33;
                    __gradient[0] += __dv * __row[0];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[3]
                {
                    let __dv: __S = __e39;
                    __gradient[1] += __dv * __row[1];
                }
                __gradient[0] += __e51;
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn gradient_coefficients(
            &self,
            __scale: &[f64; 2],
        ) -> [f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS] {
            let mut __coefficients = [0.0; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS];
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let k: f64 = self.k;
            let __e13: f64 = k;
            let __e30: f64 = __e13 * 2.0;
            let __e50: f64 = __e30 / 3.0;
            __coefficients[0] = <f64>::from(__e30);
            __coefficients[1] = <f64>::from(__e50);
            __coefficients
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn scaled_potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 2],
            __x: &[__S; 4],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 2>,
            >; 4],
            __scale: &[f64; 2],
            __prepared: &[f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 2>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                2,
            >::repeat(<__S>::from(-0.0));
            {
                let m1: f64 = self.m1;
                let m2: f64 = self.m2;
                let k: f64 = self.k;
                let __e0: __S = __x[0];
                let __e3: __S = __x[3];
                let __e5: __S = __q[0];
                let __e15: __S = __e0 * __e0;
                let __e16: __S = __e3 * __e3;
                let __e18: __S = __e15 + __e16;
                let __e19: __S = __e18.sqrt();
                let __e21: __S = __e19 - 1.0;
                let __e30: f64 = __prepared[0];
                let __e31: __S = __e0 * __e30;
                let __e32: __S = __e31 * __e21;
                let __e33: __S = __e32 / __e19;
                let __e37: __S = __e3 * __e30;
                let __e38: __S = __e37 * __e21;
                let __e39: __S = __e38 / __e19;
                let __e50: f64 = __prepared[1];
                let __e51: __S = __e5 * __e50;
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e33;
                    __gradient[0] += __dv * __row[0];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[3]
                {
                    let __dv: __S = __e39;
                    __gradient[1] += __dv * (__row[1] * __scale[1]);
                }
                __gradient[0] += __e51;
                __gradient[0] *= __scale[0];
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
    }
    impl Stretched {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_p<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            a: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            { vec2(<__D>::from(2.0) * a + <__D>::from(0.3), <__D>::from(0.0)) }
        }
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_r<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            b: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            { vec2(<__D>::from(0.0), <__D>::from(3.0) * b) }
        }
    }
    impl ::lagrange::__private::tree::Tree<2, 4, 1, 2> for Stretched {
        const BODIES: [::lagrange::__private::tree::Body<1>; 2] = [
            ::lagrange::__private::tree::Body {
                row: 0,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [::lagrange::__private::tree::Seed::Coordinate(0)],
            },
            ::lagrange::__private::tree::Body {
                row: 2,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [::lagrange::__private::tree::Seed::Coordinate(1)],
            },
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn displacements<S: ::lagrange::__private::Scalar>(
            &self,
            __t: S,
            __q: &[S; 2],
            __v: &[S; 2],
        ) -> [::lagrange::__private::tree::Seeded<S, 1>; 4] {
            let __body_0 = self
                .__lagrange_displacement_p(
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[0], __v[0], 0),
                );
            let __body_1 = self
                .__lagrange_displacement_r(
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[1], __v[1], 0),
                );
            [__body_0.x, __body_0.y, __body_1.x, __body_1.y]
        }
        #[inline(always)]
        fn mass_matrix<S: ::lagrange::__private::Scalar>(
            __jacobian: &::lagrange::__private::tree::BodyJacobians<S, 1, 2>,
            __composite: &[f64; 2],
        ) -> ::lagrange::__private::nalgebra::SMatrix<S, 2, 2> {
            let mut __m = ::lagrange::__private::nalgebra::SMatrix::<S, 2, 2>::zeros();
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                2,
                4,
                1,
                2,
            >(&mut __m, __jacobian, __composite, 0, 0);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                2,
                4,
                1,
                2,
            >(&mut __m, __jacobian, __composite, 1, 1);
            __m
        }
    }
    impl ::lagrange::__private::Prepare for Stretched {
        type Prepared = ::lagrange::__private::lagrange_core::affine::AffineConstants<
            2,
            4,
        >;
        const PREPARED_IN_ONE_BRANCH: bool = true;
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::lagrange_core::affine::AffineConstants::of::<
                Self,
            >(self)
        }
    }
    impl ::lagrange::__private::Dynamics<2> for Stretched {
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
            <Self as ::lagrange::__private::Model<2, 4>>::validate(self)?;
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
            q: &[S; 2],
            v: &[S; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 2> {
            let _prepared = __constants.prepared;
            ::lagrange::__private::tree::equations_of_motion::<
                Self,
                S,
                2,
                4,
                1,
                2,
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
            q: &[S; 2],
            v: &[S; 2],
        ) -> ::lagrange::__private::Result<[S; 2]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::accelerations::<
                        Self,
                        S,
                        2,
                        4,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    ::lagrange::__private::tree::accelerations::<
                        Self,
                        S,
                        2,
                        4,
                        1,
                        2,
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
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> ::lagrange::__private::core::option::Option<[f64; 2]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::regular_accelerations::<
                        Self,
                        2,
                        4,
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
            q: &[S; 2],
            v: &[S; 2],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::kinetic_energy::<
                Self,
                S,
                2,
                4,
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
            q: &[S; 2],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                2,
                4,
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
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                2,
                4,
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
            q: &[S; 2],
            v: &[S; 2],
        ) -> [S; 2] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 2, 4>(self, t, q, v)
        }
        #[inline]
        fn canonical_field_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> ([S; 2], [S; 2]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    Self,
                    S,
                    2,
                    4,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Stretched {
        const DOF: usize = 2;
        const PARAMETERS: &'static [&'static str] = &["m1", "m2", "k"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Stretched {
                m1: values[0],
                m2: values[1],
                k: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m1, self.m2, self.k]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<2> for Stretched {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "p",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "r",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 2,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 2],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[__bodies.p.x, __bodies.p.y, __bodies.r.x, __bodies.r.y],
            );
        }
    }
    impl Stretched {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 2]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [a, b] = *__q;
            let p: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(<__D>::from(2.0) * a + <__D>::from(0.3), <__D>::from(0.0))
            };
            let r: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(<__D>::from(0.0), <__D>::from(3.0) * b)
            };
            Bodies { p, r }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<2, 4, 3> for Stretched {
        const PARAMETER_NAMES: [&'static str; 3] = ["m1", "m2", "k"];
        const SEEDABLE: [bool; 3] = [false, false, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m1, self.m2, self.k]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 2]) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.p.x, __bodies.p.y, __bodies.r.x, __bodies.r.y]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 2], __x: &[__D; 4]) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [a, b] = *__q;
            let k: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[2]);
            let Bodies { p, r } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_spring: __D = {
                k * ((p - r).norm() - <__D>::from(1.0)).powi(2)
            };
            __potential += __potential_spring;
            let __potential_pin: __D = { k * a.powi(2) / <__D>::from(3.0) };
            __potential += __potential_pin;
            __potential
        }
    }
}
