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
