//! `pl-cosim --dir DIR [--stats FILE] [--record FILE]`: the host end of the co-simulation
//! bridge (`simpl::cosim`). Creates the FIFOs `DIR/req` and `DIR/rep`,
//! prints `ready` on stdout, then serves the firmware's requests (QEMU
//! opens `req` for writing and `rep` for reading through semihosting) with
//! the Verilated `pl_top` and the plant until the request FIFO closes. On
//! exit it prints one JSON line of statistics (to FILE, or stderr): requests,
//! PL cycles, control periods, wall seconds, control periods per wall
//! second, this process's CPU seconds (a loaded machine inflates the wall
//! time, not these), posted writes (answered with no reply), those that did
//! not end as the guest assumed, and shadow-model mismatches. Exit status 2
//! on bad arguments or when the FIFOs cannot be made, 1 on a mismatch or a
//! posted write gone wrong.
//!
//! `--record FILE` also writes every request record to FILE as received;
//! `pl-cosim --replay FILE [--stats FILE]` serves such a file's requests
//! without a guest and prints a digest of the replies: the PL side's CPU
//! time on a real request stream, without QEMU, and a check that two builds
//! answer it alike (docs/speed.md).
use rtl_sim::cosim::Bridge;
use std::fs::OpenOptions;
use std::io::{ErrorKind, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

fn usage() -> ExitCode {
    eprintln!(
        "usage: pl-cosim --dir DIR [--stats FILE] [--record FILE] | --replay FILE [--stats FILE]"
    );
    ExitCode::from(2)
}

fn fifo(p: &Path) -> Result<(), String> {
    if p.exists() {
        return Ok(());
    }
    let st = Command::new("mkfifo")
        .arg(p)
        .status()
        .map_err(|e| format!("mkfifo: {e}"))?;
    if st.success() {
        Ok(())
    } else {
        Err(format!("mkfifo {} failed", p.display()))
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut dir, mut stats, mut record, mut replay) = (None, None, None, None);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match (a.as_str(), it.next()) {
            ("--dir", Some(d)) => dir = Some(PathBuf::from(d)),
            ("--stats", Some(f)) => stats = Some(PathBuf::from(f)),
            ("--record", Some(f)) => record = Some(PathBuf::from(f)),
            ("--replay", Some(f)) => replay = Some(PathBuf::from(f)),
            _ => return usage(),
        }
    }
    if let Some(f) = replay {
        if dir.is_some() || record.is_some() {
            return usage();
        }
        let raw = match std::fs::read(&f) {
            Ok(r) if r.len() % simpl::cosim::REQUEST_LEN == 0 => r,
            Ok(_) => {
                eprintln!("pl-cosim: {}: not whole request records", f.display());
                return ExitCode::from(2);
            }
            Err(e) => {
                eprintln!("pl-cosim: {}: {e}", f.display());
                return ExitCode::from(2);
            }
        };
        let mut bridge = Bridge::new();
        let (t0, c0) = (Instant::now(), rtl_sim::thread_cpu_s());
        // FNV-1a over every reply: two builds that answer alike print the same.
        let mut digest: u64 = 0xcbf2_9ce4_8422_2325;
        for rec in raw.chunks_exact(simpl::cosim::REQUEST_LEN) {
            let mut buf = [0u8; simpl::cosim::REQUEST_LEN];
            buf.copy_from_slice(rec);
            for b in bridge.handle(&buf).map(|r| r.encode()).unwrap_or_default() {
                digest = (digest ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
            }
        }
        eprintln!("pl-cosim: replies digest {digest:016x}");
        return finish(&bridge, t0, c0, stats);
    }
    let Some(dir) = dir else { return usage() };
    let mut record = match record.map(|f| std::fs::File::create(&f).map_err(|e| (f, e))) {
        None => None,
        Some(Ok(w)) => Some(std::io::BufWriter::new(w)),
        Some(Err((f, e))) => {
            eprintln!("pl-cosim: {}: {e}", f.display());
            return ExitCode::from(2);
        }
    };
    let (req_p, rep_p) = (dir.join("req"), dir.join("rep"));
    for p in [&req_p, &rep_p] {
        if let Err(e) = fifo(p) {
            eprintln!("pl-cosim: {e}");
            return ExitCode::from(2);
        }
    }
    let mut bridge = Bridge::new();
    println!("ready");
    let _ = std::io::stdout().flush();
    // The guest opens `req` first, then `rep`: the same order here.
    let (req, rep) = match (
        OpenOptions::new().read(true).open(&req_p),
        OpenOptions::new().write(true).open(&rep_p),
    ) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("pl-cosim: cannot open the FIFOs: {e}");
            return ExitCode::from(2);
        }
    };
    let (t0, c0) = (Instant::now(), rtl_sim::thread_cpu_s());
    let mut buf = [0u8; simpl::cosim::REQUEST_LEN];
    // The guest sends its posted writes together with the next request that
    // waits: one system call takes them all.
    let mut req = std::io::BufReader::with_capacity(4096, req);
    // Replies go out when no request is left to serve: the replies to reads
    // sent together (`RegisterBus::read_many`) in one system call.
    let mut rep = std::io::BufWriter::with_capacity(4096, rep);
    loop {
        if req.buffer().is_empty() && rep.flush().is_err() {
            break;
        }
        match req.read_exact(&mut buf) {
            Ok(()) => {}
            Err(e) if e.kind() == ErrorKind::UnexpectedEof => break,
            Err(e) => {
                eprintln!("pl-cosim: request FIFO: {e}");
                break;
            }
        }
        if let Some(w) = &mut record {
            let _ = w.write_all(&buf);
        }
        // A posted write gets no reply.
        if let Some(r) = bridge.handle(&buf) {
            if rep.write_all(&r.encode()).is_err() {
                break;
            }
        }
    }
    if let Some(w) = &mut record {
        if let Err(e) = w.flush() {
            eprintln!("pl-cosim: record: {e}");
        }
    }
    finish(&bridge, t0, c0, stats)
}

/// Prints the statistics line; the exit status (1 on a mismatch).
fn finish(bridge: &Bridge, t0: Instant, c0: f64, stats: Option<PathBuf>) -> ExitCode {
    let wall = t0.elapsed().as_secs_f64();
    let cpu = rtl_sim::thread_cpu_s() - c0;
    let pl = bridge.drive().pl();
    let line = format!(
        "{{\"requests\":{},\"pl_cycles\":{},\"control_periods\":{},\"wall_s\":{:.3},\
         \"control_periods_per_wall_s\":{:.1},\"pl_cycles_per_wall_s\":{:.0},\"cpu_s\":{:.3},\
         \"pl_cycles_per_cpu_s\":{:.0},\"posted\":{},\"posted_errors\":{},\"mismatches\":{},\
         \"first_mismatch\":{:?}}}",
        bridge.requests,
        bridge.drive().pl_cycles(),
        bridge.periods,
        wall,
        bridge.periods as f64 / wall.max(1e-9),
        bridge.drive().pl_cycles() as f64 / wall.max(1e-9),
        cpu,
        bridge.drive().pl_cycles() as f64 / cpu.max(1e-9),
        bridge.posted,
        bridge.posted_errors,
        pl.mismatches(),
        pl.first_mismatch().unwrap_or("")
    );
    match stats {
        Some(f) => {
            if let Err(e) = std::fs::write(&f, format!("{line}\n")) {
                eprintln!("pl-cosim: {}: {e}", f.display());
            }
        }
        None => eprintln!("{line}"),
    }
    if pl.mismatches() > 0 || bridge.posted_errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
