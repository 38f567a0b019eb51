pub mod wedge_block {
    pub struct WedgeBlock {
        pub big_m: f64,
        pub m: f64,
        pub alpha: f64,
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
        pub x: T,
        pub d: T,
    }
    impl ::lagrange::__private::Coordinates<2> for Coords<f64> {
        const NAMES: [&'static str; 2] = ["x", "d"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 2] {
            [self.x, self.d]
        }
        #[inline(always)]
        fn from_array(values: [f64; 2]) -> Self {
            Coords {
                x: values[0],
                d: values[1],
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
        pub wedge: ::lagrange::__private::geometry::Vec2<T>,
        pub block: ::lagrange::__private::geometry::Vec2<T>,
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
        pub wedge: ::lagrange::__private::geometry::Vec2<T>,
        pub block: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl WedgeBlock {
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
            let [x, d] = *__q;
            let alpha = <__D>::from(self.alpha);
            let __param_0: __D = <__D>::from({
                let alpha: f64 = self.alpha;
                alpha.cos()
            });
            let __param_1: __D = <__D>::from({
                let alpha: f64 = self.alpha;
                alpha.sin()
            });
            let wedge: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(x, <__D>::from(0.0))
            };
            let block: ::lagrange::__private::geometry::Vec2<__D> = {
                wedge + vec2(d * __param_0, -d * __param_1)
            };
            Bodies { wedge, block }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 4],
            __x_dot: &[__D; 4],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                wedge: ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                block: ::lagrange::__private::geometry::vec2(__x_dot[2], __x_dot[3]),
            }
        }
    }
    impl ::lagrange::__private::Model<2, 4> for WedgeBlock {
        type Coords = Coords;
        const INERTIAL: usize = 4;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 2]; 4] = [
            [true, false],
            [false, false],
            [true, true],
            [true, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let big_m: f64 = self.big_m;
            let m: f64 = self.m;
            let alpha: f64 = self.alpha;
            let g: f64 = self.g;
            let __mass_wedge: f64 = big_m;
            let __mass_block: f64 = m;
            ((0.0 + self.big_m + self.m + self.alpha + self.g + __mass_wedge
                + __mass_block) * 0.0 == 0.0) & (__mass_wedge > 0.0)
                & (__mass_block > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<2, 4>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.big_m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "big_m",
                    value: self.big_m,
                });
            }
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.alpha.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "alpha",
                    value: self.alpha,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let big_m: f64 = self.big_m;
            let m: f64 = self.m;
            let alpha: f64 = self.alpha;
            let g: f64 = self.g;
            let __mass_wedge: f64 = big_m;
            let __mass_block: f64 = m;
            if !(__mass_wedge.is_finite() && __mass_wedge > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "wedge",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_wedge
                    ),
                });
            }
            if !(__mass_block.is_finite() && __mass_block > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "block",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_block
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 4] {
            let big_m: f64 = self.big_m;
            let m: f64 = self.m;
            let alpha: f64 = self.alpha;
            let g: f64 = self.g;
            let __mass_wedge: f64 = big_m;
            let __mass_block: f64 = m;
            [__mass_wedge, __mass_wedge, __mass_block, __mass_block]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.wedge.x, __bodies.wedge.y, __bodies.block.x, __bodies.block.y]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 4] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<2, 4>>::masses(self);
            let mut __weights = [0.0; 4];
            let __gravity_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights[2] += __gravity_down.x * __masses[2];
            __weights[3] += __gravity_down.y * __masses[3];
            __weights
        }
    }
    impl WedgeBlock {
        /// The constant factors of the closed-form equations of motion.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_coefficients(&self) -> [f64; 4] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let big_m: f64 = self.big_m;
            let m: f64 = self.m;
            let alpha: f64 = self.alpha;
            let g: f64 = self.g;
            let __constant_0: f64 = alpha.cos();
            let __constant_1: f64 = alpha.sin();
            let __masses = <Self as ::lagrange::__private::Model<2, 4>>::masses(self);
            [
                __masses[0] + __masses[2],
                __constant_0 * __masses[2],
                __constant_0 * __constant_0 * __masses[2]
                    + __constant_1 * __constant_1 * __masses[2],
                g * __constant_1 * __masses[2],
            ]
        }
        #[inline(always)]
        fn __lagrange_closed_form<__D: ::lagrange::__private::Scalar>(
            &self,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<__D, 2> {
            self.__lagrange_closed_form_with(
                ::lagrange::__private::core::option::Option::None,
                __q,
                __v,
            )
        }
        /// With the coefficients prepared (`Some`) or computed here (`None`), after the sines
        /// and cosines: values computed before those calls would be kept on the stack across
        /// them.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_closed_form_with<__D: ::lagrange::__private::Scalar>(
            &self,
            __prepared: ::lagrange::__private::core::option::Option<&[f64; 4]>,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<__D, 2> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let __computed: [f64; 4];
            let __k: &[f64; 4] = match __prepared {
                ::lagrange::__private::core::option::Option::Some(__k) => __k,
                ::lagrange::__private::core::option::Option::None => {
                    __computed = self.__lagrange_coefficients();
                    &__computed
                }
            };
            ::lagrange::__private::dynamics::EquationsOfMotion::from_columns(
                [
                    [<__D>::from(__k[0]), <__D>::from(__k[1])],
                    [<__D>::from(__k[1]), <__D>::from(__k[2])],
                ],
                [<__D>::from(0.0), <__D>::from(__k[3])],
                [<__D>::from(0.0), <__D>::from(0.0)],
            )
        }
        /// The canonical field (p, ṗ) = (M q̇, ∂T/∂q + 𝓕), with the coefficients prepared
        /// (`Some`) or computed here (`None`).
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_canonical_field_with<__D: ::lagrange::__private::Scalar>(
            &self,
            __prepared: ::lagrange::__private::core::option::Option<&[f64; 4]>,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ([__D; 2], [__D; 2]) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let __computed: [f64; 4];
            let __k: &[f64; 4] = match __prepared {
                ::lagrange::__private::core::option::Option::Some(__k) => __k,
                ::lagrange::__private::core::option::Option::None => {
                    __computed = self.__lagrange_coefficients();
                    &__computed
                }
            };
            (
                [
                    __v[0] * <__D>::from(__k[0]) + __v[1] * <__D>::from(__k[1]),
                    __v[0] * <__D>::from(__k[1]) + __v[1] * <__D>::from(__k[2]),
                ],
                [<__D>::from(0.0), <__D>::from(__k[3])],
            )
        }
    }
    impl ::lagrange::__private::Prepare for WedgeBlock {
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
    impl ::lagrange::__private::Dynamics<2> for WedgeBlock {
        type Coords = Coords;
        type Contacts = ::lagrange::__private::lagrange_core::constraints::NoContacts;
        const CONSTRAINT_COUNTS: ::lagrange::__private::core::option::Option<
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts,
        > = ::lagrange::__private::core::option::Option::Some(
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts::NONE,
        );
        const SCLERONOMIC: bool = true;
        const CLOSED_FORM: bool = true;
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
            self.__lagrange_closed_form::<S>(q, v)
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
                    let eom = <Self as ::lagrange::__private::Dynamics<
                        2,
                    >>::equations_of_motion_at(
                        self,
                        ::lagrange::__private::lagrange_core::evaluation::Constants::NONE
                            .with_inputs(__constants.inputs),
                        t,
                        q,
                        v,
                    );
                    ::lagrange::__private::dynamics::solve_accelerations::<
                        Coords,
                        S,
                        2,
                    >(&eom, t, q)
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
                    let eom = self.__lagrange_closed_form::<f64>(q, v);
                    let parameters_pass = <Self as ::lagrange::__private::Model<
                        2,
                        4,
                    >>::parameters_pass(self);
                    ::lagrange::__private::dynamics::regular_accelerations::<
                        2,
                    >(&eom, t, q, v, parameters_pass)
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
            self.__lagrange_canonical_field_with::<
                    S,
                >(::lagrange::__private::core::option::Option::None, q, v)
                .0
        }
        #[inline(always)]
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
                self.__lagrange_canonical_field_with::<
                        S,
                    >(::lagrange::__private::core::option::Option::None, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for WedgeBlock {
        const DOF: usize = 2;
        const PARAMETERS: &'static [&'static str] = &["big_m", "m", "alpha", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(WedgeBlock {
                big_m: values[0],
                m: values[1],
                alpha: values[2],
                g: values[3],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.big_m, self.m, self.alpha, self.g]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<2> for WedgeBlock {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "wedge",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "block",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 2,
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
                &[__bodies.wedge.x, __bodies.wedge.y, __bodies.block.x, __bodies.block.y],
            );
        }
    }
    impl WedgeBlock {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 4], __t: __D, __q: &[__D; 2]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [x, d] = *__q;
            let alpha: __D = ::lagrange::__private::parameters::lift::<
                __S,
                __D,
            >(&__p[2]);
            let wedge: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(x, <__D>::from(0.0))
            };
            let block: ::lagrange::__private::geometry::Vec2<__D> = {
                wedge + vec2(d * alpha.cos(), -d * alpha.sin())
            };
            Bodies { wedge, block }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<2, 4, 4> for WedgeBlock {
        const PARAMETER_NAMES: [&'static str; 4] = ["big_m", "m", "alpha", "g"];
        const SEEDABLE: [bool; 4] = [false, false, true, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 4] {
            [self.big_m, self.m, self.alpha, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 4], __t: __D, __q: &[__D; 2]) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.wedge.x, __bodies.wedge.y, __bodies.block.x, __bodies.block.y]
        }
    }
}
