//! Every file mechplan reads, read through one bounded reader
//! ([`read_bounded`]): a scene, an answer (JSON, SVG, DXF, a marks file)
//! and a marks file's photo. At most the limit and one byte more is ever
//! read, whatever the file is (a regular file, a device such as
//! `/dev/zero`, a pipe fed without end): more than the limit is refused at
//! once, naming the file and the limit, as bad input (exit status 2).

use crate::error::{Error, Result};
use std::io::Read;
use std::path::Path;

/// The largest photo of a marks file read (64 MiB): a phone's photo is a
/// few megabytes.
pub const MAX_PHOTO_BYTES: u64 = 64 << 20;

/// The bytes of the file `path`, at most `limit` of them; `what` names
/// what the file is in the refusal ("a scene", "an answer", "a photo").
///
/// # Errors
///
/// [`Error::Io`] naming the file where it cannot be opened or read;
/// [`Error::Input`] naming the file and the limit where it holds more than
/// `limit` bytes (a regular file by its size, before it is read; any
/// other, a device or a pipe, as soon as `limit + 1` bytes are read).
pub fn read_bounded(path: &Path, limit: u64, what: &str) -> Result<Vec<u8>> {
    let name = path.display().to_string();
    let io = |source| Error::Io {
        path: name.clone(),
        source,
    };
    let f = std::fs::File::open(path).map_err(io)?;
    let at_most = format!("{what} may have at most {limit} bytes ({})", size(limit));
    if let Ok(md) = f.metadata()
        && md.is_file()
        && md.len() > limit
    {
        return Err(Error::scene(
            "",
            format!("{name}: the file has {} bytes; {at_most}", md.len()),
        ));
    }
    let mut bytes = Vec::new();
    f.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(Error::scene(
            "",
            format!("{name}: more than {limit} bytes read and it goes on; {at_most}"),
        ));
    }
    Ok(bytes)
}

/// The text of the file `path` (UTF-8), at most `limit` bytes of it, as
/// [`read_bounded`] reads it.
///
/// # Errors
///
/// Those of [`read_bounded`], and [`Error::Io`] naming the file where it
/// is not UTF-8.
pub fn read_text_bounded(path: &Path, limit: u64, what: &str) -> Result<String> {
    let bytes = read_bounded(path, limit, what)?;
    String::from_utf8(bytes).map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e.utf8_error()),
    })
}

/// A limit in binary units: "4 MiB", "512 KiB", "100 bytes".
fn size(bytes: u64) -> String {
    match bytes {
        b if b >= 1 << 20 && b % (1 << 20) == 0 => format!("{} MiB", b >> 20),
        b if b >= 1 << 10 && b % (1 << 10) == 0 => format!("{} KiB", b >> 10),
        b => format!("{b} bytes"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_in_binary_units() {
        assert_eq!(size(4 << 20), "4 MiB");
        assert_eq!(size(8 << 10), "8 KiB");
        assert_eq!(size(100), "100 bytes");
    }
}
