//! Students' answers drawn independently of mechplan's construction
//! kernel and grader (issue 37): a planar rigid-body velocity and
//! acceleration solver written from the method itself (`rigid`), the
//! scenes and positions it is run on (`scenes`), and the drawings a
//! student hands in, honest and mistaken, written as answer JSON exactly
//! as docs/check.md defines the answer file (`drawing`).
//!
//! What is taken from mechplan: the geometry of a solved position (where
//! each point of each link is, the direction of each guide line), and the
//! index of each scene name. Not taken: its velocities, accelerations,
//! plans, construction or grading — those come from the method alone:
//! every moving link L has the fields
//!
//!   v(P) = v(O_L) + ω_L × (P − O_L),
//!   a(P) = a(O_L) + ε_L × (P − O_L) − ω_L²·(P − O_L),
//!
//! a revolute pair makes two links' fields equal at its point, a prismatic
//! pair (slider s on guide g along the unit u at the contact point P)
//! makes v_s(P) = v_g(P) + v_rel·u, ω_s = ω_g and
//! a_s(P) = a_g(P) + 2·ω_g × v_rel·u + a_rel·u, ε_s = ε_g; the frame is
//! fixed; the inputs are what the scene states. Each plan is one linear
//! system (nalgebra).
#![allow(dead_code)]

pub mod drawing;
pub mod rigid;
pub mod scenes;
