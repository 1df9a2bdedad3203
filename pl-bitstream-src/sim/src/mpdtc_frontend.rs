//! Safe wrapper of the Verilated `mpdtc_frontend` (shim:
//! `csrc/mpdtc_frontend_shim.cpp`) and the bit-exact check against
//! `models::pmsm::frontend_fixed::frontend` behind `rtl-check frontend`.
use core::ffi::c_void;
use core::ptr::NonNull;

use models::pmsm::frontend_fixed::{frontend, FrontendInputs, FrontendOutputs, FrontendParams};
use models::pmsm::mpdtc_fixed::FixedInputs;

use crate::mpdtc_vectors::Rng;

extern "C" {
    fn fe_new() -> *mut c_void;
    fn fe_set(p: *mut c_void, v: *const i64);
    fn fe_tick(p: *mut c_void);
    fn fe_get(p: *mut c_void, o: *mut u64);
    fn fe_free(p: *mut c_void);
}

/// Sign-extends the low `bits` bits of a port value.
fn sx(v: u64, bits: u32) -> i32 {
    (((v << (64 - bits)) as i64) >> (64 - bits)) as i32
}

/// One Verilated `mpdtc_frontend`.
pub struct FrontendSim {
    ptr: NonNull<c_void>,
}

/// A result of the RTL with the cycles it took.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrontendRun {
    /// The outputs in the `out_valid` cycle.
    pub out: FrontendOutputs,
    /// Cycles from the `in_valid` cycle to `out_valid`.
    pub latency_cycles: u32,
    /// `i_d_o`, `i_q_o` kept the previous result in every cycle before
    /// `out_valid` (they are the registers MPDTC_FE_ID/IQ).
    pub currents_held: bool,
}

impl FrontendSim {
    /// A new model, reset for two cycles.
    pub fn new() -> Self {
        // SAFETY: fe_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { fe_new() }).expect("fe_new returned null");
        let mut s = Self { ptr };
        let rst = [1i64; 1]
            .iter()
            .chain([0i64; 20].iter())
            .copied()
            .collect::<Vec<_>>();
        for _ in 0..2 {
            s.set(&rst);
            s.tick();
        }
        s
    }

    fn set(&mut self, v: &[i64]) {
        assert_eq!(v.len(), 21);
        // SAFETY: live object; v holds the 21 values fe_set reads.
        unsafe { fe_set(self.ptr.as_ptr(), v.as_ptr()) }
    }

    fn tick(&mut self) {
        // SAFETY: live object.
        unsafe { fe_tick(self.ptr.as_ptr()) }
    }

    fn get(&self) -> [u64; 15] {
        let mut o = [0u64; 15];
        // SAFETY: live object; o has the 15 slots fe_get writes.
        unsafe { fe_get(self.ptr.as_ptr(), o.as_mut_ptr()) };
        o
    }

    /// Runs one period: `in_valid` for one cycle with `inp` and `p`, then
    /// clocks until `out_valid` (at most 64 cycles).
    pub fn run(&mut self, inp: &FrontendInputs, p: &FrontendParams) -> FrontendRun {
        let mut v = vec![
            0,
            1,
            inp.pos as i64,
            inp.speed as i64,
            inp.adc[0] as i64,
            inp.adc[1] as i64,
            inp.adc[2] as i64,
            inp.t_ref as i64,
            p.cpr as i64,
            p.align_pos as i64,
            p.ang_scale as i64,
            p.spd_scale as i64,
        ];
        v.extend(p.age.iter().map(|&x| x as i64));
        v.extend(p.adc_off.iter().map(|&x| x as i64));
        v.extend(p.adc_gain.iter().map(|&x| x as i64));
        let before = {
            let o = self.get();
            (o[1], o[2])
        };
        let mut currents_held = true;
        self.set(&v);
        self.tick();
        v[1] = 0;
        self.set(&v);
        let mut n = 1;
        while self.get()[0] == 0 {
            assert!(n < 64, "mpdtc_frontend: no out_valid");
            let o = self.get();
            currents_held &= (o[1], o[2]) == before;
            self.tick();
            n += 1;
        }
        let o = self.get();
        let out = FrontendOutputs {
            core: FixedInputs {
                i_dq: (sx(o[1], 25), sx(o[2], 25)),
                trig: [
                    (sx(o[3], 18), sx(o[4], 18)),
                    (sx(o[5], 18), sx(o[6], 18)),
                    (sx(o[7], 18), sx(o[8], 18)),
                ],
                w_ts: sx(o[9], 18),
                t_ref: sx(o[10], 18),
            },
            phi: o[11] as u32,
            dphi: o[12] as u32 as i32,
            i_ab: (sx(o[13], 25), sx(o[14], 25)),
        };
        // One more idle cycle so the next capture is not back to back.
        self.tick();
        FrontendRun {
            out,
            latency_cycles: n,
            currents_held,
        }
    }
}

impl Default for FrontendSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for FrontendSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from fe_new and is freed exactly once.
        unsafe { fe_free(self.ptr.as_ptr()) }
    }
}

/// Registers of a drive like the simulated one (4 pole pairs... any `pp`,
/// 4096 counts, Ts, 1 ms speed window, ADC 16/2048 A per count).
pub fn drive_params(pp: u32, align: u32, ts_s: f64) -> FrontendParams {
    let cpr = 4096.0;
    FrontendParams {
        cpr: 4096,
        align_pos: align,
        ang_scale: (f64::from(pp) * 4_294_967_296.0 / cpr).round() as u64 as u32,
        spd_scale: (f64::from(pp) * ts_s * 1_099_511_627_776.0 / (cpr * 1e-3)).round() as u32,
        age: [-8192, 57_344, 122_880],
        adc_off: [0; 3],
        adc_gain: [8192; 3],
    }
}

/// One vector: realistic (drive-like registers, in-range inputs) for even
/// `k`, any port value for odd `k`.
pub fn vector(rng: &mut Rng, k: u64) -> (FrontendInputs, FrontendParams) {
    let mut bits = |b: u32| (rng.next_u64() & ((1u64 << b) - 1)) as i64;
    if k % 2 == 0 {
        let pp = 1 + (bits(3) as u32);
        let mut p = drive_params(pp, bits(12) as u32, 15.625e-6);
        p.adc_off = [
            bits(6) as i32 - 32,
            bits(6) as i32 - 32,
            bits(6) as i32 - 32,
        ];
        let inp = FrontendInputs {
            pos: bits(12) as u32,
            speed: bits(12) as i32 - 2048,
            adc: [
                bits(12) as i32 - 2048,
                bits(12) as i32 - 2048,
                bits(12) as i32 - 2048,
            ],
            t_ref: bits(18) as i32 - (1 << 17),
        };
        (inp, p)
    } else {
        let s = |v: i64, b: u32| ((v << (64 - b)) >> (64 - b)) as i32;
        let p = FrontendParams {
            cpr: bits(16) as u32,
            align_pos: bits(16) as u32,
            ang_scale: bits(32) as u32,
            spd_scale: bits(32) as u32,
            age: [s(bits(18), 18), s(bits(18), 18), s(bits(18), 18)],
            adc_off: [s(bits(16), 16), s(bits(16), 16), s(bits(16), 16)],
            adc_gain: [s(bits(18), 18), s(bits(18), 18), s(bits(18), 18)],
        };
        let inp = FrontendInputs {
            pos: bits(16) as u32,
            speed: s(bits(16), 16),
            adc: [s(bits(16), 16), s(bits(16), 16), s(bits(16), 16)],
            t_ref: s(bits(18), 18),
        };
        (inp, p)
    }
}

/// Summary of a frontend check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrontendSummary {
    /// Vectors run.
    pub vectors: u64,
    /// Vectors with any output different from the model.
    pub mismatches: u64,
    /// The latency if it was the same for every vector.
    pub latency_cycles: Option<u32>,
    /// First mismatching vector.
    pub first_mismatch: Option<u64>,
    /// Largest |cos/sin - libm| over the realistic vectors, COEF LSB.
    pub max_trig_err_lsb: f64,
}

/// Runs `n` vectors with seed `seed` through the RTL and the model.
pub fn check(seed: u64, n: u64) -> FrontendSummary {
    let mut rng = Rng(seed);
    let mut sim = FrontendSim::new();
    let mut sum = FrontendSummary {
        vectors: 0,
        mismatches: 0,
        latency_cycles: None,
        first_mismatch: None,
        max_trig_err_lsb: 0.0,
    };
    let mut lat_varied = false;
    for k in 0..n {
        let (inp, p) = vector(&mut rng, k);
        let want = frontend(&inp, &p);
        let got = sim.run(&inp, &p);
        sum.vectors += 1;
        // A result must also leave the current registers alone until its
        // out_valid (the previous result stays readable).
        if got.out != want || !got.currents_held {
            sum.mismatches += 1;
            sum.first_mismatch.get_or_insert(k);
        }
        match sum.latency_cycles {
            None if !lat_varied => sum.latency_cycles = Some(got.latency_cycles),
            Some(l) if l != got.latency_cycles => {
                lat_varied = true;
                sum.latency_cycles = None;
            }
            _ => {}
        }
        // Accuracy against libm at the four angles the RTL evaluated.
        let offs = |j: usize| {
            ((((got.out.dphi >> 8) as i64) * (((p.age[j] as i64) << 46) >> 46)) >> 8) as u32
        };
        let mut angles = [(got.out.phi, (0, 0)); 3];
        for (j, a) in angles.iter_mut().enumerate() {
            *a = (got.out.phi.wrapping_add(offs(j)), got.out.core.trig[j]);
        }
        for (phi, (c, s)) in angles {
            let x = core::f64::consts::TAU * phi as f64 / 4_294_967_296.0;
            let e = (c as f64 - 65536.0 * x.cos())
                .abs()
                .max((s as f64 - 65536.0 * x.sin()).abs());
            sum.max_trig_err_lsb = sum.max_trig_err_lsb.max(e);
        }
    }
    sum
}
