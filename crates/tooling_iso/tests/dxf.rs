//! DXF profiles: round trip, an R12 and a 2000 (AC1015) text fixture, bad files.

use geom::arc::Arc;
use geom::distance::EdgeIndex;
use geom::ring::signed_area;
use geom::Pt;
use std::f64::consts::PI;
use tooling_iso::dxf_io::{read_profile_str, write_section_string, ReadOptions, XMode};
use tooling_iso::IsoError;

/// Directed distance sup over `a`'s edges (sampled every `h`) of the distance to `b`.
fn directed(a: &[Pt], b: &EdgeIndex, h: f64) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..a.len() {
        let (p, q) = (a[i], a[(i + 1) % a.len()]);
        let n = (p.dist(q) / h).ceil().max(1.0) as usize;
        for k in 0..=n {
            let (d, _) = b.nearest(p.lerp(q, k as f64 / n as f64)).unwrap();
            worst = worst.max(d);
        }
    }
    worst
}

fn hausdorff(a: &[Pt], b: &[Pt]) -> f64 {
    let (ia, ib) = (EdgeIndex::of_rings([a]), EdgeIndex::of_rings([b]));
    directed(a, &ib, 0.01).max(directed(b, &ia, 0.01))
}

/// A turned part's half section with a convex and a concave arc: chamfer-free shaft Ø40
/// (r 20) with an R5 shoulder fillet and an R8 bulge, chorded at `tol`.
fn part(tol: f64) -> Vec<Pt> {
    let mut ring = vec![Pt::new(0.0, 0.0), Pt::new(0.0, 10.0)];
    // convex R5 corner from (0, 10) round to (-5, 15), centre (-5, 10), counter-clockwise
    ring.extend(
        Arc::between(
            Pt::new(0.0, 10.0),
            Pt::new(-5.0, 15.0),
            Pt::new(-5.0, 10.0),
            true,
        )
        .flatten(tol)
        .into_iter()
        .skip(1),
    );
    // concave R8 groove from (-12, 15) to (-28, 15), centre (-20, 15), clockwise dips down
    ring.push(Pt::new(-12.0, 15.0));
    ring.extend(
        Arc::between(
            Pt::new(-12.0, 15.0),
            Pt::new(-28.0, 15.0),
            Pt::new(-20.0, 15.0),
            false,
        )
        .flatten(tol)
        .into_iter()
        .skip(1),
    );
    ring.extend([
        Pt::new(-40.0, 15.0),
        Pt::new(-40.0, 20.0),
        Pt::new(-60.0, 20.0),
        Pt::new(-60.0, 0.0),
    ]);
    ring
}

#[test]
fn round_trip_with_arcs_is_within_half_a_micron() {
    let exact = part(1e-7);
    let written = part(0.0002);
    let intended = vec![
        Pt::new(0.0, 0.0),
        Pt::new(0.0, 9.0),
        Pt::new(-60.0, 9.0),
        Pt::new(-60.0, 0.0),
    ];
    for mode in [XMode::Radius, XMode::Diameter] {
        let text = write_section_string(
            std::slice::from_ref(&written),
            Some(std::slice::from_ref(&intended)),
            mode,
        )
        .unwrap();
        assert!(text.contains("LWPOLYLINE") && text.contains("PART") && text.contains("INTENDED"));
        assert!(text.contains("AC1015"), "`AutoCAD` 2000 header");
        let opt = ReadOptions {
            x_mode: mode,
            layer: Some("PART"),
            ..Default::default()
        };
        let back = read_profile_str(&text, &opt).unwrap();
        assert_eq!(back.len(), 1);
        let h = hausdorff(&back[0], &exact);
        assert!(h <= 0.0005, "{mode:?}: Hausdorff {h}");
        let opt = ReadOptions {
            x_mode: mode,
            layer: Some("INTENDED"),
            ..Default::default()
        };
        let back = read_profile_str(&text, &opt).unwrap();
        assert!(hausdorff(&back[0], &intended) < 1e-9);
        // every layer: two rings
        let all = read_profile_str(
            &text,
            &ReadOptions {
                x_mode: mode,
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(all.len(), 2);
    }
}

/// An R12 file as an old CAD program saves it: header with $ACADVER AC1009, LINEs, an ARC
/// and a POLYLINE/VERTEX/SEQEND with no bulge. The outline (drawing X = Z, Y = radius):
/// (0,0) up to (0,10), R5 arc centre (-5,10) from 0° to 90° to (-5,15), line to (-30,15),
/// polyline down to (-30,0) and back to (0,0).
const R12: &str = "  0
SECTION
  2
HEADER
  9
$ACADVER
  1
AC1009
  0
ENDSEC
  0
SECTION
  2
ENTITIES
  0
LINE
  8
0
 10
0.0
 20
0.0
 30
0.0
 11
0.0
 21
10.0
 31
0.0
  0
ARC
  8
0
 10
-5.0
 20
10.0
 30
0.0
 40
5.0
 50
0.0
 51
90.0
  0
LINE
  8
0
 10
-30.0
 20
15.0
 30
0.0
 11
-5.0
 21
15.0
 31
0.0
  0
POLYLINE
  8
0
 66
1
 10
0.0
 20
0.0
 30
0.0
 70
0
  0
VERTEX
  8
0
 10
-30.0
 20
15.0
 30
0.0
  0
VERTEX
  8
0
 10
-30.0
 20
0.0
 30
0.0
  0
VERTEX
  8
0
 10
0.0
 20
0.0
 30
0.0
  0
SEQEND
  8
0
  0
ENDSEC
  0
EOF
";

#[test]
fn r12_file_reads() {
    let rings = read_profile_str(R12, &ReadOptions::default()).unwrap();
    assert_eq!(rings.len(), 1);
    // 30 × 15 less the corner square outside the quarter disc: 450 − (25 − 25π/4)
    let want = 450.0 - (25.0 - 25.0 * PI / 4.0);
    let a = signed_area(&rings[0]);
    assert!((a - want).abs() < 0.01, "area {a} want {want}");
    assert!(rings[0]
        .iter()
        .all(|p| p.z >= -30.0 - 1e-9 && p.r <= 15.0 + 1e-9));
}

/// An `AutoCAD` 2000 (AC1015) file: a closed LWPOLYLINE with a bulge of 1 (a half circle
/// counter-clockwise from (0,20) to (-10,20), bulging up to Y 25), Y as diameter.
const ACAD2000: &str = "0
SECTION
2
HEADER
9
$ACADVER
1
AC1015
9
$INSUNITS
70
4
0
ENDSEC
0
SECTION
2
ENTITIES
0
LWPOLYLINE
5
2F
100
AcDbEntity
8
PROFILE
100
AcDbPolyline
90
4
70
1
10
0.0
20
0.0
10
0.0
20
20.0
42
1.0
10
-10.0
20
20.0
10
-10.0
20
0.0
0
ENDSEC
0
EOF
";

#[test]
fn acad2000_file_reads_with_diameter_y() {
    let opt = ReadOptions {
        x_mode: XMode::Diameter,
        ..Default::default()
    };
    let rings = read_profile_str(ACAD2000, &opt).unwrap();
    assert_eq!(rings.len(), 1);
    // drawing area 10 × 20 + half disc r 5; diameter Y halves every area
    let want = (200.0 + 12.5 * PI) / 2.0;
    let a = signed_area(&rings[0]);
    assert!((a - want).abs() < 0.01, "area {a} want {want}");
    let top = rings[0].iter().map(|p| p.r).fold(0.0, f64::max);
    assert!((top - 12.5).abs() <= 0.0001, "{top}");
    // the layer filter
    let opt = ReadOptions {
        layer: Some("PART"),
        ..Default::default()
    };
    assert!(matches!(
        read_profile_str(ACAD2000, &opt),
        Err(IsoError::Dxf(_))
    ));
}

fn lwpolyline(pts: &[(f64, f64)], closed: bool) -> String {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n");
    s += &format!("90\n{}\n70\n{}\n", pts.len(), i32::from(closed));
    for (x, y) in pts {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s + "0\nENDSEC\n0\nEOF\n"
}

#[test]
fn bad_outlines_are_clear_errors() {
    let o = ReadOptions::default();
    // open: the polyline is not closed
    let open = lwpolyline(&[(0.0, 0.0), (0.0, 10.0), (-10.0, 10.0)], false);
    let e = read_profile_str(&open, &o).unwrap_err();
    assert!(matches!(e, IsoError::Open { .. }), "{e}");
    assert!(e.to_string().contains("open"), "{e}");
    // a bow tie crosses itself at (5, 5)
    let bow = lwpolyline(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)], true);
    match read_profile_str(&bow, &o) {
        Err(IsoError::SelfIntersecting { x, y }) => {
            assert!((x - 5.0).abs() < 1e-9 && (y - 5.0).abs() < 1e-9)
        }
        other => panic!("{other:?}"),
    }
    // not DXF at all, and DXF without outlines
    assert!(matches!(
        read_profile_str("hello\nworld\n", &o),
        Err(IsoError::Dxf(_))
    ));
    let empty = "0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n";
    let e = read_profile_str(empty, &o).unwrap_err().to_string();
    assert!(e.contains("no LINE"), "{e}");
}

#[test]
fn files_write_and_read() {
    let ring = vec![
        Pt::new(0.0, 0.0),
        Pt::new(0.0, 10.0),
        Pt::new(-20.0, 10.0),
        Pt::new(-20.0, 0.0),
    ];
    let path = std::env::temp_dir().join(format!("tooling_iso_{}.dxf", std::process::id()));
    tooling_iso::dxf_io::write_section_file(
        &path,
        std::slice::from_ref(&ring),
        None,
        XMode::Diameter,
    )
    .unwrap();
    let opt = ReadOptions {
        x_mode: XMode::Diameter,
        ..Default::default()
    };
    let back = tooling_iso::dxf_io::read_profile_file(&path, &opt).unwrap();
    std::fs::remove_file(&path).ok();
    assert!((signed_area(&back[0]) - 200.0).abs() < 1e-9);
    let e = tooling_iso::dxf_io::read_profile_file("/nonexistent/x.dxf", &opt).unwrap_err();
    assert!(e.to_string().contains("/nonexistent/x.dxf"), "{e}");
}
