//! Line editor: turns the received byte stream into lines, with echo.
//!
//! Rules (why: a terminal user and a script must both get a sane console):
//! - CR, LF and CRLF each end one line (an LF right after a CR is swallowed);
//! - backspace (0x08) and DEL (0x7f) erase the last character (a whole UTF-8
//!   sequence) and echo `BS SP BS`;
//! - Ctrl-C (0x03) and Ctrl-U (0x15) discard the line being typed;
//! - ANSI escape sequences (arrow keys, ...) are swallowed;
//! - TAB counts as a space; any other control byte marks the line bad;
//! - bytes past [`LINE_MAX`] are dropped and mark the line too long; the
//!   editor never stops accepting bytes, so the console always recovers at
//!   the next line end.

/// Capacity of the line buffer, bytes.
pub const LINE_MAX: usize = 128;

/// Why a finished line was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineError {
    /// More than [`LINE_MAX`] bytes.
    TooLong,
    /// Not valid UTF-8.
    BadEncoding,
    /// A control character (the first one seen).
    BadChar(u8),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Esc {
    None,
    /// After ESC.
    Start,
    /// Inside `ESC [ ...` until a final byte 0x40..=0x7e.
    Csi,
    /// After `ESC O`: one more byte (F1..F4 on many terminals).
    Ss3,
}

/// The line editor state.
pub struct LineEditor {
    buf: [u8; LINE_MAX],
    len: usize,
    too_long: bool,
    bad_char: Option<u8>,
    last_was_cr: bool,
    esc: Esc,
}

impl Default for LineEditor {
    fn default() -> Self {
        Self::new()
    }
}

impl LineEditor {
    /// An empty editor.
    pub const fn new() -> Self {
        Self {
            buf: [0; LINE_MAX],
            len: 0,
            too_long: false,
            bad_char: None,
            last_was_cr: false,
            esc: Esc::None,
        }
    }

    fn reset(&mut self) {
        self.len = 0;
        self.too_long = false;
        self.bad_char = None;
        self.esc = Esc::None;
    }

    /// Feeds one received byte; `echo` gets the bytes to send back.
    ///
    /// Returns `Some` when a line ended: `Ok(text)` (possibly empty) or the
    /// reason it was rejected. The returned text borrows the editor until the
    /// next call.
    pub fn feed(&mut self, b: u8, echo: &mut dyn FnMut(&[u8])) -> Option<Result<&str, LineError>> {
        let after_cr = core::mem::replace(&mut self.last_was_cr, b == b'\r');
        // Escape sequences: swallow only bytes that belong to one, so that a
        // stray ESC never eats a line end.
        match (self.esc, b) {
            (Esc::Start, b'[') => {
                self.esc = Esc::Csi;
                return None;
            }
            (Esc::Start, b'O') => {
                self.esc = Esc::Ss3;
                return None;
            }
            (Esc::Csi, 0x20..=0x3f) => return None,
            (Esc::Csi, 0x40..=0x7e) | (Esc::Ss3, 0x20..=0x7e) => {
                self.esc = Esc::None;
                return None;
            }
            _ => self.esc = Esc::None,
        }
        match b {
            b'\n' if after_cr => None,
            b'\r' | b'\n' => {
                echo(b"\r\n");
                let result = self.finish();
                Some(result)
            }
            0x08 | 0x7f => {
                if self.len > 0 && !self.too_long {
                    // Drop UTF-8 continuation bytes, then the lead byte.
                    while self.len > 0 && self.buf[self.len - 1] & 0xc0 == 0x80 {
                        self.len -= 1;
                    }
                    self.len = self.len.saturating_sub(1);
                    echo(b"\x08 \x08");
                }
                None
            }
            0x03 | 0x15 => {
                self.reset();
                echo(b"^C\r\n");
                // An empty line: the caller prints a fresh prompt.
                Some(Ok(""))
            }
            0x1b => {
                self.esc = Esc::Start;
                None
            }
            b'\t' => self.push(b' ', echo),
            0x00..=0x1f => {
                self.bad_char.get_or_insert(b);
                None
            }
            _ => self.push(b, echo),
        }
    }

    fn push(&mut self, b: u8, echo: &mut dyn FnMut(&[u8])) -> Option<Result<&str, LineError>> {
        if self.len < LINE_MAX {
            self.buf[self.len] = b;
            self.len += 1;
            echo(&[b]);
        } else {
            self.too_long = true;
        }
        None
    }

    fn finish(&mut self) -> Result<&str, LineError> {
        let (len, too_long, bad) = (self.len, self.too_long, self.bad_char);
        self.reset();
        if too_long {
            return Err(LineError::TooLong);
        }
        if let Some(c) = bad {
            return Err(LineError::BadChar(c));
        }
        core::str::from_utf8(&self.buf[..len]).map_err(|_| LineError::BadEncoding)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::String;
    use std::vec::Vec;

    /// Feeds `input`, returns (lines or errors, echo).
    fn run(input: &[u8]) -> (Vec<Result<String, LineError>>, Vec<u8>) {
        let mut ed = LineEditor::new();
        let mut echo = Vec::new();
        let mut lines = Vec::new();
        for &b in input {
            if let Some(r) = ed.feed(b, &mut |e| echo.extend_from_slice(e)) {
                lines.push(r.map(String::from));
            }
        }
        (lines, echo)
    }

    #[test]
    fn cr_lf_and_crlf_each_end_one_line() {
        let (lines, _) = run(b"a\rb\nc\r\nd\n\re\r\r");
        let want: Vec<Result<String, LineError>> = ["a", "b", "c", "d", "", "e", ""]
            .iter()
            .map(|s| Ok(String::from(*s)))
            .collect();
        assert_eq!(lines, want);
    }

    #[test]
    fn echo_and_backspace() {
        let (lines, echo) = run(b"helx\x7fp\r");
        assert_eq!(lines, [Ok(String::from("help"))]);
        assert_eq!(echo, b"helx\x08 \x08p\r\n");
    }

    #[test]
    fn backspace_on_empty_line_echoes_nothing() {
        let (lines, echo) = run(b"\x08\x08ok\r");
        assert_eq!(lines, [Ok(String::from("ok"))]);
        assert_eq!(echo, b"ok\r\n");
    }

    #[test]
    fn backspace_erases_a_whole_utf8_character() {
        // "ä" is two bytes.
        let (lines, _) = run("aä\x08b\r".as_bytes());
        assert_eq!(lines, [Ok(String::from("ab"))]);
    }

    #[test]
    fn overlong_line_is_rejected_and_the_next_line_works() {
        let mut input = vec![b'x'; LINE_MAX + 10];
        input.extend_from_slice(b"\r\nversion\r\n");
        let (lines, echo) = run(&input);
        assert_eq!(
            lines,
            [Err(LineError::TooLong), Ok(String::from("version"))]
        );
        // Only what fitted was echoed.
        assert_eq!(echo.len(), LINE_MAX + 2 + "version".len() + 2);
    }

    #[test]
    fn exactly_full_line_is_accepted() {
        let mut input = vec![b'y'; LINE_MAX];
        input.push(b'\r');
        let (lines, _) = run(&input);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].as_ref().unwrap().len(), LINE_MAX);
    }

    #[test]
    fn invalid_utf8_is_rejected() {
        let (lines, _) = run(b"ab\xff\xfe\r");
        assert_eq!(lines, [Err(LineError::BadEncoding)]);
    }

    #[test]
    fn control_character_is_rejected_with_its_code() {
        let (lines, _) = run(b"st\x01at\x02us\r");
        assert_eq!(lines, [Err(LineError::BadChar(0x01))]);
    }

    #[test]
    fn escape_sequences_are_swallowed() {
        let (lines, echo) = run(b"he\x1b[A\x1b[1;5Dlp\r");
        assert_eq!(lines, [Ok(String::from("help"))]);
        assert_eq!(echo, b"help\r\n");
    }

    #[test]
    fn stray_escape_does_not_eat_the_line_end() {
        let (lines, _) = run(b"help\x1b\rstatus\x1b[\r");
        assert_eq!(
            lines,
            [Ok(String::from("help")), Ok(String::from("status"))]
        );
    }

    #[test]
    fn ctrl_c_discards_the_line() {
        let (lines, _) = run(b"garbage\x03help\r");
        assert_eq!(lines, [Ok(String::new()), Ok(String::from("help"))]);
    }

    #[test]
    fn tab_is_a_space() {
        let (lines, _) = run(b"help\tstatus\r");
        assert_eq!(lines, [Ok(String::from("help status"))]);
    }

    #[test]
    fn random_bytes_never_panic_and_the_editor_recovers() {
        // The workspace's test generator: deterministic garbage.
        let mut rng = models::testrng::Rng(0x1234_5678);
        let mut input = Vec::new();
        for _ in 0..100_000 {
            input.push(rng.next_u64() as u8);
        }
        // Whatever state the garbage left (even inside an escape sequence),
        // a line end, then a clean line, is understood.
        input.extend_from_slice(b"\x1b[A\r\nversion\r\n");
        let (lines, _) = run(&input);
        assert_eq!(lines.last(), Some(&Ok(String::from("version"))));
    }
}
