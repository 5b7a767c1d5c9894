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

use crate::error::{Error, Result};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;

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
    fn reversed(self) -> Conn {
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
        for st in &self.stages {
            match *st {
                Stage::Input(i) if matches!(self.roles[i], InputRole::Chained { .. }) => {
                    parts.push(class_one(i))
                }
                Stage::Input(_) => {}
                Stage::Group(g) => parts.push(self.groups[g].label(m)),
            }
        }
        parts.join(" -> ")
    }

    /// The input whose pair is `pair`, driving a cylinder or a chained
    /// slider (None for the others).
    pub fn input_of_pair(&self, pair: usize) -> Option<usize> {
        self.roles.iter().position(|r| {
            matches!(r, InputRole::Chained { pair: p, .. } | InputRole::InGroup { pair: p, .. } if *p == pair)
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
    fn owners(&self, l: usize) -> Option<usize> {
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

/// The pairs between a candidate set of links `g` and the known links: an
/// external pair joins a known link to one of `g`, an internal pair two of `g`.
/// The driving pairs of cylinders (`driven`) are not counted: their motion
/// is given.
fn connections_but(m: &Mechanism, g: &[usize], known: &[bool], driven: &[usize]) -> Vec<Conn> {
    let mut c = connections(m, g, known);
    c.retain(|c| !matches!(c.joint, Joint::P(k) if driven.contains(&k)));
    c
}

/// The pairs between a candidate set of links `g` and the known links: an
/// external pair joins a known link to one of `g`, an internal pair two of `g`.
fn connections(m: &Mechanism, g: &[usize], known: &[bool]) -> Vec<Conn> {
    let mut out = Vec::new();
    for p in 0..m.scene.points.len() {
        let ls = m.links_of_point(p);
        let in_g: Vec<usize> = ls.iter().copied().filter(|l| g.contains(l)).collect();
        if in_g.is_empty() {
            continue;
        }
        if let Some(&k) = ls.iter().find(|&&l| known[l]) {
            out.extend(in_g.iter().map(|&l| Conn {
                joint: Joint::R(p),
                from: k,
                to: l,
            }));
        } else {
            out.extend(in_g[1..].iter().map(|&l| Conn {
                joint: Joint::R(p),
                from: in_g[0],
                to: l,
            }));
        }
    }
    for (j, pr) in m.prismatics.iter().enumerate() {
        let (s, gd) = (pr.slider, pr.guide);
        let (sg, gg) = (g.contains(&s), g.contains(&gd));
        if sg && (gg || known[gd]) {
            out.push(Conn {
                joint: Joint::P(j),
                from: gd,
                to: s,
            });
        } else if gg && known[s] {
            out.push(Conn {
                joint: Joint::P(j),
                from: s,
                to: gd,
            });
        }
    }
    out
}

/// A unit of the decomposition: one link, or a cylinder's two.
#[derive(Clone, Copy, Debug)]
struct Unit {
    links: [usize; 2],
    /// The cylinder's pair and input (None: one link, `links[0]`).
    cylinder: Option<(usize, usize)>,
}

impl Unit {
    fn contains(&self, l: usize) -> bool {
        self.links[0] == l || (self.cylinder.is_some() && self.links[1] == l)
    }
    fn members(&self) -> &[usize] {
        if self.cylinder.is_some() {
            &self.links
        } else {
            &self.links[..1]
        }
    }
}

fn as_dyad(a: Unit, b: Unit, conns: &[Conn], known: &[bool]) -> Option<Dyad> {
    if conns.len() != 3 {
        return None;
    }
    let ext_of = |u: Unit| {
        conns
            .iter()
            .filter(|c| known[c.from] && u.contains(c.to))
            .copied()
            .collect::<Vec<_>>()
    };
    let mids: Vec<Conn> = conns.iter().filter(|c| !known[c.from]).copied().collect();
    let (ea, eb) = (ext_of(a), ext_of(b));
    if ea.len() != 1 || eb.len() != 1 || mids.len() != 1 {
        return None;
    }
    let mid = mids[0];
    if !(a.contains(mid.from) && b.contains(mid.to) || b.contains(mid.from) && a.contains(mid.to)) {
        return None;
    }
    let mid = if a.contains(mid.from) {
        mid
    } else {
        mid.reversed()
    };
    let mut ext1 = ea[0];
    let mut ext2 = eb[0].reversed();
    let mut units = [a, b];
    let mut mid = mid;
    let letters =
        |e1: &Conn, m: &Conn, e2: &Conn| [e1.joint.letter(), m.joint.letter(), e2.joint.letter()];
    let kind = match letters(&ext1, &mid, &ext2) {
        ['R', 'R', 'R'] => DyadKind::Rrr,
        ['R', 'R', 'P'] => DyadKind::Rrp,
        ['R', 'P', 'R'] => DyadKind::Rpr,
        ['P', 'R', 'P'] => DyadKind::Prp,
        ['R', 'P', 'P'] => DyadKind::Rpp,
        ['P', 'R', 'R'] | ['P', 'P', 'R'] => {
            // Read the contour from the other end.
            (ext1, ext2) = (ext2.reversed(), ext1.reversed());
            mid = mid.reversed();
            units = [b, a];
            if mid.joint.letter() == 'R' {
                DyadKind::Rrp
            } else {
                DyadKind::Rpp
            }
        }
        _ => return None, // PPP: no definite position
    };
    // A cylinder's slot link is the one of its two that carries the outer pair.
    let links = [ext1.to, ext2.from];
    let cylinder = units.iter().enumerate().find_map(|(slot, u)| {
        u.cylinder.map(|(pair, input)| Cylinder {
            slot,
            other: if u.links[0] == links[slot] {
                u.links[1]
            } else {
                u.links[0]
            },
            pair,
            input,
        })
    });
    Some(Dyad {
        kind,
        links,
        ext1,
        mid,
        ext2,
        cylinder,
    })
}

fn as_triad(base: usize, leashes: [usize; 3], conns: &[Conn], known: &[bool]) -> Option<Triad> {
    if conns.len() != 6 || conns.iter().any(|c| known[c.from] && c.to == base) {
        return None;
    }
    let mut ext = Vec::new();
    let mut int = Vec::new();
    for &l in &leashes {
        let e: Vec<Conn> = conns
            .iter()
            .filter(|c| known[c.from] && c.to == l)
            .copied()
            .collect();
        let i: Vec<Conn> = conns
            .iter()
            .filter(|c| {
                !known[c.from] && ((c.from == l && c.to == base) || (c.from == base && c.to == l))
            })
            .copied()
            .collect();
        if e.len() != 1 || i.len() != 1 {
            return None;
        }
        ext.push(e[0]);
        int.push(if i[0].from == l {
            i[0]
        } else {
            i[0].reversed()
        });
    }
    Some(Triad {
        base,
        leashes,
        ext: [ext[0], ext[1], ext[2]],
        int: [int[0], int[1], int[2]],
    })
}

/// Decompose the mechanism; fails with a clear message when W is not the
/// number of inputs or the links do not form class II / III groups.
pub fn analyse(m: &Mechanism) -> Result<Structure> {
    let dof = mobility(m);
    let nl = m.links.len();
    let inputs: Vec<&InputSpec> = m.scene.inputs().collect();
    let w = inputs.len() as i64;
    if dof != w {
        let count = format!(
            "mobility W = 3n - 2p5 = 3*{} - 2*{} = {dof}",
            nl - 1,
            m.revolutes.len() + m.prismatics.len()
        );
        if w == 1 {
            let why = if dof <= 0 {
                "the links cannot move (a structure, not a mechanism)".to_string()
            } else {
                format!("the mechanism needs {dof} inputs to move definitely: list them in /input")
            };
            return Err(Error::structure(format!(
                "/links: {count}, but the scene gives one input: {why}"
            )));
        }
        let why = if dof <= 0 {
            "the links cannot move (a structure, not a mechanism)".to_string()
        } else if dof > w {
            format!(
                "{} more input(s) are needed to move the mechanism definitely",
                dof - w
            )
        } else {
            format!(
                "{} input(s) too many: the mechanism cannot follow them all",
                w - dof
            )
        };
        return Err(Error::structure(format!(
            "/input: the scene gives {w} inputs, but the {count}: {why}"
        )));
    }
    let mut known = vec![false; nl];
    let mut owner = vec![None; nl];
    known[m.frame()] = true;
    let only_frame = {
        let mut k = vec![false; nl];
        k[m.frame()] = true;
        k
    };
    let pointer = |i: usize| {
        if w == 1 {
            "/input".to_string()
        } else {
            format!("/input/{i}")
        }
    };
    let mut roles = vec![InputRole::Frame; inputs.len()];
    let mut stages = Vec::new();
    // Driving pairs on moving guides, not yet placed: (input, pair).
    let mut pending: Vec<(usize, usize)> = Vec::new();
    let mut chained_links: Vec<(usize, usize)> = Vec::new();
    for (i, spec) in inputs.iter().enumerate() {
        let link = spec.link();
        let on_frame = match spec {
            InputSpec::Crank { .. } => true,
            InputSpec::Slider { pair, .. } => m.prismatics[*pair].guide == m.frame(),
        };
        if !on_frame {
            let InputSpec::Slider { pair, .. } = spec else {
                unreachable!("a crank turns about the frame")
            };
            pending.push((i, *pair));
            continue;
        }
        // The input must hang on the frame by one pair.
        let c = connections(m, &[link], &only_frame);
        let ok = match spec {
            InputSpec::Crank { pivot, .. } => c.len() == 1 && c[0].joint == Joint::R(*pivot),
            InputSpec::Slider { pair, .. } => c.len() == 1 && c[0].joint == Joint::P(*pair),
        };
        if !ok {
            return Err(Error::structure(format!(
                "{}/link: the input link \"{}\" must be joined to the frame by exactly its driving pair",
                pointer(i),
                m.link_id(link)
            )));
        }
        known[link] = true;
        stages.push(Stage::Input(i));
    }
    let mut groups: Vec<AssurGroup> = Vec::new();
    loop {
        // A driving pair with one of its links known places the other.
        let mut chained = false;
        for k in 0..pending.len() {
            let (i, pair) = pending[k];
            let pr = &m.prismatics[pair];
            let (g, sl) = (pr.guide, pr.slider);
            match (known[g], known[sl]) {
                (true, true) => {
                    return Err(Error::structure(format!(
                        "{}/link: the slider \"{}\" and its guide \"{}\" are both determined without this input: it cannot drive them",
                        pointer(i),
                        m.link_id(sl),
                        m.link_id(g)
                    )));
                }
                (true, false) | (false, true) => {
                    let (kn, other) = if known[g] { (g, sl) } else { (sl, g) };
                    roles[i] = InputRole::Chained { known: kn, pair };
                    chained_links.push((kn, other));
                    known[other] = true;
                    stages.push(Stage::Input(i));
                    pending.remove(k);
                    chained = true;
                    break;
                }
                (false, false) => {}
            }
        }
        if chained {
            continue;
        }
        let driven: Vec<usize> = pending.iter().map(|&(_, p)| p).collect();
        // The units: single links, and the cylinders' two links as one, in
        // the order of their first link.
        let mut units: Vec<Unit> = Vec::new();
        for l in (0..nl).filter(|&l| !known[l]) {
            if units.iter().any(|u| u.contains(l)) {
                continue;
            }
            let cyl = pending.iter().find(|&&(_, p)| {
                let pr = &m.prismatics[p];
                pr.guide == l || pr.slider == l
            });
            units.push(match cyl {
                Some(&(i, p)) => {
                    let pr = &m.prismatics[p];
                    Unit {
                        links: [l, if pr.guide == l { pr.slider } else { pr.guide }],
                        cylinder: Some((p, i)),
                    }
                }
                None => Unit {
                    links: [l, l],
                    cylinder: None,
                },
            });
        }
        if units.is_empty() {
            break;
        }
        let mut found = None;
        'dyads: for (i, &a) in units.iter().enumerate() {
            for &b in &units[i + 1..] {
                if a.cylinder.is_some() && b.cylinder.is_some() {
                    continue;
                }
                let set: Vec<usize> = a.members().iter().chain(b.members()).copied().collect();
                if let Some(d) = as_dyad(a, b, &connections_but(m, &set, &known, &driven), &known) {
                    found = Some(AssurGroup::Dyad(d));
                    break 'dyads;
                }
            }
        }
        let unknown: Vec<usize> = units
            .iter()
            .filter(|u| u.cylinder.is_none())
            .map(|u| u.links[0])
            .collect();
        if found.is_none() {
            'triads: for &base in &unknown {
                let adj: Vec<usize> = unknown
                    .iter()
                    .copied()
                    .filter(|&l| {
                        l != base && !connections(m, &[base, l], &vec![false; nl]).is_empty()
                    })
                    .collect();
                for x in 0..adj.len() {
                    for y in x + 1..adj.len() {
                        for z in y + 1..adj.len() {
                            let set = [base, adj[x], adj[y], adj[z]];
                            let conns = connections(m, &set, &known);
                            if let Some(t) =
                                as_triad(base, [adj[x], adj[y], adj[z]], &conns, &known)
                            {
                                found = Some(AssurGroup::Triad(t));
                                break 'triads;
                            }
                        }
                    }
                }
            }
        }
        let Some(g) = found else {
            let ids: Vec<&str> = (0..nl)
                .filter(|&l| !known[l])
                .map(|l| m.link_id(l))
                .collect();
            let cylinders = if pending.is_empty() {
                String::new()
            } else {
                format!(
                    " (a hydraulic cylinder — {} — enters a class II group as one link of variable length, joined to it by revolute pairs)",
                    pending
                        .iter()
                        .map(|&(_, p)| format!(
                            "links {} and {}",
                            m.link_id(m.prismatics[p].guide),
                            m.link_id(m.prismatics[p].slider)
                        ))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            };
            return Err(Error::structure(format!(
                "/links: links {} do not decompose into Assur groups of class II (dyads) or III (three-leash groups) attached to {}{cylinders}",
                ids.join(", "),
                (0..nl)
                    .filter(|&l| known[l])
                    .map(|l| m.link_id(l))
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        };
        if let AssurGroup::Triad(t) = &g
            && t.ext
                .iter()
                .chain(t.int.iter())
                .any(|c| matches!(c.joint, Joint::P(_)))
        {
            return Err(Error::structure(format!(
                "{} is a class III group with prismatic pairs; mechplan solves class III groups of revolute pairs only",
                g.label(m)
            )));
        }
        if let AssurGroup::Dyad(d) = &g
            && let Some(c) = d.cylinder
        {
            let by_revolutes = matches!((d.kind, c.slot), (DyadKind::Rrr, _) | (DyadKind::Rrp, 0));
            if !by_revolutes {
                return Err(Error::structure(format!(
                    "{}/link: group {} ({}) holds the cylinder {}-{} joined to it by a prismatic pair; mechplan solves a cylinder joined to its group by revolute pairs (kinds RRR, RRP)",
                    pointer(c.input),
                    g.label(m),
                    d.kind.name(),
                    m.link_id(m.prismatics[c.pair].guide),
                    m.link_id(m.prismatics[c.pair].slider)
                )));
            }
            roles[c.input] = InputRole::InGroup {
                group: groups.len(),
                pair: c.pair,
            };
            pending.retain(|&(i, _)| i != c.input);
        }
        for l in g.links() {
            known[l] = true;
            owner[l] = Some(groups.len());
        }
        stages.push(Stage::Group(groups.len()));
        groups.push(g);
    }
    Ok(Structure {
        dof,
        groups,
        owner,
        roles,
        stages,
        chained_links,
    })
}
