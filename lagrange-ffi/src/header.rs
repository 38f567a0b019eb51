//! The C header of an exported mechanism, written from the same tokens that define its functions.
//!
//! `export_c!` lists each function once; from that list it writes the `extern "C"` function and a
//! [`CFunction`] whose C types come from the Rust types by [`CType`]. So the header cannot disagree
//! with the library: [`header`] turns the list, the status and method codes, and the declaration's
//! names into the text of `PREFIX.h`.

use crate::simulation::{Method, Simulation};
use crate::status::Status;
use lagrange_core::declaration::Declaration;
use lagrange_core::evaluation::Dynamics;
use lagrange_core::model::Coordinates;
use std::ffi::c_char;
use std::fmt::Write;

/// A Rust type that crosses the C boundary, with its C spelling.
pub trait CType {
    /// The type in C (`double`, `const double *`, `dp_simulation *`).
    fn c_name() -> String;
}

macro_rules! c_types {
    ($($ty:ty => $c:literal),* $(,)?) => {
        $(impl CType for $ty {
            fn c_name() -> String {
                $c.to_string()
            }
        })*
    };
}

c_types! {
    f64 => "double",
    usize => "size_t",
    u32 => "uint32_t",
    c_char => "char",
    Status => "lagrange_status",
    () => "void",
}

/// `T *`, with the star next to the name when T is a pointer too (`dp_simulation **`).
fn pointer_to(pointee: String) -> String {
    if pointee.ends_with('*') {
        format!("{pointee}*")
    } else {
        format!("{pointee} *")
    }
}

impl<T: CType> CType for *mut T {
    fn c_name() -> String {
        pointer_to(T::c_name())
    }
}

impl<T: CType> CType for *const T {
    fn c_name() -> String {
        pointer_to(format!("const {}", T::c_name()))
    }
}

/// `PREFIX_simulation`: the header writes the prefix in (a handle's type does not know it).
impl<M: Dynamics<N>, const N: usize> CType for Simulation<M, N> {
    fn c_name() -> String {
        "PREFIX_simulation".to_string()
    }
}

/// One exported function as the header declares it.
#[derive(Clone, Debug, PartialEq)]
pub struct CFunction {
    /// The name after the prefix (`step` for `dp_step`).
    pub name: &'static str,
    /// Its documentation, line by line (the Rust doc comment).
    pub doc: &'static [&'static str],
    /// The C return type.
    pub ret: String,
    /// Each argument's name and C type.
    pub args: Vec<(&'static str, String)>,
}

/// A mechanism's C export: `export_c!(path::Mechanism, prefix = dp)` defines the type `dp` and
/// writes this impl for it, so `dp::header()` is the header (with `Export` in scope). Named by the
/// prefix, the export is a type of the crate that builds the library even when the mechanism is
/// declared in another crate.
pub trait Export {
    /// The prefix of every exported name (`dp` for `dp_step`).
    const PREFIX: &'static str;
    /// The Rust path of the mechanism as written in `export_c!`, for the header's first line.
    const RUST_PATH: &'static str;
    /// The exported functions, in the order the header lists them.
    fn functions() -> Vec<CFunction>;
    /// The C header (see [`header`]).
    fn header() -> String;
}

/// `theta[2]` → `THETA_2`: a name as the tail of a C macro name.
fn c_identifier(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    while out.ends_with('_') {
        out.pop();
    }
    out
}

/// `PREFIX_create` → `dp_create`, `PREFIX_DOF` → `DP_DOF`: the placeholder of the functions'
/// documentation replaced by the prefix, upper-case before an upper-case name.
fn with_prefix(line: &str, prefix: &str) -> String {
    let mut parts = line.split("PREFIX_");
    let mut out = parts.next().unwrap_or_default().to_string();
    for part in parts {
        match part.starts_with(|c: char| c.is_ascii_uppercase()) {
            true => out.push_str(&c_identifier(prefix)),
            false => out.push_str(prefix),
        }
        out.push('_');
        out.push_str(part);
    }
    out
}

/// A C block comment of `lines` indented by `indent` (`*/` inside a line is broken up).
fn comment(out: &mut String, indent: &str, lines: &[&str]) {
    let lines: Vec<String> = lines
        .iter()
        .map(|l| l.trim_end().replace("*/", "* /"))
        .collect();
    match lines.as_slice() {
        [] => {}
        [one] => {
            let _ = writeln!(out, "{indent}/*{one} */");
        }
        [first, rest @ ..] => {
            let _ = writeln!(out, "{indent}/*{first}");
            for line in rest {
                let _ = writeln!(out, "{indent} *{line}");
            }
            let _ = writeln!(out, "{indent} */");
        }
    }
}

/// The part every exported mechanism shares (status and method codes), once per translation unit.
fn common(out: &mut String) {
    out.push_str("#ifndef LAGRANGE_COMMON_DECLARATIONS\n#define LAGRANGE_COMMON_DECLARATIONS\n\n");
    out.push_str(
        "/* What every function returns: LAGRANGE_OK or the kind of failure; the message of\n",
    );
    out.push_str(" * a failure is PREFIX_last_error(). */\ntypedef enum lagrange_status {\n");
    for status in Status::ALL {
        let (name, meaning) = status.c_definition();
        let _ = writeln!(out, "    {name} = {}, /* {meaning} */", status as u32);
    }
    out.push_str(
        "} lagrange_status;\n\n/* Integration methods, the `method` argument of PREFIX_step. */\n",
    );
    for method in Method::ALL {
        let (name, meaning) = method.c_definition();
        let _ = writeln!(out, "#define {name} {}u /* {meaning} */", method as u32);
    }
    out.push_str("\n#endif /* LAGRANGE_COMMON_DECLARATIONS */\n\n");
}

/// `#define PREFIX_SUFFIX_NAME index` for each name.
fn indices(out: &mut String, prefix: &str, what: &str, names: &[&str]) {
    for (i, name) in names.iter().enumerate() {
        let _ = writeln!(out, "#define {prefix}_{what}{} {i}", c_identifier(name));
    }
}

/// The C header of export `E` of mechanism `M`: the shared status and method codes, the
/// sizes (`PREFIX_DOF`, `PREFIX_PARAMETER_COUNT`, `PREFIX_INPUT_COUNT`,
/// `PREFIX_CONSTRAINT_COUNT`), the index of every parameter, input, coordinate and constraint row
/// by name, the opaque handle type, and every function
/// with its documentation.
pub fn header<E: Export, M: Dynamics<N> + Declaration, const N: usize>() -> String {
    let prefix = E::PREFIX;
    let upper = c_identifier(prefix);
    let mut out = String::new();
    let _ = writeln!(
        out,
        "/* C interface of the mechanism `{}`, prefix `{prefix}`.\n * Generated by lagrange::export_c!; do not edit (regenerate it instead). */",
        E::RUST_PATH
    );
    let _ = writeln!(out, "#ifndef {upper}_H\n#define {upper}_H\n");
    out.push_str("#include <stddef.h>\n#include <stdint.h>\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    common(&mut out);
    let _ = writeln!(out, "#define {upper}_DOF {N}");
    let _ = writeln!(
        out,
        "#define {upper}_PARAMETER_COUNT {}",
        M::PARAMETERS.len()
    );
    let _ = writeln!(out, "#define {upper}_INPUT_COUNT {}", M::INPUTS.len());
    let _ = writeln!(
        out,
        "#define {upper}_CONSTRAINT_COUNT {}\n",
        M::CONSTRAINT_ROWS.len()
    );
    out.push_str("/* Parameters: indices into the `params` array of the create function. */\n");
    indices(&mut out, &upper, "PARAM_", M::PARAMETERS);
    if !M::INPUTS.is_empty() {
        out.push_str("\n/* Inputs: indices into the `u` array of the set_inputs function. */\n");
        indices(&mut out, &upper, "INPUT_", M::INPUTS);
    }
    out.push_str("\n/* Coordinates: indices into q and v. */\n");
    indices(&mut out, &upper, "", &M::Coords::NAMES);
    if !M::CONSTRAINT_ROWS.is_empty() {
        out.push_str("\n/* Constraint rows: indices into the multipliers. */\n");
        indices(&mut out, &upper, "CONSTRAINT_", M::CONSTRAINT_ROWS);
    }
    let handle = with_prefix(&Simulation::<M, N>::c_name(), prefix);
    let _ = writeln!(
        out,
        "\n/* A mechanism with checked parameters and its state; opaque. */\ntypedef struct {handle} {handle};\n"
    );
    for f in E::functions() {
        let doc: Vec<String> = f.doc.iter().map(|l| with_prefix(l, prefix)).collect();
        comment(
            &mut out,
            "",
            &doc.iter().map(String::as_str).collect::<Vec<_>>(),
        );
        let args: Vec<String> = f
            .args
            .iter()
            .map(|(name, ty)| (name, with_prefix(ty, prefix)))
            .map(|(name, ty)| match ty.ends_with('*') {
                true => format!("{ty}{name}"),
                false => format!("{ty} {name}"),
            })
            .collect();
        let args = if args.is_empty() {
            "void".to_string()
        } else {
            args.join(", ")
        };
        let ret = with_prefix(&f.ret, prefix);
        let ret = match ret.ends_with('*') {
            true => ret,
            false => format!("{ret} "),
        };
        let _ = writeln!(out, "{ret}{prefix}_{}({args});\n", f.name);
    }
    let _ = writeln!(
        out,
        "#ifdef __cplusplus\n}}\n#endif\n\n#endif /* {upper}_H */"
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn c_types_spell_pointers_as_c_does() {
        assert_eq!(<*const f64>::c_name(), "const double *");
        assert_eq!(<*mut f64>::c_name(), "double *");
        assert_eq!(<*mut *mut usize>::c_name(), "size_t **");
        assert_eq!(<*const c_char>::c_name(), "const char *");
        assert_eq!(<Status as CType>::c_name(), "lagrange_status");
    }

    #[test]
    fn names_become_c_identifiers() {
        assert_eq!(c_identifier("theta1"), "THETA1");
        assert_eq!(c_identifier("theta[2]"), "THETA_2");
        assert_eq!(c_identifier("dp"), "DP");
    }

    #[test]
    fn documentation_names_the_prefix() {
        assert_eq!(
            with_prefix(" free with PREFIX_free; PREFIX_DOF values", "dp"),
            " free with dp_free; DP_DOF values"
        );
    }

    #[test]
    fn comments_cannot_be_closed_from_inside() {
        let mut out = String::new();
        comment(&mut out, "", &[" a */ b", " c"]);
        assert_eq!(out, "/* a * / b\n * c\n */\n");
    }
}
