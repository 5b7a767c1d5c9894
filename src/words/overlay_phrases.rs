//! The check's overlay's phrases (a part of [`super::catalogue`]'s
//! `check`): the marks and the legends of a kinematic plan's overlay and
//! of a force plan's.

/// The check's overlay: the wrong step's mark and the legend's lines.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OverlayPhrases {
    /// The mark beside the wrong step's lines: `{step}`.
    pub step: String,
    /// The legend: the right plan, the student's point, where a step puts
    /// it with its tolerance, a point off that place, the wrong step's
    /// lines (drawn from the student's points; on the right plan).
    pub right_plan: String,
    pub your_point: String,
    pub step_place: String,
    pub off: String,
    pub wrong_step_own: String,
    pub wrong_step_right: String,
    /// A force plan's overlay: its title (`{links}`, `{position}`,
    /// `{mu}`, `{right}`, `{count}`); the legend: the right polygon, the
    /// student's vector right, wrong (with its tolerance circle), not
    /// judged.
    pub force_title: String,
    pub force_right_plan: String,
    pub force_right: String,
    pub force_wrong: String,
    pub force_undecided: String,
}
