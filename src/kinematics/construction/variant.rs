//! The ways to build a plan besides the standard one: a typical
//! student's mistake made on purpose (so that a hand-drawn plan can be
//! diagnosed by the mistake that explains it), or the pencil's noise.

use crate::kinematics::analytic::Order as PlanKind;

/// A typical student's mistake, built into the construction on purpose so
/// that a hand-drawn plan can be diagnosed by the mistake that explains it.
/// Each kind is a decision the construction takes at certain steps (every
/// normal component, every similar figure …); `Variant::at` makes it at
/// one of them only.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mistake {
    /// The Coriolis acceleration turned the wrong way (against ω).
    CoriolisReversed,
    /// The Coriolis acceleration left out on a rotating guide.
    CoriolisForgotten,
    /// The Coriolis acceleration as ω·v_rel, without the factor 2.
    CoriolisFactorOne,
    /// A normal component laid off from the centre instead of toward it.
    NormalFromCentre,
    /// A normal component ω²·l left out.
    NormalForgotten,
    /// A similar figure built mirrored (letters in the wrong order).
    MirroredFigure,
    /// In an RRR group, each line drawn ⊥ the other link of the group.
    WrongPerpendicular,
    /// A relative (tangential) component drawn ∥ the link instead of ⊥ it.
    TangentialParallel,
    /// A point taken on the wrong link: on a rocking guide, the guide's
    /// coincident point b₃ taken as the slider's point b₂ (the relative
    /// sliding ignored).
    WrongLink,
    /// ε1 ≠ 0 but the tangential component of the crank's point left out.
    Epsilon1Forgotten,
    /// ε1 = 0 but a tangential component ε1·l added, taking ε1 = ω1².
    Epsilon1Added,
    /// Normal components computed with the input's ω1 instead of the link's ω.
    OmegaWrongLink,
    /// The crank's velocity laid off against the sense of ω1.
    OmegaWrongSense,
    /// One vector laid off with a wrong length (an arithmetic or measuring
    /// slip): its length times `Variant::factor`.
    Slip,
    /// A point of a link placed by the figure of a neighbouring link (one
    /// sharing a joint with it): S₂ of the coupler built on the rocker's
    /// points as if it were the rocker's.
    NeighbourLink,
    /// The relative sliding laid along the wrong line: the line of a
    /// slide drawn ⊥ the guide instead of ∥ it.
    SlideAcross,
    /// A point of a link taken at the plan point of its nearest known
    /// point on the link (s₂ drawn at b) instead of by its figure.
    PointAtNeighbour,
}

/// How to build a plan besides the standard way: with a mistake, or with
/// every drafting operation perturbed by the pencil (a hand drawing).
#[derive(Clone, Copy, Debug)]
pub struct Variant {
    pub mistake: Option<Mistake>,
    /// Which of the mistake's decisions is taken wrong, counted from 0 in
    /// the order of the construction ([`Plan::decisions`] counts them);
    /// `None`: every one (the mistake repeated wherever it can be made).
    pub at: Option<usize>,
    /// The plan the mistake is made on (`None`: both).
    pub on: Option<PlanKind>,
    /// For [`Mistake::Slip`]: the wrong length over the right one.
    pub factor: f64,
    /// A second mistake made together with the first, everywhere it can
    /// be (students combine some: a Coriolis acceleration reversed and the
    /// normals from the centre).
    pub also: Option<Mistake>,
    /// Seed of the pencil noise: each laid-off point, each line and each
    /// constructed point moves by at most δ.
    pub jitter: Option<u64>,
    /// The decisions (bit n: the n-th) the mistake is made at, where it
    /// is made at several but not at all (both lines of one point drawn
    /// wrong); 0: as `at` says.
    pub among: u64,
}

impl Default for Variant {
    fn default() -> Self {
        Variant {
            mistake: None,
            at: None,
            on: None,
            factor: 1.0,
            also: None,
            jitter: None,
            among: 0,
        }
    }
}

impl Variant {
    /// The mistake `m` at every decision of its kind, on both plans.
    pub fn everywhere(m: Mistake) -> Variant {
        Variant {
            mistake: Some(m),
            ..Variant::default()
        }
    }
}
