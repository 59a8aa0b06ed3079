//! Exact steady-rolling reference for the contensou rolling laws: Kalker's exact half-space
//! theory on the Hertz ellipse (see README.md).

pub mod cases;
pub mod extrapolate;
pub mod grid;
pub mod influence;
pub mod kalker;
pub mod reference;
pub mod solver;

/// A writer of the text file at `path` (created or truncated): each call writes one line and
/// flushes, so a run cut short keeps the rows it has. Panics on an I/O error (a tool).
pub fn line_writer(path: impl AsRef<std::path::Path>) -> impl FnMut(&str) {
    use std::io::Write as _;
    let mut file = std::io::BufWriter::new(std::fs::File::create(path).expect("create csv"));
    move |text| {
        writeln!(file, "{text}")
            .and_then(|()| file.flush())
            .expect("write csv")
    }
}
