//! The G75.1 groove's shape: the trapezoid with its broken corners, in the groove's local
//! frame (u along Z toward the far side, v along the radius toward the floor), its contour
//! and the ring the report draws.

use crate::Pt;
use geom::arc::Arc;

/// How one corner of the groove is broken.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) enum Corner {
    /// A sharp corner.
    #[default]
    Sharp,
    /// A straight chamfer cutting both edges at this distance (mm) from the corner.
    Chamfer(f64),
    /// A round of this radius (mm) tangent to both edges.
    Round(f64),
}
/// The G75.1 groove as drawn: mouth corner P1, depth, floor width, flank angles, mouth
/// slope and the four corners (mouth start, mouth far, floor start, floor far).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Trapezoid {
    /// P1, the mouth corner on the start side, G54 frame (z, r).
    pub start: Pt,
    /// H: depth mouth to floor, diameter, signed (sign = X infeed direction).
    pub h: f64,
    /// D: floor width, signed (sign = Z shift direction).
    pub d: f64,
    /// A: start-side flank to floor angle, degrees, 0 < a ≤ 90.
    pub a: f64,
    /// B: far flank to floor angle, degrees, 0 < b ≤ 90.
    pub b: f64,
    /// L: slope of the mouth line, degrees, 0 ≤ p < 90 (the mouth rises away from the floor
    /// toward the far side).
    pub l: f64,
    /// Corners r1..r4: mouth start, mouth far, floor start, floor far.
    pub corners: [Corner; 4],
}

/// A point of the local frame (u along the groove toward the far side, v toward the floor).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Uv {
    pub(super) u: f64,
    pub(super) v: f64,
}

pub(super) fn uv(u: f64, v: f64) -> Uv {
    Uv { u, v }
}

impl Uv {
    pub(super) fn add(self, o: Self, k: f64) -> Self {
        uv(self.u + k * o.u, self.v + k * o.v)
    }
    pub(super) fn sub(self, o: Self) -> Self {
        uv(self.u - o.u, self.v - o.v)
    }
    pub(super) fn len(self) -> f64 {
        self.u.hypot(self.v)
    }
    pub(super) fn unit(self) -> Self {
        let l = self.len();
        uv(self.u / l, self.v / l)
    }
}

/// One element of a contour in the local frame: a line or an arc to `to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct El {
    pub(super) to: Uv,
    /// Centre and counter-clockwise (in the local frame) for an arc.
    pub(super) arc: Option<(Uv, bool)>,
}

/// The finishing contour in the local frame: from `first` (the mouth-start corner, or the
/// outer end of its chamfer/round) through `els` to the mouth-far corner.
pub(super) struct Contour {
    pub(super) first: Uv,
    pub(super) els: Vec<El>,
    /// Index of the floor line (the far corner of a blade traces it and all after it).
    pub(super) far_from: usize,
    /// Index of the start flank line (to the floor-start corner).
    pub(super) idx2a: usize,
    /// Index of the far flank line (to the mouth-far corner).
    pub(super) idx4a: usize,
    /// The sharp mouth corners P1 and P4.
    pub(super) p1: Uv,
    pub(super) p4: Uv,
}

impl Contour {
    /// The start side for roughing: P1 (mouth chamfer left out), the start flank and the
    /// floor-start corner, chorded.
    pub(super) fn rough_start(&self, tol: f64) -> Vec<Uv> {
        let mut out = vec![self.p1];
        let from = if self.idx2a == 0 {
            self.first
        } else {
            self.els[self.idx2a - 1].to
        };
        chord(from, &self.els[self.idx2a..self.far_from], tol, &mut out);
        out
    }

    /// The far side for roughing: the floor-far corner and the far flank up to P4.
    pub(super) fn rough_far(&self, tol: f64) -> Vec<Uv> {
        let from = self.els[self.far_from].to;
        let mut out = vec![from];
        chord(
            from,
            &self.els[self.far_from + 1..=self.idx4a],
            tol,
            &mut out,
        );
        out.push(self.p4);
        out
    }
}

/// Append the points of `els` from `from`, arcs chorded within `tol` (excluding `from`) by
/// the kernel's one chording routine (`geom::arc`; the local frame is a plane like any).
pub(super) fn chord(mut from: Uv, els: &[El], tol: f64, out: &mut Vec<Uv>) {
    let pt = |p: Uv| Pt::new(p.u, p.v);
    for el in els {
        if let Some((c, ccw)) = el.arc {
            let points = Arc::between(pt(from), pt(el.to), pt(c), ccw).flatten(tol.max(1e-9));
            let inner = &points[1..points.len() - 1];
            out.extend(inner.iter().map(|p| uv(p.z, p.r)));
        }
        out.push(el.to);
        from = el.to;
    }
}

/// The u of a polyline at depth v: the largest (start side) or smallest (far side) u where
/// it reaches v; above its first point, the first point's u.
pub(super) fn u_at(poly: &[Uv], v: f64, largest: bool) -> f64 {
    let mut best: Option<f64> = None;
    let mut take = |u: f64| {
        best = Some(match best {
            None => u,
            Some(b) if largest => b.max(u),
            Some(b) => b.min(u),
        })
    };
    for s in poly.windows(2) {
        let (a, b) = (s[0], s[1]);
        let (lo, hi) = (a.v.min(b.v), a.v.max(b.v));
        if v < lo - 1e-12 || v > hi + 1e-12 {
            continue;
        }
        if (b.v - a.v).abs() < 1e-12 {
            take(a.u);
            take(b.u);
        } else {
            take(a.u + (b.u - a.u) * (v - a.v) / (b.v - a.v));
        }
    }
    best.unwrap_or_else(|| {
        // above (or below) the polyline: its nearest end
        let top = if poly[0].v <= poly[poly.len() - 1].v {
            poly[0]
        } else {
            poly[poly.len() - 1]
        };
        top.u
    })
}

/// The corner points of the trapezoid and its mouth direction, local frame.
pub(super) struct Frame {
    pub(super) p: [Uv; 4],
    pub(super) mouth: Uv,
}

impl Trapezoid {
    pub(super) fn signs(&self) -> (f64, f64) {
        (self.d.signum(), self.h.signum())
    }

    pub(super) fn to_pt(self, q: Uv) -> Pt {
        let (sz, sx) = self.signs();
        Pt::new(self.start.z + sz * q.u, self.start.r + sx * q.v)
    }

    /// Whether the local frame is a mirror image of (z, r) (arcs change direction).
    pub(super) fn mirrored(&self) -> bool {
        let (sz, sx) = self.signs();
        sz * sx < 0.0
    }

    /// P1..P4 in the local frame, or why the flanks never meet the mouth.
    pub(super) fn frame(&self) -> Result<Frame, String> {
        let t = self.h.abs() / 2.0;
        let f = self.d.abs();
        let (ta, tb, tp) = (tan_deg(self.a), tan_deg(self.b), self.l.to_radians().tan());
        let p2 = uv(t / ta, t);
        let p3 = uv(p2.u + f, t);
        if tp >= tb - 1e-12 {
            return Err(format!(
                "the far flank (B{}°) never meets the mouth line sloped at L{}°",
                self.b, self.l
            ));
        }
        let u4 = (p3.u + t / tb) / (1.0 - tp / tb);
        let mouth = uv(self.l.to_radians().cos(), -self.l.to_radians().sin());
        Ok(Frame {
            p: [uv(0.0, 0.0), p2, p3, uv(u4, -tp * u4)],
            mouth,
        })
    }

    /// The finishing contour in the local frame from the mouth-start corner to the mouth-far
    /// corner (outside points on the mouth line when those corners are broken), with the
    /// index of the first element the far corner of a blade traces.
    pub(super) fn contour(&self) -> Result<Contour, String> {
        let fr = self.frame()?;
        let [p1, p2, p3, p4] = fr.p;
        // edges: into each corner (d_in) and out of it (d_out)
        let dirs = [
            (fr.mouth, p2.sub(p1).unit()),
            (p2.sub(p1).unit(), uv(1.0, 0.0)),
            (uv(1.0, 0.0), p4.sub(p3).unit()),
            (p4.sub(p3).unit(), fr.mouth),
        ];
        let cuts = self.corner_cuts(&fr, &dirs)?;
        let order = Self::ORDER.map(|(i, ci)| (fr.p[i], ci));
        let mut els = Vec::new();
        let mut first = p1;
        let (mut far_from, mut idx2a, mut idx4a) = (0, 0, 0);
        for (k, &(p, ci)) in order.iter().enumerate() {
            let (din, dout) = dirs[k];
            let a = p.add(din, -cuts[k]);
            let b = p.add(dout, cuts[k]);
            if k == 0 {
                first = a;
            } else {
                els.push(El { to: a, arc: None });
            }
            match k {
                1 => idx2a = els.len() - 1,
                2 => far_from = els.len() - 1, // the floor line ends where the far corner takes over
                3 => idx4a = els.len() - 1,
                _ => {}
            }
            match self.corners[ci] {
                Corner::Sharp => {}
                Corner::Chamfer(_) => els.push(El { to: b, arc: None }),
                Corner::Round(r) => {
                    let cross = din.u * dout.v - din.v * dout.u;
                    let ccw = cross > 0.0;
                    let n = if ccw {
                        uv(-din.v, din.u)
                    } else {
                        uv(din.v, -din.u)
                    };
                    els.push(El {
                        to: b,
                        arc: Some((a.add(n, r), ccw)),
                    });
                }
            }
        }
        Ok(Contour {
            first,
            els,
            far_from,
            idx2a,
            idx4a,
            p1,
            p4,
        })
    }

    /// How much of its two edges each corner takes (path order P1, P2, P3, P4; `dirs`: the
    /// edge directions into and out of each): a chamfer its size, a round its tangent
    /// length. Corners that together take more than an edge is long are an error.
    fn corner_cuts(&self, fr: &Frame, dirs: &[(Uv, Uv); 4]) -> Result<[f64; 4], String> {
        let [p1, p2, p3, p4] = fr.p;
        let names = [
            "A (mouth, start side)",
            "B (mouth, far side)",
            "D (floor, start side)",
            "E (floor, far side)",
        ];
        let order = Self::ORDER;
        let mut cuts = [0.0; 4];
        for (k, &(_, ci)) in order.iter().enumerate() {
            let (din, dout) = dirs[k];
            let cosang = -(din.u * dout.u + din.v * dout.v);
            let theta = cosang.clamp(-1.0, 1.0).acos(); // interior angle between the edges
            cuts[k] = match self.corners[ci] {
                Corner::Sharp => 0.0,
                Corner::Chamfer(r) => r,
                Corner::Round(r) => r / (theta / 2.0).tan(),
            };
        }
        for (edge, (a, b), len) in [
            ("start flank", (0, 1), p2.sub(p1).len()),
            ("floor", (1, 2), p3.sub(p2).len()),
            ("far flank", (2, 3), p4.sub(p3).len()),
        ] {
            if cuts[a] + cuts[b] > len + 1e-9 {
                return Err(format!(
                    "the corners {} and {} cut {:.4} mm of the {edge}, which is only {:.4} mm long",
                    names[order[a].1],
                    names[order[b].1],
                    cuts[a] + cuts[b],
                    len
                ));
            }
        }
        Ok(cuts)
    }

    /// The corners in path order: P1 (r1 = A), P2 (r3 = D), P3 (r4 = E), P4 (r2 = B), as
    /// (index of the point in the frame, index of its corner in `corners`).
    const ORDER: [(usize, usize); 4] = [(0, 0), (1, 2), (2, 3), (3, 1)];

    /// The groove as a closed ring in (z, r): the finishing contour with its chamfers and
    /// rounds (arcs chorded within `chord_tol` mm), closed along the mouth line.
    pub(crate) fn ring(&self, chord_tol: f64) -> Result<Vec<Pt>, String> {
        let k = self.contour()?;
        let mut ring = vec![k.first];
        chord(k.first, &k.els, chord_tol, &mut ring);
        Ok(ring.into_iter().map(|q| self.to_pt(q)).collect())
    }
}

pub(super) fn tan_deg(a: f64) -> f64 {
    if (a - 90.0).abs() < 1e-12 {
        f64::INFINITY
    } else {
        a.to_radians().tan()
    }
}
