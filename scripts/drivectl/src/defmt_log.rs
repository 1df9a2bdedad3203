//! Decoding of the firmware's defmt log stream (UART0, rzcobs frames).
use anyhow::{anyhow, Context as _, Result};
use defmt_decoder::{DecodeError, Locations, Table};
use std::io::{Read, Write};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// The decoding table and source locations of one firmware ELF.
pub struct LogTable {
    table: Table,
    locations: Option<Locations>,
}

impl LogTable {
    pub fn load(elf: &Path) -> Result<Self> {
        let bytes = std::fs::read(elf).with_context(|| format!("cannot read {}", elf.display()))?;
        let table = Table::parse(&bytes)
            .with_context(|| format!("bad defmt data in {}", elf.display()))?
            .ok_or_else(|| anyhow!("{} holds no defmt table (not our firmware?)", elf.display()))?;
        let locations = table.get_locations(&bytes).ok().filter(|l| !l.is_empty());
        Ok(Self { table, locations })
    }

    /// Decodes everything `input` yields until EOF, or, with `stop`, until
    /// `stop` is set (polling the input for new data meanwhile, as a growing
    /// file). Writes one line per frame; returns the number of frames.
    pub fn decode(
        &self,
        mut input: impl Read,
        out: &mut dyn Write,
        stop: Option<Arc<AtomicBool>>,
    ) -> Result<usize> {
        let mut dec = self.table.new_stream_decoder();
        let mut buf = [0u8; 4096];
        let mut frames = 0;
        loop {
            let n = input.read(&mut buf)?;
            if n == 0 {
                match &stop {
                    None => break,
                    Some(s) if s.load(Ordering::Relaxed) => {
                        // One last read after the writer stopped.
                        if input.read(&mut buf)? == 0 {
                            break;
                        }
                        continue;
                    }
                    Some(_) => {
                        std::thread::sleep(Duration::from_millis(50));
                        continue;
                    }
                }
            }
            dec.received(&buf[..n]);
            loop {
                match dec.decode() {
                    Ok(frame) => {
                        frames += 1;
                        let loc = self
                            .locations
                            .as_ref()
                            .and_then(|l| l.get(&frame.index()))
                            .map(|l| format!(" ({}:{})", l.file.display(), l.line))
                            .unwrap_or_default();
                        writeln!(out, "{}{}", frame.display(false), loc)?;
                    }
                    Err(DecodeError::UnexpectedEof) => break,
                    Err(DecodeError::Malformed) => {
                        writeln!(out, "(malformed defmt frame skipped)")?;
                    }
                }
            }
            out.flush()?;
        }
        Ok(frames)
    }
}

/// The defmt log of a QEMU as it runs: QEMU writes UART0's raw stream to
/// `<log>.bin`, a thread decodes it into `<log>` as it grows.
pub struct LiveLog {
    raw: std::path::PathBuf,
    stop: Arc<AtomicBool>,
    thread: std::thread::JoinHandle<Result<usize>>,
}

impl LiveLog {
    /// Creates `<log>.bin` (empty) and `<log>` and starts decoding with the
    /// table of `elf`.
    pub fn start(elf: &Path, log: &Path) -> Result<Self> {
        let raw = std::path::PathBuf::from(format!("{}.bin", log.display()));
        if let Some(dir) = log.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(&raw, b"").with_context(|| format!("cannot create {}", raw.display()))?;
        let table = LogTable::load(elf)?;
        let mut out = std::fs::File::create(log)
            .with_context(|| format!("cannot create {}", log.display()))?;
        let stop = Arc::new(AtomicBool::new(false));
        let thread = {
            let (stop, raw) = (stop.clone(), raw.clone());
            std::thread::spawn(move || -> Result<usize> {
                let f = std::fs::File::open(&raw)?;
                table.decode(f, &mut out, Some(stop))
            })
        };
        Ok(Self { raw, stop, thread })
    }

    /// The raw stream's file, for QEMU's first serial port.
    pub fn raw(&self) -> &Path {
        &self.raw
    }

    /// Decodes what is left once QEMU has ended; the frames decoded.
    pub fn finish(self) -> Result<usize> {
        self.stop.store(true, Ordering::Relaxed);
        self.thread
            .join()
            .map_err(|_| anyhow!("defmt decoder thread panicked"))?
    }
}
