//! Division-free computation of `l_j` (paper 001, Section VI-B, Algorithm 2),
//! beside the exact floor formula of eq. (24) it replaces.
//!
//! # Integer form used by the FPGA model
//! The explorer predicts the error of output `j` at `k` (`a_j`) and at
//! `k + L` (`a_j + delta_j`), both as raw integers of one fixed-point format
//! (see [`super::formats`]), with `L = 2^lambda`. Eq. (20)-(21) give the
//! interpolated error `a_j + l * delta_j / L`. Instead of dividing `delta_j`
//! by `L` (which would drop `lambda` bits, eq. (20)), both sides of (23) are
//! multiplied by `L` (a left shift), so the constraint becomes, exactly,
//!
//! ```text
//!     | L a_j + l delta_j | <= L bnd_j
//! ```
//!
//! Interpretation (the paper only says divisions by `L` are shifts): folding
//! `1/L` into the bound keeps every bit; the comparator grows by `lambda` bits,
//! which costs no multiplier.
//!
//! With `x_j = |delta_j|` and `y_j = L (bnd_j -+ |a_j|)` (minus when the error
//! moves towards the nearer bound, `a_j delta_j > 0`; plus when it first moves
//! back through zero, `a_j delta_j < 0`; eq. (24)), `l_j = floor(y_j / x_j)`,
//! which Algorithm 2 finds bit by bit with one add and one compare per bit.
//!
//! # Interpretations of Algorithm 2
//! - Line 10 reads "`b + c < y_j`" in the extracted text; (25b) says
//!   `x_j l <= y_j`, and eq. (24) is a floor, so `<=` is used (with `<`, exact
//!   multiples `y_j = l x_j` would come out one step short).
//! - `c` halves each iteration; that is exact only if the search range is a
//!   power of two. The search therefore always runs over `M` bits with
//!   `c_0 = 2^M x_j`, and the upper cap `L_up` (any value `<= 2^M`) is checked
//!   first, as line 3-5 do with `c = L_up x_j`.
//! - `a` starts at `2^M - 1` (all undecided bits one) and is the running upper
//!   bound on `l_j`; the early exit (line 15) fires when it drops below the
//!   lower bound `L_low`.

/// Outcome of one search lane (one output `j`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "std", derive(serde::Serialize))]
pub enum Lj {
    /// `l_j >= L_up`: the cap is returned (Algorithm 2, line 4-5).
    Capped(u32),
    /// `L_low <= l_j < L_up`, the exact value.
    Exact(u32),
    /// `l_j < L_low` (Algorithm 2, line 15-16, or `|a_j| > bnd_j`).
    Below,
}

impl Lj {
    /// The value of `l_j` after capping; `Below` maps to `None`.
    pub fn value(self) -> Option<u32> {
        match self {
            Lj::Capped(l) | Lj::Exact(l) => Some(l),
            Lj::Below => None,
        }
    }
}

/// Parameters of one search: `2^m_bits >= l_up >= l_low`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SearchRange {
    /// `M`: number of bits searched (`1..=16`).
    pub m_bits: u32,
    /// `L_up`, steps: cap on `l_j` (`1..=2^M`).
    pub l_up: u32,
    /// `L_low`, steps: values below it are not needed (`0..=L_up`).
    pub l_low: u32,
}

/// Errors of [`SearchRange::new`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SearchRangeError {
    /// `m_bits` outside `1..=16`.
    Bits,
    /// `l_up` is 0 or larger than `2^m_bits`.
    Upper,
    /// `l_low > l_up`.
    Lower,
}

impl SearchRange {
    /// Validated range.
    pub fn new(m_bits: u32, l_up: u32, l_low: u32) -> Result<Self, SearchRangeError> {
        if !(1..=16).contains(&m_bits) {
            return Err(SearchRangeError::Bits);
        }
        if l_up == 0 || l_up > (1u32 << m_bits) {
            return Err(SearchRangeError::Upper);
        }
        if l_low > l_up {
            return Err(SearchRangeError::Lower);
        }
        Ok(Self {
            m_bits,
            l_up,
            l_low,
        })
    }
}

/// Result of [`search`]: the lane outcome and the clock cycles it took
/// (one for the cap test, one per examined bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Search {
    /// Outcome.
    pub lj: Lj,
    /// Clock cycles used by this lane.
    pub cycles: u32,
}

/// Algorithm 2: largest `l` in `[L_low, L_up]` with `x l <= y`, for `x > 0`,
/// `y >= 0` (raw integers). `x = 0` means the output never moves: capped.
/// Integer widths: `x < 2^32`, `y < 2^48`; internal sums fit in `u64`
/// because `2^M x < 2^48`.
pub fn search(x: u64, y: u64, r: SearchRange) -> Search {
    // Line 3-6: cap test. `l_up * x` is a constant shift when L_up = 2^M.
    if x == 0 || (r.l_up as u64) * x <= y {
        return Search {
            lj: Lj::Capped(r.l_up),
            cycles: 1,
        };
    }
    let mut l: u32 = 0; // line 1
    let mut b: u64 = 0; // line 2: x * (bits of l decided so far)
    let mut c: u64 = x << r.m_bits; // c_0 = 2^M x, halved before use
    let mut a: u32 = (1u32 << r.m_bits) - 1; // line 7: upper bound on l
    let mut cycles = 1;
    for m in (0..r.m_bits).rev() {
        cycles += 1;
        c >>= 1; // line 9, exact: c = 2^m x
        if b + c <= y {
            // line 10-12
            b += c;
            l |= 1 << m;
        } else {
            // line 14-17
            a &= !(1u32 << m);
            if a < r.l_low {
                return Search {
                    lj: Lj::Below,
                    cycles,
                };
            }
        }
    }
    // `l < L_up` here because `L_up x > y`; `a == l` after the last bit.
    let lj = if l < r.l_low { Lj::Below } else { Lj::Exact(l) };
    Search { lj, cycles }
}

/// Maps one output's interpolation data to the search inputs `(x_j, y_j)`,
/// or `None` when `|a_j| > bnd_j` (`l_j = 0`, first case of eq. (24)).
/// `a`, `delta`, `bnd` are raw integers of the same format, `bnd >= 0`,
/// `lambda = log2(L)`.
pub fn search_inputs(a: i32, delta: i32, bnd: i32, lambda: u32) -> Option<(u64, u64)> {
    let abs_a = (a as i64).abs();
    let bnd = bnd as i64;
    if abs_a > bnd {
        return None;
    }
    let x = (delta as i64).unsigned_abs();
    // a * delta > 0: towards the near bound; otherwise (including a = 0 or
    // delta = 0) through zero to the far one. For a = 0 both agree.
    let towards = (a > 0 && delta > 0) || (a < 0 && delta < 0);
    let margin = if towards { bnd - abs_a } else { bnd + abs_a };
    Some((x, (margin as u64) << lambda))
}

/// `l_j` for one output with Algorithm 2 (search lane of an explorer).
pub fn lj_search(a: i32, delta: i32, bnd: i32, lambda: u32, r: SearchRange) -> Search {
    match search_inputs(a, delta, bnd, lambda) {
        // The `|a| > bnd` compare is the lane's first cycle.
        None => Search {
            lj: Lj::Below,
            cycles: 1,
        },
        Some((x, y)) => search(x, y, r),
    }
}

/// Eq. (24) evaluated exactly with rational arithmetic (`b_j = delta / L`),
/// `None` meaning `+inf`. The oracle for Algorithm 2.
pub fn lj_exact_eq24(a: i32, delta: i32, bnd: i32, lambda: u32) -> Option<u64> {
    let (a, d, bnd) = (a as i64, delta as i64, bnd as i64);
    let l = 1i64 << lambda;
    if a.abs() > bnd {
        return Some(0);
    }
    if d == 0 {
        return None;
    }
    // |b_j| = |d| / L, so floor((bnd -+ |a|) / |b_j|) = floor(L (bnd -+ |a|) / |d|).
    let num = if a == 0 {
        bnd
    } else if a * d < 0 {
        bnd + a.abs()
    } else {
        bnd - a.abs()
    };
    Some(((num * l) / d.abs()) as u64)
}

/// Eq. (24) then the cap and the floor of [`SearchRange`], as the search
/// should report it.
pub fn lj_reference(a: i32, delta: i32, bnd: i32, lambda: u32, r: SearchRange) -> Lj {
    let l = match lj_exact_eq24(a, delta, bnd, lambda) {
        None => return Lj::Capped(r.l_up),
        Some(l) => l,
    };
    if l >= r.l_up as u64 {
        Lj::Capped(r.l_up)
    } else if l < r.l_low as u64 || (l == 0 && (a as i64).abs() > bnd as i64) {
        Lj::Below
    } else {
        Lj::Exact(l as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Largest l in 0..=cap with |L a + l d| <= L bnd, by scanning: a third,
    /// independent statement of (23).
    fn scan(a: i32, d: i32, bnd: i32, lambda: u32, cap: u32) -> u32 {
        let big_l = 1i64 << lambda;
        let ok = |l: i64| (big_l * a as i64 + l * d as i64).abs() <= big_l * bnd as i64;
        if !ok(0) {
            return 0;
        }
        let mut l = 0;
        while l < cap as i64 && ok(l + 1) {
            l += 1;
        }
        l as u32
    }

    #[test]
    fn paper_fig4_example() {
        // L_up = 8, L_low = 2, x = 0.25, y = 1.3 -> l_j = 5 after 3 steps.
        // In Q.8: x = 64, y = 332.8 -> 332 (still floor(332/64) = 5).
        let r = SearchRange::new(3, 8, 2).unwrap();
        let s = search(64, 332, r);
        assert_eq!(s.lj, Lj::Exact(5));
        assert_eq!(s.cycles, 4);
    }

    #[test]
    fn exact_multiple_is_included() {
        // y = 5 x exactly: floor gives 5, a strict '<' would give 4.
        let r = SearchRange::new(3, 8, 0).unwrap();
        assert_eq!(search(64, 320, r).lj, Lj::Exact(5));
    }

    #[test]
    fn range_validation() {
        assert_eq!(SearchRange::new(0, 1, 0), Err(SearchRangeError::Bits));
        assert_eq!(SearchRange::new(17, 1, 0), Err(SearchRangeError::Bits));
        assert_eq!(SearchRange::new(3, 9, 0), Err(SearchRangeError::Upper));
        assert_eq!(SearchRange::new(3, 0, 0), Err(SearchRangeError::Upper));
        assert_eq!(SearchRange::new(3, 8, 9), Err(SearchRangeError::Lower));
        assert!(SearchRange::new(7, 100, 1).is_ok());
    }

    /// Exhaustive over a reduced word width: every (x, y) with x in 1..2^9,
    /// y in 0..2^13, for several caps and floors, against floor(y / x).
    #[test]
    fn exhaustive_xy_against_floor() {
        for &(m, up, low) in &[(7u32, 128u32, 0u32), (7, 100, 1), (5, 32, 3), (3, 8, 2)] {
            let r = SearchRange::new(m, up, low).unwrap();
            for x in 1u64..(1 << 9) {
                for y in 0u64..(1 << 13) {
                    let f = y / x;
                    let want = if f >= up as u64 {
                        Lj::Capped(up)
                    } else if f < low as u64 {
                        Lj::Below
                    } else {
                        Lj::Exact(f as u32)
                    };
                    let got = search(x, y, r);
                    assert_eq!(got.lj, want, "x={x} y={y} r={r:?}");
                    assert!(got.cycles <= m + 1);
                }
            }
        }
    }

    /// Exhaustive over (a_j, delta_j) for a 9-bit signed error word and
    /// several bounds: Algorithm 2 == eq. (24) == a linear scan of (23).
    #[test]
    fn exhaustive_eq24_small_words() {
        let r = SearchRange::new(6, 64, 0).unwrap();
        for &bnd in &[0i32, 1, 7, 100, 255] {
            for lambda in [0u32, 3, 5] {
                for a in -256i32..256 {
                    for d in -256i32..256 {
                        let got = lj_search(a, d, bnd, lambda, r).lj;
                        let want = lj_reference(a, d, bnd, lambda, r);
                        assert_eq!(got, want, "a={a} d={d} bnd={bnd} lambda={lambda}");
                        let s = scan(a, d, bnd, lambda, 64);
                        let v = got.value().unwrap_or(0);
                        assert_eq!(v, s, "scan a={a} d={d} bnd={bnd} lambda={lambda}");
                    }
                }
            }
        }
    }

    /// Large randomized check over the full 16-bit error words used by the
    /// FPGA model (a, delta in i16, bnd in 0..2^15, L = 2^0..2^6, M = 7).
    #[test]
    fn randomized_full_width_eq24() {
        let mut rng = crate::testrng::Rng(0x9E37_79B9_7F4A_7C15);
        let mut next = || rng.next_u64();
        for _ in 0..2_000_000 {
            let v = next();
            let a = (v as u16) as i16 as i32;
            let d = ((v >> 16) as u16) as i16 as i32;
            // Bias half of the draws to small deltas, where l_j is large.
            let d = if v >> 63 == 1 {
                d >> ((v >> 40) & 15)
            } else {
                d
            };
            let bnd = ((v >> 32) as u16 & 0x7FFF) as i32;
            let lambda = ((v >> 48) % 7) as u32;
            let low = ((v >> 52) % 4) as u32;
            let r = SearchRange::new(7, 128, low).unwrap();
            let got = lj_search(a, d, bnd, lambda, r);
            assert_eq!(
                got.lj,
                lj_reference(a, d, bnd, lambda, r),
                "a={a} d={d} bnd={bnd} lambda={lambda} low={low}"
            );
            assert!(got.cycles <= 8);
        }
    }

    #[test]
    fn worst_case_cycles_is_m_plus_one() {
        // All bits examined: y just below the cap, no early exit.
        let r = SearchRange::new(7, 128, 0).unwrap();
        assert_eq!(search(1, 127, r).cycles, 8);
        assert_eq!(search(1, 127, r).lj, Lj::Exact(127));
        // Early exit: the first cleared bit already drops a below L_low.
        let r = SearchRange::new(7, 128, 100).unwrap();
        let s = search(1, 10, r);
        assert_eq!(s.lj, Lj::Below);
        assert_eq!(s.cycles, 2);
    }
}
