//! What the robot tests share: the comparison of two results to a tolerance relative to the
//! expected one's size.

/// max |x − expected| ≤ tolerance · max |expected|.
pub fn assert_close(what: &str, x: &[f64], expected: &[f64], tolerance: f64) {
    assert_eq!(x.len(), expected.len(), "{what}: length");
    let size = expected.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
    let err = x
        .iter()
        .zip(expected)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        err <= tolerance * size,
        "{what}: differs by {err:e} (size {size:e})"
    );
}
