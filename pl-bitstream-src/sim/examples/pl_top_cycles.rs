//! The Verilated `pl_top`'s evaluation speed alone: `N` clock cycles
//! (default 200,000) after reset with idle inputs, as the co-simulation
//! steps it (`PlTopSim::step`, two evaluations per cycle). Prints the
//! cycles, the CPU seconds of this thread (`/proc/thread-self/schedstat`,
//! so a loaded machine inflates only the wall time) and the wall seconds.
//! `cargo run --release -p rtl-sim --example pl_top_cycles [N]`
//! (docs/speed.md).
use std::time::Instant;

fn main() {
    let n: u32 = match std::env::args().nth(1).map(|a| a.parse()) {
        None => 200_000,
        Some(Ok(n)) => n,
        Some(Err(_)) => {
            eprintln!("usage: pl_top_cycles [cycles]");
            std::process::exit(2);
        }
    };
    let mut pl = rtl_sim::pl_top::PlTopSim::new();
    let (c0, t0) = (rtl_sim::thread_cpu_s(), Instant::now());
    pl.idle(n);
    let (cpu, wall) = (rtl_sim::thread_cpu_s() - c0, t0.elapsed().as_secs_f64());
    println!(
        "pl_top: {n} cycles, {cpu:.3} CPU s, {wall:.3} wall s, {:.0} cycles per CPU s",
        f64::from(n) / cpu.max(1e-9)
    );
}
