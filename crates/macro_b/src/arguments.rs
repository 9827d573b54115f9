//! The `G65` argument letters (assignment I): which local variable each sets. A leaf: the
//! call (`flow`) and the system variables of the arguments (`vars`, #4101…) both read it.

/// The `G65` argument letters and the local variables they set (assignment I, spec §5.5).
pub const ARGUMENTS: [(char, u8); 21] = [
    ('A', 1),
    ('B', 2),
    ('C', 3),
    ('I', 4),
    ('J', 5),
    ('K', 6),
    ('D', 7),
    ('E', 8),
    ('F', 9),
    ('H', 11),
    ('M', 13),
    ('Q', 17),
    ('R', 18),
    ('S', 19),
    ('T', 20),
    ('U', 21),
    ('V', 22),
    ('W', 23),
    ('X', 24),
    ('Y', 25),
    ('Z', 26),
];

/// The argument letter of local `#n` under assignment I (`24` → `X`); also the letter of
/// `#4100 + n`.
pub fn letter_of_argument(n: u8) -> Option<char> {
    ARGUMENTS.iter().find(|(_, k)| *k == n).map(|(c, _)| *c)
}
