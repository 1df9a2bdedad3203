//! Boot image files: a reader for 32-bit ARM ELF load segments, stand-in
//! FSBL/bitstream files for testing `bootgen` without Vivado, and a reader
//! of the Zynq-7000 `BOOT.BIN` header (layout: Zynq-7000 Technical
//! Reference Manual UG585, "Boot Header" and bootgen's partition header
//! table) that checks the partitions independently of bootgen.
use std::fmt;

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImageError(pub String);

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ImageError {}

fn word(b: &[u8], off: usize) -> Result<u32, ImageError> {
    b.get(off..off + 4)
        .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
        .ok_or_else(|| ImageError(format!("file ends before offset {off:#x}")))
}

fn half(b: &[u8], off: usize) -> Result<u16, ImageError> {
    b.get(off..off + 2)
        .map(|w| u16::from_le_bytes([w[0], w[1]]))
        .ok_or_else(|| ImageError(format!("file ends before offset {off:#x}")))
}

/// One loadable segment of an ELF file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Segment {
    pub paddr: u32,
    pub data: Vec<u8>,
}

/// Entry point and PT_LOAD segments (with file data) of a 32-bit
/// little-endian ARM ELF executable.
pub fn read_elf(b: &[u8]) -> Result<(u32, Vec<Segment>), ImageError> {
    if b.get(0..4) != Some(b"\x7fELF") {
        return Err(ImageError("not an ELF file".into()));
    }
    if b[4] != 1 || b[5] != 1 || half(b, 18)? != 40 {
        return Err(ImageError("not a 32-bit little-endian ARM ELF".into()));
    }
    let entry = word(b, 24)?;
    let phoff = word(b, 28)? as usize;
    let phentsize = half(b, 42)? as usize;
    let phnum = half(b, 44)? as usize;
    let mut segs = Vec::new();
    for i in 0..phnum {
        let ph = phoff + i * phentsize;
        if word(b, ph)? != 1 {
            continue; // not PT_LOAD
        }
        let (off, paddr, filesz) = (
            word(b, ph + 4)? as usize,
            word(b, ph + 12)?,
            word(b, ph + 16)? as usize,
        );
        if filesz == 0 {
            continue;
        }
        let data = b
            .get(off..off + filesz)
            .ok_or_else(|| ImageError(format!("segment {i} lies outside the file")))?;
        segs.push(Segment {
            paddr,
            data: data.to_vec(),
        });
    }
    Ok((entry, segs))
}

/// A minimal ARM ELF with one executable segment of `words` NOP
/// instructions at `addr` (entry = `addr`): a stand-in FSBL.
pub fn standin_elf(addr: u32, words: usize) -> Vec<u8> {
    const EHSIZE: u16 = 52;
    const PHSIZE: u16 = 32;
    const DATA_OFF: u32 = 0x100;
    let len = (words * 4) as u32;
    let mut e = Vec::new();
    e.extend_from_slice(b"\x7fELF\x01\x01\x01\x00");
    e.extend_from_slice(&[0; 8]);
    for h in [2u16, 40] {
        e.extend_from_slice(&h.to_le_bytes()); // ET_EXEC, EM_ARM
    }
    for w in [1u32, addr, u32::from(EHSIZE), 0, 0x0500_0200] {
        e.extend_from_slice(&w.to_le_bytes()); // version, entry, phoff, shoff, flags (EABI5, hard-float)
    }
    for h in [EHSIZE, PHSIZE, 1, 40, 0, 0] {
        e.extend_from_slice(&h.to_le_bytes());
    }
    for w in [1u32, DATA_OFF, addr, addr, len, len, 5, 4] {
        e.extend_from_slice(&w.to_le_bytes()); // PT_LOAD, R+X
    }
    e.resize(DATA_OFF as usize, 0);
    for _ in 0..words {
        e.extend_from_slice(&0xE1A0_0000u32.to_le_bytes()); // mov r0, r0
    }
    e
}

/// Sync word of a 7-series configuration stream.
pub const SYNC_WORD: u32 = 0xAA99_5566;

/// A minimal `.bit` file (header fields a..e, then a configuration stream
/// that only synchronises and idles): a stand-in bitstream for bootgen.
/// `part` is the Vivado part name (`xc7z020clg484-1`).
pub fn standin_bit(design: &str, part: &str) -> Vec<u8> {
    let field = |key: u8, v: &str| {
        let mut f = vec![key];
        f.extend_from_slice(&((v.len() + 1) as u16).to_be_bytes());
        f.extend_from_slice(v.as_bytes());
        f.push(0);
        f
    };
    let mut b = vec![
        0x00, 0x09, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x00, 0x00, 0x01,
    ];
    let dev = part.trim_start_matches("xc");
    let dev = dev.rsplit_once('-').map_or(dev, |(d, _)| d);
    b.extend(field(
        b'a',
        &format!("{design};UserID=0XFFFFFFFF;Version=stand-in"),
    ));
    b.extend(field(b'b', dev));
    b.extend(field(b'c', "2000/01/01"));
    b.extend(field(b'd', "00:00:00"));
    let mut stream = vec![0xFFu8; 32];
    for w in [
        0x0000_00BB,
        0x1122_0044,
        0xFFFF_FFFF,
        0xFFFF_FFFF,
        SYNC_WORD,
    ] {
        stream.extend_from_slice(&u32::to_be_bytes(w));
    }
    for _ in 0..16 {
        stream.extend_from_slice(&0x2000_0000u32.to_be_bytes()); // type-1 NOOP
    }
    b.push(b'e');
    b.extend_from_slice(&(stream.len() as u32).to_be_bytes());
    b.extend(stream);
    b
}

/// Destination of a partition (partition attribute bits [5:4]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dest {
    None,
    Ps,
    Pl,
    Other(u32),
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Partition {
    /// Name from the image header (the file name given in the BIF).
    pub name: String,
    pub dest: Dest,
    pub load: u32,
    pub exec: u32,
    /// Partition data in the file.
    pub data: Vec<u8>,
}

fn checksum(words: impl Iterator<Item = u32>) -> u32 {
    !words.fold(0u32, |a, w| a.wrapping_add(w))
}

/// Bootgen stores image names as big-endian words in a little-endian file:
/// each 4-byte group is reversed.
fn image_name(b: &[u8], off: usize) -> Result<String, ImageError> {
    let mut out = Vec::new();
    for i in 0..64 {
        let w = word(b, off + 4 * i)?.to_be_bytes();
        for c in w {
            if c == 0 {
                return Ok(String::from_utf8_lossy(&out).into_owned());
            }
            out.push(c);
        }
    }
    Err(ImageError("image name not terminated".into()))
}

/// Partitions of a Zynq-7000 boot image, in header order, with the boot
/// header and every partition header checksum verified.
pub fn read_boot_image(b: &[u8]) -> Result<Vec<Partition>, ImageError> {
    if word(b, 0x20)? != SYNC_WORD || word(b, 0x24)? != u32::from_le_bytes(*b"XNLX") {
        return Err(ImageError(
            "no Zynq boot header (width word / XNLX id missing)".into(),
        ));
    }
    let sum = checksum((0x20..=0x44).step_by(4).map(|o| word(b, o).unwrap_or(0)));
    if sum != word(b, 0x48)? {
        return Err(ImageError(format!(
            "boot header checksum {:#x} != {sum:#x}",
            word(b, 0x48)?
        )));
    }
    let iht = word(b, 0x98)? as usize;
    let pht = word(b, 0x9C)? as usize;
    let count = word(b, iht + 4)? as usize;
    if count == 0 || count > 32 {
        return Err(ImageError(format!("implausible image count {count}")));
    }
    let mut parts = Vec::new();
    for i in 0..count {
        let h = pht + 64 * i;
        let w: Vec<u32> = (0..16)
            .map(|k| word(b, h + 4 * k))
            .collect::<Result<_, _>>()?;
        if checksum(w[..15].iter().copied()) != w[15] {
            return Err(ImageError(format!(
                "partition header {i}: checksum mismatch"
            )));
        }
        let dest = match (w[6] >> 4) & 3 {
            0 => Dest::None,
            1 => Dest::Ps,
            2 => Dest::Pl,
            d => Dest::Other(d),
        };
        let (off, len) = (w[5] as usize * 4, w[1] as usize * 4);
        let data = b
            .get(off..off + len)
            .ok_or_else(|| ImageError(format!("partition {i} lies outside the file")))?
            .to_vec();
        let name = image_name(b, w[9] as usize * 4 + 0x10)?;
        parts.push(Partition {
            name,
            dest,
            load: w[3],
            exec: w[4],
            data,
        });
    }
    Ok(parts)
}

/// Checks the order and content of a drive boot image: the FSBL first (to
/// the PS, executing at its entry, starting with its first load segment;
/// further FSBL partitions to the PS may follow), then exactly one PL
/// bitstream (containing the sync word), then the firmware's load segments
/// (to the PS, in order, byte for byte, the first executing at the
/// firmware's entry) and nothing else.
pub fn check_boot_order(
    parts: &[Partition],
    fsbl: &[u8],
    firmware: &[u8],
) -> Result<(), ImageError> {
    let e = |m: String| Err(ImageError(m));
    let (fsbl_entry, fsbl_segs) = read_elf(fsbl)?;
    let (fw_entry, fw_segs) = read_elf(firmware)?;
    let Some(first_fsbl) = fsbl_segs.first() else {
        return e("the FSBL ELF has no load segment".into());
    };
    let Some(p) = parts.first() else {
        return e("no partitions".into());
    };
    if p.dest != Dest::Ps || p.exec != fsbl_entry || !p.data.starts_with(&first_fsbl.data) {
        return e(format!("partition 0 ({}) is not the FSBL", p.name));
    }
    let pl: Vec<usize> = (0..parts.len())
        .filter(|&i| parts[i].dest == Dest::Pl)
        .collect();
    let [bit] = pl[..] else {
        return e(format!(
            "{} PL partitions, expected one bitstream",
            pl.len()
        ));
    };
    if let Some(i) = (1..bit).find(|&i| parts[i].dest != Dest::Ps) {
        return e(format!(
            "partition {i} ({}) before the bitstream is not for the PS",
            parts[i].name
        ));
    }
    let sync_be = SYNC_WORD.to_be_bytes();
    let sync_le = SYNC_WORD.to_le_bytes();
    if !parts[bit]
        .data
        .windows(4)
        .any(|w| w == sync_be || w == sync_le)
    {
        return e(format!(
            "partition {bit} ({}) has no configuration sync word",
            parts[bit].name
        ));
    }
    let fw = &parts[bit + 1..];
    if fw.len() != fw_segs.len() {
        return e(format!(
            "{} partitions after the bitstream, the firmware has {} load segments",
            fw.len(),
            fw_segs.len()
        ));
    }
    for (k, (p, seg)) in fw.iter().zip(&fw_segs).enumerate() {
        // Bootgen pads a partition to whole words.
        let same = p.data.len() >= seg.data.len()
            && p.data[..seg.data.len()] == seg.data[..]
            && p.data[seg.data.len()..].iter().all(|&x| x == 0);
        if p.dest != Dest::Ps || p.load != seg.paddr || !same {
            return e(format!(
                "partition {} ({}) is not firmware segment {k} at {:#010x}",
                bit + 1 + k,
                p.name,
                seg.paddr
            ));
        }
    }
    match fw.first() {
        Some(p) if p.exec == fw_entry => Ok(()),
        Some(p) => e(format!(
            "firmware partition executes at {:#010x}, ELF entry is {fw_entry:#010x}",
            p.exec
        )),
        None => e("no firmware partition".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standin_elf_reads_back() {
        let elf = standin_elf(0x0010_0000, 8);
        let (entry, segs) = read_elf(&elf).unwrap();
        assert_eq!(entry, 0x0010_0000);
        assert_eq!(segs.len(), 1);
        assert_eq!(segs[0].paddr, 0x0010_0000);
        assert_eq!(segs[0].data.len(), 32);
        assert_eq!(&segs[0].data[..4], &[0x00, 0x00, 0xA0, 0xE1]);
    }

    #[test]
    fn elf_reader_rejects_other_files() {
        assert!(read_elf(b"not an elf").is_err());
        let mut elf = standin_elf(0, 1);
        elf[18] = 62; // x86-64
        assert!(read_elf(&elf).unwrap_err().0.contains("ARM"));
        let elf = standin_elf(0, 1);
        assert!(
            read_elf(&elf[..0x90]).is_err(),
            "truncated segment accepted"
        );
    }

    #[test]
    fn standin_bit_has_the_header_fields_and_sync() {
        let b = standin_bit("board_top", "xc7z020clg484-1");
        let s = String::from_utf8_lossy(&b);
        assert!(s.contains("7z020clg484\0"));
        assert!(b.windows(4).any(|w| w == SYNC_WORD.to_be_bytes()));
    }

    #[test]
    fn boot_image_reader_rejects_garbage() {
        assert!(read_boot_image(&[0u8; 0x100]).is_err());
        assert!(read_boot_image(&[0u8; 4]).is_err());
    }

    fn part(name: &str, dest: Dest, load: u32, exec: u32, data: &[u8]) -> Partition {
        Partition {
            name: name.into(),
            dest,
            load,
            exec,
            data: data.to_vec(),
        }
    }

    #[test]
    fn boot_order_is_fsbl_bitstream_firmware() {
        let fsbl = standin_elf(0, 4);
        let fw = standin_elf(0x0010_0000, 8);
        let fsbl_data = read_elf(&fsbl).unwrap().1[0].data.clone();
        let fw_data = read_elf(&fw).unwrap().1[0].data.clone();
        let bit_data = [0xFF, 0xFF, 0xAA, 0x99, 0x55, 0x66, 0x20, 0x00];
        let good = vec![
            part("fsbl.elf", Dest::Ps, 0, 0, &fsbl_data),
            part("board_top.bit", Dest::Pl, 0, 0, &bit_data),
            part("firmware.elf", Dest::Ps, 0x0010_0000, 0x0010_0000, &fw_data),
        ];
        check_boot_order(&good, &fsbl, &fw).unwrap();

        let swapped = vec![good[1].clone(), good[0].clone(), good[2].clone()];
        assert!(check_boot_order(&swapped, &fsbl, &fw)
            .unwrap_err()
            .0
            .contains("not the FSBL"));
        let fw_first = vec![good[0].clone(), good[2].clone(), good[1].clone()];
        assert!(check_boot_order(&fw_first, &fsbl, &fw).is_err());
        let mut wrong_load = good.clone();
        wrong_load[2].load = 0x0020_0000;
        assert!(check_boot_order(&wrong_load, &fsbl, &fw)
            .unwrap_err()
            .0
            .contains("segment 0"));
        let mut wrong_exec = good.clone();
        wrong_exec[2].exec = 0;
        assert!(check_boot_order(&wrong_exec, &fsbl, &fw)
            .unwrap_err()
            .0
            .contains("entry"));
        let mut no_sync = good.clone();
        no_sync[1].data = vec![0; 8];
        assert!(check_boot_order(&no_sync, &fsbl, &fw)
            .unwrap_err()
            .0
            .contains("sync"));
        let mut changed = good.clone();
        changed[2].data[0] ^= 1;
        assert!(check_boot_order(&changed, &fsbl, &fw).is_err());
        assert!(check_boot_order(&good[..2], &fsbl, &fw).is_err());
    }

    #[test]
    fn names_decode_word_by_word() {
        // "fsbl.elf" as bootgen writes it.
        let raw = b"lbsffle.\0\0\0\0";
        assert_eq!(image_name(raw, 0).unwrap(), "fsbl.elf");
    }
}
