//! The diff as one self-contained HTML page: the picture inline, then the regions, the
//! times and the findings that changed as tables. No script, nothing loaded from
//! elsewhere (the run report's style sheet is inlined).

use std::fmt::Write as _;

use super::{DiffFinding, DiffReport};
use crate::layout::colour;
use crate::text::{duration, esc, num};

/// The page, with `svg` (the diff picture) inline.
pub(super) fn html(d: &DiffReport, svg: &str) -> String {
    let title = format!("latsim diff — {} → {}", d.old, d.new);
    let (verdict, vc) = if d.differs() {
        ("the parts differ".to_string(), colour::BAD)
    } else {
        (
            format!("the parts agree within {} mm", num(d.tolerance_mm, 4)),
            colour::OK,
        )
    };
    let mut out = String::with_capacity(svg.len() + 16 * 1024);
    crate::html::page_head(&mut out, &title, &verdict, vc);
    out.push_str("<section id=\"ls-picture\"><h2>Both sections</h2>\n<div class=\"picture\">\n");
    out.push_str(svg);
    out.push_str("</div></section>\n");
    regions(&mut out, d);
    times(&mut out, d);
    findings(&mut out, "Findings that appeared", &d.appeared);
    findings(&mut out, "Findings that went away", &d.gone);
    out.push_str("</body>\n</html>\n");
    out
}

fn lines(l: &[u32]) -> String {
    if l.is_empty() {
        return "—".into();
    }
    l.iter().map(u32::to_string).collect::<Vec<_>>().join(", ")
}

/// One row per region: what, area, depth, where, and the lines of each program.
fn regions(out: &mut String, d: &DiffReport) {
    let _ = writeln!(
        out,
        "<section id=\"ls-regions\"><h2>Regions <span class=\"count\">({} lost, {} gained)</span></h2>",
        d.lost.len(),
        d.gained.len()
    );
    if !d.differs() {
        out.push_str(
            "<p class=\"none\">none: the parts agree within the tolerance</p></section>\n",
        );
        return;
    }
    out.push_str("<table class=\"list\"><thead><tr><th></th><th>area mm²</th><th>depth mm</th><th>Z</th><th>X</th><th>new lines</th><th>old lines</th></tr></thead><tbody>\n");
    let rows = d
        .lost
        .iter()
        .enumerate()
        .map(|(i, r)| (format!("L{} lost", i + 1), r))
        .chain(
            d.gained
                .iter()
                .enumerate()
                .map(|(i, r)| (format!("G{} gained", i + 1), r)),
        );
    for (label, r) in rows {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{} … {}</td><td class=\"n\">{} … {}</td><td>{}</td><td>{}</td></tr>",
            esc(&label),
            num(r.area_mm2, 4),
            num(r.depth_mm, 4),
            num(r.lo[0], 3),
            num(r.hi[0], 3),
            num(2.0 * r.lo[1], 3),
            num(2.0 * r.hi[1], 3),
            lines(&r.new_lines),
            lines(&r.old_lines)
        );
    }
    out.push_str("</tbody></table></section>\n");
}

/// Cycle time and the time of each tool, old and new.
fn times(out: &mut String, d: &DiffReport) {
    let s = |v: Option<f64>| v.map_or("—".to_string(), |v| num(v, 1));
    let change = |a: Option<f64>, b: Option<f64>| {
        a.zip(b)
            .map_or("—".to_string(), |(a, b)| format!("{:+.1}", b - a))
    };
    let [old, new] = d.cycle_time_s;
    out.push_str("<section id=\"ls-times\"><h2>Times</h2><table class=\"list\"><thead><tr><th></th><th>old s</th><th>new s</th><th>change s</th></tr></thead><tbody>\n");
    let _ = writeln!(
        out,
        "<tr><td>cycle time ({} → {})</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
        esc(&duration(old)),
        esc(&duration(new)),
        s(Some(old)),
        s(Some(new)),
        change(Some(old), Some(new))
    );
    for t in &d.tools {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            esc(&t.tool),
            s(t.old_s),
            s(t.new_s),
            change(t.old_s, t.new_s)
        );
    }
    out.push_str("</tbody></table></section>\n");
}

fn findings(out: &mut String, title: &str, list: &[DiffFinding]) {
    let _ = writeln!(
        out,
        "<section><h2>{} <span class=\"count\">({})</span></h2>",
        esc(title),
        list.len()
    );
    if list.is_empty() {
        out.push_str("<p class=\"none\">none</p></section>\n");
        return;
    }
    out.push_str("<table class=\"list\"><thead><tr><th>kind</th><th>line</th><th>code</th><th>Z</th><th>X</th><th>message</th></tr></thead><tbody>\n");
    for f in list {
        let (z, x) = f.at.map_or(("—".into(), "—".into()), |p| {
            (num(p[0], 3), num(2.0 * p[1], 3))
        });
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"n\">{}</td><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td></tr>",
            esc(&f.kind),
            f.line,
            esc(&f.code),
            z,
            x,
            esc(&f.message)
        );
    }
    out.push_str("</tbody></table></section>\n");
}
