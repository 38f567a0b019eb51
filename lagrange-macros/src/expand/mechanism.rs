//! The `Mechanism` impl, and the hooks it overrides when the mechanism is constrained.

use super::{lit, private};
use proc_macro2::{Ident, TokenStream};
use quote::quote;

/// How `equations_of_motion_at` forms M, 𝓕 and b.
pub(super) enum Equations {
    /// The straight-line code of `expand::closed_form`, with its number of coefficients (what a
    /// validated handle prepares).
    ClosedForm(usize),
    /// `lagrange_core::tree` over a tree of translations (seed width, bodies).
    Tree(usize, usize),
    /// `lagrange_core::tree::rigid` over a kinematic tree of rigid bodies (bodies).
    Rigid(usize),
    /// The dual-number passes of `lagrange_core::dynamics`.
    Dense,
}

/// Whether the positions are affine in the coordinates (`crate::affine`), so a validated handle
/// prepares J and the factors of M.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Positions {
    Affine {
        /// q̈ from the prepared constants is straight-line code that runs no user code: no force
        /// is declared, every potential's gradient is derived on its expression tree
        /// (`Model::potential_gradient`), and every constraint is holonomic with derivatives
        /// derived on its tree (`expand::constraints::written_holonomic`). Then `accelerations`
        /// through the handle checks a call in one branch (`lagrange_core::affine::regular_accelerations`,
        /// `lagrange_core::constraints::regular_accelerations_prepared`).
        straight_line: bool,
    },
    General,
}

/// The `Mechanism` impl, forwarding to `lagrange_core::dynamics`.
pub(super) fn mechanism_impl(
    params: &Ident,
    n: usize,
    k: usize,
    constrained: Option<usize>,
    equations: Equations,
    rheonomic: bool,
    positions: Positions,
) -> TokenStream {
    let (p, n, k) = (private(), lit(n), lit(k));
    let prepared = match (positions, &equations) {
        (Positions::Affine { straight_line }, _) => Prepared::Affine { straight_line },
        (_, Equations::ClosedForm(count)) => Prepared::Coefficients(*count),
        (_, Equations::Rigid(b)) => Prepared::Rigid(*b),
        _ => Prepared::Nothing,
    };
    let prepare = prepare_impl(params, &n, &k, prepared);
    // A call on the plain mechanism with equations in closed form: the coefficients computed
    // here, the parameters' test joining the call's one branch (a handle checked them once).
    let plain_closed_form_call = quote! {
        #[inline(always)]
        fn regular_accelerations_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::core::option::Option<[f64; #n]> {
            let eom = self.__lagrange_closed_form::<f64>(q, v);
            let parameters_pass = <Self as #p::Model<#n, #k>>::parameters_pass(self);
            #p::dynamics::regular_accelerations::<#n>(&eom, t, q, v, parameters_pass)
        }
    };
    // Through a validated handle, q̈ uses the constants prepared once: an affine mechanism's J and
    // factors of M, the closed form's coefficients.
    let prepared_accelerations = match prepared {
        Prepared::Affine { straight_line } => {
            // A constrained mechanism starts its Schur solve from the same constants.
            let body = match constrained {
                Some(c) => {
                    let c = lit(c);
                    quote!(#p::lagrange_core::constraints::accelerations_prepared::<Self, S, #n, #k, #c>(self, prepared, t, q, v))
                }
                None => {
                    quote!(#p::lagrange_core::affine::accelerations::<Self, S, #n, #k>(self, prepared, t, q, v))
                }
            };
            // Affine positions in closed form as well (a uniform field the only force): a call
            // on the plain mechanism, which prepares nothing, takes the closed form's one branch.
            let closed_form = matches!(equations, Equations::ClosedForm(_));
            let closed_form_call = closed_form.then(|| plain_closed_form_call.clone());
            // Through a validated handle, with its prepared constants: in one branch where q̈ is
            // then straight-line code, otherwise (the hook's `None`) down the checked path.
            let prepared_call = if straight_line {
                match constrained {
                    Some(c) => {
                        let c = lit(c);
                        quote!(#p::lagrange_core::constraints::regular_accelerations_prepared::<Self, #n, #k, #c>(self, prepared, t, q, v))
                    }
                    None => {
                        quote!(#p::lagrange_core::affine::regular_accelerations::<Self, #n, #k>(self, prepared, t, q, v))
                    }
                }
            } else {
                quote!({
                    let _ = (prepared, t, q, v);
                    #p::core::option::Option::None
                })
            };
            let regular = (straight_line || closed_form).then(|| {
                quote! {
                    #[inline(always)]
                    fn regular_accelerations_prepared_at(&self, prepared: &Self::Prepared, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::core::option::Option<[f64; #n]> {
                        #prepared_call
                    }
                }
            });
            // The projection after a step from the same constants.
            let project = constrained.map(|c| {
                let c = lit(c);
                quote! {
                    fn project_prepared(&self, prepared: &Self::Prepared, t: f64, q: &mut [f64; #n], v: &mut [f64; #n]) -> #p::Result<()> {
                        #p::lagrange_core::constraints::project_prepared::<Self, #n, #k, #c>(self, prepared, t, q, v)
                    }
                }
            });
            Some(quote! {
                #[inline]
                fn accelerations_prepared_at<S: #p::Scalar>(&self, prepared: &Self::Prepared, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
                    #body
                }
                #closed_form_call
                #regular
                #project
            })
        }
        // Straight-line code: `accelerations` checks a call in one branch.
        Prepared::Coefficients(_) => Some(quote! {
            #[inline]
            fn accelerations_prepared_at<S: #p::Scalar>(&self, prepared: &Self::Prepared, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
                let eom = self.__lagrange_closed_form_with::<S>(#p::core::option::Option::Some(prepared), q, v);
                #p::dynamics::solve_accelerations::<Coords, S, #n>(&eom, t, q)
            }
            #plain_closed_form_call
            #[inline(always)]
            fn regular_accelerations_prepared_at(&self, prepared: &Self::Prepared, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::core::option::Option<[f64; #n]> {
                let eom = self.__lagrange_closed_form_with::<f64>(#p::core::option::Option::Some(prepared), q, v);
                #p::dynamics::regular_accelerations::<#n>(&eom, t, q, v, true)
            }
        }),
        Prepared::Rigid(_) => Some(rigid_prepared_calls(n.clone())),
        Prepared::Nothing => None,
    };
    let scleronomic = !rheonomic;
    // The canonical field (and the momenta) in closed form, with the prepared coefficients through
    // a handle; otherwise a scleronomic mechanism's from one hyper-dual pass.
    let canonical = match (&equations, prepared) {
        (Equations::ClosedForm(_), _) => {
            let field = quote!(self.__lagrange_canonical_field_with::<S>);
            let none = quote!(#p::core::option::Option::None);
            let prepared_field = matches!(prepared, Prepared::Coefficients(_)).then(|| quote! {
                #[inline(always)]
                fn canonical_field_prepared_at<S: #p::Scalar>(&self, prepared: &Self::Prepared, t: S, q: &[S; #n], v: &[S; #n]) -> ([S; #n], [S; #n]) {
                    #field(#p::core::option::Option::Some(prepared), q, v)
                }
            });
            Some(quote! {
                #[inline(always)]
                fn canonical_field_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> ([S; #n], [S; #n]) {
                    #field(#none, q, v)
                }
                #prepared_field
            })
        }
        _ => (!rheonomic).then(|| {
            quote! {
                #[inline]
                fn canonical_field_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> ([S; #n], [S; #n]) {
                    #p::dynamics::canonical_field::<Self, S, #n, #k>(self, t, q, v)
                }
            }
        }),
    };
    let rigid = |call: TokenStream| match equations {
        Equations::Rigid(b) => {
            let b = lit(b);
            Some(quote!({
                let __k = self.__lagrange_rigid_constants();
                #p::tree::rigid::#call::<S, #n, #b>(&<Self as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS, &__k, q, v)
            }))
        }
        _ => None,
    };
    let kinetic = rigid(quote!(kinetic_energy))
        .unwrap_or_else(|| quote!(#p::dynamics::kinetic_energy::<Self, S, #n, #k>(self, t, q, v)));
    let momenta = match equations {
        Equations::ClosedForm(_) => quote! {
            self.__lagrange_canonical_field_with::<S>(#p::core::option::Option::None, q, v).0
        },
        Equations::Rigid(_) => rigid(quote!(momenta)).expect("a rigid tree"),
        _ => quote!(#p::dynamics::momenta::<Self, S, #n, #k>(self, t, q, v)),
    };
    let closed_form = matches!(equations, Equations::ClosedForm(_));
    let equations_of_motion = match equations {
        Equations::ClosedForm(_) => quote!(self.__lagrange_closed_form::<S>(q, v)),
        Equations::Tree(w, b) => {
            let (w, b) = (lit(w), lit(b));
            quote!(#p::tree::equations_of_motion::<Self, S, #n, #k, #w, #b>(self, t, q, v))
        }
        Equations::Rigid(b) => {
            let b = lit(b);
            quote!(#p::tree::rigid::equations_of_motion::<Self, S, #n, #k, #b>(self, &self.__lagrange_rigid_constants(), t, q, v))
        }
        Equations::Dense => {
            quote!(#p::dynamics::equations_of_motion::<Self, S, #n, #k>(self, t, q, v))
        }
    };
    let overrides = constrained.map(|c| constrained_overrides(n.clone(), k.clone(), lit(c)));
    // A tree's q̈ by the articulated-body recursion where each coordinate moves one body.
    let tree_accelerations = match (&equations, constrained) {
        (Equations::Tree(w, b), None) => {
            let (w, b) = (lit(*w), lit(*b));
            Some(quote! {
                #[inline]
                fn accelerations_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
                    #p::tree::accelerations::<Self, S, #n, #k, #w, #b>(self, t, q, v)
                }
            })
        }
        // The constants computed for the call: a validated handle prepares them once.
        (Equations::Rigid(_), None) => Some(quote! {
            #[inline]
            fn accelerations_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
                self.__lagrange_rigid_accelerations(&self.__lagrange_rigid_constants(), t, q, v)
            }
            #[inline]
            fn inverse_dynamics_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n], qdd: &[S; #n]) -> [S; #n] {
                self.__lagrange_rigid_inverse_dynamics(&self.__lagrange_rigid_constants(), t, q, v, qdd)
            }
        }),
        _ => None,
    };
    let validate_constraints = constrained.map(|c| {
        let c = lit(c);
        quote!(<Self as #p::lagrange_core::constraints::Constraints<#n, #k, #c>>::validate_constraints(self)?;)
    });
    // Declared, so integrators decide from the declaration which constraint forces act.
    let counts = match constrained {
        Some(c) => {
            let c = lit(c);
            quote!(#p::lagrange_core::constraints::ConstraintCounts::of(
                &<Self as #p::lagrange_core::constraints::Constraints<#n, #k, #c>>::KINDS
            ))
        }
        None => quote!(#p::lagrange_core::constraints::ConstraintCounts::NONE),
    };
    quote! {
        #prepare
        impl #p::Dynamics<#n> for #params {
            type Coords = Coords;
            const CONSTRAINT_COUNTS: #p::core::option::Option<#p::lagrange_core::constraints::ConstraintCounts> =
                #p::core::option::Option::Some(#counts);
            const SCLERONOMIC: bool = #scleronomic;
            const CLOSED_FORM: bool = #closed_form;
            #[inline]
            fn check_parameters(&self) -> #p::Result<()> {
                <Self as #p::Model<#n, #k>>::validate(self)?;
                #validate_constraints
                #p::core::result::Result::Ok(())
            }
            #overrides
            #tree_accelerations
            #[inline(always)]
            fn equations_of_motion_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::dynamics::EquationsOfMotion<S, #n> {
                #equations_of_motion
            }
            #[inline]
            fn kinetic_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> S {
                #kinetic
            }
            #[inline]
            fn potential_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n]) -> S {
                #p::dynamics::potential_energy::<Self, S, #n, #k>(self, t, q)
            }
            #[inline]
            fn momenta_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> [S; #n] {
                #momenta
            }
            #[inline]
            fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> f64 {
                #p::dynamics::lagrangian_time_derivative::<Self, #n, #k>(self, t, q, v)
            }
            #canonical
            #prepared_accelerations
        }
    }
}

/// What a validated handle prepares.
#[derive(Clone, Copy)]
enum Prepared {
    /// J and the factors of the constant mass matrix (`crate::affine`); whether q̈ is then
    /// straight-line code (see [`Positions`]).
    Affine {
        straight_line: bool,
    },
    /// The closed form's coefficients (`expand::closed_form`).
    Coefficients(usize),
    /// A rigid tree's joint frames and inertias (`lagrange_core::tree::rigid::RigidConstants`),
    /// for its bodies.
    Rigid(usize),
    Nothing,
}

/// The `Prepare` impl (see [`Prepared`]).
fn prepare_impl(
    params: &Ident,
    n: &proc_macro2::Literal,
    k: &proc_macro2::Literal,
    prepared: Prepared,
) -> TokenStream {
    let p = private();
    if let Prepared::Coefficients(count) = prepared {
        let count = lit(count);
        return quote! {
            impl #p::Prepare for #params {
                type Prepared = [f64; #count];
                #[inline]
                fn prepare(&self) -> #p::Result<Self::Prepared> {
                    #p::core::result::Result::Ok(self.__lagrange_coefficients())
                }
            }
        };
    }
    if let Prepared::Rigid(b) = prepared {
        let b = lit(b);
        return quote! {
            impl #p::Prepare for #params {
                type Prepared = #p::tree::rigid::RigidConstants<#b>;
                #[inline]
                fn prepare(&self) -> #p::Result<Self::Prepared> {
                    #p::core::result::Result::Ok(self.__lagrange_rigid_constants())
                }
            }
        };
    }
    if let Prepared::Affine { straight_line } = prepared {
        let one_branch = straight_line.then(|| {
            quote!(
                const PREPARED_IN_ONE_BRANCH: bool = true;
            )
        });
        quote! {
            impl #p::Prepare for #params {
                type Prepared = #p::lagrange_core::affine::AffineConstants<#n, #k>;
                #one_branch
                fn prepare(&self) -> #p::Result<Self::Prepared> {
                    #p::lagrange_core::affine::AffineConstants::of::<Self>(self)
                }
            }
        }
    } else {
        quote! {
            impl #p::Prepare for #params {
                type Prepared = ();
                #[inline(always)]
                fn prepare(&self) -> #p::Result<()> {
                    #p::core::result::Result::Ok(())
                }
            }
        }
    }
}

/// The `Mechanism` hooks that make every integrator enforce the constraints.
fn constrained_overrides(
    n: proc_macro2::Literal,
    k: proc_macro2::Literal,
    c: proc_macro2::Literal,
) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    quote! {
        #[inline]
        fn accelerations_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
            #constraints::accelerations::<Self, S, #n, #k, #c>(self, t, q, v)
        }
        #[inline]
        fn holonomic_constraints_at<S: #p::Scalar>(&self, t: S, q: &[S; #n]) -> #p::core::option::Option<[S; #n]> {
            #p::core::option::Option::Some(#constraints::holonomic_values::<Self, S, #n, #k, #c>(self, t, q))
        }
        fn project(&self, t: f64, q: &mut [f64; #n], v: &mut [f64; #n]) -> #p::Result<()> {
            let mode = #constraints::infer_mode::<Self, #n, #k, #c>(self, t, q, v)?;
            #constraints::project::<Self, #n, #k, #c>(self, t, q, v, &mode)
        }
        // Inlined (the mechanism is often declared in another crate than the caller): without
        // velocity rows the check is a constant `Ok`.
        #[inline]
        fn check_declaration_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_velocity_rows_affine::<Self, #n, #k, #c>(self, t, q, v)
        }
        fn check_constraints(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_consistent::<Self, #n, #k, #c>(self, t, q, v, #constraints::CONSISTENCY_TOLERANCE)
        }
        fn step_contacts<__I: #p::lagrange_core::integrate::Integrator>(
            &self,
            state: &mut #p::State<Coords>,
            h: f64,
        ) -> #p::core::option::Option<#p::Result<()>> {
            #constraints::step_declared_contacts::<__I, Self, #n, #k, #c>(self, state, h)
        }
        fn integrate_contacts<__P, __O>(
            &self,
            method: __P,
            state: &mut #p::State<Coords>,
            t_end: f64,
            events: &mut [#p::lagrange_core::integrate::Event<'_, Coords>],
            observer: __O,
        ) -> #p::core::option::Option<#p::Result<#p::lagrange_core::integrate::Outcome<Coords>>>
        where
            __P: #p::lagrange_core::integrate::EmbeddedPair,
            __O: #p::core::ops::FnMut(#p::lagrange_core::integrate::Observation<'_, Coords, #n>),
        {
            #constraints::integrate_declared_contacts::<__P, Self, #n, #k, #c>(method, self, state, t_end, events, observer)
        }
    }
}

/// Through a validated handle, a rigid tree's q̈ and inverse dynamics from the constants it
/// prepared.
fn rigid_prepared_calls(n: proc_macro2::Literal) -> TokenStream {
    let p = private();
    quote! {
        #[inline]
        fn accelerations_prepared_at<S: #p::Scalar>(&self, prepared: &Self::Prepared, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
            self.__lagrange_rigid_accelerations(prepared, t, q, v)
        }
        #[inline]
        fn inverse_dynamics_prepared_at<S: #p::Scalar>(&self, prepared: &Self::Prepared, t: S, q: &[S; #n], v: &[S; #n], qdd: &[S; #n]) -> [S; #n] {
            self.__lagrange_rigid_inverse_dynamics(prepared, t, q, v, qdd)
        }
    }
}
