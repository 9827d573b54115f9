//! The blocks of a long O program read again on another thread, ahead of the run.

use gcode::{Block, Blocks};
use std::sync::mpsc::{channel, sync_channel, Receiver, Sender};
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
/// blocks are the same either way; a jump back before the chunk at hand ends the reading
/// ahead, and the run reads its blocks where it needs them, as without. The chunks run are
/// sent back to be freed where they were made (freeing them here was a tenth of the run:
/// malloc's locks across threads).
pub(super) struct Ahead {
    rx: Receiver<Vec<Block>>,
    spent: Sender<Vec<Block>>,
    chunk: Vec<Block>,
    /// The index of `chunk[0]`.
    first: usize,
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
        let (spent, spent_rx) = channel::<Vec<Block>>();
        scope.spawn(move || {
            let mut i = start;
            while i < blocks.len() {
                while let Ok(run) = spent_rx.try_recv() {
                    drop(run);
                }
                let end = (i + CHUNK).min(blocks.len());
                if tx.send(blocks.read(i..end)).is_err() {
                    // the run has dropped the reading ahead
                    break;
                }
                i = end;
            }
            // the rest, until the run drops the reading ahead
            for run in spent_rx {
                drop(run);
            }
        });
        Some(Self {
            rx,
            spent,
            chunk: Vec::new(),
            first: start,
        })
    }

    /// Block `i`, when it is in the chunk at hand or ahead of it (the chunks before it are
    /// passed over); `None` when the run has gone back before the chunk at hand.
    pub(super) fn get(&mut self, i: usize) -> Option<&Block> {
        if i < self.first {
            return None;
        }
        while i >= self.first + self.chunk.len() {
            let next = self.rx.recv().ok()?;
            self.first += self.chunk.len();
            let run = std::mem::replace(&mut self.chunk, next);
            // (a reading thread that has stopped leaves it to be freed here)
            let _ = self.spent.send(run);
        }
        self.chunk.get(i - self.first)
    }
}
