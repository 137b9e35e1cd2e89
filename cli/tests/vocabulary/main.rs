//! Issue 31, "the command line as one vocabulary", as one test binary with a module per part
//! (one binary links faster and takes less disk than one per part): each test fails on the
//! binary before its fix.

#[path = "../common/mod.rs"]
mod common;

mod commands;
mod errors;
mod errors_flags;
mod numbers;
mod origin;
mod outputs;
mod refusals;
mod view;
mod written_names;
