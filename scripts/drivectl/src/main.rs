//! `drivectl`: the host tool of the predictive servo drive.
//!
//! Each subcommand lives in its own module; this file only parses arguments.
use anyhow::Result;
use clap::{Parser, Subcommand};

mod calibrate_cmd;
mod console;
mod experiment;
mod experiment_move;
mod experiment_step_map;
mod explore;
mod paper_mpdcc;
mod paper_mpdtc;
mod plot;
mod running;
mod sim;
mod tel_cmd;
mod ui;

#[derive(Parser)]
#[command(
    name = "drivectl",
    version,
    about = "Host tool of the predictive servo drive"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Boot the drive once (QEMU, or share a board's --port) with its
    /// console on a local socket under target/run; every other command
    /// then uses it. Returns once it is up.
    Up(running::UpArgs),
    /// End the drive `drivectl up` started (QEMU ends cleanly).
    Down(running::DownArgs),
    /// The server `drivectl up` starts (not for direct use).
    #[command(hide = true)]
    Serve(running::UpArgs),
    /// Interactive console: over a serial port, the running drive, or a
    /// firmware booted in QEMU; Ctrl-] quits.
    Console(console::ConsoleArgs),
    /// Send one console command, print the reply, exit non-zero on `ERR`.
    Send(console::SendArgs),
    /// Measure the motor (`calibrate` on the drive) with a progress bar;
    /// write the resulting configuration (TOML) and the reply to --out;
    /// --save keeps it in the drive's flash.
    Calibrate(calibrate_cmd::CalibrateArgs),
    /// Decode a raw defmt log stream (UART0 capture) into text.
    Log(console::LogArgs),
    /// The drive's configuration as a TOML file.
    #[command(subcommand)]
    Config(ConfigCmd),
    /// Reproduce the papers' experiments.
    #[command(subcommand)]
    Paper(PaperCmd),
    /// Simulation utilities.
    #[command(subcommand)]
    Sim(SimCmd),
    /// Benchmarks (called by scripts/bench).
    #[command(subcommand)]
    Bench(BenchCmd),
    /// Experiments on the firmware (QEMU by default, --port for a board):
    /// CSV, SVG plot, table or JSON.
    #[command(subcommand)]
    Experiment(ExperimentCmd),
    /// Arm the PL capture buffer, wait for the record, write CSV and SVG.
    Capture(experiment::CaptureArgs),
    /// Design exploration (research sweeps).
    #[command(subcommand)]
    Explore(ExploreCmd),
    /// Record the live telemetry stream to CSV (lost frames reported).
    Tel(tel_cmd::TelArgs),
    /// Local web page: live plots, status, console, configuration editor,
    /// experiments (loopback only unless --allow-remote).
    Ui(ui::UiArgs),
}

#[derive(Subcommand)]
enum ExploreCmd {
    /// FPGA MPDCC model: mismatch, f_sw and THD against the reference for
    /// bounds, L, p and datapath structures.
    Mpdcc(explore::Args),
}

#[derive(Subcommand)]
enum ExperimentCmd {
    /// Torque step from rest, recorded by the PL capture buffer.
    Step(experiment::StepArgs),
    /// Frequency response of the torque loop (`sweep` on the firmware).
    Sweep(experiment::SweepArgs),
    /// Position move (`move` on the firmware) against the host simulation
    /// of the same loops; CSV and SVG of position, velocity, following
    /// error and torque.
    Move(experiment_move::MoveArgs),
    /// Torque step-response map: MPDTC and FOC on the nominal motor and the
    /// 26 corners of R, L, psi, six steps each; CSV and Markdown.
    StepMap(experiment_step_map::StepMapArgs),
}

#[derive(Subcommand)]
enum ConfigCmd {
    /// Write the drive's configuration (`config list`) to a TOML file.
    Pull(console::ConfigFileArgs),
    /// Check a TOML file against the drive's `config schema`, set its
    /// values (all or nothing), then `config save` to the drive's flash.
    Push(console::ConfigFileArgs),
}

#[derive(Subcommand)]
enum PaperCmd {
    /// Paper 000: MPDTC vs FOC on the PMSM (Tables 3, 4; Figs. 10, 11).
    Mpdtc(paper_mpdtc::Args),
    /// Paper 001: MPDCC on the 5L-ANPC + induction machine (Fig. 5, Table II).
    Mpdcc(paper_mpdcc::Args),
}

#[derive(Subcommand)]
enum SimCmd {
    /// Apply a switching-state sequence to the PMSM plant, open loop.
    Replay(sim::ReplayArgs),
}

#[derive(Subcommand)]
enum BenchCmd {
    /// PMSM closed loop (MPDTC, FOC) and open-loop replay throughput.
    Pmsm(paper_mpdtc::BenchArgs),
    /// MPDCC closed loop throughput.
    Mpdcc(paper_mpdcc::BenchArgs),
}

/// Errors are the user's to read: one line of causes, exit code 1 when the
/// drive answered `ERR`, 2 for any other failure, never a backtrace (anyhow prints one from `main` when RUST_BACKTRACE is set).
fn main() {
    // `drivectl paper mpdtc | head` must end quietly, as other command-line
    // tools do, not panic on the closed pipe: restore SIGPIPE's default action,
    // which Rust's runtime sets to "ignore".
    // SAFETY: called before any other thread exists; SIG_DFL is always valid.
    unsafe { libc::signal(libc::SIGPIPE, libc::SIG_DFL) };
    // Whatever ends this process (Ctrl-C, SIGTERM, a kill) ends the QEMU
    // and co-simulation it started.
    drivectl::link::end_children_with_parent();
    if let Err(e) = dispatch(Cli::parse().cmd) {
        // The drive's `ERR` line is already on standard output.
        if let Some(r) = e.downcast_ref::<console::Refused>() {
            eprintln!("drivectl: the drive refused {r}");
            std::process::exit(1);
        }
        eprintln!("drivectl: error: {e:#}");
        std::process::exit(2);
    }
}

fn dispatch(cmd: Cmd) -> Result<()> {
    match cmd {
        Cmd::Up(a) => running::up(a),
        Cmd::Down(a) => running::down(a),
        Cmd::Serve(a) => running::serve(a),
        Cmd::Console(a) => console::console(a),
        Cmd::Send(a) => console::send(a),
        Cmd::Calibrate(a) => calibrate_cmd::calibrate(a),
        Cmd::Log(a) => console::log(a),
        Cmd::Config(ConfigCmd::Pull(a)) => console::config_pull(a),
        Cmd::Config(ConfigCmd::Push(a)) => console::config_push(a),
        Cmd::Paper(PaperCmd::Mpdtc(a)) => paper_mpdtc::run(a),
        Cmd::Paper(PaperCmd::Mpdcc(a)) => paper_mpdcc::run(a),
        Cmd::Sim(SimCmd::Replay(a)) => sim::replay(a),
        Cmd::Bench(BenchCmd::Pmsm(a)) => paper_mpdtc::bench(a),
        Cmd::Bench(BenchCmd::Mpdcc(a)) => paper_mpdcc::bench(a),
        Cmd::Experiment(ExperimentCmd::Step(a)) => experiment::step(a),
        Cmd::Experiment(ExperimentCmd::Sweep(a)) => experiment::sweep(a),
        Cmd::Experiment(ExperimentCmd::Move(a)) => experiment_move::run(a),
        Cmd::Experiment(ExperimentCmd::StepMap(a)) => experiment_step_map::run(a),
        Cmd::Capture(a) => experiment::capture(a),
        Cmd::Explore(ExploreCmd::Mpdcc(a)) => explore::mpdcc(a),
        Cmd::Tel(a) => tel_cmd::run(a),
        Cmd::Ui(a) => ui::run(a),
    }
}
