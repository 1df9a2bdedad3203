//! `drivectl config pull|push` against the firmware in QEMU: a pulled file
//! pushed back with changes reaches the drive and its flash; bad files and
//! refused combinations change nothing.
use drivectl::config_file::{pull, push, to_toml};
use drivectl::link::Session;
use system_tests::{boot_with_flash, cmd, fresh_flash, TIMEOUT};

fn get(s: &mut Session, name: &str) -> String {
    let r = cmd(s, &format!("config get {name}"));
    assert!(r.is_ok(), "{r:?}");
    r.lines[0].clone()
}

#[test]
fn pull_edit_push_reaches_the_drive_and_its_flash() {
    let img = fresh_flash("config-file");
    let mut s = boot_with_flash(&img);
    let (schema, values) = pull(&mut s, TIMEOUT).unwrap();
    let text = to_toml(&schema, &values).unwrap();
    // Independent of the tool's formatting: the firmware's defaults.
    assert!(text.contains("\nmpdtc_t_tol = 0.08\n"), "{text}");
    assert!(text.contains("\nenc_cpr = 4096\n"), "{text}");
    // Needs enc_cpr first (enc_zero < enc_cpr): the push finds the order.
    let edited = text
        .replace("\nmpdtc_t_tol = 0.08\n", "\nmpdtc_t_tol = 0.05\n")
        .replace("\nenc_cpr = 4096\n", "\nenc_cpr = 8000\n")
        .replace("\nenc_zero = 0\n", "\nenc_zero = 5000\n");
    let before_list = cmd(&mut s, "config list");
    assert_eq!(push(&mut s, &edited, TIMEOUT).unwrap(), schema.len());
    assert_eq!(get(&mut s, "mpdtc_t_tol"), "mpdtc_t_tol = 0.05 Nm");
    assert_eq!(get(&mut s, "enc_zero"), "enc_zero = 5000 counts");
    assert_ne!(cmd(&mut s, "config list").lines, before_list.lines);
    // QEMU writes the flash image asynchronously: let it land.
    std::thread::sleep(std::time::Duration::from_millis(300));
    drop(s);
    // Saved: the next boot has it.
    let mut s = boot_with_flash(&img);
    assert_eq!(get(&mut s, "mpdtc_t_tol"), "mpdtc_t_tol = 0.05 Nm");
    assert_eq!(get(&mut s, "enc_cpr"), "enc_cpr = 8000 counts");
    // A pull now gives the pushed file back.
    let (schema, values) = pull(&mut s, TIMEOUT).unwrap();
    assert_eq!(to_toml(&schema, &values).unwrap(), edited);
}

#[test]
fn bad_files_and_refused_combinations_change_nothing() {
    let img = fresh_flash("config-file-bad");
    let mut s = boot_with_flash(&img);
    let before = cmd(&mut s, "config list");
    for bad in [
        "mpdtc_t_tol = 0.9\n",
        "motor_pole_pairs = 6.5\n",
        "nothing = 1\n",
        "mpdtc_t_tol = nan\n",
        "mpdtc_t_tol = inf\n",
        "mpdtc_t_tol = \"0.05\"\n",
        "mpdtc_t_tol = 0.05\nmpdtc_p = 0.7\n",
        "not toml",
    ] {
        assert!(push(&mut s, bad, TIMEOUT).is_err(), "{bad}");
        assert_eq!(cmd(&mut s, "config list").lines, before.lines, "{bad}");
    }
    // Each in range, refused together (K Ts >= 1 at a 40 us period): the
    // values set before the refusal are taken back.
    let e = push(
        &mut s,
        "mpdtc_t_tol = 0.05\nadc_period = 1000\nmpdtc_k = 60000\n",
        TIMEOUT,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("the previous values are back"), "{e}");
    assert_eq!(cmd(&mut s, "config list").lines, before.lines);
    let st = cmd(&mut s, "status");
    assert!(
        st.lines
            .iter()
            .any(|l| l == "config_flash: slot0 empty slot1 empty, running defaults"),
        "{st:?}"
    );
}
