//! The linear algebra of Radau5's simplified Newton iteration: the method's coefficients, the
//! first-order vectors y = (q, v), and the factorised Newton matrices of the real and complex
//! eigenvalue blocks, reduced to N-square systems by the second-order structure (see the
//! [parent module](super)).

// The coefficients carry the digits of `radau5.f`; stage loops index several arrays.
#![allow(clippy::excessive_precision, clippy::needless_range_loop)]

use super::super::newton::BlockLu;
use nalgebra::{SMatrix, SVector};

// Nodes, error weights and the transformation of A⁻¹ to block-diagonal form: `radau5.f`
// (HW II §IV.8). C = (c₁, c₂, 1); DD = e/γ₀; U1 = γ̂ = 1/γ₀; (ALPH, BETA) = α̂ ± iβ̂.
pub(super) const C1: f64 = 0.155_051_025_721_682_190_180_271_592_529;
pub(super) const C2: f64 = 0.644_948_974_278_317_809_819_728_407_471;
pub(super) const DD1: f64 = -10.048_809_399_827_415_562_460_329_507_6;
pub(super) const DD2: f64 = 1.382_142_733_160_748_895_793_662_840_98;
pub(super) const DD3: f64 = -1.0 / 3.0;
pub(super) const U1: f64 = 3.637_834_252_744_495_732_208_418_513_58;
pub(super) const ALPH: f64 = 2.681_082_873_627_752_133_895_790_743_21;
pub(super) const BETA: f64 = 3.050_430_199_247_410_569_426_377_624_79;
pub(super) const T11: f64 = 9.123_239_487_089_294_279_2e-2;
pub(super) const T12: f64 = -0.141_255_295_020_954_208_43;
pub(super) const T13: f64 = -3.002_919_410_514_742_449_2e-2;
pub(super) const T21: f64 = 0.241_717_932_707_107_018_96;
pub(super) const T22: f64 = 0.204_129_352_293_799_931_99;
pub(super) const T23: f64 = 0.382_942_112_757_261_937_79;
pub(super) const T31: f64 = 0.966_048_182_615_092_936_19;
pub(super) const TI11: f64 = 4.325_579_890_063_155_351_0;
pub(super) const TI12: f64 = 0.339_199_251_815_809_869_54;
pub(super) const TI13: f64 = 0.541_770_539_935_874_871_19;
pub(super) const TI21: f64 = -4.178_718_591_551_904_727_3;
pub(super) const TI22: f64 = -0.327_682_820_761_062_387_08;
pub(super) const TI23: f64 = 0.476_623_554_500_550_451_96;
pub(super) const TI31: f64 = -0.502_872_634_945_786_875_95;
pub(super) const TI32: f64 = 2.571_926_949_855_605_429_2;
pub(super) const TI33: f64 = -0.596_039_204_828_224_924_97;
/// Step-size controller's safety factor (`radau5.f`, WORK(2)).
pub(super) const SAFETY: f64 = 0.9;

/// A vector of the first-order system, y = (q, v).
#[derive(Clone, Copy, Debug)]
pub(super) struct Pair<const N: usize> {
    pub(super) q: SVector<f64, N>,
    pub(super) v: SVector<f64, N>,
}

impl<const N: usize> Pair<N> {
    pub(super) fn zero() -> Self {
        Pair {
            q: SVector::zeros(),
            v: SVector::zeros(),
        }
    }
    /// Σₖ cₖ xₖ.
    pub(super) fn combine<const K: usize>(c: [f64; K], x: [&Pair<N>; K]) -> Self {
        let mut r = Pair::<N>::zero();
        for k in 0..K {
            r.q.axpy(c[k], &x[k].q, 1.0);
            r.v.axpy(c[k], &x[k].v, 1.0);
        }
        r
    }
    /// Σᵢ (xᵢ/scᵢ)² over both halves.
    pub(super) fn scaled_sum(&self, scale: &Pair<N>) -> f64 {
        let mut s = 0.0;
        for i in 0..N {
            s += (self.q[i] / scale.q[i]).powi(2) + (self.v[i] / scale.v[i]).powi(2);
        }
        s
    }
}

/// The factorised Newton matrices for one h: K(σ) = σ²I − σ∂q̈/∂v − ∂q̈/∂q at the real eigenvalue
/// σ = γ̂/h, and at the complex one σ = (α̂ + iβ̂)/h in real 2N form.
#[derive(Clone, Copy, Debug)]
pub(super) struct Factors<const N: usize> {
    pub(super) h: f64,
    real: BlockLu<N, 1>,
    complex: BlockLu<N, 2>,
}

/// The Jacobians of q̈ at the start of a step.
#[derive(Clone, Copy, Debug)]
pub(super) struct Jacobians<const N: usize> {
    pub(super) by_q: SMatrix<f64, N, N>,
    pub(super) by_v: SMatrix<f64, N, N>,
}

impl<const N: usize> Jacobians<N> {
    pub(super) fn factor(&self, h: f64) -> Option<Factors<N>> {
        let id = SMatrix::<f64, N, N>::identity();
        let s = U1 / h;
        let real = BlockLu::factor(&[[id * (s * s) - self.by_v * s - self.by_q]])?;
        let (a, b) = (ALPH / h, BETA / h);
        let re = id * (a * a - b * b) - self.by_v * a - self.by_q;
        let im = id * (2.0 * a * b) - self.by_v * b;
        let complex = BlockLu::factor(&[[re, -im], [im, re]])?;
        Some(Factors { h, real, complex })
    }

    /// Solves (σI − J)(x, y) = r for the real σ = γ̂/h.
    pub(super) fn solve_real(&self, f: &Factors<N>, r: &Pair<N>) -> Pair<N> {
        let s = U1 / f.h;
        let rhs = r.v + r.q * s - self.by_v * r.q;
        let [x] = f.real.solve(&[rhs]);
        Pair {
            q: x,
            v: x * s - r.q,
        }
    }

    /// Solves (σI − J)(x + ix′) = r + ir′ for the complex σ = (α̂ + iβ̂)/h.
    pub(super) fn solve_complex(
        &self,
        f: &Factors<N>,
        r: &Pair<N>,
        ri: &Pair<N>,
    ) -> (Pair<N>, Pair<N>) {
        let (a, b) = (ALPH / f.h, BETA / f.h);
        let re = r.v + r.q * a - ri.q * b - self.by_v * r.q;
        let im = ri.v + ri.q * a + r.q * b - self.by_v * ri.q;
        let [x, xi] = f.complex.solve(&[re, im]);
        let y = Pair {
            q: x,
            v: x * a - xi * b - r.q,
        };
        let yi = Pair {
            q: xi,
            v: xi * a + x * b - ri.q,
        };
        (y, yi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_solves_invert_sigma_minus_j() {
        // (σI − J)(x, y) = (σx − y, −∂q̈/∂q·x + σy − ∂q̈/∂v·y) applied to the solutions gives back
        // the right-hand sides, for the real and the complex σ, on a stiff J (ω ≈ 1414, hω ≈ 24).
        let jac = Jacobians::<2> {
            by_q: SMatrix::<f64, 2, 2>::new(-1000001.0, 1e6, 1e6, -1e6),
            by_v: SMatrix::<f64, 2, 2>::new(0.1, 0.2, -0.3, 0.4),
        };
        let h = 0.017;
        let f = jac.factor(h).unwrap();
        let r = Pair {
            q: SVector::from([1.0, 2.0]),
            v: SVector::from([3.0, -1.0]),
        };
        let ri = Pair {
            q: SVector::from([0.5, -2.0]),
            v: SVector::from([1.0, 4.0]),
        };
        let j = |p: &Pair<2>| Pair {
            q: p.v,
            v: jac.by_q * p.q + jac.by_v * p.v,
        };
        let close = |a: &Pair<2>, b: &Pair<2>| {
            // Entries of J are 1e6, of the solution ~1e-5: round-off ~1e-16·1e6·1e-5·n.
            assert!(
                (a.q - b.q).amax() < 1e-10 && (a.v - b.v).amax() < 1e-10,
                "{a:?} vs {b:?}"
            );
        };
        let x = jac.solve_real(&f, &r);
        close(&Pair::combine([U1 / h, -1.0], [&x, &j(&x)]), &r);
        let (x, xi) = jac.solve_complex(&f, &r, &ri);
        let (a, b) = (ALPH / h, BETA / h);
        close(&Pair::combine([a, -b, -1.0], [&x, &xi, &j(&x)]), &r);
        close(&Pair::combine([a, b, -1.0], [&xi, &x, &j(&xi)]), &ri);
    }

    /// The full simplified-Newton matrix I − h(A ⊗ J) of the 3 stages on y = (q, v), as 6×6
    /// blocks of N×N (stage i, half a; stage j, half b), with A the Radau IIA matrix (HW II Table 5.6).
    fn full_matrix<const N: usize>(jac: &Jacobians<N>, h: f64) -> [[SMatrix<f64, N, N>; 6]; 6] {
        let s6 = 6f64.sqrt();
        let a = [
            [
                (88.0 - 7.0 * s6) / 360.0,
                (296.0 - 169.0 * s6) / 1800.0,
                (-2.0 + 3.0 * s6) / 225.0,
            ],
            [
                (296.0 + 169.0 * s6) / 1800.0,
                (88.0 + 7.0 * s6) / 360.0,
                (-2.0 - 3.0 * s6) / 225.0,
            ],
            [(16.0 - s6) / 36.0, (16.0 + s6) / 36.0, 1.0 / 9.0],
        ];
        let id = SMatrix::<f64, N, N>::identity();
        let zero = SMatrix::<f64, N, N>::zeros();
        let j = [[zero, id], [jac.by_q, jac.by_v]];
        std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let (i, p, k, q) = (r / 2, r % 2, c / 2, c % 2);
                let diagonal = if r == c { id } else { zero };
                diagonal - j[p][q] * (h * a[i][k])
            })
        })
    }

    /// Factorisation and one solve, split (N-square real and 2N-square complex-as-real systems)
    /// against the full 6N-square system, timed (minimum over interleaved rounds): the split is
    /// cheaper at every N ≤ 8. The flop counts are about 3N³ against 72N³, so a factor of 3 holds
    /// with a wide margin, also in unoptimised builds and under machine load.
    fn split_against_full<const N: usize>() -> (f64, f64) {
        use std::hint::black_box;
        use std::time::Instant;
        let jac = Jacobians::<N> {
            by_q: SMatrix::from_fn(|i, j| {
                if i == j {
                    -2e6
                } else {
                    1e6 / (1.0 + (i + j) as f64)
                }
            }),
            by_v: SMatrix::from_fn(|i, j| 0.01 * (i as f64 - j as f64)),
        };
        let h = 0.01;
        let r = Pair::<N> {
            q: SVector::from_fn(|i, _| 1.0 + i as f64),
            v: SVector::from_fn(|i, _| 2.0 - i as f64),
        };
        let rhs = [SVector::<f64, N>::from_fn(|i, _| i as f64 + 0.5); 6];
        let (mut split, mut full) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..30 {
            let t = Instant::now();
            for _ in 0..20 {
                let f = black_box(&jac).factor(black_box(h)).unwrap();
                black_box(jac.solve_real(&f, &r));
                black_box(jac.solve_complex(&f, &r, &r));
            }
            split = split.min(t.elapsed().as_secs_f64() / 20.0);
            let t = Instant::now();
            for _ in 0..20 {
                let lu = BlockLu::factor(&full_matrix(black_box(&jac), black_box(h))).unwrap();
                black_box(lu.solve(&rhs));
            }
            full = full.min(t.elapsed().as_secs_f64() / 20.0);
        }
        (split, full)
    }

    #[test]
    fn split_systems_are_cheaper_than_the_full_block_system() {
        for (n, (split, full)) in [
            (2, split_against_full::<2>()),
            (4, split_against_full::<4>()),
            (8, split_against_full::<8>()),
        ] {
            eprintln!(
                "N = {n}: split {:.2e} s, full 6N system {:.2e} s, ratio {:.1}",
                split,
                full,
                full / split
            );
            assert!(
                full > 3.0 * split,
                "N = {n}: split {split:e} s, full {full:e} s"
            );
        }
    }
}
