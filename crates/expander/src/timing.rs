//! Cycle time: rapids at the machine's rates, feeds per minute or per revolution
//! (G96 follows the diameter, clamped), plus dwells.

use crate::{Feed, Machine, Segment, Spindle, Toolpath};

/// Time of one segment of `tp` in seconds. Per-revolution feeds with the spindle at 0
/// rev/min cannot be timed and count 0 (the interpreter has already warned about them).
pub fn segment_time(tp: &Toolpath, seg: &Segment, machine: &Machine) -> f64 {
    time_at_feed(seg, tp.feeds.get(seg.feed), machine)
}

/// Time of `seg` at `feed`, s.
fn time_at_feed(seg: &Segment, feed: Feed, machine: &Machine) -> f64 {
    let len = seg.length();
    if len == 0.0 {
        return 0.0;
    }
    match feed {
        Feed::Rapid => {
            // Each axis at its own rate; the slower axis decides.
            let tz = (seg.to.z - seg.from.z).abs() / machine.rapid_z;
            let tr = (seg.to.r - seg.from.r).abs() / machine.rapid_x;
            tz.max(tr) * 60.0
        }
        Feed::PerMinute(f) => len / f * 60.0,
        Feed::PerRev { feed, spindle } => match spindle {
            Spindle::Rpm(n) if n > 0.0 => len / (feed * n.min(machine.max_rpm)) * 60.0,
            Spindle::Rpm(_) => 0.0,
            Spindle::Css { vc, max_rpm } => {
                // Integrate dt = ds / (f · n(r)) along the path; 32 steps bound the error
                // of the 1/r variation well below a second for any real move.
                let pts = seg.polyline(0.01);
                let mut t = 0.0;
                for w in pts.windows(2) {
                    let steps = 32;
                    for k in 0..steps {
                        let u = (k as f64 + 0.5) / steps as f64;
                        let r = (w[0].r + (w[1].r - w[0].r) * u).abs();
                        let n = rpm_css(vc, r, max_rpm);
                        if n > 0.0 {
                            t += w[0].dist(w[1]) / steps as f64 / (feed * n) * 60.0;
                        }
                    }
                }
                t
            }
        },
    }
}

/// Spindle speed under G96 at radius `r` mm: n = 1000·vc / (π·D), clamped at `max_rpm`.
pub fn rpm_css(vc: f64, r: f64, max_rpm: f64) -> f64 {
    let d = 2.0 * r;
    if d <= 1e-9 {
        return max_rpm;
    }
    (1000.0 * vc / (std::f64::consts::PI * d)).min(max_rpm)
}

/// A toolpath's cycle time and its share per tool.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Times {
    /// Every move and dwell, s.
    pub total: f64,
    /// Cutting and rapid time per tool number, in order of first use (dwells not
    /// included), s.
    pub per_tool: Vec<(u32, f64)>,
    /// The time in cut (feed and thread moves) per tool number, in the order of
    /// [`Times::per_tool`], s: the setup sheet's "in cut".
    pub cutting: Vec<(u32, f64)>,
}

/// The cycle time and the time per tool, in one pass over the moves (a million-move
/// program's moves are 120 MB: each pass over them costs about as much as its sums).
pub fn times(tp: &Toolpath, machine: &Machine) -> Times {
    let mut total = 0.0;
    let mut per_tool: Vec<(u32, f64)> = vec![];
    let mut cutting: Vec<(u32, f64)> = vec![];
    for s in &tp.segments {
        let t = segment_time(tp, s, machine);
        let cut = if s.motion == crate::Motion::Rapid {
            0.0
        } else {
            t
        };
        total += t;
        match per_tool.iter().position(|(tool, _)| *tool == s.tool) {
            Some(i) => {
                per_tool[i].1 += t;
                cutting[i].1 += cut;
            }
            None => {
                per_tool.push((s.tool, t));
                cutting.push((s.tool, cut));
            }
        }
    }
    Times {
        total: total + tp.dwell_s,
        per_tool,
        cutting,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Motion, Pt, Span};

    /// A toolpath of the one feed move `from -> to`.
    fn seg(from: Pt, to: Pt, feed: Feed) -> Toolpath {
        let mut tp = Toolpath::default();
        let feed = tp.feeds.id(feed).unwrap();
        tp.segments.push(Segment {
            motion: Motion::Feed,
            from,
            to,
            arc: None,
            tool: 1,
            hint: crate::ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed,
            span: Span::default(),
        });
        tp
    }

    #[test]
    fn per_minute_and_per_rev() {
        let m = Machine::default();
        let s = seg(
            Pt::new(0.0, 10.0),
            Pt::new(-100.0, 10.0),
            Feed::PerMinute(200.0),
        );
        assert!((times(&s, &m).total - 30.0).abs() < 1e-9);
        let s = seg(
            Pt::new(0.0, 10.0),
            Pt::new(-30.0, 10.0),
            Feed::PerRev {
                feed: 0.1,
                spindle: Spindle::Rpm(600.0),
            },
        );
        assert!((times(&s, &m).total - 30.0).abs() < 1e-9);
    }

    #[test]
    fn css_at_constant_diameter() {
        let m = Machine::default();
        // Φ100, vc 150 m/min: n = 477.46 rev/min; 50 mm at 0.2 mm/rev = 250 rev -> 31.4 s
        let s = seg(
            Pt::new(0.0, 50.0),
            Pt::new(-50.0, 50.0),
            Feed::PerRev {
                feed: 0.2,
                spindle: Spindle::Css {
                    vc: 150.0,
                    max_rpm: 3000.0,
                },
            },
        );
        let n = 1000.0 * 150.0 / (std::f64::consts::PI * 100.0);
        assert!((times(&s, &m).total - 250.0 / n * 60.0).abs() < 1e-6);
    }

    /// A tool's time in cut leaves out its rapids; its time counts them (issue 35's
    /// setup sheet), each tool in order of first use.
    #[test]
    fn time_in_cut_leaves_out_the_rapids() {
        let m = Machine::default();
        // tool 1: 100 mm at 200 mm/min (30 s), then a rapid back
        let mut tp = seg(
            Pt::new(0.0, 10.0),
            Pt::new(-100.0, 10.0),
            Feed::PerMinute(200.0),
        );
        let feed = tp.segments[0];
        let rapid_feed = tp.feeds.id(Feed::Rapid).unwrap();
        let rapid = Segment {
            motion: Motion::Rapid,
            from: feed.to,
            to: feed.from,
            feed: rapid_feed,
            ..feed
        };
        tp.segments.push(rapid);
        // tool 2: 50 mm at 200 mm/min (15 s)
        tp.segments.push(Segment {
            tool: 2,
            to: Pt::new(-50.0, 10.0),
            ..feed
        });
        let r = segment_time(&tp, &rapid, &m);
        assert!(r > 0.0);
        let t = times(&tp, &m);
        assert_eq!(t.per_tool.len(), 2);
        assert_eq!((t.per_tool[0].0, t.cutting[0].0), (1, 1));
        assert!((t.per_tool[0].1 - (30.0 + r)).abs() < 1e-9);
        assert!((t.cutting[0].1 - 30.0).abs() < 1e-9);
        assert_eq!((t.per_tool[1].0, t.cutting[1].0), (2, 2));
        assert!((t.cutting[1].1 - 15.0).abs() < 1e-9 && (t.per_tool[1].1 - 15.0).abs() < 1e-9);
    }
}
