//! Safe wrapper of the Verilated `gate_driver` (shim: `csrc/gate_driver_shim.cpp`).
use core::ffi::c_void;
use core::ptr::NonNull;

use simpl::gates::{GateInputs, GateOutputs};

extern "C" {
    fn gd_new() -> *mut c_void;
    fn gd_set_inputs(p: *mut c_void, rst: u8, en: u8, fault: u8, s: u8, dt: u16);
    fn gd_eval(p: *mut c_void);
    fn gd_tick(p: *mut c_void);
    fn gd_get_outputs(p: *mut c_void) -> u32;
    fn gd_free(p: *mut c_void);
}

/// One Verilated `gate_driver` instance (registers start at 0 = reset state).
pub struct GateDriverSim {
    ptr: NonNull<c_void>,
}

impl GateDriverSim {
    /// A new model with the clock low and reset asserted on its inputs.
    pub fn new() -> Self {
        // SAFETY: gd_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { gd_new() }).expect("gd_new returned null");
        Self { ptr }
    }

    /// Applies `inp` (clock low) and gives one rising edge; returns the
    /// registered outputs after it.
    pub fn step(&mut self, inp: &GateInputs) -> GateOutputs {
        let p = self.ptr.as_ptr();
        // SAFETY: p is the live object from gd_new; the shim masks the values
        // to the port widths.
        unsafe {
            gd_set_inputs(
                p,
                u8::from(inp.rst),
                u8::from(inp.en),
                u8::from(inp.fault),
                inp.state,
                inp.dead_time.cycles(),
            );
            gd_eval(p);
            gd_tick(p);
        }
        self.outputs()
    }

    /// Current gate outputs.
    pub fn outputs(&self) -> GateOutputs {
        // SAFETY: live object from gd_new.
        let v = unsafe { gd_get_outputs(self.ptr.as_ptr()) };
        GateOutputs {
            hi: (v & 7) as u8,
            lo: ((v >> 3) & 7) as u8,
        }
    }
}

impl Default for GateDriverSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for GateDriverSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from gd_new and is freed exactly once.
        unsafe { gd_free(self.ptr.as_ptr()) }
    }
}
