//! Errors. User errors (a bad scene, a mechanism that cannot be assembled or
//! is singular) carry enough context to fix the input; they map to exit
//! status 2 in the binary. A result that could not be written
//! ([`Error::Write`]) maps to exit status 3.

use std::fmt;

/// One problem in a scene file, located by its JSON pointer.
#[derive(Clone, Debug, PartialEq)]
pub struct Issue {
    pub pointer: String,
    pub message: String,
}

impl fmt::Display for Issue {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        if self.pointer.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.pointer, self.message)
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// An input file could not be read.
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    /// A result could not be written (a full disk, a file-size limit, a
    /// closed pipe): `path` is the file or "standard output".
    #[error("cannot write {path}: {source}")]
    Write {
        path: String,
        source: std::io::Error,
    },
    /// Not JSON, or JSON with repeated names.
    #[error("{}", .0.join("\n"))]
    Json(Vec<String>),
    /// Every problem found in the scene, each with its JSON pointer.
    #[error("{}", list(.0))]
    Scene(Vec<Issue>),
    /// Mobility ≠ 1, or the links do not decompose into Assur groups.
    #[error("{0}")]
    Structure(String),
    /// A group does not close at some input position.
    #[error("{group} cannot be assembled at {at}: {why}")]
    Assembly {
        group: String,
        at: String,
        why: String,
    },
    /// A singular position: the kinematic equations have no unique solution.
    #[error("singular position at {at}: {why}")]
    Singular { at: String, why: String },
}

fn list(v: &[Issue]) -> String {
    v.iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

impl Error {
    pub fn scene(pointer: impl Into<String>, message: impl Into<String>) -> Error {
        Error::Scene(vec![Issue {
            pointer: pointer.into(),
            message: message.into(),
        }])
    }
}

pub type Result<T> = std::result::Result<T, Error>;
