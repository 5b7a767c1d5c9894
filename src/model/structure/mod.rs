//! Structure: Chebyshev's mobility and the decomposition of the mechanism
//! into the input mechanisms and Assur groups in the order of attachment
//! (class II dyads of the five kinds, class III three-leash groups).
//!
//! Each input is a mechanism of class I: a crank or a slider on the frame
//! (I(0,1)); a driving slider on a moving guide is the input pair of its
//! guide and slider (I(2,3)), their relative slide given. When one of the
//! two is known before, the pair places the other (a manipulator's
//! telescopic arm on its crank). When neither is (a hydraulic cylinder
//! pivoted at both ends), the two are one link of known, variable length
//! at each instant ("2-3") and enter a class II group as that link.


mod decompose;
pub use decompose::analyse;
mod groups;
pub use groups::*;
