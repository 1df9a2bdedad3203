//! SPI NOR flash commands (the subset common to the n25q128 that QEMU's
//! `xilinx-zynq-a9` puts on the QSPI controller and the boards' parts):
//! READ (0x03), PAGE PROGRAM (0x02), SECTOR ERASE (0xD8, 64 KiB), WRITE
//! ENABLE (0x06), READ STATUS (0x05: bit 0 write in progress, bit 1 write
//! enable latch), READ ID (0x9F), all with 3-byte addresses. The controller
//! below it only moves bytes with the chip select held ([`SpiBus`]).
use super::store::{FlashError, NorFlash, PAGE_BYTES};

/// One SPI transaction: chip select asserted, `out` sent, then `inp.len()`
/// bytes clocked in (sending 0), chip select released.
pub trait SpiBus {
    /// Runs the transaction.
    fn transaction(&mut self, out: &[&[u8]], inp: &mut [u8]) -> Result<(), FlashError>;
}

const READ: u8 = 0x03;
const PAGE_PROGRAM: u8 = 0x02;
const SECTOR_ERASE: u8 = 0xD8;
const WRITE_ENABLE: u8 = 0x06;
const READ_STATUS: u8 = 0x05;
const READ_ID: u8 = 0x9F;
const SR_WIP: u8 = 1;
const SR_WEL: u8 = 2;
/// Status polls before a program or erase counts as failed (the n25q128's
/// sector erase takes up to 3 s; one poll is a few us on a board).
const POLLS_MAX: u32 = 10_000_000;

/// A flash behind an [`SpiBus`].
pub struct SpiNor<B>(pub B);

fn addr3(a: u32) -> [u8; 3] {
    [(a >> 16) as u8, (a >> 8) as u8, a as u8]
}

impl<B: SpiBus> SpiNor<B> {
    /// JEDEC manufacturer and device ID (n25q128: 20 BA 18).
    pub fn id(&mut self) -> Result<[u8; 3], FlashError> {
        let mut id = [0; 3];
        self.0.transaction(&[&[READ_ID]], &mut id)?;
        Ok(id)
    }
    fn status(&mut self) -> Result<u8, FlashError> {
        let mut s = [0];
        self.0.transaction(&[&[READ_STATUS]], &mut s)?;
        Ok(s[0])
    }
    fn write_enable(&mut self) -> Result<(), FlashError> {
        self.0.transaction(&[&[WRITE_ENABLE]], &mut [])?;
        if self.status()? & SR_WEL == 0 {
            return Err(FlashError);
        }
        Ok(())
    }
    fn wait_ready(&mut self) -> Result<(), FlashError> {
        for _ in 0..POLLS_MAX {
            if self.status()? & SR_WIP == 0 {
                return Ok(());
            }
        }
        Err(FlashError)
    }
}

impl<B: SpiBus> NorFlash for SpiNor<B> {
    fn read(&mut self, addr: u32, buf: &mut [u8]) -> Result<(), FlashError> {
        let a = addr3(addr);
        self.0.transaction(&[&[READ], &a], buf)
    }
    fn erase_sector(&mut self, addr: u32) -> Result<(), FlashError> {
        self.write_enable()?;
        self.0
            .transaction(&[&[SECTOR_ERASE], &addr3(addr)], &mut [])?;
        self.wait_ready()
    }
    fn program(&mut self, addr: u32, data: &[u8]) -> Result<(), FlashError> {
        // A page program wraps at the page end: split at page boundaries.
        let (mut a, mut rest) = (addr, data);
        while !rest.is_empty() {
            let room = (PAGE_BYTES - a % PAGE_BYTES) as usize;
            let (now, later) = rest.split_at(room.min(rest.len()));
            self.write_enable()?;
            self.0
                .transaction(&[&[PAGE_PROGRAM], &addr3(a), now], &mut [])?;
            self.wait_ready()?;
            a += now.len() as u32;
            rest = later;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::store::{self, SlotState, SECTOR_BYTES};
    use super::super::Config;
    use super::*;
    use crate::servo::ServoConfig;
    use std::vec::Vec;

    /// An n25q128 at the command level: 16 MiB, write-enable latch, page
    /// wrap, program clears bits, busy for `busy_polls` status reads after
    /// each program or erase.
    struct N25q {
        mem: Vec<u8>,
        wel: bool,
        busy: u32,
        busy_polls: u32,
        log: Vec<u8>,
    }

    impl SpiBus for N25q {
        fn transaction(&mut self, out: &[&[u8]], inp: &mut [u8]) -> Result<(), FlashError> {
            let bytes: Vec<u8> = out.iter().flat_map(|s| s.iter().copied()).collect();
            let cmd = bytes[0];
            self.log.push(cmd);
            let addr = || {
                (usize::from(bytes[1]) << 16) | (usize::from(bytes[2]) << 8) | usize::from(bytes[3])
            };
            match cmd {
                READ_ID => inp.copy_from_slice(&[0x20, 0xBA, 0x18]),
                READ_STATUS => {
                    let wip = self.busy > 0;
                    self.busy = self.busy.saturating_sub(1);
                    inp[0] = u8::from(wip) | if self.wel { SR_WEL } else { 0 };
                }
                WRITE_ENABLE => self.wel = true,
                READ => {
                    let a = addr();
                    inp.copy_from_slice(&self.mem[a..a + inp.len()]);
                }
                PAGE_PROGRAM | SECTOR_ERASE if !self.wel || self.busy > 0 => {}
                PAGE_PROGRAM => {
                    let a = addr();
                    let page = a & !(PAGE_BYTES as usize - 1);
                    for (k, b) in bytes[4..].iter().enumerate() {
                        let at = page + (a - page + k) % PAGE_BYTES as usize;
                        self.mem[at] &= b;
                    }
                    self.wel = false;
                    self.busy = self.busy_polls;
                }
                SECTOR_ERASE => {
                    let a = addr() & !(SECTOR_BYTES as usize - 1);
                    self.mem[a..a + SECTOR_BYTES as usize].fill(0xFF);
                    self.wel = false;
                    self.busy = self.busy_polls;
                }
                _ => panic!("unexpected command {cmd:#x}"),
            }
            Ok(())
        }
    }

    #[test]
    fn store_round_trip_through_the_commands() {
        let dev = N25q {
            mem: std::vec![0xFF; 16 << 20],
            wel: false,
            busy: 0,
            busy_polls: 3,
            log: Vec::new(),
        };
        let mut f = SpiNor(dev);
        assert_eq!(f.id().unwrap(), [0x20, 0xBA, 0x18]);
        let base = ServoConfig::default();
        let mut c = Config::default();
        c.set(&base, "mpdtc_t_tol", 0.05).unwrap();
        assert_eq!(store::save(&mut f, &c, &base).unwrap(), 0);
        c.set(&base, "mpdtc_t_tol", 0.06).unwrap();
        assert_eq!(store::save(&mut f, &c, &base).unwrap(), 1);
        let l = store::load(&mut f, &base).unwrap();
        assert_eq!(l.config, Some((c, 1)));
        assert_eq!(l.slots, [SlotState::Valid(1), SlotState::Valid(2)]);
        // Every program and erase after a write enable.
        let log = &f.0.log;
        for (k, &cmd) in log.iter().enumerate() {
            if cmd == PAGE_PROGRAM || cmd == SECTOR_ERASE {
                assert_eq!(log[k - 2], WRITE_ENABLE, "{k}");
            }
        }
    }

    #[test]
    fn programs_split_at_page_ends() {
        let dev = N25q {
            mem: std::vec![0xFF; 1 << 20],
            wel: false,
            busy: 0,
            busy_polls: 0,
            log: Vec::new(),
        };
        let mut f = SpiNor(dev);
        let data: Vec<u8> = (0..600u32).map(|x| x as u8).collect();
        f.program(250, &data).unwrap();
        let mut back = std::vec![0; 600];
        f.read(250, &mut back).unwrap();
        assert_eq!(back, data);
        // 250..256, 256..512, 512..768, 768..850: four programs.
        assert_eq!(f.0.log.iter().filter(|&&c| c == PAGE_PROGRAM).count(), 4);
    }

    #[test]
    fn a_flash_that_never_gets_ready_is_an_error() {
        struct Stuck;
        impl SpiBus for Stuck {
            fn transaction(&mut self, out: &[&[u8]], inp: &mut [u8]) -> Result<(), FlashError> {
                if out[0] == [READ_STATUS] {
                    inp[0] = SR_WIP | SR_WEL;
                }
                Ok(())
            }
        }
        // Bounded: a few seconds of polls at most, here on the host.
        let mut f = SpiNor(Stuck);
        assert_eq!(f.erase_sector(0), Err(FlashError));
    }
}
