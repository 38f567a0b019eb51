//! Rust identifiers for a file's joints (the coordinates) and links (the bodies): lower case,
//! every character that cannot be in an identifier turned into `_`, a leading digit prefixed
//! (`joint_`, `link_`), a keyword suffixed with `_`. Two elements that end up with one name, or a
//! name the declaration already uses (`t`, `g`, a coordinate's `<name>_dot`), are refused.

use super::tree::Refusal;

/// A file element's identifier, and what it was called in the file.
pub struct Named {
    pub ident: String,
    pub element: String,
}

/// An identifier for `name`; `kind` (`joint`, `link`) prefixes a name that starts with a digit.
pub fn sanitise(name: &str, kind: &str) -> String {
    let mut s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        s = format!("{kind}_{s}");
    }
    if s.chars().all(|c| c == '_') || syn::parse_str::<syn::Ident>(&s).is_err() {
        s.push('_');
    }
    s
}

/// Refuses two elements with one identifier. `taken` are the names the generated declaration
/// uses itself (with what uses them).
pub fn distinct(named: &[Named], taken: &[(&str, &str)]) -> Result<(), Refusal> {
    let mut seen: Vec<(String, String)> = taken
        .iter()
        .map(|(n, what)| (n.to_string(), what.to_string()))
        .collect();
    for n in named {
        for ident in [n.ident.clone(), format!("{}_dot", n.ident)] {
            if let Some((_, other)) = seen.iter().find(|(s, _)| *s == ident) {
                return Err(format!(
                    "{} and {other} both become `{ident}` in the declaration: rename one in the file",
                    n.element
                ));
            }
            seen.push((ident, n.element.clone()));
        }
    }
    Ok(())
}
