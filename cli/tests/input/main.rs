//! Bad, hostile and foreign input: every refusal names the file or flag; the formats each command reads.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod bad_input;
mod formats;
mod hostile_input;
