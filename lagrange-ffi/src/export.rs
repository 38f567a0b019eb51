//! `export_c!`: the C functions of a mechanism, written once here for every mechanism.

/// Exports a `#[mechanism]` to C: writes, for the parameter struct named, the `extern "C"`
/// functions `PREFIX_create`, `PREFIX_free`, `PREFIX_set_state`, `PREFIX_get_state`,
/// `PREFIX_set_inputs`, `PREFIX_get_inputs`, `PREFIX_step`, `PREFIX_steps`,
/// `PREFIX_integrate_dopri5`, `PREFIX_energies`, `PREFIX_accelerations`,
/// `PREFIX_constraint_forces` and `PREFIX_last_error`, and a type named by the prefix (`dp`)
/// whose [`Export`](crate::Export) impl gives their C header, `dp::header()`. The handle holds the
/// inputs of a declaration with `#[inputs]` (`PREFIX_set_inputs`) and every call evaluates with
/// them.
///
/// Put it in a crate built as `cdylib` or `staticlib` (see the README, "Calling a mechanism from
/// C"). Every function returns a `lagrange_status`; none unwinds into C.
///
/// ```
/// use lagrange::prelude::*;
/// use lagrange::ffi::Export;
///
/// #[mechanism]
/// pub mod pendulum {
///     pub struct Coords {
///         pub theta: f64,
///     }
///     pub struct Pendulum {
///         pub l: f64,
///         pub g: f64,
///     }
///     #[particle(mass = 1.0)]
///     fn bob() -> Vec2 {
///         vec2(theta.sin(), -theta.cos()) * l
///     }
///     #[gravity]
///     fn down() -> Vec2 {
///         vec2(0.0, -g)
///     }
/// }
///
/// lagrange::export_c!(pendulum::Pendulum, prefix = pend);
///
/// let header = pend::header();
/// assert!(header.contains("lagrange_status pend_step(pend_simulation *sim, uint32_t method, double h);"));
/// assert!(header.contains("#define PEND_PARAM_G 1"));
/// ```
#[macro_export]
macro_rules! export_c {
    ($mechanism:ty, prefix = $prefix:ident $(,)?) => {
        #[doc = concat!("The C export of `", stringify!($mechanism), "`: functions `", stringify!($prefix), "_*`; `", stringify!($prefix), "::header()` is their header.")]
        #[allow(non_camel_case_types)]
        pub enum $prefix {}

        const _: () = {
            type Mech = $mechanism;
            const N: usize = <Mech as $crate::__private::Declaration>::DOF;
            type Sim = $crate::Simulation<Mech, N>;
            type Status = $crate::Status;
            type CChar = $crate::__private::c_char;

            impl $crate::Export for $prefix {
                const PREFIX: &'static str = stringify!($prefix);
                const RUST_PATH: &'static str = stringify!($mechanism);
                fn functions() -> $crate::__private::Vec<$crate::header::CFunction> {
                    functions()
                }
                fn header() -> $crate::__private::String {
                    $crate::header::header::<$prefix, Mech, N>()
                }
            }

            $crate::__export_c_functions! { $prefix;
                /// Creates a simulation from the parameters (`len` ==
                /// PREFIX_PARAMETER_COUNT values, indexed by PREFIX_PARAM_*), at rest at q = 0,
                /// t = 0, and writes it to `*out` (NULL on failure). Free it with PREFIX_free.
                fn create(params: *const f64, len: usize, out: *mut *mut Sim) -> Status {
                    unsafe { $crate::simulation::create::<Mech, N>(params, len, out) }
                }
                /// Frees a simulation from PREFIX_create; NULL is ignored.
                fn free(sim: *mut Sim) -> () {
                    unsafe { $crate::simulation::free::<Mech, N>(sim) }
                }
                /// Sets the time, coordinates and velocities (`dof` == PREFIX_DOF values each,
                /// finite); on failure the state is unchanged.
                fn set_state(sim: *mut Sim, t: f64, q: *const f64, v: *const f64, dof: usize) -> Status {
                    unsafe { $crate::simulation::set_state::<Mech, N>(sim, t, q, v, dof) }
                }
                /// Writes the time, coordinates and velocities (`dof` == PREFIX_DOF values each);
                /// a NULL output is skipped.
                fn get_state(sim: *const Sim, t: *mut f64, q: *mut f64, v: *mut f64, dof: usize) -> Status {
                    unsafe { $crate::simulation::get_state::<Mech, N>(sim, t, q, v, dof) }
                }
                /// Sets the inputs (`len` == PREFIX_INPUT_COUNT finite values, indexed by
                /// PREFIX_INPUT_*), held constant from the next call on until the next
                /// PREFIX_set_inputs (zero after PREFIX_create); on failure they are unchanged.
                fn set_inputs(sim: *mut Sim, u: *const f64, len: usize) -> Status {
                    unsafe { $crate::simulation::set_inputs::<Mech, N>(sim, u, len) }
                }
                /// Writes the inputs held (`len` == PREFIX_INPUT_COUNT values).
                fn get_inputs(sim: *const Sim, u: *mut f64, len: usize) -> Status {
                    unsafe { $crate::simulation::get_inputs::<Mech, N>(sim, u, len) }
                }
                /// Advances the state by one step of size `h` with `method` (LAGRANGE_RK4, ...),
                /// the inputs held over it; on failure the state is unchanged.
                fn step(sim: *mut Sim, method: u32, h: f64) -> Status {
                    unsafe { $crate::simulation::step::<Mech, N>(sim, method, h) }
                }
                /// `count` steps of size `h` with `method` in one call; stops at the first
                /// failure, leaving the state after the last successful step.
                fn steps(sim: *mut Sim, method: u32, h: f64, count: usize) -> Status {
                    unsafe { $crate::simulation::steps::<Mech, N>(sim, method, h, count) }
                }
                /// Integrates to `t_end` by adaptive Dormand-Prince 5(4) with tolerances `rtol`,
                /// `atol`, the inputs held; writes the number of accepted steps to `accepted`
                /// (skipped when NULL). On failure the state is unchanged.
                fn integrate_dopri5(sim: *mut Sim, t_end: f64, rtol: f64, atol: f64, accepted: *mut usize) -> Status {
                    unsafe { $crate::simulation::integrate_dopri5::<Mech, N>(sim, t_end, rtol, atol, accepted) }
                }
                /// Writes the kinetic and potential energy at the state; a NULL output is skipped.
                fn energies(sim: *const Sim, kinetic: *mut f64, potential: *mut f64) -> Status {
                    unsafe { $crate::simulation::energies::<Mech, N>(sim, kinetic, potential) }
                }
                /// Writes the generalized accelerations at the state with the inputs held (`dof` ==
                /// PREFIX_DOF values).
                fn accelerations(sim: *const Sim, qdd: *mut f64, dof: usize) -> Status {
                    unsafe { $crate::simulation::accelerations::<Mech, N>(sim, qdd, dof) }
                }
                /// Writes the constraint multipliers (`rows` == PREFIX_CONSTRAINT_COUNT values)
                /// and the generalized constraint forces, row by row (`len` ==
                /// PREFIX_CONSTRAINT_COUNT * PREFIX_DOF values) with the inputs held; a NULL
                /// output is skipped.
                fn constraint_forces(sim: *const Sim, multipliers: *mut f64, rows: usize, generalized: *mut f64, len: usize) -> Status {
                    unsafe { $crate::simulation::constraint_forces::<Mech, N>(sim, multipliers, rows, generalized, len) }
                }
                /// The message of the last failure on this thread, owned by the library: valid
                /// until the next call into it on this thread; never free it. "" before the first
                /// failure; a success does not clear it.
                fn last_error() -> *const CChar {
                    $crate::status::last_error()
                }
            }
        };
    };
}

/// One `extern "C"` function per entry, named `PREFIX_name`, and `functions()` describing them for
/// the header, both from the same tokens.
#[doc(hidden)]
#[macro_export]
macro_rules! __export_c_functions {
    ($prefix:ident; $(
        $(#[doc = $doc:literal])*
        fn $name:ident ( $($arg:ident : $argty:ty),* ) -> $ret:ty $body:block
    )*) => {
        $(
            $(#[doc = $doc])*
            #[unsafe(export_name = concat!(stringify!($prefix), "_", stringify!($name)))]
            unsafe extern "C" fn $name($($arg: $argty),*) -> $ret $body
        )*

        fn functions() -> $crate::__private::Vec<$crate::header::CFunction> {
            $crate::__private::vec![$(
                $crate::header::CFunction {
                    name: stringify!($name),
                    doc: &[$($doc),*],
                    ret: <$ret as $crate::header::CType>::c_name(),
                    args: $crate::__private::vec![
                        $((stringify!($arg), <$argty as $crate::header::CType>::c_name())),*
                    ],
                }
            ),*]
        }
    };
}
