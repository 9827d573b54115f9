//! Macro values: IEEE doubles that may be vacant (spec/dialects.md §5.2).

use std::fmt;

/// A macro value: a number or vacant. Vacant is not 0: it is what `#0` and a variable
/// that was never assigned hold (spec/dialects.md §5.2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Value(Option<f64>);

impl Value {
    /// The vacant value (`#0`).
    pub const VACANT: Self = Self(None);

    /// A number.
    pub fn num(v: f64) -> Self {
        Self(Some(v))
    }

    /// 1.0 for true, 0.0 for false (the result of `EQ`, `LT` …).
    pub fn truth(b: bool) -> Self {
        Self::num(if b { 1.0 } else { 0.0 })
    }

    /// Whether the value is vacant.
    pub fn is_vacant(self) -> bool {
        self.0.is_none()
    }

    /// The number, `None` when vacant.
    pub fn get(self) -> Option<f64> {
        self.0
    }

    /// The number with vacant read as 0, as arithmetic and `GT GE LT LE` do.
    pub fn or_zero(self) -> f64 {
        self.0.unwrap_or(0.0)
    }

    /// As a condition (`IF [#1] …` on Haas, and every `IF`/`WHILE`): true unless the
    /// value is 0 or vacant.
    pub fn is_true(self) -> bool {
        self.0.is_some_and(|v| v != 0.0)
    }

    /// `EQ`: vacant equals only vacant (`#0 EQ #0` true, `0 EQ #0` false).
    pub fn macro_eq(self, other: Self) -> bool {
        match (self.0, other.0) {
            (None, None) => true,
            (Some(a), Some(b)) => a == b,
            _ => false,
        }
    }
}

impl From<f64> for Value {
    fn from(v: f64) -> Self {
        Self::num(v)
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            None => f.write_str("vacant"),
            Some(v) => write!(f, "{v}"),
        }
    }
}

/// Round half away from zero to an integer: `ROUND[2.5]` = 3, `ROUND[-2.5]` = −3, and the
/// rule for M S T P Q and `GOTO` targets (`M#1` with #1 = 3.5 is M04).
pub fn round_half_away(v: f64) -> f64 {
    v.round()
}

/// Round a value given to an address to the address's least increment (X 0.001 mm …),
/// halves away from zero (spec/dialects.md §5.2, S27). `increment` must be > 0.
pub fn round_to_increment(v: f64, increment: f64) -> f64 {
    debug_assert!(increment > 0.0);
    let steps = (v / increment).round();
    // Re-derive through the reciprocal when it is an integer (0.001 → 1000) so the
    // result is the closest double to the decimal value.
    let inv = 1.0 / increment;
    if (inv - inv.round()).abs() < 1e-9 {
        steps / inv.round()
    } else {
        steps * increment
    }
}

/// `FIX`: drop the fraction toward zero.
pub fn fix(v: f64) -> f64 {
    v.trunc()
}

/// `FUP`: raise the fraction away from zero (`FUP[-1.2]` = −2, not −1 as `ceil` gives).
pub fn fup(v: f64) -> f64 {
    if v >= 0.0 {
        v.ceil()
    } else {
        v.floor()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_rules() {
        assert_eq!(round_half_away(2.5), 3.0);
        assert_eq!(round_half_away(-2.5), -3.0);
        assert_eq!(round_half_away(3.5), 4.0);
        assert_eq!(round_half_away(4.49), 4.0);
        assert_eq!(round_to_increment(12.3456, 0.001), 12.346);
        assert_eq!(round_to_increment(-12.3455, 0.001), -12.346);
        assert_eq!(round_to_increment(0.00049, 0.001), 0.0);
        assert_eq!(round_to_increment(1.23456, 0.0001), 1.2346);
        assert_eq!(fix(1.2), 1.0);
        assert_eq!(fix(-1.2), -1.0);
        assert_eq!(fup(1.2), 2.0);
        assert_eq!(fup(-1.2), -2.0);
        assert_eq!(fup(-1.0), -1.0);
    }

    #[test]
    fn vacancy_basics() {
        assert!(Value::VACANT.is_vacant());
        assert!(!Value::VACANT.is_true());
        assert!(!Value::num(0.0).is_true());
        assert!(Value::num(-2.0).is_true());
        assert_eq!(Value::VACANT.or_zero(), 0.0);
        assert!(Value::VACANT.macro_eq(Value::VACANT));
        assert!(!Value::num(0.0).macro_eq(Value::VACANT));
        assert_eq!(Value::VACANT.to_string(), "vacant");
    }
}
