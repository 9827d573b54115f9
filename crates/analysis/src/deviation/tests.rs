//! The deviation's tests: intents, findings, depths and blame against hand-made parts.

use super::blame::{overlaps, SLIVER};
use super::*;
use crate::intent::*;

/// The deviation of `final_shapes` from `part` within one `zone`, at 0.01 mm, with no
/// moves to blame: every edge of `part` is a stated surface, as a drawing's.
fn deviation_in(
    blank: &[Shape],
    final_shapes: &[Shape],
    part: Vec<Shape>,
    zone: Shape,
) -> Deviation {
    let outline = part
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(&s.holes))
        .map(|ring| (ring.clone(), true))
        .collect();
    let intent = Intent {
        part,
        zone: vec![zone],
        outline,
        owner: None,
    };
    deviation(
        blank,
        final_shapes,
        &[intent],
        0.01,
        &[],
        &ToolTable::empty(),
        0.001,
    )
}

/// The clipping shortcut of [`overlaps`] against the boolean it replaces: a region with
/// a hole (a 10 × 6 frame around a 6 × 2 hole) and convex parts slid across it on a
/// grid, alone and in pairs, give the same answer.
#[test]
fn overlap_by_clipping_agrees_with_the_boolean() {
    let region = Shape {
        outer: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 6.0], [0.0, 6.0]],
        holes: vec![vec![[2.0, 2.0], [2.0, 4.0], [8.0, 4.0], [8.0, 2.0]]],
    };
    let bb = Rect::of(pts(&region.outer));
    let tri = |z: f64, r: f64| vec![[z, r], [z + 1.5, r], [z + 0.5, r + 1.0]];
    let by_boolean = |parts: &[Vec<P>]| {
        let union: Vec<Shape> = parts
            .iter()
            .map(|o| Shape {
                outer: o.clone(),
                holes: vec![],
            })
            .collect();
        area(&boolean(
            &union,
            std::slice::from_ref(&region),
            BoolOp::Intersection,
        )) > 1e-9
    };
    let (mut hits, mut misses) = (0, 0);
    for i in -4..24 {
        for j in -4..14 {
            let (z, r) = (i as f64 * 0.5, j as f64 * 0.5);
            for parts in [vec![tri(z, r)], vec![tri(z, r), tri(z + 0.25, r - 0.75)]] {
                let expect = by_boolean(&parts);
                assert_eq!(
                    overlaps(&region, &bb, &parts, SLIVER),
                    expect,
                    "at ({z}, {r})"
                );
                if expect {
                    hits += 1;
                } else {
                    misses += 1;
                }
            }
        }
    }
    // inside the hole, touching edges and far away all occur
    assert!(hits > 100 && misses > 100, "{hits} hits, {misses} misses");
}

/// A 1 mm wide step left 0.05 mm proud on a Φ30 shaft 200 mm long whose surface is
/// everywhere else 0.0002 mm proud (chord-level noise): the two make one region of
/// mean thickness 2·0.0898 / 400 ≈ 0.00045 mm, under the noise filter's tol / 10. The
/// step is a real leftover and must be found; the sliver alone is not a finding.
#[test]
fn a_leftover_joined_to_a_long_sliver_is_still_found() {
    let blank = [rect(-200.0, 0.0, 0.0, 20.0)];
    let part = vec![rect(-200.0, 0.0, 0.0, 15.0)];
    let zone = rect(-200.0, 0.0, 0.0, 30.0);
    let sliver = rect(-200.0, 0.0, 0.0, 15.0002);
    let step = rect(-101.0, -100.0, 0.0, 15.05);
    let final_shapes = boolean(&[sliver.clone(), step], &[], BoolOp::Union);
    let d = deviation_in(&blank, &final_shapes, part.clone(), zone.clone());
    assert_eq!(d.leftovers.len(), 1, "{d:?}");
    let l = &d.leftovers[0];
    assert!((l.depth - 0.05).abs() < 1e-6, "{l:?}");
    // (the booleans snap to a grid of ~5·10⁻⁸ mm over the 200 mm blank)
    assert!((l.area - (200.0 * 0.0002 + 0.0498)).abs() < 1e-4, "{l:?}");
    // the sliver alone
    let d = deviation_in(&blank, &[sliver], part, zone);
    assert!(d.leftovers.is_empty() && d.gouges.is_empty(), "{d:?}");
}

#[test]
fn gouge_and_leftover_with_depth() {
    let blank = [rect(-50.0, 0.0, 0.0, 20.0)];
    // intended: Φ30 (r 15) from Z0 to Z-20; the part: r 14.5 (0.5 deep gouge) from Z0 to
    // Z-10 and r 16 (1 mm leftover) from Z-10 to Z-20
    let part = [rect(-50.0, -20.0, 0.0, 20.0), rect(-20.0, 0.0, 0.0, 15.0)];
    let part = boolean(&part, &[], BoolOp::Union);
    let final_shapes = boolean(
        &[
            rect(-50.0, -20.0, 0.0, 20.0),
            rect(-10.0, 0.0, 0.0, 14.5),
            rect(-20.0, -10.0, 0.0, 16.0),
        ],
        &[],
        BoolOp::Union,
    );
    let zone = rect(-30.0, 10.0, 0.0, 30.0);
    let d = deviation_in(&blank, &final_shapes, part, zone);
    assert_eq!(d.gouges.len(), 1);
    assert_eq!(d.leftovers.len(), 1);
    assert!(
        (d.gouges[0].area - 5.0).abs() < 1e-6 && (d.gouges[0].depth - 0.5).abs() < 1e-6,
        "{:?}",
        d.gouges[0]
    );
    assert!((d.leftovers[0].area - 10.0).abs() < 1e-6 && (d.leftovers[0].depth - 1.0).abs() < 1e-6);
    assert!((d.max_overcut() - 0.5).abs() < 1e-6 && (d.undercut_area() - 10.0).abs() < 1e-6);
}

#[test]
fn groove_intent_wants_the_ring_gone_and_the_rest_kept() {
    let ring = [[-10.0, 20.0], [-10.0, 15.0], [-6.0, 15.0], [-6.0, 20.0]];
    let i = Intent::groove(&ring);
    // the zone grows 5 mm along Z both sides and 5 mm down: 14 × 10 box minus the 4 × 5 groove
    assert!(
        (area(&i.part) - (14.0 * 10.0 - 20.0)).abs() < 1e-9,
        "{}",
        area(&i.part)
    );
    let ring = [[-10.0, 20.0], [-8.0, 15.0], [-6.0, 15.0], [-4.0, 20.0]];
    let i = Intent::groove(&ring);
    assert!(
        (area(&i.part) - (16.0 * 10.0 - 20.0)).abs() < 1e-9,
        "{}",
        area(&i.part)
    );
}

#[test]
fn finishing_shape_sides() {
    // OD: A above; the part is below the shape within its Z span
    let blank = [rect(-50.0, 0.0, 0.0, 25.0)];
    let od = Intent::finishing(
        &[[5.0, 30.0], [0.0, 10.0], [-10.0, 10.0], [-10.0, 20.0]],
        &only(&blank),
    )
    .unwrap();
    let kept = boolean(&blank, &od.part, BoolOp::Intersection);
    let kept = boolean(&kept, &od.zone, BoolOp::Intersection);
    assert!((area(&kept) - 100.0).abs() < 1e-6, "{}", area(&kept));
    // ID: A below
    let id = Intent::finishing(&[[5.0, 5.0], [0.0, 12.0], [-10.0, 12.0]], &only(&blank)).unwrap();
    let kept = boolean(&blank, &id.part, BoolOp::Intersection);
    let kept = boolean(&kept, &id.zone, BoolOp::Intersection);
    assert!((area(&kept) - 130.0).abs() < 1e-6, "{}", area(&kept));
}

#[test]
fn within_tolerance_and_outside_the_zone_is_not_a_finding() {
    let blank = [rect(-50.0, 0.0, 0.0, 20.0)];
    let part = vec![rect(-50.0, 0.0, 0.0, 15.0)];
    // 0.005 too deep everywhere, and a deep cut outside the zone
    let final_shapes = boolean(
        &[rect(-40.0, 0.0, 0.0, 14.995), rect(-50.0, -40.0, 0.0, 5.0)],
        &[],
        BoolOp::Union,
    );
    let zone = rect(-40.0, 0.0, 0.0, 30.0);
    let d = deviation_in(&blank, &final_shapes, part, zone);
    assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
}

/// The stock a contour is read against: `began` when its cycle began, `finished` at the
/// end, on `blank`.
fn stages<'a>(began: &'a [Shape], finished: &'a [Shape], blank: &'a [Shape]) -> Stages<'a> {
    Stages {
        began,
        finished,
        blank,
    }
}

/// One stock for all three stages.
fn only(stock: &[Shape]) -> Stages<'_> {
    stages(stock, stock, stock)
}

fn zone_z(i: &Intent) -> (f64, f64) {
    let (lo, hi) = bbox(&i.zone[0].outer);
    (lo[0], hi[0])
}

/// Z spans equal to the overlay's grid (the contact points come out of a boolean).
fn assert_span(got: (f64, f64), want: (f64, f64)) {
    assert!(
        (got.0 - want.0).abs() < 1e-6 && (got.1 - want.1).abs() < 1e-6,
        "{got:?} vs {want:?}"
    );
}

/// Issue 13 item 3: `N10 G00 X20` at Z2, `G01 Z0`, `Z-20`, `X30`, `Z-35`, `N20 X41` on a
/// Φ40 blank whose face is at Z1. The lead-in Z2 → Z0 runs in front of the face at Z0: no
/// part of the shape, which starts at Z0 (the profile's vertex), whether the face was faced
/// to Z0 before the cycle or is faced after it (field run 4: "rough face, G71/G70, finish
/// face" counted the 1 mm stub in front of Z0 as part, a gouge of 10 mm², 1 mm deep). A
/// face cut 1 mm too deep after it is still found: 10 mm².
#[test]
fn a_lead_in_in_front_of_the_stock_is_no_part() {
    let path = [
        [2.0, 21.0],
        [2.0, 10.0],
        [0.0, 10.0],
        [-20.0, 10.0],
        [-20.0, 15.0],
        [-35.0, 15.0],
        [-35.0, 20.5],
    ];
    let blank = [rect(-60.0, 1.0, 0.0, 20.0)];
    let faced = [rect(-60.0, 0.0, 0.0, 20.0)];
    let finished_at = |front: f64| {
        boolean(
            &[
                rect(-60.0, -35.0, 0.0, 20.0),
                rect(-35.0, -20.0, 0.0, 15.0),
                rect(-20.0, front, 0.0, 10.0),
            ],
            &[],
            BoolOp::Union,
        )
    };
    let run = |began: &[Shape], finished: &[Shape]| {
        let i = Intent::finishing(&path, &stages(began, finished, &blank)).unwrap();
        let z = zone_z(&i);
        let d = deviation(
            &blank,
            finished,
            &[i],
            0.01,
            &[],
            &ToolTable::empty(),
            0.001,
        );
        (z, d)
    };
    for began in [&faced[..], &blank[..]] {
        let (z, d) = run(began, &finished_at(0.0));
        assert_span(z, (-35.0, 0.0));
        assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
        // (its depth is measured to the part beyond the zone, the blank's face at Z1 as
        // much as Z0: field run 4's item 5e, left)
        let (z, d) = run(began, &finished_at(-1.0));
        assert_span(z, (-35.0, 0.0));
        assert_eq!(d.gouges.len(), 1, "{d:?}");
        assert!((d.gouges[0].area - 10.0).abs() < 1e-6, "{:?}", d.gouges[0]);
    }
}

/// Item 3: a diameter reached straight from the approach (`G00 X20` at Z2, `G01 Z-20`)
/// starts where the stock started (faced to Z0: no gouge in the faced slab); a retract
/// off the last diameter (`X44 Z-36.5` from Φ30 at Z-35 on a Φ40 bar) is no part, so the
/// corner it would cut off is no leftover.
#[test]
fn approach_and_retract_are_no_part() {
    let blank = [rect(-60.0, 1.0, 0.0, 20.0)];
    let faced = [rect(-60.0, 0.0, 0.0, 20.0)];
    let path = [
        [2.0, 23.0],
        [2.0, 10.0],
        [-20.0, 10.0],
        [-20.0, 15.0],
        [-35.0, 15.0],
        [-36.5, 22.0],
    ];
    let finished = boolean(
        &[
            rect(-60.0, -35.0, 0.0, 20.0),
            rect(-35.0, -20.0, 0.0, 15.0),
            rect(-20.0, 0.0, 0.0, 10.0),
        ],
        &[],
        BoolOp::Union,
    );
    let i = Intent::finishing(&path, &stages(&faced, &finished, &blank)).unwrap();
    assert_span(zone_z(&i), (-35.0, 0.0));
    let d = deviation(
        &blank,
        &finished,
        &[i],
        0.01,
        &[],
        &ToolTable::empty(),
        0.001,
    );
    assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
    // on a blank never faced the Φ20 diameter starts at the blank's face Z1; faced to Z0
    // after the cycle (turn first, face last), at Z0: the shape states no face, and what
    // the program faces off in front of its part was never part
    let i = Intent::finishing(&path, &only(&blank)).unwrap();
    assert_span(zone_z(&i), (-35.0, 1.0));
    let i = Intent::finishing(&path, &stages(&blank, &finished, &blank)).unwrap();
    assert_span(zone_z(&i), (-35.0, 0.0));
    // a face gouged 1 mm too deep before a shape that marks its face (`G01 Z0`, `Z-20`)
    // is still found: the lead-in is dropped, the profile keeps its vertex at Z0
    let deep = [rect(-60.0, -1.0, 0.0, 20.0)];
    let marked = [
        [2.0, 21.0],
        [2.0, 10.0],
        [0.0, 10.0],
        [-20.0, 10.0],
        [-20.0, 15.0],
    ];
    let i = Intent::finishing(&marked, &stages(&deep, &deep, &blank)).unwrap();
    assert_span(zone_z(&i), (-20.0, 0.0));
}

/// A back chamfer cut toward +Z under G41 along the chamfer's own line, coming in over a
/// neck cut before (Φ60 flange Z0..−10, Φ40 neck behind): the path r = z + 39 from
/// Z−12 to Z−7 touches the flange only from (−10, 29) to (−9, 30); the lead-in over the
/// neck and the run-out above the flange are no part, so the neck is no gouge.
#[test]
fn a_lead_in_along_the_chamfer_line_is_no_part() {
    let stock = boolean(
        &[rect(-10.0, 0.0, 0.0, 30.0), rect(-60.0, -10.0, 0.0, 20.0)],
        &[],
        BoolOp::Union,
    );
    let i = Intent::compensated(&[[-12.0, 27.0], [-7.0, 32.0]], false, &only(&stock)).unwrap();
    assert_span(zone_z(&i), (-10.0, -9.0));
    let blank = [rect(-60.0, 0.0, 0.0, 30.0)];
    let finished = boolean(
        &[
            Shape {
                outer: vec![
                    [-10.0, 0.0],
                    [0.0, 0.0],
                    [0.0, 30.0],
                    [-9.0, 30.0],
                    [-10.0, 29.0],
                ],
                holes: vec![],
            },
            rect(-60.0, -10.0, 0.0, 20.0),
        ],
        &[],
        BoolOp::Union,
    );
    let d = deviation(
        &blank,
        &finished,
        &[i],
        0.01,
        &[],
        &ToolTable::empty(),
        0.001,
    );
    assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
}

/// A chamfer under G42 from Z2 to Φ26 at Z−1, Z−2, then `X32.` off the Φ30 bar before the
/// G40: the retract is no part, also in choosing the side (with it, the normals pointed
/// toward −Z and the contour claimed Φ32 over the whole bar beyond Z−2).
#[test]
fn a_retract_off_the_last_diameter_does_not_turn_the_side() {
    let stock = boolean(
        &[rect(-90.0, 0.0, 0.0, 13.0), rect(-150.0, -90.0, 0.0, 15.0)],
        &[],
        BoolOp::Union,
    );
    let path = [[2.0, 10.0], [-1.0, 13.0], [-2.0, 13.0], [-2.0, 16.0]];
    let i = Intent::compensated(&path, true, &only(&stock)).unwrap();
    // OD: closed toward −r over the chamfer's Z span from the face
    assert_span(zone_z(&i), (-2.0, 0.0));
    let (lo, _) = bbox(&i.zone[0].outer);
    assert!(lo[1] < -1e4, "{:?}", i.zone);
}

/// A cut line from (−6, 10) to (0, 7) across the corner (0, 10) of a part [−10, 0] ×
/// [0, 10]: the gouge is deepest where the corner's bisector meets the cut, (−2, 8), 2 mm
/// from both edges; its vertices are on the part's edges and its cut edge's midpoint
/// (−3, 8.5) is only 1.5 deep (what vertices and midpoints reported).
#[test]
fn a_gouge_is_as_deep_as_where_the_bisector_meets_the_cut() {
    let part = rect(-10.0, 0.0, 0.0, 10.0);
    let boundary = EdgeIndex::of_rings([pts(&part.outer)].iter().map(Vec::as_slice));
    let gouge = Shape {
        outer: vec![[-6.0, 10.0], [0.0, 7.0], [0.0, 10.0]],
        holes: vec![],
    };
    let (depth, at, _) = deepest(&gouge, &boundary, DEPTH_STEP);
    assert!((depth - 2.0).abs() < 1e-6, "{depth} at {at:?}");
    assert!(
        (at[0] + 2.0).abs() < 1e-5 && (at[1] - 8.0).abs() < 1e-5,
        "{at:?}"
    );
}

/// A sawtooth ring: teeth between r 12 and 14, `n` of them from Z0 to Z-20, on a body
/// down to the axis.
fn sawtooth(n: usize) -> Shape {
    let mut outer = vec![[-20.0, 0.0], [0.0, 0.0]];
    for k in 0..=2 * n {
        let z = -20.0 * k as f64 / (2 * n) as f64;
        outer.push([z, if k % 2 == 0 { 12.0 } else { 14.0 }]);
    }
    Shape {
        outer,
        holes: vec![],
    }
}

/// The comparison as it was before the intents were clipped to the blank's box (the
/// world and the intents FAR away, so the grid is fitted to ±FAR).
fn deviation_unclipped(blank: &[Shape], final_shapes: &[Shape], intent: &Intent) -> Deviation {
    let world = vec![rect(-FAR, FAR, -FAR, FAR)];
    let elsewhere = boolean(&world, &intent.zone, BoolOp::Difference);
    let keeps = boolean(&intent.part, &elsewhere, BoolOp::Union);
    let part = boolean(blank, &keeps, BoolOp::Intersection);
    let zone = boolean(&[], &intent.zone, BoolOp::Union);
    let should_stay = boolean(&part, &zone, BoolOp::Intersection);
    let final_zone = boolean(final_shapes, &zone, BoolOp::Intersection);
    let gone = boolean(&should_stay, final_shapes, BoolOp::Difference);
    let left = boolean(&final_zone, &part, BoolOp::Difference);
    Deviation {
        gouges: findings(gone, &part, 0.01),
        leftovers: findings(left, &part, 0.01),
        later_cuts: vec![],
    }
}

/// Issue 17: the intents are clipped to the blank's box before the booleans. On a
/// sawtooth blank with a target Φ22 (r 11) OD part, closed far away, and a final part
/// with a groove 0.5 mm into the target, gouge and leftovers are those of the unclipped
/// comparison (to its coarser grid's precision).
#[test]
fn clipping_the_intents_to_the_blank_changes_no_finding() {
    let blank = vec![sawtooth(200)];
    let target = Intent::target(vec![rect(-FAR, FAR, 0.0, 11.0)]);
    let groove = rect(-12.0, -8.0, 10.5, 20.0);
    let final_shapes = boolean(&blank, &[groove], BoolOp::Difference);
    let new = deviation(
        &blank,
        &final_shapes,
        std::slice::from_ref(&target),
        0.01,
        &[],
        &ToolTable::empty(),
        0.001,
    );
    let old = deviation_unclipped(&blank, &final_shapes, &target);
    assert_eq!(new.gouges.len(), 1);
    assert_eq!(new.leftovers.len(), 2);
    assert_eq!(new.gouges.len(), old.gouges.len());
    assert_eq!(new.leftovers.len(), old.leftovers.len());
    // the gouge: 4 mm × 0.5 mm under the target surface
    assert!(
        (new.gouges[0].area - 2.0).abs() < 1e-6,
        "{:?}",
        new.gouges[0]
    );
    assert!((new.gouges[0].depth - 0.5).abs() < 1e-6);
    for (a, b) in new
        .gouges
        .iter()
        .chain(&new.leftovers)
        .zip(old.gouges.iter().chain(&old.leftovers))
    {
        assert!(
            (a.area - b.area).abs() < 1e-4 * b.area.max(1.0),
            "{} {}",
            a.area,
            b.area
        );
        assert!((a.depth - b.depth).abs() < 1e-3, "{} {}", a.depth, b.depth);
    }
    assert!((new.undercut_area() - old.undercut_area()).abs() < 1e-3);
}

/// The box clip keeps a concave ring's area inside the box (a ring leaving and
/// re-entering the box is bridged along the box's side, enclosing nothing).
#[test]
fn box_clip_of_a_concave_ring_is_the_intersection() {
    let u = Shape {
        outer: vec![
            [0.0, 0.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [7.0, 10.0],
            [7.0, 3.0],
            [3.0, 3.0],
            [3.0, 10.0],
            [0.0, 10.0],
        ],
        holes: vec![],
    };
    let bx = Rect::new(geom::Pt::new(-1.0, 5.0), geom::Pt::new(11.0, 20.0));
    let clipped = clip_to_box(std::slice::from_ref(&u), &bx);
    let exact = boolean(
        std::slice::from_ref(&u),
        &[rect(-1.0, 11.0, 5.0, 20.0)],
        BoolOp::Intersection,
    );
    let norm = boolean(&clipped, &[], BoolOp::Union);
    assert!((area(&norm) - 30.0).abs() < 1e-9, "{}", area(&norm));
    assert!((area(&exact) - 30.0).abs() < 1e-9);
    assert_eq!(norm.len(), 2, "two legs: {norm:?}");
}

/// Field run 7 (A): an intent states the surface it outlines, not the part's other side.
/// A bore contour (the part outside r 11.2 over Z0 … −22) on a tube Φ40 / Φ20 whose OD a
/// G90 turned to Φ35.6: the OD ring, 2.2 deep and 48.4 mm², lies in the bore's zone and
/// in what it keeps, but no stated surface meets it: no gouge. The same OD cut under an
/// OD contour at r 18 is one (0.2 deep, 22 × 0.2 = 4.4 mm²).
#[test]
fn only_a_stated_surface_is_judged() {
    let blank = [rect(-30.0, 0.0, 10.0, 20.0)];
    let bore = vec![[0.0, 11.2], [-22.0, 11.2]];
    let bore_intent = Intent {
        part: vec![rect(-22.0, 0.0, 11.2, FAR)],
        zone: vec![rect(-22.0, 0.0, -FAR, FAR)],
        outline: vec![(bore.clone(), false)],
        owner: None,
    };
    let turned = boolean(
        &[rect(-30.0, -22.0, 10.0, 20.0), rect(-22.0, 0.0, 11.2, 17.8)],
        &[],
        BoolOp::Union,
    );
    let judge = |intents: &[Intent], part: &[Shape]| {
        deviation(&blank, part, intents, 0.01, &[], &ToolTable::empty(), 0.001)
    };
    let d = judge(std::slice::from_ref(&bore_intent), &turned);
    assert!(d.gouges.is_empty(), "{:?}", d.gouges);
    // an OD contour at r 18 over the same span: the G90 went 0.2 below it
    let od_intent = Intent {
        part: vec![rect(-22.0, 0.0, -FAR, 18.0)],
        zone: vec![rect(-22.0, 0.0, -FAR, FAR)],
        outline: vec![(vec![[0.0, 18.0], [-22.0, 18.0]], false)],
        owner: None,
    };
    let d = judge(&[bore_intent, od_intent], &turned);
    assert_eq!(d.gouges.len(), 1, "{:?}", d.gouges);
    let g = &d.gouges[0];
    assert!(
        (g.depth - 0.2).abs() < 1e-6 && (g.area - 4.4).abs() < 1e-6,
        "{g:?}"
    );
}
