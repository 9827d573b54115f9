//! The worked macro examples of spec/dialects.md §7 (T6, T7) and the bad inputs of issue 12,
//! run end to end through a miniature reader and machine built on the public API, the way
//! the interpreter will use it.

use crate::*;

/// An NC block: its words with their value expressions.
#[derive(Debug, Clone)]
struct Nc {
    words: Vec<(char, Expr, bool)>,
}

/// Read a program text: `;` ends a block, `N` numbers, `O` lines start programs.
fn read(src: &str, options: &Options) -> Result<Vec<MacroProgram<Nc>>> {
    let mut programs: Vec<(Option<u32>, Vec<Line<Nc>>)> = vec![(None, vec![])];
    let mut offset = 0;
    for (i, raw) in src.split('\n').enumerate() {
        let line_no = i as u32 + 1;
        let line_offset = offset;
        let base = |at: usize| Span {
            line: line_no,
            column: raw[..at].chars().count() as u32 + 1,
            offset: (line_offset + at) as u32,
            len: 0,
        };
        let span = Span {
            line: line_no,
            column: 1,
            offset: offset as u32,
            len: raw.len() as u32,
        };
        offset += raw.len() + 1;
        let text = raw.trim_end().trim_end_matches(';').trim_end();
        let mut at = text.len() - text.trim_start().len();
        if text[at..].starts_with('O') {
            let n = text[at + 1..].trim().parse().unwrap();
            programs.push((Some(n), vec![]));
            continue;
        }
        let mut seq = None;
        if text[at..].starts_with('N') {
            let digits: String = text[at + 1..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            seq = Some(digits.parse().unwrap());
            at += 1 + digits.len();
            at += text[at..].len() - text[at..].trim_start().len();
        }
        let body_text = &text[at..];
        if body_text.is_empty() {
            continue;
        }
        let body = if starts_statement(body_text) {
            Body::Stmt(parse_stmt(body_text, base(at), options)?)
        } else {
            let mut words = Vec::new();
            let mut k = at;
            while k < text.len() {
                let c = text[k..].chars().next().unwrap();
                if c.is_whitespace() {
                    k += 1;
                    continue;
                }
                assert!(c.is_ascii_alphabetic(), "{raw}: {c}");
                let rest = &text[k + 1..];
                let (e, used) = parse_operand(rest, base(k + 1))?;
                words.push((c.to_ascii_uppercase(), e, rest[..used].contains('.')));
                k += 1 + used;
            }
            Body::Block(Nc { words })
        };
        programs
            .last_mut()
            .unwrap()
            .1
            .push(Line { seq, span, body });
    }
    programs
        .into_iter()
        .filter(|(n, l)| n.is_some() || !l.is_empty())
        .map(|(n, l)| MacroProgram::new(n, l, &options.limits))
        .collect()
}

/// A lathe that only moves: X diameter, Z, G00/G01, U/W incremental.
#[derive(Debug, Default)]
struct Lathe {
    x: f64,
    z: f64,
    g: i64,
    moves: Vec<(i64, f64, f64)>,
    notes: Vec<String>,
}

impl System for Lathe {
    fn position(&self, kind: Position, axis: Axis) -> Option<f64> {
        (kind != Position::Machine).then_some(match axis {
            Axis::X => self.x,
            Axis::Z => self.z,
        })
    }
    fn modal_group(&self, group: u32) -> Option<f64> {
        (group == 1).then_some(self.g as f64)
    }
}

struct Run {
    lathe: Lathe,
    state: MacroState,
    loops: Vec<u64>,
}

fn run(src: &str, options: Options) -> Result<Run> {
    let programs = read(src, &options)?;
    let mut state = MacroState::new(options);
    let mut lathe = Lathe::default();
    let mut flow = Flow::new(&programs, 0, options.limits);
    while let Some(step) = flow.next(&mut state, &mut lathe)? {
        let Step::Block { at, block } = step else {
            unreachable!("no Haas THEN blocks here")
        };
        let words = &block.words;
        let code = |state: &mut MacroState, lathe: &mut Lathe, l: char| -> Result<Option<i64>> {
            match words.iter().find(|w| w.0 == l) {
                Some((_, e, _)) => state.integer_value(e, lathe),
                None => Ok(None),
            }
        };
        if code(&mut state, &mut lathe, 'M')? == Some(30) {
            break;
        }
        if code(&mut state, &mut lathe, 'M')? == Some(99) {
            let p = code(&mut state, &mut lathe, 'P')?.map(|p| p as u32);
            flow.ret(&mut state, p, at.span)?;
            continue;
        }
        if code(&mut state, &mut lathe, 'G')? == Some(65) {
            let (_, pe, _) = words.iter().find(|w| w.0 == 'P').expect("G65 P");
            let p = state.required(pe, "G65 P", &mut lathe)?;
            let l = code(&mut state, &mut lathe, 'L')?.unwrap_or(1);
            let mut args = Vec::new();
            for (c, e, point) in words.iter().filter(|w| !matches!(w.0, 'G' | 'P' | 'L')) {
                let mut v = state.eval(e, &mut lathe)?;
                let written = match &e.kind {
                    ExprKind::Num(w) => Some(*w),
                    ExprKind::Neg(inner) => match inner.kind {
                        ExprKind::Num(w) => Some(-w),
                        _ => None,
                    },
                    _ => None,
                };
                if let (Some(written), false) = (written, *point) {
                    let (passed, note) = g65_argument_value(*c, written, false, 0.001);
                    v = Value::num(passed);
                    lathe.notes.extend(note);
                }
                args.push(Argument {
                    letter: *c,
                    value: v,
                    span: e.span,
                });
            }
            let locals = g65_locals(&args)?;
            flow.call_macro(&mut state, p as u32, l as u32, locals, at.span)?;
            continue;
        }
        let mut moved = false;
        for (c, e, _) in words {
            match c {
                'G' => {
                    if let Some(g) = state.integer_value(e, &mut lathe)? {
                        if g <= 1 {
                            lathe.g = g;
                        }
                    }
                }
                'X' | 'Z' | 'U' | 'W' => {
                    if let Some(v) = state.address_value(e, 0.001, &mut lathe)? {
                        moved = true;
                        match c {
                            'X' => lathe.x = v,
                            'Z' => lathe.z = v,
                            'U' => lathe.x += v,
                            _ => lathe.z += v,
                        }
                    }
                }
                _ => {}
            }
        }
        if moved {
            lathe.moves.push((lathe.g, lathe.x, lathe.z));
        }
    }
    let loops = flow
        .loop_iterations(0)
        .iter()
        .copied()
        .filter(|&n| n > 0)
        .collect();
    Ok(Run {
        lathe,
        state,
        loops,
    })
}

const T6: &str = "O0600
G21 G99 T0101 ;
G97 S800 M03 ;
#1 = 50. ;
#2 = 40. ;
#3 = 2. ;
G00 X52. Z2. ;
WHILE [#1 GT #2] DO1 ;
#1 = #1 - #3 ;
IF [#1 LT #2] THEN #1 = #2 ;
G00 X#1 ;
G01 Z-25. F0.2 ;
G00 U2. ;
Z2. ;
END1 ;
#4 = #0 ;
G00 X#4 Z5. ;
G00 X100. Z100. ;
M30 ;";

#[test]
fn t6_macro_loop_and_a_vacant_address() {
    let r = run(T6, Options::fanuc()).unwrap();
    let mut expected = vec![(0, 52.0, 2.0)];
    for x in [48.0, 46.0, 44.0, 42.0, 40.0] {
        expected.push((0, x, 2.0));
        expected.push((1, x, -25.0));
        expected.push((0, x + 2.0, -25.0));
        expected.push((0, x + 2.0, 2.0));
    }
    // `G00 X#4 Z5.` moves only Z: (42, 2) → (42, 5)
    expected.push((0, 42.0, 5.0));
    expected.push((0, 100.0, 100.0));
    assert_eq!(r.lathe.moves, expected);
    // 5 loop iterations
    assert_eq!(r.loops, vec![5]);
    assert_eq!(r.state.vars.local(1), Value::num(40.0));
    assert!(r.state.vars.local(4).is_vacant());
}

const T7: &str = "#1 = 2 + 3 * 4 ;
#2 = [2 + 3] * 4 ;
#3 = #0 + 5 ;
#4 = #0 * 10 ;
#5 = FIX[-1.7] ;
#6 = FUP[-1.2] ;
#7 = ROUND[2.5] ;
#8 = ATAN[1]/[-1] ;
#9 = SQRT[16] + ABS[-3] ;
IF [#10 EQ #0] THEN #11 = 1 ;
IF [#10 EQ 0] THEN #12 = 1 ;
IF [#10 GE 0] THEN #13 = 1 ;
G00 X#1 Z#2 ;
G00 X#12 Z[#13 + #3] ;
M30 ;";

#[test]
fn t7_macro_arithmetic_functions_vacancy() {
    let r = run(T7, Options::fanuc()).unwrap();
    let v = |n| r.state.vars.local(n);
    let expected = [
        (1, Some(14.0)),
        (2, Some(20.0)),
        (3, Some(5.0)),
        (4, Some(0.0)),
        (5, Some(-1.0)),
        (6, Some(-2.0)),
        (7, Some(3.0)),
        (8, Some(135.0)),
        (9, Some(7.0)),
        (10, None),
        (11, Some(1.0)),
        (12, None),
        (13, Some(1.0)),
    ];
    for (n, want) in expected {
        assert_eq!(v(n).get(), want, "#{n}");
    }
    // rapid to (14, 20), then only Z moves to 6
    assert_eq!(r.lathe.moves, vec![(0, 14.0, 20.0), (0, 14.0, 6.0)]);
    // the final variable table for the report
    let table = r.state.vars.report();
    let numbers: Vec<u32> = table.iter().map(|e| e.number).collect();
    assert_eq!(numbers, (1..=13).collect::<Vec<_>>());
    let e12 = table[11];
    assert!(e12.read && !e12.set && e12.value.is_vacant());
    let e10 = table[9];
    assert!(e10.read && !e10.set);
}

#[test]
fn shaft_family_from_g65_arguments() {
    // three calls of one macro with arguments, one without decimal points
    let src = "G65 P9100 X30. Z-20.
G65 P9100 X24. Z-12.
G65 P9100 X20000 Z-5000
M30
O9100
IF [#24 EQ #0] GOTO 90
G00 X#24 Z2.
G01 Z#26
G00 U2.
M99
N90 #3000 = 1 (X MISSING)
M99";
    let r = run(src, Options::fanuc()).unwrap();
    assert_eq!(
        r.lathe.moves,
        vec![
            (0, 30.0, 2.0),
            (1, 30.0, -20.0),
            (0, 32.0, -20.0),
            (0, 24.0, 2.0),
            (1, 24.0, -12.0),
            (0, 26.0, -12.0),
            (0, 20.0, 2.0),
            (1, 20.0, -5.0),
            (0, 22.0, -5.0),
        ]
    );
    assert_eq!(r.lathe.notes.len(), 2);
    assert!(r.lathe.notes[0].contains("X20000 has no decimal point: it passes 20"));
    // the macro's locals are gone after M99
    assert!(r.state.vars.local(24).is_vacant());
}

fn err(src: &str) -> MacroError {
    match run(src, Options::fanuc()) {
        Ok(_) => panic!("{src}: no error"),
        Err(e) => e,
    }
}

#[test]
fn bad_inputs_are_alarms_at_their_place() {
    // division by zero
    let e = err("#1 = 0 ;\n#2 = 10 / #1 ;");
    assert_eq!(e.kind, ErrorKind::DivisionByZero);
    assert_eq!((e.span.line, e.span.column), (2, 6));
    assert!(e.message.contains("10/#1"), "{}", e.message);
    // a vacant variable in a required place
    let e = err("G65 P#7 X1. ;");
    assert_eq!(e.kind, ErrorKind::Vacant);
    assert_eq!((e.span.line, e.span.column), (1, 6));
    // END without DO
    let e = err("G00 X1. ;\nEND2 ;");
    assert_eq!(e.kind, ErrorKind::EndWithoutDo);
    assert_eq!((e.span.line, e.span.column), (2, 1));
    // DO nested beyond the limit
    let e =
        err("WHILE [1] DO1\nWHILE [1] DO2\nWHILE [1] DO3\nWHILE [1] DO1\nEND1\nEND3\nEND2\nEND1");
    assert_eq!(e.kind, ErrorKind::LoopNesting);
    assert_eq!(e.span.line, 4);
    assert!(e.message.contains("4 deep"), "{}", e.message);
    // GOTO to a missing N
    let e = err("#1 = 3 ;\nIF [#1 GT 2] GOTO 40 ;\nN30 G00 X1. ;");
    assert_eq!(e.kind, ErrorKind::SequenceMissing);
    assert_eq!((e.span.line, e.span.column), (2, 19));
    // a runaway loop ended by the budget (its speed is measured by the benchmark, not
    // asserted here: a loaded CI box must not fail a timing)
    let e = err("#1 = 1 ;\nWHILE [#1 GT 0] DO1 ;\nG00 X#1 ;\n#1 = #1 + 1 ;\nEND1 ;");
    assert_eq!(e.kind, ErrorKind::Budget);
    assert_eq!(e.span.line, 2);
    assert!(e.message.contains("ran 2499999 times"), "{}", e.message);
    // #3000 alarm with its text, from inside a macro
    let e = err(
        "G65 P9100 ;\nM30 ;\nO9100\nIF [#24 EQ #0] GOTO 90 ;\nM99 ;\nN90 #3000 = 1 (X MISSING) ;",
    );
    assert_eq!(e.kind, ErrorKind::ProgramAlarm { code: 3001 });
    assert_eq!(e.message, "alarm 3001: X MISSING");
    assert_eq!((e.span.line, e.span.column), (6, 5));
    // position read, modal read
    let r = run(
        "G01 X20. Z-3. ;\n#100 = #5001 + #5002 + #4001 ;",
        Options::fanuc(),
    )
    .unwrap();
    assert_eq!(r.state.vars.common(100), Some(Value::num(18.0)));
    let e = err("#1 = #5021 ;");
    assert_eq!(e.kind, ErrorKind::NotSimulated);
    assert_eq!(e.message, "system variable #5021 not simulated");
    // #0 cannot be assigned
    let e = err("#0 = 1 ;");
    assert_eq!(e.kind, ErrorKind::ReadOnly);
}
