//! criterion: K/E per method × precision, beside the `ellip` crate.
fn main() {}
