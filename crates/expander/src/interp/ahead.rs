//! The blocks of a long O program read again on another thread, ahead of the run.

use gcode::{Block, Blocks};
use std::sync::mpsc::{sync_channel, Receiver};
use std::thread::Scope;

/// Blocks read per message.
const CHUNK: usize = 512;
/// Messages read ahead at most (with [`CHUNK`], about 400 KB of blocks).
const QUEUE: usize = 4;
/// Programs with fewer blocks left are read where they run: a thread costs more.
const MIN_BLOCKS: usize = 8192;

/// The blocks of one O program from some index on, read again from the program text
/// ([`Blocks`]) on a thread of their own while the run goes on: reading them again where
/// they run was a sixth of a million-line run, and a second core does it meanwhile. The
/// blocks are the same either way; a jump back ends the reading ahead, and the run reads
/// its blocks where it needs them, as without.
pub(super) struct Ahead {
    rx: Receiver<Vec<Block>>,
    chunk: std::vec::IntoIter<Block>,
    /// The index of the block `chunk` yields next.
    next: usize,
}

impl Ahead {
    /// Read `blocks` from `start` on, on a thread of `scope`; `None` where they are held,
    /// or too few to be worth a thread. Drop it before `scope` ends: its thread stops then.
    pub(super) fn start<'s>(
        scope: &'s Scope<'s, '_>,
        blocks: &'s Blocks,
        start: usize,
    ) -> Option<Self> {
        if !blocks.reads_again() || blocks.len().saturating_sub(start) < MIN_BLOCKS {
            return None;
        }
        let (tx, rx) = sync_channel(QUEUE);
        scope.spawn(move || {
            let mut i = start;
            while i < blocks.len() {
                let end = (i + CHUNK).min(blocks.len());
                if tx.send(blocks.read(i..end)).is_err() {
                    // the run has dropped the reading ahead
                    return;
                }
                i = end;
            }
        });
        Some(Self {
            rx,
            chunk: Vec::new().into_iter(),
            next: start,
        })
    }

    /// Block `i`, when it is still ahead (the blocks before it are passed over); `None`
    /// when the run has gone back before the blocks read.
    pub(super) fn take(&mut self, i: usize) -> Option<Block> {
        if i < self.next {
            return None;
        }
        loop {
            match self.chunk.next() {
                Some(b) => {
                    self.next += 1;
                    if self.next == i + 1 {
                        return Some(b);
                    }
                }
                None => self.chunk = self.rx.recv().ok()?.into_iter(),
            }
        }
    }
}
