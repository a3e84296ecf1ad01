//! One error type for every front: the CLI prints it, the wasm package throws it.
//! Messages name the line and column of the input where there is one, so a user can
//! find the bad cell; nothing in core panics on bad input.

use thiserror::Error;

/// Everything that can go wrong between reading a log and printing a result.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// A cell or row of the CSV that cannot be read (1-based line of the file).
    #[error("line {line}, column {column}: {message}")]
    Cell { line: u64, column: String, message: String },
    /// A whole row or the file's structure is wrong (1-based line of the file).
    #[error("line {line}: {message}")]
    Line { line: u64, message: String },
    /// The file as a whole is unusable (empty, no data rows, too large).
    #[error("{0}")]
    File(String),
    /// A column the method needs is absent from the header.
    #[error("missing column {column}: {needed_by}")]
    MissingColumn { column: String, needed_by: String },
    /// A parameter out of its valid range, or unknown.
    #[error("parameter {name}: {message}")]
    Param { name: String, message: String },
    /// The log has the columns but not the data a method needs.
    #[error("{0}")]
    Data(String),
    /// An I/O failure of the underlying reader or writer.
    #[error("I/O error: {0}")]
    Io(String),
    /// An error inside a named drive, file or recipe: the name, then the error in its own
    /// form (a line and column stay a line and column through every layer).
    #[error("{name}: {source}")]
    In { name: String, source: Box<Error> },
}

impl Error {
    pub(crate) fn param(name: &str, message: impl Into<String>) -> Self {
        Error::Param { name: name.to_string(), message: message.into() }
    }
    pub(crate) fn data(message: impl Into<String>) -> Self {
        Error::Data(message.into())
    }
    /// This error, inside the named drive, file or recipe.
    pub fn within(self, name: &str) -> Self {
        Error::In { name: name.to_string(), source: Box::new(self) }
    }
    pub(crate) fn missing(column: &str, needed_by: &str) -> Self {
        Error::MissingColumn { column: column.to_string(), needed_by: needed_by.to_string() }
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Self {
        Error::Io(io_message(&e))
    }
}

/// An I/O error's text. In wasm, where the input is bytes in memory and the only I/O errors
/// are core's own (a size limit), their message alone: `io::Error`'s Display would link
/// the text of every OS error kind into the browser's size-capped module (BENCHMARKS.md).
pub(crate) fn io_message(e: &std::io::Error) -> String {
    #[cfg(target_arch = "wasm32")]
    return e.get_ref().map_or_else(|| "the input could not be read".to_string(), |inner| inner.to_string());
    #[cfg(not(target_arch = "wasm32"))]
    e.to_string()
}

pub type Result<T> = std::result::Result<T, Error>;
