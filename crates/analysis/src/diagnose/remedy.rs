//! Remedies, each checked by re-running the program with it: a tool of the table (or an
//! ISO tool) with the geometry the cause asks for, or a program change (a rapid split in
//! two). Only a change that removes the finding and adds none is given.

use super::insert::Facts;
use crate::deviation::Finding;
use crate::findings::{CauseKind, Crash, Remedy};
use crate::Findings;
use expander::Segment;
use geom::flat::P;
use stock::ToolTable;

/// A change to try on the program or its tools.
#[derive(Debug, Clone, PartialEq)]
pub enum Change {
    /// Tool `t` given by this `[[tool]]` entry's fields (TOML, without `t`) instead of the
    /// table's.
    Tool {
        /// The T number.
        t: u32,
        /// The entry's fields, e.g. `kind = "turning"\ninsert = "VBMT 160404"\n…`.
        entry: String,
    },
    /// Line `line`'s rapid (`G00`/`G0`) made a feed (`G01`, at the feed in force).
    Feed {
        /// 1-based line of the main program.
        line: u32,
    },
    /// Line `line`'s G41 made G42, or its G42 made G41.
    Swap {
        /// 1-based line of the main program.
        line: u32,
    },
    /// These blocks inserted before line `line` of the main program.
    Insert {
        /// 1-based line of the main program.
        line: u32,
        /// The blocks, one a line.
        text: String,
    },
}

/// What a re-run with a change concluded.
#[derive(Debug, Clone, PartialEq)]
pub struct Rerunning {
    /// Its findings (not diagnosed).
    pub findings: Findings,
    /// The part it leaves (the simulation's final section).
    pub part: Vec<stock::Shape>,
    /// The controller alarms of its toolpath.
    pub alarms: usize,
}

/// Re-runs the program with a change: the caller knows the program's text and how it was
/// read; `None` when the changed program cannot be read or run.
pub trait Rerun {
    /// The run of the program with `change`, on the same blank, machine and tolerance.
    fn rerun(&self, change: &Change) -> Option<Rerunning>;
}

/// How near a finding of a re-run must be to one of the original to be the same, mm.
const SAME_PLACE: f64 = 0.5;
/// How much of the part a change may take or keep besides what it was meant to, mm²: the
/// noise of two runs' sections (a re-cut edge's chords), well under any groove…
const SAME_PART: f64 = 0.01;
/// …and this share of the cured finding's area (what the changed moves do at their ends).
const SIDE_EFFECT: f64 = 0.02;

/// The remedies tried for one program, within a budget of re-runs.
pub(crate) struct Tries<'a> {
    pub(crate) original: &'a Findings,
    /// The part the program as written leaves.
    pub(crate) part: &'a [stock::Shape],
    /// The main program's text.
    pub(crate) source: &'a str,
    pub(crate) alarms: usize,
    pub(crate) segments: &'a [Segment],
    pub(crate) tools: &'a ToolTable,
    /// The Z of the blank's face, where a retract is clear of the part (plus a margin).
    pub(crate) face: f64,
    /// The blank's shapes.
    pub(crate) blank: &'a [stock::Shape],
    /// The deviation's tolerance, mm.
    pub(crate) tol: f64,
    /// How many times each block runs, counted when a crash first asks.
    pub(crate) runs: std::cell::OnceCell<BlockRuns>,
    pub(crate) rerun: &'a dyn Rerun,
    pub(crate) budget: &'a mut usize,
}

/// The finding a change must cure.
#[derive(Clone, Copy)]
enum Cured<'a> {
    /// The crash at this place, which took this much stock (mm²).
    Crash(P, f64),
    /// This gouge, all of its region.
    Gouge(&'a Finding),
}

fn near(p: P, q: P) -> bool {
    (p[0] - q[0]).hypot(p[1] - q[1]) <= SAME_PLACE
}

fn gouges(f: &Findings) -> &[Finding] {
    f.deviation.as_ref().map_or(&[], |d| d.gouges.as_slice())
}

/// Whether two regions share more than a sliver.
fn overlap(a: &stock::Shape, b: &stock::Shape) -> bool {
    let both = stock::boolean(
        std::slice::from_ref(a),
        std::slice::from_ref(b),
        stock::BoolOp::Intersection,
    );
    stock::area(&both) > 1e-6
}

impl Tries<'_> {
    /// Whether the run with `change` has cured `what` (no crash near its place any more, or
    /// no gouge left in its region) and has no crash, gouge or alarm the original did not
    /// have.
    fn fixes(&mut self, change: &Change, what: Cured) -> bool {
        if *self.budget == 0 {
            return false;
        }
        *self.budget -= 1;
        let Some(run) = self.rerun.rerun(change) else {
            return false;
        };
        let (oc, rc) = (&self.original.crashes, &run.findings.crashes);
        let (og, rg) = (gouges(self.original), gouges(&run.findings));
        // gone: nothing of its kind is left where it was. A gouge must be gone from its whole
        // region, not only from where it was deepest: a tool that leaves the same flank 3.35
        // mm deep instead of 4.45 moved the deepest point 1.5 mm and cured nothing.
        let gone = match what {
            Cured::Crash(at, _) => !rc.iter().any(|c| near(c.at, at)),
            Cured::Gouge(g) => !rg
                .iter()
                .any(|r| near(r.at, g.at) || overlap(&r.shape, &g.shape)),
        };
        // nothing new: every crash of the re-run is near one of the original, every gouge
        // lies in one of the original's regions (what is left of them is not new)
        let nothing_new = rc.iter().all(|c| oc.iter().any(|o| near(c.at, o.at)))
            && rg
                .iter()
                .all(|g| og.iter().any(|o| overlap(&g.shape, &o.shape)));
        gone && nothing_new && run.alarms <= self.alarms && self.same_part(&run.part, &what)
    }

    /// Whether the re-run's part differs from the program's only where the change was
    /// meant to act: it may keep stock where the program gouged (the gouges' regions) or
    /// where the cured crash's rapid cut (its area), and take stock where the program left
    /// some (the leftovers' regions); anything else over [`SAME_PART`]. A change that cures
    /// a finding by moving the program's own cuts is no fix (field run 10, B3: a retract
    /// inserted into a subprogram called twice moved its second neck from Z-22 to Z-8; the
    /// re-run had no finding, as a program without a shape to compare has none).
    fn same_part(&self, part: &[stock::Shape], what: &Cured) -> bool {
        use stock::BoolOp::Difference;
        let leftovers = self
            .original
            .deviation
            .as_ref()
            .map_or(&[][..], |d| d.leftovers.as_slice());
        // a region stops the tolerance short of the intended surface: the band between is
        // the change's too (a 27 mm gouge cured by G42 keeps 0.59 mm² besides its 43.2)
        let outside = |diff: Vec<stock::Shape>, fs: &[Finding]| {
            let regions: Vec<stock::Shape> = fs.iter().map(|f| f.shape.clone()).collect();
            let band: f64 = fs.iter().map(|f| perimeter(&f.shape)).sum::<f64>() * 2.0 * self.tol;
            (stock::area(&stock::boolean(&diff, &regions, Difference)) - band).max(0.0)
        };
        let taken = outside(stock::boolean(self.part, part, Difference), leftovers);
        let kept = outside(
            stock::boolean(part, self.part, Difference),
            gouges(self.original),
        );
        let crash = match what {
            Cured::Crash(_, area) => *area,
            Cured::Gouge(_) => 0.0,
        };
        // what the change does at the ends of the moves it changes (a nose the other side of
        // a contour ends 0.8 mm further along the next shoulder: 0.62 mm² of a G90's face,
        // beside a 43.2 mm² gouge cured)
        let cured = match what {
            Cured::Crash(_, area) => *area,
            Cured::Gouge(g) => g.area,
        };
        let slack = SAME_PART + SIDE_EFFECT * cured;
        taken <= slack && kept <= crash + slack
    }

    /// A checked remedy for a gouge: for the trailing edge, a tool with the clearance the
    /// flank needs (of the table first, else an ISO one).
    pub(crate) fn for_gouge(&mut self, g: &Finding) -> Option<Remedy> {
        let cause = g.cause.as_ref()?;
        if cause.kind == CauseKind::Compensation {
            return self.swap_side(g);
        }
        if cause.kind != CauseKind::TrailingEdge {
            return None;
        }
        let flank = cause.numbers.iter().find(|(k, _)| *k == "flank_deg")?.1;
        let seg = &self.segments[g.made_by?];
        let f = Facts::of(self.tools.tool_or_default(seg.tool))?;
        for (name, entry, clearance) in candidates(self.tools, seg.tool, &f, flank) {
            let change = Change::Tool { t: seg.tool, entry };
            if self.fixes(&change, Cured::Gouge(g)) {
                let ghost = self.ghost(&change, seg);
                return Some(Remedy {
                    text: format!(
                        "use {name} for T{:02}: {clearance:.0}° trailing clearance for this {flank:.0}° flank",
                        seg.tool
                    ),
                    tool: Some(name),
                    line: None,
                    edit: None,
                    verified: true,
                    ghost,
                });
            }
        }
        None
    }

    /// A checked remedy for a gouge along a contour compensated to the wrong side of its
    /// tool's stated tip: the other code where the compensation starts.
    fn swap_side(&mut self, g: &Finding) -> Option<Remedy> {
        let i = g.made_by?;
        let (owner, comp) =
            super::cause::wrong_side_owner(g, &self.original.intents, self.segments, i)?;
        let line = self.segments.get(owner.finish)?.span.line;
        let (code, other) = comp.codes();
        if !self.fixes(&Change::Swap { line }, Cured::Gouge(g)) {
            return None;
        }
        Some(Remedy {
            text: format!("write {other} instead of {code} at line {line}"),
            tool: None,
            line: Some(line),
            edit: Some(other.into()),
            verified: true,
            ghost: vec![],
        })
    }

    /// The cutting outline of the tool a `Change::Tool` puts on `seg`, as mounted.
    fn ghost(&self, change: &Change, seg: &Segment) -> Vec<Vec<P>> {
        let Change::Tool { t, entry } = change else {
            return vec![];
        };
        let Ok(table) = self.tools.replaced(*t, entry) else {
            return vec![];
        };
        let rear = stock::rear_tools(self.segments).contains(&seg.tool);
        stock::Mounted::new(&table, seg.tool, seg.hint, rear)
            .edge
            .parts
            .clone()
    }

    /// A checked remedy for a rapid crash: the rapid split in two (X first, Z first, or
    /// out past the face first), else fed (`G01`) into the cut.
    pub(crate) fn for_crash(&mut self, c: &Crash) -> Option<Remedy> {
        let cause = c.cause.as_ref()?;
        if cause.kind != CauseKind::Rapid {
            return None;
        }
        let seg = &self.segments[c.segment];
        let line = seg.span.line;
        let runs = self.runs.get_or_init(|| block_runs(self.segments));
        if !runs_once_as_rapids(self.segments, runs, c.segment) {
            return None;
        }
        let (x, z) = (2.0 * seg.to.r, seg.to.z);
        let clear = self.face + CLEAR;
        // a rapid that ends inside the bar went there to cut (a plunge, a pass written G00):
        // split or sent out past the face first, it cuts in the air and the part loses what
        // it was for (a groove plunged at Z2: review 1128h, #1); only fed is it cured. One
        // that ends outside the bar only passed through it (a boring bar rapiding out
        // through the wall): a retract along Z first cures that.
        let along_an_axis = seg.from.z == seg.to.z || seg.from.r == seg.to.r;
        let end = [seg.to.z, seg.to.r.abs()];
        let bar = crate::assumed::Region::new(self.blank);
        let ends_in_bar = bar.contains(end) && bar.depth_at(end, CLEAR) > IN_BAR;
        let splits = if ends_in_bar {
            vec![]
        } else {
            vec![
                (
                    format!("G00 X{}", num(x)),
                    format!("rapid to X{} first, then Z{}", num(x), num(z)),
                ),
                (
                    format!("G00 Z{}", num(z)),
                    format!("rapid to Z{} first, then X{}", num(z), num(x)),
                ),
                (
                    format!("G00 Z{}", num(clear)),
                    format!("retract to Z{} (clear of the face) first", num(clear)),
                ),
            ]
        };
        for (block, text) in splits {
            let change = Change::Insert {
                line,
                text: block.clone(),
            };
            if self.fixes(&change, Cured::Crash(c.at, c.area)) {
                return Some(Remedy {
                    text: format!("{text}: insert `{block}` before line {line}"),
                    tool: None,
                    line: Some(line),
                    edit: Some(block),
                    verified: true,
                    ghost: vec![],
                });
            }
        }
        // fed, the rapid cuts what it cut: a cure for a G00 written for a G01 — a plunge or
        // a pass along one axis that meets the bar as it came — none where it meets a
        // surface an earlier cut made (a fillet the feed would take off as the rapid did:
        // field run 10, B1), nor for a positioning move across the bar (fed, a diagonal
        // through it)
        if along_an_axis
            && bar.depth_at(c.at, 2.0 * ON_OUTLINE) <= ON_OUTLINE
            && self.fixes(&Change::Feed { line }, Cured::Crash(c.at, c.area))
        {
            let (edit, with) = match super::edit::feed_word_for(self.source, line) {
                Some(f) => (
                    format!("G01 {f}"),
                    format!(" ({f}, the program's next feed: none is in force there)"),
                ),
                None => ("G01".to_string(), String::new()),
            };
            return Some(Remedy {
                text: format!("feed into the cut: G01 instead of G00 at line {line}{with}"),
                tool: None,
                line: Some(line),
                edit: Some(edit),
                verified: true,
                ghost: vec![],
            });
        }
        None
    }
}

/// Whether the block that made move `i` is a plain rapid run once: its moves (one, or a
/// G28's two) are all rapids and follow each other. An edit of the block cures that rapid
/// alone: not a cycle that made it among its passes (a block inserted before a G71 moves its
/// start point, field run 10, B4), nor a block a loop or a subprogram runs again (B3: a
/// retract before a subprogram's `W-10.` ran on every call).
/// (`runs`: [`block_runs`] of the segments.)
fn runs_once_as_rapids(segments: &[Segment], runs: &BlockRuns, i: usize) -> bool {
    let span = segments[i].span;
    let mine = |s: &Segment| s.span.offset == span.offset && s.span.line == span.line;
    let first = segments[..i]
        .iter()
        .rposition(|s| !mine(s))
        .map_or(0, |k| k + 1);
    let end = segments[i..]
        .iter()
        .position(|s| !mine(s))
        .map_or(segments.len(), |k| i + k);
    runs.get(&(span.offset, span.line)) == Some(&1)
        && segments[first..end]
            .iter()
            .all(|s| s.motion == expander::Motion::Rapid)
}

/// How many times each block (its span's offset and line) runs: its runs of consecutive
/// moves. Counted once for a program, not once a crash (a CAM program's thousand crashes
/// each scanned its 10⁵ moves).
pub(crate) type BlockRuns = std::collections::HashMap<(u32, u32), u32>;

/// [`BlockRuns`] of `segments`.
pub(crate) fn block_runs(segments: &[Segment]) -> BlockRuns {
    let mut runs = BlockRuns::new();
    let mut last = None;
    for s in segments {
        let key = (s.span.offset, s.span.line);
        if last != Some(key) {
            *runs.entry(key).or_insert(0) += 1;
            last = Some(key);
        }
    }
    runs
}

/// The length of a shape's outline and holes, mm.
fn perimeter(s: &stock::Shape) -> f64 {
    std::iter::once(&s.outer)
        .chain(&s.holes)
        .map(|ring| {
            let n = ring.len();
            (0..n)
                .map(|k| geom::flat::dist(ring[k], ring[(k + 1) % n]))
                .sum::<f64>()
        })
        .sum()
}

/// How near the blank's outline a crash's first contact is on it, mm.
const ON_OUTLINE: f64 = 0.01;

/// How far inside the blank a rapid's end lies when it went there to cut, mm.
const IN_BAR: f64 = 0.01;

/// How far past the blank's face a retract is clear of it, mm.
const CLEAR: f64 = 2.0;

/// A length as a program writes it: at most three decimals, a point always (`X42.`).
fn num(v: f64) -> String {
    format!("{v:.3}").trim_end_matches('0').to_string()
}

/// The ISO 1832 metric nose code nearest the radius `r` (mm): a V insert offered for the
/// trailing edge keeps the nose the program was written for (an r0.4 for a sharp tool
/// traded the flank's gouge for the uncompensated nose's 0.4 mm).
fn nose_code(r: f64) -> String {
    const TENTHS: [u32; 11] = [0, 1, 2, 4, 8, 12, 16, 20, 24, 28, 32];
    let nearest = TENTHS
        .iter()
        .min_by(|a, b| {
            let d = |c: &&u32| (f64::from(**c) / 10.0 - r).abs();
            d(a).total_cmp(&d(b))
        })
        .copied()
        .unwrap_or(4);
    format!("{nearest:02}")
}

/// Tools with more trailing clearance than `flank` (plus 1°) for the same tip: the table's
/// turning tools first, then ISO ones (a 35° V on 93°: 52°; on 72.5°: 72.5°; the program's nose), as
/// (name, entry fields, clearance).
fn candidates(tools: &ToolTable, t: u32, f: &Facts, flank: f64) -> Vec<(String, String, f64)> {
    let mut out = Vec::new();
    for n in tools.numbers() {
        if n == t {
            continue;
        }
        let Some(tool) = tools.get(n) else { continue };
        let Some(other) = Facts::of(tool) else {
            continue;
        };
        if other.tip == f.tip && other.trailing_clearance() > flank + 1.0 {
            out.push((
                format!(
                    "T{n:02} ({})",
                    tools.describe(n).split_once(' ').map_or("", |x| x.1)
                ),
                tool.toml_fields(),
                other.trailing_clearance(),
            ));
        }
    }
    let hand = match f.tip {
        3 => Some('R'),
        4 => Some('L'),
        _ => None,
    };
    if let Some(h) = hand {
        let insert = format!("VBMT 1604{}", nose_code(f.nose_radius));
        for (holder, clearance) in [
            (format!("SVJB{h} 2525M16"), 52.0),
            ("SVVBN 2525M16".to_string(), 72.5),
        ] {
            if clearance > flank + 1.0 {
                out.push((
                    format!("{insert} in {holder}"),
                    format!(
                        "kind = \"turning\"\ninsert = \"{insert}\"\nholder = \"{holder}\"\ntip = {}\n",
                        f.tip
                    ),
                    clearance,
                ));
            }
        }
    }
    out.truncate(3);
    out
}
