//! Helpers shared by the expander's test files.
#![allow(dead_code, unreachable_pub)]

use expander::{Motion, Segment, Toolpath};

/// One readable line per segment, for snapshots a reviewer can read, with `extra` columns
/// (tool, feed, hint…) at the end; then the alarms and warnings.
pub fn listing(tp: &Toolpath, extra: impl Fn(&Segment) -> String) -> String {
    let mut s = String::new();
    for seg in &tp.segments {
        let kind = match (seg.motion, seg.arc) {
            (Motion::Rapid, _) => "G00".to_string(),
            (Motion::Feed, None) => "G01".to_string(),
            (Motion::Feed, Some(a)) => format!(
                "{} c(Z{:.3} X{:.3})",
                if a.ccw { "G03" } else { "G02" },
                a.center.z,
                2.0 * a.center.r
            ),
            (Motion::Thread, _) => format!("G32 lead {}", seg.lead),
        };
        s += &format!(
            "line {:>2}: {kind} Z{:.3} X{:.3} -> Z{:.3} X{:.3} {}\n",
            seg.span.line,
            seg.from.z,
            2.0 * seg.from.r,
            seg.to.z,
            2.0 * seg.to.r,
            extra(seg)
        );
    }
    for a in tp.alarms.iter().chain(&tp.warnings) {
        s += &format!("{a}\n");
    }
    s
}

/// A program from `assets/programs/`.
pub fn asset(name: &str) -> String {
    std::fs::read_to_string(format!(
        "{}/../../assets/programs/{name}",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
}
