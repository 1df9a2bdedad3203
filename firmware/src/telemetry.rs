//! The telemetry stream in the firmware: `drive::telemetry::Telemetry`
//! shared between the control interrupt, which samples the servo, and the
//! console's main loop, which sends the frames on the console UART when it
//! has nothing else to do (never inside a reply).
use crate::ps::timer;
use crate::ps::uart::Uart;
use core::cell::RefCell;
use core::sync::atomic::{AtomicBool, Ordering};
use drive::console::TelOps;
use drive::servo::Servo;
use drive::telemetry::{Counters, StreamSpec, TelStatus, Telemetry, FRAME_MAX};

/// Samples the queue holds: 4 s of drive time at 1 kHz, the time a long
/// console command (`sweep`) may keep the main loop from sending.
const QUEUE: usize = 4096;

struct Shared(RefCell<Telemetry<QUEUE>>);
// SAFETY: single core; every access is inside `crate::irq::free` (or in
// the control interrupt, which does not nest).
unsafe impl Sync for Shared {}
static TEL: Shared = Shared(RefCell::new(Telemetry::new()));
/// A stream runs: the control interrupt builds the sample point.
static RUNNING: AtomicBool = AtomicBool::new(false);

fn with<T>(f: impl FnOnce(&mut Telemetry<QUEUE>) -> T) -> T {
    crate::irq::free(|| f(&mut TEL.0.borrow_mut()))
}

/// Called by the control interrupt after each control step that took
/// `step_counts` global-timer counts.
pub fn on_step(servo: &Servo, step_counts: u64) {
    if !RUNNING.load(Ordering::Relaxed) {
        return;
    }
    let us = step_counts as f64 * 1e6 / f64::from(timer::PERIPHCLK_HZ);
    let p = servo.tel_point(us);
    with(|t| t.on_step(&p));
}

/// Sends up to `max` queued frames, each in one piece; returns whether it
/// sent any. Main loop only, between replies.
pub fn pump(con: &Uart, max: usize) -> bool {
    let mut sent = false;
    for _ in 0..max {
        let Some(s) = with(|t| t.pop()) else { break };
        let mut buf = [0u8; FRAME_MAX];
        let n = s.encode(&mut buf);
        con.write_bytes(&buf[..n]);
        sent = true;
    }
    sent
}

/// The console's handle on the stream.
pub struct Ops;

impl TelOps for Ops {
    fn start(&mut self, spec: StreamSpec) -> u8 {
        let n = with(|t| t.start(spec));
        RUNNING.store(true, Ordering::Relaxed);
        n
    }
    fn stop(&mut self) -> Counters {
        RUNNING.store(false, Ordering::Relaxed);
        with(|t| t.stop())
    }
    fn status(&mut self) -> TelStatus {
        with(|t| t.status())
    }
}
