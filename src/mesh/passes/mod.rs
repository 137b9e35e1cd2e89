//! The mesh methods: N-pass and single view ([`npass`]), single pass ([`single_pass`]), the
//! per-view duplication methods ([`duplicate`]: tiled, layered, MRT).

pub mod duplicate;
pub mod npass;
pub mod single_pass;

pub use duplicate::{MeshLayered, MeshMrt, MeshTiled};
pub use npass::MeshNPass;
pub use single_pass::{MeshSinglePass, MeshSinglePassOptions};
