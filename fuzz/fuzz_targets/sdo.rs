#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| drive_fuzz::sdo(data));
