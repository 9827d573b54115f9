//! Blank, tool outlines, sweeps, material removal.
