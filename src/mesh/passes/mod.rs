//! The mesh methods: N-pass and single view ([`npass`]), single pass ([`single_pass`]).

pub mod npass;
pub mod single_pass;

pub use npass::MeshNPass;
pub use single_pass::{CoverBounds, MeshSinglePass, MeshSinglePassOptions, Visibility};
