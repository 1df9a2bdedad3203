//! The host end of the co-simulation bridge as a child process: `pl-cosim`
//! (crate `rtl-sim`: the Verilated `pl_top` and the plant) in a private
//! directory with its two FIFOs, and the QEMU options that let the firmware
//! reach it (semihosting, `cosim=<dir>` on the guest's command line,
//! `-icount` so that guest time, and with it PL time, is repeatable).
use anyhow::{bail, Context as _, Result};
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

/// The `pl-cosim` binary: `$DRIVE_PL_COSIM`, else the one beside the
/// running executable (same cargo profile: `target/<profile>/pl-cosim`).
pub fn pl_cosim_exe() -> Result<PathBuf> {
    if let Some(p) = std::env::var_os("DRIVE_PL_COSIM") {
        return Ok(PathBuf::from(p));
    }
    let exe = std::env::current_exe().context("no path of the running executable")?;
    for dir in exe.ancestors().skip(1) {
        let p = dir.join("pl-cosim");
        if p.is_file() {
            return Ok(p);
        }
    }
    bail!("pl-cosim not found beside {}: build it with `cargo build --release -p rtl-sim --bin pl-cosim` (scripts/run --pl rtl does)", exe.display())
}

/// QEMU options for a guest that talks to the bridge in `dir`.
pub fn qemu_args(dir: &Path) -> Vec<String> {
    vec![
        // One instruction per ns, and idle time skipped to the next timer
        // deadline: the guest (and the PL) never wait for the wall clock.
        "-icount".into(),
        "shift=0,sleep=off".into(),
        "-semihosting-config".into(),
        format!(
            "enable=on,target=native,arg=firmware,arg=cosim={}",
            dir.display()
        ),
    ]
}

/// A running `pl-cosim`; stopped (and its directory removed) on drop.
pub struct Bridge {
    child: Child,
    dir: PathBuf,
}

impl Bridge {
    /// Starts `pl-cosim` and waits until its FIFOs exist.
    pub fn start() -> Result<Self> {
        static N: AtomicU32 = AtomicU32::new(0);
        let dir = std::env::temp_dir().join(format!(
            "drive-cosim-{}-{}",
            std::process::id(),
            N.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("cannot create {}", dir.display()))?;
        let exe = pl_cosim_exe()?;
        let mut cmd = Command::new(&exe);
        cmd.arg("--dir")
            .arg(&dir)
            .arg("--stats")
            .arg(dir.join("stats.json"))
            .stdin(Stdio::null())
            .stdout(Stdio::piped());
        crate::children::end_with_parent(&mut cmd);
        let mut child = cmd
            .spawn()
            .with_context(|| format!("cannot start {}", exe.display()))?;
        let mut line = String::new();
        BufReader::new(child.stdout.take().expect("piped stdout")).read_line(&mut line)?;
        if line.trim() != "ready" {
            let _ = child.kill();
            let _ = child.wait();
            bail!("{} did not start: {line:?}", exe.display());
        }
        Ok(Self { child, dir })
    }

    /// The directory with the FIFOs `req` and `rep`.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Waits (at most 10 s) for `pl-cosim` to end after QEMU closed the
    /// FIFOs and returns its statistics line (JSON).
    pub fn finish(mut self) -> Result<String> {
        self.wait(Duration::from_secs(10));
        let p = self.dir.join("stats.json");
        std::fs::read_to_string(&p).with_context(|| format!("no statistics in {}", p.display()))
    }

    fn wait(&mut self, t: Duration) {
        let t0 = Instant::now();
        while t0.elapsed() < t {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for Bridge {
    fn drop(&mut self) {
        // QEMU is gone by now (its end closes the request FIFO).
        self.wait(Duration::from_secs(2));
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}
