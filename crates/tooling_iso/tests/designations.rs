//! ISO insert and holder designations against hand values.
//!
//! Edge lengths: l from the inscribed circle d by the shape's geometry (rhombic l = d/sin ε,
//! triangle l = √3·d, trigon l = d/2·(cot 40° + cot 80°)), computed by hand below and
//! checked against the rounded l of the makers' ISO tables (Sandvik/Sumitomo catalogue
//! "insert size" tables: CNMG 12 → d 12.70 l 12.9; DNMG 15 → 12.70/15.5; VBMT 16 →
//! 9.525/16.6; TNMG 16 → 9.525/16.5; WNMG 08 → 12.70/8.7; CCMT 09 → 9.525/9.7; DCMT 11 →
//! 9.525/11.6; TPUN 11 → 6.35/11.0; CCGT 06 → 6.35/6.4). Thicknesses: ISO 1832 codes
//! 02 2.38, 03 3.18, T3 3.97, 04 4.76, 06 6.35. Inch: size 1/8", thickness 1/16", nose 1/64"
//! (vertexdiamondtool.com insert chart; denitool.com ISO 1832 page for the metric codes).

use tooling_iso::holder::Shank;
use tooling_iso::insert::Units;
use tooling_iso::{turning_facts_from, Hand, Holder, Insert, IsoError, Shape};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// (designation, shape, ε, edge l, IC d, thickness, nose r, clearance °)
#[allow(clippy::type_complexity)]
const INSERTS: [(&str, Shape, f64, f64, f64, f64, f64, f64); 18] = [
    // 12.7 / sin 80° = 12.896; 04 → 4.76; 08 → 0.8; N 0°
    ("CNMG 120408", Shape::C, 80.0, 12.896, 12.7, 4.76, 0.8, 0.0),
    // same, no space, lower case
    ("cnmg120408", Shape::C, 80.0, 12.896, 12.7, 4.76, 0.8, 0.0),
    // inch: 4/8" = 12.7; 3/16" = 4.7625; 2/64" = 0.79375
    (
        "CNMG 432",
        Shape::C,
        80.0,
        12.896,
        12.7,
        4.7625,
        0.79375,
        0.0,
    ),
    // 12.7 / sin 55° = 15.504; 06 → 6.35
    ("DNMG 150608", Shape::D, 55.0, 15.504, 12.7, 6.35, 0.8, 0.0),
    // 9.525 / sin 35° = 16.606; B 5°
    ("VBMT 160404", Shape::V, 35.0, 16.606, 9.525, 4.76, 0.4, 5.0),
    ("VNMG 160404", Shape::V, 35.0, 16.606, 9.525, 4.76, 0.4, 0.0),
    // √3 · 9.525 = 16.498
    ("TNMG 160408", Shape::T, 60.0, 16.498, 9.525, 4.76, 0.8, 0.0),
    // square: l = d
    ("SNMG 120408", Shape::S, 90.0, 12.7, 12.7, 4.76, 0.8, 0.0),
    // 6.35 · (cot 40° + cot 80°) = 6.35 · 1.36808 = 8.687
    ("WNMG 080408", Shape::W, 80.0, 8.687, 12.7, 4.76, 0.8, 0.0),
    // 9.525 / sin 80° = 9.672; T3 → 3.97; C 7°
    ("CCMT 09T304", Shape::C, 80.0, 9.672, 9.525, 3.97, 0.4, 7.0),
    // 9.525 / sin 55° = 11.628
    ("DCMT 11T304", Shape::D, 55.0, 11.628, 9.525, 3.97, 0.4, 7.0),
    // round Ø12, M0 no corner
    ("RCMT 1204M0", Shape::R, 360.0, 12.0, 12.0, 4.76, 0.0, 7.0),
    // √3 · 6.35 = 10.999 (listed 11.0); 03 → 3.18; P 11°
    ("TPUN 110304", Shape::T, 60.0, 10.999, 6.35, 3.18, 0.4, 11.0),
    // 6.35 / sin 80° = 6.448; 02 → 2.38, r 0.2
    ("CCGT 060202", Shape::C, 80.0, 6.448, 6.35, 2.38, 0.2, 7.0),
    // inch D: 4/8" → 15.504; 4/16" = 6.35; 2/64"
    ("DNMG 442", Shape::D, 55.0, 15.504, 12.7, 6.35, 0.79375, 0.0),
    // inch V: 3/8" = 9.525; 3/16"; 1/64" = 0.396875
    (
        "VNMG 331",
        Shape::V,
        35.0,
        16.606,
        9.525,
        4.7625,
        0.396875,
        0.0,
    ),
    // inch with a half: 3/8", 2.5/16" = 3.96875, 1/64"
    (
        "CCMT 32.51",
        Shape::C,
        80.0,
        9.672,
        9.525,
        3.96875,
        0.396875,
        7.0,
    ),
    // a maker's chip breaker after the nose code; 15.875 / sin 80° = 16.120; 12 → 1.2
    (
        "CNMG 160612-PM",
        Shape::C,
        80.0,
        16.120,
        15.875,
        6.35,
        1.2,
        0.0,
    ),
];

#[test]
fn insert_table() {
    for (d, shape, eps, l, ic, th, r, clear) in INSERTS {
        let i = Insert::parse(d).unwrap_or_else(|e| panic!("{d}: {e}"));
        assert_eq!(i.shape, shape, "{d}");
        assert_eq!(i.included_angle(), eps, "{d}");
        assert!(close(i.edge_length, l, 0.001), "{d}: l {}", i.edge_length);
        assert!(
            close(i.inscribed_circle.unwrap(), ic, 1e-9),
            "{d}: d {:?}",
            i.inscribed_circle
        );
        assert!(close(i.thickness, th, 1e-9), "{d}: s {}", i.thickness);
        assert!(close(i.nose_radius, r, 1e-9), "{d}: r {}", i.nose_radius);
        assert_eq!(i.clearance_angle, Some(clear), "{d}");
    }
    let i = Insert::parse("CNMG 120408-PM").unwrap();
    assert_eq!(
        (i.tolerance, i.kind, i.suffix.as_str(), i.units),
        ('M', 'G', "PM", Units::Metric)
    );
    assert_eq!(Insert::parse("CNMG 432").unwrap().units, Units::Inch);
    assert_eq!(Insert::parse("CNMG 120400").unwrap().nose_radius, 0.0);
}

#[test]
fn bad_inserts_say_what_and_the_expected_form() {
    let cases = [
        ("XNMG 120408", "'X' is not an ISO shape letter"),
        ("CNMG 120405", "nose radius code \"05\" does not exist"),
        ("CNMG 12040", "metric needs 6"),
        ("CNMG", "too short"),
        ("CZMG 120408", "'Z' is not a clearance letter"),
        ("CNZG 120408", "'Z' is not a tolerance class"),
        ("CNMZ 120408", "'Z' is not a type letter"),
        ("CNMG 435", "inch nose radius code \"5\" does not exist"),
        ("CNMG 12T908", "thickness code \"T9\" does not exist"),
    ];
    for (d, want) in cases {
        match Insert::parse(d) {
            Err(e @ IsoError::Insert { .. }) => {
                let msg = e.to_string();
                assert!(msg.contains(want), "{d}: {msg}");
                assert!(msg.contains("\"CNMG 120408\""), "{d}: {msg}");
            }
            other => panic!("{d}: {other:?}"),
        }
    }
}

/// (designation, shape, style, κr, hand, shank h, b, length, size)
#[allow(clippy::type_complexity)]
const HOLDERS: [(&str, Shape, char, f64, Hand, f64, f64, Option<f64>, u32); 14] = [
    // P lever, C 80°, L 95°, N 0°, right; 25 × 25; M 150; edge 12
    (
        "PCLNR 2525M12",
        Shape::C,
        'L',
        95.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        12,
    ),
    // J 93°, B 5° insert
    (
        "SVJBR 2525M16",
        Shape::V,
        'J',
        93.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        16,
    ),
    // left hand; K 125
    (
        "DDJNL 2020K15",
        Shape::D,
        'J',
        93.0,
        Hand::L,
        20.0,
        20.0,
        Some(125.0),
        15,
    ),
    (
        "MWLNR 2525M08",
        Shape::W,
        'L',
        95.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        8,
    ),
    (
        "PCLNL 2020K12",
        Shape::C,
        'L',
        95.0,
        Hand::L,
        20.0,
        20.0,
        Some(125.0),
        12,
    ),
    // 32 × 32, P 170
    (
        "DCLNR 3232P16",
        Shape::C,
        'L',
        95.0,
        Hand::R,
        32.0,
        32.0,
        Some(170.0),
        16,
    ),
    // V 72.5°, neutral
    (
        "SVVBN 2525M16",
        Shape::V,
        'V',
        72.5,
        Hand::N,
        25.0,
        25.0,
        Some(150.0),
        16,
    ),
    // S 45°
    (
        "PSSNR 2525M12",
        Shape::S,
        'S',
        45.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        12,
    ),
    // G 90° offset
    (
        "PTGNR 2525M16",
        Shape::T,
        'G',
        90.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        16,
    ),
    // B 75°
    (
        "PCBNR 2525M12",
        Shape::C,
        'B',
        75.0,
        Hand::R,
        25.0,
        25.0,
        Some(150.0),
        12,
    ),
    // D 45° neutral
    (
        "PSDNN 2525M12",
        Shape::S,
        'D',
        45.0,
        Hand::N,
        25.0,
        25.0,
        Some(150.0),
        12,
    ),
    // N 63°, C 7°, 12 × 12, H 100
    (
        "SDNCN 1212H11",
        Shape::D,
        'N',
        63.0,
        Hand::N,
        12.0,
        12.0,
        Some(100.0),
        11,
    ),
    // Q 107.5°, R 200
    (
        "PDQNR 2525R15",
        Shape::D,
        'Q',
        107.5,
        Hand::R,
        25.0,
        25.0,
        Some(200.0),
        15,
    ),
    // A 90°; "-": ISO 5610 preferred length
    (
        "PTANR 2020-16",
        Shape::T,
        'A',
        90.0,
        Hand::R,
        20.0,
        20.0,
        None,
        16,
    ),
];

#[test]
fn holder_table() {
    for (d, shape, style, kr, hand, h, b, len, size) in HOLDERS {
        let x = Holder::parse(d).unwrap_or_else(|e| panic!("{d}: {e}"));
        assert_eq!(x.shape, shape, "{d}");
        assert_eq!(x.style.letter, style, "{d}");
        assert_eq!(x.style.entering_angle, kr, "{d}");
        assert_eq!(x.style.lead_angle(), 90.0 - kr, "{d}");
        assert_eq!(x.hand, hand, "{d}");
        assert_eq!(
            x.shank,
            Shank::Square {
                height: h,
                width: b
            },
            "{d}"
        );
        assert_eq!(x.length, len, "{d}");
        assert_eq!(x.insert_size, size, "{d}");
    }
    // end-cutting styles
    assert!(Holder::parse("PTFNR 2525M16").unwrap().style.end_cutting);
    assert!(Holder::parse("PCKNR 2525M12").unwrap().style.end_cutting);
    // boring bars: S steel Ø20, R 200; A with coolant Ø32, S 250
    let b = Holder::parse("S20R-SCLCR09").unwrap();
    assert_eq!(
        (
            b.shank,
            b.length,
            b.style.entering_angle,
            b.hand,
            b.insert_size
        ),
        (
            Shank::Bar {
                diameter: 20.0,
                kind: 'S'
            },
            Some(200.0),
            95.0,
            Hand::R,
            9
        )
    );
    let b = Holder::parse("a32s-pdunl15").unwrap_err().to_string();
    assert!(b.contains("'U' is not a holder style"), "{b}");
    let b = Holder::parse("A32S-PDJNL15").unwrap();
    assert_eq!(b.length, Some(250.0));
    assert!(b.is_internal());
}

#[test]
fn bad_holders() {
    let cases = [
        ("PCZNR 2525M12", "'Z' is not a holder style letter"),
        ("PCLNX 2525M12", "'X' is not a hand"),
        ("PCLNR 2525Z12", "'Z' is not a length letter"),
        ("PCLNR 252M12", "too short"),
        ("XCLNR 2525M12", "'X' is not a clamping letter"),
        ("PCLNR 25A5M12", "shank height"),
        ("S20R SCLCR09", "boring bar reads"),
    ];
    for (d, want) in cases {
        let msg = Holder::parse(d).unwrap_err().to_string();
        assert!(msg.contains(want), "{d}: {msg}");
        assert!(msg.contains("\"PCLNR 2525M12\""), "{d}: {msg}");
    }
}

#[test]
fn inserts_in_holders() {
    // (insert, holder, ε, l, r, κr, hand, internal, tip)
    let cases = [
        (
            "CNMG 120408",
            "PCLNR 2525M12",
            80.0,
            12.896,
            0.8,
            95.0,
            Hand::R,
            false,
            3,
        ),
        (
            "CNMG 432",
            "PCLNR 2525M12",
            80.0,
            12.896,
            0.79375,
            95.0,
            Hand::R,
            false,
            3,
        ),
        (
            "VBMT 160404",
            "SVJBR 2525M16",
            35.0,
            16.606,
            0.4,
            93.0,
            Hand::R,
            false,
            3,
        ),
        (
            "DNMG 150608",
            "DDJNL 2020K15",
            55.0,
            15.504,
            0.8,
            93.0,
            Hand::L,
            false,
            4,
        ),
        (
            "WNMG 080408",
            "MWLNR 2525M08",
            80.0,
            8.687,
            0.8,
            95.0,
            Hand::R,
            false,
            3,
        ),
        (
            "CCMT 09T304",
            "S20R-SCLCR09",
            80.0,
            9.672,
            0.4,
            95.0,
            Hand::R,
            true,
            2,
        ),
        (
            "DNMG 150608",
            "A32S-PDJNL15",
            55.0,
            15.504,
            0.8,
            93.0,
            Hand::L,
            true,
            1,
        ),
        (
            "VBMT 160404",
            "SVVBN 2525M16",
            35.0,
            16.606,
            0.4,
            72.5,
            Hand::N,
            false,
            8,
        ),
    ];
    for (i, h, eps, l, r, kr, hand, internal, tip) in cases {
        let f = turning_facts_from(i, h).unwrap_or_else(|e| panic!("{i} {h}: {e}"));
        assert_eq!(f.included_angle, eps, "{i} {h}");
        assert!(close(f.edge_length, l, 0.001), "{i} {h}");
        assert!(close(f.nose_radius, r, 1e-9), "{i} {h}");
        assert_eq!(
            (f.entering_angle, f.hand, f.internal, f.tip),
            (kr, hand, internal, tip),
            "{i} {h}"
        );
    }
    let f = turning_facts_from("CNMG 120408", "PCLNR 2525M12").unwrap();
    assert_eq!(
        (f.shank, f.length),
        (
            Shank::Square {
                height: 25.0,
                width: 25.0
            },
            Some(150.0)
        )
    );

    let bad = [
        // a C insert in a V holder: both named
        ("CNMG 120408", "SVJBR 2525M16", "shape C (rhombic 80°)"),
        ("VNMG 160404", "SVJBR 2525M16", "clearance letter N"),
        ("CNMG 160612", "PCLNR 2525M12", "size 16"),
        // Q 107.5° + 80° ≥ 180°
        ("CNMG 120408", "PCQNR 2525M12", "no clearance"),
    ];
    for (i, h, want) in bad {
        let msg = turning_facts_from(i, h).unwrap_err().to_string();
        assert!(
            msg.contains(want) && msg.contains(i) && msg.contains(h),
            "{i} {h}: {msg}"
        );
    }
    let msg = turning_facts_from("CNMG 120408", "SVJBR 2525M16")
        .unwrap_err()
        .to_string();
    assert!(msg.contains("shape V"), "{msg}");
}
