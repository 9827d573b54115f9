//! The memory budget of a run: no input may take the machine down. The removal looks at the
//! process's resident memory now and then (at every epoch end, and every [`CHECK_EVERY`]
//! boolean calls of a worker); over the budget it stops where it is and says what grew
//! ([`OverBudget`]), and the caller ends that run (exit 2).
//!
//! The programs of a batch run side by side in one process and share its memory: when the
//! process is over the budget, the run that stops is the one that holds the most
//! ([`Ledger`]: what each removal holds, or, before its removal began, its program's size),
//! and the others go on.

use std::fmt;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// A worker looks at the process's memory once in this many boolean calls (reading it costs
/// a few microseconds; a boolean call of a tile about as much).
pub(crate) const CHECK_EVERY: u32 = 256;

/// The most memory a run may hold, bytes (`--max-memory`; by default half the machine's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MemoryBudget {
    bytes: u64,
}

impl MemoryBudget {
    /// A budget of `bytes`.
    pub fn new(bytes: u64) -> Self {
        Self { bytes }
    }

    /// Its size, bytes.
    pub fn bytes(&self) -> u64 {
        self.bytes
    }

    /// Half the machine's memory (`MemTotal` of `/proc/meminfo`, or the container's limit
    /// where that is less: cgroup v2's `memory.max`); `None` where the machine does not say
    /// (not Linux).
    pub fn half_of_machine() -> Option<Self> {
        let info = std::fs::read_to_string("/proc/meminfo").ok()?;
        let limit = std::fs::read_to_string("/sys/fs/cgroup/memory.max").ok();
        machine_memory(&info, limit.as_deref()).map(|bytes| Self::new(bytes / 2))
    }

    /// Reads a size such as `8G`, `512M`, `300000K` or `1000000` (bytes); the units are
    /// binary (`K` = 1024) and may end in `B` or `iB` (`8GiB`, `512MB`).
    pub fn parse(text: &str) -> Result<Self, String> {
        let t = text.trim();
        let digits = t
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .unwrap_or(t.len());
        let (number, unit) = t.split_at(digits);
        let scale: u64 = match unit.trim().to_ascii_uppercase().as_str() {
            "" | "B" => 1,
            "K" | "KB" | "KIB" => 1 << 10,
            "M" | "MB" | "MIB" => 1 << 20,
            "G" | "GB" | "GIB" => 1 << 30,
            "T" | "TB" | "TIB" => 1 << 40,
            other => {
                return Err(format!(
                    "`{text}`: unknown unit `{other}` (give a size such as 8G, 512M or 300000K)"
                ))
            }
        };
        let value: f64 = number
            .parse()
            .map_err(|_| format!("`{text}`: not a size (give one such as 8G, 512M or 300000K)"))?;
        let bytes = value * scale as f64;
        if !(1.0..1e18).contains(&bytes) {
            return Err(format!("`{text}`: a budget must be at least one byte"));
        }
        Ok(Self::new(bytes as u64))
    }

    /// The process's memory when it is over this budget: `Some(held)`, else `None` (also
    /// where the process's memory cannot be read).
    pub(crate) fn exceeded(&self) -> Option<u64> {
        process_memory().filter(|&held| held > self.bytes)
    }
}

/// What each program of a batch holds, bytes, for deciding which stops when the process
/// is over its budget: a program's file size until its removal looks, then what the removal
/// holds (the moves, the stock, the sweeps, the snapshots); 0 once it is done.
#[derive(Debug)]
pub struct Ledger {
    held: Vec<AtomicU64>,
    /// The most a program held when it was stopped over the budget: a program holding no
    /// more goes on (the process's own memory may keep it over a small budget after the
    /// program that grew has stopped; whether the small one then stopped too was a race).
    stopped: AtomicU64,
}

impl Ledger {
    /// A ledger of programs whose files hold `sizes` bytes.
    pub fn new(sizes: impl IntoIterator<Item = u64>) -> Arc<Self> {
        Arc::new(Self {
            held: sizes
                .into_iter()
                .map(|b| AtomicU64::new(b.max(1)))
                .collect(),
            stopped: AtomicU64::new(0),
        })
    }

    /// Program `i` is done: it holds nothing that counts.
    pub fn done(&self, i: usize) {
        if let Some(h) = self.held.get(i) {
            h.store(0, Ordering::Relaxed);
        }
    }

    /// Whether program `i`, the process being over its budget, is the one to stop: it holds
    /// at least as much as every other program not done, and more than any program stopped
    /// before it held (which it then becomes).
    fn stops(&self, i: usize) -> bool {
        let mine = self.held.get(i).map_or(0, |h| h.load(Ordering::Relaxed));
        let most = self
            .held
            .iter()
            .enumerate()
            .all(|(j, h)| j == i || h.load(Ordering::Relaxed) <= mine);
        most && self.stopped.fetch_max(mine, Ordering::Relaxed) < mine
    }
}

/// One run's budget: the process's memory against it, and, in a batch, the run's line in
/// the batch's [`Ledger`].
#[derive(Debug, Clone)]
pub struct RunMemory {
    budget: MemoryBudget,
    batch: Option<(Arc<Ledger>, usize)>,
}

impl PartialEq for RunMemory {
    fn eq(&self, other: &Self) -> bool {
        self.budget == other.budget
            && self.batch.as_ref().map(|b| b.1) == other.batch.as_ref().map(|b| b.1)
    }
}

impl RunMemory {
    /// The budget of a run on its own.
    pub fn alone(budget: MemoryBudget) -> Self {
        Self {
            budget,
            batch: None,
        }
    }

    /// The budget of program `i` of a batch.
    pub fn in_batch(budget: MemoryBudget, ledger: Arc<Ledger>, i: usize) -> Self {
        Self {
            budget,
            batch: Some((ledger, i)),
        }
    }

    /// The budget.
    pub fn budget(&self) -> MemoryBudget {
        self.budget
    }

    /// This run is done: in a batch, it holds nothing that counts any more.
    pub fn done(&self) {
        if let Some((ledger, i)) = &self.batch {
            ledger.done(*i);
        }
    }

    /// The removal of this run holds about `bytes` now.
    pub(crate) fn holds(&self, bytes: u64) {
        if let Some((ledger, i)) = &self.batch {
            if let Some(h) = ledger.held.get(*i) {
                h.store(bytes.max(1), Ordering::Relaxed);
            }
        }
    }

    /// What the process holds now, bytes (0 where the system does not say).
    pub fn held(&self) -> u64 {
        process_memory().unwrap_or(0)
    }

    /// The process's memory when it is over the budget and this run is the one to stop
    /// (alone, or holding the most of the batch's programs not done), else `None`.
    pub fn over(&self) -> Option<u64> {
        let held = self.budget.exceeded()?;
        let mine = self
            .batch
            .as_ref()
            .is_none_or(|(ledger, i)| ledger.stops(*i));
        mine.then_some(held)
    }
}

impl fmt::Display for MemoryBudget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&size(self.bytes))
    }
}

/// The process's resident memory, bytes (`VmRSS` of `/proc/self/status`); `None` where the
/// system does not say (not Linux).
pub fn process_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    kib_field(&status, "VmRSS:").map(|kib| kib * 1024)
}

/// The memory a process may take, bytes: `MemTotal` of `meminfo`, or the cgroup's
/// `memory.max` where it is a number and less (`max` means no limit).
fn machine_memory(meminfo: &str, cgroup_max: Option<&str>) -> Option<u64> {
    let total = kib_field(meminfo, "MemTotal:")? * 1024;
    let limit = cgroup_max.and_then(|t| t.trim().parse::<u64>().ok());
    Some(limit.map_or(total, |l| l.min(total)))
}

/// The value in kB of the line starting with `key` in a `/proc` file.
fn kib_field(text: &str, key: &str) -> Option<u64> {
    text.lines()
        .find_map(|l| l.strip_prefix(key))?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

/// A size in bytes as people read it: `1.4 GiB`, `212 MiB`, `96 KiB`.
pub(crate) fn size(bytes: u64) -> String {
    let b = bytes as f64;
    if b >= (1u64 << 30) as f64 {
        format!("{:.1} GiB", b / (1u64 << 30) as f64)
    } else if b >= (1u64 << 20) as f64 {
        format!("{:.0} MiB", b / (1u64 << 20) as f64)
    } else {
        format!("{:.0} KiB", b / 1024.0)
    }
}

/// A run stopped because the process went over its memory budget: where, and what grew.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("over the memory budget of {budget}: the process held {} after {moves} move{}; {what} (give --max-memory to allow more)", size(*.held), if *.moves == 1 { "" } else { "s" })]
pub struct OverBudget {
    /// The budget.
    pub budget: MemoryBudget,
    /// What the process held, bytes.
    pub held: u64,
    /// Moves whose cuts were done when it stopped.
    pub moves: usize,
    /// What grew, in words: the removal's largest structure and its size, or that the
    /// memory is held outside the removal.
    pub what: String,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_with_their_units() {
        let b = |t: &str| MemoryBudget::parse(t).map(|m| m.bytes());
        assert_eq!(b("8G"), Ok(8 << 30));
        assert_eq!(b("512M"), Ok(512 << 20));
        assert_eq!(b("512 MiB"), Ok(512 << 20));
        assert_eq!(b("300000K"), Ok(300_000 << 10));
        assert_eq!(b("1.5GB"), Ok(3 << 29));
        assert_eq!(b("1000000"), Ok(1_000_000));
        assert!(b("8X").unwrap_err().contains("unknown unit `X`"));
        assert!(b("G").unwrap_err().contains("not a size"));
        assert!(b("0").unwrap_err().contains("at least one byte"));
        assert_eq!(size(3 << 29), "1.5 GiB");
        assert_eq!(size(212 << 20), "212 MiB");
    }

    /// A container's limit below the machine's memory is the machine's memory.
    #[test]
    fn a_container_limit_below_the_machine_counts() {
        let info = "MemTotal:       24000000 kB\nMemFree:  1000 kB\n";
        assert_eq!(machine_memory(info, None), Some(24_000_000 * 1024));
        assert_eq!(machine_memory(info, Some("max\n")), Some(24_000_000 * 1024));
        assert_eq!(machine_memory(info, Some("2147483648\n")), Some(1 << 31));
        assert_eq!(
            machine_memory(info, Some("99999999999999\n")),
            Some(24_000_000 * 1024)
        );
        assert_eq!(machine_memory("MemFree: 1 kB\n", Some("1")), None);
    }

    /// This process's memory is read where the system says it (Linux), and a budget of a
    /// byte is exceeded by it.
    #[test]
    fn the_process_memory_is_read_and_compared() {
        if cfg!(target_os = "linux") {
            let held = process_memory().expect("VmRSS");
            assert!(held > 1 << 20, "{held}");
            assert_eq!(MemoryBudget::new(1).exceeded().map(|h| h > 1), Some(true));
            assert_eq!(MemoryBudget::new(u64::MAX / 2).exceeded(), None);
            assert!(MemoryBudget::half_of_machine().is_some_and(|m| m.bytes() > 1 << 20));
        }
    }
}
