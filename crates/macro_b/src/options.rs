//! Dialect choices and limits (spec/dialects.md §5.3, §5.5, §5.6).

/// Which control's macro rules apply where they differ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Dialect {
    /// FANUC custom macro B (0i/30i; also GSK).
    #[default]
    Fanuc,
    /// Haas: `WH` for `WHILE`, `IF … THEN` with an NC block, `#3000` alarms as 1000 + n,
    /// `#10000`+n aliases of the common variables.
    Haas,
    /// `LinuxCNC` (rs274ngc): `;` comments, o-words and named parameters `#<name>`; its
    /// expressions are macro B's (docs/linuxcnc.md).
    LinuxCnc,
}

/// Limits that end a program with an alarm instead of letting it run away.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Executed blocks (macro statements and NC blocks together) before the run is ended.
    pub max_blocks: u64,
    /// `DO` loops open at once (3 on FANUC and Haas).
    pub loop_depth: usize,
    /// `G65`/`G66` macro calls nested (5 on FANUC, 9 on Haas).
    pub macro_depth: usize,
    /// `M98`/`M97` subprogram calls nested (10 on FANUC).
    pub sub_depth: usize,
    /// Macro and subprogram calls together (15 on 30i).
    pub total_depth: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_blocks: DEFAULT_MAX_BLOCKS,
            loop_depth: 3,
            macro_depth: 5,
            sub_depth: 10,
            total_depth: 15,
        }
    }
}

/// The default block budget: 10⁷ executed blocks (issue 12). A loop of simple statements
/// runs out of it in well under a second.
pub const DEFAULT_MAX_BLOCKS: u64 = 10_000_000;

/// Most levels of `[ ]` in one expression, function brackets included (spec §5.3).
pub const MAX_BRACKET_DEPTH: usize = 5;

/// How macro statements are read and run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// The control.
    pub dialect: Dialect,
    /// `MOD` is available (30i and Haas; on 0i it is an error unless the profile's
    /// `macro_mod = true`).
    pub allow_mod: bool,
    /// `ATAN` results in −180…180 (parameter No. 6004 bit 0); otherwise 0 ≤ θ < 360.
    pub atan_signed: bool,
    /// `ADP[x]` multiplies by this: the reciprocal of the least input increment
    /// (1000 for IS-B millimetres). **Interpretation**: ADP restores the decimal point of a
    /// value passed without one.
    pub adp_scale: f64,
    /// The limits.
    pub limits: Limits,
}

impl Default for Options {
    fn default() -> Self {
        Self::fanuc()
    }
}

impl Options {
    /// FANUC 0i rules (no `MOD`).
    pub fn fanuc() -> Self {
        Self {
            dialect: Dialect::Fanuc,
            allow_mod: false,
            atan_signed: false,
            adp_scale: 1000.0,
            limits: Limits::default(),
        }
    }

    /// Haas rules: `MOD`, `WH`, G65 nine deep.
    pub fn haas() -> Self {
        Self {
            dialect: Dialect::Haas,
            allow_mod: true,
            limits: Limits {
                macro_depth: 9,
                ..Limits::default()
            },
            ..Self::fanuc()
        }
    }

    /// `LinuxCNC` rules: `MOD` (its modulo operator), FANUC's otherwise.
    pub fn linuxcnc() -> Self {
        Self {
            dialect: Dialect::LinuxCnc,
            allow_mod: true,
            ..Self::fanuc()
        }
    }

    /// Whether Haas rules apply.
    pub fn is_haas(&self) -> bool {
        self.dialect == Dialect::Haas
    }
}
