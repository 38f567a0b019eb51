//! The `#[mechanism]` attribute of `lagrange`. Use it through the `lagrange` crate, which documents
//! the declaration; this crate only turns a declaration into code:
//!
//! parse ([`ast`], [`attr`]) → check, collecting every error ([`check`], [`ctxt`]) → expand
//! ([`expand`]). On error the user's items are still emitted, with stubs for what the rest of their
//! code names, so one mistake gives one message.

mod ast;
mod attr;
mod check;
mod ctxt;
mod expand;
mod lift;
mod names;

#[cfg(test)]
mod expand_tests;

use proc_macro::TokenStream;

/// Turns an inline module declaring a mechanism into typed equations of motion. See the `lagrange`
/// crate's README, "The declaration".
#[proc_macro_attribute]
pub fn mechanism(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::expand(attr.into(), item.into()).into()
}
