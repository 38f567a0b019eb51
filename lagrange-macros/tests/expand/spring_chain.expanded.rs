pub mod spring_chain {
    pub const MASSES: usize = 3;
    pub struct SpringChain {
        pub m: f64,
        pub k_wall: f64,
        pub k: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    pub struct Coords<T = f64> {
        pub x: [T; MASSES],
    }
    impl<
        T: ::lagrange::__private::core::default::Default,
    > ::lagrange::__private::core::default::Default for Coords<T> {
        fn default() -> Self {
            Coords {
                x: ::lagrange::__private::core::array::from_fn(|_| T::default()),
            }
        }
    }
    impl ::lagrange::__private::Coordinates<3> for Coords<f64> {
        const NAMES: [&'static str; 3] = ["x[0]", "x[1]", "x[2]"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 3] {
            [self.x[0], self.x[1], self.x[2]]
        }
        #[inline(always)]
        fn from_array(values: [f64; 3]) -> Self {
            Coords {
                x: [values[0], values[1], values[2]],
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
        pub mass: [::lagrange::__private::geometry::Vec2<T>; 3],
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
        pub mass: [::lagrange::__private::geometry::Vec2<T>; 3],
    }
    impl SpringChain {
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
                6,
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
            let x = [__q[0], __q[1], __q[2]];
            let mass: [::lagrange::__private::geometry::Vec2<__D>; 3] = {
                let mut mass: [::lagrange::__private::geometry::Vec2<__D>; 3] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..3 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        vec2(x[i], <__D>::from(0.0))
                    };
                    mass[i] = __member;
                }
                mass
            };
            Bodies { mass }
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
                    ::lagrange::__private::geometry::vec2(__x[4], __x[5]),
                ],
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
                    ::lagrange::__private::geometry::vec2(__x_dot[4], __x_dot[5]),
                ],
            }
        }
    }
    impl SpringChain {}
    impl ::lagrange::__private::Model<3, 6> for SpringChain {
        type Coords = Coords;
        const INERTIAL: usize = 6;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 3]; 6] = [
            [true, false, false],
            [true, false, false],
            [false, true, false],
            [false, true, false],
            [false, false, true],
            [false, false, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m: f64 = self.m;
            let k_wall: f64 = self.k_wall;
            let k: f64 = self.k;
            let __mass_mass: f64 = m;
            ((0.0 + self.m + self.k_wall + self.k + __mass_mass) * 0.0 == 0.0)
                & (__mass_mass > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<3, 6>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.k_wall.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "k_wall",
                    value: self.k_wall,
                });
            }
            if !self.k.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "k",
                    value: self.k,
                });
            }
            let m: f64 = self.m;
            let k_wall: f64 = self.k_wall;
            let k: f64 = self.k;
            let __mass_mass: f64 = m;
            if !(__mass_mass.is_finite() && __mass_mass > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "mass",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_mass
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 6] {
            let m: f64 = self.m;
            let k_wall: f64 = self.k_wall;
            let k: f64 = self.k;
            let __mass_mass: f64 = m;
            [
                __mass_mass,
                __mass_mass,
                __mass_mass,
                __mass_mass,
                __mass_mass,
                __mass_mass,
            ]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 3],
        ) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.mass[0].x,
                __bodies.mass[0].y,
                __bodies.mass[1].x,
                __bodies.mass[1].y,
                __bodies.mass[2].x,
                __bodies.mass[2].y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 3],
            __x: &[__D; 6],
        ) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let x = [__q[0], __q[1], __q[2]];
            let k_wall = <__D>::from(self.k_wall);
            let k = <__D>::from(self.k);
            let __param_0: __D = <__D>::from({
                let k_wall: f64 = self.k_wall;
                0.5 * k_wall
            });
            let __param_1: __D = <__D>::from({
                let k: f64 = self.k;
                0.5 * k
            });
            let Bodies { mass } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_springs: __D = {
                let d1 = mass[1].x - mass[0].x;
                let d2 = mass[2].x - mass[1].x;
                __param_0 * mass[0].x * mass[0].x + __param_1 * (d1 * d1 + d2 * d2)
            };
            __potential += __potential_springs;
            __potential
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 3],
            __x: &[__S; 6],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 3>,
            >; 6],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 3>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                3,
            >::repeat(<__S>::from(-0.0));
            {
                let m: f64 = self.m;
                let k_wall: f64 = self.k_wall;
                let k: f64 = self.k;
                let __e0: __S = __x[0];
                let __e2: __S = __x[2];
                let __e4: __S = __x[4];
                let __e6: __S = __e2 - __e0;
                let __e7: __S = __e4 - __e2;
                let __e9: f64 = k_wall;
                let __e10: f64 = 0.5 * __e9;
                let __e11: __S = __e0 * __e10;
                let __e15: __S = __e11 + __e11;
                let __e16: f64 = k;
                let __e17: f64 = 0.5 * __e16;
                let __e24: f64 = __e17 * 2.0;
                let __e25: __S = __e6 * __e24;
                let __e31: __S = __e7 * __e24;
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e15;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e25;
                    __gradient[0] -= __dv * __row[0];
                    __gradient[1] -= __dv * __row[1];
                    __gradient[2] -= __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[2]
                {
                    let __dv: __S = __e25;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[2]
                {
                    let __dv: __S = __e31;
                    __gradient[0] -= __dv * __row[0];
                    __gradient[1] -= __dv * __row[1];
                    __gradient[2] -= __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[4]
                {
                    let __dv: __S = __e31;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn gradient_coefficients(
            &self,
            __scale: &[f64; 3],
        ) -> [f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS] {
            let mut __coefficients = [0.0; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS];
            let m: f64 = self.m;
            let k_wall: f64 = self.k_wall;
            let k: f64 = self.k;
            let __e9: f64 = k_wall;
            let __e10: f64 = 0.5 * __e9;
            let __e16: f64 = k;
            let __e17: f64 = 0.5 * __e16;
            let __e24: f64 = __e17 * 2.0;
            __coefficients[0] = <f64>::from(__e10);
            __coefficients[1] = <f64>::from(__e24);
            __coefficients
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn scaled_potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 3],
            __x: &[__S; 6],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 3>,
            >; 6],
            __scale: &[f64; 3],
            __prepared: &[f64; ::lagrange::__private::lagrange_core::model::GRADIENT_COEFFICIENTS],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 3>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                3,
            >::repeat(<__S>::from(-0.0));
            {
                let m: f64 = self.m;
                let k_wall: f64 = self.k_wall;
                let k: f64 = self.k;
                let __e0: __S = __x[0];
                let __e2: __S = __x[2];
                let __e4: __S = __x[4];
                let __e6: __S = __e2 - __e0;
                let __e7: __S = __e4 - __e2;
                let __e10: f64 = __prepared[0];
                let __e11: __S = __e0 * __e10;
                let __e15: __S = __e11 + __e11;
                let __e24: f64 = __prepared[1];
                let __e25: __S = __e6 * __e24;
                let __e31: __S = __e7 * __e24;
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e15;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[0]
                {
                    let __dv: __S = __e25;
                    __gradient[0] -= __dv * __row[0];
                    __gradient[1] -= __dv * __row[1];
                    __gradient[2] -= __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[2]
                {
                    let __dv: __S = __e25;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[2]
                {
                    let __dv: __S = __e31;
                    __gradient[0] -= __dv * __row[0];
                    __gradient[1] -= __dv * __row[1];
                    __gradient[2] -= __dv * __row[2];
                }
                if let ::lagrange::__private::core::option::Option::Some(__row) = &__rows[4]
                {
                    let __dv: __S = __e31;
                    __gradient[0] += __dv * __row[0];
                    __gradient[1] += __dv * __row[1];
                    __gradient[2] += __dv * __row[2];
                }
                __gradient[0] *= __scale[0];
                __gradient[1] *= __scale[1];
                __gradient[2] *= __scale[2];
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
    }
    impl SpringChain {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_mass_0<__D: ::lagrange::__private::Scalar>(
            &self,
            i: usize,
            __t: __D,
            __x_at_i: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            { vec2(__x_at_i, <__D>::from(0.0)) }
        }
    }
    impl ::lagrange::__private::tree::Tree<3, 6, 1, 3> for SpringChain {
        const BODIES: [::lagrange::__private::tree::Body<1>; 3] = [
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
            ::lagrange::__private::tree::Body {
                row: 4,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::None,
                seeds: [::lagrange::__private::tree::Seed::Coordinate(2)],
            },
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn displacements<S: ::lagrange::__private::Scalar>(
            &self,
            __t: S,
            __q: &[S; 3],
            __v: &[S; 3],
        ) -> [::lagrange::__private::tree::Seeded<S, 1>; 6] {
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
                .__lagrange_displacement_mass_0(
                    2,
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[2], __v[2], 0),
                );
            [__body_0.x, __body_0.y, __body_1.x, __body_1.y, __body_2.x, __body_2.y]
        }
        #[inline(always)]
        fn mass_matrix<S: ::lagrange::__private::Scalar>(
            __jacobian: &::lagrange::__private::tree::BodyJacobians<S, 1, 3>,
            __composite: &[f64; 3],
        ) -> ::lagrange::__private::nalgebra::SMatrix<S, 3, 3> {
            let mut __m = ::lagrange::__private::nalgebra::SMatrix::<S, 3, 3>::zeros();
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 0, 0);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 1, 1);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 2, 2);
            __m
        }
    }
    impl ::lagrange::__private::Prepare for SpringChain {
        type Prepared = ::lagrange::__private::lagrange_core::affine::AffineConstants<
            3,
            6,
        >;
        const PREPARED_IN_ONE_BRANCH: bool = true;
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::lagrange_core::affine::AffineConstants::of::<
                Self,
            >(self)
        }
    }
    impl ::lagrange::__private::Dynamics<3> for SpringChain {
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
            <Self as ::lagrange::__private::Model<3, 6>>::validate(self)?;
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
            let _prepared = __constants.prepared;
            ::lagrange::__private::tree::equations_of_motion::<
                Self,
                S,
                3,
                6,
                1,
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
            q: &[S; 3],
            v: &[S; 3],
        ) -> ::lagrange::__private::Result<[S; 3]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::accelerations::<
                        Self,
                        S,
                        3,
                        6,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    ::lagrange::__private::tree::accelerations::<
                        Self,
                        S,
                        3,
                        6,
                        1,
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
            q: &[f64; 3],
            v: &[f64; 3],
        ) -> ::lagrange::__private::core::option::Option<[f64; 3]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::regular_accelerations::<
                        Self,
                        3,
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
            q: &[S; 3],
            v: &[S; 3],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::kinetic_energy::<
                Self,
                S,
                3,
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
            q: &[S; 3],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                3,
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
            q: &[f64; 3],
            v: &[f64; 3],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                3,
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
            q: &[S; 3],
            v: &[S; 3],
        ) -> [S; 3] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 3, 6>(self, t, q, v)
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
                    6,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for SpringChain {
        const DOF: usize = 3;
        const PARAMETERS: &'static [&'static str] = &["m", "k_wall", "k"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(SpringChain {
                m: values[0],
                k_wall: values[1],
                k: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.k_wall, self.k]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<3> for SpringChain {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "mass",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::Some(3),
                row: 0,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[];
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
                    __bodies.mass[0].x,
                    __bodies.mass[0].y,
                    __bodies.mass[1].x,
                    __bodies.mass[1].y,
                    __bodies.mass[2].x,
                    __bodies.mass[2].y,
                ],
            );
        }
    }
    impl SpringChain {
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
            let x = [__q[0], __q[1], __q[2]];
            let mass: [::lagrange::__private::geometry::Vec2<__D>; 3] = {
                let mut mass: [::lagrange::__private::geometry::Vec2<__D>; 3] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..3 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        vec2(x[i], <__D>::from(0.0))
                    };
                    mass[i] = __member;
                }
                mass
            };
            Bodies { mass }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<3, 6, 3> for SpringChain {
        const PARAMETER_NAMES: [&'static str; 3] = ["m", "k_wall", "k"];
        const SEEDABLE: [bool; 3] = [false, true, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m, self.k_wall, self.k]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 3]) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.mass[0].x,
                __bodies.mass[0].y,
                __bodies.mass[1].x,
                __bodies.mass[1].y,
                __bodies.mass[2].x,
                __bodies.mass[2].y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 3], __x: &[__D; 6]) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let x = [__q[0], __q[1], __q[2]];
            let k_wall: __D = ::lagrange::__private::parameters::lift::<
                __S,
                __D,
            >(&__p[1]);
            let k: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[2]);
            let Bodies { mass } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_springs: __D = {
                let d1 = mass[1].x - mass[0].x;
                let d2 = mass[2].x - mass[1].x;
                <__D>::from(0.5) * k_wall * mass[0].x * mass[0].x
                    + <__D>::from(0.5) * k * (d1 * d1 + d2 * d2)
            };
            __potential += __potential_springs;
            __potential
        }
    }
}
