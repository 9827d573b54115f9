//! A holder's hand letter gives a turning tool its usual tip (right hand: toward the chuck,
//! tip 3 on the OD, 2 in a bore; left hand: toward the tailstock, 4 and 1). The direction a
//! holder cuts is its hand together with its mounting and the spindle's turning: a left-hand
//! holder mounted upside down, or behind the centre line with M04, cuts toward the chuck.
//! The tip is the program's (FANUC and Haas define it in program coordinates), so where the
//! table states no `tip` and the program feeds the tool clearly the other way, the tip is
//! read from the program (docs/field-rules.md §14).

use super::{Tool, ToolTable};
use expander::{Motion, Segment};

/// A tool read with the other tip than its holder's hand letter gives.
#[derive(Debug, Clone, PartialEq)]
pub struct TipFromUse {
    /// The T number.
    pub t: u32,
    /// The tip the hand letter gave.
    pub hand: u8,
    /// The tip the program's feeds give.
    pub tip: u8,
    /// The index of the tool's first feed the other way.
    pub first: usize,
    /// How far the tool feeds along Z toward the chuck and toward the tailstock, mm (moves
    /// more along Z than along X).
    pub toward_chuck: f64,
    /// See [`TipFromUse::toward_chuck`].
    pub toward_tailstock: f64,
}

/// The feed the other way must be this many times the feed the hand's way, and at least
/// [`MIN_FEED`] mm: a right-hand tool's odd move back along Z changes nothing; and the tool
/// must feed along Z at least as far as across it (a facing tool's step up a hub is no
/// turning).
const CLEAR: f64 = 4.0;
/// See [`CLEAR`].
const MIN_FEED: f64 = 1.0;

impl ToolTable {
    /// The tools whose tip came from their holder's hand letter and that `segments` feed
    /// clearly the other way along Z.
    pub fn tips_from_use(&self, segments: &[Segment]) -> Vec<TipFromUse> {
        self.hand_tips
            .iter()
            .filter_map(|&t| {
                let Some(Tool::Turning { tip, .. }) = self.get(t) else {
                    return None;
                };
                let (to_chuck, other) = match tip {
                    3 => (true, 4),
                    2 => (true, 1),
                    4 => (false, 3),
                    1 => (false, 2),
                    _ => return None,
                };
                let (mut minus, mut plus, mut first) = (0.0, 0.0, None);
                let mut across = 0.0;
                for (i, s) in segments.iter().enumerate() {
                    let dz = s.to.z - s.from.z;
                    if s.tool != t || s.motion != Motion::Feed {
                        continue;
                    }
                    if dz.abs() <= (s.to.r - s.from.r).abs() {
                        across += (s.to.r - s.from.r).abs();
                        continue;
                    }
                    if dz < 0.0 {
                        minus -= dz;
                    } else {
                        plus += dz;
                    }
                    if first.is_none() && (dz < 0.0) != to_chuck {
                        first = Some(i);
                    }
                }
                let (along, against) = if to_chuck {
                    (minus, plus)
                } else {
                    (plus, minus)
                };
                // a tool that faces more than it turns (a G72 hub's step up along Z) says
                // nothing of the way it turns (field run 7, C)
                let turns = along + against >= across;
                (turns && against >= MIN_FEED && against >= CLEAR * along).then_some(TipFromUse {
                    t,
                    hand: *tip,
                    tip: other,
                    first: first?,
                    toward_chuck: minus,
                    toward_tailstock: plus,
                })
            })
            .collect()
    }

    /// The table with the tips `read` gives.
    pub fn with_tips(&self, read: &[TipFromUse]) -> Self {
        let mut out = self.clone();
        for r in read {
            if let Some((_, Tool::Turning { tip, .. })) =
                out.tools.iter_mut().find(|(n, _)| *n == r.t)
            {
                *tip = r.tip;
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::removal::tests::seg;
    use crate::ToolTable;
    use expander::Motion;

    fn table(holder: &str, tip: &str) -> ToolTable {
        ToolTable::from_toml(&format!(
            "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"{holder}\"\n{tip}"
        ))
        .unwrap()
    }

    /// Feeds of T1 along Z: 30 mm toward the chuck, `back` mm toward the tailstock, and a
    /// face (along X, no evidence) and a rapid (none either).
    fn moves(back: f64) -> Vec<expander::Segment> {
        vec![
            seg(Motion::Feed, [0.0, 20.0], [-30.0, 20.0]),
            seg(Motion::Feed, [-30.0, 15.0], [-30.0 + back, 15.0]),
            seg(Motion::Feed, [0.0, 25.0], [0.0, 0.0]),
            seg(Motion::Rapid, [-30.0, 25.0], [100.0, 25.0]),
        ]
    }

    /// A left-hand holder (tip 4) fed 30 mm toward the chuck and 7.5 back is read as tip 3
    /// (4× the other way, the least that counts); 7.6 back is not clear enough. A stated tip
    /// and a right-hand holder fed its own way are kept.
    #[test]
    fn the_tip_is_read_from_the_feeds_only_when_they_clearly_go_the_other_way() {
        let read = table("PCLNL 2525M12", "").tips_from_use(&moves(7.5));
        assert_eq!(read.len(), 1);
        assert_eq!((read[0].hand, read[0].tip, read[0].first), (4, 3, 0));
        assert!((read[0].toward_chuck - 30.0).abs() < 1e-12);
        assert!(table("PCLNL 2525M12", "")
            .tips_from_use(&moves(7.6))
            .is_empty());
        assert!(table("PCLNL 2525M12", "tip = 4\n")
            .tips_from_use(&moves(0.0))
            .is_empty());
        assert!(table("PCLNR 2525M12", "")
            .tips_from_use(&moves(0.0))
            .is_empty());
        let flipped = table("PCLNL 2525M12", "").with_tips(&read);
        assert!(matches!(
            flipped.get(1),
            Some(crate::Tool::Turning { tip: 3, .. })
        ));
    }
}
