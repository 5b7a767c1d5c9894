//! What the structure is: pairs and joints, the Assur groups (dyads of each kind, triads), the inputs' roles, the stages in the order of attachment, and Chebyshev's mobility.

use crate::model::mechanism::Mechanism;

/// A kinematic pair as it enters a group: `from` is the link on the known
/// side of the contour, `to` the next one along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conn {
    pub joint: Joint,
    pub from: usize,
    pub to: usize,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Joint {
    /// A revolute pair at a named point.
    R(usize),
    /// A prismatic pair (index into `Mechanism::prismatics`).
    P(usize),
}

impl Joint {
    pub fn letter(&self) -> char {
        match self {
            Joint::R(_) => 'R',
            Joint::P(_) => 'P',
        }
    }
}

impl Conn {
    pub(super) fn reversed(self) -> Conn {
        Conn {
            joint: self.joint,
            from: self.to,
            to: self.from,
        }
    }
}

/// The five kinds of class II groups; the letters read outer pair, middle
/// pair, outer pair (`000`, `002`: kind 1 RRR … kind 5 RPP).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DyadKind {
    Rrr,
    Rrp,
    Rpr,
    Prp,
    Rpp,
}

impl DyadKind {
    pub fn name(&self) -> &'static str {
        match self {
            DyadKind::Rrr => "RRR",
            DyadKind::Rrp => "RRP",
            DyadKind::Rpr => "RPR",
            DyadKind::Prp => "PRP",
            DyadKind::Rpp => "RPP",
        }
    }
    /// The kind number ("вид") of the textbooks.
    pub fn number(&self) -> u8 {
        match self {
            DyadKind::Rrr => 1,
            DyadKind::Rrp => 2,
            DyadKind::Rpr => 3,
            DyadKind::Prp => 4,
            DyadKind::Rpp => 5,
        }
    }
}

/// A class II group: the closed contour K1 →ext1→ L1 →mid→ L2 →ext2→ K2,
/// oriented so that the letters read as `kind`.
#[derive(Clone, Debug)]
pub struct Dyad {
    pub kind: DyadKind,
    pub links: [usize; 2],
    pub ext1: Conn,
    pub mid: Conn,
    pub ext2: Conn,
    /// A cylinder standing in for one of the two links.
    pub cylinder: Option<Cylinder>,
}

impl Dyad {
    /// The links the group places, without allocation: its two links in
    /// the dyad's order, then a cylinder's other link.
    pub fn placed_links(&self) -> GroupLinks {
        let mut links = GroupLinks {
            links: [self.links[0], self.links[1], 0, 0],
            len: 2,
        };
        if let Some(cy) = self.cylinder {
            links.links[2] = cy.other;
            links.len = 3;
        }
        links
    }
}

/// A group's links (at most four) without allocation, as a slice.
#[derive(Clone, Copy, Debug)]
pub struct GroupLinks {
    pub(super) links: [usize; 4],
    pub(super) len: usize,
}

impl std::ops::Deref for GroupLinks {
    type Target = [usize];
    fn deref(&self) -> &[usize] {
        &self.links[..self.len]
    }
}

/// A hydraulic cylinder in a class II group: the guide and the slider of a
/// driving slider, neither known before the group, one link of variable
/// length (their slide is the input's). `links[slot]` of the dyad is the
/// one of the two that carries the group's outer pair (ext1 for slot 0,
/// ext2 for slot 1); `other` is the other one. The middle pair may be on
/// either.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    pub slot: usize,
    pub other: usize,
    /// The driving prismatic pair (index into `Mechanism::prismatics`).
    pub pair: usize,
    /// Which input drives it (in the scene's order of inputs).
    pub input: usize,
}

/// How an input enters the structure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InputRole {
    /// A crank or a slider on a guide of the frame: a mechanism of class I
    /// on the frame, known first.
    Frame,
    /// A slider on a moving guide: its pair's link `known` is known before
    /// it, and the pair places the other link.
    Chained { known: usize, pair: usize },
    /// A cylinder: a slider on a moving guide whose two links are known
    /// only through group `group` ([`Cylinder`]).
    InGroup { group: usize, pair: usize },
}

/// One stage of the solution, in order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stage {
    /// Input i placed (a crank, a slider on the frame, a chained slider).
    Input(usize),
    /// Group g solved (a group with a cylinder places its input there).
    Group(usize),
}

/// A chained input: input `input` slides link `other` on the known link
/// `known` in its driving pair `pair` (a slider on a moving guide).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chained {
    pub input: usize,
    pub known: usize,
    pub pair: usize,
    pub other: usize,
}

/// One step of [`Structure::steps`], the walk in the order of attachment.
#[derive(Clone, Copy, Debug)]
pub enum Step<'a> {
    /// Input `input` on the frame moves its link `link` (a crank, a slider
    /// on a guide of the frame).
    Frame { input: usize, link: usize },
    /// A slider on a moving guide.
    Chained(Chained),
    /// Group `index` (a group with a cylinder places its input there).
    Group { index: usize, group: &'a AssurGroup },
}

/// A class III three-leash group: a base link joined to three leashes, each
/// leash joined to a known link (`004`).
#[derive(Clone, Debug)]
pub struct Triad {
    pub base: usize,
    pub leashes: [usize; 3],
    /// Known link → leash i.
    pub ext: [Conn; 3],
    /// Leash i → base.
    pub int: [Conn; 3],
}

impl Triad {
    /// The links the group places, without allocation: the three
    /// leashes, then the base.
    pub fn placed_links(&self) -> GroupLinks {
        GroupLinks {
            links: [self.leashes[0], self.leashes[1], self.leashes[2], self.base],
            len: 4,
        }
    }
}

#[derive(Clone, Debug)]
pub enum AssurGroup {
    Dyad(Dyad),
    Triad(Triad),
}

impl AssurGroup {
    /// Links in scene order, as the structure formula lists them.
    pub fn links(&self) -> Vec<usize> {
        let mut v = match self {
            AssurGroup::Dyad(d) => {
                let mut v = d.links.to_vec();
                v.extend(d.cylinder.map(|c| c.other));
                v
            }
            AssurGroup::Triad(t) => {
                let mut v = t.leashes.to_vec();
                v.push(t.base);
                v
            }
        };
        v.sort_unstable();
        v
    }
    /// The two links of a cylinder in the group (in the dyad's slot, the
    /// other).
    pub fn cylinder(&self) -> Option<(usize, usize)> {
        match self {
            AssurGroup::Dyad(d) => d.cylinder.map(|c| (d.links[c.slot], c.other)),
            AssurGroup::Triad(_) => None,
        }
    }
    pub fn class(&self) -> u8 {
        match self {
            AssurGroup::Dyad(_) => 2,
            AssurGroup::Triad(_) => 3,
        }
    }
    pub fn kind(&self) -> String {
        match self {
            AssurGroup::Dyad(d) => d.kind.name().to_string(),
            AssurGroup::Triad(t) => {
                let mut s = String::new();
                for i in 0..3 {
                    s.push(t.ext[i].joint.letter());
                    s.push(t.int[i].joint.letter());
                }
                format!("three-leash {s}")
            }
        }
    }
    /// Known links the group is attached to.
    pub fn attachments(&self) -> Vec<usize> {
        match self {
            AssurGroup::Dyad(d) => vec![d.ext1.from, d.ext2.to],
            AssurGroup::Triad(t) => t.ext.iter().map(|c| c.from).collect(),
        }
    }
    /// "II(2,3)" in the Artobolevsky numbering; a cylinder reads as one
    /// link of its two: "II(1,2-3)".
    pub fn label(&self, m: &Mechanism) -> String {
        let mut ids: Vec<String> = Vec::new();
        let cyl = self.cylinder();
        for l in self.links() {
            match cyl {
                Some((a, b)) if l == a.max(b) => continue,
                Some((a, b)) if l == a.min(b) => {
                    ids.push(format!("{}-{}", m.link_id(a.min(b)), m.link_id(a.max(b))))
                }
                _ => ids.push(m.link_id(l).to_string()),
            }
        }
        format!(
            "{}({})",
            if self.class() == 2 { "II" } else { "III" },
            ids.join(",")
        )
    }
}

#[derive(Clone, Debug)]
pub struct Structure {
    /// Chebyshev's W = 3n − 2p5 − p4.
    pub dof: i64,
    pub groups: Vec<AssurGroup>,
    /// For every link: the group that determines it (None: frame or input).
    pub owner: Vec<Option<usize>>,
    /// How each input (in the scene's order) enters.
    pub roles: Vec<InputRole>,
    /// The inputs and groups in the order they are solved.
    pub stages: Vec<Stage>,
    /// (known link, link placed) of each chained input.
    pub chained_links: Vec<(usize, usize)>,
}

impl Structure {
    /// The structure formula: the mechanisms of class I (joined by "+"),
    /// then the groups and chained inputs in the order of attachment:
    /// `I(0,1) -> II(2,3) -> II(4,5)`, `I(0,1) + I(0,4) -> II(2,3)`,
    /// `I(2,3) -> II(1,2-3)`.
    pub fn formula(&self, m: &Mechanism) -> String {
        let class_one = |i: usize| {
            let spec = m.scene.input_at(i);
            let (a, b) = match (self.roles[i], spec) {
                (InputRole::Frame, _) => (m.frame(), spec.link()),
                (InputRole::Chained { pair, .. } | InputRole::InGroup { pair, .. }, _) => {
                    (m.prismatics[pair].guide, m.prismatics[pair].slider)
                }
            };
            format!("I({},{})", m.link_id(a), m.link_id(b))
        };
        let first: Vec<String> = (0..self.roles.len())
            .filter(|&i| !matches!(self.roles[i], InputRole::Chained { .. }))
            .map(class_one)
            .collect();
        let mut parts = vec![first.join(" + ")];
        for step in self.steps(m) {
            match step {
                Step::Frame { .. } => {}
                Step::Chained(ch) => parts.push(class_one(ch.input)),
                Step::Group { group, .. } => parts.push(group.label(m)),
            }
        }
        parts.join(" -> ")
    }

    /// The walk over the structure in the order of attachment: each input
    /// on the frame, each chained input with the link its pair places, each
    /// group. An input that drives a cylinder is no step of its own: its
    /// group places it. The one walk that the solvers, the plans and the
    /// force analysis (backwards) take.
    pub fn steps<'a>(&'a self, m: &'a Mechanism) -> impl DoubleEndedIterator<Item = Step<'a>> + 'a {
        self.stages.iter().filter_map(move |&stage| match stage {
            Stage::Input(input) => match self.roles[input] {
                InputRole::Frame => Some(Step::Frame {
                    input,
                    link: m.scene.input_at(input).link(),
                }),
                InputRole::Chained { known, pair } => {
                    let pr = &m.prismatics[pair];
                    let other = if pr.guide == known {
                        pr.slider
                    } else {
                        pr.guide
                    };
                    Some(Step::Chained(Chained {
                        input,
                        known,
                        pair,
                        other,
                    }))
                }
                InputRole::InGroup { .. } => None,
            },
            Stage::Group(index) => Some(Step::Group {
                index,
                group: &self.groups[index],
            }),
        })
    }

    /// Groups needed to know the motion of `links` (with the groups they hang on), in order.
    pub fn needed_for(&self, links: &[usize]) -> Vec<bool> {
        let mut need = vec![false; self.groups.len()];
        let mut stack: Vec<usize> = links.iter().flat_map(|&l| self.owners(l)).collect();
        while let Some(g) = stack.pop() {
            if !need[g] {
                need[g] = true;
                stack.extend(
                    self.groups[g]
                        .attachments()
                        .iter()
                        .flat_map(|&l| self.owners(l)),
                );
            }
        }
        need
    }

    /// The group that determines link `l`; for the link a chained input
    /// places, the group of the link it is placed on (none for the frame
    /// and the inputs on it).
    pub(super) fn owners(&self, l: usize) -> Option<usize> {
        if let Some(g) = self.owner[l] {
            return Some(g);
        }
        self.chained_links
            .iter()
            .find(|&&(_, placed)| placed == l)
            .and_then(|&(known, _)| self.owners(known))
    }
}

/// Chebyshev's count: every point in k links is k−1 revolute pairs.
pub fn mobility(m: &Mechanism) -> i64 {
    let n = m.links.len() as i64 - 1;
    let p5 = (m.revolutes.len() + m.prismatics.len()) as i64;
    3 * n - 2 * p5
}
