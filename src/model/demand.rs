//! What a scene asks to be computed, decided once: the groups to solve,
//! the links they solve, the points to report (`want.points`: only these
//! and the groups they hang on; else everything). Every part of mechplan
//! asks this type, instead of re-deciding from `want`.

use crate::model::mechanism::Mechanism;
use crate::model::structure::{InputRole, Structure};

/// The groups, links and points a scene wants (see the module's comment).
#[derive(Clone, Debug, PartialEq)]
pub struct Demand {
    /// Groups to solve, parallel to `Structure::groups`.
    pub need: Vec<bool>,
    /// Links solved (the frame, the inputs and the needed groups' links),
    /// parallel to the mechanism's links.
    pub include: Vec<bool>,
    /// Points reported, in scene order.
    pub points: Vec<usize>,
    /// The link that reports each point of the scene (the first solved
    /// link carrying it), found once: a sweep asks millions of times.
    carriers: Vec<Option<usize>>,
}

impl Demand {
    /// What `mech`'s scene wants, on its `structure`.
    pub fn of(mech: &Mechanism, structure: &Structure) -> Demand {
        let sc = &mech.scene;
        let points: Vec<usize> = match &sc.want.points {
            Some(p) => {
                let mut p = p.clone();
                p.sort_unstable();
                p
            }
            None => (0..sc.points.len()).collect(),
        };
        let carriers: Vec<usize> = points.iter().map(|&p| mech.links_of_point(p)[0]).collect();
        // The force analysis needs every link's equilibrium: with
        // `dynamics` every group is solved, whatever points are reported.
        let mut need = if sc.want.points.is_some() && sc.dynamics.is_none() {
            structure.needed_for(&carriers)
        } else {
            vec![true; structure.groups.len()]
        };
        let mut include = vec![false; mech.links.len()];
        include[mech.frame()] = true;
        // Every input placed before or between the groups is solved, with
        // the groups a chained input is placed on.
        for (i, role) in structure.roles.iter().enumerate() {
            match *role {
                InputRole::Frame => include[sc.input_at(i).link()] = true,
                InputRole::Chained { known, pair } => {
                    for (n, by) in need.iter_mut().zip(structure.needed_for(&[known])) {
                        *n |= by;
                    }
                    let pr = &mech.prismatics[pair];
                    include[pr.guide] = true;
                    include[pr.slider] = true;
                }
                InputRole::InGroup { .. } => {}
            }
        }
        for (g, grp) in structure.groups.iter().enumerate() {
            if need[g] {
                for l in grp.links() {
                    include[l] = true;
                }
            }
        }
        let carriers = (0..sc.points.len())
            .map(|p| {
                mech.links_of_point(p)
                    .into_iter()
                    .find(|&l| include[l])
            })
            .collect();
        Demand {
            need,
            include,
            points,
            carriers,
        }
    }

    /// Is group `g` solved?
    pub fn group(&self, g: usize) -> bool {
        self.need[g]
    }

    /// Is link `l` solved?
    pub fn link(&self, l: usize) -> bool {
        self.include[l]
    }

    /// The link that reports point `p`: the first solved link carrying it.
    pub fn carrier(&self, _mech: &Mechanism, p: usize) -> usize {
        self.carriers[p].expect("reported points are carried by solved links")
    }
}
