//! The model: what the scene file says ([`scene`]), the rigid links it
//! makes ([`shape`], [`mechanism`]) and their structure — mobility and
//! Assur groups in the order of attachment ([`structure`]).

pub mod mechanism;
pub mod scene;
pub mod shape;
pub mod structure;
