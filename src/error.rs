//! Errors, by kind ([`Error`]): bad input ([`Input`]: what to fix and
//! where), a mechanism that cannot be solved at an input value
//! ([`Unsolvable`]), files, and mechplan's own failures.

use std::fmt;

/// One problem in a scene file, located by its JSON pointer.
#[derive(Clone, Debug, PartialEq)]
pub struct Issue {
    /// Where: a JSON pointer (`/links/2/points/1`), a parameter's name
    /// (`output`), or empty for the file as a whole.
    pub pointer: String,
    /// What is wrong, and how to fix it.
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

/// Everything that can go wrong, in four kinds: bad input (the scene or
/// answer file, or a parameter — each problem where it is), a mechanism
/// that cannot be solved at an input value, reading or writing a file, and
/// mechplan's own failures. The binary maps them to exit statuses: 2 bad
/// input and cannot solve, 3 a write, 5 internal.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input: what to fix, and where.
    #[error(transparent)]
    Input(#[from] Input),
    /// The mechanism cannot be solved at an input value.
    #[error(transparent)]
    Unsolvable(#[from] Unsolvable),
    /// An input file could not be read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Why it could not be read.
        source: std::io::Error,
    },
    /// A result could not be written (a full disk, a file-size limit, a
    /// closed pipe): `path` is the file or "standard output".
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file, or "standard output".
        path: String,
        /// Why it could not be written.
        source: std::io::Error,
    },
    /// A failure of mechplan's own (an encoder that fails, a drawing that
    /// is not valid SVG): a bug to report, not the user's to fix.
    #[error("internal error: {0}")]
    Internal(String),
}

/// Bad input: each problem with where it is — a JSON pointer into the
/// scene or answer (`/links/2/points/1`), or a parameter's name (`output`,
/// `position`, `sheet`) that the command line shows as its option.
#[derive(Debug, thiserror::Error)]
pub enum Input {
    /// Not JSON, or JSON with repeated names.
    #[error("{}", .0.join("\n"))]
    Json(Vec<String>),
    /// Every problem found in the fields, each with its place.
    #[error("{}", list(.0))]
    Fields(Vec<Issue>),
    /// The mechanism's structure: a mobility other than the number of
    /// inputs, links that make no Assur groups, a sketch at a dead point.
    #[error("{0}")]
    Structure(String),
}

/// A mechanism that cannot be solved at an input value (`at`: "φ = 30°",
/// "s = 0.05 m").
#[derive(Debug, thiserror::Error)]
pub enum Unsolvable {
    /// A group does not close there.
    #[error("{group} cannot be assembled at {at}: {why}")]
    Assembly {
        /// The group ("group II(2,3) (RRR)") or route that does not close.
        group: String,
        /// The input value ("φ = 30°").
        at: String,
        /// Why: the circles that do not meet, and by how much.
        why: String,
    },
    /// A singular position: the kinematic equations have no unique
    /// solution there, or one the data's rounding decides.
    #[error("singular position at {at}: {why}")]
    Singular {
        /// The input value.
        at: String,
        /// Why: the dead point, the routes' disagreement, the data's rounding.
        why: String,
    },
}

fn list(v: &[Issue]) -> String {
    v.iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

impl Error {
    /// One problem of the input, at `pointer`.
    pub fn scene(pointer: impl Into<String>, message: impl Into<String>) -> Error {
        Error::fields(vec![Issue {
            pointer: pointer.into(),
            message: message.into(),
        }])
    }
    /// Problems of the input, each at its place.
    pub fn fields(issues: Vec<Issue>) -> Error {
        Error::Input(Input::Fields(issues))
    }
    /// A file that is not JSON.
    pub fn json(lines: Vec<String>) -> Error {
        Error::Input(Input::Json(lines))
    }
    /// A structure that is not a mechanism mechplan solves.
    pub fn structure(message: impl Into<String>) -> Error {
        Error::Input(Input::Structure(message.into()))
    }
    /// A group that does not close at `at`.
    pub fn assembly(
        group: impl Into<String>,
        at: impl Into<String>,
        why: impl Into<String>,
    ) -> Error {
        Error::Unsolvable(Unsolvable::Assembly {
            group: group.into(),
            at: at.into(),
            why: why.into(),
        })
    }
    /// A singular position at `at`.
    pub fn singular(at: impl Into<String>, why: impl Into<String>) -> Error {
        Error::Unsolvable(Unsolvable::Singular {
            at: at.into(),
            why: why.into(),
        })
    }
    /// The problems of the input, if it is that kind of error.
    pub fn issues_mut(&mut self) -> Option<&mut Vec<Issue>> {
        match self {
            Error::Input(Input::Fields(v)) => Some(v),
            _ => None,
        }
    }
}

/// mechplan's result type.
pub type Result<T> = std::result::Result<T, Error>;

/// Name `name` in the messages of an input's problems ("… (in NAME)"):
/// those of its fields and those of its JSON (a syntax error at its line
/// and column, a repeated name).
pub fn in_file(name: &str) -> impl Fn(Error) -> Error + '_ {
    move |e| match e {
        Error::Input(Input::Json(lines)) => Error::json(
            lines
                .into_iter()
                .map(|l| format!("{l} (in {name})"))
                .collect(),
        ),
        Error::Input(Input::Fields(mut v)) => {
            for i in &mut v {
                i.message = format!("{} (in {name})", i.message);
            }
            Error::fields(v)
        }
        e => e,
    }
}
