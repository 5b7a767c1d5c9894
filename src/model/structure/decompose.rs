//! The decomposition into Assur groups: the inputs on the frame first,
//! then, while links are left, a chained input placed on a known link, or
//! the next class II group (two units: links, or a cylinder's two links as
//! one) or class III group attached to the known links.

use super::{
    AssurGroup, Conn, Cylinder, Dyad, DyadKind, InputRole, Joint, Stage, Structure, Triad, mobility,
};
use crate::error::{Error, Result};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;

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
    let inputs: Vec<&InputSpec> = m.scene.inputs().collect();
    check_mobility(m, dof, inputs.len() as i64)?;
    let mut d = Decomposition::new(m, inputs.len());
    d.place_frame_inputs(&inputs)?;
    loop {
        // A driving pair with one of its links known places the other.
        if d.chain_one()? {
            continue;
        }
        let units = d.units();
        if units.is_empty() {
            break;
        }
        let Some(g) = d.find_group(&units) else {
            return Err(d.undecomposed());
        };
        d.attach(g)?;
    }
    Ok(Structure {
        dof,
        groups: d.groups,
        owner: d.owner,
        roles: d.roles,
        stages: d.stages,
        chained_links: d.chained_links,
    })
}

/// Chebyshev's W against the number of inputs `w`: the error that says
/// which the scene must change when they differ.
fn check_mobility(m: &Mechanism, dof: i64, w: i64) -> Result<()> {
    if dof == w {
        return Ok(());
    }
    let nl = m.links.len();
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
    Err(Error::structure(format!(
        "/input: the scene gives {w} inputs, but the {count}: {why}"
    )))
}

/// The decomposition under way: which links are known, the groups found
/// so far and the inputs' roles, in the order of attachment.
struct Decomposition<'m> {
    m: &'m Mechanism,
    /// The number of inputs (one is addressed as "/input").
    n_inputs: usize,
    known: Vec<bool>,
    owner: Vec<Option<usize>>,
    roles: Vec<InputRole>,
    stages: Vec<Stage>,
    /// Driving pairs on moving guides, not yet placed: (input, pair).
    pending: Vec<(usize, usize)>,
    chained_links: Vec<(usize, usize)>,
    groups: Vec<AssurGroup>,
}

impl<'m> Decomposition<'m> {
    fn new(m: &'m Mechanism, n_inputs: usize) -> Decomposition<'m> {
        let nl = m.links.len();
        let mut known = vec![false; nl];
        known[m.frame()] = true;
        Decomposition {
            m,
            n_inputs,
            known,
            owner: vec![None; nl],
            roles: vec![InputRole::Frame; n_inputs],
            stages: Vec::new(),
            pending: Vec::new(),
            chained_links: Vec::new(),
            groups: Vec::new(),
        }
    }

    /// The scene's pointer to input `i`.
    fn pointer(&self, i: usize) -> String {
        if self.n_inputs == 1 {
            "/input".to_string()
        } else {
            format!("/input/{i}")
        }
    }

    /// The inputs on the frame, known first; the driving sliders on moving
    /// guides wait (`pending`).
    fn place_frame_inputs(&mut self, inputs: &[&InputSpec]) -> Result<()> {
        let m = self.m;
        let only_frame = {
            let mut k = vec![false; m.links.len()];
            k[m.frame()] = true;
            k
        };
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
                self.pending.push((i, *pair));
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
                    self.pointer(i),
                    m.link_id(link)
                )));
            }
            self.known[link] = true;
            self.stages.push(Stage::Input(i));
        }
        Ok(())
    }

    /// Place one pending driving pair with one of its links known (the
    /// pair places the other): whether there was one.
    fn chain_one(&mut self) -> Result<bool> {
        let m = self.m;
        for k in 0..self.pending.len() {
            let (i, pair) = self.pending[k];
            let pr = &m.prismatics[pair];
            let (g, sl) = (pr.guide, pr.slider);
            match (self.known[g], self.known[sl]) {
                (true, true) => {
                    return Err(Error::structure(format!(
                        "{}/link: the slider \"{}\" and its guide \"{}\" are both determined without this input: it cannot drive them",
                        self.pointer(i),
                        m.link_id(sl),
                        m.link_id(g)
                    )));
                }
                (true, false) | (false, true) => {
                    let (kn, other) = if self.known[g] { (g, sl) } else { (sl, g) };
                    self.roles[i] = InputRole::Chained { known: kn, pair };
                    self.chained_links.push((kn, other));
                    self.known[other] = true;
                    self.stages.push(Stage::Input(i));
                    self.pending.remove(k);
                    return Ok(true);
                }
                (false, false) => {}
            }
        }
        Ok(false)
    }

    /// The units: single links, and the cylinders' two links as one, in
    /// the order of their first link.
    fn units(&self) -> Vec<Unit> {
        let m = self.m;
        let mut units: Vec<Unit> = Vec::new();
        for l in (0..m.links.len()).filter(|&l| !self.known[l]) {
            if units.iter().any(|u| u.contains(l)) {
                continue;
            }
            let cyl = self.pending.iter().find(|&&(_, p)| {
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
        units
    }

    /// The next group attached to the known links: a dyad of two units,
    /// else a three-leash group of single links.
    fn find_group(&self, units: &[Unit]) -> Option<AssurGroup> {
        self.find_dyad(units).or_else(|| self.find_triad(units))
    }

    fn find_dyad(&self, units: &[Unit]) -> Option<AssurGroup> {
        let driven: Vec<usize> = self.pending.iter().map(|&(_, p)| p).collect();
        for (i, &a) in units.iter().enumerate() {
            for &b in &units[i + 1..] {
                if a.cylinder.is_some() && b.cylinder.is_some() {
                    continue;
                }
                let set: Vec<usize> = a.members().iter().chain(b.members()).copied().collect();
                let conns = connections_but(self.m, &set, &self.known, &driven);
                if let Some(d) = as_dyad(a, b, &conns, &self.known) {
                    return Some(AssurGroup::Dyad(d));
                }
            }
        }
        None
    }

    fn find_triad(&self, units: &[Unit]) -> Option<AssurGroup> {
        let (m, known) = (self.m, &self.known);
        let nl = m.links.len();
        let unknown: Vec<usize> = units
            .iter()
            .filter(|u| u.cylinder.is_none())
            .map(|u| u.links[0])
            .collect();
        for &base in &unknown {
            let adj: Vec<usize> = unknown
                .iter()
                .copied()
                .filter(|&l| l != base && !connections(m, &[base, l], &vec![false; nl]).is_empty())
                .collect();
            for x in 0..adj.len() {
                for y in x + 1..adj.len() {
                    for z in y + 1..adj.len() {
                        let set = [base, adj[x], adj[y], adj[z]];
                        let conns = connections(m, &set, known);
                        if let Some(t) = as_triad(base, [adj[x], adj[y], adj[z]], &conns, known) {
                            return Some(AssurGroup::Triad(t));
                        }
                    }
                }
            }
        }
        None
    }

    /// The error of links left that form no group.
    fn undecomposed(&self) -> Error {
        let m = self.m;
        let nl = m.links.len();
        let ids: Vec<&str> = (0..nl)
            .filter(|&l| !self.known[l])
            .map(|l| m.link_id(l))
            .collect();
        let cylinders = if self.pending.is_empty() {
            String::new()
        } else {
            format!(
                " (a hydraulic cylinder — {} — enters a class II group as one link of variable length, joined to it by revolute pairs)",
                self.pending
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
        Error::structure(format!(
            "/links: links {} do not decompose into Assur groups of class II (dyads) or III (three-leash groups) attached to {}{cylinders}",
            ids.join(", "),
            (0..nl)
                .filter(|&l| self.known[l])
                .map(|l| m.link_id(l))
                .collect::<Vec<_>>()
                .join(", ")
        ))
    }

    /// Attach group `g` (refused when mechplan cannot solve it): its
    /// links known, a cylinder's input placed in it.
    fn attach(&mut self, g: AssurGroup) -> Result<()> {
        let m = self.m;
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
                    self.pointer(c.input),
                    g.label(m),
                    d.kind.name(),
                    m.link_id(m.prismatics[c.pair].guide),
                    m.link_id(m.prismatics[c.pair].slider)
                )));
            }
            self.roles[c.input] = InputRole::InGroup {
                group: self.groups.len(),
                pair: c.pair,
            };
            self.pending.retain(|&(i, _)| i != c.input);
        }
        for l in g.links() {
            self.known[l] = true;
            self.owner[l] = Some(self.groups.len());
        }
        self.stages.push(Stage::Group(self.groups.len()));
        self.groups.push(g);
        Ok(())
    }
}
