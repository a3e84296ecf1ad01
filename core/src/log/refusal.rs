//! The refusals of a log that another way of reading mends (or an option runs anyway), told
//! by kind (`Refusal::of`), so each front offers its way (an option, a command, a button)
//! without matching the words: the wasm package's `Error.code`, Python's `ValueError.code`,
//! the fleet rows' `error_code`.

use crate::error::Error;

/// A refusal that another way of reading mends (or, for a check error, an option runs
/// anyway), told by kind so each front offers its way (an option, a command, a button)
/// without matching the message's words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// A time that repeats or steps back by at most 1 s:
    /// [`TimeOrder::Fix`](super::accept::TimeOrder::Fix) puts it in order.
    TimeOrder,
    /// A time more than 1 s back (a logger restarted without a new header):
    /// [`JoinedLogs::Split`](super::accept::JoinedLogs::Split) reads each part as a log of
    /// its own.
    ClockReset,
    /// A second log joined on (`cat a.csv b.csv`):
    /// [`JoinedLogs::Split`](super::accept::JoinedLogs::Split) reads each.
    Joined,
    /// A row with fewer cells than the header: where it is the last line (a logger stopped
    /// mid-line), [`parse_fixing`](super::accept::parse_fixing) drops it.
    CutRow,
    /// A table without the v1 log's `time_s` column (a logger's own export, or a v1 log whose
    /// header is misspelt): a preset's import or a recipe reads it (`import`).
    Foreign,
    /// A log `check` finds an error in (a unit or sign mistake; [`accept`](super::accept::accept)):
    /// the finding's fix, or `ignore_check` runs it anyway.
    Check,
}

impl Refusal {
    /// The kind of the refusal `e` (the parser's, or `accept`'s for a check error), or None
    /// for any other error.
    pub fn of(e: &Error) -> Option<Refusal> {
        // A plain window search: `str::contains`' two-way searcher would add 0.6 kB to the
        // size-capped browser module (BENCHMARKS.md).
        let has = |message: &str, text: &str| message.as_bytes().windows(text.len()).any(|w| w == text.as_bytes());
        match e {
            // A time-order refusal that names a reset, the parser's or the fix's ("time 0 goes
            // back ..."), not a bad cell whose text says so ("\"...\" is not a number").
            Error::Cell { column, message, .. }
                if super::parse::is_time_order(column, message) && has(message, super::parse::CLOCK_RESET) =>
            {
                Some(Refusal::ClockReset)
            }
            Error::Cell { column, message, .. } if column == "time_s" && message.ends_with(super::parse::TIME_ORDER_REFUSAL) => {
                Some(Refusal::TimeOrder)
            }
            Error::Line { message, .. } if has(message, super::dialect::JOINED_REFUSAL) => Some(Refusal::Joined),
            Error::Line { message, .. } if message.ends_with(super::parse::CUT_ROW) => Some(Refusal::CutRow),
            Error::Line { message, .. } if message.starts_with(super::parse::NO_TIME_COLUMN) => Some(Refusal::Foreign),
            Error::Data(message) if has(message, super::accept::CHECK_REFUSED) => Some(Refusal::Check),
            _ => None,
        }
    }

    /// Its name for the fronts (the wasm package's `Error.code`, Python's `ValueError.code`).
    pub fn code(self) -> &'static str {
        match self {
            Refusal::TimeOrder => "time_order",
            Refusal::ClockReset => "clock_reset",
            Refusal::Joined => "joined",
            Refusal::CutRow => "cut_row",
            Refusal::Foreign => "foreign",
            Refusal::Check => "check",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::accept::{parse_by, TimeOrder};

    /// Each refusal a way of reading mends is told by kind, with its front name, from the
    /// parser's own error; other errors have none: a row cut short is one wherever it is
    /// (only `parse_fixing` judges whether it is the last line), a row with too many cells
    /// or a bad cell is not.
    #[test]
    fn a_refusal_is_told_by_kind() {
        let kind = |text: &str| Refusal::of(&parse_by(text.as_bytes(), TimeOrder::Error).unwrap_err()).map(Refusal::code);
        assert_eq!(kind("time_s,gyro_dps\n0,1\n1,1\n1,1\n"), Some("time_order"));
        assert_eq!(kind("time_s,gyro_dps\n0,1\n5,1\n1,1\n"), Some("clock_reset"));
        assert_eq!(kind("time_s,gyro_dps\n0,1\n1,1\n# name: b\ntime_s,gyro_dps\n0,1\n"), Some("joined"));
        // The page's parser refuses a cut last line, which this reader drops and says so.
        let cut = "time_s,gyro_dps,temp_c\n0,1,20\n0.1,1";
        assert_eq!(Refusal::of(&crate::log::parse_log(cut.as_bytes()).unwrap_err()), Some(Refusal::CutRow));
        assert_eq!(kind("time_s,gyro_dps,temp_c\n0,1\n1,1,20\n"), Some("cut_row"));
        assert_eq!(kind("time_s,gyro_dps\n0,1\n1,1,2\n"), None);
        assert_eq!(kind("time_s,gyro_dps\n0,x\n"), None);
        // A time cell whose text reads as a reset or a time-order refusal is a bad cell.
        assert_eq!(kind("time_s,gyro_dps\n0,1\na clock reset?,1\n"), None);
        assert_eq!(kind("time_s,gyro_dps\n0,1\ntime a clock reset?,1\n"), None);
        // The fix's refusal of a reset is one too.
        let fixing = parse_by(&b"time_s,gyro_dps\n0,1\n5,1\n1,1\n"[..], TimeOrder::Fix).unwrap_err();
        assert_eq!(Refusal::of(&fixing), Some(Refusal::ClockReset), "{fixing}");
        assert_eq!(kind("time_s,gyro_dps\n0,1\ntime must strictly increase,1\n"), None);
        // A table without time_s: a logger's own (a recipe reads it); any other header error is none.
        assert_eq!(kind("gyro_dps\n1\n"), Some("foreign"));
        assert_eq!(kind("Time (s);Gyroscope z (rad/s)\n0;1\n"), Some("foreign"));
        assert_eq!(kind("time_s,gyro_dps,gyro_dps\n0,1,1\n"), None);
        // Only a row's time: a gyro cell that repeats is no time-order refusal.
        let e = Error::Cell { line: 3, column: "gyro_dps".into(), message: "time must strictly increase".into() };
        assert_eq!(Refusal::of(&e), None);
        // Named inside a drive or file, it is the error of that drive or file, not the parser's.
        assert_eq!(Refusal::of(&parse_by(&b"time_s\n0\n0\n"[..], TimeOrder::Error).unwrap_err().within("a.csv")), None);
    }
}
