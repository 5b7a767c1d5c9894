//! The catalogues of phrases, one file per language
//! (`src/words/en.json`, `uk.json`, `ru.json`, compiled in), and the one
//! way their named blanks are filled ([`fill`]).

use crate::lang::Lang;
use std::sync::OnceLock;

pub use super::overlay_phrases::OverlayPhrases;

/// A phrase with its blanks filled: each `{name}` by the value named so
/// in `args` (one pass: a value is never filled again).
pub fn fill(phrase: &str, args: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(phrase.len() + 16 * args.len());
    let mut rest = phrase;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let close = open + rest[open..].find('}').expect("a closed blank");
        let name = &rest[open + 1..close];
        let value = args
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("no value for the blank {{{name}}}"));
        out.push_str(value.1);
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    out
}

/// Every phrase of one language, read from its catalogue file
/// (`src/words/en.json`, `uk.json`, `ru.json`, compiled in): a new
/// language is one more file and its line in `crate::lang`'s list.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Catalogue {
    /// The language's code, as the file's name.
    // The file must state it (deny_unknown_fields); only a unit test reads it.
    #[allow(dead_code)]
    pub language: String,
    /// The construction's steps.
    pub construction: ConstructionPhrases,
    /// The force plans' steps.
    pub force_plans: ForcePlanPhrases,
    /// The sheets' words.
    pub sheets: SheetPhrases,
    /// The handout's words.
    pub handout: HandoutPhrases,
    /// The title block's words.
    pub title_block: TitleBlockPhrases,
    /// Zhukovsky's lever's words.
    pub lever: LeverPhrases,
    /// The result tables' words.
    pub tables: TablePhrases,
    /// The lines of `solve`'s terminal table around its tables.
    pub results: ResultPhrases,
    /// `mechplan centres`' words.
    pub centres: CentrePhrases,
    /// `mechplan diagram`'s words.
    pub diagrams: DiagramPhrases,
    /// How the language writes numbers and units.
    pub units: UnitPhrases,
    /// The check of a student's plan: its report and the mistakes it names.
    pub check: CheckPhrases,
    /// The words `check` reads in a drawing's texts, and the balancing
    /// moment's subscript.
    pub reading: ReadingWords,
    /// The course sheet's structure, given data, stroke and comparison.
    pub course_sheet: CourseSheetPhrases,
}

/// Sheet 1's words beside its drawings: the structure and given data,
/// the output's stroke, the plans against the analytic solution.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CourseSheetPhrases {
    /// The caption of the structure and given data.
    pub given_caption: String,
    /// Words before Chebyshev's W and before the structure formula.
    pub mobility: String,
    pub formula: String,
    /// The output's stroke: a slider's (`{id}`), a rocker's swing.
    pub stroke_slide: String,
    pub stroke_rocker: String,
    /// The working and idle strokes' crank angles, and K.
    pub working: String,
    pub idle: String,
    pub k: String,
    /// The subscripts of φ of the working and idle strokes (φ_w, φ_i).
    pub w: String,
    pub i: String,
    /// The given data table's heads.
    pub given_head: [String; 2],
    /// The comparison's caption (`{k}`: the position), its note on how
    /// the plan's values are read (`{d}`: the reading, mm) and its heads.
    pub compare_caption: String,
    pub compare_note: String,
    pub compare_head: [String; 5],
}

/// The words of a language that `check` reads in a student's drawing (any
/// language's, whatever the scene's), and the subscript it names the
/// balancing moment (force) by.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReadingWords {
    /// M_b, F_b: "b" (uk "зр", ru "ур": "зрівноважувальний",
    /// "уравновешивающий").
    pub balancing_subscript: String,
    /// The word "plan" (a title's word starting so: "plans", "плани").
    pub plan_words: Vec<String>,
    /// Stems of "velocity" and of "acceleration" in a plan's title
    /// ("velocit", "швидкост").
    pub velocity_stems: Vec<String>,
    pub acceleration_stems: Vec<String>,
}

/// The reading words of every language, in the order of [`Lang::ALL`].
pub fn every_reading() -> impl Iterator<Item = &'static ReadingWords> {
    Lang::ALL.into_iter().map(|l| &catalogue(l).reading)
}

/// The catalogue of `lang`, read once.
pub fn catalogue(lang: Lang) -> &'static Catalogue {
    static ALL: OnceLock<[Catalogue; Lang::ALL.len()]> = OnceLock::new();
    let all = ALL.get_or_init(|| {
        Lang::ALL.map(|l| {
            serde_json::from_str(l.catalogue_text())
                .expect("the words' catalogues are valid (tested)")
        })
    });
    &all[lang.index()]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each catalogue file reads whole (every phrase there, none unknown)
    /// and says its own language.
    #[test]
    fn every_language_has_its_catalogue() {
        for lang in Lang::ALL {
            assert_eq!(catalogue(lang).language, lang.code());
        }
    }
}

/// The phrases of one language. Blanks in braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConstructionPhrases {
    /// Units of the velocity and the acceleration plan: values, rates.
    pub(super) unit: [String; 2],
    pub(super) rate_unit: [String; 2],
    /// Senses of a rate: positive, negative, zero.
    pub(super) sense: [String; 3],
    /// Directions: `{p}`, `{q}`; `{link}`; `{v}`, `{w}`; `{seg}`, `{w}`.
    pub(super) toward: String,
    pub(super) guide: String,
    pub(super) turned: String,
    pub(super) perp_sense: String,
    /// Steps.
    pub(super) pole: String,
    pub(super) lay_off: String,
    pub(super) intersect: String,
    pub(super) similar: String,
    pub(super) divide: String,
    pub(super) coincide: String,
    /// Why a point coincides: at the pole; `{link}` translates.
    pub(super) fixed: String,
    pub(super) translates: String,
    pub(super) measure: String,
    /// How a relative segment turns its link.
    pub(super) turns: String,
    pub(super) same: String,
    pub(super) equations: String,
}

/// The phrases of one language.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForcePlanPhrases {
    /// The steps' heading and the position's word.
    pub title: String,
    /// "position".
    pub position: String,
    /// "link", "links" (one, several).
    pub(super) links: [String; 2],
    /// Units: N, mm, N·m, N/mm.
    pub newton: String,
    pub mm: String,
    pub newton_metre: String,
    /// N·mm (a moment on the lever).
    pub newton_millimetre: String,
    pub(super) per_mm: String,
    /// `{formula}`, `{links}`.
    pub(super) group: String,
    /// `{ids}`.
    pub(super) input_link: String,
    /// `{at}`, `{what}`, `{f}`, `{value}`, `{n}`.
    pub(super) moment: String,
    /// `{what}`, `{f}`, `{value}`, `{n}`.
    pub(super) projection: String,
    /// `{from}`, `{f}`, `{val}`, `{n}`, `{len}`, `{mm}`, `{dir}`, `{to}`.
    pub(super) lay_off: String,
    /// `{through}`, `{f}`, `{dir}`.
    pub(super) line: String,
    /// `{out}`, `{deg}`.
    pub(super) intersect: String,
    /// `{a}`, `{b}`, `{l}`, `{mm}`, `{f}`, `{mu}`, `{val}`, `{bound}`, `{n}`, `{dir}`.
    pub(super) measure: String,
    /// `{what}`, `{value}`, `{nm}`, `{f}`, `{p}`: the couple of a guide
    /// with its force placed, and alone.
    pub(super) couple_at: String,
    pub(super) couple_alone: String,
    /// `{id}`, `{kind}`, `{b}`, `{value}`, `{unit}`, `{sense}`.
    pub(super) balancing: String,
    /// The balancing moment and force, as `{kind}` says them.
    pub(super) kind: [String; 2],
    /// A moment's senses: counter-clockwise, clockwise.
    pub(super) sense: [String; 2],
    /// The subscript of M_b, F_b.
    pub(super) balancing_sub: String,
    /// "worst intersection angle".
    pub worst: String,
}

/// The sheets' words (headings, captions, tables' heads).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SheetPhrases {
    /// The sheets' headings: the plan of the mechanism, the plans, the positions, "position", the course sheet, the results table.
    pub mechanism: String,
    pub velocities: String,
    pub accelerations: String,
    pub positions: String,
    pub position: String,
    pub course: String,
    pub table: String,
    /// The course sheet's heading of the plans of velocities.
    pub velocity_plans: String,
    /// The head of the course sheet's results table.
    pub quantity_unit: String,
    /// The heads of a plan's table of measured segments.
    pub plan_table: [String; 4],
    /// The steps' word for a value's drafting bound.
    pub drafting_bound: String,
    /// What diagrams are of: a point along its path (`{p}`), a slider or a link (`{id}`); the heading's words, and the chords.
    pub diagram_point: String,
    pub diagram_slider: String,
    pub diagram_link: String,
    pub diagrams_of: String,
    pub chords: String,
    /// The course's force analysis sheet: its title, its results table's heads, the lever's table and the reactions' captions.
    pub force_analysis: String,
    pub reactions_table: [String; 5],
    pub forces_on_lever: String,
    pub reactions_title: String,
    /// The force sheets' title, and a panel's: a group, the input link.
    pub force_sheets: String,
    /// The force sheets' note: the arrows on the free bodies are not to
    /// scale, only the polygons are (at their μ_F, in the notation).
    pub not_to_scale: String,
    /// A panel of a class II group, as the course names it: `{class}`,
    /// `{kind}` (the textbooks' вид, 1…5), `{links}`, `{letters}` (RRP).
    pub group: String,
    /// A panel of a class III group: `{links}`.
    pub group_triad: String,
    pub input_link: String,
}

/// The handout page's words around its drawings.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HandoutPhrases {
    /// The step buttons, the keys' hint, the headings of a position's section.
    pub prev: String,
    pub next: String,
    pub start: String,
    pub all: String,
    pub step: String,
    pub of: String,
    pub keys: String,
    pub position: String,
    pub after: String,
    pub no_plans: String,
    pub results: String,
    pub steps_title: String,
    pub structure: String,
    /// A dynamics scene's force analysis: its heading, the free body's
    /// and the polygon's words, the note that a free body's arrows are
    /// not to a scale of force.
    pub forces: String,
    pub free_body: String,
    pub polygon: String,
    pub not_to_scale: String,
}

/// The title block's words (ГОСТ 2.104; ДСТУ ГОСТ 2.104 in Ukrainian),
/// by where they stand.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TitleBlockPhrases {
    /// The columns' headings: change, sheet, document, signature, date.
    pub heads: [String; 5],
    /// The rows' roles: drawn, checked, technical control, standards
    /// control, approved.
    pub roles: [String; 5],
    /// Over the letter, the mass and the scale.
    pub cells: [String; 3],
    /// The letter where the scene's `sheet.letter` gives none: "У"
    /// (учбовий, учебный: a student's document, as university
    /// departments letter course projects) in uk and ru, a dash in en.
    pub letter: String,
    /// "Sheets" (their count) and "Format".
    pub sheets: String,
    /// "Format".
    pub format: String,
}

/// Zhukovsky's lever's words: its title, a force's arm, the balancing
/// force's subscript, the turned plan, its table's heads, an input, along
/// the guide.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LeverPhrases {
    /// "Zhukovsky's lever".
    pub title: String,
    /// A force's arm on the lever.
    pub arm: String,
    /// The subscript of the balancing force and moment (F_b, M_b).
    pub balancing: String,
    /// The plan of velocities turned by 90°.
    pub turned: String,
    /// The table's heads: force, F, h, F·h.
    pub heads: [String; 4],
    /// "input".
    pub input: String,
    /// "along the guide".
    pub along: String,
    /// The sign convention of the balancing force, one for the table and
    /// the caption: its magnitude, drawn as it acts; h signed.
    pub convention: String,
}

/// The result tables' words.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TablePhrases {
    /// The tables' captions: points, links, measured on the plans.
    pub points: String,
    /// "Links".
    pub links: String,
    /// "Measured on the plans".
    pub measured: String,
    /// The columns: point, link, segment, value ± bound; the worst angle.
    pub point: String,
    /// "link".
    pub link: String,
    /// "segment".
    pub segment: String,
    /// "value ± drafting bound".
    pub value: String,
    /// "worst intersection angle".
    pub worst: String,
    /// A link's angle.
    pub angle: String,
    /// The terminal's senses of a rate: positive (counter-clockwise),
    /// negative, zero.
    pub senses: [String; 3],
}

/// The lines of `solve`'s terminal table besides its tables. Blanks in
/// braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResultPhrases {
    /// The structure line's word.
    pub structure: String,
    /// A slide: `{slider}`, `{guide}`, `{point}`.
    pub slide: String,
    /// The Coriolis acceleration's symbol.
    pub coriolis: String,
    /// The cross-check of the routes: `{diff}`, `{worst}`, `{contour}`,
    /// `{constraint}`, `{us}`.
    pub routes: String,
    /// The cross-check by residuals: `{diff}`, `{worst}`, `{contour}`,
    /// `{check}`, `{us}`.
    pub residuals: String,
    /// µs.
    pub microseconds: String,
    /// What differed most: a point's (`{p}`) place, v, a; a link's (`{id}`)
    /// angle, ω, ε.
    pub of_point: [String; 3],
    pub of_link: [String; 3],
    /// A plan against a route: `{what}`, `{route}`; the routes (contour,
    /// constraint) as this phrase names them.
    pub plan: String,
    pub route: [String; 2],
    /// Nothing compared.
    pub none: String,
}

/// `mechplan centres`' words. Blanks in braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CentrePhrases {
    /// The columns' heads: centre, place, found by.
    pub heads: [String; 3],
    /// A centre's place: `{x}`, `{y}`, `{unit}`; at infinity: `{x}`, `{y}`.
    pub at: String,
    pub infinity: String,
    /// How a centre was found: at a revolute pair (`{p}`), a prismatic
    /// pair, by Kennedy's lines through links `{a}` and `{b}`.
    pub revolute: String,
    pub prismatic: String,
    pub kennedy: String,
    /// A centre not found, and why: `{a}`, `{b}`, `{i}`, `{j}`; `{i}`, `{j}`.
    pub undetermined: String,
    pub coincide: String,
    pub few_lines: String,
}

/// `mechplan diagram`'s words. Blanks in braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiagramPhrases {
    /// `{what}`, `{of}`, `{n}`, `{start}`.
    pub title: String,
    /// What the diagrams are of: a point (`{p}`), a link (`{id}`).
    pub point: String,
    pub link: String,
    /// The arc length of a point's path, a slide, an angle.
    pub of: [String; 3],
    /// Where they start: over a slider's stroke (`{x}`, `{from}`, `{to}`,
    /// `{unit}`), at a crank's angle (`{angle}`).
    pub stroke: String,
    pub turn: String,
    /// The scales' line, and the columns' words.
    pub scales: String,
    pub node: String,
    pub exact: String,
    pub central: String,
    pub interval: String,
    /// The intervals' columns: `{y}` (s′).
    pub midpoint: String,
    pub ordinate: String,
    /// The largest errors: `{v}`, `{a}`, `{s}` (s′, s″, s) and each
    /// error with where it is.
    pub errors: String,
}

/// How a language writes numbers and units: its decimal mark, and the
/// letters of the SI units it writes its own way, replaced in order
/// ("rad" before "m", "mm" before "m").
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UnitPhrases {
    /// "." or ",".
    pub decimal: String,
    /// (SI letters, the language's), in the order they are replaced.
    pub letters: Vec<[String; 2]>,
}

/// The check's report. Blanks in braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CheckPhrases {
    /// `{plan}`, `{position}`, `{mu}`, `{delta}`.
    pub title: String,
    /// The velocity plan's and the acceleration plan's word.
    pub plan: [String; 2],
    /// `{angle}`.
    pub dead_centre: String,
    pub grade_right: String,
    /// `{step}`, `{mistake}`.
    pub grade_wrong_one: String,
    /// `{count}`.
    pub grade_wrong_many: String,
    /// No step wrong, `{count}` items read off the student's points wrong.
    pub grade_wrong_items: String,
    pub grade_cannot_judge: String,
    pub steps_heading: String,
    pub steps_columns: [String; 5],
    /// Right, wrong, cannot be judged.
    pub verdicts: [String; 3],
    /// `{n}`.
    pub mistake_of_step: String,
    pub mistakes_heading: String,
    /// `{n}`, `{step}`, `{mistake}`.
    pub mistake_line: String,
    /// `{sentence}`.
    pub mistake_step: String,
    /// `{points}`.
    pub mistake_points: String,
    pub not_recognised: String,
    pub alternatives: String,
    pub items_heading: String,
    pub items_columns: [String; 6],
    /// `{expected}`, `{given}`.
    pub on_plan: String,
    /// `{step}`, `{sentence}`.
    pub drawn_at: String,
    /// `{why}`.
    pub cannot_judge_why: String,
    /// `{right}`, `{count}`, `{wrong}`, `{unjudged}`.
    pub total: String,
    /// `{right}`, `{wrong}`, `{unjudged}`.
    pub second_opinion: String,
    pub second_agrees: String,
    /// The note of an answer whose points fit another position:
    /// `{position}`, `{stated}`; with ω1 reversed at the stated one:
    /// `{stated}`; both: `{stated}`, `{position}`.
    pub elsewhere_position: String,
    pub elsewhere_reversed: String,
    pub elsewhere_both: String,
    /// `{why}`.
    pub second_disagrees: String,
    /// `{step}`.
    pub disagreement_steps_wrong: String,
    /// `{what}`.
    pub disagreement_steps_right: String,
    /// `{mistake}`.
    pub likely_mistake: String,
    /// `{step}`, `{sentence}`.
    pub enters_at: String,
    pub not_recognised_items: String,
    pub alternatives_items: String,
    /// `{name}`.
    pub point_from_own: String,
    /// `{tol}`, `{size}`.
    pub too_wide_step: String,
    /// The same where a table gives points by their lengths only: `{tol}`,
    /// `{size}`, `{segs}` (the segments whose directions are open).
    pub too_wide_table: String,
    pub too_wide: String,
    /// `{tol}`, `{moved}`, `{mistake}`, `{k}`, `{mu}`.
    pub ambiguous_step: String,
    /// `{tol}`, `{moved}`, `{mistake}`.
    pub ambiguous: String,
    /// A point known by its length from the pole only: `{tol}`,
    /// `{moved}`, `{mistake}`, `{seg}`.
    pub ambiguous_circle: String,
    /// `{mistake}`.
    pub on_velocity_plan: String,
    /// A value stated as read off the velocity plan: its item's name
    /// (`{name}`), the step that reads it (`{sentence}`: the velocity
    /// plan's measurement), a value given by the data (`{name}`,
    /// `{value}`), the student's own number beside the right one
    /// (`{value}`).
    pub stated_item: String,
    pub stated_step: String,
    pub stated_given: String,
    /// A stated sliding velocity's segment measured on the velocity plan.
    pub stated_slide: String,
    pub yours: String,
    /// A stated value wrong: `{name}`, `{given}`, `{expected}`, `{tol}`,
    /// `{unit}`; why: its sense (`{name}`), μ_v's units, another link's
    /// length (`{name}`, `{own}`, `{other}`), one factor for every ω
    /// (`{factor}`), read off wrong (`{name}`).
    pub stated_wrong: String,
    pub stated_sense: String,
    pub stated_units: String,
    pub stated_length: String,
    pub stated_common: String,
    pub stated_plain: String,
    /// The drawing is built with the right value, not the one stated.
    pub stated_unused: String,
    /// A stated value that a typical misreading gives as well: `{tol}`,
    /// `{mistake}`, `{value}`, `{mm}` (the tolerance on the velocity
    /// plan), `{k}` (how many times larger to draw it).
    pub ambiguous_stated: String,
    /// The grade and a mistake's line for a mistake made before the plan
    /// is drawn (a value read off the velocity plan, the scale): `{mistake}`;
    /// `{n}`, `{mistake}`.
    pub grade_wrong_before: String,
    pub mistake_line_before: String,
    /// A plan drawn at another scale than stated: `{drawn}`, `{stated}`,
    /// `{factor}` (the drawn segments over the right ones); the scale's
    /// step (`{mu}`, `{unit}`).
    pub scale_drawn: String,
    pub scale_step: String,
    /// What the drawn scale is beside the stated one: μ inverted, μ in
    /// the wrong units; the scale as an item of the report.
    pub scale_drawn_inverted: String,
    pub scale_drawn_units: String,
    pub scale_item: String,
    /// Each typical mistake: made at one decision, made everywhere.
    pub mistakes: MistakePhrases,
    /// Some of them at one decision, in the scene's own letters.
    pub lettered: LetteredPhrases,
    /// `{what}`, `{factor}`.
    pub slip_of: String,
    /// `{first}`, `{second}`.
    pub pair: String,
    pub branch: String,
    pub scale_units: String,
    /// `{mu}`.
    pub scale_inverted: String,
    pub a_vector: String,
    /// The items' names: a segment (`{seg}`), its direction (`{seg}`), a
    /// point off its place (`{name}`).
    pub item_segment: String,
    pub item_direction: String,
    pub item_point: String,
    /// The overlay's title: `{plan}`, `{position}`, `{right}`, `{count}`.
    pub overlay_title: String,
    /// The overlay's marks and its legend.
    pub overlay: OverlayPhrases,
    /// An item written wrong, as the gradebook names it: `{what}`,
    /// `{given}`, `{expected}`, `{tol}` (each with its unit).
    pub written_right: String,
    /// A force plan's report: `{links}`, `{position}`, `{mu}`, `{delta}`.
    pub force_title: String,
    /// `{what}`, `{given}`, `{unit}`, `{expected}`, `{tol}`, `{verdict}`.
    pub force_item: String,
    /// Right, wrong, cannot be judged (`{why}`).
    pub force_verdicts: [String; 3],
    /// `{mistake}`.
    pub force_diagnosis: String,
    pub force_not_recognised: String,
    /// Why an item cannot be judged: `{mu}`; `{what}`.
    pub force_not_finite: String,
    pub force_mistake_too: String,
    /// The force plans' typical mistakes (`force_scale`: `{k}`, a factor).
    pub force_not_reversed: String,
    pub force_weights_left_out: String,
    pub force_tau_sign: String,
    pub force_tau_along: String,
    pub force_action_for_reaction: String,
    pub force_neighbour_sign: String,
    pub force_scale: String,
    pub force_mb_sign: String,
    pub force_mb_arm: String,
    /// A diagnosis with the item it shows first in: `{mistake}`, `{item}`.
    pub force_first_at: String,
    /// Mistakes fitting alike: `{mistakes}`, joined by `force_or`.
    pub force_either: String,
    pub force_or: String,
    /// An item too small to judge at the student's μ_F: `{what}`, `{size}`.
    pub force_small: String,
    /// A value off the plan (M_b) too small to judge: `{what}`, `{tol}`.
    pub force_small_value: String,
    /// What an item is: a segment, a direction, a value.
    pub force_kinds: [String; 3],
}

/// Each typical mistake in one sentence: made at one decision, made at
/// every one.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MistakePhrases {
    pub coriolis_reversed: [String; 2],
    pub coriolis_forgotten: [String; 2],
    pub coriolis_factor_one: [String; 2],
    pub normal_from_centre: [String; 2],
    pub normal_forgotten: [String; 2],
    pub mirrored_figure: [String; 2],
    pub wrong_perpendicular: [String; 2],
    pub tangential_parallel: [String; 2],
    pub wrong_link: [String; 2],
    pub epsilon1_forgotten: [String; 2],
    pub epsilon1_added: [String; 2],
    pub omega_wrong_link: [String; 2],
    pub omega_wrong_sense: [String; 2],
    pub slip: [String; 2],
    pub neighbour_link: [String; 2],
    pub slide_across: [String; 2],
    pub point_at_neighbour: [String; 2],
}

/// Typical mistakes made at one decision, in the scene's own letters
/// (the right construction's step where the mistake enters): a
/// perpendicular to the wrong link (`{a}`, `{dir_a}`, `{b}`, `{dir_b}`:
/// the two lines as they must be), the guide's point taken for the
/// slider's (`{out}`, `{at}`), a slide's line across its guide (`{out}`,
/// `{at}`, `{dir}`), a point put at a neighbour's (`{out}`, `{fig}`).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LetteredPhrases {
    pub wrong_perpendicular: String,
    pub wrong_link: String,
    pub slide_across: String,
    pub point_at_neighbour: String,
}
