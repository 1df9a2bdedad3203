//! Least-squares accumulators of the calibration: no storage of samples
//! (no heap), only the sums of the normal equations, so a fit over
//! thousands of control periods costs a few words of state.

/// Ordinary least squares with up to [`N`] regressors, accumulated sample by
/// sample: `y = sum_j b_j x_j + e`. Solved by Gaussian elimination with
/// partial pivoting on the normal equations (small `N`, well-scaled
/// regressors: the calibration's are O(1) after scaling by the caller).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lsq<const N: usize> {
    xtx: [[f64; N]; N],
    xty: [f64; N],
    yty: f64,
    n: u32,
}

impl<const N: usize> Default for Lsq<N> {
    fn default() -> Self {
        Self {
            xtx: [[0.0; N]; N],
            xty: [0.0; N],
            yty: 0.0,
            n: 0,
        }
    }
}

/// A solved fit: coefficients, their covariance and the residual RMS.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solution<const N: usize> {
    /// Coefficients.
    pub b: [f64; N],
    /// Covariance of the coefficients, `s^2 (X'X)^-1`.
    pub cov: [[f64; N]; N],
    /// Residual root mean square (`s`, with `n - N` degrees of freedom).
    pub rms: f64,
    /// Samples.
    pub n: u32,
}

impl<const N: usize> Solution<N> {
    /// Standard error of coefficient `j`.
    pub fn se(&self, j: usize) -> f64 {
        libm::sqrt(self.cov[j][j].max(0.0))
    }
}

impl<const N: usize> Lsq<N> {
    /// Adds one sample.
    pub fn add(&mut self, x: [f64; N], y: f64) {
        for i in 0..N {
            for j in 0..N {
                self.xtx[i][j] += x[i] * x[j];
            }
            self.xty[i] += x[i] * y;
        }
        self.yty += y * y;
        self.n += 1;
    }

    /// Samples added.
    pub fn len(&self) -> u32 {
        self.n
    }

    /// Whether no sample was added.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The fit; `None` with too few samples or singular regressors.
    pub fn solve(&self) -> Option<Solution<N>> {
        if (self.n as usize) <= N {
            return None;
        }
        let inv = invert(&self.xtx)?;
        let mut b = [0.0; N];
        for (i, bi) in b.iter_mut().enumerate() {
            *bi = (0..N).map(|j| inv[i][j] * self.xty[j]).sum();
        }
        // Residual sum of squares from the sums: y'y - b'X'y.
        let bxy: f64 = (0..N).map(|j| b[j] * self.xty[j]).sum();
        let rss = (self.yty - bxy).max(0.0);
        let s2 = rss / f64::from(self.n - N as u32);
        let mut cov = inv;
        for row in cov.iter_mut() {
            for c in row.iter_mut() {
                *c *= s2;
            }
        }
        let ok = b.iter().all(|v| v.is_finite());
        ok.then_some(Solution {
            b,
            cov,
            rms: libm::sqrt(s2),
            n: self.n,
        })
    }
}

/// Inverse of a small symmetric positive matrix (Gauss-Jordan, partial
/// pivoting); `None` when singular.
fn invert<const N: usize>(m: &[[f64; N]; N]) -> Option<[[f64; N]; N]> {
    let mut a = *m;
    let mut inv = [[0.0; N]; N];
    for (i, row) in inv.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    let scale = (0..N).fold(0.0f64, |s, i| s.max(libm::fabs(m[i][i])));
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    for c in 0..N {
        let p = (c..N).max_by(|&x, &y| libm::fabs(a[x][c]).total_cmp(&libm::fabs(a[y][c])))?;
        if libm::fabs(a[p][c]) <= 1e-13 * scale {
            return None;
        }
        a.swap(c, p);
        inv.swap(c, p);
        let d = a[c][c];
        for j in 0..N {
            a[c][j] /= d;
            inv[c][j] /= d;
        }
        for r in 0..N {
            if r != c {
                let f = a[r][c];
                for j in 0..N {
                    a[r][j] -= f * a[c][j];
                    inv[r][j] -= f * inv[c][j];
                }
            }
        }
    }
    Some(inv)
}

/// Mean and sum of squares of one quantity, accumulated.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Mean {
    sum: f64,
    sq: f64,
    n: u32,
}

impl Mean {
    /// Adds a sample.
    pub fn add(&mut self, x: f64) {
        self.sum += x;
        self.sq += x * x;
        self.n += 1;
    }
    /// Samples.
    pub fn len(&self) -> u32 {
        self.n
    }
    /// Whether empty.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
    /// Mean (0 when empty).
    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.sum / f64::from(self.n)
        }
    }
    /// Sample standard deviation (0 below two samples).
    pub fn std(&self) -> f64 {
        if self.n < 2 {
            return 0.0;
        }
        let n = f64::from(self.n);
        libm::sqrt(((self.sq - self.sum * self.sum / n) / (n - 1.0)).max(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testrng::Rng;

    #[test]
    fn a_line_through_noisy_points_recovers_slope_and_its_error() {
        let mut f = Lsq::<2>::default();
        let mut r = Rng(3);
        for k in 0..1000 {
            let x = f64::from(k) / 100.0;
            f.add([x, 1.0], 0.7 * x - 0.2 + r.uniform(-0.01, 0.01));
        }
        let s = f.solve().unwrap();
        assert!((s.b[0] - 0.7).abs() < 3.0 * s.se(0), "{s:?}");
        assert!((s.b[1] + 0.2).abs() < 3.0 * s.se(1), "{s:?}");
        // Uniform noise of half-width 0.01: RMS 0.01 / sqrt(3).
        assert!((s.rms - 0.01 / 3f64.sqrt()).abs() < 5e-4, "{}", s.rms);
        // Slope error of a line: s / sqrt(sum (x - mean)^2) = 5.77e-3 / 91.2.
        assert!(
            (s.se(0) - 0.01 / 3f64.sqrt() / 91.2).abs() < 1e-5,
            "{}",
            s.se(0)
        );
    }

    #[test]
    fn exact_three_parameter_fit_and_singular_cases() {
        let mut f = Lsq::<3>::default();
        for k in 0..10 {
            let x = f64::from(k);
            f.add([x, x * x, 1.0], 2.0 * x - 0.5 * x * x + 3.0);
        }
        let s = f.solve().unwrap();
        for (b, want) in s.b.iter().zip([2.0, -0.5, 3.0]) {
            assert!((b - want).abs() < 1e-9, "{s:?}");
        }
        let mut g = Lsq::<2>::default();
        for _ in 0..5 {
            g.add([1.0, 1.0], 2.0);
        }
        assert!(g.solve().is_none());
        assert!(Lsq::<2>::default().solve().is_none());
    }

    #[test]
    fn mean_and_deviation() {
        let mut m = Mean::default();
        for x in [1.0, 2.0, 3.0, 4.0] {
            m.add(x);
        }
        assert_eq!(m.mean(), 2.5);
        assert!((m.std() - 1.290_994_448_7).abs() < 1e-9);
    }
}
