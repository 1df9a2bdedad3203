//! Fuzz targets of the CANopen protocol core's inputs (`canopen`): the
//! SDO server's requests and the socketcand text protocol.
use canopen::od::{Abort, Access, DataType, Entry, ObjectDictionary, Table};
use canopen::sdo::SdoServer;
use canopen::socketcand::{Event, Mode, Reply, Server};

/// Capacity of the string entry, bytes (longer than one segment's 7).
const STRING_BYTES: u8 = 20;
/// Limits of the INTEGER16 entry.
const I16_MIN: i64 = -1000;
/// Upper limit of the INTEGER16 entry.
const I16_MAX: i64 = 1000;
/// Requests one SDO input carries, at most.
const REQUESTS_MAX: usize = 64;

/// The dictionary the SDO target runs on: one entry of each kind the
/// checks treat differently (limits, read-only, write-only, constant,
/// string, REAL32, an unknown sub-index next to a known one).
const ENTRIES: [Entry; 9] = [
    Entry::new(0x2000, 0, DataType::Integer16, Access::Rw).range(I16_MIN, I16_MAX),
    Entry::new(0x2001, 0, DataType::Unsigned32, Access::Rw),
    Entry::new(0x2002, 0, DataType::Unsigned8, Access::Ro),
    Entry::new(0x2003, 0, DataType::VisibleString(STRING_BYTES), Access::Rw),
    Entry::new(0x2004, 0, DataType::Boolean, Access::Rw),
    Entry::new(0x2005, 0, DataType::Real32, Access::Rw).real_range(-1.0, 1.0),
    Entry::new(0x2006, 0, DataType::Unsigned16, Access::Wo),
    Entry::new(0x2007, 0, DataType::Unsigned8, Access::Const),
    Entry::new(0x2007, 1, DataType::Integer32, Access::Rw),
];

/// The values of [`ENTRIES`], in order: bytes and length.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Od {
    values: [([u8; STRING_BYTES as usize], usize); ENTRIES.len()],
}

impl Od {
    fn new() -> Self {
        let mut values = [([0u8; STRING_BYTES as usize], 0); ENTRIES.len()];
        for (v, e) in values.iter_mut().zip(ENTRIES.iter()) {
            v.1 = e.data_type.size().unwrap_or(0);
        }
        // Something to read back from the read-only and constant entries.
        values[2].0[0] = 0x5A;
        values[7].0[0] = 1;
        Self { values }
    }

    fn slot(index: u16, sub: u8) -> Option<usize> {
        ENTRIES
            .iter()
            .position(|e| e.index == index && e.sub == sub)
    }

    /// Every value is one its entry allows.
    fn assert_in_range(&self) {
        let v = |i: usize| &self.values[i].0[..self.values[i].1];
        let i16v = i64::from(i16::from_le_bytes([v(0)[0], v(0)[1]]));
        assert!((I16_MIN..=I16_MAX).contains(&i16v), "0x2000 = {i16v}");
        assert!(v(4)[0] <= 1, "BOOLEAN = {}", v(4)[0]);
        let r = f32::from_le_bytes([v(5)[0], v(5)[1], v(5)[2], v(5)[3]]);
        assert!((-1.0..=1.0).contains(&r), "0x2005 = {r}");
        assert_eq!(
            (v(2), v(7)),
            (&[0x5A][..], &[1][..]),
            "a read-only entry changed"
        );
        assert!(self.values[3].1 <= usize::from(STRING_BYTES));
    }
}

impl ObjectDictionary for Od {
    fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
        Table::new(&ENTRIES).entry(index, sub)
    }
    fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        let (bytes, len) = &self.values[Self::slot(index, sub).ok_or(Abort::ObjectDoesNotExist)?];
        let dst = out.get_mut(..*len).ok_or(Abort::General)?;
        dst.copy_from_slice(&bytes[..*len]);
        Ok(*len)
    }
    fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), Abort> {
        let (bytes, len) =
            &mut self.values[Self::slot(index, sub).ok_or(Abort::ObjectDoesNotExist)?];
        bytes
            .get_mut(..data.len())
            .ok_or(Abort::General)?
            .copy_from_slice(data);
        *len = data.len();
        Ok(())
    }
}

/// The sdo target: the input is a sequence of requests, each a length
/// byte (taken mod 10, so 0..=9 bytes: an SDO frame has 8) and that many
/// bytes. Checks, per request: a request answered with an abort, or a
/// client's abort (no answer), changes no value and leaves no transfer
/// under way; a value changes only with a download's positive response;
/// every value stays one its entry allows.
pub fn sdo(data: &[u8]) {
    let mut s = SdoServer::new();
    let mut od = Od::new();
    let mut rest = data;
    for _ in 0..REQUESTS_MAX {
        let Some((&n, tail)) = rest.split_first() else {
            break;
        };
        let n = usize::from(n % 10).min(tail.len());
        let (req, tail) = tail.split_at(n);
        rest = tail;
        let before = od.clone();
        let resp = s.handle(req, &mut od);
        match resp {
            None => {
                assert!(
                    req.len() == 8 && req[0] >> 5 == 4,
                    "no answer to {req:02X?}"
                );
                assert_eq!(od, before, "a client abort changed a value");
                assert!(!s.busy());
            }
            Some(r) if r[0] == 0x80 => {
                assert_eq!(od, before, "refused ({r:02X?}), yet changed: {req:02X?}");
                assert!(!s.busy(), "a transfer survived its abort");
            }
            // scs 3: initiate download response; scs 1: download segment
            // response.
            Some(r) if od != before => {
                assert!(matches!(r[0] >> 5, 1 | 3), "{r:02X?} changed a value");
            }
            Some(_) => {}
        }
        od.assert_in_range();
    }
}

/// The socketcand target: the input as received bytes, in two chunks split
/// where its first byte says. Checks: the events do not depend on the
/// split (the parser keeps its state between chunks); a refused command
/// changes no mode; frames are sent only once a bus is open; every frame
/// sent, written back as python-can writes it, parses to the same frame.
pub fn socketcand(data: &[u8]) {
    let Some((&cut, input)) = data.split_first() else {
        return;
    };
    let mut whole = Server::new("can0").expect("a valid bus name");
    let mut split = whole.clone();
    let mut by_byte = Vec::new();
    for &b in input {
        let mode = whole.mode();
        let Some(e) = whole.push(b) else {
            continue;
        };
        match e {
            Event::Reply(Reply::Error(_)) => {
                assert_eq!(whole.mode(), mode, "a refused command changed the mode")
            }
            Event::Reply(_) => {}
            Event::Send(f) => {
                assert_ne!(mode, Mode::NoBus, "a frame before open");
                assert_eq!(resend(&f), Some(f));
            }
        }
        assert_eq!(whole.forwards_frames(), whole.mode() == Mode::Raw);
        by_byte.push(e);
    }
    let at = usize::from(cut).min(input.len());
    let mut chunked = Vec::new();
    split.feed(&input[..at], |e| chunked.push(e));
    split.feed(&input[at..], |e| chunked.push(e));
    assert_eq!(chunked, by_byte);
    assert_eq!(split.mode(), whole.mode());
}

/// `f` as python-can's `send` writes it, through a server in raw mode.
fn resend(f: &canopen::CanFrame) -> Option<canopen::CanFrame> {
    let mut s = Server::new("can0")?;
    let mut text = format!(
        "< open can0 >< rawmode >< send {:03X} {:x} ",
        f.id(),
        f.data().len()
    );
    for b in f.data() {
        text.push_str(&format!("{b:x} "));
    }
    text.push('>');
    let mut sent = None;
    s.feed(text.as_bytes(), |e| {
        if let Event::Send(g) = e {
            sent = Some(g);
        }
    });
    sent
}
