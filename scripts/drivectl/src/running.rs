//! `drivectl up`, `drivectl down` and the server they run (`drivectl
//! serve`): one drive booted once, its console shared on a local socket
//! (see `drivectl::server`), so that every other command talks to the
//! same drive as tools on a bench do.
use crate::console::{timeout, Target};
use anyhow::{bail, Context as _, Result};
use drivectl::defmt_log::LiveLog;
use drivectl::link::Session;
use drivectl::server::{self, RunDir};
use std::os::unix::net::UnixListener;
use std::os::unix::process::CommandExt as _;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[derive(clap::Args)]
pub struct UpArgs {
    #[command(flatten)]
    pub target: Target,
    /// Seconds to wait for the drive to boot.
    #[arg(long, default_value_t = 60.0)]
    pub timeout_s: f64,
}

#[derive(clap::Args)]
pub struct DownArgs {
    /// Seconds to wait for the drive to end (then it is killed).
    #[arg(long, default_value_t = 20.0)]
    pub timeout_s: f64,
}

/// What a running drive is, for its `drive.info` and the messages.
fn describe(t: &Target) -> String {
    match &t.port {
        Some(p) => format!("the board on {p} at {} baud", t.baud),
        None => format!(
            "QEMU with the {} PL{}",
            if t.pl == "rtl" {
                "co-simulated (Verilated)"
            } else {
                "simulated"
            },
            if t.icount { ", -icount" } else { "" }
        ),
    }
}

pub fn up(a: UpArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let run = RunDir::default_dir();
    if let (Some(pid), Some(sock)) = (run.running_pid(), run.live_socket()) {
        let info = std::fs::read_to_string(run.info()).unwrap_or_default();
        println!(
            "drivectl: a drive is already running: {} (server pid {pid}), console {}; \
             `drivectl down` ends it",
            info.trim(),
            sock.display()
        );
        return Ok(());
    }
    std::fs::create_dir_all(&run.dir)
        .with_context(|| format!("cannot create {}", run.dir.display()))?;
    let log = std::fs::File::create(run.log())
        .with_context(|| format!("cannot create {}", run.log().display()))?;
    // The same arguments, `serve` for `up`: the server is this program.
    let mut args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let k = args
        .iter()
        .position(|x| x == "up")
        .context("`up` not among the arguments")?;
    args[k] = "serve".into();
    let exe = std::env::current_exe().context("cannot find drivectl's own executable")?;
    let mut cmd = Command::new(exe);
    cmd.args(&args)
        .env("DRIVECTL_RUN_DIR", &run.dir)
        .stdin(Stdio::null())
        .stdout(log.try_clone()?)
        .stderr(log);
    // Its own session: the terminal's Ctrl-C and hang-up are not its.
    // SAFETY: setsid is async-signal-safe; it runs in the child before exec.
    unsafe {
        cmd.pre_exec(|| {
            libc::setsid();
            Ok(())
        });
    }
    let mut child = cmd.spawn().context("cannot start the drive's server")?;
    eprintln!("drivectl: booting {}", describe(&a.target));
    let t0 = Instant::now();
    loop {
        if let Some(status) = child.try_wait()? {
            let text = std::fs::read_to_string(run.log()).unwrap_or_default();
            bail!(
                "the drive's server ended ({status}) before its console was up; its log ({}):\n{}",
                run.log().display(),
                text.trim_end()
            );
        }
        if let Some(sock) = run.live_socket() {
            if run.running_pid() == Some(child.id() as i32) {
                println!("drive running: {}", describe(&a.target));
                println!("  console socket  {}", sock.display());
                println!("  server pid      {}", child.id());
                println!("  defmt log       {}", run.defmt_log().display());
                println!("  server log      {}", run.log().display());
                println!(
                    "drivectl commands (send, tel, calibrate, ui, console, ...) now use it; \
                     `drivectl down` (or scripts/run --stop) ends it"
                );
                return Ok(());
            }
        }
        if t0.elapsed() > t {
            // SAFETY: kill(2) on the server this call started.
            unsafe { libc::kill(child.id() as i32, libc::SIGTERM) };
            let _ = child.wait();
            bail!(
                "the drive did not come up within {t:?}; see {}",
                run.log().display()
            );
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

pub fn down(a: DownArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let run = RunDir::default_dir();
    let Some(pid) = run.running_pid() else {
        // A stale socket of a server that was killed is only a file.
        let _ = std::fs::remove_file(run.socket());
        let _ = std::fs::remove_file(run.pid_file());
        println!("drivectl: no drive running ({})", run.dir.display());
        return Ok(());
    };
    // SAFETY: kill(2) with SIGTERM on the pid the server wrote.
    unsafe { libc::kill(pid, libc::SIGTERM) };
    let t0 = Instant::now();
    // SAFETY: signal 0 only checks that the process exists.
    while unsafe { libc::kill(pid, 0) } == 0 {
        if t0.elapsed() > t {
            // SAFETY: as above; its QEMU ends with it (PR_SET_PDEATHSIG).
            unsafe { libc::kill(pid, libc::SIGKILL) };
            let _ = std::fs::remove_file(run.socket());
            let _ = std::fs::remove_file(run.pid_file());
            bail!("the drive's server (pid {pid}) did not end within {t:?} of SIGTERM: killed");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    // The server's last words say whether QEMU ended cleanly.
    let log = std::fs::read_to_string(run.log()).unwrap_or_default();
    if let Some(e) = log.lines().find(|l| l.contains("error:")) {
        bail!(
            "the drive's server (pid {pid}) ended with: {e} (log {})",
            run.log().display()
        );
    }
    println!("drivectl: drive stopped (server pid {pid}; QEMU ended cleanly, flash writes kept)");
    Ok(())
}

/// Blocks SIGTERM, SIGINT and SIGHUP in this thread (and the threads it
/// starts) and returns them as a set for `sigwait`.
fn block_signals() -> libc::sigset_t {
    // SAFETY: plain libc signal-set calls on a local set.
    unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        for s in [libc::SIGTERM, libc::SIGINT, libc::SIGHUP] {
            libc::sigaddset(&mut set, s);
        }
        libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut());
        set
    }
}

/// The server: boots the drive, serves its console on the run directory's
/// socket until SIGTERM (or SIGINT, SIGHUP), then ends QEMU cleanly and
/// removes its files.
pub fn serve(a: UpArgs) -> Result<()> {
    // Before any thread: every thread then has them blocked and only the
    // waiting thread below takes them. Children start with an empty mask
    // (the standard library resets it before exec).
    let signals = block_signals();
    let t = timeout(a.timeout_s)?;
    let run = RunDir::default_dir();
    if let Some(pid) = run.running_pid() {
        bail!(
            "a drive's server already runs (pid {pid}, {})",
            run.dir.display()
        );
    }
    std::fs::create_dir_all(&run.dir)?;
    let _ = std::fs::remove_file(run.socket());
    let listener = UnixListener::bind(run.socket())
        .with_context(|| format!("cannot listen on {}", run.socket().display()))?;
    let mut q = a.target.qemu();
    let decoder = match a.target.port {
        None => {
            let live = LiveLog::start(&q.elf, &run.defmt_log())?;
            q.defmt_raw = Some(live.raw().to_path_buf());
            Some(live)
        }
        Some(_) => None,
    };
    let link = match &a.target.port {
        Some(p) => Session::open_serial(p, a.target.baud, t)?,
        None => Session::spawn_qemu(&q, t)?,
    };
    let qemu = link.child_id();
    std::fs::write(
        run.info(),
        format!(
            "{}{}\n",
            describe(&a.target),
            qemu.map(|p| format!(", QEMU pid {p}")).unwrap_or_default()
        ),
    )?;
    if let (None, Some(f)) = (&a.target.port, &q.flash) {
        let f = f.canonicalize().unwrap_or_else(|_| f.clone());
        std::fs::write(run.flash(), format!("{}\n", f.display()))?;
    }
    let (stopper, handle) = server::serve(link, listener);
    {
        let stopper = stopper.clone();
        std::thread::spawn(move || {
            let mut sig: libc::c_int = 0;
            // SAFETY: sigwait on the set blocked above.
            unsafe { libc::sigwait(&signals, &mut sig) };
            eprintln!("drivectl serve: signal {sig}: ending the drive");
            stopper.stop();
        });
    }
    // The pid file last: `drivectl up` takes it as "up".
    std::fs::write(run.pid_file(), format!("{}\n", std::process::id()))?;
    eprintln!(
        "drivectl serve: {} on {}",
        describe(&a.target),
        run.socket().display()
    );
    let (link, result) = handle.run();
    let _ = std::fs::remove_file(run.socket());
    let quit = link.quit(Duration::from_secs(10));
    if let Some(live) = decoder {
        let _ = live.finish();
    }
    let _ = std::fs::remove_file(run.info());
    let _ = std::fs::remove_file(run.flash());
    let _ = std::fs::remove_file(run.pid_file());
    eprintln!("drivectl serve: ended");
    result.context("the firmware's console link")?;
    quit
}
