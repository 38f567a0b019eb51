//! Compile-fail cases: each file in `tests/ui/` is one mistake in a declaration, named after it; its
//! `.stderr` snapshot shows the one message at the offending tokens. Regenerate the snapshots with
//! `TRYBUILD=overwrite cargo test --test ui` and read them.

#[test]
fn ui() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
}
