//! Structure: Chebyshev's mobility and the decomposition of the mechanism
//! into the input mechanism and Assur groups in the order of attachment
//! (class II dyads of the five kinds, class III three-leash groups).

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
            AssurGroup::Dyad(d) => d.links.to_vec(),
            AssurGroup::Triad(t) => {
                let mut v = t.leashes.to_vec();
                v.push(t.base);
                v
            }
        };
        v.sort_unstable();
        v
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
    /// "II(2,3)" in the Artobolevsky numbering.
    pub fn label(&self, m: &Mechanism) -> String {
        let ids: Vec<&str> = self.links().iter().map(|&l| m.link_id(l)).collect();
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
}

impl Structure {
    pub fn formula(&self, m: &Mechanism) -> String {
        let mut parts = vec![format!(
            "I({},{})",
            m.link_id(m.frame()),
            m.link_id(m.scene.input.link())
        )];
        parts.extend(self.groups.iter().map(|g| g.label(m)));
        parts.join(" -> ")
    }

    /// Groups needed to know the motion of `links` (with the groups they hang on), in order.
    pub fn needed_for(&self, links: &[usize]) -> Vec<bool> {
        let mut need = vec![false; self.groups.len()];
        let mut stack: Vec<usize> = links.iter().filter_map(|&l| self.owner[l]).collect();
        while let Some(g) = stack.pop() {
            if !need[g] {
                need[g] = true;
                stack.extend(
                    self.groups[g]
                        .attachments()
                        .iter()
                        .filter_map(|&l| self.owner[l]),
                );
            }
        }
        need
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

fn as_dyad(a: usize, b: usize, conns: &[Conn], known: &[bool]) -> Option<Dyad> {
    if conns.len() != 3 {
        return None;
    }
    let ext_of = |l: usize| {
        conns
            .iter()
            .filter(|c| known[c.from] && c.to == l)
            .copied()
            .collect::<Vec<_>>()
    };
    let mids: Vec<Conn> = conns.iter().filter(|c| !known[c.from]).copied().collect();
    let (ea, eb) = (ext_of(a), ext_of(b));
    if ea.len() != 1 || eb.len() != 1 || mids.len() != 1 {
        return None;
    }
    let mid = mids[0];
    let mid = if mid.from == a { mid } else { mid.reversed() };
    let mut ext1 = ea[0];
    let mut ext2 = eb[0].reversed();
    let mut links = [a, b];
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
            links = [b, a];
            if mid.joint.letter() == 'R' {
                DyadKind::Rrp
            } else {
                DyadKind::Rpp
            }
        }
        _ => return None, // PPP: no definite position
    };
    Some(Dyad {
        kind,
        links,
        ext1,
        mid,
        ext2,
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

/// Decompose the mechanism; fails with a clear message when W ≠ 1 or the
/// links do not form class II / III groups.
pub fn analyse(m: &Mechanism) -> Result<Structure> {
    let dof = mobility(m);
    let nl = m.links.len();
    if dof != 1 {
        let why = if dof <= 0 {
            "the links cannot move (a structure, not a mechanism)"
        } else {
            "the mechanism needs more than one input to move definitely"
        };
        return Err(Error::structure(format!(
            "/links: mobility W = 3n - 2p5 = 3*{} - 2*{} = {dof}, but mechplan takes one input: {why}",
            nl - 1,
            m.revolutes.len() + m.prismatics.len()
        )));
    }
    let mut known = vec![false; nl];
    let mut owner = vec![None; nl];
    known[m.frame()] = true;
    let input = m.scene.input.link();
    known[input] = true;
    // The input must hang on the frame by one pair.
    let c = connections(m, &[input], &{
        let mut k = vec![false; nl];
        k[m.frame()] = true;
        k
    });
    let ok = match &m.scene.input {
        InputSpec::Crank { pivot, .. } => c.len() == 1 && c[0].joint == Joint::R(*pivot),
        InputSpec::Slider { pair, .. } => c.len() == 1 && c[0].joint == Joint::P(*pair),
    };
    if !ok {
        return Err(Error::structure(format!(
            "/input/link: the input link \"{}\" must be joined to the frame by exactly its driving pair",
            m.link_id(input)
        )));
    }
    let mut groups: Vec<AssurGroup> = Vec::new();
    loop {
        let unknown: Vec<usize> = (0..nl).filter(|&l| !known[l]).collect();
        if unknown.is_empty() {
            break;
        }
        let mut found = None;
        'dyads: for (i, &a) in unknown.iter().enumerate() {
            for &b in &unknown[i + 1..] {
                if let Some(d) = as_dyad(a, b, &connections(m, &[a, b], &known), &known) {
                    found = Some(AssurGroup::Dyad(d));
                    break 'dyads;
                }
            }
        }
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
            let ids: Vec<&str> = unknown.iter().map(|&l| m.link_id(l)).collect();
            return Err(Error::structure(format!(
                "/links: links {} do not decompose into Assur groups of class II (dyads) or III (three-leash groups) attached to {}",
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
        for l in g.links() {
            known[l] = true;
            owner[l] = Some(groups.len());
        }
        groups.push(g);
    }
    Ok(Structure { dof, groups, owner })
}
