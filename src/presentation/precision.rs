//! The work-precision report (`crate::verification::precision`) rendered: a markdown table and a log-log plot of error
//! against run time.

use crate::format::sci;
use crate::verification::precision::{Report, Row, Stat};

/// The report as a markdown table.
pub fn to_markdown(r: &Report) -> String {
    let mut s = String::new();
    s.push_str("| method | setting | time/position | place max | v max | v median | a max | a median | ω max | ε max | ε median |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    let cell = |st: &Option<Stat>, med: bool| match st {
        None => "—".to_string(),
        Some(st) => sci(if med { st.median } else { st.max }),
    };
    for row in &r.rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            row.method,
            row.setting,
            time_str(row.time),
            cell(&row.err[0], false),
            cell(&row.err[1], false),
            cell(&row.err[1], true),
            cell(&row.err[2], false),
            cell(&row.err[2], true),
            cell(&row.err[3], false),
            cell(&row.err[4], false),
            cell(&row.err[4], true),
        ));
    }
    s
}

/// 3.2 µs, 41 ns, 1.5 ms.
pub fn time_str(t: f64) -> String {
    let (v, unit) = if t >= 1e-3 {
        (t * 1e3, "ms")
    } else if t >= 1e-6 {
        (t * 1e6, "µs")
    } else {
        (t * 1e9, "ns")
    };
    if v >= 100.0 {
        format!("{v:.0} {unit}")
    } else if v >= 10.0 {
        format!("{v:.1} {unit}")
    } else {
        format!("{v:.2} {unit}")
    }
}

/// Marker shape and colour of a method.
fn style(method: &str) -> (&'static str, &'static str, &'static str) {
    match method {
        "kernel" => (
            "square",
            "#1f77b4",
            "construction kernel: plans × μ, no pencil error",
        ),
        "contour" => ("diamond", "#2ca02c", "route (a): closed vector contours"),
        "newton" => ("circle", "#d62728", "route (b): Newton, tol 1e-4 … 1e-14"),
        "chords" => (
            "triangle",
            "#9467bd",
            "diagrams: chords to midpoints, N = 12 … 3600",
        ),
        "central" => (
            "tri-down",
            "#8c564b",
            "diagrams: central differences, N = 12 … 3600",
        ),
        _ => (
            "cross",
            "#ff7f0e",
            "hand drafting emulated: pencil δ on the plans' μ",
        ),
    }
}

fn marker(s: &mut String, shape: &str, colour: &str, x: f64, y: f64) {
    use crate::presentation::drawing::canvas::fmt;
    let r = 1.4;
    let el = match shape {
        "square" => format!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"",
            fmt(x - r),
            fmt(y - r),
            fmt(2.0 * r),
            fmt(2.0 * r)
        ),
        "circle" => format!(
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
            fmt(x),
            fmt(y),
            fmt(r)
        ),
        "diamond" => format!(
            "<polygon points=\"{},{} {},{} {},{} {},{}\"",
            fmt(x),
            fmt(y - 1.3 * r),
            fmt(x + 1.3 * r),
            fmt(y),
            fmt(x),
            fmt(y + 1.3 * r),
            fmt(x - 1.3 * r),
            fmt(y)
        ),
        "triangle" | "tri-down" => {
            // Apex up, or down (exactly the same numbers, mirrored).
            let k = if shape == "triangle" { 1.0 } else { -1.0 };
            format!(
                "<polygon points=\"{},{} {},{} {},{}\"",
                fmt(x),
                fmt(y - k * 1.3 * r),
                fmt(x + 1.2 * r),
                fmt(y + k * 0.8 * r),
                fmt(x - 1.2 * r),
                fmt(y + k * 0.8 * r)
            )
        }
        _ => {
            s.push_str(&format!(
                "<path d=\"M{} {}L{} {}M{} {}L{} {}\" stroke=\"{colour}\" stroke-width=\"0.6\" fill=\"none\"/>\n",
                fmt(x - r),
                fmt(y - r),
                fmt(x + r),
                fmt(y + r),
                fmt(x - r),
                fmt(y + r),
                fmt(x + r),
                fmt(y - r)
            ));
            return;
        }
    };
    s.push_str(&format!(
        "{el} fill=\"{colour}\" fill-opacity=\"0.75\" stroke=\"{colour}\" stroke-width=\"0.3\"/>\n"
    ));
}

/// The plot's page (mm) and its frame: left, right, top, bottom.
const PAGE: (f64, f64) = (215.0, 140.0);
const FRAME: (f64, f64, f64, f64) = (22.0, 128.0, 14.0, 122.0);
/// Errors below this are drawn at it.
const FLOOR: f64 = 1e-17;

/// The log-log plot (mm): worst relative error of the rates against the
/// run time per position, one marker per method and setting.
pub fn to_svg(r: &Report, title: &str) -> String {
    use crate::presentation::drawing::canvas::{fmt, xml};
    let (w, h) = PAGE;
    let (x0, x1, _, y1) = FRAME;
    let plot = Plot::new(r);
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n"
    );
    s.push_str(&format!(
        "<text x=\"{}\" y=\"7\" font-size=\"3.6\">{}</text>\n",
        fmt(x0),
        xml(title)
    ));
    plot.axes(&mut s);
    plot.points(&mut s);
    plot.labels(&mut s);
    legend(&mut s, r);
    s.push_str(&format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"2.2\" fill=\"#444\">{} positions; errors below 1e-17 drawn at 1e-17</text>\n",
        fmt(x1 + 3.0),
        fmt(y1),
        r.positions
    ));
    s.push_str("</svg>\n");
    s
}

/// The rows as points of the plot, (time, error, row), and the decades
/// the axes span: time `tx`, error `ey` (exponents, first and last).
struct Plot<'a> {
    pts: Vec<(f64, f64, &'a Row)>,
    tx: (f64, f64),
    ey: (f64, f64),
}

impl<'a> Plot<'a> {
    fn new(r: &'a Report) -> Plot<'a> {
        let pts: Vec<(f64, f64, &Row)> = r
            .rows
            .iter()
            .map(|row| (row.time.max(1e-12), row.worst_rates().max(FLOOR), row))
            .collect();
        let dec = |v: f64| v.log10();
        let (mut tx0, mut tx1) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut ey0, mut ey1) = (f64::INFINITY, f64::NEG_INFINITY);
        for &(t, e, _) in &pts {
            tx0 = tx0.min(dec(t).floor());
            tx1 = tx1.max(dec(t).ceil());
            ey0 = ey0.min(dec(e).floor());
            ey1 = ey1.max(dec(e).ceil());
        }
        if tx1 <= tx0 {
            tx1 = tx0 + 1.0;
        }
        if ey1 <= ey0 {
            ey1 = ey0 + 1.0;
        }
        Plot {
            pts,
            tx: (tx0, tx1),
            ey: (ey0, ey1),
        }
    }

    /// A time's abscissa, mm.
    fn px(&self, t: f64) -> f64 {
        let (x0, x1, _, _) = FRAME;
        let (tx0, tx1) = self.tx;
        x0 + (t.log10() - tx0) / (tx1 - tx0) * (x1 - x0)
    }

    /// An error's ordinate, mm.
    fn py(&self, e: f64) -> f64 {
        let (_, _, y0, y1) = FRAME;
        let (ey0, ey1) = self.ey;
        y1 - (e.log10() - ey0) / (ey1 - ey0) * (y1 - y0)
    }

    /// The grid with its decades, the frame and the axes' titles.
    fn axes(&self, s: &mut String) {
        use crate::presentation::drawing::canvas::fmt;
        let (x0, x1, y0, y1) = FRAME;
        let ((tx0, tx1), (ey0, ey1)) = (self.tx, self.ey);
        // Grid and decades.
        let mut k = tx0;
        while k <= tx1 + 1e-9 {
            let x = x0 + (k - tx0) / (tx1 - tx0) * (x1 - x0);
            s.push_str(&format!(
                "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#ccc\" stroke-width=\"0.2\"/>\n<text x=\"{0}\" y=\"{3}\" font-size=\"2.8\" text-anchor=\"middle\">10<tspan dy=\"-1.2\" font-size=\"2\">{4}</tspan></text>\n",
                fmt(x),
                fmt(y0),
                fmt(y1),
                fmt(y1 + 4.5),
                k as i32
            ));
            k += 1.0;
        }
        let step = if ey1 - ey0 > 10.0 { 2.0 } else { 1.0 };
        let mut k = ey0;
        while k <= ey1 + 1e-9 {
            let y = y1 - (k - ey0) / (ey1 - ey0) * (y1 - y0);
            s.push_str(&format!(
                "<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\" stroke=\"#ccc\" stroke-width=\"0.2\"/>\n",
                fmt(y),
                fmt(x0),
                fmt(x1)
            ));
            if ((k - ey0) / step).fract().abs() < 1e-9 {
                s.push_str(&format!(
                    "<text x=\"{}\" y=\"{}\" font-size=\"2.8\" text-anchor=\"end\">10<tspan dy=\"-1.2\" font-size=\"2\">{}</tspan></text>\n",
                    fmt(x0 - 1.5),
                    fmt(y + 1.0),
                    k as i32
                ));
            }
            k += 1.0;
        }
        s.push_str(&format!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\" stroke-width=\"0.35\"/>\n",
            fmt(x0),
            fmt(y0),
            fmt(x1 - x0),
            fmt(y1 - y0)
        ));
        s.push_str(&format!(
            "<text x=\"{}\" y=\"{}\" font-size=\"3\" text-anchor=\"middle\">run time per position, s</text>\n",
            fmt(0.5 * (x0 + x1)),
            fmt(y1 + 10.0)
        ));
        s.push_str(&format!(
            "<text transform=\"translate(6 {}) rotate(-90)\" font-size=\"3\" text-anchor=\"middle\">largest relative error of v, a, ω, ε</text>\n",
            fmt(0.5 * (y0 + y1))
        ));
    }

    /// Lines joining the settings of one method, then the markers.
    fn points(&self, s: &mut String) {
        use crate::presentation::drawing::canvas::fmt;
        for method in ["newton", "chords", "central"] {
            let line: Vec<String> = self
                .pts
                .iter()
                .filter(|p| p.2.method == method)
                .map(|&(t, e, _)| format!("{},{}", fmt(self.px(t)), fmt(self.py(e))))
                .collect();
            if line.len() > 1 {
                let (_, colour, _) = style(method);
                s.push_str(&format!(
                    "<polyline points=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"0.25\" stroke-dasharray=\"1 0.8\"/>\n",
                    line.join(" ")
                ));
            }
        }
        for &(t, e, row) in &self.pts {
            let (shape, colour, _) = style(&row.method);
            marker(s, shape, colour, self.px(t), self.py(e));
        }
    }

    /// Labels: the settings of a method whose errors agree within a
    /// factor of 3 share one label, at the first of them.
    fn labels(&self, s: &mut String) {
        use crate::presentation::drawing::canvas::{fmt, xml};
        for method in ["newton", "chords", "central"] {
            let run: Vec<&(f64, f64, &Row)> =
                self.pts.iter().filter(|p| p.2.method == method).collect();
            let mut i = 0;
            while i < run.len() {
                let mut j = i;
                while j + 1 < run.len() && (run[j + 1].1 / run[i].1).log10().abs() < 0.48 {
                    j += 1;
                }
                let short = |r: &Row| r.setting.replace("tol ", "").replace("N = ", "");
                let mut note = short(run[i].2);
                if j > i {
                    note = format!("{note} … {}", short(run[j].2));
                }
                if method != "newton" {
                    note = format!("N = {note}");
                }
                // Diagrams: only the coarsest and the finest, to stay readable.
                if method != "newton" && i != 0 && j + 1 != run.len() {
                    i = j + 1;
                    continue;
                }
                let (x, y) = (self.px(run[i].0), self.py(run[i].1));
                let (_, colour, _) = style(method);
                let left = method == "central";
                s.push_str(&format!(
                    "<text x=\"{}\" y=\"{}\" font-size=\"2.1\" fill=\"{colour}\" text-anchor=\"{}\">{}</text>\n",
                    fmt(if left { x - 2.4 } else { x + 2.4 }),
                    fmt(y + 0.8),
                    if left { "end" } else { "start" },
                    xml(&note)
                ));
                i = j + 1;
            }
        }
    }
}

/// The legend on the right: each method once, its marker and its words.
fn legend(s: &mut String, r: &Report) {
    use crate::presentation::drawing::canvas::{fmt, xml};
    let (_, x1, y0, _) = FRAME;
    let mut seen: Vec<&str> = Vec::new();
    let mut ly = y0 + 4.0;
    for row in &r.rows {
        if seen.contains(&row.method.as_str()) {
            continue;
        }
        seen.push(&row.method);
        let (shape, colour, label) = style(&row.method);
        marker(s, shape, colour, x1 + 5.0, ly - 0.9);
        let words: Vec<&str> = label.split(": ").collect();
        s.push_str(&format!(
            "<text x=\"{}\" y=\"{}\" font-size=\"2.6\">{}</text>\n",
            fmt(x1 + 8.5),
            fmt(ly),
            xml(words[0])
        ));
        if words.len() > 1 {
            ly += 3.4;
            s.push_str(&format!(
                "<text x=\"{}\" y=\"{}\" font-size=\"2.3\" fill=\"#444\">{}</text>\n",
                fmt(x1 + 8.5),
                fmt(ly),
                xml(words[1])
            ));
        }
        ly += 6.5;
    }
}
