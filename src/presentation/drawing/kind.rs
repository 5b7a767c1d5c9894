//! What a sheet shows, as its file is named (`velocity_3.svg`,
//! `lever_2_1.pdf`, `course.svg`): one type for every place a sheet is
//! named or a file is recognised as one, so the names cannot drift apart.

use std::fmt;

/// What a sheet shows, by position where it shows one position (its
/// number in the study's numbering, as the sheets print it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SheetKind {
    /// The mechanism at one position (`mechanism_N`).
    Mechanism(usize),
    /// The plan of velocities at one position (`velocity_N`).
    Velocity(usize),
    /// The plan of accelerations at one position (`acceleration_N`).
    Acceleration(usize),
    /// The mechanism in every position (`positions`).
    Positions,
    /// The kinematic diagrams (`diagrams`).
    Diagrams,
    /// The course project's kinematic sheet (`course`).
    Course,
    /// The course project's force sheet (`course_forces`).
    CourseForces,
    /// The force analysis at one position (`forces_N`).
    Forces(usize),
    /// One group's (or input's) force analysis at one position, where
    /// the sheet asked for holds them only one by one (`forces_N_M`, M
    /// from 1 in the order of the analysis).
    ForcesPart {
        /// The position's number.
        position: usize,
        /// The part, from 0.
        part: usize,
    },
    /// Zhukovsky's lever at one position (`lever_N`), of one input
    /// (`lever_N_M`, M from 1) where the mechanism has several.
    Lever {
        /// The position's number.
        position: usize,
        /// The input (from 0) where there are several.
        input: Option<usize>,
    },
}

impl SheetKind {
    /// The file stem: `velocity_3`, `lever_2_1`, `course`.
    pub fn stem(&self) -> String {
        match self {
            SheetKind::Mechanism(n) => format!("mechanism_{n}"),
            SheetKind::Velocity(n) => format!("velocity_{n}"),
            SheetKind::Acceleration(n) => format!("acceleration_{n}"),
            SheetKind::Positions => "positions".into(),
            SheetKind::Diagrams => "diagrams".into(),
            SheetKind::Course => "course".into(),
            SheetKind::CourseForces => "course_forces".into(),
            SheetKind::Forces(n) => format!("forces_{n}"),
            SheetKind::ForcesPart { position, part } => format!("forces_{position}_{}", part + 1),
            SheetKind::Lever { position, input: None } => format!("lever_{position}"),
            SheetKind::Lever {
                position,
                input: Some(i),
            } => format!("lever_{position}_{}", i + 1),
        }
    }

    /// The kind a file stem names; `None` for a stem no sheet has.
    pub fn parse(stem: &str) -> Option<SheetKind> {
        let number = |s: &str| -> Option<usize> {
            (!s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()))
                .then(|| s.parse().ok())
                .flatten()
        };
        match stem {
            "positions" => return Some(SheetKind::Positions),
            "diagrams" => return Some(SheetKind::Diagrams),
            "course" => return Some(SheetKind::Course),
            "course_forces" => return Some(SheetKind::CourseForces),
            _ => {}
        }
        let (word, rest) = stem.split_once('_')?;
        match word {
            "mechanism" => number(rest).map(SheetKind::Mechanism),
            "velocity" => number(rest).map(SheetKind::Velocity),
            "acceleration" => number(rest).map(SheetKind::Acceleration),
            "forces" => match rest.split_once('_') {
                None => number(rest).map(SheetKind::Forces),
                Some((p, m)) => {
                    let (position, m) = (number(p)?, number(m)?);
                    (m >= 1).then_some(SheetKind::ForcesPart {
                        position,
                        part: m - 1,
                    })
                }
            },
            "lever" => match rest.split_once('_') {
                None => number(rest).map(|position| SheetKind::Lever {
                    position,
                    input: None,
                }),
                Some((p, i)) => {
                    let (position, i) = (number(p)?, number(i)?);
                    (i >= 1).then_some(SheetKind::Lever {
                        position,
                        input: Some(i - 1),
                    })
                }
            },
            _ => None,
        }
    }
}

impl fmt::Display for SheetKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.stem())
    }
}

#[cfg(test)]
mod tests {
    use super::SheetKind;

    #[test]
    fn every_kind_reads_back_from_its_stem() {
        let kinds = [
            SheetKind::Mechanism(0),
            SheetKind::Velocity(12),
            SheetKind::Acceleration(3),
            SheetKind::Positions,
            SheetKind::Diagrams,
            SheetKind::Course,
            SheetKind::CourseForces,
            SheetKind::Forces(7),
            SheetKind::ForcesPart {
                position: 7,
                part: 1,
            },
            SheetKind::Lever {
                position: 2,
                input: None,
            },
            SheetKind::Lever {
                position: 2,
                input: Some(1),
            },
        ];
        for k in kinds {
            assert_eq!(SheetKind::parse(&k.stem()), Some(k), "{k}");
        }
        for stem in ["velocity_", "velocity_x", "lever_2_0", "sheets", "course_", "forces", "forces_1_0"] {
            assert_eq!(SheetKind::parse(stem), None, "{stem}");
        }
    }
}
