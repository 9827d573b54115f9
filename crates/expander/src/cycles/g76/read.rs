//! Reading a G76 block's words into [`G76Params`]: which form it is written in, the first
//! block's stored values, the second block, and the one-block forms (Haas, FANUC FS15).

use super::error::{G76Error, G76ErrorKind};
use super::*;
use gcode::Word;

/// Which layout a G76 block is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Form {
    /// `G76 P(m r a) Q(Δdmin) R(d)`: only stores values.
    First,
    /// `G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)`.
    Second,
    /// `G76 X(U) Z(W) K D …` (Haas, FS15).
    OneBlock,
}

/// The layout of a G76 block. `get` looks a word up by letter without consuming it
/// (`Block::get`). J or H: `LinuxCNC`; K or D: one-block; X/Z/U/W: second block; F without an
/// end point: a second block missing it; else a first block. Whether the dialect admits the
/// form (`fs15_format`, `haas`, `gsk980`) is the caller's check.
pub(crate) fn classify<'w>(get: impl Fn(char) -> Option<&'w Word>) -> Result<Form, G76Error> {
    if let Some(w) = get('J').or_else(|| get('H')) {
        return Err(G76Error::new(
            G76ErrorKind::LinuxCnc,
            At::word(w.letter, Some(w)),
        ));
    }
    let end = ['X', 'Z', 'U', 'W'].iter().any(|&l| get(l).is_some());
    let one = get('K').is_some() || get('D').is_some();
    match (end, one) {
        (true, true) => Ok(Form::OneBlock),
        (true, false) => Ok(Form::Second),
        (false, true) => Err(G76Error {
            kind: G76ErrorKind::NoEndPoint,
            at: None,
        }),
        (false, false) if get('F').is_some() => Err(G76Error {
            kind: G76ErrorKind::NoEndPoint,
            at: None,
        }),
        (false, false) => Ok(Form::First),
    }
}

/// A least-increment word (no decimal point when `mm_per_unit` < 1) in mm.
fn increments(letter: char, w: Option<&Word>, mm_per_unit: f64) -> Result<Option<f64>, G76Error> {
    let Some(w) = w else { return Ok(None) };
    if mm_per_unit < 1.0 && w.has_point {
        return Err(G76Error::new(
            G76ErrorKind::DecimalPoint { mm_per_unit },
            At::word(letter, Some(w)),
        ));
    }
    Ok(Some(w.value * mm_per_unit))
}

/// Read `G76 P(m)(r)(a) Q(Δdmin) R(d)`. Absent words keep `prev` (the retained values).
/// `pq_mm`: mm per P/Q unit (`Machine::pq_mm`, times 25.4 under G20 for inch increments);
/// `unit`: 1, or 25.4 under G20, for R.
pub(crate) fn read_first<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    prev: &FirstBlock,
    pq_mm: f64,
    unit: f64,
) -> Result<FirstBlock, G76Error> {
    let mut f = *prev;
    if let Some(p) = get('P') {
        let at = At::word('P', Some(p));
        let v = p.value;
        if p.has_point || v.fract() != 0.0 || !(0.0..=999_999.0).contains(&v) {
            return Err(G76Error::new(G76ErrorKind::PDigits { value: v }, at));
        }
        let v = v as u32;
        let (m, r, a) = (v / 10_000, v / 100 % 100, v % 100);
        if m == 0 {
            return Err(G76Error::new(G76ErrorKind::NoFinishingPass, at));
        }
        if !TOOL_ANGLES.contains(&a) {
            return Err(G76Error::new(
                G76ErrorKind::ToolAngle {
                    a: f64::from(a),
                    one_block: false,
                },
                at,
            ));
        }
        (f.m, f.r, f.a, f.p_at) = (m, r, a, Some(p.span));
    }
    if let Some(q) = get('Q') {
        let dmin = increments('Q', Some(q), pq_mm)?.unwrap_or(0.0);
        if dmin < 0.0 {
            return Err(G76Error::new(
                G76ErrorKind::MinDepth { dmin },
                At::word('Q', Some(q)),
            ));
        }
        (f.dmin, f.q_at) = (dmin, Some(q.span));
    }
    if let Some(r) = get('R') {
        (f.d, f.r_at) = (r.value * unit, Some(r.span));
    }
    Ok(f)
}

/// The lead: F (or Haas E) of the block, else the F in force (mm/rev, already in mm).
fn lead<'w>(
    f: Option<&'w Word>,
    e: Option<&'w Word>,
    in_force: Option<f64>,
    unit: f64,
) -> Result<(f64, At), G76Error> {
    match (f, e) {
        (Some(_), Some(w)) => Err(G76Error::new(
            G76ErrorKind::LeadTwice,
            At::word('E', Some(w)),
        )),
        (Some(w), None) => Ok((w.value * unit, At::word('F', Some(w)))),
        (None, Some(w)) => Ok((w.value * unit, At::word('E', Some(w)))),
        (None, None) => match in_force {
            Some(l) => Ok((l, At::letter('F'))),
            None => Err(G76Error::new(
                G76ErrorKind::Missing { what: "the lead" },
                At::letter('F'),
            )),
        },
    }
}

/// The letters of the end point that were written.
fn end_at<'w>(get: &mut impl FnMut(char) -> Option<&'w Word>) -> (At, At) {
    let x = match get('X') {
        Some(w) => At::word('X', Some(w)),
        None => At::word('U', get('U')),
    };
    let z = match get('Z') {
        Some(w) => At::word('Z', Some(w)),
        None => At::word('W', get('W')),
    };
    (x, z)
}

/// Read `G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)` with the retained first block. `end`: the end
/// point resolved by the caller (G54 frame, radius); `f_in_force`: the modal F in mm when the
/// block has none; `chamfer_angle`: parameter No. 5131 (45°).
pub(crate) fn read_second<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    first: &FirstBlock,
    end: Pt,
    f_in_force: Option<f64>,
    pq_mm: f64,
    unit: f64,
    chamfer_angle: f64,
) -> Result<G76Params, G76Error> {
    let (x, z) = end_at(&mut get);
    let r = get('R');
    let p = get('P');
    let q = get('Q');
    let k = increments('P', p, pq_mm)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the thread height k, radius, in least increments",
            },
            At::letter('P'),
        )
    })?;
    let dd = increments('Q', q, pq_mm)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the first depth Δd, radius, in least increments",
            },
            At::letter('Q'),
        )
    })?;
    let (lead, lead_at) = lead(get('F'), None, f_in_force, unit)?;
    let first_p = At {
        letter: 'P',
        span: first.p_at,
    };
    Ok(G76Params {
        m: first.m,
        chamfer_leads: f64::from(first.r) / 10.0,
        chamfer_angle,
        a: f64::from(first.a),
        dmin: first.dmin,
        d: first.d,
        end,
        i: r.map_or(0.0, |w| w.value * unit),
        k,
        dd,
        lead,
        law: DepthLaw::ConstantAmount,
        edges: Edges::One,
        start_angle: 0.0,
        at: Sources {
            m: first_p,
            chamfer: first_p,
            a: first_p,
            dmin: At {
                letter: 'Q',
                span: first.q_at,
            },
            d: At {
                letter: 'R',
                span: first.r_at,
            },
            x,
            z,
            i: At::word('R', r),
            k: At::word('P', p),
            dd: At::word('Q', q),
            lead: lead_at,
        },
    })
}

/// Read the one-block form `G76 X(U) Z(W) K D [I] [A] [P] [Q] F(E)` (Haas §3.5, FS15 §4.5).
/// `end`, `f_in_force`, `unit` as for [`read_second`]; the rest comes from `cfg`.
pub(crate) fn read_one_block<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    end: Pt,
    f_in_force: Option<f64>,
    unit: f64,
    cfg: &OneBlockConfig,
) -> Result<G76Params, G76Error> {
    let (x, z) = end_at(&mut get);
    let length = |letter: char, w: Option<&Word>| -> Result<Option<f64>, G76Error> {
        match cfg.kd_mm_per_unit {
            Some(mm) => increments(letter, w, mm),
            None => Ok(w.map(|w| w.value * unit)),
        }
    };
    let kw = get('K');
    let dw = get('D');
    let required = |letter: char, w: Option<&Word>, what: &'static str| {
        length(letter, w)?
            .ok_or_else(|| G76Error::new(G76ErrorKind::Missing { what }, At::letter(letter)))
    };
    let k = required('K', kw, "the thread height, radius")?;
    let dd = required('D', dw, "the first depth of cut, radius")?;
    let iw = get('I');
    let i = iw.map_or(0.0, |w| w.value * unit);
    let aw = get('A');
    let a = tool_angle(aw, cfg)?;
    let pw = get('P');
    let (law, edges) = infeed(pw)?;
    let qw = get('Q');
    let start_angle = start_angle(qw)?;
    let e = if cfg.flavor == Flavor::Haas {
        get('E')
    } else {
        None
    };
    let (lead, lead_at) = lead(get('F'), e, f_in_force, unit)?;
    let at = Sources {
        x,
        z,
        i: At::word('I', iw),
        k: At::word('K', kw),
        dd: At::word('D', dw),
        a: At::word('A', aw),
        d: At::word('K', kw),
        dmin: At::word('D', dw),
        chamfer: z,
        lead: lead_at,
        ..Sources::one_block()
    };
    Ok(G76Params {
        m: cfg.m,
        chamfer_leads: cfg.chamfer_leads,
        chamfer_angle: cfg.chamfer_angle,
        a,
        dmin: cfg.dmin,
        d: cfg.d,
        end,
        i,
        k,
        dd,
        lead,
        law,
        edges,
        start_angle,
        at,
    })
}

/// The one-block A: the tool angle 0–120 (whole degrees), or the configured one.
fn tool_angle(aw: Option<&Word>, cfg: &OneBlockConfig) -> Result<f64, G76Error> {
    match aw {
        None => Ok(cfg.a),
        Some(w) if w.value.fract() == 0.0 && (0.0..=120.0).contains(&w.value) => Ok(w.value),
        Some(w) => Err(G76Error::new(
            G76ErrorKind::ToolAngle {
                a: w.value,
                one_block: true,
            },
            At::word('A', Some(w)),
        )),
    }
}

/// The one-block P: the infeed, P1 (the default) to P4.
fn infeed(pw: Option<&Word>) -> Result<(DepthLaw, Edges), G76Error> {
    match pw.map(|w| (w.value, w.has_point)) {
        None => Ok((DepthLaw::ConstantAmount, Edges::One)),
        Some((1.0, false)) => Ok((DepthLaw::ConstantAmount, Edges::One)),
        Some((2.0, false)) => Ok((DepthLaw::ConstantAmount, Edges::Alternating)),
        Some((3.0, false)) => Ok((DepthLaw::ConstantDepth, Edges::One)),
        Some((4.0, false)) => Ok((DepthLaw::ConstantDepth, Edges::Alternating)),
        Some((value, _)) => Err(G76Error::new(
            G76ErrorKind::InfeedType { value },
            At::word('P', pw),
        )),
    }
}

/// The one-block Q: the start angle in 0.001° (whole, no point), 0 without Q.
fn start_angle(qw: Option<&Word>) -> Result<f64, G76Error> {
    match qw {
        None => Ok(0.0),
        Some(w)
            if !w.has_point && w.value.fract() == 0.0 && (0.0..=360_000.0).contains(&w.value) =>
        {
            Ok(w.value / 1000.0)
        }
        Some(w) => Err(G76Error::new(
            G76ErrorKind::StartAngle { value: w.value },
            At::word('Q', Some(w)),
        )),
    }
}
