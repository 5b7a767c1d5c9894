//! mechplan: graphoanalytic kinematic analysis of planar linkages.
//!
//! The data flow follows the method of a TMM course: [`scene`] (the file) →
//! [`mechanism`] (rigid links, pairs) → [`structure`] (mobility, Assur
//! groups) → [`positions`] → [`analytic`] (two independent routes) →
//! [`solve`] (sequences of positions, the cross-check) → [`report`].

pub mod analytic;
pub mod centres;
pub mod check;
pub mod construction;
pub mod diagrams;
pub mod drawing;
pub mod error;
pub mod frenet;
pub mod geom;
pub mod invariants;
pub mod json;
pub mod mechanism;
pub mod positions;
pub mod precision;
pub mod progress;
pub mod reference;
pub mod report;
pub mod scene;
pub mod shape;
pub mod solve;
pub mod structure;

pub use error::{Error, Issue, Result};
pub use scene::Scene;
pub use solve::{Analysis, Solved};

/// The embedded default scene: the lecture's six-link mechanism (Fig. 2.10).
pub const DEFAULT_SCENE: &str = include_str!("../fixtures/six_link_fig2_10.json");

/// Write to a temporary file beside `path`, then rename: never half a file.
pub fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    let io = |source| Error::Io {
        path: path.display().to_string(),
        source,
    };
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    let name = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.tmp{}", std::process::id()));
    std::fs::write(&tmp, bytes).map_err(io)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}
