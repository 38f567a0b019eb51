//! Compile-fail cases: each file in `tests/ui/` is one mistake in a declaration, named after it; its
//! `.stderr` snapshot shows the one message at the offending tokens. Compile-pass cases: each file
//! in `tests/ui/pass/` is a group of unusual but valid declarations that must compile and run.
//! Both are built in one trybuild batch. Regenerate the snapshots with
//! `TRYBUILD=overwrite cargo test --test ui` and read them.

#[test]
fn ui() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
    cases.pass("tests/ui/pass/*.rs");
}
