//! The scales every position's sheets share, found before any of them is
//! drawn ([`shared_scales`]): each reads every position of the sweep (a
//! long sweep's solved again for each reading, [`Sweep`]), so several
//! scales are tried in one reading.

use super::canvas::Canvas;
use super::layout::{field_size, fill, lower_scale, mechanism_canvas, mechanism_extent};
use super::output::DrawOptions;
use super::positions;
use super::sweep::{self, Sweep};
use crate::error::{Error, Result};
use crate::kinematics::construction::scale::Series;
use crate::kinematics::solve::Analysis;
use crate::studies::sheet_data::SheetData;
use kurbo::Rect;

/// The scales every position's sheets share, found before any of them is
/// drawn: the positions sheet's μ_l and drawing, and the plan of the
/// mechanism's μ_l with the box all positions' drawings are centred on.
pub(super) struct Shared {
    pub(super) positions: Option<(f64, Canvas)>,
    pub(super) mechanism: Option<(f64, Rect)>,
}

/// The scales of the sheets every position shares ([`Shared`]).
pub(super) fn shared_scales(
    an: &Analysis,
    solved: &dyn Sweep,
    data: &SheetData,
    opt: &DrawOptions,
    how: Scale,
) -> Result<Shared> {
    let fixed_l = match how {
        Scale::Scene => an.mech.scene.want.scales.mu_l,
        #[cfg(feature = "internals")]
        Scale::Fill => None,
    };
    let field = field_size(opt, 0.0);
    let configs = solved.configs();
    let extent = mechanism_extent(an, configs.iter().copied());
    let lower = lower_scale(extent.width(), extent.height(), field);
    let mut out = Shared {
        positions: None,
        mechanism: None,
    };
    if solved.is_empty() {
        return Ok(out);
    }
    if asked(an, solved, "positions") {
        let t = positions::given(data, solved.len())?;
        let bold = sweep::at(solved, t.bold)?;
        let draw = |mu: f64| {
            let mut c = Canvas::default();
            positions::draw(an, (bold, &configs), t, &mut c, mu);
            Some(c)
        };
        out.positions = Some(match fixed_l {
            Some(mu) => (mu, draw(mu).unwrap_or_default()),
            None => fill(Series::Drawing, lower, field, draw, |c| c.bounds()).ok_or_else(too_large)?,
        });
    }
    if asked(an, solved, "mechanism") {
        // A sweep solved again as it is read is solved once for each
        // reading: the scales tried read it a few at a time, the first
        // error ends the search.
        let (mut failed, mut read) = (None, Vec::new());
        let bounds = |mu: f64| match read_bounds(an, solved, opt, mu, &mut read) {
            Ok(r) => Some(r),
            Err(e) => {
                failed.get_or_insert(e);
                None
            }
        };
        out.mechanism = Some(match fixed_l {
            Some(mu) => (mu, mechanism_bounds(an, solved, opt, &[mu])?[0]),
            None => {
                let found = fill(Series::Drawing, lower, field, bounds, |r| *r);
                if let Some(e) = failed {
                    return Err(e);
                }
                found.ok_or_else(too_large)?
            }
        });
    }
    Ok(out)
}

/// How many scales one reading of the sweep tries ([`read_bounds`]).
const AT_ONCE: usize = 2;

/// The box of every position's plan of the mechanism at `mu` (as
/// [`mechanism_bounds`] gives it), from the boxes `read` so far, else
/// read with those at the next scales of the series.
fn read_bounds(
    an: &Analysis,
    sweep: &dyn Sweep,
    opt: &DrawOptions,
    mu: f64,
    read: &mut Vec<(f64, Rect)>,
) -> Result<Rect> {
    if let Some(&(_, r)) = read.iter().find(|(m, _)| *m == mu) {
        return Ok(r);
    }
    let mut mus = vec![mu];
    while mus.len() < AT_ONCE {
        let next = Series::Drawing.above(mus[mus.len() - 1]);
        mus.push(next);
    }
    let boxes = mechanism_bounds(an, sweep, opt, &mus)?;
    *read = mus.into_iter().zip(boxes).collect();
    Ok(read[0].1)
}

/// The box every position's plan of the mechanism fits in at each of
/// `mus`, each drawn and dropped in turn, in one reading of the sweep.
pub(super) fn mechanism_bounds(
    an: &Analysis,
    sweep: &dyn Sweep,
    opt: &DrawOptions,
    mus: &[f64],
) -> Result<Vec<Rect>> {
    let mut u: Vec<Option<Rect>> = vec![None; mus.len()];
    sweep.each_lean(&mut |_, s| {
        for (u, &mu) in u.iter_mut().zip(mus) {
            let b = mechanism_canvas(an, s, opt, mu).bounds();
            *u = Some(u.map_or(b, |a| a.union(b)));
        }
        Ok(())
    })?;
    Ok(u.into_iter().map(|r| r.unwrap_or(Rect::ZERO)).collect())
}

/// Whether the scene asks for drawing `d` (`want.drawings`; by default the
/// plan of the mechanism and the plans wanted, plus the positions sheet
/// when there are several positions).
pub(super) fn asked(an: &Analysis, solved: &dyn Sweep, d: &str) -> bool {
    let want = &an.mech.scene.want.drawings;
    if want.is_empty() {
        let first = solved.get(0);
        let has_vel = first.is_some_and(|s| s.plans.is_some());
        let has_acc = first
            .and_then(|s| s.plans.as_ref())
            .is_some_and(|p| p.acceleration.is_some());
        match d {
            "mechanism" => true,
            "velocity" => has_vel,
            "acceleration" => has_acc,
            "positions" => solved.len() > 1,
            "lever" => first.is_some_and(|s| s.dynamics.is_some()),
            "forces" => first
                .and_then(|s| s.dynamics.as_ref())
                .is_some_and(|d| d.force_plans.is_some()),
            _ => false,
        }
    } else {
        want.iter().any(|w| w == d)
    }
}

/// How the mechanism's scale is chosen.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Scale {
    /// The scene's μ_l (`want.scales.mu_l`) when it gives one.
    Scene,
    /// Chosen to fill, whatever the scene says ([`sheets`](super::compose::sheets)).
    #[cfg(feature = "internals")]
    Fill,
}

pub(super) fn too_large() -> Error {
    Error::Internal("no standard scale up to a million times the first fits the sheet".into())
}
