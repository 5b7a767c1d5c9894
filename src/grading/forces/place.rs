//! Which of a position's force plans an answer is: the one of its links.

use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{ForcePlan, Which};

/// A plan's place: its group's, or its input link's.
pub(super) fn which_of(p: &ForcePlan) -> Which {
    match (p.group, p.input) {
        (Some(g), _) => Which::Group(g),
        (None, Some(i)) => Which::Input(i),
        (None, None) => unreachable!("a plan is a group's or an input's"),
    }
}

/// Which plan the answer's links name.
pub(super) fn which(an: &Analysis, plans: &[ForcePlan], links: &[String]) -> Option<(Which, usize)> {
    let m = &an.mech;
    let mut want: Vec<&str> = links.iter().map(String::as_str).collect();
    want.sort_unstable();
    plans.iter().enumerate().find_map(|(k, p)| {
        let mut ids: Vec<&str> = p.links.iter().map(|&l| m.link_id(l)).collect();
        ids.sort_unstable();
        (ids == want).then(|| (which_of(p), k))
    })
}

