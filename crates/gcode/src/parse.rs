//! Text → [`Program`]: the entry points of reading. The reading itself is [`crate::read`];
//! its O programs become [`crate::Subprogram`]s whose blocks are read again from the
//! shared text where they are needed ([`crate::Blocks`]).

use std::sync::Arc;

use crate::read::{self, Keep, ParseError, ReadOptions};
use crate::Program;

/// Read a whole program text.
pub fn parse(source: &str) -> Result<Program, ParseError> {
    parse_with(source, ReadOptions::default())
}

/// Read a whole program text with options.
pub fn parse_with(source: &str, options: ReadOptions) -> Result<Program, ParseError> {
    parse_shared(Arc::from(source), options)
}

/// Read a whole program text with options, keeping the text (shared, not copied) to read
/// its blocks again where they are needed ([`crate::Blocks`]).
pub fn parse_shared(source: Arc<str>, options: ReadOptions) -> Result<Program, ParseError> {
    let reading = read::whole(&source, options, Keep::Starts)?;
    Ok(Program::from_reading(reading, &source, options))
}

/// Read a whole program text holding every block: the reference the re-read blocks of
/// [`parse_with`] are compared with in tests.
#[doc(hidden)]
pub fn parse_held(source: &str, options: ReadOptions) -> Result<Program, ParseError> {
    let reading = read::whole(source, options, Keep::Held)?;
    Ok(Program::from_reading(reading, &Arc::from(source), options))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Block, Span, Word};
    use macro_b::Dialect;

    /// Text outside parentheses that ends its line is noted where it stands (the note ran
    /// from the start of the file when nothing followed the character).
    #[test]
    fn a_note_for_text_at_the_end_of_a_line_stays_on_it() {
        let p = parse("O0001\nG0 X50. Z2.\nG1 Z-5. F0.2 \u{e9}\nG0 X60.\nM30\n").unwrap();
        let n = &p.notes[0];
        assert_eq!(
            (n.span.line, n.span.column, n.span.offset, n.span.len),
            (3, 14, 31, 2),
            "{:?}",
            n.span
        );
    }

    fn words(src: &str) -> Vec<(char, f64)> {
        parse(src).unwrap().programs[0]
            .blocks
            .iter()
            .flat_map(|b| {
                b.words
                    .iter()
                    .map(|w| (w.letter, w.value))
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    #[test]
    fn spaces_inside_words_and_case() {
        assert_eq!(
            words("g74 z-28.0 Q5 000 f0.1"),
            vec![('G', 74.0), ('Z', -28.0), ('Q', 5000.0), ('F', 0.1)]
        );
        assert_eq!(
            words("G28 U0 W 0;"),
            vec![('G', 28.0), ('U', 0.0), ('W', 0.0)]
        );
    }

    #[test]
    fn number_forms() {
        assert_eq!(
            words("X100. u.1 w0. R6. Z-17.639 P30000"),
            vec![
                ('X', 100.0),
                ('U', 0.1),
                ('W', 0.0),
                ('R', 6.0),
                ('Z', -17.639),
                ('P', 30000.0)
            ]
        );
        let p = parse("X100. P1500").unwrap();
        let b = &p.programs[0].blocks.all()[0];
        assert!(b.words[0].has_point);
        assert!(!b.words[1].has_point);
    }

    #[test]
    fn blocks_split_on_semicolon_and_newline() {
        let p = parse("M30;G0 X1\nZ2;;\n\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert_eq!(p.programs[0].blocks.all()[2].span.line, 2);
    }

    #[test]
    fn comments() {
        assert_eq!(
            words("G0 X1 (hello; world) Z2 （中文）\nG1 X2 // rest ; ignored"),
            vec![('G', 0.0), ('X', 1.0), ('Z', 2.0), ('G', 1.0), ('X', 2.0)]
        );
    }

    #[test]
    fn annotation_after_block_is_noted() {
        let p = parse("w-20 ; 精加工形狀程式段\nX1").unwrap();
        assert_eq!(p.notes.len(), 1);
        assert_eq!(p.programs[0].blocks.len(), 2);
    }

    #[test]
    fn o_programs_and_sequence_numbers() {
        let p = parse("%\nO0001;\nN10 G0 X1;\nM98 P2;\nM30;\nO0002;\nG1 X2;\nM99;\n%").unwrap();
        assert_eq!(p.programs.len(), 2);
        assert_eq!(p.programs[0].number, Some(1));
        assert_eq!(p.programs[0].blocks.all()[0].seq, Some(10));
        assert_eq!(p.find(2).unwrap().blocks.len(), 2);
    }

    #[test]
    fn block_delete() {
        let p = parse("/G0 X1\nG0 X2").unwrap();
        assert!(p.programs[0].blocks.all()[0].block_delete);
        assert!(!p.programs[0].blocks.all()[1].block_delete);
    }

    #[test]
    fn errors_have_line_and_column() {
        let e = parse("G0 X10\nG1 Z-5 X\n").unwrap_err();
        assert_eq!((e.span.line, e.span.column), (2, 8));
        assert!(e.message.contains("no value"), "{}", e.message);
        let e = parse("G1 X1.2.3").unwrap_err();
        assert!(e.message.contains("malformed"));
        let e = parse("G1 X1 X2").unwrap_err();
        assert_eq!(e.span.column, 7);
        assert!(e.message.contains("twice"));
        let e = parse("G1 #1=2").unwrap_err();
        assert_eq!(e.span.column, 4);
        let e = parse("G1 \"A\"").unwrap_err();
        assert!(e.message.contains("string literal"), "{}", e.message);
        let e = parse("G1 X1-2").unwrap_err();
        assert!(e.message.contains("malformed"));
    }

    fn notes(p: &Program) -> Vec<String> {
        p.notes.iter().map(|n| n.message.clone()).collect()
    }

    #[test]
    fn dialects_t1_framing() {
        // spec/dialects.md §7 T1: DC2, a DNC leader glued to %, ':' program number,
        // nested parentheses with quotes, a block of only N, the closing % and DC4
        let text = "\u{12}&HE:%\n:0100 (FRAMING (NESTED) \"Q\" TEST) ;\nN10 G21 G99 ;\nN20 T0101 ;\nN30 G97 S800 M03 ;\nN40 ;\nN50 G00 X52. Z2. ;\nN60 G90 X46. Z-30. F0.2 ;\nN70 X42. ;\nN80 G00 X100. Z100. ;\nN90 M30 ;\n%\n\u{14}";
        let p = parse(text).unwrap();
        assert_eq!(p.programs.len(), 1);
        assert_eq!(p.programs[0].number, Some(100));
        let blocks = &p.programs[0].blocks.all();
        assert_eq!(blocks.len(), 9);
        assert!(blocks[3].words.is_empty() && blocks[3].seq == Some(40));
        let n = notes(&p);
        assert_eq!(n.len(), 2, "{n:?}");
        assert!(n[0].contains("leader skipped: \"&HE:\""), "{n:?}");
        assert!(n[1].contains("nested parentheses"), "{n:?}");
        // the flow-control bytes: DC2 was in the leader, DC4 after the closing %
        let p = parse("G0 X1\u{11}0 Z2\n\u{13}M30\n").unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words[1].value, 10.0);
        assert!(notes(&p)[0].contains("2 RS-232"), "{:?}", notes(&p));
    }

    #[test]
    fn leader_only_before_the_first_address_line() {
        // a % after program text ends the tape; what follows is not read
        let p = parse("O1\nG0 X1\n%\nG0 X2\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1);
        assert!(notes(&p)[0].contains("after the closing %"));
        // blank lines and a comment before % are leader, with nothing to report
        let p = parse("\n(O1234.NC)\n%\nG0 X1\n%\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1);
        assert!(notes(&p)[0].contains("O1234.NC"), "{:?}", notes(&p));
    }

    #[test]
    fn a_program_number_alone_before_the_first_percent_is_leader() {
        // field run 4: a training app writes `O0090 (CONE)` above the opening `%`; the `%`
        // was read as the closing one: "nothing to simulate, the file has no blocks"
        let p = parse("O0090 (CONE D50)\n%\nG0 X1\nG0 X2\nM30\n%\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3, "{:?}", notes(&p));
        assert!(notes(&p)[0].contains("O0090 (CONE D50)"), "{:?}", notes(&p));
        // a program number followed by blocks is the program, as before
        let p = parse(":12 (X)\nG0 X1\n%\nG0 X2\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1);
    }

    #[test]
    fn percent_glued_to_the_program_number_starts_the_tape() {
        // issue 31: `%O1200(TOKARKA)` on line 1 was read as the closing % — no blocks
        let p = parse("%O1200(TOKARKA)\nG0 X10 Z2\nG1 Z-5 F.1\nM30\n%\n").unwrap();
        assert_eq!(p.programs[0].number, Some(1200));
        assert_eq!(p.programs[0].blocks.len(), 3, "{:?}", notes(&p));
        assert!(notes(&p)[0].contains("share a line"), "{:?}", notes(&p));
        // the same after a leader line and with a BOM
        let p = parse("\u{feff}  %O12\nG0 X1\nG0 X2\n%").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
    }

    #[test]
    fn line_ends_and_control_bytes() {
        let p = parse("G0 X1\rG0 X2\r\nG0 X3\n\r\rG0 X4\u{1a}").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 4);
        assert!(p.notes.is_empty(), "{:?}", notes(&p));
        let p = parse("\u{feff}G0\u{0}\u{1} X1\tZ2").unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words.len(), 3);
        assert!(
            notes(&p)[0].contains("1 unexpected control"),
            "{:?}",
            notes(&p)
        );
    }

    #[test]
    fn prose_after_semicolon_is_a_comment_but_blocks_are_blocks() {
        let p = parse("T0505 ;grooving blade 3 mm\nG0 X1;G1 Z2 F.1;\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert_eq!(notes(&p).len(), 1);
        assert!(notes(&p)[0].contains("after ';'"));
        let p = parse("G0 X1 ; (note) G1 Z2\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        // macro words are not prose: they stay code (and are refused as code)
        assert!(parse("G0 X1 ; IF [#1 EQ 2] GOTO 5\n").is_err());
    }

    #[test]
    fn comments_unclosed_nested_and_with_percent() {
        let p = parse("G1 X1 (open\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        assert!(notes(&p)[0].contains("not closed"));
        // FANUC's reading where the parentheses do not balance: ends at the first ')'
        let p = parse("(TOOL 3 (55 DEG) RH) X1").unwrap();
        assert!(notes(&p)[0].contains("nested"));
        assert_eq!(p.programs[0].blocks.all()[0].words.len(), 1);
        // where they do not balance, FANUC's reading: the comment ends at the first ')'
        let e = parse("(A (B) C").unwrap_err();
        assert!(e.message.contains("C has no value"), "{}", e.message);
        assert_eq!(e.span.column, 8);
        let p = parse("G1 X1 (50% FEED)\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        assert!(notes(&p)[0].contains("'%' inside a comment"));
    }

    #[test]
    fn program_and_sequence_numbers_and_block_delete_levels() {
        assert!(parse("O0\nG0 X1").unwrap_err().message.contains("O0"));
        assert!(parse("N0 G0 X1").unwrap_err().message.contains("N0"));
        assert_eq!(
            parse(":1234\nG0 X1").unwrap().programs[0].number,
            Some(1234)
        );
        let p = parse("/2 G0 X1\nN20 /X2\n/G0 X3").unwrap();
        let levels: Vec<u8> = p.programs[0]
            .blocks
            .iter()
            .map(|b| b.delete_level)
            .collect();
        assert_eq!(levels, [2, 1, 1]);
        assert!(p.programs[0].blocks.iter().all(|b| b.block_delete));
    }

    #[test]
    fn decimal_comma_is_an_error_unless_asked_for() {
        let e = parse("G1 X56,08 F0,2").unwrap_err();
        assert!(e.message.contains("decimal comma"), "{}", e.message);
        assert_eq!(e.span.column, 7);
        let p = parse_with(
            "G1 X56,08 F0,2",
            ReadOptions {
                decimal_comma: true,
                ..ReadOptions::default()
            },
        )
        .unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words[1].value, 56.08);
        assert_eq!(p.programs[0].blocks.all()[0].words[2].value, 0.2);
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let e = parse("（中文）X").unwrap_err();
        assert_eq!(e.span.column, 5);
    }

    fn macro_b(src: &str) -> Result<Program, ParseError> {
        parse_with(
            src,
            ReadOptions {
                macros: Some(Dialect::Fanuc),
                ..ReadOptions::default()
            },
        )
    }

    #[test]
    fn macro_statements_and_expression_words_with_spans() {
        let p = macro_b("N5 #1 = 2 + 3 * 4 ;\nWHILE [#1 GT 2] DO1\nG00 X#1 Z[#2-0.5] F0.2 (C)\nEND1\n#3000 = 1 (TOOL BROKEN) ;\n").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!(b.len(), 5);
        assert_eq!(b[0].seq, Some(5));
        let s = b[0].stmt.as_ref().unwrap();
        assert_eq!((s.span.line, s.span.column), (1, 4));
        assert!(b[0].words.is_empty());
        assert!(matches!(
            b[1].stmt.as_ref().unwrap().kind,
            macro_b::StmtKind::While { id: 1, .. }
        ));
        let w = &b[2].words;
        assert_eq!(w.len(), 4);
        assert_eq!(w[1].expr.as_ref().unwrap().to_string(), "#1");
        assert_eq!((w[1].span.column, w[1].span.len), (5, 3));
        let z = w[2].expr.as_ref().unwrap();
        assert_eq!(z.to_string(), "[#2-0.5]");
        assert_eq!((w[2].span.column, z.span.column), (9, 10));
        assert_eq!(
            (w[3].letter, w[3].value, w[3].expr.is_none()),
            ('F', 0.2, true)
        );
        assert!(matches!(
            b[3].stmt.as_ref().unwrap().kind,
            macro_b::StmtKind::End { id: 1 }
        ));
        let macro_b::StmtKind::Assign { comment, .. } = &b[4].stmt.as_ref().unwrap().kind else {
            panic!("an assignment")
        };
        assert_eq!(comment.as_deref(), Some("TOOL BROKEN"));
        // functions and signs as word values, G#10, spaces and ';' between blocks
        let p = macro_b("G#10 X-#1 Z ROUND[#2];IF [#1 EQ #0] GOTO 10;GOTO#3").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!(b.len(), 3);
        assert!(b[0].words.iter().all(|w| w.expr.is_some()));
        assert!(b[1].stmt.is_some() && b[2].stmt.is_some());
        // plain programs read as before
        assert_eq!(macro_b("G0 X1 Z2").unwrap(), parse("G0 X1 Z2").unwrap());
    }

    #[test]
    fn macro_errors_at_their_column() {
        // without macro B a # is an error that says how to turn it on
        let e = parse("G0 X1\nG1 X#1").unwrap_err();
        assert_eq!((e.span.line, e.span.column), (2, 5));
        assert!(e.message.contains("needs custom macro B"), "{}", e.message);
        assert!(e.message.contains("--control fanuc-a"), "{}", e.message);
        let e = macro_b("#1 = [2 + 3").unwrap_err();
        assert_eq!(e.span.line, 1);
        let e = macro_b("G0 X#1 X2").unwrap_err();
        assert!(e.message.contains("twice"), "{}", e.message);
        let e = macro_b("N#1 G0").unwrap_err();
        assert!(e.message.contains("N needs a number"), "{}", e.message);
        let e = macro_b("G0 X1#2").unwrap_err();
        assert_eq!(e.span.column, 6);
        let e = macro_b("#1 = 5 / \n").unwrap_err();
        assert_eq!(e.span.line, 1);
    }

    #[test]
    fn g_code_tenths() {
        let p = parse("G75.1 G01 G0").unwrap();
        let codes: Vec<_> = p.programs[0].blocks.all()[0]
            .words
            .iter()
            .map(|w| w.code_tenths())
            .collect();
        assert_eq!(codes, vec![Some(751), Some(10), Some(0)]);
    }

    #[test]
    fn numbers_written_in_pieces_keep_their_spans() {
        // a number in one piece is a slice of the source; in pieces it is copied
        let p = parse("G1 X1 2.5(c)0\u{11}1 Z-3\n").unwrap();
        let w = &p.programs[0].blocks.all()[0].words;
        assert_eq!((w[1].value, w[1].has_point), (12.501, true));
        assert_eq!(
            (w[1].span.column, w[1].span.offset, w[1].span.len),
            (4, 3, 12)
        );
        assert_eq!((w[2].value, w[2].span.column, w[2].span.len), (-3.0, 17, 3));
        let comma = ReadOptions {
            decimal_comma: true,
            ..ReadOptions::default()
        };
        let p = parse_with("X1 2,5 Z3,25", comma).unwrap();
        let w = &p.programs[0].blocks.all()[0].words;
        assert_eq!((w[0].value, w[1].value), (12.5, 3.25));
        assert_eq!((w[0].span.len, w[1].span.len), (6, 5));
        let e = parse_with("X1,2,3", comma).unwrap_err();
        assert!(
            e.message.contains("malformed number '1.2.3'"),
            "{}",
            e.message
        );
        // the 21st character of a number is refused where it stands, in one piece or not
        let e = parse("X123456789012345678901").unwrap_err();
        assert!(e.message.contains("too long"), "{}", e.message);
        assert_eq!((e.span.column, e.span.len), (1, 22));
        let e = parse("X1234567890 1234567890 1").unwrap_err();
        assert_eq!((e.span.column, e.span.len), (1, 24));
        // after a full-width space and comment, columns count characters
        let e = parse("\u{3000}（注）X1 Y").unwrap_err();
        assert_eq!((e.span.column, e.span.offset), (8, 15));
    }

    #[test]
    fn prose_after_a_later_semicolon_of_the_same_line() {
        // the rest after the first ';' is no prose, so neither is the rest after the second
        let p = parse("G0 X1;G1 Z2;G3 X4\n").unwrap();
        assert_eq!((p.programs[0].blocks.len(), p.notes.len()), (3, 0));
        // but inside '(' the first test saw no prose where the second does
        let p = parse("G0 X1; G1 ((x) ; ab\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert!(notes(&p)[0].contains("after ';'"), "{:?}", notes(&p));
    }

    /// Blocks read again from the text ([`Blocks`]) are the blocks the reader read, for the
    /// starts a block can have: an O or `:` on the block's line, `/2`, an N word before
    /// `/`, a comma address, `;` between blocks and prose after one, a lone CR, non-ASCII
    /// text before a block on its line, a leader, comments before the block, macro
    /// statements, Haas `IF … THEN`, expressions, `M98 (path)`, and the closing `%`.
    #[test]
    fn blocks_read_again_are_the_blocks_read() {
        let texts = [
            "%\nO1000 G0 X1. Z2.\n:2000 G1 X3\n/2 G0 X4\nN5 /G1 Z-1.\nG1 X5. ,C1.\nG1 Z-9 , R 2.\nM30\n%\n",
            "G0 X1;G1 Z2; ;N7 X3 ; this is prose\rG0 X9\r\nM30",
            "(\u{e9}\u{e9}) G0 X1\n\u{3000}G1 Z-2. F0.1 (note)\n  N10 G0 X5\nM30",
            "LEADER TEXT\n%\nO0001 (TITLE)\n#1=2.5\nN10 G0 X#1 Z[#1+1]\nWHILE[#1LT5]DO1\n#1=#1+1\nEND1\nIF[#1GT2]GOTO10\nM98 (sub.nc) P1\nM30\n%\ntrailer",
            "O0002\nIF [#1 EQ 0] THEN G0 X1.\nG65 P9010 A1. I2. I3.\nM30\nO9010\nG0 X#1\nM99\n",
        ];
        for text in texts {
            let read = read_as_held(text);
            assert!(!read.is_empty(), "{text:?}");
            for p in read {
                assert!(p.block_count() > 0, "{text:?}");
                for sub in &p.programs {
                    // one reader for all, as a chunk read ahead is
                    assert_eq!(sub.blocks.read(0..sub.blocks.len()), sub.blocks.all());
                    for (i, b) in sub.blocks.iter().enumerate() {
                        assert_eq!(sub.blocks.seq(i), b.seq);
                        assert_eq!(sub.blocks.block_delete(i), b.block_delete);
                        assert_eq!(sub.blocks.ends_program(i), b.ends_program());
                    }
                    assert_eq!(
                        sub.blocks.has_macro(),
                        sub.blocks.iter().any(|b| b.has_macro())
                    );
                }
            }
        }
        let p = parse_with(
            texts[3],
            ReadOptions {
                macros: Some(Dialect::Fanuc),
                ..ReadOptions::default()
            },
        )
        .unwrap();
        assert!(p.programs[0].blocks.has_macro());
        assert!(p.programs[0].blocks.positions_seq(10).eq([1]));
    }

    /// Plain blocks are read in one go (`read::plain`); the reference
    /// reading reads them character by character. Both give the same blocks, notes and
    /// errors, also for the blocks the quick reading must leave to the loop.
    #[test]
    fn plain_blocks_read_in_one_go_read_as_the_loop_reads_them() {
        let texts = [
            "G00 X1. Z2.\nG01 Z-5.0000 F0.1;\nN20 G1 X+.5 Z-0.;\n",
            "\tg1 x1 z2\r\nG1\tX3 ;\r\n\r\nM30\r\n",
            "G1 X1 .5\n",
            "G1 X1. X2.\n",
            "G65 P9010 I1. I2. J3.\nM30\n",
            "N0 G1 X1\n",
            "N1.5 G1 X1\n",
            "N1 N2 G1 X1\n",
            "N123456789 G1\n",
            "G1 X1234567890.\n",
            "G1 X12345678901234567890\n",
            "G1 X1234567890123456789\n",
            "G1 X-\n",
            "G1 X--5\n",
            "G1 X1.2.3\n",
            "GX1\n",
            "G1 X1\rG1 Z2\n",
            "G1 X1 \u{11} Z2\n",
            "O1234 G1 X1\nG1 X2\n",
            "N10 G1 X1 (c)\nN20 /G1\nG1 X1 ,C1.\n",
            "G1 X1; prose here\nG1 X#1\nG1 X-#1\nIF[#1GT1]GOTO10\nN10 #1=2\nG1 X[1]\n",
            "G1 X1\u{3000}Z2\nG1 X1 %\n",
            "G1 X1",
        ];
        for text in texts {
            read_as_held(text);
        }
    }

    /// `text` read under every option set, read again from the text ([`parse_with`]) and
    /// held by the reference reading ([`parse_held`]): the same blocks, notes or error. The
    /// programs read.
    fn read_as_held(text: &str) -> Vec<Program> {
        let mut programs = vec![];
        for macros in [None, Some(Dialect::Fanuc), Some(Dialect::Haas)] {
            for (decimal_comma, x_radius) in [(false, false), (true, false), (false, true)] {
                let options = ReadOptions {
                    decimal_comma,
                    macros,
                    x_radius,
                };
                let read = parse_with(text, options);
                assert_eq!(read, parse_held(text, options), "{text:?} {options:?}");
                programs.extend(read.ok());
            }
        }
        programs
    }

    /// Issue 16/17 memory: a million-line program keeps 20 bytes a block (where it starts,
    /// read again where needed); the blocks being run stay small too (macro parts are
    /// boxed; words exactly as many).
    #[test]
    fn blocks_and_words_stay_compact() {
        assert_eq!(std::mem::size_of::<crate::read::BlockStart>(), 20);
        let p = parse(&"G01 X1. Z2. F0.1;\n".repeat(1000)).unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1000);
        assert_eq!(std::mem::size_of::<Span>(), 16);
        assert!(
            std::mem::size_of::<Word>() <= 40,
            "{}",
            std::mem::size_of::<Word>()
        );
        assert!(
            std::mem::size_of::<Block>() <= 72,
            "{}",
            std::mem::size_of::<Block>()
        );
        let p = parse("G01 X1. Z2. F0.1;\nG00 X3.;\n").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!((b[0].words.len(), b[1].words.len()), (4, 2));
    }
}
