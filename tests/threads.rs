//! G76 through the interpreter (issue 14): the two-block FANUC/GSK form on the issue's
//! M20 × 1.5 thread, with the pass depths computed by hand.

mod common;

/// `G76 P021060 Q50 R0.05` / `G76 X18.05 Z-25 P975 Q400 F1.5` from X22 Z5, IS-B:
/// m 2, r 1.0 lead, a 60°, Δdmin 0.05, d 0.05, k 0.975, Δd 0.4. Depths Δd·√n:
/// 0.4, 0.5657, 0.6928, 0.8, 0.8944, then 0.9798 > k − d = 0.925 is cut at 0.925,
/// then m = 2 passes at k: 8 passes; the last three reach the minor diameter
/// 20 − 2·0.975 = 18.05.
#[test]
fn g76_two_block_m20x1_5_passes() {
    let text = "G99 M03 S600 T0101\nG00 X22 Z5\nG76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\nG00 X50 Z50\nM30\n";
    let program = gcode::parse(text).unwrap();
    let tp = expander::expand(&program, &expander::Machine::default(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    // the first thread move of each pass: its radius is the crest radius minus the depth
    let starts: Vec<f64> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread && s.span.line == 4)
        .filter(|s| (s.from.r - s.to.r).abs() < 1e-9)
        .map(|s| 2.0 * s.from.r)
        .collect();
    let depths = [0.4, 0.565685, 0.692820, 0.8, 0.894427, 0.925, 0.975, 0.975];
    assert_eq!(starts.len(), depths.len(), "{starts:?}");
    for (x, h) in starts.iter().zip(depths) {
        // X of a pass = 18.05 + 2·(k − h)
        let expected = 18.05 + 2.0 * (0.975 - h);
        assert!((x - expected).abs() < 2e-6, "{x} vs {expected}");
    }
    // every thread move keeps the 1.5 lead
    assert!(tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .all(|s| (s.lead - 1.5).abs() < 1e-12));
}
