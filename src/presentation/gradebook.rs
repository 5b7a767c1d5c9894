//! A group of answers graded at once (`mechplan check SCENE DIR`): a row
//! per answer ([`GradeRow`], made by [`row_of`] from a check's report, the
//! one place that reads the report for it), the gradebook as CSV
//! ([`gradebook_csv`]), the summary page as one offline HTML file
//! ([`summary_html`]), and the totals with the group's exit status
//! ([`Totals`]). Reading the answers and writing the files is the front
//! door's (`crate::study`).

use crate::grading::forces::ForceReport;
use crate::grading::{Judgement, Report, Verdict};
use crate::kinematics::construction::PlanKind;
use crate::presentation::drawing::canvas::xml;
use crate::lang::Lang;
use crate::presentation::report::csv_field;
use crate::words::check;
use crate::words::numbers::quantity;
use std::fmt::Write as _;

/// An answer's grade: its check's status, or unreadable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Grade {
    /// Every item right (status 0).
    Right,
    /// An item wrong (status 1).
    Wrong,
    /// None wrong, but some cannot be judged at this position (status 4).
    CannotBeJudged,
    /// The answer could not be read, or refused (bad JSON, an unknown
    /// point, a position the scene has not …).
    Unreadable,
}

impl Grade {
    /// As the gradebook writes it: `right`, `wrong`, `cannot be judged`,
    /// `unreadable`.
    pub fn as_str(self) -> &'static str {
        match self {
            Grade::Right => "right",
            Grade::Wrong => "wrong",
            Grade::CannotBeJudged => "cannot be judged",
            Grade::Unreadable => "unreadable",
        }
    }

    /// The grade of a check's exit status (0 right, 1 wrong, 4 cannot be
    /// judged).
    fn of_status(status: u8) -> Grade {
        match status {
            0 => Grade::Right,
            1 => Grade::Wrong,
            _ => Grade::CannotBeJudged,
        }
    }
}

/// What one answer of a group came to: a check's report, or why it could
/// not be checked (the error's message).
#[derive(Clone, Copy, Debug)]
pub enum Outcome<'a> {
    /// A plan of velocities or accelerations checked.
    Kinematic(&'a Report),
    /// A force plan checked.
    Force(&'a ForceReport),
    /// Not read, or refused: the message.
    Unreadable(&'a str),
}

/// How many items of an answer are right, wrong, and cannot be judged.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Items right.
    pub right: usize,
    /// Items wrong.
    pub wrong: usize,
    /// Items that cannot be judged at this position.
    pub undecided: usize,
}

/// One answer's row of the gradebook.
#[derive(Clone, Debug, PartialEq)]
pub struct GradeRow {
    /// The answer's file (its name in a folder, else as given).
    pub file: String,
    /// `velocity`, `acceleration` or `force`; `None` when unreadable.
    pub plan: Option<&'static str>,
    /// The position checked, by its number in the study's numbering (a
    /// `count` sweep from 0, given input values from 1: the number the
    /// sheets show); `None` when unreadable.
    pub position: Option<usize>,
    /// The grade.
    pub grade: Grade,
    /// The mistakes named, each with the step where it enters
    /// (`step 7: A normal component ω²·l is forgotten.`); for a wrong
    /// answer no typical mistake explains, `not recognised` and the
    /// explanations it cannot tell apart (`maybe: …`); then each item
    /// wrong that no step's mistake covers, as written and as it should
    /// be (`v_B: written 0.8679 m/s, right 0.6666 m/s ± 0.01000 m/s`);
    /// never empty for a wrong answer, empty when nothing is wrong.
    pub mistakes: Vec<String>,
    /// The items' counts; `None` when unreadable.
    pub counts: Option<Counts>,
    /// Why an unreadable answer could not be checked; for one checked,
    /// the report's note when its points fit another position (or this
    /// one with ω1 reversed); `None` otherwise.
    pub message: Option<String>,
}

/// The items' counts of a list of verdicts.
fn counts(verdicts: &[Verdict]) -> Counts {
    let mut c = Counts::default();
    for v in verdicts {
        match v.judgement {
            Judgement::Right => c.right += 1,
            Judgement::Wrong => c.wrong += 1,
            Judgement::CannotJudge(_) => c.undecided += 1,
        }
    }
    c
}

/// The gradebook's row of answer `file`: every field the gradebook and
/// the summary show, read from the check's report here and nowhere else.
pub fn row_of(file: &str, outcome: Outcome) -> GradeRow {
    let file = file.to_string();
    match outcome {
        Outcome::Kinematic(r) => {
            let mut mistakes = Vec::new();
            if let Some(steps) = &r.steps {
                // Judged step by step: every mistake at its step.
                for f in &steps.mistakes {
                    let k = f.step.0;
                    match &f.mistake {
                        Some(m) => mistakes.push(format!("step {k}: {m}")),
                        None => {
                            mistakes.push(format!("step {k}: not recognised"));
                            mistakes
                                .extend(f.alternatives.iter().map(|a| format!("maybe: {a}")));
                        }
                    }
                }
            } else if let Some(d) = &r.diagnosis {
                match &d.mistake {
                    Some(m) => mistakes.push(match &d.step {
                        Some((k, _)) => format!("step {k}: {m}"),
                        None => m.clone(),
                    }),
                    None => {
                        mistakes.push("not recognised".into());
                        mistakes.extend(d.alternatives.iter().map(|a| format!("maybe: {a}")));
                    }
                }
            }
            mistakes.extend(written_wrong(r));
            GradeRow {
                file,
                plan: Some(match r.plan {
                    PlanKind::Velocity => "velocity",
                    PlanKind::Acceleration => "acceleration",
                }),
                position: Some(r.position),
                grade: Grade::of_status(r.status()),
                mistakes,
                counts: Some(counts(&r.verdicts)),
                message: r.elsewhere_note(),
            }
        }
        Outcome::Force(r) => {
            let grade = Grade::of_status(r.status());
            let mistakes = match (&r.diagnosis, grade) {
                (Some(m), _) => vec![m.clone()],
                (None, Grade::Wrong) => std::iter::once("not recognised".to_string())
                    .chain(items_wrong(&r.verdicts, r.lang, |_| true))
                    .collect(),
                (None, _) => Vec::new(),
            };
            GradeRow {
                file,
                plan: Some("force"),
                position: Some(r.position),
                grade,
                mistakes,
                counts: Some(counts(&r.verdicts)),
                // The items too small to judge at the student's μ_F:
                // reported, the grade given without them.
                message: Some(
                    r.small
                        .iter()
                        .filter_map(|&i| match &r.verdicts[i].judgement {
                            Judgement::CannotJudge(why) => Some(why.as_str()),
                            _ => None,
                        })
                        .collect::<Vec<_>>()
                        .join("; "),
                )
                .filter(|m| !m.is_empty()),
            }
        }
        Outcome::Unreadable(message) => GradeRow {
            file,
            plan: None,
            position: None,
            grade: Grade::Unreadable,
            mistakes: Vec::new(),
            counts: None,
            message: Some(message.to_string()),
        },
    }
}

/// The items that make an answer wrong without a step's mistake named
/// for them, each as written and as it should be: a value (v_B, ω2, ε3)
/// read wrong off points drawn right, a segment or a direction measured
/// wrong, whatever else is judged wrong; a point judged at its step is
/// its step's mistake's (named before them). An answer judged against the
/// true plan alone (no points) has each wrong item named so, beside the
/// mistake its diagnosis names.
pub fn written_wrong(r: &Report) -> Vec<String> {
    // The drawn points a step's mistake puts off their place.
    let covered: Vec<&str> = r
        .steps
        .iter()
        .flat_map(|st| st.mistakes.iter())
        .flat_map(|f| f.points.iter().map(String::as_str))
        .collect();
    // The values read off the velocity plan and the scale, wrong before
    // the plan is drawn: each is its own mistake (step 0).
    let mut before: Vec<&str> = r
        .steps
        .iter()
        .flat_map(|st| st.mistakes.iter())
        .filter(|f| f.step.0 == 0)
        .map(|f| f.step.1.as_str())
        .collect();
    // (An answer judged against the true plan alone names it as its
    // diagnosis.)
    before.extend(
        r.diagnosis
            .iter()
            .filter_map(|d| d.step.as_ref())
            .filter(|(k, _)| *k == 0)
            .map(|(_, s)| s.as_str()),
    );
    let uncovered = |v: &Verdict| {
        let point = crate::grading::resolve(&r.plan_built, &v.key).map(|i| r.plan_built.points[i].name());
        let named_before = v
            .step
            .as_ref()
            .is_some_and(|(k, s)| *k == 0 && before.iter().any(|f| f.starts_with(s.as_str())));
        !point.is_some_and(|p| covered.contains(&p.as_str())) && !named_before
    };
    items_wrong(&r.verdicts, r.lang, uncovered)
}

/// Each wrong item of `verdicts` that `keep` keeps: what it is, what was
/// written and what is right, with the tolerance (`written_right`, in
/// `lang`).
pub(crate) fn items_wrong(verdicts: &[Verdict], lang: Lang, keep: impl Fn(&Verdict) -> bool) -> Vec<String> {
    let w = check::phrases(lang);
    verdicts
        .iter()
        .filter(|v| v.judgement == Judgement::Wrong && keep(v))
        .map(|v| {
            check::fill(
                &w.written_right,
                &[
                    ("what", &v.what),
                    ("given", &quantity(v.given, v.unit, lang)),
                    ("expected", &quantity(v.expected, v.unit, lang)),
                    ("tol", &quantity(v.tolerance, v.unit, lang)),
                ],
            )
        })
        .collect()
}

/// The gradebook's columns, in order.
pub const COLUMNS: [&str; 9] = [
    "file",
    "plan",
    "position",
    "grade",
    "mistakes",
    "right",
    "wrong",
    "undecided",
    "message",
];

/// The gradebook: a header row, then a row per answer (RFC 4180: fields
/// with a comma, a quote or a line break quoted, lines ended by CRLF).
pub fn gradebook_csv(rows: &[GradeRow]) -> String {
    let line = |fields: &[String]| {
        let mut l = fields
            .iter()
            .map(|f| csv_field(f))
            .collect::<Vec<_>>()
            .join(",");
        l.push_str("\r\n");
        l
    };
    let mut out = line(&COLUMNS.map(String::from));
    for r in rows {
        let count = |f: fn(&Counts) -> usize| r.counts.as_ref().map(f);
        out.push_str(&line(&[
            r.file.clone(),
            r.plan.unwrap_or_default().to_string(),
            opt(r.position),
            r.grade.as_str().to_string(),
            r.mistakes.join(" | "),
            opt(count(|c| c.right)),
            opt(count(|c| c.wrong)),
            opt(count(|c| c.undecided)),
            r.message.clone().unwrap_or_default(),
        ]));
    }
    out
}

/// A number, or an empty field.
fn opt(x: Option<usize>) -> String {
    x.map(|x| x.to_string()).unwrap_or_default()
}

/// How many answers of a group have each grade.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Totals {
    /// Answers right.
    pub right: usize,
    /// Answers wrong.
    pub wrong: usize,
    /// Answers none of whose items is wrong but some cannot be judged.
    pub cannot_be_judged: usize,
    /// Answers that could not be read or refused.
    pub unreadable: usize,
}

impl Totals {
    /// The totals of `rows`.
    pub fn of(rows: &[GradeRow]) -> Totals {
        let mut t = Totals::default();
        for r in rows {
            *match r.grade {
                Grade::Right => &mut t.right,
                Grade::Wrong => &mut t.wrong,
                Grade::CannotBeJudged => &mut t.cannot_be_judged,
                Grade::Unreadable => &mut t.unreadable,
            } += 1;
        }
        t
    }

    /// How many answers in all.
    pub fn answers(&self) -> usize {
        self.right + self.wrong + self.cannot_be_judged + self.unreadable
    }

    /// The group's exit status: 2 an answer unreadable, else 1 one wrong,
    /// else 4 one that cannot be judged, else 0.
    pub fn status(&self) -> u8 {
        if self.unreadable > 0 {
            2
        } else if self.wrong > 0 {
            1
        } else if self.cannot_be_judged > 0 {
            4
        } else {
            0
        }
    }

    /// "30 answers: 20 right, 6 wrong, 2 cannot be judged, 2 unreadable".
    pub fn to_text(&self) -> String {
        format!(
            "{} answer{}: {} right, {} wrong, {} cannot be judged, {} unreadable",
            self.answers(),
            if self.answers() == 1 { "" } else { "s" },
            self.right,
            self.wrong,
            self.cannot_be_judged,
            self.unreadable
        )
    }
}

/// A relative link to a file of the group's folder (`overlays/NAME.svg`):
/// every byte but the unreserved ones and `/` percent-encoded, so that a
/// name with `#`, `?`, `%`, spaces or quotes still leads to its file.
fn href(path: &str) -> String {
    let mut out = String::new();
    for b in path.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            out.push(b as char);
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

/// The page's style: a table readable at a glance, each grade coloured.
const STYLE: &str = "
:root { --ink: #1d1d1f; --muted: #6b6b70; --line: #d6d3cb; --desk: #f4f3ef; }
* { box-sizing: border-box; }
body { margin: 0; padding: 20px 28px 32px; background: var(--desk); color: var(--ink);
  font: 14px/1.45 \"DejaVu Sans\", \"Segoe UI\", Arial, sans-serif; }
h1 { font: 600 20px/1.3 \"DejaVu Serif\", Georgia, serif; margin: 0 0 4px; }
p.scene { margin: 0 0 14px; color: var(--muted); }
ul.totals { list-style: none; display: flex; flex-wrap: wrap; gap: 10px; margin: 0 0 18px; padding: 0; }
ul.totals li { padding: 8px 14px; border-radius: 4px; background: #fff; border: 1px solid var(--line);
  border-left-width: 6px; min-width: 150px; }
ul.totals li b { display: block; font-size: 22px; line-height: 1.1; }
table { border-collapse: collapse; width: 100%; background: #fff; border: 1px solid var(--line);
  box-shadow: 0 1px 3px rgba(0,0,0,.06); }
th, td { padding: 6px 10px; border-bottom: 1px solid var(--line); text-align: left; vertical-align: baseline; }
th { background: #27423c; color: #f3f0e6; font-weight: 600; font-size: 13px; }
thead tr + tr th { background: #35554e; font-weight: normal; font-size: 12px; padding-top: 3px; padding-bottom: 3px; }
th.items { text-align: center; border-bottom: 1px solid #5d7a73; padding-bottom: 3px; }
tbody tr:nth-child(even) { background: #faf9f6; }
th.num, td.num { text-align: right; font-variant-numeric: tabular-nums; width: 4em; }
td.zero { color: #b5b3ad; }
tr.wrong td.bad { color: #c62828; font-weight: 600; }
tr.cannot-be-judged td.bad { color: #b26a00; font-weight: 600; }
td.file { font-family: \"DejaVu Sans Mono\", Consolas, monospace; font-size: 13px; white-space: nowrap; }
p.note { margin: -8px 0 12px; color: var(--muted); font-size: 13px; }
td.mistakes, td.message { white-space: pre-line; }
td.mistakes, td.message { min-width: 15em; }
td.message { color: #5a3d8a; font-size: 13px; }
a { color: #1f5fa8; }
span.grade { display: inline-block; padding: 1px 8px; border-radius: 10px; font-size: 12px;
  font-weight: 600; white-space: nowrap; }
.right { --c: #2e7d32; } .wrong { --c: #c62828; } .cannot-be-judged { --c: #b26a00; } .unreadable { --c: #6a4c93; }
span.grade { color: #fff; background: var(--c); }
ul.totals li { border-left-color: var(--c); }
ul.totals li b { color: var(--c); }
";

/// The summary page: the scene's name and the totals on top, then a row
/// per answer (its file linked to its overlay when it has one, its plan,
/// position, grade in colour, mistakes, items' counts and message). One
/// self-contained file: inline style, no script, nothing fetched; every
/// text escaped. `rows` pairs each row with its overlay's path relative
/// to the page (`overlays/NAME.svg`).
pub fn summary_html(scene: &str, rows: &[(GradeRow, Option<String>)]) -> String {
    let just_rows: Vec<GradeRow> = rows.iter().map(|(r, _)| r.clone()).collect();
    let t = Totals::of(&just_rows);
    let mut h = String::new();
    h.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    h.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    let _ = writeln!(h, "<title>Check of {} — {}</title>", t.answers(), xml(scene));
    let _ = writeln!(h, "<style>{STYLE}</style>\n</head>\n<body>");
    let _ = writeln!(
        h,
        "<h1>Check of {} answer{}</h1>\n<p class=\"scene\">Scene: {}</p>",
        t.answers(),
        if t.answers() == 1 { "" } else { "s" },
        xml(scene)
    );
    h.push_str("<ul class=\"totals\">\n");
    for (g, n) in [
        (Grade::Right, t.right),
        (Grade::Wrong, t.wrong),
        (Grade::CannotBeJudged, t.cannot_be_judged),
        (Grade::Unreadable, t.unreadable),
    ] {
        let _ = writeln!(
            h,
            "<li class=\"{}\"><b>{n}</b>{}</li>",
            class(g),
            g.as_str()
        );
    }
    h.push_str("</ul>\n");
    if rows.iter().any(|(_, o)| o.is_some()) {
        h.push_str("<p class=\"note\">A file's name links to its overlay: the student's points over the right plan.</p>\n");
    }
    h.push_str(concat!(
        "<table>\n<thead>\n<tr><th rowspan=\"2\">file</th><th rowspan=\"2\">plan</th>",
        "<th rowspan=\"2\" class=\"num\">position</th><th rowspan=\"2\">grade</th>",
        "<th rowspan=\"2\">mistakes</th><th colspan=\"3\" class=\"items\">items</th>",
        "<th rowspan=\"2\">message</th></tr>\n",
        "<tr><th class=\"num\">right</th><th class=\"num\">wrong</th><th class=\"num\">undecided</th></tr>\n",
        "</thead>\n<tbody>\n"
    ));
    for (r, overlay) in rows {
        let file = match overlay {
            Some(o) => format!(
                "<a href=\"{}\" title=\"the overlay: the student's points on the right plan\">{}</a>",
                href(o),
                xml(&r.file)
            ),
            None => xml(&r.file),
        };
        // An item count, greyed when none, marked when it is what
        // graded the answer down.
        let count = |f: fn(&Counts) -> usize, bad: bool| match r.counts.as_ref().map(f) {
            None => "<td class=\"num\"></td>".to_string(),
            Some(0) => "<td class=\"num zero\">0</td>".to_string(),
            Some(n) if bad => format!("<td class=\"num bad\">{n}</td>"),
            Some(n) => format!("<td class=\"num\">{n}</td>"),
        };
        let _ = writeln!(
            h,
            "<tr class=\"{}\"><td class=\"file\">{file}</td><td>{}</td><td class=\"num\">{}</td><td><span class=\"grade\">{}</span></td><td class=\"mistakes\">{}</td>{}{}{}<td class=\"message\">{}</td></tr>",
            class(r.grade),
            r.plan.unwrap_or_default(),
            opt(r.position),
            r.grade.as_str(),
            xml(&r.mistakes.join("\n")),
            count(|c| c.right, false),
            count(|c| c.wrong, true),
            count(|c| c.undecided, true),
            xml(r.message.as_deref().unwrap_or_default()),
        );
    }
    h.push_str("</tbody>\n</table>\n</body>\n</html>\n");
    h
}

/// A grade's CSS class.
fn class(g: Grade) -> &'static str {
    match g {
        Grade::Right => "right",
        Grade::Wrong => "wrong",
        Grade::CannotBeJudged => "cannot-be-judged",
        Grade::Unreadable => "unreadable",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unreadable(file: &str, message: &str) -> GradeRow {
        row_of(file, Outcome::Unreadable(message))
    }

    #[test]
    fn fields_are_quoted_as_rfc_4180_says() {
        let csv = gradebook_csv(&[unreadable("a, \"b\".json", "line one\nline two")]);
        assert_eq!(
            csv,
            "file,plan,position,grade,mistakes,right,wrong,undecided,message\r\n\
             \"a, \"\"b\"\".json\",,,unreadable,,,,,\"line one\nline two\"\r\n"
        );
    }

    #[test]
    fn every_text_of_the_page_is_escaped_and_links_encoded() {
        let rows = vec![(
            unreadable("<a&b\".json", "x < y & z"),
            Some("overlays/a&b #1.svg".to_string()),
        )];
        let h = summary_html("<scene>", &rows);
        assert!(h.contains("&lt;a&amp;b&quot;.json"), "{h}");
        assert!(h.contains("x &lt; y &amp; z"));
        assert!(h.contains("href=\"overlays/a%26b%20%231.svg\""));
        assert!(!h.contains("<scene>") && !h.contains("<script"));
    }

    #[test]
    fn the_status_is_the_worst_grade() {
        let t = |right, wrong, cannot_be_judged, unreadable| {
            Totals {
                right,
                wrong,
                cannot_be_judged,
                unreadable,
            }
            .status()
        };
        assert_eq!(t(3, 0, 0, 0), 0);
        assert_eq!(t(3, 0, 1, 0), 4);
        assert_eq!(t(3, 1, 1, 0), 1);
        assert_eq!(t(0, 1, 1, 1), 2);
    }
}
