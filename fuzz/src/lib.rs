//! Fuzz targets of the drive's inputs. Each takes arbitrary bytes and
//! panics on a violated invariant (libFuzzer reports the panic as a crash
//! with the input that caused it):
//! - [`console`]: bytes through the console's line editor, parser and
//!   command execution on the `Servo` over the simulated PL. Every line
//!   gets exactly one final `OK`/`ERR` line; a line answered with `ERR`
//!   changes nothing (mode, gates, torque reference, configuration,
//!   faults, fault history).
//! - [`record`]: two flash slots of arbitrary bytes (with their CRC made
//!   right on request, so that the fuzzer gets past it) through the
//!   configuration store's load. The loaded configuration is valid, in
//!   range and from a valid slot of the newest sequence number; load
//!   writes nothing; a save after it loads back.
//! - [`config_set`]: a `config set <name> <value>` on the parameter table
//!   and on the console; both agree; a refusal changes nothing, an
//!   accepted value is stored as given and the configuration stays valid.
//! - [`config_push`]: a TOML file through `drivectl config push`'s check
//!   against the drive's schema: what passes is finite, whole where it must
//!   be and in range, and applying it keeps a valid configuration.
//! - [`sdo`] and [`socketcand`] ([`can`]): the CANopen core's SDO server
//!   and socketcand parser; a refused request or command changes no state.
use drive::config::store::{self, FlashError, NorFlash, SlotState, RECORD_BYTES};
use drive::config::{self, Config, PARAMS};
use drive::console::{
    self, Action, Bench, Context, DriveError, DriveOps, DriveStatus, LineEditor, PlKind, Status,
};
use drive::pl::fault::Faults;
use drive::pl::top::Mode;
use drive::servo::faults::FaultRecord;
use drive::servo::{Servo, ServoConfig, ServoError, StepResult};
use simpl::{SimConfig, SimDrive};

pub mod can;
pub use can::{sdo, socketcand};
use std::sync::OnceLock;

/// Lines of one input the console target executes, at most.
const LINES_MAX: usize = 64;

/// The console's drive: the real `Servo` on the simulated PL; `step`,
/// flash, capture and the MPDCC loop unsupported (they need time to pass).
struct FuzzDrive {
    servo: Servo,
    pl: SimDrive,
}

impl FuzzDrive {
    fn new() -> Self {
        let mut pl = SimDrive::new(&SimConfig::default()).expect("default simulation");
        let mut servo = Servo::new(&ServoConfig::default()).expect("default servo");
        servo.init(&mut pl).expect("init");
        Self { servo, pl }
    }
    /// One control period of the simulated PL and the servo.
    fn period(&mut self) {
        self.pl.advance_to_boundary(1 << 20);
        self.servo.control_step(&mut self.pl).expect("control step");
    }
    /// What a refused line must not change.
    fn snapshot(&mut self) -> String {
        let c = Config::from_servo(self.servo.config());
        format!(
            "{:?} {:?} {:?} {:?} {:?} {}",
            self.servo.mode(),
            self.servo.gates_on(&mut self.pl),
            self.servo.torque_ref_nm().to_bits(),
            c.values().map(f64::to_bits),
            self.servo.faults(&mut self.pl),
            self.servo.fault_history().total,
        )
    }
}

impl DriveOps for FuzzDrive {
    fn mode(&mut self) -> Mode {
        self.servo.mode()
    }
    fn set_mode(&mut self, m: Mode) -> Result<(), DriveError> {
        Ok(self.servo.set_mode(&mut self.pl, m)?)
    }
    fn enable(&mut self) -> Result<(), DriveError> {
        Ok(self.servo.enable(&mut self.pl)?)
    }
    fn disable(&mut self) -> Result<(), DriveError> {
        Ok(self.servo.disable(&mut self.pl)?)
    }
    fn torque_ref(&mut self) -> f64 {
        self.servo.torque_ref_nm()
    }
    fn set_torque_ref(&mut self, nm: f64) -> Result<(), DriveError> {
        Ok(self.servo.set_torque_ref(nm)?)
    }
    fn step(&mut self, _nm: f64, _window_s: f64) -> Result<StepResult, DriveError> {
        Err(DriveError::Unsupported)
    }
    fn faults(&mut self) -> Result<Faults, DriveError> {
        Ok(self.servo.faults(&mut self.pl).map_err(ServoError::from)?)
    }
    fn clear_faults(&mut self) -> Result<Faults, DriveError> {
        Ok(self.servo.clear_faults(&mut self.pl)?)
    }
    fn stall(&mut self, _ms: u32) -> Result<(), DriveError> {
        Ok(())
    }
    fn status(&mut self) -> DriveStatus {
        DriveStatus {
            mode: self.servo.mode(),
            mpdtc_autonomous: !self.servo.config().mpdtc_ps_fed,
            gates_on: self.servo.gates_on(&mut self.pl).unwrap_or(false),
            faults: self.servo.faults(&mut self.pl).unwrap_or_default(),
            measured: self.servo.measured(),
            torque_ref_nm: self.servo.torque_ref_nm(),
            control_rate_hz: self.servo.control_rate_hz(),
            periods: self.servo.periods(),
            overruns: self.servo.overruns(),
            control_irq: 0,
            control_latency: Default::default(),
            pl: PlKind::Simulated,
            sim_time_scale: None,
            store: None,
            mpdcc: None,
            motion: self.servo.motion_status(),
            aligning_left_s: self.servo.aligning_left_s(),
        }
    }
    fn bench(&mut self) -> Result<Bench, DriveError> {
        Err(DriveError::Unsupported)
    }
    fn fault_record(&mut self, k: usize) -> Result<(Option<FaultRecord>, u32), DriveError> {
        let h = self.servo.fault_history();
        Ok((h.records().nth(k).copied(), h.total))
    }
    fn config(&mut self) -> Result<ServoConfig, DriveError> {
        Ok(*self.servo.config())
    }
    fn reconfigure(&mut self, cfg: &ServoConfig) -> Result<(), DriveError> {
        Ok(self.servo.reconfigure(&mut self.pl, cfg)?)
    }
}

fn context() -> Context {
    Context {
        version: "0.0.0",
        git_hash: "fuzz",
        profile: "fuzz",
        status: Status {
            uptime_us: 0,
            ticks: 0,
            tick_hz: 1000,
            lines: 0,
            errors: 0,
            rx_overruns: 0,
            log_dropped: 0,
            net: Default::default(),
        },
    }
}

/// `Some(true)` for a reply ending in `OK`, `Some(false)` for `ERR`;
/// panics unless exactly its last line is final.
fn final_of(reply: &str) -> bool {
    assert!(
        reply.ends_with("\r\n"),
        "reply not ended by CRLF: {reply:?}"
    );
    let lines: Vec<&str> = reply[..reply.len() - 2].split("\r\n").collect();
    let is_final = |l: &str| l == "OK" || l.starts_with("ERR ");
    let (last, before) = lines.split_last().expect("a line");
    assert!(is_final(last), "no final line: {reply:?}");
    assert!(
        !before.iter().any(|l| is_final(l)),
        "two final lines: {reply:?}"
    );
    *last == "OK"
}

/// Runs one console line as the firmware does; returns its reply.
fn run_line(d: &mut FuzzDrive, line: &str) -> String {
    let mut out = String::new();
    match console::parse(line) {
        Ok(cmd) => {
            if let Ok(Action::Panic) = console::execute(cmd, &context(), d, &mut out) {
                // `debug panic`: the firmware halts with the gates off.
                out.push_str("OK\r\n");
            }
        }
        Err(e) => console::write_parse_error(&mut out, e).expect("to a String"),
    }
    out
}

/// The console target (see the crate's documentation).
pub fn console(data: &[u8]) {
    let mut d = FuzzDrive::new();
    let mut ed = LineEditor::new();
    let mut lines = 0;
    for &b in data {
        let mut echo = Vec::new();
        let before = d.snapshot();
        let reply = match ed.feed(b, &mut |e| echo.extend_from_slice(e)) {
            None => continue,
            Some(Ok(l)) if l.trim().is_empty() => continue,
            Some(Ok(l)) => {
                let l = l.to_string();
                run_line(&mut d, &l)
            }
            Some(Err(e)) => {
                let mut out = String::new();
                console::write_line_error(&mut out, e).expect("to a String");
                out
            }
        };
        if !final_of(&reply) {
            assert_eq!(d.snapshot(), before, "refused, yet changed: {reply:?}");
        }
        d.period();
        lines += 1;
        if lines == LINES_MAX {
            break;
        }
    }
}

/// Two slots of the store in memory: their record bytes only.
#[derive(Clone, PartialEq)]
struct SlotFlash([[u8; RECORD_BYTES]; 2]);

impl SlotFlash {
    fn at(addr: u32, len: usize) -> (usize, usize) {
        let off = (addr - store::SLOT0_ADDR) as usize;
        let (slot, at) = (
            off / store::SECTOR_BYTES as usize,
            off % store::SECTOR_BYTES as usize,
        );
        assert!(slot < 2 && at + len <= RECORD_BYTES, "outside the slots");
        (slot, at)
    }
}

impl NorFlash for SlotFlash {
    fn read(&mut self, addr: u32, buf: &mut [u8]) -> Result<(), FlashError> {
        let (s, a) = Self::at(addr, buf.len());
        buf.copy_from_slice(&self.0[s][a..a + buf.len()]);
        Ok(())
    }
    fn erase_sector(&mut self, addr: u32) -> Result<(), FlashError> {
        let (s, _) = Self::at(addr, 0);
        self.0[s] = [0xFF; RECORD_BYTES];
        Ok(())
    }
    fn program(&mut self, addr: u32, data: &[u8]) -> Result<(), FlashError> {
        let (s, a) = Self::at(addr, data.len());
        for (m, d) in self.0[s][a..].iter_mut().zip(data) {
            *m &= d;
        }
        Ok(())
    }
}

/// Every value of `c` passes its row's check and `c` its whole check.
fn assert_in_range(c: &Config, base: &ServoConfig) {
    for (p, &v) in PARAMS.iter().zip(c.values()) {
        assert!(config::check_value(p, v).is_ok(), "{} = {v}", p.name);
    }
    assert!(c.check(base).is_ok(), "{:?}", c.values());
}

/// The record target (see the crate's documentation). Byte 0: bit 0 (1)
/// writes slot 0's header (magic, version, count, fingerprint), bit 1
/// slot 1's; bit 2 makes slot 0's CRC right, bit 3 slot 1's. Then the
/// slots' bytes (0xFF past the end of the input).
pub fn record(data: &[u8]) {
    let base = ServoConfig::default();
    let (&flags, rest) = data.split_first().unwrap_or((&0, &[]));
    let mut f = SlotFlash([[0xFF; RECORD_BYTES]; 2]);
    for (m, d) in f.0.iter_mut().flatten().zip(rest) {
        *m = *d;
    }
    let good = store::encode(&Config::default(), 0);
    for (k, r) in f.0.iter_mut().enumerate() {
        if flags & (1 << k) != 0 {
            r[..12].copy_from_slice(&good[..12]);
        }
        if flags & (4 << k) != 0 {
            let n = RECORD_BYTES - 4;
            let crc = store::crc32(&r[..n]);
            r[n..].copy_from_slice(&crc.to_le_bytes());
        }
    }
    let before = f.clone();
    let l = store::load(&mut f, &base).expect("memory flash");
    assert!(f == before, "load wrote to the flash");
    let mut seqs = [None; 2];
    for (k, seq_k) in seqs.iter_mut().enumerate() {
        let (st, c) = store::decode(&f.0[k], &base);
        assert_eq!(st, l.slots[k]);
        if let SlotState::Valid(seq) = st {
            assert_in_range(&c.expect("a valid slot's values"), &base);
            *seq_k = Some(seq);
        }
    }
    match l.config {
        Some((c, s)) => {
            assert_in_range(&c, &base);
            let seq = seqs[s].expect("loaded from a valid slot");
            if let Some(other) = seqs[1 - s] {
                assert!(other.wrapping_sub(seq) as i32 <= 0, "an older record won");
            }
        }
        None => assert!(seqs.iter().all(Option::is_none), "a valid slot not loaded"),
    }
    // A save after any of it lands and loads back.
    let c = l.config.map_or_else(Config::default, |(c, _)| c);
    let slot = store::save(&mut f, &c, &base).expect("memory flash");
    let l2 = store::load(&mut f, &base).expect("memory flash");
    assert_eq!(l2.config, Some((c, slot)));
}

/// The config_set target (see the crate's documentation). Byte 0 picks a
/// parameter by its index (or, past the table, takes the first word of the
/// rest as the name); the rest, as UTF-8, is the value.
pub fn config_set(data: &[u8]) {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    if text.contains(['\r', '\n']) || text.len() > 100 {
        return;
    }
    let (name, value) = match PARAMS.get(usize::from(pick)) {
        Some(p) => (p.name, text),
        None => text.split_once(' ').unwrap_or((text, "")),
    };
    let base = ServoConfig::default();
    let mut c = Config::default();
    let before = c;
    let table = config::parse_value(value).and_then(|v| c.set(&base, name, v).map(|()| v));
    match table {
        Ok(v) => {
            assert_eq!(c.get(name).map(f64::to_bits), Some(v.to_bits()));
            assert_in_range(&c, &base);
        }
        Err(_) => assert!(c == before, "refused, yet changed"),
    }
    // The console's `config set` agrees, on a drive with the gates off.
    if name.contains(char::is_whitespace) || name.is_empty() || value.trim() != value {
        return;
    }
    let mut d = FuzzDrive::new();
    let s0 = d.snapshot();
    let reply = run_line(&mut d, &format!("config set {name} {value}"));
    let ok = final_of(&reply);
    if value.split_whitespace().count() == 1 {
        assert_eq!(ok, table.is_ok(), "console and table disagree: {reply:?}");
    }
    if ok {
        assert!(Config::from_servo(d.servo.config()) == c, "{reply:?}");
    } else {
        assert_eq!(d.snapshot(), s0, "refused, yet changed: {reply:?}");
    }
}

fn schema() -> &'static [drivectl::config_file::ParamSchema] {
    static S: OnceLock<Vec<drivectl::config_file::ParamSchema>> = OnceLock::new();
    S.get_or_init(|| {
        let mut line = String::new();
        config::write_schema(&mut line).expect("to a String");
        drivectl::config_file::parse_schema(&line).expect("the drive's schema")
    })
}

/// The config_push target (see the crate's documentation).
pub fn config_push(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let schema = schema();
    let Ok(vals) = drivectl::config_file::parse_toml(text, schema) else {
        return;
    };
    let base = ServoConfig::default();
    let mut c = Config::default();
    for (name, v) in &vals {
        let p = schema
            .iter()
            .find(|p| p.name == *name)
            .expect("a known name");
        assert!(v.is_finite() && (p.min..=p.max).contains(v), "{name} = {v}");
        assert!(!p.integer || v.fract() == 0.0, "{name} = {v}");
        // One value may depend on another (`enc_zero` below `enc_cpr`): a
        // refusal here is the drive's cross-check, and changes nothing.
        let before = c;
        if c.set(&base, name, *v).is_err() {
            assert!(c == before);
        }
    }
    assert_in_range(&c, &base);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A target's seed corpus (`fuzz/seeds/<target>/`).
    fn seeds(target: &str) -> Vec<Vec<u8>> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("seeds")
            .join(target);
        let mut v: Vec<(std::path::PathBuf, Vec<u8>)> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| {
                let p = e.unwrap().path();
                let b = std::fs::read(&p).unwrap();
                (p, b)
            })
            .collect();
        v.sort();
        assert!(!v.is_empty(), "no seeds in {}", dir.display());
        v.into_iter().map(|(_, b)| b).collect()
    }

    /// Runs `f` on every seed, then on `FUZZ_RUNS` (default 2000) inputs
    /// mutated from them with a fixed random sequence: byte flips,
    /// insertions, deletions, splices of two seeds. No coverage feedback
    /// (`scripts/fuzz` has it); a quick check that `cargo test` can run.
    fn run(target: &str, f: fn(&[u8])) {
        let seeds = seeds(target);
        for s in &seeds {
            f(s);
        }
        let runs: usize = std::env::var("FUZZ_RUNS")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(2000);
        let mut rng = models::testrng::Rng(0x243F_6A88_85A3_08D3);
        let mut rnd = |n: usize| (rng.next_u64() % n.max(1) as u64) as usize;
        for _ in 0..runs {
            let mut d = seeds[rnd(seeds.len())].clone();
            for _ in 0..1 + rnd(4) {
                let at = rnd(d.len() + 1);
                match rnd(4) {
                    0 if at < d.len() => d[at] ^= 1 << rnd(8),
                    1 => d.insert(at, rnd(256) as u8),
                    2 if at < d.len() => {
                        d.remove(at);
                    }
                    _ => {
                        let o = &seeds[rnd(seeds.len())];
                        let from = rnd(o.len() + 1);
                        let len = rnd(o.len() - from + 1);
                        d.splice(at..at, o[from..from + len].iter().copied());
                    }
                }
            }
            f(&d);
        }
    }

    #[test]
    fn console_seeds_and_mutants() {
        run("console", console);
    }
    #[test]
    fn record_seeds_and_mutants() {
        run("record", record);
    }
    #[test]
    fn config_set_seeds_and_mutants() {
        run("config_set", config_set);
    }
    #[test]
    fn config_push_seeds_and_mutants() {
        run("config_push", config_push);
    }
    #[test]
    fn sdo_seeds_and_mutants() {
        run("sdo", sdo);
    }
    #[test]
    fn socketcand_seeds_and_mutants() {
        run("socketcand", socketcand);
    }

    /// The `[profile.test...]` sections from `[profile.test]` to the end of
    /// a manifest, without comments and blank lines.
    fn test_profile(manifest: &str) -> Vec<String> {
        let text = std::fs::read_to_string(manifest).unwrap();
        let from = text.find("\n[profile.test]").expect("no [profile.test]");
        text[from..]
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with('#'))
            .map(String::from)
            .collect()
    }

    /// This crate's test profile is the main workspace's, so `cargo test`
    /// here with `--target-dir target` reuses its builds: a profile that
    /// differs rebuilds every dependency (about 110 s on a fresh clone).
    #[test]
    fn fuzz_profile_is_the_workspace_s() {
        let dir = env!("CARGO_MANIFEST_DIR");
        assert_eq!(
            test_profile(&format!("{dir}/Cargo.toml")),
            test_profile(&format!("{dir}/../Cargo.toml")),
            "fuzz/Cargo.toml's test profile differs from Cargo.toml's"
        );
    }
}
