//! Safe wrapper of the Verilated `mpdcc_lane` (shim:
//! `csrc/mpdcc_lane_shim.cpp`): streams lane inputs one per clock and
//! returns `l_j` of each with its latency.
use core::ffi::c_void;
use core::ptr::NonNull;

/// One lane input: the raw words of `models::mpdcc::mpdcc_fixed::lane`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LaneInput {
    /// Error at `k`, Q2.13.
    pub e0: i16,
    /// Node changes at `k + 8, 16, 32, 64`, Q4.13 (18-bit, `|n| < 2^17`).
    pub nodes: [i32; 4],
    /// Bound, Q2.13, `>= 0`.
    pub bnd: i16,
    /// Idle clock cycles before this input is offered.
    pub idle_before: u32,
}

/// One lane output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LaneOutput {
    /// `l_j`, steps (0..=128).
    pub lj: u32,
    /// Cycles from the input's strobe to its output strobe.
    pub latency_cycles: u32,
}

#[repr(C)]
struct MlIn {
    e0: i32,
    n: [i32; 4],
    bnd: i32,
    idle_before: i32,
}

#[repr(C)]
#[derive(Default, Clone, Copy)]
struct MlOut {
    lj: i32,
    latency: i32,
}

extern "C" {
    fn ml_new() -> *mut c_void;
    fn ml_run(p: *mut c_void, n: i32, inp: *const MlIn, out: *mut MlOut) -> i32;
    fn ml_free(p: *mut c_void);
}

/// One Verilated `mpdcc_lane`.
pub struct MpdccLaneSim {
    ptr: NonNull<c_void>,
}

impl MpdccLaneSim {
    /// A new lane after reset.
    pub fn new() -> Self {
        // SAFETY: ml_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { ml_new() }).expect("ml_new returned null");
        Self { ptr }
    }

    /// Streams `inputs` (in order, each after its idle cycles) and returns
    /// the outputs in arrival order; fewer outputs than inputs means the
    /// core lost some.
    pub fn run(&mut self, inputs: &[LaneInput]) -> Vec<LaneOutput> {
        let inp: Vec<MlIn> = inputs
            .iter()
            .map(|v| MlIn {
                e0: i32::from(v.e0),
                n: v.nodes,
                bnd: i32::from(v.bnd),
                idle_before: v.idle_before.min(1000) as i32,
            })
            .collect();
        let mut out = vec![MlOut::default(); inp.len()];
        let n = i32::try_from(inp.len()).expect("batch below 2^31");
        // SAFETY: live object; `inp` and `out` hold `n` repr(C) elements.
        let got = unsafe { ml_run(self.ptr.as_ptr(), n, inp.as_ptr(), out.as_mut_ptr()) };
        out.truncate(got.max(0) as usize);
        out.iter()
            .map(|o| LaneOutput {
                lj: o.lj as u32,
                latency_cycles: o.latency as u32,
            })
            .collect()
    }
}

impl Default for MpdccLaneSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for MpdccLaneSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from ml_new and is freed exactly once.
        unsafe { ml_free(self.ptr.as_ptr()) }
    }
}
