use super::*;
use crate::error::ErrorKind;

/// Shifting a statement's spans is reading it further on in the text: every kind, with
/// indirect variables, groups, signs, functions and a Haas `THEN` block.
#[test]
fn shifted_statements_are_statements_read_further_on() {
    let at = |offset: u32| Span {
        line: 3,
        column: 1,
        offset,
        len: 0,
    };
    let fanuc = Options::fanuc();
    let haas = Options::haas();
    for (text, options) in [
        ("#[#1 + 1] = -SIN[#2] * [#3 - 1] (note)", &fanuc),
        ("IF [#1 GT +2] GOTO #[#4]", &fanuc),
        ("IF [#1 EQ 0] THEN #5 = ATAN[#1]/[2]", &fanuc),
        ("IF [#1 EQ 0] THEN G0 X1.", &haas),
        ("IF [#1 NE 0] THEN", &haas),
        ("ELSE", &haas),
        ("ENDIF", &haas),
        ("WHILE [#1 LT 3] DO1", &fanuc),
        ("DO2", &fanuc),
        ("END1", &fanuc),
        ("GOTO [#1 + 10]", &fanuc),
    ] {
        let mut shifted = parse_stmt(text, at(0), options).unwrap();
        shifted.shift_spans(1000);
        assert_eq!(
            shifted,
            parse_stmt(text, at(1000), options).unwrap(),
            "{text}"
        );
    }
}

fn p(s: &str) -> Expr {
    parse_expr(s, Span::default()).unwrap_or_else(|e| panic!("{s}: {e} at {}", e.span))
}

#[test]
fn precedence_table_shapes() {
    // level 3 over level 4
    assert_eq!(p("2 + 3 * 4").to_string(), "2+3*4");
    let ExprKind::Binary(BinOp::Add, _, r) = p("2 + 3 * 4").kind else {
        panic!()
    };
    assert!(matches!(r.kind, ExprKind::Binary(BinOp::Mul, ..)));
    // brackets over everything
    let ExprKind::Binary(BinOp::Mul, l, _) = p("[2 + 3] * 4").kind else {
        panic!()
    };
    assert!(matches!(l.kind, ExprKind::Group(_)));
    // AND is level 3 like *, OR level 4 like +
    let ExprKind::Binary(BinOp::Or, _, r) = p("1 OR 2 AND 3").kind else {
        panic!()
    };
    assert!(matches!(r.kind, ExprKind::Binary(BinOp::And, ..)));
    // comparisons lowest
    let ExprKind::Binary(BinOp::Gt, l, r) = p("#1 + 1 GT #2 * 2").kind else {
        panic!()
    };
    assert!(matches!(l.kind, ExprKind::Binary(BinOp::Add, ..)));
    assert!(matches!(r.kind, ExprKind::Binary(BinOp::Mul, ..)));
    // left to right at one level
    let ExprKind::Binary(BinOp::Sub, l, _) = p("10 - 4 - 3").kind else {
        panic!()
    };
    assert!(matches!(l.kind, ExprKind::Binary(BinOp::Sub, ..)));
    // unary binds tighter than *
    let ExprKind::Binary(BinOp::Mul, l, _) = p("-2 * 3").kind else {
        panic!()
    };
    assert!(matches!(l.kind, ExprKind::Neg(_)));
    // function binds tighter than /
    assert!(matches!(
        p("SIN[30] / 2").kind,
        ExprKind::Binary(BinOp::Div, ..)
    ));
}

#[test]
fn atan_forms() {
    let e = p("ATAN[1]/[-1]");
    assert!(matches!(&e.kind, ExprKind::Call(Func::Atan, a) if a.len() == 2));
    let e = p("ATAN[1,-1]");
    assert!(matches!(&e.kind, ExprKind::Call(Func::Atan, a) if a.len() == 2));
    let e = p("ATAN[1]/2");
    assert!(matches!(&e.kind, ExprKind::Binary(BinOp::Div, ..)));
    assert!(parse_expr("SIN[1,2]", Span::default()).is_err());
    assert!(parse_expr("POW[2]", Span::default()).is_err());
}

#[test]
fn variables_and_spans() {
    let base = Span {
        line: 7,
        column: 5,
        offset: 100,
        len: 0,
    };
    let e = parse_expr("#1 + #[#2 * 2]", base).unwrap();
    let ExprKind::Binary(_, l, r) = &e.kind else {
        panic!()
    };
    assert_eq!(
        (l.span.line, l.span.column, l.span.offset, l.span.len),
        (7, 5, 100, 2)
    );
    assert_eq!((r.span.column, r.span.len), (10, 9));
    assert_eq!(e.span.len, 14);
    assert!(matches!(r.kind, ExprKind::Var(VarRef::Indirect(_))));
    let err = parse_expr("##1", base).unwrap_err();
    assert!(err.help.contains("#[#1]"));
    assert_eq!(err.span.column, 6);
    assert!(parse_expr("#1.5", base).is_err());
}

#[test]
fn bracket_limit() {
    assert!(parse_expr("[[[[[1]]]]]", Span::default()).is_ok());
    let e = parse_expr("[[[[[[1]]]]]]", Span::default()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::BracketNesting);
    assert_eq!(e.span.column, 6);
    // function brackets count
    let e = parse_expr("[[[[SIN[[1]]]]]]", Span::default()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::BracketNesting);
}

#[test]
fn huge_inputs_are_refused_not_overflowed() {
    let long = vec!["1"; 5000].join("+");
    let e = parse_expr(&long, Span::default()).unwrap_err();
    assert!(e.message.contains("operators"));
    let signs = format!("{}1", "-".repeat(100_000));
    assert!(parse_expr(&signs, Span::default()).is_err());
    assert!(parse_expr(&vec!["1"; 200].join("+"), Span::default()).is_ok());
}

#[test]
fn syntax_errors_point_at_the_place() {
    let e = parse_expr("1 + * 2", Span::default()).unwrap_err();
    assert_eq!(e.span.column, 5);
    let e = parse_expr("[1 + 2", Span::default()).unwrap_err();
    assert!(e.message.contains("']'"), "{}", e.message);
    let e = parse_expr("FOO[1]", Span::default()).unwrap_err();
    assert!(e.message.contains("FOO"));
    let e = parse_expr("1 2", Span::default()).unwrap_err();
    assert_eq!(e.span.column, 3);
    let e = parse_expr("SIN 30", Span::default()).unwrap_err();
    assert!(e.help.contains("SIN["));
}

#[test]
fn statements() {
    let o = Options::fanuc();
    let s = |t: &str| parse_stmt(t, Span::default(), &o);
    assert!(matches!(s("#1 = 2").unwrap().kind, StmtKind::Assign { .. }));
    let st = s("#3000 = 1 (TOOL BROKEN)").unwrap();
    let StmtKind::Assign { comment, .. } = st.kind else {
        panic!()
    };
    assert_eq!(comment.as_deref(), Some("TOOL BROKEN"));
    assert!(matches!(
        s("IF [#1 GT 3] GOTO 10").unwrap().kind,
        StmtKind::IfGoto { .. }
    ));
    assert!(matches!(
        s("IF[#1GT3]GOTO#2").unwrap().kind,
        StmtKind::IfGoto { .. }
    ));
    assert!(matches!(
        s("IF [#1 LT #2] THEN #1 = #2").unwrap().kind,
        StmtKind::IfThen { .. }
    ));
    assert!(matches!(
        s("WHILE [#1 GT #2] DO1").unwrap().kind,
        StmtKind::While { id: 1, .. }
    ));
    assert!(matches!(s("END1").unwrap().kind, StmtKind::End { id: 1 }));
    assert!(matches!(s("DO 2").unwrap().kind, StmtKind::Do { id: 2 }));
    assert!(matches!(
        s("GOTO [#1 + 10]").unwrap().kind,
        StmtKind::Goto { .. }
    ));
    assert!(matches!(
        s("IF [#1 EQ 1] THEN").unwrap().kind,
        StmtKind::IfBlock { .. }
    ));
    assert!(matches!(s("ELSE").unwrap().kind, StmtKind::Else));
    assert!(matches!(s("ENDIF").unwrap().kind, StmtKind::EndIf));
    // errors
    let e = s("IF [#1 EQ 1] THEN GOTO 5").unwrap_err();
    assert!(e.message.contains("THEN GOTO"));
    let e = s("IF #1 EQ 1 GOTO 5").unwrap_err();
    assert!(e.message.contains("brackets"));
    let e = s("WHILE [#1 GT 0] DO4").unwrap_err();
    assert_eq!(e.kind, ErrorKind::LoopNesting);
    assert_eq!(e.span.column, 19);
    let e = s("IF [1] THEN G01 X#24").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Unsupported);
    assert_eq!(e.span.column, 13);
    assert!(s("WH [1] DO1").is_err());
    assert!(s("#1 = ").is_err());
    assert!(s("#1 = 2 3").is_err());
    // Haas forms
    let h = Options::haas();
    let st = parse_stmt("IF [#1 NE #0] THEN G01 X#24 F#9", Span::default(), &h).unwrap();
    let StmtKind::IfThenBlock {
        text, text_span, ..
    } = st.kind
    else {
        panic!()
    };
    assert_eq!(text, "G01 X#24 F#9");
    assert_eq!(text_span.column, 20);
    assert!(parse_stmt("WH [1] DO1", Span::default(), &h).is_ok());
}

#[test]
fn operands_for_words() {
    let (e, n) = parse_operand("#1Z5.", Span::default()).unwrap();
    assert_eq!(n, 2);
    assert!(matches!(e.kind, ExprKind::Var(VarRef::Direct(1))));
    let (e, n) = parse_operand("[#2-0.5] F0.2", Span::default()).unwrap();
    assert_eq!(n, 8);
    assert!(matches!(e.kind, ExprKind::Group(_)));
    let (e, n) = parse_operand("-#1 Z2", Span::default()).unwrap();
    assert_eq!(n, 3);
    assert!(matches!(e.kind, ExprKind::Neg(_)));
    let (_, n) = parse_operand("ROUND[#1]", Span::default()).unwrap();
    assert_eq!(n, 9);
    assert!(starts_statement("#1=2"));
    assert!(starts_statement("  while [1] do1"));
    assert!(starts_statement("IF[1]GOTO5"));
    assert!(!starts_statement("G00 X#1"));
    assert!(!starts_statement("DWELL"));
}
