//! What the unit tests' hand-written models share.

/// The associated items a hand-written test model states the same way every time: `f64`
/// coordinates, which terms it has, and a `validate` with nothing to check (its parameters are
/// constants of the test).
macro_rules! test_model_items {
    ($n:literal; rheonomic: $r:literal, potential: $p:literal, forces: $f:literal, gravity: $g:literal) => {
        type Coords = [f64; $n];
        const RHEONOMIC: bool = $r;
        const HAS_POTENTIAL: bool = $p;
        const HAS_FORCES: bool = $f;
        const HAS_GRAVITY: bool = $g;
        fn validate(&self) -> crate::error::Result<()> {
            Ok(())
        }
    };
}
pub(crate) use test_model_items;
