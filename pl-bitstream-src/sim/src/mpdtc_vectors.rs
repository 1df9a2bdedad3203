//! Test vectors for `mpdtc_core` against `models::pmsm::mpdtc_fixed::decide`,
//! and the comparison loop used by the tests and `scripts/rtl-check`.
//!
//! Each vector is (state, inputs, parameters). Classes, cycled by index:
//! - realistic: the paper drive's parameter registers, currents within
//!   +-40 A, angles from a random rotor angle, speed within +-0.3 rad/period;
//! - wide: every field random over its whole format (saturation paths);
//! - corners: sector boundaries (angle = m 60 deg, +-1 LSB), zero and
//!   extreme speed, saturated currents (+-full scale), all-zero state and
//!   currents (cost ties between candidates), tolerance band 0 (no candidate
//!   in band) and full scale (all in band), zero weights and gains.
use models::pmsm::mpdtc_fixed::{self, FixedInputs, FixedParams, FixedState};
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use models::pmsm::params::MotorParams;

use crate::mpdtc_core::MpdtcCoreSim;

const CUR_MAX: i32 = (1 << 24) - 1;
const CUR_MIN: i32 = -(1 << 24);
const COEF_MAX: i32 = (1 << 17) - 1;
const COEF_MIN: i32 = -(1 << 17);
const ONE: f64 = 65536.0;

pub use models::testrng::Rng;

/// Draws over the core's formats.
trait Draw {
    fn cur(&mut self) -> i32;
    fn coef(&mut self) -> i32;
    fn amps(&mut self, a: f64) -> i32;
}

impl Draw for Rng {
    fn cur(&mut self) -> i32 {
        self.range(CUR_MIN, CUR_MAX)
    }
    fn coef(&mut self) -> i32 {
        self.range(COEF_MIN, COEF_MAX)
    }
    fn amps(&mut self, a: f64) -> i32 {
        ((self.unit() * 2.0 - 1.0) * a * ONE) as i32
    }
}

/// The paper drive's parameter registers.
pub fn paper_params() -> FixedParams {
    let cfg = MpdtcConfig::new(MotorParams::default(), MpdtcParams::default())
        .expect("default MPDTC configuration");
    FixedParams::from_config(&cfg).expect("default fixed-point registers")
}

fn trig(theta: f64) -> (i32, i32) {
    let q = |x: f64| (libm_round(x * ONE) as i32).clamp(COEF_MIN, COEF_MAX);
    (q(theta.cos()), q(theta.sin()))
}

fn libm_round(x: f64) -> f64 {
    x.round()
}

fn trig3(theta: f64, w: f64) -> [(i32, i32); 3] {
    [
        trig(theta - 0.5 * w),
        trig(theta + 0.5 * w),
        trig(theta + 1.5 * w),
    ]
}

fn realistic(rng: &mut Rng, base: &FixedParams) -> (FixedState, FixedInputs, FixedParams) {
    let w = (rng.unit() * 2.0 - 1.0) * 0.3;
    let theta = rng.unit() * std::f64::consts::TAU;
    let mut p = *base;
    p.tol = rng.range(0, 3 * 65536);
    p.int_conditional = rng.range(0, 1) == 1;
    let st = FixedState {
        s_applied: rng.range(0, 7) as u8,
        s_prev: rng.range(0, 7) as u8,
        eta_prev: (
            rng.range(-p.eta_lim, p.eta_lim),
            rng.range(-p.eta_lim, p.eta_lim),
        ),
        x: rng.range(-p.int_lim, p.int_lim),
        band_reached: rng.range(0, 1) == 1,
        iq_ref_prev: rng.amps(20.0),
        i_hat: (rng.amps(40.0), rng.amps(40.0)),
        nu: (
            rng.range(-p.eta_lim, p.eta_lim),
            rng.range(-p.eta_lim, p.eta_lim),
        ),
    };
    let inp = FixedInputs {
        i_dq: (rng.amps(40.0), rng.amps(40.0)),
        trig: trig3(theta, w),
        w_ts: (w * ONE) as i32,
        t_ref: rng.range(-(2 << 14), 2 << 14),
    };
    (st, inp, p)
}

fn wide(rng: &mut Rng) -> (FixedState, FixedInputs, FixedParams) {
    let p = FixedParams {
        a: rng.coef(),
        lambda: rng.coef(),
        u0: rng.cur(),
        u0_half: rng.cur(),
        u0_h: rng.cur(),
        psi_l: rng.cur(),
        kinv_t: rng.cur(),
        tol: rng.range(0, CUR_MAX),
        k_int: rng.coef(),
        int_lim: rng.range(0, CUR_MAX),
        int_conditional: rng.range(0, 1) == 1,
        kp_o: rng.coef(),
        ki_o: rng.coef(),
        eta_lim: rng.range(0, CUR_MAX),
        w2: [rng.coef(), rng.coef(), rng.coef(), rng.coef()],
    };
    let st = FixedState {
        s_applied: rng.range(0, 7) as u8,
        s_prev: rng.range(0, 7) as u8,
        eta_prev: (rng.cur(), rng.cur()),
        x: rng.cur(),
        band_reached: rng.range(0, 1) == 1,
        iq_ref_prev: rng.cur(),
        i_hat: (rng.cur(), rng.cur()),
        nu: (rng.cur(), rng.cur()),
    };
    let inp = FixedInputs {
        i_dq: (rng.cur(), rng.cur()),
        trig: [
            (rng.coef(), rng.coef()),
            (rng.coef(), rng.coef()),
            (rng.coef(), rng.coef()),
        ],
        w_ts: rng.coef(),
        t_ref: rng.coef(),
    };
    (st, inp, p)
}

fn corner(rng: &mut Rng, base: &FixedParams, k: u64) -> (FixedState, FixedInputs, FixedParams) {
    let (mut st, mut inp, mut p) = realistic(rng, base);
    match k % 11 {
        0 => {
            // Sector boundary, +-1 LSB on cos/sin.
            let m = rng.range(0, 5) as f64;
            let th = m * std::f64::consts::FRAC_PI_3;
            inp.trig = [trig(th), trig(th), trig(th)];
            let d = rng.range(-1, 1);
            for t in inp.trig.iter_mut() {
                t.0 = (t.0 + d).clamp(COEF_MIN, COEF_MAX);
                t.1 = (t.1 - d).clamp(COEF_MIN, COEF_MAX);
            }
        }
        1 => inp.w_ts = 0,
        2 => {
            inp.w_ts = if rng.range(0, 1) == 0 {
                COEF_MAX
            } else {
                COEF_MIN
            }
        }
        3 => {
            // Saturated currents.
            let f = |r: &mut Rng| if r.range(0, 1) == 0 { CUR_MAX } else { CUR_MIN };
            inp.i_dq = (f(rng), f(rng));
            st.i_hat = (f(rng), f(rng));
        }
        4 => {
            // Everything at rest: all candidates tie on cost (ties by n, index).
            st = FixedState {
                s_applied: rng.range(0, 7) as u8,
                s_prev: rng.range(0, 7) as u8,
                ..FixedState::default()
            };
            inp.i_dq = (0, 0);
            inp.t_ref = 0;
            inp.w_ts = 0;
            p.u0 = 0;
            p.u0_half = 0;
            p.u0_h = 0;
        }
        5 => p.tol = 0,
        6 => p.tol = CUR_MAX,
        7 => {
            p.w2 = [0; 4];
            p.kp_o = 0;
            p.ki_o = 0;
        }
        8 => {
            // Limits at their extremes.
            p.eta_lim = if rng.range(0, 1) == 0 { 0 } else { CUR_MAX };
            p.int_lim = if rng.range(0, 1) == 0 { 0 } else { CUR_MAX };
        }
        9 => {
            // Exact tie between two candidates with the same transition
            // count: legs a and b identical (u0/2 = -u0, u0h = 0, angle 0),
            // state 000, current pointing against them: 010 and 100 tie and
            // beat 000; the lower index (010) must win.
            p.u0 = rng.range(1 << 14, 1 << 18);
            p.u0_half = -p.u0;
            p.u0_h = 0;
            p.w2 = [1 << 14; 4];
            inp.trig = [(1 << 16, 0); 3];
            inp.w_ts = 0;
            inp.i_dq = (-p.u0, 0);
            st = FixedState {
                i_hat: (-p.u0, 0),
                ..FixedState::default()
            };
            p.tol = CUR_MAX;
        }
        _ => {
            // Equal weights: candidates with equal |I| tie on J^2.
            p.w2 = [1 << 14; 4];
            inp.i_dq = (0, 0);
            st.i_hat = (0, 0);
        }
    }
    (st, inp, p)
}

/// Vector `idx` of the stream with `seed`.
pub fn vector(
    rng: &mut Rng,
    base: &FixedParams,
    idx: u64,
) -> (FixedState, FixedInputs, FixedParams) {
    match idx % 4 {
        0 | 1 => realistic(rng, base),
        2 => wide(rng),
        _ => corner(rng, base, idx / 4),
    }
}

/// Whether the decision had an exact tie (same band flag, value and
/// transition count) for the best key, so that the index rule decided.
pub fn had_tie(out: &models::pmsm::mpdtc_fixed::FixedOutputs, tol: i32, s_applied: u8) -> bool {
    let key = |s: usize| {
        let n = ((s as u8 ^ s_applied) & 7).count_ones() as i64;
        if out.err[s] <= tol {
            (0i64, out.cost2[s], n)
        } else {
            (1i64, out.err[s] as i64, n)
        }
    };
    let best = key(out.s_next as usize);
    (0..8).filter(|&s| key(s) == best).count() > 1
}

/// Result of a comparison run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CheckSummary {
    /// Vectors run.
    pub vectors: u64,
    /// Vectors with any output differing from the model.
    pub mismatches: u64,
    /// Latency measured on every vector (`None` if it varied).
    pub latency_cycles: Option<u32>,
    /// Index of the first mismatching vector.
    pub first_mismatch: Option<u64>,
    /// Candidates selected by the band path vs. the error path (coverage).
    pub in_band_decisions: u64,
    /// Decisions settled by the index tie rule (coverage).
    pub ties: u64,
}

/// Runs `n` vectors from `seed` through the RTL and the model.
pub fn check(seed: u64, n: u64) -> CheckSummary {
    let base = paper_params();
    let mut rng = Rng(seed);
    let mut sim = MpdtcCoreSim::new();
    let mut sum = CheckSummary {
        vectors: 0,
        mismatches: 0,
        latency_cycles: None,
        first_mismatch: None,
        in_band_decisions: 0,
        ties: 0,
    };
    let mut lat: Option<u32> = None;
    let mut lat_varied = false;
    for idx in 0..n {
        let (st, inp, p) = vector(&mut rng, &base, idx);
        let want = mpdtc_fixed::decide(&st, &inp, &p);
        let got = sim.decide(&st, &inp, &p);
        if got.out != want || !got.ready_at_output {
            sum.mismatches += 1;
            if sum.first_mismatch.is_none() {
                sum.first_mismatch = Some(idx);
            }
        }
        if want.err[want.s_next as usize] <= p.tol {
            sum.in_band_decisions += 1;
        }
        if had_tie(&want, p.tol, st.s_applied) {
            sum.ties += 1;
        }
        match lat {
            None => lat = Some(got.latency_cycles),
            Some(l) if l != got.latency_cycles => lat_varied = true,
            _ => {}
        }
        sum.vectors += 1;
    }
    sum.latency_cycles = if lat_varied { None } else { lat };
    sum
}
