//! A live estimator's state saved to bytes and made again: a stream resumed where it stopped
//! (an app restarted, a job moved to another worker, a checkpoint) gives, row for row, the
//! headings it would have given uninterrupted. Postcard's compact binary (every f64 exact)
//! behind a header (format, gyrodrift version, state layout, estimator) and a checksum:
//! bytes that are not such a state, another estimator's, a build's whose estimators differ
//! or damaged ones are refused, saying which. The checksum finds damage, not a state
//! forged to pass it: such a state is refused by the settings' checks or runs on with the
//! numbers it holds, and does not panic (a test forges 2000).

use crate::error::{Error, Result};
use serde::de::DeserializeOwned;
use serde::Serialize;

/// The first bytes of every saved state.
const MAGIC: &[u8; 16] = b"gyrodrift state\n";

/// The saved estimators' layout (and the meaning of their fields): bumped whenever either
/// changes, so a state saved by a build whose estimators differ is refused rather than
/// misread (every commit of a release line shares its version number). The test
/// `the_saved_layout_is_the_recorded_one` trips on a change until this and its digest move.
const LAYOUT: u32 = 11;

/// An estimator whose state can be saved and resumed.
pub trait Resumable: Serialize + DeserializeOwned {
    /// The estimator's name in every front (the wasm package's and Python's class name), so
    /// a state saved in one front resumes in another.
    const KIND: &'static str;
    /// After loading: the settings checked as a new estimator's are, and what is not saved
    /// (a table the estimator computes from its settings) rebuilt.
    fn restored(self) -> Result<Self>;
}

/// The saved state: the bytes `gyrodrift state\n`, the checksum of the rest (FNV-1a, 64
/// bits, little-endian), then postcard's encoding of (gyrodrift version, the state layout,
/// estimator name, state).
pub fn save<T: Resumable>(state: &T) -> Result<Vec<u8>> {
    let body = postcard::to_stdvec(&(env!("CARGO_PKG_VERSION"), LAYOUT, T::KIND, state))
        .map_err(|e| Error::data(format!("saving the {}'s state: {e}", T::KIND)))?;
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(&fnv1a(&body).to_le_bytes());
    out.extend_from_slice(&body);
    Ok(out)
}

/// The estimator [`save`] saved; an error says why bytes are refused.
pub fn load<T: Resumable>(bytes: &[u8]) -> Result<T> {
    let refused = |why: String| Error::data(format!("restoring a {}: {why}", T::KIND));
    let Some(rest) = bytes.strip_prefix(MAGIC.as_slice()) else {
        return Err(refused("these bytes are not a saved gyrodrift state".into()));
    };
    let damaged = || refused("the saved state is damaged (its checksum differs): save it again".into());
    let (sum, body) = rest.split_first_chunk::<8>().ok_or_else(damaged)?;
    if u64::from_le_bytes(*sum) != fnv1a(body) {
        return Err(damaged());
    }
    let ((version, layout, kind), state) = postcard::take_from_bytes::<(&str, u32, &str)>(body).map_err(|_| damaged())?;
    if kind != T::KIND {
        return Err(refused(format!("the state is a {kind}'s")));
    }
    if layout != LAYOUT {
        return Err(refused(format!(
            "the state was saved by gyrodrift {version} (state layout {layout}), this is {} (layout {LAYOUT}): the estimators differ, start afresh",
            env!("CARGO_PKG_VERSION")
        )));
    }
    match postcard::take_from_bytes::<T>(state) {
        Ok((t, [])) => t.restored(),
        _ => Err(damaged()),
    }
}

/// FNV-1a, 64 bits.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gyrodometry::{Gyrodometry, GyrodometryOutput};
    use crate::hdr::{Hdr, HdrOutput, HdrParams};
    use crate::pipeline::{PipelineParams, PipelineStream};

    /// FNV-1a's published test vectors.
    #[test]
    fn fnv1a_hand_worked() {
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x8594_4171_f739_67e8);
    }

    /// A drive's rows: 20 s standing, then turns and straights with a bias and a speed.
    fn rows() -> Vec<(f64, f64, f64)> {
        (0..3000)
            .map(|i| {
                let t = i as f64 * 0.1;
                let turn = if t > 20.0 && (t / 30.0) as i64 % 3 == 1 { 12.0 } else { 0.0 };
                let speed = if t < 20.0 || (150.0..160.0).contains(&t) { 0.0 } else { 12.0 };
                (t, 0.7 + turn + 0.05 * ((i * 7919) % 13) as f64 / 13.0, speed)
            })
            .collect()
    }

    /// Saved at every 700th row and resumed from the bytes, each estimator gives what it
    /// gives uninterrupted, bit for bit, to the end.
    #[test]
    fn a_resumed_stream_gives_the_uninterrupted_headings_bit_for_bit() {
        let rows = rows();
        let mut whole = PipelineStream::new(PipelineParams::default()).unwrap();
        let mut resumed = whole.clone();
        let (mut hdr, mut hdr_resumed) = ((Hdr::new(HdrParams::default(), 0.7).unwrap(), None::<HdrOutput>), None);
        let mut odo = (Gyrodometry::new(0.5, 1.0, 0.7).unwrap(), None::<GyrodometryOutput>);
        let mut odo_resumed = odo.clone();
        for (i, &(t, w, v)) in rows.iter().enumerate() {
            if i % 700 == 0 {
                resumed = load(&save(&resumed).unwrap()).unwrap();
                hdr_resumed = Some(load::<(Hdr, Option<HdrOutput>)>(&save(hdr_resumed.as_ref().unwrap_or(&hdr)).unwrap()).unwrap());
                odo_resumed = load(&save(&odo_resumed).unwrap()).unwrap();
            }
            assert_eq!(whole.update(t, w, v).unwrap().to_bits(), resumed.update(t, w, v).unwrap().to_bits(), "row {i}");
            hdr.1 = Some(hdr.0.update(t, w).unwrap());
            let h = hdr_resumed.as_mut().unwrap();
            h.1 = Some(h.0.update(t, w).unwrap());
            assert_eq!(hdr.1, h.1, "row {i}");
            odo.1 = Some(odo.0.update(t, w, t * 0.3, t * 0.31).unwrap());
            odo_resumed.1 = Some(odo_resumed.0.update(t, w, t * 0.3, t * 0.31).unwrap());
            assert_eq!(odo.1, odo_resumed.1, "row {i}");
        }
        assert_eq!(whole.last_block(), resumed.last_block());
        // The stream had something to carry: the bias it learned (0.7 + the noise's mean).
        assert!((resumed.last_block().unwrap().bias_dps - 0.723).abs() < 0.05, "{:?}", resumed.last_block());
    }

    /// The bytes of each estimator's state after the same rows: a change of what is saved
    /// changes them. When this trips, bump [`LAYOUT`] if a field was added, removed,
    /// reordered, retyped or given another meaning (an older state would be misread), and
    /// record the new digests either way (a change of the estimators' numbers alone moves
    /// them too).
    #[test]
    fn the_saved_layout_is_the_recorded_one() {
        let mut pipe = PipelineStream::new(PipelineParams::default()).unwrap();
        let mut hdr = (Hdr::new(HdrParams::default(), 0.7).unwrap(), None::<HdrOutput>);
        let mut odo = (Gyrodometry::new(0.5, 1.0, 0.7).unwrap(), None::<GyrodometryOutput>);
        for &(t, w, v) in rows().iter().take(600) {
            pipe.update(t, w, v).unwrap();
            hdr.1 = Some(hdr.0.update(t, w).unwrap());
            odo.1 = Some(odo.0.update(t, w, t * 0.3, t * 0.31).unwrap());
        }
        let digest = |b: Vec<u8>| (b.len(), fnv1a(&b));
        let got = [
            digest(postcard::to_stdvec(&pipe).unwrap()),
            digest(postcard::to_stdvec(&hdr).unwrap()),
            digest(postcard::to_stdvec(&odo).unwrap()),
        ];
        assert_eq!(
            got,
            [(9674, 10327277118169256110), (159, 11021861302963414194), (107, 2674223023191593310)],
            "the saved state changed: see this test's doc"
        );
    }

    /// Bytes that are not a state, another estimator's, another layout's, damaged or cut
    /// are refused, each saying why; none panics.
    #[test]
    fn foreign_damaged_or_cut_bytes_are_refused_saying_why() {
        let mut s = PipelineStream::new(PipelineParams::default()).unwrap();
        for &(t, w, v) in rows().iter().take(500) {
            s.update(t, w, v).unwrap();
        }
        let bytes = save(&s).unwrap();
        let err = |b: &[u8]| load::<PipelineStream>(b).unwrap_err().to_string();
        assert!(err(b"time_s,gyro_dps\n").contains("not a saved gyrodrift state"));
        let hdr = save(&(Hdr::new(HdrParams::default(), 0.0).unwrap(), None::<HdrOutput>)).unwrap();
        assert_eq!(err(&hdr), "restoring a PipelineEstimator: the state is a HdrEstimator's");
        let mut flipped = bytes.clone();
        let mid = flipped.len() / 2;
        flipped[mid] ^= 1;
        assert!(err(&flipped).contains("damaged"));
        for cut in [MAGIC.len(), MAGIC.len() + 3, MAGIC.len() + 8, bytes.len() - 1] {
            assert!(err(&bytes[..cut]).contains("damaged"), "{cut}");
        }
        // Another layout's state (a build whose estimators differ): refused; another version
        // with this layout resumes.
        let with = |version: &str, layout: u32| {
            let body = postcard::to_stdvec(&(version, layout, "PipelineEstimator", &s)).unwrap();
            [MAGIC.as_slice(), &fnv1a(&body).to_le_bytes(), &body].concat()
        };
        assert!(err(&with("0.0.1", LAYOUT + 1)).contains(&format!("saved by gyrodrift 0.0.1 (state layout {}), this is", LAYOUT + 1)));
        assert!(load::<PipelineStream>(&with("0.0.1", LAYOUT)).is_ok());
        // Settings out of range in a checksummed state are refused as a new estimator's are.
        let bad = (Gyrodometry::new(0.5, 1.0, 0.0).unwrap(), None::<GyrodometryOutput>);
        let mut body = postcard::to_stdvec(&(env!("CARGO_PKG_VERSION"), LAYOUT, "GyrodometryEstimator", &bad)).unwrap();
        let at = body.windows(8).position(|w| w == 0.5f64.to_le_bytes()).unwrap();
        body[at..at + 8].copy_from_slice(&(-1.0f64).to_le_bytes());
        let forged = [MAGIC.as_slice(), &fnv1a(&body).to_le_bytes(), &body].concat();
        let e = load::<(Gyrodometry, Option<GyrodometryOutput>)>(&forged).unwrap_err().to_string();
        assert!(e.contains("wheelbase_m"), "{e}");
    }

    /// A state forged to pass the checksum (bytes of a saved state overwritten at random,
    /// the checksum recomputed) never panics: it is refused, or it loads and runs on (its
    /// numbers are whatever the bytes say). 2000 forgeries of 1-6 bytes each.
    #[test]
    fn a_forged_state_is_refused_or_runs_never_panics() {
        let mut s = PipelineStream::new(PipelineParams::default()).unwrap();
        let rows = rows();
        for &(t, w, v) in &rows[..600] {
            s.update(t, w, v).unwrap();
        }
        let body = postcard::to_stdvec(&(env!("CARGO_PKG_VERSION"), LAYOUT, "PipelineEstimator", &s)).unwrap();
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            seed >> 16
        };
        let mut loaded = 0;
        for _ in 0..2000 {
            let mut b = body.clone();
            for _ in 0..1 + next() % 6 {
                let at = next() as usize % b.len();
                b[at] = next() as u8;
            }
            let bytes = [MAGIC.as_slice(), &fnv1a(&b).to_le_bytes(), &b].concat();
            let run = std::panic::catch_unwind(|| {
                let Ok(mut st) = load::<PipelineStream>(&bytes) else { return false };
                for &(t, w, v) in &rows[600..1200] {
                    let _ = st.update(t, w, v);
                }
                true
            });
            loaded += usize::from(run.expect("a forged state panicked"));
        }
        assert!(loaded > 1000, "{loaded} of 2000 loaded: the forgeries reached the estimator");
    }
}
