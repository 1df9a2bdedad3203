//! The configuration in QEMU's QSPI flash: `config save`, loaded at boot,
//! bad records ignored and reported in `status`, and saves cut by killing
//! QEMU at random instants (a power cut) leaving the old or the new one.
use drive::config::store::{crc32, decode, SlotState, RECORD_BYTES, SECTOR_BYTES, SLOT0_ADDR};
use drive::servo::ServoConfig;
use drivectl::link::Session;
use std::time::Instant;
use system_tests::{assert_ok, boot_with_flash, cmd, field, fresh_flash};

/// QEMU writes the flash image asynchronously (the n25q128 model's page
/// and sector writes are queued to its block layer): a kill right after
/// the reply may still lose the save (a fixed wait before the kill is a
/// bound host load can break). Where a test needs the save on disk, QEMU
/// exits cleanly (`Session::quit`), which drains the block layer.
fn quit(s: Session) {
    s.quit(std::time::Duration::from_secs(60))
        .expect("QEMU exits on SIGTERM");
}

fn t_tol(s: &mut Session) -> f64 {
    let r = cmd(s, "config get mpdtc_t_tol");
    assert_ok(&r);
    r.lines[0]
        .strip_prefix("mpdtc_t_tol = ")
        .and_then(|v| v.strip_suffix(" Nm"))
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{r:?}"))
}

/// `config_flash: slot0 <a> slot1 <b>, running <x>`.
fn flash_status(s: &mut Session) -> String {
    let st = cmd(s, "status");
    let l = st
        .lines
        .iter()
        .find_map(|l| l.strip_prefix("config_flash: "))
        .unwrap_or_else(|| panic!("{st:?}"));
    assert_eq!(field(&st, "pl"), Some("simulated"));
    l.to_string()
}

#[test]
fn saved_configuration_survives_a_reboot() {
    let img = fresh_flash("survives");
    let mut s = boot_with_flash(&img);
    assert_eq!(
        flash_status(&mut s),
        "slot0 empty slot1 empty, running defaults"
    );
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.05"));
    assert_ok(&cmd(&mut s, "config set dead_time 70"));
    let r = cmd(&mut s, "config save");
    assert_eq!(r.lines, ["config: saved to slot0"], "{r:?}");
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.06"));
    let r = cmd(&mut s, "config save");
    assert_eq!(r.lines, ["config: saved to slot1"], "{r:?}");
    // Unsaved: gone after the reboot.
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.07"));
    quit(s);
    let mut s = boot_with_flash(&img);
    assert_eq!(
        flash_status(&mut s),
        "slot0 valid slot1 valid, running slot1"
    );
    assert_eq!(t_tol(&mut s), 0.06);
    let r = cmd(&mut s, "config get dead_time");
    assert_eq!(r.lines, ["dead_time = 70 cycles"], "{r:?}");
    // `config reset` changes the running values, not the flash.
    assert_ok(&cmd(&mut s, "config reset"));
    assert_eq!(t_tol(&mut s), 0.08);
    drop(s);
    let mut s = boot_with_flash(&img);
    assert_eq!(t_tol(&mut s), 0.06);
}

#[test]
fn bad_records_are_ignored_and_reported() {
    let img = fresh_flash("bad-records");
    let mut s = boot_with_flash(&img);
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.05"));
    assert_ok(&cmd(&mut s, "config save"));
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.06"));
    assert_ok(&cmd(&mut s, "config save"));
    quit(s);
    let slot = |k: u32| (SLOT0_ADDR + k * SECTOR_BYTES) as usize;
    let mut mem = std::fs::read(&img).unwrap();
    // A flipped bit in slot 1's values: CRC fails.
    mem[slot(1) + 30] ^= 0x04;
    std::fs::write(&img, &mem).unwrap();
    let mut s = boot_with_flash(&img);
    assert_eq!(
        flash_status(&mut s),
        "slot0 valid slot1 bad-crc, running slot0"
    );
    assert_eq!(t_tol(&mut s), 0.05);
    drop(s);
    // Slot 0 rewritten as format version 2 with a correct CRC.
    let n = RECORD_BYTES - 4;
    mem[slot(0) + 4] = 2;
    let crc = crc32(&mem[slot(0)..slot(0) + n]);
    mem[slot(0) + n..slot(0) + n + 4].copy_from_slice(&crc.to_le_bytes());
    std::fs::write(&img, &mem).unwrap();
    let mut s = boot_with_flash(&img);
    assert_eq!(
        flash_status(&mut s),
        "slot0 bad-version slot1 bad-crc, running defaults"
    );
    assert_eq!(t_tol(&mut s), 0.08);
    // The next save overwrites a bad slot and loads at the next boot.
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.04"));
    assert_ok(&cmd(&mut s, "config save"));
    quit(s);
    let mut s = boot_with_flash(&img);
    assert_eq!(t_tol(&mut s), 0.04);
}

/// Where a cut landed in a save, read from the flash image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CutKind {
    /// The target slot as before the save.
    BeforeErase,
    /// The target slot erased, nothing programmed.
    AfterErase,
    /// Part of the record programmed, its CRC not.
    MidProgram,
    /// The new record complete.
    AfterCrc,
}

const PACE_MS: u32 = 40;
const CUTS: u32 = 20;

/// The record at the start of `slot` in the image `mem`.
fn record(mem: &[u8], slot: usize) -> [u8; RECORD_BYTES] {
    let a = (SLOT0_ADDR + slot as u32 * SECTOR_BYTES) as usize;
    mem[a..a + RECORD_BYTES].try_into().unwrap()
}

/// The slot a save writes (the one not holding the newest valid record)
/// and the sequence number it writes there.
fn target_slot(mem: &[u8]) -> (usize, u32) {
    let base = ServoConfig::default();
    let seqs = [0, 1].map(|k| match decode(&record(mem, k), &base).0 {
        SlotState::Valid(seq) => Some(seq),
        _ => None,
    });
    match seqs {
        [Some(a), Some(b)] if b.wrapping_sub(a) as i32 > 0 => (0, b + 1),
        [Some(a), _] => (1, a + 1),
        [None, Some(b)] => (0, b + 1),
        [None, None] => (0, 1),
    }
}

/// Classifies a cut from the target slot before (`pre`) and after
/// (`post`) it; `None` where the image cannot tell (an erased slot before
/// the save looks the same before and after the erase), which the test
/// does not let happen.
fn classify(pre: &[u8; RECORD_BYTES], post: &[u8; RECORD_BYTES], seq: u32) -> Option<CutKind> {
    let erased = |r: &[u8]| r.iter().all(|&b| b == 0xFF);
    let n = RECORD_BYTES - 4;
    if post == pre {
        return (!erased(pre)).then_some(CutKind::BeforeErase);
    }
    if erased(post) {
        return Some(CutKind::AfterErase);
    }
    match decode(post, &ServoConfig::default()).0 {
        SlotState::Valid(s) if s == seq => Some(CutKind::AfterCrc),
        _ if erased(&post[n..]) => Some(CutKind::MidProgram),
        st => panic!("slot neither old, erased, part-programmed nor new: {st:?}"),
    }
}

/// 20 saves, each cut by killing QEMU at an instant drawn in its own
/// twentieth of 1.1 times the time a save takes, with each erase and
/// program held 40 ms longer (`debug flash-pace`: QEMU's flash model
/// writes at once). After each reboot the configuration is the old or the
/// new one with a valid record there, and, classified from the flash image,
/// cuts landed before the erase, after it, inside the programming and
/// after the CRC, each at least once.
#[test]
fn saves_cut_by_a_power_cut_leave_the_old_or_the_new_configuration() {
    let img = fresh_flash("power-cut");
    // How long a save takes here (send to reply).
    let mut s = boot_with_flash(&img);
    assert_ok(&cmd(&mut s, &format!("debug flash-pace {PACE_MS}")));
    assert_ok(&cmd(&mut s, "config set mpdtc_t_tol 0.001"));
    let t0 = Instant::now();
    assert_ok(&cmd(&mut s, "config save"));
    let save = t0.elapsed();
    quit(s);
    let mut old = 0.001;
    let mut rng = models::testrng::Rng(0x2545_F491_4F6C_DD1D);
    let (mut kept_old, mut got_new) = (0, 0);
    let mut kinds = std::collections::BTreeMap::new();
    for k in 1..=CUTS {
        let new = 0.001 + 0.01 * f64::from(k);
        let new = (new * 1000.0).round() / 1000.0;
        let mut mem = std::fs::read(&img).unwrap();
        let (slot, seq) = target_slot(&mem);
        // An erased target slot looks the same before and after the erase:
        // leave a torn record there (as a cut save would), so it does not.
        if record(&mem, slot).iter().all(|&b| b == 0xFF) {
            let a = (SLOT0_ADDR + slot as u32 * SECTOR_BYTES) as usize;
            mem[a..a + 8].fill(0x00);
            std::fs::write(&img, &mem).unwrap();
        }
        let pre = record(&mem, slot);
        let mut s = boot_with_flash(&img);
        assert_ok(&cmd(&mut s, &format!("debug flash-pace {PACE_MS}")));
        assert_ok(&cmd(&mut s, &format!("config set mpdtc_t_tol {new}")));
        // A repeatable random instant in this cut's stratum.
        let u = (rng.next_u64() % 1000) as f64 / 1000.0;
        let cut = save.mul_f64(1.1 * (f64::from(k - 1) + u) / f64::from(CUTS));
        s.send(b"config save\r").unwrap();
        std::thread::sleep(cut);
        drop(s);
        let kind = classify(&pre, &record(&std::fs::read(&img).unwrap(), slot), seq);
        assert!(
            kind.is_some(),
            "save {k}: the target slot was erased before it"
        );
        *kinds.entry(format!("{kind:?}")).or_insert(0) += 1;
        let mut s = boot_with_flash(&img);
        let got = t_tol(&mut s);
        let fs = flash_status(&mut s);
        assert!(
            got == old || got == new,
            "save {k} cut after {cut:?} ({kind:?}): t_tol {got}, old {old}, new {new}; {fs}"
        );
        assert!(
            fs.ends_with("running slot0") || fs.ends_with("running slot1"),
            "{fs}"
        );
        // The new value is running exactly when the cut came after the CRC.
        assert_eq!(
            got == new,
            kind == Some(CutKind::AfterCrc),
            "save {k}: {fs}"
        );
        if got == new {
            got_new += 1;
            old = new;
        } else {
            kept_old += 1;
        }
        drop(s);
    }
    println!("save takes {save:?}; after {CUTS} cuts: {kept_old} old, {got_new} new; {kinds:?}");
    for want in [
        CutKind::BeforeErase,
        CutKind::AfterErase,
        CutKind::MidProgram,
        CutKind::AfterCrc,
    ] {
        assert!(
            kinds.contains_key(&format!("{:?}", Some(want))),
            "no cut {want:?} in {CUTS}: {kinds:?}"
        );
    }
}
