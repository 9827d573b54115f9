//! Variables: locals per call level, common and retained variables, and the system
//! variables the interpreter answers through [`System`] (spec/dialects.md §5.1, §5.7).

use crate::span::Span;

use crate::arguments::letter_of_argument;
use crate::error::{ErrorKind, MacroError, Result};
use crate::fingerprint::{common_slot, local_slot, share, Snapshot};
use crate::named::{name_slot, Named};
use crate::options::Options;
use crate::value::{round_half_away, Value};

/// The 33 local variables `#1`–`#33` of one call level.
pub type Locals = [Value; 33];

/// An axis of a lathe's position variables (`#5001` X, `#5002` Z).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// X, as a diameter.
    X,
    /// Z.
    Z,
}

/// Which position a position variable reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Position {
    /// `#5001`–`#5002`: end point of the last block, work coordinates.
    BlockEnd,
    /// `#5021`–`#5022`: machine position (work position + active work offset).
    Machine,
    /// `#5041`–`#5042`: current work position.
    Work,
}

/// The timers `#3001` (milliseconds) and `#3002` (hours).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Timer {
    /// `#3001`.
    Millis,
    /// `#3002`.
    Hours,
}

/// The machine state behind the system variables of spec §5.7. The interpreter implements
/// it; every method has a default that answers "not simulated", so an implementation
/// overrides only what it keeps. A `None` (or `false` from a setter) becomes the error
/// "system variable #n not simulated" at the variable's place.
pub trait System {
    /// `#5001`…: a position, X as a diameter.
    fn position(&self, _kind: Position, _axis: Axis) -> Option<f64> {
        None
    }
    /// `#4001`–`#4021`: the modal G code of group 1…21 (`G01` → 1, `G99` → 99).
    fn modal_group(&self, _group: u32) -> Option<f64> {
        None
    }
    /// `#4101`–`#4126`: the last value of an address (`F`, `S`, `T` …); `Some(VACANT)`
    /// when the address was never given.
    fn last_address(&self, _letter: char) -> Option<Value> {
        None
    }
    /// `#3001`/`#3002`: simulated cycle time since the last write.
    fn timer(&self, _timer: Timer) -> Option<f64> {
        None
    }
    /// Write `#3001`/`#3002`. `false`: not simulated.
    fn set_timer(&mut self, _timer: Timer, _value: f64) -> bool {
        false
    }
    /// `#3901` (1) / `#3902` (2): parts counters.
    fn parts_counter(&self, _which: u8) -> Option<f64> {
        None
    }
    /// Write `#3901`/`#3902`. `false`: not simulated.
    fn set_parts_counter(&mut self, _which: u8, _value: f64) -> bool {
        false
    }
    /// `#2001`+: a tool offset, when the profile maps them. `None` gives the error
    /// "tool offset variables not mapped".
    fn tool_offset(&self, _number: u32) -> Option<f64> {
        None
    }
    /// `LinuxCNC`'s predefined named parameter `#<_name>` (`_x`, `_metric` …), when the
    /// machine keeps it.
    fn named_parameter(&self, _name: &str) -> Option<f64> {
        None
    }
    /// `#3006 = n (message)`: stop with a message and continue. `false`: not simulated.
    fn stop_message(&mut self, _number: f64, _message: &str) -> bool {
        false
    }
}

/// A [`System`] that simulates nothing: every system variable is "not simulated".
#[derive(Debug, Clone, Copy, Default)]
pub struct NoMachine;

impl System for NoMachine {}

/// What a variable number names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Class {
    Null,
    Local(usize),
    Common(usize),
    ToolOffset(u32),
    Alarm,
    Stop,
    Timer(Timer),
    Parts(u8),
    Modal(u32),
    LastAddress(char),
    Position(Position, Axis),
    NotSimulated,
    Missing,
}

fn is_common(n: i64) -> bool {
    (100..=199).contains(&n) || (500..=999).contains(&n)
}

fn classify(n: i64, options: &Options) -> Class {
    match n {
        0 => Class::Null,
        1..=33 => Class::Local(n as usize - 1),
        n if is_common(n) => Class::Common(n as usize),
        n if options.is_haas() && n >= 10_000 && is_common(n - 10_000) => {
            Class::Common(n as usize - 10_000)
        }
        2001..=2999 => Class::ToolOffset(n as u32),
        3000 => Class::Alarm,
        3006 => Class::Stop,
        3001 => Class::Timer(Timer::Millis),
        3002 => Class::Timer(Timer::Hours),
        3901 => Class::Parts(1),
        3902 => Class::Parts(2),
        4001..=4021 => Class::Modal((n - 4000) as u32),
        4101..=4126 => match letter_of_argument((n - 4100) as u8) {
            Some(c) => Class::LastAddress(c),
            None => Class::NotSimulated,
        },
        5001 => Class::Position(Position::BlockEnd, Axis::X),
        5002 => Class::Position(Position::BlockEnd, Axis::Z),
        5021 => Class::Position(Position::Machine, Axis::X),
        5022 => Class::Position(Position::Machine, Axis::Z),
        5041 => Class::Position(Position::Work, Axis::X),
        5042 => Class::Position(Position::Work, Axis::Z),
        n if n >= 1000 => Class::NotSimulated,
        _ => Class::Missing,
    }
}

fn not_simulated(n: i64, span: Span) -> MacroError {
    MacroError::new(
        ErrorKind::NotSimulated,
        span,
        format!("system variable #{n} not simulated"),
        "latsim simulates #3000 #3006 #3901 #3902 #4001–#4003 #4005–#4007 #4109 #4119 #4120 #5001 #5002 #5021 #5022 #5041 #5042 (not the timers #3001/#3002, the tool offsets #2001+, other modal groups and addresses)",
    )
}

fn missing(n: i64, span: Span) -> MacroError {
    MacroError::new(
        ErrorKind::NoSuchVariable,
        span,
        format!("variable #{n} does not exist"),
        "locals are #1–#33, common variables #100–#199 and #500–#999, system variables #1000 and up",
    )
}

fn read_only(n: i64, span: Span) -> MacroError {
    MacroError::new(
        ErrorKind::ReadOnly,
        span,
        format!("#{n} is read-only"),
        if n == 0 {
            "#0 is always vacant; to make a variable vacant write #1 = #0"
        } else {
            "system variables that report the machine state cannot be written"
        },
    )
}

/// One line of the variable report: a variable the run read or set, and its final value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VarEntry {
    /// The variable number.
    pub number: u32,
    /// Its value at the end.
    pub value: Value,
    /// The run read it.
    pub read: bool,
    /// The run set it.
    pub set: bool,
}

/// All macro variables of a run: one local set per call level, the common variables
/// (`#100`–`#199` vacant at start, `#500`–`#999` loaded from `--vars`), and a record of
/// which variables of the main level were read and set, for the report.
#[derive(Debug, Clone)]
pub struct Variables {
    levels: Vec<Locals>,
    /// `LinuxCNC`'s named parameters.
    named: Named,
    common: Vec<Value>,
    /// Per variable number below 1000: bit 0 read, bit 1 set (main level and commons).
    touched: Vec<u8>,
    /// The sum of every value's [`share`] (vacant adds nothing), kept as values change: a
    /// loop's state is compared in O(1) before it is compared value by value.
    fingerprint: u64,
}

impl Default for Variables {
    fn default() -> Self {
        Self::new()
    }
}

impl Variables {
    /// Everything vacant, one local level (the main program's).
    pub fn new() -> Self {
        Self {
            levels: vec![[Value::VACANT; 33]],
            named: Named::default(),
            common: vec![Value::VACANT; 1000],
            touched: vec![0; 1000],
            fingerprint: 0,
        }
    }

    /// The call level: 0 in the main program, +1 per `G65` level.
    pub fn level(&self) -> usize {
        self.levels.len() - 1
    }

    /// A new local set for a `G65`/`G66` call: vacant except the arguments.
    pub fn push_level(&mut self, args: Locals) {
        let level = self.levels.len();
        for (i, &v) in args.iter().enumerate() {
            self.fingerprint = self
                .fingerprint
                .wrapping_add(share(local_slot(level, i), v));
        }
        self.levels.push(args);
        self.named.levels.push(Default::default());
    }

    /// Leave a `G65` level (`M99`): its locals are gone. The main level stays.
    pub fn pop_level(&mut self) {
        if self.levels.len() > 1 {
            let level = self.levels.len() - 1;
            for (i, &v) in self.levels[level].iter().enumerate() {
                self.fingerprint = self
                    .fingerprint
                    .wrapping_sub(share(local_slot(level, i), v));
            }
            self.levels.pop();
            if let Some(names) = self.named.levels.pop() {
                for (name, v) in names {
                    self.fingerprint = self
                        .fingerprint
                        .wrapping_sub(share(name_slot(Some(level), &name), v));
                }
            }
        }
    }

    /// The named parameter `#<name>` at the current level (`_` first: the global), if it
    /// is defined.
    pub fn named(&self, name: &str) -> Option<Value> {
        self.named.get(name)
    }

    /// Read `#<name>`: an error at `span` when it is not defined.
    pub fn read_named(&self, name: &str, span: Span) -> Result<Value> {
        self.named.get(name).ok_or_else(|| {
            let help = if crate::named::is_global(name) {
                "set it first (#<_name> = …); of LinuxCNC's predefined parameters latsim keeps #<_value>, #<_value_returned>, #<_x>, #<_z>, #<_metric>, #<_imperial>, #<_absolute>, #<_incremental>, #<_lathe_diameter_mode>, #<_lathe_radius_mode>, #<_units_per_rev>, #<_units_per_minute>, #<_feed>, #<_rpm>, #<_current_tool>"
            } else {
                "set it first at this call level (#<name> = …), or test it with EXISTS[#<name>]"
            };
            MacroError::new(
                ErrorKind::NoSuchVariable,
                span,
                format!("named parameter #<{name}> is not defined"),
                help,
            )
        })
    }

    /// Set `#<name>` (local to the current level, or global with `_` first).
    pub fn write_named(&mut self, name: &str, v: Value) {
        let (map, level) = self.named.map_mut(name);
        let old = map.insert(name.to_string(), v).unwrap_or(Value::VACANT);
        self.refingerprint(name_slot(level, name), old, v);
    }

    /// Forget `#<name>` (the interpreter's own per-level names).
    pub fn remove_named(&mut self, name: &str) {
        let (map, level) = self.named.map_mut(name);
        if let Some(old) = map.remove(name) {
            self.refingerprint(name_slot(level, name), old, Value::VACANT);
        }
    }

    /// The named parameters of the main level and the globals a program can write, with
    /// their values, in name order (the report's `#<name>` lines).
    pub fn named_report(&self) -> Vec<(String, Value)> {
        let main = self.named.levels[0].iter();
        main.chain(self.named.globals.iter())
            .filter(|(n, _)| !n.contains(' '))
            .map(|(n, v)| (n.clone(), *v))
            .collect()
    }

    /// Local `#n` (1–33) of the current level.
    pub fn local(&self, n: usize) -> Value {
        self.levels.last().expect("main level")[n - 1]
    }

    /// Set local `#n` (1–33) of the current level (e.g. from a G65 argument on a repeat).
    pub fn set_local(&mut self, n: usize, v: Value) {
        self.put_local(n - 1, v);
    }

    /// Local index `i` (0–32) of the current level = `v`, the fingerprint kept.
    fn put_local(&mut self, i: usize, v: Value) {
        let level = self.levels.len() - 1;
        let slot = &mut self.levels[level][i];
        let old = std::mem::replace(slot, v);
        self.refingerprint(local_slot(level, i), old, v);
    }

    /// Common `#n` = `v`, the fingerprint kept.
    fn put_common(&mut self, n: usize, v: Value) {
        let old = std::mem::replace(&mut self.common[n], v);
        self.refingerprint(common_slot(n), old, v);
    }

    fn refingerprint(&mut self, slot: usize, old: Value, new: Value) {
        self.fingerprint = self
            .fingerprint
            .wrapping_sub(share(slot, old))
            .wrapping_add(share(slot, new));
    }

    /// A common variable (`#100`–`#199`, `#500`–`#999`); `None` for other numbers.
    pub fn common(&self, n: u32) -> Option<Value> {
        is_common(i64::from(n)).then(|| self.common[n as usize])
    }

    /// Load a retained variable from `--vars FILE` (`#500`–`#999`; `#100`–`#199` also
    /// accepted for Haas, where they are retained).
    pub fn load(&mut self, n: u32, v: f64, span: Span) -> Result<()> {
        if !is_common(i64::from(n)) {
            return Err(MacroError::new(
                ErrorKind::NoSuchVariable,
                span,
                format!("#{n} is not a common variable"),
                "--vars sets #100–#199 and #500–#999",
            ));
        }
        self.put_common(n as usize, Value::num(v));
        Ok(())
    }

    /// A fingerprint of every value (the locals of all levels and the common variables):
    /// different fingerprints are different values; equal ones are checked with
    /// [`Variables::same_as`].
    pub fn fingerprint(&self) -> u64 {
        self.fingerprint
    }

    /// The present values, to compare later ones with ([`Variables::same_as`]).
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            fingerprint: self.fingerprint,
            levels: self.levels.len(),
            values: self.held().collect(),
            names: self.named.held(),
        }
    }

    /// Whether every variable holds, bit for bit, what it held at `then` (vacant as
    /// vacant, -0.0 not 0.0). O(1) when the fingerprints differ.
    pub fn same_as(&self, then: &Snapshot) -> bool {
        then.fingerprint == self.fingerprint
            && then.levels == self.levels.len()
            && then.values.iter().copied().eq(self.held())
            && then.names == self.named.held()
    }

    /// (slot, bits) of every variable that holds a value, in slot order.
    fn held(&self) -> impl Iterator<Item = (u32, u64)> + '_ {
        let commons = self
            .common
            .iter()
            .enumerate()
            .map(|(n, v)| (common_slot(n), v));
        let locals = self.levels.iter().enumerate().flat_map(|(level, locals)| {
            locals
                .iter()
                .enumerate()
                .map(move |(i, v)| (local_slot(level, i), v))
        });
        commons
            .chain(locals)
            .filter_map(|(slot, v)| v.get().map(|x| (slot as u32, x.to_bits())))
    }

    /// Local `#1`–`#33` of the current level or a common variable, without noting it as
    /// read (for messages); `None` for other numbers.
    pub fn peek(&self, n: u32) -> Option<Value> {
        match n {
            1..=33 => Some(self.local(n as usize)),
            _ => self.common(n),
        }
    }

    /// The retained variables `#500`–`#999` that hold a value, to save after a run.
    pub fn retained(&self) -> Vec<(u32, f64)> {
        (500..1000u32)
            .filter_map(|n| self.common[n as usize].get().map(|v| (n, v)))
            .collect()
    }

    /// The variables of the main level and the common variables that the run read or set,
    /// with their final values, in number order.
    pub fn report(&self) -> Vec<VarEntry> {
        (1..1000u32)
            .filter(|&n| self.touched[n as usize] != 0)
            .map(|n| VarEntry {
                number: n,
                value: if n <= 33 {
                    self.levels[0][n as usize - 1]
                } else {
                    self.common[n as usize]
                },
                read: self.touched[n as usize] & 1 != 0,
                set: self.touched[n as usize] & 2 != 0,
            })
            .collect()
    }

    fn note(&mut self, n: u32, set: bool) {
        if n > 33 || self.levels.len() == 1 {
            self.touched[n as usize] |= if set { 2 } else { 1 };
        }
    }

    /// Read `#n` (`n` already rounded for `#[expr]`). `span` is the variable's place.
    pub fn read(
        &mut self,
        n: i64,
        span: Span,
        options: &Options,
        sys: &mut dyn System,
    ) -> Result<Value> {
        let v = match classify(n, options) {
            Class::Null => Value::VACANT,
            Class::Local(i) => {
                self.note(i as u32 + 1, false);
                self.levels.last().expect("main level")[i]
            }
            Class::Common(i) => {
                self.note(i as u32, false);
                self.common[i]
            }
            Class::ToolOffset(k) => match sys.tool_offset(k) {
                Some(v) => Value::num(v),
                None => {
                    return Err(MacroError::new(
                        ErrorKind::NotSimulated,
                        span,
                        format!("#{n}: tool offset variables not mapped"),
                        "map tool offset variables in the machine profile, or read the value from the tool table another way",
                    ))
                }
            },
            Class::Alarm | Class::Stop => {
                return Err(MacroError::new(
                    ErrorKind::NotSimulated,
                    span,
                    format!("#{n} can only be written"),
                    "#3000 raises an alarm and #3006 stops with a message when written",
                ))
            }
            Class::Timer(t) => Value::num(sys.timer(t).ok_or_else(|| not_simulated(n, span))?),
            Class::Parts(k) => {
                Value::num(sys.parts_counter(k).ok_or_else(|| not_simulated(n, span))?)
            }
            Class::Modal(g) => {
                Value::num(sys.modal_group(g).ok_or_else(|| not_simulated(n, span))?)
            }
            Class::LastAddress(c) => sys.last_address(c).ok_or_else(|| not_simulated(n, span))?,
            Class::Position(p, a) => {
                Value::num(sys.position(p, a).ok_or_else(|| not_simulated(n, span))?)
            }
            Class::NotSimulated => return Err(not_simulated(n, span)),
            Class::Missing => return Err(missing(n, span)),
        };
        Ok(v)
    }

    /// Write `#n = v`. `comment` is the statement's `( … )` text (the message of `#3000`
    /// and `#3006`). Writing `#3000` returns the program's alarm as the error
    /// ([`ErrorKind::ProgramAlarm`]).
    pub fn write(
        &mut self,
        n: i64,
        v: Value,
        comment: Option<&str>,
        span: Span,
        options: &Options,
        sys: &mut dyn System,
    ) -> Result<()> {
        match classify(n, options) {
            Class::Local(i) => {
                self.note(i as u32 + 1, true);
                self.put_local(i, v);
            }
            Class::Common(i) => {
                self.note(i as u32, true);
                self.put_common(i, v);
            }
            Class::Alarm => {
                let k = round_half_away(v.or_zero());
                if !(0.0..=999.0).contains(&k) {
                    return Err(MacroError::new(
                        ErrorKind::Domain,
                        span,
                        format!("#3000 = {k}: the alarm number must be 0–999"),
                        "write #3000 = n (message) with n from 0 to 999",
                    ));
                }
                let code = k as u32 + if options.is_haas() { 1000 } else { 3000 };
                let message = match comment {
                    Some(m) if !m.is_empty() => format!("alarm {code}: {m}"),
                    _ => format!("alarm {code}"),
                };
                return Err(MacroError::new(
                    ErrorKind::ProgramAlarm { code },
                    span,
                    message,
                    "the program raised this alarm itself (#3000)",
                ));
            }
            Class::Stop => {
                if !sys.stop_message(v.or_zero(), comment.unwrap_or("")) {
                    return Err(not_simulated(n, span));
                }
            }
            Class::Timer(t) => {
                if !sys.set_timer(t, v.or_zero()) {
                    return Err(not_simulated(n, span));
                }
            }
            Class::Parts(k) => {
                if !sys.set_parts_counter(k, v.or_zero()) {
                    return Err(not_simulated(n, span));
                }
            }
            Class::Null
            | Class::ToolOffset(_)
            | Class::Modal(_)
            | Class::LastAddress(_)
            | Class::Position(..) => return Err(read_only(n, span)),
            Class::NotSimulated => return Err(not_simulated(n, span)),
            Class::Missing => return Err(missing(n, span)),
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Lathe {
        ms: f64,
    }
    impl System for Lathe {
        fn position(&self, kind: Position, axis: Axis) -> Option<f64> {
            Some(match (kind, axis) {
                (Position::BlockEnd | Position::Work, Axis::X) => 42.0,
                (Position::BlockEnd | Position::Work, Axis::Z) => 2.0,
                (Position::Machine, Axis::X) => 142.0,
                (Position::Machine, Axis::Z) => 302.0,
            })
        }
        fn modal_group(&self, group: u32) -> Option<f64> {
            (group == 1).then_some(1.0)
        }
        fn last_address(&self, letter: char) -> Option<Value> {
            Some(if letter == 'F' {
                Value::num(0.2)
            } else {
                Value::VACANT
            })
        }
        fn timer(&self, _: Timer) -> Option<f64> {
            Some(self.ms)
        }
        fn set_timer(&mut self, _: Timer, v: f64) -> bool {
            self.ms = v;
            true
        }
    }

    const S: Span = Span {
        line: 3,
        column: 1,
        offset: 20,
        len: 5,
    };

    #[test]
    fn ranges() {
        let o = Options::fanuc();
        let mut v = Variables::new();
        let sys = &mut NoMachine;
        assert!(v.read(1, S, &o, sys).unwrap().is_vacant());
        assert!(v.read(0, S, &o, sys).unwrap().is_vacant());
        v.write(100, Value::num(3.0), None, S, &o, sys).unwrap();
        v.write(999, Value::num(4.0), None, S, &o, sys).unwrap();
        assert_eq!(v.read(100, S, &o, sys).unwrap(), Value::num(3.0));
        for n in [34, 99, 200, 499, -1] {
            let e = v.read(n, S, &o, sys).unwrap_err();
            assert_eq!(e.kind, ErrorKind::NoSuchVariable, "#{n}");
            assert_eq!(e.span, S);
        }
        let e = v.write(0, Value::num(1.0), None, S, &o, sys).unwrap_err();
        assert_eq!(e.kind, ErrorKind::ReadOnly);
        // Haas NGC alias
        let h = Options::haas();
        v.write(10_500, Value::num(7.0), None, S, &h, sys).unwrap();
        assert_eq!(v.read(500, S, &h, sys).unwrap(), Value::num(7.0));
        assert!(v.read(10_500, S, &o, sys).is_err());
        assert_eq!(v.retained(), vec![(500, 7.0), (999, 4.0)]);
    }

    #[test]
    fn locals_per_level() {
        let o = Options::fanuc();
        let sys = &mut NoMachine;
        let mut v = Variables::new();
        v.write(1, Value::num(1.0), None, S, &o, sys).unwrap();
        let mut args = [Value::VACANT; 33];
        args[23] = Value::num(24.0);
        v.push_level(args);
        assert_eq!(v.level(), 1);
        assert!(v.read(1, S, &o, sys).unwrap().is_vacant());
        assert_eq!(v.read(24, S, &o, sys).unwrap(), Value::num(24.0));
        v.write(2, Value::num(5.0), None, S, &o, sys).unwrap();
        v.pop_level();
        assert_eq!(v.read(1, S, &o, sys).unwrap(), Value::num(1.0));
        assert!(v.read(2, S, &o, sys).unwrap().is_vacant());
        let r = v.report();
        assert_eq!(r.len(), 2);
        assert_eq!((r[0].number, r[0].read, r[0].set), (1, true, true));
        assert_eq!((r[1].number, r[1].read, r[1].set), (2, true, false));
    }

    #[test]
    fn system_variables() {
        let o = Options::fanuc();
        let mut v = Variables::new();
        let mut m = Lathe { ms: 5.0 };
        assert_eq!(v.read(5001, S, &o, &mut m).unwrap(), Value::num(42.0));
        assert_eq!(v.read(5002, S, &o, &mut m).unwrap(), Value::num(2.0));
        assert_eq!(v.read(5022, S, &o, &mut m).unwrap(), Value::num(302.0));
        assert_eq!(v.read(5041, S, &o, &mut m).unwrap(), Value::num(42.0));
        assert_eq!(v.read(4001, S, &o, &mut m).unwrap(), Value::num(1.0));
        assert_eq!(v.read(4109, S, &o, &mut m).unwrap(), Value::num(0.2));
        assert!(v.read(4119, S, &o, &mut m).unwrap().is_vacant());
        assert_eq!(v.read(3001, S, &o, &mut m).unwrap(), Value::num(5.0));
        v.write(3001, Value::num(0.0), None, S, &o, &mut m).unwrap();
        assert_eq!(m.ms, 0.0);
        // not simulated: named
        for n in [5003, 4002, 4110, 3004, 1000, 6000, 3901] {
            let e = v.read(n, S, &o, &mut m).unwrap_err();
            assert_eq!(e.kind, ErrorKind::NotSimulated, "#{n}");
            assert!(e.message.contains(&format!("#{n}")), "{}", e.message);
        }
        let e = v.read(2001, S, &o, &mut m).unwrap_err();
        assert!(e.message.contains("tool offset variables not mapped"));
        // read-only
        for n in [5001, 4001, 4109] {
            let e = v
                .write(n, Value::num(1.0), None, S, &o, &mut m)
                .unwrap_err();
            assert_eq!(e.kind, ErrorKind::ReadOnly, "#{n}");
        }
    }

    /// The fingerprint follows every write, call level and load; a snapshot compares
    /// bit for bit: vacant is not 0, -0.0 is not 0.0, a level's locals count.
    #[test]
    fn fingerprint_and_snapshot_follow_the_values() {
        let o = Options::fanuc();
        let sys = &mut NoMachine;
        let mut v = Variables::new();
        assert_eq!(v.fingerprint(), 0);
        let empty = v.snapshot();
        v.write(1, Value::num(0.0), None, S, &o, sys).unwrap();
        assert_ne!(v.fingerprint(), 0, "0 is not vacant");
        assert!(!v.same_as(&empty));
        v.write(1, Value::VACANT, None, S, &o, sys).unwrap();
        assert_eq!(v.fingerprint(), 0);
        assert!(v.same_as(&empty));
        v.write(1, Value::num(-0.0), None, S, &o, sys).unwrap();
        let minus = v.snapshot();
        v.write(1, Value::num(0.0), None, S, &o, sys).unwrap();
        assert!(!v.same_as(&minus), "-0.0 is not 0.0 bit for bit");
        // the same value in another variable is another state
        let one = v.snapshot();
        v.write(1, Value::VACANT, None, S, &o, sys).unwrap();
        v.write(2, Value::num(0.0), None, S, &o, sys).unwrap();
        assert!(!v.same_as(&one));
        // commons, loads, levels: back to the same values, back to the same fingerprint
        let before = (v.fingerprint(), v.snapshot());
        v.write(500, Value::num(3.0), None, S, &o, sys).unwrap();
        v.load(501, 4.0, S).unwrap();
        let mut args = [Value::VACANT; 33];
        args[0] = Value::num(7.0);
        v.push_level(args);
        let inside = v.snapshot();
        v.set_local(2, Value::num(1.0));
        assert!(!v.same_as(&inside));
        v.set_local(2, Value::VACANT);
        assert!(v.same_as(&inside));
        v.pop_level();
        assert!(!v.same_as(&inside), "a level less");
        v.write(500, Value::VACANT, None, S, &o, sys).unwrap();
        v.write(501, Value::VACANT, None, S, &o, sys).unwrap();
        assert_eq!(v.fingerprint(), before.0);
        assert!(v.same_as(&before.1));
        // peek does not mark a variable read
        assert_eq!(v.peek(2), Some(Value::num(0.0)));
        assert_eq!(v.peek(5001), None);
        assert!(v.report().iter().all(|e| !e.read));
    }

    #[test]
    fn program_alarm_3000() {
        let mut v = Variables::new();
        let sys = &mut NoMachine;
        let e = v
            .write(
                3000,
                Value::num(12.0),
                Some("TOOL BROKEN"),
                S,
                &Options::fanuc(),
                sys,
            )
            .unwrap_err();
        assert_eq!(e.kind, ErrorKind::ProgramAlarm { code: 3012 });
        assert_eq!(e.message, "alarm 3012: TOOL BROKEN");
        assert_eq!(e.span, S);
        let e = v
            .write(3000, Value::num(1.0), None, S, &Options::haas(), sys)
            .unwrap_err();
        assert_eq!(e.kind, ErrorKind::ProgramAlarm { code: 1001 });
        assert_eq!(e.message, "alarm 1001");
    }
}
