//! Structural zeros of a mass matrix and of its factor, as constants of a declaration: what
//! [`Ldlt::with_pattern`](super::Ldlt::with_pattern) leaves out.

/// The pattern of M = Σᵢ μᵢ JᵢᵀJᵢ from that of J: entry (r, c) can be nonzero only if some massive
/// row i (i < `inertial`) depends on both coordinates r and c (`depends` is `Model::DEPENDS`).
///
/// ```
/// use lagrange_core::linalg::mass_pattern;
/// // Row 0 depends on q0, row 1 on q0 and q1, row 2 on q2.
/// let depends = [[true, false, false], [true, true, false], [false, false, true]];
/// let m = mass_pattern(&depends, 3);
/// assert_eq!(m, [[true, true, false], [true, true, false], [false, false, true]]);
/// ```
pub const fn mass_pattern<const N: usize, const K: usize>(
    depends: &[[bool; N]; K],
    inertial: usize,
) -> [[bool; N]; N] {
    let mut out = [[false; N]; N];
    let mut i = 0;
    while i < K && i < inertial {
        let mut r = 0;
        while r < N {
            let mut c = 0;
            while c < N {
                if depends[i][r] && depends[i][c] {
                    out[r][c] = true;
                }
                c += 1;
            }
            r += 1;
        }
        i += 1;
    }
    out
}

/// The pattern of L in M = L D Lᵀ from M's (symmetric) pattern: the symbolic factorisation, where
/// L_ij (i > j) is nonzero if M_ij is or if some k < j has L_ik and L_jk nonzero (the fill-in;
/// George & Liu, *Computer Solution of Large Sparse Positive Definite Systems*, 1981, §4.2).
/// Only the strictly lower part is meaningful.
///
/// ```
/// use lagrange_core::linalg::factor_pattern;
/// // An arrow: q0 coupled to q1 and q2, which are not coupled to each other. Eliminating q0 fills
/// // in L₂₁.
/// let m = [[true, true, true], [true, true, false], [true, false, true]];
/// assert!(factor_pattern(&m)[2][1]);
/// // Eliminated last, q0 fills in nothing.
/// let m = [[true, false, true], [false, true, true], [true, true, true]];
/// assert!(!factor_pattern(&m)[1][0]);
/// ```
pub const fn factor_pattern<const N: usize>(m: &[[bool; N]; N]) -> [[bool; N]; N] {
    let mut l = [[false; N]; N];
    let mut j = 0;
    while j < N {
        let mut i = j + 1;
        while i < N {
            let mut nonzero = m[i][j];
            let mut k = 0;
            while k < j {
                nonzero |= l[i][k] && l[j][k];
                k += 1;
            }
            l[i][j] = nonzero;
            i += 1;
        }
        j += 1;
    }
    l
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::Ldlt;
    use nalgebra::{SMatrix, SVector};

    #[test]
    fn massless_rows_do_not_couple() {
        // Row 1 (a massless point) depends on both coordinates; only row 0 carries mass.
        let depends = [[true, false], [true, true]];
        assert_eq!(mass_pattern(&depends, 1), [[true, false], [false, false]]);
        assert_eq!(mass_pattern(&depends, 2), [[true, true], [true, true]]);
    }

    /// A block-diagonal M with an arrow-shaped block: every fill-in entry of the factor must be in
    /// the pattern (else the solve would be wrong), checked against the dense factorisation on a
    /// matrix with those couplings and values of order one.
    #[test]
    fn the_structured_factorisation_solves_like_the_dense_one() {
        let couples = |r: usize, c: usize| {
            r == c || (r < 3 && c < 3 && (r == 0 || c == 0)) || (r >= 3 && c >= 3)
        };
        let mut m = SMatrix::<f64, 5, 5>::zeros();
        let mut pattern = [[false; 5]; 5];
        for r in 0..5 {
            for c in 0..5 {
                if couples(r, c) {
                    pattern[r][c] = true;
                    m[(r, c)] = if r == c {
                        4.0 + r as f64
                    } else {
                        0.5 + 0.1 * (r + c) as f64
                    };
                }
            }
        }
        let l = factor_pattern(&pattern);
        // Eliminating q0 couples q1 and q2: fill-in.
        assert!(l[2][1] && !pattern[2][1]);
        // The blocks stay apart.
        assert!(!l[3][0] && !l[4][2]);
        let b = SVector::<f64, 5>::from_fn(|i, _| 1.0 - 0.3 * i as f64);
        let structured = Ldlt::with_pattern(&m, l).unwrap().solve(&b);
        let dense = Ldlt::new(&m).unwrap().solve(&b);
        // The terms left out are exact zeros: the same operations on the same values.
        assert_eq!(structured, dense);
        assert!((m * structured - b).norm() < 1e-14);
        // And a pattern missing the fill-in would not solve the system.
        let mut short = l;
        short[2][1] = false;
        let wrong = Ldlt::with_pattern(&m, short).unwrap().solve(&b);
        assert!((m * wrong - b).norm() > 1e-6);
    }
}
