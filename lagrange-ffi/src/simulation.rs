//! [`Simulation`]: the handle a C program holds (validated parameters, a state and the inputs held),
//! and the generic
//! functions behind every exported C function. `export_c!` writes one `extern "C"` wrapper per
//! function here, for a concrete mechanism; all checking and marshalling is done once, here.
//!
//! # Safety
//!
//! Every function takes raw pointers from C. Each pointer must be NULL (refused with
//! [`Status::NullPointer`], or skipped where the function says so) or valid for the access and
//! length documented; a handle must come from [`create`] and not have been passed to [`free`].
//! Lengths are checked against the mechanism before any pointer is read, so a wrong length is a
//! clean [`Status::InvalidArgument`].

use crate::status::{guard, Failure, Status};
use lagrange_core::declaration::Declaration;
use lagrange_core::evaluation::Dynamics;
use lagrange_core::inputs::Driven;
use lagrange_core::integrate::{
    Dop853, Dopri5, GaussLegendre2, ImplicitMidpoint, Rk4, Stepper, StopReason, StormerVerlet,
    Variational,
};
use lagrange_core::model::{check_state, Coordinates, State};
use lagrange_core::{Mechanism, Validated};

/// A mechanism with validated parameters, its current state and the inputs held (one value per
/// [`Declaration::INPUTS`], zero at creation, changed only by [`set_inputs`]): what
/// `PREFIX_create` returns to C as an opaque `PREFIX_simulation *`. Every evaluation and step
/// through the handle sees the inputs, held until the next `set_inputs` (a zero-order hold).
#[derive(Debug)]
pub struct Simulation<M: Dynamics<N>, const N: usize> {
    sys: Validated<M>,
    state: State<M::Coords>,
    inputs: Vec<f64>,
}

impl<M: Dynamics<N>, const N: usize> Simulation<M, N> {
    /// The validated mechanism.
    pub fn mechanism(&self) -> &Validated<M> {
        &self.sys
    }

    /// The current state.
    pub fn state(&self) -> &State<M::Coords> {
        &self.state
    }

    /// The inputs held, flat, in the order of [`Declaration::INPUTS`].
    pub fn inputs(&self) -> &[f64] {
        &self.inputs
    }

    /// The mechanism with the inputs held: what every call evaluates and steps.
    fn driven(&self) -> Driven<'_, Validated<M>, &[f64]> {
        Driven::new(&self.sys, &self.inputs[..])
    }
}

/// The integration methods a C caller chooses by code (`LAGRANGE_RK4`, …).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Classical RK4, one step of h.
    Rk4 = 0,
    /// Dormand–Prince 5(4), adaptive over [t, t + h] with its default tolerances.
    Dopri5 = 1,
    /// Dormand–Prince 8(5,3), adaptive over [t, t + h] with its default tolerances.
    Dop853 = 2,
    /// Implicit midpoint, one step of h.
    ImplicitMidpoint = 3,
    /// 2-stage Gauss–Legendre, one step of h.
    GaussLegendre2 = 4,
    /// The variational integrator, one step of h.
    Variational = 5,
    /// Störmer–Verlet (constant mass matrix only), one step of h.
    StormerVerlet = 6,
}

impl Method {
    /// Every method, in order of code.
    pub const ALL: [Method; 7] = [
        Method::Rk4,
        Method::Dopri5,
        Method::Dop853,
        Method::ImplicitMidpoint,
        Method::GaussLegendre2,
        Method::Variational,
        Method::StormerVerlet,
    ];

    /// The method of a C code, `None` for an unknown one.
    pub fn from_code(code: u32) -> Option<Method> {
        Method::ALL.get(code as usize).copied()
    }

    /// The C name of the code (`LAGRANGE_RK4`) and its meaning, for the header.
    pub fn c_definition(self) -> (&'static str, &'static str) {
        match self {
            Method::Rk4 => ("LAGRANGE_RK4", "classical Runge-Kutta 4, one step of h"),
            Method::Dopri5 => (
                "LAGRANGE_DOPRI5",
                "Dormand-Prince 5(4), adaptive over [t, t + h], rtol 1e-6, atol 1e-9",
            ),
            Method::Dop853 => (
                "LAGRANGE_DOP853",
                "Dormand-Prince 8(5,3), adaptive over [t, t + h], rtol 1e-6, atol 1e-9",
            ),
            Method::ImplicitMidpoint => (
                "LAGRANGE_IMPLICIT_MIDPOINT",
                "implicit midpoint, one step of h",
            ),
            Method::GaussLegendre2 => (
                "LAGRANGE_GAUSS_LEGENDRE2",
                "2-stage Gauss-Legendre, one step of h",
            ),
            Method::Variational => (
                "LAGRANGE_VARIATIONAL",
                "variational integrator, one step of h",
            ),
            Method::StormerVerlet => (
                "LAGRANGE_STORMER_VERLET",
                "Stormer-Verlet (constant mass matrix only), one step of h",
            ),
        }
    }
}

/// `ptr[..len]` as a slice after checking `len == expected`; `name` for the messages.
///
/// # Safety
/// `ptr` is NULL or valid for reading `len` values.
unsafe fn input<'a>(
    name: &'static str,
    ptr: *const f64,
    len: usize,
    expected: usize,
) -> Result<&'a [f64], Failure> {
    check_len(name, len, expected)?;
    if expected == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(Failure::Null(name));
    }
    // SAFETY: non-NULL and, by the caller's contract, valid for `len` reads.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// Writes `values` to `ptr` when it is not NULL.
///
/// # Safety
/// `ptr` is NULL or valid for writing `values.len()` values.
unsafe fn output(ptr: *mut f64, values: &[f64]) {
    if !ptr.is_null() {
        // SAFETY: non-NULL and, by the caller's contract, valid for `values.len()` writes.
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), ptr, values.len()) };
    }
}

/// Checks that an output array's length is the mechanism's (unless the pointer is NULL: skipped).
fn output_len(
    name: &'static str,
    ptr: *mut f64,
    len: usize,
    expected: usize,
) -> Result<(), Failure> {
    match ptr.is_null() {
        true => Ok(()),
        false => check_len(name, len, expected),
    }
}

/// Checks that an array's length `len` is the mechanism's.
fn check_len(name: &'static str, len: usize, expected: usize) -> Result<(), Failure> {
    if len == expected {
        Ok(())
    } else {
        Err(Failure::Argument(format!(
            "`{name}` has length {len}, this mechanism needs {expected}"
        )))
    }
}

/// The handle behind `sim`.
///
/// # Safety
/// `sim` is NULL or a live handle from [`create`].
unsafe fn handle<'a, M: Dynamics<N>, const N: usize>(
    sim: *const Simulation<M, N>,
) -> Result<&'a Simulation<M, N>, Failure> {
    // SAFETY: by the caller's contract.
    unsafe { sim.as_ref() }.ok_or(Failure::Null("sim"))
}

/// The handle behind `sim`, to change its state.
///
/// # Safety
/// `sim` is NULL or a live handle from [`create`], not aliased during the call.
unsafe fn handle_mut<'a, M: Dynamics<N>, const N: usize>(
    sim: *mut Simulation<M, N>,
) -> Result<&'a mut Simulation<M, N>, Failure> {
    // SAFETY: by the caller's contract.
    unsafe { sim.as_mut() }.ok_or(Failure::Null("sim"))
}

/// `PREFIX_create`: checks `len == PARAMETER_COUNT` and the parameters, and writes a new handle at
/// rest at q = 0, t = 0, its inputs zero, to `*out` (NULL on failure). The handle is freed with [`free`].
///
/// # Safety
/// `params` is NULL or valid for `len` reads; `out` is NULL or valid for one write.
pub unsafe fn create<M: Dynamics<N> + Declaration, const N: usize>(
    params: *const f64,
    len: usize,
    out: *mut *mut Simulation<M, N>,
) -> Status {
    guard(|| {
        if out.is_null() {
            return Err(Failure::Null("out"));
        }
        // SAFETY: `out` is non-NULL and valid for a write.
        unsafe { out.write(std::ptr::null_mut()) };
        // SAFETY: by the caller's contract.
        let values = unsafe { input("params", params, len, M::PARAMETERS.len()) }?;
        let mechanism = M::from_parameters(values).ok_or_else(|| {
            Failure::Argument(format!("expected {} parameters", M::PARAMETERS.len()))
        })?;
        let sys = mechanism.validated()?;
        let state = State::at_rest(M::Coords::default());
        let inputs = vec![0.0; M::INPUTS.len()];
        let handle = Box::into_raw(Box::new(Simulation { sys, state, inputs }));
        // SAFETY: as above.
        unsafe { out.write(handle) };
        Ok(())
    })
}

/// `PREFIX_free`: frees a handle from [`create`]; NULL is ignored.
///
/// # Safety
/// `sim` is NULL or a live handle from [`create`], not used afterwards.
pub unsafe fn free<M: Dynamics<N>, const N: usize>(sim: *mut Simulation<M, N>) {
    if !sim.is_null() {
        // SAFETY: a live handle from `create` (a `Box::into_raw`), freed once.
        drop(unsafe { Box::from_raw(sim) });
    }
}

/// `PREFIX_set_state`: sets (t, q, q̇) after checking the lengths (`dof == DOF`) and that every
/// value is finite; on error the state is unchanged.
///
/// # Safety
/// `sim` is NULL or a live handle; `q` and `v` are NULL or valid for `dof` reads.
pub unsafe fn set_state<M: Dynamics<N>, const N: usize>(
    sim: *mut Simulation<M, N>,
    t: f64,
    q: *const f64,
    v: *const f64,
    dof: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle_mut(sim) }?;
        let q = unsafe { input("q", q, dof, N) }?;
        let v = unsafe { input("v", v, dof, N) }?;
        let (mut qa, mut va) = ([0.0; N], [0.0; N]);
        qa.copy_from_slice(q);
        va.copy_from_slice(v);
        check_state(&M::Coords::NAMES, t, &qa, &va)?;
        sim.state = State::new(t, M::Coords::from_array(qa), M::Coords::from_array(va));
        Ok(())
    })
}

/// `PREFIX_get_state`: writes t, q and q̇ (`dof == DOF` values each); a NULL output is skipped.
///
/// # Safety
/// `sim` is NULL or a live handle; `t` NULL or valid for a write; `q`, `v` NULL or valid for `dof`
/// writes.
pub unsafe fn get_state<M: Dynamics<N>, const N: usize>(
    sim: *const Simulation<M, N>,
    t: *mut f64,
    q: *mut f64,
    v: *mut f64,
    dof: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle(sim) }?;
        output_len("q", q, dof, N)?;
        output_len("v", v, dof, N)?;
        let s = &sim.state;
        // SAFETY: lengths checked; pointers by the caller's contract.
        unsafe {
            output(t, &[s.t]);
            output(q, &s.q.to_array());
            output(v, &s.v.to_array());
        }
        Ok(())
    })
}

/// `PREFIX_set_inputs`: sets the inputs held from the next evaluation on, after checking the
/// length (`len == INPUT_COUNT`) and that every value is finite; on error the inputs are
/// unchanged.
///
/// # Safety
/// `sim` is NULL or a live handle; `u` is NULL or valid for `len` reads.
pub unsafe fn set_inputs<M: Dynamics<N> + Declaration, const N: usize>(
    sim: *mut Simulation<M, N>,
    u: *const f64,
    len: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle_mut(sim) }?;
        let u = unsafe { input("u", u, len, M::INPUTS.len()) }?;
        if let Some((name, value)) = M::INPUTS.iter().zip(u).find(|(_, u)| !u.is_finite()) {
            return Err(Failure::Argument(format!(
                "input `{name}` is not finite ({value})"
            )));
        }
        sim.inputs.copy_from_slice(u);
        Ok(())
    })
}

/// `PREFIX_get_inputs`: writes the inputs held (`len == INPUT_COUNT` values).
///
/// # Safety
/// `sim` is NULL or a live handle; `u` NULL or valid for `len` writes.
pub unsafe fn get_inputs<M: Dynamics<N> + Declaration, const N: usize>(
    sim: *const Simulation<M, N>,
    u: *mut f64,
    len: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle(sim) }?;
        check_len("u", len, M::INPUTS.len())?;
        if u.is_null() && len > 0 {
            return Err(Failure::Null("u"));
        }
        // SAFETY: length checked, pointer by the caller's contract.
        unsafe { output(u, &sim.inputs) };
        Ok(())
    })
}

/// One step of `method` (a `LAGRANGE_*` code) with the handle's mechanism.
fn step_with<M: Dynamics<N>, const N: usize>(
    sim: &mut Simulation<M, N>,
    method: u32,
    h: f64,
) -> Result<(), Failure> {
    let sys = Driven::new(&sim.sys, &sim.inputs[..]);
    let state = &mut sim.state;
    let method = Method::from_code(method).ok_or_else(|| {
        Failure::Argument(format!(
            "unknown method {method}: the methods are 0 to {}",
            Method::ALL.len() - 1
        ))
    })?;
    match method {
        Method::Rk4 => sys.step::<Rk4>(state, h),
        Method::Dopri5 => sys.step::<Dopri5>(state, h),
        Method::Dop853 => sys.step::<Dop853>(state, h),
        Method::ImplicitMidpoint => sys.step::<ImplicitMidpoint>(state, h),
        Method::GaussLegendre2 => sys.step::<GaussLegendre2>(state, h),
        Method::Variational => sys.step::<Variational>(state, h),
        Method::StormerVerlet => sys.step::<StormerVerlet>(state, h),
    }?;
    Ok(())
}

/// `PREFIX_step`: one step of size `h` with `method`; on error the state is unchanged.
///
/// # Safety
/// `sim` is NULL or a live handle.
pub unsafe fn step<M: Dynamics<N>, const N: usize>(
    sim: *mut Simulation<M, N>,
    method: u32,
    h: f64,
) -> Status {
    // SAFETY: by the caller's contract.
    guard(|| step_with(unsafe { handle_mut(sim) }?, method, h))
}

/// `PREFIX_steps`: `count` steps of size `h` with `method`, in one call; stops at the first error,
/// leaving the state after the last successful step.
///
/// # Safety
/// `sim` is NULL or a live handle.
pub unsafe fn steps<M: Dynamics<N>, const N: usize>(
    sim: *mut Simulation<M, N>,
    method: u32,
    h: f64,
    count: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle_mut(sim) }?;
        for _ in 0..count {
            step_with(sim, method, h)?;
        }
        Ok(())
    })
}

/// `PREFIX_integrate_dopri5`: adaptive Dormand–Prince 5(4) from the state's time to `t_end` with
/// tolerances `rtol`, `atol`; writes the number of accepted steps to `accepted` (skipped when
/// NULL). On error, or when the default limit of step attempts is reached before `t_end`, the
/// state is unchanged.
///
/// # Safety
/// `sim` is NULL or a live handle; `accepted` NULL or valid for a write.
pub unsafe fn integrate_dopri5<M: Dynamics<N>, const N: usize>(
    sim: *mut Simulation<M, N>,
    t_end: f64,
    rtol: f64,
    atol: f64,
    accepted: *mut usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle_mut(sim) }?;
        let settings = Dopri5::new(rtol, atol);
        let sys = Driven::new(&sim.sys, &sim.inputs[..]);
        let mut solver = Stepper::new(&sys, settings, &sim.state)?;
        let outcome = solver.integrate(t_end, &mut [], |_| {})?;
        if let StopReason::MaxSteps = outcome.reason {
            return Err(Failure::Solver(format!(
                "Dopri5 made its {} step attempts before t_end = {t_end} (reached t = {})",
                settings.max_steps, outcome.state.t
            )));
        }
        sim.state = outcome.state;
        if !accepted.is_null() {
            // SAFETY: non-NULL, by the caller's contract valid for a write.
            unsafe { accepted.write(outcome.stats.accepted) };
        }
        Ok(())
    })
}

/// `PREFIX_energies`: writes the kinetic and potential energy at the state (NULL outputs skipped).
///
/// # Safety
/// `sim` is NULL or a live handle; the outputs NULL or valid for a write.
pub unsafe fn energies<M: Dynamics<N>, const N: usize>(
    sim: *const Simulation<M, N>,
    kinetic: *mut f64,
    potential: *mut f64,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle(sim) }?;
        let sys = sim.driven();
        let (t, v) = (
            sys.kinetic_energy(&sim.state)?,
            sys.potential_energy(&sim.state)?,
        );
        // SAFETY: by the caller's contract.
        unsafe {
            output(kinetic, &[t]);
            output(potential, &[v]);
        }
        Ok(())
    })
}

/// `PREFIX_accelerations`: writes q̈ at the state (`dof == DOF` values).
///
/// # Safety
/// `sim` is NULL or a live handle; `qdd` NULL or valid for `dof` writes.
pub unsafe fn accelerations<M: Dynamics<N>, const N: usize>(
    sim: *const Simulation<M, N>,
    qdd: *mut f64,
    dof: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle(sim) }?;
        if qdd.is_null() {
            return Err(Failure::Null("qdd"));
        }
        output_len("qdd", qdd, dof, N)?;
        let a = sim.driven().accelerations(&sim.state)?.to_array();
        // SAFETY: length checked, pointer by the caller's contract.
        unsafe { output(qdd, &a) };
        Ok(())
    })
}

/// `PREFIX_constraint_forces`: writes the multipliers λ (`rows == CONSTRAINT_COUNT` values) and the
/// generalized constraint forces λᵢ·rᵢ (`len == CONSTRAINT_COUNT * DOF` values, row-major) at the
/// state with the inputs held; NULL outputs are skipped.
///
/// # Safety
/// `sim` is NULL or a live handle; the outputs NULL or valid for `rows` and `len` writes.
pub unsafe fn constraint_forces<M: Dynamics<N> + Declaration, const N: usize>(
    sim: *const Simulation<M, N>,
    multipliers: *mut f64,
    rows: usize,
    generalized: *mut f64,
    len: usize,
) -> Status {
    guard(|| {
        // SAFETY: by the caller's contract.
        let sim = unsafe { handle(sim) }?;
        let c = M::CONSTRAINT_ROWS.len();
        output_len("multipliers", multipliers, rows, c)?;
        output_len("generalized", generalized, len, c * N)?;
        let s = &sim.state;
        let forces =
            sim.sys
                .get()
                .constraint_forces(&sim.inputs, s.t, &s.q.to_array(), &s.v.to_array())?;
        // SAFETY: lengths checked, pointers by the caller's contract.
        unsafe {
            output(multipliers, &forces.multipliers);
            output(generalized, &forces.generalized);
        }
        Ok(())
    })
}
