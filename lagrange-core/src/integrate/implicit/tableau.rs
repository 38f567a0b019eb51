//! The tableaus of the two Gauss collocation methods: implicit midpoint and 2-stage Gauss–Legendre.

/// An s-stage Gauss collocation tableau with d = bᵀA⁻¹.
pub(super) struct Tableau<const S: usize> {
    /// The method's name, for errors.
    pub(super) name: &'static str,
    pub(super) a: [[f64; S]; S],
    pub(super) b: [f64; S],
    pub(super) c: [f64; S],
    pub(super) d: [f64; S],
}

/// Implicit midpoint: a = ½, b = 1, c = ½ (the 1-stage Gauss method), so d = 2.
pub(super) const MIDPOINT: Tableau<1> = Tableau {
    name: "implicit midpoint",
    a: [[0.5]],
    b: [1.0],
    c: [0.5],
    d: [2.0],
};

/// √3/6.
const R36: f64 = 0.288_675_134_594_812_9;
/// √3.
const R3: f64 = 1.732_050_807_568_877_2;

/// 2-stage Gauss–Legendre (HNW I, Table 7.4): c = ½ ∓ √3/6, A = [[¼, ¼ − √3/6], [¼ + √3/6, ¼]],
/// b = (½, ½). A⁻¹ = [[3, 2√3 − 3], [−2√3 − 3, 3]] (det A = 1/12), so d = bᵀA⁻¹ = (−√3, √3).
pub(super) const GAUSS2: Tableau<2> = Tableau {
    name: "Gauss-Legendre 2",
    a: [[0.25, 0.25 - R36], [0.25 + R36, 0.25]],
    b: [0.5, 0.5],
    c: [0.5 - R36, 0.5 + R36],
    d: [-R3, R3],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_tableau_is_consistent() {
        // Row sums equal c (HNW I (7.2)); d·(1, 1) = bᵀA⁻¹·𝟙 = 1/c-weighted identity check:
        // d = bᵀA⁻¹ ⇔ dᵀA = bᵀ.
        for i in 0..2 {
            assert!((GAUSS2.a[i][0] + GAUSS2.a[i][1] - GAUSS2.c[i]).abs() < 1e-15);
            let da = GAUSS2.d[0] * GAUSS2.a[0][i] + GAUSS2.d[1] * GAUSS2.a[1][i];
            assert!((da - GAUSS2.b[i]).abs() < 1e-15);
        }
        assert!((R36 - 3f64.sqrt() / 6.0).abs() < 1e-16 && (R3 - 3f64.sqrt()).abs() < 1e-15);
    }
}
