//! What the cross-check found the two routes (or a plan and a route) to
//! differ in most ([`Worst`]): a quantity of a point or of a link, kept as
//! data so that each medium names it in its own words (the refusals and
//! the JSON result in English by [`std::fmt::Display`], the terminal's
//! table in the scene's language by `crate::words`).

use std::fmt;

/// A quantity the cross-check compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// A point's place.
    Position,
    /// A link's angle.
    Angle,
    /// A point's velocity.
    Velocity,
    /// A link's angular velocity.
    Omega,
    /// A point's acceleration.
    Acceleration,
    /// A link's angular acceleration.
    Epsilon,
}

impl Quantity {
    /// The quantities in the order of [`Quantity::index`] (the unit tests
    /// go through them all).
    #[cfg(test)]
    pub const ALL: [Quantity; 6] = [
        Quantity::Position,
        Quantity::Velocity,
        Quantity::Acceleration,
        Quantity::Angle,
        Quantity::Omega,
        Quantity::Epsilon,
    ];

    /// Whether it is a link's (angle, ω, ε), else a point's.
    pub fn of_link(self) -> bool {
        matches!(self, Quantity::Angle | Quantity::Omega | Quantity::Epsilon)
    }

    /// Its place among its kind's: a point's place, v, a (0, 1, 2); a
    /// link's angle, ω, ε (0, 1, 2).
    pub fn index(self) -> usize {
        match self {
            Quantity::Position | Quantity::Angle => 0,
            Quantity::Velocity | Quantity::Omega => 1,
            Quantity::Acceleration | Quantity::Epsilon => 2,
        }
    }

    /// Its English name before the point or link: "v of", "angle of".
    fn words(self) -> &'static str {
        match self {
            Quantity::Position => "position of",
            Quantity::Angle => "angle of",
            Quantity::Velocity => "v of",
            Quantity::Omega => "ω of",
            Quantity::Acceleration => "a of",
            Quantity::Epsilon => "ε of",
        }
    }
}

/// An analytic route a plan is compared against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// Route (a): the closure of the contours.
    Contour,
    /// Route (b): the constraint equations.
    Constraint,
}

impl Route {
    /// Its English name: "contour", "constraint".
    pub fn name(self) -> &'static str {
        match self {
            Route::Contour => "contour",
            Route::Constraint => "constraint",
        }
    }
}

/// The worst item of a comparison: a quantity and the name of its point
/// (or the id of its link), `None` when nothing was compared; and, where
/// a plan differed most, the route it was compared against.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Worst {
    pub item: Option<(Quantity, String)>,
    pub plan: Option<Route>,
}

impl Worst {
    /// `quantity` of the point or link named `name`.
    pub fn of(quantity: Quantity, name: &str) -> Worst {
        Worst {
            item: Some((quantity, name.to_string())),
            plan: None,
        }
    }
}

/// In English: "v of B", "ε of link 3", "a of C (plan against the contour
/// route)", "none".
impl fmt::Display for Worst {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.item {
            None => f.write_str("none")?,
            Some((q, name)) if q.of_link() => write!(f, "{} link {name}", q.words())?,
            Some((q, name)) => write!(f, "{} {name}", q.words())?,
        }
        match self.plan {
            Some(route) => write!(f, " (plan against the {} route)", route.name()),
            None => Ok(()),
        }
    }
}
