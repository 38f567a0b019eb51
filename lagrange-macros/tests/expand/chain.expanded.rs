pub mod chain {
    pub const LINKS: usize = 3;
    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    pub struct Coords<T = f64> {
        pub theta: [T; LINKS],
    }
    impl<
        T: ::lagrange::__private::core::default::Default,
    > ::lagrange::__private::core::default::Default for Coords<T> {
        fn default() -> Self {
            Coords {
                theta: ::lagrange::__private::core::array::from_fn(|_| T::default()),
            }
        }
    }
    impl ::lagrange::__private::Coordinates<3> for Coords<f64> {
        const NAMES: [&'static str; 3] = ["theta[0]", "theta[1]", "theta[2]"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 3] {
            [self.theta[0], self.theta[1], self.theta[2]]
        }
        #[inline(always)]
        fn from_array(values: [f64; 3]) -> Self {
            Coords {
                theta: [values[0], values[1], values[2]],
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
        pub bob: [::lagrange::__private::geometry::Vec2<T>; 3],
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
        pub bob: [::lagrange::__private::geometry::Vec2<T>; 3],
    }
    impl Chain {
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
            let theta = [__q[0], __q[1], __q[2]];
            let l = <__D>::from(self.l);
            let __sin_cos_theta = theta.map(|__x| __x.sin_cos());
            let bob: [::lagrange::__private::geometry::Vec2<__D>; 3] = {
                let mut bob: [::lagrange::__private::geometry::Vec2<__D>; 3] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..3 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        let link = vec2(__sin_cos_theta[i].0, -__sin_cos_theta[i].1) * l;
                        if i == 0 { link } else { bob[i - 1] + link }
                    };
                    bob[i] = __member;
                }
                bob
            };
            Bodies { bob }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 6],
            __x_dot: &[__D; 6],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                bob: [
                    ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                    ::lagrange::__private::geometry::vec2(__x_dot[2], __x_dot[3]),
                    ::lagrange::__private::geometry::vec2(__x_dot[4], __x_dot[5]),
                ],
            }
        }
    }
    impl ::lagrange::__private::Model<3, 6> for Chain {
        type Coords = Coords;
        const INERTIAL: usize = 6;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 3]; 6] = [
            [true, false, false],
            [true, false, false],
            [true, true, false],
            [true, true, false],
            [true, true, true],
            [true, true, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let __mass_bob: f64 = m;
            ((0.0 + self.m + self.l + self.g + __mass_bob) * 0.0 == 0.0)
                & (__mass_bob > 0.0)
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
            if !self.l.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "l",
                    value: self.l,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let __mass_bob: f64 = m;
            if !(__mass_bob.is_finite() && __mass_bob > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bob",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_bob
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 6] {
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let __mass_bob: f64 = m;
            [__mass_bob, __mass_bob, __mass_bob, __mass_bob, __mass_bob, __mass_bob]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 3],
        ) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.bob[0].x,
                __bodies.bob[0].y,
                __bodies.bob[1].x,
                __bodies.bob[1].y,
                __bodies.bob[2].x,
                __bodies.bob[2].y,
            ]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 6] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<3, 6>>::masses(self);
            let mut __weights = [0.0; 6];
            let __gravity_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights[2] += __gravity_down.x * __masses[2];
            __weights[3] += __gravity_down.y * __masses[3];
            __weights[4] += __gravity_down.x * __masses[4];
            __weights[5] += __gravity_down.y * __masses[5];
            __weights
        }
    }
    impl Chain {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_displacement_bob_0<__D: ::lagrange::__private::Scalar>(
            &self,
            i: usize,
            __t: __D,
            __theta_at_i: __D,
        ) -> ::lagrange::__private::geometry::Vec2<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let l = <__D>::from(self.l);
            let (__sin___theta_at_i, __cos___theta_at_i) = __theta_at_i.sin_cos();
            {
                let link = vec2(__sin___theta_at_i, -__cos___theta_at_i) * l;
                link
            }
        }
    }
    impl ::lagrange::__private::tree::Tree<3, 6, 1, 3> for Chain {
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
                parent: ::lagrange::__private::core::option::Option::Some(0),
                seeds: [::lagrange::__private::tree::Seed::Coordinate(1)],
            },
            ::lagrange::__private::tree::Body {
                row: 4,
                dim: 2,
                parent: ::lagrange::__private::core::option::Option::Some(1),
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
                .__lagrange_displacement_bob_0(
                    0,
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[0], __v[0], 0),
                );
            let __body_1 = self
                .__lagrange_displacement_bob_0(
                    1,
                    ::lagrange::__private::tree::time(
                        __t,
                        ::lagrange::__private::core::option::Option::None,
                    ),
                    ::lagrange::__private::tree::seed(__q[1], __v[1], 0),
                );
            let __body_2 = self
                .__lagrange_displacement_bob_0(
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
            >(&mut __m, __jacobian, __composite, 1, 0);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 2, 2);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 2, 1);
            ::lagrange::__private::tree::couple::<
                Self,
                S,
                3,
                6,
                1,
                3,
            >(&mut __m, __jacobian, __composite, 2, 0);
            __m
        }
    }
    impl ::lagrange::__private::Prepare for Chain {
        type Prepared = ();
        #[inline(always)]
        fn prepare(&self) -> ::lagrange::__private::Result<()> {
            ::lagrange::__private::core::result::Result::Ok(())
        }
    }
    impl ::lagrange::__private::Dynamics<3> for Chain {
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
                    ::lagrange::__private::tree::accelerations::<
                        Self,
                        S,
                        3,
                        6,
                        1,
                        3,
                    >(self, t, q, v)
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
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Chain {
        const DOF: usize = 3;
        const PARAMETERS: &'static [&'static str] = &["m", "l", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Chain {
                m: values[0],
                l: values[1],
                g: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.l, self.g]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<3> for Chain {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "bob",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::Some(3),
                row: 0,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[
            ::lagrange::__private::lagrange_core::animation::Link {
                from: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 1,
                },
                to: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 0,
                },
            },
            ::lagrange::__private::lagrange_core::animation::Link {
                from: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 2,
                },
                to: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 1,
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
                    __bodies.bob[0].x,
                    __bodies.bob[0].y,
                    __bodies.bob[1].x,
                    __bodies.bob[1].y,
                    __bodies.bob[2].x,
                    __bodies.bob[2].y,
                ],
            );
        }
    }
    impl Chain {
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
            let theta = [__q[0], __q[1], __q[2]];
            let l: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[1]);
            let __sin_cos_theta = theta.map(|__x| __x.sin_cos());
            let bob: [::lagrange::__private::geometry::Vec2<__D>; 3] = {
                let mut bob: [::lagrange::__private::geometry::Vec2<__D>; 3] = ::lagrange::__private::core::array::from_fn(|
                    _|
                ::lagrange::__private::geometry::vec2(<__D>::zero(), <__D>::zero()));
                for i in 0..3 {
                    let __member: ::lagrange::__private::geometry::Vec2<__D> = {
                        let link = vec2(__sin_cos_theta[i].0, -__sin_cos_theta[i].1) * l;
                        if i == 0 { link } else { bob[i - 1] + link }
                    };
                    bob[i] = __member;
                }
                bob
            };
            Bodies { bob }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<3, 6, 3> for Chain {
        const PARAMETER_NAMES: [&'static str; 3] = ["m", "l", "g"];
        const SEEDABLE: [bool; 3] = [false, true, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m, self.l, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 3]) -> [__D; 6] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.bob[0].x,
                __bodies.bob[0].y,
                __bodies.bob[1].x,
                __bodies.bob[1].y,
                __bodies.bob[2].x,
                __bodies.bob[2].y,
            ]
        }
    }
}
