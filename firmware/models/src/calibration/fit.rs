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

/// A weighted least-squares fit: coefficients, their covariance from the
/// rows' stated uncertainties alone, and the reduced chi-square of the
/// residuals (about 1 when the stated uncertainties are right).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weighted<const N: usize> {
    /// Coefficients.
    pub b: [f64; N],
    /// Their covariance from the rows' uncertainties, `(X' W X)^-1`.
    pub cov: [[f64; N]; N],
    /// Sum of the squared residuals in units of their uncertainties over
    /// the degrees of freedom.
    pub chi2: f64,
}

impl<const N: usize> Weighted<N> {
    /// Standard uncertainty of coefficient `j`: the stated uncertainties'
    /// share, scaled up when the residuals are larger than they allow
    /// (never down: a few degrees of freedom can scatter small by chance).
    pub fn sigma(&self, j: usize) -> f64 {
        libm::sqrt(self.cov[j][j].max(0.0) * self.chi2.max(1.0))
    }
}

/// Weighted least squares over the rows (regressors, value, standard
/// uncertainty of the value); `None` with too few rows, a row without a
/// finite positive uncertainty, or singular regressors. The columns are
/// scaled to unit norm first: the unknowns may differ by many orders of
/// magnitude.
pub fn weighted<const N: usize>(rows: &[([f64; N], f64, f64)]) -> Option<Weighted<N>> {
    if rows.iter().any(|r| !(r.2 > 0.0 && r.2.is_finite())) {
        return None;
    }
    let mut norm = [0.0; N];
    for (x, _, s) in rows {
        for (n, xi) in norm.iter_mut().zip(x) {
            *n += (xi / s) * (xi / s);
        }
    }
    let norm = norm.map(libm::sqrt);
    if norm.iter().any(|n| !(*n > 0.0 && n.is_finite())) {
        return None;
    }
    let mut f = Lsq::<N>::default();
    for (x, y, s) in rows {
        let mut xs = [0.0; N];
        for ((v, xi), n) in xs.iter_mut().zip(x).zip(&norm) {
            *v = xi / s / n;
        }
        f.add(xs, y / s);
    }
    let sol = f.solve()?;
    let inv = invert(&f.xtx)?;
    let mut b = sol.b;
    let mut cov = inv;
    for i in 0..N {
        b[i] /= norm[i];
        for j in 0..N {
            cov[i][j] /= norm[i] * norm[j];
        }
    }
    Some(Weighted {
        b,
        cov,
        chi2: sol.rms * sol.rms,
    })
}

/// Generalised least squares: as [`weighted`] with the values' errors
/// correlated, `cov` their covariance. The rows are whitened by the
/// covariance's Cholesky factor (`L^-1`) and fitted with unit
/// uncertainties; `None` when `cov` is not positive definite or the fit
/// singular.
pub fn generalised<const N: usize, const M: usize>(
    x: &[[f64; N]; M],
    y: &[f64; M],
    cov: &[[f64; M]; M],
) -> Option<Weighted<N>> {
    let l = cholesky(cov)?;
    let mut rows = [([0.0; N], 0.0, 1.0); M];
    // Forward substitution, one row at a time: row i of L^-1 [X y].
    for i in 0..M {
        let mut xi = x[i];
        let mut yi = y[i];
        for k in 0..i {
            for (a, b) in xi.iter_mut().zip(&rows[k].0) {
                *a -= l[i][k] * b;
            }
            yi -= l[i][k] * rows[k].1;
        }
        rows[i] = (xi.map(|v| v / l[i][i]), yi / l[i][i], 1.0);
    }
    weighted(&rows)
}

/// Lower Cholesky factor of a symmetric positive definite matrix; `None`
/// when it is not.
fn cholesky<const M: usize>(a: &[[f64; M]; M]) -> Option<[[f64; M]; M]> {
    let mut l = [[0.0; M]; M];
    for i in 0..M {
        for j in 0..=i {
            let s: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
            if i == j {
                let d = a[i][i] - s;
                if !(d > 0.0 && d.is_finite()) {
                    return None;
                }
                l[i][i] = libm::sqrt(d);
            } else {
                l[i][j] = (a[i][j] - s) / l[j][j];
            }
        }
    }
    Some(l)
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

    /// Two unknowns a million apart in size, rows of different
    /// uncertainty: recovered, the covariance from the uncertainties, the
    /// chi-square about one.
    #[test]
    fn weighted_fit_of_disparate_unknowns() {
        let mut r = Rng(5);
        let mut rows = [([0.0; 2], 0.0, 0.0); 200];
        for (k, row) in rows.iter_mut().enumerate() {
            let x = f64::from(k as u32) / 20.0;
            let s = if k % 2 == 0 { 1e-3 } else { 3e-3 };
            // y = 2e-6 x + 3.0, noise of standard deviation s (uniform).
            let y = 2e-6 * x + 3.0 + s * 3f64.sqrt() * r.uniform(-1.0, 1.0);
            *row = ([x, 1.0], y, s);
        }
        let w = weighted(&rows).unwrap();
        assert!((w.b[0] - 2e-6).abs() < 3.0 * w.sigma(0), "{w:?}");
        assert!((w.b[1] - 3.0).abs() < 3.0 * w.sigma(1), "{w:?}");
        assert!((w.chi2 - 1.0).abs() < 0.3, "{w:?}");
        rows[0].2 = 0.0;
        assert!(weighted(&rows).is_none());
    }

    /// Errors that accumulate (a random walk) fitted by generalised least
    /// squares: the same line as with the steps' own errors, independent.
    #[test]
    fn generalised_fit_of_a_random_walk() {
        const M: usize = 8;
        let mut r = Rng(9);
        let (mut x, mut y) = ([[0.0; 2]; M], [0.0; M]);
        let mut walk = 0.0;
        let mut cov = [[0.0; M]; M];
        for i in 0..M {
            walk += 0.01 * 3f64.sqrt() * r.uniform(-1.0, 1.0);
            let t = f64::from(i as u32);
            x[i] = [t, 1.0];
            y[i] = 0.5 * t + 2.0 + walk;
            for (j, c) in cov[i].iter_mut().enumerate() {
                *c = 1e-4 * f64::from(i.min(j) as u32 + 1);
            }
        }
        let g = generalised(&x, &y, &cov).unwrap();
        // The slope from the steps: their mean, its error 0.01 / sqrt(7).
        let steps: f64 = (1..M).map(|i| y[i] - y[i - 1]).sum::<f64>() / 7.0;
        assert!((g.b[0] - steps).abs() < 1e-12, "{g:?} {steps}");
        assert!((libm::sqrt(g.cov[0][0]) - 0.01 / 7f64.sqrt()).abs() < 1e-12);
        cov[0][0] = -1.0;
        assert!(generalised(&x, &y, &cov).is_none());
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
