//! Evaluation with the exact rules of spec/dialects.md §5.2–§5.4: vacancy, alarms for
//! division by zero and domain errors, and the rounding of values given to addresses.

use crate::span::Span;

use crate::error::{ErrorKind, MacroError, Result};
use crate::expr::{BinOp, Expr, ExprKind, Func, Stmt, StmtKind, VarRef};
use crate::options::{Dialect, Options};
use crate::value::{fix, fup, round_half_away, round_to_increment, Value};
use crate::vars::{System, Variables};

/// The macro state of a run: the variables and the dialect's options. The interpreter
/// keeps one and hands it the machine ([`System`]) on each call.
#[derive(Debug, Clone, Default)]
pub struct MacroState {
    /// All variables.
    pub vars: Variables,
    /// The dialect's rules and limits.
    pub options: Options,
}

/// Snap a trigonometric result that is within rounding noise of a round decimal, so
/// `SIN[30]` is 0.5 and `COS[90]` is 0 rather than 0.49999999999999994 and 6e-17.
fn snap(x: f64) -> f64 {
    let r = (x * 1e12).round() / 1e12;
    if (x - r).abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0) {
        r
    } else {
        x
    }
}

fn to_int(v: f64, span: Span, what: &str) -> Result<i64> {
    let t = v.trunc();
    if t.abs() > 9.0e15 {
        return Err(MacroError::new(
            ErrorKind::Domain,
            span,
            format!("{what}: {v} is too large for an integer operation"),
            "bitwise operators work on integers up to 15 digits",
        ));
    }
    Ok(t as i64)
}

fn domain(span: Span, e: &Expr, message: String) -> MacroError {
    MacroError::new(
        ErrorKind::Domain,
        span,
        format!("{message} in {e}"),
        "check the values the expression reads",
    )
}

impl MacroState {
    /// A fresh state: every variable vacant.
    pub fn new(options: Options) -> Self {
        Self {
            vars: Variables::new(),
            options,
        }
    }

    /// The number a variable reference names (`#[expr]` rounded half away from zero).
    pub fn var_number(&mut self, r: &VarRef, sys: &mut dyn System) -> Result<i64> {
        match r {
            VarRef::Direct(n) => Ok(i64::from(*n)),
            VarRef::Indirect(e) => {
                let v = self.eval(e, sys)?.or_zero();
                Ok(round_half_away(v).clamp(-1e12, 1e12) as i64)
            }
            VarRef::Named(n) => Err(MacroError::syntax(
                Span::default(),
                format!("#<{n}> has no number"),
                "a named parameter is read by name",
            )),
        }
    }

    /// Evaluate an expression. The result is vacant only for a bare vacant variable
    /// (possibly in brackets or with a sign); arithmetic and functions read vacant as 0.
    pub fn eval(&mut self, e: &Expr, sys: &mut dyn System) -> Result<Value> {
        match &e.kind {
            ExprKind::Num(v) => Ok(Value::num(*v)),
            ExprKind::Var(VarRef::Named(name)) => match self.vars.named(name) {
                Some(v) => Ok(v),
                None => match sys.named_parameter(name) {
                    Some(v) => Ok(Value::num(v)),
                    None => self.vars.read_named(name, e.span),
                },
            },
            ExprKind::Var(r) => {
                let n = self.var_number(r, sys)?;
                let options = self.options;
                let v = self.vars.read(n, e.span, &options, sys)?;
                // LinuxCNC has no vacant value: a parameter never set reads 0
                Ok(match options.dialect {
                    Dialect::LinuxCnc => Value::num(v.or_zero()),
                    _ => v,
                })
            }
            ExprKind::Call(Func::Exists, args) => {
                let defined = matches!(&args[0].kind, ExprKind::Var(VarRef::Named(n))
                    if self.vars.named(n).is_some() || sys.named_parameter(n).is_some());
                Ok(Value::truth(defined))
            }
            ExprKind::Group(inner) | ExprKind::Pos(inner) => self.eval(inner, sys),
            ExprKind::Neg(inner) => {
                let v = self.eval(inner, sys)?;
                Ok(v.get().map_or(Value::VACANT, |x| Value::num(-x)))
            }
            ExprKind::Binary(op, a, b) => {
                let x = self.eval(a, sys)?;
                let y = self.eval(b, sys)?;
                self.binary(*op, x, y, e)
            }
            ExprKind::Call(f, args) => {
                let mut xs = [0.0; 2];
                for (slot, a) in xs.iter_mut().zip(args) {
                    *slot = self.eval(a, sys)?.or_zero();
                }
                self.call(*f, &xs[..args.len()], e)
            }
        }
    }

    fn binary(&self, op: BinOp, x: Value, y: Value, e: &Expr) -> Result<Value> {
        let (a, b) = (x.or_zero(), y.or_zero());
        let r = match op {
            BinOp::Add => a + b,
            BinOp::Sub => a - b,
            BinOp::Mul => a * b,
            BinOp::Div | BinOp::Mod => {
                if op == BinOp::Mod && !self.options.allow_mod {
                    return Err(MacroError::new(
                        ErrorKind::Unsupported,
                        e.span,
                        "MOD is not available on this control (FANUC 0i)",
                        "set macro_mod = true in the machine profile for a 30i, or compute a-FIX[a/b]*b",
                    ));
                }
                if b == 0.0 {
                    let why = if y.is_vacant() {
                        " (the divisor is vacant, which counts as 0)"
                    } else {
                        ""
                    };
                    return Err(MacroError::new(
                        ErrorKind::DivisionByZero,
                        e.span,
                        format!("division by zero in {e}{why}"),
                        "check the divisor before dividing, e.g. IF [#2 EQ 0] GOTO …",
                    ));
                }
                if op == BinOp::Div {
                    a / b
                } else {
                    a % b
                }
            }
            BinOp::And | BinOp::Or | BinOp::Xor => {
                let i = to_int(a, e.span, op.symbol())?;
                let j = to_int(b, e.span, op.symbol())?;
                (match op {
                    BinOp::And => i & j,
                    BinOp::Or => i | j,
                    _ => i ^ j,
                }) as f64
            }
            BinOp::Eq => return Ok(Value::truth(x.macro_eq(y))),
            BinOp::Ne => return Ok(Value::truth(!x.macro_eq(y))),
            BinOp::Gt => return Ok(Value::truth(a > b)),
            BinOp::Ge => return Ok(Value::truth(a >= b)),
            BinOp::Lt => return Ok(Value::truth(a < b)),
            BinOp::Le => return Ok(Value::truth(a <= b)),
        };
        if !r.is_finite() {
            return Err(domain(e.span, e, "result out of range".into()));
        }
        Ok(Value::num(r))
    }

    fn call(&self, f: Func, xs: &[f64], e: &Expr) -> Result<Value> {
        let x = xs[0];
        let deg = f64::to_radians;
        let r = match f {
            Func::Sin => snap(deg(x).sin()),
            Func::Cos => snap(deg(x).cos()),
            Func::Tan => snap(deg(x).tan()),
            Func::Asin | Func::Acos => {
                if !(-1.0..=1.0).contains(&x) {
                    return Err(domain(
                        e.span,
                        e,
                        format!("{}: {x} is outside -1…1", f.name()),
                    ));
                }
                snap(if f == Func::Asin { x.asin() } else { x.acos() }.to_degrees())
            }
            Func::Atan => {
                let b = xs.get(1).copied().unwrap_or(1.0);
                let mut t = snap(x.atan2(b).to_degrees());
                if !self.options.atan_signed && t < 0.0 {
                    t += 360.0;
                }
                if t >= 360.0 {
                    t -= 360.0;
                }
                t
            }
            Func::Sqrt => {
                if x < 0.0 {
                    return Err(domain(e.span, e, format!("SQRT of the negative {x}")));
                }
                x.sqrt()
            }
            Func::Abs => x.abs(),
            Func::Round => round_half_away(x),
            Func::Fix => fix(x),
            Func::Fup => fup(x),
            Func::Ln => {
                if x <= 0.0 {
                    return Err(domain(e.span, e, format!("LN of {x} (must be > 0)")));
                }
                x.ln()
            }
            Func::Exp => x.exp(),
            Func::Pow => x.powf(xs[1]),
            Func::Adp => x * self.options.adp_scale,
            Func::Exists => unreachable!("EXISTS is answered before its argument is read"),
            Func::Bin | Func::Bcd => {
                let i = to_int(x, e.span, f.name())?;
                if i < 0 {
                    return Err(domain(e.span, e, format!("{}: {x} is negative", f.name())));
                }
                if f == Func::Bin {
                    // BCD nibbles to binary: BIN[37] (0x25) = 25
                    let (mut v, mut scale, mut k) = (0i64, 1i64, i);
                    while k > 0 {
                        let d = k & 0xF;
                        if d > 9 {
                            return Err(domain(e.span, e, format!("BIN: {x} is not a BCD value")));
                        }
                        v += d * scale;
                        scale *= 10;
                        k >>= 4;
                    }
                    v as f64
                } else {
                    // binary to BCD nibbles: BCD[25] = 37 (0x25)
                    let (mut v, mut shift, mut k) = (0i64, 0u32, i);
                    while k > 0 {
                        if shift >= 60 {
                            return Err(domain(e.span, e, format!("BCD: {x} is too large")));
                        }
                        v |= (k % 10) << shift;
                        shift += 4;
                        k /= 10;
                    }
                    v as f64
                }
            }
        };
        if !r.is_finite() {
            return Err(domain(e.span, e, "result out of range".into()));
        }
        Ok(Value::num(r))
    }

    /// A condition of `IF`/`WHILE`: true unless the value is 0 or vacant.
    pub fn condition(&mut self, e: &Expr, sys: &mut dyn System) -> Result<bool> {
        Ok(self.eval(e, sys)?.is_true())
    }

    /// The value of an NC address written with an expression (`X#1`, `Z[#2-0.5]`),
    /// rounded to the address's least `increment` (halves away from zero). `None`: the
    /// value is vacant and the address counts as not written (`G00 X#1 Z5.` with #1
    /// vacant is `G00 Z5.`). `ROUND[x]` written directly as the value rounds `x` to the
    /// increment, not to an integer (spec §5.4).
    pub fn address_value(
        &mut self,
        e: &Expr,
        increment: f64,
        sys: &mut dyn System,
    ) -> Result<Option<f64>> {
        let v = match &e.kind {
            ExprKind::Call(Func::Round, args) => Value::num(self.eval(&args[0], sys)?.or_zero()),
            _ => self.eval(e, sys)?,
        };
        Ok(v.get().map(|x| round_to_increment(x, increment)))
    }

    /// The value of an integer address (M S T P Q, `G#1`): rounded half away from zero
    /// (`M#1` with #1 = 3.5 is M04). `None` when vacant.
    pub fn integer_value(&mut self, e: &Expr, sys: &mut dyn System) -> Result<Option<i64>> {
        let v = self.eval(e, sys)?;
        match v.get() {
            None => Ok(None),
            Some(x) => {
                let r = round_half_away(x);
                if r.abs() > 9.0e15 {
                    return Err(domain(e.span, e, format!("{x} is out of range")));
                }
                Ok(Some(r as i64))
            }
        }
    }

    /// A value that must not be vacant (a required address, a `GOTO` target): vacant is an
    /// alarm naming `what`.
    pub fn required(&mut self, e: &Expr, what: &str, sys: &mut dyn System) -> Result<f64> {
        self.eval(e, sys)?.get().ok_or_else(|| {
            MacroError::new(
                ErrorKind::Vacant,
                e.span,
                format!("{what}: {e} is vacant"),
                "give the variable a value before this block",
            )
        })
    }

    /// The sequence number a jump names (`GOTO n`, `GOTO #1`, `GOTO [expr]`; `what` says
    /// which): required, rounded half away from zero (4.5 → 5), 1–99999999.
    pub fn sequence_number(&mut self, e: &Expr, what: &str, sys: &mut dyn System) -> Result<u32> {
        let Some(v) = self.eval(e, sys)?.get() else {
            return Err(MacroError::new(
                ErrorKind::Vacant,
                e.span,
                format!("{what} target: {e} is vacant"),
                "give the variable a value before this block",
            ));
        };
        let n = round_half_away(v);
        if !(1.0..=99_999_999.0).contains(&n) {
            return Err(MacroError::new(
                ErrorKind::SequenceMissing,
                e.span,
                format!("{what} {n}: sequence numbers are 1–99999999"),
                "jump to an N number that is written in this program",
            ));
        }
        Ok(n as u32)
    }

    /// Run an assignment `#i = expr` (also the one in `IF … THEN`).
    pub fn assign(
        &mut self,
        target: &VarRef,
        target_span: Span,
        value: &Expr,
        comment: Option<&str>,
        sys: &mut dyn System,
    ) -> Result<()> {
        if let VarRef::Named(name) = target {
            let v = self.eval(value, sys)?;
            self.vars.write_named(name, v);
            return Ok(());
        }
        let n = self.var_number(target, sys)?;
        let v = self.eval(value, sys)?;
        let options = self.options;
        self.vars.write(n, v, comment, target_span, &options, sys)
    }

    /// Run a statement that does not move control: an assignment, or `IF … THEN`
    /// assignment. Returns `false` for statements that belong to the flow engine
    /// (`GOTO`, `WHILE`, `END` …), which it leaves alone.
    pub fn execute(&mut self, stmt: &Stmt, sys: &mut dyn System) -> Result<bool> {
        match &stmt.kind {
            StmtKind::Assign {
                target,
                target_span,
                value,
                comment,
            } => {
                self.assign(target, *target_span, value, comment.as_deref(), sys)?;
                Ok(true)
            }
            StmtKind::IfThen { cond, then } => {
                if self.condition(cond, sys)? {
                    self.execute(then, sys)?;
                }
                Ok(true)
            }
            _ => Ok(false),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::{parse_expr, parse_stmt};
    use crate::vars::NoMachine;

    fn st() -> MacroState {
        MacroState::new(Options::fanuc())
    }

    fn ev(s: &mut MacroState, text: &str) -> Result<Value> {
        let e = parse_expr(text, Span::default()).unwrap();
        s.eval(&e, &mut NoMachine)
    }

    fn num(s: &mut MacroState, text: &str) -> f64 {
        ev(s, text)
            .unwrap_or_else(|e| panic!("{text}: {e}"))
            .get()
            .unwrap_or_else(|| panic!("{text} is vacant"))
    }

    fn run(s: &mut MacroState, text: &str) -> Result<()> {
        let st = parse_stmt(text, Span::default(), &s.options.clone()).unwrap();
        assert!(s.execute(&st, &mut NoMachine)?);
        Ok(())
    }

    /// spec §5.2, the vacancy table, row by row.
    #[test]
    fn vacancy_table() {
        let mut s = st();
        // `#1 = #0` → #1 vacant
        run(&mut s, "#1 = 5").unwrap();
        run(&mut s, "#1 = #0").unwrap();
        assert!(ev(&mut s, "#1").unwrap().is_vacant());
        // `#2 = #1` (#1 vacant) → #2 vacant
        run(&mut s, "#2 = 7").unwrap();
        run(&mut s, "#2 = #1").unwrap();
        assert!(ev(&mut s, "#2").unwrap().is_vacant());
        // `#0 + 1`, `1 + #0` → 1
        assert_eq!(num(&mut s, "#0 + 1"), 1.0);
        assert_eq!(num(&mut s, "1 + #0"), 1.0);
        // `#0 + #0`, `#0 * 10`, `#0 - #0` → 0
        assert_eq!(num(&mut s, "#0 + #0"), 0.0);
        assert_eq!(num(&mut s, "#0 * 10"), 0.0);
        assert_eq!(num(&mut s, "#0 - #0"), 0.0);
        // `5 / #0` → division by zero alarm
        let e = ev(&mut s, "5 / #0").unwrap_err();
        assert_eq!(e.kind, ErrorKind::DivisionByZero);
        // `#0 / 5` → 0
        assert_eq!(num(&mut s, "#0 / 5"), 0.0);
        // function of vacant = function of 0
        assert_eq!(num(&mut s, "SIN[#0]"), 0.0);
        assert_eq!(num(&mut s, "ABS[#0]"), 0.0);
        assert_eq!(num(&mut s, "COS[#0]"), 1.0);
        // address with a vacant variable: dropped
        let e = parse_expr("#1", Span::default()).unwrap();
        assert_eq!(s.address_value(&e, 0.001, &mut NoMachine).unwrap(), None);
        let e = parse_expr("-#1", Span::default()).unwrap();
        assert_eq!(s.address_value(&e, 0.001, &mut NoMachine).unwrap(), None);
        // address with an expression containing vacant: X[#1+10] → X10
        let e = parse_expr("[#1+10]", Span::default()).unwrap();
        assert_eq!(
            s.address_value(&e, 0.001, &mut NoMachine).unwrap(),
            Some(10.0)
        );
        // EQ, NE: vacant differs from 0
        assert_eq!(num(&mut s, "#0 EQ #0"), 1.0);
        assert_eq!(num(&mut s, "0 EQ #0"), 0.0);
        assert_eq!(num(&mut s, "#0 NE 0"), 1.0);
        // GT GE LT LE: vacant counts as 0
        assert_eq!(num(&mut s, "#0 GE 0"), 1.0);
        assert_eq!(num(&mut s, "#0 GT 0"), 0.0);
        assert_eq!(num(&mut s, "0 LE #0"), 1.0);
        assert_eq!(num(&mut s, "#0 LT 0"), 0.0);
        // condition without operator: true unless 0 or vacant
        let c = |s: &mut MacroState, t: &str| {
            let e = parse_expr(t, Span::default()).unwrap();
            s.condition(&e, &mut NoMachine).unwrap()
        };
        assert!(!c(&mut s, "[#1]"));
        assert!(!c(&mut s, "[0]"));
        assert!(c(&mut s, "[-0.5]"));
    }

    /// spec §5.3, the precedence table, row by row (values).
    #[test]
    fn precedence_table() {
        let mut s = st();
        // level 1: brackets
        assert_eq!(num(&mut s, "[2 + 3] * 4"), 20.0);
        // level 2: functions and unary bind tighter than * /
        assert_eq!(num(&mut s, "SQRT[16] * 2"), 8.0);
        assert_eq!(num(&mut s, "-2 * -3"), 6.0);
        assert_eq!(num(&mut s, "ABS[-3] - 5"), -2.0);
        // level 3: * / AND MOD over + - OR XOR, left to right
        assert_eq!(num(&mut s, "2 + 3 * 4"), 14.0);
        assert_eq!(num(&mut s, "12 / 3 * 2"), 8.0);
        assert_eq!(num(&mut s, "1 OR 6 AND 3"), 3.0); // 1 | (6 & 3)
        s.options.allow_mod = true;
        assert_eq!(num(&mut s, "27 MOD 20"), 7.0);
        assert_eq!(num(&mut s, "1 + 27 MOD 20 * 1"), 8.0);
        // level 4: + - OR XOR left to right
        assert_eq!(num(&mut s, "10 - 4 - 3"), 3.0);
        assert_eq!(num(&mut s, "5 XOR 1 + 2"), 6.0); // (5 ^ 1) + 2
        assert_eq!(num(&mut s, "12 OR 3"), 15.0);
        // level 5: comparisons last; 1.0 / 0.0
        assert_eq!(num(&mut s, "1 + 1 EQ 2"), 1.0);
        assert_eq!(num(&mut s, "[1 LT 5]"), 1.0);
        assert_eq!(num(&mut s, "2 * 3 GT 5 + 1"), 0.0);
        // combining comparisons acts as logical and/or
        run(&mut s, "#1 = 4").unwrap();
        run(&mut s, "#2 = 9").unwrap();
        assert_eq!(num(&mut s, "[#1 GT 3] AND [#2 LT 10]"), 1.0);
        assert_eq!(num(&mut s, "[#1 GT 5] OR [#2 LT 5]"), 0.0);
    }

    #[test]
    fn functions() {
        let mut s = st();
        assert_eq!(num(&mut s, "SIN[30]"), 0.5);
        assert_eq!(num(&mut s, "COS[60]"), 0.5);
        assert_eq!(num(&mut s, "COS[90]"), 0.0);
        assert_eq!(num(&mut s, "TAN[45]"), 1.0);
        assert_eq!(num(&mut s, "ASIN[0.5]"), 30.0);
        assert_eq!(num(&mut s, "ASIN[-1]"), -90.0);
        assert_eq!(num(&mut s, "ACOS[-1]"), 180.0);
        assert_eq!(num(&mut s, "ATAN[1]/[-1]"), 135.0);
        assert_eq!(num(&mut s, "ATAN[-1,-1]"), 225.0);
        assert_eq!(num(&mut s, "ATAN[-1]"), 315.0);
        assert_eq!(num(&mut s, "ATAN[0]/[1]"), 0.0);
        s.options.atan_signed = true;
        assert_eq!(num(&mut s, "ATAN[-1,-1]"), -135.0);
        assert_eq!(num(&mut s, "ROUND[1.714]"), 2.0);
        assert_eq!(num(&mut s, "ROUND[3.54]"), 4.0);
        assert_eq!(num(&mut s, "ROUND[-2.5]"), -3.0);
        assert_eq!(num(&mut s, "FIX[1.2]"), 1.0);
        assert_eq!(num(&mut s, "FIX[-1.2]"), -1.0);
        assert_eq!(num(&mut s, "FUP[1.2]"), 2.0);
        assert_eq!(num(&mut s, "FUP[-1.2]"), -2.0);
        assert_eq!(num(&mut s, "LN[1]"), 0.0);
        assert_eq!(num(&mut s, "EXP[0]"), 1.0);
        assert_eq!(num(&mut s, "POW[2,10]"), 1024.0);
        assert_eq!(num(&mut s, "BIN[37]"), 25.0);
        assert_eq!(num(&mut s, "BCD[25]"), 37.0);
        assert_eq!(num(&mut s, "ADP[0.01]"), 10.0);
        assert_eq!(num(&mut s, "-7 AND -1"), -7.0);
    }

    #[test]
    fn alarms_with_spans() {
        let mut s = st();
        let base = Span {
            line: 12,
            column: 6,
            offset: 200,
            len: 0,
        };
        let e = parse_expr("1 + 5 / [#1 - #1]", base).unwrap();
        let err = s.eval(&e, &mut NoMachine).unwrap_err();
        assert_eq!(err.kind, ErrorKind::DivisionByZero);
        assert_eq!((err.span.line, err.span.column, err.span.len), (12, 10, 13));
        assert!(err.message.contains("5/[#1-#1]"), "{}", err.message);
        for (text, col) in [
            ("SQRT[-1]", 6),
            ("2 * ASIN[1.5]", 10),
            ("ACOS[-2]", 6),
            ("LN[0]", 6),
            ("LN[-3]", 6),
            ("BIN[10]", 6),
            ("EXP[1000]", 6),
        ] {
            let e = parse_expr(text, base).unwrap();
            let err = s.eval(&e, &mut NoMachine).unwrap_err();
            assert_eq!(err.kind, ErrorKind::Domain, "{text}");
            assert_eq!(err.span.column, col, "{text}");
        }
        let e = parse_expr("5 MOD 2", base).unwrap();
        assert_eq!(
            s.eval(&e, &mut NoMachine).unwrap_err().kind,
            ErrorKind::Unsupported
        );
        s.options.allow_mod = true;
        let e = parse_expr("5 MOD 0", base).unwrap();
        assert_eq!(
            s.eval(&e, &mut NoMachine).unwrap_err().kind,
            ErrorKind::DivisionByZero
        );
        // a vacant variable where a value is required
        let e = parse_expr("#7", base).unwrap();
        let err = s.required(&e, "G65 P", &mut NoMachine).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Vacant);
        assert_eq!(err.span.column, 6);
        assert!(err.message.contains("#7 is vacant"));
    }

    #[test]
    fn address_rounding() {
        let mut s = st();
        run(&mut s, "#1 = 3.5").unwrap();
        run(&mut s, "#2 = 12.34567").unwrap();
        let e = parse_expr("#1", Span::default()).unwrap();
        assert_eq!(s.integer_value(&e, &mut NoMachine).unwrap(), Some(4));
        let e = parse_expr("#2", Span::default()).unwrap();
        assert_eq!(
            s.address_value(&e, 0.001, &mut NoMachine).unwrap(),
            Some(12.346)
        );
        // ROUND directly as the value: to the increment
        let e = parse_expr("ROUND[#2]", Span::default()).unwrap();
        assert_eq!(
            s.address_value(&e, 0.001, &mut NoMachine).unwrap(),
            Some(12.346)
        );
        // ROUND inside an expression: to an integer
        let e = parse_expr("[ROUND[#2] + 0.5]", Span::default()).unwrap();
        assert_eq!(
            s.address_value(&e, 0.001, &mut NoMachine).unwrap(),
            Some(12.5)
        );
        // indirect reference rounds its index
        run(&mut s, "#[1.6] = 9").unwrap();
        assert_eq!(num(&mut s, "#2"), 9.0);
        assert_eq!(num(&mut s, "#[#1 - 1.4]"), 9.0);
    }
}
