//! The `sheet` object: what the main title block of a drawing says
//! (ГОСТ 2.104 form 1), and `want.plans_at`, the positions whose plans go
//! on the course sheet.

use super::reader::Reader;
use super::{Numbering, PlansAt, SheetInfo};
use serde_json::Value;

impl Reader {
    pub(super) fn sheet_info(&mut self, v: Option<&Value>) -> SheetInfo {
        let mut s = SheetInfo::default();
        let Some(v) = v else { return s };
        let Some(o) = self.object(v, "/sheet") else {
            return s;
        };
        let keys = [
            "designation",
            "title",
            "author",
            "checker",
            "organisation",
            "scale",
            "letter",
        ];
        self.only_keys(o, "/sheet", &keys);
        for k in keys {
            let Some(x) = o.get(k) else { continue };
            let at = format!("/sheet/{k}");
            let (t, by) = if k == "title" {
                match self.localised(x, &at) {
                    Some(x) => x,
                    None => continue,
                }
            } else {
                match self.string(x, &at) {
                    Some(t) => (t.to_owned(), Vec::new()),
                    None => continue,
                }
            };
            // A cell of the title block holds one line.
            let long = |t: &str| t.chars().count() > 120 || t.contains('\n');
            if long(&t) || by.iter().any(|(_, t)| long(t)) {
                self.err(at, "expected one line of at most 120 characters");
                continue;
            }
            if k == "title" {
                s.titles = by;
            }
            // The letter column has three cells of one letter each.
            if k == "letter" && t.chars().count() > 3 {
                self.err(at, "expected at most 3 letters (the title block's letter cells), e.g. \"У\"");
                continue;
            }
            let t = Some(t);
            match k {
                "designation" => s.designation = t,
                "title" => s.title = t,
                "author" => s.author = t,
                "checker" => s.checker = t,
                "organisation" => s.organisation = t,
                "letter" => s.letter = t,
                _ => s.scale = t,
            }
        }
        s
    }

    /// `want.plans_at`: a list of positions whose acceleration plans go
    /// on the course sheet, or `{ "velocity": [...] | "all",
    /// "acceleration": [...], "positions_from": 0 | 1 }`; the numbers in
    /// the scene's `numbering` (a `count` sweep from 0, given values
    /// from 1) unless `positions_from` says otherwise, checked against
    /// the number of positions, kept as the k-th positions (from 1).
    pub(super) fn plans_at(&mut self, v: &Value, positions: usize, numbering: Numbering) -> PlansAt {
        let mut numbering = numbering;
        if let Some(f) = v.get("positions_from") {
            match f.as_u64().and_then(Numbering::from_first) {
                Some(n) => numbering = n,
                None => self.err(
                    "/want/plans_at/positions_from",
                    format!("expected 0 or 1, the number of the first position in plans_at, found {f}"),
                ),
            }
        }
        let range = numbering.range_text(positions);
        let list = |r: &mut Self, v: &Value, at: &str| -> Vec<usize> {
            let Some(a) = v.as_array() else {
                r.err(at, format!("expected a list of position numbers ({range})"));
                return Vec::new();
            };
            let mut out = Vec::new();
            for (k, x) in a.iter().enumerate() {
                let index = x
                    .as_u64()
                    .and_then(|n| usize::try_from(n).ok())
                    .and_then(|n| numbering.index(n, positions));
                match index {
                    Some(i) => {
                        if !out.contains(&(i + 1)) {
                            out.push(i + 1)
                        }
                    }
                    None => r.err(
                        format!("{at}/{k}"),
                        format!("expected a position number {range}"),
                    ),
                }
            }
            out
        };
        let mut p = PlansAt::default();
        if v.is_array() {
            p.acceleration = Some(list(self, v, "/want/plans_at"));
            return p;
        }
        let Some(o) = self.object(v, "/want/plans_at") else {
            return p;
        };
        self.only_keys(
            o,
            "/want/plans_at",
            &["velocity", "acceleration", "positions_from"],
        );
        if let Some(x) = o.get("velocity")
            && x.as_str() != Some("all")
        {
            p.velocity = Some(list(self, x, "/want/plans_at/velocity"));
        }
        if let Some(x) = o.get("acceleration") {
            p.acceleration = Some(list(self, x, "/want/plans_at/acceleration"));
        }
        p
    }
}
