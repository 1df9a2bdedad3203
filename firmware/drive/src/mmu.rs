//! The firmware's flat (identity) translation table for the Zynq-7000's
//! Cortex-A9: which 1 MiB section of the 4 GiB address space is what memory
//! type, and the ARMv7-A short-descriptor section entries that say so
//! (ARM Architecture Reference Manual ARMv7-A/R, B3.5.1 "Short-descriptor
//! translation table format", B3.8.2 "TEX remap disabled"; address map:
//! Zynq-7000 TRM UG585, table 4-1 "System-level address map").
//!
//! The map (one entry per MiB, 4096 entries, 16 KiB):
//! | range                      | what                          | memory type              |
//! |----------------------------|-------------------------------|--------------------------|
//! | 0x0000_0000..0x0010_0000   | OCM (low) or DDR, the FSBL's  | normal, non-cacheable    |
//! | 0x0010_0000..0x0200_0000   | DDR: code, data, stacks       | normal, write-back WA    |
//! | 0x0200_0000..0x0210_0000   | DDR: DMA rings and buffers    | normal, non-cacheable    |
//! | 0x0210_0000..0x1000_0000   | DDR (unused)                  | normal, write-back WA    |
//! | 0x4000_0000..0x8000_0000   | AXI GP0 (the PL's registers)  | device, execute-never    |
//! | 0xE000_0000..0xE030_0000   | IOP: UARTs, QSPI, ...         | device, execute-never    |
//! | 0xF800_0000..0xF900_0000   | SLCR, devcfg, A9 private, L2C | device, execute-never    |
//! | 0xFFF0_0000..              | OCM (high)                    | normal, non-cacheable    |
//! | everything else            | GP1, QSPI linear, SMC, ...    | fault (no access)        |
//!
//! DDR stops at 256 MiB, the smallest Zynq-7000 board's (and above QEMU's
//! default 128 MiB): normal memory may be read speculatively, so nothing
//! that is not RAM is mapped normal. The firmware uses nothing the map
//! leaves as a fault, so an access there is a bug, reported by the data
//! abort handler (a translation fault, DFSR status 0b00101).
//!
//! The caches need no maintenance: the one bus master besides the CPU, the
//! Ethernet controller (GEM0), reads and writes only its descriptor rings
//! and frame buffers, which the linker places in the DMA section
//! ([`DMA_BASE`], memory.x's `.dma` output section); that MiB is normal
//! non-cacheable in L1 and in the L2 (PL310), so every CPU store reaches
//! DDR (after a DSB) and every load sees what the controller wrote. The
//! QSPI store runs in I/O mode through its registers, no DMA, and device
//! memory is never cached.

/// Bytes per section (one translation-table entry).
pub const SECTION_BYTES: u32 = 1 << 20;
/// Entries of the table (4 GiB / 1 MiB).
pub const ENTRIES: usize = 4096;

/// Start of the MiB of DDR that holds the DMA descriptors and buffers
/// (memory.x's `DMA` region): normal non-cacheable.
pub const DMA_BASE: u32 = 0x0200_0000;

/// Memory type of a section.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Region {
    /// No access: a translation fault.
    Fault,
    /// Normal memory, inner and outer write-back write-allocate (L1 and L2).
    Cached,
    /// Normal memory, inner and outer non-cacheable.
    Uncached,
    /// Shareable device memory (no caching, no speculation, ordered), XN.
    Device,
}

impl Region {
    /// What `debug mmu` prints.
    pub fn name(self) -> &'static str {
        match self {
            Region::Fault => "fault (unmapped)",
            Region::Cached => "normal write-back write-allocate (L1+L2)",
            Region::Uncached => "normal non-cacheable",
            Region::Device => "device, execute-never",
        }
    }
}

/// The regions of the map above, first section index and end (exclusive).
const MAP: &[(u32, u32, Region)] = &[
    (0x000, 0x001, Region::Uncached),
    (0x001, 0x020, Region::Cached),
    (0x020, 0x021, Region::Uncached),
    (0x021, 0x100, Region::Cached),
    (0x400, 0x800, Region::Device),
    (0xE00, 0xE03, Region::Device),
    (0xF80, 0xF90, Region::Device),
    (0xFFF, 0x1000, Region::Uncached),
];

/// The memory type of the section holding `addr`.
pub fn region_of(addr: u32) -> Region {
    let s = addr >> 20;
    MAP.iter()
        .find(|(lo, hi, _)| (*lo..*hi).contains(&s))
        .map_or(Region::Fault, |&(_, _, r)| r)
}

/// Section entry bits (short descriptor): type `0b10`, B (2), C (3), XN (4),
/// domain (8:5) = 0, AP[1:0] (11:10) = 0b11 (read/write at PL0 and PL1),
/// TEX (14:12), AP[2] (15) = 0, S (16), nG (17) = 0.
const SECTION: u32 = 0b10;
const B: u32 = 1 << 2;
const C: u32 = 1 << 3;
const XN: u32 = 1 << 4;
const AP_RW: u32 = 0b11 << 10;
const TEX_SHIFT: u32 = 12;
const S: u32 = 1 << 16;

/// The entry mapping section `index` (its own address: a flat map) as `r`.
/// TEX/C/B with TEX remap off: normal WBWA = 0b001/1/1, normal
/// non-cacheable = 0b001/0/0, shareable device = 0b000/0/1.
pub fn section_entry(index: u32, r: Region) -> u32 {
    let base = (index & 0xFFF) << 20;
    let attrs = match r {
        Region::Fault => return 0,
        Region::Cached => (0b001 << TEX_SHIFT) | C | B,
        Region::Uncached => 0b001 << TEX_SHIFT,
        Region::Device => B | XN | S,
    };
    base | attrs | AP_RW | SECTION
}

/// The memory type an entry gives (the inverse of [`section_entry`]);
/// `None` for an entry of another form (page table, supersection, an
/// attribute combination this map does not use).
pub fn decode(entry: u32) -> Option<Region> {
    if entry & 0b11 == 0 {
        return Some(Region::Fault);
    }
    if entry & 0b11 != SECTION || entry & (1 << 18) != 0 {
        return None;
    }
    let tex = (entry >> TEX_SHIFT) & 0b111;
    match (tex, entry & C != 0, entry & B != 0, entry & XN != 0) {
        (0b001, true, true, _) => Some(Region::Cached),
        (0b001, false, false, _) => Some(Region::Uncached),
        (0b000, false, true, true) => Some(Region::Device),
        _ => None,
    }
}

/// Fills `table` with the flat map.
pub fn fill(table: &mut [u32; ENTRIES]) {
    for (i, e) in table.iter_mut().enumerate() {
        let i = i as u32;
        *e = section_entry(i, region_of(i << 20));
    }
}

/// TTBR0 for a table at `base` (16 KiB aligned): table walks
/// inner/outer write-back write-allocate (IRGN = 0b01 with the
/// multiprocessing extensions: bit 6 set, bit 0 clear; RGN = 0b01), not
/// shareable (one core).
pub fn ttbr0(base: u32) -> u32 {
    (base & !0x3FFF) | (1 << 6) | (0b01 << 3)
}

/// SCTLR bits the firmware sets: M (MMU, 0), C (data and unified caches,
/// 2), Z (branch prediction, 11), I (instruction cache, 12).
pub const SCTLR_M: u32 = 1 << 0;
/// SCTLR.C.
pub const SCTLR_C: u32 = 1 << 2;
/// SCTLR.Z.
pub const SCTLR_Z: u32 = 1 << 11;
/// SCTLR.I.
pub const SCTLR_I: u32 = 1 << 12;
/// All four.
pub const SCTLR_ON: u32 = SCTLR_M | SCTLR_C | SCTLR_Z | SCTLR_I;
/// SCTLR's reset value on the Cortex-A9 (TRM r4p1, 4.3.9: 0x00C5_0078, the
/// RES1 bits with everything else off: little-endian exceptions, low
/// vectors, no alignment check, no TEX remap or access flag).
pub const SCTLR_RESET: u32 = 0x00C5_0078;
/// SCTLR as the firmware writes it, whole: the reset value plus
/// [`SCTLR_ON`]. Not ORed into what it finds: after a warm restart (a
/// debugger's download and run without a core reset) SCTLR may hold the
/// previous image's bits (high vectors, alignment checks).
pub const SCTLR_BOOT: u32 = SCTLR_RESET | SCTLR_ON;

/// The regions the drivers use, for `debug mmu`: name and an address in it.
pub const USED: &[(&str, u32)] = &[
    ("ddr-code", 0x0010_0000),
    ("ddr-data", 0x0090_0000),
    ("ddr-dma", DMA_BASE),
    ("gp0-pl-regs", regmap::BASE_ADDR as u32),
    ("uart1", 0xE000_1000),
    ("gem0", 0xE000_B000),
    ("qspi", 0xE000_D000),
    ("slcr-devcfg", 0xF800_7000),
    ("a9-private", 0xF8F0_0000),
    ("ocm-high", 0xFFFF_0000),
    ("gp1-unused", 0x8000_0000),
];

#[cfg(test)]
mod tests {

    #[test]
    fn sctlr_is_written_whole_with_low_vectors_and_no_alignment_check() {
        // M, C, Z, I on; V (13, high vectors), A (1, alignment), TRE (28),
        // AFE (29), TE (30) and EE (25) off whatever a last run left.
        assert_eq!(SCTLR_BOOT, 0x00C5_187D);
        for off in [1, 13, 25, 28, 29, 30] {
            assert_eq!(SCTLR_BOOT & (1 << off), 0, "bit {off}");
        }
        assert_eq!(SCTLR_BOOT & SCTLR_ON, SCTLR_ON);
    }

    use super::*;

    #[test]
    fn entries_by_hand() {
        // DDR at 1 MiB: base 0x001, TEX 001, AP 11, C, B, section.
        assert_eq!(section_entry(0x001, Region::Cached), 0x0010_1C0E);
        // UART at 0xE00: S, AP 11, XN, B, section.
        assert_eq!(section_entry(0xE00, Region::Device), 0xE001_0C16);
        assert_eq!(section_entry(0xFFF, Region::Uncached), 0xFFF0_1C02);
        assert_eq!(section_entry(0x800, Region::Fault), 0);
    }

    #[test]
    fn decode_inverts_every_kind() {
        for r in [
            Region::Fault,
            Region::Cached,
            Region::Uncached,
            Region::Device,
        ] {
            assert_eq!(decode(section_entry(0x123, r)), Some(r));
        }
        // A coarse page table entry and a strongly-ordered section are not ours.
        assert_eq!(decode(0x0010_0001), None);
        assert_eq!(decode(0x0010_0C02), None);
    }

    #[test]
    fn the_drivers_regions_have_the_right_type() {
        let table = {
            let mut t = [0u32; ENTRIES];
            fill(&mut t);
            t
        };
        let at = |a: u32| decode(table[(a >> 20) as usize]).unwrap();
        // Code and data of memory.x, and the top of the smallest board's DDR.
        assert_eq!(at(0x0010_0000), Region::Cached);
        assert_eq!(at(0x0090_0000 + 23 * SECTION_BYTES - 1), Region::Cached);
        // The DMA MiB right above DATA, and nothing more.
        assert_eq!(at(0x0200_0000), Region::Uncached);
        assert_eq!(at(0x020F_FFFF), Region::Uncached);
        assert_eq!(at(0x0210_0000), Region::Cached);
        assert_eq!(at(DMA_BASE), Region::Uncached);
        assert_eq!(at(0x0FFF_FFFF), Region::Cached);
        assert_eq!(at(0x1000_0000), Region::Fault);
        assert_eq!(at(regmap::BASE_ADDR as u32), Region::Device);
        for a in [
            0xE000_1000,
            0xE000_B000,
            0xE000_D000,
            0xF800_700C,
            0xF8F0_0200,
            0xF8F0_2100,
        ] {
            assert_eq!(at(a), Region::Device, "{a:#x}");
        }
        assert_eq!(at(0xFFFF_0000), Region::Uncached);
        assert_eq!(at(0x8000_0000), Region::Fault);
        // Flat: every mapped entry's base is its own address.
        for (i, e) in table.iter().enumerate() {
            if *e != 0 {
                assert_eq!(e >> 20, i as u32);
            }
        }
    }

    #[test]
    fn ttbr0_keeps_the_base_and_walk_attributes() {
        assert_eq!(ttbr0(0x0098_C000), 0x0098_C048);
    }
}
