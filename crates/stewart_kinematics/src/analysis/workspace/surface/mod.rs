//! The boundary of a constant-orientation workspace as a closed triangle mesh, for
//! drawing it in 3D and writing it to a file.
//!
//! **Method.** The workspace's columns ([`ConstantOrientationWorkspace::spans`]) give,
//! on a square `xy` grid, the exact lowest and highest reachable height of each column.
//! Those two heights at the column centres are the vertices of a lower and an upper
//! height field over the grid: every grid square whose four corner columns are
//! reachable become two triangles (one when three are), above and below. Along the
//! boundary of that area a rim half a cell wide, at the boundary columns' heights, runs
//! out to the boundary columns' outer edges (mitred at corners) and a wall closes it, so
//! each boundary column counts across its whole cell, as the column sum counts it. The
//! result is closed (every directed edge is matched by its reverse) and faces outward, so
//! its enclosed volume is well defined. It differs from the column sum
//! [`ConstantOrientationWorkspace::volume`] by the linear interpolation between column
//! centres (where the sum is the midpoint rule and the mesh the trapezoid rule with a
//! half-cell end, equal on a straight edge) and at the rim's corners; tests show the two
//! agree within the workspace's own error bound.
//!
//! A column whose reachable heights split into separate pieces (possible where a leg's
//! inner stroke sphere cuts it) is drawn from its lowest to its highest reachable height,
//! and each gap between its pieces as an inward-facing box of the column's cell: a
//! cavity the enclosed volume leaves out. [`WorkspaceSurface::split_columns`] counts them.

use super::ConstantOrientationWorkspace;

/// A closed, outward-facing triangle mesh around the reachable positions.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WorkspaceSurface {
    /// Vertex positions (platform centre), metres.
    pub positions: Vec<[f64; 3]>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// Columns with more than one reachable piece, drawn as one.
    pub split_columns: usize,
}

/// Marks a column with no reachable height.
const NONE: u32 = u32::MAX;

/// Lowest and highest reachable heights on a `width × height` grid of columns.
struct Heights {
    width: usize,
    height: usize,
    /// Column centre of grid index (0, 0), and the spacing.
    origin: [f64; 2],
    cell: f64,
    /// `[low, high]` per column, `None` when out of reach; row-major in `y`.
    columns: Vec<Option<[f64; 2]>>,
    /// Columns with more than one reachable piece.
    split: usize,
    /// Unreachable gaps `(x, y, z_low, z_high)` between the pieces of a column.
    voids: Vec<[f64; 4]>,
}

impl Heights {
    fn new(ws: &ConstantOrientationWorkspace) -> Option<Self> {
        let [ex, ey, _] = ws.extent?;
        let cell = ws.cell;
        if cell <= 0.0 || !cell.is_finite() {
            return None;
        }
        let index = |v: f64, lo: f64| ((v - lo) / cell).round().max(0.0) as usize;
        let width = index(ex[1], ex[0]) + 1;
        let height = index(ey[1], ey[0]) + 1;
        let mut columns: Vec<Option<[f64; 2]>> = vec![None; width * height];
        let mut split = 0;
        let mut voids = Vec::new();
        // A column's spans come one after another, lowest first.
        for group in ws.spans.chunk_by(|a, b| a[0] == b[0] && a[1] == b[1]) {
            let [x, y, ..] = group[0];
            let k = index(y, ey[0]).min(height - 1) * width + index(x, ex[0]).min(width - 1);
            let low = group.iter().map(|s| s[2]).fold(f64::INFINITY, f64::min);
            let high = group.iter().map(|s| s[3]).fold(f64::NEG_INFINITY, f64::max);
            columns[k] = Some([low, high]);
            if group.len() > 1 {
                split += 1;
                let mut pieces = group.to_vec();
                pieces.sort_by(|a, b| a[2].total_cmp(&b[2]));
                for w in pieces.windows(2) {
                    if w[0][3] < w[1][2] {
                        voids.push([x, y, w[0][3], w[1][2]]);
                    }
                }
            }
        }
        Some(Self {
            width,
            height,
            origin: [ex[0], ey[0]],
            cell,
            columns,
            split,
            voids,
        })
    }

    fn get(&self, i: usize, j: usize) -> Option<[f64; 2]> {
        (i < self.width && j < self.height)
            .then(|| self.columns[j * self.width + i])
            .flatten()
    }

    /// Reachable corners of grid square `(i, j)` in counter-clockwise order from its
    /// lower left; squares with fewer than three take no part in the surface.
    fn square(&self, i: usize, j: usize) -> Option<Corners> {
        let all = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
        let mut corners = Corners::default();
        for (k, &(a, b)) in all.iter().enumerate() {
            if self.get(a, b).is_some() {
                corners.mask |= 1 << k;
            }
        }
        (corners.mask.count_ones() >= 3).then_some(corners)
    }

    /// Whether the square across the side from corner `from` to corner `to` of square
    /// `(i, j)` (corners numbered as in [`Heights::square`]) also carries that side.
    fn shared(&self, i: usize, j: usize, from: usize) -> bool {
        let neighbour = match from {
            0 => j.checked_sub(1).map(|b| (i, b)),
            1 => Some((i + 1, j)),
            2 => Some((i, j + 1)),
            _ => i.checked_sub(1).map(|a| (a, j)),
        };
        neighbour.is_some_and(|(a, b)| self.square(a, b).is_some())
    }
}

/// Which corners of a square are reachable (bit `k` for corner `k`).
#[derive(Clone, Copy, Default)]
struct Corners {
    mask: u8,
}

impl Corners {
    fn has(self, k: usize) -> bool {
        self.mask & (1 << k) != 0
    }

    /// The reachable corners, counter-clockwise.
    fn cycle(self) -> impl Iterator<Item = usize> {
        (0..4).filter(move |&k| self.has(k))
    }
}

impl WorkspaceSurface {
    /// The surface around `ws`'s reachable columns (see the module docs); empty when
    /// nothing is reachable.
    pub fn from_workspace(ws: &ConstantOrientationWorkspace) -> Self {
        let Some(grid) = Heights::new(ws) else {
            return Self::default();
        };
        let mut surface = Self {
            split_columns: grid.split,
            ..Self::default()
        };
        // Upper and lower vertex of every reachable column.
        let mut vertex = vec![NONE; grid.width * grid.height];
        for j in 0..grid.height {
            for i in 0..grid.width {
                if let Some([lo, hi]) = grid.get(i, j) {
                    let x = grid.origin[0] + i as f64 * grid.cell;
                    let y = grid.origin[1] + j as f64 * grid.cell;
                    vertex[j * grid.width + i] = surface.positions.len() as u32;
                    surface.positions.push([x, y, hi]);
                    surface.positions.push([x, y, lo]);
                }
            }
        }
        let top = |(a, b): (usize, usize)| vertex[b * grid.width + a];
        // Boundary edges, upper vertices, counter-clockwise around the reachable area.
        let mut edges = Vec::new();
        for j in 0..grid.height.saturating_sub(1) {
            for i in 0..grid.width.saturating_sub(1) {
                let Some(corners) = grid.square(i, j) else {
                    continue;
                };
                let at = |k: usize| top([(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)][k]);
                let mut cycle = [0; 4];
                let mut len = 0;
                for k in corners.cycle() {
                    cycle[len] = k;
                    len += 1;
                }
                let cycle = &cycle[..len];
                // Fan from the first corner: one triangle for three corners, two for four.
                for w in cycle[1..].windows(2) {
                    let [a, b, c] = [at(cycle[0]), at(w[0]), at(w[1])];
                    surface.triangles.push([a, b, c]);
                    surface.triangles.push([a + 1, c + 1, b + 1]);
                }
                // The cycle's edges that no neighbouring square carries bound the
                // surface: a diagonal always, a side when the square beyond lacks it.
                for (n, &from) in cycle.iter().enumerate() {
                    let to = cycle[(n + 1) % cycle.len()];
                    let side = (from + 1) % 4 == to;
                    if !(side && grid.shared(i, j, from)) {
                        edges.push((at(from), at(to)));
                    }
                }
            }
        }
        surface.add_rim(&edges, grid.cell);
        let half = 0.5 * grid.cell;
        for &[x, y, z0, z1] in &grid.voids {
            surface.add_void([x - half, y - half, z0], [x + half, y + half, z1]);
        }
        surface
    }

    /// Close the surface along its boundary `edges` (upper vertices, reachable area on
    /// their left) with a rim half a `cell` wide: each boundary column is reachable across
    /// its whole cell, as the column sum counts it. The rim keeps the boundary columns'
    /// heights; its outer vertices sit at the mitred offset of the boundary, and a wall
    /// joins their upper and lower copies.
    fn add_rim(&mut self, edges: &[(u32, u32)], cell: f64) {
        // Mean outward normal at every boundary vertex (indexed by column).
        let mut normals = vec![([0.0f64; 2], 0u32); self.positions.len() / 2];
        for &(a, b) in edges {
            let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let length = dx.hypot(dy);
            for v in [a, b] {
                let (n, count) = &mut normals[v as usize / 2];
                n[0] += dy / length;
                n[1] -= dx / length;
                *count += 1;
            }
        }
        // Outer copies: the offset whose projection on each of two unit normals is half a
        // cell (the miter), at most a cell long where the boundary turns sharply.
        let half = 0.5 * cell;
        let mut outer = vec![NONE; normals.len()];
        for (column, &(n, count)) in normals.iter().enumerate() {
            if count == 0 {
                continue;
            }
            let m = [n[0] / count as f64, n[1] / count as f64];
            let m2 = m[0] * m[0] + m[1] * m[1];
            let scale = if m2 >= 0.25 {
                half / m2
            } else if m2 > 1e-18 {
                2.0 * half / m2.sqrt()
            } else {
                0.0
            };
            outer[column] = self.positions.len() as u32;
            for k in [0, 1] {
                let [x, y, z] = self.positions[2 * column + k];
                self.positions.push([x + scale * m[0], y + scale * m[1], z]);
            }
        }
        for &(a, b) in edges {
            let (oa, ob) = (outer[a as usize / 2], outer[b as usize / 2]);
            // Upper strip, outer wall, lower strip.
            self.triangles.push([a, oa, ob]);
            self.triangles.push([a, ob, b]);
            self.triangles.push([ob, oa, oa + 1]);
            self.triangles.push([ob, oa + 1, ob + 1]);
            self.triangles.push([a + 1, ob + 1, oa + 1]);
            self.triangles.push([a + 1, b + 1, ob + 1]);
        }
    }

    /// A box from `min` to `max` facing inward: a hole in the enclosed volume.
    fn add_void(&mut self, min: [f64; 3], max: [f64; 3]) {
        let first = self.positions.len() as u32;
        for k in 0..8 {
            let pick = |axis: usize| {
                if k & (1 << axis) == 0 {
                    min[axis]
                } else {
                    max[axis]
                }
            };
            self.positions.push([pick(0), pick(1), pick(2)]);
        }
        // Each face's corners counter-clockwise seen from outside the box (bit 0 is x,
        // bit 1 y, bit 2 z); the triangles are laid the other way round.
        for [a, b, c, d] in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            self.triangles.push([first + a, first + c, first + b]);
            self.triangles.push([first + a, first + d, first + c]);
        }
    }

    /// The volume the mesh encloses, m³ (divergence theorem over its triangles).
    pub fn enclosed_volume(&self) -> f64 {
        let p = |k: u32| nalgebra::Vector3::from(self.positions[k as usize]);
        self.triangles
            .iter()
            .map(|&[a, b, c]| p(a).dot(&p(b).cross(&p(c))))
            .sum::<f64>()
            / 6.0
    }
}

#[cfg(test)]
mod tests;
