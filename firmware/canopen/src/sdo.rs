//! The SDO server (CiA 301 v4.2 §7.2.4): expedited and segmented upload
//! and download of object dictionary entries. Requests arrive on COB-ID
//! 0x600 + node, responses leave on 0x580 + node; every SDO frame has 8
//! data bytes. Block transfer is not supported: its initiate requests are
//! answered with abort 0x0504 0001 (command specifier not valid).
//!
//! Byte 0 of each frame is the command specifier:
//! - initiate download request `001x nnes`, response `0110 0000` (0x60);
//! - download segment request `000t nnnc`, response `001t 0000`;
//! - initiate upload request `0100 0000` (0x40), response `010x nnes`;
//! - upload segment request `011t 0000`, response `000t nnnc`;
//! - abort `1000 0000` (0x80) with the 32-bit code in bytes 4..8.
//!
//! Bytes 1..3 of initiate and abort frames carry the multiplexer (index
//! little-endian, then sub-index). `t` is the toggle bit (0 in the first
//! segment, alternating after), `n` the number of bytes at the end that
//! carry no data, `e` expedited, `s` size indicated, `c` last segment.

use crate::od::{read_checked, write_checked, Abort, ObjectDictionary};

/// Request COB-ID of the default SDO server (CiA 301 pre-defined
/// connection set): 0x600 + node-ID.
pub const fn request_cob_id(node: u8) -> u16 {
    0x600 + node as u16
}

/// Response COB-ID of the default SDO server: 0x580 + node-ID.
pub const fn response_cob_id(node: u8) -> u16 {
    0x580 + node as u16
}

/// Largest value a segmented transfer can carry, in bytes.
pub const SDO_BUFFER: usize = 64;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Idle,
    /// Segmented download under way; `size` as the initiate indicated it.
    Download {
        index: u16,
        sub: u8,
        toggle: u8,
        len: usize,
        size: Option<usize>,
    },
    /// Segmented upload under way: `len` bytes were read into the buffer at
    /// the initiate, `pos` of them sent.
    Upload {
        index: u16,
        sub: u8,
        toggle: u8,
        len: usize,
        pos: usize,
    },
}

/// One SDO server channel.
#[derive(Clone, Debug)]
pub struct SdoServer {
    state: State,
    buf: [u8; SDO_BUFFER],
}

impl Default for SdoServer {
    fn default() -> Self {
        Self::new()
    }
}

/// The abort frame's data (CiA 301 §7.2.4): 0x80, multiplexer, code.
pub fn abort_frame(index: u16, sub: u8, code: Abort) -> [u8; 8] {
    let i = index.to_le_bytes();
    let c = code.code().to_le_bytes();
    [0x80, i[0], i[1], sub, c[0], c[1], c[2], c[3]]
}

impl SdoServer {
    /// A server with no transfer under way.
    pub const fn new() -> Self {
        Self {
            state: State::Idle,
            buf: [0; SDO_BUFFER],
        }
    }

    /// Drops any transfer under way (NMT reset communication, stop).
    pub fn reset(&mut self) {
        self.state = State::Idle;
    }

    /// True while a segmented transfer is under way.
    pub fn busy(&self) -> bool {
        self.state != State::Idle
    }

    /// Handles one request's data bytes and returns the response's, or
    /// `None` when the request was an abort from the client (it has no
    /// answer). Any error ends the transfer under way with an abort frame.
    pub fn handle<D: ObjectDictionary + ?Sized>(
        &mut self,
        req: &[u8],
        od: &mut D,
    ) -> Option<[u8; 8]> {
        let (index, sub) = match self.state {
            State::Download { index, sub, .. } | State::Upload { index, sub, .. } => (index, sub),
            State::Idle => (0, 0),
        };
        if req.len() != 8 {
            self.state = State::Idle;
            // The multiplexer of an initiate request, if it got that far.
            let (index, sub) = if req.len() >= 4 && matches!(req[0] >> 5, 1 | 2) {
                (u16::from_le_bytes([req[1], req[2]]), req[3])
            } else {
                (index, sub)
            };
            return Some(abort_frame(index, sub, Abort::InvalidCommand));
        }
        let mux = (u16::from_le_bytes([req[1], req[2]]), req[3]);
        let result = match req[0] >> 5 {
            1 => self.initiate_download(req, od).map_err(|a| (mux, a)),
            0 => self
                .download_segment(req, od)
                .map_err(|a| ((index, sub), a)),
            2 => self.initiate_upload(req, od).map_err(|a| (mux, a)),
            3 => self.upload_segment(req).map_err(|a| ((index, sub), a)),
            4 => {
                self.state = State::Idle;
                return None;
            }
            // 5: block upload, 6: block download, 7: not defined.
            _ => Err((mux, Abort::InvalidCommand)),
        };
        Some(match result {
            Ok(resp) => resp,
            Err(((i, s), a)) => {
                self.state = State::Idle;
                abort_frame(i, s, a)
            }
        })
    }

    fn initiate_download<D: ObjectDictionary + ?Sized>(
        &mut self,
        req: &[u8],
        od: &mut D,
    ) -> Result<[u8; 8], Abort> {
        self.state = State::Idle;
        let index = u16::from_le_bytes([req[1], req[2]]);
        let sub = req[3];
        let expedited = req[0] & 0x02 != 0;
        let sized = req[0] & 0x01 != 0;
        let e = od.entry(index, sub)?;
        if !e.access.writable() {
            return Err(Abort::WriteReadOnly);
        }
        let ok = [0x60, req[1], req[2], sub, 0, 0, 0, 0];
        if expedited {
            let len = if sized {
                4 - ((req[0] >> 2) & 0x03) as usize
            } else {
                // Size not indicated: the type's own size when it fits.
                match e.data_type.size() {
                    Some(s) if s <= 4 => s,
                    _ => 4,
                }
            };
            write_checked(od, index, sub, &req[4..4 + len])?;
            return Ok(ok);
        }
        let size = if sized {
            let s = u32::from_le_bytes([req[4], req[5], req[6], req[7]]) as usize;
            if s > e.data_type.capacity() || s > SDO_BUFFER {
                return Err(Abort::TooLong);
            }
            if matches!(e.data_type.size(), Some(t) if s < t) {
                return Err(Abort::TooShort);
            }
            Some(s)
        } else {
            None
        };
        self.state = State::Download {
            index,
            sub,
            toggle: 0,
            len: 0,
            size,
        };
        Ok(ok)
    }

    fn download_segment<D: ObjectDictionary + ?Sized>(
        &mut self,
        req: &[u8],
        od: &mut D,
    ) -> Result<[u8; 8], Abort> {
        let State::Download {
            index,
            sub,
            toggle,
            len,
            size,
        } = self.state
        else {
            return Err(Abort::InvalidCommand);
        };
        let t = (req[0] >> 4) & 1;
        if t != toggle {
            return Err(Abort::ToggleNotAlternated);
        }
        let count = 7 - ((req[0] >> 1) & 0x07) as usize;
        let last = req[0] & 1 != 0;
        let limit = size.unwrap_or(SDO_BUFFER);
        if len + count > limit {
            return Err(Abort::TooLong);
        }
        self.buf[len..len + count].copy_from_slice(&req[1..1 + count]);
        let len = len + count;
        let resp = [0x20 | (t << 4), 0, 0, 0, 0, 0, 0, 0];
        if last {
            self.state = State::Idle;
            if matches!(size, Some(s) if s != len) {
                return Err(Abort::TypeMismatch);
            }
            let mut tmp = [0u8; SDO_BUFFER];
            tmp[..len].copy_from_slice(&self.buf[..len]);
            write_checked(od, index, sub, &tmp[..len])?;
        } else {
            self.state = State::Download {
                index,
                sub,
                toggle: t ^ 1,
                len,
                size,
            };
        }
        Ok(resp)
    }

    fn initiate_upload<D: ObjectDictionary + ?Sized>(
        &mut self,
        req: &[u8],
        od: &mut D,
    ) -> Result<[u8; 8], Abort> {
        self.state = State::Idle;
        let index = u16::from_le_bytes([req[1], req[2]]);
        let sub = req[3];
        let n = read_checked(od, index, sub, &mut self.buf)?;
        if (1..=4).contains(&n) {
            let mut r = [
                0x43 | (((4 - n) as u8) << 2),
                req[1],
                req[2],
                sub,
                0,
                0,
                0,
                0,
            ];
            r[4..4 + n].copy_from_slice(&self.buf[..n]);
            return Ok(r);
        }
        let s = (n as u32).to_le_bytes();
        self.state = State::Upload {
            index,
            sub,
            toggle: 0,
            len: n,
            pos: 0,
        };
        Ok([0x41, req[1], req[2], sub, s[0], s[1], s[2], s[3]])
    }

    fn upload_segment(&mut self, req: &[u8]) -> Result<[u8; 8], Abort> {
        let State::Upload {
            index,
            sub,
            toggle,
            len,
            pos,
        } = self.state
        else {
            return Err(Abort::InvalidCommand);
        };
        let t = (req[0] >> 4) & 1;
        if t != toggle {
            return Err(Abort::ToggleNotAlternated);
        }
        let count = (len - pos).min(7);
        let last = pos + count == len;
        let mut r = [0u8; 8];
        r[0] = (t << 4) | (((7 - count) as u8) << 1) | last as u8;
        r[1..1 + count].copy_from_slice(&self.buf[pos..pos + count]);
        self.state = if last {
            State::Idle
        } else {
            State::Upload {
                index,
                sub,
                toggle: t ^ 1,
                len,
                pos: pos + count,
            }
        };
        Ok(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::od::testod::TestOd;

    fn run(s: &mut SdoServer, od: &mut TestOd, req: [u8; 8]) -> [u8; 8] {
        s.handle(&req, od).expect("a response")
    }

    /// Abort frame bytes written out by hand: 0x80, index LE, sub, code LE.
    fn abort(index: u16, sub: u8, code: u32) -> [u8; 8] {
        let i = index.to_le_bytes();
        let c = code.to_le_bytes();
        [0x80, i[0], i[1], sub, c[0], c[1], c[2], c[3]]
    }

    #[test]
    fn cob_ids() {
        // CiA 301 pre-defined connection set: SDO tx 0x580 + node, rx 0x600 + node.
        assert_eq!(request_cob_id(5), 0x605);
        assert_eq!(response_cob_id(127), 0x5FF);
    }

    #[test]
    fn expedited_upload_of_each_size() {
        let mut s = SdoServer::new();
        let mut od = TestOd {
            u32_2001: 0x1234_5678,
            i16_2000: -2,
            b_2004: 1,
            ..Default::default()
        };
        // CiA 301 §7.2.4 initiate upload response: scs=2, n=4-size, e=1, s=1 -> 0x43/0x4B/0x4F.
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x01, 0x20, 0, 0, 0, 0, 0]),
            [0x43, 0x01, 0x20, 0x00, 0x78, 0x56, 0x34, 0x12]
        );
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x00, 0x20, 0, 0, 0, 0, 0]),
            [0x4B, 0x00, 0x20, 0x00, 0xFE, 0xFF, 0, 0]
        );
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x04, 0x20, 0, 0, 0, 0, 0]),
            [0x4F, 0x04, 0x20, 0x00, 0x01, 0, 0, 0]
        );
    }

    #[test]
    fn expedited_download_sized_and_unsized() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        // 0x2B: ccs=1, n=2, e=1, s=1: two bytes 0x01F4 = 500.
        assert_eq!(
            run(&mut s, &mut od, [0x2B, 0x00, 0x20, 0, 0xF4, 0x01, 0, 0]),
            [0x60, 0x00, 0x20, 0x00, 0, 0, 0, 0]
        );
        assert_eq!(od.i16_2000, 500);
        // 0x22: e=1, s=0: size from the data type (UNSIGNED32).
        assert_eq!(
            run(&mut s, &mut od, [0x22, 0x01, 0x20, 0, 1, 2, 3, 4]),
            [0x60, 0x01, 0x20, 0x00, 0, 0, 0, 0]
        );
        assert_eq!(od.u32_2001, 0x0403_0201);
    }

    #[test]
    fn download_abort_paths() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        // Unknown index, unknown sub-index.
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x99, 0x29, 0, 0, 0, 0, 0]),
            abort(0x2999, 0, 0x0602_0000)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x06, 0x20, 9, 0, 0, 0, 0]),
            abort(0x2006, 9, 0x0609_0011)
        );
        // Read-only and constant entries.
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x06, 0x20, 1, 0, 0, 0, 0]),
            abort(0x2006, 1, 0x0601_0002)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x00, 0x10, 0, 0, 0, 0, 0]),
            abort(0x1000, 0, 0x0601_0002)
        );
        // 4 bytes (0x23) into INTEGER16: too long; 1 byte (0x2F): too short.
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x00, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2000, 0, 0x0607_0012)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x2F, 0x00, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2000, 0, 0x0607_0013)
        );
        // 0x03E9 = 1001 > 1000; 0xFC17 = -1001 < -1000.
        assert_eq!(
            run(&mut s, &mut od, [0x2B, 0x00, 0x20, 0, 0xE9, 0x03, 0, 0]),
            abort(0x2000, 0, 0x0609_0031)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x2B, 0x00, 0x20, 0, 0x17, 0xFC, 0, 0]),
            abort(0x2000, 0, 0x0609_0032)
        );
        // BOOLEAN 2.
        assert_eq!(
            run(&mut s, &mut od, [0x2F, 0x04, 0x20, 0, 2, 0, 0, 0]),
            abort(0x2004, 0, 0x0609_0030)
        );
        // Refusals of the application pass through unchanged.
        od.refuse = Some(Abort::WrongDeviceState);
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x01, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2001, 0, 0x0800_0022)
        );
        od.refuse = Some(Abort::General);
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x01, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2001, 0, 0x0800_0000)
        );
        od.refuse = Some(Abort::UnsupportedAccess);
        assert_eq!(
            run(&mut s, &mut od, [0x23, 0x01, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2001, 0, 0x0601_0000)
        );
        assert_eq!(od.writes, 0);
        assert_eq!(od.i16_2000, 0);
    }

    #[test]
    fn upload_abort_paths() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x02, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2002, 0, 0x0601_0001)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x99, 0x29, 0, 0, 0, 0, 0]),
            abort(0x2999, 0, 0x0602_0000)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x06, 0x20, 3, 0, 0, 0, 0]),
            abort(0x2006, 3, 0x0609_0011)
        );
        // The application returned 3 bytes for an UNSIGNED32.
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x09, 0x20, 0, 0, 0, 0, 0]),
            abort(0x2009, 0, 0x0800_0000)
        );
    }

    #[test]
    fn invalid_command_specifiers() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        // Block download initiate (ccs=6: 0xC0), block upload (ccs=5: 0xA0),
        // ccs=7 (0xE0): CiA 301 §7.2.4, 0x0504 0001.
        for cs in [0xC0u8, 0xA0, 0xE0] {
            assert_eq!(
                run(&mut s, &mut od, [cs, 0x00, 0x20, 0, 0, 0, 0, 0]),
                abort(0x2000, 0, 0x0504_0001)
            );
        }
        // Segments with no transfer under way.
        assert_eq!(
            run(&mut s, &mut od, [0x00, 1, 2, 3, 4, 5, 6, 7]),
            abort(0, 0, 0x0504_0001)
        );
        assert_eq!(
            run(&mut s, &mut od, [0x60, 0, 0, 0, 0, 0, 0, 0]),
            abort(0, 0, 0x0504_0001)
        );
        // A short frame (DLC 4) of an initiate upload.
        assert_eq!(
            s.handle(&[0x40, 0x00, 0x20, 0x00], &mut od),
            Some(abort(0x2000, 0, 0x0504_0001))
        );
        assert_eq!(s.handle(&[], &mut od), Some(abort(0, 0, 0x0504_0001)));
        // An abort from the client gets no answer.
        assert_eq!(s.handle(&[0x80, 0, 0x20, 0, 0, 0, 0, 0], &mut od), None);
    }

    /// "hello, drive world!" (19 bytes) downloaded in three segments:
    /// 7 + 7 + 5 bytes (last: n = 2, c = 1).
    #[test]
    fn segmented_download() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        // Initiate: 0x21 = ccs 1, e=0, s=1; size 19 = 0x13.
        assert_eq!(
            run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 0x13, 0, 0, 0]),
            [0x60, 0x03, 0x20, 0, 0, 0, 0, 0]
        );
        assert!(s.busy());
        // Segment t=0, n=0, c=0 -> 0x00; response 0x20.
        assert_eq!(
            run(
                &mut s,
                &mut od,
                [0x00, b'h', b'e', b'l', b'l', b'o', b',', b' ']
            ),
            [0x20, 0, 0, 0, 0, 0, 0, 0]
        );
        // t=1 -> 0x10; response 0x30.
        assert_eq!(
            run(
                &mut s,
                &mut od,
                [0x10, b'd', b'r', b'i', b'v', b'e', b' ', b'w']
            ),
            [0x30, 0, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(od.writes, 0);
        // t=0, n=2, c=1 -> 0b0000_0101 = 0x05.
        assert_eq!(
            run(&mut s, &mut od, [0x05, b'o', b'r', b'l', b'd', b'!', 0, 0]),
            [0x20, 0, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(&od.s_2003[..od.s_2003_len], b"hello, drive world!");
        assert!(!s.busy());
    }

    #[test]
    fn segmented_download_toggle_error_aborts_and_writes_nothing() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 0x0E, 0, 0, 0]);
        run(&mut s, &mut od, [0x00, 1, 2, 3, 4, 5, 6, 7]);
        // Second segment with t=0 again: 0x0503 0000.
        assert_eq!(
            run(&mut s, &mut od, [0x01, 1, 2, 3, 4, 5, 6, 7]),
            abort(0x2003, 0, 0x0503_0000)
        );
        assert!(!s.busy());
        assert_eq!(od.writes, 0);
        // First segment with t=1.
        run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 0x0E, 0, 0, 0]);
        assert_eq!(
            run(&mut s, &mut od, [0x10, 1, 2, 3, 4, 5, 6, 7]),
            abort(0x2003, 0, 0x0503_0000)
        );
        assert_eq!(od.writes, 0);
    }

    #[test]
    fn segmented_download_length_errors() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        // Indicated size 21 > capacity 20.
        assert_eq!(
            run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 21, 0, 0, 0]),
            abort(0x2003, 0, 0x0607_0012)
        );
        // Indicated size 1 for UNSIGNED32.
        assert_eq!(
            run(&mut s, &mut od, [0x21, 0x01, 0x20, 0, 1, 0, 0, 0]),
            abort(0x2001, 0, 0x0607_0013)
        );
        // Indicated 3, a single last segment of 7 bytes: more than indicated.
        run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 3, 0, 0, 0]);
        assert_eq!(
            run(&mut s, &mut od, [0x01, 1, 2, 3, 4, 5, 6, 7]),
            abort(0x2003, 0, 0x0607_0012)
        );
        // Indicated 10, the transfer ends after 7 (c=1, n=0): the length of
        // the service parameter does not match.
        run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 10, 0, 0, 0]);
        assert_eq!(
            run(&mut s, &mut od, [0x01, 1, 2, 3, 4, 5, 6, 7]),
            abort(0x2003, 0, 0x0607_0010)
        );
        // Size not indicated (0x20): accepted up to the value's check;
        // 4 bytes into UNSIGNED32 in one segment (n=3, c=1: 0x07).
        assert_eq!(
            run(&mut s, &mut od, [0x20, 0x01, 0x20, 0, 0, 0, 0, 0]),
            [0x60, 0x01, 0x20, 0, 0, 0, 0, 0]
        );
        assert_eq!(
            run(&mut s, &mut od, [0x07, 0xEF, 0xBE, 0xAD, 0xDE, 0, 0, 0]),
            [0x20, 0, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(od.u32_2001, 0xDEAD_BEEF);
        assert_eq!(od.writes, 1);
    }

    #[test]
    fn segmented_upload_and_its_toggle_error() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        od.s_2003[..10].copy_from_slice(b"servodrive");
        od.s_2003_len = 10;
        // Initiate response 0x41 (scs=2, e=0, s=1) with size 10.
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x03, 0x20, 0, 0, 0, 0, 0]),
            [0x41, 0x03, 0x20, 0, 10, 0, 0, 0]
        );
        // Segment request 0x60 (t=0): 7 bytes, n=0, c=0 -> 0x00.
        assert_eq!(
            run(&mut s, &mut od, [0x60, 0, 0, 0, 0, 0, 0, 0]),
            [0x00, b's', b'e', b'r', b'v', b'o', b'd', b'r']
        );
        // Segment request 0x70 (t=1): 3 bytes, n=4, c=1 -> 0x10|0x08|1 = 0x19.
        assert_eq!(
            run(&mut s, &mut od, [0x70, 0, 0, 0, 0, 0, 0, 0]),
            [0x19, b'i', b'v', b'e', 0, 0, 0, 0]
        );
        assert!(!s.busy());
        // Again, with the toggle not alternated on the second request.
        run(&mut s, &mut od, [0x40, 0x03, 0x20, 0, 0, 0, 0, 0]);
        run(&mut s, &mut od, [0x60, 0, 0, 0, 0, 0, 0, 0]);
        assert_eq!(
            run(&mut s, &mut od, [0x60, 0, 0, 0, 0, 0, 0, 0]),
            abort(0x2003, 0, 0x0503_0000)
        );
        assert!(!s.busy());
        // A download segment in the middle of an upload.
        run(&mut s, &mut od, [0x40, 0x03, 0x20, 0, 0, 0, 0, 0]);
        assert_eq!(
            run(&mut s, &mut od, [0x00, 0, 0, 0, 0, 0, 0, 0]),
            abort(0x2003, 0, 0x0504_0001)
        );
    }

    #[test]
    fn empty_string_uploads_as_one_empty_segment() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        assert_eq!(
            run(&mut s, &mut od, [0x40, 0x03, 0x20, 0, 0, 0, 0, 0]),
            [0x41, 0x03, 0x20, 0, 0, 0, 0, 0]
        );
        // n=7, c=1 -> 0x0F.
        assert_eq!(
            run(&mut s, &mut od, [0x60, 0, 0, 0, 0, 0, 0, 0]),
            [0x0F, 0, 0, 0, 0, 0, 0, 0]
        );
    }

    #[test]
    fn client_abort_ends_transfer() {
        let mut s = SdoServer::new();
        let mut od = TestOd::default();
        run(&mut s, &mut od, [0x21, 0x03, 0x20, 0, 0x0E, 0, 0, 0]);
        assert_eq!(
            s.handle(&[0x80, 0x03, 0x20, 0, 0, 0, 0, 0x08], &mut od),
            None
        );
        assert_eq!(
            run(&mut s, &mut od, [0x00, 1, 2, 3, 4, 5, 6, 7]),
            abort(0, 0, 0x0504_0001)
        );
    }
}
