//! Reading the files a scene comes from: the scene itself and the tables it names. Every read is
//! capped before it starts (a regular file, at most a stated size; `/dev/zero` or a pipe is refused,
//! never read until memory runs out), and text that is not UTF-8 is reported with the line and
//! byte of its first bad byte.

use std::io::Read;
use std::path::Path;

/// Largest scene file read (16 MiB: a list of a million values fits).
pub const MAX_SCENE_BYTES: u64 = 16 << 20;
/// Largest table file a scene may name (a stiffness CSV).
pub const MAX_TABLE_BYTES: u64 = 4 << 20;

/// Why a file could not be read as text.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("{0}")]
    Io(#[from] std::io::Error),
    #[error("not a regular file (a folder, a device or a pipe cannot be a scene or a table)")]
    NotAFile,
    #[error("larger than the limit of {limit} bytes")]
    TooLarge { limit: u64 },
    #[error("not UTF-8 text: line {line}, byte {column} of the line (byte {offset} of the file) is 0x{byte:02X}")]
    NotUtf8 { line: usize, column: usize, offset: usize, byte: u8 },
}

/// Reads a UTF-8 text file of at most `limit` bytes.
pub fn read_text(path: &Path, limit: u64) -> Result<String, ReadError> {
    text(read_bytes(path, limit)?)
}

/// Reads a regular file of at most `limit` bytes: a folder, a device (`/dev/zero`) or a pipe is
/// refused before anything is read (opening a pipe would block until something writes to it), and
/// no more than `limit + 1` bytes are ever read. The files a user gives go through here: scenes,
/// tables, traces and REXS models.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    if !std::fs::metadata(path)?.is_file() {
        return Err(ReadError::NotAFile);
    }
    let file = std::fs::File::open(path)?;
    if !file.metadata()?.is_file() {
        return Err(ReadError::NotAFile);
    }
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge { limit });
    }
    Ok(bytes)
}

/// Bytes as UTF-8 text, or where the first bad byte is.
pub fn text(bytes: Vec<u8>) -> Result<String, ReadError> {
    String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line_start = bytes[..offset].iter().rposition(|b| *b == b'\n').map_or(0, |i| i + 1);
        let line = bytes[..offset].iter().filter(|b| **b == b'\n').count() + 1;
        ReadError::NotUtf8 { line, column: offset - line_start + 1, offset: offset + 1, byte: bytes[offset] }
    })
}
