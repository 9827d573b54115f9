// The body of the `chuck` fuzz target (`fuzz/fuzz_targets/chuck.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
use std::sync::OnceLock;

fn fixtures() -> &'static (stock::Blank, stock::ToolTable, Vec<expander::Segment>) {
    static F: OnceLock<(stock::Blank, stock::ToolTable, Vec<expander::Segment>)> = OnceLock::new();
    F.get_or_init(|| {
        let blank = stock::Blank::bar(40.0, 60.0, 0.0, None).expect("a valid blank");
        let tools = stock::ToolTable::from_toml(
            "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n",
        )
        .expect("a valid tool table");
        let program = gcode::parse("G99 M03 S500 T0101\nG00 X44 Z2\nG01 X0 F0.1\nG00 X44\nG00 Z-70\nG01 X36 Z-20\nG00 X150 Z100\nM30\n")
            .expect("a valid program");
        let tp = expander::expand(&program, &expander::Machine::default(), &Default::default());
        (blank, tools, tp.segments)
    })
}

/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let w = if text.contains('=') && !text.contains('[') {
        expander::Workholding::from_compact(text)
    } else {
        expander::Workholding::from_toml(text)
    };
    let Ok(w) = w else {
        return;
    };
    let (blank, tools, segments) = fixtures();
    if let Ok(Some(fixture)) = analysis::Fixture::new(&w, blank) {
        let _ = fixture.check(tools, segments, 0.001, &[(3, false), (5, true)]);
    }
}
