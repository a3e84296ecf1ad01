//! What the battery examples share: the battery's bases from recorded logs given on the
//! command line (CSV v1, named by their file stems) and the simulated bases.
use gyrodrift::battery::{self, Base};

/// Recorded bases from the command line's CSV files, then the battery's simulated bases
/// (20 minutes). Panics naming the file that does not read: these are examples, run by hand.
pub fn bases_from_args() -> Vec<Base> {
    let mut bases: Vec<Base> = std::env::args()
        .skip(1)
        .map(|f| {
            let file = std::fs::File::open(&f).unwrap_or_else(|e| panic!("{f}: {e}"));
            let log = gyrodrift::parse_log(file).unwrap_or_else(|e| panic!("{f}: {e}"));
            let stem = std::path::Path::new(&f).file_stem().unwrap_or_default().to_string_lossy().into_owned();
            battery::recorded_base(&stem, log)
        })
        .collect();
    bases.extend(battery::simulated_bases(20.0));
    bases
}
