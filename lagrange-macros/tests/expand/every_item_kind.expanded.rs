pub mod everything {
    use core::f64::consts::PI;
    const HALF: f64 = 0.5;
    pub struct Everything {
        pub m: f64,
        pub i: f64,
        pub k: f64,
        pub c: f64,
        pub tau: f64,
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
        pub theta: T,
        pub phi: T,
    }
    impl ::lagrange::__private::Coordinates<2> for Coords<f64> {
        const NAMES: [&'static str; 2] = ["theta", "phi"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 2] {
            [self.theta, self.phi]
        }
        #[inline(always)]
        fn from_array(values: [f64; 2]) -> Self {
            Coords {
                theta: values[0],
                phi: values[1],
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
        /// A bar on a pivot.
        pub bar: ::lagrange::__private::geometry::Planar<T>,
        pub tip: ::lagrange::__private::geometry::Vec2<T>,
        pub top: ::lagrange::__private::geometry::Spatial<T>,
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
        /// A bar on a pivot.
        pub bar: ::lagrange::__private::geometry::Planar<T>,
        pub tip: ::lagrange::__private::geometry::Vec2<T>,
        pub top: ::lagrange::__private::geometry::SpatialVelocity<T>,
    }
    impl Everything {
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
                17,
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
            let [theta, phi] = *__q;
            let (__sin_theta, __cos_theta) = theta.sin_cos();
            let bar: ::lagrange::__private::geometry::Planar<__D> = {
                planar(vec2(__sin_theta, -__cos_theta) * HALF, theta)
            };
            let tip: ::lagrange::__private::geometry::Vec2<__D> = {
                bar.point(vec2(<__D>::from(0.5), <__D>::from(0.0)))
            };
            let top: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(<__D>::from(0.0), <__D>::from(0.0), <__D>::from(1.0)),
                    rot_z(phi) * rot_x(PI * <__D>::from(0.1)),
                )
            };
            Bodies { bar, tip, top }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 17],
        ) -> Bodies<__D> {
            Bodies {
                bar: ::lagrange::__private::geometry::planar(
                    ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
                    __x[2],
                ),
                tip: ::lagrange::__private::geometry::vec2(__x[15], __x[16]),
                top: ::lagrange::__private::geometry::spatial(
                    ::lagrange::__private::geometry::vec3(__x[3], __x[4], __x[5]),
                    ::lagrange::__private::geometry::Rot3 {
                        rows: [
                            [__x[6], __x[9], __x[12]],
                            [__x[7], __x[10], __x[13]],
                            [__x[8], __x[11], __x[14]],
                        ],
                    },
                ),
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 17],
            __x_dot: &[__D; 17],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                bar: ::lagrange::__private::geometry::planar(
                    ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                    __x_dot[2],
                ),
                tip: ::lagrange::__private::geometry::vec2(__x_dot[15], __x_dot[16]),
                top: ::lagrange::__private::geometry::SpatialVelocity {
                    linear: ::lagrange::__private::geometry::vec3(
                        __x_dot[3],
                        __x_dot[4],
                        __x_dot[5],
                    ),
                    angular: ::lagrange::__private::geometry::angular_velocity(
                        [
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
                            ::lagrange::__private::geometry::vec3(
                                __x[12],
                                __x[13],
                                __x[14],
                            ),
                        ],
                        [
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
                            ::lagrange::__private::geometry::vec3(
                                __x_dot[12],
                                __x_dot[13],
                                __x_dot[14],
                            ),
                        ],
                    ),
                },
            }
        }
    }
    impl Everything {
        #[doc(hidden)]
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __potential_spring_0<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __x: &[__D; 17],
        ) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let k = <__D>::from(self.k);
            let Bodies { bar, tip, top } = self.__lagrange_bodies_from_cartesian(__x);
            let __value: __D = { k * phi.powf(2.0) * <__D>::from(0.5) };
            __value
        }
    }
    impl ::lagrange::__private::Model<2, 17> for Everything {
        type Coords = Coords;
        const INERTIAL: usize = 15;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = true;
        const HAS_FORCES: bool = true;
        const DEPENDS: [[bool; 2]; 17] = [
            [true, false],
            [true, false],
            [true, false],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [false, true],
            [true, false],
            [true, false],
        ];
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.i.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "i",
                    value: self.i,
                });
            }
            if !self.k.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "k",
                    value: self.k,
                });
            }
            if !self.c.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "c",
                    value: self.c,
                });
            }
            if !self.tau.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "tau",
                    value: self.tau,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let m: f64 = self.m;
            let i: f64 = self.i;
            let k: f64 = self.k;
            let c: f64 = self.c;
            let tau: f64 = self.tau;
            let g: f64 = self.g;
            let __mass_bar: f64 = m;
            let __inertia_bar: f64 = i;
            let __mass_top: f64 = m;
            let __inertia_top: [f64; 3] = [i, i, i * 1.5];
            if !(__mass_bar.is_finite() && __mass_bar > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bar",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_bar
                    ),
                });
            }
            if !(__inertia_bar.is_finite() && __inertia_bar > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bar",
                    reason: ::lagrange::__private::std::format!(
                        "moment of inertia must be positive and finite, got {}",
                        __inertia_bar
                    ),
                });
            }
            if !(__mass_top.is_finite() && __mass_top > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "top",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_top
                    ),
                });
            }
            let __sum: f64 = __inertia_top[0] + __inertia_top[1] + __inertia_top[2];
            for (__k, __moment) in __inertia_top.into_iter().enumerate() {
                if !(__moment.is_finite() && __moment > 0.0) {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "top",
                        reason: ::lagrange::__private::std::format!(
                            "principal moment I{} must be positive and finite, got {}",
                            __k + 1, __moment
                        ),
                    });
                }
                if __moment > __sum - __moment + 1e-12 * __sum {
                    return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                        body: "top",
                        reason: ::lagrange::__private::std::format!(
                            "principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                            __inertia_top, __k + 1
                        ),
                    });
                }
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 17] {
            let m: f64 = self.m;
            let i: f64 = self.i;
            let k: f64 = self.k;
            let c: f64 = self.c;
            let tau: f64 = self.tau;
            let g: f64 = self.g;
            let __mass_bar: f64 = m;
            let __inertia_bar: f64 = i;
            let __mass_top: f64 = m;
            let __inertia_top: [f64; 3] = [i, i, i * 1.5];
            [
                __mass_bar,
                __mass_bar,
                __inertia_bar,
                __mass_top,
                __mass_top,
                __mass_top,
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[0usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[0usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[0usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[1usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[1usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[1usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[2usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[2usize]),
                ((__inertia_top[0] + __inertia_top[1] + __inertia_top[2]) * 0.5
                    - __inertia_top[2usize]),
                0.0,
                0.0,
            ]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> [__D; 17] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [
                __bodies.bar.position.x,
                __bodies.bar.position.y,
                __bodies.bar.angle,
                __bodies.top.position.x,
                __bodies.top.position.y,
                __bodies.top.position.z,
                __bodies.top.rotation.rows[0][0],
                __bodies.top.rotation.rows[1][0],
                __bodies.top.rotation.rows[2][0],
                __bodies.top.rotation.rows[0][1],
                __bodies.top.rotation.rows[1][1],
                __bodies.top.rotation.rows[2][1],
                __bodies.top.rotation.rows[0][2],
                __bodies.top.rotation.rows[1][2],
                __bodies.top.rotation.rows[2][2],
                __bodies.tip.x,
                __bodies.tip.y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __x: &[__D; 17],
        ) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let k = <__D>::from(self.k);
            let Bodies { bar, tip, top } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_spring: __D = { k * phi.powf(2.0) * <__D>::from(0.5) };
            __potential += __potential_spring;
            __potential
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn potential_gradient<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 2],
            __x: &[__S; 17],
            __rows: &[::lagrange::__private::core::option::Option<
                ::lagrange::__private::nalgebra::SVector<__S, 2>,
            >; 17],
        ) -> ::lagrange::__private::core::option::Option<
            ::lagrange::__private::nalgebra::SVector<__S, 2>,
        > {
            let mut __gradient = ::lagrange::__private::nalgebra::SVector::<
                __S,
                2,
            >::repeat(<__S>::from(-0.0));
            {
                let __qn: [::lagrange::__private::num_dual::DualSVec<__S, 1>; 2] = [
                    <::lagrange::__private::num_dual::DualSVec<
                        __S,
                        1,
                    >>::from_re(__q[0usize]),
                    <::lagrange::__private::num_dual::DualSVec<
                        __S,
                        1,
                    >>::from_re(__q[1usize])
                        .derivative(0),
                ];
                let __xn: [::lagrange::__private::num_dual::DualSVec<__S, 1>; 17] = ::lagrange::__private::core::array::from_fn(|
                    __i|
                {
                    <::lagrange::__private::num_dual::DualSVec<
                        __S,
                        1,
                    >>::new(
                        __x[__i],
                        ::lagrange::__private::num_dual::Derivative::new(
                            __rows[__i]
                                .map(|__r| {
                                    ::lagrange::__private::nalgebra::SVector::<
                                        __S,
                                        1,
                                    >::from([__r[1]])
                                }),
                        ),
                    )
                });
                let __v = self
                    .__potential_spring_0(
                        <::lagrange::__private::num_dual::DualSVec<
                            __S,
                            1,
                        >>::from_re(__t),
                        &__qn,
                        &__xn,
                    );
                if let ::lagrange::__private::core::option::Option::Some(__g) = __v.eps.0
                {
                    __gradient[1] += __g[0];
                }
            }
            ::lagrange::__private::core::option::Option::Some(__gradient)
        }
        #[allow(unused_variables, clippy::all)]
        fn applied_forces<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __v: &[__D; 2],
            __x: &[__D; 17],
            __x_dot: &[__D; 17],
            __cartesian_force: &mut [__D; 17],
            __generalized_force: &mut [__D; 2],
        ) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let c = <__D>::from(self.c);
            let tau = <__D>::from(self.tau);
            let __param_0: __D = <__D>::from({
                let c: f64 = self.c;
                -c
            });
            let [theta_dot, phi_dot] = *__v;
            let __force_push: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(c, <__D>::from(0.0))
            };
            __cartesian_force[15] += __force_push.x;
            __cartesian_force[16] += __force_push.y;
            let __torque_motor: __D = { tau };
            __cartesian_force[2] += __torque_motor;
            let __generalized_force_damping: __D = { __param_0 * phi_dot };
            __generalized_force[1] += __generalized_force_damping;
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 17] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<2, 17>>::masses(self);
            let mut __weights = [0.0; 17];
            let __gravity_down: ::lagrange::__private::geometry::Vec3<f64> = {
                vec3(0.0, 0.0, -g)
            };
            __weights[3] += __gravity_down.x * __masses[3];
            __weights[4] += __gravity_down.y * __masses[4];
            __weights[5] += __gravity_down.z * __masses[5];
            let __gravity_plane_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_plane_down.x * __masses[0];
            __weights[1] += __gravity_plane_down.y * __masses[1];
            __weights
        }
    }
    impl ::lagrange::__private::Prepare for Everything {
        type Prepared = ();
        #[inline(always)]
        fn prepare(&self) -> ::lagrange::__private::Result<()> {
            ::lagrange::__private::core::result::Result::Ok(())
        }
    }
    impl ::lagrange::__private::Dynamics<2> for Everything {
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
            <Self as ::lagrange::__private::Model<2, 17>>::validate(self)?;
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
            ::lagrange::__private::dynamics::equations_of_motion::<
                Self,
                S,
                2,
                17,
            >(self, t, q, v)
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
                17,
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
                17,
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
                17,
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
            ::lagrange::__private::dynamics::momenta::<Self, S, 2, 17>(self, t, q, v)
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
                    17,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Everything {
        const DOF: usize = 2;
        const PARAMETERS: &'static [&'static str] = &["m", "i", "k", "c", "tau", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Everything {
                m: values[0],
                i: values[1],
                k: values[2],
                c: values[3],
                tau: values[4],
                g: values[5],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![
                self.m, self.i, self.k, self.c, self.tau, self.g
            ]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<2> for Everything {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "bar",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Planar,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "tip",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Point2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 15,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "top",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Spatial,
                count: ::lagrange::__private::core::option::Option::None,
                row: 3,
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
            q: &[f64; 2],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[
                    __bodies.bar.position.x,
                    __bodies.bar.position.y,
                    __bodies.bar.angle,
                    __bodies.tip.x,
                    __bodies.tip.y,
                    __bodies.top.position.x,
                    __bodies.top.position.y,
                    __bodies.top.position.z,
                    __bodies.top.rotation.rows[0][0],
                    __bodies.top.rotation.rows[1][0],
                    __bodies.top.rotation.rows[2][0],
                    __bodies.top.rotation.rows[0][1],
                    __bodies.top.rotation.rows[1][1],
                    __bodies.top.rotation.rows[2][1],
                    __bodies.top.rotation.rows[0][2],
                    __bodies.top.rotation.rows[1][2],
                    __bodies.top.rotation.rows[2][2],
                ],
            );
        }
    }
    impl Everything {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 6], __t: __D, __q: &[__D; 2]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let (__sin_theta, __cos_theta) = theta.sin_cos();
            let bar: ::lagrange::__private::geometry::Planar<__D> = {
                planar(vec2(__sin_theta, -__cos_theta) * HALF, theta)
            };
            let tip: ::lagrange::__private::geometry::Vec2<__D> = {
                bar.point(vec2(<__D>::from(0.5), <__D>::from(0.0)))
            };
            let top: ::lagrange::__private::geometry::Spatial<__D> = {
                spatial(
                    vec3(<__D>::from(0.0), <__D>::from(0.0), <__D>::from(1.0)),
                    rot_z(phi) * rot_x(PI * <__D>::from(0.1)),
                )
            };
            Bodies { bar, tip, top }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<2, 17, 6> for Everything {
        const PARAMETER_NAMES: [&'static str; 6] = ["m", "i", "k", "c", "tau", "g"];
        const SEEDABLE: [bool; 6] = [false, false, true, true, true, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 6] {
            [self.m, self.i, self.k, self.c, self.tau, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 6], __t: __D, __q: &[__D; 2]) -> [__D; 17] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [
                __bodies.bar.position.x,
                __bodies.bar.position.y,
                __bodies.bar.angle,
                __bodies.top.position.x,
                __bodies.top.position.y,
                __bodies.top.position.z,
                __bodies.top.rotation.rows[0][0],
                __bodies.top.rotation.rows[1][0],
                __bodies.top.rotation.rows[2][0],
                __bodies.top.rotation.rows[0][1],
                __bodies.top.rotation.rows[1][1],
                __bodies.top.rotation.rows[2][1],
                __bodies.top.rotation.rows[0][2],
                __bodies.top.rotation.rows[1][2],
                __bodies.top.rotation.rows[2][2],
                __bodies.tip.x,
                __bodies.tip.y,
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn potential_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 6], __t: __D, __q: &[__D; 2], __x: &[__D; 17]) -> __D {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let k: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[2]);
            let Bodies { bar, tip, top } = self.__lagrange_bodies_from_cartesian(__x);
            let mut __potential = <__D>::zero();
            let __potential_spring: __D = { k * phi.powf(2.0) * <__D>::from(0.5) };
            __potential += __potential_spring;
            __potential
        }
        #[allow(unused_variables, clippy::all)]
        fn applied_forces_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(
            &self,
            __p: &[__S; 6],
            __t: __D,
            __q: &[__D; 2],
            __v: &[__D; 2],
            __x: &[__D; 17],
            __x_dot: &[__D; 17],
            __cartesian_force: &mut [__D; 17],
            __generalized_force: &mut [__D; 2],
        ) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta, phi] = *__q;
            let c: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[3]);
            let tau: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[4]);
            let [theta_dot, phi_dot] = *__v;
            let __force_push: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(c, <__D>::from(0.0))
            };
            __cartesian_force[15] += __force_push.x;
            __cartesian_force[16] += __force_push.y;
            let __torque_motor: __D = { tau };
            __cartesian_force[2] += __torque_motor;
            let __generalized_force_damping: __D = { -c * phi_dot };
            __generalized_force[1] += __generalized_force_damping;
        }
    }
}
