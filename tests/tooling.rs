//! Tools as machinists name them (issue 15): an ISO insert in an ISO holder cuts exactly
//! like the same tool written in the explicit fields.

mod common;
use common::*;

fn report(tools: &str) -> serde_json::Value {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
        "--stock",
        "36x40",
        "--tools",
        asset(tools).to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap()
}

#[test]
fn cnmg_in_pclnr_cuts_seed_004_like_the_explicit_tool() {
    let mut iso = report("tools/cnmg-pclnr.toml");
    let mut explicit = report("tools/c80-r08-95.toml");
    // the report names the designation; everything else is the same, number for number
    let tools = iso["tools"][0].as_str().unwrap().to_string();
    assert!(tools.contains("(CNMG 120408 in PCLNR 2525M12)"), "{tools}");
    assert!(tools.contains("C 80°, r0.8, tip 3, κr 95°"), "{tools}");
    iso["tools"] = serde_json::Value::Null;
    explicit["tools"] = serde_json::Value::Null;
    iso["program"] = serde_json::Value::Null;
    explicit["program"] = serde_json::Value::Null;
    assert_eq!(iso, explicit);
    assert!(iso["removed_area_mm2"].as_f64().unwrap() > 50.0);
}

/// Field run 3 (a public bush whose setup sheet names PCLNL and SVJBL holders): a left-hand
/// holder gives tip 4, toward the tailstock, but the holder cuts toward the chuck mounted
/// upside down or behind the centre line with M04, and the tip is the program's. A G71/G70
/// that feeds it toward the chuck made 8 certain crashes; the tip is now read from the
/// program (3), with a warning LS-HOLDER-HAND at its first feed that way: CLEAN, as with
/// `tip = 3` stated. A stated `tip = 4` is kept (the crashes stay), and a right-hand holder
/// fed toward the chuck gets no warning.
#[test]
fn a_left_hand_holder_fed_toward_the_chuck_is_read_as_tip_3() {
    let program = "O0116\nG21 G40 G99 G18\nT0101\nG96 S200 M03\nG50 S3000\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20.\nX30.\nZ-35.\nN20 X42.\nG70 P10 Q20 F0.1\nG28 U0. W0.\nM30\n";
    let (dir, path) = temp_program("lh.nc", program.as_bytes());
    let run = |holder: &str, tip: &str| {
        let table = dir.path().join("tools.toml");
        let entry = format!(
            "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"{holder}\"\n{tip}"
        );
        std::fs::write(&table, entry).unwrap();
        let json = dir.path().join("r.json");
        let out = latsim(&[
            "run",
            path.to_str().unwrap(),
            "--control",
            "fanuc-a",
            "--stock",
            "40x60",
            "--tools",
            table.to_str().unwrap(),
            "--json",
            json.to_str().unwrap(),
        ]);
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap();
        let hand: Vec<serde_json::Value> = v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|w| w["code"] == "LS-HOLDER-HAND")
            .cloned()
            .collect();
        (out.code, v["verdict"].clone(), hand)
    };
    let (code, verdict, hand) = run("PCLNL 2525M12", "");
    assert_eq!((code, verdict.as_str()), (0, Some("clean")), "{hand:?}");
    assert_eq!(hand.len(), 1);
    assert_eq!(hand[0]["line"], 8);
    let message = hand[0]["message"].as_str().unwrap();
    assert!(message.contains("read as tip 3"), "{message}");
    let (code, verdict, hand) = run("PCLNL 2525M12", "tip = 4\n");
    assert_eq!((code, verdict.as_str()), (1, Some("crash")));
    assert!(hand.is_empty());
    let (code, verdict, hand) = run("PCLNR 2525M12", "");
    assert_eq!((code, verdict.as_str()), (0, Some("clean")));
    assert!(hand.is_empty());
}

/// `latsim check` and `latsim expand` read a holder's tip from the program's feeds as `run`
/// does: a left-hand holder fed toward the chuck under G42 expands as with `tip = 3`
/// stated (its nose compensated to that side), not as the hand's tip 4, and `check` warns
/// LS-HOLDER-HAND as `run` does.
#[test]
fn check_and_expand_read_the_holders_tip_as_run_does() {
    let program = "O0117\nG21 G40 G99 G18\nT0101\nG96 S200 M03\nG50 S3000\nG00 X42. Z2.\nG42 G00 X20. Z2.\nG01 Z-20. F0.1\nX30.\nZ-35.\nX42.\nG40 G00 X45. Z2.\nM30\n";
    let (dir, path) = temp_program("lh-g42.nc", program.as_bytes());
    let with = |tip: &str| {
        let table = dir.path().join(format!("tools{}.toml", tip.len()));
        let entry = format!(
            "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNL 2525M12\"\n{tip}"
        );
        std::fs::write(&table, entry).unwrap();
        let (p, t) = (path.to_str().unwrap(), table.to_str().unwrap());
        let expand = latsim(&[
            "expand",
            p,
            "--control",
            "fanuc-a",
            "--tools",
            t,
            "--format",
            "json",
        ]);
        let check = latsim(&["check", p, "--control", "fanuc-a", "--tools", t]);
        (expand.stdout, check)
    };
    let (read, check) = with("");
    let (stated_3, _) = with("tip = 3\n");
    let (stated_4, check_4) = with("tip = 4\n");
    assert_eq!(read, stated_3);
    assert_ne!(
        read, stated_4,
        "tip 4 compensates the nose to the other side"
    );
    assert_eq!(check.code, 0, "{}", check.stderr);
    assert!(check.stderr.contains("LS-HOLDER-HAND"), "{}", check.stderr);
    assert!(
        !check_4.stderr.contains("LS-HOLDER-HAND"),
        "{}",
        check_4.stderr
    );
}

/// A program with no tool table, run as `run` runs it, and its JSON.
fn run_without_table(program: &str) -> serde_json::Value {
    run_with(program, None, &["--stock", "40x60"])
}

/// A program on the blank `stock` (`--stock` and such) with the tool table `table` (none:
/// no table), and its JSON; the run must pass.
fn run_with(program: &str, table: Option<&str>, stock: &[&str]) -> serde_json::Value {
    let (out, json) = run_json_with(program, table, stock);
    assert_eq!(out.code, 0, "{}", out.stderr);
    json
}

/// [`run_with`], whatever the run's exit: its output and its JSON.
fn run_json_with(program: &str, table: Option<&str>, stock: &[&str]) -> (Out, serde_json::Value) {
    let (dir, path) = temp_program("drill.nc", program.as_bytes());
    let json = dir.path().join("r.json");
    let tools = dir.path().join("tools.toml");
    let mut args = vec![
        "run",
        path.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ];
    args.extend(stock);
    if let Some(table) = table {
        std::fs::write(&tools, table).unwrap();
        args.extend(["--tools", tools.to_str().unwrap()]);
    }
    let out = latsim(&args);
    let json = serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap();
    (out, json)
}

/// Field run 3 (D): a tool with no entry that only feeds along the axis at X0 is taken for
/// a drill, Ø10 with a 118° point, its size assumed (docs/field-rules.md §17). Drilled to
/// Z-20 by its tip, by G01 or by a G74 peck cycle, it leaves the same hole: Ø10 over
/// Z0 … Z-16.996 and the point's cone, 3.004 long (5 / tan 59°), in the half section
/// 5 · 16.996 + 5 · 3.004 / 2 = 92.49 mm². The default 55° insert plunged there with its
/// edge across the face, and the default G74 blade, standing 20 mm along X, hollowed the
/// whole section as it pecked (400 mm²).
#[test]
fn a_tool_that_only_feeds_along_the_axis_is_a_drill() {
    let g01 =
        "O0201\nG21 G99\nT0303 (DRILL)\nG97 S1200 M03\nG00 X0. Z3.\nG01 Z-20. F0.1\nG00 Z5.\nM30\n";
    let g74 = "O0202\nG21 G99\nT0303 (DRILL)\nG97 S1200 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-20. Q5000 F0.1\nG00 Z5.\nM30\n";
    let hand = 5.0 * (20.0 - 5.0 / 59f64.to_radians().tan()) + 2.5 * 5.0 / 59f64.to_radians().tan();
    for program in [g01, g74] {
        let v = run_without_table(program);
        let area = removed(&v);
        assert!((area - hand).abs() < 0.01, "{area} vs {hand}");
        let notes = warning_messages(&v, "LS-STOCK");
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].contains("T03") && notes[0].contains("taken for a drill"),
            "{notes:?}"
        );
    }
}

/// Field run 6 (E), a sleeve with no tool table: T02 turns the OD under G42, T03 drills
/// (taken for the Ø10 drill), T04 roughs the bore, pulls out along X19 and finishes it
/// under G41. T04 finishes nothing but a bore, so it is a boring bar (tip 2) by its moves,
/// as a G70 bore's tool is; taken for the OD default, its contour was read against the
/// stock the OD insert left and its rapid out of the bore was a certain 0.39 mm gouge
/// (0.8 mm in the full CAM program), from two assumed tools. The part is the one the same
/// program cuts with T04 stated as that boring bar.
#[test]
fn a_tool_that_finishes_a_bore_under_g41_is_a_boring_bar() {
    let program = "O1004 (SLEEVE)\nG21 G99 G40\nT0202 (OD FINISH)\nG96 S250 M03\nG0 X20. Z3.\nG1 G42 X20. Z1. F.1\nZ-15.\nX28.\nZ-25.\nX32.\nG40 G0 X34.\nZ3.\nT0303 (DRILL 20.)\nG97 S800 M03\nG0 X0. Z5.\nG83 Z-30. Q8000 F.1\nG80\nT0404 (BORING BAR)\nG96 S150 M03\nG0 X23.6 Z3.\nG1 Z-26. F.15\nX19.\nG0 Z3.\nX22. Z3.\nG1 G41 X24. Z1. F.08\nZ-26.\nX19.6\nG40 G0 Z3.\nG0 X100. Z100.\nM30\n";
    let guessed = run_with(program, None, &["--stock", "30x60"]);
    assert_eq!(guessed["verdict"], "clean", "{:#}", guessed["gouges"]);
    let gouges = guessed["gouges"].as_array().unwrap();
    assert!(
        gouges.iter().all(|g| g["assumed_tool"] == true),
        "{gouges:#?}"
    );
    assert_stock_note(&guessed, "T04", "boring bar");
    let bar = "[[tool]]\nt = 4\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 2\n";
    let stated = run_with(program, Some(bar), &["--stock", "30x60"]);
    assert_removed_alike(&guessed, &stated, 1e-6);
}

/// Field run 6 (C): a tool with no entry that drills off the axis in a drilling cycle with
/// the spindle turning (an offset indexable drill, docs/field-rules.md §19) is taken for
/// the Ø10 drill too, at its offset: the hole about the axis is Ø12 (the drill's edge at
/// 1 + 5), and its bottom the point's cone swept about the axis, deepest (Z-25) at the
/// drill's centre, 1 mm off the axis. In the half section, with the cone's slope
/// 1/tan 59°: 25 · 6 − (0.5 + 12.5) / tan 59° = 142.19 mm². Taken for the 55° insert, its
/// edges swept a cone Ø34 deep into the face (378.6 mm² of possible gouge).
#[test]
fn an_offset_drill_with_no_entry_is_a_drill() {
    let program = "O0905 (U-DRILL OFFSET X2.)\nG21 G99 G40\nT0505\nG97 S1200 M03\nG0 X2. Z5.\nG83 Z-25. F.08\nG80\nG0 X100. Z100.\nM30\n";
    let v = run_with(program, None, &["--stock", "50x60"]);
    let slope = 1.0 / 59f64.to_radians().tan();
    let hand = 25.0 * 6.0 - (0.5 + 12.5) * slope;
    let area = removed(&v);
    assert!((area - hand).abs() < 0.01, "{area} vs {hand}");
    assert_stock_note(&v, "T05", "taken for a drill");
    assert!(
        v["gouges"].as_array().unwrap().is_empty(),
        "{:#}",
        v["gouges"]
    );
}

/// Field run 6 (G), a nut with no tool table: T03 bores a tube by hand (no cycle, no
/// compensation), each pass along Z left toward the axis, as a boring bar leaves the wall;
/// T05 threads it inside. T03 is a boring bar by its moves: taken for the OD default, it
/// cut the whole wall away (178 mm² removed instead of 48), and the thread, cut in the air,
/// had no achieved X, pitch diameter nor angle. The part is the one the same program cuts
/// with T03 stated as that boring bar, and the thread measures 60°.
#[test]
fn a_tool_that_bores_by_hand_is_a_boring_bar() {
    let program = "O8000 (NUT M24X1.5)\nG21 G18 G40 G99\nT0303 (BORING BAR)\nG96 S150 M03\nG00 X20. Z2.\nG01 Z-20. F0.15\nX19.\nG00 Z2.\nX22.4\nG01 Z0. F0.1\nZ-20.\nX19.\nG00 Z2.\nG28 U0. W0.\nT0505 (ID THREAD 1.5)\nG97 S600 M03\nG00 X21. Z4.\nG76 P010060 Q50 R0.02\nG76 X24. Z-18. P920 Q250 F1.5\nG00 Z5.\nG28 U0. W0.\nM30\n";
    let blank = ["--stock", "36x30", "--bore", "18"];
    let guessed = run_with(program, None, &blank);
    assert_stock_note(&guessed, "T03", "boring bar");
    let thread = &guessed["threads"][0];
    assert_eq!(thread["side"], "id", "{thread:#}");
    let angle = thread["included_angle_deg"].as_f64().unwrap();
    assert!((angle - 60.0).abs() < 0.01, "{thread:#}");
    assert!(
        (thread["achieved_x"].as_f64().unwrap() - 24.0).abs() < 2e-3,
        "{thread:#}"
    );
    let bar = "[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 2\n";
    let stated = run_with(program, Some(bar), &blank);
    assert_removed_alike(&guessed, &stated, 1e-6);
}

/// Field run 7 (D): a tool with no entry that only plunges is a grooving blade (the
/// default 3 mm one, referenced at its corner toward −Z), its body away from the side it
/// plunges from: into the wall from a Φ20 bore, an ID blade. Taken for the 55° OD default,
/// its rapid into the bore swept the wall and the OD contour's finished diameter: a certain
/// 6.5 mm gouge of 192 mm². The groove is 3 wide (Z-15 … -12) from r10 to r13: 9 mm² more
/// than the same program without it.
#[test]
fn a_tool_that_only_plunges_is_a_blade_on_its_side() {
    let od = "O7001 (ID RELIEF GROOVE)\nG21 G40 G99\nT0101\nG96 S200 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X44.\nG01 Z0.\nX46. Z-1.\nN20 Z-32.\nG70 P10 Q20 F0.1\nG00 X100. Z50.\n";
    let groove =
        "T0505 (ID GROOVE)\nG97 S600 M03\nG00 X18. Z2.\nZ-15.\nG01 X26. F0.05\nG00 X18.\nZ50.\n";
    let blank = ["--stock", "50x40", "--bore", "20"];
    let with = run_with(&format!("{od}{groove}M30\n"), None, &blank);
    assert_eq!(with["verdict"], "clean", "{:#}", with["gouges"]);
    assert!(
        with["gouges"].as_array().unwrap().is_empty(),
        "{:#}",
        with["gouges"]
    );
    let notes = warning_messages(&with, "LS-STOCK");
    assert!(
        notes
            .iter()
            .any(|m| m.contains("T05") && m.contains("grooving blade") && m.contains("shank -x")),
        "{notes:?}"
    );
    let without = run_with(&format!("{od}M30\n"), None, &blank);
    let groove_area = removed(&with) - removed(&without);
    assert!((groove_area - 9.0).abs() < 1e-6, "{groove_area}");
}

/// Field run 7 (C): a flange faced by G72 with a hub, a CNMG in a PCLNR (no `tip` in the
/// table: the right-hand holder gives tip 3). The finishing pass steps up the hub along
/// +Z (7 mm) and feeds toward the chuck not at all; the holder-hand rule read that as a
/// tool fed the other way, tip 4, and the run had 7 holder crashes 13 mm deep and an 8 mm
/// gouge. A tool that faces more than it turns says nothing of the way it turns: tip 3, the
/// part the same program cuts with `tip = 3` stated, and no LS-HOLDER-HAND.
#[test]
fn a_g72_hub_step_does_not_turn_the_holders_hand() {
    let program = "O7007 (FLANGE WITH A HUB)\nG21 G40 G99\nT0101\nG96 S200 M03\nG00 X84. Z2.\nG72 W2. R0.5\nG72 P10 Q20 U0.2 W0.1 F0.25\nN10 G00 Z-8.\nG01 X80.\nX40.\nZ-1.\nX38. Z0.\nN20 X10.\nG70 P10 Q20 F0.1\nG00 X150. Z100.\nM30\n";
    let table = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let blank = ["--stock", "80x30", "--stock-z", "0.5"];
    let by_hand = run_with(program, Some(table), &blank);
    assert_eq!(by_hand["verdict"], "clean", "{:#}", by_hand["crashes"]);
    let hand_notes = warning_messages(&by_hand, "LS-HOLDER-HAND").len();
    assert_eq!(hand_notes, 0, "{:#}", by_hand["warnings"]);
    let stated = run_with(program, Some(&format!("{table}tip = 3\n")), &blank);
    assert_removed_alike(&by_hand, &stated, 1e-9);
}

/// A blade taken from its moves cuts as a blade everywhere (field run 7, p18 and B): a
/// thread relief plunged by a tool with no entry in a diameter another tool finished is
/// that operation's own cut (LS-LATER-CUT, no possible gouge), and a ring it parts off into
/// the hole a tool with no entry drilled falls (the next ring's rapid was a crash).
#[test]
fn a_blade_taken_from_its_moves_cuts_features_and_parts_off() {
    let relief = "O0018\nG99 G21 G40\nT0101 M03 S800\nG00 X42. Z2.\nG71 U2. R1.\nG71 P70 Q130 U0.5 W0.1 F0.25\nN70 G00 X18.\nG01 Z0. F0.1\nX20. Z-1.\nZ-15.\nX30. Z-25.\nZ-40.\nN130 X42.\nG70 P70 Q130\nG00 X200. Z100.\nT0202 M03 S400\nG00 X32. Z-15.\nX22.\nG01 X16. F0.05\nG00 X22.\nX200.\nZ100.\nM30\n";
    let v = run_with(relief, None, &["--stock", "40x60"]);
    assert!(
        v["gouges"].as_array().unwrap().is_empty(),
        "{:#}",
        v["gouges"]
    );
    let later = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "LS-LATER-CUT" && w["line"] == 19)
        .count();
    assert_eq!(later, 1, "{:#}", v["warnings"]);
    let rings = "O7005 (TWO RINGS)\nG21 G40 G99\nT0202\nG97 S900 M03\nG00 X0. Z5.\nG74 R0.5\nG74 Z-27. Q5000 F0.1\nG00 Z5.\nT0303\nG97 S500 M03\nG00 X34.\nZ-13.\nG01 X8. F0.05\nG00 X34.\nZ5.\nX20.\nZ-12.\nX34.\nZ-26.\nG01 X8. F0.05\nG00 X34.\nZ5.\nM30\n";
    let v = run_with(rings, None, &["--stock", "30x40"]);
    assert_eq!(v["verdict"], "clean", "{:#}", v["crashes"]);
}

/// Field run 8 (E): a bore turned by hand whose finishing pass is fed in along a 45°
/// chamfer is a boring bar too (the chamfer is part of the pass it leads into; its start
/// reached further out than the passes, so the tool stayed the 55° OD default: 708 mm²
/// removed instead of 394, and the ID thread measured nothing). The part is the one the
/// same program cuts entered straight.
#[test]
fn a_hand_bore_entered_along_a_chamfer_is_a_boring_bar() {
    let program = |entry: &str| {
        format!("O0004 (BORE BY HAND)\nG21 G40 G99\nT0303\nG97 S600 M03\nG00 X0. Z5.\nG83 Z-35. Q6000 F0.1\nG80\nG00 X150. Z100.\nT0404\nG96 S150 M03\nG00 X21. Z2.\nG01 Z-31. F0.15\nX20.\nG00 Z2.\n{entry}Z-31.\nX23.\nG00 Z5.\nG00 X150. Z100.\nM30\n")
    };
    let chamfered = run_with(
        &program("X27.4\nG01 X24.4 Z0.5 F0.1\n"),
        None,
        &["--stock", "50x40"],
    );
    assert_stock_note(&chamfered, "T04", "boring bar");
    let straight = run_with(
        &program("X24.4\nG01 Z0.5 F0.1\n"),
        None,
        &["--stock", "50x40"],
    );
    assert_removed_alike(&chamfered, &straight, 0.5);
}

/// Field run 5's part-off with a back chamfer, no table and no G42: short moves along Z
/// (1.1 and 0.7 mm, the chamfer's steps) are a blade's, not passes of a bore: T09 only
/// plunges, a blade; the chamfer's inward steps read as bore passes made it a boring bar
/// and the part a 10 mm certain gouge.
#[test]
fn a_part_off_chamfering_by_hand_with_no_table_is_a_blade() {
    let program = "O5006 (PIN D40 X 13 - PART OFF WITH A BACK CHAMFER)\nG21 G40 G99\nG50 S3000\nT0101\nG96 S200 M03\nG00 X52. Z2. M08\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X36.\nG01 Z0. F0.1\nX40. Z-2.\nZ-16.\nN20 X52.\nG70 P10 Q20\nG28 U0. W0.\nT0909 (PART-OFF BLADE 3 MM)\nG96 S120 M03\nG00 X52. Z-14.1\nG01 X50. F0.1\nX48. Z-13.\nX39.5\nX43.\nZ-12.3\nX40.6\nX39.1 Z-13.\nX30.\nG00 X52.\nG28 U0. W0.\nM30\n";
    let v = run_with(program, None, &["--stock", "50x40"]);
    assert_eq!(v["verdict"], "clean", "{:#}", v["gouges"]);
    assert_stock_note(&v, "T09", "grooving blade");
}

/// A report's removed area, mm².
fn removed(v: &serde_json::Value) -> f64 {
    v["removed_area_mm2"].as_f64().unwrap()
}

/// That two reports removed the same area (within `tol` mm²).
fn assert_removed_alike(a: &serde_json::Value, b: &serde_json::Value, tol: f64) {
    assert!(
        (removed(a) - removed(b)).abs() < tol,
        "{} against {}",
        removed(a),
        removed(b)
    );
}

/// That a report notes, under LS-STOCK, tool `t` with `words` in the note.
fn assert_stock_note(j: &serde_json::Value, t: &str, words: &str) {
    let notes = common::warning_messages(j, "LS-STOCK");
    assert!(
        notes.iter().any(|m| m.contains(t) && m.contains(words)),
        "{notes:?}"
    );
}

/// Field run 8 (p02): a tool with no entry that only runs a G74 face groove off the axis is
/// taken for a face-grooving blade, as seed 002 states one (3 mm, its width spanning +x from
/// its inner corner, its body toward +Z), not the radial default, which stood 20 mm along X
/// and swept that much of the face (56 mm² of a 24 mm² groove in the field run). O0210 with
/// no table removes what it removes with seed 002's own table (the drill is the assumed
/// Ø10 118° one either way).
#[test]
fn a_face_groove_with_no_entry_is_cut_by_a_face_blade() {
    let program = std::fs::read_to_string(asset("programs/O0210.nc")).unwrap();
    let table = std::fs::read_to_string(asset("tools/seed002-face3-drill10.toml")).unwrap();
    let stated = run_with(&program, Some(&table), &["--stock", "40x40"]);
    let guessed = run_with(&program, None, &["--stock", "40x40"]);
    assert_removed_alike(&guessed, &stated, 1e-3);
    assert_stock_note(&guessed, "T01", "width +x, shank +z");
}

/// Review 1128g (#1): a G75's escape at the bottom (R) runs along Z, as a G74's pecks do.
/// Counted as a face groove's, it left a tool with no entry that grooves a bore by G75
/// neither a radial nor a face blade: the default insert (and the radial default blade in
/// the cycle) cut 548 mm² instead of 347, with four possible crashes. Only a G74's moves
/// are a face groove's: the ID G75 with R is cut by the ID blade, as without R.
#[test]
fn a_g75_with_an_escape_is_still_a_radial_blade() {
    let program = |r: &str| {
        format!("O0304 (ID GROOVE BY G75 IN A DRILLED BORE)\nG21 G40 G99\nT0303\nG97 S400 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-35. Q5000 F0.1\nG00 Z50.\nT0202\nG97 S500 M03\nG00 X18. Z2.\nZ-10.\nG75 R0.5\nG75 X26. Z-16. P1000 Q2500{r} F0.08\nG00 Z2.\nG00 X100. Z100.\nM30\n")
    };
    let drill =
        "[[tool]]\nt = 3\nkind = \"drill\"\ndiameter = 20.0\npoint_angle = 118\nreach = 80.0\n";
    let with = run_with(&program(" R0.3"), Some(drill), &["--stock", "50x40"]);
    let without = run_with(&program(""), Some(drill), &["--stock", "50x40"]);
    assert_eq!(with["verdict"], "clean", "{:#}", with["crashes"]);
    assert!(
        with["crashes"].as_array().unwrap().is_empty(),
        "{:#}",
        with["crashes"]
    );
    assert_stock_note(&with, "T02", "width +z, shank -x");
    // the escape takes 0.3 mm off each groove wall's bottom corner at most
    assert_removed_alike(&with, &without, 1.0);
}

/// Field run 9 (A): a bush's counterbore roughed and finished by G72 with a boring tool
/// that has no entry (the drill and the OD tool stated). A G72 shape's first move runs
/// along Z at its start point's X, so the shape was not seen to lie in a bore: T03 stayed
/// the OD default and carved a certain 12 mm gouge into the sleeve's wall. The shape runs
/// outward of its start and nowhere inward: a bore, and T03 a boring bar; clean, as with
/// T03 stated with tip 2.
#[test]
fn a_bore_faced_in_layers_by_g72_is_a_boring_bars() {
    let program = "O0901 (BUSH - ID COUNTERBORE BY G72)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.3 W0.05 F0.25\nN10 G00 X44.\nG01 Z0. F0.1\nX48. Z-2.\nZ-42.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\nT0202\nG97 S600 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-50. Q5000 F0.1\nG00 Z5.\nG00 X100. Z100.\nT0303\nG96 S150 M03\nG00 X23. Z2.\nG72 W1. R0.5\nG72 P30 Q40 U-0.3 W0.05 F0.15\nN30 G00 Z-41.\nG01 X30. F0.1\nZ-12.\nX36.\nZ-1.\nX38. Z0.\nN40 Z2.\nG42 G00 X23. Z2.\nG70 P30 Q40\nG40 G00 Z5.\nX100. Z100.\nM30\n";
    let table = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"drill\"\ndiameter = 24.0\npoint_angle = 118\nreach = 80.0\n";
    let j = run_with(
        program,
        Some(table),
        &["--stock", "50x50", "--stock-z", "0.5"],
    );
    assert_eq!(j["verdict"], "clean", "{:#}", j["gouges"]);
    assert_stock_note(&j, "T03", "boring bar");
}

/// Field run 9 (B): a counterbore faced out by G94 in a drilled hole, the boring tool
/// listed by its insert alone (`insert = "DCMT 070204"`: no `tip`, no holder). The entry
/// took the documented tip 3, an OD tool: five certain crashes, where the same program
/// with no entry for T03 at all was clean. A turning entry whose tip the table does not
/// state takes its tip from its moves as a tool with no entry does (§17): cutting in bores
/// only, tip 2, with an LS-STOCK note; a stated tip 3 is kept (the crashes stay).
#[test]
fn an_insert_listed_alone_that_bores_is_a_boring_bar() {
    let program = "O0905 (BUSH - COUNTERBORE BY G94)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG90 X49. Z-42. F0.25\nX48.\nG00 X100. Z100.\nT0202\nG97 S600 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-50. Q5000 F0.1\nG00 Z5.\nG00 X100. Z100.\nT0303\nG96 S150 M03\nG00 X22. Z2.\nG94 X36. Z-1. F0.12\nZ-2.\nZ-3.\nZ-4.\nZ-5.\nG00 X100. Z100.\nM30\n";
    let table = |t3: &str| {
        format!("[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"drill\"\ndiameter = 24.0\npoint_angle = 118\nreach = 80.0\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\n{t3}")
    };
    let j = run_with(
        program,
        Some(&table("")),
        &["--stock", "50x50", "--stock-z", "0.5"],
    );
    assert_eq!(j["verdict"], "clean", "{:#}", j["crashes"]);
    let notes = common::warning_messages(&j, "LS-STOCK");
    assert!(
        notes
            .iter()
            .any(|m| m.contains("T03 states its insert but not its tip")),
        "{notes:?}"
    );
    // a stated tip is the table's word
    let (out, _) = run_json_with(
        program,
        Some(&table("tip = 3\n")),
        &["--stock", "50x50", "--stock-z", "0.5"],
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
}

/// Field run 9 (r7): an ID groove plunged outward from a bore by a blade entry that states
/// its width and reach but not its body's side (`shank_dir`). The entry took the default
/// `+x`, an OD blade, whose body swept the bore's wall: 2 certain crashes and a 4 mm
/// gouge. A grooving entry whose side the table does not state takes it from its plunges
/// as a blade with no entry does: an ID blade, with an LS-STOCK note; the run removes
/// what it removes with `shank_dir = "-x"` stated.
#[test]
fn a_blade_entry_without_its_side_that_plunges_from_a_bore_is_an_id_blade() {
    let program = "O0907 (BUSH - BORE, THEN AN ID GROOVE)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.3 W0.05 F0.25\nN10 G00 X44.\nG01 Z0. F0.1\nX48. Z-2.\nZ-42.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\nT0202\nG97 S600 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-50. Q5000 F0.1\nG00 Z5.\nG00 X100. Z100.\nT0303\nG96 S150 M03\nG00 X23. Z2.\nG71 U1. R0.5\nG71 P30 Q40 U-0.4 W0.05 F0.15\nN30 G00 G41 X36.\nG01 Z0. F0.1\nX32. Z-2.\nZ-40.\nN40 X23.\nG70 P30 Q40\nG40 G00 Z5.\nX100. Z100.\nT0505\nG97 S600 M03\nG00 X28. Z2.\nZ-20.\nG01 X36. F0.05\nG00 X28.\nZ2.\nG00 X100. Z100.\nM30\n";
    let table = |side: &str| {
        format!("[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"drill\"\ndiameter = 24.0\npoint_angle = 118\nreach = 80.0\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\ntip = 2\nentering_angle = 93\nshank = 16.0\n[[tool]]\nt = 5\nkind = \"grooving\"\nwidth = 3.0\nreach = 8.0\n{side}")
    };
    let unstated = run_with(program, Some(&table("")), &["--stock", "50x50"]);
    let stated = run_with(
        program,
        Some(&table("shank_dir = \"-x\"\n")),
        &["--stock", "50x50"],
    );
    assert_eq!(unstated["verdict"], "clean", "{:#}", unstated["crashes"]);
    assert_removed_alike(&unstated, &stated, 1e-6);
    assert_stock_note(&unstated, "T05", "ID blade");
}
