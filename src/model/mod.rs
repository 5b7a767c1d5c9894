//! The model: what the scene file says ([`scene`]), the rigid links it
//! makes ([`shape`], [`mechanism`]) and their structure — mobility and
//! Assur groups in the order of attachment ([`structure`]), and what the
//! scene wants computed of them ([`demand`]).

pub mod demand;
pub mod mechanism;
pub mod scene;
pub mod shape;
pub mod structure;
