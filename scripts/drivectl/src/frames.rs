//! The telemetry frames split off a console link's bytes
//! (`drive::telemetry`'s demultiplexer): the link's reader keeps the text,
//! the frames go to a [`Frames`] receiver.
use drive::telemetry::{Demux, Demuxed, Sample};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::Arc;
use std::time::Duration;

/// The receiving end of the frames found on a console link.
pub struct Frames {
    rx: Receiver<Sample>,
    bad: Arc<AtomicU64>,
}

/// The link reader's end: splits received bytes into text and frames.
pub struct Splitter {
    demux: Demux,
    tx: Sender<Sample>,
    bad: Arc<AtomicU64>,
}

impl Splitter {
    /// The text bytes of `bytes`; frames go to the [`Frames`] receiver.
    pub fn split(&mut self, bytes: &[u8]) -> Vec<u8> {
        let mut text = Vec::with_capacity(bytes.len());
        for &b in bytes {
            match self.demux.feed(b) {
                Demuxed::Text(t) => text.push(t),
                Demuxed::Frame(s) => {
                    // Nobody listening: the frame is not wanted.
                    let _ = self.tx.send(s);
                }
                Demuxed::Bad => {
                    self.bad.fetch_add(1, Ordering::Relaxed);
                }
                Demuxed::Nothing => {}
            }
        }
        text
    }
}

impl Frames {
    /// A connected pair.
    pub fn new() -> (Frames, Splitter) {
        let (tx, rx) = mpsc::channel();
        let bad = Arc::new(AtomicU64::new(0));
        (
            Frames {
                rx,
                bad: bad.clone(),
            },
            Splitter {
                demux: Demux::new(),
                tx,
                bad,
            },
        )
    }

    /// The next frame, waiting at most `timeout`.
    pub fn next(&self, timeout: Duration) -> Option<Sample> {
        // Timeout or a closed link: nothing more now.
        self.rx.recv_timeout(timeout).ok()
    }

    /// Every frame received so far.
    pub fn drain(&self) -> Vec<Sample> {
        self.rx.try_iter().collect()
    }

    /// Frames that failed their checks (CRC, COBS, length) since the start.
    pub fn bad(&self) -> u64 {
        self.bad.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use drive::telemetry::{FRAME_MAX, MAX_CHANNELS};

    #[test]
    fn the_splitter_keeps_text_and_counts_bad_frames() {
        let (frames, mut sp) = Frames::new();
        let mut buf = [0u8; FRAME_MAX];
        let sample = Sample {
            stream: 1,
            seq: 7,
            time_us: 10,
            n: 2,
            values: [1.0; MAX_CHANNELS],
        };
        let n = sample.encode(&mut buf);
        let mut wire = b"OK\r\n".to_vec();
        wire.extend_from_slice(&buf[..n]);
        let mut broken = buf;
        broken[5] ^= 0x10;
        wire.extend_from_slice(&broken[..n]);
        wire.extend_from_slice(b"drive> ");
        // Fed in two pieces, split inside the first frame.
        let mut text = sp.split(&wire[..9]);
        text.extend(sp.split(&wire[9..]));
        assert_eq!(text, b"OK\r\ndrive> ");
        let got = frames.drain();
        assert_eq!(got.len(), 1);
        assert_eq!(got[0].seq, 7);
        assert_eq!(frames.bad(), 1);
    }
}
