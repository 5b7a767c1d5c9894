//! The worked examples of docs/check.md on what is judged before the
//! plan ("Before the plan: the values stated and the scale"): each
//! answer, read from the page, checked by the command prints the lines
//! the page prints, in order, and exits with status 1. The page's numbers
//! come from answers computed by hand from the method's vector equations
//! (the true positions and velocities from `solve`), never from `check`.
//! (The first worked example, a normal component reversed, is
//! `check_catalogue.rs::the_worked_example_in_the_docs`.)

mod common;
use common::check_docs_example;

/// The shaper's ω3 read wrong (v_B3C over l_CD), every step drawn with
/// it, the Coriolis acceleration too: one mistake, before the plan, the
/// steps carried forward; the second opinion on the true velocity plan.
#[test]
fn a_wrong_stated_omega_is_carried_forward() {
    check_docs_example("### A wrong stated ω, carried forward", "shaper_fig2_11");
}

/// The four-bar's acceleration plan drawn at μ = 0.2 and stated at 0.1:
/// one mistake, the scale, the steps right at the drawn μ, a_B read with
/// the stated μ right as a reading.
#[test]
fn a_plan_drawn_at_another_scale_is_one_mistake() {
    check_docs_example("### A plan drawn at another scale", "four_bar");
}

/// For contrast, one length off at the stated μ: a slip at its step,
/// quoted with the formula's length and the student's beside it.
#[test]
fn a_slip_in_one_length_quotes_the_students_length() {
    check_docs_example("#### For contrast: a slip in one length", "four_bar");
}
