//! The stock as one set of shapes from its tiles' pieces, joined along the tile sides in
//! one walk over their rings.
//!
//! The tiles are disjoint boxes, each holding its stock cut to its box, so the union of
//! their pieces only joins pieces where they meet on a tile side. There one piece's edges
//! run along the side one way and its neighbour's the other way, point for point (the
//! points where the stock's edges cross the side are the same rounded crossings in both
//! tiles, so they may lie a grid step off the side), and the two cancel. A union by
//! `i_overlay` finds the same boundary in O(V log V) with a large constant (the 29
//! snapshots of 1 000 small arcs were 29 % of the run); here only the edges in a band
//! along each tile's sides are hashed, and the rest of each ring is copied as it is. The
//! result is what that union returns, ring for ring and point for point (rings start just
//! before their lowest-leftmost point and are listed in the order of those points; the
//! tests compare the two, and a debug build compares every snapshot).
//!
//! Anything else (an edge in the band without its twin, a point in the band away from a
//! twin, a hole, two rings touching at a point) makes it give up (`None`), and the caller
//! joins the pieces by the union.

use std::collections::HashMap;

use crate::overlay::{ring_area2, IBox, IPt, IShapes};

/// How far (grid steps) from a tile's side a point of a piece may lie and belong to that
/// side: a crossing is rounded by half a step, a crossing on an edge so rounded by another.
const BAND: i32 = 2;

/// A stretch of the joined boundary.
enum Piece {
    /// Points `from ..= from + edges` of ring `ring` (indices wrap), none of its edges
    /// cancelled.
    Run {
        ring: usize,
        from: usize,
        edges: usize,
    },
    /// What is left of a tile's side where only one piece runs along it (the stock's edge
    /// lies on the side): from its first point to the next piece's.
    Side(IPt),
}

/// The union of the tiles' pieces (`(tile, its shapes)`, the tiles disjoint), or `None`
/// where they are not as the tiles leave them (see the module).
pub(crate) fn stitch(tiles: &[(IBox, IShapes)]) -> Option<IShapes> {
    let mut rings: Vec<(&[IPt], IBox)> = Vec::new();
    for (tile, shapes) in tiles {
        for shape in shapes {
            if shape.len() != 1 || shape[0].len() < 3 {
                return None;
            }
            rings.push((&shape[0], *tile));
        }
    }
    let mut pieces: Vec<(IPt, IPt, Piece)> = Vec::new();
    let cancelled = cancelled_edges(&rings, &mut pieces)?;
    let mut out: Vec<Vec<IPt>> = Vec::new();
    for (k, (ring, _)) in rings.iter().enumerate() {
        match cancelled.get(&k) {
            None => out.push(ring.to_vec()),
            Some(gone) => runs(k, ring, gone, &mut pieces),
        }
    }
    join(&pieces, &rings, &mut out)?;
    let mut keyed: Vec<((i32, i32), Vec<IPt>)> = Vec::with_capacity(out.len());
    for mut ring in out {
        // as the union starts them: at the point before the lowest-leftmost one, or at that
        // one where the point before it goes on straight (the union drops it, and starts
        // at the next); and lists them in the order of those points
        let low = (0..ring.len()).min_by_key(|&i| (ring[i].x, ring[i].y))?;
        let n = ring.len();
        let before = (low + n - 1) % n;
        let straight = !turns(ring[(before + n - 1) % n], ring[before], ring[low]);
        let key = (ring[low].x, ring[low].y);
        ring.rotate_left(if straight { low } else { before });
        drop_collinear(&mut ring);
        if ring.len() < 3 || ring_area2(&ring) <= 0 {
            return None;
        }
        keyed.push((key, ring));
    }
    keyed.sort_unstable_by_key(|(key, _)| *key);
    Some(keyed.into_iter().map(|(_, r)| vec![r]).collect())
}

/// Which side of `tile` the point `p` lies in the band of (bits: left, right, bottom,
/// top), 0 for none.
fn sides_near(p: IPt, tile: &IBox) -> u8 {
    let near = |a: i32, b: i32| (i64::from(a) - i64::from(b)).abs() <= i64::from(BAND);
    u8::from(near(p.x, tile.min[0]))
        | u8::from(near(p.x, tile.max[0])) << 1
        | u8::from(near(p.y, tile.min[1])) << 2
        | u8::from(near(p.y, tile.max[1])) << 3
}

/// Per ring with edges along its tile's sides, which of its edges are taken out: those
/// exactly on a side (what is left of them once the edges of the pieces on both sides
/// cancel is pushed to `left`: a long edge there may meet several shorter ones, where the
/// other side is cut into smaller tiles), and the others in the band, which cancel against
/// their twins (the same points the other way). `None` where an edge in the band has no
/// twin, two pieces run the same way along a side, or a point in the band is away from
/// every edge taken out (a ring touching the side there).
fn cancelled_edges(
    rings: &[(&[IPt], IBox)],
    left: &mut Vec<(IPt, IPt, Piece)>,
) -> Option<HashMap<usize, Vec<bool>>> {
    let mut on_side: Vec<AlongSide> = Vec::new();
    let mut twins: HashMap<(IPt, IPt), (usize, usize)> = HashMap::new();
    let mut near_points: Vec<(usize, usize)> = Vec::new();
    for (k, (ring, tile)) in rings.iter().enumerate() {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let near_a = sides_near(a, tile);
            if near_a != 0 {
                near_points.push((k, i));
            }
            if near_a & sides_near(b, tile) == 0 {
                continue;
            }
            match AlongSide::of(a, b, tile, k, i) {
                Some(e) => on_side.push(e),
                None => {
                    twins.insert((a, b), (k, i));
                }
            }
        }
    }
    let mut cancelled: HashMap<usize, Vec<bool>> = HashMap::new();
    let mut cancel = |k: usize, i: usize| {
        cancelled
            .entry(k)
            .or_insert_with(|| vec![false; rings[k].0.len()])[i] = true;
    };
    for (&(a, b), &(k, i)) in &twins {
        let &(twin_ring, _) = twins.get(&(b, a))?;
        if twin_ring == k {
            return None;
        }
        cancel(k, i);
    }
    on_side.sort_unstable_by_key(|e| e.line);
    for line in on_side.chunk_by(|a, b| a.line == b.line) {
        what_is_left(line, left)?;
        for e in line {
            cancel(e.ring, e.at);
        }
    }
    for (k, i) in near_points {
        let n = rings[k].0.len();
        let gone = cancelled.get(&k)?;
        if !gone[i] && !gone[(i + n - 1) % n] {
            return None;
        }
    }
    Some(cancelled)
}

/// An edge exactly on a side of its tile.
struct AlongSide {
    /// `(vertical, the line's x or y)`.
    line: (bool, i32),
    /// Its extent along the line, and whether it runs toward `hi`.
    lo: i32,
    hi: i32,
    forward: bool,
    /// Its ring and index in the ring.
    ring: usize,
    at: usize,
}

impl AlongSide {
    /// The edge `a`–`b` (edge `at` of ring `ring`) when it lies on a side of `tile`.
    fn of(a: IPt, b: IPt, tile: &IBox, ring: usize, at: usize) -> Option<Self> {
        let (line, from, to) = if a.x == b.x && (a.x == tile.min[0] || a.x == tile.max[0]) {
            ((true, a.x), a.y, b.y)
        } else if a.y == b.y && (a.y == tile.min[1] || a.y == tile.max[1]) {
            ((false, a.y), a.x, b.x)
        } else {
            return None;
        };
        Some(Self {
            line,
            lo: from.min(to),
            hi: from.max(to),
            forward: to > from,
            ring,
            at,
        })
    }
}

/// What is left of the edges of one line once those running one way cancel those running
/// the other, pushed to `left` as pieces, split at every edge's end (as the union's graph
/// splits them). `None` where two edges run the same way over a stretch (pieces overlap).
fn what_is_left(line: &[AlongSide], left: &mut Vec<(IPt, IPt, Piece)>) -> Option<()> {
    let (vertical, c) = line[0].line;
    let point = |t: i32| {
        if vertical {
            IPt::new(c, t)
        } else {
            IPt::new(t, c)
        }
    };
    let mut events: Vec<(i32, i32)> = line
        .iter()
        .flat_map(|e| {
            let w = if e.forward { 1 } else { -1 };
            [(e.lo, w), (e.hi, -w)]
        })
        .collect();
    events.sort_unstable();
    let mut cover = 0;
    let mut at = events.chunk_by(|a, b| a.0 == b.0).peekable();
    while let Some(here) = at.next() {
        cover += here.iter().map(|e| e.1).sum::<i32>();
        if cover.abs() > 1 {
            return None;
        }
        if let (Some(next), true) = (at.peek(), cover != 0) {
            let (from, to) = if cover > 0 {
                (here[0].0, next[0].0)
            } else {
                (next[0].0, here[0].0)
            };
            left.push((point(from), point(to), Piece::Side(point(from))));
        }
    }
    Some(())
}

/// The runs of ring `k`'s edges between its cancelled ones (`touched`: per edge), with
/// their first and last points.
fn runs(k: usize, ring: &[IPt], touched: &[bool], pieces: &mut Vec<(IPt, IPt, Piece)>) {
    let n = ring.len();
    // start just after a touched edge, so that no run wraps past the start
    let Some(first) = (0..n).find(|&i| touched[i]) else {
        return;
    };
    let mut i = first + 1;
    while i < first + 1 + n {
        if touched[i % n] {
            i += 1;
            continue;
        }
        let from = i;
        while i < first + 1 + n && !touched[i % n] {
            i += 1;
        }
        let edges = i - from;
        pieces.push((
            ring[from % n],
            ring[(from + edges) % n],
            Piece::Run {
                ring: k,
                from: from % n,
                edges,
            },
        ));
    }
}

/// The rings the pieces close into, each followed by the one starting where it ends.
/// `None` where two start at one point (rings touching there) or one ends where none
/// starts.
fn join(
    pieces: &[(IPt, IPt, Piece)],
    rings: &[(&[IPt], IBox)],
    out: &mut Vec<Vec<IPt>>,
) -> Option<()> {
    let mut starting: HashMap<IPt, usize> = HashMap::with_capacity(pieces.len());
    for (i, (start, _, _)) in pieces.iter().enumerate() {
        if starting.insert(*start, i).is_some() {
            return None;
        }
    }
    let mut used = vec![false; pieces.len()];
    for first in 0..pieces.len() {
        if used[first] {
            continue;
        }
        let mut ring = Vec::new();
        let mut at = first;
        while !used[at] {
            used[at] = true;
            let (_, end, piece) = &pieces[at];
            match *piece {
                Piece::Run {
                    ring: k,
                    from,
                    edges,
                } => {
                    let pts = rings[k].0;
                    ring.extend((from..from + edges).map(|i| pts[i % pts.len()]));
                }
                Piece::Side(from) => ring.push(from),
            }
            at = *starting.get(end)?;
        }
        if at != first {
            return None;
        }
        out.push(ring);
    }
    Some(())
}

/// Removes the points where a ring goes on straight (or back), as the union's output has
/// none, in one pass: each point is checked against the last one kept, then the ring's
/// ends against each other. The first point stays first unless it is removed.
fn drop_collinear(ring: &mut Vec<IPt>) {
    let mut kept: Vec<IPt> = Vec::with_capacity(ring.len());
    for &p in ring.iter() {
        while kept.len() >= 2 && !turns(kept[kept.len() - 2], kept[kept.len() - 1], p) {
            kept.pop();
        }
        kept.push(p);
    }
    let mut first = 0;
    while kept.len() - first >= 3 {
        let n = kept.len();
        if !turns(kept[n - 2], kept[n - 1], kept[first]) {
            kept.pop();
        } else if !turns(kept[n - 1], kept[first], kept[first + 1]) {
            first += 1;
        } else {
            break;
        }
    }
    kept.drain(..first);
    *ring = kept;
}

/// Whether the path `a`, `b`, `c` turns at `b` (does not go on straight or back).
fn turns(a: IPt, b: IPt, c: IPt) -> bool {
    let (ux, uy) = (
        i64::from(b.x) - i64::from(a.x),
        i64::from(b.y) - i64::from(a.y),
    );
    let (vx, vy) = (
        i64::from(c.x) - i64::from(b.x),
        i64::from(c.y) - i64::from(b.y),
    );
    ux * vy - uy * vx != 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::overlay::Engine;

    fn ring(pts: &[[i32; 2]]) -> Vec<IPt> {
        pts.iter().map(|p| IPt::new(p[0], p[1])).collect()
    }

    fn tile(x0: i32, x1: i32, y0: i32, y1: i32) -> IBox {
        IBox {
            min: [x0, y0],
            max: [x1, y1],
        }
    }

    /// `stock` cut into `cols` columns over `bx`, column `i` into `rows(i)` tiles, as the
    /// strips and their tile trees cut it (tiles of unequal columns meet at T-junctions).
    fn tiles(
        stock: &IShapes,
        bx: IBox,
        cols: i32,
        mut rows: impl FnMut(i32) -> i32,
        engine: &mut Engine,
    ) -> Vec<(IBox, IShapes)> {
        let at = |lo: i32, hi: i32, k: i32, n: i32| lo + (hi - lo) * k / n;
        let mut parts = Vec::new();
        for i in 0..cols {
            let (x0, x1) = (
                at(bx.min[0], bx.max[0], i, cols),
                at(bx.min[0], bx.max[0], i + 1, cols),
            );
            let n = rows(i);
            for j in 0..n {
                let (y0, y1) = (
                    at(bx.min[1], bx.max[1], j, n),
                    at(bx.min[1], bx.max[1], j + 1, n),
                );
                let t = tile(x0, x1, y0, y1);
                parts.push((t, engine.intersection(stock, [&t.corners()[..]])));
            }
        }
        parts
    }

    fn union(parts: &[(IBox, IShapes)], engine: &mut Engine) -> IShapes {
        let shapes: Vec<IShapes> = parts.iter().map(|(_, s)| s.clone()).collect();
        engine.union(&shapes)
    }

    /// Random stocks (a bar less random triangles and boxes, each over the bar's top edge)
    /// in random tilings, even and uneven: the stitch returns exactly what the union
    /// returns, or gives up; it gives up rarely.
    #[test]
    fn tiled_random_stocks_stitch_to_their_union() {
        let mut engine = Engine::new();
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = |m: i32| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % m as u64) as i32
        };
        let (mut joined, mut gave_up) = (0, 0);
        // on a grid of 1 000 steps a unit, as a run's grid is fine against its tiles: a
        // cut's edge within the band of a tile side (where it gives up) is as rare
        let k = 1000;
        for case in 0..400 {
            let bar = vec![vec![ring(&[
                [0, 0],
                [1000 * k, 0],
                [1000 * k, 300 * k],
                [0, 300 * k],
            ])]];
            let cuts: Vec<Vec<IPt>> = (0..1 + next(12))
                .map(|_| {
                    let (cx, cy) = (next(1000 * k), 100 * k + next(190 * k));
                    if next(2) == 0 {
                        ring(&[
                            [cx, cy],
                            [cx + 5 * k + next(80 * k), 330 * k],
                            [cx - next(60 * k), 340 * k],
                        ])
                    } else {
                        let w = 5 * k + next(100 * k);
                        ring(&[[cx, cy], [cx + w, cy], [cx + w, 320 * k], [cx, 320 * k]])
                    }
                })
                .collect();
            let stock = engine.difference(&bar, cuts.iter().map(|c| &c[..]));
            let bx = tile(-30 * k, 1030 * k, -20 * k, 320 * k);
            let cols = 1 + next(9);
            let rows: Vec<i32> = (0..cols)
                .map(|_| if case % 2 == 0 { 3 } else { 1 + next(6) })
                .collect();
            let parts = tiles(&stock, bx, cols, |i| rows[i as usize], &mut engine);
            match stitch(&parts) {
                Some(s) => {
                    assert_eq!(s, union(&parts, &mut engine), "case {case}");
                    joined += 1;
                }
                None => gave_up += 1,
            }
        }
        assert!(joined >= 396, "joined {joined}, gave up {gave_up}");
    }

    /// The stitch gives up where the union has more to do: a hole, two pieces that
    /// overlap, a piece touching its neighbour's edge at a point.
    #[test]
    fn gives_up_where_the_pieces_are_not_cut_tiles() {
        let square = |x0: i32, x1: i32| vec![vec![ring(&[[x0, 0], [x1, 0], [x1, 10], [x0, 10]])]];
        let with_hole = vec![(
            tile(-5, 30, -5, 20),
            vec![vec![
                ring(&[[0, 0], [20, 0], [20, 10], [0, 10]]),
                ring(&[[5, 2], [5, 8], [15, 8], [15, 2]]),
            ]],
        )];
        assert_eq!(stitch(&with_hole), None);
        // two pieces over the side x = 10, overlapping between 8 and 12
        let overlapping = vec![
            (tile(-5, 10, -5, 20), square(0, 12)),
            (tile(10, 30, -5, 20), square(8, 20)),
        ];
        assert_eq!(stitch(&overlapping), None);
        // a triangle's tip on the side x = 10, at the middle of the square's edge there
        let touching = vec![
            (tile(-5, 10, -5, 20), square(0, 10)),
            (
                tile(10, 30, -5, 20),
                vec![vec![ring(&[[10, 5], [20, 0], [20, 10]])]],
            ),
        ];
        assert_eq!(stitch(&touching), None);
    }

    /// Stock edges exactly on tile sides (a face on a strip's side, as the blank's face at
    /// Z0 often is; a bar cut at a side; a bar filling its tiles, a short tile beside two
    /// long ones) are joined as the union joins them.
    #[test]
    fn edges_on_tile_sides_join_as_the_union_joins_them() {
        let mut engine = Engine::new();
        let rect = |x0: i32, x1: i32, y0: i32, y1: i32| {
            vec![vec![ring(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]])]]
        };
        let cases = [
            vec![(tile(-5, 10, -5, 20), rect(0, 10, 0, 10))],
            vec![
                (tile(-5, 10, -5, 20), rect(0, 10, 0, 10)),
                (tile(10, 30, -5, 20), rect(10, 20, 0, 10)),
            ],
            vec![
                (tile(0, 10, 0, 10), rect(0, 10, 0, 10)),
                (tile(10, 20, 0, 4), rect(10, 20, 0, 4)),
                (tile(10, 20, 4, 10), rect(10, 20, 4, 10)),
                (tile(0, 10, 10, 30), rect(0, 10, 10, 30)),
            ],
        ];
        for parts in cases {
            let union = union(&parts, &mut engine);
            assert_eq!(stitch(&parts), Some(union), "{parts:?}");
        }
    }
}
